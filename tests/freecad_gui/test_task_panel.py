"""The Groove command and task panel in FreeCAD's GUI (1.1 and 1.0, under Xvfb).

What a user does: open a turned part, make a Job, select a face, press the
Groove button, type values into the fields, watch the preview, press OK or
Cancel. Fields are typed into key by key and buttons clicked; every test
saves a screenshot of the panel and the 3D view.
"""

import FreeCAD
import FreeCADGui
import Part
import pytest
from gui_helpers import (  # noqa: E402
    DEFAULT_DOCK_WIDTHS,
    choose,
    close_shop,
    make_gui_shop,
    note_default_docks,
    open_panel,
    process,
    roomy_task_panel,
    screenshot,
    screenshot_widget,
    show_part,
    shown_message,
    start_groove_command,
    task_button,
    type_into,
    version,
    wait_for,
    zoom_to,
)
from parts import face_name  # noqa: E402
from PySide import QtCore, QtGui

from freecad_groove import make_groove  # noqa: E402
from freecad_groove.gui import widgets  # noqa: E402
from freecad_groove.ops.groove.gui import panel as task_panel  # noqa: E402
from freecad_groove.ops.groove.gui.command import CommandGroove  # noqa: E402
from freecad_groove.ops.groove.gui.tool_page import ToolPage  # noqa: E402
from freecad_groove.ops.groove.gui.view import TurnedFaceGate, ViewProviderGroove  # noqa: E402

Ok, Apply, Cancel = QtGui.QDialogButtonBox.Ok, QtGui.QDialogButtonBox.Apply, QtGui.QDialogButtonBox.Cancel
TOOL_WIDTH = 3.0  # the default tool bit has no Width: typed into the op's ToolWidth (start_command)
DEFAULT_DOCKS = DEFAULT_DOCK_WIDTHS  # dock title -> width as FreeCAD starts (before roomy_task_panel widens them)


@pytest.fixture(scope="module", autouse=True)
def cam_workbench():
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    process(0.2)
    note_default_docks()  # (the widths seen first in the suite: the docks may have been widened since)


@pytest.fixture
def shop():
    """(doc, job, model): the stepped shaft in a Job made as the GUI makes it."""
    doc, job, model = make_gui_shop("GrooveGui")
    show_part(doc)
    yield doc, job, model
    close_shop(doc)


def ops(job):
    return [o for o in job.Operations.Group if type(getattr(o, "Proxy", None)).__name__ == "ObjectGroove"]


def start_command(doc, model, face_key, blade=TOOL_WIDTH):
    """Start the command on a face; the Job's end mill has no Width, so the
    blade's width is typed on the tool page (``blade``; None: left unknown)."""
    panel = start_groove_command(doc, model, face_key)
    roomy_task_panel()
    if blade is not None:
        replan(panel.groove_page, panel.groove_page.field("ToolWidth"), "%g mm" % blade)
    return panel.obj, panel, panel.groove_page


def replan(page, field, text):
    """Type ``text`` into ``field`` and wait for the preview to follow."""
    before = page.replans
    type_into(field, text)
    shown = field.text() if hasattr(field, "text") else None
    wait_for(lambda: page.replans > before, what="the preview after typing %r (the field shows %r)" % (text, shown))
    number = float(text.split()[0])
    value = field.property("rawValue") if field.property("rawValue") is not None else field.value()
    assert value == pytest.approx(number), "typed %r, the field shows %r = %r" % (text, shown, value)


def extent(polyline, axis):
    values = [p[axis] for p in polyline]
    return min(values), max(values)


def menu_text(command):
    return FreeCADGui.Command.get(command).getInfo()["menuText"].replace("&", "")


def cam_menu():
    """CAM's top-level menu (the one holding the V-carve action)."""
    vcarve = menu_text("CAM_Vcarve")
    for menu in FreeCADGui.getMainWindow().menuBar().findChildren(QtGui.QMenu):
        if vcarve in [a.text().replace("&", "") for a in menu.actions()]:
            return menu
    raise AssertionError("no CAM menu with %s" % vcarve)


