"""The complete scene printed in the docs (docs/scene.md; the README prints a shorter excerpt) is
a scene that loads, and it is the seed 002 study model of examples/: reference = the example
file, loaded independently, compared at every whole degree."""

import re
from pathlib import Path

import numpy as np
import pytest

from femcam.scene import load_scene

ROOT = Path(__file__).resolve().parents[1]


def _scene_blocks():
    """```toml blocks that start with a ``name =`` line (whole scenes) in the README and the docs pages."""
    blocks = []
    for md in [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]:
        for b in re.findall(r"```toml\n(.*?)```", md.read_text(encoding="utf-8"), re.S):
            if re.match(r"(\s*#.*\n)*\s*name\s*=", b):  # a whole scene starts with its name
                blocks.append(pytest.param(b, id=f"{md.name}:{len(blocks)}"))
    return blocks


def test_a_scene_snippet_exists():
    assert _scene_blocks()


@pytest.mark.parametrize("text", _scene_blocks())
def test_scene_snippet_loads_and_is_the_study_model(text, tmp_path):
    p = tmp_path / "snippet.toml"
    p.write_text(text, encoding="utf-8")
    sc = load_scene(p)
    ref = load_scene(ROOT / "examples" / "seed002_study_model.toml")
    theta = np.radians(np.arange(0.0, 360.0, 1.0))
    a, b = sc.analyse(theta), ref.analyse(theta)
    assert sc.omega == pytest.approx(20 * np.pi, rel=1e-15)  # 600 rpm
    for k in ("s", "phi", "rho", "Fc"):
        np.testing.assert_allclose(getattr(a, k), getattr(b, k), rtol=1e-12, atol=0, err_msg=k)
    assert (sc.study.a_over_h, sc.study.tolerance, sc.study.rtol) == (10.0, 2e-3, None)
    assert sc.study.angles_deg == "0:360:1" and sc.study.plots is True
