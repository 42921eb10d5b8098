"""The open vocabulary: unknown nouns become guessed objects of a shape family; places set the scene."""

import json

import pytest

from scenewright.core.catalogue import load_catalogue
from scenewright.analysis.parser import parse_scene
from scenewright.analysis.parser.vocabulary import GENERIC, load_vocabulary, scaled


def objects(text: str) -> dict[str, tuple[str, bool]]:
    """name → (category, guessed), one entry per distinct name."""
    return {o.name: (o.category, o.guessed) for o in parse_scene(text).objects}


def test_every_entry_names_a_catalogue_category_with_a_plausible_size():
    catalogue = load_catalogue()
    vocabulary = load_vocabulary()
    assert len(vocabulary.entries) > 500
    for phrase, entry in vocabulary.entries.items():
        assert entry.category in catalogue, phrase
        assert entry.rests in ("ground", "surface", "hanging"), phrase
        assert 0.01 < max(entry.size) <= 40, phrase


def test_families_are_catalogue_records_reached_only_through_the_vocabulary():
    catalogue = load_catalogue()
    families = {"animal", "bird", "figure", "machine", "tank", "structure", "panel", "container", "tool",
                "vehicle", GENERIC}  # fmt: skip
    assert families <= set(catalogue)
    assert {name for name, c in catalogue.items() if c.family} == families - {"bird"}
    # "all sorts of things" names no object even though "thing" is a family
    assert parse_scene("A room with all sorts of things and a sofa.").objects[0].category == "sofa"


@pytest.mark.parametrize(
    "text, name, category",
    [
        ("A camel rests near the well.", "camel", "animal"),
        ("Three pigs wallow in the mud.", "pig", "animal"),
        ("Two fuel tanks stand by the road.", "fuel tank", "tank"),
        ("A ferris wheel turns slowly.", "ferris wheel", "structure"),
        ("An anvil sits in the forge.", "anvil", "tool"),
        ("A street musician plays by the fountain.", "street musician", "figure"),
        ("A knight guards the gate.", "knight", "figure"),
        ("A helicopter is parked beside the crates.", "helicopter", "vehicle"),
        ("An arcade cabinet glows in the corner.", "arcade cabinet", "machine"),
        ("A scoreboard stands near the field.", "scoreboard", "panel"),
        ("A rooster struts across the yard.", "rooster", "bird"),
        ("A triceratops roams among the trees.", "triceratops", "animal"),
    ],
)
def test_unknown_nouns_become_guessed_objects_named_by_the_text(text, name, category):
    found = objects(text)
    assert found[name] == (category, True), found


def test_dragon_statue_is_a_statue_named_dragon_statue():
    found = objects("A dragon statue stands in the plaza.")
    assert found == {"dragon statue": ("statue", False)}


def test_a_noun_nobody_listed_is_a_generic_thing_not_dropped():
    parsed = parse_scene("A zorbulator stands next to a bench.")
    thing = next(o for o in parsed.objects if o.name == "zorbulator")
    assert thing.guessed and thing.id == "zorbulator_1"
    assert thing.category in load_catalogue()  # a family ("…ator" → machine) or the generic thing
    assert any(r.source == thing.id and r.relation == "side of" for r in parsed.relations)


@pytest.mark.parametrize(
    "text",
    [
        "A sunny afternoon in the park with a bench.",
        "A bench under a clear blue sky on a windy day.",
        "A bench with a view of the sea at sunset.",
        "A bench in a quiet corner, a sense of calm everywhere.",
    ],
)
def test_times_weather_places_and_abstract_nouns_are_no_objects(text):
    assert [o.category for o in parse_scene(text).objects] == ["bench"]


def test_sizes_follow_the_head_word_and_size_words():
    pig = next(o for o in parse_scene("A pig.").objects)
    giant = next(o for o in parse_scene("A giant pig.").objects)
    tiny = next(o for o in parse_scene("A tiny pig.").objects)
    assert giant.size[2] > pig.size[2] > tiny.size[2]
    assert scaled((1.0, 2.0, 3.0), ["huge"]) == (2.0, 4.0, 6.0)
    elephant = next(o for o in parse_scene("An elephant.").objects)
    assert elephant.size[2] > 2.5 > pig.size[2]


