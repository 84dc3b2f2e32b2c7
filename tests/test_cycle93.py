"""CYCLE93: parameters, validation (with the Siemens alarms), geometry and the
moves' structure. The material-removal proof is in test_cycle93_simulation.py."""

import math
from pathlib import Path

import pytest
from cycle93_helpers import assert_reentries, chip_breaks
from hypothesis import given
from hypothesis import strategies as st

from freecad_groove.engine import CycleError, GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles import pecking
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.cycle93_constants import (
    DEFAULT_VRT_INCH,
    DEFAULT_VRT_MM,
    FREE_OFF_INCH,
    FREE_OFF_MM,
    REENTRY_CLEARANCE_INCH,
    REENTRY_CLEARANCE_MM,
)
from freecad_groove.engine.moves import DWELL, FEED, MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, RAPID
from freecad_groove.engine.numbers import MAX_MOVES

SEED_CALL = "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"
SEED_START = MachineState(x=40.0, z=65.0)  # N30 G00 X80 Z65, X as a diameter
TOOL = Settings(tool=GroovingTool(3.0, 0.4))


def call(**kw):
    """A plain external longitudinal groove, with overrides."""
    base = dict(
        axfa=20.0, axsa=-10.0, widg=6.0, depg=3.0, angc=0.0, ang1=0.0, ang2=0.0,
        rco1=0.0, rco2=0.0, rci1=0.0, rci2=0.0, fal1=0.0, fal2=0.0, idep=1.0,
        dwt=0.0, typ=5, vrt=0.0,
    )
    base.update(kw)
    return Cycle93(**base)


# -- text -----------------------------------------------------------------------


def test_seed_call_parses_field_by_field():
    c = Cycle93.parse("N40 " + SEED_CALL)
    assert (c.axfa, c.axsa, c.widg, c.depg, c.angc) == (35, 60, 30, 25, 12)
    assert (c.ang1, c.ang2, c.rco1, c.rco2, c.rci1, c.rci2) == (15, 16, 0, 0, -2, -2)
    assert (c.fal1, c.fal2, c.idep, c.dwt, c.typ, c.vrt, c.dn) == (1, 1, 10, 1, 5, 0, None)
    assert c.emit() == SEED_CALL


def test_empty_positions_are_kept_and_dn_is_optional():
    c = Cycle93.parse("CYCLE93(35, 60, 30, 25, , , , , , , , , , 2, , 5, , 2)")
    assert c.angc is None and c.vrt is None and c.dn == 2
    assert c.emit() == "CYCLE93(35, 60, 30, 25, , , , , , , , , , 2, , 5, , 2)"
    assert Cycle93.parse(c.emit()) == c


numbers = st.one_of(st.none(), st.integers(-500, 500).map(float), st.decimals(-500, 500, places=3).map(float))


@given(
    values=st.lists(numbers, min_size=17, max_size=17),
    typ=st.one_of(st.none(), st.integers(0, 20)),
    dn=st.one_of(st.none(), st.integers(0, 99)),
)
def test_parse_emit_round_trip(values, typ, dn):
    names = ["axfa", "axsa", "widg", "depg", "angc", "ang1", "ang2", "rco1", "rco2", "rci1", "rci2",
             "fal1", "fal2", "idep", "dwt", "typ", "vrt"]
    kw = dict(zip(names, values))
    kw["typ"] = typ
    c = Cycle93(**kw, dn=dn)
    assert Cycle93.parse(c.emit()) == c


@pytest.mark.parametrize(
    "text, param",
    [
        ("CYCLE93(35, 60, 30, SPD)", "DEPG"),
        ("CYCLE93(35, 60, 30, 25, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 5.5)", "TYP"),
        ("CYCLE93(" + ", ".join(["1"] * 19) + ")", "call"),
        ("G0 X10", "call"),
    ],
)
def test_unreadable_calls_name_the_parameter(text, param):
    with pytest.raises(CycleError) as e:
        Cycle93.parse(text)
    assert e.value.parameter == param
    assert str(e.value).startswith("CYCLE93 " + param)


def test_a_parameter_with_too_many_digits_is_named_and_shortened():
    with pytest.raises(CycleError) as e:
        Cycle93.parse("CYCLE93(35, %s)" % ("1" * 4301))
    assert str(e.value) == "CYCLE93 AXSA=1111111111...: the number has more than 4300 digits"


# -- validation: every rule, its message and its alarm ------------------------------


