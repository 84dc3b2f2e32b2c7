"""The translator (freecad_groove.engine.translator): modal tracking
(diameter/radius, G90/G91, U/W, units, N numbers, comments), translation of
carried blocks, cycle expansion in place, errors with line numbers. The
tokenizer: test_reader.py; random input and LinuxCNC's rs274 reading the
translations: test_translator_accepts.py."""

import os

import pytest
from conftest import ROOT

from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import RAPID, GroovingTool, MachineState
from freecad_groove.engine.settings import Settings
from freecad_groove.engine.translator import Translator, translate_program

# the title first, then the setup line (every target's programs open so: output/writer.py Writer.header)
LINUXCNC_HEAD = ["(PROGRAM: %s program, cycles expanded for linuxcnc by freecad-groove)", "G18 G7 G21 G90 G91.1 G40"]
# The seed's blade (examples/tools.tbl, T5). CYCLE93 is refused without a blade, so the helpers below
# translate with this one unless a test passes its own settings (tests/test_tool_table.py: the blade rules).
BLADE = Settings(tool=GroovingTool(3.0, 0.2))


def body(text, dialect, **kw):
    """The translated lines after the LinuxCNC header and title."""
    kw.setdefault("settings", BLADE)
    lines = translate_program(text, dialect, **kw).splitlines()
    assert lines[:2] == [LINUXCNC_HEAD[0] % dialect, LINUXCNC_HEAD[1]]
    return lines[2:]


def error(text, dialect, **kw):
    kw.setdefault("settings", BLADE)
    with pytest.raises(ProgramError) as info:
        translate_program(text, dialect, **kw)
    return info.value


def reader(dialect, lines, **kw):
    kw.setdefault("settings", BLADE)
    t = Translator(dialect, **kw)
    for number, line in enumerate(lines, 1):
        t.line(line, number)
    return t


# ---------------------------------------------------------------- modal tracking


def test_diameter_by_default_and_siemens_diamof():
    t = reader("sinumerik", ["G0 X80 Z65"])
    assert (t.state.x, t.state.z) == (40.0, 65.0)
    t.line("DIAMOF", 2)
    t.line("G0 X20", 3)
    assert t.state.x == 20.0
    t.line("DIAMON", 4)
    t.line("X20", 5)
    assert t.state.x == 10.0


def test_siemens_diam90_radius_increments():
    t = reader("sinumerik", ["G0 X80 Z65", "DIAM90", "G91 X-4", "G90 X30"])
    assert t.state.x == 15.0
    t = reader("sinumerik", ["G0 X80 Z65", "DIAM90", "G91 X-4"])
    assert t.state.x == 36.0


def test_g91_incremental_siemens_and_ab():
    for dialect in ("sinumerik", "ab9"):
        t = reader(dialect, ["G0 X80. Z65.", "G91 G0 X-10. Z-5.", "X-10."])
        assert (t.state.x, t.state.z, t.state.incremental) == (30.0, 60.0, True)
        t.line("G90 X100.", 4)
        assert t.state.x == 50.0 and not t.state.incremental


def test_fanuc_u_w_incremental():
    t = reader("fanuc", ["G00 X80. Z65.", "U-10. W-5."])
    assert (t.state.x, t.state.z) == (35.0, 60.0)
    assert body("G00 X80. Z65.\nU-10. W-5.\nM30", "fanuc") == ["G0 X80. Z65.", "X70. Z60.", "M2"]


def test_ab_g07_g08_mapping():
    lines = ["G08", "G0 X20. Z0.", "G07", "X20."]
    t = reader("ab9", lines[:2])
    assert t.state.x == 20.0 and not t.state.diameter  # G08 = radius (default mapping)
    t.line(lines[2], 3)
    t.line(lines[3], 4)
    assert t.state.x == 10.0
    swapped = Settings(ab_g07_is_diameter=False)
    t = reader("ab9", lines[:2], settings=swapped)
    assert t.state.x == 10.0 and t.state.diameter  # G08 = diameter
    assert body("G08\nG0 X20. Z0.\nM30", "ab9") == ["G0 X40. Z0.", "M2"]


def test_units_convert_the_position():
    t = reader("fanuc", ["G21", "G00 X50.8 Z25.4", "G20"])
    assert t.state.x == pytest.approx(1.0) and t.state.z == pytest.approx(1.0) and not t.state.metric
    assert body("G00 X50.8 Z25.4\nG20\nU-1.\nM30", "fanuc") == ["G0 X50.8 Z25.4", "G20", "X1.", "M2"]
    t = reader("sinumerik", ["G0 X80 Z65", "G700"])
    assert not t.state.metric
    t.line("G710", 3)
    assert t.state.metric and t.state.x == pytest.approx(40.0)


