"""The Groove op's numeric properties and their ranges (freecad/bounds.py;
the table in docs/op-bounds.md is made from these rows).

Lengths stay below the 1 000 000 every CYCLE93 length parameter and written
coordinate must stay below (engine/numbers.py MAX_WORD); the rules CYCLE93
itself puts on a value are checked by the engine, whose message names the
property (``more``). Feeds and speeds are the op's own choices, documented
here: a feed per revolution up to 10 mm/rev (a blade feeds 0.02 to 0.5),
surface speeds up to 10 000 m/min, spindle speeds up to the 99 999 rpm the
posts' S word holds.

FreeCAD layer: plain data.
"""

from ...engine.cycles.cycle93_constants import MAX_FLANK_ANGLE
from ...engine.numbers import MAX_DWELL_SECONDS, MAX_WORD
from ...freecad.bounds import Bound

MAX_FEED_PER_REV_MM = 10.0
MAX_SURFACE_SPEED_M_MIN = 10000.0
MAX_RPM = 99999.0  # the largest S word the posts write
M_MIN_PER_MM_S = 60.0 / 1000.0  # a FreeCAD speed (mm/s) in m/min

_WORD = "CYCLE93's lengths and every written coordinate stay below 1e6 (engine MAX_WORD)"


def _length(name: str, more: str = "", why: str = _WORD) -> Bound:
    return Bound(name, 0.0, MAX_WORD, "mm", more, why)


BOUNDS = (
    _length("Position", "the groove must lie on the face (the op)"),
    _length("Width", "greater than 0 and at least the blade's width (engine: WIDG, alarm 61602)"),
    _length("Depth", "greater than 0 (engine: DEPG); at most the blade's CuttingEdgeHeight (the op)"),
    Bound("FlankAngle1", 0.0, MAX_FLANK_ANGLE, "°", "", "SINUMERIK CYCLE93 ANG1", checker="the engine (ANG1)"),
    Bound("FlankAngle2", 0.0, MAX_FLANK_ANGLE, "°", "", "SINUMERIK CYCLE93 ANG2", checker="the engine (ANG2)"),
    _length("EdgeCorner1", "fits the groove (engine: RCO1)"),
    _length("EdgeCorner2", "fits the groove (engine: RCO2)"),
    _length("BaseCorner1", "fits the groove (engine: RCI1)"),
    _length("BaseCorner2", "fits the groove (engine: RCI2)"),
    _length("BaseAllowance", "less than the groove's depth (engine: FAL1)"),
    _length("FlankAllowance", "less than half the groove's width (engine: FAL2)"),
    _length("Infeed", "greater than 0 (engine: IDEP)"),
    Bound("Dwell", 0.0, MAX_DWELL_SECONDS, "s", "0 = none", "the longest dwell any output writes (engine "
          "MAX_DWELL_SECONDS)", high_open=False, checker="the engine (DWT)"),
    _length("Retract", "0 = 1 mm"),
    Bound("GrooveCount", 1, 10000, "", "", "FreeCAD's constraint on the property", high_open=False),
    _length("Pitch", "greater than 0 when GrooveCount is more than 1 (the op)"),
    _length("ToolWidth", "greater than 0 unless the tool bit has a Width (the op)"),
    _length("ToolCornerRadius"),
    Bound("FeedPerRev", 0.0, MAX_FEED_PER_REV_MM, "mm/rev", "0 = the tool controller's HorizFeed",
          "the op's choice: ten times a heavy grooving feed", high_open=False),
    Bound("SurfaceSpeed", 0.0, MAX_SURFACE_SPEED_M_MIN, "m/min", "0 = a fixed SpindleSpeed",
          "the op's choice: above any lathe's cutting speed", high_open=False, scale=M_MIN_PER_MM_S),
    Bound("MaxSpindleSpeed", 0.0, MAX_RPM, "rpm", "greater than 0 with SurfaceSpeed",
          "the posts' S word (5 digits)", high_open=False),
    Bound("SpindleSpeed", 0.0, MAX_RPM, "rpm", "0 = the tool controller's SpindleSpeed",
          "the posts' S word (5 digits)", high_open=False),
)

# The grooving blade tool bit's lengths the op reads (its tool controller's Tool).
TOOL_BOUNDS = (
    _length("Width", "greater than 0: the blade's width (else the op's ToolWidth)"),
    _length("CornerRadius"),
    _length("CuttingEdgeHeight", "the blade's free reach: a deeper groove is refused (0 or none: not checked)"),
    _length("FirstCutDiameterMin", "a face groove's first plunge cutting below it is refused (0 or none: not "
                                   "checked)"),
    _length("FirstCutDiameterMax", "a face groove's first plunge cutting above it is refused (0 or none: not "
                                   "checked)"),
    _length("MinBoreDiameter", "an internal groove in a smaller bore is refused (0 or none: not checked)"),
    _length("HolderWidth", "the turning check draws the holder (0 or none: not drawn)"),
)
