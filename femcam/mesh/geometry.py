"""Body outline and size field in gmsh: the exact surface arc (:func:`surface_height`), the
layout shared by the plain and the coated body (:class:`BodyLayout`), the outline
(:func:`outline`) and the graded size field (:func:`size_field`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError
from .options import MeshOptions


def surface_height(x, R):
    r"""Depth of a circular arc of signed radius ``R`` below its tangent at x = 0.

    .. math:: \delta(x) = R - \sqrt{R^2 - x^2} = \frac{\kappa x^2}{1 + \sqrt{1 - \kappa^2 x^2}},
              \quad \kappa = 1/R

    exact for every ``R`` including ``inf`` (flat, 0) and ``R < 0`` (concave, negative).

    Parameters
    ----------
    x : array_like
        Abscissa along the common tangent (m).
    R : float
        Signed arc radius (m; < 0 concave, ``inf`` flat).

    Returns
    -------
    ndarray
        ``delta(x)`` (m), shape of ``x``.

    >>> round(float(surface_height(0.006, 0.01)) * 1e3, 6)
    2.0
    """
    x = _validate.finite_array("x", x, "m")
    R = _validate.radius("R", R, "m")
    k = 0.0 if math.isinf(R) else 1.0 / R
    return k * x**2 / (1.0 + np.sqrt(np.maximum(1.0 - (k * x) ** 2, 0.0)))


def body_size(R: float, cap: float | None, default_cap: float) -> float:
    """Body size ``L = min(|R|, cap)``.

    Parameters
    ----------
    R : float
        Signed surface radius (m; inf flat).
    cap : float or None
        Size cap (m); None: ``default_cap``.
    default_cap : float
        Cap used when ``cap`` is None (m; inf: none).

    Returns
    -------
    float
        L (m).
    """
    L = abs(R) if math.isfinite(R) else math.inf
    c = cap if cap is not None else default_cap
    return min(L, c)


@dataclass(frozen=True)
class BodyLayout:
    """Sizes of one body's mesh, shared by the plain and the coated body (all in m).

    Parameters
    ----------
    name : str
        The body (``"cam"`` or ``"roller"``).
    R, L : float
        Signed surface radius and body size (m).
    a_ref : float
        Reference half-width (m).
    h : float
        Fine element size ``a_ref / a_over_h`` (m).
    n_fine : int
        Number of fine elements along ``|x| <= xf``.
    xf : float
        Half-length of the fine zone, ``n_fine h / 2`` (m).
    W : float
        Half-width of the surface arc, ``0.9 L`` (m).
    lc : float
        Largest element size, ``max_size_fraction L`` (m).
    """

    name: str
    R: float
    L: float
    a_ref: float
    h: float
    n_fine: int
    xf: float
    W: float
    lc: float


def body_layout(name: str, R: float, L: float, a_ref: float, opts: MeshOptions) -> BodyLayout:
    """The :class:`BodyLayout` of one body.

    Parameters
    ----------
    name : str
        The body (``"cam"`` or ``"roller"``).
    R : float
        Signed surface radius (m; < 0 concave, inf flat).
    L : float
        Body size (m).
    a_ref : float
        Reference half-width (m).
    opts : MeshOptions
        Mesh options (fine zone, element sizes).

    Returns
    -------
    BodyLayout
        ``h``, ``n_fine``, ``xf`` (a whole number of ``h``), ``W = 0.9 L``, ``lc`` (m).

    Raises
    ------
    InputError
        The body is too small for the fine zone.
    """
    _validate.radius("R", R, "m")
    L = _validate.positive("L", L, "m")
    _validate.instance("opts", opts, MeshOptions)
    a_ref = _validate.positive("a_ref", a_ref, "m")
    h = a_ref / opts.a_over_h
    xf = opts.fine_half_width * a_ref
    n_fine = int(round(2 * xf / h))
    xf = 0.5 * n_fine * h  # exact multiple of h
    W = 0.9 * L
    if W <= xf * 1.5:
        raise InputError(f"[follower] base_radius_mm, roller_radius_mm and [program] give the {name} a "
                         f"radius of curvature (body size) of {L * 1e3:.4g} mm here: too small for the fine "
                         f"mesh zone |x| <= {xf * 1e3:.4g} mm around a contact half-width of "
                         f"{a_ref * 1e3:.4g} mm (set by the contact force, [materials.*] E_GPa, nu and "
                         "[follower] face_width_mm); give a larger base_radius_mm or roller_radius_mm, a "
                         "longer beta_deg or smaller lift_mm, a wider face_width_mm or a lighter load "
                         "([dynamics] preload_N, spring_N_per_m) (API: MeshOptions.fine_half_width)")
    return BodyLayout(name=name, R=R, L=L, a_ref=a_ref, h=h, n_fine=n_fine, xf=xf, W=W,
                      lc=L * opts.max_size_fraction)


def outline(gmsh, lay: BodyLayout):
    """The body's outline: three surface arcs (the middle one is the fine zone ``|x| <= xf``),
    the sides and the fixed bottom at ``y = -L``.

    Parameters
    ----------
    gmsh : module
        gmsh with the body's (empty) current model.
    lay : BodyLayout
        The body's sizes (m).

    Returns
    -------
    (list of int, int, int)
        gmsh tags ``(arcs, bottom, surface)``.

    Raises
    ------
    InputError
        The arc reaches the fixed support.
    """
    geo = gmsh.model.geo
    R, L, W, xf, lc = lay.R, lay.L, lay.W, lay.xf, lay.lc
    ys = -surface_height(np.array([-W, -xf, xf, W]), R)
    if not (ys[3] > -L + 1e-12 * L and ys[0] > -L + 1e-12 * L):
        raise InputError(f"body {lay.name}: arc reaches the fixed support; use a larger |R| or smaller W")
    p = [geo.addPoint(x, y, 0.0, lc) for x, y in zip((-W, -xf, xf, W), ys, strict=True)]
    if math.isinf(R):
        arcs = [geo.addLine(p[0], p[1]), geo.addLine(p[1], p[2]), geo.addLine(p[2], p[3])]
    else:
        c = geo.addPoint(0.0, -R, 0.0, lc)
        arcs = [geo.addCircleArc(p[i], c, p[i + 1]) for i in range(3)]
    br = geo.addPoint(W, -L, 0.0, lc)
    bl = geo.addPoint(-W, -L, 0.0, lc)
    right = geo.addLine(p[3], br)
    bottom = geo.addLine(br, bl)
    left = geo.addLine(bl, p[0])
    cl = geo.addCurveLoop(arcs + [right, bottom, left])
    return arcs, bottom, geo.addPlaneSurface([cl])


def size_field(gmsh, fine_curve: int, lay: BodyLayout, opts: MeshOptions) -> None:
    """Set the background size field: ``h`` near the fine curve, growing to ``lc``.

    The size is ``h`` within ``fine_depth * a_ref`` of the fine curve and grows with slope
    ``growth`` up to ``lc``; size-from-points/curvature/boundary are switched off (they
    override the field). The curves' nodes are placed by integrating the field to gmsh's
    ``Mesh.LcIntegrationPrecision`` 1e-7 (the default 1e-9 costs ~10 ms more a body): against
    1e-9 a node moves by ~1e-4 ``h``, or a curve whose integrated size lies near a rounding
    point gains or loses a node; the triangles inside then differ as after any perturbation
    (node count within 0.3 %, the same angles).

    Parameters
    ----------
    gmsh : module
        gmsh with the body's synchronised geometry.
    fine_curve : int
        gmsh tag of the fine-zone curve.
    lay : BodyLayout
        The body's sizes (m).
    opts : MeshOptions
        ``fine_depth`` (x a_ref) and ``growth`` (-).
    """
    h, lc, a_ref = lay.h, lay.lc, lay.a_ref
    f = gmsh.model.mesh.field
    fd = f.add("Distance")
    f.setNumbers(fd, "CurvesList", [fine_curve])
    f.setNumber(fd, "Sampling", max(2 * lay.n_fine, 100))
    ft = f.add("Threshold")
    f.setNumber(ft, "InField", fd)
    f.setNumber(ft, "SizeMin", h)
    f.setNumber(ft, "SizeMax", lc)
    f.setNumber(ft, "DistMin", opts.fine_depth * a_ref)
    f.setNumber(ft, "DistMax", opts.fine_depth * a_ref + (lc - h) / opts.growth)
    f.setAsBackgroundMesh(ft)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.Algorithm", 6)  # Frontal-Delaunay: good quality graded meshes
    gmsh.option.setNumber("Mesh.LcIntegrationPrecision", 1e-7)
    gmsh.option.setNumber("Mesh.ElementOrder", 1)
