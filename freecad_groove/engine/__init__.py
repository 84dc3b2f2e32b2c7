"""The freecad-groove cycle engine: pure Python, no FreeCAD, no Qt.

Plain data in (cycle parameters, the machine state before the call, settings),
plain data out (expanded moves, native call text, G-code programs).
"""

from .errors import CycleError, ProgramError
from .moves import DWELL, FEED, RAPID, GroovingTool, MachineState, Move
from .settings import DEFAULT_SETTINGS, Settings

__all__ = [
    "CycleError",
    "ProgramError",
    "Move",
    "RAPID",
    "FEED",
    "DWELL",
    "GroovingTool",
    "MachineState",
    "Settings",
    "DEFAULT_SETTINGS",
]
