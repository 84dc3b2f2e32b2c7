"""Driving FreeCAD's GUI from tests the way a user would: key presses into
fields, clicks on buttons, waiting on the Qt event loop; and screenshots.

Runs inside FreeCAD's GUI (tests/freecad_gui/start.py). Screenshots go to
$FREECAD_GROOVE_SHARE/$FREECAD_GROOVE_SCREENSHOTS (default "screenshots").
"""

import os
import sys
import time

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "freecad"))
from parts import face_name, shaft_shape  # noqa: E402

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


class Poll:
    """Calls ``action(value)`` once ``predicate()`` gives a true value, checking from a timer on the Qt event loop
    every ``interval_ms``; ``failed(text)`` instead when ``timeout`` s pass first. For steps inside modal dialogs:
    a check never waits itself (``wait_for`` there would stop the code that is still building the dialog, when it
    lets the event loop run before its own exec(), until the wait times out). Keep the Poll referenced."""

    def __init__(self, predicate, action, failed, what, timeout=60.0, interval_ms=20):
        self.predicate, self.action, self.failed, self.what = predicate, action, failed, what
        self.end = time.monotonic() + timeout
        self.timeout = timeout
        self.timer = QtCore.QTimer()
        self.timer.setInterval(interval_ms)
        self.timer.timeout.connect(self._check)
        self.timer.start()

    def _check(self):
        value = self.predicate()
        if value or time.monotonic() > self.end:
            self.timer.stop()  # before acting: the action may run a modal dialog's event loop
            if value:
                self.action(value)
            else:
                self.failed("timed out after %.1f s waiting for %s" % (self.timeout, self.what))

    def stop(self):
        self.timer.stop()


def key_of(char):
    """The Qt key code of a character."""
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
        press(widget, key_of(char), char)
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


def task_button(panel, which, timeout=30.0):
    """The task panel's OK/Apply/Cancel button (QDialogButtonBox.StandardButton) once it shows: FreeCAD puts the
    button box into the task view when the panel opens, and Qt shows a widget put into a shown window only when
    its event loop runs again (on a busy machine a test could look before). (From the panel: searching the main
    window can reach boxes of closed dialogs whose C++ side is gone, which crashes PySide2.) AssertionError
    naming what hides it when it does not show."""
    def shown():
        button = panel.buttonBox.button(which) if getattr(panel, "buttonBox", None) is not None else None
        return button if button is not None and button.isVisible() else None

    try:
        return wait_for(shown, timeout=timeout, what="the task dialog button %s" % which)
    except AssertionError as error:
        raise AssertionError("%s; hidden: %s" % (error, hidden_part(panel, which))) from None


def hidden_part(panel, which):
    """What keeps the panel's button ``which`` from showing: the widget itself or its first hidden ancestor."""
    box = getattr(panel, "buttonBox", None)
    widget = box.button(which) if box is not None else None
    if widget is None:
        return "no button box" if box is None else "no such button"
    while widget is not None:
        if widget.isHidden():
            return "%s %r" % (type(widget).__name__, widget.objectName())
        widget = widget.parentWidget()
    return "nothing hidden (the main window not shown?)"


def buttons_shown(panel):
    """Whether the panel's OK button is there and visible (a boolean, for wait_for: never a wrapper to print)."""
    box = getattr(panel, "buttonBox", None)
    button = box.button(QtGui.QDialogButtonBox.Ok) if box is not None else None
    return button is not None and button.isVisible()


def screenshot_folder():
    """Where screenshots go (made if missing), or None: not saved."""
    share = os.environ.get("FREECAD_GROOVE_SHARE", "")
    folder = os.environ.get("FREECAD_GROOVE_SCREENSHOTS", "screenshots")
    if not os.path.isabs(folder):
        if not share:
            return None
        folder = os.path.join(share, folder)
    os.makedirs(folder, exist_ok=True)
    return folder


