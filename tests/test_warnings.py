"""Warnings: what a cycle cannot do as programmed, reported without stopping the
run (engine/warnings.py), from CYCLE93 (allowances that leave the blade no room)
and the Fanuc/Haas relief (into the wall between grooves), through the
translator and the command line."""


import pytest
from test_cli import run_inline

from freecad_groove.engine import GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles.ab_g77 import G77
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.fanuc_g75 import FanucG74, FanucG75, HaasG75
from freecad_groove.engine.cycles.milltronics import G31
from freecad_groove.engine.tool_table import read_tool_table
from freecad_groove.engine.translator import Translator, translate_program
from freecad_groove.engine.warnings import CycleWarning, cycle_warnings

BLADE = Settings(tool=GroovingTool(3.0, 0.2))  # --tool-width 3
NO_ROOM = "CYCLE93(35, 60, 4, 5, 0, 0, 0, 0, 0, 0, 0, 0.2, 0.6, 2, 0, 5, 0)"  # base 4 - 2 x 0.6 = 2.8 < 3
C93_PROGRAM = """N10 T5 D1 S500 M3
N20 G95 G90 F0.2
N30 G0 X80 Z65
N40 %s
N50 M2
""" % NO_ROOM
G75_PROGRAM = """O1001
N10 G21
N20 G99
N30 T0303
N40 G97 S600 M03
N50 G00 X50. Z0.
N60 G75 R0.5
N70 G75 X40. Z-20. P2000 Q5000 R1. F0.1
N80 M30
"""
START = MachineState(x=40.0, z=65.0, feed=0.2, feed_per_rev=True)
G75_START = MachineState(x=25.0, z=0.0, feed=0.1, feed_per_rev=True)


NO_ROOM_TEXT = ("CYCLE93: the allowances FAL1=0.2 FAL2=0.6 leave no room for the 3 mm blade: FAL2 leaves a "
                "roughing base 2.8 mm wide; roughing runs on the final profile, leaving nothing for the finishing pass")


def no_room(warnings):
    """The allowance warnings alone (these grooves' sharp base corners also
    leave the blade's r0.2 unreached: cycle93_reach, tested in test_cycle93_reach)."""
    return [warning for warning in warnings if warning.parameter in ("FAL1", "FAL2")]


def assert_one(warnings, cycle, parameter, text):
    (warning,) = warnings
    assert (warning.cycle, warning.parameter, warning.text) == (cycle, parameter, text)


def test_warning_text():
    warning = CycleWarning("CYCLE93", "FAL2", "roughing runs on the final profile")
    assert warning.text == "CYCLE93: roughing runs on the final profile"


def test_a_cycle_without_warnings_has_none():
    assert cycle_warnings(G31(), START, BLADE) == []  # G31 declares no warnings: Cycle's default


# ---------------------------------------------------------------- CYCLE93 (item 8)


def test_cycle93_allowances_that_leave_no_room_warn_naming_fal2():
    call = Cycle93.parse(NO_ROOM)
    geometry = call.geometry(BLADE)
    assert geometry.roughs_to_final
    assert geometry.no_room.parameter == "FAL2"
    assert geometry.no_room.room == pytest.approx(2.8) and geometry.no_room.need == 3.0
    assert_one(no_room(call.warnings(START, BLADE)), "CYCLE93", "FAL2", NO_ROOM_TEXT)


def test_cycle93_raised_base_that_leaves_no_room_for_a_base_corner_names_fal1():
    call = Cycle93.parse("CYCLE93(35, 60, 8, 5, 0, 0, 0, 0, 0, 2, 2, 4.5, 0.4, 2, 0, 5, 0)")
    (warning,) = no_room(call.warnings(START, BLADE))
    assert warning.parameter == "FAL1"
    assert "FAL1=4.5 FAL2=0.4" in warning.text and "too short for the base corner RCI1" in warning.text


def test_cycle93_inch_program_says_in():
    blade = Settings(tool=GroovingTool(0.12, 0.008))
    call = Cycle93.parse("CYCLE93(1.4, 2.4, 0.16, 0.2, 0, 0, 0, 0, 0, 0, 0, 0.008, 0.024, 0.08, 0, 5, 0)")
    (warning,) = no_room(call.warnings(MachineState(x=1.6, z=2.6, feed=0.008, feed_per_rev=True, metric=False),
                                       blade))
    assert "the 0.12 in blade" in warning.text and "0.112 in wide" in warning.text


@pytest.mark.parametrize("text", [
    "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)",  # the seed example
    "CYCLE93(35, 60, 4, 5, 0, 0, 0, 0, 0, 0, 0, 0.2, 0.4, 2, 0, 5, 0)",  # base 3.2: room for the blade
    "CYCLE93(35, 60, 3, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 5, 0)",  # no allowances: nothing to warn of
])
def test_cycle93_with_room_or_without_allowances_has_no_warning(text):
    assert no_room(Cycle93.parse(text).warnings(START, BLADE)) == []


def test_cycle93_warning_leaves_the_moves_and_output_as_they_were():
    warnings = []
    text = translate_program(C93_PROGRAM, "sinumerik", BLADE, warnings=warnings)
    assert [(line, w.parameter) for line, w in warnings] == [(4, "FAL2"), (4, "RCI1"), (4, "RCI2")]
    assert translate_program(C93_PROGRAM, "sinumerik", BLADE) == text


# ---------------------------------------------------------------- Fanuc/Haas relief (item 9)


