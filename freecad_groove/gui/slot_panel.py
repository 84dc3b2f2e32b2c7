"""The Cylinder slot task panel, on FreeCAD CAM's op panel framework
(Path.Op.Gui.Base) like the Groove panel: OK/Apply/Cancel, the undo
transaction, the tool controller combo.

Pages:
- Base Geometry: FreeCAD's list, here of the cylindrical face and the edges
  of the slot's centre line (in order).
- Cylinder slot: the tool controller and coolant, the path (the edges in Base
  Geometry, or a sketch of the developed surface: DevelopedSketch), Depth,
  Passes, Allowance, Retract, and the live preview of the developed path with
  its passes (slot_preview.py: a picture in the panel).

Every changed value re-plans the op from the panel's values
(ObjectCylinderSlot.plan_with: the document is not touched) and redraws the
picture. An invalid value shows the op's message in one line (red) on both
pages and marks its field; OK and Apply are refused while it stands. The
plan's warnings (slot_reach.py) show in amber and never block. OK writes the
values and recomputes; Cancel aborts the panel's transaction (for a new op,
deletes it).

Not stored in documents (ViewProviderCylinderSlot.setEdit in slot_view.py
builds it): free to move.
"""

import FreeCAD
import FreeCADGui
import Path.Op.Gui.Base as PathOpGui
import PathScripts.PathUtils as PathUtils
from PySide import QtCore, QtGui

from ..freecad.groove_properties import error_properties
from . import ICON
from .qt_wrappers import ForgetsButtonBox
from .slot_preview import DevelopedPicture, developed_path
from .task_dialog import document_looks
from .widgets import (
    CONTEXT,
    ERROR_LABEL,
    WARNING_LABEL,
    QuantityFields,
    add_error_label,
    child,
    connect_changed,
    fit_narrow_docks,
    mark_invalid,
    new_warning_label,
    show_error,
    show_warnings,
)

translate = FreeCAD.Qt.translate

PREVIEW_DELAY_MS = 20  # coalesces the signals of one edit into one re-plan
SLOT_QUANTITIES = (("depth", "Depth"), ("allowance", "Allowance"), ("retract", "Retract"))
TOOLTIPS = {
    "Depth": "Depth of the slot below the cylinder, radial (J = -2 Depth)",
    "Passes": "Rough passes before the finish pass (L; 1 runs as 2, as GSK does)",
    "Allowance": "Finishing allowance, radial, left by the rough passes (K = 2 Allowance)",
    "Retract": "Clearance above the cylinder the tool retracts to between passes, radial (R = 2 Retract)",
    "DevelopedSketch": "The slot's path: the edges picked on the Base Geometry page, or a sketch of the developed "
                       "surface (sketch x = Z, sketch y = radius * C)",
}


class SlotBaseGeometryPage(PathOpGui.TaskPanelBaseGeometryPage):
    """FreeCAD's base geometry page (a face and edges), with the op's message."""

    InitBase = False  # a new op has its face and edges already: CAM would re-add the selection of one object only

    def getForm(self):
        form = super().getForm()
        add_error_label(form)
        fit_narrow_docks(form)
        return form


def _quantity_field(name: str) -> object:
    field = FreeCADGui.UiLoader().createWidget("Gui::QuantitySpinBox")
    field.setObjectName(name)
    field.setProperty("unit", "mm")
    field.setProperty("minimum", 0.0)
    field.setProperty("maximum", 100000.0)
    return field


def _row(layout: object, text: str, widget: object, tooltip: str = "") -> None:
    label = QtGui.QLabel(translate(CONTEXT, text))
    row = layout.rowCount()
    layout.addWidget(label, row, 0)
    layout.addWidget(widget, row, 1)
    for item in (label, widget):
        item.setToolTip(translate(CONTEXT, tooltip))


