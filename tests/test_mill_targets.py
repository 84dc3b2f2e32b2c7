"""Mill-style output (targets "linuxcnc-mill", "fanuc-mill"): G17, X as a plain
coordinate, Y words, dress subprogram calls; rs274 reads every LinuxCNC one."""

import pytest
from rs274 import require_rs274, run_rs274

from freecad_groove.engine.cycles.ab_g83 import G83_1
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import DRESS, FEED, MachineState, Move
from freecad_groove.engine.output.program import write_program
from freecad_groove.engine.output.targets import program_target
from freecad_groove.engine.output.writer import Writer


def test_mill_twins_of_the_targets():
    assert program_target("linuxcnc", mill=True).name == "linuxcnc-mill"
    assert program_target("fanuc", mill=True).name == "fanuc-mill"
    assert program_target("fanuc-mill", mill=True).name == "fanuc-mill"


@pytest.mark.parametrize("name", ["sinumerik", "haas", "ab9", "gsk", "linuxcnc-c", "fanuc-c"])
def test_a_lathe_target_without_a_mill_twin_refuses_a_mill_style_program_naming_the_targets_that_take_it(name):
    with pytest.raises(ValueError, match=r"^%s is a lathe target: a mill-style program \(X/Y/Z\) cannot be written "
                       r"for it \(targets for it: linuxcnc, fanuc, milltronics, ab9grind\)$" % name):
        program_target(name, mill=True)


@pytest.mark.parametrize("name", ["milltronics", "ab9grind", "linuxcnc-mill"])
def test_a_mill_target_refuses_a_lathe_program(name):
    with pytest.raises(ValueError, match=r"^%s is a mill target: a lathe program \(X/Z\) cannot" % name):
        program_target(name, mill=False)


def test_linuxcnc_mill_writes_g17_plain_x_y_and_the_dress_call():
    writer = Writer("linuxcnc-mill", True, False, x=0.0, z=0.0, feed=10.0, y=0.0)
    assert writer.header() == ["G17 G21 G90 G91.1 G40 G94"]
    lines = writer.write([Move(FEED, 25.0, 0.0, None, 0.0, -0.1), Move(DRESS, 25.0, 0.0, None, 12, -0.1),
                          Move(FEED, 30.0, 0.0, 10.0, 0.0, -0.1)])
    # X25 is written as 25 (not a diameter 50); after the dress every axis, G1 and F again
    assert lines == ["G1 X25. Y-0.1", "o<dress12> call", "G1 X30. Y-0.1 Z0. F10."]


def test_fanuc_mill_writes_g94_not_g98_and_m98():
    writer = Writer("fanuc-mill", True, False, x=0.0, z=0.0, feed=10.0, y=0.0)
    assert writer.header(program_number=7) == ["%", "O0007", "G21", "G17 G90 G40 G94"]
    assert writer.write([Move(DRESS, 0.0, 0.0, None, 12, 0.0)]) == ["M98 P12"]


def test_a_lathe_target_refuses_a_dress_call_and_a_y_move():
    with pytest.raises(ProgramError, match="no Y axis"):
        Writer("linuxcnc").write([Move(DRESS, 0.0, 0.0, None, 12, 0.0)])
    with pytest.raises(ProgramError, match="dress program call cannot be written for fanuc"):
        Writer("fanuc").write([Move(DRESS, 0.0, 0.0, None, 12)])


def test_a_dress_call_away_from_the_position_held_is_refused():
    writer = Writer("linuxcnc-mill", True, False, x=0.0, z=0.0, y=0.0)
    with pytest.raises(ProgramError, match="a dress call away from the position held .X5."):
        writer.write([Move(DRESS, 5.0, 0.0, None, 12, 0.0)])


def test_rs274_runs_an_expanded_g83_1_with_its_dress_calls_where_the_engine_puts_them():
    require_rs274()
    model = G83_1(X=50.0, I=5.0, Y=-0.25, J=0.1, Z=10.0, K=6.0, R=4.0, F=20.0, E=3000.0, P=12, D=2, L=1)
    moves = model.expand(MachineState(x=0.0, z=0.0, y=0.0, diameter_mode=False))
    text = write_program(moves, "linuxcnc-mill", MachineState(x=0.0, z=0.0, y=0.0, feed=20.0, feed_per_rev=False))
    # the dress program dwells 0.012 s: its DWELL marks where rs274 ran it
    dress = "o<dress12> sub\nG4 P0.012\no<dress12> endsub\nM2\n"
    canon = run_rs274(text, files={"dress12.ngc": dress}, xyz=True)
    expected = [("G0", 0.0, 0.0, 0.0)] + [
        ("G4", m.x, m.y, m.z) if m.kind == DRESS else ("G1", m.x, m.y, m.z) for m in moves[:-1]]
    assert moves[-1][1:7] == moves[-2][1:3] + (20.0, 0.0, -0.25, None)  # the last sets F again, moves nothing
    got = [(c[0], c[1], c[2], c[3]) for c in canon]
    assert len(got) == len(expected)
    for (kind, x, y, z), want in zip(got, expected):
        assert kind == want[0] and abs(x - want[1]) < 1e-4 and abs(y - want[2]) < 1e-4 and abs(z - want[3]) < 1e-4
    assert [c[5] for c in canon if c[0] == "G4"] == [0.012] * 3  # G83.1 first, then D2
