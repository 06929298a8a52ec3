"""Two-body FE contact model: build once (mesh, assemble, factorise, condense), solve many.

The result of a solve (:class:`ContactResult`, its :class:`StressMax` and
:class:`SurfaceStress`) is in :mod:`femcam.fe.result`; the names are importable from here too.

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

import dataclasses
import math
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from types import SimpleNamespace

import numpy as np
import scipy.sparse as sp

from .. import _validate
from .._repr import compact_repr
from .._threads import single_threaded_blas
from ..errors import PhysicsError
from ..hertz.conformity import roller_does_not_fit
from ..hertz.contact import effective_radius, half_width, peak_pressure
from ..materials import PLANES, Material, effective_modulus
from ..mesh import ContactMesh, MeshOptions, build_contact_mesh, surface_height
from .contact import load_operator, solve_lcp, trapezoid_weights
from .elasticity import (
    ELEMENTS,
    ORDERINGS,
    Body,
    assemble_body,
    element_gradients,
    probe_matrix,
    scalar_node_coordinates,
    stress_operator,
)
from .passrange import pass_grid
from .recovery import build_eval_set, depth, derived, fit_half_width, johnson_frame
from .result import ContactResult, traction_fields, window_extrema
from .traction import solve_partial_slip

#: values of ``SolverOptions.stress_operators``
STRESS_OPERATORS = ("precompute", "per_solve")


@dataclass(frozen=True, kw_only=True)
class SolverOptions:
    """Contact solver and model-reuse options.

    Parameters
    ----------
    ordering : str
        SuperLU column ordering, one of :data:`femcam.fe.elasticity.ORDERINGS`
        (``MMD_AT_PLUS_A`` default, see elasticity.py).
    max_iter : int
        Active-set iteration limit, 1..10000.
    tol : float
        Complementarity tolerance (relative residual) [-], > 0.
    a_range : tuple of float
        ``(lo, hi)``: the model covers load cases with Hertz ``a / a_ref`` in this interval [-].
    kappa_tol : float
        ... and with ``|1/rho - 1/rho_ref| * L_cam <= kappa_tol`` (cam shape reuse; ``L_cam``
        the cam body size) [-].
    eval_depth : float
        Stresses are precomputed at nodes down to ``eval_depth * a_ref`` below the surface (and
        over the fine zone in x) [-, multiple of a_ref], 0..20.
    fit_threshold : float
        Nodes with ``p > fit_threshold * max(p)`` enter the half-width fit [-], 0..0.9.
    stress_operators : {"precompute", "per_solve"}
        ``"precompute"``: the build condenses the stresses of the window onto the contact
        unknowns (2 n_c solves per body; each solve then costs a few ms): for models solved at
        many load cases (sweep families). ``"per_solve"``: the contact DOFs are factorised last
        and the contact compliance is the Schur complement in the trailing factor blocks (no
        solve per contact unknown); each solve back-solves both bodies once for the stresses:
        for one-off models (a single scene, fresh verification models); the two bodies of such
        a model are built in two threads. Same numbers to ~1e-12; times in
        docs/performance.md (benchmarks/bench_fe.py --modes).
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
        _validate.choice("ordering", self.ordering, ORDERINGS)
        _validate.integer("max_iter", self.max_iter, 1, "iterations")
        _validate.in_range("max_iter", self.max_iter, 1, 10000, "")
        _validate.positive("tol", self.tol, "")
        lo = _validate.positive("a_range[0]", self.a_range[0], "")
        hi = _validate.positive("a_range[1]", self.a_range[1], "")
        if lo >= hi:
            raise _validate.fail("a_range", self.a_range, "", "must be (lo, hi) with lo < hi")
        _validate.positive("kappa_tol", self.kappa_tol, "")
        _validate.in_range("eval_depth", self.eval_depth, 0.0, 20.0, "(x a_ref)")
        _validate.in_range("fit_threshold", self.fit_threshold, 0.0, 0.9, "")
        _validate.choice("stress_operators", self.stress_operators, STRESS_OPERATORS)


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
        raise _validate.fail(name, value, "m", "must be a number (inf for a flat cam)")
    if math.isnan(value) or value == 0:
        raise _validate.fail(name, value, "m", "must be nonzero (inf for a flat cam)")
    return float(value)


