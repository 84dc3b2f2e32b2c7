"""A new user's first hour with each op, in FreeCAD's GUI (1.1 and 1.0, under Xvfb; issue 21).

For the Groove, the Cylinder slot and the Plunge grind: a new Job with CAM's
defaults (its default tool controller: an end mill, feed 0, speed 0) -> the
op's button in CAM's "New Operations" toolbar -> only what the panel offers
-> OK -> CAM's Post Process command with each of the op's posts (each writes
its file) -> then a second new Job, whose panel opens and closes with OK.
Nowhere a traceback in the Report view, nor CAM's Job error (its Job panel
failed on every OK with KeyError 'Allowance' once a Cylinder slot had
registered its SetupSheet properties without them in its prototype). The
LinuxCNC programs go to $FREECAD_GROOVE_SHARE/posted/, where
tests/test_freecad.py runs LinuxCNC's rs274 on them; each op's panel, ready
for OK, is saved at the dock's default width (<version>-first-hour-<op>.png:
the README's pictures, through scripts/screenshots).
"""

import os

import FreeCAD
import FreeCADGui
import Part
import pytest
from gui_helpers import (
    buttons_shown,
    close_shop,
    no_traceback,
    post_with_cam_post,
    process,
    report_view,
    screenshot_dock,
    task_button,
    toolbar_action,
    type_into,
    version,
    wait_for,
)
from parts import face_name
from PySide import QtGui

from freecad_groove.ops.grind.gui import panel as grind_panel
from freecad_groove.ops.groove.gui import tool_page

POSTED = os.path.join(os.environ.get("FREECAD_GROOVE_SHARE") or os.getcwd(), "posted")
SUFFIX = {"sinumerik_lathe": "mpf", "linuxcnc_lathe": "ngc", "linuxcnc_grind": "ngc"}
# the machine's live tool and C axis codes, which no post can know (posts/live_tool.py); M64/M65: LinuxCNC's
SLOT_SWITCHES = {"gsk_lathe": "--c-axis-on M14 --c-axis-off M15 --live-tool-cw M13 --live-tool-stop M25",
                 "linuxcnc_lathe": "--c-axis-on 'M64 P0' --c-axis-off 'M65 P0' --live-tool-cw 'M64 P1' "
                                   "--live-tool-stop 'M65 P1'"}
Ok = QtGui.QDialogButtonBox.Ok


@pytest.fixture(scope="module", autouse=True)
def cam_workbench():
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    process(0.2)


def no_job_error(step):
    text = no_traceback(step)
    assert "Job.ERROR" not in text and "KeyError" not in text, "%s:\n%s" % (step, text)


def new_job(name, shapes):
    """(doc, job): the ``shapes`` {name: shape} in a new document and a Job of them as CAM's GUI makes it (with
    its default stock and tool controller, untouched); the Report view cleared."""
    import Path.Main.Gui.Job as PathJobGui

    doc = FreeCAD.newDocument(name)
    parts = []
    for part_name, shape in shapes.items():
        parts.append(doc.addObject("Part::Feature", part_name))
        parts[-1].Shape = shape
    doc.recompute()
    job = PathJobGui.Create(parts, openTaskPanel=False)
    doc.recompute()
    tc = job.Tools.Group[0]
    assert tc.HorizFeed.Value == 0 and tc.SpindleSpeed == 0  # what a new Job gives
    report_view().clear()
    return doc, job


def the_open_panel(doc):
    """The task panel of the add-on's op in ``doc`` once it is open and has checked its values."""
    def panel():
        for obj in doc.Objects:
            vp = getattr(getattr(obj, "ViewObject", None), "Proxy", None)
            if getattr(vp, "panel", None) is not None and FreeCADGui.Control.activeDialog():
                return vp.panel
        return None

    found = wait_for(panel, what="the op's task panel")
    wait_for(lambda: buttons_shown(found), what="the panel's buttons")
    page = found.groove_page
    wait_for(lambda: page.replans > 0 and not page._timer.isActive(), what="the panel's values checked")
    return found


def press_ok(panel):
    page = panel.groove_page
    wait_for(lambda: not page._timer.isActive(), what="the values checked")
    ok = task_button(panel, Ok)
    assert ok.isEnabled(), page.error
    ok.click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)


def post_each(doc, job, posts, what, args=None):
    os.makedirs(POSTED, exist_ok=True)
    texts = {}
    for post in posts:
        path = os.path.join(POSTED, "first_hour_%s_%s.%s" % (what, post, SUFFIX.get(post, "nc")))
        if os.path.exists(path):
            os.remove(path)
        post_with_cam_post(doc, job, post, path, (args or {}).get(post, ""))
        no_job_error("CAM_Post with %s" % post)
        assert os.path.exists(path), "%s: CAM_Post wrote no %s\n%s" % (post, path, report_view().toPlainText())
        texts[post] = open(path).read()
    return texts


