"""Design studies (femcam.study): validation against independent references, reproducibility,
resume, dedup and bad input. Hertz-only studies of a few dozen variants (well under a second
each); the Dask study of >= 1000 variants and the FE candidates are marked slow."""

import math
import pickle
from pathlib import Path

import numpy as np
import pytest
import tomllib

import femcam.study.run as study_run
from femcam.cli import main
from femcam.errors import ConvergenceError, InputError
from femcam.io import read_csv
from femcam.profile import min_base_radius
from femcam.scene import Scene, load_scene
from femcam.study import Constraints, StudySpec, pareto_mask, parse_vary, run_study
from femcam.study.variants import to_toml

ROOT = Path(__file__).resolve().parents[1]
SEED002 = ROOT / "examples" / "seed002_study_model.toml"


def _same_tables(t1: dict, t2: dict) -> None:
    assert t1.keys() == t2.keys()
    for k in t1:
        a, b = np.asarray(t1[k]), np.asarray(t2[k])
        if a.dtype.kind == "f":
            np.testing.assert_array_equal(a, b, err_msg=k)  # bit-identical: same inputs, same numbers
        else:
            assert a.tolist() == b.tolist(), k


def test_smallest_feasible_base_circle_brackets_min_base_radius():
    """The smallest base radius of a 0.25 mm grid with phi <= 30 deg lies within one step above
    the closed-form optimum of a cycloidal rise (in-line roller), which also matches
    femcam.profile.min_base_radius."""
    h, beta, Rr = 10e-3, math.radians(100.0), 10e-3
    # closed form (Norton ch. 8): tan(phi) = s' / (Rp + s) <= tan(30 deg)  <=>  Rp >= s'/tan30 - s;
    # cycloidal rise s = h (u - sin(2 pi u)/(2 pi)), s' = (h/beta)(1 - cos(2 pi u)); the fall is the mirror
    u = np.linspace(0.0, 1.0, 2_000_001)
    s = h * (u - np.sin(2 * np.pi * u) / (2 * np.pi))
    s1 = h / beta * (1.0 - np.cos(2 * np.pi * u))
    Rb_exact = np.max(s1 / math.tan(math.radians(30.0)) - s) - Rr
    base = load_scene(SEED002).with_law("cycloidal")
    Rb_lib = min_base_radius("roller", base.program, phi_max=math.radians(30.0), Rr=Rr).Rb
    assert Rb_lib == pytest.approx(Rb_exact, rel=1e-6)  # 2e6 samples: ~1e-12 relative sampling error
    step = 0.25
    spec = StudySpec.parse(["program.law=cycloidal", "follower.base_radius_mm=3:8:0.25"])
    r = run_study(SEED002, spec, constraints=Constraints(phi_limit=math.radians(30.0)))
    ok = r.table["margin_phi"] >= 0
    Rb_grid = np.min(r.table["follower.base_radius_mm"][ok]) * 1e-3
    # the study samples 720 angles: phi near its peak is flat, so the sampled max is within
    # ~1e-5 relative of the true one; a 0.25 mm grid brackets the optimum to one step
    assert Rb_grid - step * 1e-3 < Rb_exact <= Rb_grid, (Rb_grid, Rb_exact)
    assert np.all(r.table["margin_phi"][~ok] < 0) and np.all(np.diff(r.table["phi_max"]) < 0)


def test_grid_and_lhs_variants():
    """A grid is the product of its lists; a Latin hypercube puts one sample in each of its N strata."""
    spec = StudySpec.parse(["follower.base_radius_mm=10:20:5", "program.law=bezier5,bezier7"])
    assert [tuple(v.values()) for v in spec.variants()] == [
        (10.0, "bezier5"), (10.0, "bezier7"), (15.0, "bezier5"), (15.0, "bezier7"), (20.0, "bezier5"),
        (20.0, "bezier7")]
    n = 50
    spec = StudySpec.parse(["follower.base_radius_mm=10:20", "dynamics.preload_N=1000:2000"], lhs=n, seed=3)
    v = spec.variants()
    for key, lo, hi in (("follower.base_radius_mm", 10, 20), ("dynamics.preload_N", 1000, 2000)):
        strata = np.floor((np.array([x[key] for x in v]) - lo) / (hi - lo) * n).astype(int)
        assert sorted(strata.tolist()) == list(range(n)), key  # the LHS property itself
    assert v == StudySpec.parse(["follower.base_radius_mm=10:20", "dynamics.preload_N=1000:2000"],
                                lhs=n, seed=3).variants()


def test_control_points_reproduce_the_named_bezier_laws():
    """Bernstein control points [0,0,0,1,1,1] and [0,0,0,0,1,1,1,1] are the laws bezier5 and
    bezier7 (seed 002 eq. 12): a control-point study gives the named-law rows exactly."""
    cp = run_study(SEED002, StudySpec.parse(["program.law=null",
                                             "program.control_points=[0,0,0,1,1,1];[0,0,0,0,1,1,1,1]"]))
    named = run_study(SEED002, StudySpec.parse(["program.law=bezier5,bezier7"]))
    for k in ("p0_max", "phi_max", "rho_min", "Fc_min"):
        np.testing.assert_allclose(cp.table[k], named.table[k], rtol=1e-12, err_msg=k)


