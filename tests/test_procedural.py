"""Procedural meshes: every shape fills its box as valid PBR glTF, styles and words show."""

from __future__ import annotations

import io
import json
import logging
import shutil
import struct
import subprocess
from pathlib import Path

import numpy as np
import pytest
import trimesh
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from scenewright.backends import MeshRequest, create_backend
from scenewright.core.catalogue import load_catalogue
from scenewright.core.styles import find_look
from scenewright.errors import InputError
from scenewright.geometry import GLTF_TO_SCENE
from scenewright.procedural import SHAPES
from scenewright.procedural.builder import Model
from scenewright.core.colours import COLOURS, MATERIAL_COLOURS
from scenewright.procedural.material import described_surfaces, find_colour, find_material
from scenewright.backends.procedural_meshes import ProceduralMeshes
from scenewright.procedural.meshes import build_glb, build_model, choose_shape, keyword_shape
from scenewright.core.catalogue import POST, POSTED
from scenewright.procedural.style import ROLES, resolve_style
from scenewright.procedural.textures import ground_texture
from scenewright.scene import STYLES, Vec3
from scenewright.settings import Settings

VOCABULARY = """table round_table coffee_table desk chair armchair office_chair stool sofa bench bed
bookshelf cabinet fireplace wardrobe nightstand counter table_lamp floor_lamp pendant_lamp rug tv monitor laptop
potted_plant vase bathtub toilet sink stove fridge piano clock mirror picture_frame trash_can crate barrel
books bottle cup bowl garland tree pine_tree palm_tree bush flower_bed rock fountain statue lamp_post sign fence
arch bollard hydrant car truck bus bicycle boat building house kiosk market_stall tent umbrella swing slide
treadmill whiteboard robot crystal tower well cart pillar generic
animal bird figure machine tank structure panel container tool vehicle""".split()

#: The shape families unknown nouns get, with names that pick their variants.
FAMILIES = {
    "animal": ["camel", "elephant", "giraffe", "pig", "sheep", "goat", "horse", "dog", "fox", "dragon", "dinosaur", "t-rex"],
    "bird": ["sparrow", "penguin", "owl", "flamingo"],
    "figure": ["person", "street musician", "violinist", "knight", "wizard", "astronaut", "scarecrow", "mannequin", "alien"],
    "machine": ["machine", "arcade cabinet", "generator", "compressor", "terminal", "printer", "kiln", "periscope", "crane game",
                "sewing machine"],
    "tank": ["fuel tank", "silo", "water tower", "boiler", "cauldron", "aquarium"],
    "structure": ["ferris wheel", "windmill", "crane", "carousel", "stage", "scaffold", "bleachers", "catapult", "quarter pipe"],
    "panel": ["notice board", "banner", "screen", "solar panel"],
    "container": ["box", "chest", "trunk", "sack", "basket", "rucksack", "travel case", "ice chest", "bird cage", "playpen",
                  "crab pot", "reel", "hat box"],
    "tool": ["anvil", "hammer", "toolbox", "gadget", "mattock", "pitchfork", "golf club", "sabre", "magnifier", "eyeglass",
             "manuscript", "parchment", "spyglass", "traffic cone", "award", "record player", "weather vane", "longboard",
             "spare tire", "microscope", "skull", "till", "impact wrench", "compass", "secateurs", "measuring tape"],
    "vehicle": ["tractor", "forklift", "cart", "golf cart", "drone", "spaceship", "army tank", "zeppelin", "gyrocopter", "u-boat",
                "ore cart", "stroller"],
    "statue": ["dragon statue", "lion statue", "horse statue", "statue"],
}

#: Typical sizes (x width, y depth, z height) so each shape is tested at a plausible box.
SIZES = {
    "car": (1.8, 4.5, 1.5), "truck": (2.5, 7.0, 3.2), "bus": (2.5, 11.0, 3.2), "bicycle": (0.6, 1.7, 1.0),
    "boat": (2.0, 5.0, 1.5), "building": (12.0, 10.0, 20.0), "house": (8.0, 7.0, 6.0), "tree": (3.0, 3.0, 5.0),
    "pine_tree": (2.0, 2.0, 5.0), "palm_tree": (3.0, 3.0, 6.0), "fence": (4.0, 0.1, 1.1), "rug": (2.0, 1.4, 0.02),
    "tower": (4.0, 4.0, 12.0), "lamp_post": (0.6, 0.6, 4.0), "sofa": (2.1, 0.9, 0.85), "bed": (1.6, 2.1, 1.0),
    "clock": (0.4, 0.08, 0.4), "picture_frame": (0.8, 0.04, 0.6), "bottle": (0.08, 0.08, 0.3), "cup": (0.12, 0.09, 0.1),
}


def glb_json(glb: bytes) -> dict:
    length = struct.unpack("<I", glb[12:16])[0]
    return json.loads(glb[20 : 20 + length])


def load(glb: bytes) -> trimesh.Scene:
    return trimesh.load(io.BytesIO(glb), file_type="glb")


def scene_frame(scene: trimesh.Scene) -> dict[str, trimesh.Trimesh]:
    """Each role's geometry in the scene frame (+Z up, front −Y)."""
    return {name: g.copy().apply_transform(GLTF_TO_SCENE) for name, g in scene.geometry.items()}


def assert_fills(glb: bytes, size) -> None:
    lo, hi = load(glb).bounds
    expected = np.array([size[0], size[2], size[1]])
    np.testing.assert_allclose(hi - lo, expected, rtol=0.02)
    assert abs(lo[1]) < 1e-6
    np.testing.assert_allclose([(lo[0] + hi[0]) / 2, (lo[2] + hi[2]) / 2], 0, atol=1e-6 + 0.01 * max(size))


def test_vocabulary_is_covered():
    assert set(SHAPES) == set(VOCABULARY)
    assert len(SHAPES) - 1 >= 70


def test_the_fit_fills_the_box_whatever_the_generator_drew():
    """Filling the box is the fit's work (Model.finish), not each generator's: a drawing three
    times too big and off centre still comes out at the object's size, centred, on the ground."""
    size = (1.2, 0.5, 0.8)
    model = Model(size, resolve_style("realistic"), np.random.default_rng(0))
    model.box("body", (1.0, 2.0, 0.5), (4.6, 3.5, 2.9), rounded=0.0)
    glb = model.finish().export(file_type="glb")
    assert_fills(glb, size)


@pytest.mark.parametrize("shape", VOCABULARY)
def test_every_shape_is_valid_pbr_gltf(shape):
    size = SIZES.get(shape, (0.8, 0.6, 0.9))
    glb = build_glb(shape, size, "realistic", seed=7)
    tree = glb_json(glb)
    assert tree["materials"] and all("pbrMetallicRoughness" in m for m in tree["materials"])
    assert all("NORMAL" in p["attributes"] for mesh in tree["meshes"] for p in mesh["primitives"])
    faces = sum(len(g.faces) for g in load(glb).geometry.values())
    assert 12 <= faces <= 6000


