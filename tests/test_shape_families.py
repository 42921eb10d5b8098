"""Shape families for unknown nouns: each family and variant is a recognisable, styled,
multi-material object in its box, and names reach the right family."""

from __future__ import annotations

import numpy as np
import pytest
from test_procedural import FAMILIES, assert_fills, base_colours, load, scene_frame

from scenewright.analysis.parser import parse_scene
from scenewright.procedural.meshes import build_glb, build_model, choose_shape
from scenewright.procedural.shapes.families import FAMILY_WORDS, family_of
from scenewright.scene import STYLES

CASES = [(family, name) for family, names in FAMILIES.items() for name in names]
BOX = (1.0, 2.0, 2.0)


def points(shape: str, size, name: str, roles=None) -> np.ndarray:
    parts = scene_frame(build_model(shape, size, "realistic", 1, name=name))
    return np.concatenate([g.vertices for role, g in parts.items() if roles is None or role in roles])


@pytest.mark.parametrize(("family", "name"), CASES)
def test_every_variant_fills_its_box_with_several_materials(family, name):
    size = (1.2, 1.6, 1.4)
    glb = build_glb(family, size, "realistic", 4, name=name)
    assert_fills(glb, size)
    scene = load(glb)
    assert len(scene.geometry) >= 3, f"{name}: parts with their own materials"
    assert sum(len(g.faces) for g in scene.geometry.values()) <= 6000


@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_a_family_s_variants_differ(family):
    looks = {tuple(sorted((role, len(g.vertices)) for role, g in build_model(family, (1, 1, 1), "realistic", 1, name=n).geometry.items()))
             for n in FAMILIES[family]}
    assert len(looks) == len(FAMILIES[family])


@pytest.mark.parametrize("family", sorted(FAMILY_WORDS))
def test_styles_restyle_every_family(family):
    name = FAMILIES[family][0]
    looks = set()
    for style in STYLES:
        scene = build_model(family, (1, 1, 1), style, 1, name=name)
        looks.add(tuple(np.round(np.concatenate(sorted(base_colours(scene).values(), key=tuple)), 2)))
    assert len(looks) == len(STYLES)


def test_animals_read_as_their_animal():
    def mid_height(name):
        p = points("animal", BOX, name)
        middle = p[(np.abs(p[:, 1]) < 0.2 * BOX[1]) & (np.abs(p[:, 0]) < 0.2 * BOX[0])]
        return middle[:, 2].max() / BOX[2]

    assert mid_height("camel") > mid_height("horse") + 0.15, "a camel has a hump in the middle of its back"
    giraffe = points("animal", BOX, "giraffe")
    assert giraffe[giraffe[:, 2] > 0.9 * BOX[2], 1].mean() < -0.3 * BOX[1], "a giraffe's head is high and in front"
    trunk = points("animal", BOX, "elephant")
    assert np.any((trunk[:, 1] < -0.3 * BOX[1]) & (trunk[:, 2] < 0.25 * BOX[2]) & (np.abs(trunk[:, 0]) < 0.15 * BOX[0])), \
        "an elephant's trunk reaches down in front"
    wings = points("animal", BOX, "dragon", roles={"wing"})
    assert np.abs(wings[:, 0]).max() > 0.45 * BOX[0] and wings[:, 2].max() > 0.9 * BOX[2], "a dragon spreads its wings"
    pig = scene_frame(build_model("animal", (0.5, 1.0, 0.55), "realistic", 1, name="pig"))
    assert "skin_pink" in pig, "a pig is pink"


def test_figures_stand_and_hold_what_they_are_named_for():
    size = (0.6, 0.5, 1.75)
    musician = scene_frame(build_model("figure", size, "realistic", 1, name="street musician"))
    assert musician["hair"].vertices[:, 2].max() > 0.95 * size[2], "the head is at the top"
    guitar = musician["wood"].vertices
    assert guitar[:, 1].max() < 0 and 0.3 * size[2] < guitar[:, 2].mean() < 0.7 * size[2], "a guitar held in front"
    knight = scene_frame(build_model("figure", size, "realistic", 1, name="knight"))
    assert {"metal", "chrome", "paint"} <= set(knight), "armour, a sword and a shield"
    assert "hair" not in knight


def test_structures_and_tanks_have_their_shape():
    wheel = points("structure", (20, 8, 22), "ferris wheel", roles={"paint"})
    hub = np.array([0.0, 22 - 0.06 * 22 - 0.9 * 10])
    radius = np.hypot(wheel[:, 0] - hub[0], wheel[:, 2] - hub[1])
    rims = radius[radius > 5]
    assert rims.std() < 0.05 * rims.mean(), "the ferris wheel's rims are circles about the hub"
    fuel = points("tank", (3, 1.4, 1.6), "fuel tank", roles={"paint"})
    assert np.ptp(fuel[:, 0]) > 2 * np.ptp(fuel[:, 2]), "a fuel tank lies on its side"
    silo = points("tank", (3, 3, 8), "silo")
    assert np.ptp(silo[:, 2]) > 2 * np.ptp(silo[:, 0])


