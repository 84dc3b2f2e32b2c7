"""Command-line verify benchmark: prints figures, asserts nothing.

    python3 benchmarks/bench_cli_verify.py [--calls 20 200] [--root CHECKOUT] [--json]

Writes a Siemens program of N featured CYCLE93 calls (bench_cli_memory's
grooves: one every 40 mm along one bar, flank angles, edge radii, base
chamfers, allowances), runs ``python3 -m freecad_groove verify PROGRAM`` on it
in a child process (one per run, so each figure is its own) and prints its
time, its peak resident memory (its own: figures.CLI_CHILD), its exit status and the
number of moves simulated. Issue 22's goal: 200 calls verified in 1 s.
--json: the figures as JSON lines (benchmarks/figures.py).
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time

import figures
from bench_cli_memory import program

ROOT = figures.package_root(__file__)


def run_child(path: str, root: str, env: dict) -> tuple:
    """(seconds, peak MiB, exit status, report) of one ``verify`` child (``env``: figures.child_env)."""
    argv = [sys.executable, "-c", figures.CLI_CHILD, "verify", path, "--dialect", "sinumerik", "--tool-width", "3",
            "--tool-radius", "0.4"]
    t0 = time.perf_counter()
    proc = subprocess.run(argv, cwd=root, env=env, capture_output=True, check=False)
    seconds = time.perf_counter() - t0
    err = proc.stderr.decode()
    if proc.returncode not in (0, 1):
        said = [line for line in err.splitlines() if line.strip() and not line.startswith("maxrss")]
        raise SystemExit("verify failed (%d): %s" % (proc.returncode, said[-1] if said else "-"))
    return seconds, int(err.split("maxrss")[-1]) / 1024.0, proc.returncode, proc.stdout.decode()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, nargs="+", default=[20, 200])
    parser.add_argument("--root", default=ROOT, help="the checkout whose freecad_groove runs")
    figures.add_json_option(parser)
    args = parser.parse_args()
    figures.start(args)
    print("%7s %9s %9s %6s %s" % ("calls", "seconds", "peak MiB", "exit", "total line"))
    with tempfile.TemporaryDirectory() as folder:
        env = figures.child_env(folder)
        warm_up = os.path.join(folder, "warm_up.mpf")
        with open(warm_up, "w") as f:
            f.write(program(1))
        run_child(warm_up, args.root, env)  # writes the bytecode
        for calls in args.calls:
            path = os.path.join(folder, "calls%d.mpf" % calls)
            with open(path, "w") as f:
                f.write(program(calls))
            seconds, mib, status, report = run_child(path, args.root, env)
            total = [line for line in report.splitlines() if ": total: " in line]
            print("%7d %9.2f %9.1f %6d %s" % (calls, seconds, mib, status,
                                               total[0].split(": total: ")[1][:90] if total else "-"))
            name = "command line verify, %s featured CYCLE93 calls" % figures.thousands(calls)
            figures.record(name, seconds, "s", figures.LOWER, "<= 1" if calls == 200 else None)
            figures.record(name + ": peak memory", mib, "MiB", figures.LOWER)


if __name__ == "__main__":
    main()
