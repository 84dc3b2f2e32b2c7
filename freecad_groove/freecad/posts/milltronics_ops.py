"""Which CAM ops the ``milltronics_mill`` post writes as a Milltronics autoroutine, and the call for each.

CAM's own Face op (Path.Op.MillFace.ObjectFace) becomes one ``G33`` (facing),
its Pocket Shape op (Path.Op.PocketShape.ObjectPocket) one ``G34``
(rectangular pocket), when the autoroutine cuts what the op's own Path cuts:

- the area: the op's removal shape (what CAM clears, BoundaryShape,
  ClearEdges and extensions included) cut across is one outline, a rectangle
  along X and Y (G34: its corners may be quarter arcs of one radius, P150);
  the tool's edge touches the outline, as in the engine's expansion, and
  the bound box of the op's Path is the outline less the tool's radius;
- the depths: V = the highest and Z = the lowest Z level at which the op's
  Path cuts across X-Y, Q = StepDown: V, V - Q, ... Z must be the levels of
  the Path (a FinishDepth or any other pattern of depths differs). Z is what
  the Path cuts, not FinalDepth: they differ where CAM stops above it
  (FreeCAD 1.0's Face op never cuts its last depth: floor_note); R =
  SafeHeight;
- the pattern: G33 goes back and forth along the long side (ClearingPattern
  ZigZag, ZigZagAngle 0 for X, 90 for Y); G34 laps from the centre outward
  (Offset, StartAt Center), CutMode Climb = G41, Conventional = G42 with the
  spindle Forward (M3); no StartPoint, no ExtraOffset, no rest machining;
  G33's Path starts its cut at the upper right corner (as CAM's ZigZag at
  0 degrees does);
- the tool: an end mill; P155 = StepOver % x its diameter (at most the
  diameter); F = the tool controller's VertFeed, the X-Y feed its HorizFeed;
- the engine's own rules (engine/cycles/milltronics.py) hold.

Anything else is a reason (one line, no parentheses: it goes into a comment)
for writing the op as moves. Lengths come out in the program's units (mm, or
inches with ``inches``), feeds per minute.
"""

import math
from typing import Any, List, NamedTuple, Optional, Tuple, Union

from ...engine.cycles.milltronics import G33, G34, MilltronicsCycle
from ...engine.errors import CycleError
from ...engine.moves import MachineState, Move
from ...engine.native import NotNative  # why an op is written as moves: the project's one reason type
from ...engine.numbers import MM_PER_INCH
from ...engine.settings import Settings
from ..units import SECONDS_PER_MINUTE

FACE_OP = ("Path.Op.MillFace", "ObjectFace")
POCKET_OP = ("Path.Op.PocketShape", "ObjectPocket")
LENGTH_TOL = 1e-3  # mm: CAM writes its depths with a few 1e-6 mm of noise
ANGLE_TOL = 1e-6  # degrees / radians
MOTION = {"G1": "G1", "G01": "G1", "G2": "G2", "G02": "G2", "G3": "G3", "G03": "G3"}
REACH_TOL = 0.01  # mm: how far the op's Path may end from where the cycle's tool centre turns
DECIMALS = {False: 3, True: 4}  # the P parameters and words: mm, inch


class Rectangle(NamedTuple):
    """An axis-aligned rectangle (mm): centre, sizes, corner radius."""

    cx: float
    cy: float
    size_x: float
    size_y: float
    corner: float


class NativeOp(NamedTuple):
    """An op written as an autoroutine: the call and where it starts, in the program's units."""

    label: str
    call: MilltronicsCycle
    note: Optional[str]  # floor_note
    x: float  # the rectangle's centre: the cycle starts over it
    y: float
    clearance: float  # the op's ClearanceHeight: Z over the centre before the call
    xy_feed: float
    moves: List[Move]  # the engine's expansion (the proof that it can be cut)


def _value(quantity: Any) -> float:
    return float(getattr(quantity, "Value", quantity))


def proxy_kind(op: Any) -> Optional[str]:
    """"G33" for CAM's Face op, "G34" for its Pocket Shape op, else None."""
    proxy = type(getattr(op, "Proxy", None))
    key = (proxy.__module__, proxy.__name__)
    return {FACE_OP: "G33", POCKET_OP: "G34"}.get(key)


def tool_shape(tool: Any) -> str:
    """The tool bit's shape name, lower case ("endmill"): 1.1's ShapeType, 1.0's ShapeName or BitShape file."""
    for name in ("ShapeType", "ShapeName"):
        value = getattr(tool, name, None)
        if value:
            return str(value).lower()
    bit_shape = str(getattr(tool, "BitShape", "") or "")
    return bit_shape.replace("\\", "/").rsplit("/", 1)[-1].rsplit(".", 1)[0].lower()


