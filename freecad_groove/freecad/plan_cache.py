"""A Groove op's plans kept in the saved document, with the fingerprint of
what they were planned from.

Planning (groove_plan.py: the engine's expansion and warnings, the link
rapids checked against the model) is the costly part of a post. The op keeps
its plans after a recompute; after reopening a document they are gone, and
every post would plan every op again. So the op's proxy saves them (dumps:
what a post reads of each GroovePlan) with a fingerprint taken when they were
planned, and after reopening reuses them only when the fingerprint of the
document's inputs is the same; otherwise the op plans again (nothing stale is
trusted). The fingerprint covers every input plan() reads:

- the add-on's version and a digest of its planning code (the engine and the
  FreeCAD layer's modules: a changed add-on never reuses an old plan);
- the op's input properties (groove_properties.PROPERTIES less the derived
  ones), Base (objects and faces, and those objects' properties and Shape
  digests) and ToolController;
- the tool controller's and its tool bit's properties (feeds, Width,
  CornerRadius, ...; not the bit's Shape, its 3D view);
- the Job's model objects (their properties, Label included: faces are named
  by it, and a digest of each Shape's BREP text: every face and Placement)
  and its Stock and SetupSheet.

A restored plan has no ``geometry`` (GroovePlan.geometry: the preview's,
which plans afresh); the rest is what the plan held when it was saved.

FreeCAD layer: duck-typed FreeCAD objects, no FreeCAD import.
"""

import base64
import dataclasses
import functools
import hashlib
import json
import os
import re
import zlib
from typing import Optional

from .. import __version__
from ..engine import GroovingTool, MachineState, Settings
from ..engine.cycles.cycle93 import Cycle93
from ..engine.moves import Move
from ..engine.warnings import CycleWarning
from .faces import GrooveFace
from .groove_plan import GroovePlan
from .groove_properties import DERIVED, PROPERTIES
from .links import LinkMove

FORMAT = 2  # of the saved data (2: a plan keeps its retreat); a new format never reads an old one
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
    """The add-on's version and a digest of its planning code (the engine and
    the FreeCAD layer's modules; the posts and the GUI do not plan)."""
    package = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    digest = hashlib.sha256(__version__.encode())
    for folder in ("engine", os.path.join("engine", "cycles"), "freecad"):
        path = os.path.join(package, folder)
        for name in sorted(os.listdir(path)):
            if name.endswith(".py"):
                with open(os.path.join(path, name), "rb") as f:
                    digest.update(name.encode() + b"\0" + f.read())
    return "%s+%s" % (__version__, digest.hexdigest()[:16])


def _canonical(value: object) -> object:
    """A property value as JSON data that changes whenever the value does."""
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, (list, tuple)):
        return [_canonical(item) for item in value]
    if isinstance(value, dict):
        return [[str(k), _canonical(v)] for k, v in sorted(value.items(), key=lambda item: str(item[0]))]
    if hasattr(value, "Value") and hasattr(value, "Unit"):  # a Quantity
        return ["Q", repr(value.Value), str(value.Unit)]
    if hasattr(value, "Name") and hasattr(value, "Document"):  # a linked object: its own values count elsewhere
        return ["O", value.Name]
    if hasattr(value, "Base") and hasattr(value, "Rotation"):  # a Placement
        return ["P", _canonical(tuple(value.Base)), _canonical(tuple(value.Rotation.Q))]
    if hasattr(value, "x") and hasattr(value, "y") and hasattr(value, "z"):  # a Vector
        return ["V", repr(value.x), repr(value.y), repr(value.z)]
    text = repr(value)
    if " at 0x" in text:  # a repr naming an address (a Material) changes with every session: not a planning input
        return [type(value).__name__]
    return [type(value).__name__, text]


def _shape_digest(shape: object) -> Optional[str]:
    """A digest of a Part shape's BREP text (its geometry, topology and
    placement), less what a save and reopen changes (BREP_FLAGS, BREP_NEGATIVE_ZERO)."""
    if shape is None or shape.isNull():
        return None
    text = BREP_NEGATIVE_ZERO.sub("0", BREP_FLAGS.sub("", shape.exportBrepToString()))
    return hashlib.sha256(text.encode()).hexdigest()


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


def fingerprint(op: object, job: object) -> str:
    """The fingerprint of every input ``op``'s plans depend on (the module's notes)."""
    tool_controller = getattr(op, "ToolController", None)
    data = [
        FORMAT, engine_stamp(), _values(op, OP_INPUTS),
        # a tool bit's Shape is its 3D view (rebuilt on opening): its properties are what plans read
        _values(tool_controller, shape=False), _values(getattr(tool_controller, "Tool", None), shape=False),
        [_values(base) for base, _subs in op.Base or []],
        [_values(model) for model in job.Model.Group],
        _values(getattr(job, "Stock", None)), _values(getattr(job, "SetupSheet", None)),
    ]
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()


# -- the saved plans ----------------------------------------------------------------
def _fields(value: object) -> dict:
    return {f.name: getattr(value, f.name) for f in dataclasses.fields(value)}


def _plan_data(plan: GroovePlan, faces: list) -> list:
    face = _fields(plan.face)
    if face not in faces:
        faces.append(face)
    return [faces.index(face), plan.index, plan.position, _fields(plan.cycle), _fields(plan.start), plan.start_on,
            [list(step) for step in plan.link], [list(move) for move in plan.moves],
            [[w.cycle, w.parameter, w.message] for w in plan.warnings], [list(step) for step in plan.retreat]]


def pack(plans: list[GroovePlan], stamp: str) -> str:
    """The text the op's proxy saves: ``plans`` with their fingerprint ``stamp``."""
    faces: list = []
    settings = [_fields(plans[0].settings) if plans else None]
    if plans and any(plan.settings != plans[0].settings for plan in plans):  # one per op today; guarded
        settings = [_fields(plan.settings) for plan in plans]
    data = {"format": FORMAT, "fingerprint": stamp, "plans": [_plan_data(plan, faces) for plan in plans],
            "faces": faces, "settings": [dict(s, tool=s["tool"] and _fields(s["tool"])) for s in settings if s]}
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


def _settings(data: dict) -> Settings:
    tool = data["tool"]
    return Settings(**dict(data, tool=GroovingTool(**tool) if tool else None))


def unpack(text: str, stamp: Optional[str] = None) -> Optional[list[GroovePlan]]:
    """The plans of a pack() text (their ``geometry`` None); None when it is
    not one, or when ``stamp`` is given and is not its fingerprint."""
    data = _unpacked(text)
    if data is None or (stamp is not None and data["fingerprint"] != stamp):
        return None
    faces = [GrooveFace(**dict(face, start=tuple(face["start"]), end=tuple(face["end"]))) for face in data["faces"]]
    settings = [_settings(s) for s in data["settings"]]
    plans = []
    for k, (face, index, position, cycle, start, start_on, link, moves, warnings, retreat) in enumerate(data["plans"]):
        plans.append(GroovePlan(
            faces[face], index, position, Cycle93(**cycle), settings[k if len(settings) > 1 else 0],
            MachineState(**start), start_on, [LinkMove(*step) for step in link], [Move(*move) for move in moves],
            [LinkMove(*step) for step in retreat], None, [CycleWarning(*w) for w in warnings]))
    return plans
