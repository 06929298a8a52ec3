"""Two-body FE contact model: build once (mesh, assemble, factorise, condense), solve many.

``ContactModel.build`` meshes the cam (surface radius ``rho_ref``) and the roller, assembles and
factorises each body once, condenses both onto the fine-zone contact vertices and precomputes
the stress operators near the contact (``SolverOptions.stress_operators``: or back-solves the
stresses per load case, for one-off models; docs/performance.md). ``model.solve(F, rho, mu)``
then only solves the small complementarity problem (``femcam.fe.contact``) with the gap of
the TRUE ``rho`` and multiplies the precomputed operators: a few milliseconds per cam angle.

Reuse error: the body meshes keep the ``rho_ref`` shape while the gap uses ``rho``; the contact
fine zone is ``|x| <= fine_half_width * a_ref``. ``model.covers(F, rho)`` says whether a load case
is inside the validated range (``SolverOptions.a_range``, ``kappa_tol``; see docs/fe.md for the
measured reuse errors).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from .. import _validate as chk
from ..errors import PhysicsError
from ..hertz.conformity import roller_does_not_fit
from ..hertz.contact import effective_radius, half_width, peak_pressure
from ..materials import PLANES, Material, effective_modulus
from ..mesh import ContactMesh, MeshOptions, build_contact_mesh, surface_height
from .contact import load_matrix, solve_lcp, trapezoid_weights
from .elasticity import ELEMENTS, ORDERINGS, Body, assemble_body
from .recovery import build_eval_set, derived, fit_half_width
from .traction import solve_partial_slip

#: values of ``SolverOptions.stress_operators``
STRESS_OPERATORS = ("precompute", "per_solve")


@dataclass(frozen=True, kw_only=True)
class SolverOptions:
    """Contact solver and model-reuse options.

    ordering: SuperLU column ordering (``MMD_AT_PLUS_A`` default, see elasticity.py).
    max_iter, tol: active-set iteration limit and complementarity tolerance.
    a_range: model covers load cases with Hertz a / a_ref in this interval.
    kappa_tol: ... and with |1/rho - 1/rho_ref| * L_cam <= kappa_tol (cam shape reuse).
    eval_depth: stresses are precomputed at nodes down to eval_depth * a_ref below the surface
        (and over the fine zone in x).
    fit_threshold: nodes with p > fit_threshold * max(p) enter the half-width fit.
    stress_operators: ``"precompute"``: the build condenses the stresses of the window onto the
        contact unknowns (2 n_c solves per body; each solve then costs a few ms): for models
        solved at many load cases (sweep families). ``"per_solve"``: the contact DOFs are
        factorised last and the contact compliance is the Schur complement in the trailing
        factor blocks (no solve per contact unknown); each solve back-solves both bodies once
        for the stresses: for one-off models (a single scene, fresh verification models).
        Same numbers to ~1e-12; times in docs/performance.md (benchmarks/bench_fe.py --modes).
    """

    ordering: str = "MMD_AT_PLUS_A"
    max_iter: int = 50
    tol: float = 1e-10
    a_range: tuple = (0.6, 1.6)
    kappa_tol: float = 0.5
    eval_depth: float = 2.0
    fit_threshold: float = 0.2
    stress_operators: str = "precompute"

    def __post_init__(self):
        chk.choice("ordering", self.ordering, ORDERINGS)
        chk.in_range("max_iter", self.max_iter, 1, 10000, "")
        chk.positive("tol", self.tol, "")
        lo = chk.positive("a_range[0]", self.a_range[0], "")
        hi = chk.positive("a_range[1]", self.a_range[1], "")
        if lo >= hi:
            raise chk.fail("a_range", self.a_range, "", "must be (lo, hi) with lo < hi")
        chk.positive("kappa_tol", self.kappa_tol, "")
        chk.in_range("eval_depth", self.eval_depth, 0.0, 20.0, "(x a_ref)")
        chk.in_range("fit_threshold", self.fit_threshold, 0.0, 0.9, "")
        chk.choice("stress_operators", self.stress_operators, STRESS_OPERATORS)


@dataclass(frozen=True)
class StressMax:
    """A stress maximum: value (Pa), location (x, z) in m in the body's frame, body name."""

    value: float
    x: float
    z: float
    body: str


