"""A Groove op's plans kept in the saved document, with the fingerprint of
what they were planned from.

Planning (plan.py: the engine's expansion and warnings, the link
rapids checked against the model) is the costly part of a post. The op keeps
its plans after a recompute; after reopening a document they are gone, and
every post would plan every op again. So the op's proxy saves them (dumps:
what a post reads of each GroovePlan) with a fingerprint taken when the
document is saved (kept_plans.py: only while the op is untouched since it
planned them and the objects it read are the same; else nothing is saved),
and after reopening reuses them only when the fingerprint of the
document's inputs is the same; otherwise the op plans again (nothing stale is
trusted). The fingerprint covers every input plan() reads:

- the add-on's version and a digest of its planning code (the engine, the
  shared FreeCAD layer's modules and the Groove op's: a changed add-on never
  reuses an old plan);
- the op's input properties (properties.PROPERTIES less the derived
  ones), Base (objects and faces, and those objects' properties and Shape
  digests) and ToolController;
- the tool controller's and its tool bit's properties (feeds, Width,
  CornerRadius, ...; not the bit's Shape, its 3D view);
- the Job's model objects (their properties, Label included: faces are named
  by it, and a digest of each Shape's BREP text: every face and Placement)
  and its Stock and SetupSheet.

What the op reads of the other objects (inputs(): the tool controller, the
bit, Base, the model, the stock, the setup sheet) is digested once per change
of each (freecad/changes.py; a shape's BREP digest once per shape,
freecad/shape_memo.py): in the session, the kept plans are checked against it
before every post (a Job's stock changed recomputes no op).

A restored plan has no ``geometry`` (GroovePlan.geometry: the preview's,
which plans afresh); the rest is what the plan held when it was saved.

When the costs fall (benchmarks/bench_freecad.sh, 500 grooves): the proxy
reads its saved plans as the document opens (read(), in its loads: about
1.4 ms per 100 grooves); the first post that needs an op's plans checks the
fingerprints of every Groove op of its Job at once, reading each input they
share (tool controller, model, stock: one BREP digest each) once (the memo
of inputs()). The ops whose fingerprint matches take their saved plans,
as if recomputed then; the others plan again at their own post, once: the
plans are kept with their fingerprint for the next posts (and the next
save) while the op stays untouched (ObjectGroove.current_plan; an input
changed while the document was closed, a document that saved none). So the
first post after reopening costs a fingerprint per op more than a post
before saving (about 0.2 ms, the first op's 0.7 ms).

FreeCAD layer: duck-typed FreeCAD objects (FreeCAD itself through changes.py and shape_memo.py).
"""

import base64
import dataclasses
import functools
import hashlib
import json
import math
import os
import re
import struct
import zlib
from typing import NamedTuple, Optional

from ... import __version__
from ...engine import GroovingTool, MachineState, Settings
from ...engine.cycles.cycle93 import Cycle93
from ...engine.moves import Move
from ...engine.warnings import CycleWarning
from ...freecad.changes import read_once
from ...freecad.faces import GrooveFace
from ...freecad.shape_memo import ShapeMemo
from .links import LinkMove
from .plan import GroovePlan
from .properties import DERIVED, PROPERTIES

# Of the saved data (2: a plan keeps its retreat; 3: column-wise; 4: arcs, their centres): a new format never
# reads an old one (the op plans again), and an older release never reads a newer one.
FORMAT = 4
# Property types left out of an object's fingerprint: outputs (Path), shapes
# (digested on their own), the proxy, expressions (their results are values).
SKIPPED_TYPES = ("Part::PropertyPartShape", "Path::PropertyPath", "App::PropertyPythonObject",
                 "App::PropertyExpressionEngine")
SKIPPED_NAMES = ("Visibility",)  # hiding an object changes no plan
# BREP text that differs for one shape after saving and reopening it: the flags
# line of each sub-shape (its "checked" flag) and the sign of zeros.
BREP_FLAGS = re.compile(r"^[01]{7}$", re.MULTILINE)
BREP_NEGATIVE_ZERO = re.compile(r"(?<=\s)-0(?=\s)")
OP_INPUTS = tuple(name for _t, name, _g, _tip, _d in PROPERTIES if name not in DERIVED) + ("Base", "ToolController")


