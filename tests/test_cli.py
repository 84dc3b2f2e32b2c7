"""The command line (python3 -m freecad_groove): output, the one-line error
contract (PROGRAM:LINE: message, exit 2, nothing on stdout, OUT untouched), no
traceback for any input, --help, emit, and scripts/demo."""

import contextlib
import io
import os
import re
import subprocess
import sys

import pytest
from conftest import EXAMPLES, ROOT
from hypothesis import given
from hypothesis import strategies as st

from freecad_groove import cli
from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.tool_table import read_tool_table
from freecad_groove.engine.translator import translate_program

SEED = os.path.join(ROOT, "examples", "seed_cycle93.mpf")
TOOLS = os.path.join(ROOT, "examples", "tools.tbl")  # the examples' blades (T5: the seed's 3 mm blade)
TABLE = ["--tool-table", TOOLS]
ERROR_LINE = re.compile(r"^(?P<name>[^\n]*):(?P<line>\d+): (?P<message>[^\n]+)\n\Z")
# The seed example's corners a flat blade cannot reach are reported on stderr (cycle93_reach).
WARNING_LINE = re.compile(r"^[^\n]*:\d+: warning: CYCLE93: [^\n]+ cannot be reached by a [^\n]+\n", re.M)


def only_warnings(stderr: bytes) -> bool:
    """True when stderr holds nothing but the CYCLE93 unreachable-material warnings."""
    return WARNING_LINE.sub("", stderr.decode()) == ""


def run(*args, stdin=None):
    """Run the real command line in a child process."""
    return subprocess.run(
        [sys.executable, "-m", "freecad_groove", *args],
        cwd=ROOT,
        input=stdin,
        capture_output=True,
        timeout=120,
    )


