"""The command line's verify and plot: every example verifies and plots;
hand-written G1 gouges and G0 collisions name their line and exit 1;
hand-derived figures of one rectangular groove; bad input exits 2 with one
line; the picture is a valid SVG/PNG written atomically; arcs as chords."""

import glob
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest
from conftest import IN_CI, ROOT

from freecad_groove.engine.settings import DEFAULT_SETTINGS
from freecad_groove.verify.program_check import check_program, report
from freecad_groove.verify.program_record import ARC_CHORD_TOL, arc_chords, radius_centre, record_program

EXAMPLES = os.path.join(ROOT, "examples")
TOOLS = os.path.join(EXAMPLES, "tools.tbl")
# Each example program: its dialect and blade (the comments in the programs say which blade they use).
EXAMPLE_OPTIONS = {
    "ab9_g77.nc": ["--dialect", "ab9", "--tool-width", "3"],
    "fanuc_g75.nc": ["--dialect", "fanuc", "--tool-width", "3"],
    "haas_g75.nc": ["--dialect", "haas", "--tool-width", "3"],
    "seed_cycle93.mpf": ["--dialect", "sinumerik", "--tool-table", TOOLS],
}
# Mill-style examples (a grinder's X/Y/Z): verify and plot refuse them with one line (no turned section)
MILL_EXAMPLES = {"ab9_g83.nc": ["--dialect", "ab9grind"],
                 "milltronics_g33_g34.nc": ["--dialect", "milltronics", "--tool-diameter", "0.25"]}
SHARP_3MM = ["--dialect", "fanuc", "--tool-width", "3", "--tool-radius", "0"]

# One groove 3 mm wide, 5 mm deep per side (X50 -> X40 at Z-10), pecked in
# 1 mm steps without retracts, 0.1 mm/rev at 500 rpm.
GROOVE = """O1000
N10 G21
N20 G99
N30 T0303
N40 G97 S500 M03
N50 G00 X50. Z-10.
N60 G75 R0.
N70 G75 X40. P1000 F0.1
{extra}N80 G00 X100. Z50.
N90 M30
"""


# Run the command line as if ``package`` were not installed (the error a missing module raises).
BLOCK_PACKAGE = """import sys
class Missing:
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] == %r:
            raise ModuleNotFoundError("No module named %%r" %% name, name=name)
sys.meta_path.insert(0, Missing())
from freecad_groove.cli import main
sys.exit(main(sys.argv[1:]))
"""


def run(*args, env=None):
    return subprocess.run([sys.executable, "-m", "freecad_groove", *args], cwd=ROOT, capture_output=True,
                          timeout=300, env=env)


def needs_matplotlib():
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        if IN_CI:
            raise
        pytest.skip("matplotlib is not installed (requirements-test.txt pins it)")


