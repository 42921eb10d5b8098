"""The room priors of analysis/composition/walls.py: what hangs, what is mounted, what stands against a wall."""

from __future__ import annotations

import pytest

from scenewright.analysis.composition.walls import ceiling_for, room_constraints
from scenewright.scene import Constraint, SceneObject, Vec3


def _o(oid: str, category: str, z: float) -> SceneObject:
    return SceneObject(id=oid, name=category, category=category, size=Vec3(x=0.5, y=0.5, z=z))


def test_a_thing_above_another_that_would_pass_the_ceiling_hangs_from_it_over_its_target():
    objects = [_o("lantern_1", "lantern", 0.4), _o("desk_1", "desk", 0.75), _o("mirror_1", "mirror", 0.8),
               _o("sink_1", "sink", 0.9), _o("lamp_1", "pendant_lamp", 0.3), _o("rug_1", "rug", 0.02),
               _o("drone_1", "drone", 0.2), _o("kite_1", "kite", 0.4), _o("wardrobe_1", "wardrobe", 1.9)]
    said = [Constraint(relation="above", source=s, target=t)
            for s, t in (("lantern_1", "desk_1"), ("mirror_1", "sink_1"), ("drone_1", "rug_1"),
                         ("kite_1", "wardrobe_1"))]
    got = {str(c) for c in room_constraints(objects, said, 2.7)}
    # Hung from the ceiling, its centre still 2 m over the desk's (0.375 + 2 + 0.2 <= 2.7): "above" holds there.
    assert {"lantern_1 on ceiling ceiling", "lantern_1 above desk_1"} <= got
    # Over a 1.9 m wardrobe no ceiling of 2.7 m leaves room for the paper's "above": near it.
    assert {"kite_1 on ceiling ceiling", "kite_1 near wardrobe_1"} <= got
    assert {"mirror_1 near sink_1", "mirror_1 on wall room"} <= got  # mounted: the wall gives the height
    assert "drone_1 above rug_1" in got  # 0.02 + 2 + 0.2 m fits under 2.7 m
    assert "lantern_1 above desk_1" in {str(c) for c in room_constraints(objects, said, 4.0)}


def test_a_thing_on_the_wall_above_another_keeps_above_and_puts_what_it_hangs_over_at_a_wall():
    objects = [_o("picture_frame_1", "picture_frame", 0.4), _o("dresser_1", "dresser", 0.8),
               _o("radio_1", "radio", 0.25), _o("sideboard_1", "table", 0.8), _o("wall_clock_1", "wall_clock", 0.3)]
    said = [Constraint(relation="above", source="picture_frame_1", target="dresser_1"),
            Constraint(relation="on", source="radio_1", target="sideboard_1"),
            Constraint(relation="above", source="wall_clock_1", target="radio_1")]
    got = {str(c) for c in room_constraints(objects, said, 3.2)}
    assert {"picture_frame_1 above dresser_1", "picture_frame_1 on wall room", "dresser_1 against wall room"} <= got
    # Over a thing standing on a table, the table is what goes to the wall.
    assert {"wall_clock_1 above radio_1", "sideboard_1 against wall room"} <= got
    assert "radio_1 against wall room" not in got
    # Under a low ceiling the wall gives the height and the target the place.
    low = {str(c) for c in room_constraints(objects, said, 2.4)}
    assert {"picture_frame_1 near dresser_1", "wall_clock_1 near radio_1"} <= low


def test_a_ceiling_nobody_sized_is_raised_for_what_hangs_above_another_up_to_a_limit():
    objects = [_o("picture_frame_1", "picture_frame", 0.4), _o("wardrobe_1", "wardrobe", 2.0),
               _o("kite_1", "kite", 0.5), _o("tree_1", "tree", 6.0)]
    said = [Constraint(relation="above", source="picture_frame_1", target="wardrobe_1")]
    # Its centre 2 m over the wardrobe's (1 m), its top 0.2 m higher, a hair under the ceiling: 3.25 m.
    assert ceiling_for(objects, said, 2.7) == pytest.approx(3.25)
    assert ceiling_for(objects, said, 3.5) == 3.5  # never lowered
    over_tree = [Constraint(relation="above", source="kite_1", target="tree_1")]
    assert ceiling_for(objects, over_tree, 2.7) == 2.7  # past TALLEST: left to the other rules


def test_above_a_thing_on_the_wall_is_near_it_and_raises_no_ceiling():
    objects = [_o("picture_frame_1", "picture_frame", 0.4), _o("mirror_1", "mirror", 0.8)]
    said = [Constraint(relation="above", source="picture_frame_1", target="mirror_1")]
    assert "picture_frame_1 near mirror_1" in {str(c) for c in room_constraints(objects, said, 3.4)}
    assert ceiling_for(objects, said, 2.7) == 2.7


def test_storage_beside_a_thing_goes_to_a_wall_but_between_two_stands_in_their_gap():
    objects = [_o("bookshelf_1", "bookshelf", 1.9), _o("sofa_1", "sofa", 0.85), _o("dresser_1", "dresser", 0.8),
               _o("bed_1", "bed", 0.6), _o("desk_1", "desk", 0.75)]
    said = [Constraint(relation="left of", source="bookshelf_1", target="sofa_1"),
            Constraint(relation="right of", source="dresser_1", target="bed_1"),
            Constraint(relation="left of", source="dresser_1", target="desk_1")]
    got = {str(c) for c in room_constraints(objects, said, 2.7)}
    assert "bookshelf_1 against wall room" in got
    assert "dresser_1 against wall room" not in got


