"""The Groove panel leaves no PySide wrapper of a widget FreeCAD deletes
(FreeCAD 1.1 and 1.0, under Xvfb; freecad_groove/gui/qt_wrappers.py).

FreeCAD makes the task dialog's OK/Cancel box in C++ and deletes it with the
dialog; a wrapper of it still mapped to its address was handed out for the
next panel's widgets built there (a spin box read as a QDialogButtonBox in
1.1, a segfault in 1.0).
"""

import gc
import weakref

import FreeCADGui
import pytest
from gui_helpers import close_shop, make_gui_shop, open_panel, process, task_button, wait_for
from parts import face_name
from PySide import QtGui

from freecad_groove import make_groove
from freecad_groove.gui.qt_wrappers import shiboken

Ok, Cancel = QtGui.QDialogButtonBox.Ok, QtGui.QDialogButtonBox.Cancel


@pytest.fixture
def shop():
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc, job, model = make_gui_shop("Wrappers")
    op = make_groove(job, (model, face_name(model.Shape, "cylinder")), width=4.5, depth=1.5, position=6, tool_width=3)
    yield doc, op
    close_shop(doc)


def edit(doc, op):
    FreeCADGui.getDocument(doc.Name).setEdit(op.Name)
    panel = wait_for(lambda: open_panel(doc), what="the Groove task panel")
    wait_for(lambda: panel.groove_page.replans > 0, what="the preview")
    wait_for(lambda: panel.buttonBox.button(Cancel).isVisible(), what="the panel's buttons")
    return panel


@pytest.mark.parametrize("button", [Cancel, Ok], ids=["cancel", "ok"])
def test_closing_the_panel_forgets_the_button_box_freecad_deletes(shop, button):
    doc, op = shop
    panel = edit(doc, op)
    box = panel.buttonBox
    buttons = box.findChildren(QtGui.QPushButton)
    assert shiboken.isValid(box) and buttons
    task_button(panel, button).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    # Booleans first: pytest's report of a failed assert would print a stale wrapper, which crashes.
    released = panel.buttonBox is None
    box_forgotten = not shiboken.isValid(box)  # a stale wrapper would still claim its address
    buttons_forgotten = not any(shiboken.isValid(b) for b in buttons)
    assert released, "the closed panel still holds its button box"
    assert box_forgotten, "the button box FreeCAD deleted still has a wrapper"
    assert buttons_forgotten, "a button FreeCAD deleted still has a wrapper"


def test_a_panel_opened_while_the_last_one_is_still_held_reads_its_own_widgets(shop):
    doc, op = shop
    held = []  # as a test, or Python's garbage before it collects a panel, holds them
    for _round in range(4):
        panel = edit(doc, op)
        assert panel.groove_page.values()["Width"] == pytest.approx(4.5)
        held.append(panel)
        task_button(panel, Cancel).click()
        wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
        process(0.05)


@pytest.mark.parametrize("button", [Cancel, Ok], ids=["cancel", "ok"])
def test_closing_the_panel_forgets_the_widgets_its_pages_hold(shop, button):
    # The pages hold wrappers of widgets Qt made from the .ui files (the fields, the picture's label) until the
    # garbage collector frees the closed panel: FreeCAD 1.0 segfaulted reading a Groove field's text in
    # test_model_panel_cases, the wrapper handed out for it being the last panel's label at that address.
    doc, op = shop
    panel = edit(doc, op)
    page = panel.groove_page
    held = list(page.fields.widgets.values()) + [page.diagram.label, page.form]
    assert all(shiboken.isValid(w) and not shiboken.createdByPython(w) for w in held)
    task_button(panel, button).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    still_valid = sum(1 for w in held if shiboken.isValid(w))  # a count: a stale wrapper must not be printed
    assert still_valid == 0, "%d widgets FreeCAD deleted still have wrappers" % still_valid


def test_a_new_panel_frees_the_closed_panels_first(shop):
    # A closed panel's pages live on in reference cycles, holding wrappers of the widgets and list items FreeCAD
    # deleted; the next panel's widgets built at those addresses were handed them (FreeCAD 1.0: the Groove page's
    # error label as a QTableWidgetItem, the panel did not open). Python's collector is off here: it runs when it
    # likes, which made the crash come and go.
    doc, op = shop
    gc.disable()
    try:
        panel = edit(doc, op)
        closed_page = weakref.ref(panel.groove_page)
        task_button(panel, Cancel).click()
        wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
        process(0.05)
        del panel
        assert closed_page() is not None  # held by its cycles: only the collector frees it
        panel = edit(doc, op)
        assert closed_page() is None, "the closed panel's page outlived the opening of the next"
        task_button(panel, Cancel).click()
        wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    finally:
        gc.enable()
