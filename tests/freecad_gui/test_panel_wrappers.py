"""The Groove panel leaves no PySide wrapper of a widget FreeCAD deletes
(FreeCAD 1.1 and 1.0, under Xvfb; freecad_groove/gui/qt_wrappers.py).

FreeCAD makes the task dialog's OK/Cancel box in C++ and deletes it with the
dialog; a wrapper of it still mapped to its address was handed out for the
next panel's widgets built there (a spin box read as a QDialogButtonBox in
1.1, a segfault in 1.0).
"""

import gc
import os
import weakref

import FreeCADGui
import pytest
from gui_helpers import close_shop, make_gui_shop, open_panel, process, task_button, wait_for
from parts import face_name
from PySide import QtCore, QtGui

from freecad_groove import make_groove
from freecad_groove.gui import PANELS, qt_wrappers
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


LIST_FORM = """<?xml version="1.0" encoding="UTF-8"?>
<ui version="4.0"><class>Form</class>
 <widget class="QWidget" name="Form"><layout class="QVBoxLayout" name="layout">
  <item><widget class="QListWidget" name="offsets">
   <item><property name="text"><string>G54</string></property></item>
   <item><property name="text"><string>G55</string></property></item>
  </widget></item>
  <item><widget class="QTableWidget" name="tools"><property name="rowCount"><number>1</number></property>
   <property name="columnCount"><number>2</number></property></widget></item>
 </layout></widget></ui>
"""


def made_by_qt_form(tmp_path, name):
    """A form Qt builds from a .ui file (a list of two items, a table of one row), as CAM's panels are."""
    path = tmp_path / (name + ".ui")
    path.write_text(LIST_FORM)
    form = FreeCADGui.PySideUic.loadUi(str(path))
    table = form.findChild(QtGui.QTableWidget, "tools")
    table.setItem(0, 0, QtGui.QTableWidgetItem("T1"))
    return form


def delete_in_qt(widget):
    """Qt deletes ``widget`` (as FreeCAD deletes a closed dialog): shiboken does not hear of it."""
    widget.deleteLater()
    QtCore.QCoreApplication.sendPostedEvents(None, QtCore.QEvent.DeferredDelete)


def test_a_new_panel_forgets_the_items_of_list_widgets_freecad_deleted(tmp_path):
    # CAM's Job panel (FreeCAD 1.0) reads its work offset list and tool table item by item and lives on after
    # FreeCAD deleted its dialog: the item wrappers, which PySide 2's wrapper of the list keeps, stayed mapped
    # to freed addresses, and a later panel's widgets were handed them (the Apply button as a
    # QListWidgetItem). A new panel forgets them first. (PySide 6's list keeps no item wrapper: none is left.)
    closed, kept = made_by_qt_form(tmp_path, "closed"), made_by_qt_form(tmp_path, "kept")
    closed_list, kept_list = closed.findChild(QtGui.QListWidget), kept.findChild(QtGui.QListWidget)
    items = [weakref.ref(closed_list.item(row)) for row in range(2)]  # taken as CAM takes them, not held
    table_item = weakref.ref(closed.findChild(QtGui.QTableWidget).item(0, 0))
    kept_items = [kept_list.item(0), kept.findChild(QtGui.QTableWidget).item(0, 0)]
    delete_in_qt(closed)
    qt_wrappers.collect_closed_panels()
    left = sum(1 for ref in items + [table_item] if ref() is not None and shiboken.isValid(ref()))
    left += shiboken.isValid(closed_list)
    kept_valid = all(shiboken.isValid(w) for w in [kept_list] + kept_items)
    texts = [kept_list.item(0).text(), kept_items[1].text()]
    delete_in_qt(kept)
    qt_wrappers.collect_closed_panels()
    assert left == 0, "%d wrappers of the closed form's list, items and table item are still mapped" % left
    assert kept_valid and texts == ["G54", "T1"]


def test_a_window_whose_wrapper_says_it_is_gone_makes_the_new_panel_forget_nothing(monkeypatch, tmp_path):
    # FreeCAD 1.0 handed out, among its windows, a wrapper that said its object was gone (test_saved_documents):
    # reading its children raised and the panel did not open. Its views cannot be told from closed ones then.
    gone = QtGui.QWidget()
    shiboken.delete(gone)
    form = made_by_qt_form(tmp_path, "closed")
    held = weakref.ref(form.findChild(QtGui.QListWidget).item(0))
    delete_in_qt(form)
    real = QtGui.QApplication.topLevelWidgets
    monkeypatch.setattr(QtGui.QApplication, "topLevelWidgets", staticmethod(lambda: [gone] + list(real())))
    forgotten = qt_wrappers.forget_closed_views()
    qt_wrappers.collect_closed_panels()  # and the panel opens: no error
    monkeypatch.undo()
    qt_wrappers.collect_closed_panels()
    assert forgotten == 0
    assert held() is None or not shiboken.isValid(held()), "forgotten once the windows can be read again"


