"""The command line's --to: every control's output, and the refusals of what a
target cannot take (one line naming the option or the word, status 2, nothing
on stdout), never an internal error or a program the control would reject."""

import io
import sys

import pytest
from test_cli import run_inline

from freecad_groove.engine.output.targets import TARGETS


def test_expand_help_lists_every_target():
    status, out, _err = run_inline(["expand", "--help"])
    assert status == 0
    text = " ".join(out.split())
    for name in TARGETS:
        assert "%s = " % name in text, name


@pytest.mark.parametrize("example, dialect, to", [
    ("examples/ab9_g83.nc", "ab9grind", "linuxcnc-c"),
    ("examples/ab9_g83.nc", "ab9grind", "sinumerik"),
    ("examples/milltronics_g33_g34.nc", "milltronics", "fanuc-c"),
    ("examples/ab9_g77.nc", "ab9", "milltronics"),
    ("examples/ab9_g77.nc", "ab9", "ab9grind"),
])
def test_a_program_for_a_target_of_the_other_kind_is_refused_naming_the_option(example, dialect, to):
    tool = ["--tool-diameter", "0.25"] if dialect == "milltronics" else []
    status, out, err = run_inline(["expand", example, "--dialect", dialect, "--to", to] + tool)
    assert (status, out) == (2, "")
    assert err.startswith("%s:0: --to %s: %s is a " % (example, to, to)) and err.count("\n") == 1
    assert "internal error" not in err


def test_a_tool_number_the_target_cannot_hold_is_refused_naming_it(tmp_path):
    # LinuxCNC's rs274 reads T2147483648 as a negative tool id: never written
    path = tmp_path / "t.mpf"
    path.write_text("T2147483648 D1\nM30\n")
    status, out, err = run_inline(["expand", str(path), "--dialect", "sinumerik"])
    assert (status, out) == (2, "")
    assert err.endswith("t.mpf:1: tool number 2147483648 cannot be written for linuxcnc (0 to 99999)\n")


def test_a_spindle_speed_that_would_be_written_as_zero_is_refused(tmp_path):
    # S0.000001 under feed per revolution would be written S0.: the spindle would not turn
    path = tmp_path / "s.mpf"
    path.write_text("G95 S0.000001 M03\nG0 X10. Z0.\nG1 X5. F0.1\nM30\n")
    status, out, err = run_inline(["expand", str(path), "--dialect", "sinumerik"])
    assert (status, out) == (2, "")
    assert err.endswith("s.mpf:1: S0.000001 rounds to 0 in the output (4 decimals): the spindle would not turn\n")


def test_output_naming_the_program_itself_is_refused_and_the_program_kept(tmp_path):
    program = tmp_path / "part.nc"
    text = "G21 G98\nG0 X50. Z2.\nM30\n"
    program.write_text(text)
    link = tmp_path / "same.nc"
    link.symlink_to("part.nc")
    for out in (program, link):
        status, stdout, err = run_inline(["expand", str(program), "--dialect", "fanuc", "-o", str(out)])
        assert (status, stdout) == (2, "")
        assert err == "%s:0: -o names the program being read (%s): write the output to another file\n" % (
            out, program)
    assert program.read_text() == text and sorted(p.name for p in tmp_path.iterdir()) == ["part.nc", "same.nc"]


# ---------------------------------------------------------------- bounded input


@pytest.mark.parametrize("command", ["expand", "verify"])
def test_a_line_longer_than_the_bound_is_refused_on_its_line(tmp_path, command):
    path = tmp_path / "long.nc"
    path.write_text("G21 G98\nG0 X" + "1" * 70000 + ".\nM30\n")
    status, out, err = run_inline([command, str(path), "--dialect", "fanuc", "--tool-width", "3"])
    assert (status, out) == (2, "")
    assert err == "%s:2: the line is longer than 65536 characters\n" % path


def test_a_program_that_is_not_text_is_refused_at_its_first_nul_byte(tmp_path):
    path = tmp_path / "zeros.nc"
    path.write_bytes(b"G21 G98\nG0 X1.\n\0\0\0")
    status, out, err = run_inline(["expand", str(path), "--dialect", "fanuc"])
    assert (status, out, err) == (2, "", "%s:3: a NUL byte: the program is not a text file\n" % path)


def test_dev_zero_as_the_program_or_the_tool_table_is_refused_at_once():
    status, out, err = run_inline(["expand", "/dev/zero", "--dialect", "fanuc"])
    assert (status, out, err) == (2, "", "/dev/zero:1: a NUL byte: the program is not a text file\n")
    status, out, err = run_inline(["expand", "examples/fanuc_g75.nc", "--dialect", "fanuc", "--tool-width", "3",
                                   "--tool-table", "/dev/zero"])
    assert (status, out, err) == (2, "", "/dev/zero:1: a NUL byte: the tool table is not a text file\n")


def test_a_tool_table_longer_than_the_bound_is_refused(tmp_path, monkeypatch):
    from freecad_groove import cli_io

    monkeypatch.setattr(cli_io, "MAX_TABLE_BYTES", 100)
    path = tmp_path / "tools.tbl"
    path.write_text("5 3.0 0.2 minus\n" * 10)
    status, out, err = run_inline(["expand", "examples/fanuc_g75.nc", "--dialect", "fanuc", "--tool-width", "3",
                                   "--tool-table", str(path)])
    assert (status, out, err) == (2, "", "%s:0: the tool table is longer than 100 bytes\n" % path)


