"""The closed-form field of what CYCLE93's plunges leave (cycle93_material)
against a brute-force reference: every column of a fine grid, the lowest
level the blade reaches there found by a ternary search along each segment
of the chain (the blade's level at a column is convex along a straight move)."""

import math
import random

import numpy as np
import pytest

from freecad_groove.engine.cycles.cycle93_material import FLOOR_TOL, MATERIAL_MARGIN, MaterialTop, _sweep, lower_hull
from freecad_groove.engine.cycles.cycle93_witness import _axis, _over_blade

COLUMNS = 40000
TOL = 0.002  # mm: the grid misses a peak by up to its spacing times the slopes beside it


def _outline(s, w, r):
    """The blade's front level over its front-left point at offset s (inf outside [0, w])."""
    s = np.asarray(s, dtype=float)
    out = np.zeros_like(s)
    if r > 0:
        left, right = s < r, s > w - r
        out[left] = r - np.sqrt(np.maximum(r * r - (r - s[left]) ** 2, 0.0))
        out[right] = r - np.sqrt(np.maximum(r * r - (s[right] - (w - r)) ** 2, 0.0))
    out[(s < 0) | (s > w)] = np.inf
    return out


def _field(xs, slots, slope, w, r):
    level = slope * xs
    for u, bottom in slots:
        level = np.minimum(level, bottom + _outline(xs - u, w, r))
    return level


def _swept(xs, chain, w, r):
    """Lowest level of the blade moved along the chain, per column."""
    best = np.full_like(xs, np.inf)
    segments = list(zip(chain, chain[1:])) or [(chain[0], chain[0])]
    for (u0, v0), (u1, v1) in segments:
        du, dv = u1 - u0, v1 - v0
        if du == 0:
            best = np.minimum(best, min(v0, v1) + _outline(xs - u0, w, r))
            continue
        lo = np.clip((xs - w - u0) / du, 0.0, 1.0)  # positions whose blade covers the column
        hi = np.clip((xs - u0) / du, 0.0, 1.0)
        ok = lo <= hi
        a, b = lo.copy(), hi.copy()
        for _ in range(80):
            m1, m2 = a + (b - a) / 3, b - (b - a) / 3
            f1 = v0 + m1 * dv + _outline(xs - u0 - m1 * du, w, r)
            f2 = v0 + m2 * dv + _outline(xs - u0 - m2 * du, w, r)
            left = f1 < f2
            b = np.where(left, m2, b)
            a = np.where(left, a, m1)
        t = 0.5 * (a + b)
        level = np.minimum.reduce([v0 + t * dv + _outline(xs - u0 - t * du, w, r),
                                   v0 + lo * dv + _outline(xs - u0 - lo * du, w, r),
                                   v0 + hi * dv + _outline(xs - u0 - hi * du, w, r)])
        best = np.minimum(best, np.where(ok, level, np.inf))
    return best


def _case(rng):
    w = rng.uniform(1.5, 5.0)
    r = rng.choice([0.0, rng.uniform(0.05, min(0.8, 0.45 * w))])
    slope = rng.choice([0.0, 0.0, 0.2, -0.3])
    u, slots = 0.0, []
    for _ in range(rng.randint(1, 5)):
        slots.append((u, rng.uniform(-5.0, -1.0)))
        u += rng.uniform(0.3, 1.0) * w
    points = [(rng.uniform(-0.5 * w, u), rng.uniform(-6.0, 0.5)) for _ in range(rng.randint(1, 5))]
    return w, r, slope, slots, lower_hull(points)


def _cleared(slope, slots, w, r):
    """The field over a bar of ``slope`` after plunges of a w-wide, r-cornered blade to each (u, bottom) of
    ``slots``."""
    material = MaterialTop(-30.0, 60.0, slope)
    for u, bottom in slots:
        material.clear_slot(u, u, bottom, w, r)
    return material


def _bisected(material, outline, floor):
    """The closed form's stand: the limit ``exceeds`` switches at, bisected."""
    lo, hi = -20.0, 20.0
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if material.exceeds(outline, floor, mid) else (lo, mid)
    return lo


def _floor(rng, a, b):
    """A random profile under the blade: a polyline with one vertical step."""
    us = sorted(rng.uniform(a - 1.0, b + 1.0) for _ in range(rng.randint(2, 6)))
    pts = [(u, rng.uniform(-6.0, 0.0)) for u in us]
    k = rng.randrange(len(pts))
    pts.insert(k + 1, (pts[k][0], rng.uniform(-6.0, 0.0)))
    return [(a - 50.0, pts[0][1])] + pts + [(b + 50.0, pts[-1][1])]


