"""The modal state of an input program: what the reader knows after each block."""

from dataclasses import dataclass, field
from typing import Dict, Optional, Set

from .moves import MachineState
from .reader import Word

__all__ = ["ModalState", "TRACKED"]


@dataclass
class ModalState:
    """What the reader knows after each block. None = unknown.

    x is a radius, z absolute, in the program's current units.
    """

    x: Optional[float] = None
    z: Optional[float] = None
    c: Optional[float] = None  # the rotary C axis in degrees (GSK), None = unknown
    y: Optional[float] = None  # mill-style programs (Dialect.mill)
    motion: Optional[str] = None  # RAPID, FEED, "G2", "G3"
    incremental: bool = False  # G91 (Siemens, AB)
    diameter: bool = True  # X words are diameters
    diam90: bool = False  # Siemens DIAM90: diameters in G90, radii in G91
    metric: bool = True
    siemens_g70: bool = False  # Siemens G70: inch lengths, feed in the basic system
    feed_per_rev: Optional[bool] = None
    feed: Optional[float] = None
    spindle: Optional[float] = None  # the last S value
    spindle_dir: Optional[int] = None  # 3 / 4 running (M3/M4), 5 stopped, None not started in this program
    css: bool = False  # G96 active
    speed_limit: Optional[float] = None  # G50 S / LIMS=
    tool: Optional[int] = None
    retract_e: Optional[Word] = None  # Fanuc "G75 R(e)" / "G74 R(e)"
    # what a cycle with a program memory (cycle class MEMORY, e.g. G83) left for the next one: key -> words;
    # replaced, never changed in place, so a block-delete line that changes it makes it ambiguous
    cycle_memory: Dict[str, Dict[str, float]] = field(default_factory=dict)
    ended: bool = False
    ambiguous: Set[str] = field(default_factory=set)  # items a block-delete '/' line may have changed

    def x_words_diameter(self) -> bool:
        """True when the X words of the next block are diameters."""
        return self.diameter and not (self.diam90 and self.incremental)

    def machine_state(self) -> MachineState:
        """The state a cycle called now starts from."""
        return MachineState(
            x=self.x,
            z=self.z,
            feed=self.feed,
            diameter_mode=self.x_words_diameter(),
            incremental=self.incremental,
            metric=self.metric,
            feed_per_rev=bool(self.feed_per_rev),
            c=self.c,
            y=self.y,
        )


# the items a block-delete line makes ambiguous when it changes them
TRACKED = ("x", "y", "z", "motion", "incremental", "diameter", "diam90", "metric", "siemens_g70", "feed_per_rev",
           "feed", "spindle", "spindle_dir", "css", "speed_limit", "tool", "retract_e", "cycle_memory", "c")
