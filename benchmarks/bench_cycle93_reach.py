"""Cost of CYCLE93's unreachable-material warning (issue 9 items 2 and 11):
prints figures, asserts nothing.

    python3 benchmarks/bench_cycle93_reach.py [--repeat N]

For grooves with 0..4 R2 corners (RCI1, RCI2, then RCO1, RCO2) and the seed
example, all with a 5 mm r0.4 blade, the time per call (ms) of, each on a
geometry built afresh (``Cycle93.geometry`` keeps a few, which would hide
the cost; each the best of 5 rounds):
- geometry: ``GrooveGeometry`` alone (profiles, envelopes' curves);
- expand: the geometry and its moves;
- warning alone: ``cycle93_warnings`` on a geometry built but not expanded
  (it builds the final envelope's pieces itself);
- warning after expand: ``cycle93_warnings`` on a geometry already expanded,
  as the translator and the FreeCAD op run it (validate, expand and warnings
  of one call share one geometry), computed: the warnings kept for a groove
  shape met before (cycle93_reach) are forgotten before each call;
- and found again: the warnings of a groove of a shape met before (a
  program's grooves repeated along a shaft), a figure only.
--json: the figures as JSON lines (benchmarks/figures.py).
"""

import argparse
import importlib
import time

import figures

figures.use_package(__file__)

from freecad_groove.engine import GroovingTool, Settings  # noqa: E402
from freecad_groove.engine.cycles.cycle93 import Cycle93  # noqa: E402
from freecad_groove.engine.cycles.cycle93_geometry import GrooveGeometry  # noqa: E402
from freecad_groove.engine.cycles.cycle93_warnings import cycle93_warnings  # noqa: E402

# The warnings of the last groove shapes (a tree since issue 22 keeps them): forgotten before each measured call.
KEPT = getattr(importlib.import_module("freecad_groove.engine.cycles.cycle93_reach"), "_REACH_CACHE", None)

RADII = ("RCI1", "RCI2", "RCO1", "RCO2")
SEED = "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"
START = (40.0, 65.0)  # reference corner, X radius and Z


def groove(corners: int) -> Cycle93:
    """A longitudinal groove 25 wide, 10 deep, with ``corners`` R2 corners."""
    radii = {name.lower(): 2.0 for name in RADII[:corners]}
    return Cycle93(axfa=35.0, axsa=60.0, widg=25.0, depg=10.0, angc=0.0, idep=5.0, typ=5, **radii)


ROUNDS = 5  # each figure is the best of this many rounds: the machine is shared, other loads only add


def per_call(fn, repeat: int) -> float:
    fn()
    best = float("inf")
    for _ in range(ROUNDS):
        t0 = time.perf_counter()
        for _ in range(repeat):
            fn()
        best = min(best, (time.perf_counter() - t0) / repeat)
    return best


def warnings_per_call(prepare, repeat: int, kept: bool = False) -> float:
    """Time per call of the warnings over geometries ``prepare()`` gives (each
    used once), computed each time (the warnings a groove of the same shape
    had are forgotten before each), or with ``kept`` found again."""
    best = float("inf")
    for _ in range(ROUNDS):
        geometries = [prepare() for _ in range(repeat)]
        if kept:
            cycle93_warnings(geometries[0])
        t0 = time.perf_counter()
        for geo in geometries:
            if KEPT is not None and not kept:
                KEPT.clear()
            cycle93_warnings(geo)
        best = min(best, (time.perf_counter() - t0) / repeat)
    return best


def measure(call: Cycle93, settings: Settings, repeat: int) -> tuple:
    """(geometry, expand, warning alone, warning after expand) in seconds per call."""
    def fresh() -> GrooveGeometry:
        return GrooveGeometry(call, settings, True)

    def expanded() -> GrooveGeometry:
        geo = fresh()
        geo.expand(*START)
        return geo

    geometry = per_call(fresh, repeat)
    expand = per_call(expanded, repeat)
    alone = warnings_per_call(fresh, repeat)
    after = warnings_per_call(expanded, repeat)
    again = warnings_per_call(expanded, repeat, kept=True)
    return geometry, expand, alone, after, again


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=50)
    figures.add_json_option(parser)
    args = parser.parse_args()
    figures.start(args)
    settings = Settings(tool=GroovingTool(5.0, 0.4))
    cases = [("%d R2 corners" % n, groove(n)) for n in range(5)] + [("seed example", Cycle93.parse(SEED))]
    print("CYCLE93 warnings, 5 mm r0.4 blade, best of %d rounds of %d calls (ms per call)" % (ROUNDS, args.repeat))
    print("%-16s %9s %9s %15s %21s  %s" % ("groove", "geometry", "expand", "warning alone", "warning after expand",
                                          "warned corners"))
    for name, call in cases:
        geometry, expand, alone, after, again = measure(call, settings, args.repeat)
        reported = len([w for w in cycle93_warnings(GrooveGeometry(call, settings, True))
                        if w.parameter in RADII])
        print("%-16s %9.2f %9.2f %15.2f %21.2f  %d" % (name, 1e3 * geometry, 1e3 * expand, 1e3 * alone, 1e3 * after,
                                                       reported))
        figures.record("CYCLE93 geometry + expand, %s: best per call" % name, 1e3 * expand, "ms", figures.LOWER)
        figures.record("CYCLE93 unreachable-material warning after expand, %s: best per call" % name, 1e3 * after,
                       "ms", figures.LOWER)
        figures.record("CYCLE93 warnings of a groove shape met before (a program's repeated groove), %s: best per "
                       "call" % name, 1e3 * again, "ms", figures.LOWER)


if __name__ == "__main__":
    main()
