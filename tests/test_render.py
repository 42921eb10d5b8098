import importlib.util
import json
import os
import signal
import struct
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st

import scenewright
from scenewright.errors import InputError, MissingExtra
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE, SCENE_TO_GLTF, object_matrix
from scenewright.render import (
    PREVIEWS,
    best_render,
    object_corners,
    render,
    render_info,
    scene_bounds,
)
from scenewright.render.views import (
    FILL,
    VIEWS,
    best_view,
    camera_matrix,
    half_fov_tangents,
    view_direction,
    visibility,
)
from scenewright.scene import Scene, SceneObject, Vec3

has_bpy = importlib.util.find_spec("bpy") is not None


def small_scene(tmp_path) -> tuple[Scene, SceneFolder]:
    """Three boxes and a ground node, exported the way the pipeline's scene.glb is laid out."""
    return box_folder(
        tmp_path,
        Scene(
            text="a table with a chair in front of it and a lamp to the right",
            objects=[
                SceneObject(id="table_1", name="table", position=Vec3(x=0, y=0, z=0.4), size=Vec3(x=1.4, y=0.8, z=0.8)),
                SceneObject(id="chair_1", name="chair", position=Vec3(x=-1.2, y=-1.0, z=0.45), size=Vec3(x=0.5, y=0.5, z=0.9)),
                SceneObject(
                    id="lamp_1", name="lamp", position=Vec3(x=1.5, y=0.3, z=0.8), rotation=Vec3(z=30), size=Vec3(x=0.3, y=0.3, z=1.6)
                ),
            ],
        ),
    )


def box_folder(tmp_path, scene: Scene) -> tuple[Scene, SceneFolder]:
    """A scene folder whose scene.glb holds each object as a coloured box of its size and pose."""
    folder = SceneFolder(tmp_path / "scene")
    folder.create()
    glb = trimesh.Scene()
    colours = [[200, 80, 60, 255], [60, 120, 200, 255], [230, 200, 70, 255]]
    for i, obj in enumerate(scene.objects):
        box = trimesh.creation.box(extents=obj.size.tuple())
        box.apply_translation([0, 0, obj.size.z / 2])
        box.apply_transform(SCENE_TO_GLTF)  # stored like an asset: glTF convention
        box.visual.face_colors = colours[i % len(colours)]
        glb.add_geometry(box, node_name=obj.id, geom_name=obj.id, transform=SCENE_TO_GLTF @ object_matrix(obj) @ GLTF_TO_SCENE)
    ground = trimesh.creation.box(extents=(8, 8, 0.01))
    ground.apply_transform(SCENE_TO_GLTF)
    glb.add_geometry(ground, node_name="ground", geom_name="ground")
    folder.glb.write_bytes(glb.export(file_type="glb"))
    folder.save(scene)
    return scene, folder


def project(m: np.ndarray, points, aspect: float) -> np.ndarray:
    """Points → (x, y) in frame units (±1 at the frame's edges) for the camera at ``m``."""
    cam = (np.linalg.inv(m) @ np.c_[np.asarray(points, float), np.ones(len(points))].T).T[:, :3]
    assert np.all(cam[:, 2] < 0), "a point behind the camera"  # it looks down −Z
    tan_x, tan_y = half_fov_tangents(aspect)
    return np.c_[cam[:, 0] / -cam[:, 2] / tan_x, cam[:, 1] / -cam[:, 2] / tan_y]


def scene_of(boxes) -> Scene:
    objects = [
        SceneObject(id=f"o{i}", name="box", position=Vec3(x=x, y=y, z=sz / 2), rotation=Vec3(z=yaw), size=Vec3(x=sx, y=sy, z=sz))
        for i, (x, y, yaw, sx, sy, sz) in enumerate(boxes)
    ]
    return Scene(text="boxes", objects=objects)


box_params = st.tuples(
    st.floats(-20, 20), st.floats(-20, 20), st.floats(-180, 180), st.floats(0.2, 6), st.floats(0.2, 6), st.floats(0.2, 8)
)


