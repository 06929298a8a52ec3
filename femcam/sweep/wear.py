r"""Archard wear columns of the sweep: the same data goes into the sweep's VTK and CSV.

Per angle, with the wear module's own functions used as they are:

* ``v_slip`` (m/s) and ``V_cam`` (m/s, speed of the contact over the cam surface) from
  :func:`femcam.wear.slip.follower_slip` with the scene's ``[wear]`` slip model (roller:
  slide-to-roll ratio ``srr``, default 2 %, or the inertia-limited model);
* ``wear_depth`` (m per revolution): :func:`femcam.wear.map.wear_depth_per_angle`, i.e. the
  per-pass Archard closed form ``k w v_slip / V_cam`` with ``w = pi a p0 / 2`` -- the depth the
  contact leaves on the cam surface point it passes over at that angle, in one revolution;
* ``wear_source``: which pressure it used -- ``"fe"`` (the FE's a and p0, when the FE answered),
  ``"hertz"`` (method hertz, or the FE failed at that angle but Hertz applies), ``"none"``
  (no contact: depth 0; or no pressure at all, e.g. an undercut row: depth NaN).

``k`` (m^3/(N m)) comes from the scene's ``[wear]`` table through
:func:`femcam.wear.options.wear_coefficient_info` (``k_mm3_per_N_m``, or ``K`` with the cam
hardness; default K = 1e-8, H = 2000 N/mm^2 as seed 000); the slip model's keys come from the
same checked table through :func:`femcam.wear.options.slip_kwargs`, as in ``femcam wear map``.

The per-pass depth depends on the pressure only through ``w = int p dx``; with the FE source it is
the elliptic fit's ``pi a_fe p0_fit / 2``, which differs from the FE's exact ``F/l`` by about
``err_a + err_p0`` (~1 % at a_over_h = 10), the same convention as ``femcam wear map --source fe``.
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np

from ..errors import FemcamError
from ..wear.map import wear_depth_per_angle
from ..wear.options import slip_kwargs, wear_coefficient_info
from ..wear.slip import SlipResult, follower_slip


@dataclasses.dataclass(frozen=True)
class WearSetup:
    """What the chunks need for the wear columns: ``k`` and the slip of every angle.

    Parameters
    ----------
    k : float
        Archard coefficient (m^3/(N m)); NaN when wear is not computed.
    slip : femcam.wear.slip.SlipResult or None
        Slip over all sweep angles (arrays of shape (n,)); None: wear not computed.
    model : str
        The slip model's name.
    error : str
        Why wear is not computed ("" otherwise).
    """

    k: float
    slip: SlipResult | None
    model: str = ""
    error: str = ""

    def to_dict(self) -> dict:
        """JSON-able record for the provenance.

        Returns
        -------
        dict
            ``k_m3_per_N_m`` (Archard k [m^3/(N m)]), ``slip_model``, ``depth`` (how the depth
            column is defined) and ``error`` (only when wear is not computed).
        """
        out = {"k_m3_per_N_m": self.k, "slip_model": self.model,
               "depth": "per revolution at the contact point: k (pi a p0 / 2) v_slip / V_cam"}
        if self.error:
            out["error"] = self.error
        return out

    def chunk(self, a: int, b: int) -> SlipResult | None:
        """The slip of rows ``a:b`` (a chunk).

        Parameters
        ----------
        a, b : int
            Row range.

        Returns
        -------
        femcam.wear.slip.SlipResult or None
            None if wear is not computed.
        """
        if self.slip is None:
            return None
        s = self.slip
        return dataclasses.replace(s, theta=s.theta[a:b], v_slip=s.v_slip[a:b], V_cam=s.V_cam[a:b],
                                   V_follower=s.V_follower[a:b],
                                   **{n: (getattr(s, n)[a:b] if getattr(s, n) is not None else None)
                                      for n in ("Omega", "Omega_req", "slipping")})


def _uniform_revolution(theta) -> bool:
    t = np.asarray(theta, float)
    if t.size < 4:
        return False
    d = np.diff(t)
    return bool(np.all(d > 0) and np.ptp(d) <= 1e-9 * d.mean()
                and abs(t[-1] - t[0] + d.mean() - 2 * np.pi) <= 1e-9)


def slip_for_angles(scene, theta, st):
    """:class:`femcam.wear.slip.SlipResult` at the sweep angles, from the scene's slip model.

    The inertia-limited roller model integrates over one revolution on a uniform grid; for
    other angle sets it runs on a 0.5 deg grid and its speeds are interpolated (periodically).

    Parameters
    ----------
    scene : femcam.scene.Scene
    theta : ndarray, shape (n,)
        Cam angles (rad).
    st : femcam.scene.SceneState
        ``scene.analyse(theta)``.

    Returns
    -------
    femcam.wear.slip.SlipResult
        Arrays of shape (n,) (m/s).
    """

    # the checked [wear] table, as femcam wear map / evolution_case
    kw = slip_kwargs(scene.wear, omega=scene.omega, mu=scene.mu, follower=scene.follower)
    model = kw["roller_model"]
    theta = np.asarray(theta, float)
    if model != "inertia" or _uniform_revolution(theta):
        return follower_slip(scene.follower, theta, st.s, st.s1, st.s2,
                             Fc=np.clip(st.Fc, 0.0, None), **kw)
    grid = np.radians(np.arange(0.0, 360.0, 0.5))
    g = scene.analyse(grid)
    sg = follower_slip(scene.follower, grid, g.s, g.s1, g.s2, Fc=np.clip(g.Fc, 0.0, None), **kw)
    tw = np.mod(theta, 2 * np.pi)

    def at(v):
        return np.interp(tw, grid, v, period=2 * np.pi)

    return dataclasses.replace(sg, theta=theta, v_slip=at(sg.v_slip), V_cam=at(sg.V_cam),
                               V_follower=at(sg.V_follower),
                               **dict.fromkeys(("Omega", "Omega_req", "slipping")),
                               message=(sg.message + "; " if sg.message else "")
                               + "interpolated from a 0.5 deg revolution")


def wear_setup(scene, theta, st) -> WearSetup:
    """k and the slip for all sweep angles.

    Where the wear model refuses the scene for a documented reason (a
    :class:`~femcam.errors.FemcamError`, e.g. a follower without a slip model) the wear columns
    are NaN, the reason is recorded in the provenance and warned about: wear never stops a
    contact sweep. Programming errors (AttributeError, TypeError, ...) propagate.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (its ``[wear]`` table and follower).
    theta : ndarray, shape (n,)
        Cam angles [rad].
    st : femcam.scene.SceneState
        ``scene.analyse(theta)``.

    Returns
    -------
    WearSetup
        ``k`` [m^3/(N m)] and the slip at the ``n`` angles, or NaN/None and the reason.
    """
    try:
        k = float(wear_coefficient_info(scene.wear, scene.cam.hardness)[0])
        slip = slip_for_angles(scene, theta, st)
    except FemcamError as exc:
        msg = f"wear columns not computed: {type(exc).__name__}: {exc}"
        warnings.warn(msg, stacklevel=3)
        return WearSetup(k=float("nan"), slip=None, error=msg)
    return WearSetup(k=k, slip=slip, model=str(slip.model))


def fill_wear(rows, slip, k: float, method: str) -> None:
    """Fill ``v_slip``, ``V_cam``, ``wear_depth`` and ``wear_source`` of a chunk's rows.

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table (modified in place).
    slip : femcam.wear.slip.SlipResult or None
        Slip at the chunk's angles.
    k : float
        Archard k (m^3/(N m)).
    method : str
        ``"fe"`` or ``"hertz"``.
    """
    n = rows.theta.size
    src = np.full(n, "none", dtype=object)
    if slip is None:
        rows.wear_source = src
        return
    rows.v_slip[:] = slip.v_slip
    rows.V_cam[:] = slip.V_cam
    status = np.asarray(rows.status).astype(str)
    fe_ok = (status == "ok") & np.isfinite(rows.p0_fit) & np.isfinite(rows.a_fe) \
        if method == "fe" else np.zeros(n, bool)
    hz = (status == "ok") | (status == "failed")
    hz &= ~fe_ok & np.isfinite(rows.p0_hertz) & np.isfinite(rows.a_hertz) & (rows.Fc > 0)
    a = np.where(fe_ok, rows.a_fe, np.where(hz, rows.a_hertz, 0.0))
    p0 = np.where(fe_ok, rows.p0_fit, np.where(hz, rows.p0_hertz, 0.0))  # the fit's pair
    F = np.where(fe_ok | hz, rows.Fc, 0.0)
    depth = np.asarray(wear_depth_per_angle(rows.theta, a, p0, F, slip, k), dtype=float)
    lost = ~(fe_ok | hz) & (status != "liftoff")  # contact but no pressure: unknown, not zero
    rows.wear_depth[:] = np.where(lost, np.nan, depth)
    src[fe_ok] = "fe"
    src[hz] = "hertz"
    rows.wear_source = src
