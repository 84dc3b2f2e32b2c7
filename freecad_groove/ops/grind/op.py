"""The Plunge grind operation: an Allen-Bradley 9/Series G83/G83.1 plunge
surface grind of one flat face.

Headless layer: FreeCAD, Part and Path only. The class path
``freecad_groove.ops.grind.op.ObjectPlungeGrind`` is stored in every document
saved since the ops moved here; documents saved before store
``freecad_groove.freecad.plunge_grind_op.ObjectPlungeGrind``, which that
module keeps as a shim. Neither may move.

Axes (docs/plunge-grind.md): the face is planar and looks up (+Z); the
wheel reciprocates along FreeCAD X (ReciprocationAxis, or Y), crosses over
along the other of X and Y and plunges down along -Z. In the G83's words:
X/I = FreeCAD X, Y = FreeCAD Z, Z = FreeCAD Y (GrindPlan.axes "XZY"; with
ReciprocationAxis Y: "YZX"). The grinder posts write with the same mapping
(their --axes must agree). The Path drives the lowest point of the wheel's
periphery at the middle of its width.

The call (all absolute, G90): the reversal points I = the face's low end
along ReciprocationAxis - Overtravel (the start) and X = its high end +
Overtravel; the crossover from the wheel flush with the face's low edge
across it (start) to flush with its high edge (Z);
a face narrower than the wheel gets no crossover (the wheel centred on it).
The start height is the face + Allowance + StartClearance; Y = the face.
J, Q, K, R, L, F, E, P, D and G83.1 come from the properties
(properties.py).

The model must not rise above the face where the wheel's lowest point passes
(between the reversal points, over the crossover and its half width, up to
the safe height), nor enter what the wheel's body sweeps above that point
(clearance.py: a wall beside the face within the wheel's radius of a
reversal point): the op refuses such a face (naming Base and Overtravel).
The body is checked with the tool bit's Diameter (a grinding wheel bit: one
with a Width), else WheelDiameter; with neither it is not checked, and the
plan says so in a warning (the report view, the task panel).

The Path (path.py): G17, a comment with the call, down from the safe height
to the start, the engine's expansion, back up to the safe height.

Errors never escape execute (as in the Groove op): one line "<Label>: <message>"
naming the property, the Path a comment repeating it, op_error(obj) keeps it.
"""

import math
from typing import Optional

import FreeCAD
import Part
import PathScripts.PathUtils as PathUtils

from ...engine.cycles.ab_g83 import G83, G83_1
from ...engine.errors import CycleError
from ...engine.moves import MachineState
from ...freecad.addon_op import AddonOp, create_op, modelled_part, op_error  # noqa: F401 - its API
from ...freecad.bounds import check_bounds
from ...freecad.units import SECONDS_PER_MINUTE, length_mm
from .clearance import CLEAR_ABOVE_MM, check_wheel_body, wheel_sweep
from .path import path_commands
from .plan import TOLERANCE, FlatFace, GrindPlan, read_face, rounded
from .properties import BOUNDS, DERIVED, MAX_WORD, PROPERTIES, WORD_PROPERTIES, GrindInputError


def _named(error: CycleError) -> GrindInputError:
    """An engine error with the op property its word comes from named first."""
    prop = WORD_PROPERTIES.get(error.parameter)
    if prop is None:
        return GrindInputError(str(error))
    return GrindInputError("%s: %s" % (prop, error), (prop,))


