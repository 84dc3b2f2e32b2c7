"""The posts' one error: :class:`PostError`, naming the op and the op property at fault."""

from typing import Mapping, Optional

from ...engine import CycleError
from ...ops.groove.properties import describe_cycle93_parameter


class PostError(ValueError):
    """A post cannot write the program. ``op``: the Label of the object at
    fault (None for option errors); ``parameter``: the op property (and cycle
    parameter) at fault, when known."""

    def __init__(self, message: str, op: Optional[str] = None, parameter: Optional[str] = None) -> None:
        self.op = op
        self.parameter = parameter
        text = message
        if parameter:
            text = "%s: %s" % (parameter, text)
        if op:
            text = "%s: %s" % (op, text)
        super().__init__(text)


def cycle_post_error(label: str, error: CycleError, properties: Optional[Mapping[str, str]] = None) -> PostError:
    """A PostError for a CycleError of op ``label``, naming the op property the
    cycle word came from: ``properties`` maps the words of a pecking cycle;
    without it the word is a CYCLE93 parameter (groove_properties' table)."""
    if properties is None:
        parameter = describe_cycle93_parameter(error.parameter)
    else:
        parameter = properties.get(error.parameter)
    return PostError(error.message, op=label, parameter=parameter or None)