@pytest.mark.parametrize(
    "kw, param, alarm, words",
    [
        (dict(typ=0), "TYP", 61002, "1..8 or 11..18"),
        (dict(typ=9), "TYP", 61002, "1..8 or 11..18"),
        (dict(typ=10), "TYP", 61002, "1..8 or 11..18"),
        (dict(typ=19), "TYP", 61002, "1..8 or 11..18"),
        (dict(typ=None), "TYP", 61002, "1..8 or 11..18"),
        (dict(angc=-0.5), "ANGC", None, "0 <= ANGC <= 180"),
        (dict(angc=180.5), "ANGC", None, "0 <= ANGC <= 180"),
        (dict(ang1=89.999), "ANG1", None, "0 <= ANG1 < 89.999"),
        (dict(ang1=-1), "ANG1", None, "0 <= ANG1 < 89.999"),
        (dict(ang2=90), "ANG2", None, "0 <= ANG2 < 89.999"),
        (dict(idep=None), "IDEP", None, "must be programmed"),
        (dict(idep=0), "IDEP", None, "greater than 0"),
        (dict(idep=-1), "IDEP", None, "greater than 0"),
        (dict(widg=-6), "WIDG", None, "without sign"),
        (dict(widg=2.5), "WIDG", 61602, "narrower than the tool width 3"),
        (dict(widg=0), "WIDG", 61602, "narrower than the tool width"),
        (dict(depg=0), "DEPG", None, "greater than 0"),
        (dict(depg=-3), "DEPG", None, "greater than 0"),
        (dict(fal1=-0.1), "FAL1", None, "must not be negative"),
        (dict(fal1=3), "FAL1", None, "less than the groove depth"),
        (dict(fal2=-0.1), "FAL2", None, "must not be negative"),
        (dict(fal2=3), "FAL2", None, "less than the groove width"),
        (dict(vrt=-1), "VRT", None, "must not be negative"),
        (dict(dwt=-1), "DWT", None, "must not be negative"),
        (dict(axfa=None), "AXFA", None, "must be programmed"),
        (dict(depg=None), "DEPG", None, "must be programmed"),
        (dict(depg=5, rci1=3.5, rci2=2.5), "RCI1/RCI2", 61603, "touch or intersect"),
        (dict(rci1=3, rci2=3), "RCI1/RCI2", 61603, "touch or intersect"),
        (dict(typ=15, depg=4, rci1=-3.5, rci2=-3), "RCI1/RCI2", 61603, "touch or intersect"),
        (dict(typ=2, angc=0), "ANGC", 61603, "face groove on a contour element parallel"),
        (dict(typ=6, angc=180), "ANGC", 61603, "face groove on a contour element parallel"),
        (dict(typ=5, angc=90), "ANGC", 61603, "not perpendicular"),
        (dict(rco1=2, rci1=1.5), "RCO1/RCI1", 61603, "overlap"),
        (dict(typ=1, angc=40, ang2=70), "ANG2", 61603, "does not reach the groove base"),
    ],
)
def test_validation_rule(kw, param, alarm, words):
    with pytest.raises(CycleError) as e:
        call(**kw).validate(TOOL)
    err = e.value
    assert err.parameter == param
    assert err.alarm == alarm
    assert words in str(err)
    if err.value is not None:
        assert "=" in str(err)  # the value is printed
    if alarm is not None:
        assert str(err).endswith("(alarm %d)" % alarm)


def test_message_names_parameter_value_rule_and_alarm():
    with pytest.raises(CycleError) as e:
        call(widg=2.5).validate(TOOL)
    assert str(e.value) == "CYCLE93 WIDG=2.5: groove is narrower than the tool width 3 (alarm 61602)"


@pytest.mark.parametrize(
    "width, radius, alarm, words",
    [(0.0, 0.0, 61602, "cutting edge width must be greater than 0"), (3.0, 1.5, None, "less than half")],
)
def test_tool_rules(width, radius, alarm, words):
    with pytest.raises(CycleError) as e:
        call().validate(Settings(tool=GroovingTool(width, radius)))
    assert e.value.alarm == alarm
    assert words in str(e.value)


def test_start_point_inside_the_part_is_refused():
    with pytest.raises(CycleError) as e:
        call().expand(MachineState(x=15.0, z=0.0), TOOL)
    assert e.value.parameter == "start point"
    assert "inside the part" in str(e.value)


def test_start_point_whose_approach_would_cut_is_refused():
    # External groove approaches along Z first: from X19 (radius), below the
    # surface at radius 20 but beside the groove, the Z move would cut.
    with pytest.raises(CycleError) as e:
        call(axsa=-10.0).expand(MachineState(x=19.0, z=30.0), TOOL)
    assert e.value.parameter == "start point"


def test_base_radii_that_just_fit_are_accepted():
    call(rci1=1.4, rci2=1.4).validate(TOOL)  # 2.8 of a 6 mm base


# -- geometry ---------------------------------------------------------------------


def extent(moves):
    xs = [m.x for m in moves]
    zs = [m.z for m in moves]
    return min(xs), max(xs), min(zs), max(zs)


