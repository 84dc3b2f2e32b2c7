"""Forgetting PySide's wrappers of Qt objects FreeCAD deletes.

PySide (shiboken) keeps one Python wrapper per C++ address. A widget FreeCAD
makes in C++ and hands to Python (the task dialog's OK/Cancel button box, in
``modifyStandardButtons``) is deleted by FreeCAD when the dialog closes
without shiboken hearing of it: while anything still holds its wrapper (CAM's
panel keeps ``self.buttonBox``; the panel lives on until Python's garbage
collector breaks its reference cycles), the address stays mapped to it. Qt
then builds the next panel's widgets at freed addresses, and PySide hands out
the old wrapper for them: a spin box comes back as a QDialogButtonBox (an
AttributeError in FreeCAD 1.1) or a form layout's item as a widget, whose
methods then run on the wrong object (the segfault FreeCAD 1.0 showed inside
``QFormLayout.itemAt`` about one GUI-suite run in four).

``forget`` invalidates such wrappers once their objects are gone: shiboken
drops the address, and a wrapper still held raises "already deleted" instead
of reaching another object. Wrappers of objects Python made are left alone
(shiboken hears of their deletion itself). ``ForgetsButtonBox`` does it for
a CAM op task panel (Path.Op.Gui.Base.TaskPanel): every op panel of the
add-on derives from it.
"""

import gc

from PySide import QtCore, QtGui

try:  # FreeCAD 1.1: Qt 6
    import shiboken6 as shiboken
except ImportError:  # FreeCAD 1.0: Qt 5
    import shiboken2 as shiboken


# The base class of every wrapper (shiboken's Object): what shiboken's isValid and invalidate may be handed. A
# signal's SignalInstance, which PySide keeps in a widget's __dict__, is none (invalidating one segfaulted).
WRAPPER = next(cls for cls in QtCore.QObject.__mro__ if cls.__name__ == "Object")


def made_by_qt(objects: list) -> list:
    """The wrappers of ``objects`` (None allowed) and of their children that C++ made: those whose deletion
    shiboken does not hear of. Call it while the objects are surely alive (it reads their children), and
    ``forget`` the wrappers once the objects are deleted (that reads nothing of them)."""
    found = {}
    for obj in objects:
        if obj is None or not shiboken.isValid(obj):
            continue
        for item in [obj] + list(obj.findChildren(QtCore.QObject)):
            if not shiboken.createdByPython(item):
                found[id(item)] = item
    return list(found.values())


def made_by_python(objects: list) -> list:
    """The wrappers of the children of ``objects`` (None allowed) that Python made: the error, warning and row
    message labels, the "Groove from the model" box, a Python-made form's fields. A panel holds them until the
    dialog is gone: FreeCAD 1.1 aborted twice inside shiboken's Object::destroy while Qt deleted such a widget
    with the dialog (a wrapper freed in the middle of its own destroy: PySide records a widget inserted into a
    layout the .ui file made as a child of the layout's wrapper, which comes and goes); one more reference keeps
    the wrapper whole until shiboken has let go of the widget."""
    found = {}
    for obj in objects:
        if obj is None or not shiboken.isValid(obj):
            continue
        for item in obj.findChildren(QtCore.QObject):
            if shiboken.createdByPython(item):
                found[id(item)] = item
    return list(found.values())


def list_items(objects: list) -> list:
    """The wrappers of the items of every list and table widget in ``objects`` (None allowed): items are no
    QObjects, so made_by_qt cannot find them, and a page that lives on in a reference cycle (CAM's base
    geometry page) keeps their wrappers after FreeCAD deleted them with the dialog (FreeCAD 1.0: CAM's next
    Job dialog was handed one for a button, "QListWidgetItem has no attribute 'clicked'"). Call it while the
    objects are surely alive, and ``forget`` the wrappers once they are deleted."""
    found = []
    for obj in objects:
        if obj is None or not shiboken.isValid(obj):
            continue
        for widget in obj.findChildren(QtGui.QListWidget):
            found += [widget.item(row) for row in range(widget.count())]
        for widget in obj.findChildren(QtGui.QTableWidget):
            found += [widget.item(row, column) for row in range(widget.rowCount())
                      for column in range(widget.columnCount())]
    return [item for item in found if item is not None]


def forget(wrappers: list) -> None:
    """Invalidate ``wrappers`` (from made_by_qt) once their objects are deleted; shiboken's flags only,
    so a wrapper of an object already gone is safe here."""
    for wrapper in wrappers:
        if shiboken.isValid(wrapper):
            shiboken.invalidate(wrapper)


