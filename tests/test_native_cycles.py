"""expand --native-cycles: the calls written as the target's own cycle, pair by
pair, their words derived by hand; each output read back by the engine's
reader of the target's control expands (through LinuxCNC's rs274) to the
moves of the input program's own expansion, within the output's resolution.
CYCLE93 written as a pecking cycle cuts its groove in other moves (pecks
instead of CYCLE93's chip-breaking, by design, as the lathe posts write it):
there the read-back moves are derived by hand and swept through the groove's
stock by the material-removal oracle."""

import os
import re

import pytest
from conftest import ROOT
from native_helpers import BLADE, assert_reads_back, canonical, lines_after, native
from shapely.geometry import Polygon

from freecad_groove import verify as sim
from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.cycles.ab_g77 import G76, G77
from freecad_groove.engine.cycles.ab_g83 import G83, G83_1
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.fanuc_g75 import FanucG74, FanucG75, HaasG74, HaasG75
from freecad_groove.engine.cycles.milltronics import G33, G34
from freecad_groove.engine.moves import MINUS_X, MINUS_Z, MachineState


def example(name):
    with open(os.path.join(ROOT, "examples", name)) as f:
        return f.read()


FANUC = example("fanuc_g75.nc")  # G00 X62. Z-15. / G75 R0.5 / G75 X50. Z-35. P2000 Q2500 R0. F0.05
HAAS = example("haas_g75.nc")  # G00 X62. Z-15. / G75 X50. Z-30. I2. K2.5 D0. F0.05
AB9 = example("ab9_g77.nc")  # G00 X52. Z-10. / G77 X44. Z-30. I1.5 K10. F0.06 D0.  (then a cut-off with D0.5)
FANUC_CALL = "G75 R0.5 / G75 X50. Z-35. P2000 Q2500 R0. F0.05"
HAAS_CALL = "G75 X50. Z-30. I2. K2.5 D0. F0.05"
AB9_CALL = "G77 X44. Z-30. I1.5 K10. F0.06 D0."

# ----------------------------------------------------------------------------- the same family


def test_a_fanuc_g75_is_written_for_fanuc_and_gsk_with_its_retract_in_the_first_block():
    for target in ("fanuc", "gsk", "fanuc-c"):
        text = assert_reads_back(FANUC, "fanuc", target)
        blocks = lines_after(text, FANUC_CALL, 3)
        assert blocks == ["G75 R0.5", "G75 X50. Z-35. P2000 Q2500 F0.05", "N80 G00 X100. Z50."], text
        blocks = blocks[:2]
        model = FanucG75.parse("\n".join(blocks))
        assert (model.e, model.X, model.Z, model.P, model.Q, model.R, model.F) == (0.5, 50.0, -35.0, 2000, 2500,
                                                                                   None, 0.05)


def test_a_fanuc_g75_without_its_first_block_gets_the_retract_the_settings_give():
    program = FANUC.replace("N60 G75 R0.5\n", "")
    text = assert_reads_back(program, "fanuc", "fanuc", Settings(peck_retract=0.3))
    assert lines_after(text, "G75 X50. Z-35.", 2) == ["G75 R0.3", "G75 X50. Z-35. P2000 Q2500 F0.05"]


def test_a_haas_g75_is_written_for_haas_naming_setting_22():
    text = assert_reads_back(HAAS, "haas", "haas")
    assert lines_after(text, HAAS_CALL, 3) == ["(peck retract e = 0.5 mm: setting 22)",
                                               "G75 X50. Z-30. I2. K2.5 F0.05", "N70 G00 X100. Z50."], text


def test_an_allen_bradley_g77_is_written_for_ab9_naming_the_amp_parameter():
    text = assert_reads_back(AB9, "ab9", "ab9")
    blocks = lines_after(text, AB9_CALL, 2)
    assert blocks == ["(peck retract e = 0.5 mm: AMP parameter)", "G77 X44. Z-30. I1.5 K10. F0.06 D0."], text
    assert G77.parse(blocks[1]) == G77(X=44.0, Z=-30.0, I=1.5, K=10.0, F=0.06, D=0.0)
    # the cut-off shifts D0.5 at the bottom: the same family keeps it
    assert lines_after(text, "G77 X-1. I2. F0.04 D0.5", 2)[-1] == "G77 X-1. I2. F0.04 D0.5"


