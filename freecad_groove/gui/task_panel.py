"""The Groove task panel, built on FreeCAD CAM's own op panel framework
(Path.Op.Gui.Base): the same layout, OK/Apply/Cancel, undo transaction and
tool controller handling as FreeCAD's operations.

Pages:
- Base Geometry: FreeCAD's list of picked faces, plus the groove kind in
  words (longitudinal/face/oblique, external/internal) for the faces.
- Tool and coolant: tool controller (with FreeCAD 1.1's editor), coolant
  mode, and the blade's width/corner radius used when the tool bit has none.
- Groove: the groove's size (resources/panels/PageGrooveEdit.ui) with a
  labelled cross-section picture.

While the panel is open every changed value re-plans the op from the panel's
values (ObjectGroove.plan_with: the document is not touched) and redraws the
preview (preview.py). An invalid value marks its field red, the engine's
message (with the Siemens alarm number where there is one) shows on the
pages, and OK and Apply are refused until it is fixed. OK writes the values
into the op and recomputes; Cancel aborts the panel's transaction (and, for a
new op, deletes it), so the document is as it was.
"""

import os

import FreeCAD
import FreeCADGui
import Path.Op.Gui.Base as PathOpGui
from PySide import QtCore, QtGui

from ..freecad import faces as faces_mod
from ..freecad import groove_op
from . import ICON, PANELS, preview

translate = FreeCAD.Qt.translate
CONTEXT = "FreeCADGroove"

PREVIEW_DELAY_MS = 20  # coalesces the signals of one edit into one re-plan
INVALID_STYLE = "border: 2px solid #d00000;"
ERROR_STYLE = "color: #b00000;"

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
TOOL_QUANTITIES = (("toolWidth", "ToolWidth"), ("toolCornerRadius", "ToolCornerRadius"))

# Enumeration texts as shown (translated); the op stores the untranslated value.
CORNER_TYPE_TEXT = {
    "None": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "None"),
    "Radius": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Radius"),
    "Chamfer": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Chamfer"),
}
CHAMFER_MEASURE_TEXT = {
    groove_op.CHAMFER_MEASURES[0]: FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Chamfer length (CHF)"),
    groove_op.CHAMFER_MEASURES[1]: FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Leg length (CHR)"),
}
REFERENCE_CORNER_TEXT = {
    "minus": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "minus"),
    "plus": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "plus"),
}


def _load(name):
    return FreeCADGui.PySideUic.loadUi(os.path.join(PANELS, name))


def child(form, name):
    """A form's widget by object name (not getattr: "width" is also QWidget.width())."""
    return form.findChild(QtCore.QObject, name)


def _svg_pixmap(path, width, height):
    """An SVG drawn with QtSvg (FreeCAD 1.1's Qt has no SVG image plugin for QIcon)."""
    from PySide import QtSvg

    pixmap = QtGui.QPixmap(width, height)
    pixmap.fill(QtCore.Qt.transparent)
    painter = QtGui.QPainter(pixmap)
    QtSvg.QSvgRenderer(path).render(painter)
    painter.end()
    return pixmap


def _fill_combo(combo, texts):
    combo.blockSignals(True)
    combo.clear()
    for value, text in texts.items():
        combo.addItem(translate(CONTEXT, text), value)
    combo.blockSignals(False)


def _select(combo, value):
    combo.blockSignals(True)
    index = combo.findData(value)
    if index >= 0:
        combo.setCurrentIndex(index)
    combo.blockSignals(False)


def _connect_changed(widget, slot):
    """Call slot() whenever the user changes the widget's value."""
    if isinstance(widget, QtGui.QComboBox):
        widget.currentIndexChanged.connect(lambda *_a: slot())
    else:
        widget.valueChanged.connect(lambda *_a: slot())


def _mark(widget, invalid):
    if widget is None:
        return
    if invalid:
        if widget.property("grooveInvalid") is not True:
            widget.setProperty("grooveInvalid", True)
            widget.setStyleSheet(INVALID_STYLE)
    elif widget.property("grooveInvalid") is True:
        widget.setProperty("grooveInvalid", False)
        widget.setStyleSheet("")


