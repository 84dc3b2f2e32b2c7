"""The safe envelope around the Job's model and the link rapids along it.

The part turns about the Z axis. The envelope is the region outside the
model that the Groove op's rapids between grooves travel on: the cylinder
X = R + c (R: the model's largest radius, c: the clearance) and the planes
Z = Zmax + c and Z = Zmin - c. A link moves onto the envelope, along it and
off it to the next start point, one axis at a time. The envelope also tells
whether a straight rapid passes through the model (in the XZ half plane at
Y = 0, which is exact for bodies of revolution).

The op starts at its safe start point, the lathe's counterpart of CAM's
ClearanceHeight: the clearance outside the stock's (and model's) largest
radius and beyond its +Z end. The first link leaves it along the outside of
the stock and enters the stock's region only straight at the first groove's
start point (over material the groove needs turned to the model anyway).

FreeCAD layer: FreeCAD and Part only.
"""

import math
from typing import NamedTuple, Optional

import FreeCAD
import Part

from ...freecad.faces import edge_curve
from ...freecad.shape_memo import ShapeMemo

TESSELLATION = 0.01  # mm: deflection used to find the model's largest radius
HIT_LENGTH = 1e-6  # mm of a rapid inside a solid that counts as a collision
SAME_POSITION = 1e-12  # mm: a link move this short is not written

# Where a start point is on the envelope.
SIDE = "side"  # on the cylinder X = R + c
TOP = "top"  # on the plane Z = Zmax + c
BOTTOM = "bottom"  # on the plane Z = Zmin - c

Point = tuple[float, float]  # (x, z): radius and Z in the XZ half plane


class LinkMove(NamedTuple):
    """One G0 of a link: where it goes, None for an axis it does not move
    (the first link starts from an unknown position)."""

    x: Optional[float]
    z: Optional[float]


def _coaxial(surface: object) -> bool:
    """True when a Part surface or circle (a FreeCAD object) turns about the Z axis."""
    axis, center = surface.Axis, surface.Center
    return math.hypot(axis.x, axis.y) <= 1e-9 * axis.Length and math.hypot(center.x, center.y) <= 1e-9


def _edge_radius(edge: object) -> float:
    """Largest distance of a Part edge from the Z axis (exact for coaxial
    circles and lines, else from points 0.001 mm apart in deflection, plus that;
    a degenerated edge: its vertex)."""
    curve = edge_curve(edge)
    if isinstance(curve, Part.Circle) and _coaxial(curve):
        return curve.Radius
    points = [vertex.Point for vertex in edge.Vertexes]
    if curve is not None and not isinstance(curve, (Part.Line, Part.LineSegment)) and edge.Length > 0:
        return max(math.hypot(p.x, p.y) for p in edge.discretize(Deflection=0.001)) + 0.001
    return max(math.hypot(p.x, p.y) for p in points) if points else 0.0


def largest_radius(shape: object) -> Optional[float]:
    """Largest distance of a Part shape from the Z axis (None: an empty shape),
    computed once per shape (shape_memo.py: every recompute and preview reads
    the model's and the stock's, which rarely change)."""
    return _LARGEST_RADIUS(shape)


def _largest_radius(shape: object) -> Optional[float]:
    """largest_radius, computed. Exact for turned parts: on planes and on
    cylinders and cones about Z the distance peaks on the boundary; other faces
    are tessellated (plus the tessellation's deflection)."""
    radii = [math.hypot(vertex.Point.x, vertex.Point.y) for vertex in shape.Vertexes]
    radii += [_edge_radius(edge) for edge in shape.Edges]
    for face in shape.Faces:
        surface = face.Surface
        if isinstance(surface, Part.Plane) or (isinstance(surface, (Part.Cylinder, Part.Cone)) and _coaxial(surface)):
            continue
        points = face.tessellate(TESSELLATION)[0]
        if points:
            radii.append(max(math.hypot(p.x, p.y) for p in points) + TESSELLATION)
    return max(radii) if radii else None


_LARGEST_RADIUS = ShapeMemo(_largest_radius)


class _LinkWriter:
    """Collects a link's G0 moves from a position that may be unknown (None
    on an axis), leaving out moves that go nowhere."""

    def __init__(self, start: Optional[Point]):
        self.x, self.z = start if start is not None else (None, None)
        self.moves: list[LinkMove] = []

    def go(self, x: Optional[float] = None, z: Optional[float] = None) -> None:
        new_x = self.x if x is None else x
        new_z = self.z if z is None else z
        same_x = new_x is None or (self.x is not None and abs(new_x - self.x) <= SAME_POSITION)
        same_z = new_z is None or (self.z is not None and abs(new_z - self.z) <= SAME_POSITION)
        if same_x and same_z:
            return
        self.moves.append(LinkMove(new_x, new_z))
        self.x, self.z = new_x, new_z

    def onto(self, surface: str, levels: dict, x: Optional[float] = None, z: Optional[float] = None) -> None:
        """Move onto ``surface`` (to its level ``levels[surface]`` on its own
        axis), the other axis to ``x``/``z`` when given."""
        if surface == SIDE:
            self.go(x=levels[SIDE], z=z)
        else:
            self.go(x=x, z=levels[surface])


