"""The scene checker: every problem of a scene file collected, then one
:class:`~femcam.errors.SceneError` that lists them (dotted key, value, expected unit, and a
did-you-mean for a misspelt key).

A table is checked against its key table of :mod:`femcam.scene.schema` by
:meth:`_Checker.table`; the table-group modules add their cross-key problems with
:meth:`_Checker.add`.
"""

from __future__ import annotations

import difflib
import math

from ..errors import SceneError
from .ranges import group_of, range_problem
from .schema import _CHOICES, STUDY_RANGES, STUDY_WHOLE, study_problem

#: problems one SceneError lists (then "... and N more")
MAX_PROBLEMS = 20


def _fmt(v) -> str:
    """A TOML value as the user wrote it: strings quoted, booleans lower case."""
    return repr(v) if isinstance(v, str) else str(v).lower() if isinstance(v, bool) else f"{v}"


class _Checker:
    """Collects every problem of a scene file, then raises one SceneError.

    Parameters
    ----------
    path : str
        The scene file, named in the error.

    Attributes
    ----------
    problems : list of str
        ``"key = value unit: condition"`` or ``"key: message"``, in the order found.
    """

    def __init__(self, path: str):
        self.path = path
        self.problems: list[str] = []

    def add(self, key: str, msg: str) -> None:
        """Record one problem of dotted ``key``; ``msg`` starts with ``"= value"`` or is a message."""
        # "key = value unit: condition" (like femcam._validate), or "key: message"
        self.problems.append(f"{key} {msg}" if msg.startswith("= ") else f"{key}: {msg}")

    def table(self, raw, key: str, spec: dict, *, extra: tuple = ()) -> dict:
        """Check one table: types, ranges, unknown and missing keys.

        Parameters
        ----------
        raw : object
            The parsed TOML value (a dict for a table; anything else is a problem).
        key : str
            Dotted name of the table (``""`` for the top level).
        spec : dict
            The key table (:mod:`femcam.scene.schema`).
        extra : tuple of str
            Sub-table names skipped here (checked by their own module).

        Returns
        -------
        dict
            The valid keys, converted to SI with their factors (strings, lists, booleans as
            given; whole numbers as ``int``).
        """
        out = {}
        if not isinstance(raw, dict):
            self.add(key, f"= {_fmt(raw)}: must be a table [{key}]")
            return out
        for k, v in raw.items():
            dk = f"{key}.{k}" if key else k
            if k in extra:
                continue
            if k not in spec:
                self.add(dk, f"= {_fmt(v)}: unknown key{self._hint(k, spec)}")
                continue
            unit, factor, check, _ = spec[k]
            val = self.value(dk, k, v, unit, factor, check, group=group_of(key))
            if val is not None:
                out[k] = val
        for k, (unit, _, _, required) in spec.items():
            if required and k not in raw:
                u = f" (unit: {unit})" if unit else ""
                self.add(f"{key}.{k}" if key else k, f"missing required key{u}")
        return out

    @staticmethod
    def _hint(k: str, spec: dict) -> str:
        """The did-you-mean of an unknown key ``k`` (a unit suffix left out, or a near match)."""
        pref = [n for n in spec if n.startswith(k + "_")]
        near = pref or difflib.get_close_matches(k, list(spec), n=1, cutoff=0.6)
        if not near:
            return f"; valid keys: {', '.join(spec)}"
        unit = spec[near[0]][0]
        why = " (units go in the key name)" if pref else ""
        return f"; did you mean {near[0]!r}{' in ' + unit if unit else ''}?{why}"

    def value(self, dk, k, v, unit, factor, check, *, group: str = ""):
        """One value checked against its basic check and its stated range, converted to SI.

        Parameters
        ----------
        dk, k : str
            Dotted key (for the message) and key (for :data:`_CHOICES` and the study ranges).
        v : object
            The TOML value.
        unit : str
            Unit shown to the user.
        factor : float or None
            SI factor of a number.
        check : str
            The check of :mod:`femcam.scene.schema`.
        group : str, optional
            Table group of :data:`femcam.scene.ranges.RANGES` (the key's stated range).

        Returns
        -------
        object or None
            The value in SI; None when a problem was added.
        """
        if check in ("str", "list", "strlist", "seglist", "bool"):
            return self._plain(dk, k, v, check)
        x = self._number(dk, v, unit, factor, check)
        if x is None:
            return x
        study = k in STUDY_RANGES or k in STUDY_WHOLE
        problem = (study_problem(k, x) if study else None) or range_problem(group, k, float(v), unit, check)
        if problem:
            self.add(dk, f"= {_fmt(v)}{' ' + unit if unit else ''}: {problem}")
            return None
        if not study:
            return x
        return int(x) if k in STUDY_WHOLE else x

    def _plain(self, dk, k, v, check):
        """A string, list of numbers, segment array or boolean (None: a problem was added)."""
        if check == "seglist":
            return v  # handled by femcam.scene.program
        if check == "str":
            if not isinstance(v, str):
                self.add(dk, f"= {_fmt(v)}: must be a string")
                return None
            if k in _CHOICES and v not in _CHOICES[k]:
                self.add(dk, f"= {v!r}: must be one of {', '.join(map(repr, _CHOICES[k]))}")
                return None
            return v
        if check == "strlist":
            bad = [x for x in v if not isinstance(x, str) or x not in _CHOICES.get(k, (x,))] \
                if isinstance(v, list) else [v]
            if bad or not v:
                self.add(dk, f"= {_fmt(v)}: must be a non-empty list of "
                         f"{', '.join(map(repr, _CHOICES[k])) if k in _CHOICES else 'strings'}")
                return None
            return [str(x) for x in v]
        if check == "list":
            ok = isinstance(v, list) and all(isinstance(x, int | float) and not isinstance(x, bool)
                                             for x in v)
            if not ok:
                self.add(dk, f"= {_fmt(v)}: must be a list of numbers")
                return None
            return [float(x) for x in v]
        if not isinstance(v, bool):
            self.add(dk, f"= {_fmt(v)}: must be true or false")
            return None
        return v

    def _number(self, dk, v, unit, factor, check):
        """A finite number passing ``check`` (pos, nonneg, num, nu), times ``factor``."""
        u = f" {unit}" if unit else ""
        if isinstance(v, bool) or not isinstance(v, int | float):
            self.add(dk, f"= {_fmt(v)}: must be a number in{u or ' (dimensionless)'}")
            return None
        x = float(v)
        bad = None
        if not math.isfinite(x):
            bad = "must be finite"
        elif check == "pos" and x <= 0:
            bad = "must be > 0"
        elif check == "nonneg" and x < 0:
            bad = "must be >= 0"
        elif check == "nu" and not (-1.0 < x < 0.5):
            bad = "Poisson's ratio must be in (-1, 0.5)"
        if bad:
            self.add(dk, f"= {_fmt(v)}{u}: {bad}")
            return None
        return x * factor

    def raise_if_any(self) -> None:
        """Raise one SceneError listing the problems (at most :data:`MAX_PROBLEMS`), if any.

        Raises
        ------
        SceneError
            ``"scene file <path>: N problems"`` then one problem a line.
        """
        if self.problems:
            n = len(self.problems)
            head = f"scene file {self.path}: {n} problem{'s' if n > 1 else ''}"
            shown = self.problems[:MAX_PROBLEMS] + ([f"... and {n - MAX_PROBLEMS} more"]
                                                    if n > MAX_PROBLEMS else [])
            raise SceneError(head + "\n  " + "\n  ".join(shown))
