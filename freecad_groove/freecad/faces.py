"""What a picked face of a turned part means for a groove.

The part turns about the Job's Z axis: the global Z axis through the origin.
A groove is cut into one face of revolution about that axis:

- a cylinder: a longitudinal groove (plunged along X) at its radius;
- a cone at most 45 degrees off the Z axis: a longitudinal groove on an
  oblique contour, ANGC taken from the cone;
- a cone steeper than that: a face groove (plunged along Z) on an oblique
  contour (CYCLE93's paraxial roughing refuses longitudinal grooves on
  contours tilted more than 45 degrees, and a face groove suits them);
- a plane whose normal is +Z or -Z: a face groove.

External/internal: for cylinders and shallow cones from the face normal,
pointing away from the axis = external (plunge -X), toward it = internal
(plunge +X). For planes and steep cones from the normal's Z component, as
CYCLE93 reads face grooves: +Z = external (a face looking toward +Z, plunged
-Z), -Z = internal (plunged +Z).

ANGC follows freecad_groove.engine.cycle93: the direction of the contour line
in the (Z, radius X) half plane, counter-clockwise from +Z with X up, 0..180.
A cone whose radius grows toward +Z has ANGC in (0, 90), one that shrinks
toward +Z in (90, 180); a cylinder 0, a plane 90.

Only Part is needed (no Path, no GUI); the result is plain data.
"""

import math
from dataclasses import dataclass
from typing import Optional

import Part

from ..engine.numbers import format_decimal

AXIS_TOLERANCE = 1e-7  # |sin| of the angle between a surface axis and Z
ON_AXIS_TOLERANCE = 1e-6  # mm: how far an axis may pass from the origin's Z axis
LONGITUDINAL_LIMIT = 45.0  # degrees off Z up to which a cone takes longitudinal grooves
LONGITUDINAL = "longitudinal"
FACE = "face"


def edge_curve(edge: object) -> Optional[object]:
    """A Part edge's curve, None for a degenerated edge (the pole of a sphere
    or torus), whose Curve raises "undefined curve type"."""
    if getattr(edge, "Degenerated", False):
        return None
    try:
        return edge.Curve
    except (TypeError, RuntimeError, AttributeError):  # Part reports an unknown curve as TypeError
        return None


def _fmt(value):
    return format_decimal(value, 3, point=False)


@dataclass(frozen=True)
class GrooveFace:
    """A face of revolution about Z, as a groove sees it.

    name      how to name the face in messages ("Shaft.Face3")
    surface   "cylinder", "cone" or "plane"
    kind      "longitudinal" (grooves plunged along X) or "face" (along Z)
    external  True: plunged -X (longitudinal) / -Z (face)
    angc      CYCLE93 ANGC of the contour line, degrees
    r_min, r_max, z_min, z_max   the face's extent (radius, Z)
    start     (radius, z) where Position is measured from: the face's +Z end
              for longitudinal grooves, its outer edge for face grooves
    end       (radius, z) at the other end of the face's contour line
    """

    name: str
    surface: str
    kind: str
    external: bool
    angc: float
    r_min: float
    r_max: float
    z_min: float
    z_max: float
    start: tuple
    end: tuple

    @property
    def longitudinal(self):
        return self.kind == LONGITUDINAL

    def point_at(self, position):
        """(radius, z) of the contour point ``position`` from ``start``: along
        -Z for longitudinal grooves, toward the axis for face grooves
        (paraxial distances, the way CYCLE93 measures; may lie past the face)."""
        (r0, z0), (r1, z1) = self.start, self.end
        if self.longitudinal:
            z = z0 - position
            r = r0 if z1 == z0 else r0 + (z - z0) * (r1 - r0) / (z1 - z0)
            return r, z
        r = r0 - position
        z = z0 if r1 == r0 else z0 + (r - r0) * (z1 - z0) / (r1 - r0)
        return r, z

    def describe(self):
        """Words for the op's GrooveKind: e.g. "longitudinal, external",
        "oblique (ANGC 12°), external", "face, internal"."""
        side = "external" if self.external else "internal"
        if self.surface == "cone":
            what = "oblique" if self.longitudinal else "oblique face"
            return "%s (ANGC %s°), %s" % (what, _fmt(self.angc), side)
        return "%s, %s" % (self.kind, side)


def _radial(p):
    return math.hypot(p.x, p.y)


def _check_axis(name, surface):
    axis = surface.Axis
    if math.hypot(axis.x, axis.y) > AXIS_TOLERANCE * axis.Length:
        raise ValueError(
            "%s: the %s's axis (%s, %s, %s) is not the Z axis the part turns about"
            % (name, type(surface).__name__.lower(), _fmt(axis.x), _fmt(axis.y), _fmt(axis.z))
        )
    center = surface.Center
    if math.hypot(center.x, center.y) > ON_AXIS_TOLERANCE:
        raise ValueError(
            "%s: the %s's axis passes through X%s Y%s, not through the Z axis the part turns about"
            % (name, type(surface).__name__.lower(), _fmt(center.x), _fmt(center.y))
        )


