"""The asset stage: normalised files, sizes written back, cache, partial failure, resume."""

from __future__ import annotations

import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

from hunyuan_server import box_glb, png, servers
from scenewright.assets import generate_assets, load_meshes
from scenewright.assets.load import AssetMeshes
from scenewright.backends.hunyuan3d import Hunyuan3D
from scenewright.cache import RequestCache
from scenewright.errors import BackendError, InputError
from scenewright.folder import SceneFolder
from scenewright.backends.procedural_meshes import ProceduralMeshes
from scenewright.scene import Scene, SceneObject, Vec3


class Counting:
    """Wraps a MeshGenerator and records every request it is asked for."""

    def __init__(self, inner, fail=(), broken=()):
        self.inner, self.fail, self.broken = inner, set(fail), set(broken)
        self.name = inner.name
        self.params, self.concurrency = inner.params, inner.concurrency
        self.asked: list[str] = []

    def cancel(self):
        self.inner.cancel()

    def generate(self, requests, progress=None):
        self.asked += [r.id for r in requests]
        bad = [r.id for r in requests if r.id in self.fail]
        if bad:
            raise BackendError(f"{self.name} failed for {', '.join(bad)}")
        out = self.inner.generate(requests, progress)
        return {oid: (b"<html>nope</html>" if oid in self.broken else glb) for oid, glb in out.items()}


def room(tmp_path: Path, name="room") -> tuple[Scene, SceneFolder]:
    folder = SceneFolder(tmp_path / name)
    folder.create()
    scene = Scene(
        text="a sofa, a coffee table and a floor lamp",
        objects=[
            SceneObject(id="sofa_1", name="sofa", category="sofa", size=Vec3(x=2.0, y=0.9, z=0.85),
                        visual_description="a grey fabric sofa"),
            SceneObject(id="coffee_table_1", name="coffee table", category="coffee_table",
                        size=Vec3(x=1.1, y=0.6, z=0.45), visual_description="an oak coffee table"),
            SceneObject(id="floor_lamp_1", name="floor lamp", category="floor_lamp",
                        size=Vec3(x=0.4, y=0.4, z=1.6)),
        ],
    )
    folder.save(scene)
    return scene, folder


def test_assets_are_written_normalised_and_sizes_follow_the_mesh(tmp_path):
    scene, folder = room(tmp_path)
    heights = {o.id: o.size.z for o in scene.objects}
    notes: list[str] = []
    offered: list[list[str | None]] = []
    store = AssetMeshes()
    generate_assets(scene, folder, ProceduralMeshes(), RequestCache(tmp_path / "cache"), notes.append,
                    store=store, checkpoint=lambda: offered.append([o.asset for o in scene.objects]))
    meshes = load_meshes(scene, folder)
    assert set(meshes) == {o.id for o in scene.objects}
    for obj in scene.objects:
        assert obj.asset == f"assets/{obj.id}.glb" and folder.asset(obj.id).is_file()
        lo, hi = meshes[obj.id].bounds
        assert obj.size.z == heights[obj.id]
        assert hi - lo == pytest.approx(obj.size.tuple(), abs=1e-4)
        assert lo[2] == pytest.approx(0.0, abs=1e-5)
        assert (lo[:2] + hi[:2]) / 2 == pytest.approx((0.0, 0.0), abs=1e-4)
    assert set(heights) <= set(notes)
    # A checkpoint is offered as each asset lands, the document then naming it; the stage itself
    # saves nothing (the pipeline does).
    assert [sum(a is not None for a in assets) for assets in offered] == [1, 2, 3]
    assert folder.load().objects[0].asset is None
    assert scene.provenance[-1].stage == "assets"
    # The run's store holds every file parsed as written: the same meshes as a fresh parse.
    for oid, mesh in meshes.items():
        kept = store.parsed(folder.asset(oid)).mesh
        assert np.array_equal(kept.vertices, mesh.vertices) and np.array_equal(kept.faces, mesh.faces)


def test_a_rerun_builds_nothing_and_another_scene_reuses_the_cache(tmp_path):
    cache = RequestCache(tmp_path / "cache")
    scene, folder = room(tmp_path)
    meshes = Counting(ProceduralMeshes())
    generate_assets(scene, folder, meshes, cache)
    folder.save(scene)  # as the pipeline does after the stage
    assert len(meshes.asked) == 3
    generate_assets(folder.load(), folder, meshes, cache)
    assert len(meshes.asked) == 3
    other, other_folder = room(tmp_path, "copy")
    generate_assets(other, other_folder, meshes, cache)
    assert len(meshes.asked) == 3
    assert other_folder.asset("sofa_1").read_bytes() == folder.asset("sofa_1").read_bytes()
    # A deleted asset file is rebuilt.
    folder.asset("sofa_1").unlink()
    generate_assets(folder.load(), folder, meshes, cache)
    assert folder.asset("sofa_1").is_file() and meshes.asked[3:] == ["sofa_1"]


def test_failures_are_named_after_the_others_are_saved(tmp_path):
    scene, folder = room(tmp_path)
    cache = RequestCache(tmp_path / "cache")
    meshes = Counting(ProceduralMeshes(), fail={"sofa_1"}, broken={"floor_lamp_1"})
    with pytest.raises(BackendError) as info:
        generate_assets(scene, folder, meshes, cache)
    text = str(info.value)
    assert "sofa_1" in text and "floor_lamp_1" in text and "procedural" in text and "2 of 3" in text
    saved = scene
    assert saved.get("coffee_table_1").asset == "assets/coffee_table_1.glb"
    assert saved.get("sofa_1").asset is None and saved.get("floor_lamp_1").asset is None
    # The broken mesh was not cached: a healthy re-run asks for exactly the two failures.
    healthy = Counting(ProceduralMeshes())
    generate_assets(saved, folder, healthy, cache)
    assert sorted(healthy.asked) == ["floor_lamp_1", "sofa_1"]


