"""The cycle registry: every cycle the engine knows, declared once.

A cycle class declares what the rest of the project needs to know about it as
class attributes, and is registered with the ``@register`` decorator:

    NAME       the code as the control writes it: "CYCLE93", "G77"
    KEY        its name on the command line: "cycle93", "ab-g77"
    ALIASES    other command-line names: ("g77",)
    CONTROLS   the input controls whose programs use it: ("ab9",)
    TITLE      one line for help texts
    FORM       how a block is recognised: CALL (``NAME(p1, p2, ...)``, the
               Siemens call syntax) or G_WORD (the G code ``NAME`` among
               letter-and-number words)
    WORD_HELP  ((word, help text), ...) in the order the cycle writes them
    COUNTED    words that are integers in least input increments (Fanuc P, Q)
    RETRACT_BLOCK  optional: the letter of a separate first block ``NAME R(e)``
               that only sets the peck retract for the next cycle (Fanuc "R")
    NEEDS_BLADE    optional, default False: True when the cycle's moves depend
               on the blade (its width, corner radius, reference corner), as
               CYCLE93's do; such a cycle is expanded only with a known blade
               (``Settings.tool`` or a tool table's entry), never a guessed
               one. Cycles that drive the programmed point (G77, G75...) leave
               it False.

and the methods ``parse(text)``, ``emit()``, ``validate(settings)`` and
``expand(state, settings)``; optionally ``warnings(state, settings) ->
List[warnings.CycleWarning]``: what the expansion from the same state cannot
do as programmed but does anyway (CYCLE93 roughing on the final profile, a
Fanuc relief into the wall between grooves). A cycle without it has none
(``warnings.cycle_warnings``); the translator calls it after ``expand()`` and
keeps the warnings with the line. The program reader, the command line (``expand``,
``emit``, ``--help``) and the posts look cycles up here; adding a cycle is one
new module in ``engine/cycles/`` whose classes carry ``@register``.
"""

import importlib
from dataclasses import dataclass
from typing import Dict, Tuple, Type

CALL = "call"
G_WORD = "g-word"
FORMS = (CALL, G_WORD)


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
    controls: Tuple[str, ...]
    title: str
    form: str
    words: Tuple[CycleWord, ...]
    cycle_class: type
    aliases: Tuple[str, ...] = ()
    retract_block: str = ""  # the letter of a separate "NAME R(e)" first block; "" when none
    needs_blade: bool = False  # its moves depend on the blade: never expanded with an unknown one


_BY_KEY: Dict[str, CycleEntry] = {}
_ENTRIES: list = []


def register(cls: Type) -> Type:
    """Class decorator: add a cycle class to the registry (see the module notes)."""
    counted = tuple(getattr(cls, "COUNTED", ()))
    entry = CycleEntry(
        key=cls.KEY,
        name=cls.NAME,
        controls=tuple(cls.CONTROLS),
        title=cls.TITLE,
        form=cls.FORM,
        words=tuple(CycleWord(word, text, word in counted) for word, text in cls.WORD_HELP),
        cycle_class=cls,
        aliases=tuple(getattr(cls, "ALIASES", ())),
        retract_block=getattr(cls, "RETRACT_BLOCK", ""),
        needs_blade=bool(getattr(cls, "NEEDS_BLADE", False)),
    )
    if entry.form not in FORMS:
        raise ValueError("%s: FORM must be one of %s" % (cls.__name__, ", ".join(FORMS)))
    for key in (entry.key,) + entry.aliases:
        known = _BY_KEY.get(key)
        if known is not None and known.cycle_class is not cls:
            raise ValueError("cycle key %r is registered twice (%s, %s)" % (key, known.cycle_class.__name__,
                                                                           cls.__name__))
    for other in _ENTRIES:
        if other.cycle_class is not cls and other.name == entry.name and set(other.controls) & set(entry.controls):
            raise ValueError("%s is registered twice for %s" % (entry.name, ", ".join(entry.controls)))
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


def cycles_of(control: str) -> Tuple[CycleEntry, ...]:
    """The cycles an input control's programs may call."""
    return tuple(e for e in cycles() if control in e.controls)


def entry(key: str) -> CycleEntry:
    """The cycle with command-line name (or alias) ``key``; ValueError when unknown."""
    _load()
    try:
        return _BY_KEY[key]
    except KeyError:
        raise ValueError("unknown cycle %r (known: %s)" % (key, ", ".join(sorted(_BY_KEY)))) from None


def cycle_for(control: str, name: str) -> type:
    """The cycle class a ``control`` program calls as ``name`` ("CYCLE93", "G77");
    ValueError when that control has no such cycle."""
    for e in cycles_of(control):
        if e.name == name.upper():
            return e.cycle_class
    raise ValueError("%s is not a cycle of %s programs" % (name, control))
