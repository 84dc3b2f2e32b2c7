"""What a grooving blade's holder allows (issue 20, item 5): a face-grooving blade's first-cut diameter range and
an internal bar's smallest bore (engine/blade_limits.py; the tool table's dmin=, dmax=, bore=), and the holder
drawn by the turning check (verify/holder.py; the tool table's holder=). Each one given is checked; one not
given changes nothing."""

import subprocess
import sys

import pytest
from conftest import ROOT

from freecad_groove.engine import GroovingTool, ProgramError
from freecad_groove.engine.blade_limits import BladeEntry, BladeLimits, limits_problem
from freecad_groove.engine.moves import FEED, MINUS_X, MINUS_Z, PLUS_X, RAPID, Move
from freecad_groove.engine.tool_table import read_tool_table
from freecad_groove.engine.translator import translate_program
from freecad_groove.verify.holder import Holder
from freecad_groove.verify.shapes import box
from freecad_groove.verify.turning import GrooveRun, OpInput, check_ops

# A face groove (VARI 2, ANGC 90) at AXFA R60, 5 wide toward +X, 4 deep, FAL2 0.2: the roughing's first plunge
# stands FAL2 inside the groove's side at R60: the 3 mm blade (minus corner) over R60.2..63.2, diameters
# 120.4..126.4. VARI 3 is the internal longitudinal groove at the same AXFA: its bore is R60, diameter 120.
CALL = "CYCLE93(60, 0, 5, 4, %d, 0, 0, 0, 0, 0, 0, 0.2, 0.2, 1, 0, %d, 1)"
PROGRAM = "N10 T5 D1 S400 M03\nN20 G95 G90 F0.2\nN30 G00 X%d Z10\nN40 %s\nN50 M02\n"
FACE_PROGRAM = PROGRAM % (100, CALL % (90, 2))
BORE_PROGRAM = PROGRAM % (40, CALL % (0, 3))


def table(text):
    return read_tool_table(text, "tools.tbl")


def refusal(program, text):
    with pytest.raises(ProgramError) as info:
        translate_program(program, "sinumerik", tools=table(text))
    assert info.value.line == 4
    return str(info.value)


def run(*args):
    return subprocess.run([sys.executable, "-m", "freecad_groove", *args], cwd=ROOT, capture_output=True,
                          timeout=300)


# ---------------------------------------------------------------- the tool table's fields


def test_a_table_line_may_give_the_first_cut_range_the_smallest_bore_and_the_holder():
    tools = table("5 3 0.2 minus 12 dmin=40 dmax=60 holder=16\n7 2 0.1 minus bore=20 side=internal\n9 3 0 minus\n")
    assert tools.limits[5] == BladeLimits(40.0, 60.0, None) and tools.limits[7] == BladeLimits(None, None, 20.0)
    assert tools.holders == {5: 16.0} and tools.sides == {7: "internal"}
    assert 9 not in tools.limits  # not given: not checked


@pytest.mark.parametrize("line, message", [
    ("5 3 0.2 minus dmin=0", "1: dmin=0: must be greater than 0 (leave the field out when it is not known)"),
    ("5 3 0.2 minus dmax=-4", "1: dmax=-4: must be greater than 0 (leave the field out when it is not known)"),
    ("5 3 0.2 minus bore=nan", "1: bore=nan: must be a number"),
    ("5 3 0.2 minus dmin=60 dmax=40", "1: dmin=60: must be less than dmax=40"),
    ("5 3 0.2 minus dmin=4 dmin=5", "1: dmin=5: dmin= is given twice"),
    ("5 3 0.2 minus holder=16", "1: holder=16: needs the reach field (the holder begins at the blade's free reach)"),
    ("5 3 0.2 minus 12 holder=2", "1: holder=2: must be at least the blade's width 3"),
    ("5 3 0.2 minus hand=left", "1: hand=left: unknown; the named fields are side=, dmin=, dmax=, bore=, holder="),
])
def test_a_bad_field_is_refused_naming_it(line, message):
    with pytest.raises(ProgramError) as info:
        table(line)
    assert "%d: %s" % (info.value.line, info.value) == message


# ---------------------------------------------------------------- the checks (engine and expand)


