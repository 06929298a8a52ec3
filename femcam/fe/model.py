"""Two-body FE contact model: build once (mesh, assemble, factorise, condense), solve many.

``ContactModel.build`` meshes the cam (surface radius ``rho_ref``) and the roller, assembles and
factorises each body once, condenses both onto the fine-zone contact vertices and precomputes
the stress operators near the contact. ``model.solve(F, rho, mu)`` then only solves the small
complementarity problem (``femcam.fe.contact``) with the gap of the TRUE ``rho`` and multiplies
the precomputed operators: a few milliseconds per cam angle.

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

from .. import _validate as chk
from ..errors import PhysicsError
from ..hertz.conformity import roller_does_not_fit
from ..hertz.contact import effective_radius, half_width, peak_pressure
from ..materials import PLANES, Material, effective_modulus
from ..mesh import ContactMesh, MeshOptions, build_contact_mesh, surface_height
from .contact import load_matrix, solve_lcp, trapezoid_weights
from .elasticity import ELEMENTS, ORDERINGS, Body, assemble_body
from .recovery import build_eval_set, derived, fit_half_width


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
    """

    ordering: str = "MMD_AT_PLUS_A"
    max_iter: int = 50
    tol: float = 1e-10
    a_range: tuple = (0.6, 1.6)
    kappa_tol: float = 0.5
    eval_depth: float = 2.0
    fit_threshold: float = 0.2

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

    a, x0: fitted half-width and centre (m); p0: fitted peak (Pa); p0_nodal: max nodal pressure;
    x, p: contact vertex abscissae (m) and pressures (Pa); force: integral of p times length (N),
    force_error: relative error against F; delta: rigid approach (m); gap (m) at the vertices;
    von_mises_max, tau1_max, txz_abs_max: StressMax (largest value) over both bodies;
    sx_max, sx_min, sz_max, sz_min, sy_max, sy_min: StressMax of the signed components (``_max``
    the largest, e.g. the trailing-edge tension ``sx_max`` ~ 2 mu p0 at x = -a on the cam for
    ``sliding = +1``; ``_min`` the most compressive, e.g. ``sz_min`` ~ -p0 at the surface);
    max_by_body: ``{"cam"|"roller": {key: StressMax}}`` with the keys of :data:`MAXIMA_KEYS`
    (the nine over both bodies above are read-only properties derived from it);
    all over the stress window ``|x| <= fine_half_width * a_ref``, ``z <= eval_depth * a_ref``;
    x_surface, sx, sz, txz: cam surface stresses (Johnson frame, Pa; properties, the arrays of
    ``surface_by_body["cam"]``); surface_by_body:
    ``{"cam"|"roller": SurfaceStress}`` (the roller's in its own Johnson frame: its friction
    traction acts in ``-sliding x``, so its tension peak is at x = +a); iterations, residual,
    history, active, converged; timings (s) per phase; n_dofs; hertz_a, hertz_p0 (if Hertz
    applies) and outside_hertz (a / min radius > 0.1).
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


