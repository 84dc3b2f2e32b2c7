"""The translator's native cycle calls (``expand --native-cycles``): each cycle
call written as the target's own cycle where engine/native decides it cuts
the same, else its expanded moves after a comment with the reason."""

from typing import List, Optional, Tuple

from .dialects import DIAMETER_REGISTER
from .errors import ProgramError
from .moves import GroovingTool, MachineState, Move
from .native import NativeOutput, NotNative
from .output.native import native_lines
from .settings import Settings
from .tool_table import ToolTable, blade_for
from .translate_base import TranslatorBase

__all__ = ["NativeCycleTranslation"]


class NativeCycleTranslation(TranslatorBase):
    """Writes a cycle call's lines: its expansion, or with ``native`` (a
    NativeOutput; None: every call expanded, the default) the target's own call."""

    native: Optional[NativeOutput] = None

    def _cycle_output(self, model: object, start: MachineState, settings: Settings,
                      moves: List[Move]) -> Tuple[List[str], List[Move]]:
        """The lines of a cycle call and the moves the output makes with them."""
        if self.native is None:
            return self.writer.write(moves, self._prefix), moves
        try:
            call = self.native.call(model, start, settings, moves, self._native_blade(), self._native_register())
        except NotNative as why:
            note = self.writer.line([], notes=["expanded: %s" % why], prefix=self._prefix)
            return [note] + self.writer.write(moves, self._prefix), moves
        return native_lines(self.writer, call, self._prefix), call.all_moves()

    def _native_blade(self) -> Optional[GroovingTool]:
        """The blade of the tool in force (a CYCLE93 written in place of another call cuts with it), or None."""
        tools = self.tools if isinstance(self.tools, ToolTable) else None
        if tools is not None and "tool" in self.state.ambiguous - self._defined:
            return None
        try:
            return blade_for(self.state.tool, tools, self.settings.tool)
        except ProgramError:
            return None

    def _native_register(self) -> Optional[int]:
        """The Milltronics D register in force (None: none programmed, or another dialect)."""
        if self.dialect.tool_words != DIAMETER_REGISTER or "tool" in self.state.ambiguous - self._defined:
            return None
        return self.state.tool
