"""A Job's tool controllers as a LinuxCNC tool table (layer 2: no Qt).

    text = linuxcnc_tool_table_of(job)   # engine/output/lathe_tools.py's format

Each tool controller of the Job gives one line, by its ToolNumber:

* a grooving blade (a tool bit with Width and CornerRadius): its orientation Q
  from the Groove ops that cut with it: each op's ReferenceCorner and where it
  cuts (its TYP: 5 longitudinal external -> external, 7 -> internal, 6 and 8
  face grooves -> face); ops that disagree (one tool, two orientations) are an
  error naming them, as is a blade no Groove op uses (its side unknown);
* any other tool (an end mill, a grinding wheel): its Diameter as D, no Q.

Lengths in mm (FreeCAD's internal unit). ToolTableError names the tool
controller and what is wrong.
"""

from typing import Dict, List, Tuple

from ..engine.errors import ProgramError
from ..engine.moves import GroovingTool
from ..engine.numbers import format_value
from ..engine.output.lathe_tools import ToolLine, blade_line, linuxcnc_lines
from .units import length_mm

__all__ = ["ToolTableError", "linuxcnc_tool_table_of"]

SIDE_OF_TYP = {5: "external", 7: "internal", 6: "face", 8: "face"}  # TYP % 10: the add-on's grooves are 'right'


class ToolTableError(ValueError):
    """A Job whose tools cannot be written as a tool table: the message names the tool controller."""


def _uses(job) -> Dict[str, List[object]]:
    """Tool controller name -> the Job's ops that cut with it."""
    uses: Dict[str, List[object]] = {}
    for op in getattr(getattr(job, "Operations", None), "Group", []):
        controller = getattr(op, "ToolController", None)
        if controller is not None:
            uses.setdefault(controller.Name, []).append(op)
    return uses


def _blade_line(controller, bit, ops) -> ToolLine:
    """The tool line of a grooving blade, its orientation from the Groove ops using it."""
    grooves = [op for op in ops if hasattr(op, "ReferenceCorner") and hasattr(op, "TYP")]
    if not grooves:
        raise ToolTableError("%s: no Groove op cuts with its grooving blade, so where it cuts (its orientation Q) "
                             "is unknown; add the op, or leave the tool controller out of the Job"
                             % controller.Label)
    cuts: Dict[Tuple[str, str], List[str]] = {}
    for op in grooves:
        side = SIDE_OF_TYP.get(int(op.TYP) % 10)
        if side is None:
            raise ToolTableError("%s: the Groove op %s has no groove yet (TYP %d): recompute it" % (
                controller.Label, op.Label, int(op.TYP)))
        cuts.setdefault((str(op.ReferenceCorner), side), []).append(op.Label)
    if len(cuts) > 1:
        raise ToolTableError("%s: its ops cut with it in %d ways (%s); a tool has one orientation in LinuxCNC's "
                             "table: give each way its own tool controller and tool number" % (
                                 controller.Label, len(cuts), "; ".join("%s %s: %s" % (ref, side, ", ".join(labels))
                                                                        for (ref, side), labels in cuts.items())))
    (reference, side), = cuts
    blade = GroovingTool(length_mm(bit.Width), length_mm(bit.CornerRadius), reference)
    return blade_line(int(controller.ToolNumber), blade, side, "mm")


def _round_line(controller, bit) -> ToolLine:
    diameter = length_mm(bit.Diameter)
    return ToolLine(int(controller.ToolNumber), diameter, None, "%s, diameter %s mm" % (
        bit.Label, format_value(diameter)))


def linuxcnc_tool_table_of(job) -> str:
    """The LinuxCNC tool table of ``job``'s tool controllers (module notes)."""
    uses = _uses(job)
    lines, numbers = [], {}
    for controller in getattr(getattr(job, "Tools", None), "Group", []):
        bit = getattr(controller, "Tool", None)
        if bit is None:
            raise ToolTableError("%s: it has no tool bit" % controller.Label)
        number = int(controller.ToolNumber)
        if number in numbers:
            raise ToolTableError("%s: tool number %d is %s's too; a table has one line a number"
                                 % (controller.Label, number, numbers[number]))
        numbers[number] = controller.Label
        if hasattr(bit, "Width") and hasattr(bit, "CornerRadius"):
            lines.append(_blade_line(controller, bit, uses.get(controller.Name, [])))
        elif hasattr(bit, "Diameter"):
            lines.append(_round_line(controller, bit))
        else:
            raise ToolTableError("%s: its tool bit %s has no Diameter nor blade Width" % (controller.Label, bit.Label))
    try:
        return linuxcnc_lines(lines, "mm", "the Job %s" % job.Label)
    except ProgramError as exc:
        raise ToolTableError(str(exc)) from None
