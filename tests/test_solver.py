import itertools
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from scenewright.layout import audit, check, colliding_pairs, feedback_text, solve
from scenewright.bench.layout import independent_collisions
from scenewright.testing.problems import hard_problem, planted_problem
from scenewright.layout.relations import Boxes, check_room, plan_gap
from scenewright.scene import Constraint, Room, SceneObject, Vec3


def box(oid, x=0.0, y=0.0, z=None, size=(1.0, 1.0, 1.0), yaw=0.0):
    s = Vec3.of(size)
    return SceneObject(id=oid, name=oid, size=s, position=Vec3(x=x, y=y, z=s.z / 2 if z is None else z),
                       rotation=Vec3(z=yaw))


def c(rel, s, t):
    return {"relation": rel, "source": s, "target": t}


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(3, 14), st.integers(0, 10_000))
def test_planted_problems_are_solved_correctly(n, seed):
    p = planted_problem(n, seed)
    result = solve(p.objects, p.constraints, meshes=p.meshes, bounds=p.bounds, seed=seed)
    report = result.report
    by_id = {o.id: o for o in result.objects}
    placed = set(report.placed)
    for con in result.constraints:
        if con.source in placed and con.target in placed:
            assert check(con.relation, by_id[con.source], by_id[con.target]), str(con)
    kept = [o for o in result.objects if o.id in placed]
    assert independent_collisions(kept, p.meshes, result.constraints) == []
    half = np.array(p.bounds) / 2
    for o in kept:
        box_ = Boxes.of(o)
        assert np.all(box_.lo[:2] >= -half - 1e-9) and np.all(box_.hi[:2] <= half + 1e-9)
    assert placed | {u.id for u in report.unplaced} == set(by_id)
    assert all(u.reason for u in report.unplaced)
    assert report.complete  # planted problems are satisfiable


def test_ground_default_and_vertical_relations():
    table = box("table", size=(1.2, 0.8, 0.75), z=3.0)
    cup = box("cup", 0.2, 0.1, z=0.0, size=(0.1, 0.1, 0.12))
    lamp = box("lamp", size=(0.4, 0.4, 0.3), z=0.5)
    result = solve([table, cup, lamp], [c("on", "cup", "table"), c("above", "lamp", "table")])
    t, cp, lp = result.objects
    assert t.position.z == pytest.approx(0.375)  # nothing puts the table anywhere but the ground
    assert check("on", cp, t) and check("above", lp, t)
    assert lp.position.z - 0.375 >= 2.0 - 1e-9 and lp.position.z - 0.15 > 0.75


def test_face_to_turns_the_source_and_other_yaws_are_kept():
    sofa = box("sofa", 0, 2, size=(2, 0.9, 0.8))
    tv = box("tv", 0.5, -1, size=(1.2, 0.3, 0.7), yaw=10)
    shelf = box("shelf", 3, 0, size=(0.8, 0.4, 1.8), yaw=90)
    result = solve([tv, sofa, shelf], [c("face to", "sofa", "tv"), c("in front of", "tv", "sofa")])
    by = {o.id: o for o in result.objects}
    assert check("face to", by["sofa"], by["tv"]) and check("in front of", by["tv"], by["sofa"])
    assert by["shelf"].rotation.z == 90 and by["tv"].rotation.z == 10


def test_bounds_keep_objects_inside():
    objects = [box(f"b{k}", 5.0, 5.0, size=(1.0, 1.0, 1.0)) for k in range(6)]
    result = solve(objects, [], bounds=(4.0, 4.0))
    assert result.report.complete
    for o in result.objects:
        b = Boxes.of(o)
        assert np.all(np.abs(b.lo[:2]) <= 2 + 1e-9) and np.all(np.abs(b.hi[:2]) <= 2 + 1e-9)


def test_fixed_objects_keep_their_pose():
    a, b = box("a"), box("b", 0.3)
    result = solve([a, b], [c("right of", "b", "a")], fixed=["a"])
    assert result.objects[0] == a
    assert check("right of", result.objects[1], result.objects[0])
    # A fixed source constrains a free target from the other side.
    result = solve([a, b], [c("left of", "a", "b")], fixed=["a"])
    assert check("left of", result.objects[0], result.objects[1])


def test_infeasible_constraints_are_reported_with_the_nearest_miss():
    a, b = box("a"), box("b", 2)
    result = solve([a, b], [c("left of", "b", "a"), c("right of", "b", "a")], seed=1)
    [u] = result.report.unplaced
    assert u.id == "b" and u.reason == "its constraints cannot all hold at once"  # each alone could
    assert {str(f) for f in u.failed} == {"b left of a", "b right of a"}
    # It is placed at its nearest miss: one of the two holds, the other misses by the least.
    assert u.nearest_miss.startswith("placed at") and "misses by 2.20 m" in u.nearest_miss
    a2, b2 = result.objects
    assert check("left of", b2, a2) != check("right of", b2, a2)
    assert result.posed == {"a", "b"} and colliding_pairs(result.objects) == []
    text = feedback_text(result.report, result.objects)
    assert "Placed 1 of 2" in text and "b left of a; b right of a" in text


