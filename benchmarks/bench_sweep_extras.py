"""Cost of the sweep's extra column providers (femcam.sweep.extras), and the README figures.

For each example scene with a provider: a Hertz sweep with the providers and the same sweep of
the scene without them (the provider's keys removed), serial; first checks that the sweep's
columns equal the provider's direct call (correctness before timing), then prints the added
time per angle. Writes the provider plots of each run into docs/img/extras_<provider>.png.

    PYTHONPATH=. python benchmarks/bench_sweep_extras.py [--quick]
"""

from __future__ import annotations

import dataclasses
import os
import platform
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from femcam.assess import assess_rows
from femcam.halfspace.rows import finite_length_rows
from femcam.scene import contact_case, finite_case, load_scene
from femcam.sweep import RunOptions, SweepOptions, extras, sweep

ROOT = Path(__file__).resolve().parents[1]
QUICK = "--quick" in sys.argv
CASES = [  # (scene, provider, bare replacement, step_deg)
    ("seed002_assess", "assess", {"tribology": {}}, 1.0),
    ("seed002_crowned", "halfspace", {"finite_length": {}}, 1.0),
    ("seed002_needle_roller", "bodies", {"bodies": {}}, 10.0),
    ("seed002_coated", "layers", {"layers": {}}, 10.0),
]


def check(name, scene, theta, table):
    """The sweep's columns equal the provider's direct call (CSV-independent, SI)."""
    if name == "assess":
        d = assess_rows(contact_case(scene, theta))
        assert np.allclose(table["assess_lam"], d["lam"], rtol=1e-12, equal_nan=True)
    if name == "halfspace":   # each angle alone (the provider's cold start), every 30th angle
        strip = finite_case(scene).strip()
        for i in range(0, theta.size, 30):
            st = scene.analyse(theta[i:i + 1])
            d = finite_length_rows(strip, theta[i:i + 1], st.Fc, st.rho, scene.follower.Rr)
            assert np.allclose(table["hs_p_axial_peak"][i], d["p_axial_peak"][0], rtol=1e-12)


def run(step_override=None):
    rows = []
    for fname, prov, bare_kw, step in CASES:
        step = step_override or step
        scene = load_scene(ROOT / "examples" / f"{fname}.toml")
        bare = dataclasses.replace(scene, **bare_kw)
        assert [p.name for p in extras.providers_for(bare)] == []
        theta = np.radians(np.arange(0.0, 360.0, step))
        with tempfile.TemporaryDirectory() as d, tempfile.TemporaryDirectory() as d0:
            t0 = time.perf_counter()
            sweep(bare,
                  SweepOptions(angles=theta, method="hertz", plots=True),
                  RunOptions(workers=1, out=d0))
            t_bare = time.perf_counter() - t0
            t0 = time.perf_counter()
            r = sweep(scene,
                      SweepOptions(angles=theta, method="hertz", plots=True),
                      RunOptions(workers=1, out=d))
            t_with = time.perf_counter() - t0
            check(prov, scene, theta, r.table)
            png = r.paths.get(f"plot_extras_{prov}")
            if png:
                (ROOT / "docs" / "img").mkdir(parents=True, exist_ok=True)
                shutil.copy(png, ROOT / "docs" / "img" / f"extras_{prov}.png")
        rows.append((fname, prov, theta.size, t_bare, t_with, (t_with - t_bare) / theta.size))
    return rows


if __name__ == "__main__":
    rows = run(30.0 if QUICK else None)
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores (shared), "
          f"load average {os.getloadavg()}")
    print(f"{'scene':<24}{'provider':<11}{'angles':>7}{'bare s':>9}{'with s':>9}{'added ms/angle':>16}")
    for f, p, n, tb, tw, per in rows:
        print(f"{f:<24}{p:<11}{n:>7}{tb:>9.2f}{tw:>9.2f}{per * 1e3:>16.1f}")
    print("(both write CSV/NPZ and the plots; 'with' adds the provider's columns and its PNG)")
