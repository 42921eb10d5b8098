"""The room's demands on a layout (layout/room.py) and the solver keeping them: containment in
rectangles and L-shapes, door and window strips kept clear, walkability from the doors."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from scenewright.layout import audit, check, solve
from scenewright.layout.relations import check_room
from scenewright.layout.room import SLACK, RoomShape, access_trouble, boxes_of, problems, wall_facing
from scenewright.scene import Constraint, Opening, Room, SceneObject, Vec3

L_SHAPE = [(0.0, 0.0), (5.0, 0.0), (5.0, 2.5), (2.5, 2.5), (2.5, 5.0), (0.0, 5.0)]


def box(oid: str, x: float, y: float, sx: float = 1.0, sy: float = 1.0, sz: float = 1.0, yaw: float = 0.0,
        z: float | None = None) -> SceneObject:
    return SceneObject(id=oid, name=oid, size=Vec3(x=sx, y=sy, z=sz),
                       position=Vec3(x=x, y=y, z=sz / 2 if z is None else z), rotation=Vec3(z=yaw))


def door_room(width: float = 4.0, depth: float = 5.0) -> Room:
    room = Room.rectangle(width, depth)
    return Room.model_validate({**room.model_dump(), "openings": [
        Opening(kind="door", wall=3, offset=depth - 0.8, width=0.9, height=2.1),
        Opening(kind="window", wall=2, offset=width / 2, width=1.2, height=1.2, sill=0.9),
    ]})


def test_outside_by_measures_how_far_a_footprint_pokes_through_a_wall():
    shape = RoomShape(Room.rectangle(4, 5))
    out = shape.outside_by(boxes_of([box("in", 0, 0), box("poke", 1.8, 0), box("far", 10, 10)]))
    assert out[0] == 0
    assert out[1] == pytest.approx(0.3)
    assert out[2] > 10


def test_a_box_over_the_inner_corner_of_an_l_shape_is_outside_though_its_corners_are_in():
    shape = RoomShape(Room(floor=L_SHAPE))
    # It straddles the inner corner at (2.5, 2.5) with its centre on the floor: only the corner
    # (2.8, 2.8) is off it, and the walls meeting there poke 0.3 m into it.
    out = shape.outside_by(boxes_of([box("corner", 2.3, 2.3, 1.0, 1.0), box("arm", 1.0, 4.0), box("turned", 1.2, 1.2, 1.2, 0.4, yaw=45)]))
    assert out[0] == pytest.approx(0.3, abs=1e-6)
    assert out[1] == 0 and out[2] == 0


def test_door_strip_blocks_floor_things_and_window_strip_only_what_rises_past_the_sill():
    room = door_room()
    shape = RoomShape(room)
    door_y = 2.5 - (5.0 - 0.8)  # the left wall runs from the back corner to the front one
    objects = [
        box("in_door", -1.6, door_y, 0.6, 0.6, 0.8),
        box("desk_under_window", 0.0, 2.15, 1.2, 0.6, 0.75),
        box("wardrobe_at_window", 0.0, 2.2, 1.2, 0.6, 2.0),
        box("lamp_over_door", -1.6, door_y, 0.5, 0.5, 0.4, z=2.4),
    ]
    blocking = shape.blocking(boxes_of(objects))
    assert blocking[0] > 0 and blocking[2] > 0
    assert blocking[1] == 0 and blocking[3] == 0
    said = problems(room, objects)
    assert any("door 0 on wall_3 is blocked by in_door" in p for p in said)
    assert any("window 1 on wall_2 is blocked by wardrobe_at_window" in p for p in said)


def test_a_wall_of_furniture_across_the_room_leaves_the_far_side_unreachable():
    room = door_room()
    shelf_row = [box(f"shelf_{k}", -1.5 + k, 0.0, 1.0, 0.4, 1.9) for k in range(4)]
    behind = box("chair", 0.0, 1.5, 0.5, 0.5, 0.9)
    front = box("table", 0.0, -1.5, 0.8, 0.8, 0.75)
    missed, stuck = RoomShape(room).unreachable([*shelf_row, behind, front])
    assert stuck == []
    assert "chair" in missed and "table" not in missed
    # With a gap the agent fits through, everything is reached.
    opened = [o for o in shelf_row if o.id != "shelf_1"]
    assert RoomShape(room).unreachable([*opened, behind, front]) == ([], [])


def test_trouble_a_larger_room_could_cure_counts_each_object_out_of_reach():
    """One sentence names every object out of reach; growing a room must still see seven of
    them as worse than one (a troop bay kept seven seats unreachable over a grown room with one)."""
    room = door_room()
    shelf_row = [box(f"shelf_{k}", -1.5 + k, 0.0, 1.0, 0.4, 1.9) for k in range(4)]
    one = [*shelf_row, box("chair_0", 0.0, 1.5, 0.5, 0.5, 0.9)]
    three = [*one, box("chair_1", -1.2, 1.5, 0.5, 0.5, 0.9), box("chair_2", 1.2, 1.5, 0.5, 0.5, 0.9)]
    assert len(problems(room, one)) == len(problems(room, three)) == 1
    assert (access_trouble(room, one), access_trouble(room, three)) == (1, 3)
    assert access_trouble(Room.rectangle(3, 3), [box("a", 0, 0)]) == 0  # no door: no larger floor cures that


def test_a_room_without_a_door_is_reported():
    assert "the room has no door" in problems(Room.rectangle(3, 3), [box("a", 0, 0)])


def test_wall_facing_picks_the_wall_whose_outside_faces_that_way():
    rect = Room.rectangle(4, 5)
    assert [wall_facing(rect, s) for s in ("front", "right", "back", "left")] == [0, 1, 2, 3]
    ell = Room(floor=L_SHAPE)
    # Two walls face back (+Y): the far one (y = 5) is the back wall.
    assert wall_facing(ell, "back") == 4
    assert wall_facing(ell, "right") == 1
    with pytest.raises(ValueError, match="unknown side"):
        wall_facing(ell, "up")


def test_solver_keeps_room_relations_and_reports_what_it_cannot():
    room = door_room()
    objects = [box("bed", 0, 0, 1.6, 2.1, 0.6), box("wardrobe", 0, 0, 1.2, 0.6, 2.0), box("mirror", 0, 0, 0.6, 0.04, 0.9),
               box("fan", 0, 0, 1.0, 1.0, 0.4), box("plant", 0, 0, 0.5, 0.5, 1.0)]
    constraints = [
        Constraint(relation="against wall", source="bed", target="wall_2"),
        Constraint(relation="against wall", source="wardrobe", target="room"),
        Constraint(relation="on wall", source="mirror", target="room"),
        Constraint(relation="on ceiling", source="fan", target="ceiling"),
        Constraint(relation="in corner", source="plant", target="room"),
    ]
    result = solve(objects, constraints, room=room, seed=1)
    assert result.report.unplaced == [] and result.report.room == []
    by_id = {o.id: o for o in result.objects}
    for c in constraints:
        assert check_room(c.relation, by_id[c.source], room, c.target), str(c)
    assert by_id["bed"].position.y > 1.0 and by_id["bed"].yaw % 360 == pytest.approx(0.0, abs=1e-6)
    mirror = by_id["mirror"]
    assert 0.3 <= mirror.position.z - mirror.size.z / 2 and mirror.position.z + mirror.size.z / 2 <= room.height
    assert by_id["fan"].position.z + 0.2 == pytest.approx(room.height, abs=0.02)


def test_room_relations_without_a_room_are_dropped_with_the_reason():
    result = solve([box("bed", 0, 0)], [Constraint(relation="against wall", source="bed", target="room")])
    assert result.constraints == []
    assert "needs a room" in result.report.dropped[0].reason


def test_a_wall_that_does_not_exist_is_dropped_naming_the_walls():
    result = solve([box("bed", 0, 0)], [Constraint(relation="against wall", source="bed", target="wall_7")],
                   room=Room.rectangle(4, 4))
    assert "wall_0 .. wall_3" in result.report.dropped[0].reason


def test_a_room_too_small_reports_what_does_not_fit_and_by_how_much():
    objects = [box(f"crate_{k}", 0, 0, 1.0, 1.0, 1.0) for k in range(6)]
    result = solve(objects, [], room=Room.rectangle(2.0, 2.0), seed=0)
    assert result.report.unplaced
    assert result.report.room[0].startswith(", ".join(u.id for u in result.report.unplaced) + " do not fit: the floor objects cover 6.0 m² of the 4.0 m² floor (150%); about 13.1 m² more floor")


@st.composite
def rooms_and_objects(draw, near: bool = False):
    if draw(st.booleans()):
        width, depth = draw(st.floats(3.0, 8.0)), draw(st.floats(3.0, 8.0))
        room = Room.rectangle(width, depth)
    else:
        a, b = draw(st.floats(4.0, 8.0)), draw(st.floats(4.0, 8.0))
        cut_x, cut_y = draw(st.floats(0.4, 0.6)) * a, draw(st.floats(0.4, 0.6)) * b
        room = Room(floor=[(0, 0), (a, 0), (a, cut_y), (cut_x, cut_y), (cut_x, b), (0, b)])
    area = RoomShape(room).area
    objects, used = [], 0.0
    for k in range(draw(st.integers(1, 6))):
        sx, sy = draw(st.floats(0.3, 1.5)), draw(st.floats(0.3, 1.5))
        if used + sx * sy > 0.2 * area:
            break
        used += sx * sy
        reach = 5 if near else 10  # near: most of them on the floor or across a wall
        objects.append(box(f"o{k}", draw(st.floats(-reach, reach)), draw(st.floats(-reach, reach)), sx, sy,
                           draw(st.floats(0.2, 2.0)),
                           yaw=draw(st.sampled_from([0.0, 30.0, 90.0]))))
    return room, objects


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rooms_and_objects(), st.integers(0, 3))
def test_every_object_the_solver_places_lies_inside_the_floor(case, seed):
    room, objects = case
    result = solve(objects, [], room=room, seed=seed, time_limit=5.0)
    placed = [o for o in result.objects if o.id in set(result.report.placed)]
    assert len(placed) == len(objects)
    out = RoomShape(room).outside_by(boxes_of(placed))
    assert np.all(out <= SLACK), dict(zip([o.id for o in placed], out))


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rooms_and_objects())
def test_wall_things_placed_against_random_walls_hold_against_wall(case):
    room, objects = case
    constraints = [Constraint(relation="against wall", source=o.id, target="room") for o in objects]
    result = solve(objects, constraints, room=room, seed=0, time_limit=5.0)
    placed = {o.id: o for o in result.objects if o.id in set(result.report.placed)}
    for c in constraints:
        if c.source in placed:
            assert check_room("against wall", placed[c.source], room)
    assert RoomShape(room).outside_by(boxes_of(list(placed.values()))).max(initial=0) <= SLACK


def test_without_the_solver_room_relations_are_audited():
    room = door_room()
    objects = [box("bed", 0, 0, 1.6, 2.1, 0.6), box("mirror", 0, 0, 0.6, 0.04, 0.9)]
    constraints = [Constraint(relation="against wall", source="bed", target="wall_2"),
                   Constraint(relation="on wall", source="mirror", target="room")]
    result = audit(objects, constraints, room=room)
    assert {u.id for u in result.report.unplaced} == {"bed", "mirror"}
    assert all("violates" in u.reason for u in result.report.unplaced)
    assert any("does not hold" in line for line in result.report.room)


def _plain_walk(room: Room, boxes, reach):
    """The walkability check written out plainly, for comparison: every footprint's distance to
    every grid cell of the whole room, nothing kept between calls."""
    from scipy import ndimage

    from scenewright.layout.relations import _rectangle, _to_rectangle
    from scenewright.layout.room import AGENT_RADIUS, CELL, FLOOR, HEAD_ROOM, REACH, _strip

    shape = RoomShape(room)
    grid, free = shape._grid()
    standing = (boxes.lo[:, 2] < HEAD_ROOM) & (boxes.hi[:, 2] > FLOOR)
    for c, h, x in zip(*_rectangle(boxes[standing])):
        free = free & (_to_rectangle(grid, c, h, x) >= AGENT_RADIUS)
    labels, _ = ndimage.label(free)
    reached, stuck = set(), []
    for k, o in enumerate(room.openings):
        if o.kind != "door":
            continue
        rect, _, _ = _strip(room, o)
        local = np.einsum("...j,ij->...i", grid - rect.centre[0], rect.axes[0])
        found = set(np.unique(labels[free & np.all(np.abs(local) <= rect.half[0] + 1e-9, axis=-1)])) - {0}
        stuck += [] if found else [k]
        reached |= found
    walked = np.isin(labels, sorted(reached))
    limit = AGENT_RADIUS + REACH + CELL
    missed = [int(i) for i in np.flatnonzero(reach)
              if not np.any(_to_rectangle(grid, *(a[i] for a in _rectangle(boxes)))[walked] <= limit)]
    return missed, stuck


@st.composite
def walk_cases(draw):
    width, depth = draw(st.floats(2.5, 7.0)), draw(st.floats(2.5, 7.0))
    room = Room.rectangle(width, depth)
    doors = [Opening(kind="door", wall=w, offset=draw(st.floats(0.5, 2.0)), width=0.9, height=2.1)
             for w in draw(st.lists(st.integers(0, 3), min_size=1, max_size=2, unique=True))]
    room = Room.model_validate({**room.model_dump(), "openings": doors})
    layouts = []
    for _ in range(draw(st.integers(1, 4))):  # several layouts through one room shape
        n = draw(st.integers(1, 9))
        objects = [box(f"o{k}", draw(st.floats(-width / 2, width / 2)), draw(st.floats(-depth / 2, depth / 2)),
                       draw(st.floats(0.2, 2.5)), draw(st.floats(0.2, 1.2)), draw(st.sampled_from([0.02, 0.8, 2.0])),
                       yaw=draw(st.sampled_from([0.0, 30.0, 90.0, 135.0])))
                   for k in range(n)]
        layouts.append(objects)
    return room, layouts


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(walk_cases())
def test_the_kept_walkability_check_answers_as_the_plain_one(case):
    """The room shape keeps each footprint's grid cells between calls (the solver asks about
    the same placed objects with every pose it tries): its answers are the plain check's."""
    room, layouts = case
    shape = RoomShape(room)
    for objects in layouts + layouts[::-1]:
        boxes = boxes_of(objects)
        reach = boxes.lo[:, 2] < 0.05
        assert shape.walk(boxes, reach) == _plain_walk(room, boxes, reach)