def test_dependents_of_an_object_at_its_nearest_miss_are_placed_against_it():
    objects = [box("a"), box("b", 2), box("c", 4, size=(0.2, 0.2, 0.2)), box("d", -3, size=(0.3, 0.3, 0.3))]
    result = solve(objects, [c("left of", "b", "a"), c("right of", "b", "a"), c("on", "c", "b"),
                             c("near", "d", "c")])
    assert [u.id for u in result.report.unplaced] == ["b"]  # only the real conflict is reported
    by = {o.id: o for o in result.objects}
    assert check("on", by["c"], by["b"]) and check("near", by["d"], by["c"])


def test_constraints_that_only_hold_outside_the_bounds():
    objects = [box("stool", size=(0.3, 0.3, 0.5)), box("vase", -3, size=(0.2, 0.2, 0.3))]
    result = solve(objects, [c("far", "vase", "stool")], bounds=(3.0, 3.0))
    [u] = result.report.unplaced
    assert u.id == "vase" and u.reason == "no candidate position satisfies 'vase far stool'"
    assert [str(f) for f in u.failed] == ["vase far stool"] and "'vase far stool' misses by" in u.nearest_miss
    result = solve([box("stool"), box("vase", 12, 0)], [c("far", "vase", "stool")])
    assert result.report.complete  # the same constraint without bounds


def test_a_target_too_small_to_hold_its_load():
    objects = [box("stool", size=(0.3, 0.3, 0.5)), box("tv", 3, size=(1.0, 0.3, 0.6))]
    result = solve(objects, [c("on", "tv", "stool"), c("left of", "tv", "stool")])
    [u] = result.report.unplaced
    assert u.id == "tv" and u.reason == "its constraints cannot all hold at once"
    assert "'tv left of stool' misses by" in u.nearest_miss or "'tv on stool' misses by" in u.nearest_miss


def test_crowded_bounds_report_collisions():
    objects = [box(f"b{k}", size=(1.0, 1.0, 1.0)) for k in range(3)]
    result = solve(objects, [], bounds=(2.2, 1.1))
    assert len(result.report.placed) == 2
    [u] = result.report.unplaced
    assert "collides (most often with b" in u.reason and "it would collide with" in u.nearest_miss


def test_ablation_keeps_initial_poses_and_reports_violations():
    a, b, cc = box("a"), box("b", 0.5), box("c", 5)
    result = audit([a, b, cc], [c("left of", "c", "a")])
    assert [o.position for o in result.objects] == [a.position, b.position, cc.position]
    assert result.report.solver is False
    reasons = {u.id: u.reason for u in result.report.unplaced}
    assert "collides with b" in reasons["a"] and "violates 'c left of a'" in reasons["c"]
    assert result.report.placed == []


def test_same_seed_same_layout_and_limits_still_return_a_layout():
    p = planted_problem(12, 3)
    one = solve(p.objects, p.constraints, meshes=p.meshes, bounds=p.bounds, seed=5)
    two = solve(p.objects, p.constraints, meshes=p.meshes, bounds=p.bounds, seed=5)
    assert one.objects == two.objects
    capped = solve(p.objects, p.constraints, meshes=p.meshes, bounds=p.bounds, node_limit=3)
    assert len(capped.objects) == len(p.objects)
    assert set(capped.report.placed) | {u.id for u in capped.report.unplaced} == {o.id for o in p.objects}


def test_bad_arguments_name_the_culprit():
    from scenewright.errors import InputError

    with pytest.raises(InputError, match="fixed ids \\['ghost'\\]"):
        solve([box("a")], [], fixed=["ghost"])
    with pytest.raises(InputError, match="bounds"):
        solve([box("a")], [], bounds=(0, 3))


SIDES = ["left of", "right of", "in front of", "behind", "near", "side of"]


# Derandomized so every run sees the same draws; two chairs on the *same* side of the table
# facing each other once failed here ("it cannot turn there", see the test below).
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True)
@given(st.sampled_from(SIDES), st.sampled_from(SIDES), st.floats(-180, 180), st.floats(-180, 180),
       st.floats(-3, 3), st.floats(-3, 3), st.integers(0, 1000))
def test_mutual_facing_is_solved_not_dropped(rel1, rel2, yaw1, yaw2, x, y, seed):
    objects = [box("table", size=(1.6, 0.9, 0.75), yaw=30), box("chair1", x, y, size=(0.5, 0.55, 0.9), yaw=yaw1),
               box("chair2", -x, -y, size=(0.5, 0.55, 0.9), yaw=yaw2)]
    cons = [c("face to", "chair1", "chair2"), c("face to", "chair2", "chair1"),
            c(rel1, "chair1", "table"), c(rel2, "chair2", "table")]
    result = solve(objects, cons, bounds=(12.0, 12.0), seed=seed)
    assert result.report.dropped == [] and result.report.complete, result.report
    by = {o.id: o for o in result.objects}
    for con in result.constraints:
        assert check(con.relation, by[con.source], by[con.target]), str(con)
    assert colliding_pairs(result.objects) == []


