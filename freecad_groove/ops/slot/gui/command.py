"""The Cylinder slot command: enabled when a face of a Job's model and the
slot's path are selected (the face, then Ctrl+click the edges of its centre
line in order, or a sketch of the developed surface); makes the op
(make_cylinder_slot) with its task panel open. A button in CAM's "New
Operations" toolbar and an entry in its menu, between the Turning Groove and
the Plunge grind.

Imports no CAM module until the command is used (FreeCAD's GUI start registers it).
"""

import FreeCAD
import FreeCADGui

from ....gui.commands import jobs
from . import ICON

COMMAND = "FreeCADGroove_CylinderSlot"
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP


def _selection():
    """(job, (model, "FaceN"), [(model, "EdgeN"), ...] or a sketch) from the selection, or None."""
    doc = FreeCAD.ActiveDocument
    found = jobs(doc) if doc is not None else []
    face, edges, sketch, job = None, [], None, None
    for sel in FreeCADGui.Selection.getSelectionEx():
        for owner in found:
            if sel.Object in owner.Model.Group:
                job = owner
        if sel.Object.isDerivedFrom("Sketcher::SketchObject"):  # the developed path, whatever of it is picked
            sketch = sel.Object
            continue
        for sub in sel.SubElementNames:
            if sub.startswith("Face") and face is None:
                face = (sel.Object, sub)
            elif sub.startswith("Edge"):
                edges.append((sel.Object, sub))
    if job is None or face is None or (not edges) == (sketch is None):
        return None
    return job, face, sketch if sketch is not None else edges


class CommandCylinderSlot:
    NAME = COMMAND
    TOOLBAR = "New Operations"  # CAM's toolbar of operations, beside the Turning Groove
    MENU_AFTER = "FreeCADGroove_Groove"  # right after the Turning Groove in CAM's menu

    def GetResources(self):
        return {"Pixmap": ICON, "MenuText": QT_TRANSLATE_NOOP(COMMAND, "Cylinder slot"),
                "ToolTip": QT_TRANSLATE_NOOP(COMMAND, "Mill a slot on a cylinder with a live tool and the C axis "
                                             "(GSK G7.1): select the cylindrical face of the Job's part, then "
                                             "Ctrl+click the edges of the slot's centre line on it, in order, "
                                             "or a sketch of the developed surface")}

    def IsActive(self):
        return _selection() is not None

    def Activated(self):
        picked = _selection()
        if picked is None:
            return None
        from ..api import make_cylinder_slot

        job, face, path = picked
        doc = job.Document
        doc.openTransaction("Cylinder slot")
        try:
            obj = make_cylinder_slot(job, face, path, recompute=True)
        except ValueError as e:  # a pair make_cylinder_slot refuses: one line, nothing made
            doc.abortTransaction()
            FreeCAD.Console.PrintError("Cylinder slot: %s\n" % e)
            return None
        doc.commitTransaction()
        obj.ViewObject.Proxy.deleteOnReject = True  # Cancel in the panel deletes the new op
        obj.ViewObject.Document.setEdit(obj.ViewObject, 0)
        return obj

