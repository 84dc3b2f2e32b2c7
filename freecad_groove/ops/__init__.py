"""The add-on's operations, a folder each, the same shape in each:

    <op>/__init__.py   its declaration (KIND, registry.OpKind) and a map of the folder
    <op>/op.py         the op's proxy class (a class path documents store), Create(), SetupProperties()
    <op>/properties.py its properties, declared once, and the error that names the ones to fix
    <op>/plan.py       what it cuts (its plan) and the pieces that make one
    <op>/path.py       its Path from the plan
    <op>/api.py        its make_* call for scripts (freecad_groove.make_*)
    <op>/gui/          the GUI layer: command.py (the command), view.py (the view provider), panel.py
                       (the task panel), preview.py (what the panel draws while it is open)

groove/         the Groove: CYCLE93 grooves on faces of a turned part
slot/           the Cylinder slot: a slot on a cylinder as a GSK G7.1 region (live tool, C axis)
grind/          the Plunge grind: a flat face as an Allen-Bradley 9/Series G83/G83.1
turning_check/  the Check turning command: a Job's Groove ops simulated on its turned section (a
                command over the ops, not an op: check.py, gui/command.py, gui/panel.py, gui/preview.py)

Layers: everything under ops/ is the FreeCAD layer (FreeCAD, Part, Path; never Qt) but the gui/ packages,
the GUI layer, the only place here importing FreeCADGui or PySide. What several ops share stays in
freecad_groove/freecad/ (faces, units, tool bits, the op base, posts) and freecad_groove/gui/ (the dialog,
the live page, widgets, the commands' place in CAM). The declarations (this file, registry.py and each
folder's __init__.py) import nothing of FreeCAD: FreeCAD's GUI reads them when it starts.
"""

from . import grind, groove, slot
from .registry import register

# Every op, in the order of their commands in CAM's toolbar and menu (one placed after another).
KINDS = tuple(register(kind) for kind in (groove.KIND, slot.KIND, grind.KIND))
