"""What CYCLE93's material tracking costs per call: prints figures, asserts nothing.

    python3 benchmarks/bench_cycle93_air.py [--calls 50]

For the six reference grooves of bench_machining_time.py (5 mm blade, r0.2)
and one with every feature (flanks 15 and 10 degrees, chamfers and radii at
all four corners, allowances, ANGC 5), the time of one ``Cycle93.expand``
(best of a few rounds of ``--calls`` calls each, process CPU time: steady on
a loaded machine), once as the engine runs it (contour and finishing passes
fed only where material remains: cycle93_material / cycle93_passes) and once
with the tracking replaced by a stub that feeds every pass stretch (full
passes, as before issue 9 item 12). The difference is what the tracking adds
per call; the rest (the envelope, the plunges) is the same in both.

Last run (CPU ms per call: tracked / full / tracking), before (branch air2
merged on main's exact envelope: a polygon field lowered after every fed
move, each move tested) and after (branch air3: the plunges' material in
closed form, each stretch between plunge positions tested whole, the passes'
own cuts not tracked):

  groove     before                     after
  rect        0.45 /  0.26 /  0.20       0.26 /  0.25 /  0.01
  R1 base     5.03 /  0.69 /  4.34       1.13 /  0.72 /  0.41
  flanks 15   2.74 /  0.38 /  2.36       0.63 /  0.40 /  0.23
  ANGC 12     1.90 /  0.37 /  1.53       0.62 /  0.40 /  0.21
  narrow      0.22 /  0.19 /  0.03       0.20 /  0.20 /  0.01
  deep        0.50 /  0.29 /  0.20       0.30 /  0.29 /  0.01
  all         9.46 /  0.87 /  8.59       1.50 /  0.93 /  0.58

The target (issue 9 item 11: a CYCLE93 call under 3 ms, the tracking well
under 1 ms of it) is met on these grooves and on bench_cycle93_radii.py's.
--json: the figures as JSON lines (benchmarks/figures.py).
"""

import argparse
import time

import figures
from bench_machining_time import BASE, BLADE, GROOVES, START  # (puts the package on sys.path)

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

    def stand_blade(self, *args):
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
        t0 = time.process_time()
        for _ in range(calls):
            call.expand(state, settings)
        best = min(best, (time.process_time() - t0) / calls)
    return 1000 * best


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--calls", type=int, default=50, help="calls per timing round (default 50)")
    figures.add_json_option(ap)
    args = ap.parse_args()
    figures.start(args)
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
        label = "every-feature" if name == "all" else name
        figures.record("CYCLE93 expand with material tracking, %s groove: CPU per call" % label, tracked, "ms",
                       figures.LOWER, "< 3")
        figures.record("CYCLE93 material tracking alone, %s groove: CPU per call" % label, tracked - full, "ms",
                       figures.LOWER, "< 1")


if __name__ == "__main__":
    main()