@settings(max_examples=25, deadline=None)
@given(
    shape=st.sampled_from(VOCABULARY),
    size=st.tuples(*[st.floats(0.05, 40.0)] * 3),
    style=st.sampled_from(STYLES),
    seed=st.integers(0, 2**32),
    name=st.sampled_from(["", "dog", "lighthouse", "campfire", "torii gate", "sailboat", "treasure chest", "snowman", "camel",
                          "dragon statue", "street musician", "fuel tank", "ferris wheel", "anvil", "tractor", "knight",
                          "arcade cabinet", "round mirror"]),
)
def test_any_size_style_and_variant_fills_the_box_on_a_face_budget(shape, size, style, seed, name):
    glb = build_glb(shape, size, style, seed, name=name)
    assert_fills(glb, size)
    assert sum(len(g.faces) for g in load(glb).geometry.values()) <= 12000


def base_colours(scene: trimesh.Scene) -> dict[str, np.ndarray]:
    return {n: np.asarray(g.visual.material.baseColorFactor[:3], float) / 255 for n, g in scene.geometry.items()}


def test_styles_change_materials_visibly():
    looks = {}
    for style in STYLES:
        scene = build_model("sofa", (2.0, 0.9, 0.85), style, seed=1)
        looks[style] = tuple(np.round(base_colours(scene)["fabric"], 2))
    assert len(set(looks.values())) == len(STYLES)


def emissive(scene: trimesh.Scene) -> bool:
    return any(np.any(np.asarray(g.visual.material.emissiveFactor) > 0.1) for g in scene.geometry.values())


def test_cyberpunk_glows_and_realistic_does_not():
    assert emissive(build_model("sofa", (2.0, 0.9, 0.85), "cyberpunk", seed=1))
    assert not emissive(build_model("sofa", (2.0, 0.9, 0.85), "realistic", seed=1))


def test_low_poly_is_flat_shaded_with_few_segments():
    flat = build_model("barrel", (0.6, 0.6, 0.9), "low-poly", seed=1).geometry["wood"]
    smooth = build_model("barrel", (0.6, 0.6, 0.9), "realistic", seed=1).geometry["wood"]
    assert len(flat.vertices) == 3 * len(flat.faces)
    assert len(flat.faces) < len(smooth.faces) / 2


def test_steampunk_metal_is_brass_and_cartoon_is_rounder():
    steam = build_model("floor_lamp", (0.4, 0.4, 1.6), "steampunk", seed=1).geometry["metal"].visual.material
    r, g, b = np.asarray(steam.baseColorFactor[:3], float)
    assert r > g > b and steam.metallicFactor == 1.0
    cartoon = build_model("crate", (0.6, 0.6, 0.6), "cartoon", seed=1).geometry["wood"]
    realistic = build_model("crate", (0.6, 0.6, 0.6), "realistic", seed=1).geometry["wood"]
    assert cartoon.volume < 0.97 * realistic.volume  # bigger bevels shave the corners


def test_a_named_look_draws_its_base_geometry_in_its_own_palette():
    noir = build_model("armchair", (0.9, 0.9, 1.0), "film noir", seed=1)
    realistic = build_model("armchair", (0.9, 0.9, 1.0), "realistic", seed=1)
    assert sorted(noir.geometry) == sorted(realistic.geometry)
    for role, mesh in noir.geometry.items():
        assert np.allclose(mesh.vertices, realistic.geometry[role].vertices)
        r, g, b = np.asarray(mesh.visual.material.baseColorFactor[:3], float)
        assert abs(r - g) < 1e-6 and abs(g - b) < 1e-6, role  # black and white
    assert resolve_style("Ukiyo-e").family == "anime" and resolve_style("film-noir style").name == "film noir"
    assert resolve_style("voxel").flat and resolve_style("synthwave").neon


def test_a_named_look_shifts_the_ground_texture_too():
    grey = ground_texture("grass", "film noir", seed=3).astype(int)
    assert np.abs(grey[..., 0] - grey[..., 1]).max() <= 1 and np.abs(grey[..., 1] - grey[..., 2]).max() <= 1
    colour = ground_texture("grass", "realistic", seed=3).astype(int)
    assert np.abs(colour[..., 1] - colour[..., 0]).mean() > 5


def test_a_print_look_draws_every_role_in_its_few_inks():
    poster = resolve_style("a Bauhaus poster")  # a style name: its look word names the look
    assert poster.name == "poster" and poster.inks
    colours = {role: poster.surface(role).color for role in ROLES}
    assert all(c in poster.inks for c in colours.values())
    assert colours["skin"] != colours["clothes"] and colours["wall"] == max(poster.inks, key=sum)  # paper, not skin
    tile = ground_texture("grass", "comic", seed=3).astype(float) + 1
    ratios = tile / tile.sum(axis=2, keepdims=True)
    assert np.ptp(ratios.reshape(-1, 3), axis=0).max() < 0.02  # one flat ink, only its lightness varies


def test_a_one_ink_look_draws_every_colour_between_its_ink_and_its_paper():
    engraving = resolve_style("copperplate engraving")
    dark, light = (np.array(c) for c in engraving.duotone)
    for role in ("wood", "fabric", "leaf", "brick", "paint"):
        colour = np.array(engraving.surface(role).color)
        t = (colour - dark) / (light - dark)
        assert np.allclose(t, t[0], atol=1e-6) and 0 <= t[0] <= 1, role
    assert sum(engraving.surface("dark_wood").color) < sum(engraving.surface("paper").color)
    tile = ground_texture("wood_floor", "blueprint", seed=2).astype(int)
    assert (tile[..., 2] > tile[..., 0]).all()  # blue, down to the ground
    # paper is lit flat and bright, not under a blue sky; a look that says nothing lights as its base
    assert (find_look("engraving").lit, find_look("voxel").lit, find_look("film noir").lit) == ("cartoon", "low-poly", "realistic")


