"""Peak memory (RSS) of a long Hertz sweep written to disk, against the number of angles.

Each size runs in a fresh interpreter (``ru_maxrss`` is a per-process peak). Correctness first:
the CSV must have one row per angle, its ``theta_deg`` column must equal the requested angles
(to the CSV's 10 significant digits) and every row must be ``ok``, ``liftoff`` or
``undercut``. Then the table: angles, wall time, peak RSS, RSS above the 1 000-angle run per
angle, and the machine's load average (the machine is shared: times are indicative only).

    PYTHONPATH=$PWD python benchmarks/bench_sweep_memory.py [N ...] [--root DIR ...]

``--root DIR`` (repeatable) times the femcam of another source tree as well (e.g. an earlier
commit unpacked with ``git archive C | tar -x -C DIR``) for a before/after table. From 20 000
angles on, a sweep into an output directory keeps its table on disk
(``femcam.sweep.store.StoredTable``): the RSS above the 1 000-angle run is then the analytic
chain's per-angle state (transient) and the per-angle inputs of the chunks, not the table.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CHILD = r"""
import json, resource, sys, time
import numpy as np
from femcam.sweep import RunOptions, SweepOptions, sweep
n, out = int(sys.argv[1]), sys.argv[2]
th = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
t0 = time.perf_counter()
sweep(str(sys.argv[3]), SweepOptions(angles=th, method="hertz", chunk_size=1000, vtk_every=0,
                                     plots=False), RunOptions(out=out, workers=1))
dt = time.perf_counter() - t0
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # before the check below
csv = np.genfromtxt(f"{out}/sweep.csv", delimiter=",", names=True, comments="#", dtype=None,
                    encoding="utf-8")
ok = bool(csv.size == n and np.allclose(csv["theta_deg"], np.degrees(th), rtol=1e-9, atol=1e-7)
          and set(np.asarray(csv["status"]).astype(str)) <= {"ok", "liftoff", "undercut"})
print(json.dumps({"n": n, "s": dt, "rss_MB": rss,
                  "ok": ok}))
"""


def run(n: int, scene: Path, root: Path = ROOT) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        p = subprocess.run([sys.executable, "-c", CHILD, str(n), str(Path(tmp) / "out"), str(scene)],
                           capture_output=True, text=True, env={**os.environ, "PYTHONPATH": str(root)},
                           check=True, cwd=root)
    return json.loads(p.stdout.strip().splitlines()[-1])


def main(sizes, roots) -> int:
    scene = ROOT / "examples" / "seed002_study_model.toml"
    print(f"machine: {platform.machine()} {platform.system()}, {os.cpu_count()} CPUs; "
          f"load average {os.getloadavg()[0]:.2f} (shared machine)")
    print("| femcam tree | angles | time (s) | peak RSS (MB) | RSS above the first row per angle (kB) |")
    print("|---|---:|---:|---:|---:|")
    for root in roots:
        rows = [run(n, scene, root) for n in sizes]
        bad = [r["n"] for r in rows if not r["ok"]]
        if bad:
            print(f"CSV check failed for n = {bad} ({root})")
            return 1
        base = rows[0]
        name = "this tree" if root == ROOT else str(root)
        for r in rows:
            per = (r["rss_MB"] - base["rss_MB"]) * 1024 / max(1, r["n"] - base["n"]) if r is not base else 0.0
            print(f"| {name} | {r['n']} | {r['s']:.1f} | {r['rss_MB']:.0f} | {per:.2f} |", flush=True)
    print(f"load average at the end {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("sizes", nargs="*", type=int, default=[1000, 10000, 100000])
    ap.add_argument("--root", type=Path, action="append", default=None)
    a = ap.parse_args()
    sys.exit(main(a.sizes, [ROOT, *(a.root or [])]))
