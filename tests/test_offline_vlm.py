import pytest

from scenewright.analysis.arrange import initial_objects
from scenewright.core.catalogue import load_catalogue
from scenewright.backends.offline_vlm import OfflineVLM, relax_constraints
from scenewright.analysis.parser import parse_scene
from scenewright.analysis.parser.room import build_room, read_room
from scenewright.backends import VisionLanguageModel, create_backend
from scenewright.core.plan import EditPlan
from scenewright.errors import BackendError, InputError
from scenewright.geometry import front_direction, world_box
from scenewright.scene import Constraint, LayoutReport, Scene, UnplacedObject
from scenewright.settings import Settings

LIVING = (
    "A cosy living room. A grey sofa faces a TV on a TV stand. A coffee table stands in front of the sofa, "
    "a floor lamp to the left of the sofa, and a potted plant near the TV. A rug lies under the coffee table."
)


@pytest.fixture
def vlm() -> OfflineVLM:
    return OfflineVLM()


def test_registry_builds_it_and_it_meets_the_protocol():
    vlm = create_backend("vlm", "offline", Settings())
    assert isinstance(vlm, OfflineVLM) and isinstance(vlm, VisionLanguageModel)
    assert vlm.name == "offline"
    with pytest.raises(InputError, match="takes no argument"):
        create_backend("vlm", "offline:gpt", Settings())


def test_describe_objects(vlm):
    objects = vlm.describe_objects(LIVING, "realistic", None).value
    assert [o.id for o in objects] == ["sofa_1", "tv_1", "tv_stand_1", "coffee_table_1", "floor_lamp_1",
                                       "potted_plant_1", "rug_1"]  # fmt: skip
    catalogue = load_catalogue()
    for obj in objects:
        assert obj.category in catalogue
        assert obj.size.tuple() == catalogue[obj.category].size
        assert obj.visual_description


@pytest.mark.parametrize("text", ["", "   \n "])
def test_empty_text_is_bad_input(vlm, text):
    with pytest.raises(InputError, match="empty"):
        vlm.describe_objects(text, "realistic", None).value


def test_text_without_objects_is_bad_input(vlm):
    with pytest.raises(InputError, match="no object recognised in the text; name things like 'a sofa'"):
        vlm.describe_objects("A feeling of calm and quiet joy.", "realistic", None).value


def test_parse_is_cached_per_text(vlm):
    assert vlm.parse(LIVING) is vlm.parse(LIVING + "  ")


def test_constraints_follow_the_parse(vlm):
    objects = vlm.describe_objects(LIVING, "realistic", None).value
    constraints = vlm.write_constraints(LIVING, objects, None).value
    keys = {c.key() for c in constraints}
    assert {
        ("face to", "sofa_1", "tv_1"),
        ("on", "tv_1", "tv_stand_1"),
        ("in front of", "coffee_table_1", "sofa_1"),
        ("left of", "floor_lamp_1", "sofa_1"),
        ("near", "potted_plant_1", "tv_1"),
        ("on", "coffee_table_1", "rug_1"),
    } <= keys


def test_constraints_skip_removed_objects_and_map_other_ids(vlm):
    objects = vlm.describe_objects(LIVING, "realistic", None).value
    kept = [o for o in objects if o.id != "tv_1"]
    assert all("tv_1" not in (c.source, c.target) for c in vlm.write_constraints(LIVING, kept, None).value)
    renamed = [o.model_copy(update={"id": f"obj{i}"}) for i, o in enumerate(objects)]
    constraints = vlm.write_constraints(LIVING, renamed, None).value
    assert ("left of", "obj4", "obj0") in {c.key() for c in constraints}


def test_judging_needs_a_remote_model(vlm):
    with pytest.raises(BackendError, match="--vlm openai:MODEL"):
        vlm.judge(LIVING, b"png", "semantic")


def test_plan_edit_uses_the_rule_based_planner(vlm):
    scene = Scene(text=LIVING, objects=vlm.describe_objects(LIVING, "realistic", None).value)
    plan = vlm.plan_edit(scene, "move the floor lamp to the right of the sofa").value
    assert isinstance(plan, EditPlan)
    assert plan.operation == "move" and plan.focus == "floor_lamp_1"


