"""3D FE reference (gmsh tetrahedra, scikit-fem) for the finite-length half-space contact.

One roller-cam contact of seed 002's dwell (F = 1500 N, R = 5 mm, steel on steel, both bodies
10 mm wide, ending at the same plane): a rigid indenter with the relative gap ``x^2/2R + c(y)``
pressed frictionlessly onto ONE elastic block of modulus ``E_b = E* (1 - nu^2)``, which has the
same combined compliance ``1/E*`` as the two steel bodies (identical materials, frictionless: no
Dundurs coupling; Johnson 1985 §5.1). Two blocks, 10 mm deep and 10 mm to the side:

* ``free end``: the block ends at ``y = L/2`` with a free face, as the real bodies do;
* ``continued``: the block runs on 5 mm past the end of the loaded length, which is what the
  half-space model assumes.

``continued`` against the half-space is the FE's own error (finite block, mesh); ``free end``
against the half-space is the free-end error of the half-space model.

Mesh: ``meshes/halfspace_block3d.toml`` (parameters) / ``.geo`` (the same geometry for the gmsh
GUI): a quarter block (symmetry ``x = 0`` and ``y = 0``, bottom fixed) whose top face is split at
the contact strip ``0 <= x <= 2b, 0 <= y <= L/2``; linear tetrahedra graded from ``0.30 b`` on the
strip (``0.22 b`` over its last 0.3 mm, the roller end) by a cascade of gmsh Box fields. Contact
(default ``--method dirichlet``): an active set on the full FE model, the active strip nodes
held at ``u_z = h - alpha`` (Dirichlet), ``alpha`` from the load balance by linearity, tensile
nodes released and penetrating nodes added, one SuperLU factorisation per iteration (5-7).
``--method condense`` condenses the strip's nodes to a compliance matrix (one factorisation,
1757 back-solves) and solves femcam's primal-dual active set
(:func:`femcam.fe.contact.solve_lcp`) on it: the same nodal forces, 5-15 x slower (the
multi-right-hand-side back-solves dominate).

Comparison like with like: the half-space pressure (64 x 256 cells) is turned into consistent
nodal forces on the same strip triangles (edge-midpoint rule, exact for quadratics), and the FE
and half-space nodal forces are summed over the same node sets: mid-length ``|y| < 1 mm`` and the
last 0.25 mm at the end, reported as loads per unit length in units of ``F/L``.

Run:  python benchmarks/bench_halfspace_fe3d_gmsh.py [--cases log-free,log-cont,none-free,none-cont]
      [--write-msh DIR]
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import resource
import time
from pathlib import Path

import numpy as np
import scipy.sparse.linalg as spla
import tomllib
from scipy.interpolate import RegularGridInterpolator

from femcam.fe.contact import solve_lcp
from femcam.halfspace.crown import RollerProfile
from femcam.halfspace.strip import FiniteLengthContact

ROOT = Path(__file__).resolve().parents[1]
PARAMS = tomllib.loads((ROOT / "meshes" / "halfspace_block3d.toml").read_text())
E_STAR, NU = 210e9 / (2 * 0.91), 0.3
F, R, L = 1500.0, 0.005, 0.010
B = math.sqrt(4 * F / L * R / (math.pi * E_STAR))       # 2D Hertz half-width (Johnson eq. 4.45)
CASES = {"log-free": ("logarithmic", 0.0), "log-cont": ("logarithmic", 5e-3),
         "none-free": ("none", 0.0), "none-cont": ("none", 5e-3)}


def build_mesh(extend: float, write: Path | None = None, scale: float = 1.0):
    """gmsh tetrahedral quarter block (m): ``(p (3, N), t (4, M))``; ``scale`` multiplies the
    strip and end sizes (mesh convergence)."""
    import gmsh  # lazy: mesh generator only for this benchmark

    g, m = PARAMS["geometry"], PARAMS["mesh"]
    mm = 1e-3
    b, Lh, X, D = B / mm, L / 2 / mm, g["side_mm"], g["depth_mm"]
    sb, ext = g["strip_over_b"], extend / mm
    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("block")
        occ = gmsh.model.occ
        box = occ.addBox(0, 0, -D, X, Lh + ext, D)
        rect = occ.addRectangle(0, 0, 0, sb * b, Lh)
        occ.fragment([(3, box)], [(2, rect)])
        occ.synchronize()
        for name in ("MeshSizeFromPoints", "MeshSizeFromCurvature", "MeshSizeExtendFromBoundary"):
            gmsh.option.setNumber(f"Mesh.{name}", 0)
        gmsh.option.setNumber("Mesh.Algorithm3D", m["algorithm3d"])
        fld = gmsh.model.mesh.field
        ids = []
        for k in range(10):                      # h + growth * distance: a cascade of boxes
            d = 0.0 if k == 0 else 2.0 ** (k - 1) * b
            f = fld.add("Box")
            for key, val in (("VIn", scale * m["h_contact_over_b"] * b + m["growth"] * d),
                             ("VOut", m["h_max_mm"]), ("XMin", -1.0), ("XMax", sb * b + d),
                             ("YMin", -1.0), ("YMax", Lh + d),
                             ("ZMin", -b - d), ("ZMax", 1.0), ("Thickness", d + b)):
                fld.setNumber(f, key, val)
            ids.append(f)
        f = fld.add("Box")
        band = m["end_band_mm"]
        for key, val in (("VIn", scale * m["h_end_over_b"] * b), ("VOut", m["h_max_mm"]), ("XMin", -1.0),
                         ("XMax", sb * b), ("YMin", Lh - band), ("YMax", Lh + band), ("ZMin", -b),
                         ("ZMax", 1.0), ("Thickness", b)):
            fld.setNumber(f, key, val)
        ids.append(f)
        fmin = fld.add("Min")
        fld.setNumbers(fmin, "FieldsList", ids)
        fld.setAsBackgroundMesh(fmin)
        gmsh.model.mesh.generate(3)
        if write is not None:
            gmsh.write(str(write / f"halfspace_block3d_ext{ext:g}mm.msh"))
        tags, xyz, _ = gmsh.model.mesh.getNodes()
        _, ntags = gmsh.model.mesh.getElementsByType(4)
    finally:
        gmsh.finalize()
    idx = np.full(int(tags.max()) + 1, -1)
    idx[tags.astype(int)] = np.arange(tags.size)
    t = idx[ntags.astype(int)].reshape(-1, 4).T
    used = np.unique(t)
    ren = np.full(tags.size, -1)
    ren[used] = np.arange(used.size)
    return xyz.reshape(-1, 3).T[:, used] * mm, ren[t]


def fe_model(p, t):
    """Stiffness (csc), fixed DOFs, strip nodes and their ``u_z`` DOFs, DOF count, mesh."""
    from skfem import Basis, ElementTetP1, ElementVector, MeshTet, asm  # lazy: FE benchmark only
    from skfem.models.elasticity import lame_parameters, linear_elasticity

    mesh = MeshTet(p, t)
    ib = Basis(mesh, ElementVector(ElementTetP1()))
    K = asm(linear_elasticity(*lame_parameters(E_STAR * (1 - NU**2), NU)), ib).tocsc()
    zb = p[2].min()
    dofs = ib.get_dofs
    fix = np.unique(np.concatenate([dofs(lambda x: np.isclose(x[2], zb)).all(),
                                    dofs(lambda x: np.isclose(x[0], 0.0)).nodal["u^1"],
                                    dofs(lambda x: np.isclose(x[1], 0.0)).nodal["u^2"]]))
    xs = PARAMS["geometry"]["strip_over_b"] * B
    top = np.nonzero(np.isclose(p[2], 0.0, atol=1e-12) & (p[0] <= xs * (1 + 1e-9))
                     & (p[1] <= L / 2 * (1 + 1e-9)))[0]
    return K, fix, top, ib.nodal_dofs[2, top], ib.N, mesh


def condensed(K, fix, uz):
    """Compliance (m/N) of the strip's ``u_z`` DOFs: one factorisation, back-solves in blocks."""
    free = np.setdiff1d(np.arange(K.shape[0]), fix)
    lu = spla.splu(K[free][:, free])
    pos = np.full(K.shape[0], -1)
    pos[free] = np.arange(free.size)
    C = np.empty((uz.size, uz.size))
    for s in range(0, uz.size, 256):                    # unit downward force at each strip node
        cols = np.arange(s, min(s + 256, uz.size))
        rhs = np.zeros((free.size, cols.size))
        rhs[pos[uz[cols]], np.arange(cols.size)] = -1.0
        C[:, cols] = -lu.solve(rhs)[pos[uz]]
    return 0.5 * (C + C.T)


