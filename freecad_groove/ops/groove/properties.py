"""The Groove op's properties, declared once: their types, groups, tooltips
and defaults, and which property each CYCLE93 parameter comes from (so the
op, its task panel and the posts name the same property for an error), and
the error that names the properties to fix, the checks of their values
that name them, and the CYCLE93 value of a corner's two properties.

FreeCAD layer: imports FreeCAD (for the tooltips' translation marker), never Qt.
"""

import math
from typing import Optional, Tuple

import FreeCAD

from ...engine.cycles.cycle93 import ALARM_WIDTH
from ...freecad.bounds import check_bounds
from .bounds import BOUNDS

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

CORNER_TYPES = ["None", "Radius", "Chamfer"]
CHAMFER_MEASURES = ["Chamfer length (CHF)", "Leg length (CHR)"]
REFERENCE_CORNERS = ["minus", "plus"]
MAX_GROOVES = 10000


def _tip(text: str) -> str:
    """A tooltip, marked for translation in the "App::Property" context."""
    return QT_TRANSLATE_NOOP("App::Property", text)


_EDGE1 = "1 = the groove's start edge: its +Z edge (longitudinal grooves) or its outer edge (face grooves)"
_CORNER_SIZE = "Size of the %s %s (RC%s): the radius, or the chamfer measured as ChamferMeasure says. " + _EDGE1 + "."
_CORNER_TYPE = "What the %s %s gets: None (sharp), Radius or Chamfer (the size is %s)."


def _corner(name: str, size_place: str, type_place: str, flank: str, word: str) -> tuple:
    """The two rows of a corner: its size ``name`` (CYCLE93's RC``word``) and
    its kind ``name``Type; the tooltips say where the corner is."""
    return (
        ("App::PropertyLength", name, "Groove", _tip(_CORNER_SIZE % (size_place, flank, word)), 0.0),
        ("App::PropertyEnumeration", name + "Type", "Groove", _tip(_CORNER_TYPE % (type_place, flank, name)),
         CORNER_TYPES),
    )


