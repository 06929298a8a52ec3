"""A scene's ``[wear]`` table: checked keys (units in the key names) and the wear coefficient used.

:func:`femcam.scene.load_scene` checks ``[wear]`` with the other tables (unknown key, value,
expected unit, a "did you mean" hint: :func:`femcam.scene.wear_table`, whose schema is
:data:`WEAR_KEYS`); :func:`wear_options` checks it again for a scene built in code or edited
with ``dataclasses.replace`` and raises one :class:`~femcam.errors.SceneError` listing every
problem.

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

from ..errors import InputError
from ..scene import wear_table
from ..scene.checker import _Checker
from ..scene.schema import _WEAR
from .archard import dimensional_coefficient

#: key -> (unit shown to the user, SI factor, check, required) -- the scene loader's schema
WEAR_KEYS = _WEAR

#: seed 000's inputs, the defaults
DEFAULT_K = 1e-8
DEFAULT_H = 2000e6


def wear_options(scene) -> dict:
    """The scene's ``[wear]`` table checked and converted to SI (keys as in the table).

    Raises :class:`~femcam.errors.SceneError` (an ``InputError``) naming every unknown key or
    bad value with the expected unit, e.g. ``wear.k = 1e-17: unknown key; did you mean
    'k_mm3_per_N_m' in mm^3/(N m)? (units go in the key name)``.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (its ``wear`` table, cam hardness [Pa], source path).

    Returns
    -------
    dict of str -> float or str
        The checked ``[wear]`` keys with SI values under SI names (``k`` in m^3/(N m), ``J_kg_m2``
        in kg m^2, ``T_drag_N_m`` in N m, ``tip_radius`` in m, ``cycles`` in revolutions).

    Raises
    ------
    SceneError
        Every unknown key or bad value.
    """
    ck = _Checker(scene.source_path or scene.name)
    out = wear_table(ck, dict(scene.wear or {}), scene.cam.hardness)
    ck.raise_if_any()
    return out


def wear_coefficient_info(scene) -> tuple[float, str]:
    """``(k, where)``: the dimensional wear coefficient (m^3/(N m)) the scene asks for, and a
    sentence saying where it came from (scene key or default).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (its ``wear`` table, cam hardness [Pa], source path).

    Returns
    -------
    k : float
        Dimensional wear coefficient [m^3/(N m)].
    where : str
        Where ``k`` came from.

    Raises
    ------
    SceneError
        A bad ``[wear]`` table.
    """
    opts = wear_options(scene)
    hardness = scene.cam.hardness
    if "k" in opts:
        k = opts["k"]
        return k, f"scene [wear] k_mm3_per_N_m = {k * 1e9:g} mm^3/(N m)"
    if "K" in opts:
        k = dimensional_coefficient(opts["K"], hardness)
        return k, (f"scene [wear] K = {opts['K']:g} / [materials.cam] hardness_MPa = "
                   f"{hardness / 1e6:g} MPa")
    if hardness:
        return dimensional_coefficient(DEFAULT_K, hardness), (
            f"default K = {DEFAULT_K:g} of seed 000, the scene gives no [wear] K or k_mm3_per_N_m; "
            f"H from the scene's [materials.cam] hardness_MPa = {hardness / 1e6:g} MPa")
    return dimensional_coefficient(DEFAULT_K, DEFAULT_H), (
        f"default: seed 000's K = {DEFAULT_K:g} and H = {DEFAULT_H / 1e6:g} N/mm^2; the scene gives "
        "no [wear] K or k_mm3_per_N_m and no [materials.cam] hardness_MPa")


def slip_kwargs(scene, opts: dict | None = None) -> dict:
    """Keyword arguments of :func:`~femcam.wear.slip.follower_slip` from the scene (``omega``,
    ``mu``) and its checked ``[wear]`` table ``opts`` (default: :func:`wear_options`).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (``omega`` [rad/s], ``mu`` [-]).
    opts : dict, optional
        Checked SI ``[wear]`` table; default :func:`wear_options` of ``scene``.

    Returns
    -------
    dict
        ``omega`` [rad/s], ``roller_model``, ``srr`` [-], ``mu`` [-] (the scene's friction, 0
        included), ``J`` [kg m^2] or None, ``T_drag`` [N m].

    Raises
    ------
    InputError
        A roller follower with ``roller_model = "inertia"`` and friction 0: only friction spins
        the roller, so without it its speed is not set by the scene (refused with that reason).
    """
    if opts is None:
        opts = wear_options(scene)
    model = opts.get("roller_model", "srr")
    if model == "inertia" and scene.mu == 0 and getattr(scene.follower, "translating_roller", False):
        # J dOmega/dt = mu Fc Rr - T_drag sign(Omega): with mu = 0 any constant spin (T_drag = 0)
        # is a periodic answer, or the roller coasts to rest: the scene does not set the speed
        raise InputError("contact.friction = 0: the inertia-limited roller model ([wear] roller_model "
                         "= 'inertia') needs friction > 0 (only friction spins the roller; without it "
                         "the roller speed is not set by the scene): give [contact] friction or use "
                         "roller_model = 'srr'")
    return dict(omega=scene.omega, roller_model=model, srr=opts.get("srr", 0.02),
                mu=scene.mu, J=opts.get("J_kg_m2"), T_drag=opts.get("T_drag_N_m", 0.0))


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


def follower_tip_radius(scene) -> float | None:
    """Knife-edge tip radius (m) of a scene: ``[follower] tip_radius_mm`` (``Scene.tip_radius``);
    None if not given (the former ``[wear] tip_radius_mm`` is refused by the scene loader).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (its ``wear`` table, cam hardness [Pa], source path).

    Returns
    -------
    float or None
        Tip radius [m], or None.
    """
    return getattr(scene, "tip_radius", None)
