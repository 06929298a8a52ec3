"""Faults a sweep must survive without losing or mixing results.

Each test reproduces one fault (a relative ``--out`` read from another directory, a Dask worker
with another working directory, two writers in one directory, a resume over another scene's
chunks, threads meshing at once, Ctrl-C) and checks the behaviour against what the files must
contain, counted independently of femcam (file listings, the XML of the ``.pvd``, the grid size
of the analytic Hertz ``.vtu`` fixed by its definition: ``(2 n - 1) n`` points for n = 41).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from femcam.cli import main
from femcam.errors import FemcamError, InputError
from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, parse_angles_deg, sweep
from femcam.sweep.store import CHUNK_SCENE_KEY, DirLock

ROOT = Path(__file__).resolve().parents[1]
STUDY = ROOT / "examples" / "seed002_study_model.toml"
HERTZ_GRID_POINTS = (2 * 41 - 1) * 41  # write_hertz_vtu's structured grid, n = 41


def _pvd_files(pvd: Path) -> list[str]:
    return [ds.attrib["file"] for ds in ET.parse(pvd).getroot().iter("DataSet")]


# -- 1. .pvd paths relative to the .pvd ------------------------------------------------------
def test_pvd_opens_from_another_directory_with_relative_out(tmp_path, monkeypatch):
    """The README form ``--out results/NAME`` (relative): the .pvd must name its files relative
    to itself, so pyvista opens it from any working directory."""
    pv = pytest.importorskip("pyvista")
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    rc = main(["sweep", str(STUDY), "--out", "results/s", "--angles-deg", "0:360:60",
               "--method", "hertz", "--vtk-every", "1", "--no-plots", "--progress", "off"])
    assert rc == 0
    pvd = work / "results" / "s" / "sweep.pvd"
    files = _pvd_files(pvd)
    on_disk = sorted(p.name for p in (pvd.parent / "vtk").glob("*.vtu"))
    assert files and sorted(Path(f).name for f in files) == on_disk
    assert all(f.startswith("vtk/") for f in files), files  # relative to the .pvd
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    reader = pv.get_reader(str(pvd))
    assert len(reader.time_values) == len(files)
    for t in reader.time_values:
        reader.set_active_time_value(t)
        mesh = reader.read()[0]
        assert mesh.n_points == HERTZ_GRID_POINTS


# -- 3. one writer per output directory -------------------------------------------------------
def test_second_writer_is_refused_with_one_line(tmp_path, capsys):
    out = tmp_path / "run"
    out.mkdir()
    held = DirLock(out).acquire()
    try:
        rc = main(["sweep", str(STUDY), "--out", str(out), "--angles-deg", "0:90:30",
                   "--method", "hertz", "--no-plots", "--progress", "off"])
    finally:
        held.release()
    err = capsys.readouterr().err.strip()
    assert rc == 1
    assert len(err.splitlines()) == 1 and "another femcam sweep" in err and str(os.getpid()) in err
    assert sorted(p.name for p in out.iterdir()) == [".femcam.lock"]  # nothing written


@pytest.mark.slow  # ~1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_lock_is_released_when_the_holder_is_killed(tmp_path):
    """SIGKILL leaves no stale lock: the kernel drops a flock with the holder's descriptor."""
    code = ("import sys, time; from femcam.sweep.store import DirLock; "
            "DirLock(sys.argv[1]).acquire(); print('held', flush=True); time.sleep(60)")
    proc = subprocess.Popen([sys.executable, "-c", code, str(tmp_path)], stdout=subprocess.PIPE,
                            env={**os.environ, "PYTHONPATH": str(ROOT)})
    try:
        assert proc.stdout.readline().strip() == b"held"
        with pytest.raises(InputError, match=f"pid {proc.pid}"):
            DirLock(tmp_path).acquire()
    finally:
        proc.kill()
        proc.communicate(timeout=30)
    DirLock(tmp_path).acquire().release()


def test_non_empty_directory_needs_resume_or_overwrite(tmp_path, capsys):
    args = ["sweep", str(STUDY), "--out", str(tmp_path), "--angles-deg", "0:90:30",
            "--method", "hertz", "--vtk-every", "0", "--no-plots", "--progress", "off"]
    (tmp_path / "notes.txt").write_text("mine")
    assert main(args) == 1
    err = capsys.readouterr().err
    assert "not empty" in err and "--overwrite" in err and "--resume" in err
    assert not (tmp_path / "sweep.csv").exists()
    assert main(args + ["--overwrite"]) == 0
    assert (tmp_path / "sweep.csv").exists() and (tmp_path / "notes.txt").read_text() == "mine"