@pytest.mark.parametrize("source", ["file", "stdin"])
def test_a_short_program_read_whole_reserves_no_memory_for_the_bound(tmp_path, monkeypatch, source):
    # read(limit + 1) reserved the bound (1 GiB) before reading a byte: verify of a five-line program stopped
    # with "internal error (MemoryError)" under a 700 MB address-space limit.
    import tracemalloc

    from freecad_groove import cli_io

    path = tmp_path / "part.nc"
    path.write_text("G21 G98\nG0 X40. Z2.\nM30\n")
    if source == "stdin":
        stdin = io.TextIOWrapper(open(path, "rb"))  # a real file's buffer, as a pipe's; closed below
        monkeypatch.setattr(sys, "stdin", stdin)
    tracemalloc.start()
    try:
        name, text = cli_io.read_text(str(path) if source == "file" else "-", "the program", cli_io.MAX_PROGRAM_BYTES)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    if source == "stdin":
        stdin.close()
    assert text == path.read_text()
    assert peak < 4 * cli_io.CHUNK, "%d bytes at the peak reading a 26-byte program" % peak


def test_a_program_longer_than_the_bound_read_whole_is_refused_naming_the_bound(tmp_path, monkeypatch):
    from freecad_groove import cli_io

    monkeypatch.setattr(cli_io, "MAX_PROGRAM_BYTES", 100)
    path = tmp_path / "long.nc"
    path.write_text("G0 X40. Z2.\n" * 20)
    status, out, err = run_inline(["verify", str(path), "--dialect", "fanuc", "--tool-width", "3"])
    assert (status, out, err) == (2, "", "%s:0: the program is longer than 100 bytes\n" % path)


def test_running_out_of_memory_is_said_in_one_line(monkeypatch):
    from freecad_groove import cli_verify

    def exhausted(*_args):
        raise MemoryError()

    monkeypatch.setattr(cli_verify, "_check", exhausted)
    status, out, err = run_inline(["verify", "examples/fanuc_g75.nc", "--dialect", "fanuc", "--tool-width", "3"])
    assert (status, out) == (2, "")
    assert err == ("examples/fanuc_g75.nc:0: out of memory: the run needs more memory than this machine gives it "
                   "(verify and plot hold the whole program's moves)\n")


@pytest.mark.parametrize("command", ["expand", "verify"])
def test_running_out_of_memory_inside_a_cycle_is_said_as_out_of_memory(monkeypatch, command):
    # The translator turned any exception on a line into "internal error (...)": MemoryError too, so a cycle
    # that ran out of memory said "internal error (MemoryError: )" instead of the out-of-memory line.
    from freecad_groove.engine.cycles import pecking

    def exhausted(*_args, **_kwargs):
        raise MemoryError()

    monkeypatch.setattr(pecking.PeckingCycle, "expand", exhausted)
    status, out, err = run_inline([command, "examples/fanuc_g75.nc", "--dialect", "fanuc", "--tool-width", "3"])
    assert (status, out) == (2, "")
    held = " (verify and plot hold the whole program's moves)" if command == "verify" else ""  # expand streams
    assert err == ("examples/fanuc_g75.nc:0: out of memory: the run needs more memory than this machine gives it"
                   "%s\n" % held)


# ---------------------------------------------------------------- words that once made internal errors


@pytest.mark.parametrize("dialect", ["fanuc", "haas", "gsk"])
def test_a_g_word_with_a_sign_is_refused_naming_it(tmp_path, dialect):
    path = tmp_path / "g.nc"
    path.write_text("G21 G98\nG-.5 X1.\nM30\n")
    status, out, err = run_inline(["expand", str(path), "--dialect", dialect])
    assert (status, out) == (2, "")
    assert err == "%s:2: G-.5 is not a G code: a G word is a whole number, or one with a decimal such as G7.1\n" % path


@pytest.mark.parametrize("dialect, block, message", [
    ("fanuc", "M%s T0101", "M9999999999... is not supported (machine-specific M codes are not translated)"),
    ("sinumerik", "T5 D1 M%s", "M9999999999... is not supported (machine-specific M codes are not translated)"),
    # Milltronics reads T with M6 only: the M word is not M6
    ("milltronics", "T1 M%s", "T1 without M6: a tool selected for a later change is not translated; program the "
                              "tool change as T1 M6 in one block"),
])
def test_an_m_word_too_large_for_a_float_is_refused_in_one_line(tmp_path, dialect, block, message):
    path = tmp_path / "m.nc"
    path.write_text(("G21\n" if dialect != "sinumerik" else "") + block % ("9" * 400) + "\nM30\n")
    tool = ["--tool-diameter", "1"] if dialect == "milltronics" else []
    status, out, err = run_inline(["expand", str(path), "--dialect", dialect] + tool)
    line = 1 if dialect == "sinumerik" else 2
    assert (status, out, err) == (2, "", "%s:%d: %s\n" % (path, line, message))