def test_mutual_facing_on_one_side_of_a_table():
    # Found by hypothesis: the chair placed first stood flush against the table's left edge and
    # could not turn to face the second without crossing it; it now keeps room to turn.
    objects = [box("table", size=(1.6, 0.9, 0.75), yaw=30), box("chair1", -3.0, 0.0, size=(0.5, 0.55, 0.9), yaw=1.0),
               box("chair2", 3.0, 0.0, size=(0.5, 0.55, 0.9), yaw=0.0)]
    cons = [c("face to", "chair1", "chair2"), c("face to", "chair2", "chair1"),
            c("left of", "chair1", "table"), c("left of", "chair2", "table")]
    result = solve(objects, cons, bounds=(12.0, 12.0), seed=0)
    assert result.report.complete, result.report
    by = {o.id: o for o in result.objects}
    for con in result.constraints:
        assert check(con.relation, by[con.source], by[con.target]), str(con)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(3, 16), st.integers(0, 10_000))
def test_hard_problems_keep_every_constraint_the_report_does_not_name(n, seed):
    p = hard_problem(n, seed)
    result = solve(p.objects, p.constraints, meshes=p.meshes, bounds=p.bounds, seed=seed)
    named = {f.key() for u in result.report.unplaced for f in u.failed}
    by = {o.id: o for o in result.objects}
    for con in result.constraints:
        if con.key() not in named:
            assert check(con.relation, by[con.source], by[con.target]), str(con)
    kept = [o for o in result.objects if o.id in result.posed]
    assert independent_collisions(kept, p.meshes, result.constraints) == []


def test_an_unplaced_objects_report_names_every_constraint_it_leaves_unmet():
    # Found by hypothesis: an object that could not turn to face its partner had that facing only in
    # the prose of the nearest miss, not among the failed constraints. A planted contradiction (the
    # last object both left and right of the first) makes sure something is left unmet.
    p = hard_problem(5, 209)
    first, last = p.constraints[0].target, p.objects[-1].id
    conflict = [Constraint(relation=r, source=last, target=first) for r in ("left of", "right of")]
    result = solve(p.objects, [*p.constraints, *conflict], meshes=p.meshes, bounds=p.bounds, seed=209)
    named = {f.key() for u in result.report.unplaced for f in u.failed}
    by = {o.id: o for o in result.objects}
    unmet = [con for con in result.constraints if not check(con.relation, by[con.source], by[con.target])]
    assert unmet, "the planted conflict should leave something unmet"
    assert {con.key() for con in unmet} <= named


def test_a_contradiction_costs_one_object_not_its_dependents():
    p = planted_problem(60, 7)
    # The object most others depend on, directly or not, gets two constraints that contradict.
    depends: dict[str, set[str]] = {}
    for con in p.constraints:
        depends.setdefault(con.target, set()).add(con.source)

    def reach(x, seen):
        for s in depends.get(x, ()):
            if s not in seen:
                seen.add(s)
                reach(s, seen)
        return seen

    hub = max((o.id for o in p.objects), key=lambda x: len(reach(x, set())))
    assert len(reach(hub, set())) >= 5
    anchor = next(o.id for o in p.objects if o.id != hub and hub not in reach(o.id, set()) and o.id not in reach(hub, set()))
    bad = [c("left of", hub, anchor), c("right of", hub, anchor)]
    result = solve(p.objects, p.constraints + [Constraint.model_validate(b) for b in bad],
                   meshes=p.meshes, bounds=p.bounds, seed=7)
    assert len(result.report.placed) >= len(p.objects) - 2
    [u] = result.report.unplaced
    assert u.id == hub and {str(f) for f in u.failed} == {f"{hub} left of {anchor}", f"{hub} right of {anchor}"}
    assert hub in result.posed and u.nearest_miss.startswith("placed at")


def test_objects_turn_to_fit_unless_their_yaw_is_kept():
    # A 1.9 m long cabinet fits the 2 x 1 m room only turned a quarter, whichever way it came.
    for yaw in (0.0, 180.0, 33.0):
        result = solve([box("a", size=(0.9, 1.9, 1.0), yaw=yaw)], [], bounds=(2.0, 1.0))
        assert result.report.complete and result.objects[0].rotation.z % 180 == 90
    kept = solve([box("a", size=(0.9, 1.9, 1.0))], [], bounds=(2.0, 1.0), keep_yaw=["a"])
    assert [u.id for u in kept.report.unplaced] == ["a"] and kept.objects[0].rotation.z == 0
    # Two of them in a 2 x 2 room: side by side as they are, or one above the other turned.
    pair = [box("a", size=(0.9, 1.9, 1.0), yaw=90), box("b", 0.3, size=(0.9, 1.9, 1.0), yaw=90)]
    result = solve(pair, [], bounds=(2.0, 2.0))
    assert result.report.complete and colliding_pairs(result.objects) == []


