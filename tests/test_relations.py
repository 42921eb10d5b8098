import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scenewright.geometry import yaw_towards
from scenewright.layout import check, violation
from scenewright.layout.relations import Boxes, half_extents, holds, propose
from scenewright.scene import SceneObject, Vec3


def box(oid, x=0.0, y=0.0, z=None, size=(1.0, 1.0, 1.0), yaw=0.0):
    s = Vec3.of(size)
    return SceneObject(id=oid, name=oid, size=s, position=Vec3(x=x, y=y, z=s.z / 2 if z is None else z),
                       rotation=Vec3(z=yaw))


T = box("t")  # unit cube at the origin: x, y in [-0.5, 0.5]


@pytest.mark.parametrize(
    "relation, at_limit, past_limit",
    [
        ("left of", dict(x=-1.1), dict(x=-1.09)),
        ("right of", dict(x=1.1), dict(x=1.09)),
        ("in front of", dict(y=-1.1), dict(y=-1.09)),
        ("behind", dict(y=1.1), dict(y=1.09)),
        ("side of", dict(x=-1.1), dict(x=1.09)),
        ("side of", dict(x=1.1), dict(x=-1.09)),
    ],
)
def test_relative_buffer_holds_exactly_at_the_limit(relation, at_limit, past_limit):
    assert check(relation, box("s", **at_limit), T)
    assert violation(relation, box("s", **at_limit), T) == 0.0
    assert not check(relation, box("s", **past_limit), T)
    assert violation(relation, box("s", **past_limit), T) == pytest.approx(0.01)


def test_relative_relations_ignore_the_other_axis():
    assert check("left of", box("s", x=-2, y=50), T)
    assert check("in front of", box("s", x=-40, y=-2), T)
    assert not check("left of", box("s", x=-0.2, y=5), T)


def test_rotated_target_uses_its_world_box():
    rotated = box("t", size=(2.0, 0.2, 1.0), yaw=90)  # now 0.2 wide in x, 2 deep in y
    assert check("left of", box("s", x=-0.7), rotated)  # 0.1 + 0.1 + 0.5 = 0.7
    assert not check("in front of", box("s", y=-1.5), rotated)  # 1 + 0.1 + 0.5 = 1.6 needed
    assert check("in front of", box("s", y=-1.6), rotated)
    diag = box("t", size=(1.0, 1.0, 1.0), yaw=45)  # half width √½
    assert not check("right of", box("s", x=1.1), diag)
    assert check("right of", box("s", x=np.sqrt(0.5) + 0.6), diag)


def test_near_and_far_measure_the_horizontal_gap():
    assert check("near", box("s", x=3.0), T)  # gap exactly 2
    assert not check("near", box("s", x=3.01), T)
    d = 2.0 / np.sqrt(2)  # diagonal gap of exactly 2
    assert check("near", box("s", x=1 + d - 1e-9, y=1 + d - 1e-9), T)
    assert not check("near", box("s", x=1 + d + 0.01, y=1 + d + 0.01), T)
    assert check("near", box("s", z=5.0), T)  # height does not count
    assert not check("far", box("s", x=9.0), T)  # gap exactly 8 is not > 8
    assert check("far", box("s", x=9.01), T)
    assert violation("far", box("s", x=5.0), T) == pytest.approx(4.0)


def test_on_needs_contact_within_2mm_and_the_centre_over_the_host():
    assert check("on", box("s", z=1.0 + 0.5 + 0.0019), T)
    assert check("on", box("s", z=1.0 + 0.5 - 0.0019), T)
    assert not check("on", box("s", z=1.0 + 0.5 + 0.0021), T)
    assert check("on", box("s", x=0.49, z=1.5), T)  # overhangs by 49 cm, its centre still over T
    assert not check("on", box("s", x=0.9, z=1.5), T)  # overlaps by 10 cm: it would tip off
    assert not check("on", box("s", x=1.0, z=1.5), T)  # only touches edge to edge
    assert violation("on", box("s", x=1.5, z=1.5), T) == pytest.approx(1.0)  # centre 1 m past T's edge
    turned = box("t", size=(2.0, 0.4, 1.0), yaw=90.0)  # its long side along y
    assert check("on", box("s", y=0.9, z=1.5, size=(0.2, 0.2, 1.0)), turned)
    assert not check("on", box("s", x=0.3, z=1.5, size=(0.2, 0.2, 1.0)), turned)


def test_stacked_on_chain():
    table = box("table", size=(1.2, 0.8, 0.75))
    book = box("book", size=(0.3, 0.2, 0.05), z=0.75 + 0.025)
    cup = box("cup", size=(0.08, 0.08, 0.1), z=0.8 + 0.05)
    assert check("on", book, table) and check("on", cup, book)
    assert not check("on", cup, table)
    assert violation("on", cup, table) == pytest.approx(0.05 - 0.002)


