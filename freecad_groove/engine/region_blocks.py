"""The region form: a start block, path blocks and a cancel block are one call
(GSK ``G7.1 C(c)`` ... ``G7.1 C0``).

The cycle declares ``BLOCKS = RegionBlocks`` and gives the region hooks
(``Cycle.region_ends``, ``Cycle.check_region_block``). The start block opens
the region; each block after it is checked as it is read (an error names its
own line) and kept; the cancel block closes it and the whole region runs as
one call, its errors and its comment on the start block's line. A program
that ends inside a region is refused.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, List, Optional

from .block_forms import BlockForm, CycleCall, OpenBlocks
from .cycle import Cycle, gives_hook
from .errors import CycleError, ProgramError

if TYPE_CHECKING:
    from .reader import Block
    from .registry import CycleEntry
    from .translate_cycle import CycleTranslation

__all__ = ["OpenRegion", "RegionBlocks"]

REGION_HOOKS = ("region_ends", "check_region_block")


class RegionBlocks(BlockForm):
    """The blocks from the call up to its cancel block are one call."""

    TITLE = "a region up to a cancel block"

    @classmethod
    def declaration_errors(cls, cycle: type) -> List[str]:
        return super().declaration_errors(cycle) + [
            "a region cycle gives %s" % hook for hook in REGION_HOOKS if not gives_hook(cycle, hook)]

    @classmethod
    def read_call(cls, translator: CycleTranslation, block: Block, entry: CycleEntry, call: CycleCall) -> None:
        if block.delete:
            translator._fail("%s on a block-delete '/' line: a region is not translated there" % call.name)
        try:
            if entry.cycle_class.region_ends(call.text):
                translator._fail("%s cancels a region that was not started" % call.text)
        except CycleError as exc:
            translator._fail(exc.message)
        translator.open_blocks(OpenRegion(block, entry, call))


class OpenRegion(OpenBlocks):
    """A region while it is read: its start block, entry and call, the path blocks'
    texts, and what the last path block's check returned for the next one."""

    def __init__(self, block: Block, entry: CycleEntry, call: CycleCall) -> None:
        self.block = block
        self.entry = entry
        self.call = call
        self.texts: List[str] = []
        self.context: Optional[object] = None

    @property
    def cycle(self) -> type[Cycle]:
        return self.entry.cycle_class

    def read(self, translator: CycleTranslation, block: Block) -> None:
        """A block inside the region: a path block, checked now, or the block that ends it."""
        if block.delete:
            translator._fail("a block-delete '/' line inside the %s region is not translated" % self.call.name)
        if block.keywords or block.call:  # (comments on a path block are not written)
            translator._fail("%s inside the %s region: only its path blocks may be there"
                             % ((block.keywords or [block.call])[0], self.call.name))
        text = " ".join(word.letter + word.text for word in block.words)
        try:
            if self.cycle.region_ends(text):
                self._finish(translator, text)
                return
            self.context = self.cycle.check_region_block(text, self.context)
        except CycleError as exc:
            translator._fail(exc.message)
        self.texts.append(text)

    def _finish(self, translator: CycleTranslation, cancel: str) -> None:
        """The cancel block read: the whole region is one call, its errors on its first line."""
        translator.open_blocks(None)
        line, translator._line = translator._line, self.block.line
        translator._not_ambiguous("c", why=self.call.name)
        text = "\n".join([self.call.text] + self.texts + [cancel])
        label = "%s ... %s, %d path blocks" % (self.call.text, cancel, len(self.texts))
        translator.run_cycle(self.block, self.entry, self.call._replace(text=text), label)
        translator._line = line
        translator.state.motion = None  # the motion after the region is not the one before it
        translator._defined.add("motion")

    def close(self, translator: CycleTranslation) -> None:
        """At the end of the program: a region without its cancel block is refused."""
        raise ProgramError("the %s region is not closed: it ends with %s C0" % (self.call.text, self.call.name),
                           self.block.line)
