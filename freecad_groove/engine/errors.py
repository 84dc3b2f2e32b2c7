"""The one error type every cycle raises for bad input.

A machinist must be able to act on the message alone, so it always names the
cycle, the parameter, the value that was given and the rule it broke, plus the
control's own alarm number where the manual has one.
"""


def format_value(value):
    """Write a number the way a G-code programmer would read it back."""
    if isinstance(value, float):
        text = ("%.6f" % value).rstrip("0").rstrip(".")
        return text if text not in ("-0", "") else "0"
    return str(value)


class CycleError(ValueError):
    """Invalid cycle parameters or an unreadable cycle call.

    Attributes: ``cycle`` (e.g. "CYCLE93"), ``parameter`` (the control's own
    name, e.g. "WIDG"), ``value``, ``rule`` (a sentence fragment), ``alarm``
    (the control's alarm number or None).
    """

    def __init__(self, parameter, value, rule, alarm=None, cycle=None):
        self.parameter = parameter
        self.value = value
        self.rule = rule
        self.alarm = alarm
        self.cycle = cycle
        super().__init__(self.message)

    @property
    def message(self):
        head = self.cycle + " " if self.cycle else ""
        if self.value is None:
            text = "%s%s: %s" % (head, self.parameter, self.rule)
        else:
            text = "%s%s=%s: %s" % (head, self.parameter, format_value(self.value), self.rule)
        if self.alarm is not None:
            text += " (alarm %s)" % self.alarm
        return text

    def with_cycle(self, cycle):
        """The same error, tagged with the cycle name (for errors raised by shared helpers)."""
        if self.cycle is None:
            self.cycle = cycle
            self.args = (self.message,)
        return self


class ProgramError(ValueError):
    """A line of an input program the reader cannot understand or translate."""

    def __init__(self, message, line=None):
        self.line = line
        super().__init__(message)
