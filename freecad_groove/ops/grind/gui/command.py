"""The Plunge grind command: a button at the end of CAM's "New Operations"
toolbar and an entry in the CAM menu (as the Turning Groove command), after
the Cylinder slot.
Enabled when the active document holds a CAM Job; with a flat face of a
Job's part selected it makes the op in that Job with its task panel open
(view.create; the panel takes the selected face as its Base).

Imports no CAM module until the command is used (FreeCAD's GUI start registers it).
"""

import FreeCAD

from ....gui.commands import chosen_job, has_job
from . import ICON

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

COMMAND = "FreeCADGroove_PlungeGrind"
MENU_TEXT = QT_TRANSLATE_NOOP(COMMAND, "Plunge grind")
TOOL_TIP = QT_TRANSLATE_NOOP(COMMAND, "Plunge grind a flat face (Allen-Bradley 9/Series G83/G83.1) with a grinding "
                             "wheel: select a flat face of the Job's part looking up (+Z), then set the picks, "
                             "feeds and dresses in the task panel")


class CommandPlungeGrind:
    NAME = COMMAND
    TOOLBAR = "New Operations"  # CAM's toolbar of operations, as the Groove command's
    # after the Turning Groove and the Cylinder slot (after V-Carve, before the 3D operations)
    MENU_AFTER = "FreeCADGroove_CylinderSlot"

    def GetResources(self):
        return {"Pixmap": ICON, "MenuText": MENU_TEXT, "ToolTip": TOOL_TIP}

    def IsActive(self):
        return has_job()

    def Activated(self):
        job = chosen_job()
        from .view import create

        return create(job) if job is not None else None
