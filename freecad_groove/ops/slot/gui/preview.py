"""The Cylinder slot panel's live preview: the slot's path on the developed
surface of its cylinder, drawn into a picture in the panel (not the 3D view,
where the op's own Path is drawn wrapped by view.py).

The developed plane: Z to the right, the developed length s = radius * C (C in
radians) up, both in mm at one scale (a true picture). Drawn: the face's Z
range (grey band), the slot as wide as the end mill (light blue), its centre
line (dark blue) with the start marked, and under the picture the passes: the
radius of each rough pass and of the finish (the X the region cuts at).

``developed_path`` is plain Python (testable without Qt); the picture is a
QPixmap painted with QPainter into a QLabel, redrawn at the label's width.
"""

import math
from typing import List, NamedTuple, Optional, Tuple

from PySide import QtCore, QtGui

PICTURE_SIZE = (360, 200)  # px at most
MARGIN = 8  # px around the drawing
FACE_COLOUR = (225, 225, 225)
SLOT_COLOUR = (150, 190, 255)
LINE_COLOUR = (20, 60, 200)
AXIS_COLOUR = (90, 90, 90)  # the axis names: Z to the right, R*C up


class DevelopedPath(NamedTuple):
    """What the picture shows: centre line [(z, s)], slot width, face Z range, radius, pass radii."""

    centre: List[Tuple[float, float]]
    width: float
    face_range: Tuple[float, float]
    radius: float
    pass_radii: List[float]


def developed_path(plan: object, width: float) -> DevelopedPath:
    """The picture's content from a plan.SlotPlan and the end mill's diameter ``width``."""
    cylinder, region, start = plan.cylinder, plan.region, plan.start
    to_s = cylinder.radius * math.pi / 180.0
    z, c = start.z, start.c
    centre = [(z, c * to_s)]
    for block in region.path:
        z = block.z if block.z is not None else z
        c = block.c if block.c is not None else c
        centre.append((z, c * to_s))
    return DevelopedPath(centre, width, (cylinder.z_min, cylinder.z_max), cylinder.radius,
                         list(region.pass_radii(start)))


def passes_text(path: DevelopedPath) -> str:
    """"Passes at R19.6, R19.2; finish R19" (radii in mm)."""
    rough = ", ".join("R%g" % round(r, 4) for r in path.pass_radii[:-1])
    return "Passes at %s; finish R%g" % (rough, round(path.pass_radii[-1], 4))


def _bounds(path: DevelopedPath) -> Tuple[float, float, float, float]:
    half = path.width / 2.0
    zs = [z for z, _s in path.centre] + list(path.face_range)
    ss = [s for _z, s in path.centre]
    return min(zs) - half, max(zs) + half, min(ss) - half, max(ss) + half


def paint(path: DevelopedPath, width: int, height: int) -> object:
    """A QPixmap of ``path`` at ``width`` x ``height`` px."""
    pixmap = QtGui.QPixmap(width, height)
    pixmap.fill(QtCore.Qt.white)
    z0, z1, s0, s1 = _bounds(path)
    scale = min((width - 2 * MARGIN) / max(z1 - z0, 1e-9), (height - 2 * MARGIN) / max(s1 - s0, 1e-9))
    left = (width - (z1 - z0) * scale) / 2.0
    bottom = height - (height - (s1 - s0) * scale) / 2.0

    def at(z: float, s: float) -> object:
        return QtCore.QPointF(left + (z - z0) * scale, bottom - (s - s0) * scale)

    painter = QtGui.QPainter(pixmap)
    painter.setRenderHint(QtGui.QPainter.Antialiasing)
    face = QtCore.QRectF(at(path.face_range[0], s1), at(path.face_range[1], s0))
    painter.fillRect(face, QtGui.QColor(*FACE_COLOUR))
    line = QtGui.QPolygonF([at(z, s) for z, s in path.centre])
    slot_pen = QtGui.QPen(QtGui.QColor(*SLOT_COLOUR), max(1.0, path.width * scale))
    slot_pen.setCapStyle(QtCore.Qt.RoundCap)
    slot_pen.setJoinStyle(QtCore.Qt.RoundJoin)
    painter.setPen(slot_pen)
    painter.drawPolyline(line)
    painter.setPen(QtGui.QPen(QtGui.QColor(*LINE_COLOUR), 1.5))
    painter.drawPolyline(line)
    painter.setBrush(QtGui.QColor(*LINE_COLOUR))
    painter.drawEllipse(line[0], 3.0, 3.0)  # the start
    painter.setPen(QtGui.QColor(*AXIS_COLOUR))
    painter.drawText(QtCore.QPointF(width - MARGIN - 10, height - 3), "Z")
    painter.drawText(QtCore.QPointF(3, MARGIN + 6), "R\u00b7C")
    painter.end()
    return pixmap


class DevelopedPicture(QtCore.QObject):
    """Draws a DevelopedPath (or nothing) into a QLabel at the label's width, at most PICTURE_SIZE; the passes
    in a second label. ``path`` is what is drawn now (None: nothing), ``draws`` how many times it was drawn."""

    def __init__(self, label: object, passes_label: object):
        super().__init__(label)
        self.label, self.passes_label = label, passes_label
        self.path: Optional[DevelopedPath] = None
        self.draws = 0
        label.setSizePolicy(QtGui.QSizePolicy.Ignored, QtGui.QSizePolicy.Fixed)
        label.setMinimumSize(0, 0)
        label.setAlignment(QtCore.Qt.AlignCenter)
        label.installEventFilter(self)

    def eventFilter(self, watched: object, event: object) -> bool:
        if event.type() == QtCore.QEvent.Resize and self.path is not None:
            self._draw()
        return False

    def show(self, path: Optional[DevelopedPath]) -> None:
        self.path = path
        self.passes_label.setText(passes_text(path) if path is not None else "")
        if path is None:
            self.label.clear()
            self.label.setFixedHeight(0)
            return
        self._draw()

    def _draw(self) -> None:
        width = max(40, min(self.label.width() or PICTURE_SIZE[0], PICTURE_SIZE[0]))
        height = max(40, round(width * PICTURE_SIZE[1] / PICTURE_SIZE[0]))
        self.label.setPixmap(paint(self.path, width, height))
        self.label.setFixedHeight(height)
        self.draws += 1
