"""Whether the Cylinder slot op's end mill can cut the slot it is given.

FreeCAD layer (reads a tool bit's properties; no Part). The live end mill
points along X at the cylinder; the rules (docs/cylinder-slot.md, its table):

- its Diameter is the slot's width: none (0) is an error;
- its flutes must reach the slot's bottom: Depth greater than the bit's
  CuttingEdgeHeight is an error (the shank would rub the walls);
- its holder must clear the part: with the tip at the slot's bottom the
  holder stands at (cylinder radius - Depth + Length); below the largest
  radius of the Job's model and stock (their bounding boxes) that is a
  warning (the bounding box may be a shoulder elsewhere along Z);
- a bit with neither CuttingEdgeHeight nor Length: a warning that the reach
  is not checked (no silent assumption);
- the slot's width along Z: the centre line may leave the face's Z range by
  at most the end mill's radius (a sketch's path; edges lie on the face by
  definition), more is an error (developed.py); a slot whose side runs past the
  face's Z end (the end mill cutting past it, into air or a shoulder) is a
  warning naming by how much.
"""

import math
from typing import List, Optional, Tuple

from ...freecad.units import length_mm
from .properties import MAX_LENGTH_MM, SlotInputError

TOLERANCE = 1e-6  # mm


def bit_length(tool: object, name: str) -> Optional[float]:
    """The tool bit's length property ``name`` in mm, or None when it has none (or 0)."""
    value = getattr(tool, name, None) if tool is not None else None
    if value is None:
        return None
    value = length_mm(value)
    if not (math.isfinite(value) and value < MAX_LENGTH_MM):
        raise SlotInputError("ToolController: the tool bit's %s=%s: must be a length below %g mm"
                             % (name, value, MAX_LENGTH_MM), ("ToolController",))
    return value if value > 0 else None


def _mm(value: float) -> str:
    return "%g mm" % round(value, 4)


def check_tool(tool: object, tool_name: str, depth: float) -> None:
    """SlotInputError when the end mill has no diameter or its flutes are shorter than ``depth``."""
    if bit_length(tool, "Diameter") is None:
        raise SlotInputError("ToolController: %s has no Diameter: the end mill's diameter is the slot's width"
                               % tool_name, ("ToolController",))
    flutes = bit_length(tool, "CuttingEdgeHeight")
    if flutes is not None and depth > flutes + TOLERANCE:
        raise SlotInputError("Depth=%s: deeper than the cutting edge of %s (CuttingEdgeHeight=%s): the shank "
                               "would rub the slot's walls" % (_mm(depth), tool_name, _mm(flutes)), ("Depth",))


def reach_warnings(tool: object, tool_name: str, radius: float, depth: float, largest_radius: float) -> List[str]:
    """The holder-clearance warning (or that the reach is not checked) of check_tool's end mill."""
    length = bit_length(tool, "Length")
    if length is None:
        if bit_length(tool, "CuttingEdgeHeight") is None:
            return ["%s has neither CuttingEdgeHeight nor Length: the end mill's reach is not checked" % tool_name]
        return []
    holder = radius - depth + length
    if holder < largest_radius - TOLERANCE:
        return ["%s (Length=%s) at the slot's bottom (radius %s) has its holder at radius %s, inside the part's "
                "largest radius %s (model and stock): check that the holder clears the part"
                % (tool_name, _mm(length), _mm(radius - depth), _mm(holder), _mm(largest_radius))]
    return []


def z_range_warnings(z_values: List[float], tool_radius: float, face_range: Tuple[float, float],
                     face_name: str) -> List[str]:
    """A warning for each Z end of the face that the slot's side (centre line +- the tool radius) runs past."""
    low, high = min(z_values) - tool_radius, max(z_values) + tool_radius
    out = []
    if low < face_range[0] - TOLERANCE:
        out.append("the slot runs %s past the Z%g end of %s (the end mill cuts beyond the face)"
                   % (_mm(face_range[0] - low), round(face_range[0], 4), face_name))
    if high > face_range[1] + TOLERANCE:
        out.append("the slot runs %s past the Z%g end of %s (the end mill cuts beyond the face)"
                   % (_mm(high - face_range[1]), round(face_range[1], 4), face_name))
    return out
