"""One chunk of the sweep table, typed: :class:`ChunkRows`.

A chunk's rows are filled by some 35 functions (the analytic chain, Hertz, the FE solves, the
ring headline, wear, the estimates and the extra column providers), each writing a few
columns: ``rows.p0_fe[i] = r.p0_nodal``. The columns are exactly the declared ones: the sweep's
own (:data:`femcam.sweep.table.NUMERIC`, :data:`~femcam.sweep.table.TEXT_COLUMNS`) and those of
every provider in :data:`femcam.sweep.extras.PROVIDERS` (their numeric
:class:`femcam._columns.Column` tuples, e.g. ``HALFSPACE``, ``ASSESS``, ``RING``, ``CAM_DISK``,
``LAYERS``, ``LAYER_ESTIMATES``, their text columns and
:data:`~femcam.sweep.extras.ERROR_COLUMN`). The class has one slot per declared column, so a
misspelt or undeclared column fails where it is written (``rows.p0_fee = ...`` raises
:class:`AttributeError`), not later as a missing column in the CSV.

The sweep's own columns exist from the start (NaN numbers, empty strings); a provider's column
exists once its provider has set it (``setattr(rows, column.si, values)``: only the declared
names are accepted) and is absent otherwise, so :meth:`ChunkRows.items` yields what the chunk
computed: the sweep's columns in their declared order, then the provider columns in the order
they were set (the order of the chunk files in ``DIR/chunks/``). The writers
(:meth:`femcam.sweep.store.ChunkStore.write`, :meth:`femcam.sweep.table.TableBuilder.put`) read
:meth:`ChunkRows.items`; a chunk read back from its file is :meth:`ChunkRows.from_arrays`.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping

import numpy as np

from .extras import ERROR_COLUMN, PROVIDERS
from .table import NUMERIC, TEXT_COLUMNS

__all__ = ["PROVIDER_NUMERIC", "PROVIDER_TEXT", "ChunkRows"]

#: the providers' numeric columns (SI names), in :data:`~femcam.sweep.extras.PROVIDERS` order
PROVIDER_NUMERIC = tuple(dict.fromkeys(c.si for p in PROVIDERS for c in p.columns))
#: the providers' text columns, then :data:`~femcam.sweep.extras.ERROR_COLUMN`
PROVIDER_TEXT = tuple(dict.fromkeys([t for p in PROVIDERS for t in p.text] + [ERROR_COLUMN]))

_SWEEP = NUMERIC + TEXT_COLUMNS
_PROVIDER = frozenset(PROVIDER_NUMERIC + PROVIDER_TEXT)
_COLUMNS = frozenset(_SWEEP) | _PROVIDER
_TEXT = frozenset(TEXT_COLUMNS + PROVIDER_TEXT)
#: slots that are no column
_OWN = ("_n", "_added", "ring_error")


def _unknown(name: str) -> str:
    near = [c for c in sorted(_COLUMNS) if c.startswith(name[:3])][:6]
    return (f"ChunkRows has no column {name!r}: the columns are the declared ones "
            "(femcam.sweep.table.NUMERIC, TEXT_COLUMNS and the providers' of "
            "femcam.sweep.extras.PROVIDERS)" + (f"; similar: {', '.join(near)}" if near else ""))


class ChunkRows:
    """The rows of one sweep chunk: one array of shape (n,) per declared column.

    Numeric columns are float arrays in SI units (NaN where not computed), text columns object
    (or ``str``) arrays. Read and write a column as an attribute (``rows.p0_fe[i] = p``,
    ``rows.wear_source = src``); a name computed at run time through ``getattr`` /
    ``setattr`` (``setattr(rows, column.si, values)``). Writing a name that is no declared
    column raises :class:`AttributeError`; so does reading a provider column that was not set
    in this chunk (:meth:`get` gives a default instead). A whole column written must have
    shape (n,).

    Parameters
    ----------
    n : int
        Rows (angles) of the chunk.

    Attributes
    ----------
    ring_error : Exception or None
        The ring model's refusal, kept by the ring headline step
        (:func:`femcam.sweep.ringhead.ring_headline`) for the ``bodies`` provider, which raises
        it (:func:`femcam.sweep.providers.ring_chunk`); no column.

    Examples
    --------
    >>> rows = ChunkRows(2)
    >>> rows.p0_fe[1] = 1.2e9
    >>> rows.p0_fe.tolist(), "hs_w_max" in rows
    ([nan, 1200000000.0], False)
    >>> rows.p0_fee = [0.0, 0.0]  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    AttributeError: ChunkRows has no column 'p0_fee': ...
    """

    __slots__ = _SWEEP + PROVIDER_NUMERIC + PROVIDER_TEXT + _OWN

    def __init__(self, n: int):
        object.__setattr__(self, "_n", int(n))
        object.__setattr__(self, "_added", [])
        object.__setattr__(self, "ring_error", None)
        for name in NUMERIC:
            object.__setattr__(self, name, np.full(self._n, np.nan))
        for name in TEXT_COLUMNS:
            object.__setattr__(self, name, np.full(self._n, "", dtype=object))

    @classmethod
    def from_arrays(cls, arrays: Mapping) -> ChunkRows:
        """A chunk from its columns (e.g. a chunk file read back), every name checked.

        Parameters
        ----------
        arrays : Mapping[str, ndarray]
            Column name -> array of shape (n,): every sweep column, and provider columns in
            the order they were set.

        Returns
        -------
        ChunkRows
            The chunk, holding the given arrays.
        """
        rows = cls(np.shape(arrays["theta"])[0])
        for name, v in arrays.items():
            setattr(rows, name, v)
        return rows

    @property
    def n(self) -> int:
        """Rows of the chunk.

        Returns
        -------
        int
        """
        return self._n

    @staticmethod
    def is_text(name: str) -> bool:
        """True for a text column (the sweep's or a provider's), False for a numeric one.

        Parameters
        ----------
        name : str
            A declared column.

        Returns
        -------
        bool
        """
        if name not in _COLUMNS:
            raise KeyError(_unknown(name))
        return name in _TEXT

    def columns(self) -> tuple[str, ...]:
        """The columns the chunk holds: the sweep's in declared order, then the provider
        columns in the order they were set.

        Returns
        -------
        tuple of str
        """
        return _SWEEP + tuple(self._added)

    def items(self) -> Iterator[tuple[str, np.ndarray]]:
        """``(name, array)`` of every column the chunk holds, in :meth:`columns` order.

        Yields
        ------
        tuple of (str, ndarray)
        """
        for name in self.columns():
            yield name, object.__getattribute__(self, name)

    def get(self, name: str, default=None):
        """The column ``name``, or ``default`` when it is a provider column not set here.

        Parameters
        ----------
        name : str
            A declared column (else :class:`KeyError`).
        default : object, optional
            Returned for a declared column the chunk does not hold.

        Returns
        -------
        ndarray or object
        """
        return getattr(self, name) if name in self else default

    def __contains__(self, name: str) -> bool:
        if name not in _COLUMNS:
            raise KeyError(_unknown(name))
        return name in _SWEEP or name in self._added

    def __getattr__(self, name: str):   # only reached for unset slots and unknown names
        if name in _PROVIDER:
            raise AttributeError(f"column {name!r} is not computed in this chunk (its provider "
                                 "did not run or has not run yet)")
        raise AttributeError(_unknown(name))

    def __setattr__(self, name: str, value) -> None:
        if name not in _COLUMNS:
            if name == "ring_error":
                object.__setattr__(self, name, value)
                return
            raise AttributeError(_unknown(name))
        if np.shape(value) != (self._n,):
            raise ValueError(f"column {name!r}: shape {np.shape(value)}, the chunk has "
                             f"{self._n} rows")
        if name in _PROVIDER and name not in self._added:
            self._added.append(name)
        object.__setattr__(self, name, value)

    def __delattr__(self, name: str) -> None:
        raise AttributeError(f"ChunkRows columns are not removed ({name!r})")

    def __getstate__(self) -> dict:
        return {"n": self._n, "columns": dict(self.items()), "ring_error": self.ring_error}

    def __setstate__(self, state: dict) -> None:
        object.__setattr__(self, "_n", state["n"])
        object.__setattr__(self, "_added", [])
        object.__setattr__(self, "ring_error", state["ring_error"])
        for name, v in state["columns"].items():
            setattr(self, name, v)

    def __repr__(self) -> str:
        return f"ChunkRows(n={self._n}, columns={len(self.columns())})"
