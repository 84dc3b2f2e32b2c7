"""The retract block form: a block ``NAME R(e)`` alone sets the peck retract e
of the next call (Fanuc two-block G75/G74, as the GSK 980TDi writes them too).

The cycle declares ``BLOCKS = RetractBlock`` and ``RETRACT_BLOCK = "R"``. A
block holding the letter alone (none of the cycle's other words) is the first
block: e is kept in ``ModalState.retract_e`` (ambiguous after a block-delete
line that sets it) and written as a comment; the next call of any cycle of the
form reads it, as the first line of its text (``G75 R0.5`` then the call).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, List, Sequence

from .block_forms import BlockForm, CycleCall, SingleBlock

if TYPE_CHECKING:
    from .reader import Block, Word
    from .registry import CycleEntry
    from .translate_cycle import CycleTranslation

__all__ = ["RetractBlock"]


class RetractBlock(BlockForm):
    """``NAME R(e)`` before the call sets e for the next call; the call itself is one block."""

    TITLE = "a retract block NAME R(e) before the call"

    @classmethod
    def declaration_errors(cls, cycle: type) -> List[str]:
        words = [word for word, _help in cycle.WORD_HELP]
        if cycle.RETRACT_BLOCK not in words:
            return ["RETRACT_BLOCK %r must be one of its words (%s)" % (cycle.RETRACT_BLOCK, ", ".join(words))]
        return []

    @classmethod
    def read_call(cls, translator: CycleTranslation, block: Block, entry: CycleEntry, call: CycleCall) -> None:
        if cls._is_retract_block(entry, call.words):
            cls._retract_block(translator, block, entry, call.words)
            return
        SingleBlock.read_call(translator, block, entry, cls._with_retract_block(translator, entry, call))

    @staticmethod
    def _is_retract_block(entry: CycleEntry, words: Sequence[Word]) -> bool:
        """True when the block holds none of the cycle's words but the retract block's."""
        cycle_words = {word.name for word in entry.words} - {entry.retract_block}
        return not {word.letter for word in words} & cycle_words

    @staticmethod
    def _retract_block(translator: CycleTranslation, block: Block, entry: CycleEntry, words: Sequence[Word]) -> None:
        """``G75 R(e)`` alone: it only stores e for the next cycle of its kind."""
        letter = entry.retract_block
        if len(words) != 1 or words[0].letter != letter:
            translator._fail("%s: the first block is %s %s(e) (the peck retract) alone"
                             % (entry.name, entry.name, letter))
        translator._length(words[0])
        translator.state.retract_e = words[0]
        translator._defined.add("retract_e")
        kinds = "/".join(other.name for other in translator.dialect.cycles() if other.retract_block)
        note = "%s %s%s: peck retract e for the next %s" % (entry.name, letter, words[0].text, kinds)
        translator._emit_line(block, [], note)

    @staticmethod
    def _with_retract_block(translator: CycleTranslation, entry: CycleEntry, call: CycleCall) -> CycleCall:
        """The call with the retract block read before it, when there was one."""
        retract = translator.state.retract_e
        if retract is None:
            return call
        translator._not_ambiguous("retract_e", why="%s %s(e)" % (entry.name, entry.retract_block))
        text = "%s %s%s\n%s" % (entry.name, retract.letter, retract.text, call.text)
        return call._replace(text=text)
