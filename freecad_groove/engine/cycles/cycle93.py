"""Siemens CYCLE93: grooving on a straight contour element.

    CYCLE93(AXFA, AXSA, WIDG, DEPG, ANGC, ANG1, ANG2, RCO1, RCO2, RCI1, RCI2,
            FAL1, FAL2, IDEP, DWT, TYP, VRT [, DN])

(Siemens' own names: SPD, SPL, WIDG, DIAG, STA1, ANG1, ANG2, RCO1, RCO2, RCI1,
RCI2, FAL1, FAL2, IDEP, DTB, VARI, _VRT, _DN.)

Geometry, as this module reads the Siemens manual (choices marked *):
- The contour is the straight line through the start point (AXSA, AXFA) at
  ANGC to the longitudinal axis, ANGC measured counter-clockwise from +Z with
  X up (so ANGC = 12 on an external groove is a cone whose diameter grows
  toward +Z)*. The approach point X80 Z65 of the manual's example clears it.
- TYP units digit: 1 longitudinal/external/left, 2 face/external/left,
  3 longitudinal/internal/left, 4 face/internal/left, 5..8 the same "right".
  Longitudinal: external plunges -X, internal +X; "left" puts the start point
  on the groove's -Z edge (groove extends toward +Z), "right" on its +Z edge.
  Face*: external plunges -Z (a face looking toward +Z), internal +Z; axes
  swapped as for G76/G74: "left" extends the groove from AXFA toward +X,
  "right" toward -X.
- DEPG is the paraxial depth (along the plunge axis) from the contour to the
  groove base, which runs parallel to the contour. WIDG is the width of the
  base, measured along the groove's own axis (Z for longitudinal grooves), the
  width the tool width is checked against*. The start point is the top of the
  flank on the start side; flanks open outward by ANG1/ANG2 from the plunge
  direction.
- RCO1/RCO2 round (>0) or chamfer (<0) the part's edges at the top of the
  flanks, RCI1/RCI2 the corners at the base. Chamfers are CHF (length of the
  chamfer) for TYP 1..8 and CHR (leg along each element) for TYP 11..18.
- FAL1 is kept on the base (paraxially), FAL2 on the flanks (normal to them).
- AXFA, DEPG, FAL1 (longitudinal) and FAL2 (face) are radius values unless
  Settings.cycle93_diameter_input says the control reads them as diameters.

Expansion (the manual's four steps), driving the tool's reference corner:
1+2. Paraxial plunges across the opening, equally spaced at most 95 % of
  (tool width - 2 x corner radius) apart, from the start side*; each to the
  roughing profile (final profile less the allowances) in equal infeeds of at
  most IDEP (the first fed from 0.1 mm over the contour*), each followed by
  a rapid chip-breaking retract of VRT (0 = 1 mm) and a feed back in; a DWT
  dwell at the bottom of the plunges that reach the base (the manual: "dwell
  time at recess base"; not where a plunge stops on a flank or a base corner
  above the base); a rapid free-off of 1 mm* from the second plunge on; rapid
  retract to VRT above the contour.
  Traverses run VRT above the contour, parallel to it.
3. When flanks are angled, base corners rounded or the contour oblique, a
  contour-parallel pass on the roughing profile from each edge toward the
  groove removes the plunges' staircase.
4. Finishing passes on the final profile from each edge to the groove centre,
  already compensated for the corner radius (the path is the exact boundary
  of where the blade may go), when there is an allowance or an edge radius.
The cycle approaches along the longitudinal axis first for external grooves
(the facing axis for internal ones), and returns to its start point the
reverse way*.

Limits*: the length parameters are less than MAX_WORD (1000000) in magnitude,
like every written coordinate; a call whose expansion could hold more than
MAX_MOVES (1000000) moves is refused before it is expanded, naming WIDG, DEPG
or IDEP (``cycle93_size`` counts plunges, infeeds and contour points from the
parameters). Numbers*: Siemens reads the parameters as REAL (IEEE doubles), so
emit() writes each one exactly, as the shortest decimal that reads back as the
same double, without an exponent (Siemens writes exponents as EX).
"""

import math
import operator
import re
from dataclasses import dataclass, fields
from functools import lru_cache
from typing import ClassVar, List, Optional, Tuple

from ..blade_limits import BladeEntry, face_band, first_plunge
from ..cycle import Cycle
from ..moves import MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, MachineState, Move
from ..numbers import DIGITS_RULE, format_exact, format_value, shortened, too_many_digits
from ..registry import CALL, register
from ..settings import DEFAULT_SETTINGS, Settings
from ..warnings import CycleWarning
from .cycle93_constants import (  # noqa: F401 - the constants are part of this module's API
    ALARM_FORM,
    ALARM_TYP,
    ALARM_WIDTH,
    DEFAULT_VRT_INCH,
    DEFAULT_VRT_MM,
    MAX_FLANK_ANGLE,
    NAME,
    PARAMS,
    PATH_TOLERANCE,
    WIDTH_STEP_FACTOR,
    cycle93_error,
)
from .cycle93_geometry import GrooveGeometry
from .cycle93_shapes import forget_shapes
from .cycle93_shapes import geometry as shape_geometry
from .cycle93_warnings import cycle93_warnings


