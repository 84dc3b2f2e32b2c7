"""Whether the Groove op's grooving blade reaches the groove's bottom.

A grooving blade (the add-on's tool bit: resources/tools/grooving.fcstd,
freecad/toolbit.py) cuts down to its free reach, its tool bit's
``CuttingEdgeHeight`` ("Cutting depth (free reach)", default 12 mm); deeper,
its holder hits the part. The op refuses a groove whose Depth (along the
plunge: radial for longitudinal grooves, along Z for face grooves) is more
than that, naming Depth and CuttingEdgeHeight (README "The blade's reach").
A tool bit without a Width is no grooving blade (an end mill of a new Job:
the op then takes ToolWidth) and is not checked; nor is a blade whose
CuttingEdgeHeight is 0 (unknown).

FreeCAD layer: reads a tool bit's properties, no Part.
"""

from ...engine.numbers import format_value
from ...freecad.units import length_mm
from .properties import GrooveInputError

TOLERANCE_MM = 1e-9


def check_reach(obj: object) -> None:
    """GrooveInputError naming Depth when the groove is deeper than the grooving blade's free reach (its tool
    bit's CuttingEdgeHeight): the holder would hit the part. Only a grooving blade (a bit with a Width) is
    checked, and only when its CuttingEdgeHeight is given (not 0)."""
    bit = getattr(getattr(obj, "ToolController", None), "Tool", None)
    if bit is None or getattr(bit, "Width", None) is None or getattr(bit, "CuttingEdgeHeight", None) is None:
        return
    reach = length_mm(bit.CuttingEdgeHeight)
    depth = length_mm(obj.Depth)
    if reach > 0 and depth > reach + TOLERANCE_MM:
        raise GrooveInputError(
            "Depth=%s mm: deeper than the blade's free reach, CuttingEdgeHeight=%s mm of %s: its holder would hit "
            "the part (use a blade that reaches %s mm, or groove less deep)"
            % (format_value(depth), format_value(reach), getattr(bit, "Label", "the tool bit"), format_value(depth)),
            ("Depth",))
