"""Streaming (issue 9, item 13): the translation is made block by block from
lines read one at a time (engine.translator.iter_translation), written through
a temporary file as it comes (engine.output.write_chunks_atomically), and
nothing reaches OUT or stdout before the whole run succeeded."""

import io
import os
import subprocess
import sys

import pytest
from conftest import ROOT
from hypothesis import given
from hypothesis import strategies as st
from test_cli import assert_one_error_line, run

from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.output import files
from freecad_groove.engine.output.files import write_chunks_atomically
from freecad_groove.engine.translator import iter_translation, program_lines, translate_program

BLADE = Settings(tool=GroovingTool(3.0, 0.4))
CALL = "CYCLE93(35, %g, 10, 6, 0, 10, 15, 0.5, 0.5, -1, -1, 0.3, 0.2, 2, 0.5, 5, 0)"


def grooves(n, end="N60 M02"):
    """A Siemens program of n featured CYCLE93 calls along a shaft, as lines."""
    lines = ["N10 T5 D1 S400 M03", "N20 G95 G90 F0.2", "N30 G00 X80 Z65"]
    for k in range(n):
        lines += ["G00 X80 Z%g" % (5 - 40 * k), CALL % (-40 * k)]
    return lines + [end]


class Broken(Exception):
    pass


def feed(lines, log, fail_after=None):
    """Yield ``lines`` (each with its newline), logging how many were taken;
    raise Broken instead of the line after ``fail_after``."""
    for index, line in enumerate(lines):
        if index == fail_after:
            raise Broken("the input broke off")
        log.append(index)
        yield line + "\n"


# ---------------------------------------------------------------- engine


def test_the_translation_comes_out_before_the_input_is_read_whole():
    lines = grooves(50)
    taken = []
    chunks = iter_translation(feed(lines, taken, fail_after=10), "sinumerik", BLADE)
    out = []
    with pytest.raises(Broken):
        for chunk in chunks:
            out.append((len(taken), chunk))
    text = "".join(chunk for _, chunk in out)
    # the calls of lines 5, 7, 9
    assert text.splitlines()[1].startswith("G18 G7 G21 G90") and text.count("(CYCLE93") == 3
    # each chunk is the output of the line just read: at most one line read ahead
    assert [n for n, _ in out] == sorted(n for n, _ in out) and out[-1][0] == 10
    assert translate_program("".join(line + "\n" for line in lines[:10]), "sinumerik", BLADE).startswith(text)


def test_no_output_line_is_held_once_it_is_yielded():
    chunks = iter_translation(feed(grooves(20), []), "sinumerik", BLADE)
    frame = chunks.gi_frame
    held = []
    for _chunk in chunks:
        if chunks.gi_frame is not None:
            held.append(len(frame.f_locals["self"].body))
    assert held[0] == 1  # the header comes out first, the first line's output next
    assert len(held) > 20 and max(held[1:]) == 0


@pytest.mark.parametrize("program", [
    "\n".join(grooves(3)) + "\n",
    "\r\n".join(grooves(3)),
    "\r".join(grooves(2)) + "\r",
])
def test_the_chunks_join_to_translate_program(program):
    whole = translate_program(program, "sinumerik", BLADE)
    assert "".join(iter_translation(program, "sinumerik", BLADE)) == whole
    from_file = io.StringIO(program, newline="")  # a text file's lines, ends of line kept
    assert "".join(iter_translation(from_file, "sinumerik", BLADE)) == whole


def test_the_header_waits_for_the_program_number():
    program = "%\n(made by hand)\nO1234 (a groove)\nG21 G98\nG0 X80. Z5.\nM30\n%\n"
    chunks = list(iter_translation(io.StringIO(program), "fanuc", target="fanuc"))
    assert "".join(chunks) == translate_program(program, "fanuc", target="fanuc")
    assert chunks[0].startswith("%\nO1234 (")
    assert "".join(chunks).index("(made by hand)") > "".join(chunks).index("O1234")


@given(st.lists(st.sampled_from(["G0 X1. Z2.", "", "(c)", "\r", "\n", "\r\n", "M30"]), max_size=12))
def test_program_lines_reads_a_file_as_the_text_is_split(parts):
    text = "".join(parts)
    assert list(program_lines(io.StringIO(text, newline=""))) == list(program_lines(text))


