"""A host the text places nowhere goes where the one thing on it is placed (composition.relational)."""

from scenewright.analysis.composition.footprint import Footprint
from scenewright.analysis.composition.relational import place_related
from scenewright.analysis.parser import ParsedObject, ParsedRelation


def obj(oid, category, size):
    return ParsedObject(id=oid, category=category, name=category, description=category, size=size, group=0)


def far_away(o, placed):
    return Footprint(40.0, 40.0, o.size[2] / 2, 0.0, o.size)


def test_a_tub_carrying_a_shrub_goes_where_the_shrub_is_said_to_be():
    """"A bay shrub grows in a tub to the left of the well": the tub takes the shrub's place, far
    enough out for the shrub's crown, and the shrub stands on it."""
    well = obj("well_1", "well", (1.5, 1.5, 1.0))
    shrub = obj("bush_1", "bush", (1.6, 1.6, 1.5))
    tub = obj("planter_1", "planter", (0.6, 0.6, 0.5))
    rels = [ParsedRelation("bush_1", "on", "planter_1"), ParsedRelation("bush_1", "left of", "well_1")]
    placed = place_related([well, shrub, tub], rels, far_away)
    w, p, s = placed["well_1"], placed["planter_1"], placed["bush_1"]
    assert p.x < w.x and abs(p.y - w.y) < 1.0
    assert w.x - p.x >= (1.5 + 1.6) / 2  # the crown clears the well
    assert (s.x, s.y) == (p.x, p.y) and s.z > p.z


def test_a_seat_keeps_its_own_placing():
    """A sitter's relations are not lent to the seat (the seat handling already brings it there)."""
    desk = obj("desk_1", "desk", (1.4, 0.7, 0.75))
    clerk = obj("clerk_1", "figure", (0.5, 0.3, 1.75))
    stool = obj("stool_1", "stool", (0.4, 0.4, 0.45))
    rels = [ParsedRelation("clerk_1", "on", "stool_1"), ParsedRelation("clerk_1", "left of", "desk_1")]
    placed = place_related([desk, clerk, stool], rels, far_away)
    assert (placed["stool_1"].x, placed["stool_1"].y) == (40.0, 40.0)


def test_a_long_seat_takes_the_side_all_its_sitters_share():
    """"Eight children sit on benches on both sides of the table": each bench goes to its sitters'
    side of the table, which turns its long sides to them (the children were on benches metres off)."""
    table = obj("table_1", "table", (1.8, 0.9, 0.8))
    kids = [obj(f"child_{i}", "figure", (0.4, 0.3, 0.7)) for i in range(1, 5)]
    benches = [obj("bench_1", "bench", (1.6, 0.6, 0.8)), obj("bench_2", "bench", (1.6, 0.6, 0.8))]
    rels = []
    for i, kid in enumerate(kids):
        rels += [ParsedRelation(kid.id, "on", f"bench_{i % 2 + 1}"),
                 ParsedRelation(kid.id, ("left of", "right of")[i % 2], "table_1")]
    placed = place_related([table, *kids, *benches], rels, far_away)
    t, left, right = placed["table_1"], placed["bench_1"], placed["bench_2"]
    assert t.yaw % 180 == 90  # its long sides face the benches
    assert left.x < t.x < right.x and abs(left.y - t.y) < 1.0 and abs(right.y - t.y) < 1.0