def test_size_words_resize_things_within_bounds():
    """A name already says a typical size, so size words move it only so far ("a giant
    drilling rig" is no 40 m tower); a person's barely at all ("a tall woman" is no giant)."""
    sizes = {o.description: o.size for o in parse_scene(
        "A small wardrobe, a wardrobe, a huge wardrobe and a colossal sofa. A tall woman waves."
    ).objects}
    wardrobe = sizes["wardrobe"][2]
    assert 0.35 * wardrobe <= sizes["small wardrobe"][2] < wardrobe < sizes["huge wardrobe"][2] <= 1.6 * wardrobe
    sofa = next(o for o in parse_scene("A sofa.").objects).size
    assert sizes["colossal sofa"][0] == pytest.approx(1.6 * sofa[0], abs=1e-3)
    woman = next(o for o in parse_scene("A woman waves.").objects).size
    assert woman[2] < sizes["tall woman"][2] <= 1.1 * woman[2] + 1e-3


def test_guessed_things_rest_where_their_kind_rests():
    parsed = parse_scene("A workbench with a hammer, and an anvil beside it.")
    rests = {o.name: o.rests for o in parsed.objects if o.guessed}
    assert rests == {"hammer": "surface", "anvil": "ground"}


def test_the_pig_is_not_the_camel():
    parsed = parse_scene("A camel stands by the well. A pig sleeps near the camel.")
    assert sorted(o.id for o in parsed.objects if o.guessed) == ["camel_1", "pig_1"]
    assert ("pig_1", "near", "camel_1") in {(r.source, r.relation, r.target) for r in parsed.relations}


@pytest.mark.parametrize(
    "text, kept, place",
    [
        ("A sci-fi hangar with a spaceship and two fuel tanks.", {"spaceship"}, "hangar"),
        ("Inside a warehouse, a forklift stands beside the crates.", {"forklift", "crate"}, "warehouse"),
    ],
)
def test_a_place_word_sets_the_scene_instead_of_building_it(text, kept, place):
    parsed = parse_scene(text)
    categories = {o.category for o in parsed.objects}
    assert "warehouse" not in categories and "building" not in categories
    assert {o.name.split()[-1] for o in parsed.objects} >= kept
    assert place in parsed.places and parsed.indoor


def test_a_farmhouse_kitchen_builds_no_house():
    parsed = parse_scene("A farmhouse kitchen with a table and two chairs.")
    assert sorted(o.category for o in parsed.objects) == ["chair", "chair", "table"]


def test_a_building_the_text_places_stays_an_object():
    parsed = parse_scene("A barn stands behind the pond.")
    assert [o.category for o in parsed.objects] == ["barn", "pond"]


@pytest.mark.parametrize(
    "text, absent",
    [
        ("Two robots stand guard beside the gate.", "guard"),
        ("Stone fox statues guard the path.", "guard"),
        ("A round rug with a bear face lies on the floor.", "bear"),
        ("Two camel-hair tents are pitched by the pool.", "camel"),
        ("A potted fig plant stands next to the sofa.", "plant stand"),
        ("Crates overflow with apples, pumpkins and carrots.", "pumpkin"),
    ],
)
def test_nouns_used_as_verbs_kinds_or_contents_are_no_objects(text, absent):
    assert absent not in objects(text)


def test_a_place_floor_is_the_setting():
    parsed = parse_scene("An abandoned factory floor with a rusted conveyor belt and a pile of scrap metal.")
    assert [o.name for o in parsed.objects] == ["conveyor belt"]
    assert parsed.places == ["factory"] and parsed.indoor


def test_people_count_as_figures_and_taxis_as_cars():
    parsed = parse_scene("A busy street with lots of people, a food truck and a couple of taxis.")
    categories = [o.category for o in parsed.objects]
    assert categories.count("figure") == 5 and categories.count("car") == 2 and "thing" not in categories


