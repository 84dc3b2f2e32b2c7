"""The bounds of the ops' numeric properties: one row per property, checked
before an op plans anything, and printed as the table in docs/op-bounds.md.

FreeCAD takes NaN, infinities and huge numbers from a script, an expression
or the property editor (an infinite length is kept as the largest double).
None of them may reach an op's Path or a post: each op checks its numeric
properties against its table first (check_bounds) and names the first
property out of range, with its value and the rule. Where an engine cycle
has a tighter rule of its own (CYCLE93's WIDG greater than 0, G83's J, ...),
the row says so (``more``) and the engine's message, naming the property,
refuses the value; the op's own range then only keeps the number finite and
below what a program can hold.

FreeCAD layer: no import of FreeCAD (values are duck-typed Quantities).
"""

import math
from dataclasses import dataclass
from typing import Callable, Iterable, Optional, Tuple

from .units import length_mm

# Beyond this no value is checked by anyone but check_bounds: far beyond every range below.
HARD_LIMIT = 1.0e15


@dataclass(frozen=True)
class Bound:
    """The range of one numeric property: ``low`` <= value <= ``high`` in ``unit`` (``low_open``: value >
    ``low``; ``high_open``: value < ``high``); ``scale`` turns FreeCAD's internal value (mm, mm/s, degrees,
    seconds, a count) into ``unit``; ``more`` is the rest of the rule as a sentence (who checks it), ``why``
    where the range comes from. ``checker``: who refuses a value out of the range with a message of its own
    (an engine cycle, naming the property); check_bounds then refuses only what is not finite or beyond
    HARD_LIMIT, which no checker is written for."""

    name: str
    low: float
    high: float
    unit: str = "mm"
    more: str = ""
    why: str = ""
    low_open: bool = False
    high_open: bool = True
    scale: float = 1.0
    checker: str = ""

    def range_text(self) -> str:
        """The range as the table and the messages write it: "0 <= FeedPerRev <= 10 mm/rev"."""
        low = "%s %s " % (_number(self.low), "<" if self.low_open else "<=")
        high = " %s %s" % ("<" if self.high_open else "<=", _number(self.high))
        unit = " " + self.unit if self.unit else ""
        return low + self.name + high + unit

    def problem(self, value: float) -> Optional[str]:
        """The message for ``value`` (in ``unit``) out of range, None when it is in it."""
        if not math.isfinite(value):
            return "%s=%s: must be a finite number" % (self.name, value)
        if self.checker and abs(value) < HARD_LIMIT:
            return None
        below = value <= self.low if self.low_open else value < self.low
        above = value >= self.high if self.high_open else value > self.high
        if below or above:
            unit = " " + self.unit if self.unit else ""
            return "%s=%s%s: must be %s" % (self.name, _number(value), unit, self.range_text())
        return None


def _number(value: float) -> str:
    """A number for a message: as short as it reads exactly (1e+06, 89.999, 0.5)."""
    if float(value).is_integer() and abs(value) < 1e15:
        return str(int(value))
    return "%.12g" % value


def number_of(value: object) -> float:
    """A property's value as a plain float (a Quantity's Value; an int, a bool); NaN when it is not a number."""
    try:
        return length_mm(value)
    except (TypeError, ValueError, OverflowError):
        return math.nan


def check_bounds(obj: object, bounds: Iterable[Bound], error: Callable[[str, Tuple[str, ...]], Exception],
                 prefix: str = "") -> None:
    """Raise ``error(message, (name,))`` for the first property of ``obj`` out of its bound (``prefix`` is put
    before the property name to read it: "" for the op's own properties)."""
    for bound in bounds:
        value = getattr(obj, prefix + bound.name, None)
        if value is None:
            continue
        message = bound.problem(number_of(value) * bound.scale)
        if message is not None:
            raise error(message, (bound.name,))


def first_problem(values: dict, bounds: Iterable[Bound]) -> Optional[Tuple[str, str]]:
    """(property name, message) of the first of ``values`` {name: value in the bound's unit} out of range."""
    for bound in bounds:
        if bound.name in values:
            message = bound.problem(number_of(values[bound.name]))
            if message is not None:
                return bound.name, message
    return None


def table_rows(op: str, bounds: Iterable[Bound]) -> list:
    """The Markdown table rows of ``bounds`` (docs/op-bounds.md): op, property, range, rest of the rule, why."""
    return ["| %s | %s | %s | %s | %s |" % (op, b.name, b.range_text(), _rest(b), b.why or "-") for b in bounds]


def _rest(bound: Bound) -> str:
    parts = [p for p in (bound.more, "refused by %s" % bound.checker if bound.checker else "") if p]
    return "; ".join(parts) or "-"
