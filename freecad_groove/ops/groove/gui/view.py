"""The Groove op's view provider, its selection gate (only faces a groove can
be cut into) and a new op with its task panel open (the command's).

The class path ``freecad_groove.ops.groove.gui.view.ViewProviderGroove`` is
stored in GUI documents saved since the ops moved here; documents saved
before store ``freecad_groove.gui.task_panel.ViewProvider``, which that
module keeps as a shim. Neither may move.
"""

import FreeCAD
import FreeCADGui

from ....freecad.faces import analyse_face
from ....gui.op_view import OpViewProvider
from ....gui.widgets import CONTEXT
from .. import KIND
from ..model import read_model_groove
from ..op import Create
from . import ICON
from .panel import GroovePage, GrooveTaskPanel

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP


class ViewProviderGroove(OpViewProvider):
    """The Groove op's view provider (gui/op_view.py): its page, its dialog with the tool page, the turned-face
    selection gate."""

    KIND = KIND
    CREATE = staticmethod(Create)
    PAGE = GroovePage
    ICON = ICON
    TITLE = QT_TRANSLATE_NOOP(CONTEXT, "Groove")
    DIALOG = GrooveTaskPanel

    def getSelectionFactory(self):
        return select_turned_faces


class TurnedFaceGate:
    """Lets the user pick only faces a groove can be cut into."""

    def allow(self, doc: object, obj: object, sub: str) -> bool:
        if not sub or not sub.startswith("Face") or not hasattr(obj, "Shape"):
            return False
        try:
            analyse_face(obj.Shape.getElement(sub), sub)
        except Exception:
            try:  # a face of a modelled groove: a corner radius is a torus
                read_model_groove(obj.Shape, sub, sub)
            except Exception:
                return False
        return True


def select_turned_faces() -> None:
    """Let the user pick only faces a groove can be cut into."""
    FreeCADGui.Selection.addSelectionGate(TurnedFaceGate())


def create(job: object) -> object:
    """A new Groove in ``job`` with its task panel open (the command's); None when it cannot be made."""
    return ViewProviderGroove.create(job)
