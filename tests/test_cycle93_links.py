"""CYCLE93's links and retracts where the Siemens manual leaves them open
(docs/choices.md): the plunges' entry clearance, the free-off as a rapid, and
contour passes that end where the last of their material is cut. Move lists
derived by hand."""

import math

import pytest

from freecad_groove.engine import GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.moves import FEED, RAPID

BLADE = Settings(tool=GroovingTool(5.0, 0.2))


def first_infeeds(moves):
    """Indexes of the first infeed of each plunge: a feed straight down in X
    right after a rapid straight down at the same Z, itself after a rapid
    that is not a chip-breaking retract (a retract follows a feed)."""
    found = []
    for i in range(2, len(moves)):
        a, b, m = moves[i - 2], moves[i - 1], moves[i]
        down = m.kind == FEED and b.kind == RAPID and m.z == b.z and m.x < b.x
        if down and a.kind == RAPID and a.z == b.z and a.x > b.x and moves[i - 3].kind != FEED:
            found.append(i)
    return found


def test_each_plunge_rapids_down_to_the_entry_clearance_over_the_highest_contour_under_the_blade():
    # TYP 5 (longitudinal, external, right) at radius 50 from Z0 toward -Z on a cone of ANGC 12:
    # the contour is X = 50 + Z tan 12 (radius), rising toward +Z. The 5 mm blade's reference corner
    # is its -Z one, so over a plunge at Z the highest contour under it is at Z + 5. Each plunge
    # comes over it VRT (1 mm) above that, rapids on down to 0.1 above it and feeds from there.
    call = Cycle93(axfa=50.0, axsa=0.0, widg=25.0, depg=10.0, angc=12.0, idep=2.0, typ=5, vrt=0.0)
    moves = call.expand(MachineState(x=53.0, z=5.0), BLADE)
    geo = call.geometry(BLADE)
    # The plunges first, then the two passes along the oblique base (entered over what the plunges left).
    starts = first_infeeds(moves)
    assert len(starts) == len(geo.plunge_positions()) + 2 == 8
    plunges = starts[:6]
    assert [moves[i].z for i in plunges] == pytest.approx([geo.frame.blade(u, 0.0)[1] for u in geo.plunge_positions()])
    for i in plunges:
        z = moves[i].z
        top = 50.0 + (z + 5.0) * math.tan(math.radians(12.0))
        assert (moves[i - 2].kind, moves[i - 2].x) == (RAPID, pytest.approx(top + 1.0, abs=1e-9))
        assert (moves[i - 1].kind, moves[i - 1].x) == (RAPID, pytest.approx(top + 0.1, abs=1e-9))


def test_a_vrt_below_the_entry_clearance_is_where_the_plunge_feeds_from():
    # VRT 0.05, 8 wide: two plunges. The blade comes over each at radius 50.05 (VRT above the contour)
    # and feeds from there: no rapid on down (the entry clearance is never more than VRT).
    call = Cycle93(axfa=50.0, axsa=0.0, widg=8.0, depg=3.0, angc=0.0, idep=5.0, typ=5, vrt=0.05)
    moves = call.expand(MachineState(x=53.0, z=5.0), BLADE)
    plunges = [i for i, m in enumerate(moves) if m.kind == FEED and moves[i - 1].kind == RAPID
               and moves[i - 1].z == m.z and m.x < moves[i - 1].x]
    assert len(plunges) == 2
    for i in plunges:
        assert moves[i - 1].x == pytest.approx(50.05, abs=1e-9)


def test_a_contour_pass_ends_at_the_foot_of_the_flank_where_the_plunges_have_cut_the_base():
    # TYP 1 (longitudinal, external, left) at radius 20 from Z0 toward +Z: 6 wide at the base, 3 deep,
    # both flanks at 45 degrees, so the opening runs from Z0 to Z12 and the base from Z3 to Z9; one
    # infeed (IDEP 5), VRT 1; a sharp 2 mm blade, reference corner at its -Z edge (covering Z to Z+2).
    # Plunge positions across the opening for the blade from Z0 to Z10, at most 0.95 * 2 = 1.9 apart:
    # 6 steps of 10/6. At Z0 and Z10 the blade stands on the flank's top (X20): no plunge. At 5/3 the
    # blade's -Z corner meets flank 1 at X20 - 5/3; at 10/3, 5 and 20/3 the base (X17); at 25/3 its +Z
    # corner (Z31/3) meets flank 2 at X20 - 5/3. Each plunge rapids to X21, on down to X20.1 and feeds;
    # the free-off (a rapid, 1 mm back toward the previous plunge) only where that one is cut as deep:
    # after 5, 20/3 and 25/3, not after 10/3 (the one at 5/3 stopped higher).
    # Step 3 from each edge: down the flank from the top (X20, entered from X20.1) to its foot, the
    # blade's -Z corner at Z3 (left) or its +Z corner at Z9, the reference at Z7 (right). From there
    # on along the base to the next plunge position (10/3, 20/3) the blade would cut nothing: the
    # plunges there have cut the base. So each pass goes straight up from the foot.
    call = Cycle93.parse("CYCLE93(20, 0, 6, 3, 0, 45, 45, 0, 0, 0, 0, 0, 0, 5, 0, 1, 1)")
    moves = call.expand(MachineState(x=25.0, z=-5.0), Settings(tool=GroovingTool(2.0, 0.0)))
    a, b = 20.0 - 5.0 / 3.0, 17.0
    expected = [(RAPID, 25.0, 0.0), (RAPID, 21.0, 0.0)]
    for z, bottom, freed in ((5 / 3, a, None), (10 / 3, b, None), (5.0, b, 4.0), (20 / 3, b, 17 / 3),
                             (25 / 3, a, 22 / 3)):
        expected += [(RAPID, 21.0, z), (RAPID, 20.1, z), (FEED, bottom, z)]
        if freed is not None:
            expected += [(RAPID, bottom, freed)]
        expected += [(RAPID, 21.0, z if freed is None else freed)]
    expected += [(RAPID, 21.0, 0.0), (RAPID, 20.1, 0.0), (FEED, 20.0, 0.0), (FEED, a, 5 / 3), (FEED, 17.0, 3.0),
                 (RAPID, 21.0, 3.0),
                 (RAPID, 21.0, 10.0), (RAPID, 20.1, 10.0), (FEED, 20.0, 10.0), (FEED, a, 25 / 3), (FEED, 17.0, 7.0),
                 (RAPID, 21.0, 7.0),
                 (RAPID, 25.0, 7.0), (RAPID, 25.0, -5.0)]  # back the way the approach came
    got = [(m.kind, m.x, m.z) for m in moves]
    assert got == [(k, pytest.approx(x, abs=1e-9), pytest.approx(z, abs=1e-9)) for k, x, z in expected]
