"""The numeric flags of every subcommand and their stated ranges, checked while the command
line is parsed (before any file is read or any work starts).

A subcommand adds a numeric flag with :func:`add_number` and a :class:`Range`; the value is
parsed and checked by the flag's action (:class:`NumberAction`), which raises
:class:`FlagError` (an :class:`~femcam.errors.InputError`) naming the flag, the value, the
unit and the range. ``femcam.cli.main`` prints it as one line and exits 1.
``tests/test_cli_flags.py`` walks the parser, requires every numeric flag to be a
:class:`NumberAction` and feeds each one nonsense (nan, inf, -1, 0, 1e30), so a flag added
later is covered without anyone remembering to.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from dataclasses import dataclass

from .. import _validate
from ..errors import InputError

#: the one rule of every START:STOP:STEP flag (--angles-deg, --rpm-sweep, study --vary): the
#: stop is included when it falls on the grid (to 1e-9 of a step); an angle range spanning whole
#: turns drops its stop, the same cam position as its start (femcam._validate.angles_deg)
RANGE_RULE = ("START:STOP:STEP, stop included when it falls on the grid (an angle range of "
              "whole turns drops it: the same cam position as START)")


class FlagError(InputError):
    """A flag value out of its range, raised while parsing; ``prog`` is ``femcam <command>``."""

    def __init__(self, message: str, prog: str):
        super().__init__(message)
        self.prog = prog


@dataclass(frozen=True)
class Range:
    """The accepted values of one numeric flag.

    Parameters
    ----------
    unit : str
        Unit shown after the value (``"deg"``, ``"mm"``, ``"(number of blocks)"``).
    lo, hi : float
        Bounds (inclusive unless ``lo_open`` / ``hi_open``).
    lo_open, hi_open : bool
        Exclude that bound.
    whole : bool
        A whole number (the value is stored as ``int``).
    why : str
        The reason for the bounds, appended to the refusal.
    words : tuple of str
        Words accepted as they are (``("auto",)``).
    check : callable or None
        ``check(x) -> str | None``: a further condition (e.g. the scene's range of the same
        setting), its text on failure.
    """

    unit: str
    lo: float
    hi: float
    lo_open: bool = False
    hi_open: bool = False
    whole: bool = False
    why: str = ""
    words: tuple = ()
    check: Callable | None = None

    def text(self, unit: bool = True) -> str:
        """The range as written in ``--help`` (and, without the unit, in refusals), e.g.
        ``(0, 10] deg``."""
        lb, rb = "(" if self.lo_open else "[", ")" if self.hi_open else "]"
        kind = "a whole number in " if self.whole else ""
        return f"{kind}{lb}{self.lo:g}, {self.hi:g}{rb}" + (f" {self.unit}" if unit and self.unit else "")

    def parse(self, flag: str, text):
        """The checked value of ``text`` (``int`` when ``whole``, a word of ``words`` as is).

        Parameters
        ----------
        flag : str
            The flag, named in the error.
        text : str or float
            The value as given.

        Returns
        -------
        float or int or str
            The value.

        Raises
        ------
        InputError
            Not a number, not finite, outside the range, not whole, or failing ``check``.
        """
        if isinstance(text, str) and text.strip().lower() in self.words:
            return text.strip().lower()
        try:  # shown as a number where it is one: 1e-09 and nan, not '1e-9' and 'nan'
            shown = float(text) if isinstance(text, str) else text
        except ValueError:
            shown = text
        x = _validate.number(flag, shown, self.unit)
        if self.check is not None:  # the setting's own condition first (its words and hint)
            problem = self.check(x)
            if problem:
                raise _validate.fail(flag, shown, self.unit, problem)
        lo_bad = x <= self.lo if self.lo_open else x < self.lo
        hi_bad = x >= self.hi if self.hi_open else x > self.hi
        if lo_bad or hi_bad or (self.whole and x != math.floor(x)):
            words = f" or {', '.join(self.words)}" if self.words else ""
            why = f" ({self.why})" if self.why else ""
            must = f"must be {'' if self.whole else 'in '}{self.text(unit=False)}"
            raise _validate.fail(flag, shown, self.unit, f"{must}{words}{why}")
        return int(x) if self.whole else x


class NumberAction(argparse.Action):
    """Store a numeric flag checked against its :class:`Range` (``self.range``)."""

    def __init__(self, option_strings, dest, range: Range, **kw):  # noqa: A002 - argparse's kwarg style
        super().__init__(option_strings, dest, **kw)
        self.range = range

    def __call__(self, parser, namespace, values, option_string=None):
        try:
            setattr(namespace, self.dest, self.range.parse(option_string or self.dest, values))
        except InputError as exc:
            raise FlagError(str(exc), " ".join(parser.prog.split()[:2])) from None


def add_number(p, flag: str, rng: Range, *, help: str = "", **kw):  # noqa: A002 - argparse's name
    """Add a numeric flag whose value is checked against ``rng`` while parsing.

    Parameters
    ----------
    p : argparse.ArgumentParser
        The subcommand's parser.
    flag : str
        The flag, e.g. ``"--step-deg"``.
    rng : Range
        Its accepted values; the range is appended to the help text.
    help : str
        Help text.
    **kw
        Further ``add_argument`` keywords (``default``, ``metavar``, ``dest``).

    Returns
    -------
    argparse.Action
        The flag's action.
    """
    text = f"{help}; range {rng.text()}" if help else f"range {rng.text()}"
    if help == argparse.SUPPRESS:
        text = argparse.SUPPRESS
    return p.add_argument(flag, action=NumberAction, range=rng, help=text, **kw)