def _body_part(name, geo, mat, *, x, plane, element, solver, a_ref) -> SimpleNamespace:
    """Assemble, factorise and condense one body: ``body``, its load operators ``Bn, Bt`` (with
    the body's signs: pressure into the body, friction +x on the cam, -x on the roller), its
    stress window ``ev``, the condensed displacements ``Yn, Yt`` at its contact vertices (normal
    rows, then tangential) and the condensation time ``t_cond`` (s)."""
    b = assemble_body(geo, mat, plane=plane, element=element, ordering=solver.ordering,
                      contact_last=solver.stress_operators == "per_solve")
    t1 = time.perf_counter()
    sn, st = (-1.0, 1.0) if name == "cam" else (1.0, -1.0)
    Bn = sn * load_operator(b, geo.contact, x, 1)
    Bt = st * load_operator(b, geo.contact, x, 0)
    ydof = b.basis.nodal_dofs[1, geo.contact]
    cdof = np.concatenate([ydof, b.basis.nodal_dofs[0, geo.contact]])
    S_c = sp.csr_matrix((np.ones(cdof.size), (np.arange(cdof.size), cdof)),
                        shape=(cdof.size, b.n_dofs))
    ev, Yn, Yt = build_eval_set(b, Bn, Bt, S_c, float(x[-1]), solver.eval_depth * a_ref,
                                precompute=solver.stress_operators == "precompute")
    grid = pass_grid(b, ev.nodes, ev.x, ev.z, ev.surface)   # rows of equal depth: the txz range
    ev = dataclasses.replace(ev, **dict(zip(("pass_P", "pass_x", "pass_z", "pass_ok"), grid, strict=True)))
    return SimpleNamespace(body=b, Bn=Bn, Bt=Bt, ev=ev, Yn=Yn, Yt=Yt,
                           t_cond=time.perf_counter() - t1)


