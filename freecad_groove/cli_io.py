"""The command line's input and output: its one-line failures
(``PROGRAM:LINE: message``), the program read a line at a time, the tool
table, the output written atomically (to OUT or, through an anonymous
temporary file, to standard output) and the report on standard error.
cli.py and cli_verify.py share them."""

import codecs
import contextlib
import io
import os
import sys
import tempfile
from typing import Any, Iterable, Iterator, Optional, Tuple

from .engine.output.files import write_chunks_atomically

CHUNK = 1 << 16  # characters or bytes read at a time
# Bounds on what is read, so that no input (a 40 MB line, /dev/zero, an endless pipe) holds memory or runs on:
MAX_LINE_CHARS = 1 << 16  # characters in one line of a program (a 4300-digit number fits many times over)
MAX_PROGRAM_BYTES = 1 << 30  # a program, read from a file or copied from standard input
MAX_TABLE_BYTES = 1 << 24  # a tool table


class Failure(Exception):
    """A run that stops: ``NAME:LINE: message`` on standard error, exit status 2."""

    def __init__(self, name: str, line: int, message: str) -> None:
        super().__init__(message)
        self.name = name
        self.line = line
        self.message = message

    @classmethod
    def of_program_error(cls, name: str, exc: Exception) -> "Failure":
        """``NAME:LINE: message`` for an engine ProgramError (line 0 when it has none)."""
        return cls(name, exc.line if exc.line is not None else 0, str(exc))


def unexpected(exc: Exception, command: str = "") -> str:
    """The one line said for an error no check foresaw: running out of memory, else an internal error;
    ``command``: the command that ran (verify and plot hold the program's moves: the line says so)."""
    if isinstance(exc, MemoryError):
        return "out of memory: the run needs more memory than this machine gives it%s" % (
            " (verify and plot hold the whole program's moves)" if command in ("verify", "plot") else "")
    return "internal error (%s: %s)" % (type(exc).__name__, exc)


def program_name(path: str) -> str:
    """How messages name a file given on the command line ("-": standard input)."""
    return "<stdin>" if path == "-" else path


def one_line(text: object) -> str:
    return " ".join(str(text).split())


def check_not_the_program(out: Optional[str], program: str) -> None:
    """A Failure when OUT is the program being read (the same file, through any
    name or link): the translation would replace its own source."""
    if out in (None, "-") or program == "-":
        return
    try:
        same = os.path.samefile(out, program)
    except OSError:  # OUT does not exist yet (or cannot be looked at: the write says why)
        return
    if same:
        raise Failure(out, 0, "-o names the program being read (%s): write the output to another file" % program)


def read_text(path: str, what: str, limit: Optional[int] = None) -> Tuple[str, str]:
    """A small text file (the tool table) read whole, at most ``limit`` bytes
    (default MAX_TABLE_BYTES): UTF-8, else Latin-1; a NUL byte is refused (not a
    text file)."""
    name = program_name(path)
    limit = MAX_TABLE_BYTES if limit is None else limit
    try:
        if path == "-":
            data = _read_at_most(sys.stdin.buffer, limit + 1)
        else:
            with open(path, "rb") as f:
                data = _read_at_most(f, limit + 1)
    except OSError as exc:
        raise Failure(name, 0, "cannot read %s: %s" % (what, exc.strerror or exc)) from None
    if b"\0" in data:
        raise Failure(name, data.count(b"\n", 0, data.index(b"\0")) + 1, "a NUL byte: %s is not a text file" % what)
    if len(data) > limit:
        raise Failure(name, 0, "%s is longer than %d bytes" % (what, limit))
    try:
        return name, data.decode("utf-8")
    except UnicodeDecodeError:
        return name, data.decode("latin-1")


def _read_at_most(source: Any, size: int) -> bytes:
    """At most ``size`` bytes of ``source``, a chunk at a time: read(size) reserves ``size`` bytes before it
    reads one (1 GiB for a program: verify of a five-line program ran out of memory under a 700 MB limit)."""
    chunks, read = [], 0
    while read < size:
        chunk = source.read(min(CHUNK, size - read))
        if not chunk:
            break
        chunks.append(chunk)
        read += len(chunk)
    return b"".join(chunks)


