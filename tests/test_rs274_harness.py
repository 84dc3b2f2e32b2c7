"""Tests of the rs274 harness (tests/rs274.py): LinuxCNC's interpreter reads
a hand-written lathe program into the moves we expect, and rejects bad ones."""

import pytest
from rs274 import RS274Error, canonical_matches, parse_canonical, require_rs274, run_rs274

from freecad_groove.engine.moves import arc, dwell, feed, rapid


@pytest.fixture
def rs274():
    return require_rs274()


def same(actual, expected, tol=1e-9):
    """Canonical move lists equal (kinds and None exactly, numbers within tol)."""
    if len(actual) != len(expected):
        return False
    for a, e in zip(actual, expected):
        for u, v in zip(a, e):
            if isinstance(v, float) and isinstance(u, float):
                if abs(u - v) > tol:
                    return False
            elif u != v:
                return False
    return True


LATHE_PROGRAM = """\
(hand-written external groove, diameter mode)
G18 G7 G21 G90 G94
G0 X80 Z5
G0 Z-10
G1 X70 F100
G4 P0.5
G1 X60 Z-12 F50
G1 Z-14
G0 X100
M2
"""

# (kind, x radius, z, feed in force, dwell seconds)
LATHE_EXPECTED = [
    ("G0", 40.0, 5.0, None, 0.0),
    ("G0", 40.0, -10.0, None, 0.0),
    ("G1", 35.0, -10.0, 100.0, 0.0),
    ("G4", 35.0, -10.0, 100.0, 0.5),
    ("G1", 30.0, -12.0, 50.0, 0.0),
    ("G1", 30.0, -14.0, 50.0, 0.0),
    ("G0", 50.0, -14.0, None, 0.0),
]

LATHE_ENGINE = [
    rapid(40.0, 5.0),
    rapid(40.0, -10.0),
    feed(35.0, -10.0, 100.0),
    dwell(35.0, -10.0, 0.5),
    feed(30.0, -12.0, 50.0),
    feed(30.0, -14.0),
    rapid(50.0, -14.0),
]


def test_lathe_program_moves(rs274):
    assert same(run_rs274(LATHE_PROGRAM), LATHE_EXPECTED)


def test_radius_mode_and_incremental(rs274):
    program = "G18 G8 G21 G90\nG0 X40 Z5\nG91 G1 X-5 Z-2 F80\nG90 G0 X50\nM2\n"
    assert same(
        run_rs274(program),
        [("G0", 40.0, 5.0, None, 0.0), ("G1", 35.0, 3.0, 80.0, 0.0), ("G0", 50.0, 3.0, None, 0.0)],
    )


def test_inch_program_stays_in_inches(rs274):
    program = "G18 G7 G20 G90 G94\nG0 X2 Z0.1\nG1 X1.5 F4\nM2\n"
    assert same(run_rs274(program), [("G0", 1.0, 0.1, None, 0.0), ("G1", 0.75, 0.1, 4.0, 0.0)])


def test_feed_per_rev_needs_a_spindle(rs274):
    # G95 is accepted with a turning spindle; without one rs274 refuses it.
    ok = "G18 G7 G21 G90 G95 S500 M3\nG0 X40 Z2\nG1 X30 F0.1\nM5\nM2\n"
    assert same(run_rs274(ok)[-1:], [("G1", 15.0, 2.0, 0.1, 0.0)])
    with pytest.raises(RS274Error, match="zero spindle speed"):
        run_rs274(ok.replace(" S500 M3", ""))


def test_error_program_raises_with_message_and_line(rs274):
    program = "G18 G7 G21 G90\nG1 X70 Z60 Q3\nM2\n"
    with pytest.raises(RS274Error) as err:
        run_rs274(program)
    assert "Q word" in err.value.message
    assert err.value.line == "G1 X70 Z60 Q3"
    assert "G1 X70 Z60 Q3" in str(err.value)


def test_program_without_end_raises(rs274):
    with pytest.raises(RS274Error, match="program end"):
        run_rs274("G18 G7 G21 G90\nG0 X10 Z0\n")


def test_unknown_word_raises(rs274):
    with pytest.raises(RS274Error):
        run_rs274("G18 G7 G21 G90\nG77 X10 Z-5\nM2\n")


