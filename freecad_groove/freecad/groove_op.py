"""The Groove operation: CYCLE93 grooves on faces of a turned part.

Headless layer: FreeCAD, Part and Path only (no Qt, no FreeCADGui), so jobs
can be built and recomputed by scripts and in ``freecadcmd``.

Coordinates: the part turns about the Job's Z axis (the global Z axis through
the origin). The op's Path is in the G18 plane: X = radius in model
coordinates, Z; never Y. Its moves drive the blade's reference corner
(README, "Conventions").

What the op does with each face in ``Base`` (see faces.py for the reading of
the face) and each of ``GrooveCount`` grooves:

1. It derives one CYCLE93 call. TYP is "right": 5 longitudinal external, 7
   longitudinal internal, 6 face external, 8 face internal (+10 when
   ChamferMeasure is CHR). The start point AXFA/AXSA is the groove's start
   edge on the face's contour: ``Position`` from the face's +Z end for
   longitudinal grooves (measured along Z, i.e. paraxially, also on cones),
   from its outer edge toward the axis for face grooves (measured along X).
   Groove k (0-based) sits at ``Position + k * Pitch``. ANGC comes from the
   face.
2. It checks the finished groove lies on the face (not past its ends, not
   below the axis).
3. It picks a start point outside the part (the "safe envelope"), expands the
   call there with the engine and checks the approach and final retreat
   rapids against the model's solids (in the XZ half plane at Y = 0, which is
   exact for bodies of revolution); when they would pass through the part
   it tries the next candidate:
   - longitudinal external: X = R + c, Z beside the groove (the blade over
     its first plunge position), where R is the model's largest radius and c
     the clearance (Retract, 0 = 1 mm);
   - longitudinal internal: Z = Zmax + c (the blade wholly beyond the part's
     +Z end), X at the clearance level the cycle itself would approach at
     (c inside the bore's contour line); then the same from the -Z end;
   - face grooves: X = R + c (the blade wholly outside the part), Z at the
     cycle's clearance level above the face; then a column approach: X over
     the first plunge position, Z = Zmax + c (external) / Zmin - c (internal).
4. Rapids link the grooves along the envelope: the cylinder X = R + c and the
   planes Z = Zmax + c and Z = Zmin - c, moving one axis at a time. The first
   groove's link starts with a single-axis retract from wherever the tool is:
   G0 X(R + c) when the start point is on the cylinder or below the part,
   G0 Z(Zmax + c) when it is beyond the +Z end (internal grooves).
   The job's stock is not taken into account: the op assumes the part was
   turned to the model's contour before grooving.

The Path: a comment with the op's label (the base class), G18, then per
groove a comment naming the face and the call, the link rapids (G0), and the
engine's expansion: G0, G1 with F = the tool controller's HorizFeed (FreeCAD's
internal mm/s like every CAM op; posts write it as mm/min), G4 P<seconds>.

Errors (a face that takes no groove, a CycleError from the engine, no room to
approach) are raised from opExecute with the engine's message: FreeCAD marks
the op invalid with that message as its status (``obj.getStatusString()``),
the document and the other objects stay valid, the op's Path is replaced by
one comment that repeats the message, and the next recompute after a fix
clears it. FreeCAD 1.0 and 1.1 behave the same; both also print the
traceback and "<Label>: <message>" on the report view / console.
"""

import math
from dataclasses import dataclass, field

import FreeCAD
import Part
import Path
import Path.Op.Base as PathOp
import PathScripts.PathUtils as PathUtils

from .. import hooks
from ..engine import CycleError, GroovingTool, MachineState, Settings
from ..engine.cycles.cycle93 import ALARM_WIDTH, DEFAULT_VRT_MM, Cycle93
from ..engine.moves import DWELL, FEED, RAPID
from ..engine.numbers import format_value
from .faces import analyse_face, element_name
from .groove_properties import (  # noqa: F401 - error_properties and the tables are this module's API too
    CHAMFER_MEASURES,
    DERIVED,
    MAX_GROOVES,
    PROPERTIES,
    PROPERTY_NAMES,
    PROPERTY_TYPES,
    error_properties,
)
from .units import feed_mm_per_min, length_mm

