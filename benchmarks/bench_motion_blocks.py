"""Motion blocks per CYCLE93 groove, against the profile's elements: prints figures, asserts nothing.

    python3 benchmarks/bench_motion_blocks.py [--against REF] [--calls 60]

The grooves: the six reference grooves of bench_machining_time.py (TYP 5 at
radius 50 from Z0, W 25, DEPG 10, IDEP 2, VRT 0, a 5 mm blade of corner
radius 0.2 from X53 Z5 radius X: rect, R1 base, flanks 15, ANGC 12, narrow,
deep) and the four-R2-corner groove of issue 19 (CYCLE93(20, -10, 12, 5, 0,
0, 0, 2, 2, 2, 2, 0.2, 0.2, 2, 0, 5, 0), a 3 mm blade of corner radius 0.4
from X60 Z5, X a diameter).

For each:
- blocks: the motion blocks of the expansion written for LinuxCNC
  (targets.write_program): every line that moves the tool (G0, G1, G2, G3,
  or X/Z words in the motion mode in force), the first rapid to the start
  point included; and how many of them are G2/G3;
- elements: the lines and arcs of the programmed (final) profile the contour
  and finishing passes follow: flank 1, the base and flank 2 where they are
  longer than nothing, and each edge or base corner's arc (a radius) or line
  (a chamfer). A pass that follows the profile exactly needs at least one
  block per element: the lower bound of the passes' feeds, next to which the
  blocks show what the plunges and the links add;
- ms/call: the CPU time of one Cycle93.expand from an empty geometry cache,
  the fastest of ``--calls`` calls (the least disturbed by other work on the
  machine), for these grooves and for the six with radii and chamfers of
  bench_cycle93_radii.py (W 25, DEPG 10, a 5 mm blade r0.4: "r0.4 ...").

``--against REF`` measures a git ref the same way (``git worktree add`` of
REF in a temporary folder, this script's measuring code run there with that
tree's freecad_groove) and prints both side by side; the worktree is removed
afterwards. Both trees are measured in their own process, one after the
other, twice, and the faster round of each is kept.

Issue 19 (arcs stay arcs), last run on the 2-core test machine (loaded 5 by other
work: the times move by a few percent from run to run), against main at 3d18f68:

  groove                 blocks before -> after  elements  ms/call before -> after
  rect                    99 ->    99 ( 0 arcs)         3           0.45 ->   0.44
  R1 base                180 ->   110 ( 2 arcs)         5           2.08 ->   1.95
  flanks 15              134 ->   106 ( 2 arcs)         3           1.15 ->   1.19
  ANGC 12                126 ->   126 ( 0 arcs)         3           1.60 ->   1.10
  narrow                  19 ->    19 ( 0 arcs)         3           0.48 ->   0.32
  deep                   189 ->   189 ( 0 arcs)         3           0.79 ->   0.52
  4 x R2 (#19)           408 ->    90 ( 8 arcs)         7           4.70 ->   3.96
  r0.4 1 x R2            181 ->   120 ( 1 arcs)         4           1.66 ->   1.49
  r0.4 2 x R2            247 ->   125 ( 2 arcs)         5           1.94 ->   1.67
  r0.4 3 x R2            301 ->   130 ( 3 arcs)         6           3.09 ->   2.69
  r0.4 4 x R2            356 ->   136 ( 4 arcs)         7           4.04 ->   3.35
  r0.4 4 x C1            188 ->   140 ( 4 arcs)         7           2.11 ->   2.02
  r0.4 everything        318 ->   150 ( 8 arcs)         7           3.24 ->   3.01

The contour and finishing passes write one G2/G3 where they wrote a run of
chords: the four-R2-corner groove's 408 blocks (412 lines of `emit --expand`)
become 90 (94 lines); the grooves without arcs to write are unchanged. The
time is the same or less with radii and chamfers (fewer moves to make);
flanks 15 writes two vertex arcs and takes about as long.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

BASE = dict(axfa=50.0, axsa=0.0, widg=25.0, depg=10.0, angc=0.0, ang1=0.0, ang2=0.0, rco1=0.0, rco2=0.0,
            rci1=0.0, rci2=0.0, fal1=0.0, fal2=0.0, idep=2.0, dwt=0.0, typ=5, vrt=0.0)
REFERENCE = [  # bench_machining_time.py's GROOVES, with its blade and start
    ("rect", dict()),
    ("R1 base", dict(rci1=1.0, rci2=1.0)),
    ("flanks 15", dict(ang1=15.0, ang2=15.0)),
    ("ANGC 12", dict(angc=12.0)),
    ("narrow", dict(widg=5.0)),
    ("deep", dict(depg=20.0)),
]
RADII = [  # bench_cycle93_radii.py's grooves: W 25, DEPG 10 with corners, a 5 mm blade r0.4 from X53 Z5 (timed)
    ("1 x R2", dict(rco1=2.0)),
    ("2 x R2", dict(rco1=2.0, rco2=2.0)),
    ("3 x R2", dict(rco1=2.0, rco2=2.0, rci1=2.0)),
    ("4 x R2", dict(rco1=2.0, rco2=2.0, rci1=2.0, rci2=2.0)),
    ("4 x C1", dict(rco1=-1.0, rco2=-1.0, rci1=-1.0, rci2=-1.0)),
    ("everything", dict(angc=12.0, ang1=15.0, ang2=16.0, rco1=2.0, rco2=2.0, rci1=1.0, rci2=1.0, fal1=0.3,
                        fal2=0.2)),
]
R2_CALL = dict(axfa=20.0, axsa=-10.0, widg=12.0, depg=5.0, angc=0.0, ang1=0.0, ang2=0.0, rco1=2.0, rco2=2.0,
               rci1=2.0, rci2=2.0, fal1=0.2, fal2=0.2, idep=2.0, dwt=0.0, typ=5, vrt=0.0)
MOTION = re.compile(r"\bG0?([0-3])\b")
AXIS = re.compile(r"\b[XZ]-?[\d.]")


def grooves():
    """(name, call words, blade (width, corner radius), start (radius x, z))."""
    out = [(name, dict(BASE, **kw), (5.0, 0.2), (53.0, 5.0)) for name, kw in REFERENCE]
    out.append(("4 x R2 (#19)", R2_CALL, (3.0, 0.4), (30.0, 5.0)))
    return out + [("r0.4 " + name, dict(BASE, **kw), (5.0, 0.4), (53.0, 5.0)) for name, kw in RADII]


def motion_blocks(text):
    """(motion blocks, of them arcs) of a written LinuxCNC program (see the module notes)."""
    blocks = arcs = 0
    motion = None
    for line in text.splitlines():
        line = re.sub(r"\([^)]*\)", "", line)
        codes = MOTION.findall(line)
        motion = codes[-1] if codes else motion
        if AXIS.search(line) and not re.search(r"\bG0?4\b", line):
            blocks += 1
            arcs += motion in ("2", "3")
    return blocks, arcs


def profile_elements(geo):
    """The lines and arcs of the final profile between the opening's edges (see the module notes)."""
    import math

    pieces = [corner.element() for corner in geo.final_corners]
    count = sum(1 for points, _arc in pieces if len(points) > 1)  # a radius or a chamfer
    for (before, _a), (after, _b) in zip(pieces, pieces[1:]):
        count += math.dist(before[-1], after[0]) > 1e-9  # flank 1, the base, flank 2
    return count


