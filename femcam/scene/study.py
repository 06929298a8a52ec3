"""``[fe]`` and ``[sweep]``: the study settings a sweep reads from a scene (:attr:`Scene.study`;
arguments of :func:`femcam.sweep` and flags of ``femcam sweep`` override them). Their ranges are
:func:`femcam.scene.schema.study_problem`, which :class:`femcam.sweep.options.SweepOptions`
checks through too.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

from .. import _validate
from ..errors import InputError
from .checker import _Checker
from .schema import _FE, _SWEEP, METHODS, RTOL_ON, STUDY_UNITS, STUDY_WHOLE, study_problem

__all__ = ["StudySettings"]


@dataclass(frozen=True, kw_only=True)
class StudySettings:
    """The ``[fe]`` and ``[sweep]`` settings of a scene; None where the scene does not give one.

    The values are checked by the scene loader (:func:`femcam.scene.load_scene`, ranges of
    :func:`femcam.scene.schema.study_problem`); a sweep takes each one that its
    :class:`femcam.sweep.SweepOptions` leaves at None (:mod:`femcam.sweep.settings`).

    Parameters
    ----------
    a_over_h : float or None
        ``[fe] a_over_h``: elements per contact half-width, ``h = a / a_over_h`` [-].
    tolerance : float or None
        ``[fe] tolerance``: bound on the model-reuse error of p0 [-] (relative).
    rtol : float or None
        ``[fe] rtol_pct`` / 100: requested bound on the estimated relative error [-] (a
        fraction; the scene key is in percent).
    rtol_on : tuple of str or None
        ``[fe] rtol_on``: the quantities ``rtol`` bounds (stems of the ``err_est_*`` columns).
    method : str or None
        ``[sweep] method``: ``"fe"``, ``"hertz"`` or ``"auto"``.
    angles_deg : str or None
        ``[sweep] angles_deg``: the cam angles as ``"start:stop:step"`` [deg].
    chunk_size : int or None
        ``[sweep] chunk_size``: angles per chunk [angles].
    vtk_every : int or None
        ``[sweep] vtk_every``: a ``.vtu`` every k-th angle [angles] (0: none).
    plots : bool or None
        ``[sweep] plots``: write the PNG plots.

    Raises
    ------
    InputError
        A value of the wrong kind or out of its range (the scene's rules), naming the key.
    """

    a_over_h: float | None = None
    tolerance: float | None = None
    rtol: float | None = None
    rtol_on: tuple | None = None
    method: str | None = None
    angles_deg: str | None = None
    chunk_size: int | None = None
    vtk_every: int | None = None
    plots: bool | None = None

    def __post_init__(self):
        for key, unit in STUDY_UNITS.items():   # a_over_h, tolerance, chunk_size, vtk_every
            value = getattr(self, key)
            if value is not None:
                x = _validate.number(key, value, unit)
                problem = study_problem(key, x)
                if problem:
                    raise _validate.fail(key, value, unit, problem)
                object.__setattr__(self, key, int(x) if key in STUDY_WHOLE else x)
        if self.rtol is not None:
            object.__setattr__(self, "rtol", _validate.positive("rtol", self.rtol, "(relative error)"))
        if self.method is not None:
            _validate.choice("method", self.method, METHODS)
        if self.rtol_on is not None:
            names = (self.rtol_on,) if isinstance(self.rtol_on, str) else tuple(self.rtol_on)
            for q in names:
                _validate.choice("rtol_on", q, RTOL_ON)
            object.__setattr__(self, "rtol_on", names)
        if self.angles_deg is not None:
            _validate.angles_deg("angles_deg", self.angles_deg)
        if self.plots is not None and not isinstance(self.plots, bool):
            raise _validate.fail("plots", self.plots, "", "must be true or false")

    def given(self) -> dict:
        """The settings the scene gives.

        Returns
        -------
        dict
            Field name -> value (the fields' units), without the None ones.
        """
        return {f.name: getattr(self, f.name) for f in fields(self) if getattr(self, f.name) is not None}


def _study(ck: _Checker, raw: dict) -> StudySettings:
    """The checked [fe] and [sweep] settings.

    Parameters
    ----------
    ck : _Checker
        Collects the problems.
    raw : dict
        The parsed scene file.

    Returns
    -------
    StudySettings
        None for each key the scene does not give (or gives with a problem, collected in ``ck``).
    """
    out = {t: ck.table(raw[t], t, spec) if t in raw else {} for t, spec in (("fe", _FE), ("sweep", _SWEEP))}
    if isinstance(out["sweep"].get("angles_deg"), str):
        try:
            _validate.angles_deg("sweep.angles_deg", out["sweep"]["angles_deg"])
        except InputError as exc:
            ck.add("sweep.angles_deg", str(exc).removeprefix("sweep.angles_deg "))
            out["sweep"].pop("angles_deg")
    fe, sw = out["fe"], out["sweep"]
    if "rtol_pct" in fe:
        fe["rtol"] = float(fe.pop("rtol_pct")) / 100.0   # percent -> fraction
    if isinstance(fe.get("rtol_on"), str):
        fe["rtol_on"] = tuple(q.strip() for q in fe["rtol_on"].split(",") if q.strip())
    try:
        return StudySettings(**fe, **sw)
    except InputError as exc:   # a problem the table checks already collected
        ck.add("fe/sweep", str(exc))
        return StudySettings()