TESSELLATION = 0.01  # mm: deflection used to find the model's largest radius
HIT_LENGTH = 1e-6  # mm of a rapid inside a solid that counts as a collision

# TYP units digit for "right" grooves: (longitudinal, external) -> TYP
TYP_RIGHT = {(True, True): 5, (True, False): 7, (False, True): 6, (False, False): 8}


class GrooveInputError(ValueError):
    """A value of the op that cannot make a groove; ``properties`` names the
    op properties to fix (the task panel marks their fields)."""

    def __init__(self, message, properties=()):
        super().__init__(message)
        self.properties = tuple(properties)


class _WithValues:
    """An op object seen with some property values replaced: plan() on it
    shows what the op would cut with the task panel's values, without
    writing them to the document."""

    def __init__(self, obj, values):
        self._obj = obj
        self._values = values

    def __getattr__(self, name):
        values = self.__dict__["_values"]
        if name in values:
            return values[name]
        return getattr(self.__dict__["_obj"], name)


def document_object(obj):
    """The FreeCAD object behind ``obj`` (itself, or what _WithValues wraps)."""
    return obj._obj if isinstance(obj, _WithValues) else obj


def _comment(text):
    """A Path comment body: FreeCAD drops inner parentheses."""
    return "(%s)" % text.replace("(", "[").replace(")", "]")


def _coaxial(surface):
    axis, center = surface.Axis, surface.Center
    return math.hypot(axis.x, axis.y) <= 1e-9 * axis.Length and math.hypot(center.x, center.y) <= 1e-9


def _edge_radius(edge):
    """Largest distance of an edge from the Z axis (exact for coaxial circles
    and lines, else from points 0.001 mm apart in deflection, plus that)."""
    curve = getattr(edge, "Curve", None)
    if isinstance(curve, Part.Circle) and _coaxial(curve):
        return curve.Radius
    points = [v.Point for v in edge.Vertexes]
    if not isinstance(curve, (Part.Line, Part.LineSegment)) and edge.Length > 0:
        return max(math.hypot(p.x, p.y) for p in edge.discretize(Deflection=0.001)) + 0.001
    return max(math.hypot(p.x, p.y) for p in points) if points else 0.0


def _largest_radius(shape):
    """Largest distance of a shape from the Z axis. Exact for turned parts: on
    planes and on cylinders and cones about Z the distance peaks on the
    boundary; other faces are tessellated (plus the tessellation's deflection)."""
    best = None
    for v in shape.Vertexes:
        r = math.hypot(v.Point.x, v.Point.y)
        best = r if best is None else max(best, r)
    for edge in shape.Edges:
        r = _edge_radius(edge)
        best = r if best is None else max(best, r)
    for face in shape.Faces:
        surface = face.Surface
        if isinstance(surface, Part.Plane) or (isinstance(surface, (Part.Cylinder, Part.Cone)) and _coaxial(surface)):
            continue
        points = face.tessellate(TESSELLATION)[0]
        if points:
            r = max(math.hypot(p.x, p.y) for p in points) + TESSELLATION
            best = r if best is None else max(best, r)
    return best


# -- the plan -----------------------------------------------------------------

SIDE, TOP, BOTTOM = "side", "top", "bottom"


@dataclass
class GroovePlan:
    """One groove the op cuts.

    face      the GrooveFace it is cut into
    index     0-based number of the groove on that face
    position  its Position (Position + index * Pitch)
    cycle     the Cycle93 call
    settings  the engine Settings (tool width, corner radius, reference corner)
    start     MachineState at the start point the call is expanded from
    start_on  where that start point is on the safe envelope: "side" (X = R + c),
              "top" (Z = Zmax + c) or "bottom" (Z = Zmin - c)
    link      G0 moves [(x or None, z or None)] from the previous groove's start
              point (for the first groove: from wherever the tool is) to ``start``
    moves     the engine's expansion of ``cycle`` from ``start``
    geometry  ``cycle.geometry(settings)``: the groove's profile (the preview draws it)
    """

    face: object
    index: int
    position: float
    cycle: Cycle93
    settings: Settings
    start: MachineState
    start_on: str
    link: list = field(default_factory=list)
    moves: list = field(default_factory=list)
    geometry: object = None