@pytest.mark.parametrize(
    "typ, plunge",
    [(1, MINUS_X), (5, MINUS_X), (3, PLUS_X), (7, PLUS_X), (2, MINUS_Z), (6, MINUS_Z), (4, PLUS_Z), (8, PLUS_Z),
     (11, MINUS_X), (18, PLUS_Z)],
)
def test_typ_units_digit_selects_the_plunge_direction(typ, plunge):
    assert call(typ=typ).plunge_direction() == plunge


def test_left_and_right_longitudinal_grooves_extend_toward_plus_and_minus_z():
    def sharp(c):
        return [c.geometry(TOOL).frame.point(u, v) for u, v in c.geometry(TOOL).corners_sharp]

    right = sharp(call(typ=5))  # start point on the right: groove toward -Z
    left = sharp(call(typ=1))
    assert max(z for _x, z in right) == pytest.approx(-10) and min(z for _x, z in right) == pytest.approx(-16)
    assert min(z for _x, z in left) == pytest.approx(-10) and max(z for _x, z in left) == pytest.approx(-4)
    assert min(x for x, _z in right) == pytest.approx(17)  # radius 20 minus 3 deep
    internal = sharp(call(typ=7))
    assert max(x for x, _z in internal) == pytest.approx(23)  # bore grows outward


def test_face_grooves_swap_the_axes():
    face = call(typ=2, angc=90, axfa=10.0, axsa=0.0)
    pts = [face.geometry(TOOL).frame.point(u, v) for u, v in face.geometry(TOOL).corners_sharp]
    assert min(z for _x, z in pts) == pytest.approx(-3)  # plunged 3 deep toward -Z
    # "left": toward +X
    assert min(x for x, _z in pts) == pytest.approx(10) and max(x for x, _z in pts) == pytest.approx(16)
    right = call(typ=6, angc=90, axfa=16.0, axsa=0.0)
    pts = [right.geometry(TOOL).frame.point(u, v) for u, v in right.geometry(TOOL).corners_sharp]
    assert min(x for x, _z in pts) == pytest.approx(10) and max(x for x, _z in pts) == pytest.approx(16)
    internal = call(typ=4, angc=90, axfa=10.0, axsa=0.0)
    pts = [internal.geometry(TOOL).frame.point(u, v) for u, v in internal.geometry(TOOL).corners_sharp]
    assert max(z for _x, z in pts) == pytest.approx(3)  # toward +Z


def test_angc_is_measured_counter_clockwise_from_plus_z():
    # ANGC 12 on the seed's external groove: the contour rises toward +Z, so
    # the far edge (toward -Z) is lower than the start point.
    g = Cycle93.parse(SEED_CALL).geometry(TOOL)
    p1, _b1, _b2, p2 = [g.frame.point(u, v) for u, v in g.corners_sharp]
    assert p1 == pytest.approx((35.0, 60.0))
    slope = (p1[0] - p2[0]) / (p1[1] - p2[1])
    assert slope == pytest.approx(math.tan(math.radians(12)))


def test_flank_angles_open_the_groove_and_widg_is_the_base_width():
    g = call(ang1=20, ang2=10, depg=4.0).geometry(TOOL)
    p1, b1, b2, p2 = g.corners_sharp
    assert b2[0] - b1[0] == pytest.approx(6.0)
    assert b1[0] - p1[0] == pytest.approx(4 * math.tan(math.radians(20)))
    assert p2[0] - b2[0] == pytest.approx(4 * math.tan(math.radians(10)))


def test_chamfer_chf_and_chr_readings_differ_by_the_corner_angle():
    chf = call(rci1=-1.0, typ=5).geometry(TOOL).final_corners[1]
    chr_ = call(rci1=-1.0, typ=15).geometry(TOOL).final_corners[1]
    assert chr_.length == pytest.approx(1.0)  # CHR: 1 mm along each element
    assert chf.length == pytest.approx(1.0 / math.sqrt(2))  # CHF: the 1 mm chamfer of a 90 degree corner


def test_diameter_input_setting_halves_axfa_depg_and_fal1():
    radius = call(axfa=20.0, depg=3.0, fal1=0.5).geometry(TOOL)
    dia = call(axfa=40.0, depg=6.0, fal1=1.0).geometry(Settings(tool=TOOL.tool, cycle93_diameter_input=True))
    assert [c for p in dia.corners_sharp for c in p] == pytest.approx([c for p in radius.corners_sharp for c in p])
    assert dia.frame.x0 == 20.0
    assert [c for p in dia.rough_top for c in p] == pytest.approx([c for p in radius.rough_top for c in p])


# -- moves ------------------------------------------------------------------------


