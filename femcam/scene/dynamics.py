"""``[dynamics]``: the rigid-follower dynamics of seed 002 eq. 11 and the elastic follower train
(``model = one_dof | two_dof``, :mod:`femcam.dynamics`; docs/dynamics.md).

Masses in kg, stiffnesses in N/m, damping in N s/m or as a dimensionless ratio, preload in N.
"""

from __future__ import annotations

from ..dynamics import TrainModel, arm_train, lever_spring
from ..errors import InputError
from ..loads import ArmDynamics, FollowerDynamics
from .checker import _Checker, _fmt
from .follower import is_oscillating
from .schema import _ARM_DYNAMICS, _DYNAMICS, _TRAIN


def _dynamics(ck: _Checker, raw: dict, follower=None) -> tuple:
    """``(FollowerDynamics | ArmDynamics | None, TrainModel | None, steps_per_rev | None)`` from
    [dynamics] (exactly one of the two damping keys; the train of ``model = one_dof | two_dof``;
    ``follower``: the loaded follower, whose arm length refers an arm's train to its roller)."""
    g = raw.get("dynamics", {})
    dy = ck.table(g, "dynamics", _DYNAMICS)
    if not (isinstance(g, dict) and "dynamics" in raw):
        return None, None, None
    steps = int(dy["steps_per_rev"]) if "steps_per_rev" in dy else None
    if is_oscillating(raw):
        arm = _arm_dynamics(ck, g, dy)
        return arm, _arm_train(ck, g, dy, arm, getattr(follower, "L", None)), steps
    for k in _ARM_DYNAMICS:
        if k in g:
            ck.add(f"dynamics.{k}", f"= {_fmt(g[k])}: only an oscillating follower (motion = 'oscillating') "
                   "has this key")
    for k in ("mass_kg", "spring_N_per_m", "preload_N"):
        if k not in g:
            ck.add(f"dynamics.{k}", f"missing required key (unit: {_DYNAMICS[k][0]})")
    dyn = _follower_dynamics(ck, g, dy)
    return dyn, _train(ck, g, dy, dyn), steps


#: the linear spring of an arm and its lever (femcam.dynamics.arm.lever_spring)
_LEVER = ("spring_N_per_m", "preload_N", "spring_lever_mm")
#: the torsional spring of an arm
_TORSION = ("spring_rate_N_m_per_rad", "preload_N_m")
#: an arm's train keys in rotational units, and the translating train keys they replace
_ARM_TRAIN = {"train_stiffness_N_per_m": "train_stiffness_N_m_per_rad",
              "train_damping_N_s_per_m": "train_damping_N_m_s_per_rad",
              "second_mass_kg": "second_inertia_kg_m2",
              "second_stiffness_N_per_m": "second_stiffness_N_m_per_rad",
              "second_damping_N_s_per_m": "second_damping_N_m_s_per_rad"}


def _arm_spring(ck: _Checker, g: dict, dy: dict):
    """``(k_t, M_pl)`` of the arm's spring: torsional keys, or a linear spring on its lever
    (``k l^2``, ``F_pl l``; linearised, femcam.dynamics.arm.lever_spring); never both."""
    lever = [k for k in _LEVER if k in g]
    if lever and any(k in g for k in _TORSION):
        ck.add("dynamics.spring_lever_mm", f"= {_fmt(g.get('spring_lever_mm'))} mm: give the arm's spring "
               "either as torsional (spring_rate_N_m_per_rad, preload_N_m) or as linear on a lever "
               "(spring_N_per_m, preload_N, spring_lever_mm), not both")
        return None
    keys = _LEVER if lever else _TORSION
    for k in keys:
        if k not in g:
            ck.add(f"dynamics.{k}", f"missing required key for an oscillating follower (unit: "
                   f"{_DYNAMICS[k][0]})" + ("; a linear spring needs spring_N_per_m, preload_N and "
                                            "spring_lever_mm" if lever else ""))
    if not all(k in dy for k in keys):
        return None
    if lever:
        return lever_spring(dy["spring_N_per_m"], dy["spring_lever_mm"], dy["preload_N"])
    return dy["spring_rate_N_m_per_rad"], dy["preload_N_m"]