def dirichlet_active_set(K, fix, uz, h, W, max_iter=50):
    """Load-controlled frictionless contact by an active set on the full FE model: the active
    strip nodes get ``u_z = h - alpha`` (Dirichlet), ``alpha`` from the load balance (linearity:
    ``u = u_h + alpha u_1``); tensile nodes leave, penetrating nodes join; one factorisation per
    iteration. Returns the nodal contact forces (N, >= 0), ``alpha`` and the iteration count."""
    n = K.shape[0]
    act = h <= np.quantile(h, 0.3)
    for it in range(1, max_iter + 1):
        D = uz[act]
        free = np.setdiff1d(np.arange(n), np.concatenate([fix, D]))
        lu = spla.splu(K[free][:, free])
        UD = np.stack([h[act], -np.ones(D.size)], axis=1)              # u_D = h + alpha (-1)
        Uf = lu.solve(-(K[free][:, D] @ UD))
        r = K[D][:, free] @ Uf + K[D][:, D] @ UD                        # reactions on the block
        f0, f1 = -r[:, 0], -r[:, 1]                                     # contact force = -reaction
        alpha = (W - f0.sum()) / f1.sum()
        f = np.zeros(h.size)
        f[act] = f0 + alpha * f1
        u = np.zeros((n, 2))
        u[free], u[D] = Uf, UD
        uzs = u[uz, 0] + alpha * u[uz, 1]
        pen = (~act) & (uzs > h - alpha + 1e-9 * abs(alpha))
        ten = act & (f < -1e-12 * W)
        if not (pen.any() or ten.any()):
            return f, alpha, it, True
        act = (act & ~ten) | pen
    return f, alpha, max_iter, False