def test_feed_mode_and_feed_tracking():
    t = reader("fanuc", ["G99 F0.2"])
    assert t.state.feed_per_rev is True and t.state.feed == 0.2
    t.line("G98", 2)  # a feed-mode change forgets the feed (LinuxCNC resets F too)
    assert t.state.feed_per_rev is False and t.state.feed is None
    t.line("G21", 3)
    t.line("F100.", 4)
    t.line("G20", 5)  # units change forgets it too
    assert t.state.feed is None


def test_n_numbers_and_comments_carried():
    text = "N10 G95 F0.2 (FEED)\n(ALONE)\nN20 G0 X80 Z65 ; Siemens comment\nN30 M30"
    assert body(text, "sinumerik") == [
        "N10 G95 F0.2 (FEED)",
        "(ALONE)",
        "N20 G0 X80. Z65. (Siemens comment)",
        "N30 M2",
    ]


def test_output_is_absolute_and_modal_codes_dropped():
    text = "G0 X80 Z65\nG91 G1 X-2 F100 G94\nZ-3\nDIAMOF\nG90 G0 X50\nM30"
    assert body(text, "sinumerik") == ["G0 X80. Z65.", "G94 G1 X78. F100.", "Z62.", "G0 X100.", "M2"]


def test_motion_code_written_when_the_output_differs():
    # "G2" alone sets the mode but is not written (LinuxCNC refuses G2 without
    # words); the next block then needs it.
    text = "G98 F100.\nG00 X80. Z70.\nG02\nX60. Z60. I-10. K0\nM30"
    assert body(text, "fanuc") == ["G94 F100.", "G0 X80. Z70.", "G2 X60. Z60. I-10. K0.", "M2"]


# ---------------------------------------------------------------- carried blocks


def test_tool_words():
    assert body("T0303", "fanuc") == ["T3 M6 G43", "M2"]
    assert body("T0312", "haas") == ["T3 M6 G43 H12", "M2"]
    assert body("T300", "ab9") == ["T3 M6 G49", "M2"]
    assert body("T5 D1", "sinumerik") == ["T5 M6 G43", "M2"]
    assert body("T5", "sinumerik") == ["T5 M6 G43", "M2"]
    assert body("T5\nD0\nD1", "sinumerik") == ["T5 M6 G43", "G49", "G43", "M2"]
    fanuc = translate_program("T5 D1\nD0", "sinumerik", target="fanuc").splitlines()
    # D1, the tool's own first edge: its own offset register (T0501 would apply register 1, another tool's)
    assert fanuc[-4:] == ["T0505", "T0500", "M30", "%"]
    assert "T12: write the tool and offset" in str(error("T12", "fanuc"))
    assert "second cutting edge" in str(error("T5 D2", "sinumerik"))
    assert "M6 is added" in str(error("T0101 M06", "fanuc"))


def test_spindle_restarted_after_m6():
    # LinuxCNC's M6 stops the spindle; a turret index does not
    assert body("S500 M3\nT0101\nT0202 M4\nM5\nT0303", "fanuc") == [
        "S500 M3", "T1 M6 G43 M3", "T2 M6 G43 M4", "M5", "T3 M6 G43", "M2",
    ]
    out = translate_program("S500 M3\nT0101", "fanuc", target="fanuc").splitlines()
    assert out[-3] == "T0101"


def test_tool_change_forgets_the_position():
    t = reader("fanuc", ["G00 X80. Z65.", "T0101"])
    assert t.state.x is None and t.state.z is None
    e = error("G00 X80. Z65.\nT0101\nU-2.", "fanuc")
    assert e.line == 3 and "X position is not known" in str(e)


def test_m_codes():
    assert body("M03 S500\nM08\nM7 M8\nM05 M09\nM01\nM00", "fanuc") == [
        "S500 M3", "M8", "M7 M8", "M5 M9", "M1", "M0", "M2",
    ]
    assert "M98 is not supported" in str(error("M98", "fanuc"))
    assert "same modal group" in str(error("M3 M4", "fanuc"))
    fanuc = translate_program("M03 S500\nM02", "fanuc", target="fanuc").splitlines()
    assert fanuc[-3:] == ["S500 M03", "M30", "%"]


