"""VTU export (meshio) read back with pyvista, and the off-screen von Mises PNG."""

import numpy as np
import pytest

from femcam.fe import MeshOptions, solve_contact
from femcam.io import write_fe_vtu
from femcam.materials import STEEL


@pytest.fixture(scope="module")
def result():
    return solve_contact(1500.0, 0.02, 0.01, STEEL, STEEL, 0.01, mu=0.2, mesh=MeshOptions(a_over_h=8))


def test_vtu_roundtrip(result, tmp_path):
    pv = pytest.importorskip("pyvista")
    path = write_fe_vtu(tmp_path / "scene.vtu", result)
    grid = pv.read(path)
    for name in ("displacement_m", "stress_Pa", "tau1_Pa", "von_mises_Pa", "contact_pressure_Pa"):
        assert name in grid.point_data, name
    assert grid.point_data["displacement_m"].shape[1] == 3
    assert np.all(np.isfinite(grid.point_data["von_mises_Pa"]))
    # the pressure on the surface integrates to the load per unit width (trapezoid over the
    # surface points that carry pressure, in x order): independent of the solver's own weights
    on = grid.point_data["contact_pressure_Pa"] > 0
    cam = (grid.points[:, 1] <= 0) & on
    x = grid.points[cam, 0]
    order = np.argsort(x)
    w = np.trapezoid(grid.point_data["contact_pressure_Pa"][cam][order], x[order])
    assert w == pytest.approx(1500.0 / 0.01, rel=2e-2), "int p dx = F / l"
    # sz on the cam surface equals -p at the centre (traction boundary condition)
    i0 = np.argmin(np.abs(grid.points[:, 0]) + np.abs(grid.points[:, 1]) + (grid.points[:, 1] > 0))
    assert grid.point_data["stress_Pa"][i0, 1] == pytest.approx(-result.p0, rel=2e-2)


@pytest.mark.slow  # ~1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_von_mises_png(result, tmp_path):
    pytest.importorskip("pyvista")
    from femcam.viz.fe import plot_von_mises

    path = plot_von_mises(result, tmp_path / "vm.png", size=(400, 300))
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 5000
