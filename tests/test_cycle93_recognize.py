"""Reading CYCLE93 calls from notches of a section outline (engine/cycles/cycle93_recognize.py)."""

import math
import random

import pytest

from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.cycle93_outline import ArcSegment, NotchError, Segment
from freecad_groove.engine.cycles.cycle93_recognize import profile_elements, recognize
from freecad_groove.engine.errors import CycleError

GEOMETRY_FIELDS = ("axfa", "axsa", "widg", "depg", "angc", "ang1", "ang2", "rco1", "rco2", "rci1", "rci2", "typ")


def outline_of(notch, material_below):
    """A closed outline: the contour line 20 mm on either side of ``notch``
    (elements from one contour point to the other), then around a block of
    material on the side ``material_below`` says ((dz, dr): a unit vector
    pointing into the material). Returns (outline, index of the notch's first element)."""
    first, last = notch[0].start, notch[-1].end
    d = (last[0] - first[0], last[1] - first[1])
    n = math.hypot(*d)
    d = (d[0] / n, d[1] / n)
    far_a = (first[0] - 20 * d[0], first[1] - 20 * d[1])
    far_b = (last[0] + 20 * d[0], last[1] + 20 * d[1])
    into = material_below
    deep_b = (far_b[0] + 40 * into[0], far_b[1] + 40 * into[1])
    deep_a = (far_a[0] + 40 * into[0], far_a[1] + 40 * into[1])
    outline = [Segment(far_a, first), *notch, Segment(last, far_b), Segment(far_b, deep_b),
               Segment(deep_b, deep_a), Segment(deep_a, far_a)]
    return outline, 1


def into_material(call):
    """(dz, dr) of the plunge direction of ``call`` (into the material)."""
    longitudinal, external, _left, _chr = call.kind()
    sign = -1.0 if external else 1.0
    return (0.0, sign) if longitudinal else (sign, 0.0)


def outline_of_call(call):
    notch = profile_elements(call)
    outline, first = outline_of(notch, into_material(call))
    return outline, first, len(notch)


def assert_same_call(found, call):
    for name in GEOMETRY_FIELDS:
        assert getattr(found, name) == pytest.approx(getattr(call, name) or 0.0, abs=1e-6), name


def random_call(rng, typ):
    longitudinal = typ % 10 in (1, 3, 5, 7)
    oblique = rng.random() < 0.5
    if longitudinal:
        angc = 0.0 if not oblique else rng.choice([1, -1]) * round(rng.uniform(3, 35), 3) % 180
    else:
        angc = 90.0 if not oblique else round(rng.uniform(55, 125), 3)

    def corner():
        kind = rng.random()
        if kind < 0.3:
            return 0.0
        return round(rng.uniform(0.1, 0.6), 3) * (1 if kind < 0.65 else -1)

    return Cycle93(axfa=round(rng.uniform(15, 40), 3), axsa=round(rng.uniform(-30, 30), 3),
                   widg=round(rng.uniform(3, 8), 3), depg=round(rng.uniform(1.5, 5), 3), angc=angc,
                   ang1=round(rng.uniform(0, 25), 3) * (rng.random() < 0.6), ang2=round(rng.uniform(0, 25), 3)
                   * (rng.random() < 0.6), rco1=corner(), rco2=corner(), rci1=corner(), rci2=corner(), typ=typ)


def test_generated_calls_read_back_field_by_field_for_every_typ_and_contour():
    rng = random.Random(93)
    checked = {typ: 0 for typ in list(range(1, 9)) + list(range(11, 19))}
    while min(checked.values()) < 12:
        typ = rng.choice(list(checked))
        call = random_call(rng, typ)
        try:
            outline, first, count = outline_of_call(call)
        except CycleError:
            continue  # a form CYCLE93 refuses (corners that overlap): nothing to read back
        picked = first + rng.randrange(count)  # any element of the notch: base, flank or corner
        found = recognize(outline, picked, right=typ % 10 >= 5, chr_chamfers=typ > 10)
        assert_same_call(found.call, call)
        checked[typ] += 1


@pytest.mark.parametrize("typ", [5, 7, 6, 8])
def test_a_rectangular_groove_reads_as_its_hand_derived_call(typ):
    # TYP 5: a 4 mm wide, 2 mm deep groove in a R20 cylinder from Z-10 (its +Z edge) to Z-14.
    longitudinal = typ in (5, 7)
    sign = -1 if typ in (5, 6) else 1
    if longitudinal:
        pts = [(-10, 20), (-10, 20 + 2 * sign), (-14, 20 + 2 * sign), (-14, 20)]
    else:  # a face at Z0, groove from radius 30 (outer edge) to 26, 2 deep
        pts = [(0, 30), (2 * sign, 30), (2 * sign, 26), (0, 26)]
    notch = [Segment(a, b) for a, b in zip(pts, pts[1:])]
    outline, first = outline_of(notch, (0.0, float(sign)) if longitudinal else (float(sign), 0.0))
    found = recognize(outline, first + 1).call
    if longitudinal:
        assert (found.axfa, found.axsa, found.widg, found.depg, found.angc) == (20, -10, 4, 2, 0)
    else:
        assert (found.axfa, found.axsa, found.widg, found.depg, found.angc) == (30, 0, 4, 2, 90)
    assert (found.ang1, found.ang2, found.rco1, found.rci2, found.typ) == (0, 0, 0, 0, typ)


