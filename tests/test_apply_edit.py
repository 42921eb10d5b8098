"""apply_edit on a real scene folder: only the focus (and what rests on it) changes, the new
constraints hold, nothing collides, and a failed edit leaves every file as it was."""

from __future__ import annotations

import numpy as np
import pytest

from editing_scenes import BoxMeshes, NoImages, PictureImages, RulePlanner, snapshot
from scenewright.assets import load_meshes
from scenewright.backends import Backends
from scenewright.core.protocols import Answer
from scenewright.editing import EditPlan, apply_edit, entries, validate_plan
from scenewright.errors import InfeasibleLayout, InputError
from scenewright.layout import check, clean_constraints, colliding_pairs
from scenewright.scene import Constraint, Vec3
from scenewright.settings import Settings


@pytest.fixture
def backends():
    return Backends(vlm=RulePlanner(), images=NoImages(), meshes=BoxMeshes())


SETTINGS = Settings(cache_dir=None, time_limit=5.0)


def edit(folder, instruction, backends):
    return apply_edit(folder.load(), folder, instruction, backends=backends, settings=SETTINGS)


def pose(obj):
    return np.array([*obj.position.tuple(), obj.rotation.z])


def assert_others_unmoved(before, after, moved):
    for obj in after.objects:
        if obj.id not in moved:
            assert np.allclose(pose(obj), pose(before.get(obj.id)), atol=1e-3), obj.id


def assert_sound(folder, scene):
    assert colliding_pairs(scene.objects, load_meshes(scene, folder), scene.constraints) == []
    for c in scene.constraints:
        assert check(c.relation, scene.get(c.source), scene.get(c.target)), str(c)
    assert clean_constraints(scene.objects, scene.constraints)[1] == []  # valid, unique, acyclic
    assert folder.load() == scene  # what apply_edit returned is what it saved


def test_an_old_constraint_the_edit_would_close_a_cycle_with_gives_way(folder, backends):
    assert any(c.key() == ("near", "armchair_1", "coffee_table_1") for c in folder.load().constraints)
    after = edit(folder, "turn the coffee table to face the armchair", backends)
    assert ("face to", "coffee_table_1", "armchair_1") in {c.key() for c in after.constraints}
    assert ("near", "armchair_1", "coffee_table_1") not in {c.key() for c in after.constraints}
    assert any("would make a cycle" in change for change in entries(folder)[-1].changes)
    assert_sound(folder, after)


def test_move_re_solves_only_the_focus_and_carries_what_rests_on_it(folder, backends):
    before = folder.load()
    after = edit(folder, "move the coffee table to the right of the floor lamp", backends)
    assert check("right of", after.get("coffee_table_1"), after.get("floor_lamp_1"))
    assert not any(c.source == "coffee_table_1" and c.relation == "in front of" for c in after.constraints)
    assert_others_unmoved(before, after, {"coffee_table_1", "vase_1"})
    # the vase rode along: same offset, still resting on the table
    offset = lambda s: pose(s.get("vase_1"))[:2] - pose(s.get("coffee_table_1"))[:2]  # noqa: E731
    assert np.allclose(offset(after), offset(before), atol=1e-6)
    assert check("on", after.get("vase_1"), after.get("coffee_table_1"))
    assert_sound(folder, after)


def test_turn_to_face_keeps_the_place(folder, backends):
    before = folder.load()
    after = edit(folder, "turn the armchair to face the bookshelf", backends)
    armchair = after.get("armchair_1")
    assert check("face to", armchair, after.get("bookshelf_1"))
    assert np.allclose(pose(armchair)[:3], pose(before.get("armchair_1"))[:3])
    assert_others_unmoved(before, after, {"armchair_1"})
    assert_sound(folder, after)


