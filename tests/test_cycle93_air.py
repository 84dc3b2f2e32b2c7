"""CYCLE93 steps 3 and 4 feed only where material remains (issue 9 item 12):
measured with the shapely simulation against the moves themselves."""

import pytest
from cycle93_helpers import after_the_plunges
from shapely.geometry import Polygon
from test_cycle93_simulation import run

from freecad_groove import verify as sim
from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.cycles import cycle93_material
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.moves import FEED
from freecad_groove.verify.depth import depth_inside
from freecad_groove.verify.overlay import area, difference, intersection

BLADE = GroovingTool(5.0, 0.2)
START = (53.0, 5.0)
BENCH = dict(axfa=50.0, axsa=0.0, widg=25.0, depg=10.0, angc=0.0, idep=2.0, typ=5)  # the benchmark's grooves
AIR_AREA = 1e-6  # mm^2: a feed removing less than this ran through air


def air_feed(call, tool, start):
    """Length (mm) of the contour and finishing passes' feeds that remove no
    material, and the total feed length of the expansion."""
    moves, first, remaining = after_the_plunges(call, tool, start)
    plunge = call.plunge_direction()
    air = total = 0.0
    here = (moves[first - 1].x, moves[first - 1].z)
    for move in moves[first:]:
        if move.kind == FEED:
            length = ((move.x - here[0]) ** 2 + (move.z - here[1]) ** 2) ** 0.5
            swept = sim.swept_area(tool, plunge, here, (move.x, move.z))
            total += length
            if area(intersection(remaining, swept)) < AIR_AREA:
                air += length
            remaining = difference(remaining, swept)
        here = (move.x, move.z)
    return air, total


@pytest.mark.parametrize(
    "extra, limit",
    [(dict(rci1=1.0, rci2=1.0), 8.0), (dict(ang1=15.0, ang2=15.0), 4.5), (dict(angc=12.0), 3.0),
     (dict(ang1=10.0, rci1=1.0, rci2=0.5, rco1=0.5, rco2=-0.5, fal1=0.2, fal2=0.2), 10.0)],
    ids=["R1 base", "flanks 15", "ANGC 12", "featured"],
)
def test_contour_and_finishing_passes_feed_less_through_air(extra, limit):
    """mm of pass feeds that remove nothing. Before, the passes traced the
    whole profile (down both walls to the plunges' bottoms, along the oblique
    base): 17.6, 5.7, 22.3 and 12.2 mm; moves tested one by one against a
    polygon field (branch air2) 6.8, 3.8, 0.6 and 8.7; stretches between plunge
    positions tested whole against the exact field 6.7, 3.8, 0.6 and 8.6 (what
    remains: short links, and the ends of stretches that cut elsewhere)."""
    air, total = air_feed(Cycle93(**dict(BENCH, **extra)), BLADE, START)
    assert air < limit, (air, total)


def test_the_r1_groove_feeds_less_than_with_full_passes():
    call = Cycle93(**dict(BENCH, rci1=1.0, rci2=1.0))
    skipping = air_feed(call, BLADE, START)[1]
    cuts = cycle93_material.MaterialTop.cuts
    try:
        cycle93_material.MaterialTop.cuts = lambda *a: True
        full = air_feed(call, BLADE, START)[1]
    finally:
        cycle93_material.MaterialTop.cuts = cuts
    assert skipping < full - 20.0, (skipping, full)


@pytest.mark.parametrize(
    "extra, limit", [(dict(rci1=1.0, rci2=1.0), 11.0), (dict(rco1=2.0, rco2=2.0, rci1=2.0, rci2=2.0), 20.0)],
    ids=["R1 base", "4 x R2"],
)
def test_a_pass_does_not_feed_down_a_wall_the_last_plunge_cleared(extra, limit):
    """mm fed by the contour and finishing passes in all. Before (corners as
    inscribed polygons, a stand above 1e-6 counted as material), the right
    pass's descent along the wall at u = 20 - 1e-10 (the trace's float, the
    last plunge at 20) was found to cut: the corner polygon's nearly vertical
    first side turned that shift into a stand over the noise, and 9 mm were
    fed down the slot: 18.3 and 25.5 mm fed in all; now 9.5 and 17.8."""
    assert air_feed(Cycle93(**dict(BENCH, **extra)), BLADE, START)[1] < limit


