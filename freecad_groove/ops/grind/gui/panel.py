"""The Plunge grind task panel, on FreeCAD CAM's op panel framework
(Path.Op.Gui.Base) as the Groove panel is: CAM's Base Geometry page (one
flat face looking up) and the "Plunge grind" page: the tool controller, the
coolant mode and every property of properties.PROPERTIES but
the derived GrindCall, which the page shows as the G83/G83.1 block the
values program.

While the panel is open every changed value re-plans the op from the panel's
values (the op seen through addon_op.WithValues: the document is not
touched) and draws its strokes in the 3D view (preview.py); an
invalid value shows the op's message in one line on both pages, frames the
fields it names red, and OK and Apply are refused until it is
fixed (task_dialog.AddonTaskPanel). OK writes the values into the op and
recomputes; Cancel aborts the panel's transaction (and, for a new op,
deletes it).

The page's class path is stored in documents (in the view provider's state,
as CAM's op view providers keep their page):
``freecad_groove.ops.grind.gui.panel.PlungeGrindPage`` since the ops moved
here, ``freecad_groove.gui.grind_panel.PlungeGrindPage`` before (that module
keeps it as a shim). Keep it here.
"""

import FreeCAD
import FreeCADGui
import PathScripts.PathUtils as PathUtils
from PySide import QtCore, QtGui

from ....freecad.addon_op import WithValues
from ....gui.geometry_page import FacesPage
from ....gui.live_page import LivePage
from ....gui.widgets import (
    CONTEXT,
    add_error_label,
    child,
    connect_changed,
    fit_narrow_docks,
    select_data,
    show_quantity,
)
from ..properties import DERIVED, PROPERTIES
from . import ICON
from .preview import GrindPreview

translate = FreeCAD.Qt.translate

UNITS = {"App::PropertyLength": "mm", "App::PropertySpeed": "mm/min"}  # quantity fields and the unit they show
INTEGER_RANGE = (0, 99999)  # the op checks the ranges of L, P, D and names the property
FIELDS = tuple(p for p in PROPERTIES if p[1] not in DERIVED)  # (type, name, group, tooltip, default)
TOOL_CONTROLLER, COOLANT = "ToolController", "CoolantMode"
GRIND_CALL_LABEL = "grindCall"
NEW_WHEEL_BUTTON = "newWheelTool"


def widget_name(prop: str) -> str:
    """The object name of the field of op property ``prop`` ("PlungePick" -> "plungePick")."""
    return prop[0].lower() + prop[1:]


def label_text(prop: str) -> str:
    """The field's label: the property's name in words ("PlungePick" -> "Plunge pick")."""
    words = "".join(" " + c.lower() if c.isupper() else c for c in prop).strip()
    return words[0].upper() + words[1:]


def _new_field(type_id: str, default: object, parent: object) -> object:
    """The widget editing a property of type ``type_id``."""
    if type_id in UNITS:
        field = FreeCADGui.UiLoader().createWidget("Gui::QuantitySpinBox", parent)
        field.setProperty("unit", UNITS[type_id])
        field.setProperty("minimum", -1e9)  # the op says why a negative value is wrong, naming it
        field.setProperty("maximum", 1e9)
    elif type_id == "App::PropertyInteger":
        field = QtGui.QSpinBox(parent)
        field.setRange(*INTEGER_RANGE)
    elif type_id == "App::PropertyBool":
        field = QtGui.QCheckBox(parent)
    else:  # App::PropertyEnumeration
        field = QtGui.QComboBox(parent)
        for value in default:
            field.addItem(value, value)
    return field


class GrindBaseGeometryPage(FacesPage):
    """FreeCAD's base geometry page, faces only, with the op's message."""


