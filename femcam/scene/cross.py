"""Cross-key limits of a scene: values each inside their own range (:mod:`femcam.scene.ranges`)
that do not fit together. Each problem names the scene keys it relates, their values and units.

* a coating at most :data:`COATING_MAX_FRACTION` of the coated body's radius (a surface layer,
  not a body: the Hertz reference and the FE body take the substrate's radius), one coated
  body per scene (femcam models one);
* a case shallower than half the hardened body (:meth:`femcam.layers.Case.check_body`, checked
  here against the scene keys), with a surface harder than the core by the case-depth
  criterion;
* a crown drop at most :data:`CROWN_DROP_MAX_FRACTION` of the roller radius;
* a pin clearance at most :data:`PIN_CLEARANCE_MAX` of the roller bore (linearised gap);
* a damping given in N s/m at most :data:`DAMPING_RATIO_MAX` times the critical damping
  ``2 sqrt(k m)`` (the ratio keys' own range);
* the roller-support keys on a roller follower only.
"""

from __future__ import annotations

import math

from .checker import _Checker, _fmt
from .ranges import RANGES
from .schema import _SUPPORT

#: largest coating thickness / coated body radius
COATING_MAX_FRACTION = 0.1
#: largest crown drop / roller radius
CROWN_DROP_MAX_FRACTION = 0.05
#: largest pin clearance / roller bore radius (femcam.bodies.geometry.RollerBearing)
PIN_CLEARANCE_MAX = 0.05
#: effective-case-depth criterion, core + 50 HV (DIN 50190-3): a case whose surface is not harder
#: than that has no case depth. The same value as femcam.layers.case.DELTA_H (restated: the
#: scene layer sits below layers; tests/test_scene_ranges.py checks they agree)
CASE_STEP_HV = 50.0
#: largest damping / critical damping (the range of the ``*_damping_ratio`` keys)
DAMPING_RATIO_MAX = RANGES["dynamics"]["damping_ratio"].hi


def _num(tab, key):
    """``tab[key]`` as a float when it is a finite number (else None: reported by the table)."""
    v = tab.get(key) if isinstance(tab, dict) else None
    ok = isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)
    return float(v) if ok else None


def _add(ck: _Checker, key: str, msg: str) -> None:
    """Add a cross-key problem unless ``key`` already has one (its own range, say)."""
    if not any(p.startswith(key + " ") or p.startswith(key + ":") for p in ck.problems):
        ck.add(key, msg)


def _body_radii(fraw: dict) -> dict:
    """Scene key and value (mm) of each body's radius: cam base radius, roller radius."""
    out = {}
    for body, key in (("cam", "base_radius_mm"), ("roller", "roller_radius_mm"),
                      ("follower", "roller_radius_mm"), ("pin", "pin_radius_mm")):
        if _num(fraw, key) is not None and _num(fraw, key) > 0:
            out[body] = (f"follower.{key}", _num(fraw, key))
    return out


def cross_key_problems(ck: _Checker, raw: dict) -> None:
    """Add the cross-key problems of the parsed scene ``raw`` to ``ck``.

    Parameters
    ----------
    ck : _Checker
        Collects the problems.
    raw : dict
        The parsed scene file (scene units).
    """
    fraw = raw.get("follower") if isinstance(raw.get("follower"), dict) else {}
    _layers(ck, raw, fraw)
    _crown(ck, fraw)
    _pin_clearance(ck, fraw)
    _damping(ck, raw.get("dynamics") if isinstance(raw.get("dynamics"), dict) else {})
    ftype = fraw.get("type")
    if ftype in ("knife_edge", "flat_faced"):
        for k in _SUPPORT:
            if k in fraw:
                _add(ck, f"follower.{k}", f"= {_fmt(fraw[k])}: a {ftype} follower has no roller "
                       "(roller_support and its keys are for type = 'roller')")