@pytest.mark.parametrize("seed", range(40))
def test_the_closed_form_stand_matches_a_brute_force_one(seed):
    """Field minus the swept outline, highest value; then with the outline
    raised to a floor (the profile) less FLOOR_TOL."""
    rng = random.Random(seed)
    w, r, slope, slots, chain = _case(rng)
    material = _cleared(slope, slots, w, r)
    outline = _sweep(chain, w, r)
    a, b = outline[0][0], outline[-1][1]
    xs = np.linspace(a + 1e-6, b - 1e-6, COLUMNS)
    field, swept = _field(xs, slots, slope, w, r), _swept(xs, chain, w, r)
    nowhere = [(-100.0, -1e9), (100.0, -1e9)]  # a floor that never raises the outline
    assert _bisected(material, outline, nowhere) == pytest.approx(float(np.max(field - swept)), abs=TOL)
    floor = _floor(rng, a, b)
    raised = np.maximum(swept, np.interp(xs, [p[0] for p in floor], [p[1] for p in floor]) - FLOOR_TOL)
    assert _bisected(material, outline, floor) == pytest.approx(float(np.max(field - raised)), abs=TOL)


def test_a_stretch_cuts_exactly_when_the_swept_blade_stands_under_the_field_whether_or_not_the_shortcut_answers():
    """cuts answers many stretches without the sweep (MaterialTop._verdict);
    each answer is the sweep's (exceeds over the stretch's lower hull), on
    stretches whose points come in either direction and above their hull,
    slots cleared where the blade has stood and floors with a step."""
    answered = {True: 0, False: 0}
    for seed in range(1500):
        rng = random.Random(seed)
        w, r, slope, slots, _chain = _case(rng)
        material = _cleared(slope, slots, w, r)
        material.cuts([(0.0, 0.0)], w, r, [(-100.0, -1e9), (100.0, -1e9)])  # the field built: later slots lower it
        for u, v in rng.sample(slots, rng.randint(0, len(slots))):
            material.stand_blade(u + rng.uniform(-0.5, 0.5), v + rng.uniform(-1.0, 1.0), w, r)
        u0 = rng.uniform(-0.5 * w, slots[-1][0])
        points = [(u0 + k * rng.uniform(0.05, 0.8), rng.uniform(-6.0, 0.5)) for k in range(rng.randint(1, 6))]
        if rng.random() < 0.5:
            points.reverse()  # a pass from the far edge
        a, b = min(points)[0], max(points)[0] + w
        floor = _floor(rng, a, b) if rng.random() < 0.7 else [(-100.0, -1e9), (100.0, -1e9)]
        verdict = material._verdict(points, w, r, floor)
        swept = material.exceeds(_sweep(lower_hull(points), w, r), floor, MATERIAL_MARGIN)
        assert material.cuts(points, w, r, floor) == swept, seed
        assert verdict in (None, swept), seed
        if verdict is not None:
            answered[verdict] += 1
    assert answered[True] > 80 and answered[False] > 80, answered  # both shortcuts were put to the test


def test_the_flat_stand_is_the_field_s_highest_point_over_the_blade():
    material = MaterialTop(-30.0, 60.0, 0.0)
    material.clear_slot(0.0, 0.0, -4.0, 3.0, 0.4)
    material.clear_slot(2.5, 2.5, -4.0, 3.0, 0.4)
    # Between the two slots the tooth's tip stands where their corner arcs meet:
    # at u = 2.75, 0.25 mm from both arcs' ends; level -4 + 0.4 - sqrt(0.4^2 - 0.15^2).
    tip = -4.0 + 0.4 - math.sqrt(0.16 - 0.0225)
    assert material.stand(1.0, -4.0, 3.0) == pytest.approx(tip + 4.0, abs=1e-12)
    assert material.stand(-2.0, -4.0, 1.5) == pytest.approx(4.0, abs=1e-12)  # the contour beside the slot


