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

**Pressure source.** Per pass the depth depends on the pressure only through ``w = int p dx``,
which equilibrium fixes at ``F/l`` for any distribution; the distribution only smooths the map
over ~``a`` where the load changes. With the FE sweep's ``a_fe``/``p0_fe`` the map rebuilds an
ellipse whose ``pi a p0/2`` misses ``F/l`` by the FE's accuracy on ``a`` and ``p0``
(``WearMap.load_error``, ~1 % for seed 002), so FE-based wear agrees with Hertz-based wear to
that accuracy, not better. An angle with ``Fc > 0`` but no pressure (failed solve) raises, or is
skipped with a warning (sweep results), see :func:`contact_columns`.

**Roller drift.** The cam comes back to the same point after a revolution; the roller does not:
the contact advances ``D = int V_follower dt`` (mod ``2 pi Rr``) per cam revolution, so
revolution n lays the one-revolution roller pattern down shifted by ``n D``.
``WearMap.depth_follower_cycles`` sums these shifts exactly (:func:`drift_sum`);
``cycles x depth_follower`` is the phase-locked bound (``D`` a multiple of ``2 pi Rr``). A
constant ``D`` is itself an idealisation (real slip varies from revolution to revolution): what is
robust is the mean, ``cycles x mean(depth_follower)``, and for large N with ``D/(2 pi Rr)`` not
close to a ratio of small integers the pattern flattens towards it.

