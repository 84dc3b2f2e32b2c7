"""What a program makes the tool do, block by block, for the command line's
``verify`` and ``plot``: the translator reads the program (every check of
``expand`` applies) and this module records, with each block's line, the
moves it makes, the blade cutting them, the feeds and speeds in force and,
for a cycle call, the grooves the call declares.

It reads the translator's work through four of its methods, wrapped here (the
engine never imports this package): ``_motion`` (a G0/G1/G2/G3 block: its end
point, arc words), ``_dwell_seconds`` (a G4's time), ``_collect_warnings``
(a cycle call: the model, its start and settings) and ``_after_cycle`` (the
expanded moves).

Everything recorded is in mm (an inch program is scaled), X a radius;
geometry as lists of (x, z) points like ``moves.Move``.

Choices (docs/command-line.md, "Choices of verify and plot"):

* An arc G2/G3 becomes chords no farther than ARC_CHORD_TOL from the arc;
  a cycle's arcs (CYCLE93's contour and finishing passes) become chords no
  farther than arcs.SWEEP_TOL, the simulation's own. Seen with Z to the right
  and X (the radius) up, G2 turns clockwise (the plane G18 seen from +Y).
* A CYCLE93 call declares its groove by its profile (GrooveGeometry's
  region); a pecking cycle (G77/G76, G75/G74) one groove per plunge position:
  the blade's outline swept from the cycle's start to its bottom.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Optional

from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.pecking import PeckingCycle
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import DWELL, FEED, MINUS_X, PLUS_X, RAPID, GroovingTool, Move
from freecad_groove.engine.numbers import MM_PER_INCH
from freecad_groove.engine.tool_table import blade_for
from freecad_groove.engine.translator import Translator, program_lines

from . import arcs
from .arcs import SWEEP_TOL, radius_centre, straightened
from .outline import clip_to_box, swept_hull

Point = tuple[float, float]  # (x, z), x the radius

ARC_CHORD_TOL = 0.0005  # mm: the chords of a G2/G3 stay this close to the arc (half the check's tolerance)
CONTOUR_AIR = 1000.0  # mm: how far above a CYCLE93's contour line the air it takes reaches
FEET_PER_METRE = 1000.0 / 25.4 / 12.0


@dataclass(frozen=True)
class SpeedState:
    """The feed mode and spindle in force (mm, mm/min or mm/rev, m/min)."""

    feed: Optional[float]
    per_rev: bool
    rpm: Optional[float]
    surface_speed: Optional[float]
    max_rpm: Optional[float]


@dataclass
class Step:
    """A cycle call, or the plain blocks (G0/G1/G2/G3, G4) between two calls
    with one tool: ``lines`` the line of each move; ``grooves`` the grooves a
    call declares (closed (x, z) rings)."""

    label: str
    line: int
    start: Point
    tool: Optional[int]
    scale: float = 1.0  # mm per program unit when the step runs (the blade's lengths are program units)
    blade: Optional[GroovingTool] = None
    plunge: Optional[str] = None
    cycle: bool = False
    moves: list[Move] = field(default_factory=list)
    lines: list[int] = field(default_factory=list)
    speeds: list[SpeedState] = field(default_factory=list)
    grooves: list[list[Point]] = field(default_factory=list)
    air: list[list[Point]] = field(default_factory=list)  # what the call takes to be air already


MILLED = ("%s: verify and plot check turning programs (the lathe's XZ section); a program that turns the C axis "
          "(G7.1, a live tool) mills, which they do not simulate")


class RecordingTranslator(Translator):
    """A Translator that records the Steps of the program it reads."""

    def _c_value(self, word, kind):  # a C position: the program mills with the C axis
        self._fail(MILLED % ("C" + word.text))

    def run_cycle(self, block, entry, call, label):
        if entry.cycle_class.C_AXIS:
            self._fail(MILLED % entry.cycle_class.NAME)
        super().run_cycle(block, entry, call, label)

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.steps: list[Step] = []
        self.first_approach: Optional[Point] = None
        self._call: Optional[tuple] = None
        self._speed_states: dict[tuple, SpeedState] = {}

    # -- units and state --------------------------------------------------------

    def _mm(self) -> float:
        return 1.0 if self.state.metric else MM_PER_INCH

    def _position(self) -> Optional[Point]:
        state, scale = self.state, self._mm()
        if state.x is None or state.z is None:
            return None
        return (state.x * scale, state.z * scale)

    def _speeds(self, feed: Optional[float] = None) -> SpeedState:
        state, scale = self.state, self._mm()
        feed = state.feed if feed is None else feed
        surface = None
        if state.css and state.spindle is not None:
            surface = state.spindle if state.metric else state.spindle / FEET_PER_METRE
        values = (None if feed is None else feed * scale, bool(state.feed_per_rev),
                  None if state.css else state.spindle, surface, state.speed_limit)
        known = self._speed_states.get(values)  # one object per state: a program's moves share a few
        if known is None:
            known = self._speed_states[values] = SpeedState(*values)
        return known

    def _plain_step(self, start: Point) -> Step:
        """The open plain step of the tool in force, a new one when there is none."""
        last = self.steps[-1] if self.steps else None
        if last is None or last.cycle or last.tool != self.state.tool or last.scale != self._mm():
            last = Step("moves", self._line, start, self.state.tool, self._mm())
            self.steps.append(last)
        return last

    def _add(self, moves: list[Move], start: Point) -> None:
        step = self._plain_step(start)
        step.moves.extend(moves)
        step.lines.extend([self._line] * len(moves))
        step.speeds.extend([self._speeds()] * len(moves))
        if self.first_approach is None and moves and moves[0].kind == RAPID:
            self.first_approach = (moves[-1].x, moves[-1].z)

    # -- the wrapped translator methods -----------------------------------------

    def _motion(self, block, groups, output) -> None:
        start = self._position()
        super()._motion(block, groups, output)
        end = self._position()
        if start is None or end is None or not block.letters() & {"X", "Z", "U", "W"}:
            if end is not None and self.first_approach is None and self.state.motion == RAPID:
                self.first_approach = end
            return
        kind = self.state.motion
        if kind in (RAPID, FEED):
            self._add([Move(kind, end[0], end[1])], start)
        else:
            centre = self._arc_centre(block, start, end, kind)
            self._add([Move(FEED, x, z) for x, z in arc_chords(start, end, centre, kind == "G2")], start)

    def _arc_centre(self, block, start: Point, end: Point, kind: str) -> Point:
        scale = self._mm()
        radius_word = block.get("R") or block.get("CR")
        if radius_word is None:
            i, k = (block.get(letter) for letter in ("I", "K"))
            return (start[0] + (i.value * scale if i else 0.0), start[1] + (k.value * scale if k else 0.0))
        return radius_centre(start, end, radius_word.value * scale, kind == "G2")

    def _dwell_seconds(self, reading, word) -> float:
        seconds = super()._dwell_seconds(reading, word)
        where = self._position()
        if where is not None:
            self._add([Move(DWELL, where[0], where[1], None, seconds)], where)
        return seconds

    def _collect_warnings(self, entry, model, start, settings) -> None:
        super()._collect_warnings(entry, model, start, settings)
        self._call = (entry, model, start, settings)

    def _after_cycle(self, moves) -> None:
        start, feed = self._position(), self.state.feed
        super()._after_cycle(moves)
        entry, model, machine, settings = self._call
        scale = self._mm()
        try:
            blade = blade_for(self.state.tool, self.tools, settings.tool)
        except ProgramError as exc:
            self._fail("verify needs the blade of %s: %s" % (entry.name, exc))
        step = Step("%s (line %d)" % (entry.name, self._line), self._line, start, self.state.tool, scale,
                    mm_blade(blade, scale), cycle=True)
        scaled = [mm_move(move, scale) for move in moves]
        feeds = []
        for move in moves:  # a move without F runs at the last F before it
            feed = feed if move.f is None else move.f
            feeds.append(feed)
        speeds = [self._speeds(f) for f in feeds]
        for index, move in straightened(scaled, start, SWEEP_TOL):  # its arcs as chords, like a G2/G3 block's
            step.moves.append(move)
            step.speeds.append(speeds[index])
        step.lines = [self._line] * len(step.moves)
        step.plunge, grooves, air = declared_grooves(entry.name, model, machine, settings, blade)
        step.grooves = [[(x * scale, z * scale) for x, z in ring] for ring in grooves]
        step.air = [[(x * scale, z * scale) for x, z in ring] for ring in air]
        if self.first_approach is None:
            self.first_approach = start
        self.steps.append(step)


def mm_move(move: Move, scale: float) -> Move:
    """The move in mm (``scale`` mm per program unit): its end, an arc's centre and radius."""
    if scale == 1.0:
        return move
    centre = None if move.centre is None else (move.centre[0] * scale, move.centre[1] * scale)
    return move._replace(x=move.x * scale, z=move.z * scale, centre=centre,
                         radius=None if move.radius is None else move.radius * scale)


