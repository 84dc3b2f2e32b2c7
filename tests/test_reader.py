"""The program reader (freecad_groove.engine.reader, the tokenizer): words with
and without spaces, a block's parts, Siemens calls, keywords and
assignments, % lines, and its errors with their line numbers."""

import pytest

from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.reader import parse_block

# ---------------------------------------------------------------- tokenizer


@pytest.mark.parametrize("text", ["G00X80Z65", "G0 X80 Z65", "g00 x80 z65", "G 00 X 80 Z 65", "G0\tX80  Z65 "])
def test_words_with_and_without_spaces(text):
    b = parse_block(text, "sinumerik")
    assert [(w.letter, w.value) for w in b.words] == [("G", 0), ("X", 80), ("Z", 65)]


def test_block_parts():
    b = parse_block("/N40 G1 X-.5 Z+3. F0.2 (feed in) ; rest", "fanuc", 7)
    assert b.line == 7 and b.delete and b.number == 40
    assert [(w.letter, w.text) for w in b.words] == [("G", "1"), ("X", "-.5"), ("Z", "+3."), ("F", "0.2")]
    assert b.comments == ["feed in", " rest"]


def test_siemens_call_keywords_assignments():
    b = parse_block("N40 CYCLE93(35, 60, 30) ; groove", "sinumerik")
    assert b.number == 40 and b.call == "CYCLE93(35, 60, 30)" and b.comments == [" groove"]
    b = parse_block("cycle93 (1,2)", "sinumerik")
    assert b.call == "CYCLE93(1,2)"
    b = parse_block("DIAMOF G1 X=20 CR=5 LIMS=3000", "sinumerik")
    assert b.keywords == ["DIAMOF"]
    assert [(w.letter, w.value) for w in b.words] == [("G", 1), ("X", 20), ("CR", 5), ("LIMS", 3000)]


def test_percent_lines():
    assert parse_block("%", "fanuc").percent
    assert parse_block("%_N_GROOVE_MPF", "sinumerik").percent


@pytest.mark.parametrize(
    "text, dialect, message",
    [
        ("G0 X", "fanuc", "X must be followed by a number"),
        ("G0 X80 @", "sinumerik", "cannot read '@'"),
        ("/2 G0 X1.", "fanuc", "block delete level /2"),
        ("G0 (open", "fanuc", "not closed"),
        ("DIAMON", "fanuc", "a word is one letter and a number"),
        ("G0 N10", "sinumerik", "must be the first word"),
        ("N1.5 G0", "sinumerik", "whole number"),
        ("CYCLE95(1,2)", "sinumerik", "CYCLE95(...) is not supported"),
        ("CYCLE93(1,2", "sinumerik", "not closed"),
        ("X=R1", "sinumerik", "parameters and expressions are not evaluated"),
        ("GOTOF LABEL", "sinumerik", "GOTOF is not supported"),
        ("G0 X٣", "sinumerik", "X must be followed by a number"),  # only ASCII digits
    ],
)
def test_tokenizer_errors(text, dialect, message):
    with pytest.raises(ProgramError) as info:
        parse_block(text, dialect, 3)
    assert info.value.line == 3 and message in str(info.value)


TOO_LONG = "1" * 4301  # one digit more than a number may have (Python's int() limit)


@pytest.mark.parametrize(
    "text, dialect, shown",
    [
        ("N" + TOO_LONG + " G0", "fanuc", "N1111111111..."),
        ("G" + TOO_LONG, "haas", "G1111111111..."),
        ("G0 X-" + TOO_LONG + ".5", "ab9", "X-111111111..."),
        ("M" + TOO_LONG, "sinumerik", "M1111111111..."),
        ("G2 X1 Z1 CR=" + TOO_LONG, "sinumerik", "CR=1111111111..."),
        ("G1 X=0." + "0" * 4300 + "1", "sinumerik", "X0.00000000..."),  # digits after the point count too
    ],
    ids=["N", "G", "X", "M", "CR", "decimals"],
)
def test_a_number_with_too_many_digits_is_named_with_its_line(text, dialect, shown):
    with pytest.raises(ProgramError) as info:
        parse_block(text, dialect, 7)
    assert info.value.line == 7 and str(info.value) == shown + ": the number has more than 4300 digits"


def test_a_number_of_4300_digits_is_read():
    assert parse_block("N" + "1" * 4300 + " G0 X0." + "0" * 4298 + "1", "sinumerik").number == int("1" * 4300)
