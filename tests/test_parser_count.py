"""How many things the offline reader makes of a text."""

from collections import Counter

import pytest

from scenewright.analysis.parser import parse_scene


def counts(text: str) -> Counter:
    """Last word of each object's name → how many."""
    return Counter(o.name.split()[-1].lower() for o in parse_scene(text).objects)


@pytest.mark.parametrize(
    ("text", "word"),
    [
        ("A grocer weighs apples on the old scales, and a boy waits beside the scales.", "scale"),
        ("A pair of scales stands on the shop counter.", "scale"),
        ("The smith works the bellows by the forge while an apprentice sweeps behind the bellows.", "bellows"),
        ("A jeweller lifts a ring with pincers at her bench.", "pincers"),
    ],
)
def test_a_plural_only_noun_is_one_thing(text, word):
    assert counts(text)[word] == 1


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("A stone lion sits on every side of the monument.", "lion", 4),
        ("Lanterns glow on all sides of the gazebo.", "lantern", 4),
        ("Flower beds lie on all three sides of the lawn.", "bed", 3),
        ("Pillars run along every side of the market hall.", "pillar", 12),
        ("Two flags fly on every side of the tower.", "flag", 2),
    ],
)
def test_every_side_gives_one_a_side_and_a_row_along_each(text, word, many):
    assert counts(text)[word] == many


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("Four looms stand in a row, each loom fitted with a spindle.", "spindle", 4),
        ("Five trawlers lie at the quay, each boat moored to a bollard.", "bollard", 5),
        ("Three porters climb the pass, each of them with a basket on his back.", "basket", 3),
        ("Four rowers rest on the jetty, every one of them with an oar.", "oar", 4),
    ],
)
def test_each_member_named_again_or_of_them_gets_its_own(text, word, many):
    assert counts(text)[word] == many


def test_them_after_each_names_the_members_not_what_each_has():
    parsed = parse_scene(
        "Four mules stand in a row, each mule tied to a hitching post. The muleteer walks behind them."
    )
    rels = {(r.source.rsplit("_", 1)[0], r.relation, r.target.rsplit("_", 1)[0]) for r in parsed.relations}
    assert any(s == "muleteer" and k == "behind" and t == "mule" for s, k, t in rels)


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("Five fig trees grow in stone tubs along the terrace.", "tub", 5),
        ("Six small palms stand in brass pots beside the stairs.", "pot", 6),
        ("Two bay trees stand in a wide trough.", "trough", 1),
    ],
)
def test_plants_in_uncounted_pots_get_one_each(text, word, many):
    assert counts(text)[word] == many


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("A stone urn stands at each corner of the terrace.", "urn", 4),
        ("A red lamp glows at each wingtip of the glider.", "lamp", 2),
        ("A narrow bench with a cushion at each end sits by the wall.", "cushion", 2),
        ("A falconer stands with a hawk on each shoulder.", "falconer", 1),
    ],
)
def test_a_thing_at_each_corner_or_end_is_one_a_part(text, word, many):
    assert counts(text)[word] == many


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("An oil lamp burns on every bedside table.", "table", 3),
        ("An oil lamp burns on every bedside table.", "lamp", 3),
        ("A sentry waits at each gate.", "sentry", 3),
        ("A clerk stamps every parcel at the counter.", "parcel", 1),
    ],
)
def test_each_place_not_named_before_is_several(text, word, many):
    assert counts(text)[word] == many


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("A boy feeds a goat from a herd of about twenty grazing past the barn.", "goat", 21),
        ("A ranger watches a flock of thirty wheeling over the marsh behind a heron.", "heron", 1),
        ("A farmer leads a cow towards a herd of ten, resting under an oak.", "cow", 11),
    ],
)
def test_a_herd_of_a_number_is_that_many_of_the_animal_before(text, word, many):
    assert counts(text)[word] == many
    assert not {"about", "grazing", "wheeling", "resting"} & set(counts(text))


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("A shepherd minds a herd of about fifteen goats on the slope.", "goat", 15),
        ("Some thirty geese waddle past the barn.", "goose", 30),
        ("A crowd of a hundred fans cheers behind the barrier.", "fan", 50),
        ("Thirty guests watch from benches across from the island.", "guest", 30),
        ("Twenty-five chairs stand in the hall.", "chair", 25),
        ("Sixty lanterns hang over the square.", "lantern", 50),
        ("Twenty-two lanterns hang over the square.", "lantern", 22),
        ("Eleven monks walk past the gate.", "monk", 11),
    ],
)
def test_rough_and_large_counts_are_read_and_capped_at_a_crowd(text, word, many):
    assert counts(text)[word] == many
    assert "about" not in counts(text)


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("Rows of pupils sit on benches facing the blackboard, a dozen in all, each holding a candle.", "pupil", 12),
        ("Rows of pupils sit on benches facing the blackboard, a dozen in all, each holding a candle.", "candle", 12),
        ("Monks kneel on cushions along the wall, nine in total.", "monk", 9),
        ("Monks kneel on cushions along the wall, nine in total.", "cushion", 9),
        # a count in apposition right after the noun, wherever it stands; the word after it is its verb
        ("A tour bus has pulled in, and its passengers, a dozen of them, crowd along the parapet.", "passenger", 12),
        ("A tour bus has pulled in, and its passengers, a dozen of them, crowd along the parapet.", "crowd", 0),
    ],
)
def test_a_total_after_the_subject_counts_it(text, word, many):
    assert counts(text)[word] == many


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("Deer drink at the pond beyond the fence.", "deer", 3),  # no determiner: several
        ("A wooden frame hung with drying fish stands by the tent.", "fish", 3),
        ("The deer drinks from the pond.", "deer", 1),
        ("A sheep grazes by the wall.", "sheep", 1),
        ("Five sheep lie by the gate.", "sheep", 5),
        ("A farmer leads a flock of sheep past the barn.", "sheep", 6),  # the quantity word counts them
    ],
)
def test_a_bare_noun_whose_plural_is_its_singular_is_several(text, word, many):
    assert counts(text)[word] == many