def screenshot_widget(name, widget):
    """Save one widget (a dock: the picture cropped to it) as <name>.png."""
    folder = screenshot_folder()
    if folder is None:
        return None
    process(0.05)
    path = os.path.join(folder, name + ".png")
    widget.grab().save(path)
    return path


def screenshot(name):
    """Save the main window (task panel and 3D view) as <name>.png and the 3D
    view alone as <name>-3d.png."""
    folder = screenshot_folder()
    if folder is None:
        return None
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


DEFAULT_DOCK_WIDTHS = {}  # dock title -> its width as FreeCAD starts (note_default_docks)
TASK_DOCKS = ("Tasks", "Combo View", "Combo view")


def note_default_docks():
    """Note each shown dock's width the first time it is seen (before any test made it wider: roomy_task_panel
    widens it, a panel of FreeCAD 1.0 whose buttons need more widens the combo view, and neither narrows it
    again). Called as the suite starts (this module is imported) and by the fixtures that show the window."""
    for dock in FreeCADGui.getMainWindow().findChildren(QtGui.QDockWidget):
        if dock.isVisible():
            DEFAULT_DOCK_WIDTHS.setdefault(dock.windowTitle(), dock.width())


note_default_docks()


def roomy_task_panel():
    """Widen the docks (combo view, tasks) so the panel shows whole in screenshots."""
    mw = FreeCADGui.getMainWindow()
    docks = [d for d in mw.findChildren(QtGui.QDockWidget) if d.isVisible() and d.windowTitle() in TASK_DOCKS]
    note_default_docks()
    if docks:
        mw.resizeDocks(docks, [480] * len(docks), QtCore.Qt.Horizontal)
    process()


def screenshot_dock(name):
    """The task dock (1.1: the tasks dock, 1.0: the combo view) put back at the width FreeCAD gives it
    (roomy_task_panel widens it), saved as <name>.png in 256 colours (small enough for the README). (Found from
    the main window, as roomy_task_panel finds it: no wrappers made of the widgets between it and the panel.)"""
    mw = FreeCADGui.getMainWindow()
    docks = [d for d in mw.findChildren(QtGui.QDockWidget) if d.isVisible() and d.windowTitle() in TASK_DOCKS]
    assert docks, "no task dock shown"
    widths = [DEFAULT_DOCK_WIDTHS.get(d.windowTitle(), d.width()) for d in docks]
    mw.resizeDocks(docks, widths, QtCore.Qt.Horizontal)
    folder = screenshot_folder()
    if folder is None:
        return None
    process(0.1)
    path = os.path.join(folder, name + ".png")
    docks[0].grab().toImage().convertToFormat(QtGui.QImage.Format_Indexed8).save(path)
    return path


def _open_panels(attribute):
    """[(view provider, its task panel)] of the objects of every document whose view provider holds a panel
    in ``attribute``."""
    found = []
    for doc in FreeCAD.listDocuments().values():
        for obj in doc.Objects:
            vp = getattr(getattr(obj, "ViewObject", None), "Proxy", None)
            if getattr(vp, attribute, None) is not None:
                found.append((vp, getattr(vp, attribute)))
    return found


def open_op_panels():
    """[(view provider, its task panel)] of the ops (CAM's and the add-on's) with a panel open in any document."""
    return _open_panels("panel")


def open_job_panels():
    """[(view provider, its task panel)] of the CAM Jobs with a panel open in any document (a test that failed
    while one was open left it: its selection observer then answered every later selection with a traceback,
    failing the tests after it)."""
    return [(vp, panel) for vp, panel in _open_panels("taskPanel") if type(vp).__name__ == "ViewProvider"]


