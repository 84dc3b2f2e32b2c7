"""Writing a posted program to the file the user chose: atomically
(engine/output/files.py: the old file or the new one, never a torn one; links
followed, anything but a regular file refused), a refusal as PostError."""

from ...engine.output.files import write_atomically
from .post_error import PostError


def write_program_file(filename: str, text: str) -> None:
    """``text`` into ``filename``; PostError naming the file and why it cannot be written."""
    try:
        write_atomically(filename, text)
    except OSError as e:
        raise PostError("cannot write %s: %s" % (filename, e.strerror or e)) from None
