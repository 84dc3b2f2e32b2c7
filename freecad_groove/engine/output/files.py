"""Writing a finished program to a file so that it is never half written and
nothing else is ever destroyed (the command line's ``-o`` and the posts).

:func:`write_atomically` writes to the file the user meant:

* a symbolic link is followed to its final target: the target gets the new
  text, the link stays a link (a dangling link gets its target created);
* only a regular file or a new path is written: a directory, a named pipe, a
  device or a socket is refused;
* a file the user may not write is refused: whatever ``os.access`` says, and
  as root, whom the permission bits do not stop, a file without its owner's
  write bit (``chmod u-w``, mode 0444) too, so a write-protected file stays
  protected from the command line as from an editor;
* the folder must exist and be writable by the same rules (the new text goes
  through a temporary file there);
* the new text goes to a temporary file in the target's folder (chunk by
  chunk: nothing reaches the target before the last chunk), is flushed to
  disk, gets the target's mode (and owner and group where the user may set
  them: root always) and is renamed over the target: the file is either the
  old one or the whole new one, never a mix. A file with other hard links is
  replaced at this name only. On Linux the temporary file has no name while
  it is written (``O_TMPFILE``): it is linked as ``.NAME.XXXXXXXXXX.tmp`` only
  when whole, and renamed over the target at once; where the system or the
  file system has no unnamed files, it is ``.NAME.XXXXXXXXXX.tmp`` from the
  start.

A refused path raises :class:`OutputRefused`, an ``OSError`` whose
``strerror`` says why in one line; other ``OSError`` propagate. The temporary
file is removed on any error or exception, a ``KeyboardInterrupt`` or a signal
handler's exception included, and an exception raised by the iterable of
chunks (a translation error on a late line) too: a named one's name is chosen
before the file is made (``O_EXCL``), so an exception raised the instant after
still finds it. A kill -9 or a crash leaves a ``.NAME.*.tmp`` behind only
between its link and its rename (an unnamed file, whatever it held, goes with
the process), or, where there are no unnamed files, at any time while it is
written.
"""

import codecs
import errno
import os
import secrets
import stat
from typing import Iterable, Optional, Tuple

__all__ = ["OutputRefused", "write_atomically", "write_chunks_atomically"]

