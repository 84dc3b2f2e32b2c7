"""What a Cylinder slot op cuts (SlotPlan) and the G7.1 region's path blocks
from the developed path (the op plans: op.py).

FreeCAD layer: plain data, no import of FreeCAD.
"""

from typing import List, NamedTuple, Optional, Tuple

from ...engine.cycles.gsk_g7_1 import DECIMALS, GskG7_1, PathBlock
from ...engine.moves import MachineState, Move
from .cutting import SlotCutting
from .developed import SlotCylinder
from .properties import SlotInputError


class SlotPlan(NamedTuple):
    """What the op cuts: the region, where it starts, the safe radius, the moves, what it cuts with."""

    cylinder: SlotCylinder
    region: GskG7_1
    start: MachineState
    safe_radius: float
    moves: List[Move]
    warnings: Tuple[str, ...] = ()  # what the end mill may not do as planned (reach.py): shown, never blocking
    cutting: Optional[SlotCutting] = None  # the feed and the live tool's speed (cutting.py)


def rounded(value: float) -> float:
    """``value`` to the region's decimals (no -0.0)."""
    return round(value, DECIMALS) + 0.0


def region_blocks(points: List[Tuple[float, float]], feed: float) -> Tuple[PathBlock, ...]:
    """G1 blocks to each corner after the start; the words that change only; F on the first."""
    blocks, (z, c) = [], (rounded(points[0][0]), rounded(points[0][1]))
    for pz, pc in points[1:]:
        nz, nc = rounded(pz), rounded(pc)
        if (nz, nc) == (z, c):
            continue
        blocks.append(PathBlock("G1", z=nz if nz != z else None, c=nc if nc != c else None,
                                f=None if blocks else round(feed, 6)))
        z, c = nz, nc
    if not blocks:
        raise SlotInputError("Base: the slot's path has no length on the developed surface", ("Base",))
    return tuple(blocks)
