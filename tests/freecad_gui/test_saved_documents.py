"""Documents saved from FreeCAD 1.1's GUI by earlier code, opened in
FreeCAD's GUI (1.1 and 1.0, under Xvfb) with this code.

tests/freecad/data/groove_gui_saved_at_bfb45ff.FCStd (the previous release,
commit bfb45ff) stores the class paths only a GUI document and a tool bit
hold: the op's view provider ``freecad_groove.gui.task_panel.ViewProvider``
with its page class ``freecad_groove.gui.task_panel.GroovePage``, and the
grooving blade's tool bit ``freecad_groove.freecad.toolbit.ToolBitGrooving``
(a FreeCAD 1.1 class: FreeCAD 1.0 opens the document, reports that it cannot
restore the bit's proxy, and keeps the bit's Width and CornerRadius, which
the op reads).

tests/freecad/data/ops_saved_at_3d18f68.FCStd (commit 3d18f68, before the
ops moved into freecad_groove/ops/; made by
tests/freecad/data/make_saved_documents.py) stores the view providers of a
Groove, a Cylinder slot and a Plunge grind, and the page classes of the
Groove's and the Plunge grind's, by their paths of then: the shims in
freecad_groove/gui/ keep them.
"""

import math
import os

import FreeCADGui
import PathScripts.PathUtils as PathUtils
import pytest
from gui_helpers import cancel_open_panel, open_panel, process, screenshot, task_button, version, wait_for
from PySide import QtGui

# isort: split
# (gui_helpers has put tests/freecad on sys.path)
from documents import DATA, opened, path_commands, stored_classes, without_chip_break_reentries

from freecad_groove.freecad import toolbit
from freecad_groove.freecad.addon_op import op_error
from freecad_groove.ops.grind.gui.panel import PlungeGrindPage
from freecad_groove.ops.grind.gui.view import ViewProviderPlungeGrind
from freecad_groove.ops.groove.gui import ICON
from freecad_groove.ops.groove.gui.panel import GroovePage
from freecad_groove.ops.groove.gui.view import ViewProviderGroove
from freecad_groove.ops.groove.op import ObjectGroove
from freecad_groove.ops.slot.gui.panel import SlotPage
from freecad_groove.ops.slot.gui.view import ViewProviderCylinderSlot

GUI_AT_BFB45FF = os.path.join(DATA, "groove_gui_saved_at_bfb45ff.FCStd")
# What make_saved_documents.py made: the blade, and the groove on the R20 cylinder.
BLADE_WIDTH, BLADE_CORNER_RADIUS = 2.5, 0.1
GROOVE = {"Position": 5.0, "Width": 4.0, "Depth": 2.0, "Infeed": 1.0}


@pytest.fixture
def saved():
    """(document, its Groove op) as bfb45ff saved them."""
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    with opened(GUI_AT_BFB45FF) as doc:
        process()
        yield doc, doc.getObject("Groove")
        cancel_open_panel()
    process()


def test_the_op_keeps_this_codes_view_provider(saved):
    doc, op = saved
    view_provider = op.ViewObject.Proxy
    assert type(view_provider) is ViewProviderGroove
    assert view_provider.getIcon() == ICON
    # what the view provider stored: the page FreeCAD builds to edit the op
    assert (view_provider.OpPageModule, view_provider.OpPageClass) == ("freecad_groove.gui.task_panel", "GroovePage")


def test_the_op_recomputes_to_the_path_it_saved(saved):
    doc, op = saved
    assert isinstance(op.Proxy, ObjectGroove)
    path = path_commands(op)
    op.touch()
    doc.recompute()
    assert op_error(op) is None, op_error(op)
    assert any(name == "G1" for name, _words in path_commands(op))
    # 2 deep in infeeds of 1: each plunge breaks the chip once and, since
    # issue 9, rapids back down its slot after it. Since issue 10 the path
    # starts at the safe start point, 1 mm (the clearance) outside the radius
    # of the saved Job's stock (its box's corner) and beyond its +Z end, and
    # comes down in Z outside it to the start point's Z before moving in X,
    # where bfb45ff's went out to X21 from wherever the tool was; at the end
    # it goes back out in X and up in Z to the safe start point, where
    # bfb45ff's stayed at the start point. The rest is as saved.
    assert path[3:5] == [("G0", {"X": 21.0}), ("G0", {"X": 21.0, "Z": 22.5})]
    stock = PathUtils.findParentJob(op).Stock.Shape
    safe_x = round(max(math.hypot(v.X, v.Y) for v in stock.Vertexes) + 1.0, 6)
    safe_z = round(stock.BoundBox.ZMax + 1.0, 6)
    path[3:4] = [("G0", {"X": safe_x, "Z": safe_z}), ("G0", {"X": safe_x, "Z": 22.5})]
    path += [("G0", {"X": safe_x, "Z": 22.5}), ("G0", {"X": safe_x, "Z": safe_z})]
    now = path_commands(op)
    assert without_chip_break_reentries(now) == path
    assert len(now) > len(path)


