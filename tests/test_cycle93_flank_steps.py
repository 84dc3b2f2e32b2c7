"""CYCLE93 seed step 3 (issue 9, item 5): "Machining of the flanks in one step
if angles are programmed under ANG1 or ANG2. Infeed along the groove width is
carried out in several steps if the flank width is larger."

Read as: the plunges across the opening are the steps of the infeed along the
groove width (each stops on the angled flank, leaving a tooth at most one
width step wide), and the flank pass takes those teeth one move per step. So
no move of step 3 removes material over more than one width step (95 % of
w - 2r) across the groove, however wide the flank; measured here with the
material-removal simulation, move by move."""

import pytest
from cycle93_helpers import after_the_plunges
from test_cycle93_simulation import run

from freecad_groove import verify as sim
from freecad_groove.engine import GroovingTool
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.cycle93_constants import WIDTH_STEP_FACTOR
from freecad_groove.engine.moves import FEED
from freecad_groove.verify.overlay import area, difference, intersection

BLADE = GroovingTool(5.0, 0.2)
START = (53.0, 5.0)  # radius X, Z: beside the groove, above the part
CHIP = 0.01  # mm: thinner removed material is a skim, not engagement


def wide_flank_groove(typ=5, ang1=30.0, ang2=40.0, **kw):
    """Flanks 10 x tan(30) = 5.8 and 10 x tan(40) = 8.4 wide across: wider than the blade."""
    base = dict(axfa=50.0, axsa=0.0, widg=12.0, depg=10.0, angc=0.0, ang1=ang1, ang2=ang2, idep=4.0, typ=typ)
    return Cycle93(**dict(base, **kw))


def step3_widths(call, tool, start):
    """For every feed of the contour passes (after the plunges): the width
    across the groove (along Z) of the material thicker than CHIP it removes."""
    moves, first, remaining = after_the_plunges(call, tool, start)
    plunge = call.plunge_direction()
    widths = []
    here = (moves[first - 1].x, moves[first - 1].z)
    for move in moves[first:]:
        if move.kind == FEED:
            swept = sim.swept_area(tool, plunge, here, (move.x, move.z))
            removed = intersection(remaining, swept)
            # Material thicker than CHIP (the trace's own path-tolerance
            # skims along the flank are not a cut across the groove).
            chip = removed.buffer(-CHIP).buffer(CHIP)
            if not chip.is_empty and area(chip) > 1e-6:
                zmin, _xmin, zmax, _xmax = chip.bounds
                widths.append(zmax - zmin)
            remaining = difference(remaining, swept)
        here = (move.x, move.z)
    return widths


@pytest.mark.parametrize("typ", [5, 1, 3, 7])
def test_no_step3_move_takes_more_than_one_width_step_of_a_wide_flank(typ):
    step = WIDTH_STEP_FACTOR * (BLADE.width - 2 * BLADE.corner_radius)
    start = START if typ in (5, 1) else (40.0, 5.0)
    call = wide_flank_groove(typ=typ, axfa=50.0 if typ in (5, 1) else 40.0)
    widths = step3_widths(call, BLADE, start)
    assert widths, "step 3 removed nothing"
    assert max(widths) <= step + 0.01, (max(widths), step)


def test_the_wide_flank_groove_is_cut_clean_and_accepted_by_linuxcnc():
    verdict, _ = run(wide_flank_groove(fal1=0.3, fal2=0.2, rci1=0.5, rco2=-0.5), BLADE)
    sim.assert_clean(verdict, allow_infeasible=True)
