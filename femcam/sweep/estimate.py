r"""A posteriori discretisation-error estimates of the FE rows (two-level, per model family).

Symbols
-------
==========  ===========================================================  =========
symbol      meaning                                                      unit
==========  ===========================================================  =========
``q_h``     a quantity (p0, a, von Mises max, tau1 max) on the family     Pa, m
            model's mesh, ``h = a_ref / a_over_h``
``q_H``     the same on a coarser mesh of the same family, ``H ~ 2 h``     Pa, m
``r``       ``H / h`` (exactly ``n_fine / n_fine_coarse``)                 -
``p``       observed convergence rate of the quantity (:data:`RATES`)      -
``e_ref``   estimated relative error at the family's reference load      -
``e_row``   the same carried to one row: ``e_ref (a_ref / a_row)^p``       -
==========  ===========================================================  =========

Method (Richardson's two-level estimate, Roache 1998 §5.4): with ``q_h = q + C h^p``,
``q_h - q_H = C h^p (1 - r^p)``, so the error of ``q_h`` is

.. math:: e_h = \frac{|q_h - q_H|}{r^p - 1}.

The family's model is solved at its reference load (the load whose Hertz half-width is
``a_ref`` at ``rho_ref``); one coarse model of the same family (mesh graded to the same
``a_ref``, ``stress_operators="per_solve"``) is built and solved at the same load: one extra
coarse build per family, none per row. Each row carries the estimate through its own
``a_row / h``: ``e_row = e_ref (a_ref / a_row)^p`` (2D elasticity is scale invariant, so the
relative error depends on ``a/h``). For p0 the family's verified reuse error
(:class:`femcam.sweep.verify.FamilyRecord`, the difference to a model graded to the row itself)
is added, so the node alignment of the row's contact edge is accounted for.

The coarse level keeps the parity of the fine zone's element count ``n_fine = 5 a_over_h``: with
``n_fine`` even the contact centre ``x = 0`` is a node on both levels, with it odd it is the
middle of an element on both, so the sampling error of the nodal peak (``(h/2a)^2 / 2`` at mid
element) scales with ``h^2`` on both levels instead of switching on and off between them.

What the estimate leaves out: the **finite-body** (domain-size) part of an FE-vs-Hertz
difference (the FE bodies are clamped at a depth ``min(|rho|, Rr)``; Hertz is a half-space). It
does not shrink with h and is no discretisation error: measured on the seed 002 study model it is
below 0.002 % for p0 and a but +1.1 % for tau1 max (docs/estimate.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import FemcamError
from ..fe import SolverOptions
from ..layers.interface import interface_stress
from ..mesh import MeshOptions
from .cache import ModelCache, _disk_key, _key, build_model, default_cache, model_args
from .options import ContactParams, ResolvedOptions, contact_params

__all__ = ["LAYER_QUANTITIES", "QUANTITIES", "RATES", "FamilyEstimate", "coarse_mesh", "estimated",
           "family_estimate", "estimate_families", "estimate_run", "estimate_text", "fill_row_estimate",
           "layer_quantities", "predict_a_over_h", "prefetch_estimate", "reached_text", "reference_load",
           "row_estimate"]

#: quantities estimated: name -> (sweep column of the estimate, ContactResult reader)
QUANTITIES = ("p0", "a", "vm", "tau1")
#: observed convergence rates p (log-log slope of the error vs h, seed 002 study model, P2,
#: even n_fine, a/h = 4 ... 20, docs/estimate.md): p0 nodal peak 1.68-1.89 (the smaller taken:
#: a larger estimate), a 1.91; the stress maxima 2 (the nominal rate of a P2 field's recovered
#: nodal stress; their measured differences are within a recovery noise of ~0.05 %)
RATES = {"p0": 1.7, "a": 1.9, "vm": 2.0, "tau1": 2.0, "interface_tau": 2.0, "interface_sn": 2.0}
#: coated scenes: the interface stresses of the coated body estimated on the same two levels
#: (``interface_tau``: ``max |tau|`` at the interface, ``interface_sn``: its most compressive
#: normal stress, :func:`femcam.layers.interface_stress`); rate 2, the nominal rate of the
#: recovered nodal stress of a P2 field (docs/estimate.md: measured against the layered
#: half-space)
LAYER_QUANTITIES = ("interface_tau", "interface_sn")


@dataclass(frozen=True)
class FamilyEstimate:
    """The two-level error estimate of one family's model at its reference load.

    Attributes
    ----------
    a_ref : float
        The family model's reference half-width [m] (its mesh size is ``a_ref / a_over_h``).
    a_over_h, a_over_h_coarse : float
        Elements per ``a_ref`` on the family mesh and on the coarse mesh [-].
    err : dict[str, float]
        Estimated relative error at the reference load per quantity of :data:`QUANTITIES` [-]
        (NaN where the coarse model could not be built or solved).
    reuse : float
        The family's verified p0 reuse error [-] (added to the p0 estimate of each row).
    """

    a_ref: float
    a_over_h: float
    a_over_h_coarse: float
    err: dict
    reuse: float = 0.0

    def carried(self, quantity: str, a_over_h_row: float) -> float:
        """The estimate of ``quantity`` carried to a row solved at ``a_over_h_row`` elements per
        its own half-width: ``e_ref (a_over_h / a_over_h_row)^p`` (2D elasticity is scale
        invariant), without the reuse error.

        Parameters
        ----------
        quantity : str
            A key of ``err`` (:data:`RATES`).
        a_over_h_row : float
            Elements per the row's half-width [-].

        Returns
        -------
        float
            Relative error [-] (NaN when the estimate or the row's resolution is missing).
        """
        e = self.err.get(quantity, math.nan)
        if not (a_over_h_row > 0 and math.isfinite(e)):
            return math.nan
        return e * (self.a_over_h / a_over_h_row) ** RATES[quantity]

    def to_dict(self) -> dict:
        """JSON-able form (provenance).

        Returns
        -------
        dict
            The attributes (lengths in m, errors relative).
        """
        return {"a_ref": self.a_ref, "a_over_h": self.a_over_h,
                "a_over_h_coarse": self.a_over_h_coarse, "err": dict(self.err), "reuse": self.reuse}


def coarse_mesh(a_over_h: float, fine_half_width: float = 2.5) -> MeshOptions:
    """The coarse level of a two-level estimate: ``H = 2 h`` with the fine level's node pattern.

    The coarse fine zone holds ``n2`` elements of size ``2 h``, ``n2`` the whole number of the
    parity of the fine level's ``n = round(2 fine_half_width a_over_h)`` nearest ``n / 2`` (not
    below it): every coarse node is a fine node, ``x = 0`` is a node on both levels or on neither,
    and so is the Hertz edge ``x = a_ref`` when it is one on the fine level. (Keeping the fine
    zone's width and rounding ``H`` instead moved the nodes against the contact edge and gave
    effectivities of 0.06-5 at a/h = 10 and 14.)

    Parameters
    ----------
    a_over_h : float
        Elements per half-width of the family mesh [-], 4 to 400.
    fine_half_width : float
        Half-width of the family mesh's uniform zone in ``a_ref`` [-].

    Returns
    -------
    femcam.mesh.MeshOptions
        ``a_over_h / 2`` and the coarse zone's half-width ``n2 / a_over_h`` (in ``a_ref``).

    >>> m = coarse_mesh(10.0); m.a_over_h, m.fine_half_width
    (5.0, 2.6)
    """
    a_over_h = _validate.in_range("a_over_h", a_over_h, 4.0, 400.0, "(elements per half-width)")
    n = int(round(2 * fine_half_width * a_over_h))
    n2 = int(math.ceil(n / 2))
    if n2 % 2 != n % 2:
        n2 += 1
    return MeshOptions(a_over_h=a_over_h / 2.0, fine_half_width=n2 / a_over_h)


def reference_load(cp: ContactParams, rho_ref: float, a_ref: float) -> float:
    r"""The contact force whose Hertz half-width is ``a_ref`` at ``rho_ref``.

    .. math:: F = \frac{\pi E^* a^2 l}{4 R}, \qquad \frac{1}{R} = \frac{1}{\rho} + \frac{1}{R_r}

    Parameters
    ----------
    cp : ContactParams
        Roller radius and face width [m], materials.
    rho_ref : float
        Cam radius of curvature [m] (``inf``: flat).
    a_ref : float
        Half-width [m].

    Returns
    -------
    float
        F [N].

    Raises
    ------
    InputError
        A concave cam that does not fit the roller (``1/R <= 0``).
    """
    a_ref = _validate.positive("a_ref", a_ref, "m")
    inv_R = 1.0 / cp.Rr + (0.0 if math.isinf(rho_ref) else 1.0 / rho_ref)
    if not inv_R > 0:
        raise _validate.fail("rho_ref", rho_ref, "m", "the roller does not fit this concave cam")
    return math.pi * cp.E_star * a_ref**2 * cp.length * inv_R / 4.0


def _quantities(r) -> dict:
    return {"p0": r.p0_nodal, "a": r.a, "vm": r.von_mises_max.value, "tau1": r.tau1_max.value}


def estimated(cp: ContactParams) -> tuple:
    """The quantities a family estimate holds for a scene: :data:`QUANTITIES`, and
    :data:`LAYER_QUANTITIES` when the contact FE carries a coating.

    Parameters
    ----------
    cp : ContactParams
        Contact parameters of the scene (``coat_body``).

    Returns
    -------
    tuple of str
    """
    return QUANTITIES + (LAYER_QUANTITIES if cp.coat_body is not None else ())


def layer_quantities(r, cp: ContactParams) -> dict:
    """The interface stresses of a coated solve (:data:`LAYER_QUANTITIES`), ``{}`` when uncoated.

    Parameters
    ----------
    r : femcam.fe.ContactResult
        A solve of the coated model (with its model).
    cp : ContactParams
        Contact parameters (``coat_body``).

    Returns
    -------
    dict[str, float]
        ``interface_tau`` (max ``|tau|``) and ``interface_sn`` (the most compressive normal
        stress) [Pa]; NaN when the solve has no interface to read (a
        :class:`~femcam.errors.FemcamError` of :func:`femcam.layers.interface_stress`).
    """
    if cp.coat_body is None:
        return {}
    try:
        it = interface_stress(r, cp.coat_body)
    except FemcamError:   # no interface in the fine zone: the headline's estimates stand
        return dict.fromkeys(LAYER_QUANTITIES, math.nan)
    return {"interface_tau": float(it.tau_abs_max), "interface_sn": float(it.sigma_n_min)}


def family_estimate(cp: ContactParams, rho_ref: float, a_ref: float, options: ResolvedOptions,
                    cache: ModelCache | None = None, reuse: float = 0.0) -> FamilyEstimate:
    """Two-level estimate of one family model's relative errors at its reference load.

    Parameters
    ----------
    cp : ContactParams
        Contact parameters of the scene.
    rho_ref, a_ref : float
        The family's reference cam radius and half-width [m].
    options : ResolvedOptions
        ``a_over_h`` of the family model (>= 4).
    cache : ModelCache, optional
        Where the family model is taken from (default: the process's cache).
    reuse : float
        The family's verified reuse error [-].

    Returns
    -------
    FamilyEstimate
        NaN errors where the coarse model failed (the rows then carry NaN estimates).
    """
    cache = cache or default_cache()
    # the coarse level of the family's own model: coated when the scene is (the coating band in
    # the contact FE and the widened fine zone of model_args, build_model), nested in its nodes
    mesh2 = coarse_mesh(options.a_over_h, model_args(cp, rho_ref, a_ref, options)["mesh"].fine_half_width)
    a2, r_h = mesh2.a_over_h, 2.0
    nan = {q: math.nan for q in estimated(cp)}
    try:
        F = reference_load(cp, rho_ref, a_ref)
        fine = cache.solve(cache.model_for(cp, rho_ref, a_ref, options), F, rho_ref, cp.mu,
                           cp.sliding, check=False)
        qH = _coarse_quantities(cp, rho_ref, a_ref, options, mesh2, F, cache)
        qh = {**_quantities(fine), **layer_quantities(fine, cp)}
    except (FemcamError, ValueError, ArithmeticError):
        return FamilyEstimate(a_ref, options.a_over_h, a2, nan, float(reuse))
    err = {q: abs(qh[q] - qH[q]) / abs(qh[q]) / (r_h ** RATES[q] - 1.0) for q in nan}
    return FamilyEstimate(a_ref, options.a_over_h, a2, err, float(reuse))


def _coarse_quantities(cp, rho_ref, a_ref, options, mesh2, F, cache) -> dict:
    """The coarse level's quantities (:func:`_quantities`): from the persistent model cache
    when an earlier run stored them under the same content key (the coarse mesh and the load in
    it), from the background build :func:`prefetch_estimate` started, or built now."""
    return cache.background.take(*_coarse_job(cp, rho_ref, a_ref, options, mesh2, F, cache))


def _coarse_job(cp, rho_ref, a_ref, options, mesh2, F, cache) -> tuple:
    """The background key of one coarse level and the function computing its quantities."""
    solver = SolverOptions(stress_operators="per_solve")
    disk = getattr(cache, "disk", None)
    load = (F, cp.mu, cp.sliding, mesh2.a_over_h, mesh2.fine_half_width)
    dk = _disk_key("estimate_coarse", cp, rho_ref, a_ref, options, solver, load) if disk is not None else None

    def job() -> dict:
        qH = disk.get(dk) if dk is not None else None
        if isinstance(qH, dict) and set(qH) == set(estimated(cp)) and all(map(math.isfinite, qH.values())):
            return qH
        coarse_model = build_model(cp, rho_ref, a_ref, options, solver, mesh=mesh2)
        rH = coarse_model.solve(F=F, rho=rho_ref, mu=cp.mu, sliding=cp.sliding, check=False)
        qH = {**_quantities(rH), **layer_quantities(rH, cp)}
        if dk is not None and all(map(math.isfinite, qH.values())):
            disk.put(dk, {k: float(v) for k, v in qH.items()})
        return qH

    job.disk_key = dk
    return ("estimate_coarse", _key(cp, rho_ref, a_ref, options), load), job


def prefetch_estimate(cp: ContactParams, rho_ref: float, a_ref: float, options: ResolvedOptions,
                      cache: ModelCache | None = None) -> None:
    """Start the coarse level of :func:`family_estimate` (same arguments) in the background
    thread of ``cache`` (:meth:`~femcam.sweep.cache.ModelCache.building_in_background`;
    nothing outside it): the sweep's family phase builds it while the family models are built
    and scanned.

    Parameters
    ----------
    cp : ContactParams
        Contact parameters of the scene.
    rho_ref, a_ref : float
        The family's reference cam radius and half-width [m].
    options : ResolvedOptions
        ``a_over_h`` of the family model (below 4: no estimate, nothing started).
    cache : ModelCache, optional
        Its background thread (default: the process's cache).
    """
    cache = cache or default_cache()
    if options.a_over_h < 4.0 or not cache.background.threads:
        return
    try:
        mesh2 = coarse_mesh(options.a_over_h, model_args(cp, rho_ref, a_ref, options)["mesh"].fine_half_width)
        F = reference_load(cp, rho_ref, a_ref)
    except (FemcamError, ValueError, ArithmeticError):
        return   # family_estimate says NaN for it
    key, job = _coarse_job(cp, rho_ref, a_ref, options, mesh2, F, cache)
    cache.submit_build(key, job, job.disk_key)


def row_estimate(est: FamilyEstimate, a_row: float, a_model: float | None = None) -> dict:
    """One row's estimated relative errors from its family's estimate.

    Parameters
    ----------
    est : FamilyEstimate
        The family's estimate.
    a_row : float
        The row's Hertz half-width [m].
    a_model : float, optional
        ``a_ref`` of the model that solved the row [m] (default ``est.a_ref``; a row with a model
        of its own has ``a_model = a_row``: its mesh size is ``a_row / a_over_h``).

    Returns
    -------
    dict[str, float]
        ``{"p0", "a", "vm", "tau1"}`` -> relative error [-]: ``e_ref (h_row / h_ref)^p`` with
        ``h_row / h_ref = a_model / a_row``, plus the family's reuse error for p0 (0 for a model
        of its own).
    """
    a_model = est.a_ref if a_model is None else float(a_model)
    scale = a_model / float(a_row) if a_row > 0 else math.nan
    out = {q: est.err[q] * scale ** RATES[q] for q in QUANTITIES}
    own = a_model != est.a_ref
    out["p0"] = out["p0"] + (0.0 if own else abs(est.reuse))
    return out


def predict_a_over_h(est: FamilyEstimate, target: float, quantity: str = "p0") -> float:
    """The ``a_over_h`` at which ``quantity``'s estimated discretisation error reaches ``target``.

    .. math:: n = n_0 \\left(e_0 / e_{target}\\right)^{1/p}

    Parameters
    ----------
    est : FamilyEstimate
        An estimate at ``est.a_over_h``.
    target : float
        Relative error to reach [-], > 0.
    quantity : str
        One of :data:`RATES` (:data:`QUANTITIES`, :data:`LAYER_QUANTITIES`).

    Returns
    -------
    float
        Elements per half-width [-] (NaN when the estimate is NaN).
    """
    target = _validate.positive("target", target, "(relative error)")
    _validate.choice("quantity", quantity, tuple(RATES))
    e0 = est.err[quantity]
    if not np.isfinite(e0):
        return math.nan
    return est.a_over_h * (max(e0, 1e-300) / target) ** (1.0 / RATES[quantity])


def fill_row_estimate(rows, i: int, est: FamilyEstimate | None, a_row: float,
                      a_model: float, a_over_h: float) -> None:
    """Write row ``i``'s estimates (``err_est_*``, relative) and ``a_over_h_row`` into ``rows``.

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table (SI).
    i : int
        Row index.
    est : FamilyEstimate or None
        The row's family estimate (None: the estimates stay NaN).
    a_row : float
        The row's Hertz half-width [m].
    a_model : float
        ``a_ref`` of the model that solved the row [m].
    a_over_h : float
        Elements per ``a_model`` of that model [-].
    """
    rows.a_over_h_row[i] = a_over_h * a_row / a_model if a_model > 0 else math.nan
    if est is None:
        return
    for q, e in row_estimate(est, a_row, a_model).items():
        getattr(rows, f"err_est_{q}")[i] = e


def estimate_families(records, cp: ContactParams, options: ResolvedOptions,
                      cache: ModelCache | None = None) -> dict:
    """Two-level estimates of every verified family (one coarse model build each).

    Parameters
    ----------
    records : list of femcam.sweep.verify.FamilyRecord
        The verified families (``id``, ``rho_ref``, ``a_ref`` in m, ``reuse_error``).
    cp : ContactParams
        Contact parameters of the scene.
    options : ResolvedOptions
        ``a_over_h`` of the family models; below 4 no estimate is made (the coarse level
        would fall below 2 elements per half-width).
    cache : ModelCache, optional
        Where the family models are (default: the process's cache).

    Returns
    -------
    dict[int, FamilyEstimate]
        Family id -> estimate (empty when ``a_over_h < 4``).
    """
    if options.a_over_h < 4.0:
        return {}
    out = {}
    for rec in records:
        reuse = rec.reuse_error if np.isfinite(rec.reuse_error) else math.nan
        opts = options.for_family(getattr(rec, "a_over_h", None))   # the family's own mesh
        if opts.a_over_h < 4.0:
            continue
        out[int(rec.id)] = family_estimate(cp, rec.rho_ref, rec.a_ref, opts, cache, reuse)
    return out


def estimate_run(run, cache: ModelCache | None = None) -> None:
    """A sweep's family estimates (FE methods with verified families), kept once computed.

    Parameters
    ----------
    run : femcam.sweep.outputs.SweepRun
        The sweep's state after the family phase; ``run.estimates`` is set in place.
    cache : ModelCache, optional
        Where the family models are.
    """
    if run.opts.method == "hertz" or not run.records or run.estimates:
        return
    run.estimates = estimate_families(run.records, contact_params(run.scene), run.opts, cache)


def reached_text(t, ok, choice: dict) -> str:
    """``"; reached: p0 0.31 %, tau1 0.2 %"``: the largest estimate over the ``ok`` rows of each
    quantity ``rtol`` controlled (``choice["rtol_on"]``).

    Parameters
    ----------
    t : Mapping[str, ndarray]
        The sweep table (``err_est_*`` relative).
    ok : ndarray of bool
        The ``ok`` rows.
    choice : dict
        ``provenance["options"]["rtol_choice"]``.

    Returns
    -------
    str
        The text ("" when no controlled quantity has a finite estimate).
    """
    parts = []
    for q in choice.get("rtol_on", ["p0"]):
        v = np.where(ok, np.asarray(t.get(f"err_est_{q}", np.full(ok.shape, np.nan)), float), np.nan)
        if np.any(np.isfinite(v)):
            met = "met" if np.nanmax(v) <= choice["rtol"] else "NOT met"
            parts.append(f"{q} {100 * float(np.nanmax(v)):.3g} % ({met})")
    return "; reached: " + ", ".join(parts) if parts else ""


def estimate_text(result) -> str:
    """The largest error estimates of a sweep's FE rows, for the summary line and ``report.md``.

    Parameters
    ----------
    result : femcam.sweep.SweepResult
        A finished sweep (its ``table`` with the ``err_est_*`` columns, relative, and its
        ``provenance["options"]``, with ``rtol_choice`` when ``rtol`` chose the mesh).

    Returns
    -------
    str
        E.g. ``"estimated error (largest over 172 FE rows): p0 0.308 %, a 1.25 %, von Mises
        0.21 %, tau1 0.19 %"`` plus the rtol choice; ``""`` without estimates.
    """
    t = result.table
    if "err_est_p0" not in t:
        return ""
    ok = np.asarray(t["status"]).astype(str) == "ok"
    names = {"p0": "p0", "a": "a", "vm": "von Mises", "tau1": "tau1", "interface_tau": "interface shear",
             "interface_sn": "interface normal", "bore_hoop": "bore hoop", "pin_p0": "pin p0",
             "needle_Q": "needle load"}
    parts = []
    for q, name in names.items():
        if f"err_est_{q}" not in t:
            continue
        v = np.where(ok, np.asarray(t[f"err_est_{q}"], float), np.nan)
        if np.any(np.isfinite(v)):
            parts.append(f"{name} {100 * float(np.nanmax(v)):.3g} %")
    if not parts:
        return ""
    n = int(np.count_nonzero(ok & np.isfinite(np.asarray(t["err_est_p0"], float))))
    text = f"estimated discretisation error (largest over {n} FE rows): " + ", ".join(parts)
    choice = result.provenance.get("options", {}).get("rtol_choice")
    if choice:
        own = choice.get("family_a_over_h") or [choice["a_over_h"]]
        mesh = (f"a/h = {min(own):g}" if min(own) == max(own) else
                f"a/h = {min(own):g}-{max(own):g} over {len(own)} families")
        text += (f"; rtol {100 * choice['rtol']:g} % on {', '.join(choice.get('rtol_on', ['p0']))}: "
                 f"{mesh}, reuse tolerance {100 * choice['tolerance']:g} %" + reached_text(t, ok, choice))
    return text
