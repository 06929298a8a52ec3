r"""The per-angle chain and the grouping of angles into model families.

At every cam angle :math:`\theta`:

1. kinematics, profile and loads from the scene (``Scene.analyse``): s, v, a, j, phi, rho, Fc;
2. Hertz (:class:`femcam.hertz.LineContact`) with ``R1 = rho`` (cam), ``R2 = Rr`` (roller);
3. ``method="fe"``: the FE contact solve (:mod:`femcam.fe`) with the same F, rho and mu;
   ``method="hertz"``: the analytic maxima instead (a fast, legitimate analytic sweep).

Families (``method="fe"``)
--------------------------
2D linear elasticity is invariant under a uniform scaling of the geometry: the stiffness of a
body meshed in units of ``a`` is the same matrix for every ``a``. From angle to angle only the
gap shape ``x^2 / 2R`` and the load change. So one mesh + factorisation serves every angle whose
``a`` (and ``Rr / rho``) stays close to the model's reference. The parent process plans the
families and verifies the reuse error against ``tolerance`` with fresh models, splitting
families until it holds (:func:`femcam.sweep.families.verify_families`); each worker process
then builds a family's model once (:func:`model_for`, a per-process cache; forked workers
inherit the parent's) and checks it with ``model.covers(F, rho)``; an angle it does not cover
gets its own model (flag ``rebuilt``). Because the plan depends only on the set of angles (and
is stored with the chunks for ``resume``), results do not depend on chunking, the number of
workers, the executor, or resuming.
"""

from __future__ import annotations

import os
import time
import traceback
import warnings
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np

from .. import _validate as V  # noqa: N812
from ..errors import FemcamError, InputError
from .families import (  # noqa: F401 - re-exported for callers and tests
    STATS,
    TOLERANCE_FLOOR,
    build_model,
    clear_model_cache,
    family_spans,
    hertz_half_width_any,
    model_for,
    plan_families,
    solve_cached,
    verify_families,
)
from .result import empty_rows
from .wear import fill_wear

METHODS = ("fe", "hertz")


@dataclass(frozen=True, kw_only=True)
class SweepOptions:
    """Numerical options of a sweep (recorded in the manifest and the provenance header).

    method : ``"fe"`` (default) or ``"hertz"``.
    a_over_h : FE element size in the contact zone, ``h = a / a_over_h`` (``--mesh-size``).
    tolerance : bound on the reuse error ``|p0(family model) / p0(fresh model) - 1|``
        (``--tolerance``), verified with fresh models at each family's worst-covered angles;
        families are split until it holds (:mod:`femcam.sweep.families`). At least
        :data:`~femcam.sweep.families.TOLERANCE_FLOOR` (1e-4).
    chunk_size : angles per chunk (unit of work and of the on-disk store).
    vtk_every : write a ``.vtu`` every k-th angle (0: none).
    """

    method: str = "fe"
    a_over_h: float = 10.0
    tolerance: float = 2e-3
    chunk_size: int = 30
    vtk_every: int = 0

    def __post_init__(self):
        V.choice("method", self.method, METHODS)
        object.__setattr__(self, "a_over_h", V.in_range("a_over_h", self.a_over_h, 2.0, 400.0))
        tol = V.in_range("tolerance", self.tolerance, 0.0, 0.5, lo_open=True)
        if tol < TOLERANCE_FLOOR:
            raise V.fail("tolerance", tol, "", f"must be >= {TOLERANCE_FLOOR:g}: the reuse error is a "
                         "discretisation effect of the order of the FE error itself (~0.2 % at "
                         "a_over_h = 10, smaller on finer meshes); below the floor nearly every "
                         "angle needs its own model. Refine a_over_h for more accurate p0")
        object.__setattr__(self, "tolerance", tol)
        if int(self.chunk_size) != self.chunk_size or self.chunk_size < 1:
            raise V.fail("chunk_size", self.chunk_size, "angles", "must be an integer >= 1")
        if int(self.vtk_every) != self.vtk_every or self.vtk_every < 0:
            raise V.fail("vtk_every", self.vtk_every, "angles", "must be an integer >= 0")
        object.__setattr__(self, "chunk_size", int(self.chunk_size))
        object.__setattr__(self, "vtk_every", int(self.vtk_every))

    def to_dict(self) -> dict:
        return {"method": self.method, "a_over_h": self.a_over_h, "tolerance": self.tolerance,
                "chunk_size": self.chunk_size, "vtk_every": self.vtk_every}


