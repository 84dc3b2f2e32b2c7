"""The Plunge grind command and task panel (FreeCAD 1.1 and 1.0, under Xvfb):
a flat face picked -> the command opens the panel on a new op; a changed
value -> OK -> the op recomputed with it; an invalid value refuses OK with
the op's message; Cancel of a new op leaves no op. A screenshot.
"""

import FreeCAD
import FreeCADGui
import Part
import pytest
from gui_helpers import (
    close_shop,
    make_gui_shop,
    process,
    roomy_task_panel,
    screenshot,
    shown_message,
    task_button,
    type_into,
    version,
    wait_for,
)
from PySide import QtGui

from freecad_groove.gui import qt_wrappers
from freecad_groove.gui.widgets import INVALID_PROPERTY, WARNED_PROPERTY, WARNING_LABEL
from freecad_groove.ops.grind.gui import command as grind_command
from freecad_groove.ops.grind.gui import panel as grind_panel
from freecad_groove.ops.grind.gui import view as grind_view
from freecad_groove.ops.grind.op import ObjectPlungeGrind, op_error

TOP = "Face6"  # Part.makeBox: the top face (Z20)


@pytest.fixture
def shop():
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc, job, block = make_gui_shop("GrindGui", feed="300 mm/min", shape=Part.makeBox(100, 40, 20))
    yield doc, job, block
    FreeCADGui.Selection.clearSelection()
    close_shop(doc)


def grind_ops(job):
    return [o for o in job.Operations.Group if isinstance(getattr(o, "Proxy", None), ObjectPlungeGrind)]


def open_grind_panel(doc):
    if not FreeCADGui.Control.activeDialog():
        return None
    for obj in doc.Objects:
        vp = getattr(getattr(obj, "ViewObject", None), "Proxy", None)
        if isinstance(vp, grind_view.ViewProviderPlungeGrind) and vp.panel is not None:
            return vp.panel
    return None


def start_command(doc, block):
    """Select the block's top face, press Plunge grind; the panel once it checked its values."""
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(doc.Name, block.Name, TOP)
    process()
    assert grind_command.CommandPlungeGrind().IsActive()
    FreeCADGui.runCommand(grind_command.COMMAND)
    panel = wait_for(lambda: open_grind_panel(doc), what="the Plunge grind task panel")
    wait_for(lambda: panel.groove_page.replans > 0, what="the first check of the values")
    wait_for(lambda: panel.buttonBox.button(QtGui.QDialogButtonBox.Cancel).isVisible(), what="the buttons")
    return panel


def settle(page):
    """Let the page re-check the values typed (its timer fired: it may have done so while they were typed)."""
    process(0.05)
    wait_for(lambda: not page._timer.isActive(), what="the values checked")


