"""GSK G7.1 benchmark: prints figures, asserts nothing.

    python3 benchmarks/bench_gsk_g7_1.py

A Type II region on an R20 cylinder whose path is a barrel-cam track of N
arcs (R10, a quarter circle each on the developed surface, 56 segments
each within the 0.001 mm chord tolerance), with L rough passes: the time to
expand it into moves and to write them for linuxcnc-c, and the moves per
second (issue 22's goal: 1,000,000). The figures go in docs/benchmarks.md's
Benchmarks section; --json: as JSON lines (benchmarks/figures.py).
"""

import argparse
import math
import time

import figures

figures.use_package(__file__)

try:
    from freecad_groove.engine.cycles.gsk_g7_1 import GskG7_1
except ImportError:  # a tree before the cycle protocol's names
    from freecad_groove.engine.cycles.gsk_g71 import GskG71 as GskG7_1
from freecad_groove.engine.moves import MachineState  # noqa: E402

write_moves = figures.first_of("write_moves", "freecad_groove.engine.output.program", "freecad_groove.engine.targets")


def region(arcs: int, passes: int) -> GskG7_1:
    to_s = 20.0 * math.pi / 180.0
    lines = ["G7.1 C20. J-4. R2. K0.2 L%d" % passes]
    z = s = 0.0
    for k in range(arcs):
        z -= 10.0
        s += 10.0
        lines.append("%s Z%.4f C%.4f R10.%s" % ("G2" if k % 2 else "G3", z, s / to_s, " F100." if k == 0 else ""))
    lines.append("G7.1 C0")
    return GskG7_1.parse("\n".join(lines))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    figures.add_json_option(parser)
    figures.start(parser.parse_args())
    start = MachineState(x=21.0, z=0.0, c=0.0, feed=50.0, feed_per_rev=False)
    print("arcs  passes  moves     expand s  write s  moves/s (expand+write)")
    for arcs, passes in ((10, 5), (100, 10), (100, 100), (1000, 10)):
        model = region(arcs, passes)
        t0 = time.perf_counter()
        moves = model.expand(start)
        t1 = time.perf_counter()
        write_moves(moves, "linuxcnc-c", start)
        t2 = time.perf_counter()
        print("%5d %6d %8d  %8.3f  %7.3f  %9.0f" % (arcs, passes, len(moves), t1 - t0, t2 - t1,
                                                     len(moves) / (t2 - t0)))
        figures.record("G7.1 expand + write, %d arcs, L%d" % (arcs, passes), len(moves) / (t2 - t0), "moves/s",
                       figures.HIGHER, ">= 1,000,000")


if __name__ == "__main__":
    main()
