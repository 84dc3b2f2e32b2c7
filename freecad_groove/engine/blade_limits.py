"""What a grooving blade's holder allows beside its free reach (tool_table.reach_problem): the first-cut
diameter range of a face-grooving blade and the smallest bore of an internal grooving bar.

    entry = model.blade_entry(start, settings, moves)      # BladeEntry: where the first plunge cuts
    limits_problem(entry, BladeLimits(first_cut_min=40, first_cut_max=60), "T5's blade (tools.tbl)")

* A face groove (a plunge along Z) is cut by a face-grooving blade whose holder is curved to a range of
  diameters: its first plunge must lie wholly inside [first_cut_min, first_cut_max]: the smallest diameter
  the blade cuts there at least first_cut_min, the largest at most first_cut_max (the catalogues' Dmin and
  Dmax; the curve of the holder rubs the part's face outside them).
* An internal groove (a plunge along +X) is cut by a bar that enters bores of min_bore and more: the bore
  at the groove's opening must be at least min_bore.

A limit None (not given) is not checked. Diameters, like the moves' X, in the program's units (the op: mm).

Layer 1: pure Python.
"""

from dataclasses import dataclass
from typing import Optional, Sequence, Tuple

from .moves import FEED, MINUS_Z, PLUS_X, PLUS_Z, GroovingTool, Move
from .numbers import format_value

__all__ = ["BladeEntry", "BladeLimits", "first_plunge", "limits_problem"]

TOLERANCE = 1e-9


@dataclass(frozen=True)
class BladeLimits:
    """What the blade's holder allows (None: not given, not checked); diameters. ``names``: how the message
    names each limit (the tool table's fields, the tool bit's properties)."""

    first_cut_min: Optional[float] = None
    first_cut_max: Optional[float] = None
    min_bore: Optional[float] = None
    names: Tuple[str, str, str] = ("dmin", "dmax", "bore")
    unit: str = ""  # after each length in the message (the op's: " mm")


@dataclass(frozen=True)
class BladeEntry:
    """Where a cycle's blade first cuts: its ``plunge`` (moves.MINUS_X ...), the diameters its first plunge
    spans across a face (``low``..``high``, Z plunges) and the diameter of the bore at the groove's opening
    (``bore``, +X plunges; else None)."""

    plunge: str
    low: Optional[float] = None
    high: Optional[float] = None
    bore: Optional[float] = None


def first_plunge(moves: Sequence[Move]) -> Optional[Move]:
    """The first feed of an expansion: a grooving cycle's first plunge."""
    return next((move for move in moves if move.kind == FEED), None)


def face_band(tool: GroovingTool, x: float) -> Tuple[float, float]:
    """The diameters a blade plunging along Z covers with its reference corner at radius ``x`` (the blade
    extends toward +X from a minus reference, toward -X from a plus one: moves.GroovingTool)."""
    low = x - tool.reference_offset
    return 2 * low, 2 * (low + float(tool.width))


def limits_problem(entry: Optional[BladeEntry], limits: Optional[BladeLimits], blade: str) -> Optional[str]:
    """Why the blade (``blade`` names it in the message) cannot cut where ``entry`` says (see the module);
    None when it can or nothing is given."""
    if entry is None or limits is None:
        return None
    lo_name, hi_name, bore_name = limits.names

    def length(value: float) -> str:
        return format_value(value) + limits.unit

    if entry.plunge in (MINUS_Z, PLUS_Z) and entry.low is not None:
        span = "%s..%s" % (format_value(entry.low), length(entry.high))
        both = limits.first_cut_min is not None and limits.first_cut_max is not None
        given = ["%s=%s" % (name, length(value)) if value is not None else "no " + name
                 for name, value in ((lo_name, limits.first_cut_min), (hi_name, limits.first_cut_max))]
        blade_range = "%s, %s" % (blade, (" to " if both else ", ").join(given))  # both names and values
        if limits.first_cut_min is not None and entry.low < limits.first_cut_min - TOLERANCE:
            return ("%s=%s: the face groove's first plunge cuts diameters %s, below the first-cut diameter range "
                    "of %s: its curved holder would hit the face (use a blade for these diameters)"
                    % (lo_name, length(limits.first_cut_min), span, blade_range))
        if limits.first_cut_max is not None and entry.high > limits.first_cut_max + TOLERANCE:
            return ("%s=%s: the face groove's first plunge cuts diameters %s, above the first-cut diameter range "
                    "of %s: its curved holder would hit the face (use a blade for these diameters)"
                    % (hi_name, length(limits.first_cut_max), span, blade_range))
    if entry.plunge == PLUS_X and entry.bore is not None and limits.min_bore is not None:
        if entry.bore < limits.min_bore - TOLERANCE:
            return ("%s=%s: the internal groove's bore is %s, smaller than the smallest bore %s enters: its bar "
                    "would hit the bore (use a smaller bar)" % (bore_name, length(limits.min_bore), length(entry.bore),
                                                                 blade))
    return None
