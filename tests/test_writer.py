"""The writer of every output (freecad_groove.engine.output.writer) and its
whole programs (output.program): exact text for small cases worked out by
hand, number format, modal word dropping, errors, speed, and LinuxCNC's rs274
reading what the LinuxCNC writer writes."""

import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import FEED, RAPID, MachineState, Move, dwell, feed, rapid
from freecad_groove.engine.output.program import write_moves, write_program
from freecad_groove.engine.output.writer import MAX_COMMENT, Writer, format_number


def comment(text, limit=MAX_COMMENT):
    return Writer("linuxcnc").comment(text, limit)

# A plunge from X80 Z65 (radius 40): rapid to Z60, feed to X60 at F0.2, dwell
# 1.5 s, rapid out, rapid back to Z65.
PLUNGE = [rapid(40, 60), feed(30, 60, 0.2), dwell(30, 60, 1.5), rapid(40, 60), rapid(40, 65)]
AT_START = MachineState(x=40.0, z=65.0, feed=None, metric=True, feed_per_rev=True)


# ---------------------------------------------------------------- numbers


@pytest.mark.parametrize(
    "value, digits, text",
    [
        (80, 4, "80."),
        (80.0, 4, "80."),
        (0.5, 4, "0.5"),
        (-3, 4, "-3."),
        (1.23456, 4, "1.2346"),
        (1.23456, 3, "1.235"),
        (0.0, 4, "0."),
        (-0.0, 4, "0."),
        (-0.00001, 4, "0."),  # rounds to zero: never "-0."
        (-0.00005001, 4, "-0.0001"),
        (123456.78, 4, "123456.78"),
    ],
)
def test_format_number(value, digits, text):
    assert format_number(value, digits) == text


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf, 1e6, -1e6, 1e300])
def test_format_number_refuses_what_a_control_cannot_read(value):
    with pytest.raises(ProgramError):
        format_number(value, 4)


# ---------------------------------------------------------------- moves, exact text


def test_linuxcnc_moves_exact():
    assert write_moves(PLUNGE, "linuxcnc", AT_START) == [
        "G0 Z60.",  # X unchanged from the state: not written
        "G1 X60. F0.2",  # X is a diameter
        "G4 P1.5",  # seconds
        "G0 X80.",
        "Z65.",  # G0 still modal
    ]


def test_fanuc_moves_exact():
    assert write_moves(PLUNGE, "fanuc", AT_START) == [
        "G00 Z60.",
        "G01 X60. F0.2",
        "G04 P1500",  # milliseconds, integer
        "G00 X80.",
        "Z65.",
    ]


def test_motion_code_written_when_state_motion_differs():
    assert write_moves([rapid(40, 60)], "linuxcnc", AT_START, motion=RAPID) == ["Z60."]
    assert write_moves([rapid(40, 60)], "linuxcnc", AT_START, motion=FEED) == ["G0 Z60."]


def test_feed_written_only_when_its_text_changes():
    state = MachineState(x=40.0, z=65.0, feed=0.2)
    moves = [feed(35, 65, 0.2), feed(30, 65, 0.2000000001), feed(25, 65, 0.1), feed(20, 65)]
    assert write_moves(moves, "linuxcnc", state, motion=FEED) == ["X70.", "X60.", "X50. F0.1", "X40."]


def test_move_to_the_same_place_is_dropped_but_its_feed_kept():
    state = MachineState(x=40.0, z=65.0, feed=0.2)
    assert write_moves([feed(40, 65, 0.2), feed(40.00001, 65.00001)], "linuxcnc", state, motion=FEED) == []
    assert write_moves([feed(40, 65, 0.3)], "linuxcnc", state, motion=FEED) == ["F0.3"]