def test_toml_round_trip_of_every_example():
    """The variant writer gives back exactly what tomllib parsed (every example scene)."""
    for f in sorted((ROOT / "examples").glob("*.toml")):
        raw = tomllib.loads(f.read_text(encoding="utf-8"))
        assert tomllib.loads(to_toml(raw)) == raw, f.name


def test_pareto_mask_against_brute_force():
    """The sweep-line Pareto set equals the O(n^2) definition of non-domination."""
    rng = np.random.default_rng(0)
    f1, f2 = rng.integers(0, 12, 200).astype(float), rng.integers(0, 12, 200).astype(float)
    cand = rng.random(200) < 0.8
    brute = np.array([cand[i] and not np.any(cand & (f1 <= f1[i]) & (f2 <= f2[i])
                                             & ((f1 < f1[i]) | (f2 < f2[i]))) for i in range(200)])
    # ties (equal in both): the definition keeps all copies, the sweep keeps one; compare sets of points
    assert {(a, b) for a, b in zip(f1[brute], f2[brute], strict=True)} == \
        {(a, b) for a, b in zip(*np.array([f1, f2])[:, pareto_mask(f1, f2, cand)], strict=True)}


def test_reproducible_with_one_and_two_workers(tmp_path):
    """Same inputs give a bit-identical table, serially and on two local processes."""
    spec = StudySpec.parse(["follower.base_radius_mm=8:14:2", "program.law=bezier5,bezier9"])
    a = run_study(SEED002, spec)
    b = run_study(SEED002, spec)
    c = run_study(SEED002, spec, scheduler="processes", workers=2, batch_size=2)
    _same_tables(a.table, b.table)
    _same_tables(a.table, pickle.loads(pickle.dumps(c)).table)  # results pickle (cross Dask)
    _same_tables(a.table, c.table)


def test_resume_after_a_kill_gives_the_same_table(tmp_path, monkeypatch):
    """A study killed after two batches resumes from its records and computes only the rest."""
    spec = StudySpec.parse(["follower.base_radius_mm=8:15:1"])
    full = run_study(SEED002, spec)
    real, calls = study_run.evaluate_batch, []

    def dying(task):
        calls.append(1)
        if len(calls) == 3:
            raise KeyboardInterrupt  # the kill, between two stored batches
        return real(task)

    monkeypatch.setattr(study_run, "evaluate_batch", dying)
    with pytest.raises(KeyboardInterrupt):
        run_study(SEED002, spec, out=tmp_path / "s", batch_size=2)
    assert len(list((tmp_path / "s" / "variants").glob("*.json"))) == 4
    (tmp_path / "s" / "variants" / "x.json.tmp").write_text("half a record")  # a killed write
    monkeypatch.setattr(study_run, "evaluate_batch", real)
    with pytest.raises(InputError, match="--resume"):
        run_study(SEED002, spec, out=tmp_path / "s", resume=False)
    res = run_study(SEED002, spec, out=tmp_path / "s", resume=True)
    assert (res.n_reused, res.n_computed) == (4, 4)
    _same_tables(full.table, res.table)
    cols, head = read_csv(tmp_path / "s" / "study.csv")
    np.testing.assert_allclose(cols["p0_max_MPa"], full.table["p0_max"] * 1e-6, rtol=1e-9)  # 10 digits
    assert "femcam" in head["versions"] and "constraints" in head["options"]


def test_duplicate_variants_are_computed_once():
    """10 and 10.0 are one variant (one content hash): computed once, two rows."""
    spec = StudySpec.parse(["follower.base_radius_mm=10,12,10.0"])
    r = run_study(SEED002, spec)
    assert (r.n_variants, r.n_unique, r.n_computed) == (3, 2, 2)
    assert r.table["duplicate_of"].tolist() == [-1, -1, 0]
    assert r.table["p0_max"][0] == r.table["p0_max"][2]


def test_bad_input_is_refused_with_the_key():
    with pytest.raises(InputError, match="did you mean follower.base_radius_mm"):
        run_study(SEED002, StudySpec.parse(["follower.base_radus_mm=10,12"]))
    with pytest.raises(InputError, match="did you mean program.segment.0.beta_deg"):
        run_study(SEED002, StudySpec.parse(["program.segmnt.0.beta_deg=90,100"]))
    with pytest.raises(InputError, match="empty"):
        parse_vary("follower.base_radius_mm=20:10:1")
    with pytest.raises(InputError, match="empty"):
        parse_vary("follower.base_radius_mm=")
    with pytest.raises(InputError, match="--lhs"):
        StudySpec.parse(["follower.base_radius_mm=10:20"])
    # a value the scene checker refuses on its own is refused up front, naming key, value and unit
    with pytest.raises(InputError, match=r"follower.base_radius_mm=-1: .*= -1 mm: must be > 0"):
        run_study(SEED002, StudySpec.parse(["follower.base_radius_mm=-1,10"]))
    with pytest.raises(InputError, match="phi_limit"):
        Constraints(phi_limit=0.0)


