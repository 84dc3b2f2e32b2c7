"""Where the Plunge grind op's wheel goes, checked against the Job's model:
its body above the lowest point of its periphery (which the op's Path
drives; op.py's check_clear checks that point's own sweep).

The wheel is a disc of radius R = diameter / 2 turning about an axis along
the crossover, its lowest point on the Path. What it sweeps, in the plane of
reciprocation (r) and plunge (z), over the crossover's whole span (the
wheel's width each side of its middle):

- the strokes between the reversal points I and X at every height from the
  face up to the start height: the discs centred R above the face at I and
  at X, the band between them from the face up to R above it, and above
  that the band from I - R to X + R up to the start height + R;
- the rapids down to the start (at I) and up after the grind (at I or X)
  from the safe height: the bands I - R .. I + R and X - R .. X + R up to
  the safe height + R.

The model may touch this region (a wall flush with the wheel's side) but
not enter it by CLEAR_ABOVE_MM or more above the face. What sits above the
wheel's top (its spindle, guard) is not checked.

FreeCAD layer: FreeCAD and Part only.
"""

from typing import List, Optional

import FreeCAD
import Part

from ...freecad.addon_op import modelled_part
from .properties import GrindInputError

CLEAR_ABOVE_MM = 1e-3  # model material this far into the wheel's sweep and more is in its way
MIN_VOLUME_MM3 = 1e-6  # a common volume below this is a touch, not a collision


class Frame:
    """FreeCAD coordinates from the grind's (r: reciprocation, c: crossover, z: plunge); ``axes`` as GrindPlan's
    ("XZY": r = X, c = Y; "YZX": r = Y, c = X)."""

    def __init__(self, axes: str):
        self.along_y = axes[0] == "Y"

    def point(self, r: float, c: float, z: float) -> FreeCAD.Vector:
        return FreeCAD.Vector(c, r, z) if self.along_y else FreeCAD.Vector(r, c, z)

    def box(self, r0: float, r1: float, c0: float, c1: float, z0: float, z1: float) -> Optional[Part.Shape]:
        """The box r0..r1, c0..c1, z0..z1 (None when empty)."""
        if r1 - r0 <= 0 or c1 - c0 <= 0 or z1 - z0 <= 0:
            return None
        sizes = (c1 - c0, r1 - r0) if self.along_y else (r1 - r0, c1 - c0)
        return Part.makeBox(sizes[0], sizes[1], z1 - z0, self.point(r0, c0, z0))

    def disc(self, r: float, z: float, radius: float, c0: float, c1: float) -> Part.Shape:
        """The wheel centred at (r, z), its axis along the crossover from c0 to c1."""
        direction = FreeCAD.Vector(1, 0, 0) if self.along_y else FreeCAD.Vector(0, 1, 0)
        return Part.makeCylinder(radius, c1 - c0, self.point(r, c0, z), direction)


def wheel_sweep(axes: str, reversals: tuple, cross: tuple, face_z: float, start_z: float, safe_z: float,
                radius: float) -> List[Part.Shape]:
    """The solids that hold what the wheel's body sweeps (see the module notes); ``reversals`` (I, X) along
    the reciprocation, ``cross`` the span of the wheel's width along the crossover."""
    frame = Frame(axes)
    (i, x), (c0, c1) = sorted(reversals), cross
    low = face_z + CLEAR_ABOVE_MM
    centre = low + radius
    solids = [frame.disc(i, centre, radius, c0, c1), frame.disc(x, centre, radius, c0, c1),
              frame.box(i, x, c0, c1, low, centre),
              frame.box(i - radius, x + radius, c0, c1, centre, max(start_z, low) + radius)]
    for end in (i, x):
        solids.append(frame.box(end - radius, end + radius, c0, c1, centre, safe_z + radius))
    return [s for s in solids if s is not None]


def check_wheel_body(job: object, face_name: str, sweep: List[Part.Shape], diameter: float) -> None:
    """GrindInputError (naming Base and Overtravel) when a model of ``job`` enters the wheel's ``sweep``."""
    for model in job.Model.Group:
        shape = getattr(model, "Shape", None)
        if shape is None or shape.isNull():
            continue
        if sum(shape.common(solid).Volume for solid in sweep) > MIN_VOLUME_MM3:
            raise GrindInputError(
                "Base: the wheel's body (diameter %g) meets %s beside %s: a wall within the wheel's radius of a "
                "reversal point (reduce Overtravel, grind with a smaller wheel, or grind another face)"
                % (diameter, modelled_part(job, model).Label, face_name), ("Base", "Overtravel"))
