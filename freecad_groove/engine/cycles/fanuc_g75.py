"""Fanuc two-block G75 / G74 and Haas one-block G75 / G74 pecking groove cycles.

Built on the pecking machinery in ``ab_g77`` (one loop, :func:`ab_g77.peck_grooves`,
for all six cycles; same number format, same parse rules, same state handling).

Fanuc (notes/cycles.md) ``G75 R(e);`` then ``G75 X(U) Z(W) P(di) Q(dk) R(dd) F;``

* First block R = e, the peck retract (per side). ``e`` in the model; None when
  the first block is not written: ``Settings.retract_e`` is used (Fanuc's
  parameter 5139 plays that role on the control).
* X (or U) groove bottom, Z (or W) last groove. X/Z follow G90/G91
  (``MachineState.incremental``), U/W are always incremental; X and U follow
  diameter mode. The model keeps the letter that was used.
* P = peck depth along X, Q = shift between grooves along Z: unsigned integers in
  least input increments, 0.001 mm metric / 0.0001 in inch (P2000 = 2 mm),
  converted with ``MachineState.metric`` at expand time.
* Second block R = dd, relief along Z at the groove bottom, toward the side the
  grooves came from (against the Q stepping), not at the first plunge.
* Pecks: FEED di, RAPID back e, FEED di + e, ... the last infeed lands on X; then
  the relief (not at the first groove), RAPID to the start X, RAPID along Z to the
  next groove (the last shift is shortened so the last groove is exactly at Z).
  The cycle ends with a RAPID to the start point.
* G74 is the face twin: Z (W) bottom, X (U) last groove, Q peck along Z, P shift
  along X, R relief along X. G74 without X/U and P is peck drilling along Z.

Haas one-block ``G75 X(U) Z(W) I K D F`` (and G74): I peck along X, K shift along Z,
D relief along Z (same rule as Fanuc's dd), decimal values (not increments); e is
``Settings.retract_e`` (Haas setting 22). G74: K peck along Z, I shift along X,
D relief along X.

Choices the manuals leave open (besides those listed in ``ab_g77``):

* The relief is a RAPID move, and it is only made when there is more than one
  groove (the first plunge never gets it). As on the control, a relief larger
  than the gap already cut (Q > tool width, or dd > Q) runs the blade into the
  wall at rapid: it is moved as programmed, and ``warnings()`` (pecking.py)
  says so when the blade's width is known (``Settings.tool``; None: no warning).
* The plunge-axis bottom (X/U for G75, Z/W for G74) is required and must differ
  from the start; P (G75) / Q (G74) then is required and > 0. The shift word is
  required and > 0 only when the last groove is away from the start; Q0 / K0 is
  accepted for a single groove.
* emit() writes both Fanuc blocks (joined by "\\n") when e is set, else only the
  cycle block. parse() takes one or two blocks (lines or ";"-separated); a lone
  ``G75 R..`` is refused as an incomplete first block.
* P and Q are refused when written with a decimal point or when above 8 digits;
  X/Z/U/W/R/F follow the 4-decimal word format of ``ab_g77``.
* Errors name the first-block R as "R(e)"; "R" is the second block's relief.
"""

from dataclasses import dataclass
from typing import ClassVar, Optional

from ..errors import CycleError
from ..registry import G_WORD, register
from ..retract_block import RetractBlock
from ..settings import DEFAULT_SETTINGS, Settings
from .cycle_words import check_number, read_block, word_value
from .pecking import PeckingCycle

__all__ = ["FanucG75", "FanucG74", "HaasG75", "HaasG74"]


