r"""Finite-length contact over cam angles: the columns the sweep writes.

:func:`finite_length_rows` solves the half-space strip (:mod:`femcam.halfspace.strip`) at each
cam angle, reusing the kernel FFTs across angles and warm-starting the conjugate gradients (from
the previous angle's pressure, or from the cold solution at the nearest anchor angle so that a
row depends on its own angle alone: ``start``), and returns one SI array per column
(:data:`COLUMNS` gives the CSV name with its unit and the factor from SI). It takes the contact
at the angles (force, cam curvature) and the roller radius, and :func:`strip_for` the roller's
finite-length record and the contact pair: the scene is analysed by the caller
(``femcam.scene.finite_case`` bundles the records; this package is below ``femcam.scene``).

The relative radius in the rolling direction is ``1/R = 1/rho + 1/Rr`` (Johnson 1985 eq. 4.44;
``rho < 0`` on a concave flank) and ``E*`` is the three-dimensional contact modulus
``1/E* = sum (1 - nu_i^2)/E_i`` (Johnson eq. 4.22), whatever ``[contact] plane`` says: the
half-space is neither plane strain nor plane stress, it is the body itself. A logarithmic crown is
designed for the largest contact force of the revolution (at its relative radius) unless
``crown_drop_um`` fixes its end drop.
"""

from __future__ import annotations

import math
import threading
import weakref

import numpy as np

from .. import _validate
from .._columns import Column
from ..errors import InputError
from ..materials import effective_modulus
from .crown import RollerProfile
from .strip import FiniteLengthContact

#: SI column -> its :class:`femcam._columns.Column` (CSV name with unit, factor from SI)
COLUMNS = {c.si: c for c in (
    Column("p_axial_peak", "p_axial_peak_MPa", 1e-6, "peak of p(x, y) over the strip"),
    Column("y_peak", "y_axial_peak_mm", 1e3, "axial position of that peak (0 = mid-plane)"),
    Column("L_eff", "L_eff_mm", 1e3, "loaded length (slices with w > 0)"),
    Column("w_max", "w_max_N_per_mm", 1e-3, "most loaded slice (mean over 2b axially)"),
    Column("y_wmax", "y_w_max_mm", 1e3, "axial position of that slice"),
    Column("y_centre", "y_load_centre_mm", 1e3, "load centre int w y dy / F"),
    Column("edge_factor", "edge_factor", 1.0, "p_axial_peak / 2D Hertz p0 at w = F / L"),
    Column("iterations", "hs_iterations", 1.0, "CG iterations"),
    Column("converged", "hs_converged", 1.0),
    Column("flagged", "hs_flagged", 1.0, "any StripResult flag (see ``flags``)"),
)}


#: spacing of the anchor angles of ``start="anchor"`` (rad): every angle is warm-started from the
#: cold solution at the nearest multiple; 10 deg costs ~1.3x the iterations of a warm start from
#: the previous angle of a 1-deg sweep, against ~2.5x for a cold start at every angle
ANCHOR_STEP = math.radians(10.0)
STARTS = ("previous", "anchor", "cold")
_ANCHORS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_ANCHOR_LOCK = threading.Lock()


def anchor_angles(theta) -> np.ndarray:
    """The anchor angles of ``start="anchor"``: the multiples of :data:`ANCHOR_STEP` nearest the
    cam angles ``theta``, each once, ascending (rad).

    Parameters
    ----------
    theta : float or array_like
        Cam angles [rad].

    Returns
    -------
    ndarray, shape (n_anchor,)
        ``j * ANCHOR_STEP`` [rad] for each ``j = round(theta / ANCHOR_STEP)``.

    Examples
    --------
    >>> np.degrees(anchor_angles(np.radians([3.0, 7.0, 12.0]))).round(6)
    array([ 0., 10.])
    """
    th = _validate.finite_array("theta", np.atleast_1d(theta), "rad").ravel()
    return np.array([j * ANCHOR_STEP for j in sorted({round(float(t) / ANCHOR_STEP) for t in th})])


def _anchor_start(fl: FiniteLengthContact, F: float, rho: float, Rr: float):
    """The cold solution's pressure at an anchor angle's contact force ``F`` (N) and cam radius
    of curvature ``rho`` (m) with a roller of radius ``Rr`` (m), cached per strip on those three
    values (all the solution depends on besides the strip), or None where the anchor has no
    Hertzian contact (the angle then starts cold)."""
    key = (F, rho, Rr)
    with _ANCHOR_LOCK:
        cache = _ANCHORS.setdefault(fl, {})
        if key in cache:
            return cache[key]
    inv = 1.0 / rho + 1.0 / Rr
    p = fl.solve(F, 1.0 / inv).p if (F > 0.0 and inv > 0.0) else None
    with _ANCHOR_LOCK:
        cache[key] = p
    return p


