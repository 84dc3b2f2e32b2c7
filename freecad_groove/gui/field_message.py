"""The op's message shown right under the field being edited.

A long page (the Groove's) scrolls: its message line at the top is out of
view while the user edits a field further down, and only the field's red
frame and a grey OK say that something is wrong. So while a message stands,
a second label shows it directly under the field the user is in (the field
with the keyboard focus, else the first field the message names), as a row
of that field's form; the page's own message line at the top is hidden
meanwhile (it shows the same text). Forms are QFormLayouts (a field in an
inner box layout of a row counts as that row's).

GUI layer: Qt only through FreeCAD's ``PySide`` shim. Not stored in documents.
"""

from typing import Optional

from PySide import QtCore, QtGui

from .widgets import ERROR_LABEL, ERROR_STYLE, child

FIELD_MESSAGE = "fieldErrorLabel"  # object name of the label under the field


def _row_of(layout: object, widget: object) -> int:
    """The row of form ``layout`` holding ``widget`` (itself or in a row's inner layout), or -1."""
    row, _role = layout.getWidgetPosition(widget)
    if row >= 0:
        return row
    # A row's inner layout is found as the form layout's child QObject, not through itemAt(): a layout item's
    # wrapper (QLayoutItem, another address than the QLayout's) outlived its row and FreeCAD 1.0 crashed on
    # the next panel built at that address.
    for inner in layout.findChildren(QtGui.QLayout):
        if inner.indexOf(widget) >= 0:
            row, _role = layout.getLayoutPosition(inner)
            if row >= 0:
                return row
    return -1


def _form_row(form: object, widget: object) -> tuple:
    """(the QFormLayout of ``form`` holding ``widget``, its row), or (None, -1)."""
    for layout in form.findChildren(QtGui.QFormLayout):
        row = _row_of(layout, widget)
        if row >= 0:
            return layout, row
    return None, -1


def _focused_field(form: object) -> Optional[object]:
    """The field of ``form`` that has the keyboard focus, or None. Asked of the form's spin boxes and combo boxes
    (hasFocus), not by walking up from QApplication.focusWidget(): wrappers taken of the widgets on that way (a
    spin box's inner line edit) outlived them, and FreeCAD 1.0 crashed on the next panel."""
    for kind in (QtGui.QAbstractSpinBox, QtGui.QComboBox):
        for field in form.findChildren(kind):
            if field.hasFocus() and _form_row(form, field)[0] is not None:
                return field
    return None


class FieldMessage:
    """The message label under the field being edited, on one page's form."""

    def __init__(self, form: object):
        self.form = form
        # The label while one shows (Python made it: shiboken hears of its deletion). No wrapper of a layout
        # Qt made is kept: FreeCAD deletes the form with the panel without shiboken hearing, and a wrapper
        # still held would be handed out for the next panel's widget built at that address (qt_wrappers.py).
        self.label = None

    def show(self, message: object, named: list) -> None:
        """Show ``message`` (None: hide) under the focused field, else under the first of the fields ``named``;
        the page's top message line hidden while it does."""
        field = _focused_field(self.form) if message else None
        if field is None and message:
            field = next((f for f in named if f is not None and _form_row(self.form, f)[0] is not None), None)
        self._remove()
        top = child(self.form, ERROR_LABEL)
        if field is None:
            if top is not None:
                top.setVisible(bool(message))
            return
        layout, row = _form_row(self.form, field)
        self.label = QtGui.QLabel(str(message))
        self.label.setObjectName(FIELD_MESSAGE)
        self.label.setWordWrap(True)
        self.label.setStyleSheet(ERROR_STYLE)
        layout.insertRow(row + 1, self.label)
        if top is not None:
            top.setVisible(False)
        QtCore.QTimer.singleShot(0, self._keep_in_view)

    def _remove(self) -> None:
        """The label's row removed (the label deleted with it: removeRow, in PySide2 too, unlike takeRow)."""
        if self.label is not None:
            for layout in self.form.findChildren(QtGui.QFormLayout):
                row, _role = layout.getWidgetPosition(self.label)
                if row >= 0:
                    layout.removeRow(row)
                    break
        self.label = None

    def _keep_in_view(self) -> None:
        """Scroll the page's scroll areas so the label shows (it may sit below the dock's bottom)."""
        try:
            label = self.label
            parent = label.parentWidget() if label is not None else None
            while parent is not None:
                if isinstance(parent, QtGui.QScrollArea) and label.isVisible():
                    parent.ensureWidgetVisible(label, 0, 4)
                parent = parent.parentWidget()
        except RuntimeError:  # the panel closed meanwhile: its widgets are gone
            pass
