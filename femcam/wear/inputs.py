"""Per-angle contact columns of the wear map (``theta, a, p0, Fc``) from a sweep result or a
mapping, with the missing-pressure policy (raise, skip with a warning, zero); see
:func:`contact_columns` and :mod:`femcam.wear.map`."""

from __future__ import annotations

import warnings

import numpy as np

from .. import _validate

_KEYS = {
    "hertz": (("a_hertz", "a"), ("p0_hertz", "p0")),
    # the FE's fitted ellipse (a_fe, p0_fit: pi a p0 / 2 is its load); p0_fe (the solved peak)
    # for a table without the fit
    "fe": (("a_fe", "a"), ("p0_fit", "p0_fe", "p0")),
    # finite-length roller, the most loaded slice (femcam.wear.axial): pi a p0 / 2 = w_max
    "axial_peak": (("a_axial", "a"), ("p0_axial", "p0")),
}

#: what to do where the contact force is positive but the pressure is missing (NaN or <= 0)
MISSING = ("raise", "skip", "zero")


class WearInputWarning(UserWarning):
    """Angles of a sweep result were skipped by the wear map (their FE solve failed)."""


def _get(src, names):
    for n in names:
        try:
            val = src[n]
        except (KeyError, IndexError, TypeError, ValueError):
            val = getattr(src, n, None)
        if val is not None:
            return np.asarray(val, dtype=float)
    return None


def _get_text(src, name):
    try:
        val = src[name]
    except (KeyError, IndexError, TypeError, ValueError):
        val = getattr(src, name, None)
    return None if val is None else np.asarray(val).astype(str)


def _loaded_have(a, p0, Fc):
    """``(loaded, have)``: contact force ``Fc > 0``; a usable pressure (``a``, ``p0`` finite, > 0)."""
    loaded = np.isfinite(Fc) & (Fc > 0)
    have = np.isfinite(a) & np.isfinite(p0) & (a > 0) & (p0 > 0)
    return loaded, have


def _degrees(theta, idx, limit: int = 12) -> str:
    d = [f"{np.degrees(theta[i]):g}" for i in idx[:limit]]
    more = f" ... ({len(idx)} angles)" if len(idx) > limit else ""
    return "[" + ", ".join(d) + "]" + more


def _missing_pressure(source, theta, lost, missing, pressure, ka, kp, skipped) -> None:
    """Angles ``lost`` have ``Fc > 0`` but no pressure: raise, or skip them with a warning
    (see :func:`contact_columns`)."""
    status = _get_text(source, "status")
    failed = np.zeros(theta.size, bool) if status is None else (status == "failed")
    if missing is None:
        skip, stop = lost[failed[lost]], lost[~failed[lost]]
    else:
        skip, stop = (lost, lost[:0]) if missing == "skip" else (lost[:0], lost)
    what = f"{ka[0]}/{kp[0]}"
    if stop.size:
        hint = ""
        if status is not None and np.all(status[stop] == "ok"):
            hint = (f"; the sweep has no {what} there (was it run with method='hertz'? then use "
                    "pressure='hertz')" if pressure == "fe" else
                    "; Hertz theory does not apply there (sweep flag hertz_invalid): use pressure='fe'")
        raise _validate.fail("theta", _degrees(theta, stop), "deg",
                      f"contact force Fc > 0 but the contact pressure {what} is missing (NaN or "
                      f"<= 0) at {stop.size} angle(s){hint}; wear there is unknown, not zero "
                      "(missing='skip' skips such angles with a warning)")
    if skip.size:
        msgs = _get_text(source, "message")
        why = ""
        if msgs is not None:
            uniq = sorted({m for m in msgs[skip] if m})
            why = "; sweep message(s): " + " | ".join(uniq[:3]) if uniq else ""
        warnings.warn(f"wear map: skipped {skip.size} angle(s) theta = {_degrees(theta, skip)} deg "
                      f"where Fc > 0 but {what} is missing (failed solve): they carry no load, "
                      f"so the wear near them is underestimated{why}", WearInputWarning, stacklevel=4)
        if skipped is not None:
            skipped.extend(int(i) for i in skip)


