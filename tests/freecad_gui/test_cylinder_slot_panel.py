"""The Cylinder slot task panel in FreeCAD's GUI (1.1 and 1.0, under Xvfb).

What a user does: select the R20 shaft's cylinder and the helix on it (or a
sketch of the developed surface), press the Cylinder slot command, type values
into the panel, watch the developed path, press OK or Cancel. The helix: one
turn (pitch 20) from Z10, i.e. on the developed surface a line from (Z10, s0)
to (Z30, s = 40 pi). Pass radii by hand (gsk_g7_1's rule): rough passes at
20 - (Depth - Allowance) * n / 2 (n = 1, 2), the finish at 20 - Depth.
"""

import math

import FreeCAD
import FreeCADGui
import Part
import pytest
from gui_helpers import (
    buttons_shown,
    close_shop,
    make_slot_shop,
    process,
    roomy_task_panel,
    screenshot,
    task_button,
    type_into,
    version,
    wait_for,
)
from PySide import QtGui

from freecad_groove.gui import widgets
from freecad_groove.ops.slot.gui import command as slot_command
from freecad_groove.ops.slot.gui import panel as slot_panel
from freecad_groove.ops.slot.gui import view as slot_view

Ok, Apply, Cancel = QtGui.QDialogButtonBox.Ok, QtGui.QDialogButtonBox.Apply, QtGui.QDialogButtonBox.Cancel
V = FreeCAD.Vector
HELIX_END = (30.0, 40.0 * math.pi)


@pytest.fixture
def shop():
    doc, job = make_slot_shop("slotpanel")
    yield doc, job
    FreeCADGui.Selection.clearSelection()
    close_shop(doc)


def slot_ops(job):
    return [o for o in job.Operations.Group if hasattr(o, "Region")]


def open_slot_panel(doc):
    """The open Cylinder slot panel of an op in ``doc``, or None."""
    if not FreeCADGui.Control.activeDialog():
        return None
    for obj in doc.Objects:
        vp = getattr(getattr(obj, "ViewObject", None), "Proxy", None)
        if isinstance(vp, slot_view.ViewProviderCylinderSlot) and getattr(vp, "panel", None) is not None:
            return vp.panel
    return None


def run_command(doc, picks):
    """Select ``picks`` [(object, sub or None)], press Cylinder slot; the panel once its preview is drawn."""
    FreeCADGui.Selection.clearSelection()
    for obj, sub in picks:
        if sub:
            FreeCADGui.Selection.addSelection(obj, sub)
        else:
            FreeCADGui.Selection.addSelection(obj)
    process()
    FreeCADGui.runCommand(slot_command.COMMAND)
    panel = wait_for(lambda: open_slot_panel(doc), what="the Cylinder slot panel")
    wait_for(lambda: panel.op_page.replans > 0, what="the first preview")
    wait_for(lambda: buttons_shown(panel), what="the panel's buttons")
    roomy_task_panel()
    return panel, panel.op_page


def replan(page, field, text):
    before = page.replans
    type_into(field, text)
    wait_for(lambda: page.replans > before, what="the preview after typing %r" % text)


def close_with(panel, which):
    task_button(panel, which).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)


def centre(page):
    return [(round(z, 6), round(s, 6)) for z, s in page.picture.path.centre]


def test_command_with_face_and_edge_opens_the_panel_and_ok_writes_the_depth(shop):
    doc, job = shop
    shaft, line = job.Model.Group
    panel, page = run_command(doc, [(shaft, "Face1"), (line, "Edge1")])
    (op,) = slot_ops(job)
    assert isinstance(panel, slot_panel.SlotTaskPanel)
    base = next(p for p in panel.featurePages if isinstance(p, slot_panel.SlotBaseGeometryPage))
    assert sorted(base.form.baseList.item(i).text() for i in range(base.form.baseList.count())) == \
        sorted(["%s.Face1" % shaft.Label, "%s.Edge1" % line.Label])
    # The developed path: the helix as one straight line; the passes of the defaults (Depth 1, Allowance 0.1)
    assert page.error is None and page.picture.draws > 0
    assert centre(page) == [(10.0, 0.0), (pytest.approx(HELIX_END[0]), pytest.approx(HELIX_END[1], abs=1e-3))]
    assert page.picture.path.width == pytest.approx(5.0)  # the Job's 5 mm end mill
    passes = widgets.child(page.form, "passesLabel")
    assert passes.text() == "Passes at R19.55, R19.1; finish R19"
    assert not widgets.child(page.form, "developedPicture").pixmap().isNull()
    screenshot("%s-cylinder-slot-panel" % version())

    replan(page, page.field("Depth"), "2 mm")
    assert passes.text() == "Passes at R19.05, R18.1; finish R18"
    assert op.Depth.Value == pytest.approx(1.0)  # not written before OK
    close_with(panel, Ok)
    assert slot_ops(job) == [op] and op.Depth.Value == pytest.approx(2.0)
    assert op.Region == "G7.1 C20. J-4. R2. K0.2 L2"
    assert min(c.Parameters["X"] for c in op.Path.Commands if c.Name == "G1") == pytest.approx(18.0)


