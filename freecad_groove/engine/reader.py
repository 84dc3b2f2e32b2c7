"""Read the lines of a lathe program into words.

    parse_block(text, dialect, line) -> Block

A *dialect* is the control a program is read as ("sinumerik", "ab9",
"fanuc", "haas", ...); what the tokenizer needs of it (Siemens names: the
keywords, ``NAME=`` assignments, the ``NAME(...)`` calls of the registered
cycles) is in its Dialect (dialects.py). What the words mean is the
translator's business (translator.py).
"""

import re
from typing import List, NamedTuple, NoReturn, Optional, Set, Tuple

from .dialects import Dialect, dialect_named
from .errors import ProgramError
from .numbers import digits_message, too_many_digits

__all__ = ["Block", "Word", "parse_block"]

# ---------------------------------------------------------------- words and blocks


class Word(NamedTuple):
    """One word of a block: ``X80.`` is Word("X", "80.", 80.0)."""

    letter: str  # upper case; "CR", "LIMS" for Siemens assignments
    text: str  # the number as written
    value: float


class Block:
    """One line of an input program, read into words."""

    __slots__ = ("line", "text", "delete", "number", "words", "keywords", "call", "comments", "percent", "parameters")

    def __init__(self, line: int, text: str) -> None:
        self.line = line
        self.text = text
        self.delete = False
        self.number: Optional[int] = None  # N value
        self.words: List[Word] = []  # in order, without N
        self.keywords: List[str] = []  # Siemens DIAMON, DIAMOF, DIAM90
        self.call: Optional[str] = None  # Siemens "CYCLE93(...)" as written, name upper case
        self.comments: List[str] = []
        self.percent = False
        self.parameters: List[Tuple[str, str]] = []  # Milltronics "P151=1": ("P151", "1")

    def get(self, letter: str) -> Optional[Word]:
        """The first word with ``letter``, or None."""
        for word in self.words:
            if word.letter == letter:
                return word
        return None

    def all(self, letter: str) -> List[Word]:
        """Every word with ``letter``, in order."""
        return [word for word in self.words if word.letter == letter]

    def letters(self) -> Set[str]:
        """The letters of the block's words."""
        return {word.letter for word in self.words}

    def is_empty(self) -> bool:
        """True when the block holds nothing but comments."""
        return not (self.words or self.keywords or self.call or self.parameters or self.number is not None)

    def __repr__(self) -> str:
        return "Block(%d, %r)" % (self.line, self.text)


# ---------------------------------------------------------------- tokenizer

_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)")
_SPACE = re.compile(r"[ \t]*")
_LETTERS = re.compile(r"[A-Za-z]+")
_IDENT_TAIL = re.compile(r"[A-Za-z0-9_]*")
_NOT_EVALUATED = "must be followed by a number (parameters and expressions are not evaluated)"


def parse_block(text: str, dialect: str, line: int = 1) -> Block:
    """Read one line of a ``dialect`` program into a Block (raises ProgramError)."""
    return _BlockReader(text, dialect_named(dialect), line).read()


