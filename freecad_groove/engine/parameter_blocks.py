"""Parameter blocks: ``P151=1`` alone in a block sets a P parameter for the calls
that follow (Milltronics G33/G34 read P150-P155 so).

A cycle declares the parameters it reads as ``PARAMETERS`` and the program
memory they are kept in as ``MEMORY`` (program_memory.py); its
``with_earlier`` takes them from there. The reader splits the assignments off
(``Block.parameters``) where the dialect has them
(``Dialect.parameter_assignments``); the translator hands such a block
to :func:`read_parameter_block`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .numbers import MAX_WORD
from .program_memory import remember

if TYPE_CHECKING:
    from .reader import Block
    from .translate_cycle import CycleTranslation

__all__ = ["read_parameter_block"]


def read_parameter_block(translator: CycleTranslation, block: Block) -> None:
    """``P151=1``: a P parameter of the control's cycles (their PARAMETERS), kept in
    the program memory of each cycle that reads it (its MEMORY) for the calls that follow."""
    name, text = block.parameters[0]
    if block.words or block.keywords or block.call or len(block.parameters) > 1:
        translator._fail("%s=%s: a parameter assignment stands alone in its block" % (name, text))
    readers = [entry.cycle_class for entry in translator.dialect.cycles() if entry.cycle_class.PARAMETERS]
    known = tuple(dict.fromkeys(parameter for cycle in readers for parameter in cycle.PARAMETERS))
    key = "P%d" % int(name[1:]) if name[1:].isdigit() else name
    if key not in known:
        translator._fail("%s=%s: not a parameter of the %s cycles (%s)" % (name, text, translator.dialect.maker,
                                                                          ", ".join(known) or "none"))
    value = float(text)
    if not abs(value) < MAX_WORD:
        translator._fail("%s=%s: must be less than %g in magnitude" % (name, text, MAX_WORD))
    readers = [cycle for cycle in readers if key in cycle.PARAMETERS]
    translator._not_ambiguous("cycle_memory", why="the parameters %s calls read" % readers[0].NAME)
    for memory in dict.fromkeys(cycle.MEMORY for cycle in readers):
        remember(translator, memory, dict(translator.state.cycle_memory.get(memory, {}), **{key: value}))
    translator._emit_line(block, [], "%s=%s: for the %s that follow" % (
        key, text, "/".join(cycle.NAME for cycle in readers)))
