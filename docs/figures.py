"""Every figure of ``docs/img/``: the command that draws it and a fingerprint of its source data.

A figure in the docs is only as true as the numbers it was drawn from. Each entry of
:data:`FIGURES` names the producer (a benchmark script, a femcam subcommand or a viz function)
and the sources of its numbers:

* ``files``: the scene files and the producer script it reads (their bytes are hashed);
* ``data``: the plotted numbers themselves, recomputed here where that is cheap (motion laws,
  kinematics, profile and contact force, Hertz, seed 000's table, the follower dynamics), or,
  for figures drawn from FE, half-space or ring solves, the analytic quantities they are drawn
  against (the Hertz curves over the same angles), which change whenever the scene, the
  kinematics or the loads do.

The fingerprint is the SHA-256 of both, with the numbers written to 8 significant digits.
``docs/figures.json`` holds the fingerprints the figures were drawn with, and
``tests/test_figures.py`` fails when a figure's sources changed since (redraw it with its
producer, then record) or when a PNG in ``docs/img/`` has no entry here.

    python docs/figures.py            # list figures whose sources changed
    python docs/figures.py --record   # after redrawing: store the fingerprints, write docs/figures.md
"""

from __future__ import annotations

import hashlib
import json
import sys
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
IMG = DOCS / "img"
RECORD = DOCS / "figures.json"
PAGE = DOCS / "figures.md"

STUDY = "examples/seed002_study_model.toml"


@dataclass(frozen=True)
class Figure:
    """One PNG of docs/img: who draws it and from what."""

    name: str                      #: file name in docs/img
    producer: str                  #: the command or function that draws it
    files: tuple = ()              #: scene files and scripts it reads (paths from the repo root)
    data: tuple = ()               #: (function name, arguments) of the numbers below
    caption: str = ""
    extra: dict = field(default_factory=dict)


# --- the numbers -----------------------------------------------------------------------------

def _scene(path, law=None):
    from femcam.scene import load_scene

    sc = load_scene(ROOT / path)
    return sc.with_law(law) if law else sc


def laws():
    """Normalised s, v, a, j of the laws of femcam.viz.analytic.plot_laws."""
    from femcam.kinematics import law
    from femcam.viz.analytic import LAWS_FIGURE

    u = np.linspace(0.0, 1.0, 401)
    return [np.asarray(getattr(law(n), k)(u)) for n in LAWS_FIGURE for k in ("s", "v", "a", "j")]


def analysis(path, step_deg=1.0, law=None):
    """Kinematics, profile and contact force of a scene over one revolution."""
    st = _scene(path, law).analyse(np.radians(np.arange(0.0, 360.0, step_deg)))
    return [st.s, st.v, st.a, st.j, st.phi, st.rho, st.Fc]


def hertz(path, step_deg=1.0, law=None):
    """Hertz half-width and peak pressure of a scene over one revolution (the curve FE is drawn on)."""
    from femcam.hertz import LineContact

    sc = _scene(path, law)
    st = sc.analyse(np.radians(np.arange(0.0, 360.0, step_deg)))
    ok = st.Fc > 0
    hc = LineContact(F=st.Fc[ok], length=sc.length, R1=st.rho[ok], R2=sc.follower.Rr,
                     cam=sc.cam, roller=sc.roller, mu=sc.mu)
    return [st.Fc, st.rho, hc.a, hc.p0]


def hertz_pair():
    """The steel pair of the Hertz and FE figures: Rr = 10 mm, rho = 20 mm, 1500 N, l = 10 mm."""
    from femcam.hertz import LineContact
    from femcam.materials import STEEL

    hc = LineContact(F=1500.0, length=0.01, R1=0.02, R2=0.01, cam=STEEL, roller=STEEL, mu=0.2)
    return [hc.a, hc.p0]


def seed000():
    """Seed 000's table as recomputed by femcam wear seed000 (v_rms, S, W per law)."""
    from femcam.wear import seed000_table

    return [np.array([[v for v in vars(r).values() if isinstance(v, (int, float))]
                      for r in seed000_table().rows], dtype=float)]