def test_words_compared_as_written_so_rounding_never_drifts():
    # 0.00004 steps are below the 4-decimal resolution: the written X follows the
    # true value, not an accumulated one.
    state = MachineState(x=10.0, z=0.0, feed=0.1)
    moves = [feed(10.0 - 0.00002 * k, 0.0) for k in range(1, 8)]
    lines = write_moves(moves, "linuxcnc", state, motion=FEED)
    written = [float(line[1:]) for line in lines]
    assert written == sorted(written, reverse=True)
    assert abs(written[-1] - 2 * moves[-1].x) <= 0.00005


def test_negative_zero_never_written():
    state = MachineState(x=5.0, z=1.0, feed=0.1)
    assert write_moves([rapid(-0.00001, -0.00001)], "linuxcnc", state) == ["G0 X0. Z0."]


def test_inch_digits():
    state = MachineState(x=1.0, z=0.0, metric=False)
    moves = [rapid(0.123456, -0.123456)]
    assert write_moves(moves, "linuxcnc", state) == ["G0 X0.24691 Z-0.12346"]
    assert write_moves(moves, "fanuc", state) == ["G00 X0.2469 Z-0.1235"]


def test_a_writer_switched_to_inch_writes_the_values_it_met_in_mm_with_the_inch_digits():
    # write() keeps the text of each value met from call to call (a post writes each groove with a call):
    # kept for the units' digits only
    writer = Writer("linuxcnc")
    assert writer.write([rapid(0.123456, -0.123456)]) == ["G0 X0.2469 Z-0.1235"]
    writer.set_units(False)
    assert writer.write([rapid(0.123456, -0.123456)]) == ["X0.24691 Z-0.12346"]
    writer.set_units(True)
    assert writer.write([rapid(0.123456, -0.123456), rapid(1.0, -0.123456)]) == ["X0.2469 Z-0.1235", "X2."]


def test_metric_digits_fanuc_is_three_decimals():
    state = MachineState(x=1.0, z=0.0)
    assert write_moves([rapid(10.12345, -1.00049)], "fanuc", state) == ["G00 X20.247 Z-1."]


def test_feed_keeps_six_decimals():
    state = MachineState(x=1.0, z=0.0, metric=False)
    assert write_moves([feed(0.5, 0.0, 0.000125)], "linuxcnc", state) == ["G1 X1. F0.000125"]


def test_unknown_position_writes_both_axes():
    writer = Writer("linuxcnc")
    assert writer.write([rapid(40, 65)]) == ["G0 X80. Z65."]


def test_block_delete_prefix():
    assert write_moves(PLUNGE[:2], "linuxcnc", AT_START) == ["G0 Z60.", "G1 X60. F0.2"]
    writer = Writer.from_state(AT_START, "linuxcnc")
    assert writer.write(PLUNGE[:2], prefix="/") == ["/G0 Z60.", "/G1 X60. F0.2"]


def test_dwell_formats():
    w = Writer("linuxcnc")
    assert w.dwell(1.5) == "G4 P1.5"
    assert w.dwell(0) == "G4 P0."
    assert w.dwell(0.0004) == "G4 P0."
    f = Writer("fanuc")
    assert f.dwell(1.5) == "G04 P1500"
    assert f.dwell(0.0004) == "G04 P0"
    assert f.dwell(2.0006) == "G04 P2001"


@pytest.mark.parametrize(
    "moves",
    [
        [feed(30, 60)],  # a feed move with no feed in force anywhere
        [rapid(math.nan, 0)],
        [rapid(0, math.inf)],
        [rapid(1e7, 0)],
        [dwell(0, 0, -1)],
        [dwell(0, 0, math.nan)],
        [feed(30, 60, 0)],
        [feed(30, 60, -0.1)],
        [Move("G7", 1, 1)],
    ],
)
def test_writer_refuses(moves):
    with pytest.raises(ProgramError):
        write_moves(moves, "linuxcnc", MachineState(x=40.0, z=65.0))


def test_writer_state_kept_after_an_error():
    writer = Writer.from_state(AT_START, "linuxcnc")
    with pytest.raises(ProgramError):
        writer.write([rapid(40, 60), rapid(math.nan, 0)])
    assert writer.z_text == "60." and writer.motion == RAPID


