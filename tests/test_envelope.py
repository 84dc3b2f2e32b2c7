"""The exact envelope (engine/envelope.py) judged by shapely: where a blade
stands at ``lowest(u)`` it touches the material and does not cut it, and a
blade following ``trace`` never cuts it and never leaves it by more than the
tolerance.

The material and the blade are polygons here, drawn finer than anything
checked: the material's arcs chorded to 1e-8 on the side of more material
(bumps by a polygon outside them, bowls by chords inside), the blade's
corners by 1024 segments a quarter (2e-7 inside the true corner, r <= 0.8).
Profiles: CYCLE93 grooves with radii larger and smaller than the blade's
corner, on the base (bowls) and at the edges (bumps), flank angles, an oblique
contour and chamfers, cut with a round-cornered and a sharp blade."""

import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from shapely.affinity import translate
from shapely.geometry import Polygon, box
from shapely.prepared import prep

from freecad_groove.engine import CycleError, GroovingTool, Settings
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.envelope import Envelope, arc_points

TOL = 0.0002
FINE = 1e-8  # the material polygon's chord error
LIFT = 1e-5  # a blade this far above lowest(u) cuts nothing (far above the polygons' errors)
DROP = 1e-4  # and this far below it cuts

GROOVES = {
    # RCO1 2 > r and RCO2 0.2 < r at the edges (bumps), RCI1 2 > r and RCI2 0.2 < r on the base (bowls)
    "radii": dict(widg=10.0, depg=5.0, rco1=2.0, rco2=0.2, rci1=2.0, rci2=0.2),
    # flank angles, an oblique contour, a chamfer, a base radius under the blade's
    "angled": dict(widg=9.0, depg=4.0, angc=10.0, ang1=15.0, ang2=20.0, rco1=1.0, rco2=-0.5, rci1=0.3, rci2=1.5),
    # a base radius equal to the blade's corner radius, an edge chamfer
    "equal": dict(widg=8.0, depg=3.0, rco1=-0.6, rci1=0.4, rci2=0.4),
}
BLADES = {"r0.4": GroovingTool(5.0, 0.4), "sharp": GroovingTool(5.0, 0.0)}


def envelope(groove, blade):
    call = Cycle93(axfa=30.0, axsa=0.0, idep=1.0, typ=1, **GROOVES[groove])
    return call.geometry(Settings(tool=BLADES[blade])).final_env


def material(env):
    """The material under the envelope's top, as a polygon (arcs chorded on the side of more material)."""
    pts = []
    for index, (p, q) in enumerate(zip(env.points, env.points[1:])):
        arc = getattr(env, "arcs", {}).get(index)  # (main before the exact envelope: a polyline)
        if arc is None:
            pts += [p, q]
            continue
        (cu, cv), radius = arc.center, arc.radius
        a0, a1 = (math.atan2(p[1] - cv, p[0] - cu), math.atan2(q[1] - cv, q[0] - cu))
        if arc.bump:
            a0, a1 = a0 % (2 * math.pi), a1 % (2 * math.pi)  # from about pi/2 down toward 0
            a0 = a0 - 2 * math.pi if a0 > 1.5 * math.pi else a0
            a1 = a1 - 2 * math.pi if a1 > 1.5 * math.pi else a1
        else:
            a0, a1 = a0 % (2 * math.pi), a1 % (2 * math.pi)
            a0 = a0 + 2 * math.pi if a0 < 0.5 * math.pi else a0
            a1 = a1 + 2 * math.pi if a1 < 0.5 * math.pi else a1
        pts += arc_points(arc.center, radius, a0, a1, outside=arc.bump, tol=FINE)
    bottom = min(v for _u, v in pts) - 20.0
    return Polygon(pts + [(pts[-1][0], bottom), (pts[0][0], bottom)]).buffer(0)


def blade_shape(env):
    """The blade with its minus edge at u = 0 and its front edge at v = 0."""
    w, r = env.width, env.radius
    if r == 0:
        return box(0.0, 0.0, w, 30.0)
    return box(0.0, r, w, 30.0).union(box(r, 0.0, w - r, 30.0)).union(
        box(r, r, w - r, 30.0).buffer(r, quad_segs=1024))


