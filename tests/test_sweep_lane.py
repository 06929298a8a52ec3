"""femcam.sweep.lane: the family phase's forked helper process (results, faults, no orphans)."""

from __future__ import annotations

import functools
import operator
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

from femcam import RunOptions, SweepOptions, sweep
from femcam.sweep import lane as lane_module
from femcam.sweep.cache import ModelCache, default_cache
from femcam.sweep.lane import ForkLane, fork_available
from femcam.sweep.run import parse_angles_deg
from femcam.sweep.table import WALL_CLOCK

pytestmark = pytest.mark.skipif(not fork_available(), reason="the helper process needs fork")

ROOT = Path(__file__).resolve().parents[1]
STUDY = ROOT / "examples" / "seed002_study_model.toml"


def _children(pid: int | None = None) -> list[int]:
    """Process ids whose parent is ``pid`` (default this process), zombies included."""
    pid = os.getpid() if pid is None else pid
    out = []
    for d in Path("/proc").iterdir():
        if not d.name.isdigit():
            continue
        try:
            stat = (d / "stat").read_text()
        except OSError:
            continue
        if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
            out.append(int(d.name))
    return out


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def _wait_sent_and_done(lane, key, timeout=30.0):
    """Wait until the child has computed the job ``key`` (so that take returns its result)."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        entry = lane._queue.get(key)
        if entry is not None and entry[2] == "sent" and entry[1].done():
            return
        time.sleep(0.01)
    raise AssertionError(f"the child did not compute {key!r} within {timeout} s")


def test_child_computes_a_job_and_the_caller_gets_its_result():
    with ForkLane() as lane:
        assert lane.pid is None and lane.threads == 1   # forked on the first job only
        lane.submit("pid", functools.partial(os.getpid))
        assert lane.pid in _children()
        _wait_sent_and_done(lane, "pid")
        assert lane.take("pid", os.getpid) == lane.pid != os.getpid()
        # never queued, or not picklable (a closure): computed here
        assert lane.take("other", lambda: 7) == 7
        lane.submit("closure", lambda: os.getpid())
        assert lane.take("closure", os.getpid) == os.getpid()
    assert lane.pid not in _children() and not _alive(lane.pid)


def test_priority_orders_the_queue_and_a_waiting_caller_helps():
    with ForkLane() as lane:
        lane.submit("slow", functools.partial(time.sleep, 1.0))
        end = time.monotonic() + 30
        while lane._queue["slow"][2] != "sent" and time.monotonic() < end:
            time.sleep(0.01)
        lane.submit("later", functools.partial(operator.add, 1, 1), priority=1)
        lane.submit("soon", functools.partial(operator.add, 2, 2), priority=0)
        assert lane._next()[0].args == (2, 2)
        # waiting for "slow" in the child, the caller computes the queued jobs itself
        assert lane.take("slow", lambda: "here") is None
        assert [e[2] for e in lane._queue.values()] == ["local", "local"]
        assert lane.take("soon", lambda: -1) == 4 and lane.take("later", lambda: -1) == 2


def test_a_job_that_fails_in_the_child_is_computed_here_and_raises_here():
    def here():
        raise ZeroDivisionError("here")

    with ForkLane() as lane:
        lane.submit("bad", functools.partial(operator.truediv, 1, 0))
        _wait_sent_and_done(lane, "bad")
        with pytest.raises(ZeroDivisionError, match="here"):
            lane.take("bad", here)
        assert lane.threads == 1  # the child serves on


def test_a_child_that_dies_costs_time_not_a_hang():
    with ForkLane() as lane:
        lane.submit("long", functools.partial(time.sleep, 60))
        lane.submit("queued", functools.partial(operator.add, 1, 2))
        end = time.monotonic() + 30
        while lane._queue["long"][2] != "sent" and time.monotonic() < end:
            time.sleep(0.01)
        os.kill(lane.pid, signal.SIGKILL)
        t0 = time.monotonic()
        assert lane.take("long", lambda: "here") == "here"
        assert lane.take("queued", lambda: 3) == 3
        assert time.monotonic() - t0 < 20
        assert lane.threads == 0
        lane.submit("after", functools.partial(operator.add, 1, 1))  # no child: not queued
        assert lane.take("after", lambda: "here") == "here"
    assert lane.pid not in _children()


def test_close_ends_a_child_busy_with_a_job_nobody_takes():
    lane = ForkLane()
    lane.submit("long", functools.partial(time.sleep, 60))
    end = time.monotonic() + 30
    while lane._queue["long"][2] != "sent" and time.monotonic() < end:
        time.sleep(0.01)
    t0 = time.monotonic()
    lane.close()
    assert time.monotonic() - t0 < 20
    assert lane.pid not in _children() and not _alive(lane.pid)
    lane.close()  # idempotent


def test_ctrl_c_in_the_parent_ends_the_child():
    with pytest.raises(KeyboardInterrupt):
        with ForkLane() as lane:
            lane.submit("long", functools.partial(time.sleep, 60))
            raise KeyboardInterrupt
    assert lane.pid not in _children() and not _alive(lane.pid)


def test_the_child_ignores_sigint():
    with ForkLane() as lane:
        lane.submit("first", functools.partial(os.getpid))
        _wait_sent_and_done(lane, "first")  # the child has set its handlers
        os.kill(lane.pid, signal.SIGINT)
        lane.submit("pid", functools.partial(os.getpid))
        _wait_sent_and_done(lane, "pid")
        assert lane.take("pid", os.getpid) == lane.pid


def test_a_lane_without_jobs_forks_nothing():
    before = set(_children())
    with ForkLane() as lane:
        assert lane.take("x", lambda: 1) == 1
        lane.submit("closure", lambda: 2)   # not picklable: not a reason to fork
    assert lane.pid is None and set(_children()) <= before


def test_no_orphan_when_the_parent_is_killed(tmp_path):
    """A parent killed with SIGKILL (no cleanup runs) leaves no helper process behind."""
    script = textwrap.dedent("""
        import functools, sys, time
        from femcam.sweep.lane import ForkLane
        lane = ForkLane()
        lane.submit("long", functools.partial(time.sleep, 120))
        print(lane.pid, flush=True)
        time.sleep(120)
    """)
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True, env=env)
    try:
        child = int(proc.stdout.readline())
        assert _alive(child)
    finally:
        proc.kill()
        proc.wait()
    end = time.monotonic() + 20
    while _alive(child) and time.monotonic() < end:
        time.sleep(0.05)
    assert not _alive(child), "the helper process outlived its killed parent"


def test_no_helper_process_from_a_worker_thread():
    """A sweep run in a worker thread (Dask, a threaded study) does not fork: another thread
    might hold a lock the child needs."""
    import threading

    seen = []
    t = threading.Thread(target=lambda: seen.append(fork_available()))
    t.start()
    t.join()
    assert seen == [False] and fork_available()


def test_without_fork_the_family_phase_uses_a_thread(monkeypatch):
    from femcam._threads import Background
    from femcam.sweep import cache as cache_module

    monkeypatch.setattr(cache_module, "fork_available", lambda: False)
    cache = ModelCache()
    with cache.building_in_background(1, process=True) as bg:
        assert isinstance(bg, Background) and bg.threads == 1
    with cache.building_in_background(0, process=True) as bg:
        assert bg.threads == 0   # workers=1: neither a process nor a thread


def _same_sweeps(a, b):
    for k in a.table:
        if k in WALL_CLOCK:
            continue
        x, y = np.asarray(a.table[k]), np.asarray(b.table[k])
        assert x.dtype == y.dtype and np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), k
    timing = ("build_time", "check_time", "solve_time")
    strip = [[{k: v for k, v in f.items() if k not in timing} for f in r.provenance["families"]]
             for r in (a, b)]
    assert strip[0] == strip[1]
    assert a.provenance["estimates"] == b.provenance["estimates"]


@pytest.fixture(scope="module")
def one_process():
    """The reference: ``workers=1``, which starts neither a helper process nor a thread."""
    from femcam.sweep import cache as cache_module

    def refuse(*a, **k):
        raise AssertionError("workers=1 started a helper")

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(cache_module, "ForkLane", refuse)
        mp.setattr(cache_module, "Background", refuse)
        default_cache().clear()
        return sweep(STUDY, SweepOptions(angles=parse_angles_deg("0:360:15"), chunk_size=8),
                     RunOptions(workers=1, model_cache=False))


def test_workers_1_starts_no_helper(one_process):
    assert one_process.provenance["options"]["workers"] == 1


def test_a_sweep_whose_helper_dies_at_once_gives_the_same_rows(monkeypatch, one_process):
    """The helper process exits before its first job: every build is done in this process,
    same rows, and no process is left."""
    from femcam.sweep import run as run_module

    monkeypatch.setattr(run_module, "_background_threads", lambda run: 1)
    monkeypatch.setattr(lane_module, "_serve", lambda *a: os._exit(3))
    before = set(_children())
    default_cache().clear()
    r = sweep(STUDY, SweepOptions(angles=parse_angles_deg("0:360:15"), chunk_size=8),
              RunOptions(workers="auto", model_cache=False))
    _same_sweeps(one_process, r)
    assert set(_children()) <= before


def test_what_the_helper_builds_is_stored_by_this_process(monkeypatch, tmp_path):
    """A cold sweep with the helper process fills the persistent cache (the helper writes
    nothing: this process stores what it receives), so that a warm sweep builds nothing."""
    from femcam.sweep import run as run_module

    th = np.radians([30.0, 60.0, 90.0, 120.0, 200.0, 250.0])
    opts = SweepOptions(angles=th, a_over_h=4)
    run = RunOptions(cache_dir=tmp_path / "c", workers="auto")
    before = set(_children())
    with monkeypatch.context() as mp:
        mp.setattr(run_module, "_background_threads", lambda run: 1)
        default_cache().clear()
        cold = sweep(STUDY, opts, run)
    assert set(_children()) <= before, "the helper process was not reaped"
    default_cache().clear()
    warm = sweep(STUDY, opts, RunOptions(cache_dir=tmp_path / "c", workers=1))
    mc = [r.provenance["options"]["model_cache"] for r in (cold, warm)]
    assert mc[0]["built"] >= 1 and mc[1]["built"] == 0 and mc[1]["loaded"] == mc[0]["built"]
    assert mc[1]["checks_built"] == 0 and mc[1]["checks_loaded"] == mc[0]["checks_built"]
    assert warm.provenance["estimates"] == cold.provenance["estimates"]
    for k in cold.table:
        if k not in WALL_CLOCK:
            x, y = np.asarray(cold.table[k]), np.asarray(warm.table[k])
            assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), k


def test_ctrl_c_in_the_family_phase_leaves_no_helper(monkeypatch):
    """Ctrl-C while the helper builds: the sweep says it was interrupted, the helper is ended
    and reaped."""
    from femcam.sweep import run as run_module
    from femcam.sweep import verify as verify_module
    from femcam.sweep.run import SweepInterrupted

    def interrupted(*a, **k):
        raise KeyboardInterrupt

    from femcam.sweep import cache as cache_module

    started = []

    class Counted(cache_module.ForkLane):
        def _start(self):
            ok = super()._start()
            started.append(self.pid)
            return ok

    monkeypatch.setattr(cache_module, "ForkLane", Counted)
    monkeypatch.setattr(run_module, "_background_threads", lambda run: 1)
    monkeypatch.setattr(verify_module, "_finish_group", interrupted)
    before = set(_children())
    default_cache().clear()
    with pytest.raises(SweepInterrupted):
        sweep(STUDY, SweepOptions(angles=parse_angles_deg("0:360:30")),
              RunOptions(workers="auto", model_cache=False))
    assert started and started[0] is not None   # the helper was running
    assert set(_children()) <= before and not _alive(started[0])