@register
@dataclass(frozen=True)
class Cycle93(Cycle):
    """One CYCLE93 call, its parameters as programmed (None = left empty)."""

    NAME: ClassVar[str] = NAME
    KEY: ClassVar[str] = "cycle93"
    DIALECTS: ClassVar[tuple] = ("sinumerik",)
    TITLE: ClassVar[str] = "Siemens CYCLE93 groove"
    FORM: ClassVar[str] = CALL
    NEEDS_BLADE: ClassVar[bool] = True  # the plunges are placed with the blade's width
    WORD_HELP: ClassVar[tuple] = (
        ("AXFA", "start point in the transverse axis X (radius value unless --diameter-input)"),
        ("AXSA", "start point in the longitudinal axis Z (absolute)"),
        ("WIDG", "groove width (without sign)"),
        ("DEPG", "groove depth (without sign; radius value unless --diameter-input)"),
        ("ANGC", "angle between the contour and the longitudinal axis, 0..180 degrees"),
        ("ANG1", "flank angle on the start point side, 0..<89.999 degrees"),
        ("ANG2", "flank angle on the other side, 0..<89.999 degrees"),
        ("RCO1", "outer edge on the start side: radius (positive) or chamfer (negative)"),
        ("RCO2", "outer edge on the other side: radius (positive) or chamfer (negative)"),
        ("RCI1", "groove base corner on the start side: radius (positive) or chamfer (negative)"),
        ("RCI2", "groove base corner on the other side: radius (positive) or chamfer (negative)"),
        ("FAL1", "finishing allowance on the groove base"),
        ("FAL2", "finishing allowance on the flanks"),
        ("IDEP", "infeed depth per plunge (required, without sign)"),
        ("DWT", "dwell at the groove base, seconds"),
        ("TYP", "machining type 1..8 / 11..18: 1 long. ext. left, 2 face ext. left, 3 long. int. left, "
         "4 face int. left, 5..8 the same on the right; +10 = chamfers as CHR"),
        ("VRT", "retraction distance from the contour (0 = 1 mm), also the chip-breaking retract"),
        ("DN", "D number of the second cutting edge (840D, optional)"),
    )

    axfa: Optional[float] = None
    axsa: Optional[float] = None
    widg: Optional[float] = None
    depg: Optional[float] = None
    angc: Optional[float] = None
    ang1: Optional[float] = None
    ang2: Optional[float] = None
    rco1: Optional[float] = None
    rco2: Optional[float] = None
    rci1: Optional[float] = None
    rci2: Optional[float] = None
    fal1: Optional[float] = None
    fal2: Optional[float] = None
    idep: Optional[float] = None
    dwt: Optional[float] = None
    typ: Optional[int] = None
    vrt: Optional[float] = None
    dn: Optional[int] = None

    # -- text ---------------------------------------------------------------
    def emit(self) -> str:
        """The call as the control reads it: every value exactly (the shortest
        decimal that reads back as the same double, no exponent), so
        ``parse(emit(m)) == m``."""
        values = _fields_of(self)
        if values[-1] is None:
            values = values[:-1]
        texts = _EXACT_TEXTS
        return "CYCLE93(%s)" % ", ".join("" if v is None else texts.get(v) or _exact_text(v) for v in values)

    @classmethod
    def parse(cls, text: str) -> "Cycle93":
        """The model of a call as written; raises CycleError naming the parameter."""
        m = re.search(r"CYCLE93\s*\((.*)\)", text, re.IGNORECASE)
        if not m:
            raise cycle93_error("call", text.strip(), "must read CYCLE93(AXFA, AXSA, ..., VRT)")
        args = [a.strip() for a in m.group(1).split(",")]
        if len(args) > len(PARAMS):
            raise cycle93_error("call", len(args), "takes at most %d parameters" % len(PARAMS))
        values = {}
        for name, arg in zip(PARAMS, args):
            if arg == "":
                continue
            if too_many_digits(arg):
                raise cycle93_error(name, shortened(arg), DIGITS_RULE)
            try:
                num = float(arg)
            except ValueError:
                raise cycle93_error(
                    name,
                    arg,
                    "must be a number (variables and expressions are not evaluated)",
                ) from None
            if not math.isfinite(num):
                raise cycle93_error(name, arg, "must be a finite number")
            if name in ("TYP", "DN"):
                if num != int(num):
                    raise cycle93_error(name, num, "must be a whole number")
                num = int(num)
            values[name.lower()] = num
        return cls(**values)

    # -- reading the parameters ---------------------------------------------
    def value(self, name: str, default: float = 0.0) -> float:
        """Parameter ``name`` ("WIDG"), ``default`` when left empty."""
        v = getattr(self, name.lower())
        return default if v is None else v

    def kind(self) -> Tuple[bool, bool, bool, bool]:
        """(longitudinal, external, left, chamfers_as_chr) from TYP."""
        typ = self.typ
        if typ is None or typ not in set(range(1, 9)) | set(range(11, 19)):
            raise cycle93_error("TYP", typ, "must be 1..8 or 11..18", ALARM_TYP)
        unit = typ % 10
        return unit in (1, 3, 5, 7), unit in (1, 2, 5, 6), unit <= 4, typ > 10

    def validate(self, settings: Settings = DEFAULT_SETTINGS, metric: bool = True) -> "Cycle93":
        """Check every rule (raises CycleError); returns self."""
        self.geometry(settings, metric)
        return self

    def plunge_direction(self) -> str:
        """MINUS_X, PLUS_X, MINUS_Z or PLUS_Z: the way the blade cuts (from TYP)."""
        longitudinal, external, _left, _chr = self.kind()
        if longitudinal:
            return MINUS_X if external else PLUS_X
        return MINUS_Z if external else PLUS_Z

    def geometry(self, settings: Settings = DEFAULT_SETTINGS, metric: bool = True) -> GrooveGeometry:
        """Validate and return the groove's GrooveGeometry: built once per
        (call, settings, metric) while it is among the last GEOMETRY_CACHE_SIZE
        used, so that validate(), expand() and warnings() of one call (the
        translator's sequence; the op's expansions from each candidate start)
        share it. Read it, never change it."""
        return _cached_geometry(self, settings, metric)

    # -- expansion ----------------------------------------------------------
    def expand(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[Move]:
        """The moves of the reference corner from ``state`` (x radius, z)."""
        geo = self.geometry(settings, state.metric)
        return geo.expand(state.x, state.z)

    def blade_depth(self, settings: Settings) -> Optional[Tuple[float, str]]:
        """DEPG as a radius (halved for a longitudinal groove in diameter input), for the blade's reach."""
        depth = float(self.depg) / (2 if settings.cycle93_diameter_input and self.kind()[0] else 1)
        return depth, "CYCLE93 DEPG=%s" % format_value(self.depg)

    def blade_entry(self, state: MachineState, settings: Settings, moves: List[Move]) -> Optional[BladeEntry]:
        """The diameters the first plunge spans (face grooves) or the bore at the groove's opening (internal
        longitudinal grooves: the region's smallest radius), as blade_limits reads them."""
        plunge = self.plunge_direction()
        first = first_plunge(moves)
        if plunge in (MINUS_Z, PLUS_Z) and first is not None and first.x is not None:
            low, high = face_band(settings.tool, float(first.x))
            return BladeEntry(plunge, low=low, high=high)
        if plunge == PLUS_X:
            region = self.geometry(settings, state.metric).region_world()
            return BladeEntry(plunge, bore=2 * min(float(x) for x, _z in region))
        return None

    def warnings(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[CycleWarning]:
        """What the expansion from ``state`` cannot do as programmed: allowances
        that leave the blade no room (roughing then runs on the final profile),
        material the blade cannot reach. On the geometry expand() just used."""
        return cycle93_warnings(self.geometry(settings, state.metric))


# A few geometries, not one per call of a program: memory stays flat however
# long the program (the command line streams it).
GEOMETRY_CACHE_SIZE = 16


@lru_cache(maxsize=GEOMETRY_CACHE_SIZE)
def _cached_geometry(call: Cycle93, settings: Settings, metric: bool) -> GrooveGeometry:
    return shape_geometry(call, settings, metric, GrooveGeometry)  # the shape's, placed (cycle93_shapes)


_clear_geometries = _cached_geometry.cache_clear


def _forget_geometries() -> None:
    """The geometry cache's cache_clear: also the shapes kept (the next geometry is built afresh)."""
    _clear_geometries()
    forget_shapes()


_cached_geometry.cache_clear = _forget_geometries  # type: ignore[method-assign]

# The call's parameters in order, read once: dataclasses.fields() on every emit() was a tenth of a post's time.
_FIELD_NAMES = tuple(f.name for f in fields(Cycle93))
_fields_of = operator.attrgetter(*_FIELD_NAMES)  # the parameters in the call's order, in one call

# format_exact's text of the parameter values met (a post writes each groove's call as a comment: the
# values repeat from call to call). A value is its own key: 5 and 5.0 are equal and written alike ("5"),
# as are 0.0 and -0.0 ("0"); NaN never reaches a call (validate) and would never be found.
_EXACT_TEXTS: dict = {}
EXACT_TEXTS_KEPT = 4096


def _exact_text(value: float) -> str:
    text = format_exact(value)
    if len(_EXACT_TEXTS) >= EXACT_TEXTS_KEPT:
        _EXACT_TEXTS.clear()
    _EXACT_TEXTS[value] = text
    return text
