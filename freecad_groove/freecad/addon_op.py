"""What the add-on's operations (freecad_groove/ops/: Groove, Cylinder slot,
Plunge grind) share on CAM's op framework (Path.Op.Base.ObjectOp): the tool
controller they are made with, their features, their properties added on
creation and on restore (a document saved by an older version gets the new
ones), and no milling depths; the one-line report of an op that cannot cut
(report_error, op_error) and the Path comment it leaves; an op seen with a
task panel's values (WithValues); making an op with its view provider
(create_op) and registering its kind with CAM's SetupSheet (register_op_kind:
when its proxy class is made, from its declaration, ops/registry.py), with
the prototype CAM's SetupSheet editor reads its defaults from
(setup_prototype).

Not stored in documents (each op's own class is): free to move.

FreeCAD layer: FreeCAD's CAM only.
"""

import math
import traceback
from typing import Optional

import FreeCAD
import Path
import Path.Op.Base as PathOp

from ..ops import registry
from .changes import read_once


def comment_body(text: str) -> str:
    """A Path comment body: FreeCAD drops inner parentheses."""
    return "(%s)" % text.replace("(", "[").replace(")", "]")


def op_error(obj: object) -> Optional[str]:
    """Why the op ``obj`` made nothing at its last recompute (None: it is fine): the message it reported,
    the tool it has no more when that changed since (the posts refuse it too), or FreeCAD's status of an
    invalid object."""
    proxy = getattr(obj, "Proxy", None)
    error = getattr(proxy, "error", None)
    if error:
        return error
    if isinstance(proxy, AddonOp) and proxy.tool_changed(obj):  # FreeCAD did not recompute the op since
        problem = cannot_run(obj)  # (a tool controller that lost its tool is Invalid: its ops wait for it)
        if problem is not None:
            return str(problem)
    return None if obj.isValid() else obj.getStatusString()


def modelled_part(job: object, model: object) -> object:
    """The object the user modelled that ``model`` (an object of the Job's model, usually its clone) was made
    from, for names; ValueError naming Base when that part is gone (deleted: the clone has nothing to read
    it from, and CAM's own lookup fails with an IndexError)."""
    if job is None:
        return model
    try:
        return job.Proxy.baseObject(job, model)
    except (IndexError, AttributeError, ReferenceError):
        raise ModelGoneError("Base: %s: the part the Job's model was made from is gone (deleted?): add the part "
                             "to the Job again and pick its faces" % getattr(model, "Label", model)) from None


class ModelGoneError(ValueError):
    """The Job's model lost the part it was made from; ``properties`` names Base (the task panels mark it)."""

    properties = ("Base",)


# Tool controller properties a change of which changes what an op makes (with every length of its tool bit).
TOOL_CONTROLLER_VALUES = ("ToolNumber", "HorizFeed", "VertFeed", "SpindleSpeed", "SpindleDir")


def tool_signature(obj: object) -> tuple:
    """What the op ``obj`` reads of its tool controller and tool bit, to compare (FreeCAD does not recompute an
    op when only its tool bit changed): their names, the tool controller's feeds and speeds, the bit's lengths;
    each object read again only after it changed (changes.read_once: FreeCAD asks at every recompute)."""
    tc = getattr(obj, "ToolController", None)
    if tc is None:
        return (None,)
    tc_values, tool = read_once(tc, "tool signature", _tool_controller_values)
    if tool is None:
        return (tc.Name, None, tc_values)
    return (tc.Name, tool.Name, tc_values, read_once(tool, "tool signature", _tool_lengths))


def _tool_controller_values(tc: object) -> tuple:
    """(the tool controller's TOOL_CONTROLLER_VALUES as text, its tool bit)."""
    return tuple(str(getattr(tc, name, None)) for name in TOOL_CONTROLLER_VALUES), getattr(tc, "Tool", None)


def _tool_lengths(tool: object) -> tuple:
    """((name, length), ...) of every length of the tool bit ``tool``."""
    lengths = []
    for name in sorted(getattr(tool, "PropertiesList", ())):
        try:
            value = getattr(tool, name)
        except Exception:  # a property FreeCAD cannot read back: not a size of the tool
            continue
        if hasattr(value, "Value") and hasattr(value, "Unit"):
            lengths.append((name, repr(float(value.Value))))
    return tuple(lengths)


