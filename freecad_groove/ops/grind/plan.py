"""What a Plunge grind op grinds (GrindPlan: the G83/G83.1 call, the wheel's
start, the expansion) and the flat face it grinds, read from a picked face
(the op plans: op.py).

FreeCAD layer: Part only.
"""

from dataclasses import dataclass, field
from typing import List

import Part

from ...engine.cycles.ab_g83 import G83
from ...engine.moves import MachineState, Move
from .properties import GrindInputError

TOLERANCE = 1e-6


@dataclass
class GrindPlan:
    """What the op grinds: the call, where the wheel stands before it, its expansion."""

    call: G83
    start: MachineState  # x reciprocation, y plunge (FreeCAD Z), z crossover
    moves: List[Move]
    safe_z: float
    face_name: str
    axes: str = "XZY"  # the FreeCAD axes of the grinder's X, Y, Z words (reciprocation, plunge, crossover)
    warnings: List[str] = field(default_factory=list)  # what the op does but could not check


@dataclass
class FlatFace:
    """A picked face: its extent in X and Y and its height."""

    name: str
    x_min: float
    x_max: float
    y_min: float
    y_max: float
    z: float

    def along(self, axis: str) -> tuple:
        """(length from, to, width from, to): along ``axis`` ("X" or "Y") and across it."""
        if axis == "Y":
            return self.y_min, self.y_max, self.x_min, self.x_max
        return self.x_min, self.x_max, self.y_min, self.y_max


def read_face(face: object, name: str) -> FlatFace:
    """The FlatFace of ``face``; GrindInputError unless it is a plane looking
    up (+Z), a rectangle with edges along X and Y."""
    surface = getattr(face, "Surface", None)
    if not isinstance(surface, Part.Plane):
        raise GrindInputError("%s: not a flat face (pick a plane looking up, +Z)" % name, ("Base",))
    u0, u1, v0, v1 = face.ParameterRange
    normal = face.normalAt((u0 + u1) / 2, (v0 + v1) / 2)
    if abs(normal.z - 1) > TOLERANCE:
        raise GrindInputError("%s: its normal (%.3g, %.3g, %.3g) is not +Z: the wheel plunges down along -Z"
                              % ((name,) + tuple(round(v, 6) + 0.0 for v in normal)), ("Base",))
    box = face.BoundBox
    if abs(face.Area - box.XLength * box.YLength) > 1e-6 * max(1.0, face.Area):
        raise GrindInputError("%s: not a rectangle with edges along X and Y (the wheel would grind past it)"
                              % name, ("Base",))
    return FlatFace(name, box.XMin, box.XMax, box.YMin, box.YMax, box.ZMax)


def rounded(value: object) -> object:
    """A length rounded off FreeCAD's float noise (1e-9 mm), so the block reads as the face's numbers."""
    return round(value, 9) + 0.0 if isinstance(value, float) else value
