"""The Groove task panel's "Tool and coolant" page: the tool controller (with
FreeCAD 1.1's editor), the coolant mode, the blade's width, corner radius and
reference corner used when the tool bit has none, and a button that makes a
grooving tool controller for the Job in one click.

Not stored in documents (panel.GrooveTaskPanel builds it): free to move.
"""

import FreeCAD
import Path.Op.Gui.Base as PathOpGui
from PySide import QtGui

from ....freecad import toolbit
from ....gui.widgets import (
    CONTEXT,
    QuantityFields,
    add_error_label,
    connect_changed,
    fill_combo,
    load_form,
    select_data,
)

translate = FreeCAD.Qt.translate

TOOL_QUANTITIES = (("toolWidth", "ToolWidth"), ("toolCornerRadius", "ToolCornerRadius"))

# Enumeration texts as shown (translated); the op stores the untranslated value.
REFERENCE_CORNER_TEXT = {
    "minus": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "minus"),
    "plus": FreeCAD.Qt.QT_TRANSLATE_NOOP(CONTEXT, "plus"),
}


class ToolPage(PathOpGui.TaskPanelPage):
    """Tool controller, coolant, and the blade's size when the tool bit has none."""

    def getForm(self):
        form = load_form("PageGrooveToolEdit.ui")
        fill_combo(form.referenceCorner, REFERENCE_CORNER_TEXT)
        add_error_label(form)
        return form

    def initPage(self, obj):
        self.fields = QuantityFields(self.form, TOOL_QUANTITIES)
        self.groove_page = None  # set by GrooveTaskPanel

    def getTitle(self, obj):
        return translate(CONTEXT, "Tool and coolant")

    def getIcon(self, obj):
        return None

    def setFields(self, obj):
        self.setupToolController(obj, self.form.toolController)
        self.setupCoolant(obj, self.form.coolantController)
        self.fields.set_from(obj)
        select_data(self.form.referenceCorner, str(obj.ReferenceCorner))
        self.show_tool_source(obj)

    def getFields(self, obj):
        self.updateToolController(obj, self.form.toolController)
        self.updateCoolant(obj, self.form.coolantController)
        self.fields.write_to(obj)
        value = self.form.referenceCorner.currentData()
        if value and obj.ReferenceCorner != value:
            obj.ReferenceCorner = value

    def values(self) -> dict:
        """{op property: value} as this page shows them."""
        values = self.fields.values()
        values["ReferenceCorner"] = self.form.referenceCorner.currentData()
        return values

    def registerSignalHandlers(self, obj):
        for widget in list(self.fields.widgets.values()) + [self.form.referenceCorner, self.form.coolantController]:
            connect_changed(widget, self.changed)
        if not hasattr(self, "tcEditor"):  # FreeCAD 1.0: the base class does not follow the combo
            self.form.toolController.currentIndexChanged.connect(self._tool_controller_changed)
        self.form.newGroovingTool.clicked.connect(lambda *_a: self.new_grooving_tool_controller())

    def new_grooving_tool_controller(self) -> object:
        """A new tool controller in the op's Job whose bit is a grooving blade
        of the Blade width and Corner radius fields (the width asked for while
        it is 0, unknown), selected for the op. Returns it, or None."""
        values = self.fields.values()
        width, radius = values["ToolWidth"], values["ToolCornerRadius"]
        if not width > 0:
            width = ask_blade_width(self.form)
            if width is None:
                return None
        import PathScripts.PathUtils as PathUtils

        try:
            tc = toolbit.make_grooving_tool_controller(PathUtils.findParentJob(self.obj), width, radius)
        except Exception as error:  # a message, not a traceback
            FreeCAD.Console.PrintError(
                translate(CONTEXT, "Cannot create the grooving tool controller: {0}").format(error) + "\n")
            return None
        self.obj.ToolController = tc
        self.setupToolController(self.obj, self.form.toolController)
        self.show_tool_source(self.obj)
        self.changed()
        return tc

    def _tool_controller_changed(self, *_args):
        self.updateToolController(self.obj, self.form.toolController)
        self.changed()

    def changed(self) -> None:
        """A value changed: the panel is dirty, the preview follows."""
        self.setDirty()
        if self.groove_page is not None:
            self.groove_page.schedule_preview()

    def show_tool_source(self, obj: object) -> None:
        """Say where the blade's size comes from; the op's own size fields are
        enabled only for what the tool bit does not give."""
        tool_controller = getattr(obj, "ToolController", None)
        bit = getattr(tool_controller, "Tool", None)
        given = [name for name in ("Width", "CornerRadius")
                 if bit is not None and getattr(bit, name, None) is not None]
        if given:
            text = translate(
                CONTEXT, "The tool bit {0} gives the blade's {1}: the fields below are not used for it."
            ).format(bit.Label, " and ".join(given))
        else:
            text = translate(CONTEXT, "The tool bit has no Width or CornerRadius: the blade size below is used.")
        self.form.toolSourceLabel.setText(text)
        self.form.toolWidth.setEnabled("Width" not in given)
        self.form.toolCornerRadius.setEnabled("CornerRadius" not in given)

    def updateData(self, obj, prop):
        if prop == "ToolController":
            self.show_tool_source(obj)
            if self.groove_page is not None:
                self.groove_page.schedule_preview()


def ask_blade_width(parent: object) -> object:
    """The blade width (mm) the user types into a dialog, or None (cancelled)."""
    width, ok = QtGui.QInputDialog.getDouble(
        parent, translate(CONTEXT, "Grooving tool controller"),
        translate(CONTEXT, "Width of the grooving blade (mm):"), 0.0, 0.0, 1000.0, 3)
    return width if ok and width > 0 else None