def test_api_non_empty_out_names_resume_and_overwrite(tmp_path):
    """The API refuses a non-empty ``out`` in its own words (the arguments and what each does),
    the CLI in flag words (tests/test_cli_errors.py)."""
    (tmp_path / "notes.txt").write_text("mine")
    msg = (f"out = '{tmp_path}': the directory is not empty; pass resume=True to continue the sweep "
           "in it, overwrite=True to replace its results, or choose another out")
    with pytest.raises(InputError) as e:
        sweep(load_scene(STUDY),
              SweepOptions(angles=parse_angles_deg("0:90:30"), method="hertz", plots=False),
              RunOptions(out=tmp_path, progress=False))
    assert str(e.value) == msg
    assert not (tmp_path / "sweep.csv").exists()


def test_resume_refuses_a_chunk_of_another_scene(tmp_path):
    """A chunk computed for another scene (here: another motion law) inside a directory whose
    manifest names this scene is refused, never reported under this scene's name."""
    th = parse_angles_deg("0:360:30")
    scene = load_scene(STUDY)
    other = scene.with_law("bezier7")
    a, b = tmp_path / "a", tmp_path / "b"
    sweep(scene,
          SweepOptions(angles=th, chunk_size=4, method="hertz", vtk_every=0, plots=False),
          RunOptions(out=a, workers=1))
    sweep(other,
          SweepOptions(angles=th, chunk_size=4, method="hertz", vtk_every=0, plots=False),
          RunOptions(out=b, workers=1))
    with np.load(a / "chunks" / "chunk_00001.npz") as za, \
            np.load(b / "chunks" / "chunk_00001.npz") as zb:
        assert str(za[CHUNK_SCENE_KEY]) != str(zb[CHUNK_SCENE_KEY])
        assert not np.array_equal(za["Fc"], zb["Fc"])  # the two scenes really differ
    (b / "chunks" / "chunk_00001.npz").replace(a / "chunks" / "chunk_00001.npz")
    with pytest.raises(InputError, match="chunk_00001.npz was computed for another scene"):
        sweep(scene,
              SweepOptions(angles=th, chunk_size=4, method="hertz", vtk_every=0, plots=False),
              RunOptions(out=a, resume=True, workers=1))


# -- 4. gmsh from several threads --------------------------------------------------------------
def test_meshing_from_four_threads_matches_serial():
    """Four threads mesh at once (a Dask worker with threads_per_worker=4): every mesh must equal
    the one built alone (same node and triangle counts, same coordinates)."""
    from femcam.mesh import MeshOptions, build_contact_mesh

    kw = dict(Rr=0.02, rho=0.05, a_ref=2e-4, options=MeshOptions(a_over_h=4))
    ref = build_contact_mesh(**kw)
    got, errors = [None] * 4, []

    def work(k):
        try:
            got[k] = build_contact_mesh(**kw)
        except Exception as exc:  # collected: an assertion in a thread would be lost
            errors.append(exc)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(120)
    assert not errors, errors
    for m in got:
        for body in ("cam", "roller"):
            np.testing.assert_array_equal(getattr(m, body).points, getattr(ref, body).points)
            np.testing.assert_array_equal(getattr(m, body).triangles, getattr(ref, body).triangles)


# -- 2. + 4. Dask: files come back to the client; threaded workers ----------------------------
@pytest.mark.slow
def test_dask_threaded_worker_relative_out_files_come_back(tmp_path, monkeypatch):
    """A LocalCluster worker process started in another directory, 4 threads, FE method, a
    relative ``out``: every .vtu lands in the client's ``out/vtk`` (none in the worker's
    directory) and the .pvd lists them; losing them fails loudly."""
    distributed = pytest.importorskip("dask.distributed")
    wdir, cdir = tmp_path / "worker", tmp_path / "client"
    wdir.mkdir()
    cdir.mkdir()
    monkeypatch.chdir(wdir)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=4, processes=True,
                                  dashboard_address=None) as cluster:
        monkeypatch.chdir(cdir)
        th = parse_angles_deg("0:360:30")
        res = sweep(STUDY,
                    SweepOptions(angles=th, chunk_size=3, vtk_every=1, plots=False),
                    RunOptions(out="rel", client=cluster))
        n_ok = int(np.count_nonzero(res.ok))
        vtus = sorted(p.name for p in (cdir / "rel" / "vtk").glob("*.vtu"))
        assert n_ok > 0 and len(vtus) == n_ok
        assert sorted(Path(f).name for f in _pvd_files(cdir / "rel" / "sweep.pvd")) == vtus
        assert not list(wdir.rglob("*.vtu"))
        from femcam.sweep import parallel as par

        monkeypatch.setattr(par, "_write_back", lambda task, files: None)  # files lost
        with pytest.raises(FemcamError, match=".vtu files are missing"):
            sweep(STUDY,
                  SweepOptions(angles=th, chunk_size=3, vtk_every=1, plots=False),
                  RunOptions(out="rel2", client=cluster))


