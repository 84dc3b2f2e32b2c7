"""The Cylinder slot operation: a slot milled on a cylinder by a live end mill
on a lathe with a C axis (a helical oil groove, a barrel-cam track, a keyway
on the circumference), as a GSK ``G7.1`` Type II roughing cycle.

Headless layer: FreeCAD, Part and Path only. The class path
``freecad_groove.freecad.cylinder_slot_op.ObjectCylinderSlot`` is stored in
every saved document: it must never move.

Base holds one cylindrical face about the Job's Z axis and the edges of the
slot's centre line on it, in order (slot_path.py develops them into Z and C).
The end mill's diameter is the slot's width: the op drives its centre along
the path. The region (engine/cycles/gsk_g71.py) is built from the op:

    G7.1 C(radius) J(-2 Depth) R(2 Retract) K(2 Allowance) L(Passes)
    G1 Z.. C.. F(feed) ... (the developed path)   G7.1 C0

Depth, Retract and Allowance are radial (mm, as the model is measured); the
program's J, R, K are diameters. The feed is the tool controller's HorizFeed
(along the developed path; an error when it is 0: no silent default).

The Path: a comment naming the face and the region (its start block), G18,
G0 X to the safe radius (the largest radius of the model and the stock plus
Retract), G0 Z C to the path's start, the region's moves (G0/G1 with X, Z, C;
F in FreeCAD's mm/s: for a move that turns C only it is the engine's degrees
per minute over 60), then G0 X back to the safe radius.

Errors never escape execute (as in groove_op): one line "<Label>: <message>"
in the report view, a Path of one comment with it, the message kept for the
posts (op_error).
"""

import math
from typing import List, NamedTuple, Optional, Tuple

import FreeCAD
import Part
import Path
import PathScripts.PathUtils as PathUtils

from ..engine.cycles.gsk_g71 import DECIMALS, GskG71, PathBlock
from ..engine.moves import FEED, RAPID, MachineState, Move
from . import slot_reach
from .addon_op import AddonOp, create_op, register_op_kind
from .faces import element_name
from .groove_op import _WithValues  # an op seen with the panel's values (the same wrapper as the Groove panel's)
from .groove_properties import GrooveInputError
from .op_path import comment_body
from .slot_path import SlotCylinder, developed_path, read_cylinder
from .units import SECONDS_PER_MINUTE, feed_mm_per_min, length_mm

OP_NAME = "CylinderSlot"  # the op's kind in CAM's SetupSheet registry
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
)
DERIVED = ("SlotWidth", "Region")
LENGTHS = tuple(name for type_id, name, _tip, _default in PROPERTIES if type_id == "App::PropertyLength")


class SlotPlan(NamedTuple):
    """What the op cuts: the region, where it starts, the safe radius and the moves."""

    cylinder: SlotCylinder
    region: GskG71
    start: MachineState
    safe_radius: float
    moves: List[Move]
    warnings: Tuple[str, ...] = ()  # what the end mill may not do as planned (slot_reach): shown, never blocking


def op_error(obj: object) -> Optional[str]:
    """Why the op ``obj`` cut nothing at its last recompute (None: it is fine)."""
    error = getattr(getattr(obj, "Proxy", None), "error", None)
    if error:
        return error
    return None if obj.isValid() else obj.getStatusString()


def _number(obj: object, name: str) -> float:
    value = length_mm(getattr(obj, name))
    if not math.isfinite(value):
        raise GrooveInputError("%s=%s: must be a finite number" % (name, value), (name,))
    return value


def _rounded(value: float) -> float:
    return round(value, DECIMALS) + 0.0  # no -0.0


def region_blocks(points: List[Tuple[float, float]], feed: float) -> Tuple[PathBlock, ...]:
    """G1 blocks to each corner after the start; the words that change only; F on the first."""
    blocks, (z, c) = [], (_rounded(points[0][0]), _rounded(points[0][1]))
    for pz, pc in points[1:]:
        nz, nc = _rounded(pz), _rounded(pc)
        if (nz, nc) == (z, c):
            continue
        blocks.append(PathBlock("G1", z=nz if nz != z else None, c=nc if nc != c else None,
                                f=None if blocks else round(feed, 6)))
        z, c = nz, nc
    if not blocks:
        raise GrooveInputError("Base: the slot's path has no length on the developed surface", ("Base",))
    return tuple(blocks)


