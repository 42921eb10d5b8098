"""The arranger's placement priors, one rule at a time, and its guarantees as properties."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scenewright.analysis.arrange import compose, initial_objects, share_supports
from scenewright.core.catalogue import load_catalogue
from scenewright.analysis.composition import roles
from scenewright.analysis.composition.edges import share
from scenewright.analysis.composition.outdoor import SCATTER_GAP
from scenewright.analysis.composition.spread import MIN_SPREAD, ground_objects, scene_spread, spread
from scenewright.analysis.parser import ParsedObject, ParsedRelation, ParsedScene, parse_scene
from scenewright.geometry import front_direction, world_box
from scenewright.layout import relations as rel


def _scene(*categories: str, relations=(), indoor=True) -> ParsedScene:
    """A parse of the given categories, numbered per category, with catalogue sizes; the things of
    one category are named together, one phrase ("two desks")."""
    catalogue = load_catalogue()
    count: dict[str, int] = {}
    objects = []
    for c in categories:
        count[c] = count.get(c, 0) + 1
        label = c.replace("_", " ")
        objects.append(ParsedObject(f"{c}_{count[c]}", c, label, label, catalogue[c].size, categories.index(c)))
    rels = [ParsedRelation(s, r, t, inferred) for s, r, t, inferred in relations]
    return ParsedScene(" ".join(categories), objects, rels, "realistic", "wood", indoor)


def _by_id(objects):
    return {o.id: o for o in objects}


def _faces(obj, target, within: float = 10.0) -> bool:
    """Whether ``obj``'s front points at ``target``'s centre within ``within`` degrees."""
    d = front_direction(obj.rotation.z)
    v = np.array([target.position.x - obj.position.x, target.position.y - obj.position.y])
    return float(d @ v) / float(np.linalg.norm(v)) >= math.cos(math.radians(within))


def _gap(a, b) -> float:
    (alo, ahi), (blo, bhi) = world_box(a), world_box(b)
    return float(max(0.0, blo[0] - ahi[0], alo[0] - bhi[0], blo[1] - ahi[1], alo[1] - bhi[1]))


def _plan_overlap(a, b) -> bool:
    (alo, ahi), (blo, bhi) = world_box(a), world_box(b)
    return all(alo[i] < bhi[i] - 1e-6 and blo[i] < ahi[i] - 1e-6 for i in range(2))


# --- functional groups -------------------------------------------------------------------------


def test_four_desks_each_get_a_chair_facing_them():
    objects = _by_id(initial_objects(_scene(*["desk"] * 4, *["office_chair"] * 4)))
    desks = [o for o in objects.values() if o.category == "desk"]
    chairs = [o for o in objects.values() if o.category == "office_chair"]
    for desk in desks:
        near = [c for c in chairs if _gap(c, desk) < 0.3]
        assert len(near) == 1, (desk.id, [c.id for c in near])
        chair = near[0]
        assert _faces(chair, desk)
        # in front of the desk: on the side its front (−Y at yaw 0) looks to
        assert chair.position.y < desk.position.y
    # the desks are set out in a grid, not a line
    assert spread((d.position.x, d.position.y) for d in desks) > 0.5


def test_chairs_go_around_a_dining_table_facing_it():
    objects = initial_objects(_scene("table", *["chair"] * 6))
    table = next(o for o in objects if o.category == "table")
    for chair in (o for o in objects if o.category == "chair"):
        assert _gap(chair, table) < 0.3
        assert _faces(chair, table, within=45.0)


def test_a_lounge_gathers_around_its_coffee_table_and_faces_the_tv():
    parsed = _scene("sofa", "armchair", "coffee_table", "tv_stand", "rug", "floor_lamp")
    made = compose(parsed)
    o = _by_id(made.objects)
    sofa, chair, table, tv, rug, lamp = (o[k] for k in ("sofa_1", "armchair_1", "coffee_table_1", "tv_stand_1",
                                                         "rug_1", "floor_lamp_1"))  # fmt: skip
    assert _faces(sofa, tv) and _faces(tv, sofa)
    assert _gap(sofa, table) < 0.8 and _gap(chair, table) < 0.8
    assert _faces(chair, table, within=45.0)
    # the rug lies under the group: what stands wholly on it says so (the solver keeps it
    # there), what would stand half on it stands off its edge
    on_rug = {r.source for r in made.relations if r.relation == "on" and r.target == "rug_1"}
    assert on_rug == {"coffee_table_1"}
    assert rel.check("on", table, rug)
    assert not _plan_overlap(sofa, rug) and not _plan_overlap(chair, rug)
    assert _gap(lamp, sofa) < 0.3


def test_a_bed_has_nightstands_either_side_of_its_head_and_a_chest_at_its_foot():
    made = compose(_scene("bed", "nightstand", "nightstand", "treasure_chest", "rug"))
    o = _by_id(made.objects)
    bed, left, right, chest = o["bed_1"], o["nightstand_1"], o["nightstand_2"], o["treasure_chest_1"]
    xs = sorted([left.position.x, right.position.x])
    assert xs[0] < bed.position.x - bed.size.x / 2 and xs[1] > bed.position.x + bed.size.x / 2
    for stand in (left, right):
        assert stand.position.y > bed.position.y  # at the head (the back, +Y at yaw 0)
        assert _gap(stand, bed) < 0.2
    assert chest.position.y < bed.position.y - bed.size.y / 2
    assert _gap(chest, bed) < 0.3
    # the rug lies at the bed's foot, the chest on it
    assert o["rug_1"].position.y < bed.position.y - bed.size.y / 2
    assert ("treasure_chest_1", "on", "rug_1") in {(r.source, r.relation, r.target) for r in made.relations}


def test_each_desk_gets_its_own_monitor():
    parsed = _scene("desk", "desk", "monitor", "monitor",
                    relations=[("monitor_1", "on", "desk_1", True), ("monitor_2", "on", "desk_1", True)])  # fmt: skip
    hosts = {r.source: r.target for r in share_supports(parsed)}
    assert hosts == {"monitor_1": "desk_1", "monitor_2": "desk_2"}
    o = _by_id(compose(parsed).objects)
    assert rel.check("on", o["monitor_2"], o["desk_2"])


# --- edges, rows, scatter ----------------------------------------------------------------------


def test_bookshelves_stand_at_an_edge_with_their_backs_outward():
    objects = initial_objects(_scene("table", "chair", "chair", "bookshelf", "bookshelf", "bookshelf", "bookshelf"))
    rest = [o for o in objects if o.category != "bookshelf"]
    lo = np.min([world_box(o)[0] for o in rest], axis=0)
    hi = np.max([world_box(o)[1] for o in rest], axis=0)
    centre = (lo + hi) / 2
    for shelf in (o for o in objects if o.category == "bookshelf"):
        slo, shi = world_box(shelf)
        outside = shi[0] <= lo[0] or slo[0] >= hi[0] or slo[1] >= hi[1]
        assert outside, shelf.id
        assert shi[1] > lo[1] + 1e-6 or slo[1] >= hi[1], "never in the open front"
        front = front_direction(shelf.rotation.z)
        inward = centre[:2] - np.array([shelf.position.x, shelf.position.y])
        assert float(front @ inward) > 0.7 * float(np.linalg.norm(inward))


def test_storage_alone_makes_a_u_not_a_line():
    assert share(2) == ["back", "back"]
    assert share(5) == ["back", "back", "back", "left", "right"]
    objects = initial_objects(_scene(*["bookshelf"] * 5))
    assert scene_spread(objects) >= MIN_SPREAD


def test_stalls_stand_around_a_fountain_facing_it_and_leave_the_front_open():
    o = _by_id(initial_objects(_scene("fountain", *["market_stall"] * 5, indoor=False)))
    fountain = o["fountain_1"]
    for k in range(1, 6):
        stall = o[f"market_stall_{k}"]
        assert _faces(stall, fountain)
        assert stall.position.y > fountain.position.y - 0.5  # none between the fountain and the viewer


def test_stalls_without_a_square_line_a_street_facing_each_other():
    o = _by_id(initial_objects(_scene(*["market_stall"] * 4, indoor=False)))
    left = [s for s in o.values() if s.rotation.z == pytest.approx(90.0)]
    right = [s for s in o.values() if s.rotation.z == pytest.approx(-90.0)]
    assert len(left) == 2 and len(right) == 2
    assert max(s.position.x for s in left) < min(s.position.x for s in right) - 2.0  # the walk between


def test_vehicles_park_along_an_edge_beside_a_free_road():
    objects = initial_objects(_scene("bench", "fountain", "lamp_post", "car", "car", "tree", "tree", indoor=False))
    cars = [o for o in objects if o.category == "car"]
    others = [o for o in objects if o.category not in ("car", "tree")]
    edge = max(world_box(o)[1][0] for o in others)
    assert all(world_box(c)[0][0] > edge + 2.0 for c in cars)
    assert len({round(c.position.x, 3) for c in cars}) == 1  # nose to tail


def test_trees_are_poisson_spaced_and_deterministic_per_seed():
    parsed = _scene(*["tree"] * 8, *["rock"] * 4, *["bush"] * 4, "campfire", indoor=False)
    objects = compose(parsed, seed=3).objects
    natural = [o for o in objects if roles.kind(o.category) in roles.NATURAL]
    for i, a in enumerate(natural):
        for b in natural[i + 1 :]:
            reach = (max(a.size.x, a.size.y) + max(b.size.x, b.size.y)) / 2
            distance = math.hypot(a.position.x - b.position.x, a.position.y - b.position.y)
            assert distance >= reach + SCATTER_GAP - 1e-6, (a.id, b.id)
    assert compose(parsed, seed=3).objects == objects
    assert compose(parsed, seed=4).objects != objects


# --- the text first, and never a line ----------------------------------------------------------


def test_stated_relations_hold_at_the_first_poses():
    text = (
        "A home office: a desk with a monitor on it, an office chair to the left of the desk, a bookshelf "
        "behind the desk, a plant near the chair, and a lamp on the desk."
    )
    made = compose(parse_scene(text))
    o = _by_id(made.objects)
    for r in made.relations:
        assert rel.check(r.relation, o[r.source], o[r.target]), r


def test_three_unrelated_objects_are_not_collinear():
    objects = initial_objects(_scene("lamp_post", "bench", "trash_can", indoor=False))
    assert scene_spread(objects) >= MIN_SPREAD


def test_a_stated_row_is_broken_sideways_only_where_the_relations_allow():
    parsed = _scene("crate", "barrel", "crate", "barrel",
                    relations=[("crate_1", "left of", "barrel_1", False), ("barrel_1", "left of", "crate_2", False),
                               ("crate_2", "left of", "barrel_2", False)])  # fmt: skip
    made = compose(parsed)
    o = _by_id(made.objects)
    assert scene_spread(made.objects) >= MIN_SPREAD
    for r in made.relations:
        assert rel.check(r.relation, o[r.source], o[r.target])


def test_spread_measures_lines():
    assert spread([(0, 0), (1, 0), (2, 0), (3, 0)]) == pytest.approx(0.0)
    assert spread([(0, 0), (1, 0), (0, 1), (1, 1)]) == pytest.approx(1.0)
    assert spread([(0, 0), (1, 1)]) == 1.0


# --- properties --------------------------------------------------------------------------------

_GROUND = sorted(c.name for c in load_catalogue().values() if c.rests == "ground")
_SURFACE = sorted(c.name for c in load_catalogue().values() if c.rests == "surface")


@st.composite
def scenes(draw):
    ground = draw(st.lists(st.sampled_from(_GROUND), min_size=1, max_size=14))
    surface = draw(st.lists(st.sampled_from(_SURFACE), max_size=4))
    parsed = _scene(*ground, *surface, indoor=draw(st.booleans()))
    supports = [o.id for o in parsed.objects if load_catalogue()[o.category].support]
    for o in parsed.objects[len(ground) :]:
        if supports:
            parsed.relations.append(ParsedRelation(o.id, "on", draw(st.sampled_from(supports)), True))
    return parsed


@settings(max_examples=60, deadline=None)
@given(scenes(), st.integers(0, 2**16))
def test_compositions_never_overlap_never_line_up_and_repeat_per_seed(parsed, seed):
    made = compose(parsed, seed)
    assert [o.id for o in made.objects] == [o.id for o in parsed.objects]
    resting = {frozenset((r.source, r.target)) for r in made.relations if r.relation in ("on", "above")}
    ground = [o for o in ground_objects(made.objects) if o.size.z >= 0.1]
    for i, a in enumerate(ground):
        for b in ground[i + 1 :]:
            if frozenset((a.id, b.id)) not in resting:
                assert not _plan_overlap(a, b), (a.id, b.id)
    if len(ground_objects(made.objects)) >= 3:
        assert scene_spread(made.objects) >= MIN_SPREAD
    assert compose(parsed, seed).objects == made.objects


# --- formations and anchors the text states ----------------------------------------------------


def test_two_rows_of_chairs_facing_an_arch_stand_in_two_rows_in_front_of_it():
    made = compose(parse_scene("A garden with a white arch. Ten folding chairs are set out in two rows facing the arch."))
    o = _by_id(made.objects)
    chairs = [v for k, v in o.items() if k.startswith("chair")]
    arch = o["arch_1"]
    rows = sorted({round(c.position.y, 2) for c in chairs})
    assert len(rows) == 2 and all(sum(round(c.position.y, 2) == y for c in chairs) == 5 for y in rows)
    assert all(c.position.y < arch.position.y for c in chairs)  # in front of it, where it looks
    assert all(_faces(c, arch) for c in chairs)
    assert not any(_plan_overlap(a, b) for i, a in enumerate(chairs) for b in chairs[i + 1 :])


def test_a_stack_is_each_on_the_one_below_from_the_composition():
    parsed = parse_scene("Three wooden crates are stacked beside the barn.")
    made = compose(parsed)
    chain = {(r.source, r.relation, r.target) for r in made.relations}
    assert {("crate_2", "on", "crate_1"), ("crate_3", "on", "crate_2")} <= chain
    o = _by_id(made.objects)
    for r in made.relations:
        assert rel.check(r.relation, o[r.source], o[r.target]), r


def test_a_row_of_unrelated_things_stands_side_by_side_and_a_circle_faces_its_middle():
    made = compose(parse_scene("A laundromat. Four washing machines stand in a row. A sofa stands nearby. "
                               "A table and a lamp."))  # fmt: skip
    machines = sorted((v for v in made.objects if v.id.startswith("washing")), key=lambda v: v.position.x)
    assert len({round(m.position.y, 3) for m in machines}) == 1  # one straight row
    assert all(_gap(a, b) < 0.5 for a, b in zip(machines, machines[1:]))  # side by side
    ring = [v for v in compose(parse_scene("Six stools stand in a circle.")).objects]
    centre = np.mean([[s.position.x, s.position.y] for s in ring], axis=0)
    radii = [math.hypot(s.position.x - centre[0], s.position.y - centre[1]) for s in ring]
    assert max(radii) - min(radii) < 1e-3 and min(radii) >= 0.99  # poses are rounded to 0.1 mm
    for s in ring:
        d = front_direction(s.rotation.z)
        v = centre - np.array([s.position.x, s.position.y])
        assert float(d @ v) / float(np.linalg.norm(v)) > 0.99


def test_anchors_send_things_to_the_back_the_front_and_the_middle():
    parsed = parse_scene("A hall. A sofa and a coffee table. An armchair. A rug lies in the middle of the room. "
                         "A wardrobe stands at the back. A bench stands at the front.")  # fmt: skip
    o = _by_id(compose(parsed).objects)
    others = [v for k, v in o.items() if k not in ("wardrobe_1", "bench_1")]
    assert all(o["wardrobe_1"].position.y > v.position.y for v in others)
    assert all(o["bench_1"].position.y < v.position.y for v in others)


@pytest.mark.parametrize("seat", ["armchair", "sofa"])
def test_a_seat_by_the_fireplace_turns_to_it(seat):
    parsed = _scene(seat, "fireplace", relations=[(f"{seat}_1", "near", "fireplace_1", False)])
    made = compose(parsed)
    assert (f"{seat}_1", "face to", "fireplace_1") in {(r.source, r.relation, r.target) for r in made.relations}
    objects = _by_id(made.objects)
    assert _faces(objects[f"{seat}_1"], objects["fireplace_1"])


def test_a_seat_that_faces_something_else_keeps_it():
    parsed = _scene("armchair", "fireplace", "tv", relations=[
        ("armchair_1", "near", "fireplace_1", False), ("armchair_1", "face to", "tv_1", False)])
    assert ("armchair_1", "face to", "fireplace_1") not in {(r.source, r.relation, r.target) for r in compose(parsed).relations}


def test_a_stack_taller_than_one_can_reach_stands_in_columns_side_by_side():
    parsed = parse_scene("A cellar. Eight oak barrels are stacked against the far wall.")
    made = compose(parsed)
    o = _by_id(made.objects)
    barrels = [v for v in made.objects if v.category == "barrel"]
    assert len(barrels) == 8 and max(b.position.z + b.size.z / 2 for b in barrels) <= 2.0 + 1e-6
    feet = [b for b in barrels if b.position.z - b.size.z / 2 < 1e-3]
    assert 1 < len(feet) < len(barrels)  # a pile: several columns, each more than one high
    for r in made.relations:
        if r.source in o and r.target in o:
            assert rel.check(r.relation, o[r.source], o[r.target]), r


def test_a_person_at_a_console_turns_to_it():
    made = compose(parse_scene("A cramped radio room. A radio operator sits at the control panel by the door."))
    objects = _by_id(made.objects)
    operator = next(k for k in objects if k.startswith("radio_operator") or k.startswith("operator"))
    assert (operator, "face to", "control_panel_1") in {(r.source, r.relation, r.target) for r in made.relations}


def test_one_who_sits_at_a_console_on_a_chair_has_the_chair_turned_to_it():
    parsed = _scene("figure", "office_chair", "control_panel", relations=[
        ("figure_1", "near", "control_panel_1", False), ("figure_1", "on", "office_chair_1", False)])
    made = compose(parsed)
    turned = {(r.source, r.relation, r.target) for r in made.relations}
    assert ("office_chair_1", "face to", "control_panel_1") in turned
    assert ("figure_1", "face to", "control_panel_1") not in turned  # the chair turns them
    o = _by_id(made.objects)
    assert _faces(o["office_chair_1"], o["control_panel_1"], within=30.0)


def test_a_row_stays_a_row_by_relations_between_its_members():
    parsed = parse_scene("A motocross paddock. Five vans are parked in a row along the fence.")
    made = compose(parsed)
    chain = {(r.source, r.relation, r.target) for r in made.relations if r.inferred and r.relation == "right of"}
    assert chain == {(f"truck_{k + 1}", "right of", f"truck_{k}") for k in range(1, 5)}
    o = _by_id(made.objects)
    assert all(rel.check("right of", o[f"truck_{k + 1}"], o[f"truck_{k}"]) for k in range(1, 5))


def test_a_row_beside_a_thing_stands_on_one_side_of_it():
    made = compose(parse_scene("A desert camp. Three camels kneel in a row beside a striped tent."))
    o = _by_id(made.objects)
    sides = {rel.check("right of", o[f"camel_{k}"], o["tent_1"]) for k in (1, 2, 3)}
    assert sides == {True}, sides  # not one left of it and two right


def test_a_row_facing_a_thing_is_left_to_its_group():
    parsed = parse_scene("A small hall. Five chairs stand in a row facing the tv.")
    assert [o.formation for o in parsed.objects if o.category == "chair"] == ["row"] * 5
    assert not [r for r in compose(parsed).relations if r.relation == "right of"]


def test_a_stack_on_a_host_wide_enough_for_several_is_a_pile_of_layers_on_it():
    """"Six crates are stacked on a pallet": four on the pallet (as many as its top takes), two on
    them; not a column of four and a second column on the floor."""
    made = compose(parse_scene("A warehouse. Six crates are stacked on a pallet in the corner."))
    o = _by_id(made.objects)
    crates = [v for v in made.objects if v.category == "crate"]
    pallet = o["pallet_1"]
    on_pallet = [c for c in crates if rel.check("on", c, pallet)]
    assert len(crates) == 6 and len(on_pallet) == 4
    for a in crates:
        for b in crates:
            assert a is b or not _plan_overlap(a, b) or abs(a.position.z - b.position.z) > 0.1
    for r in made.relations:
        if r.source in o and r.target in o:
            assert rel.check(r.relation, o[r.source], o[r.target]), r


def test_a_bridge_between_two_things_left_and_right_turns_its_length_across_the_gap():
    scene = parse_scene("A wooden rope bridge crosses between two cliffs.")
    bridge = next(o for o in initial_objects(scene) if o.category == "bridge")
    assert bridge.size.y > bridge.size.x and abs(abs(bridge.rotation.z) - 90.0) < 1e-6


def test_a_table_with_a_bench_on_either_side_turns_its_long_sides_to_them():
    """"A pine table with two benches on either side of it": the benches stood at its ends."""
    def table_yaw(text):
        return next(o for o in initial_objects(parse_scene(text)) if o.category == "table").rotation.z

    assert abs(abs(table_yaw("A pine table stands in the middle, with two benches on either side of it.")) - 90.0) < 1e-6
    assert table_yaw("A pine table stands in the middle, with two chairs on either side of it.") == 0.0


def test_nothing_is_packed_out_of_sight_behind_a_barn():
    """A claymation farmyard: the piglets and their trough stood behind the 6 m barn, where the
    viewer (at −y) could not see them; and a farmer right of the barn stood by its middle."""
    o = _by_id(initial_objects(parse_scene(
        "A red barn stands behind a muddy pond. A farmer leans on a wooden fence to the right of the barn. "
        "Two piglets sleep in the mud next to a feeding trough.")))
    barn = o["barn_1"]
    for i in ("piglet_1", "piglet_2", "feeding_trough_1"):
        behind = o[i].position.y > barn.position.y + barn.size.y / 2 - 0.01
        across = abs(o[i].position.x - barn.position.x) < barn.size.x / 2
        assert not (behind and across), i
    assert o["farmer_1"].position.y < barn.position.y  # by the barn's front corner


def test_what_stands_between_rows_keeps_the_rows_and_stands_in_their_aisle():
    """"Four grow tables stand in two rows. A robot rolls between the rows": the rows broke up
    around the robot joined to two tables."""
    o = _by_id(initial_objects(parse_scene(
        "A hydroponics bay: four long grow tables stand in two rows. A maintenance robot rolls between the rows.")))
    ys = sorted({round(o[f"table_{k}"].position.y, 3) for k in range(1, 5)})
    assert len(ys) == 2  # two rows
    robot = o["robot_1"]
    assert ys[0] < robot.position.y < ys[1]
    assert rel.check("behind", robot, o["table_1"]) and rel.check("in front of", robot, o["table_3"])


def test_the_only_thing_above_a_long_table_hangs_over_its_middle():
    o = _by_id(initial_objects(parse_scene("A bay: a long grow table stands under a bright lamp.")))
    lamp, table = o["pendant_lamp_1"], o["table_1"]
    assert abs(lamp.position.x - table.position.x) < 1e-6 and abs(lamp.position.y - table.position.y) < 1e-6


def test_a_ring_of_wide_things_stands_beyond_the_targets_other_neighbours():
    sides = ("left of", "right of", "in front of", "behind")
    ring = [(f"tent_{k + 1}", side, "campfire_1", False) for k, side in enumerate(sides)]
    ring += [(f"tent_{k + 1}", "face to", "campfire_1", False) for k in range(4)]
    benches = [("bench_1", "left of", "campfire_1", False), ("bench_2", "right of", "campfire_1", False)]
    objects = _by_id(initial_objects(_scene(*["tent"] * 4, "campfire", "bench", "bench", relations=ring + benches)))
    fire = objects["campfire_1"]
    for bench, tent in (("bench_1", "tent_1"), ("bench_2", "tent_2")):
        assert _gap(objects[bench], fire) < _gap(objects[tent], fire)  # the bench hugs the fire, the tent is beyond
    assert not any(_plan_overlap(objects[a], objects[b]) for a in objects for b in objects if a < b)


def test_an_inferred_support_stays_among_the_things_named_together():
    """"Twelve desks ... a globe sits on the corner of her desk" (the teacher's): the globe was
    handed to the first school desk, one of another phrase."""
    parsed = parse_scene("Six desks face the teacher's desk. A globe sits on her desk.")
    hosts = {r.source: r.target for r in share_supports(parsed)}
    assert hosts["globe_1"] == "desk_7"


def test_rows_facing_a_thing_take_along_what_stands_by_each_member():
    """"Twelve desks in three rows of four, each with a chair behind it, facing the teacher's desk":
    the rows fell apart into one fanned line, the chairs left where the desks had been."""
    made = compose(parse_scene("A classroom. Twelve desks stand in three rows of four, each with a chair behind it, "
                               "facing the teacher's desk at the front."))
    o = _by_id(made.objects)
    desks = [o[f"desk_{k}"] for k in range(1, 13)]
    assert len({round(d.position.y, 2) for d in desks}) == 3
    assert all(_faces(d, o["desk_13"]) for d in desks)
    assert all(rel.check("behind", o[f"chair_{k}"], o[f"desk_{k}"]) for k in range(1, 13))
    standing = [v for v in o.values() if v.size.z >= 0.1]
    assert not any(_plan_overlap(a, b) for i, a in enumerate(standing) for b in standing[i + 1 :])


def test_a_row_along_a_fence_stands_in_front_of_it_and_the_fence_runs_its_length():
    """"Four camper vans are parked in a row along the fence": the first van stood apart by a
    3 m fence, the others in a row beyond it."""
    made = compose(parse_scene("A festival car park. Four camper vans are parked in a row along the fence, "
                               "and a girl sits on the roof of the last van."))
    o = _by_id(made.objects)
    vans, fence = [o[f"truck_{k}"] for k in range(1, 5)], o["fence_1"]
    assert len({round(v.position.y, 2) for v in vans}) == 1 and all(v.position.y < fence.position.y for v in vans)
    assert fence.size.x >= sum(v.size.x for v in vans)
    assert all(rel.check("near", v, fence) for v in vans) and rel.check("on", o["girl_1"], vans[-1])


def test_a_thing_with_a_ring_round_it_keeps_room_for_the_ring_from_what_it_stands_by():
    """"Two tents, with a campfire in front of them surrounded by four logs": the campfire hugged
    the tents and the log behind it went round behind the tents, metres away."""
    made = compose(parse_scene("Two tents stand side by side, with a campfire in front of them surrounded by four logs."))
    o = _by_id(made.objects)
    fire = o["campfire_1"]
    assert all(_gap(o[f"log_{k}"], fire) < 1.0 for k in range(1, 5))
    assert all(rel.check("in front of", fire, o[t]) for t in ("tent_1", "tent_2"))


def test_a_big_building_tied_to_nothing_stands_behind_the_groups():
    """A ski village: the 8 m chalet the text puts by nothing stood among the groups (beside them,
    or in front); set out like tall storage, it closes the back."""
    o = _by_id(initial_objects(parse_scene(
        "A snowy village. A wooden chalet stands at the foot of the slope. Three skiers chat beside a sled. "
        "Two children build a snowman near a bench. A man chops logs beside a shed, and a woman waits by a lamp post.")))
    chalet = o.pop("chalet_1")
    assert all(x.position.y < chalet.position.y for x in o.values())
