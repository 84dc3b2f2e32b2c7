"""Whether a change to CYCLE93's expansion left its programs as they were: prints, asserts nothing.

    python3 benchmarks/same_cycle93.py --against REF [--calls 850] [--seed 1]

Speed work on the expansion must not change a move. This expands the same
calls with the working tree and with REF (written out by ``git archive``),
each in its own process, and compares, call by call: ``Cycle93.expand``'s
moves and ``warnings``' list (their reprs: every float to the last bit, or
the error raised), and the LinuxCNC program ``python3 -m freecad_groove
expand`` writes from a Sinumerik program holding the call, with its exit
code and messages. The calls: the grooves of count_cycle93.py and
``--calls`` seeded random ones (every TYP, blades 2-5 mm with corner radii
0-0.8, widths, depths, contour and flank angles, radii and chamfers,
allowances, infeeds, VRT, start points; some refused, which is compared too).
It prints how many were compared and which differ (exit code 1 if any).
"""

import argparse
import contextlib
import io
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
NAMES = "axfa axsa widg depg angc ang1 ang2 rco1 rco2 rci1 rci2 fal1 fal2 idep dwt typ vrt".split()


def _corner(rnd: random.Random) -> float:
    return rnd.choice([0, 0, round(rnd.uniform(0.2, 3), 1), -round(rnd.uniform(0.2, 2), 1)])


def random_call(rnd: random.Random):
    """(parameters in order, blade (width, radius), start (radius x, z)) of one random call."""
    typ = rnd.choice([1, 2, 3, 4, 5, 6, 7, 8, 11, 12, 13, 14, 15, 16, 17, 18])
    face, internal = typ % 10 in (2, 4, 6, 8), typ % 10 in (3, 4, 7, 8)
    width, radius = rnd.choice([2.0, 3.0, 4.0, 5.0]), rnd.choice([0.0, 0.2, 0.4, 0.8])
    widg = round(rnd.uniform(width, 30), rnd.choice([0, 1, 3]))
    depg = round(rnd.uniform(1, 12), rnd.choice([0, 1, 3]))
    angc = rnd.choice([0, 0, 0, round(rnd.uniform(0, 20), 1), round(rnd.uniform(160, 180), 1)])
    if face:
        angc = rnd.choice([90, 90, round(rnd.uniform(70, 110), 1)])
    ang1, ang2 = rnd.choice([0, 0, round(rnd.uniform(0, 40), 1)]), rnd.choice([0, 0, round(rnd.uniform(0, 40), 1)])
    rco1, rco2, rci1, rci2 = _corner(rnd), _corner(rnd), _corner(rnd), _corner(rnd)
    fal1, fal2 = rnd.choice([0, 0, round(rnd.uniform(0, 0.5), 2)]), rnd.choice([0, 0, round(rnd.uniform(0, 0.5), 2)])
    idep, dwt, vrt = rnd.choice([round(rnd.uniform(0.5, 6), 1), 2.0]), rnd.choice([0, 0, 1]), rnd.choice([0, 0.5, 1.5])
    axsa = round(rnd.uniform(-60, 0), 1)
    if not face:
        axfa = round(rnd.uniform(60, 140), 1) if not internal else round(rnd.uniform(40, 120), 1)
        x0 = axfa + 90 if not internal else 4
        z0 = axsa + rnd.uniform(-5, 5) + (0 if typ % 10 in (5, 6, 7, 8) else -widg)
    else:
        axfa, axsa = round(rnd.uniform(40, 140), 1), round(rnd.uniform(-30, 0), 1)
        x0 = round(axfa + rnd.uniform(-5, 5), 2)
        z0 = axsa + 40 if not internal else axsa - 40
    params = (axfa, axsa, widg, depg, angc, ang1, ang2, rco1, rco2, rci1, rci2, fal1, fal2, idep, dwt, typ, vrt)
    return params, (width, radius), (x0 / 2, z0)


def calls(count: int, seed: int):
    """(label, CYCLE93 parameters or words, blade, start): the benchmark grooves, then the random calls."""
    sys.path.insert(0, HERE)
    from count_cycle93 import grooves

    out = [(name, words, blade, start) for name, words, blade, start in grooves()]
    rnd = random.Random(seed)
    return out + [("random %d" % k,) + random_call(rnd) for k in range(count)]


