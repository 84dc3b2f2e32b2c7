"""What CYCLE93's material tracking costs per call: prints figures, asserts nothing.

    python3 benchmarks/bench_cycle93_air.py [--calls 50]

For the six reference grooves of bench_machining_time.py (5 mm blade, r0.2)
and one with every feature (flanks 15 and 10 degrees, chamfers and radii at
all four corners, allowances, ANGC 5), the time of one ``Cycle93.expand`` (best of a few rounds of ``--calls``
calls each), once as the engine runs it (contour and finishing passes fed
only where material remains: cycle93_material / cycle93_passes) and once
with the tracking replaced by a stub that feeds every pass move and records
nothing (full passes, as before issue 9 item 12). The difference is what the
tracking adds per call; the rest (the envelope, the plunges) is the same in
both.

Last run (ms per call: tracked / full / tracking), before (fadb78c, branch
air) and after (branch air2: one walk along field and blade per test or cut,
a test stopping at the first stand, swept fronts as Minkowski sums):

  groove     before                     after
  rect        0.48 /  0.12 /  0.36       0.31 /  0.12 /  0.19
  R1 base    33.2  / 11.9  / 21.4       21.0  / 12.2  /  8.8
  flanks 15   8.50 /  0.79 /  7.72       4.64 /  0.80 /  3.84
  ANGC 12     7.59 /  0.91 /  6.68       4.48 /  0.90 /  3.58
  narrow      0.11 /  0.06 /  0.05       0.09 /  0.06 /  0.03
  deep        0.55 /  0.17 /  0.38       0.36 /  0.18 /  0.19
  all        49.4  /  9.9  / 39.4       26.1  /  9.8  / 16.2

The target (issue 9 item 11: a CYCLE93 call under 3 ms, the tracking well
under 1 ms of it) is not reached: the tracking still lowers the field once
per fed move (about 40 us each, 160 to 290 per call on the featured grooves).
"""

import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from bench_machining_time import BASE, BLADE, GROOVES, START  # noqa: E402

from freecad_groove.engine import MachineState, Settings  # noqa: E402
from freecad_groove.engine.cycles import cycle93_geometry  # noqa: E402
from freecad_groove.engine.cycles.cycle93 import Cycle93  # noqa: E402

ALL_FEATURES = ("all", dict(ang1=15.0, ang2=10.0, rco1=-0.5, rco2=1.0, rci1=1.0, rci2=-0.5, fal1=0.2, fal2=0.3,
                           angc=5.0))


class FullPasses:
    """Stands in for MaterialTop: every pass stretch cuts, nothing is recorded."""

    passed = None

    def __init__(self, lo, hi, slope):
        pass

    def clear_slot(self, *args):
        pass

    def note_pass(self, *args):
        pass

    def cuts(self, *args):
        return True

    def stand(self, *args):
        return 0.0


def per_call_ms(call, settings, calls, rounds=5):
    state = MachineState(x=START[0], z=START[1])
    call.expand(state, settings)
    best = float("inf")
    for _ in range(rounds):
        t0 = time.perf_counter()
        for _ in range(calls):
            call.expand(state, settings)
        best = min(best, (time.perf_counter() - t0) / calls)
    return 1000 * best


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--calls", type=int, default=50, help="calls per timing round (default 50)")
    args = ap.parse_args()
    settings = Settings(tool=BLADE)
    print("CYCLE93 time per call, ms (best of 5 rounds of %d calls)" % args.calls)
    print("%-10s %9s %9s %9s %7s" % ("groove", "tracked", "full", "tracking", "moves"))
    tracked_class = cycle93_geometry.MaterialTop
    for name, kw in GROOVES + [ALL_FEATURES]:
        call = Cycle93(**dict(BASE, **kw))
        moves = len(call.expand(MachineState(x=START[0], z=START[1]), settings))
        tracked = per_call_ms(call, settings, args.calls)
        cycle93_geometry.MaterialTop = FullPasses
        try:
            full = per_call_ms(call, settings, args.calls)
        finally:
            cycle93_geometry.MaterialTop = tracked_class
        print("%-10s %9.3f %9.3f %9.3f %7d" % (name, tracked, full, tracked - full, moves))


if __name__ == "__main__":
    main()