def _edge_radial_range(edge):
    """(min, max) distance from the Z axis of an edge's points."""
    curve = edge_curve(edge)
    if curve is None:  # degenerated: a point
        radii = [_radial(v.Point) for v in edge.Vertexes]
        return min(radii), max(radii)
    if isinstance(curve, Part.Circle):
        axis, center = curve.Axis, curve.Center
        if math.hypot(axis.x, axis.y) <= AXIS_TOLERANCE and math.hypot(center.x, center.y) <= ON_AXIS_TOLERANCE:
            return curve.Radius, curve.Radius
    pts = edge.discretize(Deflection=0.001) if edge.Length > 0 else [v.Point for v in edge.Vertexes]
    radii = [_radial(p) for p in pts]
    return min(radii), max(radii)


def _revolution_face(name, face, surface):
    """Cylinder or cone: the contour line's two ends from the parameter range."""
    _check_axis(name, surface)
    u0, u1, v0, v1 = face.ParameterRange
    a, b = face.valueAt(u0, v0), face.valueAt(u0, v1)
    ra, rb = _radial(a), _radial(b)
    if abs(a.z - b.z) < 1e-9 and abs(ra - rb) < 1e-9:
        raise ValueError("%s: a degenerate %s face" % (name, type(surface).__name__.lower()))
    if isinstance(surface, Part.Cylinder):
        angc = 0.0
        tilt = 0.0
    else:
        angc = math.degrees(math.atan2(rb - ra, b.z - a.z))
        if angc < 0:
            angc += 180.0
        if angc >= 180.0:
            angc -= 180.0
        tilt = min(angc, 180.0 - angc)  # degrees off the Z axis
    # Which side the material is on: the outward normal at the face's middle.
    um, vm = 0.5 * (u0 + u1), 0.5 * (v0 + v1)
    p, n = face.valueAt(um, vm), face.normalAt(um, vm)
    radial_out = p.x * n.x + p.y * n.y  # > 0: the normal points away from the axis
    z_min, z_max = min(a.z, b.z), max(a.z, b.z)
    r_min, r_max = min(ra, rb), max(ra, rb)
    if tilt <= LONGITUDINAL_LIMIT + 1e-9:
        if abs(radial_out) < 1e-12:
            raise ValueError("%s: cannot tell which side of the face the material is on" % name)
        hi, lo = ((ra, a.z), (rb, b.z)) if a.z > b.z else ((rb, b.z), (ra, a.z))
        return GrooveFace(
            name, "cylinder" if angc == 0.0 else "cone", LONGITUDINAL, radial_out > 0,
            angc, r_min, r_max, z_min, z_max, hi, lo,
        )
    outer, inner = ((ra, a.z), (rb, b.z)) if ra > rb else ((rb, b.z), (ra, a.z))
    return GrooveFace(name, "cone", FACE, n.z > 0, angc, r_min, r_max, z_min, z_max, outer, inner)


def _plane_face(name, face, surface):
    u0, _u1, v0, _v1 = face.ParameterRange
    n = face.normalAt(u0, v0)  # a plane's normal is the same everywhere; this one heeds the face's orientation
    if math.hypot(n.x, n.y) > AXIS_TOLERANCE:
        raise ValueError(
            "%s: a plane whose normal (%s, %s, %s) is not along Z; face grooves need a face square to the axis"
            % (name, _fmt(n.x), _fmt(n.y), _fmt(n.z))
        )
    z = face.Vertexes[0].Point.z if face.Vertexes else face.CenterOfMass.z
    ranges = [_edge_radial_range(e) for e in face.Edges]
    r_max = max(hi for _lo, hi in ranges)
    if face.isInside(Part.Vertex(0, 0, z).Point, 1e-6, True):
        r_min = 0.0
    else:
        r_min = min(lo for lo, _hi in ranges)
    if r_max - r_min < 1e-9:
        raise ValueError("%s: a degenerate plane face" % name)
    return GrooveFace(name, "plane", FACE, n.z > 0, 90.0, r_min, r_max, z, z, (r_max, z), (r_min, z))


def analyse_face(face, name="face"):
    """GrooveFace for a Part face; ValueError naming the face when no groove
    can be cut into it (sphere, torus, plane not square to Z, off-axis)."""
    if not isinstance(face, Part.Face):
        shape_type = getattr(face, "ShapeType", type(face).__name__)
        raise ValueError("%s: not a face (%s); pick a cylinder, cone or plane face" % (name, shape_type))
    surface = face.Surface
    if isinstance(surface, (Part.Cylinder, Part.Cone)):
        return _revolution_face(name, face, surface)
    if isinstance(surface, Part.Plane):
        return _plane_face(name, face, surface)
    kind = type(surface).__name__
    raise ValueError(
        "%s: a %s face; grooves go on a cylinder, a cone or a plane square to the Z axis"
        % (name, {"SurfaceOfRevolution": "surface of revolution", "BSplineSurface": "B-spline"}.get(kind, kind.lower()))
    )


def element_name(obj, sub):
    """"Label.Face3" for messages."""
    return "%s.%s" % (getattr(obj, "Label", getattr(obj, "Name", "?")), sub)