class ObjectCylinderSlot(AddonOp):
    """Proxy of a Cylinder slot operation (Path::FeaturePython)."""

    OP_NAME = OP_NAME
    FEATURES = ("FeatureTool", "FeatureBaseFaces", "FeatureBaseEdges", "FeatureCoolant")

    # -- FreeCAD op API ---------------------------------------------------------
    def _add_missing_properties(self, obj: object) -> None:
        for type_id, name, tooltip, default in PROPERTIES:
            if name not in obj.PropertiesList:
                obj.addProperty(type_id, name, GROUP, tooltip)
                if default is not None:
                    setattr(obj, name, default)
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
        self._write_derived(obj, plan.region.emit().split("\n")[0], self.tool_diameter(obj))
        for warning in plan.warnings:
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, warning))
        self.commandlist.extend(path_commands(plan))

    def _report_error(self, obj: object, error: Exception) -> None:
        self._write_derived(obj, "", 0.0)
        self.report_error(obj, error)

    @staticmethod
    def _write_derived(obj: object, region: str, width: float) -> None:
        if obj.Region != region:
            obj.Region = region
        if abs(length_mm(obj.SlotWidth) - width) > 1e-12:
            obj.SlotWidth = width

    # -- the plan -----------------------------------------------------------------
    def current_plan(self, obj: object) -> SlotPlan:
        """The plan of the last recompute while nothing touched the op since, else a new one (the posts)."""
        plan = getattr(self, "_plan", None)
        if plan is not None and getattr(self, "error", None) is None and not ({"Touched", "Invalid"} & set(obj.State)):
            return plan
        return self.plan(obj)

    def picked(self, obj: object) -> Tuple[Tuple[object, str], List[Tuple[object, str]]]:
        """((face, "Label.FaceN"), [(edge, "Label.EdgeN"), ...]) from Base; GrooveInputError when not one face."""
        job = PathUtils.findParentJob(obj)
        faces, edges = [], []
        for base, subs in obj.Base or []:
            named = job.Proxy.baseObject(job, base) if job is not None else base
            for sub in (subs,) if isinstance(subs, str) else subs:
                name = element_name(named, sub or "(whole object)")
                try:
                    shape = base.Shape.getElement(sub)
                except Exception:
                    raise GrooveInputError("Base: %s: no such face or edge in the model" % name, ("Base",)) from None
                (faces if sub.startswith("Face") else edges if sub.startswith("Edge") else []).append((shape, name))
        if len(faces) != 1:
            raise GrooveInputError("Base: %d faces picked: pick the one cylindrical face the slot is cut in"
                                   % len(faces), ("Base",))
        return faces[0], edges

    def tool_diameter(self, obj: object) -> float:
        tool = getattr(getattr(obj, "ToolController", None), "Tool", None)
        return length_mm(getattr(tool, "Diameter", 0.0)) if tool is not None else 0.0

    def feed_mm_per_min(self, obj: object) -> float:
        tc = getattr(obj, "ToolController", None)
        if tc is None:
            raise GrooveInputError("ToolController: none: the op needs an end mill's tool controller",
                                   ("ToolController",))
        feed = feed_mm_per_min(length_mm(tc.HorizFeed))
        if not (math.isfinite(feed) and feed > 0):
            raise GrooveInputError("HorizFeed=%s: the tool controller's feed must be greater than 0 (the slot is "
                                   "milled at it along its developed path)" % feed, ("ToolController",))
        return feed

    def region(self, obj: object, cylinder: SlotCylinder, points: list) -> GskG71:
        depth, allowance, retract = (_number(obj, n) for n in ("Depth", "Allowance", "Retract"))
        if not depth > 0:
            raise GrooveInputError("Depth=%s: must be greater than 0" % depth, ("Depth",))
        if not allowance < depth:
            raise GrooveInputError("Allowance=%s: must be less than Depth=%s" % (allowance, depth), ("Allowance",))
        if not retract > 0:
            raise GrooveInputError("Retract=%s: must be greater than 0 (the tool retracts above the cylinder)"
                                   % retract, ("Retract",))
        if not 1 <= obj.Passes <= 9999:
            raise GrooveInputError("Passes=%s: must be from 1 to 9999" % obj.Passes, ("Passes",))
        blocks = region_blocks(points, self.feed_mm_per_min(obj))
        return GskG71(C=_rounded(cylinder.radius), path=blocks, J=_rounded(-2.0 * depth), R=_rounded(2.0 * retract),
                      K=_rounded(2.0 * allowance), L=int(obj.Passes))

    def plan(self, obj: object) -> SlotPlan:
        """The region and its moves (GrooveInputError/CycleError naming what is wrong)."""
        (face, face_name), edges = self.picked(obj)
        cylinder = read_cylinder(face, face_name)
        sketch = getattr(obj, "DevelopedSketch", None)
        if sketch is not None:
            if edges:
                raise GrooveInputError("Base: edges picked and a DevelopedSketch given: the path is one or the "
                                       "other", ("Base", "DevelopedSketch"))
            edges = sketch_edges(sketch)
        tool_radius = self.tool_diameter(obj) / 2.0
        points = developed_path(cylinder, face, edges, sketch=sketch is not None, margin=tool_radius)
        region = self.region(obj, cylinder, points)
        tool = getattr(obj.ToolController, "Tool", None)  # region() refused an op without a tool controller
        tool_name = getattr(tool, "Label", obj.ToolController.Label)
        slot_reach.check_tool(tool, tool_name, -region.J / 2.0)
        first = region.path[0]
        start = MachineState(x=region.clearance_radius(), z=_rounded(points[0][0]), c=_rounded(points[0][1]),
                             feed=first.f)
        moves = region.expand(start)
        largest = max(self.largest_radius(obj), cylinder.radius)
        warnings = slot_reach.reach_warnings(tool, tool_name, cylinder.radius, -region.J / 2.0, largest) + \
            slot_reach.z_range_warnings([z for z, _c in points], tool_radius, (cylinder.z_min, cylinder.z_max),
                                        cylinder.name)
        safe = largest + _number(obj, "Retract")
        return SlotPlan(cylinder, region, start, max(safe, start.x), moves, tuple(warnings))

    def plan_with(self, obj: object, values: dict) -> SlotPlan:
        """plan() as it would be with ``values`` {property: value (mm, a count, an object)} in place of the
        op's own (the task panel's preview); the document is not touched."""
        wrapped = {name: FreeCAD.Units.Quantity(float(value), FreeCAD.Units.Length) if name in LENGTHS else value
                   for name, value in values.items()}
        return self.plan(_WithValues(obj, wrapped))

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
        raise GrooveInputError("DevelopedSketch: %s has no edges" % sketch.Label, ("DevelopedSketch",))
    return [(edge, "%s.Edge%d" % (sketch.Label, i + 1)) for i, edge in enumerate(edges)]


