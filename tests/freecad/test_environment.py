"""FreeCAD-level checks of the test environment itself: the right FreeCAD, the
engine under FreeCAD's Python giving the host's moves, the moves surviving
FreeCAD's Path data (in memory, as text, through a saved document), and the
CAM modules the Groove operation and the posts will build on.

Runs inside FreeCAD only (tests/freecad/run_suite.py, driven by
tests/test_freecad.py); the host's pytest does not collect this folder.
"""

import json
import math
import os
import sys

import FreeCAD
import Path
import pytest
import seed_case

TOL = 1e-6  # FreeCAD writes G-code text with 6 decimals
LABEL = os.environ.get("FREECAD_GROOVE_LABEL", "")
QT_MAJOR = {"1.0": 5, "1.1": 6}  # Debian's builds: 1.0 with Qt 5/PySide2, 1.1 with Qt 6/PySide6


def freecad_version():
    major, minor, patch = FreeCAD.Version()[:3]
    return "%s.%s" % (major, minor), "%s.%s.%s" % (major, minor, patch)


def moves():
    return seed_case.expand()


def with_starts(moves):
    """(move, the position it starts from (x, z)) for the seed's moves, from its start point."""
    here, out = (seed_case.START["x"], seed_case.START["z"]), []
    for move in moves:
        out.append((move, here))
        here = here if move.kind == "G4" else (move.x, move.z)
    return out


def expected_params(move, here):
    """The words of the Path.Command an operation puts in its Path for this move (an arc's I, K
    its centre less its start ``here``)."""
    if move.kind == "G4":
        return {"P": move.p}
    params = {"X": move.x, "Z": move.z}
    if move.kind in ("G2", "G3"):
        params.update(I=move.centre[0] - here[0], K=move.centre[1] - here[1])
    if move.f is not None:
        params["F"] = move.f
    return params


def commands_of(moves):
    return [Path.Command(move.kind, expected_params(move, here)) for move, here in with_starts(moves)]


def assert_same_commands(got, want_moves, tol, what):
    assert len(got) == len(want_moves), "%s: %d commands, expected %d" % (what, len(got), len(want_moves))
    for i, (cmd, (move, here)) in enumerate(zip(got, with_starts(want_moves))):
        want = expected_params(move, here)
        assert cmd.Name == move.kind, "%s: command %d is %s, expected %s" % (what, i, cmd.Name, move.kind)
        assert sorted(cmd.Parameters) == sorted(want), "%s: command %d %s has words %s, expected %s" % (
            what, i, cmd.Name, sorted(cmd.Parameters), sorted(want))
        for word, value in want.items():
            assert abs(cmd.Parameters[word] - value) <= tol, "%s: command %d %s %s%r, expected %r" % (
                what, i, cmd.Name, word, cmd.Parameters[word], value)


# -- which FreeCAD ------------------------------------------------------------------


def test_freecad_version_is_as_labelled():
    minor, full = freecad_version()
    assert tuple(int(n) for n in minor.split(".")) >= (1, 0), "FreeCAD %s: the add-on needs 1.0 or newer" % full
    if LABEL:
        assert minor == LABEL, "run as FreeCAD %s but this is FreeCAD %s" % (LABEL, full)
    else:
        assert minor in ("1.0", "1.1"), "FreeCAD %s: the tests target 1.1 and 1.0" % full


def test_headless_and_qt_binding_as_expected():
    assert not FreeCAD.GuiUp, "freecadcmd should run without the GUI"
    from PySide import QtCore  # FreeCAD's shim: PySide6 in 1.1, PySide2 in 1.0

    minor, full = freecad_version()
    if minor not in QT_MAJOR:
        pytest.skip("FreeCAD %s: no expected Qt version" % full)
    qt_major = int(QtCore.qVersion().split(".")[0])
    assert qt_major == QT_MAJOR[minor], "FreeCAD %s runs Qt %s" % (full, QtCore.qVersion())


