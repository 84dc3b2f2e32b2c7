"""The simulation oracle (freecad_groove.verify) on arc moves (G2/G3), with
hand-made programs whose right answer is known: an arc sweeps the circle the
way it turns, a gouge an arc makes is caught and the exact arc is clean, an
arc without a centre or with its end off its circle is refused.

Geometry is (z, x) with x the radius; moves are (x, z) like moves.Move.
"""

import math

import pytest
import shapely
from shapely.geometry import Point

from freecad_groove.engine.moves import ARC_CW, MINUS_X, GroovingTool, Move, arc, feed, rapid
from freecad_groove.verify import bar, check_groove, region, simulate

STOCK = bar(20.0, -50.0, 0.0)  # test_simulation.py's bar: radius 20 from Z-50 to Z0
TOOL = GroovingTool(3.0, 0.4)
START = (25.0, -10.0)


def test_an_arc_without_a_centre_or_off_its_circle_is_an_error():
    with pytest.raises(ValueError, match="neither a centre nor a radius"):
        simulate([Move(ARC_CW, 25.0, -8.0)], TOOL, MINUS_X, START, STOCK)
    with pytest.raises(ValueError, match="off the circle"):  # the end 1 mm off the circle through the start
        simulate([arc(True, 26.0, -8.0, (25.0, -9.0))], TOOL, MINUS_X, START, STOCK)


# A sharp blade 1 wide plunging -X, its reference corner at its -Z end, from X(radius)10 Z0 to
# X10 Z2 round the centre X10 Z1 (radius 1): G2 (clockwise, Z right and X up) goes over the top
# through X11 Z1, G3 under it through X9 Z1. The stock below X9.9.
NARROW = GroovingTool(1.0, 0.0)
ARC_STOCK = region(0.0, 9.9, -5.0, 8.0)


def test_an_arc_sweeps_its_circle_the_way_it_turns():
    under = simulate([arc(False, 10.0, 2.0, (10.0, 1.0))], NARROW, MINUS_X, (10.0, 0.0), ARC_STOCK)
    zmin, xmin, zmax, xmax = under.removed.bounds
    assert xmin == pytest.approx(9.0, abs=1e-5)  # the blade's front down to the circle's lowest point
    # the reference corner below X9.9 while |z - 1| < sqrt(1 - 0.1 ** 2); the blade reaches 1 beyond it
    assert (zmin, zmax) == (pytest.approx(1.0 - math.sqrt(1 - 0.1 ** 2), abs=1e-4),
                            pytest.approx(1.0 + math.sqrt(1 - 0.1 ** 2) + 1.0, abs=1e-4))
    over = simulate([arc(True, 10.0, 2.0, (10.0, 1.0))], NARROW, MINUS_X, (10.0, 0.0), ARC_STOCK)
    assert over.removed.area < 1e-12
    assert over.final == under.final == (10.0, 2.0)


def test_a_gouge_made_by_an_arc_is_caught_and_the_exact_arc_is_clean():
    # The groove Z-10..-7, 5 deep, its base corners rounded R1 (centres X16 Z-9 and X16 Z-8). A blade
    # 1 wide with corner radius 0.4, reference corner at its -Z side: its -Z corner's centre rolls
    # down the left radius 1 - 0.4 = 0.6 from the radius' centre, so the reference corner (0.4 lower
    # and 0.4 toward -Z) runs on the circle of radius 0.6 about X15.6 Z-9.4, from the wall (X15.6
    # Z-10, angle 180 degrees, Z right and X up) to the bottom (X15 Z-9.4, 270 degrees): a G3. Exactly
    # on it, nothing is gouged; the same moves 0.01 lower dig 0.01 into the radius.
    rounded = shapely.union_all([region(16.0, 20.0, -10.0, -7.0), region(15.0, 16.0, -9.0, -8.0),
                                 Point(-9.0, 16.0).buffer(1.0, quad_segs=256),
                                 Point(-8.0, 16.0).buffer(1.0, quad_segs=256)])
    target = rounded.intersection(region(15.0, 20.0, -10.0, -7.0))
    tool = GroovingTool(1.0, 0.4)

    def moves(drop):
        return [rapid(21.0, -10.0), feed(15.6 - drop, -10.0), arc(False, 15.0 - drop, -9.4, (15.6 - drop, -9.4)),
                rapid(21.0, -9.4)]

    clean = check_groove(simulate(moves(0.0), tool, MINUS_X, (25.0, -10.0), STOCK), target, tool)
    assert not clean.gouged and not clean.rapid_collisions
    dug = check_groove(simulate(moves(0.01), tool, MINUS_X, (25.0, -10.0), STOCK), target, tool)
    assert dug.gouge == pytest.approx(0.01, abs=1e-3)