def test_fanuc_relief_into_the_wall_between_grooves_warns():
    model = FanucG75.parse("G75 X40. Z-20. P2000 Q5000 R2.5 F0.1")  # 5 - 3 = 2 < 2.5
    assert_one(model.warnings(G75_START, BLADE), "G75", "R",
               "G75: the relief R=2.5 at the groove bottom rapids the blade's side into the wall between grooves: "
               "grooves 5 mm apart (Q=5000) leave a 2 mm wall beside the 3 mm blade")


def test_fanuc_relief_within_the_cut_bottom_does_not_warn():
    # plunges 2 mm apart with a 3 mm blade: the bottom behind the blade is cut, R1 stays in it
    assert FanucG75.parse("G75 X40. Z-20. P2000 Q2000 R1. F0.1").warnings(G75_START, BLADE) == []
    assert FanucG75.parse("G75 X40. Z-20. P2000 Q5000 R0 F0.1").warnings(G75_START, BLADE) == []
    assert FanucG75.parse("G75 X40. P2000 R1. F0.1").warnings(G75_START, BLADE) == []  # one groove: no relief


def test_fanuc_relief_past_the_previous_plunge_warns():
    (warning,) = FanucG75.parse("G75 X40. Z-20. P2000 Q2000 R2.5 F0.1").warnings(G75_START, BLADE)
    assert "R=2.5" in warning.text and "Q=2000" in warning.text and "3 mm blade" in warning.text


def test_relief_without_a_blade_cannot_be_checked():
    assert FanucG75.parse("G75 X40. Z-20. P2000 Q5000 R2.5 F0.1").warnings(G75_START, Settings()) == []


def test_haas_d_and_the_face_twin_warn_too_and_allen_bradley_d_does_not():
    (haas,) = HaasG75.parse("G75 X40. Z-20. I2. K5. D1. F0.1").warnings(G75_START, BLADE)
    assert haas.parameter == "D" and "D=1" in haas.text and "K=5" in haas.text
    face_start = MachineState(x=10.0, z=0.0, feed=0.1, feed_per_rev=True)
    (face,) = FanucG74.parse("G74 X60. Z-5. P5000 Q2000 R1. F0.1").warnings(face_start, BLADE)
    assert face.cycle == "G74" and "P=5000" in face.text
    assert G77.parse("G77 X40. Z-20. I2. K5. D1. F0.1").warnings(G75_START, BLADE) == []


def test_fanuc_warning_through_the_translator_with_the_tool_tables_blade():
    warnings = []
    text = translate_program(G75_PROGRAM, "fanuc", BLADE, warnings=warnings)
    assert [(line, w.parameter) for line, w in warnings] == [(8, "R")]
    assert translate_program(G75_PROGRAM, "fanuc", BLADE) == text  # the warning changes nothing written
    table = read_tool_table("3 3.0 0.2 minus\n")  # no --tool-width: the table's T3 gives the width
    translator = Translator("fanuc", Settings(), tools=table)
    for number, line in enumerate(G75_PROGRAM.splitlines(), 1):
        translator.line(line, number)
    assert [line for line, _ in translator.warnings] == [8]
    assert translate_program(G75_PROGRAM, "fanuc", Settings(), warnings=[]) == text  # no blade: no warning


# ---------------------------------------------------------------- the command line


def test_command_line_prints_warnings_on_stderr_and_exits_0(tmp_path):
    path = tmp_path / "part.mpf"
    path.write_text(C93_PROGRAM)
    status, out, err = run_inline(["expand", str(path), "--dialect", "sinumerik", "--tool-width", "3"])
    assert status == 0
    assert out == translate_program(C93_PROGRAM, "sinumerik", BLADE, source_name="part.mpf")
    corner = "0.01 mm² up to 0.20 mm deep at base corner %d cannot be reached by a 3 mm flat blade (r0.2)"
    assert err == "".join("%s:4: warning: %s\n" % (path, text) for text in (
        NO_ROOM_TEXT, "CYCLE93: " + corner % 1, "CYCLE93: " + corner % 2))
    out_file = tmp_path / "part.ngc"
    status, out, err2 = run_inline(["expand", str(path), "--dialect", "sinumerik", "--tool-width", "3",
                                    "-o", str(out_file)])
    assert (status, out, err2) == (0, "", err)
    assert out_file.read_text() == translate_program(C93_PROGRAM, "sinumerik", BLADE, source_name="part.mpf")


def test_a_failed_run_prints_its_error_alone(tmp_path):
    path = tmp_path / "part.mpf"
    path.write_text(C93_PROGRAM.replace("N50 M2", "N50 M77"))
    status, out, err = run_inline(["expand", str(path), "--dialect", "sinumerik", "--tool-width", "3"])
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and ":5: " in err and "warning" not in err


def test_emit_expand_prints_the_cycles_warnings():
    argv = ["emit", "g75", "-X", "40.", "-Z", "-20.", "-P", "2000", "-Q", "5000", "-R", "2.5", "-F", "0.1",
            "--expand", "--start-x", "50", "--start-z", "0", "--tool-width", "3", "--spindle", "500"]
    status, out, err = run_inline(argv)
    assert status == 0 and out.splitlines()[1].startswith("G18")
    assert err.startswith("emit fanuc-g75:1: warning: G75: the relief R=2.5 ")
    status, out, err = run_inline(argv[:14])  # the native call alone: nothing expanded, nothing to warn of
    assert (status, out, err) == (0, "G75 X40. Z-20. P2000 Q5000 R2.5 F0.1\n", "")