# Straight moves to rounded places, either axis left out (None: it does not move), rapids and feeds.
_AXIS = st.one_of(st.none(), st.integers(-400, 400).map(lambda k: k / 8.0))
_STRAIGHT = st.tuples(st.sampled_from([RAPID, FEED]), _AXIS, _AXIS, st.sampled_from([None, 0.1, 0.2]))


@settings(max_examples=300, deadline=None)
@given(st.lists(_STRAIGHT, max_size=12), st.sampled_from(["linuxcnc", "fanuc", "sinumerik", "ab9"]),
       st.booleans())
def test_moves_written_in_one_go_are_the_moves_written_one_at_a_time(steps, target, known):
    # the posts write a groove's link and retreat rapids in one write(); a rapid at a time (move()) is the
    # reference: the same lines, the same modal state after
    state = AT_START if known else MachineState(x=None, z=None, feed=0.2)
    together, alone = Writer.from_state(state, target), Writer.from_state(state, target)
    moves = [Move(kind, x, z, f) for kind, x, z, f in steps if x is not None or z is not None]
    try:
        lines = [line for move in moves for line in alone.move(move.kind, move.x, move.z, move.f)]
    except ProgramError as exc:  # a feed with no F in force: refused the same way
        with pytest.raises(ProgramError, match=re.escape(str(exc))):
            together.write(moves)
        return
    assert together.write(moves) == lines
    assert together._modal() == alone._modal()


def test_unknown_target():
    with pytest.raises(ValueError):
        Writer("heidenhain")


# ---------------------------------------------------------------- header, footer, comments


def test_linuxcnc_header():
    assert Writer("linuxcnc", metric=True, feed_per_rev=True).header() == ["G18 G7 G21 G90 G91.1 G40 G95"]
    assert Writer("linuxcnc", metric=False, feed_per_rev=False).header("T") == [
        "(T)",  # the title first, as on every target (Fanuc: on the O line)
        "G18 G7 G20 G90 G91.1 G40 G94",
    ]
    assert Writer("linuxcnc").header() == ["G18 G7 G21 G90 G91.1 G40"]  # feed mode unknown: not written
    assert Writer("linuxcnc").footer() == ["M2"]


def test_fanuc_header():
    assert Writer("fanuc", metric=True, feed_per_rev=True).header("PART", 12) == [
        "%",
        "O0012 (PART)",
        "G21",  # units alone in their block
        "G40 G99",
    ]
    assert Writer("fanuc", metric=False, feed_per_rev=False).header() == ["%", "G20", "G40 G98"]
    assert Writer("fanuc").footer() == ["M30", "%"]


@pytest.mark.parametrize(
    "text, written",
    [
        ("plain", "(plain)"),
        ("a (nested) one", "(a nested one)"),
        ("MSG, hello", "(- MSG, hello)"),
        ("  msg,hello", "(- msg,hello)"),
        ("DEBUG, x", "(- DEBUG, x)"),
        ("PROBEOPEN file.txt", "(- PROBEOPEN file.txt)"),
        ("logclose", "(- logclose)"),
        ("py, print(1)", "(- py, print1)"),
        ("AXIS,stop", "(- AXIS,stop)"),
        ("Groove 1, left", "(Groove 1, left)"),
        ("Ø40 über", "(?40 ?ber)"),
        ("tab\there", "(tab?here)"),
    ],
)
def test_comment(text, written):
    assert comment(text) == written


def test_long_comment_is_cut():
    text = comment("x" * 1000)
    assert len(text) == MAX_COMMENT + 2 and text.endswith("...)")
    assert comment("x" * 1000, 10) == "(xxxxxxx...)"


# ---------------------------------------------------------------- whole programs