@pytest.mark.parametrize(
    ("text", "many"),
    [
        ("Onlookers gather behind a rope barrier.", 10),  # a crowd word, bare: a crowd
        ("A grandstand packed with onlookers.", 10),
        ("A crowd of onlookers waits by the gate.", 10),  # as many, however it is said
        ("Two onlookers wait by the gate.", 2),
    ],
)
def test_a_bare_crowd_of_onlookers_is_a_crowd(text, many):
    assert counts(text)["onlooker"] == many


def test_a_count_in_digits_is_taken_as_meant():
    assert counts("30 chairs stand in rows in the hall.")["chair"] == 30


def test_each_then_a_passive_phrase_gives_one_per_member():
    """"Four stalls stand in a half circle, each lit by a lantern": four lanterns, one by each."""
    parsed = parse_scene("Four stalls stand in a half circle, each lit by a green lantern.")
    lanterns = [o for o in parsed.objects if o.category == "lantern"]
    assert len(lanterns) == 4
    assert {(r.source, r.target) for r in parsed.relations if r.relation == "near"} == {
        (f"lantern_{i}", f"market_stall_{i}") for i in range(1, 5)
    }


def test_on_each_of_the_n_hosts_is_one_on_each_of_n():
    parsed = parse_scene("A radio sits on each of the four crates.")
    assert sorted(o.category for o in parsed.objects) == ["crate"] * 4 + ["radio"] * 4
    assert {(r.source, r.target) for r in parsed.relations if r.relation == "on"} == {(f"radio_{i}", f"crate_{i}") for i in range(1, 5)}


@pytest.mark.parametrize(
    ("text", "word", "many"),
    [
        ("Two mules wait by the well, each loaded with two bundles of firewood.", "firewood", 4),
        ("Three sacks of flour lean against the cart.", "sack", 3),
        ("Bundles of straw lie by the barn.", "straw", 4),
    ],
)
def test_each_counted_lot_of_stuff_is_one_thing(text, word, many):
    assert counts(text)[word] == many


@pytest.mark.parametrize(
    "text",
    ["Building blocks are stacked into a tower next to the toy chest.", "Toy blocks lie piled into a tower by the bed."],
)
def test_the_shape_a_group_is_set_out_in_is_no_thing(text):
    assert counts(text)["tower"] == 0 and counts(text)["block"] >= 3


def test_counts_in_words_between_twelve_and_twenty_are_read():
    found = counts("Fourteen players sit on the benches, and seventeen fans wave by the gate.")
    assert found["player"] == 14 and found["fan"] == 17


