"""3D finite-element reference for the finite-length half-space contact (scikit-fem).

One roller-cam contact of seed 002's dwell (F = 1500 N, R = 5 mm, steel on steel, both bodies
10 mm wide, ending at the same plane): a rigid indenter with the relative gap
``x^2/2R + c(y)`` pressed frictionlessly onto ONE elastic block of modulus
``E_b = E* (1 - nu^2)``, which has the same combined compliance ``1/E*`` as the two steel bodies
(identical materials, frictionless: no Dundurs coupling). Two blocks, 10 mm deep and 10 mm to each
side of the contact (as deep as the contact is long, so the axial coupling of the half-space is
not cut off by the fixed bottom):

* ``free end``: the block ends at ``y = L/2`` with a free face, as the real bodies do;
* ``continued``: the block runs on 5 mm past the end of the loaded length, which is what the
  half-space model assumes.

``continued`` against the half-space is the FE's own error (finite block, mesh); ``free end``
against ``continued`` is the free-end error of the half-space model.

Mesh: a quarter block (symmetry ``x = 0`` and ``y = 0``, bottom fixed), trilinear hexahedra
(``ElementVector(ElementHex1)``) on a tensor grid graded towards the contact (``x``, ``z``) and the
roller end (``y``). Contact: the top-face nodes of the contact zone are condensed to a compliance
matrix (one factorisation, one back-solve per node) and the frictionless, load-controlled
contact is solved on it by an active-set method. The reference of docs/halfspace.md is the gmsh
tetrahedral version (``bench_halfspace_fe3d_gmsh.py``); this hand-graded hex mesh is kept as an
independent discretisation that cross-checks its free-end error (slower: 141-325 s per case).

Run:  python benchmarks/bench_halfspace_fe3d.py   (4 cases, 141-325 s each at load average 7-8 on the
      shared 2 cores; about 2 GB of memory seen during a factorisation)
"""

from __future__ import annotations

import math
import os
import time

import numpy as np
import scipy.sparse.linalg as spla

from femcam.halfspace.crown import RollerProfile
from femcam.halfspace.strip import FiniteLengthContact

E_STAR, NU = 210e9 / (2 * 0.91), 0.3
F, R, L = 1500.0, 0.005, 0.010
B = math.sqrt(4 * F / L * R / (math.pi * E_STAR))       # 2D Hertz half-width (Johnson eq. 4.45)


def graded(fine_end: float, h_fine: float, total: float, ratio: float) -> np.ndarray:
    """Nodes 0 .. total: uniform h_fine up to fine_end, then growing by ``ratio``."""
    xs = list(np.arange(0.0, fine_end + 1e-15, h_fine))
    h = h_fine
    while xs[-1] < total - 1e-12:
        h *= ratio
        xs.append(min(xs[-1] + h, total))
    return np.array(xs)


def mesh_coords(extend: float = 0.0, X=10e-3, D=10e-3):
    x = graded(2.0 * B, B / 6, X, 1.5)
    end = L / 2
    yt = graded(0.4e-3, B / 3, end, 1.4)                 # from the end inwards
    y = np.unique(np.round(end - yt[::-1], 12))
    if extend > 0:                                        # the block continues past the end
        y = np.concatenate([y, end + graded(0.0, B / 3, extend, 1.7)[1:]])
    z = -graded(1.0 * B, B / 6, D, 1.5)[::-1]
    return x, y, z


def fe_compliance(x, y, z, nx_c):
    from skfem import Basis, ElementHex1, ElementVector, MeshHex, asm  # lazy: FE only
    from skfem.models.elasticity import lame_parameters, linear_elasticity

    m = MeshHex.init_tensor(x, y, z)
    ib = Basis(m, ElementVector(ElementHex1()), intorder=2)   # 2x2x2 Gauss: exact on boxes
    E_b = E_STAR * (1 - NU**2)
    K = asm(linear_elasticity(*lame_parameters(E_b, NU)), ib).tocsc()
    dofs = ib.get_dofs
    fix = np.concatenate([dofs(lambda p: np.isclose(p[2], z[0])).all(),
                          dofs(lambda p: np.isclose(p[0], 0.0)).nodal["u^1"],
                          dofs(lambda p: np.isclose(p[1], 0.0)).nodal["u^2"]])
    free = np.setdiff1d(np.arange(ib.N), fix)
    # contact candidates: top-face nodes with x <= x[nx_c - 1] on the loaded length |y| <= L/2
    top = np.nonzero(np.isclose(m.p[2], 0.0) & (m.p[0] <= x[nx_c - 1] + 1e-15)
                     & (m.p[1] <= L / 2 + 1e-12))[0]
    uz = ib.nodal_dofs[2, top]
    t = time.perf_counter()
    lu = spla.splu(K[free][:, free])
    print(f"  factorisation {time.perf_counter() - t:.1f} s", flush=True)
    pos = np.full(ib.N, -1)
    pos[free] = np.arange(free.size)
    rhs = np.zeros((free.size, top.size))
    rhs[pos[uz], np.arange(top.size)] = -1.0           # unit force pushing down at each node
    C = -lu.solve(rhs)[pos[uz]]                          # downward deflection per unit force
    return m.p[:, top], 0.5 * (C + C.T), ib.N


