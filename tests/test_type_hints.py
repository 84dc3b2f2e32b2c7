"""The engine's public API is typed: every public function, method and class
constructor of freecad_groove/engine/ (names without a leading underscore, in
modules and classes without one) annotates its parameters and its return.
Read from the source, so a new public function without hints fails here."""

import ast
import glob
import os

import pytest
from conftest import ROOT

ENGINE = sorted(glob.glob(os.path.join(ROOT, "freecad_groove", "engine", "**", "*.py"), recursive=True))


def _public(name):
    return not name.startswith("_") or name == "__init__"


def unannotated(source, filename="<source>"):
    """'name: what is missing' for each public function of ``source`` lacking hints."""
    tree = ast.parse(source, filename)
    missing = []

    def check(func, owner):
        where = owner + func.name
        args = func.args
        params = args.posonlyargs + args.args + args.kwonlyargs
        if owner and params and params[0].arg in ("self", "cls"):
            params = params[1:]
        for extra in (args.vararg, args.kwarg):
            if extra is not None:
                params.append(extra)
        for param in params:
            if param.annotation is None:
                missing.append("%s: parameter %s" % (where, param.arg))
        if func.returns is None:
            missing.append("%s: return" % where)

    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and _public(node.name):
            check(node, "")
        elif isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
            for item in node.body:
                if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)) and _public(item.name):
                    check(item, node.name + ".")
    return missing


def test_the_check_finds_a_missing_parameter_and_return_hint():
    source = (
        "def typed(a: int) -> int: ...\n"
        "def untyped(a, b: int): ...\n"
        "def _private(a): ...\n"
        "class Model:\n"
        "    def method(self, x: float) -> None: ...\n"
        "    def bare(self, y): ...\n"
        "class _Hidden:\n"
        "    def free(self, z): ...\n"
    )
    assert unannotated(source) == [
        "untyped: parameter a", "untyped: return", "Model.bare: parameter y", "Model.bare: return",
    ]


@pytest.mark.parametrize("path", ENGINE, ids=lambda p: os.path.relpath(p, ROOT))
def test_public_engine_api_has_type_hints(path):
    with open(path, encoding="utf-8") as f:
        assert unannotated(f.read(), path) == []