def strip_for(finite, pair, Rr: float, *, Fc=None, rho=None, nx: int = 64, ny: int = 128,
              tol: float = 1e-5) -> FiniteLengthContact:
    """The :class:`~femcam.halfspace.strip.FiniteLengthContact` of a roller's finite-length keys
    (defaults: roller width = cam face width = the contact length).

    Parameters
    ----------
    finite : femcam.scene.FiniteLength or None
        The roller's finite-length record (m, rad; ``Scene.finite_length``): its roller profile
        and cam face width. None: a straight roller as wide as the cam, ``pair.length``.
    pair : femcam.scene.ContactPair
        The contact pair: ``cam`` and ``roller`` materials (Pa) and ``length`` (m).
    Rr : float
        Roller radius [m].
    Fc, rho : array_like, optional
        Contact force [N] and cam radius of curvature [m] over one revolution
        (``femcam.scene.finite_case`` analyses 720 angles): a logarithmic crown is designed for
        the largest ``Fc`` at its relative radius ``1/R = 1/rho + 1/Rr``. Needed for a
        logarithmic crown only (ignored otherwise).
    nx, ny : int
        Cells across the contact (rolling direction) and along the axis [-].
    tol : float
        Relative pressure-change tolerance of the conjugate gradients [-].

    Returns
    -------
    FiniteLengthContact
        The strip.

    Raises
    ------
    InputError
        A logarithmic crown without ``Fc`` and ``rho``.
    """
    _validate.positive("tol", tol, "")
    Rr = _validate.positive("Rr", Rr, "m")
    _validate.record("pair", pair, "a femcam.scene.ContactPair", "cam", "roller", "length")
    Fc = _validate.optional(_validate.finite_array, "Fc", Fc, "N")
    rho = _validate.optional(_validate.radius_array, "rho", rho, "m")
    prof = finite.roller_profile() if finite is not None else RollerProfile(width=pair.length)
    E_star = effective_modulus(pair.cam, pair.roller, "strain")
    Q = Rd = None
    if prof.crown == "logarithmic":
        if Fc is None or rho is None:
            raise InputError("crown = logarithmic: the crown is designed for the largest contact force "
                             "of the revolution; give Fc (N) and rho (m) over one revolution")
        Fc, rho = _validate.broadcast(Fc=Fc, rho=rho)
        i = int(np.argmax(Fc))
        Q, Rd = float(Fc[i]), float(1.0 / (1.0 / rho[i] + 1.0 / Rr))
    cam_width = pair.length if finite is None else finite.cam_width
    return FiniteLengthContact(prof, cam_width=cam_width, E_star=E_star, design_load=Q,
                               design_radius=Rd, nx=nx, ny=ny, tol=tol)


def finite_length_rows(strip: FiniteLengthContact, theta, Fc, rho, Rr: float, *, start: str = "previous",
                       anchor_Fc=None, anchor_rho=None) -> dict:
    """Finite-length contact of a roller at cam angles ``theta`` (rad).

    Parameters
    ----------
    strip : FiniteLengthContact
        The strip (e.g. :func:`strip_for`; built once, it reuses its kernel FFTs).
    theta : float or array_like, shape (n_theta,)
        Cam angles [rad].
    Fc : float or array_like, shape (n_theta,)
        Contact force at ``theta`` [N] (``<= 0``: lift-off).
    rho : float or array_like, shape (n_theta,)
        Cam radius of curvature at the contact [m] (< 0 concave, inf flat).
    Rr : float
        Roller radius [m].
    start : {"previous", "anchor", "cold"}, optional
        Where the conjugate gradients of each angle start: the previous angle's pressure
        (default; fewest iterations, but a row then depends on the angles before it); the cold
        solution at the nearest multiple of :data:`ANCHOR_STEP` (cached per strip; a row depends
        on its own angle alone: bit-identical whatever other angles are solved with it, the
        sweep's choice); or cold at every angle. The starts agree within the solver tolerance
        (measured: at most 4.4e-5 relative on ``p_axial_peak`` of the crowned example).
    anchor_Fc, anchor_rho : array_like, shape (n_anchor,), optional
        Contact force [N] and cam radius of curvature [m] at :func:`anchor_angles` of ``theta``
        (``start="anchor"`` only, where they are needed).

    Returns
    -------
    dict of arrays, one value per angle, SI units:
        ``theta`` (rad), ``Fc`` (N), ``R`` (m), the keys of :data:`COLUMNS`, ``flags`` (tuple of
        :class:`~femcam.halfspace.strip.StripResult` flags per angle), ``p_line`` (n_theta x ny,
        Pa: peak pressure of each axial slice), ``w`` (n_theta x ny, N/m: load per unit length of
        each slice), ``y`` (ny, m: slice centres). Angles with no contact force (lift-off, ``Fc <=
        0``) or a non-convex relative curvature get NaN and the flag ``"no_contact"`` /
        ``"non_hertzian"``.
    """
    th = _validate.finite_array("theta", np.atleast_1d(theta), "rad").ravel()
    if start not in STARTS:
        raise _validate.fail("start", start, "", f"must be one of {', '.join(STARTS)}")
    fl = _validate.instance("strip", strip, FiniteLengthContact, "a femcam.halfspace.FiniteLengthContact "
                            "(femcam.halfspace.strip_for)")
    Rr = _validate.positive("Rr", Rr, "m")
    Fc, rho = _validate.broadcast(theta=th, Fc=_validate.finite_array("Fc", Fc, "N"),
                                  rho=_validate.radius_array("rho", rho, "m"))[1:]
    anchors = _anchors(th, anchor_Fc, anchor_rho) if start == "anchor" else None
    with np.errstate(divide="ignore"):
        inv = 1.0 / rho + 1.0 / Rr
    n = th.size
    out = {k: np.full(n, np.nan) for k in COLUMNS}
    R = np.where(inv > 0, 1.0 / np.where(inv > 0, inv, 1.0), np.nan)   # nan: concave-conformal
    out.update(theta=th, Fc=np.array(Fc, float), R=R)
    out["p_line"] = np.full((n, fl.ny), np.nan)
    out["w"] = np.full((n, fl.ny), np.nan)
    out["y"] = fl.y.copy()
    flags = []
    p_prev = None
    for i in range(n):
        F, R = float(Fc[i]), float(out["R"][i])
        if not F > 0.0 or not math.isfinite(R):
            flags.append(("no_contact",) if not F > 0.0 else ("non_hertzian",))
            continue
        p_start = (p_prev if start == "previous" else None) if start != "anchor" else \
            _anchor_start(fl, *anchors[round(float(th[i]) / ANCHOR_STEP)], Rr)
        r = fl.solve(F, R, p_start=p_start)
        p_prev = r.p
        p0 = math.sqrt(F / fl.L * fl.E_star / (math.pi * R))
        for k, v in (("p_axial_peak", r.p_max), ("y_peak", r.y_peak), ("L_eff", r.L_eff),
                     ("w_max", r.w_max), ("y_wmax", r.y_wmax), ("y_centre", r.y_centre),
                     ("edge_factor", r.p_max / p0), ("iterations", r.iterations),
                     ("converged", float(r.converged)), ("flagged", float(bool(r.flags)))):
            out[k][i] = v
        out["p_line"][i] = r.p_line
        out["w"][i] = r.w
        flags.append(r.flags)
    out["flags"] = tuple(flags)
    return out


