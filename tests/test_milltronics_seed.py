"""The Milltronics manual's own facing program (seed 004), as printed, and G33/G34 from an unknown Z (issue 20,
item 1). The seed's program has no Z before its G33: ``G43 H1`` (Z unknown) and ``G0 X1 Y2``. The control
rapids to the start corner and down to the clearance plane R, both absolute; the expansion does the same
(X Y at the height the tool is at, then Z to R); only G98, which returns to that unknown Z, is refused."""

import subprocess
import sys
from pathlib import Path

import pytest
from rs274 import require_rs274, run_rs274
from shapely.geometry import box
from test_milltronics import inside, swept

from freecad_groove.engine.cycles.milltronics import G33, G34
from freecad_groove.engine.errors import CycleError, ProgramError
from freecad_groove.engine.moves import FEED, RAPID, MachineState
from freecad_groove.engine.settings import Settings
from freecad_groove.engine.translator import translate_program

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "milltronics_g33_g34.nc"
QUARTER = Settings(mill_tool_diameter=0.25)
# Seed 004, "Facing Cycle Program", copied line by line from the page (its "FS" is a scan of "F5")
AS_PRINTED = [
    "N1 G20 G90 (inch/absolute)",
    "N2 S1000 M3 D1 G43 H1 (spindle CW1000 RPM, calls tool #1's offsets)",
    "N3 G0 X1 Y2 (rapid to the center of the pocket)",
    "N4 F20 (X-Y feedrate)",
    "N5 P151=1 (X dimension)",
    "N6 P152=3 (Y dimension)",
    "N7 P155=.1 (cut width)",
    "N8 G33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5",
]
SEED = "\n".join(AS_PRINTED + ["M30"]) + "\n"
BLOCK = "P151=1\nP152=3\nP155=.1\nG33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5"


def unknown_z(x=1.0, y=2.0, feed=20.0):
    return MachineState(x=x, y=y, z=None, feed=feed, diameter_mode=False, metric=False)


def test_the_example_file_begins_with_the_seeds_facing_program_as_printed():
    assert EXAMPLE.read_text().splitlines()[:8] == AS_PRINTED


def test_the_seed_program_as_printed_rapids_x_y_at_the_height_held_then_z_to_r():
    lines = translate_program(SEED, "milltronics", QUARTER, target="linuxcnc").splitlines()
    at = lines.index("N8 (G33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5)")
    # by hand: the upper right corner inset by the tool radius .125: X1 + .5 - .125, Y2 + 1.5 - .125; G0 from N3
    assert lines[at + 1:at + 5] == ["X1.375 Y3.375", "Z0.1", "G1 Z-0.3 F5.", "Y0.625 F20."]
    assert lines[-2:] == ["G0 Z0.1", "M2"]  # G99: back to R


def test_the_engine_from_an_unknown_z_moves_x_y_first_with_z_held():
    moves = G33.parse(BLOCK).expand(unknown_z(), QUARTER)
    assert moves[0] == (RAPID, 1.375, None, None, 0.0, 3.375, None, None, None)  # Z None: held
    assert (moves[1].kind, moves[1].x, moves[1].y, moves[1].z) == (RAPID, 1.375, 3.375, 0.1)
    assert (moves[2].kind, moves[2].z, moves[2].f) == (FEED, -0.3, 5.0)
    known = G33.parse(BLOCK).expand(MachineState(x=1.0, y=2.0, z=1.0, feed=20.0, diameter_mode=False,
                                                 metric=False), QUARTER)
    assert moves[1:] == known[1:]  # the rest as from a known Z above R


def test_a_pocket_from_an_unknown_z_goes_down_to_r_at_its_centre():
    text = "P151=1\nP152=1.5\nP155=.1\nG34 G99 R.1 Z-.1 V-.1"
    moves = G34.parse(text).expand(unknown_z(), QUARTER)
    assert (moves[0].kind, moves[0].x, moves[0].y, moves[0].z) == (RAPID, 1.0, 2.0, 0.1)  # already over it
    assert (moves[1].kind, moves[1].z) == (FEED, -0.1)


