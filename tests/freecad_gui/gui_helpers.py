"""Driving FreeCAD's GUI from tests the way a user would: key presses into
fields, clicks on buttons, waiting on the Qt event loop; and screenshots.

Runs inside FreeCAD's GUI (tests/freecad_gui/start.py). Screenshots go to
$FREECAD_GROOVE_SHARE/$FREECAD_GROOVE_SCREENSHOTS (default "screenshots").
"""

import os
import time

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

KEYS = {".": QtCore.Qt.Key_Period, " ": QtCore.Qt.Key_Space, "-": QtCore.Qt.Key_Minus, ",": QtCore.Qt.Key_Comma}


def process(seconds=0.0):
    """Run the event loop for ``seconds`` (at least once)."""
    end = time.monotonic() + seconds
    while True:
        QtGui.QApplication.processEvents()
        if time.monotonic() >= end:
            return
        time.sleep(0.005)


def wait_for(predicate, timeout=5.0, what="condition"):
    """Run the event loop until predicate() is true; AssertionError after ``timeout`` s."""
    end = time.monotonic() + timeout
    while True:
        QtGui.QApplication.processEvents()
        value = predicate()
        if value:
            return value
        if time.monotonic() > end:
            raise AssertionError("timed out after %.1f s waiting for %s" % (timeout, what))
        time.sleep(0.005)


def _key(char):
    if char.isdigit():
        return QtCore.Qt.Key_0 + int(char)
    if char.isalpha():
        return QtCore.Qt.Key_A + (ord(char.upper()) - ord("A"))
    return KEYS[char]


def press(widget, key, text=""):
    for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
        QtGui.QApplication.sendEvent(widget, QtGui.QKeyEvent(kind, key, QtCore.Qt.NoModifier, text))


def type_into(widget, text, leave=True):
    """Replace a field's text by typing ``text`` key by key, then Tab to the
    next field, as a user would. (Not Enter: in a task panel Enter presses OK.)"""
    widget.setFocus()
    widget.selectAll()
    for char in text:
        press(widget, _key(char), char)
    if leave:
        press(widget, QtCore.Qt.Key_Tab)
    process()


def choose(combo, value):
    """Pick the combo box entry whose data (or text) is ``value``, as a user would."""
    index = combo.findData(value)
    if index < 0:
        index = combo.findText(value)
    assert index >= 0, "%s has no entry %r" % (combo.objectName(), value)
    combo.setCurrentIndex(index)
    process()


def task_button(panel, which):
    """The task panel's OK/Apply/Cancel button (QDialogButtonBox.StandardButton).
    (From the panel: searching the main window can reach boxes of closed
    dialogs whose C++ side is gone, which crashes PySide2.)"""
    button = panel.buttonBox.button(which)
    assert button is not None and button.isVisible(), "no visible task dialog button %s" % which
    return button


def screenshot(name):
    """Save the main window (task panel and 3D view) as <name>.png and the 3D
    view alone as <name>-3d.png."""
    share = os.environ.get("FREECAD_GROOVE_SHARE", "")
    folder = os.environ.get("FREECAD_GROOVE_SCREENSHOTS", "screenshots")
    if not os.path.isabs(folder):
        if not share:
            return None
        folder = os.path.join(share, folder)
    os.makedirs(folder, exist_ok=True)
    process(0.05)
    path = os.path.join(folder, name + ".png")
    FreeCADGui.getMainWindow().grab().save(path)
    # The 3D view rendered on its own as well: grabbing the window leaves it
    # blank in FreeCAD 1.0 under Xvfb.
    gui_doc = FreeCADGui.ActiveDocument
    view = gui_doc.ActiveView if gui_doc is not None else None
    if view is not None and hasattr(view, "saveImage"):
        view.saveImage(os.path.join(folder, name + "-3d.png"), 1000, 700, "Current")
    return path


# The lathe's view of the XZ plane: Z to the right, X (radius) up, seen from
# +Y. The camera's right/up/back axes are world Z/X/Y: a -120 degree turn about (1, 1, 1).
LATHE_VIEW = FreeCAD.Rotation(FreeCAD.Vector(1, 1, 1), -120)


def show_part(doc):
    """A view of the XZ plane (where the groove section and path are drawn)."""
    view = FreeCADGui.getDocument(doc.Name).ActiveView
    view.setCameraOrientation(LATHE_VIEW)
    view.fitAll()
    process()
    return view


def zoom_to(doc, x, z, size):
    """Look at the point (x, 0, z) of the XZ plane, ``size`` mm high in the view."""
    view = show_part(doc)
    cam = view.getCameraNode()
    cam.position.setValue(x, 1000.0, z)  # the lathe view looks along -Y
    if hasattr(cam, "height"):  # orthographic camera
        cam.height.setValue(size)
    process()
    return view


def roomy_task_panel():
    """Widen the docks (combo view, tasks) so the panel shows whole in screenshots."""
    mw = FreeCADGui.getMainWindow()
    docks = [d for d in mw.findChildren(QtGui.QDockWidget)
             if d.isVisible() and d.windowTitle() in ("Tasks", "Combo View", "Combo view")]
    if docks:
        mw.resizeDocks(docks, [480] * len(docks), QtCore.Qt.Horizontal)
    process()


def version():
    return ".".join(FreeCAD.Version()[:2])