def run_inline(argv, stdin_bytes=b""):
    """Run cli.main in this process (fast, for fuzzing): (status, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    fake_stdin = io.TextIOWrapper(io.BytesIO(stdin_bytes))
    old_stdin = sys.stdin
    sys.stdin = fake_stdin
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                status = cli.main(argv)
            except SystemExit as exc:
                status = exc.code
    finally:
        sys.stdin = old_stdin
    return status, out.getvalue(), err.getvalue()


def assert_one_error_line(proc, name, line, fragment=None):
    assert proc.returncode == 2
    assert proc.stdout == b""
    err = proc.stderr.decode()
    m = ERROR_LINE.match(err)
    assert m, err
    assert m.group("name") == name and int(m.group("line")) == line, err
    assert "Traceback" not in err
    if fragment:
        assert fragment in m.group("message"), err
    return m.group("message")


BLADE = Settings(tool=GroovingTool(3.0, 0.2))  # --tool-width 3 (radius 0.2, reference minus)
BAD_CYCLE = open(SEED).read().replace("30, 25, 12", "1, 25, 12")  # WIDG 1 < tool width 3


# ---------------------------------------------------------------- expand


@pytest.mark.parametrize("name", sorted(EXAMPLES))
@pytest.mark.parametrize("target", ["linuxcnc", "fanuc"])
def test_expand_examples_to_stdout(name, target):
    proc = run("expand", "examples/" + name, "--dialect", EXAMPLES[name], "--to", target, *TABLE)
    assert proc.returncode == 0, proc.stderr
    text = open(os.path.join(ROOT, "examples", name)).read()
    warnings = []
    assert proc.stdout.decode() == translate_program(text, EXAMPLES[name], target=target, source_name=name,
                                                     tools=read_tool_table(open(TOOLS).read()), warnings=warnings)
    assert proc.stderr.decode() == "".join("examples/%s:%d: warning: %s\n" % (name, line, warning.text)
                                           for line, warning in warnings)


def test_expand_default_target_is_linuxcnc():
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", *TABLE)
    assert proc.returncode == 0
    assert proc.stdout.decode().splitlines()[1].startswith("G18 G7 G21 G90")


def test_expand_to_file(tmp_path):
    out = tmp_path / "seed.ngc"
    proc = run("expand", SEED, "--dialect", "sinumerik", "-o", str(out), "--tool-width", "3")
    assert proc.returncode == 0 and proc.stdout == b"" and only_warnings(proc.stderr)
    assert out.read_text() == translate_program(open(SEED).read(), "sinumerik", BLADE, source_name="seed_cycle93.mpf")
    assert sorted(os.listdir(tmp_path)) == ["seed.ngc"]  # no temporary file left
    # replaced when it exists, keeping its permissions
    out.write_text("old\n")
    os.chmod(out, 0o640)
    assert run("expand", SEED, "--dialect", "sinumerik", "-o", str(out), *TABLE).returncode == 0
    assert out.read_text() != "old\n" and (os.stat(out).st_mode & 0o777) == 0o640


def test_expand_from_stdin():
    proc = run("expand", "-", "--dialect", "sinumerik", *TABLE, stdin=open(SEED, "rb").read())
    assert proc.returncode == 0
    assert proc.stdout.decode() == translate_program(open(SEED).read(), "sinumerik", BLADE, source_name="stdin")


def test_invalid_cycle(tmp_path):
    program = tmp_path / "bad.mpf"
    program.write_text(BAD_CYCLE)
    out = tmp_path / "out.ngc"
    out.write_text("old program\n")
    proc = run("expand", str(program), "--dialect", "sinumerik", "-o", str(out), *TABLE)
    message = assert_one_error_line(proc, str(program), 4, "CYCLE93 WIDG=1")
    assert "61602" in message
    assert out.read_text() == "old program\n"  # untouched
    assert sorted(os.listdir(tmp_path)) == ["bad.mpf", "out.ngc"]
    # without -o: nothing on stdout either
    proc = run("expand", str(program), "--dialect", "sinumerik", *TABLE)
    assert_one_error_line(proc, str(program), 4, "CYCLE93")


def test_unreadable_line(tmp_path):
    program = tmp_path / "bad.nc"
    program.write_text("G21\nG99\nG00 X80. Z65. @@\nM30\n")
    out = tmp_path / "out.ngc"
    proc = run("expand", str(program), "--dialect", "fanuc", "-o", str(out))
    assert_one_error_line(proc, str(program), 3, "cannot read")
    assert not out.exists()
    assert sorted(os.listdir(tmp_path)) == ["bad.nc"]


def test_invalid_cycle_from_stdin():
    proc = run("expand", "-", "--dialect", "sinumerik", *TABLE, stdin=BAD_CYCLE.encode())
    assert_one_error_line(proc, "<stdin>", 4, "CYCLE93")


def test_missing_program(tmp_path):
    missing = str(tmp_path / "nope.nc")
    proc = run("expand", missing, "--dialect", "fanuc")
    assert_one_error_line(proc, missing, 0, "cannot read the program")
    proc = run("expand", str(tmp_path), "--dialect", "fanuc")  # a directory
    assert_one_error_line(proc, str(tmp_path), 0, "cannot read the program")


def test_unwritable_output(tmp_path):
    out = str(tmp_path / "no" / "such" / "dir.ngc")
    proc = run("expand", SEED, "--dialect", "sinumerik", "-o", out, *TABLE)
    assert_one_error_line(proc, out, 0, "cannot write the output")


def test_garbage_bytes_in_a_real_process():
    for data in (b"\x00\xff\xfe garbage \x80\n", b"G0 X\xe9", "G0 X80 Z65 (Ø)\nM30\n".encode("latin-1")):
        for dialect in EXAMPLES.values():
            proc = run("expand", "-", "--dialect", dialect, stdin=data)
            assert b"Traceback" not in proc.stderr
            assert proc.returncode in (0, 2)
            if proc.returncode:
                assert proc.stdout == b"" and ERROR_LINE.match(proc.stderr.decode()), proc.stderr


@given(st.binary(max_size=300), st.sampled_from(sorted(set(EXAMPLES.values()))))
def test_no_traceback_for_random_bytes(data, dialect):
    status, out, err = run_inline(["expand", "-", "--dialect", dialect], data)
    assert status in (0, 2)
    if status == 2:
        assert out == ""
        m = ERROR_LINE.match(err)
        assert m and m.group("name") == "<stdin>", err
        assert not m.group("message").startswith("internal error"), err
    else:
        assert err == "" and out


@given(st.text(max_size=300), st.sampled_from(sorted(set(EXAMPLES.values()))))
def test_no_traceback_for_random_text(text, dialect):
    status, out, err = run_inline(["expand", "-", "--dialect", dialect], text.encode("utf-8", "surrogatepass"))
    assert status in (0, 2)
    if status == 2:
        assert out == "" and ERROR_LINE.match(err), err
        assert "internal error" not in err


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_every_option_with_every_dialect(name):
    args = [
        "expand", "examples/" + name, "--dialect", EXAMPLES[name],
        "--tool-width", "3", "--tool-radius", "0.2", "--retract", "0.5", "--diameter-input",
        "--g07-radius", "--reference-corner", "minus", "--clearance", "1", "--max-contour-tilt", "45",
        "--units", "mm", "--feed-mode", "rev", "--x-mode", "diameter", "--to", "fanuc",
    ]
    if EXAMPLES[name] == "sinumerik":
        args.remove("--diameter-input")  # would read AXFA 35 as a diameter: another groove
    if EXAMPLES[name] == "ab9":
        args.remove("--g07-radius")  # the example selects G07 = diameter
    proc = run(*args)
    assert proc.returncode == 0, proc.stderr


def test_options_change_the_result():
    seed = ["expand", SEED, "--dialect", "sinumerik", "--tool-width", "3"]  # the width is the last one given
    base = run(*seed).stdout
    assert run(*seed, "--reference-corner", "plus").stdout != base
    assert run(*seed, "--tool-width", "4").stdout != base
    proc = run(*seed, "--tool-width", "31")  # wider than the groove
    assert_one_error_line(proc, SEED, 4, "WIDG")
    ab = ["expand", "examples/ab9_g77.nc", "--dialect", "ab9"]
    assert run(*ab, "--retract", "0.3").stdout != run(*ab).stdout
    assert run(*ab, "--g07-radius").stdout != run(*ab).stdout


@pytest.mark.parametrize(
    "args",
    [
        ["expand", SEED, "--dialect", "sinumerik", "--tool-width", "0"],
        ["expand", SEED, "--dialect", "sinumerik", "--tool-width", "nan"],
        ["expand", SEED, "--dialect", "sinumerik", "--retract", "-1"],
        ["expand", SEED, "--dialect", "mazak"],
        ["expand", SEED],
        ["frobnicate"],
    ],
)
def test_bad_options_are_argparse_errors(args):
    proc = run(*args)
    assert proc.returncode == 2 and proc.stdout == b""
    assert b"Traceback" not in proc.stderr and b"usage:" in proc.stderr


# ---------------------------------------------------------------- help


@pytest.mark.parametrize(
    "args, words",
    [
        (["--help"], ["expand", "emit", "diameter", "radius", "Reference corner"]),
        (["expand", "--help"], ["--dialect", "--tool-width", "--tool-table", "--reference-corner", "--diameter-input",
                                "--g07-radius", "--retract", "PROGRAM:LINE", "DIAMETERS"]),
        (["emit", "--help"], ["cycle93", "ab-g77", "fanuc-g75", "haas-g75"]),
        (["emit", "cycle93", "--help"], ["--axfa", "--typ", "radius value", "--expand"]),
        (["emit", "g77", "--help"], ["-X", "LAST groove", "-D"]),
        (["emit", "fanuc-g75", "--help"], ["-P", "least input increments", "--first-block-r"]),
    ],
)
def test_help(args, words):
    proc = run(*args)
    assert proc.returncode == 0 and proc.stderr == b""
    text = proc.stdout.decode()
    for word in words:
        assert word in text, word


# ---------------------------------------------------------------- emit


def test_emit_native_calls():
    proc = run("emit", "g77", "-X", "40", "-Z", "-30", "-I", "2", "-K", "5", "-D", "0", "-F", "0.08")
    assert proc.returncode == 0 and proc.stdout == b"G77 X40. Z-30. I2. K5. F0.08 D0.\n"
    proc = run("emit", "fanuc-g75", "-e", "0.5", "-X", "40", "-Z", "-30", "-P", "2000", "-Q", "5000", "-F", "0.08")
    assert proc.stdout == b"G75 R0.5\nG75 X40. Z-30. P2000 Q5000 F0.08\n"
    proc = run("emit", "haas-g75", "-X", "40", "-I", "2")
    assert proc.stdout == b"G75 X40. I2.\n"
    proc = run("emit", "cycle93", "--axfa", "35", "--axsa", "60", "--widg", "30", "--depg", "25", "--angc", "12",
               "--ang1", "15", "--ang2", "16", "--rco1", "0", "--rco2", "0", "--rci1", "-2", "--rci2", "-2",
               "--fal1", "1", "--fal2", "1", "--idep", "10", "--dwt", "1", "--typ", "5", "--vrt", "0",
               "--tool-width", "3")
    assert proc.returncode == 0
    assert proc.stdout.decode().startswith("CYCLE93(35, 60, 30, 25, 12, 15, 16")


def test_emit_refuses_an_invalid_call():
    proc = run("emit", "cycle93", "--axfa", "35", "--axsa", "60", "--widg", "1", "--depg", "25", "--idep", "10",
               "--typ", "5", "--tool-width", "3")
    assert_one_error_line(proc, "emit cycle93", 1, "WIDG=1")
    proc = run("emit", "g77", "-X", "40", "-I", "2")  # D is required
    assert_one_error_line(proc, "emit ab-g77", 1, "D")
    proc = run("emit", "fanuc-g75", "-X", "40", "-P", "2.5")
    assert proc.returncode == 2 and b"usage:" in proc.stderr


def test_emit_expand_is_a_whole_program_accepted_by_rs274():
    proc = run("emit", "g77", "-X", "44", "-I", "2", "-D", "0", "-F", "0.1", "--expand", "--start-x", "50",
               "--start-z", "0", "--feed-mode", "min")
    assert proc.returncode == 0, proc.stderr
    text = proc.stdout.decode()
    assert text.splitlines()[:3] == [
        "(Allen-Bradley 9/Series G77 grooving / cut-off: G77 X44. I2. F0.1 D0.)",
        "G18 G7 G21 G90 G91.1 G40 G94",
        "G0 X50. Z0.",
    ]
    from rs274 import require_rs274, run_rs274

    require_rs274()
    assert len(run_rs274(text)) == 5
    proc = run("emit", "g77", "-X", "44", "-I", "2", "-D", "0", "--expand")
    assert_one_error_line(proc, "emit ab-g77", 1, "start point")
    proc = run("emit", "g77", "-X", "44", "-I", "2", "-D", "0", "-F", "0.1", "--expand", "--start-x", "50",
               "--start-z", "0")  # feed per revolution by default: needs the spindle
    assert_one_error_line(proc, "emit ab-g77", 1, "spindle")
    proc = run("emit", "g77", "-X", "44", "-I", "2", "-D", "0", "-F", "0.1", "--expand", "--start-x", "50",
               "--start-z", "0", "--spindle", "600", "--to", "fanuc")
    assert proc.returncode == 0
    assert proc.stdout.decode().splitlines()[:6] == [
        "%", "(Allen-Bradley 9/Series G77 grooving / cut-off: G77 X44. I2. F0.1 D0.)", "G21", "G40 G99",
        "G97 S600 M03", "G00 X50. Z0.",
    ]


# ---------------------------------------------------------------- scripts/demo


def test_demo_script(tmp_path):
    # The command-line part only: the FreeCAD part is tests/test_demo.py's.
    proc = subprocess.run(["bash", os.path.join(ROOT, "scripts", "demo"), str(tmp_path)], capture_output=True,
                          timeout=300, env=dict(os.environ, PYTHON=sys.executable, FREECAD_GROOVE_DEMO_FREECAD="0"))
    assert proc.returncode == 0, proc.stderr
    names = sorted(os.listdir(tmp_path))
    # 7 examples x (LinuxCNC, Fanuc), the 4 turning ones plotted, and the summary
    assert len(names) == 7 * 2 + 4 + 1 and "seed_cycle93.ngc" in names and "haas_g75.fanuc.nc" in names
    assert {"ab9_g83.ngc", "milltronics_g33_g34.ngc", "gsk_g7_1.fanuc.nc", "fanuc_g75.png", "summary.txt"} <= set(names)
    for name in names:
        if name != "summary.txt":
            assert str(tmp_path / name) in proc.stdout.decode()
            assert str(tmp_path / name) in (tmp_path / "summary.txt").read_text()


def test_emit_reads_negative_words_written_g_code_style():
    # "-30." is how a machinist writes it; argparse alone would take it for an option.
    proc = run("emit", "g77", "-X", "40.", "-Z", "-30.", "-I", "2.", "-K", "5.", "-D", "-1.", "-F", "0.08")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == b"G77 X40. Z-30. I2. K5. F0.08 D-1.\n"
