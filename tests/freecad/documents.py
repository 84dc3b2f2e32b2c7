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


def _back_in(cut, up, down):
    """True when ``down`` lies strictly between ``cut`` and ``up`` on the one
    line along one axis that joins them (words as in path_commands)."""
    axes = [k for k in ("X", "Y", "Z") if k in cut or k in up or k in down]  # not the G1's F
    moved = [k for k in axes if cut.get(k) != up.get(k)]
    if len(moved) != 1 or any(down.get(k) != cut.get(k) for k in axes if k not in moved):
        return False
    a, b, c = cut[moved[0]], up[moved[0]], down[moved[0]]
    return min(a, b) < c < max(a, b)


def without_chip_break_reentries(commands):
    """``commands`` (path_commands) without the rapid back down its own slot
    that CYCLE93 makes after each chip-breaking retract since issue 9 (a G1
    into the part, a G0 back out along the same line, then a G0 back in along
    it, short of where the G1 ended): the path an earlier release wrote."""
    out = []
    for name, words in commands:
        if name == "G0" and len(out) >= 2 and out[-1][0] == "G0" and out[-2][0] == "G1" \
                and _back_in(out[-2][1], out[-1][1], words):
            continue
        out.append((name, words))
    return out
