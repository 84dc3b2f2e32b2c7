"""``tools --to linuxcnc``: the project's tool table as a LinuxCNC lathe tool
table. LinuxCNC's own interpreter reads it, and its cutter compensation shows
where it takes each blade's control point: on the blade's reference corner."""

import subprocess
import sys

import pytest
from conftest import ROOT
from rs274 import require_rs274, run_rs274

from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.output.lathe_tools import linuxcnc_tool_table, orientation, orientation_angles
from freecad_groove.engine.tool_table import read_tool_table

# Where each blade's reference corner is, by hand (moves.GroovingTool: minus is the -Z corner for X plunges,
# the -X corner for Z plunges): the front edge cuts at low X plunging toward -X (external), high X toward +X
# (internal), low Z toward -Z (face), high Z toward +Z (back-face). (side, reference) -> (X, Z) of the corner.
CORNERS = {
    ("external", "minus"): ("low", "low"), ("external", "plus"): ("low", "high"),
    ("internal", "minus"): ("high", "low"), ("internal", "plus"): ("high", "high"),
    ("face", "minus"): ("low", "low"), ("face", "plus"): ("high", "low"),
    ("back-face", "minus"): ("low", "high"), ("back-face", "plus"): ("high", "high"),
}
# LinuxCNC's orientation figure (lathe-user.adoc) and interp_queue.cc: the control point of 1 at low X and high
# Z, 2 low X low Z, 3 high X low Z, 4 high X high Z.
Q_BY_HAND = {("low", "high"): 1, ("low", "low"): 2, ("high", "low"): 3, ("high", "high"): 4}
R = 0.02  # the blades' corner radius in the rs274 runs (inch: rs274 alone reads its tool table in inches)


def cli(*args, stdin=None):
    return subprocess.run([sys.executable, "-m", "freecad_groove", *args], cwd=ROOT, input=stdin,
                          capture_output=True, text=True, timeout=60)


@pytest.mark.parametrize("side, reference", sorted(CORNERS))
def test_each_blade_gets_the_orientation_of_its_reference_corner(side, reference):
    assert orientation(reference, side) == Q_BY_HAND[CORNERS[side, reference]]


def test_the_angles_lie_where_linuxcncs_own_sample_lathe_table_draws_each_orientation():
    # configs/sim/axis/lathe.tbl of LinuxCNC: Q1 I95 J155, Q2 I85 J25, Q3 I275 J335, Q4 I265 J205 (degrees
    # counter-clockwise from +Z, X up): a blade's square edges are those turned to the nearest axis.
    samples = {1: (95, 155), 2: (85, 25), 3: (275, 335), 4: (265, 205)}
    for q, (front, back) in samples.items():
        ours = orientation_angles(q)
        assert abs(ours[0] - front) <= 5 and abs(ours[1] - back) <= 25, (q, ours)


def _control_point(table, tool):
    """(x, z) where rs274's cutter compensation puts tool ``tool``'s control point: a pass along -Z at X0.5
    with the tip above it (G42) and one along -X at Z0 with the tip on its +Z side (G41), last feed of each."""
    along_z = ("G18 G20 G90\nT%d M6 G43\nG0 X1 Z0.5\nG42 G1 X0.5 Z0.3 F1\nG1 Z-0.5\nG1 Z-1.0\nG40 G0 X1\nM2\n"
               % tool)
    along_x = "G18 G20 G90\nT%d M6 G43\nG0 X1 Z0.5\nG41 G1 X0.8 Z0 F1\nG1 X0.6\nG1 X0.4\nG40 G0 Z1\nM2\n" % tool
    x = [m for m in run_rs274(along_z, tool_table=table) if m[0] == "G1"][-1][1]
    z = [m for m in run_rs274(along_x, tool_table=table) if m[0] == "G1"][-1][2]
    return x, z