def mm_blade(blade: GroovingTool, scale: float) -> GroovingTool:
    """The blade with its width and corner radius in mm (``scale`` mm per program unit)."""
    if scale == 1.0:
        return blade
    return replace(blade, width=blade.width * scale, corner_radius=blade.corner_radius * scale)


# ---------------------------------------------------------------- geometry


def arc_chords(start: Point, end: Point, centre: Point, clockwise: bool) -> list[Point]:
    """Points (x, z) along the arc from start to end (end included), chords within ARC_CHORD_TOL."""
    return arcs.arc_chords(start, end, centre, clockwise, ARC_CHORD_TOL) or [end]


Rings = list[list[Point]]


def declared_grooves(name: str, model, start, settings, blade: GroovingTool) -> tuple[str, Rings, Rings]:
    """(plunge direction, the grooves the call declares, what it takes to be
    air already), (x, z) rings in the program's units. CYCLE93 takes the
    contour turned: the air above its contour line across the groove's
    window (GrooveGeometry.final_top's ends)."""
    if isinstance(model, PeckingCycle):  # G77/G76, G75/G74
        plunge = model.plunge_direction(start)
        bottom, p0, positions, _peck = model._grooves(start)
        return plunge, [_plunge_groove(model.AXIS, plunge, blade, p0, bottom, s) for s in positions], []
    if isinstance(model, Cycle93):
        geometry = model.geometry(replace(settings, tool=blade), start.metric)
        lo, hi, m = geometry.final_top[0][0], geometry.final_top[-1][0], geometry.slope
        above = [(lo, m * lo), (hi, m * hi), (hi, m * hi + CONTOUR_AIR), (lo, m * lo + CONTOUR_AIR)]
        air = [geometry.frame.point(u, v) for u, v in above]
        # the groove as declared, its arcs within the simulation's own tolerance (PATH_TOLERANCE is in
        # the program's units: 0.005 mm in an inch program, as much as the exact arcs the passes cut)
        return model.plunge_direction(), [geometry.region_world(SWEEP_TOL * _units(start))], [air]
    raise ProgramError("verify does not know the groove %s declares" % name)