@dataclass(frozen=True, eq=False)
class ContactModel:
    """Factorised two-body model; see the module docstring. Build with :meth:`build`.

    Parameters
    ----------
    Rr : float
        Roller (FE "roller" body) radius [m].
    rho_ref : float
        Cam radius of curvature the cam body is meshed with [m] (signed, ``inf`` = flat).
    a_ref : float
        Reference half-width that grades the mesh and sizes the fine zone [m].
    length : float
        Face width [m].
    cam, roller : femcam.materials.Material
        Materials of the two bodies.
    plane : {"strain", "stress"}
        Plane-elasticity assumption.
    element : {"P1", "P2"}
        Triangle element.
    mesh : femcam.mesh.ContactMesh
        The meshes of both bodies.
    bodies : dict of str to Body
        ``"cam"``, ``"roller"``: the assembled, factorised bodies.
    x : ndarray of float, shape (n_c,)
        Abscissae of the contact vertices [m].
    w : ndarray of float, shape (n_c,)
        Trapezoid weights of the pressure hats [m].
    An : ndarray of float, shape (n_c, n_c)
        Normal separation per unit nodal pressure (both bodies) [m/Pa].
    At : ndarray of float, shape (n_c, n_c)
        Normal separation per unit nodal tangential traction [m/Pa].
    Bn, Bt : dict of str to scipy.sparse.csc_matrix, shape (n_dofs_body, n_c)
        Per body: consistent nodal forces of unit pressure / traction hats, with the body's
        signs [m].
    evals : dict of str to femcam.fe.recovery.EvalSet
        Per body: the stress window.
    options : SolverOptions
        Solver options the model was built with.
    timings : dict of str to float
        Build phases (mesh, assembly, factorisation, condensation, bodies_wall) [s].
    n_dofs : int
        Total DOFs of both bodies.
    Ctt, Ctn : ndarray of float, shape (n_c, n_c), or None
        Tangential compliances: ``u_cam,x - u_roller,x`` per unit tangential / normal hat [m/Pa].
    """

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

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @classmethod
    def build(cls, *, Rr: float, rho_ref: float, cam: Material, roller: Material, length: float,
              a_ref: float, mesh: MeshOptions | None = None, solver: SolverOptions | None = None,
              plane: str = "strain", element: str = "P2") -> ContactModel:
        """Mesh, assemble, factorise and condense (see module docstring).

        Parameters
        ----------
        Rr : float
            Roller radius [m], > 0.
        rho_ref : float
            Cam radius of curvature to mesh [m], signed (negative = concave, ``inf`` = flat),
            nonzero.
        cam, roller : femcam.materials.Material
            Materials of the two bodies.
        length : float
            Face width [m], > 0.
        a_ref : float
            Reference half-width [m], > 0 (grades the mesh and sizes the fine zone).
        mesh : femcam.mesh.MeshOptions, optional
            Mesh options.
        solver : SolverOptions, optional
            Solver options (default ``SolverOptions()``).
        plane : {"strain", "stress"}, optional
            Plane-elasticity assumption.
        element : {"P1", "P2"}, optional
            Triangle element.

        Returns
        -------
        ContactModel
            The built model.

        Raises
        ------
        InputError
            A bad argument (named, with its value and unit).
        """
        rho_ref = _radius("rho_ref", rho_ref)
        for name, v, kind, what in (("cam", cam, Material, "Material"),
                                    ("roller", roller, Material, "Material"),
                                    ("mesh", mesh, MeshOptions | None, "MeshOptions or None"),
                                    ("solver", solver, SolverOptions | None, "SolverOptions or None")):
            if not isinstance(v, kind):
                raise _validate.fail(name, v, "", f"must be a {what}")
        Rr = _validate.positive("Rr", Rr, "m")
        length = _validate.positive("length", length, "m")
        a_ref = _validate.positive("a_ref", a_ref, "m")
        _validate.choice("plane", plane, PLANES)
        _validate.choice("element", element, ELEMENTS)
        solver = solver or SolverOptions()
        t0 = time.perf_counter()
        cm = build_contact_mesh(Rr=Rr, rho=rho_ref, a_ref=a_ref, options=mesh)
        t_mesh = time.perf_counter() - t0
        x = cm.cam.contact_x
        args = dict(x=x, plane=plane, element=element, solver=solver, a_ref=a_ref)
        jobs = (("cam", cm.cam, cam), ("roller", cm.roller, roller))
        # one-off models (per_solve): the two bodies in two threads (SuperLU's solves and numpy's
        # kernels release the GIL and overlap on 2 cores; two SuperLU factorisations do not
        # overlap: scipy runs one at a time, docs/performance.md). Models
        # built for many load cases (precompute: the sweep's families, kept in a cache) are
        # built in the main thread: in worker threads the a/h = 26 sweep's peak RSS grew from
        # 1.12 GB to 1.46 GB (glibc per-thread arenas; docs/performance.md)
        with single_threaded_blas():
            if solver.stress_operators == "per_solve":
                with ThreadPoolExecutor(max_workers=2) as pool:
                    parts = dict(pool.map(lambda job: (job[0], _body_part(*job, **args)), jobs))
            else:
                parts = {job[0]: _body_part(*job, **args) for job in jobs}
        bodies = {k: v.body for k, v in parts.items()}
        Bn = {k: v.Bn for k, v in parts.items()}
        Bt = {k: v.Bt for k, v in parts.items()}
        evals = {k: v.ev for k, v in parts.items()}
        nc = x.size
        # separation grows with roller uy and with -cam uy; the relative tangential
        # displacement is u_cam,x - u_roller,x (femcam.fe.traction)
        An = parts["roller"].Yn[:nc] - parts["cam"].Yn[:nc]
        At = parts["roller"].Yt[:nc] - parts["cam"].Yt[:nc]
        Ctt = parts["cam"].Yt[nc:] - parts["roller"].Yt[nc:]
        Ctn = parts["cam"].Yn[nc:] - parts["roller"].Yn[nc:]
        timings = {"mesh": t_mesh,
                   "assembly": sum(b.t_assembly for b in bodies.values()),
                   "factorisation": sum(b.t_factor for b in bodies.values()),
                   "condensation": sum(v.t_cond for v in parts.values()),
                   "bodies_wall": time.perf_counter() - t0 - t_mesh}
        return cls(Rr=Rr, rho_ref=float(rho_ref), a_ref=a_ref, length=length, cam=cam, roller=roller,
                   plane=plane, element=element, mesh=cm, bodies=bodies, x=x,
                   w=trapezoid_weights(x), An=An, At=At, Bn=Bn, Bt=Bt, evals=evals,
                   options=solver, timings=timings,
                   n_dofs=sum(b.n_dofs for b in bodies.values()), Ctt=Ctt, Ctn=Ctn)

    # ------------------------------------------------------------------ validity
    def hertz(self, F: float, rho: float):
        """Hertz half-width and peak pressure of the load case (Johnson 1985 eq. 4.45).

        Parameters
        ----------
        F : float
            Contact force over ``length`` [N].
        rho : float
            Cam radius of curvature [m], signed (``inf`` = flat).

        Returns
        -------
        a : float
            Half-width [m]; nan if Hertz does not apply (a concave cam that does not fit).
        p0 : float
            Peak pressure [Pa]; nan likewise.

        Raises
        ------
        InputError
            ``F`` not a number >= 0 or ``rho`` not a nonzero number.
        """
        F, rho = _validate.nonnegative("F", F, "N"), _radius("rho", rho)
        return _hertz(F, self.length, rho, self.Rr, self.cam, self.roller, self.plane)

    def coverage(self, F: float, rho: float) -> str:
        """Why the model does not cover a load case (see :class:`SolverOptions`).

        Parameters
        ----------
        F : float
            Contact force over ``length`` [N].
        rho : float
            Cam radius of curvature [m], signed (``inf`` = flat).

        Returns
        -------
        str
            Empty if the model covers ``(F, rho)``, else the reason.

        Raises
        ------
        InputError
            ``F`` not a number >= 0 or ``rho`` not a nonzero number.
        """
        F, rho = _validate.nonnegative("F", F, "N"), _radius("rho", rho)
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
        """Whether a load case is inside the range this model was built and validated for.

        Parameters
        ----------
        F : float
            Contact force over ``length`` [N].
        rho : float
            Cam radius of curvature [m], signed (``inf`` = flat).

        Returns
        -------
        bool
            True when :meth:`coverage` finds no reason against.
        """
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
            sx, sz, txz = ev.stresses(sol_p, q)
            maxima[name], surfaces[name] = window_extrema(name, ev, sx, sz, txz,
                                                          self._sy(name, sx, sz))
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
            model=self, q=q, message=msg, **traction_fields(trac, q, self.w, self.x, self.length))

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
            # (a coating band makes the bodies dissimilar near the surface)
            similar = ((self.cam.E, self.cam.nu) == (self.roller.E, self.roller.nu)
                       and getattr(self.cam, "coating", None) is None
                       and getattr(self.roller, "coating", None) is None)
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
        F = _validate.nonnegative("F", F, "N")
        rho = _radius("rho", rho)
        if math.isnan(rho) or rho == 0.0:
            raise _validate.fail("rho", rho, "m", "must be nonzero (inf for a flat cam)")
        mu = _validate.nonnegative("mu", mu, "")
        if sliding not in (1, -1):
            raise _validate.fail("sliding", sliding, "", "must be +1 or -1")
        if Q is not None:
            Q = _validate.number("Q", Q, "N")
        if rolling not in (0, 1, -1):
            raise _validate.fail("rolling", rolling, "", "must be 0 (no rolling), +1 or -1")
        return F, rho, mu, Q

    def _gap(self, rho: float, gap) -> np.ndarray:
        """Initial gap (m) at ``self.x``: ``gap`` if given (checked), else the osculating arcs."""
        if gap is None:
            return surface_height(self.x, self.Rr) + surface_height(self.x, rho)
        g = _validate.finite_array("gap", gap, "m")
        if g.shape != self.x.shape:
            raise _validate.fail("gap", f"shape {g.shape}", "m",
                                 f"must have the shape {self.x.shape} of model.x")
        return g

    def _sy(self, name, sx, sz):
        nu = (self.cam if name == "cam" else self.roller).nu
        return nu * (sx + sz) if self.plane == "strain" else np.zeros_like(sx)

    # ------------------------------------------------------------------ full fields
    def full_field(self, r: ContactResult, body: str = "cam"):
        """Displacement and stresses at all scalar nodes of ``body`` (one back-solve).

        Parameters
        ----------
        r : ContactResult
            A result solved by this model.
        body : {"cam", "roller"}, optional
            The body.

        Returns
        -------
        u : ndarray of float, shape (2, n)
            Nodal displacements ``(u_x, u_y)`` in the FE frame [m].
        fields : dict of str to ndarray
            ``sx, sz, txz, sy, tau1, von_mises`` (n,) in the body's Johnson frame [Pa], ``xy``
            (2, n) node coordinates in the FE frame [m] and ``z`` (n,) depth [m].
        """
        _validate.choice("body", body, ("cam", "roller"))
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

    def field_gradients(self, body: str = "cam") -> tuple:
        """:func:`~femcam.fe.elasticity.element_gradients` of one body, built once per model
        (the recovery indicator of each of the body's ``.vtu`` files reads it).

        Parameters
        ----------
        body : {"cam", "roller"}, optional
            The body.

        Returns
        -------
        tuple
            ``(dphi, sdofs, edofs, lam, mu, cnt)`` of :func:`~femcam.fe.elasticity.element_gradients`.
        """
        _validate.choice("body", body, ("cam", "roller"))
        key = ("gradients", body)
        if key not in self._field_ops:
            self._field_ops[key] = element_gradients(self.bodies[body])
        return self._field_ops[key]

    def stress_at(self, r: ContactResult, x, z, body: str = "cam"):
        """Stresses interpolated (nodal field) at points of ``body``.

        Parameters
        ----------
        r : ContactResult
            A result solved by this model.
        x : array_like of float
            Abscissae [m].
        z : array_like of float
            Depths below the body's surface [m]; broadcast against ``x``.
        body : {"cam", "roller"}, optional
            The body.

        Returns
        -------
        tuple of ndarray
            ``(sx, sz, txz, sy, tau1, von_mises)`` [Pa], each of the broadcast shape.

        Raises
        ------
        InputError
            ``body`` not "cam" or "roller", or a point outside the body.
        """
        _validate.choice("body", body, ("cam", "roller"))
        x = _validate.finite_array("x", x, "m")
        z = _validate.finite_array("z", z, "m")
        x, z = np.broadcast_arrays(x, z)
        b: Body = self.bodies[body]
        ys = surface_height(x, b.geometry.R)
        y = (-ys - z) if body == "cam" else (ys + z)
        _, fld = self.full_field(r, body)
        try:
            P = probe_matrix(b, np.stack([x.ravel(), y.ravel()]))
        except ValueError:
            raise _validate.fail("(x, z)", (x.tolist(), z.tolist()), "m",
                                 "must lie inside the body") from None
        return tuple((P @ fld[k]).reshape(x.shape)
                     for k in ("sx", "sz", "txz", "sy", "tau1", "von_mises"))