def test_arcs_come_back_as_g2_and_g3_with_their_centre(rs274):
    # From X60 Z0 (radius 30): G2 R5 to radius 25 Z-5. Seen with Z to the right and X up, the minor
    # arc turning clockwise (its angle about the centre falling) from (z 0, x 30) to (z -5, x 25) has
    # its centre at (x 30, z -5): from angle 0 to -90 degrees. Then G3 I0 K5 back: centre (x 25, z 0).
    program = "G18 G7 G21 G90\nG0 X60 Z0\nG2 X50 Z-5 R5 F100\nG3 X60 Z0 I0 K5\nM2\n"
    canon = run_rs274(program)
    assert same(canon[-2:], [("G2", 25.0, -5.0, 100.0, 0.0), ("G3", 30.0, 0.0, 100.0, 0.0)])
    assert [c.centre for c in canon[-2:]] == [pytest.approx((30.0, -5.0)), pytest.approx((25.0, 0.0))]
    assert canon[0].centre is None
    engine = [rapid(30.0, 0.0), arc(True, 25.0, -5.0, (30.0, -5.0)), arc(False, 30.0, 0.0, (25.0, 0.0))]
    assert canonical_matches(engine, canon) == []
    turned = [engine[0], arc(False, 25.0, -5.0, (30.0, -5.0)), engine[2]]  # the other way round
    assert any("G3" in p and "G2" in p for p in canonical_matches(turned, canon))
    moved = [engine[0], arc(True, 25.0, -5.0, (25.0, 0.0)), engine[2]]  # the other circle through both ends
    assert any("centre" in p for p in canonical_matches(moved, canon))
    assert any("G1" in p for p in canonical_matches([engine[0], feed(25.0, -5.0), engine[2]], canon))


def test_arcs_in_the_xy_plane_come_back_with_their_centre(rs274):
    # G17 from X10 Y0 counter-clockwise about the origin to X0 Y10, at Z-1.
    canon = run_rs274("G17 G21 G90\nG0 X10 Y0 Z-1\nG3 X0 Y10 I-10 J0 F100\nM2\n", xyz=True)
    assert same(canon[-1:], [("G3", 0.0, 10.0, -1.0, 100.0, 0.0)])
    assert canon[-1].centre == pytest.approx((0.0, 0.0))


def test_engine_moves_match_rs274(rs274):
    canon = run_rs274(LATHE_PROGRAM)
    assert canonical_matches(LATHE_ENGINE, canon) == []
    # start skips moves the test program makes before the cycle
    assert canonical_matches(LATHE_ENGINE[2:], canon, start=2) == []


# --- canonical_matches and the parser, without rs274 -------------------------


def test_canonical_matches_reports_each_difference():
    canon = list(LATHE_EXPECTED)
    wrong = list(LATHE_ENGINE)
    wrong[1] = rapid(40.0, -10.001)  # 0.001 off in Z
    wrong[2] = feed(35.0, -10.0, 90.0)  # wrong feed
    wrong[3] = dwell(35.0, -10.0, 1.0)  # wrong dwell
    wrong[4] = rapid(30.0, -12.0)  # wrong kind
    problems = canonical_matches(wrong, canon)
    assert len(problems) == 4, problems
    assert "move 1" in problems[0] and "move 2" in problems[1] and "move 3" in problems[2]
    assert "G0" in problems[3] and "G1" in problems[3]
    assert canonical_matches(LATHE_ENGINE, canon, tol=1e-4) == []
    assert canonical_matches(wrong[:1], canon, tol=1e-4) != []  # rs274 has extra moves
    assert canonical_matches(wrong[:1], canon, trailing=True) == []
    assert canonical_matches(LATHE_ENGINE + [rapid(0.0, 0.0)], canon) != []  # engine has extra


def test_parser_rejects_lines_that_are_not_canonical_calls():
    good = "    1 N..... STRAIGHT_TRAVERSE(40.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)\n"
    assert same(parse_canonical(good), [("G0", 40.0, 5.0, None, 0.0)])
    with pytest.raises(RS274Error) as err:
        parse_canonical(good + "Bad number format\n")
    assert err.value.line == "Bad number format"


def test_parser_tracks_feed_and_numbered_lines():
    text = (
        "   10 N..... SET_FEED_RATE(0.1500)\n"
        "   11 N00010 STRAIGHT_FEED(35.0000, 0.0000, -2.0000, 0.0000, 0.0000, 0.0000)\n"
        "   12 N..... DWELL(1.0000)\n"
        '   13 N..... COMMENT("hello")\n'
    )
    assert same(parse_canonical(text), [("G1", 35.0, -2.0, 0.15, 0.0), ("G4", 35.0, -2.0, 0.15, 1.0)])


def test_missing_rs274_fails_under_ci_and_skips_elsewhere(monkeypatch):
    import rs274 as harness

    monkeypatch.setattr(harness, "RS274", "/nonexistent/rs274")
    monkeypatch.setattr(harness.shutil, "which", lambda name: None)
    assert not harness.rs274_available()
    monkeypatch.setenv("CI", "true")
    with pytest.raises(pytest.fail.Exception, match="linuxcnc-uspace"):
        require_rs274()
    monkeypatch.delenv("CI")
    with pytest.raises(pytest.skip.Exception):
        require_rs274()
    with pytest.raises(RS274Error, match="not installed"):
        run_rs274("M2\n")
