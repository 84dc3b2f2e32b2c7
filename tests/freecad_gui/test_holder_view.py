"""Check turning draws the blade's holder where it enters the part (issue 20, item 5), in FreeCAD's GUI (1.1 and
1.0, under Xvfb): a grooving blade reaching 4 mm with a 20 mm holder (HolderWidth), a groove 2 deep on the R14
cylinder beside the R20 step (tests/freecad/test_blade_holder.py works the figures out): the panel lists the moves
whose holder enters the step, the view draws what it enters and the holder's outline; with HolderWidth 0 (not
given) nothing of the holder is drawn.
"""

import FreeCADGui
import pytest
from gui_helpers import (
    close_shop,
    make_gui_shop,
    process,
    roomy_task_panel,
    screenshot,
    version,
    wait_for,
    zoom_to,
)
from parts import face_name

from freecad_groove import make_groove
from freecad_groove.freecad import toolbit
from freecad_groove.ops.turning_check.check import STOCK_TURNED
from freecad_groove.ops.turning_check.gui import panel as turning_panel
from freecad_groove.ops.turning_check.gui.command import CommandCheckTurning

SMALL = {"small": lambda f: f.surface == "cylinder" and f.external and abs(f.r_max - 14) < 1e-9}


@pytest.fixture
def shop():
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc, job, model = make_gui_shop("HolderGui")
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2, CuttingEdgeHeight=4, HolderWidth=20)
    op = make_groove(job, (model, face_name(model.Shape, "small", SMALL)), tool_controller=tc, position=15,
                     width=4, depth=2, infeed=1)
    doc.recompute()
    yield doc, job, op, tc
    close_shop(doc)


def test_check_turning_draws_the_holder_entering_the_step(shop):
    doc, job, op, tc = shop
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.runCommand(CommandCheckTurning.NAME)
    panel = wait_for(lambda: turning_panel._open_panel, what="the Turning check panel")
    roomy_task_panel()
    panel.stock.setCurrentIndex(panel.stock.findData(STOCK_TURNED))
    process()
    text = panel.figures.toPlainText()
    assert "%s: PROBLEMS" % op.Label in text and "HOLDER IN STOCK: G0 (Path command" in text, text
    assert panel.drawing.drawn["holder"] and panel.drawing.drawn["holder outline"]
    assert not panel.drawing.drawn["gouge"]
    job.Stock.ViewObject.Visibility = False
    zoom_to(doc, 16.0, 32.0, 36.0)
    screenshot("%s-turning-check-holder" % version())
    tc.Tool.HolderWidth = 0
    doc.recompute()
    panel.again.click()
    process()
    assert "%s: ok" % op.Label in panel.figures.toPlainText(), panel.figures.toPlainText()
    assert not panel.drawing.drawn["holder"] and not panel.drawing.drawn["holder outline"]
    panel.reject()
    process()