@functools.lru_cache(maxsize=None)
def engine_stamp() -> str:
    """The add-on's version and a digest of its planning code (the engine, the
    shared FreeCAD layer's modules and the Groove op's folder; the posts and the GUI do not plan)."""
    package = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    digest = hashlib.sha256(__version__.encode())
    for folder in ("engine", os.path.join("engine", "cycles"), "freecad", "ops", os.path.join("ops", "groove")):
        path = os.path.join(package, folder)
        for name in sorted(os.listdir(path)):
            if name.endswith(".py"):
                with open(os.path.join(path, name), "rb") as f:
                    digest.update(name.encode() + b"\0" + f.read())
    return "%s+%s" % (__version__, digest.hexdigest()[:16])


def _canonical(value: object) -> object:
    """A property value as JSON data that changes whenever the value does (its kind found once per type)."""
    kind = _KINDS.get(type(value))
    if kind is None:
        kind = _KINDS[type(value)] = _kind_of(value)
    return kind(value)


def _repr_value(value: object) -> list:
    text = repr(value)
    if " at 0x" in text:  # a repr naming an address (a Material) changes with every session: not a planning input
        return [type(value).__name__]
    return [type(value).__name__, text]


def _kind_of(value: object):
    """How _canonical writes a value of ``value``'s type."""
    if value is None or isinstance(value, (bool, int, str)):
        return lambda v: v
    if isinstance(value, float):
        return repr
    if isinstance(value, (list, tuple)):
        return lambda v: [_canonical(item) for item in v]
    if isinstance(value, dict):
        return lambda v: [[str(k), _canonical(x)] for k, x in sorted(v.items(), key=lambda item: str(item[0]))]
    if hasattr(value, "Value") and hasattr(value, "Unit"):  # a Quantity
        return lambda v: ["Q", repr(v.Value), str(v.Unit)]
    if hasattr(value, "Name") and hasattr(value, "Document"):  # a linked object: its own values count elsewhere
        return lambda v: ["O", v.Name]
    if hasattr(value, "Base") and hasattr(value, "Rotation"):  # a Placement
        return lambda v: ["P", _canonical(tuple(v.Base)), _canonical(tuple(v.Rotation.Q))]
    if hasattr(value, "x") and hasattr(value, "y") and hasattr(value, "z"):  # a Vector
        return lambda v: ["V", repr(v.x), repr(v.y), repr(v.z)]
    return _repr_value


_KINDS: dict = {}  # type -> _kind_of's function


def _shape_digest(shape: object) -> Optional[str]:
    """A digest of a Part shape's BREP text (its geometry, topology and
    placement), less what a save and reopen changes (BREP_FLAGS, BREP_NEGATIVE_ZERO);
    taken once per shape (shape_memo.py: the model's and the stock's are read at every recompute)."""
    if shape is None or shape.isNull():
        return None
    return _SHAPE_DIGEST(shape)


def _brep_digest(shape: object) -> str:
    text = BREP_NEGATIVE_ZERO.sub("0", BREP_FLAGS.sub("", shape.exportBrepToString()))
    return hashlib.sha256(text.encode()).hexdigest()


_SHAPE_DIGEST = ShapeMemo(_brep_digest)


def _values(obj: object, names: Optional[tuple] = None, shape: bool = True) -> object:
    """[(name, canonical value)] of ``obj``'s properties ``names`` (None: all but
    the skipped ones), plus its Shape's digest when it has one and ``shape``."""
    if obj is None:
        return None
    if names is None:
        names = tuple(name for name in sorted(obj.PropertiesList)
                      if name not in SKIPPED_NAMES and obj.getTypeIdOfProperty(name) not in SKIPPED_TYPES)
    values = [[name, _canonical(getattr(obj, name, None))] for name in names]
    if shape and getattr(obj, "Shape", None) is not None and hasattr(obj.Shape, "exportBrepToString"):
        values.append(["Shape", _shape_digest(obj.Shape)])
    return [obj.Name, values]


def _digest(data: object) -> str:
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()


def _input_digest(obj: object, shape: bool, memo: dict) -> Optional[str]:
    """The digest of _values(obj, shape=shape), taken once per ``memo`` and
    once per change of ``obj`` (changes.read_once)."""
    if obj is None:
        return None
    key = (id(obj), shape)  # the object is kept with its digest: no other object gets its id meanwhile
    kept = memo.get(key)
    if kept is None or kept[0] is not obj:
        kept = memo[key] = (obj, read_once(obj, "plan inputs, shape" if shape else "plan inputs",
                                           lambda o: _digest(_values(o, shape=shape))))
    return kept[1]


