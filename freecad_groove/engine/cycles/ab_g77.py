"""Allen-Bradley 9/Series lathe G77 (grooving / cut-off) and G76, its face twin,
built on the shared pecking machinery (``pecking``).

The 9/Series lathe manual (chapter 23) says, for
``G77 X__ Z__ I__ K__ F__ D__;``:

* **X** - the bottom of the groove, reached from the X the tool held before the
  block. Absolute or incremental (the modal G90/G91, ``MachineState.incremental``)
  and read per radius/diameter mode (``MachineState.diameter_mode``). For a
  cut-off it drives the tool through the centre (or beyond the OD from inside).
* **Z** - where the *last* groove is cut; not programmed for one groove.
  Absolute or incremental. Grooves are cut at the start Z, start Z + K, ...
  and the last one is always at Z even when the final gap is smaller than K.
* **K** - distance between grooves, always incremental.
* **I** - infeed per step, always incremental. Each step is followed by a retract
  of **e** (an AMP parameter: ``Settings.retract_e``); then infeed I + e, retract
  e, infeed I + e ... until the bottom X is reached.
* At the bottom: shift **D** at rapid (incremental, signed, "should move the tool
  away from the part"; must be programmed, 0 when not cutting off), then rapid
  retract to the starting X.
* **F** - optional; replaces the active feed for the infeeds.

G76 is the face twin with the axes swapped: Z = groove bottom, X = last groove
(diameter mode applies), K = infeed per peck along Z, I = distance between grooves
along X, D = shift along X at full depth.

Choices the manual leaves open (each a named constant here, each with a test;
the choices every pecking cycle shares are in ``pecking``):

* ``RETURN_TO_START_Z`` (True): after the last groove the tool rapids back to the
  start Z at the start X, so the cycle ends where it began. False: it stays at
  the last groove (shifted by D) at the start X.
* D's axis is the groove-stepping axis (Z for G77, X for G76); D is done at every
  groove (the manual's figure), at rapid, signed as programmed, as a per-side
  (radius) distance. Whether it really points away from the part cannot be
  checked here: the manual's CAUTION stands.
* K (G77) and I (G76) are unsigned: the grooves step from the start toward Z
  (X). A negative value is refused; 0 or missing is refused only when the last
  groove is away from the start.
"""

from dataclasses import dataclass
from typing import ClassVar, Optional

from ..registry import G_WORD, register
from .pecking import PeckingCycle

__all__ = ["G77", "G76", "RETURN_TO_START_Z"]

RETURN_TO_START_Z = True

# ---------------------------------------------------------------- Allen-Bradley


@dataclass(frozen=True)
class _AllenBradley(PeckingCycle):
    """The words of G77 and G76, in the order emit() writes them."""

    DIALECTS: ClassVar[tuple] = ("ab9",)
    FORM: ClassVar[str] = G_WORD
    WORDS = ("X", "Z", "I", "K", "F", "D")
    SHIFT_D = True

    X: Optional[float] = None
    Z: Optional[float] = None
    I: Optional[float] = None  # noqa: E741 - the control's word
    K: Optional[float] = None
    F: Optional[float] = None
    D: Optional[float] = None

    def _returns_to_start(self):
        return RETURN_TO_START_Z


@register
@dataclass(frozen=True)
class G77(_AllenBradley):
    """Allen-Bradley 9/Series ``G77 X__ Z__ I__ K__ F__ D__`` (9/Series lathe manual, chapter 23).

    X groove bottom (abs/inc per G90/G91, diameter per mode; required, must
    differ from the start X: below it = external/cut-off, MINUS_X; above = internal,
    PLUS_X). Z last groove (abs/inc; omitted = one groove). K groove spacing along Z,
    incremental, unsigned, > 0 when Z is away from the start. I infeed per peck
    (> 0, incremental, per side). D rapid shift along Z at full depth, every groove,
    signed (required, 0 = none). F feed of the infeeds (optional).

    Per groove: FEED I, RAPID back e, FEED I + e, ... the last infeed lands on X;
    RAPID D along Z (if D != 0); RAPID to the start X; RAPID along Z to the next
    groove. After the last: RAPID to the start Z (``RETURN_TO_START_Z``).
    """

    NAME: ClassVar[str] = "G77"
    KEY: ClassVar[str] = "ab-g77"
    ALIASES: ClassVar[tuple] = ("g77",)
    TITLE: ClassVar[str] = "Allen-Bradley 9/Series G77 grooving / cut-off"
    WORD_HELP: ClassVar[tuple] = (
        ("X", "groove bottom X (absolute or incremental per G90/G91; diameter in diameter mode)"),
        ("Z", "Z of the LAST groove (omit for one groove)"),
        ("I", "infeed per peck along X, per side"),
        ("K", "distance between grooves along Z (always incremental)"),
        ("F", "feed for the infeeds (optional: the active feed otherwise)"),
        ("D", "rapid shift along Z at full depth (signed, away from the part; 0 when not cutting off; required)"),
    )
    AXIS: ClassVar[str] = "X"
    BOTTOM: ClassVar[tuple] = ("X",)
    LAST: ClassVar[tuple] = ("Z",)
    PECK: ClassVar[str] = "I"
    PITCH: ClassVar[str] = "K"
    RELIEF: ClassVar[str] = "D"


@register
@dataclass(frozen=True)
class G76(_AllenBradley):
    """Allen-Bradley 9/Series ``G76 X__ Z__ I__ K__ F__ D__``: G77 with the axes swapped.

    Z groove bottom (abs/inc; below the start Z = MINUS_Z, above = PLUS_Z). X last
    groove (abs/inc, diameter per mode; omitted = one groove). I groove spacing
    along X (per side, unsigned). K infeed per peck along Z (> 0). D rapid shift
    along X at full depth (per side, signed, required, 0 = none). F as in G77.
    """

    NAME: ClassVar[str] = "G76"
    KEY: ClassVar[str] = "ab-g76"
    ALIASES: ClassVar[tuple] = ("g76",)
    TITLE: ClassVar[str] = "Allen-Bradley 9/Series G76 face grooving"
    WORD_HELP: ClassVar[tuple] = (
        ("X", "X of the LAST face groove (omit for one; diameter in diameter mode)"),
        ("Z", "groove bottom Z (absolute or incremental)"),
        ("I", "distance between grooves along X, per side"),
        ("K", "infeed per peck along Z"),
        ("F", "feed for the infeeds (optional)"),
        ("D", "rapid shift along X at full depth (signed, per side; required, 0 = none)"),
    )
    AXIS: ClassVar[str] = "Z"
    BOTTOM: ClassVar[tuple] = ("Z",)
    LAST: ClassVar[tuple] = ("X",)
    PECK: ClassVar[str] = "K"
    PITCH: ClassVar[str] = "I"
    RELIEF: ClassVar[str] = "D"