def test_resized_stretches_any_floor_and_keeps_each_opening_on_its_wall_at_its_share():
    from scenewright.layout.room import resized

    room = Room.model_validate({"floor": L_SHAPE, "openings": [
        Opening(kind="door", wall=0, offset=1.0, width=0.9, height=2.1),
        Opening(kind="window", wall=4, offset=2.0, width=1.0, height=1.2, sill=0.9)]})
    big = resized(room, 10.0, 7.5, 3.0)
    assert big.floor == [(-2.5, -1.25), (7.5, -1.25), (7.5, 2.5), (2.5, 2.5), (2.5, 6.25), (-2.5, 6.25)]
    assert big.height == 3.0
    assert [(o.wall, o.offset) for o in big.openings] == [(0, 2.0), (4, pytest.approx(4.0))]
    small = resized(room, 2.0, 2.0)  # the window's wall is 1 m now: it no longer fits
    assert [o.kind for o in small.openings] == ["door"]


def test_a_box_past_the_ceiling_misfits_and_is_reported():
    room = door_room()
    shape = RoomShape(room)
    objects = [box("under", 0, 0, sz=1.0, z=2.1), box("through", 1, 1, sz=1.0, z=2.5)]
    assert list(shape.above_ceiling(boxes_of(objects))) == [0.0, pytest.approx(0.3)]
    assert shape.misfit(boxes_of(objects))[1] == pytest.approx(0.3)
    assert "through reaches 0.30 m above the ceiling" in problems(room, objects)