class ToolError(ValueError):
    """The op's tool controller or tool cannot cut; ``properties`` names ToolController (the panels mark it)."""

    properties = ("ToolController",)


def parent_job(obj: object) -> object:
    """The Job ``obj`` (an op, or a Job) is in, None when in none: CAM's PathUtils.findParentJob without its
    Path.Log.track(), which takes a stack trace at every call (0.2-0.7 ms; a recompute asked several times)."""
    import Path.Main.Job as PathJob

    if isinstance(getattr(obj, "Proxy", None), PathJob.ObjectJob):
        return obj
    for parent in obj.InList:
        if isinstance(getattr(parent, "Proxy", None), PathJob.ObjectJob):
            return parent
        if parent.TypeId in ("Path::FeaturePython", "Path::FeatureCompoundPython", "App::DocumentObjectGroup"):
            job = parent_job(parent)
            if job is not None:
                return job
    return None


def cannot_run(obj: object) -> Optional[ValueError]:
    """Why CAM's own execute would return before the op's opExecute, keeping the old Path (None: it runs it):
    a Job whose model is empty (its clones deleted), or a tool problem (tool_problem)."""
    job = parent_job(obj)
    if job is not None and not job.Model.Group:
        return ModelGoneError("Base: the Job %s has no model left (deleted?): nothing to cut" % job.Label)
    return tool_problem(obj)


def tool_problem(obj: object) -> Optional[ToolError]:
    """Why the op ``obj`` has no tool to cut with (None: it has one): no tool controller, a tool controller
    without a tool bit or with tool number 0, a bit whose Diameter is 0 or not a finite length."""
    tc = getattr(obj, "ToolController", None)
    if tc is None:
        return ToolError("ToolController: none: pick the tool controller the op cuts with")
    tool = getattr(tc, "Tool", None)
    if tool is None:
        return ToolError("ToolController: %s has no tool bit: give it one" % tc.Label)
    if int(getattr(tc, "ToolNumber", 1)) == 0:
        return ToolError("ToolController: %s has tool number 0: give it the tool's number" % tc.Label)
    diameter = getattr(tool, "Diameter", None)
    value = float(diameter.Value) if hasattr(diameter, "Value") else float(diameter or 0.0)
    if not (math.isfinite(value) and 0.0 < value < 1.0e6):
        return ToolError("ToolController: %s's tool bit %s has Diameter=%s: must be a length greater than 0 and "
                         "less than 1e6 mm" % (tc.Label, tool.Label, "%g" % value if math.isfinite(value) else value))
    return None


class WithValues:
    """An op object seen with some property values replaced: the op's plan()
    on it shows what the op would make with a task panel's values, without
    writing them to the document."""

    def __init__(self, obj: object, values: dict):
        self._obj = obj
        self._values = values

    def __getattr__(self, name: str) -> object:
        values = self.__dict__["_values"]
        if name in values:
            return values[name]
        return getattr(self.__dict__["_obj"], name)


def document_object(obj: object) -> object:
    """The FreeCAD object behind ``obj`` (itself, or what WithValues wraps)."""
    return obj._obj if isinstance(obj, WithValues) else obj