#: (key, field, arg-extremum) of ``ContactResult.max_by_body[body]``: the first three are maxima
#: of non-negative quantities, ``<c>_max`` / ``<c>_min`` the largest / most negative value of
#: component ``<c>``
_EXTREMA = (("von_mises", "von_mises", np.argmax), ("tau1", "tau1", np.argmax),
            ("txz_abs", "txz_abs", np.argmax), ("sx_max", "sx", np.argmax), ("sx_min", "sx", np.argmin),
            ("sz_max", "sz", np.argmax), ("sz_min", "sz", np.argmin), ("sy_max", "sy", np.argmax),
            ("sy_min", "sy", np.argmin))
#: keys of ``ContactResult.max_by_body[body]`` (see ``_EXTREMA``)
MAXIMA_KEYS = tuple(k for k, _, _ in _EXTREMA)


def _over_bodies(key: str) -> property:
    """Read-only ``ContactResult`` attribute: the :class:`StressMax` ``key`` over both bodies
    (the most negative for ``*_min`` keys, else the largest; the cam's on a tie)."""
    pick = min if key.endswith("_min") else max

    def get(self) -> StressMax:
        return pick((m[key] for m in self.max_by_body.values()), key=lambda s: s.value)

    return property(get, doc=f"StressMax of ``{key}`` over both bodies")


def _cam_surface(name: str) -> property:
    """Read-only ``ContactResult`` attribute: field ``name`` of ``surface_by_body["cam"]``."""
    return property(lambda self: getattr(self.surface_by_body["cam"], name),
                    doc=f"cam surface ``{name}`` (``surface_by_body['cam'].{name}``)")


@dataclass(frozen=True, eq=False)
class SurfaceStress:
    """Stresses (Pa) on the contact surface (z = 0) of one body in its Johnson frame, sorted by x
    (m), at the vertex and P2 midside nodes of the fine-zone contact curve
    ``|x| <= fine_half_width * a_ref``; ``sy`` the out-of-plane stress."""

    x: np.ndarray
    sx: np.ndarray
    sz: np.ndarray
    txz: np.ndarray
    sy: np.ndarray
    body: str