def test_a_look_named_in_colours_draws_in_them():
    two = resolve_style("textile in teal and saffron")  # flat inks, with a shade and a tint of them
    assert two.name == "textile" and two.duotone is None and len(two.inks) == 4
    assert {COLOURS["teal"], COLOURS["saffron"]} < set(two.inks) and min(map(sum, two.inks)) < sum(COLOURS["teal"])
    porcelain = resolve_style("ceramic in navy and teal")  # a look in one ink: its dark and its light
    assert porcelain.duotone == (COLOURS["navy"], COLOURS["teal"]) and porcelain.inks is None
    noir = resolve_style("textile in black and white")  # a colour with no hue: a tonal range, not two inks
    assert noir.duotone == (COLOURS["black"], COLOURS["white"]) and noir.inks is None
    wood = resolve_style("marquetry in cherry and birch")  # a look of flat inks snaps to the named ones
    assert set(wood.inks) == {MATERIAL_COLOURS["cherry"], MATERIAL_COLOURS["birch"]}
    assert {wood.surface(role).color for role in ("wood", "fabric", "leaf", "paint")} <= set(wood.inks)
    one = resolve_style("sketch in crimson")  # one colour: its own shade and tint
    dark, light = one.duotone
    assert dark[0] > dark[1] and light[0] > light[1] and sum(dark) < sum(light)
    many = resolve_style("poster in red and yellow and teal")
    assert many.inks == (COLOURS["red"], COLOURS["yellow"], COLOURS["teal"]) and many.duotone is None
    assert resolve_style("ceramic").duotone == tuple(tuple(c) for c in find_look("ceramic").palette["duotone"])


def test_unknown_style_falls_back_to_realistic_with_a_note(caplog):
    resolve_style.cache_clear()
    with caplog.at_level(logging.WARNING):
        assert resolve_style("baroque-glitch").name == "realistic"
    assert "baroque-glitch" in caplog.text
    assert resolve_style("Low Poly").name == "low-poly"
    assert resolve_style("cartoon-style").name == "cartoon"


@pytest.mark.parametrize(
    ("description", "check"),
    [
        ("a red sofa", lambda c: c[0] > 0.5 and c[0] > 2 * c[1] and c[0] > 2 * c[2]),
        ("dark blue velvet upholstery", lambda c: c[2] > c[0] and c[2] > c[1] and max(c) < 0.5),
        ("a pastel pink couch", lambda c: c[0] > c[1] and min(c) > 0.5),
        ("a green sofa", lambda c: c[1] > c[0] and c[1] > c[2]),
    ],
)
def test_colour_words_recolour_the_main_part(description, check):
    colour = base_colours(build_model("sofa", (2.0, 0.9, 0.85), "realistic", seed=1, description=description))["fabric"]
    assert check(colour), colour


def test_colour_before_a_part_noun_goes_to_that_part():
    lamp = base_colours(build_model("table_lamp", (0.35, 0.35, 0.6), "realistic", 1, "a white lamp with a green shade"))
    assert lamp["shade"][1] > lamp["shade"][0] and min(lamp["ceramic"]) > 0.8
    # a house's door takes its own colour, and whitewash is white, not the walls' default render
    cottage = base_colours(build_model("house", (6.0, 5.0, 5.0), "realistic", 1, "a whitewashed cottage with a blue door"))
    assert cottage["dark_wood"][2] > 2 * cottage["dark_wood"][0] and min(cottage["wall"]) > 0.7


def test_vehicles_come_in_many_colours_unless_their_trade_or_the_text_fixes_one():
    """A car park of undescribed cars is not one red: each vehicle's paint is picked by its seed;
    a fire engine stays red, a taxi yellow, and a colour the text names wins."""
    def paint(name: str, seed: int, description: str = "", style: str = "realistic"):
        return tuple(base_colours(build_model("car", (1.9, 4.5, 1.5), style, seed, description, name=name))["paint"])

    assert len({paint("hatchback", seed) for seed in range(12)}) >= 4
    assert paint("hatchback", 3) == paint("hatchback", 3)
    fire = paint("fire engine", 5)
    assert fire[0] > 0.5 and fire[0] > 3 * fire[1]
    taxi = paint("taxi", 5)
    assert taxi[0] > 0.6 and taxi[1] > 0.6 and taxi[2] < 0.4
    green = paint("hatchback", 5, "a green hatchback")
    assert green[1] > green[0] and green[1] > green[2]
    assert len({paint("hatchback", seed, style="steampunk") for seed in range(6)}) == 1  # the style's own paint


def test_material_words_set_the_surface():
    chrome = build_model("table", (1.2, 0.8, 0.75), "realistic", 1, "a polished chrome table").geometry["wood"]
    assert chrome.visual.material.metallicFactor == 1.0 and chrome.visual.material.roughnessFactor < 0.1
    glass = build_model("table", (1.2, 0.8, 0.75), "realistic", 1, "a glass table").geometry["wood"]
    assert glass.visual.material.alphaMode == "BLEND"
    walnut = base_colours(build_model("table", (1.2, 0.8, 0.75), "realistic", 1, "walnut"))["wood"]
    oak = base_colours(build_model("table", (1.2, 0.8, 0.75), "realistic", 1, "oak"))["wood"]
    assert walnut.sum() < oak.sum()


def test_material_parsing():
    assert find_colour("A Dark Blue chair") == pytest.approx(tuple(0.45 * c for c in (0.12, 0.3, 0.75)))
    assert find_colour("sky blue walls")[2] > 0.9
    assert find_colour("a wooden chair") is None
    assert find_material("a wooden chair").color == find_material("wood").color
    roles = ("wood", "cushion", "fabric")
    assert described_surfaces("a plain chair", "wood", roles, ROLES.get) == {}
    assert described_surfaces("red leather", "fabric", roles, ROLES.get)["fabric"].roughness == find_material("leather").roughness
    split = described_surfaces("a walnut chair with a red cushion", "wood", roles, ROLES.get)
    assert split["wood"].color == find_material("walnut").color and split["cushion"].color == find_colour("red")
    assert described_surfaces("a large oak tree", "leaf", ("leaf", "bark"), ROLES.get) == {}
    assert described_surfaces("a red maple tree", "leaf", ("leaf", "bark"), ROLES.get)["leaf"].color == find_colour("red")
    # a part the object lacks leaves the colour to the main part
    assert described_surfaces("a chair with a red shade", "wood", roles, ROLES.get)["wood"].color == find_colour("red")


@pytest.mark.parametrize("style", ["realistic", "cyberpunk"])
def test_a_glowing_colour_is_light_in_the_glb(style):
    def emissive(name: str) -> list[list[float]]:
        tree = glb_json(build_glb("fridge", (0.9, 0.8, 1.8), style, 3, name=name))
        return [m.get("emissiveFactor", [0, 0, 0]) for m in tree["materials"]]

    pink = [e for e in emissive("a glowing pink vending machine") if e[0] > 0.5 and e[1] < e[0] and e[2] > e[1]]
    assert pink, "the body glows pink"
    assert not any(e[0] > 0.5 and e[1] < e[0] and e[2] > e[1] for e in emissive("a pink vending machine"))
    neon = described_surfaces("a neon green sign", "paint", ("paint",), ROLES.get)["paint"]
    assert neon.emissive == neon.color == find_colour("green")


def test_generation_is_deterministic_and_varies_by_seed():
    assert build_glb("tree", (3, 3, 5), "realistic", 5) == build_glb("tree", (3, 3, 5), "realistic", 5)
    assert build_glb("tree", (3, 3, 5), "realistic", 5) != build_glb("tree", (3, 3, 5), "realistic", 6)