def _route(previous_on: Optional[str], target_on: str) -> list[str]:
    """The envelope surfaces a link travels on, in order (previous_on None:
    from an unknown position, which first retracts along one axis)."""
    if previous_on is None:
        return [target_on] if target_on in (TOP, SIDE) else [SIDE, BOTTOM]
    if previous_on == target_on:
        return [previous_on]
    if {previous_on, target_on} == {TOP, BOTTOM}:
        return [previous_on, SIDE, target_on]
    return [previous_on, target_on]


class SafeEnvelope:
    """The region outside the model the op's link rapids travel on.

    shapes     the model's Part shapes (None and null shapes are left out)
    clearance  mm kept between the model and the envelope
    """

    def __init__(self, shapes: list, clearance: float):
        radius, z_min, z_max = None, None, None
        self.solids = []
        for shape in shapes:
            if shape is None or shape.isNull():
                continue
            shape_radius = largest_radius(shape)
            if shape_radius is None:
                continue
            bounds = shape.BoundBox
            radius = shape_radius if radius is None else max(radius, shape_radius)
            z_min = bounds.ZMin if z_min is None else min(z_min, bounds.ZMin)
            z_max = bounds.ZMax if z_max is None else max(z_max, bounds.ZMax)
            self.solids.extend(shape.Solids)
        if radius is None:
            raise ValueError("the Job's model has no shape to groove")
        self.clearance = clearance
        self.model_radius, self.z_min, self.z_max = radius, z_min, z_max
        self.r_safe = radius + clearance
        self.z_top = z_max + clearance
        self.z_bottom = z_min - clearance

    def hits(self, a: Point, b: Point) -> bool:
        """True when the straight rapid a -> b runs through one of the model's solids."""
        if math.dist(a, b) < 1e-9 or not self.solids:
            return False
        edge = Part.LineSegment(FreeCAD.Vector(a[0], 0, a[1]), FreeCAD.Vector(b[0], 0, b[1])).toShape()
        for solid in self.solids:
            if not edge.BoundBox.intersect(solid.BoundBox):
                continue
            if edge.common(solid).Length > HIT_LENGTH:
                return True
        return False

    def safe_start(self, stock: object) -> Point:
        """The op's safe start point (x, z): the clearance outside the larger
        of the stock's (a Part shape; None or null: no stock) and the model's
        largest radius, and beyond the higher of their +Z ends (CAM's
        ClearanceHeight is likewise derived from the stock's ZMax)."""
        radius, z_max = self.model_radius, self.z_max
        if stock is not None and not stock.isNull():
            stock_radius = largest_radius(stock)
            if stock_radius is not None:
                radius = max(radius, stock_radius)
                z_max = max(z_max, stock.BoundBox.ZMax)
        return (radius + self.clearance, z_max + self.clearance)

    def _levels(self, ends: list) -> dict:
        """{surface: its level} for a link between ``ends`` [(point, on)]: a
        start point beyond the envelope moves its surface out to it."""
        def beyond(surface, axis):
            return [point[axis] for point, on in ends if point is not None and on == surface]

        return {
            SIDE: max([self.r_safe] + beyond(SIDE, 0)),
            TOP: max([self.z_top] + beyond(TOP, 1)),
            BOTTOM: min([self.z_bottom] + beyond(BOTTOM, 1)),
        }

    def link(self, previous: Optional[Point], previous_on: Optional[str], target: Point,
             target_on: str, origin: Optional[Point] = None) -> list[LinkMove]:
        """G0 moves along the envelope, one axis at a time, from ``previous``
        (a start point on the envelope surface ``previous_on``) to ``target``
        on the surface ``target_on``. ``previous`` None: the op's first link,
        from ``origin`` (the safe start point, which its first move goes to
        on both axes) or, without one, from wherever the tool is."""
        if previous is None and origin is not None:
            # leave the safe point outside the stock: beyond its +Z end for a
            # start point beyond the part's +Z end, else outside its radius
            previous, previous_on = origin, TOP if target_on == TOP else SIDE
            moves = [LinkMove(*origin)]
        else:
            moves = []
        levels = self._levels([(previous, previous_on), (target, target_on)])
        writer = _LinkWriter(previous)
        for surface in _route(previous_on if previous is not None else None, target_on):
            writer.onto(surface, levels)
        writer.onto(target_on, levels, x=target[0], z=target[1])
        writer.go(x=target[0], z=target[1])
        return moves + writer.moves

    def retreat(self, last: Point, last_on: str, origin: Point) -> list[LinkMove]:
        """G0 moves from the op's last start point ``last`` (on the envelope
        surface ``last_on``) back to its safe start point ``origin``: the way
        the first link would come in from there, reversed, one axis at a time
        (a program ends where a CAM op leaves the tool: at clearance)."""
        way_in = [(step.x, step.z) for step in self.link(None, None, last, last_on, origin)]
        return [LinkMove(*point) for point in reversed(way_in[:-1])]
