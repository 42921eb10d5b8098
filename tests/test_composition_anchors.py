"""A group the text anchors in the room moves there as one (composition.anchors)."""

import pytest

from scenewright.analysis.arrange import compose
from scenewright.analysis.composition.anchors import into_room
from scenewright.analysis.parser import parse_scene
from scenewright.geometry import front_direction, world_box
from scenewright.layout import relations as rel
from scenewright.scene import Room


def _placed(text: str, room: Room):
    parsed = parse_scene(text)
    composition = compose(parsed)
    objects = {o.id: o for o in into_room(composition.objects, room, composition.anchored)}
    return parsed, composition, objects


def _inside(obj, room: Room) -> bool:
    (lo, hi) = world_box(obj)
    xs, ys = [p[0] for p in room.floor], [p[1] for p in room.floor]
    return lo[0] >= min(xs) - 1e-6 and lo[1] >= min(ys) - 1e-6 and hi[0] <= max(xs) + 1e-6 and hi[1] <= max(ys) + 1e-6


def test_a_group_at_the_back_goes_to_the_back_wall_as_one():
    room = Room.rectangle(5.0, 4.0)
    text = ("An upright piano stands at the back of the room with a bench in front of it. A music stand is to "
            "the left of the piano, and a tall plant stands behind the music stand. A small rug lies in front of "
            "the bench.")
    parsed, composition, objects = _placed(text, room)
    (group,) = composition.anchored
    assert (group.member, group.anchor) == ("piano_1", "back")
    assert set(group.ids) == {o.id for o in parsed.objects}
    piano = objects["piano_1"]
    assert world_box(piano)[1][1] == pytest.approx(2.0, abs=0.03)  # its back at the back wall
    # the bench keeps its place before the keys: the group moved, not the piano alone
    before = {o.id: o for o in composition.objects}
    offset = lambda objs: (objs["bench_1"].position.x - objs["piano_1"].position.x,  # noqa: E731
                           objs["bench_1"].position.y - objs["piano_1"].position.y)
    assert offset(objects) == pytest.approx(offset(before), abs=1e-3)
    # what stood behind the piano's line (the plant behind the stand) steps in, the stand before it
    assert all(_inside(o, room) for o in objects.values())
    for r in parsed.relations:
        assert rel.check(r.relation, objects[r.source], objects[r.target]), r


def test_a_desk_in_the_corner_takes_its_chair_into_the_nearer_back_corner():
    room = Room.rectangle(5.0, 4.0)
    text = "A wide desk stands in the corner, with an office chair in front of it and a bin to the right of the desk."
    parsed, composition, objects = _placed(text, room)
    desk, chair = objects["desk_1"], objects["office_chair_1"]
    lo, hi = world_box(desk)
    assert hi[1] == pytest.approx(2.0, abs=0.03)
    assert lo[0] == pytest.approx(-2.5, abs=0.03) or hi[0] == pytest.approx(2.5, abs=0.03)
    assert rel.check("in front of", chair, desk) and world_box(chair)[1][1] > world_box(desk)[0][1] - 0.5
    assert all(_inside(o, room) for o in objects.values())


def test_nothing_is_set_out_behind_a_group_the_text_puts_at_the_back():
    text = ("An upright piano stands at the back of the room with a bench in front of it. A desk with a lamp on it "
            "stands in the room, and an office chair is in front of the desk. A wardrobe and a bookshelf stand nearby.")
    composition = compose(parse_scene(text))
    objects = {o.id: o for o in composition.objects}
    back = world_box(objects["piano_1"])[1][1]
    assert all(world_box(o)[1][1] <= back + 1e-6 for o in objects.values())


def test_one_thing_against_the_wall_is_left_to_its_room_relation():
    assert compose(parse_scene("A wardrobe stands against the wall.")).anchored == ()


