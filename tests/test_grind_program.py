"""The grinder program of plunge grinds (engine/grind_program.py): the 9/Series
native program read back by the engine's ab9grind reader, the LinuxCNC
expanded program through rs274, both giving the engine's expansion."""

import pytest
from rs274 import require_rs274, run_rs274

from freecad_groove.engine.cycles.ab_g83 import G83, G83_1
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.grind_program import GrindItem, PlainMoves, WheelChange, grind_program
from freecad_groove.engine.moves import DRESS, FEED, RAPID, MachineState, Move
from freecad_groove.engine.translator import translate_program

# the box of tests/freecad/test_plunge_grind.py: a 100 x 40 face at Z20 (grinder Y), a 10 mm wheel
CALL = G83_1(X=105.0, I=-5.0, Y=20.0, J=0.02, Z=35.0, K=5.0, L=1, F=60.0, E=6000.0, P=12, D=2)
START = MachineState(x=-5.0, z=5.0, y=20.15, feed=60.0, diameter_mode=False)
SAFE = 26.0
DRESS_SUB = "o<dress12> sub\nG4 P0.5\no<dress12> endsub\nM2\n"


def item(call=CALL):
    return GrindItem("PlungeGrind: Block.Face6", call, START, SAFE, call.expand(START))


def canonical(text, tools=()):
    """rs274's moves (kind, x, y, z) rounded, a dress being rs274's G4 of the dress subprogram."""
    return [(c[0], round(c[1], 4), round(c[2], 4), round(c[3], 4)) for c in
            run_rs274(text, files={"dress12.ngc": DRESS_SUB}, xyz=True, tool_table=list(tools) or None)]


def test_the_native_program_writes_the_approach_then_the_g83_block():
    lines = grind_program([item()], "ab9grind", True, "Job").splitlines()
    assert lines == ["%", "O0001", "(Job)", "G90 G94 G21", "(PlungeGrind: Block.Face6)", "G00 Y26.", "X-5. Z5.",
                     "Y20.15", "G83.1 X105. I-5. Y20. J0.02 Z35. K5. L1 F60. E6000. P12 D2", "G00 Y26.", "M30"]


def test_rs274_moves_the_expanded_linuxcnc_program_as_the_engine_expands():
    require_rs274()
    canon = canonical(grind_program([item()], "linuxcnc", False, "Job"))
    expected = [("G0", -5.0, 20.15, 5.0)]  # after G0 Y26 (X, Z unknown: rs274's 0) and G0 X-5 Z5
    for move in CALL.expand(START):
        step = ("G4" if move.kind == DRESS else "G1", round(move.x, 4), round(move.y, 4), round(move.z, 4))
        if move.kind == DRESS or step[1:] != expected[-1][1:]:
            expected.append(step)
    expected.append(("G0", expected[-1][1], SAFE, expected[-1][3]))
    assert canon[2:] == expected
    assert canon[:2] == [("G0", 0.0, SAFE, 0.0), ("G0", -5.0, SAFE, 5.0)]


def test_the_native_program_read_back_by_the_ab9grind_reader_moves_as_the_expanded_one():
    require_rs274()
    native = grind_program([item()], "ab9grind", True, "Job")
    expanded = grind_program([item()], "linuxcnc", False, "Job")
    assert canonical(translate_program(native, "ab9grind", target="linuxcnc")) == canonical(expanded)


def test_an_expanded_dress_is_refused_for_the_9_series():
    with pytest.raises(ProgramError, match=r"a dress \(P12\) cannot be written expanded for the 9/Series"):
        grind_program([item()], "ab9grind", False, "Job")
    call = G83(X=105.0, I=-5.0, Y=20.0, J=0.02, Z=35.0, K=5.0, L=1, F=60.0, E=6000.0)
    lines = grind_program([item(call)], "ab9grind", False, "Job").splitlines()
    assert lines[8] == "(G83 X105. I-5. Y20. J0.02 Z35. K5. L1 F60. E6000.)" and lines[9] == "G01 Y20.13 F60."


def test_plain_moves_are_written_as_they_are_and_linuxcnc_has_no_native_cycle():
    moves = PlainMoves("Profile", [Move(RAPID, 1.0, 2.0, y=30.0), Move(FEED, 4.0, 2.0, 50.0, y=30.0)])
    assert grind_program([moves], "linuxcnc", False, "Job").splitlines() == [
        "(Job)", "G17 G21 G90 G91.1 G40 G94", "(Profile)", "G0 X1. Y30. Z2.", "G1 X4. F50.", "M2"]
    with pytest.raises(ProgramError, match="linuxcnc has no G83 cycle"):
        grind_program([item()], "linuxcnc", True, "Job")


def test_coolant_goes_on_after_the_comment_and_off_after_the_op():
    lines = grind_program([item()._replace(coolant=8)], "ab9grind", True, "Job").splitlines()
    assert lines[4:7] == ["(PlungeGrind: Block.Face6)", "M08", "G00 Y26."] and lines[-3:] == ["G00 Y26.", "M09", "M30"]
    moves = PlainMoves("Profile", [Move(RAPID, 1.0, 2.0, y=30.0)], 7)
    assert grind_program([moves], "linuxcnc", False, "Job").splitlines()[-5:] == [
        "(Profile)", "M7", "G0 X1. Y30. Z2.", "M9", "M2"]


# ---------------------------------------------------------------- the wheel: tool change and spindle

def grind_call():
    return G83(X=105.0, I=-5.0, Y=20.0, J=0.02, Z=35.0, K=5.0, L=1, F=60.0, E=6000.0)