class Judge:
    """Whether a blade at (u, v) cuts the envelope's material, and how far from it it is."""

    def __init__(self, env):
        self.solid = material(env)
        self.fast = prep(self.solid)
        self.blade = blade_shape(env)
        # No deeper than the polygon's chord error (a wall is passed EDGE_EPS =
        # 1e-9 inside it): the blade thinned by that cuts nothing.
        self.thin = self.blade.buffer(-FINE - 2e-9)
        self.fat = self.blade.buffer(TOL + 1e-6, quad_segs=64)

    def cuts(self, u, v, thin=False):
        shape = translate(self.thin if thin else self.blade, u, v)
        return self.fast.intersects(shape) and shape.intersection(self.solid).area > 0

    def near(self, u, v):
        """True when the blade at (u, v) is within the tolerance of the material."""
        return self.fast.intersects(translate(self.fat, u, v))


def positions(env):
    """Blade positions over the groove: a grid, and around every place where
    the blade's side, corner or flat front passes a vertex."""
    inner = env.points[1:-1]
    lo, hi = inner[0][0] - env.width - 0.5, inner[-1][0] + 0.5
    us = [lo + (hi - lo) * k / 120 for k in range(121)]
    for pu, _pv in inner:
        for off in (0.0, env.radius, env.width - env.radius, env.width):
            us += [pu - off - 1e-3, pu - off + 1e-3]
    return us


CASES = [(g, b) for g in GROOVES for b in BLADES]


@pytest.mark.parametrize("groove, blade", CASES)
def test_a_blade_at_the_lowest_level_touches_the_material_without_cutting_it(groove, blade):
    env = envelope(groove, blade)
    judge = Judge(env)
    for u in positions(env):
        v = env.lowest(u)
        assert not judge.cuts(u, v + LIFT), (u, v)
        assert judge.cuts(u, v - DROP), (u, v)


@pytest.mark.parametrize("groove, blade", CASES)
def test_a_blade_following_the_trace_never_cuts_and_stays_within_the_tolerance(groove, blade):
    env = envelope(groove, blade)
    judge = Judge(env)
    inner = env.points[1:-1]
    lo, hi = inner[0][0] - env.radius, inner[-1][0] - env.width + env.radius  # the finishing pass
    pts = env.trace(lo, hi, TOL)
    assert pts[0] == (lo, env.lowest(lo)) and pts[-1] == (hi, env.lowest(hi))
    for (u0, v0), (u1, v1) in zip(pts, pts[1:]):
        for t in (0.0, 0.5):
            u, v = u0 + t * (u1 - u0), v0 + t * (v1 - v0)
            assert not judge.cuts(u, v, thin=True), (u, v)
            assert judge.near(u, v), (u, v)


@pytest.mark.parametrize("groove, blade", CASES)
def test_the_trace_never_dips_below_the_lowest_level(groove, blade):
    # The same on many more points, against lowest() (which the test above
    # proves exact): every chord of the trace lies on or above it.
    env = envelope(groove, blade)
    inner = env.points[1:-1]
    pts = env.trace(inner[0][0] - env.radius, inner[-1][0] - env.width + env.radius, TOL)
    for (u0, v0), (u1, v1) in zip(pts, pts[1:]):
        if u1 == u0:
            continue  # along a wall
        for k in range(1, 16):
            u, v = u0 + (u1 - u0) * k / 16, v0 + (v1 - v0) * k / 16
            # Where the boundary stands vertical, as a distance: not below it
            # anywhere within 1e-9 along u.
            assert v >= min(env.lowest(u + d) for d in (-1e-9, 0.0, 1e-9)) - 1e-9, (u, v, env.lowest(u))


