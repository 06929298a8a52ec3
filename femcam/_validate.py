"""Small input checks shared by every module.

Each check returns the value as ``float`` (or a float array) and raises
:class:`femcam.errors.InputError` with one message that names the parameter, its value and
its unit: ``"<name> = <value> <unit>: must be <condition>"``.

Parameters common to every check: ``name`` (str, the parameter as the user wrote it: an API
argument, a CLI flag or a scene key), ``value`` (the input), ``unit`` (str, shown after the
value; "" for none) and the bounds of the condition (``lo``, ``hi``, options). Returns: the
checked value (``float``, ``int``, ``str`` or ``ndarray``, as each name says). Import it as
``from femcam import _validate`` (one name everywhere).
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
    if type(value) in _SCALARS:  # fast path (a 0-d ufunc costs ~10x a math call)
        return np.asarray(number(name, value, unit))
    arr = _floats(name, value, unit)
    if not np.isfinite(arr).all():  # the method, not np.all: a tenth of the call overhead
        bad = arr[~np.isfinite(arr)].flat[0]
        raise fail(name, bad, unit, "must be finite (array contains NaN/inf)")
    return arr


_F64 = np.dtype(float)
_SCALARS = frozenset((float, int, np.float64))  # bool is its own type: not in the fast path


def _floats(name: str, value, unit: str) -> np.ndarray:
    """``value`` as a float array; text, ``None``, booleans and non-numbers refused. A float64
    array is returned as it is and a Python float or int converted directly (the hot cases:
    these checks run per cam angle)."""
    t = type(value)
    if t is np.ndarray and value.dtype == _F64:
        return value
    if t is float or t is int:
        return np.asarray(value, dtype=float)
    if value is None or isinstance(value, str | bytes | bool):
        raise fail(name, value, unit, "must be a number or an array of numbers")
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise fail(name, value, unit, "must be numeric") from None


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
    if type(value) in _SCALARS:
        return np.asarray(positive(name, value, unit))
    arr = finite_array(name, value, unit)
    if not (arr > 0.0).all():
        positive(name, float(arr[arr <= 0.0].flat[0]), unit)  # raises the scalar message
    return arr


def in_range_array(name: str, value, lo: float, hi: float, unit: str = "", *,
                   lo_open: bool = False, hi_open: bool = False) -> np.ndarray:
    """A float array (or scalar) of finite numbers, all in [lo, hi] (ends open on request)."""
    arr = finite_array(name, value, unit)
    bad = (arr <= lo if lo_open else arr < lo) | (arr >= hi if hi_open else arr > hi)
    if bad.any():
        in_range(name, float(arr[bad].flat[0]), lo, hi, unit, lo_open=lo_open, hi_open=hi_open)
    return arr


def data_array(name: str, value, unit: str = "", *, inf_ok: bool = False) -> np.ndarray:
    """A float array of numbers in which NaN marks a missing value (a failed solve, no contact);
    text, ``None``, booleans and (unless ``inf_ok``) ``inf`` are refused."""
    arr = _floats(name, value, unit)
    if not inf_ok and np.isinf(arr).any():
        raise fail(name, float(arr[np.isinf(arr)].flat[0]), unit,
                   "must be finite (NaN marks a missing value)")
    return arr


def nonnegative_array(name: str, value, unit: str = "") -> np.ndarray:
    """A float array (or scalar) of finite numbers, all >= 0."""
    if type(value) in _SCALARS:
        return np.asarray(nonnegative(name, value, unit))
    arr = finite_array(name, value, unit)
    if not (arr >= 0.0).all():
        nonnegative(name, float(arr[arr < 0.0].flat[0]), unit)  # raises the scalar message
    return arr


def radius_array(name: str, value, unit: str = "m") -> np.ndarray:
    """A signed radius of curvature (or an array of them): nonzero, not NaN; ``-inf``/``inf`` is a
    flat surface and a negative value a concave one, so both are accepted."""
    arr = _floats(name, value, unit)
    bad = np.isnan(arr) | (arr == 0.0)
    if bad.any():
        raise fail(name, float(arr[bad].flat[0]), unit,
                   "must be a nonzero number (negative = concave, inf = flat)")
    return arr


def broadcast(**named) -> tuple:
    """The arrays ``named`` (name -> ndarray) broadcast against each other, or an InputError
    naming the parameters and their shapes (never numpy's "operands could not be broadcast").

    >>> [a.shape for a in broadcast(s=np.zeros(3), Rb=np.asarray(0.01))]
    [(3,), (3,)]
    """
    try:
        return tuple(np.broadcast_arrays(*named.values()))
    except ValueError:
        shapes = ", ".join(f"{k} has shape {np.shape(v)}" for k, v in named.items())
        raise InputError(f"{', '.join(named)}: {shapes}: they do not broadcast (give one value, or one "
                         "per element of the others)") from None


def radius(name: str, value, unit: str = "m") -> float:
    """One signed radius of curvature (see :func:`radius_array`) as a ``float``."""
    arr = radius_array(name, value, unit)
    if arr.ndim != 0:
        raise fail(name, value, unit, "must be a number (negative = concave, inf = flat)")
    return float(arr)


def record(name: str, value, what: str, *attrs: str):
    """An input record (a scene, a model, a program) recognised by the attributes the caller reads
    (duck typing keeps the layers one way: a lower module need not import the record's class);
    anything else, a string or ``None`` included, raises naming ``name`` and ``what`` it must be."""
    if value is None or isinstance(value, str | bytes | int | float) or \
            not all(hasattr(value, a) for a in attrs):
        raise fail(name, value if value is None or isinstance(value, str | int | float) else
                   type(value).__name__, "", f"must be {what}")
    return value


def instance(name: str, value, cls: type, what: str = ""):
    """``value`` if it is a ``cls``, else an error naming ``name`` and what it must be."""
    if not isinstance(value, cls):
        shown = value if value is None or isinstance(value, str | int | float) else type(value).__name__
        raise fail(name, shown, "", f"must be {what or 'a ' + cls.__name__}")
    return value


def optional(check, name: str, value, *args, **kwargs):
    """``None`` (not given) or ``check(name, value, *args, **kwargs)``."""
    return None if value is None else check(name, value, *args, **kwargs)


def workers(name: str, value) -> int | str:
    """A worker count: an integer >= 1, or ``"auto"`` (any case; also a numeric string).

    Parameters
    ----------
    name : str
        Parameter name for the message (``"workers"``, ``"--workers"``).
    value : int, float or str
        The requested number of processes.

    Returns
    -------
    int or str
        The count, or ``"auto"``.

    >>> workers("workers", " AUTO "), workers("workers", "2"), workers("workers", 3.0)
    ('auto', 2, 3)
    """
    if isinstance(value, str):
        text = value.strip().lower()
        if text == "auto":
            return "auto"
        try:
            value = float(text)
        except ValueError:
            raise fail(name, value, "processes", "must be an integer >= 1 or 'auto'") from None
    w = number(name, value, "processes")
    if w < 1 or w != int(w):
        raise fail(name, value, "processes", "must be an integer >= 1 or 'auto'")
    return int(w)


#: most cam angles one call of Scene.analyse / femcam run computes at once (the sweep analyses in
#: blocks and is not bound by it); bytes per angle measured at 1e5 angles (seed002_assess.toml):
#: Scene.analyse 241 B peak (tracemalloc), `femcam run` ~0.8 kB of process memory (RSS growth
#: from 1e4 to 1e5 angles, tables and plots included)
MAX_ANGLES = 1_000_000
#: most angles of one assessment: ~3.6 kB per angle of process memory for `femcam assess`
#: (RSS growth 1e4 -> 1e5 angles: per-angle text flags, CSV), 633 B peak in assess() itself
MAX_ASSESS_ANGLES = 400_000


def angle_count(name: str, value, n: int, bytes_per_angle: float, what: str,
                cap: int = MAX_ANGLES) -> int:
    """Refuse ``n`` angles above ``cap`` before any work, with the memory estimate.

    Parameters
    ----------
    name : str
        Parameter or flag for the message (``"theta"``, ``"--angles-deg"``).
    value : object
        The value as the user gave it (the ``START:STOP:STEP`` text, or ``"N angles"``).
    n : int
        Number of angles asked for.
    bytes_per_angle : float
        Measured memory per angle of ``what`` [B].
    what : str
        The computation (``"femcam run"``, ``"Scene.analyse"``).
    cap : int
        Largest accepted number of angles.

    Returns
    -------
    int
        ``n``.

    >>> angle_count("theta", "10 angles", 10, 241.0, "Scene.analyse")
    10
    """
    if n > cap:
        raise fail(name, value, "deg" if name.endswith("-deg") else "",
                   f"{n:,} angles, more than the {cap:,} that {what} computes at once: it would need "
                   f"~{n * bytes_per_angle / 1e9:.2g} GB ({bytes_per_angle:g} B per angle, measured at "
                   "1e5 angles); use a coarser step (0:360:0.001 is 360,000 angles)")
    return n


def radians_hint(name: str, spec) -> str:
    """A note when a ``start:stop:step`` spec in degrees spans 2 pi or pi (within 1 %): most
    likely radians typed into a degree flag (``--angles-deg 0:6.28:0.1``); "" otherwise and for
    a spec :func:`angles_deg` refuses (its error says that).

    Parameters
    ----------
    name : str
        The flag or key (``"--angles-deg"``).
    spec : str
        ``start:stop:step`` [deg].

    Returns
    -------
    str
        One line, or "".

    >>> radians_hint("--angles-deg", "0:360:1")
    ''
    >>> radians_hint("--angles-deg", "0:6.28:0.1")[:44]
    "--angles-deg = '0:6.28:0.1' spans 6.28 deg ="
    """
    try:
        start, stop, _ = (float(p) for p in str(spec).split(":"))
    except ValueError:
        return ""
    span = stop - start
    for turn, word in ((2.0 * np.pi, "2 pi"), (np.pi, "pi")):
        if abs(span / turn - 1.0) <= 0.01:
            return (f"{name} = {spec!r} spans {span:g} deg = {word} as a number: the angles are "
                    "degrees (radians? a whole turn is 0:360:STEP); running what was asked")
    return ""


def angles_deg(name: str, spec, max_angles: int = 10_000_000) -> np.ndarray:
    """``"start:stop:step"`` in degrees -> radians; the stop is included when it falls on the
    grid (to 1e-9 of a step), except that a range of whole turns (``stop - start`` a multiple
    of 360 deg) drops it: the same cam position as ``start``, not computed twice.

    Parameters
    ----------
    name : str
        Parameter name for the message (``"--angles-deg"``).
    spec : str
        ``start:stop:step`` (deg), finite, ``step > 0``, ``stop > start``.
    max_angles : int
        Largest accepted number of angles.

    Returns
    -------
    ndarray
        The angles (rad).

    >>> np.degrees(angles_deg("--angles-deg", "0:90:30")).round(6).tolist()
    [0.0, 30.0, 60.0, 90.0]
    >>> angles_deg("--angles-deg", "0:360:1").size  # a full turn: 0 to 359 deg
    360
    """
    parts = str(spec).split(":")
    if len(parts) != 3:
        raise fail(name, spec, "deg", "must be start:stop:step, e.g. 0:360:1")
    try:
        start, stop, step = (float(p) for p in parts)
    except ValueError:
        raise fail(name, spec, "deg", "must be three numbers start:stop:step") from None
    if not all(np.isfinite([start, stop, step])):
        raise fail(name, spec, "deg", "must be finite numbers")
    if step <= 0:
        raise fail(name, spec, "deg", "step must be > 0")
    if stop <= start:
        raise fail(name, spec, "deg", "stop must be > start")
    k = (stop - start) / step                        # steps from start to stop
    on_grid = abs(k - round(k)) <= 1e-9 * max(1.0, round(k))   # relative: 0:360:0.00004 is on it
    n = (round(k) if on_grid else int(np.floor(k))) + 1
    turns = (stop - start) / 360.0
    if on_grid and abs(turns - round(turns)) < 1e-12:
        n -= 1  # whole turns: the stop is the start's cam position
    if n > max_angles:
        raise fail(name, spec, "deg", f"gives more than {max_angles:.0e} angles")
    return np.radians(start + step * np.arange(n))