def dynamics(path):
    """Contact force of the follower train over one revolution (periodic steady state)."""
    r = _scene(path).dynamic_response
    return [r.Fc_min, r.Fc_max]


# --- the figures -----------------------------------------------------------------------------

_RUN = f"femcam run {STUDY} (five analysis plots, file prefix seed002_)"
_SWEEP = f"femcam sweep {STUDY} --out DIR: DIR/plots/"
_REAL = "benchmarks/bench_real_cam.py --plots"

FIGURES = (
    Figure("kinematics_laws.png", "femcam.viz.analytic.plot_laws('docs/img/kinematics_laws.png')",
           data=("laws",)),
    *(Figure(f"seed002_{k}.png", _RUN, (STUDY,), ("analysis", STUDY)) for k in
      ("svaj", "phi", "rho", "fc", "cam")),
    Figure("hertz_tau1.png", "benchmarks/bench_hertz.py --figure docs/img/hertz_tau1.png",
           ("benchmarks/bench_hertz.py",), ("hertz_pair",)),
    Figure("fe_von_mises.png", "femcam.viz.fe.plot_von_mises(r, 'docs/img/fe_von_mises.png') on the "
           "steel pair (docs/fe.md)", (), ("hertz_pair",)),
    Figure("sweep_p0.png", _SWEEP + "p0_vs_angle.png", (STUDY,), ("hertz", STUDY)),
    Figure("sweep_maxima.png", _SWEEP + "maxima_vs_angle.png", (STUDY,), ("hertz", STUDY)),
    Figure("sweep_surface_worst.png", _SWEEP + "surface_stress_worst.png", (STUDY,), ("hertz", STUDY)),
    Figure("sweep_svaj_loads.png", _SWEEP + "svaj_loads.png", (STUDY,), ("analysis", STUDY)),
    Figure("sweep_bezier.png", "benchmarks/bench_sweep.py (writes docs/img/sweep_bezier.png)",
           (STUDY, "benchmarks/bench_sweep.py"), ("hertz_laws", STUDY)),
    Figure("sweep_junction_p0.png", _REAL,
           ("examples/shm_dwell_junction.toml", "benchmarks/bench_real_cam.py"),
           ("hertz", "examples/shm_dwell_junction.toml")),
    Figure("fe_junction_p0.png", _REAL, ("examples/shm_dwell_junction.toml", "benchmarks/bench_real_cam.py"),
           ("hertz", "examples/shm_dwell_junction.toml")),
    Figure("fe_carter.png", _REAL, ("examples/shm_dwell_junction.toml", "benchmarks/bench_real_cam.py")),
    Figure("fe_followers.png", _REAL, ("examples/seed003_knife_edge.toml", "examples/flat_faced.toml",
                                       "benchmarks/bench_real_cam.py"),
           ("analysis", "examples/seed003_knife_edge.toml")),
    Figure("sweep_knife_edge_p0.png", "benchmarks/bench_real_cam.py (sweep_follower_plots)",
           ("examples/seed003_knife_edge.toml", "benchmarks/bench_real_cam.py"),
           ("analysis", "examples/seed003_knife_edge.toml")),
    Figure("sweep_flat_faced_p0.png", "benchmarks/bench_real_cam.py (sweep_follower_plots)",
           ("examples/flat_faced.toml", "benchmarks/bench_real_cam.py"),
           ("analysis", "examples/flat_faced.toml")),
    Figure("speed_error.png", "benchmarks/bench_speed_error.py --plot docs/img/speed_error.png",
           (STUDY, "benchmarks/bench_speed_error.py"), ("hertz_pair",)),
    Figure("bodies_wall_study.png", "benchmarks/figures_bodies.py",
           ("examples/seed002_needle_roller.toml", "benchmarks/figures_bodies.py"),
           ("analysis", "examples/seed002_needle_roller.toml")),
    Figure("bodies_hoop.png", "benchmarks/figures_bodies.py",
           ("examples/seed002_needle_roller.toml", "benchmarks/figures_bodies.py"),
           ("analysis", "examples/seed002_needle_roller.toml")),
    Figure("cam_disk_web.png", "benchmarks/figures_cam_disk.py",
           ("examples/seed002_cam_on_shaft.toml", "benchmarks/figures_cam_disk.py"),
           ("analysis", "examples/seed002_cam_on_shaft.toml")),
    Figure("cam_disk_hoop.png", "benchmarks/figures_cam_disk.py",
           ("examples/seed002_cam_on_shaft.toml", "benchmarks/figures_cam_disk.py"),
           ("analysis", "examples/seed002_cam_on_shaft.toml")),
    Figure("layers_seed002.png", "benchmarks/fig_layers.py",
           ("examples/seed002_coated.toml", "benchmarks/fig_layers.py"),
           ("hertz", "examples/seed002_coated.toml")),
    Figure("layers_reference.png",
           "benchmarks/fig_layers.py (FE vs tests/test_layers.py's layered half-space)",
           ("benchmarks/fig_layers.py", "tests/test_layers.py")),
    Figure("halfspace_crowns.png", "benchmarks/bench_halfspace.py",
           ("examples/seed002_crowned.toml", "benchmarks/bench_halfspace.py"), ("hertz", STUDY)),
    Figure("halfspace_peak_vs_angle.png", "benchmarks/bench_halfspace.py",
           ("examples/seed002_crowned.toml", "benchmarks/bench_halfspace.py"), ("hertz", STUDY)),
    Figure("halfspace_map_worst.png", "benchmarks/bench_halfspace.py",
           ("examples/seed002_crowned.toml", "benchmarks/bench_halfspace.py"), ("hertz", STUDY)),
    Figure("extras_assess.png", "femcam sweep examples/seed002_assess.toml: DIR/plots/extras_assess.png",
           ("examples/seed002_assess.toml",), ("hertz", "examples/seed002_assess.toml")),
    Figure("extras_halfspace.png",
           "femcam sweep examples/seed002_crowned.toml: DIR/plots/extras_halfspace.png",
           ("examples/seed002_crowned.toml",), ("hertz", "examples/seed002_crowned.toml")),
    Figure("extras_bodies.png",
           "femcam sweep examples/seed002_needle_roller.toml: DIR/plots/extras_bodies.png",
           ("examples/seed002_needle_roller.toml",), ("hertz", "examples/seed002_needle_roller.toml")),
    Figure("extras_layers.png", "femcam sweep examples/seed002_coated.toml: DIR/plots/extras_layers.png",
           ("examples/seed002_coated.toml",), ("hertz", "examples/seed002_coated.toml")),
    Figure("dynamics_seed002_force.png", "benchmarks/bench_dynamics.py --figures docs/img",
           ("examples/seed002_dynamic.toml", "benchmarks/bench_dynamics.py"),
           ("dynamics", "examples/seed002_dynamic.toml")),
    Figure("dynamics_rpm_sweep.png", "benchmarks/bench_dynamics.py --figures docs/img",
           ("examples/seed002_dynamic.toml", "benchmarks/bench_dynamics.py"),
           ("dynamics", "examples/seed002_dynamic.toml")),
    *(Figure(f"assess_{k}.png", "benchmarks/bench_assess.py --figures docs/img (femcam.viz.assess)",
             ("examples/seed002_assess.toml", "benchmarks/bench_assess.py"),
             ("hertz", "examples/seed002_assess.toml"))
      for k in ("lambda", "temperature", "safety", "outline")),
    Figure("assess_flat_lambda.png", "benchmarks/bench_assess.py --figures docs/img",
           ("benchmarks/bench_assess.py",)),
    Figure("wear_laws.png", "femcam wear seed000 --out DIR: DIR/wear_laws.png", (), ("seed000",)),
    Figure("wear_map_bezier5.png", f"femcam wear map {STUDY} --out DIR: DIR/wear_bezier5.png",
           (STUDY,), ("hertz", STUDY)),
    Figure("wear_polar_bezier5.png", f"femcam wear map {STUDY} --out DIR: DIR/wear_bezier5_polar.png",
           (STUDY,), ("hertz", STUDY)),
    Figure("optimise_svaj.png", "benchmarks/fig_optimise.py", (STUDY, "benchmarks/fig_optimise.py"),
           ("analysis", STUDY)),
    *(Figure(f"study_{k}_seed002.png", "benchmarks/bench_study.py --n 0 --figures docs/img",
             (STUDY, "benchmarks/bench_study.py"), ("analysis", STUDY))
      for k in ("pareto", "constraint_map")),
    *(Figure(f"{n}.png", f"femcam synth --case seed003 --out DIR --study: DIR/{n}.png",
             ("examples/seed003_knife_edge.toml",), ("analysis", "examples/seed003_knife_edge.toml"))
      for n in ("synth_curve", "synth_error_phi", "synth_study_k", "synth_study_k_mu")),
)


