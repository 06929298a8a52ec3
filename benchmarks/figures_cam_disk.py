"""Figures and table of the cam disk on its shaft (docs/bodies.md).

    PYTHONPATH=. python benchmarks/figures_cam_disk.py

* ``docs/img/cam_disk_web.png``: the seed 002 cam (base radius 10 mm, Rr = 10 mm, l = 10 mm,
  line-to-line steel shaft) for shaft bores 2 .. 8.5 mm: the largest tensile bore hoop stress
  over one revolution (global model) and at the peak-force angle (fully refined model and the
  global model there), the change of p0, a and the approach against today's local cam body.
* ``docs/img/cam_disk_hoop.png``: hoop stress of the complete cam disk of the example
  ``examples/seed002_cam_on_shaft.toml`` (bore 6 mm) at its peak force (refined model; the VTU
  is written to a temporary directory, not kept).

Prints the table (markdown) with the machine's load average.
"""

from __future__ import annotations

import math
import os
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from femcam.bodies.cam_rows import disk_from_case  # noqa: E402
from femcam.bodies.cam_study import peak_angle, refined_at, web_study  # noqa: E402
from femcam.io import write_cam_vtu  # noqa: E402
from femcam.scene import cam_disk_case, load_scene  # noqa: E402

BORES_MM = (2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 8.5)


def plot_web(r: dict, path: Path) -> Path:
    import matplotlib  # plotting only

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # plotting only

    web = r["web"] * 1e3
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(web, r["hoop_max_rev"] / 1e6, "o-", label="max over the revolution (global)")
    ax[0].plot(web, r["hoop_refined"] / 1e6, "s--", label="at the peak force (refined)")
    ax[0].plot(web, r["hoop_global_at_theta"] / 1e6, "x:", label="at the peak force (global)")
    ax[0].set_xlabel("web = base radius - bore radius (mm)")
    ax[0].set_ylabel("tensile hoop stress at the bore (MPa)")
    ax[0].legend(fontsize=8)
    ax[0].grid(alpha=0.3)
    ax[1].plot(web, 100 * r["dp0"], "o-", label="p0 vs local cam body")
    ax[1].plot(web, 100 * r["da"], "s-", label="a vs local cam body")
    ax[1].plot(web, 100 * (r["delta"] / r["delta_local"] - 1), "^-", label="approach vs local cam body")
    ax[1].set_yscale("symlog", linthresh=0.01)
    ax[1].set_xlabel("web (mm)")
    ax[1].set_ylabel("change at the peak force (%)")
    ax[1].legend(fontsize=8)
    ax[1].grid(alpha=0.3)
    fig.suptitle(f"seed 002 cam on a line-to-line steel shaft (F = {r['F']:.0f} N at "
                 f"{math.degrees(r['theta']):.0f} deg)", fontsize=10)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_cam_hoop(vtu: Path, path: Path) -> Path:
    import pyvista as pv  # rendering only

    grid = pv.read(str(vtu))
    grid.points = grid.points * 1e3
    cam = grid.extract_cells(np.nonzero(grid.cell_data["body"] == 0)[0])
    cam.point_data["hoop (MPa)"] = cam.point_data["hoop"] / 1e6
    pl = pv.Plotter(off_screen=True, window_size=[760, 760])
    pl.add_mesh(cam, scalars="hoop (MPa)", cmap="coolwarm", clim=(-60, 60),
                scalar_bar_args={"title": "cam hoop stress about its centre (MPa)", "vertical": False,
                                 "position_x": 0.2, "position_y": 0.02, "width": 0.6})
    pl.view_xy()
    pl.add_text("cam disk on its shaft; roller contact at the top (origin)", font_size=10)
    path.parent.mkdir(parents=True, exist_ok=True)
    pl.screenshot(str(path))
    pl.close()
    return path


def main() -> int:
    img = ROOT / "docs" / "img"
    sc = load_scene(ROOT / "examples" / "seed002_cam_on_shaft.toml")
    case = cam_disk_case(sc)                              # the outline over 720 angles
    at = sc.analyse(np.array([peak_angle(case.revolution)]))   # the refined model's angle
    rev = sc.analyse(np.linspace(0.0, 2 * math.pi, 360, endpoint=False))  # the global model's
    r = web_study(case, [b * 1e-3 for b in BORES_MM], state=at, revolution=rev)
    th = r["theta"]
    r["F"] = float(at.Fc[0])
    print(f"load average {os.getloadavg()} (shared machine); peak force {r['F']:.1f} N at "
          f"{math.degrees(th):.1f} deg")
    print("| bore (mm) | web (mm) | p0 (MPa) | dp0 vs local (%) | a (um) | da (%) | approach / local (um) "
          "| bore hoop at peak F: refined / global (MPa) | max bore hoop over rev. (MPa) at (deg) "
          "| shaft p0 (MPa), arc (deg) | t refined / global / 360 angles (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for i in range(r["web"].size):
        print(f"| {r['Rb'][i] * 1e3:g} | {r['web'][i] * 1e3:.3g} | {r['p0'][i] / 1e6:.1f} | "
              f"{100 * r['dp0'][i]:.4f} | {r['a'][i] * 1e6:.2f} | {100 * r['da'][i]:.4f} | "
              f"{r['delta'][i] * 1e6:.2f} / "
              f"{r['delta_local'][i] * 1e6:.2f} | {r['hoop_refined'][i] / 1e6:.1f} / "
              f"{r['hoop_global_at_theta'][i] / 1e6:.1f} | {r['hoop_max_rev'][i] / 1e6:.1f} at "
              f"{math.degrees(r['theta_hoop_max_rev'][i]):.0f} | {r['shaft_p0'][i] / 1e6:.1f}, "
              f"{math.degrees(r['shaft_arc'][i]):.0f} | {r['t_refined'][i]:.2f} / {r['t_global'][i]:.2f} / "
              f"{r['t_rev'][i]:.2f} |")
    print("wrote", plot_web(r, img / "cam_disk_web.png"))
    m, res = refined_at(case, disk_from_case(case), at)
    with tempfile.TemporaryDirectory() as tmp:
        vtu = write_cam_vtu(Path(tmp) / "cam_disk.vtu", m, res)
        print("wrote", plot_cam_hoop(vtu, img / "cam_disk_hoop.png"))
    print(f"load average after {os.getloadavg()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
