"""Seed 000 (Archard/RMS) reproduced: closed forms vs quadrature, and the hand-derived numbers."""

import math

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.wear import archard
from femcam.wear.seed000 import (
    PAPER_TABLE3,
    Seed000Inputs,
    format_table3,
    seed000_table,
    v2_integral_closed,
    v2_integral_quad,
)

kin = pytest.importorskip("femcam.kinematics")
ALL_LAWS = [n for n in kin.LAW_NAMES if n not in ("bezier", "polynomial")]


@pytest.mark.parametrize("name", ALL_LAWS)
def test_closed_form_matches_quadrature(name):
    I_c = v2_integral_closed(name)
    I_q = v2_integral_quad(name)
    assert math.isfinite(I_c), f"no closed form for {name}"
    assert I_c == pytest.approx(I_q, rel=1e-10), f"{name}: hand-derived int v^2 du vs scipy quad"


def test_closed_form_matches_trapezoid_on_law_v():
    # a third, cruder method: composite trapezoid on 200001 points (error ~ 1e-10)
    u = np.linspace(0.0, 1.0, 200001)
    for name in ALL_LAWS:
        v = kin.law(name).v(u)
        assert v2_integral_closed(name) == pytest.approx(np.trapezoid(v * v, u), rel=1e-8), name


def test_parametric_laws_closed_forms():
    # 3-4-5 written two ways (Bezier 0,0,0,1,1,1 and polynomial 10u^3-15u^4+6u^5): 10/7 by hand
    assert v2_integral_closed(kin.law("bezier", control_points=[0, 0, 0, 1, 1, 1])) == pytest.approx(10 / 7)
    poly = kin.law("polynomial", coefficients=[0, 0, 0, 10, -15, 6])
    assert v2_integral_closed(poly) == pytest.approx(10 / 7)
    # Bezier [0, 1]: uniform velocity, v = 1
    assert v2_integral_closed(kin.law("bezier", control_points=[0, 1])) == pytest.approx(1.0)
    L = kin.law("bezier", control_points=[0, 0.1, 0.5, 0.7, 1.0])
    assert v2_integral_closed(L) == pytest.approx(v2_integral_quad(L), rel=1e-10)


def test_seed000_numbers_hand_derived():
    # independent hand derivation (not femcam): h = 10 mm, beta = pi, omega = 1 rad/s
    h, beta, w = 10.0, math.pi, 1.0
    v_uv = h * w / beta
    v_shm = h * math.pi * w / (2 * beta * math.sqrt(2))
    v_cyc = h * w / beta * math.sqrt(1.5)
    expected_v = {"uniform_velocity": v_uv, "shm": v_shm, "cycloidal": v_cyc}
    K, L, H = 1e-8, 500.0, 2000.0  # N/mm^2 -> W in mm^3
    t = seed000_table()
    for name, v in expected_v.items():
        r = t.row(name)
        S = h * v / v_shm
        assert r.v_rms * 1e3 == pytest.approx(v, rel=1e-12), name
        assert r.S * 1e3 == pytest.approx(S, rel=1e-12), name
        assert r.W * 1e9 == pytest.approx(K * L * S / H, rel=1e-12), name
    # the coordinator's rounded values
    assert t.row("shm").v_rms * 1e3 == pytest.approx(3.536, abs=5e-4)
    assert t.row("cycloidal").v_rms * 1e3 == pytest.approx(3.898, abs=5e-4)
    assert t.row("uniform_velocity").S * 1e3 == pytest.approx(9.00, abs=5e-3)
    assert t.row("cycloidal").S * 1e3 == pytest.approx(11.03, abs=5e-3)
    assert t.row("cycloidal").W * 1e9 == pytest.approx(2.76e-8, abs=5e-11)


