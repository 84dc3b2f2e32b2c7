"""Warnings: what a cycle cannot do as asked, reported without stopping the run.

A cycle that runs, but not quite as programmed (CYCLE93 roughing on the final
profile because the allowances leave the blade no room) or in a way that may
crash (a Fanuc relief that rapids the blade into the wall between grooves),
says so with a :class:`CycleWarning`. Errors stop the run (``CycleError``);
warnings never change the moves.

Each cycle class may define ``warnings(state, settings) -> List[CycleWarning]``
beside ``expand()`` (the hook of ``cycle.Cycle``, whose default is none);
:func:`cycle_warnings` calls it. The translator collects them per
line (``Translator.warnings``), the command line prints them on stderr as
``PROGRAM:LINE: warning: CYCLE93: ...`` and the FreeCAD op in its report view.
"""

from dataclasses import dataclass
from typing import TYPE_CHECKING, List, Optional

from .moves import MachineState
from .settings import Settings

if TYPE_CHECKING:  # cycle.py imports this module
    from .cycle import Cycle

__all__ = ["CycleWarning", "cycle_warnings"]


@dataclass(frozen=True)
class CycleWarning:
    """One warning of a cycle call.

    ``cycle`` the cycle's name ("CYCLE93", "G75"); ``parameter`` the word or
    parameter it concerns ("FAL2", "R"), None when none; ``message`` what the
    cycle does instead, naming the values.
    """

    cycle: str
    parameter: Optional[str]
    message: str

    @property
    def text(self) -> str:
        """The one-line text: ``CYCLE93: message``."""
        return "%s: %s" % (self.cycle, self.message)


def cycle_warnings(model: "Cycle", state: MachineState, settings: Settings) -> List[CycleWarning]:
    """The warnings of a cycle model (its ``warnings(state, settings)``; Cycle's default: none)."""
    return list(model.warnings(state, settings))