_NOT_REGULAR = (
    (stat.S_ISDIR, "a directory"),
    (stat.S_ISFIFO, "a named pipe (FIFO)"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


_BUFFER = 1 << 16  # bytes written to the temporary file at a time


class OutputRefused(OSError):
    """A path :func:`write_atomically` does not write; ``strerror`` says why."""

    def __init__(self, code: int, reason: str, filename: str) -> None:
        super().__init__(code, reason, filename)


def _is_root() -> bool:
    return hasattr(os, "geteuid") and os.geteuid() == 0


def _may_write(path: str, st: os.stat_result, access: int) -> bool:
    """Whether the user may write ``path``: ``os.access`` (which also says no
    on a read-only file system) and, for root, the owner's write bit."""
    return os.access(path, access) and not (_is_root() and not st.st_mode & stat.S_IWUSR)


def _refusal(path: str, st: os.stat_result, what: str) -> str:
    """Why the user may not write ``path`` (``what``: how the message names it)."""
    if hasattr(os, "statvfs") and os.statvfs(path).f_flag & os.ST_RDONLY:
        return "%s is on a read-only file system" % what
    if not st.st_mode & stat.S_IWUSR:
        return "%s is write-protected (mode %04o)" % (what, stat.S_IMODE(st.st_mode))
    return "no permission to write %s (mode %04o)" % (what, stat.S_IMODE(st.st_mode))


def _check_folder(filename: str, folder: str) -> None:
    try:
        st = os.stat(folder)
    except (FileNotFoundError, NotADirectoryError):
        raise OutputRefused(errno.ENOENT, "the folder %s does not exist" % folder, filename) from None
    if not stat.S_ISDIR(st.st_mode):
        raise OutputRefused(errno.ENOTDIR, "%s is not a folder" % folder, filename)
    if not _may_write(folder, st, os.W_OK | os.X_OK):
        raise OutputRefused(errno.EACCES, _refusal(folder, st, "the folder " + folder), filename)


def _resolve(filename: str) -> Tuple[str, Optional[os.stat_result]]:
    """The final target of ``filename`` and its stat (None for a new path),
    refusing what write_atomically does not write."""
    if filename.endswith(("/", os.sep)):
        raise OutputRefused(errno.EISDIR, "the name ends with '/': a folder, not a file", filename)
    target = os.path.realpath(filename)
    what = "it" if target == os.path.abspath(filename) else "its link target " + target
    try:
        st = os.stat(target)
    except (FileNotFoundError, NotADirectoryError):  # a new path; _check_folder says what is wrong with its folder
        st = None
    if st is not None:
        for test, kind in _NOT_REGULAR:
            if test(st.st_mode):
                raise OutputRefused(errno.EINVAL, "%s is %s, not a regular file" % (what, kind), filename)
        if not _may_write(target, st, os.W_OK):
            raise OutputRefused(errno.EACCES, _refusal(target, st, what), filename)
    _check_folder(filename, os.path.dirname(target))
    return target, st


def _temp_name(target: str) -> str:
    """A fresh name ``.NAME.XXXXXXXXXX.tmp`` next to ``target``."""
    folder, name = os.path.split(target)
    return os.path.join(folder, ".%s.%s.tmp" % (name, secrets.token_hex(5)))


def _create(path: str) -> int:
    """Make the file ``path``, which must not exist (FileExistsError)."""
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
    return os.open(path, flags, 0o600)


def _fill(fd: int, chunks: Iterable[str], encoder: codecs.IncrementalEncoder, old: Optional[os.stat_result]) -> None:
    """Write the encoded ``chunks`` to the temporary file ``fd`` (left open) and give it the old file's owner
    and mode (a new file: 0666 less the umask)."""
    with os.fdopen(fd, "wb", buffering=_BUFFER, closefd=False) as f:
        for chunk in chunks:
            f.write(encoder.encode(chunk))
        f.write(encoder.encode("", True))
        f.flush()
        os.fsync(f.fileno())
    if old is None:
        umask = os.umask(0)
        os.umask(umask)
        os.fchmod(fd, 0o666 & ~umask)
        return
    if hasattr(os, "fchown"):
        try:
            os.fchown(fd, old.st_uid, old.st_gid)
        except OSError:
            try:
                os.fchown(fd, -1, old.st_gid)  # the group alone, where the user belongs to it
            except OSError:
                pass
    os.fchmod(fd, stat.S_IMODE(old.st_mode))  # after chown, which clears set-id bits


def _unnamed(folder: str) -> Optional[int]:
    """An unnamed temporary file in ``folder`` (Linux O_TMPFILE, linked into place
    through /proc only when whole), or None where the system or the file system
    has none: then a named one is used."""
    flag = getattr(os, "O_TMPFILE", None)
    if flag is None or not os.path.isdir("/proc/self/fd"):
        return None
    try:
        return os.open(folder, flag | os.O_WRONLY, 0o600)
    except OSError:
        return None


def _link_into_place(fd: int, target: str) -> None:
    """Give the unnamed file ``fd`` a fresh name next to ``target`` and rename it over
    ``target``: a kill can leave a temporary file only between these two steps."""
    proc = os.open("/proc", os.O_RDONLY)
    try:
        for _attempt in range(100):
            tmp = _temp_name(target)
            try:  # linkat(AT_SYMLINK_FOLLOW) of /proc/self/fd/N: Python calls linkat only with a directory fd
                os.link("self/fd/%d" % fd, tmp, src_dir_fd=proc, follow_symlinks=True)
                break
            except FileExistsError:
                continue
        else:
            raise FileExistsError(errno.EEXIST, "no free name for the temporary file", target)
    finally:
        os.close(proc)
    try:
        os.replace(tmp, target)
    except BaseException:
        _remove(tmp)
        raise


def _remove(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass


def _sync_folder(folder: str) -> None:
    """Flush the rename to disk where the system allows it (POSIX)."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _write_named(target: str, chunks: Iterable[str], encoder: codecs.IncrementalEncoder,
                 old: Optional[os.stat_result]) -> None:
    """The text through a named temporary file next to ``target``, renamed over it."""
    tmp = None
    try:
        for _attempt in range(100):
            tmp = _temp_name(target)  # known before the file exists: any exception from here on removes it
            try:
                fd = _create(tmp)
                break
            except FileExistsError:
                tmp = None  # another file's name: not ours to remove
        else:
            raise FileExistsError(errno.EEXIST, "no free name for the temporary file", target)
        try:
            _fill(fd, chunks, encoder, old)
        finally:
            os.close(fd)
        os.replace(tmp, target)
    except BaseException:
        if tmp is not None:
            _remove(tmp)
        raise


def write_atomically(filename: str, text: str, encoding: str = "utf-8", errors: str = "strict") -> None:
    """Write ``text`` to the file ``filename`` means (see the module): the old
    file or the whole new one, nothing else touched, no temporary file left.
    Raises OutputRefused for a path it does not write, OSError on a failure."""
    write_chunks_atomically(filename, (text,), encoding, errors)


def write_chunks_atomically(filename: str, chunks: Iterable[str], encoding: str = "utf-8",
                            errors: str = "strict") -> None:
    """write_atomically for a text given in ``chunks`` (any iterable of str,
    e.g. a generator making the text as it goes): the path is checked before
    the first chunk is taken, each chunk is encoded and written to the
    temporary file as it comes, and the target is replaced after the last.
    An exception raised by ``chunks`` leaves the target untouched, removes the
    temporary file and propagates unchanged."""
    target, old = _resolve(filename)
    encoder = codecs.getincrementalencoder(encoding)(errors)
    fd = _unnamed(os.path.dirname(target))
    if fd is not None:
        try:
            _fill(fd, chunks, encoder, old)
            _link_into_place(fd, target)
        finally:
            os.close(fd)
    else:
        _write_named(target, chunks, encoder, old)
    _sync_folder(os.path.dirname(target))