def test_on_a_long_stretch_the_blades_over_a_column_found_by_bisection_are_those_a_walk_finds():
    """A stretch over an arc's chords has tens of points: the shortcut finds
    the blades over a column by bisecting their u (``_axis``). Its answers
    are the walk's on random long chains either way round, at random columns
    and levels, and cuts still answers as the sweep does on them."""
    checked = {True: 0, False: 0}
    for seed in range(300):
        rng = random.Random(seed)
        w, r, slope, slots, _chain = _case(rng)
        u0 = rng.uniform(-0.5 * w, slots[-1][0])
        chain = [(u0 + k * rng.choice([0.0, rng.uniform(0.01, 0.4)]), rng.uniform(-6.0, 0.5)) for k in range(30)]
        chain = sorted(chain)[:rng.randint(9, 30)]
        if rng.random() < 0.5:
            chain.reverse()
        a, b = min(chain)[0], max(chain)[0] + w
        floor = _floor(rng, a, b) if rng.random() < 0.7 else [(-100.0, -1e9), (100.0, -1e9)]
        axis = _axis(chain)
        assert axis is not None
        for _ in range(20):
            x, level = rng.uniform(a - 0.5, b + 0.5), rng.uniform(-7.0, 1.0)
            walked = _over_blade(level, x, chain, w, r, floor, MATERIAL_MARGIN)
            assert _over_blade(level, x, chain, w, r, floor, MATERIAL_MARGIN, axis) == walked, seed
            checked[walked] += 1
        material = _cleared(slope, slots, w, r)
        swept = material.exceeds(_sweep(lower_hull(chain), w, r), floor, MATERIAL_MARGIN)
        assert material.cuts(chain, w, r, floor) == swept, seed
    assert checked[True] > 200 and checked[False] > 200, checked
    assert _axis(chain[:8]) is None and _axis([(0.0, 0.0), (1.0, 0.0), (0.5, 0.0)] * 3) is None


def test_by_the_opening_s_edges_the_shortcut_answers_as_the_sweep_where_the_field_is_the_profile_itself():
    """Beside the opening the field is the contour, the profile the pass
    follows (the floor), not cut: the shortcut's False there (the field no
    higher than the floor, ``_under_floor``) and its True are the sweep's,
    with the blade's positions near the edge, either way round."""
    beside = 0
    for seed in range(1500):
        rng = random.Random(seed)
        w, r, slope, slots, _chain = _case(rng)
        material = _cleared(slope, slots, w, r)
        right = slots[-1][0] + w  # the opening: [0, right], its base below every slot
        floor = [(-100.0, -100.0 * slope), (0.0, 0.0), (0.0, -7.0), (right, -7.0 + rng.uniform(-0.5, 0.5)),
                 (right, right * slope), (100.0, 100.0 * slope)]
        edge = rng.choice([0.0, right - w])
        u0 = edge + rng.uniform(-0.6 * w, 0.3 * w)
        points = [(u0 + k * rng.uniform(0.02, 0.3), slope * u0 + rng.uniform(-0.3, 0.05))
                  for k in range(rng.randint(1, 4))]
        if rng.random() < 0.5:
            points.reverse()
        verdict = material._verdict(points, w, r, floor)
        swept = material.exceeds(_sweep(lower_hull(points), w, r), floor, MATERIAL_MARGIN)
        assert verdict in (None, swept), seed
        assert material.cuts(points, w, r, floor) == swept, seed
        lowest = min(v for _u, v in points)
        if verdict is False and material.stand(min(points)[0], lowest, max(points)[0] + w - min(points)[0]) > 0.01:
            beside += 1  # the field stands over the stretch's lowest point: the floor said no
    assert beside > 80, beside


def test_a_stretch_from_or_to_a_blade_s_own_slot_is_answered_as_the_sweep_answers_it():
    """A stretch starting (or ending) where a blade stood, at the bottom of
    its slot: the slot's corner arc is the swept outline's there when the
    stretch does not fall from that point (rise to it), and the shortcut's
    False by that (``_in_end_corners``) is the sweep's, as its other
    answers; stretches that fall away from the slot too."""
    own = 0
    for seed in range(1500):
        rng = random.Random(seed)
        w, r, slope, slots, _chain = _case(rng)
        if r == 0:
            r = 0.4 * rng.uniform(0.1, 1.0) * w
        material = _cleared(slope, slots, w, r)
        u, bottom = rng.choice(slots)
        steps = [(k * rng.uniform(0.1, 0.9), rng.choice([0.0, 0.0, rng.uniform(-0.3, 0.6)])) for k in range(1, 4)]
        points = [(u, bottom)] + [(u + du, bottom + dv) for du, dv in steps[:rng.randint(0, 3)]]
        if rng.random() < 0.5:  # ending at the slot, from the left
            points = [(2 * u - p, q) for p, q in reversed(points)]
        floor = [(-100.0, -1e9), (100.0, -1e9)]
        verdict = material._verdict(points, w, r, floor)
        swept = material.exceeds(_sweep(lower_hull(points), w, r), floor, MATERIAL_MARGIN)
        assert verdict in (None, swept), seed
        assert material.cuts(points, w, r, floor) == swept, seed
        if verdict is False and material.stand(min(points)[0], bottom, max(points)[0] + w - min(points)[0]) > 0.01:
            own += 1  # a corner stands over the lowest point: the slot's own corners said no
    assert own > 80, own
