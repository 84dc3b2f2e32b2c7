"""The Cylinder slot operation: a slot milled on a cylinder by a live end mill
on a lathe with a C axis (a helical oil groove, a barrel-cam track, a keyway
on the circumference), as a GSK ``G7.1`` Type II roughing cycle.

Headless layer: FreeCAD, Part and Path only. The class path
``freecad_groove.ops.slot.op.ObjectCylinderSlot`` is stored in every document
saved since the ops moved here; documents saved before store
``freecad_groove.freecad.cylinder_slot_op.ObjectCylinderSlot``, which that
module keeps as a shim. Neither may move.

Base holds one cylindrical face about the Job's Z axis and the edges of the
slot's centre line on it, in order (developed.py develops them into Z and C).
The end mill's diameter is the slot's width: the op drives its centre along
the path. The region (engine/cycles/gsk_g7_1.py) is built from the op:

    G7.1 C(radius) J(-2 Depth) R(2 Retract) K(2 Allowance) L(Passes)
    G1 Z.. C.. F(feed) ... (the developed path)   G7.1 C0

Depth, Retract and Allowance are radial (mm, as the model is measured); the
program's J, R, K are diameters. The feed is the tool controller's HorizFeed
(along the developed path), the live tool's speed its SpindleSpeed; where they
are 0 (a new Job's), the documented defaults of cutting.py, shown in the
read-only FeedsAndSpeeds.

The Path (path.py): from the safe radius (the largest radius of the model
and the stock plus Retract) to the path's start, the region's moves, back to
the safe radius.

Errors never escape execute (as in the Groove op): one line "<Label>: <message>"
in the report view, a Path of one comment with it, the message kept for the
posts (op_error).
"""

import math
from typing import List, Tuple

import FreeCAD
import Part
import PathScripts.PathUtils as PathUtils

from ...engine.cycles.gsk_g7_1 import GskG7_1
from ...engine.moves import MachineState
from ...freecad.addon_op import AddonOp, WithValues, create_op, modelled_part, op_error  # noqa: F401 - its API
from ...freecad.bounds import check_bounds
from ...freecad.faces import element_name
from ...freecad.units import length_mm
from . import reach
from .cutting import slot_cutting
from .developed import SlotCylinder, developed_path, read_cylinder
from .path import path_commands
from .plan import SlotPlan, region_blocks, rounded
from .properties import BOUNDS, DERIVED, GROUP, LENGTHS, PROPERTIES, SlotInputError, finite_length


