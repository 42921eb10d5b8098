"""Reading the room from the text (analysis/parser/room.py): size, height, openings, sides,
the --room option, rooms sized around their objects, room relations from wall phrases."""

from __future__ import annotations

import pytest

from scenewright.analysis.parser import parse_scene
from scenewright.analysis.parser.room import (
    COVERAGE,
    RECTANGLE_WALLS,
    build_room,
    floor_area,
    parse_room_option,
    place_openings,
    read_room,
    room_for,
    wall_phrases,
)
from scenewright.errors import InputError
from scenewright.layout.room import RoomShape
from scenewright.scene import Room, SceneObject, Vec3


@pytest.mark.parametrize(
    "text, size, height",
    [
        ("a 4 by 5 m bedroom with a bed", (4.0, 5.0), None),
        ("A 4x5 metre room with a desk", (4.0, 5.0), None),
        ("the kitchen measures 3 by 4 m", (3.0, 4.0), None),
        ("a living room 5 x 6 m with high ceilings", (5.0, 6.0), 3.4),
        ("a 12 by 15 feet office", (12 * 0.3048, 15 * 0.3048), None),
        ("a 2 by 1 m rug in a bedroom", None, None),  # the rug's size, not the room's
        ("a room with a 3 m ceiling and a sofa", None, 3.0),
        ("a small, low-ceilinged attic with a cot", None, 2.4),
        ("a high-ceilinged gallery with two statues", None, 3.4),
    ],
)
def test_read_room_reads_the_stated_size_and_height(text, size, height):
    got = read_room(text)
    assert got.size == (pytest.approx(size) if size else None)
    assert got.height == height


def test_size_words_scale_the_place_and_only_the_place():
    assert read_room("a small bathroom with a tub").scale < 1 < read_room("a large open-plan kitchen").scale
    assert read_room("a kitchen with a small table").scale == 1.0


def test_openings_with_their_walls_and_counts():
    got = read_room("a large open-plan kitchen with two windows on the back wall and a door on the right wall")
    assert got.openings == (("window", "back", 2), ("door", "right", 1))
    # "the door" refers to the door already named; a plural with no count is two
    assert read_room("a study with a door and a desk next to the door").openings == (("door", None, 1),)
    assert read_room("a bedroom with large windows").openings == (("window", None, 2),)


@pytest.mark.parametrize("value", ["0x5", "5x0", "4 by 5", "big", "4x5x30", "-4x5", "4x5x1"])
def test_bad_room_options_name_the_value(value):
    with pytest.raises(InputError, match=f"--room {value!r}"):
        parse_room_option(value)


def test_room_options():
    assert parse_room_option(None) == "auto" and parse_room_option(" NONE ") == "none"
    assert parse_room_option("4x5") == (4.0, 5.0, None)
    assert parse_room_option("4.5×6x3") == (4.5, 6.0, 3.0)


def _objects(*sizes):
    return [SceneObject(id=f"o{k}", name="crate", category="crate", size=Vec3(x=x, y=y, z=z))
            for k, (x, y, z) in enumerate(sizes)]


def test_a_room_sized_around_its_objects_leaves_walking_space():
    objects = _objects(*[(1.2, 0.8, 0.9)] * 8)
    room = build_room(read_room("a storeroom full of crates"), objects)
    area = RoomShape(room).area
    need, longest = floor_area(objects)
    assert need / area <= COVERAGE + 1e-9
    assert min(room.wall_length(0), room.wall_length(1)) >= longest + 1.8
    assert [o.kind for o in room.openings].count("door") >= 1


def test_rugs_and_hung_things_take_no_floor():
    rug = SceneObject(id="rug", name="rug", category="rug", size=Vec3(x=3, y=2, z=0.02))
    mirror = SceneObject(id="m", name="mirror", category="mirror", size=Vec3(x=0.6, y=0.04, z=0.9))
    assert floor_area([rug, mirror]) == (0.0, 0.0)


