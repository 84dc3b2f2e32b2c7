"""Coin line sets drawn in the 3D view, and the colours of the moves: what
the ops' previews and the turning check's drawing are made of.

Not stored in documents: free to move.
"""

from pivy import coin

RAPID_COLOR = (0.85, 0.1, 0.1)
FEED_COLOR = (0.1, 0.35, 1.0)


def line_nodes(color: tuple, width: float, pattern: object = None) -> tuple:
    """(separator, coordinates, line set) of Coin nodes drawing lines in ``color``."""
    sep = coin.SoSeparator()
    mat = coin.SoBaseColor()
    mat.rgb.setValue(*color)
    style = coin.SoDrawStyle()
    style.lineWidth = width
    if pattern is not None:
        style.linePattern = pattern
    coords = coin.SoCoordinate3()
    lines = coin.SoLineSet()
    for node in (mat, style, coords, lines):
        sep.addChild(node)
    return sep, coords, lines


def fill_lines(coords: object, lines: object, polys: list) -> None:
    """The Coin nodes ``coords`` and ``lines`` (line_nodes) drawing the polylines ``polys``."""
    points = [p for poly in polys for p in poly]
    coords.point.setNum(0)
    lines.numVertices.setNum(0)
    if points:
        coords.point.setValues(0, len(points), points)
        lines.numVertices.setValues(0, len(polys), [len(poly) for poly in polys])