def contact_columns(source, *, pressure: str = "hertz", missing: str | None = None,
                    skipped: list | None = None):
    """``(theta, a, p0, Fc)`` arrays (SI) from a SweepResult-like object or a mapping.

    ``pressure="fe"`` reads ``a_fe``/``p0_fit`` (the FE's fitted ellipse; ``p0_fe`` without a
    ``p0_fit`` column), ``"hertz"`` reads ``a_hertz``/``p0_hertz``; both
    fall back to plain ``a``/``p0``. Angles without contact (``Fc <= 0``) carry no load.

    An angle with ``Fc > 0`` but no pressure (``a`` or ``p0`` NaN or <= 0: a failed FE solve, a
    Hertz-invalid angle) is *not* silently taken as no contact. ``missing``:

    * ``"raise"`` -- :class:`~femcam.errors.InputError` naming the angles (deg);
    * ``"skip"`` -- a :class:`WearInputWarning` naming the angles, which then carry no load
      (the wear there is underestimated); their indices are appended to ``skipped``;
    * ``"zero"`` -- silently no load (the behaviour :func:`wear_depth_per_angle` keeps);
    * ``None`` (default) -- ``"skip"`` for the rows of a sweep result whose ``status`` is
      ``"failed"`` (the sweep's ``message`` is quoted), ``"raise"`` for everything else.

    Without an ``Fc`` column, contact is read from the width alone (NaN or 0 = no contact).

    Parameters
    ----------
    source : SweepResult-like or mapping
        Columns ``theta`` [rad], ``a`` [m], ``p0`` [Pa] (under the names of ``pressure``) and,
        optionally, ``Fc`` [N], ``status`` and ``message``; shape (n,) each.
    pressure : {"hertz", "fe", "axial_peak"}
        Which columns hold ``a``/``p0``: ``a_hertz``/``p0_hertz``, ``a_fe``/``p0_fe`` or
        ``a_axial``/``p0_axial`` (the last of :mod:`femcam.wear.axial`).
    missing : {"raise", "skip", "zero"}, optional
        Missing-pressure policy, see above; None picks per row.
    skipped : list, optional
        Receives the indices of the skipped angles.

    Returns
    -------
    theta : ndarray, shape (n,), float
        Cam angles [rad].
    a : ndarray, shape (n,), float
        Contact half-width [m]; 0 where no contact (or skipped).
    p0 : ndarray, shape (n,), float
        Peak pressure [Pa]; 0 where no contact (or skipped).
    Fc : ndarray, shape (n,), float
        Contact force [N]; 0 where no contact (or skipped). Without an ``Fc`` column: 1 where
        there is contact, 0 elsewhere (not a force).

    Raises
    ------
    InputError
        A column missing, a negative ``a``, a bad ``pressure``/``missing``, or a missing
        pressure that the policy refuses.
    """
    _validate.choice("pressure", pressure, tuple(_KEYS))
    if missing is not None:
        _validate.choice("missing", missing, MISSING)
    (ka, kp) = _KEYS[pressure]
    theta = _get(source, ("theta",))
    a, p0, Fc = _get(source, ka), _get(source, kp), _get(source, ("Fc",))
    for name, arr in (("theta", theta), ("a", a), ("p0", p0)):
        if arr is None:
            raise _validate.fail("source", type(source).__name__, "", f"has no column '{name}' "
                         f"(looked for {ka if name == 'a' else kp if name == 'p0' else name})")
    if Fc is None:
        Fc = np.where(np.isfinite(a) & (a > 0), 1.0, 0.0)
    theta = _validate.finite_array("theta", theta, "rad")
    bad = np.isfinite(a) & (a < 0)
    if np.any(bad):
        raise _validate.fail("a", float(a[bad][0]), "m", "must be >= 0 (contact half-width)")
    loaded, have = _loaded_have(a, p0, Fc)
    lost = np.flatnonzero(loaded & ~have)
    if lost.size and missing != "zero":
        _missing_pressure(source, theta, lost, missing, pressure, ka, kp, skipped)
    noc = ~(loaded & have)
    a = np.where(noc, 0.0, a)
    p0 = np.where(noc, 0.0, np.clip(p0, 0.0, None))
    return theta, a, p0, np.where(noc, 0.0, Fc)
