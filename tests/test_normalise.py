"""Asset normalisation: any GLB ends centred, on the ground, at the requested height."""

from __future__ import annotations

import json
import struct

import numpy as np
import pytest
import trimesh
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from scenewright.assets import asset_mesh
from scenewright.assets.normalise import check_glb, normalise, parse_glb, to_glb
from scenewright.errors import BackendError
from scenewright.geometry import object_matrix
from scenewright.scene import SceneObject, Vec3

extent = st.floats(0.02, 10.0)
offset = st.floats(-100.0, 100.0)
height = st.floats(0.05, 20.0)


def glb_of(*meshes: trimesh.Trimesh, transforms=None) -> bytes:
    scene = trimesh.Scene()
    for index, mesh in enumerate(meshes):
        scene.add_geometry(mesh, node_name=f"n{index}", transform=None if transforms is None else transforms[index])
    return scene.export(file_type="glb")


def empty_glb() -> bytes:
    """A valid GLB with no meshes at all (trimesh refuses to write one)."""
    body = json.dumps({"asset": {"version": "2.0"}, "scenes": [{"nodes": []}], "scene": 0}).encode()
    body += b" " * (-len(body) % 4)
    chunk = struct.pack("<I4s", len(body), b"JSON") + body
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunk)) + chunk


def check_normalised(scene: trimesh.Scene, size: Vec3, wanted_z: float) -> None:
    lo, hi = scene.bounds
    tol = 1e-6 * max(1.0, wanted_z, *(hi - lo))
    assert lo[1] == pytest.approx(0.0, abs=tol)
    assert hi[1] - lo[1] == pytest.approx(wanted_z, rel=1e-6)
    assert (lo[0] + hi[0]) / 2 == pytest.approx(0.0, abs=tol)
    assert (lo[2] + hi[2]) / 2 == pytest.approx(0.0, abs=tol)
    assert size.z == wanted_z
    assert size.x == pytest.approx(max(hi[0] - lo[0], 0.001), rel=1e-6)
    assert size.y == pytest.approx(max(hi[2] - lo[2], 0.001), rel=1e-6)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(ex=extent, ey=extent, ez=extent, ox=offset, oy=offset, oz=offset, z=height)
def test_any_box_normalises(ex, ey, ez, ox, oy, oz, z):
    box = trimesh.creation.box(extents=(ex, ey, ez))
    box.apply_translation((ox, oy, oz))
    data = glb_of(box)
    scene, size = normalise(data, Vec3(x=1, y=1, z=z), name="crate_1", backend="test")
    check_normalised(scene, size, z)
    # Uniform rescale: the proportions of the stored (float32) mesh survive.
    stored = parse_glb(data).extents
    scale = z / stored[1]
    assert size.x == pytest.approx(max(stored[0] * scale, 0.001), rel=1e-6)
    assert size.y == pytest.approx(max(stored[2] * scale, 0.001), rel=1e-6)


@pytest.mark.filterwarnings("ignore:invalid value encountered:RuntimeWarning")  # trimesh, on flat hulls
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    points=st.lists(st.tuples(offset, offset, offset), min_size=8, max_size=30, unique=True),
    angle=st.floats(-np.pi, np.pi),
    z=height,
)
def test_any_mesh_under_a_rotated_node_normalises(points, angle, z):
    hull = trimesh.PointCloud(np.array(points)).convex_hull
    assume(hull.extents is not None and hull.extents.min() > 1e-3)  # a solid, not a plane
    node = trimesh.transformations.rotation_matrix(angle, [0.3, 1.0, 0.2])
    node[:3, 3] = [5.0, -7.0, 2.0]
    second = trimesh.creation.icosphere(subdivisions=1, radius=0.5)
    scene, size = normalise(glb_of(hull, second, transforms=[node, np.eye(4)]), Vec3(x=1, y=1, z=z),
                            name="statue_1", backend="test")
    check_normalised(scene, size, z)
    # What is written is what was measured.
    again = trimesh.load(trimesh.util.wrap_as_stream(to_glb(scene)), file_type="glb", force="scene")
    assert np.allclose(again.bounds, scene.bounds, atol=1e-4 * max(1.0, z))


