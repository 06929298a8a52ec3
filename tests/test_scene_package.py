"""femcam.scene as a package: the public names other modules import resolve, and the scene's
[fe]/[sweep] checks and SweepOptions accept and refuse the same values (one copy of each
range check, femcam.scene.schema.study_problem).

References: the accepted values are typed in here from the command line's documented choices
(``femcam sweep --method {fe,hertz,auto}``, ``--chunk-size >= 1``, ``--vtk-every >= 0``).
"""

from pathlib import Path

import pytest

import femcam.scene as scene_pkg
from femcam.errors import InputError, SceneError
from femcam.scene import load_scene
from femcam.sweep.options import SweepOptions

STUDY = (Path(__file__).resolve().parents[1] / "examples" / "seed002_study_model.toml").read_text()


def test_public_names_resolve_and_private_ones_are_not_re_exported():
    # the public names other modules and tests import from femcam.scene (grep of femcam/, tests/);
    # private helpers are imported from their own modules (scene.checker, scene.schema)
    for name in ("Scene", "SceneState", "load_scene", "wear_table", "roller_support_problems",
                 "MAX_PROBLEMS", "UNDERCUT_CHECK_N"):
        assert hasattr(scene_pkg, name), name
    for name in ("_Checker", "_WEAR", "_RANGES"):
        assert not hasattr(scene_pkg, name), name
    assert scene_pkg.UNDERCUT_CHECK_N == 7200 and scene_pkg.MAX_PROBLEMS == 20


def _load(tmp_path, extra):
    p = tmp_path / "scene.toml"
    p.write_text(STUDY + "\n" + extra)
    return load_scene(p)


@pytest.mark.parametrize("method", ["fe", "hertz", "auto"])
def test_scene_accepts_every_sweep_method(tmp_path, method):
    assert _load(tmp_path, f'[sweep]\nmethod = "{method}"').study.method == method
    assert SweepOptions(method=method).method == method


@pytest.mark.parametrize("key, good, bad", [("chunk_size", [1, 7], [0, 2.5, -3]),
                                            ("vtk_every", [0, 5], [-1, 0.5]),
                                            ("a_over_h", [2, 400], [1.99, 400.5]),
                                            ("tolerance", [1e-4, 0.5], [9e-5, 0.51])])
def test_scene_and_sweep_options_agree(tmp_path, key, good, bad):
    table = "fe" if key in ("a_over_h", "tolerance") else "sweep"
    for v in good:
        assert getattr(SweepOptions(**{key: v}), key) == v
        assert getattr(_load(tmp_path, f"[{table}]\n{key} = {v}").study, key) == v
    for v in bad:
        with pytest.raises(InputError, match=f"^{key} = "):
            SweepOptions(**{key: v})
        with pytest.raises(SceneError, match=f"{table}.{key} = "):
            _load(tmp_path, f"[{table}]\n{key} = {v}")
