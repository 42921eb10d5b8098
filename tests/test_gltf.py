"""True colours and materials: sRGB colours become linear glTF factors, named colours display
as named in the assembled scene.glb, glass transmits, material words set the surface."""

from __future__ import annotations

import copy
import io

import numpy as np
import pytest
import trimesh
from hypothesis import given
from hypothesis import strategies as st

from gltf_validator import assert_valid
from scenewright.cli import main
from scenewright.folder import SceneFolder
from scenewright.gltf import json_chunk, keep_materials, srgb_to_linear
from scenewright.core.colours import COLOURS
from scenewright.procedural.material import MATERIALS


def to_srgb(linear) -> np.ndarray:
    """What a viewer shows for a linear factor (the sRGB encoding, written independently)."""
    c = np.clip(np.asarray(linear, float), 0, 1)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1 / 2.4) - 0.055)


def test_srgb_to_linear_is_the_srgb_transfer_function():
    assert srgb_to_linear((0.0, 1.0)) == (0.0, 1.0)
    assert srgb_to_linear((0.5,))[0] == pytest.approx(0.21404, abs=1e-5)
    assert srgb_to_linear((0.04045,))[0] == pytest.approx(0.04045 / 12.92)
    # the two pieces meet: no jump at the threshold
    below, above = srgb_to_linear((0.04045 - 1e-9, 0.04045 + 1e-9))
    assert above - below < 1e-6
    assert srgb_to_linear((-0.2, 1.3)) == (0.0, 1.0), "out-of-range colours are clamped"


@given(st.lists(st.floats(0.0, 1.0), min_size=1, max_size=4))
def test_the_conversion_round_trips_and_darkens(values):
    linear = srgb_to_linear(values)
    np.testing.assert_allclose(to_srgb(linear), values, atol=1e-6)  # the two thresholds differ by ~1e-7
    assert all(lin <= v + 1e-12 for lin, v in zip(linear, values))


def test_keep_materials_restores_exact_factors_and_splits_shared_materials():
    tree = {
        "materials": [{"name": "wood", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.2, 0.2, 1.0]}}],
        "meshes": [{"name": "a", "primitives": [{"material": 0}]}, {"name": "b", "primitives": [{"material": 0}]},
                   {"name": "c", "primitives": [{"material": 0}]}],
    }
    glass = {"name": "wood", "pbrMetallicRoughness": {"baseColorFactor": [0.21404, 0.2, 0.2, 0.35]},
             "alphaMode": "BLEND", "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}}}
    plain = {"name": "wood", "pbrMetallicRoughness": {"baseColorFactor": [0.19, 0.2, 0.2, 1.0]}}
    original = copy.deepcopy(tree["materials"][0])
    keep_materials({"a": glass, "b": plain})(tree)
    a, b, c = (tree["materials"][m["primitives"][0]["material"]] for m in tree["meshes"])
    assert a["pbrMetallicRoughness"]["baseColorFactor"] == [0.21404, 0.2, 0.2, 0.35]
    assert a["extensions"] == glass["extensions"] and "extensions" not in b
    assert b["pbrMetallicRoughness"]["baseColorFactor"] == [0.19, 0.2, 0.2, 1.0]
    assert c == original, "a mesh with no recorded material keeps its own"
    assert len(tree["materials"]) == 3 and tree["extensionsUsed"] == ["KHR_materials_transmission"]


TEXT = (
    "A living room with a grey fabric sofa, a walnut coffee table in front of the sofa, a brown "
    "leather armchair beside the sofa, a red rug under the coffee table, a navy blue cabinet, a "
    "glass vase on the coffee table, a round mirror and a gold statue."
)


@pytest.fixture(scope="module")
def living_room(tmp_path_factory):
    out = tmp_path_factory.mktemp("colours") / "room"
    assert main(["generate", TEXT, "--out", str(out), "--no-render"]) == 0
    folder = SceneFolder(out)
    tree = json_chunk(folder.glb.read_bytes())
    return folder, tree


def materials_of(tree: dict, object_id: str) -> dict[str, dict]:
    """Role → material of one object's meshes in the assembled scene (meshes are ``id/role``)."""
    found = {}
    for mesh in tree["meshes"]:
        owner, _, role = mesh["name"].partition("/")
        if owner == object_id:
            found[role] = tree["materials"][mesh["primitives"][0]["material"]]
    assert found, f"{object_id} has no meshes in scene.glb"
    return found


def shown(material: dict) -> np.ndarray:
    return to_srgb(material["pbrMetallicRoughness"]["baseColorFactor"][:3])


@pytest.mark.parametrize(
    ("object_id", "role", "named"),
    [
        ("sofa_1", "fabric", COLOURS["grey"]),
        ("coffee_table_1", "wood", MATERIALS["walnut"].color),
        ("armchair_1", "fabric", COLOURS["brown"]),
        ("rug_1", "fabric", COLOURS["red"]),
        ("cabinet_1", "wood", COLOURS["navy"]),
    ],
)
def test_named_colours_display_as_named_in_the_scene_glb(living_room, object_id, role, named):
    _, tree = living_room
    material = materials_of(tree, object_id)[role]
    np.testing.assert_allclose(shown(material), named, atol=0.01)


def test_a_grey_sofa_is_grey_not_near_white(living_room):
    _, tree = living_room
    fabric = materials_of(tree, "sofa_1")["fabric"]["pbrMetallicRoughness"]["baseColorFactor"]
    assert max(fabric[:3]) < 0.25, "linear factor of mid grey is about 0.21; 0.5 would show as #BCBCBC"
    assert np.all(np.abs(shown({"pbrMetallicRoughness": {"baseColorFactor": fabric}}) - 0.5) < 0.01)


def test_material_words_show_in_the_scene_glb(living_room):
    _, tree = living_room
    leather = materials_of(tree, "armchair_1")["fabric"]["pbrMetallicRoughness"]
    assert leather["roughnessFactor"] == pytest.approx(MATERIALS["leather"].roughness)
    assert leather["metallicFactor"] == 0.0
    glass = materials_of(tree, "vase_1")["ceramic"]
    assert glass["alphaMode"] == "BLEND" and glass["pbrMetallicRoughness"]["baseColorFactor"][3] < 1
    assert glass["extensions"]["KHR_materials_transmission"]["transmissionFactor"] > 0.5
    assert "KHR_materials_transmission" in tree["extensionsUsed"]
    gold = [m["pbrMetallicRoughness"] for m in materials_of(tree, "statue_1").values()]
    assert any(p["metallicFactor"] == 1.0 and np.allclose(to_srgb(p["baseColorFactor"][:3]), MATERIALS["gold"].color, atol=0.01)
               for p in gold), "a gold statue is gold metal"


def test_the_scene_with_glass_is_valid_gltf(living_room):
    folder, _ = living_room
    report = assert_valid(folder.glb)
    assert "KHR_materials_transmission" in report["info"]["extensionsUsed"]


def test_normalised_assets_keep_their_exact_materials(caplog):
    from scenewright.assets.normalise import normalise, to_glb
    from scenewright.procedural.meshes import build_glb
    from scenewright.scene import Vec3

    glb = build_glb("table", (1.2, 0.8, 0.75), "realistic", 1, "a glass table", "table")
    asset, _ = normalise(glb, Vec3(x=1.2, y=0.8, z=0.75), name="table_1", backend="procedural")
    kept = json_chunk(to_glb(asset, source=glb))["materials"]
    assert kept == json_chunk(glb)["materials"]
    with caplog.at_level("WARNING"):
        plain = json_chunk(to_glb(asset, source=b"glTF\x02\x00\x00\x00 not json"))
    assert "unreadable" in caplog.text and "extensions" not in plain["materials"][0]


# Reading triangles straight from a GLB (what the solver and export need of an asset) ---------
def _glb_with(primitive_mode: int, indices: list[int], node: dict, parent: dict | None = None) -> bytes:
    from scenewright.export.splice import GlbWriter

    out = GlbWriter("test")
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0, 2, 0]], dtype=float)
    position = out.accessor(points, "VEC3")
    index = out.accessor(np.array(indices), "SCALAR")
    mesh = out.add("meshes", {"primitives": [{"attributes": {"POSITION": position}, "indices": index,
                                             "mode": primitive_mode}]})
    holder = out.node("holder")
    out.tree["nodes"][holder].update(parent or {})
    child = out.node("child", parent=holder)
    out.tree["nodes"][child].update(node, mesh=mesh)
    return out.to_bytes()