def _show_error(label, message):
    if label is None:
        return
    label.setText(message or "")
    label.setStyleSheet(ERROR_STYLE)
    label.setVisible(bool(message))


def _add_to_layout(layout, widget):
    if isinstance(layout, QtGui.QGridLayout):
        layout.addWidget(widget, layout.rowCount(), 0, 1, max(1, layout.columnCount()))
    else:
        layout.addWidget(widget)


def _add_error_label(form):
    """The label the engine's message shows in (objectName errorLabel), hidden while all is well."""
    label = QtGui.QLabel(form)
    label.setObjectName("errorLabel")
    label.setWordWrap(True)
    label.setVisible(False)
    _add_to_layout(form.layout(), label)
    return label


class _Fields:
    """Quantity fields (Gui::QuantitySpinBox, unit set in the .ui) for op
    properties. Not CAM's PathGuiUtil.QuantitySpinBox: that one resets a field
    from its property whenever the field gets focus, which would drop a value
    typed earlier, since this panel writes to the op only on OK or Apply."""

    def __init__(self, form, obj, pairs):
        self.widgets = {prop: child(form, name) for name, prop in pairs}

    def set_from(self, obj):
        for prop, widget in self.widgets.items():
            widget.blockSignals(True)
            widget.setProperty("rawValue", float(getattr(obj, prop).Value))
            widget.blockSignals(False)

    def write_to(self, obj):
        for prop, value in self.values().items():
            if abs(getattr(obj, prop).Value - value) > 1e-12:
                setattr(obj, prop, value)

    def values(self):
        """{property: value in mm or degrees} as the fields show them now."""
        return {prop: float(widget.property("rawValue")) for prop, widget in self.widgets.items()}


class BaseGeometryPage(PathOpGui.TaskPanelBaseGeometryPage):
    """FreeCAD's base geometry page, plus the groove kind of the picked faces."""

    def getForm(self):
        form = super().getForm()
        self.kind_label = QtGui.QLabel(form)
        self.kind_label.setObjectName("grooveKind")
        self.kind_label.setWordWrap(True)
        _add_to_layout(form.layout(), self.kind_label)
        _add_error_label(form)
        return form

    def supportsEdges(self):
        return False

    def supportsVertexes(self):
        return False

    def setFields(self, obj):
        super().setFields(obj)
        self.show_kind(obj)

    def show_kind(self, obj):
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


class ToolPage(PathOpGui.TaskPanelPage):
    """Tool controller, coolant, and the blade's size when the tool bit has none."""

    def getForm(self):
        form = _load("PageGrooveToolEdit.ui")
        _fill_combo(form.referenceCorner, REFERENCE_CORNER_TEXT)
        _add_error_label(form)
        return form

    def initPage(self, obj):
        self.fields = _Fields(self.form, obj, TOOL_QUANTITIES)
        self.groove_page = None  # set by GrooveTaskPanel

    def getTitle(self, obj):
        return translate(CONTEXT, "Tool and coolant")

    def getIcon(self, obj):
        return None

    def setFields(self, obj):
        self.setupToolController(obj, self.form.toolController)
        self.setupCoolant(obj, self.form.coolantController)
        self.fields.set_from(obj)
        _select(self.form.referenceCorner, str(obj.ReferenceCorner))
        self.show_tool_source(obj)

    def getFields(self, obj):
        self.updateToolController(obj, self.form.toolController)
        self.updateCoolant(obj, self.form.coolantController)
        self.fields.write_to(obj)
        value = self.form.referenceCorner.currentData()
        if value and obj.ReferenceCorner != value:
            obj.ReferenceCorner = value

    def values(self):
        out = self.fields.values()
        out["ReferenceCorner"] = self.form.referenceCorner.currentData()
        return out

    def registerSignalHandlers(self, obj):
        for widget in list(self.fields.widgets.values()) + [self.form.referenceCorner, self.form.coolantController]:
            _connect_changed(widget, self.changed)
        if not hasattr(self, "tcEditor"):  # FreeCAD 1.0: the base class does not follow the combo
            self.form.toolController.currentIndexChanged.connect(self._tool_controller_changed)

    def _tool_controller_changed(self, *_args):
        self.updateToolController(self.obj, self.form.toolController)
        self.changed()

    def changed(self):
        self.setDirty()
        if self.groove_page is not None:
            self.groove_page.schedule_preview()

    def show_tool_source(self, obj):
        tc = getattr(obj, "ToolController", None)
        bit = getattr(tc, "Tool", None)
        has = [n for n in ("Width", "CornerRadius") if bit is not None and getattr(bit, n, None) is not None]
        if has:
            text = translate(CONTEXT, "The tool bit {0} gives the blade's {1}: the fields below are not used for it.").format(
                bit.Label, " and ".join(has))
        else:
            text = translate(CONTEXT, "The tool bit has no Width or CornerRadius: the blade size below is used.")
        self.form.toolSourceLabel.setText(text)
        self.form.toolWidth.setEnabled("Width" not in has)
        self.form.toolCornerRadius.setEnabled("CornerRadius" not in has)

    def updateData(self, obj, prop):
        if prop == "ToolController":
            self.show_tool_source(obj)
            if self.groove_page is not None:
                self.groove_page.schedule_preview()


