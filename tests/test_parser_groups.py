"""Which words the offline reader makes things of, how many, and how groups share them out:
loads on what carries them, groups of groups, wares in hand, seats in rows."""

from collections import Counter

import pytest

from scenewright.analysis.parser import parse_scene


def counts(text: str) -> Counter:
    """Last word of each object's name → how many."""
    return Counter(o.name.split()[-1].lower() for o in parse_scene(text).objects)


def relations(text: str) -> set[tuple[str, str, str]]:
    """(source name, relation, target name) of every relation, by the objects' last words."""
    scene = parse_scene(text)
    name = {o.id: o.name.split()[-1].lower() for o in scene.objects}
    return {(name[r.source], r.relation, name[r.target]) for r in scene.relations}


@pytest.mark.parametrize(
    ("text", "load", "host"),
    [
        ("A barrow heaped with pumpkins waits; a market stall piled with baskets of plums stands by the well.", "basket", "stall"),
        ("A canal boat loaded with barrels is moored at the quay.", "barrel", "boat"),
        ("A wooden counter lined with toolboxes runs along the wall.", "toolbox", "counter"),
    ],
)
def test_a_countable_load_stands_on_what_it_is_piled_on(text, load, host):
    assert counts(text)[load] >= 2
    assert (load, "on", host) in relations(text)


def test_a_small_load_or_a_filling_stays_contents():
    assert counts("A market stall piled with plums stands by the well.")["plum"] == 0
    assert counts("A cupboard filled with boxes stands in the hall.")["box"] == 0


def test_the_holder_with_a_load_of_plural_contents_keeps_its_own_verb():
    # "crates of turnips waits": after a plural, "waits" is the cart's verb, not a compound noun
    found = relations("A handcart piled with crates of turnips waits by the barn.")
    assert ("handcart", "near", "barn") in found and ("crate", "near", "barn") not in found


def test_every_shelf_of_racks_named_before_is_those_racks():
    text = "Steel racks fill the storeroom, every shelf stacked with paint tins the size of buckets."
    assert counts(text)["shelf"] == 0
    text = "Two dressers stand by the wall, each shelf packed with toolboxes."
    assert counts(text)["shelf"] == 0 and ("toolbox", "on", "dresser") in relations(text)


def test_a_group_of_groups_counts_every_member():
    text = "Three teams of oxen drag logs uphill, each pair pulling a sledge with a drover behind it."
    assert counts(text)["ox"] + counts(text)["oxen"] == 6
    assert counts(text)["sledge"] == 3


def test_an_uncounted_plural_in_rows_is_several_a_row():
    text = "Vans are parked in three long rows, and a gazebo stands behind each one."
    assert counts(text)["van"] == 9 and counts(text)["gazebo"] == 9


def test_sitters_in_rows_of_chairs_have_a_chair_each():
    text = "Eight pupils sit in two rows of stools facing the blackboard."
    assert counts(text)["stool"] == 8
    assert ("pupil", "on", "stool") in relations(text)
    # a bench holds several: the rows keep the benches the quantity word makes
    assert counts("Nine monks sit in three rows of benches.")["bench"] == 3


def test_what_a_person_sells_from_the_hand_is_there_in_hand():
    text = "A hawker sells balloons beside the carousel."
    assert counts(text)["balloon"] == 3
    assert ("balloon", "on", "hawker") in relations(text)
    assert ("hawker", "side of", "carousel") in relations(text)
    # what a stall or a cart sells is its wares
    assert counts("A kiosk sells balloons beside the carousel.")["balloon"] == 0


def test_two_single_things_on_either_side_are_one_a_side():
    text = "A trumpeter and a cellist stand on either side of the harp."
    assert counts(text)["trumpeter"] == 1 and counts(text)["cellist"] == 1
    assert {("trumpeter", "left of", "harp"), ("cellist", "right of", "harp")} <= relations(text)
    assert counts("A stone urn stands on either side of the gate.")["urn"] == 2


def test_a_set_of_a_plural_only_noun_is_one():
    assert counts("A set of copper scales sits on the counter.")["scale"] == 1