def test_several_counted_on_each_side_are_that_many_a_side_and_on_either_side_one_each():
    assert counts("Two players stand on each side of the net.")["player"] == 4
    assert counts("Two lamps stand on either side of the bed.")["lamp"] == 2


def test_a_definite_plural_named_before_its_counted_group_is_that_group():
    text = "A librarian holds up a picture book for the children to see. Nine children sit on a rug in front of him."
    assert counts(text)["child"] == 9
    assert counts("Two boys kick a ball. The boys laugh while three girls watch.")["boy"] == 2  # back, as before


def test_counted_sitters_in_seats_named_before_without_a_count_have_a_seat_each():
    found = Counter(o.category for o in parse_scene(
        "A small planetarium. Rows of reclining seats curve around the projector. Twenty children lie back in the seats."
    ).objects)
    assert found["chair"] == 20, found
    # benches hold several: as many as before
    found = Counter(o.category for o in parse_scene("A locker room with benches along the walls. Fourteen players sit on the benches.").objects)
    assert found["bench"] < 14, found


def test_their_uncounted_things_come_one_per_owner_wherever_they_are_put():
    found = Counter(o.category for o in parse_scene(
        "A dozen spacesuits hang on racks along the back wall, their helmets on a shelf above them."
    ).objects)
    assert found["tool"] == 12, found  # the helmets: the spacesuits', not the racks'


def test_one_at_each_one_of_a_group_and_a_seat_named_once_is_a_seat_each():
    """"A clerk sits at each one on a comfy stool": a clerk per desk, a stool per clerk."""
    scene = parse_scene("Three desks stand in a row. A clerk sits at each one on a comfy stool.")
    assert Counter(o.category for o in scene.objects)["stool"] == 3
    found = {(r.source, r.relation, r.target) for r in scene.relations}
    assert {("clerk_3", "near", "desk_3"), ("clerk_3", "on", "stool_3")} <= found
    # a word nobody listed that sits on a seat is a person, and gets a seat of its own too
    mission = parse_scene("Three consoles face a screen. A flight controller sits at each one on a swivel chair.")
    kinds = Counter(o.category for o in mission.objects)
    assert kinds["figure"] == 3 and kinds["office_chair"] == 3


def test_stacked_in_a_pyramid_is_six_and_a_count_wins():
    assert counts("Oak barrels are stacked in a pyramid against the back wall.")["barrel"] == 6
    assert counts("Three crates are stacked into a tower by the door.")["crate"] == 3


def test_living_things_on_every_one_of_a_group_are_one_each_and_things_a_few():
    assert counts("Ten trampolines stand in two rows, and children bounce on every one of them.")["child"] == 10
    assert counts("Four tables stand in the hall, and vases stand on each of them.")["vase"] == 12


def test_several_stacks_stand_as_that_many_columns():
    from scenewright.analysis.composition.formations import stack_relations

    parsed = parse_scene("Three stacks of metal crates stand along the left wall.")
    assert len(parsed.objects) == 9 and {o.formation_lines for o in parsed.objects} == {3}
    stacked = {(r.source, r.target) for r in stack_relations(parsed.objects, parsed.relations) if r.relation == "on"}
    assert stacked == {("crate_4", "crate_1"), ("crate_5", "crate_2"), ("crate_6", "crate_3"), ("crate_7", "crate_4"),
                       ("crate_8", "crate_5"), ("crate_9", "crate_6")}  # three columns of three on the first three


def test_a_plural_the_opening_names_without_a_count_is_the_group_counted_later():
    text = "A fishing contest among frogs, painted in soft gouache. Six frogs in straw hats sit along a wooden jetty."
    assert sum(o.category == "animal" and o.name.endswith("frog") for o in parse_scene(text).objects) == 6
    # a later sentence's plural is no opening: the rows after it are more of them
    shelves = ("A cave cut into a hillside. Tall shelves line both walls. Between the two rows of shelves, a "
               "trolley waits.")
    assert sum(o.category == "bookshelf" for o in parse_scene(shelves).objects) > 2


def test_some_of_them_placed_apart_are_split_from_the_rest():
    def on(text: str, host: str) -> set[str]:
        return {r.source for r in parse_scene(text).relations if r.relation == "on" and r.target.startswith(host)}

    assert len(on("Ten penguins huddle on the ice, and three of them dive from a floe.", "floe")) == 3
    assert len(on("Five boys play football, and one of them sits on a bench.", "bench")) == 1
    # one of a flanking pair who only turns its head keeps its side
    text = "Two scarecrows stand on either side of the farm gate, and one of them has turned its head to watch."
    sides = {r.relation for r in parse_scene(text).relations if r.source.startswith("scarecrow")}
    assert sides >= {"left of", "right of"}


