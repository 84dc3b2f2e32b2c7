"""The turning check's pure part (freecad_groove.verify.turning, section,
machining_time) on hand-made ops whose figures are known: a rectangular
groove plunged twice into a bar, the same with one plunge 1 mm too deep, a
rapid into the bar, and machining times worked out by hand or by numeric
integration. Each check runs on both models: the column model (turning,
turned_section: numpy only, what verify_job and verify run) and the shapely
oracle (turning_shapely, section). Geometry (z, x), x the radius; positions
(x, z)."""

import math

import pytest

from freecad_groove.engine.moves import MINUS_X, GroovingTool, arc, dwell, feed, rapid
from freecad_groove.verify import section, turned_section, turning, turning_shapely
from freecad_groove.verify.machining_time import Feeds, clock_text, machining_time
from freecad_groove.verify.turning import GrooveRun, OpInput

TOOL = GroovingTool(3.0, 0.2)
FILLET = 0.2**2 * (1 - math.pi / 4)  # material a 0.2 mm corner radius leaves in a sharp corner
GROOVE = [(20.0, 25.0), (18.0, 25.0), (18.0, 21.0), (20.0, 21.0)]  # 4 wide, 2 deep: world (x, z)
FEEDS = Feeds(feed=60.0, per_rev=False)


def plunges(bottom2=18.0):
    return [rapid(21, 21), feed(18, 21), rapid(21, 21), rapid(21, 22), feed(bottom2, 22), dwell(bottom2, 22, 0.5),
            rapid(21, 22)]


def op(moves, label="Groove"):
    run = GrooveRun(moves, list(range(1, len(moves) + 1)), TOOL, MINUS_X, GROOVE, reach_warning=2 * FILLET)
    return OpInput(label, (21.0, 21.0), [run], FEEDS)


@pytest.fixture(params=["columns", "shapely"])
def engine(request):
    """(check_ops, the section module it takes its regions from) of one model."""
    if request.param == "columns":
        return turning.check_ops, turned_section
    return turning_shapely.check_ops, section


def shaft(sections):
    """The model: a shaft R20 from Z0 to Z50, as the full cut through the axis (both halves)."""
    return sections.rings_section([[(0, -20), (50, -20), (50, 20), (0, 20)]])


def test_rectangular_groove_removes_its_area_without_gouge(engine):
    check_ops, sections = engine
    result = check_ops([op(plunges())], sections.bar_section(20.0, 0.0, 50.0), shaft(sections))
    check = result.ops[0]
    assert check.ok, result.summary()
    assert check.removed == pytest.approx(8.0 - 2 * FILLET, abs=1e-4)
    assert check.unreachable == pytest.approx(2 * FILLET, abs=1e-4)
    assert check.unreachable == pytest.approx(check.reach_warning, abs=1e-4)
    assert check.gouge_depth == 0 and check.leftover == 0 and not check.rapid_hits
    assert check.time.feed == pytest.approx(6.0) and check.time.dwell == pytest.approx(0.5)
    assert result.remaining.area == pytest.approx(50 * 20 - check.removed, abs=1e-6)
    assert "no gouge" in result.summary()


def test_plunge_too_deep_is_a_gouge_with_where(engine):
    check_ops, sections = engine
    check = check_ops([op(plunges(bottom2=17.0))], sections.bar_section(20.0, 0.0, 50.0), shaft(sections)).ops[0]
    assert not check.ok
    assert check.gouge_depth == pytest.approx(1.0, abs=1e-3)
    x, z = check.gouge_at
    assert 17.0 <= x <= 18.0 and 22.0 <= z <= 25.0, check.gouge_at
    assert "GOUGE" in check.summary() and "1.0000 mm deep" in check.summary()


def test_a_shallow_plunge_leaves_reachable_material(engine):
    check_ops, sections = engine
    check = check_ops([op(plunges(bottom2=18.5))], sections.bar_section(20.0, 0.0, 50.0), shaft(sections)).ops[0]
    assert check.leftover == pytest.approx(0.5 * 1.0, abs=0.05)  # Z24..25 (plunge 1 reaches Z24), 0.5 deep
    assert "LEFTOVER" in check.summary()


def test_rapid_into_the_bar_is_reported_with_its_path_command(engine):
    check_ops, sections = engine
    moves = [rapid(21, 21), rapid(19, 30)] + plunges()
    check = check_ops([op(moves)], sections.bar_section(20.0, 0.0, 50.0), shaft(sections)).ops[0]
    assert [hit.command for hit in check.rapid_hits] == [2, 3]  # into the bar at X19 Z30, and out again
    assert "RAPID THROUGH STOCK" in check.summary()