def test_a_missing_object_image_is_an_input_error(tmp_path):
    scene, folder = room(tmp_path)
    scene.objects[0].image = "images/objects/sofa_1.png"
    with pytest.raises(InputError, match="sofa_1.*images/objects/sofa_1.png"):
        generate_assets(scene, folder, ProceduralMeshes(), RequestCache(None))


def test_load_meshes_skips_objects_without_assets_and_names_missing_files(tmp_path):
    scene, folder = room(tmp_path)
    assert load_meshes(scene, folder) == {}
    scene.objects[0].asset = "assets/sofa_1.glb"
    with pytest.raises(InputError, match="sofa_1.*missing"):
        load_meshes(scene, folder)


def imaged_scene(tmp_path: Path, n: int) -> tuple[Scene, SceneFolder]:
    folder = SceneFolder(tmp_path / "yard")
    folder.create()
    objects = []
    for i in range(1, n + 1):
        oid = f"crate_{i}"
        path = folder.object_image(oid)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(png((i * 30 % 256, 50, 50)))
        objects.append(SceneObject(id=oid, name="crate", size=Vec3(x=1, y=1, z=0.6), image=folder.relative(path)))
    scene = Scene(text="crates", objects=objects)
    folder.save(scene)
    return scene, folder


def test_hunyuan_assets_resume_without_resubmitting_finished_ones(tmp_path):
    scene, folder = imaged_scene(tmp_path, 5)
    cache = RequestCache(tmp_path / "cache")
    # A server that builds two assets and then dies.
    with servers({"fault": "die", "healthy_jobs": 2}) as (dying,):
        with pytest.raises(BackendError) as info:
            generate_assets(scene, folder, Hunyuan3D([dying.url], poll_interval=0.01), cache)
    assert "3 of 5 assets failed" in str(info.value) and "out of rotation" in str(info.value)
    finished = [o for o in scene.objects if o.asset]
    assert len(finished) == 2
    folder.save(scene)  # as the pipeline does when a stage stops
    final = folder.load()
    with servers({}) as (fresh,):
        generate_assets(final, folder, Hunyuan3D([fresh.url], poll_interval=0.01), cache)
        assert fresh.counts["send"] == 3
        finished_images = {folder.resolve(o.image).read_bytes() for o in finished}
        assert not finished_images & set(fresh.submitted)
    assert all(o.asset for o in final.objects)
    # Rescaled by height: the 0.8 × 1.2 × 0.6 (glTF) model at 0.6 m tall.
    assert final.get("crate_1").size.tuple() == pytest.approx((0.4, 0.3, 0.6))
    folder.save(final)
    # A deleted asset comes back from the cache (keyed by its image): no server is asked.
    folder.asset("crate_1").unlink()
    with servers({}) as (idle,):
        generate_assets(folder.load(), folder, Hunyuan3D([idle.url], poll_interval=0.01), cache)
        assert idle.counts["send"] == 0 and folder.asset("crate_1").is_file()


KILLED_RUN = textwrap.dedent(
    """
    import sys
    from scenewright.assets import generate_assets
    from scenewright.backends.hunyuan3d import Hunyuan3D
    from scenewright.cache import RequestCache
    from scenewright.folder import DocumentSaver, SceneFolder

    folder = SceneFolder(sys.argv[1])
    scene = folder.load()
    # A slow backend: every landed asset is worth a checkpoint (the pipeline's saver, interval 0).
    saver = DocumentSaver(folder, scene, interval=0.0)
    generate_assets(scene, folder, Hunyuan3D([sys.argv[2]], poll_interval=0.01), RequestCache(None),
                    checkpoint=saver.checkpoint)
    """
)


def test_a_killed_run_resumes_without_resubmitting_finished_assets(tmp_path):
    scene, folder = imaged_scene(tmp_path, 6)
    with servers({"delay": 0.4}) as (server,):
        run = subprocess.Popen([sys.executable, "-c", KILLED_RUN, str(folder.root), server.url])
        try:
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline and run.poll() is None:
                if sum(1 for o in folder.load().objects if o.asset) >= 2:
                    break
                time.sleep(0.02)
        finally:
            run.kill()
            run.wait()
        done = [o for o in folder.load().objects if o.asset]
        assert 2 <= len(done) < 6, "the run was meant to be killed half way"
        before = len(server.submitted)
        resumed = folder.load()
        generate_assets(resumed, folder, Hunyuan3D([server.url], poll_interval=0.01), RequestCache(None))
        resubmitted = server.submitted[before:]
        assert len(resubmitted) == 6 - len(done)
        assert not {folder.resolve(o.image).read_bytes() for o in done} & set(resubmitted)
    assert all(o.asset for o in resumed.objects)


def test_box_fixture_is_what_the_servers_return():
    # The resume test's size check relies on this model.
    from scenewright.assets.normalise import parse_glb

    assert parse_glb(box_glb()).extents == pytest.approx((0.8, 1.2, 0.6))
    assert np.isfinite(parse_glb(box_glb()).bounds).all()
