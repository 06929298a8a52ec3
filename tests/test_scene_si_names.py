"""Units only at the edges: the dicts and records a loaded scene hands on (``Scene.layers``,
``Scene.tribology``, ...) hold SI values under SI names, never under a key that names an edge
unit (``thickness_um`` holding metres). References are the values typed in the scene files
times the unit factor written in the test."""

import dataclasses
import glob
import math
import pathlib

import pytest

from femcam.assess import assessment_inputs
from femcam.errors import InputError
from femcam.layers import scene_layers
from femcam.scene import load_scene
from femcam.sweep import providers
from femcam.wear.coating import coating_wear

EX = pathlib.Path(__file__).resolve().parent.parent / "examples"
#: edge-unit suffixes: a key ending so must not hold an SI value
EDGE = ("_um", "_mm", "_GPa", "_MPa", "_HV", "_deg", "_rpm", "_per_GPa", "_mm2_per_s", "_mm3_per_N_m")
HV = 9.80665e6  # Pa per HV (1 kgf/mm^2)


def _scene(tmp_path, name, old, new):
    text = (EX / name).read_text()
    assert old in text
    p = tmp_path / name
    p.write_text(text.replace(old, new))
    return load_scene(p)


def _edge_keys(d, where=""):
    """``(path, value)`` of every key ending in an edge-unit suffix, nested dicts and records
    (their fields by name) walked."""
    if dataclasses.is_dataclass(d) and not isinstance(d, type):
        d = {f.name: getattr(d, f.name) for f in dataclasses.fields(d)}
    elif isinstance(d, tuple):   # Scene.layers: one record per body
        d = dict(enumerate(d))
    elif not isinstance(d, dict):
        return []
    out = []
    for k, v in d.items():
        if isinstance(v, dict) or (dataclasses.is_dataclass(v) and not isinstance(v, type)):
            out += _edge_keys(v, f"{where}.{k}")
        elif isinstance(k, str) and k.endswith(EDGE):
            out.append((f"{where}.{k}", v))
    return out


def test_layers_hold_si_values_under_si_names():
    scene = load_scene(EX / "seed002_coated.toml")
    by_body = {b.body: b for b in scene.layers}
    coat, case = by_body["roller"].coating, by_body["cam"].case
    # seed002_coated.toml: thickness_um = 2.5, E_GPa = 170, hardness_MPa = 18000,
    # interface_shear_strength_MPa = 250; depth_mm = 0.3, 700 / 300 HV
    assert coat.thickness == pytest.approx(2.5e-6, rel=1e-12)
    assert coat.E == pytest.approx(170e9, rel=1e-12)
    assert coat.hardness == pytest.approx(18e9, rel=1e-12)
    assert coat.interface_shear_strength == pytest.approx(250e6, rel=1e-12)
    assert case.depth == pytest.approx(0.3e-3, rel=1e-12)
    assert case.surface_hardness == pytest.approx(700 * HV, rel=1e-12)
    lay = scene_layers(scene.layers, scene.follower)
    body, c = lay["coating"]
    assert body == "roller" and c.thickness == pytest.approx(2.5e-6, rel=1e-12)
    assert c.interface_shear_strength == pytest.approx(250e6, rel=1e-12)
    assert lay["case"][1].depth == pytest.approx(0.3e-3, rel=1e-12)


def test_coating_wear_k_under_its_si_name(tmp_path):
    scene = _scene(tmp_path, "seed002_coated.toml", "interface_shear_strength_MPa = 250.0",
                   "interface_shear_strength_MPa = 250.0\nwear_k_mm3_per_N_m = 2e-7\n"
                   "[wear]\nk_mm3_per_N_m = 1e-6")
    assert {b.body: b for b in scene.layers}["roller"].coating.wear_k == pytest.approx(2e-7 * 1e-9, rel=1e-12)
    cw = coating_wear(scene.layers, scene.wear, scene.cam.hardness)
    assert cw.k_coating == pytest.approx(2e-16, rel=1e-12)
    assert cw.thickness == pytest.approx(2.5e-6, rel=1e-12)
    # the scene's [wear] k_mm3_per_N_m = 1e-6 is the substrate's k (1 mm^3 = 1e-9 m^3)
    assert cw.k_substrate == pytest.approx(1e-15, rel=1e-12)
    with pytest.raises(InputError, match="layers = "):
        coating_wear(scene, scene.wear, scene.cam.hardness)        # the records, not the scene
    with pytest.raises(InputError, match="wear = "):
        coating_wear(scene.layers, {"k": 1e-15}, scene.cam.hardness)


