"""The Plunge grind panel's live preview: the strokes the panel's values
program (the plan's expansion: the wheel's lowest point, at the middle of
its width), drawn in the 3D view while the panel is open; the approach
rapids from the safe height dashed red, the feeds blue. The document is not
touched: the op's own Path follows on OK or Apply.
"""

from typing import List, Tuple

from pivy import coin

from ....engine.moves import FEED
from ....gui.lines import FEED_COLOR, RAPID_COLOR, fill_lines, line_nodes

Point = Tuple[float, float, float]


def plan_points(plan: object) -> Tuple[List[Point], List[Point]]:
    """(approach rapids, feeds) of ``plan`` (plan.GrindPlan) as FreeCAD points: the rapid down
    from the safe height to the start, then every feed move of the expansion."""
    recip, plunge, cross = plan.axes

    def point(r: float, c: float, z: float) -> Point:
        where = {recip: r, cross: c, plunge: z}
        return (where["X"], where["Y"], where["Z"])

    start = point(plan.start.x, plan.start.z, plan.start.y)
    rapids = [point(plan.start.x, plan.start.z, plan.safe_z), start]
    feeds = [start] + [point(m.x, m.z, m.y) for m in plan.moves if m.kind == FEED]
    return rapids, feeds


class GrindPreview:
    """Coin nodes in a view's scene graph (none without a view): show(plan) redraws (None: nothing),
    remove() takes them out. ``feeds`` holds the feed polyline drawn."""

    def __init__(self, view: object):
        self.root = coin.SoAnnotation()  # over the part: the strokes run on its face
        self.root.setName("FreeCADGroovePlungeGrindPreview")
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        self.root.addChild(pick)
        self._rapid = line_nodes(RAPID_COLOR, 1, 0x0F0F)
        self._feed = line_nodes(FEED_COLOR, 1.5)
        for separator, _coords, _lines in (self._rapid, self._feed):
            self.root.addChild(separator)
        self.feeds: List[Point] = []
        self._graph = view.getSceneGraph() if view is not None and hasattr(view, "getSceneGraph") else None
        if self._graph is not None:
            self._graph.addChild(self.root)

    def show(self, plan: object) -> None:
        rapids, self.feeds = plan_points(plan) if plan is not None else ([], [])
        for (_separator, coords, lines), points in ((self._rapid, rapids), (self._feed, self.feeds)):
            fill_lines(coords, lines, [points] if points else [])

    def remove(self) -> None:
        if self._graph is not None:
            self._graph.removeChild(self.root)
            self._graph = None
