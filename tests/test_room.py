"""The room's meshes: walls are closed slabs outside the floor line with openings that go
through, corners closed, every part named and coloured; scene.glb, Blender and the renderer
carry them."""

from __future__ import annotations

import importlib.util
import json
import subprocess
import sys

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st

from gltf_validator import assert_valid
from scenewright.export import assemble
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE, SCENE_TO_GLTF, object_matrix
from scenewright.procedural.room import (
    CEILING_THICKNESS,
    FLOOR_THICKNESS,
    GLTF_MATERIAL,
    WALL_THICKNESS,
    opening_centre,
    opening_nodes,
    room_meshes,
    wall_normal,
)
from scenewright.render.views import VIEWS, cut_away
from scenewright.scene import Opening, Room, Scene, SceneObject, Vec3

has_bpy = importlib.util.find_spec("bpy") is not None
T = WALL_THICKNESS


def _room() -> Room:
    return Room.rectangle(
        5.0,
        6.0,
        openings=[
            Opening(kind="door", wall=0, offset=1.0, width=0.9, height=2.1),
            Opening(kind="window", wall=2, offset=2.0, width=1.2, height=1.2, sill=0.9),
            Opening(kind="window", wall=3, offset=3.0, width=1.0, height=1.0, sill=1.0),
        ],
    )


L_FLOOR = [(0.0, 0.0), (6.0, 0.0), (6.0, 3.0), (3.0, 3.0), (3.0, 6.0), (0.0, 6.0)]


def _l_room() -> Room:
    return Room(
        floor=L_FLOOR,
        openings=[
            Opening(kind="door", wall=3, offset=1.5, width=0.9, height=2.1),
            Opening(kind="window", wall=2, offset=1.5, width=1.0, height=1.0, sill=1.0),
        ],
    )


def _hits(mesh: trimesh.Trimesh, origin, direction) -> np.ndarray:
    """Distances along the ray at which it crosses the mesh's triangles (Möller–Trumbore)."""
    tri = mesh.triangles
    d = np.asarray(direction, float)
    e1, e2 = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
    p = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, p)
    ok = np.abs(det) > 1e-12
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = np.asarray(origin, float) - tri[:, 0]
    u = np.einsum("ij,ij->i", s, p) * inv
    q = np.cross(s, e1)
    v = (q @ d) * inv
    t = np.einsum("ij,ij->i", e2, q) * inv
    hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
    return t[hit]


def _meshes(room: Room, style: str = "realistic") -> dict[str, trimesh.Trimesh]:
    meshes = room_meshes(room, style)
    names = [name for name, _ in meshes]
    assert len(names) == len(set(names))
    return dict(meshes)


def test_every_part_is_named_and_coloured():
    meshes = _meshes(_room())
    assert set(meshes) == {
        "room/floor", "room/ceiling", *(f"room/wall_{i}" for i in range(4)),
        "room/door_0/frame", "room/door_0/leaf", "room/door_0/handle",
        "room/window_0/frame", "room/window_0/glass", "room/window_1/frame", "room/window_1/glass",
    }
    assert opening_nodes(_room()) == ["room/door_0", "room/window_0", "room/window_1"]
    for name, mesh in meshes.items():
        assert len(mesh.faces) > 0, name
        if name == "room/floor":
            assert mesh.visual.material.baseColorTexture is not None
            assert mesh.visual.uv.shape == (len(mesh.vertices), 2)
        else:
            assert GLTF_MATERIAL in mesh.metadata, name
    glass = meshes["room/window_0/glass"].metadata[GLTF_MATERIAL]
    assert glass["alphaMode"] == "BLEND" and "KHR_materials_transmission" in glass["extensions"]


