"""The names, alarm numbers, limits and tolerances of CYCLE93, and its error;
shared by the model (``cycle93``), the geometry (``cycle93_geometry``) and the
size check (``cycle93_size``)."""

from typing import Optional

from ..errors import CycleError

NAME = "CYCLE93"
PARAMS = (
    "AXFA", "AXSA", "WIDG", "DEPG", "ANGC", "ANG1", "ANG2", "RCO1", "RCO2",
    "RCI1", "RCI2", "FAL1", "FAL2", "IDEP", "DWT", "TYP", "VRT", "DN",
)
ALARM_TYP = 61002
ALARM_WIDTH = 61602
ALARM_FORM = 61603
MAX_FLANK_ANGLE = 89.999
WIDTH_STEP_FACTOR = 0.95  # Siemens manual: at most 95 % of (tool width - edge radii)
DEFAULT_VRT_MM = 1.0  # Siemens manual: VRT = 0 means 1 mm
DEFAULT_VRT_INCH = 0.04
# After a chip-breaking retract the blade rapids back down its own slot to
# this far above the depth it reached, then feeds on: only this gap is fed in
# air, not VRT. Never more than VRT (with VRT below it, no rapid back down).
# Also how far over what the plunges left the contour passes start feeding.
REENTRY_CLEARANCE_MM = 0.1
REENTRY_CLEARANCE_INCH = 0.004
# The Siemens manual: "From the second cut along the groove width onwards, the tool will
# retract by 1 mm before each retraction": at the bottom of every plunge after
# the first the blade rapids this far along the groove's axis back toward the
# previous plunge (never further than it, inside slots cut as deep), then out.
FREE_OFF_MM = 1.0
FREE_OFF_INCH = 0.04
PATH_TOLERANCE = 0.0002  # chord error allowed on contour passes and arcs
EPS = 1e-9
# The contour passes run on past the opening's lower edge, overhanging it,
# only where the blade reaches more than this lower there (see
# GrooveGeometry.pass_range): not for float noise.
OVERHANG_GAIN = 1e-6
# A plunge that ends this close to the roughing profile's base line is on the
# base: DWT dwells there only ("dwell time at recess base").
BASE_TOLERANCE = 1e-6
# The length parameters: like every written coordinate, less than MAX_WORD in
# magnitude (beyond that, doubles no longer hold PATH_TOLERANCE).
LENGTH_PARAMS = ("AXFA", "AXSA", "WIDG", "DEPG", "RCO1", "RCO2", "RCI1", "RCI2", "FAL1", "FAL2", "IDEP", "VRT")


def cycle93_error(param: str, value: object, rule: str, alarm: Optional[int] = None) -> CycleError:
    """A CycleError of CYCLE93."""
    return CycleError(param, value, rule, alarm=alarm, cycle=NAME)