class ObjectCylinderSlot(AddonOp):
    """Proxy of a Cylinder slot operation (Path::FeaturePython)."""

    FEATURES = ("FeatureTool", "FeatureBaseFaces", "FeatureBaseEdges", "FeatureCoolant")
    DECLARED_PROPERTIES = tuple((type_id, name, GROUP, tip, default) for type_id, name, tip, default in PROPERTIES)

    # -- FreeCAD op API ---------------------------------------------------------
    def _add_missing_properties(self, obj: object) -> None:
        super()._add_missing_properties(obj)
        for name in DERIVED:
            obj.setEditorMode(name, 1)

    def opExecute(self, obj: object) -> None:
        self.error = None
        self._plan = None
        try:
            plan = self.plan(obj)
        except Exception as e:  # CycleError and input errors are ValueErrors; anything else too
            self._report_error(obj, e)
            return
        self._plan = plan
        self._write_derived(obj, plan.region.emit().split("\n")[0], self.tool_diameter(obj), plan.cutting.describe())
        for warning in plan.warnings:
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, warning))
        self.commandlist.extend(path_commands(plan))

    def _report_error(self, obj: object, error: Exception) -> None:
        self._write_derived(obj, "", 0.0, "")
        self.report_error(obj, error)

    @staticmethod
    def _write_derived(obj: object, region: str, width: float, feeds: str) -> None:
        if obj.Region != region:
            obj.Region = region
        if obj.FeedsAndSpeeds != feeds:
            obj.FeedsAndSpeeds = feeds
        if abs(length_mm(obj.SlotWidth) - width) > 1e-12:
            obj.SlotWidth = width

    # -- the plan -----------------------------------------------------------------
    def current_plan(self, obj: object) -> SlotPlan:
        """The plan of the last recompute while nothing touched the op since, else a new one (the posts)."""
        plan = getattr(self, "_plan", None)
        if plan is not None and getattr(self, "error", None) is None and not ({"Touched", "Invalid"} & set(obj.State)) \
                and not self.tool_changed(obj):
            return plan
        return self.plan(obj)

    def picked(self, obj: object) -> Tuple[Tuple[object, str], List[Tuple[object, str]]]:
        """((face, "Label.FaceN"), [(edge, "Label.EdgeN"), ...]) from Base; SlotInputError when not one face."""
        job = PathUtils.findParentJob(obj)
        faces, edges = [], []
        for base, subs in obj.Base or []:
            try:
                named = modelled_part(job, base)
            except ValueError as e:
                raise SlotInputError(str(e), ("Base",)) from None
            for sub in (subs,) if isinstance(subs, str) else subs:
                name = element_name(named, sub or "(whole object)")
                try:
                    shape = base.Shape.getElement(sub)
                except Exception:
                    raise SlotInputError("Base: %s: no such face or edge in the model" % name, ("Base",)) from None
                (faces if sub.startswith("Face") else edges if sub.startswith("Edge") else []).append((shape, name))
        if len(faces) != 1:
            raise SlotInputError("Base: %d faces picked: pick the one cylindrical face the slot is cut in"
                                   % len(faces), ("Base",))
        return faces[0], edges

    def tool_diameter(self, obj: object) -> float:
        """The end mill's Diameter in mm (0 without one; SlotInputError when it is not a finite length)."""
        tool = getattr(getattr(obj, "ToolController", None), "Tool", None)
        return (reach.bit_length(tool, "Diameter") or 0.0) if tool is not None else 0.0

    def region(self, obj: object, cylinder: SlotCylinder, points: list, feed: float) -> GskG7_1:
        depth, allowance, retract = (finite_length(obj, n) for n in ("Depth", "Allowance", "Retract"))
        if not depth > 0:
            raise SlotInputError("Depth=%s: must be greater than 0" % depth, ("Depth",))
        if not allowance < depth:
            raise SlotInputError("Allowance=%s: must be less than Depth=%s" % (allowance, depth), ("Allowance",))
        if not retract > 0:
            raise SlotInputError("Retract=%s: must be greater than 0 (the tool retracts above the cylinder)"
                                   % retract, ("Retract",))
        if not 1 <= obj.Passes <= 9999:
            raise SlotInputError("Passes=%s: must be from 1 to 9999" % obj.Passes, ("Passes",))
        blocks = region_blocks(points, feed)
        return GskG7_1(C=rounded(cylinder.radius), path=blocks, J=rounded(-2.0 * depth), R=rounded(2.0 * retract),
                      K=rounded(2.0 * allowance), L=int(obj.Passes))

    def plan(self, obj: object) -> SlotPlan:
        """The region and its moves (SlotInputError/CycleError naming what is wrong)."""
        check_bounds(obj, BOUNDS, SlotInputError)
        (face, face_name), edges = self.picked(obj)
        cylinder = read_cylinder(face, face_name)
        sketch = getattr(obj, "DevelopedSketch", None)
        if sketch is not None:
            if edges:
                raise SlotInputError("Base: edges picked and a DevelopedSketch given: the path is one or the "
                                       "other", ("Base", "DevelopedSketch"))
            edges = sketch_edges(sketch)
        tool_radius = self.tool_diameter(obj) / 2.0
        points = developed_path(cylinder, face, edges, sketch=sketch is not None, margin=tool_radius)
        cutting = slot_cutting(obj)
        region = self.region(obj, cylinder, points, cutting.feed)
        tool = getattr(obj.ToolController, "Tool", None)  # region() refused an op without a tool controller
        tool_name = getattr(tool, "Label", obj.ToolController.Label)
        reach.check_tool(tool, tool_name, -region.J / 2.0)
        self.check_tool(obj)
        first = region.path[0]
        start = MachineState(x=region.clearance_radius(), z=rounded(points[0][0]), c=rounded(points[0][1]),
                             feed=first.f)
        moves = region.expand(start)
        largest = max(self.largest_radius(obj), cylinder.radius)
        warnings = reach.reach_warnings(tool, tool_name, cylinder.radius, -region.J / 2.0, largest) + \
            reach.z_range_warnings([z for z, _c in points], tool_radius, (cylinder.z_min, cylinder.z_max),
                                        cylinder.name)
        safe = largest + finite_length(obj, "Retract")
        return SlotPlan(cylinder, region, start, max(safe, start.x), moves, tuple(warnings), cutting)

    def plan_with(self, obj: object, values: dict) -> SlotPlan:
        """plan() as it would be with ``values`` {property: value (mm, a count, an object)} in place of the
        op's own (the task panel's preview); the document is not touched."""
        wrapped = {name: FreeCAD.Units.Quantity(float(value), FreeCAD.Units.Length) if name in LENGTHS else value
                   for name, value in values.items()}
        return self.plan(WithValues(obj, wrapped))

    def largest_radius(self, obj: object) -> float:
        """The largest radius of the Job's model and stock (their bounding boxes)."""
        job = PathUtils.findParentJob(obj)
        shapes = [m.Shape for m in getattr(getattr(job, "Model", None), "Group", [])]
        stock = getattr(job, "Stock", None)
        if stock is not None and hasattr(stock, "Shape"):
            shapes.append(stock.Shape)
        radius = 0.0
        for shape in shapes:
            box = shape.BoundBox
            if box.isValid():
                radius = max(radius, math.hypot(max(abs(box.XMin), abs(box.XMax)), max(abs(box.YMin), abs(box.YMax))))
        return radius


def sketch_edges(sketch: object) -> List[Tuple[object, str]]:
    """The sketch's edges in its own coordinates, sorted into a chain, named "Label.EdgeN"."""
    shape = sketch.Shape.copy()
    shape.transformShape(sketch.Placement.inverse().toMatrix())
    edges = Part.__sortEdges__(shape.Edges)
    if not edges:
        raise SlotInputError("DevelopedSketch: %s has no edges" % sketch.Label, ("DevelopedSketch",))
    return [(edge, "%s.Edge%d" % (sketch.Label, i + 1)) for i, edge in enumerate(edges)]


def SetupProperties() -> list:
    """The op properties a Job's SetupSheet may hold defaults for: the region's Depth, Passes, Allowance and
    Retract (not DevelopedSketch: a link to one sketch is no default for every slot, and CAM's SetupSheet
    editor has no editor for a link)."""
    return [name for _t, name, _tip, _d in PROPERTIES if name not in DERIVED + ("DevelopedSketch",)]


def Create(name: str, obj: object = None, parentJob: object = None, tool_controller: object = None) -> object:
    """A Cylinder slot op (Path::FeaturePython with an ObjectCylinderSlot proxy) in ``parentJob``; with the GUI
    up, its view provider (gui/view.py, bound to its kind by the GUI: ops/registry.py)."""
    return create_op(ObjectCylinderSlot, name, obj, parentJob, tool_controller)