def build_form() -> object:
    """The Cylinder slot page's widgets (object names = the op's properties, first letter lower case)."""
    form = QtGui.QWidget()
    form.setObjectName("PageCylinderSlotEdit")
    layout = QtGui.QGridLayout(form)
    layout.setColumnStretch(1, 1)
    error = QtGui.QLabel(form)
    error.setObjectName(ERROR_LABEL)
    error.setWordWrap(True)
    error.setVisible(False)
    layout.addWidget(error, 0, 0, 1, 2)
    layout.addWidget(new_warning_label(form), 1, 0, 1, 2)
    form.toolController, form.coolantController, form.developedSketch = (QtGui.QComboBox(form) for _ in range(3))
    form.developedSketch.setObjectName("developedSketch")
    _row(layout, "Tool controller", form.toolController, "The end mill: its diameter is the slot's width")
    _row(layout, "Coolant mode", form.coolantController)
    _row(layout, "Path", form.developedSketch, TOOLTIPS["DevelopedSketch"])
    for name, prop in SLOT_QUANTITIES[:1]:
        _row(layout, prop, _quantity_field(name), TOOLTIPS[prop])
    form.passes = QtGui.QSpinBox(form)
    form.passes.setObjectName("passes")
    form.passes.setRange(1, 9999)
    _row(layout, "Passes", form.passes, TOOLTIPS["Passes"])
    for name, prop in SLOT_QUANTITIES[1:]:
        _row(layout, prop, _quantity_field(name), TOOLTIPS[prop])
    for name in ("developedPicture", "passesLabel"):
        label = QtGui.QLabel(form)
        label.setObjectName(name)
        label.setWordWrap(True)
        layout.addWidget(label, layout.rowCount(), 0, 1, 2)
    layout.setRowStretch(layout.rowCount(), 1)  # the page's spare height below everything, not between rows
    fit_narrow_docks(form)
    return form