def test_incremental_and_radius_words_are_written_absolute_and_as_diameters():
    # from X62. Z-15. (radius 31): U-12. is the bottom at X50., W-20. the last groove at Z-35.
    program = FANUC.replace("G75 X50. Z-35.", "G75 U-12. W-20.")
    text = assert_reads_back(program, "fanuc", "fanuc")
    assert lines_after(text, "G75 U-12. W-20.", 2)[-1] == "G75 X50. Z-35. P2000 Q2500 F0.05"
    radius = HAAS.replace("G00 X62.", "G00 X31.").replace("G75 X50.", "G75 X25.").replace("I2.", "I1.")
    text = assert_reads_back(radius, "haas", "haas", start=MachineState(diameter_mode=False))
    assert lines_after(text, "G75 X25.", 2)[-1] == "G75 X50. Z-30. I1. K2.5 F0.05"


def test_cycle93_is_written_for_sinumerik_as_it_is_with_the_feed_it_cuts_at():
    seed = example("seed_cycle93.mpf")  # N20 G95 G90 F0.2: the feed in force, no F block needed
    text = assert_reads_back(seed, "sinumerik", "sinumerik")
    call = "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"
    assert lines_after(text, "CYCLE93 35, 60")[0] == call
    assert Cycle93.parse(call) == Cycle93.parse(seed)


GSK_SLOT = """%
O0012
G21 G98
G0 X50. Z5. C0.
Z0.
G07.1 C20. J-4. R2. K0.4 L2
G1 Z-10. F100.
C90.
G07.1 C0
G0 X60.
M30
%
"""


def test_a_gsk_g7_1_region_is_written_for_gsk_block_by_block():
    text = assert_reads_back(GSK_SLOT, "gsk", "gsk", rotary=True, linuxcnc="linuxcnc-c")
    assert lines_after(text, "G07.1 C20. J-4. R2. K0.4 L2 ...", 5) == [
        "G07.1 C20. J-4. R2. K0.4 L2", "G1 Z-10. F100.", "G1 C90.", "G07.1 C0", "G00 X60."]


GRINDER = example("ab9_g83.nc")


def test_g83_calls_are_written_for_the_grinder_with_every_word_absolute():
    files = {"dress12.ngc": "o<dress12> sub\no<dress12> endsub\nM2\n"}
    text = assert_reads_back(GRINDER, "ab9grind", "ab9grind", Settings(), xyz=True, files=files,
                             linuxcnc="linuxcnc")
    first = lines_after(text, "G83.1 X100. Y-0.2", 1)
    assert first == ["G83.1 X100. I0. Y-0.2 J0.1 Z30. K8. L1 F20. E3000. P12 D2"]
    assert G83_1.parse(first[0]) == G83_1(X=100.0, I=0.0, Y=-0.2, J=0.1, Z=30.0, K=8.0, L=1, F=20.0, E=3000.0,
                                          P=12, D=2)
    # G91 G83 Y-0.05 J0.02 Q0.01 L2 from Y-0.2: X, Z, K, E and P from the first call, Y-0.25 absolute,
    # F the feed in force (the G1 Y-0.2 F200. before it), I the start X (never programmed)
    second = lines_after(text, "G83 Y-0.05", 1)
    assert second == ["G83 X100. I0. Y-0.25 J0.02 Z30. K8. Q0.01 L2 F200. E3000. P12"]
    assert G83.parse(second[0]).Y == -0.25


MILL = example("milltronics_g33_g34.nc")
INCH_MILL = Settings(mill_tool_diameter=0.25)


