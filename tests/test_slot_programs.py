"""The LinuxCNC post's programs of Cylinder slot ops, checked on the host by
LinuxCNC's rs274 with a C axis (rs274 is not in the FreeCAD roots).

tests/freecad/write_slot_programs.py, run inside FreeCAD 1.1 and 1.0, posts a
helical groove and a keyway on an R20 cylinder (the ops of
tests/freecad/test_cylinder_slot.py); rs274 must accept each program and its
canonical moves, from the op's first move on, must be the op's Path: kind, X
(radius), Z, C, and for feed moves the F in force (mm/min; LinuxCNC reads F
along Z when Z moves, so the helix's path feed shows as 120 * 20 / 127.245).
"""

import json

import pytest
from freecad_roots import FREECADCMD, LABELS, describe, exec_code, run
from rs274 import require_rs274, run_rs274

WRITER_CODE = exec_code("tests/freecad/write_slot_programs.py")


@pytest.fixture(scope="module", params=LABELS)
def programs(request, tmp_path_factory):
    share = tmp_path_factory.mktemp("slot-%s" % request.param)
    proc, where = run(request.param, share, FREECADCMD, [WRITER_CODE], {}, 600)
    result_file = share / "slot_programs.json"
    assert result_file.exists(), "FreeCAD %s (%s) wrote no programs:\n%s" % (request.param, where, describe(proc))
    result = json.loads(result_file.read_text())
    assert not result["error"], result["error"]
    return result["cases"]


def _full_positions(moves):
    """The op's moves as full positions (a G0 of X alone keeps Z and C)."""
    here, out = {}, []
    for kind, x, z, c, f in moves:
        here.update({k: v for k, v in (("x", x), ("z", z), ("c", c)) if v is not None})
        out.append((kind, here["x"], here.get("z", 0.0), here.get("c", 0.0), f))
    return out


@pytest.mark.parametrize("case", ["helix", "keyway", "keyway-switched"])
def test_rs274_accepts_the_c_moves(programs, case):
    require_rs274()
    program, moves = programs[case]["program"], programs[case]["moves"]
    canon = run_rs274(program, tool_table=[1], rotary=True)
    want = _full_positions(moves)
    got = canon[len(canon) - len(want):]
    assert len(canon) >= len(want), canon
    for (kind, x, z, feed, _dwell, c), (wkind, wx, wz, wc, wf) in zip(got, want):
        assert kind == wkind, (got, want)
        assert (x, z, c) == pytest.approx((wx, wz, wc), abs=1e-4), ((kind, x, z, c), (wkind, wx, wz, wc))
        if wf is not None:
            assert feed == pytest.approx(wf, rel=1e-6), (kind, feed, wf)
    assert got[-2][5] == pytest.approx(0.0 if case == "helix" else 90.0)  # back at the path's start
    assert any(abs(c - 360.0) < 1e-9 for *_r, c in got) if case == "helix" else all(c == 90.0 for *_r, c in got[2:])


def test_the_switches_stand_around_the_slot(programs):
    """--c-axis-on/--live-tool-cw before the slot's first move, --live-tool-stop/--c-axis-off after its last;
    the main spindle never started (rs274 accepted the program in test_rs274_accepts_the_c_moves)."""
    lines = [line.strip() for line in programs["keyway-switched"]["program"].splitlines()]
    first_move = next(i for i, line in enumerate(lines) if line.startswith("G0"))
    last_move = max(i for i, line in enumerate(lines) if line.startswith(("G0", "G1", "X", "Z", "C")))
    assert lines.index("M64 P0") < lines.index("M64 P1 S1000") < first_move
    assert last_move < lines.index("M65 P1") < lines.index("M65 P0")
    assert not [line for line in lines if line.startswith(("M3", "M4")) or " M3" in line], lines