class SafeEnvelope:
    """The region outside the model the op's link rapids travel on."""

    def __init__(self, shapes, clearance):
        radius, z_lo, z_hi = None, None, None
        self.solids = []
        for shape in shapes:
            if shape is None or shape.isNull():
                continue
            r = _largest_radius(shape)
            if r is None:
                continue
            bb = shape.BoundBox
            radius = r if radius is None else max(radius, r)
            z_lo = bb.ZMin if z_lo is None else min(z_lo, bb.ZMin)
            z_hi = bb.ZMax if z_hi is None else max(z_hi, bb.ZMax)
            self.solids.extend(shape.Solids)
        if radius is None:
            raise ValueError("the Job's model has no shape to groove")
        self.clearance = clearance
        self.model_radius, self.z_min, self.z_max = radius, z_lo, z_hi
        self.r_safe = radius + clearance
        self.z_top = z_hi + clearance
        self.z_bottom = z_lo - clearance

    def hits(self, a, b):
        """True when the straight rapid a -> b ((x, z) in the XZ half plane at
        Y = 0) runs through one of the model's solids."""
        if math.dist(a, b) < 1e-9 or not self.solids:
            return False
        edge = Part.LineSegment(FreeCAD.Vector(a[0], 0, a[1]), FreeCAD.Vector(b[0], 0, b[1])).toShape()
        for solid in self.solids:
            if not edge.BoundBox.intersect(solid.BoundBox):
                continue
            if edge.common(solid).Length > HIT_LENGTH:
                return True
        return False

    def link(self, prev, prev_on, target, target_on):
        """G0 moves [(x or None, z or None)] along the envelope, one axis at a
        time, from ``prev`` (None: unknown) to ``target``."""
        out = []
        cur = [None, None]  # None: not known (the first link starts anywhere)

        def go(x=None, z=None):
            nx = cur[0] if x is None else x
            nz = cur[1] if z is None else z
            same_x = nx is None or (cur[0] is not None and abs(nx - cur[0]) <= 1e-12)
            same_z = nz is None or (cur[1] is not None and abs(nz - cur[1]) <= 1e-12)
            if same_x and same_z:
                return
            out.append((nx, nz))
            cur[0], cur[1] = nx, nz

        x_line = max([self.r_safe] + [p[0] for p, on in ((prev, prev_on), (target, target_on)) if p is not None and on == SIDE])
        z_top = max([self.z_top] + [p[1] for p, on in ((prev, prev_on), (target, target_on)) if p is not None and on == TOP])
        z_bot = min([self.z_bottom] + [p[1] for p, on in ((prev, prev_on), (target, target_on)) if p is not None and on == BOTTOM])

        def onto(surface):
            if surface == SIDE:
                go(x=x_line)
            elif surface == TOP:
                go(z=z_top)
            else:
                go(z=z_bot)

        if prev is None:
            # From an unknown position: retract along one axis first.
            if target_on == TOP:
                route = [TOP]
            elif target_on == SIDE:
                route = [SIDE]
            else:
                route = [SIDE, BOTTOM]
        else:
            cur[0], cur[1] = prev
            if prev_on == target_on:
                route = [prev_on]
            elif {prev_on, target_on} == {TOP, BOTTOM}:
                route = [prev_on, SIDE, target_on]
            else:
                route = [prev_on, target_on]
        for surface in route:
            onto(surface)
        if target_on == SIDE:
            go(x=x_line, z=target[1])
        elif target_on == TOP:
            go(x=target[0], z=z_top)
        else:
            go(x=target[0], z=z_bot)
        go(x=target[0], z=target[1])
        return out


