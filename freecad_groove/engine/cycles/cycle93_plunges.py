"""Steps 1 and 2 of CYCLE93: the roughing plunges across the groove, with
their chip-breaking retracts, the dwell at the base and the free-off.

The Siemens manual: "From the second cut along the groove width onwards, the tool will
retract by 1 mm before each retraction." Read here as a free-off along the
groove's axis (the frame's u): at the bottom of every plunge after the first,
the blade rapids ``FREE_OFF_MM`` (``FREE_OFF_INCH``) back toward the previous
plunge, away from the wall it has just cut, and only then out, so its side
does not rub that wall on the way up. It is a RAPID, a retract (the manual
leaves G0 or G1 open; Fanuc's G75 relief is one): it is never longer than the
distance to the previous plunge (the blade stays inside the slot already
cut), and there is none when the previous plunge stopped higher (on an angled
flank or a base corner): its slot is not cut down to this depth, so the move
removes nothing.

Each plunge comes over its place VRT above the contour and feeds its first
infeed from there: VRT is the clearance the machinist sets for the stock as
it stands (a rough bar wants more), so no rapid goes below it over stock that
is not cut yet (docs/choices.md).
"""

import math
from typing import TYPE_CHECKING, Callable, List, Optional, Tuple

from ..envelope import Envelope
from ..moves import Move, dwell
from .cycle93_constants import (
    BASE_TOLERANCE,
    EPS,
    FREE_OFF_INCH,
    FREE_OFF_MM,
    REENTRY_CLEARANCE_INCH,
    REENTRY_CLEARANCE_MM,
)
from .cycle93_material import MaterialTop
from .cycle93_size import infeed_count

if TYPE_CHECKING:  # the geometry imports this module
    from .cycle93_geometry import GrooveGeometry

Go = Callable[[str, float, float], None]


def free_off(geo: "GrooveGeometry", u: float, bottom: float, previous: Optional[Tuple[float, float]]) -> float:
    """u the blade frees off to at the bottom of the plunge at ``u``:
    ``previous`` is (u, bottom) of the plunge before it, or None for the
    first. Toward the previous plunge by FREE_OFF_MM (FREE_OFF_INCH), at most
    the distance to it; not at all when its slot is not this deep."""
    if previous is None:
        return u
    u_prev, bottom_prev = previous
    if bottom_prev > bottom + BASE_TOLERANCE:
        return u
    room = abs(u - u_prev)
    step = min(FREE_OFF_MM if geo.metric else FREE_OFF_INCH, room)
    return u - math.copysign(step, u - u_prev)


def base_envelope(geo: "GrooveGeometry") -> Envelope:
    """Where the blade stands on the roughing profile's base line alone
    (extended past both flanks): a plunge whose bottom is there reached the
    base, not a flank or a base corner above it."""
    (u1, v1), (u2, v2) = geo.rough_corners[1].vertex, geo.rough_corners[2].vertex
    lo, hi = geo.rough_top[0][0], geo.rough_top[-1][0]
    line = [(lo, v1 + (lo - u1) * geo.slope), (hi, v2 + (hi - u2) * geo.slope)]
    return Envelope(line, geo.tool.width, geo.tool.corner_radius)


def plunges(geo: "GrooveGeometry", positions: List[float], go: Go, out: List[Move], material: MaterialTop) -> None:
    """Steps 1 and 2: plunges in equal infeeds, each fed from VRT over the
    contour, with chip-breaking retracts (VRT up, then a
    rapid back down the blade's own slot to the re-entry clearance), DWT at
    the bottom of those that reach the base, the free-off (a rapid) from the
    second plunge on, then out; each slot is cleared in ``material``."""
    p = geo.params
    vrt, idep, dwt = p["VRT"], p["IDEP"], p["DWT"]
    reentry = min(vrt, REENTRY_CLEARANCE_MM if geo.metric else REENTRY_CLEARANCE_INCH)
    bottoms = [geo.rough_env.lowest(u) for u in positions]
    base = base_envelope(geo) if dwt > 0 else None  # only a dwell asks where the base is
    previous = None
    for u, bottom in zip(positions, bottoms):
        top = geo.contour_top(u)
        if bottom >= top - EPS:
            continue  # the blade cannot enter here without cutting the allowance
        go("r", u, top + vrt)
        total = top - bottom
        n = int(infeed_count(total, idep))  # the count ExpansionSize checked before expanding
        inc = total / n
        for k in range(1, n + 1):
            level = bottom if k == n else top - k * inc
            go("f", u, level)
            if k < n:
                go("r", u, level + vrt)
                go("r", u, level + reentry)  # only through the slot just cut
        if base is not None and bottom <= base.lowest(u) + BASE_TOLERANCE:
            x, z = geo.frame.blade(u, bottom)
            out.append(dwell(x, z, dwt))
        freed = free_off(geo, u, bottom, previous)
        if freed != u:
            go("r", freed, bottom)  # a retract inside the slots already cut this deep (FREE_OFF_RAPID)
        # Out to the plunge's own clearance, or higher when the contour over
        # the freed blade is (an oblique contour): VRT above it either way.
        go("r", freed, max(top + vrt, geo.clearance(freed)))
        previous = (u, bottom)
        material.clear_slot(u, freed, bottom, geo.tool.width, geo.tool.corner_radius)
