"""The Groove operation: CYCLE93 grooves on faces of a turned part.

Headless layer: FreeCAD, Part and Path only (no Qt, no FreeCADGui), so jobs
can be built and recomputed by scripts and in ``freecadcmd``. The class path
``freecad_groove.ops.groove.op.ObjectGroove`` is stored in every document
saved since the ops moved here; documents saved before store
``freecad_groove.freecad.groove_op.ObjectGroove``, which that module keeps
as a shim. Neither may move.

Coordinates: the part turns about the Job's Z axis (the global Z axis through
the origin). The op's Path is in the G18 plane: X = radius in model
coordinates, Z; never Y. Its moves drive the blade's reference corner
(docs/choices.md, "Conventions").

What the op does with each face in ``Base`` (see faces.py for the reading of
the face) and each of ``GrooveCount`` grooves:

1. It derives one CYCLE93 call (here; the corners' values: properties.py). TYP is "right": 5 longitudinal
   external, 7 longitudinal internal, 6 face external, 8 face internal (+10
   when ChamferMeasure is CHR). The start point AXFA/AXSA is the groove's
   start edge on the face's contour: ``Position`` from the face's +Z end for
   longitudinal grooves (measured along Z, i.e. paraxially, also on cones),
   from its outer edge toward the axis for face grooves (measured along X).
   Groove k (0-based) sits at ``Position + k * Pitch``. ANGC comes from the
   face.
2. It plans the groove (plan.py): checks the finished groove lies on
   the face, picks a start point outside the part whose approach and retreat
   rapids stay out of the model, and expands the call there with the engine.
3. Rapids link the grooves along the safe envelope around the model
   (links.py): the cylinder X = R + c and the planes Z = Zmax + c and
   Z = Zmin - c (R the model's largest radius, c the clearance: Retract,
   0 = 1 mm), moving one axis at a time. The first groove's link starts with
   G0 to the safe start point (Xs, Zs) = (Rs + c, Zs_max + c), Rs and Zs_max
   the largest radius and +Z end of the Job's stock and model together (the
   model alone without stock), then one axis at a time: G0 Z along the
   outside of the stock, then G0 X in, to a start point on the cylinder or
   below the part; G0 X above the stock, then G0 Z down, to one beyond the
   +Z end (internal and face grooves). After the last groove the op goes
   back to the safe start point the same way, reversed (links.py retreat),
   so the tool ends at clearance as after CAM's own ops.
   Apart from that the stock is not taken into account: the op assumes the
   part was turned to the model's contour before grooving.

The Path: a comment with the op's label (the base class), G18, then per
groove a comment naming the face and the call, the link rapids (G0), the
engine's expansion and, after the last groove, the rapids back to the safe
start point. The expansion: G0, G1 with F = the op's feed (cutting.py: FeedPerRev, the
tool controller's HorizFeed, the default) in FreeCAD's internal mm/s like every
CAM op (a feed per revolution at the first groove's spindle speed; the posts
write the op's own feed and spindle, cutting.py), G4 P<seconds>.

Errors (a face that takes no groove, a CycleError from the engine, no room to
approach, a NaN or infinite value) never escape execute: FreeCAD would print
a Python traceback before the message (for a value typed in the property
editor too), and a Python feature of FreeCAD 1.0/1.1 cannot become "Invalid"
without one. As FreeCAD CAM's own ops do, the op reports one error line
"<Label>: <message>" in the report view instead, its Path is replaced by a
comment that repeats the message (no stale toolpath in the 3D view), the
message is kept (op_error(obj), addon_op.py), the posts refuse the op with it, and the
next recompute after a fix clears it. The document and the other objects
stay valid.

FreeCAD objects (the op's document object ``obj``, jobs, tool controllers)
are typed ``object`` below.
"""

from typing import Optional

import FreeCAD

from ...engine import GroovingTool, Settings
from ...engine.cycles.cycle93 import DEFAULT_VRT_MM, Cycle93
from ...engine.numbers import format_value
from ...freecad.addon_op import (  # noqa: F401 - its API
    AddonOp,
    WithValues,
    create_op,
    document_object,
    modelled_part,
    op_error,
    parent_job,
)
from ...freecad.bounds import first_problem
from ...freecad.faces import GrooveFace, analyse_face, element_name
from ...freecad.units import feed_mm_per_min, length_mm
from .bounds import TOOL_BOUNDS
from .cutting import CuttingData, cutting_data
from .kept_plans import KeptPlans
from .links import SafeEnvelope
from .model import MODEL_VALUES, ModelGroove, not_overridden, read_picked_groove, with_model_hint
from .path import path_commands
from .plan import GroovePlan, blade_origin, plan_groove
from .properties import (  # noqa: F401 - this module's API too
    CHAMFER_MEASURES,
    DERIVED,
    MAX_GROOVES,
    PROPERTIES,
    PROPERTY_NAMES,
    PROPERTY_TYPES,
    GrooveInputError,
    check_finite,
    corner_value,
    describe_cycle93_parameter,
    error_properties,
    finite_or_error,
)
from .reach import check_holder_limits, check_reach