def check_line_lengths(text: str, name: str) -> None:
    """A Failure on the first line of a program read whole that is longer than MAX_LINE_CHARS."""
    for number, line in enumerate(text.splitlines(), 1):
        if len(line) > MAX_LINE_CHARS:
            raise Failure(name, number, "the line is longer than %d characters" % MAX_LINE_CHARS)


def tool_table(args: Any) -> Any:
    """The --tool-table read (None without one); bad lines as TABLE:LINE: message."""
    from .engine.errors import ProgramError
    from .engine.mill_tool_table import read_mill_tool_table
    from .engine.tool_table import read_tool_table

    path = args.tool_table
    if path is None:
        return None
    if args.tool_width is None and (args.tool_radius is not None or args.reference_corner is not None):
        raise Failure(path, 0, "--tool-radius and --reference-corner shape the --tool-width blade, which is not "
                       "given: the table gives each tool's own; give --tool-width too for the tools it does not list")
    if path == "-" and args.program == "-":
        raise Failure("<stdin>", 0, "the program and the tool table cannot both be read from standard input")
    name, text = read_text(path, "the tool table")
    try:
        if getattr(args, "dialect", None) == "milltronics":  # end mill diameters by D number
            return read_mill_tool_table(text, name)
        return read_tool_table(text, name)
    except ProgramError as exc:
        raise Failure.of_program_error(name, exc) from None



@contextlib.contextmanager
def open_program(path: str, name: str) -> Iterator[io.TextIOWrapper]:
    """The program as a text file to read line by line. Standard input (or a
    pipe given by name) is first copied to an anonymous temporary file. The
    text is UTF-8 when the whole file is valid UTF-8, else Latin-1, as when the
    program was read whole: a first pass over the file decides, a chunk at a
    time. Ends of line are kept for the engine (\\n, \\r\\n, \\r)."""
    with contextlib.ExitStack() as stack:
        try:
            source = sys.stdin.buffer if path == "-" else stack.enter_context(open(path, "rb"))
            if not source.seekable():
                spool = stack.enter_context(tempfile.TemporaryFile())
                _copy_bounded(source, spool, name)
                spool.seek(0)
                source = spool
            begin = source.tell()  # standard input redirected from a file may be read from further on
            encoding = text_encoding(source, name)
            source.seek(begin)
        except OSError as exc:
            raise Failure(name, 0, "cannot read the program: %s" % (exc.strerror or exc)) from None
        text = io.TextIOWrapper(source, encoding=encoding, newline="")
        try:
            yield text
        finally:
            text.detach()  # the file is closed by the stack (standard input is not closed)


def _checked_chunks(source: Any, name: str) -> Iterator[bytes]:
    """The program's bytes a chunk at a time; a Failure at a NUL byte (not a text
    file: /dev/zero) or beyond MAX_PROGRAM_BYTES."""
    size = lines = 0
    for chunk in iter(lambda: source.read(CHUNK), b""):
        if b"\0" in chunk:
            raise Failure(name, lines + chunk.count(b"\n", 0, chunk.index(b"\0")) + 1,
                          "a NUL byte: the program is not a text file")
        size += len(chunk)
        lines += chunk.count(b"\n")
        if size > MAX_PROGRAM_BYTES:
            raise Failure(name, 0, "the program is longer than %d bytes" % MAX_PROGRAM_BYTES)
        yield chunk


def _copy_bounded(source: Any, spool: Any, name: str) -> None:
    """Standard input (or a pipe) copied to ``spool``, within the program's bounds."""
    for chunk in _checked_chunks(source, name):
        spool.write(chunk)


def text_encoding(source: Any, name: str = "PROGRAM") -> str:
    """utf-8 when the whole binary file ``source`` decodes as UTF-8, else latin-1
    (a Failure for a file that is not a text program: _checked_chunks)."""
    decoder = codecs.getincrementaldecoder("utf-8")()
    try:
        for chunk in _checked_chunks(source, name):
            decoder.decode(chunk)
        decoder.decode(b"", True)
    except UnicodeDecodeError:
        for _chunk in _checked_chunks(source, name):  # the rest is checked all the same
            pass
        return "latin-1"
    return "utf-8"