def occupied(meshes, lo, hi) -> bool:
    """Whether any of the meshes' surface lies inside the box [lo, hi] (scene frame), by sampling."""
    points = np.concatenate([trimesh.sample.sample_surface(m, 5000, seed=0)[0] for m in meshes])
    return bool(np.any(np.all((points >= lo) & (points <= hi), axis=1)))


def test_silhouettes_read_as_their_objects():
    chair = list(scene_frame(build_model("chair", (0.5, 0.5, 0.9), "realistic", 1)).values())
    assert occupied(chair, (-0.25, 0.1, 0.7), (0.25, 0.25, 0.9)), "a chair has a back above the seat, behind"
    assert not occupied(chair, (-0.2, -0.25, 0.6), (0.2, 0.0, 0.9)), "and nothing above the front of its seat"
    table = list(scene_frame(build_model("table", (1.6, 0.9, 0.75), "realistic", 1)).values())
    assert occupied(table, (0.6, 0.3, 0.3), (0.8, 0.45, 0.4)), "a table has legs at its corners"
    assert not occupied(table, (-0.5, -0.2, 0.05), (0.5, 0.2, 0.5)), "and open space under its top"
    car = scene_frame(build_model("car", (1.8, 4.5, 1.5), "realistic", 1))
    wheels = car["rubber"].vertices
    assert wheels[:, 2].max() < 0.5 * 1.5 and np.ptp(wheels[:, 1]) > 2.5 and np.ptp(wheels[:, 0]) > 1.6
    assert car["glass"].vertices[:, 2].min() > 0.6
    tree = scene_frame(build_model("tree", (3, 3, 5), "realistic", 1))
    assert tree["leaf"].vertices[:, 2].mean() > tree["bark"].vertices[:, 2].mean() + 1.5
    bed = scene_frame(build_model("bed", (1.6, 2.1, 1.0), "realistic", 1))
    tall = bed["wood"].vertices[bed["wood"].vertices[:, 2] > 0.9]
    assert tall[:, 1].min() > 0.9, "the headboard is at the back"
    lamp = build_model("table_lamp", (0.35, 0.35, 0.6), "realistic", 1)
    assert emissive(lamp)


@pytest.mark.parametrize(
    ("name", "category", "shape"),
    [
        ("oak dining table", None, "table"), ("table lamp", None, "table_lamp"), ("street lamp", None, "lamp_post"),
        ("two red couches", None, "sofa"), ("coffee table", None, "coffee_table"), ("thingamajig", None, "generic"),
        ("my seat", "office_chair", "office_chair"), ("fir", None, "pine_tree"), ("bookshelves", None, "bookshelf"),
    ],
)
def test_shape_choice(name, category, shape):
    assert choose_shape(name, category) == shape


def test_keyword_shape_prefers_the_head_noun():
    assert keyword_shape("lamp on a table") == "table"
    assert keyword_shape("wooden crate") == "crate"
    assert keyword_shape("zzz") is None


def test_backend_generates_every_request():
    backend = create_backend("meshes", "procedural", Settings())
    assert isinstance(backend, ProceduralMeshes) and backend.name == "procedural"
    requests = [
        MeshRequest(id="sofa_1", name="sofa", category="sofa", description="a blue sofa", style="anime", size=Vec3(x=2, y=0.9, z=0.8)),
        MeshRequest(id="thing_1", name="thing", category=None, description="", style="weird", size=Vec3(x=1, y=1, z=1)),
    ]
    seen: list[str] = []
    result = backend.generate(requests, progress=seen.append)
    assert set(result) == {"sofa_1", "thing_1"} and len(seen) == 2
    assert_fills(result["sofa_1"], (2, 0.9, 0.8))
    with pytest.raises(InputError, match="no argument"):
        ProceduralMeshes.from_spec("x", Settings())
    assert len(backend.params["code"]) == 16, "the asset cache key follows the generators' code"


VALIDATOR = Path(__file__).resolve().parents[1] / "tools" / "validate-gltf.mjs"


@pytest.mark.node
@pytest.mark.skipif(
    shutil.which("node") is None or not (VALIDATOR.parent / "node_modules" / "gltf-validator").exists(),
    reason="needs `make tools` (the Khronos glTF validator)",
)
@pytest.mark.parametrize(
    ("shape", "style"),
    [("rock", "realistic"), ("crystal", "cartoon"), ("sofa", "low-poly"), ("car", "cyberpunk"),
     ("palm_tree", "steampunk"), ("fountain", "anime"), ("bottle", "realistic"), ("animal", "low-poly"),
     ("figure", "realistic"), ("structure", "cartoon"), ("tank", "cyberpunk"), ("statue", "steampunk"),
     ("vehicle", "anime"), ("bird", "realistic"), ("machine", "realistic"), ("panel", "low-poly"),
     ("container", "cartoon"), ("tool", "realistic")],
)
def test_khronos_validator_finds_no_errors(tmp_path, shape, style):
    path = tmp_path / f"{shape}.glb"
    names = {"animal": "dragon", "figure": "street musician", "structure": "ferris wheel", "tank": "fuel tank",
             "statue": "lion statue", "vehicle": "tractor", "machine": "arcade cabinet", "panel": "solar panel",
             "container": "trunk", "tool": "anvil", "bird": "flamingo"}
    path.write_bytes(build_glb(shape, SIZES.get(shape, (0.8, 0.6, 0.9)), style, seed=2, name=names.get(shape, "")))
    run = subprocess.run(["node", str(VALIDATOR), str(path)], capture_output=True, text=True, timeout=60)
    report = json.loads(run.stdout)
    assert report["issues"]["numErrors"] == 0, report["issues"]["messages"][:5]