class AddonOp(PathOp.ObjectOp):
    """Base of the add-on's op proxies. A subclass is the proxy an op's
    declaration names (ops/registry.py: OpKind.proxy); made, it gets that
    declaration as KIND (whose name is the op's kind, which CAM's SetupSheet
    registry looks it up by, not the object's name) and its kind joins CAM's
    SetupSheet registry (register_op_kind). It sets FEATURES (names of
    Path.Op.Base feature flags) and DECLARED_PROPERTIES, and extends
    _add_missing_properties with what it sets at every opening."""

    KIND = None  # the op's declaration (registry.OpKind), set when the subclass is made
    FEATURES = ("FeatureTool", "FeatureBaseFaces", "FeatureCoolant")
    # The op's own properties as declared, (type, name, group, tooltip, default) each: what a new op gets, and
    # what CAM's SetupSheet editor shows of those the op's SetupProperties() name (setup_prototype).
    DECLARED_PROPERTIES: tuple = ()

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        kind = registry.kind_of(cls)
        if kind is None and cls.KIND is None:
            raise TypeError("%s.%s: no op declares it as its proxy (ops/registry.py)" % (cls.__module__,
                                                                                          cls.__qualname__))
        if kind is not None:  # a subclass of a declared proxy keeps its kind
            cls.KIND = kind
            register_op_kind(kind, cls)

    def __init__(self, obj: object, name: str, parentJob: object = None, tool_controller: object = None):
        # The base class picks a tool controller while it is built; headless,
        # with several in the job and no GUI to ask, FreeCAD's picker fails,
        # so it is steered to this one (see isToolSupported).
        if tool_controller is None and parentJob is not None and getattr(parentJob, "Tools", None):
            group = parentJob.Tools.Group
            tool_controller = group[0] if group else None
        self._tc_hint = tool_controller
        try:
            super().__init__(obj, self.KIND.name, parentJob)
        finally:
            self._tc_hint = None
        if tool_controller is not None and getattr(obj, "ToolController", None) is None:
            obj.ToolController = tool_controller

    def opFeatures(self, obj: object) -> int:
        flags = 0
        for name in self.FEATURES:
            flags |= getattr(PathOp, name, 0)
        return flags

    def initOperation(self, obj: object) -> None:
        self._add_missing_properties(obj)

    def opOnDocumentRestored(self, obj: object) -> None:
        self._add_missing_properties(obj)

    def opSetDefaultValues(self, obj: object, job: object) -> None:
        pass

    def opUpdateDepths(self, obj: object) -> None:
        """CAM's milling depth logic works on the Z bounding box; these ops'
        depths are their own (a groove's, a slot's along X, a ground face's)."""

    def isToolSupported(self, obj: object, tool: object) -> bool:
        hint = getattr(self, "_tc_hint", None)
        return tool == hint.Tool if hint is not None else True

    def execute(self, obj: object) -> None:
        """CAM's execute, remembering the tool it ran with (mustExecute). CAM's own returns early, the old Path
        kept, when the Job's model is empty or the tool controller has no tool or its Diameter is 0 (cannot_run):
        then the op's opExecute runs here instead, and its plan refuses the tool (check_tool) or the missing
        faces as any other error."""
        self._tool_seen = tool_signature(obj)
        try:
            problem = cannot_run(obj) if getattr(obj, "Active", True) else None
        except Exception as e:  # a tool FreeCAD cannot read: the same refusal
            problem = ToolError("ToolController: its tool cannot be read (%s: %s)" % (type(e).__name__, e))
        if problem is None:
            super().execute(obj)
            return
        self.commandlist = [Path.Command("(%s)" % obj.Label)]
        self.opExecute(obj)
        if getattr(self, "error", None) is None:  # an opExecute that does not plan: refuse here
            self.report_error(obj, problem)
        obj.Path = Path.Path(self.commandlist)

    def check_tool(self, obj: object) -> None:
        """ToolError (naming ToolController) when the op has no tool to cut with (see tool_problem)."""
        problem = tool_problem(obj)
        if problem is not None:
            raise problem

    def mustExecute(self, obj: object) -> bool:
        """FreeCAD asks on every recompute: the op recomputes when its tool controller or tool bit changed since
        it last ran (a tool bit's Diameter set to 0, a tool controller losing its tool)."""
        return self.tool_changed(obj)

    def tool_changed(self, obj: object) -> bool:
        """Whether the op's tool controller or tool bit changed since it last ran (the posts then plan again)."""
        seen = getattr(self, "_tool_seen", None)
        return seen is not None and seen != tool_signature(obj)

    def report_error(self, obj: object, error: Exception) -> None:
        """An op that cannot cut: one error line "<Label>: <message>" in the
        report view (an exception escaping execute would print a Python
        traceback too), a Path of one comment repeating it (never a stale
        toolpath), the message kept in ``self.error``."""
        message = str(error) if isinstance(error, ValueError) else "%s: %s" % (type(error).__name__, error)
        if not isinstance(error, ValueError):  # a bug, not an input: its traceback for the log level
            FreeCAD.Console.PrintLog(traceback.format_exc())
        self.error = message
        self.commandlist.append(Path.Command(comment_body("%s: %s" % (obj.Label, message))))
        FreeCAD.Console.PrintError("%s: %s\n" % (obj.Label, message))

    def _add_missing_properties(self, obj: object) -> None:
        """Add the DECLARED_PROPERTIES ``obj`` lacks, each set to its default (an enumeration: its choices,
        then the first); an op adds what it sets on every opening after this (constraints, editor modes: not
        stored in the document). PropertiesList is read once: each read builds a new list, and read for each
        property it took 0.8 ms an op (FreeCAD 1.1), a third of opening a Job of 500 Groove ops."""
        present = set(obj.PropertiesList)
        for type_id, name, group, tooltip, default in self.DECLARED_PROPERTIES:
            if name in present:
                continue
            obj.addProperty(type_id, name, group, tooltip)
            if default is not None:
                setattr(obj, name, default)
            if type_id == "App::PropertyEnumeration":
                setattr(obj, name, default[0])


