"""CYCLE93's links and retracts where the Siemens manual leaves them open
(docs/choices.md): the plunges fed from VRT, the free-off as a rapid, and
contour passes that end where the last of their material is cut. Move lists
derived by hand."""

import math

import pytest

from freecad_groove.engine import GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.moves import FEED, RAPID

BLADE = Settings(tool=GroovingTool(5.0, 0.2))


def plunge_entries(moves, positions_z):
    """For each plunge at Z in ``positions_z``: (the rapids before its first feed since the last feed, that
    feed)."""
    found = []
    for z in positions_z:
        i = next(i for i, m in enumerate(moves) if m.kind == FEED and m.z == pytest.approx(z, abs=1e-9))
        j = i
        while j > 0 and moves[j - 1].kind == RAPID:
            j -= 1
        found.append((moves[j:i], moves[i]))
    return found


@pytest.mark.parametrize("vrt, clearance", [(0.0, 1.0), (5.0, 5.0), (0.05, 0.05)])
def test_each_plunge_feeds_from_vrt_over_the_highest_contour_under_the_blade(vrt, clearance):
    # TYP 5 (longitudinal, external, right) at radius 50 from Z0 toward -Z on a cone of ANGC 12:
    # the contour is X = 50 + Z tan 12 (radius), rising toward +Z. The 5 mm blade's reference corner
    # is its -Z one, so over a plunge at Z the highest contour under it is at Z + 5. Each plunge
    # comes over it VRT above that (VRT 0: 1 mm) and feeds from there: VRT is the clearance the
    # machinist gives the stock as it stands, so no rapid goes lower over stock not cut yet.
    call = Cycle93(axfa=50.0, axsa=0.0, widg=25.0, depg=10.0, angc=12.0, idep=2.0, typ=5, vrt=vrt)
    moves = call.expand(MachineState(x=60.0, z=5.0), BLADE)
    geo = call.geometry(BLADE)
    zs = [geo.frame.blade(u, 0.0)[1] for u in geo.plunge_positions()]
    assert len(zs) == 6
    for (rapids, feed), z in zip(plunge_entries(moves, zs), zs):
        top = 50.0 + (z + 5.0) * math.tan(math.radians(12.0))
        assert rapids and (rapids[-1].x, rapids[-1].z) == (pytest.approx(top + clearance, abs=1e-9),
                                                           pytest.approx(z, abs=1e-9))
        assert min(m.x for m in rapids) == pytest.approx(top + clearance, abs=1e-9)
        assert feed.x < top


def test_a_contour_pass_ends_at_the_foot_of_the_flank_where_the_plunges_have_cut_the_base():
    # TYP 1 (longitudinal, external, left) at radius 20 from Z0 toward +Z: 6 wide at the base, 3 deep,
    # both flanks at 45 degrees, so the opening runs from Z0 to Z12 and the base from Z3 to Z9; one
    # infeed (IDEP 5), VRT 1; a sharp 2 mm blade, reference corner at its -Z edge (covering Z to Z+2).
    # Plunge positions across the opening for the blade from Z0 to Z10, at most 0.95 * 2 = 1.9 apart:
    # 6 steps of 10/6. At Z0 and Z10 the blade stands on the flank's top (X20): no plunge. At 5/3 the
    # blade's -Z corner meets flank 1 at X20 - 5/3; at 10/3, 5 and 20/3 the base (X17); at 25/3 its +Z
    # corner (Z31/3) meets flank 2 at X20 - 5/3. Each plunge rapids to X21 and feeds from there;
    # the free-off (a rapid, 1 mm back toward the previous plunge) only where that one is cut as deep:
    # after 5, 20/3 and 25/3, not after 10/3 (the one at 5/3 stopped higher).
    # Step 3 from each edge: down the flank from the top (X20, fed from X21: VRT over the edge's stock, not
    # cut yet) to its foot, the
    # blade's -Z corner at Z3 (left) or its +Z corner at Z9, the reference at Z7 (right). From there
    # on along the base to the next plunge position (10/3, 20/3) the blade would cut nothing: the
    # plunges there have cut the base. So each pass goes straight up from the foot.
    call = Cycle93.parse("CYCLE93(20, 0, 6, 3, 0, 45, 45, 0, 0, 0, 0, 0, 0, 5, 0, 1, 1)")
    moves = call.expand(MachineState(x=25.0, z=-5.0), Settings(tool=GroovingTool(2.0, 0.0)))
    a, b = 20.0 - 5.0 / 3.0, 17.0
    expected = [(RAPID, 25.0, 0.0), (RAPID, 21.0, 0.0)]
    for z, bottom, freed in ((5 / 3, a, None), (10 / 3, b, None), (5.0, b, 4.0), (20 / 3, b, 17 / 3),
                             (25 / 3, a, 22 / 3)):
        expected += [(RAPID, 21.0, z), (FEED, bottom, z)]
        if freed is not None:
            expected += [(RAPID, bottom, freed)]
        expected += [(RAPID, 21.0, z if freed is None else freed)]
    expected += [(RAPID, 21.0, 0.0), (FEED, 20.0, 0.0), (FEED, a, 5 / 3), (FEED, 17.0, 3.0),
                 (RAPID, 21.0, 3.0),
                 (RAPID, 21.0, 10.0), (FEED, 20.0, 10.0), (FEED, a, 25 / 3), (FEED, 17.0, 7.0),
                 (RAPID, 21.0, 7.0),
                 (RAPID, 25.0, 7.0), (RAPID, 25.0, -5.0)]  # back the way the approach came
    got = [(m.kind, m.x, m.z) for m in moves]
    assert got == [(k, pytest.approx(x, abs=1e-9), pytest.approx(z, abs=1e-9)) for k, x, z in expected]