#: (shape, name, a role only that name's variant has): names that pick a variant of a shape
#: that is no family (the families' variants are in :data:`FAMILIES`).
VARIANTS = [
    ("generic", "dog", "fur"), ("generic", "spaceship", "glass"), ("tower", "lighthouse", "light"),
    ("rock", "campfire", "flame"), ("barrel", "log", "bark"), ("crate", "treasure chest", "gold"),
    ("lamp_post", "traffic light", "flower_alt"), ("statue", "snowman", "ceramic"),
    ("crate", "hay bale", "straw"), ("crate", "shipping container", "paint"), ("truck", "forklift tractor", "yellow_paint"),
    ("rug", "pond", "water"), ("rug", "swimming pool", "water"), ("vehicle", "hot air balloon vehicle", "flower_alt"),
    ("rock", "anthill", "soil"), ("rock", "outcrop", "leaf"), ("rock", "large dune", "sand"), ("rock", "grassy hill", "leaf"), ("kiosk", "puppet theatre", "canvas_alt"),
    ("bowl", "crab pot", "brick"), ("cart", "ore cart", "metal"), ("generic", "gourd", "leaf"), ("generic", "beach ball", "paint"),
    ("barrel", "bass drum", "hide"), ("generic", "ramp", "wood"), ("fence", "stepladder", "dark_wood"),
    ("fridge", "water dispenser", "glass"), ("fridge", "petrol pump", "screen"), ("bowl", "skillet", "dark_wood"), ("bowl", "tea pot", "accent"),
    ("generic", "goalpost", "canvas_alt"), ("generic", "smokestack", "brick"), ("floor_lamp", "hat stand", "brass"),
    ("trash_can", "pillar box", "paper"), ("counter", "vitrine", "glass"), ("generic", "rail", "dark_metal"),
    ("generic", "orrery", "gold"),
    ("bookshelf", "weapon rack", "metal"), ("bookshelf", "shoe rack", "wood"), ("bookshelf", "wine rack", "lacquer"),
    ("bookshelf", "dumbbell rack", "rubber"), ("generic", "balloon", "paper"), ("tool", "grindstone", "stone"),
    ("machine", "jukebox", "light"), ("machine", "hair dryer", "chrome"), ("armchair", "throne", "gold"),
    ("panel", "windsock", "canvas_alt"), ("structure", "windsock", "canvas_alt"), ("tower", "satellite dish", "plastic"),
    ("structure", "radar dish", "plastic"), ("tool", "bicycle wheel", "metal"),
    ("tool", "shoe last", "wood"), ("tool", "potter's wheel", "plastic"),
    ("vehicle", "diesel train", "screen"), ("vehicle", "electric train", "canvas_alt"), ("vehicle", "longship", "wood"),
    ("vehicle", "narrowboat", "canvas_alt"), ("bus", "tram", "canvas_alt"), ("structure", "stone platform", "yellow_paint"),
    ("structure", "wooden platform", "dark_wood"), ("vehicle", "snowmobile", "leather"), ("vehicle", "snowcat", "screen"),
    ("boat", "rowing boat", "dark_wood"), ("boat", "viking longship", "canvas"), ("vehicle", "jet plane", "plastic"),
    ("vehicle", "twin-propeller airplane", "plastic"), ("vehicle", "flying saucer", "dark_metal"),
    ("bookshelf", "shelf bookshelf", "ceramic"), ("cart", "luggage cart", "rubber"), ("vehicle", "baggage trolley", "rubber"),
    ("panel", "cricket scoreboard", "lacquer"), ("panel", "painted backdrop", "leaf"), ("panel", "folding screen", "paper"),
    ("tent", "forecourt canopy", "light"),
    ("cart", "wooden sledge", "dark_wood"), ("cart", "sleigh", "fabric"), ("cart", "wheelbarrow", "rubber"),
    ("machine", "weighing scales", "brass"), ("vehicle", "touring caravan", "canvas_alt"),
    ("generic", "dragon egg", "scales"), ("container", "nest", "straw"),
    ("boat", "papyrus boat", "straw"), ("boat", "bamboo raft boat", "straw"), ("panel", "board platform", "dark_wood"),
    ("generic", "signal fire thing", "flame"), ("house", "log cabin", "wood"), ("house", "fishing hut", "wood"),
    ("fireplace", "wood stove fireplace", "glass"), ("stove", "pot-bellied stove", "flame"), ("crystal", "planet hologram", "light"),
    ("house", "red barn", "canvas_alt"), ("structure", "mast", "canvas_alt"), ("truck", "ice cream van", "flower"),
    ("crystal", "dragon hologram", "light"), ("container", "water trough", "water"), ("container", "feeding trough", "straw"),
    ("container", "cat carrier", "metal"),
]


def test_a_thing_headed_by_fire_burns_and_one_fire_is_only_for_does_not():
    """"a signal fire" is a fire; "a fire blanket" or "fire sand bucket" is for fires."""
    assert "flame" in build_model("generic", (0.6, 0.6, 0.6), "realistic", 1, name="beacon fires thing").geometry
    for name in ("fire blanket thing", "fire sand bucket thing"):
        assert "flame" not in build_model("generic", (0.6, 0.6, 0.6), "realistic", 1, name=name).geometry


@pytest.mark.parametrize(("shape", "name", "role"), VARIANTS)
def test_names_pick_variants_within_a_shape(shape, name, role):
    variant = build_model(shape, (1.0, 1.0, 1.5), "realistic", 1, name=name)
    plain = build_model(shape, (1.0, 1.0, 1.5), "realistic", 1, name=shape)
    assert role in variant.geometry and set(variant.geometry) != set(plain.geometry)


def test_the_object_s_own_word_picks_the_variant_before_its_category_s():
    """The builder's name is the object's name then its category's: a forklift filed under
    tractors is drawn as a forklift, a plain tractor as a tractor."""
    forklift = build_model("truck", (2.0, 3.5, 2.5), "realistic", 1, name="forklift tractor")
    tractor = build_model("truck", (2.0, 3.5, 2.5), "realistic", 1, name="tractor")
    assert "yellow_paint" in forklift.geometry and "yellow_paint" not in tractor.geometry


def _vehicle(name: str, size=(3.0, 14.0, 4.0)) -> Model:
    model = Model(size, resolve_style("realistic"), np.random.default_rng(0), name=f"{name} vehicle")
    SHAPES["vehicle"](model)
    return model


def test_a_train_s_traction_words_pick_steam_or_a_unit_of_as_many_carriages_as_said():
    """Steam (or an old or toy train) is the locomotive with its boiler's brass dome; diesel,
    electric or a plain train is a unit of carriages, one stripe a side each, with a pantograph
    only when electric."""
    for steam in ("steam train", "old locomotive", "toy train", "locomotive"):
        assert "brass" in _vehicle(steam).parts and "screen" not in _vehicle(steam).parts, steam
    for name, carriages in (("two-carriage diesel train", 2), ("three car electric train", 3), ("train", 2), ("railcar", 1)):
        model = _vehicle(name)
        assert "brass" not in model.parts and len(model.parts["canvas_alt"]) == 2 * carriages, name
    top = {name: max(p.vertices[:, 2].max() for p in _vehicle(name).parts["dark_metal"]) for name in ("diesel train", "electric train")}
    assert top["electric train"] > top["diesel train"]  # the pantograph stands over the exhaust stacks


def test_a_wall_thing_on_a_post_has_its_face_up_top_and_fills_its_box():
    """A clock the composition stood on a post outdoors: the post from the ground, the dial above it."""
    size = (0.35, 0.12, 0.35 + POST)
    glb = build_glb("clock", size, "realistic", 1, description=f"station clock {POSTED}", name="clock wall clock")
    assert_fills(glb, size)
    parts = scene_frame(load(glb))
    assert parts["ceramic"].bounds[0][2] > POST - 0.01 and parts["dark_metal"].bounds[0][2] < 0.01


