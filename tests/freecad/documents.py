"""Opening FreeCAD documents in tests: saved ones in tests/freecad/data/, and
a document saved and opened again. Shared by the FreeCAD-level tests and the
GUI tests (tests/freecad_gui/). Needs FreeCAD, not pytest.
"""

import contextlib
import os
import re
import zipfile

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


def stored_classes(path, member="Document.xml", tag="Object"):
    """{object name: "module.Class"} of the Python proxies a saved document stores in ``member``: the objects'
    in Document.xml, the view providers' (tag "ViewProvider") in GuiDocument.xml."""
    with zipfile.ZipFile(str(path)) as saved:
        xml = saved.read(member).decode()
    found = {}
    for name, body in re.findall(r'<%s name="([^"]+)"[^>]*>(.*?)</%s>' % (tag, tag), xml, re.S):
        proxy = re.search(r'<Python [^>]*module="([^"]+)" class="([^"]+)"', body)
        if proxy:
            found[name] = "%s.%s" % proxy.groups()
    return found


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
    it, short of where the G1 ended), nor the free-off at the bottom of its
    later plunges (see _without_free_offs): the path an earlier release wrote."""
    out = []
    for name, words in commands:
        if name == "G0" and len(out) >= 2 and out[-1][0] == "G0" and out[-2][0] == "G1" \
                and _back_in(out[-2][1], out[-1][1], words):
            continue
        out.append((name, words))
    return _without_free_offs(out)


FREE_OFF_MM = 1.0  # the saved documents are metric


def _moved(a, b):
    """The axes along which ``b`` moves from ``a`` (words as in path_commands)."""
    return [k for k in ("X", "Y", "Z") if k in b and a.get(k) != b[k]]


def _without_free_offs(commands):
    """``commands`` without CYCLE93's free-off (issue 9): at the bottom of a
    plunge (a G0 then a G1 along one axis) a G1 (a G0 since issue 22) of at
    most 1 mm along the other axis, then G0s out from there. The free-off is dropped and the G0s
    that follow it, up to the next G1, start from the plunge's position again
    (the freed coordinate back to the plunge's), as an earlier release wrote
    them; every other move is kept as it is."""
    out, swap, held = [], None, None
    for name, words in commands:
        if held is not None:  # a move that looked like a free-off: one only if a rapid goes straight out next
            held_name, held_words, free = held
            held = None
            if name == "G0" and words.get(free[0], free[1]) == free[1] and _moved(held_words, words):
                swap = free
            else:
                out.append((held_name, held_words))
        free = _free_off(out, words) if name in ("G0", "G1") else None
        if free is not None:  # a G1, or since issue 22 (item 4) a G0: the free-off is a rapid now
            swap = None
            held = (name, words, free)
            continue
        if name == "G1":
            swap = None
        elif name == "G0" and swap is not None and words.get(swap[0]) == swap[1]:
            words = dict(words, **{swap[0]: swap[2]})
        out.append((name, words))
    if held is not None:
        out.append(held[:2])
    return out


def _free_off(out, words):
    """(axis, freed value, plunge's value) when a G1 with ``words`` after
    ``out`` is a free-off, else None."""
    last = [(n, w) for n, w in out[-3:] if n != "G4"][-2:]  # a dwell may stand at the bottom
    if [n for n, _w in last] != ["G0", "G1"]:
        return None
    before, bottom = last[0][1], last[1][1]
    down, along = _moved(before, bottom), _moved(bottom, words)
    if len(down) != 1 or len(along) != 1 or down == along:
        return None
    axis = along[0]
    if not 0 < abs(words[axis] - bottom[axis]) <= FREE_OFF_MM + 1e-6:
        return None
    return axis, words[axis], bottom[axis]