def test_program_end():
    assert body("G0 X10 Z0", "sinumerik") == ["G0 X10. Z0.", "M2"]  # an end is added
    assert body("M30\n(after)\n%\n", "fanuc") == ["M2"]  # comments after the end are dropped
    e = error("M30\nG00 X10.", "fanuc")
    assert e.line == 2 and "after the program end" in str(e)


def test_long_comments_fit_linuxcnc_blocks():
    text = "N10 G0 X80 Z65 (" + "x" * 400 + ")\n(" + "y" * 400 + ")\nM30"
    lines = body(text, "sinumerik")
    assert all(len(line) <= 250 for line in lines)
    assert lines[0].startswith("N10 G0 X80. Z65. (xxx") and lines[0].endswith("...)")
    from rs274 import require_rs274, run_rs274

    require_rs274()
    run_rs274("\n".join([LINUXCNC_HEAD[1]] + lines) + "\n")


def test_o_numbers():
    out = translate_program("%\nO1234 (NAME)\nG00 X10. Z0.\nM30\n%", "fanuc", target="fanuc").splitlines()
    assert out[:2] == ["%", "O1234 (PROGRAM: fanuc program O1234, cycles expanded for fanuc by freecad-groove)"]
    assert "(NAME)" in out
    out = translate_program("O1234\nM30", "haas").splitlines()
    assert out[0] == "(PROGRAM: haas program O1234, cycles expanded for linuxcnc by freecad-groove)"
    assert out[2:] == ["M2"]
    e = error("O1\nG0 X1. Z1.\nO2", "fanuc")
    assert e.line == 3 and "second O" in str(e)


def test_spindle_speed_limit_and_css():
    text = "G50 S2500\nG96 S200 M3\nG97 S500\nG96 S180\nG50 S2000\nM30"
    assert body(text, "fanuc") == [
        "(G50 S2500: spindle limit for G96)",
        "G96 D2500 S200 M3",
        "G97 S500",
        "G96 D2500 S180",
        "G96 D2000 S180",
        "M2",
    ]
    assert body("G96 S200 LIMS=3000 M3\nLIMS=2000\nM30", "sinumerik") == [
        "G96 D3000 S200 M3", "G96 D2000 S200", "M2",
    ]
    out = translate_program("G96 S200 LIMS=3000 M3\nM30", "sinumerik", target="fanuc").splitlines()
    assert out[-4:] == ["G50 S3000", "G96 S200 M03", "M30", "%"]
    assert "G96 needs the surface speed" in str(error("G96 M3", "fanuc"))
    assert "G97 after G96 needs" in str(error("G96 S100\nG97", "fanuc"))
    assert "G50 is supported only" in str(error("G50 X100. Z0.", "fanuc"))


@pytest.mark.parametrize(
    "text, dialect, dwell",
    [
        ("G4 F2", "sinumerik", "G4 P2."),
        ("G04 X1.5", "fanuc", "G4 P1.5"),
        ("G04 U1.5", "fanuc", "G4 P1.5"),
        ("G04 P1500", "fanuc", "G4 P1.5"),
        ("G04 P1.5", "haas", "G4 P1.5"),  # decimal point: seconds
        ("G04 P1500", "haas", "G4 P1.5"),  # no decimal point: milliseconds
    ],
)
def test_dwell(text, dialect, dwell):
    assert body(text, dialect) == [dwell, "M2"]


@pytest.mark.parametrize(
    "text, dialect, message",
    [
        ("G04 P1.5", "fanuc", "must be a whole number"),
        ("G4 S10", "sinumerik", "spindle revolutions"),
        ("G04 P1.", "ab9", "not documented"),
        ("G4 F1 X2", "sinumerik", "exactly one time word"),
        ("G04 P" + "9" * 400, "fanuc", "the dwell must be 0 to 99999 s"),  # not an overflow converting to seconds
        ("G04 P" + "9" * 400, "haas", "the dwell must be 0 to 99999 s"),
    ],
    ids=["fanuc-P1.5", "sinumerik-S", "ab9", "two-words", "fanuc-400-digits", "haas-400-digits"],
)
def test_dwell_errors(text, dialect, message):
    assert message in str(error(text, dialect))


