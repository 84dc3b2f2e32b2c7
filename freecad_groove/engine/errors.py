"""The error types of the engine.

A machinist must be able to act on the message alone, so a CycleError always
names the cycle, the parameter, the value that was given (exactly, never
rounded into another value) and the rule it broke, plus the control's own
alarm number where the manual has one.
"""

from typing import Optional

from .numbers import format_given


class CycleError(ValueError):
    """Invalid cycle parameters or an unreadable cycle call.

    Attributes: ``cycle`` (e.g. "CYCLE93"), ``parameter`` (the control's own
    name, e.g. "WIDG"), ``value``, ``rule`` (a sentence fragment), ``alarm``
    (the control's alarm number or None).
    """

    def __init__(
        self,
        parameter: str,
        value: object,
        rule: str,
        alarm: Optional[int] = None,
        cycle: Optional[str] = None,
    ) -> None:
        self.parameter = parameter
        self.value = value
        self.rule = rule
        self.alarm = alarm
        self.cycle = cycle
        super().__init__(self.message)

    @property
    def message(self) -> str:
        """The one-line message: ``CYCLE PARAMETER=VALUE: rule (alarm N)``."""
        head = self.cycle + " " if self.cycle else ""
        if self.value is None:
            text = "%s%s: %s" % (head, self.parameter, self.rule)
        else:
            text = "%s%s=%s: %s" % (head, self.parameter, format_given(self.value), self.rule)
        if self.alarm is not None:
            text += " (alarm %s)" % self.alarm
        return text


class ProgramError(ValueError):
    """A line of an input program the reader cannot understand or translate."""

    def __init__(self, message: str, line: Optional[int] = None) -> None:
        self.line = line
        super().__init__(message)
