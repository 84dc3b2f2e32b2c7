"""The command line's --to: every control's output, and the refusals of what a
target cannot take (one line naming the option or the word, status 2, nothing
on stdout), never an internal error or a program the control would reject."""

import pytest
from test_cli import run_inline

from freecad_groove.engine.output.targets import TARGETS


def test_expand_help_lists_every_target():
    status, out, _err = run_inline(["expand", "--help"])
    assert status == 0
    text = " ".join(out.split())
    for name in TARGETS:
        assert "%s = " % name in text, name


@pytest.mark.parametrize("example, dialect, to", [
    ("examples/ab9_g83.nc", "ab9grind", "linuxcnc-c"),
    ("examples/ab9_g83.nc", "ab9grind", "sinumerik"),
    ("examples/milltronics_g33_g34.nc", "milltronics", "fanuc-c"),
    ("examples/ab9_g77.nc", "ab9", "milltronics"),
    ("examples/ab9_g77.nc", "ab9", "ab9grind"),
])
def test_a_program_for_a_target_of_the_other_kind_is_refused_naming_the_option(example, dialect, to):
    status, out, err = run_inline(["expand", example, "--dialect", dialect, "--to", to, "--tool-diameter", "0.25"]
                                  if dialect == "milltronics" else ["expand", example, "--dialect", dialect, "--to", to])
    assert (status, out) == (2, "")
    assert err.startswith("%s:0: --to %s: %s is a " % (example, to, to)) and err.count("\n") == 1
    assert "internal error" not in err


def test_a_tool_number_the_target_cannot_hold_is_refused_naming_it(tmp_path):
    # LinuxCNC's rs274 reads T2147483648 as a negative tool id: never written
    path = tmp_path / "t.mpf"
    path.write_text("T2147483648 D1\nM30\n")
    status, out, err = run_inline(["expand", str(path), "--dialect", "sinumerik"])
    assert (status, out) == (2, "")
    assert err.endswith("t.mpf:1: tool number 2147483648 cannot be written for linuxcnc (0 to 99999)\n")


def test_a_spindle_speed_that_would_be_written_as_zero_is_refused(tmp_path):
    # S0.000001 under feed per revolution would be written S0.: the spindle would not turn
    path = tmp_path / "s.mpf"
    path.write_text("G95 S0.000001 M03\nG0 X10. Z0.\nG1 X5. F0.1\nM30\n")
    status, out, err = run_inline(["expand", str(path), "--dialect", "sinumerik"])
    assert (status, out) == (2, "")
    assert err.endswith("s.mpf:1: S0.000001 rounds to 0 in the output (4 decimals): the spindle would not turn\n")
