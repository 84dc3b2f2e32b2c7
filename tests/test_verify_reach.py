"""The turning check's unreachable figure (the column model's reach,
verify/column_reach.py) against the independent model of a blade's reach
(tests/blade_oracle.py) on generated steep CYCLE93 grooves (contours 45 to 80
degrees off the groove's axis): a blade may overhang the groove's opening
where the contour falls away, so the figure is what no placement reaches,
not the material under the groove's columns: within 1 % of the oracle, and
on a slanted contour within what the columns' width allows (see figures).
Nothing is gouged and no rapid meets stock."""

import pytest
from blade_oracle import blade_reach
from hypothesis import HealthCheck, assume, given, settings
from shapely.geometry import Polygon
from test_cycle93_reach import steep_grooves

from freecad_groove.engine import CycleError, GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.verify import turned_section, turning
from freecad_groove.verify.turning import GrooveRun, OpInput

# The oracle's grid (blade_oracle.STEP, 0.002 mm) meets a wall up to a step off: its area is that much off
# along the groove's depth (the reach warnings' own tests allow the same slack).
GRID_SLACK = 0.002


def figures(call, tool):
    """(the column model's unreachable mm^2, the oracle's, the columns' slack) of one groove cut by its own
    expansion. The slack: a column holds the part's top at its centre, and on a contour of slope m the part
    stands higher at the column's side by m times half its width; a blade stands at column edges, which
    may miss its best place by as much again: it reaches up to m times a column's width lower or higher
    in the model, across its width at most (issue 22: the columns' width is the model's error there)."""
    setup = Settings(tool=tool)
    geo = call.geometry(setup)
    lo, hi = geo.opening(geo.final_top)
    u = lo - tool.width - 4.0
    start = geo.frame.blade(u, max(geo.contour_top(u), geo.contour_top(hi)) + 3.0)
    moves = call.expand(MachineState(x=start[0], z=start[1], feed=0.1, feed_per_rev=False), setup)
    stock_ring, region = geo.stock_world(), geo.region_world(1e-5)
    stock, groove = turned_section.groove_region(stock_ring), turned_section.groove_region(region)
    run = GrooveRun(list(moves), list(range(1, len(moves) + 1)), tool, call.plunge_direction(), region)
    check = turning.check_ops([OpInput("groove", start, [run])], stock, stock - groove).ops[0]
    assert check.gouge_depth == 0 and not check.rapid_hits, check.summary()
    target = Polygon([(z, x) for x, z in region]).buffer(0)
    _reached, missed = blade_reach(Polygon([(z, x) for x, z in stock_ring]), target, tool.width,
                                   tool.corner_radius, call.plunge_direction())
    slack = turning.step_for([tool]) * abs(geo.slope) * tool.width
    return check.unreachable, missed.area, slack


@pytest.mark.parametrize("text, expected", [
    # A contour at 60 degrees: the blade overhangs the lower edge of the opening; the wedge below that edge's
    # level between the base and the flank (the reach warning says 2.60 mm^2). The columns alone said 6.15.
    ("CYCLE93(20, -10, 6, 3, 60, 0, 0, 0, 0, 0, 0, 0.2, 0.2, 2, 0, 5, 0)", 2.60),
    # A groove on a 50 degree cone: the contour runs along the part's surface, which the columns took for a
    # wall over the whole groove (39.6 mm^2 of the 40 unreachable).
    ("CYCLE93(35, 0, 10, 4, 50, 0, 0, 0, 0, 0, 0, 0.3, 0.2, 2, 0, 5, 0)", 4.668),
])
def test_a_steep_groove_is_unreachable_only_where_no_placement_of_the_blade_reaches(text, expected):
    mine, oracle, _slack = figures(Cycle93.parse(text), GroovingTool(3.0, 0.2 if "20," in text[:12] else 0.4))
    assert oracle == pytest.approx(expected, rel=0.01)
    assert mine == pytest.approx(oracle, rel=0.01, abs=GRID_SLACK)


@settings(derandomize=True, database=None, max_examples=25, deadline=None,
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(steep_grooves())
def test_generated_steep_grooves_are_unreachable_as_the_blade_oracle_says(case):
    call, tool = case
    try:
        call.validate(Settings(tool=tool))
    except CycleError:
        assume(False)
    mine, oracle, slack = figures(call, tool)
    assert mine == pytest.approx(oracle, rel=0.01, abs=GRID_SLACK + slack), (call.emit(), tool)
