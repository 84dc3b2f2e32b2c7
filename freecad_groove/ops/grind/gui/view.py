"""The Plunge grind op's view provider, and the new op with its task panel
open (grind_panel.py) that the Plunge grind command (grind_command.py) makes.

The class path ``freecad_groove.gui.grind_view.ViewProviderPlungeGrind`` is
stored in documents: keep it.
"""

import FreeCAD
import Path.Op.Gui.Base as PathOpGui

from ..freecad import plunge_grind_op
from . import GRIND_ICON, task_panel
from .grind_command import MENU_TEXT, TOOL_TIP
from .grind_panel import PlungeGrindPage, select_flat_faces
from .task_dialog import AddonTaskPanel
from .widgets import CONTEXT


class ViewProviderPlungeGrind(task_panel.ViewProvider):
    """The op's view provider: the Groove's (FreeCAD's, with the add-on's icon and task panel), with the Plunge
    grind's icon, flat-face selection gate and task panel."""

    ICON = GRIND_ICON
    TITLE = FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Plunge grind")
    NAME = "PlungeGrind"
    DIALOG = AddonTaskPanel  # no tool page: the tool controller is on the Plunge grind page

    @staticmethod
    def make_op(name: str, job: object) -> object:
        return plunge_grind_op.Create(name, parentJob=job)

    @staticmethod
    def command_resources() -> object:
        """The op's command resources (PathOpGui.CommandResources): the page class FreeCAD stores."""
        return PathOpGui.CommandResources("PlungeGrind", plunge_grind_op.Create, PlungeGrindPage, GRIND_ICON,
                                          MENU_TEXT, None, TOOL_TIP)

    def getSelectionFactory(self):
        return select_flat_faces


def attach_view_provider(obj: object, delete_on_reject: bool = False) -> None:
    """Give the op its view provider (ops made by scripts get one too, through hooks)."""
    task_panel.attach_view_provider(obj, delete_on_reject, ViewProviderPlungeGrind)


def create(job: object) -> object:
    """A new Plunge grind op in ``job`` with its task panel open (the selected face taken as its Base, as
    CAM's panels do); Cancel deletes it again. Returns the op, or None."""
    return task_panel.create(job, ViewProviderPlungeGrind)