class GroovePage(PathOpGui.TaskPanelPage):
    """The groove's size; owns the live preview and the validity state."""

    def getForm(self):
        form = _load("PageGrooveEdit.ui")
        for name in ("edgeCorner1Type", "edgeCorner2Type", "baseCorner1Type", "baseCorner2Type"):
            _fill_combo(child(form, name), CORNER_TYPE_TEXT)
        _fill_combo(form.chamferMeasure, CHAMFER_MEASURE_TEXT)
        child(form, "diagram").setPixmap(_svg_pixmap(os.path.join(PANELS, "groove_section.svg"), 360, 170))
        # The message goes first: the page is taller than the task view.
        error = child(form, "errorLabel")
        error.parentWidget().layout().removeWidget(error)
        form.layout().insertWidget(0, error)
        error.setVisible(False)
        return form

    def taskPanelBaseGeometryPage(self, obj, features):
        return BaseGeometryPage(obj, features)

    def initPage(self, obj):
        self.fields = _Fields(self.form, obj, GROOVE_QUANTITIES)
        self.other_pages = []  # set by GrooveTaskPanel: pages whose values and errors share this state
        self.preview = None
        self.error = None  # the message while the values make no groove
        self.invalid = ()  # properties marked
        self.plans = []
        self.replans = 0
        self.on_validity_changed = None
        self._timer = QtCore.QTimer()  # no parent: it must outlive the form, which Cancel may delete first
        self._timer.setSingleShot(True)
        self._timer.setInterval(PREVIEW_DELAY_MS)
        self._timer.timeout.connect(self.update_preview)

    def getTitle(self, obj):
        return translate(CONTEXT, "Groove")

    def getIcon(self, obj):
        return ICON

    # -- fields <-> op ----------------------------------------------------------
    def setFields(self, obj):
        self.fields.set_from(obj)
        for name in CORNERS:
            _select(self.field(name + "Type"), str(getattr(obj, name + "Type")))
        _select(self.form.chamferMeasure, str(obj.ChamferMeasure))
        self.form.dwell.setValue(float(obj.Dwell))
        self.form.grooveCount.setValue(int(obj.GrooveCount))
        self._enable_corner_sizes()
        self.schedule_preview()

    def getFields(self, obj):
        self.fields.write_to(obj)
        for name in CORNERS:
            value = self.field(name + "Type").currentData()
            if value and getattr(obj, name + "Type") != value:
                setattr(obj, name + "Type", value)
        value = self.form.chamferMeasure.currentData()
        if value and obj.ChamferMeasure != value:
            obj.ChamferMeasure = value
        if abs(float(obj.Dwell) - self.form.dwell.value()) > 1e-12:
            obj.Dwell = self.form.dwell.value()
        if int(obj.GrooveCount) != self.form.grooveCount.value():
            obj.GrooveCount = self.form.grooveCount.value()

    def values(self):
        """{op property: value} as this page shows them."""
        out = self.fields.values()
        for name in CORNERS:
            out[name + "Type"] = self.field(name + "Type").currentData()
        out["ChamferMeasure"] = self.form.chamferMeasure.currentData()
        out["Dwell"] = self.form.dwell.value()
        out["GrooveCount"] = self.form.grooveCount.value()
        return out

    def all_values(self):
        out = {}
        for page in self.other_pages:
            if hasattr(page, "values"):
                out.update(page.values())
        out.update(self.values())
        return out

    def field(self, prop):
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
            _connect_changed(widget, self.changed)

    def changed(self):
        self._enable_corner_sizes()
        self.setDirty()
        self.schedule_preview()

    def _enable_corner_sizes(self):
        for name in CORNERS:
            self.field(name).setEnabled(self.field(name + "Type").currentData() != "None")

    def updateData(self, obj, prop):
        if prop in ("Base", "ToolController"):
            self.schedule_preview()

    # -- preview and validity ---------------------------------------------------
    def schedule_preview(self):
        self._timer.start()

    def update_preview(self):
        """Re-plan the op from the panel's values; redraw or show the error."""
        self._timer.stop()
        obj = self.obj
        error, invalid, plans = None, (), []
        try:
            plans = obj.Proxy.plan_with(obj, self.all_values())
        except ValueError as e:  # CycleError and GrooveInputError are ValueErrors
            error, invalid = str(e), groove_op.error_properties(e)
        except Exception as e:  # a bug, not bad input: say so in the panel, details in the report view
            import traceback

            FreeCAD.Console.PrintError(traceback.format_exc())
            error = translate(CONTEXT, "Internal error while planning the groove: {0}").format(e)
        self.replans += 1
        self.plans = plans
        self._show_angc(obj, plans)
        if self.preview is None:
            view = FreeCADGui.ActiveDocument.ActiveView if FreeCADGui.ActiveDocument else None
            self.preview = preview.Preview(view if hasattr(view, "getSceneGraph") else None)
        self.preview.show(plans)
        self.set_error(error, invalid)

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

    def set_error(self, message, properties=()):
        was_valid = self.error is None
        self.error = message
        for prop in self.invalid:
            _mark(self.field(prop), False)
        self.invalid = tuple(properties) if message else ()
        for prop in self.invalid:
            _mark(self.field(prop), True)
        if "Base" in self.invalid:
            _mark(self._base_list(), True)
        else:
            _mark(self._base_list(), False)
        for page in [self] + list(self.other_pages):
            _show_error(child(page.form, "errorLabel"), message)
        if was_valid != (message is None) and self.on_validity_changed is not None:
            self.on_validity_changed()

    def _base_list(self):
        for page in self.other_pages:
            if isinstance(page, BaseGeometryPage):
                return page.form.baseList
        return None

    def cleanupPage(self, obj):
        self._timer.stop()
        if self.preview is not None:
            self.preview.remove()
            self.preview = None