# -- the operation --------------------------------------------------------------


class ObjectGroove(PathOp.ObjectOp):
    """Proxy of a Groove operation (Path::FeaturePython)."""

    def __init__(self, obj, name, parentJob=None, tool_controller=None):
        # The base class picks a tool controller while it is built; headless,
        # with several in the job and no GUI to ask, FreeCAD's picker fails,
        # so it is steered to this one (see isToolSupported).
        if tool_controller is None and parentJob is not None and getattr(parentJob, "Tools", None):
            group = parentJob.Tools.Group
            tool_controller = group[0] if group else None
        self._tc_hint = tool_controller
        try:
            super().__init__(obj, name, parentJob)
        finally:
            self._tc_hint = None
        if tool_controller is not None and getattr(obj, "ToolController", None) is None:
            obj.ToolController = tool_controller

    # -- FreeCAD op API ---------------------------------------------------------
    def opFeatures(self, obj):
        flags = 0
        for name in ("FeatureTool", "FeatureBaseFaces", "FeatureCoolant"):
            flags |= getattr(PathOp, name, 0)
        return flags

    def initOperation(self, obj):
        self._add_missing_properties(obj)

    def opOnDocumentRestored(self, obj):
        self._add_missing_properties(obj)

    def opSetDefaultValues(self, obj, job):
        pass

    def opUpdateDepths(self, obj):
        """The milling depth logic works on the Z bounding box; a lathe groove
        has no start/final depth."""
        pass

    def isToolSupported(self, obj, tool):
        hint = getattr(self, "_tc_hint", None)
        if hint is not None:
            return tool == hint.Tool
        return True

    def opExecute(self, obj):
        self._plans = None
        faces = None
        try:
            faces = self.groove_faces(obj)
            self._write_derived(obj, faces)
            plans = self.plan(obj, faces)
        except Exception as e:  # CycleError and face errors are ValueErrors; anything else too:
            if faces is None:  # never leave a stale Path behind an invalid op
                self._write_derived(obj, [])
            obj.Path = Path.Path([Path.Command(_comment("%s: %s" % (obj.Label, e)))])
            raise
        self.commandlist.extend(self.commands(obj, plans))
        self._plans = plans  # the posts reuse it while the op stays up to date

    def current_plan(self, obj):
        """plan(obj) as the last recompute made it, while nothing has touched
        the op since (planning checks every link rapid against the model, the
        costly part of posting); otherwise a fresh plan."""
        plans = getattr(self, "_plans", None)
        if plans is not None and not ({"Touched", "Invalid"} & set(obj.State)):
            return plans
        return self.plan(obj)

    # -- properties -------------------------------------------------------------
    def _add_missing_properties(self, obj):
        for type_id, name, group, tooltip, default in PROPERTIES:
            if name in obj.PropertiesList:
                continue
            obj.addProperty(type_id, name, group, tooltip)
            setattr(obj, name, default)
            if isinstance(default, list):
                setattr(obj, name, default[0])
        # Constraints and editor modes are not stored in the document.
        obj.GrooveCount = (max(1, int(obj.GrooveCount)), 1, MAX_GROOVES, 1)
        for name in DERIVED:
            obj.setEditorMode(name, 1)

    def _write_derived(self, obj, faces):
        if faces:
            first = self.cycle(obj, faces[0], 0)
            kinds = []
            for f in faces:
                if f.describe() not in kinds:
                    kinds.append(f.describe())
            values = {"GrooveKind": "; ".join(kinds), "AXFA": first.axfa, "AXSA": first.axsa,
                      "ANGC": first.angc, "TYP": first.typ}
        else:
            values = {"GrooveKind": "", "AXFA": 0.0, "AXSA": 0.0, "ANGC": 0.0, "TYP": 0}
        for name, value in values.items():
            old = getattr(obj, name)
            if isinstance(value, str) or isinstance(value, int):
                if old != value:
                    setattr(obj, name, value)
            elif abs(length_mm(old) - value) > 1e-12:
                setattr(obj, name, value)

    # -- deriving the grooves ---------------------------------------------------
    def groove_faces(self, obj):
        """GrooveFace of every face in Base (ValueError naming a face that takes no groove)."""
        out = []
        job = PathUtils.findParentJob(document_object(obj))
        for base, subs in obj.Base or []:
            if isinstance(subs, str):
                subs = (subs,)
            named = job.Proxy.baseObject(job, base) if job is not None else base
            for sub in subs:
                name = element_name(named, sub or "(whole object)")
                if not sub:
                    raise GrooveInputError("%s: pick a face of the part, not the whole object" % name, ("Base",))
                try:
                    shape = base.Shape.getElement(sub)
                except Exception:
                    raise GrooveInputError("%s: no such element in the model (did the model change?)" % name, ("Base",)) from None
                try:
                    out.append(analyse_face(shape, name))
                except ValueError as e:
                    raise GrooveInputError(str(e), ("Base",)) from None
        return out

    def settings(self, obj):
        """Engine Settings: the tool bit's Width/CornerRadius when it has them,
        else the op's ToolWidth/ToolCornerRadius; the op's ReferenceCorner."""
        tc = getattr(obj, "ToolController", None)
        bit = getattr(tc, "Tool", None) if tc is not None else None
        width = obj.ToolWidth.Value
        radius = obj.ToolCornerRadius.Value
        if bit is not None:
            if getattr(bit, "Width", None) is not None:
                width = length_mm(bit.Width)
            if getattr(bit, "CornerRadius", None) is not None:
                radius = length_mm(bit.CornerRadius)
        return Settings(tool=GroovingTool(width=width, corner_radius=radius, reference=str(obj.ReferenceCorner)))

    def cycle(self, obj, face, index):
        """The Cycle93 call for groove ``index`` (0-based) on ``face``."""
        position = obj.Position.Value + index * obj.Pitch.Value
        r, z = face.point_at(position)
        typ = TYP_RIGHT[(face.longitudinal, face.external)]
        if obj.ChamferMeasure == CHAMFER_MEASURES[1]:
            typ += 10
        return Cycle93(
            axfa=round(r, 9) + 0.0, axsa=round(z, 9) + 0.0,
            widg=obj.Width.Value, depg=obj.Depth.Value, angc=round(face.angc, 9),
            ang1=obj.FlankAngle1.Value, ang2=obj.FlankAngle2.Value,
            rco1=_corner(obj, "EdgeCorner1"), rco2=_corner(obj, "EdgeCorner2"),
            rci1=_corner(obj, "BaseCorner1"), rci2=_corner(obj, "BaseCorner2"),
            fal1=obj.BaseAllowance.Value, fal2=obj.FlankAllowance.Value,
            idep=obj.Infeed.Value, dwt=float(obj.Dwell), typ=typ, vrt=obj.Retract.Value,
        )

    def feed_mm_per_min(self, obj):
        tc = getattr(obj, "ToolController", None)
        return feed_mm_per_min(tc.HorizFeed.Value) if tc is not None else None

    def plan(self, obj, faces=None):
        """Every groove the op cuts, in order: [GroovePlan]. Raises ValueError
        (CycleError from the engine) when one cannot be cut."""
        if faces is None:
            faces = self.groove_faces(obj)
        if not faces:
            return []
        count = int(obj.GrooveCount)
        if count < 1:
            raise GrooveInputError("GrooveCount=%d: must be 1 or more" % count, ("GrooveCount",))
        if count > 1 and not obj.Pitch.Value > 0:
            raise GrooveInputError(
                "Pitch=%s: must be greater than 0 with GrooveCount %d" % (format_value(obj.Pitch.Value), count), ("Pitch",)
            )
        job = PathUtils.findParentJob(document_object(obj))
        if job is None:
            raise ValueError("%s is not in a Job" % obj.Label)
        settings = self.settings(obj)
        clearance = obj.Retract.Value or DEFAULT_VRT_MM
        env = SafeEnvelope([m.Shape for m in job.Model.Group if hasattr(m, "Shape")], clearance)
        feed = self.feed_mm_per_min(obj)
        plans = []
        prev, prev_on = None, None
        for face in faces:
            for index in range(count):
                call = self.cycle(obj, face, index)
                geo = call.geometry(settings)
                position = obj.Position.Value + index * obj.Pitch.Value
                _check_on_face(face, geo, index, position)
                start, start_on, moves = _start_and_moves(face, geo, call, settings, env, feed, index)
                link = env.link(prev, prev_on, (start.x, start.z), start_on)
                plans.append(GroovePlan(face, index, position, call, settings, start, start_on, link, moves, geo))
                prev, prev_on = (start.x, start.z), start_on
        return plans

    def plan_with(self, obj, values):
        """plan() as it would be with ``values`` {property name: value (mm,
        degrees, seconds, counts, enumeration text)} in place of the op's own
        (the task panel's preview); the document is not touched."""
        wrapped = {}
        for name, value in values.items():
            kind = PROPERTY_TYPES.get(name, "")
            if kind in ("App::PropertyLength", "App::PropertyDistance"):
                value = FreeCAD.Units.Quantity(float(value), FreeCAD.Units.Length)
            elif kind == "App::PropertyAngle":
                value = FreeCAD.Units.Quantity(float(value), FreeCAD.Units.Angle)
            wrapped[name] = value
        return self.plan(_WithValues(obj, wrapped))

    def cycles(self, obj):
        """[(Cycle93, Settings, start MachineState)] of every groove, in order:
        what a post needs to write the native calls (the start point is where
        the tool must stand before each call; GroovePlan.link says how the op
        got there)."""
        return [(p.cycle, p.settings, p.start) for p in self.current_plan(obj)]

    def commands(self, obj, plans):
        """Path commands for ``plans``: G18, then per groove a comment, the
        link rapids and the expanded moves."""
        tc = getattr(obj, "ToolController", None)
        f = tc.HorizFeed.Value if tc is not None else 0.0
        out = [Path.Command("G18")]
        for p in plans:
            out.append(Path.Command(_comment("%s groove %d: %s" % (p.face.name, p.index + 1, p.cycle.emit()))))
            for x, z in p.link:
                params = {}
                if x is not None:
                    params["X"] = x
                if z is not None:
                    params["Z"] = z
                out.append(Path.Command("G0", params))
            for m in p.moves:
                if m.kind == RAPID:
                    out.append(Path.Command("G0", {"X": m.x, "Z": m.z}))
                elif m.kind == FEED:
                    out.append(Path.Command("G1", {"X": m.x, "Z": m.z, "F": f}))
                elif m.kind == DWELL:
                    out.append(Path.Command("G4", {"P": m.p}))
        return out


