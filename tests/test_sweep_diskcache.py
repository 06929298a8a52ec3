"""The persistent model cache (femcam.sweep.diskcache): never stale, never half-read, bounded.

References are independent of the cache: a model built fresh in the same process (the cold
path), the inputs the model reports (its own E, Rr, mesh options), the bytes written, and the
file system. Models here use a coarse mesh (a_over_h = 4, ~0.1 s a build) so each test stays
near 1 s; the whole-sweep checks are in the slow pass.

Warm and cold answers are compared **bit for bit** (``assert_array_equal``, not a tolerance):
a loaded model holds the very arrays the cold build computed (a pickle round trip of float64
is exact), and its bodies are assembled and factorised again from the stored mesh by the same
deterministic code, so nothing can differ but the timing columns.
"""

from __future__ import annotations

import dataclasses
import multiprocessing
import os
from pathlib import Path

import numpy as np
import pytest

import femcam
from femcam.cli import main
from femcam.sweep import RunOptions, SweepOptions, default_cache, sweep
from femcam.sweep import cache as cache_mod
from femcam.sweep.cache import ModelCache
from femcam.sweep.diskcache import DiskCache, content_key, default_dir
from femcam.sweep.options import ContactParams, ResolvedOptions, contact_params
from femcam.sweep.plan import hertz_half_width

STUDY = Path(__file__).resolve().parents[1] / "examples" / "seed002_study_model.toml"
FAST = ResolvedOptions(a_over_h=4)
RHO = 0.02   # cam radius of the family model (m)
F = 1500.0   # contact force (N)


@pytest.fixture
def cp(study_scene):
    return contact_params(study_scene)


@pytest.fixture
def disk(tmp_path):
    return DiskCache(tmp_path / "cache")


def _a(cp, F=F, rho=RHO):
    return float(hertz_half_width(np.array([F]), np.array([rho]), cp)[0])


def _model(disk, cp, rho=RHO, options=FAST):
    """A model through a new process-like ModelCache on ``disk``, and that cache's stats."""
    c = ModelCache(disk=disk)
    m = c.model_for(cp, rho, _a(cp, rho=rho), options)
    return m, c.stats


def test_default_directory_order(monkeypatch, tmp_path):
    monkeypatch.setenv("FEMCAM_CACHE_DIR", str(tmp_path / "a"))
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "x"))
    assert default_dir() == tmp_path / "a"
    monkeypatch.delenv("FEMCAM_CACHE_DIR")
    assert default_dir() == tmp_path / "x" / "femcam"
    monkeypatch.delenv("XDG_CACHE_HOME")
    assert default_dir() == Path.home() / ".cache" / "femcam"


def test_the_suite_does_not_use_the_users_cache():
    """tests/conftest.py points every test (and subprocess) at a session directory."""
    assert os.environ["FEMCAM_CACHE_DIR"]
    assert os.path.basename(os.environ["FEMCAM_CACHE_DIR"]).startswith("femcam-test-cache-")


def test_warm_model_is_the_cold_model_bit_for_bit(cp, disk):
    cold, s1 = _model(disk, cp)
    warm, s2 = _model(disk, cp)
    assert (s1["built"], s1["loaded"], s2["built"], s2["loaded"]) == (1, 0, 0, 1)
    assert not warm.bodies  # the factors were not stored; rebuilt on demand
    for F_i in (0.8 * F, F, 1.3 * F):
        rc = cold.solve(F=F_i, rho=RHO * 1.02, mu=0.1)
        rw = warm.solve(F=F_i, rho=RHO * 1.02, mu=0.1)
        np.testing.assert_array_equal(rw.p, rc.p)
        assert (rw.p0_nodal, rw.a) == (rc.p0_nodal, rc.a)
        for body in ("cam", "roller"):
            assert rw.max_by_body[body] == rc.max_by_body[body]
    # a full field needs the factor: assembled again from the stored mesh, the same numbers
    uc, fc = cold.full_field(rc, "cam")
    uw, fw = warm.full_field(rw, "cam")
    np.testing.assert_array_equal(uw, uc)
    np.testing.assert_array_equal(fw["von_mises"], fc["von_mises"])


