"""A program memory: the words a call omits come from the previous call.

A cycle declares ``MEMORY = "key"`` (9/Series grinder G83: its words;
Milltronics G31-G34: the P parameters and the clearance plane R) and gives the
memory hooks ``with_earlier(memory, state)`` (the call with the omitted words
filled in) and ``remembered(state)`` (what the next call takes). The
translator keeps each memory in ``ModalState.cycle_memory[key]``, replaced and
never changed in place, so that a block-delete line that changes it makes it
ambiguous; parameter blocks (parameter_blocks.py) write into it too.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .cycle import Cycle, Memory
from .moves import MachineState

if TYPE_CHECKING:
    from .translate_cycle import CycleTranslation

__all__ = ["remember", "with_memory"]


def with_memory(translator: CycleTranslation, model: Cycle, start: MachineState) -> Cycle:
    """The call with the words it omits from the previous call of its memory; what it
    leaves for the next one is kept."""
    translator._not_ambiguous("cycle_memory", why=model.MEMORY_WHAT % model.NAME)
    model = model.with_earlier(translator.state.cycle_memory.get(model.MEMORY, {}), start)
    remember(translator, model.MEMORY, model.remembered(start))
    return model


def remember(translator: CycleTranslation, key: str, memory: Memory) -> None:
    """Memory ``key`` is now ``memory`` (the whole dict replaced: see the module notes)."""
    translator.state.cycle_memory = dict(translator.state.cycle_memory, **{key: memory})
    translator._defined.add("cycle_memory")
