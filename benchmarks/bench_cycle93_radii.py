"""CYCLE93 expansion time against the number of corner radii: prints figures, asserts nothing.

    python3 benchmarks/bench_cycle93_radii.py [--calls 200]

Each groove is external and longitudinal (TYP 5) at radius 50 from Z0:
W 25, DEPG 10, IDEP 2, VRT 0 (1 mm), cut with a 5 mm blade of corner radius
0.4 from X53 Z5 (radius X). The grooves add R2 corners one at a time (RCO1,
then RCO2, RCI1, RCI2), then come one with 1 mm chamfers on all four corners
and one with everything (ANGC 12, flanks 15/16, RCO 2, RCI 1, allowances
FAL1 0.3 FAL2 0.2). For each: the median time of one ``Cycle93.expand``
(geometry and moves, from the call to the move list; the geometry cache is
emptied before each call, so nothing is reused) over ``--calls`` calls, the
same with ``warnings()`` after it (what the command line and the op do per
call), and the number of moves.

Target (issue 9, item 11): under 3 ms a call on the 2-core test machine
with any radii and chamfers. --json: the figures as JSON lines
(benchmarks/figures.py).
"""

import argparse
import statistics
import sys
import time

import figures

figures.use_package(__file__)

from freecad_groove.engine import GroovingTool, MachineState, Settings  # noqa: E402
from freecad_groove.engine.cycles.cycle93 import Cycle93, _cached_geometry  # noqa: E402

BLADE = GroovingTool(5.0, 0.4)
START = MachineState(x=53.0, z=5.0, feed=0.1)
BASE = dict(axfa=50.0, axsa=0.0, widg=25.0, depg=10.0, angc=0.0, ang1=0.0, ang2=0.0, rco1=0.0, rco2=0.0,
            rci1=0.0, rci2=0.0, fal1=0.0, fal2=0.0, idep=2.0, dwt=0.0, typ=5, vrt=0.0)
GROOVES = [
    ("no radius", dict()),
    ("1 x R2", dict(rco1=2.0)),
    ("2 x R2", dict(rco1=2.0, rco2=2.0)),
    ("3 x R2", dict(rco1=2.0, rco2=2.0, rci1=2.0)),
    ("4 x R2", dict(rco1=2.0, rco2=2.0, rci1=2.0, rci2=2.0)),
    ("4 x C1", dict(rco1=-1.0, rco2=-1.0, rci1=-1.0, rci2=-1.0)),
    ("everything", dict(angc=12.0, ang1=15.0, ang2=16.0, rco1=2.0, rco2=2.0, rci1=1.0, rci2=1.0,
                        fal1=0.3, fal2=0.2)),
]


def time_per_call(call, settings, calls, warnings=False):
    """Median seconds of one expansion (and its warnings) from an empty
    geometry cache over ``calls`` calls, and the moves."""
    moves = call.expand(START, settings)
    times = []
    for _ in range(calls):
        _cached_geometry.cache_clear()
        t0 = time.perf_counter()
        call.expand(START, settings)
        if warnings:
            call.warnings(START, settings)
        times.append(time.perf_counter() - t0)
    return statistics.median(times), len(moves)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--calls", type=int, default=200)
    figures.add_json_option(ap)
    args = ap.parse_args()
    figures.start(args)
    settings = Settings(tool=BLADE)
    print("CYCLE93 expand, 5 mm blade r0.4, W25 DEPG10 (Python %s, median of %d calls)"
          % (sys.version.split()[0], args.calls))
    print("%-12s %10s %18s %7s" % ("groove", "ms/call", "with warnings", "moves"))
    for name, kw in GROOVES:
        call = Cycle93(**dict(BASE, **kw))
        secs, moves = time_per_call(call, settings, args.calls)
        with_warnings, _moves = time_per_call(call, settings, args.calls, warnings=True)
        print("%-12s %10.2f %18.2f %7d" % (name, secs * 1000, with_warnings * 1000, moves))
        figures.record("CYCLE93 expand, %s: median" % name, secs * 1000, "ms", figures.LOWER, "< 3")
        figures.record("CYCLE93 expand + warnings, %s: median" % name, with_warnings * 1000, "ms", figures.LOWER,
                       "< 3")


if __name__ == "__main__":
    main()
