from scenewright.layout import clean_constraints, topological_order
from scenewright.scene import Constraint, SceneObject, Vec3


def objs(*ids):
    return [SceneObject(id=i, name=i, size=Vec3(x=1, y=1, z=1)) for i in ids]


def c(rel, s, t):
    return {"relation": rel, "source": s, "target": t}


def test_bad_entries_are_dropped_with_reasons():
    kept, dropped = clean_constraints(objs("a", "b"), [
        c("near", "a", "b"),
        c("near", "a", "b"),
        c("left of", "a", "a"),
        c("on", "a", "ghost"),
        c("under", "a", "b"),
        {"relation": "near", "source": "a"},
    ])
    assert [str(k) for k in kept] == ["a near b"]
    reasons = [d.reason for d in dropped]
    assert "duplicate" in reasons[0]
    assert "itself" in reasons[1]
    assert "unknown object 'ghost'" in reasons[2] and "objects are: a, b" in reasons[2]
    assert "unknown relation 'under'" in reasons[3] and "valid relations" in reasons[3]
    assert "target" in reasons[4]
    assert dropped[2].constraint == {"type": "vertical", "relation": "on", "source": "a", "target": "ghost"}


def test_relation_spelling_is_normalised():
    same = Constraint(relation="face to", source="a", target="b")
    kept, dropped = clean_constraints(objs("a", "b"), [c("Face_To", "a", "b"), same])
    assert [k.relation for k in kept] == ["face to"] and len(dropped) == 1


def test_cycles_are_broken_deterministically_keeping_vertical_first():
    given = [
        c("near", "table", "cup"), c("left of", "chair", "table"), c("on", "cup", "table"), c("near", "cup", "chair"),
    ]
    first = clean_constraints(objs("table", "cup", "chair"), given)
    second = clean_constraints(objs("table", "cup", "chair"), given)
    assert first == second
    kept, dropped = first
    assert "cup on table" in [str(k) for k in kept]
    assert [d.constraint["relation"] for d in dropped] == ["near"]
    assert dropped[0].constraint["source"] == "table" and "cycle" in dropped[0].reason


def test_long_cycle_reports_its_path():
    given = [c("near", "a", "b"), c("near", "b", "c"), c("near", "c", "a")]
    kept, dropped = clean_constraints(objs("a", "b", "c"), given)
    assert len(kept) == 2 and len(dropped) == 1
    assert "(c -> a -> b -> c, each placed relative to the next)" in dropped[0].reason


def test_topological_order_puts_targets_first():
    kept, _ = clean_constraints(objs("lamp", "table", "cup", "rug"), [
        c("on", "cup", "table"), c("above", "lamp", "table"), c("near", "table", "rug"),
    ])
    order = topological_order(["lamp", "table", "cup", "rug"], kept)
    assert order.index("rug") < order.index("table") < order.index("cup")
    assert order.index("table") < order.index("lamp")
    assert topological_order(["b", "a"], []) == ["b", "a"]
    assert topological_order(["b", "a"], [], key={"a": 0, "b": 1}.get) == ["a", "b"]


def test_mutual_facing_is_not_a_cycle_but_positional_cycles_still_are():
    given = [
        c("face to", "chair1", "chair2"), c("face to", "chair2", "chair1"),
        c("in front of", "chair1", "table"), c("behind", "chair2", "table"),
        c("face to", "table", "chair1"),  # closes a cycle with 'chair1 in front of table': still kept
        c("near", "table", "chair2"),  # closes a positional cycle: dropped
    ]
    kept, dropped = clean_constraints(objs("table", "chair1", "chair2"), given)
    assert [str(k) for k in kept] == [
        "chair1 face to chair2", "chair2 face to chair1", "chair1 in front of table", "chair2 behind table",
        "table face to chair1",
    ]
    assert [d.constraint["relation"] for d in dropped] == ["near"] and "cycle" in dropped[0].reason
    order = topological_order(["chair1", "chair2", "table"], kept)
    assert order.index("table") < order.index("chair1") and order.index("table") < order.index("chair2")