def _tool_diameter(op: Any) -> float:
    controller = getattr(op, "ToolController", None)
    tool = getattr(controller, "Tool", None)
    if tool is None:
        raise NotNative("the op has no tool controller")
    shape = tool_shape(tool)
    if shape != "endmill":
        raise NotNative("the tool is a %s: G33/G34 cut with an end mill" % (shape or "tool of unknown shape"))
    diameter = _value(getattr(tool, "Diameter", 0.0))
    if not diameter > 0:
        raise NotNative("the tool's Diameter is %g" % diameter)
    return diameter


def _edge_kind(edge: Any) -> str:
    return type(edge.Curve).__name__


def rectangle_of(shape: Any) -> Rectangle:
    """The rectangle a removal shape clears, cut across halfway up; NotNative when it is not one."""
    if shape is None or shape.isNull():
        raise NotNative("the op has no removal shape: recompute it")
    box = shape.BoundBox
    import FreeCAD
    import Part

    wires = shape.slice(FreeCAD.Vector(0, 0, 1), (box.ZMin + box.ZMax) / 2.0)
    if len(wires) != 1:
        raise NotNative("the area is %d outlines: the cycle clears one rectangle" % len(wires))
    wire = wires[0]
    arcs = []
    for edge in wire.Edges:
        kind = _edge_kind(edge)
        start, end = edge.Vertexes[0].Point, edge.Vertexes[-1].Point
        if kind in ("Line", "LineSegment"):
            if abs(start.x - end.x) > LENGTH_TOL and abs(start.y - end.y) > LENGTH_TOL:
                raise NotNative("an edge of the area is not along X or Y")
        elif kind == "Circle" and abs(abs(edge.LastParameter - edge.FirstParameter) - math.pi / 2) < ANGLE_TOL:
            arcs.append(edge.Curve.Radius)
        else:
            raise NotNative("the area is not a rectangle: an edge is a %s" % kind)
    corner = arcs[0] if arcs else 0.0
    if len(arcs) not in (0, 4) or any(abs(r - corner) > LENGTH_TOL for r in arcs):
        raise NotNative("the area's corners are not four arcs of one radius")
    wire_box = wire.BoundBox
    expected = wire_box.XLength * wire_box.YLength - (4 - math.pi) * corner ** 2
    area = Part.Face(wire).Area
    if abs(area - expected) > LENGTH_TOL * (wire_box.XLength + wire_box.YLength):
        raise NotNative("the area is not a rectangle along X and Y")
    if abs(shape.Volume - area * box.ZLength) > LENGTH_TOL * (wire_box.XLength + wire_box.YLength) * box.ZLength:
        raise NotNative("the area changes with depth: the cycle clears one rectangle at every depth")
    return Rectangle(wire_box.Center.x, wire_box.Center.y, wire_box.XLength, wire_box.YLength, corner)


def path_depths(op: Any) -> Tuple[float, ...]:
    """The Z levels (mm, highest first) at which the op's Path feeds across X-Y."""
    where = {"X": None, "Y": None, "Z": None}
    levels: List[float] = []
    for command in op.Path.Commands:
        params = command.Parameters
        before = dict(where)
        where.update({axis: params[axis] for axis in "XYZ" if axis in params})
        if command.Name not in MOTION or before["Z"] is None:
            continue
        flat = abs(where["Z"] - before["Z"]) <= LENGTH_TOL
        moved = any(before[a] is not None and abs(where[a] - before[a]) > LENGTH_TOL for a in "XY")
        if flat and moved and not any(abs(where["Z"] - level) <= LENGTH_TOL for level in levels):
            levels.append(where["Z"])
    return tuple(sorted(levels, reverse=True))


def _arc_extremes(start: Tuple[float, float], end: Tuple[float, float], params: Any,
                  clockwise: bool) -> List[Tuple[float, float]]:
    """The points of an X-Y arc (I, J from its start) furthest along +X, +Y, -X, -Y that lie on it."""
    cx, cy = start[0] + params.get("I", 0.0), start[1] + params.get("J", 0.0)
    radius = math.hypot(start[0] - cx, start[1] - cy)
    a0, a1 = math.atan2(start[1] - cy, start[0] - cx), math.atan2(end[1] - cy, end[0] - cx)
    sweep = (a0 - a1 if clockwise else a1 - a0) % (2 * math.pi) or 2 * math.pi
    points = []
    for quarter in range(4):
        angle = quarter * math.pi / 2
        along = ((a0 - angle) if clockwise else (angle - a0)) % (2 * math.pi)
        if along <= sweep:
            points.append((cx + radius * math.cos(angle), cy + radius * math.sin(angle)))
    return points


