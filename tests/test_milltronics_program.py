"""Reading Milltronics programs (--dialect milltronics): P assignment blocks, the G33/G34
autoroutines with G99 and G41/G42 in their block, G31/G32, inch and metric, LinuxCNC through rs274."""

import re
import subprocess
import sys
from pathlib import Path

import pytest
from rs274 import require_rs274, run_rs274

from freecad_groove.engine.cycles.milltronics import G33, G34
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.mill_tool_table import read_mill_tool_table
from freecad_groove.engine.moves import MachineState
from freecad_groove.engine.settings import DEFAULT_SETTINGS, Settings
from freecad_groove.engine.translator import translate_program

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "milltronics_g33_g34.nc"
QUARTER = Settings(mill_tool_diameter=0.25)
SEED = """N1 G20 G90
N3 G0 X1 Y2 Z1.
N4 F20
N5 P151=1
N6 P152=3
N7 P155=.1
N8 G33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5
N9 M30
"""


def test_the_seed_program_expands_to_the_engine_moves_in_the_xy_plane():
    lines = translate_program(SEED, "milltronics", QUARTER, target="linuxcnc").splitlines()
    assert lines[1] == "G17 G21 G90 G91.1 G40 G94"  # feed per minute: a mill's programs have no G94
    assert lines[2:9] == ["N1 G20", "N3 G0 X1. Y2. Z1.", "N4 F20.",
                          "N5 (P151=1: for the G33/G34 that follow)", "N6 (P152=3: for the G33/G34 that follow)",
                          "N7 (P155=.1: for the G33/G34 that follow)", "N8 (G33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5)"]
    assert lines[9:13] == ["X1.375 Y3.375", "Z0.1", "G1 Z-0.3 F5.", "Y0.625 F20."]
    assert lines[-2:] == ["G0 Z0.1", "N9 M2"]


def test_the_seed_program_runs_in_linuxcnc_as_the_engine_moves():
    require_rs274()
    canon = run_rs274(translate_program(SEED, "milltronics", QUARTER, target="linuxcnc"), xyz=True)
    model = G33.parse("P151=1\nP152=3\nP155=.1\nG33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5")
    moves = model.expand(MachineState(x=1.0, y=2.0, z=1.0, feed=20.0, metric=False, diameter_mode=False), QUARTER)
    # canon[0] is the G0 to X1 Y2 Z1 (rs274 reports in the program's inches)
    assert [c[0] for c in canon[1:]] == [m.kind for m in moves]
    for c, m in zip(canon[1:], moves):  # the inch output has 4 decimals (X1.28125 is written X1.2812)
        assert c[1:4] == pytest.approx((m.x, m.y, m.z), abs=6e-5)


