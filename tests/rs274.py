"""Run LinuxCNC's own G-code interpreter (rs274, Debian package linuxcnc-uspace)
as an independent reader of the programs we write.

    canon = run_rs274(text)          # [(kind, x, z, feed, dwell), ...]
    canon = run_rs274(text, tool_table=[3])   # a program with T3 M6
    problems = canonical_matches(expansion.moves, canon, start=1)
    assert not problems, "\\n".join(problems)

``kind`` is "G0" (STRAIGHT_TRAVERSE), "G1" (STRAIGHT_FEED), "G4" (DWELL),
"G2" or "G3" (ARC_FEED turning clockwise or counter-clockwise: seen with Z to
the right and X up in G18, X to the right and Y up in G17). x is the
radius (rs274 converts G7 diameter words), z absolute, in the program's length
unit. feed is the feed rate in force as rs274 last set it (None for G0, and
before the first SET_FEED_RATE), dwell is seconds for G4 and 0.0 otherwise. A G4 carries
the position it holds. An arc's tuple also has ``.centre``: (x radius, z) of
its centre (G17: (x, y)); the other moves' ``.centre`` is None.

rs274 reports an error by printing the message and the offending line (and,
in the version tested, exiting 1); any output line that is not a numbered
canonical call, any stderr text other than its "executing" banner, or a
non-zero exit raises RS274Error.

Notes on the interpreter (LinuxCNC 2.9, Debian 12):
* it starts at X0 Z0 and needs M2/M30 (or %) at the end;
* G95 (feed per revolution) feeds need a turning spindle (S... M3), or it
  stops with "Cannot feed with zero spindle speed in feed per rev mode";
* it keeps its tool table in $HOME/.tool.mmap (created with O_TRUNC, mapped
  shared): runs sharing a HOME crash each other with SIGBUS, so every run
  here gets its own temporary HOME.
"""

import os
import re
import shutil
import subprocess
import tempfile

RS274 = "/usr/bin/rs274"

_CANON = re.compile(r"^\s*\d+\s+N\S*\s+([A-Z_][A-Z0-9_]*)\((.*)\)\s*$")


class RS274Error(Exception):
    """rs274 rejected the program (or printed something we do not understand)."""

    def __init__(self, message, line=None, output=""):
        self.message = message
        self.line = line  # the offending program line rs274 printed, if any
        self.output = output  # everything it printed
        text = message if line is None else "%s (at: %s)" % (message, line)
        super().__init__(text)


def rs274_path():
    found = shutil.which("rs274")
    if found:
        return found
    if os.path.isfile(RS274) and os.access(RS274, os.X_OK):
        return RS274
    return None


def rs274_available():
    return rs274_path() is not None


def _ci():
    return os.environ.get("CI", "").strip().lower() not in ("", "0", "false", "no")


def require_rs274():
    """Call at the top of a test (or from a fixture) that needs rs274: returns
    its path; fails the test when CI is set and rs274 is missing, else skips."""
    import pytest

    path = rs274_path()
    if path is None:
        message = "rs274 (Debian package linuxcnc-uspace) is not installed; scripts/test installs it"
        if _ci():
            pytest.fail(message)
        pytest.skip(message)
    return path


def _numbers(args, count, line):
    try:
        values = [float(a) for a in args.split(",")]
    except ValueError:
        raise RS274Error("cannot read the arguments of a canonical call", line=line) from None
    if len(values) < count:
        raise RS274Error("canonical call has %d arguments, expected %d" % (len(values), count), line=line)
    return values


class Canonical(tuple):
    """A canonical move (a plain tuple, see the module notes) with ``centre``:
    an arc's centre, None for the other moves."""

    def __new__(cls, values, centre=None):
        move = tuple.__new__(cls, values)
        move.centre = centre
        return move


def _arc(values, x, y, z, feed, xyz, plane):
    """An ARC_FEED's canonical move: in XZ (G18) its values are Z, X, centre Z,
    centre X, rotation, Y; in XY (G17) X, Y, centre X, centre Y, rotation, Z."""
    kind = "G3" if values[4] > 0 else "G2"
    if plane == "XZ":
        z, x = values[0], values[1]
        centre = (values[3], values[2])
    else:
        x, y = values[0], values[1]
        z = values[5] if len(values) > 5 else z
        centre = (values[2], values[3])
    move = (kind, x, y, z, feed, 0.0) if xyz else (kind, x, z, feed, 0.0)
    return Canonical(move, centre), x, y, z


