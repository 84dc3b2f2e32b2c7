"""The command line's output (python3 -m freecad_groove): what -o refuses, a
full or closed standard output, a broken pipe, SIGINT/SIGTERM/SIGHUP while it
runs (one line PROGRAM:0: interrupted, exit 128 + the signal, no temporary
file), and words with more digits than a number may have."""

import os
import signal
import stat
import subprocess
import sys
import time

import pytest
from conftest import ROOT
from test_cli import SEED, assert_one_error_line, only_warnings, run

from freecad_groove.engine.output import files

TOO_LONG = "1" * 4301  # one digit more than a number may have (numbers.MAX_DIGITS)
SIGNALS = [(signal.SIGINT, 130), (signal.SIGTERM, 143), (signal.SIGHUP, 129)]


def expand_to(out):
    return run("expand", SEED, "--dialect", "sinumerik", "--tool-width", "3", "-o", str(out))


# ---------------------------------------------------------------- -o


def test_output_through_a_symbolic_link(tmp_path):
    (tmp_path / "jobs").mkdir()
    real = tmp_path / "jobs" / "part.ngc"
    real.write_text("old\n")
    link = tmp_path / "part.ngc"
    link.symlink_to(real)
    proc = expand_to(link)
    assert proc.returncode == 0 and only_warnings(proc.stderr)
    assert link.is_symlink() and real.read_text().splitlines()[1].startswith("G18 G7")
    assert sorted(os.listdir(tmp_path)) == ["jobs", "part.ngc"] and os.listdir(tmp_path / "jobs") == ["part.ngc"]


def test_output_refuses_what_is_not_a_regular_file(tmp_path):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    assert_one_error_line(expand_to(fifo), str(fifo), 0,
                          "cannot write the output: it is a named pipe (FIFO), not a regular file")
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert_one_error_line(expand_to(tmp_path), str(tmp_path), 0, "it is a directory, not a regular file")
    link = tmp_path / "full.ngc"
    link.symlink_to("/dev/full")
    assert_one_error_line(expand_to(link), str(link), 0, "its link target /dev/full is a character device")
    assert link.is_symlink() and stat.S_ISCHR(os.stat("/dev/full").st_mode)
    assert sorted(os.listdir(tmp_path)) == ["fifo", "full.ngc"]


def test_output_refuses_a_write_protected_file(tmp_path):
    out = tmp_path / "part.ngc"
    out.write_text("keep me\n")
    os.chmod(out, 0o444)
    assert_one_error_line(expand_to(out), str(out), 0, "cannot write the output: it is write-protected (mode 0444)")
    assert out.read_text() == "keep me\n" and os.listdir(tmp_path) == ["part.ngc"]
    locked = tmp_path / "locked"
    locked.mkdir(mode=0o555)
    try:
        assert_one_error_line(expand_to(locked / "new.ngc"), str(locked / "new.ngc"), 0, "write-protected (mode 0555)")
        assert os.listdir(locked) == []
    finally:
        os.chmod(locked, 0o755)


# ---------------------------------------------------------------- standard output


def test_a_full_standard_output():
    with open("/dev/full", "wb") as full:
        proc = subprocess.run([sys.executable, "-m", "freecad_groove", "expand", SEED, "--dialect", "sinumerik",
                               "--tool-width", "3"], cwd=ROOT, stdout=full, stderr=subprocess.PIPE, timeout=120)
    assert proc.returncode == 2
    assert proc.stderr == b"<stdout>:0: cannot write the output: No space left on device\n"


def test_a_closed_standard_output():
    proc = subprocess.run(["sh", "-c", 'exec "$0" -m freecad_groove emit g77 -X 40 -I 2 -D 0 >&-', sys.executable],
                          cwd=ROOT, stderr=subprocess.PIPE, timeout=120)
    assert proc.returncode == 2
    assert proc.stderr == b"<stdout>:0: cannot write the output: standard output is closed\n"


