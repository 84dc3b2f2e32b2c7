"""The cycle protocol (engine/cycle.py): every registered cycle derives from
Cycle, the registry checks each declaration, nothing probes a cycle for an
attribute, and a new way of writing a call over blocks is a new block form
class that the translator takes up unchanged.

The probe rule, read from the source with ast: in freecad_groove/, no
``getattr``/``hasattr`` names a member of Cycle as a string (the protocol is
read, never probed: ``cls.MEMORY``, not ``getattr(cls, "MEMORY", "")``); and
where cycles are handled (the engine outside engine/cycles/, the command line,
verify) no ``getattr``/``hasattr`` takes a cycle class, a model or a registry
entry: a name ``cycle``, ``cycle_class``, ``cls``, ``model`` or ``entry``, or
anything ``.cycle_class``. Inside engine/cycles/ a cycle reads its own words
by letter (``getattr(self, letter)``), which is no probe."""

import ast
import glob
import os
import re
from dataclasses import dataclass
from typing import ClassVar, Optional

import pytest
from conftest import ROOT

from freecad_groove.engine import FEED, RAPID, CycleError, Move, ProgramError, registry
from freecad_groove.engine.block_forms import BlockForm, CycleCall, OpenBlocks, SingleBlock, call_label
from freecad_groove.engine.cycle import Cycle
from freecad_groove.engine.cycles.ab_g77 import G77
from freecad_groove.engine.cycles.cycle_words import read_block, word_value
from freecad_groove.engine.region_blocks import RegionBlocks
from freecad_groove.engine.retract_block import RetractBlock
from freecad_groove.engine.translator import translate_program

PROTOCOL = frozenset(name for name in vars(Cycle) if not name.startswith("_"))
CYCLE_NAMES = frozenset(("cycle", "cycle_class", "cls", "model", "entry"))
PROBES = ("getattr", "hasattr")


def _is_cycle(node):
    """Whether an expression is, by its name, a cycle class, model or entry."""
    if isinstance(node, ast.Name):
        return node.id in CYCLE_NAMES
    return isinstance(node, ast.Attribute) and node.attr == "cycle_class"


def probes(source, handles_cycles, filename="<source>"):
    """'line: call' for each getattr/hasattr of ``source`` the rule forbids (see the module notes);
    ``handles_cycles``: the file is one where cycles are handled (the second half of the rule)."""
    found = []
    for node in ast.walk(ast.parse(source, filename)):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in PROBES
                and len(node.args) >= 2):
            continue
        name = node.args[1]
        names_member = isinstance(name, ast.Constant) and name.value in PROTOCOL
        if names_member or (handles_cycles and _is_cycle(node.args[0])):
            found.append("%d: %s" % (node.lineno, ast.unparse(node)))
    return found


def _source_files():
    """(path relative to ROOT, whether cycles are handled there) of every product module."""
    for path in sorted(glob.glob(os.path.join(ROOT, "freecad_groove", "**", "*.py"), recursive=True)):
        rel = os.path.relpath(path, ROOT).replace(os.sep, "/")
        engine = rel.startswith("freecad_groove/engine/") and not rel.startswith("freecad_groove/engine/cycles/")
        handles = engine or rel.startswith(("freecad_groove/cli", "freecad_groove/verify/"))
        yield rel, handles


def test_the_probe_rule_finds_the_probes_it_names_and_passes_plain_reads():
    source = (
        'if getattr(entry.cycle_class, "REGION", False): pass\n'  # a cycle class, and a name it could declare
        'if hasattr(model, "note"): pass\n'  # a hook probed on a model
        'method = getattr(thing, "warnings", None)\n'  # a hook by name, on anything
        'count = getattr(cls, "COUNTED", ())\n'
        'value = getattr(args, "dialect", None)\n'  # the command line's options: no cycle, no member
        'word = getattr(self, letter)\n'  # a cycle's own word by letter
        'shape = getattr(obj, "Shape", None)\n'
    )
    assert probes(source, handles_cycles=True) == [
        '1: getattr(entry.cycle_class, \'REGION\', False)',
        "2: hasattr(model, 'note')",
        "3: getattr(thing, 'warnings', None)",
        "4: getattr(cls, 'COUNTED', ())",
    ]
    # where cycles are not handled (FreeCAD's objects are "model" there too) only the member names count
    assert probes('shape = getattr(model, "Shape", None)\nx = getattr(model, "MEMORY", "")\n', False) == [
        "2: getattr(model, 'MEMORY', '')"]