@settings(max_examples=60, deadline=None)
@given(boxes=st.lists(box_params, min_size=1, max_size=8), aspect=st.sampled_from([16 / 9, 4 / 3, 1.0, 9 / 16]))
def test_every_view_frames_every_object_corner_tightly(boxes, aspect):
    corners = object_corners(scene_of(boxes))
    for view in VIEWS:
        xy = project(camera_matrix(view, corners, aspect), corners, aspect)
        assert np.all(np.abs(xy) <= FILL + 1e-6), view
        # Tight: the objects span the full FILL share on one axis, centred on both. (Objects of
        # at least 20 cm: tinier scenes are held back by the lens's near clipping distance.)
        span = xy.max(axis=0) - xy.min(axis=0)
        assert span.max() >= 2 * FILL - 1e-6 and span.max() >= 2 * 0.8, (view, span)
        assert np.allclose(xy.max(axis=0), -xy.min(axis=0), atol=1e-6), view


def test_views_keep_their_directions_whatever_they_frame():
    corners = object_corners(scene_of([(0, 0, 0, 1, 1, 1), (9, 4, 30, 2, 1, 3)]))
    for view in VIEWS:
        m = camera_matrix(view, corners, 16 / 9)
        assert np.allclose(m[:3, 2], view_direction(view))  # the camera looks down its −Z
        assert abs(m[2, 0]) < 1e-12  # no roll: the frame's x axis stays level
    front = camera_matrix("front", corners, 16 / 9)
    assert front[1, 3] < min(c[1] for c in corners)  # in front of (−Y from) every object


def test_object_corners_follow_the_pose():
    (box,) = scene_of([(2, 3, 90, 4, 1, 2)]).objects
    corners = np.array(object_corners(Scene(text="x", objects=[box])))
    assert corners.shape == (8, 3)
    # Turned a quarter: the 4 m side now runs along y; bottom on the ground.
    assert np.allclose(corners.min(axis=0), [1.5, 1.0, 0.0]) and np.allclose(corners.max(axis=0), [2.5, 5.0, 2.0])


def test_visibility_decodes_indices_and_ignores_background():
    image = np.zeros((2, 3, 4), np.uint8)
    image[0, 0] = [1, 0, 0, 255]
    image[0, 1] = [1, 0, 0, 255]
    image[1, 2] = [2, 1, 0, 255]  # index 258
    image[1, 1] = [2, 0, 0, 0]  # transparent: background, not counted
    ids = [f"o{i}" for i in range(258)]
    counts = visibility(image, ids)
    assert counts["o0"] == 2 and counts["o257"] == 1 and counts["o1"] == 0


def test_best_view_prefers_more_objects_then_well_shown_ones_then_even_shares_then_paper_order():
    assert best_view({"iso_left": {"a": 5, "b": 0}, "front": {"a": 1, "b": 1}}) == "front"
    assert best_view({"iso_left": {"a": 1}, "front": {"a": 1}, "right": {"a": 1}}) == "iso_left"
    # Same objects seen: the view where fewer are mostly hidden wins over the one with more pixels.
    assert best_view({"iso_left": {"a": 60, "b": 30}, "right": {"a": 200, "b": 5}}) == "iso_left"
    # All well shown: the even view beats one with more pixels that one object dominates.
    assert best_view({"iso_left": {"a": 900, "b": 100, "c": 100}, "front": {"a": 300, "b": 200, "c": 200}}) == "front"


@settings(max_examples=50, deadline=None)
@given(
    counts=st.lists(st.lists(st.integers(6000, 8000), min_size=3, max_size=3), min_size=3, max_size=3),
    zoom=st.sampled_from([2, 3]),
)
def test_zooming_in_on_a_view_does_not_make_it_win(counts, zoom):
    # Even zoomed, counts stay within a factor 4 of each other: every object stays well shown,
    # so only the last keys decide, and a nearer camera (all counts scaled) must not matter.
    visible = {view: dict(zip("abc", row, strict=True)) for view, row in zip(VIEWS, counts, strict=True)}
    chosen = best_view(visible)
    for view in VIEWS:
        zoomed = {**visible, view: {i: n * zoom for i, n in visible[view].items()}}
        assert best_view(zoomed) == chosen


