"""A new user's first hour, end to end in FreeCAD's GUI (1.1 and 1.0, under Xvfb).

A Job made with CAM's defaults (its default tool controller: feed 0, speed
0), a face picked, the Groove command, OK, then CAM's own Post Process
command (CAM_Post, not our export function) with each lathe post: every post
writes its file, and nothing in the Report view at any step is a traceback.
The LinuxCNC program goes to $FREECAD_GROOVE_SHARE/posted/ where
tests/test_freecad.py runs LinuxCNC's rs274 on it (rs274 is on the host).
A failing post through the same command writes no file and reports one line.
"""

import os

import FreeCAD
import FreeCADGui
import pytest
from gui_helpers import (
    close_shop,
    make_gui_shop,
    no_traceback,
    open_panel,
    process,
    report_view,
    start_groove_command,
    task_button,
    wait_for,
)
from gui_helpers import post_with_cam_post as cam_post
from PySide import QtGui

from freecad_groove.ops.groove.gui import tool_page as tool_page_module
from freecad_groove.ops.groove.gui.tool_page import ToolPage
from freecad_groove.ops.groove.op import op_error

NAMES = ["sinumerik", "ab9", "fanuc", "haas", "linuxcnc"]
SUFFIX = {"sinumerik": "mpf", "ab9": "nc", "fanuc": "nc", "haas": "nc", "linuxcnc": "ngc"}
BLADE_WIDTH = 3.0  # typed into the width dialog the one-click tool controller asks
POSTED = os.path.join(os.environ.get("FREECAD_GROOVE_SHARE") or os.getcwd(), "posted")


@pytest.fixture(scope="module", autouse=True)
def cam_workbench():
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    process(0.2)


@pytest.fixture
def new_job():
    """(doc, job, model): a Job as CAM's GUI makes it, its default tool controller untouched."""
    doc, job, model = make_gui_shop("NewUser", feed=None)
    report_view().clear()
    yield doc, job, model
    close_shop(doc)


def test_a_new_job_grooves_and_posts_with_cams_post_command(new_job, monkeypatch):
    doc, job, model = new_job
    tc = job.Tools.Group[0]
    assert tc.HorizFeed.Value == 0 and tc.SpindleSpeed == 0  # what a new Job gives
    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/CAM").SetString("PostProcessorOutputPolicy", "")
    panel = start_groove_command(doc, model, "cylinder")
    no_traceback("the Groove command")
    op = panel.obj
    # The default tool is an end mill: no blade width, so OK waits for one (none is made up).
    def ok_shown():
        button = panel.buttonBox.button(QtGui.QDialogButtonBox.Ok)
        return button is not None and button.isVisible()

    wait_for(ok_shown, what="the panel's OK button")
    ok = task_button(panel, QtGui.QDialogButtonBox.Ok)
    assert not ok.isEnabled()
    tool_page = next(p for p in panel.featurePages if isinstance(p, ToolPage))
    monkeypatch.setattr(tool_page_module, "ask_blade_width", lambda parent: BLADE_WIDTH)  # the modal dialog
    tool_page.form.newGroovingTool.click()  # the one click the panel offers
    wait_for(ok.isEnabled, what="OK enabled by the grooving tool controller")
    assert op.ToolController.Tool.Width.Value == BLADE_WIDTH
    no_traceback("Create grooving tool controller")
    ok.click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    assert open_panel(doc) is None and op_error(op) is None, op_error(op)
    assert "0.05 mm/rev" in op.FeedsAndSpeeds and "500 rpm" in op.FeedsAndSpeeds
    no_traceback("OK")
    os.makedirs(POSTED, exist_ok=True)
    for name in NAMES:
        path = os.path.join(POSTED, "new_job_%s.%s" % (name, SUFFIX[name]))
        if os.path.exists(path):
            os.remove(path)
        cam_post(doc, job, name + "_lathe", path)
        no_traceback("CAM_Post with %s_lathe" % name)
        assert os.path.exists(path), "%s_lathe: CAM_Post wrote no %s\n%s" % (name, path, report_view().toPlainText())
        text = open(path).read()
        assert "G97 S500" in text and "F0.05" in text, text
    # a post that fails (a bad option) writes nothing and says so in one line, without a traceback
    path = os.path.join(POSTED, "refused.nc")
    report_view().clear()
    cam_post(doc, job, "fanuc_lathe", path, "--bogus")
    text = no_traceback("CAM_Post with a bad option")
    assert not os.path.exists(path)
    assert "fanuc_lathe_post: unrecognized arguments: --bogus (no file written)" in text, text
    # --help: the options in the Report view, no file
    report_view().clear()
    cam_post(doc, job, "fanuc_lathe", path, "--help")
    text = no_traceback("CAM_Post with --help")
    assert not os.path.exists(path) and "--inches" in text, text
