"""The words of everything a program says but its moves: modes, the frame
(header, footer), blocks and comments, dwell, tools, the spindle and its
constant surface speed, each the target's way (a mixin of the Writer)."""

from typing import List, Optional, Sequence

from ..errors import ProgramError
from ..numbers import MAX_DWELL_SECONDS, MAX_WORD, format_decimal
from .syntax import CSS_D_WORD, CSS_G50_ALONE, CSS_LIMS, SEMICOLON, TOOL_EDGE, TOOL_M6, Target
from .words import MAX_COMMENT, MAX_LINE, comment_text, format_number

__all__ = ["MachineWords"]

DWELL_DIGITS = 3  # decimals of a dwell in seconds


class MachineWords:
    """Words and lines other than moves, for the Writer (which holds the state they read)."""

    target: Target
    metric: bool
    x_diameter: bool
    feed_per_rev: Optional[bool]
    f_text: Optional[str]

    def m_code(self, number: int) -> str:
        """``M3`` or ``M03``: an M code the target's way."""
        return self.target.m_code % number

    def units_code(self, metric: Optional[bool] = None) -> str:
        """The code of metric or inch lengths (default: the writer's units)."""
        return self.target.units_codes[0 if (self.metric if metric is None else metric) else 1]

    def feed_mode_code(self, feed_per_rev: bool) -> str:
        """The code of feed per minute or per revolution."""
        return self.target.feed_mode_codes[1 if feed_per_rev else 0]

    def set_feed_mode(self, feed_per_rev: bool) -> str:
        """The feed-mode code a block writes; the F in force is forgotten, since
        LinuxCNC sets F to 0 on every G93/G94/G95, even the active one (a block
        that keeps feeding writes F again)."""
        self.feed_per_rev = bool(feed_per_rev)
        self.f_text = None
        return self.feed_mode_code(feed_per_rev)

    def x_mode_code(self, diameter: Optional[bool] = None) -> str:
        """The code of X as a diameter or a radius ("" when it is a machine parameter)."""
        return self.target.x_mode_codes[0 if (self.x_diameter if diameter is None else diameter) else 1]

    # -- lines ------------------------------------------------------------------

    def comment(self, text: str, limit: int = MAX_COMMENT) -> str:
        """A comment line (or a block's trailing comment) the target's way."""
        body = comment_text(text, limit)
        return "; " + body if self.target.comments == SEMICOLON else "(" + body + ")"

    def dwell(self, seconds: float) -> str:
        """The dwell block for ``seconds``."""
        target = self.target
        if target.dwell_refusal:
            raise ProgramError(target.dwell_refusal)
        if not 0 <= seconds <= MAX_DWELL_SECONDS:
            raise ProgramError("dwell of %r s cannot be written (0 to %g s)" % (seconds, MAX_DWELL_SECONDS))
        if target.dwell_milliseconds:
            return "%s %s%d" % (target.dwell_code, target.dwell_word, int(round(seconds * 1000.0)))
        return "%s %s%s" % (target.dwell_code, target.dwell_word, format_number(seconds, DWELL_DIGITS))

    def line(self, words: Sequence[str], number: Optional[int] = None, notes: Sequence[str] = (),
             prefix: str = "") -> str:
        """One block: ``N..``, the words and a comment holding ``notes`` (joined
        with `` ; ``), the comment cut to keep the block within MAX_LINE;
        ProgramError when the block is longer even so, or N beyond the target's."""
        limit = self.target.max_block_number
        if number is not None and limit is not None and number > limit:
            raise ProgramError("N%d: a %s block number has at most %d digits" % (number, self.target.name,
                                                                                len(str(limit))))
        parts = ([] if number is None else ["N%d" % number]) + list(words)
        text = " ".join(parts)
        if notes:
            room = MAX_LINE - len(prefix) - len(text) - 3
            text = (text + " " if text else "") + self.comment(" ; ".join(notes), room)
        if len(prefix) + len(text) > MAX_LINE:
            raise ProgramError("the translated block is longer than %d characters (LinuxCNC's limit)" % MAX_LINE)
        return prefix + text

    def header(self, title: Optional[str] = None, program_number: Optional[int] = None,
               notes: Sequence[str] = ()) -> List[str]:
        """The lines that open a program: the frame (``%``, the O number), the
        title and ``notes`` as comments, the target's setup lines (units,
        feed mode when known, X mode)."""
        target = self.target
        out = ["%"] if target.percent_start else []
        titles = [title] if title else []
        if target.program_number and program_number is not None:
            number = target.program_number % int(program_number)
            if titles and target.title_on_number_line:
                number += " " + self.comment(titles.pop())
            out.append(number)
        out += [self.comment(text) for text in titles + list(notes)]
        modes = {"units": self.units_code(),
                 "feed_mode": "" if self.feed_per_rev is None else self.feed_mode_code(self.feed_per_rev),
                 "x_mode": self.x_mode_code()}
        out += [" ".join(template.format(**modes).split()) for template in target.setup]
        return out

    def footer(self) -> List[str]:
        """The lines that end a program."""
        return [self.target.end_code] + (["%"] if self.target.percent_end else [])

    # -- machine functions ---------------------------------------------------------

    def tool_change(self, tool: Optional[int], offset: Optional[int] = None, own: bool = True,
                    in_place: Optional[int] = None) -> List[str]:
        """The words of a tool change to ``tool`` (None: the tool in place,
        ``in_place`` when known, only its offset changes) with length offset
        ``offset`` (``own``: the tool's own entry; 0: cancelled; None: not said)."""
        target = self.target
        if target.tool_form == TOOL_EDGE:
            if offset and not own:
                raise ProgramError("T%s with the offset of tool %d: a Siemens D number is a cutting edge of the "
                                   "tool itself" % ("" if tool is None else tool, offset))
            edge = "D%d" % (0 if offset == 0 else 1)
            return [edge] if tool is None else self._checked_tool(tool, "T%d" % tool) + [edge]
        if target.tool_form == TOOL_M6:
            words = [] if tool is None else self._checked_tool(tool, target.tool_number % tool) + [self.m_code(6)]
            if offset is not None and target.tool_length_offset:
                words += ["G49"] if offset == 0 else ["G43"] if own else ["G43", "H%d" % offset]
            return words
        tool = in_place if tool is None else tool
        if tool is None:
            raise ProgramError("D%s: no tool selected before (the %s tool word holds the tool and its offset)"
                               % (offset, target.maker))
        offset = tool if offset is None or (own and offset) else offset  # the tool's own register: T0505
        if tool > 99 or offset > 99:
            raise ProgramError("T%d offset %d does not fit Fanuc's T<2 digits><2 digits>" % (tool, offset))
        return ["T%02d%02d" % (tool, offset)]

    def length_offset(self, register: Optional[int]) -> List[str]:
        """The words of a tool length offset: ``G43 H<register>``, ``G49`` for None."""
        return ["G49"] if register is None else ["G43", "H%d" % register]

    def _checked_tool(self, tool: int, word: str) -> List[str]:
        if not 0 <= tool <= self.target.max_tool:
            raise ProgramError("tool number %d cannot be written for %s (0 to %d)"
                               % (tool, self.target.name, self.target.max_tool))
        return [word]

    def speed_text(self, value: float) -> str:
        """The text of an S word (rpm or surface speed); ProgramError where the
        target takes whole numbers only, or where it would read as 0."""
        if not 0 <= value < MAX_WORD:
            raise ProgramError("spindle speed %r cannot be written" % (value,))
        if value == int(value):
            return "%d" % value
        if self.target.whole_speed:
            raise ProgramError("S%s: %s S words are whole numbers (rpm, or the surface speed)"
                               % (format_decimal(value, 6, False), self.target.maker))
        text = format_number(value, 4)
        if float(text) == 0:
            raise ProgramError("S%s rounds to 0 in the output (4 decimals): the spindle would not turn"
                               % format_decimal(value, 10, False))
        return text

    def speed_word(self, value: float) -> str:
        """``S..``: a spindle speed (rpm, or the surface speed under G96)."""
        return "S" + self.speed_text(value)

    def rpm_words(self, speed: Optional[float]) -> List[str]:
        """G97 (spindle speed in rpm, constant surface speed off) with the speed when given."""
        return ["G97"] + ([] if speed is None else [self.speed_word(speed)])

    def limit_words(self, limit: float) -> Optional[tuple]:
        """(lines standing alone before, words) that set the spindle limit
        ``limit`` on its own; None where the limit is a word of G96 (LinuxCNC's D)."""
        target = self.target
        text = self.speed_text(limit)
        if target.css_form == CSS_G50_ALONE:
            return ["G50 S" + text], []
        if target.css_form == CSS_LIMS:
            return [], ["LIMS=" + text]
        return ([], []) if target.css_refusal else None

    def surface_speed(self, speed: float, limit: Optional[float], limit_changed: bool = True) -> tuple:
        """(lines standing alone before, words) of constant surface speed
        ``speed`` with the spindle limited to ``limit`` rpm (None: not known):
        the limit with G96 where the target needs it there (LinuxCNC's D),
        else where it changed (``limit_changed``)."""
        target = self.target
        if target.css_refusal:
            raise ProgramError(target.css_refusal)
        s_word = "S" + self.speed_text(speed)
        limit_text = None if limit is None else self.speed_text(limit)
        if target.css_form == CSS_D_WORD:
            return [], ["G96"] + ([] if limit_text is None else ["D" + limit_text]) + [s_word]
        said = limit_text is not None and limit_changed
        if target.css_form == CSS_G50_ALONE:
            return (["G50 S" + limit_text] if said else []), ["G96", s_word]
        return [], ["G96", s_word] + (["LIMS=" + limit_text] if said else [])
