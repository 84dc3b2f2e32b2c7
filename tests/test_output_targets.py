"""Every target's syntax (freecad_groove.engine.output.targets), on one small
hand-made program and on the seed examples: the expected programs are written
out by hand from each control's table (header, comments, tool change, spindle,
dwell, arcs, M codes, end); each target's output is read back by the engine's
own reader for that control and must make the same moves as the LinuxCNC
translation, which rs274 accepts."""

import math
import os
import re

import pytest
from conftest import ROOT
from rs274 import require_rs274, run_rs274

from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import ARC_CCW, ARC_CW, FEED, Move
from freecad_groove.engine.output.targets import LATHE_TARGETS, MILL_TARGETS, TARGETS
from freecad_groove.engine.output.writer import Writer
from freecad_groove.engine.tool_table import read_tool_table
from freecad_groove.engine.translator import translate_program

# A Fanuc program: a tool, the spindle and coolant, a feed, a dwell of 1.5 s, a
# quarter arc G03 by its centre from X50 Z-10 (radius 25) to X40 Z-15 about
# (radius 20, Z-10), and a quarter arc G02 by its radius 5 to X50 Z-20 (centre
# radius 25, Z-15), a spindle stop, the end.
HAND = """%
O0042 (HAND)
N10 G21 G99 G40
N20 T0101
N30 G97 S800 M03 M08
N40 G00 X50. Z2.
N50 G01 Z-10. F0.2
N60 G04 P1500
N70 G03 X40. Z-15. I-5. K0.
N80 G02 X50. Z-20. R5.
N90 G00 X60.
N100 M05 M09
N110 M30
%
"""

TITLE = "hand.nc: fanuc program O42, cycles expanded for %s by freecad-groove"

FANUC_BODY = [
    "(HAND)", "G21", "N10 G99 G40", "N20 T0101", "N30 G97 S800 M03 M08", "N40 G00 X50. Z2.", "N50 G01 Z-10. F0.2",
    "N60 G04 P1500", "N70 G03 X40. Z-15. I-5. K0.", "N80 G02 X50. Z-20. R5.", "N90 G00 X60.", "N100 M05 M09",
    "N110 M30", "%",
]

EXPECTED = {
    "linuxcnc": ["(%s)" % TITLE % "linuxcnc", "G18 G7 G21 G90 G91.1 G40", "(HAND)", "N10 G21 G95 G40",
                 "N20 T1 M6 G43", "N30 G97 S800 M3 M8", "N40 G0 X50. Z2.", "N50 G1 Z-10. F0.2", "N60 G4 P1.5",
                 "N70 G3 X40. Z-15. I-5. K0.", "N80 G2 X50. Z-20. R5.", "N90 G0 X60.", "N100 M5 M9", "N110 M2"],
    # Fanuc: %, the O number with the title, G21 alone, G40 and the feed mode, two-digit codes, G04 P in ms
    "fanuc": ["%", "O0042 (%s)" % TITLE % "fanuc", "G21", "G40"] + FANUC_BODY,
    # GSK: Fanuc's syntax
    "gsk": ["%", "O0042 (%s)" % TITLE % "gsk", "G21", "G40"] + FANUC_BODY,
    # Haas: Fanuc's, with G04 P in seconds
    "haas": ["%", "O0042 (%s)" % TITLE % "haas", "G21", "G40"]
    + [line.replace("G04 P1500", "G04 P1.5") for line in FANUC_BODY],
    # Siemens: ";" comments, G71, DIAMON, T1 D1, G4 F seconds, arcs by CR= (both 90 degrees: positive)
    "sinumerik": ["; %s" % TITLE % "sinumerik", "G18 G71 G90 G40 DIAMON", "; HAND", "N10 G71 G95 G40",
                  "N20 T1 D1", "N30 G97 S800 M3 M8", "N40 G0 X50. Z2.", "N50 G1 Z-10. F0.2", "N60 G4 F1.5",
                  "N70 G3 X40. Z-15. CR=5.", "N80 G2 X50. Z-20. CR=5.", "N90 G0 X60.", "N100 M5 M9", "N110 M30"],
}