class SlotPage(PathOpGui.TaskPanelPage):
    """The slot's values and the live preview; owns the validity state."""

    def getForm(self):
        return build_form()

    def taskPanelBaseGeometryPage(self, obj, features):
        return SlotBaseGeometryPage(obj, features)

    def initPage(self, obj):
        self.fields = QuantityFields(self.form, SLOT_QUANTITIES)
        self.picture = DevelopedPicture(child(self.form, "developedPicture"), child(self.form, "passesLabel"))
        self.other_pages = []  # set by SlotTaskPanel
        self.error, self.invalid, self.warnings, self.plan, self.replans = None, (), [], None, 0
        self.on_validity_changed = None
        self._timer = QtCore.QTimer()  # no parent: it must outlive the form, which Cancel may delete first
        self._timer.setSingleShot(True)
        self._timer.setInterval(PREVIEW_DELAY_MS)
        self._timer.timeout.connect(self.update_preview)

    def getTitle(self, obj):
        return translate(CONTEXT, "Cylinder slot")

    def getIcon(self, obj):
        return ICON

    # -- fields <-> op ----------------------------------------------------------
    def setFields(self, obj):
        self.setupToolController(obj, self.form.toolController)
        self.setupCoolant(obj, self.form.coolantController)
        self.fields.set_from(obj)
        self.form.passes.blockSignals(True)
        self.form.passes.setValue(int(obj.Passes))
        self.form.passes.blockSignals(False)
        self._fill_sketches(obj)
        self.schedule_preview()

    def _fill_sketches(self, obj):
        combo = self.form.developedSketch
        combo.blockSignals(True)
        combo.clear()
        combo.addItem(translate(CONTEXT, "Edges in Base Geometry"), "")
        for sketch in obj.Document.Objects:
            if sketch.isDerivedFrom("Sketcher::SketchObject"):
                combo.addItem(sketch.Label, sketch.Name)
        linked = getattr(obj, "DevelopedSketch", None)
        combo.setCurrentIndex(max(0, combo.findData(linked.Name)) if linked is not None else 0)
        combo.blockSignals(False)

    def getFields(self, obj):
        self.updateCoolant(obj, self.form.coolantController)
        self.fields.write_to(obj)
        values = self.values()
        for name in ("Passes", "DevelopedSketch", "ToolController"):
            if name in values and getattr(obj, name) != values[name]:
                setattr(obj, name, values[name])

    def values(self) -> dict:
        """{op property: value} as the page shows them."""
        values = self.fields.values()
        values["Passes"] = self.form.passes.value()
        name = self.form.developedSketch.currentData()
        values["DevelopedSketch"] = self.obj.Document.getObject(name) if name else None
        # By its label among the Job's (not PathUtils.findToolController: it may ask the user, or fail on 1.1's
        # "Copy"/"New tool controller" entries); none of them picked: the op's own stays.
        label = self.form.toolController.currentText()
        tc = next((c for c in PathUtils.getToolControllers(self.obj) if c.Label == label), None)
        if tc is not None:
            values["ToolController"] = tc
        return values

    def field(self, prop: str) -> object:
        """The widget of an op property on this page, or None."""
        return child(self.form, prop[0].lower() + prop[1:])

    def registerSignalHandlers(self, obj):
        widgets = list(self.fields.widgets.values()) + [self.form.passes, self.form.developedSketch,
                                                        self.form.coolantController, self.form.toolController]
        for widget in widgets:
            connect_changed(widget, self.changed)

    def changed(self) -> None:
        self.setDirty()
        self.schedule_preview()

    def updateData(self, obj, prop):
        if prop in ("Base", "ToolController", "DevelopedSketch"):
            self.schedule_preview()

    # -- preview and validity ---------------------------------------------------
    def schedule_preview(self) -> None:
        self._timer.start()

    def update_preview(self) -> None:
        """Re-plan the op from the panel's values; redraw, or show the error."""
        self._timer.stop()
        error, invalid, plan = None, (), None
        values = self.values()
        try:
            plan = self.obj.Proxy.plan_with(self.obj, values)
        except ValueError as bad_input:  # CycleError and GrooveInputError are ValueErrors
            error, invalid = str(bad_input), error_properties(bad_input)
        except Exception as bug:  # a bug, not bad input: say so in the panel, details in the report view
            import traceback

            FreeCAD.Console.PrintError(traceback.format_exc())
            error = translate(CONTEXT, "Internal error while planning the slot: {0}").format(bug)
        self.replans += 1
        self.plan = plan
        width = end_mill_diameter(values.get("ToolController", self.obj.ToolController))
        self.picture.show(developed_path(plan, width) if plan is not None else None)
        self.set_error(error, invalid)
        self.warnings = list(plan.warnings) if plan is not None else []
        for page in [self] + list(self.other_pages):
            show_warnings(child(page.form, WARNING_LABEL), self.warnings)

    def set_error(self, message: object, properties: tuple = ()) -> None:
        """Show ``message`` (None: the values make a slot) on every page and mark the fields of ``properties``."""
        was_valid = self.error is None
        self.error = message
        for prop in self.invalid:
            mark_invalid(self._field_anywhere(prop), False)
        self.invalid = tuple(properties) if message else ()
        for prop in self.invalid:
            mark_invalid(self._field_anywhere(prop), True)
        for page in [self] + list(self.other_pages):
            show_error(child(page.form, ERROR_LABEL), message)
        if was_valid != (message is None) and self.on_validity_changed is not None:
            self.on_validity_changed()

    def _field_anywhere(self, prop: str) -> object:
        if prop == "Base":
            return next((p.form.baseList for p in self.other_pages if isinstance(p, SlotBaseGeometryPage)), None)
        return self.field(prop)

    def cleanupPage(self, obj):
        self._timer.stop()


def end_mill_diameter(tool_controller: object) -> float:
    """The diameter (mm) of the tool controller's tool bit (0: none)."""
    tool = getattr(tool_controller, "Tool", None)
    diameter = getattr(tool, "Diameter", 0.0)
    return float(getattr(diameter, "Value", diameter))