class PlungeGrindPage(LivePage):
    """The op's own values; owns the validity state the dialog reads (live_page.py, as the Groove page)."""

    INTERNAL_ERROR = FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "Internal error while planning the grind: {0}")

    def getForm(self):
        form = QtGui.QWidget()
        form.setObjectName("PlungeGrindPage")
        outer = QtGui.QVBoxLayout(form)
        add_error_label(form)
        call = QtGui.QLabel(form)
        call.setObjectName(GRIND_CALL_LABEL)
        call.setWordWrap(True)
        call.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        outer.addWidget(call)
        grid = QtGui.QFormLayout()
        outer.addLayout(grid)
        for name, text in ((TOOL_CONTROLLER, "Tool controller"), (COOLANT, "Coolant")):
            combo = QtGui.QComboBox(form)
            combo.setObjectName(widget_name(name))
            grid.addRow(translate(CONTEXT, text), combo)
        button = QtGui.QPushButton(translate(CONTEXT, "Create grinding wheel tool controller"), form)
        button.setObjectName(NEW_WHEEL_BUTTON)
        button.setToolTip(translate(CONTEXT, "A new tool controller in the Job whose bit is a grinding wheel of the "
                                    "Wheel width and Wheel diameter below (asked for while 0), selected for the op"))
        grid.addRow(button)
        for type_id, name, _group, tooltip, default in FIELDS:
            field = _new_field(type_id, default, form)
            field.setObjectName(widget_name(name))
            field.setToolTip(translate("App::Property", tooltip))
            grid.addRow(translate(CONTEXT, label_text(name)), field)
        outer.addStretch(1)
        fit_narrow_docks(form)
        return form

    def taskPanelBaseGeometryPage(self, obj, features):
        return GrindBaseGeometryPage(obj, features)

    def initPage(self, obj):
        self.init_live()  # its preview: the strokes drawn in the 3D view (preview.py)
        self.plan = None
        self.shown = {}

    def getTitle(self, obj):
        return translate(CONTEXT, "Plunge grind")

    def getIcon(self, obj):
        return ICON

    def field(self, prop: str) -> object:
        return child(self.form, widget_name(prop))

    # -- fields <-> op ----------------------------------------------------------
    def _fill_tool_controllers(self, selected: object) -> None:
        combo = self.field(TOOL_CONTROLLER)
        combo.blockSignals(True)
        combo.clear()
        for tc in PathUtils.getToolControllers(self.obj):
            combo.addItem(tc.Label, tc.Name)
        combo.blockSignals(False)
        if selected is not None:
            select_data(combo, selected.Name)

    def setFields(self, obj):
        self._fill_tool_controllers(obj.ToolController)
        combo = self.field(COOLANT)
        combo.blockSignals(True)
        combo.clear()
        for mode in PathUtils.findParentJob(obj).SetupSheet.CoolantModes:
            combo.addItem(mode, mode)
        combo.blockSignals(False)
        select_data(combo, str(obj.CoolantMode))
        self.shown = {}  # {property: the quantity field's value as shown for the op's own value}
        for type_id, name, _group, _tip, _default in FIELDS:
            self._show(self.field(name), type_id, getattr(obj, name))
            if type_id in UNITS:
                self.shown[name] = FreeCAD.Units.Quantity(self.field(name).property("value")).Value
        self.schedule_preview()

    @staticmethod
    def _show(field: object, type_id: str, value: object) -> None:
        field.blockSignals(True)
        if type_id in UNITS:
            show_quantity(field, value.Value)  # as many decimals as it has (up to 6)
        elif type_id == "App::PropertyInteger":
            field.setValue(int(value))
        elif type_id == "App::PropertyBool":
            field.setChecked(bool(value))
        else:
            select_data(field, str(value))
        field.blockSignals(False)

    def values(self) -> dict:
        """{op property: value} as the page shows them (quantities for lengths and feeds, the tool controller
        object)."""
        values = {}
        for type_id, name, _group, _tip, _default in FIELDS:
            field = self.field(name)
            if type_id in UNITS:
                values[name] = FreeCAD.Units.Quantity(field.property("value"))
                if values[name].Value == self.shown.get(name):  # untouched: the op's own value, not its rounding
                    values[name] = getattr(self.obj, name)
            elif type_id == "App::PropertyInteger":
                values[name] = field.value()
            elif type_id == "App::PropertyBool":
                values[name] = field.isChecked()
            else:
                values[name] = field.currentData()
        tc_name = self.field(TOOL_CONTROLLER).currentData()
        values[TOOL_CONTROLLER] = self.obj.Document.getObject(tc_name) if tc_name else self.obj.ToolController
        values[COOLANT] = self.field(COOLANT).currentData() or str(self.obj.CoolantMode)
        return values

    def getFields(self, obj):
        for name, value in self.values().items():
            now = getattr(obj, name)
            same = abs(now.Value - value.Value) <= 1e-12 if hasattr(value, "Value") else now == value
            if not same:
                setattr(obj, name, value)

    def registerSignalHandlers(self, obj):
        for _type, name, _group, _tip, _default in FIELDS + (("", TOOL_CONTROLLER, "", "", ""),
                                                             ("", COOLANT, "", "", "")):
            field = self.field(name)
            if isinstance(field, QtGui.QCheckBox):
                field.toggled.connect(lambda *_a: self.changed())
            else:
                connect_changed(field, self.changed)
        child(self.form, NEW_WHEEL_BUTTON).clicked.connect(lambda *_a: self.new_wheel_tool_controller())

    def changed(self) -> None:
        self.setDirty()
        self.schedule_preview()

    def new_wheel_tool_controller(self) -> object:
        """A new tool controller in the op's Job whose bit is a grinding wheel of the Wheel width and Wheel
        diameter fields (each asked for while 0), turning at the speed asked for (no default: a wheel must
        never turn faster than it is rated for), selected for the op (written on OK). Its feeds are the tool
        controller's defaults (0): the op's PlungeFeed and ReciprocationFeed on this page give them. Returns
        it, or None."""
        from ....freecad.wheel_toolbit import make_wheel_tool_controller

        sizes = {}
        for prop, text in (("WheelWidth", "Width of the grinding wheel (mm):"),
                           ("WheelDiameter", "Diameter of the grinding wheel (mm):"),
                           ("SpindleSpeed", "Speed of the grinding wheel (rpm; at most its rated speed):")):
            value = self.values()[prop].Value if prop != "SpindleSpeed" else 0.0
            if not value > 0:
                value, ok = QtGui.QInputDialog.getDouble(self.form, translate(CONTEXT, "Grinding wheel tool "
                                                                              "controller"),
                                                         translate(CONTEXT, text), 0.0, 0.0, 100000.0, 3)
                if not (ok and value > 0):
                    return None
            sizes[prop] = value
        try:
            tc = make_wheel_tool_controller(PathUtils.findParentJob(self.obj), sizes["WheelWidth"],
                                            sizes["WheelDiameter"])
            tc.SpindleSpeed, tc.SpindleDir = sizes["SpindleSpeed"], "Forward"
        except Exception as error:  # a message, not a traceback
            FreeCAD.Console.PrintError(translate(CONTEXT, "Cannot create the grinding wheel tool controller: {0}")
                                       .format(error) + "\n")
            return None
        self._fill_tool_controllers(tc)
        self.changed()
        return tc

    def updateData(self, obj, prop):
        if prop in ("Base", TOOL_CONTROLLER):
            self.schedule_preview()

    # -- validity -----------------------------------------------------------------
    def replan(self) -> object:
        """The op's plan from the page's values (live_page.LivePage)."""
        return self.obj.Proxy.plan(WithValues(self.obj, self.values()))

    def show_plan(self, plan: object) -> None:
        """The G83 block ``plan`` programs and its strokes in the 3D view (none while invalid), and its
        warnings; the field each names ("WheelDiameter: ...") framed amber."""
        self.plan = plan
        child(self.form, GRIND_CALL_LABEL).setText(plan.call.emit() if plan is not None else "")
        if self.preview is None:
            gui_document = FreeCADGui.ActiveDocument
            self.preview = GrindPreview(gui_document.ActiveView if gui_document is not None else None)
        self.preview.show(plan)
        lines = plan.warnings if plan is not None else []
        named = [name for _type, name, _group, _tip, _default in FIELDS
                 if any(line.startswith(name + ":") for line in lines)]
        self.show_warning_lines(lines, tuple(named))