def _strip_triangles(mesh, top):
    """Boundary triangles of the contact strip (all three nodes strip nodes)."""
    f = mesh.facets[:, mesh.boundary_facets()]
    on = np.isin(f, top).all(axis=0)
    return f[:, on]


def consistent_forces(p, tri, top, pressure):
    """``int N_i p dA`` on the strip triangles (edge-midpoint rule, exact for quadratics)."""
    P = p[:2]
    a, b, c = (P[:, tri[k]] for k in range(3))
    area = 0.5 * np.abs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))
    mids = {(0, 1): 0.5 * (a + b), (1, 2): 0.5 * (b + c), (0, 2): 0.5 * (a + c)}
    pm = {k: pressure(v.T) for k, v in mids.items()}
    f = np.zeros(p.shape[1])
    for (i, j), val in pm.items():
        for n in (i, j):
            np.add.at(f, tri[n], area / 3.0 * 0.5 * val)
    return f[top]


def half_space(crown):
    prof = RollerProfile(width=L, crown=crown)
    hs = FiniteLengthContact(prof, cam_width=L, E_star=E_STAR, design_load=F, design_radius=R, nx=64,
                             ny=256, tol=1e-8).solve(F, R)
    xe = np.concatenate([[hs.x[0] - (hs.x[1] - hs.x[0]) / 2], hs.x, [hs.x[-1] + (hs.x[1] - hs.x[0]) / 2]])
    ye = np.concatenate([[-L / 2], hs.y, [L / 2]])
    pe = np.pad(hs.p, 1, mode="constant")
    pe[1:-1, 0], pe[1:-1, -1] = hs.p[:, 0], hs.p[:, -1]      # constant to the end of the end cell
    itp = RegularGridInterpolator((xe, ye), pe, bounds_error=False, fill_value=0.0)
    return hs, itp, prof