def test_bounds_cover_objects_and_footprint():
    scene = Scene(
        text="x",
        bounds=(10.0, 4.0),
        objects=[SceneObject(id="a", name="a", position=Vec3(x=6, y=0, z=1), size=Vec3(x=2, y=2, z=2))],
    )
    low, high = scene_bounds(scene)
    assert low == [-5.0, -2.0, 0.0] and high == [7.0, 2.0, 2.0]


def test_render_refuses_unknown_views_and_missing_glb(tmp_path):
    scene, folder = small_scene(tmp_path)
    with pytest.raises(InputError, match="iso_left"):
        render(scene, folder, views=("top",))
    folder.glb.unlink()
    with pytest.raises(InputError, match="scene.glb"):
        render(scene, folder)


def test_missing_bpy_names_the_extra_before_starting_blender(tmp_path, monkeypatch):
    scene, folder = small_scene(tmp_path)
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "bpy" else real(name, *a))
    monkeypatch.setattr("subprocess.run", lambda *a, **k: pytest.fail("the worker must not start"))
    with pytest.raises(MissingExtra, match=r"scenewright\[render\]"):
        render(scene, folder, draft=True)


@pytest.mark.blender
@pytest.mark.skipif(not has_bpy, reason="needs the render extra (bpy)")
def test_draft_render_shows_every_object_in_its_index_pass(tmp_path):
    scene, folder = small_scene(tmp_path)
    paths = render(scene, folder, draft=True, keep_all=True)
    assert paths[0].name == f"{render_info(folder)['best']}.png"
    assert sorted(p.name for p in paths) == sorted(f"{v}.png" for v in VIEWS)
    info = json.loads((folder.renders / "renders.json").read_text())
    assert info["missing"] == []
    best = info["visible"][info["best"]]
    assert set(best) == {o.id for o in scene.objects}
    assert all(pixels > 0 for pixels in best.values()), best
    from PIL import Image

    image = np.asarray(Image.open(best_render(folder)).convert("RGB"))
    assert image.shape == (*PREVIEWS["draft"].resolution[::-1], 3)
    assert image.std() > 5  # a picture, not a flat fill


@pytest.mark.blender
@pytest.mark.skipif(not has_bpy, reason="needs the render extra (bpy)")
def test_the_view_choice_passes_over_a_view_where_a_big_object_hides_a_small_one(tmp_path):
    # A tall, wide screen stands in front (−Y) of a crate: from the front and from the front-left
    # the screen hides it; from the right both stand side by side. The worker's index passes
    # must see that, and the choice must take the view that shows both.
    scene, folder = box_folder(
        tmp_path,
        Scene(
            text="a crate behind a screen",
            objects=[
                SceneObject(id="screen_1", name="screen", position=Vec3(x=0, y=-0.5, z=1.5), size=Vec3(x=4, y=0.4, z=3)),
                SceneObject(id="crate_1", name="crate", position=Vec3(x=0, y=0.5, z=0.25), size=Vec3(x=0.5, y=0.5, z=0.5)),
            ],
        ),
    )
    render(scene, folder, draft=True)
    info = render_info(folder)
    assert info["best"] == "right", info["visible"]
    assert info["visible"]["front"]["crate_1"] == 0 and info["visible"]["right"]["crate_1"] > 0
    assert all(info["visible"][view]["screen_1"] > 0 for view in VIEWS)


