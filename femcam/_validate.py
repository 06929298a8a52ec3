"""Small input checks shared by every module.

Each check returns the value as ``float`` (or a float array) and raises
:class:`femcam.errors.InputError` with one message that names the parameter, its value and
its unit: ``"<name> = <value> <unit>: must be <condition>"``.
"""

from __future__ import annotations

import math

import numpy as np

from .errors import InputError


def _fmt(value) -> str:
    try:
        return f"{value!r}" if not isinstance(value, float) else f"{value:g}"
    except Exception:  # pragma: no cover - repr of exotic objects
        return "<unprintable>"


def fail(name: str, value, unit: str, condition: str) -> InputError:
    """Build the standard error (caller raises it)."""
    u = f" {unit}" if unit else ""
    return InputError(f"{name} = {_fmt(value)}{u}: {condition}")


def number(name: str, value, unit: str = "") -> float:
    """A finite real number."""
    if isinstance(value, bool):
        raise fail(name, value, unit, "must be a number")
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise fail(name, value, unit, "must be a number") from None
    if not math.isfinite(x):
        raise fail(name, value, unit, "must be finite")
    return x


def positive(name: str, value, unit: str = "") -> float:
    """A finite number > 0."""
    x = number(name, value, unit)
    if x <= 0.0:
        raise fail(name, value, unit, "must be > 0")
    return x


def nonnegative(name: str, value, unit: str = "") -> float:
    """A finite number >= 0."""
    x = number(name, value, unit)
    if x < 0.0:
        raise fail(name, value, unit, "must be >= 0")
    return x


def in_range(name: str, value, lo: float, hi: float, unit: str = "", *,
             lo_open: bool = False, hi_open: bool = False) -> float:
    """A finite number in [lo, hi]; ``lo_open``/``hi_open`` make that end exclusive."""
    x = number(name, value, unit)
    bad_lo = x <= lo if lo_open else x < lo
    bad_hi = x >= hi if hi_open else x > hi
    if bad_lo or bad_hi:
        lb = "(" if lo_open else "["
        rb = ")" if hi_open else "]"
        raise fail(name, value, unit, f"must be in {lb}{lo:g}, {hi:g}{rb}")
    return x


def finite_array(name: str, value, unit: str = "") -> np.ndarray:
    """A float array with no NaN or inf.

    Text, ``None`` and booleans are refused (``numpy`` would read ``"1500"`` as 1500.0 and
    ``None`` as NaN), so the message names what was passed, not a converted value.
    """
    if value is None or isinstance(value, str | bytes | bool):
        raise fail(name, value, unit, "must be a number or an array of numbers")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise fail(name, value, unit, "must be numeric") from None
    if not np.all(np.isfinite(arr)):
        bad = arr[~np.isfinite(arr)].flat[0]
        raise fail(name, bad, unit, "must be finite (array contains NaN/inf)")
    return arr


def choice(name: str, value, options) -> str:
    """One of a fixed set of strings."""
    if value not in options:
        raise InputError(f"{name} = {value!r}: must be one of {sorted(options)}")
    return value


def integer(name: str, value, lo: int | None = None, unit: str = "") -> int:
    """An integer (``int`` or an integral ``numpy`` integer; not bool, not float) ``>= lo``."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        raise fail(name, value, unit, "must be an integer" + (f" >= {lo}" if lo is not None else ""))
    n = int(value)
    if lo is not None and n < lo:
        raise fail(name, value, unit, f"must be an integer >= {lo}")
    return n


def positive_array(name: str, value, unit: str = "") -> np.ndarray:
    """A float array (or scalar) of finite numbers, all > 0."""
    arr = finite_array(name, value, unit)
    if np.any(arr <= 0.0):
        positive(name, float(arr[arr <= 0.0].flat[0]), unit)  # raises the scalar message
    return arr


def in_range_array(name: str, value, lo: float, hi: float, unit: str = "", *,
                   lo_open: bool = False, hi_open: bool = False) -> np.ndarray:
    """A float array (or scalar) of finite numbers, all in [lo, hi] (ends open on request)."""
    arr = finite_array(name, value, unit)
    bad = (arr <= lo if lo_open else arr < lo) | (arr >= hi if hi_open else arr > hi)
    if np.any(bad):
        in_range(name, float(arr[bad].flat[0]), lo, hi, unit, lo_open=lo_open, hi_open=hi_open)
    return arr