def test_engine_imports_from_the_checkout_under_freecads_python():
    import freecad_groove.engine as engine

    checkout = os.environ.get("FREECAD_GROOVE_CHECKOUT", "/mnt/freecad-groove")
    assert os.path.realpath(engine.__file__).startswith(os.path.realpath(checkout) + os.sep)
    assert sys.version_info >= (3, 10)
    assert "FreeCAD" in sys.modules  # this very interpreter is FreeCAD's


# -- the engine inside FreeCAD gives the host's moves ------------------------------------


def test_seed_cycle93_expands_to_the_hosts_moves():
    share = os.environ.get("FREECAD_GROOVE_SHARE", "")
    path = os.environ.get("FREECAD_GROOVE_HOST_MOVES") or os.path.join(share, seed_case.HOST_MOVES_FILE)
    if not share and not os.environ.get("FREECAD_GROOVE_HOST_MOVES"):
        pytest.skip("no host moves given: tests/test_freecad.py writes them (FREECAD_GROOVE_SHARE)")
    with open(path) as f:
        host = json.load(f)
    mine = seed_case.as_json()
    assert (host["call"], host["start"], host["tool"]) == (mine["call"], mine["start"], mine["tool"])
    assert len(mine["moves"]) == len(host["moves"]), "%d moves here, %d on the host" % (
        len(mine["moves"]), len(host["moves"]))
    worst = 0.0
    for i, (a, b) in enumerate(zip(mine["moves"], host["moves"])):
        assert a[0] == b[0], "move %d: %s here, %s on the host" % (i, a, b)
        for u, v in zip(a[1:], b[1:]):
            assert (u is None) == (v is None), "move %d: %s here, %s on the host" % (i, a, b)
            if u is not None:
                assert math.isfinite(u)
                worst = max(worst, abs(u - v))
                assert abs(u - v) <= 1e-9, "move %d: %s here, %s on the host" % (i, a, b)
    assert worst <= 1e-9


def test_seed_moves_have_every_kind():
    kinds = {m.kind for m in moves()}
    assert kinds == {"G0", "G1", "G2", "G3", "G4"}, kinds  # so the round trips below cover all five


# -- the moves survive FreeCAD's Path data ---------------------------------------------


def test_moves_survive_path_command():
    want = moves()
    assert_same_commands(commands_of(want), want, TOL, "Path.Command")


def test_moves_survive_path_text_round_trip():
    want = moves()
    text = Path.Path(commands_of(want)).toGCode()
    assert text.count("\n") >= len(want)
    again = Path.Path()
    again.setFromGCode(text)
    assert_same_commands(again.Commands, want, TOL, "Path.toGCode/setFromGCode")


def test_moves_survive_a_saved_and_reopened_document(tmp_path):
    want = moves()
    doc = FreeCAD.newDocument("GrooveSeed")
    try:
        obj = doc.addObject("Path::Feature", "Seed")
        obj.Path = Path.Path(commands_of(want))
        filename = str(tmp_path / "seed.FCStd")
        doc.saveAs(filename)
    finally:
        FreeCAD.closeDocument(doc.Name)
    doc = FreeCAD.openDocument(filename)
    try:
        assert_same_commands(doc.getObject("Seed").Path.Commands, want, TOL, "saved document")
    finally:
        FreeCAD.closeDocument(doc.Name)


# -- the CAM modules the add-on builds on -------------------------------------------------


def test_cam_job_and_operation_base_import_headless():
    import Path.Main.Job
    import Path.Op.Base

    assert callable(Path.Main.Job.Create)
    assert isinstance(Path.Op.Base.ObjectOp, type)
    for hook in ("opFeatures", "initOperation", "opExecute"):
        assert hasattr(Path.Op.Base.ObjectOp, hook), hook
    assert not FreeCAD.GuiUp


def test_post_processor_search_paths_are_listed():
    import Path.Preferences

    paths = Path.Preferences.searchPathsPost()
    assert isinstance(paths, list) and paths
    assert all(isinstance(p, str) for p in paths)
    assert any(p.rstrip("/").endswith("Path/Post/scripts") for p in paths), paths