def same_canon(a, b, tol=1e-3):
    """Two rs274 canonical move lists are the same moves: kinds, X and Z (and a dwell's seconds) within ``tol``."""
    assert len(a) == len(b), (len(a), len(b))
    for one, two in zip(a, b):
        assert one[0] == two[0] and all(math.isclose(p, q, abs_tol=tol) for p, q in zip(one[1:3], two[1:3])), (one, two)
        if one[0] == "G4":
            assert math.isclose(one[-1], two[-1], abs_tol=tol), (one, two)
    return True


def lines(text, to, dialect="fanuc", settings=None, name="hand.nc"):
    return translate_program(text, dialect, settings or Settings(), target=to, source_name=name).splitlines()


@pytest.mark.parametrize("to", sorted(EXPECTED))
def test_the_hand_made_program_in_each_lathe_syntax(to):
    assert lines(HAND, to) == EXPECTED[to]


def test_the_allen_bradley_9_series_gets_its_arcs_by_centre_and_refuses_the_dwell():
    # its manual documents no dwell word and no R arcs here: the radius arc's centre (radius 25, Z-15) is written
    # from its start (radius 20, Z-15): I5. K0.
    with pytest.raises(ProgramError, match=r"^a dwell \(G4\) cannot be written for the Allen-Bradley 9/Series"):
        lines(HAND, "ab9")
    out = lines(HAND.replace("N60 G04 P1500\n", ""), "ab9")
    assert out[:5] == ["(%s)" % TITLE % "ab9", "G18 G21 G90 G40 G07", "(HAND)", "N10 G21 G95 G40", "N20 T0101"]
    assert out[8:10] == ["N70 G03 X40. Z-15. I-5. K0.", "N80 G02 X50. Z-20. I5. K0."]
    assert out[-1] == "N110 M30"


def test_the_g07_meaning_of_the_machine_is_the_one_written():
    # a 9/Series whose G07 selects radius mode (Settings.ab_g07_is_diameter False) is set to diameters with G08
    out = lines("G0 X50. Z2.\nM30\n", "ab9", "ab9", Settings(ab_g07_is_diameter=False))
    assert out[1] == "G18 G21 G90 G40 G08"


@pytest.mark.parametrize("to", ["fanuc", "haas", "sinumerik", "ab9", "gsk"])
def test_each_lathe_output_reads_back_as_the_same_moves(to):
    # the output read by the engine's own reader of that control makes the moves of the LinuxCNC translation
    require_rs274()
    program = HAND.replace("N60 G04 P1500\n", "") if to == "ab9" else HAND
    direct = run_rs274(translate_program(program, "fanuc"), tool_table={1})
    written = translate_program(program, "fanuc", target=to)
    again = run_rs274(translate_program(written, to), tool_table={1})
    assert same_canon(again, direct)


@pytest.mark.parametrize("example, dialect", [
    ("seed_cycle93.mpf", "sinumerik"), ("ab9_g77.nc", "ab9"), ("fanuc_g75.nc", "fanuc"), ("haas_g75.nc", "haas"),
])
@pytest.mark.parametrize("to", ["linuxcnc", "fanuc", "haas", "sinumerik", "gsk", "ab9", "linuxcnc-c", "fanuc-c"])
def test_the_seed_examples_expand_for_every_lathe_target_and_read_back_the_same(example, dialect, to):
    require_rs274()
    with open(os.path.join(ROOT, "examples", example)) as f:
        program = f.read()
    with open(os.path.join(ROOT, "examples", "tools.tbl")) as f:
        tools = read_tool_table(f.read(), "tools.tbl")
    settings = Settings(tool=GroovingTool(3.0, 0.2))
    direct = translate_program(program, dialect, settings, tools=tools)
    tool_numbers = {int(n) for n in re.findall(r"^(?:N\d+ )?T(\d+) M6", direct, re.M)}
    if to == "ab9" and example == "seed_cycle93.mpf":  # its CYCLE93 dwells DWT = 1 s at the base
        with pytest.raises(ProgramError, match="a dwell .G4. cannot be written for the Allen-Bradley 9/Series"):
            translate_program(program, dialect, settings, target=to, tools=tools)
        return
    written = translate_program(program, dialect, settings, target=to, tools=tools)
    reader = {"linuxcnc-c": "linuxcnc", "fanuc-c": "fanuc"}.get(to, to)
    if reader == "linuxcnc":
        again = written
    else:
        again = translate_program(written, reader, settings)
    assert same_canon(run_rs274(again, tool_table=tool_numbers), run_rs274(direct, tool_table=tool_numbers))


