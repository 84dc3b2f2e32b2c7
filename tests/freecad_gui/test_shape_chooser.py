"""The grooving blade in FreeCAD 1.1's tool library (under Xvfb).

What a user does: CAM > Tool library editor (CAM_ToolBitLibraryOpen), "Add
tool bit", the shape chooser opens; "Grooving blade" is among its entries,
drawn with its icon; a click on it makes a tool bit, which then works in a
Groove op. The dialogs are modal: the steps inside them run from a timer
once each dialog shows (never a wait inside the timer: CAM builds the
chooser, letting the event loop run, before it shows it; a wait there held it
until it timed out), and a watchdog closes whatever is still open so a
failure cannot hang the suite. FreeCAD 1.0 has no shape chooser: skipped.
"""

import traceback

import FreeCADGui
import Part
import pytest
from gui_helpers import Poll, close_shop, make_gui_shop, process, screenshot_widget, version
from parts import face_name
from PySide import QtCore, QtGui

from freecad_groove import make_groove, make_plunge_grind
from freecad_groove.freecad import shape_assets, toolbit, wheel_toolbit
from freecad_groove.freecad.addon_op import op_error

pytestmark = pytest.mark.skipif(not shape_assets.AVAILABLE, reason="FreeCAD 1.0 has no tool bit shape chooser: "
                                "the grooving blade comes from the Groove panel's tool page")
POLL_S = 60.0  # a dialog not shown by then did not open: a failure
WATCHDOG_MS = 90000


@pytest.fixture(scope="module", autouse=True)
def cam_workbench():
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    process(0.2)


def _dialog_with(child_name):
    """The visible top-level widget holding a child named ``child_name``."""
    for widget in QtGui.QApplication.topLevelWidgets():
        if widget.isVisible() and widget.findChild(QtCore.QObject, child_name) is not None:
            return widget
    return None


def _close_modal_dialogs():
    for _ in range(5):
        modal = QtGui.QApplication.activeModalWidget()
        if modal is None:
            return
        modal.close()
        process(0.1)


def _shape_buttons():
    """(the shape chooser, its ShapeButtons) once it is the modal dialog, else None."""
    from Path.Tool.shape.ui.shapebutton import ShapeButton

    chooser = QtGui.QApplication.activeModalWidget()
    buttons = [b for b in chooser.findChildren(QtGui.QToolButton) if isinstance(b, ShapeButton)] if chooser else []
    return (chooser, buttons) if buttons else None


def _failed(seen, text):
    seen.setdefault("error", text)
    _close_modal_dialogs()


def _in_the_chooser(seen, found):
    """Inside the shape chooser (``found``: it and its ShapeButtons): find the shape, note what it shows, click
    it."""
    try:
        chooser, buttons = found
        seen["entries"] = sorted(b.label_widget.text() for b in buttons)
        (button,) = [b for b in buttons if b.shape.id == seen.get("shape_id", shape_assets.SHAPE_ID)]
        seen["label"] = button.label_widget.text()
        seen["shape"] = button.shape
        seen["icon_drawn"] = not button.icon_widget.icon_widget.pixmap().isNull()
        screenshot_widget("%s-shape-chooser%s" % (version(), seen.get("shot", "")), chooser)
        button.click()
    except Exception:
        _failed(seen, traceback.format_exc())


def _in_the_editor(seen, editor):
    """Inside the tool library editor: press "Add tool bit" (the chooser's steps start once it runs), then close
    the editor."""
    try:
        seen["polls"].append(Poll(_shape_buttons, lambda found: _in_the_chooser(seen, found),
                                  lambda text: _failed(seen, text), "the shape chooser", timeout=POLL_S))
        editor.findChild(QtCore.QObject, "addToolBitButton").click()  # returns when the chooser closes
        process(0.2)
        screenshot_widget("%s-tool-library-editor" % version(), editor)
    except Exception:
        seen.setdefault("error", traceback.format_exc())
    _close_modal_dialogs()


def _local_toolbits():
    from Path.Tool.camassets import cam_assets

    return {str(u) for u in cam_assets.list_assets(asset_type="toolbit", store="local")}


