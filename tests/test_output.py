"""Writing files (freecad_groove.engine.output.write_atomically, shared by the
command line's -o and the posts): the file the user meant (symbolic links
followed, the link kept), nothing but a regular file or a new path written,
write-protected files and folders refused (as root too), mode and owner kept,
no temporary file left, even when a signal arrives while it is created. The
temporary file is unnamed while it is written where Linux allows it
(O_TMPFILE), else named from the start: the tests marked with the
``temporary`` fixture run both ways."""

import os
import re
import signal
import socket
import stat

import pytest

from freecad_groove.engine.output import files as output
from freecad_groove.engine.output.files import write_atomically

TEMP_NAME = re.compile(r"^\.(?P<name>.+)\.[^.]+\.tmp\Z")


def listing(folder):
    return sorted(os.listdir(folder))


def refused(path, fragment):
    """write_atomically refuses ``path`` with a message holding ``fragment``."""
    with pytest.raises(OSError) as info:
        write_atomically(str(path), "new\n")
    assert type(info.value).__name__ == "OutputRefused", repr(info.value)
    assert fragment in info.value.strerror, info.value.strerror
    return info.value.strerror


@pytest.fixture(params=["unnamed", "named"])
def temporary(request, monkeypatch, tmp_path):
    """The kind of temporary file write_atomically uses: unnamed while written
    (Linux O_TMPFILE), or named from the start (output._unnamed says none)."""
    if request.param == "named":
        monkeypatch.setattr(output, "_unnamed", lambda folder: None)
    else:
        fd = output._unnamed(str(tmp_path))
        if fd is None:
            pytest.skip("this system or file system has no unnamed temporary files (O_TMPFILE)")
        os.close(fd)
    return request.param


@pytest.fixture
def renames(monkeypatch):
    """Every (source, destination) os.replace is called with."""
    calls = []
    real = os.replace

    def replace(src, dst, *args, **kwargs):
        calls.append((str(src), str(dst)))
        return real(src, dst, *args, **kwargs)

    monkeypatch.setattr(os, "replace", replace)
    return calls


# ---------------------------------------------------------------- the file the user meant


def test_a_new_file_and_a_replaced_one(tmp_path, temporary, renames):
    path = tmp_path / "prog.nc"
    write_atomically(str(path), "G0 X1.\n")
    assert path.read_text() == "G0 X1.\n" and listing(tmp_path) == ["prog.nc"]
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~umask
    path.write_text("old\n")
    os.chmod(path, 0o640)
    write_atomically(str(path), "G0 X2.\n")
    assert path.read_text() == "G0 X2.\n" and stat.S_IMODE(path.stat().st_mode) == 0o640
    assert listing(tmp_path) == ["prog.nc"]
    # the temporary file: next to the target, named .NAME.XXXXXXXX.tmp
    for src, dst in renames:
        assert os.path.dirname(src) == str(tmp_path) and dst == str(path)
        assert TEMP_NAME.match(os.path.basename(src)).group("name") == "prog.nc"


def test_a_symbolic_link_is_followed_and_stays_a_link(tmp_path, temporary, renames):
    here, there = tmp_path / "here", tmp_path / "there"
    here.mkdir()
    there.mkdir()
    target = there / "prog.nc"
    target.write_text("old\n")
    os.chmod(target, 0o604)
    link = here / "prog.nc"
    link.symlink_to(os.path.join("..", "there", "prog.nc"))
    chain = here / "chain.nc"  # a link to the link
    chain.symlink_to("prog.nc")
    write_atomically(str(chain), "new\n")
    assert link.is_symlink() and chain.is_symlink() and os.readlink(link) == os.path.join("..", "there", "prog.nc")
    assert target.read_text() == "new\n" and stat.S_IMODE(target.stat().st_mode) == 0o604
    assert listing(here) == ["chain.nc", "prog.nc"] and listing(there) == ["prog.nc"]
    # the temporary file went into the target's folder, so the rename stays on its file system
    assert [os.path.dirname(src) for src, _ in renames] == [str(there)]
    assert TEMP_NAME.match(os.path.basename(renames[0][0])).group("name") == "prog.nc"