# -- 5. Ctrl-C -----------------------------------------------------------------------------------
def _wait_for_a_chunk(proc, out: Path) -> None:
    """Until the sweep ``proc`` writing into ``out`` has saved its first chunk (120 s at most)."""
    t0 = time.monotonic()
    while not list((out / "chunks").glob("chunk_*.npz")):
        assert proc.poll() is None, proc.communicate(timeout=60)
        assert time.monotonic() - t0 < 120, "no chunk appeared"
        time.sleep(0.02)


def _interrupt(tmp_path, *extra):
    out = tmp_path / "run"
    cmd = [sys.executable, "-m", "femcam", "sweep", str(STUDY), "--out", str(out),
           "--angles-deg", "0:360:20", "--chunk-size", "3", "--no-plots", "--progress", "off",
           "--workers", "1", "--vtk-every", "0", "--chunk-delay-s", "0.5", *extra]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env={**os.environ, "PYTHONPATH": str(ROOT)})
    try:
        _wait_for_a_chunk(proc, out)
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate(timeout=60)
    return proc.returncode, err.decode().strip(), out


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_ctrl_c_before_any_gmsh_mesh_one_line_and_130(tmp_path):
    """Hertz method: gmsh is never initialised."""
    rc, err, out = _interrupt(tmp_path, "--method", "hertz")
    assert rc == 130, err  # the one line (or the traceback) says why
    assert len(err.splitlines()) == 1 and "Traceback" not in err, err
    n = len(list((out / "chunks").glob("chunk_*.npz")))
    assert f"{n} of 6 chunks saved" in err and "--resume" in err


@pytest.mark.slow
def test_ctrl_c_after_gmsh_meshed_one_line_and_130(tmp_path):
    """FE method: the families were meshed (gmsh initialised and finalised) before the chunks."""
    rc, err, out = _interrupt(tmp_path, "--method", "fe")
    assert rc == 130, err  # the one line (or the traceback) says why
    assert len(err.splitlines()) == 1 and "Traceback" not in err, err
    assert "--resume" in err


# -- 12. results you can come back to ---------------------------------------------------------
def test_sweep_reloads_with_report(tmp_path):
    """The fast version: tables only; ``SweepResult.load`` gives back the exact SI table."""
    from femcam.sweep import SweepResult

    th = parse_angles_deg("0:360:45")
    res = sweep(STUDY,
                SweepOptions(angles=th, method="hertz", vtk_every=0, plots=False),
                RunOptions(out=tmp_path, workers=1))
    back = SweepResult.load(tmp_path)
    assert back.method == "hertz" and back.n_angles == th.size == 8
    np.testing.assert_array_equal(back.theta, th)
    for k in ("Fc", "p0_hertz", "vm_max", "wear_depth"):
        np.testing.assert_array_equal(back[k], res[k])
    assert list(back.status) == list(res.status)
    assert back.surface_profile is None  # no plots: no plot data
    assert "8 angles" in (tmp_path / "report.md").read_text()
    assert back.paths["report"] == str(tmp_path / "report.md")