def _anchors(th: np.ndarray, Fc, rho) -> dict:
    """``round(angle / ANCHOR_STEP) -> (Fc, rho)`` (N, m) of the anchors of ``th`` (rad) from
    the arrays given at :func:`anchor_angles` ``(th)``."""
    angles = anchor_angles(th)
    if Fc is None or rho is None:
        raise InputError('start = "anchor": give anchor_Fc (N) and anchor_rho (m), the contact at '
                         "anchor_angles(theta)")
    Fc = _validate.finite_array("anchor_Fc", np.atleast_1d(Fc), "N").ravel()
    rho = _validate.radius_array("anchor_rho", np.atleast_1d(rho), "m").ravel()
    if Fc.shape != angles.shape or rho.shape != angles.shape:
        raise InputError(f"anchor_Fc has shape {Fc.shape}, anchor_rho {rho.shape}: give one value at each "
                         f"of the {angles.size} anchor_angles(theta)")
    return {round(float(a) / ANCHOR_STEP): (float(f), float(r))
            for a, f, r in zip(angles, Fc, rho, strict=True)}


def to_csv_columns(rows: dict) -> dict:
    """The :data:`COLUMNS` of ``rows`` under their CSV names, converted to the CSV units.

    Parameters
    ----------
    rows : dict of array_like
        SI columns, e.g. from :func:`finite_length_rows`; keys not in :data:`COLUMNS` are dropped.

    Returns
    -------
    dict of ndarray
        CSV column name (with unit, e.g. ``p_axial_peak_MPa``) -> values in that unit.

    Examples
    --------
    >>> to_csv_columns({"L_eff": np.array([0.01])})
    {'L_eff_mm': array([10.])}
    """
    return {COLUMNS[k].csv: np.asarray(v) * COLUMNS[k].factor for k, v in rows.items() if k in COLUMNS}


def has_finite_length(finite, length: float) -> bool:
    """True when the scene asks for the finite-length contact: a crown, edge radius or
    misalignment key, or a roller or cam width that differs from the 2D contact length. (The
    scene gives both widths for every roller scene with a face width, so a record alone does
    not mean asked for.)

    Parameters
    ----------
    finite : femcam.scene.finite.FiniteLength or None
        The scene's finite-length keys (``Scene.finite_length``; m, rad).
    length : float
        The 2D contact length (m; ``Scene.length``).

    Returns
    -------
    bool
        The finite-length (half-space) contact applies: the sweep's ``halfspace`` provider and
        the wear map's most loaded slice.
    """
    length = _validate.positive("length", length, "m")
    if finite is None:
        return False
    return bool(finite.shaped) or any(w != length for w in (finite.roller_width, finite.cam_width))