def test_write_program_linuxcnc_exact():
    state = MachineState(x=40.0, z=65.0, feed=0.2, metric=True, feed_per_rev=True)
    moves = [rapid(40, 60), feed(30, 60), dwell(30, 60, 1.5), rapid(40, 60)]
    assert write_program(moves, "linuxcnc", state, title="demo", spindle=400) == (
        "(demo)\n"
        "G18 G7 G21 G90 G91.1 G40 G95\n"
        "G97 S400 M3\n"
        "G0 X80. Z65.\n"
        "Z60.\n"
        "G1 X60. F0.2\n"  # the state's feed, written on the first feed move
        "G4 P1.5\n"
        "G0 X80.\n"
        "M2\n"
    )


def test_write_program_spindle():
    state = MachineState(x=40.0, z=65.0, feed=0.2, feed_per_rev=True)
    assert write_program([], "linuxcnc", state, spindle=500).splitlines()[1] == "G97 S500 M3"
    assert write_program([], "linuxcnc", state, spindle=500.5).splitlines()[1] == "G97 S500.5 M3"
    assert write_program([], "fanuc", state, spindle=500).splitlines()[3] == "G97 S500 M03"
    with pytest.raises(ProgramError):
        write_program([], "fanuc", state, spindle=500.5)


def test_write_program_fanuc_exact():
    state = MachineState(x=40.0, z=65.0, feed=0.2, metric=True, feed_per_rev=True)
    moves = [rapid(40, 60), feed(30, 60), dwell(30, 60, 1.5), rapid(40, 60)]
    assert write_program(moves, "fanuc", state, title="demo", program_number=7, spindle=400) == (
        "%\nO0007 (demo)\nG21\nG40 G99\nG97 S400 M03\nG00 X80. Z65.\nZ60.\nG01 X60. F0.2\nG04 P1500\nG00 X80.\n"
        "M30\n%\n"
    )
    with pytest.raises(ProgramError):
        write_program(moves, "fanuc", state)  # feed per revolution, no spindle


# ---------------------------------------------------------------- LinuxCNC reads what we write


def test_rs274_reads_write_program():
    from rs274 import canonical_matches, require_rs274, run_rs274

    require_rs274()
    state = MachineState(x=40.0, z=65.0, feed=0.2, metric=True, feed_per_rev=True)
    moves = [
        rapid(40, 60),
        feed(30.00004, 60, 0.2),
        dwell(30.00004, 60, 1.5),
        rapid(40, 60),
        rapid(40, 57.123456),
        feed(-0.5, 57.123456, 0.05),
        rapid(40, 57.123456),
        rapid(40, 65),
    ]
    canon = run_rs274(write_program(moves, "linuxcnc", state, spindle=500))
    assert not canonical_matches([rapid(40, 65)] + moves, canon, tol=1e-4)


def test_rs274_reads_inch_program():
    from rs274 import canonical_matches, require_rs274, run_rs274

    require_rs274()
    state = MachineState(x=1.0, z=0.5, feed=5.0, metric=False, feed_per_rev=False)
    moves = [feed(0.812345, 0.5), rapid(1.0, 0.5), rapid(1.0, -0.25), feed(0.5, -0.25, 2.5)]
    canon = run_rs274(write_program(moves, "linuxcnc", state))
    assert not canonical_matches([rapid(1.0, 0.5)] + moves, canon, tol=1e-4)  # rs274 prints 4 decimals


@pytest.mark.parametrize("axis", ["y", "c"])
def test_a_lathe_target_refuses_a_move_on_an_axis_it_cannot_write(axis):
    """A move that sets Y or C (mill-style and cylinder-interpolation cycles) is refused by the lathe targets,
    naming the axis, instead of being written without it."""
    for target in ("linuxcnc", "fanuc"):
        with pytest.raises(ProgramError, match="%s cannot be written for %s: its output has no %s axis"
                           % (axis.upper(), target, axis.upper())):
            Writer(target).write([Move("G1", 10.0, 0.0, 0.1, **{axis: 5.0})])
    assert Writer("linuxcnc").write([Move("G1", 10.0, 0.0, 0.1)])  # lathe moves as before
