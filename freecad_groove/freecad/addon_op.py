"""What the add-on's operations (Groove, Cylinder slot, Plunge grind) share
on CAM's op framework (Path.Op.Base.ObjectOp): the tool controller they are
made with, their features, their properties added on creation and on
restore (a document saved by an older version gets the new ones), and no
milling depths; the one-line report of an op that cannot cut; making an op
with its view provider (create_op) and registering its kind with CAM's
SetupSheet (register_op_kind).

Not stored in documents (each op's own class is): free to move.

FreeCAD layer: FreeCAD's CAM only.
"""

import traceback

import FreeCAD
import Path
import Path.Op.Base as PathOp

from .. import hooks
from .op_path import comment_body


class AddonOp(PathOp.ObjectOp):
    """Base of the add-on's op proxies. A subclass sets OP_NAME (the op's
    kind, which CAM's SetupSheet registry looks it up by, not the object's
    name), FEATURES (names of Path.Op.Base feature flags) and
    _add_missing_properties."""

    OP_NAME = ""
    FEATURES = ("FeatureTool", "FeatureBaseFaces", "FeatureCoolant")

    def __init__(self, obj: object, name: str, parentJob: object = None, tool_controller: object = None):
        # The base class picks a tool controller while it is built; headless,
        # with several in the job and no GUI to ask, FreeCAD's picker fails,
        # so it is steered to this one (see isToolSupported).
        if tool_controller is None and parentJob is not None and getattr(parentJob, "Tools", None):
            group = parentJob.Tools.Group
            tool_controller = group[0] if group else None
        self._tc_hint = tool_controller
        try:
            super().__init__(obj, self.OP_NAME, parentJob)
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
        raise NotImplementedError


def create_op(proxy_class: type, name: str, obj: object, parent_job: object, tool_controller: object,
              view_hook: str) -> object:
    """An op (Path::FeaturePython with a ``proxy_class`` proxy) in ``parent_job`` (None: the active document's
    Job); with the GUI up it also gets its view provider, from the factory the GUI set in ``hooks.<view_hook>``."""
    if obj is None:
        doc = parent_job.Document if parent_job is not None else FreeCAD.ActiveDocument
        obj = doc.addObject("Path::FeaturePython", name)
    obj.Proxy = proxy_class(obj, name, parent_job, tool_controller)
    factory = getattr(hooks, view_hook)
    if factory is not None and getattr(obj, "ViewObject", None) is not None:
        factory(obj)
    return obj


def register_op_kind(op_name: str, setup_properties: object, prototype: object = None) -> None:
    """Register the op kind ``op_name`` with CAM's SetupSheet, as FreeCAD's own ops are: a Job applies its
    SetupSheet to every new op by kind and logs "SetupSheet has no support for ..." for an unregistered one.
    ``prototype(name, prototype)``: what the SetupSheet editor builds for its properties (default: as given)."""
    import Path.Base.SetupSheet as PathSetupSheet

    PathSetupSheet.RegisterOperation(op_name, prototype or (lambda name, proto: proto), setup_properties)
