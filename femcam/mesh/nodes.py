"""From the meshed gmsh model to a :class:`BodyMesh`: node and triangle extraction
(:func:`gmsh_nodes`, :func:`extract`), the fine-zone snapping (:func:`finish_body`), the
counter-clockwise ordering (:func:`ccw`) and the roller's mirror image (:func:`mirror`)."""

from __future__ import annotations

import numpy as np

from .. import _validate
from ..errors import FemcamError
from .geometry import BodyLayout, surface_height
from .options import BodyMesh, PhysicalGroup


def gmsh_nodes(gmsh, surface):
    """Nodes and triangles of the meshed gmsh model.

    Parameters
    ----------
    gmsh : module
        The gmsh module of an open :func:`~femcam.mesh.gmsh_session` with a meshed model.
    surface : int
        gmsh tag of the surface whose triangles are returned (-1: all surfaces).

    Returns
    -------
    points : ndarray, shape (N, 2)
        Node coordinates (m).
    index : ndarray of int
        Maps a gmsh node tag to its 0-based row of ``points`` (-1 where unused).
    triangles : ndarray of int, shape (T, 3)
        Triangles of ``surface`` as rows of ``points``.
    """
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    pts = xyz.reshape(-1, 3)[:, :2]
    index = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(tags.size)
    _, _, ntri = gmsh.model.mesh.getElements(2, surface)
    tri = index[np.asarray(ntri[0], dtype=np.int64)].reshape(-1, 3)
    return pts, index, tri


def _physical_groups(gmsh, index, known: dict) -> dict:
    """``{name: (dim, tag, elements (n, k))}`` of the meshed model's physical groups.

    ``known`` maps ``(dim, entity)`` to that entity's elements read already (the surface's
    triangles): a group of that one entity takes the same array, not a second copy.
    """
    groups = {}
    for gdim, gtag in gmsh.model.getPhysicalGroups():
        blocks = []
        for ent in gmsh.model.getEntitiesForPhysicalGroup(gdim, gtag):
            if (gdim, int(ent)) in known:
                blocks.append(known[gdim, int(ent)])
                continue
            types, _, ntags = gmsh.model.mesh.getElements(gdim, int(ent))
            for et, nt in zip(types, ntags, strict=True):
                nn = gmsh.model.mesh.getElementProperties(et)[3]
                blocks.append(index[np.asarray(nt, dtype=np.int64)].reshape(-1, nn))
        elements = blocks[0] if len(blocks) == 1 else np.concatenate(blocks)
        groups[gmsh.model.getPhysicalName(gdim, gtag)] = (gdim, int(gtag), elements)
    return groups


def extract(gmsh, surface, arcs, bottom):
    """Nodes, triangles, node sets and physical groups of the meshed model (0-based indices).

    Parameters
    ----------
    gmsh : module
        gmsh with the body's meshed model.
    surface : int
        gmsh tag of the surface whose triangles are taken (-1: all surfaces).
    arcs : list of int
        gmsh tags of the three surface arcs (``arcs[1]`` the fine zone).
    bottom : int
        gmsh tag of the fixed bottom line.

    Returns
    -------
    tuple
        ``(points (N, 2) m, triangles (T, 3), fine, surface, fixed, groups)``: the node sets
        of the fine arc ``arcs[1]``, of all ``arcs`` and of ``bottom``; ``groups`` as
        ``{name: (dim, tag, elements)}``.
    """
    pts, index, tri = gmsh_nodes(gmsh, surface)

    def curve_nodes(curves):
        out = []
        for cv in curves:
            nt = gmsh.model.mesh.getNodes(1, cv, includeBoundary=True)[0]
            out.append(index[nt.astype(np.int64)])
        return _unique(np.concatenate(out), pts.shape[0])

    # one surface: its physical group is the triangles read above (one getElements, one array)
    groups = _physical_groups(gmsh, index, {(2, int(surface)): tri} if surface > 0 else {})
    return pts, tri, curve_nodes([arcs[1]]), curve_nodes(arcs), curve_nodes([bottom]), groups


