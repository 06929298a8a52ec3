"""How result objects present themselves: a compact ``repr`` (the class name, the key facts with
units, and the array fields by shape, never their values: a scene state's default dataclass repr
printed 370 kB of numbers; a notebook cell or a log line should show what the object is, in one
line) and a pandas DataFrame of a table (pandas is optional: imported only when asked for).
"""

from __future__ import annotations

import dataclasses

import numpy as np

#: longest repr returned (characters)
MAX_REPR = 1000


def span(values, scale: float = 1.0, unit: str = "", fmt: str = ".4g") -> str:
    """``"lo..hi unit"`` of the finite values of an array (``"-"`` when there is none).

    Parameters
    ----------
    values : array_like
        The values (SI).
    scale : float
        Factor SI -> the unit shown.
    unit : str
        Unit written after the range.
    fmt : str
        Format of each end.

    Returns
    -------
    str
        The range.

    >>> span([0.001, 0.003, float("nan")], 1e3, "mm")
    '1..3 mm'
    """
    v = np.asarray(values, dtype=float).ravel() * scale
    v = v[np.isfinite(v)]
    if v.size == 0:
        return "-"
    return f"{v.min():{fmt}}..{v.max():{fmt}}" + (f" {unit}" if unit else "")


def _items(obj):
    """``(name, value)`` of the fields of a dataclass, else of the public attributes."""
    if dataclasses.is_dataclass(obj):
        return [(f.name, getattr(obj, f.name, None)) for f in dataclasses.fields(obj) if f.repr]
    return [(k, v) for k, v in vars(obj).items() if not k.startswith("_")] \
        if hasattr(obj, "__dict__") else []


def _scalar(v) -> str | None:
    """A number, flag or short text as written in a repr; None for anything else."""
    if isinstance(v, (bool, np.bool_)):
        return str(bool(v))
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        return f"{float(v):.6g}"
    if isinstance(v, str) and len(v) <= 60:
        return repr(v)
    if isinstance(v, np.ndarray) and v.ndim == 0 and v.dtype.kind in "biuf":
        return f"{v.item():.6g}"
    return None


def compact_repr(obj, facts=None) -> str:
    """``ClassName(fact, ..., arrays (n,): a b c)``: the facts given (by default the scalar
    fields, ``name=value``), then the array fields grouped by shape; at most :data:`MAX_REPR`
    characters.

    Parameters
    ----------
    obj : object
        The object (its class name; its fields when it is a dataclass, else its attributes).
    facts : iterable of str, optional
        Key facts with their units, e.g. ``"720 angles"``, ``"Fc 1491..1516 N"``; None: the
        object's scalar fields.

    Returns
    -------
    str
        The repr.

    >>> from dataclasses import dataclass
    >>> @dataclass
    ... class R:
    ...     theta: np.ndarray
    ...     s: np.ndarray
    ...     ok: bool = True
    >>> compact_repr(R(np.zeros(3), np.zeros(3)), ["3 angles"])
    'R(3 angles; arrays (3,): theta s)'
    >>> compact_repr(R(np.zeros(3), np.zeros((3, 2))))
    'R(ok=True; arrays (3,): theta; arrays (3, 2): s)'
    """
    items = _items(obj)
    if facts is None:
        parts = [f"{k}={t}" for k, v in items if (t := _scalar(v)) is not None]
    else:
        parts = [str(f) for f in facts]
    shapes: dict[tuple, list[str]] = {}
    for k, v in items:
        if isinstance(v, np.ndarray) and v.ndim:
            shapes.setdefault(v.shape, []).append(k)
    parts += [f"arrays {shape}: " + " ".join(names) for shape, names in shapes.items()]
    text = f"{type(obj).__name__}({'; '.join(parts)})"
    return text if len(text) <= MAX_REPR else text[:MAX_REPR - 5] + " ...)"


def dataframe(columns: dict, owner: str = "to_dataframe"):
    """A ``pandas.DataFrame`` of table columns (numbers as float or int, text as ``str``).

    Parameters
    ----------
    columns : dict[str, array_like]
        Column name (unit in the name) -> values, all of one length.
    owner : str
        The method asking, named in the error when pandas is missing.

    Returns
    -------
    pandas.DataFrame
        One column per entry, in order.

    Raises
    ------
    ImportError
        pandas is not installed (femcam does not require it), with the install command.
    """
    try:
        import pandas as pd  # optional: femcam itself never needs pandas
    except ImportError as exc:
        raise ImportError(f"{owner}() needs pandas, which femcam does not install: "
                          "pip install pandas (or pip install femcam[test])") from exc
    out = {}
    for k, v in columns.items():
        a = np.asarray(v)
        out[k] = a.astype(str) if a.dtype.kind in "USO" else a
    return pd.DataFrame(out)