def test_form_rows_are_chosen_past_a_wrapper_that_says_its_widget_is_gone():
    # FreeCAD 1.0 once handed out, for a child of the Plunge grind form being built, a wrapper saying its object
    # was gone: choose_form_rows raised RuntimeError and the panel did not open (1.1 crashed at the same place).
    from freecad_groove.gui.widgets import FORM_ROW, choose_form_rows

    form = QtGui.QWidget()
    layout = QtGui.QFormLayout(form)
    layout.addRow(QtGui.QLabel("Wheel width", form), QtGui.QLineEdit(form))
    gone = QtGui.QLabel("gone")
    shiboken.delete(gone)
    real = form.children
    form.children = lambda: [gone] + list(real())
    choose_form_rows(layout)
    assert layout.rowWrapPolicy() == QtGui.QFormLayout.DontWrapRows  # a short label and a field fit FORM_ROW
    assert FORM_ROW >= 100
    # a label wider than a row: every label above its field, the same walk
    holder = QtGui.QWidget()
    wide = QtGui.QFormLayout(holder)
    wide.addRow(QtGui.QLabel("W" * 60, holder), QtGui.QLineEdit(holder))
    choose_form_rows(wide)
    assert wide.rowWrapPolicy() == QtGui.QFormLayout.WrapAllRows


def test_the_buttons_freecad_makes_are_read_past_wrappers_of_deleted_objects_at_their_addresses():
    # FreeCAD 1.0 segfaulted enabling the OK button in modifyStandardButtons: PySide handed the new button out
    # through a wrapper of another type still mapped to its address. Such a wrapper is made here by hand.
    class Base:
        def modifyStandardButtons(self, box):
            self.read = [box.button(b) for b in (Ok, Cancel)]

    class Panel(qt_wrappers.ForgetsButtonBox, Base):
        pass

    box = QtGui.QDialogButtonBox(Ok | Cancel)  # its buttons are made in C++, as FreeCAD's are
    box.accepted.connect(lambda: None)  # PySide keeps the signal in the box's __dict__: no wrapper to forget
    addresses = []
    for b in (Ok, Cancel):
        button = box.button(b)
        addresses.append(shiboken.getCppPointer(button)[0])
        shiboken.invalidate(button)  # the button's own wrapper no longer mapped: as if never taken
    stale = [shiboken.wrapInstance(address, QtGui.QLabel) for address in addresses]
    assert isinstance(box.button(Ok), QtGui.QLabel)  # what PySide hands out now, without the panel's care
    panel = Panel()
    panel.modifyStandardButtons(box)
    read_right = [isinstance(button, QtGui.QPushButton) for button in panel.read]
    qt_wrappers.forget(stale)
    assert read_right == [True, True], "a button was handed out through another object's wrapper"


def test_the_picture_reads_nothing_of_an_event_handed_out_through_another_objects_wrapper():
    # FreeCAD 1.0 segfaulted in ScaledPicture.eventFilter reading the type of an event handed out that way.
    from freecad_groove.gui.widgets import ScaledPicture

    read = []

    class Item(QtGui.QListWidgetItem):  # stands for a deleted list item's wrapper at the event's address
        def type(self):
            read.append("type")
            return 0

    label = QtGui.QLabel()
    svg = os.path.join(PANELS, "groove_section.svg")
    picture = ScaledPicture(label, svg, 200, 100)
    item = Item()
    filtered = picture.eventFilter(label, item)
    assert read == [] and filtered is False
    views = QtGui.QListWidget()
    views.addItems(["G54"])  # an item Qt makes: its wrapper is one PySide may hand out stale
    made_by_qt = views.item(0)
    picture.eventFilter(label, made_by_qt)
    assert not shiboken.isValid(made_by_qt), "forgotten: the next event at that address gets its own wrapper"
    label.resize(80, 60)
    picture.eventFilter(label, QtGui.QResizeEvent(QtCore.QSize(80, 60), QtCore.QSize(200, 100)))
    assert picture.drawn == 80


def test_a_new_panel_forgets_the_wrappers_of_widgets_qt_deleted_that_python_still_holds(tmp_path):
    # CAM's Job panel leaves the wrappers of its form, its tab widget and its 16 setup sheet op forms held after
    # FreeCAD deleted its dialog; CAM's next Job panel was handed them for its own widgets and failed ("Internal
    # C++ object (QTableView) already deleted", or a segfault). Here a form Qt made, held in Python, deleted by Qt.
    closed, kept = made_by_qt_form(tmp_path, "closed"), made_by_qt_form(tmp_path, "kept")
    held = [closed, closed.findChild(QtGui.QListWidget), kept, kept.findChild(QtGui.QListWidget)]
    delete_in_qt(closed)
    forgotten = qt_wrappers.forget_deleted_widgets()
    valid = [shiboken.isValid(w) for w in held]
    text = kept.findChild(QtGui.QTableWidget).item(0, 0).text()
    delete_in_qt(kept)
    qt_wrappers.forget_deleted_widgets()
    assert valid == [False, False, True, True] and forgotten >= 1, (valid, forgotten)
    assert text == "T1"


def test_a_deleted_widget_s_wrapper_that_keeps_a_live_one_is_left(tmp_path, monkeypatch):
    # Invalidating a wrapper invalidates the wrappers it keeps: one handed out again for a widget built since
    # (in use) must stay valid, so its keeper is left.
    closed, live = made_by_qt_form(tmp_path, "closed"), made_by_qt_form(tmp_path, "live")
    delete_in_qt(closed)
    real = qt_wrappers._wrappers_kept_by
    monkeypatch.setattr(qt_wrappers, "_wrappers_kept_by", lambda w: [live] if w is closed else real(w))
    qt_wrappers.forget_deleted_widgets()
    left = shiboken.isValid(closed)
    monkeypatch.undo()
    qt_wrappers.forget_deleted_widgets()
    gone = not shiboken.isValid(closed)
    assert left and gone and shiboken.isValid(live)
    delete_in_qt(live)