# TYP units digit for "right" grooves: (longitudinal, external) -> TYP
TYP_RIGHT = {(True, True): 5, (True, False): 7, (False, True): 6, (False, False): 8}
TYP_CHR = 10  # added to TYP when chamfers are measured along their legs (CHR)


class ObjectGroove(KeptPlans, AddonOp):
    """Proxy of a Groove operation (Path::FeaturePython)."""

    DECLARED_PROPERTIES = PROPERTIES
    POSTED_AS = "groove"  # what the posts recognise it by in one lookup (posts/objects.py: own_groove_op)

    # -- FreeCAD op API ---------------------------------------------------------
    def opOnChanged(self, obj: object, prop: str) -> None:
        """A model value set by hand while ModelGroove is on overrides the model's (ModelOverrides)."""
        if (prop in MODEL_VALUES and getattr(obj, "ModelGroove", False) and not getattr(self, "_writing_model", False)
                and "Restore" not in obj.State and prop not in obj.ModelOverrides):
            obj.ModelOverrides = list(obj.ModelOverrides) + [prop]

    def opExecute(self, obj: object) -> None:
        self._plans = None
        self._saved_plans = None  # what the document held: superseded by this recompute
        self.error = None
        faces = None
        try:
            check_finite(obj)
            model = self._apply_model(obj)  # read once: a model's section costs about 1 ms a face
            faces = [model.face] if model is not None else self.groove_faces(obj)
            self._write_derived(obj, faces)
            plans = self.plan(obj, faces)
            cutting = cutting_data(obj)
        except Exception as e:  # CycleError and input errors are ValueErrors; anything else too
            self._report_error(obj, e, faces is None)
            return
        self.commandlist.extend(self.commands(obj, plans, cutting))
        if obj.FeedsAndSpeeds != cutting.describe():
            obj.FeedsAndSpeeds = cutting.describe()
        self._keep_plans(obj, plans, cutting)
        for plan in plans:  # what the cycles cannot do as programmed: once per recompute
            for text in plan.warning_texts:
                FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, text))

    def _report_error(self, obj: object, error: Exception, clear_derived: bool) -> None:
        """report_error, the derived properties cleared first (``clear_derived``)."""
        if clear_derived:
            self._write_derived(obj, [])
        named = describe_cycle93_parameter(getattr(error, "parameter", None) or "-")
        if named and not str(error).startswith(named):  # the property to fix first, as the posts say it
            error = GrooveInputError("%s: %s" % (named, error), error_properties(error))
        self.report_error(obj, error)

    # -- properties -------------------------------------------------------------
    def _add_missing_properties(self, obj: object) -> None:
        super()._add_missing_properties(obj)
        # Constraints and editor modes are not stored in the document.
        obj.GrooveCount = (max(1, int(obj.GrooveCount)), 1, MAX_GROOVES, 1)
        for name in DERIVED:
            obj.setEditorMode(name, 1)

    def _write_derived(self, obj: object, faces: list[GrooveFace]) -> None:
        if faces:
            first = self.cycle(obj, faces[0], 0)
            kinds = []
            for face in faces:
                if face.describe() not in kinds:
                    kinds.append(face.describe())
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

    # -- grooves read from the model (model.py) -------------------------
    def model_groove(self, obj: object) -> ModelGroove:
        """The modelled groove the picked faces belong to (GrooveInputError naming what does not fit)."""
        try:
            return read_picked_groove([(base.Shape, sub, named.Label) for base, named, sub, _n in self._picked(obj)],
                                      obj.ChamferMeasure == CHAMFER_MEASURES[1])
        except ValueError as e:
            raise GrooveInputError(str(e), ("Base",)) from None

    def _apply_model(self, obj: object) -> Optional[ModelGroove]:
        """ModelGroove: the groove read, its values written (less ModelOverrides), FromModel naming them."""
        values, model = {}, None
        if getattr(obj, "ModelGroove", False):
            model = self.model_groove(obj)
            values = not_overridden(model.values, obj.ModelOverrides)
            self._writing_model = True
            try:
                for name, value in values.items():
                    old = getattr(obj, name)
                    if (abs(old.Value - value) > 1e-12) if hasattr(old, "Value") else old != value:
                        setattr(obj, name, value)
            finally:
                self._writing_model = False
        if hasattr(obj, "FromModel") and list(obj.FromModel) != list(values):
            obj.FromModel = list(values)
        return model

    def in_modelled_groove(self, obj: object) -> bool:
        """Whether a picked face belongs to a groove of the model (the turning check then judges the op by the
        model alone there)."""
        for base, named, sub, _name in self._picked(obj):
            try:
                read_picked_groove([(base.Shape, sub, named.Label)])
            except ValueError:
                continue
            return True
        return False

    # -- deriving the grooves ---------------------------------------------------
    def _picked(self, obj: object) -> list[tuple]:
        """(part, its model object for names, "FaceN", "Label.FaceN") of every picked element."""
        picked = []
        job = parent_job(document_object(obj))
        for base, subs in obj.Base or []:
            if isinstance(subs, str):
                subs = (subs,)
            try:
                named = modelled_part(job, base)
            except ValueError as e:
                raise GrooveInputError(str(e), ("Base",)) from None
            for sub in subs:
                name = element_name(named, sub or "(whole object)")
                if not sub:
                    raise GrooveInputError("%s: pick a face of the part, not the whole object" % name, ("Base",))
                picked.append((base, named, sub, name))
        return picked

    def groove_faces(self, obj: object) -> list[GrooveFace]:
        """GrooveFace of every face in Base (ValueError naming a face that takes
        no groove); with ModelGroove, the contour line of the modelled groove."""
        if getattr(obj, "ModelGroove", False):
            return [self.model_groove(obj).face]
        faces = []
        for base, _named, sub, name in self._picked(obj):
            try:
                shape = base.Shape.getElement(sub)
            except Exception:
                raise GrooveInputError("%s: no such element in the model (did the model change?)" % name,
                                       ("Base",)) from None
            try:
                faces.append(analyse_face(shape, name))
            except ValueError as e:
                raise GrooveInputError(with_model_hint(str(e), base.Shape, sub), ("Base",)) from None
        return faces

    def settings(self, obj: object) -> Settings:
        """Engine Settings: the tool bit's Width/CornerRadius when it has them,
        else the op's ToolWidth/ToolCornerRadius; the op's ReferenceCorner."""
        tool_controller = getattr(obj, "ToolController", None)
        bit = getattr(tool_controller, "Tool", None) if tool_controller is not None else None
        width = obj.ToolWidth.Value
        radius = obj.ToolCornerRadius.Value
        if bit is not None:
            bit_values = {b.name: getattr(bit, b.name) for b in TOOL_BOUNDS if getattr(bit, b.name, None) is not None}
            problem = first_problem(bit_values, TOOL_BOUNDS)
            if problem is not None:
                name, message = problem
                owner = {"Width": "ToolWidth", "CornerRadius": "ToolCornerRadius"}.get(name, "ToolController")
                raise GrooveInputError("the tool bit's %s (%s)" % (message, getattr(bit, "Label", "tool bit")),
                                       (owner,))
            if "Width" in bit_values:
                width = length_mm(bit.Width)
            if "CornerRadius" in bit_values:
                radius = length_mm(bit.CornerRadius)
        if not width > 0:  # no default blade: a wrong width cuts a wrong groove
            raise GrooveInputError(
                "ToolWidth: the blade's width is unknown: the tool controller %s has no grooving blade (its tool "
                "bit has no Width). Create a grooving tool controller (task panel: Tool and coolant) or set "
                "ToolWidth" % getattr(tool_controller, "Label", "(none)"), ("ToolWidth",))
        return Settings(tool=GroovingTool(width=width, corner_radius=radius, reference=str(obj.ReferenceCorner)))

    def position(self, obj: object, index: int) -> float:
        """Position of groove ``index`` (0-based): Position + index * Pitch."""
        return obj.Position.Value + index * obj.Pitch.Value

    def cycle(self, obj: object, face: GrooveFace, index: int) -> Cycle93:
        """The Cycle93 call for groove ``index`` (0-based) on ``face``."""
        radius, z = face.point_at(self.position(obj, index))
        typ = TYP_RIGHT[(face.longitudinal, face.external)]
        if obj.ChamferMeasure == CHAMFER_MEASURES[1]:
            typ += TYP_CHR
        return Cycle93(
            axfa=round(radius, 9) + 0.0, axsa=round(z, 9) + 0.0,
            widg=obj.Width.Value, depg=obj.Depth.Value, angc=round(face.angc, 9),
            ang1=obj.FlankAngle1.Value, ang2=obj.FlankAngle2.Value,
            rco1=corner_value(obj, "EdgeCorner1"), rco2=corner_value(obj, "EdgeCorner2"),
            rci1=corner_value(obj, "BaseCorner1"), rci2=corner_value(obj, "BaseCorner2"),
            fal1=obj.BaseAllowance.Value, fal2=obj.FlankAllowance.Value,
            idep=obj.Infeed.Value, dwt=float(obj.Dwell), typ=typ, vrt=obj.Retract.Value,
        )

    def feed_mm_per_min(self, obj: object) -> Optional[float]:
        """The tool controller's HorizFeed in mm/min (None without a tool controller)."""
        tool_controller = getattr(obj, "ToolController", None)
        if tool_controller is None:
            return None
        feed = finite_or_error(tool_controller.HorizFeed.Value, "%s HorizFeed" % tool_controller.Label, ())
        return feed_mm_per_min(feed)

    def _check_count(self, obj: object) -> int:
        """GrooveCount, refused when below 1 or when Pitch cannot space the grooves."""
        count = int(obj.GrooveCount)
        if count < 1:
            raise GrooveInputError("GrooveCount=%d: must be 1 or more" % count, ("GrooveCount",))
        if count > 1 and not obj.Pitch.Value > 0:
            raise GrooveInputError(
                "Pitch=%s: must be greater than 0 with GrooveCount %d" % (format_value(obj.Pitch.Value), count),
                ("Pitch",),
            )
        return count

    def _parent_job(self, obj: object) -> object:
        """The Job the op is in (ValueError when it is in none)."""
        job = parent_job(document_object(obj))
        if job is None:
            raise ValueError("%s is not in a Job" % obj.Label)
        return job

    def envelope(self, obj: object, job: object) -> SafeEnvelope:
        """The safe envelope around ``job``'s model, with the op's Retract (0 = 1 mm) as clearance."""
        clearance = obj.Retract.Value or DEFAULT_VRT_MM
        return SafeEnvelope([model.Shape for model in job.Model.Group if hasattr(model, "Shape")], clearance)

    def plan(self, obj: object, faces: Optional[list[GrooveFace]] = None) -> list[GroovePlan]:
        """Every groove the op cuts, in order: [GroovePlan]. Raises ValueError
        (CycleError from the engine) when one cannot be cut."""
        if faces is None:
            check_finite(obj)
            faces = self.groove_faces(obj)
        if not faces:
            raise GrooveInputError("Base: no face picked: pick the face(s) to groove (nothing to cut)", ("Base",))
        count = self._check_count(obj)
        job = self._parent_job(obj)
        self.check_tool(obj)
        settings = self.settings(obj)
        check_reach(obj)
        envelope = self.envelope(obj, job)
        feed = self.feed_mm_per_min(obj)
        stock = getattr(getattr(job, "Stock", None), "Shape", None)
        origin = envelope.safe_start(stock)
        plans = []
        for face in faces:
            for index in range(count):
                call = self.cycle(obj, face, index)
                previous = plans[-1] if plans else None
                plans.append(plan_groove(face, index, self.position(obj, index), call, settings, envelope, feed,
                                         previous, origin))
        check_holder_limits(obj, plans)
        last = plans[-1]
        last.retreat = envelope.retreat(last.start_point, last.start_on, blade_origin(origin, last.cycle, settings))
        return plans

    def plan_with(self, obj: object, values: dict) -> list[GroovePlan]:
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
        return self.plan(WithValues(obj, wrapped))

    def cycles(self, obj: object) -> list[tuple]:
        """[(Cycle93, Settings, start MachineState)] of every groove, in order:
        what a post needs to write the native calls (the start point is where
        the tool must stand before each call; GroovePlan.link says how the op
        got there)."""
        return [(plan.cycle, plan.settings, plan.start) for plan in self.current_plan(obj)]

    def commands(self, obj: object, plans: list[GroovePlan], cutting: Optional[CuttingData] = None) -> list:
        """Path commands for ``plans`` (path_commands), feeds at the op's
        feed (cutting.py) in mm/s: a feed per revolution at the spindle speed
        of the first groove's start radius."""
        cutting = cutting or cutting_data(obj)
        radius = plans[0].cycle.axfa if plans else 0.0
        return path_commands(plans, cutting.feed_mm_per_s(radius))


def SetupProperties() -> list:
    """The op properties a Job's SetupSheet may hold defaults for: none (a
    groove's size belongs to its face, the blade's to the tool controller)."""
    return []


def Create(name: str, obj: object = None, parentJob: object = None, tool_controller: object = None) -> object:
    """Create(name, obj=None, parentJob=None) ... a Groove operation
    (Path::FeaturePython with an ObjectGroove proxy), added to ``parentJob``
    (or the document's only Job). With the GUI up it also gets its view
    provider (the one the GUI bound to its kind, ops/registry.py)."""
    return create_op(ObjectGroove, name, obj, parentJob, tool_controller)
