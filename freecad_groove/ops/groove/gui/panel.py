"""The Groove task panel, built on FreeCAD CAM's own op panel framework
(Path.Op.Gui.Base): the same layout, OK/Apply/Cancel, undo transaction and
tool controller handling as FreeCAD's operations.

Pages:
- Base Geometry: FreeCAD's list of picked faces, plus the groove kind in
  words (longitudinal/face/oblique, external/internal) for the faces.
- Tool and coolant (tool_page.py): tool controller, coolant mode, the
  blade's width/corner radius used when the tool bit has none, and a button
  that makes a grooving tool controller for the Job.
- Groove: the groove's size (resources/panels/PageGrooveEdit.ui) with a
  labelled cross-section picture.

While the panel is open every changed value re-plans the op from the panel's
values (ObjectGroove.plan_with: the document is not touched) and redraws the
preview (preview.py). An invalid value marks its field red, the engine's
message (with the Siemens alarm number where there is one) shows on the
pages, and OK and Apply are refused until it is fixed; so is a panel with
no face picked (OK would make an op that cuts nothing). Warnings of the plans
(what the op cannot do as programmed but does anyway) show in amber under it,
one a line, and mark their fields amber; OK stays enabled. OK writes the values
into the op and recomputes; Cancel aborts the panel's transaction (and, for a
new op, deletes it), so the document is as it was.

A document saved from the GUI stores, in the view provider's state, the
class path of the page FreeCAD builds when the op is edited:
``freecad_groove.ops.groove.gui.panel.GroovePage`` since the ops moved here,
``freecad_groove.gui.task_panel.GroovePage`` before (that module keeps it as
a shim). Keep GroovePage here. The pages are built from the small Qt helpers
in gui/widgets.py; the dialog around them (OK refused while invalid, the
document's modified flag) is gui/task_dialog.py, with the tool page
(tool_page.py) added by GrooveTaskPanel here.
"""

import os

import FreeCAD
import FreeCADGui
from PySide import QtGui

from ....freecad.addon_op import WithValues
from ....gui import PANELS
from ....gui.geometry_page import FacesPage
from ....gui.live_page import LivePage
from ....gui.task_dialog import AddonTaskPanel
from ....gui.widgets import (
    CONTEXT,
    ERROR_LABEL,
    QuantityFields,
    ScaledPicture,
    add_label,
    child,
    connect_changed,
    fill_combo,
    load_form,
    new_warning_label,
    select_data,
    show_quantity,
)
from ..model import MODEL_VALUES, not_overridden
from ..properties import CHAMFER_MEASURES, GrooveInputError, cycle93_properties, error_properties
from . import ICON, preview
from .tool_page import ToolPage

translate = FreeCAD.Qt.translate

FROM_MODEL_LABEL = "fromModelLabel"  # the line naming the values that came from the model
FROM_MODEL_PROPERTY = "fromModel"  # Qt property of a field showing the model's value

DIAGRAM_SIZE = (360, 170)  # px: the groove picture at most (groove_section.svg is 360 x 170)

# (widget name, op property): quantity fields (Gui::QuantitySpinBox)
GROOVE_QUANTITIES = (
    ("position", "Position"), ("width", "Width"), ("depth", "Depth"),
    ("flankAngle1", "FlankAngle1"), ("flankAngle2", "FlankAngle2"),
    ("edgeCorner1", "EdgeCorner1"), ("edgeCorner2", "EdgeCorner2"),
    ("baseCorner1", "BaseCorner1"), ("baseCorner2", "BaseCorner2"),
    ("baseAllowance", "BaseAllowance"), ("flankAllowance", "FlankAllowance"),
    ("infeed", "Infeed"), ("retract", "Retract"), ("pitch", "Pitch"),
)
CORNERS = ("EdgeCorner1", "EdgeCorner2", "BaseCorner1", "BaseCorner2")

# Enumeration texts as shown (translated); the op stores the untranslated value.
# Short: a combo box is as wide as its longest text, and the page must fit 1.0's narrow dock.
CORNER_TYPE_TEXT = {
    "None": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "None"),
    "Radius": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Radius"),
    "Chamfer": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Chamfer"),
}
CHAMFER_MEASURE_TEXT = {
    CHAMFER_MEASURES[0]: FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Length (CHF)"),
    CHAMFER_MEASURES[1]: FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Leg (CHR)"),
}