def _hertz(F, length, rho, Rr, cam, roller, plane):
    """Hertz (a, p0) from Johnson eq. 4.45 (:mod:`femcam.hertz`); (nan, nan) when 1/R <= 0."""
    if roller_does_not_fit(rho, Rr):
        return math.nan, math.nan
    w = F / length
    a = float(half_width(w, effective_radius(rho, Rr), effective_modulus(cam, roller, plane)))
    return a, float(peak_pressure(w, a))


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

    @classmethod
    def build(cls, *, Rr: float, rho_ref: float, cam: Material, roller: Material, length: float,
              a_ref: float, mesh: MeshOptions | None = None, solver: SolverOptions | None = None,
              plane: str = "strain", element: str = "P2") -> ContactModel:
        """Mesh, assemble, factorise and condense (see module docstring)."""
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
        t_cond = 0.0
        x = cm.cam.contact_x
        for name, geo, mat in (("cam", cm.cam, cam), ("roller", cm.roller, roller)):
            b = assemble_body(geo, mat, plane=plane, element=element, ordering=solver.ordering)
            bodies[name] = b
            t1 = time.perf_counter()
            # body-specific signs: pressure into the body, friction +x on cam, -x on roller
            sn = -1.0 if name == "cam" else 1.0
            st = 1.0 if name == "cam" else -1.0
            By = load_matrix(b, geo.contact, x, 1)
            Bx = load_matrix(b, geo.contact, x, 0)
            Un = b.solve(sn * By)
            Ut = b.solve(st * Bx)
            Bn[name], Bt[name] = sn * By, st * Bx
            ydof = b.basis.nodal_dofs[1, geo.contact]
            # separation grows with roller uy and with -cam uy
            sg = 1.0 if name == "roller" else -1.0
            An = sg * Un[ydof] if An is None else An + sg * Un[ydof]
            At = sg * Ut[ydof] if At is None else At + sg * Ut[ydof]
            evals[name] = build_eval_set(b, Un, Ut, float(x[-1]), solver.eval_depth * a_ref)
            t_cond += time.perf_counter() - t1
        timings = {"mesh": t_mesh,
                   "assembly": sum(b.t_assembly for b in bodies.values()),
                   "factorisation": sum(b.t_factor for b in bodies.values()),
                   "condensation": t_cond}
        return cls(Rr=Rr, rho_ref=float(rho_ref), a_ref=a_ref, length=length, cam=cam, roller=roller,
                   plane=plane, element=element, mesh=cm, bodies=bodies, x=x,
                   w=trapezoid_weights(x), An=An, At=At, Bn=Bn, Bt=Bt, evals=evals,
                   options=solver, timings=timings,
                   n_dofs=sum(b.n_dofs for b in bodies.values()))

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
              check: bool = True) -> ContactResult:
        """Solve one load case: F (N over ``length``), rho (m), mu (-), sliding (+1 or -1).

        ``check=True`` raises :class:`PhysicsError` when :meth:`covers` is False; the solve
        always raises it when the loaded zone reaches the end of the meshed fine zone.
        """
        F = chk.nonnegative("F", F, "N")
        rho = float(rho)
        if math.isnan(rho) or rho == 0.0:
            raise chk.fail("rho", rho, "m", "must be nonzero (inf for a flat cam)")
        mu = chk.nonnegative("mu", mu, "")
        if sliding not in (1, -1):
            raise chk.fail("sliding", sliding, "", "must be +1 or -1")
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
            h0 = surface_height(self.x, self.Rr) + surface_height(self.x, rho)
            sol_p, g, delta, active, it, res, hist, conv = p, h0, 0.0, np.zeros(nc, bool), 0, 0.0, (), True
        else:
            A = self.An + (sliding * mu) * self.At
            h0 = surface_height(self.x, self.Rr) + surface_height(self.x, rho)
            a0 = aH if math.isfinite(aH) else self.a_ref
            active0 = np.abs(self.x) < a0
            sol = solve_lcp(A, h0, self.w, F / self.length, active0=active0,
                            max_iter=self.options.max_iter, tol=self.options.tol)
            sol_p, g, delta, active = sol.p, sol.g, sol.delta, sol.active
            it, res, hist, conv = sol.iterations, sol.residual, sol.history, sol.converged
            if active[0] or active[-1]:
                raise PhysicsError(
                    f"the loaded zone reaches the end of the meshed fine zone |x| <= {self.x[-1]:.4g} m "
                    f"(F = {F:g} N, rho = {rho:g} m); rebuild with a larger a_ref")
        t1 = time.perf_counter()
        a, x0, p0 = fit_half_width(self.x, sol_p, self.options.fit_threshold)
        force = float(self.w @ sol_p) * self.length
        maxima, surfaces = {}, {}
        for name, ev in self.evals.items():
            # einsum, not `@`: OpenBLAS's threaded gemv busy-waits on a loaded 2-core machine
            # (Sn and St of one body at a/20 with two busy processes: 43 ms vs 6 ms einsum)
            s = np.einsum("cij,j->ci", ev.Sn, sol_p)
            if mu > 0:
                s += (sliding * mu) * np.einsum("cij,j->ci", ev.St, sol_p)
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
            model=self)

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
        f = self.Bn[body] @ r.p + (r.sliding * r.mu) * (self.Bt[body] @ r.p)
        u = b.solve(f)
        s = stress_operator(b) @ u
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
    (or, when Hertz does not apply or F = 0, 1 % of Rr)."""
    if a_ref is None:
        aH, _ = _hertz(chk.nonnegative("F", F, "N"), chk.positive("length", length, "m"), float(rho),
                       chk.positive("Rr", Rr, "m"), cam, roller, plane)
        a_ref = aH if (math.isfinite(aH) and aH > 0) else 0.01 * Rr
    model = ContactModel.build(Rr=Rr, rho_ref=rho, cam=cam, roller=roller, length=length, a_ref=a_ref,
                               mesh=mesh, solver=solver, plane=plane, element=element)
    return model.solve(F=F, rho=rho, mu=mu, sliding=sliding)