def test_the_command_opens_the_panel_and_ok_recomputes_the_op_with_the_changed_value(shop):
    doc, job, block = shop
    panel = start_command(doc, block)
    page = panel.groove_page
    assert isinstance(panel, qt_wrappers.ForgetsButtonBox)
    assert isinstance(page, grind_panel.PlungeGrindPage)
    (op,) = grind_ops(job)
    assert [(b.Name, list(s)) for b, s in op.Base] == [(job.Model.Group[0].Name, [TOP])]  # the picked face
    # The Job's default tool bit is no wheel: its width is unknown until WheelWidth is set.
    assert page.error is not None and page.error.startswith("WheelWidth:")
    assert not task_button(panel, QtGui.QDialogButtonBox.Ok).isEnabled()
    type_into(page.field("WheelWidth"), "10")
    type_into(page.field("Overtravel"), "3")
    settle(page)
    assert page.error is None, page.error
    # The end mill has no wheel diameter: the wheel's body goes unchecked, said in amber.
    warning = page.form.findChild(QtGui.QLabel, WARNING_LABEL)
    warned = warning.isVisible() and warning.text().startswith("Warning: WheelDiameter: the wheel's diameter is "
                                                               "unknown")
    assert warned and page.field("WheelDiameter").property(WARNED_PROPERTY) is True
    assert page.plan.call.X == pytest.approx(103.0) and page.plan.call.I == pytest.approx(-3.0)
    assert child_text(page, "grindCall").startswith("G83 X103. I-3. Y20.")
    assert op.Overtravel.Value == pytest.approx(5.0)  # the document is not touched before OK
    # The strokes of the panel's values in the 3D view: between the reversal points, never below the face.
    preview = page.preview
    xs, zs = [p[0] for p in preview.feeds], [p[2] for p in preview.feeds]
    assert (min(xs), max(xs)) == (pytest.approx(-3.0), pytest.approx(103.0)) and min(zs) == pytest.approx(20.0)
    graph = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    assert graph.findChild(preview.root) >= 0
    FreeCADGui.ActiveDocument.ActiveView.viewIsometric()
    FreeCADGui.SendMsgToActiveView("ViewFit")
    show_top_of(page)
    screenshot("%s-plunge-grind-panel" % version())
    task_button(panel, QtGui.QDialogButtonBox.Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    assert (op.Overtravel.Value, op.WheelWidth.Value) == (pytest.approx(3.0), pytest.approx(10.0))
    assert graph.findChild(preview.root) < 0 and page.preview is None  # the preview goes with the panel
    assert op_error(op) is None, op_error(op)
    assert op.GrindCall.startswith("G83 X103. I-3. Y20.")
    xs = [c.Parameters["X"] for c in op.Path.Commands if c.Name == "G1" and "X" in c.Parameters]
    assert min(xs) == pytest.approx(-3.0) and max(xs) == pytest.approx(103.0)  # recomputed with Overtravel 3


def show_top_of(page):
    """Scroll the task view to the page's first lines (the message, the G83 block) for the screenshot."""
    roomy_task_panel()
    widget = page.form
    while widget is not None and not isinstance(widget, QtGui.QScrollArea):
        widget = widget.parentWidget()
    if widget is not None:
        widget.ensureWidgetVisible(page.form.findChild(QtGui.QLabel, WARNING_LABEL))
    process(0.1)


def child_text(page, name):
    return page.form.findChild(QtGui.QLabel, name).text()


def test_an_invalid_value_refuses_ok_with_the_ops_message(shop):
    doc, job, block = shop
    panel = start_command(doc, block)
    page = panel.groove_page
    type_into(page.field("WheelWidth"), "10")
    type_into(page.field("CrossPick"), "12")
    settle(page)
    message = "CrossPick=12: must be at most the wheel's width 10 (the strokes would leave ridges)"
    assert page.error == message
    shown, marked = shown_message(page.form) == message, \
        page.field("CrossPick").property(INVALID_PROPERTY) is True
    ok_enabled = task_button(panel, QtGui.QDialogButtonBox.Ok).isEnabled()
    assert shown and marked and not ok_enabled
    assert page.preview.feeds == []  # no strokes while the values make no grind
    refused = panel.accept() is False  # Enter in a field presses OK: refused too
    still_open = open_grind_panel(doc) is panel
    assert refused and still_open
    (op,) = grind_ops(job)
    assert op.CrossPick.Value == 0.0  # nothing written
    type_into(page.field("CrossPick"), "4")
    settle(page)
    assert page.error is None and task_button(panel, QtGui.QDialogButtonBox.Ok).isEnabled()
    task_button(panel, QtGui.QDialogButtonBox.Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    assert op.CrossPick.Value == pytest.approx(4.0) and " K4. " in op.GrindCall


def test_cancel_of_a_new_op_leaves_no_op(shop):
    doc, job, block = shop
    names = sorted(o.Name for o in doc.Objects)
    panel = start_command(doc, block)
    type_into(panel.groove_page.field("WheelWidth"), "10")
    assert len(grind_ops(job)) == 1
    task_button(panel, QtGui.QDialogButtonBox.Cancel).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    assert grind_ops(job) == [] and sorted(o.Name for o in doc.Objects) == names


def test_a_scripted_op_gets_the_view_provider_and_opens_its_panel(shop):
    from freecad_groove import make_plunge_grind

    doc, job, block = shop
    op = make_plunge_grind(job, (block, TOP), wheel_width=8)
    assert isinstance(op.ViewObject.Proxy, grind_view.ViewProviderPlungeGrind)
    assert op.ViewObject.Proxy.dumps()["OpPageClass"] == "PlungeGrindPage"
    assert op.ViewObject.Proxy.dumps()["OpPageModule"] == "freecad_groove.ops.grind.gui.panel"
    FreeCADGui.getDocument(doc.Name).setEdit(op.Name)
    panel = wait_for(lambda: open_grind_panel(doc), what="the panel")
    wait_for(lambda: panel.groove_page.replans > 0, what="the check")
    wait_for(lambda: panel.buttonBox.button(QtGui.QDialogButtonBox.Cancel).isVisible(), what="the buttons")
    assert panel.groove_page.error is None and panel.groove_page.field("WheelWidth").property("value").Value == 8
    task_button(panel, QtGui.QDialogButtonBox.Cancel).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    assert grind_ops(job) == [op] and FreeCAD.ActiveDocument is not None


def test_the_commands_sit_in_cams_toolbar_and_menu_turning_groove_cylinder_slot_plunge_grind(shop):
    mw = FreeCADGui.getMainWindow()
    operations = next(tb for tb in mw.findChildren(QtGui.QToolBar) if tb.objectName() == "New Operations")
    buttons = [a.text() for a in operations.actions()]
    at = buttons.index("Turning Groove")
    assert buttons[at:at + 3] == ["Turning Groove", "Cylinder slot", "Plunge grind"], buttons
    icons = [a.icon().pixmap(32, 32).toImage() for a in operations.actions()[at:at + 3]]
    assert icons[0] != icons[1] and icons[1] != icons[2] and icons[0] != icons[2]  # each its own picture
    menus = [m for m in mw.menuBar().findChildren(QtGui.QMenu)  # CAM's menu: the one with the Turning Groove
             if "Turning Groove" in [a.text().replace("&", "") for a in m.actions()]]
    actions = menus[0].actions()
    texts = [a.text().replace("&", "") for a in actions]
    at = texts.index("Turning Groove")
    assert texts[at + 1:at + 3] == ["Cylinder slot", "Plunge grind"] and actions[at + 3].isSeparator(), texts
    FreeCADGui.Selection.clearSelection()
    assert grind_command.CommandPlungeGrind().IsActive()  # a Job in the document


def test_cancel_of_an_existing_op_keeps_its_values_and_a_saved_op_reopens_with_its_panel(tmp_path):
    from freecad_groove import make_plunge_grind

    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc, job, block = make_gui_shop("GrindSaved", feed="300 mm/min", shape=Part.makeBox(100, 40, 20))
    op = make_plunge_grind(job, (block, TOP), wheel_width=8, overtravel=4)
    doc.recompute()
    call, op_name, path = op.GrindCall, op.Name, str(tmp_path / "grind.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    process(0.1)
    doc = FreeCAD.openDocument(path)
    try:
        op = doc.getObject(op_name)
        kept = isinstance(op.ViewObject.Proxy, grind_view.ViewProviderPlungeGrind)
        assert kept and op.ViewObject.Proxy.getIcon().endswith("plunge_grind.svg")
        doc.recompute()
        assert op_error(op) is None and op.GrindCall == call
        FreeCADGui.getDocument(doc.Name).setEdit(op.Name)
        panel = wait_for(lambda: open_grind_panel(doc), what="the panel of the reopened op")
        wait_for(lambda: panel.buttonBox.button(QtGui.QDialogButtonBox.Cancel).isVisible(), what="the buttons")
        settle(panel.groove_page)
        type_into(panel.groove_page.field("Overtravel"), "2")
        settle(panel.groove_page)
        assert panel.groove_page.plan.call.I == pytest.approx(-2.0)
        task_button(panel, QtGui.QDialogButtonBox.Cancel).click()
        wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
        process(0.1)
        doc.recompute()
        assert op.Overtravel.Value == pytest.approx(4.0) and op.GrindCall == call  # as it was
    finally:
        close_shop(doc)


def test_the_panel_makes_a_grinding_wheel_tool_controller_in_one_click(shop, monkeypatch):
    doc, job, block = shop
    panel = start_command(doc, block)
    page = panel.groove_page
    tool_controllers = len(job.Tools.Group)
    type_into(page.field("WheelWidth"), "12")
    type_into(page.field("WheelDiameter"), "150")
    settle(page)
    asked = []  # the modal dialogs: only the wheel's speed is asked (its sizes are in the fields)

    def typed(parent, title, label, *args):
        asked.append(label)
        return 2500.0, True

    monkeypatch.setattr(QtGui.QInputDialog, "getDouble", typed)
    page.form.findChild(QtGui.QPushButton, grind_panel.NEW_WHEEL_BUTTON).click()
    settle(page)
    assert asked == ["Speed of the grinding wheel (rpm; at most its rated speed):"]
    assert len(job.Tools.Group) == tool_controllers + 1
    tc = job.Tools.Group[-1]
    assert page.field("ToolController").currentData() == tc.Name
    assert (tc.Tool.Width.Value, tc.Tool.Diameter.Value) == (pytest.approx(12), pytest.approx(150))
    assert (tc.SpindleSpeed, tc.SpindleDir) == (pytest.approx(2500), "Forward")
    # Its feeds are 0: the op says so until its own feeds are set.
    assert page.error == "PlungeFeed=0: no feed (the tool controller's VertFeed is 0.0): set PlungeFeed", page.error
    type_into(page.field("PlungeFeed"), "1")  # mm/s (FreeCAD's default unit schema): 60 mm/min
    type_into(page.field("ReciprocationFeed"), "100")
    settle(page)
    assert page.error is None and page.warnings == []  # the wheel bit gives its diameter: the body is checked
    assert page.plan.call.Z == pytest.approx(34.0)  # flush with Y40: the 12 mm wheel's middle
    task_button(panel, QtGui.QDialogButtonBox.Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    (op,) = grind_ops(job)
    assert op.ToolController == tc and op_error(op) is None, op_error(op)
    assert " Z34. K6. L1 F60. E6000." in op.GrindCall  # K: half the 12 mm wheel


def test_ok_keeps_the_exact_values_of_fields_left_alone(shop):
    """A quantity field rounds to the decimals it shows: a value the user did not touch goes back as it was."""
    from freecad_groove import make_plunge_grind

    doc, job, block = shop
    op = make_plunge_grind(job, (block, TOP), wheel_width=8, plunge_feed="50 mm/min",
                           reciprocation_feed="3337 mm/min", start_clearance="1.23456 mm")
    FreeCADGui.getDocument(doc.Name).setEdit(op.Name)
    panel = wait_for(lambda: open_grind_panel(doc), what="the panel")
    wait_for(lambda: panel.buttonBox.button(QtGui.QDialogButtonBox.Cancel).isVisible(), what="the buttons")
    settle(panel.groove_page)
    type_into(panel.groove_page.field("Overtravel"), "3")
    settle(panel.groove_page)
    task_button(panel, QtGui.QDialogButtonBox.Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    assert op.Overtravel.Value == pytest.approx(3.0)
    assert (op.PlungeFeed.Value, op.ReciprocationFeed.Value) == (50 / 60, 3337 / 60)  # mm/s, exactly
    assert op.StartClearance.Value == 1.23456 and op_error(op) is None