def cancel_open_panel():
    """The open task panel (if any) closed. (Control.reject() first, as the Cancel button does, made the next
    Groove panel segfault FreeCAD 1.0 and 1.1 in test_task_panel when the document was closed right after:
    closeDialog only.) What CAM's op panel does only in its accept or reject done here too: it stops observing
    the selection (else, its widgets deleted, it answered a later selection with a traceback in the Report
    view, failing a later test that reads it, or not, as the garbage collector ran), and the wrappers of the
    widgets FreeCAD deletes with it are forgotten (gui/qt_wrappers.py: a wrapper left at a freed address is
    handed out for the next panel's widget built there)."""
    from freecad_groove.gui import qt_wrappers

    if not FreeCADGui.Control.activeDialog():
        return
    panels = open_op_panels()
    held = []
    for _vp, panel in panels:
        FreeCADGui.Selection.removeObserver(panel)
        forms = panel.form if isinstance(panel.form, list) else [panel.form]
        held += qt_wrappers.made_by_qt(forms + [getattr(panel, "buttonBox", None)])
    jobs = open_job_panels()
    for _vp, panel in jobs:  # a Job panel left open by a failed test: its preCleanup's part (the rest is its view)
        FreeCADGui.Selection.removeObserver(panel)
    FreeCADGui.Control.closeDialog()
    for vp, _panel in panels:
        vp.panel = None  # as CAM's clearTaskPanel does: open_op_panels no longer finds it
    for vp, _panel in jobs:
        vp.taskPanel = None  # as CAM's resetTaskPanel does
    process()
    qt_wrappers.forget(held)
    qt_wrappers.collect_closed_panels()  # (the items of its lists, no QObjects, are not among those forgotten)


def close_shop(doc):
    """The end of a GUI fixture: its task dialog (if open) cancelled as its Cancel button does, and its document
    closed. (Not closeDialog alone: CAM's op panel stops observing the selection only in its accept or reject; a
    panel closed without either stayed an observer and, once the garbage collector had deleted its widgets,
    answered every later selection with a traceback in the Report view, which failed a later test that reads
    the Report view, or not, as the collector ran.)"""
    cancel_open_panel()
    FreeCAD.closeDocument(doc.Name)
    process()


def make_gui_shop(name, feed="120 mm/min", shape=None):
    """(doc, job, model): the stepped shaft of tests/freecad/parts.py (or
    ``shape``) in a new document, in a Job made as CAM's GUI makes it (with
    its view provider and its default stock around that shape); its tool
    controllers feed at ``feed`` (None: as the Job made them)."""
    import Path.Main.Gui.Job as PathJobGui

    doc = FreeCAD.newDocument(name)
    shaft = doc.addObject("Part::Feature", "Shaft")
    shaft.Shape = shaft_shape() if shape is None else shape
    doc.recompute()
    job = PathJobGui.Create([shaft], openTaskPanel=False)
    for tc in job.Tools.Group if feed is not None else []:
        tc.HorizFeed = feed
        tc.VertFeed = feed
    doc.recompute()
    return doc, job, job.Model.Group[0]


def open_panel(doc):
    """The open task panel of a Groove or Plunge grind op in ``doc`` (their view provider's), or None."""
    from freecad_groove.gui.op_view import OpViewProvider

    if not FreeCADGui.Control.activeDialog():
        return None
    for obj in doc.Objects:
        vp = getattr(getattr(obj, "ViewObject", None), "Proxy", None)
        if isinstance(vp, OpViewProvider) and vp.panel is not None:
            return vp.panel
    return None


def start_groove_command(doc, model, face_key):
    """Select a face of the Job's model (a key of parts.FACES) and press the
    Groove button; returns the task panel once its first preview is drawn."""
    from freecad_groove.ops.groove.gui.command import CommandGroove

    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(doc.Name, model.Name, face_name(model.Shape, face_key))
    process()
    FreeCADGui.runCommand(CommandGroove.NAME)
    panel = wait_for(lambda: open_panel(doc), what="the Groove task panel")
    page = panel.groove_page
    wait_for(lambda: page.preview is not None and page.replans > 0, what="the first preview")
    return panel


