"""Writing a finished program to a file so that it is never half written."""

import os
import tempfile


def write_atomically(filename: str, text: str, encoding: str = "utf-8", errors: str = "strict") -> None:
    """Write ``text`` to ``filename`` through a temporary file in the same
    folder renamed over it: the file is either the old one (keeping its
    permissions) or the whole new one. OSError propagates; the temporary file
    never stays behind."""
    folder = os.path.dirname(os.path.abspath(filename))
    try:
        mode = os.stat(filename).st_mode & 0o7777
    except FileNotFoundError:
        umask = os.umask(0)
        os.umask(umask)
        mode = 0o666 & ~umask
    fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(filename) + ".", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "w", encoding=encoding, errors=errors, newline="\n") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, mode)
        os.replace(tmp, filename)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