def nosed_model() -> trimesh.Trimesh:
    """A glTF-frame body 1 wide, 2 tall, 1 deep, with a nose sticking out toward its front (+Z)."""
    body = trimesh.creation.box(extents=(1.0, 2.0, 1.0))
    nose = trimesh.creation.box(extents=(0.2, 0.2, 0.5))
    nose.apply_translation((0.0, 0.5, 0.75))
    return trimesh.util.concatenate([body, nose])


def test_y_up_becomes_z_up_and_front_faces_minus_y():
    scene, size = normalise(glb_of(nosed_model()), Vec3(x=1, y=1, z=4.0), name="robot_1", backend="test")
    mesh = asset_mesh(to_glb(scene))
    lo, hi = mesh.bounds
    assert lo[2] == pytest.approx(0.0, abs=1e-6) and hi[2] == pytest.approx(4.0)
    assert size.y == pytest.approx(hi[1] - lo[1]) and size.x == pytest.approx(hi[0] - lo[0])
    # Scaled ×2: the body spans y −0.5…1.5 and the nose (0.4 wide) reaches out to −1.5, toward −Y.
    assert lo[1] == pytest.approx(-1.5) and hi[1] == pytest.approx(1.5)
    nose = mesh.vertices[mesh.vertices[:, 1] < -0.6]
    assert len(nose) and np.all(np.abs(nose[:, 0]) <= 0.2 + 1e-6)
    # Placed at yaw 90 the front turns toward +X (front_direction(90) = (1, 0)).
    obj = SceneObject(id="robot_1", name="robot", size=size, rotation=Vec3(z=90.0), position=Vec3(z=2.0))
    placed = mesh.to_trimesh().apply_transform(object_matrix(obj))
    assert placed.bounds[1][0] == pytest.approx(1.5) and placed.bounds[0][0] == pytest.approx(-1.5)
    nose = placed.vertices[placed.vertices[:, 0] > 0.6]
    assert len(nose) and np.all(np.abs(nose[:, 1]) <= 0.2 + 1e-6)
    assert placed.bounds[0][2] == pytest.approx(0.0, abs=1e-6)


@pytest.mark.parametrize(
    ("data", "why"),
    [
        (b"<html>502 Bad Gateway</html>", "glTF magic"),
        (b"", "too short"),
        (glb_of(trimesh.creation.box())[:-40], "truncated"),
        (empty_glb(), "no triangles"),
        (glb_of(trimesh.creation.box(extents=(1.0, 0.0, 1.0))), "flat"),
    ],
)
def test_invalid_meshes_name_object_and_backend(data, why):
    with pytest.raises(BackendError, match=why) as info:
        normalise(data, Vec3(x=1, y=1, z=1), name="sofa_1", backend="hunyuan3d")
    assert "sofa_1" in str(info.value) and "hunyuan3d" in str(info.value)


def test_points_alone_are_not_a_mesh():
    cloud = trimesh.Scene(trimesh.PointCloud(np.random.default_rng(0).random((20, 3))))
    data = cloud.export(file_type="glb")
    assert check_glb(data) is None
    with pytest.raises(BackendError, match="no triangles"):
        normalise(data, Vec3(x=1, y=1, z=1), name="tree_1", backend="library")


def test_max_faces_reduces_heavy_meshes_and_keeps_their_colour():
    pytest.importorskip("fast_simplification")
    sphere = trimesh.creation.icosphere(subdivisions=5)
    sphere.visual.face_colors = np.tile([20, 200, 40, 255], (len(sphere.faces), 1))
    scene, size = normalise(glb_of(sphere), Vec3(x=1, y=1, z=2.0), name="bush_1", backend="test", max_faces=2000)
    faces = sum(len(g.faces) for g in scene.geometry.values())
    assert faces <= 2000 and faces > 500
    check_normalised(scene, size, 2.0)
    colours = next(iter(scene.geometry.values())).visual.vertex_colors
    assert np.all(colours[:, :3] == [20, 200, 40])