def test_finishing_skips_what_the_roughing_passes_ran_on_the_same_profile():
    """With edge radii and no allowances the finishing profile is the
    roughing one below the edges: its passes there would retrace the roughing
    passes through air (15.7 mm of air feed); they are skipped (5.0 mm left:
    links and grazes)."""
    air, _total = air_feed(Cycle93(**dict(BENCH, rco1=2.0, rco2=2.0, rci1=2.0, rci2=2.0)), BLADE, START)
    assert air < 7.0, air


# Grooves where a blade's corner drawn as one chord per arc skipped moves that
# would still have cut (slivers up to 0.006 mm left): random ANGC, flanks,
# corners, allowances, both reference corners.
SLIVER_CASES = [
    ("CYCLE93(24.02, -14.15, 9.42, 5.05, 166.1, 12.1, 24.6, -0.77, 0, 0, 1, 0.17, 0, 0.58, 0, 3, 0.3)",
     GroovingTool(3.62, 0.33, reference="minus")),
    ("CYCLE93(21.37, -17.67, 9.84, 3.07, 110.7, 0, 3.4, 0.37, 0, 0.23, -0.88, 0.42, 0, 3.31, 0.5, 17, 2)",
     GroovingTool(1.55, 0.39, reference="minus")),
    ("CYCLE93(18.99, 13.96, 7.01, 3.97, 65.7, 0, 0, 0.11, -0.25, -1.14, 0, 0.06, 0.32, 1.32, 0.5, 5, 0.3)",
     GroovingTool(3.19, 0.32, reference="plus")),
    ("CYCLE93(36.66, -15.05, 6.42, 5.71, 0, 14.9, 3.5, 0, 0, -0.32, 0.56, 0.45, 0, 3.22, 0.5, 11, 0.3)",
     GroovingTool(1.95, 0.44, reference="minus")),
]


def _remaining(call, tool, full):
    cuts = cycle93_material.MaterialTop.cuts
    try:
        if full:
            cycle93_material.MaterialTop.cuts = lambda *a: True
        verdict, moves = run(call, tool, interpreter=False)
    finally:
        cycle93_material.MaterialTop.cuts = cuts
    sim.assert_clean(verdict, allow_infeasible=True)
    settings = Settings(tool=tool)
    geo = call.geometry(settings)
    lo, hi = geo.opening(geo.final_top)
    u = lo - tool.width - 4.0
    start = geo.frame.blade(u, max(geo.contour_top(u), geo.contour_top(hi)) + 3.0)
    stock = Polygon([(z, x) for x, z in geo.stock_world()])
    return sim.simulate(moves, tool, call.plunge_direction(), start, stock).remaining


@pytest.mark.parametrize("text, tool", SLIVER_CASES)
def test_skipping_air_leaves_what_full_passes_leave(text, tool):
    """The material left standing is the full passes' (what they cut and the
    skipping passes do not is never thicker than MATERIAL_MARGIN)."""
    call = Cycle93.parse(text)
    skipping = _remaining(call, tool, False)
    extra = difference(skipping, _remaining(call, tool, True))
    depth = depth_inside(extra, skipping, 0.0001)[0] if area(extra) > 1e-12 else 0.0
    assert depth <= cycle93_material.MATERIAL_MARGIN + 1e-4, depth


def test_a_blade_as_wide_as_the_groove_still_takes_the_base_allowance():
    """Each finishing pass of a groove exactly the blade's width is one point
    (a plunge to the final base): it must still be fed when the allowance
    stands there. Before, a one-point pass had no move to test and was
    dropped, leaving the 0.05 mm base allowance standing."""
    call = Cycle93.parse("CYCLE93(15, 0, 1.5, 0.8, 0, 0, 0, 0, 0, 0, 0, 0.05, 0, 0.3, 0, 1, 0)")
    verdict, _moves = run(call, GroovingTool(1.5, 0.0), interpreter=False)
    sim.assert_clean(verdict)
