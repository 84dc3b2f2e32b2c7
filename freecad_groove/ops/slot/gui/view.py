"""The Cylinder slot op in FreeCAD's GUI: its command (a face and the slot's
edges selected -> the op) and its view provider, which draws the op's X/Z/C
moves wrapped on the cylinder (FreeCAD's own Path view knows no C: it draws
them flat in the XZ plane).

The class path ``freecad_groove.gui.slot_view.ViewProviderCylinderSlot`` is
stored in documents: keep it. Editing the op (the command, a double-click)
opens its task panel (slot_panel.py).
"""

import math
from typing import List, Tuple

import FreeCAD
import FreeCADGui

COMMAND = "FreeCADGroove_CylinderSlot"
STEP_DEGREES = 2.0  # the drawn wrap: C turns of at most this many degrees per straight piece
RAPID_COLOUR = (0.9, 0.9, 0.2)
FEED_COLOUR = (0.1, 0.4, 1.0)
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

Point = Tuple[float, float, float]


def wrapped_segments(commands: list) -> List[Tuple[bool, List[Point]]]:
    """(is_feed, [3D points]) for each G0/G1 of ``commands``: X a radius, C degrees about Z,
    a move that turns C drawn as pieces of at most STEP_DEGREES."""
    here = {"X": None, "Z": None, "C": 0.0}
    out = []
    for command in commands:
        if command.Name not in ("G0", "G1"):
            continue
        start = dict(here)
        here.update({k: v for k, v in command.Parameters.items() if k in here})
        if start["X"] is None or start["Z"] is None or here["X"] is None or here["Z"] is None:
            continue
        count = max(1, math.ceil(abs(here["C"] - start["C"]) / STEP_DEGREES))
        points = []
        for k in range(count + 1):
            t = k / count
            r = start["X"] + (here["X"] - start["X"]) * t
            z = start["Z"] + (here["Z"] - start["Z"]) * t
            c = math.radians(start["C"] + (here["C"] - start["C"]) * t)
            points.append((r * math.cos(c), r * math.sin(c), z))
        out.append((command.Name == "G1", points))
    return out


class ViewProviderCylinderSlot:
    """Draws the op's Path wrapped on its cylinder (feeds blue, rapids yellow)."""

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        from pivy import coin

        self.Object, self.vobj, self.panel = vobj.Object, vobj, None
        self.deleteOnReject = False  # True while a new op's first panel is open: Cancel deletes the op
        self.wrapped = coin.SoSeparator()
        self.wrapped.setName("CylinderSlotWrapped")
        vobj.RootNode.addChild(self.wrapped)
        self._draw()

    def updateData(self, obj, prop):
        if prop == "Path":
            self._draw()
        if getattr(self, "panel", None) is not None:
            self.panel.updateData(obj, prop)

    # -- the task panel (CAM's op panel framework calls these names) -----------------
    def setEdit(self, vobj=None, mode=0):
        if mode != 0:
            return False
        from . import slot_panel

        self.panel = slot_panel.open_panel(vobj or self.vobj, self.deleteOnReject)
        self.deleteOnReject = False
        return True

    def unsetEdit(self, vobj=None, mode=0):
        if getattr(self, "panel", None) is not None:
            self.panel.reject(False)
        return True

    def doubleClicked(self, vobj):
        vobj.Document.setEdit(vobj, 0)
        return True

    def clearTaskPanel(self):
        self.panel = None
        job = self.Object.Proxy.getJob(self.Object)
        if job is not None and hasattr(getattr(job.ViewObject, "Proxy", None), "resetEditVisibility"):
            job.ViewObject.Proxy.resetEditVisibility(job)

    def _draw(self):
        from pivy import coin

        node = getattr(self, "wrapped", None)
        if node is None:
            return
        node.removeAllChildren()
        for feed in (True, False):
            segments = [points for is_feed, points in wrapped_segments(self.Object.Path.Commands) if is_feed == feed]
            if not segments:
                continue
            colour, coords, lines = coin.SoBaseColor(), coin.SoCoordinate3(), coin.SoLineSet()
            colour.rgb = FEED_COLOUR if feed else RAPID_COLOUR
            coords.point.setValues(0, [p for points in segments for p in points])
            lines.numVertices.setValues(0, [len(points) for points in segments])
            for child in (colour, coords, lines):
                node.addChild(child)

    def getIcon(self):
        from . import ICON

        return ICON

    def dumps(self):
        return None

    def loads(self, state):
        return None

    def onDocumentRestored(self, vobj):
        self.attach(vobj)


def attach_view_provider(obj) -> None:
    """Give the op ``obj`` its view provider (with the GUI up)."""
    if getattr(obj, "ViewObject", None) is not None:
        ViewProviderCylinderSlot(obj.ViewObject)


def _selection():
    """(job, (model, "FaceN"), [(model, "EdgeN"), ...] or a sketch) from the selection, or None."""
    from .command import _jobs

    doc = FreeCAD.ActiveDocument
    jobs = _jobs(doc) if doc is not None else []
    face, edges, sketch, job = None, [], None, None
    for sel in FreeCADGui.Selection.getSelectionEx():
        for owner in jobs:
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
    def GetResources(self):
        from . import ICON

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
        from ..freecad.slot_api import make_cylinder_slot

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


def register() -> None:
    FreeCADGui.addCommand(COMMAND, CommandCylinderSlot())
