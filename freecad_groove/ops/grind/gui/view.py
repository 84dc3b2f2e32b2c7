"""The Plunge grind op's view provider, its selection gate (flat faces
looking up) and the new op with its task panel open (panel.py) that the
Plunge grind command (command.py) makes.

The class path ``freecad_groove.ops.grind.gui.view.ViewProviderPlungeGrind``
is stored in GUI documents saved since the ops moved here; documents saved
before store ``freecad_groove.gui.grind_view.ViewProviderPlungeGrind``, which
that module keeps as a shim. Neither may move.
"""

import FreeCAD
import FreeCADGui

from ....gui.op_view import OpViewProvider
from ....gui.widgets import CONTEXT
from .. import KIND
from ..op import Create
from ..plan import read_face
from . import ICON
from .panel import PlungeGrindPage


class ViewProviderPlungeGrind(OpViewProvider):
    """The op's view provider (gui/op_view.py): the Plunge grind's page, icon and flat-face selection gate;
    the add-on's dialog without a tool page (the tool controller is on the Plunge grind page)."""

    KIND = KIND
    CREATE = staticmethod(Create)
    PAGE = PlungeGrindPage
    ICON = ICON
    TITLE = FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Plunge grind")

    def getSelectionFactory(self):
        return select_flat_faces


class FlatFaceGate:
    """Lets the user pick only faces a plunge grind can take (flat, looking up, a rectangle along X and Y)."""

    def allow(self, doc: object, obj: object, sub: str) -> bool:
        if not sub or not sub.startswith("Face") or not hasattr(obj, "Shape"):
            return False
        try:
            read_face(obj.Shape.getElement(sub), sub)
        except Exception:
            return False
        return True


def select_flat_faces() -> None:
    FreeCADGui.Selection.addSelectionGate(FlatFaceGate())


def create(job: object) -> object:
    """A new Plunge grind op in ``job`` with its task panel open (the selected face taken as its Base, as
    CAM's panels do); Cancel deletes it again. Returns the op, or None."""
    return ViewProviderPlungeGrind.create(job)