def _corner(obj, name):
    kind = getattr(obj, name + "Type")
    size = getattr(obj, name).Value
    if kind == "Radius":
        return size
    if kind == "Chamfer":
        return -size if size else 0.0
    return 0.0


def _check_on_face(face, geo, index, position):
    """The finished groove must lie on the face: not past its ends, not below the axis."""
    tol = 1e-6
    region = geo.region_world()
    xs = [x for x, _z in region]
    zs = [z for _x, z in region]
    what = "%s: groove %d (Position %s mm)" % (face.name, index + 1, format_value(float(position)))
    placement = ("Position",) if index == 0 else ("Position", "Pitch", "GrooveCount")
    if face.longitudinal:
        if min(zs) < face.z_min - tol or max(zs) > face.z_max + tol:
            raise GrooveInputError(
                "%s spans Z %s..%s, past the face (Z %s..%s)"
                % (what, format_value(min(zs)), format_value(max(zs)), format_value(face.z_min), format_value(face.z_max)),
                placement,
            )
        if min(xs) < -tol:
            raise GrooveInputError("%s reaches X %s, past the axis" % (what, format_value(min(xs))), ("Depth",))
    elif min(xs) < face.r_min - tol or max(xs) > face.r_max + tol:
        raise GrooveInputError(
            "%s spans radius %s..%s, past the face (radius %s..%s)"
            % (what, format_value(min(xs)), format_value(max(xs)), format_value(face.r_min), format_value(face.r_max)),
            placement,
        )


