"""Profile evolution in blocks of cycles (femcam.wear.evolution)."""

import math
from pathlib import Path

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.io import read_meta
from femcam.scene import contact_case
from femcam.wear import evolution as ev
from femcam.wear import slip as wslip

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
STUDY = str(EXAMPLES / "seed002_study_model.toml")

TH2 = np.radians(np.arange(0.0, 360.0, 2.0))   # 180 angles: fast


@pytest.fixture(scope="module")
def seed002(study_scene):
    return study_scene


# --------------------------------------------------------------------------- a stiff-spring ring
RB, RR, OMEGA, SRR, LEN = 0.02, 0.01, 10.0, 0.02, 0.01
FPL, KS = 100.0, 1e5                          # 1 mm of wear takes the whole preload off


def _ring(k):
    """A circular cam (no lift: s = s1 = s2 = 0, phi = 0, rho = Rb) under a roller, spring
    preload FPL, spring rate KS: the wear depth is uniform, and the force after a total wear
    H (cam + roller mean) is FPL - KS H. A synthetic case where evolution matters."""
    from femcam.loads import FollowerDynamics
    from femcam.materials import STEEL

    th = np.linspace(0.0, 2 * np.pi, 64, endpoint=False)
    z = np.zeros_like(th)
    sl = wslip.roller_srr(th, z, z, z, Rb=RB, Rr=RR, omega=OMEGA, srr=SRR)
    return ev.EvolutionCase(theta=th, s=z, s1=z, s2=z, phi=z, rho=np.full_like(th, RB), slip=sl,
                            dynamics=FollowerDynamics(m=0.1, k=KS, Fpl=FPL, c=0.0), omega=OMEGA, Rr=RR,
                            length=LEN, cam=STEEL, roller=STEEL, k=k)


def _ring_rates(k):
    """By hand: per revolution the worn volume is k F v_slip T (T = 2 pi/omega), spread over the
    cam circumference 2 pi Rb and the roller's 2 pi Rr; v_slip = 2 SRR V_cam/(2 + SRR), V_cam =
    omega Rb. Returns (cam depth per N per newton, total (cam + roller) depth per N per newton)."""
    T = 2 * np.pi / OMEGA
    v = 2 * SRR * OMEGA * RB / (2 + SRR)
    vol = k * v * T / LEN                      # per newton, per unit width
    c_cam = vol / (2 * np.pi * RB)
    return c_cam, c_cam + vol / (2 * np.pi * RR)


K_RING = 1.0 / (1000 * KS * _ring_rates(1.0)[1])   # c1 KS N = 1 over N = 1000 revolutions


def test_ring_blocks_are_explicit_euler_of_the_hand_ode():
    """Independent reference: dH/dN = c1 (FPL - KS H) by hand; explicit Euler with M blocks of dN
    gives H_M = FPL/KS (1 - (1 - c1 KS dN)^M), the cam its share c_cam/c1 of it."""
    case = _ring(K_RING)
    c_cam, c1 = _ring_rates(K_RING)
    N = 1000.0
    for M in (1, 3, 8):
        r = ev.evolve(case, N, N / M, n_grid=8192)
        H = FPL / KS * (1 - (1 - c1 * KS * N / M) ** M)
        # rtol: the roller mean (lift loss) comes from its 8192-point grid (~a/3.5): measured 4e-9
        np.testing.assert_allclose(r.depth_cam, H * c_cam / c1, rtol=1e-7)
        # the force of each block: FPL - KS H_b (phi = 0, lift loss uniform)
        Hb = FPL / KS * (1 - (1 - c1 * KS * N / M) ** np.arange(M))
        np.testing.assert_allclose(r.Fc_blocks, (FPL - KS * Hb)[:, None] * np.ones(64), rtol=1e-7)


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_convergence_first_order_against_exact_and_halvings():
    """(2) Errors against the exact ODE solution H = FPL/KS (1 - exp(-c1 KS N)) halve with the block
    size (first order), and so do the differences between successive halvings."""
    case = _ring(K_RING)
    c_cam, c1 = _ring_rates(K_RING)
    N = 1000.0
    exact = c_cam / c1 * FPL / KS * (1 - math.exp(-c1 * KS * N))
    ct = ev.convergence_table(case, N, 32, n_grid=4096)
    assert ct.blocks == [1, 2, 4, 8, 16, 32]
    err = np.abs(ct.max_depth - exact)
    r_err = err[2:-1] / err[3:]                    # 4 -> 8 -> 16 -> 32 blocks
    assert np.all((r_err > 1.8) & (r_err < 2.2)), r_err
    d = ct.diff_next[:-1]
    assert np.all((d[2:-1] / d[3:] > 1.8) & (d[2:-1] / d[3:] < 2.2)), d
    order = ct.order[np.isfinite(ct.order)]           # 2..32 blocks; coarse blocks are pre-asymptotic
    assert np.all(np.abs(order[-2:] - 1.0) < 0.15), order
    assert abs(ct.max_depth[-1] / exact - 1) < 0.02   # 32 blocks: within 2 % of the exact ODE