def inputs(op: object, job: object, memo: Optional[dict] = None) -> list:
    """The digests of the objects other than ``op`` its plans read (the module's
    notes), each read again only after it changed (changes.py). ``memo``: the
    digests already taken, shared by the ops fingerprinted with it at one time."""
    memo = {} if memo is None else memo
    tool_controller = getattr(op, "ToolController", None)
    return [
        # a tool bit's Shape is its 3D view (rebuilt on opening): its properties are what plans read
        _input_digest(tool_controller, False, memo), _input_digest(getattr(tool_controller, "Tool", None), False, memo),
        [_input_digest(base, True, memo) for base, _subs in op.Base or []],
        [_input_digest(model, True, memo) for model in job.Model.Group],
        _input_digest(getattr(job, "Stock", None), True, memo),
        _input_digest(getattr(job, "SetupSheet", None), True, memo),
    ]


def fingerprint(op: object, job: object, memo: Optional[dict] = None, shared: Optional[list] = None) -> str:
    """The fingerprint of every input ``op``'s plans depend on (the module's
    notes): its own input properties and ``shared`` (default: inputs(op, job, memo))."""
    shared = inputs(op, job, memo) if shared is None else shared
    return _digest([FORMAT, engine_stamp(), _values(op, OP_INPUTS), shared])


# -- the saved plans ----------------------------------------------------------------
# The format is column-wise, to read fast (the first post after reopening reads
# every op's plans): each dataclass's fields named once, the moves' X and Z
# as packed IEEE doubles (exact), their kinds as one string, the few feeds and
# dwell times they carry as [move number, value], an arc's centre as [move
# number, x, z] and a radius arc's radius as [move number, radius]. JSON keeps
# int, float and None apart.
DATACLASSES = {"face": GrooveFace, "cycle": Cycle93, "start": MachineState, "settings": Settings,
               "tool": GroovingTool}


@functools.cache  # a dataclass's fields do not change: read 6 times per saved op, 36 ms of opening 500 ops
def _names(cls: type) -> list[str]:
    """The field names of dataclass ``cls`` (a list shared by every caller: not to be changed)."""
    return [f.name for f in dataclasses.fields(cls)]


def _row(value: object) -> list:
    return [getattr(value, name) for name in _names(type(value))]


def _settings_row(settings: Settings) -> list:
    row = _row(settings)
    row[_names(Settings).index("tool")] = settings.tool and _row(settings.tool)
    return row


def _indexed(rows: list, row: object) -> int:
    """The index of ``row`` in ``rows`` (appended when new)."""
    if row not in rows:
        rows.append(row)
    return rows.index(row)


def _moves_data(plans: list[GroovePlan]) -> dict:
    kinds: list = []
    codes, numbers, feeds, dwells, counts, centres, radii = [], [], [], [], [], [], []
    for plan in plans:
        counts.append(len(plan.moves))
        for move in plan.moves:
            codes.append(_indexed(kinds, move.kind))
            if move.f is not None:
                feeds.append([len(codes) - 1, move.f])
            if move.p != 0.0 or math.copysign(1.0, move.p) < 0:  # -0.0 kept as it was
                dwells.append([len(codes) - 1, move.p])
            if move.centre is not None:
                centres.append([len(codes) - 1, move.centre[0], move.centre[1]])
            if move.radius is not None:
                radii.append([len(codes) - 1, move.radius])
            numbers += (float(move.x), float(move.z))
    return {"kinds": kinds, "codes": "".join(chr(48 + code) for code in codes), "counts": counts,
            "xz": base64.b64encode(struct.pack("<%dd" % len(numbers), *numbers)).decode("ascii"),
            "f": feeds, "p": dwells, "c": centres, "r": radii}