def test_openings_default_to_a_door_and_a_back_window_and_never_overlap():
    room = Room.rectangle(4, 5)
    openings = place_openings(room, [])
    assert {(o.kind, o.wall) for o in openings} == {("door", RECTANGLE_WALLS["left"]), ("window", RECTANGLE_WALLS["back"])}
    crowded = place_openings(room, [("window", "back", 4), ("door", "back", 1)])
    spans = sorted((o.offset - o.width / 2, o.offset + o.width / 2) for o in crowded if o.wall == 2)
    assert all(a[1] <= b[0] for a, b in zip(spans, spans[1:]))
    assert all(0 <= lo and hi <= room.wall_length(2) for lo, hi in spans)


def test_room_for_follows_the_option_and_the_text():
    objects = _objects((1, 1, 1))
    assert room_for("a bedroom with a bed", objects, "none") is None
    assert room_for("a park with a bench", objects, "auto") is None
    assert room_for("a bedroom with a bed", objects, "auto") is not None
    fixed = room_for("a park with a bench", objects, (3.0, 4.0, None))
    assert (fixed.wall_length(0), fixed.wall_length(1), fixed.height) == (3.0, 4.0, 2.7)
    assert room_for("a bedroom", objects, "auto", proposal=None, proposed=True) is None


def test_wall_phrases_become_room_relations_with_their_wall():
    parsed = parse_scene("A cosy bedroom. A bed stands against the back wall with a nightstand beside it. "
                         "A wardrobe is in the corner. A painting hangs on the left wall.")
    got = {(r.source, r.relation, r.target) for r in wall_phrases(parsed)}
    assert got == {("bed_1", "against wall", "wall_2"), ("wardrobe_1", "in corner", "room"),
                   ("picture_frame_1", "on wall", "wall_3")}


def test_a_thing_leaning_on_a_wall_stands_against_it():
    parsed = parse_scene("A bicycle leans on the wall. A clock hangs on the wall.")
    got = {(r.source, r.relation, r.target) for r in wall_phrases(parsed)}
    assert got == {("bicycle_1", "against wall", "room"), ("wall_clock_1", "on wall", "room")}


def test_a_wall_thing_does_not_take_the_corner_of_the_next_clause():
    """A mirror is a wall thing, and a wall phrase after another thing still hangs it ("a mirror
    above the basin on the left wall"); a corner phrase there belongs to the thing named before it."""
    parsed = parse_scene("A small gym. A big mirror hangs above the bench press, and a fan stands in the corner. "
                         "A clock over the door on the right wall.")
    got = {(r.source, r.relation, r.target) for r in wall_phrases(parsed)}
    assert ("fan_1", "in corner", "room") in got and ("wall_clock_1", "on wall", "wall_1") in got
    assert not any(source == "mirror_1" for source, _, _ in got)


def test_a_thing_at_the_far_end_does_not_take_the_wall_of_the_next_clause():
    """The stage at the far end stands against the back wall, a low platform on the floor, and
    the screen named after it hangs (the stage took the screen's "on the wall" and was stood on
    end as a board 5 m high)."""
    parsed = parse_scene("A pub. The quizmaster stands on a low stage at the far end with a microphone in his hand, "
                         "and a projector screen hangs on the wall behind him.")
    got = {(r.source, r.relation, r.target) for r in wall_phrases(parsed)}
    assert got == {("projector_screen_1", "on wall", "room"), ("stage_1", "against wall", "wall_2")}
    stage = next(o for o in parsed.objects if o.name.endswith("stage"))
    assert stage.size[2] < 1.0 < stage.size[1]


def test_the_nearest_of_a_wall_and_a_ceiling_phrase_after_a_thing_places_it():
    """A thing takes the first phrase after its name: hung on the wall when the wall comes first,
    though the ceiling is named later in the sentence for something the parse did not keep; a
    ceiling with a word before it ("the vaulted ceiling") is the ceiling."""
    parsed = parse_scene("A boathouse. Two oars hang on hooks on the left wall, and a haze of smoke hangs from "
                         "the ceiling. Three lanterns hang from the beamed ceiling above the barrel.")
    got = {(r.source, r.relation, r.target) for r in wall_phrases(parsed)}
    assert ("oar_1", "on wall", "wall_3") in got and ("oar_1", "on ceiling", "ceiling") not in got
    assert ("lantern_1", "on ceiling", "ceiling") in got