def test_suits_of_armour_before_a_verb_are_the_subject():
    assert counts("Two suits of armour guard the stairs.")["armour"] == 2


def test_things_with_a_top_that_project_keep_their_kind():
    categories = {o.category for o in parse_scene("A holographic desk glows beside the console.").objects}
    assert "desk" in categories and "hologram" not in categories
    # a thing of light is a hologram
    assert {o.category for o in parse_scene("Two holographic whales drift above the pool.").objects} >= {"hologram"}


def test_a_thing_of_his_that_opens_a_clause_and_lies_somewhere_is_there():
    text = "The tanner stands at a bench; his leather apron lies on it beside a bucket."
    assert counts(text)["apron"] == 1 and ("apron", "on", "bench") in relations(text)
    # and whoever has a "his" is a person, so "it" is not him
    text = "The falconer stands at a table; his glove lies on it beside a knife."
    assert ("glove", "on", "table") in relations(text)


def test_an_unlisted_word_worn_before_a_person_verb_is_clothing():
    text = "A picker in a bandeau kneels beside the crates."
    assert counts(text)["bandeau"] == 0 and counts(text)["picker"] == 1


def test_a_leader_is_a_person():
    scene = parse_scene("The expedition leader stands by the tent.")
    assert [o.category for o in scene.objects] == ["figure", "tent"]


def test_kind_words_before_a_bare_plural_object_make_one_name():
    text = "A forklift robot carries steel girders up the ramp."
    assert counts(text)["girder"] == 3


def test_a_describing_word_that_ends_its_phrase_is_the_noun():
    # "baby" describes before a noun ("a baby elephant") and names one at the end ("a sleeping baby")
    assert counts("A father rocks a sleeping baby by the fire.")["baby"] == 1
    assert counts("A baby goat skips past the trough.")["goat"] == 1
    assert counts("A baby goat skips past the trough.")["baby"] == 0


def test_a_small_living_thing_held_is_in_arms():
    assert ("kitten", "on", "girl") in relations("A girl holds a kitten by the window.")
    assert ("pony", "on", "girl") not in relations("A girl holds a pony by the gate.")


def test_what_a_seat_or_perch_is_packed_with_is_a_crowd_on_it():
    text = "Terraces packed with supporters rise behind the pitch, and a jetty crowded with picnickers juts out."
    assert counts(text)["picnicker"] >= 3 and ("picnicker", "on", "jetty") in relations(text)
    # a cart's load is no crowd
    load = parse_scene("A wheelbarrow packed with dags stands by the shed.")
    assert {o.category for o in load.objects} == {"cart", "shed"}


def test_a_noun_after_a_quantity_of_names_the_kind_of_the_plural_after_it():
    # no "cat" can follow "a row of" alone: "cat stands" are stands of a kind, though "stands" is a verb too
    assert counts("A balloon drifts over a row of cat stands.")["stand"] == 4
    assert counts("A flock of sheep grazes by the wall.")["sheep"] >= 3


def test_separate_things_are_one_each():
    text = "Three clerks sit at separate desks facing the window."
    assert counts(text)["desk"] == 3
    assert counts("Two porters wait by separate carts.")["cart"] == 2


def test_a_bare_plural_subject_goes_on_past_what_sorts_it_comes_in():
    assert counts("A harbour at noon. Gliders of every shape fly above the boats.")["glider"] == 3
    assert counts("A harbour at noon. Zorbs of all sizes roll along the quay.")["zorb"] == 3


def test_a_ship_called_her_stays_a_ship():
    # "her" names ships too: only "his", or "her" with clothing or a body part, makes its owner a person
    scene = parse_scene("The steamer waits at the quay; her funnel smokes.")
    assert all(o.category != "figure" for o in scene.objects if o.name == "steamer")


def test_clothing_listed_in_the_plural_put_somewhere_is_there():
    text = "The glazier stands at the kiln; her gloves lie on the bench."
    assert counts(text)["glove"] >= 1 and ("glove", "on", "bench") in relations(text)