def test_command_sits_with_cams_operations_as_turning_groove(shop):
    mw = FreeCADGui.getMainWindow()
    toolbars = [tb for tb in mw.findChildren(QtGui.QToolBar) if tb.isVisible()]
    toolbar_texts = [a.text() for tb in toolbars for a in tb.actions()]
    assert "Turning Groove" in toolbar_texts and "Groove" not in toolbar_texts  # PartDesign's Groove is "Groove"
    operations = next(tb for tb in toolbars if tb.objectName() == "New Operations")
    assert "Turning Groove" in [a.text() for a in operations.actions()]
    # In the CAM menu: right after V-Carve (the engraving operations), before the separator and the 3D ops.
    actions = [a for a in cam_menu().actions()]
    texts = [a.text().replace("&", "") for a in actions]
    at = texts.index("Turning Groove")
    assert texts[at - 1] == menu_text("CAM_Vcarve"), texts
    assert texts[at + 1:at + 3] == ["Cylinder slot", "Plunge grind"] and actions[at + 3].isSeparator(), texts
    assert at < len(texts) - 4, "not at the bottom of the menu: %s" % texts
    assert CommandGroove().IsActive()  # the document has a Job
    screenshot("%s-toolbar" % version())


def test_command_needs_a_job():
    doc = FreeCAD.newDocument("NoJob")
    try:
        assert not CommandGroove().IsActive()
        screenshot("%s-no-job" % version())
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_groove_made_in_the_panel(shop):
    doc, job, model = shop
    op, panel, page = start_command(doc, model, "cylinder")
    base_page = next(p for p in panel.featurePages if isinstance(p, task_panel.BaseGeometryPage))
    assert base_page.form.baseList.count() == 1
    assert "longitudinal, external" in base_page.kind_label.text()
    assert widgets.child(page.form, "angc").text().startswith("0")

    # The preview is in the 3D view: one groove section, the toolpath.
    assert page.preview.in_scene()
    assert len(page.preview.sections) == 1 and page.preview.feeds
    z0, z1 = extent(page.preview.sections[0], 2)
    assert z1 - z0 == pytest.approx(4.0)  # the default width
    first_feeds = list(page.preview.feeds)

    # Typed values move the preview, not the document.
    replan(page, page.field("Width"), "6 mm")
    replan(page, page.field("Depth"), "3 mm")
    replan(page, page.field("Position"), "8 mm")
    section = page.preview.sections[0]
    z0, z1 = extent(section, 2)
    x0, x1 = extent(section, 0)
    assert z1 - z0 == pytest.approx(6.0)
    assert z1 == pytest.approx(30.0 - 8.0)  # the cylinder's +Z end is Z30
    assert (x0, x1) == (pytest.approx(17.0), pytest.approx(20.0))
    assert page.preview.feeds != first_feeds
    assert min(p[0] for seg in page.preview.feeds for p in seg) == pytest.approx(17.0)
    assert op.Width.Value == pytest.approx(4.0)  # not written before OK
    assert page.error is None and task_button(panel, Ok).isEnabled()
    screenshot("%s-panel" % version())

    # More grooves: the second one would run off the face's -Z end (Z10)...
    replan(page, page.field("Pitch"), "10 mm")
    replan(page, page.field("GrooveCount"), "2")
    assert page.error is not None and "groove 2" in page.error and "past the face" in page.error
    assert page.field("Pitch").property("grooveInvalid") is True
    assert page.preview.sections == [] and not task_button(panel, Ok).isEnabled()
    # ... until they start nearer the +Z end: one section each, 10 apart.
    replan(page, page.field("Position"), "2 mm")
    assert page.error is None and page.field("Pitch").property("grooveInvalid") is not True
    assert sorted(extent(sec, 2)[1] for sec in page.preview.sections) == [pytest.approx(18.0), pytest.approx(28.0)]
    replan(page, page.field("GrooveCount"), "1")
    replan(page, page.field("Position"), "8 mm")

    preview = page.preview
    task_button(panel, Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    assert ops(job) == [op]
    assert not preview.in_scene()
    assert (op.Width.Value, op.Depth.Value, op.Position.Value) == (6.0, 3.0, 8.0)
    assert op.State == [] or "Invalid" not in op.State
    feeds = [c for c in op.Path.Commands if c.Name == "G1"]
    assert feeds
    assert min(c.Parameters["X"] for c in feeds) == pytest.approx(17.0)
    zs = [c.Parameters["Z"] for c in feeds]
    assert min(zs) >= 16.0 - 1e-6 and max(zs) <= 22.0 - TOOL_WIDTH + 1e-6  # the reference corner stays in the groove
    # For the picture: the part with the groove cut (the finished groove's
    # section revolved about Z); the toolpath in the section plane shows through it.
    FreeCADGui.Selection.clearSelection()
    grooved = doc.addObject("Part::Feature", "Grooved")
    shape = model.Shape
    for plan in op.Proxy.plan(op):
        points = [FreeCAD.Vector(x, 0, z) for x, z in plan.geometry.region_world()]
        section = Part.Face(Part.makePolygon(points + points[:1]))
        shape = shape.cut(section.revolve(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 0, 1), 360))
    grooved.Shape = shape
    assert grooved.Shape.Volume < model.Shape.Volume
    model.ViewObject.Visibility = False
    job.Stock.ViewObject.Visibility = False
    zoom_to(doc, 12.0, 20.0, 40.0)
    screenshot("%s-grooved-part" % version())