def test_the_tool_bit_still_gives_the_blade_size(saved):
    doc, op = saved
    bit = op.ToolController.Tool
    assert (bit.Width.Value, bit.CornerRadius.Value) == (BLADE_WIDTH, BLADE_CORNER_RADIUS)
    if toolbit.NEW_TOOLBITS:
        assert isinstance(bit.Proxy, toolbit.ToolBitGrooving)
    else:  # FreeCAD 1.0 has no asset tool bits, so no such class: the bit comes back without a proxy
        assert getattr(bit, "Proxy", None) is None
    (_call, settings, _start), = op.Proxy.cycles(op)
    assert (settings.tool.width, settings.tool.corner_radius) == (BLADE_WIDTH, BLADE_CORNER_RADIUS)


def test_double_click_opens_the_groove_panel(saved):
    doc, op = saved
    FreeCADGui.getDocument(doc.Name).setEdit(op.Name)  # what a double-click in the tree does
    panel = wait_for(lambda: open_panel(doc), what="the Groove task panel")
    page = panel.groove_page
    assert type(page) is GroovePage
    for prop, value in GROOVE.items():
        assert page.field(prop).property("rawValue") == pytest.approx(value), prop
    wait_for(lambda: page.replans > 0, what="the preview")
    assert page.error is None and len(page.preview.sections) == 1
    assert not page.field("ToolWidth").isEnabled()  # the tool bit gives the width
    screenshot("%s-saved-at-bfb45ff" % version())
    task_button(panel, QtGui.QDialogButtonBox.Cancel).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    assert doc.getObject(op.Name) is op and op.Width.Value == GROOVE["Width"]


# ------------------------------------------------------------------ the ops as commit 3d18f68 saved them

OPS_AT_3D18F68 = os.path.join(DATA, "ops_saved_at_3d18f68.FCStd")
# op -> (the view provider's class path the document stores, the class it must open as now,
#        the page class stored in the view provider's state then (None: it keeps none), the page class now)
STORED_VIEWS = {
    "Groove": ("freecad_groove.gui.task_panel.ViewProvider", ViewProviderGroove,
               ("freecad_groove.gui.task_panel", "GroovePage"), GroovePage),
    "CylinderSlot": ("freecad_groove.gui.slot_view.ViewProviderCylinderSlot", ViewProviderCylinderSlot, None,
                     SlotPage),
    "PlungeGrind": ("freecad_groove.gui.grind_view.ViewProviderPlungeGrind", ViewProviderPlungeGrind,
                    ("freecad_groove.gui.grind_panel", "PlungeGrindPage"), PlungeGrindPage),
}


@pytest.fixture
def ops_saved():
    """The document 3d18f68 saved, open in the GUI."""
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    with opened(OPS_AT_3D18F68) as doc:
        process()
        yield doc
        cancel_open_panel()
    process()


def _panel_of(op):
    """The open task panel of ``op`` (its view provider's), or None."""
    panel = getattr(op.ViewObject.Proxy, "panel", None)
    return panel if FreeCADGui.Control.activeDialog() else None


def test_the_ops_saved_before_the_move_keep_this_codes_view_providers(ops_saved):
    stored = stored_classes(OPS_AT_3D18F68, "GuiDocument.xml", "ViewProvider")
    for name, (path, cls, page, _page_cls) in STORED_VIEWS.items():
        assert stored[name] == path
        view_provider = ops_saved.getObject(name).ViewObject.Proxy
        assert type(view_provider) is cls, name
        if page is not None:  # what the view provider stored: the page FreeCAD builds to edit the op
            assert (view_provider.OpPageModule, view_provider.OpPageClass) == page


@pytest.mark.parametrize("name", list(STORED_VIEWS))
def test_double_click_opens_the_panel_of_an_op_saved_before_the_move(ops_saved, name):
    op = ops_saved.getObject(name)
    FreeCADGui.getDocument(ops_saved.Name).setEdit(op.Name)  # what a double-click in the tree does
    panel = wait_for(lambda: _panel_of(op), what="the %s task panel" % name)
    page = panel.op_page
    assert type(page) is STORED_VIEWS[name][3]
    wait_for(lambda: page.replans > 0, what="the check of its values")
    assert page.error is None, page.error
    screenshot("%s-%s-saved-at-3d18f68" % (version(), name))
    task_button(panel, QtGui.QDialogButtonBox.Cancel).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    assert ops_saved.getObject(name) is op and op_error(op) is None


def test_the_ops_saved_before_the_move_are_saved_again_with_their_view_providers_paths_now(ops_saved, tmp_path):
    again = tmp_path / "again.FCStd"
    ops_saved.saveAs(str(again))
    stored = stored_classes(again, "GuiDocument.xml", "ViewProvider")
    for name, (_before, cls, _page, _page_cls) in STORED_VIEWS.items():
        assert stored[name] == "%s.%s" % (cls.__module__, cls.__name__)
        assert stored[name].startswith("freecad_groove.ops.")