def test_milltronics_autoroutines_are_written_with_their_d_register_and_p_blocks():
    text = assert_reads_back(MILL, "milltronics", "milltronics", INCH_MILL, xyz=True, linuxcnc="linuxcnc")
    facing = lines_after(text, "G33 G99 G41 R.1", 5)
    assert facing == ["D1", "P151=1.", "P152=3.", "P155=0.1", "G33 G99 G41 R0.1 Z-0.5 V-0.3 Q0.1 F5."]
    assert G33.parse("\n".join(facing[1:])) == G33(R=0.1, Z=-0.5, V=-0.3, Q=0.1, F=5.0, G99=True,
                                                   compensation="G41", P151=1.0, P152=3.0, P155=0.1)
    pocket = lines_after(text, "G34 G99 G41 R.1", 8)
    assert pocket == ["D1", "P150=0.25", "P151=2.", "P152=1.5", "P153=0.01", "P154=0.01", "P155=0.15",
                      "G34 G99 G41 R0.1 Z-0.4 V-0.1 Q0.15 F5."]
    assert isinstance(G34.parse("\n".join(pocket[1:])), G34)
    # G31 after a native G33: the clearance plane R0.1 the call gave the control; G32: a machine setting
    assert lines_after(text, "G31: Z0.1, the last R") == ["G31"]
    assert lines_after(text, "N18 (G32", 2) == ["(tool change position Z4.: a machine setting, "
                                             "milltronics_tool_change_inch)", "G32"]


# ----------------------------------------------------------------------------- pecking to pecking


def test_a_fanuc_g75_is_written_for_haas_and_ab9_with_their_words():
    haas = assert_reads_back(FANUC, "fanuc", "haas")
    assert lines_after(haas, FANUC_CALL, 2) == ["(peck retract e = 0.5 mm: setting 22)",
                                                "G75 X50. Z-35. I2. K2.5 F0.05"]
    assert HaasG75.parse(lines_after(haas, FANUC_CALL, 2)[1]) == HaasG75(X=50.0, Z=-35.0, I=2.0, K=2.5, F=0.05)
    ab9 = assert_reads_back(FANUC, "fanuc", "ab9")
    blocks = lines_after(ab9, FANUC_CALL, 2)
    assert blocks == ["(peck retract e = 0.5 mm: AMP parameter)", "G77 X50. Z-35. I2. K2.5 F0.05 D0."]
    assert G77.parse(blocks[1]) == G77(X=50.0, Z=-35.0, I=2.0, K=2.5, F=0.05, D=0.0)


def test_an_allen_bradley_g77_without_a_shift_is_written_for_fanuc_and_haas():
    fanuc = assert_reads_back(AB9.replace("D0.5", "D0."), "ab9", "fanuc")
    assert lines_after(fanuc, AB9_CALL, 2) == ["G75 R0.5", "G75 X44. Z-30. P1500 Q10000 F0.06"]
    assert lines_after(fanuc, "G77 X-1. I2. F0.04 D0.", 2) == ["G75 R0.5", "G75 X-1. P2000 F0.04"]
    haas = assert_reads_back(AB9.replace("D0.5", "D0."), "ab9", "haas")
    assert lines_after(haas, AB9_CALL, 2)[-1] == "G75 X44. Z-30. I1.5 K10. F0.06"


def test_a_haas_g75_is_written_for_fanuc_with_setting_22_as_its_first_block():
    text = assert_reads_back(HAAS, "haas", "fanuc", Settings(peck_retract=0.25))
    assert lines_after(text, HAAS_CALL, 2) == ["G75 R0.25", "G75 X50. Z-30. P2000 Q2500 F0.05"]


def test_a_relief_between_fanuc_and_haas_is_the_same_relief():
    # three grooves at Z-15, -17.5, -20 with a 0.3 relief toward the grooves cut: Fanuc R, Haas D
    program = FANUC.replace("Z-35. P2000 Q2500 R0.", "Z-20. P2000 Q2500 R0.3")
    text = assert_reads_back(program, "fanuc", "haas")
    assert lines_after(text, "P2000 Q2500 R0.3", 2)[-1] == "G75 X50. Z-20. I2. K2.5 D0.3 F0.05"
    haas = HAAS.replace("D0.", "D0.3")
    text = assert_reads_back(haas, "haas", "fanuc")
    assert lines_after(text, "I2. K2.5 D0.3", 2)[-1] == "G75 X50. Z-30. P2000 Q2500 R0.3 F0.05"


FACE = """%
O0003
G21
G40 G99
T0303
G97 S600 M03
G00 X30. Z2.
G74 R0.5
G74 X50. Z-6. P2500 Q2000 F0.04
G00 X100. Z50.
M30
%
"""


