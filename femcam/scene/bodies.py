"""Real bodies (:mod:`femcam.bodies`; docs/bodies.md): the roller as a ring on a pin or needles
(``[follower] roller_support``) and the cam on a shaft (``[cam] bore_mm``).

Radii in mm, the clearance in um; the checked values are SI.
"""

from __future__ import annotations

import math

from .checker import _Checker, _fmt
from .schema import _BODY_MATERIALS, _FOLLOWER, _SUPPORT_KEYS


def roller_support_problems(*, Ro, Ri, support, Rp, c, Z, r_n) -> list[str]:
    """Geometry problems of a ring support: bore inside the roller, pin + clearance = bore
    (pin), pin + 2 needles + clearance = bore and needles that fit around the pitch circle
    (needles). Used by the scene loader and by :mod:`femcam.bodies.geometry`.

    Parameters
    ----------
    Ro : float
        Roller (ring) outer radius (m).
    Ri : float
        Roller bore radius (m).
    support : str
        ``"solid"`` (no problems), ``"pin"`` or ``"needles"``.
    Rp : float
        Pin radius (m).
    c : float
        Radial clearance (m).
    Z : float
        Number of needles (a whole number >= 3 for ``"needles"``).
    r_n : float
        Needle radius (m).

    Returns
    -------
    list of str
        One message a problem, in the scene's units (mm, um); empty when the geometry fits.

    Examples
    --------
    >>> roller_support_problems(Ro=0.01, Ri=0.005, support="pin", Rp=0.00499, c=1e-5, Z=0, r_n=0)
    []
    >>> roller_support_problems(Ro=0.01, Ri=0.012, support="pin", Rp=0.005, c=0.0, Z=0, r_n=0)
    ['roller_bore_mm = 12 mm: must be in (0, roller_radius_mm = 10 mm)']
    """
    out = []
    if support == "solid":
        return out
    if not 0.0 < Ri < Ro:
        return [f"roller_bore_mm = {Ri * 1e3:g} mm: must be in (0, roller_radius_mm = {Ro * 1e3:g} mm)"]
    if support == "pin":
        if not math.isclose(Rp + c, Ri, rel_tol=1e-9, abs_tol=1e-12):
            out.append(f"pin_radius_mm + pin_clearance_um = {Rp * 1e3:g} mm + {c * 1e6:g} um = "
                       f"{(Rp + c) * 1e3:g} mm: must equal roller_bore_mm = {Ri * 1e3:g} mm")
        return out
    if Z < 3 or Z != int(Z):
        out.append(f"needle_count = {Z:g}: must be a whole number >= 3 (fewer cannot hold the ring)")
    if not math.isclose(Rp + 2 * r_n + c, Ri, rel_tol=1e-9, abs_tol=1e-12):
        out.append(f"pin_radius_mm + 2 needle_radius_mm + pin_clearance_um = {Rp * 1e3:g} + "
                   f"{2 * r_n * 1e3:g} mm + {c * 1e6:g} um = {(Rp + 2 * r_n + c) * 1e3:g} mm: must "
                   f"equal roller_bore_mm = {Ri * 1e3:g} mm")
    pitch = Ri - r_n
    if Z >= 3 and pitch > 0 and 2 * pitch * math.sin(math.pi / Z) < 2 * r_n:
        zmax = int(math.pi / math.asin(min(1.0, r_n / pitch)))
        out.append(f"needle_count = {Z:g} needles of radius {r_n * 1e3:g} mm do not fit around the "
                   f"pitch circle of radius {pitch * 1e3:g} mm (they overlap by "
                   f"{(2 * r_n - 2 * pitch * math.sin(math.pi / Z)) * 1e6:.3g} um); at most {zmax} fit")
    return out


def _check_bodies(ck: _Checker, raw: dict, fo: dict, mats: dict) -> dict:
    """The real-body keys: which apply, their geometry, the pin/shaft materials. Returns the SI
    dict stored in ``Scene.bodies`` (empty for today's solid roller and local cam body)."""
    fraw = raw.get("follower", {}) if isinstance(raw.get("follower"), dict) else {}
    support = fo.get("roller_support", "solid")
    given = [k for k in _SUPPORT_KEYS["needles"] if k in fraw]
    needed = _SUPPORT_KEYS.get(support, ())
    for k in given:
        if k not in needed:
            ck.add(f"follower.{k}", f"= {_fmt(fraw[k])}: not used with roller_support = {support!r}")
    for k in needed:
        if k not in fraw:
            ck.add(f"follower.{k}", f"missing: required with roller_support = {support!r} "
                   f"(unit: {_FOLLOWER[k][0]})")
    out = {}
    if needed and all(k in fo for k in needed) and "roller_radius_mm" in fo:
        geo = dict(Ro=fo["roller_radius_mm"], Ri=fo["roller_bore_mm"], support=support,
                   Rp=fo["pin_radius_mm"], c=fo["pin_clearance_um"], Z=fo.get("needle_count", 0.0),
                   r_n=fo.get("needle_radius_mm", 0.0))
        for msg in roller_support_problems(**geo):
            ck.add("follower", msg)
        out.update(geo, Z=int(geo["Z"]))
    # [cam] is checked once, by _finite_length (one _CAM schema); here only a valid bore is used
    bore = raw.get("cam", {}).get("bore_mm") if isinstance(raw.get("cam"), dict) else None
    ok = isinstance(bore, int | float) and not isinstance(bore, bool) and math.isfinite(bore) and bore > 0
    cam = {"bore_mm": bore * 1e-3} if ok else {}
    if "bore_mm" in cam and "base_radius_mm" in fo and cam["bore_mm"] >= fo["base_radius_mm"]:
        ck.add("cam.bore_mm", f"= {_fmt(raw['cam']['bore_mm'])} mm: the shaft bore radius must be < "
               f"base_radius_mm = {fo['base_radius_mm'] * 1e3:g} mm")
    if "bore_mm" in cam:
        out["cam_bore"] = cam["bore_mm"]
    out.update({k: v for k, v in mats.items() if k in _BODY_MATERIALS})
    return out
