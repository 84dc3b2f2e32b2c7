"""A Groove op's lathe feeds and speeds: where each comes from, and the defaults.

The op's own values (FeedPerRev, SurfaceSpeed with MaxSpindleSpeed,
SpindleSpeed) come first; where the op leaves one at 0 (unset), its tool
controller's (HorizFeed per minute, SpindleSpeed); where that gives none
either (a new Job's default tool controller has feed 0 and speed 0), the
documented defaults below, so a groove is never posted with feed 0 or a
stopped spindle. The op shows what it uses in its read-only
``FeedsAndSpeeds`` property.

Units here: feeds mm/rev or mm/min, surface speed m/min, spindle speeds rpm.
FreeCAD layer (reads FreeCAD objects), no Qt.
"""

import math
from dataclasses import dataclass
from typing import Optional

from ...engine.numbers import MAX_WORD, format_decimal
from ...freecad.units import SECONDS_PER_MINUTE, feed_mm_per_min, length_mm
from .bounds import BOUNDS
from .properties import GrooveInputError

DEFAULT_FEED_PER_REV = 0.05  # mm/rev: when neither the op nor its tool controller gives a feed
DEFAULT_RPM = 500.0  # rpm: when neither the op nor its tool controller gives a spindle speed
MAX_RPM = 99999.0  # the largest S word the posts write
MM_S_PER_M_MIN = 1000.0 / SECONDS_PER_MINUTE  # a FreeCAD speed (mm/s) per m/min


@dataclass(frozen=True)
class CuttingData:
    """What a groove is cut with.

    feed           mm/rev (``per_rev``) or mm/min
    rpm            fixed spindle speed (G97), None with constant surface speed
    surface_speed  m/min (G96), None for a fixed speed
    max_rpm        the spindle limit of constant surface speed
    direction      the tool controller's SpindleDir ("Forward", "Reverse", "None")
    feed_from, speed_from   where the values came from, in words
    """

    feed: float
    per_rev: bool
    rpm: Optional[float]
    surface_speed: Optional[float]
    max_rpm: Optional[float]
    direction: str
    feed_from: str
    speed_from: str

    def describe(self) -> str:
        """One line for the op's FeedsAndSpeeds property."""
        feed = "%s mm/%s" % (format_decimal(self.feed, 4, point=False), "rev" if self.per_rev else "min")
        if self.surface_speed is not None:
            speed = "%s m/min, at most %d rpm" % (format_decimal(self.surface_speed, 2, point=False),
                                                 int(self.max_rpm or 0))
        else:
            speed = "%d rpm" % int(round(self.rpm or 0))
        return "feed %s (%s); spindle %s (%s)" % (feed, self.feed_from, speed, self.speed_from)

    def rpm_at(self, radius: float) -> float:
        """The spindle speed with the tool at ``radius`` (mm)."""
        if self.surface_speed is None:
            return float(self.rpm or 0.0)
        if radius <= 0:
            return float(self.max_rpm or 0.0)
        return min(float(self.max_rpm or 0.0), self.surface_speed * 1000.0 / (2.0 * math.pi * radius))

    def feed_mm_per_s(self, radius: float) -> float:
        """The feed as FreeCAD's Path F (mm/s), a per-revolution feed at ``radius``."""
        per_min = self.feed * self.rpm_at(radius) if self.per_rev else self.feed
        return per_min / SECONDS_PER_MINUTE


_BOUNDS = {b.name: b for b in BOUNDS}


def _value(op: object, name: str, to_number=float) -> float:
    """Op property ``name`` as a number (FreeCAD's internal unit); GrooveInputError unless in its range
    (bounds.py: finite, 0 or more, at most the documented largest)."""
    value = to_number(getattr(op, name, 0.0) or 0.0)
    bound = _BOUNDS[name]
    message = bound.problem(value * bound.scale)
    if message is not None:
        raise GrooveInputError(message + " (0 = unset)", (name,))
    return value


def _speed(value: float, name: str) -> float:
    if value > MAX_RPM:
        raise GrooveInputError("%s=%g: must be at most %d rpm" % (name, value, MAX_RPM), (name,))
    return value


def _feed(op: object, tool_controller: object) -> tuple:
    """(feed, per_rev, where from)."""
    per_rev = _value(op, "FeedPerRev", length_mm)
    if per_rev > 0:
        return per_rev, True, "the op's FeedPerRev"
    horizontal = feed_mm_per_min(length_mm(tool_controller.HorizFeed)) if tool_controller is not None else 0.0
    if not (math.isfinite(horizontal) and horizontal < MAX_WORD):
        raise GrooveInputError("HorizFeed=%g mm/min: the tool controller %s's HorizFeed must be a feed below %g "
                               "mm/min" % (horizontal, tool_controller.Label, MAX_WORD), ("ToolController",))
    if horizontal > 0:
        return horizontal, False, "the tool controller's HorizFeed"
    return DEFAULT_FEED_PER_REV, True, "default: the op's FeedPerRev and the tool controller's HorizFeed are 0"


def cutting_data(op: object) -> CuttingData:
    """The feeds and speeds op ``op`` cuts with (GrooveInputError naming a bad property)."""
    tool_controller = getattr(op, "ToolController", None)
    feed, per_rev, feed_from = _feed(op, tool_controller)
    surface = _value(op, "SurfaceSpeed", length_mm) / MM_S_PER_M_MIN
    limit = _speed(_value(op, "MaxSpindleSpeed"), "MaxSpindleSpeed")
    fixed = _speed(_value(op, "SpindleSpeed"), "SpindleSpeed")
    direction = str(getattr(tool_controller, "SpindleDir", "Forward")) if tool_controller is not None else "Forward"
    if surface > 0:
        if not limit > 0:
            raise GrooveInputError("MaxSpindleSpeed=0: constant surface speed (SurfaceSpeed) needs the spindle's "
                                   "limit, in rpm", ("MaxSpindleSpeed",))
        return CuttingData(feed, per_rev, None, surface, limit, direction, feed_from, "the op's SurfaceSpeed")
    if fixed > 0:
        return CuttingData(feed, per_rev, fixed, None, None, direction, feed_from, "the op's SpindleSpeed")
    tc_speed = float(getattr(tool_controller, "SpindleSpeed", 0.0) or 0.0) if tool_controller is not None else 0.0
    if math.isfinite(tc_speed) and tc_speed > 0:
        return CuttingData(feed, per_rev, tc_speed, None, None, direction, feed_from,
                           "the tool controller's SpindleSpeed")
    return CuttingData(feed, per_rev, DEFAULT_RPM, None, None, direction, feed_from,
                       "default: the op's and the tool controller's SpindleSpeed are 0")