def write(tmp_path, text, name="part.nc"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_every_example_is_listed():
    programs = {os.path.basename(p) for p in glob.glob(os.path.join(EXAMPLES, "*")) if not p.endswith(".tbl")}
    assert programs == set(EXAMPLE_OPTIONS) | set(MILL_EXAMPLES) | {"gsk_g7_1.nc"}


@pytest.mark.parametrize("command", ["verify", "plot"])
@pytest.mark.parametrize("name", sorted(MILL_EXAMPLES))
def test_mill_style_programs_are_refused_in_one_line(tmp_path, command, name):
    out = ["-o", str(tmp_path / "out.svg")] if command == "plot" else []
    path = os.path.join(EXAMPLES, name)
    result = run(command, path, *MILL_EXAMPLES[name], *out)
    assert result.returncode == 2
    assert result.stderr.decode().strip().splitlines() == [
        "%s:0: verify and plot check turning programs (the lathe's XZ section); %s programs are mill-style "
        "(X/Y/Z)" % (path, MILL_EXAMPLES[name][1])]
    assert not os.listdir(tmp_path)


MILLED = ("verify and plot check turning programs (the lathe's XZ section); a program that turns the C axis (G7.1, "
          "a live tool) mills, which they do not simulate")


@pytest.mark.parametrize("command", ["verify", "plot"])
@pytest.mark.parametrize("program, where", [
    ("gsk_g7_1.nc", "6: C0."),  # C positioned before the region
    ("G21 G98\nG0 X46. Z5.\nG7.1 C20. J-4. R2. K0.4 L2\nG1 Z-30. F100.\nG1 C90.\nG7.1 C0\nM30\n", "3: G7.1"),
])
def test_a_c_axis_program_is_refused_in_one_line_naming_its_first_c(tmp_path, command, program, where):
    # a live tool milling on the developed surface is not a turning blade: no XZ section to simulate it on
    path = os.path.join(EXAMPLES, program) if program.endswith(".nc") else write(tmp_path, program, "slot.nc")
    out = ["-o", str(tmp_path / "out.svg")] if command == "plot" else []
    result = run(command, path, "--dialect", "gsk", *out)
    assert result.returncode == 2
    assert result.stderr.decode().strip().splitlines() == ["%s:%s: %s" % (path, where, MILLED)]
    assert not (tmp_path / "out.svg").exists()


@pytest.mark.parametrize("name", sorted(EXAMPLE_OPTIONS))
def test_examples_verify_clean(name):
    result = run("verify", os.path.join(EXAMPLES, name), *EXAMPLE_OPTIONS[name])
    assert result.returncode == 0, result.stderr.decode()
    out = result.stdout.decode()
    assert "gouge 0.0000 mm^2" in out and out.rstrip().endswith(": ok")
    assert "Traceback" not in result.stderr.decode()


@pytest.mark.parametrize("name", sorted(EXAMPLE_OPTIONS))
def test_examples_plot(name, tmp_path):
    needs_matplotlib()
    out = str(tmp_path / "section.svg")
    result = run("plot", os.path.join(EXAMPLES, name), *EXAMPLE_OPTIONS[name], "-o", out)
    assert result.returncode == 0, result.stderr.decode()
    root = ET.parse(out).getroot()
    assert root.tag.endswith("svg")


def test_plot_png_is_a_png(tmp_path):
    needs_matplotlib()
    from PIL import Image

    out = str(tmp_path / "section.png")
    assert run("plot", write(tmp_path, GROOVE.format(extra="")), *SHARP_3MM, "-o", out).returncode == 0
    with Image.open(out) as image:
        image.verify()
        assert image.format == "PNG"


def test_hand_derived_groove_figures(tmp_path):
    """15 mm^2 removed (3 x 5); feed 5 mm at 0.1 mm/rev and 500 rpm = 6 s; at
    5000 mm/min the rapids take 5 mm (back out) and 60 mm (Z-10 -> Z50) / 5000 min."""
    settings = DEFAULT_SETTINGS.with_tool(3.0, 0.0, None)
    record = record_program(GROOVE.format(extra=""), "fanuc", settings)
    result = check_program("part.nc", record, rapid_rate=5000.0)
    assert result.ok
    cycle = result.job.ops[0]
    assert cycle.removed == pytest.approx(15.0, abs=1e-6)
    assert cycle.gouge_area == 0 and cycle.leftover == 0 and cycle.unreachable == pytest.approx(0, abs=1e-9)
    assert result.times[0].feed == pytest.approx(6.0)
    assert result.times[0].rapid == pytest.approx(5.0 / 5000 * 60)
    assert result.times[1].rapid == pytest.approx(60.0 / 5000 * 60)
    text = report(result)
    assert "removed 15.0000 mm^2" in text and "feeds 6.0 s" in text



@pytest.mark.parametrize("metric", [True, False])
def test_a_cycle93_with_radii_verifies_clean_its_arcs_recorded_as_fine_chords(metric):
    """The four-R2-corner groove (its passes write G2/G3), in mm and as the same groove in inch: the
    record keeps the cycle's arcs as chords within the simulation's 1e-5 mm; the check finds no
    gouge, no leftover the blade could reach, no rapid through stock."""
    call = "CYCLE93(20, -10, 12, 5, 0, 0, 0, 2, 2, 2, 2, 0.2, 0.2, 2, 0, 5, 0)"
    if not metric:  # the same groove in inch: every length / 25.4
        call = "CYCLE93(%s)" % ", ".join(
            repr(float(v) / 25.4) if k not in (4, 5, 6, 14, 15) else v for k, v in enumerate(call[8:-1].split(", ")))
    program = "%s\nG95 S500 M3\nG0 X60 Z5\nF0.1\n%s\nM30\n" % ("G710" if metric else "G700", call)
    unit = 1.0 if metric else 25.4
    record = record_program(program, "sinumerik", DEFAULT_SETTINGS.with_tool(3.0 / unit, 0.4 / unit, None))
    moves = [m for step in record.steps if step.cycle for m in step.moves]
    assert {m.kind for m in moves} == {"G0", "G1"}
    result = check_program("part.mpf", record)
    assert result.ok, report(result)
    assert result.job.ops[-1].leftover == pytest.approx(0.0, abs=1e-6)


def test_inch_program_is_checked_in_mm():
    """The same groove in inch: 0.1 in blade (2.54 mm), 0.2 in deep (5.08 mm),
    0.004 in/rev at 500 rpm over 0.2 in: 6 s; figures in mm."""
    program = GROOVE.format(extra="").replace("G21", "G20").replace("X50. Z-10.", "X2. Z-0.4").replace(
        "X40. P1000 F0.1", "X1.6 P1000 F0.004").replace("X100. Z50.", "X4. Z2.")
    record = record_program(program, "fanuc", DEFAULT_SETTINGS.with_tool(0.1, 0.0, None))
    result = check_program("part.nc", record)
    assert result.ok
    assert result.job.ops[0].removed == pytest.approx(2.54 * 5.08, abs=1e-6)
    assert result.times[0].feed == pytest.approx(6.0)

def test_hand_written_g1_plunge_outside_the_groove_is_a_gouge(tmp_path):
    program = write(tmp_path, GROOVE.format(extra="N75 G00 Z-20.\nN76 G01 X44. F0.1\nN77 G00 X50.\n"))
    result = run("verify", program, *SHARP_3MM)
    assert result.returncode == 1
    errors = result.stderr.decode().splitlines()
    assert len(errors) == 1 and errors[0].startswith(program + ":10: gouge: ")  # N76 is the file's line 10
    assert "the moves of lines 9-12 cut 8.99" in errors[0]  # 3 wide, 3 deep, less the tolerance's skin
    assert "3.0000 mm deep at X44.00" in errors[0]  # the bottom of the plunge



def test_plot_of_a_gouge_exits_1_and_draws(tmp_path):
    needs_matplotlib()
    out = tmp_path / "gouge.svg"
    program = write(tmp_path, GROOVE.format(extra="N75 G00 Z-20.\nN76 G01 X44. F0.1\nN77 G00 X50.\n"))
    result = run("plot", program, *SHARP_3MM, "-o", str(out))
    assert result.returncode == 1 and ":10: gouge: " in result.stderr.decode()
    assert ET.parse(out).getroot().tag.endswith("svg")

def test_rapid_through_standing_stock_is_a_collision(tmp_path):
    program = write(tmp_path, GROOVE.format(extra="N75 G00 X44. Z-20.\n"))
    result = run("verify", program, *SHARP_3MM)
    assert result.returncode == 1
    errors = result.stderr.decode().splitlines()
    assert errors[0].startswith(program + ":9: collision: G0 X50.000 Z-10.000 -> X44.000 Z-20.000 passes through")
    assert all(" collision: " in line for line in errors)  # and the rapid out again


@pytest.mark.parametrize("bottom, status", [("X-1.", 0), ("X10.", 1)])
def test_cut_off_piece_falls_away(tmp_path, bottom, status):
    """After a cut-off through the centre (X-1.) the piece beyond it falls:
    rapids through where it stood are no collision; after a groove to X10.
    the same rapids hit the piece, still held."""
    text = GROOVE.format(extra="N72 G00 X50. Z-40.\nN73 G75 %s P2000 F0.05\nN74 G00 X-1. Z-38.\nN76 G00 X50.\n"
                         % bottom)
    result = run("verify", write(tmp_path, text), *SHARP_3MM)
    assert result.returncode == status, result.stderr.decode()
    if status:
        assert ":11: collision: G0 X50.000 Z-40.000 -> X-1.000 Z-38.000" in result.stderr.decode()


@pytest.mark.parametrize("extra, message", [
    ("N75 G01 X44 F0.1\n", ":9: X44 needs a decimal point"),
    ("N75 G02 X44. Z-20.\n", ":9: G2/G3 needs either I/K (centre) or the radius"),
])
def test_bad_program_exits_2_with_one_line(tmp_path, extra, message):
    program = write(tmp_path, GROOVE.format(extra=extra))
    result = run("verify", program, *SHARP_3MM)
    assert result.returncode == 2 and result.stdout == b""
    lines = result.stderr.decode().splitlines()
    assert len(lines) == 1 and lines[0].startswith(program + message)


def test_no_blade_exits_2(tmp_path):
    result = run("verify", write(tmp_path, GROOVE.format(extra="")), "--dialect", "fanuc")
    lines = result.stderr.decode().splitlines()
    assert result.returncode == 2 and len(lines) == 1 and "blade" in lines[0] and "--tool-width" in lines[0]


def test_stock_option(tmp_path):
    program = write(tmp_path, GROOVE.format(extra=""))
    result = run("verify", program, *SHARP_3MM, "--stock", "48x20")
    assert result.returncode == 0
    assert "bar D48.000 from Z-27.000 to Z-7.000 (diameter as given (--stock))" in result.stdout.decode()
    assert "removed 12.0000 mm^2" in result.stdout.decode()  # 3 wide, radius 24 down to 20
    bad = run("verify", program, *SHARP_3MM, "--stock", "48y")
    assert bad.returncode == 2 and b"DIAMETERxLENGTH" in bad.stderr


def test_verify_needs_no_shapely(tmp_path):
    """The column model runs on numpy alone: with shapely not importable, verify gives the hand-derived figures."""
    code = BLOCK_PACKAGE % "shapely"
    args = ["verify", write(tmp_path, GROOVE.format(extra="")), *SHARP_3MM]
    result = subprocess.run([sys.executable, "-c", code, *args], cwd=ROOT, capture_output=True, timeout=300)
    assert result.returncode == 0, result.stderr.decode()
    assert "removed 15.0000 mm^2" in result.stdout.decode() and result.stdout.decode().rstrip().endswith(": ok")


@pytest.mark.parametrize("package, command", [("numpy", "verify"), ("matplotlib", "plot")])
def test_missing_package_one_line(tmp_path, package, command):
    out = str(tmp_path / "x.svg")
    code = BLOCK_PACKAGE % package
    args = [command, write(tmp_path, GROOVE.format(extra="")), *SHARP_3MM] + (["-o", out] if command == "plot" else [])
    result = subprocess.run([sys.executable, "-c", code, *args], cwd=ROOT, capture_output=True, timeout=300)
    lines = result.stderr.decode().splitlines()
    assert result.returncode == 2 and len(lines) == 1, lines
    assert "apt install python3-%s" % package in lines[0] and "pip install %s" % package in lines[0]
    assert not os.path.exists(out)


def test_plot_is_atomic(tmp_path):
    needs_matplotlib()
    out = tmp_path / "section.svg"
    bad = write(tmp_path, GROOVE.format(extra="N75 G01 X44 F0.1\n"))
    assert run("plot", bad, *SHARP_3MM, "-o", str(out)).returncode == 2
    assert list(tmp_path.iterdir()) == [tmp_path / "part.nc"]  # no picture, no temporary file
    out.write_text("old")
    assert run("plot", bad, *SHARP_3MM, "-o", str(out)).returncode == 2
    assert out.read_text() == "old"
    wrong = run("plot", write(tmp_path, GROOVE.format(extra=""), "ok.nc"), *SHARP_3MM, "-o", str(tmp_path / "x.pdf"))
    assert wrong.returncode == 2 and b".svg or .png" in wrong.stderr


def test_arc_chords_g2_is_clockwise_with_z_right_x_up():
    """G2 from Z-10 to Z10 on a circle of radius 10 about X0 Z0 passes over the top (X 10)."""
    points = arc_chords((0.0, -10.0), (0.0, 10.0), (0.0, 0.0), clockwise=True)
    assert max(x for x, _z in points) == pytest.approx(10.0, abs=ARC_CHORD_TOL)
    for (x0, z0), (x1, z1) in zip([(0.0, -10.0)] + points, points):
        mid = math.hypot((x0 + x1) / 2, (z0 + z1) / 2)
        assert 10.0 - ARC_CHORD_TOL - 1e-12 <= mid <= 10.0  # each chord within the tolerance of the arc
    assert radius_centre((0.0, -10.0), (10.0, 0.0), 10.0, clockwise=True) == pytest.approx((0.0, 0.0))
    assert radius_centre((0.0, -10.0), (10.0, 0.0), 10.0, clockwise=False) == pytest.approx((10.0, -10.0))


def test_plain_arc_into_the_part_is_a_gouge(tmp_path):
    """A G2 half circle R5 from X50 Z-30 to X50 Z-40 (on the bar's surface,
    radius 25): clockwise seen with Z right and X up, moving toward -Z it
    dips 5 mm into the bar; the G3 goes over the top, in the air."""
    extra = "N75 G00 Z-30.\nN76 G02 Z-40. R5.\nN77 G00 X100.\n"
    result = run("verify", write(tmp_path, GROOVE.format(extra=extra)), *SHARP_3MM)
    assert result.returncode == 1 and ":10: gouge" in result.stderr.decode()
    extra_g3 = "N75 G00 Z-30.\nN76 G03 Z-40. R5.\nN77 G00 X100.\n"  # over the top: in the air
    assert run("verify", write(tmp_path, GROOVE.format(extra=extra_g3)), *SHARP_3MM).returncode == 0


def test_matplotlib_and_shapely_are_imported_lazily():
    """expand and emit never load shapely or matplotlib; verify loads neither (the column model is numpy)."""
    code = ("import sys; from freecad_groove import cli; import freecad_groove.verify.program_check; "
            "print('matplotlib' in sys.modules, 'shapely' in sys.modules)")
    assert subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True).stdout == b"False False\n"
    code = "import sys; from freecad_groove import cli; print('shapely' in sys.modules or 'matplotlib' in sys.modules)"
    assert subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True).stdout == b"False\n"
