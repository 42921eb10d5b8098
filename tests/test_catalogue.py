import pytest

from scenewright.core.catalogue import (
    RESTS,
    SHAPE_NAMES,
    _validate,
    load_catalogue,
    lookup,
    phrase_index,
    singular,
    words,
)

#: Categories allowed past 5 m because the real thing is that big (catalogue module docstring).
LARGE = {"barn", "building", "bus", "crane", "flagpole", "food_truck", "greenhouse", "house", "lighthouse",
         "palm_tree", "pier", "pine_tree", "rocket", "shipping_container", "spaceship", "tower", "tree", "tree_house", "truck",
         "warehouse", "windmill", "structure"}  # fmt: skip


def test_catalogue_is_large_and_well_formed():
    catalogue = load_catalogue()
    assert len(catalogue) >= 150
    for name, category in catalogue.items():
        assert category.name == name
        assert category.shape in SHAPE_NAMES, name
        assert category.rests in RESTS, name
        assert all(v > 0 for v in category.size), name
        assert set(category.tags) <= {"indoor", "outdoor"} and category.tags, name
        # a shape family is reached through the vocabulary's words, never by a phrase of its own
        assert category.synonyms or category.family, f"{name} has no synonyms"


def test_sizes_are_plausible():
    for category in load_catalogue().values():
        biggest = max(category.size)
        assert biggest >= 0.1, category.name
        if category.name not in LARGE:
            assert biggest <= 5.0, category.name


@pytest.mark.parametrize(
    "tag, names",
    [
        ("indoor", ("sofa", "armchair", "coffee_table", "tv", "rug", "floor_lamp", "bookshelf")),  # living
        ("indoor", ("bed", "nightstand", "wardrobe", "dresser")),  # bedroom
        ("indoor", ("fridge", "stove", "counter", "sink", "microwave")),  # kitchen
        ("indoor", ("bathtub", "toilet", "shower", "mirror")),  # bath
        ("indoor", ("desk", "office_chair", "monitor", "laptop", "filing_cabinet")),  # office
        ("indoor", ("school_desk", "whiteboard", "lectern", "locker")),  # classroom
        ("indoor", ("treadmill", "exercise_bike", "weight_bench", "yoga_mat")),  # gym
        ("indoor", ("lab_bench", "microscope", "flask", "fume_hood")),  # lab
        ("indoor", ("shop_shelf", "cash_register", "display_case", "mannequin")),  # shop
        ("indoor", ("statue", "pedestal", "display_case", "rope_barrier")),  # museum
        ("indoor", ("round_table", "chair", "menu_board", "wine_rack", "booth")),  # restaurant
        ("outdoor", ("bench", "lamp_post", "fire_hydrant", "bollard", "mailbox", "bus_stop", "traffic_light")),
        ("outdoor", ("car", "truck", "bus", "bicycle", "boat")),  # vehicles
        ("outdoor", ("tree", "pine_tree", "palm_tree", "bush", "flower_bed", "rock")),  # plants
        ("outdoor", ("market_stall", "crate", "barrel", "umbrella")),  # market
        ("outdoor", ("swing", "slide", "seesaw", "sandbox")),  # playground
        ("outdoor", ("fountain", "pond", "picnic_table", "gazebo")),  # park
        ("outdoor", ("lighthouse", "anchor", "buoy", "shipping_container")),  # dock
        ("outdoor", ("crystal", "cauldron", "robot", "portal", "hologram", "spaceship")),  # fantasy & sci-fi
        ("outdoor", ("house", "building", "kiosk", "tower")),  # buildings & kiosks
    ],
)
def test_every_kind_of_scene_is_covered(tag, names):
    catalogue = load_catalogue()
    for name in names:
        assert name in catalogue and tag in catalogue[name].tags, name