def test_the_layout_does_not_depend_on_machine_load():
    p = planted_problem(25, 11)
    idle = solve(p.objects, p.constraints, meshes=p.meshes, bounds=p.bounds, seed=2)
    hog = subprocess.Popen([sys.executable, "-c", "while True: pass"])
    try:
        loaded = solve(p.objects, p.constraints, meshes=p.meshes, bounds=p.bounds, seed=2)
    finally:
        hog.kill()
        hog.wait()
    assert loaded.objects == idle.objects and loaded.report.nodes == idle.report.nodes


def test_the_search_ends_on_counted_work_not_on_the_clock(monkeypatch):
    """With a budget too small for the problem, a clock racing past the time limit (short of
    the backstop) gives the same layout as one that never moves."""
    from scenewright.layout import solver

    p = hard_problem(30, 1)

    def solved(clock):
        monkeypatch.setattr(solver, "_cpu", clock)
        return solve(p.objects, p.constraints, meshes=p.meshes, bounds=p.bounds, seed=0, time_limit=0.3)

    still = solved(lambda: 0.0)
    calls = itertools.count()
    racing = solved(lambda: 0.0 if next(calls) < 2 else 0.3 * solver.CPU_BACKSTOP - 0.1)
    assert racing.objects == still.objects and racing.report.nodes == still.report.nodes
    monkeypatch.undo()
    ample = solve(p.objects, p.constraints, meshes=p.meshes, bounds=p.bounds, seed=0)
    assert still.report.nodes < ample.report.nodes  # the budget did end the search


def _room_case(table_size, lamp_size, relation):
    room = Room.rectangle(5.0, 6.0)
    table = box("table", 1.0, -1.0, size=table_size)
    lamp = box("lamp", -1.5, 2.0, z=1.0, size=lamp_size)
    cons = [c(relation, "lamp", "table"), {"relation": "on ceiling", "source": "lamp", "target": "ceiling"}]
    return room, solve([table, lamp], cons, room=room, seed=0)


def test_a_lamp_hung_from_the_ceiling_above_a_table_hangs_over_it():
    room, result = _room_case((1.2, 0.8, 0.75), (0.4, 0.4, 0.4), "above")
    assert result.report.complete, result.report
    table, lamp = result.objects
    assert check("above", lamp, table) and check_room("on ceiling", lamp, room, "ceiling")


def test_a_lamp_hung_from_the_ceiling_near_a_table_hangs_over_it():
    room, result = _room_case((1.2, 0.8, 0.75), (0.4, 0.4, 0.4), "near")
    table, lamp = result.objects
    assert check_room("on ceiling", lamp, room, "ceiling")
    assert check("above", lamp, table)  # started from the table's centre, not its own guess


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.floats(0.4, 2.0), st.floats(0.4, 2.0), st.floats(0.3, 1.2), st.floats(0.1, 0.8), st.floats(0.1, 0.6))
def test_hung_above_holds_whenever_the_ceiling_leaves_room_for_it(tx, ty, tz, lxy, lz):
    room, result = _room_case((tx, ty, tz), (lxy, lxy, lz), "above")
    table, lamp = result.objects
    # Hung from the 2.7 m ceiling its centre is at 2.7 - lz / 2: above holds iff that is 2 m over
    # the table's centre and its bottom clears the table's top.
    feasible = 2.7 - lz / 2 - tz / 2 >= 2.0 and 2.7 - lz > tz + 0.002
    assert result.report.complete == feasible, result.report
    if feasible:
        assert check("above", lamp, table) and check_room("on ceiling", lamp, room, "ceiling")
    else:
        assert {f.relation for u in result.report.unplaced for f in u.failed} & {"above", "on ceiling"}


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.floats(2.5, 4.0), st.floats(-2.0, 2.0), st.floats(-4.0, 4.0), st.floats(-4.0, 4.0), st.integers(0, 100))
def test_a_thing_right_of_one_and_left_of_another_stands_in_their_gap(dx, dy, ax, ay, seed):
    # The reader writes "a bin between the machine and the stall" as right of one, left of the
    # other and near both; the bin's own first guess (ax, ay) may be anywhere. (The pair stands
    # close enough that the middle of the gap is within 2 m of both: farther apart, near + near
    # cannot both hold.)
    from scenewright.evaluation.stated import between

    objects = [box("a", -dx / 2, -dy / 2, size=(0.8, 0.8, 1.0)), box("b", dx / 2, dy / 2, size=(0.8, 0.8, 1.0)),
               box("bin", ax, ay, size=(0.4, 0.4, 0.6))]
    cons = [c("right of", "bin", "a"), c("left of", "bin", "b"), c("near", "bin", "a"), c("near", "bin", "b")]
    result = solve(objects, cons, bounds=(12.0, 12.0), fixed=["a", "b"], seed=seed)
    assert result.report.complete
    by = {o.id: o for o in result.objects}
    assert between(by["bin"], by["a"], by["b"])