def test_vtu_fields_of_a_warm_model_are_read_back_without_a_factor(cp, disk):
    """A model built here stores the back-solves of its full fields (a sweep's ``.vtu``,
    ``store_fields``); the same model loaded from the cache reads them back and never
    assembles or factorises a body, with the cold fields bit for bit. A load that was not
    stored factorises the body from the stored mesh: the cold numbers again."""
    from femcam.fe.export import scene_arrays
    from femcam.sweep.diskcache import StoredBody, store_fields

    cold, _ = _model(disk, cp)
    store_fields(cold, disk)
    rc = cold.solve(F=F, rho=RHO, mu=0.1)
    cold_arrays = scene_arrays(rc)
    n_entries = len(list(disk.directory.glob("*.pkl")))
    assert n_entries == 3, "the model and one displacement entry per body"
    warm, _ = _model(disk, cp)
    store_fields(warm, disk)
    rw = warm.solve(F=F, rho=RHO, mu=0.1)
    warm_arrays = scene_arrays(rw)
    for name in ("cam", "roller"):
        b = warm.bodies[name]
        assert isinstance(b, StoredBody) and b._full is None, f"{name} was factorised"
    np.testing.assert_array_equal(warm_arrays[0], cold_arrays[0])
    np.testing.assert_array_equal(warm_arrays[1], cold_arrays[1])
    for k, v in cold_arrays[3].items():
        np.testing.assert_array_equal(warm_arrays[3][k], v, err_msg=k)
    # another load: not stored, so the body is factorised (and that field is stored in turn)
    rc2, rw2 = (m.solve(F=1.2 * F, rho=RHO, mu=0.1) for m in (cold, warm))
    uw, fw = warm.full_field(rw2, "cam")
    uc, fc = cold.full_field(rc2, "cam")
    assert warm.bodies["cam"]._full is not None
    np.testing.assert_array_equal(uw, uc)
    np.testing.assert_array_equal(fw["von_mises"], fc["von_mises"])
    # a damaged displacement entry is a miss (removed, solved again), never a wrong field
    m3, _ = _model(disk, cp)
    store_fields(m3, disk)
    for p in disk.directory.glob("*.pkl"):       # (m3 is loaded already)
        p.write_bytes(p.read_bytes()[:100])
    u3, _ = m3.full_field(m3.solve(F=F, rho=RHO, mu=0.1), "roller")
    np.testing.assert_array_equal(u3, cold.full_field(rc, "roller")[0])


@dataclasses.dataclass(frozen=True)
class _Coated(ContactParams):
    """A field added to ContactParams later (a coating, another helper's a_over_h choice)."""

    coating_um: float = 0.0


def _version(monkeypatch):
    monkeypatch.setattr(femcam, "__version__", femcam.__version__ + ".post1")


def _mesh_option(monkeypatch):
    real = cache_mod.model_args

    def args(*a, **k):  # a mesh option the sweep options do not carry
        out = real(*a, **k)
        return {**out, "mesh": dataclasses.replace(out["mesh"], fine_half_width=3.0)}

    monkeypatch.setattr(cache_mod, "model_args", args)


CHANGES = {
    "material_E": (lambda cp, mp: (dataclasses.replace(
        cp, cam=dataclasses.replace(cp.cam, E=1.01 * cp.cam.E)), RHO, FAST),
        lambda m, cp: m.cam.E == 1.01 * cp.cam.E),
    "roller_radius": (lambda cp, mp: (dataclasses.replace(cp, Rr=1.01 * cp.Rr), RHO, FAST),
                      lambda m, cp: m.Rr == 1.01 * cp.Rr),
    "cam_radius": (lambda cp, mp: (cp, 1.01 * RHO, FAST), lambda m, cp: m.rho_ref == 1.01 * RHO),
    "mesh_a_over_h": (lambda cp, mp: (cp, RHO, ResolvedOptions(a_over_h=5)),
                      lambda m, cp: m.mesh.options.a_over_h == 5),
    "mesh_option": (lambda cp, mp: (_mesh_option(mp), (cp, RHO, FAST))[1],
                    lambda m, cp: m.mesh.options.fine_half_width == 3.0),
    "femcam_version": (lambda cp, mp: (_version(mp), (cp, RHO, FAST))[1], lambda m, cp: True),
    "new_params_field": (lambda cp, mp: (dataclasses.replace(cp, coating_um=2.0), RHO, FAST),
                         lambda m, cp: True),
}


