"""The live preview: what the op would cut, drawn in the 3D view while the
task panel is open, from the panel's values (the document is not touched).

Drawn in the XZ plane at Y = 0 (X = radius), the plane the op's Path uses:
- the finished groove's cross-section of every groove (orange, thick),
- the expanded toolpath: rapids (red, dashed) and feeds (blue), arcs as
  chords within PREVIEW_ARC_TOL of them.

It sits in an SoAnnotation, drawn over the part: the section plane runs
through the solid, where the part's own faces would hide it.
"""

from pivy import coin

from ....engine.arcs import arc_chords
from ....engine.moves import ARC_CW, ARCS, FEED, RAPID
from ....gui.lines import FEED_COLOR, RAPID_COLOR, fill_lines, line_nodes

SECTION_COLOR = (1.0, 0.55, 0.0)
PREVIEW_ARC_TOL = 0.001  # mm: the chords an arc is drawn with stay this close to it


def polylines(plans):
    """([section polyline], [rapid segment], [feed segment]) of ``plans``
    (GroovePlan list), each a list of (x, y, z) points."""
    sections, rapids, feeds = [], [], []
    prev_start = (None, None)  # each link starts at the previous groove's start point
    for p in plans:
        region = [(x, 0.0, z) for x, z in p.geometry.region_world()]
        if region:
            sections.append(region + [region[0]])
        # The first link starts wherever the tool is: drawn from its first known point.
        cur_x, cur_z = prev_start
        for x, z in p.link:
            nx = cur_x if x is None else x
            nz = cur_z if z is None else z
            if None not in (cur_x, cur_z, nx, nz):
                rapids.append([(cur_x, 0.0, cur_z), (nx, 0.0, nz)])
            cur_x, cur_z = nx, nz
        cur = (p.start.x, 0.0, p.start.z)
        prev_start = (p.start.x, p.start.z)
        for m in p.moves:
            if m.kind in ARCS:
                points = arc_chords((cur[0], cur[2]), (m.x, m.z), m.centre, m.kind == ARC_CW, PREVIEW_ARC_TOL)
                feeds.append([cur] + [(x, 0.0, z) for x, z in points])
            elif m.kind not in (RAPID, FEED):
                continue
            else:
                (rapids if m.kind == RAPID else feeds).append([cur, (m.x, 0.0, m.z)])
            cur = (m.x, 0.0, m.z)
    return sections, rapids, feeds


class Preview:
    """Coin nodes in a view's scene graph; show(plans) redraws, remove() takes
    them out. ``sections``/``rapids``/``feeds`` hold what is drawn."""

    def __init__(self, view):
        self.view = view
        self.root = coin.SoAnnotation()
        self.root.setName("FreeCADGroovePreview")
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        self.root.addChild(pick)
        self._section = line_nodes(SECTION_COLOR, 3)
        self._rapid = line_nodes(RAPID_COLOR, 1, 0x0F0F)
        self._feed = line_nodes(FEED_COLOR, 1.5)
        for separator, _coords, _line_set in (self._section, self._rapid, self._feed):
            self.root.addChild(separator)
        self.sections, self.rapids, self.feeds = [], [], []
        self.updates = 0  # how many times it was redrawn
        self._graph = view.getSceneGraph() if view is not None else None
        if self._graph is not None:
            self._graph.addChild(self.root)

    def in_scene(self):
        return self._graph is not None and self._graph.findChild(self.root) >= 0

    def show(self, plans):
        self.sections, self.rapids, self.feeds = polylines(plans)
        drawn = ((self._section, self.sections), (self._rapid, self.rapids), (self._feed, self.feeds))
        for (_separator, coords, line_set), polys in drawn:
            fill_lines(coords, line_set, polys)
        self.updates += 1

    def clear(self):
        self.show([])

    def remove(self):
        if self._graph is not None and self._graph.findChild(self.root) >= 0:
            self._graph.removeChild(self.root)
        self._graph = None
