"""The add-on's commands in FreeCAD's CAM workbench: an op's registration
(register_op: its command, its view provider), a command's place in CAM's
toolbar and menu, and the Job a new op goes into.

A command class carries its FreeCAD name (NAME) and its place: TOOLBAR (None:
in no toolbar nor menu, FreeCAD's command list only) and MENU_AFTER, the
command it follows in CAM's menu. Registering one imports no CAM module:
FreeCAD's GUI start registers them.

Not stored in documents: free to move.
"""

import FreeCAD
import FreeCADGui

from ..ops.registry import OpKind, bind_view_provider


def register_op(kind: OpKind) -> None:
    """Register op ``kind`` in the GUI: its command (into CAM's toolbar and menu) and its view provider,
    which every new op of the kind gets, a script's too (loaded then: it imports CAM)."""
    add_command(kind.load(kind.command)())
    bind_view_provider(kind, lambda obj: kind.load(kind.view_provider).assign(obj))


def add_command(command: object) -> None:
    """Add ``command`` to FreeCAD as its NAME, and to CAM's menu after its MENU_AFTER (None: in no menu) and
    toolbar TOOLBAR (None: in no toolbar)."""
    if getattr(command, "MENU_AFTER", None) is None:
        FreeCADGui.addCommand(command.NAME, command)
    else:
        add_to_cam(command.NAME, command, command.TOOLBAR, command.MENU_AFTER)


def jobs(doc: object) -> list:
    """The CAM Jobs of ``doc``."""
    return [o for o in doc.Objects if getattr(o, "Proxy", None) is not None and type(o.Proxy).__name__ == "ObjectJob"]


def job_of_selection(jobs: list) -> object:
    """The Job whose model holds the selected object, or None."""
    for sel in FreeCADGui.Selection.getSelectionEx():
        for job in jobs:
            model = getattr(job, "Model", None)
            if model is not None and sel.Object in model.Group:
                return job
    return None


def chosen_job() -> object:
    """The Job a new op goes into: the one whose model holds the selection, else the active document's only
    Job, else the one the user picks (None: none)."""
    doc = FreeCAD.ActiveDocument
    found = jobs(doc) if doc is not None else []
    if not found:
        return None
    job = job_of_selection(found)
    if job is None:
        if len(found) == 1:
            return found[0]
        import PathScripts.PathUtils as PathUtils

        job = PathUtils.UserInput.chooseJob(found)
    return job


def has_job() -> bool:
    """Whether the active document holds a CAM Job (the op commands are enabled then)."""
    doc = FreeCAD.ActiveDocument
    return doc is not None and bool(jobs(doc))


class Manipulator:
    """Puts ``command`` at the end of CAM's toolbar ``toolbar`` and into its
    menu right after ``menu_after`` whenever CAM is built; then the commands
    of ``entries`` added after it, in order."""

    def __init__(self, command: str, toolbar: str, menu_after: str):
        self.entries = [(command, toolbar, menu_after)]

    def modifyToolBars(self):
        return [{"append": command, "toolBar": toolbar} for command, toolbar, _after in self.entries if toolbar]

    def modifyMenuBar(self):
        # "insert" with "after" puts it right after menu_after; "append" would
        # put it at the very end of the menu that holds menu_after.
        return [{"insert": command, "menuItem": after, "after": ""} for command, _toolbar, after in self.entries]


_manipulators = {}  # command name -> its Manipulator (added once)


def add_to_cam(name: str, command: object, toolbar: str, menu_after: str) -> None:
    """Add FreeCAD command ``name`` and (once) its place in CAM's toolbar and menu."""
    FreeCADGui.addCommand(name, command)
    if name in _manipulators:
        return
    if menu_after in _manipulators:  # after another command of the add-on: in its manipulator, so placed after it
        _manipulators[name] = _manipulators[menu_after]  # (FreeCAD runs the manipulators in no fixed order)
        _manipulators[name].entries.append((name, toolbar, menu_after))
    else:
        _manipulators[name] = Manipulator(name, toolbar, menu_after)
        FreeCADGui.addWorkbenchManipulator(_manipulators[name])
