"""Opening the Groove panel to look does not mark a saved document modified
(FreeCAD 1.1 and 1.0, under Xvfb).

CAM's op panel shows the op and hides the Job's model and stock while it is
open, and puts their Visibility back on closing: FreeCAD counts that as a
modification, so a machinist who only looked was asked to save. The panel
keeps the document unmodified when it changed nothing in it (Cancel, or OK with
no value changed); a changed value, Apply, or a new tool controller still mark
it modified.
"""

import FreeCAD
import FreeCADGui
import pytest
from gui_helpers import close_shop, make_gui_shop, open_panel, process, task_button, type_into, wait_for
from parts import face_name
from PySide import QtGui

from freecad_groove import make_groove

Ok, Apply, Cancel = QtGui.QDialogButtonBox.Ok, QtGui.QDialogButtonBox.Apply, QtGui.QDialogButtonBox.Cancel


@pytest.fixture
def saved(tmp_path):
    """(document, its Groove op, its Gui document): saved, closed and opened again, unmodified."""
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc, job, model = make_gui_shop("LookOnly")
    make_groove(job, (model, face_name(model.Shape, "cylinder")), width=4.5, depth=1.5, position=6, tool_width=3)
    model.ViewObject.Visibility = True  # as CAM's GUI leaves a Job: its model's clone shown, the part hidden
    doc.getObject("Shaft").ViewObject.Visibility = False
    doc.recompute()
    path = str(tmp_path / "look_only.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    process()
    doc = FreeCAD.openDocument(path)
    process(0.1)
    gui_doc = FreeCADGui.getDocument(doc.Name)
    assert not gui_doc.Modified
    yield doc, doc.getObject("Groove"), gui_doc
    close_shop(doc)


def visibilities(doc):
    return {o.Name: o.ViewObject.Visibility for o in doc.Objects if getattr(o, "ViewObject", None) is not None}


def edit(doc, op):
    """Open the op's panel as a double-click in the tree does; returns it once its preview is drawn."""
    FreeCADGui.getDocument(doc.Name).setEdit(op.Name)
    panel = wait_for(lambda: open_panel(doc), what="the Groove task panel")
    wait_for(lambda: panel.groove_page.replans > 0, what="the preview")
    return panel


def close_with(panel, button):
    task_button(panel, button).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)


@pytest.mark.parametrize("button", [Cancel, Ok], ids=["cancel", "ok"])
def test_opening_and_closing_the_panel_keeps_a_saved_document_unmodified(saved, button):
    doc, op, gui_doc = saved
    before = visibilities(doc)
    edit(doc, op)
    assert gui_doc.Modified  # CAM's panel changed the Visibility of the op, model and stock
    close_with(open_panel(doc), button)
    assert visibilities(doc) == before
    assert not gui_doc.Modified
    assert op.Width.Value == pytest.approx(4.5)


def test_a_changed_value_marks_the_document_modified(saved):
    doc, op, gui_doc = saved
    panel = edit(doc, op)
    page = panel.groove_page
    before = page.replans
    type_into(page.field("Width"), "5 mm")
    wait_for(lambda: page.replans > before, what="the preview after typing")
    close_with(panel, Ok)
    assert op.Width.Value == pytest.approx(5.0)
    assert gui_doc.Modified


def test_apply_then_cancel_leaves_the_document_modified(saved):
    doc, op, gui_doc = saved
    panel = edit(doc, op)
    page = panel.groove_page
    before = page.replans
    type_into(page.field("Depth"), "2 mm")
    wait_for(lambda: page.replans > before, what="the preview after typing")
    task_button(panel, Apply).click()
    process(0.1)
    close_with(panel, Cancel)
    assert gui_doc.Modified


def test_a_document_modified_before_stays_modified(saved):
    doc, op, gui_doc = saved
    op.Label = "Groove renamed"
    process()
    assert gui_doc.Modified
    close_with(edit(doc, op), Cancel)
    assert gui_doc.Modified