def test_counted_plurals_of_compound_things_are_things():
    found = objects("Two music stands, three thermoses and a donkey tied to a post.")
    assert found["music stand"] == ("tool", True) and found["thermos"] == ("tool", True)
    assert found["post"] == ("thing", True)
    assert objects("A potted fig plant stands next to the sofa.").keys() >= {"sofa"}


def test_an_opening_place_or_a_part_of_one_is_the_setting():
    parsed = parse_scene("A neon cyberpunk hangar on the edge of the megacity, late at night. A spaceship sits in the middle.")
    assert [o.category for o in parsed.objects] == ["spaceship"] and parsed.places == ["hangar"]
    parsed = parse_scene("A small design office on the top floor of a converted warehouse. A desk stands by the window.")
    assert [o.category for o in parsed.objects] == ["desk"]
    assert [o.category for o in parse_scene("A warehouse.").objects] == ["warehouse"]  # nothing else: the thing


def test_a_participle_after_a_thing_is_no_kind():
    assert "ferris wheel" in objects("A huge ferris wheel strung with coloured bulbs turns slowly.")


@pytest.mark.parametrize(
    "word, family",
    [("lutenist", "figure"), ("custodian", "figure"), ("mountaineer", "figure"), ("zator", GENERIC), ("list", GENERIC)],
)
def test_trade_endings_give_people_and_short_stems_give_nothing(word, family):
    assert load_vocabulary().guess(word).category == family


def test_an_agent_noun_is_a_person_only_when_it_acts_like_one():
    vocabulary = load_vocabulary()
    assert vocabulary.guess_agent("gleaners", True).category == "figure"
    assert vocabulary.guess_agent("dehumidifier", False) is None
    assert vocabulary.guess_agent("blorp", True) is None  # no agent ending
    assert "shovels" in vocabulary.person_verbs and "stands" not in vocabulary.person_verbs


@pytest.mark.parametrize("name", ["vocabulary.json", "catalogue.json", "relation_phrases.json"])
def test_no_data_file_names_a_key_twice(name):
    """A key written twice loads as its last value and silently drops the first (two branches
    that both teach a word merge that way): every key once."""
    from importlib import resources

    def unique(pairs):
        keys = [k for k, _ in pairs]
        assert len(keys) == len(set(keys)), sorted({k for k in keys if keys.count(k) > 1})
        return dict(pairs)

    json.loads(resources.files("scenewright.data").joinpath(name).read_text(encoding="utf-8"), object_pairs_hook=unique)


@pytest.mark.parametrize(
    "text,name",
    [
        ("A baker kneads dough while his colleague sweeps the floor.", "colleague"),
        ("A partner waits at the gate.", "partner"),
        ("The old sailor rows the dinghy and his companion bails water.", "companion"),
    ],
)
def test_a_word_for_whose_someone_is_names_a_person(text, name):
    # "her colleague holds a bag": a relational word nobody listed is a person, not a thing
    assert objects(text)[name] == ("figure", True)


def test_a_short_word_in_ish_names_a_kind_and_a_long_one_describes():
    # "finish", "polish": nouns that name the kind of the next one; "greenish", "bluish" describe it
    assert objects("A finish ribbon is stretched between two stakes.")["finish ribbon"][0] == GENERIC
    found = {o.name for o in parse_scene("A greenish bottle and a bluish jug stand on the shelf.").objects}
    assert {"bottle", "jug"} <= found


def test_a_word_for_a_machine_and_a_bird_is_the_bird_when_it_does_what_birds_do():
    got = {o.id: o.category for o in parse_scene("Three cranes wade by the lake. A crane lifts a crate onto the pier.").objects}
    assert [got[k] for k in ("crane_1", "crane_2", "crane_3")] == ["bird"] * 3
    assert got["crane_4"] == "crane"


def test_a_plural_after_of_is_a_noun_not_a_verb():
    """"a cluster of hot dog stands" are stands, not dogs that stand."""
    got = {o.category for o in parse_scene("A ferris wheel turns above a cluster of hot dog stands.").objects}
    assert "market_stall" in got and "dog" not in got
