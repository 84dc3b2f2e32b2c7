"""Command-line memory benchmark: prints figures, asserts nothing.

    python3 benchmarks/bench_cli_memory.py [--calls 1000 10000] [--plain] [--stdout] [--root CHECKOUT] [--json]

Writes a Siemens program of N featured CYCLE93 calls (flank angles, edge
radii, base chamfers, allowances; a grooving blade given with --tool-width),
runs ``python3 -m freecad_groove expand PROGRAM -o OUT`` on it in a child
process (``--stdout``: to standard output, into the null device) and prints the
child's own peak resident memory (figures.CLI_CHILD: Linux's VmHWM, one
child per run), its time, and the sizes of the
program and of the output. Flat memory: the peak stays about the same from
1,000 to 10,000 calls (10,000 take one to two minutes). ``--plain``: plain
calls instead (a rectangular groove 10 wide and 6 deep, no other feature), the
figures issue 22 sets: memory flat from 1k to 100k calls, the time a call.
--json: the figures as JSON lines (benchmarks/figures.py).
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time

import figures

ROOT = figures.package_root(__file__)

# A groove every 40 mm along the shaft: 10 mm wide, 6 deep, flanks at 10 and
# 15 degrees, radii 0.5 at the top, chamfers 1 at the base, finishing
# allowances 0.3 and 0.2, infeed 2 with a dwell (every feature on).
CALL = "CYCLE93(35, %g, 10, 6, 0, 10, 15, 0.5, 0.5, -1, -1, 0.3, 0.2, 2, 0.5, 5, 0)"
# The same groove plain: rectangular, square corners, no allowance, no dwell.
PLAIN_CALL = "CYCLE93(35, %g, 10, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 5, 0)"


# Past this many calls the grooves start again at Z0: Z stays a plain number
# (%g writes -1.2e+06 from 25,000 calls on, which no control reads).
WRAP = 10000


def program(n: int, call: str = CALL) -> str:
    """A program of ``n`` calls ``call``, a groove every 40 mm (the first
    WRAP, then the same places again)."""
    lines = ["N10 T5 D1 S400 M03", "N20 G95 G90 F0.2", "N30 G00 X80 Z65"]
    for k in range(n):
        z = -(k % WRAP) * 40.0
        lines.append("G00 X80 Z%g" % (z + 5))
        lines.append(call % z)
    lines.append("N60 M02")
    return "\n".join(lines) + "\n"


def run_child(path: str, out: str, to_stdout: bool, root: str, env: dict) -> tuple:
    """Peak memory (MiB) and seconds of one ``expand`` child (``env``: figures.child_env)."""
    argv = [sys.executable, "-c", figures.CLI_CHILD, "expand", path, "--dialect", "sinumerik", "--tool-width", "3",
            "--tool-radius", "0.4"]
    if not to_stdout:
        argv += ["-o", out]
    with open(os.devnull, "wb") as null:
        t0 = time.perf_counter()
        proc = subprocess.run(argv, cwd=root, env=env, stdout=null, stderr=subprocess.PIPE, check=False)
        seconds = time.perf_counter() - t0
    err = proc.stderr.decode()
    if proc.returncode != 0:
        said = [line for line in err.splitlines() if line.strip() and not line.startswith("maxrss")]
        raise SystemExit("expand failed (%d): %s" % (proc.returncode, said[-1] if said else "-"))
    kib = int(err.split("maxrss")[-1])  # Linux: KiB
    return kib / 1024.0, seconds


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--calls", type=int, nargs="+", default=[1000, 10000])
    ap.add_argument("--plain", action="store_true", help="plain CYCLE93 calls instead of featured ones")
    ap.add_argument("--stdout", action="store_true", help="write to standard output instead of -o OUT")
    ap.add_argument("--root", default=ROOT, help="the checkout to run (default: this one; another to compare)")
    figures.add_json_option(ap)
    args = ap.parse_args()
    figures.start(args)
    kind = "plain" if args.plain else "featured"
    print("freecad-groove command-line memory (Python %s): expand N %s CYCLE93 calls %s"
          % (sys.version.split()[0], kind, "to stdout" if args.stdout else "-o OUT"))
    with tempfile.TemporaryDirectory() as tmp:
        env = figures.child_env(tmp)
        warm_up = os.path.join(tmp, "warm_up.mpf")
        with open(warm_up, "w") as f:
            f.write(program(1, PLAIN_CALL if args.plain else CALL))
        run_child(warm_up, os.path.join(tmp, "warm_up.ngc"), args.stdout, args.root, env)  # writes the bytecode
        for n in args.calls:
            path = os.path.join(tmp, "prog%d.mpf" % n)
            with open(path, "w") as f:
                f.write(program(n, PLAIN_CALL if args.plain else CALL))
            out = os.path.join(tmp, "out%d.ngc" % n)
            peak, seconds = run_child(path, out, args.stdout, args.root, env)
            size = os.path.getsize(out) if not args.stdout else None
            print("  %6d calls: program %6.1f MiB, output %s, peak memory %7.1f MiB, %6.1f s (%.2f ms a call)"
                  % (n, os.path.getsize(path) / 2**20,
                     "%7.1f MiB" % (size / 2**20) if size is not None else "(stdout)", peak, seconds,
                     1000 * seconds / n))
            name = "command line expand%s, %s %s CYCLE93 calls" % (" to stdout" if args.stdout else "",
                                                                   figures.thousands(n), kind)
            figures.record(name + ": peak memory", peak, "MiB", figures.LOWER, "flat")
            figures.record(name + ": per call", 1000 * seconds / n, "ms", figures.LOWER)
            if size is not None:
                os.remove(out)
            os.remove(path)


if __name__ == "__main__":
    main()
