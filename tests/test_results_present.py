"""Result objects present themselves compactly: a ``repr`` of at most ~1 kB that states the class,
the sizes and the key facts with units (never the arrays' values), and ``to_dataframe()`` with
the columns and units of the CSV femcam writes for that result (femcam._repr, femcam.io).
"""

from __future__ import annotations

import dataclasses
import math
import re
from pathlib import Path

import numpy as np
import pytest

from femcam._repr import MAX_REPR, compact_repr
from femcam.fe.result import ContactResult
from femcam.io import csv_text
from femcam.scene import contact_case, load_scene
from femcam.sweep import RunOptions, SweepOptions, SweepResult, sweep

EX = Path(__file__).resolve().parents[1] / "examples"
STUDY = EX / "seed002_study_model.toml"


def _short(r: str, *facts: str) -> None:
    assert len(r) <= MAX_REPR, f"repr of {len(r)} characters: {r[:200]}..."
    for f in facts:
        assert re.search(f, r), f"{f!r} not in {r!r}"


@pytest.fixture(scope="module")
def state():
    return load_scene(STUDY).analyse(np.radians(np.arange(0.0, 360.0, 0.5)))


@pytest.fixture(scope="module")
def hertz_dir(tmp_path_factory):
    d = tmp_path_factory.mktemp("sweep")
    sweep(load_scene(STUDY),
          SweepOptions(angles=np.radians([40.0, 50.0, 60.0]), method="hertz", plots=False, vtk_every=0),
          RunOptions(out=d, progress=None))
    return d


def test_scene_state_profile_loads_reprs_are_short(state):
    # the default dataclass repr of this state printed ~370 kB of numbers
    Fc = f"Fc {state.Fc.min():.4g}..{state.Fc.max():.4g} N"
    _short(repr(state), r"^SceneState\(", "720 angles 0..359.5 deg", re.escape(Fc), "lift-off 0",
           r"arrays \(720,\): theta s v a j")
    _short(repr(state.profile), r"^CamProfile\(RollerFollower", "720 angles",
           re.escape(f"rho {state.rho[np.isfinite(state.rho)].min() * 1e3:.4g}.."))
    _short(repr(state.loads), r"^LoadResult\(", re.escape(Fc))


def test_scene_repr_stays_the_full_identity():
    """Scene's repr is its identity (the sweep's resume hash and ``scene_repr`` in sweep.npz):
    it keeps every parameter, and stays short because a scene holds no arrays."""
    sc = load_scene(STUDY)
    assert len(repr(sc)) < 4 * MAX_REPR and repr(sc).startswith("Scene(name='seed002_study_model'")
    assert "Rr=0.01" in repr(sc)
    assert repr(sc.with_law("bezier7")) != repr(sc)


def test_sweep_repr_and_dataframe_match_the_csv(hertz_dir):
    pd = pytest.importorskip("pandas", reason="pandas is in femcam's [test] extra")
    r = SweepResult.load(hertz_dir)
    fc = np.nanmax(r.table["Fc"])
    _short(repr(r), r"^SweepResult\(method 'hertz'", "3 angles 40..60 deg", "ok 3",
           re.escape(f"Fc max {fc:.5g} N"), "MPa", "files: csv npz")
    df = r.to_dataframe()
    csv = pd.read_csv(hertz_dir / "sweep.csv")
    assert list(df.columns) == list(csv.columns) and df.shape == csv.shape == (3, len(csv.columns))
    for c in csv.columns:
        if pd.api.types.is_numeric_dtype(csv[c]):
            np.testing.assert_allclose(df[c].to_numpy(float), csv[c].to_numpy(float), rtol=1e-9,
                                       equal_nan=True, err_msg=c)
        else:    # the CSV's text is the exact text made CSV-safe
            assert [csv_text(v) for v in df[c]] == csv[c].astype(str).tolist(), c
    # units as in the CSV: degrees and MPa, from the SI table
    np.testing.assert_allclose(df["theta_deg"], [40.0, 50.0, 60.0])
    np.testing.assert_allclose(df["p0_hertz_MPa"], r.table["p0_hertz"] * 1e-6)


