"""A CYCLE93 pass split at the plunge positions, and parted into stretches there.

``split_at`` and ``_groups`` find the positions a trace crosses by position
(one bisection each) when the trace's u never turns back, the usual pass;
these tests hold them to the move-by-move definitions written out here, on
random traces going either way, with vertical steps, points at the positions
and exact paths along circles.
"""

import math
import random

from freecad_groove.engine.cycles.cycle93_passes import STEP_EPS, _groups
from freecad_groove.engine.cycles.cycle93_profile import split_at
from freecad_groove.engine.envelope import PathPoint
from freecad_groove.engine.envelope_curves import CUP, Curve


def split_by_moves(pts, positions):
    """Each move's crossings strictly inside it (by 1e-9), in the move's direction, on its line or circle."""
    positions = sorted(positions)
    out = [pts[0]]
    for start, end in zip(pts, pts[1:]):
        (u0, v0), (u1, v1) = start, end
        inside = [c for c in positions if min(u0, u1) + 1e-9 < c < max(u0, u1) - 1e-9]
        for c in (inside if u1 >= u0 else inside[::-1]):
            arc = getattr(end, "arc", None)
            if arc is None:
                v = v0 + (v1 - v0) * (c - u0) / (u1 - u0)
            else:
                v = arc.cv - math.sqrt(max(arc.size ** 2 - (c - arc.cu) ** 2, 0.0))
            out.append(PathPoint(c, v, arc) if isinstance(pts[0], PathPoint) else (c, v))
        out.append(end)
    return out


def groups_by_points(pts, steps):
    """Stretches bounded by the inner points within STEP_EPS of a step."""
    bounds = [0] + [k for k in range(1, len(pts) - 1)
                    if any(pts[k][0] - STEP_EPS <= s <= pts[k][0] + STEP_EPS for s in steps)] + [len(pts) - 1]
    return list(zip(bounds, bounds[1:])) if len(pts) > 1 else [(0, 0)]


def random_trace(rnd, steps, exact):
    """A trace by increasing u: random moves, some vertical, some ending on a step, some along a circle."""
    u, pts = rnd.uniform(-3, 0), []
    for _ in range(rnd.randint(1, 40)):
        pts.append((u, rnd.uniform(-5, 5)))
        u += rnd.choice([0.0, rnd.uniform(0, 2), rnd.uniform(0, 1e-8)])
        if rnd.random() < 0.2:
            u = rnd.choice(steps) + rnd.choice([0.0, 1e-10, -1e-10, 5e-10])
            u = max(u, pts[-1][0])
    if not exact:
        return pts
    out = [PathPoint(*pts[0])]
    for (u0, _v0), (u1, v1) in zip(pts, pts[1:]):
        if u1 - u0 > 0.5 and rnd.random() < 0.5:  # along a cup spanning the move
            cu, r = 0.5 * (u0 + u1), u1 - u0
            arc = Curve(cu - r, cu + r, CUP, cu, 1.0, r)
            out[-1] = PathPoint(out[-1][0], arc.cv - math.sqrt(r * r - (out[-1][0] - cu) ** 2), out[-1].arc)
            out.append(PathPoint(u1, arc.cv - math.sqrt(r * r - (u1 - cu) ** 2), arc))
        else:
            out.append(PathPoint(u1, v1))
    return out


def test_a_pass_either_way_is_split_where_a_move_crosses_a_position_as_move_by_move():
    rnd = random.Random(93)
    for _ in range(1500):
        steps = sorted(rnd.uniform(-2, 20) for _ in range(rnd.randint(0, 8)))
        steps += rnd.sample(steps, min(len(steps), rnd.randint(0, 1)))  # a position given twice
        pts = random_trace(rnd, steps or [0.0], rnd.random() < 0.4)
        if rnd.random() < 0.5:
            pts = pts[::-1] if not isinstance(pts[0], PathPoint) else \
                [PathPoint(*pts[-1])] + [PathPoint(*pts[k], pts[k + 1].arc) for k in range(len(pts) - 2, -1, -1)]
        got, want = split_at(pts, steps), split_by_moves(pts, steps)
        assert [tuple(p) for p in got] == [tuple(p) for p in want]
        assert [type(p) for p in got] == [type(p) for p in want]
        assert [getattr(p, "arc", None) for p in got] == [getattr(p, "arc", None) for p in want]


def test_a_trace_that_turns_back_is_split_move_by_move_too():
    pts = [(0.0, 0.0), (4.0, 1.0), (1.0, 2.0), (5.0, 3.0)]
    assert split_at(pts, [2.0]) == [(0.0, 0.0), (2.0, 0.5), (4.0, 1.0), (2.0, 1 + 2 / 3), (1.0, 2.0),
                                    (2.0, 2.25), (5.0, 3.0)]


def test_the_stretches_part_at_the_inner_points_on_a_step_either_way_and_on_a_trace_that_turns_back():
    rnd = random.Random(22)
    for _ in range(1500):
        steps = sorted(rnd.uniform(-2, 20) for _ in range(rnd.randint(0, 8)))
        pts = split_at(random_trace(rnd, steps or [0.0], False), steps)
        if rnd.random() < 0.3:
            pts = pts[::-1]
        if rnd.random() < 0.1 and len(pts) > 3:
            pts[1], pts[2] = pts[2], pts[1]  # u turns back
        assert _groups(pts, steps) == groups_by_points(pts, steps)
    assert _groups([(1.0, 0.0)], [1.0]) == [(0, 0)]
