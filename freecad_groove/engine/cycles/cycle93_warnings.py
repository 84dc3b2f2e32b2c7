"""CYCLE93's warnings: where the allowances leave the blade no room to rough,
and the material the blade cannot reach (``cycle93_reach``).

Roughing stops at the allowances (FAL1 on the base, FAL2 on the flanks) and a
finishing pass follows. When the roughing profile those allowances leave is
too narrow for the blade, or too short for the base corners RCI1/RCI2, the
geometry roughs to the final profile instead (``GrooveGeometry.roughs_to_final``,
with the reason in ``GrooveGeometry.no_room``), and the cycle says so with a
warning rather than silently.
"""

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, List, Optional, Sequence, Tuple

from ..numbers import format_given, format_value
from ..warnings import CycleWarning
from .cycle93_constants import NAME
from .cycle93_reach import reach_warnings

if TYPE_CHECKING:  # the geometry imports this module
    from .cycle93_geometry import GrooveGeometry

Point = Tuple[float, float]

__all__ = ["NoRoom", "no_room", "cycle93_warnings"]


@dataclass(frozen=True)
class NoRoom:
    """Why roughing runs on the final profile.

    ``parameter`` the allowance to blame ("FAL2": the flank allowances narrow
    the base; "FAL1": the raised base shortens the flanks); ``room`` the length
    left (radius values, the program's units); ``need`` what had to fit there;
    ``what`` names the room and the need in words.
    """

    parameter: str
    room: float
    need: float
    what: str


def no_room(tool_width: float, slope: float, rough: Sequence[Any], points: Sequence[Point],
            units: str) -> Optional[NoRoom]:
    """None when the roughing profile has room for the blade and its base
    corners, else why not. ``rough`` the roughing profile's four corners (each
    with ``.length``, its cut back along each element), ``points`` their
    vertices r1, rb1, rb2, r2; ``units`` "mm" or "in" for the words."""
    r1, rb1, rb2, r2 = points
    base = rb2[0] - rb1[0]
    along = base * math.hypot(1, slope)  # the base's length along the contour
    corners = rough[1].length + rough[2].length
    if base < tool_width:
        return NoRoom("FAL2", base, tool_width, "FAL2 leaves a roughing base %s %s wide" % (_length(base), units))
    if corners >= along:
        return NoRoom("FAL2", along, corners, "FAL2 leaves a roughing base %s %s long, too short for the base "
                      "corners RCI1 and RCI2" % (_length(along), units))
    for name, corner, top, bottom in (("RCI1", rough[1], r1, rb1), ("RCI2", rough[2], r2, rb2)):
        flank = math.dist(top, bottom)
        if corner.length > flank:
            return NoRoom("FAL1", flank, corner.length, "FAL1 leaves a roughing flank %s %s long, too short for "
                          "the base corner %s" % (_length(flank), units, name))
    return None


def _length(value: float) -> str:
    return format_value(round(max(value, 0.0), 4))


def cycle93_warnings(geometry: "GrooveGeometry") -> List[CycleWarning]:
    """The warnings of a CYCLE93 groove: roughing on the final profile, and
    the material the blade cannot reach (``cycle93_reach``)."""
    return _no_room_warnings(geometry) + reach_warnings(geometry)


def _no_room_warnings(geometry: "GrooveGeometry") -> List[CycleWarning]:
    reason = geometry.no_room
    if not geometry.roughs_to_final or reason is None:
        return []
    call = geometry.call
    units = "mm" if geometry.metric else "in"
    message = "the allowances FAL1=%s FAL2=%s leave no room for the %s %s blade: %s; roughing runs on the " \
              "final profile, leaving nothing for the finishing pass" % (
                  format_given(call.value("FAL1")), format_given(call.value("FAL2")),
                  format_value(geometry.tool.width), units, reason.what)
    return [CycleWarning(NAME, reason.parameter, message)]