def test_seed_example_moves_follow_the_four_steps():
    c = Cycle93.parse(SEED_CALL)
    moves = c.expand(SEED_START, TOOL)
    assert moves[-1][:3] == (RAPID, 40.0, 65.0)  # back at the start point
    # External groove: first along Z (the longitudinal axis) at the start X.
    assert moves[0].kind == RAPID and moves[0].x == 40.0 and moves[0].z != 65.0
    assert moves[1].kind == RAPID and moves[1].z == moves[0].z
    dwells = [m for m in moves if m.kind == DWELL]
    assert dwells and all(m.p == 1.0 for m in dwells)
    # Every plunge: equal infeeds of at most IDEP (10), each followed by a
    # 1 mm (VRT = 0) rapid chip-breaking retract, a rapid back down to 0.1
    # above the depth reached, then fed on.
    plunges = split_plunges(moves)
    assert len(plunges) >= 10
    widths = sorted({round(p["z"], 6) for p in plunges})
    steps = [b - a for a, b in zip(widths, widths[1:])]
    assert max(steps) <= 0.95 * (3.0 - 2 * 0.4) + 1e-9
    assert max(steps) - min(steps) < 1e-5  # equal steps
    deepest = max(plunges, key=lambda p: p["depth"])
    assert len(deepest["infeeds"]) == 3  # about 25 mm deep in IDEP 10 infeeds
    incs = deepest["infeeds"]
    assert max(incs) - min(incs) < 1e-6 and max(incs) <= 10
    assert deepest["retracts"] == pytest.approx([1.0, 1.0])
    assert deepest["reentries"] == pytest.approx([0.1, 0.1])


def split_plunges(moves, vrt=1.0):
    """The roughing plunges of an external longitudinal groove: a rapid to the
    clearance, feeds straight down in X with rapid chip-breaking retracts and
    rapid re-entries in between, a dwell at the bottom. ``reentries``: how far
    above the depth reached each re-entry rapid stops."""

    def chip_break(j):  # a retract (after a feed), a re-entry (back down after a retract) or the entry
        up, down = moves[j - 1], moves[j]
        back_in = up.kind == RAPID and moves[j - 2].kind == FEED and down.z == up.z and down.x < up.x
        entry = up.kind == RAPID and moves[j + 1].kind == FEED and down.z == up.z and down.x < up.x
        return moves[j - 1].kind == FEED or back_in or entry

    out = []
    for i, m in enumerate(moves):
        if m.kind != DWELL:
            continue
        j = i - 1
        while moves[j].kind != RAPID or chip_break(j):
            j -= 1  # back to the rapid that brought the tool over this plunge
        seq = moves[j:i]
        assert all(s.z == m.z for s in seq)
        top = seq[0].x - vrt
        levels = [s.x for s in seq if s.kind == FEED]
        infeeds = [a - b for a, b in zip([top] + levels, levels)]
        triples = list(zip(seq, seq[1:], seq[2:]))
        retracts = [b.x - a.x for a, b, _c in triples if a.kind == FEED and b.kind == RAPID]
        reentries = [c.x - a.x for a, b, c in triples if a.kind == FEED and b.kind == RAPID and c.kind == RAPID]
        out.append(dict(z=m.z, depth=top - m.x, infeeds=infeeds, retracts=retracts, reentries=reentries))
    return out


def test_plain_groove_moves_by_hand():
    # 6 wide at radius 20 from z -10 toward -Z, 3 deep, IDEP 1, VRT 0 = 1 mm,
    # a 3 mm blade (r 0.4): the opening -16..-10 takes 3 plunges (3 mm to
    # cover in steps of at most 0.95 * (3 - 0.8) = 2.09: 2 steps of 1.5),
    # from the start side: minus corner at z -13, -14.5, -16. Each: rapid to
    # VRT above the surface (X21), three infeeds of 1 (X19, X18, X17) fed from
    # there (VRT is the clearance over uncut stock); after the first two a
    # chip-breaking retract of VRT (X20, X19), a rapid back down the slot just
    # cut to 0.1 above the depth reached (X19.1, X18.1), then the feed on. At
    # the bottom of the second and third plunge the free-off: a rapid of 1 mm
    # along Z back toward the previous plunge (1.5 away, cut as deep), to
    # Z-13.5 and Z-15; the first plunge has none. Out from there. No contour
    # pass (square flanks, no allowance), back to the start the way the
    # approach came (along X from the freed Z-15, then along Z).
    moves = call().expand(MachineState(x=25.0, z=0.0), TOOL)
    expected = [(RAPID, 25.0, -13.0)]
    for z, freed in ((-13.0, None), (-14.5, -13.5), (-16.0, -15.0)):
        expected += [(RAPID, 21.0, z), (FEED, 19.0, z), (RAPID, 20.0, z), (RAPID, 19.1, z),
                     (FEED, 18.0, z), (RAPID, 19.0, z), (RAPID, 18.1, z), (FEED, 17.0, z)]
        if freed is None:
            expected += [(RAPID, 21.0, z)]  # the first plunge: straight out
        else:
            expected += [(RAPID, 17.0, freed), (RAPID, 21.0, freed)]  # free-off along the bottom, then out
    expected += [(RAPID, 25.0, -15.0), (RAPID, 25.0, 0.0)]
    assert [(m.kind, round(m.x, 9), round(m.z, 9)) for m in moves] == expected