def test_a_statue_shows_its_subject_on_a_plinth():
    size = (1.5, 1.5, 2.5)
    lion = scene_frame(build_model("statue", size, "realistic", 1, name="lion statue"))
    person = scene_frame(build_model("statue", size, "realistic", 1, name="statue"))
    for statue in (lion, person):
        assert statue["stone"].vertices[:, 2].max() < 0.25 * size[2] and statue["marble"].vertices[:, 2].min() > 0.15 * size[2]
    lion_extent, person_extent = np.ptp(lion["marble"].vertices, axis=0), np.ptp(person["marble"].vertices, axis=0)
    assert lion_extent[1] > 1.3 * lion_extent[0], "a four-legged subject runs front to back"
    assert person_extent[2] > 1.5 * person_extent[1], "a figure stands"
    gold = build_model("statue", size, "realistic", 1, name="gold statue").geometry
    assert "gold" in gold and gold["gold"].visual.material.metallicFactor == 1.0


def test_a_round_mirror_is_round_in_any_box():
    for size in ((0.6, 0.04, 0.9), (0.6, 0.3, 1.5), (0.8, 0.05, 0.8)):
        glass = scene_frame(build_model("mirror", size, "realistic", 1, name="round mirror"))["mirror"].vertices
        width, _, height = np.ptp(glass, axis=0)
        assert width == pytest.approx(height, rel=0.02), size
    square = scene_frame(build_model("mirror", (0.6, 0.04, 0.9), "realistic", 1, name="mirror"))["mirror"].vertices
    assert np.ptp(square[:, 2]) > 1.3 * np.ptp(square[:, 0])


@pytest.mark.parametrize(
    ("name", "family"),
    [("camel", "animal"), ("three pigs", "animal"), ("dragon statue", "animal"), ("statue of a horse", "animal"),
     ("street musician", "figure"), ("man with a guitar", "figure"), ("fuel tanks", "tank"), ("ferris wheel", "structure"),
     ("anvil", "tool"), ("boxes", "container"), ("notice board", "panel"), ("golf cart", "vehicle"), ("parrot", "bird"),
     ("horse cart", None), ("queen bed", None), ("hot dog stand", None), ("statue", None), ("bronze cannon", "tank")],
)
def test_a_name_s_head_noun_picks_the_family(name, family):
    assert family_of(name) == family


@pytest.mark.parametrize(
    ("name", "category", "shape"),
    [("camel", None, "camel_shape"), ("camel", "animal", "animal"), ("fuel tank", None, "tank"),
     ("street musician", "figure", "figure"), ("ferris wheel", None, "structure"), ("anvil", None, "tool"),
     ("dragon statue", "statue", "statue"), ("tractor", None, "truck"), ("cannon", None, "tank")],
)
def test_family_names_and_words_choose_the_shape(name, category, shape):
    expected = "animal" if shape == "camel_shape" else shape
    assert choose_shape(name, category) == expected


def test_the_generic_shape_follows_any_hint_in_the_name():
    camel = build_model("generic", (0.7, 2.2, 2.1), "realistic", 1, name="camel")
    assert "fur_light" in camel.geometry and len(camel.geometry) >= 3
    assert "wing" in build_model("generic", (3, 4, 2), "realistic", 1, name="dragon").geometry
    draped = build_model("generic", (1, 1, 1), "realistic", 1, name="thingamajig")
    assert set(draped.geometry) == {"fabric"}  # no hint: a lump under a dust sheet, not a crate-like block


@pytest.mark.parametrize(
    ("noun", "shape"),
    [("zeppelin", "vehicle"), ("ore cart", "cart"), ("outcrop", "rock"), ("anthill", "rock"), ("bleachers", "structure"),
     ("catapult", "structure"), ("spyglass", "tool"), ("magnifier", "tool"), ("manuscript", "tool"), ("golf club", "tool"),
     ("rucksack", "container"), ("cool box", "container"), ("record player", "tool"), ("playpen", "container"),
     ("marionette", "figure"), ("bass drum", "barrel"), ("gourd", "generic")],
)
def test_a_read_noun_reaches_the_shape_that_draws_it(noun, shape):
    """From the text: what the reader files a noun as (a catalogue category or a family)
    picks the shape, and the shape's variant for that name (the tests above) draws it."""
    obj = parse_scene(f"There is a {noun} by the old wall.").objects[0]
    assert choose_shape(obj.name, obj.category) == shape, (obj.name, obj.category)