def read_lines(text: Any, name: str) -> Iterator[str]:
    """The lines of the text file ``text`` one by one, each at most
    MAX_LINE_CHARS characters (a longer one is a Failure on its line, read no
    further); a read error as a Failure (not an OSError, which the output would
    take for its own)."""
    number = 0
    try:
        while True:
            line = text.readline(MAX_LINE_CHARS + 1)
            if not line:
                return
            number += 1
            if len(line) > MAX_LINE_CHARS and not line.endswith(("\n", "\r")):
                raise Failure(name, number, "the line is longer than %d characters" % MAX_LINE_CHARS)
            yield line
    except OSError as exc:
        raise Failure(name, 0, "cannot read the program: %s" % (exc.strerror or exc)) from None


def write_chunks(chunks: Iterable[str], out: Optional[str]) -> None:
    """Write the chunks to ``out`` atomically ("-" or None: stdout). OUT: through
    its temporary file, renamed over OUT after the last chunk. Stdout: through
    an anonymous temporary file, copied to stdout after the last chunk, so that
    a run that fails writes nothing there."""
    if out not in (None, "-"):
        try:
            write_chunks_atomically(out, chunks, encoding="ascii", errors="replace")
        except OSError as exc:
            raise Failure(out, 0, "cannot write the output: %s" % (exc.strerror or exc)) from None
        return
    try:
        spool = tempfile.TemporaryFile("w+", encoding="utf-8", newline="")
    except OSError as exc:
        raise Failure("<stdout>", 0, "cannot make the temporary file: %s" % (exc.strerror or exc)) from None
    with spool:
        try:
            for chunk in chunks:
                spool.write(chunk)
            spool.seek(0)
        except OSError as exc:
            raise Failure("<stdout>", 0, "cannot write the temporary file: %s" % (exc.strerror or exc)) from None
        write_stdout(iter(lambda: spool.read(CHUNK), ""))


def write_stdout(chunks: Iterable[str]) -> None:
    """Write the text ``chunks`` to standard output; a closed or failing stdout (not a
    broken pipe, which main ends quietly) is a Failure naming <stdout>."""
    stream = sys.stdout
    if stream is None:  # started with stdout closed (>&-)
        raise Failure("<stdout>", 0, "cannot write the output: standard output is closed")
    try:
        for chunk in chunks:
            stream.write(chunk)
        stream.flush()
    except BrokenPipeError:
        raise
    except (OSError, ValueError) as exc:  # ValueError: a closed file object
        quiet_stdout()
        raise Failure("<stdout>", 0, "cannot write the output: %s" % (getattr(exc, "strerror", None) or exc)) from None


def quiet_stdout() -> None:
    """Point sys.stdout at the null device, so that nothing is written (or
    fails again) when Python flushes it on exit."""
    try:
        sys.stdout = open(os.devnull, "w")
    except OSError:
        pass



def report(name: str, line: int, message: str) -> None:
    sys.stderr.write("%s:%s: %s\n" % (one_line(name), line, one_line(message)))
    sys.stderr.flush()


class WarningSpool:
    """The warnings of a run, (line, CycleWarning) pairs appended as they
    arise, kept as their lines in a temporary file (in memory while small:
    tempfile.SpooledTemporaryFile) rather than as objects, so that memory
    stays flat however many there are; ``report`` prints them in their order
    once the run has succeeded (a failed run reports its error alone)."""

    def __init__(self) -> None:
        self._file = tempfile.SpooledTemporaryFile(max_size=1 << 20, mode="w+", encoding="utf-8",
                                                   errors="surrogatepass", newline="\n")

    def append(self, item: Tuple[int, Any]) -> None:
        line, warning = item
        self._file.write("%s %s\n" % (line, one_line(warning.text)))

    def extend(self, items: Iterable[Tuple[int, Any]]) -> None:
        for item in items:
            self.append(item)

    def report(self, name: str) -> None:
        """Each warning as ``NAME:LINE: warning: ...`` on stderr (see ``report``), in the order they came."""
        spool = self._file
        spool.seek(0)
        name = one_line(name)
        for text in spool:
            line, message = text[:-1].split(" ", 1)
            sys.stderr.write("%s:%s: %s\n" % (name, line, one_line("warning: " + message)))
        sys.stderr.flush()

    def close(self) -> None:
        self._file.close()