def test_a_blade_rolling_over_a_square_edge_stays_outside_it():
    # The blade's corner rolls round the groove's square edge on a circle of
    # its own radius about the edge: concave, so chords inside it would cut
    # the edge (up to the tolerance); the trace runs outside it.
    env = Envelope([(-10.0, 0.0), (0.0, 0.0), (0.0, -5.0), (10.0, -5.0), (10.0, 0.0), (20.0, 0.0)], 5.0, 0.4)
    pts = env.trace(-0.4, 0.0, TOL)
    for (u0, v0), (u1, v1) in zip(pts, pts[1:]):
        if u1 == u0:
            continue
        for k in range(1, 16):
            u, v = u0 + (u1 - u0) * k / 16, v0 + (v1 - v0) * k / 16
            centre_distance = math.hypot(u + 0.4, v + 0.4)  # corner centre to the edge
            assert 0.4 - 1e-12 <= centre_distance <= 0.4 + TOL + 1e-12


def test_a_blade_over_a_bump_follows_the_bump_widened_by_its_corner_in_the_fewest_chords():
    # A quarter bump of radius 2 from level to vertical, under a blade of
    # corner radius 0.4: the left corner's centre runs on a circle of 2.4 about
    # the bump's centre, so the trace is that arc (chorded outside it to the
    # tolerance: as many chords as a circle of 2.4 needs, and no more).
    top = [(-10.0, 0.0), (0.0, 0.0), (2.0, -2.0), (2.0, -8.0), (20.0, -8.0)]
    env = Envelope(top, 5.0, 0.4, {1: _arc((0.0, -2.0), 2.0, True)})
    pts = env.trace(-0.4, 2.0, TOL)
    on_arc = [(u, v) for u, v in pts if -0.4 < u < 2.0]
    for u, v in on_arc:
        assert 2.4 <= math.hypot(u + 0.4, v + 2.4) <= 2.4 + TOL + 1e-12  # the corner centre
    chords = math.ceil((math.pi / 2) / (2 * math.acos(2.4 / (2.4 + TOL))))
    assert len(on_arc) == chords  # the corners of the polygon outside the arc
    # Then down the wall, from where the corner leaves the bump (EDGE_EPS
    # short of its vertical end, so 7e-5 above the end of the circle).
    assert pts[-1] == (2.0, -8.0) and pts[-2][0] == 2.0 and pts[-2][1] == pytest.approx(-2.4, abs=1e-4)


def test_a_groove_exactly_as_wide_as_the_blade_lets_it_down_at_that_one_position():
    env = Envelope([(-10.0, 0.0), (0.0, 0.0), (0.0, -5.0), (5.0, -5.0), (5.0, 0.0), (20.0, 0.0)], 5.0, 0.4)
    assert env.lowest(0.0) == -5.0
    assert env.lowest(-1e-3) > -0.5 and env.lowest(1e-3) > -0.5
    pts = env.trace(-0.4, 0.4, TOL)
    assert (0.0, -5.0) in [(round(u, 8), v) for u, v in pts]  # down the slot and back up


def _arc(center, radius, bump):
    from freecad_groove.engine.envelope import Arc

    return Arc(center, radius, bump)


corner = st.one_of(st.just(0.0), st.decimals("0.05", "2", places=2).map(float),
                   st.decimals("-1", "-0.1", places=2).map(float))


@settings(max_examples=25, suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(typ=st.sampled_from([1, 5, 11]), angc=st.sampled_from([0.0, 8.0, 172.0]), ang1=st.sampled_from([0.0, 12.0]),
       ang2=st.sampled_from([0.0, 25.0]), rco1=corner, rco2=corner, rci1=corner, rci2=corner,
       radius=st.sampled_from([0.0, 0.1, 0.4, 0.8]))
def test_on_generated_grooves_a_blade_at_the_lowest_level_touches_without_cutting(
        typ, angc, ang1, ang2, rco1, rco2, rci1, rci2, radius):
    call = Cycle93(axfa=30.0, axsa=0.0, widg=11.0, depg=5.0, angc=angc, ang1=ang1, ang2=ang2, rco1=rco1, rco2=rco2,
                   rci1=rci1, rci2=rci2, idep=1.0, typ=typ)
    try:
        env = call.geometry(Settings(tool=GroovingTool(4.0, radius))).final_env
    except CycleError:
        assume(False)
    judge = Judge(env)
    for u in positions(env)[::3]:
        v = env.lowest(u)
        assert not judge.cuts(u, v + LIFT), (u, v)
        assert judge.cuts(u, v - DROP), (u, v)
