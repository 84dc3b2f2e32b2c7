"""Motion blocks of the translator: the motion mode, the end point from
X/U/Z/W, arc words and the checks on arcs and feed moves."""

import math
from typing import List, NamedTuple, Optional, Set

from .dialects import MOTION
from .moves import ARCS, FEED, RAPID, Move
from .numbers import ARC_IJK_TOLERANCE, ARC_R_TOLERANCE, MM_PER_INCH
from .output.targets import TARGETS
from .reader import Block, Word
from .translate_base import Groups, TranslatorBase

__all__ = ["AxisTarget", "MotionTranslation"]

# Y only in mill-style programs; C: the rotary axis of the controls that read it (GSK), G0 only
_AXES = {"X", "Y", "Z", "U", "W", "C"}
_ARC_WORDS = {"I", "K", "R", "CR"}


class AxisTarget(NamedTuple):
    """A block's end point (x a radius) and which axes it wrote."""

    x: Optional[float]
    z: Optional[float]
    has_x: bool
    has_z: bool
    y: Optional[float] = None
    has_y: bool = False


class MotionTranslation(TranslatorBase):
    """G0/G1/G2/G3 and the axis words."""

    def _motion(self, block: Block, groups: Groups, output: List[str]) -> None:
        """Apply the block's motion code and move; add the output words."""
        state = self.state
        explicit = groups.get(MOTION)
        if explicit is not None:
            state.motion = explicit.value
            self._defined.add("motion")
        arc_letters = block.letters() & _ARC_WORDS
        if not block.letters() & _AXES:
            if arc_letters:
                self._fail("%s without an end point" % "/".join(sorted(arc_letters)))
            return
        kind = self._motion_kind(arc_letters)
        circle = self._arc_words(block, arc_letters) if kind in ARCS else {}
        if kind != RAPID:
            self._check_feed_move(block)
        target = self._axis_target(block)
        if circle:
            self._check_arc_start(block, target)
            if "centre" in circle:  # I and K from the start
                circle["centre"] = (state.x + circle["centre"][0], state.z + circle["centre"][1])
        c = None if block.get("C") is None else self._c_value(block.get("C"), kind)
        move = Move(kind, target.x if target.has_x else None, target.z if target.has_z else None,
                    y=target.y if target.has_y else None, c=c, **circle)
        output.extend(self.writer.programmed(move, explicit is not None))
        state.x, state.y, state.z = target.x, target.y, target.z
        self.writer.motion = kind

    def _c_value(self, word: Word, kind: str) -> float:
        """A C position outside a G7.1 region: rapid only, on a target that writes C."""
        if kind != RAPID:
            self._fail("C%s in a %s move: C is only fed inside a G7.1 region (position it with G0)"
                       % (word.text, kind))
        target = self.writer.target
        if not target.c_feed:
            self._fail("C%s: the output %s has no C axis (targets with C: %s)"
                       % (word.text, target.name, ", ".join(name for name, t in TARGETS.items() if t.c_feed)))
        value = self._finite_length(word)
        self.state.c = value
        self._defined.add("c")
        return value

    def _motion_kind(self, arc_letters: Set[str]) -> str:
        """The motion mode in force for a block with axis words."""
        if self.state.motion is None:
            self._fail("axis words without a motion mode in force: program G0 or G1")
        self._not_ambiguous("motion", why="the motion mode")
        kind = self.state.motion
        if kind in (RAPID, FEED) and arc_letters:
            self._fail("%s is only read with G2/G3" % "/".join(sorted(arc_letters)))
        return kind

    def _arc_words(self, block: Block, arc_letters: Set[str]) -> dict:
        """The arc's circle as Move fields: its centre from the start (I, K:
        incremental radius values; made absolute once the start is checked) or
        its radius (R, CR=)."""
        has_centre = bool(arc_letters & {"I", "K"})
        has_radius = bool(arc_letters & {"R", "CR"})
        if has_centre == has_radius:
            self._fail("G2/G3 needs either I/K (centre) or the radius (%s)" % self.dialect.arc_radius_word)
        radius_word = block.get("R") or block.get("CR")
        if radius_word is not None:
            radius = self._finite_length(radius_word)
            if not radius > 0:
                self._fail("%s%s: the arc radius must be positive (arcs over 180 degrees are not translated)"
                           % (radius_word.letter, radius_word.text))
            return {"radius": radius}
        return {"centre": tuple(0.0 if block.get(letter) is None else self._finite_length(block.get(letter))
                                for letter in "IK")}

    def _finite_length(self, word: Word) -> float:
        value = self._length(word)
        self._check_finite(value, word)
        return value

    def _check_feed_move(self, block: Block) -> None:
        """A feed move needs the feed mode, a feed rate and (per revolution) the spindle."""
        state = self.state
        if state.feed_per_rev is None:
            self._fail("feed move before the feed mode is programmed (%s)" % self.dialect.feed_mode_codes)
        self._not_ambiguous("feed_per_rev", why="the feed mode")
        if state.siemens_g70:
            self._fail("feed move in Siemens G70 (feed in the basic system): use G700")
        if state.feed is None:
            self._fail("feed move with no feed rate (F) in force")
        self._check_spindle_for_feed("feed move")
        if block.get("F") is None:
            self._not_ambiguous("feed", why="the feed rate")

    # -- end point --------------------------------------------------------------

    def _axis_target(self, block: Block) -> AxisTarget:
        """The block's end point from X/U/Z/W."""
        x_word, u_word, z_word, w_word = (block.get(letter) for letter in ("X", "U", "Z", "W"))
        if x_word is not None and u_word is not None:
            self._fail("X and U in one block")
        if z_word is not None and w_word is not None:
            self._fail("Z and W in one block")
        x = y = z = None
        y_word = block.get("Y")
        if y_word is not None:
            self._not_ambiguous("incremental", why="the Y word")
            y = self._axis_value("y", y_word, False)
        if x_word is not None or u_word is not None:
            self._not_ambiguous("diameter", "diam90", "incremental", why="the X word")
            x = self._axis_value("x", x_word or u_word, u_word is not None)
        if z_word is not None or w_word is not None:
            self._not_ambiguous("incremental", why="the Z word")
            z = self._axis_value("z", z_word or w_word, w_word is not None)
        return AxisTarget(self.state.x if x is None else x, self.state.z if z is None else z, x is not None,
                          z is not None, self.state.y if y is None else y, y is not None)

    def _axis_value(self, axis: str, word: Word, incremental_word: bool) -> float:
        """Where ``word`` puts ``axis`` ("x": a radius (mill style: plain), "y", "z")."""
        value = self._finite_length(word)
        if axis == "x" and self.state.x_words_diameter():
            value /= 2.0
        if not (incremental_word or self.state.incremental):
            self._defined.add(axis)
            return value
        position = getattr(self.state, axis)
        if position is None:
            self._fail("%s%s is incremental but the %s position is not known: program an absolute %s first"
                       % (word.letter, word.text, axis.upper(), axis.upper()))
        self._not_ambiguous(axis, why="the incremental %s word" % word.letter)
        return position + value

    # -- arcs ---------------------------------------------------------------------

    def _check_arc_start(self, block: Block, target: AxisTarget) -> None:
        state = self.state
        writer = self.writer
        if state.x is None or state.z is None:
            self._fail("G2/G3 needs a known start point: program an absolute X and Z before the arc")
        self._not_ambiguous("x", "z", why="the start of the arc")
        # checked on the numbers as written: what the output control will compute with
        self._check_arc(block, writer.written_x(state.x), float(writer.z_word(state.z)),
                        writer.written_x(target.x), float(writer.z_word(target.z)))

    def _check_arc(self, block: Block, x0: float, z0: float, x1: float, z1: float) -> None:
        """Refuse an arc whose end point is not on its circle (LinuxCNC would refuse it too).

        Tolerances (per side): I/K centre, the two radii differ by at most
        ARC_IJK_TOLERANCE; R, the chord is at most 2 R + ARC_R_TOLERANCE."""
        scale = 1.0 if self.state.metric else 1.0 / MM_PER_INCH
        radius_word = block.get("R") or block.get("CR")
        if radius_word is not None:
            radius = float(self.writer.length_word(radius_word.value))
            half = math.hypot(x1 - x0, z1 - z0) / 2.0
            if half == 0:
                self._fail("G2/G3 with %s: the end point is the start point (no circle is defined)"
                           % radius_word.letter)
            if half - radius > ARC_R_TOLERANCE * scale:
                self._fail("G2/G3: radius %s%s is too small to reach the end point (half the chord is %.4f)"
                           % (radius_word.letter, radius_word.text, half))
            return
        i = self._written_length(block.get("I"))
        k = self._written_length(block.get("K"))
        centre_x, centre_z = x0 + i, z0 + k
        start_radius = math.hypot(i, k)
        end_radius = math.hypot(x1 - centre_x, z1 - centre_z)
        if start_radius < ARC_IJK_TOLERANCE * scale:
            self._fail("G2/G3: zero radius (I and K put the centre on the start point)")
        if abs(start_radius - end_radius) > ARC_IJK_TOLERANCE * scale:
            self._fail("G2/G3: the end point is not on the circle: radius %.4f at the start, %.4f at the end "
                       "(I and K are radius values, incremental from the start)" % (start_radius, end_radius))

    def _written_length(self, word: Optional[Word]) -> float:
        """A length word's value as the output writes it (0 when not programmed)."""
        return float(self.writer.length_word(word.value)) if word is not None else 0.0