def test_worn_curvature_against_polar_curve():
    """Eq. (1) against the curvature of the polar curve r(t) = R - h(R t) (independent formula
    k = (r^2 + 2 r'^2 - r r'')/(r^2 + r'^2)^1.5), with a wavy h."""
    R, h0, h2, m = 0.02, 2e-4, 5e-5, 7
    t = np.linspace(0, 2 * np.pi, 400, endpoint=False)

    def h(s):
        return h0 + h2 * np.cos(m * s / R)

    s = R * t
    h1 = -h2 * m / R * np.sin(m * s / R)
    hpp = -h2 * (m / R) ** 2 * np.cos(m * s / R)
    r = R - h(s)
    rp, rpp = -R * h1, -R * R * hpp
    ref = (r * r + 2 * rp * rp - r * rpp) / (r * r + rp * rp) ** 1.5
    np.testing.assert_allclose(ev.worn_curvature(1 / R, 0.0, h(s), h1, hpp), ref, rtol=1e-12)
    # approximation quoted in the docs: 1/(rho - h) + h''
    np.testing.assert_allclose(ev.worn_curvature(1 / R, 0.0, h(s), h1, hpp), 1 / (R - h(s)) + hpp, rtol=0.05)


# --------------------------------------------------------------------------- seed 002
def test_single_block_equals_linear_map_times_n(seed002):
    """(1) One block of N revolutions = the existing map's depth per revolution x N (cam and roller,
    the roller with its drift), computed through femcam wear map's own path."""
    from femcam.wear.scene import scene_wear

    N = 1e6
    wm, _st, _slip = scene_wear(contact_case(seed002, TH2), cycles=N)
    r = ev.evolve(ev.evolution_case(contact_case(seed002, TH2)), N, N)
    np.testing.assert_allclose(r.depth_cam, wm.depth_cam * N, rtol=1e-12, atol=0)
    np.testing.assert_allclose(r.depth_follower, wm.depth_follower_cycles, rtol=1e-12,
                               atol=1e-12 * wm.max_depth_follower)
    np.testing.assert_allclose(r.depth_linear, wm.depth_cam * N, rtol=1e-12)


def test_small_k_matches_linear_map(seed002):
    """(3) k -> 0: the evolved depth tends to the linear one, the relative change linear in k."""
    rel = []
    for k in (5e-18, 5e-17):
        r = ev.evolve(ev.evolution_case(contact_case(seed002, TH2), k=k), 1e6, 2.5e5, n_grid=2000)
        rel.append(np.max(np.abs(r.depth_cam - r.depth_linear)) / r.max_depth_linear)
    assert rel[0] < 1e-6
    assert 8.0 < rel[1] / rel[0] < 12.0, rel