def test_face_grooves_go_between_g74_g76_and_haas_g74():
    # from X30. Z2.: grooves at X30, 35, 40, 45, 50 (P2500: 2.5 mm per side), 8 mm deep in pecks of 2
    ab9 = assert_reads_back(FACE, "fanuc", "ab9")
    blocks = lines_after(ab9, "G74 X50. Z-6.", 2)
    assert G76.parse(blocks[-1]) == G76(X=50.0, Z=-6.0, I=2.5, K=2.0, F=0.04, D=0.0)
    haas = assert_reads_back(FACE, "fanuc", "haas")
    assert HaasG74.parse(lines_after(haas, "G74 X50. Z-6.", 2)[-1]) == HaasG74(X=50.0, Z=-6.0, I=2.5, K=2.0, F=0.04)
    back = assert_reads_back(ab9, "ab9", "fanuc")
    model = FanucG74.parse("\n".join(lines_after(back, "G76 X50. Z-6.", 2)))
    assert (model.e, model.X, model.Z, model.P, model.Q, model.F) == (0.5, 50.0, -6.0, 2500, 2000, 0.04)


def test_a_haas_program_in_inch_keeps_four_decimals_and_counts_fanuc_words_in_ten_thousandths():
    program = HAAS.replace("G21", "G20").replace("X62.", "X2.5").replace("Z-15.", "Z-0.6") \
        .replace("X50. Z-30. I2. K2.5 D0. F0.05", "X2.0126 Z-1.2 I0.0787 K0.1 D0. F0.002")
    text = assert_reads_back(program, "haas", "fanuc", Settings(peck_retract=0.02))
    assert lines_after(text, "X2.0126 Z-1.2", 2) == ["G75 R0.02", "G75 X2.0126 Z-1.2 P787 Q1000 F0.002"]


# ----------------------------------------------------------------------------- pecking to CYCLE93

ONE_PECK = """%
O0002
G21
G40 G99
T0303
G97 S600 M03
G00 X62. Z-15.
G75 X56. P5000 F0.05
G00 X30. Z2.
G74 Z-3. Q5000 F0.05
G00 X100. Z50.
M30
%
"""


@pytest.mark.parametrize("reference, axsa, axfa", [("minus", -15, 15), ("plus", -18, 12)])
def test_one_groove_cut_in_one_peck_is_written_as_cycle93(reference, axsa, axfa):
    settings = Settings(tool=GroovingTool(3.0, 0.2, reference))
    text = assert_reads_back(ONE_PECK, "fanuc", "sinumerik", settings)
    # G75 from X62. Z-15. (radius 31) to X56. (radius 28): VRT 1, the contour at radius 30, 2 deep, the
    # blade's reference corner at Z-15: its -Z edge at Z-15 (minus) or Z-18 (plus); IDEP the peck, 5
    longitudinal = lines_after(text, "G75 X56. P5000", 2)
    assert longitudinal == ["F0.05", "CYCLE93(30, %s, 3, 2, , , , , , , , , , 5, , 1, 1)" % axsa]
    # G74 from X30. Z2. to Z-3.: VRT 1, the contour at Z1, 4 deep, the blade's -X edge at radius 15 or 12
    face = lines_after(text, "G74 Z-3. Q5000", 1)
    assert face == ["CYCLE93(%s, 1, 3, 4, 90, , , , , , , , , 5, , 2, 1)" % axfa]
    assert Cycle93.parse(face[0]).kind() == (False, True, True, False)


# ----------------------------------------------------------------------------- CYCLE93 to pecking

PLAIN = """T5 D1 S400 M03
G95 G90 F0.1
G00 X80 Z65
CYCLE93(35, 60, 3, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 1, 0)
G00 X80 Z65
CYCLE93(35, 50, 8, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 5, 0.5)
G00 X80 Z70
CYCLE93(20, 62, 3, 4, 90, 0, 0, 0, 0, 0, 0, 0, 0, 1.5, 0, 2, 0)
M02
"""
BLADE_WIDE = "CYCLE93 35, 60, 3, 5"
WIDE = "CYCLE93 35, 50, 8, 5"
FACE93 = "CYCLE93 20, 62, 3, 4"