def _arm_dynamics(ck: _Checker, g: dict, dy: dict) -> ArmDynamics | None:
    """The arm of an oscillating follower: moment balance about the pivot
    (femcam.loads.arm_contact_force)."""
    for k in ("mass_kg", "damping_N_s_per_m", "damping_ratio"):
        if k in g:
            ck.add(f"dynamics.{k}", f"= {_fmt(g[k])} {_DYNAMICS[k][0]}: a translating follower's key; an "
                   "oscillating arm takes arm_inertia_kg_m2, spring_rate_N_m_per_rad, preload_N_m "
                   "(or spring_N_per_m, preload_N on spring_lever_mm), damping_N_m_s_per_rad")
    if "arm_inertia_kg_m2" not in g:
        ck.add("dynamics.arm_inertia_kg_m2", "missing required key for an oscillating follower "
               "(unit: kg m^2)")
    spring = _arm_spring(ck, g, dy)
    if spring is None or "arm_inertia_kg_m2" not in dy:
        return None
    return ArmDynamics(I=dy["arm_inertia_kg_m2"], k_t=spring[0], M_pl=spring[1],
                       c_t=dy.get("damping_N_m_s_per_rad", 0.0))


def _arm_train_keys(ck: _Checker, g: dict, dy: dict, model: str) -> None:
    """Report translating train keys, keys the model does not use and a fractional step count."""
    for k, rot in _ARM_TRAIN.items():
        if k in g:
            ck.add(f"dynamics.{k}", f"= {_fmt(g[k])} {_DYNAMICS[k][0]}: a translating train's key; an "
                   f"oscillating arm's train takes {rot} ({_DYNAMICS[rot][0]}) about the pivot")
    allowed = {"rigid": (), "one_dof": ("train_",), "two_dof": ("train_", "second_")}.get(model, ())
    for k in g:
        if (k.startswith(("train_", "second_")) and not k.startswith(allowed) and k not in _ARM_TRAIN
                or k == "steps_per_rev" and model == "rigid"):
            ck.add(f"dynamics.{k}", f"= {_fmt(g[k])}: not used by model = {model!r}")
    if "steps_per_rev" in dy and dy["steps_per_rev"] != int(dy["steps_per_rev"]):
        ck.add("dynamics.steps_per_rev", f"= {_fmt(g['steps_per_rev'])}: must be a whole number")


def _arm_train(ck: _Checker, g: dict, dy: dict, arm, L):
    """The elastic train of an arm (model = one_dof | two_dof) in rotational units, referred to
    the roller's arc travel (femcam.dynamics.arm.arm_train); None for model = "rigid"."""
    bad_model = "model" in g and "model" not in dy  # a bad model name, reported already
    model = dy.get("model", "rigid")
    _arm_train_keys(ck, g, dy, model)
    if bad_model or model == "rigid":
        return None
    need = ["train_stiffness_N_m_per_rad"] + (["second_inertia_kg_m2", "second_stiffness_N_m_per_rad"]
                                              if model == "two_dof" else [])
    ok = arm is not None and L is not None
    for k in need:
        if k not in g:
            ck.add(f"dynamics.{k}", f"missing required key for model = {model!r} of an oscillating arm "
                   f"(unit: {_DYNAMICS[k][0]})")
        ok = ok and k in dy
    damp = {}
    for p in ["train"] + (["second"] if model == "two_dof" else []):
        given = [k for k in (f"{p}_damping_ratio", f"{p}_damping_N_m_s_per_rad") if k in g]
        if len(given) != 1:
            ck.add("dynamics", f"model = {model!r}: give exactly one of {p}_damping_ratio "
                   f"(dimensionless) or {p}_damping_N_m_s_per_rad (N m s/rad); got {given or 'none'}")
        ok = ok and len(given) == 1 and given[0] in dy
        damp[p] = (dy.get(f"{p}_damping_N_m_s_per_rad"), dy.get(f"{p}_damping_ratio"))
    if not ok:
        return None
    sec = ({} if model == "one_dof" else
           {"I2": dy["second_inertia_kg_m2"], "K2": dy["second_stiffness_N_m_per_rad"],
            "C2": damp["second"][0], "zeta2": damp["second"][1]})
    try:
        return arm_train(arm, L, K_t=dy["train_stiffness_N_m_per_rad"], C_t=damp["train"][0],
                         zeta_t=damp["train"][1], **sec)
    except InputError as exc:  # arm_inertia_kg_m2 = 0: a massless arm has no train dynamics
        ck.add("dynamics.arm_inertia_kg_m2", f"= {_fmt(g['arm_inertia_kg_m2'])} kg m^2, model = {model!r}: "
               f"{exc}")
        return None


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