def contact(C, h, W):
    """Active set: f >= 0, C f - alpha = -h on the contact, sum f = W, no penetration."""
    S = h <= np.quantile(h, 0.3)
    for _ in range(200):
        idx = np.nonzero(S)[0]
        n = idx.size
        A = np.zeros((n + 1, n + 1))
        A[:n, :n] = C[np.ix_(idx, idx)]
        A[:n, n] = -1.0
        A[n, :n] = 1.0
        sol = np.linalg.solve(A, np.concatenate([-h[idx], [W]]))
        f = np.zeros_like(h)
        f[idx], alpha = sol[:n], sol[n]
        if f.min() < -1e-12 * W:
            S[idx[np.argmin(sol[:n])]] = False
            continue
        gap = C @ f + h - alpha
        pen = (~S) & (gap < -1e-12 * abs(alpha))
        if not pen.any():
            return f, alpha
        S |= pen
    raise RuntimeError("active set did not converge")


def tributary(c):
    e = np.concatenate([[c[0]], 0.5 * (c[1:] + c[:-1]), [c[-1]]])
    return np.diff(e)


def slice_loads(pts, f, x, y):
    """Full-width slice load w(y) (N/m) from the quarter model's nodal forces."""
    w, ty = np.zeros(y.size), tributary(y)               # y = 0 node: half a cell (symmetry plane)
    for j, yj in enumerate(y):
        w[j] = 2 * f[np.isclose(pts[1], yj)].sum() / ty[j]   # x >= 0 half, mirrored
    return w


def run(crown: str, extend: float = 0.0):
    x, y, z = mesh_coords(extend)
    y = y[y <= L / 2 + 1e-12]
    nx_c = int(np.searchsorted(x, 1.8 * B)) + 1
    t = time.perf_counter()
    pts, C, ndof = fe_compliance(x, mesh_coords(extend)[1], z, nx_c)
    prof = RollerProfile(width=L, crown=crown)
    kw = dict(design_load=F, b=B, E_star=E_STAR) if crown == "logarithmic" else {}
    c = prof.drop(pts[1], **kw)
    f, alpha = contact(C, pts[0] ** 2 / (2 * R) + c - c.min(), F / 4)
    t_fe = time.perf_counter() - t
    w_fe = slice_loads(pts, f, x, y)
    hs = FiniteLengthContact(prof, cam_width=L, E_star=E_STAR, design_load=F, design_radius=R, nx=64,
                             ny=256, tol=1e-8).solve(F, R)
    w_hs = np.interp(y, hs.y, hs.w)
    edge = f[np.isclose(pts[0], x[nx_c - 1])].sum() / f.sum()   # load on the last candidate column
    return dict(y=y, w_fe=w_fe, w_hs=w_hs, hs=hs, t=t_fe, ndof=ndof, ncand=C.shape[0], edge=edge)


def report(crown, r, label):
    w0 = F / L
    y = r["y"]
    mid = y < 1e-3
    end = y > L / 2 - 0.25e-3
    e_mid = r["w_fe"][mid].mean() / r["w_hs"][mid].mean() - 1
    hs = r["hs"]
    end_hs = hs.w[hs.y > L / 2 - 0.25e-3].mean() * 0.25e-3
    end_fe = np.trapezoid(r["w_fe"][end], y[end]) * 0.25e-3 / (y[end][-1] - y[end][0])
    e_end = end_fe / end_hs - 1
    assert r["edge"] == 0.0, "contact reached the last candidate column: widen nx_c"
    print(f"{crown + ' ' + label:<24} {r['ndof']:>7d} {r['ncand']:>6d} {r['t']:8.1f} "
          f"{r['w_fe'][mid].mean() / w0:9.3f} {r['w_hs'][mid].mean() / w0:9.3f} {e_mid:+8.2%} "
          f"{end_fe / 0.25e-3 / w0:9.3f} {end_hs / 0.25e-3 / w0:9.3f} {e_end:+8.2%}")
    return e_mid, e_end


def main():
    print(f"3D FE (hex, quarter block) vs half-space (64 x 256), F = {F} N, R = {R * 1e3} mm, "
          f"L = {L * 1e3} mm,"
          f" b = {B * 1e6:.1f} um; load avg {os.getloadavg()[0]:.2f} (2 shared cores)")
    print(f"{'crown, block':<24} {'DOFs':>7} {'cand':>6} {'FE (s)':>8} {'w_mid FE':>9} {'w_mid HS':>9} "
          f"{'err':>8} {'w_end FE':>9} {'w_end HS':>9} {'err':>8}")
    print("(w in units of F/L; mid: |y| < 1 mm; end: the last 0.25 mm)")
    out = {}
    for crown in ("logarithmic", "none"):
        for label, ext in (("free end", 0.0), ("continued", 5e-3)):
            out[crown, label] = report(crown, run(crown, ext), label)
        # correctness: the continued block is what the half-space assumes, so it must agree
        e_mid, e_end = out[crown, "continued"]
        assert abs(e_mid) < 0.02 and abs(e_end) < 0.10, f"FE continued block vs half-space ({crown})"
    return out


if __name__ == "__main__":
    main()
