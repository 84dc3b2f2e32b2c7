"""Which cycle calls each target writes natively, read from the targets'
tables and the cycle registry: the command line's ``--native-cycles`` help."""

from typing import Dict, List, Tuple

from ..cycles.pecking import PeckingCycle
from ..output.syntax import Target
from ..output.targets import TARGETS
from ..registry import cycles_of

__all__ = ["native_pairs"]

PECKING_DIALECTS = ("ab9", "fanuc", "gsk", "haas")  # the dialects whose programs call pecking cycles


def _pecking_codes(dialect: str) -> Tuple[str, Tuple[type, ...]]:
    """The pecking cycles of a dialect's programs: their codes ("G77/G76") and classes."""
    entries = [e for e in cycles_of(dialect) if issubclass(e.cycle_class, PeckingCycle)]
    return "/".join(e.name for e in entries), tuple(e.cycle_class for e in entries)


def _pecking_sources(target: Target) -> Tuple[List[str], List[str]]:
    """The dialects whose pecking calls are the target's own cycles, and the others ("G75/G74 (fanuc, gsk)")."""
    own_classes = set(_pecking_codes(target.native.dialect)[1])
    own: List[str] = []
    other: Dict[Tuple[type, ...], List[str]] = {}
    codes = {}
    for dialect in PECKING_DIALECTS:
        code, classes = _pecking_codes(dialect)
        if set(classes) == own_classes:
            own.append(dialect)
        else:
            other.setdefault(classes, []).append(dialect)
            codes[classes] = code
    return own, ["%s (%s)" % (codes[classes], ", ".join(dialects)) for classes, dialects in other.items()]


def _target_pairs(target: Target) -> List[str]:
    native = target.native
    parts = []
    if native.grooves == "cycle93":
        parts.append("CYCLE93; G77/G76, G75/G74 calls of one groove cut in one peck, where CYCLE93 cuts the same "
                     "moves")
    elif native.grooves == "pecking":
        own, other = _pecking_sources(target)
        parts.append("%s/%s of %s programs; plain CYCLE93 grooves (as the lathe posts write them); %s where "
                     "they cut the same moves" % (native.longitudinal, native.face, " and ".join(own),
                                                   ", ".join(other)))
    if native.slots:
        parts.append("G7.1 regions")
    if native.grinds:
        parts.append("G83/G83.1")
    if native.mill:
        parts.append("G31-G34 (G33/G34 with the D register programmed)")
    return parts


def native_pairs() -> Dict[str, str]:
    """Target name -> what it writes natively (targets without native cycles left out)."""
    pairs = {}
    for name, target in TARGETS.items():
        parts = _target_pairs(target)
        if parts:
            pairs[name] = "; ".join(parts)
    return pairs
