"""The cam disk in `femcam sweep` (femcam.sweep.providers): checked first, then timed.

    PYTHONPATH=. python benchmarks/bench_cam_disk_sweep.py [--angles-deg 0:360:1]

For examples/seed002_cam_on_shaft.toml (bore 6 mm) and three shaft fits (contact line-to-line,
contact with a 20 um clearance, bonded), one `femcam sweep --method hertz` each (VTU every 10
angles). Checks before any time is printed: the largest ``bore_hoop_MPa`` of every
``vtk/camdisk_*.vtu`` equals the CSV's ``cam_bore_hoop_max_MPa`` of its row (1e-8), and the one-off
check of the local body (fully refined disk model at the peak force) did not flag the example.
Printed: the sweep's wall time, the check's time and numbers, the VTU count and time per VTU,
the largest bore hoop stress and shaft pressure over the revolution, the load average (the
machine is shared: times are not comparable between loads).
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import platform
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from femcam.cli import main  # noqa: E402

EXAMPLE = ROOT / "examples" / "seed002_cam_on_shaft.toml"
FITS = {"contact, c = 0": "", "contact, c = 20 um": "shaft_clearance_um = 20.0\n",
        "bonded": 'shaft_fit = "bonded"\n'}


def _rows(out: Path) -> list[dict]:
    return list(csv.DictReader(ln for ln in (out / "sweep.csv").read_text().splitlines()
                               if not ln.startswith("#")))


def run(label: str, extra: str, angles: str, tmp: Path) -> dict:
    import meshio  # the check reads the VTUs

    scene = tmp / f"{len(extra)}.toml"
    scene.write_text(EXAMPLE.read_text().replace("bore_mm = 6.0 ", "bore_mm = 6.0\n" + extra, 1))
    out = tmp / f"out{len(extra)}"
    t0 = time.perf_counter()
    assert main(["sweep", str(scene), "--out", str(out), "--method", "hertz", "--angles-deg", angles,
                 "--no-plots", "--workers", "1", "--vtk-every", "10", "--progress", "off"]) == 0
    wall = time.perf_counter() - t0
    load = os.getloadavg()
    rows = {float(r["theta_deg"]): r for r in _rows(out)}
    vtus = sorted((out / "vtk").glob("camdisk_*.vtu"))
    for p in vtus:
        deg = float(p.name.split("_")[2].replace("deg.vtu", ""))
        m = meshio.read(p)
        ref = float(rows[deg]["cam_bore_hoop_max_MPa"])
        assert abs(np.nanmax(m.point_data["bore_hoop_MPa"]) / ref - 1) < 1e-8, (p, ref)
    prov = json.loads(str(np.load(out / "sweep.npz")["provenance_json"]))
    check = prov["extras"]["cam_disk"]["check"]
    assert not check["exceeds"], check["line"]
    hoop = max(float(r["cam_bore_hoop_max_MPa"]) for r in rows.values())
    shaft = max(float(r["shaft_p0_MPa"]) for r in rows.values())
    return {"fit": label, "wall": wall, "check": check, "n_vtu": len(vtus), "hoop": hoop, "shaft": shaft,
            "load": load}


def vtu_time(n: int = 10) -> float:
    """Mean time (s) of one global-model VTU of the example (model built first, not timed)."""
    from femcam.bodies.cam_geometry import contact_frame
    from femcam.bodies.cam_global import CamGlobalModel
    from femcam.bodies.cam_rows import disk_from_case
    from femcam.io import write_global_cam_vtu
    from femcam.scene import cam_disk_case, load_scene

    sc = load_scene(EXAMPLE)
    g = CamGlobalModel.build(disk=disk_from_case(cam_disk_case(sc)), length=sc.length, plane=sc.plane)
    with tempfile.TemporaryDirectory() as d:
        C, nn, _, F = contact_frame(sc.analyse(np.array([0.0])))
        write_global_cam_vtu(Path(d) / "w.vtu", g, C, nn, F)  # builds the cached stress operator
        t0 = time.perf_counter()
        for k in range(n):
            C, nn, _, F = contact_frame(sc.analyse(np.array([0.6 * k])))
            write_global_cam_vtu(Path(d) / f"{k}.vtu", g, C, nn, F)
        return (time.perf_counter() - t0) / n


def main_bench() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--angles-deg", default="0:360:1")
    args = ap.parse_args()
    print(f"machine: {platform.node()} {platform.processor() or platform.machine()}, "
          f"{os.cpu_count()} CPUs (shared), python {platform.python_version()}")
    with tempfile.TemporaryDirectory() as d:
        res = [run(k, v, args.angles_deg, Path(d)) for k, v in FITS.items()]
    print("\n| shaft fit | sweep wall (s) | check: time (s), DOFs | check: p0 disk / local (MPa) | "
          "check: a disk / local (um) | contact move (um) | with the move: dp0, da | camdisk VTUs | "
          "max bore hoop (MPa) | max shaft p0 (MPa) | load average |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in res:
        c = r["check"]
        print(f"| {r['fit']} | {r['wall']:.2f} | {c['time_s']:.2f}, {c['n_dofs']} | "
              f"{c['p0_disk_MPa']:.2f} / {c['p0_local_MPa']:.2f} ({100 * c['dp0']:+.3f} %) | "
              f"{c['a_disk_um']:.2f} / {c['a_local_um']:.2f} ({100 * c['da']:+.3f} %) | {c['x0_um']:+.2f} | "
              f"{100 * c['dp0_moved']:+.3f} %, {100 * c['da_moved']:+.3f} % | "
              f"{r['n_vtu']} | {r['hoop']:.1f} | {r['shaft']:.1f} | {r['load'][0]:.1f} |")
    t = vtu_time()
    print(f"\none camdisk VTU (global model, one back-substitution + meshio write): {1e3 * t:.0f} ms, "
          f"load average {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main_bench()
