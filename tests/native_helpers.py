"""Helpers of the native-cycle tests (test_native_cycles.py, test_native_reasons.py):
translate a program with --native-cycles, pick out its blocks, read the
output back with the engine's reader of the target's own control and run
both through LinuxCNC's rs274 (tests/rs274.py)."""

import re

from rs274 import require_rs274, run_rs274

from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.output.targets import TARGETS
from freecad_groove.engine.translator import translate_program

BLADE = Settings(tool=GroovingTool(3.0, 0.2))  # a 3 mm blade, corner radius 0.2, its -Z corner the reference
RESOLUTION = 0.001  # mm: the lathe targets' and the grinder's resolution (3 decimals)


def native(program, dialect, target, settings=BLADE, **kw):
    """The program translated for ``target`` with --native-cycles."""
    return translate_program(program, dialect, settings, target=target, native_cycles=True, **kw)


def reader_of(target):
    """The dialect that reads a program written for ``target`` (the target's own)."""
    return TARGETS[target].native.dialect or target


def lines_after(text, comment, count=1):
    """The ``count`` lines after the first comment holding ``comment``."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if comment in line and ("(" in line or ";" in line))
    return lines[start + 1:start + 1 + count]


def canonical(text, dialect, settings=BLADE, xyz=False, rotary=False, files=None, linuxcnc="linuxcnc", **kw):
    """rs274's canonical moves of ``text`` (a ``dialect`` program) translated for LinuxCNC
    (``kw``: translate_program's start, tools), without the moves that go nowhere."""
    require_rs274()
    program = translate_program(text, dialect, settings, target=linuxcnc, **kw)
    tools = {int(t) for t in re.findall(r"\b[TH](\d+)\b", program)}
    moves, here = [], None
    for move in run_rs274(program, tool_table=tools, xyz=xyz, rotary=rotary, files=files):
        where = move[1:4] if xyz else move[1:3] + move[5:]
        if move[0] in ("G0", "G1") and here is not None and all(abs(a - b) <= 1e-9 for a, b in zip(where, here)):
            continue
        here = where
        moves.append(move)
    return moves


def same_canonical(expected, got, tolerance=RESOLUTION, xyz=False):
    """The first difference of two canonical move lists (None: the same within ``tolerance``)."""
    axes = slice(1, 4) if xyz else slice(1, 3)
    for index, (a, b) in enumerate(zip(expected, got)):
        if a[0] != b[0] or any(abs(u - v) > tolerance for u, v in zip(a[axes], b[axes])):
            return "move %d: %s, read back %s" % (index, a, b)
        feed = 4 if xyz else 3
        if a[0] == "G1" and abs(a[feed] - b[feed]) > 1e-6:
            return "move %d: feed %s, read back %s" % (index, a[feed], b[feed])
    if len(expected) != len(got):
        return "%d moves, read back %d" % (len(expected), len(got))
    return None


def assert_reads_back(program, dialect, target, settings=BLADE, start=None, tools=None, **kw):
    """The native output of ``program`` read back by the target's own reader cuts the
    moves the program's own expansion cuts (rs274 reads both; ``kw``: canonical's);
    returns the output. ``start``, ``tools``: translate_program's, for the program."""
    text = native(program, dialect, target, settings, start=start, tools=tools)
    expected = canonical(program, dialect, settings, start=start, tools=tools, **kw)
    got = canonical(text, reader_of(target), settings, tools=tools, **kw)
    problem = same_canonical(expected, got, xyz=kw.get("xyz", False))
    assert problem is None, "%s\n%s" % (problem, text)
    return text