def test_a_room_for_many_floor_objects_leaves_more_floor_to_walk_per_object():
    from scenewright.layout.room import COVERAGE, WALL_SERVED, floor_needed

    # Up to the objects the walls serve, the floor is the footprint at COVERAGE ...
    assert floor_needed(10.0, WALL_SERVED) == pytest.approx(10.0 / COVERAGE)
    assert floor_needed(3.0, 5) == pytest.approx(3.0 / COVERAGE)
    # ... beyond, each object gets more floor, like √n: four times the objects, twice the share.
    per_object = [floor_needed(0.5 * n, n) / n for n in (WALL_SERVED, 2 * WALL_SERVED, 4 * WALL_SERVED)]
    assert per_object[0] < per_object[1] < per_object[2]
    assert per_object[2] == pytest.approx(2.0 * per_object[0])


def test_a_room_sized_for_many_floor_objects_gives_each_more_floor():
    from scenewright.analysis.parser.room import build_room, read_room
    from scenewright.layout.room import COVERAGE, WALL_SERVED

    def sofas(n):
        return [SceneObject(id=f"sofa_{k}", name="sofa", category="sofa", size=Vec3(x=2.0, y=0.9, z=0.85))
                for k in range(n)]

    n = 3 * WALL_SERVED
    room = RoomShape(build_room(read_room(f"a showroom with {n} sofas"), sofas(n)))
    covered = n * 2.0 * 0.9 / room.area
    assert covered <= COVERAGE * (WALL_SERVED / n) ** 0.5 + 1e-9