def test_nothing_in_the_product_probes_a_cycle():
    found = []
    for rel, handles in _source_files():
        with open(os.path.join(ROOT, rel), encoding="utf-8") as f:
            found += ["%s:%s" % (rel, probe) for probe in probes(f.read(), handles, rel)]
    assert found == []


def test_the_rule_reads_the_modules_that_handle_cycles():
    handled = {rel for rel, handles in _source_files() if handles}
    assert {"freecad_groove/engine/translate_cycle.py", "freecad_groove/engine/registry.py",
            "freecad_groove/engine/warnings.py", "freecad_groove/cli.py", "freecad_groove/cli_parameters.py",
            "freecad_groove/verify/program_record.py", "freecad_groove/engine/region_blocks.py"} <= handled
    assert "freecad_groove/engine/cycles/milltronics.py" not in handled


# ---------------------------------------------------------------- the declarations


@pytest.mark.parametrize("entry", registry.cycles(), ids=lambda e: e.key)
def test_every_registered_cycle_derives_from_cycle_and_declares_a_block_form(entry):
    cls = entry.cycle_class
    assert issubclass(cls, Cycle) and issubclass(cls.BLOCKS, BlockForm)
    assert registry.declaration_errors(cls) == []


def test_the_cycles_declare_the_block_forms_of_their_manuals():
    forms = {entry.key: entry.cycle_class.BLOCKS for entry in registry.cycles()}
    assert {key for key, form in forms.items() if form is RetractBlock} == {"fanuc-g75", "fanuc-g74"}
    assert {key for key, form in forms.items() if form is RegionBlocks} == {"gsk-g7.1"}
    memories = {entry.key: entry.cycle_class.MEMORY for entry in registry.cycles() if entry.cycle_class.MEMORY}
    assert memories == {"ab-g83": "ab-g83", "ab-g83.1": "ab-g83", "milltronics-g31": "milltronics",
                        "milltronics-g32": "milltronics", "milltronics-g33": "milltronics",
                        "milltronics-g34": "milltronics"}
    parameters = {entry.key for entry in registry.cycles() if entry.cycle_class.PARAMETERS}
    assert parameters == {"milltronics-g33", "milltronics-g34"}


@dataclass(frozen=True)
class ToyPlunge(Cycle):
    """``G79 X__ F__``: one plunge to X (a diameter) at F and a rapid back to the start."""

    NAME: ClassVar[str] = "G79"
    KEY: ClassVar[str] = "toy-g79"
    DIALECTS: ClassVar[tuple] = ("ab9",)
    TITLE: ClassVar[str] = "a toy plunge"
    FORM: ClassVar[str] = registry.G_WORD
    WORD_HELP: ClassVar[tuple] = (("X", "plunge bottom X (diameter)"), ("F", "feed of the plunge"))

    X: Optional[float] = None
    F: Optional[float] = None

    @classmethod
    def parse(cls, text: str) -> "ToyPlunge":
        return cls(**read_block(" ".join(text.split("\n")), cls.NAME, ("X", "F")))

    def emit(self) -> str:
        return " ".join([self.NAME] + [letter + word_value(value) for letter, value in
                                       (("X", self.X), ("F", self.F)) if value is not None])

    def validate(self, settings: object = None) -> "ToyPlunge":
        if self.X is None or self.F is None:
            raise CycleError("X" if self.X is None else "F", None, "must be programmed", cycle=self.NAME)
        return self

    def expand(self, state: object, settings: object = None) -> list:
        return [Move(FEED, self.X / 2.0, state.z, self.F), Move(RAPID, state.x, state.z)]


