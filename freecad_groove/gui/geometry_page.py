"""FacesPage: FreeCAD CAM's base geometry page (its list of picked faces),
faces only, with the op's message under its own lines: the Base Geometry
page of the Groove and Plunge grind panels.

Not stored in documents: free to move.
"""

import Path.Op.Gui.Base as PathOpGui

from . import qt_wrappers
from .widgets import add_error_label, fit_narrow_docks


class FacesPage(PathOpGui.TaskPanelBaseGeometryPage):
    """FreeCAD's base geometry page, faces only, with the op's message under
    its own lines (add_lines)."""

    def getForm(self):
        form = super().getForm()
        qt_wrappers.drop_stale(form)
        self.add_lines(form)
        add_error_label(form)
        # Now: FreeCAD's task view sets its minimum width from the pages once, when it shows them.
        fit_narrow_docks(form)
        return form

    def add_lines(self, form: object) -> None:
        """Lines of a subclass above the message."""

    def supportsEdges(self):
        return False

    def supportsVertexes(self):
        return False