class ObjectPlungeGrind(AddonOp):
    """Proxy of a Plunge grind operation (Path::FeaturePython)."""

    DECLARED_PROPERTIES = PROPERTIES

    # -- FreeCAD op API ---------------------------------------------------------
    def opExecute(self, obj: object) -> None:
        self.error = None
        self._plan = None
        try:
            plan = self.plan(obj)
        except Exception as e:  # input and engine errors are ValueErrors; anything else is reported too
            self._report_error(obj, e)
            return
        self._plan = plan
        for warning in plan.warnings:
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, warning))
        if obj.GrindCall != plan.call.emit():
            obj.GrindCall = plan.call.emit()
        self.commandlist.extend(path_commands(plan))

    def _report_error(self, obj: object, error: Exception) -> None:
        if obj.GrindCall:
            obj.GrindCall = ""
        self.report_error(obj, error)

    def _add_missing_properties(self, obj: object) -> None:
        super()._add_missing_properties(obj)
        for name in DERIVED:
            obj.setEditorMode(name, 1)

    # -- the plan ---------------------------------------------------------------
    def current_plan(self, obj: object) -> GrindPlan:
        """The plan of the last recompute while nothing touched the op, else a fresh one (the posts' entry)."""
        plan = getattr(self, "_plan", None)
        if plan is not None and getattr(self, "error", None) is None and not ({"Touched", "Invalid"} & set(obj.State)) \
                and not self.tool_changed(obj):
            return plan
        return self.plan(obj)

    def face(self, obj: object) -> FlatFace:
        """The one picked face (GrindInputError naming Base otherwise)."""
        pairs = obj.Base or []
        picked = [(base, sub) for base, subs in pairs for sub in ((subs,) if isinstance(subs, str) else subs)]
        if len(picked) != 1:
            raise GrindInputError("Base: pick exactly one flat face (%d picked)" % len(picked), ("Base",))
        base, sub = picked[0]
        job = PathUtils.findParentJob(obj)
        try:
            named = modelled_part(job, base)  # the user's object, not the clone
        except ValueError as e:
            raise GrindInputError(str(e), ("Base",)) from None
        name = "%s.%s" % (named.Label, sub)
        try:
            shape = base.Shape.getElement(sub)
        except Exception:
            raise GrindInputError("%s: no such element in the model (did the model change?)" % name,
                                  ("Base",)) from None
        return read_face(shape, name)

    def wheel_width(self, obj: object) -> float:
        """The tool bit's Width, else WheelWidth; GrindInputError when neither is above 0."""
        bit = getattr(getattr(obj, "ToolController", None), "Tool", None)
        width = length_mm(bit.Width) if getattr(bit, "Width", None) is not None else obj.WheelWidth.Value
        if not (math.isfinite(width) and width < MAX_WORD):
            raise GrindInputError("WheelWidth: the tool bit's Width=%s: must be a length below %g mm"
                                  % (width, MAX_WORD), ("WheelWidth",))
        if not width > 0:
            raise GrindInputError("WheelWidth: the wheel's width is unknown: the tool bit has no Width (use a "
                                  "grinding wheel tool bit) and WheelWidth is 0", ("WheelWidth",))
        return width

    def feeds(self, obj: object) -> tuple:
        """(F, E) in mm/min: the op's PlungeFeed/ReciprocationFeed, 0 = the tool controller's VertFeed/HorizFeed."""
        tc = getattr(obj, "ToolController", None)
        out = []
        for prop, tc_prop in (("PlungeFeed", "VertFeed"), ("ReciprocationFeed", "HorizFeed")):
            value = getattr(obj, prop).Value
            if not (value >= 0 and math.isfinite(value)):
                raise GrindInputError("%s=%s mm/s: must be a finite feed, 0 or more" % (prop, value), (prop,))
            if value == 0 and tc is not None:
                value = getattr(tc, tc_prop).Value
            if not (value > 0 and math.isfinite(value)):
                raise GrindInputError("%s=0: no feed (the tool controller's %s is %s): set %s"
                                      % (prop, tc_prop, value, prop), (prop,))
            out.append(value * SECONDS_PER_MINUTE)
        return tuple(out)

    def _check(self, obj: object, width: float) -> tuple:
        """(K, R) with their defaults; GrindInputError naming a property that breaks a rule."""
        for name in ("Allowance", "PlungePick", "Overtravel", "StartClearance", "Retract", "CrossoverPlungePick",
                     "CrossPick", "SecondaryCrossPick"):
            value = getattr(obj, name).Value
            if value < 0 or value != value or value in (float("inf"), float("-inf")):
                raise GrindInputError("%s=%s: must be a finite length, 0 or more" % (name, value), (name,))
        for name in ("Allowance", "PlungePick"):
            if not getattr(obj, name).Value > 0:
                raise GrindInputError("%s=0: must be greater than 0" % name, (name,))
        k = obj.CrossPick.Value or width / 2
        r = obj.SecondaryCrossPick.Value or k
        for name, value in (("CrossPick", k), ("SecondaryCrossPick", r)):
            if value > width + TOLERANCE:
                raise GrindInputError("%s=%g: must be at most the wheel's width %g (the strokes would leave "
                                      "ridges)" % (name, value, width), (name,))
        return k, r

    def call(self, obj: object, face: FlatFace, width: float) -> tuple:
        """(G83 or G83_1 call, start MachineState) for ``face`` (see the module notes)."""
        k, r = self._check(obj, width)
        feed, recip_feed = self.feeds(obj)
        length_from, length_to, width_from, width_to = face.along(str(obj.ReciprocationAxis))
        start_x = length_from - obj.Overtravel.Value
        if width_to - width_from > width + TOLERANCE:
            cross_start, cross_end = width_from + width / 2, width_to - width / 2
        else:
            cross_start = cross_end = (width_from + width_to) / 2
        start_y = rounded(face.z + obj.Allowance.Value + obj.StartClearance.Value)
        kind = G83_1 if obj.DressFirst else G83
        words = dict(X=length_to + obj.Overtravel.Value, I=start_x, Y=face.z, J=obj.PlungePick.Value,
                     Z=cross_end, K=k, R=r if r != k else None, Q=obj.CrossoverPlungePick.Value or None,
                     L=int(obj.SparkOutPasses), F=feed, E=recip_feed, P=int(obj.DressProgram) or None,
                     D=int(obj.DressCount) or None)
        start = MachineState(x=rounded(start_x), z=rounded(cross_start), y=start_y, feed=feed, diameter_mode=False)
        try:
            return kind(**{key: rounded(value) for key, value in words.items()}).validate(), start
        except CycleError as e:
            raise _named(e) from None

    def plan(self, obj: object) -> GrindPlan:
        """The GrindPlan of ``obj``; GrindInputError naming the property to fix."""
        check_bounds(obj, BOUNDS, GrindInputError)
        face = self.face(obj)
        self.check_tool(obj)
        width = self.wheel_width(obj)
        call, start = self.call(obj, face, width)
        try:
            moves = call.expand(start)
        except CycleError as e:
            raise _named(e) from None
        safe = self.safe_z(obj) + obj.Retract.Value
        axes = "YZX" if str(obj.ReciprocationAxis) == "Y" else "XZY"
        self.check_clear(obj, face, call, start, width, safe, axes)
        diameter = self.wheel_diameter(obj)
        if diameter is None:
            warnings = ["WheelDiameter: the wheel's diameter is unknown (the tool bit has no Width: not a grinding "
                        "wheel bit; WheelDiameter is 0): its body above the lowest point is not checked against "
                        "the part"]
        else:
            warnings = []
            low, high = sorted((start.z, call.Z))
            sweep = wheel_sweep(axes, (call.I, call.X), (low - width / 2, high + width / 2), face.z, start.y, safe,
                                diameter / 2)
            check_wheel_body(PathUtils.findParentJob(obj), face.name, sweep, diameter)
        return GrindPlan(call, start, moves, safe, face.name, axes, warnings)

    def wheel_diameter(self, obj: object) -> Optional[float]:
        """The grinding wheel bit's Diameter (a bit with a Width), else WheelDiameter; None when unknown."""
        bit = getattr(getattr(obj, "ToolController", None), "Tool", None)
        if getattr(bit, "Width", None) is not None and getattr(bit, "Diameter", None) is not None:
            diameter = length_mm(bit.Diameter)
        else:
            diameter = obj.WheelDiameter.Value
        if not (diameter >= 0 and math.isfinite(diameter)):
            raise GrindInputError("WheelDiameter=%s: must be a finite length, 0 or more" % diameter,
                                  ("WheelDiameter",))
        return diameter if diameter > 0 else None

    def check_clear(self, obj: object, face: FlatFace, call: G83, start: MachineState, width: float,
                    safe: float, axes: str) -> None:
        """GrindInputError (naming Base and Overtravel) when the model rises above the face anywhere the
        wheel's lowest point passes over it, between the reversal points and over the crossover, up to the
        safe height: a wall within the overtravel, or a face that is the floor of a pocket."""
        low, high = sorted((start.z, call.Z))
        spans = {axes[0]: sorted((call.I, call.X)), axes[2]: [low - width / 2, high + width / 2]}
        (x0, x1), (y0, y1) = spans["X"], spans["Y"]
        height = safe - face.z - CLEAR_ABOVE_MM
        if height <= 0:
            return
        sweep = Part.makeBox(x1 - x0, y1 - y0, height, FreeCAD.Vector(x0, y0, face.z + CLEAR_ABOVE_MM))
        job = PathUtils.findParentJob(obj)
        for model in job.Model.Group:
            shape = getattr(model, "Shape", None)
            if shape is not None and not shape.isNull() and shape.common(sweep).Volume > 1e-6:
                raise GrindInputError(
                    "Base: the wheel's path over %s (X%g..%g, Y%g..%g) meets %s above the face: a wall within the "
                    "Overtravel or a pocket floor (reduce Overtravel, or grind another face)"
                    % (face.name, x0, x1, y0, y1, modelled_part(job, model).Label),
                    ("Base", "Overtravel"))

    def safe_z(self, obj: object) -> float:
        """The top of the Job's stock and model (ValueError when the op is in no Job)."""
        job = PathUtils.findParentJob(obj)
        if job is None:
            raise ValueError("%s is not in a Job" % obj.Label)
        shapes = [m.Shape for m in job.Model.Group if hasattr(m, "Shape")]
        stock = getattr(getattr(job, "Stock", None), "Shape", None)
        if stock is not None and not stock.isNull():
            shapes.append(stock)
        return max(s.BoundBox.ZMax for s in shapes)


def SetupProperties() -> list:
    """No op property takes a SetupSheet default (the face gives the grind)."""
    return []


def Create(name: str, obj: object = None, parentJob: object = None, tool_controller: object = None) -> object:
    """A Plunge grind operation (Path::FeaturePython with an ObjectPlungeGrind proxy) in ``parentJob``; with the
    GUI up, its view provider (gui/view.py, bound to its kind by the GUI: ops/registry.py)."""
    return create_op(ObjectPlungeGrind, name, obj, parentJob, tool_controller)