def test_invalid_width_shows_the_message_and_ok_is_refused(shop):
    doc, job, model = shop
    op, panel, page = start_command(doc, model, "cylinder")
    replan(page, page.field("Width"), "2 mm")
    assert page.error is not None
    assert "WIDG=2" in page.error and "61602" in page.error
    assert shown_message(page.form) == page.error  # at the top of the pages
    assert page.field("Width").property("grooveInvalid") is True
    assert not task_button(panel, Ok).isEnabled()
    screenshot("%s-invalid-width" % version())

    task_button(panel, Ok).click()  # a disabled button: nothing happens
    process(0.1)
    assert FreeCADGui.Control.activeDialog()
    assert panel.accept() is False  # and if OK were reached anyway
    assert FreeCADGui.Control.activeDialog()
    assert op.Width.Value == pytest.approx(4.0)

    replan(page, page.field("Width"), "5 mm")
    assert page.error is None and shown_message(page.form) is None
    assert page.field("Width").property("grooveInvalid") is not True
    assert task_button(panel, Ok).isEnabled()


def test_error_on_a_corner_names_the_alarm_and_marks_the_corner(shop):
    doc, job, model = shop
    op, panel, page = start_command(doc, model, "cylinder")
    choose(page.field("BaseCorner1Type"), "Radius")
    choose(page.field("BaseCorner2Type"), "Radius")
    replan(page, page.field("BaseCorner1"), "2 mm")
    replan(page, page.field("BaseCorner2"), "2.5 mm")
    assert page.error is not None and "61603" in page.error
    assert page.field("BaseCorner1").property("grooveInvalid") is True
    assert page.field("BaseCorner2").property("grooveInvalid") is True
    assert not task_button(panel, Ok).isEnabled()
    screenshot("%s-invalid-corners" % version())