# ---------------------------------------------------------------------------------------------
# scene adapter: the few contact parameters the sweep needs
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ContactParams:
    Rr: float          # roller radius (m)
    length: float      # face width (m)
    cam: object        # Material
    roller: object     # Material
    mu: float          # friction coefficient
    plane: str         # "strain" | "stress"
    sliding: int = 1   # +1: friction traction on the cam in +x (scene "+x"), -1: "-x"


def _first(obj, names, default=None):
    for n in names:
        cur = obj
        ok = True
        for part in n.split("."):
            if not hasattr(cur, part):
                ok = False
                break
            cur = getattr(cur, part)
        if ok and cur is not None:
            return cur
    return default


def contact_params(scene) -> ContactParams:
    """Read roller radius, face width, materials, mu and plane from a Scene."""
    Rr = _first(scene, ["Rr", "follower.Rr", "roller_radius"])
    length = _first(scene, ["length", "face_width", "width", "contact.length"])
    cam = _first(scene, ["cam_material", "materials.cam", "cam"])
    roller = _first(scene, ["roller_material", "materials.roller", "roller"])
    mu = _first(scene, ["mu", "friction", "contact.mu"], 0.0)
    plane = _first(scene, ["plane", "contact.plane"], "strain")
    missing = [n for n, v in (("Rr", Rr), ("length", length), ("cam", cam), ("roller", roller))
               if v is None]
    if missing:
        raise InputError(f"scene = {type(scene).__name__}: the sweep needs a roller follower "
                         f"scene; missing {', '.join(missing)}")
    kind = getattr(_first(scene, ["follower"]), "kind", "roller")
    if kind != "roller" or not float(Rr) > 0.0:
        raise InputError(f"follower.type = {kind!r}: the contact sweep needs a roller follower "
                         "(a knife edge has no contact width; a flat-faced follower has no FE "
                         "contact model yet)")
    sliding = -1 if str(_first(scene, ["sliding"], "+x")).strip() == "-x" else 1
    return ContactParams(float(Rr), float(length), cam, roller, float(mu), str(plane), sliding)


# ---------------------------------------------------------------------------------------------
# Hertz: normalised maxima (computed once; scale with p0 and a)
# ---------------------------------------------------------------------------------------------
@lru_cache(maxsize=32)
def hertz_shape_factors(mu: float, nu: float, plane: str) -> dict:
    r"""Maxima of the Hertz fields in units of p0 and a, for friction ``mu``.

    Hertz line-contact stresses are self-similar: :math:`\sigma/p_0` depends only on
    :math:`(x/a, z/a, \mu, \nu)` (Johnson 1985 §7.1, McEwen 1949), so the maxima of von Mises
    and tau1 (:mod:`femcam.hertz.maxima`) are found once and scaled by each angle's p0 and a.
    Surface extremes: seed 002 eqs. 5-7 on a fine grid of ``x/a``.
    """
    from ..hertz import max_shear, max_von_mises, surface_stress

    vm = max_von_mises(mu, nu, plane)
    t1 = max_shear(mu)
    xs = np.linspace(-3.0, 3.0, 60001)
    sx, sz, txz = surface_stress(xs, 1.0, 1.0, mu)
    return {"von_mises": (vm.value, vm.z), "tau1": (t1.value, t1.z),
            "sx_min": float(np.min(sx)), "sx_max": float(np.max(sx)),
            "sz_min": float(np.min(sz)), "txz_absmax": float(np.max(np.abs(txz)))}