def drop_stale(form: object) -> None:
    """Forget the wrappers PySide holds for the children of ``form``, a form Qt has just made from a .ui file:
    Python cannot have taken a wrapper of them yet, so any it holds is a wrapper of a deleted object that was
    at the same address (a closed panel's widget or list item, still held by something), which PySide would
    hand out, of the wrong type, for the new widget (FreeCAD 1.0 segfaulted reading a Groove field in
    test_model_panel_cases, late in the whole GUI suite). Only shiboken's flags and map are touched: no method
    of a wrong-typed wrapper is called. Run it before anything reads the form's widgets."""
    for item in form.findChildren(QtCore.QObject):
        if not shiboken.createdByPython(item):
            shiboken.invalidate(item)
    # FreeCAD's loader set an attribute of the form for each named widget (form.width): wrappers taken the same
    # way, now forgotten too, so each is taken again. One may be a stale wrapper of no QObject at all (a list
    # item's: FreeCAD 1.0 handed form.chamferMeasure out as a QListWidgetItem), which findChildren cannot
    # return: forgotten and taken again as well.
    for name, value in list(vars(form).items()):
        if not isinstance(value, WRAPPER):
            continue  # not a wrapper: the form's own Python attributes, or a signal PySide keeps there
        if isinstance(value, QtCore.QObject) and shiboken.isValid(value):
            continue
        if shiboken.isValid(value):
            shiboken.invalidate(value)
        found = form.findChild(QtCore.QObject, name)
        if found is not None:
            setattr(form, name, found)


# Qt's item views and their items (which are no QObjects): what forget_closed_views looks for.
ITEM_VIEWS = (QtGui.QListWidget, QtGui.QTableWidget, QtGui.QTreeWidget)
VIEW_ITEMS = (QtGui.QListWidgetItem, QtGui.QTableWidgetItem, QtGui.QTreeWidgetItem)


def wrappers_alive() -> list:
    """Every PySide wrapper Python's collector knows of (one walk over its objects: the panels' opening pays it
    once)."""
    return [obj for obj in gc.get_objects() if isinstance(obj, WRAPPER)]


def forget_closed_views(alive: list | None = None) -> int:
    """Forget the wrappers of list, table and tree widgets that no window has any more, and of their items; the
    number forgotten. CAM's Job panel (FreeCAD 1.0) reads its work offset list and tool controller table item
    by item, and lives on after FreeCAD deleted its dialog: the item wrappers it took (19 for a Job of one
    tool controller, 57 after three Jobs: test_first_hour) stayed mapped to freed addresses, and our next
    panel's widgets built there were handed them (the Apply button, the chamfer measure box as a
    QListWidgetItem, test_model_panel_cases). Views Python made and shows are left alone, and only shiboken's
    flags are touched: nothing of a deleted object is read."""
    live = set()
    for top in QtGui.QApplication.topLevelWidgets():
        if not shiboken.isValid(top):
            # a window Qt has whose wrapper says it is gone (FreeCAD 1.0, test_saved_documents): its views cannot
            # be told from closed ones, so nothing is forgotten this time
            return 0
        live.add(id(top))
        live.update(id(view) for view in top.findChildren(QtGui.QAbstractItemView))
    # a view shiboken knows is deleted (PySide hears of a QObject's deletion) or one no window has
    closed = [obj for obj in (wrappers_alive() if alive is None else alive)
              if isinstance(obj, ITEM_VIEWS) and id(obj) not in live
              and (not shiboken.isValid(obj) or not shiboken.createdByPython(obj))]
    forgotten = 0
    for view in closed:
        # the items' wrappers the view's wrapper keeps (as their parent): what gc sees it hold. Items are no
        # QObjects: shiboken does not hear of their deletion with the view.
        for item in [obj for obj in gc.get_referents(view) if isinstance(obj, VIEW_ITEMS)] + [view]:
            if shiboken.isValid(item):
                shiboken.invalidate(item)
                forgotten += 1
    return forgotten


