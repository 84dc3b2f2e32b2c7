"""The cycle registry: what the cycles declare, and that a new cycle needs
nothing but its module and its registration.

The second half registers a toy cycle for the tests' duration (the registry's
tables are swapped for copies, so no other test sees it) and checks that the
program reader, the translator and the command line take it up."""

import io
from contextlib import redirect_stdout
from dataclasses import dataclass, fields
from typing import ClassVar, Optional

import pytest

from freecad_groove import cli
from freecad_groove.engine import FEED, RAPID, CycleError, Move, ProgramError, registry
from freecad_groove.engine.cycle import Cycle
from freecad_groove.engine.cycles import cycle93
from freecad_groove.engine.cycles.ab_g77 import G77
from freecad_groove.engine.cycles.cycle_words import read_block, word_value
from freecad_groove.engine.dialects import DIALECTS
from freecad_groove.engine.translator import translate_program


def test_every_dialect_calls_its_grooving_cycles():
    calls = {dialect: sorted(e.name for e in registry.cycles_of(dialect)) for dialect in DIALECTS}
    assert calls == {
        "sinumerik": ["CYCLE93"],
        "ab9": ["G76", "G77"],
        "ab9grind": ["G83", "G83.1"],
        "fanuc": ["G74", "G75"],
        "haas": ["G74", "G75"],
        "gsk": ["G7.1", "G74", "G75"],
        "milltronics": ["G31", "G32", "G33", "G34"],
    }


def test_a_cycle_is_found_by_dialect_and_code_and_by_command_line_name():
    assert registry.cycle_for("fanuc", "g75").__name__ == "FanucG75"
    assert registry.cycle_for("haas", "G75").__name__ == "HaasG75"
    assert registry.entry("g77").key == "ab-g77"
    with pytest.raises(ValueError, match="G77 is not a cycle of fanuc programs"):
        registry.cycle_for("fanuc", "G77")
    with pytest.raises(ValueError, match="unknown cycle 'g99'"):
        registry.entry("g99")


@pytest.mark.parametrize("entry", registry.cycles(), ids=lambda e: e.key)
def test_the_word_help_covers_exactly_the_words_the_cycle_writes(entry):
    cls = entry.cycle_class
    written = cycle93.PARAMS if entry.form == registry.CALL else cls.WORDS
    assert [word.name for word in entry.words] == list(written)
    assert all(word.help for word in entry.words)
    assert {word.name for word in entry.words if word.counted} == set(cls.COUNTED)


def test_a_cycle_registered_twice_under_another_class_is_refused(monkeypatch):
    monkeypatch.setattr(registry, "_ENTRIES", list(registry.cycles()))
    monkeypatch.setattr(registry, "_BY_KEY", dict(registry._BY_KEY))
    clash = type("Clash", (G77,), {"KEY": "clash", "ALIASES": (), "TITLE": "t"})  # another class called G77
    with pytest.raises(ValueError, match="G77 is registered twice for ab9"):
        registry.register(clash)


# ---------------------------------------------------------------- a new cycle, nothing else


@dataclass(frozen=True)
class ToyPlunge(Cycle):
    """``G79 X__ F__``: one straight plunge to X (a diameter) at F and a rapid
    back to the start: a cycle no control has, to show the seams."""

    NAME: ClassVar[str] = "G79"
    KEY: ClassVar[str] = "toy-g79"
    ALIASES: ClassVar[tuple] = ("g79",)
    DIALECTS: ClassVar[tuple] = ("ab9",)
    TITLE: ClassVar[str] = "a toy plunge"
    FORM: ClassVar[str] = registry.G_WORD
    WORD_HELP: ClassVar[tuple] = (("X", "plunge bottom X (diameter)"), ("F", "feed of the plunge"))

    X: Optional[float] = None
    F: Optional[float] = None

    @classmethod
    def parse(cls, text: str) -> "ToyPlunge":
        return cls(**read_block(text, cls.NAME, ("X", "F")))

    def emit(self) -> str:
        return " ".join([self.NAME] + [f.name + word_value(getattr(self, f.name)) for f in fields(self)
                                       if getattr(self, f.name) is not None])

    def validate(self, settings: object = None) -> "ToyPlunge":
        if self.X is None:
            raise CycleError("X", None, "must be programmed", cycle=self.NAME)
        return self

    def expand(self, state: object, settings: object = None) -> list:
        return [Move(FEED, self.X / 2.0, state.z, self.F), Move(RAPID, state.x, state.z)]


PROGRAM = "G21 G90 G95\nS500 M3\nG0 X50. Z-4.\nG79 X40. F0.1\nM30\n"


@pytest.fixture
def toy_registered(monkeypatch):
    monkeypatch.setattr(registry, "_ENTRIES", list(registry.cycles()))
    monkeypatch.setattr(registry, "_BY_KEY", dict(registry._BY_KEY))
    registry.register(ToyPlunge)


def test_without_its_registration_the_reader_refuses_the_toy_code():
    with pytest.raises(ProgramError, match="G79 is not supported"):
        translate_program(PROGRAM, "ab9")


def test_a_registered_cycle_is_read_and_expanded_in_its_dialects_programs(toy_registered):
    lines = translate_program(PROGRAM, "ab9").splitlines()
    # worked by hand: the comment naming the call, the plunge to X40 at F0.1, the rapid back to X50
    assert lines[-4:] == ["(G79 X40. F0.1)", "G1 X40. F0.1", "G0 X50.", "M2"]
    with pytest.raises(ProgramError, match="G79 is not supported"):
        translate_program(PROGRAM.replace("G21 G90 G95", "G21 G99"), "fanuc")  # not one of its DIALECTS


def test_a_registered_cycle_is_on_the_command_line(toy_registered):
    out = io.StringIO()
    with redirect_stdout(out):
        assert cli.main(["emit", "g79", "-X", "40", "-F", "0.1"]) == 0
    assert out.getvalue() == "G79 X40. F0.1\n"
    help_text = io.StringIO()
    with redirect_stdout(help_text), pytest.raises(SystemExit):
        cli.main(["emit", "--help"])
    assert "toy-g79 (g79)" in help_text.getvalue() and "a toy plunge" in help_text.getvalue()