def test_plain_cycle93_grooves_are_written_for_fanuc_as_the_posts_write_them():
    text = native(PLAIN, "sinumerik", "fanuc")
    # a blade-wide groove (TYP 1: AXSA 60 is its -Z edge): over it at VRT 1 above radius 35, X72., along Z
    # first from X80 Z65; the bottom radius 30; the peck IDEP 2; e = VRT; back the way it came
    assert lines_after(text, BLADE_WIDE, 6) == ["Z60.", "G00 X72. Z60.", "G75 R1.", "G75 X60. P2000 F0.1",
                                             "G00 X80.", "Z65."]
    # 8 wide (TYP 5: AXSA 50 is its +Z edge, Z42. to Z50.): from the first plunge at Z47. to the last at
    # Z42., stepping 95 % of (3 - 2 x 0.2) = 2.47; X71.: VRT 0.5 above radius 35
    assert lines_after(text, WIDE, 6) == ["Z47.", "G00 X71. Z47.", "G75 R0.5", "G75 X60. Z42. P2000 Q2470 F0.1",
                                       "G00 X80.", "Z65."]
    # a face groove (TYP 2, ANGC 90): the contour at Z62, the blade's -X edge at radius 20, 4 deep
    assert lines_after(text, FACE93, 6) == ["Z63.", "G00 X40. Z63.", "G74 R1.", "G74 Z58. Q1500 F0.1",
                                         "G00 X80.", "Z70."]


@pytest.mark.parametrize("target, note, call", [
    ("ab9", "(peck retract e = 0.5 mm: AMP parameter)", "G77 X60. I2. F0.1 D0."),
    ("haas", "(peck retract e = 0.5 mm: setting 22)", "G75 X60. I2. F0.1"),
    ("gsk", None, "G75 X60. P2000 F0.1"),
])
def test_plain_cycle93_grooves_are_written_for_the_other_pecking_controls(target, note, call):
    text = native(PLAIN, "sinumerik", target)
    blocks = lines_after(text, BLADE_WIDE, 6 if note else 6)
    approach = ["Z60.", "G00 X72. Z60."]
    assert blocks == ([note] if note else []) + approach + ([] if note else ["G75 R1."]) + [call, "G00 X80.", "Z65."]


@pytest.mark.parametrize("target", ["ab9", "fanuc", "haas", "gsk"])
def test_cycle93_written_as_pecking_cycles_cuts_each_groove_clean(target):
    """The read-back moves of each groove swept through its stock by the oracle: nothing left within the
    blade's reach, no gouge, no rapid into the stock."""
    text = native(PLAIN, "sinumerik", target)
    canon = canonical(text, "ab9" if target == "ab9" else target)
    starts = [(40.0, 65.0), (40.0, 65.0), (40.0, 70.0)]  # each call's CYCLE93 start point, radius
    calls = [Cycle93.parse(line) for line in PLAIN.splitlines() if line.startswith("CYCLE93")]
    at = [i for i, c in enumerate(canon) if (c[1], c[2]) in starts]
    begin = 0
    for call, start in zip(calls, starts):
        # from the arrival at the call's start point to the return to it
        begin = next(i for i in at if i >= begin and (canon[i][1], canon[i][2]) == start)
        end = next(i for i in at if i > begin and (canon[i][1], canon[i][2]) == start)
        geometry = call.geometry(BLADE)
        moves = [sim_move(c) for c in canon[begin + 1:end + 1]]
        stock = Polygon([(z, x) for x, z in geometry.stock_world()])
        result = sim.simulate(moves, BLADE.tool, call.plunge_direction(), start, stock)
        region = Polygon([(z, x) for x, z in geometry.region_world()]).buffer(0)
        verdict = sim.check_groove(result, region, BLADE.tool, tol=0.001, plunge=call.plunge_direction())
        sim.assert_clean(verdict, allow_infeasible=True)
        begin = end  # the return to it may be the next call's arrival
    assert MINUS_X == calls[0].plunge_direction() and MINUS_Z == calls[2].plunge_direction()