def _level(geo, us, u_first):
    """The clearance level the cycle approaches at between us and u_first."""
    vrt = geo.params["VRT"]
    return max(geo.clearance(u_first), max(geo.contour_top(us), geo.contour_top(u_first)) + vrt)


def _candidates(face, geo, settings, env):
    """Start points to try, best first: [((x, z), on)]."""
    frame = geo.frame
    tool = settings.tool
    w, off = tool.width, tool.reference_offset
    u_first = geo.plunge_positions()[0]
    out = []
    if face.longitudinal and face.external:
        out.append(((env.r_safe, frame.blade(u_first, 0.0)[1]), SIDE))
    elif face.longitudinal:
        for z_ref, on in ((env.z_top + off, TOP), (env.z_bottom - w + off, BOTTOM)):
            us = frame.blade_of(frame.x0, z_ref)[0]
            x = frame.blade(us, _level(geo, us, u_first))[0]
            if x >= 0:
                out.append(((x, z_ref), on))
    else:
        x_ref = env.r_safe + off
        us = frame.blade_of(x_ref, frame.z0)[0]
        out.append(((x_ref, frame.blade(us, _level(geo, us, u_first))[1]), SIDE))
        x_col = frame.blade(u_first, 0.0)[0]
        out.append(((x_col, env.z_top if face.external else env.z_bottom), TOP if face.external else BOTTOM))
    return out


