"""The asset-library backend: index or inferred index, token matching, axis fixes."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from scenewright.assets import asset_mesh, generate_assets
from scenewright.backends.library import AssetLibrary, infer_index
from scenewright.assets.normalise import normalise, to_glb
from scenewright.backends import MeshRequest, create_backend
from scenewright.cache import RequestCache
from scenewright.errors import BackendError, InputError
from scenewright.folder import SceneFolder
from scenewright.scene import Scene, SceneObject, Vec3
from scenewright.settings import Settings


def request(oid, name, category=None, description="") -> MeshRequest:
    return MeshRequest(id=oid, name=name, category=category, description=description, style="realistic",
                       size=Vec3(x=1, y=1, z=1))


def box(extents) -> trimesh.Trimesh:
    return trimesh.creation.box(extents=extents)


@pytest.fixture
def collection(tmp_path):
    root = tmp_path / "library"
    (root / "seating").mkdir(parents=True)
    (root / "lighting").mkdir()
    trimesh.Scene(box((2.0, 0.8, 0.9))).export(root / "seating" / "red_leather_couch.glb")
    trimesh.Scene(box((0.5, 0.9, 0.4))).export(root / "seating" / "wooden_chair.glb")
    trimesh.Scene(box((0.3, 1.7, 0.3))).export(root / "lighting" / "brass_lamp.glb")
    box((0.6, 0.6, 1.8)).export(root / "tall_cabinet.obj")  # z-up file
    return root


def test_index_is_inferred_from_file_and_folder_names(collection):
    entries = {e.file: e for e in infer_index(collection)}
    assert entries["seating/red_leather_couch.glb"].category == "sofa"  # catalogue synonym
    assert entries["seating/red_leather_couch.glb"].tags == ("seating",)
    assert entries["seating/wooden_chair.glb"].category == "chair"
    assert entries["tall_cabinet.obj"].name == "tall cabinet"


def test_requests_match_by_category_then_name_words(collection):
    library = AssetLibrary(collection)
    assert library.match(request("sofa_1", "sofa", "sofa")).file == "seating/red_leather_couch.glb"
    assert library.match(request("chair_2", "wooden chair")).file == "seating/wooden_chair.glb"
    assert library.match(request("lamp_1", "brass lamp", description="a brass reading lamp")).file == (
        "lighting/brass_lamp.glb"
    )


def test_no_match_names_the_object_and_the_closest_candidates(collection):
    library = AssetLibrary(collection)
    with pytest.raises(BackendError) as info:
        library.generate([request("piano_1", "grand piano", "piano", "a black wooden piano")])
    text = str(info.value)
    assert "piano_1" in text and "closest" in text and "wooden chair" in text  # 'wooden' is the only hit


def test_glb_files_come_back_unchanged_and_obj_files_become_glb(collection):
    library = AssetLibrary(collection)
    out = library.generate([request("chair_1", "chair", "chair")])
    assert out["chair_1"] == (collection / "seating" / "wooden_chair.glb").read_bytes()
    cabinet = library.generate([request("cabinet_1", "cabinet", "cabinet")])["cabinet_1"]
    assert cabinet[:4] == b"glTF"


def test_index_toml_sets_up_axis_and_turn(collection):
    (collection / "index.toml").write_text(
        '[[asset]]\nfile = "tall_cabinet.obj"\nname = "tall cabinet"\ncategory = "cabinet"\nup = "z"\n'
        '\n[[asset]]\nfile = "seating/wooden_chair.glb"\nname = "chair"\ntags = ["wood"]\nturn = 90\n'
    )
    library = AssetLibrary(collection)
    assert [e.file for e in library.entries] == ["tall_cabinet.obj", "seating/wooden_chair.glb"]
    glb = library.generate([request("cabinet_1", "cabinet", "cabinet")])["cabinet_1"]
    scene, size = normalise(glb, Vec3(x=1, y=1, z=1.8), name="cabinet_1", backend="library")
    # z-up file: its 1.8 m z extent is the height, its 0.6 × 0.6 footprint stays.
    assert size.tuple() == pytest.approx((0.6, 0.6, 1.8))
    chair = library.generate([request("chair_1", "chair")])["chair_1"]
    # Turned 90° about +Y: width (0.5) and depth (0.4) swap, the height stays.
    mesh = asset_mesh(to_glb(normalise(chair, Vec3(x=1, y=1, z=0.9), name="chair_1", backend="library")[0]))
    assert mesh.extents == pytest.approx((0.4, 0.5, 0.9))


def test_index_errors_name_the_file_and_the_fix(collection):
    (collection / "index.toml").write_text('[[asset]]\nfile = "missing.glb"\n')
    with pytest.raises(InputError, match="missing.glb"):
        AssetLibrary(collection)
    (collection / "index.toml").write_text('[[asset]]\nfile = "tall_cabinet.obj"\ncolour = "red"\n')
    with pytest.raises(InputError, match="unknown: colour"):
        AssetLibrary(collection)
    (collection / "index.toml").write_text('[[asset]]\nfile = "tall_cabinet.obj"\nup = "x"\n')
    with pytest.raises(InputError, match="up"):
        AssetLibrary(collection)


def test_from_spec_needs_a_folder_with_assets(tmp_path, collection):
    assert isinstance(create_backend("meshes", f"library:{collection}", Settings()), AssetLibrary)
    with pytest.raises(InputError, match="library:/path"):
        AssetLibrary.from_spec("", Settings())
    with pytest.raises(InputError, match="not a folder"):
        AssetLibrary.from_spec(str(tmp_path / "nope"), Settings())
    (tmp_path / "empty").mkdir()
    with pytest.raises(InputError, match="no .glb or .obj"):
        AssetLibrary.from_spec(str(tmp_path / "empty"), Settings())


def test_a_changed_collection_changes_the_cache_key(collection):
    before = AssetLibrary(collection).params
    trimesh.Scene(box((1.0, 1.0, 1.0))).export(collection / "crate.glb")
    assert AssetLibrary(collection).params != before


def test_library_assets_through_the_stage(tmp_path, collection):
    folder = SceneFolder(tmp_path / "scene")
    folder.create()
    scene = Scene(text="a couch and a chair", objects=[
        SceneObject(id="sofa_1", name="couch", category="sofa", size=Vec3(x=1.5, y=1.0, z=0.45)),
        SceneObject(id="chair_1", name="chair", category="chair", size=Vec3(x=0.5, y=0.5, z=0.9)),
    ])
    generate_assets(scene, folder, AssetLibrary(collection), RequestCache(tmp_path / "cache"))
    # The couch (2.0 × 0.8 tall × 0.9 deep) scaled to 0.45 m tall keeps its proportions.
    assert scene.get("sofa_1").size.tuple() == pytest.approx((2.0 * 0.45 / 0.8, 0.9 * 0.45 / 0.8, 0.45))
    assert np.isclose(scene.get("chair_1").size.z, 0.9)