def test_every_target_is_a_lathe_or_a_mill_and_each_mill_twin_is_a_mill():
    assert set(LATHE_TARGETS) | set(MILL_TARGETS) == set(TARGETS)
    for name in LATHE_TARGETS:
        twin = TARGETS[name].mill_twin
        assert not TARGETS[name].mill and (not twin or TARGETS[twin].mill)


# ---------------------------------------------------------------- arcs, each form


QUARTERS = [
    # (kind, start (x radius, z), end, centre): seen from +Y with Z to the right and X up, G3 turns counter-clockwise
    (ARC_CCW, (25.0, -10.0), (20.0, -15.0), (20.0, -10.0)),  # from the top of the circle to its left: +90 degrees
    (ARC_CW, (20.0, -15.0), (25.0, -20.0), (25.0, -15.0)),  # from the bottom to the left, clockwise: 90 degrees
    (ARC_CW, (25.0, -10.0), (20.0, -15.0), (20.0, -10.0)),  # the first arc the other way round: 270 degrees
]


@pytest.mark.parametrize("kind, start, end, centre, cr", [q + (cr,) for q, cr in zip(QUARTERS, (5.0, 5.0, -5.0))])
def test_siemens_cr_is_the_radius_negative_beyond_180_degrees(kind, start, end, centre, cr):
    writer = Writer("sinumerik", x=start[0], z=start[1], feed=0.1, motion=FEED)
    x_word = "X%g." % (2 * end[0])
    assert writer.write([Move(kind, end[0], end[1], centre=centre)]) == [
        "%s %s Z%g. CR=%g." % (kind, x_word, end[1], cr)]


@pytest.mark.parametrize("kind, start, end, centre", QUARTERS)
def test_centre_arcs_write_i_and_k_from_the_start_as_written(kind, start, end, centre):
    # the start is written with 4 decimals; I and K are the centre less that start, radius values
    writer = Writer("linuxcnc", x=start[0] + 0.00001, z=start[1], feed=0.1, motion=FEED)
    i, k = centre[0] - start[0], centre[1] - start[1]
    assert writer.write([Move(kind, end[0], end[1], centre=centre)]) == [
        "%s X%g. Z%g. I%s K%s" % (kind, 2 * end[0], end[1], _word(i), _word(k))]


def _word(value):
    return ("%g" % value) + ("." if value == int(value) else "")


@pytest.mark.parametrize("radius, kind, centre", [(5.0, ARC_CW, (25.0, -15.0)), (5.0, ARC_CCW, (20.0, -20.0))])
def test_a_radius_arc_has_its_centre_on_the_side_its_direction_says(radius, kind, centre):
    # from (20, -15) to (25, -20): G2 with R5 turns about (25, -15), G3 about (20, -20)
    writer = Writer("ab9", x=20.0, z=-15.0, feed=0.1, motion=FEED)
    words = writer.write([Move(kind, 25.0, -20.0, radius=radius)])[0].split()
    i, k = float(words[3][1:]), float(words[4][1:])
    assert (20.0 + i, -15.0 + k) == centre


def test_an_arc_shorter_than_the_resolution_is_not_written_and_a_mill_arc_is_in_xy():
    lathe = Writer("linuxcnc", x=20.0, z=0.0, feed=0.1, motion=FEED)
    assert lathe.write([Move(ARC_CW, 20.00001, 0.00001, centre=(10.0, 0.0))]) == []
    mill = Writer("linuxcnc-mill", x=0.0, z=5.0, y=0.0, feed=100.0, motion=FEED)
    assert mill.write([Move(ARC_CCW, 10.0, 5.0, y=10.0, centre=(0.0, 10.0))]) == ["G3 X10. Y10. I0. J10."]