class _BlockReader:
    """A cursor over one line while parse_block reads it."""

    def __init__(self, text: str, dialect: Dialect, line: int) -> None:
        self.text = text
        self.end = len(text)
        self.dialect = dialect
        self.block = Block(line, text)
        self.pos = 0
        self.first_word = True

    def fail(self, message: str) -> NoReturn:
        raise ProgramError(message, self.block.line)

    def skip_space(self, pos: int) -> int:
        return _SPACE.match(self.text, pos).end()

    def char(self, pos: int) -> str:
        """The character at ``pos``; "" past the end."""
        return self.text[pos] if pos < self.end else ""

    def read(self) -> Block:
        self.pos = self.skip_space(0)
        if self.char(self.pos) == "%":
            self.block.percent = True
            return self.block
        if self.char(self.pos) == "/":
            self.block.delete = True
            self.pos += 1
            if self.char(self.pos).isdigit():
                self.fail("block delete level /%s is not supported (only /)" % self.text[self.pos])
        while True:
            self.pos = self.skip_space(self.pos)
            if self.pos >= self.end or not self.read_item():
                return self.block

    def read_item(self) -> bool:
        """Read a comment or a word at ``pos``; False when the rest of the line is a comment."""
        char = self.text[self.pos]
        if char == "(":
            close = self.text.find(")", self.pos + 1)
            if close < 0:
                self.fail("comment opened with '(' is not closed")
            self.block.comments.append(self.text[self.pos + 1 : close])
            self.pos = close + 1
            return True
        if char == ";":
            self.block.comments.append(self.text[self.pos + 1 :])
            return False
        letters = _LETTERS.match(self.text, self.pos)
        if not letters:
            self.fail("cannot read %r" % self.text[self.pos:self.pos + 12])
        if len(letters.group()) > 1:
            self.read_name(letters)
        else:
            self.read_letter_word(letters.group().upper(), letters.end())
        self.first_word = False
        return True

    def read_number(self, name: str, message: str) -> str:
        """The number at ``pos`` of the word ``name`` (as written: ``X``, ``CR=``)."""
        number = _NUMBER.match(self.text, self.pos)
        if not number:
            self.fail(message)
        self.pos = number.end()
        if too_many_digits(number.group()):
            self.fail(digits_message(name, number.group()))
        return number.group()

    def read_letter_word(self, letter: str, after: int) -> None:
        """``X80``, ``X 80`` (Siemens also ``X=80``) and the block number ``N10``."""
        self.pos = self.skip_space(after)
        if self.dialect.long_names and self.char(self.pos) == "=":
            self.pos = self.skip_space(self.pos + 1)
        number = self.read_number(letter, "%s %s" % (letter, _NOT_EVALUATED))
        if letter == "P" and self.dialect.parameter_assignments and self.char(self.skip_space(self.pos)) == "=":
            self.pos = self.skip_space(self.skip_space(self.pos) + 1)
            name = "P" + number
            self.block.parameters.append((name, self.read_number(name + "=", "%s= %s" % (name, _NOT_EVALUATED))))
            return
        if letter != "N":
            self.block.words.append(Word(letter, number, float(number)))
            return
        if not self.first_word:
            self.fail("N%s: the block number must be the first word" % number)
        if not number.isdigit():
            self.fail("N%s: the block number must be a whole number" % number)
        self.block.number = int(number)

    def read_name(self, letters: "re.Match[str]") -> None:
        """A Siemens name: a keyword, a cycle call or an assignment."""
        if not self.dialect.long_names:
            self.fail("cannot read %r: a word is one letter and a number" % self.text[self.pos:self.pos + 12])
        tail = _IDENT_TAIL.match(self.text, letters.end())
        name = (letters.group() + tail.group()).upper()
        self.pos = tail.end()
        if name in self.dialect.keywords:
            self.block.keywords.append(name)
            return
        after = self.skip_space(self.pos)
        if self.char(after) == "(":
            self.read_call(name, after)
        elif name in self.dialect.assignments:
            if self.char(after) != "=":
                self.fail("%s must be followed by '=' and a number" % name)
            self.pos = self.skip_space(after + 1)
            number = self.read_number(name + "=", "%s= %s" % (name, _NOT_EVALUATED))
            self.block.words.append(Word(name, number, float(number)))
        else:
            self.fail("%s is not supported" % name)

    def read_call(self, name: str, opening: int) -> None:
        """``NAME(...)`` from the opening parenthesis at ``opening``."""
        names = self.dialect.call_names()
        if name not in names:
            self.fail("%s(...) is not supported (only %s)" % (name, ", ".join(names)))
        if self.block.call is not None:
            self.fail("two cycle calls in one block")
        depth = 0
        close = opening
        while close < self.end:
            depth += {"(": 1, ")": -1}.get(self.text[close], 0)
            if depth == 0:
                break
            close += 1
        if close >= self.end:
            self.fail("%s( is not closed with ')'" % name)
        self.block.call = name + self.text[opening : close + 1]
        self.pos = close + 1