class RefusesOkWhileInvalid:
    """Mixin before Path.Op.Gui.Base.TaskPanel: OK and Apply disabled while ``self.op_page.error`` stands, and
    refused (one line in the report view) if reached anyway; the page re-plans with the values shown first."""

    def update_buttons(self) -> None:
        box = getattr(self, "buttonBox", None)
        if box is None:
            return
        valid = self.op_page.error is None
        box.button(QtGui.QDialogButtonBox.Ok).setEnabled(valid)
        box.button(QtGui.QDialogButtonBox.Apply).setEnabled(valid and self.isDirty())

    def pageDirtyChanged(self, page):
        self.update_buttons()

    def modifyStandardButtons(self, buttonBox):
        super().modifyStandardButtons(buttonBox)
        fit_narrow_docks(buttonBox)  # OK, Cancel, Apply: three 80 px buttons are wider than 1.0's dock
        self.update_buttons()

    def _refuse(self) -> bool:
        self.op_page.update_preview()  # the values the user sees now, not those of 20 ms ago
        if self.op_page.error is None:
            return False
        FreeCAD.Console.PrintWarning("%s: %s\n" % (self.obj.Label, self.op_page.error))
        return True

    def accept(self, resetEdit=True):
        if self._refuse():
            return False
        super().accept(resetEdit)
        return True

    def clicked(self, button):
        if button == QtGui.QDialogButtonBox.Apply and self._refuse():
            return
        super().clicked(button)


class SlotTaskPanel(ForgetsButtonBox, RefusesOkWhileInvalid, PathOpGui.TaskPanel):
    """FreeCAD's op task panel for the Cylinder slot: OK/Apply refused while the slot is invalid; the button
    box's wrappers forgotten on closing (qt_wrappers.py)."""

    def __init__(self, obj, deleteOnReject, opPage, selectionFactory):
        self.op_page = opPage
        # Before CAM's panel shows the op and hides the model and stock: that marks the document modified.
        self.gui_document = FreeCADGui.getDocument(obj.Document.Name)
        self.was_modified, self.looks_before = self.gui_document.Modified, document_looks(obj.Document)
        self.applied = False  # Apply wrote the panel's values into the op
        super().__init__(obj, deleteOnReject, opPage, selectionFactory)
        opPage.other_pages = [p for p in self.featurePages if p is not opPage]
        opPage.on_validity_changed = self.update_buttons

    def clicked(self, button):
        was_dirty = self.isDirty()
        super().clicked(button)
        if button == QtGui.QDialogButtonBox.Apply and was_dirty and not self.isDirty():
            self.applied = True

    def reject(self, resetEdit=True):
        """Cancel; a saved document stays unmodified when the panel of an existing op changed nothing in it
        (CAM's panel only shows and hides objects while it is open), as the Groove panel does."""
        unchanged = not self.deleteOnReject and not self.applied
        result = super().reject(resetEdit)
        if unchanged and not self.was_modified and document_looks(self.gui_document.Document) == self.looks_before:
            self.gui_document.Modified = False
        return result


def open_panel(vobj: object, delete_on_reject: bool) -> SlotTaskPanel:
    """Show the panel of the op of ``vobj`` (ViewProviderCylinderSlot.setEdit)."""
    obj = vobj.Object
    page = SlotPage(obj, 0)
    page.setTitle(translate(CONTEXT, "Cylinder slot"))
    page.setIcon(ICON)
    panel = SlotTaskPanel(obj, delete_on_reject, page, lambda: None)
    FreeCADGui.Control.closeDialog()
    FreeCADGui.Control.showDialog(panel)
    panel.setupUi()
    job = PathUtils.findParentJob(obj)
    if job is not None and hasattr(getattr(job.ViewObject, "Proxy", None), "setupEditVisibility"):
        job.ViewObject.Proxy.setupEditVisibility(job)
    return panel