def test_triangles_follow_node_transforms_and_primitive_modes():
    from scenewright.gltf import Glb, glb_triangles

    turn = [0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)]  # 90° about z
    data = _glb_with(4, [0, 1, 2, 1, 3, 2], {"translation": [1.0, 0.0, 0.0], "rotation": turn, "scale": [2, 2, 2]},
                     parent={"matrix": np.eye(4).reshape(-1).tolist()})
    vertices, faces = glb_triangles(Glb.parse(data))
    loaded = trimesh.load_scene(io.BytesIO(data), file_type="glb").to_mesh()
    np.testing.assert_allclose(np.sort(vertices, axis=0), np.sort(loaded.vertices, axis=0), atol=1e-9)
    np.testing.assert_allclose(vertices[1], [1.0, 2.0, 0.0], atol=1e-9)  # (1,0,0) scaled, turned, moved
    assert faces.tolist() == [[0, 1, 2], [1, 3, 2]]
    assert glb_triangles(Glb.parse(_glb_with(5, [0, 1, 2, 3, 4], {})))[1].tolist() == [[0, 1, 2], [2, 1, 3], [2, 3, 4]]
    assert glb_triangles(Glb.parse(_glb_with(6, [0, 1, 2, 3], {})))[1].tolist() == [[0, 1, 2], [0, 2, 3]]
    mirrored = glb_triangles(Glb.parse(_glb_with(4, [0, 1, 2], {"scale": [-1, 1, 1]})))[1]
    assert mirrored.tolist() == [[2, 1, 0]], "a mirroring node turns the winding over"


def test_triangles_of_a_file_that_refers_to_what_it_lacks_are_a_value_error():
    from scenewright.gltf import Glb, glb_triangles

    glb = Glb.parse(_glb_with(4, [0, 1, 7], {}))
    with pytest.raises(ValueError, match="vertex"):
        glb_triangles(glb)
    glb.tree["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9
    with pytest.raises(ValueError, match="does not hold"):
        glb_triangles(glb)
    glb.tree["accessors"][0]["count"] = 10_000
    glb.tree["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 0
    with pytest.raises(ValueError, match="runs past"):
        glb_triangles(glb)