def test_a_phrase_s_target_is_its_own_not_the_one_an_earlier_each_named():
    """"... with a monitor on every desk. A supervisor paces between the rows": the rows are no
    "every desk", so the supervisor is one, not one per desk."""
    got = counts("Eight imps sit at two rows of desks, with a glowing monitor on every desk. "
                 "A horned supervisor paces between the rows.")
    assert got["supervisor"] == 1 and got["monitor"] == 8, got


def test_each_at_its_own_thing_is_one_apiece_and_a_thing_of_its_own():
    got = counts("Ten young pandas kneel in two rows, each at its own low table with a brush on it.")
    assert got["table"] == 10 and got["brush"] == 10, got  # (the table was read as a part of a panda)
    assert counts("Four students sit in a row, each at his own desk.")["desk"] == 4


def test_groups_of_a_count_multiply_it():
    def count(text: str, category: str) -> int:
        return sum(o.category == category for o in parse_scene(text).objects)

    assert count("Two teams of five players crouch behind low wooden barricades.", "figure") == 10
    assert count("Three rows of four chairs face the stage.", "chair") == 12
    assert count("Two groups of three children play in the sand.", "figure") == 6
    assert count("A team of four firefighters sprays water on the barn.", "figure") == 4


def test_sitters_on_uncounted_benches_share_them():
    """A bench seats as many side by side as its length holds; a stool or a ring carries one."""
    got = counts("Eight children sit on benches on both sides of the table.")
    assert got["child"] == 8 and got["bench"] == 2, got
    assert counts("Four astronauts sit on stools.")["stool"] == 4
    assert counts("A dozen swimmers bob on inflatable rings in the pool.")["ring"] == 12


def test_a_stack_said_once_for_each_thing_is_a_stack_each():
    got = parse_scene("Two cannons stand on the deck, each with a stack of cannonballs beside it.")
    feet = {r.target for r in got.relations if r.source.startswith("cannonball") and r.relation == "side of"}
    assert feet == {"cannon_1", "cannon_2"}


def test_one_doing_something_to_each_one_is_one_at_each():
    got = counts("Six hydraulic presses stand in two rows of three, and a worker in ear defenders tends each one.")
    assert got["worker"] == 6 and got["press"] == 6 and got["defenders"] == 0, got


def test_a_people_group_of_a_kind_counts_its_people():
    got = counts("A pipe band of six pipers and two drummers marches past.")
    assert got["piper"] == 6 and got["drummer"] == 2 and got["band"] == 0, got
    assert counts("A family of four shelters under the awning.")["shelter"] == 0  # (their verb)


def test_a_host_named_in_a_fronted_phrase_before_each_is_not_one_each():
    got = parse_scene("Three bears sit on a blanket. On the blanket in front of each bear is a little plate.")
    assert Counter(o.category for o in got.objects)["picnic_blanket"] == 1
    rel = {(r.source, r.relation, r.target) for r in got.relations}
    assert {("plate_1", "in front of", "bear_1"), ("plate_3", "in front of", "bear_3")} <= rel


@pytest.mark.parametrize("text", [
    "On either side of the gate stands a stone lion.",
    "On either side of the temple door stands a stone lion, and a monk sweeps the steps between them.",
])
def test_a_fronted_either_side_gives_one_a_side(text):
    got = parse_scene(text)
    assert counts(text)["lion"] == 2
    if "monk" in text:
        rel = {(r.source, r.relation, r.target) for r in got.relations}
        assert {("monk_1", "right of", "stone_lion_1"), ("monk_1", "left of", "stone_lion_2")} <= rel


def test_swords_crossed_are_no_ground_to_stand_on():
    assert not any(r.relation == "on" and r.target.startswith("sword")
                   for r in parse_scene("Two knights cross swords on the drawbridge.").relations)


def test_teams_counted_by_members_are_no_things_of_the_verb():
    """"Two teams of three play under the hoop": six "play" things were read after the count."""
    assert {o.name for o in parse_scene("A park. Two teams of three play under the hoop.").objects} == {"team", "hoop"}