# --- the feedback loop ---------------------------------------------------------------------------


def C(relation, source, target):
    return Constraint(relation=relation, source=source, target=target)


def test_revision_relaxes_the_failed_relations(vlm):
    constraints = [C("left of", "a", "t"), C("face to", "a", "t"), C("near", "b", "t"), C("on", "c", "t")]
    report = LayoutReport(
        unplaced=[
            UnplacedObject(id="a", failed=[C("left of", "a", "t"), C("face to", "a", "t")], reason="no room"),
            UnplacedObject(id="c", failed=[C("on", "c", "t")], reason="top too small"),
        ]
    )
    revised = vlm.revise_constraints("text", [], constraints, report, None).value
    assert [c.key() for c in revised] == [("near", "a", "t"), ("near", "b", "t")]


def test_revision_without_failed_relations_drops_the_weakest():
    constraints = [C("behind", "a", "t"), C("far", "a", "u"), C("near", "b", "t")]
    report = LayoutReport(unplaced=[UnplacedObject(id="a", failed=[], reason="collides everywhere")])
    assert [c.key() for c in relax_constraints(constraints, report)] == [("behind", "a", "t"), ("near", "b", "t")]


def test_revision_keeps_everything_when_all_placed():
    constraints = [C("behind", "a", "t")]
    assert relax_constraints(constraints, LayoutReport(placed=["a", "t"])) == constraints


def test_revision_merges_duplicates():
    constraints = [C("left of", "a", "t"), C("near", "a", "t")]
    report = LayoutReport(unplaced=[UnplacedObject(id="a", failed=[C("left of", "a", "t")], reason="x")])
    assert [c.key() for c in relax_constraints(constraints, report)] == [("near", "a", "t")]


# --- first poses ---------------------------------------------------------------------------------


def _overlap(a, b) -> bool:
    (amin, amax), (bmin, bmax) = world_box(a), world_box(b)
    return all(amin[i] < bmax[i] - 1e-6 and bmin[i] < amax[i] - 1e-6 for i in range(3))


def test_first_poses_follow_the_relations():
    objects = {o.id: o for o in initial_objects(parse_scene(LIVING))}
    sofa, table, lamp, tv, stand, rug = (objects[k] for k in ("sofa_1", "coffee_table_1", "floor_lamp_1", "tv_1",
                                                              "tv_stand_1", "rug_1"))  # fmt: skip
    # the composition stands centred on the origin, where the room is built around it
    ground = [o for o in objects.values() if o.position.z - o.size.z / 2 < 0.05 and o.size.z >= 0.1]
    lo = [min(world_box(o)[0][i] for o in ground) for i in (0, 1)]
    hi = [max(world_box(o)[1][i] for o in ground) for i in (0, 1)]
    assert [(a + b) / 2 for a, b in zip(lo, hi)] == pytest.approx([0.0, 0.0], abs=1e-3)
    assert table.position.y < sofa.position.y  # in front = −Y
    assert lamp.position.x < sofa.position.x
    # the TV stands on its stand, the table on the rug: bottoms meet tops
    assert tv.position.z - tv.size.z / 2 == pytest.approx(stand.position.z + stand.size.z / 2)
    assert table.position.z - table.size.z / 2 == pytest.approx(rug.position.z + rug.size.z / 2)
    # the sofa looks at the TV
    direction = front_direction(sofa.rotation.z)
    to_tv = (tv.position.x - sofa.position.x, tv.position.y - sofa.position.y)
    assert direction[0] * to_tv[0] + direction[1] * to_tv[1] > 0


def test_chairs_around_a_table_face_it():
    objects = initial_objects(parse_scene("Four chairs surround a round table."))
    table = next(o for o in objects if o.category == "round_table")
    for chair in (o for o in objects if o.category == "chair"):
        d = front_direction(chair.rotation.z)
        to_table = (table.position.x - chair.position.x, table.position.y - chair.position.y)
        assert d[0] * to_table[0] + d[1] * to_table[1] > 0


def test_first_poses_do_not_overlap_on_the_ground():
    text = (
        "A market square with three stalls, a fountain in the middle, four benches around the fountain, "
        "two lamp posts, a cart to the left of the fountain, barrels, crates and a tree."
    )
    objects = initial_objects(parse_scene(text))
    for i, a in enumerate(objects):
        for b in objects[i + 1 :]:
            assert not _overlap(a, b), (a.id, b.id)


