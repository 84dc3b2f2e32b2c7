"""Check turning on a groove read from the model (FreeCAD 1.1 and 1.0, under Xvfb).

What a user does: the Job's model carries a modelled groove (model_parts.py's
"rectangular": R20, 4 wide and 2 deep at Z26..30), a Groove op made on one
of its faces with no dimensions; Check turning finds it clean; then the
op's Depth is set 1 mm deeper than the model's (an override) and Check
again shows the gouge in red, about 1 mm deep at X17 under the model's base,
naming the op. Screenshots of both checks for the README.
"""

import FreeCAD
import FreeCADGui
import pytest
from gui_helpers import (
    close_shop,
    make_gui_shop,
    process,
    roomy_task_panel,
    screenshot,
    show_part,
    version,
    wait_for,
    zoom_to,
)
from model_parts import CASES, part_shape
from pylib import require_shapely
from test_model_panel import groove_face

from freecad_groove import make_groove
from freecad_groove.ops.groove.op import op_error
from freecad_groove.ops.turning_check.gui import panel as turning_panel
from freecad_groove.ops.turning_check.gui.command import CommandCheckTurning

CALL = CASES["rectangular"]


@pytest.fixture
def shop():
    """(doc, job, op): the modelled groove in a GUI-made Job (its default stock: a bar R21, Z19..37) and
    an op made on a face of the groove with no dimensions."""
    require_shapely()
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc, job, model = make_gui_shop("ModelTurningGui", shape=part_shape(CALL))
    op = make_groove(job, (model, groove_face(model.Shape)), name="GrooveFromModel", infeed=1, tool_width=2,
                     tool_corner_radius=0.1)
    doc.recompute()
    assert op_error(op) is None and list(op.ModelOverrides) == [], op_error(op)
    show_part(doc)
    yield doc, job, op
    close_shop(doc)


def test_check_turning_passes_the_models_groove_and_shows_the_too_deep_override(shop):
    doc, job, op = shop
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.runCommand(CommandCheckTurning.NAME)
    panel = wait_for(lambda: turning_panel._open_panel, what="the Turning check panel")
    roomy_task_panel()
    text = panel.figures.toPlainText()
    assert "%s: ok" % op.Label in text and "no gouge" in text, text
    assert "bar R21.000 from Z19.000 to Z37.000" in text and "removed 11.99" in text, text
    assert panel.drawing.drawn["remaining"] and not panel.drawing.drawn["gouge"]
    job.Stock.ViewObject.Visibility = False  # the drawn section is the stock left
    zoom_to(doc, 18.5, 28.0, 9.0)
    screenshot("%s-turning-check-model-ok" % version())

    op.Depth = CALL.depg + 1  # typed over the model's value: an override
    doc.recompute()
    assert list(op.ModelOverrides) == ["Depth"] and op_error(op) is None, op_error(op)
    panel.again.click()
    process()
    text = panel.figures.toPlainText()
    assert "%s: PROBLEMS" % op.Label in text and "GOUGE" in text, text
    assert "1.0000 mm deep at X17.00" in text, text
    assert panel.drawing.drawn["gouge"] and panel.runs == 2
    screenshot("%s-turning-check-model-gouge" % version())
    panel.reject()
    process()
    assert not FreeCADGui.Control.activeDialog()
    FreeCAD.ActiveDocument.recompute()
