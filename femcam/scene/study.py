"""``[fe]`` and ``[sweep]``: the study settings ``femcam sweep`` reads from a scene (command-line
flags override them). Their ranges are :func:`femcam.scene.schema.study_problem`, which
:class:`femcam.sweep.options.SweepOptions` checks through too.
"""

from __future__ import annotations

from .. import _validate
from ..errors import InputError
from .checker import _Checker
from .schema import _FE, _SWEEP


def _study(ck: _Checker, raw: dict) -> dict:
    """The checked [fe] and [sweep] settings.

    Parameters
    ----------
    ck : _Checker
        Collects the problems.
    raw : dict
        The parsed scene file.

    Returns
    -------
    dict
        ``{"fe": {...}, "sweep": {...}}``: ``a_over_h``, ``tolerance`` (dimensionless);
        ``method``, ``angles_deg`` (the text, checked by :func:`femcam._validate.angles_deg`),
        ``chunk_size``, ``vtk_every`` (angles), ``plots``. Empty dicts for absent tables.
    """
    out = {t: ck.table(raw[t], t, spec) if t in raw else {} for t, spec in (("fe", _FE), ("sweep", _SWEEP))}
    if isinstance(out["sweep"].get("angles_deg"), str):
        try:
            _validate.angles_deg("sweep.angles_deg", out["sweep"]["angles_deg"])
        except InputError as exc:
            ck.add("sweep.angles_deg", str(exc).removeprefix("sweep.angles_deg "))
    return out
