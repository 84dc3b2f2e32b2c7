"""The geometry of a CYCLE93 groove and its expansion into moves.

``GrooveGeometry`` is built from a validated call (``cycle93.Cycle93``): the
groove frame, the final and roughing profiles with their corners, the exact
envelope of where the blade may go, and the Siemens manual's four machining
steps as moves of the blade's reference corner. The module notes of
``cycle93`` say how the Siemens manual is read.
"""

import math
from operator import itemgetter
from typing import TYPE_CHECKING, List, Optional, Tuple

from ..envelope import Envelope, Turn
from ..moves import FEED, RAPID, REFERENCE_PLUS, Move, arc
from ..numbers import MAX_DWELL_SECONDS, MAX_WORD, format_given, format_value
from ..settings import Settings
from .cycle93_constants import (
    ALARM_FORM,
    ALARM_WIDTH,
    DEFAULT_VRT_INCH,
    DEFAULT_VRT_MM,
    EPS,
    LENGTH_PARAMS,
    MAX_FLANK_ANGLE,
    NAME,
    OVERHANG_GAIN,
    PATH_TOLERANCE,
    cycle93_error,
)
from .cycle93_material import MaterialTop
from .cycle93_passes import feed_where_material
from .cycle93_plunges import plunges
from .cycle93_profile import FOLD_TOLERANCE, Corner, Frame, intersect, split_at, unit, without_float_folds
from .cycle93_size import ExpansionSize, plunge_count
from .cycle93_warnings import NoRoom, no_room

if TYPE_CHECKING:  # the model imports this module
    from .cycle93 import Cycle93

Point = Tuple[float, float]

__all__ = ["Frame", "GrooveGeometry", "split_at"]

_new_move = tuple.__new__
_MOVE_DEFAULTS = tuple(Move._field_defaults[name] for name in Move._fields[3:])  # f, p, y, c, centre, radius