def _between(source, first, second):
    from scenewright.evaluation.stated import between

    return between(source, first, second)


def test_a_thing_between_two_stands_on_the_line_joining_them():
    # The kennel stands well back of the shed: right of one and left of the other holds anywhere
    # in a band, but only on the line between them does a viewer see the crate between the two.
    objects = [box("shed", -4.0, 0.0, size=(3.0, 2.5, 2.2)), box("kennel", 1.5, 3.0, size=(0.3, 0.3, 0.5)),
               box("crate", 0.0, -3.0, size=(0.8, 0.6, 0.5)), box("post", -1.25, 1.5, size=(0.3, 0.3, 1.0))]
    constraints = [Constraint(relation=r, source="crate", target=t)
                   for r, t in (("right of", "shed"), ("left of", "kennel"), ("near", "shed"), ("near", "kennel"))]
    result = solve(objects, constraints, seed=3, fixed={"shed", "kennel", "post"})  # a post in the middle of the gap
    by_id = {o.id: o for o in result.objects}
    assert result.report.unplaced == []
    assert _between(by_id["crate"], by_id["shed"], by_id["kennel"])


def test_the_second_end_of_a_between_leaves_the_gap_on_the_side_the_relations_ask():
    # First poses with the tractor right of the barn; three hay bales must stand right of the tractor
    # and left of the barn, so the tractor has to end up left of the barn, a bale's width apart.
    objects = [box("barn", 0.0, 0.0, size=(6.0, 5.0, 4.0)), box("tractor", 6.0, 0.0, size=(1.8, 3.0, 2.0))] + [
        box(f"bale_{i}", 3.0, 4.0 + i, size=(1.2, 1.0, 1.0)) for i in range(3)]
    constraints = [Constraint(relation=r, source=f"bale_{i}", target=t)
                   for i in range(3) for r, t in (("right of", "tractor"), ("left of", "barn"))]
    result = solve(objects, constraints, seed=4)
    by_id = {o.id: o for o in result.objects}
    assert result.report.unplaced == []
    assert all(check(c.relation, by_id[c.source], by_id[c.target]) for c in constraints)
    assert by_id["tractor"].position.x < by_id["barn"].position.x


def test_constraints_to_several_objects_that_conflict_name_only_what_must_give_way():
    """Relations to two objects that cannot all hold: the report names the weakest that keep the
    rest possible (here "left of b" and "near b"), the strongest (in front of, then the text's
    order) kept, so the feedback gives up the conflict and not everything the object was asked."""
    objects = [box("a"), box("b", -5.0), box("s", 3.0, size=(0.5, 0.5, 0.5))]
    said = [c("right of", "s", "a"), c("left of", "s", "b"), c("near", "s", "a"), c("near", "s", "b"),
            c("in front of", "s", "a")]
    result = solve(objects, said, fixed=["a", "b"], seed=2)
    [u] = result.report.unplaced
    assert u.id == "s" and u.reason == "its constraints cannot all hold at once"
    assert {str(f) for f in u.failed} == {"s left of b", "s near b"}


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(gap=st.floats(3.0, 9.0), seed=st.integers(0, 1000))
def test_what_the_report_keeps_of_a_conflict_can_hold_together(gap, seed):
    """Whatever a conflict between two targets gives up, the rest has a pose: solved again
    without the constraints the report names, the object is placed and all the rest hold."""
    objects = [box("a"), box("b", -gap), box("s", 2.0, size=(0.4, 0.4, 0.4))]
    said = [c("right of", "s", "a"), c("left of", "s", "b"), c("behind", "s", "b"), c("near", "s", "a")]
    first = solve(objects, said, fixed=["a", "b"], seed=seed)
    [u] = first.report.unplaced
    named = {f.key() for f in u.failed}
    assert named and len(named) < len(said)
    kept = [x for x in said if (x["relation"], x["source"], x["target"]) not in named]
    again = solve(objects, kept, fixed=["a", "b"], seed=seed)
    assert again.report.complete


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(k=st.integers(1, 3), seed=st.integers(0, 1000), dy=st.floats(-3.0, 3.0))
def test_a_row_seated_between_two_things_sits_in_their_gap(k, seed, dy):
    """k people, each on a stool, right of one kiosk and left of another: the kiosks leave a gap
    wide enough for all of them, and the stools go into it, so each person stands
    on the line joining the two (the evaluation's *between*), not merely in the two half-planes."""
    from scenewright.evaluation.stated import between

    objects = [box("east", 0.0, 0.0, size=(1.2, 0.8, 1.0)), box("west", 1.0, dy, size=(1.0, 1.0, 1.0))]
    said = []
    for j in range(k):
        objects += [box(f"stool{j}", -2.0 + j, 4.0, size=(0.4, 0.4, 0.5)),
                    box(f"fan{j}", 3.0, -2.0 - j, size=(0.45, 0.3, 1.0))]
        said += [c("on", f"fan{j}", f"stool{j}"), c("right of", f"fan{j}", "east"), c("left of", f"fan{j}", "west")]
    result = solve(objects, said, bounds=(14.0, 14.0), seed=seed)
    assert result.report.complete
    by = {o.id: o for o in result.objects}
    for j in range(k):
        assert between(by[f"fan{j}"], by["east"], by["west"]), f"fan{j}"


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(far=st.floats(4.0, 9.0), side=st.sampled_from(["near", "in front of", "left of", "behind"]),
       seed=st.integers(0, 1000))
