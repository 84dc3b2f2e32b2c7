"""How many moves a CYCLE93 groove expands into, counted from its corners
before anything is expanded, and the refusal of a call beyond ``MAX_MOVES``.

What grows with the parameters:
- the plunges across the opening: its width over the width step, 95 % of
  (tool width - 2 x corner radius) (WIDG, or DEPG through angled flanks);
- the infeeds of each plunge: its depth over IDEP (DEPG or IDEP; ANGC when
  the contour's rise under the blade is deeper than DEPG);
- the points of the contour passes: the chords of the envelope's arcs (the
  profile's radii RCO, RCI widened or narrowed by the blade's corner radius,
  and the blade's corners rolling over the profile's vertices), PATH_TOLERANCE
  from the true arcs, and the points where its pieces meet.

Each count is arithmetic on the groove's corners (upper bounds, as floats, so
that even an infinite count compares): nothing loops over a count, and the
check takes as long for IDEP 1e-300 as for IDEP 1.
"""

import math
from typing import TYPE_CHECKING, Sequence

from ..envelope_curves import outside_step
from ..numbers import MAX_MOVES
from .cycle93_constants import EPS, PATH_TOLERANCE, WIDTH_STEP_FACTOR, cycle93_error

if TYPE_CHECKING:  # the geometry imports this module
    from .cycle93_geometry import GrooveGeometry
    from .cycle93_profile import Corner

# Moves besides the plunges and the contour passes: the approach (at most 3)
# and the retreat (at most 3) with a margin.
FRAME_MOVES = 8
# A trace's envelope is the maximum of its contact curves (three for each
# vertex of the profile, one or two for each line or arc): each curve gives
# at most this many pieces, and each piece up to three points besides its
# chords (its start, a wall's second point, the rounding up of its chords).
PIECES_PER_CURVE = 4
POINTS_PER_PIECE = 3


def arc_chords(radius: float, turn: float, tol: float = PATH_TOLERANCE) -> float:
    """Chords a trace takes for ``turn`` radians of a ``radius`` arc of the
    envelope, on the safe side (a polygon outside it, 0 without an arc);
    infinite when the step underflows."""
    if radius <= 0 or turn <= 0:
        return 0.0
    step = outside_step(radius, tol)
    return math.ceil(turn / step) if step > 0 else math.inf


def trace_points(corners: Sequence["Corner"], blade_radius: float) -> float:
    """An upper bound of the points of the traces over one profile (its four
    corners between the contour's ends), however they split it."""
    vertices = 2 + 3 * len(corners)  # the contour's ends; two ends and a bump's top a corner
    elements = 1 + 2 * len(corners)
    curves = 3 * vertices + 2 * elements
    chords = 2 * vertices * arc_chords(blade_radius, math.pi / 2)  # a blade corner over a vertex
    for c in corners:
        if c.value > 0:
            chords += arc_chords(c.value + blade_radius, c.turn)  # a bowl's R - r takes fewer
    return chords + POINTS_PER_PIECE * PIECES_PER_CURVE * curves


def plunge_count(lo: float, hi: float, width: float, radius: float) -> float:
    """Plunges ``GrooveGeometry.plunge_positions`` makes over the opening lo..hi."""
    span = hi - width - lo
    if not span > EPS:
        return 1.0
    step = WIDTH_STEP_FACTOR * (width - 2 * radius)
    steps = span / step - 1e-9 if step > 0 else math.inf
    return math.ceil(steps) + 1.0 if math.isfinite(steps) else steps


def infeed_count(depth: float, idep: float) -> float:
    """Infeeds of a plunge ``depth`` deep in steps of at most ``idep``."""
    steps = depth / idep - 1e-9
    return max(1.0, math.ceil(steps) if math.isfinite(steps) else steps)


def _count_text(count: float, what: str) -> str:
    """``3 plunges``, ``1 infeed``, ``6.32e+300 plunges``."""
    number = "%d" % count if count < 1e15 else "%.3g" % count
    return "%s %s" % (number, what if count == 1 else what + "s")


class ExpansionSize:
    """The counts of one groove, from its corners (GrooveGeometry before its
    profiles are traced); each an upper bound."""

    def __init__(self, geo: "GrooveGeometry") -> None:
        tool, p = geo.tool, geo.params
        self.geo = geo
        rough = geo.rough_corners
        lo, hi = rough[0].vertex[0], rough[-1].vertex[0]
        if geo.slope != 0:
            # The plunges may run on over the opening's lower edge (GrooveGeometry.pass_range): by less
            # than the blade's flat front, on either side as far as this count knows.
            reach = tool.width - 2 * tool.corner_radius
            lo, hi = lo - reach, hi + reach
        self.plunges = plunge_count(lo, hi, tool.width, tool.corner_radius)
        top = max(geo.contour_top(lo), geo.contour_top(hi - tool.width))
        bottom = min(c.vertex[1] for c in rough)
        self.infeeds = infeed_count(top - bottom, p["IDEP"])
        # Over, the infeeds, the chip-breaking retracts and re-entries, the
        # dwell, the free-off, out: 1 + n + 2 (n - 1) + 3.
        self.plunge_moves = self.plunges * (3 * self.infeeds + 2)
        self.contour_moves = sum(trace_points(corners, tool.corner_radius) for corners in (rough, geo.final_corners))
        # Each of the (at most four) passes is split where it crosses a plunge position, and past an edge where
        # the flat front leaves the opening and where it stands lowest (GrooveGeometry._contour_passes).
        self.contour_moves += 4 * (self.plunges + 4)
        self.moves = FRAME_MOVES + self.plunge_moves + self.contour_moves

    def check(self) -> None:
        """Raise CycleError naming the parameter to blame when the expansion
        could hold more than MAX_MOVES moves."""
        if self.moves <= MAX_MOVES:
            return
        geo, tool, p = self.geo, self.geo.tool, self.geo.params
        if self.infeeds > self.plunges:
            # DEPG or IDEP: the one further from the tool width in orders of
            # magnitude (DEPG / width > width / IDEP).
            name = "DEPG" if p["DEPG"] * p["IDEP"] > tool.width ** 2 else "IDEP"
            if tool.width * abs(geo.slope) > p["DEPG"]:
                name = "ANGC"  # a contour nearly square to the groove's axis: the rise under the blade
        else:
            # Across: WIDG, unless angled flanks widen the opening more.
            opening = geo.rough_corners[-1].vertex[0] - geo.rough_corners[0].vertex[0]
            name = "WIDG" if p["WIDG"] >= opening - p["WIDG"] else "DEPG"
        step = WIDTH_STEP_FACTOR * (tool.width - 2 * tool.corner_radius)
        raise cycle93_error(
            name, getattr(geo.call, name.lower()),
            "gives %s (steps of at most %s across) of up to %s, and up to %s of contour passes: more than the %d "
            "moves an expansion may hold"
            % (_count_text(self.plunges, "plunge"), "%g" % step, _count_text(self.infeeds, "infeed"),
               _count_text(self.contour_moves, "move"), MAX_MOVES),
        )