def solve_contact(F: float, rho: float, Rr: float, cam: Material, roller: Material, length: float,
                  mu: float = 0.0, *, sliding: int = 1, a_ref: float | None = None,
                  mesh: MeshOptions | None = None, solver: SolverOptions | None = None,
                  plane: str = "strain", element: str = "P2") -> ContactResult:
    """Build a model graded for this load case and solve it (cold). ``a_ref`` defaults to Hertz a
    (or, when Hertz does not apply or F = 0, 1 % of Rr). A one-off model: ``solver`` defaults
    to ``SolverOptions(stress_operators="per_solve")`` (same numbers, no per-unknown solves).

    Parameters
    ----------
    F : float
        Contact force over ``length`` [N], >= 0.
    rho : float
        Cam radius of curvature [m], signed (negative = concave, ``inf`` = flat).
    Rr : float
        Roller radius [m], > 0.
    cam, roller : femcam.materials.Material
        Materials of the two bodies.
    length : float
        Face width [m], > 0.
    mu : float, optional
        Coulomb friction coefficient [-] (full sliding).
    sliding : {+1, -1}, optional
        Direction of the friction traction on the cam along x.
    a_ref : float, optional
        Reference half-width [m] that grades the mesh.
    mesh : femcam.mesh.MeshOptions, optional
        Mesh options.
    solver : SolverOptions, optional
        Solver options.
    plane : {"strain", "stress"}, optional
        Plane-elasticity assumption.
    element : {"P1", "P2"}, optional
        Triangle element.

    Returns
    -------
    ContactResult
        The solved load case (see :meth:`ContactModel.solve`).
    """
    ContactModel._check_inputs(F, rho, mu, sliding, None, 0)  # before the mesh is built
    if a_ref is None:
        aH, _ = _hertz(_validate.nonnegative("F", F, "N"), _validate.positive("length", length, "m"),
                       _radius("rho", rho),
                       _validate.positive("Rr", Rr, "m"), cam, roller, plane)
        a_ref = aH if (math.isfinite(aH) and aH > 0) else 0.01 * Rr
    solver = solver or SolverOptions(stress_operators="per_solve")
    model = ContactModel.build(Rr=Rr, rho_ref=rho, cam=cam, roller=roller, length=length, a_ref=a_ref,
                               mesh=mesh, solver=solver, plane=plane, element=element)
    return model.solve(F=F, rho=rho, mu=mu, sliding=sliding)
