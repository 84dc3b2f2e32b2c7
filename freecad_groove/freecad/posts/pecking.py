"""The pecking-cycle calls (Allen-Bradley G77/G76, Fanuc and Haas G75/G74) that
cut a group of plain CYCLE93 grooves: the engine decides and builds them
(``engine/native/cycle93_pecking.py``, shared with ``expand --native-cycles``);
this adapter gives it the post's output and names the op property at fault."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, List

from ...engine import CycleError
from ...engine.native import NotNative
from ...engine.native.cycle93_pecking import PeckingCall, PeckingOutput, groove_span, pecking_calls, plain_reason
from ...engine.numbers import MM_PER_INCH
from .post_error import cycle_post_error

if TYPE_CHECKING:
    from .program import Program

__all__ = ["NotNative", "PECKING_PROPERTIES", "PeckingCall", "PeckingCalls", "groove_span", "plain_reason"]

# pecking word -> what the op sets it from
PECKING_PROPERTIES = {"I": "Infeed", "K": "Infeed", "P": "Infeed", "Q": "Infeed", "X": "Depth", "Z": "Depth",
                      "F": "FeedPerRev (or the tool controller's HorizFeed)", "e": "Retract", "R(e)": "Retract"}


class PeckingCalls:
    """The pecking-cycle calls of one Groove op's groups of grooves, for a
    Program; ``feed`` the grooves' feed (mm/rev with ``per_rev``, else
    mm/min), ``label`` the op's. The calls' words are in the output's units;
    the plans are in mm."""

    def __init__(self, program: Program, label: str, feed: float, per_rev: bool = False) -> None:
        options = program.options
        self.output = PeckingOutput(
            program.writer.target, program.writer, 1.0 / MM_PER_INCH if options.inches else 1.0,
            options.native_decimals, options.diameter, options.retract, None, options.reference)
        self.label = label
        self.feed = feed
        self.per_rev = per_rev

    def calls(self, group: List[Any]) -> List[PeckingCall]:
        """The calls that cut ``group``; NotNative (the whole reason: ``G75
        cannot cut flank angles``) when the control's cycle cannot cut them."""
        try:
            return pecking_calls(group, self.output, self.feed, self.per_rev)
        except CycleError as exc:
            raise cycle_post_error(self.label, exc, PECKING_PROPERTIES) from None