def test_material_words_colour_the_room_and_the_style_shifts_them():
    def wall_colour(room, style="realistic"):
        return _meshes(room, style)["room/wall_0"].metadata[GLTF_MATERIAL]["pbrMetallicRoughness"]["baseColorFactor"]

    plain = wall_colour(Room.rectangle(4, 4))
    red = wall_colour(Room.rectangle(4, 4, wall_material="red brick"))
    assert red[0] > 2 * red[2] and plain != red
    assert wall_colour(Room.rectangle(4, 4), "cyberpunk") != plain
    tiles = _meshes(Room.rectangle(4, 4, floor_material="ceramic tiles"))["room/floor"].visual.material
    wood = _meshes(Room.rectangle(4, 4))["room/floor"].visual.material
    assert np.asarray(tiles.baseColorTexture).tolist() != np.asarray(wood.baseColorTexture).tolist()


@pytest.mark.parametrize("room", [_room(), _l_room()], ids=["rectangle", "l-shape"])
def test_every_mesh_is_a_closed_outward_facing_surface(room):
    for name, mesh in _meshes(room).items():
        assert mesh.is_watertight and mesh.is_winding_consistent, name
        assert mesh.volume > 0, name  # outward normals


def test_walls_stand_outside_the_floor_line_and_fill_the_band_around_it():
    room = _room()
    meshes = _meshes(room)
    for i, ((x0, y0), (x1, y1)) in enumerate(room.walls):
        wall = meshes[f"room/wall_{i}"]
        inward = wall_normal(room, i)
        depth = (wall.vertices[:, :2] - (x0, y0)) @ inward[:2]
        assert depth.max() == pytest.approx(0.0, abs=1e-9)  # the inner face is the wall line
        assert depth.min() == pytest.approx(-T, abs=1e-9)
        assert wall.bounds[0][2] == 0.0 and wall.bounds[1][2] == pytest.approx(room.height)
    # The slabs close the corners and do not overlap: together they fill the band between the
    # floor rectangle and the rectangle grown by the thickness, less the openings.
    holes = sum(o.width * o.height for o in room.openings)
    band = ((5 + 2 * T) * (6 + 2 * T) - 5 * 6) * room.height - holes * T
    assert sum(meshes[f"room/wall_{i}"].volume for i in range(4)) == pytest.approx(band, rel=1e-9)


def test_floor_and_ceiling_cover_the_room_and_the_walls():
    room = _l_room()
    meshes = _meshes(room)
    floor, ceiling = meshes["room/floor"], meshes["room/ceiling"]
    assert floor.bounds[1][2] == 0.0 and floor.bounds[0][2] == pytest.approx(-FLOOR_THICKNESS)
    assert ceiling.bounds[0][2] == pytest.approx(room.height)
    assert ceiling.bounds[1][2] == pytest.approx(room.height + CEILING_THICKNESS)
    walls = sum(meshes[f"room/wall_{i}"].volume for i in range(6)) / room.height
    holes = sum(o.width * o.height for o in room.openings) * T / room.height
    # Floor area = the L's 27 m² plus the walls' footprint.
    assert floor.volume / FLOOR_THICKNESS == pytest.approx(27.0 + walls + holes, rel=1e-9)


def _through(room: Room, meshes, index: int, along: float = 0.0):
    """Hits on the opening's wall of a ray from inside the room, crossing the wall at the
    opening's centre shifted ``along`` the wall."""
    o = room.openings[index]
    inward = wall_normal(room, o.wall)
    (x0, y0), (x1, y1) = room.walls[o.wall]
    direction = np.array([x1 - x0, y1 - y0, 0.0]) / room.wall_length(o.wall)
    start = opening_centre(room, index) + along * direction + 0.5 * inward
    return _hits(meshes[f"room/wall_{o.wall}"], start, -inward)


@pytest.mark.parametrize("room", [_room(), _l_room()], ids=["rectangle", "l-shape"])
def test_a_ray_through_each_opening_misses_its_wall_and_beside_it_hits_both_faces(room):
    meshes = _meshes(room)
    for k, o in enumerate(room.openings):
        assert len(_through(room, meshes, k)) == 0, (k, o)
        beside = _through(room, meshes, k, along=o.width / 2 + 0.2)
        np.testing.assert_allclose(sorted(set(np.round(beside, 9))), [0.5, 0.5 + T], atol=1e-9)


