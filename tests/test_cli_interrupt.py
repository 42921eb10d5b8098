"""Ctrl-C: exit 130 with how to go on, promptly, sending no job that had not started and
keeping every mesh that had finished."""

from __future__ import annotations

import io
import os
import signal
import subprocess
import sys
import time

from pathlib import Path

import trimesh
from PIL import Image

import scenewright

from scenewright.testing.hunyuan3d_standin import StandInServer
from scenewright.cli import main
from scenewright.folder import SceneFolder

TEXT = "a wooden table with a chair and a lamp"


class FirstJobOnly(StandInServer):
    """Finishes the first job at once; every later one takes ten minutes (until ``fast``)."""

    fast = False

    def _queue(self, image):
        self.delay = 0.1 if self.fast or not self.submitted else 600.0
        return super()._queue(image)


def _box() -> bytes:
    return trimesh.Scene(trimesh.creation.box(extents=(1.0, 1.0, 1.0))).export(file_type="glb")


def _picture(shade: int) -> bytes:
    out = io.BytesIO()
    Image.new("RGBA", (16, 16), (shade, 90, 40, 255)).save(out, format="PNG")
    return out.getvalue()


def _scene_waiting_for_meshes(root) -> SceneFolder:
    """A scene whose analysis is done, each object with its picture, and no asset yet."""
    assert main(["generate", TEXT, "--out", str(root), "--no-render"]) == 0
    folder = SceneFolder(root)
    scene = folder.load()
    for k, obj in enumerate(scene.objects):
        path = folder.object_image(obj.id)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(_picture(40 * k))
        folder.resolve(obj.asset).unlink()
        obj.image, obj.asset = folder.relative(path), None
    scene.done, scene.layout, scene.glb_sha256 = ["analyze"], None, None
    folder.glb.unlink()
    folder.save(scene)
    return folder


def test_ctrl_c_during_the_meshes_exits_130_at_once_keeping_what_finished(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    folder = _scene_waiting_for_meshes(tmp_path / "scene")
    ids = [o.id for o in folder.load().objects]
    assert len(ids) == 3
    (tmp_path / "scenewright.toml").write_text(
        f'cache_dir = "{(tmp_path / "cache").as_posix()}"\nmesh_concurrency = 1\n'
        "[extra.hunyuan3d]\npoll_interval = 0.05\n"
    )
    with FirstJobOnly(model=lambda image: _box()) as server:
        meshes = ["--meshes", f"hunyuan3d:{server.url}", "--no-render"]
        command = [sys.executable, "-m", "scenewright", "generate", "--resume", str(folder.root), *meshes]
        env = {**os.environ, "PYTHONPATH": str(Path(scenewright.__file__).parents[1])}  # this checkout's code
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        try:
            deadline = time.monotonic() + 120
            while (server.counts["send"] < 2 or server.counts["status"] < 3) and time.monotonic() < deadline:
                assert process.poll() is None, process.communicate()
                time.sleep(0.05)
            polls = server.counts["status"]
            process.send_signal(signal.SIGINT)
            # the second job would run ten minutes and job_timeout is half an hour: a run that
            # waited for either would be killed here, and fail
            _, err = process.communicate(timeout=60)
        finally:
            if process.poll() is None:
                process.kill()
                process.wait()
        assert process.returncode == 130, err
        assert f"interrupted; resume with `scenewright generate --resume {folder.root}`" in " ".join(err.split())
        assert server.counts["send"] == 2  # the third job was never sent
        assert server.counts["status"] <= polls + 5  # and the second was given up, not polled on
        scene = folder.load()
        assert scene.get(ids[0]).asset is not None and folder.resolve(scene.get(ids[0]).asset).is_file()
        assert [o.asset for o in scene.objects[1:]] == [None, None]
        assert not list(folder.root.rglob(".*.tmp")) and not (folder.root / ".scenewright.lock").exists()

        server.fast = True
        server.restart()  # drop the abandoned ten-minute job from its queue
        assert main(["generate", "--resume", str(folder.root), *meshes]) == 0
        assert server.counts["send"] == 4  # only the two unfinished ones again
        assert "export" in folder.load().done


def test_ctrl_c_prints_how_to_resume_and_exits_130(tmp_path, monkeypatch, capsys):
    from scenewright.layout import stage

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(stage, "arrange", interrupted)  # the pipeline's layout stage looks it up when it runs
    out = tmp_path / "scene"
    assert main(["generate", TEXT, "--out", str(out), "--no-render"]) == 130
    err = " ".join(capsys.readouterr().err.split())
    assert f"interrupted; resume with `scenewright generate --resume {out}`" in err
    monkeypatch.undo()
    assert main(["generate", "--resume", str(out), "--no-render"]) == 0
    assert os.path.isfile(out / "scene.glb")


def test_ctrl_c_while_object_images_are_drawn_sends_no_image_request_not_yet_started(tmp_path, monkeypatch):
    from scenewright.testing.fake_openai import CHAT, EDIT, GENERATE, FakeOpenAI, chat_reply, image_reply, object_item

    answers = {
        "scene_objects": {"objects": [object_item(f"crate_{i}", f"crate number {i}", (0.5, 0.5, 0.5), 2.0 * i)
                                      for i in range(1, 7)]},
        "redundant_images": {"redundant": []},
        "spatial_constraints": {"constraints": []},
    }
    monkeypatch.chdir(tmp_path)
    (tmp_path / "scenewright.toml").write_text(
        f'cache_dir = "{(tmp_path / "cache").as_posix()}"\nmax_retries = 0\ntimeout = 30\nimage_concurrency = 2\n'
    )
    with FakeOpenAI() as server:
        server.responders[CHAT] = lambda request: chat_reply(answers[request.schema_name])
        server.responders[GENERATE] = lambda request: image_reply()
        server.responders[EDIT] = lambda request: image_reply(delay=2.0)
        flags = ["--vlm", "openai:test-model", "--images", "openai:test-image", "--base-url", server.url, "--no-render"]
        command = [sys.executable, "-m", "scenewright", "generate", "six crates", "--out", "scene", *flags]
        env = {k: v for k, v in os.environ.items() if k != "OPENAI_API_KEY"}
        env["PYTHONPATH"] = str(Path(scenewright.__file__).parents[1])
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        try:
            deadline = time.monotonic() + 120
            while len(server.seen(EDIT)) < 2 and time.monotonic() < deadline:
                assert process.poll() is None, process.communicate()
                time.sleep(0.02)
            process.send_signal(signal.SIGINT)
            _, err = process.communicate(timeout=60)
        finally:
            if process.poll() is None:
                process.kill()
                process.wait()
        assert process.returncode == 130, err
        assert len(server.seen(EDIT)) == 2  # the two in flight; the other four were never asked for
        server.responders[EDIT] = lambda request: image_reply()
        assert main(["generate", "--resume", "scene", *flags]) == 0
        assert len(server.seen(EDIT)) == 2 + 4 + 1  # the two in flight landed in the cache; then the ground
