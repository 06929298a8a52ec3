"""``[dynamics]``: the rigid-follower dynamics of seed 002 eq. 11 and the elastic follower train
(``model = one_dof | two_dof``, :mod:`femcam.dynamics`; docs/dynamics.md).

Masses in kg, stiffnesses in N/m, damping in N s/m or as a dimensionless ratio, preload in N.
"""

from __future__ import annotations

from ..dynamics import TrainModel
from ..errors import InputError
from ..loads import ArmDynamics, FollowerDynamics
from .checker import _Checker, _fmt
from .follower import is_oscillating
from .schema import _ARM_DYNAMICS, _DYNAMICS, _TRAIN

#: the keys of a translating follower's [dynamics] that an oscillating arm replaces
_TRANSLATING = ("mass_kg", "spring_N_per_m", "preload_N", "damping_N_s_per_m", "damping_ratio")


def _dynamics(ck: _Checker, raw: dict) -> tuple:
    """``(FollowerDynamics | None, TrainModel | None, steps_per_rev | None)`` from [dynamics]
    (exactly one of the two damping keys; the train of ``model = one_dof | two_dof``)."""
    g = raw.get("dynamics", {})
    dy = ck.table(g, "dynamics", _DYNAMICS)
    if not (isinstance(g, dict) and "dynamics" in raw):
        return None, None, None
    if is_oscillating(raw):
        return _arm_dynamics(ck, g, dy), None, None
    for k in _ARM_DYNAMICS:
        if k in g:
            ck.add(f"dynamics.{k}", f"= {_fmt(g[k])}: only an oscillating follower (motion = 'oscillating') "
                   "has this key")
    for k in ("mass_kg", "spring_N_per_m", "preload_N"):
        if k not in g:
            ck.add(f"dynamics.{k}", f"missing required key (unit: {_DYNAMICS[k][0]})")
    dyn = _follower_dynamics(ck, g, dy)
    steps = int(dy["steps_per_rev"]) if "steps_per_rev" in dy else None
    return dyn, _train(ck, g, dy, dyn), steps


def _arm_dynamics(ck: _Checker, g: dict, dy: dict) -> ArmDynamics | None:
    """The rigid arm of an oscillating follower: moment balance about the pivot
    (femcam.loads.arm_contact_force); the elastic train is not modelled for an arm."""
    for k in _TRANSLATING:
        if k in g:
            ck.add(f"dynamics.{k}", f"= {_fmt(g[k])} {_DYNAMICS[k][0]}: a translating follower's key; an "
                   "oscillating arm takes arm_inertia_kg_m2, spring_rate_N_m_per_rad, preload_N_m, "
                   "damping_N_m_s_per_rad")
    if g.get("model", "rigid") != "rigid" or any(k.startswith(("train_", "second_", "steps_")) for k in g):
        ck.add("dynamics.model", f"= {_fmt(g.get('model', 'rigid'))}: the elastic follower train (one_dof, "
               "two_dof) of an oscillating arm is not modelled; use model = 'rigid' (the moment balance "
               "about the pivot)")
    for k in ("arm_inertia_kg_m2", "spring_rate_N_m_per_rad", "preload_N_m"):
        if k not in g:
            ck.add(f"dynamics.{k}", f"missing required key for an oscillating follower (unit: "
                   f"{_ARM_DYNAMICS[k][0]})")
    if not all(k in dy for k in ("arm_inertia_kg_m2", "spring_rate_N_m_per_rad", "preload_N_m")):
        return None
    return ArmDynamics(I=dy["arm_inertia_kg_m2"], k_t=dy["spring_rate_N_m_per_rad"], M_pl=dy["preload_N_m"],
                       c_t=dy.get("damping_N_m_s_per_rad", 0.0))


def _follower_dynamics(ck: _Checker, g: dict, dy: dict) -> FollowerDynamics | None:
    """The rigid-follower dynamics of eq. 11 (mass, spring, preload, damping)."""
    given = [k for k in ("damping_N_s_per_m", "damping_ratio") if k in g]
    if len(given) != 1:
        ck.add("dynamics", "give exactly one of damping_N_s_per_m (N s/m) or damping_ratio "
               f"(dimensionless); got {given or 'none'}")
        return None
    if not all(k in dy for k in ("mass_kg", "spring_N_per_m", "preload_N", given[0])):
        return None
    try:
        return FollowerDynamics(m=dy["mass_kg"], k=dy["spring_N_per_m"], Fpl=dy["preload_N"],
                                c=dy.get("damping_N_s_per_m"), zeta=dy.get("damping_ratio"))
    except InputError:  # only a damping ratio with c_c = 2 sqrt(k m) = 0 fails here
        ck.add("dynamics.damping_ratio",
               f"= {_fmt(g['damping_ratio'])} (dimensionless): the critical "
               f"damping c_c = 2 sqrt(k m) = 2 sqrt({dy['spring_N_per_m']:g} N/m * "
               f"{dy['mass_kg']:g} kg) = 0 N s/m, so a ratio cannot set the damping; give "
               "damping_N_s_per_m (N s/m) instead")
        return None



def _train(ck: _Checker, raw: dict, dy: dict, dyn):
    """The TrainModel of [dynamics] (None for model = "rigid"); problems go to ``ck``."""
    if "model" in raw and "model" not in dy:  # a bad model name, reported already
        return None
    model = dy.get("model", "rigid")
    allowed = {"rigid": (), "one_dof": ("train_",), "two_dof": ("train_", "second_")}.get(model, ())
    for k in raw:
        if (k.startswith(("train_", "second_")) and not k.startswith(allowed)
                or k == "steps_per_rev" and model == "rigid"):
            ck.add(f"dynamics.{k}", f"= {_fmt(raw[k])}: not used by model = {model!r}")
    if "steps_per_rev" in dy and dy["steps_per_rev"] != int(dy["steps_per_rev"]):
        ck.add("dynamics.steps_per_rev", f"= {_fmt(raw['steps_per_rev'])}: must be a whole number")
    if model == "rigid":
        return None
    parts = ["train"] + (["second"] if model == "two_dof" else [])
    need = ["train_stiffness_N_per_m"] + (["second_mass_kg", "second_stiffness_N_per_m"]
                                          if model == "two_dof" else [])
    ok = dyn is not None
    for k in need:
        if k not in raw:
            ck.add(f"dynamics.{k}", f"missing required key for model = {model!r} (unit: {_TRAIN[k][0]})")
        ok = ok and k in dy
    for p in parts:
        given = [k for k in (f"{p}_damping_ratio", f"{p}_damping_N_s_per_m") if k in raw]
        if len(given) != 1:
            ck.add("dynamics", f"model = {model!r}: give exactly one of {p}_damping_ratio "
                   f"(dimensionless) or {p}_damping_N_s_per_m (N s/m); got {given or 'none'}")
        ok = ok and len(given) == 1 and given[0] in dy
    if not ok:
        return None
    sec = ({} if model == "one_dof" else
           {"m2": dy["second_mass_kg"], "k2": dy["second_stiffness_N_per_m"],
            "c2": dy.get("second_damping_N_s_per_m"), "zeta2": dy.get("second_damping_ratio")})
    try:
        return TrainModel(follower=dyn, k_t=dy["train_stiffness_N_per_m"],
                          c_t=dy.get("train_damping_N_s_per_m"), zeta_t=dy.get("train_damping_ratio"),
                          **sec)
    except InputError as exc:  # mass_kg = 0: a massless follower has no train dynamics
        ck.add("dynamics", f"model = {model!r}: {exc}")
        return None