@pytest.mark.parametrize("change", sorted(CHANGES))
def test_a_changed_input_never_reuses_a_stale_model(change, cp, disk, monkeypatch):
    base = _Coated(**{f.name: getattr(cp, f.name) for f in dataclasses.fields(cp)}) \
        if change == "new_params_field" else cp
    _model(disk, base)
    _, s = _model(disk, base)
    assert s["loaded"] == 1, "the unchanged inputs must hit (else this test proves nothing)"
    make, check = CHANGES[change]
    cp2, rho, options = make(base, monkeypatch)
    m, s = _model(disk, cp2, rho, options)
    assert (s["built"], s["loaded"]) == (1, 0), f"{change}: a stale model was loaded"
    assert check(m, cp), f"{change}: the model was not built from the changed input"


def test_fresh_check_p0_is_stored_and_keyed(cp, disk):
    a = _a(cp)
    c1 = ModelCache(disk=disk)
    p_cold = c1.fresh_p0(cp, RHO, a, FAST, F)
    c2 = ModelCache(disk=disk)
    assert c2.fresh_p0(cp, RHO, a, FAST, F) == p_cold   # exact: the stored float
    assert (c1.stats["checks_built"], c2.stats["checks_built"], c2.stats["checks_loaded"]) == (1, 0, 1)
    c3 = ModelCache(disk=disk)
    p_mu = c3.fresh_p0(dataclasses.replace(cp, mu=0.2), RHO, a, FAST, F)   # another load case
    assert c3.stats["checks_built"] == 1 and p_mu != p_cold


