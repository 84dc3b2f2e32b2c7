"""Engine benchmark: prints figures, asserts nothing.

    python3 benchmarks/bench_engine.py

1. A G77 pattern of N grooves (10,000 by default): expand, then write as
   LinuxCNC G-code. Reports time, output moves per second and peak memory
   (tracemalloc), and the same for N/4 and N/2 so the growth can be read.
   The same for Fanuc's two-block G75 (the same grooves: 2 mm pecks, 5 mm
   apart; the retract e the default setting's).
2. A program of 200 CYCLE93 calls (seed-like grooves along a shaft) run
   through the same translator the command-line tool uses.
Target (issue 2): at least 100,000 output moves per second on one core,
memory growing linearly with the number of grooves; issue 22: 1,000,000.
--json: the figures as JSON lines (benchmarks/figures.py).
"""

import argparse
import sys
import time
import tracemalloc

import figures

figures.use_package(__file__)

from freecad_groove.engine import GroovingTool, MachineState, Settings  # noqa: E402
from freecad_groove.engine.cycles.ab_g77 import G77  # noqa: E402
from freecad_groove.engine.cycles.fanuc_g75 import FanucG75  # noqa: E402
from freecad_groove.engine.translator import translate_program  # noqa: E402

write_moves = figures.first_of("write_moves", "freecad_groove.engine.output.program", "freecad_groove.engine.targets")


def measure(fn):
    tracemalloc.start()
    t0 = time.perf_counter()
    result = fn()
    elapsed = time.perf_counter() - t0
    _cur, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    # time again without tracemalloc, which slows allocation-heavy code
    t0 = time.perf_counter()
    fn()
    plain = time.perf_counter() - t0
    return result, min(elapsed, plain), peak


def pecking_pattern(n, cycle="G77"):
    """Expand and write ``n`` grooves 5 mm apart, 2 mm pecks, from X50 (diameter) down to X40."""
    if cycle == "G77":
        call = G77(X=40.0, Z=-(n - 1) * 5.0, I=2.0, K=5.0, F=0.05, D=0.0)
    else:
        call = FanucG75(X=40.0, Z=-(n - 1) * 5.0, P=2000, Q=5000, R=0.0, F=0.05)
    state = MachineState(x=25.0, z=0.0, feed=0.05)

    def run():
        moves = call.expand(state)
        lines = write_moves(moves, "linuxcnc", state)
        return len(moves), len(lines)

    return run


def cycle93_program(n):
    lines = ["N10 T5 D1 S400 M03", "N20 G95 G90 F0.2", "N30 G00 X80 Z65"]
    for k in range(n):
        z = -k * 40.0
        lines.append("G00 X80 Z%g" % (z + 5))
        lines.append("CYCLE93(35, %g, 10, 6, 0, 10, 15, 0.5, 0.5, -1, -1, 0.3, 0.2, 2, 0.5, 5, 0)" % z)
    lines.append("N60 M02")
    text = "\n".join(lines) + "\n"
    settings = Settings(tool=GroovingTool(3.0, 0.4))

    def run():
        out = translate_program(text, "sinumerik", settings, target="linuxcnc")
        return out.count("\n")

    return run


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--grooves", type=int, default=10000)
    ap.add_argument("--calls", type=int, default=200)
    figures.add_json_option(ap)
    args = ap.parse_args()
    figures.start(args)
    print("freecad-groove engine benchmark (Python %s, one core)" % sys.version.split()[0])
    for cycle in ("G77", "G75"):
        print("%s pattern: expand + write LinuxCNC" % cycle)
        for n in (args.grooves // 4, args.grooves // 2, args.grooves):
            (moves, lines), secs, peak = measure(pecking_pattern(n, cycle))
            print(
                "  %6d grooves: %7d moves, %7d lines in %.3f s = %9.0f moves/s, peak memory %6.1f MiB "
                "(%.0f bytes/move)" % (n, moves, lines, secs, moves / secs, peak / 2**20, peak / moves)
            )
            name = "%s expand + write, %s grooves" % (cycle, figures.thousands(n))
            figures.record(name, moves / secs, "moves/s", figures.HIGHER,
                           ">= 1,000,000" if n == args.grooves else None)
            figures.record(name + ": peak memory", peak / 2**20, "MiB", figures.LOWER)
    print("CYCLE93 program: translate (parse, validate, expand, write)")
    for n in (args.calls // 2, args.calls):
        out_lines, secs, peak = measure(cycle93_program(n))
        print(
            "  %6d calls: %7d output lines in %.3f s = %9.0f lines/s, %.2f ms per call, peak memory %6.1f MiB"
            % (n, out_lines, secs, out_lines / secs, 1000 * secs / n, peak / 2**20)
        )
        figures.record("CYCLE93 program translated, %d featured calls: per call" % n, 1000 * secs / n, "ms",
                       figures.LOWER)


if __name__ == "__main__":
    main()
