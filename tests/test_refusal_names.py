"""Refusals on scene-driven paths lead with the scene key the user wrote, in its own unit, not
the internal symbol (issue 29 review, item 5): ``[cam] bore_mm = 9.99 mm`` (not ``Rb (bore
radius, ...) = 0.00999 m``), the keys that set the contact half-width (not ``a_ref``), and what
a user can change (not ``MeshOptions.domain_over_a``).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from femcam.bodies.cam_global import global_mesh_for
from femcam.bodies.cam_rows import disk_from_case
from femcam.errors import InputError
from femcam.mesh import MeshOptions
from femcam.mesh.geometry import body_layout
from femcam.scene import cam_disk_case, load_scene

EX = Path(__file__).resolve().parents[1] / "examples"
INTERNAL = ("Rb (", "a_ref", "fine_half_width =", "domain_over_a", "in code:")


def test_a_bore_leaving_a_10_um_web_is_named_by_its_scene_key():
    sc = load_scene(EX / "seed002_cam_on_shaft.toml")
    with pytest.raises(InputError) as e:
        global_mesh_for(disk_from_case(cam_disk_case(sc), Rb=9.99e-3))
    msg = str(e.value)
    assert msg.startswith("[cam] bore_mm = 9.99 mm: "), msg
    assert not any(w in msg for w in INTERNAL), msg


def test_a_body_too_small_for_the_fine_zone_names_the_scene_keys():
    with pytest.raises(InputError) as e:
        body_layout("cam", 0.01, 1e-3, 1e-3, MeshOptions())
    msg = str(e.value)
    assert msg.startswith("[follower] base_radius_mm, roller_radius_mm and [program] give the cam"), msg
    assert "face_width_mm" in msg and "preload_N" in msg
    assert not any(w in msg for w in INTERNAL), msg
