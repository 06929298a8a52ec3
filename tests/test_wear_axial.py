"""The wear map of a finite-length roller (femcam.wear.axial, ``femcam wear map``) and the FE
source of a knife-edge follower.

References computed here: the Archard depth per pass ``k w v_slip / V_cam`` (Archard 1953) with
the most loaded slice's ``w_max`` of the half-space solution (femcam.halfspace, validated in
test_halfspace.py against Hertz and Lundberg), and with ``w = pi a p0 / 2`` (Johnson 1985
eq. 4.44) of an FE table written in the test.
"""

from __future__ import annotations

import csv
import math
import types
from pathlib import Path

import numpy as np
import pytest

from femcam.halfspace.rows import finite_length_rows
from femcam.scene import contact_case, finite_case, load_scene
from femcam.wear.axial import scene_wear_axial
from femcam.wear.options import wear_coefficient_info
from femcam.wear.scene import scene_wear

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
CROWNED = str(EXAMPLES / "seed002_crowned.toml")
KNIFE = str(EXAMPLES / "seed003_knife_edge.toml")
TH8 = np.radians(np.arange(0.0, 360.0, 45.0))
TH36 = np.radians(np.arange(0.0, 360.0, 10.0))      # the CLI's coarsest step (10 deg)


def _wear_of(scene):
    """The arguments of wear_coefficient_info: the scene's [wear] record and cam hardness (Pa)."""
    return scene.wear, scene.cam.hardness


def _rows(scene, theta):
    """The half-space rows at ``theta`` (rad) with the default strip, warm-started angle to angle."""
    st = scene.analyse(theta)
    return finite_length_rows(finite_case(scene).strip(), theta, st.Fc, st.rho, scene.follower.Rr)


def _csv(path):
    lines = [ln for ln in Path(path).read_text().splitlines() if not ln.startswith("#")]
    return list(csv.DictReader(lines))


@pytest.mark.slow
def test_crowned_wear_scales_with_the_axial_peak_load():
    """Per pass the depth is k w v_slip / V_cam: the finite-length map over the 2D one is
    w_max l / Fc angle by angle, w_max from the half-space solution computed here."""
    scene = load_scene(CROWNED)
    ax, st, slip = scene_wear_axial(contact_case(scene, TH8), finite_case(scene), cycles=1.0)
    hz, _, _ = scene_wear(contact_case(scene, TH8), cycles=1.0)
    r = _rows(scene, TH8)
    Fc = np.clip(st.Fc, 0.0, None)
    on = Fc > 0
    k = wear_coefficient_info(scene.wear, scene.cam.hardness)[0]
    np.testing.assert_allclose(ax.depth_pass[on], k * r["w_max"][on] * slip.v_slip[on] / slip.V_cam[on],
                               rtol=1e-9)
    np.testing.assert_allclose(ax.depth_pass[on] / hz.depth_pass[on], r["w_max"][on] * scene.length / Fc[on],
                               rtol=1e-9)
    assert np.all(ax.depth_pass[on] > hz.depth_pass[on])      # tilted roller: w_max > Fc / l
    # 1e-3: Archard volume conservation of the map at 10 deg steps, as asserted for the 2D map in
    # tests/test_wear.py (a quadrature error of the angle grid, not a physics tolerance)
    assert ax.load_error == 0.0 and ax.conservation_error < 1e-3


@pytest.mark.slow
def test_cli_wear_map_of_a_crowned_roller_uses_the_axial_peak(tmp_path):
    from femcam.cli import main

    assert main(["wear", "map", CROWNED, "--out", str(tmp_path), "--step-deg", "10", "--cycles", "1",
                 "--no-plots"]) == 0
    summ = _csv(tmp_path / "wear_summary.csv")[0]
    assert summ["pressure"] == "axial_peak"
    rows = _csv(tmp_path / "wear_scene.csv")
    scene = load_scene(CROWNED)
    r = _rows(scene, TH36)
    k = wear_coefficient_info(scene.wear, scene.cam.hardness)[0]
    ref = [k * w * float(x["v_slip_m_s"]) / float(x["V_cam_m_s"]) * 1e9 for w, x in zip(r["w_max"], rows,
                                                                                        strict=True)]
    np.testing.assert_allclose([float(x["depth_pass_closed_nm"]) for x in rows], ref, rtol=1e-5)  # 6 digits


def test_cli_fe_source_sweeps_the_knife_edge_itself(tmp_path, monkeypatch):
    """``--source fe`` on a knife edge sweeps the knife-edge scene (full sliding at the tip) with
    the flag's tip radius, not a rolling-tip roller scene; the depth per pass is the FE table's
    k (pi a p0 / 2) v_slip / V_cam."""
    import femcam.cli.wear as cw
    from femcam.cli import main

    seen = {}

    def fake_sweep(scene, options, run=None):
        angles, seen["scene"], seen["method"] = options.angles, scene, options.method
        a, p0 = np.full(angles.size, 40e-6), np.full(angles.size, 900e6)
        tab = {"theta": angles, "a_fe": a, "p0_fe": p0, "Fc": np.full(angles.size, 500.0)}
        return types.SimpleNamespace(table=tab, **tab)

    monkeypatch.setattr(cw, "sweep", fake_sweep)
    assert main(["wear", "map", KNIFE, "--out", str(tmp_path), "--source", "fe", "--tip-radius-mm", "0.5",
                 "--step-deg", "10", "--cycles", "1", "--no-plots"]) == 0
    assert seen["scene"].follower.kind == "knife_edge" and seen["method"] == "fe"
    assert seen["scene"].tip_radius == pytest.approx(0.5e-3, rel=1e-12)
    k = wear_coefficient_info(*_wear_of(load_scene(KNIFE)))[0]
    rows = _csv(tmp_path / "wear_scene.csv")
    w = math.pi * 40e-6 * 900e6 / 2
    ref = [k * w * float(x["v_slip_m_s"]) / float(x["V_cam_m_s"]) * 1e9 if float(x["Fc_N"]) > 0 else 0.0
           for x in rows]
    np.testing.assert_allclose([float(x["depth_pass_closed_nm"]) for x in rows], ref, rtol=1e-5)
    assert _csv(tmp_path / "wear_summary.csv")[0]["pressure"] == "fe"