def _declared(**attributes):
    """A toy plunge subclass declaring ``attributes`` (hooks included)."""
    return type("Declared", (ToyPlunge,), attributes)


@pytest.mark.parametrize("attributes, error", [
    ({"KEY": ""}, "KEY must be given"),
    ({"DIALECTS": ()}, "DIALECTS must be given"),
    ({"FORM": "words"}, "FORM must be one of call, g-word"),
    ({"COUNTED": ("P",)}, "COUNTED P is not one of its words"),
    ({"BLOCKS": RetractBlock}, "RETRACT_BLOCK '' must be one of its words (X, F)"),
    ({"RETRACT_BLOCK": "F"}, "RETRACT_BLOCK 'F' is read only by BLOCKS = RetractBlock, not SingleBlock"),
    ({"BLOCKS": RegionBlocks}, "a region cycle gives region_ends"),
    ({"BLOCKS": CycleCall}, "BLOCKS must be a block form (block_forms.BlockForm)"),
    ({"PARAMETERS": ("P151",), "MEMORY": ""}, "PARAMETERS are kept in a program memory: MEMORY must be given"),
    ({"MEMORY": "toy"}, "a cycle with a MEMORY gives with_earlier"),
])
def test_register_refuses_a_declaration_that_breaks_the_protocol(monkeypatch, attributes, error):
    monkeypatch.setattr(registry, "_ENTRIES", list(registry.cycles()))
    monkeypatch.setattr(registry, "_BY_KEY", dict(registry._BY_KEY))
    cls = _declared(**attributes)
    assert error in registry.declaration_errors(cls)
    with pytest.raises(ValueError, match="cycle Declared: .*" + re.escape(error)):
        registry.register(cls)


def test_register_refuses_a_class_that_does_not_derive_from_cycle():
    plain = type("Plain", (), {"NAME": "G79", "KEY": "plain", "DIALECTS": ("ab9",), "TITLE": "t",
                               "FORM": registry.G_WORD, "WORD_HELP": ()})
    with pytest.raises(ValueError, match="cycle Plain: does not derive from engine.cycle.Cycle"):
        registry.register(plain)


def test_a_cycle_without_parse_emit_expand_is_refused():
    bare = type("Bare", (Cycle,), {"NAME": "G79", "KEY": "bare", "DIALECTS": ("ab9",), "TITLE": "t",
                                   "FORM": registry.G_WORD})
    assert registry.declaration_errors(bare) == ["parse must be given", "emit must be given", "expand must be given"]


def test_a_subclass_takes_the_declaration_and_the_hooks_of_its_family():
    assert registry.declaration_errors(type("Again", (G77,), {})) == []  # G77's family gives every hook


def test_the_base_class_defaults_are_the_cycle_without_extras():
    toy = ToyPlunge(X=40.0, F=0.1)
    assert toy.warnings(None, None) == [] and toy.note(None, None) is None
    assert toy.with_earlier({"X": 1.0}, None) is toy and toy.remembered(None) == {}
    assert ToyPlunge.region_ends("G79 X1.") is False and ToyPlunge.check_region_block("X1.", "ctx") == "ctx"
    assert (ToyPlunge.BLOCKS, ToyPlunge.MEMORY, ToyPlunge.PARAMETERS, ToyPlunge.MILL, ToyPlunge.Z_ONLY,
            ToyPlunge.FROM_UNKNOWN_Z, ToyPlunge.NEEDS_BLADE, ToyPlunge.RETRACT_BLOCK) == (
        SingleBlock, "", (), False, False, False, False, "")


# ---------------------------------------------------------------- a new block form, nothing else


