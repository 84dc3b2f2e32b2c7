"""The Cylinder slot op in FreeCAD's GUI (1.1 and 1.0, under Xvfb): the
command from a selected face and edge, and the op's moves drawn wrapped on
the cylinder (FreeCAD's Path view draws X/Z/C flat). A screenshot.
"""

import math

import FreeCAD
import FreeCADGui
import pytest
from gui_helpers import buttons_shown, make_slot_shop, process, screenshot, task_button, version, wait_for
from PySide import QtGui

from freecad_groove.ops.slot.gui import command as slot_command
from freecad_groove.ops.slot.gui import view as slot_view

V = FreeCAD.Vector


@pytest.fixture
def shop():
    doc, job = make_slot_shop("slotgui")
    yield doc, job
    FreeCADGui.Selection.clearSelection()
    FreeCAD.closeDocument(doc.Name)
    process(0.1)


def test_command_makes_the_op_and_draws_it_wrapped(shop):
    doc, job = shop
    shaft, line = job.Model.Group
    FreeCADGui.Selection.clearSelection()
    assert not slot_command.CommandCylinderSlot().IsActive()  # nothing selected: the command is off
    FreeCADGui.Selection.addSelection(shaft, "Face1")
    FreeCADGui.Selection.addSelection(line, "Edge1")
    FreeCADGui.runCommand(slot_command.COMMAND)
    process(0.2)
    ops = [o for o in job.Operations.Group if hasattr(o, "Region")]
    assert len(ops) == 1 and ops[0].Region == "G7.1 C20. J-2. R2. K0.2 L2"  # the op's defaults
    op = ops[0]
    assert isinstance(op.ViewObject.Proxy, slot_view.ViewProviderCylinderSlot)
    panel = wait_for(lambda: op.ViewObject.Proxy.panel, what="the op's task panel")  # the command opens it
    wait_for(lambda: buttons_shown(panel), what="the panel's buttons")
    task_button(panel, QtGui.QDialogButtonBox.Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    node = op.ViewObject.Proxy.wrapped
    coords = [node.getChild(i) for i in range(node.getNumChildren()) if node.getChild(i).isOfType(
        __import__("pivy").coin.SoCoordinate3.getClassTypeId())]
    assert len(coords) == 2  # feeds and rapids
    points = [coords[0].point[i] for i in range(coords[0].point.getNum())]
    # the finish pass follows the helix one turn at radius 19 (Depth 1): 180 pieces of 2 degrees
    finish = [p for p in points if abs(math.hypot(p[0], p[1]) - 19.0) < 1e-4]
    assert len(finish) >= 181
    for p in finish:
        if p[2] > 10.0 + 1e-6:  # on the helix: z = 10 + 20 * angle / 360
            angle = math.degrees(math.atan2(p[1], p[0])) % 360.0
            assert (p[2] - 10.0) % 20.0 == pytest.approx(angle * 20.0 / 360.0, abs=1e-3) or angle < 1e-3 \
                or angle > 360 - 1e-3
    for obj in doc.Objects:  # the slot is below the surface: the part as wires only
        if obj.isDerivedFrom("Part::Feature") and getattr(obj, "ViewObject", None) is not None:
            obj.ViewObject.DisplayMode = "Wireframe"
    process(0.2)
    FreeCADGui.ActiveDocument.ActiveView.viewIsometric()
    FreeCADGui.SendMsgToActiveView("ViewFit")
    screenshot("%s-cylinder-slot" % version())
