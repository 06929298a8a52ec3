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
    assert t.row("cycloidal").peak_jerk > t.row("shm").peak_jerk   # magnitude claim fails
    assert t.row("uniform_velocity").junction.startswith("velocity jump")
    assert t.row("shm").junction.startswith("acceleration jump")
    assert t.row("cycloidal").junction == "finite jerk jump"
    assert t.row("poly4567").junction == "jerk continuous"


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