def test_delete_removes_what_rests_only_on_it_and_says_so(folder, backends):
    after = edit(folder, "remove the coffee table", backends)
    ids = {o.id for o in after.objects}
    assert "coffee_table_1" not in ids and "vase_1" not in ids
    assert {r.id for r in after.removed} == {"coffee_table_1", "vase_1"}
    assert "coffee_table_1" in next(r.reason for r in after.removed if r.id == "vase_1")
    assert all({c.source, c.target}.isdisjoint({"coffee_table_1", "vase_1"}) for c in after.constraints)
    assert b"coffee_table_1" not in folder.glb.read_bytes()
    assert_sound(folder, after)


def test_replace_regenerates_the_asset_in_place(folder, backends):
    before = folder.load()
    old_asset = before.get("sofa_1").asset
    after = edit(folder, "paint the sofa blue", backends)
    sofa = after.get("sofa_1")
    assert "blue" in sofa.visual_description
    assert sofa.asset != old_asset and folder.resolve(sofa.asset).is_file()
    assert folder.resolve(old_asset).is_file()  # kept for undo
    assert backends.meshes.requests[-1].description == sofa.visual_description
    assert np.allclose(pose(sofa), pose(before.get("sofa_1")))
    assert_others_unmoved(before, after, {"sofa_1"})
    assert_sound(folder, after)


def test_replace_with_a_larger_thing_re_places_it_when_it_no_longer_fits(folder, backends):
    before = folder.load()
    after = edit(folder, "replace the floor lamp with a wardrobe", backends)
    wardrobe = after.get("floor_lamp_1")
    assert wardrobe.category == "wardrobe" and wardrobe.size.x > 1.0
    assert check("right of", wardrobe, after.get("sofa_1"))
    assert_others_unmoved(before, after, {"floor_lamp_1"})
    assert_sound(folder, after)


def test_replace_draws_a_new_object_image_where_the_image_backend_can(folder):
    backends = Backends(vlm=RulePlanner(), images=PictureImages(), meshes=BoxMeshes())
    after = edit(folder, "swap the floor lamp for a lantern", backends)
    lantern = after.get("floor_lamp_1")
    assert lantern.image is not None and folder.resolve(lantern.image).is_file()
    assert backends.meshes.requests[-1].image == folder.resolve(lantern.image).read_bytes()


def test_replace_lifts_what_rests_on_it_with_its_new_height(folder, backends):
    after = edit(folder, "make the coffee table taller", backends)
    table, vase = after.get("coffee_table_1"), after.get("vase_1")
    assert table.size.z > 0.6
    assert check("on", vase, table)
    assert_sound(folder, after)


def test_add_places_a_new_object_with_its_constraints(folder, backends):
    before = folder.load()
    after = edit(folder, "add a red armchair next to the sofa", backends)
    new = after.get("armchair_2")
    assert new.category == "armchair" and "red" in new.visual_description
    assert folder.resolve(new.asset).is_file()
    assert check("side of", new, after.get("sofa_1"))
    assert_others_unmoved(before, after, {"armchair_2"})
    assert_sound(folder, after)


def test_impossible_placement_reports_why_and_changes_nothing(folder, backends):
    scene = folder.load()
    scene.bounds = (12.0, 6.0)
    folder.save(scene)
    files = snapshot(folder.root)
    with pytest.raises(InfeasibleLayout, match="bookshelf_1"):
        edit(folder, "move the bookshelf far from the sofa", backends)
    assert snapshot(folder.root) == files


@pytest.mark.parametrize(
    "instruction",
    ["move the chair next to the sofa", "move the piano next to the sofa", "", "add a flux capacitor"],
)
def test_refused_edits_leave_every_file_as_it_was(folder, backends, instruction):
    files = snapshot(folder.root)
    with pytest.raises(InputError):
        edit(folder, instruction, backends)
    assert snapshot(folder.root) == files