def run(case: str, write: Path | None = None, scale: float = 1.0, method: str = "dirichlet") -> dict:
    crown, ext = CASES[case]
    t0 = time.perf_counter()
    p, t = build_mesh(ext, write, scale)
    t_mesh = time.perf_counter() - t0
    K, fix, top, uz, ndof, mesh = fe_model(p, t)
    tri = _strip_triangles(mesh, top)
    hs, itp, prof = half_space(crown)
    kw = dict(design_load=F, b=B, E_star=E_STAR) if crown == "logarithmic" else {}
    c = prof.drop(p[1, top], **kw)
    h = p[0, top] ** 2 / (2 * R) + c - c.min()
    t1 = time.perf_counter()
    if method == "condense":
        sol = solve_lcp(condensed(K, fix, uz), h, np.ones(top.size), F / 4,
                        active0=h <= np.quantile(h, 0.3), max_iter=200)
        f_fe, conv, lcp_it = sol.p, sol.converged, sol.iterations
    else:
        f_fe, _alpha, lcp_it, conv = dirichlet_active_set(K, fix, uz, h, F / 4)
    t_fact = time.perf_counter() - t1
    t_fe = time.perf_counter() - t0
    f_hs = consistent_forces(p, tri, top, itp)
    y, x = p[1, top], p[0, top]
    mid, end = y < 1e-3, y > L / 2 - 0.25e-3
    w0 = F / L
    r = dict(case=case, ndof=ndof, ncand=top.size, ntet=t.shape[1], t_mesh=t_mesh, t_fact=t_fact, t_fe=t_fe,
             converged=conv, lcp_it=lcp_it,
             w_mid_fe=4 * f_fe[mid].sum() / 2e-3 / w0, w_mid_hs=4 * f_hs[mid].sum() / 2e-3 / w0,
             w_end_fe=2 * f_fe[end].sum() / 0.25e-3 / w0, w_end_hs=2 * f_hs[end].sum() / 0.25e-3 / w0,
             balance_hs=4 * f_hs.sum() / F - 1, edge=float(f_fe[x > 0.95 * x.max()].sum() / f_fe.sum()),
             w_mid_cells=float(hs.w[np.abs(hs.y) < 1e-3].mean() / w0),
             w_end_cells=float(hs.w[hs.y > L / 2 - 0.25e-3].mean() / w0))
    return r


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--write-msh", type=Path, default=None)
    ap.add_argument("--h-scale", type=float, default=1.0, help="multiply the strip and end sizes")
    ap.add_argument("--method", choices=("dirichlet", "condense"), default="dirichlet",
                    help="active set on the full model (default) or on the condensed strip compliance")
    args = ap.parse_args(argv)
    print(f"3D FE (gmsh P1 tets, quarter block) vs half-space (64 x 256): F = {F} N, R = {R * 1e3} mm, "
          f"L = {L * 1e3} mm, b = {B * 1e6:.1f} um; machine {platform.machine()}, {os.cpu_count()} cores "
          f"shared with other jobs; load avg {' '.join(f'{v:.2f}' for v in os.getloadavg())}")
    print("w in units of F/L from the same strip nodes (FE nodal forces; half-space pressure -> consistent "
          "nodal forces): mid |y| < 1 mm, end: last 0.25 mm")
    hdr = (f"{'case':<10} {'DOFs':>7} {'tets':>7} {'cand':>5} {'mesh s':>6} {'cont s':>6} {'total s':>7} "
           f"{'w_mid FE':>8} {'HS':>6} {'err':>7} {'w_end FE':>8} {'HS':>6} {'err':>7}  load avg")
    print(hdr)
    out = {}
    for case in args.cases.split(","):
        r = run(case.strip(), args.write_msh, args.h_scale, args.method)
        e_mid, e_end = r["w_mid_fe"] / r["w_mid_hs"] - 1, r["w_end_fe"] / r["w_end_hs"] - 1
        print(f"{case:<10} {r['ndof']:>7d} {r['ntet']:>7d} {r['ncand']:>5d} {r['t_mesh']:6.1f} "
              f"{r['t_fact']:6.1f} {r['t_fe']:7.1f} {r['w_mid_fe']:8.3f} {r['w_mid_hs']:6.3f} {e_mid:+7.2%} "
              f"{r['w_end_fe']:8.3f} {r['w_end_hs']:6.3f} {e_end:+7.2%}  {os.getloadavg()[0]:.2f}"
              f"   (LCP {r['lcp_it']} it, conv {r['converged']}, HS balance {r['balance_hs']:+.1e}, "
              f"load on outer 5 % of strip {r['edge']:.1e}; HS cells: mid {r['w_mid_cells']:.3f} "
              f"end {r['w_end_cells']:.3f})", flush=True)
        assert r["converged"] and r["edge"] == 0.0, f"{case}: LCP or strip too narrow"
        out[case] = (e_mid, e_end)
        if case.endswith("cont"):   # correctness: the continued block is what the half-space assumes
            assert abs(e_mid) < 0.03 and abs(e_end) < 0.10, f"FE continued block vs half-space ({case})"
    print(f"peak memory {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6:.2f} GB")
    return out


if __name__ == "__main__":
    main()
