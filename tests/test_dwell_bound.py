"""One bound on CYCLE93's dwell DWT, in the model, for every output (issue 20, item 9): 0 to 99999 s, the
longest dwell every target writes (the expansion's G4 already stopped there). Before, ``emit cycle93 --dwt
99999999`` wrote the native call while the expansion refused the same value."""

import pytest
from test_cli import run_inline

from freecad_groove.engine import GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.errors import CycleError, ProgramError
from freecad_groove.engine.numbers import MAX_DWELL_SECONDS
from freecad_groove.engine.translator import translate_program

BLADE = Settings(tool=GroovingTool(3.0, 0.2))
RULE = "the dwell must be 0 to 99999 s, the longest every target writes"
CALL = "CYCLE93(20, -10, 6, 3, 0, 0, 0, 0, 0, 0, 0, 0.2, 0.2, 2, %s, 5, 0)"
WORDS = ["--axfa", "20", "--axsa", "-10", "--widg", "6", "--depg", "3", "--fal1", ".2", "--fal2", ".2",
         "--idep", "2", "--typ", "5", "--tool-width", "3", "--tool-radius", ".2"]
PROGRAM = "G90 G95 G71\nT1 D1\nS500 M3\nG0 X50 Z5 F.1\n%s\nM30\n"
HUGE = "9" * 309  # read as 1e+309: infinite; "1" and 308 zeros: 1e+308


def test_the_bound_is_the_one_the_writer_uses():
    assert MAX_DWELL_SECONDS == 99999.0


@pytest.mark.parametrize("dwt, shown", [("99999999", "99999999"), ("99999.001", "99999.001"),
                                        ("1" + "0" * 308, "1e+308")])
def test_the_model_refuses_a_dwell_beyond_the_bound_naming_dwt_value_and_rule(dwt, shown):
    with pytest.raises(CycleError) as raised:
        Cycle93.parse(CALL % dwt).validate(BLADE)
    assert raised.value.message == "CYCLE93 DWT=%s: %s" % (shown, RULE)


def test_the_bound_itself_is_written_natively_and_expanded():
    model = Cycle93.parse(CALL % "99999").validate(BLADE)
    moves = model.expand(MachineState(x=25.0, z=5.0, feed=0.1, feed_per_rev=True), BLADE)
    assert {move.p for move in moves if move.kind == "G4"} == {99999.0}
    assert ", 99999, 5" in model.emit()


@pytest.mark.parametrize("dwt", ["99999999", "1" + "0" * 308])
def test_emit_native_and_emit_expand_refuse_the_same_dwell_in_one_line(dwt):
    for extra in ([], ["--expand", "--start-x", "50", "--start-z", "5", "--feed", ".1", "--spindle", "500"]):
        status, out, err = run_inline(["emit", "cycle93"] + WORDS + ["--dwt", dwt] + extra)
        assert (status, out) == (2, ""), err
        assert err.startswith("emit cycle93:1: CYCLE93 DWT=") and err.endswith(": %s\n" % RULE), err
        assert err.count("\n") == 1


@pytest.mark.parametrize("target, native", [("sinumerik", True), ("sinumerik", False), ("linuxcnc", False),
                                            ("fanuc", False)])
def test_a_program_with_the_dwell_is_refused_for_every_output(target, native):
    with pytest.raises(ProgramError, match=r"CYCLE93 DWT=99999999: %s" % RULE) as raised:
        translate_program(PROGRAM % (CALL % "99999999"), "sinumerik", BLADE, target=target, native_cycles=native)
    assert raised.value.line == 5


def test_a_309_digit_dwell_is_refused_as_the_parameter_not_a_traceback():
    status, out, err = run_inline(["emit", "cycle93"] + WORDS + ["--dwt", HUGE])
    assert (status, out) == (2, "") and err.startswith("emit cycle93") and "DWT" in err and err.count("\n") == 1