def test_an_error_comes_after_the_lines_before_it():
    lines = grooves(5, end="G1 X40. Z-1. F0.1 Q7")
    out = []
    with pytest.raises(ProgramError) as info:
        for chunk in iter_translation(iter(line + "\n" for line in lines), "sinumerik", BLADE):
            out.append(chunk)
    assert info.value.line == len(lines) and "".join(out).count("(CYCLE93") == 5


# ---------------------------------------------------------------- write_chunks_atomically


@pytest.mark.parametrize("named", [False, True], ids=["unnamed", "named"])
def test_chunks_go_to_the_temporary_file_and_the_target_waits(tmp_path, monkeypatch, named):
    # the temporary file has a name while it is written only where the system has no unnamed ones
    if named:
        monkeypatch.setattr(files, "_unnamed", lambda folder: None)
    else:
        fd = files._unnamed(str(tmp_path))
        if fd is None:
            pytest.skip("this system or file system has no unnamed temporary files (O_TMPFILE)")
        os.close(fd)
    target = tmp_path / "part.ngc"
    target.write_text("old\n")
    seen = []

    def chunks():
        for k in range(3):
            yield "G0 X%d.\n" % k
            seen.append((target.read_text(), sorted(os.listdir(tmp_path))))

    write_chunks_atomically(str(target), chunks())
    assert target.read_text() == "G0 X0.\nG0 X1.\nG0 X2.\n" and os.listdir(tmp_path) == ["part.ngc"]
    assert all(old == "old\n" and len(names) == (2 if named else 1) for old, names in seen)


def test_an_error_from_the_chunks_leaves_the_target_and_no_temporary_file(tmp_path):
    target = tmp_path / "part.ngc"
    target.write_text("old\n")
    with pytest.raises(Broken):
        write_chunks_atomically(str(target), feed(["G0 X1."] * 100, [], fail_after=50))
    assert target.read_text() == "old\n" and os.listdir(tmp_path) == ["part.ngc"]


def test_chunks_are_encoded_as_one_text(tmp_path):
    target = tmp_path / "part.txt"
    write_chunks_atomically(str(target), iter(["ab", "c\u00e9", "\n"]), encoding="utf-16")
    assert target.read_bytes() == "abc\u00e9\n".encode("utf-16")  # one byte order mark


# ---------------------------------------------------------------- the command line


def long_program_failing_late(tmp_path):
    program = tmp_path / "long.mpf"
    lines = grooves(30, end="G1 X40. Z-1. F0.1 Q7")
    program.write_text("\n".join(lines) + "\n")
    return program, len(lines)


def test_an_error_late_in_a_long_program_writes_nothing_to_stdout(tmp_path):
    program, last = long_program_failing_late(tmp_path)
    proc = run("expand", str(program), "--dialect", "sinumerik", "--tool-width", "3")
    assert_one_error_line(proc, str(program), last, "Q7")


def test_an_error_late_in_a_long_program_leaves_out_untouched(tmp_path):
    program, last = long_program_failing_late(tmp_path)
    out = tmp_path / "part.ngc"
    out.write_text("old program\n")
    proc = run("expand", str(program), "--dialect", "sinumerik", "--tool-width", "3", "-o", str(out))
    assert_one_error_line(proc, str(program), last, "Q7")
    assert out.read_text() == "old program\n" and sorted(os.listdir(tmp_path)) == ["long.mpf", "part.ngc"]


def test_standard_input_and_a_pipe_are_read_as_a_file_is(tmp_path):
    program = b"(caf\xe9)\r\n" + "\r\n".join(grooves(2)).encode() + b"\r\n"  # not UTF-8: read as Latin-1
    path = tmp_path / "p.mpf"
    path.write_bytes(program)
    args = ["expand", "--dialect", "sinumerik", "--tool-width", "3"]
    from_file = run(*args[:1], str(path), *args[1:])
    assert from_file.returncode == 0 and b"(caf?)" in from_file.stdout  # one character, not two
    from_stdin = run(*args[:1], "-", *args[1:], stdin=program)
    assert from_stdin.stdout == from_file.stdout.replace(b"p.mpf:", b"stdin:")
    piped = subprocess.run(["sh", "-c", 'cat "$1" | "$0" -m freecad_groove expand /dev/stdin --dialect sinumerik '
                            "--tool-width 3", sys.executable, str(path)], cwd=ROOT, capture_output=True, timeout=120)
    assert piped.returncode == 0 and piped.stdout == from_file.stdout.replace(b"p.mpf:", b"stdin:")