@pytest.mark.blender
@pytest.mark.skipif(not has_bpy, reason="needs the render extra (bpy)")
def test_a_blender_failure_becomes_a_backend_error_with_its_stderr(tmp_path):
    from scenewright.errors import BackendError

    scene, folder = small_scene(tmp_path)
    # A header that passes the check before Blender starts, over a body Blender cannot read.
    folder.glb.write_bytes(b"glTF" + struct.pack("<II", 2, 24) + b"\x00" * 12)
    with pytest.raises(BackendError, match="Blender render failed") as info:
        render(scene, folder, draft=True)
    assert "Traceback" in str(info.value) or "Error" in str(info.value)


def _gone(pid: int) -> bool:
    """Whether the process has ended (a zombie nobody reaped has ended too)."""
    try:
        with open(f"/proc/{pid}/stat") as fh:
            return fh.read().rsplit(")", 1)[1].split()[0] in ("Z", "X")
    except FileNotFoundError:
        return True


def _wait_gone(pid: int, seconds: float = 30.0) -> bool:
    deadline = time.monotonic() + seconds
    while not _gone(pid) and time.monotonic() < deadline:
        time.sleep(0.05)
    return _gone(pid)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the kernel's parent-death signal is Linux's")
def test_a_worker_dies_with_the_process_that_started_it_even_by_sigkill(tmp_path):
    parent_code = (
        "import sys, time; from pathlib import Path; from scenewright.render import start_worker\n"
        "w = start_worker([sys.executable, '-c', 'import time; time.sleep(600)'], Path(sys.argv[1]))\n"
        "print(w.pid, flush=True); time.sleep(600)\n"
    )
    env = {**os.environ, "PYTHONPATH": str(Path(scenewright.__file__).parents[1])}
    parent = subprocess.Popen([sys.executable, "-c", parent_code, str(tmp_path)], stdout=subprocess.PIPE, text=True, env=env)
    try:
        worker = int(parent.stdout.readline())
        assert not _gone(worker)
        parent.send_signal(signal.SIGKILL)  # no cleanup of its own can run
        parent.wait()
        assert _wait_gone(worker), "the worker outlived its parent"
    finally:
        parent.kill()
        parent.wait()
        parent.stdout.close()


@pytest.mark.blender
@pytest.mark.skipif(not has_bpy, reason="needs the render extra (bpy)")
def test_ctrl_c_during_a_render_exits_130_and_leaves_no_worker_and_no_files(tmp_path):
    _, folder = small_scene(tmp_path)
    before = sorted(p.relative_to(folder.root) for p in folder.root.rglob("*"))
    private = tmp_path / "tmp"
    private.mkdir()
    env = {**os.environ, "TMPDIR": str(private), "PYTHONPATH": str(Path(scenewright.__file__).parents[1])}
    command = [sys.executable, "-m", "scenewright", "render", str(folder.root), "--resolution", "640x360", "--samples", "64"]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, cwd=tmp_path)
    try:
        deadline = time.monotonic() + 120
        workers: list[int] = []
        while not workers and time.monotonic() < deadline:  # the worker names its job, in our TMPDIR
            assert process.poll() is None, process.communicate()
            workers = [int(p.name) for p in Path("/proc").iterdir() if p.name.isdigit() and _cmdline_has(p, str(private))]
            time.sleep(0.05)
        assert workers, "the render worker never started"
        time.sleep(1.0)  # into Blender's own work
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=60)
    finally:
        process.kill()
        process.wait()
    assert process.returncode == 130, err
    assert "interrupted; the previews were left as they were" in " ".join(err.split())
    assert all(_wait_gone(pid) for pid in workers)
    assert list(private.iterdir()) == []  # the worker's temporary folder is gone too
    assert sorted(p.relative_to(folder.root) for p in folder.root.rglob("*")) == before


def _cmdline_has(proc: Path, text: str) -> bool:
    try:
        return text in (proc / "cmdline").read_bytes().decode(errors="replace") and "render.worker" in (
            proc / "cmdline"
        ).read_bytes().decode(errors="replace")
    except OSError:
        return False
