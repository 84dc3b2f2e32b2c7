"""The size rule of the code base, read from the source: no module of the
add-on over MAX_MODULE_LINES lines, no function over MAX_FUNCTION_LINES (a
module or function grown past them holds more than one concept: split it)."""

import ast
import glob
import os

import pytest
from conftest import ROOT

MAX_MODULE_LINES = 500
MAX_FUNCTION_LINES = 60
SOURCES = sorted(glob.glob(os.path.join(ROOT, "freecad_groove", "**", "*.py"), recursive=True)
                 + glob.glob(os.path.join(ROOT, "postprocessors", "*.py"))
                 + [os.path.join(ROOT, "Init.py"), os.path.join(ROOT, "InitGui.py")])


def too_long(source, filename="<source>"):
    """'what: lines' for the module and each function of ``source`` beyond the rule."""
    found = []
    lines = source.count("\n")
    if lines > MAX_MODULE_LINES:
        found.append("module: %d lines" % lines)
    for node in ast.walk(ast.parse(source, filename)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            length = node.end_lineno - node.lineno + 1
            if length > MAX_FUNCTION_LINES:
                found.append("%s: %d lines" % (node.name, length))
    return found


def test_the_rule_finds_a_long_function_and_a_long_module():
    function = "def long():\n" + "    x = 1\n" * 60
    assert too_long(function) == ["long: 61 lines"]
    assert too_long("x = 1\n" * 501) == ["module: 501 lines"]
    assert too_long("def short():\n" + "    x = 1\n" * 59) == []


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: os.path.relpath(p, ROOT))
def test_no_module_over_500_lines_and_no_function_over_60(path):
    with open(path, encoding="utf-8") as f:
        assert too_long(f.read(), path) == []