@pytest.mark.parametrize("cycle, text", [(G33, BLOCK.replace("G99", "G98")),
                                         (G34, "P151=1\nP152=1.5\nP155=.1\nG34 G98 R.1 Z-.1 V-.1")])
def test_g98_from_an_unknown_z_is_refused_naming_g98(cycle, text):
    with pytest.raises(CycleError, match=r"^%s G98: returns to the Z before the call, which is not known"
                       % cycle.NAME):
        cycle.parse(text).expand(unknown_z(), QUARTER)


def test_g98_from_a_known_z_returns_there_and_g98_with_g99_is_refused():
    moves = G33.parse(BLOCK.replace("G99", "G98")).expand(
        MachineState(x=1.0, y=2.0, z=1.5, feed=20.0, diameter_mode=False, metric=False), QUARTER)
    assert (moves[-1].kind, moves[-1].z) == (RAPID, 1.5)
    model = G33.parse(BLOCK.replace("G99", "G98"))
    assert model.emit().endswith("G33 G98 G41 R0.1 Z-0.5 V-0.3 Q0.1 F5.") and G33.parse(model.emit()) == model
    with pytest.raises(CycleError, match=r"G33 G99: G98 and G99 in one block"):
        G33.parse(BLOCK.replace("G99", "G98 G99"))


def test_a_program_with_g98_and_no_z_is_refused_on_the_call_line():
    with pytest.raises(ProgramError, match=r"G33 G98: returns to the Z before the call") as raised:
        translate_program(SEED.replace("G99", "G98"), "milltronics", QUARTER, target="linuxcnc")
    assert raised.value.line == 8


def test_rs274_runs_the_seed_as_printed_and_the_tool_faces_the_rectangle_at_every_depth():
    require_rs274()
    canon = run_rs274(translate_program(SEED, "milltronics", QUARTER, target="linuxcnc"), xyz=True,
                      tool_table=[1])
    moves = G33.parse(BLOCK).expand(unknown_z(), QUARTER)
    # canon[0] is N3's G0 X1 Y2 at the Z rs274 starts at; the engine's first move holds that Z
    held = canon[0][3]
    assert [c[0] for c in canon[1:]] == [m.kind for m in moves]
    for c, m in zip(canon[1:], moves):
        assert c[1:4] == pytest.approx((m.x, m.y, held if m.z is None else m.z), abs=6e-5)
    # the simulation: what rs274 ran covers the rectangle at every depth and never leaves it
    ran = [type("Ran", (), {"kind": c[0], "x": c[1], "y": c[2], "z": round(c[3], 6)}) for c in canon]
    rounded = box(0.5, 0.5, 1.5, 3.5).buffer(-0.125).buffer(0.125, quad_segs=64)  # corners at the tool radius
    scallop = 0.125 - (0.125 ** 2 - (0.1 / 2) ** 2) ** 0.5  # between passes of at most P155 .1
    assert sorted({c.z for c in ran if c.kind == FEED}) == [-0.5, -0.4, -0.3]
    for depth in (-0.3, -0.4, -0.5):
        area = swept(ran, depth, 0.125)
        assert rounded.buffer(-scallop - 1e-4).difference(area).area < 1e-7
    assert inside([c for c in ran if c.z < 0], 1, 2, 0.5, 1.5, 0.0, 0.125)


def test_the_example_runs_as_printed_from_the_command_line_and_in_rs274():
    require_rs274()
    proc = subprocess.run([sys.executable, "-m", "freecad_groove", "expand", str(EXAMPLE), "--dialect", "milltronics",
                           "--tool-diameter", "0.25", "--to", "linuxcnc"], cwd=ROOT, capture_output=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    canon = run_rs274(proc.stdout.decode(), xyz=True, tool_table=[1])
    assert canon[0][:4] == ("G0", pytest.approx(1.0), pytest.approx(2.0), pytest.approx(0.0))  # N3: X Y only
    assert canon[1][:4] == ("G0", pytest.approx(1.375), pytest.approx(3.375), pytest.approx(0.0))
    assert canon[2][:4] == ("G0", pytest.approx(1.375), pytest.approx(3.375), pytest.approx(0.1))
