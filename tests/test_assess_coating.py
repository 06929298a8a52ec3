"""An assessment of a coated scene says that it treats the coated body as homogeneous (issue 29
review, item 1): the contact, stresses and fatigue data of the assessment are the substrate's.

Reference: the sweep's own flag of the same scene test (``headline_omits_coating``,
:func:`femcam.sweep.headline.omitted_physics`); the assessment must never omit it silently, on
the API (flag per contact row, ``Assessment.omitted``), the console and report.md/report.html.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from femcam.assess import assess
from femcam.cli import main
from femcam.layers.from_scene import scene_coatings
from femcam.scene import contact_case, load_scene
from femcam.sweep.headline import omitted_physics as headline_omitted

EXAMPLE = Path("examples/seed002_assess.toml")
COATING = """
[materials.roller.coating]
name = "a-C:H DLC"
thickness_um = 2.5
E_GPa = 170.0
nu = 0.22
"""


def _coated(tmp_path) -> Path:
    text = EXAMPLE.read_text().replace("[contact]", COATING + "\n[contact]", 1)
    path = tmp_path / "coated.toml"
    path.write_text(text)
    return path


def test_the_assessment_of_a_coated_scene_flags_every_contact_row(tmp_path):
    scene = load_scene(_coated(tmp_path))
    # same scene test; the assessment's own contact is Hertz's, as a sweep of method hertz (the
    # FE sweep's coated model carries the coating: no flag there)
    assert [f for f, _ in headline_omitted(scene, "hertz")] == ["headline_omits_coating"]
    assert headline_omitted(scene, "fe") == ()
    res = assess(contact_case(scene, np.radians([0.0, 60.0, 90.0])), coatings=scene_coatings(scene.layers))
    on = res.rows["Fc"] > 0
    assert on.all()
    assert all("omits_coating" in f.split(";") for f in res.rows["flags"])
    assert len(res.omitted) == 1
    assert res.omitted[0].startswith("the assessment treats the coated body as homogeneous: "
                                     "the roller's 2.5 um coating (E 170 GPa)")
    plain_scene = load_scene(EXAMPLE)
    plain = assess(contact_case(plain_scene, np.radians([0.0, 60.0])),
                   coatings=scene_coatings(plain_scene.layers))
    assert plain.omitted == () and not any("omits_coating" in f for f in plain.rows["flags"])


def test_the_cli_says_it_on_the_console_and_in_the_report(tmp_path, capsys):
    out = tmp_path / "o"
    rc = main(["assess", str(_coated(tmp_path)), "--angles-deg", "0:60:60", "--out", str(out),
               "--no-plots"])
    assert rc == 0
    console = capsys.readouterr().out
    assert "the assessment treats the coated body as homogeneous" in console
    for f in ("report.md", "report.html"):
        text = (out / f).read_text()
        assert "the assessment treats the coated body as homogeneous" in text, f
        assert "omits_coating at 2 angles" in text, f