def _choose_in_the_tool_library(seen):
    """CAM > Tool library editor > Add tool bit > the shape ``seen["shape_id"]`` (default the grooving blade);
    ``seen`` gets what the chooser showed. Each step starts when its dialog is shown (Poll: the editor and the
    chooser let the event loop run while they are built, before they show)."""
    seen["polls"] = [Poll(lambda: _dialog_with("addToolBitButton"), lambda editor: _in_the_editor(seen, editor),
                          lambda text: _failed(seen, text), "the tool library editor", timeout=POLL_S)]
    watchdog = QtCore.QTimer()  # stopped below: it must not close a later test's dialogs
    watchdog.setSingleShot(True)
    watchdog.timeout.connect(_close_modal_dialogs)
    watchdog.start(WATCHDOG_MS)
    try:
        FreeCADGui.runCommand("CAM_ToolBitLibraryOpen")  # modal: returns when the editor closes
        process(0.2)
    finally:
        watchdog.stop()
        for poll in seen.pop("polls"):
            poll.stop()


def test_the_shape_chooser_offers_the_grooving_blade():
    from Path.Tool.camassets import cam_assets

    before = _local_toolbits()
    seen = {}
    _choose_in_the_tool_library(seen)
    assert "error" not in seen, seen["error"]
    assert seen["label"] == "Grooving blade" and "Grooving blade" in seen["entries"], seen
    assert "Endmill" in seen["entries"]
    assert seen["icon_drawn"] and seen["shape"].get_icon().id == "grooving.svg"
    (new,) = _local_toolbits() - before
    made = cam_assets.get(new, store=["local", "builtin"])
    assert isinstance(made, toolbit.ToolBitGrooving)
    # The new bit in a Job (as the tool library's "Add to Job" does): the op reads its blade.
    import Path.Tool.Controller as PathToolController

    doc, job, model = make_gui_shop("ChooserBlade")
    try:
        bit = made.attach_to_doc(doc)
        bit.Width, bit.CornerRadius = 2, 0.25
        tc = PathToolController.Create("TC: " + made.label, bit, 9)
        tc.HorizFeed = tc.VertFeed = "100 mm/min"
        job.Proxy.addToolController(tc)
        op = make_groove(job, (model, face_name(model.Shape, "cylinder")), tool_controller=tc,
                         position=5, width=4, depth=2, infeed=1)
        doc.recompute()
        assert op_error(op) is None, op_error(op)
        (_c, settings, _st), = op.Proxy.cycles(op)
        assert (settings.tool.width, settings.tool.corner_radius) == (pytest.approx(2), pytest.approx(0.25))
        assert bit.Diameter.Value == pytest.approx(2)
    finally:
        close_shop(doc)


def test_the_shape_chooser_offers_the_grinding_wheel():
    from Path.Tool.camassets import cam_assets

    before = _local_toolbits()
    seen = {"shape_id": shape_assets.WHEEL_SHAPE_ID, "shot": "-wheel"}
    _choose_in_the_tool_library(seen)
    assert "error" not in seen, seen["error"]
    assert seen["label"] == "Grinding wheel" and "Grooving blade" in seen["entries"], seen
    assert seen["icon_drawn"] and seen["shape"].get_icon().id == "grindingwheel.svg"
    (new,) = _local_toolbits() - before
    made = cam_assets.get(new, store=["local", "builtin"])
    assert isinstance(made, wheel_toolbit.ToolBitGrindingWheel)
    import Path.Tool.Controller as PathToolController

    doc, job, model = make_gui_shop("ChooserWheel", shape=Part.makeBox(100, 40, 20))
    try:
        bit = made.attach_to_doc(doc)
        bit.Width, bit.Diameter = 8, 120
        tc = PathToolController.Create("TC: " + made.label, bit, 6)
        tc.HorizFeed = tc.VertFeed = "300 mm/min"
        job.Proxy.addToolController(tc)
        op = make_plunge_grind(job, (model, "Face6"), tool_controller=tc)
        doc.recompute()
        assert op_error(op) is None, op_error(op)
        assert op.Proxy.current_plan(op).call.Z == pytest.approx(36.0)  # flush with Y40: the 8 mm wheel's middle
        assert op.Proxy.current_plan(op).warnings == []
    finally:
        close_shop(doc)
