"""Physical properties per object: derived from the asset, stored in the document, cached."""

from __future__ import annotations

import numpy as np
import pytest

from scenewright.cache import RequestCache
from scenewright.errors import InputError
from scenewright.export import physics as physics_module
from scenewright.export.colliders import Collider
from scenewright.export.physics import ensure_physics, friction, mass_properties, over_support
from scenewright.scene import Constraint
from sim_scenes import box as _box
from sim_scenes import glb as _glb
from sim_scenes import scene_of as _scene


def test_a_wooden_crate_gets_mass_from_density_and_volume(tmp_path):
    scene, folder = _scene(tmp_path, {"crate_1": ("crate", _box((0.5, 0.5, 0.5), (0, 0, 0.25)))})
    scene.objects[0].visual_description = "an old wooden crate"
    pieces = ensure_physics(scene, folder, RequestCache(tmp_path / "cache"))
    record = scene.get("crate_1").physics
    assert record.mass == pytest.approx(physics_module.DENSITY["crate"] * 0.125, rel=1e-3)
    assert record.center_of_mass.tuple() == pytest.approx((0, 0, 0.25), abs=1e-6)
    # A uniform cube: I = m (a² + a²) / 12 about each axis.
    assert record.inertia[:3] == pytest.approx([record.mass * 0.5 / 12] * 3, rel=1e-3)
    assert (record.material, record.friction) == ("wood", 0.5)
    assert record.method == "hull" and record.hulls == 1 and len(pieces["crate_1"].hulls) == 1
    assert not record.static
    assert folder.resolve(record.collider).is_file()
    # Stored in the document on disk, not only in memory.
    assert folder.load().get("crate_1").physics == record


def test_records_are_reused_and_pieces_come_from_the_cache(tmp_path, monkeypatch):
    scene, folder = _scene(tmp_path, {"crate_1": ("crate", _box((0.5, 0.5, 0.5), (0, 0, 0.25)))})
    cache = RequestCache(tmp_path / "cache")
    ensure_physics(scene, folder, cache)
    first = scene.get("crate_1").physics

    def no_recompute(*args, **kwargs):
        raise AssertionError("the collider was computed again")

    monkeypatch.setattr(physics_module, "collider", no_recompute)
    ensure_physics(scene, folder, cache)  # the record is current
    assert scene.get("crate_1").physics == first
    # A fresh copy of the same scene (another folder, no records) takes the pieces from the cache.
    other, other_folder = _scene(tmp_path / "b", {"crate_1": ("crate", _box((0.5, 0.5, 0.5), (0, 0, 0.25)))})
    ensure_physics(other, other_folder, cache)
    assert other.get("crate_1").physics.mass == first.mass


def test_a_changed_asset_is_derived_again(tmp_path):
    scene, folder = _scene(tmp_path, {"crate_1": ("crate", _box((0.5, 0.5, 0.5), (0, 0, 0.25)))})
    cache = RequestCache(tmp_path / "cache")
    ensure_physics(scene, folder, cache)
    folder.asset("crate_1").write_bytes(_glb(_box((0.5, 0.5, 1.0), (0, 0, 0.5))))
    ensure_physics(scene, folder, cache)
    assert scene.get("crate_1").physics.volume == pytest.approx(0.25, rel=1e-3)


def test_fixtures_hanging_things_and_animals_are_static(tmp_path):
    scene, folder = _scene(
        tmp_path,
        {
            "tree_1": ("tree", _box((0.5, 0.5, 2), (0, 0, 1))),
            "lamp_1": ("table_lamp", _box((0.2, 0.2, 0.4), (0, 0, 0.2))),
            "cat_1": ("cat", _box((0.2, 0.4, 0.3), (0, 0, 0.15))),
            "crate_1": ("crate", _box((0.5, 0.5, 0.5), (0, 0, 0.25))),
        },
        constraints=[Constraint(relation="above", source="lamp_1", target="crate_1")],
    )
    ensure_physics(scene, folder, RequestCache(None))
    assert [o.id for o in scene.objects if o.physics.static] == ["tree_1", "lamp_1", "cat_1"]


def test_an_object_without_an_asset_collides_as_its_size_box(tmp_path):
    scene, folder = _scene(tmp_path, {"box_1": ("crate", None)})
    pieces = ensure_physics(scene, folder, RequestCache(None))
    assert pieces["box_1"].hulls[0].extents == pytest.approx([0.5, 0.5, 0.5])


def test_a_missing_asset_file_is_an_input_error_naming_the_object(tmp_path):
    scene, folder = _scene(tmp_path, {"crate_1": ("crate", _box((0.5, 0.5, 0.5), (0, 0, 0.25)))})
    folder.asset("crate_1").unlink()
    with pytest.raises(InputError, match="crate_1.*missing"):
        ensure_physics(scene, folder, RequestCache(None))


def test_friction_prefers_the_description_then_the_largest_material():
    assert friction("a brass floor lamp", ["fabric"]) == ("brass", 0.4)
    assert friction("a lamp", ["shade", "rubber"]) == ("rubber", 1.0)
    assert friction("a thing", ["glow"]) == physics_module.DEFAULT_FRICTION


def test_mass_sits_where_the_solid_is():
    heavy, light = _box((0.2, 0.2, 0.2), (0, 0, 0.1)), _box((0.2, 0.2, 0.2), (0, 0, 1.1))
    piece = Collider([heavy, light], "parts", weights=[3.0, 1.0])
    com, inertia = mass_properties(piece, 4.0)
    assert com == pytest.approx([0, 0, 0.35])
    assert np.allclose(inertia, inertia.T) and np.all(np.linalg.eigvalsh(inertia) > 0)


def test_a_centre_of_mass_outside_the_support_is_brought_over_it():
    # Two feet from x = -0.5 to 0.5; a centre of mass at x = 0.8 would tip the thing over.
    feet = [_box((0.1, 0.4, 0.1), (-0.45, 0, 0.05)), _box((0.1, 0.4, 0.1), (0.45, 0, 0.05))]
    piece = Collider(feet, "parts")
    moved, distance = over_support(np.array([0.8, 0.0, 1.0]), piece)
    assert abs(moved[0]) <= 0.5 * physics_module.SUPPORT_SHARE + 1e-9 and moved[2] == 1.0
    assert distance == pytest.approx(0.8 - moved[0])
    kept, zero = over_support(np.array([0.1, 0.05, 1.0]), piece)
    assert zero == 0.0 and kept.tolist() == [0.1, 0.05, 1.0]