def test_plans_are_validated_like_model_answers(folder):
    scene = folder.load()
    bad = [
        EditPlan(operation="move", focus="piano_1"),
        EditPlan(operation="move", focus="sofa_1",
                 constraints=[Constraint(relation="near", source="bookshelf_1", target="sofa_1")]),
        EditPlan(operation="move", focus="sofa_1",
                 constraints=[Constraint(relation="near", source="sofa_1", target="sofa_1")]),
        EditPlan(operation="move", focus="sofa_1",
                 constraints=[Constraint(relation="near", source="sofa_1", target="piano_1")]),
        EditPlan(operation="replace", focus="sofa_1"),
        EditPlan(operation="move", focus="sofa_1"),  # neither where to nor a turn
        EditPlan(operation="move", focus="sofa_1", offset=Vec3(x=1.0),  # two places at once
                 constraints=[Constraint(relation="near", source="sofa_1", target="bookshelf_1")]),
        EditPlan(operation="replace", focus="sofa_1", offset=Vec3(x=1.0), new_object={"name": "sofa"}),
    ]
    for plan in bad:
        with pytest.raises(InputError):
            validate_plan(scene, plan)
    reused = validate_plan(scene, EditPlan(
        operation="add", focus="sofa_1", new_object={"name": "sofa", "category": "sofa"},
        constraints=[Constraint(relation="near", source="sofa_1", target="bookshelf_1")],
    ))
    assert reused.focus == "sofa_2" and reused.constraints[0].source == "sofa_2"


class ScriptedPlanner:
    """Stands in for a model backend: answers one fixed structured plan."""

    name = "scripted"

    def __init__(self, plan):
        self.plan = plan

    def plan_edit(self, scene, instruction):
        return Answer(self.plan)


def test_a_model_plan_that_replaces_and_re_places_is_carried_out(folder):
    plan = EditPlan(
        operation="replace", focus="floor_lamp_1",
        new_object={"name": "brass lantern", "category": "lantern", "visual_description": "a brass lantern"},
        constraints=[Constraint(relation="on", source="floor_lamp_1", target="table_1")],
    )
    backends = Backends(vlm=ScriptedPlanner(plan), images=NoImages(), meshes=BoxMeshes())
    before = folder.load()
    after = edit(folder, "put a brass lantern on the dining table instead of the floor lamp", backends)
    lantern = after.get("floor_lamp_1")
    assert lantern.name == "brass lantern" and check("on", lantern, after.get("table_1"))
    assert not any(c.source == "floor_lamp_1" and c.relation == "right of" for c in after.constraints)
    assert_others_unmoved(before, after, {"floor_lamp_1"})
    assert_sound(folder, after)


def test_an_object_cannot_be_placed_on_what_rests_on_it(folder, backends):
    files = snapshot(folder.root)
    with pytest.raises(InputError, match="vase_1 rests on coffee_table_1"):
        edit(folder, "put the coffee table on the vase", backends)
    assert snapshot(folder.root) == files


def test_turning_in_place_into_a_neighbour_is_refused(folder, backends):
    files = snapshot(folder.root)
    with pytest.raises(InfeasibleLayout, match="chair_3"):
        edit(folder, "rotate the dining table by 90 degrees", backends)
    assert snapshot(folder.root) == files


def test_turning_in_place_turns_what_rests_on_it_too(folder, backends):
    before = folder.load()
    after = edit(folder, "rotate the coffee table by 90 degrees", backends)
    assert after.get("coffee_table_1").yaw == pytest.approx(90.0)
    assert after.get("vase_1").yaw == pytest.approx(90.0)
    assert np.allclose(pose(after.get("coffee_table_1"))[:3], pose(before.get("coffee_table_1"))[:3])
    assert_sound(folder, after)