def path_commands(plan: SlotPlan) -> list:
    """The op's Path commands after its label (see the module notes)."""
    start = plan.start
    commands = [Path.Command(comment_body("%s: %s" % (plan.cylinder.name, plan.region.emit().split("\n")[0]))),
                Path.Command("G18"),
                Path.Command("G0", {"X": plan.safe_radius}),
                Path.Command("G0", {"Z": start.z, "C": start.c})]
    if plan.safe_radius != start.x:
        commands.append(Path.Command("G0", {"X": start.x}))
    for move in plan.moves:
        words = {"X": move.x, "Z": move.z, "C": move.c}
        if move.kind == FEED:
            words["F"] = move.f / SECONDS_PER_MINUTE
            commands.append(Path.Command("G1", words))
        elif move.kind == RAPID:
            commands.append(Path.Command("G0", words))
    commands.append(Path.Command("G0", {"X": plan.safe_radius}))
    return commands


def SetupProperties() -> list:
    return [name for _t, name, _tip, _d in PROPERTIES if name not in DERIVED]


def Create(name: str, obj: object = None, parentJob: object = None, tool_controller: object = None) -> object:
    """A Cylinder slot op (Path::FeaturePython with an ObjectCylinderSlot proxy) in ``parentJob``; with the GUI
    up, its view provider (gui/slot_view.py) through hooks."""
    return create_op(ObjectCylinderSlot, name, obj, parentJob, tool_controller, "slot_view_provider_factory")


register_op_kind(OP_NAME, SetupProperties)
