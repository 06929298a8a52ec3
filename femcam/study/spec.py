"""What a design study varies: ``KEY=VALUES`` specifications and the variants they make.

A key is a dotted path into the scene file, with the unit the scene file gives it
(``follower.base_radius_mm``, ``operating.rpm``, ``dynamics.preload_N``, ``program.law``); list
entries by index (``program.segment.0.beta_deg``, ``program.control_points.3``). Values stay in
the scene file's units: the scene loader converts them to SI for every variant.

VALUES syntax (one ``--vary`` each):

=========================== ====================================================================
``20:40:5``                 grid: start, stop, step; the stop is included when it lies on the grid
``20:40``                   Latin hypercube only (``--lhs N``): the range sampled
``bezier5,bezier7,9.5``     a list (numbers where they parse, else text: law names)
``[0,0,0,1,1,1];[0,0,1,1]`` a list of lists (JSON, ``;``-separated): whole control-point lists
``null``                    (in a list) the key is removed: ``program.law=null`` with
                            ``program.control_points=...`` (the scene takes one or the other)
=========================== ====================================================================
"""

from __future__ import annotations

import itertools
import json
import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError

#: the largest number of variants a study accepts (a typo like ``0:1000:0.001`` is refused)
MAX_VARIANTS = 1_000_000
#: the largest Latin-hypercube seed (a whole number exact as a float)
MAX_SEED = 2**53


def whole(name: str, value, lo: int, hi: int, unit: str = "") -> int:
    """A whole number in ``[lo, hi]`` (an integral float such as ``720.0`` too), else an
    :class:`~femcam.errors.InputError` naming ``name``.

    Parameters
    ----------
    name : str
        The parameter, named in the error.
    value : int or float
        The value given.
    lo, hi : int
        Bounds (inclusive).
    unit : str
        Unit shown after the value.

    Returns
    -------
    int
        The value.

    >>> whole("lhs", 8.0, 1, 10, "samples")
    8
    """
    x = _validate.number(name, value, unit)
    if x != math.floor(x) or not lo <= x <= hi:
        raise _validate.fail(name, value, unit, f"must be a whole number in [{lo:g}, {hi:g}]")
    return int(x)


@dataclass(frozen=True, kw_only=True)
class Variable:
    """One varied scene key.

    Parameters
    ----------
    key : str
        Dotted scene key with its unit in the name (``follower.base_radius_mm``).
    values : tuple
        Grid values in the key's scene-file unit (numbers, text or lists); empty for a range.
    lo, hi : float or None
        The range of a Latin-hypercube variable (scene-file unit), ``lo < hi``.
    """

    key: str
    values: tuple = ()
    lo: float | None = None
    hi: float | None = None

    def __post_init__(self):
        if not self.key or not isinstance(self.key, str):
            raise InputError(f"vary: key {self.key!r} must be a dotted scene key (follower.base_radius_mm)")
        if not self.values and (self.lo is None or self.hi is None):
            raise InputError(f"vary {self.key}: empty set of values (give values, or a range lo:hi)")
        if self.lo is not None or self.hi is not None:
            _validate.number("lo", self.lo, "(the key's unit)")
            _validate.number("hi", self.hi, "(the key's unit)")
        if self.lo is not None and not (math.isfinite(self.lo) and math.isfinite(self.hi)
                                        and self.lo < self.hi):
            raise InputError(f"vary {self.key}: range {self.lo:g}:{self.hi:g} is empty "
                             "(need lo < hi, finite, in the key's unit)")

    def first(self):
        """The first value (the range's ``lo``): used to check the key up front.

        Returns
        -------
        object
            A value in the key's scene-file unit.
        """
        return self.values[0] if self.values else self.lo

    def probes(self) -> tuple:
        """The values checked up front, each alone on the base scene (every grid value; a
        range's two ends).

        Returns
        -------
        tuple
            Values in the key's scene-file unit.
        """
        return tuple(self.values) if self.values else (self.lo, self.hi)


def _number(text: str):
    """``text`` as an int or float when it parses, else the stripped text."""
    t = text.strip()
    if t == "null":  # remove the key from the variant (law=null with control_points=[...])
        return None
    try:
        v = float(t)
    except ValueError:
        return t
    return int(v) if v.is_integer() and "." not in t and "e" not in t.lower() else v


def _grid(key: str, text: str) -> tuple:
    """``start:stop:step`` (the stop included when it lies on the grid, to 1e-9 of a step)."""
    parts = [p.strip() for p in text.split(":")]
    try:
        a, b, step = (float(p) for p in parts)
    except ValueError:
        raise InputError(f"vary {key}={text}: a range is START:STOP:STEP of numbers "
                         "(in the key's unit)") from None
    if not all(math.isfinite(x) for x in (a, b, step)) or step <= 0:
        raise InputError(f"vary {key}={text}: STEP = {step:g} must be a finite number > 0")
    if b < a:
        raise InputError(f"vary {key}={text}: empty range (STOP {b:g} < START {a:g})")
    n = int(math.floor((b - a) / step + 1e-9)) + 1
    if n > MAX_VARIANTS:
        raise InputError(f"vary {key}={text}: {n} values, more than {MAX_VARIANTS}")
    # rounded to 12 significant digits: 0.1 steps give 0.3, not 0.30000000000000004, so the
    # variant (and its content hash) does not depend on how the grid was spelled
    return tuple(float(f"{a + i * step:.12g}") for i in range(n))


