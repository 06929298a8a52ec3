"""A scene's ``[wear]`` table: checked keys (units in the key names) and the wear coefficient used.

:func:`femcam.scene.load_scene` checks ``[wear]`` with the other tables (unknown key, value,
expected unit, a "did you mean" hint: :func:`femcam.scene.wear_table`, whose schema is
:data:`WEAR_KEYS`) into the typed record :class:`femcam.scene.wear.WearSettings`
(``Scene.wear``, SI), which checks its values again when built in code; the functions here
take that record.

Keys (all optional)
-------------------
=================  ==================  ===================================================
key                unit                meaning
=================  ==================  ===================================================
K                  (dimensionless)     Archard coefficient; needs the cam's hardness_MPa
k_mm3_per_N_m      mm^3/(N m)          dimensional coefficient k (instead of K)
roller_model       "srr" | "inertia"   roller slip model (default "srr")
srr                (dimensionless)     slide-to-roll ratio, -2 < srr < 2 (default 0.02)
J_kg_m2            kg m^2              roller polar inertia (inertia model)
T_drag_N_m         N m                 roller bearing drag torque (inertia model)
cycles             revolutions         number of cam revolutions (default 1e6)
=================  ==================  ===================================================

Wear coefficient (:func:`wear_coefficient_info`), in this order: ``k_mm3_per_N_m``; ``K`` with
``[materials.cam] hardness_MPa`` (``K`` without a hardness is an error: K alone has no unit of
wear); neither: seed 000's K = 1e-8 with the cam hardness if the scene gives one, else with
seed 000's H = 2000 N/mm^2. The returned text says which case applied.
"""

from __future__ import annotations

from .. import _validate
from ..errors import InputError, SceneError
from ..scene.schema import _WEAR
from ..scene.wear import WearSettings
from .archard import dimensional_coefficient

#: key -> (unit shown to the user, SI factor, check, required) -- the scene loader's schema
WEAR_KEYS = _WEAR

#: seed 000's inputs, the defaults
DEFAULT_K = 1e-8
DEFAULT_H = 2000e6


def wear_coefficient_info(wear: WearSettings, hardness: float | None) -> tuple[float, str]:
    """``(k, where)``: the dimensional wear coefficient (m^3/(N m)) a scene's ``[wear]`` asks
    for, and a sentence saying where it came from (scene key or default).

    Parameters
    ----------
    wear : femcam.scene.wear.WearSettings
        The scene's ``[wear]`` table in SI (``Scene.wear``).
    hardness : float or None
        Cam hardness [Pa] (``Scene.cam.hardness``); None: not given.

    Returns
    -------
    k : float
        Dimensional wear coefficient [m^3/(N m)].
    where : str
        Where ``k`` came from.

    Raises
    ------
    SceneError
        ``K`` without a cam hardness (K alone has no unit of wear).
    """
    wear = _validate.instance("wear", wear, WearSettings, "a femcam.scene.wear.WearSettings")
    hardness = _validate.optional(_validate.positive, "hardness", hardness, "Pa")
    if wear.k is not None:
        return wear.k, f"scene [wear] k_mm3_per_N_m = {wear.k * 1e9:g} mm^3/(N m)"
    if wear.K is not None:
        if not hardness:
            raise SceneError(f"wear.K = {wear.K:g} (dimensionless): needs the cam hardness "
                             "[materials.cam] hardness_MPa (MPa), k = K/H; or give k_mm3_per_N_m "
                             "(mm^3/(N m))")
        k = dimensional_coefficient(wear.K, hardness)
        return k, (f"scene [wear] K = {wear.K:g} / [materials.cam] hardness_MPa = "
                   f"{hardness / 1e6:g} MPa")
    if hardness:
        return dimensional_coefficient(DEFAULT_K, hardness), (
            f"default K = {DEFAULT_K:g} of seed 000, the scene gives no [wear] K or k_mm3_per_N_m; "
            f"H from the scene's [materials.cam] hardness_MPa = {hardness / 1e6:g} MPa")
    return dimensional_coefficient(DEFAULT_K, DEFAULT_H), (
        f"default: seed 000's K = {DEFAULT_K:g} and H = {DEFAULT_H / 1e6:g} N/mm^2; the scene gives "
        "no [wear] K or k_mm3_per_N_m and no [materials.cam] hardness_MPa")


def slip_kwargs(wear: WearSettings, *, omega: float, mu: float, follower) -> dict:
    """Keyword arguments of :func:`~femcam.wear.slip.follower_slip` from a scene's ``[wear]``
    settings, its speed, friction and follower.

    Parameters
    ----------
    wear : femcam.scene.wear.WearSettings
        The scene's ``[wear]`` table in SI (``Scene.wear``).
    omega : float
        Cam speed [rad/s].
    mu : float
        Friction coefficient [-] (the scene's, 0 included).
    follower : object
        The follower (its ``translating_roller`` flag).

    Returns
    -------
    dict
        ``omega`` [rad/s], ``roller_model``, ``srr`` [-], ``mu`` [-], ``J`` [kg m^2] or None,
        ``T_drag`` [N m].

    Raises
    ------
    InputError
        A roller follower with ``roller_model = "inertia"`` and friction 0: only friction spins
        the roller, so without it its speed is not set by the scene (refused with that reason).
    """
    wear = _validate.instance("wear", wear, WearSettings, "a femcam.scene.wear.WearSettings")
    if wear.roller_model == "inertia" and mu == 0 and getattr(follower, "translating_roller", False):
        # J dOmega/dt = mu Fc Rr - T_drag sign(Omega): with mu = 0 any constant spin (T_drag = 0)
        # is a periodic answer, or the roller coasts to rest: the scene does not set the speed
        raise InputError("contact.friction = 0: the inertia-limited roller model ([wear] roller_model "
                         "= 'inertia') needs friction > 0 (only friction spins the roller; without it "
                         "the roller speed is not set by the scene): give [contact] friction or use "
                         "roller_model = 'srr'")
    return dict(omega=omega, roller_model=wear.roller_model, srr=wear.srr, mu=mu, J=wear.J,
                T_drag=wear.T_drag)


def describe_k(k: float, where: str) -> str:
    """``k = 5e-18 m^3/(N m) = 5e-09 mm^3/(N m) (where)``.

    Parameters
    ----------
    k : float
        Dimensional wear coefficient [m^3/(N m)].
    where : str
        Where ``k`` came from.

    Returns
    -------
    str
        ``k`` in m^3/(N m) and mm^3/(N m) with its origin.
    """
    return f"k = {k:.4g} m^3/(N m) = {k * 1e9:.4g} mm^3/(N m) ({where})"