def _units(state) -> float:
    """Program units per mm in ``state``."""
    return 1.0 if state.metric else 1.0 / MM_PER_INCH


def _plunge_groove(axis: str, plunge: str, blade: GroovingTool, p0: float, bottom: float, s: float) -> list[Point]:
    """The blade's outline swept from p0 to bottom at s, cut off at p0 (the groove's opening)."""
    a, b = ((p0, s), (bottom, s)) if axis == "X" else ((s, p0), (s, bottom))
    hull = swept_hull(blade, plunge, a, b)
    zmin, xmin = hull.min(axis=0)
    zmax, xmax = hull.max(axis=0)
    if plunge in (MINUS_X, PLUS_X):
        window = (zmin, min(p0, bottom), zmax, max(p0, bottom))
    else:
        window = (min(p0, bottom), xmin, max(p0, bottom), xmax)
    ring = clip_to_box(hull, *window).tolist()
    ring.append(ring[0])
    return [(x, z) for z, x in ring]


def record_program(text, dialect: str, settings, start=None, tools=None) -> RecordingTranslator:
    """Read the whole program; ProgramError on the first line that cannot be translated."""
    translator = RecordingTranslator(dialect, settings, start=start, tools=tools)
    for _chunk in translator.translate(program_lines(text)):
        pass
    return translator
