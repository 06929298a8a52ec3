"""The assessment data of a scene as typed records (:attr:`femcam.scene.Scene.tribology`):
the lubricant, the surface roughness, the oil temperature and each body's material data.

Values are SI under the SI names of :data:`femcam.scene.schema.SI_NAMES` (``cam_Ra`` in m,
``pressure_viscosity`` in 1/Pa, ``yield_strength`` in Pa); temperatures stay in degC, as
named. A field is None when the scene does not give it: which combinations an assessment
needs is decided by :func:`femcam.assess.assessment_inputs`, not here.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields

from .. import _validate


def _check(rec, units: dict) -> None:
    """Each given (not None) numeric field of ``rec`` checked by its rule in ``units``
    (``name -> (unit, "pos" | "nonneg" | "num")``), named ``<table>.<field>``."""
    where = rec._TABLE
    for name, (unit, rule) in units.items():
        v = getattr(rec, name)
        check = {"pos": _validate.positive, "nonneg": _validate.nonnegative, "num": _validate.number}[rule]
        object.__setattr__(rec, name, _validate.optional(check, f"{where}.{name}", v, unit))


def _text(rec, *names: str) -> None:
    """Each given text field of ``rec`` must be a str."""
    for n in names:
        v = getattr(rec, n)
        if v is not None and not isinstance(v, str):
            raise _validate.fail(f"{rec._TABLE}.{n}", v, "", "must be text")


def _repr(rec) -> str:
    """``Name(field=value, ...)`` of the given fields only (a compact line)."""
    return f"{type(rec).__name__}({', '.join(f'{n}={getattr(rec, n)!r}' for n in given(rec))})"


def given(rec) -> tuple[str, ...]:
    """The names of the fields of ``rec`` that the scene gives (not None).

    Parameters
    ----------
    rec : LubricantData, SurfaceRoughness or MaterialData
        A record of this module.

    Returns
    -------
    tuple of str
        Field names, in declaration order.

    >>> given(SurfaceRoughness(cam_Ra=2e-7))
    ('cam_Ra',)
    """
    return tuple(f.name for f in fields(rec) if getattr(rec, f.name) is not None)


@dataclass(frozen=True, kw_only=True)
class LubricantData:
    """The ``[lubricant]`` table, checked, in SI (keyword-only; None: not given).

    Parameters
    ----------
    name : str or None
        Oil name (a :data:`femcam.tribology.OILS` name, or the user's label).
    source : str or None
        Where the data come from (free text).
    viscosity_Pa_s : float or None
        Dynamic viscosity at ``temperature_C`` (Pa s; exponential law).
    temperature_C : float or None
        Reference temperature of ``viscosity_Pa_s`` (degC).
    viscosity_temperature_coefficient_per_K : float or None
        Exponential temperature-viscosity coefficient (1/K).
    kinematic_viscosity_40C, kinematic_viscosity_100C : float or None
        Kinematic viscosities at 40 and 100 degC (m^2/s; ASTM D341 law).
    pressure_viscosity : float or None
        Pressure-viscosity coefficient (1/Pa; from ``pressure_viscosity_per_GPa``).
    alpha_per_Pa : float or None
        The same coefficient given in 1/Pa.
    density_kg_per_m3 : float or None
        Density (kg/m^3).
    """

    _TABLE = "lubricant"
    name: str | None = None
    source: str | None = None
    viscosity_Pa_s: float | None = None
    temperature_C: float | None = None
    viscosity_temperature_coefficient_per_K: float | None = None
    kinematic_viscosity_40C: float | None = None
    kinematic_viscosity_100C: float | None = None
    pressure_viscosity: float | None = None
    alpha_per_Pa: float | None = None
    density_kg_per_m3: float | None = None

    def __post_init__(self):
        _text(self, "name", "source")
        _check(self, {"viscosity_Pa_s": ("Pa s", "pos"), "temperature_C": ("degC", "num"),
                      "viscosity_temperature_coefficient_per_K": ("1/K", "nonneg"),
                      "kinematic_viscosity_40C": ("m^2/s", "pos"),
                      "kinematic_viscosity_100C": ("m^2/s", "pos"),
                      "pressure_viscosity": ("1/Pa", "pos"), "alpha_per_Pa": ("1/Pa", "pos"),
                      "density_kg_per_m3": ("kg/m^3", "pos")})

    def __repr__(self) -> str:
        """The given fields only."""
        return _repr(self)


@dataclass(frozen=True, kw_only=True)
class SurfaceRoughness:
    """The ``[surface]`` table, checked, in SI (keyword-only; None: not given).

    Parameters
    ----------
    cam_Ra, roller_Ra : float or None
        Arithmetic mean roughness of the cam and the follower surface (m).
    cam_Rq, roller_Rq : float or None
        RMS roughness (m), instead of ``Ra``.
    """

    _TABLE = "surface"
    cam_Ra: float | None = None
    roller_Ra: float | None = None
    cam_Rq: float | None = None
    roller_Rq: float | None = None

    def __post_init__(self):
        _check(self, {k: ("m", "nonneg") for k in ("cam_Ra", "roller_Ra", "cam_Rq", "roller_Rq")})

    def __repr__(self) -> str:
        """The given fields only."""
        return _repr(self)


@dataclass(frozen=True, kw_only=True)
class MaterialData:
    """One body's material data for the assessment (``[materials.<body>]`` extras), in SI
    (keyword-only; None: not given).

    Parameters
    ----------
    yield_strength : float or None
        Yield strength (Pa).
    thermal_conductivity_W_per_m_K : float or None
        Thermal conductivity (W/(m K)).
    density_kg_per_m3 : float or None
        Density (kg/m^3).
    specific_heat_J_per_kg_K : float or None
        Specific heat (J/(kg K)).
    contact_fatigue_strength : float or None
        Contact fatigue strength sigma_Hlim (Pa).
    contact_fatigue_cycles : float or None
        Reference cycles of ``contact_fatigue_strength`` (cycles).
    contact_fatigue_exponent : float or None
        S-N exponent (dimensionless).
    shear_fatigue_limit : float or None
        Shear fatigue limit tau_e (Pa).
    scuffing_temperature_C : float or None
        Scuffing temperature (degC).
    """

    _TABLE = "materials"
    yield_strength: float | None = None
    thermal_conductivity_W_per_m_K: float | None = None
    density_kg_per_m3: float | None = None
    specific_heat_J_per_kg_K: float | None = None
    contact_fatigue_strength: float | None = None
    contact_fatigue_cycles: float | None = None
    contact_fatigue_exponent: float | None = None
    shear_fatigue_limit: float | None = None
    scuffing_temperature_C: float | None = None

    def __post_init__(self):
        _check(self, {"yield_strength": ("Pa", "pos"), "thermal_conductivity_W_per_m_K": ("W/(m K)", "pos"),
                      "density_kg_per_m3": ("kg/m^3", "pos"), "specific_heat_J_per_kg_K": ("J/(kg K)", "pos"),
                      "contact_fatigue_strength": ("Pa", "pos"), "contact_fatigue_cycles": ("cycles", "pos"),
                      "contact_fatigue_exponent": ("", "pos"), "shear_fatigue_limit": ("Pa", "pos"),
                      "scuffing_temperature_C": ("degC", "num")})

    def __repr__(self) -> str:
        """The given fields only."""
        return _repr(self)


#: the bodies that carry material data
BODIES = ("cam", "roller", "pin", "shaft")


@dataclass(frozen=True, kw_only=True)
class Tribology:
    """The assessment data of a scene (keyword-only; :mod:`femcam.assess` reads them).

    Parameters
    ----------
    lubricant : LubricantData or None
        ``[lubricant]``; None: not given (a dry scene).
    surface : SurfaceRoughness or None
        ``[surface]``; None: not given.
    oil_temperature_C : float or None
        ``[operating] oil_temperature_C``, the oil inlet/bulk temperature (degC).
    cam, roller, pin, shaft : MaterialData
        Each body's material data (empty: none given).
    """

    lubricant: LubricantData | None = None
    surface: SurfaceRoughness | None = None
    oil_temperature_C: float | None = None
    cam: MaterialData = field(default_factory=MaterialData)
    roller: MaterialData = field(default_factory=MaterialData)
    pin: MaterialData = field(default_factory=MaterialData)
    shaft: MaterialData = field(default_factory=MaterialData)

    def __post_init__(self):
        _validate.optional(_validate.instance, "tribology.lubricant", self.lubricant, LubricantData)
        _validate.optional(_validate.instance, "tribology.surface", self.surface, SurfaceRoughness)
        object.__setattr__(self, "oil_temperature_C", _validate.optional(
            _validate.number, "operating.oil_temperature_C", self.oil_temperature_C, "degC"))
        for b in BODIES:
            _validate.instance(f"tribology.{b}", getattr(self, b), MaterialData)

    def __repr__(self) -> str:
        """The given parts only (bodies without data left out)."""
        parts = [f"{n}={getattr(self, n)!r}" for n in ("lubricant", "surface", "oil_temperature_C")
                 if getattr(self, n) is not None]
        parts += [f"{b}={getattr(self, b)!r}" for b in BODIES if given(getattr(self, b))]
        return f"Tribology({', '.join(parts)})"

    @property
    def empty(self) -> bool:
        """True when the scene gives no assessment data at all."""
        return (self.lubricant is None and self.surface is None and self.oil_temperature_C is None
                and not any(given(getattr(self, b)) for b in BODIES))


def tribology_record(lubricant: dict | None, surface: dict | None, oil_temperature_C: float | None,
                     materials: dict) -> Tribology:
    """The :class:`Tribology` of checked SI tables (keys as :data:`~femcam.scene.schema.SI_NAMES`).

    Parameters
    ----------
    lubricant, surface : dict or None
        The checked ``[lubricant]`` and ``[surface]`` tables under SI names (None: not given).
    oil_temperature_C : float or None
        Oil temperature (degC).
    materials : dict
        ``{body: {SI name: value}}`` of the material data (Pa, W/(m K), ...).

    Returns
    -------
    Tribology
        The typed record.
    """
    return Tribology(lubricant=None if lubricant is None else LubricantData(**lubricant),
                     surface=None if surface is None else SurfaceRoughness(**surface),
                     oil_temperature_C=oil_temperature_C,
                     **{b: MaterialData(**materials.get(b, {})) for b in BODIES})
