r"""Local Archard wear depth on the cam surface and on the follower.

Archard's law per unit area, :math:`dh = k\,p\,ds_{slip}` (k in m^3/(N m), p in Pa), summed over
the time a surface point spends under the moving contact:

.. math:: h(x) = k\int p\big(x - \xi(t)\big)\,v_{slip}(t)\,dt

where ``xi(t)`` is the contact centre's position along that surface (cam: arc length; roller:
circumferential coordinate, periodic ``2 pi Rr``; flat face: distance from the axis).

Symbols
-------
=========  ================================================  ===========  ==================
symbol     meaning                                           unit         source
=========  ================================================  ===========  ==================
k          dimensional wear coefficient (``K/H``)            m^3/(N m)    Archard (1953)
p(x)       contact pressure, Hertz ``p0 sqrt(1 - x^2/a^2)``  Pa           Johnson eq. 4.44
a, p0      contact half-width, peak pressure                 m, Pa        Johnson §4.2
w          load per unit length, ``int p dx = pi a p0 / 2``  N/m          Johnson eq. 4.44
v_slip     sliding speed at the contact                      m/s          :mod:`.slip`
V          speed of the contact over the surface             m/s          :mod:`.slip`
xi         contact-centre coordinate on the surface          m
l          face width (contact length)                       m
=========  ================================================  ===========  ==================

**Per pass, closed form** (quasi-stationary: ``a``, ``p0``, ``v_slip`` and ``V`` do not change
while the contact crosses a point). With ``dt = dxi / V``:

.. math:: \Delta h = k\,\frac{v_{slip}}{V}\int p\,dx = k\,w\,\frac{v_{slip}}{V}

i.e. k times the load per unit length times the slip per unit rolled length
(:func:`depth_per_pass`). For Hertz, ``w = pi a p0 / 2``.

**Map** (:func:`surface_depth`): the contact moves linearly from ``xi_j`` to ``xi_{j+1}`` in each
step with the step's mid values of ``a, p0, v_slip``; the time integral is then exact:

.. math:: \int p(x-\xi(t))\,dt = \frac{1}{V}\big[P(x-\xi_j) - P(x-\xi_{j+1})\big],\quad
          P(y) = \frac{p_0 a}{2}\Big(\eta\sqrt{1-\eta^2} + \arcsin\eta\Big),\ \eta = \mathrm{clip}(y/a)

so the map conserves volume to round-off: ``l int h dx = k sum F v_slip dt`` (Archard's
``W = k L S``), whatever the grid, as long as the grid resolves ``a``.

Assumptions: Archard wear with constant k (no running-in); pressure from Hertz or the FE sweep
(elliptical profile with the sweep's ``a``/``p0``); the profile is not updated as it wears
(linear in cycles: depth after N cycles = N x depth per revolution); wear is uniform across the
face width; both bodies wear with the same k (give a different k per body by scaling).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import _validate as vd
from .slip import SlipResult


# --------------------------------------------------------------------------- formulas
def hertz_load_per_length(a, p0):
    r"""``w = int p dx = pi a p0 / 2`` (N/m) for the Hertz elliptical pressure (Johnson eq. 4.44).

    >>> round(float(hertz_load_per_length(1e-4, 1e9)), 3)
    157079.633
    """
    return 0.5 * np.pi * np.asarray(a, dtype=float) * np.asarray(p0, dtype=float)


def depth_per_pass(k, w, v_slip, V_transport):
    r"""Wear depth left by one pass of the contact over a surface point (m).

    .. math:: \Delta h = k\,w\,v_{slip}/V

    ``V_transport = 0`` (the contact sits still on that surface, e.g. a knife-edge tip) gives
    ``inf`` where ``k w v_slip > 0``.

    >>> float(depth_per_pass(1e-17, 1e5, 0.2, 1.0))     # k w (slip per rolled length)
    2e-13
    """
    k = vd.nonnegative("k", k, "m^3/(N m)")
    w = np.clip(np.nan_to_num(np.asarray(w, dtype=float), nan=0.0), 0.0, None)
    v = np.abs(np.asarray(v_slip, dtype=float))
    Vt = np.abs(np.asarray(V_transport, dtype=float))
    num = k * w * v
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(Vt > 0, num / np.where(Vt > 0, Vt, 1.0), np.where(num > 0, np.inf, 0.0))
    return out


def _ellipse_primitive(y, a, p0):
    """P(y) = int_{-a}^{y} p0 sqrt(1 - t^2/a^2) dt - w/2 (odd; constant -+ w/2 outside)."""
    eta = np.clip(y / a, -1.0, 1.0)
    return 0.5 * p0 * a * (eta * np.sqrt(1.0 - eta * eta) + np.arcsin(eta))


def surface_depth(x, xi, a, p0, v_slip, dt, *, k, period=None, chunk: int = 256):
    r"""Archard depth ``h(x) = k int p(x - xi(t)) v_slip dt`` on grid ``x`` (m).

    ``xi`` (n+1 contact positions, m) bound n steps of duration ``dt`` (s); ``a``, ``p0``,
    ``v_slip`` (n values) hold in each step. ``period`` makes the coordinate periodic (cam
    perimeter, roller circumference). Steps with ``a <= 0``, NaN or ``p0 <= 0`` carry no load.
    Vectorised over the grid; steps are processed in chunks of ``chunk``.
    """
    k = vd.nonnegative("k", k, "m^3/(N m)")
    x = np.asarray(x, dtype=float)
    xi = np.asarray(xi, dtype=float)
    a = np.nan_to_num(np.asarray(a, dtype=float), nan=0.0)
    p0 = np.nan_to_num(np.asarray(p0, dtype=float), nan=0.0)
    v = np.abs(np.asarray(v_slip, dtype=float))
    dt = np.asarray(dt, dtype=float)
    live = (a > 0) & (p0 > 0) & (v > 0) & (dt > 0)
    idx = np.flatnonzero(live)
    h = np.zeros_like(x)
    if idx.size == 0 or k == 0.0:
        return h
    x0 = xi[idx]
    dxi = xi[idx + 1] - xi[idx]
    a_, p_, g = a[idx], p0[idx], k * v[idx] * dt[idx]           # g = k v_slip dt (m^3/N)
    # moving steps: exact time integral; near-still steps (|dxi| < 1e-6 a): p(x - xi) dt
    moving = np.abs(dxi) > 1e-6 * a_
    safe = np.where(moving, dxi, 1.0)
    for s0 in range(0, idx.size, chunk):
        sl = slice(s0, s0 + chunk)
        y = x[:, None] - x0[None, sl]
        if period is not None:
            y = (y + 0.5 * period) % period - 0.5 * period
        A, P0 = a_[None, sl], p_[None, sl]
        exact = (_ellipse_primitive(y, A, P0) - _ellipse_primitive(y - dxi[None, sl], A, P0)) / safe[None, sl]
        eta = np.clip(y / A, -1.0, 1.0)
        still = P0 * np.sqrt(1.0 - eta * eta)
        h += np.where(moving[None, sl], exact, still) @ g[sl]
    return h


# --------------------------------------------------------------------------- inputs
_KEYS = {
    "hertz": (("a_hertz", "a"), ("p0_hertz", "p0")),
    "fe": (("a_fe", "a"), ("p0_fe", "p0")),
}


def _get(src, names):
    for n in names:
        try:
            val = src[n]
        except (KeyError, IndexError, TypeError, ValueError):
            val = getattr(src, n, None)
        if val is not None:
            return np.asarray(val, dtype=float)
    return None


def contact_columns(source, *, pressure: str = "hertz"):
    """``(theta, a, p0, Fc)`` arrays (SI) from a SweepResult-like object or a mapping.

    ``pressure="fe"`` reads ``a_fe``/``p0_fe``, ``"hertz"`` reads ``a_hertz``/``p0_hertz``; both
    fall back to plain ``a``/``p0``. Angles without contact (``Fc <= 0``, NaN width) carry no load.
    """
    vd.choice("pressure", pressure, tuple(_KEYS))
    (ka, kp) = _KEYS[pressure]
    theta = _get(source, ("theta",))
    a, p0, Fc = _get(source, ka), _get(source, kp), _get(source, ("Fc",))
    for name, arr in (("theta", theta), ("a", a), ("p0", p0)):
        if arr is None:
            raise vd.fail("source", type(source).__name__, "", f"has no column '{name}' "
                         f"(looked for {ka if name == 'a' else kp if name == 'p0' else name})")
    if Fc is None:
        Fc = np.where(np.isfinite(a) & (a > 0), 1.0, 0.0)
    theta = vd.finite_array("theta", theta, "rad")
    bad = np.isfinite(a) & (a < 0)
    if np.any(bad):
        raise vd.fail("a", float(a[bad][0]), "m", "must be >= 0 (contact half-width)")
    noc = ~(np.isfinite(a) & np.isfinite(p0) & (Fc > 0))
    a = np.where(noc, 0.0, a)
    p0 = np.where(noc, 0.0, np.clip(p0, 0.0, None))
    return theta, a, p0, np.where(noc, 0.0, Fc)


# --------------------------------------------------------------------------- map
@dataclass(frozen=True)
class WearMap:
    """Wear of cam and follower over one revolution and after ``cycles`` revolutions (SI).

    Per cam angle: ``xi_cam`` (arc position of the contact centre, m), ``depth_pass`` (closed
    form ``k w v_slip/V_cam``, m per revolution), ``depth_at_theta`` (map value at ``xi_cam``).
    On grids: ``x_cam``/``depth_cam`` (m per revolution) and ``x_follower``/``depth_follower``.
    Volumes per revolution (m^3): ``volume_cam = l int h dx``, ``volume_follower``, and the
    independent Archard total ``volume_archard = k sum F v_slip dt``; ``conservation_error`` is
    their relative difference (cam). ``*_total`` properties multiply by ``cycles``.
    """

    theta: np.ndarray
    xi_cam: np.ndarray
    depth_pass: np.ndarray
    depth_at_theta: np.ndarray
    x_cam: np.ndarray
    depth_cam: np.ndarray
    x_follower: np.ndarray
    depth_follower: np.ndarray
    perimeter: float
    volume_cam: float
    volume_follower: float
    volume_archard: float
    conservation_error: float
    k: float
    length: float
    cycles: float
    model: str

    @property
    def depth_cam_total(self) -> np.ndarray:
        return self.cycles * self.depth_cam

    @property
    def i_max(self) -> int:
        return int(np.argmax(self.depth_at_theta))

    @property
    def max_depth(self) -> float:
        """Largest cam wear depth after ``cycles`` revolutions (m)."""
        return float(self.cycles * np.max(self.depth_cam))

    @property
    def x_max(self) -> float:
        """Arc position of the deepest cam wear (m from the contact point at ``theta[0]``)."""
        return float(self.x_cam[int(np.argmax(self.depth_cam))])

    @property
    def theta_max(self) -> float:
        """Cam angle (rad) at which the deepest point of the cam is in contact."""
        return float(self.theta[self.i_max])

    def summary(self) -> dict:
        return {"max_depth_m": self.max_depth, "theta_max_rad": self.theta_max, "x_max_m": self.x_max,
                "volume_cam_m3": self.cycles * self.volume_cam,
                "volume_follower_m3": self.cycles * self.volume_follower,
                "conservation_error": self.conservation_error, "cycles": self.cycles, "model": self.model}


def _cumulative(theta_closed, f_closed):
    """Cumulative trapezoid of f over theta (same length, starting at 0)."""
    return np.concatenate(([0.0], np.cumsum(0.5 * (f_closed[1:] + f_closed[:-1]) * np.diff(theta_closed))))


def wear_map(source, slip: SlipResult, *, k, length, cycles: float = 1.0, pressure: str = "hertz",
             n_grid: int | None = None) -> WearMap:
    """Archard wear map of one revolution from per-angle contact data and a slip model.

    ``source``: SweepResult-like object or mapping with ``theta`` (rad, uniform over one
    revolution, endpoint excluded), ``a``/``p0`` (m, Pa; ``a_hertz``/``p0_hertz`` or
    ``a_fe``/``p0_fe``) and ``Fc`` (N). ``slip``: a :class:`~femcam.wear.slip.SlipResult` on the
    same angles. ``k`` in m^3/(N m), ``length`` (face width) in m.
    """
    k = vd.nonnegative("k", k, "m^3/(N m)")
    length = vd.positive("length", length, "m")
    cycles = vd.nonnegative("cycles", cycles, "revolutions")
    theta, a, p0, Fc = contact_columns(source, pressure=pressure)
    n = theta.size
    if slip.theta.shape != theta.shape or not np.allclose(slip.theta, theta, atol=1e-12):
        raise vd.fail("slip.theta", f"{slip.theta.size} angles", "rad",
                      "must equal the contact table's angles")
    dth = np.diff(theta)
    span = theta[-1] - theta[0] + (float(np.mean(dth)) if n > 1 else 0.0)
    if n < 4 or np.any(dth <= 0) or abs(span - 2 * np.pi) > 1e-6:
        raise vd.fail("theta", f"[{theta[0]:g} .. {theta[-1]:g}] ({n} points)", "rad",
                     "must be increasing, uniform, one revolution, endpoint excluded")
    omega = slip.omega
    # close the revolution: step j runs from theta_j to theta_{j+1} (theta_n = theta_0 + 2 pi)
    thc = np.append(theta, theta[0] + 2 * np.pi)

    def closed(f):
        return np.append(f, f[0])

    xi_c = _cumulative(thc, closed(slip.V_cam) / omega)
    perimeter = float(xi_c[-1])
    xi_f = _cumulative(thc, closed(slip.V_follower) / omega)
    dt = np.diff(thc) / omega

    def mid(f):
        fc = closed(f)
        return 0.5 * (fc[1:] + fc[:-1])

    a_m, p_m, v_m = mid(a), mid(p0), mid(slip.v_slip)
    # a step that touches a no-contact angle carries no load (liftoff edges)
    contact = (a > 0) & (p0 > 0)
    both = contact & np.roll(contact, -1)
    a_m, p_m = np.where(both, a_m, 0.0), np.where(both, p_m, 0.0)

    a_pos = a_m[a_m > 0]
    if n_grid is None:
        a_min = float(a_pos.min()) if a_pos.size else perimeter
        n_grid = int(np.clip(np.ceil(perimeter / (a_min / 3.0)), 2000, 40000))
    x_cam = np.linspace(0.0, perimeter, int(n_grid), endpoint=False)
    depth_cam = surface_depth(x_cam, xi_c, a_m, p_m, v_m, dt, k=k, period=perimeter)

    Pf = slip.follower_period
    if Pf is not None:
        x_f = np.linspace(0.0, Pf, int(n_grid), endpoint=False)
        xi_fw = xi_f
    else:
        amax = float(a_pos.max()) if a_pos.size else 0.0
        lo, hi = float(xi_f.min()) - 1.5 * amax, float(xi_f.max()) + 1.5 * amax
        x_f = np.linspace(lo, hi, int(n_grid))
        xi_fw = xi_f
    depth_f = surface_depth(x_f, xi_fw, a_m, p_m, v_m, dt, k=k, period=Pf)

    w_m = hertz_load_per_length(a_m, p_m)
    vol_archard = float(k * np.sum(w_m * length * v_m * dt))
    vol_cam = float(length * np.sum(depth_cam) * (x_cam[1] - x_cam[0]))
    dxf = x_f[1] - x_f[0] if x_f.size > 1 else 0.0
    vol_f = float(length * np.sum(depth_f) * dxf) if Pf is not None else \
        float(length * np.trapezoid(depth_f, x_f))
    cons = abs(vol_cam - vol_archard) / vol_archard if vol_archard > 0 else 0.0
    w = hertz_load_per_length(a, p0)
    return WearMap(
        theta=theta, xi_cam=xi_c[:-1], depth_pass=depth_per_pass(k, w, slip.v_slip, slip.V_cam),
        depth_at_theta=np.interp(xi_c[:-1], x_cam, depth_cam, period=perimeter),
        x_cam=x_cam, depth_cam=depth_cam, x_follower=x_f, depth_follower=depth_f, perimeter=perimeter,
        volume_cam=vol_cam, volume_follower=vol_f, volume_archard=vol_archard, conservation_error=cons,
        k=k, length=length, cycles=cycles, model=slip.model)


def wear_depth_per_angle(theta, a, p0, Fc, slip: SlipResult, k):
    """Sweep-facing closed form: cam wear depth per revolution at the contact of each angle (m).

    ``k w v_slip / V_cam`` with ``w = pi a p0 / 2``; zero where there is no contact (``Fc <= 0``
    or NaN width). Same length as ``theta``; for the sweep's CSV/VTK wear column.
    """
    _, a, p0, _ = contact_columns({"theta": theta, "a": a, "p0": p0, "Fc": Fc})
    return depth_per_pass(k, hertz_load_per_length(a, p0), slip.v_slip, slip.V_cam)