class GrooveTaskPanel(PathOpGui.TaskPanel):
    """FreeCAD's op task panel with the tool page added and OK/Apply refused
    while the groove is invalid."""

    def __init__(self, obj, deleteOnReject, opPage, selectionFactory):
        super().__init__(obj, deleteOnReject, opPage, selectionFactory)
        self.groove_page = opPage
        tool_page = ToolPage(obj, obj.Proxy.opFeatures(obj))
        tool_page.parent = self
        tool_page.initPage(obj)
        tool_page.onDirtyChanged(self.pageDirtyChanged)
        tool_page.groove_page = opPage
        self.featurePages.insert(self.featurePages.index(opPage), tool_page)
        opPage.other_pages = [p for p in self.featurePages if p is not opPage]
        opPage.on_validity_changed = self.update_buttons
        self._insert_form(tool_page, obj)

    def _insert_form(self, page, obj):
        """Show ``page`` just before the Groove page, whatever the layout."""
        op_form = self.groove_page.form
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

    @property
    def valid(self):
        return self.groove_page.error is None

    def update_buttons(self):
        box = getattr(self, "buttonBox", None)
        if box is None:
            return
        box.button(QtGui.QDialogButtonBox.Ok).setEnabled(self.valid)
        box.button(QtGui.QDialogButtonBox.Apply).setEnabled(self.valid and self.isDirty())

    def pageDirtyChanged(self, page):
        self.update_buttons()

    def modifyStandardButtons(self, buttonBox):
        super().modifyStandardButtons(buttonBox)
        self.update_buttons()

    def _refuse(self):
        self.groove_page.update_preview()  # the values the user sees now, not those of 20 ms ago
        if self.valid:
            return False
        FreeCAD.Console.PrintWarning("%s: %s\n" % (self.obj.Label, self.groove_page.error))
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