@dataclass(frozen=True, eq=False)
class ContactResult:
    """Solution of one load case (per the model's face width ``length``).

    Attributes
    ----------
    F : float
        Contact force over ``length`` (N).
    rho : float
        Cam radius of curvature passed to the solve (m; inf flat, < 0 concave).
    mu : float
        Friction coefficient (-).
    sliding : int
        +1/-1, direction of the full-sliding traction on the cam (used when ``Q`` is None).
    a, x0 : float
        Fitted Hertz half-width and centre (m) (a Hertz-ellipse fit: near a curvature jump the
        pressure is not an ellipse, use ``p0_nodal``).
    p0 : float
        Fitted peak pressure (Pa).
    p0_nodal : float
        Largest nodal pressure (Pa).
    x, p : ndarray
        Contact vertex abscissae (m) and pressures (Pa).
    gap : ndarray
        Gap after loading at the vertices (m).
    delta : float
        Rigid approach (m).
    force, force_error : float
        Integral of p times length (N) and its relative error against F (-).
    max_by_body : dict
        ``{"cam"|"roller": {key: StressMax}}`` with the keys of :data:`MAXIMA_KEYS` over the
        stress window ``|x| <= fine_half_width * a_ref``, ``z <= eval_depth * a_ref``; the nine
        over both bodies (``von_mises_max``, ``tau1_max``, ``txz_abs_max``, ``sx_max``,
        ``sx_min``, ``sz_max``, ``sz_min``, ``sy_max``, ``sy_min``; Pa) are properties derived
        from it (e.g. the trailing-edge tension ``sx_max`` ~ 2 mu p0 at x = -a on the cam for
        ``sliding = +1``).
    surface_by_body : dict
        ``{"cam"|"roller": SurfaceStress}`` (Pa, each in its own Johnson frame); ``x_surface``,
        ``sx``, ``sz``, ``txz`` are the cam's (properties).
    iterations, residual, history, active : int, float, tuple, ndarray
        Active-set diagnostics of the normal problem (residual dimensionless).
    converged : bool
        True when the normal (and tangential) active sets settled within tolerance; False with
        the reason in ``message``.
    timings : dict
        Seconds per phase (mesh, assembly, factorisation, condensation, contact, recovery).
    n_dofs : int
        Total degrees of freedom.
    hertz_a, hertz_p0 : float
        Hertz half-width (m) and peak (Pa) of the osculating arcs (nan if Hertz does not apply).
    outside_hertz : bool
        Hertz a / min radius > 0.1.
    q : ndarray
        Tangential traction at the vertices on the cam in +x (Pa): ``sliding mu p`` for full
        sliding, the partial-slip solution when ``Q`` was given.
    Q : float
        Tangential force carried, ``length * w . q`` (N, on the cam in +x).
    slip_state : str
        ``"none"``, ``"stick"``, ``"partial slip"`` or ``"sliding"``.
    stick : ndarray of bool
        Stick nodes (partial slip).
    stick_width : float
        Extent of the stick zone (m).
    creep, shift : float
        Carter creepage (-) when rolling, Cattaneo rigid shift (m) without (nan otherwise).
    message : str
        Why the solve did not converge (empty when it did).
    """

    F: float
    rho: float
    mu: float
    sliding: int
    a: float
    x0: float
    p0: float
    p0_nodal: float
    x: np.ndarray
    p: np.ndarray
    gap: np.ndarray
    delta: float
    force: float
    force_error: float
    max_by_body: dict
    surface_by_body: dict
    iterations: int
    residual: float
    history: tuple
    active: np.ndarray
    converged: bool
    timings: dict
    n_dofs: int
    hertz_a: float
    hertz_p0: float
    outside_hertz: bool
    model: ContactModel = field(repr=False)
    q: np.ndarray | None = None
    Q: float = 0.0
    slip_state: str = "none"
    stick: np.ndarray | None = None
    stick_width: float = 0.0
    creep: float = math.nan
    shift: float = math.nan
    message: str = ""

    # derived from max_by_body / surface_by_body (not stored twice)
    von_mises_max = _over_bodies("von_mises")
    tau1_max = _over_bodies("tau1")
    txz_abs_max = _over_bodies("txz_abs")
    sx_max = _over_bodies("sx_max")
    sx_min = _over_bodies("sx_min")
    sz_max = _over_bodies("sz_max")
    sz_min = _over_bodies("sz_min")
    sy_max = _over_bodies("sy_max")
    sy_min = _over_bodies("sy_min")
    x_surface = _cam_surface("x")
    sx = _cam_surface("sx")
    sz = _cam_surface("sz")
    txz = _cam_surface("txz")

    def __getstate__(self):
        # a pickled result is independent of its model (the factorisation is large and bound
        # to this process): the full-field methods then take the model explicitly
        return {**self.__dict__, "model": None}

    def model_or(self, model=None) -> ContactModel:
        """``model``, else the model that solved this result (None after unpickling: pass it)."""
        m = model if model is not None else self.model
        if m is None:
            raise chk.fail("model", None, "", "this ContactResult was unpickled without its "
                           "factorised model; pass the ContactModel that solved it (model=...)")
        return m

    def field_at_nodes(self, body: str = "cam", model=None):
        """Full-field (u (2, n), stress dict) at the scalar nodes of ``body`` (one back-solve)."""
        return self.model_or(model).full_field(self, body)

    def stress_at(self, x, z, body: str = "cam", model=None):
        """(sx, sz, txz, sy, tau1, von_mises) at arbitrary points (x, z >= 0 depth), Pa."""
        return self.model_or(model).stress_at(self, x, z, body)

    def to_vtu(self, path, model=None):
        """Write both bodies to one .vtu (see :mod:`femcam.fe.export`); returns the path."""
        from .export import write_vtu

        return write_vtu(self, path, model=model)


