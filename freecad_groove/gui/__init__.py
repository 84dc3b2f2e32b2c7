"""GUI layer: the Groove command, its task panel and the live preview.

The only layer that imports FreeCADGui or Qt (always through FreeCAD's
``PySide`` shim, so it runs on PySide6 in FreeCAD 1.1 and PySide2 in 1.0).
``InitGui.py`` calls ``register()`` when FreeCAD's GUI starts; the CAM
modules are imported only when the command is first used. Module and class
names in task_panel.py are stored in documents (the view provider's class,
the page class): keep them stable.

    command.py     the Turning Groove command and its place in CAM's toolbar and menu
    task_panel.py  view provider, task panel pages, OK/Cancel handling
    tool_page.py   the panel's "Tool and coolant" page (grooving tool controller button)
    widgets.py     the Qt helpers the pages are built from (forms, fields, error labels)
    qt_wrappers.py   forgetting PySide's wrappers of the widgets FreeCAD deletes with a closed panel
    preview.py     the groove cross-section and toolpath drawn while editing
    slot_view.py   the Cylinder slot command and the op's Path drawn wrapped on its cylinder
    slot_panel.py, slot_preview.py  the Cylinder slot task panel and its picture of the developed path
    turning_view.py  the Check turning command: verify_job's section in the 3D view, figures in a task panel
    grind_command.py  the Plunge grind command; grind_view.py its view provider, grind_panel.py its task panel,
                      grind_preview.py the strokes drawn while it is open
"""

import os

RESOURCES = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "resources")
ICON = os.path.join(RESOURCES, "icons", "groove.svg")
GRIND_ICON = os.path.join(RESOURCES, "icons", "plunge_grind.svg")
PANELS = os.path.join(RESOURCES, "panels")
TRANSLATIONS = os.path.join(RESOURCES, "translations")
COMMAND = "FreeCADGroove_Groove"


def _attach_view_provider(obj):
    from . import task_panel

    task_panel.attach_view_provider(obj)


def _attach_grind_view_provider(obj):
    from . import grind_view

    grind_view.attach_view_provider(obj)


def register():
    """Add the Groove command to the CAM workbench and give ops made by
    scripts their view provider."""
    import FreeCADGui

    from .. import hooks
    from . import command, grind_command, slot_view, turning_view

    FreeCADGui.addLanguagePath(TRANSLATIONS)
    FreeCADGui.updateLocale()
    command.register()
    turning_view.register()
    hooks.view_provider_factory = _attach_view_provider
    slot_view.register()
    hooks.slot_view_provider_factory = slot_view.attach_view_provider
    grind_command.register()
    hooks.grind_view_provider_factory = _attach_grind_view_provider
