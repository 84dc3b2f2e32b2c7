"""The Plunge grind op's view provider, and the new op with its task panel
open (grind_panel.py) that the Plunge grind command (grind_command.py) makes.

The class path ``freecad_groove.gui.grind_view.ViewProviderPlungeGrind`` is
stored in documents: keep it.
"""

import FreeCAD
import Path.Op.Gui.Base as PathOpGui

from ..freecad import plunge_grind_op
from . import GRIND_ICON
from .grind_command import MENU_TEXT, TOOL_TIP
from .grind_panel import PlungeGrindPage, PlungeGrindTaskPanel, select_flat_faces
from .widgets import CONTEXT

translate = FreeCAD.Qt.translate


class ViewProviderPlungeGrind(PathOpGui.ViewProvider):
    """The op's view provider: FreeCAD's, with the add-on's icon, a flat-face selection gate and the Plunge
    grind task panel."""

    def getIcon(self):
        if getattr(self, "Object", None) is not None and not self.Object.Active:
            return ":/icons/CAM_OpActive.svg"
        return GRIND_ICON

    def getSelectionFactory(self):
        return select_flat_faces

    def setEdit(self, vobj=None, mode=0):
        if mode != 0:
            return False
        if vobj is None:
            vobj = self.vobj
        page = self.getTaskPanelOpPage(vobj.Object)
        page.setTitle(translate(CONTEXT, "Plunge grind"))
        page.setIcon(GRIND_ICON)
        self.setupTaskPanel(PlungeGrindTaskPanel(vobj.Object, self.deleteObjectsOnReject(), page,
                                                 self.getSelectionFactory()))
        self.deleteOnReject = False
        return True


def resources() -> object:
    """The op's command resources (PathOpGui.CommandResources): the page class FreeCAD stores."""
    return PathOpGui.CommandResources("PlungeGrind", plunge_grind_op.Create, PlungeGrindPage, GRIND_ICON,
                                      MENU_TEXT, None, TOOL_TIP)


def attach_view_provider(obj: object, delete_on_reject: bool = False) -> None:
    """Give the op its view provider (ops made by scripts get one too, through hooks)."""
    vobj = getattr(obj, "ViewObject", None)
    if vobj is None:
        return
    if not isinstance(getattr(vobj, "Proxy", None), ViewProviderPlungeGrind):
        vobj.Proxy = ViewProviderPlungeGrind(vobj, resources())
    vobj.Proxy.setDeleteObjectsOnReject(delete_on_reject)


def create(job: object) -> object:
    """A new Plunge grind op in ``job`` with its task panel open (the selected face taken as its Base, as
    CAM's panels do); Cancel deletes it again. Returns the op, or None."""
    doc = job.Document
    doc.openTransaction(translate(CONTEXT, "Create Plunge grind"))
    try:
        obj = plunge_grind_op.Create("PlungeGrind", parentJob=job)
        attach_view_provider(obj, delete_on_reject=True)
        obj.ViewObject.Visibility = True
    except Exception as error:
        doc.abortTransaction()
        FreeCAD.Console.PrintError(translate(CONTEXT, "Plunge grind: cannot create the operation: {0}").format(error)
                                   + "\n")
        return None
    doc.commitTransaction()
    obj.ViewObject.Document.setEdit(obj.ViewObject, 0)
    return obj
