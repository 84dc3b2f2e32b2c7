"""Opening FreeCAD documents in tests: saved ones in tests/freecad/data/, and
a document saved and opened again. Shared by the FreeCAD-level tests and the
GUI tests (tests/freecad_gui/). Needs FreeCAD, not pytest.
"""

import contextlib
import os

import FreeCAD

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")


@contextlib.contextmanager
def opened(path):
    """The document at ``path``, open for the with block, closed after it."""
    doc = FreeCAD.openDocument(path)
    try:
        yield doc
    finally:
        if doc.Name in FreeCAD.listDocuments():
            FreeCAD.closeDocument(doc.Name)


@contextlib.contextmanager
def reopened(doc, path):
    """``doc`` saved as ``path``, closed, and open again for the with block."""
    doc.saveAs(str(path))
    FreeCAD.closeDocument(doc.Name)
    with opened(str(path)) as again:
        yield again


def path_commands(obj):
    """[(name, {word: value rounded to 6 places})] of an object's Path."""
    return [(c.Name, {k: round(v, 6) for k, v in c.Parameters.items()}) for c in obj.Path.Commands]