# (type, name, group, tooltip, default); enumerations: default = the list, first entry selected.
PROPERTIES = (
    ("App::PropertyLength", "Position", "Groove", _tip(
        "Where the groove starts: distance from the face's +Z end along Z to the groove's +Z edge "
        "(cylinders, cones), or from the face's outer edge toward the axis to the groove's outer edge "
        "(planes, steep cones). Sets AXSA/AXFA."), 0.0),
    ("App::PropertyLength", "Width", "Groove", _tip(
        "Width of the groove base along the groove's own axis (WIDG); at least the tool width."), 4.0),
    ("App::PropertyLength", "Depth", "Groove", _tip(
        "Depth of the groove from the face, along the plunge axis (DEPG, a radius value for longitudinal "
        "grooves)."), 2.0),
    ("App::PropertyAngle", "FlankAngle1", "Groove", _tip(
        "Angle of flank 1 from the plunge direction, opening outward (ANG1), 0 <= angle < 89.999. "
        + _EDGE1 + "."), 0.0),
    ("App::PropertyAngle", "FlankAngle2", "Groove", _tip(
        "Angle of flank 2 (the far edge) from the plunge direction, opening outward (ANG2), "
        "0 <= angle < 89.999."), 0.0),
    *_corner("EdgeCorner1", "part's edge at the top of", "edge at the top of", "flank 1", "O1"),
    *_corner("EdgeCorner2", "part's edge at the top of", "edge at the top of", "flank 2", "O2"),
    *_corner("BaseCorner1", "corner between the base and", "corner between the base and", "flank 1", "I1"),
    *_corner("BaseCorner2", "corner between the base and", "corner between the base and", "flank 2", "I2"),
    ("App::PropertyEnumeration", "ChamferMeasure", "Groove", _tip(
        "How chamfer sizes are measured: the chamfer's own length (CHF, TYP 1..8) or the leg along each "
        "element it cuts (CHR, TYP 11..18)."), CHAMFER_MEASURES),
    ("App::PropertyBool", "ModelGroove", "Groove", _tip(
        "Read the groove from the model: the picked face is a face of a modelled groove (its base, a flank, a "
        "corner) and Position, Width, Depth, the flank angles and the corners come from it, except the "
        "properties listed in ModelOverrides; the groove is cut into the contour line around it."), False),
    ("App::PropertyStringList", "ModelOverrides", "Groove", _tip(
        "With ModelGroove: the properties whose own values override the model's (a property set by hand is "
        "added here; remove its name to take the model's value again)."), []),
    ("App::PropertyLength", "BaseAllowance", "Groove", _tip(
        "Finishing allowance left on the base by the roughing (FAL1)."), 0.0),
    ("App::PropertyLength", "FlankAllowance", "Groove", _tip(
        "Finishing allowance left on the flanks by the roughing, normal to them (FAL2)."), 0.0),
    ("App::PropertyLength", "Infeed", "Groove", _tip(
        "Largest infeed of one plunge step before a chip-breaking retract (IDEP); greater than 0."), 1.0),
    ("App::PropertyFloat", "Dwell", "Groove", _tip(
        "Dwell where a roughing plunge reaches the groove base (not where it stops on a flank), in seconds "
        "(DWT); 0 = none."), 0.0),
    ("App::PropertyLength", "Retract", "Groove", _tip(
        "Chip-breaking retract and clearance above the contour (VRT); 0 = 1 mm. Also the clearance "
        "kept outside the model for the op's start points."), 0.0),
    ("App::PropertyIntegerConstraint", "GrooveCount", "Groove", _tip(
        "Number of equal grooves on each face (1 or more), Pitch apart."), (1, 1, MAX_GROOVES, 1)),
    ("App::PropertyLength", "Pitch", "Groove", _tip(
        "Distance from one groove to the next: toward -Z for longitudinal grooves, toward the axis for "
        "face grooves. Must be greater than 0 when GrooveCount is more than 1."), 0.0),
    ("App::PropertyLength", "ToolWidth", "Tool", _tip(
        "Width of the blade's cutting edge; used when the tool controller's tool bit has no Width. "
        "0 = unknown: the op then asks for a grooving tool controller or a width."), 0.0),
    ("App::PropertyLength", "ToolCornerRadius", "Tool", _tip(
        "Radius of the blade's two front corners; used when the tool bit has no CornerRadius."), 0.2),
    ("App::PropertyEnumeration", "ReferenceCorner", "Tool", _tip(
        "The blade corner the Path drives: minus = on the blade's -Z side (X plunges) or -X side "
        "(Z plunges), plus = the other one."), REFERENCE_CORNERS),
    # Lathe feeds and speeds (cutting.py): 0 = unset, the tool controller's value, else the documented default.
    ("App::PropertyLength", "FeedPerRev", "Feeds and speeds", _tip(
        "Feed per revolution of the grooves (mm/rev, in/rev: G95/G99). 0 = the tool controller's HorizFeed "
        "(per minute); when that is 0 too, 0.05 mm/rev."), 0.0),
    ("App::PropertySpeed", "SurfaceSpeed", "Feeds and speeds", _tip(
        "Constant surface speed (G96, e.g. 120 m/min), limited to MaxSpindleSpeed. 0 = a fixed spindle "
        "speed: SpindleSpeed."), 0.0),
    ("App::PropertyFloat", "MaxSpindleSpeed", "Feeds and speeds", _tip(
        "Spindle limit of the constant surface speed, rpm (Siemens LIMS, Fanuc/Haas G50 S, LinuxCNC G96 D); "
        "needed with SurfaceSpeed."), 0.0),
    ("App::PropertyFloat", "SpindleSpeed", "Feeds and speeds", _tip(
        "Fixed spindle speed of the grooves, rpm (G97), when SurfaceSpeed is 0. 0 = the tool controller's "
        "SpindleSpeed; when that is 0 too, 500 rpm."), 0.0),
    ("App::PropertyString", "GrooveKind", "Derived", _tip(
        "What the op made of the face(s): longitudinal/oblique/face, external/internal."), ""),
    ("App::PropertyString", "FeedsAndSpeeds", "Derived", _tip(
        "The feed and spindle speed the grooves are cut with, and where each comes from."), ""),
    ("App::PropertyStringList", "FromModel", "Derived", _tip(
        "With ModelGroove: the properties whose values came from the model at the last recompute."), []),
    ("App::PropertyDistance", "AXFA", "Derived", _tip(
        "CYCLE93 AXFA of the first groove: the start point's radius (X)."), 0.0),
    ("App::PropertyDistance", "AXSA", "Derived", _tip(
        "CYCLE93 AXSA of the first groove: the start point's Z."), 0.0),
    ("App::PropertyAngle", "ANGC", "Derived", _tip(
        "CYCLE93 ANGC: the contour's angle, counter-clockwise from +Z with X up."), 0.0),
    ("App::PropertyInteger", "TYP", "Derived", _tip(
        "CYCLE93 TYP: 5 longitudinal external, 7 longitudinal internal, 6 face external, 8 face "
        "internal (all 'right'); +10 with CHR chamfers."), 0),
)
PROPERTY_NAMES = tuple(p[1] for p in PROPERTIES)
PROPERTY_TYPES = {p[1]: p[0] for p in PROPERTIES}
DERIVED = tuple(p[1] for p in PROPERTIES if p[2] == "Derived")
DEFAULTS = {p[1]: (p[4][0] if p[0] == "App::PropertyEnumeration" else p[4]) for p in PROPERTIES}