@pytest.mark.parametrize(
    "kw, start, metric, tool, breaks",
    [
        # The seed example: 12 plunges, the deepest in 3 infeeds.
        (None, SEED_START, True, TOOL, None),
        # The plain groove above: 3 plunges of 3 infeeds, 2 chip-breaks each.
        (dict(), MachineState(x=25.0, z=0.0), True, TOOL, 6),
        # A face groove (plunging -Z), VRT 0.5: 3 plunges x 2.
        (dict(typ=2, angc=90, axfa=10.0, axsa=0.0, vrt=0.5), MachineState(x=5.0, z=2.0), True, TOOL, 6),
        # An internal groove (plunging +X), 3 deep in IDEP 0.7: 5 infeeds.
        (dict(typ=7, idep=0.7), MachineState(x=10.0, z=5.0), True, TOOL, 12),
        # VRT below the clearance: the retract already stands there.
        (dict(vrt=0.05), MachineState(x=25.0, z=0.0), True, TOOL, 6),
        # Inch: VRT 0 = 0.04 in, re-entry 0.004 in; 0.1 deep in IDEP 0.05.
        (dict(axfa=1.0, axsa=0.0, widg=0.25, depg=0.1, idep=0.05), MachineState(x=1.2, z=0.5, metric=False), False,
         Settings(tool=GroovingTool(0.12, 0.01)), 3),
    ],
)
def test_after_each_chip_break_the_blade_rapids_back_down_its_slot(kw, start, metric, tool, breaks):
    c = Cycle93.parse(SEED_CALL) if kw is None else call(**kw)
    moves = c.expand(start, tool)
    vrt = c.geometry(tool, metric=metric).params["VRT"]
    clearance = min(vrt, REENTRY_CLEARANCE_MM if metric else REENTRY_CLEARANCE_INCH)
    count = assert_reentries(moves, c.plunge_direction(), vrt, clearance)
    assert count == (breaks if breaks is not None else len(chip_breaks(moves, c.plunge_direction(), vrt))) > 0


def free_offs(c, start, tool, metric=True):
    """[(k, freed u or None)] of each plunge k: after its bottom (and dwell)
    the next move, in the groove frame, checked to be a RAPID along the bottom
    followed by a RAPID straight out, or that RAPID out alone (None)."""
    geo = c.geometry(tool, metric=metric)
    moves = [m for m in c.expand(start, tool) if m.kind != DWELL]
    uv = [geo.frame.blade_of(m.x, m.z) for m in moves]
    found = []
    for k, u in enumerate(geo.plunge_positions()):
        bottom = geo.rough_env.lowest(u)
        i = next(j for j, (a, b) in enumerate(uv) if moves[j].kind == FEED
                 and a == pytest.approx(u, abs=1e-9) and b == pytest.approx(bottom, abs=1e-9))
        freed = None
        if moves[i + 1].kind == RAPID and uv[i + 1][0] != pytest.approx(u, abs=1e-9):
            freed, level = uv[i + 1]
            assert level == pytest.approx(bottom, abs=1e-9)  # along the bottom, nothing deeper
            i += 1
        assert moves[i + 1].kind == RAPID and uv[i + 1][0] == pytest.approx(uv[i][0], abs=1e-9)
        assert uv[i + 1][1] > bottom  # straight out from where the blade stands
        found.append((k, freed, u, bottom))
    return found


@pytest.mark.parametrize(
    "kw, start, metric, tool, free",
    [
        # The plain groove: 3 plunges 1.5 apart, free-off 1 mm.
        (dict(), MachineState(x=25.0, z=0.0), True, TOOL, 1.0),
        # with a dwell at the base: the dwell first, then the free-off.
        (dict(dwt=2.0), MachineState(x=25.0, z=0.0), True, TOOL, 1.0),
        # A face groove and an internal one.
        (dict(typ=2, angc=90, axfa=10.0, axsa=0.0, vrt=0.5), MachineState(x=5.0, z=2.0), True, TOOL, 1.0),
        (dict(typ=7, idep=0.7), MachineState(x=10.0, z=5.0), True, TOOL, 1.0),
        # 3.5 wide: 2 plunges 0.5 apart, so the free-off is 0.5 (less room).
        (dict(widg=3.5), MachineState(x=25.0, z=0.0), True, TOOL, 0.5),
        # Inch: 0.04 in.
        (dict(axfa=1.0, axsa=0.0, widg=0.5, depg=0.1, idep=0.05), MachineState(x=1.2, z=0.5, metric=False), False,
         Settings(tool=GroovingTool(0.12, 0.01)), 0.04),
    ],
)
def test_from_the_second_plunge_on_the_blade_frees_off_toward_the_previous_one(kw, start, metric, tool, free):
    found = free_offs(call(**kw), start, tool, metric)
    assert len(found) >= 2 and found[0][1] is None  # the first plunge: straight out
    for (_k, _f, u_prev, _b), (_k2, freed, u, _bottom) in zip(found, found[1:]):
        step = min(free, abs(u - u_prev))
        assert freed == pytest.approx(u - math.copysign(step, u - u_prev), abs=1e-9)


