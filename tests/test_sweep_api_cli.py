"""The library equals the CLI (issue 24 item 6): ``femcam.sweep(path, ...)`` and ``femcam sweep
path`` resolve the scene's ``[fe]``/``[sweep]`` settings by one rule
(:func:`femcam.sweep.settings.resolve_settings`: given > scene > default) and write the same rows.

References: the expected settings are typed from the scene text written here and from the
defaults documented in docs/sweep.md (a_over_h 10, tolerance 0.2 %, 30 angles a chunk); the two
tables are compared cell by cell except the wall-clock columns (``femcam.sweep.table.WALL_CLOCK``).
"""

import csv
from pathlib import Path

import numpy as np
import pytest

import femcam
from femcam.cli import main
from femcam.errors import InputError
from femcam.scene import load_scene
from femcam.sweep.settings import resolve_settings
from femcam.sweep.table import WALL_CLOCK

STUDY = (Path(__file__).resolve().parents[1] / "examples" / "seed002_study_model.toml").read_text()

HERTZ = ("[fe]\na_over_h = 12\ntolerance = 1e-3\n[sweep]\nmethod = \"hertz\"\n"
         "angles_deg = \"0:360:30\"\nchunk_size = 5\nvtk_every = 0\nplots = false\n")
#: a small FE case: three angles on the rise, a coarse mesh
FE = "[fe]\na_over_h = 6\n[sweep]\nmethod = \"fe\"\nangles_deg = \"40:60:10\"\nvtk_every = 0\nplots = false\n"


def _scene(tmp_path, extra: str) -> Path:
    p = tmp_path / "scene.toml"
    p.write_text(STUDY + "\n" + extra)
    return p