@pytest.mark.parametrize("damage", ["corrupt", "truncated"])
def test_damaged_entry_is_detected_removed_and_rebuilt(damage, cp, disk, capsys):
    cold, _ = _model(disk, cp)
    (path,) = disk.directory.glob("*.pkl")
    data = bytearray(path.read_bytes())
    if damage == "corrupt":
        data[len(data) // 2] ^= 0xFF          # one flipped byte in the payload
    else:
        data = data[: len(data) // 3]          # a writer killed mid-file (not via os.replace)
    path.write_bytes(bytes(data))
    m, s = _model(disk, cp)
    assert (s["built"], s["loaded"]) == (1, 0)
    err = capsys.readouterr().err
    assert err.count("corrupt or incomplete") == 1 and path.name in err
    r = m.solve(F=F, rho=RHO, mu=0.1)
    np.testing.assert_array_equal(r.p, cold.solve(F=F, rho=RHO, mu=0.1).p)
    _, s = _model(disk, cp)
    assert s["loaded"] == 1, "the rebuilt model was stored again"


def _writer(root, key, value, barrier, n):
    d = DiskCache(root)
    barrier.wait()
    for _ in range(n):
        d.put(key, value)


def test_two_processes_writing_one_key_leave_one_valid_entry(tmp_path):
    ctx = multiprocessing.get_context("fork")
    key = content_key("test", "same key")
    values = [np.full(1_000_000, float(i)) for i in (1, 2)]   # 8 MB each: writes overlap
    barrier = ctx.Barrier(2)
    procs = [ctx.Process(target=_writer, args=(tmp_path, key, v, barrier, 4)) for v in values]
    for p in procs:
        p.start()
    for p in procs:
        p.join(60)
        assert p.exitcode == 0
    d = DiskCache(tmp_path)
    got = d.get(key)
    assert d.stats["corrupt"] == 0 and got is not None
    assert any(np.array_equal(got, v) for v in values)
    assert [p.name for p in d.directory.iterdir()] == [f"{key}.pkl"], "no temporary files left"


def test_unwritable_directory_builds_and_says_so_once(cp, tmp_path, capsys):
    blocker = tmp_path / "a_file"
    blocker.write_text("not a directory")
    disk = DiskCache(blocker / "cache")    # mkdir fails (also as root, unlike a chmod)
    m, s = _model(disk, cp)
    _model(disk, cp, rho=1.01 * RHO)
    assert s["built"] == 1 and m.solve(F=F, rho=RHO).converged
    assert capsys.readouterr().err.count("cannot write to") == 1


def test_size_bound_evicts_the_least_recently_used(tmp_path):
    d = DiskCache(tmp_path, max_bytes=3000)
    keys = [content_key("test", i) for i in range(4)]
    for i, k in enumerate(keys[:3]):
        assert d.put(k, bytes(800))
        os.utime(d.path(k), (1000.0 + i, 1000.0 + i))   # written in order 0, 1, 2
    assert d.get(keys[0]) is not None                   # used now: the newest
    d.put(keys[3], bytes(800))                          # 4 x ~900 B > 3000 B: one must go
    assert [d.path(k).exists() for k in keys] == [True, False, True, True]
    assert d.stats["evicted"] == 1


def test_disabled_cache_reads_and_writes_nothing(cp, tmp_path):
    d = DiskCache(tmp_path, enabled=False)
    _model(d, cp)
    _, s = _model(d, cp)
    assert s["built"] == 1 and not (tmp_path / "models-v1").exists()


def _table(r):
    return {k: np.asarray(v) for k, v in r.table.items() if "time" not in k}


@pytest.mark.slow  # three small FE sweeps, ~3 s
def test_sweep_rows_warm_equal_cold_and_no_cache_builds(study_scene, tmp_path, capsys):
    th = np.radians([30.0, 60.0, 90.0, 120.0])
    opts = SweepOptions(angles=th, a_over_h=4)
    run = RunOptions(cache_dir=tmp_path / "c", workers=1)
    default_cache().clear()
    cold = sweep(study_scene, opts, run)
    default_cache().clear()          # a new process: nothing in memory
    warm = sweep(study_scene, opts, run)
    default_cache().clear()
    off = sweep(study_scene, opts, dataclasses.replace(run, model_cache=False))
    mc = [r.provenance["options"]["model_cache"] for r in (cold, warm, off)]
    assert mc[0]["built"] >= 1 and mc[0]["loaded"] == 0
    assert mc[1]["built"] == 0 and mc[1]["loaded"] == mc[0]["built"]
    assert mc[1]["checks_built"] == 0 and mc[1]["checks_loaded"] == mc[0]["checks_built"]
    assert mc[2]["loaded"] == 0 and mc[2]["built"] == mc[0]["built"]
    assert "reused from cache" in mc[1]["line"]
    tc, tw, to = _table(cold), _table(warm), _table(off)
    for k in tc:
        np.testing.assert_array_equal(tw[k], tc[k], err_msg=k)
        np.testing.assert_array_equal(to[k], tc[k], err_msg=k)
    # the CLI: --no-cache builds, and the summary line says so
    default_cache().clear()
    code = main(["sweep", str(STUDY), "--angles-deg", "30:90:30", "--a-over-h", "4",
                 "--no-plots", "--vtk-every", "0", "--no-cache", "--out", str(tmp_path / "o")])
    out = capsys.readouterr().out
    assert code == 0 and "model cache off (--no-cache)" in out


def test_dask_workers_read_the_clients_cache_and_write_nothing(cp, tmp_path):
    """A Dask task runs through ``parallel._files_back`` on the worker: its cache is read only
    (it loads what the client stored; a model it must build is not stored)."""
    from femcam.sweep.diskcache import attach
    from femcam.sweep.parallel import _files_back
    from femcam.sweep.pipeline import ChunkTask

    client = DiskCache(tmp_path)
    _model(client, cp)                                    # the client's verification stored it
    task = ChunkTask(index=0, scene=None, theta=np.zeros(1), options=FAST, disk=client.spec())
    seen = _files_back(lambda t: t.disk, task)[0]
    worker = ModelCache()
    attach(worker, seen)
    assert worker.disk.writable is False and worker.disk.root == client.root
    worker.model_for(cp, RHO, _a(cp), FAST)               # loaded from the client's entry
    worker.model_for(cp, 1.01 * RHO, _a(cp, rho=1.01 * RHO), FAST)   # built, not stored
    assert (worker.stats["loaded"], worker.stats["built"]) == (1, 1)
    assert len(list(client.directory.glob("*.pkl"))) == 1


def test_estimate_coarse_level_is_stored_and_reused(cp, disk, monkeypatch):
    """The two-level estimate's coarse solve is stored too: a warm estimate builds no coarse
    model and gives the cold estimate's errors bit for bit."""
    from femcam.sweep import estimate as est_mod
    built = []
    real = est_mod.build_model

    def counting(*a, **k):
        built.append(k.get("mesh"))
        return real(*a, **k)

    monkeypatch.setattr(est_mod, "build_model", counting)
    a = _a(cp)
    cold = est_mod.family_estimate(cp, RHO, a, FAST, ModelCache(disk=disk))
    n_cold = len(built)
    warm = est_mod.family_estimate(cp, RHO, a, FAST, ModelCache(disk=disk))
    assert n_cold == 1 and len(built) == 1          # the coarse model was built once, cold only
    assert warm.err == cold.err and all(np.isfinite(list(cold.err.values())))