def _traction_fields(trac, Q, q, w, x, length, mu) -> dict:
    """ContactResult traction fields from a TractionSolution (or the friction-free/sliding q)."""
    if trac is None:
        state = "sliding" if np.any(q) else "none"
        return {"Q": float(w @ q) * length, "slip_state": state, "stick": np.zeros(x.size, bool),
                "stick_width": 0.0, "creep": math.nan, "shift": math.nan}
    return {"Q": float(w @ trac.q) * length, "slip_state": trac.slip_state, "stick": trac.stick,
            "stick_width": trac.stick_width, "creep": trac.creep, "shift": trac.shift}


def _hertz(F, length, rho, Rr, cam, roller, plane):
    """Hertz (a, p0) from Johnson eq. 4.45 (:mod:`femcam.hertz`); (nan, nan) when 1/R <= 0."""
    if roller_does_not_fit(rho, Rr):
        return math.nan, math.nan
    w = F / length
    a = float(half_width(w, effective_radius(rho, Rr), effective_modulus(cam, roller, plane)))
    return a, float(peak_pressure(w, a))


def _radius(name: str, value) -> float:
    """A signed radius of curvature (m): a real number or +-inf (flat), not 0 or nan."""
    if isinstance(value, bool) or not isinstance(value, int | float | np.integer | np.floating):
        raise chk.fail(name, value, "m", "must be a number (inf for a flat cam)")
    if math.isnan(value) or value == 0:
        raise chk.fail(name, value, "m", "must be nonzero (inf for a flat cam)")
    return float(value)