def test_rs274_turns_every_written_arc_the_way_the_engine_means():
    require_rs274()
    writer = Writer("linuxcnc", True, False)
    moves = [Move("G0", 25.0, -10.0)] + [Move(kind, end[0], end[1], 0.1, centre=centre)
                                         for kind, _start, end, centre in QUARTERS[:2]]
    text = "\n".join(writer.header("arcs") + writer.write(moves) + writer.footer()) + "\n"
    arcs = [c for c in run_rs274(text) if c[0] not in ("G0", "G1", "G4")]
    assert len(arcs) == 2
    # rs274's ARC_FEED: the end (x a radius), as the engine meant it
    for canon, (_kind, _start, end, _centre) in zip(arcs, QUARTERS[:2]):
        assert math.isclose(canon[1], end[0], abs_tol=1e-4) and math.isclose(canon[2], end[1], abs_tol=1e-4)


@pytest.mark.parametrize("siemens, fanuc", [("T5 D1", "T0505"), ("T5 D0", "T0500"), ("T12", "T1212")])
def test_a_siemens_tool_with_its_own_edge_takes_its_own_offset_register_on_fanuc(siemens, fanuc):
    # Siemens D1 is the first cutting edge of the tool itself; Fanuc's T0501 would apply register 1 (another tool's)
    out = lines("%s\nG0 X50. Z2.\nM30\n" % siemens, "fanuc", "sinumerik")
    assert out[4] == fanuc  # after %, the title, G21 and G40


def test_a_fanuc_offset_of_another_tool_has_no_siemens_d_number():
    with pytest.raises(ProgramError, match=r"^T5 with the offset of tool 12: a Siemens D number is a cutting edge "):
        lines("T0512\nG0 X50. Z2.\nM30\n", "sinumerik")


# ---------------------------------------------------------------- mill-style programs


def test_the_milltronics_example_expanded_for_milltronics_makes_the_same_moves():
    # the seed's facing and pocket, expanded into Milltronics' own G0/G1/G2/G3 (3 decimals in mm, 4 in inch; its
    # comments in parentheses; the pocket's rounded corners as G17 arcs), read by rs274 (standard RS274 words, which
    # the Milltronics reader here does not take back: it refuses G2/G3): the moves of the LinuxCNC translation
    require_rs274()
    with open(os.path.join(ROOT, "examples", "milltronics_g33_g34.nc")) as f:
        program = f.read()
    settings = Settings(mill_tool_diameter=0.25)
    written = translate_program(program, "milltronics", settings, target="milltronics")
    assert written.splitlines()[:2] == [
        "(PROGRAM: milltronics program, cycles expanded for milltronics by freecad-groove)", "G21 G90 G40"]
    direct = translate_program(program, "milltronics", settings)
    assert same_canon_xyz(run_rs274(written, tool_table={1}, xyz=True), run_rs274(direct, tool_table={1}, xyz=True))


@pytest.mark.parametrize("to, reader", [("linuxcnc", None), ("fanuc", None)])
def test_the_grinder_example_is_written_on_the_mill_twins(to, reader):
    with open(os.path.join(ROOT, "examples", "ab9_g83.nc")) as f:
        program = f.read()
    out = translate_program(program, "ab9grind", target=to).splitlines()
    setup = {"linuxcnc": "G17 G21 G90 G91.1 G40", "fanuc": "G17 G90 G40"}[to]
    assert setup in out[:4] and ("o<dress12> call" if to == "linuxcnc" else "M98 P12") in out


def same_canon_xyz(a, b, tol=1e-3):
    assert len(a) == len(b), (len(a), len(b))
    for one, two in zip(a, b):
        assert one[0] == two[0] and all(math.isclose(p, q, abs_tol=tol) for p, q in zip(one[1:4], two[1:4])), (
            one, two)
    return True