class BaseGeometryPage(FacesPage):
    """FreeCAD's base geometry page, plus the groove kind of the picked faces."""

    def add_lines(self, form: object) -> None:
        self.kind_label = add_label(form, "grooveKind")

    def setFields(self, obj):
        super().setFields(obj)
        self.show_kind(obj)

    def show_kind(self, obj: object) -> None:
        """The groove kind of the faces in Base, in words."""
        words = []
        try:
            for face in obj.Proxy.groove_faces(obj):
                text = "%s: %s" % (face.name, face.describe())
                if text not in words:
                    words.append(text)
        except ValueError:
            pass  # the error shows on every page
        if words:
            self.kind_label.setText(translate(CONTEXT, "Groove kind") + ": " + "; ".join(words))
        else:
            self.kind_label.setText(translate(CONTEXT, "Pick a cylinder, cone or plane face of the turned part."))

    def pageUpdateData(self, obj, prop):
        super().pageUpdateData(obj, prop)
        if prop == "Base":
            self.show_kind(obj)


class GroovePage(LivePage):
    """The groove's size; owns the live preview and the validity state (live_page.py)."""

    INTERNAL_ERROR = FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Internal error while planning the groove: {0}")

    def getForm(self):
        form = load_form("PageGrooveEdit.ui")
        for name in ("edgeCorner1Type", "edgeCorner2Type", "baseCorner1Type", "baseCorner2Type"):
            fill_combo(child(form, name), CORNER_TYPE_TEXT)
        fill_combo(form.chamferMeasure, CHAMFER_MEASURE_TEXT)
        # The picture follows the dock's width (never sets it): whole, smaller in a narrow dock.
        self.diagram = ScaledPicture(child(form, "diagram"), os.path.join(PANELS, "groove_section.svg"), *DIAGRAM_SIZE)
        # The message goes first: the page is taller than the task view.
        error = child(form, ERROR_LABEL)
        error.parentWidget().layout().removeWidget(error)
        form.layout().insertWidget(0, error)
        error.setVisible(False)
        form.layout().insertWidget(1, new_warning_label(form))
        model = QtGui.QCheckBox(translate(CONTEXT, "Groove from the model"), form)
        model.setObjectName("modelGroove")
        model.setToolTip(translate(CONTEXT, "The picked face is a face of a modelled groove (its base, a flank, a "
                                   "corner): its position, size, angles and corners come from the model. A value "
                                   "changed here overrides the model's."))
        form.layout().insertWidget(2, model)
        note = QtGui.QLabel(form)
        note.setObjectName(FROM_MODEL_LABEL)
        note.setWordWrap(True)
        note.setVisible(False)
        form.layout().insertWidget(3, note)
        return form

    def taskPanelBaseGeometryPage(self, obj, features):
        return BaseGeometryPage(obj, features)

    def initPage(self, obj):
        self.fields = QuantityFields(self.form, GROOVE_QUANTITIES)
        self.init_live()
        self.plans = []
        self.model_shown = {}  # {property: value} the fields show from the model
        self.model_box_chosen = False  # the user ticked or unticked "Groove from the model" (it no longer follows)

    def getTitle(self, obj):
        return translate(CONTEXT, "Groove")

    def getIcon(self, obj):
        return ICON

    # -- fields <-> op ----------------------------------------------------------
    def setFields(self, obj):
        self.fields.set_from(obj)
        for name in CORNERS:
            select_data(self.field(name + "Type"), str(getattr(obj, name + "Type")))
        select_data(self.form.chamferMeasure, str(obj.ChamferMeasure))
        self.form.dwell.setValue(float(obj.Dwell))
        self.form.grooveCount.setValue(int(obj.GrooveCount))
        self.model_box().blockSignals(True)
        self.model_box().setChecked(bool(getattr(obj, "ModelGroove", False)))
        self.model_box().blockSignals(False)
        shown = self.values()
        self.model_shown = {p: shown[p] for p in getattr(obj, "FromModel", []) if p in shown} \
            if self.model_box().isChecked() else {}
        self._show_from_model()
        self._enable_corner_sizes()
        if getattr(getattr(self, "parent", None), "deleteOnReject", False):  # a new op: its faces just picked
            self.follow_picked_faces(obj)
        self.schedule_preview()

    def getFields(self, obj):
        if bool(getattr(obj, "ModelGroove", False)) != self.model_box().isChecked():
            obj.ModelGroove = self.model_box().isChecked()  # first: values changed after it are overrides
        from_model = self._from_model()
        for prop, value in self.fields.values().items():
            if prop not in from_model and abs(getattr(obj, prop).Value - value) > 1e-12:
                setattr(obj, prop, value)
        for name in CORNERS:
            value = self.field(name + "Type").currentData()
            if value and name + "Type" not in from_model and getattr(obj, name + "Type") != value:
                setattr(obj, name + "Type", value)
        value = self.form.chamferMeasure.currentData()
        if value and obj.ChamferMeasure != value:
            obj.ChamferMeasure = value
        if abs(float(obj.Dwell) - self.form.dwell.value()) > 1e-12:
            obj.Dwell = self.form.dwell.value()
        if int(obj.GrooveCount) != self.form.grooveCount.value():
            obj.GrooveCount = self.form.grooveCount.value()

    def values(self) -> dict:
        """{op property: value} as this page shows them."""
        values = self.fields.values()
        for name in CORNERS:
            values[name + "Type"] = self.field(name + "Type").currentData()
        values["ChamferMeasure"] = self.form.chamferMeasure.currentData()
        values["Dwell"] = self.form.dwell.value()
        values["GrooveCount"] = self.form.grooveCount.value()
        values["ModelGroove"] = self.model_box().isChecked()
        return values

    def all_values(self) -> dict:
        """{op property: value} as every page of the panel shows them."""
        values = {}
        for page in self.other_pages:
            if hasattr(page, "values"):
                values.update(page.values())
        values.update(self.values())
        return values

    def field(self, prop: str) -> object:
        """The field of an op property ("Width") on any page, or None."""
        name = prop[0].lower() + prop[1:]
        for page in [self] + list(self.other_pages):
            widget = child(page.form, name)
            if widget is not None:
                return widget
        return None

    def registerSignalHandlers(self, obj):
        widgets = list(self.fields.widgets.values())
        widgets += [self.field(n + "Type") for n in CORNERS]
        widgets += [self.form.chamferMeasure, self.form.dwell, self.form.grooveCount]
        for widget in widgets:
            connect_changed(widget, self.changed)
        self.model_box().toggled.connect(lambda *_a: self.model_toggled())
        # the chamfers read as CHR or CHF: the model's values read again
        self.form.chamferMeasure.currentIndexChanged.connect(
            lambda *_a: self.fill_from_model() if self.model_box().isChecked() else None)
        self.model_box().clicked.connect(lambda *_a: setattr(self, "model_box_chosen", True))

    def changed(self) -> None:
        """A value changed: the panel is dirty, the preview follows."""
        self._show_from_model()
        self._enable_corner_sizes()
        self.setDirty()
        self.schedule_preview()

    def _enable_corner_sizes(self):
        for name in CORNERS:
            self.field(name).setEnabled(self.field(name + "Type").currentData() != "None")

    def updateData(self, obj, prop):
        if prop == "Base":
            self.follow_picked_faces(obj)
        if prop == "Base" and self.model_box().isChecked():
            self.fill_from_model()
        if prop in ("Base", "ToolController"):
            self.schedule_preview()

    # -- values from the model ----------------------------------------------------
    def model_box(self) -> object:
        """The "Groove from the model" check box (ModelGroove)."""
        return child(self.form, "modelGroove")

    def follow_picked_faces(self, obj: object) -> None:
        """A picked face of a groove in the model ticks "Groove from the model": the op takes the model's groove
        by default (a groove typed into a modelled groove's face would cut below its finished shape), until the
        user ticks or unticks the box."""
        if self.model_box_chosen or self.model_box().isChecked():
            return
        try:
            modelled = obj.Proxy.in_modelled_groove(obj)
        except ValueError:  # a face the op refuses: its message shows with the preview
            return
        if modelled:  # (its signal may not be connected yet: the panel connects them after setFields)
            self.model_box().blockSignals(True)
            self.model_box().setChecked(True)
            self.model_box().blockSignals(False)
            self.model_toggled()

    def model_toggled(self) -> None:
        if self.model_box().isChecked():
            self.fill_from_model()
        else:
            self.model_shown = {}
        self.changed()

    def fill_from_model(self) -> None:
        """Show the model's values (those not in the op's ModelOverrides) in the
        fields; nothing when the picked faces make no modelled groove (the
        preview then shows why)."""
        obj = self.obj
        try:
            groove = obj.Proxy.model_groove(WithValues(obj, {"ChamferMeasure": self.values()[
                "ChamferMeasure"]}))
        except ValueError:
            self.model_shown = {}
            return
        self.model_shown = not_overridden(groove.values, list(obj.ModelOverrides))
        for prop, value in self.model_shown.items():
            widget = self.field(prop)
            widget.blockSignals(True)
            if prop.endswith("Type"):
                select_data(widget, value)
            else:
                show_quantity(widget, value)
            widget.blockSignals(False)
        self._show_from_model()

    def _from_model(self) -> tuple:
        """The properties whose fields still show the model's value."""
        shown = self.values()
        return tuple(p for p, v in self.model_shown.items()
                     if (shown[p] == v if isinstance(v, str) else abs(shown[p] - v) <= 1e-9))

    def _show_from_model(self) -> None:
        """"From the model: Position, Width, ..." over the fields, each such field marked."""
        from_model = self._from_model()
        for prop in MODEL_VALUES:
            widget = self.field(prop)
            if widget is not None:
                widget.setProperty(FROM_MODEL_PROPERTY, prop in from_model)
        label = child(self.form, FROM_MODEL_LABEL)
        label.setText(translate(CONTEXT, "From the model: {0}").format(", ".join(from_model)) if from_model else "")
        label.setVisible(bool(from_model))

    # -- preview and validity ---------------------------------------------------
    def error_fields(self, bad_input: ValueError) -> tuple:
        """The op properties an error names, a CYCLE93 parameter's included (properties.error_properties)."""
        return error_properties(bad_input)

    def replan(self) -> list:
        """The op's plans from the panel's values (live_page.LivePage)."""
        plans = self.obj.Proxy.plan_with(self.obj, self.all_values())
        if not plans:  # OK would make an op that cuts nothing
            raise GrooveInputError(translate(
                CONTEXT, "Base Geometry: no face picked. Pick a cylinder, cone or plane face of the turned part "
                "and press Add."), ("Base",))
        return plans

    def show_plan(self, plans: object) -> None:
        """Draw ``plans`` (None while invalid) and show their warnings."""
        self.plans = plans or []
        self._show_angc(self.obj, self.plans)
        if self.preview is None:
            view = FreeCADGui.ActiveDocument.ActiveView if FreeCADGui.ActiveDocument else None
            self.preview = preview.Preview(view if hasattr(view, "getSceneGraph") else None)
        self.preview.show(self.plans)
        named = [prop for plan in self.plans for warning in plan.warnings
                 for prop in cycle93_properties(warning.parameter)]
        self.show_warning_lines([text for plan in self.plans for text in plan.warning_texts], tuple(named))

    def _show_angc(self, obj, plans):
        if plans:
            faces = [plans[0].face]
        else:  # the values make no groove; the face may still have an angle
            try:
                faces = obj.Proxy.groove_faces(obj)
            except ValueError:
                faces = []
        if faces:
            text = FreeCAD.Units.Quantity(faces[0].angc, FreeCAD.Units.Angle).UserString
        else:
            text = ""
        self.form.angc.setText(text)


class GrooveTaskPanel(AddonTaskPanel):
    """The Groove op's dialog: the tool page (tool_page.py) before the Groove page."""

    def add_pages(self, obj, op_page):
        """The tool page before the Groove page."""
        tool_page = ToolPage(obj, obj.Proxy.opFeatures(obj))
        tool_page.parent = self
        tool_page.initPage(obj)
        tool_page.onDirtyChanged(self.pageDirtyChanged)
        tool_page.groove_page = op_page
        self.featurePages.insert(self.featurePages.index(op_page), tool_page)
        self._insert_form(tool_page, obj)

    def _insert_form(self, page, obj):
        """Show ``page`` just before the Groove page, whatever the layout."""
        op_form = self.op_page.form
        if isinstance(self.form, QtGui.QToolBox):
            at = self.form.indexOf(op_form)
            reversed_order = at == 0 and self.form.count() > 1
            index = at + 1 if reversed_order else at
            self.form.insertItem(index, page.form, page.getTitle(obj))
            self.form.setCurrentWidget(op_form)
        else:
            page.form.setWindowTitle(page.getTitle(obj))
            at = self.form.index(op_form)
            reversed_order = at == 0 and len(self.form) > 1
            self.form.insert(at + 1 if reversed_order else at, page.form)
