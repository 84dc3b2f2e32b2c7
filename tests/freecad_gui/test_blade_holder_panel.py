"""The Groove task panel refuses a face groove outside the face-grooving blade's first-cut diameter range
(issue 20, item 5): the tool bit's FirstCutDiameterMin. FreeCAD 1.1 and 1.0, under Xvfb; the Job's tool bit is
made a blade 3 mm wide with a range from 31 mm, as test_groove_reach_panel.py makes its blade.
"""

import FreeCADGui
import pytest
from gui_helpers import (
    close_shop,
    make_blade_shop,
    process,
    replan,
    roomy_task_panel,
    shown_message,
    start_groove_command,
    task_button,
    wait_for,
)
from PySide import QtGui

Ok = QtGui.QDialogButtonBox.Ok


@pytest.fixture
def shop():
    doc, job, model = make_blade_shop("BladeHolderGui", Width=3.0, CornerRadius=0.2, CuttingEdgeHeight=8.0,
                                      FirstCutDiameterMin=31.0)
    yield doc, job, model
    close_shop(doc)


def test_a_face_groove_below_the_first_cut_range_is_shown_and_ok_is_refused(shop):
    """The shoulder (R14..20): a groove 4 wide at Position 1 plunges first over diameters 32..38 (allowed); at
    Position 2 over 30..36, below 31."""
    doc, job, model = shop
    panel = start_groove_command(doc, model, "shoulder")
    roomy_task_panel()
    page = panel.groove_page
    for name, text in (("Width", "4 mm"), ("Depth", "3 mm"), ("Position", "1 mm")):
        replan(page, page.field(name), text)
    assert page.error is None, page.error
    replan(page, page.field("Position"), "2 mm")
    assert page.error is not None and page.error.startswith(
        "FirstCutDiameterMin=31 mm: the face groove's first plunge cuts diameters 30..36 mm, below"), page.error
    assert shown_message(page.form) == page.error
    assert page.field("Position").property("grooveInvalid") is True
    assert not task_button(panel, Ok).isEnabled()
    assert panel.accept() is False  # and if OK were reached anyway
    process(0.1)
    assert FreeCADGui.Control.activeDialog()
    replan(page, page.field("Position"), "1 mm")
    assert page.error is None and task_button(panel, Ok).isEnabled()
    task_button(panel, Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