def test_a_balloon_is_widest_high_up_over_a_small_basket():
    """Not a car: the envelope's widest ring is in its upper half, the basket under it small."""
    model = Model((6.0, 6.0, 9.0), resolve_style("realistic"), np.random.default_rng(0), name="hot air balloon vehicle")
    SHAPES["vehicle"](model)
    envelope = model.parts["paint"][0].vertices
    widest = envelope[np.argmax(np.linalg.norm(envelope[:, :2], axis=1)), 2]
    assert widest > 0.5 * 9.0 and "glass" not in model.parts and "rubber" not in model.parts
    basket = model.parts["wood"][0].vertices
    assert np.ptp(basket[:, 0]) < 0.3 * 6.0 and abs(basket[:, 2].min()) < 1e-9


def test_tiger_stripes_are_hoops_round_its_body():
    """Each stripe crosses the back from side to side (wider across than along the body),
    on an orange coat."""
    model = Model((0.8, 2.0, 1.0), resolve_style("realistic"), np.random.default_rng(0), name="tiger")
    SHAPES["animal"](model)
    assert model.main == "fur_orange" and len(model.parts["fur_dark"]) >= 7
    for stripe in model.parts["fur_dark"]:
        extent = np.ptp(stripe.vertices, axis=0)
        assert extent[0] > 3 * extent[1]


def test_a_picnic_table_has_a_bench_along_each_side():
    model = Model((1.8, 1.5, 0.75), resolve_style("realistic"), np.random.default_rng(0), name="picnic table")
    SHAPES["table"](model)
    seats = [p for p in model.parts["wood"] if abs(p.vertices[:, 2].max() - 0.45) < 0.02 and np.ptp(p.vertices[:, 0]) > 1.5]
    assert sorted(np.sign(p.vertices[:, 1].mean()) for p in seats) == [-1, 1]


def test_every_extruded_outline_is_star_shaped_about_its_mean(monkeypatch):
    """An extrusion's caps are fans from the outline's mean (parts.prism): a notched outline
    (the arcade cabinet's side) folds them over, a dark patch in renders. Generators split
    such outlines into convex pieces."""
    from scenewright.procedural import parts

    checked, folded = [], []
    real = parts.prism

    def prism(polygon, depth):
        poly = np.asarray(polygon, float)
        centre, following = poly.mean(axis=0), np.roll(poly, -1, axis=0)
        turns = (poly[:, 0] - centre[0]) * (following[:, 1] - centre[1]) - (poly[:, 1] - centre[1]) * (following[:, 0] - centre[0])
        checked.append(len(poly))
        if (turns > 1e-12).any() and (turns < -1e-12).any():
            folded.append(poly.round(3).tolist())
        return real(polygon, depth)

    monkeypatch.setattr(parts, "prism", prism)
    for shape, names in (("machine", ("arcade", "console", "machine")), ("vehicle", ("car", "tractor", "spaceship")),
                         ("table", ("picnic table",)), ("sign", ("tombstone", "sign")), ("boat", ("boat",))):
        for name in names:
            for style in ("realistic", "low-poly"):
                SHAPES[shape](Model((1.0, 0.8, 1.2), resolve_style(style), np.random.default_rng(0), name=name))
    assert checked, "no outline was extruded: the check saw nothing"
    assert not folded, folded[:3]


def test_a_description_alone_does_not_change_what_an_object_is():
    described = build_model("rock", (1.0, 1.0, 0.6), "realistic", 1, description="a rock beside the campfire", name="rock")
    assert "flame" not in described.geometry


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-3, 3), min_size=9, max_size=9))
def test_closed_form_inverse_matches_numpy(values):
    from scenewright.procedural.parts import inverse3

    m = np.array(values).reshape(3, 3)
    det = np.linalg.det(m)
    assume(abs(det) > 1e-3)
    inverse, got = inverse3(m)
    assert got == pytest.approx(det, rel=1e-9, abs=1e-12)
    assert np.allclose(inverse, np.linalg.inv(m), rtol=1e-7, atol=1e-9)


def test_a_singular_part_transform_is_refused():
    from scenewright.procedural.parts import inverse3

    with pytest.raises(ValueError, match="singular"):
        inverse3(np.diag([1.0, 0.0, 1.0]))


def test_cat_tree_top_platform_is_the_top_of_its_box():
    """The solver rests ``on`` things at the host box's top; a cat tree's widest platform is
    there, so cats put on it lie on carpet, not on a post tip."""
    model = Model((0.6, 0.6, 1.6), resolve_style("realistic"), np.random.default_rng(0), name="cat tree")
    SHAPES["pillar"](model)
    verts = np.concatenate([p.vertices for parts in model.parts.values() for p in parts])
    top = verts[verts[:, 2] > verts[:, 2].max() - 1e-6]
    span = top[:, :2].max(axis=0) - top[:, :2].min(axis=0)
    assert (span >= 0.5).all()
    assert "marble" not in model.parts  # not drawn as a column


@pytest.mark.parametrize("style", ["realistic", "cartoon", "low-poly"])
@pytest.mark.parametrize("category", sorted(c.name for c in load_catalogue().values() if c.rest_height))
def test_rest_height_is_where_the_mesh_has_its_seat(category, style):
    """A category's ``rest_height`` (the seat under a backrest, the mattress under a headboard)
    is an upward surface of its mesh near the footprint's middle, at that share of its height,
    fitted to the box as :meth:`Model.finish` fits it."""
    entry = load_catalogue()[category]
    model = Model(entry.size, resolve_style(style), np.random.default_rng(0), name=entry.label)
    SHAPES[entry.shape](model)
    parts = [p for ps in model.parts.values() for p in ps]
    verts = np.concatenate([p.vertices for p in parts])
    lo, hi = verts.min(axis=0), verts.max(axis=0)
    size = np.array(entry.size)
    heights = []
    for part in parts:
        tri = (part.vertices[part.faces] - lo) * size / (hi - lo)
        normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        up = normal[:, 2] > 0.95 * np.linalg.norm(normal, axis=1)
        centre = tri.mean(axis=1)
        middle = (np.abs(centre[:, 0] - size[0] / 2) < 0.3 * size[0]) & (np.abs(centre[:, 1] - size[1] / 2) < 0.3 * size[1])
        heights += list(centre[up & middle, 2] / size[2])
    assert heights, "no upward surface near the middle"
    assert min(heights, key=lambda h: abs(h - entry.rest_height)) == pytest.approx(entry.rest_height, abs=0.04)