def test_a_hand_tool_lies_along_its_long_side():
    """A hammer filed 0.1 m wide and 0.35 m long is drawn along its length, head in front;
    standing, a rake has its head at the bottom."""
    hammer = scene_frame(build_model("tool", (0.1, 0.35, 0.08), "realistic", 1, name="hammer"))
    assert np.ptp(hammer["wood"].vertices[:, 1]) > 3 * np.ptp(hammer["wood"].vertices[:, 0])
    assert hammer["metal"].vertices[:, 1].max() < hammer["rubber"].vertices[:, 1].min()
    rake = scene_frame(build_model("tool", (0.4, 0.1, 1.5), "realistic", 1, name="rake"))
    assert rake["metal"].vertices[:, 2].max() < 0.2 * 1.5


def test_seats_of_a_grandstand_rise_to_the_back():
    stand = scene_frame(build_model("structure", (12, 6, 4), "realistic", 1, name="bleachers"))
    seats = np.concatenate([stand[role].vertices for role in ("paint", "accent")])
    front, back = seats[seats[:, 1] < 0], seats[seats[:, 1] > 1]
    assert back[:, 2].max() > front[:, 2].max() + 0.5


def test_a_stairway_s_steps_rise_to_the_back_and_a_spiral_one_winds_round_its_post():
    flight = points("structure", (1.4, 3.2, 2.8), "stone stairway", roles=("stone",))
    front, back = flight[flight[:, 1] < -0.8], flight[flight[:, 1] > 0.8]
    assert back[:, 2].max() > front[:, 2].max() + 1.0
    spiral = points("structure", (2.0, 2.0, 3.2), "spiral staircase", roles=("stone",))
    quarters = {(bool(x > 0), bool(y > 0)) for x, y, _ in spiral[spiral[:, 2] > 0.5]}
    assert len(quarters) == 4  # steps all round, not a straight flight


def test_a_thin_panel_is_a_sheet_without_feet_standing_or_lying():
    """A calendar on a wall or a map on a table: its printed face starts near the edge it rests
    on (feet would hold it off the wall or the table); a free-standing board stands on feet."""
    upright = points("panel", (0.4, 0.02, 0.5), "calendar", roles={"paper"})
    assert upright[:, 2].min() < 0.1 * 0.5 and np.ptp(upright[:, 1]) < 0.05
    lying = points("panel", (0.6, 0.45, 0.01), "map")
    assert np.ptp(lying[:, 2]) < 0.03 and np.ptp(lying[:, 1]) > 0.9 * 0.45
    notice = points("panel", (1.2, 0.3, 1.6), "notice board", roles={"fur_light"})
    assert notice[:, 2].min() > 0.3 * 1.6, "a free-standing board keeps its feet"


def test_a_rocking_horse_stands_on_runners_and_toys_are_drawn_as_what_they_show():
    runners = points("animal", (0.4, 1.0, 0.8), "rocking horse", roles={"dark_wood"})
    assert np.ptp(runners[:, 1]) > 0.7 and runners[:, 2].min() < 0.02, "runners along its length, on the floor"
    hooves = points("animal", (0.4, 1.0, 0.8), "rocking horse", roles={"dark_plastic"})
    assert hooves[:, 2].min() > 0.02, "the hooves stand on the runners"
    teddy = scene_frame(build_model("tool", (0.3, 0.25, 0.35), "realistic", 1, name="teddy bear"))
    toolbox = scene_frame(build_model("tool", (0.3, 0.25, 0.35), "realistic", 1, name="toolbox"))
    assert set(teddy) != set(toolbox)


def test_a_stagecoach_is_a_closed_coach_on_four_wheels_not_a_car():
    coach = scene_frame(build_model("vehicle", (1.7, 3.2, 2.2), "realistic", 1, name="stagecoach"))
    car = scene_frame(build_model("vehicle", (1.7, 3.2, 2.2), "realistic", 1, name="sedan"))
    assert "glass" in coach and "dark_wood" in coach and set(coach) != set(car)


def test_a_dollhouse_is_drawn_as_a_little_house_not_a_box():
    dollhouse = scene_frame(build_model("container", (0.8, 0.4, 0.8), "realistic", 1, name="dollhouse"))
    box = scene_frame(build_model("container", (0.8, 0.4, 0.8), "realistic", 1, name="box"))
    assert set(dollhouse) != set(box) and len(dollhouse) > len(box)


def test_a_crayon_is_a_stick_with_a_tip_lying_along_its_length():
    crayon = points("tool", (0.012, 0.09, 0.012), "crayon")
    assert np.ptp(crayon[:, 1]) > 5 * np.ptp(crayon[:, 2])