def test_arcs():
    text = "G98 F100.\nG00 X80. Z70.\nG02 X60. Z60. I-10. K0\nG03 X80. Z50. R10.\nM30"
    assert body(text, "fanuc") == ["G94 F100.", "G0 X80. Z70.", "G2 X60. Z60. I-10. K0.", "G3 X80. Z50. R10.", "M2"]
    assert body("G94 F100\nG0 X80 Z70\nG2 X60 Z60 CR=10\nM30", "sinumerik")[2] == "G2 X60. Z60. R10."


@pytest.mark.parametrize(
    "block, message",
    [
        ("G02 X60. Z59.9 I-10. K0", "not on the circle"),
        ("G02 X60. Z40. R10.", "too small to reach"),
        ("G02 X80. Z70. R10.", "end point is the start point"),
        ("G02 X60. Z60. I0 K0", "zero radius"),
        ("G02 X60. Z60. R-10.", "must be positive"),
        ("G02 X60. Z60.", "either I/K"),
        ("G01 X60. R5.", "only read with G2/G3"),
    ],
)
def test_arc_errors(block, message):
    e = error("G98 F100.\nG00 X80. Z70.\n" + block, "fanuc")
    assert e.line == 3 and message in str(e)


# ---------------------------------------------------------------- refusals (with line numbers)


@pytest.mark.parametrize(
    "text, dialect, line, message",
    [
        ("G00 X80 Z65", "fanuc", 1, "X80 needs a decimal point"),
        ("G21\nG00 X80. Z65.\nG01 X70. F0.1", "fanuc", 3, "feed mode is programmed"),
        ("G99\nG00 X80. Z65.\nG01 X70.", "fanuc", 3, "no feed rate"),
        ("G99 F0.1\nG00 X80. Z65.\nG01 X70.", "fanuc", 3, "no spindle speed"),
        ("G98 F100.\nG00 X80. Z65.\nG01 X70.", "fanuc", 3, None),  # per minute: no spindle needed
        ("G0 X80 Z65\nX70", "sinumerik", 2, None),  # fine: G0 modal
        ("X70 Z65", "sinumerik", 1, "without a motion mode"),
        ("G91 G0 X2", "sinumerik", 1, "X position is not known"),
        ("G90 G00 X10.", "fanuc", 1, "turning cycle"),
        ("G94", "haas", 1, "facing cycle"),
        ("G28 U0 W0", "fanuc", 1, "reference return"),
        ("G41 G1 X10. Z0.", "fanuc", 1, "nose radius compensation"),
        ("G17", "sinumerik", 1, "XZ plane"),
        ("G0 G1 X10", "sinumerik", 1, "same modal group"),
        ("G0 X10 X20", "sinumerik", 1, "programmed twice"),
        ("G0 X10. U2.", "fanuc", 1, "X and U in one block"),
        ("G0 U2.", "sinumerik", 1, "U2. is not supported"),
        ("G0 X10 R5", "sinumerik", 1, "R parameters"),
        ("G70", "sinumerik", 1, None),  # inch lengths: fine ...
        ("G70 F2", "sinumerik", 1, "G700"),  # ... but not a feed in G70
        ("G12.1", "fanuc", 1, "G12.1 is not supported"),
        ("G0 X10. Z0. E5.", "fanuc", 1, "E5. is not supported"),
        ("\n\nG0 X1 Z1 @", "sinumerik", 3, "cannot read"),
        ("G0 X1e3 Z1", "sinumerik", 1, "E3 is not supported"),
        ("G0 X80 Z65\r\nG1 X70\r\n", "sinumerik", 2, "feed mode"),
        ("DIAMOF\nG0 X1 Z1\nG0 X900000", "sinumerik", 3, "cannot be written"),
        ("G0 X80 Z65\rG1 X70\r", "sinumerik", 2, "feed mode"),
    ],
)
def test_refusals(text, dialect, line, message):
    if message is None:
        translate_program(text, dialect)
        return
    e = error(text, dialect)
    assert e.line == line and message in str(e), str(e)


def test_block_delete():
    # a carried "/" block keeps its slash
    assert body("G0 X80 Z65\n/G0 X10\nG0 X20\nG91 X2\nM30", "sinumerik") == [
        "G0 X80. Z65.", "/G0 X10.", "G0 X20.", "X22.", "M2",
    ]
    # the position after a "/" move depends on the switch: incremental moves
    # and cycles are refused until an absolute position is programmed
    e = error("G0 X80 Z65\n/G0 X10\nG91 G0 X2", "sinumerik")
    assert e.line == 3 and "block-delete" in str(e)
    e = error("G95 F0.2 S200 M3\nG0 X80 Z65\n/G1 X70 F0.3\nG1 X60", "sinumerik")
    assert e.line == 4 and "feed" in str(e)
    assert body("G95 F0.2 S200 M3\nG0 X80 Z65\n/G1 X70 F0.3\nG1 X60 F0.1\nM2", "sinumerik")[-2:] == [
        "G1 X60. F0.1", "M2",
    ]


