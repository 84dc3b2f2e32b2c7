"""Machining time of six reference CYCLE93 grooves: prints figures, asserts nothing.

    python3 benchmarks/bench_machining_time.py [--feed 100] [--rapid 10000]

Rates: feed 0.1 mm/rev at 1000 rpm = 100 mm/min, rapid 10,000 mm/min; no
dwell (DWT 0), no acceleration. Each groove is external and longitudinal
(TYP 5) at radius 50 from Z0, VRT 0 (1 mm), cut with a 5 mm blade of corner
radius 0.2 from X53 Z5 (radius X), back there at the end:

  rect       W 25, DEPG 10, IDEP 2, square corners
  R1 base    the same with R1 base corners (RCI1 = RCI2 = 1)
  flanks 15  the same with both flanks at 15 degrees (ANG1 = ANG2 = 15)
  ANGC 12    the same on an oblique contour (ANGC 12)
  narrow     W 5 = the blade width, DEPG 10, IDEP 2
  deep       W 25, DEPG 20, IDEP 2

For each: feed and rapid length and time, the chip-breaking retracts, and
lower bounds:
- feed: the groove's area / (blade width x feed rate). A blade plunging
  along its own axis removes at most its width in mm^2 per mm of feed (its
  front edge is that wide), and CYCLE93 roughs by plunging; so no program
  that plunges the groove out can feed for less. (A sideways pass can take
  more per mm, but CYCLE93's only take the allowances and the plunges'
  staircase.)
- rapid: twice the straight distance from the start point to the nearest
  blade position VRT above the groove's opening: the cycle must get there
  and come back to where it started.

Seconds (feed + rapid = total; feed bound), before (3d3117c: fed back in by
VRT + the next infeed after each chip-break) and after (a rapid back down
to 0.1 mm above the depth reached):

  groove     breaks  before                  after                   feed >=
  rect         24    54.00 + 0.92 =  54.92   41.04 + 1.05 = 42.09    30.00
  R1 base      24    70.76 + 1.24 =  72.00   57.80 + 1.37 = 59.17    29.95
  flanks 15    20    62.07 + 1.30 =  63.37   51.27 + 1.41 = 52.68    33.22
  ANGC 12      30    83.39 + 1.24 =  84.62   67.19 + 1.40 = 68.58    30.00
  narrow        4     9.00 + 0.23 =   9.23    6.84 + 0.26 =  7.10     6.00
  deep         54   108.00 + 1.46 = 109.46   78.84 + 1.76 = 80.60    60.00

Contour and finishing passes fed only where material remains (issue 9 item
12, second part): total seconds before (main, with the free-off) and after:

  groove     before   after
  rect        45.11   45.11
  R1 base     61.58   55.32
  flanks 15   55.70   54.63
  ANGC 12     68.58   56.17
  narrow       7.10    7.10
  deep        83.61   83.61

Links and retracts the manual leaves open (issue 22 item 4): each plunge
rapids down to 0.1 mm over the contour and feeds from there (was: fed from
VRT, 1 mm), the 1 mm free-off is a rapid inside the slots already cut (was a
feed), and a contour pass that has come down a corner or a flank ends there
instead of running on along a base the plunges have cut. Seconds and ratio to
the lower bound, main (144a764) and after:

  groove     main            after           floor (the manual's plunges and passes)
  rect       45.11  1.498    38.93  1.293    37.13  1.233
  R1 base    49.69  1.652    40.30  1.340    38.32  1.274
  flanks 15  54.63  1.639    46.03  1.381    44.41  1.332
  ANGC 12    55.69  1.849    52.48  1.742    50.32  1.671
  narrow      7.10  1.160     6.56  1.072     6.26  1.023
  deep       83.61  1.391    77.44  1.288    73.84  1.228
  six       295.83  1.558   261.74  1.378   250.28  1.318

The goal 1.15 is out of reach with the manual's plunges: equal width steps
of at most 95 % of (blade width - 2 x corner radius) plunge 6 times across a
25 mm groove with a 5 mm blade, 1.2 x the 5 plunges the area needs, each the
full depth (rect, deep); an oblique base (ANGC 12) adds an infeed (10.04 mm
in IDEP 2: 6 infeeds) and the contour pass along the whole base that takes
off the plunges' staircase (20.4 mm at feed); flanks and base corners add
their contour passes. What is left above the floor is the 0.1 mm entry and
re-entry clearances (one per plunge and per chip-break).

--json: the figures as JSON lines (benchmarks/figures.py): each groove's
total seconds and its ratio to its lower bound, and the six grooves' total
over their lower bounds' total (feed + rapid; issue 22's goal: at most 1.15).
"""