@pytest.mark.slow
def test_api_defaults_match_the_cli_and_a_sweep_reloads_and_replots(tmp_path):
    """``sweep(..., out=DIR)`` writes what ``femcam sweep --out DIR`` writes (a .vtu every 10th
    angle, the plots, report.md); ``SweepResult.load(DIR)`` gives back the table and the plots'
    data, and ``plot_sweep`` re-plots from it alone."""
    pytest.importorskip("matplotlib")
    from femcam.sweep import SweepResult
    from femcam.viz.sweep import plot_sweep

    th = parse_angles_deg("0:360:15")  # 24 angles: the 10th-angle series is rows 0, 10, 20
    api, cli = tmp_path / "api", tmp_path / "cli"
    res = sweep(STUDY, SweepOptions(angles=th, method="hertz"), RunOptions(out=api, workers=1))
    assert main(["sweep", str(STUDY), "--out", str(cli), "--angles-deg", "0:360:15",
                 "--method", "hertz", "--workers", "1", "--progress", "off"]) == 0
    tree = {d: sorted(str(p.relative_to(d)) for p in d.rglob("*")
                      if p.is_file() and "chunks" not in p.parts) for d in (api, cli)}
    assert tree[api] == tree[cli]
    assert sorted(Path(f).name for f in _pvd_files(api / "sweep.pvd")) == \
        [f"angle_{d:08.3f}deg.vtu" for d in (0.0, 150.0, 300.0)]
    report = (api / "report.md").read_text()
    assert f"{th.size} angles" in report and "| p0 Hertz | " in report

    back = SweepResult.load(api)
    assert back.method == "hertz" and back.n_angles == th.size
    np.testing.assert_array_equal(back.theta, th)  # SI, exact round trip of float64
    for k in ("Fc", "p0_hertz", "vm_max"):
        np.testing.assert_array_equal(back[k], res[k])
    assert list(back.status) == list(res.status)
    assert back.hertz_factors is not None and back.surface_profile is not None
    replot = tmp_path / "replot"
    paths = plot_sweep(back, replot)
    assert sorted(Path(p).name for p in paths.values()) == \
        sorted(p.name for p in (api / "plots").glob("*.png"))
    with pytest.raises(InputError, match="no sweep.npz"):
        SweepResult.load(tmp_path)


def test_vtu_arrays_have_units_and_one_stress_tensor(tmp_path):
    """Hertz field at the centre of the contact surface (Johnson 1985 §4.2, frictionless): the
    tensor ``stress_Pa`` must read sx = sz = -p0, sy = -2 nu p0 (plane strain), txz = 0, with
    p0 = sqrt(w E* / (pi R)) computed here; von Mises of the written tensor equals the written
    ``von_mises_Pa`` everywhere (frame invariant)."""
    import meshio

    from femcam.hertz import LineContact
    from femcam.io import write_hertz_vtu
    from femcam.materials import STEEL

    F, L, R1, R2 = 2000.0, 0.01, 0.03, 0.01
    hc = LineContact(F=F, length=L, R1=R1, R2=R2, cam=STEEL, roller=STEEL, mu=0.0)
    m = meshio.read(write_hertz_vtu(tmp_path / "h.vtu", hc))
    assert {"stress_Pa", "von_mises_Pa", "tau1_Pa", "contact_pressure_Pa"} <= set(m.point_data)
    S = m.point_data["stress_Pa"]
    assert S.shape == (len(m.points), 6)
    E_star = STEEL.E / (2 * (1 - STEEL.nu ** 2))
    p0 = np.sqrt(F / L * E_star / (np.pi * R1 * R2 / (R1 + R2)))
    i0 = int(np.argmin(np.hypot(m.points[:, 0], m.points[:, 1])))
    assert np.hypot(*m.points[i0, :2]) == 0.0
    np.testing.assert_allclose(S[i0, :4], [-p0, -p0, -2 * STEEL.nu * p0, 0.0], rtol=1e-9, atol=1e-6 * p0)
    sxx, syy, szz, sxy = S[:, 0], S[:, 1], S[:, 2], S[:, 3]
    vm = np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3 * sxy ** 2)
    np.testing.assert_allclose(vm, m.point_data["von_mises_Pa"], rtol=1e-9, atol=1e-9 * p0)


def test_contact_result_pickles_without_its_model(tmp_path):
    """A pickled ContactResult drops the factorised model (small, process independent); its
    full-field methods then take the model explicitly and give the original's numbers."""
    import pickle

    from femcam.fe import MeshOptions, solve_contact
    from femcam.materials import STEEL

    r = solve_contact(1500.0, 0.02, 0.01, STEEL, STEEL, 0.01, mesh=MeshOptions(a_over_h=4))
    blob = pickle.dumps(r)
    back = pickle.loads(blob)
    assert back.model is None and back.p0 == r.p0 and back.converged == r.converged
    np.testing.assert_array_equal(back.p, r.p)
    with pytest.raises(InputError, match="unpickled"):
        back.field_at_nodes()
    u0, s0 = r.field_at_nodes()
    u1, s1 = back.field_at_nodes(model=r.model)
    np.testing.assert_array_equal(u0, u1)
    np.testing.assert_array_equal(s0["von_mises"], s1["von_mises"])