def test_picking_the_contour_beside_a_notch_is_refused():
    pts = [(-10, 20), (-10, 18), (-14, 18), (-14, 20)]
    outline, first = outline_of([Segment(a, b) for a, b in zip(pts, pts[1:])], (0.0, -1.0))
    with pytest.raises(NotchError, match="is in no notch"):
        recognize(outline, 0)


def test_an_undercut_is_refused_naming_the_flank_and_its_lean():
    # flank 2 (the -Z one) leans 1 mm back over a 2 mm deep base: the bottom is wider than the top
    pts = [(-10, 20), (-10, 18), (-15, 18), (-14, 20)]
    outline, first = outline_of([Segment(a, b) for a, b in zip(pts, pts[1:])], (0.0, -1.0))
    with pytest.raises(NotchError, match=r"flank 2 .* leans 26.565051 degrees back over the base \(an undercut"):
        recognize(outline, first + 1)


def test_a_base_not_parallel_to_the_contour_is_refused():
    pts = [(-10, 20), (-10, 18), (-14, 17.5), (-14, 20)]
    outline, first = outline_of([Segment(a, b) for a, b in zip(pts, pts[1:])], (0.0, -1.0))
    with pytest.raises(NotchError, match="no base parallel to the contour"):
        recognize(outline, first)


def test_a_stepped_groove_is_refused():
    pts = [(-10, 20), (-10, 18), (-12, 18), (-12, 17), (-14, 17), (-14, 20)]
    outline, first = outline_of([Segment(a, b) for a, b in zip(pts, pts[1:])], (0.0, -1.0))
    with pytest.raises(NotchError, match="2 segments parallel to the contour .a stepped groove"):
        recognize(outline, first + 2)


def test_an_arc_that_is_not_tangent_is_refused():
    # a R1 arc from the +Z flank's foot into the base, centred so it meets the flank at an angle
    pts = [(-10, 20), (-10, 18.5)]
    # legs 0.5 on the flank and 1.5 on the base: a true arc (centre equidistant from both ends), not tangent
    arc = ArcSegment((-10, 18.5), (-11.5, 18), (-11.25, 19.75), ccw=False)
    notch = [Segment(pts[0], pts[1]), arc, Segment((-11.5, 18), (-14, 18)), Segment((-14, 18), (-14, 20))]
    outline, first = outline_of(notch, (0.0, -1.0))
    rule = "the arc from Z-10 X18.5 to Z-11.5 X18 is not tangent to both elements it joins"
    with pytest.raises(NotchError, match=rule):
        recognize(outline, first + 1)


def test_a_chamfer_with_unequal_legs_is_refused():
    pts = [(-10, 20), (-10, 18.5), (-11, 18), (-14, 18), (-14, 20)]  # legs 0.5 and 1
    outline, first = outline_of([Segment(a, b) for a, b in zip(pts, pts[1:])], (0.0, -1.0))
    rule = r"the chamfer from Z-10 X18.5 to Z-11 X18 has legs 0.5 and 1.0: CYCLE93.s chamfers have equal legs"
    with pytest.raises(NotchError, match=rule):
        recognize(outline, first)


def test_a_semicircular_groove_has_no_base_and_is_refused():
    notch = [ArcSegment((-10, 20), (-14, 20), (-12, 20), ccw=False)]
    outline, first = outline_of(notch, (0.0, -1.0))
    with pytest.raises(NotchError, match="no base parallel to the contour"):
        recognize(outline, first)


def test_split_contour_and_base_pieces_are_joined():
    # the base in two pieces, the contour after the notch in two: still one groove
    pts = [(-10, 20), (-10, 18), (-12, 18), (-14, 18), (-14, 20)]
    outline, first = outline_of([Segment(a, b) for a, b in zip(pts, pts[1:])], (0.0, -1.0))
    found = recognize(outline, first + 2).call
    assert (found.widg, found.depg, found.typ) == (4, 2, 5)


def test_a_notch_of_more_than_seven_elements_is_refused_naming_the_count():
    # a base with two ribs standing on it: eleven segments between the contour's pieces
    pts = [(-10, 20), (-10, 17), (-11, 17), (-11, 17.5), (-11.5, 17.5), (-11.5, 17), (-12.5, 17), (-12.5, 17.5),
           (-13, 17.5), (-13, 17), (-14, 17), (-14, 20)]
    outline, first = outline_of([Segment(a, b) for a, b in zip(pts, pts[1:])], (0.0, -1.0))
    rule = "from Z-10 X20 to Z-14 X20 has 11 elements: CYCLE93 cuts two flanks, a base and four corners"
    for picked in (first, first + 3, first + 10):
        with pytest.raises(NotchError, match=rule):
            recognize(outline, picked)
