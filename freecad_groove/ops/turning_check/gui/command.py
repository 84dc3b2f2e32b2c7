"""The Check turning command: a button in CAM's "Project Setup" toolbar (with
Job, Post and Sanity) and an entry in its menu after CAM_Sanity; enabled when
the active document holds a CAM Job. It checks the Job whose model holds the
selection, else the document's only Job, else the one the user picks
(gui/commands.chosen_job, as the op commands), in its task panel (panel.py).

Imports no CAM module until the command is used (FreeCAD's GUI start registers it).
"""

import FreeCAD

from ....gui.commands import chosen_job, has_job
from . import ICON

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP


class CommandCheckTurning:
    NAME = "FreeCADGroove_CheckTurning"
    TOOLBAR = "Project Setup"  # CAM's toolbar with Job, Post and Sanity (1.0 and 1.1)
    MENU_AFTER = "CAM_Sanity"

    def GetResources(self):
        return {
            "Pixmap": ICON,
            "MenuText": QT_TRANSLATE_NOOP("FreeCADGroove_CheckTurning", "Check turning"),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FreeCADGroove_CheckTurning",
                "Simulate the Job's Groove ops on the turned section of its stock: what is removed, gouges "
                "into the part (red), material left in the grooves (orange), rapids through stock, machining time",
            ),
        }

    def IsActive(self):
        return has_job()

    def Activated(self):
        job = chosen_job()
        if job is None:
            return None
        from .panel import open_panel

        return open_panel(job)
