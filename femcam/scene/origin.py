"""The scene file as written, kept read-only for provenance (:attr:`femcam.scene.Scene.origin`).

The parsed TOML is frozen (tables become :class:`FrozenMapping`, arrays tuples) so that no code
can change it after loading; it is read to copy, hash or vary the scene file, never for physics
(the typed records of :class:`~femcam.scene.Scene` carry the SI values). :func:`thaw` gives back
the plain ``dict``/``list`` form :mod:`tomllib` returns, for writing a variant of the file.
"""

from __future__ import annotations

from collections.abc import Mapping


class FrozenMapping(Mapping):
    """A read-only mapping (a TOML table as written); picklable, unlike ``types.MappingProxyType``.

    Parameters
    ----------
    items : mapping
        The table (its values already frozen by :func:`freeze`).
    """

    def __init__(self, items=()):
        self._items = dict(items)

    def __getitem__(self, key):
        """The value under ``key``."""
        return self._items[key]

    def __iter__(self):
        """The keys, in the order written."""
        return iter(self._items)

    def __len__(self) -> int:
        """The number of keys."""
        return len(self._items)

    def __repr__(self) -> str:
        """``FrozenMapping({...})``."""
        return f"FrozenMapping({self._items!r})"


def freeze(value):
    """``value`` made immutable, recursively: dict -> :class:`FrozenMapping`, list -> tuple.

    Parameters
    ----------
    value : object
        A parsed TOML value (table, array, string, number, bool, date).

    Returns
    -------
    object
        The frozen value.

    >>> freeze({"a": [1, {"b": 2}]})["a"][1]["b"]
    2
    """
    if isinstance(value, Mapping):
        return FrozenMapping((k, freeze(v)) for k, v in value.items())
    if isinstance(value, list | tuple):
        return tuple(freeze(v) for v in value)
    return value


def thaw(value):
    """The plain form of a :func:`freeze` d value: mappings -> dict, tuples -> list (a new copy).

    Parameters
    ----------
    value : object
        A frozen (or plain) TOML value.

    Returns
    -------
    object
        ``dict``/``list`` as :mod:`tomllib` returns them.

    >>> thaw(freeze({"a": [1, 2]}))
    {'a': [1, 2]}
    """
    if isinstance(value, Mapping):
        return {k: thaw(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [thaw(v) for v in value]
    return value