def test_too_many_objects_are_refused_naming_the_limit_and_the_flag():
    vlm = OfflineVLM(max_objects=10)
    with pytest.raises(InputError) as err:
        vlm.describe_objects("A hall with twelve chairs.", "realistic", None).value
    assert "12 objects" in str(err.value) and "limit of 10" in str(err.value)
    assert "--max-objects" in str(err.value) and "max_objects" in str(err.value)
    assert len(vlm.describe_objects("A hall with ten chairs.", "realistic", None).value) == 10


def test_the_limit_comes_from_settings_and_defaults_to_150():
    assert create_backend("vlm", "offline", Settings()).max_objects == 150
    settings = Settings()
    settings.max_objects = 7
    assert create_backend("vlm", "offline", settings).max_objects == 7
    with pytest.raises(InputError, match="150"):
        OfflineVLM().describe_objects("A stadium with 1000000 seats and 999999 chairs.", "realistic", None).value


def test_guessed_objects_are_recorded_for_the_provenance(vlm):
    answer = vlm.describe_objects("A camel and two fuel tanks beside a bench.", "realistic", None)
    objects = answer.value
    assert [o.id for o in objects] == ["camel_1", "fuel_tank_1", "fuel_tank_2", "bench_1"]
    assert [o.name for o in objects][:2] == ["camel", "fuel tank"]
    (event,) = answer.repairs
    assert event.data["guessed"] == {"camel_1": "animal", "fuel_tank_1": "tank", "fuel_tank_2": "tank"}
    assert "camel_1 (animal)" in event.message
    assert vlm.find_redundant(objects, {}).repairs == ()  # reported once, with its own answer


def test_support_repairs_are_recorded_with_the_constraints(vlm):
    text = "A desk stands by the window, and a sofa sits on the desk."
    objects = vlm.describe_objects(text, "realistic", None).value
    answer = vlm.write_constraints(text, objects, None)
    assert ("sofa_1", "side of", "desk_1") in {(c.source, c.relation, c.target) for c in answer.value}
    assert [e.data["step"] for e in answer.repairs] == ["repair"]
    assert "desk_1 cannot hold it" in answer.repairs[0].message


def test_constraints_keep_what_the_composition_added(vlm):
    text = "A living room with a sofa, a coffee table and a rug."
    objects = vlm.describe_objects(text, "realistic", None).value
    constraints = {(c.source, c.relation, c.target) for c in vlm.write_constraints(text, objects, None).value}
    assert ("coffee_table_1", "on", "rug_1") in constraints  # the rug was laid under the coffee table


def test_revision_keeps_a_support_while_a_side_of_it_gives_way():
    # "a kettle on the shelf, beside it": both fail together; the side goes first.
    constraints = [C("on", "kettle", "shelf"), C("side of", "kettle", "shelf")]
    report = LayoutReport(unplaced=[UnplacedObject(id="kettle", failed=list(constraints), reason="cannot all hold")])
    once = relax_constraints(constraints, report)
    assert [c.key() for c in once] == [("on", "kettle", "shelf"), ("near", "kettle", "shelf")]
    alone = LayoutReport(unplaced=[UnplacedObject(id="kettle", failed=[once[0]], reason="top too small")])
    assert [c.key() for c in relax_constraints(once, alone)] == [("near", "kettle", "shelf")]


def test_a_support_only_inferred_gives_way_to_a_side_the_text_states():
    vlm = OfflineVLM()
    text = "A toaster stands beside a small round table in the kitchen."
    # the reader guesses no support onto the thing the toaster stands beside: both cannot hold
    assert not any(r.relation == "on" for r in vlm.composition(text).relations)
    objects = vlm.describe_objects(text, "realistic", None).value
    written = {str(c) for c in vlm.write_constraints(text, objects, None).value}
    assert written == {"toaster_1 side of round_table_1"}