def test_the_example_program_runs_in_linuxcnc_and_every_move_stays_in_its_rectangles():
    require_rs274()
    proc = subprocess.run([sys.executable, "-m", "freecad_groove", "expand", str(EXAMPLE), "--dialect", "milltronics",
                           "--tool-diameter", "0.25", "--to", "linuxcnc"], cwd=ROOT, capture_output=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    canon = run_rs274(proc.stdout.decode(), xyz=True, tool_table=[1])  # T1 M6, G43 H1: tool 1 in the table
    inch = [c[:4] for c in canon]
    assert inch[0] == ("G0", 1.0, 2.0, 0.0)  # N3 G0 X1 Y2: X and Y alone (the seed as printed has no Z)
    cuts = [c for c in inch if c[3] < -1e-9]
    assert min(c[3] for c in cuts) == pytest.approx(-0.5)
    for _, x, y, _ in cuts:  # the facing (centre X1 Y2, 1 x 3) or the pocket (centre X4 Y2, 2 x 1.5)
        in_face = abs(x - 1) <= 0.375 + 1e-6 and abs(y - 2) <= 1.375 + 1e-6
        in_pocket = abs(x - 4) <= 0.875 + 1e-6 and abs(y - 2) <= 0.625 + 1e-6
        assert in_face or in_pocket
    assert inch[-1][3] == pytest.approx(4.0)  # G32: the tool change Z (default 4")


def test_g31_goes_to_the_last_r_else_the_setting_and_g32_to_the_tool_change_setting():
    text = "G21 G90\nG0 X0 Y0 Z50.\nG31\nG0 Z20.\nG32\nM30\n"
    settings = Settings(milltronics_tool_change_inch=2.0)
    lines = translate_program(text, "milltronics", settings, target="linuxcnc").splitlines()
    # metric program: 0.1" = 2.54 mm, 2" = 50.8 mm; the comment shows the Z used
    assert lines[4:8] == ["(G31: Z2.54, setting milltronics_clearance_inch)", "Z2.54", "G0 Z20.",
                          "(G32: Z50.8, setting milltronics_tool_change_inch)"]
    after_r = SEED.replace("N9 M30", "G0 Z2.\nG31\nM30")
    lines = translate_program(after_r, "milltronics", QUARTER, target="linuxcnc").splitlines()
    assert lines[-3:] == ["(G31: Z0.1, the last R)", "Z0.1", "M2"]


def test_the_p_parameters_stay_in_force_for_the_next_call_and_r_too():
    text = SEED.replace("N9 M30", "G0 X1 Y2\nG33 Z-.1 V-.1\nM30")
    lines = translate_program(text, "milltronics", QUARTER, target="linuxcnc").splitlines()
    second = lines[lines.index("(G33 Z-.1 V-.1)") + 1:]
    # the same rectangle (P151, P152, P155 in force), R.1 from the first call, no G99: the lift at the end
    assert second[:3] == ["X1.375 Y3.375", "G1 Z-0.1", "Y0.625"]  # Z feed: the X-Y feed in force
    assert second[-2:] == ["G0 Z0.", "M2"]


def test_a_metric_pocket_program():
    text = ("G21 G90\nG0 X0 Y0 Z5.\nF300\nP151=40\nP152=30\nP155=5\nP150=8\nG34 G99 G42 R2. Z-3. V-1.5 Q1.5 F100\n"
            "M30\n")
    lines = translate_program(text, "milltronics", Settings(mill_tool_diameter=10.0), target="linuxcnc").splitlines()
    model = G34.parse("P151=40\nP152=30\nP155=5\nP150=8\nG34 G99 G42 R2. Z-3. V-1.5 Q1.5 F100")
    moves = model.expand(MachineState(x=0.0, y=0.0, z=5.0, feed=300.0, diameter_mode=False),
                         Settings(mill_tool_diameter=10.0))
    assert "G1 Z-1.5 F100." in lines and "G1 Z-3. F100." in lines
    assert lines[-2] == "G0 Z2." and moves[-1].z == 2.0


@pytest.mark.parametrize("text, message", [
    ("G0 X0 Y0 Z1.\nG99\n", r"2: G99: only a cycle's block \(G33/G34/G31/G32\) may hold it"),
    ("G0 X0 Y0 Z1.\nG41 X1\n", "2: G41: only a cycle's block"),
    ("G0 X0 Y0 Z1.\nP151=1 X2\n", "2: P151=1: a parameter assignment stands alone in its block"),
    ("G0 X0 Y0 Z1.\nP149=1\n", r"2: P149=1: not a parameter of the Milltronics cycles \(P150, P151"),
    ("G0 X0 Y0 Z1.\nG43\n", "2: G43 without H: program the tool length offset as G43 H<n>"),
    ("T1\n", "1: T1 without M6: a tool selected for a later change is not translated; program the tool change "
              "as T1 M6 in one block"),
    ("M6\n", "1: M6 without T: program the tool change as T<n> M6 in one block"),
    ("T0 M6\n", "1: T0: the tool number must be 1 or more"),
    ("S1000 M3 H1\n", r"1: H1 without G43: program the tool length offset as G43 H<n>"),
    ("G49 H1\n", r"1: H1 without G43"),
    ("D1.5\n", "1: D1.5 must be a whole number"),
    ("G0 X0 Y0 Z1.\nF20\nP151=1\nP152=1\nP155=.1\nG33 R.1 Z-.1 V-.1\n",
     "6: G33 tool diameter: is not known: give the end mill's diameter"),
    ("G0 X0 Y0 Z1.\nF20\nP151=1\nP152=1\nP155=.3\nG34 R.1 Z-.1 V-.1\n",
     r"6: G34 P155=0.3: the cut width is larger than the tool \(diameter 0.25\)"),
    ("G0 X0 Y0 Z1.\nF20\nP152=1\nP155=.1\nG33 R.1 Z-.1 V-.1\n", r"5: G33 P151: must be given"),
    ("G0 X0 Y0 Z1.\nF20\nP151=1\nP152=1\nP155=.1\nG33 G0 R.1 Z-.1 V-.1\n", "6: G0 shares the block with the cycle"),
    ("G0 X0 Y0 Z1.\nG31 X1\n", "2: G31 X=1: is not a word of G31"),
    ("G0 X0 Y0 Z1.\nF20\nP151=1\nP152=1\nP155=.1\nG91 G33 R.1 Z-.1 V-.1\n",
     "6: G33 G91: R, Z and V are read as absolute Z: program the autoroutine in G90"),
    ("G0 X0 Y0 Z1.\nF20\nP151=1\nP152=1\n/P155=.1\nG33 R.1 Z-.1 V-.1\n",
     "6: the P parameters and the clearance plane R G33 runs with depends on a block-delete '/' line"),
])
def test_errors_name_the_line_and_the_rule(text, message):
    settings = QUARTER if "tool diameter" not in message else Settings()
    line, message = message.split(": ", 1)
    with pytest.raises(ProgramError, match=message) as raised:
        translate_program("G20 G90\n" + text + "M30\n", "milltronics", settings, target="linuxcnc")
    assert raised.value.line == int(line) + 1


def test_the_command_line_refuses_a_broken_program_in_one_line(tmp_path):
    program = tmp_path / "bad.nc"
    program.write_text("G20 G90\nG0 X0 Y0 Z1.\nF20\nP151=1\nP152=1\nP155=.1\nG33 R.1 Z-.1 V-.2\nM30\n")
    proc = subprocess.run([sys.executable, "-m", "freecad_groove", "expand", str(program), "--dialect", "milltronics",
                           "--tool-diameter", "0.25", "--to", "fanuc"], cwd=ROOT, capture_output=True, timeout=120)
    assert proc.returncode != 0 and proc.stdout == b""
    assert proc.stderr.decode().strip().splitlines() == [
        "%s:7: G33 V=-0.2: the first depth is below the final depth Z-0.1" % program]


def _emit(*args):
    return subprocess.run([sys.executable, "-m", "freecad_groove", "emit", *args], cwd=ROOT, capture_output=True,
                          timeout=120)


def test_emit_takes_the_p_parameters_as_options_and_writes_their_blocks_before_the_call():
    seed = ["--p151", "1", "--p152", "3", "--p155", ".1", "-R", ".1", "-Z", "-.5", "-V", "-.3", "-Q", ".1", "-F", "5"]
    proc = _emit("g33", *seed)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.decode().splitlines() == ["P151=1.", "P152=3.", "P155=0.1", "G33 R0.1 Z-0.5 V-0.3 Q0.1 F5."]
    proc = _emit("g34", "--p150", ".25", "--p151", "2", "--p152", "1.5", "--p155", ".15", "-R", ".1", "-Z", "-.4",
                 "-Q", ".15")
    assert proc.stdout.decode().splitlines()[0] == "P150=0.25" and proc.returncode == 0
    # the rules see them: a cut width over the tool's diameter; --expand runs the seed's facing
    seed[5] = ".3"
    proc = _emit("g33", *seed, "--tool-diameter", ".25")
    assert proc.returncode == 2 and proc.stdout == b""
    assert proc.stderr.decode().strip() == ("emit milltronics-g33:1: G33 P155=0.3: the cut width is larger than the "
                                            "tool (diameter 0.25): ridges would be left")
    seed[5] = ".1"
    proc = _emit("g33", *seed, "--tool-diameter", ".25", "--expand", "--start-x", "1", "--start-y", "2", "--start-z",
                 "1", "--feed", "20", "--units", "inch", "--feed-mode", "min")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.decode().splitlines()[3:5] == ["X1.375 Y3.375", "Z0.1"]  # the upper right corner first
    assert _emit("g31", "--p151", "1").returncode == 2  # G31 reads no P parameter: no option


@pytest.mark.parametrize("cycle, words", [
    ("g33", ["--p151", "1", "--p152", "3", "--p155", ".1"]),
    ("g34", ["--p150", ".25", "--p151", "2", "--p152", "1.5", "--p155", ".15"]),
])
def test_emit_expand_runs_g33_and_g34_from_the_height_the_tool_is_at_without_start_z(cycle, words):
    # as in a whole program (seed 004's N3 G0 X1 Y2, no Z): X Y at the height held, then Z down to R; no Z is
    # written before the cycle's own R rapid
    require_rs274()
    proc = _emit(cycle, *words, "-R", ".1", "-Z", "-.4", "-Q", ".15", "-F", "5", "--tool-diameter", ".25",
                 "--expand", "--start-x", "1", "--start-y", "2", "--feed", "20", "--units", "inch",
                 "--feed-mode", "min")
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.decode().splitlines()
    assert lines[2] == "G0 X1. Y2."
    first_z = next(i for i, line in enumerate(lines) if i > 0 and "Z" in line)
    assert lines[first_z] == "Z0.1" and "G1" not in " ".join(lines[3:first_z])  # rapids in X Y, then to R
    moves = run_rs274(proc.stdout.decode(), xyz=True)
    assert min(move[3] for move in moves) == pytest.approx(-0.4)  # the final depth Z, reached
    assert _emit("g77", "-X", "40.", "-Z", "-30.", "-I", "2.", "-K", "5.", "-D", "0", "-F", "0.08", "--expand",
                 "--start-x", "50").returncode == 2  # a lathe cycle still needs its start Z


# ---------------------------------------------------------------- the end mill's diameter by D number

MILL_TABLE = "# D  diameter\n1  0.25\n2  0.125   # a 1/8\" end mill\n"
BY_D = """G20 G90
G0 X1 Y2 Z1.
S1000 M3 %s
F20
P151=1
P152=3
P155=.1
G33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5
M30
"""


def _first_corner(text, settings=DEFAULT_SETTINGS, tools=None):
    """The first X Y of the G33's moves (the upper right corner less the tool radius) and the G33's comment."""
    lines = translate_program(text, "milltronics", settings, target="linuxcnc", tools=tools).splitlines()
    at = next(i for i, line in enumerate(lines) if line.startswith("(G33"))
    return lines[at + 1], lines[at]


def test_a_tool_table_gives_the_diameter_of_the_d_in_force():
    table = read_mill_tool_table(MILL_TABLE, "mill.tbl")
    assert table == {1: 0.25, 2: 0.125} and table.source == "mill.tbl"
    corner, title = _first_corner(BY_D % "D2", tools=table)
    assert corner == "X1.4375 Y3.4375"  # 1 + 0.5 - 0.0625
    assert title == "(G33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5: tool diameter 0.125, D2 of mill.tbl)"
    assert _first_corner(BY_D % "D1", tools=table)[0] == "X1.375 Y3.375"
    lines = translate_program(BY_D % "D2", "milltronics", Settings(), target="linuxcnc", tools=table).splitlines()
    assert "S1000 M3 (D2: the diameter register of the G33/G34 that follow)" in lines
    # a D the table does not list, or no D: --tool-diameter; else refused naming what to give
    assert _first_corner(BY_D % "D7", QUARTER, table)[0] == "X1.375 Y3.375"
    assert _first_corner(BY_D % "", Settings(mill_tool_diameter=0.125), table)[0] == "X1.4375 Y3.4375"
    with pytest.raises(ProgramError, match=r"^G33: the tool diameter is unknown: D7 is not in the tool table mill.tbl"):
        translate_program(BY_D % "D7", "milltronics", Settings(), target="linuxcnc", tools=table)
    with pytest.raises(ProgramError, match="no D is programmed before it, so the tool table mill.tbl cannot give it"):
        translate_program(BY_D % "", "milltronics", Settings(), target="linuxcnc", tools=table)
    with pytest.raises(ProgramError, match="the tool diameter of G33 depends on a block-delete '/' line"):
        translate_program(BY_D.replace("S1000 M3 %s", "D1\n/D2"), "milltronics", Settings(), target="linuxcnc",
                          tools=table)


@pytest.mark.parametrize("text, message", [
    ("1 0.25 x\n", "1: 3 fields: a line holds D and diameter"),
    ("1.5 0.25\n", "1: D=1.5: must be a whole number, 0 or more"),
    ("1 0\n", "1: diameter=0: must be a number greater than 0"),
    ("1 nan\n", "1: diameter=nan: must be a number greater than 0"),
    ("1 .25\n\n1 .5\n", "3: D=1: is in the table twice"),
])
def test_the_mill_tool_table_rules(text, message):
    line, message = message.split(": ", 1)
    with pytest.raises(ProgramError, match=re.escape(message)) as raised:
        read_mill_tool_table(text, "mill.tbl")
    assert raised.value.line == int(line)


def test_the_command_line_reads_a_mill_tool_table_for_a_milltronics_program(tmp_path):
    program, table = tmp_path / "by_d.nc", tmp_path / "mill.tbl"
    program.write_text(BY_D % "D2")
    table.write_text(MILL_TABLE)
    proc = subprocess.run([sys.executable, "-m", "freecad_groove", "expand", str(program), "--dialect", "milltronics",
                           "--tool-table", str(table), "--to", "linuxcnc"], cwd=ROOT, capture_output=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "X1.4375 Y3.4375" in proc.stdout.decode().splitlines()
    table.write_text("2 0.125 minus\n")
    proc = subprocess.run([sys.executable, "-m", "freecad_groove", "expand", str(program), "--dialect", "milltronics",
                           "--tool-table", str(table)], cwd=ROOT, capture_output=True, timeout=120)
    assert proc.returncode != 0 and proc.stdout == b""
    assert proc.stderr.decode().strip() == "%s:1: 3 fields: a line holds D and diameter (e.g. '1 0.25')" % table


# the milltronics_mill post's form of a tool change (the seed's D1 G43 H1), with the G32 before it
TOOL_CHANGES = """G20 G90
G32
T1 M6
S3000 M3
D1 G43 H1
G0 X1 Y2 Z1.
F20
P151=1
P152=3
P155=.1
G33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5
G31
G32
T2 M6
S2000 M3
D2 G43 H2
G0 X3 Y2 Z1.
G49
M30
"""
TWO_TOOLS = "1 0.25\n2 0.5\n"


def _tool_lines(target):
    """The translation around the G33's moves: up to its call, and from the G31 after it."""
    tools = read_mill_tool_table(TWO_TOOLS, "tools.tbl")
    lines = translate_program(TOOL_CHANGES, "milltronics", Settings(), target=target, tools=tools).splitlines()
    call = next(at for at, line in enumerate(lines) if line.startswith("(G33"))
    return lines[:call], lines[lines.index("(G31: Z0.1, the last R)"):]


def test_tool_changes_and_length_offsets_are_written_for_linuxcnc_and_rs274_runs_them():
    head, tail = _tool_lines("linuxcnc")
    assert head[2:] == [
        "G20", "(G32: Z4., setting milltronics_tool_change_inch)", "G0 Z4.",  # at the start: Z alone
        "T1 M6", "S3000 M3", "G43 H1 (D1: the diameter register of the G33/G34 that follow)", "G0 X1. Y2. Z1.",
        "F20.", "(P151=1: for the G33/G34 that follow)", "(P152=3: for the G33/G34 that follow)",
        "(P155=.1: for the G33/G34 that follow)"]
    assert tail == [
        "(G31: Z0.1, the last R)", "(G32: Z4., setting milltronics_tool_change_inch)", "Z4.",
        "T2 M6", "S2000 M3", "G43 H2 (D2: the diameter register of the G33/G34 that follow)", "G0 X3. Y2. Z1.",
        "G49", "M2"]
    require_rs274()
    tools = read_mill_tool_table(TWO_TOOLS, "tools.tbl")
    text = translate_program(TOOL_CHANGES, "milltronics", Settings(), target="linuxcnc", tools=tools)
    canon = run_rs274(text, xyz=True, tool_table=[1, 2])
    assert canon[0][0] == "G0" and canon[0][3] == pytest.approx(4.0)  # the G32 before any X Y
    assert canon[-2][1:4] == pytest.approx(canon[-3][1:3] + (4.0,))  # G32 after the cut: Z alone, X Y held
    assert canon[-1][1:4] == pytest.approx((3.0, 2.0, 1.0))


def test_tool_changes_and_length_offsets_are_written_for_fanuc():
    head, tail = _tool_lines("fanuc")
    assert head[4:11] == [
        "G20", "(G32: Z4., setting milltronics_tool_change_inch)", "G00 Z4.",
        "T01 M06", "S3000 M03", "G43 H1 (D1: the diameter register of the G33/G34 that follow)", "G00 X1. Y2. Z1."]
    assert tail == [
        "(G31: Z0.1, the last R)", "(G32: Z4., setting milltronics_tool_change_inch)", "Z4.",
        "T02 M06", "S2000 M03", "G43 H2 (D2: the diameter register of the G33/G34 that follow)", "G00 X3. Y2. Z1.",
        "G49", "M30", "%"]


def test_after_a_tool_change_the_position_is_unknown():
    text = "G20 G90\nG0 X0 Y0 Z1.\nT1 M6\nF20\nP151=1\nP152=1\nP155=.1\nG33 R.1 Z-.1 V-.1\nM30\n"
    with pytest.raises(ProgramError, match="G33 needs its start point: program an absolute X and Y before") as raised:
        translate_program(text, "milltronics", QUARTER, target="linuxcnc")
    assert raised.value.line == 8


def test_a_tool_change_keeps_the_diameter_register_in_force():
    # T selects the tool, D the diameter register: without a D after T2 M6 the G33 still cuts with D1's 0.25
    text = ("G20 G90\nD1\nT2 M6\nG0 X1 Y2 Z1.\nF20\nP151=1\nP152=3\nP155=.1\nG33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5\n"
            "M30\n")
    tools = read_mill_tool_table(TWO_TOOLS, "tools.tbl")
    lines = translate_program(text, "milltronics", Settings(), target="linuxcnc", tools=tools).splitlines()
    assert "(G33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5: tool diameter 0.25, D1 of tools.tbl)" in lines


def test_a_pocket_with_rounded_corners_runs_in_linuxcnc_with_the_engine_arcs():
    require_rs274()
    text = ("G21 G90\nG0 X0 Y0 Z5.\nF300\nP151=40\nP152=30\nP155=5\nP150=8\nG34 G99 G42 R2. Z-3. V-1.5 Q1.5 F100\n"
            "M30\n")
    canon = run_rs274(translate_program(text, "milltronics", Settings(mill_tool_diameter=10.0), target="linuxcnc"),
                      xyz=True)
    model = G34.parse("P151=40\nP152=30\nP155=5\nP150=8\nG34 G99 G42 R2. Z-3. V-1.5 Q1.5 F100")
    moves = model.expand(MachineState(x=0.0, y=0.0, z=5.0, feed=300.0, diameter_mode=False),
                         Settings(mill_tool_diameter=10.0))
    assert [c[0] for c in canon[1:]] == [m.kind for m in moves]
    assert {"G2"} <= {c[0] for c in canon}  # G42: clockwise laps, their corners G2
    for c, m in zip(canon[1:], moves):
        assert c[1:4] == pytest.approx((m.x, m.y, m.z), abs=1e-4)
        assert c.centre == (None if m.centre is None else pytest.approx(m.centre, abs=2e-4))