def test_plural_names_fellow_subjects_and_fixing_verbs_put_things_on_the_wall():
    """ "Shelves" names a shelf; a thing's fellow subjects come with it ("ladles and pans hang on
    the wall"); bolted or screwed to a bulkhead is on a wall, hung in the window too (standing in
    it is not); a wall cupboard, a wall-mounted screen and framed things hang on a wall, but a
    thing framed *by* others does not; "hooked to the ceiling" hangs."""
    parsed = parse_scene("A ship's galley. Two shelves are screwed to the left wall. Ladles and pans hang in a "
                         "line on the wall over the sink. A fire extinguisher is bolted to the bulkhead by the "
                         "hatch. A lantern hangs in the window, and a cat sits in the window. A wall cupboard "
                         "holds the spices, beside three framed maps. A sofa stands framed by two lamps.")
    got = {(r.source, r.relation, r.target) for r in wall_phrases(parsed)}
    on_wall = {s for s, r, _ in got if r == "on wall"}
    assert {"bookshelf_1", "bookshelf_2", "ladle_1", "pot_1", "fire_extinguisher_1", "lantern_1"} <= on_wall
    assert ("bookshelf_1", "on wall", "wall_3") in got
    assert {"cabinet_1", "map_1"} <= on_wall or {"cupboard_1", "map_1"} <= on_wall
    assert "cat_1" not in on_wall and "lamp_1" not in on_wall and "sofa_1" not in on_wall
    puppets = parse_scene("A toy shop. Two marionettes dangle from strings hooked to the ceiling.")
    assert {(r.source, r.relation) for r in wall_phrases(puppets)} >= {("marionette_1", "on ceiling")}


def test_a_shelf_fixed_to_a_wall_is_a_wall_shelf_and_a_free_standing_one_a_bookcase():
    """Storage the text fixes to a wall is a wall unit's height, so what stands on it fits under
    the ceiling; one standing on the floor keeps its size."""
    fixed = parse_scene("A pottery. Jugs crowd two shelves screwed to the left wall.")
    standing = parse_scene("A pottery. Jugs crowd two shelves by the kiln.")
    height = {o.id: o.size[2] for o in fixed.objects}
    assert height["bookshelf_1"] <= 0.5 and max(o.size[2] for o in standing.objects if o.category == "bookshelf") > 1.5
    assert ("bottle_1", "on", "bookshelf_1") in {(r.source, r.relation, r.target) for r in fixed.relations}


def test_a_thing_nobody_listed_fixed_to_a_wall_lies_flat_against_it():
    """A guessed thing of no shape on a wall is a board, a sheet guessed lying flat is stood up,
    and both are as thin as a sheet; a tool hung there keeps its shape."""
    found = {o.name: o for o in parse_scene(
        "A cabin. A diploma hangs on the wall, a map is pinned to the left wall and a hammer hangs on the wall."
    ).objects}
    board, sheet = found["diploma"], found["map"]
    assert board.category == "panel" and board.size[1] <= 0.05 and board.size[2] > 0.3
    assert sheet.size[1] <= 0.05 < sheet.size[2]
    assert found["hammer"].size == parse_scene("A hammer lies on the bench.").objects[0].size
    lying = {o.name: o for o in parse_scene("A cabin. A map lies open on the table.").objects}
    assert lying["map"].size[2] <= 0.05


@pytest.mark.parametrize("text, floor, walls, ceiling", [
    ("A kitchen with white tiled walls and a stone floor.", "stone", "white tiled", None),
    ("A bar with brick walls, a wooden floor and a concrete ceiling.", "wood floor", "brick", "concrete"),
    ("A bedroom. A bed stands against the back wall; a fan hangs from the ceiling.", "carpet", None, None),
    ("The kitchen wall holds a clock.", "tiles", None, None),
])
def test_room_materials_are_read_from_the_words_before_floor_walls_and_ceiling(text, floor, walls, ceiling):
    request = read_room(text)
    assert (request.floor_material, request.wall_material, request.ceiling_material) == (floor, walls, ceiling)