def test_a_dangling_link_gets_its_target_created(tmp_path):
    link = tmp_path / "prog.nc"
    link.symlink_to("real.nc")
    write_atomically(str(link), "new\n")
    assert link.is_symlink() and (tmp_path / "real.nc").read_text() == "new\n"
    broken = tmp_path / "broken.nc"
    broken.symlink_to(os.path.join("missing", "real.nc"))
    refused(broken, "the folder %s does not exist" % (tmp_path / "missing"))
    loop = tmp_path / "loop.nc"
    loop.symlink_to("loop.nc")
    with pytest.raises(OSError):
        write_atomically(str(loop), "new\n")
    assert loop.is_symlink() and os.readlink(loop) == "loop.nc"


# ---------------------------------------------------------------- what is never written


def test_a_named_pipe_is_refused(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    assert refused(fifo, "named pipe") == "it is a named pipe (FIFO), not a regular file"
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode) and listing(tmp_path) == ["pipe"]
    link = tmp_path / "to-pipe"
    link.symlink_to("pipe")
    assert refused(link, "named pipe") == "its link target %s is a named pipe (FIFO), not a regular file" % fifo
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode) and link.is_symlink()


def test_a_device_node_is_refused(tmp_path):
    node = tmp_path / "null"
    try:
        os.mknod(node, stat.S_IFCHR | 0o666, os.makedev(1, 3))  # a node of /dev/null, made here
    except (PermissionError, AttributeError):
        pytest.skip("making a device node needs root")
    refused(node, "a character device, not a regular file")
    assert stat.S_ISCHR(os.lstat(node).st_mode) and listing(tmp_path) == ["null"]
    # a link to a real device: the device is named
    link = tmp_path / "full.nc"
    link.symlink_to("/dev/full")
    refused(link, "its link target /dev/full is a character device")
    assert stat.S_ISCHR(os.lstat("/dev/full").st_mode)


def test_a_directory_and_a_socket_are_refused(tmp_path):
    folder = tmp_path / "folder"
    folder.mkdir()
    refused(folder, "it is a directory, not a regular file")
    refused(str(tmp_path / "new") + "/", "a folder, not a file")
    assert not (tmp_path / "new").exists()
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    try:
        sock.bind(str(tmp_path / "sock"))
        refused(tmp_path / "sock", "it is a socket, not a regular file")
        assert stat.S_ISSOCK(os.lstat(tmp_path / "sock").st_mode)
    finally:
        sock.close()
    assert listing(tmp_path) == ["folder", "sock"]


def test_a_write_protected_file_is_refused_even_for_root(tmp_path):
    # Root's writes are not stopped by the permission bits: a file without its
    # owner's write bit is refused explicitly (for everyone else os.access says no).
    path = tmp_path / "prog.nc"
    path.write_text("keep me\n")
    os.chmod(path, 0o444)
    assert refused(path, "write-protected") == "it is write-protected (mode 0444)"
    assert path.read_text() == "keep me\n" and stat.S_IMODE(path.stat().st_mode) == 0o444
    link = tmp_path / "link.nc"
    link.symlink_to("prog.nc")
    refused(link, "its link target %s is write-protected" % path)
    assert listing(tmp_path) == ["link.nc", "prog.nc"]


def test_a_missing_or_write_protected_folder_is_refused(tmp_path):
    refused(tmp_path / "no" / "prog.nc", "the folder %s does not exist" % (tmp_path / "no"))
    plain = tmp_path / "plain"
    plain.write_text("a file\n")
    refused(plain / "prog.nc", "is not a folder")
    refused(plain / "sub" / "prog.nc", "the folder %s does not exist" % (plain / "sub"))
    locked = tmp_path / "locked"
    locked.mkdir()
    os.chmod(locked, 0o555)
    try:
        refused(locked / "prog.nc", "the folder %s is write-protected (mode 0555)" % locked)
        assert listing(locked) == []
    finally:
        os.chmod(locked, 0o755)