def _rapids_clear(env, start, moves):
    """The approach (rapids up to the first feed) and the final retreat (the
    rapids after the one that leaves the groove) stay out of the model."""
    kinds = [m.kind for m in moves]
    if FEED not in kinds:
        return True
    first = kinds.index(FEED)
    pts = [start] + [(m.x, m.z) for m in moves[:first]]
    last = len(kinds) - 1 - [k != RAPID for k in reversed(kinds)].index(True)
    retreat = [(m.x, m.z) for m in moves[last + 1:]]
    for seq in (pts, retreat):
        for a, b in zip(seq, seq[1:]):
            if env.hits(a, b):
                return False
    return True


def _start_and_moves(face, geo, call, settings, env, feed, index):
    error = None
    tried = []
    for (x, z), on in _candidates(face, geo, settings, env):
        start = MachineState(x=x, z=z, feed=feed, feed_per_rev=False, metric=True)
        try:
            moves = call.expand(start, settings)
        except CycleError as e:
            error = e
            continue
        if _rapids_clear(env, (x, z), moves):
            return start, on, moves
        tried.append("X%s Z%s" % (format_value(x), format_value(z)))
    if error is not None and not tried:
        raise error
    raise ValueError(
        "%s: groove %d: every approach passes through the part (tried from %s); "
        "the groove cannot be reached from outside the model"
        % (face.name, index + 1, ", ".join(tried) or "nowhere")
    )


def Create(name, obj=None, parentJob=None, tool_controller=None):
    """Create(name, obj=None, parentJob=None) ... a Groove operation
    (Path::FeaturePython with an ObjectGroove proxy), added to ``parentJob``
    (or the document's only Job). With the GUI up it also gets its view
    provider (freecad_groove.hooks.view_provider_factory)."""
    if obj is None:
        doc = parentJob.Document if parentJob is not None else FreeCAD.ActiveDocument
        obj = doc.addObject("Path::FeaturePython", name)
    obj.Proxy = ObjectGroove(obj, name, parentJob, tool_controller)
    if hooks.view_provider_factory is not None and getattr(obj, "ViewObject", None) is not None:
        hooks.view_provider_factory(obj)
    return obj
