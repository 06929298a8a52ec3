"""``femcam._threads``: one OpenBLAS thread inside ``single_threaded_blas``, the counts restored
after, and the scan of the loaded libraries cached until a module is imported."""

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