def test_the_member_the_text_puts_in_the_middle_stands_at_the_origin():
    text = "A cat sleeps in the middle of the room, next to a round table with two chairs around it."
    parsed = parse_scene(text)
    (cat,) = [o for o in parsed.objects if o.anchor == "centre"]
    placed = {o.id: o for o in compose(parsed).objects}[cat.id]
    assert (placed.position.x, placed.position.y) == pytest.approx((0.0, 0.0), abs=1e-6)


def test_a_composition_stands_centred_so_its_room_holds_it():
    """The room is built centred on the origin around the first poses: groups packed to one side
    of the first would start outside it (and be squeezed along a wall by the solver)."""
    from scenewright.analysis.parser.room import room_for

    text = ("A busy joinery workshop: a long workbench with two stools, a lathe, a drill press, a table saw, "
            "a tall cabinet of tools, a rack of clamps, a stack of planks, a sawhorse, a glue pot on a shelf, "
            "three barrels, two crates and a wheelbarrow.")
    objects = compose(parse_scene(text)).objects
    room = room_for(text, objects)
    ground = [o for o in objects if o.position.z - o.size.z / 2 < 0.05 and o.size.z >= 0.1]
    lo = [min(world_box(o)[0][i] for o in ground) for i in (0, 1)]
    hi = [max(world_box(o)[1][i] for o in ground) for i in (0, 1)]
    assert [(a + b) / 2 for a, b in zip(lo, hi)] == pytest.approx([0.0, 0.0], abs=1e-3)
    assert all(_inside(o, room) for o in ground)


def test_stools_line_a_counter_and_go_to_the_wall_with_it():
    """A designer lines the bar stools up along the counter's front, facing it; in a room the
    counter stands against a wall, so it goes there with its stools, not alone."""
    room = Room.rectangle(6.0, 5.0)
    parsed, composition, objects = _placed("A roadside diner with a long counter, three stools and a jukebox.", room)
    counter = objects["counter_1"]
    stools = [objects[f"stool_{k}"] for k in (1, 2, 3)]
    for stool in stools:
        assert rel.check("in front of", stool, counter)
        assert abs(stool.position.y - counter.position.y) < counter.size.y / 2 + stool.size.y + 0.3
        d = front_direction(stool.rotation.z)
        assert d[1] > 0.99  # facing the counter behind it (+Y)
    assert sorted(round(s.position.y, 3) for s in stools)[0] == sorted(round(s.position.y, 3) for s in stools)[-1]
    assert world_box(counter)[1][1] == pytest.approx(2.5, abs=0.03)  # its back at the back wall
    assert any(g.member == "counter_1" for g in composition.anchored)


def test_a_hung_thing_in_the_middle_does_not_pin_the_group_under_it():
    """"A fan in the middle of the room" hangs there whatever stands under it: the group under
    it (a bed against the back wall, its rug, the cat on the rug) is not held at the centre,
    and the other groups are not packed out of a small room in front of it."""
    room = Room.rectangle(4.0, 5.0)
    text = ("A narrow bed stands against the back wall with a small rug in front of it, and a cat sleeps on the rug. "
            "A ceiling fan turns in the middle of the room above the cat. A desk with a chair in front of it stands "
            "nearby, and a tall wardrobe.")
    parsed, composition, objects = _placed(text, room)
    assert {o.id: o.anchor for o in parsed.objects}.get("ceiling_fan_1") == "centre"
    # nothing pins the middle: the composition stands centred as a whole, as any other
    ground = [o for o in composition.objects if o.position.z - o.size.z / 2 < 0.05 and o.size.z >= 0.1]
    lo = [min(world_box(o)[0][i] for o in ground) for i in (0, 1)]
    hi = [max(world_box(o)[1][i] for o in ground) for i in (0, 1)]
    assert [(a + b) / 2 for a, b in zip(lo, hi)] == pytest.approx([0.0, 0.0], abs=1e-3)
    # and the bed's group goes to the back wall as one, inside the room
    assert world_box(objects["bed_1"])[1][1] == pytest.approx(2.5, abs=0.03)
    assert _inside(objects["bed_1"], room) and _inside(objects["cat_1"], room)
