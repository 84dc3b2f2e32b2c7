"""The blade corner a post's words measure (``--reference-corner``) against the op's own.

A groove plan's words are for the op's ReferenceCorner; when the post writes
the other corner, every word moves by the blade's width along the groove's
axis (Z for longitudinal grooves, X for face grooves), the blade does not.
"""

from typing import Any, NamedTuple, Optional

from ...engine.moves import REFERENCE_PLUS, Move
from ...engine.settings import Settings


class Shift(NamedTuple):
    """What to add to a plan's words: ``dx`` (radius) and ``dz``."""

    dx: float
    dz: float


def corner_shift(plan: Any, reference: Optional[str]) -> Shift:
    """The shift from the op's reference corner to ``reference`` (None: the op's own)."""
    tool = plan.settings.tool
    if reference is None or reference == tool.reference:
        return Shift(0.0, 0.0)
    d = (tool.width if reference == REFERENCE_PLUS else 0.0) - tool.reference_offset
    return Shift(0.0, d) if plan.cycle.kind()[0] else Shift(d, 0.0)


def shifted(move: Move, shift: Shift, f: Optional[float]) -> Move:
    """``move`` measured from the other corner: its end and an arc's centre shifted, its feed ``f``."""
    centre = None if move.centre is None else (move.centre[0] + shift.dx, move.centre[1] + shift.dz)
    return Move(move.kind, move.x + shift.dx, move.z + shift.dz, f, move.p, centre=centre, radius=move.radius)


def corner_settings(plan: Any, reference: Optional[str]) -> Settings:
    """The plan's engine settings with the tool measured from ``reference`` (None: the op's own)."""
    return plan.settings if reference is None else plan.settings.with_tool(reference=reference)