def pack(plans: list[GroovePlan], stamp: str) -> str:
    """The text the op's proxy saves: ``plans`` with their fingerprint ``stamp``."""
    faces: list = []
    settings: list = []
    columns = {
        "face": [_indexed(faces, _row(plan.face)) for plan in plans],
        "settings": [_indexed(settings, _settings_row(plan.settings)) for plan in plans],
        "index": [plan.index for plan in plans], "position": [plan.position for plan in plans],
        "cycle": [_row(plan.cycle) for plan in plans], "start": [_row(plan.start) for plan in plans],
        "start_on": [plan.start_on for plan in plans],
        "link": [[[step.x, step.z] for step in plan.link] for plan in plans],
        "retreat": [[[step.x, step.z] for step in plan.retreat] for plan in plans],
        "warnings": [[[w.cycle, w.parameter, w.message] for w in plan.warnings] for plan in plans],
    }
    data = {"format": FORMAT, "fingerprint": stamp, "fields": {k: _names(c) for k, c in DATACLASSES.items()},
            "faces": faces, "settings": settings, "plans": columns, "moves": _moves_data(plans)}
    text = json.dumps(data, separators=(",", ":"))
    return base64.b64encode(zlib.compress(text.encode(), 9)).decode("ascii")


def saved_fingerprint(text: str) -> Optional[str]:
    """The fingerprint of a pack() text (None: not one of this format)."""
    data = _unpacked(text)
    return data["fingerprint"] if data is not None else None


def _unpacked(text: str) -> Optional[dict]:
    try:
        data = json.loads(zlib.decompress(base64.b64decode(text)))
    except (ValueError, TypeError, zlib.error):
        return None
    return data if isinstance(data, dict) and data.get("format") == FORMAT else None


def _face(row: list) -> GrooveFace:
    values = dict(zip(_names(GrooveFace), row))
    return GrooveFace(**dict(values, start=tuple(values["start"]), end=tuple(values["end"])))


def _settings(row: list) -> Settings:
    settings = Settings(*row)
    return dataclasses.replace(settings, tool=GroovingTool(*settings.tool)) if settings.tool else settings


def _moves(data: dict) -> list[list[Move]]:
    """The moves of each plan (_moves_data's columns)."""
    kinds = [data["kinds"][ord(code) - 48] for code in data["codes"]]
    numbers = struct.unpack("<%dd" % (2 * len(kinds)), base64.b64decode(data["xz"]))
    feeds, dwells = [None] * len(kinds), [0.0] * len(kinds)
    for k, f in data["f"]:
        feeds[k] = f
    for k, p in data["p"]:
        dwells[k] = p
    moves = list(map(Move, kinds, numbers[0::2], numbers[1::2], feeds, dwells))
    for k, x, z in data["c"]:
        moves[k] = moves[k]._replace(centre=(x, z))
    for k, radius in data["r"]:
        moves[k] = moves[k]._replace(radius=radius)
    out, first = [], 0
    for count in data["counts"]:
        out.append(moves[first:first + count])
        first += count
    return out


class SavedPlans(NamedTuple):
    """What an op's proxy read from the opened document: the pack() text (saved
    again as it is while not used), its fingerprint and its plans."""

    text: str
    fingerprint: str
    plans: list[GroovePlan]


def read(text: object) -> Optional[SavedPlans]:
    """The SavedPlans of a pack() text; None when it is not one (or none)."""
    data = _unpacked(text) if isinstance(text, str) and text else None
    if data is None or data["fields"] != {k: _names(c) for k, c in DATACLASSES.items()}:  # saved by other code
        return None
    faces = [_face(row) for row in data["faces"]]
    settings = [_settings(row) for row in data["settings"]]
    columns = data["plans"]
    plans = [GroovePlan(faces[face], index, position, Cycle93(*cycle), settings[setting], MachineState(*start),
                        start_on, [LinkMove(x, z) for x, z in link], moves, [LinkMove(x, z) for x, z in retreat],
                        None, [CycleWarning(*w) for w in warnings])
             for face, setting, index, position, cycle, start, start_on, link, retreat, warnings, moves in zip(
                 columns["face"], columns["settings"], columns["index"], columns["position"], columns["cycle"],
                 columns["start"], columns["start_on"], columns["link"], columns["retreat"], columns["warnings"],
                 _moves(data["moves"]))]
    return SavedPlans(text, data["fingerprint"], plans)


def unpack(text: str, stamp: Optional[str] = None) -> Optional[list[GroovePlan]]:
    """The plans of a pack() text (their ``geometry`` None); None when it is
    not one, or when ``stamp`` is given and is not its fingerprint."""
    saved = read(text)
    return saved.plans if saved is not None and (stamp is None or saved.fingerprint == stamp) else None
