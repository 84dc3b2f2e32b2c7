"""Counted instructions of one CYCLE93 expand: prints figures, asserts nothing.

    python3 benchmarks/count_cycle93.py [--against REF ...] [--only NAME,...] [--expansions 3]

Wall-clock and even CPU times move by 10-40 % on a shared machine; the
instructions a run executes do not (to a few thousandths). For each groove
of bench_motion_blocks.py and bench_cycle93_reach.py (names as there) this
runs, under ``valgrind --tool=cachegrind --cache-sim=no``, a Python that
imports the tree's freecad_groove, expands the groove once (imports and
first-call costs), then expands it N more times, each from an empty geometry
cache (``_cached_geometry.cache_clear()``, as the benchmarks do); and the same
with N = 0. The figure is the difference over N: millions of instructions per
expand. The working tree is measured, then each ``--against`` ref, written
out by ``git archive`` into a temporary folder (one row per groove, one
column per tree). PYTHONHASHSEED=0 keeps the runs the same.

Needs valgrind (``apt-get install valgrind``). A run under valgrind takes
about 3-10 s: 14 grooves x 2 runs x 3 trees take about 5 minutes on one core.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SEED = "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"  # bench_cycle93_reach.py's


def grooves():
    """(name, call words or text, blade (width, corner radius), start (radius x, z))."""
    sys.path.insert(0, HERE)
    from bench_motion_blocks import grooves as motion_grooves

    out = [row for row in motion_grooves() if row[0] not in ("r0.4 2 x R2", "r0.4 3 x R2")]
    reach = dict(axfa=35.0, axsa=60.0, widg=25.0, depg=10.0, angc=0.0, idep=5.0, typ=5)
    out.append(("reach 0 R2", reach, (5.0, 0.4), (40.0, 65.0)))
    out.append(("reach 4 R2", dict(reach, rci1=2.0, rci2=2.0, rco1=2.0, rco2=2.0), (5.0, 0.4), (40.0, 65.0)))
    out.append(("seed example", SEED, (5.0, 0.4), (40.0, 65.0)))
    return out


def child(tree: str, name: str, count: int) -> None:
    """Under valgrind: expand groove ``name`` with ``tree``'s freecad_groove once, then ``count`` times afresh."""
    rows = {row[0]: row for row in grooves()}
    sys.path.insert(0, tree)
    from freecad_groove.engine import GroovingTool, MachineState, Settings
    from freecad_groove.engine.cycles.cycle93 import Cycle93, _cached_geometry

    _name, words, (width, radius), (x, z) = rows[name]
    call = Cycle93.parse(words) if isinstance(words, str) else Cycle93(**words)
    settings = Settings(tool=GroovingTool(width, radius))
    state = MachineState(x=x, z=z, feed=0.1, feed_per_rev=True)
    call.expand(state, settings)
    for _ in range(count):
        _cached_geometry.cache_clear()
        call.expand(state, settings)


def instructions(python: str, tree: str, name: str, count: int) -> int:
    """The instructions valgrind counted for ``child(tree, name, count)``."""
    env = dict(os.environ, PYTHONHASHSEED="0")
    proc = subprocess.run(["valgrind", "--tool=cachegrind", "--cache-sim=no", "--cachegrind-out-file=/dev/null",
                           python, os.path.abspath(__file__), "--child", tree, name, str(count)],
                          capture_output=True, text=True, env=env, check=True)
    for line in proc.stderr.splitlines():
        if "I   refs:" in line or "I refs:" in line:
            return int(line.split(":")[1].replace(",", "").strip())
    raise RuntimeError("no instruction count in valgrind's output:\n" + proc.stderr[-2000:])


def per_expand(python: str, tree: str, name: str, count: int) -> float:
    """Millions of instructions one expand takes (``count`` expansions less none, over ``count``)."""
    return (instructions(python, tree, name, count) - instructions(python, tree, name, 0)) / count / 1e6


def written_out(ref: str, into: str) -> str:
    """``git archive REF`` unpacked in a new folder under ``into``."""
    folder = tempfile.mkdtemp(prefix="ref-", dir=into)
    archive = subprocess.run(["git", "archive", "--format=tar", ref], cwd=ROOT, capture_output=True, check=True)
    subprocess.run(["tar", "-x", "-C", folder], input=archive.stdout, check=True)
    return folder


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--against", metavar="REF", action="append", default=[], help="a git ref counted beside")
    ap.add_argument("--only", help="these grooves only (names as printed, comma-separated)")
    ap.add_argument("--expansions", type=int, default=3, help="expansions counted per groove (default 3)")
    ap.add_argument("--python", default=sys.executable, help="the Python that runs the expansions")
    ap.add_argument("--child", nargs=3, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child(args.child[0], args.child[1], int(args.child[2]))
        return
    names = [row[0] for row in grooves()]
    if args.only:
        names = [name for name in names if name in args.only.split(",")]
    scratch = tempfile.mkdtemp(prefix="count-cycle93-")
    try:
        trees = [("tree", ROOT)] + [(ref, written_out(ref, scratch)) for ref in args.against]
        print("millions of instructions per CYCLE93 expand (cachegrind, %d expansions less 0, empty geometry cache)"
              % args.expansions)
        print("%-18s" % "groove" + "".join("%10s" % label[:9] for label, _path in trees)
              + ("".join("   /%-6s" % ref[:6] for ref in args.against)))
        for name in names:
            counts = [per_expand(args.python, path, name, args.expansions) for _label, path in trees]
            ratios = "".join("%10.2f" % (counts[0] / other) for other in counts[1:])
            print("%-18s" % name + "".join("%10.2f" % c for c in counts) + ratios, flush=True)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
