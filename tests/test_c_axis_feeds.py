"""The F of every move of a GSK G7.1 region on every target with a C axis (linuxcnc-c, fanuc-c, gsk), in mm
and in inch, Type I and Type II (issue 20, item 3: in inch, fanuc-c wrote "feed 2.3e+20 cannot be written").

The feeds are derived by hand. The slot, on a cylinder of radius Rc (C word): ``G1 Z-a F f`` along the axis,
then ``G1 Z-2a C90.`` (oblique), then ``G1 C180.`` (a quarter turn alone). The developed length of a quarter
turn is s = Rc * pi / 2. mm: Rc 20, a 10, f 100; inch: Rc .8, a .4, f 4.

- the move along Z: F f on every target (linear a, no turn);
- the oblique move: t = hypot(a, s) / f minutes. linuxcnc-c (along Z when Z moves): a / t;
  fanuc-c and gsk (degrees counted as lengths in the path): hypot(a, 90) / t;
- the quarter turn alone: t = s / f; every target 90 / t degrees per minute.
mm: t = 0.3296908 (30.33145 and 274.6629), then 286.478898; inch: t = 0.3296908 (1.213258 and 272.9857), then
286.478898.
"""

import math

import pytest
from rs274 import require_rs274, run_rs274

from freecad_groove.engine.cycles.gsk_g7_1 import GskG7_1
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import MachineState
from freecad_groove.engine.numbers import format_decimal
from freecad_groove.engine.output.targets import TARGETS
from freecad_groove.engine.translator import translate_program

C_TARGETS = ("linuxcnc-c", "fanuc-c", "gsk")
UNITS = {  # G code, cylinder radius (the C word), a, f, the start X (diameter) of Type I and of Type II
    "mm": ("G21", 20.0, 10.0, 100.0, 40.0, 42.0),
    "inch": ("G20", 0.8, 0.4, 4.0, 1.6, 1.7),
}
TYPE_II = {"mm": " J-4. R2. K.4 L2", "inch": " J-.2 R.1 K.02 L2"}


def program(units, type_ii):
    code, radius, a, f, x1, x2 = UNITS[units]
    return "\n".join([
        "%s G98" % code,
        "G0 X%s Z0. C0." % format_decimal(x2 if type_ii else x1, 4),
        "G7.1 C%s%s" % (format_decimal(radius, 4), TYPE_II[units] if type_ii else ""),
        "G1 Z-%s F%s" % (format_decimal(a, 4), format_decimal(f, 4)),
        "G1 Z-%s C90." % format_decimal(2 * a, 4),
        "G1 C180.",
        "G7.1 C0",
        "M30",
    ]) + "\n"


def expected_feeds(units, target):
    """The F of the three path moves, by the rules in the module notes."""
    _code, radius, a, f, _x1, _x2 = UNITS[units]
    quarter = radius * math.pi / 2
    oblique = math.hypot(a, quarter) / f
    along = a / oblique if TARGETS[target].c_feed == "linear" else math.hypot(a, 90.0) / oblique
    return [f, along, 90.0 / (quarter / f)]


def test_the_c_targets_are_the_three_the_tests_cover():
    assert sorted(name for name, target in TARGETS.items() if target.c_feed) == sorted(C_TARGETS)


def test_the_hand_derived_feeds_are_the_numbers_in_the_notes():
    assert [round(value, 4) for value in expected_feeds("mm", "linuxcnc-c")] == [100.0, 30.3314, 286.4789]
    assert round(expected_feeds("mm", "fanuc-c")[1], 3) == 274.663
    assert [round(value, 4) for value in expected_feeds("inch", "linuxcnc-c")] == [4.0, 1.2133, 286.4789]
    assert round(expected_feeds("inch", "gsk")[1], 3) == 272.986


def path_feeds(text, passes):
    """The F in force on each feed move along the path, pass by pass: the feed moves of Z or C without X (an
    infeed writes X), motion and F modal as the control reads them."""
    motion, feed, feeds = None, None, []
    for line in text.splitlines():
        words = [] if line.startswith(("(", "%")) else line.split()
        for word in words:
            if word in ("G0", "G00", "G1", "G01"):
                motion = word.lstrip("G0") or "0"
            elif word[0] == "F":
                feed = float(word[1:])
        axes = {word[0] for word in words if word[0] in "XZC"}
        if motion == "1" and axes and "X" not in axes:
            feeds.append(feed)
    assert len(feeds) == 3 * passes, text
    return [feeds[index:index + 3] for index in range(0, len(feeds), 3)]


