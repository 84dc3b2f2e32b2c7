"""Block forms: how a cycle's call is written over a program's blocks.

A cycle declares its form as ``BLOCKS`` (cycle.py); the translator reads the
block that names the cycle (``CycleCall``) and hands it to the form's
``read_call``, which runs the call (``translator.run_cycle``), keeps the block
for a later call, or starts reading the blocks that follow (an
:class:`OpenBlocks` set with ``translator.open_blocks``; the translator then
hands it every block until it closes itself). So a new way of writing a call
is a new form class, not a new branch in the translator.

The forms:

    SingleBlock   the call is one block (CYCLE93, G77, G83, ...): the default
    RetractBlock  a block ``NAME R(e)`` alone sets the peck retract for the
                  next call (Fanuc G75/G74 two-block form; retract_block.py)
    RegionBlocks  a start block, path blocks and a cancel block are one call
                  (GSK G7.1 ... G7.1 C0; region_blocks.py)

Words set for later calls are declared beside the form: a program memory
(``MEMORY``: program_memory.py) and parameter blocks (``PARAMETERS``,
``P151=1``: parameter_blocks.py).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar, List, NamedTuple

if TYPE_CHECKING:  # the reader, the registry and the translator import this module (through cycle.py)
    from .reader import Block, Word
    from .registry import CycleEntry
    from .translate_cycle import CycleTranslation

__all__ = ["BlockForm", "CycleCall", "OpenBlocks", "SingleBlock", "call_label"]


class CycleCall(NamedTuple):
    """A cycle block as read: the cycle's name, its text for the cycle's parse(),
    and its words (G-word cycles; empty for a ``NAME(...)`` call)."""

    name: str
    text: str
    words: List[Word]


def call_label(call: CycleCall) -> str:
    """The call's text on one line, for the comment before its moves."""
    return " / ".join(call.text.split("\n"))


class BlockForm:
    """How a cycle's call is written over blocks (a class: forms keep no state;
    what a program leaves for later calls lives in the translator's ModalState)."""

    TITLE: ClassVar[str] = ""  # what the form is, for the registry table: "one block"

    @classmethod
    def declaration_errors(cls, cycle: type) -> List[str]:
        """What is wrong with ``cycle``'s declaration for this form, [] when nothing.
        RETRACT_BLOCK is RetractBlock's alone."""
        if cycle.RETRACT_BLOCK:
            return ["RETRACT_BLOCK %r is read only by BLOCKS = RetractBlock, not %s"
                    % (cycle.RETRACT_BLOCK, cls.__name__)]
        return []

    @classmethod
    def read_call(cls, translator: CycleTranslation, block: Block, entry: CycleEntry, call: CycleCall) -> None:
        """A block naming the cycle, its mode codes already applied: run the call, keep
        the block for a later call, or open the blocks that follow."""
        raise NotImplementedError("%s.read_call" % cls.__name__)


class SingleBlock(BlockForm):
    """The call is one block: parsed, checked, expanded and written in place."""

    TITLE = "one block"

    @classmethod
    def read_call(cls, translator: CycleTranslation, block: Block, entry: CycleEntry, call: CycleCall) -> None:
        translator.run_cycle(block, entry, call, call_label(call))


class OpenBlocks:
    """The blocks after a call that belong to it, while they are read (a region):
    the translator hands every block but empty ones to ``read`` until the reading
    closes itself (``translator.open_blocks(None)``), and calls ``close`` at the
    program's end when it is still open."""

    def read(self, translator: CycleTranslation, block: Block) -> None:
        """One block of the call."""
        raise NotImplementedError("%s.read" % type(self).__name__)

    def close(self, translator: CycleTranslation) -> None:
        """The program ended while the blocks are open: ProgramError naming what ends them."""
        raise NotImplementedError("%s.close" % type(self).__name__)
