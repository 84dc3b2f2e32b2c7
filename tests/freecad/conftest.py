"""Fixtures of the FreeCAD-level tests (run inside FreeCAD; the host's tests/conftest.py ignores this folder)."""

import pytest


@pytest.fixture
def closing():
    """A list the test appends its documents to; each is closed after the test."""
    import FreeCAD

    docs = []
    yield docs
    for doc in docs:
        FreeCAD.closeDocument(doc.Name)


@pytest.fixture
def console(monkeypatch):
    """FreeCAD's report view: {"PrintMessage": [...], "PrintError": [...]} from now on."""
    import FreeCAD

    seen = {"PrintMessage": [], "PrintError": []}
    for kind, lines in seen.items():
        monkeypatch.setattr(FreeCAD.Console, kind, lines.append, raising=False)
    return seen
