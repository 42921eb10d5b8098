from scenewright.analysis.composition.hosts import CARRIED, HAND, LONGEST, PLATFORM, RAISED, TOP_SHARE, fit_unsized, laid_flat, lengthen
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


def unsized(oid, name):
    """A guessed thing nobody sized: the generic family's middling crate."""
    return ParsedObject(id=oid, category="thing", name=name, description=name, size=(0.6, 0.6, 0.6), group=0, guessed=True)


def test_a_thing_nobody_sized_fits_a_hand_or_its_host_s_top_and_never_grows():
    keeper = obj("figure_1", "figure", (0.5, 0.3, 1.75))
    out = {o.id: o for o in fit_unsized(scene([keeper, unsized("whistle_1", "tin whistle")], [on("whistle_1", "figure_1")]))}
    assert max(out["whistle_1"].size) == HAND and out["figure_1"].size == keeper.size
    shelf = obj("nightstand_1", "nightstand", (0.5, 0.4, 0.6))
    out = {o.id: o for o in fit_unsized(scene([shelf, unsized("gizmo_1", "gizmo")], [on("gizmo_1", "nightstand_1")]))}
    assert max(out["gizmo_1"].size) == TOP_SHARE * 0.4
    dais = obj("stage_1", "stage", (6.0, 4.0, 1.0))
    big = unsized("gizmo_2", "gizmo")
    assert fit_unsized(scene([dais, big], [on("gizmo_2", "stage_1")]))[1].size == big.size  # small enough already
    sized = ParsedObject(id="lute_1", category="guitar", name="lute", description="lute", size=(0.4, 0.1, 0.9), group=0)
    assert fit_unsized(scene([keeper, sized], [on("lute_1", "figure_1")]))[1].size == sized.size  # a known size stays


def test_a_thing_nobody_knows_on_a_seat_a_rock_or_another_unknown_keeps_its_size():
    """There it is as likely someone the reader did not know ("two riggers on a boulder")."""
    stranger = unsized("oddling_1", "oddling")
    for host in (obj("bench_1", "bench", (1.6, 0.6, 0.85)), obj("rock_1", "rock", (1.2, 1.0, 0.8)), unsized("lift_1", "lift")):
        assert fit_unsized(scene([host, stranger], [on("oddling_1", host.id)]))[1].size == stranger.size, host.id


def test_a_board_people_or_animals_stand_on_lies_flat_and_one_with_a_notice_stays_upright():
    """"Four plasterers stand on a plank panel", "a goat on a board": a low deck, long enough for
    them; a board with a notice pinned on it is still a sign."""
    board = obj("panel_1", "panel", (1.2, 0.08, 1.6))
    men = [obj(f"figure_{i}", "figure", (0.55, 0.35, 1.75)) for i in range(4)]
    flat = laid_flat(scene([board, *men], [on(m.id, "panel_1") for m in men]))[0]
    assert flat.size[2] == RAISED and flat.size[1] >= 1.0 and flat.size[0] >= 4 * 0.55
    assert PLATFORM in flat.description
    goat = obj("animal_1", "animal", (0.4, 1.0, 0.8))
    assert laid_flat(scene([board, goat], [on("animal_1", "panel_1")]))[0].size[2] == RAISED
    plasterer = ParsedObject(id="plasterer_1", category="thing", name="plasterer", description="plasterer",
                             size=(0.6, 0.6, 0.6), group=0, guessed=True)  # an agent noun nobody listed
    assert laid_flat(scene([board, plasterer], [on("plasterer_1", "panel_1")]))[0].size[2] == RAISED
    notice = obj("paper_1", "paper", (0.3, 0.01, 0.4))
    assert laid_flat(scene([board, notice], [on("paper_1", "panel_1")]))[0].size == board.size
    table = obj("table_1", "table", (1.8, 0.9, 0.76))
    assert laid_flat(scene([table, men[0]], [on(men[0].id, "table_1")]))[0].size == table.size


def test_a_parasol_a_person_carries_is_the_hand_held_kind_and_one_on_the_ground_is_not():
    lady = obj("figure_1", "figure", (0.5, 0.3, 1.75))
    held = ParsedObject("umbrella_1", "umbrella", "parasol", "parasol", (2.2, 2.2, 2.3), group=1)
    out = {o.id: o for o in fit_unsized(scene([lady, held], [on("umbrella_1", "figure_1")]))}
    assert max(out["umbrella_1"].size) == CARRIED and out["umbrella_1"].size[0] == out["umbrella_1"].size[1]
    table = obj("table_1", "table", (1.8, 0.9, 0.76))
    assert fit_unsized(scene([table, held], []))[1].size == held.size  # shading a table: the patio kind


def test_a_refectory_bench_is_as_long_as_its_twelve_sitters():
    bench = obj("bench_1", "bench", (2.4, 0.6, 0.85))
    monks = [obj(f"monk_{i}", "figure", (0.5, 0.35, 1.75)) for i in range(12)]
    width = lengthen(scene([bench, *monks], [on(m.id, "bench_1") for m in monks]))[0].size[0]
    assert width >= 12 * 0.5


def test_a_counter_grows_to_take_the_stools_that_line_its_front():
    """"Six stools line the counter": one row along its front, not two rows crowding a 2 m counter."""
    counter = obj("counter_1", "counter", (2.0, 0.65, 0.92))
    stools = [obj(f"stool_{i}", "stool", (0.4, 0.4, 0.75)) for i in range(6)]
    front = [ParsedRelation(source=s.id, relation="in front of", target="counter_1") for s in stools]
    assert lengthen(scene([counter, *stools], front))[0].size[0] >= 6 * 0.4
    crowd = [obj(f"man_{i}", "figure", (0.5, 0.3, 1.75)) for i in range(6)]  # a queue is no row of seats
    queue = [ParsedRelation(source=m.id, relation="in front of", target="counter_1") for m in crowd]
    assert lengthen(scene([counter, *crowd], queue))[0].size == counter.size
