"""The Cylinder slot op's view provider, which draws the op's X/Z/C moves
wrapped on the cylinder (FreeCAD's own Path view knows no C: it draws them
flat in the XZ plane).

The class path ``freecad_groove.ops.slot.gui.view.ViewProviderCylinderSlot``
is stored in GUI documents saved since the ops moved here; documents saved
before store ``freecad_groove.gui.slot_view.ViewProviderCylinderSlot``, which
that module keeps as a shim. Neither may move. Editing the op (the command,
a double-click) opens its task panel (panel.py).
"""

import math
from typing import List, Tuple

from . import ICON

STEP_DEGREES = 2.0  # the drawn wrap: C turns of at most this many degrees per straight piece
RAPID_COLOUR = (0.9, 0.9, 0.2)
FEED_COLOUR = (0.1, 0.4, 1.0)
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

    @classmethod
    def assign(cls, obj: object) -> None:
        """Give the op ``obj`` this view provider (with the GUI up; ops made by scripts too: ops/registry.py)."""
        if getattr(obj, "ViewObject", None) is not None:
            cls(obj.ViewObject)

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
        from .panel import open_panel

        self.panel = open_panel(vobj or self.vobj, self.deleteOnReject)
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
        return ICON

    def dumps(self):
        return None

    def loads(self, state):
        return None

    def onDocumentRestored(self, vobj):
        self.attach(vobj)