def test_a_seat_goes_where_its_sitter_is_asked_to_be(far, side, seed):
    """A painter on a stool, asked to be by an easel far from where the stool began: the stool
    (no relation of its own) takes its candidates from the painter's relation, so the first
    search places both, and the painter's relations hold."""
    objects = [box("easel", far, 0.0, size=(0.8, 0.6, 1.6)), box("stool", -far, 0.0, size=(0.4, 0.4, 0.6)),
               box("painter", 0.0, 3.0, size=(0.5, 0.4, 1.0))]
    said = [c("on", "painter", "stool"), c(side, "painter", "easel")]
    result = solve(objects, said, bounds=(24.0, 24.0), seed=seed, fixed=["easel"])
    assert result.report.complete
    by = {o.id: o for o in result.objects}
    assert check("on", by["painter"], by["stool"]) and check(side, by["painter"], by["easel"])


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(k=st.integers(4, 12), width=st.floats(0.5, 1.4), seed=st.integers(0, 1000))
def test_more_twins_than_their_holder_holds_fill_it_without_spending_the_search(k, width, seed):
    """k like jars on a sideboard that holds fewer: the ones left over collide only with their
    twins, so the search does not jump back to shuffle them (which only swaps which is left over);
    it fills the top, reports the rest, and stays far inside its node budget."""
    from scenewright.layout.solver import NODES_PER_OBJECT

    objects = [box("sideboard", size=(width, 0.4, 0.9))]
    objects += [box(f"jar{j}", 2.0 + 0.4 * j, 2.0, size=(0.3, 0.3, 0.25)) for j in range(k)]
    said = [c("on", f"jar{j}", "sideboard") for j in range(k)]
    result = solve(objects, said, bounds=(8.0, 8.0), seed=seed)
    assert not independent_collisions(result.objects, {}, result.constraints)
    on_top = [x for x in result.report.placed if x != "sideboard"]
    assert on_top and len(on_top) + len(result.report.unplaced) == k
    assert not {u.id for u in audit(result.objects, result.constraints).report.unplaced} & set(on_top)
    assert result.report.nodes < (NODES_PER_OBJECT * len(objects) + 1000) / 3


def test_twins_are_like_leaves_with_the_same_constraints():
    from scenewright.layout.solver import _Search
    from scenewright.scene import Constraint

    objects = [box("shelf", size=(2.0, 0.4, 1.0)), box("bench", 3.0, size=(2.0, 0.4, 1.0))]
    objects += [box(f"cup{j}", size=(0.2, 0.2, 0.2)) for j in range(3)] + [box("mug", size=(0.2, 0.2, 0.3))]
    objects += [box("odd", size=(0.2, 0.2, 0.2)), box("spoon", size=(0.1, 0.1, 0.1))]
    said = [c("on", f"cup{j}", "shelf") for j in range(3)] + [c("on", "mug", "shelf"), c("on", "odd", "bench")]
    said += [c("on", "cup2", "shelf"), c("on", "spoon", "cup0")]
    search = _Search(objects, [Constraint(**x) for x in said], None, None, set(), 0)
    twins = {search.objects[i].id: {search.objects[j].id for j in js} for i, js in search.twins.items()}
    assert twins["cup1"] == set()  # cup0 holds a spoon, cup2 has another constraint; the mug is taller
    assert twins["odd"] == set() and "cup0" not in twins and "shelf" not in twins


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(3, 12), st.integers(0, 10_000), st.booleans(), st.data())
def test_any_pose_answers_as_the_full_set_of_poses_does(n, seed, in_room, data):
    # Forward checking asks any_pose() (each constraint judged only where the ones before hold,
    # the room only where all hold); poses() judges every candidate: the answers must agree,
    # and both draw the same random candidates, so the search goes on the same either way.
    from scenewright.layout.solver import _Search
    from scenewright.scene import Room

    p = planted_problem(n, seed, with_meshes=False)
    room = Room.rectangle(*p.bounds) if in_room else None
    quick, full = (_Search(p.objects, p.constraints, None, p.bounds, (), seed, room=room) for _ in range(2))
    placed = data.draw(st.sets(st.integers(0, len(p.objects) - 1)))
    for search in (quick, full):
        for i in sorted(placed):
            search.put(i, np.array(p.solution[i].position.tuple()), p.solution[i].yaw)
    for i, item in quick.items.items():
        for density in ("probe", "check", "wide"):
            poses = full.poses(full.items[i], density)
            assert quick.any_pose(item, density) == bool(np.any(poses.ok & poses.inside))
            assert quick.any_pose(item, density, bounded=False, inside=False) == bool(
                full.poses(full.items[i], density, bounded=False).ok.any())


