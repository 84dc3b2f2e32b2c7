"""The lathe posts: each one (:class:`LathePost`) a target of the engine's
output layer (``engine/output/targets.py``: its whole syntax) under the post's name.

Nothing here writes a word: what a post says about itself (its tooltip, the
help of its options, which options it takes) is derived from its target's
table, and the program is written by the engine's writer and program builder.
A post stub ``postprocessors/<name>_lathe_post.py`` names its lathe post
(``LATHE_POST = "<name>"``, a key of ``LATHE_POST_TARGETS``); any lathe target
of the engine can have one.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Dict, Optional

from ...engine.output.syntax import Target
from ...engine.output.targets import LATHE_TARGETS, TARGETS, with_g07_meaning
from ...engine.registry import cycle_for

if TYPE_CHECKING:
    from .options import Options

# What a post writes a groove as, when it writes it natively.
NATIVE_CYCLE93 = "cycle93"  # Siemens CYCLE93, every groove
NATIVE_PECKING = "pecking"  # a pecking cycle (G77/G76, G75/G74), plain grooves only

# The lathe posts: the stub's LATHE_POST -> its target (LinuxCNC's post writes the C axis of a Cylinder slot).
LATHE_POST_TARGETS = {"sinumerik": "sinumerik", "ab9": "ab9", "fanuc": "fanuc", "haas": "haas", "gsk": "gsk",
               "linuxcnc": "linuxcnc-c"}


class LathePost:
    """One lathe post: its target and what the post says of it."""

    def __init__(self, name: str, target: Target) -> None:
        self.target = target
        self.name = name  # the post stub's LATHE_POST: "gsk"
        self.freecad_name = name + "_lathe"  # its name in FreeCAD (a Job's PostProcessor; the stub's file less _post)
        self.title = target.title

    @property
    def native(self) -> Optional[str]:
        """NATIVE_CYCLE93, NATIVE_PECKING or None (grooves always expanded)."""
        return self.target.native.grooves or None

    @property
    def digits(self) -> int:
        """Decimals of coordinates in mm (--precision's default; inch: one more)."""
        return self.target.digits_mm

    @property
    def has_x_mode(self) -> bool:
        """Whether the post takes --x-mode (X words as diameters or radii)."""
        return bool(self.target.x_mode_codes[0])

    @property
    def x_mode_codes(self) -> str:
        return "/".join(self.target.x_mode_codes)

    @property
    def x_words(self) -> str:
        """How the tooltip says X is written."""
        code = self.target.x_mode_codes[0]
        return "a diameter, %s" % code if code else "a diameter"

    @property
    def expand_help_note(self) -> str:
        """What --expand-cycles' help adds."""
        return "" if self.native else "; the default: %s has no grooving cycle" % self.target.maker

    @property
    def g07_radius_option(self) -> bool:
        """--g07-radius: G07 may select radius mode on this target (Allen-Bradley)."""
        return self.target.x_mode_codes == ("G07", "G08")

    @property
    def o_number_frame(self) -> bool:
        """"%" lines around the program and an O number (--program-number)."""
        return bool(self.target.program_number)

    @property
    def c_feed(self) -> Optional[str]:
        """Whether (and how) the target writes the C axis of a Cylinder slot."""
        return self.target.c_feed

    @property
    def native_slot(self) -> bool:
        """A Cylinder slot op as a native GSK G7.1 Type II region (--native-cycles)."""
        return self.target.native.slots

    # -- the pecking cycles
    @property
    def cycle_dialect(self) -> str:
        """The engine's dialect whose registered cycles the post writes."""
        return self.target.native.dialect

    @property
    def longitudinal_cycle(self) -> str:
        return self.target.native.longitudinal

    @property
    def face_cycle(self) -> str:
        return self.target.native.face

    @property
    def retract_word(self) -> Optional[str]:
        """The cycle word holding the peck retract e (Fanuc's first-block R), or None."""
        return self.target.native.retract_word or None

    @property
    def retract_setting(self) -> Optional[str]:
        """Where the control keeps e otherwise (named in a comment), or None."""
        return self.target.native.retract_setting or None

    @property
    def least_input_increment(self) -> float:
        """mm: counted words (Fanuc P/Q) are whole multiples of it."""
        return 10.0 ** -self.target.digits_mm

    @property
    def least_input_increment_inch(self) -> float:
        return 10.0 ** -self.target.digits_inch

    @property
    def pecking_codes(self) -> str:
        """Both cycle codes, for help texts ("G77/G76")."""
        return "%s/%s" % (self.longitudinal_cycle, self.face_cycle)

    def pecking_cycle(self, longitudinal: bool) -> type:
        """The engine's cycle class the post writes for a longitudinal or a face groove."""
        return cycle_for(self.cycle_dialect, self.longitudinal_cycle if longitudinal else self.face_cycle)

    # -- help texts
    def grooves_summary(self) -> str:
        """How the post writes grooves, for its tooltip."""
        if self.native == NATIVE_CYCLE93:
            return "grooves as native CYCLE93 calls"
        if self.native == NATIVE_PECKING:
            return "plain grooves as native %s calls, others expanded" % self.pecking_codes
        return "grooves expanded into G0/G1 moves and G2/G3 arcs"

    def retract_help(self) -> str:
        """How --retract reaches the control, for its help."""
        if self.retract_word:
            return "written as %s R(%s)" % (self.longitudinal_cycle, self.retract_word)
        return "a machine setting on this control, stated in a comment"

    def units(self, inches: bool) -> str:
        """The code of metric or inch lengths and feeds."""
        return self.target.units_codes[1 if inches else 0]

    def program_target(self, options: Options) -> Target:
        """The target the program is written for with ``options``: the Allen-Bradley
        G07/G08 swapped with --g07-radius."""
        return with_g07_meaning(self.target, options.g07_is_diameter)


LATHE_POSTS: Dict[str, LathePost] = {name: LathePost(name, TARGETS[target])
                                     for name, target in LATHE_POST_TARGETS.items()}


def lathe_post_named(name: str) -> LathePost:
    """The lathe post ``name`` (a key of LATHE_POSTS, or any other lathe target); ValueError when unknown."""
    if name not in LATHE_POSTS and name in LATHE_TARGETS:
        LATHE_POSTS[name] = LathePost(name, TARGETS[name])
    try:
        return LATHE_POSTS[name]
    except KeyError:
        raise ValueError("unknown control %r (known: %s)" % (name, ", ".join(LATHE_POSTS))) from None
