"""The Check turning command: verify_job() on a Job, the resulting half
section drawn in the 3D view over the part, the figures per op in a task
panel. "Check again" (or the command once more) runs the check anew after a
change; Close takes the drawing away.

Drawn in the XZ plane at Y = 0 (X = radius), like the op's Path and the
Groove panel's preview, in an SoAnnotation over the part: the stock left
standing (grey outline), gouges (red), material left in the grooves that the
blade could reach (orange) and what it cannot reach (yellow).
"""

import FreeCAD
import FreeCADGui
from pivy import coin
from PySide import QtGui

from . import ICON
from .command import add_to_cam
from .preview import fill_lines, line_nodes

COMMAND_CHECK = "FreeCADGroove_CheckTurning"
_open_panel = None  # the TurningPanel shown in the task view, if any
TOOLBAR = "Project Setup"  # CAM's toolbar with Job, Post and Sanity (1.0 and 1.1)
MENU_AFTER = "CAM_Sanity"
REMAINING_COLOR = (0.45, 0.45, 0.45)
GOUGE_COLOR = (0.9, 0.0, 0.0)
LEFTOVER_COLOR = (1.0, 0.55, 0.0)
UNREACHABLE_COLOR = (0.9, 0.8, 0.0)

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP


def rings(geometry):
    """Every ring (exterior and holes) of a shapely (z, x) geometry as (x, 0, z) points."""
    out = []
    if geometry is None or geometry.is_empty:
        return out
    parts = getattr(geometry, "geoms", [geometry])
    for part in parts:
        if part.geom_type == "Polygon":
            for ring in [part.exterior] + list(part.interiors):
                out.append([(x, 0.0, z) for z, x in ring.coords])
        elif part.geom_type in ("MultiPolygon", "GeometryCollection"):
            out += rings(part)
    return out


class SectionDrawing:
    """Coin nodes in a view's scene graph; show(result) redraws, remove()
    takes them out. ``drawn`` holds the rings of each layer by name."""

    LAYERS = (("remaining", REMAINING_COLOR, 1.5), ("unreachable", UNREACHABLE_COLOR, 3),
              ("leftover", LEFTOVER_COLOR, 3), ("gouge", GOUGE_COLOR, 4))

    def __init__(self, view):
        self.root = coin.SoAnnotation()
        self.root.setName("FreeCADGrooveTurningCheck")
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        self.root.addChild(pick)
        self._layers = {}
        for name, color, width in self.LAYERS:
            self._layers[name] = line_nodes(color, width)
            self.root.addChild(self._layers[name][0])
        self.drawn = {name: [] for name, _c, _w in self.LAYERS}
        self._graph = view.getSceneGraph() if view is not None else None
        if self._graph is not None:
            self._graph.addChild(self.root)

    def show(self, result):
        """Draw a verify.turning.JobCheck (None: nothing)."""
        ops = result.ops if result is not None else []
        self.drawn = {
            "remaining": rings(result.remaining) if result is not None else [],
            "unreachable": [r for op in ops for r in rings(op.unreachable_region)],
            "leftover": [r for op in ops for r in rings(op.leftover_region)],
            "gouge": [r for op in ops for r in rings(op.gouge_region)],
        }
        for name, polys in self.drawn.items():
            _separator, coords, lines = self._layers[name]
            fill_lines(coords, lines, polys)

    def in_scene(self):
        return self._graph is not None and self._graph.findChild(self.root) >= 0

    def remove(self):
        if self.in_scene():
            self._graph.removeChild(self.root)
        self._graph = None


class TurningPanel:
    """The task panel: the figures per op (the check's summary), Check again, Close."""

    def __init__(self, job):
        self.job = job
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(translate("FreeCADGroove_CheckTurning", "Turning check"))
        layout = QtGui.QVBoxLayout(self.form)
        self.figures = QtGui.QPlainTextEdit()
        self.figures.setObjectName("figures")
        self.figures.setReadOnly(True)
        self.again = QtGui.QPushButton(translate("FreeCADGroove_CheckTurning", "Check again"))
        self.again.setObjectName("check_again")
        self.again.clicked.connect(self.check)
        layout.addWidget(self.figures)
        layout.addWidget(self.again)
        gui_doc = FreeCADGui.getDocument(job.Document.Name)
        self.drawing = SectionDrawing(gui_doc.ActiveView if gui_doc is not None else None)
        self.result = None
        self.runs = 0
        self.check()

    def check(self):
        """Run verify_job and show its result; its message when the Job cannot be checked."""
        from ..freecad.turning_check import TurningCheckError, verify_job

        try:
            self.result = verify_job(self.job)
            text = self.result.summary()
        except TurningCheckError as e:
            self.result, text = None, str(e)
        self.runs += 1
        self.figures.setPlainText(text)
        self.drawing.show(self.result)
        FreeCAD.Console.PrintMessage(text + "\n")

    def getStandardButtons(self):
        return QtGui.QDialogButtonBox.Close

    def _close(self):
        global _open_panel
        self.drawing.remove()
        if _open_panel is self:
            _open_panel = None
        FreeCADGui.Control.closeDialog()
        return True

    def reject(self):
        return self._close()

    def accept(self):
        return self._close()


class CommandCheckTurning:
    def GetResources(self):
        return {
            "Pixmap": ICON,
            "MenuText": QT_TRANSLATE_NOOP("FreeCADGroove_CheckTurning", "Check turning"),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FreeCADGroove_CheckTurning",
                "Simulate the Job's Groove ops on the turned section of its stock: what is removed, gouges "
                "into the part (red), material left in the grooves (orange), rapids through stock, machining time",
            ),
        }

    def IsActive(self):
        from .command import _jobs

        doc = FreeCAD.ActiveDocument
        return doc is not None and bool(_jobs(doc))

    def Activated(self):
        from .command import _jobs, job_of_selection

        doc = FreeCAD.ActiveDocument
        jobs = _jobs(doc) if doc is not None else []
        job = job_of_selection(jobs) or (jobs[0] if len(jobs) == 1 else None)
        if job is None and jobs:
            import PathScripts.PathUtils as PathUtils

            job = PathUtils.UserInput.chooseJob(jobs)
        if job is None:
            return None
        global _open_panel
        if _open_panel is not None and FreeCADGui.Control.activeDialog():  # a second run: the new result
            _open_panel.job = job
            _open_panel.check()
            return _open_panel
        if FreeCADGui.Control.activeDialog():
            FreeCADGui.Control.closeDialog()
        _open_panel = TurningPanel(job)
        FreeCADGui.Control.showDialog(_open_panel)
        return _open_panel


def register():
    add_to_cam(COMMAND_CHECK, CommandCheckTurning(), TOOLBAR, MENU_AFTER)