def test_an_invalid_value_refuses_ok_with_the_ops_message(shop):
    doc, job = shop
    shaft, line = job.Model.Group
    panel, page = run_command(doc, [(shaft, "Face1"), (line, "Edge1")])
    (op,) = slot_ops(job)
    replan(page, page.field("Allowance"), "1.5 mm")
    assert page.error == "Allowance=1.5: must be less than Depth=1.0"
    label = widgets.child(page.form, "errorLabel")
    assert label.isVisible() and label.text() == page.error and "\n" not in page.error
    assert page.field("Allowance").property("grooveInvalid") is True
    assert page.picture.path is None  # nothing drawn for a slot that cannot be cut
    ok_enabled = task_button(panel, Ok).isEnabled()
    assert not ok_enabled
    screenshot("%s-cylinder-slot-invalid" % version())
    refused = panel.accept() is False  # if OK were reached anyway
    still_open = bool(FreeCADGui.Control.activeDialog())
    assert refused and still_open
    assert op.Allowance.Value == pytest.approx(0.1)
    replan(page, page.field("Allowance"), "0.3 mm")
    valid = page.error is None and task_button(panel, Ok).isEnabled()
    unmarked = page.field("Allowance").property("grooveInvalid") is not True
    assert valid and unmarked
    close_with(panel, Ok)
    assert op.Allowance.Value == pytest.approx(0.3)


def test_cancel_of_a_new_op_leaves_no_op(shop):
    doc, job = shop
    shaft, line = job.Model.Group
    before = sorted(o.Name for o in doc.Objects)
    panel, page = run_command(doc, [(shaft, "Face1"), (line, "Edge1")])
    assert len(slot_ops(job)) == 1
    replan(page, page.field("Depth"), "3 mm")
    close_with(panel, Cancel)
    assert slot_ops(job) == []
    assert sorted(o.Name for o in doc.Objects) == before


def test_command_with_face_and_sketch_uses_the_sketch_as_the_path(shop):
    import Sketcher

    doc, job = shop
    shaft, _line = job.Model.Group
    assert Sketcher
    sketch = doc.addObject("Sketcher::SketchObject", "Developed")
    sketch.addGeometry(Part.LineSegment(V(5, 10, 0), V(45, 10, 0)))  # a keyway along Z at s = 10
    doc.recompute()
    panel, page = run_command(doc, [(shaft, "Face1"), (sketch, None)])
    (op,) = slot_ops(job)
    assert op.DevelopedSketch == sketch
    assert page.form.developedSketch.currentData() == sketch.Name
    assert page.error is None
    assert centre(page) == [(5.0, pytest.approx(10.0, abs=1e-3)), (45.0, pytest.approx(10.0, abs=1e-3))]
    # back to the edges in Base Geometry: there are none, which the panel says
    before = page.replans
    page.form.developedSketch.setCurrentIndex(0)
    wait_for(lambda: page.replans > before, what="the preview")
    assert page.error.startswith("Base: no edge of the slot's path")
    assert not task_button(panel, Ok).isEnabled()
    page.form.developedSketch.setCurrentIndex(page.form.developedSketch.findData(sketch.Name))
    wait_for(lambda: page.error is None, what="the sketch again")
    close_with(panel, Ok)
    assert op.DevelopedSketch.Name == sketch.Name and not op.Proxy.error


def test_double_click_reopens_the_panel_and_cancel_keeps_the_op(shop):
    from freecad_groove import make_cylinder_slot

    doc, job = shop
    shaft, line = job.Model.Group
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], depth=1.5, passes=3, allowance=0.2, retract=2)
    FreeCADGui.getDocument(doc.Name).setEdit(op.Name)  # what a double-click in the tree does
    panel = wait_for(lambda: open_slot_panel(doc), what="the panel")
    page = panel.op_page
    wait_for(lambda: page.replans > 0, what="the preview")
    assert page.field("Depth").property("rawValue") == pytest.approx(1.5)
    assert page.field("Passes").value() == 3
    assert page.field("Retract").property("rawValue") == pytest.approx(2.0)
    replan(page, page.field("Passes"), "4")
    assert len(page.picture.path.pass_radii) == 5
    wait_for(lambda: buttons_shown(panel), what="the panel's buttons")
    close_with(panel, Cancel)
    assert slot_ops(job) == [op] and op.Passes == 3


