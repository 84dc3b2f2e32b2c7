"""The Turning Groove command: a button at the end of CAM's "New
Operations" toolbar and an entry in the CAM menu right after the engraving
operations (CAM_Vcarve), before the 3D operations. Named "Turning Groove":
PartDesign already has a "Groove" command.

Enabled when the active document holds a CAM Job. With a face of a Job's
model selected it makes the op in that Job on that face (the task panel's
base geometry takes the selection, as FreeCAD's own ops do); otherwise in
the document's only Job, or the one the user picks.

Imports no CAM module until the command is used (FreeCAD's GUI start registers it).
"""

import FreeCAD

from ....gui.commands import chosen_job, has_job
from . import ICON

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

MENU_TEXT = QT_TRANSLATE_NOOP("FreeCADGroove_Groove", "Turning Groove")


class CommandGroove:
    NAME = "FreeCADGroove_Groove"
    TOOLBAR = "New Operations"  # CAM's toolbar of operations (1.0 and 1.1)
    MENU_AFTER = "CAM_Vcarve"  # the last engraving operation of CAM's menu, before its separator (1.0 and 1.1)

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
        return has_job()

    def Activated(self):
        job = chosen_job()
        if job is None:
            return None
        from .view import create

        return create(job)