def test_a_truck_s_trade_shapes_its_body():
    """A fire engine is painted to the tail with a ladder on its roof, a pickup's bed is open (what
    rides in the back shows), a plain lorry carries a box."""
    def truck(name: str) -> Model:
        model = Model((2.5, 8.0, 3.2), resolve_style("realistic"), np.random.default_rng(0), name=name)
        SHAPES["truck"](model)
        return model

    fire, pickup, lorry = truck("fire engine truck"), truck("pickup truck"), truck("lorry truck")
    assert "canvas_alt" not in fire.parts and "canvas_alt" not in pickup.parts and "canvas_alt" in lorry.parts
    tail = [p for p in fire.parts["paint"] if p.vertices[:, 1].max() > 3.9]
    assert tail and max(p.vertices[:, 2].max() for p in tail) > 0.8 * 3.2
    assert max(p.vertices[:, 2].max() for p in fire.parts["metal"]) > 0.85 * 3.2  # the roof ladder
    bed = [p for p in pickup.parts["paint"] if p.vertices[:, 1].min() > -1.0]
    assert bed and max(p.vertices[:, 2].max() for p in bed) < 0.5 * 3.2


def test_a_castle_and_a_church_are_no_office_blocks():
    """A castle has battlements and corner towers with pointed roofs over its walls, a church a
    spire over its nave; neither has an office block's glass door."""
    def build(name: str, size) -> Model:
        model = Model(size, resolve_style("realistic"), np.random.default_rng(0), name=f"{name} building")
        SHAPES["building"](model)
        return model

    castle = build("castle", (30.0, 26.0, 18.0))
    assert "glass" not in castle.parts and len(castle.parts["roof"]) >= 5
    assert max(p.vertices[:, 2].max() for p in castle.parts["roof"]) > 0.9 * 18.0
    church = build("church", (12.0, 24.0, 18.0))
    spire = max(church.parts["roof"], key=lambda p: p.vertices[:, 2].max())
    assert spire.vertices[:, 2].max() > 0.95 * 18.0 and spire.vertices[:, 1].mean() < 0  # at the front


def test_a_dome_habitat_is_a_dome_not_a_tower_block_or_a_truss():
    """A habitat dome, an igloo or a geodesic dome is a round shell with its door toward the
    viewer, whether the catalogue files it as a building or the open vocabulary as a structure."""
    for name, shape in (("dome habitat", "building"), ("igloo", "structure")):
        model = Model((8.0, 8.0, 4.0), resolve_style("realistic"), np.random.default_rng(0), name=name)
        SHAPES[shape](model)
        shell = max(model.parts["wall"], key=lambda p: len(p.vertices))
        top = shell.vertices[shell.vertices[:, 2] > 0.9 * 4.0]
        assert len(top) and np.abs(top[:, :2]).max() < 0.25 * 8.0  # rounded up to a crown
        assert "truss" not in model.parts and "concrete" not in model.parts
        door = [p for p in model.parts["dark_metal"] if p.vertices[:, 1].max() < -3.5]
        assert door, name


def test_a_pagoda_has_tiers_of_roofs_narrowing_upward():
    model = Model((6.0, 6.0, 10.0), resolve_style("realistic"), np.random.default_rng(0), name="pagoda")
    SHAPES["building"](model)
    roofs = sorted(model.parts["roof"], key=lambda p: p.vertices[:, 2].min())
    assert len(roofs) >= 3 and "glass" not in model.parts
    widths = [np.ptp(p.vertices[:, 0]) for p in roofs]
    assert widths == sorted(widths, reverse=True)


def test_a_helmet_is_a_rounded_shell_not_a_toolbox():
    model = Model((0.25, 0.3, 0.25), resolve_style("realistic"), np.random.default_rng(0), name="helmet")
    SHAPES["tool"](model)
    shell = model.parts["paint"][0].vertices
    top = shell[shell[:, 2] > 0.95 * 0.25]
    assert len(top) and np.abs(top[:, :2]).max() < 0.06


def test_a_fireplace_burns_behind_its_surround():
    """A fireplace is a brick surround with a fire in it, not a cabinet; a wood stove is iron,
    "wood" naming what it burns, not what it is made of."""
    fire = build_model("fireplace", (1.5, 0.5, 1.2), "realistic", 1, name="fireplace")
    assert {"brick", "flame", "bark"} <= set(fire.geometry)
    stove = build_model("fireplace", (0.6, 0.5, 1.8), "realistic", 1, "wood stove", name="wood stove fireplace")
    assert stove.geometry["dark_metal"].visual.material.metallicFactor > 0.5


def test_a_low_stage_is_a_deck_and_a_tall_one_has_a_truss():
    assert "light" not in build_model("structure", (5.0, 3.0, 0.8), "realistic", 1, name="stage").geometry
    assert "light" in build_model("structure", (8.0, 5.0, 4.0), "realistic", 1, name="stage").geometry


def _figure_model(name: str, size, seed: int = 0) -> Model:
    model = Model(size, resolve_style("realistic"), np.random.default_rng(seed), name=name)
    SHAPES["figure"](model)
    return model


@pytest.mark.parametrize(("name", "size", "people"), [("couple", (1.0, 0.5, 1.75), 2), ("family", (1.4, 0.6, 1.75), 4),
                                                     ("crowd", (3.0, 2.0, 1.75), 8)])
def test_a_word_for_several_people_draws_that_many_inside_its_box(name, size, people):
    one = len(_figure_model("person", (0.55, 0.3, 1.75)).parts["skin"])
    group = _figure_model(name, size)
    assert len(group.parts["skin"]) == people * one  # heads, hands and necks: one set each
    points = np.vstack([p.vertices for parts in group.parts.values() for p in parts])
    assert np.all(np.abs(points[:, 0]) <= size[0] / 2 + 1e-6) and np.all(np.abs(points[:, 1]) <= size[1] / 2 + 1e-6)
    assert points[:, 2].max() <= size[2] + 1e-6
    if name == "family":  # two grown-ups and two children: only the grown-ups' heads are up high
        high = [p for p in group.parts["skin"] if p.vertices[:, 2].max() > 0.8 * size[2]]
        alone = [p for p in _figure_model("person", (0.55, 0.3, 1.75)).parts["skin"] if p.vertices[:, 2].max() > 0.8 * 1.75]
        assert alone and len(high) == 2 * len(alone)


def test_people_dress_in_more_than_one_colour():
    shirts = {_figure_model("person", (0.55, 0.3, 1.75), seed).tints["clothes"] for seed in range(12)}
    assert len(shirts) >= 3
    assert "clothes" not in _figure_model("knight", (0.55, 0.3, 1.75)).tints  # armour keeps its metal