import argparse
import math

import figures

figures.use_package(__file__)

from freecad_groove.engine import GroovingTool, MachineState, Settings  # noqa: E402
from freecad_groove.engine.cycles.cycle93 import Cycle93  # noqa: E402
from freecad_groove.engine.moves import ARC_CW, ARCS, FEED, RAPID  # noqa: E402

BLADE = GroovingTool(5.0, 0.2)
START = (53.0, 5.0)  # radius X, Z
BASE = dict(axfa=50.0, axsa=0.0, widg=25.0, depg=10.0, angc=0.0, ang1=0.0, ang2=0.0, rco1=0.0, rco2=0.0,
            rci1=0.0, rci2=0.0, fal1=0.0, fal2=0.0, idep=2.0, dwt=0.0, typ=5, vrt=0.0)
GROOVES = [
    ("rect", dict()),
    ("R1 base", dict(rci1=1.0, rci2=1.0)),
    ("flanks 15", dict(ang1=15.0, ang2=15.0)),
    ("ANGC 12", dict(angc=12.0)),
    ("narrow", dict(widg=5.0)),
    ("deep", dict(depg=20.0)),
]


def lengths(moves, start):
    """Feed and rapid path lengths (mm) from ``start``, and the chip-breaking
    retracts: a rapid straight out after a feed, the plunge going on at the
    same Z (directly, or after a rapid back down)."""
    feed = rapid = 0.0
    here = start
    for m in moves:
        step = math.dist(here, (m.x, m.z))
        if m.kind in ARCS:  # its length along the circle (G2 clockwise with Z right and X up)
            (cx, cz), radius = m.centre, math.dist(here, m.centre)
            turn = (math.atan2(m.x - cx, m.z - cz) - math.atan2(here[0] - cx, here[1] - cz)) % (2 * math.pi)
            feed += radius * (2 * math.pi - turn if m.kind == ARC_CW else turn)
        elif m.kind == FEED:
            feed += step
        elif m.kind == RAPID:
            rapid += step
        here = (m.x, m.z)
    breaks = 0
    for i in range(1, len(moves) - 2):
        cut, out, on = moves[i - 1], moves[i], moves[i + 1]
        if on.kind == RAPID and on.z == cut.z:
            on = moves[i + 2]  # the rapid back down
        breaks += cut.kind == FEED and out.kind == RAPID and out.z == on.z == cut.z and on.kind == FEED
    return feed, rapid, breaks


def area(points):
    """Area of a closed polygon (shoelace)."""
    return abs(sum(x0 * z1 - x1 * z0 for (x0, z0), (x1, z1) in zip(points, points[1:]))) / 2


def rapid_bound(geo):
    """Twice the distance from START to the nearest reference-corner position
    VRT above the opening."""
    lo, hi = geo.opening(geo.final_top)
    best = math.inf
    for k in range(201):
        u = lo + (hi - BLADE.width - lo) * k / 200
        best = min(best, math.dist(START, geo.frame.blade(u, geo.clearance(u))))
    return 2 * best


def measure(name, kw, feed_rate, rapid_rate):
    call = Cycle93(**dict(BASE, **kw))
    settings = Settings(tool=BLADE)
    moves = call.expand(MachineState(x=START[0], z=START[1]), settings)
    geo = call.geometry(settings)
    feed, rapid, breaks = lengths(moves, START)
    feed_min, rapid_min = feed / feed_rate, rapid / rapid_rate
    bound_feed = area(geo.region_world()) / (BLADE.width * feed_rate)
    bound_rapid = rapid_bound(geo) / rapid_rate
    return (name, feed, rapid, breaks, 60 * feed_min, 60 * rapid_min, 60 * (feed_min + rapid_min),
            60 * bound_feed, 60 * bound_rapid, bound_feed / feed_min, where_fed(moves, geo, START))