def test_no_free_off_where_the_previous_plunge_stopped_higher():
    # The seed example's base is oblique, deeper away from the start side:
    # each plunge's predecessor stopped higher, its slot not cut this deep.
    found = free_offs(Cycle93.parse(SEED_CALL), SEED_START, TOOL)
    for (_k, _f, u_prev, bottom_prev), (_k2, freed, u, bottom) in zip(found, found[1:]):
        if bottom_prev > bottom + 1e-6:
            assert freed is None
        else:
            assert freed == pytest.approx(u - math.copysign(min(1.0, abs(u - u_prev)), u - u_prev), abs=1e-9)


def test_free_off_is_the_one_in_the_guides_choices():
    assert (FREE_OFF_MM, FREE_OFF_INCH) == (1.0, 0.04)
    readme = (Path(__file__).parent.parent / "docs" / "choices.md").read_text(encoding="utf-8")
    row = next(line for line in readme.splitlines() if line.startswith("| free-off"))
    assert "1 mm" in row and "0.04 in" in row and "FREE_OFF_MM" in row and "a RAPID" in row


def test_reentry_clearance_is_the_one_in_the_guides_choices_and_below_the_default_vrt():
    assert (REENTRY_CLEARANCE_MM, REENTRY_CLEARANCE_INCH) == (0.1, 0.004)
    assert REENTRY_CLEARANCE_MM < DEFAULT_VRT_MM and REENTRY_CLEARANCE_INCH < DEFAULT_VRT_INCH
    readme = (Path(__file__).parent.parent / "docs" / "choices.md").read_text(encoding="utf-8")
    row = next(line for line in readme.splitlines() if line.startswith("| chip-break retract |"))
    assert "0.1 mm" in row and "0.004 in" in row and "REENTRY_CLEARANCE_MM" in row


def test_plain_groove_is_plunged_only_with_no_contour_pass():
    moves = call().expand(MachineState(x=25.0, z=0.0), TOOL)
    feeds = [m for m in moves if m.kind == FEED]
    # every feed is a straight plunge (no Z motion while feeding) but for the
    # free-offs: along Z at the depth just reached
    prev = None
    for m in moves:
        if m.kind == FEED:
            assert prev is not None and (m.z == prev.z or (prev.kind == FEED and m.x == prev.x == 17.0))
        prev = m
    assert min(m.x for m in feeds) == pytest.approx(17.0)
    # plunge positions cover the groove from -16 to -10 with a 3 mm blade
    refs = sorted({round(m.z, 9) for m in feeds})
    assert refs[0] == pytest.approx(-16.0) and refs[-1] == pytest.approx(-13.0)


def test_internal_groove_approaches_along_x_first():
    moves = call(typ=7).expand(MachineState(x=10.0, z=5.0), TOOL)
    assert moves[0].kind == RAPID and moves[0].z == 5.0 and moves[0].x != 10.0
    assert moves[-1][:3] == (RAPID, 10.0, 5.0)


def test_reference_corner_plus_shifts_every_move_by_the_width():
    minus = call().expand(MachineState(x=25.0, z=0.0), TOOL)
    plus_settings = Settings(tool=GroovingTool(3.0, 0.4, reference="plus"))
    plus = call().expand(MachineState(x=25.0, z=3.0), plus_settings)
    def body(ms):
        return [(m.kind, round(m.x, 9), round(m.z, 9)) for m in ms[:-2]]

    assert [(k, x, z + 3.0) for k, x, z in body(minus)][1:] == body(plus)[1:]


def test_vrt_sets_both_chip_break_and_clearance():
    moves = call(vrt=0.5, depg=3.0, idep=1.0).expand(MachineState(x=25.0, z=0.0), TOOL)
    ups = [b.x - a.x for a, b in zip(moves, moves[1:]) if a.kind == FEED and b.kind == RAPID and b.z == a.z]
    assert ups and all(u == pytest.approx(0.5) for u in ups[:2])
    top_rapids = {round(m.x, 9) for m in moves if m.kind == RAPID and m.x < 25}
    assert 20.5 in top_rapids  # 0.5 above the surface at radius 20


def test_inch_program_defaults_vrt_to_004():
    c = call(axfa=1.0, axsa=0.0, widg=0.25, depg=0.1, idep=0.05)
    moves = c.expand(MachineState(x=1.2, z=0.5, metric=False), Settings(tool=GroovingTool(0.12, 0.01)))
    assert max(m.x for m in moves if m.kind == RAPID and m.x < 1.2) == pytest.approx(1.04)


# -- DWT: a dwell at the recess base only ---------------------------------------------


