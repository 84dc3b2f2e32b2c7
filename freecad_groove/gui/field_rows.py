"""The op's message in the row of the field being edited (issue 21 item 9).

The Groove page is taller than the task view: its message line at the top
scrolls out of view while the user edits a field further down, and only the
field's red frame and a grey OK would say that something is wrong. So each
field row of a page's form layouts gets a message label right under it, made
once when the panel is built and hidden until a message stands; the message
then shows in the row of the field the user last changed (else of the first
field the message names), and still at the top of the pages.

Nothing is looked up while the panel is used: the labels are made by Python
as children of the page's form, the page keeps {property: label} until its
cleanupPage, which deletes them (remove_message_rows), and the field the
user changed is known by its property (each field's change signal says
which). Deleted by the page, not left to Qt's deletion of the dialog: PySide
records a label inserted into a form layout as the child of that layout's
wrapper, a wrapper PySide makes and drops each time Python reads the layout,
and FreeCAD 1.1 once segfaulted in shiboken's releaseWrapper deleting such a
label with the dialog (the whole GUI suite in CI, test_model_panel_cases).

A previous try found the focused field when a message came, and inserted
and removed a row each time; the wrappers of Qt's widgets and layout items
it took outlived them and crashed FreeCAD 1.0's next panel.

GUI layer: Qt only through FreeCAD's ``PySide`` shim. Not stored in documents.
"""

from PySide import QtGui

from .qt_wrappers import shiboken
from .widgets import ERROR_STYLE

FIELD_MESSAGE = "fieldMessage"  # object name of the message labels under the field rows


def row_of(layout: object, widget: object) -> int:
    """The row of form ``layout`` holding ``widget`` (itself, or in a row's inner layout: a corner's kind and
    size), or -1."""
    row, _role = layout.getWidgetPosition(widget)
    if row >= 0:
        return row
    for inner in layout.findChildren(QtGui.QLayout):  # the rows' inner layouts are the form layout's children
        if inner.indexOf(widget) >= 0:
            row, _role = layout.getLayoutPosition(inner)
            if row >= 0:
                return row
    return -1


def add_message_rows(form: object, fields: dict) -> dict:
    """A hidden message label under each row of ``form``'s form layouts that holds one of ``fields`` ({op
    property: widget}); returns {property: its row's label} (the fields of one row share it)."""
    labels = {}
    for layout in form.findChildren(QtGui.QFormLayout):
        rows = {}
        for prop, widget in fields.items():
            row = row_of(layout, widget) if widget is not None else -1
            if row >= 0:
                rows.setdefault(row, []).append(prop)
        for row in sorted(rows, reverse=True):  # from the bottom: a row inserted moves only those below it
            label = QtGui.QLabel(form)
            label.setObjectName(FIELD_MESSAGE)
            label.setWordWrap(True)
            label.setStyleSheet(ERROR_STYLE)
            label.setVisible(False)
            layout.insertRow(row + 1, label)
            for prop in rows[row]:
                labels[prop] = label
    return labels


def show_in_row(labels: dict, message: object, edited: object, named: tuple) -> None:
    """Show ``message`` (None: hide) in the row label of property ``edited`` (the field the user last changed),
    else of the first of the properties ``named`` that has one; every other row label hidden."""
    chosen = None
    if message:
        chosen = labels.get(edited) or next((labels[p] for p in named if p in labels), None)
    for label in {id(label): label for label in labels.values()}.values():
        if label is chosen:
            label.setText(str(message))
        label.setVisible(label is chosen)


def remove_message_rows(labels: dict) -> None:
    """Delete the message labels of ``labels`` (from add_message_rows) now, while the panel and every wrapper
    are whole; their rows are left empty."""
    for label in {id(label): label for label in labels.values()}.values():
        if shiboken.isValid(label):
            shiboken.delete(label)
