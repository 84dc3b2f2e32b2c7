"""Whether the Groove op's grooving blade reaches the groove's bottom, and whether its holder fits where it cuts.

A grooving blade (the add-on's tool bit: resources/tools/grooving.fcstd,
freecad/toolbit.py) cuts down to its free reach, its tool bit's
``CuttingEdgeHeight`` ("Cutting depth (free reach)", default 12 mm); deeper,
its holder hits the part. The op refuses a groove whose Depth (along the
plunge: radial for longitudinal grooves, along Z for face grooves) is more
than that, naming Depth and CuttingEdgeHeight (README "The blade's reach").
A tool bit without a Width is no grooving blade (an end mill of a new Job:
the op then takes ToolWidth) and is not checked; nor is a blade whose
CuttingEdgeHeight is 0 (unknown).

A face-grooving blade's first-cut diameter range and an internal bar's
smallest bore (the tool bit's FirstCutDiameterMin, FirstCutDiameterMax,
MinBoreDiameter: freecad/blade_holder.py; 0 = not given, not checked) are
checked on the planned grooves (check_holder_limits): each face groove's
first plunge must cut diameters inside the range, each internal longitudinal
groove's bore be at least the smallest bore (engine/blade_limits.py).

FreeCAD layer: reads a tool bit's properties, no Part.
"""

from ...engine.blade_limits import limits_problem
from ...engine.numbers import format_value
from ...freecad.blade_holder import blade_limits
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


def check_holder_limits(obj: object, plans: list) -> None:
    """GrooveInputError when a planned groove (``plans``: GroovePlan) lies outside what the blade's holder allows:
    a face groove's first plunge outside its first-cut diameter range (naming Position), an internal groove's
    bore smaller than its smallest bore (naming Base). Only what the tool bit gives is checked."""
    bit = getattr(getattr(obj, "ToolController", None), "Tool", None)
    limits = blade_limits(bit) if bit is not None and getattr(bit, "Width", None) is not None else None
    if limits is None:
        return
    blade = getattr(bit, "Label", "the tool bit")
    for plan in plans:
        entry = plan.cycle.blade_entry(plan.start, plan.settings, plan.moves)
        problem = limits_problem(entry, limits, blade)
        if problem is not None:
            where = "Position" if entry.bore is None else "Base"
            raise GrooveInputError("%s; the groove at Position=%s mm of %s"
                                   % (problem, format_value(plan.position), plan.face.name), (where,))