@dataclass(frozen=True, eq=False)
class ContactModel:
    """Factorised two-body model; see the module docstring. Build with :meth:`build`."""

    Rr: float
    rho_ref: float
    a_ref: float
    length: float
    cam: Material
    roller: Material
    plane: str
    element: str
    mesh: ContactMesh
    bodies: dict
    x: np.ndarray
    w: np.ndarray
    An: np.ndarray
    At: np.ndarray
    Bn: dict
    Bt: dict
    evals: dict
    options: SolverOptions
    timings: dict
    n_dofs: int
    #: tangential compliances (m/Pa): u_cam,x - u_roller,x per unit tangential / normal hat
    Ctt: np.ndarray | None = None
    Ctn: np.ndarray | None = None
    #: per-body full-field stress operators, built on the first :meth:`full_field` (they were
    #: rebuilt for every written .vtu: 1.44 s -> 0.41 s CPU for the 36 files of README command 1)
    _field_ops: dict = field(default_factory=dict, repr=False)

    @classmethod
    def build(cls, *, Rr: float, rho_ref: float, cam: Material, roller: Material, length: float,
              a_ref: float, mesh: MeshOptions | None = None, solver: SolverOptions | None = None,
              plane: str = "strain", element: str = "P2") -> ContactModel:
        """Mesh, assemble, factorise and condense (see module docstring)."""
        rho_ref = _radius("rho_ref", rho_ref)
        for name, v, kind, what in (("cam", cam, Material, "Material"),
                                    ("roller", roller, Material, "Material"),
                                    ("mesh", mesh, MeshOptions | None, "MeshOptions or None"),
                                    ("solver", solver, SolverOptions | None, "SolverOptions or None")):
            if not isinstance(v, kind):
                raise chk.fail(name, v, "", f"must be a {what}")
        Rr = chk.positive("Rr", Rr, "m")
        length = chk.positive("length", length, "m")
        a_ref = chk.positive("a_ref", a_ref, "m")
        chk.choice("plane", plane, PLANES)
        chk.choice("element", element, ELEMENTS)
        solver = solver or SolverOptions()
        t0 = time.perf_counter()
        cm = build_contact_mesh(Rr=Rr, rho=rho_ref, a_ref=a_ref, options=mesh)
        t_mesh = time.perf_counter() - t0
        bodies, Bn, Bt, An, At, evals = {}, {}, {}, None, None, {}
        Ctt, Ctn = 0.0, 0.0  # tangential condensed compliances (femcam.fe.traction)
        t_cond = 0.0
        x = cm.cam.contact_x
        for name, geo, mat in (("cam", cm.cam, cam), ("roller", cm.roller, roller)):
            b = assemble_body(geo, mat, plane=plane, element=element, ordering=solver.ordering,
                              contact_last=solver.stress_operators == "per_solve")
            bodies[name] = b
            t1 = time.perf_counter()
            # body-specific signs: pressure into the body, friction +x on cam, -x on roller
            sn = -1.0 if name == "cam" else 1.0
            st = 1.0 if name == "cam" else -1.0
            # sparse: a hat loads 3 nodes (the dense (n_dofs, n_c) arrays were 2 x 54 MB per
            # body at a/h = 40, kept for full_field)
            Bn[name] = sp.csc_matrix(sn * load_matrix(b, geo.contact, x, 1))
            Bt[name] = sp.csc_matrix(st * load_matrix(b, geo.contact, x, 0))
            # displacements read at the contact vertices: normal (y) rows, then tangential (x)
            ydof = b.basis.nodal_dofs[1, geo.contact]
            cdof = np.concatenate([ydof, b.basis.nodal_dofs[0, geo.contact]])
            S_c = sp.csr_matrix((np.ones(cdof.size), (np.arange(cdof.size), cdof)),
                                shape=(cdof.size, b.n_dofs))
            evals[name], Yn, Yt = build_eval_set(
                b, Bn[name], Bt[name], S_c, float(x[-1]), solver.eval_depth * a_ref,
                precompute=solver.stress_operators == "precompute")
            # separation grows with roller uy and with -cam uy
            sg = 1.0 if name == "roller" else -1.0
            nc = ydof.size
            An = sg * Yn[:nc] if An is None else An + sg * Yn[:nc]
            At = sg * Yt[:nc] if At is None else At + sg * Yt[:nc]
            # relative tangential displacement u_cam,x - u_roller,x (femcam.fe.traction)
            Ctt = Ctt - sg * Yt[nc:]
            Ctn = Ctn - sg * Yn[nc:]
            t_cond += time.perf_counter() - t1
        timings = {"mesh": t_mesh,
                   "assembly": sum(b.t_assembly for b in bodies.values()),
                   "factorisation": sum(b.t_factor for b in bodies.values()),
                   "condensation": t_cond}
        return cls(Rr=Rr, rho_ref=float(rho_ref), a_ref=a_ref, length=length, cam=cam, roller=roller,
                   plane=plane, element=element, mesh=cm, bodies=bodies, x=x,
                   w=trapezoid_weights(x), An=An, At=At, Bn=Bn, Bt=Bt, evals=evals,
                   options=solver, timings=timings,
                   n_dofs=sum(b.n_dofs for b in bodies.values()), Ctt=Ctt, Ctn=Ctn)

    # ------------------------------------------------------------------ validity
    def hertz(self, F: float, rho: float):
        """Hertz (a, p0) of the load case, (nan, nan) if Hertz does not apply."""
        return _hertz(F, self.length, rho, self.Rr, self.cam, self.roller, self.plane)

    def coverage(self, F: float, rho: float) -> str:
        """Empty string if the model covers (F, rho), else the reason."""
        k = 0.0 if math.isinf(rho) else 1.0 / rho
        k_ref = 0.0 if math.isinf(self.rho_ref) else 1.0 / self.rho_ref
        dk = abs(k - k_ref) * self.mesh.cam.L
        if dk > self.options.kappa_tol:
            return (f"cam curvature 1/rho = {k:g} 1/m differs from the mesh's {k_ref:g} 1/m by "
                    f"{dk:.3g} x body size (> kappa_tol = {self.options.kappa_tol:g})")
        if roller_does_not_fit(rho, self.Rr):
            return f"rho = {rho:g} m: concave cam with |rho| <= Rr = {self.Rr:g} m"
        a, _ = self.hertz(F, rho)
        lo, hi = self.options.a_range
        if math.isfinite(a) and F > 0 and not (lo <= a / self.a_ref <= hi):
            return (f"predicted half-width a = {a:.4g} m is {a / self.a_ref:.3g} a_ref, outside "
                    f"a_range = [{lo:g}, {hi:g}]")
        return ""

    def covers(self, F: float, rho: float) -> bool:
        """True if (F, rho) is inside the range this model was built and validated for."""
        return not self.coverage(F, rho)

    # ------------------------------------------------------------------ solve
    def solve(self, *, F: float, rho: float, mu: float = 0.0, sliding: int = 1,
              check: bool = True, gap: np.ndarray | None = None, Q: float | None = None,
              rolling: int = 0) -> ContactResult:
        """Solve one load case with full sliding friction (or none).

        Parameters
        ----------
        F : float
            Contact force over the face width ``length`` (N).
        rho : float
            Cam radius of curvature at the contact (m; < 0 concave, inf flat). Sets the
            osculating-arc gap when ``gap`` is None, and the Hertz estimate and coverage check.
        mu : float
            Coulomb friction coefficient (-); the traction is ``sliding * mu * p`` on the cam.
        sliding : {+1, -1}
            Direction of the friction traction on the cam along x.
        check : bool
            Raise :class:`PhysicsError` when :meth:`covers` is False.
        gap : ndarray, optional
            Initial gap (m) at the contact vertices ``self.x`` (e.g. the exact gap of
            :func:`femcam.fe.gap.exact_gap`); default the two osculating arcs.
        Q : float, optional
            Tangential force on the cam in +x over ``length`` (N). None (default): the traction
            is ``sliding * mu * p`` (full sliding). Given: Coulomb partial slip
            (:mod:`femcam.fe.traction`); ``|Q| >= mu F`` is full sliding in the direction of
            ``Q`` (``slip_state = "sliding"``), never a failed solve.
        rolling : {0, +1, -1}
            With ``Q``: 0 is a Cattaneo-Mindlin shift (no rolling), +-1 steady rolling with the
            surface material flowing through the contact in +-x (Carter).

        Returns
        -------
        ContactResult
            Pressures (Pa), half-width (m), stresses (Pa) and solver diagnostics. The solve
            always raises :class:`PhysicsError` when the loaded zone reaches the end of the
            meshed fine zone, and :class:`ConvergenceError` when the active set does not settle.
        """
        F, rho, mu, Q = self._check_inputs(F, rho, mu, sliding, Q, rolling)
        if math.isfinite(rho) and rho < 0 and -rho <= self.Rr:
            raise PhysicsError(f"rho = {rho:g} m: a concave cam with |rho| <= Rr = {self.Rr:g} m cannot "
                               "hold the roller (conformal or interfering contact)")
        if check and F > 0:
            why = self.coverage(F, rho)
            if why:
                raise PhysicsError(f"load case outside the model's range: {why}; rebuild the model")
        t0 = time.perf_counter()
        nc = self.x.size
        aH, p0H = self.hertz(F, rho)
        if F == 0.0:
            p = np.zeros(nc)
            h0 = self._gap(rho, gap)
            sol_p, g, delta, active, it, res, hist, conv = p, h0, 0.0, np.zeros(nc, bool), 0, 0.0, (), True
            q, trac, msg = p, None, ""
        else:
            sol, q, trac = self._contact(F, rho, mu, sliding, self._gap(rho, gap), Q, rolling, aH)
            sol_p, g, delta, active = sol.p, sol.g, sol.delta, sol.active
            it, res, hist, msg = sol.iterations, sol.residual, sol.history, sol.message
            conv = sol.converged and (trac is None or trac.converged)
            if trac is not None and trac.message:
                msg = f"{msg}; {trac.message}" if msg else trac.message
        t1 = time.perf_counter()
        a, x0, p0 = fit_half_width(self.x, sol_p, self.options.fit_threshold)
        force = float(self.w @ sol_p) * self.length
        maxima, surfaces = {}, {}
        for name, ev in self.evals.items():
            s = ev.stresses(sol_p, q)
            sx, sz, txz = s
            sy = self._sy(name, sx, sz)
            tau1, vm = derived(sx, sz, txz, sy)
            fields = {"von_mises": vm, "tau1": tau1, "txz_abs": np.abs(txz), "sx": sx, "sz": sz,
                      "sy": sy}
            m = {}
            for key, comp, arg in _EXTREMA:
                i = int(arg(fields[comp]))
                m[key] = StressMax(float(fields[comp][i]), float(ev.x[i]), float(ev.z[i]), name)
            maxima[name] = m
            k = ev.surface
            surfaces[name] = SurfaceStress(x=ev.x[k], sx=sx[k], sz=sz[k], txz=txz[k], sy=sy[k],
                                           body=name)
        t2 = time.perf_counter()
        timings = dict(self.timings, contact=t1 - t0, recovery=t2 - t1)
        outside = bool(math.isfinite(aH) and aH / min(self.Rr, abs(rho)) > 0.1)
        return ContactResult(
            F=F, rho=rho, mu=mu, sliding=sliding, a=a, x0=x0, p0=p0,
            p0_nodal=float(sol_p.max()) if sol_p.size else 0.0, x=self.x, p=sol_p, gap=g,
            delta=float(delta), force=force, force_error=(abs(force - F) / F if F > 0 else 0.0),
            max_by_body=maxima, surface_by_body=surfaces,
            iterations=it, residual=res, history=hist, active=active, converged=conv,
            timings=timings, n_dofs=self.n_dofs, hertz_a=aH, hertz_p0=p0H, outside_hertz=outside,
            model=self, q=q, message=msg, **_traction_fields(trac, Q, q, self.w, self.x, self.length, mu))

    def _contact(self, F, rho, mu, sliding, h0, Q, rolling, aH):
        """Normal LCP, and with ``Q`` the partial-slip traction (fixed point on the normal-
        tangential coupling ``At q``; one pass for similar materials). Returns (LCP solution,
        q (Pa, on the cam in +x), TractionSolution or None)."""
        a0 = aH if math.isfinite(aH) else self.a_ref
        W = F / self.length
        kw = dict(active0=np.abs(self.x) < a0, max_iter=self.options.max_iter, tol=self.options.tol)
        trac = None
        if Q is None or abs(Q) >= mu * F:  # friction-free, full sliding at mu, or Q it cannot carry
            s = sliding if Q is None else (1 if Q >= 0 else -1)
            sol = solve_lcp(self.An + (s * mu) * self.At, h0, self.w, W, **kw)
            q = (s * mu) * sol.p
            if Q is not None:
                trac = solve_partial_slip(self.Ctt, self.x, self.w, sol.p, Q / self.length, mu)
        else:
            q = np.zeros_like(self.x)
            # similar materials (Dundurs beta = 0): normal and tangential problems decouple
            # (Johnson 1985 §7.1), one pass; otherwise a fixed point on the coupling At q
            similar = (self.cam.E, self.cam.nu) == (self.roller.E, self.roller.nu)
            for _ in range(1 if similar else 20):
                sol = solve_lcp(self.An, h0 + self.At @ q, self.w, W, **kw)
                trac = solve_partial_slip(self.Ctt, self.x, self.w, sol.p, Q / self.length, mu,
                                          rolling=rolling, u0=self.Ctn @ sol.p)
                dq = float(np.max(np.abs(trac.q - q)))
                q = trac.q
                if dq <= 1e-9 * max(float(np.max(np.abs(q))), 1e-300):
                    break
        if sol.active[0] or sol.active[-1]:
            raise PhysicsError(
                f"the loaded zone reaches the end of the meshed fine zone |x| <= {self.x[-1]:.4g} m "
                f"(F = {F:g} N, rho = {rho:g} m); rebuild with a larger a_ref")
        return sol, q, trac

    @staticmethod
    def _check_inputs(F, rho, mu, sliding, Q, rolling):
        """Checked (F, rho, mu, Q) of :meth:`solve`."""
        F = chk.nonnegative("F", F, "N")
        rho = _radius("rho", rho)
        if math.isnan(rho) or rho == 0.0:
            raise chk.fail("rho", rho, "m", "must be nonzero (inf for a flat cam)")
        mu = chk.nonnegative("mu", mu, "")
        if sliding not in (1, -1):
            raise chk.fail("sliding", sliding, "", "must be +1 or -1")
        if Q is not None:
            Q = chk.number("Q", Q, "N")
        if rolling not in (0, 1, -1):
            raise chk.fail("rolling", rolling, "", "must be 0 (no rolling), +1 or -1")
        return F, rho, mu, Q

    def _gap(self, rho: float, gap) -> np.ndarray:
        """Initial gap (m) at ``self.x``: ``gap`` if given (checked), else the osculating arcs."""
        if gap is None:
            return surface_height(self.x, self.Rr) + surface_height(self.x, rho)
        g = chk.finite_array("gap", gap, "m")
        if g.shape != self.x.shape:
            raise chk.fail("gap", f"shape {g.shape}", "m", f"must have the shape {self.x.shape} of model.x")
        return g

    def _sy(self, name, sx, sz):
        nu = (self.cam if name == "cam" else self.roller).nu
        return nu * (sx + sz) if self.plane == "strain" else np.zeros_like(sx)

    # ------------------------------------------------------------------ full fields
    def full_field(self, r: ContactResult, body: str = "cam"):
        """Displacement (2, n_scalar) and stresses at all scalar nodes of ``body``."""
        from .elasticity import scalar_node_coordinates, stress_operator
        from .recovery import depth, johnson_frame

        chk.choice("body", body, ("cam", "roller"))
        b: Body = self.bodies[body]
        q = r.q if r.q is not None else (r.sliding * r.mu) * r.p  # partial slip: the solved q
        f = self.Bn[body] @ r.p + self.Bt[body] @ q
        u = b.solve(f)
        S = self._field_ops.get(body)
        if S is None:
            S = self._field_ops.setdefault(body, stress_operator(b))
        s = S @ u
        n = b.n_dofs // 2
        sx, sz, txz = johnson_frame(b, s[:n], s[n:2 * n], s[2 * n:])
        sy = self._sy(body, sx, sz)
        tau1, vm = derived(sx, sz, txz, sy)
        xy = scalar_node_coordinates(b)
        return np.stack([u[0::2], u[1::2]]), {
            "sx": sx, "sz": sz, "txz": txz, "sy": sy, "tau1": tau1, "von_mises": vm,
            "xy": xy, "z": depth(b, xy)}

    def stress_at(self, r: ContactResult, x, z, body: str = "cam"):
        """Stresses interpolated (P2 nodal field) at points (x, z) of ``body``; Pa."""
        x = chk.finite_array("x", x, "m")
        z = chk.finite_array("z", z, "m")
        x, z = np.broadcast_arrays(x, z)
        b: Body = self.bodies[body]
        ys = surface_height(x, b.geometry.R)
        y = (-ys - z) if body == "cam" else (ys + z)
        from skfem import Basis

        _, fld = self.full_field(r, body)
        sb = Basis(b.mesh, b.basis.elem.elem)
        try:
            P = sb.probes(np.stack([x.ravel(), y.ravel()]))
        except ValueError:
            raise chk.fail("(x, z)", (x.tolist(), z.tolist()), "m", "must lie inside the body") from None
        return tuple((P @ fld[k]).reshape(x.shape)
                     for k in ("sx", "sz", "txz", "sy", "tau1", "von_mises"))


