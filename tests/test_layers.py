"""The three layers' import rule, read from the source (no FreeCAD needed):
imports only point down. The engine imports neither FreeCAD nor Qt nor the
upper layers nor the verification package; the FreeCAD layer, the posts and
Init.py import FreeCAD but never Qt or the GUI layer (freecad_groove.gui);
only the GUI layer, InitGui.py and the GUI tests import FreeCADGui or Qt. The
verification package (freecad_groove.verify) imports the engine and shapely
but neither FreeCAD nor Qt nor the FreeCAD and GUI layers."""

import ast
import glob
import os

import pytest
from conftest import ROOT

FREECAD = {"FreeCAD", "Part", "Path", "PathScripts", "Mesh", "Sketcher"}
GUI = {"FreeCADGui", "PySide", "PySide2", "PySide6", "PyQt5", "PyQt6", "Gui", "pivy"}
FREECAD_LAYER = {"freecad_groove.freecad"}
GUI_LAYER = {"freecad_groove.gui"}
VERIFY_LAYER = {"freecad_groove.verify"}


def _package(path):
    rel = os.path.relpath(path, ROOT)[:-3].split(os.sep)
    return rel[:-1] if rel[-1] != "__init__" else rel[:-1]


def imported_modules(path, package=None):
    """Every module a file imports, relative imports made absolute (from the
    file's place in the tree, or ``package`` ["freecad_groove", ...])."""
    package = _package(path) if package is None else package
    tree = ast.parse(open(path, encoding="utf-8").read(), path)
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            yield from (a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level == 0:
                yield node.module or ""
                continue
            base = package[: len(package) - (node.level - 1)]
            module = ".".join(base + ([node.module] if node.module else []))
            yield module
            yield from (module + "." + a.name for a in node.names)  # each may be a module


def _hits(name, forbidden):
    top = set(name.split(".")) & {f for f in forbidden if "." not in f}
    layers = {f for f in forbidden if "." in f and (name == f or name.startswith(f + "."))}
    return top | layers


def files(*patterns):
    found = sorted(f for p in patterns for f in glob.glob(os.path.join(ROOT, p), recursive=True))
    assert found, patterns
    return found


@pytest.mark.parametrize(
    "patterns, forbidden",
    [
        (("freecad_groove/engine/**/*.py", "freecad_groove/__main__.py", "freecad_groove/cli.py",
          "freecad_groove/cli_io.py", "freecad_groove/cli_options.py", "freecad_groove/cli_parameters.py",
          "freecad_groove/hooks.py"),
         FREECAD | GUI | FREECAD_LAYER | GUI_LAYER | VERIFY_LAYER),
        (("freecad_groove/verify/*.py",), FREECAD | GUI | FREECAD_LAYER | GUI_LAYER),
        (("freecad_groove/cli_verify.py",), FREECAD | GUI | FREECAD_LAYER | GUI_LAYER),
        # The package's make_groove() loads the FreeCAD layer lazily, on its first call.
        (("freecad_groove/__init__.py",), FREECAD | GUI | GUI_LAYER),
        (("freecad_groove/freecad/*.py", "freecad_groove/freecad/posts/*.py", "freecad_groove/demo.py",
          "postprocessors/*_post.py", "Init.py"),
         GUI | GUI_LAYER),
    ],
    ids=["engine", "verify", "cli_verify", "package", "freecad"],
)
def test_layer_imports(patterns, forbidden):
    for path in files(*patterns):
        for name in imported_modules(path):
            hit = _hits(name, forbidden)
            assert not hit, "%s imports %s" % (os.path.relpath(path, ROOT), name)


def test_rule_catches_a_forbidden_import(tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("def f():\n    from PySide import QtCore\n")
    assert "PySide" in list(imported_modules(str(bad)))


@pytest.mark.parametrize("source, package, found, layer, allowed", [
    # the FreeCAD layer importing the GUI layer
    ("from ..gui import task_panel\n", "freecad", "freecad_groove.gui.task_panel", GUI_LAYER,
     "freecad_groove.freecad.groove_op"),
    # the engine importing the verification package
    ("from ..verify import simulate\n", "engine", "freecad_groove.verify", VERIFY_LAYER, "freecad_groove.engine.moves"),
])
def test_rule_catches_a_relative_import_of_an_upper_layer(tmp_path, source, package, found, layer, allowed):
    bad = tmp_path / "bad.py"
    bad.write_text(source)
    names = list(imported_modules(str(bad), package=["freecad_groove", package]))
    assert found in names
    assert _hits(found, layer)
    assert not _hits(allowed, layer)


def test_the_engine_patterns_reach_every_engine_package():
    """A new package under engine/ (output/, cycles/) is checked like the rest."""
    checked = set(files("freecad_groove/engine/**/*.py"))
    for sub in ("output", "cycles"):
        inside = glob.glob(os.path.join(ROOT, "freecad_groove", "engine", sub, "*.py"))
        assert inside and set(inside) <= checked, sub