def test_max_faces_leaves_light_meshes_alone():
    box = trimesh.creation.box()
    scene, _ = normalise(glb_of(box), Vec3(x=1, y=1, z=1), name="crate_1", backend="test", max_faces=100)
    assert sum(len(g.faces) for g in scene.geometry.values()) == 12


def test_the_files_own_normals_survive():
    # Normals no renderer would compute from the faces: every one points up.
    box = trimesh.creation.box(extents=(1.0, 2.0, 1.0))
    box.vertex_normals = np.tile([0.0, 1.0, 0.0], (len(box.vertices), 1))
    scene, _ = normalise(glb_of(box), Vec3(x=1, y=1, z=3.0), name="pillar_1", backend="test")
    mesh = next(iter(parse_glb(to_glb(scene)).geometry.values()))
    assert np.allclose(mesh.vertex_normals, [0.0, 1.0, 0.0], atol=1e-6)


@pytest.mark.parametrize("mirror", [False, True])
def test_asset_mesh_is_trimesh_to_mesh_in_the_scene_frame(mirror):
    """The triangles read straight from the file are the ones trimesh's own loader gives, each
    with the same winding (a mirroring node turns it over); meshes may come in another order."""
    from scenewright.geometry import GLTF_TO_SCENE

    scene = trimesh.Scene()
    scene.add_geometry(trimesh.creation.box((1, 2, 3)), geom_name="a")
    node = np.diag([-1.0, 1.0, 1.0, 1.0]) if mirror else np.eye(4)
    node[:3, 3] = (0.5, 0.2, -0.3)
    scene.add_geometry(trimesh.creation.icosphere(1, 0.4), geom_name="b", transform=node)
    data = to_glb(scene)
    expected = parse_glb(data).to_mesh()
    expected.apply_transform(GLTF_TO_SCENE)
    got = asset_mesh(data)

    def oriented(mesh) -> set:
        """Each triangle as its corners from the smallest one on, so only a flip changes it."""
        out = set()
        for tri in np.round(mesh.vertices[mesh.faces], 9):
            corners = [tuple(c) for c in tri]
            k = corners.index(min(corners))
            out.add(tuple(corners[k:] + corners[:k]))
        return out

    assert len(got.faces) == len(expected.faces) and oriented(got) == oriented(expected)


def test_a_glb_in_the_convention_is_stored_as_it_came():
    from scenewright.assets.normalise import stored_glb
    from scenewright.procedural.meshes import build_glb

    glb = build_glb("sofa", (2.0, 0.9, 0.85), "realistic", 1)
    data, size = stored_glb(glb, Vec3(x=2.0, y=0.9, z=0.85), name="sofa_1", backend="procedural")
    assert data == glb
    assert size.tuple() == pytest.approx((2.0, 0.9, 0.85), abs=1e-6)
    # Asked for another height, it is rescaled as any backend's mesh is.
    data, size = stored_glb(glb, Vec3(x=2.0, y=0.9, z=1.7), name="sofa_1", backend="procedural")
    assert data != glb
    assert size.tuple() == pytest.approx((4.0, 1.8, 1.7), abs=1e-5)


def test_building_and_storing_a_procedural_asset_and_a_room_needs_no_mesh_library():
    import subprocess
    import sys

    code = (
        "import sys\n"
        "from scenewright.assets.normalise import stored_glb\n"
        "from scenewright.export.glb import room_glb\n"
        "from scenewright.procedural.meshes import build_glb\n"
        "from scenewright.scene import Room, Scene, Vec3\n"
        "glb = build_glb('chair', (0.5, 0.5, 0.9), 'cartoon', 3)\n"
        "stored_glb(glb, Vec3(x=0.5, y=0.5, z=0.9), name='chair_1', backend='procedural')\n"
        "room_glb(Scene(text='a room', room=Room.rectangle(4.0, 3.0, 2.7)))\n"
        "print(sorted({m.split('.')[0] for m in sys.modules} & {'trimesh', 'networkx'}))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"