def create_op(proxy_class: type, name: str, obj: object, parent_job: object, tool_controller: object) -> object:
    """An op (Path::FeaturePython with a ``proxy_class`` proxy) in ``parent_job`` (None: the active document's
    Job); with the GUI up it also gets its view provider, the one the GUI bound to its kind (ops/registry.py)."""
    if obj is None:
        doc = parent_job.Document if parent_job is not None else FreeCAD.ActiveDocument
        obj = doc.addObject("Path::FeaturePython", name)
    obj.Proxy = proxy_class(obj, name, parent_job, tool_controller)
    registry.assign_view_provider(proxy_class.KIND, obj)
    return obj


def register_op_kind(kind: registry.OpKind, proxy_class: type) -> None:
    """Register the op kind ``kind`` with CAM's SetupSheet, as FreeCAD's own ops are: a Job applies its
    SetupSheet to every new op by kind and logs "SetupSheet has no support for ..." for an unregistered one.
    CAM's SetupSheet editor (the Job panel's "Operations" defaults, read on every Job panel's OK) asks the
    kind's prototype for each property its SetupProperties() name: setup_prototype gives it them."""
    import Path.Base.SetupSheet as PathSetupSheet

    def setup_properties() -> list:  # read when asked: the op's module is still loading now
        return kind.load(kind.setup_properties)()

    PathSetupSheet.RegisterOperation(kind.name, lambda name, proto: setup_prototype(proxy_class, proto,
                                                                                   setup_properties()),
                                     setup_properties)


def prototype_value(type_id: str, default: object) -> object:
    """A declared default as CAM's prototype property holds it: lengths and angles as Quantities (its editor
    and display read them so), an enumeration as its choices (then its first is set)."""
    if type_id in ("App::PropertyLength", "App::PropertyDistance"):
        return FreeCAD.Units.Quantity(float(default), FreeCAD.Units.Length)
    if type_id == "App::PropertyAngle":
        return FreeCAD.Units.Quantity(float(default), FreeCAD.Units.Angle)
    return default


def setup_prototype(proxy_class: type, proto: object, names: list) -> object:
    """CAM's SetupSheet prototype ``proto`` (Path/Base/SetupSheetOpPrototype.OpPrototype) of the op
    ``proxy_class``: each property of ``names`` as the op declares it (type, group, tooltip), its value the
    op's default. A name the op does not declare is a bug of the op (ValueError naming it)."""
    declared = {p[1]: p for p in proxy_class.DECLARED_PROPERTIES}
    missing = [name for name in names if name not in declared]
    if missing:
        raise ValueError("%s: SetupProperties() names %s, which it does not declare"
                         % (proxy_class.__qualname__, ", ".join(missing)))
    for name in names:
        type_id, _name, group, tooltip, default = declared[name]
        proto.addProperty(type_id, name, group, tooltip)
        if type_id == "App::PropertyEnumeration":
            setattr(proto, name, list(default))
            default = default[0]
        if default is not None:
            setattr(proto, name, prototype_value(type_id, default))
    return proto