def test_dwell_only_where_a_plunge_reaches_the_base():
    # Flanks at 30 degrees, 3 deep: the opening is 6 + 2 * 3 * tan 30 = 9.464
    # wide, so the minus corner plunges at z = -13 - k * 6.464 / 4, k = 0..4
    # (steps of at most 0.95 * (3 - 2 * 0.4) = 2.09). The first and the last
    # stop on a flank, the three between reach the base at radius 17: only
    # those dwell ("dwell time at recess base").
    moves = call(ang1=30, ang2=30, dwt=0.5).expand(MachineState(x=25.0, z=0.0), TOOL)
    span = 6 + 6 * math.tan(math.radians(30)) - 3
    plunge_z = [-13 - span * k / 4 for k in range(5)]
    dwells = [(m.x, m.z, m.p) for m in moves if m.kind == DWELL]
    assert dwells == pytest.approx([(17.0, z, 0.5) for z in plunge_z[1:4]])
    for z in (plunge_z[0], plunge_z[4]):  # plunged, down to the flank, no dwell
        assert any(m.kind == FEED and m.z == pytest.approx(z) and 17.1 < m.x < 20 for m in moves)


def test_seed_example_dwells_where_its_plunges_end_on_the_oblique_base():
    # The roughing base runs FAL1 = 1 above the base: x = 11 + (z - 60) tan 12
    # at the start point's z = 60. The 3 mm blade's corner (r 0.4) rests on it
    # where the slope q = tan 12 is tangent to the corner: s = 2.6 + 0.4 q /
    # sqrt(1 + q^2) from the minus corner, s - 2.6 = 0.0832, 0.4 - sqrt(0.16 -
    # 0.0832^2) = 0.00875 above the front edge. A plunge ending higher stopped
    # on a flank or a base chamfer.
    q = math.tan(math.radians(12))
    s = 2.6 + 0.4 * q / math.hypot(1, q)
    lift = 0.4 - math.sqrt(0.16 - (s - 2.6) ** 2)

    def base(z):
        return 11 + (z + s - 60) * q - lift

    moves = Cycle93.parse(SEED_CALL).expand(SEED_START, TOOL)
    first_pass = next(i for i in range(1, len(moves)) if moves[i].kind == FEED and moves[i].z != moves[i - 1].z)
    roughing = moves[:first_pass]
    bottoms = {}
    for m in roughing:
        if m.kind == FEED:
            bottoms[m.z] = min(m.x, bottoms.get(m.z, m.x))
    dwell_z = [m.z for m in roughing if m.kind == DWELL]
    on_base = [z for z, x in bottoms.items() if x <= base(z) + 1e-6]
    assert dwell_z == on_base
    assert all(m.x == pytest.approx(base(m.z), abs=1e-9) for m in roughing if m.kind == DWELL)
    assert 0 < len(on_base) < len(bottoms)  # plunges on the flanks and chamfers do not dwell


# -- the size of an expansion, counted before anything is expanded --------------------------


def test_one_move_limit_for_every_cycle():
    assert MAX_MOVES == 1_000_000
    assert pecking.MAX_MOVES is MAX_MOVES


@pytest.mark.parametrize(
    "kw, param, start",
    [
        # 6 wide with a 3 mm blade: 3 plunges, (6 - 3) / 2.09 = 1.4 steps apart;
        # 3 deep in infeeds of 0.000001: 3000000 infeeds.
        (dict(idep=0.000001), "IDEP", "IDEP=0.000001: gives 3 plunges (steps of at most 2.09 across) of up to 3000000 "
                                      "infeeds"),
        # 999999 deep in infeeds of 1: DEPG is the one far from the blade's size.
        (dict(depg=999999, idep=1), "DEPG", "DEPG=999999: gives 3 plunges (steps of at most 2.09 across) of up to "
                                            "999999 infeeds"),
        # (999999 - 3) / 2.09 = 478466.98 steps: 478468 plunges of 3 infeeds.
        (dict(widg=999999), "WIDG", "WIDG=999999: gives 478468 plunges (steps of at most 2.09 across) of up to 3 "
                                    "infeeds"),
        # An 80 degree flank 99999 deep opens the groove 567k wide: DEPG.
        (dict(depg=99999, ang1=80, idep=99999), "DEPG", "DEPG=99999: gives "),
    ],
)
def test_an_expansion_beyond_the_move_limit_is_refused_naming_the_parameter(kw, param, start):
    with pytest.raises(CycleError) as e:
        call(**kw).validate(TOOL)
    assert e.value.parameter == param
    assert str(e.value).startswith("CYCLE93 " + start)
    assert str(e.value).endswith("more than the 1000000 moves an expansion may hold")