def test_a_thing_on_the_wall_above_one_against_it_hangs_over_it_at_the_height_above_asks():
    room = Room.rectangle(4.0, 3.0, 3.3)
    objects = [box("dresser", 0, 0, 1.2, 0.5, 1.4), box("frame", 1, 1, 0.6, 0.04, 0.5, z=1.5)]
    constraints = [
        Constraint(relation="against wall", source="dresser", target="room"),
        Constraint(relation="on wall", source="frame", target="room"),
        Constraint(relation="above", source="frame", target="dresser"),
    ]
    result = solve(objects, constraints, room=room, seed=3)
    assert result.report.unplaced == []
    by_id = {o.id: o for o in result.objects}
    assert check("above", by_id["frame"], by_id["dresser"])
    assert check_room("on wall", by_id["frame"], room, "room")


def test_the_front_wall_is_the_last_a_thing_is_stood_against():
    """Nearest the anchor first, but a spot on the viewer's front wall only after every other
    wall's: a fireplace there would show the camera its back."""
    from scenewright.layout.relations import FRONT_PENALTY, RoomTarget, propose_wall

    room = RoomTarget.of(Room.rectangle(6, 6))
    anchor = np.array([0.0, -2.5])  # close to the front wall
    xy, yaws, cost = propose_wall("against wall", np.array([0.75, 0.25]), room, anchor)
    assert np.all(np.diff(cost) >= 0)
    front = xy[:, 1] < -2.5
    assert front.any() and not front[0]
    assert np.all(cost[front] >= FRONT_PENALTY)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rooms_and_objects(near=True), st.lists(st.floats(0.0, 3.5), min_size=6, max_size=6))
