"""GUI layer, shared part: what the ops' GUIs (freecad_groove/ops/<op>/gui/,
the same layer) are built from, and their registration when FreeCAD's GUI
starts.

The only layer that imports FreeCADGui or Qt (always through FreeCAD's
``PySide`` shim, so it runs on PySide6 in FreeCAD 1.1 and PySide2 in 1.0).
``InitGui.py`` calls ``register()`` when FreeCAD's GUI starts; the CAM
modules are imported only when a command is first used.

    commands.py     the commands' place in CAM's toolbar and menu, the Job a new op goes into, and
                    register_op(kind): an op's command and view provider (ops/registry.py)
    op_view.py      OpViewProvider: FreeCAD's op view provider with the add-on's icon, selection gate and
                    dialog (the Groove's and the Plunge grind's derive from it); a new op with its panel open
    task_dialog.py  AddonTaskPanel, the dialog of every op panel: OK refused while invalid, the modified flag
    live_page.py    an op page that re-plans as the user types: the error, warnings, framed fields
    field_rows.py   the op's message also in the row of the field being edited
    geometry_page.py  FreeCAD's base geometry page, faces only, with the op's message
    widgets.py      the Qt helpers the pages are built from (forms, fields, error labels)
    qt_wrappers.py  forgetting PySide's wrappers of the widgets FreeCAD deletes with a closed panel
    lines.py        Coin line sets drawn in the 3D view (the previews', the turning check's)
    task_panel.py, grind_view.py, grind_panel.py, slot_view.py
                    shims: class paths documents saved before the ops moved to ops/ store
"""

import os

RESOURCES = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "resources")
ICONS = os.path.join(RESOURCES, "icons")
PANELS = os.path.join(RESOURCES, "panels")
TRANSLATIONS = os.path.join(RESOURCES, "translations")


def icon_path(name: str) -> str:
    """The add-on's icon file ``name`` ("groove.svg")."""
    return os.path.join(ICONS, name)


def register():
    """Add every op's command to the CAM workbench and give ops made by scripts their view provider (one
    registration per op, ops.KINDS), then the Check turning command."""
    import FreeCADGui

    from ..ops import KINDS
    from ..ops.turning_check.gui.command import CommandCheckTurning
    from .commands import add_command, register_op
    from .tool_table_command import CommandExportToolTable

    FreeCADGui.addLanguagePath(TRANSLATIONS)
    FreeCADGui.updateLocale()
    for kind in KINDS:
        register_op(kind)
    add_command(CommandCheckTurning())
    add_command(CommandExportToolTable())