@pytest.mark.parametrize(
    "phrase, name",
    [
        ("couch", "sofa"),
        ("Couches", "sofa"),
        ("bookshelves", "bookshelf"),
        ("street lamps", "lamp_post"),
        ("boxes", "crate"),
        ("benches", "bench"),
        ("cacti", "cactus"),
        ("suits of armour", "suit_of_armor"),
        ("bedside table", "nightstand"),
        ("coffee_table", "coffee_table"),
        ("  Palm Trees ", "palm_tree"),
        ("koi", "fish"),
        ("squat rack", "squat_rack"),
        ("ice rink", "pond"),
        # "A of B" read as the compound "B A" the catalogue knows
        ("rack of dumbbells", "dumbbell_rack"),
        ("racks of bikes", "bike_rack"),
        ("rack of wine", "wine_rack"),
        ("demonstration bench", "lab_bench"),
        ("stack of magazines", "books"),
        ("white screen", "projector_screen"),
        ("computer screen", "monitor"),
        ("water basin", "fountain"),
        ("studio monitors", "speaker"),
    ],
)
def test_lookup_finds_synonyms_and_plurals(phrase, name):
    category = lookup(phrase)
    assert category is not None and category.name == name


@pytest.mark.parametrize("phrase", ["", "xylophone", "the", "happiness", "lake"])
def test_lookup_unknown_is_none(phrase):
    assert lookup(phrase) is None


def test_every_phrase_names_one_category():
    owners: dict[tuple[str, ...], set[str]] = {}
    for category in load_catalogue().values():
        if category.family:  # reached through the vocabulary, not by its own name
            continue
        for phrase in category.phrases:
            owners.setdefault(tuple(words(phrase)), set()).add(category.name)
    shared = {k: v for k, v in owners.items() if len(v) > 1}
    assert not shared
    assert set(phrase_index()) == set(owners)


@pytest.mark.parametrize(
    "plural, single",
    [("chairs", "chair"), ("benches", "bench"), ("shelves", "shelf"), ("berries", "berry"), ("glass", "glass"),
     ("bus", "bus"), ("boxes", "box"), ("cacti", "cactus"), ("pegasi", "pegasus"), ("tv", "tv"),
     ("volcanoes", "volcano"), ("potatoes", "potato"), ("canoes", "canoe"), ("horseshoes", "horseshoe")],
)  # fmt: skip
def test_singular(plural, single):
    assert singular(plural) == single


def test_validation_names_the_bad_field():
    entry = {"name": "thing", "synonyms": [], "size": [1, 1, 1], "rests": "ground", "shape": "blob", "tags": []}
    with pytest.raises(ValueError, match="unknown shape 'blob'"):
        _validate(entry, set())
    with pytest.raises(ValueError, match="rests 'floating'"):
        _validate({**entry, "shape": "generic", "rests": "floating"}, set())
    with pytest.raises(ValueError, match="three positive sizes"):
        _validate({**entry, "shape": "generic", "size": [1, 0, 1]}, set())
    with pytest.raises(ValueError, match="appears twice"):
        _validate({**entry, "shape": "generic"}, {"thing"})


@pytest.mark.parametrize(
    ("phrase", "category", "tallest"),
    [
        ("tall cat tree", "cat_tree", 2.0),  # furniture, not a 6 m tree
        ("scratching post", "scratching_post", 1.0),
        ("Christmas tree", "christmas_tree", 2.5),  # a room's tree, not a 7 m pine
        ("bird bath", "bird_bath", 1.0),  # not a 3 m fountain
        ("dog bed", "pet_bed", 0.4),  # not a person's bed
        ("coat tree", "coat_rack", 2.0),
        ("tree house", "tree_house", 8.0),
        ("oak tree", "tree", 8.0),  # the head's own category where no compound claims the phrase
    ],
)
def test_compound_nouns_name_their_own_thing(phrase, category, tallest):
    """A modifier that turns the head noun into another thing ("cat tree", "bird bath") is a
    phrase of that thing's category, so the longest match, not the head, picks shape and size."""
    found = lookup(phrase.split(" ", 1)[1] if phrase.startswith("tall ") else phrase)
    assert found is not None and found.name == category
    assert found.size[2] <= tallest