def test_where_the_reader_guesses_a_wall_thing_hangs_it_is_near_that_thing_not_above_it():
    vlm = OfflineVLM()
    text = "A dining room with a long table and a large painting."
    assert any(r.relation == "above" and r.inferred for r in vlm.composition(text).relations)
    objects = vlm.describe_objects(text, "realistic", None).value
    written = {str(c) for c in vlm.write_constraints(text, objects, None).value}
    assert written == {"picture_frame_1 near table_1"}
    # a table the text puts in the middle of the room has no wall for the painting to hang on above it
    centred = "A dining room with a long table in the middle and a large painting."
    objects = vlm.describe_objects(centred, "realistic", None).value
    assert not vlm.write_constraints(centred, objects, None).value
    stated = "A dining room with a long table. A large painting hangs above the table."
    objects = vlm.describe_objects(stated, "realistic", None).value
    assert "picture_frame_1 above table_1" in {str(c) for c in vlm.write_constraints(stated, objects, None).value}


def test_a_guess_that_repeats_what_the_text_states_for_another_of_its_kind_stands_as_stated():
    from dataclasses import replace

    from scenewright.analysis.parser import ParsedRelation

    vlm = OfflineVLM()
    text = "A tall cabinet and two wall clocks."
    composed = vlm.composition(text)
    ids = {o.id for o in composed.objects}
    assert {"cabinet_1", "wall_clock_1", "wall_clock_2"} <= ids
    # One clock the text hangs above the cabinet, the other the reader only guessed there.
    guessed = [ParsedRelation("wall_clock_1", "above", "cabinet_1"),
               ParsedRelation("wall_clock_2", "above", "cabinet_1", inferred=True)]
    vlm._compositions[vlm.parse(text).text] = replace(composed, relations=guessed)
    written = {str(c) for c in vlm.write_constraints(text, composed.objects, None).value}
    assert written == {"wall_clock_1 above cabinet_1", "wall_clock_2 above cabinet_1"}


def test_a_side_whose_relaxed_form_failed_as_well_is_dropped_not_relaxed():
    # "left of the airship" would become "near the airship", which failed in the same round: gone.
    constraints = [C("in front of", "car", "mast"), C("left of", "car", "ship"), C("near", "car", "ship")]
    report = LayoutReport(unplaced=[UnplacedObject(id="car", failed=constraints[1:], reason="cannot all hold")])
    assert [c.key() for c in relax_constraints(constraints, report)] == [("in front of", "car", "mast")]


def test_a_support_only_inferred_gives_way_to_a_wall_the_text_hangs_the_thing_on():
    from scenewright.analysis.parser.room import room_for

    vlm = OfflineVLM()
    text = "A workshop with a workbench. A saw hangs on the left wall."
    assert any(r.relation == "on" and r.inferred for r in vlm.composition(text).relations)  # the reader's guess
    objects = vlm.describe_objects(text, "realistic", None).value
    room = room_for(text, objects, (5.0, 4.0, None))
    assert [str(c) for c in vlm.write_constraints(text, objects, None, room).value] == ["saw_1 on wall wall_3"]


def test_a_thing_hung_above_another_that_cannot_hang_there_still_hangs_from_the_ceiling():
    # "a dozen pans hang from the ceiling above the hob": those that find no place over the hob
    # give up the hob first, and keep the ceiling
    constraints = [C("above", "pan", "hob"), C("on ceiling", "pan", "ceiling"), C("near", "cook", "hob")]
    report = LayoutReport(unplaced=[UnplacedObject(id="pan", failed=constraints[:2], reason="no room over it")])
    assert [c.key() for c in relax_constraints(constraints, report)] == [
        ("on ceiling", "pan", "ceiling"), ("near", "cook", "hob")]


def test_a_guess_of_what_a_picture_hangs_over_keeps_to_the_wall_the_text_hangs_it_on():
    """"Three oil paintings hang on the right wall": not over a cabinet the text stands along the back wall."""
    vlm = OfflineVLM()
    text = "An antique shop: two glass display cabinets stand along the back wall, and three oil paintings hang on the right wall."
    objects = vlm.describe_objects(text, "realistic", None).value
    room = build_room(read_room(text), objects)
    written = {str(c) for c in vlm.write_constraints(text, objects, None, room).value}
    assert not any(c.startswith("picture_frame") and "display_case" in c for c in written)
    assert "picture_frame_1 on wall wall_1" in written
