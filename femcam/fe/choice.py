r"""The FE on the real cam, per angle: which model answers (Hertz, FE with the osculating-arc gap,
FE with the exact gap), its estimated error, and the traction from the mechanism.

Build once per model family with :func:`build_real_cam`, then call :func:`solve_angle` per cam
angle. Each call returns an :class:`AngleResult` whose :meth:`AngleResult.row` gives the CSV
columns ``model``, ``curvature_jump``, ``exact_vs_arc_p0_pct``, ``Q_N``, ``Q_over_muFc``,
``stick_width_um``, ``slip_state`` (plus the p0 of each model and the error estimates).

Error estimates (cheap, before any FE solve): Hertz's p0 goes as the square root of the gap
curvature, so a relative gap error ``e_g = max_{|x|<=a} |g_exact - g_arc| / g_arc(a)`` moves p0 by
about ``e_g / 2``:

.. math:: \epsilon_{arc} \approx \tfrac12\,e_g,\qquad
          \epsilon_{Hertz} \approx \epsilon_{arc} + (a/R_{min})^2

(the second term the small-slope order of Hertz theory, Johnson 1985 §4.1). The cheapest model
whose estimate is within ``tol_pct`` answers; ``force_exact`` (e.g. the ``curvature_jump`` rows)
solves both FE gaps and reports their p0 difference, ``exact_vs_arc_p0_pct``. Near a curvature
jump the pressure is not a Hertz ellipse: p0 is the largest nodal pressure (``p0_nodal``).

Tangential force on the cam, local x (:mod:`femcam.fe.gap` frame), from the mechanism:

* roller: the friction torque the roller needs, ``T_f = J dOmega/dt + T_drag sign(Omega)``
  (:func:`femcam.wear.slip.roller_inertia`, Omega counter-clockwise positive), acts on the roller
  rim as ``T_f / Rr`` along ``t`` (torque of a force ``F t`` at ``-Rr n`` is ``Rr F``), so
  ``Q = -T_f / Rr`` on the cam (:func:`mechanism_Q`);
* knife-edge, flat-faced: full sliding, ``Q = s mu Fc`` with ``s`` from
  :func:`femcam.fe.followers.sliding_sign`.

References: K. L. Johnson, *Contact Mechanics*, 1985, §4.1, §7.1, §8.2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..materials import effective_modulus
from ..mesh import MeshOptions
from .followers import check_face, rolling_direction, sliding_sign
from .gap import arc_gap, contact_geometry, gap_from_surface, local_surface
from .model import ContactModel, SolverOptions
from .result import ContactResult

MODELS = ("hertz", "fe_arc", "fe_exact")


@dataclass(frozen=True, eq=False)
class RealCam:
    """A built FE model for one follower on one cam program (see :func:`build_real_cam`).

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program.
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
        The follower (:mod:`femcam.profile`).
    model : ContactModel
        The built two-body FE model.
    tip_radius : float or None
        Knife-edge tip radius [m]; None for the other followers.
    face_length : float or None
        Flat-face length [m]; None = no edge-contact check.
    swapped : bool
        Flat-faced follower: the FE "cam" body is the follower and the FE "roller" the cam
        (:data:`femcam.fe.followers.FLAT_FACE_BODIES`).
    E_star : float
        Contact modulus ``E*`` [Pa].
    """

    program: object
    follower: object
    model: ContactModel
    tip_radius: float | None
    face_length: float | None
    swapped: bool
    E_star: float


def build_real_cam(*, program, follower, cam, roller, length: float, F_ref: float, rho_ref: float,
                   plane: str = "strain", tip_radius: float | None = None,
                   face_length: float | None = None, mesh: MeshOptions | None = None,
                   solver: SolverOptions | None = None) -> RealCam:
    """Build the FE model of a follower family; ``F_ref`` and ``rho_ref`` set the reference
    half-width ``a_ref`` (Hertz) that sizes the mesh.

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program.
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
        The follower (:mod:`femcam.profile`).
    cam, roller : femcam.materials.Material
        Materials of the cam and of the follower.
    length : float
        Contact face width [m].
    F_ref : float
        Reference contact force [N], > 0.
    rho_ref : float
        Reference cam radius of curvature [m] (signed, ``inf`` = flat).
    plane : {"strain", "stress"}, optional
        Plane-elasticity assumption.
    tip_radius : float, optional
        Knife-edge tip radius [m] (required for a knife-edge follower).
    face_length : float, optional
        Flat-face length [m]; None = no edge-contact check.
    mesh : femcam.mesh.MeshOptions, optional
        Mesh options (default ``MeshOptions()``).
    solver : SolverOptions, optional
        Solver options (default ``SolverOptions()``).

    Returns
    -------
    RealCam
        The built model, to pass to :func:`solve_angle`.
    """
    _, R = contact_geometry(follower, tip_radius)
    F_ref = _validate.positive("F_ref", F_ref, "N")
    rho_ref = _validate.number("rho_ref", rho_ref, "m")
    E_star = effective_modulus(cam, roller, plane)
    swapped = follower.flat_face
    inv = (0.0 if math.isinf(R) else 1 / R) + (0.0 if math.isinf(rho_ref) else 1 / rho_ref)
    a_ref = math.sqrt(4 * F_ref / length / max(inv, 1e-300) / (math.pi * E_star))
    if swapped:  # the cam is the curved FE "roller", the flat follower the FE "cam"
        m = ContactModel.build(Rr=rho_ref, rho_ref=math.inf, cam=roller, roller=cam, length=length,
                               a_ref=a_ref, mesh=mesh, solver=solver, plane=plane)
    else:
        m = ContactModel.build(Rr=R, rho_ref=rho_ref, cam=cam, roller=roller, length=length,
                               a_ref=a_ref, mesh=mesh, solver=solver, plane=plane)
    return RealCam(program=program, follower=follower, model=m, tip_radius=tip_radius,
                   face_length=face_length, swapped=swapped, E_star=E_star)


def mechanism_Q(Omega, theta, omega: float, *, J: float, T_drag: float, Rr: float) -> np.ndarray:
    """Tangential force on the cam along local x from the roller spin:
    ``Q = -(J omega dOmega/dtheta + T_drag sign Omega) / Rr``.

    Parameters
    ----------
    Omega : array_like of float, shape (n,)
        Roller spin [rad/s], counter-clockwise positive, over one periodic revolution.
    theta : array_like of float, shape (n,)
        The uniform cam-angle grid of ``Omega`` [rad] (periodic central differences).
    omega : float
        Cam speed [rad/s], > 0 (as in :func:`femcam.wear.slip.roller_inertia`).
    J : float
        Roller polar moment of inertia about its axle [kg m^2], > 0.
    T_drag : float
        Roller bearing drag torque [N m], >= 0.
    Rr : float
        Roller radius [m], > 0.

    Returns
    -------
    ndarray of float, shape (n,)
        ``Q`` on the cam along local x [N].
    """
    Om = _validate.finite_array("Omega", Omega, "rad/s")
    th = _validate.finite_array("theta", theta, "rad")
    dth = float(np.mean(np.diff(th)))
    dOm = (np.roll(Om, -1) - np.roll(Om, 1)) / (2 * dth)  # periodic central difference
    J = _validate.positive("J", J, "kg m^2")
    omega = _validate.positive("omega", omega, "rad/s")
    T_f = J * omega * dOm + _validate.nonnegative("T_drag", T_drag, "N m") * np.sign(Om)
    return -T_f / _validate.positive("Rr", Rr, "m")


@dataclass(frozen=True, eq=False)
class AngleResult:
    """Per-angle answer: the model that answered and why, p0 of each model, error estimates,
    traction and the answering FE result.

    Parameters
    ----------
    theta : float
        Cam angle [rad].
    model : str
        The model that answered, one of :data:`MODELS`.
    reason : str
        Why that model answered.
    curvature_jump : bool
        The angle is inside the straddle span of a curvature jump.
    p0 : float
        Peak pressure of the answering model [Pa] (largest nodal pressure for the FE).
    p0_hertz, p0_arc, p0_exact : float
        Peak pressure of Hertz, FE with the arc gap, FE with the exact gap [Pa]; nan if not
        computed.
    est_err_hertz_pct, est_err_arc_pct : float
        Estimated p0 errors of Hertz and of the arc-gap FE [%].
    Q : float
        Tangential force on the cam along local x [N].
    Q_over_muFc : float
        ``Q / (mu Fc)`` [-]; nan when ``mu = 0``.
    stick_width : float
        Width of the stick zone [m].
    slip_state : str
        One of :data:`femcam.fe.traction.SLIP_STATES`.
    result : ContactResult or None
        The answering FE result; None for Hertz.
    """

    theta: float
    model: str
    reason: str
    curvature_jump: bool
    p0: float
    p0_hertz: float
    p0_arc: float
    p0_exact: float
    est_err_hertz_pct: float
    est_err_arc_pct: float
    Q: float
    Q_over_muFc: float
    stick_width: float
    slip_state: str
    result: ContactResult | None

    @property
    def exact_vs_arc_p0_pct(self) -> float:
        """100 (p0_arc / p0_exact - 1), nan unless both FE gaps were solved."""
        return 100.0 * (self.p0_arc / self.p0_exact - 1.0)

    def row(self) -> dict:
        """CSV columns (units in the names).

        Returns
        -------
        dict
            Column name -> value: ``theta_deg``, ``p0_MPa``, ``Q_N``, ``stick_width_um``, ...
        """
        return {"theta_deg": math.degrees(self.theta), "model": self.model,
                "curvature_jump": self.curvature_jump, "p0_MPa": self.p0 / 1e6,
                "p0_hertz_MPa": self.p0_hertz / 1e6, "exact_vs_arc_p0_pct": self.exact_vs_arc_p0_pct,
                "est_err_hertz_pct": self.est_err_hertz_pct, "est_err_arc_pct": self.est_err_arc_pct,
                "Q_N": self.Q, "Q_over_muFc": self.Q_over_muFc, "stick_width_um": self.stick_width * 1e6,
                "slip_state": self.slip_state, "model_reason": self.reason}


def _estimates(surf, x, a, R_eff):
    g_ex = gap_from_surface(surf, x)
    g_arc = arc_gap(x, surf.R, surf.rho)
    inner = np.abs(x) <= a
    e_g = float(np.max(np.abs(g_ex - g_arc)[inner])) / (a * a / (2 * R_eff))
    R_min = min(surf.R, abs(surf.rho))
    return g_ex, g_arc, 50.0 * e_g, 50.0 * e_g + 100.0 * (a / R_min) ** 2


def _traction(rc: RealCam, theta, F, mu, Q):
    """(Q on the cam, rolling, sliding) in the FE frame; the FE frame's x is the physical x,
    but with swapped bodies the traction on the FE cam (the follower) is -Q."""
    if rc.follower.rolls:
        roll = int(rolling_direction(rc.program, rc.follower, [theta])[0])
        return (0.0 if Q is None else float(Q)), roll, 1
    s = int(sliding_sign(rc.program, rc.follower, [theta], tip_radius=rc.tip_radius)[0])
    return s * mu * F, 0, (-s if rc.swapped else s)


def solve_angle(rc: RealCam, theta: float, F: float, *, mu: float, Q: float | None = None,
                curvature_jump: bool = False, tol_pct: float = 1.0, force_exact: bool = False) -> AngleResult:
    """Answer one cam angle ``theta`` (rad) at contact force ``F`` (N) with friction ``mu``.

    Roller: ``Q`` (N, on the cam along local x; :func:`mechanism_Q`) is solved as partial slip;
    knife-edge and flat-faced slide fully in the direction of the sliding velocity. The
    cheapest model within ``tol_pct`` answers (module docstring); ``force_exact`` or
    ``curvature_jump`` also solves both FE gaps.

    Parameters
    ----------
    rc : RealCam
        The built model (:func:`build_real_cam`).
    theta : float
        Cam angle [rad].
    F : float
        Contact force [N], > 0.
    mu : float
        Coefficient of friction [-].
    Q : float, optional
        Roller only: tangential force on the cam along local x [N] (None = 0).
    curvature_jump : bool, optional
        The angle straddles a curvature jump: solve both FE gaps, p0 the largest nodal pressure.
    tol_pct : float, optional
        Accepted estimated p0 error of the cheapest model [%].
    force_exact : bool, optional
        Solve both FE gaps whatever the estimates.

    Returns
    -------
    AngleResult
        The per-angle answer.

    Raises
    ------
    PhysicsError
        A cusp or undercut in the contact zone, or a flat-face edge contact (naming the angle).
    """
    m = rc.model
    F = _validate.positive("F", F, "N")
    surf = local_surface(rc.program, rc.follower, theta, float(m.x[-1]), tip_radius=rc.tip_radius)
    inv = (0.0 if math.isinf(surf.R) else 1 / surf.R) + (0.0 if math.isinf(surf.rho) else 1 / surf.rho)
    R_eff = 1 / inv
    a = math.sqrt(4 * F / m.length * R_eff / (math.pi * rc.E_star))
    check_face(rc.program, rc.follower, rc.face_length, [theta], a)
    p0_h = 2 * F / m.length / (math.pi * a)
    g_ex, g_arc, e_arc, e_h = _estimates(surf, m.x, a, R_eff)
    Qc, roll, slide = _traction(rc, theta, F, mu, Q)
    Q_fe = -Qc if rc.swapped else Qc
    exact = force_exact or curvature_jump
    kw = dict(F=F, rho=math.inf if rc.swapped else surf.rho, mu=mu, check=False)
    if rc.follower.rolls:
        kw.update(Q=Q_fe, rolling=roll)
    else:
        kw.update(sliding=slide)
    p0_arc = p0_ex = math.nan
    res = None
    if exact or e_arc > tol_pct:
        res = m.solve(gap=g_ex, **kw)
        p0_ex = res.p0_nodal
        name, why = "fe_exact", (f"arc-gap error estimate {e_arc:.3g} % > tol {tol_pct:g} %" if not exact
                                 else "curvature jump / exact requested")
        if exact:
            p0_arc = m.solve(gap=g_arc, **kw).p0_nodal
    elif e_h > tol_pct or rc.follower.flat_face and rc.face_length is None:
        res = m.solve(gap=g_arc, **kw)
        p0_arc = res.p0_nodal
        name, why = "fe_arc", f"Hertz error estimate {e_h:.3g} % > tol {tol_pct:g} %"
    else:
        name, why = "hertz", f"Hertz error estimate {e_h:.3g} % <= tol {tol_pct:g} %"
    if res is not None:
        Qr = -res.Q if rc.swapped else res.Q
        state, width = res.slip_state, res.stick_width
        p0 = res.p0_nodal
    else:  # Hertz with the closed forms (Carter, Johnson 1985 §8.2)
        f = abs(Qc) / (mu * F) if mu > 0 else (math.inf if Qc else 0.0)
        Qr = math.copysign(min(abs(Qc), mu * F), Qc)
        state = "none" if Qc == 0 else ("sliding" if f >= 1 else "partial slip")
        width = 2 * a * math.sqrt(1 - f) if f < 1 else 0.0
        p0 = p0_h
    return AngleResult(theta=float(theta), model=name, reason=why, curvature_jump=bool(curvature_jump),
                       p0=p0, p0_hertz=p0_h, p0_arc=p0_arc, p0_exact=p0_ex, est_err_hertz_pct=e_h,
                       est_err_arc_pct=e_arc, Q=Qr, Q_over_muFc=(Qr / (mu * F) if mu > 0 else math.nan),
                       stick_width=width, slip_state=state, result=res)