def finish_body(lay: BodyLayout, pts, tri, fine, surf, fixed, groups) -> BodyMesh:
    """Drop unreferenced nodes, snap the fine zone to the exact arc, orient triangles.

    The fine-zone vertices are moved to the uniform abscissae ``x_i = -xf + i h`` on the exact
    arc so that the cam and roller contact vertices pair one to one.

    Parameters
    ----------
    lay : BodyLayout
        The body's sizes (m).
    pts, tri, fine, surf, fixed, groups
        What :func:`extract` returns: points (N, 2) m, triangles (T, 3), node sets of the fine
        arc, the surface and the support, ``{name: (dim, tag, elements)}``.

    Returns
    -------
    BodyMesh
        In the cam orientation (below ``y = 0``).

    Raises
    ------
    FemcamError
        gmsh returned another number of fine-zone nodes than ``n_fine + 1``.
    """
    # drop unreferenced nodes (arc centres, geometry-only points)
    used = _unique(tri, pts.shape[0])
    renum = np.full(pts.shape[0], -1, dtype=np.int64)
    renum[used] = np.arange(used.size)
    pts = pts[used]
    tri_in, tri = tri, renum[tri]
    fine, surf, fixed = renum[fine], renum[surf], renum[fixed]
    # a group holding the triangles array itself (extract's one surface) shares its result
    groups = {k: (d, t, tri if e is tri_in else renum[e]) for k, (d, t, e) in groups.items()}
    # snap fine-zone vertices to the uniform abscissae on the exact arc
    n_fine = lay.n_fine
    order = np.argsort(pts[fine, 0])
    fine = fine[order]
    if fine.size != n_fine + 1:
        raise FemcamError(f"gmsh returned {fine.size} fine-zone nodes, expected {n_fine + 1}")
    xs = -lay.xf + lay.h * np.arange(n_fine + 1)
    pts[fine, 0] = xs
    pts[fine, 1] = -surface_height(xs, lay.R)
    # counter-clockwise triangles
    tri_r, tri = tri, ccw(pts, tri)
    phys = {k: PhysicalGroup(name=k, dim=d, tag=t,
                             elements=(tri if e is tri_r else ccw(pts, e) if d == 2 else e).T.copy())
            for k, (d, t, e) in groups.items()}
    return BodyMesh(name=lay.name, points=pts.T.copy(), triangles=tri.T.copy(), fixed=fixed,
                    contact=fine, contact_x=xs, surface=surf, L=float(lay.L), R=float(lay.R),
                    groups=phys)


def _unique(idx: np.ndarray, n: int) -> np.ndarray:
    """``np.unique(idx)`` for node indices in ``[0, n)``: a counting pass (the same sorted
    int64 array; numpy's hash-based unique took milliseconds on a body's triangles)."""
    return np.flatnonzero(np.bincount(np.asarray(idx, dtype=np.int64).ravel(), minlength=n))


def ccw(pts: np.ndarray, tri: np.ndarray) -> np.ndarray:
    """Triangles reordered counter-clockwise.

    Parameters
    ----------
    pts : ndarray, shape (N, 2)
        Node coordinates (m).
    tri : ndarray of int, shape (T, 3)
        Triangles (rows of ``pts``).

    Returns
    -------
    ndarray of int, shape (T, 3)
        A copy, with the clockwise triangles' last two nodes swapped.
    """
    pts = _validate.finite_array("pts", pts, "m")
    if pts.ndim != 2 or pts.shape[1] != 2:
        raise _validate.fail("pts", f"shape {pts.shape}", "m", "must have the shape (N, 2)")
    tri = np.array(tri, dtype=int)
    d = pts[tri]
    det = (d[:, 1, 0] - d[:, 0, 0]) * (d[:, 2, 1] - d[:, 0, 1]) - \
          (d[:, 2, 0] - d[:, 0, 0]) * (d[:, 1, 1] - d[:, 0, 1])
    tri[det < 0] = tri[det < 0][:, [0, 2, 1]]
    return tri


def mirror(b: BodyMesh) -> BodyMesh:
    """The body mirrored to ``y >= 0`` (``y -> -y``, triangles kept counter-clockwise).

    Parameters
    ----------
    b : BodyMesh
        A body meshed in the cam orientation (the roller).

    Returns
    -------
    BodyMesh
        A new body; node numbering and node sets unchanged.
    """
    pts = b.points.copy()
    pts[1] *= -1.0
    tri = b.triangles[[0, 2, 1]].copy()
    groups = {k: PhysicalGroup(name=g.name, dim=g.dim, tag=g.tag,
                               elements=g.elements[[0, 2, 1]].copy() if g.dim == 2 else g.elements)
              for k, g in b.groups.items()}
    return BodyMesh(name=b.name, points=pts, triangles=tri, fixed=b.fixed, contact=b.contact,
                    contact_x=b.contact_x, surface=b.surface, L=b.L, R=b.R, groups=groups,
                    coating=b.coating)