class ViewProvider(PathOpGui.ViewProvider):
    """The op's view provider: FreeCAD's, with the add-on's icon, selection
    gate and task panel."""

    def getIcon(self):
        if getattr(self, "Object", None) is not None and not self.Object.Active:
            return ":/icons/CAM_OpActive.svg"
        return ICON

    def getSelectionFactory(self):
        return select_turned_faces

    def setEdit(self, vobj=None, mode=0):
        if mode != 0:
            return False
        if vobj is None:
            vobj = self.vobj
        page = self.getTaskPanelOpPage(vobj.Object)
        page.setTitle(translate(CONTEXT, "Groove"))
        page.setIcon(ICON)
        self.setupTaskPanel(GrooveTaskPanel(vobj.Object, self.deleteObjectsOnReject(), page, self.getSelectionFactory()))
        self.deleteOnReject = False
        return True


class TurnedFaceGate:
    """Lets the user pick only faces a groove can be cut into."""

    def allow(self, doc, obj, sub):
        if not sub or not sub.startswith("Face") or not hasattr(obj, "Shape"):
            return False
        try:
            faces_mod.analyse_face(obj.Shape.getElement(sub), sub)
        except Exception:
            return False
        return True


def select_turned_faces():
    FreeCADGui.Selection.addSelectionGate(TurnedFaceGate())


def resources():
    return PathOpGui.CommandResources(
        "Groove", groove_op.Create, GroovePage, ICON,
        FreeCAD.Qt.QT_TRANSLATE_NOOP("FreeCADGroove_Groove", "Groove"), None,
        FreeCAD.Qt.QT_TRANSLATE_NOOP("FreeCADGroove_Groove", "Cut a groove into a turned face"),
    )


def attach_view_provider(obj, delete_on_reject=False):
    """Give the op its view provider (ops made by scripts get one too)."""
    vobj = obj.ViewObject
    if vobj is None:
        return
    if not isinstance(getattr(vobj, "Proxy", None), ViewProvider):
        vobj.Proxy = ViewProvider(vobj, resources())
    vobj.Proxy.setDeleteObjectsOnReject(delete_on_reject)


def create(job):
    """A new Groove op in ``job`` with its task panel open (what the command
    does). Cancel deletes it again. Returns the op, or None."""
    doc = job.Document
    doc.openTransaction(translate(CONTEXT, "Create Groove"))
    try:
        obj = groove_op.Create("Groove", parentJob=job)
        attach_view_provider(obj, delete_on_reject=True)
        obj.ViewObject.Visibility = True
    except Exception as e:
        doc.abortTransaction()
        FreeCAD.Console.PrintError(translate(CONTEXT, "Groove: cannot create the operation: {0}").format(e) + "\n")
        return None
    doc.commitTransaction()
    obj.ViewObject.Document.setEdit(obj.ViewObject, 0)
    return obj
