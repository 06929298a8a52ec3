"""Figures of docs/bodies.md (PNG in docs/img/), with the numbers printed.

    PYTHONPATH=. python benchmarks/figures_bodies.py

* ``docs/img/bodies_wall_study.png``: the seed 002 roller (Rr = 10 mm, l = 10 mm) at its peak cam
  force, on a full complement of 1 mm needles and on a pin (c = 10 um): max tensile bore hoop
  stress and the change of p0 and a against the solid roller (Hertz), vs the ring wall.
* ``docs/img/bodies_hoop.png`` (+ ``docs/img/bodies_needle_roller.vtu`` is NOT kept: large): the
  hoop stress of the example needle roller's ring at the peak force, load line between two
  needles (the cage position with the larger bore stress).
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

from femcam.bodies import solve_ring  # noqa: E402
from femcam.bodies.rows import build_for  # noqa: E402
from femcam.bodies.study import wall_study  # noqa: E402
from femcam.io import write_ring_vtu  # noqa: E402
from femcam.scene import load_scene  # noqa: E402
from femcam.viz.bodies import plot_hoop, plot_wall_study  # noqa: E402


def main() -> int:
    img = ROOT / "docs" / "img"
    sc = load_scene(ROOT / "examples" / "seed002_needle_roller.toml")
    theta = np.radians(np.arange(0.0, 360.0, 1.0))
    st = sc.analyse(theta)
    k = int(np.argmax(st.Fc))
    F, rho = float(st.Fc[k]), float(st.rho[k])
    print(f"peak cam force {F:.1f} N at theta = {math.degrees(theta[k]):.0f} deg, rho = {rho * 1e3:.2f} mm; "
          f"load avg {os.getloadavg()[0]:.2f}")
    m = build_for(sc.bodies.roller, sc.pair, st.Fc, st.rho)
    r = solve_ring(m, F=F, rho=rho, cage=math.pi / sc.bodies.roller.Z)
    print(f"needle roller, load between needles: bore hoop max {r.hoop_max / 1e6:.1f} MPa at "
          f"{math.degrees(r.hoop_theta) + 90:.1f} deg from the load line; Q_max {r.needle_Q_max:.0f} N")
    with tempfile.TemporaryDirectory() as d:
        vtu = write_ring_vtu(Path(d) / "ring.vtu", m, r)
        lim = 1.2 * r.hoop_max / 1e6
        plot_hoop(vtu, img / "bodies_hoop.png", clim=(-lim, lim))
    walls = np.array([1.5, 2.0, 2.5, 3.0, 4.0, 5.0]) * 1e-3
    studies = {}
    for label, support in (("needles (r_n = 1 mm, full complement)", "needles"), ("pin, c = 10 um", "pin")):
        s = wall_study(Ro=0.01, walls=walls, support=support, F=F, rho=rho, length=sc.length, cam=sc.cam,
                       ring=sc.roller, pin=sc.bodies.roller.pin, c=10e-6)
        studies[label] = s
        print(f"\n{label}\n| wall (mm) | bore hoop max (MPa) | p0 vs solid (%) | a vs solid (%) | "
              "Q_max (N) | DOFs |\n|---|---|---|---|---|---|")
        for i in range(walls.size):
            dp0 = 100 * (s["p0"][i] / s["p0_solid"][i] - 1)
            da = 100 * (s["a"][i] / s["a_solid"][i] - 1)
            print(f"| {s['wall'][i] * 1e3:.1f} | {s['hoop_max'][i] / 1e6:.0f} | {dp0:+.2f} | {da:+.2f}"
                  f" | {s['needle_Q_max'][i]:.0f} | {int(s['n_dofs'][i])} |")
    plot_wall_study(studies, img / "bodies_wall_study.png",
                    title=f"seed 002 roller Rr = 10 mm, F = {F:.0f} N (peak), l = 10 mm")
    print(f"\nload avg {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
