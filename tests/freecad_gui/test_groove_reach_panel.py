"""The Groove task panel refuses a groove deeper than the blade's free reach
(issue 20, item 5): the tool bit's CuttingEdgeHeight. FreeCAD 1.1 and 1.0,
under Xvfb; the Job's tool bit is made a blade 3 mm wide reaching 8 mm, as the
demo makes its own (freecad_groove/demo.py).
"""

import FreeCADGui
import pytest
from gui_helpers import (
    close_shop,
    make_blade_shop,
    process,
    replan,
    roomy_task_panel,
    screenshot,
    shown_message,
    start_groove_command,
    task_button,
    version,
    wait_for,
)
from PySide import QtGui

Ok = QtGui.QDialogButtonBox.Ok


@pytest.fixture
def shop():
    doc, job, model = make_blade_shop("GrooveReachGui", Width=3.0, CornerRadius=0.2, CuttingEdgeHeight=8.0)
    yield doc, job, model
    close_shop(doc)


def test_a_depth_past_the_blades_reach_is_shown_and_ok_is_refused(shop):
    doc, job, model = shop
    panel = start_groove_command(doc, model, "cylinder")
    roomy_task_panel()
    page = panel.groove_page
    replan(page, page.field("Depth"), "12 mm")
    assert page.error is not None and page.error.startswith("Depth=12 mm: deeper than the blade's free reach, "
                                                            "CuttingEdgeHeight=8 mm"), page.error
    assert shown_message(page.form) == page.error
    assert page.field("Depth").property("grooveInvalid") is True
    assert not task_button(panel, Ok).isEnabled()
    screenshot("%s-depth-past-reach" % version())
    assert panel.accept() is False  # and if OK were reached anyway
    process(0.1)
    assert FreeCADGui.Control.activeDialog()
    replan(page, page.field("Depth"), "8 mm")
    assert page.error is None and task_button(panel, Ok).isEnabled()
    task_button(panel, Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
