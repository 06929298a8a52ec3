"""Per-angle assessment of a cam-follower scene: film, flash temperature, yield, shakedown,
contact fatigue, scuffing and the wear coefficient of the lubrication regime.

The functions take the scene's contact as a :class:`femcam.scene.case.ContactCase`
(``contact_case(scene, theta)``) and the coated bodies (``(body, coating)`` pairs) from the caller.

Chain per cam angle (vectorised): :meth:`Scene.analyse` (kinematics, profile, contact force; the
case's ``state``) ->
:func:`femcam.wear.slip.follower_slip` (surface speeds ``u1 = V_cam``, ``u2 = V_follower``; roller
slip model of the scene's ``[wear]``) -> :class:`femcam.hertz.LineContact` (or the FE ``a``/``p0``
of a sweep table) -> :mod:`femcam.tribology` formulas.

Followers: roller (``R2 = Rr``, slip model), knife-edge with a tip radius (``[follower]
tip_radius_mm``; the cam cut for the radiused tip, full sliding; a sharp tip is refused: it has no
contact width), flat-faced (``R2 = inf``; the entrainment speed ``(u1 + u2)/2`` passes through zero
where ``rho + s'' = 0``... and the film collapses there, flagged ``no_entrainment``).

Columns (:data:`COLUMNS`: SI name, CSV name, factor) are returned by :func:`assess_rows`; text
columns are ``regime`` and ``flags`` (``;``-separated: ``liftoff``, ``no_entrainment``,
``W_range``, ``U_range``, ``low_peclet``, ``hertz_validity``, ``dtau_hertz``: an FE row with
FE stresses but no finite ``txz_range_max``, so its orthogonal-shear range is Hertz's shape
factor at the FE ``p0``; ``omits_coating``: a contact row of a coated scene, assessed as if the
coated body were homogeneous, :func:`omitted_physics`).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from .. import _validate
from .._columns import Column
from .._repr import compact_repr, dataframe
from ..errors import InputError
from ..hertz import HertzValidityWarning, LineContact
from ..layers.from_scene import coating_phrase
from ..scene.case import ContactCase
from ..tribology import fatigue, film, flash
from ..tribology.regime import wear_coefficient
from ..wear.options import slip_kwargs, wear_coefficient_info
from ..wear.slip import follower_slip
from .inputs import AssessInputs, assessment_inputs

#: the assessment's columns (:class:`femcam._columns.Column`)
COLUMNS = (
    Column("theta", "theta_deg", 180.0 / math.pi),
    Column("Fc", "Fc_N", 1.0),
    Column("cam_x", "cam_x_mm", 1e3),
    Column("cam_y", "cam_y_mm", 1e3),
    Column("R", "R_eff_mm", 1e3),
    Column("a", "a_um", 1e6),
    Column("p0", "p0_MPa", 1e-6),
    Column("u_cam", "u_cam_m_per_s", 1.0),
    Column("u_follower", "u_follower_m_per_s", 1.0),
    Column("U", "U_entrain_m_per_s", 1.0),
    Column("v_slide", "v_slide_m_per_s", 1.0),
    Column("eta0", "eta0_mPa_s", 1e3),
    Column("h_min", "h_min_um", 1e6),
    Column("h_c", "h_c_um", 1e6),
    Column("lam", "lambda", 1.0),
    Column("dT_flash", "dT_flash_K", 1.0),
    Column("T_contact", "T_contact_C", 1.0),
    Column("Pe_cam", "Pe_cam", 1.0),
    Column("Pe_follower", "Pe_follower", 1.0),
    Column("p0_over_k", "p0_over_k", 1.0),
    Column("sf_yield", "sf_yield", 1.0),
    Column("sf_shakedown", "sf_shakedown", 1.0),
    Column("dtau_orth", "dtau_orth_MPa", 1e-6),
    Column("util_subsurface", "util_subsurface", 1.0),
    Column("sf_subsurface", "sf_subsurface", 1.0),
    Column("sf_surface_fatigue", "sf_surface_fatigue", 1.0),
    Column("N_pitting", "N_pitting_cycles", 1.0),
    Column("sf_scuffing", "sf_scuffing", 1.0),
    Column("k_wear", "k_wear_mm3_per_N_m", 1e9),
)
TEXT = ("regime", "flags")
#: criterion -> (column, "min"|"max") for the worst-angle summary
WORST = {"film (lambda)": ("lam", "min"), "contact temperature": ("T_contact", "max"),
         "scuffing": ("sf_scuffing", "min"), "first yield": ("sf_yield", "min"),
         "shakedown": ("sf_shakedown", "min"), "subsurface fatigue": ("sf_subsurface", "min"),
         "surface fatigue": ("sf_surface_fatigue", "min"), "pitting life": ("N_pitting", "min")}


def _case(case) -> ContactCase:
    return _validate.instance("case", case, ContactCase, "a femcam.scene.case.ContactCase "
                              "(femcam.scene.case.contact_case(scene, theta))")


def _geometry(case: ContactCase):
    """``(R2 in m, tip radius or None)`` per follower type (a knife edge's case state is the cam
    cut for its radiused tip)."""
    if getattr(case.follower, "draws_circle", False):  # R2 = Rr: a roller, on a slide or an arm, or a pad
        return case.follower.Rr, None
    if getattr(case.follower, "flat_face", False):
        return math.inf, None
    if case.tip_radius is None:
        raise InputError("follower type = knife_edge: a sharp tip has no contact width, so film, "
                         "pressure and temperatures are undefined; give the tip radius: scene [follower] "
                         "tip_radius_mm (mm)")
    return case.tip_radius, case.tip_radius


def _contact(case: ContactCase, st, R2, table, n):
    """Hertz (or FE from ``table``) ``a, p0, w, R, E_star, valid`` per angle."""
    Fc = np.where(st.liftoff, 0.0, np.clip(st.Fc, 0.0, None))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", HertzValidityWarning)   # reported per angle in flags
        pr = case.pair
        hc = LineContact(F=Fc, length=pr.length, R1=st.rho, R2=R2, cam=pr.cam, roller=pr.roller, mu=pr.mu,
                         plane=pr.plane)
    a, p0 = np.broadcast_to(hc.a, (n,)).copy(), np.broadcast_to(hc.p0, (n,)).copy()
    source = np.full(n, "hertz", dtype=object)
    if table is not None and "a_fe" in table and "p0_fe" in table:
        a_fe, p_fe = np.asarray(table["a_fe"], float), np.asarray(table["p0_fe"], float)
        use = np.isfinite(a_fe) & np.isfinite(p_fe) & (a_fe > 0)
        a, p0 = np.where(use, a_fe, a), np.where(use, p_fe, p0)
        source[use] = "fe"
    w = Fc / case.pair.length
    return Fc, a, p0, w, np.broadcast_to(hc.R, (n,)), hc.E_star, np.broadcast_to(hc.valid, (n,)), source


def _speeds(case: ContactCase, st, theta, Fc, tip):
    """Surface speeds ``(V_cam, V_follower)`` at ``theta``. The inertia-limited roller model needs
    one whole revolution: for any other set of angles (a sweep chunk) it is solved on the case's
    ``revolution`` angles and interpolated (periodic, linear)."""
    kw = slip_kwargs(case.wear, omega=case.omega, mu=case.pair.mu, follower=case.follower)
    full = theta.size >= 4 and np.allclose(np.diff(theta), theta[1] - theta[0]) and \
        abs(theta[-1] - theta[0] + (theta[1] - theta[0]) - 2.0 * math.pi) < 1e-9
    if kw["roller_model"] != "inertia" or case.revolution is None or full:
        r = follower_slip(case.follower, theta, st.s, st.s1, st.s2, Fc=Fc, tip_radius=tip, **kw)
        return r.V_cam, r.V_follower
    sg = case.revolution
    grid = sg.theta
    r = follower_slip(case.follower, grid, sg.s, sg.s1, sg.s2, Fc=np.where(sg.liftoff, 0.0, sg.Fc), **kw)
    th = np.mod(theta, 2.0 * math.pi)
    return (np.interp(th, grid, r.V_cam, period=2.0 * math.pi),
            np.interp(th, grid, r.V_follower, period=2.0 * math.pi))


def _pair(inp: AssessInputs, key: str):
    return inp.cam.get(key), inp.roller.get(key)


def _thermal(inp, mu, w, a, u1, u2, T_oil, out, flags):
    if not inp.has("flash temperature"):
        return
    b1, b2 = (flash.effusivity(m["K"], m["rho"], m["c"]) for m in (inp.cam, inp.roller))
    k1, k2 = (m["K"] / (m["rho"] * m["c"]) for m in (inp.cam, inp.roller))
    out["dT_flash"] = flash.flash_temperature(mu, w, a, u1, u2, b1, b2)
    out["Pe_cam"], out["Pe_follower"] = flash.peclet(u1, a, k1), flash.peclet(u2, a, k2)
    flags.append(("low_peclet", (np.minimum(out["Pe_cam"], out["Pe_follower"]) < flash.PECLET_MIN)
                  & (out["dT_flash"] > 0)))
    if T_oil is not None:
        out["T_contact"] = T_oil + out["dT_flash"]
        if inp.has("scuffing"):
            out["sf_scuffing"] = flash.scuffing_safety(min(_pair(inp, "T_scuff")), T_oil, out["dT_flash"])


def _strength(inp, mu, p0, out):
    with np.errstate(divide="ignore"):
        inv_p0 = np.where(p0 > 0, 1.0 / np.where(p0 > 0, p0, 1.0), np.inf)
    out["dtau_orth"] = fatigue.orthogonal_shear_range(mu)[0] * p0
    if inp.has("yield and shakedown"):
        k = 0.5 * min(_pair(inp, "Y"))                       # Tresca: k = Y/2 of the weaker body
        out["p0_over_k"] = p0 / k
        out["sf_yield"] = fatigue.first_yield_limit(mu) * k * inv_p0
        out["sf_shakedown"] = fatigue.shakedown_limit(mu) * k * inv_p0
    if inp.has("subsurface fatigue"):
        out["util_subsurface"] = 0.5 * out["dtau_orth"] / min(_pair(inp, "tau_e"))
        with np.errstate(divide="ignore"):
            out["sf_subsurface"] = np.where(out["util_subsurface"] > 0, 1.0 / out["util_subsurface"], np.inf)
    if inp.has("surface fatigue"):
        lim = [(m["sigma_Hlim"], m.get("N_ref", fatigue.SN_CYCLES_ISO6336),
                m.get("m", fatigue.SN_EXPONENT_ISO6336)) for m in (inp.cam, inp.roller)]
        out["sf_surface_fatigue"] = min(x[0] for x in lim) * inv_p0
        out["N_pitting"] = np.minimum(*(fatigue.sn_cycles(p0, s, N_ref=N, m=m) for s, N, m in lim))


def _fe_stresses(inp, table, source, out, flags):
    r"""FE stress maxima of a sweep table, where the FE answered: first yield from the FE
    ``tau1_max`` (``k / tau1_max``) and the orthogonal shear range from the FE subsurface field,
    ``txz_range_max`` (Johnson 1985 §9.2),

    .. math:: \Delta\tau = \max_z\left[\max_x \tau_{xz}(x, z) - \min_x \tau_{xz}(x, z)\right]

    never a surface value (the surface ``|txz|`` of the FE window is a contact-edge quantity, 2-4 %
    of ``p0`` under a sticking roller, against ``0.5 p0`` below the surface). FE rows without a
    finite range keep Hertz's shape factor at the FE ``p0``; those with an FE field (finite
    ``tau1_max``) are flagged ``dtau_hertz``."""
    fe = np.asarray(source) == "fe"
    if "tau1_max" in table and inp.has("yield and shakedown"):
        t1 = np.asarray(table["tau1_max"], float)
        use = fe & np.isfinite(t1) & (t1 > 0)
        k = 0.5 * min(_pair(inp, "Y"))
        out["sf_yield"] = np.where(use, k / np.where(use, t1, 1.0), out["sf_yield"])
    tr = np.asarray(table["txz_range_max"], float) if "txz_range_max" in table else np.full(fe.size, np.nan)
    use = fe & np.isfinite(tr)
    field = np.isfinite(np.asarray(table["tau1_max"], float)) if "tau1_max" in table else fe
    flags.append(("dtau_hertz", fe & ~use & field))      # an FE field without its range
    out["dtau_orth"] = np.where(use, tr, out["dtau_orth"])
    if inp.has("subsurface fatigue"):
        out["util_subsurface"] = 0.5 * out["dtau_orth"] / min(_pair(inp, "tau_e"))
        with np.errstate(divide="ignore"):
            out["sf_subsurface"] = np.where(out["util_subsurface"] > 0, 1.0 / out["util_subsurface"], np.inf)


def assess_rows(case: ContactCase, table=None, *, lubricated: bool = True,
                inputs: AssessInputs | None = None, coatings=()) -> dict:
    """Assessment columns at the case's cam angles: dict of arrays, SI names of :data:`COLUMNS`
    plus the text columns ``regime``, ``flags``, ``source`` (``hertz``/``fe``).

    ``table``: optional sweep table (mapping with ``a_fe``, ``p0_fe`` per angle in m, Pa; optional
    ``tau1_max``, ``txz_range_max`` in Pa) whose finite FE values replace Hertz ``a``/``p0`` and,
    where given, the first-yield maximum and the orthogonal-shear range over one pass (shakedown
    and surface fatigue keep Hertz's shape factors with the FE ``p0``; so does the range where
    ``txz_range_max`` is missing, flagged ``dtau_hertz``). Criteria
    without their material data are NaN (see :attr:`AssessInputs.skipped`). Angles outside a
    formula's validity are computed and flagged. Raises :class:`~femcam.errors.SceneError` if a
    lubricated assessment lacks lubricant data, and :class:`~femcam.errors.InputError` for a sharp
    knife-edge.

    Parameters
    ----------
    case : femcam.scene.case.ContactCase
        The scene's contact at cam angles ``theta`` [rad] (state, materials, friction, speed,
        ``tribology`` and ``wear`` data): ``contact_case(scene, theta)``.
    table : mapping or SweepResult, optional
        Sweep table with per-angle ``a_fe`` [m], ``p0_fe`` [Pa] and optionally ``tau1_max``,
        ``txz_range_max`` [Pa]; None: Hertz only.
    lubricated : bool
        Assess the EHL film (needs ``[lubricant]``, ``[surface]``, ``oil_temperature_C``).
    inputs : AssessInputs, optional
        Pre-checked inputs; default :func:`assessment_inputs` of ``case.tribology``.
    coatings : sequence of (str, coating)
        The scene's coated bodies (:func:`femcam.layers.from_scene.scene_coatings`): their
        contact rows are flagged ``omits_coating``.

    Returns
    -------
    dict of str -> ndarray, shape (n,)
        The SI columns of :data:`COLUMNS` (float; NaN where not assessed) and the text columns
        ``regime``, ``flags``, ``source`` (object arrays).

    Raises
    ------
    SceneError
        A lubricated assessment without its lubricant, roughness or oil temperature data.
    InputError
        A sharp knife-edge follower (no tip radius).
    """
    case = _case(case)
    theta = case.theta
    n = _validate.angle_count("theta", f"{theta.size} angles", theta.size, 3600.0, "the assessment",
                              _validate.MAX_ASSESS_ANGLES)
    inp = inputs or assessment_inputs(case.tribology, lubricated=lubricated, where=case.where)
    table = getattr(table, "table", table)                   # a SweepResult or its table mapping
    R2, tip = _geometry(case)
    st = case.state
    Fc, a, p0, w, R, E_star, valid, source = _contact(case, st, R2, table, n)
    u1, u2 = _speeds(case, st, theta, Fc, tip)
    out = {c.si: np.full(n, np.nan) for c in COLUMNS}
    out.update(theta=theta, Fc=Fc, cam_x=st.profile.x, cam_y=st.profile.y)
    out.update(R=R, a=a, p0=p0, u_cam=u1, u_follower=u2, U=0.5 * (u1 + u2),
               v_slide=np.abs(u1 - u2))
    flags = [("liftoff", np.asarray(st.liftoff, bool)), ("hertz_validity", ~np.asarray(valid, bool))]
    if omitted_physics(coatings):
        flags.append(("omits_coating", Fc > 0))
    k0 = wear_coefficient_info(case.wear, case.pair.cam.hardness)[0]
    regime = np.full(n, "dry", dtype=object)
    if inp.lubricant is not None:
        eta0 = float(inp.lubricant.viscosity(inp.T_oil))
        f = film.film_thickness(U=out["U"], w=w, R=R, E_star=E_star, eta0=eta0, alpha=inp.lubricant.alpha,
                                sigma=inp.sigma)
        out.update(eta0=np.full(n, eta0), h_min=f["h_min"], h_c=f["h_c"], lam=f["lam"],
                   k_wear=wear_coefficient(k0, f["lam"]))
        regime = np.array(film.REGIME_NAMES, dtype=object)[f["regime"]]
        flags += [(nm, m & (Fc > 0)) for nm, m in f["flags"]]
    else:
        out["k_wear"] = np.full(n, k0)
    _thermal(inp, case.pair.mu, w, a, u1, u2, inp.T_oil, out, flags)
    _strength(inp, case.pair.mu, p0, out)
    if table is not None:
        _fe_stresses(inp, table, source, out, flags)
    out["regime"] = np.where(Fc > 0, regime, "no contact")
    out["flags"] = np.array([";".join(nm for nm, m in flags if m[i]) for i in range(n)], dtype=object)
    out["source"] = source
    return out


@dataclass(frozen=True)
class Assessment:
    """An assessment: the per-angle ``rows`` (:func:`assess_rows`), the ``inputs`` used, the
    ``worst`` angle per criterion and the ``notes`` (what was skipped and why).

    Parameters
    ----------
    scene_name : str
        Name of the assessed scene.
    rows : dict of str -> ndarray, shape (n,)
        Per-angle columns of :func:`assess_rows` (SI names and units of :data:`COLUMNS`).
    inputs : AssessInputs
        The checked inputs used.
    worst : dict of str -> tuple
        Criterion -> ``(value in the column's SI unit, theta [rad], index)``, see :func:`worst_angles`.
    notes : tuple of str
        Criteria skipped and the keys that would enable them.
    omitted : tuple of str
        What the scene holds that the assessment leaves out (:func:`omitted_physics`: a coating),
        one sentence each; said on the console and in the report.
    """

    scene_name: str
    rows: dict
    inputs: AssessInputs
    worst: dict
    notes: tuple
    omitted: tuple = ()

    def __repr__(self) -> str:
        """Scene, angles, the worst angle per criterion and the skipped count (a compact line)."""
        theta = np.asarray(self.rows.get("theta", ()), float)
        worst = [f"{c} {v:.4g} at {math.degrees(t):.1f} deg" for c, (v, t, _) in self.worst.items()]
        return compact_repr(self, [repr(self.scene_name), f"{theta.size} angles", *worst,
                                   f"{len(self.notes)} criteria skipped"])

    def to_dataframe(self):
        """The per-angle rows as a ``pandas.DataFrame`` with the columns of ``assessment.csv``
        (:func:`csv_columns`: names with units, values in those units; text columns as ``str``).

        Returns
        -------
        pandas.DataFrame
            One row per cam angle.

        Raises
        ------
        ImportError
            pandas is not installed (femcam does not require it).
        """
        return dataframe(csv_columns(self.rows), "Assessment.to_dataframe")


def column_extreme(values, mask, how: str):
    """``(value, index)`` of the largest (``how="max"``) or smallest (``"min"``) finite value of
    ``values`` where ``mask`` holds, or None when there is none.

    Parameters
    ----------
    values : array_like, shape (n,)
        A table column (any unit; returned as is).
    mask : ndarray of bool, shape (n,)
        The rows that count.
    how : {"max", "min"}
        Which extreme.

    Returns
    -------
    tuple of (float, int) or None
        The extreme value and its row index.
    """
    v = np.where(mask, np.asarray(values, float), np.nan)
    if not np.any(np.isfinite(v)):
        return None
    i = int(np.nanargmin(v) if how == "min" else np.nanargmax(v))
    return float(v[i]), i


def worst_angles(rows: dict) -> dict:
    """criterion -> ``(value, theta in rad, index)`` of the worst contact angle (NaN columns skipped).

    Parameters
    ----------
    rows : dict of str -> ndarray, shape (n,)
        Columns of :func:`assess_rows`; angles with ``Fc <= 0`` are ignored.

    Returns
    -------
    dict of str -> tuple of (float, float, int)
        Criterion of :data:`WORST` -> ``(value in the column's SI unit, theta [rad], index)``;
        criteria with no finite value are left out.
    """
    on = rows["Fc"] > 0
    res = {}
    for crit, (col, how) in WORST.items():
        e = column_extreme(rows[col], on, how)
        if e is not None:
            res[crit] = (e[0], float(rows["theta"][e[1]]), e[1])
    return res


def assess(case: ContactCase, *, table=None, lubricated: bool = True, coatings=()) -> Assessment:
    """Assess a scene's contact at the case's cam angles (``contact_case(scene)``: 360 angles
    over one revolution).

    Parameters
    ----------
    case : femcam.scene.case.ContactCase
        The scene's contact at cam angles [rad] (:func:`femcam.scene.case.contact_case`).
    table : mapping or SweepResult, optional
        Sweep table whose FE values replace Hertz's (see :func:`assess_rows`).
    lubricated : bool
        Assess the EHL film (needs the lubricant data).
    coatings : sequence of (str, coating)
        The scene's coated bodies (:func:`femcam.layers.from_scene.scene_coatings`), which the
        assessment leaves out (:func:`omitted_physics`).

    Returns
    -------
    Assessment
        Per-angle rows, inputs, worst angle per criterion and notes.

    Raises
    ------
    SceneError
        A lubricated assessment without its lubricant, roughness or oil temperature data.
    """
    case = _case(case)
    inp = assessment_inputs(case.tribology, lubricated=lubricated, where=case.where)
    rows = assess_rows(case, table, inputs=inp, coatings=coatings)
    notes = tuple(f"{crit}: skipped, needs {', '.join(keys)}" for crit, keys in inp.skipped.items())
    fe_rows = np.asarray(rows["source"]) == "fe"
    if table is not None and not np.all(fe_rows):
        notes += (f"contact: {int(np.sum(~fe_rows))} of {fe_rows.size} angles fall back to Hertz (the sweep "
                  "table has no finite positive a_fe, p0_fe there: a Hertz-method sweep, or rows the FE "
                  "did not answer); the source column says which",)
    if np.any(fe_rows) and "txz_range_max" not in getattr(table, "table", table):
        notes += ("subsurface fatigue: the sweep table has no txz_range_max (a sweep written before "
                  "femcam computed the FE range of txz over one pass): dtau_orth is Hertz's range "
                  "(McEwen) at the FE p0 on every FE row; re-run the sweep for the FE field",)
    return Assessment(scene_name=case.name, rows=rows, inputs=inp, worst=worst_angles(rows), notes=notes,
                      omitted=omitted_physics(coatings))


def omitted_physics(coatings) -> tuple[str, ...]:
    """What a scene with these coated bodies holds that the assessment leaves out, one sentence
    each: a coating (from :func:`femcam.layers.from_scene.scene_coatings`, the scene test the
    sweep's ``headline_omits_coating`` uses). The film, the flash temperature and the strength and
    fatigue data are the substrate's; the contact and its stresses are the coated model's where
    they come from an FE sweep table (``femcam sweep``, whose headline FE carries the coating),
    Hertz's of homogeneous bodies otherwise. Every contact row carries the flag ``omits_coating``.

    Parameters
    ----------
    coatings : sequence of (str, coating)
        The scene's coated bodies, ``(body, coating)`` pairs (thickness [m], modulus [Pa]).

    Returns
    -------
    tuple of str
        Empty for an uncoated scene.
    """
    return tuple(f"the assessment treats the coated body as homogeneous: {coating_phrase(body, c)} is "
                 "not in its film, flash temperature or fatigue data (the substrate's are used; flag "
                 "omits_coating), nor in its contact unless that comes from a femcam sweep's FE (the "
                 "coated model); the coating's own stresses are the coating_* and interface_* columns "
                 "of femcam sweep" for body, c in coatings)


def csv_columns(rows: dict) -> dict:
    """The rows with CSV names and units (``theta_deg``, ``h_min_um``, ...), text columns last.

    Parameters
    ----------
    rows : dict of str -> ndarray, shape (n,)
        Columns of :func:`assess_rows` (SI).

    Returns
    -------
    dict of str -> ndarray, shape (n,)
        Float columns renamed and scaled to their CSV unit (:data:`COLUMNS`), then the text columns.
    """
    out = {c.csv: np.asarray(rows[c.si], float) * c.factor for c in COLUMNS}
    out.update({t: rows[t] for t in (*TEXT, "source") if t in rows})
    return out


def wear_factor(case: ContactCase, table=None):
    """The Archard coefficient's lubrication factor and regime per angle, for the wear map.

    Parameters
    ----------
    case : femcam.scene.case.ContactCase
        The scene's contact at cam angles [rad] (its ``[wear]`` coefficient, ``[lubricant]``
        and knife-edge tip radius [m]).
    table : dict, optional
        A sweep table (FE ``a_fe`` [m] / ``p0_fe`` [Pa] used where finite), as for
        :func:`assess_rows`.

    Returns
    -------
    k_factor : ndarray, shape (n,), or None
        ``k(lambda) / k`` [-]; None for a scene without [lubricant] or with ``k = 0`` (dry k).
    regime : ndarray of str, shape (n,), or None
        ``boundary`` / ``mixed`` / ``full`` per angle (``no contact`` where ``Fc = 0``).
    """
    case = _case(case)
    k = wear_coefficient_info(case.wear, case.pair.cam.hardness)[0]
    if case.tribology.lubricant is None or not k > 0:
        return None, None
    r = assess_rows(case, table)
    return r["k_wear"] / k, r["regime"]