def _rows(out: Path) -> list[dict]:
    """sweep.csv's rows without the wall-clock columns (``fe_time_ms``, ``build_time_ms``)."""
    with open(out / "sweep.csv", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    return [{k: v for k, v in r.items() if not k.startswith(WALL_CLOCK)} for r in rows]


def _both(tmp_path, scene, options=None, flags=()):
    """(API result, API rows, CLI rows) of the same scene, settings and overrides."""
    r = femcam.sweep(str(scene), options,
                     femcam.RunOptions(out=tmp_path / "api", progress=False, model_cache=False))
    code = main(["sweep", str(scene), "--out", str(tmp_path / "cli"), "--progress", "off",
                 "--no-cache", *flags])
    assert code == 0
    return r, _rows(tmp_path / "api"), _rows(tmp_path / "cli")


def test_hertz_rows_equal_with_scene_settings(tmp_path):
    r, api, cli = _both(tmp_path, _scene(tmp_path, HERTZ))
    assert len(api) == 12 and api == cli
    assert r.method == "hertz" and not (tmp_path / "api" / "plots").exists()
    o = r.provenance["options"]
    assert (o["a_over_h"], o["tolerance"], o["chunk_size"], o["vtk_every"]) == (12.0, 1e-3, 5, 0)
    assert set(o["settings"]["sources"].values()) == {"scene", "default"}
    assert o["settings"]["sources"]["method"] == "scene"
    assert o["settings"]["values"]["angles_deg"] == "0:360:30"


def test_explicit_keyword_overrides_the_scene_like_the_flag(tmp_path):
    r, api, cli = _both(tmp_path, _scene(tmp_path, HERTZ),
                        femcam.SweepOptions(angles=np.radians([0.0, 90.0]), chunk_size=1),
                        ("--angles-deg", "0:90:90", "--chunk-size", "1"))
    assert len(api) == 2 and api == cli
    assert r.provenance["options"]["chunk_size"] == 1
    assert r.provenance["options"]["settings"]["sources"]["chunk_size"] == "argument"


def test_fe_rows_equal_with_scene_settings(tmp_path):
    r, api, cli = _both(tmp_path, _scene(tmp_path, FE))
    assert len(api) == 3 and api == cli
    assert r.method == "fe" and r.provenance["options"]["a_over_h"] == 6.0
    assert np.isfinite(r.table["p0_fe"]).all()


@pytest.mark.parametrize("study", [HERTZ, FE], ids=["hertz", "fe"])
def test_sweep_of_a_path_without_options_equals_the_cli(tmp_path, monkeypatch, study):
    """``femcam.sweep(path)``, no options at all (in memory, the default model cache), computes
    the rows of ``femcam sweep path``: every numeric column of the two tables bit-identical but
    the wall-clock ones (the CLI's own table, taken from the sweep it runs)."""
    import femcam.cli.sweep as cli_sweep

    monkeypatch.setenv("FEMCAM_CACHE_DIR", str(tmp_path / "cache"))
    path = _scene(tmp_path, study)
    r = femcam.sweep(path)
    seen = []
    monkeypatch.setattr(cli_sweep, "sweep", lambda *a, **k: seen.append(femcam.sweep(*a, **k)) or seen[-1])
    assert main(["sweep", str(path), "--out", str(tmp_path / "cli"), "--progress", "off"]) == 0
    cli = seen[0].table
    numeric = [k for k, v in r.table.items() if np.asarray(v).dtype.kind in "fiub"
               and not k.startswith(WALL_CLOCK)]
    assert "p0_hertz" in numeric and len(numeric) > 10 and sorted(cli) == sorted(r.table)
    for k in numeric:
        np.testing.assert_array_equal(np.asarray(cli[k]), np.asarray(r.table[k]), err_msg=k)


def test_old_keywords_are_gone_and_options_are_typed(tmp_path):
    """No keyword style besides the two records: a stray keyword is Python's TypeError, a
    record of the wrong kind an InputError naming the parameter."""
    path = _scene(tmp_path, HERTZ)
    with pytest.raises(TypeError):
        femcam.sweep(path, angles=[0.0])
    with pytest.raises(InputError, match="options = 'dict': must be a SweepOptions"):
        femcam.sweep(path, {"angles": [0.0]})
    with pytest.raises(InputError, match="run = 'SweepOptions': must be a RunOptions"):
        femcam.sweep(path, femcam.SweepOptions(), femcam.SweepOptions())


def test_defaults_without_scene_settings(tmp_path):
    st = resolve_settings(load_scene(_scene(tmp_path, "")), {})
    assert (st.a_over_h, st.tolerance, st.chunk_size, st.vtk_every, st.method, st.plots, st.rtol) == \
        (10.0, 2e-3, 30, 10, "fe", True, None)
    assert st.angles.size == 360 and set(st.sources.values()) == {"default"} and st.from_scene == ()


def test_rtol_against_a_over_h(tmp_path):
    """rtol chooses the mesh: one given beats the scene's other key; both given, or both in the
    scene, refused; the scene's rtol_pct is dropped under method hertz (the CLI's rule)."""
    sc = load_scene(_scene(tmp_path, "[fe]\nrtol_pct = 1\n"))
    assert resolve_settings(sc, {}).rtol == pytest.approx(0.01)
    assert resolve_settings(sc, {}).tolerance == pytest.approx(0.005)   # rtol / 2
    st = resolve_settings(sc, {"a_over_h": 14.0})
    assert (st.rtol, st.a_over_h) == (None, 14.0)
    assert resolve_settings(sc, {"method": "hertz"}).rtol is None
    sc2 = load_scene(_scene(tmp_path, "[fe]\na_over_h = 20\n"))
    assert resolve_settings(sc2, {"rtol": 0.01}).rtol == 0.01
    with pytest.raises(InputError, match="rtol = 0.01 .*cannot be given with a_over_h = 10"):
        resolve_settings(sc2, {"rtol": 0.01, "a_over_h": 10.0})
    sc3 = load_scene(_scene(tmp_path, "[fe]\nrtol_pct = 1\na_over_h = 20\n"))
    with pytest.raises(InputError, match=r"\[fe\] rtol_pct = 1 %: cannot be given with \[fe\] a_over_h"):
        resolve_settings(sc3, {})
    assert resolve_settings(sc3, {"a_over_h": 8.0}).a_over_h == 8.0


def test_check_refuses_what_the_sweep_refuses(tmp_path, capsys):
    """`femcam check` reads the [fe]/[sweep] settings as the sweep does: a scene giving both
    rtol_pct and a_over_h fails the check with the sweep's one line, not only the sweep."""
    path = _scene(tmp_path, "[fe]\nrtol_pct = 0.5\na_over_h = 12\n")
    assert main(["check", str(path)]) == 1
    err = capsys.readouterr().err
    assert "[fe] rtol_pct = 0.5 %: cannot be given with [fe] a_over_h" in err
    assert len(err.strip().splitlines()) == 1


def test_mesh_size_flag_is_gone(tmp_path, capsys):
    """One name per quantity: the scene key [fe] a_over_h is the flag --a-over-h; the old
    --mesh-size is an unknown argument (argparse's exit 2), not an abbreviation of another flag."""
    path = _scene(tmp_path, HERTZ)
    with pytest.raises(SystemExit) as exc:
        main(["sweep", str(path), "--out", str(tmp_path / "o"), "--mesh-size", "8"])
    assert exc.value.code == 2
    assert "unrecognized arguments: --mesh-size 8" in capsys.readouterr().err
    assert main(["sweep", str(path), "--out", str(tmp_path / "o"), "--a-over-h", "8",
                 "--progress", "off"]) == 0
