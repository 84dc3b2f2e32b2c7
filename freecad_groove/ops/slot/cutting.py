"""A Cylinder slot's feed and live tool speed: where each comes from, and the defaults.

The slot is milled by the live end mill at its tool controller's HorizFeed
(along the developed path, mm/min in the program) and SpindleSpeed (the live
tool's, with its SpindleDir). Where the tool controller gives none (a new
Job's default tool controller has feed 0 and speed 0), the documented
defaults below, so that a new Job's slot can be posted as it is, never with
feed 0 or a still end mill; the op shows what it uses in its read-only
``FeedsAndSpeeds`` (the task panel too), the posts write the same.

The defaults are low for a small end mill in steel on a live tool (about
16 m/min and 0.025 mm a tooth for a 5 mm two-flute end mill, CAM's default
tool): slow, never too fast; a machinist sets the tool controller's.

FreeCAD layer (reads FreeCAD objects' values), no Qt.
"""

import math
from dataclasses import dataclass

from ...engine.numbers import format_decimal
from ...freecad.units import feed_mm_per_min, length_mm
from .properties import SlotInputError

DEFAULT_FEED_MM_MIN = 50.0  # along the developed path, when the tool controller's HorizFeed is 0
DEFAULT_LIVE_RPM = 1000  # the live tool's, when the tool controller's SpindleSpeed is 0
MAX_RPM = 99999  # the largest S word the posts write


@dataclass(frozen=True)
class SlotCutting:
    """What a slot is milled with: ``feed`` mm/min along the developed path, the live tool's ``rpm`` and
    ``reverse`` (SpindleDir Reverse), and where each came from, in words."""

    feed: float
    rpm: int
    reverse: bool
    feed_from: str
    speed_from: str

    def describe(self) -> str:
        """One line for the op's FeedsAndSpeeds property."""
        return "feed %s mm/min (%s); live tool %d rpm %s (%s)" % (
            format_decimal(self.feed, 3, point=False), self.feed_from, self.rpm, "CCW" if self.reverse else "CW",
            self.speed_from)


def slot_cutting(obj: object) -> SlotCutting:
    """The feed and live tool speed op ``obj`` mills with (SlotInputError naming the tool controller when it
    has none, or a value that is not a number 0 or more)."""
    tc = getattr(obj, "ToolController", None)
    if tc is None:
        raise SlotInputError("ToolController: none: the op needs an end mill's tool controller", ("ToolController",))
    feed = feed_mm_per_min(length_mm(tc.HorizFeed))
    rpm = float(getattr(tc, "SpindleSpeed", 0.0) or 0.0)
    for name, value in (("HorizFeed", feed), ("SpindleSpeed", rpm)):
        if not (math.isfinite(value) and value >= 0):
            raise SlotInputError("%s=%s: the tool controller's %s must be a number, 0 or more (0: the default)"
                                 % (name, value, name), ("ToolController",))
    if rpm > MAX_RPM:
        raise SlotInputError("SpindleSpeed=%g: the live tool's speed must be at most %d rpm" % (rpm, MAX_RPM),
                             ("ToolController",))
    reverse = str(getattr(tc, "SpindleDir", "Forward")) == "Reverse"
    feed_from, speed_from = "the tool controller's HorizFeed", "the tool controller's SpindleSpeed"
    if feed == 0:
        feed, feed_from = DEFAULT_FEED_MM_MIN, "default: the tool controller's HorizFeed is 0"
    if round(rpm) == 0:
        rpm, speed_from = DEFAULT_LIVE_RPM, "default: the tool controller's SpindleSpeed is 0"
    return SlotCutting(feed, int(round(rpm)), reverse, feed_from, speed_from)
