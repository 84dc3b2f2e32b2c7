"""G83 plunge grinding benchmark: prints figures, asserts nothing.

    python3 benchmarks/bench_ab_g83.py

A G83 of growing size (picks of 0.002 mm over a depth of 0.1 to 0.4 mm,
crossover 0..300 mm in picks of 2 mm, strokes between X0 and X400): expand,
then write as a LinuxCNC mill program. Reports the moves, the best of 3
times, output moves per second (the engine's target for the cycles: at
least 100,000 a second on one core; issue 22: 1,000,000). --json: the
figures as JSON lines (benchmarks/figures.py).
"""

import argparse
import time

import figures

figures.use_package(__file__)

from freecad_groove.engine.cycles.ab_g83 import G83  # noqa: E402
from freecad_groove.engine.moves import MachineState  # noqa: E402

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
    state = MachineState(x=0.0, y=0.0, z=0.0, diameter_mode=False, feed=20.0, feed_per_rev=False)
    print("%8s %9s %10s %10s %12s" % ("depth", "moves", "expand s", "write s", "moves/s"))
    for depth in (0.1, 0.2, 0.4):
        model = G83(X=400.0, Y=-depth, J=0.002, Z=300.0, K=2.0, Q=0.002, L=2, F=20.0, E=6000.0, P=1, D=5)
        moves, expand = best_of(lambda model=model: model.expand(state))
        _text, write = best_of(lambda moves=moves: write_program(moves, "linuxcnc-mill", state))
        print("%8.1f %9d %10.3f %10.3f %12.0f" % (depth, len(moves), expand, write, len(moves) / (expand + write)))
        figures.record("G83 expand + write, %g mm deep" % depth, len(moves) / (expand + write), "moves/s",
                       figures.HIGHER, ">= 1,000,000")


if __name__ == "__main__":
    main()
