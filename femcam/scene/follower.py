"""``[follower]`` and ``[cam]``: the follower geometry, the keys of one follower type, and the
finite-length contact keys of a roller (femcam.halfspace; docs/halfspace.md).

Lengths are given in mm (``_mm``) and um (``_um``), angles in deg; the checked values are SI.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..errors import InputError
from ..kinematics import CamProgram
from ..profile import (
    DIRECTIONS,
    OscillatingPadFollower,
    OscillatingRollerFollower,
    arm_geometry,
    make_follower,
)
from .checker import _Checker, _fmt
from .finite import FiniteLength
from .schema import _ARM, _CAM, _FINITE, _FINITE_SI, _FOLLOWER, _FOLLOWER_ONLY
from .state import _dense_theta


def is_oscillating(raw: dict) -> bool:
    """True when the parsed scene's ``[follower] motion`` is ``"oscillating"``.

    Parameters
    ----------
    raw : dict
        The parsed scene file.

    Returns
    -------
    bool
        ``[follower] motion == "oscillating"``.
    """
    g = raw.get("follower")
    return isinstance(g, dict) and g.get("motion") == "oscillating"


def _follower(ck: _Checker, raw: dict):
    """``(checked [follower] table in SI, follower or None)``."""
    g = raw.get("follower", {})
    fo = ck.table(g, "follower", _FOLLOWER)
    ftype = fo.get("type")
    follower = None
    if is_oscillating(raw):
        return fo, _oscillating(ck, g, fo, ftype)
    arm = [k for k in _ARM if isinstance(g, dict) and k in g and k != "motion"]
    if ftype == "curved_pad":
        ck.add("follower.type", "= 'curved_pad': a curved pad is modelled on an arm only (motion = "
               "'oscillating', pad_radius_mm); a translating curved face is type = 'knife_edge' with "
               "tip_radius_mm")
    elif arm:
        ck.add(f"follower.{arm[0]}", f"= {_fmt(g[arm[0]])}: only an oscillating follower (motion = "
               "'oscillating') has this key")
    elif ftype == "roller" and "roller_radius_mm" not in g:
        ck.add("follower.roller_radius_mm", "missing required key for a roller follower (unit: mm)")
    elif _follower_only_keys(ck, g, ftype):
        pass
    elif ftype in ("knife_edge", "flat_faced") and "roller_radius_mm" in g:
        ck.add("follower.roller_radius_mm", f"= {_fmt(g['roller_radius_mm'])}: "
               f"a {ftype} follower has no roller")
    elif ftype and isinstance(g, dict) and set(g) <= set(fo) and "base_radius_mm" in fo:
        try:
            follower = make_follower(ftype, Rb=fo["base_radius_mm"], Rr=fo.get("roller_radius_mm", 0.0),
                                     e=fo.get("offset_mm", 0.0))
        except InputError:  # only the offset can fail here: |e| < prime radius
            Rr_m = fo.get("roller_radius_mm", 0.0) if ftype == "roller" else 0.0
            Rp_mm = (fo["base_radius_mm"] + Rr_m) * 1e3
            ck.add("follower.offset_mm", f"= {_fmt(g['offset_mm'])} mm: must satisfy "
                   f"|offset| < prime-circle radius {Rp_mm:g} mm")
    return fo, follower


#: type -> (radius key, its own key that the other type refuses, follower class)
_ARM_TYPES = {"roller": ("roller_radius_mm", "pad_radius_mm", OscillatingRollerFollower),
              "curved_pad": ("pad_radius_mm", "roller_radius_mm", OscillatingPadFollower)}


def _oscillating(ck: _Checker, g: dict, fo: dict, ftype):
    """The OscillatingRollerFollower (``type = "roller"``) or OscillatingPadFollower (``type =
    "curved_pad"``) of ``motion = "oscillating"`` (None on a problem)."""
    if ftype not in (None, *_ARM_TYPES):
        ck.add("follower.type", f"= {_fmt(ftype)}: an oscillating follower is a roller (type = 'roller') "
               "or a curved pad (type = 'curved_pad'); knife-edge and flat-faced arms are not modelled")
        return None
    rkey, other, cls = _ARM_TYPES[ftype or "roller"]
    bad = [k for k in ("offset_mm", other, *_FOLLOWER_ONLY) if k in g]
    for k in bad:
        unit = f" {_FOLLOWER[k][0]}" if _FOLLOWER[k][0] else ""
        ck.add(f"follower.{k}", f"= {_fmt(g[k])}{unit}: not a key of an oscillating follower of type "
               f"'{ftype or 'roller'}' (its keys: pivot_distance_mm, arm_length_mm, direction, {rkey})")
    for k, unit in ((rkey, "mm"), ("pivot_distance_mm", "mm"), ("arm_length_mm", "mm")):
        if k not in g:
            ck.add(f"follower.{k}", f"missing required key for an oscillating follower (unit: {unit})")
    need = ("base_radius_mm", rkey, "pivot_distance_mm", "arm_length_mm")
    if bad or not all(k in fo for k in need) or ("direction" in g and "direction" not in fo):
        return None
    Rb, Rr, a, L = (fo[k] for k in need)
    what = rkey[:-len("_radius_mm")]
    if a <= Rb:
        ck.add("follower.pivot_distance_mm", f"= {_fmt(g['pivot_distance_mm'])} mm: the pivot lies inside "
               f"the base circle: must be > base_radius_mm = {_fmt(g['base_radius_mm'])} mm")
        return None
    if not abs(a - L) < Rb + Rr < a + L:
        key = rkey if Rb + Rr >= a + L else "arm_length_mm"  # a too large pad or roller names itself
        ck.add(f"follower.{key}", f"= {_fmt(g[key])} mm: the arm cannot put the {what} on the base "
               f"circle: need |pivot_distance_mm - arm_length_mm| < base_radius_mm + {rkey} = "
               f"{(Rb + Rr) * 1e3:g} mm < pivot_distance_mm + arm_length_mm = {(a + L) * 1e3:g} mm")
        return None
    return cls(Rb=Rb, Rr=Rr, a=a, L=L, sigma=DIRECTIONS[fo.get("direction", "away_from_pivot")])


def arm_program(program, follower):
    """The scene program of an oscillating follower: each lift (rad, from ``lift_deg``) times the
    arm length, the roller centre's arc travel ``L psi`` (m); other programs unchanged.

    Parameters
    ----------
    program : femcam.kinematics.CamProgram or None
        The checked program (lifts of an oscillating follower in rad).
    follower : object
        The checked follower.

    Returns
    -------
    femcam.kinematics.CamProgram or None
        The program in m.
    """
    if not getattr(follower, "oscillating", False) or program is None:
        return program
    L = follower.L
    return CamProgram([dataclasses.replace(sg, h=sg.h * L) if sg.h else sg for sg in program.segments])


def arm_fold(ck: _Checker, program, follower) -> None:
    """Refuse a program whose largest arm lift folds the arm past the line pivot-cam centre.

    Parameters
    ----------
    ck : _Checker
        Collects the problem.
    program : femcam.kinematics.CamProgram or None
        The checked program (lifts in rad for an oscillating follower).
    follower : object
        The checked follower (only an OscillatingRollerFollower is checked).
    """
    if not getattr(follower, "oscillating", False) or program is None:
        return
    top = program.h_max  # rad: checked before arm_program scales it
    if top >= follower.psi_fold:
        ck.add("program.segment.lift_deg", f"= {math.degrees(top):g} deg (the largest arm lift of the "
               f"program): folds the arm past the line pivot-cam centre; must be < "
               f"{math.degrees(follower.psi_fold):.4g} deg (180 deg - the base-circle arm angle "
               f"{math.degrees(follower.beta0):.4g} deg)")


def arm_self_locking(ck: _Checker, program, follower, mu) -> None:
    """Refuse a friction coefficient that self-locks the arm somewhere on the cam.

    The moment of a unit contact force about the pivot is ``D = L cos(phi) + mu s_f d_t``
    (:func:`femcam.loads.arm_lever`); where ``D <= 0`` no contact force drives the arm. Checked
    on the whole-cam grid of the undercut check (a sliding pad only; a roller's lever is 0).

    Parameters
    ----------
    ck : _Checker
        Collects the problem.
    program : femcam.kinematics.CamProgram or None
        The checked program (lifts in rad for an oscillating follower).
    follower : object
        The checked follower.
    mu : float or None
        The checked ``[contact] friction`` [-].
    """
    if not getattr(follower, "oscillating", False) or program is None or not mu:
        return
    th = _dense_theta(program)
    d = program.derivatives(th)
    try:
        lev = follower.friction_lever(d.s, d.s1, d.s2)
        D = follower.L * np.cos(arm_geometry(follower, d.s, d.s1, d.s2).phi) + mu * lev
    except InputError:  # a folded arm: reported by arm_fold
        return
    if np.any(D <= 0.0):
        i = int(np.argmin(D))
        ck.add("contact.friction", f"= {_fmt(mu)} (dimensionless): self-locks the arm at theta = "
               f"{math.degrees(th[i]):.2f} deg: the friction moment mu s_f d_t = {mu * lev[i] * 1e3:.4g} mm "
               f"per N of contact force cancels the normal force's L cos(phi) = "
               f"{(D[i] - mu * lev[i]) * 1e3:.4g} mm, so the cam cannot drive the arm; lower the "
               "friction or change pivot_distance_mm, arm_length_mm or pad_radius_mm")


def _follower_only_keys(ck: _Checker, raw, ftype) -> bool:
    """Report keys of another follower type (tip_radius_mm on a roller, ...); True if any."""
    bad = [k for k in _FOLLOWER_ONLY if ftype and isinstance(raw, dict) and k in raw
           and _FOLLOWER_ONLY[k] != ftype]
    for k in bad:
        ck.add(f"follower.{k}", f"= {_fmt(raw[k])}: only a {_FOLLOWER_ONLY[k]} follower has this key, "
               f"not a {ftype}")
    return bool(bad)



def _finite_length(ck: _Checker, raw: dict, fo: dict, ftype) -> FiniteLength | None:
    """Check the finite-length keys; returns them in SI as a :class:`FiniteLength`, or None
    (no face width, a follower without a roller, or a problem)."""
    cam = ck.table(raw.get("cam", {}), "cam", _CAM)
    graw = raw.get("follower", {}) if isinstance(raw.get("follower"), dict) else {}
    given = [k for k in _FINITE if k in graw]
    if given and ftype in ("knife_edge", "flat_faced"):
        ck.add(f"follower.{given[0]}", f"= {_fmt(graw[given[0]])}: a {ftype} follower has no roller")
        return None
    if any(k in graw and k not in fo for k in _FINITE) or "face_width_mm" not in fo:
        return None
    out = {v: fo[k] for k, v in _FINITE_SI.items() if k in fo}
    out.setdefault("roller_width", fo["face_width_mm"])
    out["cam_width"] = cam.get("face_width_mm", fo["face_width_mm"])
    finite = FiniteLength(**out)
    try:
        finite.roller_profile()
    except InputError as exc:
        msg = str(exc)
        for k, v in _FINITE_SI.items():  # name the scene key and unit, not the SI parameter
            if msg.startswith(v + " ") or msg.startswith(v + ":"):
                unit = _FINITE[k][0]
                ck.add(f"follower.{k}", f"= {_fmt(graw.get(k, fo.get(k)))}{' ' + unit if unit else ''}: "
                       f"{msg.split(': ', 1)[-1]}")
                return None
        ck.add("follower", msg)
        return None
    return finite