def test_owner_and_group_are_kept_where_the_user_may_set_them(tmp_path):
    if not hasattr(os, "geteuid") or os.geteuid() != 0:
        pytest.skip("giving a file to another owner needs root")
    path = tmp_path / "prog.nc"
    path.write_text("old\n")
    os.chown(path, 4321, 4322)
    os.chmod(path, 0o664)
    write_atomically(str(path), "new\n")
    st = path.stat()
    assert (st.st_uid, st.st_gid, stat.S_IMODE(st.st_mode)) == (4321, 4322, 0o664)
    assert path.read_text() == "new\n"


# ---------------------------------------------------------------- interrupted writes


class Stop(BaseException):
    pass


@pytest.fixture
def sigterm_raises():
    """SIGTERM raises Stop in this process for the test's duration."""

    def handler(signum, frame):
        raise Stop(signum)

    previous = signal.signal(signal.SIGTERM, handler)
    yield
    signal.signal(signal.SIGTERM, previous)


def test_a_signal_the_instant_the_temporary_file_is_made_still_removes_it(tmp_path, monkeypatch, sigterm_raises):
    # A named temporary file (where there are no unnamed ones): the handler runs
    # right after the file is made, before the call that made it returns:
    # write_atomically must know the name already.
    monkeypatch.setattr(output, "_unnamed", lambda folder: None)
    real = os.open

    def open_then_signal(path, flags, *args, **kwargs):
        fd = real(path, flags, *args, **kwargs)
        if flags & os.O_CREAT:
            os.kill(os.getpid(), signal.SIGTERM)
        return fd

    monkeypatch.setattr(os, "open", open_then_signal)
    path = tmp_path / "prog.nc"
    path.write_text("old\n")
    with pytest.raises(Stop):
        write_atomically(str(path), "new\n")
    assert listing(tmp_path) == ["prog.nc"] and path.read_text() == "old\n"


def test_a_free_temporary_name_is_found(tmp_path, monkeypatch, temporary, renames):
    # The first name drawn is taken by another file, which is left alone.
    names = iter(["taken", "free"])
    monkeypatch.setattr(output.secrets, "token_hex", lambda n: next(names))
    other = tmp_path / ".prog.nc.taken.tmp"
    other.write_text("not ours\n")
    write_atomically(str(tmp_path / "prog.nc"), "new\n")
    assert other.read_text() == "not ours\n" and listing(tmp_path) == [".prog.nc.taken.tmp", "prog.nc"]
    assert renames == [(str(tmp_path / ".prog.nc.free.tmp"), str(tmp_path / "prog.nc"))]


def test_an_exception_while_writing_removes_the_temporary_file(tmp_path, monkeypatch, temporary, sigterm_raises):
    def fsync(fd):
        os.kill(os.getpid(), signal.SIGTERM)

    monkeypatch.setattr(output.os, "fsync", fsync)
    path = tmp_path / "prog.nc"
    with pytest.raises(Stop):
        write_atomically(str(path), "new\n")
    assert listing(tmp_path) == []


def test_a_signal_between_the_link_and_the_rename_removes_the_linked_name(tmp_path, monkeypatch, sigterm_raises):
    # the one step where an unnamed temporary file has a name: a signal there still leaves nothing behind
    if output._unnamed(str(tmp_path)) is None:
        pytest.skip("this system or file system has no unnamed temporary files (O_TMPFILE)")

    def replace(src, dst):
        os.kill(os.getpid(), signal.SIGTERM)

    monkeypatch.setattr(output.os, "replace", replace)
    path = tmp_path / "prog.nc"
    path.write_text("old\n")
    with pytest.raises(Stop):
        write_atomically(str(path), "new\n")
    assert listing(tmp_path) == ["prog.nc"] and path.read_text() == "old\n"