def parse_vary(text: str, *, lhs: bool = False) -> Variable:
    """One ``KEY=VALUES`` specification (module docstring).

    Parameters
    ----------
    text : str
        ``KEY=VALUES``.
    lhs : bool
        A Latin-hypercube study: ``LO:HI`` is a range (a grid needs ``START:STOP:STEP``).

    Returns
    -------
    Variable
        The key and its values or range.

    Raises
    ------
    InputError
        No ``=``, an empty value list or range, a malformed range.

    >>> parse_vary("follower.base_radius_mm=20:30:5").values
    (20.0, 25.0, 30.0)
    >>> parse_vary("program.law=bezier5,bezier7").values
    ('bezier5', 'bezier7')
    """
    key, eq, vals = str(text).partition("=")
    key, vals = key.strip(), vals.strip()
    if not eq or not key:
        raise InputError(f"vary {text!r}: give KEY=VALUES (follower.base_radius_mm=20:40:5)")
    if not vals:
        raise InputError(f"vary {key}: empty set of values")
    if vals.startswith("["):
        try:
            lists = tuple(json.loads(v) for v in vals.split(";") if v.strip())
        except ValueError as exc:
            raise InputError(f"vary {key}={vals}: not a ';'-separated list of JSON lists ({exc})") from None
        return Variable(key=key, values=lists)
    if ":" in vals:
        parts = vals.split(":")
        if len(parts) == 2 and lhs:
            try:
                lo, hi = float(parts[0]), float(parts[1])
            except ValueError:
                raise InputError(f"vary {key}={vals}: a range is LO:HI of numbers") from None
            return Variable(key=key, lo=lo, hi=hi)
        if len(parts) != 3:
            raise InputError(f"vary {key}={vals}: a grid range is START:STOP:STEP"
                             + ("" if lhs else " (LO:HI only with --lhs)"))
        return Variable(key=key, values=_grid(key, vals))
    items = tuple(_number(v) for v in vals.split(",") if v.strip())
    if not items:
        raise InputError(f"vary {key}: empty set of values")
    return Variable(key=key, values=items)


@dataclass(frozen=True, kw_only=True)
class StudySpec:
    """The variables of a study and how they are combined.

    Parameters
    ----------
    vary : tuple of Variable
        The varied keys (distinct).
    lhs : int or None
        Latin-hypercube sample count; None: the full grid (every combination).
    seed : int
        Seed of the Latin hypercube (numpy ``default_rng``).
    """

    vary: tuple
    lhs: int | None = None
    seed: int = 0

    def __post_init__(self):
        object.__setattr__(self, "vary", tuple(self.vary))
        if not self.vary:
            raise InputError("vary: nothing to vary; give at least one KEY=VALUES")
        keys = [v.key for v in self.vary]
        dup = sorted({k for k in keys if keys.count(k) > 1})
        if dup:
            raise InputError(f"vary: key {dup[0]} given twice; give each key once")
        for v in self.vary:
            _validate.instance("vary", v, Variable, "a tuple of Variable (parse_vary)")
        whole("seed", self.seed, 0, MAX_SEED)
        if self.lhs is not None:
            whole("lhs", self.lhs, 1, MAX_VARIANTS, "samples")
        else:
            rng = [v.key for v in self.vary if not v.values]
            if rng:
                raise InputError(f"vary {rng[0]}: LO:HI is a Latin-hypercube range; give --lhs N "
                                 "or a grid START:STOP:STEP")
            n = math.prod(len(v.values) for v in self.vary)
            if n > MAX_VARIANTS:
                raise InputError(f"vary: the grid has {n} variants, more than {MAX_VARIANTS}")

    @classmethod
    def parse(cls, texts, *, lhs: int | None = None, seed: int = 0) -> StudySpec:
        """A spec from ``KEY=VALUES`` strings (the CLI's ``--vary``).

        Parameters
        ----------
        texts : sequence of str
            ``KEY=VALUES`` each.
        lhs : int or None
            Latin-hypercube samples (None: grid).
        seed : int
            Latin-hypercube seed.

        Returns
        -------
        StudySpec
            The checked spec.
        """
        return cls(vary=tuple(parse_vary(t, lhs=lhs is not None) for t in texts), lhs=lhs, seed=seed)

    @property
    def keys(self) -> tuple:
        """The varied keys, in order (tuple of str)."""
        return tuple(v.key for v in self.vary)

    def variants(self) -> list:
        """Every variant as ``{key: value}`` (scene-file units), in a fixed order.

        Returns
        -------
        list of dict
            Grid: the product in ``vary`` order (last key fastest). Latin hypercube: ``lhs``
            samples, each variable's range cut into ``lhs`` strata sampled once each (a list
            variable: its entries drawn by stratum); floats to 12 significant digits.
        """
        if self.lhs is None:
            grid = itertools.product(*(v.values for v in self.vary))
            return [dict(zip(self.keys, combo, strict=True)) for combo in grid]
        rng = np.random.default_rng(self.seed)
        n = int(self.lhs)
        cols = []
        for v in self.vary:
            u = (rng.permutation(n) + rng.random(n)) / n
            if v.values:
                cols.append([v.values[min(int(x * len(v.values)), len(v.values) - 1)] for x in u])
            else:
                cols.append([float(f"{v.lo + x * (v.hi - v.lo):.12g}") for x in u])
        return [dict(zip(self.keys, row, strict=True)) for row in zip(*cols, strict=True)]
