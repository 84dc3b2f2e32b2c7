"""The three layers' import rule, read from the source (no FreeCAD needed):
the engine imports neither FreeCAD nor Qt; the FreeCAD layer, the posts and
Init.py import FreeCAD but never Qt or the GUI."""

import ast
import glob
import os

import pytest

from conftest import ROOT

FREECAD = {"FreeCAD", "Part", "Path", "PathScripts", "Mesh", "Sketcher"}
GUI = {"FreeCADGui", "PySide", "PySide2", "PySide6", "PyQt5", "PyQt6", "Gui"}


def imported_modules(path):
    tree = ast.parse(open(path, encoding="utf-8").read(), path)
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            yield from (a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0:
            yield node.module or ""


def files(*patterns):
    found = sorted(f for p in patterns for f in glob.glob(os.path.join(ROOT, p)))
    assert found, patterns
    return found


@pytest.mark.parametrize(
    "patterns, forbidden",
    [
        (("freecad_groove/engine/*.py", "freecad_groove/__init__.py", "freecad_groove/__main__.py",
          "freecad_groove/cli.py"), FREECAD | GUI),
        (("freecad_groove/freecad/*.py", "freecad_groove/demo.py", "postprocessors/*_post.py", "Init.py"), GUI),
    ],
    ids=["engine", "freecad"],
)
def test_layer_imports(patterns, forbidden):
    for path in files(*patterns):
        for name in imported_modules(path):
            hit = set(name.split(".")) & forbidden
            assert not hit, "%s imports %s" % (os.path.relpath(path, ROOT), name)


def test_rule_catches_a_forbidden_import(tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("def f():\n    from PySide import QtCore\n")
    assert "PySide" in list(imported_modules(str(bad)))