def _layers(ck: _Checker, raw: dict, fraw: dict) -> None:
    mraw = raw.get("materials") if isinstance(raw.get("materials"), dict) else {}
    radii = _body_radii(fraw)
    coated = [a for a, t in mraw.items() if isinstance(t, dict) and "coating" in t]
    if len(coated) > 1:
        ck.add("materials", f"coatings on {', '.join(f'[materials.{a}.coating]' for a in coated)}: "
               "femcam models one coated body per scene")
    for alias, tabs in mraw.items():
        if not isinstance(tabs, dict) or alias not in radii:
            continue
        rkey, R = radii[alias]
        t = _num(tabs.get("coating"), "thickness_um")
        if t is not None and t > COATING_MAX_FRACTION * R * 1e3:
            _add(ck, f"materials.{alias}.coating.thickness_um",
                   f"= {_fmt(tabs['coating']['thickness_um'])} um: must be <= {COATING_MAX_FRACTION:g} x "
                   f"{rkey} = {COATING_MAX_FRACTION * R * 1e3:g} um (a coating is a surface layer "
                   "on the body, not the body)")
        _case_pair(ck, alias, tabs.get("case"))
        d = _num(tabs.get("case"), "depth_mm")
        if d is not None and alias != "pin" and d >= 0.5 * R:
            _add(ck, f"materials.{alias}.case.depth_mm",
                   f"= {_fmt(tabs['case']['depth_mm'])} mm: must be < half of {rkey} = {0.5 * R:g} mm "
                   "(a case deeper than half the body is a through-hardened body)")


def _case_pair(ck: _Checker, alias: str, case) -> None:
    """Surface harder than the core by the case-depth criterion (hardness, or yield / 3)."""
    for s_key, c_key, step, unit in (("surface_hardness_HV", "core_hardness_HV", CASE_STEP_HV, "HV"),
                                     ("surface_yield_MPa", "core_yield_MPa",
                                      CASE_STEP_HV * 9.80665 / 3.0, "MPa")):
        s, c = _num(case, s_key), _num(case, c_key)
        if s is not None and c is not None and s - c <= step:
            _add(ck, f"materials.{alias}.case.{s_key}", f"= {_fmt(case[s_key])} {unit}: must exceed "
                 f"{c_key} = {_fmt(case[c_key])} {unit} by more than {step:.4g} {unit} (the case-depth "
                 "criterion core + 50 HV, DIN 50190-3)")


def _crown(ck: _Checker, fraw: dict) -> None:
    d, R = _num(fraw, "crown_drop_um"), _num(fraw, "roller_radius_mm")
    if d is not None and R is not None and R > 0 and d > CROWN_DROP_MAX_FRACTION * R * 1e3:
        _add(ck, "follower.crown_drop_um", f"= {_fmt(fraw['crown_drop_um'])} um: must be <= "
               f"{CROWN_DROP_MAX_FRACTION:g} x roller_radius_mm = {CROWN_DROP_MAX_FRACTION * R * 1e3:g} um "
               "(a crown is a small drop of the profile, not a change of the roller's shape)")


def _pin_clearance(ck: _Checker, fraw: dict) -> None:
    """The pin clearance against the bore (:class:`femcam.bodies.geometry.RollerBearing`'s
    linearised gap needs ``c <= 0.05 Ri``), refused at load rather than at run time."""
    c, Ri = _num(fraw, "pin_clearance_um"), _num(fraw, "roller_bore_mm")
    if c is not None and Ri is not None and Ri > 0 and c > PIN_CLEARANCE_MAX * Ri * 1e3:
        _add(ck, "follower.pin_clearance_um", f"= {_fmt(fraw['pin_clearance_um'])} um: must be <= "
             f"{PIN_CLEARANCE_MAX:g} x roller_bore_mm = {PIN_CLEARANCE_MAX * Ri * 1e3:g} um (the "
             "linearised pin-bore gap needs a clearance small against the bore)")


def _damping(ck: _Checker, dy: dict) -> None:
    """Damping in N s/m against the critical damping of its own mass and stiffness."""
    for ckey, kkey, mkey in (("damping_N_s_per_m", "spring_N_per_m", "mass_kg"),
                             ("train_damping_N_s_per_m", "train_stiffness_N_per_m", "mass_kg"),
                             ("second_damping_N_s_per_m", "second_stiffness_N_per_m", "second_mass_kg")):
        c, k, m = _num(dy, ckey), _num(dy, kkey), _num(dy, mkey)
        if c is None or k is None or m is None or k <= 0 or m <= 0:
            continue
        cc = 2.0 * math.sqrt(k * m)
        if c > DAMPING_RATIO_MAX * cc:
            _add(ck, f"dynamics.{ckey}", f"= {_fmt(dy[ckey])} N s/m: must be <= {DAMPING_RATIO_MAX:g} x the "
                   f"critical damping 2 sqrt({kkey} * {mkey}) = {cc:.4g} N s/m (ratio {c / cc:.3g})")