class FeedBlock(BlockForm):
    """A toy form: the block after the call gives its F (``G79 X40.`` then ``F0.1``)."""

    TITLE = "the call, then its feed block"

    @classmethod
    def read_call(cls, translator, block, entry, call: CycleCall) -> None:
        translator.open_blocks(_OpenFeedBlock(block, entry, call))


class _OpenFeedBlock(OpenBlocks):
    def __init__(self, block, entry, call):
        self.block, self.entry, self.call = block, entry, call

    def read(self, translator, block) -> None:
        translator.open_blocks(None)
        call = self.call._replace(text=self.call.text + "\n" + " ".join(w.letter + w.text for w in block.words))
        translator.run_cycle(block, self.entry, call, call_label(call))

    def close(self, translator) -> None:
        raise ProgramError("%s without its feed block" % self.call.text, self.block.line)


@dataclass(frozen=True)
class ToyFeedBlock(ToyPlunge):
    KEY: ClassVar[str] = "toy-g79-feed-block"
    BLOCKS: ClassVar[type] = FeedBlock


@pytest.fixture
def feed_block_registered(monkeypatch):
    monkeypatch.setattr(registry, "_ENTRIES", list(registry.cycles()))
    monkeypatch.setattr(registry, "_BY_KEY", dict(registry._BY_KEY))
    registry.register(ToyFeedBlock)


PROGRAM = "G21 G90 G95\nS500 M3\nG0 X50. Z-4.\nG79 X40.\nF0.1\nM30\n"


def test_a_new_block_form_is_taken_up_by_the_translator_unchanged(feed_block_registered):
    lines = translate_program(PROGRAM, "ab9").splitlines()
    # worked by hand: the comment naming both blocks, the plunge to X40 at F0.1, the rapid back to X50
    assert lines[-4:] == ["(G79 X40. / F0.1)", "G1 X40. F0.1", "G0 X50.", "M2"]


def test_a_program_that_ends_inside_a_new_form_is_refused_by_the_form(feed_block_registered):
    with pytest.raises(ProgramError, match="G79 X40. without its feed block") as caught:
        translate_program("G21 G90 G95\nS500 M3\nG0 X50. Z-4.\nG79 X40.\n", "ab9")
    assert caught.value.line == 4


# ---------------------------------------------------------------- the table in docs/architecture.md


def _table_rows():
    """The rows of "The registered cycles" in docs/architecture.md: cells without their code marks, "—" as ""."""
    with open(os.path.join(ROOT, "docs", "architecture.md"), encoding="utf-8") as f:
        text = f.read()
    section = text.split("## The registered cycles\n", 1)[1].split("\n## ", 1)[0]
    rows = [line.strip("|").split("|") for line in section.splitlines() if line.startswith("| ")]
    return [[cell.replace("`", "").replace("—", "").strip() for cell in row] for row in rows[1:]]  # without the header


def _declared_row(entry):
    cls = entry.cycle_class
    key = entry.key + (" (%s)" % ", ".join(entry.aliases) if entry.aliases else "")
    also = (["RETRACT_BLOCK " + cls.RETRACT_BLOCK] if cls.RETRACT_BLOCK else []) + [
        name for name, flag in (("NEEDS_BLADE", cls.NEEDS_BLADE), ("MILL", cls.MILL), ("Z_ONLY", cls.Z_ONLY),
                                ("FROM_UNKNOWN_Z", cls.FROM_UNKNOWN_Z)) if flag]
    return [entry.name, key, ", ".join(entry.dialects), "CALL" if entry.form == registry.CALL else "G_WORD",
            cls.BLOCKS.__name__, cls.MEMORY, " ".join(cls.PARAMETERS), ", ".join(also),
            cls.__module__.rsplit(".", 1)[1] + ".py"]


def test_the_architecture_table_lists_every_registered_cycle_with_its_declaration():
    assert _table_rows() == [_declared_row(entry) for entry in registry.cycles()]