def test_an_l_shaped_room_keeps_the_rectangle_s_walls_front_right_back_left():
    from scenewright.analysis.parser.room import build_room
    from scenewright.layout.room import RoomShape, wall_facing

    request = read_room("An L-shaped living room with two windows on the back wall and a door on the right wall.")
    assert request.shape == "L"
    room = build_room(request, [])
    assert len(room.floor) == 6
    assert [wall_facing(room, side) for side in ("front", "right", "back", "left")] == [0, 1, 2, 3]
    assert sorted((o.kind, o.wall) for o in room.openings) == [("door", 1), ("window", 2), ("window", 2)]
    assert RoomShape(room).area >= 4.5 * 5.0 * 0.99  # the living room's usual floor, the notch cut out


def test_a_ceiling_may_be_raised_only_where_nobody_gave_a_height():
    from scenewright.analysis.parser.room import tall_freely

    assert tall_freely("auto", "a workshop with a pegboard above the bench")
    assert tall_freely("4x5", "a workshop with a pegboard above the bench")
    assert not tall_freely("4x5x2.6", "a workshop")
    assert not tall_freely("auto", "a low-ceilinged workshop")
    assert not tall_freely("none", "a workshop")


def test_a_thing_named_before_another_that_hangs_from_the_ceiling_stays_on_the_floor():
    """"... beside a long counter, and three paper lanterns hang from the ceiling": the lanterns
    hang, the counter, whose name comes first, does not (the hanging verb opens the phrase)."""
    parsed = parse_scene("A tea room. A clock is fixed to the wall behind a long counter, and three paper "
                         "lanterns hang from the ceiling above the tables.")
    got = {(r.source, r.relation) for r in wall_phrases(parsed)}
    assert ("lantern_1", "on ceiling") in got and not any(s.startswith("counter") for s, _ in got)


def test_a_thing_hung_from_something_overhead_that_is_no_thing_hangs_from_the_ceiling():
    """"hang from the X overhead": whatever the X is called (a catwalk, a loft), what hangs from it
    hangs from the room's top; a thing of the scene named there carries what hangs from it."""
    parsed = parse_scene("A film studio. Six floodlights hang from the steel catwalk overhead, and a camera "
                         "stands on a dolly.")
    got = {(r.source, r.relation) for r in wall_phrases(parsed)}
    assert ("floodlight_6", "on ceiling") in got
    assert not any(s.startswith("camera") or s.startswith("dolly") for s, _ in got)


def test_a_wall_thing_named_in_a_standing_form_stands_against_the_wall():
    standing = wall_phrases(parse_scene("A cheval mirror stands against the left wall beside the wardrobe."))
    hung = wall_phrases(parse_scene("A round mirror hangs on the left wall."))
    assert [r.relation for r in standing] == ["against wall"]
    assert [r.relation for r in hung] == ["on wall"]


@pytest.mark.parametrize(("text", "indoor"), [
    ("A child's playroom in claymation style. A rocking horse stands by the window.", True),
    ("A quiet tearoom. Two ladies sit at a small table.", True),
    ("A research station in Antarctica. Three red huts stand in a row on the snow, and a snowcat waits.", False),
    ("Mushrooms grow around a fallen log.", False),
    ("A medieval blacksmith's forge: horseshoes hang from hooks on the wall.", True),
])
def test_a_room_a_compound_names_is_inside_and_several_buildings_stand_outside(text, indoor):
    assert parse_scene(text).indoor is indoor


def test_things_that_cover_or_line_the_walls_are_on_or_against_them_not_in_a_corner_named_later():
    parsed = parse_scene("A watchmaker's workshop. Dozens of clocks cover the walls, and a grandfather clock stands in the corner.")
    said = {(r.source, r.relation) for r in wall_phrases(parsed)}
    assert ("wall_clock_1", "on wall") in said and ("wall_clock_1", "in corner") not in said
    assert ("grandfather_clock_1", "in corner") in said


def test_a_broom_names_no_room():
    assert not parse_scene("A farmyard. A broom leans by the fence, and a dog sleeps on the grass.").indoor