class GrooveInputError(ValueError):
    """A value of the op that cannot make a groove; ``properties`` names the
    op properties to fix (the task panel marks their fields)."""

    def __init__(self, message: str, properties: Tuple[str, ...] = ()):
        super().__init__(message)
        self.properties = tuple(properties)


# CYCLE93 parameter (a CycleError.parameter, composite ones split at "/") ->
# the op property it comes from
CYCLE93_PROPERTIES = {
    "AXFA": "Position", "AXSA": "Position", "start point": "Position",
    "WIDG": "Width", "DEPG": "Depth", "ANGC": "Base", "ANG1": "FlankAngle1", "ANG2": "FlankAngle2",
    "RCO1": "EdgeCorner1", "RCO2": "EdgeCorner2", "RCI1": "BaseCorner1", "RCI2": "BaseCorner2",
    "FAL1": "BaseAllowance", "FAL2": "FlankAllowance", "IDEP": "Infeed", "DWT": "Dwell",
    "VRT": "Retract", "TYP": "ChamferMeasure", "tool width": "ToolWidth", "tool corner radius": "ToolCornerRadius",
}
# What a message adds after a property name, where the value may come from elsewhere.
PROPERTY_NOTES = {
    "Base": "the face's contour",
    "ToolWidth": "or the tool bit's Width",
    "ToolCornerRadius": "or the tool bit's CornerRadius",
}


def cycle93_properties(parameter: object) -> Tuple[str, ...]:
    """The op properties a CYCLE93 parameter ("WIDG", "RCI1/RCI2") comes from
    (the known ones, in order)."""
    return tuple(CYCLE93_PROPERTIES[p] for p in str(parameter).split("/") if p in CYCLE93_PROPERTIES)


def describe_cycle93_parameter(parameter: object) -> Optional[str]:
    """The op properties of a CYCLE93 parameter for a message
    ("BaseCorner1/BaseCorner2", "ToolWidth (or the tool bit's Width)"); None
    when a part of it comes from no property."""
    parts = str(parameter).split("/")
    if not all(p in CYCLE93_PROPERTIES for p in parts):
        return None
    names = [CYCLE93_PROPERTIES[p] for p in parts]
    return "/".join(n + (" (%s)" % PROPERTY_NOTES[n] if n in PROPERTY_NOTES else "") for n in names)


def error_properties(error: Exception) -> Tuple[str, ...]:
    """The op properties an error from plan() is about: () when it names none."""
    props = getattr(error, "properties", None)
    if props is not None:
        return tuple(props)
    parameter = getattr(error, "parameter", None)  # a CycleError
    if parameter is None:
        return ()
    props = cycle93_properties(parameter)
    if props == ("Width",) and getattr(error, "alarm", None) == ALARM_WIDTH:
        props += ("ToolWidth",)  # narrower than the blade: either may be wrong
    return props


def check_finite(obj: object) -> None:
    """GrooveInputError naming the first numeric op property out of its range
    (bounds.py): NaN, an infinity (FreeCAD takes both from a script or an
    expression), a number beyond what a program can hold."""
    check_bounds(obj, BOUNDS, GrooveInputError)


def finite_or_error(value: float, what: str, properties: tuple) -> float:
    """``value`` when finite, else GrooveInputError naming ``what``."""
    if not math.isfinite(value):
        raise GrooveInputError("%s=%s: must be a finite number" % (what, value), properties)
    return value


def corner_value(obj: object, name: str) -> float:
    """CYCLE93's RCO/RCI value of the corner property ``name``: the radius,
    the chamfer as a negative number, 0 for none."""
    kind = getattr(obj, name + "Type")
    size = getattr(obj, name).Value
    if kind == "Radius":
        return size
    if kind == "Chamfer":
        return -size if size else 0.0
    return 0.0
