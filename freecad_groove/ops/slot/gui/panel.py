"""The Cylinder slot task panel, on FreeCAD CAM's op panel framework
(Path.Op.Gui.Base) like the Groove panel: OK/Apply/Cancel, the undo
transaction, the tool controller combo.

Pages:
- Base Geometry: FreeCAD's list, here of the cylindrical face and the edges
  of the slot's centre line (in order).
- Cylinder slot: the tool controller (under it the feed and live tool speed
  the slot is milled with: ops/slot/cutting.py) and coolant, the path (the edges in Base
  Geometry, or a sketch of the developed surface: DevelopedSketch), Depth,
  Passes, Allowance, Retract, and the live preview of the developed path with
  its passes (preview.py: a picture in the panel).

Every changed value re-plans the op from the panel's values
(ObjectCylinderSlot.plan_with: the document is not touched) and redraws the
picture (preview.py). An invalid value shows the op's message in one line (red) on both
pages and marks its field; OK and Apply are refused while it stands. The
plan's warnings (reach.py) show in amber and never block. OK writes the
values and recomputes; Cancel aborts the panel's transaction (for a new op,
deletes it).

Not stored in documents (ViewProviderCylinderSlot.setEdit in view.py builds
it): free to move.
"""

import FreeCAD
import FreeCADGui
import Path.Op.Gui.Base as PathOpGui
import PathScripts.PathUtils as PathUtils
from PySide import QtGui

from ....gui import qt_wrappers
from ....gui.live_page import LivePage
from ....gui.task_dialog import AddonTaskPanel
from ....gui.widgets import (
    CONTEXT,
    ERROR_LABEL,
    QuantityFields,
    add_error_label,
    child,
    connect_changed,
    fit_narrow_docks,
    new_warning_label,
)
from . import ICON
from .preview import DevelopedPicture, developed_path

translate = FreeCAD.Qt.translate

SLOT_QUANTITIES = (("depth", "Depth"), ("allowance", "Allowance"), ("retract", "Retract"))
TOOLTIPS = {
    "Depth": "Depth of the slot below the cylinder, radial (J = -2 Depth)",
    "Passes": "Rough passes before the finish pass (L; 1 runs as 2, as GSK does)",
    "Allowance": "Finishing allowance, radial, left by the rough passes (K = 2 Allowance)",
    "Retract": "Clearance above the cylinder the tool retracts to between passes, radial (R = 2 Retract)",
    "FeedsAndSpeeds": "The feed and the live tool's speed: the tool controller's HorizFeed and SpindleSpeed, or the "
                      "defaults where they are 0 (set them in the tool controller)",
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
    form.feedsAndSpeeds = QtGui.QLabel(form)  # the op's FeedsAndSpeeds as planned with the panel's values
    form.feedsAndSpeeds.setObjectName("feedsAndSpeeds")
    form.feedsAndSpeeds.setWordWrap(True)
    form.feedsAndSpeeds.setToolTip(translate(CONTEXT, TOOLTIPS["FeedsAndSpeeds"]))
    layout.addWidget(form.feedsAndSpeeds, layout.rowCount(), 0, 1, 2)
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


class SlotPage(LivePage):
    """The slot's values and the live preview; owns the validity state (live_page.py)."""

    INTERNAL_ERROR = FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Internal error while planning the slot: {0}")

    def getForm(self):
        return build_form()

    def taskPanelBaseGeometryPage(self, obj, features):
        return SlotBaseGeometryPage(obj, features)

    def initPage(self, obj):
        self.fields = QuantityFields(self.form, SLOT_QUANTITIES)
        self.picture = DevelopedPicture(child(self.form, "developedPicture"), child(self.form, "passesLabel"))
        self.init_live()  # no preview in the 3D view: the picture is in the page
        self.plan = None
        self.planned_values = {}

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

    # -- preview and validity (live_page.LivePage) --------------------------------
    def replan(self) -> object:
        self.planned_values = self.values()
        return self.obj.Proxy.plan_with(self.obj, self.planned_values)

    def show_plan(self, plan: object) -> None:
        """The developed path of ``plan`` (none while invalid) and its warnings."""
        self.plan = plan
        width = end_mill_diameter(self.planned_values.get("ToolController", self.obj.ToolController))
        self.picture.show(developed_path(plan, width) if plan is not None else None)
        self.form.feedsAndSpeeds.setText(plan.cutting.describe() if plan is not None else "")
        self.show_warning_lines(list(plan.warnings) if plan is not None else [])


def end_mill_diameter(tool_controller: object) -> float:
    """The diameter (mm) of the tool controller's tool bit (0: none)."""
    tool = getattr(tool_controller, "Tool", None)
    diameter = getattr(tool, "Diameter", 0.0)
    return float(getattr(diameter, "Value", diameter))


class SlotTaskPanel(AddonTaskPanel):
    """The add-on's op dialog (task_dialog.py: OK/Apply refused while the slot is invalid, the button box's
    wrappers forgotten on closing, a saved document left unmodified by a look) for the Cylinder slot."""


def open_panel(vobj: object, delete_on_reject: bool) -> SlotTaskPanel:
    """Show the panel of the op of ``vobj`` (ViewProviderCylinderSlot.setEdit)."""
    obj = vobj.Object
    qt_wrappers.collect_closed_panels()
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