def test_every_person_of_a_list_with_commas_is_one_and_each_is_placed():
    text = "A tavern. A baker, a cook, a smith and a miller sit at a table."
    assert counts(text) == Counter({"baker": 1, "cook": 1, "smith": 1, "miller": 1, "table": 1})
    assert {(who, "near", "table") for who in ("baker", "cook", "smith", "miller")} <= relations(text)
    # a person renamed between commas is still one ("the keeper, an old woman, feeds ...")
    assert counts("A zoo. The keeper, an old woman, feeds the tiger.") == Counter({"keeper": 1, "tiger": 1})


def test_the_members_a_colon_lists_are_the_plural_before_it():
    text = ("A camp. Four adventurers sit around a crackling campfire on logs: a knight, an elf archer, "
            "a dwarf with an axe and a wizard holding a staff.")
    found = counts(text)
    assert found["adventurer"] == 0 and all(found[w] == 1 for w in ("knight", "archer", "dwarf", "wizard"))
    assert found["log"] == 4  # a log each, sat on
    scene = parse_scene(text)
    name = {o.id: o.name.split()[-1] for o in scene.objects}
    sides = {name[r.source]: r.relation for r in scene.relations
             if name[r.target] == "campfire" and r.relation in ("left of", "right of", "in front of", "behind")}
    assert set(sides) == {"knight", "archer", "dwarf", "wizard"} and len(set(sides.values())) == 4
    assert ("axe", "on", "dwarf") in relations(text) and ("staff", "on", "wizard") in relations(text)


def test_single_people_around_one_thing_share_its_sides():
    scene = parse_scene("A camp. A knight, an elf, a dwarf and a wizard sit around a campfire.")
    sides = [r.relation for r in scene.relations if r.relation in ("left of", "right of", "in front of", "behind")]
    assert sorted(sides) == sorted(["left of", "right of", "in front of", "behind"])


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A cafe. A round table with two chairs stands by the window.", "left of"),  # round it
        ("A cafe. Three tables stand by the window, each with two chairs.", "in front of"),
        ("An office. A desk with a chair stands by the window.", "in front of"),  # pulled up to its front
    ],
)
def test_seats_that_come_with_a_table_are_pulled_up_to_it(text, kind):
    found = relations(text)
    seat = next(s for s, r, t in found if r == "face to")
    assert (seat, kind, next(t for s, r, t in found if r == "face to")) in found


def test_each_with_a_thing_in_front_of_them_is_the_sitters():
    text = "A ramen bar. Five customers sit on tall stools along the counter, each with a bowl in front of them."
    found = relations(text)
    assert ("bowl", "in front of", "customer") in found and ("bowl", "in front of", "stool") not in found
    # "each with ... on it" is each of the things
    assert ("file", "on", "table") in relations("A court. Two lawyers stand at separate tables, each with a stack of files on it.")


def test_his_thing_after_one_on_each_is_each_ones():
    text = "Barracks in a castle tower. Six bunk beds line the walls, and a knight snores on each bed, his helmet on the floor beside the bed."
    found = counts(text)
    assert found["helmet"] == 6 and found["knight"] == 6
    scene = parse_scene(text)
    beside = {r.target for r in scene.relations if r.source.startswith("helmet")}
    assert len(beside) == 6  # each by his own bed
    # "her collie" after a flock is the girl's one collie
    assert counts("A green. A girl drives a flock of geese towards a pen, her collie trotting behind them.")["collie"] == 1


def test_each_with_a_thing_after_people_on_seats_is_each_person():
    text = "A taproom. Six customers sit on stools around a table, each with a glass of stout."
    assert counts(text)["glass"] == 6 and ("glass", "on", "customer") in relations(text)


def test_a_subjects_thing_in_hand_named_between_commas_leaves_the_subject_its_verb():
    found = relations("A harbour. The coxswain, radio in hand, waits at the foot of the slipway.")
    assert ("coxswain", "in front of", "slipway") in found and ("radio", "on", "coxswain") in found