def parse_canonical(output, rotary=False, xyz=False):
    """Canonical moves from rs274's standard output (see module docstring);
    ``rotary``: each straight move also carries C (degrees) as a 6th item;
    ``xyz``: (kind, x, y, z, feed, dwell) for mill-style programs."""
    moves = []
    y = 0.0
    x = z = 0.0  # the interpreter starts at the origin
    feed = None
    plane = "XY"
    for raw in output.splitlines():
        if not raw.strip():
            continue
        m = _CANON.match(raw)
        if not m:
            raise RS274Error("rs274 printed a line that is not a canonical call", line=raw.strip(), output=output)
        name, args = m.group(1), m.group(2)
        if name == "STRAIGHT_TRAVERSE":
            x, y, z = _numbers(args, 6, raw)[:3]
            move = ("G0", x, y, z, None, 0.0) if xyz else ("G0", x, z, None, 0.0)
            moves.append(move + ((_numbers(args, 6, raw)[5],) if rotary else ()))
        elif name == "STRAIGHT_FEED":
            x, y, z = _numbers(args, 6, raw)[:3]
            move = ("G1", x, y, z, feed, 0.0) if xyz else ("G1", x, z, feed, 0.0)
            moves.append(move + ((_numbers(args, 6, raw)[5],) if rotary else ()))
        elif name == "SET_FEED_RATE":
            feed = _numbers(args, 1, raw)[0]
        elif name == "DWELL":
            seconds = _numbers(args, 1, raw)[0]
            moves.append(("G4", x, y, z, feed, seconds) if xyz else ("G4", x, z, feed, seconds))
        elif name == "SELECT_PLANE":
            plane = "XZ" if "XZ" in args else "XY" if "XY" in args else args
        elif name == "ARC_FEED":
            if plane not in ("XZ", "XY"):
                raise RS274Error("an arc in the plane %s" % plane, line=raw)
            move, x, y, z = _arc(_numbers(args, 6, raw), x, y, z, feed, xyz, plane)
            moves.append(move)
    return [m if isinstance(m, Canonical) else Canonical(m) for m in moves]


def tool_table_text(tools):
    """A LinuxCNC tool table with one line per tool number (pocket = number, no offsets)."""
    return "".join("T%d P%d Z0 ;\n" % (t, t) for t in sorted({int(t) for t in tools}))


def run_rs274(program_text, timeout=60, tool_table=None, files=None, xyz=False, rotary=False):
    """Interpret ``program_text`` with rs274 and return its canonical moves.

    ``files``: {name: text} written beside the program (named subroutines
    ``o<name> call`` are looked up there, e.g. ``dress12.ngc``); ``xyz``: moves
    as (kind, x, y, z, feed, dwell) (see parse_canonical).
    ``tool_table``: None (default) runs with an empty tool table, in which rs274
    refuses every T word; an iterable of tool numbers gives a table holding
    them (see tool_table_text); a str is the table's text as is. ``rotary``:
    straight moves carry C as a 6th item (parse_canonical)."""
    path = rs274_path()
    if path is None:
        raise RS274Error("rs274 is not installed (Debian package linuxcnc-uspace)")
    if tool_table is None:
        table = ""
    elif isinstance(tool_table, str):
        table = tool_table
    else:
        table = tool_table_text(tool_table)
    with tempfile.TemporaryDirectory(prefix="rs274-") as tmp:
        ngc = os.path.join(tmp, "program.ngc")
        tbl = os.path.join(tmp, "tools.tbl")
        with open(ngc, "w") as f:
            f.write(program_text if program_text.endswith("\n") else program_text + "\n")
        with open(tbl, "w") as f:
            f.write(table)
        for name, text in (files or {}).items():
            with open(os.path.join(tmp, name), "w") as f:
                f.write(text)
        # rs274 keeps its tool table in $HOME/.tool.mmap, created with
        # O_TRUNC and mapped shared: two runs with the same HOME (parallel
        # tests, another shell) truncate each other's map and die of SIGBUS.
        env = dict(os.environ, HOME=tmp)
        proc = subprocess.run(
            [path, "-t", tbl, "-g", ngc],
            cwd=tmp,
            env=env,
            stdin=subprocess.DEVNULL,
            capture_output=True,
            text=True,
            timeout=timeout,
        )
    output = proc.stdout
    errors = [text for text in proc.stderr.splitlines() if text.strip() and text.strip() != "executing"]
    if errors:
        # rs274 prints the message, then the offending line.
        message = errors[0].strip()
        line = errors[1].strip() if len(errors) > 1 else None
        raise RS274Error(message, line=line, output=output + proc.stderr)
    moves = parse_canonical(output, rotary, xyz)
    if proc.returncode != 0:
        if proc.returncode < 0:
            how = "was killed by signal %d" % -proc.returncode
        else:
            how = "exited with status %d" % proc.returncode
        raise RS274Error("rs274 " + how, output=output + proc.stderr)
    return moves