def hertz_laws(path):
    """Hertz p0 of the study model with each of bezier5, 7, 9 (the three curves of sweep_bezier)."""
    return [x for law in ("bezier5", "bezier7", "bezier9") for x in hertz(path, law=law)]


_DATA = {"laws": laws, "analysis": analysis, "hertz": hertz, "hertz_pair": hertz_pair,
         "hertz_laws": hertz_laws, "seed000": seed000, "dynamics": dynamics}


def _numbers(arrays) -> bytes:
    flat = np.concatenate([np.atleast_1d(np.asarray(a, dtype=float)).ravel() for a in arrays])
    return " ".join(f"{v:.8g}" for v in flat).encode()


def fingerprint(fig: Figure, cache: dict | None = None) -> str:
    """SHA-256 of the figure's source files (bytes, line endings normalised) and numbers."""
    cache = {} if cache is None else cache
    h = hashlib.sha256()
    for rel in fig.files:
        h.update(rel.encode() + b"\0" + (ROOT / rel).read_bytes().replace(b"\r\n", b"\n") + b"\0")
    if fig.data:
        if fig.data not in cache:
            cache[fig.data] = _numbers(_DATA[fig.data[0]](*fig.data[1:]))
        h.update(cache[fig.data])
    return h.hexdigest()