def test_above_is_measured_centre_to_centre_without_contact_and_with_footprint_overlap():
    # T's centre is at 0.5 m: "positioned 2 m above" it puts the source's centre at 2.5 m.
    lamp = box("lamp", size=(0.4, 0.4, 0.3), z=0.5 + 2.0)
    assert check("above", lamp, T)
    low = box("lamp", size=(0.4, 0.4, 0.3), z=0.5 + 1.99)
    assert not check("above", low, T)
    assert violation("above", low, T) == pytest.approx(0.01)
    aside = box("lamp", size=(0.4, 0.4, 0.3), x=0.8, z=3.5)
    assert not check("above", aside, T)
    overlapping = box("lamp", size=(0.4, 0.4, 0.3), x=0.69, z=3.5)
    assert check("above", overlapping, T)
    # A pendant lamp under a 2.7 m ceiling over a 0.75 m table: above it.
    table = box("table", size=(1.2, 0.8, 0.75))
    assert check("above", box("lamp", size=(0.4, 0.4, 0.4), z=2.7 - 0.2), table)


def test_above_never_touches_its_target():
    tall = box("tall", size=(1.0, 1.0, 3.0))  # centre 1.5 m, top 3 m
    resting = box("lamp", size=(0.4, 0.4, 1.0), z=3.0 + 0.5)  # centre 2 m higher, bottom on its top
    assert not check("above", resting, tall) and check("on", resting, tall)
    assert violation("above", resting, tall) == pytest.approx(0.002)
    assert check("above", box("lamp", size=(0.4, 0.4, 1.0), z=3.0 + 0.51), tall)


@pytest.mark.parametrize("angle", range(0, 360, 45))
def test_face_to_in_every_quadrant(angle):
    a = np.radians(angle)
    src_xy = (5 * np.cos(a), 5 * np.sin(a))
    yaw = yaw_towards(src_xy, (0.0, 0.0))
    assert check("face to", box("s", *src_xy, yaw=yaw), T)
    assert check("face to", box("s", *src_xy, yaw=yaw + 9.9), T)
    assert check("face to", box("s", *src_xy, yaw=yaw - 9.9), T)
    assert not check("face to", box("s", *src_xy, yaw=yaw + 10.5), T)
    assert not check("face to", box("s", *src_xy, yaw=yaw + 180), T)
    assert violation("face to", box("s", *src_xy, yaw=yaw + 30), T) == pytest.approx(20.0)


def test_face_to_front_is_minus_y_at_yaw_zero():
    assert check("face to", box("s", y=3.0), T)  # T is at −Y of s
    assert not check("face to", box("s", y=-3.0), T)
    assert not check("face to", box("s"), box("t", z=5.0))  # same plan centre faces nothing


def test_unknown_relation_names_the_valid_ones():
    with pytest.raises(ValueError, match="valid relations: left of"):
        check("under", box("s"), T)


RELATIONS = ["left of", "right of", "in front of", "behind", "side of", "near", "far", "on", "above", "face to"]
coord = st.floats(-10, 10, allow_nan=False)
dim = st.floats(0.05, 3.0, allow_nan=False)


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(RELATIONS), coord, coord, st.floats(0, 5), dim, dim, dim, st.floats(-180, 180),
       coord, coord, dim, dim, dim, st.floats(-180, 180))
def test_violation_is_zero_exactly_when_the_check_holds(
    relation, x, y, z, sx, sy, sz, yaw, tx, ty, tsx, tsy, tsz, tyaw
):
    s = box("s", x, y, z + sz / 2, (sx, sy, sz), yaw)
    t = box("t", tx, ty, None, (tsx, tsy, tsz), tyaw)
    assert (violation(relation, s, t) == 0.0) == check(relation, s, t)
    assert violation(relation, s, t) >= 0.0


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(["left of", "right of", "in front of", "behind", "side of", "on", "above", "near"]),
       coord, coord, dim, dim, st.floats(-180, 180), coord, coord, st.integers(0, 1000))
def test_proposed_candidates_satisfy_their_relation(relation, tx, ty, sx, sy, tyaw, ax, ay, seed):
    target = Boxes.of(box("t", tx, ty, None, (1.2, 0.9, 0.7), tyaw))
    size = Vec3(x=sx, y=sy, z=0.3)
    half = half_extents(size, Vec3())
    pts = propose(relation, half, target, np.array([ax, ay]), np.random.default_rng(seed))
    z = {"on": 0.7 + 0.15, "above": 0.35 + 2.0}.get(relation, 0.15)
    cands = Boxes.at(np.column_stack([pts, np.full(len(pts), z)]), half, np.zeros(len(pts)))
    ok = holds(relation, cands, target)
    if relation == "near":  # a bounding rectangle: most, not all, candidates hold
        assert ok.any()
    else:
        assert ok.all()
    dist = np.linalg.norm(pts - [ax, ay], axis=1)
    assert np.all(np.diff(dist) >= -1e-9)  # nearest to the anchor first


