"""OpViewProvider: the view provider of the add-on's ops on CAM's op
framework (the Groove's and the Plunge grind's derive from it), and a new op
made with its task panel open (what their commands do).

It is FreeCAD's op view provider (Path.Op.Gui.Base.ViewProvider, as
SetupOperation's ops get it) with the add-on's icon, its selection gate and
its dialog (task_dialog.AddonTaskPanel: OK refused while the op's page holds
an error). A subclass names the op's declaration (KIND, ops/registry.py),
its Create, its page class (FreeCAD stores the page's class path in the view
provider's state: keep it where it is), its icon and title, and may name
another dialog and selection gate.

Not stored in documents itself (each op's subclass is): free to move.
"""

import FreeCAD
import Path.Op.Gui.Base as PathOpGui

from . import qt_wrappers
from .task_dialog import AddonTaskPanel
from .widgets import CONTEXT

translate = FreeCAD.Qt.translate


class OpViewProvider(PathOpGui.ViewProvider):
    """The op's view provider: FreeCAD's, with the add-on's icon, selection gate and task panel."""

    KIND = None  # the op's declaration (ops/registry.py): its name is a new op's object name
    CREATE = None  # the op's Create(name, obj=None, parentJob=None) (op.py), a staticmethod
    PAGE = None  # the op's page class (its panel.py)
    ICON = ""
    TITLE = ""  # the op's kind, as the page's title says it (QT_TRANSLATE_NOOP in CONTEXT)
    DIALOG = AddonTaskPanel

    @classmethod
    def command_resources(cls) -> object:
        """What FreeCAD's op view provider is made from (PathOpGui.CommandResources, as SetupOperation gives
        it): the op's kind, its Create, the page class it stores, the icon. (It reads no menu text or tool
        tip: the op's command has its own.)"""
        return PathOpGui.CommandResources(cls.KIND.name, cls.CREATE, cls.PAGE, cls.ICON, cls.TITLE, None, "")

    @classmethod
    def assign(cls, obj: object, delete_on_reject: bool = False) -> None:
        """Give the op ``obj`` this view provider (ops made by scripts get one too: ops/registry.py)."""
        vobj = getattr(obj, "ViewObject", None)
        if vobj is None:
            return
        if type(getattr(vobj, "Proxy", None)) is not cls:
            vobj.Proxy = cls(vobj, cls.command_resources())
        vobj.Proxy.setDeleteObjectsOnReject(delete_on_reject)

    @classmethod
    def create(cls, job: object) -> object:
        """A new op of this kind in ``job`` with its task panel open (what its command does). Cancel
        deletes it again. Returns the op, or None."""
        doc = job.Document
        kind = translate(CONTEXT, cls.TITLE)
        doc.openTransaction(translate(CONTEXT, "Create {0}").format(kind))
        try:
            obj = cls.CREATE(cls.KIND.name, parentJob=job)
            cls.assign(obj, delete_on_reject=True)
            obj.ViewObject.Visibility = True
        except Exception as error:
            doc.abortTransaction()
            FreeCAD.Console.PrintError(translate(CONTEXT, "{0}: cannot create the operation: {1}").format(kind, error)
                                       + "\n")
            return None
        doc.commitTransaction()
        obj.ViewObject.Document.setEdit(obj.ViewObject, 0)
        return obj

    def getIcon(self):
        if getattr(self, "Object", None) is not None and not self.Object.Active:
            return ":/icons/CAM_OpActive.svg"
        return self.ICON

    def setEdit(self, vobj=None, mode=0):
        if mode != 0:
            return False
        if vobj is None:
            vobj = self.vobj
        qt_wrappers.collect_closed_panels()
        page = self.getTaskPanelOpPage(vobj.Object)
        page.setTitle(translate(CONTEXT, self.TITLE))
        page.setIcon(self.ICON)
        panel = self.DIALOG(vobj.Object, self.deleteObjectsOnReject(), page, self.getSelectionFactory())
        self.setupTaskPanel(panel)
        self.deleteOnReject = False
        return True