def test_contact_result_repr_states_the_solve_not_its_arrays():
    """A ContactResult with the array sizes of a fine mesh (values are not the point here)."""
    vals = {}
    for f in dataclasses.fields(ContactResult):
        vals[f.name] = 0.0
    big = np.zeros(100_000)
    vals.update(F=1500.0, rho=0.0125, mu=0.1, p0=1.1e9, a=2.5e-4, hertz_p0=1.09e9,
                force_error=1e-4, converged=True, iterations=7, n_dofs=123456,
                slip_state="partial slip", x=big, p=big, gap=big, q=big, active=big > 1,
                stick=big > 1, max_by_body={}, surface_by_body={}, timings={}, history=(),
                message="")
    r = object.__new__(ContactResult)
    for k, v in vals.items():
        object.__setattr__(r, k, v)
    _short(repr(r), r"^ContactResult\(F 1500 N", "rho 12.5 mm", "p0 1100 MPa", "a 250 um",
           "converged True in 7 iterations", "123456 dofs", "partial slip",
           r"arrays \(100000,\): x p gap")


def test_dynamics_and_rpm_sweep(tmp_path):
    pd = pytest.importorskip("pandas", reason="pandas is in femcam's [test] extra")
    from femcam.cli import main

    sc = load_scene(EX / "seed002_dynamic.toml")
    r = sc.dynamic_response
    _short(repr(r), r"^DynamicsResult\(one_dof", "600 rpm", "3600 steps/rev", "converged True")
    assert main(["dynamics", str(EX / "seed002_dynamic.toml"), "--out", str(tmp_path),
                 "--no-plots"]) == 0
    df, csv = r.to_dataframe(), pd.read_csv(tmp_path / "dynamics.csv")
    assert list(df.columns) == list(csv.columns) and len(df) == len(csv) == 3600
    np.testing.assert_allclose(df["theta_deg"], np.arange(3600) * 0.1, atol=1e-9)
    np.testing.assert_allclose(df["Fc_N"], csv["Fc_N"], rtol=1e-9)


def test_assessment_repr_and_dataframe():
    pd = pytest.importorskip("pandas", reason="pandas is in femcam's [test] extra")
    from femcam.assess import assess, csv_columns

    theta = np.radians(np.arange(0.0, 360.0, 30.0))
    a = assess(contact_case(load_scene(EX / "seed002_assess.toml"), theta))
    c, (v, t, _) = next(iter(a.worst.items()))
    _short(repr(a), r"^Assessment\('", "12 angles", re.escape(f"{c} {v:.4g} at {math.degrees(t):.1f} deg"))
    df = a.to_dataframe()
    assert list(df.columns) == list(csv_columns(a.rows)) and len(df) == 12
    np.testing.assert_allclose(df["theta_deg"], np.arange(0.0, 360.0, 30.0))
    assert isinstance(pd.DataFrame, type)


def test_compact_repr_is_bounded():
    @dataclasses.dataclass
    class Many:
        pass

    r = compact_repr(Many(), [f"fact {i}" for i in range(500)])
    assert len(r) <= MAX_REPR and r.endswith(" ...)")


def test_to_dataframe_without_pandas_says_how_to_install(monkeypatch, hertz_dir):
    import sys

    monkeypatch.setitem(sys.modules, "pandas", None)     # import pandas -> ImportError
    with pytest.raises(ImportError, match=r"SweepResult.to_dataframe\(\) needs pandas.*pip install pandas"):
        SweepResult.load(hertz_dir).to_dataframe()


def test_wear_map_slip_stress_field_and_svaj_reprs():
    """The other result records print their scalars and the arrays' shapes, not the values."""
    from femcam.hertz import LineContact
    from femcam.materials import STEEL
    from femcam.scene import contact_case
    from femcam.wear.axial import scene_wear_map

    sc = load_scene(STUDY)
    wm, _st, slip = scene_wear_map(contact_case(sc, np.radians(np.arange(0.0, 360.0, 10.0))), cycles=1000)
    _short(repr(wm), r"^WearMap\(36 angles", "nm", r"mm\^3", "1000 cycles")
    _short(repr(slip), r"^SlipResult\(", r"arrays \(36,\): theta v_slip V_cam")
    svaj = sc.program.svaj(np.radians(np.arange(0.0, 360.0, 0.01)), omega=sc.omega)
    _short(repr(svaj), r"^SVAJ\(omega=62.8319; arrays \(36000,\): theta s v a j\)$")
    x = np.linspace(-1e-4, 1e-4, 20_001)
    hc = LineContact(F=1000.0, length=0.01, R1=0.01, R2=0.01, cam=STEEL, roller=STEEL)
    field = hc.stress(x, 5e-5 + 0 * x)
    _short(repr(field), r"^StressField\(", r"arrays \(20001,\): sx sz txz")