def _outline(centre, half, yaw, m=120):
    t = np.linspace(-1.0, 1.0, m)
    ones = np.ones(m)
    local = np.concatenate([
        np.stack([t * half[0], ones * half[1]], 1), np.stack([t * half[0], -ones * half[1]], 1),
        np.stack([ones * half[0], t * half[1]], 1), np.stack([-ones * half[0], t * half[1]], 1),
    ])
    a = np.radians(yaw)
    return local @ np.array([[np.cos(a), np.sin(a)], [-np.sin(a), np.cos(a)]]) + centre


def _inside(point, centre, half, yaw):
    a = np.radians(yaw)
    d = np.asarray(point) - centre
    local = np.array([d[0] * np.cos(a) + d[1] * np.sin(a), -d[0] * np.sin(a) + d[1] * np.cos(a)])
    return bool(np.all(np.abs(local) <= half))


@settings(max_examples=60, deadline=None)
@given(coord, coord, dim, dim, st.floats(-180, 180), coord, coord, dim, dim, st.floats(-180, 180))
def test_near_measures_the_true_footprints_of_turned_objects(x, y, sx, sy, yaw, tx, ty, tsx, tsy, tyaw):
    s = box("s", x, y, None, (sx, sy, 1.0), yaw)
    t = box("t", tx, ty, None, (tsx, tsy, 1.0), tyaw)
    cs, hs, ct, ht = np.array([x, y]), np.array([sx, sy]) / 2, np.array([tx, ty]), np.array([tsx, tsy]) / 2
    # Brute force: the distance between the two outlines, 0 when one holds the other.
    gap = np.sqrt(((_outline(cs, hs, yaw)[:, None] - _outline(ct, ht, tyaw)[None]) ** 2).sum(-1)).min()
    if _inside(cs, ct, ht, tyaw) or _inside(ct, cs, hs, yaw):
        gap = 0.0
    tolerance = 0.05 * max(sx, sy, tsx, tsy)  # the outline's sampling step
    if gap > 2.0 + tolerance:
        assert not check("near", s, t)
    if gap < 2.0 - tolerance:
        assert check("near", s, t)
    assert violation("near", s, t) == pytest.approx(max(0.0, gap - 2.0), abs=tolerance)


def test_a_turned_object_is_near_by_its_footprint_not_its_world_box():
    # A 4 m beam across the diagonal: its world box comes within 1.44 m of T, the beam itself 3.44 m.
    beam = box("s", 3.0, 3.0, size=(4.0, 0.2, 1.0), yaw=-45)
    assert not check("near", beam, T)
    assert violation("near", beam, T) == pytest.approx(2.5 * np.sqrt(2) - 0.1 - 2.0)
    assert check("near", box("s", 3.0, 3.0, size=(4.0, 0.2, 1.0), yaw=45), T)  # along the diagonal: 1.54 m


def test_on_a_seat_rests_on_its_cushions_not_its_backrest():
    """A sofa's catalogue ``rest_height`` (a share of its height) is its top for ``on``: the
    check, the violation and the solver's candidate height all use it; other things keep their top."""
    from scenewright.core.catalogue import load_catalogue
    from scenewright.layout.relations import rest_share, source_heights

    sofa = box("sofa", size=(2.1, 0.9, 0.85)).model_copy(update={"category": "sofa"})
    seat = 0.85 * load_catalogue()["sofa"].rest_height
    assert rest_share(sofa) == pytest.approx(seat / 0.85) and rest_share(T) == 1.0
    person = box("p", size=(0.4, 0.6, 0.7), z=seat + 0.35)
    assert check("on", person, sofa) and violation("on", person, sofa) == 0.0
    on_backrest = box("p", size=(0.4, 0.6, 0.7), z=0.85 + 0.35)
    assert not check("on", on_backrest, sofa)
    assert violation("on", on_backrest, sofa) == pytest.approx(0.85 - seat - 0.002, abs=1e-6)
    assert source_heights("on", 0.35, Boxes.of(sofa), 0.0) == pytest.approx([seat + 0.35])
    assert source_heights("on", 0.35, Boxes.of(T), 0.0) == pytest.approx([1.35])


