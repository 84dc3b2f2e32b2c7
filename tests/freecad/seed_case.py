"""The seed CYCLE93 call, expanded the same way on the host and inside FreeCAD.

No FreeCAD import: tests/test_freecad.py (host) writes ``as_json()`` into the
directory it shares with the FreeCAD run, and test_environment.py (inside
FreeCAD) expands the same call again and compares.
"""

from freecad_groove.engine import GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles.cycle93 import Cycle93

SEED_CALL = "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"
START = {"x": 40.0, "z": 65.0}  # N30 G00 X80 Z65: x is a radius
TOOL = {"width": 3.0, "corner_radius": 0.4}
HOST_MOVES_FILE = "host_moves.json"


def expand():
    """The seed call's moves: a list of Move (its arcs with their centres)."""
    settings = Settings(tool=GroovingTool(TOOL["width"], TOOL["corner_radius"]))
    return Cycle93.parse(SEED_CALL).expand(MachineState(**START), settings)


def as_json():
    """The inputs and the moves, as plain JSON data."""
    return {
        "call": SEED_CALL,
        "start": dict(START),
        "tool": dict(TOOL),
        "moves": [[m.kind, m.x, m.z, m.f, m.p] + (list(m.centre) if m.centre else [None, None]) for m in expand()],
    }