def measure(calls):
    """{name: {blocks, arcs, elements, ms}} for the freecad_groove on sys.path."""
    from freecad_groove.engine import GroovingTool, MachineState, Settings
    from freecad_groove.engine.cycles.cycle93 import Cycle93, _cached_geometry
    try:  # the output layer of issue 19; before it, engine/targets.py
        from freecad_groove.engine.output.program import write_program
    except ImportError:
        from freecad_groove.engine.targets import write_program

    out = {}
    for name, words, (width, radius), (x, z) in grooves():
        call, settings = Cycle93(**words), Settings(tool=GroovingTool(width, radius))
        state = MachineState(x=x, z=z, feed=0.1, feed_per_rev=True)
        moves = call.expand(state, settings)
        blocks, arcs = motion_blocks(write_program(moves, "linuxcnc", state, spindle=500.0))
        fastest = float("inf")
        for _ in range(calls):
            _cached_geometry.cache_clear()
            t0 = time.process_time()
            call.expand(state, settings)
            fastest = min(fastest, time.process_time() - t0)
        out[name] = dict(blocks=blocks, arcs=arcs, elements=profile_elements(call.geometry(settings)),
                         ms=1000.0 * fastest)
    return out


def measured_in(tree, calls):
    """measure() run in its own process with ``tree``'s freecad_groove."""
    proc = subprocess.run([sys.executable, os.path.abspath(__file__), "--rows", "--tree", tree, "--calls", str(calls)],
                          capture_output=True, text=True, timeout=3600, check=True)
    return json.loads(proc.stdout)