Assumptions: Archard wear with constant k (no running-in); pressure from Hertz or the FE sweep
(elliptical profile with the sweep's ``a``/``p0``); the profile is not updated as it wears
(linear in cycles: depth after N cycles = N x depth per revolution on the cam; the roller with
its drift); wear is uniform across the face width; both bodies wear with the same k (give a
different k per body by scaling).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import _validate
from .._repr import compact_repr, span
from .inputs import MISSING, WearInputWarning, _loaded_have, contact_columns
from .slip import SlipResult
from .surface import (
    _depth_per_pass,
    _ellipse_primitive,
    depth_per_pass,
    drift_sum,
    hertz_load_per_length,
    surface_depth,
)

__all__ = ["MISSING", "WearInputWarning", "WearMap", "_ellipse_primitive", "contact_columns",
           "depth_per_pass", "drift_sum", "hertz_load_per_length", "surface_depth", "wear_depth_per_angle",
           "wear_map"]


@dataclass(frozen=True)
class WearMap:
    """Wear of cam and follower over one revolution and after ``cycles`` revolutions (SI).

    Per cam angle: ``xi_cam`` (arc position of the contact centre, m), ``depth_pass`` (closed
    form ``k w v_slip/V_cam``, m per revolution), ``depth_at_theta`` (map value at ``xi_cam``).
    On grids: ``x_cam``/``depth_cam`` (m per revolution) and ``x_follower``/``depth_follower``
    (m per revolution; ``x_follower``: roller, arc from the roller point in contact at
    ``theta[0]`` in the first revolution; flat face, distance from the follower axis; radiused
    knife-edge tip, arc ``r_tip phi`` from the tip's axis point).

    ``depth_follower_cycles`` is the follower depth after ``cycles`` revolutions. On a roller
    the contact does not come back to the same roller point after a cam revolution: it has
    advanced by ``follower_drift`` (m, modulo ``2 pi Rr``), so revolution n lays the one-
    revolution pattern down shifted by ``n D``; the sum is evaluated exactly (Fourier series,
    geometric sum), see :func:`drift_sum`. ``max_depth_follower_locked`` is the bound
    ``cycles x max(depth_follower)`` a phase-locked roller (``D`` a multiple of ``2 pi Rr``)
    would reach. Other followers do not drift (``depth_follower_cycles = cycles x
    depth_follower``).

    Volumes per revolution (m^3): ``volume_cam = l int h dx``, ``volume_follower``, and the
    independent Archard total ``volume_archard = k sum F v_slip dt``; ``conservation_error`` is
    their relative difference (cam). ``load_error`` is the largest ``|l pi a p0/2 - Fc| / Fc``
    over the contact angles: 0 for Hertz, the fit error of an FE ``a``/``p0``. ``skipped``:
    indices of angles skipped for a missing pressure. ``*_total`` properties are the values
    after ``cycles`` revolutions (coating and roller drift included); ``max_depth``, ``x_max``,
    ``theta_max``/``i_max`` and the follower's ``max_depth_follower``/``x_max_follower`` all
    come from these totals, so the reported position is where the reported depth is.

    Attributes
    ----------
    theta : ndarray, shape (n,), float
        Cam angles [rad], uniform over one revolution.
    xi_cam : ndarray, shape (n,), float
        Arc position of the contact centre on the cam [m], 0 at ``theta[0]``.
    depth_pass : ndarray, shape (n,), float
        Closed-form depth per pass ``k w v_slip / V_cam`` at each angle [m per revolution].
    depth_at_theta : ndarray, shape (n,), float
        Map depth at ``xi_cam`` [m per revolution].
    x_cam : ndarray, shape (n_grid,), float
        Cam grid, arc position from the contact point at ``theta[0]`` [m], over one perimeter.
    depth_cam : ndarray, shape (n_grid,), float
        Cam wear depth on ``x_cam`` [m per revolution].
    x_follower : ndarray, shape (n_grid,), float
        Follower grid [m] (roller: arc; flat face: distance from the axis; tip: ``r_tip phi``).
    depth_follower : ndarray, shape (n_grid,), float
        Follower wear depth on ``x_follower`` [m per revolution], no drift.
    perimeter : float
        Cam perimeter swept by the contact in one revolution [m].
    volume_cam, volume_follower : float
        Worn volumes ``l int h dx`` per revolution [m^3].
    volume_archard : float
        Archard volume ``k sum F v_slip dt`` per revolution [m^3].
    conservation_error : float
        ``|volume_cam - volume_archard| / volume_archard`` [-].
    k : float
        Dimensional wear coefficient [m^3/(N m)].
    length : float
        Face width (contact length) [m].
    cycles : float
        Number of cam revolutions [-].
    model : str
        Slip model (``SlipResult.model``).
    depth_follower_cycles : ndarray, shape (n_grid,), float, or None
        Follower depth after ``cycles`` revolutions with the roller drift [m].
    follower_period : float or None
        Roller circumference ``2 pi Rr`` [m]; None for a non-periodic follower coordinate.
    follower_drift : float
        Advance of the roller contact per cam revolution, modulo ``follower_period`` [m].
    load_error : float
        Largest ``|l pi a p0 / 2 - Fc| / Fc`` over the contact angles [-].
    skipped : tuple of int
        Indices of angles skipped for a missing pressure.
    k_factor : ndarray, shape (n,), float, or None
        Per-angle multiplier of ``k`` [-] (lubricated scenes); None: dry k.
    regime : ndarray, shape (n,), str, or None
        Lubrication regime per angle; None: dry.
    depth_cam_cycles : ndarray, shape (n_grid,), float, or None
        Depth of a coated cam after ``cycles`` revolutions [m]; None: uncoated.
    coating : dict or None
        Coating record (body, ``thickness_m``, ``k_coating``, ``k_substrate``,
        ``revolutions_through``, source); None: uncoated.
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
    depth_follower_cycles: np.ndarray | None = None
    follower_period: float | None = None
    follower_drift: float = 0.0
    load_error: float = 0.0
    skipped: tuple = ()
    #: per-angle multiplier of k (lubricated scenes: k(lambda)/k, femcam.assess.wear_factor) and the
    #: lubrication regime of each angle ("boundary", "mixed", "full", "no contact"); None: dry k
    k_factor: np.ndarray | None = None
    regime: np.ndarray | None = None
    #: a coated body's depth after ``cycles`` (femcam.wear.coating: the coating's k until worn
    #: through) and the coating record (body, thickness_m, k_coating, k_substrate,
    #: revolutions_through, source); None: uncoated
    depth_cam_cycles: np.ndarray | None = None
    coating: dict | None = None

    def __repr__(self) -> str:
        """Angles, the largest depth, the volumes and k (a compact line)."""
        return compact_repr(self, [
            f"{self.theta.size} angles",
            f"cam depth/rev {span(self.depth_cam, 1e9, 'nm')}",
            f"cam volume/rev {self.volume_cam * 1e9:.4g} mm^3",
            f"k {self.k:.3g} m^3/(N m)",
            f"{self.cycles:g} cycles",
            self.model,
        ])

    @property
    def depth_cam_total(self) -> np.ndarray:
        """Cam depth on ``x_cam`` after ``cycles`` revolutions (m), coating included."""
        if self.depth_cam_cycles is not None:
            return self.depth_cam_cycles
        return self.cycles * self.depth_cam

    @property
    def _cam_rank(self) -> np.ndarray:
        """Cam depth on ``x_cam`` that locates the deepest point: the coated total after ``cycles``
        (its shape is not the one-revolution map's), else the one-revolution map (same argmax as
        ``cycles x depth_cam``, and still defined at ``cycles = 0``)."""
        return self.depth_cam if self.depth_cam_cycles is None else self.depth_cam_cycles

    @property
    def i_max(self) -> int:
        """Index of the angle whose contact point is deepest after ``cycles`` revolutions."""
        at_theta = np.interp(self.xi_cam, self.x_cam, self._cam_rank, period=self.perimeter)
        return int(np.argmax(at_theta))

    @property
    def max_depth(self) -> float:
        """Largest cam wear depth after ``cycles`` revolutions (m)."""
        return float(np.max(self.depth_cam_total))

    @property
    def x_max(self) -> float:
        """Arc position of the deepest cam wear after ``cycles`` (m from the contact point at
        ``theta[0]``)."""
        return float(self.x_cam[int(np.argmax(self._cam_rank))])

    @property
    def theta_max(self) -> float:
        """Cam angle (rad) at which the deepest point of the cam is in contact."""
        return float(self.theta[self.i_max])

    @property
    def volume_cam_total(self) -> float:
        """Worn cam volume after ``cycles`` revolutions (m^3): ``l int h dx`` of
        :attr:`depth_cam_total` (coating included), integrated as :attr:`volume_cam`."""
        return _volume(self.x_cam, self.depth_cam_total, self.length, periodic=True)

    @property
    def volume_follower_total(self) -> float:
        """Worn follower volume after ``cycles`` revolutions (m^3): ``l int h dx`` of
        :attr:`depth_follower_total` (coating and drift included), integrated as
        :attr:`volume_follower`."""
        return _volume(self.x_follower, self.depth_follower_total, self.length,
                       periodic=self.follower_period is not None)

    @property
    def depth_follower_total(self) -> np.ndarray:
        """Follower depth after ``cycles`` revolutions (m), roller drift included."""
        if self.depth_follower_cycles is not None:
            return self.depth_follower_cycles
        return self.cycles * self.depth_follower

    @property
    def max_depth_follower(self) -> float:
        """Largest follower wear depth after ``cycles`` revolutions (m), roller drift included."""
        return float(np.max(self.depth_follower_total)) if self.depth_follower.size else 0.0

    @property
    def x_max_follower(self) -> float:
        """Position (m, coordinate of ``x_follower``) of the deepest follower wear after ``cycles``."""
        return float(self.x_follower[int(np.argmax(self.depth_follower_total))]) if self.depth_follower.size \
            else 0.0

    @property
    def max_depth_follower_locked(self) -> float:
        """``cycles x`` the largest follower depth of one revolution (m): the phase-locked bound."""
        return float(self.cycles * np.max(self.depth_follower)) if self.depth_follower.size else 0.0

    def summary(self) -> dict:
        """The headline figures after ``cycles`` revolutions, units in the key names.

        Returns
        -------
        dict
            ``max_depth_m``, ``theta_max_rad``, ``x_max_m``, the follower depths and position
            (m), ``follower_drift_m``, ``volume_cam_m3`` and ``volume_follower_m3`` (after
            ``cycles``, integrated from the depth totals, coating included),
            ``conservation_error`` and ``load_error`` [-], ``skipped_angles_rad``, ``cycles``,
            ``model``; plus ``coating`` (coated) and ``regime_angles`` (angle count
            per lubrication regime) when set.
        """
        return {"max_depth_m": self.max_depth, "theta_max_rad": self.theta_max, "x_max_m": self.x_max,
                "max_depth_follower_m": self.max_depth_follower,
                "x_max_follower_m": self.x_max_follower,
                "max_depth_follower_locked_m": self.max_depth_follower_locked,
                "follower_drift_m": self.follower_drift,
                "volume_cam_m3": self.volume_cam_total,
                "volume_follower_m3": self.volume_follower_total,
                "conservation_error": self.conservation_error, "load_error": self.load_error,
                "skipped_angles_rad": [float(self.theta[i]) for i in self.skipped],
                "cycles": self.cycles, "model": self.model,
                **({} if self.coating is None else {"coating": dict(self.coating)}),
                **({} if self.regime is None else
                   {"regime_angles": {str(g): int(n) for g, n in
                                      zip(*np.unique(np.asarray(self.regime).astype(str), return_counts=True),
                                          strict=True)}})}


def _volume(x, h, length, *, periodic: bool) -> float:
    """``l int h dx`` (m^3) of depths ``h`` (m) on the uniform grid ``x`` (m): the rectangle sum
    on a periodic grid (endpoint excluded), the trapezoid rule otherwise."""
    if periodic:
        return float(length * np.sum(h) * (x[1] - x[0] if x.size > 1 else 0.0))
    return float(length * np.trapezoid(h, x))


def _cumulative(theta_closed, f_closed):
    """Cumulative trapezoid of f over theta (same length, starting at 0)."""
    return np.concatenate(([0.0], np.cumsum(0.5 * (f_closed[1:] + f_closed[:-1]) * np.diff(theta_closed))))


def wear_map(source, slip: SlipResult, *, k, length, cycles: float = 1.0, pressure: str = "hertz",
             n_grid: int | None = None, missing: str | None = None, k_factor=None,
             regime=None) -> WearMap:
    """Archard wear map of one revolution from per-angle contact data and a slip model.

    Parameters
    ----------
    source : SweepResult-like or mapping
        Columns ``theta`` [rad] (uniform over one revolution, endpoint excluded), ``a`` [m] and
        ``p0`` [Pa] (``a_hertz``/``p0_hertz``, ``a_fe``/``p0_fe`` or, for ``"axial_peak"``,
        ``a_axial``/``p0_axial`` of the most loaded slice, :mod:`femcam.wear.axial`) and ``Fc``
        [N], shape (n,) each.
    slip : SlipResult
        Sliding and transport speeds on the same angles (:mod:`femcam.wear.slip`).
    k : float
        Dimensional wear coefficient [m^3/(N m)], >= 0.
    length : float
        Face width (contact length) [m], > 0.
    cycles : float
        Number of cam revolutions [-], >= 0.
    pressure : {"hertz", "fe", "axial_peak"}
        Which ``a``/``p0`` columns to read.
    n_grid : int, optional
        Grid points on each surface; default ``perimeter / (a_min / 3)`` clipped to
        [2000, 40000].
    missing : {"raise", "skip", "zero"}, optional
        What to do at angles with ``Fc > 0`` and no pressure, see :func:`contact_columns`
        (default: skip with a warning the ``failed`` rows of a sweep result, raise otherwise).
    k_factor : array_like, shape (n,), optional
        Per-angle multiplier of ``k`` [-] (``k(lambda)/k`` of the lubrication regime,
        from :func:`femcam.assess.wear_factor`); default 1.
    regime : array_like of str, shape (n,), optional
        Lubrication regime per angle; stored only.

    Returns
    -------
    WearMap
        Cam and follower depths [m per revolution and after ``cycles``], volumes [m^3] and
        checks.

    Raises
    ------
    InputError
        On a bad ``k``, ``length``, ``cycles``, ``pressure`` or ``missing``, angles that are not
        one uniform revolution (at least 4), ``slip.theta`` unlike ``theta``, or a missing
        pressure under ``missing="raise"``.
    """
    k = _validate.nonnegative("k", k, "m^3/(N m)")
    length = _validate.positive("length", length, "m")
    cycles = _validate.nonnegative("cycles", cycles, "revolutions")
    n_grid = _validate.optional(_validate.integer, "n_grid", n_grid, 2, "(grid points)")
    _validate.instance("slip", slip, SlipResult)
    skipped: list = []
    theta, a, p0, Fc = contact_columns(source, pressure=pressure, missing=missing, skipped=skipped)
    n = theta.size
    if slip.theta.shape != theta.shape or not np.allclose(slip.theta, theta, atol=1e-12):
        raise _validate.fail("slip.theta", f"{slip.theta.size} angles", "rad",
                      "must equal the contact table's angles")
    dth = np.diff(theta)
    span = theta[-1] - theta[0] + (float(np.mean(dth)) if n > 1 else 0.0)
    if n < 4 or np.any(dth <= 0) or abs(span - 2 * np.pi) > 1e-6:
        raise _validate.fail("theta", f"[{theta[0]:g} .. {theta[-1]:g}] ({n} points)", "rad",
                     "must be increasing, uniform, one revolution, endpoint excluded")
    omega = slip.omega
    v_wear = slip.v_slip
    if k_factor is not None:  # k(lambda)/k of a lubricated scene (femcam.assess.wear_factor)
        v_wear = slip.v_slip * _validate.nonnegative_array("k_factor", k_factor, "")
    # close the revolution: step j runs from theta_j to theta_{j+1} (theta_n = theta_0 + 2 pi)
    thc = np.append(theta, theta[0] + 2 * np.pi)

    def closed(f):
        return np.append(f, f[0])

    xi_c = _cumulative(thc, closed(slip.V_cam) / omega)
    perimeter = float(xi_c[-1])
    xi_f = _cumulative(thc, closed(slip.V_follower) / omega) + float(slip.follower_origin)
    dt = np.diff(thc) / omega

    def mid(f):
        fc = closed(f)
        return 0.5 * (fc[1:] + fc[:-1])

    a_m, p_m, v_m = mid(a), mid(p0), mid(v_wear)  # k(lambda) enters as k x factor x v_slip
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
    drift = 0.0
    if Pf is not None:
        x_f = np.linspace(0.0, Pf, int(n_grid), endpoint=False)
        drift = float(np.mod(xi_f[-1] - xi_f[0], Pf))
    else:
        amax = float(a_pos.max()) if a_pos.size else 0.0
        lo, hi = float(xi_f.min()) - 1.5 * amax, float(xi_f.max()) + 1.5 * amax
        x_f = np.linspace(lo, hi, int(n_grid))
    depth_f = surface_depth(x_f, xi_f, a_m, p_m, v_m, dt, k=k, period=Pf)
    depth_f_cycles = drift_sum(depth_f, Pf, drift, cycles) if Pf is not None else cycles * depth_f

    w_m = hertz_load_per_length(a_m, p_m)
    vol_archard = float(k * np.sum(w_m * length * v_m * dt))
    vol_cam = _volume(x_cam, depth_cam, length, periodic=True)
    vol_f = _volume(x_f, depth_f, length, periodic=Pf is not None)
    cons = abs(vol_cam - vol_archard) / vol_archard if vol_archard > 0 else 0.0
    w = hertz_load_per_length(a, p0)
    on = (Fc > 0) & (w > 0)
    load_err = float(np.max(np.abs(w[on] * length / Fc[on] - 1.0))) if np.any(on) else 0.0
    if pressure == "axial_peak":  # w = w_max by construction: its ratio to Fc / l is physics, not error
        load_err = 0.0
    return WearMap(
        theta=theta, xi_cam=xi_c[:-1], depth_pass=_depth_per_pass(k, w, v_wear, slip.V_cam),
        depth_at_theta=np.interp(xi_c[:-1], x_cam, depth_cam, period=perimeter),
        x_cam=x_cam, depth_cam=depth_cam, x_follower=x_f, depth_follower=depth_f, perimeter=perimeter,
        volume_cam=vol_cam, volume_follower=vol_f, volume_archard=vol_archard, conservation_error=cons,
        k=k, length=length, cycles=cycles, model=slip.model, depth_follower_cycles=depth_f_cycles,
        follower_period=Pf, follower_drift=drift, load_error=load_err, skipped=tuple(skipped),
        k_factor=None if k_factor is None else np.asarray(k_factor, float),
        regime=None if regime is None else np.asarray(regime))


def wear_depth_per_angle(theta, a, p0, Fc, slip: SlipResult, k, *, missing: str = "zero"):
    """Sweep-facing closed form: cam wear depth per revolution at the contact of each angle (m).

    ``k w v_slip / V_cam`` with ``w = pi a p0 / 2``; zero where there is no contact (``Fc <= 0``
    or NaN width). Same length as ``theta``; for the sweep's CSV/VTK wear column.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Cam angles [rad].
    a : array_like, shape (n,)
        Contact half-width [m]; NaN or 0 for no contact.
    p0 : array_like, shape (n,)
        Peak contact pressure [Pa].
    Fc : array_like, shape (n,)
        Contact force [N].
    slip : SlipResult
        Sliding and transport speeds on the same angles.
    k : float
        Dimensional wear coefficient [m^3/(N m)], >= 0.
    missing : {"zero", "nan", "raise"}
        What an angle with ``Fc > 0`` but NaN ``a``/``p0`` (a failed solve) gets: ``"zero"``
        (default, unchanged behaviour), ``"nan"`` (NaN in that row: unknown, not zero), or
        ``"raise"`` (:class:`~femcam.errors.InputError` naming the angles).

    Returns
    -------
    ndarray, shape (n,), float
        Cam wear depth per pass [m per revolution]; ``inf`` where ``V_cam = 0`` with slip.
    """
    _validate.choice("missing", missing, ("zero", "nan", "raise"))
    _validate.finite_array("theta", theta, "rad")
    k = _validate.nonnegative("k", k, "m^3/(N m)")
    _validate.instance("slip", slip, SlipResult)
    a_in, p_in, F_in = (_validate.data_array(n, x, u) for n, x, u in
                        (("a", a, "m"), ("p0", p0, "Pa"), ("Fc", Fc, "N")))   # NaN: a failed solve
    _, a_, p_, _ = contact_columns({"theta": theta, "a": a_in, "p0": p_in, "Fc": F_in},
                                   missing="raise" if missing == "raise" else "zero")
    h = _depth_per_pass(k, hertz_load_per_length(a_, p_), slip.v_slip, slip.V_cam)
    if missing == "nan":
        loaded, have = _loaded_have(*np.broadcast_arrays(a_in, p_in, F_in))
        h = np.where(loaded & ~have, np.nan, h)
    return h
