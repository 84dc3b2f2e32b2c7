"""expand --native-cycles: each reason a call is written as moves instead of
the target's own cycle (one comment line, then the program's own expansion,
the same as without --native-cycles), the command line's option and help."""

import os
import re

import pytest
from conftest import ROOT
from native_helpers import BLADE, native
from test_cli import run_inline

from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.native import native_pairs
from freecad_groove.engine.translator import translate_program


def example(name):
    with open(os.path.join(ROOT, "examples", name)) as f:
        return f.read()


def expanded_with(text, reason):
    """The output holds ``(expanded: reason)`` (``; expanded: reason`` for Siemens) once."""
    found = re.findall(r"^[(;] ?expanded: (.*?)\)?$", text, re.M)
    assert reason in found, "%r not among %r\n%s" % (reason, found, text)


def motion(text):
    """The output's blocks other than comments (what the control runs)."""
    return [line for line in text.splitlines() if not line.startswith(("(", ";")) and "(" not in line[:1]]


def expansion(text, label):
    """The blocks written for the call whose comment holds ``label``: up to the next block of the program."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if label in line and line.lstrip("N0123456789 ")[:1] in "(;")
    out = []
    for line in lines[start + 1:]:
        if line.startswith("N") or (line.startswith(("(", ";")) and "expanded:" not in line):
            break
        if "expanded:" not in line:
            out.append(line)
    return out


def assert_same_moves_as_expanded(text, program, dialect, target, settings=BLADE, label=None, **kw):
    """Where a call falls back, the output writes for it exactly what the translation without
    --native-cycles writes: the blocks after each ``(expanded: ...)`` comment (``label``: only
    those of the call whose comment holds it)."""
    plain = translate_program(program, dialect, settings, target=target, **kw)
    lines = text.splitlines()
    labels = [lines[i - 1] for i, line in enumerate(lines) if "expanded:" in line]
    compared = []
    for line in labels:
        key = line[line.index("(") + 1 if "(" in line else line.index(";") + 2:].rstrip(")")[:40]
        if label is None or label in key:
            ours = expansion(text, key)
            assert ours == expansion(plain, key), key
            compared += ours
    assert compared, text  # some blocks were compared


FANUC = example("fanuc_g75.nc")
AB9 = example("ab9_g77.nc")
GRINDER = example("ab9_g83.nc")
MILL = example("milltronics_g33_g34.nc")


# ----------------------------------------------------------------------------- targets without the cycle


@pytest.mark.parametrize("program, dialect, target, reason, settings", [
    (FANUC, "fanuc", "linuxcnc", "LinuxCNC has no grooving cycle", BLADE),
    (GRINDER, "ab9grind", "linuxcnc", "LinuxCNC has no G83 plunge grinding cycle", Settings()),
    (GRINDER, "ab9grind", "fanuc", "Fanuc has no G83 plunge grinding cycle", Settings()),
    (MILL, "milltronics", "linuxcnc", "LinuxCNC has no Milltronics autoroutine G31-G34",
     Settings(mill_tool_diameter=0.25)),
])
def test_a_target_without_the_cycle_family_gets_the_moves_and_says_so(program, dialect, target, reason, settings):
    text = native(program, dialect, target, settings)
    expanded_with(text, reason)
    assert_same_moves_as_expanded(text, program, dialect, target, settings)


def test_a_gsk_region_is_expanded_for_fanuc_c_which_has_no_g71():
    program = """%\nO0012\nG21 G98\nG0 X50. Z5. C0.\nZ0.\nG07.1 C20.\nG1 Z-10. F100.\nC90.\nG07.1 C0\nM30\n%\n"""
    text = native(program, "gsk", "fanuc-c", Settings())
    expanded_with(text, "Fanuc has no G7.1 cylinder slot cycle")
    assert_same_moves_as_expanded(text, program, "gsk", "fanuc-c", Settings())


# ----------------------------------------------------------------------------- CYCLE93 to a pecking cycle

GROOVE = """T5 D1 S400 M03
G95 G90 F0.1
G00 X80 Z65
CYCLE93(35, 60, %s, 0, 1, 0)
M02
"""
PLAIN_WORDS = "3, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2"  # WIDG .. IDEP, then DWT 0, TYP 1, VRT 0


@pytest.mark.parametrize("words, why", [
    ("3, 5, 0, 5, 0, 0, 0, 0, 0, 0, 0, 2", "flank angles"),
    ("3, 5, 0, 0, 0, 0, 0, 0.3, 0, 0, 0, 2", "edge or base radii/chamfers"),
    ("3, 5, 0, 0, 0, -0.3, 0, 0, 0, 0, 0, 2", "edge or base radii/chamfers"),
    ("3, 5, 0, 0, 0, 0, 0, 0, 0, 0.1, 0, 2", "finishing allowances"),
    ("3, 5, 10, 0, 0, 0, 0, 0, 0, 0, 0, 2", "an oblique contour ANGC 10."),
    ("3, 5, 0, 5, 0, 0, 0, 0, 0, 0.1, 0, 2", "flank angles, finishing allowances"),
    ("3, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.0004", "an Infeed below the cycle's resolution"),
])
@pytest.mark.parametrize("target, code", [("fanuc", "G75"), ("haas", "G75"), ("ab9", "G77"), ("gsk", "G75")])
def test_cycle93_grooves_a_pecking_cycle_cannot_cut_are_expanded_with_the_posts_reason(target, code, words, why):
    program = GROOVE % words
    text = native(program, "sinumerik", target)
    expanded_with(text, "%s cannot cut %s" % (code, why))
    assert_same_moves_as_expanded(text, program, "sinumerik", target)


def test_a_dwell_at_the_bottom_is_a_reason_too():
    program = GROOVE.replace(", 0, 1, 0)", ", 0.5, 1, 0)") % PLAIN_WORDS
    text = native(program, "sinumerik", "fanuc")
    expanded_with(text, "G75 cannot cut a dwell at the bottom")


def test_cycle93_without_a_feed_in_force_fails_as_without_native_cycles():
    program = (GROOVE % PLAIN_WORDS).replace("G95 G90 F0.1", "G95 G90")
    for native_cycles in (False, True):
        with pytest.raises(ProgramError, match="feed move with no feed rate") as info:
            translate_program(program, "sinumerik", BLADE, target="fanuc", native_cycles=native_cycles)
        assert info.value.line == 4


# ----------------------------------------------------------------------------- pecking to pecking


def test_an_allen_bradley_d_shift_is_not_a_fanuc_or_haas_relief():
    text = native(AB9, "ab9", "fanuc")  # the cut-off G77 X-1. I2. F0.04 D0.5
    expanded_with(text, "the D shift of G77 is made at the bottom of every groove, the relief R of G75 never at "
                        "the first")
    expanded_with(native(AB9, "ab9", "haas"), "the D shift of G77 is made at the bottom of every groove, the "
                                              "relief D of G75 never at the first")
    assert_same_moves_as_expanded(text, AB9, "ab9", "fanuc")


def test_a_fanuc_relief_is_not_an_allen_bradley_d_shift():
    program = FANUC.replace("Z-35. P2000 Q2500 R0.", "Z-20. P2000 Q2500 R0.3")  # three grooves, relief 0.3
    text = native(program, "fanuc", "ab9")
    expanded_with(text, "the relief R of G75 is not made at the first groove, the D shift of G77 is made at every "
                        "groove")
    assert_same_moves_as_expanded(text, program, "fanuc", "ab9")
    one = FANUC.replace("Z-35. P2000 Q2500 R0.", "P2000 R0.3")  # one groove: a relief is never made
    assert "G77 X50. I2. F0.05 D0." in native(one, "fanuc", "ab9")


@pytest.mark.parametrize("target, setting", [("ab9", "AMP parameter G77"), ("haas", "setting 22 G75")])
def test_a_fanuc_retract_other_than_the_machine_setting_falls_back_naming_both(target, setting):
    program = FANUC.replace("G75 R0.5", "G75 R0.3")
    text = native(program, "fanuc", target)
    expanded_with(text, "the peck retract e is 0.3 mm, the %s reads is 0.5 mm: give --retract 0.3" % setting)
    assert_same_moves_as_expanded(text, program, "fanuc", target)
    assert re.search(r"^G7[57] X50\. Z-35\.", native(program, "fanuc", target, Settings(peck_retract=0.3)), re.M)
    # a call of one peck per groove never retracts: the setting does not matter
    one_peck = program.replace("P2000", "P6000")
    assert re.search(r"^G7[57] X50\. Z-35\.", native(one_peck, "fanuc", target), re.M)


def test_a_call_whose_rebuilt_words_cut_elsewhere_falls_back_where_they_differ():
    # K2.4704 steps in 0.1 um: a Fanuc Q counts 0.001 mm (Q2470), so its grooves land elsewhere (6, not 5)
    program = AB9.replace("G77 X44. Z-30. I1.5 K10.", "G77 X44. Z-19.8816 I1.5 K2.4704")
    text = native(program, "ab9", "fanuc")
    found = re.findall(r"^\(expanded: (G75 cuts other moves: move \d+ is .*)\)$", text, re.M)
    assert found, text
    assert_same_moves_as_expanded(text, program, "ab9", "fanuc")


# ----------------------------------------------------------------------------- pecking to CYCLE93

PECKS = """%
O0002
G21
G40 G99
T0303
G97 S600 M03
G00 X62. Z-15.
CALL
G00 X100. Z50.
M30
%
"""


@pytest.mark.parametrize("call, reason, settings", [
    ("G75 X56. Z-25. P5000 Q2500 F0.05", "CYCLE93 cuts one groove a call, G75 cuts 5", BLADE),
    ("G75 X50. P2000 F0.05", "CYCLE93 cuts in equal infeeds, each followed by a retract and a rapid back down, "
                             "not G75's 3 pecks", BLADE),
    ("G75 X56. P5000 F0.05", "CYCLE93 places its plunge with the blade, which is not known: give --tool-width or "
                             "--tool-table", Settings()),
])
def test_a_pecking_call_cycle93_cannot_cut_alike_falls_back(call, reason, settings):
    program = PECKS.replace("CALL", call)
    text = native(program, "fanuc", "sinumerik", settings)
    expanded_with(text, reason)
    assert_same_moves_as_expanded(text, program, "fanuc", "sinumerik", settings)


def test_an_allen_bradley_shift_is_no_cycle93():
    program = AB9.replace("G77 X-1. I2. F0.04 D0.5", "G77 X40. I20. F0.04 D0.5")
    text = native(program, "ab9", "sinumerik")
    expanded_with(text, "CYCLE93 has no shift at the groove bottom as G77's D")


# ----------------------------------------------------------------------------- Milltronics


def test_an_autoroutine_without_a_d_register_and_the_g31_after_it_fall_back():
    program = MILL.replace("M3 D1 G43 H1", "M3 G43 H1").replace("R.1 Z-.5", "R.2 Z-.5")
    settings = Settings(mill_tool_diameter=0.25)
    text = native(program, "milltronics", "milltronics", settings)
    expanded_with(text, "G33 reads the end mill's diameter from the D register in force, which the program does "
                        "not select with D<n>")
    # the output's control never got R.2 (the G33 was written as moves): its G31 would go to parameter 140
    expanded_with(text, "G31 rises to the last R the output's control was given, not the program's: an "
                        "autoroutine before it is written as moves")
    assert_same_moves_as_expanded(text, program, "milltronics", "milltronics", settings)


# ----------------------------------------------------------------------------- the command line


def test_expand_native_cycles_writes_what_the_translator_writes():
    path = os.path.join(ROOT, "examples", "fanuc_g75.nc")
    status, out, err = run_inline(["expand", path, "--dialect", "fanuc", "--to", "ab9", "--native-cycles"])
    assert (status, err) == (0, "")
    assert out == translate_program(FANUC, "fanuc", Settings(), target="ab9", source_name="fanuc_g75.nc",
                                    native_cycles=True)
    assert "G77 X50. Z-35. I2. K2.5 F0.05 D0." in out
    status, plain, _ = run_inline(["expand", path, "--dialect", "fanuc", "--to", "ab9"])
    assert status == 0 and "G77" not in plain and "expanded:" not in plain


def test_expand_help_says_what_native_cycles_does_and_lists_the_pairs():
    status, out, _ = run_inline(["expand", "--help"])
    assert status == 0
    text = " ".join(out.split())
    assert "--native-cycles write each cycle call as the target's own cycle where one cuts the same grooves" in text
    for target, pairs in native_pairs().items():
        assert "%s: %s" % (target, pairs) in text
    pairs = native_pairs()
    assert set(pairs) == {"fanuc", "fanuc-c", "gsk", "haas", "ab9", "sinumerik", "milltronics", "ab9grind"}
    assert pairs["ab9"].startswith("G77/G76 of ab9 programs; plain CYCLE93 grooves")
    assert "G75/G74 (fanuc, gsk)" in pairs["haas"] and "G77/G76 (ab9)" in pairs["haas"]
    assert "G7.1 regions" in pairs["gsk"] and pairs["ab9grind"] == "G83/G83.1"


def test_a_blade_from_the_tool_table_reaches_the_cycle93_written_for_a_pecking_call():
    from freecad_groove.engine.tool_table import read_tool_table

    program = PECKS.replace("CALL", "G75 X56. P5000 F0.05")
    tools = read_tool_table("3 3.0 0.2 plus\n")
    text = native(program, "fanuc", "sinumerik", Settings(), tools=tools)
    assert "CYCLE93(30, -18, 3, 2, , , , , , , , , , 5, , 1, 1)" in text
    assert GroovingTool(3.0, 0.2, "plus").reference_offset == 3.0


EMIT_G75 = ["emit", "g75", "-X", "50.", "-Z", "-35.", "-P", "2000", "-Q", "2500", "-F", "0.05", "--expand",
            "--start-x", "62", "--start-z", "-15", "--spindle", "600", "--native-cycles"]


def test_emit_expand_native_cycles_writes_the_targets_call_or_says_why():
    status, out, err = run_inline(EMIT_G75 + ["-e", "0.5", "--to", "ab9"])
    assert (status, err) == (0, "")
    assert out.splitlines()[3:7] == ["G00 X62. Z-15.", "(peck retract e = 0.5 mm: AMP parameter)",
                                     "G77 X50. Z-35. I2. K2.5 F0.05 D0.", "M30"]
    status, out, err = run_inline(EMIT_G75 + ["-e", "0.3", "--to", "haas"])
    assert (status, err) == (0, "")
    lines = out.splitlines()
    assert lines[5:8] == ["G00 X62. Z-15.", "(expanded: the peck retract e is 0.3 mm, the setting 22 G75 reads is "
                                            "0.5 mm: give --retract 0.3)", "G01 X58. F0.05"]
    status, plain, _ = run_inline(EMIT_G75[:-1] + ["-e", "0.3", "--to", "haas"])
    assert [line for line in lines if "expanded:" not in line] == plain.splitlines()