def test_block_delete_on_a_cycle_prefixes_every_line():
    text = "G95 F0.1 S500 M3\nG0 X50. Z0.\n/G77 X44. I2. D0.\nG0 X60. Z5.\nM30"
    lines = body(text, "ab9")
    start = lines.index("/(G77 X44. I2. D0.)")
    cycle = lines[start + 1 : lines.index("G0 X60. Z5.")]
    assert cycle and all(line.startswith("/") for line in cycle)
    # the cycle returns to its start: the position stays known ...
    body("G95 F0.1 S500 M3\nG0 X50. Z0.\n/G77 X44. I2. D0.\nG77 X40. I2. D0.", "ab9")
    # ... but its F makes the feed depend on the switch
    e = error("G95 F0.1 S500 M3\nG0 X50. Z0.\n/G77 X44. I2. F0.2 D0.\nG77 X40. I2. D0.", "ab9")
    assert e.line == 4 and "feed" in str(e)


# ---------------------------------------------------------------- cycles in place


def test_ab_g77_single_groove_exact():
    # Worked by hand from seed 000: start X50 (radius 25), bottom X44 (radius
    # 22), I2 per side: feed to 23, rapid back e = 0.5 (default), feed I + e to
    # the bottom 22, D0: no shift, rapid to the start X. One groove: no Z move.
    text = "G21 G90 G95\nT0101\nS500 M3\nG0 X50. Z0.\nN50 G77 X44. I2. F0.1 D0.\nG0 X60. Z5.\nM30"
    assert body(text, "ab9") == [
        "G21 G95",
        "T1 M6 G43",
        "S500 M3",
        "G0 X50. Z0.",
        "N50 (G77 X44. I2. F0.1 D0.)",
        "G1 X46. F0.1",
        "G0 X47.",
        "G1 X44.",
        "G0 X50.",
        "G0 X60. Z5.",
        "M2",
    ]


def test_fanuc_two_block_g75_passes_e():
    text = "G21\nG99 S500 M3\nG00 X50. Z0.\nN60 G75 R1.\nN70 G75 X44. P2000 F0.1\nM30"
    lines = body(text, "fanuc")
    assert lines[3] == "N60 (G75 R1.: peck retract e for the next G75/G74)"
    assert lines[4] == "N70 (G75 R1. / G75 X44. P2000 F0.1)"
    # P2000 = 2 mm per side; e = 1 from the first block
    assert lines[5:9] == ["G1 X46. F0.1", "G0 X48.", "G1 X44.", "G0 X50."]


def test_fanuc_e_is_modal_and_shared_by_g74_and_g75():
    t = reader("fanuc", ["G21", "G99 F0.1 S500 M3", "G00 X50. Z0.", "G74 R1."])
    assert t.state.retract_e.text == "1."
    t.line("G75 X44. P2000", 5)
    assert t.body[-3:-1] == ["G0 X48.", "G1 X44."]


def test_haas_g75_one_block_uses_the_retract_setting():
    text = "G21\nG99 S500 M3\nG00 X50. Z0.\nG75 X44. I2. F0.1\nM30"
    settings = Settings(peck_retract=0.25)
    lines = body(text, "haas", settings=settings)
    assert lines[4:8] == ["G1 X46. F0.1", "G0 X46.5", "G1 X44.", "G0 X50."]


def test_state_after_a_cycle():
    t = reader("fanuc", ["G21", "G99 F0.2 S500 M3", "G00 X50. Z0.", "G75 X44. Z-5. P2000 Q2500 F0.1"])
    s = t.state
    assert (s.x, s.z) == (25.0, 0.0)  # the cycle returns to its start
    assert s.feed == 0.1  # the last F the cycle wrote
    assert s.motion == RAPID  # Fanuc G75 is non-modal: G00 stays
    assert t.writer.motion == RAPID
    t = reader("ab9", ["G95 F0.2 S500 M3", "G0 X50. Z0.", "G77 X44. I2. D0."])
    assert t.state.feed == 0.2 and t.state.motion is None  # motion after an AB cycle is not known
    e = error("G95 F0.2 S500 M3\nG0 X50. Z0.\nG77 X44. I2. D0.\nX60.", "ab9")
    assert e.line == 4 and "motion mode" in str(e)