@dataclass(frozen=True)
class _Fanuc(PeckingCycle):
    """The words of Fanuc G75 and G74 (e: R of the first block)."""

    DIALECTS: ClassVar[tuple] = ("fanuc", "gsk")  # GSK 980TDi writes the same two blocks
    FORM: ClassVar[str] = G_WORD
    WORDS = ("X", "U", "Z", "W", "P", "Q", "R", "F")
    COUNTED = ("P", "Q")
    RELIEF = "R"
    BLOCKS: ClassVar[type] = RetractBlock  # "G75 R(e)" before the cycle block sets e
    RETRACT_BLOCK: ClassVar[str] = "R"

    e: Optional[float] = None
    X: Optional[float] = None
    U: Optional[float] = None
    Z: Optional[float] = None
    W: Optional[float] = None
    P: Optional[int] = None
    Q: Optional[int] = None
    R: Optional[float] = None
    F: Optional[float] = None

    def _retract(self, settings, metric):
        if self.e is not None:
            return self.e, "R(e)"
        return super()._retract(settings, metric)

    def validate(self, settings: Settings = DEFAULT_SETTINGS) -> "PeckingCycle":
        if self.e is not None:
            check_number(self.NAME, "R(e)", self.e)
        return super().validate(settings)

    def emit(self) -> str:
        cycle = self._words_text()
        if self.e is None:
            return cycle
        return "%s R%s\n%s" % (self.NAME, word_value(self.e), cycle)

    @classmethod
    def parse(cls, text: str) -> "PeckingCycle":
        blocks = [block for block in text.replace(";", "\n").split("\n") if block.strip()]
        if len(blocks) > 2:
            raise CycleError(
                cls.NAME, None, "takes at most two blocks: %s R(e) then the cycle block" % cls.NAME, cycle=cls.NAME
            )
        e = None
        if len(blocks) == 2:
            e = read_block(blocks[0], cls.NAME, ("R",)).get("R")
            if e is None:
                raise CycleError(
                    "R(e)", None, "must be programmed in the first block %s R(e)" % cls.NAME, cycle=cls.NAME
                )
        words = read_block(blocks[-1] if blocks else "", cls.NAME, cls.WORDS, cls.COUNTED)
        if set(words) == {"R"} and len(blocks) == 1:
            raise CycleError(
                "/".join(cls.BOTTOM),
                None,
                "must be programmed: %s R.. alone is only the first block (peck retract e)" % cls.NAME,
                cycle=cls.NAME,
            )
        return cls(e=e, **words).validate()


@register
@dataclass(frozen=True)
class FanucG75(_Fanuc):
    """Fanuc ``G75 R(e);`` ``G75 X(U) Z(W) P(di) Q(dk) R(dd) F;``: grooves along Z, plunging in X.

    X/U groove bottom (required, != start X), Z/W last groove (omitted = one),
    P peck along X (increments, > 0), Q shift along Z (increments, > 0 when Z is
    away from the start), R relief along Z (>= 0, not at the first groove), F feed.
    """

    NAME: ClassVar[str] = "G75"
    KEY: ClassVar[str] = "fanuc-g75"
    ALIASES: ClassVar[tuple] = ("g75",)
    TITLE: ClassVar[str] = "Fanuc two-block G75 grooving"
    WORD_HELP: ClassVar[tuple] = (
        ("X", "groove bottom X (diameter, absolute)"),
        ("U", "groove bottom as an increment from the start X (diameter)"),
        ("Z", "Z of the last groove (absolute; omit for one groove)"),
        ("W", "last groove as an increment from the start Z"),
        ("P", "peck depth along X in least input increments, no decimal point (P2000 = 2 mm)"),
        ("Q", "groove spacing along Z in least input increments (Q5000 = 5 mm)"),
        ("R", "relief along Z at the groove bottom (not on the first groove)"),
        ("F", "feed (optional)"),
    )
    AXIS: ClassVar[str] = "X"
    BOTTOM: ClassVar[tuple] = ("X", "U")
    LAST: ClassVar[tuple] = ("Z", "W")
    PECK: ClassVar[str] = "P"
    PITCH: ClassVar[str] = "Q"