def test_a_door_leaves_the_doorway_free_and_opens_outward():
    room = _room()
    meshes = _meshes(room)
    inward = wall_normal(room, 0)
    centre = opening_centre(room, 0)
    for part in ("frame", "leaf", "handle"):
        assert len(_hits(meshes[f"room/door_0/{part}"], centre + 0.5 * inward, -inward)) == 0, part
    leaf = meshes["room/door_0/leaf"]
    # Wall 0 is the front wall (y = -3): the open leaf stands outside it, not in the room.
    assert leaf.bounds[1][1] == pytest.approx(-3.0 - T) and leaf.bounds[0][1] == pytest.approx(-3.0 - T - 0.9)
    # A window's glass fills its hole.
    glass = _hits(meshes["room/window_0/glass"], opening_centre(room, 1) + 0.5 * wall_normal(room, 2), -wall_normal(room, 2))
    np.testing.assert_allclose(sorted(set(np.round(glass, 9))), [0.5 + T / 2 - 0.005, 0.5 + T / 2 + 0.005])


def test_an_opening_reaching_into_an_inner_corner_is_narrowed_to_what_goes_through(caplog):
    room = Room(floor=L_FLOOR, openings=[Opening(kind="door", wall=3, offset=0.46, width=0.9, height=2.1)])
    meshes = _meshes(room)
    assert "reaches into the corner" in caplog.text
    assert meshes["room/wall_3"].is_watertight
    assert len(_through(room, meshes, 0, along=0.1)) == 0


@settings(max_examples=25, deadline=None)
@given(
    width=st.floats(2.0, 9.0),
    depth=st.floats(2.0, 9.0),
    height=st.floats(2.2, 4.0),
    spots=st.lists(st.tuples(st.integers(0, 3), st.floats(0.05, 0.95), st.booleans()), max_size=4),
)
def test_any_rectangle_with_openings_gives_closed_walls_with_holes_through(width, depth, height, spots):
    openings = []
    for wall, share, door in spots:
        length = width if wall % 2 == 0 else depth
        w = 0.8
        offset = min(max(share * length, w / 2 + 0.2), length - w / 2 - 0.2)
        if any(o.wall == wall and abs(o.offset - offset) < w + 0.1 for o in openings):
            continue
        if door:
            openings.append(Opening(kind="door", wall=wall, offset=offset, width=w, height=2.0))
        else:
            openings.append(Opening(kind="window", wall=wall, offset=offset, width=w, height=1.0, sill=0.9))
    room = Room.rectangle(width, depth, height, openings=openings)
    meshes = _meshes(room)
    for i in range(4):
        assert meshes[f"room/wall_{i}"].is_watertight and meshes[f"room/wall_{i}"].volume > 0
    for k in range(len(openings)):
        assert len(_through(room, meshes, k)) == 0
    holes = sum(o.width * o.height for o in openings)
    band = ((width + 2 * T) * (depth + 2 * T) - width * depth) * height - holes * T
    assert sum(meshes[f"room/wall_{i}"].volume for i in range(4)) == pytest.approx(band, rel=1e-6)


@settings(max_examples=20, deadline=None)
@given(sides=st.integers(3, 9), radius=st.floats(2.0, 6.0), turn=st.floats(0.0, 2 * np.pi))
def test_the_walls_of_any_regular_room_close_every_corner_without_overlap(sides, radius, turn):
    angles = turn + 2 * np.pi * np.arange(sides) / sides
    room = Room(floor=[(radius * np.cos(a), radius * np.sin(a)) for a in angles])
    meshes = _meshes(room)
    side = 2 * radius * np.sin(np.pi / sides)
    area = sides * radius**2 * np.sin(2 * np.pi / sides) / 2
    # The floor grown outward by T with mitred corners: area + perimeter·T + T²·Σ tan(turn/2).
    grown = area + sides * side * T + T**2 * sides * np.tan(np.pi / sides)
    walls = [meshes[f"room/wall_{i}"] for i in range(sides)]
    assert all(w.is_watertight and w.volume > 0 for w in walls)
    assert sum(w.volume for w in walls) == pytest.approx((grown - area) * room.height, rel=1e-9)
    assert meshes["room/floor"].volume == pytest.approx(grown * FLOOR_THICKNESS, rel=1e-9)


