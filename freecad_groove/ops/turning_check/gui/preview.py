"""The turning check's half section, drawn in the 3D view over the part
while its panel is open: in the XZ plane at Y = 0 (X = radius), like the
op's Path and the Groove panel's preview, in an SoAnnotation: the stock left
standing (grey outline), gouges (red), material left in the grooves that the
blade could reach (orange), what it cannot reach (yellow), and where a
blade's holder enters standing material: that material (magenta) and the
holder's outline at the end of each move that does (violet; the first
HOLDER_OUTLINES of an op).
"""

from pivy import coin

from ....gui.lines import fill_lines, line_nodes

REMAINING_COLOR = (0.45, 0.45, 0.45)
GOUGE_COLOR = (0.9, 0.0, 0.0)
LEFTOVER_COLOR = (1.0, 0.55, 0.0)
UNREACHABLE_COLOR = (0.9, 0.8, 0.0)
HOLDER_COLOR = (0.85, 0.0, 0.85)
HOLDER_OUTLINE_COLOR = (0.5, 0.2, 0.9)
HOLDER_OUTLINES = 3


def rings(geometry):
    """Every outline of a region as (x, 0, z) points: a verify.shapes.Section
    (the turning check's column model) or a shapely (z, x) geometry (rings:
    exteriors and holes)."""
    out = []
    if geometry is None or geometry.is_empty:
        return out
    if hasattr(geometry, "outlines"):
        return [[(float(x), 0.0, float(z)) for z, x in outline] for outline in geometry.outlines()]
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
              ("leftover", LEFTOVER_COLOR, 3), ("gouge", GOUGE_COLOR, 4), ("holder", HOLDER_COLOR, 4),
              ("holder outline", HOLDER_OUTLINE_COLOR, 2))

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
            "holder": [r for op in ops for r in rings(op.holder_region)],
            "holder outline": [[(float(x), 0.0, float(z)) for z, x in hit.outline]
                               for op in ops for hit in op.holder_hits[:HOLDER_OUTLINES]],
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