def faster(rounds):
    """The rounds merged: each groove's fastest time (the figures are the same in every round)."""
    best = dict(rounds[0])
    for other in rounds[1:]:
        for name, row in other.items():
            if row["ms"] < best[name]["ms"]:
                best[name] = row
    return best


def against(ref, calls):
    """(ours, theirs): this checkout and ``ref`` (a git worktree in a temporary folder), measured twice each."""
    folder = tempfile.mkdtemp(prefix="bench-motion-blocks-")
    tree = os.path.join(folder, "tree")
    subprocess.run(["git", "-C", ROOT, "worktree", "add", "--detach", tree, ref], check=True, capture_output=True)
    try:
        ours, theirs = [], []
        for _ in range(2):
            theirs.append(measured_in(tree, calls))
            ours.append(measured_in(ROOT, calls))
        return faster(ours), faster(theirs)
    finally:
        subprocess.run(["git", "-C", ROOT, "worktree", "remove", "--force", tree], capture_output=True)
        shutil.rmtree(folder, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--against", metavar="REF", help="a git ref measured the same way, printed beside")
    ap.add_argument("--calls", type=int, default=60, help="expansions timed per groove (default 60)")
    ap.add_argument("--rows", action="store_true", help=argparse.SUPPRESS)  # against(): one tree's rows
    ap.add_argument("--tree", default=ROOT, help=argparse.SUPPRESS)
    sys.path.insert(0, HERE)
    import figures

    figures.add_json_option(ap)
    args = ap.parse_args()
    figures.start(args)
    if args.rows:
        sys.path.insert(0, args.tree)
        print(json.dumps(measure(args.calls)))
        return
    if not args.against:
        sys.path.insert(0, figures.package_root(__file__))
        rows = measure(args.calls)
        print("%-17s %8s %6s %9s %9s" % ("groove", "blocks", "arcs", "elements", "ms/call"))
        for name, row in rows.items():
            print("%-17s %8d %6d %9d %9.2f" % (name, row["blocks"], row["arcs"], row["elements"], row["ms"]))
            figures.record("CYCLE93 %s: motion blocks" % name, row["blocks"], "blocks", figures.LOWER)
            figures.record("CYCLE93 %s: expand, fastest call" % name, row["ms"], "ms", figures.LOWER,
                           "< 3" if name.startswith("4 x R2") else None)
        return
    ours, theirs = against(args.against, args.calls)
    print("motion blocks and expand time (CPU ms, the fastest of %d calls): %s (before) -> this checkout (after)"
          % (args.calls, args.against))
    print("%-17s %27s %9s %24s" % ("groove", "blocks before -> after", "elements", "ms/call before -> after"))
    for name, row in ours.items():
        old = theirs[name]
        blocks = "%8d -> %5d (%2d arcs)" % (old["blocks"], row["blocks"], row["arcs"])
        print("%-17s %27s %9d %14.2f -> %6.2f" % (name, blocks, row["elements"], old["ms"], row["ms"]))


if __name__ == "__main__":
    main()