def test_the_wheel_change_writes_the_tool_change_then_the_spindle_and_stops_it_at_the_end():
    wheel = WheelChange("TC: Wheel", 3, 1500.0)
    items = [wheel, item(grind_call()), wheel, item(grind_call()), wheel._replace(clockwise=False),
             WheelChange("TC: Other", 4, 2000.0)]
    lines = grind_program(items, "ab9grind", True, "Job").splitlines()
    assert lines[4:7] == ["(tool 3: TC: Wheel)", "T03 M06", "S1500 M03"]
    assert lines.count("T03 M06") == 1 and lines.count("S1500 M03") == 1  # the same wheel again: nothing
    assert lines[-6:] == ["S1500 M04", "(tool 4: TC: Other)", "T04 M06", "S2000 M03", "M05", "M30"]
    linuxcnc = grind_program([wheel, item(grind_call())], "linuxcnc", False, "Job").splitlines()
    assert linuxcnc[2:5] == ["(tool 3: TC: Wheel)", "T3 M6 G43", "S1500 M3"] and linuxcnc[-2:] == ["M5", "M2"]


def test_a_still_wheel_stops_the_spindle_and_the_next_tool_starts_it_again():
    lines = grind_program([WheelChange("TC: Wheel", 3, 1500.0), item(grind_call()), WheelChange("TC: Wheel", 3, 0.0),
                           WheelChange("TC: Other", 4, 900.0), item(grind_call())], "ab9grind", True,
                          "Job").splitlines()
    second = lines.index("T04 M06")
    assert lines[second - 2:second + 5] == ["M05", "(tool 4: TC: Other)", "T04 M06", "S900 M03",
                                            "(PlungeGrind: Block.Face6)", "G00 Y26.", "X-5. Z5."]
    assert lines[-3:] == ["G00 Y26.", "M05", "M30"]


def test_rs274_runs_the_linuxcnc_program_with_its_tool_change_and_spindle():
    require_rs274()
    text = grind_program([WheelChange("TC: Wheel", 3, 1500.0), item(grind_call())], "linuxcnc", False, "Job")
    canon = run_rs274(text, tool_table=[3], xyz=True)
    moves = [(c[0], round(c[1], 4), round(c[2], 4), round(c[3], 4)) for c in canon]
    assert moves[1:3] == [("G0", -5.0, SAFE, 5.0), ("G0", -5.0, 20.15, 5.0)]


@pytest.mark.parametrize("wheel, target, message", [
    (WheelChange("TC: Wheel", 3, 1500.5), "ab9grind", r"^TC: Wheel: S1500.5: Allen-Bradley S words are whole "
                                                     r"numbers \(rpm, or the surface speed\)$"),
    (WheelChange("TC: Wheel", 100, 1500.0), "ab9grind", r"^TC: Wheel: tool number 100 cannot be written \(1..99\)$"),
    (WheelChange("TC: Wheel", 0, 1500.0), "linuxcnc", r"^TC: Wheel: tool number 0 cannot be written \(1..99999\)$"),
    (WheelChange("TC: Wheel", 3, 1e6), "linuxcnc", r"^TC: Wheel: spindle speed 1000000.0 cannot be written$"),
])
def test_wheels_the_control_cannot_take_are_refused_naming_the_tool_controller(wheel, target, message):
    with pytest.raises(ProgramError, match=message):
        grind_program([wheel], target, False, "Job")


def test_a_tool_call_in_a_grinder_program_keeps_the_wheel_turning_on_linuxcnc():
    # LinuxCNC's M6 stops the spindle; the 9/Series T does not: the wheel must turn again before it grinds
    # (in the same block: LinuxCNC runs M3 after M6).
    program = "G20 G90 G94\nS3000 M03\nG0 X0. Y1. Z1.\nT0303\nG1 X1. F10.\nM30\n"
    lines = translate_program(program, "ab9grind", target="linuxcnc").splitlines()
    assert lines[lines.index("G0 X0. Y1. Z1.") + 1:][:2] == ["T3 M6 G43 M3", "G1 X1. F10."]


def test_the_9_series_program_with_its_wheel_changes_is_read_back_by_the_ab9grind_reader():
    # what the ab9_grind post writes (T03 M06, S1500 M03) is a program its own reader takes: tool 3 with its own
    # offset as T0303 reads, the wheel started by the program's M03 (no second M3: the block after starts it)
    items = [WheelChange("TC: Wheel", 3, 1500.0), item(grind_call()), WheelChange("TC: Other", 4, 2000.0),
             item(grind_call())]
    native = grind_program(items, "ab9grind", True, "Job")
    assert "T03 M06" in native.splitlines() and "T04 M06" in native.splitlines()
    lines = translate_program(native, "ab9grind", target="linuxcnc").splitlines()
    changes = [line for line in lines if " M6" in line]
    assert changes == ["T3 M6 G43", "T4 M6 G43 M3"]  # the second change: the wheel was turning, M6 stops it
    expanded = grind_program(items, "linuxcnc", False, "Job")
    assert canonical(translate_program(native, "ab9grind", target="linuxcnc"), [3, 4]) == canonical(expanded, [3, 4])


@pytest.mark.parametrize("block, message", [
    ("M06", r"M6 without T: program the tool change as T<n> M6 in one block"),
    ("T0 M06", r"T0 M6: the tool number must be a whole number of 1 or more"),
    ("T1.5 M06", r"T1.5 M6: the tool number must be a whole number of 1 or more"),
])
def test_a_9_series_tool_change_without_a_tool_is_refused_naming_the_words(block, message):
    with pytest.raises(ProgramError, match=message):
        translate_program("G21 G90 G94\n%s\nM30\n" % block, "ab9grind", target="linuxcnc")
