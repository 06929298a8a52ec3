"""More cam angles than can be computed in bounded memory are refused before any work, with the
estimate (issue 29 review, item 3): ``femcam run``/``assess --angles-deg 0:360:0.00004`` (9e6
angles) used to grow past 6 GB. Reference: the bytes per angle measured at 1e5 angles
(femcam._validate.MAX_ANGLES, MAX_ASSESS_ANGLES).
"""

from __future__ import annotations

import numpy as np
import pytest

from femcam import _validate
from femcam.assess import assess
from femcam.cli import main
from femcam.errors import InputError
from femcam.scene import contact_case, load_scene

EXAMPLE = "examples/seed002_assess.toml"


@pytest.mark.parametrize("cmd, cap", [("run", _validate.MAX_ANGLES), ("assess", _validate.MAX_ASSESS_ANGLES)])
def test_the_cli_refuses_millions_of_angles_with_the_estimate(tmp_path, capsys, cmd, cap):
    out = tmp_path / "o"
    rc = main([cmd, EXAMPLE, "--angles-deg", "0:360:0.00004", "--out", str(out)])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 1 and len(err) == 1, err
    assert "--angles-deg = '0:360:0.00004' deg: 9,000,000 angles" in err[0]
    assert f"more than the {cap:,}" in err[0] and " GB (" in err[0]
    assert not out.exists()


def test_the_api_refuses_too(tmp_path):
    scene = load_scene(EXAMPLE)
    with pytest.raises(InputError, match=r"^theta = .*more than the 1,000,000 .*GB"):
        scene.analyse(np.zeros(_validate.MAX_ANGLES + 1))
    with pytest.raises(InputError, match=r"^theta = .*more than the 400,000 .*GB"):
        assess(contact_case(scene, np.zeros(_validate.MAX_ASSESS_ANGLES + 1)))
    assert scene.analyse(np.zeros(3)).Fc.shape == (3,)
