r"""Profile evolution: wear → geometry → load and Hertz pressure → wear, in blocks of cycles.

:mod:`.map` is linear in cycles: the depth after N revolutions is N times the depth of one
revolution of the *unworn* cam. Here the cam is worn in blocks of ``dN`` revolutions; before
each block the contact is recomputed on the worn geometry (explicit Euler in N):

.. math:: h_{b+1}(x) = h_b(x) + \Delta N\,\dot h\big(x;\,h_b\big),\qquad
          \dot h(x; h) = k\int p_h\big(x-\xi(t)\big)\,v_{slip}(t)\,dt

where ``dot h`` is :func:`~femcam.wear.map.wear_map`'s depth per revolution with the pressure
``p_h`` of the worn geometry. The error after N revolutions is first order in ``dN``
(:func:`convergence_table` measures the order).

Symbols
-------
=========  ==================================================  =========  =========================
symbol     meaning                                             unit       source
=========  ==================================================  =========  =========================
h(s)       cam wear depth, inward along the normal             m          this module
s          arc length along the *unworn* cam surface           m          :mod:`.map` ``x_cam``
kappa      unworn cam curvature ``1/rho`` (> 0 convex)         1/m        :mod:`femcam.profile`
kappa_w    curvature of the worn surface                       1/m        eq. (1) below
H_r        mean roller wear depth (uniform, see below)         m          :mod:`.map`, drift
ds_f       follower lift lost to the wear                      m          eq. (2)
Fc         normal contact force on the worn cam                N          seed 002 eq. 11
a, p0      Hertz half-width and peak pressure                  m, Pa      Johnson §4.2, eq. 4.44
k          Archard wear coefficient                            m^3/(N m)  Archard (1953)
dN         block size                                          revs       this module
=========  ==================================================  =========  =========================

**(1) Curvature of the worn surface.** The worn surface is the unworn one moved inward by
``h(s)`` along the normal, ``W(s) = C(s) + h(s) N(s)`` (``C`` arc-length parametrised, tangent
``T``, inward normal ``N``; Frenet, do Carmo *Differential Geometry of Curves and Surfaces*
§1-5: ``T' = kappa N``, ``N' = -kappa T``). Then ``W' = (1 - kappa h) T + h' N`` and
``W'' = -(kappa' h + 2 kappa h') T + (kappa (1 - kappa h) + h'') N``, so the signed curvature
``(W' x W'')/|W'|^3`` is, exactly,

.. math:: \kappa_w = \frac{(1-\kappa h)\big[\kappa(1-\kappa h) + h''\big]
                     + h'\,(\kappa' h + 2\kappa h')}{\big[(1-\kappa h)^2 + h'^2\big]^{3/2}}
          \;\approx\; \frac{1}{\rho - h} + h''

(primes: d/ds along the unworn surface). A worn-in dimple (``h'' < 0``) flattens the cam;
``h'' > 0`` (the rim of a worn band) sharpens it. ``rho_w = 1/kappa_w`` goes into Hertz.

**(2) Load.** The follower (roller) keeps touching the worn cam: its centre moves towards the
cam by ``h + H_r`` along the contact normal, i.e. by ``ds_f = -(h + H_r)/cos phi`` along its
axis (first order; the change of the pressure angle ``phi``, O(h'), is neglected). The force is
seed 002 eq. 11 on the worn lift ``s + ds_f`` (spring ``k_s ds_f``, and the inertia and
damping of its variation with the cam angle, ``m omega^2 ds_f''`` and ``c omega ds_f'``, by
periodic central differences in theta):
:math:`F_c = [m\omega^2(s_2 + \Delta s_f'') + c\,\omega(s_1 + \Delta s_f') + k_s(s + \Delta s_f)
+ F_{pl}]/\cos\varphi`.

**Roller.** The roller's wear is the drift-summed pattern of :mod:`.map` (each block's
revolutions laid down with the contact's drift ``D`` per revolution, from the block's starting
phase). For the geometry it enters only as its mean depth ``H_r`` (the pattern flattens towards
it, see :func:`~femcam.wear.map.drift_sum`): roller radius ``Rr - H_r`` and the lift loss (2).

Assumptions: Archard, constant k, no running-in; Hertz line contact on the local radii (valid
while ``a << rho_w, Rr``: the largest ``a/min(|rho_w|, Rr)`` is reported); the contact point and
the slip (speeds, arc positions, drift) stay those of the unworn cam (their changes are
O(h/rho)); quasi-static dynamics of the rigid follower train (seed 002 eq. 11); uniform wear
across the face width. Roller followers only: a radiused knife-edge tip wears to a flat of
about its own contact width (tens of µm against a = 6 µm, see docs/wear.md), a conformal
contact that Hertz does not describe.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from .._repr import compact_repr
from ..hertz import LineContact
from ..loads import contact_force
from ..scene.case import ContactCase
from .map import WearMap, drift_sum, wear_map
from .options import slip_kwargs, wear_coefficient_info
from .slip import SlipResult, follower_slip


# --------------------------------------------------------------------------- geometry
def worn_curvature(kappa, dkappa_ds, h, h1, h2):
    r"""Signed curvature (1/m, > 0 convex) of a surface of curvature ``kappa`` worn by ``h(s)``.

    ``h1 = dh/ds``, ``h2 = d^2h/ds^2`` along the unworn arc length; ``dkappa_ds`` the unworn
    curvature's derivative. Exact for the offset curve ``C + h N`` (see the module text, eq. 1):

    .. math:: \kappa_w = \frac{(1-\kappa h)[\kappa(1-\kappa h) + h''] + h'(\kappa' h + 2\kappa h')}
                              {[(1-\kappa h)^2 + h'^2]^{3/2}}

    Parameters
    ----------
    kappa : float or ndarray
        Unworn curvature ``1/rho``, > 0 convex [1/m].
    dkappa_ds : float or ndarray
        Its derivative along the unworn arc length [1/m^2].
    h : float or ndarray
        Wear depth, inward along the normal [m].
    h1 : float or ndarray
        ``dh/ds`` [-].
    h2 : float or ndarray
        ``d^2h/ds^2`` [1/m].

    Returns
    -------
    ndarray, broadcast shape of the inputs
        Signed curvature of the worn surface [1/m].

    Examples
    --------
    >>> round(float(worn_curvature(1 / 0.02, 0.0, 1e-3, 0.0, 0.0)), 9)   # circle: 1/(rho - h)
    52.631578947
    """
    kappa, dk, h, h1, h2 = (_validate.finite_array(n, x, u) for n, x, u in (
        ("kappa", kappa, "1/m"), ("dkappa_ds", dkappa_ds, "1/m^2"), ("h", h, "m"), ("h1", h1, ""),
        ("h2", h2, "1/m")))
    q = 1.0 - kappa * h
    return (q * (kappa * q + h2) + h1 * (dk * h + 2.0 * kappa * h1)) / (q * q + h1 * h1) ** 1.5


def _periodic_d1_d2(f, dx):
    """First and second periodic central differences of ``f`` on a uniform grid of step ``dx``."""
    fp, fm = np.roll(f, -1), np.roll(f, 1)
    return (fp - fm) / (2.0 * dx), (fp - 2.0 * f + fm) / (dx * dx)


def _fourier_shift(h, period, d):
    """``h(x - d)`` of a periodic uniform-grid function (trigonometric interpolant)."""
    H = np.fft.rfft(h)
    m = np.arange(H.size)
    ph = np.exp(-2j * np.pi * np.mod(m * np.mod(d / period, 1.0), 1.0))
    if h.size % 2 == 0:
        ph[-1] = ph[-1].real
    return np.fft.irfft(H * ph, n=h.size)


# --------------------------------------------------------------------------- the case
@dataclass(frozen=True)
class EvolutionCase:
    """The unworn state over one revolution (SI) that the evolution starts from.

    ``theta`` uniform over one revolution (endpoint excluded); lift ``s`` (m) and its cam-angle
    derivatives ``s1`` (m/rad), ``s2`` (m/rad^2); pressure angle ``phi`` (rad); cam surface
    radius of curvature ``rho`` (m, signed, ``inf`` flat); ``slip`` on the same angles;
    ``dynamics`` a :class:`~femcam.loads.FollowerDynamics`; roller radius ``Rr`` (m); face width
    ``length`` (m); ``cam``/``roller`` materials; wear coefficient ``k`` (m^3/(N m)).

    Parameters
    ----------
    theta : ndarray, shape (n,)
        Cam angles, uniform over one revolution, endpoint excluded [rad].
    s : ndarray, shape (n,)
        Follower lift [m].
    s1 : ndarray, shape (n,)
        ``ds/dtheta`` [m/rad].
    s2 : ndarray, shape (n,)
        ``d^2s/dtheta^2`` [m/rad^2].
    phi : ndarray, shape (n,)
        Pressure angle [rad].
    rho : ndarray, shape (n,)
        Signed radius of curvature of the cam surface (``inf`` flat) [m].
    slip : SlipResult
        Contact speeds on the same angles [m/s].
    dynamics : femcam.loads.FollowerDynamics
        Follower train (mass, spring, damping, preload) of the contact force.
    omega : float
        Cam speed [rad/s].
    Rr : float
        Roller radius [m].
    length : float
        Face width [m].
    cam, roller : femcam.materials.Material
        Materials of the two bodies.
    k : float
        Archard wear coefficient [m^3/(N m)].
    name : str
        Scene name.
    """

    theta: np.ndarray
    s: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    phi: np.ndarray
    rho: np.ndarray
    slip: SlipResult
    dynamics: object
    omega: float
    Rr: float
    length: float
    cam: object
    roller: object
    k: float
    name: str = ""

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)



def evolution_case(contact: ContactCase, *, k: float | None = None) -> EvolutionCase:
    """The :class:`EvolutionCase` of a roller-follower scene's contact.

    Slip from the scene's ``[wear]`` settings (as ``femcam wear map``); ``k`` (m^3/(N m))
    defaults to the scene's wear coefficient (:func:`~femcam.wear.options.wear_coefficient_info`).
    Other followers raise :class:`~femcam.errors.InputError`.

    Parameters
    ----------
    contact : femcam.scene.case.ContactCase
        A roller-follower scene's contact at cam angles uniform over one revolution, endpoint
        excluded [rad] (``contact_case(scene, theta)``).
    k : float, optional
        Archard wear coefficient [m^3/(N m)]; default the scene's.

    Returns
    -------
    EvolutionCase
        The unworn state (SI).

    Raises
    ------
    InputError
        A follower other than a roller, or ``k < 0``.
    """
    c = _validate.instance("contact", contact, ContactCase, "a femcam.scene.case.ContactCase "
                           "(femcam.scene.case.contact_case(scene, theta))")
    if not getattr(c.follower, "translating_roller", False):
        kind = type(c.follower).__name__
        raise _validate.fail("follower type", getattr(c.follower, "kind", kind), "",
                      "profile evolution is implemented for roller followers only (a radiused "
                      "knife-edge tip wears to a conformal flat that Hertz does not describe; a "
                      "flat face is not modelled); run without --evolve-blocks")
    if k is None:
        k = wear_coefficient_info(c.wear, c.pair.cam.hardness)[0]
    k = _validate.nonnegative("k", k, "m^3/(N m)")
    st = c.state
    Fc = np.clip(st.Fc, 0.0, None)
    kw = slip_kwargs(c.wear, omega=c.omega, mu=c.pair.mu, follower=c.follower)
    slip = follower_slip(c.follower, st.theta, st.s, st.s1, st.s2, Fc=Fc, **kw)
    return EvolutionCase(theta=np.asarray(st.theta, float), s=st.s, s1=st.s1, s2=st.s2, phi=st.phi,
                         rho=st.rho, slip=slip, dynamics=c.dynamics, omega=c.omega,
                         Rr=c.follower.Rr, length=c.pair.length, cam=c.pair.cam, roller=c.pair.roller,
                         k=k, name=c.name)


# --------------------------------------------------------------------------- result
@dataclass(frozen=True)
class EvolutionResult:
    """Wear after ``cycles`` revolutions evolved in ``blocks`` blocks of ``block`` revolutions.

    ``x_cam``/``depth_cam`` (m, total) on the cam arc grid of :mod:`.map`; ``depth_linear`` the
    non-evolving map's ``cycles x`` depth per revolution (the first block's map).
    ``x_follower``/``depth_follower`` the roller depth (m, total, drift included) and
    ``depth_follower_linear`` the map's. Per block (rows): ``Fc_blocks`` (N), ``a_blocks`` (m),
    ``p0_blocks`` (Pa), ``rho_blocks`` (worn cam radius at the contact, m). ``volume_cam`` =
    ``l int h dx`` (m^3); ``volume_archard`` = ``sum_b dN k sum_j F v_slip dt`` over the blocks
    with the evolving force (m^3). ``a_over_R_max``: largest Hertz ``a/min(|rho_w|, Rr)``.

    Parameters
    ----------
    cycles : float
        Total cam revolutions [-].
    block : float
        Revolutions per block [-].
    blocks : int
        Number of blocks.
    theta : ndarray, shape (n,)
        Cam angles [rad].
    x_cam : ndarray, shape (m,)
        Arc-length grid on the unworn cam [m].
    depth_cam : ndarray, shape (m,)
        Evolved cam depth after ``cycles`` [m].
    depth_linear : ndarray, shape (m,)
        Non-evolving map's depth after ``cycles`` [m].
    x_follower : ndarray, shape (m_f,)
        Grid on the roller surface [m].
    depth_follower : ndarray, shape (m_f,)
        Evolved roller depth after ``cycles``, drift included [m].
    depth_follower_linear : ndarray, shape (m_f,)
        Non-evolving map's roller depth after ``cycles`` [m].
    xi_cam : ndarray, shape (n,)
        Arc position of the contact on the cam per angle [m].
    Fc_blocks : ndarray, shape (blocks, n)
        Contact force per block and angle [N].
    a_blocks : ndarray, shape (blocks, n)
        Hertz half-width [m].
    p0_blocks : ndarray, shape (blocks, n)
        Hertz peak pressure [Pa].
    rho_blocks : ndarray, shape (blocks, n)
        Worn cam radius of curvature at the contact [m].
    volume_cam : float
        Worn cam volume ``l int h dx`` [m^3].
    volume_archard : float
        Archard volume with the evolving force, summed over the blocks [m^3].
    a_over_R_max : float
        Largest ``a / min(|rho_w|, Rr)`` [-].
    maps : list of WearMap
        The wear map of each block (one revolution each).
    """

    cycles: float
    block: float
    blocks: int
    theta: np.ndarray
    x_cam: np.ndarray
    depth_cam: np.ndarray
    depth_linear: np.ndarray
    x_follower: np.ndarray
    depth_follower: np.ndarray
    depth_follower_linear: np.ndarray
    xi_cam: np.ndarray
    Fc_blocks: np.ndarray
    a_blocks: np.ndarray
    p0_blocks: np.ndarray
    rho_blocks: np.ndarray
    volume_cam: float
    volume_archard: float
    a_over_R_max: float
    maps: list = field(default_factory=list, repr=False)

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @property
    def max_depth(self) -> float:
        """Largest evolved cam depth (m)."""
        return float(np.max(self.depth_cam))

    @property
    def max_depth_linear(self) -> float:
        """Largest cam depth of the non-evolving map after ``cycles`` (m)."""
        return float(np.max(self.depth_linear))

    @property
    def depth_at_theta(self) -> np.ndarray:
        """Evolved cam depth at the contact of each cam angle (m)."""
        return np.interp(self.xi_cam, self.x_cam, self.depth_cam, period=self.x_cam[-1] + self.x_cam[1])


def _check_blocks(cycles, block):
    cycles = _validate.positive("cycles", cycles, "revolutions")
    block = _validate.positive("block", block, "revolutions")
    if block > cycles * (1 + 1e-12):
        raise _validate.fail("block", block, "revolutions", f"must be <= cycles = {cycles:g} revolutions")
    m = cycles / block
    M = int(round(m))
    if abs(m - M) > 1e-9 * max(1.0, m):
        raise _validate.fail("block", block, "revolutions",
                      f"must divide cycles = {cycles:g} revolutions into a whole number of blocks "
                      f"(cycles/block = {m:.6g})")
    return cycles, block, M


def evolve(case: EvolutionCase, cycles: float, block: float, *, n_grid: int | None = None) -> EvolutionResult:
    """Evolve the cam (and roller) wear over ``cycles`` revolutions in blocks of ``block``.

    Each block: worn curvature (eq. 1) and lift loss (eq. 2) from the current depths, the
    contact force on the worn lift, Hertz ``a``, ``p0`` on the worn radii, then
    :func:`~femcam.wear.map.wear_map` for ``block`` revolutions (explicit Euler). ``block =
    cycles`` is the linear map. ``n_grid`` (cam and roller grid points) defaults to the first
    block's choice in :func:`~femcam.wear.map.wear_map` and is kept for every block.

    Raises :class:`~femcam.errors.InputError` for ``cycles <= 0``, ``block <= 0``,
    ``block > cycles`` or ``cycles/block`` not a whole number, and
    :class:`~femcam.hertz.HertzValidityError` if the worn cam becomes conformal (``1/R <= 0``).

    Parameters
    ----------
    case : EvolutionCase
        The unworn state.
    cycles : float
        Total cam revolutions, ``> 0`` [-].
    block : float
        Revolutions per block, dividing ``cycles`` into a whole number [-].
    n_grid : int, optional
        Cam and roller grid points.

    Returns
    -------
    EvolutionResult
        Depths [m], per-block contact data and volumes [m^3].

    Raises
    ------
    InputError
        Bad ``cycles``, ``block`` or ``n_grid``, or a contact that does not move over the cam.
    HertzValidityError
        The worn cam becomes conformal.
    """
    cycles, block, M = _check_blocks(cycles, block)
    if n_grid is not None:
        n_grid = _validate.integer("n_grid", n_grid, 2, "(grid points)")
    th, om, sl = case.theta, case.omega, case.slip
    n = th.size
    dth = 2.0 * math.pi / n
    cphi = np.cos(case.phi)
    rho = np.asarray(case.rho, float)
    kappa = 1.0 / np.where(np.isfinite(rho) & (rho != 0), rho, np.inf)     # 0 where flat
    s_t = np.asarray(sl.V_cam, float) / om                 # ds/dtheta of the contact on the cam
    if np.any(s_t <= 0):
        raise _validate.fail("slip.V_cam", float(np.min(s_t * om)), "m/s",
                      "must be > 0 at every angle (the contact must move over the cam)")
    s_tt = _periodic_d1_d2(s_t, dth)[0]
    dkappa_ds = _periodic_d1_d2(kappa, dth)[0] / s_t
    h_cam = None
    h_fol = None
    H_r = 0.0
    rows = {"Fc": [], "a": [], "p0": [], "rho": []}
    maps: list[WearMap] = []
    vol_arch = 0.0
    ratio = 0.0
    lin_cam = lin_fol = None
    for b in range(M):
        if h_cam is None:
            h_c = np.zeros(n)
            kw = kappa
        else:
            # h at the contact of each cam angle, differentiated in theta (the map resolves the
            # depth at the scale of the angle step, not below it: see the module text)
            h_c = np.interp(maps[0].xi_cam, maps[0].x_cam, h_cam, period=maps[0].perimeter)
            h_t, h_tt = _periodic_d1_d2(h_c, dth)
            h1 = h_t / s_t
            h2 = (h_tt - h1 * s_tt) / (s_t * s_t)
            kw = worn_curvature(kappa, dkappa_ds, h_c, h1, h2)
        ds_f = -(h_c + H_r) / cphi
        d1f, d2f = _periodic_d1_d2(ds_f, dth)
        loads = contact_force(case.dynamics, th, case.s + ds_f, om * (case.s1 + d1f),
                              om * om * (case.s2 + d2f), case.phi)
        Fc = np.clip(loads.Fc, 0.0, None)
        R1 = np.where(kw != 0, 1.0 / np.where(kw != 0, kw, 1.0), np.inf)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")          # validity is reported as a_over_R_max
            hc = LineContact(F=Fc, length=case.length, R1=R1, R2=case.Rr - H_r, cam=case.cam,
                             roller=case.roller)
        a, p0 = np.asarray(hc.a, float), np.asarray(hc.p0, float)
        on = Fc > 0
        if np.any(on):
            rmin = np.minimum(np.abs(R1), case.Rr - H_r)
            ratio = max(ratio, float(np.max(a[on] / rmin[on])))
        wm = wear_map({"theta": th, "a": a, "p0": p0, "Fc": Fc}, sl, k=case.k, length=case.length,
                      cycles=block, pressure="hertz", n_grid=n_grid)
        if n_grid is None:
            n_grid = wm.x_cam.size
        maps.append(wm)
        for key, val in (("Fc", Fc), ("a", a), ("p0", p0), ("rho", R1)):
            rows[key].append(val)
        vol_arch += block * wm.volume_archard
        add_c = block * wm.depth_cam
        add_f = wm.depth_follower_cycles
        if wm.follower_period is not None and b > 0:
            add_f = _fourier_shift(add_f, wm.follower_period, b * block * wm.follower_drift)
        h_cam = add_c if h_cam is None else h_cam + add_c
        h_fol = add_f if h_fol is None else h_fol + add_f
        H_r = float(np.mean(h_fol)) if wm.follower_period is not None else 0.0
        if b == 0:
            lin_cam = cycles * wm.depth_cam
            lin_fol = (drift_sum(wm.depth_follower, wm.follower_period, wm.follower_drift, cycles)
                       if wm.follower_period is not None else cycles * wm.depth_follower)
    wm0 = maps[0]
    dx = wm0.x_cam[1] - wm0.x_cam[0]
    return EvolutionResult(
        cycles=cycles, block=block, blocks=M, theta=th, x_cam=wm0.x_cam, depth_cam=h_cam,
        depth_linear=lin_cam, x_follower=wm0.x_follower, depth_follower=h_fol,
        depth_follower_linear=lin_fol, xi_cam=wm0.xi_cam,
        Fc_blocks=np.array(rows["Fc"]), a_blocks=np.array(rows["a"]), p0_blocks=np.array(rows["p0"]),
        rho_blocks=np.array(rows["rho"]), volume_cam=float(case.length * np.sum(h_cam) * dx),
        volume_archard=float(vol_arch), a_over_R_max=ratio, maps=maps)


# --------------------------------------------------------------------------- convergence
@dataclass(frozen=True)
class ConvergenceTable:
    """Evolutions with ``blocks[i]`` blocks (block size ``cycles/blocks[i]``).

    ``max_depth`` (m) per row; ``diff_finest`` = max over the cam of ``|h_i - h_finest|`` (m);
    ``diff_next`` = max ``|h_i - h_{i+1}|`` (m, NaN on the last row); ``order`` =
    ``log2(diff_next[i-1]/diff_next[i])`` for halvings (NaN where undefined): 1 for explicit
    Euler. ``linear_max_depth``: the non-evolving map's maximum (m).

    Parameters
    ----------
    cycles : float
        Total cam revolutions [-].
    blocks : list of int
        Block counts, one per row.
    results : list of EvolutionResult
        The evolution of each row.
    max_depth : ndarray, shape (rows,)
        Largest cam depth [m].
    diff_finest : ndarray, shape (rows,)
        Max ``|h_i - h_finest|`` over the cam [m].
    diff_next : ndarray, shape (rows,)
        Max ``|h_i - h_{i+1}|`` [m]; NaN on the last row.
    order : ndarray, shape (rows,)
        Observed order of convergence [-]; NaN where undefined.
    linear_max_depth : float
        Non-evolving map's largest depth [m].
    """

    cycles: float
    blocks: list
    results: list
    max_depth: np.ndarray
    diff_finest: np.ndarray
    diff_next: np.ndarray
    order: np.ndarray
    linear_max_depth: float

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @property
    def finest(self) -> EvolutionResult:
        """The evolution with the most blocks (last row)."""
        return self.results[-1]

    def rows(self):
        """``(header, rows)`` for CSV (SI to µm/nm as named in the header).

        Returns
        -------
        header : list of str
            Column names with their units.
        rows : list of list
            One row per block count (depths in um and nm as in the header).
        """
        head = ["blocks", "block_revolutions", "max_depth_um", "diff_to_finest_max_nm", "diff_to_next_max_nm",
                "observed_order", "change_vs_linear_max_depth"]
        out = []
        for i, nb in enumerate(self.blocks):
            out.append([nb, f"{self.cycles / nb:.8g}", f"{self.max_depth[i] * 1e6:.10g}",
                        f"{self.diff_finest[i] * 1e9:.6g}", f"{self.diff_next[i] * 1e9:.6g}",
                        f"{self.order[i]:.4g}", f"{self.max_depth[i] / self.linear_max_depth - 1:.6e}"])
        return head, out


#: most block solves x cam angles of one convergence table: one block re-solves the pressure at
#: every angle, ~1.1 ms per angle (seed 002, 720 angles: 4 blocks in 8 s, 32 in 54 s, i.e.
#: ~0.8 s per block); 400,000 is ~7 min, e.g. 256 blocks (511 block solves) at 0.5 deg
MAX_ANGLE_SOLVES = 400_000
#: measured seconds per angle per block solve, for the refusal's time estimate
SECONDS_PER_ANGLE_SOLVE = 1.1e-3


def evolution_problem(n_angles: int, max_blocks: int) -> str | None:
    """Why a convergence table of ``max_blocks`` at ``n_angles`` cam angles is refused, or None.

    Parameters
    ----------
    n_angles : int
        Cam angles per revolution (-).
    max_blocks : int
        Largest block count (-); 1, 2, 4, ... ``max_blocks`` blocks are run, ``~2 max_blocks``
        block solves in all.

    Returns
    -------
    str or None
        The estimate, the cap and what to change; None when it fits.
    """
    solves = sum(block_counts(max_blocks)) * int(n_angles)
    if solves <= MAX_ANGLE_SOLVES:
        return None
    return (f"{sum(block_counts(max_blocks)):,} block solves of {n_angles} angles would take "
            f"~{solves * SECONDS_PER_ANGLE_SOLVE / 60:.3g} min (~{SECONDS_PER_ANGLE_SOLVE * 1e3:g} ms "
            f"per angle per block), above the cap of {MAX_ANGLE_SOLVES:,} angle solves "
            "(femcam.wear.evolution.MAX_ANGLE_SOLVES); use fewer blocks or a coarser angle step")


def block_counts(max_blocks: int) -> list:
    """1, 2, 4, ... (powers of two <= ``max_blocks``), then ``max_blocks`` if it is not one.

    Parameters
    ----------
    max_blocks : int
        Largest block count, ``>= 1``.

    Returns
    -------
    list of int
        The block counts.
    """
    max_blocks = _validate.integer("blocks", max_blocks, 1, "(number of blocks)")
    out, nb = [], 1
    while nb <= max_blocks:
        out.append(nb)
        nb *= 2
    if out[-1] != max_blocks:
        out.append(max_blocks)
    return out


def convergence_table(case: EvolutionCase, cycles: float, max_blocks: int, *,
                      n_grid: int | None = None) -> ConvergenceTable:
    """Evolve with 1, 2, 4, ... blocks up to ``max_blocks`` (see :func:`block_counts`) and tabulate
    the convergence in the block size (max-norm differences over the cam depth).

    Parameters
    ----------
    case : EvolutionCase
        The unworn state.
    cycles : float
        Total cam revolutions, ``> 0`` [-].
    max_blocks : int
        Largest block count.
    n_grid : int, optional
        Cam and roller grid points; default the first evolution's.

    Returns
    -------
    ConvergenceTable
        Depths and differences [m] and observed orders.
    """
    cycles = _validate.positive("cycles", cycles, "revolutions")
    counts = block_counts(_validate.integer("max_blocks", max_blocks, 1, "blocks"))
    why = evolution_problem(np.size(case.theta), max_blocks)   # before any block is run
    if why:
        raise _validate.fail("max_blocks", max_blocks, "(number of blocks)", why)
    first = evolve(case, cycles, cycles, n_grid=n_grid)       # counts[0] == 1: the linear map
    n_grid = first.x_cam.size
    res = [first] + [evolve(case, cycles, cycles / nb, n_grid=n_grid) for nb in counts[1:]]
    H = [r.depth_cam for r in res]
    md = np.array([r.max_depth for r in res])
    dfin = np.array([float(np.max(np.abs(h - H[-1]))) for h in H])
    dnext = np.array([float(np.max(np.abs(H[i] - H[i + 1]))) for i in range(len(H) - 1)] + [np.nan])
    order = np.full(len(H), np.nan)
    for i in range(1, len(H) - 1):
        halving = counts[i] == 2 * counts[i - 1] and counts[i + 1] == 2 * counts[i]
        if halving and dnext[i] > 0 and dnext[i - 1] > 0:
            order[i] = math.log2(dnext[i - 1] / dnext[i])
    return ConvergenceTable(cycles=cycles, blocks=counts, results=res, max_depth=md, diff_finest=dfin,
                            diff_next=dnext, order=order, linear_max_depth=res[0].max_depth_linear)


__all__ = ["EvolutionCase", "EvolutionResult", "ConvergenceTable", "evolution_case", "evolve",
           "convergence_table", "block_counts", "worn_curvature"]