def canonical_matches(engine_moves, canon, start=0, tol=1e-4, trailing=False, centre_tol=2e-4):
    """Compare engine moves (moves.Move, x radius) with rs274's ``canon``
    moves pairwise, from ``canon[start]`` on (``start`` skips the moves a test
    program makes before the cycle). Kinds must match (RAPID "G0", FEED "G1",
    DWELL "G4", ARC_CW "G2", ARC_CCW "G3"), x and z within ``tol``, an arc's
    centre within ``centre_tol`` (its I/K are written from the start as
    written, both rounded), a FEED's or an arc's f (when not None) the feed in
    force, a DWELL's seconds. Unless ``trailing``, canon must have no moves
    after the last engine move. Returns a list of mismatch descriptions
    (empty: they match).
    """
    problems = []
    canon = list(canon)
    part = canon[start:]
    engine = list(engine_moves)
    for i, (m, c) in enumerate(zip(engine, part)):
        kind, x, z, feed, dwell = c
        where = "move %d (canonical %d)" % (i, start + i)
        if m.kind != kind:
            problems.append("%s: engine %s X%.4f Z%.4f, rs274 %s X%.4f Z%.4f" % (where, m.kind, m.x, m.z, kind, x, z))
            continue
        if abs(m.x - x) > tol or abs(m.z - z) > tol:
            problems.append("%s %s: engine X%.6f Z%.6f, rs274 X%s Z%s" % (where, kind, m.x, m.z, x, z))
        if kind in ("G2", "G3") and (m.centre is None or max(abs(m.centre[0] - c.centre[0]),
                                                              abs(m.centre[1] - c.centre[1])) > centre_tol):
            problems.append("%s %s: engine centre %s, rs274 centre X%.4f Z%.4f" % (where, kind, m.centre, *c.centre))
        if kind in ("G1", "G2", "G3") and m.f is not None and (feed is None or abs(m.f - feed) > tol):
            problems.append("%s %s: engine F%g, rs274 feed %s" % (where, kind, m.f, feed))
        if kind == "G4" and abs(m.p - dwell) > tol:
            problems.append("%s G4: engine P%g s, rs274 dwell %g s" % (where, m.p, dwell))
    if len(part) < len(engine):
        problems.append("rs274 has %d moves after canonical %d, engine has %d" % (len(part), start, len(engine)))
    elif len(part) > len(engine) and not trailing:
        extra = part[len(engine)]
        problems.append(
            "rs274 has %d extra moves after the engine's %d, first %s X%.4f Z%.4f"
            % (len(part) - len(engine), len(engine), extra[0], extra[1], extra[2])
        )
    return problems


def written_moves(moves, metric=True):
    """The moves as the LinuxCNC writer puts them on paper: a move whose written
    X and Z equal the previous ones is dropped (it does not move the tool), so
    the list compares one to one with rs274's canonical moves."""
    from freecad_groove.engine.moves import DWELL
    from freecad_groove.engine.output.writer import Writer

    w = Writer("linuxcnc", metric)
    out, prev = [], None
    for m in moves:
        if m.kind == DWELL:
            out.append(m)
            continue
        key = (w.x_word(m.x), w.z_word(m.z))
        if key != prev:
            out.append(m)
            prev = key
    return out