def test_paper_slips_identified():
    # the paper's SHM value is pi/sqrt(2): h/beta = 10/pi dropped after cancelling
    assert PAPER_TABLE3["shm"]["v_rms_mm_s"] == pytest.approx(math.pi / math.sqrt(2), abs=5e-4)
    # its UV value is right
    assert PAPER_TABLE3["uniform_velocity"]["v_rms_mm_s"] == pytest.approx(10 / math.pi, abs=5e-4)
    # and the ranking reverses: Cauchy-Schwarz, uniform velocity has the least v_rms
    t = seed000_table(ALL_LAWS)
    v = {r.law: r.v_rms for r in t.rows}
    assert min(v, key=v.get) == "uniform_velocity"


def test_jerk_and_continuity():
    t = seed000_table(ALL_LAWS)
    # peak jerk coefficients by hand: SHM pi^3/2, cycloidal 4 pi^2, 3-4-5 = 60
    assert t.row("shm").Cj == pytest.approx(math.pi**3 / 2, rel=1e-6)
    assert t.row("cycloidal").Cj == pytest.approx(4 * math.pi**2, rel=1e-6)
    assert t.row("poly345").Cj == pytest.approx(60.0, rel=1e-6)
    assert t.row("cycloidal").interior_peak_jerk > t.row("shm").interior_peak_jerk  # magnitude claim fails
    assert t.row("uniform_velocity").junction.startswith("velocity jump")
    assert t.row("shm").junction.startswith("acceleration jump")
    assert t.row("cycloidal").junction == "finite jerk jump"
    assert t.row("poly4567").junction == "jerk continuous"


def test_peak_jerk_interior_and_with_dwells():
    # hand values, h = 10 mm, beta = pi, omega = 1 rad/s: j_max = Cj h omega^3 / beta^3 (mm/s^3)
    h_b3 = 10.0 / math.pi**3
    interior = {"uniform_velocity": 0.0, "shm": math.pi**3 / 2 * h_b3, "cycloidal": 4 * math.pi**2 * h_b3,
                "poly345": 60.0 * h_b3, "poly4567": 52.5 * h_b3}
    # next to a dwell: a velocity step (UV) or an acceleration step (SHM) makes the jerk infinite
    with_dwell = dict(interior, uniform_velocity=math.inf, shm=math.inf)
    t = seed000_table(list(interior))
    for name in interior:
        r = t.row(name)
        assert r.interior_peak_jerk * 1e3 == pytest.approx(interior[name], rel=1e-6, abs=1e-12), name
        assert r.peak_jerk * 1e3 == pytest.approx(with_dwell[name], rel=1e-6, abs=1e-12), name
    assert t.row("shm").interior_peak_jerk * 1e3 == pytest.approx(5.0, rel=1e-12)   # 10 pi^3/(2 pi^3)
    txt = format_table3(t)
    for pretty, expect in (("Uniform Velocity", ["0.0000", "inf"]), ("SHM", ["5.0000", "inf"]),
                           ("Cycloidal", ["12.7324", "12.7324"])):
        ln = next(ln for ln in txt.splitlines() if ln.startswith(pretty) and "jerk" in ln)
        # columns after the name: int v^2 du, quad rel.diff, Cj, interior, with dwells
        assert ln[len(pretty):].split()[3:5] == expect, ln


def test_cli_csv_jerk_columns(tmp_path):
    import csv

    from femcam.cli import main

    assert main(["wear", "seed000", "--csv", str(tmp_path / "t.csv")]) == 0
    lines = (tmp_path / "t.csv").read_text().splitlines()
    rows = {r["law"]: r for r in csv.DictReader(lines)}
    assert float(rows["uniform_velocity"]["interior_peak_jerk_mm_s3"]) == 0.0
    assert float(rows["uniform_velocity"]["peak_jerk_with_dwells_mm_s3"]) == math.inf
    assert float(rows["shm"]["interior_peak_jerk_mm_s3"]) == pytest.approx(5.0, rel=1e-5)
    assert float(rows["shm"]["peak_jerk_with_dwells_mm_s3"]) == math.inf
    cyc = 40.0 / math.pi    # 4 pi^2 x 10 / pi^3
    assert float(rows["cycloidal"]["interior_peak_jerk_mm_s3"]) == pytest.approx(cyc, rel=1e-5)
    assert float(rows["cycloidal"]["peak_jerk_with_dwells_mm_s3"]) == pytest.approx(cyc, rel=1e-5)