def test_a_broken_pipe_ends_quietly_with_status_1():
    program = "G21 G98\nG0 X80. Z5.\n" + "G1 X40. Z-1. F100.\nG1 X41. Z-2.\n" * 20000 + "M30\n"
    child = subprocess.Popen([sys.executable, "-m", "freecad_groove", "expand", "-", "--dialect", "fanuc"], cwd=ROOT,
                             stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    child.stdout.close()  # nobody reads: the first write breaks the pipe
    _, err = child.communicate(program.encode(), timeout=120)
    assert child.returncode == 1 and err == b""


# ---------------------------------------------------------------- signals


def default_signals():
    """In the child: the signals tested at their default disposition, whatever this process inherited (under
    nohup SIGHUP is ignored, and the command line keeps a signal ignored at its start ignored)."""
    for sig, _status in SIGNALS:
        signal.signal(sig, signal.SIG_DFL)


def wait_for(condition, child, what):
    deadline = time.monotonic() + 60
    while not condition():
        assert child.poll() is None, child.communicate()
        assert time.monotonic() < deadline, "timed out waiting for " + what
        time.sleep(0.01)


def signalled_while_reading(sig, preexec_fn, rest=None):
    """(exit status, stdout, stderr) of the command line expanding stdin, sent ``sig`` while it reads the
    program; ``rest``: more of the program, written after the signal (None: stdin stays open)."""
    child = subprocess.Popen([sys.executable, "-m", "freecad_groove", "expand", "-", "--dialect", "fanuc"], cwd=ROOT,
                             stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             preexec_fn=preexec_fn)
    try:
        # More than a pipe holds: written only once the command line reads the
        # program, with its handlers in place; stdin stays open, it waits for more.
        child.stdin.write(b"G21 G98\n" + b"(a comment line)\n" * 20000)
        child.stdin.flush()
        child.send_signal(sig)
        out, err = child.communicate(rest, timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
    return child.returncode, out, err


@pytest.mark.parametrize("sig, status", SIGNALS)
def test_a_signal_while_reading_the_program(sig, status):
    assert signalled_while_reading(sig, default_signals) == (status, b"", b"<stdin>:0: interrupted\n")


def test_a_hangup_ignored_from_the_start_stays_ignored_as_under_nohup():
    def ignore_hangup():
        default_signals()
        signal.signal(signal.SIGHUP, signal.SIG_IGN)

    status, out, err = signalled_while_reading(signal.SIGHUP, ignore_hangup, b"G0 X80. Z5.\nG1 X40. F100.\nM30\n")
    assert status == 0, err
    assert b"X40" in out and b"interrupted" not in err


# The command line in a child whose file writes pause after the temporary file
# is written (os.fsync sleeps, after making the file PAUSED names): the signal
# arrives while the output is written. NAMED=1: a named temporary file (as
# where the system has no unnamed ones).
PAUSED_WRITER = """
import os, sys, time
from freecad_groove.engine.output import files
if os.environ.get("NAMED") == "1":
    files._unnamed = lambda folder: None
real_fsync = os.fsync
def fsync(fd):
    real_fsync(fd)
    open(os.environ["PAUSED"], "w").close()
    time.sleep(60)
os.fsync = fsync
from freecad_groove import cli
sys.exit(cli.main(sys.argv[1:]))
"""


def paused_writer(tmp_path, named):
    """A child writing ``tmp_path``/out/part.ngc (over an old program), paused with the whole text in its
    temporary file; (child, the output file)."""
    folder = tmp_path / "out"
    folder.mkdir()
    out = folder / "part.ngc"
    out.write_text("old program\n")
    paused = tmp_path / "paused"
    env = dict(os.environ, PAUSED=str(paused), NAMED="1" if named else "0")
    child = subprocess.Popen([sys.executable, "-c", PAUSED_WRITER, "expand", SEED, "--dialect", "sinumerik",
                              "--tool-width", "3", "-o", str(out)], cwd=ROOT, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, env=env, preexec_fn=default_signals)
    wait_for(paused.exists, child, "the paused write")
    return child, out


@pytest.mark.parametrize("named", [False, True], ids=["unnamed", "named"])
@pytest.mark.parametrize("sig, status", SIGNALS)
def test_a_signal_while_writing_the_output_leaves_no_temporary_file(tmp_path, sig, status, named):
    child, out = paused_writer(tmp_path, named)
    try:
        child.send_signal(sig)
        _, err = child.communicate(timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
    assert (child.returncode, err) == (status, ("%s:0: interrupted\n" % SEED).encode())
    assert os.listdir(out.parent) == ["part.ngc"] and out.read_text() == "old program\n"


def test_a_kill_9_while_writing_the_output_leaves_no_temporary_file(tmp_path):
    # the temporary file has no name while it is written (Linux O_TMPFILE): killed, it goes with the process
    fd = files._unnamed(str(tmp_path))
    if fd is None:
        pytest.skip("this system or file system has no unnamed temporary files (O_TMPFILE)")
    os.close(fd)
    child, out = paused_writer(tmp_path, named=False)
    child.kill()
    child.communicate(timeout=60)
    assert os.listdir(out.parent) == ["part.ngc"] and out.read_text() == "old program\n"


# ---------------------------------------------------------------- numbers with too many digits


@pytest.mark.parametrize("word", ["N", "G", "X", "M", "T"])
def test_a_word_with_too_many_digits(tmp_path, word):
    program = tmp_path / "long.nc"
    program.write_text("G21 G98\n%s%s\nM30\n" % (word, TOO_LONG))
    proc = run("expand", str(program), "--dialect", "fanuc")
    assert_one_error_line(proc, str(program), 2, "%s1111111111...: the number has more than 4300 digits" % word)


def test_a_cycle_word_with_too_many_digits():
    proc = run("emit", "fanuc-g75", "-X", "40", "-P", TOO_LONG)
    assert_one_error_line(proc, "emit fanuc-g75", 1, "G75 P=1111111111...: the number has more than 4300 digits")
    proc = run("emit", "cycle93", "--axfa", TOO_LONG)
    assert_one_error_line(proc, "emit cycle93", 1, "CYCLE93 AXFA=1111111111...: the number has more than 4300 digits")