@pytest.mark.parametrize("target", C_TARGETS)
@pytest.mark.parametrize("units", ["mm", "inch"])
@pytest.mark.parametrize("type_ii", [False, True], ids=["type-i", "type-ii"])
def test_every_c_target_writes_the_hand_derived_feed_of_each_path_move(target, units, type_ii):
    text = translate_program(program(units, type_ii), "gsk", target=target)
    expected = [float(format_decimal(value, 6)) for value in expected_feeds(units, target)]
    passes = 3 if type_ii else 1  # L2: two rough passes and the finish
    for feeds in path_feeds(text, passes):
        assert feeds == pytest.approx(expected, abs=1.5e-6), text


@pytest.mark.parametrize("units", ["mm", "inch"])
@pytest.mark.parametrize("type_ii", [False, True], ids=["type-i", "type-ii"])
def test_rs274_runs_the_linuxcnc_c_program_at_the_hand_derived_feeds(units, type_ii):
    require_rs274()
    text = translate_program(program(units, type_ii), "gsk", target="linuxcnc-c")
    canon = run_rs274(text, rotary=True)
    expected = expected_feeds(units, "linuxcnc-c")
    turns = [move for move in canon if move[0] == "G1" and move[5] is not None]
    along = [move for move in turns if abs(move[2] + UNITS[units][2]) < 1e-6 and abs(move[5]) < 1e-6]
    oblique = [move for move in turns if abs(move[5] - 90.0) < 1e-6]
    quarter = [move for move in turns if abs(move[5] - 180.0) < 1e-6]
    passes = 3 if type_ii else 1
    assert (len(along), len(oblique), len(quarter)) == (passes, passes, passes)
    for group, feed in zip((along, oblique, quarter), expected):
        assert [move[3] for move in group] == [pytest.approx(feed, abs=1e-4)] * passes  # rs274 prints 4 decimals


def test_the_issue_program_in_inch_is_written_for_fanuc_c_as_for_linuxcnc_c():
    # the issue's reproducer: a quarter turn at F4 on a .8" cylinder, 4 * 180 / (pi * .8) = 286.478898 deg/min
    text = "G20 G98\nG0 X2. Z.2 C0.\nG7.1 C.8 J-.2 R.1 K.02 L2\nG1 C90. F4.\nG7.1 C0\nM30\n"
    for target in C_TARGETS:
        written = translate_program(text, "gsk", target=target)
        turns = [line for line in written.splitlines() if line.startswith("C90.")]
        assert turns == ["C90. F286.478898"] * 3, written


@pytest.mark.parametrize("type_ii", [False, True], ids=["type-i", "type-ii"])
def test_a_region_whose_path_does_not_move_is_refused_naming_it(type_ii):
    # found by tests/test_cli_fuzz_seed_inputs.py: Type II ended in "internal error (IndexError)"
    text = "G20 G98\nG0 X%s Z0. C0.\nG7.1 C.8%s\nG1 C0. F2.\nG7.1 C0\nM30\n" % (
        "1.7" if type_ii else "1.6", TYPE_II["inch"] if type_ii else "")
    for target in C_TARGETS:
        with pytest.raises(ProgramError, match=r"^G7.1 path: no block of the region moves Z or C from where the "
                                               r"tool is \(Z0. C0.\): nothing to cut$") as raised:
            translate_program(text, "gsk", target=target)
        assert raised.value.line == 3


def test_a_type_ii_path_back_to_its_start_makes_no_empty_return_move():
    # found by test_gsk_g7_1's rs274 comparison: E = G, the return E -> G was a move of no length the writer drops
    text = "G21 G98\nG0 X42. Z0. C0.\nG7.1 C20. J-3. R1. K0.2 L3\nG1 C0.1 F200.\nG1 C0.\nG7.1 C0\nM30\n"
    region = GskG7_1.parse("G7.1 C20. J-3. R1. K0.2 L3\nG1 C0.1 F200.\nG1 C0.\nG7.1 C0")
    moves = region.expand(MachineState(x=21.0, z=0.0, c=0.0, feed=None, feed_per_rev=False))
    # per pass (3 rough, 1 finish): infeed, C0.1, C0, X out; the first pass after the rapid to G (X41)
    assert [move.kind for move in moves] == ["G0"] + ["G1", "G1", "G1", "G0"] * 4
    assert len(run_rs274(translate_program(text, "gsk", target="linuxcnc-c"), rotary=True)) == 1 + len(moves)
