"""Milltronics G33/G34 benchmark: prints figures, asserts nothing.

    python3 benchmarks/bench_milltronics.py

A G33 facing and a G34 pocket (corner radius 5 mm) of growing size, 10 mm end
mill, cut width 2 mm, depth 10 mm in steps of 1 mm (metric): expand, then
write as a LinuxCNC mill program. Reports the moves, the best of 3 times and
output moves per second (the engine's target for the cycles: at least
100,000 a second on one core; issue 22: 1,000,000). --json: the figures as
JSON lines (benchmarks/figures.py).
"""

import argparse
import time

import figures

figures.use_package(__file__)

from freecad_groove.engine.cycles.milltronics import G33, G34  # noqa: E402
from freecad_groove.engine.moves import MachineState  # noqa: E402
from freecad_groove.engine.settings import Settings  # noqa: E402

write_program = figures.first_of("write_program", "freecad_groove.engine.output.program",
                                 "freecad_groove.engine.targets")


def best_of(fn, rounds=3):
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - start)
    return result, min(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    figures.add_json_option(parser)
    figures.start(parser.parse_args())
    state = MachineState(x=0.0, y=0.0, z=5.0, diameter_mode=False, feed=600.0, feed_per_rev=False)
    settings = Settings(mill_tool_diameter=10.0)
    print("%6s %7s %9s %10s %10s %12s" % ("cycle", "size", "moves", "expand s", "write s", "moves/s"))
    for cycle in (G33, G34):
        for size in (200.0, 400.0, 800.0):
            model = cycle(R=2.0, Z=-10.0, V=-1.0, Q=1.0, F=100.0, G99=True, P150=5.0, P151=size, P152=size / 2,
                          P155=2.0)
            moves, expand = best_of(lambda model=model: model.expand(state, settings))
            _text, write = best_of(lambda moves=moves: write_program(moves, "linuxcnc-mill", state))
            print("%6s %7.0f %9d %10.3f %10.3f %12.0f" % (cycle.NAME, size, len(moves), expand, write,
                                                          len(moves) / (expand + write)))
            figures.record("%s expand + write, %g x %g mm" % (cycle.NAME, size, size / 2),
                           len(moves) / (expand + write), "moves/s", figures.HIGHER, ">= 1,000,000")


if __name__ == "__main__":
    main()
