"""The Turning Groove command: a button at the end of CAM's "New
Operations" toolbar and an entry in the CAM menu right after the engraving
operations (CAM_Vcarve), before the 3D operations. Named "Turning Groove":
PartDesign already has a "Groove" command.

Enabled when the active document holds a CAM Job. With a face of a Job's
model selected it makes the op in that Job on that face (the task panel's
base geometry takes the selection, as FreeCAD's own ops do); otherwise in
the document's only Job, or the one the user picks.
"""

import FreeCAD
import FreeCADGui

from . import COMMAND, ICON

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

TOOLBAR = "New Operations"  # CAM's toolbar of operations (1.0 and 1.1)
MENU_AFTER = "CAM_Vcarve"  # the last engraving operation of CAM's menu, before its separator (1.0 and 1.1)
MENU_TEXT = QT_TRANSLATE_NOOP("FreeCADGroove_Groove", "Turning Groove")
WORKBENCH = "CAMWorkbench"


def _jobs(doc):
    return [o for o in doc.Objects if getattr(o, "Proxy", None) is not None and type(o.Proxy).__name__ == "ObjectJob"]


def job_of_selection(jobs):
    """The Job whose model holds the selected object, or None."""
    for sel in FreeCADGui.Selection.getSelectionEx():
        for job in jobs:
            model = getattr(job, "Model", None)
            if model is not None and sel.Object in model.Group:
                return job
    return None


def chosen_job():
    """The Job a new op goes into: the one whose model holds the selection, else the active document's only
    Job, else the one the user picks (None: none)."""
    doc = FreeCAD.ActiveDocument
    jobs = _jobs(doc) if doc is not None else []
    if not jobs:
        return None
    job = job_of_selection(jobs)
    if job is None:
        if len(jobs) == 1:
            return jobs[0]
        import PathScripts.PathUtils as PathUtils

        job = PathUtils.UserInput.chooseJob(jobs)
    return job


class CommandGroove:
    def GetResources(self):
        return {
            "Pixmap": ICON,
            "MenuText": MENU_TEXT,
            "ToolTip": QT_TRANSLATE_NOOP(
                "FreeCADGroove_Groove",
                "Cut a groove (CYCLE93) into a turned face: select a cylinder, cone or plane face of "
                "the Job's part, then set the groove's size in the task panel",
            ),
        }

    def IsActive(self):
        doc = FreeCAD.ActiveDocument
        return doc is not None and bool(_jobs(doc))

    def Activated(self):
        job = chosen_job()
        if job is None:
            return None
        from . import task_panel

        return task_panel.create(job)


class Manipulator:
    """Puts ``command`` at the end of CAM's toolbar ``toolbar`` and into its
    menu right after ``menu_after`` whenever CAM is built; then the commands
    of ``entries`` added after it, in order."""

    def __init__(self, command: str, toolbar: str, menu_after: str):
        self.entries = [(command, toolbar, menu_after)]

    def modifyToolBars(self):
        return [{"append": command, "toolBar": toolbar} for command, toolbar, _after in self.entries]

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


def register():
    add_to_cam(COMMAND, CommandGroove(), TOOLBAR, MENU_AFTER)