def test_a_face_groove_outside_the_first_cut_range_is_refused_naming_the_field():
    assert refusal(FACE_PROGRAM, "5 3 0.2 minus dmin=121") == (
        "dmin=121: the face groove's first plunge cuts diameters 120.4..126.4, below the first-cut diameter range "
        "of T5's blade (tools.tbl), dmin=121, no dmax: its curved holder would hit the face (use a blade for these "
        "diameters)")
    assert refusal(FACE_PROGRAM, "5 3 0.2 minus dmin=100 dmax=126") == (
        "dmax=126: the face groove's first plunge cuts diameters 120.4..126.4, above the first-cut diameter range "
        "of T5's blade (tools.tbl), dmin=100 to dmax=126: its curved holder would hit the face (use a blade for "
        "these diameters)")
    plain = translate_program(FACE_PROGRAM, "sinumerik", tools=table("5 3 0.2 minus\n"))
    assert translate_program(FACE_PROGRAM, "sinumerik", tools=table("5 3 0.2 minus dmin=120.4 dmax=126.4")) == plain
    assert translate_program(FACE_PROGRAM, "sinumerik", tools=table("5 3 0.2 minus bore=500")) == plain  # a face


def test_an_internal_groove_in_a_bore_smaller_than_the_bars_is_refused():
    assert refusal(BORE_PROGRAM, "5 3 0.2 minus bore=120.5") == (
        "bore=120.5: the internal groove's bore is 120, smaller than the smallest bore T5's blade (tools.tbl) "
        "enters: its bar would hit the bore (use a smaller bar)")
    plain = translate_program(BORE_PROGRAM, "sinumerik", tools=table("5 3 0.2 minus\n"))
    assert translate_program(BORE_PROGRAM, "sinumerik", tools=table("5 3 0.2 minus bore=120 dmin=500")) == plain


def test_the_seeds_external_groove_is_not_limited_by_a_range_or_a_bore():
    seed = open(ROOT + "/examples/seed_cycle93.mpf").read()
    assert translate_program(seed, "sinumerik", tools=table("5 3 0.2 minus dmin=500 dmax=600 bore=900")) == \
        translate_program(seed, "sinumerik", tools=table("5 3 0.2 minus"))


def test_limits_problem_checks_only_what_is_given():
    face = BladeEntry(MINUS_Z, low=30.0, high=36.0)
    assert limits_problem(face, BladeLimits(), "B") is None
    assert limits_problem(face, BladeLimits(first_cut_max=36.0), "B") is None
    assert limits_problem(face, None, "B") is None and limits_problem(None, BladeLimits(1.0), "B") is None
    assert limits_problem(BladeEntry(PLUS_X, bore=12.0), BladeLimits(min_bore=12.0), "B") is None
    assert limits_problem(BladeEntry(MINUS_X), BladeLimits(100.0, 200.0, 300.0), "B") is None


def test_expand_refuses_it_in_one_line(tmp_path):
    program, tools = tmp_path / "face.mpf", tmp_path / "t.tbl"
    program.write_text(FACE_PROGRAM)
    tools.write_text("# T width radius reference reach\n5 3.0 0.2 minus 12 dmin=130 dmax=150\n")
    proc = run("expand", str(program), "--dialect", "sinumerik", "--tool-table", str(tools))
    assert proc.returncode == 2 and proc.stdout == b""
    assert proc.stderr.decode().splitlines() == [
        "%s:4: dmin=130: the face groove's first plunge cuts diameters 120.4..126.4, below the first-cut diameter "
        "range of T5's blade (%s), dmin=130 to dmax=150: its curved holder would hit the face (use a blade for these "
        "diameters)"
        % (program, tools)]


# ---------------------------------------------------------------- the holder in the turning check

BLADE = GroovingTool(3.0, 0.2)
BAR = box(-60, 0, 0, 30)  # (z, x): a bar R30 from Z-60 to Z0


def plunge_check(holder, bottom=15.0):
    """A plunge from R32 to ``bottom`` at Z-10 (the blade over Z-10..-7) and out, in the R30 bar."""
    moves = [Move(RAPID, 32.0, -10.0), Move(FEED, bottom, -10.0, f=0.1), Move(RAPID, 32.0, -10.0)]
    region = [(30.0, -10.0), (bottom, -10.0), (bottom, -7.0), (30.0, -7.0)]
    run_ = GrooveRun(moves, [1, 2, 3], BLADE, MINUS_X, region, holder=holder)
    return check_ops([OpInput("Groove", (40.0, -10.0), [run_])], BAR, BAR).ops[0]