#: ``nearly_conformal`` flag threshold on :func:`gap_nonparabolicity`
NEARLY_CONFORMAL_GAP = 1e-3


def gap_nonparabolicity(a, rho, Rr) -> np.ndarray:
    r"""Relative error of Hertz's parabolic gap at the contact edge ``x = a``.

    The gap between two circles of signed radii ``rho`` (cam) and ``Rr`` (roller) is
    :math:`h(x) = \frac{x^2}{2}(\frac1{R_r} + \frac1\rho) + \frac{x^4}{8}(\frac1{R_r^3} +
    \frac1{\rho^3}) + O(x^6)`; Hertz keeps the first term. The ratio of the second to the first
    at ``x = a``,

    .. math:: \epsilon = \frac{a^2}{4}\,\frac{1/R_r^3 + 1/\rho^3}{1/R_r + 1/\rho},

    is tiny for convex contacts (``a^2 / 4 R^2``) but grows without bound for a concave cam
    nearly conformal with the roller, where the quadratic terms cancel and the quartic ones do
    not. (Measured: rho = -1.02 Rr, eps = 0.62 %, FE p0 - Hertz = +0.55 %; rho = -1.005 Rr,
    eps = 2.5 %, FE - Hertz = +2.4 %.)
    """
    rho = np.asarray(rho, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        k = np.where(np.isfinite(rho), 1.0 / rho, 0.0)
        eps = 0.25 * np.asarray(a, float) ** 2 * (1.0 / Rr**3 + k**3) / (1.0 / Rr + k)
    return eps


def _hertz_rows(rows, flags, idx, cp: ContactParams, F, rho, method: str):
    """Fill Hertz a/p0 (and, for method hertz, the stress maxima) of rows ``idx``."""
    from ..hertz import HertzValidityWarning, LineContact

    if idx.size == 0:
        return
    with warnings.catch_warnings():  # a/R not small: flagged per row below instead
        warnings.simplefilter("ignore", HertzValidityWarning)
        hc = LineContact(F=F[idx], length=cp.length, R1=rho[idx], R2=cp.Rr, cam=cp.cam,
                         roller=cp.roller, mu=cp.mu, plane=cp.plane, direction=cp.sliding)
    for i in idx[~np.atleast_1d(hc.valid)]:
        flags[i].append("hertz_large_a")
    a_h = np.atleast_1d(np.asarray(hc.a, float))
    eps = gap_nonparabolicity(a_h, rho[idx], cp.Rr)
    for i in idx[(rho[idx] < 0) & (eps > NEARLY_CONFORMAL_GAP)]:
        flags[i].append("nearly_conformal")
    rows["a_hertz"][idx] = hc.a
    rows["p0_hertz"][idx] = hc.p0
    if method == "hertz":
        k = hertz_shape_factors(cp.mu, cp.cam.nu, cp.plane)
        p0, a = np.asarray(hc.p0), np.asarray(hc.a)
        rows["vm_max"][idx] = k["von_mises"][0] * p0
        rows["vm_depth"][idx] = k["von_mises"][1] * a
        rows["tau1_max"][idx] = k["tau1"][0] * p0
        rows["tau1_depth"][idx] = k["tau1"][1] * a
        for name in ("sx_min", "sx_max", "sz_min", "txz_absmax"):
            rows[name][idx] = k[name] * p0


def roller_does_not_fit(rho, Rr) -> np.ndarray:
    """``1/rho + 1/Rr <= 0``, i.e. a concave cam with ``|rho| <= Rr``: the roller does not fit.

    For a roller follower ``rho = rho_pitch - Rr``, so ``-Rr < rho < 0`` means a convex pitch
    curve tighter than the roller (an undercut cam) and ``rho = -Rr`` a perfectly conformal
    (zero-clearance) fit. Neither Hertz nor the FE has a contact solution there.
    """
    with np.errstate(divide="ignore"):
        return (1.0 / np.asarray(rho, float) + 1.0 / Rr) <= 0.0


def undercut_message(rho: float, Rr: float) -> str:
    return (f"concave cam with |rho| = {abs(rho) * 1e3:.6g} mm <= roller radius Rr = {Rr * 1e3:.6g} mm:"
            f" the roller does not fit the concave cam (pitch-curve radius rho + Rr = "
            f"{(rho + Rr) * 1e3:.6g} mm; undercut/interference), no contact solution")


def _fe_fill(rows, i, r):
    """Copy one :class:`femcam.fe.ContactResult` into row ``i``.

    Maxima are over both bodies (``StressMax.value``, depth ``z`` below that body's surface);
    surface extremes are on the cam surface of the FE model's stress window.
    """
    rows["a_fe"][i] = r.a
    rows["p0_fe"][i] = r.p0
    rows["vm_max"][i] = r.von_mises_max.value
    rows["vm_depth"][i] = r.von_mises_max.z
    rows["tau1_max"][i] = r.tau1_max.value
    rows["tau1_depth"][i] = r.tau1_max.z
    x, sx, sz, txz = surface_stresses_of(r)
    if sx.size:
        rows["sx_min"][i] = sx.min()
        rows["sx_max"][i] = sx.max()
        rows["sz_min"][i] = sz.min()
        rows["txz_absmax"][i] = np.abs(txz).max()
    rows["iterations"][i] = r.iterations
    rows["residual"][i] = r.residual
    rows["n_dofs"][i] = r.n_dofs


# ---------------------------------------------------------------------------------------------
# one chunk
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ChunkTask:
    """Everything a worker needs for one chunk (small: a scene and a few hundred angles)."""

    index: int
    scene: object
    theta: np.ndarray
    options: SweepOptions
    family: np.ndarray = field(default_factory=lambda: np.zeros(0, int))
    refs: dict = field(default_factory=dict)
    vtk_dir: str | None = None
    vtk_mask: np.ndarray | None = None
    slip: object | None = None      # femcam.wear.slip.SlipResult of these angles (None: no wear)
    wear_k: float = float("nan")    # Archard k, m^3/(N m)


def analytic_rows(scene, theta) -> tuple[dict, object]:
    """Rows with the kinematics/profile/load columns filled, and the scene state."""
    theta = np.asarray(theta, dtype=float)
    st = scene.analyse(theta)
    rows = empty_rows(theta.size)
    rows["theta"][:] = theta
    for name in ("s", "v", "a", "j", "phi", "rho", "Fc"):
        rows[name][:] = np.asarray(getattr(st, name), dtype=float)
    return rows, st


def contact_mask(rows, st) -> np.ndarray:
    lift = np.asarray(getattr(st, "liftoff", rows["Fc"] <= 0.0), dtype=bool)
    return ~lift & (rows["Fc"] > 0.0)


def run_chunk(task: ChunkTask) -> dict:
    """Compute the rows of one chunk (runs in a worker process).

    In worker processes and Dask worker threads BLAS runs single-threaded (the parallelism is
    over chunks; BLAS threads on top only oversubscribe the cores). The caller's process is left
    alone in the serial case.
    """
    import multiprocessing
    import threading

    from .._threads import single_threaded_blas

    if multiprocessing.parent_process() is None and threading.current_thread() is threading.main_thread():
        return _run_chunk(task)
    with single_threaded_blas():
        return _run_chunk(task)


def _run_chunk(task: ChunkTask) -> dict:
    opts = task.options
    cp = contact_params(task.scene)
    rows, st = analytic_rows(task.scene, task.theta)
    n = rows["theta"].size
    contact = contact_mask(rows, st)
    F, rho = rows["Fc"], rows["rho"]
    flags = [[] for _ in range(n)]

    # lift-off: no contact -- zero width, zero pressure, zero stress
    lift = np.flatnonzero(~contact)
    rows["status"][lift] = "liftoff"
    for name in ("a_hertz", "p0_hertz", "a_fe", "p0_fe", "vm_max", "tau1_max", "sx_min", "sx_max",
                 "sz_min", "txz_absmax"):
        rows[name][lift] = 0.0
    if opts.method == "hertz":
        rows["a_fe"][:] = np.nan
        rows["p0_fe"][:] = np.nan

    # the roller does not fit the concave cam: no contact solution at all
    nofit = contact & roller_does_not_fit(rho, cp.Rr)
    for i in np.flatnonzero(nofit):
        rows["status"][i] = "undercut"
        rows["message"][i] = undercut_message(float(rho[i]), cp.Rr)
    good = np.flatnonzero(contact & ~nofit)
    _hertz_rows(rows, flags, good, cp, F, rho, opts.method)
    rows["fe_time"][:] = 0.0
    rows["build_time"][:] = 0.0
    vtk_fe = {}
    if opts.method == "hertz":
        rows["status"][good] = "ok"
    else:
        for i in good:
            b0 = STATS["build_time"]
            try:
                fid = int(task.family[i])
                rho_ref, a_ref = task.refs[fid]
                model = model_for(cp, rho_ref, a_ref, opts)
                own = hasattr(model, "covers") and not model.covers(F[i], rho[i])
                if own:  # outside the family's range (e.g. nearly conformal): its own model
                    a_i = float(hertz_half_width_any(F[i:i + 1], rho[i:i + 1], cp)[0])
                    model = model_for(cp, float(rho[i]), a_i, opts)
                    flags[i].append("rebuilt")
                t0 = time.perf_counter()
                r = solve_cached(model, float(F[i]), float(rho[i]), cp.mu, cp.sliding,
                                 check=not own)
                t_solve = time.perf_counter() - t0
                tm = getattr(r, "timings", None) or {}
                rows["fe_time"][i] = (tm["contact"] + tm.get("recovery", 0.0)
                                      if "contact" in tm else t_solve)
                _fe_fill(rows, i, r)
                rows["family"][i] = fid
                if getattr(r, "outside_hertz", False) and "hertz_large_a" not in flags[i]:
                    flags[i].append("hertz_large_a")
                if getattr(r, "converged", True):
                    rows["status"][i] = "ok"
                else:
                    rows["status"][i] = "failed"
                    rows["message"][i] = str(getattr(r, "message", "FE contact solve did not converge"))
                if task.vtk_dir is not None and task.vtk_mask is not None and task.vtk_mask[i]:
                    vtk_fe[i] = r
            except (FemcamError, ValueError, ArithmeticError, RuntimeError, MemoryError) as exc:
                rows["status"][i] = "failed"
                msg = f"{type(exc).__name__}: {exc}"
                if os.environ.get("FEMCAM_DEBUG"):
                    msg += " | " + traceback.format_exc().replace("\n", " | ")
                rows["message"][i] = msg
            rows["build_time"][i] = STATS["build_time"] - b0
        ok = rows["status"] == "ok"
        with np.errstate(invalid="ignore", divide="ignore"):
            rows["err_a"][:] = np.where(ok, rows["a_fe"] / rows["a_hertz"] - 1.0, np.nan)
            rows["err_p0"][:] = np.where(ok, rows["p0_fe"] / rows["p0_hertz"] - 1.0, np.nan)
    fill_wear(rows, task.slip, task.wear_k, opts.method)
    # VTU files last: not part of any timing column
    if task.vtk_dir is not None and task.vtk_mask is not None:
        for i, r in vtk_fe.items():
            write_fe_vtu(Path(task.vtk_dir) / vtu_name(task.theta[i]), r,
                         wear=_vtu_wear(task, rows, i))
        if opts.method == "hertz":
            for i in np.flatnonzero(task.vtk_mask & (rows["status"] == "ok")):
                write_hertz_vtu(Path(task.vtk_dir) / vtu_name(task.theta[i]), cp, F[i], rho[i],
                                wear=_vtu_wear(task, rows, i))
    for i in range(n):
        rows["flags"][i] = ";".join(flags[i])
    for name in ("status", "flags", "wear_source", "message"):
        rows[name] = np.asarray(rows[name]).astype(str)
    delay = float(os.environ.get("FEMCAM_SWEEP_TEST_DELAY_S", "0") or 0)
    if delay > 0:  # test hook: makes "kill after k chunks" deterministic in the resume test
        time.sleep(delay)
    return rows


def _vtu_wear(task: ChunkTask, rows, i) -> dict | None:
    """Wear data for the VTU of row ``i``: k, v_slip, V_cam, depth per revolution, angle."""
    if task.slip is None or not np.isfinite(task.wear_k):
        return None
    return {"k": float(task.wear_k), "v_slip": float(rows["v_slip"][i]),
            "V_cam": float(rows["V_cam"][i]), "wear_depth_per_rev": float(rows["wear_depth"][i]),
            "theta_deg": float(np.degrees(rows["theta"][i])), "Fc": float(rows["Fc"][i])}


# ---------------------------------------------------------------------------------------------
# VTU per angle
# ---------------------------------------------------------------------------------------------
def vtu_name(theta: float) -> str:
    return f"angle_{np.degrees(theta):08.3f}deg.vtu"


def _field_data(wear: dict | None) -> dict:
    if not wear:
        return {}
    return {"theta_deg": wear["theta_deg"], "Fc_N": wear["Fc"], "wear_k_m3_per_N_m": wear["k"],
            "v_slip_m_s": wear["v_slip"], "V_cam_m_s": wear["V_cam"],
            "wear_depth_per_rev_m": wear["wear_depth_per_rev"]}


def write_fe_vtu(path: Path, r, wear: dict | None = None) -> None:
    """Both bodies of a solved angle (:func:`femcam.fe.export.scene_arrays`) plus wear.

    Extra point data ``wear_rate`` (m/s): Archard's local rate ``k p v_slip`` on the contact
    surfaces (``p`` = the FE nodal contact pressure), 0 elsewhere. Field data: ``theta_deg``,
    ``Fc_N``, ``wear_k_m3_per_N_m``, ``v_slip_m_s``, ``V_cam_m_s``, ``wear_depth_per_rev_m``.
    """
    from ..fe.export import scene_arrays
    from ..io import write_vtu

    points, cells, cell_type, point_data, body = scene_arrays(r)
    if wear:
        point_data = dict(point_data, wear_rate=wear["k"] * np.asarray(point_data["contact_pressure"])
                          * wear["v_slip"])
    write_vtu(path, points, [(cell_type, cells)], point_data, field_data=_field_data(wear),
              cell_data={"body": [body]})


def write_hertz_vtu(path: Path, cp: ContactParams, F: float, rho: float, n: int = 41,
                    wear: dict | None = None) -> None:
    """The analytic Hertz field in the cam on a structured grid ``|x| <= 3a``, ``0 <= z <= 3a``
    (plus ``contact_pressure`` and ``wear_rate = k p v_slip`` on the surface row z = 0)."""
    from ..hertz import LineContact
    from ..io import write_vtu

    hc = LineContact(F=F, length=cp.length, R1=rho, R2=cp.Rr, cam=cp.cam, roller=cp.roller,
                     mu=cp.mu, plane=cp.plane, direction=cp.sliding)
    a = float(hc.a)
    xs = np.linspace(-3 * a, 3 * a, 2 * n - 1)
    zs = np.linspace(0.0, 3 * a, n)
    X, Z = np.meshgrid(xs, zs)
    sf = hc.stress(X.ravel(), Z.ravel())
    ids = np.arange(X.size).reshape(Z.shape)
    quads = np.column_stack([ids[:-1, :-1].ravel(), ids[:-1, 1:].ravel(), ids[1:, 1:].ravel(),
                             ids[1:, :-1].ravel()])
    pts = np.column_stack([X.ravel(), -Z.ravel()])  # cam below the surface: y = -z
    data = {"sx": sf.sx, "sz": sf.sz, "txz": sf.txz, "sy": sf.sy, "tau1": sf.tau1,
            "von_mises": sf.von_mises}
    p = np.where(Z == 0.0, hc.pressure(X), 0.0).ravel()
    data["contact_pressure"] = p
    if wear:
        data["wear_rate"] = wear["k"] * p * wear["v_slip"]
    write_vtu(path, pts, [("quad", quads)], {k: np.asarray(v, float) for k, v in data.items()},
              field_data=_field_data(wear))


# ---------------------------------------------------------------------------------------------
# the worst angle, for the surface-stress plot
# ---------------------------------------------------------------------------------------------
def worst_surface_profile(result, scene, options: SweepOptions | None = None) -> dict:
    """Surface sx, sz, txz along x at the angle of highest p0: Hertz lines (+ FE points).

    The FE values come from the model the sweep used for that angle: its family's model
    (references from ``result.families``; in the process that ran the sweep it is the cached
    model and its cached solution, nothing is built or solved again), or the angle's own model
    for a ``rebuilt`` row.
    """
    from ..hertz import LineContact

    cp = contact_params(scene)
    i = result.worst_index("p0_fe" if result.method == "fe" else "p0_hertz")
    t = result.table
    F, rho, theta = float(t["Fc"][i]), float(t["rho"][i]), float(t["theta"][i])
    out = {"theta_deg": float(np.degrees(theta)), "Fc": F, "rho": rho, "mu": cp.mu}
    a_est = float(hertz_half_width_any(np.array([F]), np.array([rho]), cp)[0])
    if not bool(roller_does_not_fit(rho, cp.Rr)):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            hc = LineContact(F=F, length=cp.length, R1=rho, R2=cp.Rr, cam=cp.cam, roller=cp.roller,
                             mu=cp.mu, plane=cp.plane, direction=cp.sliding)
        x = np.linspace(-2.5, 2.5, 1001) * float(hc.a)
        sx, sz, txz = hc.surface_stress(x)
        out.update(x_hertz=x, sx_hertz=sx, sz_hertz=sz, txz_hertz=txz)
        out["a_hertz"] = float(hc.a)
    else:
        out["a_hertz"] = a_est
    if result.method == "fe" and t["status"][i] == "ok":
        opts = options or SweepOptions(**{k: v for k, v in result.provenance.get("options", {}).items()
                                          if k in ("a_over_h", "tolerance")})
        refs = {int(f["id"]): (float(f["rho_ref"]), float(f["a_ref"])) for f in result.families}
        fid = int(t["family"][i]) if np.isfinite(t["family"][i]) else -1
        rebuilt = "rebuilt" in str(t["flags"][i]).split(";")
        if rebuilt or fid not in refs:
            model, out["fe_model"] = model_for(cp, rho, a_est, opts), "own"
        else:
            model, out["fe_model"] = model_for(cp, *refs[fid], opts), f"family {fid}"
        r = solve_cached(model, F, rho, cp.mu, cp.sliding, check=False)
        xs, sxs, szs, txzs = surface_stresses_of(r)
        out.update(x_fe=xs, sx_fe=sxs, sz_fe=szs, txz_fe=txzs, p0_fe=float(r.p0))
    return out


def surface_stresses_of(r):
    """``(x, sx, sz, txz)`` on the cam surface from a ContactResult."""
    for names in (("x_surface", "sx", "sz", "txz"),
                  ("x_surface", "sx_surface", "sz_surface", "txz_surface")):
        if all(hasattr(r, n) for n in names):
            return tuple(np.asarray(getattr(r, n), float) for n in names)
    ss = r.surface_stress
    if callable(ss):
        ss = ss()
    return tuple(np.asarray(v, float) for v in ss)