def feed_box(op: Any) -> Optional[Tuple[float, float, float, float]]:
    """X min, X max, Y min, Y max (mm) of the op's feed moves (G1-G3, arcs included), None without any."""
    where = {"X": None, "Y": None, "Z": None}
    points: List[Tuple[float, float]] = []
    for command in op.Path.Commands:
        params = command.Parameters
        before = (where["X"], where["Y"])
        where.update({axis: params[axis] for axis in "XYZ" if axis in params})
        name = MOTION.get(command.Name)
        if name in ("G1", "G2", "G3") and None not in before and None not in (where["X"], where["Y"]):
            points += [before, (where["X"], where["Y"])]
            if name != "G1":
                points += _arc_extremes(before, (where["X"], where["Y"]), params, name == "G2")
    if not points:
        return None
    xs, ys = [x for x, _y in points], [y for _x, y in points]
    return min(xs), max(xs), min(ys), max(ys)


def _check_reach(op: Any, rect: Rectangle, diameter: float) -> None:
    """NotNative when the op's Path (its bound box in X-Y) does not reach the walls less the tool's radius, as
    the cycle does, or goes beyond."""
    box = feed_box(op)
    if box is None:
        raise NotNative("the op's Path cuts nothing")
    inset_x, inset_y = rect.size_x / 2.0 - diameter / 2.0, rect.size_y / 2.0 - diameter / 2.0
    cycle = (rect.cx - inset_x, rect.cx + inset_x, rect.cy - inset_y, rect.cy + inset_y)
    own = box
    if any(abs(a - b) > REACH_TOL for a, b in zip(own, cycle)):
        raise NotNative("the op's Path reaches X%s..%s Y%s..%s, the cycle's tool centre X%s..%s Y%s..%s"
                        % tuple("%g" % round(value, 3) for value in own + cycle))


def _check_start(op: Any, rect: Rectangle, diameter: float) -> None:
    """G33: NotNative when the op's Path does not start its cut at the upper right corner, as G33 does."""
    where = {"X": None, "Y": None}
    for command in op.Path.Commands:
        if MOTION.get(command.Name) and None not in where.values():
            break
        where.update({axis: command.Parameters[axis] for axis in "XY" if axis in command.Parameters})
    corner = (rect.cx + rect.size_x / 2.0 - diameter / 2.0, rect.cy + rect.size_y / 2.0 - diameter / 2.0)
    if None in where.values() or any(abs(where[a] - c) > REACH_TOL for a, c in zip("XY", corner)):
        raise NotNative("the op's Path starts at X%s Y%s, G33 at the upper right corner X%g Y%g"
                        % (tuple("?" if where[a] is None else "%g" % round(where[a], 3) for a in "XY")
                           + (round(corner[0], 3), round(corner[1], 3))))


def _check_pattern(op: Any, kind: str, rect: Rectangle) -> None:
    name = "ClearingPattern" if hasattr(op, "ClearingPattern") else "OffsetPattern"  # 1.1 renamed it
    pattern = str(getattr(op, name, ""))
    if getattr(op, "UseStartPoint", False):
        raise NotNative("UseStartPoint is set: the cycle starts %s" % ("at the upper right corner" if kind == "G33"
                                                                       else "at the centre"))
    if abs(_value(getattr(op, "ExtraOffset", 0.0))) > LENGTH_TOL:
        raise NotNative("ExtraOffset is not 0: the cycle cuts to the area's edges")
    if getattr(op, "UseRestMachining", False):
        raise NotNative("UseRestMachining is set: the cycle clears the whole area")
    if kind == "G33":
        if rect.corner > 0:
            raise NotNative("the area has rounded corners: G33 faces a sharp rectangle")
        along = 0.0 if rect.size_x >= rect.size_y - LENGTH_TOL else 90.0
        angle = _value(op.ZigZagAngle) % 180.0
        if pattern != "ZigZag" or min(abs(angle - along), 180.0 - abs(angle - along)) > ANGLE_TOL:
            raise NotNative("the op clears %s at %g degrees: G33 goes back and forth along the long side "
                            "(%s ZigZag, ZigZagAngle %g)" % (pattern, angle, name, along))
    else:
        if pattern != "Offset" or str(op.StartAt) != "Center":
            raise NotNative("the op clears %s from the %s: G34 laps from the centre outward (%s Offset, "
                            "StartAt Center)" % (pattern, str(op.StartAt).lower(), name))
        direction = str(getattr(op.ToolController, "SpindleDir", "Forward"))
        if direction != "Forward":
            raise NotNative("the spindle turns %s: G41 climbs and G42 cuts conventional with M3" % direction)