def solve_contact(F: float, rho: float, Rr: float, cam: Material, roller: Material, length: float,
                  mu: float = 0.0, *, sliding: int = 1, a_ref: float | None = None,
                  mesh: MeshOptions | None = None, solver: SolverOptions | None = None,
                  plane: str = "strain", element: str = "P2") -> ContactResult:
    """Build a model graded for this load case and solve it (cold). ``a_ref`` defaults to Hertz a
    (or, when Hertz does not apply or F = 0, 1 % of Rr). A one-off model: ``solver`` defaults
    to ``SolverOptions(stress_operators="per_solve")`` (same numbers, no per-unknown solves)."""
    if a_ref is None:
        aH, _ = _hertz(chk.nonnegative("F", F, "N"), chk.positive("length", length, "m"), float(rho),
                       chk.positive("Rr", Rr, "m"), cam, roller, plane)
        a_ref = aH if (math.isfinite(aH) and aH > 0) else 0.01 * Rr
    solver = solver or SolverOptions(stress_operators="per_solve")
    model = ContactModel.build(Rr=Rr, rho_ref=rho, cam=cam, roller=roller, length=length, a_ref=a_ref,
                               mesh=mesh, solver=solver, plane=plane, element=element)
    return model.solve(F=F, rho=rho, mu=mu, sliding=sliding)