def test_add_records_where_the_new_object_started_and_delete_drops_it(folder, backends):
    scene = folder.load()
    scene.remember_initial_poses()  # as the layout stage leaves a generated scene
    folder.save(scene)
    after = edit(folder, "add a red armchair next to the sofa", backends)
    (new,) = {o.id for o in after.objects} - {o.id for o in scene.objects}
    assert set(after.initial) == set(scene.initial) | {new}
    assert all(after.initial[oid] == scene.initial[oid] for oid in scene.initial)
    start = after.initial[new]
    sofa = after.get("sofa_1").position  # the edit starts the search at the first target
    assert (start.position.x, start.position.y) == (sofa.x, sofa.y)
    assert start.position.z == after.get(new).size.z / 2
    assert start.position != after.get(new).position  # the solver moved it off the sofa; the record stayed
    gone = edit(folder, "remove the coffee table", backends)
    assert set(gone.initial) == set(after.initial) - {"coffee_table_1", "vase_1"}


def test_an_add_records_only_the_new_object_in_a_scene_without_recorded_poses(folder, backends):
    before = folder.load()
    after = edit(folder, "add a red armchair next to the sofa", backends)
    assert set(after.initial) == {o.id for o in after.objects} - {o.id for o in before.objects} != set()


def test_a_shift_moves_the_focus_by_exactly_the_step_and_carries_what_rests_on_it(folder, backends):
    before = folder.load()
    after = edit(folder, "move the coffee table 30 cm to the left", backends)
    step = pose(after.get("coffee_table_1")) - pose(before.get("coffee_table_1"))
    assert np.allclose(step, [-0.3, 0, 0, 0], atol=1e-9)
    assert np.allclose(pose(after.get("vase_1")) - pose(before.get("vase_1")), step, atol=1e-9)
    assert_others_unmoved(before, after, {"coffee_table_1", "vase_1"})
    assert_sound(folder, after)


def test_a_shift_drops_the_focus_constraints_that_no_longer_hold(folder, backends):
    after = edit(folder, "push the armchair 3 metres forward", backends)
    assert after.get("armchair_1").position.y == pytest.approx(-4.0)
    assert not any(c.source == "armchair_1" and c.relation == "near" for c in after.constraints)
    assert_sound(folder, after)


@pytest.mark.parametrize(
    ("bounds", "instruction", "says"),
    [(None, "move chair_1 1 m to the right", "chair_1 and table_1"),
     ((8.0, 6.0), "move the bookshelf 3 m to the left", "bounds")],
)
def test_a_shift_into_a_neighbour_or_out_of_bounds_is_refused(folder, backends, bounds, instruction, says):
    folder.save(folder.load().model_copy(update={"bounds": bounds}))
    files = snapshot(folder.root)
    with pytest.raises(InfeasibleLayout, match=says):
        edit(folder, instruction, backends)
    assert snapshot(folder.root) == files


@pytest.mark.parametrize(
    "plan, says",
    [
        ({"operation": "move", "focus": "sofa_1", "offset": {"x": 1e308}}, "within ±10000 m"),
        ({"operation": "move", "focus": "sofa_1", "offset": {"y": -10_002.0}}, "within ±10000 m"),
        ({"operation": "move", "focus": "sofa_1", "yaw": float("nan")}, "finite number of degrees"),
        ({"operation": "move", "focus": "sofa_1", "yaw": float("inf")}, "finite number of degrees"),
        ({"operation": "add", "focus": "crate_1", "new_object": {"name": "crate", "size": {"x": 5e3, "y": 1, "z": 1}}},
         "between 0.001 and 1000 metres"),
    ],
)
def test_a_model_plan_with_wild_numbers_is_refused_and_writes_nothing(folder, plan, says):
    files = snapshot(folder.root)
    backends = Backends(vlm=ScriptedPlanner(EditPlan.model_validate(plan)), images=NoImages(), meshes=BoxMeshes())
    with pytest.raises(InputError, match=says):
        edit(folder, "do as the model says", backends)
    assert snapshot(folder.root) == files
    assert entries(folder) == []


def test_nan_in_a_model_offset_is_refused_where_the_answer_is_read():
    from pydantic import ValidationError

    with pytest.raises(ValidationError, match="finite"):
        EditPlan.model_validate({"operation": "move", "focus": "sofa_1", "offset": {"x": float("nan")}})