@settings(max_examples=60, deadline=None)
@given(share=st.floats(0.2, 1.0), height=st.floats(0.3, 2.0), yaw=st.floats(0, 360), dx=st.floats(-0.4, 0.4))
def test_on_rests_at_the_share_of_the_host_height(share, height, yaw, dx):
    host = Boxes.at(np.array([0.0, 0.0, height / 2]), np.array([0.5, 0.5, height / 2]), yaw, rest=share)
    rest = share * height
    src = Boxes.at(np.array([dx, 0.0, rest + 0.2]), np.array([0.1, 0.1, 0.2]), 0.0)
    assert holds("on", src, host)
    sunk = Boxes.at(np.array([dx, 0.0, rest + 0.2 - 0.01]), np.array([0.1, 0.1, 0.2]), 0.0)
    assert not holds("on", sunk, host)


@settings(max_examples=40, deadline=None)
@given(top=st.floats(2.4, 4.0), height=st.floats(0.4, 1.2), name=st.sampled_from(["cage", "golden cage", "birdcage"]))
def test_what_is_put_on_a_cage_rests_on_its_floor_wherever_it_hangs(top, height, name):
    """A cage's load sits inside it, on its base (the container family's ``rest_inside``): a
    canary "in a cage" hung with its top at the ceiling still rests on it; a chest of the same
    family keeps its lid as its top."""
    from scenewright.layout.relations import rest_share, source_heights

    cage = box("cage", size=(0.5, 0.5, height), z=top - height / 2).model_copy(
        update={"category": "container", "name": name})
    floor = top - height + 0.08 * height
    assert rest_share(cage) == pytest.approx(0.08)
    (z,) = source_heights("on", 0.05, Boxes.of(cage), 0.0)
    canary = box("canary", size=(0.1, 0.1, 0.1), z=z)
    assert z == pytest.approx(floor + 0.05) and check("on", canary, cage)
    assert not check("on", box("canary", size=(0.1, 0.1, 0.1), z=top + 0.05), cage)  # not on its dome
    chest = cage.model_copy(update={"name": "toy chest"})
    assert rest_share(chest) == 1.0


@settings(max_examples=60, deadline=None)
@given(initial=st.floats(0.0, 8.0), half=st.floats(0.05, 0.5))
def test_above_offers_its_lowest_level_whatever_the_initial_height(initial, half):
    """A drone the arranger set above a low ceiling still has a level over the girl below it
    that fits under the ceiling: the lowest one the relation allows is always among the heights."""
    from scenewright.layout.relations import lowest_above, source_heights

    target = Boxes.of(T)
    heights = source_heights("above", half, target, initial)
    lowest = lowest_above(half, float(target.lo[2]), float(target.hi[2]))
    assert min(heights) == pytest.approx(lowest) and heights[0] == pytest.approx(max(initial, lowest))
    for z in heights:
        assert check("above", box("s", size=(0.2, 0.2, 2 * half), z=float(z)), T)


@settings(max_examples=40, deadline=None)
@given(yaw=st.floats(-180, 180), name=st.sampled_from(["trawler", "rowing boat", "yacht"]), seed=st.integers(0, 1000))
def test_what_is_put_on_a_boat_stands_on_its_deck_clear_of_the_cabin(yaw, name, seed):
    """A boat's top for ``on`` is its deck (a motor boat's before its cabin, an open boat's floor):
    the check, the solver's candidates and their height agree, wherever the boat is turned."""
    from scenewright.core.vessels import deck_area, deck_share
    from scenewright.layout.relations import rest_area, rest_share, source_heights

    boat = box("b", 1.0, -2.0, size=(4.0, 13.0, 5.0), yaw=yaw).model_copy(update={"category": "boat", "name": name})
    words = f"{name} boat"
    assert rest_share(boat) == deck_share(words, (4.0, 13.0, 5.0))
    assert tuple(rest_area(boat)) == deck_area(words, (4.0, 13.0, 5.0))
    target = Boxes.of(boat)
    half = np.array([0.25, 0.15, 0.9])
    pts = propose("on", half, target, np.array([1.0, -2.0]), np.random.default_rng(seed))
    (z,) = source_heights("on", 0.9, target, 0.0)
    assert z == pytest.approx(rest_share(boat) * 5.0 + 0.9)
    ok = holds("on", Boxes.at(np.column_stack([pts, np.full(len(pts), z)]), half, np.zeros(len(pts))), target)
    assert ok.all()
    a = np.radians(yaw)
    local = (pts - [1.0, -2.0]) @ np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
    x0, y0, x1, y1 = deck_area(words, (4.0, 13.0, 5.0))
    assert np.all((local[:, 0] >= x0 * 2.0 - 1e-6) & (local[:, 0] <= x1 * 2.0 + 1e-6))
    assert np.all((local[:, 1] >= y0 * 6.5 - 1e-6) & (local[:, 1] <= y1 * 6.5 + 1e-6))
    at_centre = box("p", 1.0, -2.0, size=(0.5, 0.3, 1.8), z=z)
    assert check("on", at_centre, boat) == (y0 <= 0.0 <= y1)  # a trawler's middle is its cabin