def test_what_stands_on_a_thing_hung_above_another_counts_toward_the_ceiling():
    objects = [_o("shelf_1", "shop_shelf", 0.4), _o("sofa_1", "sofa", 0.8), _o("trunk_1", "crate", 0.5)]
    said = [Constraint(relation="above", source="shelf_1", target="sofa_1"),
            Constraint(relation="on wall", source="shelf_1", target="room"),
            Constraint(relation="on", source="trunk_1", target="shelf_1")]
    # The shelf's top at 0.4 + 2 + 0.2 = 2.6 m, and the trunk on it 0.5 m higher.
    assert ceiling_for(objects, said, 2.7) == pytest.approx(3.15)
    assert "shelf_1 near sofa_1" in {str(c) for c in room_constraints(objects, said, 2.9)}


def test_a_fireplace_and_a_tv_stand_stand_against_a_wall_even_with_a_seat_by_them():
    objects = [_o("fireplace_1", "fireplace", 1.2), _o("tv_stand_1", "tv_stand", 0.5), _o("armchair_1", "armchair", 0.9)]
    said = [Constraint(relation="near", source="armchair_1", target="fireplace_1")]
    got = {str(c) for c in room_constraints(objects, said, 2.7)}
    assert {"fireplace_1 against wall room", "tv_stand_1 against wall room"} <= got
    assert "armchair_1 against wall room" not in got


def test_a_cycle_of_on_does_not_hang_the_priors():
    objects = [_o("frame_1", "picture_frame", 0.4), _o("box_1", "crate", 0.3), _o("tin_1", "crate", 0.2),
               _o("chest_1", "dresser", 0.8)]
    said = [Constraint(relation=r, source=a, target=b)
            for r, a, b in (("on", "box_1", "frame_1"), ("on", "tin_1", "box_1"), ("on", "box_1", "tin_1"),
                            ("above", "frame_1", "chest_1"))]
    assert ceiling_for(objects, said, 2.7) >= 2.7
    assert room_constraints(objects, said, 3.0)


def test_what_rests_on_a_hung_thing_hangs_with_it_not_against_the_ceiling():
    """"A cage with two finches inside hangs from the ceiling": the finches are on the cage, and
    only the cage is mounted; a thing resting on nothing keeps its mounting."""
    objects = [_o("cage_1", "container", 0.8), _o("finch_1", "bird", 0.1), _o("lamp_1", "pendant_lamp", 0.3)]
    said = [Constraint(relation="on ceiling", source=s, target="ceiling") for s in ("cage_1", "finch_1", "lamp_1")]
    said.append(Constraint(relation="on", source="finch_1", target="cage_1"))
    got = {str(c) for c in room_constraints(objects, said, 3.0)}
    assert {"cage_1 on ceiling ceiling", "finch_1 on cage_1", "lamp_1 on ceiling ceiling"} <= got
    assert not any(c.startswith("finch_1 on ceiling") or c.startswith("finch_1 on wall") for c in got)


def test_a_flat_thing_above_another_goes_on_the_wall_over_it_not_under_the_ceiling():
    """A screen or a board above a thing is mounted on the wall (and its target stands at that
    wall); a lantern above the same thing hangs from the ceiling."""
    screen = SceneObject(id="screen_1", name="screen", category="monitor", size=Vec3(x=0.7, y=0.08, z=0.45))
    board = SceneObject(id="board_1", name="chalkboard", category="whiteboard", size=Vec3(x=1.6, y=0.05, z=1.0))
    objects = [screen, board, _o("locker_1", "cabinet", 1.2), _o("bench_1", "bench", 0.5),
               _o("lantern_1", "lantern", 0.4)]
    said = [Constraint(relation="above", source=s, target=t)
            for s, t in (("screen_1", "locker_1"), ("board_1", "bench_1"), ("lantern_1", "locker_1"))]
    got = {str(c) for c in room_constraints(objects, said, 3.0)}
    assert {"screen_1 on wall room", "board_1 on wall room", "locker_1 against wall room"} <= got
    assert "lantern_1 on ceiling ceiling" in got and "screen_1 on ceiling ceiling" not in got


def test_a_flat_thing_above_a_counter_someone_stands_behind_hangs_from_the_ceiling():
    """"A robot chef works behind the counter ... neon signs hang above the counter": the counter
    stands off the wall for its chef, so the signs hang over it from the ceiling (they pulled it
    against a side wall, the stools and the chef at its ends)."""
    sign = SceneObject(id="sign_1", name="neon sign", category="sign", size=Vec3(x=1.0, y=0.08, z=0.5))
    objects = [sign, _o("counter_1", "counter", 0.92), _o("robot_1", "robot", 1.7)]
    said = [Constraint(relation="above", source="sign_1", target="counter_1"),
            Constraint(relation="behind", source="robot_1", target="counter_1")]
    got = {str(c) for c in room_constraints(objects, said, 3.0)}
    assert "sign_1 on ceiling ceiling" in got
    assert not any(c.startswith("counter_1 against wall") or c.startswith("sign_1 on wall") for c in got)
    # with nobody behind it the sign goes on the wall and the counter to that wall, as before
    got = {str(c) for c in room_constraints(objects, said[:1], 3.0)}
    assert {"sign_1 on wall room", "counter_1 against wall room"} <= got
    # the text hangs it on the wall: it stays there, only near the counter its waiter stands behind
    stated = [*said, Constraint(relation="on wall", source="sign_1", target="room")]
    got = {str(c) for c in room_constraints(objects, stated, 3.0)}
    assert {"sign_1 on wall room", "sign_1 near counter_1"} <= got
    assert not any(c.startswith("counter_1 against wall") for c in got)
