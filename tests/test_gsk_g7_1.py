"""GSK G7.1: cylindrical interpolation (Type I) and its roughing cycle (Type II).

Move lists are derived by hand from the module notes of cycles/gsk_g7_1.py: an
L-shaped slot on an R20 cylinder (C20.): from Z0 C0, G1 Z-10. (10 mm along the
axis), then G1 C90. (a quarter turn: 20*pi/2 = 31.4159 mm on the developed
surface). F100 along the developed path: the Z move writes F100, the C move
100 * 180 / (pi * 20) = 286.4789 degrees per minute (same time: 0.314159 min).
Tuples are (kind, x radius, z, f, c).
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pecking_helpers import F, R, raises
from rs274 import require_rs274, run_rs274
from test_cli import run_inline

from freecad_groove.engine.cycles.gsk_g7_1 import GskG7_1, PathBlock, arc_points
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import MachineState
from freecad_groove.engine.numbers import ARC_CHORD_TOLERANCE, format_decimal
from freecad_groove.engine.output.program import write_program
from freecad_groove.engine.output.writer import Writer
from freecad_groove.engine.translator import translate_program

C_FEED = 100.0 * 180.0 / (math.pi * 20.0)
L_SLOT = "G1 Z-10. F100.\nG1 C90."


def state(x, z=0.0, c=0.0, feed=None, feed_per_rev=False, **kw):
    return MachineState(x=x, z=z, c=c, feed=feed, feed_per_rev=feed_per_rev, **kw)


def moves_of(moves):
    return [(m.kind, round(m.x, 9), round(m.z, 9), None if m.f is None else round(m.f, 6),
             None if m.c is None else round(m.c, 9)) for m in moves]


def region(start, path=L_SLOT, cancel="G7.1 C0"):
    return GskG7_1.parse("\n".join([start, path, cancel]))


def test_type_i_runs_the_path_once_at_the_start_x():
    m = region("G7.1 C20.")
    assert m == GskG7_1(C=20.0, path=(PathBlock("G1", z=-10.0, f=100.0), PathBlock("G1", c=90.0)))
    assert moves_of(m.expand(state(18.0))) == [
        (F, 18.0, -10.0, 100.0, 0.0),
        (F, 18.0, -10.0, round(C_FEED, 6), 90.0),
    ]


def test_type_ii_rough_passes_finish_retract_and_return():
    # J-4 (diameter): finish at diameter 40-4 = 36 (r18); K0.4: rough passes down to
    # r18.2 in L2 equal steps: r19.1, r18.2; R2.: the cycle start G at diameter 42 (r21).
    m = region("G7.1 C20. J-4. R2. K0.4 L2")
    one_pass = lambda x, infeed: [  # noqa: E731
        (F, x, 0.0, infeed, 0.0),  # G -> An: X infeed
        (F, x, -10.0, 100.0, 0.0),  # An -> Bn along Z
        (F, x, -10.0, round(C_FEED, 6), 90.0),  # Bn -> Dn: the quarter turn
        (R, 21.0, -10.0, None, 90.0),  # Dn -> E: X straight out
        (R, 21.0, 0.0, None, 0.0),  # E -> G: Z and C back
    ]
    expected = [(R, 21.0, 0.0, None, 0.0)] + one_pass(19.1, 50.0) + one_pass(18.2, 100.0) + one_pass(18.0, 100.0)
    assert moves_of(m.expand(state(25.0, feed=50.0))) == expected


def test_type_ii_l1_runs_as_two_rough_passes_and_no_rapid_when_starting_at_g():
    m = region("G107 C20. J-4. R2. K0. L1")
    moves = m.expand(state(21.0, feed=50.0))
    assert moves[0].kind == F  # already at G: no F -> G rapid
    infeeds = [mv.x for mv in moves if mv.kind == F and mv.z == 0.0 and mv.c == 0.0]
    assert infeeds == [pytest.approx(20.0 - 1.0), pytest.approx(18.0), pytest.approx(18.0)]
    assert m.code == "G107" and m.emit().endswith("G107 C0")


def test_type_ii_internal_cut_infeeds_toward_plus_x():
    m = region("G7.1 C20. J2. R1. K0. L2")  # bore of diameter 40 cut to 42; G at diameter 39
    radii = m.pass_radii(state(19.5))
    assert radii == [pytest.approx(20.5), pytest.approx(21.0), pytest.approx(21.0)]
    assert m.expand(state(19.0, feed=50.0))[0][:3] == (R, 19.5, 0.0)


def test_arc_in_the_developed_plane_is_segmented_within_the_chord_tolerance():
    # G2 R5 from (z0, s0) to (z5, s-5): clockwise seen with Z right, s up: the centre is (0, -5).
    to_s = 20.0 * math.pi / 180.0
    m = region("G7.1 C20.", "G2 Z5. C%s R5. F100." % format(-5.0 / to_s, ".4f"))
    moves = m.expand(state(18.0))
    points = [(0.0, 0.0)] + [(mv.z, mv.c * to_s) for mv in moves]
    assert len(moves) > 10
    for (z0, s0), (z1, s1) in zip(points, points[1:]):
        assert math.hypot(z1, s1 + 5.0) == pytest.approx(5.0, abs=1e-3)  # on the circle (C rounded to 0.0001)
        mid = math.hypot((z0 + z1) / 2.0, (s0 + s1) / 2.0 + 5.0)
        assert 5.0 - mid <= ARC_CHORD_TOLERANCE + 1e-6  # the sagitta
    assert all(b[0] >= a[0] for a, b in zip(points, points[1:]))  # clockwise: z grows from the top
    assert (moves[-1].z, moves[-1].c) == (5.0, round(-5.0 / to_s, 4))
    for move, (z0, s0) in zip(moves, points):  # each segment runs at 100 along the developed path
        length = math.hypot(move.z - z0, move.c * to_s - s0)
        assert abs(move.z - z0) / move.f == pytest.approx(length / 100.0)


def test_arc_points_g3_goes_the_other_way():
    points = arc_points((0.0, 0.0), (5.0, -5.0), 5.0, clockwise=False)  # centre (5, 0)
    assert all(math.hypot(z - 5.0, s) == pytest.approx(5.0) for z, s in points)
    assert points[0][0] < 0.5 and points[0][1] < -0.1


@pytest.mark.parametrize("text, fragments", [
    ("G7.1 C-20.\nG1 Z-1.\nG7.1 C0", ["C=-20", "greater than 0"]),
    ("G7.1 C20. J-4. R1. K0.\nG1 Z-1.\nG7.1 C0", ["L: must be programmed: Type II needs J, R, K and L"]),
    ("G7.1 C20. J0. R1. K0. L2\nG1 Z-1.\nG7.1 C0", ["J=0", "must not be 0"]),
    ("G7.1 C20. J-41. R1. K0. L2\nG1 Z-1.\nG7.1 C0", ["J=-41", "leave the cylinder"]),
    ("G7.1 C20. J-4. R-1. K0. L2\nG1 Z-1.\nG7.1 C0", ["R=-1", "without a sign"]),
    ("G7.1 C20. J-4. R1. K-0.1 L2\nG1 Z-1.\nG7.1 C0", ["K=-0.1", "without a sign"]),
    ("G7.1 C20. J-4. R1. K4. L2\nG1 Z-1.\nG7.1 C0", ["K=4", "less than the total cut"]),
    ("G7.1 C20. J-4. R1. K0. L0\nG1 Z-1.\nG7.1 C0", ["L=0", "from 1 to 9999"]),
    ("G7.1 C20. J-4. R1. K0. L10000\nG1 Z-1.\nG7.1 C0", ["L=10000", "from 1 to 9999"]),
    ("G7.1 C20. J-4. R1. K0. L2.\nG1 Z-1.\nG7.1 C0", ["L=2", "whole number"]),
    ("G7.1 C20\nG1 Z-1.\nG7.1 C0", ["C=20", "decimal point"]),
    ("G7.1 C20. X40.\nG1 Z-1.\nG7.1 C0", ["X=40", "only C, J, R, K, L"]),
    ("G7.1 C20.\nG7.1 C0", ["path", "at least one"]),
    ("G7.1 C20.\nG0 Z-1.\nG7.1 C0", ["G=G0", "rapid moves are not allowed"]),
    ("G7.1 C20.\nG1 X30. Z-1.\nG7.1 C0", ["X=30", "no X in the path"]),
    ("G7.1 C20.\nG2 Z-1. C5. I1.\nG7.1 C0", ["I=1", "radius R, not I/K"]),
    ("G7.1 C20.\nG1 W-1.\nG7.1 C0", ["W=-1", "absolute Z"]),
    ("G7.1 C20.\nG1 Z-1. M8\nG7.1 C0", ["M=8", "outside the G7.1 region"]),
    ("G7.1 C20.\nG4 Z-1.\nG7.1 C0", ["G=G4", "only G1, G2 and G3"]),
    ("G7.1 C20.\nZ-1.\nG7.1 C0", ["needs G1, G2 or G3"]),
    ("G7.1 C20.\nG1 F100.\nG7.1 C0", ["G1: a path block needs Z or C"]),
    ("G7.1 C20.\nG2 Z-1. C5.\nG7.1 C0", ["R: G2 needs its radius"]),
    ("G7.1 C20.\nG1 Z-1. R5.\nG7.1 C0", ["R=5", "G1 block has no arc radius"]),
    ("G7.1 C20.\nG3 Z-1. C5. R-5.\nG7.1 C0", ["R=-5", "over 180 degrees"]),
    ("G7.1 C20.\nG7.1 C10.\nG7.1 C0", ["second G7.1 start"]),
    ("G7.1 C20.\nG1 Z-1.", ["ends with its cancel block G7.1 C0"]),
    ("G7.1 C20.\nG1 Z-1.\nG7.1 C0 J1.", ["J: the cancel block G7.1 C0 holds nothing else"]),
])
def test_each_validation_rule_has_its_message(text, fragments):
    raises(lambda: GskG7_1.parse(text), "G7.1 ", *fragments)


@pytest.mark.parametrize("path, start, fragments", [
    ("G2 Z-20. C0. R5. F100.", state(18.0), ["R=5", "out of reach"]),
    ("G2 Z0. C0. R5. F100.", state(18.0), ["R=5", "full circle"]),
    (L_SLOT, state(18.0, c=None), ["C: the C position before G7.1 is not known"]),
    (L_SLOT, state(18.0, feed_per_rev=True), ["G99", "feeds per minute"]),
    ("G1 Z-10.", state(18.0), ["F: no feed in force"]),
])
def test_what_only_the_start_state_shows_is_refused(path, start, fragments):
    m = region("G7.1 C20.", path)
    raises(lambda: m.expand(start), *fragments)


def test_type_ii_start_inside_the_cycle_start_x_is_refused():
    m = region("G7.1 C20. J-4. R2. K0. L2")
    raises(lambda: m.expand(state(20.0, feed=50.0)), "X=40", "cycle start X42.")


def test_spellings_and_modal_motion_are_read():
    m = GskG7_1.parse("N10 G07.1 C20.;G1 Z-1. F80.;C10.;G3 Z-2. C12. R3.;G07.1 C0;")
    assert m.code == "G07.1"
    assert [b.motion for b in m.path] == ["G1", "G1", "G3"]
    assert GskG7_1.parse(m.emit()) == m


_number = st.integers(-999999, 999999).map(lambda n: n / 1000.0)
_blocks = st.lists(
    st.one_of(
        st.builds(PathBlock, st.just("G1"), _number, _number, st.none(), st.one_of(st.none(), st.just(120.0))),
        st.builds(PathBlock, st.sampled_from(["G2", "G3"]), _number, st.one_of(st.none(), _number),
                  st.integers(1, 99999).map(lambda n: n / 100.0), st.none()),
    ),
    min_size=1, max_size=5,
)


@given(
    radius=st.integers(1, 999999).map(lambda n: n / 1000.0),
    path=_blocks,
    type_ii=st.booleans(),
    code=st.sampled_from(["G7.1", "G07.1", "G107"]),
    passes=st.integers(1, 9999),
)
def test_parse_emit_roundtrip(radius, path, type_ii, code, passes):
    words = dict(J=-radius, R=1.5, K=radius / 2.0 if radius / 2.0 == round(radius / 2.0, 4) else 0.0,
                 L=passes) if type_ii else {}
    m = GskG7_1(C=radius, path=tuple(path), code=code, **words).validate()
    assert GskG7_1.parse(m.emit()) == m


# ---------------------------------------------------------------- output with C


def test_linuxcnc_c_writes_the_region_and_rs274_runs_it_move_for_move():
    require_rs274()
    m = region("G7.1 C20. J-4. R2. K0.4 L2")
    start = state(25.0, feed=50.0)
    moves = m.expand(start)
    text = write_program(moves, "linuxcnc-c", start, title="L slot")
    assert text.startswith("(L slot)\nG18 G7 G21 G90 G91.1 G40 G94\n")
    # C modal like X and Z; F of the C move in degrees per minute
    assert "G1 X38.2 F50.\nZ-10. F100.\nC90. F286.478898\nG0 X42.\nZ0. C0.\n" in text
    canon = run_rs274(text, rotary=True)
    expected = [(R, 25.0, 0.0, 0.0)] + [(mv.kind, mv.x, mv.z, mv.c) for mv in moves]
    assert [(c[0], c[1], c[2], c[5]) for c in canon] == [
        (kind, pytest.approx(x, abs=1e-4), pytest.approx(z, abs=1e-4), pytest.approx(c, abs=1e-4))
        for kind, x, z, c in expected]
    feeds = [c[3] for c in canon if c[0] == F]
    assert feeds[:3] == [pytest.approx(50.0), pytest.approx(100.0), pytest.approx(C_FEED, abs=1e-4)]


def test_an_oblique_move_runs_the_developed_feed_on_both_c_targets():
    # G1 Z-10. C90. F100.: developed length hypot(10, 31.4159) = 32.9690 mm, 0.329690 min at F100.
    # linuxcnc-c: F along Z = 10 / 0.329690 = 30.3315; fanuc-c: degrees as mm, hypot(10, 90) / 0.329690 = 274.67.
    m = region("G7.1 C20.", "G1 Z-10. C90. F100.")
    start = state(18.0)
    minutes = math.hypot(10.0, 10.0 * math.pi) / 100.0
    moves = m.expand(start)
    assert moves_of(moves) == [(F, 18.0, -10.0, round(10.0 / minutes, 6), 90.0)]
    fanuc = Writer("fanuc-c")
    fanuc.sync(18.0, 0.0, None, None, c=0.0)
    (line,) = fanuc.write(moves)
    assert line == "G01 Z-10. C90. F%s" % format_decimal(math.hypot(10.0, 90.0) / minutes, 6)
    linuxcnc = Writer("linuxcnc-c")
    linuxcnc.sync(18.0, 0.0, None, None, c=0.0)
    assert linuxcnc.write(moves) == ["G1 Z-10. C90. F%s" % format_decimal(10.0 / minutes, 6)]


def test_a_lathe_target_refuses_c_and_names_the_targets_with_c():
    moves = region("G7.1 C20.").expand(state(18.0, feed=100.0))
    with pytest.raises(ProgramError, match=r"no C axis \(targets with C: gsk, linuxcnc-c, fanuc-c\)"):
        Writer("linuxcnc").write(moves)


# ---------------------------------------------------------------- reading GSK programs

GSK_PROGRAM = """%
O0012
G21 G98
G0 X50. Z5. C0.
Z0.
G07.1 C20. J-4. R2. K0.4 L2
G1 Z-10. F100. (along the axis)
C90.
G07.1 C0
G0 X60.
M30
%
"""


def test_a_gsk_program_is_translated_for_linuxcnc_c_and_rs274_runs_it():
    text = translate_program(GSK_PROGRAM, "gsk", target="linuxcnc-c", source_name="slot")
    assert "G0 X50. Z5. C0.\nZ0.\n(G07.1 C20. J-4. R2. K0.4 L2 ... G07.1 C0, 2 path blocks)\nX42.\n" in text
    moves = GskG7_1.parse("G7.1 C20. J-4. R2. K0.4 L2\nG1 Z-10. F100.\nC90.\nG7.1 C0").expand(state(25.0))
    require_rs274()
    canon = run_rs274(text, rotary=True)
    assert [(c[0], round(c[1], 4), round(c[2], 4), round(c[5], 4)) for c in canon[2:-1]] == [
        (mv.kind, round(mv.x, 4), round(mv.z, 4), round(mv.c, 4)) for mv in moves]
    assert canon[-1][:3] == (R, 30.0, 0.0)  # G0 X60. after the region


def test_g107_and_g7_1_spellings_and_gsk_g75_through_the_fanuc_pecking_cycle():
    for code in ("G7.1", "G107"):
        text = translate_program(GSK_PROGRAM.replace("G07.1", code), "gsk", target="fanuc-c")
        assert "(%s C20. J-4. R2. K0.4 L2 ... %s C0, 2 path blocks)" % (code, code) in text
    grooves = "G21 G98\nT0101\nS500 M3\nG0 X52. Z-10.\nG75 R0.3\nG75 X40. Z-16. P2500 Q2500 R0.2 F50.\nM30\n"
    gsk = translate_program(grooves, "gsk", source_name="p")
    assert gsk == translate_program(grooves, "fanuc", source_name="p").replace("fanuc program", "gsk program")
    assert "G75 X40. Z-16. P2500 Q2500 R0.2 F50." in gsk


@pytest.mark.parametrize("program, line, fragment", [
    (GSK_PROGRAM.replace("C90.", "G0 C90."), 8, "G7.1 G=G0: rapid moves are not allowed"),
    (GSK_PROGRAM.replace("C90.", "G1 X30. C90."), 8, "G7.1 X=30: the depth of a G7.1 region"),
    (GSK_PROGRAM.split("G07.1 C0")[0], 6, "the G07.1 C20. J-4. R2. K0.4 L2 region is not closed"),
    ("G21 G98\nG0 X50. Z0. C0.\nG107 C0\nM30\n", 3, "G107 C0 cancels a region that was not started"),
    (GSK_PROGRAM.replace("G0 X50. Z5. C0.", "G0 X50. Z5."), 6, "G7.1 C: the C position before G07.1 is not known"),
    (GSK_PROGRAM.replace("G21 G98", "G21 G99 S500 M3"), 6, "G7.1 G99: cylindrical interpolation feeds per minute"),
    (GSK_PROGRAM.replace("G0 X60.", "G1 C10. F100."), 10, "C10. in a G1 move: C is only fed inside a G7.1 region"),
    (GSK_PROGRAM.replace("C20. J-4.", "C20. J-41."), 6, "J=-41: the finish diameter"),
])
def test_gsk_program_errors_name_their_line(program, line, fragment):
    with pytest.raises(ProgramError) as info:
        translate_program(program, "gsk", target="linuxcnc-c")
    assert info.value.line == line and fragment in str(info.value), (info.value.line, str(info.value))


def test_c_for_a_target_without_c_axis_is_one_error_line_on_the_command_line(tmp_path):
    path = tmp_path / "slot.nc"
    path.write_text(GSK_PROGRAM)
    status, out, err = run_inline(["expand", str(path), "--dialect", "gsk", "--to", "linuxcnc"])
    assert (status, out) == (2, "")
    assert err.endswith("/slot.nc:4: C0.: the output linuxcnc has no C axis "
                        "(targets with C: gsk, linuxcnc-c, fanuc-c)\n")
    assert err.count("\n") == 1
    status, out, err = run_inline(["expand", str(path), "--dialect", "gsk", "--to", "fanuc-c"])
    assert status == 0 and "G01 X38.2 F100.\nZ-10.\nC90. F286.478898\n" in out


@settings(max_examples=25, deadline=None)
@given(
    blocks=st.lists(st.tuples(st.sampled_from(["G1", "G2", "G3"]), st.integers(-300, 300), st.integers(-3600, 3600)),
                    min_size=1, max_size=4),
    type_ii=st.booleans(),
)
def test_rs274_runs_every_region_move_for_move(blocks, type_ii):
    """Random paths of lines and half-circle-or-less arcs (R = the chord: always reachable) on an R20 cylinder."""
    require_rs274()
    to_s = 20.0 * math.pi / 180.0
    z, c, path = 0.0, 0.0, []
    for motion, dz, dc in blocks:
        end_z, end_c = dz / 10.0, dc / 10.0
        if (end_z, end_c) == (z, c):
            continue
        radius = "" if motion == "G1" else " R%s" % format_decimal(
            math.ceil(math.hypot(end_z - z, (end_c - c) * to_s) * 1000.0) / 1000.0, 3)
        path.append("%s Z%s C%s%s" % (motion, format_decimal(end_z, 1), format_decimal(end_c, 1), radius))
        z, c = end_z, end_c
    if not path:
        return
    start = "G7.1 C20." + (" J-3. R1. K0.2 L3" if type_ii else "")
    program = "G21 G98\nG0 X%s Z0. C0.\n%s\n%s F200.\n%s\nG7.1 C0\nM30\n" % (
        "42." if type_ii else "38.", start, path[0], "\n".join(path[1:]))
    text = translate_program(program, "gsk", target="linuxcnc-c")
    region_text = "\n".join([start, path[0] + " F200."] + path[1:] + ["G7.1 C0"])
    moves = GskG7_1.parse(region_text).expand(state(21.0 if type_ii else 19.0, feed=None))
    canon = run_rs274(text, rotary=True)[1:]
    assert [move[0] for move in canon] == [mv.kind for mv in moves]
    for (_, x, zz, _, _, cc), mv in zip(canon, moves):  # rs274 prints 4 decimals of the written 4
        assert (x, zz, cc) == (pytest.approx(mv.x, abs=1.5e-4), pytest.approx(mv.z, abs=1.5e-4),
                               pytest.approx(mv.c, abs=1.5e-4))


# ---------------------------------------------------------------- simulation in the developed plane


def _exact_slot_centre(to_s):
    """The programmed centre line of SLOT_WITH_ARC on the developed surface, the arc sampled
    at 0.0001 degree (exact to far below the chord tolerance)."""
    from shapely.geometry import LineString

    # Z0 C0 -> G1 Z-10. -> G3 R10 to Z-20. s10 (quarter circle, centre (-10, 10)) -> G1 s30.
    arc = [(-10.0 + 10.0 * math.cos(a), 10.0 + 10.0 * math.sin(a))
           for a in (math.radians(-90.0 - k * 0.0001) for k in range(0, 900001, 50))]
    return LineString([(0.0, 0.0), (-10.0, 0.0)] + arc + [(-20.0, 10.0), (-20.0, 30.0)])


SLOT_WITH_ARC = "G1 Z-10. F100.\nG2 Z-20. C%s R10.\nG1 C%s"


def test_each_pass_sweeps_the_programmed_slot_and_the_last_reaches_the_programmed_depth():
    """A 6 mm end mill along each pass, in the developed plane (z, C as mm on the R20 surface):
    the slot it sweeps is the programmed slot (6 mm wide around the programmed centre line)
    within the chord tolerance, neither wider nor narrower; the passes go down to 2C+J."""
    to_s = 20.0 * math.pi / 180.0
    c10, c30 = 10.0 / to_s, 30.0 / to_s
    # G2 from (-10, 0) to (-20, 10) with R10, clockwise seen with z right and s up: centre (-10, 10)
    m = region("G7.1 C20. J-3. R1. K0.3 L3", SLOT_WITH_ARC % (format(c10, ".4f"), format(c30, ".4f")))
    moves = m.expand(state(21.0, feed=50.0))
    programmed = _exact_slot_centre(to_s)
    slot = programmed.buffer(3.0, quad_segs=64)
    passes, current = [], None
    for move in moves:
        if move.kind == F and (move.z, move.c) == (0.0, 0.0):  # an infeed starts a pass
            current = [(0.0, 0.0)]
            passes.append((move.x, current))
        elif move.kind == F:
            current.append((move.z, move.c * to_s))
    assert [round(x, 9) for x, _ in passes] == [19.55, 19.1, 18.65, 18.5]  # 2C+J = 37: radius 18.5
    from shapely.geometry import LineString
    for _, points in passes:
        swept = LineString(points).buffer(3.0, quad_segs=64)
        assert LineString(points).hausdorff_distance(programmed) <= ARC_CHORD_TOLERANCE + 2e-5  # C to 4 decimals
        assert swept.difference(slot.buffer(ARC_CHORD_TOLERANCE + 2e-5)).area < 1e-9  # no wider
        assert slot.difference(swept.buffer(ARC_CHORD_TOLERANCE + 2e-5)).area < 1e-9  # no narrower


def test_the_chord_tolerance_is_in_mm_in_inch_programs_too():
    # the same arc in inch (R0.5 in): segments within 0.001 mm = 0.0000394 in of it
    points = arc_points((0.0, 0.0), (0.5, -0.5), 0.5, clockwise=True, scale=1.0 / 25.4)
    here = (0.0, 0.0)
    for point in points:
        mid = ((here[0] + point[0]) / 2.0, (here[1] + point[1]) / 2.0)
        assert 0.5 - math.hypot(mid[0], mid[1] + 0.5) <= 0.001 / 25.4 + 1e-12
        here = point
    assert len(points) > len(arc_points((0.0, 0.0), (0.5, -0.5), 0.5, clockwise=True))
