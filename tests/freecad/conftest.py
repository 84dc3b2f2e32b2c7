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