def test_cli_all_laws(tmp_path, capsys):
    """``--all-laws``: every named law is present, and the closed-form int v^2 du equals the
    quadrature and the hand values (and v_rms = (h omega/beta) sqrt(I) with them)."""
    import csv

    from femcam.cli import main

    assert main(["wear", "seed000", "--all-laws", "--csv", str(tmp_path / "all.csv")]) == 0
    out = capsys.readouterr().out
    lines = (tmp_path / "all.csv").read_text().splitlines()
    rows = {r["law"]: r for r in csv.DictReader(lines)}
    assert set(rows) == set(ALL_LAWS)
    assert len(ALL_LAWS) == 10
    for pretty in ("Uniform Velocity", "SHM", "Cycloidal", "3-4-5 polynomial", "4-5-6-7 polynomial",
                   "Modified sine", "Modified trapezoid", "bezier5", "bezier7", "bezier9"):
        assert pretty in out, pretty
    # hand-derived I (module docstring; Bernstein product integral for the Bezier laws); the
    # Bezier 9 value 1.814068 is checked against a 200001-point trapezoid below instead
    hand = {"uniform_velocity": 1.0, "shm": math.pi**2 / 8, "cycloidal": 1.5, "poly345": 10 / 7,
            "poly4567": 4900 / 3003, "bezier5": 10 / 7, "bezier7": 700 / 429}
    u = np.linspace(0.0, 1.0, 200001)
    for name, r in rows.items():
        I_c, I_q = float(r["int_v2_du"]), float(r["int_v2_du_quad"])
        assert I_c == pytest.approx(I_q, rel=1e-9), name              # closed form = quadrature
        v = kin.law(name).v(u)
        I_ref = hand.get(name, np.trapezoid(v * v, u))
        assert I_c == pytest.approx(I_ref, rel=1e-8), name
        v_rms = 10.0 / math.pi * math.sqrt(I_ref)                   # mm/s, h = 10 mm, beta = pi
        assert float(r["v_rms_mm_s"]) == pytest.approx(v_rms, rel=1e-5), name
        assert float(r["S_mm"]) == pytest.approx(10.0 * math.sqrt(I_ref / (math.pi**2 / 8)), rel=1e-5), name


def test_format_and_inputs():
    txt = format_table3(seed000_table())
    assert "Ratio to SHM" in txt and "11.03" in txt and "Paper vs femcam" in txt
    with pytest.raises(InputError, match="H = "):
        Seed000Inputs(H=0.0)
    with pytest.raises(InputError, match="K = "):
        Seed000Inputs(K=-1e-8)


def test_archard_conversion_and_errors():
    k = archard.dimensional_coefficient(1e-8, 2e9)
    assert k == pytest.approx(5e-18, rel=1e-15)
    assert archard.dimensionless_coefficient(k, 2e9) == pytest.approx(1e-8, rel=1e-15)
    # W = K L S / H with S = 10 mm in mm units: 1e-8*500*10/2000 = 2.5e-8 mm^3 = 2.5e-17 m^3
    assert archard.archard_volume(k, 500.0, 0.010) == pytest.approx(2.5e-17, rel=1e-12)
    assert archard.archard_volume(k, 500.0, 0.0) == 0.0
    with pytest.raises(InputError, match=r"k = -1e-18 m\^3/\(N m\): must be >= 0"):
        archard.archard_volume(-1e-18, 500.0, 0.01)
    with pytest.raises(InputError, match="H = 0 Pa"):
        archard.dimensional_coefficient(1e-8, 0.0)
    with pytest.raises(InputError, match="H = -5 Pa"):
        archard.dimensionless_coefficient(1e-18, -5.0)
    with pytest.raises(InputError, match="L = "):
        archard.archard_volume(1e-18, np.array([1.0, -2.0]), 0.01)
