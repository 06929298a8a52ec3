"""The assessment inputs of a scene: lubricant, composite roughness, oil temperature, material
extras (yield, thermal, fatigue, scuffing), checked and converted to SI.

:func:`assessment_inputs` raises one :class:`~femcam.errors.SceneError` naming every missing or
contradictory key of a lubricated assessment (``[lubricant]``, ``[surface]``,
``[operating] oil_temperature_C``). Material extras are optional per criterion: a criterion whose
data are missing is skipped, and :attr:`AssessInputs.skipped` says which keys would enable it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .. import _validate
from .._repr import compact_repr
from ..errors import InputError, SceneError
from ..scene.schema import SI_NAMES
from ..scene.tribology import LubricantData, SurfaceRoughness, Tribology, given
from ..tribology.film import RQ_PER_RA
from ..tribology.lubricants import OILS, Lubricant, lubricant

#: material extras (scene key -> SI name) used by the assessment
MATERIAL_KEYS = {"yield_strength_MPa": "Y", "thermal_conductivity_W_per_m_K": "K",
                 "density_kg_per_m3": "rho", "specific_heat_J_per_kg_K": "c",
                 "contact_fatigue_strength_MPa": "sigma_Hlim", "contact_fatigue_cycles": "N_ref",
                 "contact_fatigue_exponent": "m", "shear_fatigue_limit_MPa": "tau_e",
                 "scuffing_temperature_C": "T_scuff"}
#: the same by the SI name the scene hands on (femcam.scene.schema.SI_NAMES)
_BY_SI_NAME = {SI_NAMES.get(k, k): sym for k, sym in MATERIAL_KEYS.items()}
#: criterion -> material keys it needs (in both bodies)
CRITERIA = {"flash temperature": ("thermal_conductivity_W_per_m_K", "density_kg_per_m3",
                                  "specific_heat_J_per_kg_K"),
            "scuffing": ("scuffing_temperature_C",),
            "yield and shakedown": ("yield_strength_MPa",),
            "subsurface fatigue": ("shear_fatigue_limit_MPa",),
            "surface fatigue": ("contact_fatigue_strength_MPa",)}


@dataclass(frozen=True)
class AssessInputs:
    """Checked assessment inputs (SI; temperatures in degC).

    Parameters
    ----------
    lubricant : Lubricant or None
        The oil; None for a dry assessment.
    sigma : float or None
        Composite RMS roughness of the two surfaces [m]; None when dry.
    T_oil : float or None
        Oil (inlet, bulk) temperature [degC]; None when dry.
    cam, roller : dict of str -> float
        Material extras per body, by SI name: ``Y``, ``sigma_Hlim``, ``tau_e`` [Pa], ``K``
        [W/(m K)], ``rho`` [kg/m^3], ``c`` [J/(kg K)], ``N_ref``, ``m`` [-], ``T_scuff`` [degC].
    skipped : dict of str -> list of str
        Criterion -> the scene keys that are missing for it.
    """

    lubricant: Lubricant | None
    sigma: float | None
    T_oil: float | None
    cam: dict
    roller: dict
    skipped: dict = field(default_factory=dict)

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    def has(self, criterion: str) -> bool:
        """Whether ``criterion`` (a key of :data:`CRITERIA`) has its data.

        Parameters
        ----------
        criterion : str
            Criterion name, e.g. ``"flash temperature"``.

        Returns
        -------
        bool
            False if the criterion is in :attr:`skipped`.
        """
        return criterion not in self.skipped


_EXPO_UNITS = {"viscosity_Pa_s": "Pa s", "temperature_C": "degC",
               "viscosity_temperature_coefficient_per_K": "1/K"}


def _viscosity_law(lub: LubricantData, base: dict, problems: list) -> dict:
    """Keyword arguments of the viscosity law of :class:`Lubricant` ({} and a problem if none)."""
    expo = [k for k in ("viscosity_Pa_s", "temperature_C", "viscosity_temperature_coefficient_per_K")
            if getattr(lub, k) is not None]
    walther = [k for k in ("kinematic_viscosity_40C", "kinematic_viscosity_100C")
               if getattr(lub, k) is not None]  # m^2/s
    visc = {}
    if expo and walther:
        problems.append("lubricant: give either viscosity_Pa_s + temperature_C + "
                        "viscosity_temperature_coefficient_per_K or the two kinematic viscosities, not both")
    elif expo:
        if len(expo) < 3:
            need = [f"{k} ({u})" for k, u in _EXPO_UNITS.items() if k not in expo]
            problems.append(f"lubricant: has {', '.join(expo)}; the exponential law also needs "
                            f"{', '.join(need)}")
        else:
            visc = dict(eta_ref=lub.viscosity_Pa_s, T_ref_C=lub.temperature_C,
                        beta_T=lub.viscosity_temperature_coefficient_per_K)
    elif walther:
        if len(walther) < 2:
            problems.append("lubricant: the ASTM D341 law needs both kinematic_viscosity_40C_mm2_per_s and "
                            "kinematic_viscosity_100C_mm2_per_s (mm^2/s)")
        else:
            visc = dict(nu40=lub.kinematic_viscosity_40C, nu100=lub.kinematic_viscosity_100C)
    elif "nu40" in base:
        visc = dict(nu40=base["nu40"], nu100=base["nu100"])
    else:
        problems.append("lubricant: missing viscosity: give name (a table oil) or viscosity_Pa_s (Pa s) + "
                        "temperature_C (degC) + viscosity_temperature_coefficient_per_K (1/K), or "
                        "kinematic_viscosity_40C_mm2_per_s + kinematic_viscosity_100C_mm2_per_s (mm^2/s)")
    return visc


def _first(*values):
    """The first value that is not None (None if all are)."""
    return next((v for v in values if v is not None), None)


def _lubricant(lub: LubricantData, problems: list) -> Lubricant | None:
    base = {}
    if lub.name in OILS:
        o = lubricant(lub.name)
        base = dict(nu40=o.nu40, nu100=o.nu100, rho=o.rho, alpha=o.alpha, source=o.source)
    elif lub.name is not None and not any(k.startswith(("viscosity", "kinematic")) for k in given(lub)):
        problems.append(f"lubricant.name = {lub.name!r}: not a table oil ({', '.join(map(repr, OILS))}); "
                        "or give its data (viscosity keys, pressure_viscosity_per_GPa, density_kg_per_m3)")
        return None
    if lub.pressure_viscosity is not None and lub.alpha_per_Pa is not None:  # both 1/Pa
        problems.append("lubricant: give pressure_viscosity_per_GPa (1/GPa) or alpha_per_Pa (1/Pa), not both")
    alpha = _first(lub.pressure_viscosity, lub.alpha_per_Pa, base.get("alpha"))
    rho = _first(lub.density_kg_per_m3, base.get("rho"))
    visc = _viscosity_law(lub, base, problems)
    if alpha is None:
        problems.append("lubricant.pressure_viscosity_per_GPa: missing (1/GPa; or alpha_per_Pa in 1/Pa)")
    if rho is None:
        problems.append("lubricant.density_kg_per_m3: missing (kg/m^3)")
    if problems or not visc:
        return None
    try:
        return Lubricant(name=_first(lub.name, "scene oil"), alpha=alpha, rho=rho,
                         source=_first(lub.source, base.get("source", "")), **visc)
    except InputError as exc:
        problems.append(f"lubricant: {exc}")
        return None


def _roughness(surf: SurfaceRoughness, problems: list) -> float | None:
    rq = []
    for body in ("cam", "roller"):
        ra, q = f"{body}_Ra", f"{body}_Rq"  # m (scene keys *_Ra_um, *_Rq_um)
        Ra, Rq = getattr(surf, ra), getattr(surf, q)
        if Ra is not None and Rq is not None:
            problems.append(f"surface: give {ra}_um or {q}_um (um), not both")
        elif Rq is not None:
            rq.append(Rq)
        elif Ra is not None:
            rq.append(RQ_PER_RA * Ra)          # Gaussian heights: Rq = sqrt(pi/2) Ra
        else:
            problems.append(f"surface.{ra}_um: missing (um; or {q}_um)")
    if len(rq) < 2:
        return None
    sigma = float((rq[0] ** 2 + rq[1] ** 2) ** 0.5)
    if sigma <= 0.0:
        problems.append("surface: composite roughness is 0 um: lambda = h/sigma is undefined")
        return None
    return sigma


def assessment_inputs(tribology: Tribology, *, lubricated: bool = True, where: str = "scene") -> AssessInputs:
    """Collect the assessment inputs of a scene's ``tribology`` (see the module docstring).

    Parameters
    ----------
    tribology : femcam.scene.tribology.Tribology
        The scene's assessment data (``Scene.tribology``, SI).
    lubricated : bool
        Require and read the lubricant, roughness and oil temperature.
    where : str
        The scene named in the error (its file, or its name).

    Returns
    -------
    AssessInputs
        The checked inputs (SI; temperatures in degC).

    Raises
    ------
    SceneError
        One error listing every missing or contradictory key of a lubricated assessment.
    """
    tri = _validate.instance("tribology", tribology, Tribology, "a femcam.scene.tribology.Tribology")
    problems: list[str] = []
    lub = sigma = T_oil = None
    if lubricated:
        if tri.lubricant is None:
            problems.append("[lubricant]: missing table; a lubricated assessment needs name (one of "
                            f"{', '.join(map(repr, OILS))}) or viscosity_Pa_s, temperature_C, "
                            "viscosity_temperature_coefficient_per_K, pressure_viscosity_per_GPa, "
                            "density_kg_per_m3")
        else:
            lub = _lubricant(tri.lubricant, problems)
        if tri.surface is None:
            problems.append("[surface]: missing table; give cam_Ra_um and roller_Ra_um (um; or *_Rq_um)")
        else:
            sigma = _roughness(tri.surface, problems)
        if tri.oil_temperature_C is None:
            problems.append("operating.oil_temperature_C: missing (degC), the inlet/bulk temperature")
        T_oil = tri.oil_temperature_C
        for key, T in (("operating.oil_temperature_C", T_oil),
                       ("lubricant.temperature_C", getattr(tri.lubricant, "temperature_C", None))):
            if T is not None and T <= -273.15:
                problems.append(f"{key} = {T:g} degC: must be above absolute zero (-273.15 degC)")
    if problems:
        n = len(problems)
        raise SceneError(f"scene {where}: {n} problem{'s' if n > 1 else ''} for the assessment\n  "
                         + "\n  ".join(problems))
    props = {b: {_BY_SI_NAME[k]: getattr(getattr(tri, b), k) for k in given(getattr(tri, b))}
             for b in ("cam", "roller")}
    skipped = {}
    for crit, keys in CRITERIA.items():
        miss = [f"[materials.{b}] {k}" for k in keys for b in ("cam", "roller")
                if MATERIAL_KEYS[k] not in props[b]]
        if miss:
            skipped[crit] = miss
    if not lubricated:
        skipped["scuffing"] = ["[operating] oil_temperature_C"]
    return AssessInputs(lubricant=lub, sigma=sigma, T_oil=T_oil, cam=props["cam"], roller=props["roller"],
                        skipped=skipped)