def test_the_calls_of_issue_9_are_refused():
    seed = "CYCLE93(35, 60, 30, %s, 12, 15, 16, 0, 0, -2, -2, 1, 1, %s, 1, 5, 0)"
    with pytest.raises(CycleError) as e:
        Cycle93.parse(seed % ("12345678", "10")).validate(TOOL)
    assert str(e.value) == ("CYCLE93 DEPG=12345678: must be less than 1000000 in magnitude, like every coordinate "
                            "written")
    for idep in ("0.000000001", "0.000001"):
        with pytest.raises(CycleError) as e:
            Cycle93.parse(seed % ("25", idep)).expand(SEED_START, TOOL)
        assert e.value.parameter == "IDEP" and "moves an expansion may hold" in str(e.value)


@pytest.mark.parametrize(
    "kw, tool, param, words",
    [
        (dict(depg=1e300), TOOL, "DEPG", "DEPG=1e+300: must be less than 1000000 in magnitude"),
        (dict(widg=1e300), TOOL, "WIDG", "WIDG=1e+300: must be less than 1000000 in magnitude"),
        (dict(widg=1e300, depg=1e300), TOOL, "WIDG", "less than 1000000 in magnitude"),
        (dict(rco1=1e300), TOOL, "RCO1", "less than 1000000 in magnitude"),
        (dict(vrt=1e300), TOOL, "VRT", "less than 1000000 in magnitude"),
        (dict(axfa=-1e300), TOOL, "AXFA", "AXFA=-1e+300: must be less than 1000000 in magnitude"),
        (dict(depg=999999, widg=999999, idep=0.000001), TOOL, "IDEP", "moves an expansion may hold"),
        (dict(idep=1e-300), TOOL, "IDEP", "of up to 3e+300 infeeds"),
        # A blade 1e-300 wide: 6 / (0.95 * 1e-300) plunges.
        (dict(), Settings(tool=GroovingTool(1e-300)), "WIDG", "WIDG=6: gives 6.32e+300 plunges"),
    ],
)
def test_huge_values_give_a_clean_error_at_once(kw, tool, param, words):
    with pytest.raises(CycleError) as e:
        call(**kw).validate(tool)
    assert e.value.parameter == param
    assert words in str(e.value)


def test_a_wide_base_radius_of_a_large_groove_is_traced():
    # The arc of a 12345 radius ends a rounding error (~1e-12) behind the
    # flank it meets; the profile must not be taken as folding back.
    c = Cycle93.parse("CYCLE93(60000, 0, 20000, 20000, 0, 0, 0, 12345, 0, 0, 0, 0, 0, 20000, 0, 5, 0)")
    settings = Settings(tool=GroovingTool(4.0))
    moves = c.expand(MachineState(x=60010.0, z=10.0), settings)
    assert min(m.x for m in moves) == pytest.approx(40000.0)
    assert len(moves) <= c.geometry(settings).size.moves


# -- messages and numbers: the values as programmed -----------------------------------


@pytest.mark.parametrize(
    "kw, message",
    [
        (dict(widg=-1.0), "CYCLE93 WIDG=-1: must be entered without sign"),
        (dict(widg=-0.0000001), "CYCLE93 WIDG=-0.0000001: must be entered without sign"),
        (dict(widg=2.9999999), "CYCLE93 WIDG=2.9999999: groove is narrower than the tool width 3 (alarm 61602)"),
        (dict(depg=-0.00000012), "CYCLE93 DEPG=-0.00000012: must be greater than 0 (enter without sign)"),
    ],
)
def test_messages_quote_the_value_as_programmed(kw, message):
    with pytest.raises(CycleError) as e:
        call(**kw).validate(TOOL)
    assert str(e.value) == message


def test_emit_writes_every_value_exactly_without_an_exponent():
    c = call(axfa=0.1 + 0.2, axsa=-10.123456789, widg=6.0000001, fal1=1e-7, dwt=0.0, vrt=-0.0)
    assert c.emit() == ("CYCLE93(0.30000000000000004, -10.123456789, 6.0000001, 3, 0, 0, 0, 0, 0, 0, 0, "
                        "0.0000001, 0, 1, 0, 5, 0)")
    assert Cycle93.parse(c.emit()) == c


@given(
    values=st.lists(st.floats(allow_nan=False, allow_infinity=False), min_size=16, max_size=16),
    many=st.lists(st.decimals(-1000, 1000, places=12).map(float), min_size=16, max_size=16),
    typ=st.integers(1, 18),
)
def test_parse_emit_round_trip_keeps_every_decimal(values, many, typ):
    names = ["axfa", "axsa", "widg", "depg", "angc", "ang1", "ang2", "rco1", "rco2", "rci1", "rci2",
             "fal1", "fal2", "idep", "dwt", "vrt"]
    for row in (values, many):
        c = Cycle93(**dict(zip(names, row)), typ=typ)
        text = c.emit()
        assert "e" not in text.lower().replace("cycle", "")  # Siemens writes exponents as EX: none at all
        assert Cycle93.parse(text) == c
