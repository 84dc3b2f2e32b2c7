"""The picture of a verified program (the command line's ``plot``): the XZ
half section with Z to the right and X (the radius) up, as a lathe drawing.

Drawn: the stock (light grey), the part the program declares (grey), what
the program leaves standing (outlined), the reference corner's path (rapids
dashed blue, feeds solid black), gouges (red), leftover the blade could reach
(magenta) and unreachable material (orange). matplotlib is imported here
only (its object API, no pyplot: no window, no global state); this module is
imported only by ``plot``.
"""

from __future__ import annotations

import io

from matplotlib.figure import Figure
from matplotlib.patches import PathPatch
from matplotlib.path import Path

from freecad_groove.engine.moves import DWELL, FEED, RAPID

from .program_check import ProgramCheck

STOCK, PART, GOUGE, LEFTOVER, UNREACHABLE = "#e6e6e6", "#9a9a9a", "#d62728", "#c000c0", "#ff9900"
FIGURE_INCHES = (10.0, 5.0)
PNG_DPI = 150


def _polygons(geometry) -> list:
    if geometry.is_empty:
        return []
    if hasattr(geometry, "geoms"):
        return [p for g in geometry.geoms for p in _polygons(g)]
    return [geometry] if geometry.geom_type == "Polygon" else []


def _rings(geometry) -> list:
    """The closed (z, x) outlines of a region: a Section (the column model) or a shapely geometry."""
    if hasattr(geometry, "outlines"):
        return [outline.tolist() for outline in geometry.outlines()]
    return [list(ring.coords) for polygon in _polygons(geometry) for ring in [polygon.exterior, *polygon.interiors]]


def _patch(geometry, **style) -> PathPatch | None:
    """One patch of the outlines of ``geometry`` (z, x), holes kept."""
    paths = [Path(ring, closed=True) for ring in _rings(geometry)]
    if not paths:
        return None
    return PathPatch(Path.make_compound_path(*paths), **style)


def _add(ax, geometry, label: str, **style) -> None:
    patch = _patch(geometry, label=label, **style)
    if patch is not None:
        ax.add_patch(patch)


def _moves(ax, result: ProgramCheck) -> None:
    """The reference corner's path: rapids dashed, feeds solid (labelled once each)."""
    labels = {RAPID: "rapid (G0)", FEED: "feed (G1/G2/G3, cycles)"}
    styles = {RAPID: dict(color="#1f77b4", linestyle="--", linewidth=0.7),
              FEED: dict(color="black", linestyle="-", linewidth=0.8)}
    for step in result.steps:
        position = step.start
        for move in step.moves:
            if move.kind == DWELL:
                continue
            end = (move.x, move.z)
            ax.plot([position[1], end[1]], [position[0], end[0]], label=labels.pop(move.kind, None),
                    **styles[move.kind])
            position = end


def _add_each(ax, checks, attribute: str, label: str, **style) -> None:
    """Each op's region ``attribute``, labelled once."""
    for check in checks:
        region = getattr(check, attribute)
        if not region.is_empty:
            _add(ax, region, label, **style)
            label = None


def draw(result: ProgramCheck, fmt: str) -> bytes:
    """The picture as SVG or PNG bytes (``fmt`` "svg" or "png")."""
    job = result.job
    figure = Figure(figsize=FIGURE_INCHES)
    ax = figure.add_subplot()
    _add(ax, job.stock, "stock", facecolor=STOCK, edgecolor="none")
    _add(ax, job.part, "part (stock less the declared grooves)", facecolor=PART, edgecolor="none")
    _add(ax, job.remaining, "left standing", facecolor="none", edgecolor="#404040", linewidth=0.6)
    _add_each(ax, job.ops, "gouge_region", "gouge", facecolor=GOUGE, edgecolor=GOUGE)
    _add_each(ax, job.ops, "leftover_region", "leftover (reachable)", facecolor=LEFTOVER, edgecolor=LEFTOVER)
    _add_each(ax, job.ops, "unreachable_region", "unreachable", facecolor=UNREACHABLE, edgecolor=UNREACHABLE)
    _moves(ax, result)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("Z (mm)")
    ax.set_ylabel("X radius (mm)")
    ax.set_title("%s: %s" % (result.name, "ok" if result.ok else "%d problem(s)" % len(result.findings)))
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small")
    figure.tight_layout()
    buffer = io.BytesIO()
    metadata = {"Date": None} if fmt == "svg" else {}
    figure.savefig(buffer, format=fmt, dpi=PNG_DPI, metadata=metadata)
    return buffer.getvalue()