def test_a_groove_the_model_shows_is_judged_against_the_model(engine):
    """The modelled groove (the shaft with the notch Z21..25 R18) is no part to leave; the same groove
    programmed 1 mm deeper cuts into the modelled part: a gouge."""
    check_ops, sections = engine
    notch = [(0, -20), (50, -20), (50, 20), (25, 20), (25, 18), (21, 18), (21, 20), (0, 20)]
    model = sections.rings_section([notch])
    deeper = [(20.0, 25.0), (17.0, 25.0), (17.0, 21.0), (20.0, 21.0)]
    part = sections.part_to_leave(model, [sections.groove_region(deeper)])
    assert part.area == pytest.approx(model.area)
    moves = [rapid(21, 21), feed(17, 21), rapid(21, 21), rapid(21, 22), feed(17, 22), rapid(21, 22)]
    run = GrooveRun(moves, list(range(1, 7)), TOOL, MINUS_X, deeper)
    check = check_ops([OpInput("Deeper", (21.0, 21.0), [run], FEEDS)], sections.bar_section(20.0, 0.0, 50.0),
                      model).ops[0]
    assert check.gouge_depth == pytest.approx(1.0, abs=1e-3) and check.gouge_at[0] < 18.0
    plain = sections.part_to_leave(shaft(sections), [sections.groove_region(GROOVE)])
    assert plain.area == pytest.approx(50 * 20 - 8.0)


@pytest.mark.parametrize("sections", [turned_section, section])
def test_rings_section_takes_holes_and_the_positive_half(sections):
    tube = sections.rings_section([[(0, -20), (50, -20), (50, 20), (0, 20)], [(10, -5), (45, -5), (45, 5), (10, 5)]])
    assert tube.area == pytest.approx(50 * 20 - 35 * 5)


def test_feed_per_minute_and_rapid_rates():
    feeds = Feeds(feed=120.0, per_rev=False, rapid_x=3000.0, rapid_z=6000.0)
    t = machining_time((0, 0), [rapid(10, 30), feed(10, 24), dwell(10, 24, 1.5)], feeds)
    assert t.rapid == pytest.approx(max(10 / 3000, 30 / 6000) * 60)
    assert t.feed == pytest.approx(6 / 120 * 60) and t.dwell == 1.5
    assert clock_text(t.total) == "00:00:05" and clock_text(3725.4) == "01:02:05"


def test_feed_per_rev_at_a_fixed_speed():
    t = machining_time((20, 0), [feed(10, 0)], Feeds(feed=0.1, per_rev=True, rpm=500.0))
    assert t.feed == pytest.approx(10 / (0.1 * 500) * 60)


def test_an_arc_is_timed_along_its_length():
    # A half circle of radius 5 (G2 from X(radius)10 Z0 over X15 Z5 to X10 Z10): 5 pi long at 60 mm/min;
    # the G3 the other way round the same centre is as long.
    for clockwise in (True, False):
        t = machining_time((10, 0), [arc(clockwise, 10, 10, (10, 5))], FEEDS)
        assert t.feed == pytest.approx(5 * math.pi / 60 * 60, rel=1e-4)  # timed along chords within 0.001 mm
    # per revolution at a fixed speed: length / (feed x rpm)
    t = machining_time((10, 0), [arc(True, 15, 5, (10, 5))], Feeds(feed=0.1, per_rev=True, rpm=500.0))
    assert t.feed == pytest.approx(2.5 * math.pi / (0.1 * 500) * 60, rel=1e-4)


@pytest.mark.parametrize("x0, x1", [(20, 10), (10, 0), (3, 20), (-2, 6), (15, 15)])
def test_constant_surface_speed_matches_numeric_integration(x0, x1):
    """V 100 m/min capped at 2000 rpm (from radius 7.96 mm in), 0.1 mm/rev, a move with Z too."""
    feeds = Feeds(feed=0.1, per_rev=True, surface_speed=100.0, max_rpm=2000.0)
    z1 = 4.0
    t = machining_time((x0, 0), [feed(x1, z1)], feeds).feed
    n = 20000
    length = math.hypot(x1 - x0, z1)
    expected = 0.0
    for i in range(n):
        x = abs(x0 + (x1 - x0) * (i + 0.5) / n)
        rpm = min(2000.0, 100000.0 / (2 * math.pi * x)) if x > 0 else 2000.0
        expected += length / n / (0.1 * rpm) * 60
    assert t == pytest.approx(expected, rel=1e-6)