def test_cycle_refusals():
    e = error("G95 F0.1\nN40 CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)", "sinumerik")
    assert e.line == 2 and "start point" in str(e)
    e = error("G0 X80 Z65\nCYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)", "sinumerik")
    assert e.line == 2 and "feed mode" in str(e)
    e = error("S400 M3\nG0 X80 Z65\nG95\nCYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)",
              "sinumerik")
    assert e.line == 4 and "no feed rate" in str(e)
    e = error("G0 X80 Z65\nG95 F0.1\nCYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)", "sinumerik")
    assert e.line == 3 and "no spindle speed" in str(e)
    e = error("S400 M3\nM5\nG0 X80 Z65\nG95 F0.1\nCYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)",
              "sinumerik")
    assert e.line == 5 and "spindle stopped" in str(e)
    e = error("S400\nG0 X80 Z65\nG95 F0.1\nG1 X70", "sinumerik")
    assert e.line == 4 and "spindle not started" in str(e)
    e = error("G0 X80 Z65\nG95 F.1\nG1 CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)",
              "sinumerik")
    assert e.line == 3 and "shares the block" in str(e)
    e = error("G21\nG99\nG00 X62. Z-15.\nG75 X50. Z-20. P2000 Q2500 F0.05 M8", "fanuc")
    assert e.line == 4 and "M8 shares the block" in str(e)
    e = error("G21\nG99\nG00 X62. Z-15.\nG75 R1", "fanuc")
    assert e.line == 4 and "decimal point" in str(e)


def test_cycle_error_becomes_program_error_with_the_line():
    seed = open(os.path.join(ROOT, "examples", "seed_cycle93.mpf")).read()
    e = error(seed.replace("30, 25, 12", "1, 25, 12"), "sinumerik")
    assert e.line == 4 and e.args[0].startswith("CYCLE93 WIDG=1")
    e = error("G95 F0.1 S500 M3\nG0 X50. Z0.\n\nG77 X44. I0 D0.", "ab9")
    assert e.line == 4 and "G77" in str(e) and "I" in str(e)


def test_mode_codes_in_a_cycle_block_apply_first():
    lines = body("G94 F100. S500 M3\nG0 X50. Z0.\nG95 F0.1 G77 X44. I2. D0.\nM30", "ab9")
    assert lines[2] == "G95"  # then the call, with the feed of its F word
    assert lines[3] == "(G77 F0.1 X44. I2. D0.)"


def test_seed_example_structure():
    seed = open(os.path.join(ROOT, "examples", "seed_cycle93.mpf")).read()
    lines = body(seed, "sinumerik")
    assert lines[:4] == ["N10 T5 M6 G43 S400 M3", "N20 G95 F0.2", "N30 G0 X80. Z65.",
                         "N40 (CYCLE93 35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"]
    assert lines[-2:] == ["N50 G0 X50. Z65.", "N60 M2"]


def test_fanuc_target():
    text = open(os.path.join(ROOT, "examples", "fanuc_g75.nc")).read()
    out = translate_program(text, "fanuc", target="fanuc", source_name="fanuc_g75.nc").splitlines()
    assert out[:4] == ["%", "O1001 (fanuc_g75.nc: fanuc program O1001, cycles expanded for fanuc by freecad-groove)",
                       "G21", "G40"]
    assert "N10 G21" in out and "N20 G99 G40" in out and "N30 T0303" in out
    assert "G01 X58. F0.05" in out and "G00 X59." in out
    assert out[-2:] == ["N100 M30", "%"]


def test_start_modes():
    start = MachineState(diameter_mode=False, metric=False, feed_per_rev=True)
    out = translate_program("S500 M3\nG0 X1. Z0.\nG1 X0.5 F0.004\nM30", "ab9", start=start).splitlines()
    assert out[1] == "G18 G7 G20 G90 G91.1 G40 G95"
    assert out[3:5] == ["G0 X2. Z0.", "G1 X1. F0.004"]


def test_unknown_dialect_or_target():
    with pytest.raises(ValueError):
        translate_program("", "heidenhain")
    with pytest.raises(ValueError):
        translate_program("", "fanuc", target="mazak")
