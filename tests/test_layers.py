"""The three layers' import rule, read from the source (no FreeCAD needed):
imports only point down. The engine imports neither FreeCAD nor Qt nor the
upper layers nor the verification package; the FreeCAD layer (freecad_groove/
freecad/, the posts, each op's folder under freecad_groove/ops/ but its gui/
package) and Init.py import FreeCAD but never Qt or the GUI layer
(freecad_groove/gui/ and every op's gui/ package); only the GUI layer,
InitGui.py and the GUI tests import FreeCADGui or Qt. The ops' declarations
(ops/__init__.py, ops/registry.py, each op folder's __init__.py) import
nothing but each other: FreeCAD's GUI reads them when it starts, before CAM.
The verification package (freecad_groove.verify) imports the engine and
shapely but neither FreeCAD nor Qt nor the FreeCAD and GUI layers."""

import ast
import glob
import os
import re

import pytest
from conftest import ROOT

FREECAD = {"FreeCAD", "Part", "Path", "PathScripts", "Mesh", "Sketcher"}
GUI = {"FreeCADGui", "PySide", "PySide2", "PySide6", "PyQt5", "PyQt6", "Gui", "pivy"}
OPS = os.path.join(ROOT, "freecad_groove", "ops")
OP_FOLDERS = sorted(n for n in os.listdir(OPS) if os.path.isfile(os.path.join(OPS, n, "__init__.py")))
FREECAD_LAYER = {"freecad_groove.freecad", "freecad_groove.ops"}
# the shared GUI package and every op's gui/ package
GUI_LAYER = {"freecad_groove.gui"} | {"freecad_groove.ops.%s.gui" % op for op in OP_FOLDERS}
VERIFY_LAYER = {"freecad_groove.verify"}
# What an op declaration may import: the registry and the other declarations (the package, an op's package).
DECLARATION_IMPORTS = re.compile(r"freecad_groove\.ops(\.registry(\.\w+)?|\.\w+(\.KIND)?)?$")


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
          "freecad_groove/cli_io.py", "freecad_groove/cli_options.py", "freecad_groove/cli_parameters.py"),
         FREECAD | GUI | FREECAD_LAYER | GUI_LAYER | VERIFY_LAYER),
        (("freecad_groove/verify/*.py",), FREECAD | GUI | FREECAD_LAYER | GUI_LAYER),
        (("freecad_groove/cli_verify.py",), FREECAD | GUI | FREECAD_LAYER | GUI_LAYER),
        # The package's make_groove() loads the FreeCAD layer lazily, on its first call.
        (("freecad_groove/__init__.py",), FREECAD | GUI | GUI_LAYER),
        (("freecad_groove/freecad/*.py", "freecad_groove/freecad/posts/*.py", "freecad_groove/demo/*.py",
          "postprocessors/*_post.py", "Init.py"),
         GUI | GUI_LAYER),
        # each op's folder but its gui/ package: the FreeCAD layer
        (("freecad_groove/ops/*.py", "freecad_groove/ops/*/*.py"), GUI | GUI_LAYER),
    ],
    ids=["engine", "verify", "cli_verify", "package", "freecad", "ops"],
)
def test_layer_imports(patterns, forbidden):
    for path in files(*patterns):
        for name in imported_modules(path):
            hit = _hits(name, forbidden)
            assert not hit, "%s imports %s" % (os.path.relpath(path, ROOT), name)


def test_the_ops_rule_reads_every_op_module_but_the_gui_packages():
    checked = files("freecad_groove/ops/*.py", "freecad_groove/ops/*/*.py")
    assert {"groove", "slot", "grind", "turning_check"} <= set(OP_FOLDERS)
    for op in OP_FOLDERS:
        assert os.path.join(OPS, op, "__init__.py") in checked
        assert not [path for path in checked if os.sep + "gui" + os.sep in path]
        assert glob.glob(os.path.join(OPS, op, "gui", "*.py")), "%s has no gui/ package" % op
    assert os.path.join(OPS, "groove", "op.py") in checked


def test_the_op_declarations_import_only_each_other():
    for path in files("freecad_groove/ops/__init__.py", "freecad_groove/ops/registry.py",
                      "freecad_groove/ops/*/__init__.py"):
        for name in imported_modules(path):
            if name.startswith("freecad_groove") or name.split(".")[0] in FREECAD | GUI:
                assert DECLARATION_IMPORTS.match(name), "%s imports %s" % (os.path.relpath(path, ROOT), name)


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
    # an op's FreeCAD-layer module importing its own gui/ package, or another op's
    ("from .gui import view\n", "ops.groove", "freecad_groove.ops.groove.gui.view", GUI_LAYER,
     "freecad_groove.ops.groove.plan"),
    ("from ..grind.gui.panel import PlungeGrindPage\n", "ops.slot", "freecad_groove.ops.grind.gui.panel", GUI_LAYER,
     "freecad_groove.ops.grind.plan"),
])
def test_rule_catches_a_relative_import_of_an_upper_layer(tmp_path, source, package, found, layer, allowed):
    bad = tmp_path / "bad.py"
    bad.write_text(source)
    names = list(imported_modules(str(bad), package=["freecad_groove"] + package.split(".")))
    assert found in names
    assert _hits(found, layer)
    assert not _hits(allowed, layer)


def test_the_engine_patterns_reach_every_engine_package():
    """A new package under engine/ (output/, cycles/) is checked like the rest."""
    checked = set(files("freecad_groove/engine/**/*.py"))
    for sub in ("output", "cycles"):
        inside = glob.glob(os.path.join(ROOT, "freecad_groove", "engine", sub, "*.py"))
        assert inside and set(inside) <= checked, sub


def test_rule_catches_qt_in_an_ops_freecad_layer_module(tmp_path):
    """A GUI import in an op's module outside its gui/ package fails the ops rule (as the engine's would)."""
    bad = tmp_path / "bad.py"
    bad.write_text("import FreeCAD\nfrom PySide import QtGui\nimport FreeCADGui\n")
    hits = [name for name in imported_modules(str(bad), package=["freecad_groove", "ops", "groove"])
            if _hits(name, GUI | GUI_LAYER)]
    assert hits == ["PySide", "FreeCADGui"]


def test_rule_catches_an_op_declaration_importing_its_op(tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("from .op import ObjectGroove\n")
    names = list(imported_modules(str(bad), package=["freecad_groove", "ops", "groove"]))
    assert names == ["freecad_groove.ops.groove.op", "freecad_groove.ops.groove.op.ObjectGroove"]
    assert not any(DECLARATION_IMPORTS.match(name) for name in names)
    assert DECLARATION_IMPORTS.match("freecad_groove.ops.registry.OpKind")
    assert DECLARATION_IMPORTS.match("freecad_groove.ops.groove.KIND")