def test_a_holder_entering_the_bar_beside_a_deep_groove_is_reported_with_its_move():
    """15 deep, the holder from 12 behind the cutting edge: at the bottom it begins at R27; 20 wide, centred on the
    blade (Z-18.5..1.5), it stands in the bar (R27..30) over Z-18.5..0 less the blade's own Z-10..-7: 3 x 15.5 =
    46.5 mm^2, on the plunge (Path command 2) and on the rapid out (3)."""
    check = plunge_check(Holder(12.0, 20.0))
    assert not check.ok and check.gouge_depth == 0
    assert [(h.command, h.rapid) for h in check.holder_hits] == [(2, False), (3, True)]
    assert check.holder_hits[0].area == pytest.approx(46.5, abs=1e-6)
    assert 27.0 <= check.holder_hits[0].at[0] <= 30.0
    assert check.holder_region.area == pytest.approx(46.5, abs=1e-6)  # what the panel draws (magenta)
    outline = check.holder_hits[0].outline  # (z, x) at the plunge's end: Z-18.5..1.5, R27..127
    assert outline.min(axis=0) == pytest.approx([-18.5, 27.0]) and outline.max(axis=0) == pytest.approx([1.5, 127.0])
    assert "HOLDER IN STOCK: G1 (Path command 2) X32.000 Z-10.000 -> X15.000 Z-10.000: its holder (20 mm wide, " \
           "from 12 mm behind the cutting edge) enters 46.5 mm^2 of standing material" in check.summary()


@pytest.mark.parametrize("holder", [None, Holder(16.0, 20.0), Holder(12.0, 3.0)])
def test_a_holder_that_stays_out_or_is_not_given_changes_nothing(holder):
    """Beginning at R31 (reach 16), or as wide as the blade (its own slot), or none: no hit, the same figures."""
    check = plunge_check(holder)
    assert check.ok and check.holder_hits == [] and check.holder_region.is_empty
    assert check.removed == pytest.approx(plunge_check(None).removed)


def test_a_face_grooving_holder_is_drawn_across_the_radius():
    """A face plunge at R10 (the blade over R10..13) to Z-15: the holder from Z-3, 20 wide (R1.5..21.5), stands
    in the bar (Z-3..0) less the blade's R10..13: 17 x 3 = 51 mm^2."""
    moves = [Move(RAPID, 10.0, 2.0), Move(FEED, 10.0, -15.0, f=0.1), Move(RAPID, 10.0, 2.0)]
    run_ = GrooveRun(moves, [1, 2, 3], BLADE, MINUS_Z, [(10, 0), (10, -15), (13, -15), (13, 0)],
                     holder=Holder(12.0, 20.0))
    check = check_ops([OpInput("Face", (40.0, 5.0), [run_])], BAR, BAR).ops[0]
    assert check.holder_hits[0].area == pytest.approx(51.0, abs=1e-6)


GROOVE = """O1000
N10 G21
N20 G99
N30 T0303
N40 G97 S500 M03
N50 G00 X50. Z-10.
N60 G75 R0.
N70 G75 X40. P1000 F0.1
N80 G00 X100. Z50.
N90 M30
"""


def test_verify_reports_the_holder_when_the_tool_table_gives_one(tmp_path):
    """The default stock: a bar D50 from Z-20 to Z-7. The G75 groove 5 deep (R25 -> R20); the holder from 4 behind
    the cutting edge begins at R24 at the bottom; 10 wide (Z-13.5..-3.5) it stands in the bar over Z-13.5..-10:
    3.5 x 1 = 3.5 mm^2, on the last peck and the rapid out (line 8). Reaching 5, it stays out; no holder= (or no
    reach), no holder drawn."""
    program, tools = tmp_path / "part.nc", tmp_path / "t.tbl"
    program.write_text(GROOVE)
    tools.write_text("3 3 0 minus 4 holder=10\n")
    proc = run("verify", str(program), "--dialect", "fanuc", "--tool-table", str(tools))
    assert proc.returncode == 1
    assert proc.stderr.decode().splitlines() == [
        "%s:8: holder: G0 X40.000 Z-10.000 -> X50.000 Z-10.000: the blade's holder (10 wide, from 4 behind the "
        "cutting edge) enters 3.5 mm^2 of standing material near X49.000 Z-13.475 (X diameters, mm)" % program,
        "%s:8: holder: G1 X42.000 Z-10.000 -> X40.000 Z-10.000: the blade's holder (10 wide, from 4 behind the "
        "cutting edge) enters 3.5 mm^2 of standing material near X49.000 Z-13.475 (X diameters, mm)" % program]
    assert "HOLDER IN STOCK AT 2 MOVE(S)" in proc.stdout.decode()
    for text in ("3 3 0 minus 5 holder=10\n", "3 3 0 minus 4\n"):
        tools.write_text(text)
        proc = run("verify", str(program), "--dialect", "fanuc", "--tool-table", str(tools))
        assert proc.returncode == 0 and proc.stderr == b"", proc.stderr
