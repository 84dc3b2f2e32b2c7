"""What the op pages of the add-on's panels (Groove, Cylinder slot, Plunge
grind) share: every changed value re-plans the op from the panel's values
(the document is not touched), a short while after the edit's last signal;
the plan is drawn, or the op's error shows in one line on every page with the
fields it names framed red (the dialog, task_dialog.AddonTaskPanel, refuses
OK meanwhile), and in the row of the field being edited (field_rows.py: the
top of a long page scrolls out of view); the plan's warnings show in amber
under it, their fields framed amber.

A page defines ``replan()`` (the plan from the values shown; a ValueError
for bad values), ``show_plan(plan)`` (None while invalid), ``field(prop)``
and ``INTERNAL_ERROR``; it calls ``init_live`` from initPage and
``show_warning_lines`` with the plan's warnings.
"""

import traceback

import FreeCAD
import Path.Op.Gui.Base as PathOpGui
from PySide import QtGui

from .field_rows import add_message_rows, remove_message_rows, show_in_row
from .widgets import (
    CONTEXT,
    ERROR_LABEL,
    WARNING_LABEL,
    child,
    coalescing_timer,
    mark_invalid,
    mark_warned,
    show_error,
    show_warnings,
)

translate = FreeCAD.Qt.translate

REPLAN_DELAY_MS = 20  # coalesces the signals of one edit into one re-plan


class LivePage(PathOpGui.TaskPanelPage):
    """An op page that re-plans as the user types, owning the panel's validity state."""

    INTERNAL_ERROR = FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Internal error while planning the op: {0}")

    def init_live(self) -> None:
        self.other_pages = []  # set by the dialog: pages whose values and messages share this state
        self.error = None  # the op's message while the values make nothing
        self.invalid = ()  # properties framed red
        self.warnings = []  # the warning texts shown
        self.warned = ()  # properties framed amber
        self.replans = 0
        self.preview = None  # a drawing in the 3D view with remove(), if the page has one
        self.on_validity_changed = None  # the dialog's: OK follows the validity
        self.message_rows = []  # {property: message label under its field's row} of each page (field_rows.py)
        self.edited = None  # the property whose field the user changed last
        self._timer = coalescing_timer(REPLAN_DELAY_MS, self.update_preview)

    def schedule_preview(self) -> None:
        """Re-plan once the signals of the current edit are in."""
        self._timer.start()

    def update_preview(self) -> None:
        """Re-plan the op from the panel's values; draw the plan, or show the error."""
        self._timer.stop()
        error, invalid, plan = None, (), None
        try:
            plan = self.replan()
        except ValueError as bad_input:  # the op's input errors and CycleError are ValueErrors
            error, invalid = str(bad_input), self.error_fields(bad_input)
        except Exception as bug:  # a bug, not bad input: say so in the panel, details in the report view
            FreeCAD.Console.PrintError(traceback.format_exc())
            error = translate(CONTEXT, self.INTERNAL_ERROR).format(bug)
        self.replans += 1
        self.set_error(error, invalid)
        self.show_plan(plan)

    def error_fields(self, bad_input: ValueError) -> tuple:
        """The op properties an error names (their fields are framed): its ``properties`` (the ops' input
        errors); a page whose engine errors name properties too reads them (the Groove's: CYCLE93's)."""
        return tuple(getattr(bad_input, "properties", ()))

    def set_error(self, message: object, properties: tuple = ()) -> None:
        """Show ``message`` (None: the values make an op) on every page and frame the fields of ``properties``
        ("Base": the face list)."""
        was_valid = self.error is None
        self.error = message
        self.invalid = self._mark(self.invalid, tuple(properties) if message else (), mark_invalid)
        for page in [self] + list(self.other_pages):
            show_error(child(page.form, ERROR_LABEL), message)
        for labels in self.message_rows:
            show_in_row(labels, message, self.edited, self.invalid)
        if was_valid != (message is None) and self.on_validity_changed is not None:
            self.on_validity_changed()

    def add_message_rows(self) -> None:
        """A message row under each field row of every page (field_rows.py), and each field's change noted as
        the field being edited. Called once by the dialog, once the pages show the op's values (their change
        signals then come from the user)."""
        fields = {}
        for prop in self.obj.PropertiesList:
            widget = self.marked_field(prop)
            if isinstance(widget, (QtGui.QAbstractSpinBox, QtGui.QComboBox)):
                fields[prop] = widget
        for page in [self] + list(self.other_pages):
            self.message_rows.append(add_message_rows(page.form, fields))
        for prop, widget in fields.items():
            signal = widget.currentIndexChanged if isinstance(widget, QtGui.QComboBox) else widget.valueChanged
            signal.connect(lambda *_a, p=prop: setattr(self, "edited", p))

    def show_warning_lines(self, lines: list, properties: tuple = ()) -> None:
        """Show warning ``lines`` in amber on every page and frame the fields of ``properties``."""
        self.warnings = list(lines)
        self.warned = self._mark(self.warned, tuple(dict.fromkeys(properties)), mark_warned)
        for page in [self] + list(self.other_pages):
            show_warnings(child(page.form, WARNING_LABEL), self.warnings)

    def _mark(self, old: tuple, new: tuple, mark: object) -> tuple:
        """Unframe the fields of the properties ``old``, frame those of ``new``; returns ``new``."""
        for prop in old:
            mark(self.marked_field(prop), False)
        for prop in new:
            mark(self.marked_field(prop), True)
        return tuple(new)

    def marked_field(self, prop: str) -> object:
        """The field of an op property on any page; "Base": the base geometry page's face list."""
        if prop != "Base":
            return self.field(prop)
        for page in self.other_pages:
            if isinstance(page, PathOpGui.TaskPanelBaseGeometryPage):
                return page.form.baseList
        return None

    def cleanupPage(self, obj):
        self._timer.stop()
        for labels in self.message_rows:
            remove_message_rows(labels)
        self.message_rows = []
        if self.preview is not None:
            self.preview.remove()
            self.preview = None
