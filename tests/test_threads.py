"""``femcam._threads``: one OpenBLAS thread inside ``single_threaded_blas``, the counts restored
after, and the scan of the loaded libraries cached until a module is imported; ``Background``:
results taken back by key, a job not yet started computed by the caller."""

import sys

import pytest

from femcam import _threads


def test_single_threaded_blas_sets_and_restores_the_counts_with_the_scan_cached():
    before = _threads.blas_threads()
    if not before:
        pytest.skip("no OpenBLAS found in this process (another BLAS, or not Linux)")
    scans = []
    real = _threads._scan_blas_libs

    def counting():
        scans.append(1)
        return real()

    _threads._scan_blas_libs, _threads._found = counting, (-1, [])
    try:
        with _threads.single_threaded_blas():
            assert _threads.blas_threads() == [1] * len(before)
        assert _threads.blas_threads() == before
        assert len(scans) == 1                       # scanned once for the four calls above
        sys.modules["_femcam_test_dummy"] = sys      # a new module: the next call scans again
        _threads.blas_threads()
        assert len(scans) == 2
    finally:
        sys.modules.pop("_femcam_test_dummy", None)
        _threads._scan_blas_libs, _threads._found = real, (-1, [])


def test_background_takes_results_steals_queued_jobs_and_reraises():
    import threading

    started, release = threading.Event(), threading.Event()

    def blocking():
        started.set()
        release.wait(10)
        return "from the background"

    ran_here = []
    with _threads.Background(1) as bg:
        bg.submit("slow", blocking)
        assert started.wait(10)
        bg.submit("queued", lambda: "from the background")  # waits behind "slow"
        # a job that has not started is cancelled and computed by the caller
        assert bg.take("queued", lambda: ran_here.append(1) or "here") == "here"
        assert ran_here == [1]
        release.set()
        assert bg.take("slow", lambda: "here") == "from the background"  # running: waited for
        # while the job it takes runs, the caller runs the queued ones (kept for their take)
        started.clear(), release.clear()
        bg.submit("slow2", blocking)
        assert started.wait(10)
        bg.submit("releases", lambda: release.set() or "ran while waiting")
        assert bg.take("slow2", lambda: "here") == "from the background"
        assert bg.take("releases", lambda: "again") == "ran while waiting"
        bg.submit("bad", lambda: 1 / 0)
        with pytest.raises(ZeroDivisionError):  # raised in the caller, wherever the job ran
            bg.take("bad", lambda: 1 / 0)
        assert bg.take("never submitted", lambda: 7) == 7
    bg.submit("after close", lambda: 1)   # closed: nothing queued, the caller computes
    assert bg.take("after close", lambda: 2) == 2
    assert _threads.Background(0).take("x", lambda: 3) == 3


def test_background_defer_is_never_dropped():
    done = []
    with _threads.Background(1) as bg:
        bg.submit("long", lambda: __import__("time").sleep(0.05))
        bg.defer(lambda: done.append("deferred"))   # queued behind "long", run before exit
    assert done == ["deferred"]
    _threads.Background(0).defer(lambda: done.append("at once"))
    assert done == ["deferred", "at once"]