def sim_move(canonical_move):
    from freecad_groove.engine.moves import Move

    kind, x, z, feed, dwell = canonical_move
    return Move(kind, x, z, feed, dwell)


def test_the_pecking_calls_read_back_into_the_grooves_own_span():
    """The first groove read back from each control: it pecks from X72 to X60 at Z60 (2 mm pecks, e the
    retract) and returns to X80 Z65, as derived by hand."""
    retract = {"ab9": 0.5, "haas": 0.5, "fanuc": 1.0, "gsk": 1.0}
    for target, e in retract.items():
        canon = canonical(native(PLAIN, "sinumerik", target), target)
        index = next(i for i, c in enumerate(canon) if (c[0], c[1], c[2]) == ("G0", 36.0, 60.0))
        pecks = [("G1", 34.0), ("G0", 34.0 + e), ("G1", 32.0), ("G0", 32.0 + e), ("G1", 30.0), ("G0", 36.0)]
        got = [(c[0], round(c[1], 6)) for c in canon[index + 1:index + 7]]
        assert got == pecks, (target, got)
        assert {round(c[2], 6) for c in canon[index:index + 7]} == {60.0}
        assert [(c[0], c[1], c[2]) for c in canon[index + 7:index + 9]] == [("G0", 40.0, 60.0), ("G0", 40.0, 65.0)]


def test_cycle93_grooves_are_written_natively_when_the_tool_table_gives_the_blade():
    program = PLAIN.replace("T5 D1", "T7 D1")
    from freecad_groove.engine.tool_table import read_tool_table

    tools = read_tool_table("7 3.0 0.2 minus\n")
    text = native(program, "sinumerik", "fanuc", Settings(), tools=tools)
    assert "G75 X60. P2000 F0.1" in text


def test_without_native_cycles_every_call_is_expanded_as_before():
    from freecad_groove.engine.translator import translate_program

    for target in ("fanuc", "ab9", "sinumerik"):
        plain = translate_program(FANUC, "fanuc", BLADE, target=target)
        assert not re.search(r"^(G7[4-7]|CYCLE93)", plain, re.M) and "expanded:" not in plain
        assert "cycles expanded for %s" % target in plain


def test_cycle93_read_with_diameter_input_says_the_control_must_read_it_so():
    seed = example("seed_cycle93.mpf").replace("CYCLE93(35, 60, 30, 25,", "CYCLE93(70, 60, 30, 50,")
    settings = Settings(tool=GroovingTool(3.0, 0.2), cycle93_diameter_input=True)
    text = assert_reads_back(seed, "sinumerik", "sinumerik", settings)
    assert lines_after(text, "CYCLE93 70, 60", 2) == [
        "; CYCLE93 reads AXFA, DEPG, FAL1 and FAL2 as diameters: the control must too, --diameter-input",
        "CYCLE93(70, 60, 30, 50, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"]


def test_a_haas_g75_is_written_for_ab9_and_gsk():
    ab9 = assert_reads_back(HAAS, "haas", "ab9")
    assert G77.parse(lines_after(ab9, HAAS_CALL, 2)[1]) == G77(X=50.0, Z=-30.0, I=2.0, K=2.5, F=0.05, D=0.0)
    gsk = assert_reads_back(HAAS, "haas", "gsk")
    model = FanucG75.parse("\n".join(lines_after(gsk, HAAS_CALL, 2)))
    assert (model.e, model.X, model.Z, model.P, model.Q, model.F) == (0.5, 50.0, -30.0, 2000, 2500, 0.05)


def test_an_allen_bradley_plunge_in_one_peck_is_written_as_cycle93():
    # from X52. Z-10. (radius 26) to X47. (23.5): one peck of 3 >= 2.5; VRT 1, the contour at radius 25;
    # the call's F becomes the feed in force CYCLE93 cuts at
    program = AB9.replace("G77 X44. Z-30. I1.5 K10. F0.06 D0.", "G77 X47. I3. F0.06 D0.")
    text = assert_reads_back(program, "ab9", "sinumerik")
    assert lines_after(text, "G77 X47. I3.", 2) == ["F0.06", "CYCLE93(25, -10, 3, 1.5, , , , , , , , , , 3, , 1, 1)"]