def test_tribology_holds_si_values_under_si_names(tmp_path):
    scene = _scene(tmp_path, "seed002_assess.toml", 'name = "ISO VG 46 mineral"',
                   'name = "test oil"\nkinematic_viscosity_40C_mm2_per_s = 46.0\n'
                   "kinematic_viscosity_100C_mm2_per_s = 6.8\npressure_viscosity_per_GPa = 20.0\n"
                   "density_kg_per_m3 = 861.0")
    tri = scene.tribology
    assert tri.lubricant.pressure_viscosity == pytest.approx(20e-9, rel=1e-12)
    assert tri.lubricant.kinematic_viscosity_40C == pytest.approx(46e-6, rel=1e-12)
    assert tri.surface.cam_Ra == pytest.approx(0.2e-6, rel=1e-12)
    assert tri.cam.yield_strength == pytest.approx(1700e6, rel=1e-12)
    ai = assessment_inputs(scene.tribology)
    assert ai.lubricant.alpha == pytest.approx(20e-9, rel=1e-12)
    assert ai.lubricant.nu100 == pytest.approx(6.8e-6, rel=1e-12)
    rq = math.sqrt(math.pi / 2.0)  # Gaussian heights: Rq / Ra
    assert ai.sigma == pytest.approx(math.hypot(rq * 0.2e-6, rq * 0.1e-6), rel=1e-12)
    assert ai.cam["Y"] == pytest.approx(1700e6, rel=1e-12)
    assert ai.roller["tau_e"] == pytest.approx(350e6, rel=1e-12)


@pytest.mark.parametrize("path", sorted(glob.glob(str(EX / "*.toml"))), ids=lambda p: pathlib.Path(p).stem)
def test_no_edge_unit_key_holds_an_si_value(path):
    """An edge-unit key in a dict the scene hands on holds the value as written (the sweep's
    angles_deg string is documented as written); every other value is SI-named, and the typed
    records (Scene.tribology, Scene.wear) have no field named with an edge unit."""
    scene = load_scene(path)
    for attr in ("layers", "bodies", "finite_length"):
        raw_tab = scene.origin.get(attr, {})
        for key, v in _edge_keys(getattr(scene, attr)):
            assert key.count(".") == 1 and raw_tab.get(key[1:]) == v, f"Scene.{attr}{key} = {v!r}"
    tri = scene.tribology
    for rec in (scene.wear, tri.lubricant, tri.surface, tri.cam, tri.roller, tri.pin, tri.shaft):
        if rec is not None:
            names = [f.name for f in dataclasses.fields(rec)]
            assert not [n for n in names if n.endswith(EDGE)], f"{type(rec).__name__} {names}"
    # the [fe]/[sweep] record: only the angle spec keeps its edge unit, as written
    study = {k: v for k, v in dataclasses.asdict(scene.study).items() if v is not None}
    assert [k for k in study if k.endswith(EDGE)] == (["angles_deg"] if "angles_deg" in study else [])
    assert study.get("angles_deg") == scene.origin.get("sweep", {}).get("angles_deg")


def test_layer_columns_si_names_csv_names_unchanged():
    csv = ("interface_tau_max_MPa", "interface_sn_min_MPa", "interface_sn_max_MPa",
           "interface_utilisation", "coating_sx_max_MPa", "coating_sx_utilisation",
           "case_utilisation_max", "case_z_at_max_mm", "case_margin")
    assert tuple(c.csv for c in providers.LAYERS) == csv
    assert "layer_interface_tau_max" in {c.si for c in providers.LAYERS}
    assert "layer_case_z_at_max" in {c.si for c in providers.LAYERS}
    for col in providers.LAYERS:
        assert not col.si.endswith(EDGE), col.si
        assert col.factor == (1e-6 if col.unit == "MPa" else 1e3 if col.unit == "mm" else 1.0)