def test_refused_combination_and_failed_variant_are_recorded(monkeypatch):
    """Each value alone is a valid scene, but 170 + 120 deg leaves the first dwell negative:
    that variant is a 'refused' row; an evaluation error becomes a 'failed' row; none dropped."""
    spec = StudySpec.parse(["program.segment.0.beta_deg=100,170", "program.segment.2.beta_deg=100,120"])
    r = run_study(SEED002, spec)
    assert r.table["status"].tolist() == ["ok", "ok", "ok", "refused"]
    assert "program.segment[1].beta_deg" in r.table["reason"][3] and not r.table["feasible"][3]
    real = Scene.analyse

    def flaky(self, theta, **kw):
        if abs(self.follower.Rb - 0.012) < 1e-12:
            raise ConvergenceError("train response not periodic (test)")
        return real(self, theta, **kw)

    monkeypatch.setattr(Scene, "analyse", flaky)
    r = run_study(SEED002, StudySpec.parse(["follower.base_radius_mm=10,12,14"]))
    assert r.table["status"].tolist() == ["ok", "failed", "ok"]
    assert "ConvergenceError: train response not periodic" in r.table["reason"][1]


def test_infeasible_study_names_the_constraint():
    r = run_study(SEED002, StudySpec.parse(["follower.base_radius_mm=8:12:2"]),
                  constraints=Constraints(phi_limit=math.radians(5.0)))
    assert r.n_feasible == 0
    assert r.message.startswith("no feasible variant: the phi constraint fails in every variant")


def test_cli_study(tmp_path, capsys):
    out = tmp_path / "o"
    assert main(["study", str(SEED002), "--vary", "follower.base_radius_mm=9:12:1", "--vary",
                 "program.law=bezier5,bezier7", "--out", str(out), "--no-plots"]) == 0
    cols, head = read_csv(out / "study.csv")
    assert len(cols["variant"]) == 8 and "femcam study" in head["command"]
    assert cols["program.law"].tolist()[:2] == ["bezier5", "bezier7"]
    assert main(["study", str(SEED002), "--vary", "follower.base_radius_mm=9:12:1", "--out", str(out)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--resume" in err[0]
    # a bad key or flag is refused before anything is written: the directory is not created
    bad = tmp_path / "n"
    assert main(["study", str(SEED002), "--vary", "follower.base_radus_mm=9,10", "--out", str(bad)]) == 1
    assert main(["study", str(SEED002), "--vary", "follower.base_radius_mm=9,10", "--angles-per-rev", "5",
                 "--out", str(tmp_path / "n")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert "did you mean follower.base_radius_mm" in err[0] and "--angles-per-rev = 5" in err[1]
    assert not (tmp_path / "n").exists()


@pytest.mark.slow
def test_fe_candidates_and_plots(tmp_path):
    """The FE peak pressure of the best candidate agrees with its Hertz value (a convex cam on
    a roller is a Hertz line contact: within 1 % at a/h = 10, docs/fe.md), and the plots exist."""
    from femcam.study import FEOptions

    spec = StudySpec.parse(["follower.base_radius_mm=9:13:1", "follower.roller_radius_mm=8,10"])
    r = run_study(SEED002, spec, fe=FEOptions(top=2), out=tmp_path, plots=True)
    fe = np.isfinite(r.table["p0_fe"])
    assert fe.sum() == 2 and set(r.table["model"][fe]) == {"hertz+fe"}
    np.testing.assert_allclose(r.table["p0_fe"][fe], r.table["p0_max"][fe], rtol=1e-2,
                               err_msg="FE p0 against Hertz p0 (Johnson 1985 eq. 4.45)")
    assert Path(r.paths["pareto"]).stat().st_size > 0 and Path(r.paths["constraint_map"]).stat().st_size > 0


@pytest.mark.slow
def test_thousand_variants_on_a_dask_local_cluster():
    """>= 1000 LHS variants on a 2-worker Dask LocalCluster give the serial table exactly."""
    from dask.distributed import Client, LocalCluster

    spec = StudySpec.parse(["follower.base_radius_mm=8:20", "follower.roller_radius_mm=5:15",
                            "dynamics.preload_N=800:2000", "program.law=bezier5,bezier7,bezier9,cycloidal"],
                           lhs=1000, seed=1)
    serial = run_study(SEED002, spec)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as lc, \
            Client(lc) as client:
        dist = run_study(SEED002, spec, scheduler=client)
    assert dist.n_variants == 1000 and dist.n_computed == serial.n_unique
    _same_tables(serial.table, dist.table)
