"""Real bodies (:mod:`femcam.bodies`; docs/bodies.md): the roller as a ring on a pin or needles
(``[follower] roller_support``) and the cam on a shaft (``[cam] bore_mm``).

Radii in mm, the clearance in um; the checked values are SI, handed on as the typed records
:class:`RealBodies` (:class:`RollerSupport`, :class:`CamShaft`) that femcam.bodies reads.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..materials import Material
from .checker import _Checker, _fmt
from .schema import _FOLLOWER, _SUPPORT_KEYS


@dataclass(frozen=True, kw_only=True)
class RollerSupport:
    """The roller as a ring on a pin or on needles, in SI (built by the scene loader from
    ``[follower] roller_support``, ``roller_radius_mm``, ``roller_bore_mm``, ``pin_radius_mm``,
    ``pin_clearance_um``, ``needle_count``, ``needle_radius_mm`` and ``[materials.pin]``, after
    :func:`roller_support_problems` found none).

    Parameters
    ----------
    support : {"pin", "needles"}
        What carries the ring.
    Ro : float
        Roller (ring) outer radius (m).
    Ri : float
        Roller bore radius (m).
    Rp : float
        Pin radius (m).
    c : float
        Radial clearance (m).
    Z : int
        Number of needles (0 for a pin).
    r_n : float
        Needle radius (m; 0 for a pin).
    pin : femcam.materials.Material or None
        ``[materials.pin]`` (Pa), also the needles'; None: the roller's material.
    """

    support: str
    Ro: float
    Ri: float
    Rp: float
    c: float
    Z: int = 0
    r_n: float = 0.0
    pin: Material | None = None


@dataclass(frozen=True, kw_only=True)
class CamShaft:
    """The cam as a disk on its shaft, in SI (built by the scene loader from ``[cam] bore_mm``,
    ``shaft_fit``, ``shaft_clearance_um`` and ``[materials.shaft]``).

    Parameters
    ----------
    bore : float
        Shaft bore radius of the cam (m).
    fit : {"contact", "bonded"}
        Shaft-bore fit.
    clearance : float
        Radial shaft clearance (m; shaft radius ``bore - clearance``).
    shaft : femcam.materials.Material or None
        ``[materials.shaft]`` (Pa); None: the cam's material.
    """

    bore: float
    fit: str = "contact"
    clearance: float = 0.0
    shaft: Material | None = None


@dataclass(frozen=True, kw_only=True)
class RealBodies:
    """The real bodies of a scene (femcam.bodies; docs/bodies.md): both None for the solid
    roller and the cam as a local body.

    Parameters
    ----------
    roller : RollerSupport or None
        The roller on a pin or needles; None: ``roller_support = "solid"``.
    cam : CamShaft or None
        The cam on its shaft; None: no ``[cam] bore_mm``.
    """

    roller: RollerSupport | None = None
    cam: CamShaft | None = None


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


def _check_bodies(ck: _Checker, raw: dict, fo: dict, mats: dict) -> RealBodies:
    """The real-body keys: which apply, their geometry, the pin/shaft materials. Returns the
    record stored in ``Scene.bodies`` (both parts None for the solid roller and local cam body)."""
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
    roller = cam = None
    if needed and all(k in fo for k in needed) and "roller_radius_mm" in fo:
        geo = dict(Ro=fo["roller_radius_mm"], Ri=fo["roller_bore_mm"], support=support,
                   Rp=fo["pin_radius_mm"], c=fo["pin_clearance_um"], Z=fo.get("needle_count", 0.0),
                   r_n=fo.get("needle_radius_mm", 0.0))
        problems = roller_support_problems(**geo)
        for msg in problems:
            ck.add("follower", msg)
        if not problems:
            roller = RollerSupport(**(geo | {"Z": int(geo["Z"])}), pin=mats.get("pin"))
    # [cam] is checked once, by _finite_length (one _CAM schema); here only valid values are used
    craw = raw.get("cam", {}) if isinstance(raw.get("cam"), dict) else {}
    bore = _valid_number(craw.get("bore_mm"), positive=True)
    if bore is not None and "base_radius_mm" in fo and bore * 1e-3 >= fo["base_radius_mm"]:
        ck.add("cam.bore_mm", f"= {_fmt(craw['bore_mm'])} mm: the shaft bore radius must be < "
               f"base_radius_mm = {fo['base_radius_mm'] * 1e3:g} mm")
    fit = _shaft_fit(ck, craw, bore)
    if bore is not None:
        cam = CamShaft(bore=bore * 1e-3, **fit, shaft=mats.get("shaft"))
    return RealBodies(roller=roller, cam=cam)


def _valid_number(v, *, positive: bool):
    """``v`` as a float when it is a finite number (> 0 or >= 0), else None (the schema check
    has already reported it)."""
    ok = isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)
    return float(v) if ok and (v > 0 if positive else v >= 0) else None


#: largest shaft clearance / bore radius (the linearised gap ``c - e cos psi`` of the shaft-bore
#: contact needs ``c << Rb``; :class:`femcam.bodies.cam_geometry.CamDisk` refuses more)
SHAFT_CLEARANCE_MAX = 0.05


def shaft_fit_problems(*, bore_mm, fit, clearance_um) -> list[str]:
    """Problems of the ``[cam]`` shaft-fit keys (scene units): a fit or clearance without a
    bore, a clearance above :data:`SHAFT_CLEARANCE_MAX` x bore, a bonded fit with a clearance.

    Parameters
    ----------
    bore_mm : float or None
        ``[cam] bore_mm`` (mm), None when not given.
    fit : str or None
        ``"contact"`` or ``"bonded"``; None when not given (contact).
    clearance_um : float or None
        ``[cam] shaft_clearance_um`` (um, >= 0), None when not given (0).

    Returns
    -------
    list of str
        ``"cam.<key> = value unit: reason"`` lines; empty when the keys fit.

    Examples
    --------
    >>> shaft_fit_problems(bore_mm=6.0, fit="contact", clearance_um=10.0)
    []
    >>> for m in shaft_fit_problems(bore_mm=6.0, fit="bonded", clearance_um=400.0):
    ...     print(m.split(" (")[0])
    cam.shaft_clearance_um = 400 um: must be <= 0.05 x bore_mm
    cam.shaft_fit = 'bonded' with shaft_clearance_um = 400 um: a bonded fit has no clearance
    """
    given = [(k, v) for k, v in (("shaft_fit", fit), ("shaft_clearance_um", clearance_um)) if v is not None]
    if bore_mm is None:
        unit = {"shaft_clearance_um": " um"}
        return [f"cam.{k} = {_fmt(v)}{unit.get(k, '')}: needs cam.bore_mm "
                "(the cam on its shaft); without it the cam is "
                "today's local body" for k, v in given]
    out = []
    c_max = SHAFT_CLEARANCE_MAX * bore_mm * 1e3
    if clearance_um is not None and clearance_um > c_max:
        out.append(f"cam.shaft_clearance_um = {clearance_um:g} um: must be <= {SHAFT_CLEARANCE_MAX:g} x "
                   f"bore_mm ({bore_mm:g} mm) = {c_max:g} um (linearised shaft-bore gap: clearance << bore)")
    if fit == "bonded" and clearance_um:
        out.append(f"cam.shaft_fit = 'bonded' with shaft_clearance_um = {clearance_um:g} um: a bonded "
                   "fit has no clearance (give 0 um, or shaft_fit = 'contact')")
    return out


def _shaft_fit(ck: _Checker, craw: dict, bore) -> dict:
    """The checked ``[cam] shaft_fit``, ``shaft_clearance_um`` as ``{"fit": str, "clearance": m}``
    (defaults "contact", 0 with a bore; {} without one or on a problem)."""
    fit = craw.get("shaft_fit") if craw.get("shaft_fit") in ("contact", "bonded") else None
    c = _valid_number(craw.get("shaft_clearance_um"), positive=False)
    problems = shaft_fit_problems(bore_mm=bore, fit=fit, clearance_um=c)
    for msg in problems:
        key, rest = msg.split(" ", 1)
        ck.add(key, rest)
    if bore is None or problems:
        return {}
    return {"fit": fit or "contact", "clearance": (c or 0.0) * 1e-6}