def _scaled(value: float, inches: bool) -> float:
    return round(value / MM_PER_INCH if inches else value, DECIMALS[inches])


def _feeds(op: Any, inches: bool) -> Tuple[float, float]:
    """The X-Y and Z feeds per minute (HorizFeed, VertFeed in mm/s); NotNative when either is 0."""
    controller = op.ToolController
    feeds = []
    for name in ("HorizFeed", "VertFeed"):
        value = _value(getattr(controller, name)) * SECONDS_PER_MINUTE
        if not value > 0:
            raise NotNative("the tool controller's %s is 0: the cycle needs its feed" % name)
        feeds.append(_scaled(value, inches))
    return feeds[0], feeds[1]


def make_call(op: Any, kind: str, rect: Rectangle, diameter: float, inches: bool) -> MilltronicsCycle:
    """The G33/G34 model of ``op`` over ``rect`` (see the module notes)."""
    step = _value(op.StepDown)
    if not step > 0:
        raise NotNative("StepDown is %g: the cycle's Q must be greater than 0" % step)
    levels = path_depths(op)
    if not levels:
        raise NotNative("the op's Path cuts nothing")
    words = dict(R=_scaled(_value(op.SafeHeight), inches), Z=_scaled(levels[-1], inches),
                 V=_scaled(levels[0], inches), Q=_scaled(step, inches), F=_feeds(op, inches)[1], G99=True,
                 P151=_scaled(rect.size_x, inches), P152=_scaled(rect.size_y, inches),
                 P155=_scaled(float(op.StepOver) / 100.0 * diameter, inches))
    if kind == "G33":
        return G33(compensation="G41", **words)
    compensation = "G41" if str(op.CutMode) == "Climb" else "G42"
    return G34(compensation=compensation, P150=_scaled(rect.corner, inches), P153=0.0, P154=0.0, **words)


def floor_note(op: Any) -> Optional[str]:
    """A note when the op's Path stops above its FinalDepth (FreeCAD 1.0's Face op never cuts its last depth)."""
    levels = path_depths(op)
    final = _value(op.FinalDepth)
    if levels and levels[-1] > final + LENGTH_TOL:
        return ("Z is the lowest level the op's Path cuts, %g, not its FinalDepth %g" % (round(levels[-1], 4), final))
    return None


def _depths_differ(op: Any, depths: Tuple[float, ...], inches: bool) -> Optional[str]:
    """Why the depths the call cuts at (program units) are not those of the op's Path, or None."""
    scale = MM_PER_INCH if inches else 1.0
    cycle = [z * scale for z in depths]
    own = path_depths(op)
    if len(cycle) != len(own) or any(abs(a - b) > 2 * LENGTH_TOL for a, b in zip(cycle, own)):
        return ("the op's Path cuts at Z %s, the cycle V, V-Q ... Z would cut at Z %s"
                % (", ".join("%g" % round(z, 4) for z in own) or "nothing",
                   ", ".join("%g" % round(z, 4) for z in cycle)))
    return None


def recognise(op: Any, inches: bool) -> Union[NativeOp, str]:
    """The autoroutine of ``op``, or why it is written as moves (one line)."""
    kind = proxy_kind(op)
    if kind is None:
        return "only CAM's Face and Pocket Shape ops have autoroutines here"
    try:
        diameter = _tool_diameter(op)
        rect = rectangle_of(getattr(op, "removalshape", None))
        _check_pattern(op, kind, rect)
        _check_reach(op, rect, diameter)
        if kind == "G33":
            _check_start(op, rect, diameter)
        call = make_call(op, kind, rect, diameter, inches)
        x, y = _scaled(rect.cx, inches), _scaled(rect.cy, inches)
        clearance = _scaled(_value(op.ClearanceHeight), inches)
        xy_feed = _feeds(op, inches)[0]
        start = MachineState(x=x, y=y, z=clearance, feed=xy_feed, metric=not inches, diameter_mode=False)
        settings = Settings(mill_tool_diameter=_scaled(diameter, inches))
        moves = call.expand(start, settings)
        reason = _depths_differ(op, call.plan(start, settings).depths, inches)
        if reason:
            raise NotNative(reason)
    except NotNative as e:
        return str(e)
    except CycleError as e:
        return str(e).replace("(", "[").replace(")", "]")
    return NativeOp(str(op.Label), call, floor_note(op), x, y, clearance, xy_feed, moves)
