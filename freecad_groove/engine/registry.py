"""The cycle registry: every cycle the engine knows, declared once.

A cycle class derives from ``cycle.Cycle``, which names everything the rest of
the project reads of a cycle, with its default: the declaration (NAME, KEY,
ALIASES, DIALECTS, TITLE, FORM, WORD_HELP, COUNTED, NEEDS_BLADE, MILL,
Z_ONLY, FROM_UNKNOWN_Z, BLOCKS, RETRACT_BLOCK, MEMORY, MEMORY_WHAT, PARAMETERS) and the hooks
(parse, emit, validate, expand, warnings, note, the memory hooks
with_earlier/remembered, the region hooks region_ends/check_region_block).
It is registered with the ``@register`` decorator, which checks the
declaration (:func:`declaration_errors`) and refuses a class that breaks it.

The program reader, the translator (which hands a cycle's blocks to its block
form, ``BLOCKS``), the command line (``expand``, ``emit``, ``--help``), the
posts and verify look cycles up here; adding a cycle is one new module in
``engine/cycles/`` whose classes carry ``@register`` (docs/architecture.md,
"How to add a cycle").
"""

import importlib
from dataclasses import dataclass
from typing import Dict, List, Tuple, Type

from .block_forms import BlockForm
from .cycle import CALL, FORMS, G_WORD, REQUIRED_HOOKS, Cycle, gives_hook

__all__ = ["CALL", "FORMS", "G_WORD", "CycleEntry", "CycleWord", "cycle_for", "cycles", "cycles_of",
           "declaration_errors", "entry", "register"]


@dataclass(frozen=True)
class CycleWord:
    """One word (or call parameter) of a cycle, with its help text."""

    name: str
    help: str
    counted: bool = False  # an integer in least input increments, no decimal point


@dataclass(frozen=True)
class CycleEntry:
    """What the registry knows of one cycle class."""

    key: str
    name: str
    dialects: Tuple[str, ...]
    title: str
    form: str
    words: Tuple[CycleWord, ...]
    cycle_class: Type[Cycle]
    aliases: Tuple[str, ...] = ()
    retract_block: str = ""  # the letter of a separate "NAME R(e)" first block; "" when none
    needs_blade: bool = False  # its moves depend on the blade: never expanded with an unknown one


_BY_KEY: Dict[str, CycleEntry] = {}
_ENTRIES: list = []


def declaration_errors(cls: type) -> List[str]:
    """What is wrong with a cycle class's declaration (cycle.Cycle), [] when nothing."""
    if not (isinstance(cls, type) and issubclass(cls, Cycle)):
        return ["does not derive from engine.cycle.Cycle"]
    errors = ["%s must be given" % name for name, value in (("NAME", cls.NAME), ("KEY", cls.KEY),
                                                           ("DIALECTS", cls.DIALECTS), ("TITLE", cls.TITLE))
              if not value]
    if cls.FORM not in FORMS:
        errors.append("FORM must be one of %s" % ", ".join(FORMS))
    words = [word for word, _help in cls.WORD_HELP]
    if len(set(words)) != len(words):
        errors.append("WORD_HELP names a word twice")
    errors += ["COUNTED %s is not one of its words" % word for word in cls.COUNTED if word not in words]
    errors += ["%s must be given" % hook for hook in REQUIRED_HOOKS if not gives_hook(cls, hook)]
    if not (isinstance(cls.BLOCKS, type) and issubclass(cls.BLOCKS, BlockForm)):
        return errors + ["BLOCKS must be a block form (block_forms.BlockForm)"]
    errors += cls.BLOCKS.declaration_errors(cls)
    if cls.PARAMETERS and not cls.MEMORY:
        errors.append("PARAMETERS are kept in a program memory: MEMORY must be given")
    if cls.MEMORY:
        errors += ["a cycle with a MEMORY gives %s" % hook for hook in ("with_earlier", "remembered")
                   if not gives_hook(cls, hook)]
    return errors


def register(cls: Type[Cycle]) -> Type[Cycle]:
    """Class decorator: add a cycle class to the registry (see the module notes);
    ValueError when its declaration is wrong or it clashes with a registered one."""
    errors = declaration_errors(cls)
    if errors:
        raise ValueError("cycle %s: %s" % (cls.__name__, "; ".join(errors)))
    counted = tuple(cls.COUNTED)
    entry = CycleEntry(
        key=cls.KEY,
        name=cls.NAME,
        dialects=tuple(cls.DIALECTS),
        title=cls.TITLE,
        form=cls.FORM,
        words=tuple(CycleWord(word, text, word in counted) for word, text in cls.WORD_HELP),
        cycle_class=cls,
        aliases=tuple(cls.ALIASES),
        retract_block=cls.RETRACT_BLOCK,
        needs_blade=cls.NEEDS_BLADE,
    )
    for key in (entry.key,) + entry.aliases:
        known = _BY_KEY.get(key)
        if known is not None and known.cycle_class is not cls:
            raise ValueError("cycle key %r is registered twice (%s, %s)" % (key, known.cycle_class.__name__,
                                                                           cls.__name__))
    for other in _ENTRIES:
        if other.cycle_class is not cls and other.name == entry.name and set(other.dialects) & set(entry.dialects):
            raise ValueError("%s is registered twice for %s" % (entry.name, ", ".join(entry.dialects)))
    if all(e.cycle_class is not cls for e in _ENTRIES):
        _ENTRIES.append(entry)
    for key in (entry.key,) + entry.aliases:
        _BY_KEY[key] = entry
    return cls


def _load() -> None:
    # the cycle modules register themselves when the cycles package is imported
    importlib.import_module(__package__ + ".cycles")


def cycles() -> Tuple[CycleEntry, ...]:
    """Every registered cycle, in registration order."""
    _load()
    return tuple(_ENTRIES)


def cycles_of(dialect: str) -> Tuple[CycleEntry, ...]:
    """The cycles a ``dialect``'s programs may call."""
    return tuple(e for e in cycles() if dialect in e.dialects)


def entry(key: str) -> CycleEntry:
    """The cycle with command-line name (or alias) ``key``; ValueError when unknown."""
    _load()
    try:
        return _BY_KEY[key]
    except KeyError:
        raise ValueError("unknown cycle %r (known: %s)" % (key, ", ".join(sorted(_BY_KEY)))) from None


def cycle_for(dialect: str, name: str) -> Type[Cycle]:
    """The cycle class a ``dialect`` program calls as ``name`` ("CYCLE93", "G77");
    ValueError when that dialect has no such cycle."""
    for e in cycles_of(dialect):
        if e.name == name.upper():
            return e.cycle_class
    raise ValueError("%s is not a cycle of %s programs" % (name, dialect))