def test_fits_answers_as_a_zero_misfit_does(case, heights):
    # The solver asks fits() of its candidates (the cheap measures first): the same answer as misfit().
    room, objects = case
    room = Room.model_validate({**room.model_dump(), "height": 2.7, "openings": [
        Opening(kind="door", wall=0, offset=1.0, width=0.9, height=2.1),
        Opening(kind="window", wall=1, offset=1.0, width=1.2, height=1.2, sill=0.9),
    ]})
    shape = RoomShape(room)
    lifted = [o.model_copy(update={"position": Vec3(x=o.position.x, y=o.position.y, z=z)})
              for o, z in zip(objects, heights)]
    boxes = boxes_of(lifted)
    assert list(shape.fits(boxes)) == list(shape.misfit(boxes) <= 1e-9)
    # outside_by() and blocking() skip what their plan extents clear: the full measures agree.
    assert list(shape.outside_by(boxes)) == list(shape._outside_by(boxes))
    full = np.zeros(len(lifted))
    for _, rect, bottom, top in shape.strips:
        band = (boxes.lo[:, 2] < top - 1e-9) & (boxes.hi[:, 2] > bottom + 1e-9)
        full = np.maximum(full, np.where(band, shape._penetration(boxes, rect)[:, 0], 0.0))
    assert list(shape.blocking(boxes)) == list(np.where(full > SLACK, full, 0.0))