@pytest.mark.parametrize("side, reference", sorted(CORNERS))
def test_linuxcnc_reads_the_table_and_compensates_on_the_blades_reference_corner(side, reference):
    # The tip's edge runs on the path (X0.5 / Z0) with the tip's centre r beyond it; the control point LinuxCNC
    # drives is r further on toward a high corner, r back toward a low one: X 0.5 or 0.5 + 2r, Z 0 or 2r.
    require_rs274()
    proc = cli("tools", "-", "--to", "linuxcnc", "--units", "inch",
               stdin="7 0.12 %s %s side=%s\n" % (R, reference, side))
    assert proc.returncode == 0, proc.stderr
    x, z = _control_point(proc.stdout, 7)
    corner_x, corner_z = CORNERS[side, reference]
    assert x == pytest.approx(0.5 if corner_x == "low" else 0.5 + 2 * R, abs=1e-4)
    assert z == pytest.approx(0.0 if corner_z == "low" else 2 * R, abs=1e-4)


def test_a_table_written_whole_by_hand():
    table = read_tool_table("5 3.0 0.2 minus side=external  # the cut-off\n7 2.5 0.1 plus side=internal\n", "t.tbl")
    assert linuxcnc_tool_table(table, "mm").splitlines()[1:] == [
        "T5 P5 D0.4 I90 J0 Q2 ;T5: grooving blade 3 mm, corner radius 0.2, reference minus, external",
        "T7 P7 D0.2 I270 J180 Q4 ;T7: grooving blade 2.5 mm, corner radius 0.1, reference plus, internal",
    ]


def test_the_header_names_the_tables_unit():
    table = read_tool_table("5 0.12 0.01 minus side=face\n", "t.tbl")
    assert "lengths in inch" in linuxcnc_tool_table(table, "inch").splitlines()[0]


@pytest.mark.parametrize("line, message", [
    ("5 3 0.2 minus", "1: T5: its side is not given: add side=external|internal|face|back-face"),
    ("5 3 0.2 minus side=top", "1: side=top: must be external, internal, face or back-face"),
    ("5 3 0.2 minus hand=left", "1: hand=left: unknown; the named fields are side=, dmin=, dmax=, bore=, holder="),
    ("0 3 0.2 minus side=face", "1: T=0: LinuxCNC's tool numbers are 1 to 99999 (T0 is no tool)"),
    ("100000 3 0.2 minus side=face", "1: T=100000: LinuxCNC's tool numbers are 1 to 99999"),
    ("# nothing", "0: <stdin> lists no tool: nothing to write"),
])
def test_a_table_linuxcnc_cannot_take_is_refused_in_one_line_naming_the_field(line, message):
    proc = cli("tools", "-", "--to", "linuxcnc", "--units", "mm", stdin=line + "\n")
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr.startswith("<stdin>:" + message) and len(proc.stderr.splitlines()) == 1, proc.stderr


def test_the_unit_must_be_given(tmp_path):
    proc = cli("tools", "-", "--to", "linuxcnc", stdin="5 3 0.2 minus side=face\n")
    assert proc.returncode == 2 and "--units" in proc.stderr


def test_the_cycles_read_a_table_with_sides_as_before():
    table = read_tool_table("5 3.0 0.2 minus side=external\n", "t.tbl")
    assert table[5].width == 3.0 and table.sides == {5: "external"}
    with pytest.raises(ProgramError, match="side= is given twice"):
        read_tool_table("5 3.0 0.2 minus side=external side=face\n", "t.tbl")


def test_an_output_file_is_written_whole_and_the_table_is_never_replaced(tmp_path):
    source = tmp_path / "tools.tbl"
    source.write_text("5 3 0.2 minus side=external\n")
    out = tmp_path / "linuxcnc.tbl"
    assert cli("tools", str(source), "--to", "linuxcnc", "--units", "mm", "-o", str(out)).returncode == 0
    assert out.read_text().splitlines()[1].startswith("T5 P5 D0.4 I90 J0 Q2 ;")
    proc = cli("tools", str(source), "--to", "linuxcnc", "--units", "mm", "-o", str(source))
    assert proc.returncode == 2 and source.read_text() == "5 3 0.2 minus side=external\n"