def test_the_reach_check_shows_in_the_panel(shop):
    """The end mill's flutes (CuttingEdgeHeight 3) refuse Depth 4 on the Depth field; a 3 mm long end mill's
    holder inside the stock's radius is an amber warning that leaves OK enabled."""
    doc, job = shop
    shaft, line = job.Model.Group
    tool = job.Tools.Group[0].Tool
    tool.CuttingEdgeHeight = 3.0
    tool.Length = 3.0
    panel, page = run_command(doc, [(shaft, "Face1"), (line, "Edge1")])
    warning = widgets.child(page.form, "warningLabel")
    assert page.error is None and len(page.warnings) == 1 and "check that the holder clears the part" in \
        page.warnings[0]
    shown = warning.isVisible() and warning.text() == "Warning: " + page.warnings[0]
    assert shown and warning.styleSheet() == widgets.WARNING_STYLE
    assert task_button(panel, Ok).isEnabled()
    replan(page, page.field("Depth"), "4 mm")
    assert page.error == ("Depth=4 mm: deeper than the cutting edge of %s (CuttingEdgeHeight=3 mm): the shank "
                          "would rub the slot's walls" % tool.Label)
    marked = page.field("Depth").property("grooveInvalid") is True
    assert marked and not task_button(panel, Ok).isEnabled() and page.warnings == []
    close_with(panel, Cancel)
    assert slot_ops(job) == []


def test_a_tool_controller_picked_in_the_panel_sets_the_slot_width_and_is_written_on_ok(shop):
    """A second tool controller (a 3 mm wide bit: its Diameter is 3) picked in the combo: the picture's slot is
    3 mm wide at once, the op keeps its own until OK."""
    from freecad_groove.freecad import toolbit

    doc, job = shop
    shaft, line = job.Model.Group
    narrow = toolbit.make_grooving_tool_controller(job, 3.0, 0.0, CuttingEdgeHeight=10.0)
    narrow.HorizFeed = "120 mm/min"
    first = job.Tools.Group[0]
    panel, page = run_command(doc, [(shaft, "Face1"), (line, "Edge1")])
    (op,) = slot_ops(job)
    assert op.ToolController == first and page.picture.path.width == pytest.approx(5.0)
    before = page.replans
    combo = page.form.toolController
    combo.setCurrentIndex(combo.findText(narrow.Label))
    wait_for(lambda: page.replans > before, what="the preview")
    assert page.error is None and page.picture.path.width == pytest.approx(3.0)
    assert op.ToolController == first
    close_with(panel, Ok)
    assert op.ToolController == narrow and op.SlotWidth.Value == pytest.approx(3.0)


def test_a_look_at_a_saved_documents_op_leaves_it_unmodified(shop):
    """Double-click, Cancel: the document is as it was, its modified flag too (CAM's panel hides the model and
    shows the op while open); after an Apply the flag stays set (Cancel undid the value, the flag is not worth
    reasoning about then)."""
    from freecad_groove import make_cylinder_slot

    doc, job = shop
    shaft, line = job.Model.Group
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")])
    gui_doc = FreeCADGui.getDocument(doc.Name)
    gui_doc.Modified = False  # as just saved
    looks = {o.Name: o.ViewObject.Visibility for o in doc.Objects if o.ViewObject is not None}
    for apply in (False, True):
        gui_doc.setEdit(op.Name)
        panel = wait_for(lambda: open_slot_panel(doc), what="the panel")
        wait_for(lambda p=panel: p.op_page.replans > 0 and buttons_shown(p), what="the preview")
        if apply:
            replan(panel.op_page, panel.op_page.field("Depth"), "1.5 mm")
            task_button(panel, Apply).click()
            process(0.1)
        close_with(panel, Cancel)
        after = {o.Name: o.ViewObject.Visibility for o in doc.Objects if o.ViewObject is not None}
        modified = bool(gui_doc.Modified)
        assert after == looks and modified == apply
    assert op.Depth.Value == pytest.approx(1.0)  # Cancel undoes what Apply wrote (CAM aborts the panel's transaction)