def second_job(doc, job):
    """A second new Job through CAM's GUI, its panel open, closed with OK."""
    import Path.Main.Gui.Job as PathJobGui

    report_view().clear()
    model = doc.getObject("Shaft")
    other = PathJobGui.Create([model], openTaskPanel=True)
    wait_for(FreeCADGui.Control.activeDialog, what="the new Job's panel")
    no_job_error("the second Job's panel")
    box = wait_for(lambda: next((b for b in FreeCADGui.getMainWindow().findChildren(QtGui.QDialogButtonBox)
                                 if b.isVisible() and b.button(Ok) is not None), None), what="the Job panel's OK")
    box.button(Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the Job panel to close")
    process(0.1)
    no_job_error("the second Job's OK")
    assert other.Name in [o.Name for o in doc.Objects]


def ops_of(job, kind):
    return [o for o in job.Operations.Group if type(getattr(o, "Proxy", None)).__name__ == kind]


def test_the_groove_from_a_new_job_to_every_lathe_post(monkeypatch):
    from parts import shaft_shape

    doc, job = new_job("FirstGroove", {"Shaft": shaft_shape()})
    try:
        model = job.Model.Group[0]
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(doc.Name, model.Name, face_name(model.Shape, "cylinder"))
        toolbar_action("New Operations", "Turning Groove").trigger()
        panel = the_open_panel(doc)
        no_job_error("the Turning Groove button")
        assert not task_button(panel, Ok).isEnabled()  # an end mill has no blade width: none is made up
        monkeypatch.setattr(tool_page, "ask_blade_width", lambda parent: 3.0)  # the width dialog, typed 3
        page = next(p for p in panel.featurePages if isinstance(p, tool_page.ToolPage))
        page.form.newGroovingTool.click()  # the one click the panel offers
        wait_for(lambda: panel.groove_page.error is None, what="a valid groove with the grooving tool")
        screenshot_dock("%s-first-hour-groove" % version())  # the README's: what a new user sees
        press_ok(panel)
        (op,) = ops_of(job, "ObjectGroove")
        no_job_error("OK")
        assert not op.ToolController.Tool.ViewObject.Visibility  # hidden as CAM hides its end mill
        assert "0.05 mm/rev" in op.FeedsAndSpeeds
        posts = ["sinumerik_lathe", "ab9_lathe", "fanuc_lathe", "haas_lathe", "gsk_lathe", "linuxcnc_lathe"]
        post_each(doc, job, posts, "groove")
        second_job(doc, job)
    finally:
        close_shop(doc)


def test_the_cylinder_slot_from_a_new_job_to_the_posts_with_a_c_axis():
    helix = Part.makeHelix(20.0, 20.0, 20.0)
    helix.translate(FreeCAD.Vector(0, 0, 10))
    doc, job = new_job("FirstSlot", {"Shaft": Part.makeCylinder(20, 50), "SlotLine": helix})
    try:
        shaft, line = job.Model.Group
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(shaft, "Face1")
        FreeCADGui.Selection.addSelection(line, "Edge1")
        toolbar_action("New Operations", "Cylinder slot").trigger()
        panel = the_open_panel(doc)
        no_job_error("the Cylinder slot button")
        page = panel.groove_page
        assert page.error is None, page.error  # a new Job's tool controller: the documented defaults
        feeds = page.form.findChild(QtGui.QLabel, "feedsAndSpeeds").text()
        assert feeds.startswith("feed 50 mm/min (default") and "live tool 1000 rpm" in feeds, feeds
        screenshot_dock("%s-first-hour-slot" % version())
        press_ok(panel)
        (op,) = ops_of(job, "ObjectCylinderSlot")
        no_job_error("OK")
        assert not op.ToolController.Tool.ViewObject.Visibility  # CAM's own end mill, hidden by CAM
        assert op.FeedsAndSpeeds == feeds
        texts = post_each(doc, job, ["gsk_lathe", "linuxcnc_lathe"], "slot", SLOT_SWITCHES)
        assert "M13 S1000" in texts["gsk_lathe"].splitlines() and "M64 P1 S1000" in texts["linuxcnc_lathe"]
        for text in texts.values():  # the main spindle never started
            assert not [line for line in text.splitlines() if line.startswith(("G97", "M03", "M3 ", "M05", "M5"))]
        second_job(doc, job)
    finally:
        close_shop(doc)


def test_the_plunge_grind_from_a_new_job_to_the_grinder_posts(monkeypatch):
    doc, job = new_job("FirstGrind", {"Shaft": Part.makeBox(100, 40, 20)})
    try:
        block = job.Model.Group[0]
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(doc.Name, block.Name, "Face6")  # the top face
        toolbar_action("New Operations", "Plunge grind").trigger()
        panel = the_open_panel(doc)
        no_job_error("the Plunge grind button")
        page = panel.groove_page
        assert page.error.startswith("WheelWidth:") and not task_button(panel, Ok).isEnabled()
        typed = iter([10.0, 200.0, 1800.0])  # the width, diameter and speed dialogs
        monkeypatch.setattr(QtGui.QInputDialog, "getDouble", lambda *args: (next(typed), True))
        page.form.findChild(QtGui.QPushButton, grind_panel.NEW_WHEEL_BUTTON).click()
        wait_for(lambda: page.error is not None and page.error.startswith("PlungeFeed=0"), what="the feeds asked")
        type_into(page.field("PlungeFeed"), "1")  # mm/s: FreeCAD's default unit schema
        type_into(page.field("ReciprocationFeed"), "100")
        wait_for(lambda: page.error is None and not page._timer.isActive(), what="a valid grind")
        screenshot_dock("%s-first-hour-grind" % version())
        press_ok(panel)
        (op,) = ops_of(job, "ObjectPlungeGrind")
        no_job_error("OK")
        assert not op.ToolController.Tool.ViewObject.Visibility  # no 200 mm disc over the part
        texts = post_each(doc, job, ["ab9_grind", "linuxcnc_grind"], "grind")
        assert "S1800 M03" in texts["ab9_grind"] and "S1800 M3" in texts["linuxcnc_grind"], texts
        second_job(doc, job)
    finally:
        close_shop(doc)