# -- 11. progress --------------------------------------------------------------------------------
def test_progress_phase_shows_long_phases_only():
    import io

    from femcam.sweep import Progress

    long, short = io.StringIO(), io.StringIO()
    with Progress(0, enabled=True, stream=long, delay_s=0.0).phase("model families", 0.01):
        time.sleep(0.1)
    with Progress(0, enabled=True, stream=short, delay_s=5.0).phase("model families", 0.01):
        pass
    text = long.getvalue()  # not a terminal: two plain lines
    assert text.startswith("femcam: model families ...\n") and text.endswith(" s\n")
    assert text.splitlines()[-1].startswith("femcam: model families: ")
    assert short.getvalue() == ""
    off = io.StringIO()
    with Progress(0, enabled=False, stream=off, delay_s=0.0).phase("x", 0.01):
        time.sleep(0.03)
    assert off.getvalue() == ""


@pytest.mark.slow
def test_animate_writes_one_gif_frame_per_vtu(tmp_path, capsys):
    pytest.importorskip("pyvista")
    from PIL import Image

    assert main(["sweep", str(STUDY), "--out", str(tmp_path), "--angles-deg", "0:360:90",
                 "--method", "hertz", "--vtk-every", "1", "--no-plots", "--progress", "off",
                 "--animate"]) == 0
    n_vtu = len(_pvd_files(tmp_path / "sweep.pvd"))
    with Image.open(tmp_path / "animation.gif") as gif:
        assert gif.n_frames == n_vtu == 4
    with pytest.raises(InputError, match="animate"):
        sweep(STUDY, SweepOptions(angles=[0.0], method="hertz", animate=True))


@pytest.mark.slow
def test_ctrl_c_with_a_process_pool_one_line_and_130(tmp_path):
    """Pool workers ignore SIGINT (the parent stops the pool): still one line, exit 130, and no
    worker left behind (their stdout pipe reaches EOF: communicate returned)."""
    rc, err, out = _interrupt(tmp_path, "--method", "fe", "--workers", "2")
    assert rc == 130, err  # the one line (or the traceback) says why
    assert len(err.splitlines()) == 1 and "Traceback" not in err, err
    assert "--resume" in err


def _children(pid: int) -> list[int]:
    """The child processes of ``pid`` (Linux ``/proc``; none elsewhere)."""
    kids = []
    for task in Path(f"/proc/{pid}/task").glob("*"):
        try:
            kids += [int(k) for k in (task / "children").read_text().split()]
        except OSError:
            pass
    return kids


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="needs Linux /proc")
def test_a_pool_worker_killed_one_line_the_saved_chunks_and_resume(tmp_path):
    """A worker killed mid-sweep (the OOM killer, ``kill -9``): one line naming what happened,
    how many chunks are saved and how to resume, exit 1, never Python's BrokenProcessPool
    traceback; ``--resume`` then completes the sweep (all 6 chunk files of 18 angles)."""
    out = tmp_path / "run"
    cmd = [sys.executable, "-m", "femcam", "sweep", str(STUDY), "--out", str(out),
           "--angles-deg", "0:360:20", "--chunk-size", "3", "--no-plots", "--progress", "off",
           "--vtk-every", "0", "--chunk-delay-s", "1.0", "--method", "hertz", "--workers", "2"]
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    try:
        _wait_for_a_chunk(proc, out)
        kids = _children(proc.pid)
        assert kids, "no worker process found"
        os.kill(kids[0], signal.SIGKILL)
        _, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate(timeout=60)
    err = err.decode().strip()
    assert proc.returncode == 1, err
    assert len(err.splitlines()) == 1 and "Traceback" not in err, err
    assert "worker process" in err and "chunks saved" in err and "--resume" in err, err
    res = subprocess.run(cmd + ["--resume"], capture_output=True, env=env, timeout=300)
    assert res.returncode == 0, res.stderr.decode()
    assert len(list((out / "chunks").glob("chunk_*.npz"))) == 6