class GrooveGeometry:
    """A validated CYCLE93 groove: its frame, final and roughing profiles and
    the expansion into moves."""

    def __init__(self, call: "Cycle93", settings: Settings, metric: bool = True) -> None:
        self.call = call
        self.settings = settings
        self.metric = metric
        self.roughs_to_final = False  # the allowances leave no room: roughing runs on the final profile
        self.no_room: Optional[NoRoom] = None  # why (only when there are allowances to blame)
        if settings.tool is None:
            raise cycle93_error("tool width", None, "the blade is unknown: give it as Settings.tool")
        if not settings.tool.width > 0:
            raise cycle93_error(
                "tool width",
                settings.tool.width,
                "cutting edge width must be greater than 0",
                ALARM_WIDTH,
            )
        tool = settings.tool.validate(NAME)
        self.tool = tool
        longitudinal, external, left, chr_mode = call.kind()
        self.longitudinal, self.external, self.left = longitudinal, external, left
        self.chr_mode = chr_mode
        p = self._read_parameters(call, settings, metric)
        self.params = p
        su = 1.0 if left else -1.0
        sv = 1.0 if external else -1.0
        self.frame = Frame(p["AXFA"], p["AXSA"], longitudinal, su, sv, tool.width, tool.reference == REFERENCE_PLUS)
        self.slope = self._contour_slope(p["ANGC"], su, sv)
        self._build(p)

    # -- parameters ---------------------------------------------------------
    @staticmethod
    def _read_parameters(call, settings, metric):
        p = {}
        for name in ("AXFA", "AXSA", "WIDG", "DEPG"):
            v = getattr(call, name.lower())
            if v is None:
                raise cycle93_error(name, None, "must be programmed")
            p[name] = float(v)
        for name in ("ANGC", "ANG1", "ANG2", "RCO1", "RCO2", "RCI1", "RCI2", "FAL1", "FAL2", "DWT", "VRT"):
            p[name] = float(call.value(name))
        if call.idep is None:
            raise cycle93_error("IDEP", None, "must be programmed in all cases")
        p["IDEP"] = float(call.idep)
        for name in LENGTH_PARAMS:
            if not abs(p[name]) < MAX_WORD:
                raise cycle93_error(name, getattr(call, name.lower()),
                                    "must be less than %d in magnitude, like every coordinate written" % MAX_WORD)
        longitudinal = call.kind()[0]
        if settings.cycle93_diameter_input:
            p["AXFA"] /= 2
            if longitudinal:
                p["DEPG"] /= 2
                p["FAL1"] /= 2
            else:
                p["FAL2"] /= 2
        GrooveGeometry._check_parameters(call, settings, p)
        if p["VRT"] == 0:
            p["VRT"] = DEFAULT_VRT_MM if metric else DEFAULT_VRT_INCH
        return p

    @staticmethod
    def _check_parameters(call, settings, p):
        """The Siemens manual's rules on single parameters (p: read, in radius values)."""
        if p["WIDG"] < 0:
            raise cycle93_error("WIDG", call.widg, "must be entered without sign")
        if p["WIDG"] < settings.tool.width - EPS:
            raise cycle93_error(
                "WIDG",
                call.widg,
                "groove is narrower than the tool width %s" % format_given(settings.tool.width),
                ALARM_WIDTH,
            )
        if p["DEPG"] <= 0:
            raise cycle93_error("DEPG", call.depg, "must be greater than 0 (enter without sign)")
        if not 0 <= p["ANGC"] <= 180:
            raise cycle93_error("ANGC", call.angc, "must be in the range 0 <= ANGC <= 180 degrees")
        for name in ("ANG1", "ANG2"):
            if not 0 <= p[name] < MAX_FLANK_ANGLE:
                raise cycle93_error(
                    name,
                    getattr(call, name.lower()),
                    "must be in the range 0 <= %s < 89.999 degrees" % name,
                )
        if p["IDEP"] <= 0:
            raise cycle93_error("IDEP", call.idep, "must be greater than 0 (enter without sign)")
        for name in ("FAL1", "FAL2", "DWT", "VRT"):
            if p[name] < 0:
                raise cycle93_error(name, getattr(call, name.lower()), "must not be negative (enter without sign)")
        if p["DWT"] > MAX_DWELL_SECONDS:  # one bound for every output: native calls, expansions, the posts, the op
            raise cycle93_error("DWT", call.dwt, "the dwell must be 0 to %s s, the longest every target writes"
                                % format_given(MAX_DWELL_SECONDS))
        if p["FAL1"] >= p["DEPG"]:
            raise cycle93_error(
                "FAL1",
                call.fal1,
                "base allowance must be less than the groove depth DEPG %s" % format_given(call.depg),
            )
        if 2 * p["FAL2"] >= p["WIDG"]:
            raise cycle93_error(
                "FAL2",
                call.fal2,
                "two flank allowances must be less than the groove width WIDG %s" % format_given(call.widg),
            )

    def _contour_slope(self, angc, su, sv):
        a = math.radians(angc)
        if self.longitudinal:
            c = math.cos(a)
            if abs(c) < 1e-9:
                rule = "a longitudinal groove needs a contour that is not perpendicular to the longitudinal axis"
                raise cycle93_error("ANGC", angc, rule, ALARM_FORM)
            slope = su * sv * math.tan(a)
        else:
            s = math.sin(a)
            if abs(s) < 1e-9:
                rule = "face groove on a contour element parallel to the longitudinal axis"
                raise cycle93_error("ANGC", angc, rule, ALARM_FORM)
            slope = su * sv * math.cos(a) / s
        if abs(slope) < 1e-12:
            slope = 0.0  # cos(90 degrees) is 6e-17 in floating point: keep faces exactly square
        tilt = math.degrees(math.atan(abs(slope)))
        limit = self.settings.cycle93_max_contour_tilt
        if limit is not None and tilt > limit + 1e-9:
            axis = "longitudinal" if self.longitudinal else "facing"
            raise cycle93_error(
                "ANGC", angc,
                "contour is %.3f degrees off the %s axis; the shop limit is %g "
                "(setting cycle93_max_contour_tilt)"
                % (tilt, axis, limit),
            )
        return slope

    # -- profile ------------------------------------------------------------
    def _build(self, p):
        m = self.slope
        depth, width = p["DEPG"], p["WIDG"]
        t1, t2 = math.tan(math.radians(p["ANG1"])), math.tan(math.radians(p["ANG2"]))
        contour_dir = (1.0, m)
        d1 = (t1, -1.0)  # flank 1, going down into the groove
        d2 = (t2, 1.0)  # flank 2, going up out of it
        if 1 + m * t1 <= 1e-9:
            raise cycle93_error(
                "ANG1",
                p["ANG1"],
                "flank 1 does not reach the groove base on this contour (ANGC %s)" % format_value(p["ANGC"]),
                ALARM_FORM,
            )
        if 1 - m * t2 <= 1e-9:
            raise cycle93_error(
                "ANG2",
                p["ANG2"],
                "flank 2 does not reach the groove base on this contour (ANGC %s)" % format_value(p["ANGC"]),
                ALARM_FORM,
            )
        p1 = (0.0, 0.0)
        b1 = intersect(p1, d1, (0.0, -depth), contour_dir)
        b2 = (b1[0] + width, b1[1] + m * width)
        p2 = intersect(b2, d2, p1, contour_dir)
        self.corners_sharp = (p1, b1, b2, p2)
        chr_mode = self.chr_mode
        final = [
            Corner(p1, contour_dir, d1, p["RCO1"], chr_mode),
            Corner(b1, d1, contour_dir, p["RCI1"], chr_mode),
            Corner(b2, contour_dir, d2, p["RCI2"], chr_mode),
            Corner(p2, d2, contour_dir, p["RCO2"], chr_mode),
        ]
        self._check_form(final, (p1, b1, b2, p2), p)
        self.final_corners = final
        self.rough_corners = self._rough_corners(p, final, (p1, b1, b2, p2), (t1, t2))
        # Counted before a single arc is traced: a call beyond MAX_MOVES stops here.
        self.size = ExpansionSize(self)
        self.size.check()
        self.final_top = self._material_top(final)
        self.rough_top = self._material_top(self.rough_corners)
        for top in (self.final_top, self.rough_top):
            us = list(map(itemgetter(0), top))  # u never stepping back: no fold, nothing to test point by point
            if us != sorted(us) and any(b[0] < a[0] - FOLD_TOLERANCE for a, b in zip(top, top[1:])):
                raise cycle93_error("call", None, "groove form wrong: the profile folds back on itself", ALARM_FORM)
        self.final_env = self._envelope(final, self.final_top)
        self.rough_env = self._envelope(self.rough_corners, self.rough_top)

    def _rough_corners(self, p, final, sharp, tangents):
        """The roughing profile: flanks moved in by FAL2 (normal), base up by FAL1."""
        m = self.slope
        depth = p["DEPG"]
        p1, _b1, b2, p2 = sharp
        t1, t2 = tangents
        contour_dir = (1.0, m)
        d1 = (t1, -1.0)
        d2 = (t2, 1.0)
        chr_mode = self.chr_mode
        fal1, fal2 = p["FAL1"], p["FAL2"]
        n1 = unit(1.0, t1)
        n2 = unit(-1.0, t2)
        q1 = (p1[0] + fal2 * n1[0], p1[1] + fal2 * n1[1])
        q2 = (b2[0] + fal2 * n2[0], b2[1] + fal2 * n2[1])
        base_r = (0.0, -depth + fal1)
        r1 = intersect(q1, d1, (0.0, 0.0), contour_dir)
        rb1 = intersect(q1, d1, base_r, contour_dir)
        rb2 = intersect(q2, d2, base_r, contour_dir)
        r2 = intersect(q2, d2, (0.0, 0.0), contour_dir)
        rough = [
            Corner(r1, contour_dir, d1, 0.0, chr_mode),
            Corner(rb1, d1, contour_dir, p["RCI1"], chr_mode),
            Corner(rb2, contour_dir, d2, p["RCI2"], chr_mode),
            Corner(r2, d2, contour_dir, 0.0, chr_mode),
        ]
        # When the allowances leave no room for the blade, rough to the final
        # profile (without its edge features) rather than not at all, and say why.
        units = "mm" if self.metric else "in"
        reason = no_room(self.tool.width, m, rough, (r1, rb1, rb2, r2), units)
        self.no_room = reason if fal1 > 0 or fal2 > 0 else None
        self.roughs_to_final = reason is not None
        if reason is not None:
            rough = [Corner(p1, contour_dir, d1, 0.0, chr_mode)] + final[1:3] + [Corner(p2, d2, contour_dir, 0.0,
                                                                                         chr_mode)]
        return rough

    def _check_form(self, corners, sharp, p):
        c_p1, c_b1, c_b2, c_p2 = corners
        p1, b1, b2, p2 = sharp
        base_len = math.dist(b1, b2)
        if c_b1.length + c_b2.length >= base_len - 1e-9 and (c_b1.length > 0 or c_b2.length > 0):
            raise cycle93_error(
                "RCI1/RCI2", (p["RCI1"], p["RCI2"]),
                "radii/chamfers at the groove base touch or intersect (they need %s of the %s base)"
                % (format_value(c_b1.length + c_b2.length), format_value(base_len)),
                ALARM_FORM,
            )
        for name, outer, inner, top, bottom in (
            ("1", c_p1, c_b1, p1, b1),
            ("2", c_p2, c_b2, p2, b2),
        ):
            flank = math.dist(top, bottom)
            if outer.length + inner.length > flank + 1e-9:
                raise cycle93_error(
                    "RCO%s/RCI%s" % (name, name), (p["RCO" + name], p["RCI" + name]),
                    "radius/chamfer at the edge and at the base of flank %s overlap (they need %s of the %s flank)"
                    % (name, format_value(outer.length + inner.length), format_value(flank)),
                    ALARM_FORM,
                )

    def _envelope(self, corners, top):
        """Where the blade may go over the profile of ``corners``, its arcs
        staying arcs: the vertices where one element meets the next (with the
        contour's ends of ``top``, the polyline of ``_material_top``) and the
        arcs between them (keyed by the index of their first vertex)."""
        points = [top[0]]
        arcs = {}
        for c in corners:
            ends, arc = c.element()
            if arc is not None:
                arcs[len(points)] = arc
            points.extend(ends)
        points.append(top[-1])
        return Envelope(without_float_folds(points), self.tool.width, self.tool.corner_radius, arcs)

    def _material_top(self, corners):
        pts = []
        for c in corners:
            pts.extend(c.points())
        m = self.slope
        reach = self.tool.width + self.params["VRT"] + 1.0
        lo, hi = pts[0][0] - reach, pts[-1][0] + reach
        return [(lo, m * lo)] + without_float_folds(pts) + [(hi, m * hi)]

    # -- derived quantities -------------------------------------------------
    def opening(self, top: List[Point]) -> Point:
        """u of the first and last point where the profile leaves the contour."""
        return top[1][0], top[-2][0]

    def contour_top(self, u: float) -> float:
        """Highest contour level under the blade at u."""
        m = self.slope
        return max(m * u, m * (u + self.tool.width))

    def clearance(self, u: float) -> float:
        """The level VRT above the contour under the blade at u."""
        return self.contour_top(u) + self.params["VRT"]

    def region_uv(self, tol: Optional[float] = None) -> List[Point]:
        """The finished groove region (closed polygon, groove frame), its arcs
        chorded toward more material within ``tol`` (None: PATH_TOLERANCE, in
        the program's units)."""
        if tol is None:
            top = self.final_top[1:-1]
        else:
            top = without_float_folds([p for c in self.final_corners for p in c.points(tol)])
        return top + [top[0]]

    def region_world(self, tol: Optional[float] = None) -> List[Point]:
        """The finished groove region as world (x, z) points (``tol``: see region_uv)."""
        return [self.frame.point(u, v) for u, v in self.region_uv(tol)]

    def stock_world(self, margin: Optional[float] = None) -> List[Point]:
        """A window of the part's material around the groove, world (x, z):
        everything below the contour line, for simulation."""
        m = self.slope
        lo, hi = self.final_top[0][0], self.final_top[-1][0]
        if margin is not None:
            lo, hi = self.final_top[1][0] - margin, self.final_top[-2][0] + margin
        bottom = min(v for _u, v in self.final_top) - 2 * self.tool.width - 1.0
        pts = [(lo, m * lo), (hi, m * hi), (hi, bottom), (lo, bottom)]
        return [self.frame.point(u, v) for u, v in pts]

    def pass_range(self, env: Envelope, top: List[Point], flat: bool = False) -> Point:
        """Blade positions (minus edge) the contour passes over ``top`` start
        from: the opening's left edge - r and right edge - w + r (the flat
        front reaches both flanks). On an oblique contour the pass from the
        opening's lower edge may start further out, overhanging it: a paraxial
        blade goes wherever it does not cut the part, and beyond that edge the
        contour falls away. Out to the first position where the blade stands
        lowest while its flat front is over the edge (with ``flat``: where the
        plunges end); then, where that is lower than the flanks let it go or
        the edge is rounded or chamfered, on to where the blade leaves the
        opening (its rounded corner reaches under the edge's radius, or
        chamfer, there). A sharp edge the blade rests on keeps it no lower."""
        r, w = self.tool.corner_radius, self.tool.width
        left, right = self.opening(top)
        ua, ub = left - r, right - w + r
        if self.slope == 0:
            return ua, ub
        lower_left = self.slope > 0
        start, end = (ua, left - w + r) if lower_left else (ub, right - r)
        out = env.deepest(start, end, OVERHANG_GAIN)
        corners = self.final_corners if top is self.final_top else self.rough_corners
        if not flat and (out != start or corners[0 if lower_left else 3].value != 0):
            out = left - w if lower_left else right
        return (out, ub) if lower_left else (ua, out)

    def plunge_positions(self) -> List[float]:
        """u of the roughing plunges, from the start side, equally spaced:
        from flank to flank, or out to where the roughing passes overhang
        the opening's lower edge (``pass_range``)."""
        lo, hi = self.opening(self.rough_top)
        tool = self.tool
        w, r = tool.width, tool.corner_radius
        hi -= w
        if self.slope != 0:
            ua, ub = self.pass_range(self.rough_env, self.rough_top, flat=True)
            lo, hi = min(lo, ua) if ua < lo - r else lo, max(hi, ub) if ub > hi + r else hi
        count = int(plunge_count(lo, hi + w, w, r))
        if count == 1:
            return [0.5 * (lo + hi)]
        n = count - 1
        return [lo + (hi - lo) * k / n for k in range(n + 1)]

    # -- moves --------------------------------------------------------------
    def expand(self, x_start: float, z_start: float) -> List[Move]:
        """Moves from the reference-corner position (x_start radius, z_start)."""
        frame = self.frame
        blade = frame.blade
        out = []
        last = [None]

        def go(kind: str, u: float, v: float, turn: Turn = None) -> None:
            """A rapid ("r") or feed ("f") of the blade to (u, v); a feed along a
            circle of the groove frame with ``turn`` (its centre, counter-clockwise)."""
            x, z = blade(u, v)
            if turn is None:  # Move(RAPID or FEED, x, z), without its __new__'s frame (a move per point of a pass)
                move = _new_move(Move, (RAPID if kind == "r" else FEED, x, z) + _MOVE_DEFAULTS)
            else:
                move = arc(frame.clockwise(turn[2]), x, z, blade(turn[0], turn[1]))
            if not out or out[-1] != move:
                out.append(move)
            last[0] = u

        us, vs = frame.blade_of(x_start, z_start)
        positions = self.plunge_positions()
        u_first = positions[0]
        along_first = self.longitudinal == self.external  # the Siemens manual: external grooves move along Z first
        approach = self._approach(us, vs, u_first, along_first)
        for u, v in approach:
            go("r", u, v)

        material = MaterialTop(self.final_top[0][0], self.final_top[-1][0], self.slope)
        plunges(self, positions, go, out, material)
        self._profile_passes(go, material, positions)

        # Back to the start point the way the approach came.
        for u, v in self._retreat(us, vs, last[0], along_first):
            go("r", u, v)
        return out

    def _profile_passes(self, go, material, steps):
        """Step 3: take the plunges' staircase off flanks, base corners and an
        oblique base; step 4: finishing on the final profile, unless the
        roughing already ran on it (no allowances, no edge features). Both
        feed only where material remains (``material``), one move per width
        step at most (split at the plunge positions ``steps``)."""
        p = self.params
        staircase = p["ANG1"] > 0 or p["ANG2"] > 0 or p["RCI1"] != 0 or p["RCI2"] != 0 or self.slope != 0
        if staircase:
            self._contour_passes(self.rough_env, self.rough_top, go, material, steps)
        if self.rough_top != self.final_top:
            self._contour_passes(self.final_env, self.final_top, go, material, steps)

    def _contour_passes(self, env, top, go, material, steps):
        """From each edge of the opening toward the middle along the envelope."""
        r, w = self.tool.corner_radius, self.tool.width
        left, right = self.opening(top)
        mid = 0.5 * (left - r + right - w + r)
        # Past an edge the stretches also part where the flat front leaves the opening and where it stands
        # lowest over the edge: each is fed only if it cuts (out there mostly air).
        steps = sorted(set(steps).union((left - w + r, right - r), self.pass_range(env, top, flat=True)))
        for start in self.pass_range(env, top):
            chorded, vertices, written = env.trace_and_path(start, mid, PATH_TOLERANCE)  # one walk: both
            exact = vertices if written else None
            pts = split_at(chorded, steps)
            feed_where_material(self, pts, go, material, steps, top, env, top is self.rough_top, exact, vertices)

    def _leg_clear(self, u_from, u_to, level):
        """True when a blade moving along u at ``level`` stays above the contour."""
        lo, hi = min(u_from, u_to), max(u_from, u_to)
        return level >= max(self.contour_top(lo), self.contour_top(hi)) - 1e-9

    def _approach(self, us, vs, u_first, along_first):
        if not self._leg_clear(us, us, vs):
            x, z = self.frame.blade(us, vs)
            raise cycle93_error(
                "start point", None,
                "X%s Z%s (radius X) is inside the part: the tool must stand outside the contour before the call"
                % (format_value(x), format_value(z)),
            )
        clear = self.clearance(u_first)
        if along_first:
            if not self._leg_clear(us, u_first, vs):
                x, z = self.frame.blade(us, vs)
                raise cycle93_error(
                    "start point", None,
                    "X%s Z%s (radius X): moving from it to the groove along the %s axis would cut the part"
                    % (format_value(x), format_value(z), "longitudinal" if self.longitudinal else "facing"),
                )
            return [(u_first, vs), (u_first, clear)]
        level = max(clear, max(self.contour_top(us), self.contour_top(u_first)) + self.params["VRT"])
        legs = [(us, level), (u_first, level)]
        if level > clear:
            legs.append((u_first, clear))
        return legs

    def _retreat(self, us, vs, u_last, along_first):
        if along_first:
            if self._leg_clear(u_last, us, vs):
                return [(u_last, vs), (us, vs)]
            level = max(self.contour_top(us), self.contour_top(u_last)) + self.params["VRT"]
            return [(u_last, level), (us, level), (us, vs)]
        level = max(self.clearance(u_last), max(self.contour_top(us), self.contour_top(u_last)) + self.params["VRT"])
        return [(u_last, level), (us, level), (us, vs)]