def test_volume_bookkeeping_with_evolving_force(seed002):
    """(4) l int h dx = sum over blocks of dN k sum_j F_j v_slip,j dt, with each block's force
    (rectangle rule here, the map's exact step integral there)."""
    case = ev.evolution_case(contact_case(seed002, TH2), k=5e-14)        # 1e4 x the default: ~0.16 mm
    N, M = 1e6, 4
    r = ev.evolve(case, N, N / M, n_grid=2000)
    dt = (TH2[1] - TH2[0]) / seed002.omega
    vol = sum(N / M * case.k * np.sum(F * case.slip.v_slip) * dt for F in r.Fc_blocks)
    assert r.volume_cam == pytest.approx(vol, rel=2e-3)
    # the map's own step integral: exact up to its grid (2000 points, ~ a): measured 8e-6
    assert r.volume_cam == pytest.approx(r.volume_archard, rel=1e-4)
    assert not np.allclose(r.Fc_blocks[-1], r.Fc_blocks[0], rtol=1e-6, atol=0), "the force evolves"
    assert r.a_over_R_max < 0.05


def test_seed002_large_k_converges_first_order(seed002):
    case = ev.evolution_case(contact_case(seed002, np.radians(np.arange(0.0, 360.0, 3.0))), k=5e-14)
    ct = ev.convergence_table(case, 1e6, 8, n_grid=1200)
    d = ct.diff_next[:-1]
    assert np.all(d[1:] < d[:-1])
    assert np.all((d[:-1] / d[1:] > 1.6) & (d[:-1] / d[1:] < 2.4)), d
    assert abs(ct.max_depth[-1] / ct.linear_max_depth - 1) < 1e-3   # roller cam: evolution is small


# --------------------------------------------------------------------------- errors
@pytest.mark.parametrize("cycles, block, text", [
    (1000.0, 0.0, "block = 0 revolutions: must be > 0"),
    (1000.0, -5.0, "block = -5 revolutions: must be > 0"),
    (1000.0, 2000.0, "block = 2000 revolutions: must be <= cycles = 1000 revolutions"),
    (1000.0, 300.0, "block = 300 revolutions: must divide cycles = 1000 revolutions"),
    (0.0, 1.0, "cycles = 0 revolutions: must be > 0"),
    (float("nan"), 1.0, "cycles = nan revolutions: must be finite"),
])
def test_bad_block_inputs(cycles, block, text):
    with pytest.raises(InputError, match=text.replace("(", r"\(")):
        ev.evolve(_ring(1e-12), cycles, block)


def test_knife_edge_and_bad_block_count_refused():
    sc_mod = pytest.importorskip("femcam.scene")
    sc = sc_mod.load_scene(str(EXAMPLES / "seed003_knife_edge.toml"))
    with pytest.raises(InputError, match="follower type = 'knife_edge': profile evolution is implemented"):
        ev.evolution_case(contact_case(sc, TH2))
    with pytest.raises(InputError, match=r"blocks = 0 \(number of blocks\): must be an integer >= 1"):
        ev.block_counts(0)


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_cli_evolve_blocks(tmp_path, capsys):
    from femcam.cli import main

    rc = main(["wear", "map", STUDY, "--out", str(tmp_path), "--step-deg", "3",
               "--evolve-blocks", "4"])
    assert rc == 0
    rows = (tmp_path / "wear_scene_evolution.csv").read_text().splitlines()
    assert read_meta(tmp_path / "wear_scene_evolution.csv")["dc:title"].startswith("femcam wear map")
    assert rows[0].split(",")[:3] == ["blocks", "block_revolutions", "max_depth_um"]
    assert [r.split(",")[0] for r in rows[1:]] == ["1", "2", "4"]
    assert (tmp_path / "wear_scene_evolution.png").stat().st_size > 1000
    assert "evolution" in capsys.readouterr().out
    assert main(["wear", "map", STUDY, "--out", str(tmp_path),
                 "--evolve-blocks", "0"]) == 1
    assert "--evolve-blocks = 0 (number of blocks): must be a whole number in [1, 4096]" \
        in capsys.readouterr().err


def test_bad_grid_and_cli_source_refused(tmp_path, capsys):
    with pytest.raises(InputError, match=r"n_grid = 0 \(grid points\): must be an integer >= 2"):
        ev.evolve(_ring(1e-12), 1000.0, 100.0, n_grid=0)
    from femcam.cli import main

    # refused before any map is computed or written
    assert main(["wear", "map", STUDY, "--out", str(tmp_path / "o"), "--source", "fe",
                 "--evolve-blocks", "2"]) == 1
    assert "--source = fe: --evolve-blocks uses Hertz pressure" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()
