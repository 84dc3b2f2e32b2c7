"""Plain data shared by every cycle: expanded moves, the grooving tool, the
machine state a cycle starts from.

Coordinates are always *radius* X and absolute Z in the program's length unit.
Diameter/radius programming, incremental words and dialect syntax are handled
at the edges (the cycle parsers read them, the dialect writers write them).
"""

from dataclasses import dataclass
from typing import NamedTuple, Optional, Tuple

from .errors import CycleError

RAPID = "G0"
FEED = "G1"
DWELL = "G4"
DRESS = "dress"  # a call of the wheel's dress subprogram (grinding cycles): p = its program number
# Arcs, in the plane of the moves (a lathe's XZ, G18; a mill-style program's XY, G17): clockwise and
# counter-clockwise seen from the plane's positive normal (G18: from +Y, with Z to the right and X up;
# G17: from +Z, with X to the right and Y up), as G2 and G3 turn on every control written for.
ARC_CW = "G2"
ARC_CCW = "G3"
ARCS = (ARC_CW, ARC_CCW)


class Move(NamedTuple):
    """One expanded move of the tool's reference corner.

    kind  RAPID, FEED, ARC_CW, ARC_CCW, DWELL or DRESS (a dress subprogram
          call, at the position held; each target writes its own subprogram call).
    x, z  target (radius, absolute); for DWELL the position held. x None: X
          (and Y) not moved, a mill's Z-only rapid (Milltronics G31/G32);
          z None: Z not moved, a mill's X Y rapid at the height held when
          the Z before a Milltronics G33/G34 is not known.
    f     feed for FEED moves, None = the feed already in force.
    p     dwell time in seconds for DWELL, the program number for DRESS, else 0.
    y     target Y of a cycle on a machine with a Y axis (mill-style
          programs; X is then a plain coordinate, not a radius); None: the
          axis is not moved (every lathe cycle).
    c     target of the rotary C axis in degrees (cylinder interpolation);
          None: not moved.
    centre  an arc's centre (ARC_CW, ARC_CCW) in the plane of the move,
          absolute: (x radius, z) on a lathe, (x, y) mill-style.
    radius  an arc given by its radius instead (a program's R or CR= word,
          kept as programmed): positive up to 180 degrees; None: by centre.
    A target that cannot write an axis a move sets refuses the move
    (targets.py) rather than dropping it.
    """

    kind: str
    x: Optional[float]
    z: Optional[float]
    f: Optional[float] = None
    p: float = 0.0
    y: Optional[float] = None
    c: Optional[float] = None
    centre: Optional[Tuple[float, float]] = None
    radius: Optional[float] = None


def rapid(x: float, z: float) -> Move:
    return Move(RAPID, x, z)


def feed(x: float, z: float, f: Optional[float] = None) -> Move:
    return Move(FEED, x, z, f)


def arc(clockwise: bool, x: float, z: float, centre: Tuple[float, float], f: Optional[float] = None) -> Move:
    """An arc to (x, z) about ``centre`` (absolute, the plane's coordinates)."""
    return Move(ARC_CW if clockwise else ARC_CCW, x, z, f, centre=centre)


def dwell(x: float, z: float, seconds: float) -> Move:
    return Move(DWELL, x, z, None, seconds)


# Plunge directions: which way the tool's front edge cuts.
MINUS_X = "-X"  # external longitudinal groove, cut-off
PLUS_X = "+X"  # internal longitudinal groove
MINUS_Z = "-Z"  # face groove in a face looking toward +Z
PLUS_Z = "+Z"  # face groove in a face looking toward -Z
PLUNGE_DIRECTIONS = (MINUS_X, PLUS_X, MINUS_Z, PLUS_Z)

# Which of the two front corners the moves drive.
REFERENCE_MINUS = "minus"  # the corner on the tool's -Z side (X plunges) or -X side (Z plunges)
REFERENCE_PLUS = "plus"


@dataclass(frozen=True)
class GroovingTool:
    """A grooving/parting blade: a flat front edge ``width`` wide with both front
    corners rounded by ``corner_radius``.

    Expanded moves drive the *reference corner*: the imaginary sharp corner where
    the front edge meets a side edge. With ``reference="minus"`` (default) that is
    the side toward -Z for X plunges (the blade extends from the reference toward
    +Z) and toward -X for Z plunges (the blade extends toward +X).
    """

    width: float
    corner_radius: float = 0.0
    reference: str = REFERENCE_MINUS
    length: float = 60.0  # usable blade length behind the front edge (simulation, reach checks)

    def validate(self, cycle: Optional[str] = None) -> "GroovingTool":
        """Refuse a blade no cycle can run with; returns self."""
        if not self.width > 0:
            raise CycleError("tool width", self.width, "must be greater than 0", cycle=cycle)
        if self.corner_radius < 0:
            raise CycleError("tool corner radius", self.corner_radius, "must not be negative", cycle=cycle)
        if not self.corner_radius < self.width / 2:
            raise CycleError(
                "tool corner radius",
                self.corner_radius,
                "must be less than half the tool width %g" % self.width,
                cycle=cycle,
            )
        if self.reference not in (REFERENCE_MINUS, REFERENCE_PLUS):
            raise CycleError("tool reference corner", self.reference, "must be 'minus' or 'plus'", cycle=cycle)
        return self

    @property
    def reference_offset(self) -> float:
        """Distance from the blade's minus-side edge to the reference corner."""
        return 0.0 if self.reference == REFERENCE_MINUS else self.width


@dataclass
class MachineState:
    """Where the tool is and which modes are in force when a cycle is called.

    x is a radius. ``diameter_mode`` says how X *words* are read (G7/DIAMON...),
    ``incremental`` whether words are G91-style.
    """

    x: float = 0.0
    z: Optional[float] = 0.0  # None: not known (only a cycle with FROM_UNKNOWN_Z is called so)
    feed: Optional[float] = None
    diameter_mode: bool = True
    incremental: bool = False
    metric: bool = True
    feed_per_rev: Optional[bool] = False
    c: Optional[float] = None  # the rotary C axis in degrees (GSK G7.1); None: unknown or no C axis
    y: Optional[float] = None  # mill-style programs (grinders): the Y position; None on a lathe or unknown
