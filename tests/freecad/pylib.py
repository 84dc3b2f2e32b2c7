"""shapely for the FreeCAD runs: the folder the host unpacked for this
Python (tests/freecad_shapely.py, FREECAD_GROOVE_PYLIB relative to
FREECAD_GROOVE_SHARE) on sys.path, appended (a FreeCAD's own shapely comes
first); and the fixture body that skips, or under CI fails, without it."""

import os
import sys


def add_pylib():
    pylib = os.environ.get("FREECAD_GROOVE_PYLIB")
    if pylib:
        folder = os.path.join(os.environ.get("FREECAD_GROOVE_SHARE", ""), pylib, "cp%d%d" % sys.version_info[:2])
        if os.path.isdir(folder) and folder not in sys.path:
            sys.path.append(folder)


def require_shapely():
    """The shapely module; pytest skip (CI: fail) when this FreeCAD cannot import it."""
    import pytest

    add_pylib()
    try:
        import shapely
    except ImportError:
        why = "shapely is not importable in this FreeCAD (FREECAD_GROOVE_PYLIB=%r)" % os.environ.get(
            "FREECAD_GROOVE_PYLIB")
        if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
            pytest.fail(why)
        pytest.skip(why)
    return shapely