def test_a_stack_too_tall_for_the_room_gives_up_its_top_at_once():
    # Its height is its support's top wherever the two stand: no jump back, no restart can help.
    from scenewright.scene import Room

    room = Room.model_validate({**Room.rectangle(4.0, 4.0).model_dump(), "height": 2.5})
    objects = [box("dresser", size=(1.0, 0.5, 1.6)), box("trunk", size=(0.6, 0.4, 0.5)),
               box("hatbox", size=(0.4, 0.4, 0.6))]
    constraints = [c("on", "trunk", "dresser"), c("on", "hatbox", "trunk")]
    result = solve(objects, constraints, room=room, seed=3)
    assert result.report.placed == ["dresser", "trunk"]
    (top,) = result.report.unplaced
    assert top.id == "hatbox" and "ceiling" in top.reason
    assert result.report.nodes <= 10  # one search, no backjumps


def _class_on_a_pew(dx, dy):
    """A teacher near a desk at the front wall, a pew (placed first, the larger) behind the desk
    and two pupils on it in front of the teacher, facing her: she must stand beyond the pew, away
    from where her candidates start."""
    objects = [box("desk", -1.0 + dx, -2.2, size=(1.8, 0.9, 0.76)),
               box("pew", -0.8 + dx, -1.2 + dy, size=(1.6, 0.6, 0.45)),
               box("teacher", 0.5 + dx, -2.3, size=(0.5, 0.8, 1.7)),
               box("pupil_1", -0.9 + dx, -1.1 + dy, size=(0.5, 0.6, 1.2)),
               box("pupil_2", -1.2 + dx, -1.1 + dy, size=(0.5, 0.6, 1.2))]
    constraints = [c("near", "teacher", "desk")] + [
        c(r, f"pupil_{k}", t) for k in (1, 2)
        for r, t in (("on", "pew"), ("in front of", "teacher"), ("face to", "teacher"))]
    return objects, constraints


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(dx=st.floats(-0.5, 1.5), dy=st.floats(-0.3, 0.3), seed=st.integers(0, 1000))
def test_a_class_on_a_pew_is_laid_out_whole_and_right(dx, dy, seed):
    objects, constraints = _class_on_a_pew(dx, dy)
    result = solve(objects, constraints, room=Room.rectangle(5.4, 5.4), seed=seed)
    assert result.report.complete
    by_id = {o.id: o for o in result.objects}
    for con in result.constraints:
        assert check(con.relation, by_id[con.source], by_id[con.target]), str(con)


def test_a_rerun_aims_where_a_dependent_can_stand():
    # The teacher's allowance runs out on the desk's side of the pew. Before, it did so again and
    # again in every rerun (395 nodes); now a rerun puts first her untried candidates that leave
    # the pupils a pose (the first search stays as it was, at most 130 nodes here).
    objects, constraints = _class_on_a_pew(0.0, 0.0)
    result = solve(objects, constraints, room=Room.rectangle(5.4, 5.4), seed=0)
    assert result.report.complete
    assert result.report.nodes <= 230


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(dx=st.floats(-0.5, 1.5), dy=st.floats(-0.3, 0.3), seed=st.integers(0, 1000))
@example(dx=0.0, dy=0.0, seed=0)  # one that aims (some first searches never run out of allowance)
def test_aiming_only_reorders_the_untried_candidates(dx, dy, seed):
    from scenewright.layout.solver import _Search

    seen = []
    aim = _Search.aim

    def watched(self, node):
        before = node.centres.copy(), node.yaws.copy(), node.cursor, len(node.centres)
        aimed = aim(self, node)
        seen.append((before, node.centres, node.yaws, aimed))
        return aimed

    objects, constraints = _class_on_a_pew(dx, dy)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(_Search, "aim", watched)
        solve(objects, constraints, room=Room.rectangle(5.4, 5.4), seed=seed)
    assert seen or (dx, dy, seed) != (0.0, 0.0, 0)
    for (centres, yaws, k, n), after, after_yaws, aimed in seen:
        assert len(after) == n
        assert np.array_equal(after[:k], centres[:k])  # what was tried stays as it was
        rows = lambda xy, y: sorted(map(tuple, np.column_stack([xy, y]).round(9)))
        assert rows(after[k:], after_yaws[k:]) == rows(centres[k:], yaws[k:])
        if not aimed:
            assert np.array_equal(after, centres)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_rerun_moves_a_support_by_what_its_load_must_leave_room_for(seed):
    # A walrus left of and in front of a pup on a crate by the front wall has no room there. The
    # pup fails, not the walrus: before, each jump back moved the crate by a pup's size (0.15 m)
    # until the search gave the walrus up; now a rerun moves it by the walrus's.
    room = Room.model_validate({**Room.rectangle(9.9, 10.3).model_dump(), "height": 2.7})
    objects = [box("crate", 2.0, -3.0, size=(2.4, 0.6, 0.3)), box("pup", 2.0, -3.0, z=0.45, size=(0.3, 0.3, 0.3)),
               box("walrus", -0.7, 0.0, size=(2.2, 4.4, 2.0))]
    constraints = [c("on", "pup", "crate"), c("left of", "walrus", "pup"), c("in front of", "walrus", "pup"),
                   c("face to", "walrus", "pup")]
    result = solve(objects, constraints, room=room, seed=seed)
    assert result.report.complete
    by_id = {o.id: o for o in result.objects}
    for con in result.constraints:
        assert check(con.relation, by_id[con.source], by_id[con.target]), str(con)