def test_a_sentence_opening_on_a_wall_puts_its_subject_there():
    parsed = parse_scene("A chip shop. On the wall behind the otters, a menu board lists the day's catch. "
                         "Along the back wall, three tall shelves hold jars.")
    got = {(r.source, r.relation, r.target) for r in wall_phrases(parsed)}
    assert ("menu_board_1", "on wall", "room") in got and ("bookshelf_1", "against wall", "wall_2") in got
    assert not any(source.startswith("otter") for source, _, _ in got)


def test_what_hangs_from_hooks_in_the_ceiling_hangs_from_the_ceiling():
    parsed = parse_scene("A butcher's shop. Whole hams hang from hooks in the ceiling beams.")
    assert ("ham_1", "on ceiling", "ceiling") in {(r.source, r.relation, r.target) for r in wall_phrases(parsed)}


def test_things_of_a_two_word_name_said_in_the_plural_take_their_wall():
    parsed = parse_scene("A chamber. Three treasure chests stand around a brass table. Oil lamps hang on the walls.")
    got = {(r.source, r.relation) for r in wall_phrases(parsed)}
    lamps = [o.id for o in parsed.objects if o.name == "oil lamp"]
    assert lamps and got == {(i, "on wall") for i in lamps}


def test_a_thing_at_the_back_of_the_room_stands_against_the_back_wall_unless_someone_is_behind_it():
    def walls(text: str) -> set[tuple[str, str, str]]:
        return {(r.source, r.relation, r.target) for r in wall_phrases(parse_scene(text))}

    assert walls("A shop. A long counter runs across the back.") == {("counter_1", "against wall", "wall_2")}
    assert walls("A bakery. A counter stands at the back of the shop, and a baker waits behind it.") == set()


def test_a_thing_named_stand_takes_no_wall_phrase_from_the_verb_stand():
    """"Three clocks stand against the left wall. ... a parrot on a wooden stand": the clocks' wall."""
    got = {(r.source, r.relation, r.target) for r in wall_phrases(parse_scene(
        "A shop. Three grandfather clocks stand against the left wall, and a parrot perches on a wooden stand."
    ))}
    assert got == {(f"grandfather_clock_{k}", "against wall", "wall_3") for k in (1, 2, 3)}


def test_a_thing_hung_beside_the_door_is_on_its_wall_and_one_standing_there_is_not():
    """"A brass ship's bell hangs beside the door" stood on the dresser, the nearest thing."""
    def placed(text):
        return {(r.source, r.relation) for r in wall_phrases(parse_scene(text))}

    assert placed("A kitchen. A brass bell hangs beside the door.") == {("bell_1", "on wall")}
    assert placed("A kitchen. A coat rack stands beside the door, and a dog sleeps by the door.") == set()


def test_a_standing_board_fixed_to_a_wall_hangs_flat():
    from scenewright.analysis.parser.room import WALL_SHEET_DEPTH, wall_units

    parsed = parse_scene("A bakery: a counter stands by the window, and a chalkboard menu hangs on the wall behind it.")
    board = next(o for o in wall_units(parsed) if o.category == "menu_board")
    assert board.size[1] == WALL_SHEET_DEPTH and board.size[0] > board.size[2] and board.rests == "hanging"
    standing = next(o for o in parse_scene("A chalkboard menu stands by the door of the cafe.").objects)
    assert standing.size[1] > WALL_SHEET_DEPTH  # an A-frame on the pavement keeps its legs


def test_a_plural_right_after_a_named_thing_is_its_verb_not_the_things_on_the_wall():
    """"A blacksmith hammers a sword ... Tongs and hammers hang on the wall": the first "hammers"
    is the smith's verb, so the hammers are found where they hang (they lay on the floor)."""
    parsed = parse_scene("A forge. A blacksmith hammers a sword on an anvil. Tongs and hammers hang on the wall.")
    on_wall = {r.source for r in wall_phrases(parsed) if r.relation == "on wall"}
    assert {"tongs_1", "hammer_1"} <= on_wall


def test_things_hung_from_the_beams_or_rafters_hang_from_the_ceiling_with_their_fellows():
    parsed = parse_scene("A halfling kitchen. Onions and a ham hang from the low beams.")
    hung = {r.source for r in wall_phrases(parsed) if r.relation == "on ceiling"}
    assert {"onion_1", "onion_3", "ham_1"} <= hung