def collect_closed_panels() -> None:
    """Free the Python objects of closed panels before a new panel's widgets are built. A closed panel's pages
    live on in reference cycles until Python's garbage collector breaks them, holding wrappers of widgets and
    of items (a list's or a table's, which are no QObjects: ``forget`` cannot find them) that FreeCAD deleted
    with the dialog; the next panel's widgets built at those addresses were handed these wrappers (FreeCAD 1.0,
    test_model_panel_cases: the Groove page's error label came back as a QTableWidgetItem, the tool page's
    combo box as a QListWidgetItem, and the panel did not open). Then forget what CAM's panels left of their
    list and table widgets (forget_closed_views) and the wrappers of widgets Qt deleted that Python still holds
    (forget_deleted_widgets: CAM's Job panel leaves 18 or 19 each time it closes)."""
    gc.collect()
    alive = wrappers_alive()
    try:
        forget_closed_views(alive)
    except RuntimeError:  # a wrapper that says its object is gone: forget nothing rather than fail the panel
        pass
    try:
        forget_deleted_widgets(alive)
    except RuntimeError:  # the same: never a reason for a panel not to open
        pass


def address(wrapper: object) -> int:
    """The C++ address ``wrapper`` stands for (shiboken's record: nothing of the object is read)."""
    return shiboken.getCppPointer(wrapper)[0]


def _wrappers_kept_by(wrapper: object) -> list:
    """The wrappers ``wrapper`` keeps, and those they keep (shiboken reports a wrapper's children to Python's
    collector): what invalidating ``wrapper`` invalidates with it."""
    found, todo, seen = [], [wrapper], {id(wrapper)}
    while todo:
        for kept in gc.get_referents(todo.pop()):
            if isinstance(kept, WRAPPER) and id(kept) not in seen:
                seen.add(id(kept))
                found.append(kept)
                todo.append(kept)
    return found


def forget_deleted_widgets(alive: list | None = None) -> int:
    """Forget the wrappers of widgets Qt made and has deleted, still held in Python; the number forgotten.
    Qt knows every widget alive (QApplication.allWidgets), so a Qt-made widget's wrapper whose address is not
    among them is one of a deleted widget: held on, it is handed out for the next widget built at that address.
    CAM's Job panel (FreeCAD 1.0 and 1.1) leaves 18 such wrappers each time it closes (its form, its tab widget
    and the forms of the 16 setup sheet op editors), and CAM's own panels built later were handed them: the
    next Job panel's setup sheet raised "Internal C++ object (QTableView) already deleted" or segfaulted, an op
    panel's tool controller editor segfaulted in installEventFilter. A wrapper that keeps a wrapper of a live
    object (a wrapper handed out again for a widget built since, in use) is left alone: invalidating it would
    invalidate that one too. Only shiboken's flags and records are read and changed."""
    app = QtGui.QApplication.instance()
    if app is None:
        return 0
    widgets = {address(widget) for widget in QtGui.QApplication.allWidgets()}
    deleted = [obj for obj in (wrappers_alive() if alive is None else alive)
               if isinstance(obj, QtGui.QWidget) and shiboken.isValid(obj)
               and not shiboken.createdByPython(obj) and address(obj) not in widgets]
    if not deleted:
        return 0
    objects = set(widgets) | {address(app)}
    for top in QtGui.QApplication.topLevelWidgets():
        if not shiboken.isValid(top):
            return 0  # a window whose wrapper says it is gone (forget_closed_views): the live set is not whole
        objects.update(address(child) for child in top.findChildren(QtCore.QObject))
    forgotten = 0
    for wrapper in deleted:
        if not shiboken.isValid(wrapper):
            continue  # invalidated with a wrapper that kept it
        if any(shiboken.isValid(kept) and address(kept) in objects for kept in _wrappers_kept_by(wrapper)):
            continue
        shiboken.invalidate(wrapper)
        forgotten += 1
    return forgotten


class ForgetsButtonBox:
    """Mixin before Path.Op.Gui.Base.TaskPanel: the dialog's button box, which
    FreeCAD made and deletes, leaves no wrapper behind when the panel closes."""

    def modifyStandardButtons(self, buttonBox):
        # FreeCAD has just made the box and its buttons: any wrapper PySide holds for them is one of a deleted
        # object once at the same address (FreeCAD 1.0 segfaulted enabling the OK button handed out that way).
        drop_stale(buttonBox)
        super().modifyStandardButtons(buttonBox)
        # Taken now: when the panel is cleaned up FreeCAD may have deleted the box already (a closed document).
        self.made_by_qt = made_by_qt([buttonBox])

    def cleanup(self, resetEdit):
        self.buttonBox = None  # from now on there are no buttons to enable
        super().cleanup(resetEdit)
        forget(getattr(self, "made_by_qt", []))
