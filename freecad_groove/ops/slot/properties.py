"""The Cylinder slot op's properties, declared once (type, name, tooltip,
default; all in the group "Cylinder slot"), and the error that names the
properties to fix.

FreeCAD layer: plain data, no import of FreeCAD.
"""

import math
from typing import Tuple

from ...freecad.bounds import Bound
from ...freecad.units import length_mm

GROUP = "Cylinder slot"

# (type, name, tooltip, default)
PROPERTIES = (
    ("App::PropertyLength", "Depth", "Depth of the slot below the cylinder, radial (J = -2 Depth).", 1.0),
    ("App::PropertyInteger", "Passes", "Rough passes before the finish pass (L; 1 runs as 2, as GSK does).", 2),
    ("App::PropertyLength", "Allowance", "Finishing allowance, radial: left by the rough passes (K = 2 Allowance).",
     0.1),
    ("App::PropertyLength", "Retract", "Clearance above the cylinder the tool retracts to between passes, radial "
     "(R = 2 Retract); also the clearance of the safe radius.", 1.0),
    ("App::PropertyLink", "DevelopedSketch", "A sketch of the slot's path on the developed surface, used instead "
     "of edges in Base: sketch x = Z, sketch y = the developed length radius*C (C 0 at y 0).", None),
    ("App::PropertyLength", "SlotWidth", "The slot's width: the end mill's diameter (read only).", 0.0),
    ("App::PropertyString", "Region", "The G7.1 start block the op cuts with (read only).", ""),
    ("App::PropertyString", "FeedsAndSpeeds", "The feed and the live tool's speed the slot is milled with, and "
     "where each comes from: the tool controller's HorizFeed and SpindleSpeed, or the defaults where they are 0 "
     "(read only).", ""),
)
DERIVED = ("SlotWidth", "Region", "FeedsAndSpeeds")

# The ranges of the numeric properties (freecad/bounds.py; docs/op-bounds.md): the program writes Depth,
# Allowance and Retract doubled (diameters J, K, R), below G7.1's 100000.
MAX_LENGTH_MM = 50000.0
_WORD = "written doubled (J, K, R), below G7.1's 100000 (engine gsk_g7_1 MAX_WORD)"
BOUNDS = (
    Bound("Depth", 0.0, MAX_LENGTH_MM, "mm", "greater than 0; at most the end mill's CuttingEdgeHeight (the op)",
          _WORD),
    Bound("Passes", 1, 9999, "", "", "G7.1's L (engine gsk_g7_1 MAX_PASSES)", high_open=False),
    Bound("Allowance", 0.0, MAX_LENGTH_MM, "mm", "less than Depth (the op)", _WORD),
    Bound("Retract", 0.0, MAX_LENGTH_MM, "mm", "greater than 0 (the op)", _WORD),
)
LENGTHS = tuple(name for type_id, name, _tip, _default in PROPERTIES if type_id == "App::PropertyLength")


class SlotInputError(ValueError):
    """A value of the op that cannot make a slot; ``properties`` names the op properties to fix (the task
    panel marks their fields)."""

    def __init__(self, message: str, properties: Tuple[str, ...] = ()):
        super().__init__(message)
        self.properties = tuple(properties)


def finite_length(obj: object, name: str) -> float:
    """The op's length property ``name`` in mm; SlotInputError naming it unless finite."""
    value = length_mm(getattr(obj, name))
    if not math.isfinite(value):
        raise SlotInputError("%s=%s: must be a finite number" % (name, value), (name,))
    return value
