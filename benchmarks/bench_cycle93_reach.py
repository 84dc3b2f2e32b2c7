"""Cost of CYCLE93's unreachable-material warning (issue 9 item 2): prints
figures, asserts nothing.

    python3 benchmarks/bench_cycle93_reach.py [--repeat N]

For grooves with 0..4 R2 corners (RCI1, RCI2, then RCO1, RCO2) and the seed
example, all with a 5 mm r0.4 blade: the time per call of
``Cycle93.warnings`` (geometry included), of the geometry alone, and their
difference, the warning's own cost (``cycle93_reach.unreachable_regions``).
"""

import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

from freecad_groove.engine import GroovingTool, MachineState, Settings  # noqa: E402
from freecad_groove.engine.cycles.cycle93 import Cycle93  # noqa: E402

RADII = ("RCI1", "RCI2", "RCO1", "RCO2")
SEED = "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"


def groove(corners: int) -> Cycle93:
    """A longitudinal groove 25 wide, 10 deep, with ``corners`` R2 corners."""
    radii = {name.lower(): 2.0 for name in RADII[:corners]}
    return Cycle93(axfa=35.0, axsa=60.0, widg=25.0, depg=10.0, angc=0.0, idep=5.0, typ=5, **radii)


def per_call(fn, repeat: int) -> float:
    fn()
    t0 = time.perf_counter()
    for _ in range(repeat):
        fn()
    return (time.perf_counter() - t0) / repeat


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=50)
    args = parser.parse_args()
    settings = Settings(tool=GroovingTool(5.0, 0.4))
    state = MachineState(x=40.0, z=65.0, feed=0.2, feed_per_rev=True)
    cases = [("%d R2 corners" % n, groove(n)) for n in range(5)] + [("seed example", Cycle93.parse(SEED))]
    print("CYCLE93 warnings, 5 mm r0.4 blade, %d calls each (ms per call)" % args.repeat)
    print("%-16s %10s %10s %10s  %s" % ("groove", "warnings", "geometry", "warning", "reported"))
    for name, call in cases:
        total = per_call(lambda c=call: c.warnings(state, settings), args.repeat)
        geometry = per_call(lambda c=call: c.geometry(settings), args.repeat)
        reported = len([w for w in call.warnings(state, settings) if w.parameter in ("RCI1", "RCI2")])
        print("%-16s %10.2f %10.2f %10.2f  %d" % (name, 1e3 * total, 1e3 * geometry, 1e3 * (total - geometry),
                                                  reported))


if __name__ == "__main__":
    main()