def version():
    return ".".join(FreeCAD.Version()[:2])


def make_slot_shop(name):
    """(doc, job): an R20 shaft (Z 0..50) and a helix of one turn on it (pitch 20, from Z10: the "SlotLine"
    object), both in a Job made as CAM's GUI makes it, its tool controllers feeding at 120 mm/min; the main
    window shown and CAM active (the Cylinder slot GUI tests)."""
    import Part
    import Path.Main.Gui.Job as PathJobGui

    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc = FreeCAD.newDocument(name)
    shaft = doc.addObject("Part::Feature", "Shaft")
    shaft.Shape = Part.makeCylinder(20, 50)
    helix = Part.makeHelix(20.0, 20.0, 20.0)
    helix.translate(FreeCAD.Vector(0, 0, 10))
    line = doc.addObject("Part::Feature", "SlotLine")
    line.Shape = helix
    doc.recompute()
    job = PathJobGui.Create([shaft, line], openTaskPanel=False)
    for tc in job.Tools.Group:
        tc.HorizFeed = "120 mm/min"
    doc.recompute()
    return doc, job


def report_view():
    """The Report view's text widget (FreeCAD's ReportOutput)."""
    mw = FreeCADGui.getMainWindow()
    dock = next(d for d in mw.findChildren(QtGui.QDockWidget) if d.objectName() in ("Report view", "ReportView"))
    return dock.findChild(QtGui.QTextEdit)


def no_traceback(step):
    """The Report view's text; AssertionError naming ``step`` when it holds a traceback."""
    text = report_view().toPlainText()
    assert "Traceback" not in text, "%s: a traceback in the Report view:\n%s" % (step, text)
    return text


def post_with_cam_post(doc, job, post, path, args=""):
    """CAM's Post Process command (CAM_Post) on ``job`` with post ``post`` ("fanuc_lathe"), writing ``path``."""
    job.PostProcessor = post
    job.PostProcessorArgs = args
    job.PostProcessorOutputFile = path
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(doc.Name, job.Name)
    process()
    FreeCADGui.runCommand("CAM_Post")
    process(0.1)


def toolbar_action(toolbar, text):
    """The action (button) ``text`` of CAM's toolbar ``toolbar`` ("New Operations"), once FreeCAD enabled it
    (it updates its commands' state on a timer)."""
    bar = next(tb for tb in FreeCADGui.getMainWindow().findChildren(QtGui.QToolBar) if tb.objectName() == toolbar)
    action = next(a for a in bar.actions() if a.text().replace("&", "") == text)
    wait_for(action.isEnabled, what="the %s button enabled" % text)
    return action


def shown_message(form):
    """The op's message as a page shows it (its line at the top), or None while it shows none. (Not isVisible
    alone: a page of the panel not shown has no visible widgets; isHidden says what the page would show.)"""
    from freecad_groove.gui.widgets import ERROR_LABEL

    label = form.findChild(QtGui.QLabel, ERROR_LABEL)
    if label is not None and not label.isHidden() and label.text():
        return label.text()
    return None


def make_blade_shop(name, **lengths):
    """make_gui_shop(name) with its Job's tool bit made a grooving blade: each of ``lengths`` (Width=3.0,
    CuttingEdgeHeight=8.0, ...) a length property of the bit, added where the bit has none."""
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc, job, model = make_gui_shop(name)
    bit = job.Tools.Group[0].Tool
    for prop, value in lengths.items():
        if prop not in bit.PropertiesList:
            bit.addProperty("App::PropertyLength", prop, "Grooving blade", prop)
        setattr(bit, prop, value)
    doc.recompute()
    return doc, job, model


def replan(page, field, text):
    """Type ``text`` into ``field`` and wait for the page's preview planned again."""
    before = page.replans
    type_into(field, text)
    wait_for(lambda: page.replans > before, what="the preview after typing %r" % text)