def test_allowances_that_leave_the_blade_no_room_warn_in_amber_and_ok_stays(shop):
    doc, job, model = shop
    op, panel, page = start_command(doc, model, "cylinder")
    label = widgets.child(page.form, "warningLabel")
    flank = page.field("FlankAllowance")
    # A sharp blade reaches the sharp base corners: only the allowances can warn here.
    replan(page, page.field("ToolCornerRadius"), "0 mm")
    assert page.warnings == [] and not label.isVisible()
    # The 3 mm blade in the 4 mm wide groove: flank allowances of 0.6 leave a 2.8 mm roughing base.
    replan(page, flank, "0.6 mm")
    assert page.error is None and len(page.warnings) == 1
    text = page.warnings[0]
    assert text.split(": ", 1)[0].endswith("." + face_name(model.Shape, "cylinder"))  # "Shaft.Face3"
    assert text.split(": ", 1)[1].startswith("groove 1: CYCLE93: the allowances")
    assert "FAL2=0.6" in text and "no room for the 3 mm blade" in text and "2.8 mm wide" in text
    assert label.isVisible() and label.text() == "Warning: " + text
    assert label.styleSheet() == widgets.WARNING_STYLE != widgets.ERROR_STYLE
    assert not widgets.child(page.form, "errorLabel").isVisible()
    assert flank.property("grooveWarned") is True and flank.property("grooveInvalid") is not True
    assert flank.styleSheet() == widgets.WARNED_STYLE != widgets.INVALID_STYLE
    assert page.field("BaseAllowance").property("grooveWarned") is not True
    assert task_button(panel, Ok).isEnabled()
    tool_page = next(p for p in panel.featurePages if isinstance(p, ToolPage))
    assert widgets.child(tool_page.form, "warningLabel").text() == label.text()
    for area in FreeCADGui.getMainWindow().findChildren(QtGui.QScrollArea):  # the message, for the picture
        if area.isAncestorOf(label):
            area.ensureWidgetVisible(label)
    screenshot("%s-allowance-warning" % version())

    # An error replaces the warning while it stands.
    replan(page, page.field("Width"), "2 mm")
    assert page.error is not None and page.warnings == [] and not label.isVisible()
    assert flank.property("grooveWarned") is not True and not task_button(panel, Ok).isEnabled()
    replan(page, page.field("Width"), "4 mm")
    assert page.error is None and len(page.warnings) == 1 and flank.property("grooveWarned") is True

    # A value that leaves the blade room: the warning goes.
    replan(page, flank, "0.2 mm")
    assert page.warnings == [] and not label.isVisible()
    assert flank.property("grooveWarned") is not True and flank.styleSheet() == ""

    # Warnings never block: OK writes the values.
    replan(page, flank, "0.6 mm")
    assert len(page.warnings) == 1 and task_button(panel, Ok).isEnabled()
    task_button(panel, Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    assert ops(job) == [op] and op.FlankAllowance.Value == pytest.approx(0.6)
    assert [len(plan.warnings) for plan in op.Proxy.plan(op)] == [1]


def test_cancel_leaves_no_op(shop):
    doc, job, model = shop
    before = sorted(o.Name for o in doc.Objects)
    op, panel, page = start_command(doc, model, "shoulder")
    replan(page, page.field("Width"), "3.5 mm")
    assert "face, external" in next(
        p for p in panel.featurePages if isinstance(p, task_panel.BaseGeometryPage)).kind_label.text()
    screenshot("%s-face-groove" % version())
    preview = page.preview
    task_button(panel, Cancel).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    assert sorted(o.Name for o in doc.Objects) == before
    assert ops(job) == []
    assert not preview.in_scene()


def test_double_click_reopens_the_panel_with_the_ops_values(shop):
    doc, job, model = shop
    op = make_groove(job, (model, face_name(model.Shape, "cylinder")), width=4.5, depth=1.5, position=6,
                     edge_corner1_type="Chamfer", edge_corner1=0.5, tool_width=TOOL_WIDTH)
    assert isinstance(op.ViewObject.Proxy, ViewProviderGroove)  # scripts' ops get the view provider too
    FreeCADGui.getDocument(doc.Name).setEdit(op.Name)  # what a double-click in the tree does
    panel = wait_for(lambda: open_panel(doc), what="the panel")
    page = panel.groove_page
    assert page.field("Width").property("rawValue") == pytest.approx(4.5)
    assert page.field("Depth").property("rawValue") == pytest.approx(1.5)
    assert page.field("Position").property("rawValue") == pytest.approx(6.0)
    assert page.field("EdgeCorner1Type").currentData() == "Chamfer"
    assert page.field("EdgeCorner1").isEnabled() and not page.field("EdgeCorner2").isEnabled()
    wait_for(lambda: page.replans > 0, what="the preview")
    replan(page, page.field("Width"), "5 mm")
    screenshot("%s-reopened" % version())
    task_button(panel, Cancel).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    assert ops(job) == [op]  # an existing op stays on Cancel
    assert op.Width.Value == pytest.approx(4.5)


def base_page_of(panel):
    return next(p for p in panel.featurePages if isinstance(p, task_panel.BaseGeometryPage))


def test_faces_are_added_and_removed_on_the_base_geometry_page(shop):
    doc, job, model = shop
    op, panel, page = start_command(doc, model, "cylinder")
    base = base_page_of(panel)
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(doc.Name, model.Name, face_name(model.Shape, "shoulder"))
    wait_for(lambda: base.form.addBase.isEnabled(), what="the Add button")
    before = page.replans
    base.form.addBase.click()
    wait_for(lambda: page.replans > before, what="the preview with two faces")
    assert base.form.baseList.count() == 2
    assert "longitudinal, external" in base.kind_label.text() and "face, external" in base.kind_label.text()
    assert page.error is None and len(page.preview.sections) == 2
    screenshot("%s-two-faces" % version())

    base.form.baseList.setCurrentRow(0)
    before = page.replans
    base.form.deleteBase.click()
    wait_for(lambda: page.replans > before, what="the preview with one face")
    assert base.form.baseList.count() == 1
    assert "longitudinal" not in base.kind_label.text()
    assert len(page.preview.sections) == 1
    x0, x1 = extent(page.preview.sections[0], 0)  # a face groove: it runs along X on the shoulder
    assert x1 == pytest.approx(20.0)


def test_only_turned_faces_can_be_picked(shop):
    doc, job, model = shop
    gate = TurnedFaceGate()
    names = ["Face%d" % (i + 1) for i in range(len(model.Shape.Faces))]
    assert all(gate.allow(doc, model, n) for n in names)
    assert not gate.allow(doc, model, "Edge1")
    box = doc.addObject("Part::Box", "Block")
    doc.recompute()
    assert not any(gate.allow(doc, box, "Face%d" % (i + 1)) for i in range(6) if i not in (4, 5))
    screenshot("%s-selection-gate" % version())


def test_a_blade_wider_than_the_groove_is_shown_on_the_tool_page(shop):
    doc, job, model = shop
    op, panel, page = start_command(doc, model, "cylinder")
    tool_page = next(p for p in panel.featurePages if isinstance(p, ToolPage))
    assert page.field("ToolWidth").isEnabled()  # the default tool bit has no Width
    replan(page, page.field("ToolWidth"), "5 mm")
    assert page.error is not None and "tool width 5" in page.error and "61602" in page.error
    assert shown_message(tool_page.form) == page.error
    assert page.field("ToolWidth").property("grooveInvalid") is True
    assert page.field("Width").property("grooveInvalid") is True
    assert not task_button(panel, Ok).isEnabled()
    if isinstance(panel.form, QtGui.QToolBox):  # show the tool page, as a user who opened it sees it
        panel.form.setCurrentWidget(tool_page.form)
    screenshot("%s-blade-too-wide" % version())
    replan(page, page.field("Width"), "6 mm")
    assert page.error is None and task_button(panel, Ok).isEnabled()
    task_button(panel, Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    assert (op.ToolWidth.Value, op.Width.Value) == (5.0, 6.0)


def tool_page_of(panel):
    return next(p for p in panel.featurePages if isinstance(p, ToolPage))


def show_page(panel, page):
    if isinstance(panel.form, QtGui.QToolBox):
        panel.form.setCurrentWidget(page.form)
    process(0.05)


def test_without_a_grooving_blade_the_panel_says_so_and_one_click_makes_one(shop):
    doc, job, model = shop
    op, panel, page = start_command(doc, model, "cylinder", blade=None)
    tool_page = tool_page_of(panel)
    # The Job's only tool is FreeCAD's end mill: no blade width, and none made up.
    assert page.field("ToolWidth").property("rawValue") == 0
    assert page.error is not None and "blade's width is unknown" in page.error
    assert page.field("ToolWidth").property("grooveInvalid") is True
    assert not task_button(panel, Ok).isEnabled()
    show_page(panel, tool_page)
    screenshot("%s-no-blade" % version())
    # One click: a grooving tool controller with the blade typed on the page, selected for the op.
    replan(page, page.field("ToolWidth"), "2.5 mm")
    replan(page, page.field("ToolCornerRadius"), "0.3 mm")
    before = page.replans
    tool_page.form.newGroovingTool.click()
    wait_for(lambda: page.replans > before, what="the preview with the new tool controller")
    tc = op.ToolController
    assert tc in job.Tools.Group and len(job.Tools.Group) == 2
    assert tc.Tool.Width.Value == pytest.approx(2.5) and tc.Tool.CornerRadius.Value == pytest.approx(0.3)
    assert tool_page.form.toolController.currentText() == tc.Label
    assert not page.field("ToolWidth").isEnabled()
    assert "gives the blade's Width" in tool_page.form.toolSourceLabel.text()
    assert page.error is None and task_button(panel, Ok).isEnabled()
    screenshot("%s-grooving-tool-controller" % version())
    task_button(panel, Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    assert op.ToolController == tc and "Invalid" not in op.State
    assert op.Proxy.settings(op).tool.width == pytest.approx(2.5)


def test_the_grooving_tool_controller_button_asks_for_an_unknown_width(shop, monkeypatch):
    doc, job, model = shop
    op, panel, page = start_command(doc, model, "cylinder", blade=None)
    from freecad_groove.ops.groove.gui import tool_page as tool_page_mod

    asked = []
    monkeypatch.setattr(tool_page_mod, "ask_blade_width", lambda parent: asked.append(parent) or None)
    assert tool_page_of(panel).new_grooving_tool_controller() is None  # cancelled: nothing made
    assert len(asked) == 1 and len(job.Tools.Group) == 1
    monkeypatch.setattr(tool_page_mod, "ask_blade_width", lambda parent: 3.5)
    tc = tool_page_of(panel).new_grooving_tool_controller()
    assert tc.Tool.Width.Value == pytest.approx(3.5) and op.ToolController == tc
    wait_for(lambda: page.error is None, what="the groove with the new blade")


def test_ok_without_a_face_says_what_is_missing(shop):
    doc, job, model = shop
    FreeCADGui.Selection.clearSelection()
    process()
    FreeCADGui.runCommand(CommandGroove.NAME)
    panel = wait_for(lambda: open_panel(doc), what="the Groove task panel")
    page = panel.groove_page
    wait_for(lambda: page.replans > 0, what="the first preview")
    roomy_task_panel()
    replan(page, page.field("ToolWidth"), "3 mm")
    assert page.error is not None and "no face picked" in page.error
    assert widgets.child(page.form, "errorLabel").isVisible()
    assert base_page_of(panel).form.baseList.property("grooveInvalid") is True
    assert not task_button(panel, Ok).isEnabled()
    assert panel.accept() is False and FreeCADGui.Control.activeDialog()
    screenshot("%s-no-face" % version())
    # Picking a face fixes it.
    base = base_page_of(panel)
    FreeCADGui.Selection.addSelection(doc.Name, model.Name, face_name(model.Shape, "cylinder"))
    wait_for(lambda: base.form.addBase.isEnabled(), what="the Add button")
    base.form.addBase.click()
    wait_for(lambda: page.error is None, what="the groove on the picked face")
    assert task_button(panel, Ok).isEnabled()


def default_docks():
    """The docks back at the width FreeCAD starts with (1.0: the combo view, 1.1: the tasks dock)."""
    mw = FreeCADGui.getMainWindow()
    docks = [d for d in mw.findChildren(QtGui.QDockWidget) if d.isVisible() and d.windowTitle() in DEFAULT_DOCKS]
    mw.resizeDocks(docks, [DEFAULT_DOCKS[d.windowTitle()] for d in docks], QtCore.Qt.Horizontal)
    process(0.1)


def scroll_areas_holding(widget):
    """The visible scroll areas a widget is shown in, outermost first (the
    task view's; in the toolbox layout also the toolbox's own per page)."""
    mw = FreeCADGui.getMainWindow()
    return [a for a in mw.findChildren(QtGui.QScrollArea)
            if a.isVisible() and a.widget() is not None and a.widget().isAncestorOf(widget)]


def dock_of(widget):
    """The dock a widget is shown in (1.0: the combo view, 1.1: the tasks dock)."""
    while widget is not None and not isinstance(widget, QtGui.QDockWidget):
        widget = widget.parentWidget()
    assert widget is not None, "the panel is in no dock"
    return widget


LINE_EDIT_PADDING = 4  # px: Qt's line edit keeps 2 px each side of its text


def check_page_fits(page):
    """A page shown in the default dock: no wider than the room it gets, no
    horizontal scrollbar, every field showing FIELD_SAMPLE (or its own size) inside the
    page, every message wrapped inside it, the picture whole."""
    title = page.getTitle(page.obj)
    process(0.1)
    areas = scroll_areas_holding(page.form)
    assert areas, "no scroll area holds the page %s" % title
    room = areas[-1].viewport().width()
    hint = page.form.minimumSizeHint().width()
    assert hint <= room, "%s needs %d px, the dock gives %d" % (title, hint, room)
    for area in areas:
        assert not area.horizontalScrollBar().isVisible(), "a horizontal scrollbar on %s" % title
    right = page.form.width()
    for box in page.form.findChildren(QtGui.QAbstractSpinBox):
        if box.isVisible():
            least = min(box.sizeHint().width(), widgets.text_width(box, widgets.FIELD_SAMPLE))
            assert box.width() >= least, "%s is squeezed" % box.objectName()
            assert box.mapTo(page.form, QtCore.QPoint(box.width(), 0)).x() <= right, "%s is cut" % box.objectName()
            edit = box.findChild(QtGui.QLineEdit)  # its text whole (1.0 showed Position "25.00 mn")
            margins = edit.textMargins()
            room = edit.width() - margins.left() - margins.right() - LINE_EDIT_PADDING - widgets.edit_padding(box)
            need = widgets.text_width(edit, edit.text())
            assert need <= room, "%s shows %r in %d px, needs %d" % (box.objectName(), edit.text(), room, need)
    for label in page.form.findChildren(QtGui.QLabel):
        if label.isVisible() and label.text():
            end = label.mapTo(page.form, QtCore.QPoint(label.width(), 0)).x()
            assert end <= right, "%r is cut off" % label.text()[:40]
            if label.objectName() in (widgets.ERROR_LABEL, widgets.WARNING_LABEL):
                assert label.wordWrap() and label.height() > label.fontMetrics().height() * 1.5  # wrapped
    diagram = widgets.child(page.form, "diagram")
    if diagram is not None:
        assert diagram.pixmap().width() <= diagram.width(), "the picture is cut"


def test_panel_fits_the_default_dock_width(shop):
    doc, job, model = shop
    # A tool controller named at length: its combo box is then as wide as widgets.COMBO_CHARS characters. Run
    # alone (test_task_panel.py in 1.0) the Tool and coolant page needed 227 px of the combo view's 218, its
    # combo box fitted so; the test leaves the name to chance no longer.
    job.Tools.Group[0].Label = "TC: a tool controller with a name longer than the dock"
    default_docks()
    panel = start_groove_command(doc, model, "cylinder")
    try:
        page = panel.groove_page
        replan(page, page.field("Position"), "25 mm")  # two digits before the point
        replan(page, page.field("Width"), "2 mm")  # a long message (the blade's width is unknown) on every page
        assert page.error is not None and len(page.error) > 80
        dock = dock_of(page.form)
        for p in panel.featurePages:
            show_page(panel, p)
            check_page_fits(p)
            # The pages never widen the dock: at most FreeCAD's own OK/Cancel/Apply row does, as for
            # every CAM op (1.0: 273 px for a 260 px combo view; 1.1's task dock has room for both).
            widest = max(panel.buttonBox.minimumSizeHint().width(), DEFAULT_DOCKS.get(dock.windowTitle(), 0))
            assert panel.form.minimumSizeHint().width() <= widest, "%s widens the dock" % p.getTitle(p.obj)
        tool_page = tool_page_of(panel)
        if hasattr(tool_page, "tcEditor"):  # FreeCAD 1.1: the tool controller's editor shown in the page
            show_page(panel, tool_page)
            tool_page.form.editToolController.setChecked(True)
            process(0.1)
            check_page_fits(tool_page)
            screenshot_widget("%s-tool-page-default-dock" % version(), dock_of(tool_page.form))
            tool_page.form.editToolController.setChecked(False)
        show_page(panel, page)
        scroll_areas_holding(page.form)[-1].ensureWidgetVisible(widgets.child(page.form, "errorLabel"))
        screenshot_widget("%s-panel-default-dock" % version(), dock_of(page.form))
    finally:  # closed here: FreeCAD 1.0 crashes closing a panel from the fixture after a failure
        task_button(panel, Cancel).click()
        wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")




def row_message(form):
    """The message label shown under a field row of ``form`` (gui/field_rows.py), or None."""
    from freecad_groove.gui.field_rows import FIELD_MESSAGE

    shown = [label for label in form.findChildren(QtGui.QLabel, FIELD_MESSAGE) if not label.isHidden()]
    assert len(shown) <= 1, [label.text() for label in shown]
    return shown[0] if shown else None


def in_view(widget, area):
    """``widget`` shows whole inside the viewport of scroll area ``area``."""
    top_left = widget.mapTo(area.viewport(), QtCore.QPoint(0, 0))
    return widget.isVisible() and area.viewport().rect().contains(QtCore.QRect(top_left, widget.size()))


def test_the_message_shows_in_the_row_of_the_field_being_edited(shop):
    # issue 21: on the long Groove page the message line at the top scrolled out of view while a field further
    # down was edited: only the red frame and a grey OK were left to see
    doc, job, model = shop
    default_docks()
    panel = start_groove_command(doc, model, "cylinder")
    try:
        page, tool_page = panel.groove_page, tool_page_of(panel)
        # At the start the Job's end mill gives no blade width: the message names ToolWidth, and no field has
        # been edited yet: it shows under ToolWidth on the tool page (and at the top of every page).
        assert page.error.startswith("ToolWidth"), page.error
        assert row_message(tool_page.form).text() == page.error and row_message(page.form) is None
        replan(page, page.field("ToolWidth"), "3 mm")  # a blade: the groove is valid, no message anywhere
        assert page.error is None and row_message(tool_page.form) is None and row_message(page.form) is None
        show_page(panel, page)
        area = scroll_areas_holding(page.form)[-1]
        count, pitch = page.field("GrooveCount"), page.field("Pitch")
        area.ensureWidgetVisible(pitch)  # the user scrolls down to the repeat
        wait_for(lambda: in_view(count, area), what="GrooveCount in view")
        before = page.replans
        type_into(count, "2", leave=False)  # Pitch 0 with two grooves: an error naming Pitch
        wait_for(lambda: page.replans > before and page.error is not None, what="the error")
        assert page.error.startswith("Pitch=0"), page.error
        assert shown_message(page.form) == page.error  # at the top of the page too, out of view here
        top = widgets.child(page.form, widgets.ERROR_LABEL)
        assert not in_view(top, area)
        near = row_message(page.form)
        assert near is not None and near.text() == page.error
        wait_for(lambda: in_view(near, area), what="the message in view while GrooveCount is edited")
        at = near.mapTo(page.form, QtCore.QPoint(0, 0)).y()
        field_at = count.mapTo(page.form, QtCore.QPoint(0, count.height())).y()
        assert 0 <= at - field_at <= 12, (at, field_at)  # right under the field being edited
        assert pitch.property("grooveInvalid") is True and not task_button(panel, Ok).isEnabled()
        screenshot_widget("%s-message-in-the-row" % version(), dock_of(page.form))
        replan(page, pitch, "6 mm")  # fixed: the message goes
        assert page.error is None and row_message(page.form) is None and top.isHidden()
        area.ensureWidgetVisible(pitch)
        before = page.replans
        type_into(pitch, "0", leave=False)  # the wrong field itself being edited: the message under it
        wait_for(lambda: page.replans > before and page.error is not None, what="the error")
        assert page.error.startswith("Pitch=0"), page.error
        near = row_message(page.form)
        assert near is not None and near.text() == page.error
        wait_for(lambda: in_view(near, area), what="the message in view while Pitch is edited")
        field_at = pitch.mapTo(page.form, QtCore.QPoint(0, pitch.height())).y()
        assert 0 <= near.mapTo(page.form, QtCore.QPoint(0, 0)).y() - field_at <= 12
        # The page deletes its message labels itself when it is cleaned up, while the form is whole: FreeCAD
        # 1.1 once segfaulted in shiboken deleting one with the dialog (field_rows.remove_message_rows).
        from freecad_groove.gui.field_rows import FIELD_MESSAGE
        from freecad_groove.gui.qt_wrappers import shiboken

        forms = (page.form, tool_page.form)
        labels = [label for form in forms for label in form.findChildren(QtGui.QLabel, FIELD_MESSAGE)]
        assert len(labels) >= 10, len(labels)
        page.cleanupPage(page.obj)  # as CAM's panel does on closing; Cancel below runs it again (a no-op)
        assert not any(shiboken.isValid(label) for label in labels) and shiboken.isValid(page.form)
        assert page.form.findChildren(QtGui.QLabel, FIELD_MESSAGE) == []
    finally:
        task_button(panel, Cancel).click()
        wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
