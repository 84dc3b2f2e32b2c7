"""The add-on's op task dialogs: FreeCAD CAM's op task panel with OK and
Apply refused while the op's page holds an error, and a document left
unmodified by a look at the panel (CAM's panel changes Visibility while it is
open): AddonTaskPanel, the dialog of every op's panel (the Groove's,
ops/groove/gui/panel.GrooveTaskPanel, adds its tool page).

Not stored in documents (the view providers' setEdit builds it): free to move.
"""

import FreeCAD
import FreeCADGui
import Path.Op.Gui.Base as PathOpGui
from PySide import QtGui

from . import qt_wrappers
from .widgets import fit_narrow_docks


class AddonTaskPanel(qt_wrappers.ForgetsButtonBox, PathOpGui.TaskPanel):
    """FreeCAD's op task panel with OK/Apply refused while the op's page holds an error; its button box's
    wrappers forgotten on closing (qt_wrappers.py). The op's page has ``error``, ``update_preview()``,
    ``other_pages`` and ``on_validity_changed``."""

    def __init__(self, obj, deleteOnReject, opPage, selectionFactory):
        # Before CAM's panel shows the op and hides the model and stock: that marks the document modified.
        self.gui_document = FreeCADGui.getDocument(obj.Document.Name)
        self.was_modified = self.gui_document.Modified
        self.looks_before = document_looks(obj.Document)
        self.applied = False  # Apply wrote the panel's values into the op
        super().__init__(obj, deleteOnReject, opPage, selectionFactory)
        self.op_page = opPage
        self.add_pages(obj, opPage)
        opPage.other_pages = [p for p in self.featurePages if p is not opPage]
        opPage.on_validity_changed = self.update_buttons

    @property
    def groove_page(self) -> object:
        """The op's page (the name the Groove and Plunge grind tests read)."""
        return self.op_page

    def add_pages(self, obj: object, op_page: object) -> None:
        """The add-on's pages besides CAM's (none here)."""

    def setupUi(self):
        super().setupUi()
        for page in self.featurePages:  # FreeCAD's own pages too, now filled (1.1's tool controller editor)
            fit_narrow_docks(page.form)
        self.op_page.add_message_rows()  # now: the fields show the op's values, a change is the user's
        # Held by the panel, which FreeCAD's dialog keeps until its forms are deleted (qt_wrappers.py).
        self.made_by_python = qt_wrappers.made_by_python([page.form for page in self.featurePages])

    @property
    def valid(self) -> bool:
        return self.op_page.error is None

    def update_buttons(self) -> None:
        """OK only while the op is valid, Apply also only while there is something to apply."""
        box = getattr(self, "buttonBox", None)
        if box is None:
            return
        box.button(QtGui.QDialogButtonBox.Ok).setEnabled(self.valid)
        box.button(QtGui.QDialogButtonBox.Apply).setEnabled(self.valid and self.isDirty())

    def pageDirtyChanged(self, page):
        self.update_buttons()

    def modifyStandardButtons(self, buttonBox):
        super().modifyStandardButtons(buttonBox)
        fit_narrow_docks(buttonBox)  # OK, Cancel, Apply: three 80 px buttons are wider than 1.0's dock
        self.update_buttons()

    def _refuse(self):
        self.op_page.update_preview()  # the values the user sees now, not those of 20 ms ago
        if self.valid:
            return False
        FreeCAD.Console.PrintWarning("%s: %s\n" % (self.obj.Label, self.op_page.error))
        return True

    def accept(self, resetEdit=True):
        if self._refuse():
            return False
        unchanged = not self.isDirty() and self._left_alone()
        super().accept(resetEdit)
        self._keep_unmodified(unchanged)
        return True

    def reject(self, resetEdit=True):
        unchanged = self._left_alone()
        result = super().reject(resetEdit)
        self._keep_unmodified(unchanged)
        return result

    def clicked(self, button):
        if button == QtGui.QDialogButtonBox.Apply:
            if self._refuse():
                return
            self.applied = self.applied or self.isDirty()
        super().clicked(button)

    def cleanup(self, resetEdit):
        # The pages' widgets FreeCAD deletes with the dialog: their wrappers the pages hold (fields, the picture's
        # label) forgotten once they are gone, so the next panel's widgets built at their addresses get wrappers
        # of their own (qt_wrappers.py; FreeCAD 1.0 segfaulted reading a Groove field's text in
        # test_model_panel_cases, the page of the panel before still holding a label at that address).
        forms = [page.form for page in self.featurePages]
        held = qt_wrappers.made_by_qt(forms) + qt_wrappers.list_items(forms)
        super().cleanup(resetEdit)
        qt_wrappers.forget(held)

    def _left_alone(self) -> bool:
        """An existing op, and nothing applied: the panel wrote nothing into it."""
        return not self.deleteOnReject and not self.applied

    def _keep_unmodified(self, unchanged: bool) -> None:
        """A document that was saved stays unmodified when the panel changed
        nothing in it: CAM's panel changes only the Visibility of the op, model,
        stock and Job while it is open, which is not worth asking to save.
        Called once the panel is closed: every object must be shown or hidden
        as before, and no object added (a grooving tool controller)."""
        if unchanged and not self.was_modified and document_looks(self.gui_document.Document) == self.looks_before:
            self.gui_document.Modified = False


def document_looks(doc: object) -> dict:
    """{object name: whether it is shown} of every object of ``doc``."""
    return {o.Name: bool(o.ViewObject.Visibility) if getattr(o, "ViewObject", None) is not None else None
            for o in doc.Objects}