def current() -> dict:
    cache: dict = {}
    return {f.name: fingerprint(f, cache) for f in FIGURES}


def page(prints: dict) -> str:
    """docs/figures.md: one row per figure."""
    rows = ["# Figures and their sources", "",
            "Every figure of the docs, the command or function that draws it, the sources of its",
            "numbers and their fingerprint (SHA-256, first 12 hex digits). Generated by",
            "`python docs/figures.py --record`; `tests/test_figures.py` fails when a figure's",
            "sources changed since it was drawn, or when a figure has no entry.", "",
            "| figure | drawn by | source files | numbers | fingerprint |", "|---|---|---|---|---|"]
    for f in FIGURES:
        files = ", ".join(f"`{p}`" for p in f.files) or "-"
        data = f"`{f.data[0]}({', '.join(map(str, f.data[1:]))})`" if f.data else "-"
        rows.append(f"| [{f.name}](img/{f.name}) | `{f.producer}` | {files} | {data} | "
                    f"`{prints[f.name][:12]}` |")
    return "\n".join(rows) + "\n"


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    now = current()
    if "--record" in argv:
        RECORD.write_text(json.dumps(now, indent=1, sort_keys=True) + "\n", encoding="utf-8")
        PAGE.write_text(page(now), encoding="utf-8")
        print(f"recorded {len(now)} fingerprints in {RECORD.relative_to(ROOT)}; "
              f"wrote {PAGE.relative_to(ROOT)}")
        return 0
    old = json.loads(RECORD.read_text(encoding="utf-8")) if RECORD.exists() else {}
    stale = sorted(n for n in now if old.get(n) != now[n])
    for n in stale:
        print(f"{n}: sources changed; redraw with: {next(f.producer for f in FIGURES if f.name == n)}")
    return 1 if stale else 0


if __name__ == "__main__":
    raise SystemExit(main())