def where_fed(moves, geo, start):
    """(the plunges' depths, the rest of their feed (air: entries and re-entries), the contour and
    finishing passes' feed), mm: a plunge feeds along the plunge axis at a plunge position; its depth is
    from the contour over the blade to where it stops."""
    positions = geo.plunge_positions()
    depth = sum(max(geo.contour_top(u) - geo.rough_env.lowest(u), 0.0) for u in positions)
    plunged = 0.0
    here = geo.frame.blade_of(*start)
    for m in moves:
        there = geo.frame.blade_of(m.x, m.z)
        if m.kind == FEED and abs(there[0] - here[0]) < 1e-9 and any(abs(there[0] - u) < 1e-9 for u in positions):
            plunged += abs(there[1] - here[1])
        here = there
    feed = lengths(moves, start)[0]
    return depth, plunged - depth, feed - plunged


BOUND_DEFINITION = (
    "lower bound = feed bound + rapid bound:",
    "  feed bound  = the groove's area / (blade width x feed rate): a blade plunging along its own axis removes",
    "                at most its width in mm^2 per mm fed, and CYCLE93 roughs by plunging",
    "  rapid bound = twice the straight distance from the start point to the nearest blade position VRT above",
    "                the groove's opening, at the rapid rate: there and back",
    "ratio = the cycle's time (feed + rapid) / the lower bound; goal (issue 22): at most 1.15",
)


WHERE = """
Where the feed goes (mm): the plunges' depths (equal steps of at most 95 % of the blade's width less its
corner radii, each plunge from the contour to where it stops, in equal infeeds: the Siemens manual's steps 1
and 2), the rest of the plunges' feed (air: the VRT entries over the contour and the re-entries after each
chip-break), the contour and finishing passes (steps 3 and 4, fed where material stands). Floor: the
depths and passes at feed plus the rapids, what the manual's plunges and passes take whatever the links."""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--feed", type=float, default=100.0, help="feed rate, mm/min (default 100)")
    ap.add_argument("--rapid", type=float, default=10000.0, help="rapid rate, mm/min (default 10000)")
    figures.add_json_option(ap)
    args = ap.parse_args()
    figures.start(args)
    print("CYCLE93 machining time: feed %g mm/min, rapid %g mm/min, blade %g mm (r %g)"
          % (args.feed, args.rapid, BLADE.width, BLADE.corner_radius))
    print("\n".join(BOUND_DEFINITION))
    print("%-10s %8s %8s %6s %8s %8s %8s | %8s %8s %8s %6s"
          % ("groove", "feed mm", "rapid mm", "breaks", "feed s", "rapid s", "time s",
             "feed >=", "rapid >=", "bound s", "ratio"))
    total = bound = 0.0
    rows = []
    for name, kw in GROOVES:
        row = measure(name, kw, args.feed, args.rapid)
        rows.append(row)
        lower = row[7] + row[8]
        print("%-10s %8.2f %8.2f %6d %8.2f %8.2f %8.2f | %8.2f %8.2f %8.2f %6.3f"
              % (row[:9] + (lower, row[6] / lower)))
        figures.record("CYCLE93 machining time, %s groove" % name, row[6], "s", figures.LOWER)
        figures.record("CYCLE93 machining time / lower bound, %s groove" % name, row[6] / lower, "x", figures.LOWER,
                       "<= 1.15")
        total += row[6]
        bound += lower
    print("six grooves: %.2f s against a lower bound of %.2f s (feed + rapid): %.3f x" % (total, bound, total / bound))
    print(WHERE)
    print("%-10s %8s %8s %8s %8s | %8s %6s" % ("groove", "depths", "air", "passes", "rapid s", "floor s", "ratio"))
    floors = 0.0
    for row in rows:
        depth, air, passes = row[10]
        floor = 60 * (depth + passes) / args.feed + row[5]
        floors += floor
        print("%-10s %8.2f %8.2f %8.2f %8.2f | %8.2f %6.3f" % (row[0], depth, air, passes, row[5], floor,
                                                              floor / (row[7] + row[8])))
    print("six grooves: the floor %.2f s, %.3f x the lower bound" % (floors, floors / bound))
    figures.record("CYCLE93 machining time / lower bound, six reference grooves", total / bound, "x", figures.LOWER,
                   "<= 1.15")


if __name__ == "__main__":
    main()