def test_render_refuses_a_corrupt_asset_or_scene_glb_before_starting_blender(tmp_path, monkeypatch):
    scene, folder = small_scene(tmp_path)
    monkeypatch.setattr("subprocess.run", lambda *a, **k: pytest.fail("the worker must not start"))
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: object())
    folder.assets.mkdir()
    (folder.assets / "table_1.glb").write_bytes(b"")
    scene.objects[0].asset = "assets/table_1.glb"
    with pytest.raises(InputError, match=r"table_1 \(its asset assets/table_1.glb is not a usable GLB.*--resume"):
        render(scene, folder, draft=True)
    scene.objects[0].asset = None
    folder.glb.write_bytes(folder.glb.read_bytes()[:100])
    with pytest.raises(InputError, match=r"scene.glb \(header declares .* \(truncated\?\)\)"):
        render(scene, folder, draft=True)


@pytest.mark.parametrize(
    ("resolution", "samples", "message"),
    [
        ((100000, 100000), 16, "more than max_render_pixels"),
        ((1280, 720), 10**6, "more than max_render_samples"),
        ((8, 8), 16, "at least 16x16"),
    ],
)
def test_render_size_and_samples_are_bounded(tmp_path, monkeypatch, resolution, samples, message):
    scene, folder = small_scene(tmp_path)
    monkeypatch.setattr("subprocess.run", lambda *a, **k: pytest.fail("the worker must not start"))
    with pytest.raises(InputError, match=message):
        render(scene, folder, resolution=resolution, samples=samples)


@pytest.mark.parametrize(
    "content",
    ["{not json", "[]", '{"images": {"front": "/etc/hostname"}, "best": "front"}',
     '{"images": {"front": "../../outside.png"}, "best": "front"}', '{"images": {}, "best": 3}',
     '{"images": {"front": "renders/front.png"}, "best": "front", "resolution": [1, "x"]}'],
)
def test_a_broken_or_tampered_renders_json_is_an_input_error(tmp_path, content):
    _, folder = small_scene(tmp_path)
    folder.renders.mkdir()
    (folder.renders / "renders.json").write_text(content)
    with pytest.raises(InputError, match="renders.json"):
        best_render(folder)