def expanded(words, blade, start) -> str:
    """The moves and warnings of one call (their reprs), or the error it raised."""
    from freecad_groove.engine import GroovingTool, MachineState, Settings
    from freecad_groove.engine.cycles.cycle93 import Cycle93, _cached_geometry

    try:
        call = Cycle93.parse(words) if isinstance(words, str) else \
            Cycle93(**(words if isinstance(words, dict) else dict(zip(NAMES, words))))
        settings = Settings(tool=GroovingTool(*blade))
        state = MachineState(x=start[0], z=start[1], feed=0.1, feed_per_rev=True)
        return repr(call.expand(state, settings)) + repr(call.warnings(state, settings))
    except Exception as error:  # compared like any answer
        return "error %s %s" % (type(error).__name__, error)
    finally:
        _cached_geometry.cache_clear()


def written(call_text: str, blade, start, folder: str) -> list:
    """Exit code, messages and program of the command line's expand of a program holding the call."""
    from freecad_groove.cli import main

    src, dst = os.path.join(folder, "p.mpf"), os.path.join(folder, "o.ngc")
    with open(src, "w") as f:
        f.write("N10 T1 D1 S500 M03\nN20 G90 G95 F0.1\nN30 G00 X%r Z%r\nN40 %s\nN50 G00 X%r Z%r\nN60 M02\n"
                % (2 * start[0], start[1], call_text, 2 * start[0], start[1]))
    if os.path.exists(dst):
        os.remove(dst)
    err, out = io.StringIO(), io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
        try:
            code = main(["expand", "--dialect", "sinumerik", "--tool-width", str(blade[0]), "--tool-radius",
                         str(blade[1]), "-o", dst, src])
        except SystemExit as stop:
            code = stop.code
    text = open(dst).read() if os.path.exists(dst) else None
    # The messages name the files: their folder differs from run to run.
    return [code, out.getvalue().replace(folder, "DIR"), err.getvalue().replace(folder, "DIR"), text]


def child(tree: str, count: int, seed: int, out_path: str) -> None:
    """In its own process: every call's answers with ``tree``'s freecad_groove, as JSON in ``out_path``."""
    rows = calls(count, seed)
    sys.path.insert(0, tree)
    folder = tempfile.mkdtemp(prefix="same-cycle93-")
    answers = {}
    try:
        for label, words, blade, start in rows:
            if isinstance(words, str):
                text = words
            else:
                values = [words.get(n) for n in NAMES] if isinstance(words, dict) else list(words)
                text = "CYCLE93(%s)" % ", ".join("" if v is None else repr(v) for v in values)
            answers[label] = [text, expanded(words, blade, start)] + written(text, blade, start, folder)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    with open(out_path, "w") as f:
        json.dump(answers, f)


def answers_of(tree: str, count: int, seed: int, folder: str, python: str) -> dict:
    path = os.path.join(folder, "answers-%d.json" % len(os.listdir(folder)))
    subprocess.run([python, os.path.abspath(__file__), "--child", tree, str(count), str(seed), path], check=True)
    with open(path) as f:
        return json.load(f)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--against", metavar="REF", default="main", help="the git ref compared with (default main)")
    ap.add_argument("--calls", type=int, default=850, help="random calls (default 850)")
    ap.add_argument("--seed", type=int, default=1, help="the random calls' seed (default 1)")
    ap.add_argument("--python", default=sys.executable, help="the Python that expands")
    ap.add_argument("--child", nargs=4, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child(args.child[0], int(args.child[1]), int(args.child[2]), args.child[3])
        return 0
    scratch = tempfile.mkdtemp(prefix="same-cycle93-")
    try:
        ref = os.path.join(scratch, "ref")
        os.mkdir(ref)
        archive = subprocess.run(["git", "archive", "--format=tar", args.against], cwd=ROOT, capture_output=True,
                                 check=True)
        subprocess.run(["tar", "-x", "-C", ref], input=archive.stdout, check=True)
        results = os.path.join(scratch, "results")
        os.mkdir(results)
        ours = answers_of(ROOT, args.calls, args.seed, results, args.python)
        theirs = answers_of(ref, args.calls, args.seed, results, args.python)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    differ = [label for label in ours if ours[label] != theirs.get(label)]
    refused = sum(1 for answer in ours.values() if answer[1].startswith("error"))
    print("compared %d calls (%d benchmark grooves, %d random of seed %d, %d of them refused) with %s: %d differ"
          % (len(ours), len(ours) - args.calls, args.calls, args.seed, refused, args.against, len(differ)))
    for label in differ[:10]:
        print("  %s: %s" % (label, ours[label][0]))
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