def test_a_sign_wider_than_tall_is_a_board_without_posts():
    """A neon sign over a bar is a glowing board; a signpost stands on its posts."""
    def roles(size):
        return set(build_model("sign", size, "realistic", seed=1, name="neon sign").geometry)

    assert "dark_metal" not in roles((1.0, 0.08, 0.5)) and "concrete" not in roles((1.0, 0.08, 0.5))
    assert "dark_metal" in roles((0.6, 0.1, 2.2))
    board = build_model("sign", (1.0, 0.08, 0.5), "realistic", seed=1, name="neon sign")
    assert np.allclose(board.extents, (1.0, 0.5, 0.08), atol=0.02)  # glTF: x, up, depth


def test_a_low_swim_ring_lies_flat_and_a_life_ring_stands_up():
    """A swim ring on the water is a flat torus; a life ring on a rail stands on its edge."""
    flat = load(build_glb("generic", (1.0, 1.0, 0.25), "realistic", 1, name="inflatable ring"))
    upright = load(build_glb("generic", (0.7, 0.1, 0.7), "realistic", 1, name="life ring"))
    assert_fills(build_glb("generic", (1.0, 1.0, 0.25), "realistic", 1, name="inflatable ring"), (1.0, 1.0, 0.25))
    ring = next(iter(flat.geometry.values()))
    # a flat ring leaves its middle empty seen from above (glTF is y-up): no vertex near the upright axis
    assert np.min(np.hypot(ring.vertices[:, 0], ring.vertices[:, 2])) > 0.2
    hoop = next(iter(upright.geometry.values()))
    assert np.min(np.hypot(hoop.vertices[:, 0], hoop.vertices[:, 2])) < 0.05  # seen from above it crosses the axis


def test_a_footbridge_is_a_deck_rising_to_its_crown_with_rails():
    """A bridge is walked along its depth: its deck is low at both ends and high in the middle,
    and nothing closes the way under its crown (the old arch drew a tunnel)."""
    size = (2.0, 5.0, 1.5)
    assert_fills(build_glb("arch", size, "realistic", 1, name="arched bridge"), size)
    model = build_model("arch", size, "realistic", 1, "red arched bridge", name="arched bridge")
    points = np.vstack([g.vertices for g in scene_frame(model).values()])
    ends = points[np.abs(points[:, 1]) > 0.45 * size[1]]
    middle = points[np.abs(points[:, 1]) < 0.05 * size[1]]
    assert ends[:, 2].min() < 0.05 and middle[:, 2].min() > 0.3  # the deck springs from the ground, open below its crown
    stone = build_model("arch", size, "realistic", 1, "stone bridge", name="stone bridge")
    assert set(stone.geometry) == {"stone"}


def test_a_flowering_tree_is_known_by_its_blossom_and_a_skin_rug_by_its_fur():
    cherry = build_model("tree", (4.0, 4.0, 6.0), "realistic", 1, name="cherry tree")
    assert "blossom" in cherry.geometry and "leaf" not in cherry.geometry
    assert "leaf" in build_model("tree", (4.0, 4.0, 6.0), "realistic", 1, name="oak tree").geometry
    pelt = build_model("rug", (2.4, 1.7, 0.02), "realistic", 1, name="bearskin rug")
    assert set(pelt.geometry) == {"fur_dark"}
    assert_fills(build_glb("rug", (2.4, 1.7, 0.02), "realistic", 1, name="sheepskin rug"), (2.4, 1.7, 0.02))


def test_a_cabbage_is_a_green_head_of_leaves_and_a_climbing_frame_has_its_deck_at_its_rest_height():
    from scenewright.core.catalogue import load_catalogue
    from scenewright.procedural.meshes import build_model

    cabbage = build_model("generic", (0.2, 0.2, 0.18), "realistic", 0, "", "cabbage thing")
    assert set(cabbage.geometry) == {"leaf"}
    frame = build_model("structure", (3.0, 2.0, 2.2), "realistic", 0, "", "jungle gym climbing_frame")
    deck = frame.geometry["wood"].bounds  # glTF: y up
    assert deck[1][1] == pytest.approx(load_catalogue()["climbing_frame"].rest_height * 2.2, abs=1e-3)


def test_a_string_of_lights_sags_across_its_width_and_bunting_carries_flags():
    from scenewright.procedural.meshes import build_model

    lights = build_model("garland", (5.0, 0.1, 0.6), "realistic", 0, "", "fairy lights string_lights")
    assert {"light", "dark_plastic"} <= set(lights.geometry)
    bounds = lights.geometry["dark_plastic"].bounds  # glTF: x across, y up
    assert bounds[1][0] - bounds[0][0] == pytest.approx(5.0, abs=0.05) and bounds[0][1] < 0.3 < bounds[1][1]
    bunting = build_model("garland", (5.0, 0.1, 0.6), "realistic", 0, "", "bunting string_lights")
    assert "light" not in bunting.geometry and {"canvas", "accent"} <= set(bunting.geometry)


def test_lanterns_are_lanterns_and_a_potted_palm_has_its_pot():
    lamp = build_model("table_lamp", (0.3, 0.3, 0.5), "realistic", seed=1, name="table lamp")
    oil = build_model("table_lamp", (0.25, 0.25, 0.4), "realistic", seed=1, name="lantern")
    stone = build_model("table_lamp", (0.5, 0.5, 1.3), "realistic", seed=1, description="stone", name="stone lantern")
    paper = build_model("table_lamp", (0.4, 0.4, 0.5), "realistic", seed=1, description="paper", name="paper lantern")
    assert "shade" in lamp.geometry and not {"shade"} & ({*oil.geometry} | {*stone.geometry} | {*paper.geometry})
    assert "glass" in oil.geometry and "stone" in stone.geometry and "paper" in paper.geometry
    potted = build_model("palm_tree", (1.0, 1.0, 2.2), "realistic", seed=1, description="tall potted palm", name="palm")
    assert "ceramic" in potted.geometry
    assert "ceramic" not in build_model("palm_tree", (4.0, 4.0, 6.0), "realistic", seed=1, name="palm").geometry


def test_a_seal_is_no_leopard():
    seal = build_model("animal", (0.5, 1.6, 0.5), "realistic", seed=1, name="leopard seal")
    leopard = build_model("animal", (0.5, 1.6, 0.9), "realistic", seed=1, name="leopard")
    assert "hide" in seal.geometry and "fur_light" not in seal.geometry and "fur_light" in leopard.geometry


def test_a_toy_castle_keeps_its_towers_and_courtyard():
    """A castle stated on a rug is a metre across: walls 0.4 m thick filled it into a block (its
    parts took 83 % of its box; a full-size castle's take under a quarter)."""
    for size in ((1.0, 0.9, 0.6), (30.0, 24.0, 16.0)):
        scene = build_model("building", size, "realistic", seed=1, name="wooden castle building")
        lo, hi = scene.bounds
        fill = sum(abs(g.volume) for g in scene.geometry.values()) / np.prod(hi - lo)
        assert fill < 0.5, (size, fill)