def test_each_view_cuts_away_the_ceiling_and_the_walls_nearer_the_camera():
    room = _room()  # walls: 0 front (−y), 1 right, 2 back, 3 left; window_1 is on the left wall
    assert cut_away(room, "front") == ["room/ceiling", "room/wall_0", "room/door_0"]
    assert cut_away(room, "right") == ["room/ceiling", "room/wall_1"]
    assert cut_away(room, "iso_left") == ["room/ceiling", "room/wall_0", "room/wall_3", "room/door_0", "room/window_1"]
    for view in VIEWS:  # the far walls always stay, so the room reads as a room
        assert "room/wall_2" not in cut_away(room, view)


# scene.glb, Blender, renders ---------------------------------------------------------------
def _room_scene(tmp_path) -> tuple[Scene, SceneFolder]:
    """Three box assets in a 5 × 6 m room, laid out as the pipeline's folder holds them."""
    folder = SceneFolder(tmp_path / "scene")
    folder.create()
    folder.assets.mkdir()
    scene = Scene(
        text="a sofa, a table and a lamp in a room",
        objects=[
            SceneObject(id="sofa_1", name="sofa", size=Vec3(x=2.0, y=0.9, z=0.8),
                        position=Vec3(x=0.0, y=2.3, z=0.4)),
            SceneObject(id="table_1", name="table", size=Vec3(x=1.2, y=0.7, z=0.75),
                        position=Vec3(x=0.2, y=0.5, z=0.375), rotation=Vec3(z=20)),
            SceneObject(id="lamp_1", name="lamp", size=Vec3(x=0.4, y=0.4, z=1.6),
                        position=Vec3(x=-2.0, y=2.3, z=0.8)),
        ],
        room=_room(),
    )
    for i, obj in enumerate(scene.objects):
        box = trimesh.creation.box(extents=obj.size.tuple())
        box.apply_translation([0, 0, obj.size.z / 2])
        box.apply_transform(SCENE_TO_GLTF)
        box.visual.face_colors = [[200, 80, 60, 255], [60, 120, 200, 255], [230, 200, 70, 255]][i]
        folder.asset(obj.id).write_bytes(box.export(file_type="glb"))
        obj.asset = folder.relative(folder.asset(obj.id))
    folder.save(scene)
    assemble(scene, folder)
    return scene, folder


def _scene_frame_bounds(loaded: trimesh.Scene, prefix: str) -> np.ndarray:
    points = [
        trimesh.transform_points(loaded.geometry[geometry].vertices, GLTF_TO_SCENE @ loaded.graph[node][0])
        for node in loaded.graph.nodes_geometry
        if node.startswith(prefix)
        for geometry in [loaded.graph[node][1]]
    ]
    points = np.vstack(points)
    return np.array([points.min(axis=0), points.max(axis=0)])


def test_scene_glb_holds_the_room_as_named_nodes_with_the_floor_at_zero(tmp_path):
    scene, folder = _room_scene(tmp_path)
    loaded = trimesh.load_scene(folder.glb)
    nodes = set(loaded.graph.nodes)
    assert {name for name, _ in room_meshes(scene.room, scene.style)} <= nodes
    assert {"room", *opening_nodes(scene.room)} <= nodes
    assert "ground" not in nodes  # the room's floor is the ground
    floor = _scene_frame_bounds(loaded, "room/floor")
    assert floor[1][2] == pytest.approx(0.0, abs=1e-6)
    np.testing.assert_allclose(floor[1][:2], [2.5 + T, 3.0 + T], atol=1e-6)
    wall = _scene_frame_bounds(loaded, "room/wall_2")  # the back wall, behind y = 3
    assert wall[0][1] == pytest.approx(3.0, abs=1e-6) and wall[1][2] == pytest.approx(scene.room.height)
    # Objects keep their poses beside the room.
    np.testing.assert_allclose(loaded.graph.get("sofa_1")[0], SCENE_TO_GLTF @ object_matrix(scene.objects[0]) @ GLTF_TO_SCENE, atol=1e-6)