def _searches(objects, constraints, **kw):
    """The layout, and the node budget of each search :func:`solve` ran."""
    from scenewright.layout import solver

    budgets = []
    dfs = solver._dfs

    def watched(search, deadline, node_limit, first=frozenset()):
        budgets.append(node_limit)
        return dfs(search, deadline, node_limit, first)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(solver, "_dfs", watched)
        return solve(objects, constraints, **kw), budgets


@pytest.mark.parametrize("tall", [2.3, 1.2])
def test_a_lamp_over_a_cupboard_that_reaches_the_ceiling_is_given_up_at_once(tall):
    # Hung above a wardrobe that nearly reaches the ceiling, a lantern has no height it can
    # take wherever the two stand: no rerun can mend that, so one search is all the solve runs
    # (before, four, each jumping back into the wardrobe). A lower wardrobe leaves it room.
    room = Room.rectangle(4.0, 4.0, height=3.0)
    objects = [box("wardrobe", 1.0, 1.0, size=(1.0, 0.6, tall)), box("lantern", 0.0, 0.0, z=2.2, size=(0.3, 0.3, 0.4)),
               box("stool", -1.0, 0.0, size=(0.4, 0.4, 0.45))]
    constraints = [c("above", "lantern", "wardrobe"), c("near", "stool", "wardrobe")]
    result, budgets = _searches(objects, constraints, room=room, seed=0)
    if tall > 2.0:
        assert [u.id for u in result.report.unplaced] == ["lantern"]
        assert [str(x) for x in result.report.unplaced[0].failed] == ["lantern above wardrobe"]
        assert len(budgets) == 1
    else:
        assert result.report.complete


def test_the_last_rerun_searches_twice_as_long_as_the_first_not_all_that_is_left():
    # Nine crates a metre wide cannot all stand in a 2.2 m room: every search fails, and the last
    # one stops at twice a first search's nodes rather than running on through the whole budget.
    from scenewright.layout.solver import ATTEMPT_NODES, LAST_NODES, RESTARTS

    objects = [box(f"crate_{k}", 0.1 * k, 0.0, size=(1.0, 1.0, 0.5)) for k in range(9)]
    result, budgets = _searches(objects, [], room=Room.rectangle(2.2, 2.2), seed=0)
    assert not result.report.complete
    first = ATTEMPT_NODES * len(objects) + 100
    assert budgets[:RESTARTS] == [first] * (RESTARTS - 1) + [LAST_NODES * first]


@pytest.mark.parametrize("seed", [0, 1])
@pytest.mark.parametrize("relation, dx, dy", [("left of", -0.9, 0.0), ("right of", 0.9, 0.0),
                                              ("in front of", 0.0, -0.9), ("side of", 0.9, 0.0)])
def test_a_thing_set_beside_its_target_stays_beside_it_when_the_target_moves(relation, dx, dy, seed):
    # A sapling must leave its first spot (a kiln stands there); the ladder the first poses leaned
    # against it goes with it, rather than to the spot of the half-plane nearest its old one,
    # metres off along the kiln.
    objects = [box("kiln", size=(6, 6, 1)), box("sapling", size=(1, 1, 3)), box("ladder", dx, dy, size=(0.6, 0.4, 2))]
    result = solve(objects, [c(relation, "ladder", "sapling")], fixed=["kiln"], seed=seed, bounds=(30.0, 30.0))
    by_id = {o.id: o for o in result.objects}
    assert np.hypot(by_id["sapling"].position.x, by_id["sapling"].position.y) > 3.0  # it did move
    assert check(relation, by_id["ladder"], by_id["sapling"])
    assert plan_gap(by_id["ladder"], by_id["sapling"]) <= 0.5
