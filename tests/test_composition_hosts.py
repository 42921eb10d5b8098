from scenewright.analysis.composition.hosts import LONGEST, lengthen
from scenewright.analysis.parser import ParsedObject, ParsedRelation, ParsedScene


def obj(oid, category, size):
    return ParsedObject(id=oid, category=category, name=category, description=category, size=size, group=0)


def scene(objects, relations):
    return ParsedScene(text="", objects=objects, relations=relations, style="realistic", ground="floor", indoor=True)


def on(source, target):
    return ParsedRelation(source=source, relation="on", target=target)


def test_a_cabinet_grows_to_hold_two_aquariums_side_by_side():
    cabinet = obj("cabinet_1", "cabinet", (0.9, 0.45, 1.2))
    tanks = [obj(f"aquarium_{i}", "aquarium", (1.0, 0.4, 0.6)) for i in (1, 2)]
    out = {o.id: o for o in lengthen(scene([cabinet, *tanks], [on(t.id, "cabinet_1") for t in tanks]))}
    assert out["cabinet_1"].size[0] >= 2.0 + 0.1
    assert out["cabinet_1"].size[1:] == (0.45, 1.2)
    assert out["aquarium_1"].size == (1.0, 0.4, 0.6)


def test_a_deep_table_holds_its_load_in_rows_and_one_thing_changes_nothing():
    table = obj("table_1", "table", (1.8, 0.9, 0.76))
    plates = [obj(f"plate_{i}", "plate", (0.25, 0.25, 0.03)) for i in range(6)]
    out = lengthen(scene([table, *plates], [on(p.id, "table_1") for p in plates]))
    assert out[0].size == table.size  # three rows of two fit its top
    vase = obj("vase_1", "vase", (2.5, 0.3, 0.4))
    assert lengthen(scene([table, vase], [on("vase_1", "table_1")]))[0].size == table.size


def test_hosts_that_do_not_stretch_keep_their_size_and_none_passes_the_cap():
    stool = obj("stool_1", "stool", (0.4, 0.4, 0.45))
    cats = [obj(f"cat_{i}", "cat", (0.5, 0.25, 0.3)) for i in range(2)]
    assert lengthen(scene([stool, *cats], [on(c.id, "stool_1") for c in cats]))[0].size == stool.size
    counter = obj("counter_1", "counter", (2.0, 0.65, 0.92))
    crates = [obj(f"crate_{i}", "crate", (0.6, 0.6, 0.4)) for i in range(12)]
    assert lengthen(scene([counter, *crates], [on(c.id, "counter_1") for c in crates]))[0].size[0] == LONGEST


def test_a_host_the_catalogue_does_not_know_is_as_wide_as_its_load():
    sill = ParsedObject(id="sill_1", category="thing", name="sill", description="stone sill", size=(0.6, 0.6, 0.6),
                        group=0, guessed=True)
    pigeons = [obj(f"pigeon_{i}", "bird", (0.3, 0.3, 0.3)) for i in range(3)]
    out = {o.id: o for o in lengthen(scene([sill, *pigeons], [on(p.id, "sill_1") for p in pigeons]))}
    assert out["sill_1"].size[0] >= 3 * 0.3 + 0.2


def test_a_boulder_grows_as_a_whole_to_hold_three_goats_and_a_pebble_keeps_its_size():
    rock = obj("rock_1", "rock", (1.2, 1.0, 0.8))
    goats = [obj(f"goat_{i}", "animal", (0.4, 1.0, 0.8)) for i in (1, 2, 3)]
    grown = {o.id: o for o in lengthen(scene([rock, *goats], [on(g.id, "rock_1") for g in goats]))}["rock_1"]
    assert grown.size[0] * grown.size[1] >= 1.5 * 3 * 0.4 * 1.0 - 1e-3
    assert abs(grown.size[0] / grown.size[1] - 1.2) < 1e-3 and grown.size[2] > 0.8  # the same boulder, bigger
    crow = obj("bird_1", "bird", (0.3, 0.3, 0.3))
    assert lengthen(scene([rock, crow], [on("bird_1", "rock_1")]))[0].size == rock.size