@pytest.mark.node
def test_a_room_scene_is_valid_gltf(tmp_path):
    _, folder = _room_scene(tmp_path)
    report = assert_valid(folder.glb)
    assert report["issues"]["messages"] == []
    assert "KHR_materials_transmission" in report["info"]["extensionsUsed"]


BLENDER_RAYS = """
import json, sys
import bpy
from mathutils import Vector
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=sys.argv[1])
depsgraph = bpy.context.evaluated_depsgraph_get()
out = []
for origin, direction in json.loads(sys.argv[2]):
    hit, location, normal, index, obj, matrix = bpy.context.scene.ray_cast(depsgraph, Vector(origin), Vector(direction))
    out.append(obj.name if hit else None)
print(json.dumps({"hits": out, "names": sorted(o.name for o in bpy.data.objects)}))
"""


@pytest.mark.blender
@pytest.mark.skipif(not has_bpy, reason="needs the render extra (bpy)")
def test_blender_imports_the_room_and_sees_through_its_door(tmp_path):
    scene, folder = _room_scene(tmp_path)
    room = scene.room
    inward = wall_normal(room, 0)
    door = opening_centre(room, 0)
    rays = [
        (door + 0.5 * inward, -inward),  # through the doorway: nothing
        (door + 0.5 * inward + [1.2, 0.0, 0.0], -inward),  # beside it: the front wall
        (door + 0.5 * inward + [0.0, 0.0, 1.3], -inward),  # above it: the wall over the door
    ]
    proc = subprocess.run(
        [sys.executable, "-c", BLENDER_RAYS, str(folder.glb), json.dumps([[list(map(float, o)), list(map(float, d))] for o, d in rays])],
        capture_output=True, text=True, timeout=300,
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    result = json.loads(proc.stdout.strip().splitlines()[-1])
    assert result["hits"] == [None, "room/wall_0", "room/wall_0"]
    assert {"room/floor", "room/wall_0", "room/door_0", "room/window_0/glass"} <= set(result["names"])


@pytest.mark.blender
@pytest.mark.skipif(not has_bpy, reason="needs the render extra (bpy)")
def test_every_view_of_a_room_shows_every_object(tmp_path):
    from PIL import Image

    from scenewright.render import render

    scene, folder = _room_scene(tmp_path)
    render(scene, folder, draft=True, keep_all=True)
    info = json.loads((folder.renders / "renders.json").read_text())
    for view in VIEWS:  # the near walls would hide the objects from the front and left views
        assert all(pixels > 0 for pixels in info["visible"][view].values()), (view, info["visible"][view])
    image = np.asarray(Image.open(folder.renders / "front.png").convert("RGB"), float)
    assert image.std() > 5



# Simulation exports -----------------------------------------------------------------------
def test_mujoco_collides_the_walls_as_boxes_and_the_doorway_stays_open(tmp_path):
    mujoco = pytest.importorskip("mujoco", reason="loading MJCF needs the 'sim' extra (mujoco)")
    from scenewright.cli import main
    from scenewright.procedural.room import wall_boxes

    scene, folder = _room_scene(tmp_path)
    assert main(["export", str(folder.root), "--format", "mjcf"]) == 0
    model = mujoco.MjModel.from_xml_path(str(folder.simulation / "mjcf" / "scene.xml"))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    boxes = wall_boxes(scene.room)
    for name, _, extents in boxes:
        geom = model.geom(name)
        assert geom.type[0] == mujoco.mjtGeom.mjGEOM_BOX and geom.bodyid[0] == 0  # static, in the world
        np.testing.assert_allclose(geom.size, extents / 2.0, rtol=1e-5)
    assert model.geom("room/wall_0").contype[0] == 0  # the visual mesh does not collide
    room, hit = scene.room, np.array([-1], dtype=np.int32)
    inward, door = wall_normal(room, 0), opening_centre(room, 0)
    collision_only = np.array([0, 0, 0, 1, 0, 0], dtype=np.uint8)

    def ray(start) -> str | None:
        distance = mujoco.mj_ray(model, data, np.asarray(start, float), -inward, collision_only, 1, -1, hit)
        return None if distance < 0 else model.geom(int(hit[0])).name

    assert ray(door + 0.5 * inward) is None
    assert ray(door + 0.5 * inward + [1.2, 0.0, 0.0]).startswith("room/wall_0/box_")


def test_usd_holds_the_room_with_static_wall_colliders(tmp_path):
    pytest.importorskip("pxr", reason="USD export needs the 'sim' extra (usd-core)")
    from pxr import Usd, UsdGeom, UsdPhysics

    from scenewright.cli import main
    from scenewright.procedural.room import wall_boxes

    scene, folder = _room_scene(tmp_path)
    assert main(["export", str(folder.root), "--format", "usd"]) == 0
    stage = Usd.Stage.Open(str(folder.simulation / "scene.usd"))
    room = stage.GetPrimAtPath("/World/room")
    colliders = [p for p in Usd.PrimRange(room) if p.HasAPI(UsdPhysics.CollisionAPI)]
    assert len(colliders) == len(wall_boxes(scene.room))
    assert not any(p.HasAPI(UsdPhysics.RigidBodyAPI) for p in Usd.PrimRange(room))
    visual = {p.GetName() for p in Usd.PrimRange(room) if p.IsA(UsdGeom.Mesh)}
    assert {"floor", "ceiling", "wall_0", "door_0_leaf", "window_0_glass"} <= visual
    cache = UsdGeom.BBoxCache(Usd.TimeCode.Default(), [UsdGeom.Tokens.default_, UsdGeom.Tokens.guide])
    back = cache.ComputeWorldBound(stage.GetPrimAtPath("/World/room/collision/wall_2_box_0")).ComputeAlignedRange()
    assert back.GetMin()[1] == pytest.approx(3.0, abs=1e-5) and back.GetMax()[1] == pytest.approx(3.0 + T, abs=1e-5)


@pytest.mark.node
@pytest.mark.parametrize("engine", ["godot", "unreal"])
def test_glb_physics_gives_every_wall_box_colliders_and_stays_valid(tmp_path, engine):
    from scenewright.cli import main
    from scenewright.procedural.room import wall_boxes

    scene, folder = _room_scene(tmp_path)
    out = tmp_path / f"{engine}.glb"
    assert main(["export", str(folder.root), "-f", "glb-physics", "--engine", engine, "--out", str(out)]) == 0
    assert_valid(out)
    nodes = trimesh.load_scene(out).graph.nodes
    prefix, suffix = ("room_wall_", "-convcolonly") if engine == "godot" else ("UCX_room_wall_", "")
    walls = [n for n in nodes if n.startswith(prefix) and n.endswith(suffix)]
    assert len(walls) == len(wall_boxes(scene.room))


def test_the_studio_draws_the_room_without_its_ceiling(tmp_path):
    pytest.importorskip("viser", reason="viser is not installed (the studio extra: make install-studio)")
    import socket

    from scenewright.backends import backends_from_settings
    from scenewright.settings import Settings
    from scenewright.studio import Session
    from scenewright.studio.server import Studio

    scene, folder = _room_scene(tmp_path)
    settings = Settings()
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    studio = Studio(Session(folder, backends=backends_from_settings(settings), settings=settings), port=port)
    try:
        drawn = {name.removeprefix("__") for name in studio._nodes if name.startswith("__room/")}
        expected = {name for name, _ in room_meshes(scene.room, scene.style)} - {"room/ceiling"}
        assert drawn == expected
        assert "__ground" not in studio._nodes
    finally:
        studio.stop()