@register
@dataclass(frozen=True)
class FanucG74(_Fanuc):
    """Fanuc ``G74 R(e);`` ``G74 X(U) Z(W) P(di) Q(dk) R(dd) F;``: face grooves along X, plunging in Z.

    Z/W groove bottom (required, != start Z), X/U last groove (omitted = one: peck
    drilling), Q peck along Z (increments, > 0), P shift along X (increments, > 0
    when X is away from the start), R relief along X (>= 0, not at the first), F feed.
    """

    NAME: ClassVar[str] = "G74"
    KEY: ClassVar[str] = "fanuc-g74"
    ALIASES: ClassVar[tuple] = ("g74",)
    TITLE: ClassVar[str] = "Fanuc two-block G74 face grooving / peck drilling"
    WORD_HELP: ClassVar[tuple] = (
        ("X", "X of the last face groove (diameter; omit for one groove / peck drilling)"),
        ("U", "last groove as an increment from the start X (diameter)"),
        ("Z", "groove bottom Z (absolute)"),
        ("W", "groove bottom as an increment from the start Z"),
        ("P", "groove spacing along X in least input increments (P5000 = 5 mm)"),
        ("Q", "peck depth along Z in least input increments, no decimal point (Q2000 = 2 mm)"),
        ("R", "relief along X at the groove bottom (not on the first groove)"),
        ("F", "feed (optional)"),
    )
    AXIS: ClassVar[str] = "Z"
    BOTTOM: ClassVar[tuple] = ("Z", "W")
    LAST: ClassVar[tuple] = ("X", "U")
    PECK: ClassVar[str] = "Q"
    PITCH: ClassVar[str] = "P"


@dataclass(frozen=True)
class _Haas(PeckingCycle):
    """The words of Haas G75 and G74."""

    DIALECTS: ClassVar[tuple] = ("haas",)
    FORM: ClassVar[str] = G_WORD
    WORDS = ("X", "U", "Z", "W", "I", "K", "D", "F")
    RELIEF = "D"

    X: Optional[float] = None
    U: Optional[float] = None
    Z: Optional[float] = None
    W: Optional[float] = None
    I: Optional[float] = None  # noqa: E741 - the control's word
    K: Optional[float] = None
    D: Optional[float] = None
    F: Optional[float] = None


@register
@dataclass(frozen=True)
class HaasG75(_Haas):
    """Haas ``G75 X(U) Z(W) I K D F``: grooves along Z, plunging in X.

    I peck along X (> 0), K shift along Z (> 0 when Z is away from the start),
    D relief along Z (>= 0, not at the first groove); e = Settings.retract_e.
    """

    NAME: ClassVar[str] = "G75"
    KEY: ClassVar[str] = "haas-g75"
    ALIASES: ClassVar[tuple] = ()
    TITLE: ClassVar[str] = "Haas one-block G75 grooving"
    WORD_HELP: ClassVar[tuple] = (
        ("X", "groove bottom X (diameter, absolute)"),
        ("U", "groove bottom as an increment from the start X (diameter)"),
        ("Z", "Z of the last groove (omit for one groove)"),
        ("W", "last groove as an increment from the start Z"),
        ("I", "peck depth along X, per side"),
        ("K", "groove spacing along Z"),
        ("D", "relief along Z at the groove bottom (not on the first groove)"),
        ("F", "feed (optional)"),
    )
    AXIS: ClassVar[str] = "X"
    BOTTOM: ClassVar[tuple] = ("X", "U")
    LAST: ClassVar[tuple] = ("Z", "W")
    PECK: ClassVar[str] = "I"
    PITCH: ClassVar[str] = "K"


@register
@dataclass(frozen=True)
class HaasG74(_Haas):
    """Haas ``G74 X(U) Z(W) I K D F``: face grooves along X, plunging in Z.

    K peck along Z (> 0), I shift along X (> 0 when X is away from the start),
    D relief along X (>= 0, not at the first groove); e = Settings.retract_e.
    """

    NAME: ClassVar[str] = "G74"
    KEY: ClassVar[str] = "haas-g74"
    ALIASES: ClassVar[tuple] = ()
    TITLE: ClassVar[str] = "Haas one-block G74 face grooving"
    WORD_HELP: ClassVar[tuple] = (
        ("X", "X of the last face groove (diameter; omit for one)"),
        ("U", "last groove as an increment from the start X (diameter)"),
        ("Z", "groove bottom Z (absolute)"),
        ("W", "groove bottom as an increment from the start Z"),
        ("I", "groove spacing along X, per side"),
        ("K", "peck depth along Z"),
        ("D", "relief along X at the groove bottom (not on the first groove)"),
        ("F", "feed (optional)"),
    )
    AXIS: ClassVar[str] = "Z"
    BOTTOM: ClassVar[tuple] = ("Z", "W")
    LAST: ClassVar[tuple] = ("X", "U")
    PECK: ClassVar[str] = "K"
    PITCH: ClassVar[str] = "I"