def test_projected_area_of_a_box_facing_the_camera():
    from scenewright.render.views import projected_area

    camera = np.eye(4)
    camera[:3, 3] = (0.0, 0.0, 10.0)  # looking down −Z at a 2 × 2 square 10 m away
    square = [[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (0.0, -0.001)]
    width, height = 1280, 720
    tan_w = 18.0 / 35.0
    pixels_per_metre = (width / 2) / (tan_w * 10.0)
    assert projected_area(square, camera, (width, height)) == pytest.approx((2 * pixels_per_metre) ** 2, rel=1e-3)
    camera[:3, 3] = (0.0, 0.0, -10.0)  # behind it
    assert projected_area(square, camera, (width, height)) == 0.0


def test_a_few_dozen_pixels_of_an_object_do_not_count_as_seeing_it():
    # The console shows 40 px of the 4000 its box covers in the front view: not seen there, so
    # the front view shows no more than the first view in the paper's order.
    visible = {"iso_left": {"ship": 90000, "console": 0}, "front": {"ship": 150000, "console": 40}}
    expected = {"iso_left": {"ship": 120000, "console": 3000}, "front": {"ship": 160000, "console": 4000}}
    assert best_view(visible) == "front"  # any pixel counted: the front "shows" both
    assert best_view(visible, expected, frame_pixels=1280 * 720) == "iso_left"
    # A speck: 6 px of a 1280 × 720 frame is not seen even when that is all its box covers.
    speck = {"iso_left": {"ship": 90000, "bolt": 0}, "front": {"ship": 90000, "bolt": 6}}
    assert best_view(speck, {"iso_left": {"bolt": 6}, "front": {"bolt": 6}}, frame_pixels=1280 * 720) == "iso_left"


def test_larger_and_more_related_objects_weigh_more_in_the_view_choice():
    from scenewright.render.views import object_weights

    weights = object_weights({"barn": (10, 8, 6), "cow": (2, 0.8, 1.5), "hen": (0.3, 0.3, 0.4)},
                             {"barn": 2, "cow": 1, "hen": 0})
    assert weights["barn"] > weights["cow"] > weights["hen"]
    # One view shows the barn and the cow, the other the hen and the cow: the barn matters more.
    visible = {"iso_left": {"barn": 0, "cow": 500, "hen": 80}, "front": {"barn": 9000, "cow": 400, "hen": 0}}
    assert best_view(visible) == "iso_left"  # unweighted: a tie on count, then evenness
    assert best_view(visible, weights=weights) == "front"


def test_preview_qualities_grow_from_draft_to_final_and_unknown_ones_are_refused(tmp_path):
    from scenewright.render import PREVIEWS

    draft, default, final = (PREVIEWS[k] for k in ("draft", "default", "final"))
    assert default.resolution == (1280, 720)
    for small, large in ((draft, default), (default, final)):
        assert small.resolution[0] < large.resolution[0] and small.samples <= large.samples
        assert all(a <= b for a, b in zip(small.bounces, large.bounces))
    scene, folder = small_scene(tmp_path)
    with pytest.raises(InputError, match="draft, default, final"):
        render(scene, folder, preview="ultra")


def test_each_preview_quality_reaches_the_worker_with_its_denoiser_settings(tmp_path, monkeypatch):
    import scenewright.render as rendering

    class Stop(Exception):
        pass

    jobs = []

    def worker(job_path, result_path, timeout):
        jobs.append(json.loads(Path(job_path).read_text()))
        raise Stop

    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: object())
    monkeypatch.setattr(rendering, "_run_worker", worker)
    scene, folder = small_scene(tmp_path)
    for preview in PREVIEWS:
        with pytest.raises(Stop):
            render(scene, folder, preview=preview)
    assert [(j["denoise_quality"], j["denoise_prefilter"], j["samples"]) for j in jobs] == [
        (q.denoise, q.prefilter, q.samples) for q in PREVIEWS.values()
    ]
    # Only the final quality denoises the albedo and normal guides as well.
    assert [j["denoise_prefilter"] for j in jobs] == ["FAST", "FAST", "ACCURATE"]


def test_generate_refuses_an_unknown_preview_before_it_starts(tmp_path, capsys):
    from scenewright.cli import main

    out = tmp_path / "s"
    assert main(["generate", "a chair", "--out", str(out), "--preview", "ultra"]) == 2
    assert "--preview 'ultra'" in capsys.readouterr().err and not out.exists()


@pytest.mark.blender
@pytest.mark.skipif(not has_bpy, reason="needs the render extra (bpy)")
def test_the_water_beyond_the_shore_is_rendered_blue_and_hides_nothing_above_it(tmp_path):
    from PIL import Image

    from scenewright.scene import Water

    scene, folder = box_folder(
        tmp_path,
        Scene(
            text="a crate on a quay and a buoy in the harbour",
            objects=[
                SceneObject(id="crate_1", name="crate", position=Vec3(x=-1, y=-1, z=0.25), size=Vec3(x=0.5, y=0.5, z=0.5)),
                SceneObject(id="buoy_1", name="buoy", position=Vec3(x=1, y=3, z=0.4), size=Vec3(x=0.8, y=0.8, z=0.8)),
            ],
        ),
    )
    scene.ground.water = Water(shore=1.0)
    render(scene, folder, draft=True, views=["front"])
    info = render_info(folder)
    assert all(pixels > 0 for pixels in info["visible"]["front"].values()), info["visible"]
    image = np.asarray(Image.open(folder.renders / "front.png").convert("RGB")).astype(float)
    water = image[image.shape[0] // 6 : image.shape[0] // 3, : image.shape[1] // 4]  # left, beyond the shore
    assert water[..., 2].mean() > water[..., 0].mean() + 10
