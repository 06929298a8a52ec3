"""The scene loader hands on typed frozen records (issue 24 item 1): ``Scene.tribology``,
``Scene.wear``, the read-only ``Scene.origin`` and ``Scene.overrides``, and the
``ContactCase`` the physics packages take. References are the values typed in the example
scene files times the unit factors written here."""

import dataclasses
import math
import pickle
from pathlib import Path

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.scene import (
    ContactCase,
    MaterialData,
    Tribology,
    WearSettings,
    contact_case,
    load_scene,
)
from femcam.scene.origin import thaw

EX = Path(__file__).resolve().parent.parent / "examples"


def test_records_are_frozen_and_si():
    sc = load_scene(EX / "seed002_assess.toml")
    assert isinstance(sc.tribology, Tribology) and isinstance(sc.wear, WearSettings)
    assert sc.tribology.oil_temperature_C == 70.0                     # [operating] oil_temperature_C
    assert sc.tribology.surface.roller_Ra == pytest.approx(0.1e-6)    # roller_Ra_um = 0.1
    assert sc.tribology.pin == MaterialData() and not sc.tribology.empty
    with pytest.raises(dataclasses.FrozenInstanceError):
        sc.tribology.oil_temperature_C = 20.0
    seed000 = load_scene(EX / "seed000_rise.toml")
    assert seed000.wear.K == pytest.approx(1e-8) and seed000.wear.k is None   # [wear] K = 1e-8
    assert load_scene(EX / "seed002_study_model.toml").tribology.empty


def test_origin_is_the_toml_as_written_and_read_only():
    sc = load_scene(EX / "seed002_study_model.toml")
    assert sc.origin["follower"]["roller_radius_mm"] == sc.follower.Rr * 1e3
    with pytest.raises(TypeError):
        sc.origin["follower"]["roller_radius_mm"] = 1.0
    assert isinstance(sc.origin["program"]["segment"], tuple)         # arrays frozen as tuples
    plain = thaw(sc.origin)
    assert isinstance(plain, dict) and isinstance(plain["program"]["segment"], list)
    plain["follower"]["roller_radius_mm"] = 1.0                       # a copy: the origin keeps its value
    assert sc.origin["follower"]["roller_radius_mm"] == sc.follower.Rr * 1e3
    again = pickle.loads(pickle.dumps(sc))                            # scenes cross process boundaries
    assert again.origin == sc.origin and again.tribology == sc.tribology


def test_overrides_are_pairs_and_a_dict_field_is_refused():
    sc = load_scene(EX / "seed002_study_model.toml")
    ov = sc.with_law("bezier", control_points=[0.0, 0.0, 0.5, 1.0, 1.0]).overrides
    assert ov == (("law", "bezier"), ("control_points", (0.0, 0.0, 0.5, 1.0, 1.0)))
    with pytest.raises(InputError, match="Scene.wear"):
        dataclasses.replace(sc, wear={"srr": 0.05})
    with pytest.raises(InputError, match="Scene.tribology"):
        dataclasses.replace(sc, tribology={})


def test_contact_case_of_a_knife_edge_is_the_cam_cut_for_its_tip():
    """The knife edge's case state is that of a roller of the tip radius r (Johnson 1985 §4.3):
    its pressure angle is the roller's, tan(phi) = (s' - e) / (sqrt((Rb + r)^2 - e^2) + s)
    (Norton, Cam Design and Manufacturing Handbook, eq. 7.1: the pitch radius Rb + r), not the
    sharp edge's (pitch radius Rb)."""
    sc = load_scene(EX / "seed003_knife_edge.toml")
    th = np.radians([30.0, 60.0, 100.0])
    c = contact_case(sc, th)
    r = 2e-3                                                   # [follower] tip_radius_mm = 2
    assert isinstance(c, ContactCase) and c.tip_radius == pytest.approx(r)
    f, st = sc.follower, c.state
    assert np.ptp(st.s) > 0                                     # angles on the rise
    phi = np.arctan((st.s1 - f.e) / (np.sqrt((f.Rb + r) ** 2 - f.e**2) + st.s))
    np.testing.assert_allclose(st.phi, phi, rtol=1e-9, atol=1e-12)
    assert c.follower is sc.follower and c.revolution is None
    with pytest.raises(InputError, match="applies to knife-edge followers only"):
        contact_case(load_scene(EX / "seed002_study_model.toml"), th, tip_radius=1e-3)
    full = contact_case(dataclasses.replace(load_scene(EX / "seed002_study_model.toml"),
                                            wear=WearSettings(roller_model="inertia", J=5e-3)), th)
    assert full.revolution.theta.size == 720 and math.isclose(full.revolution.theta[1], 2 * math.pi / 720)
