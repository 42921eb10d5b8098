"""The Meshy backend against a stand-in of its image-to-3D task API on 127.0.0.1."""

from __future__ import annotations

import base64
import json
import threading
import time
import uuid
from collections import Counter
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import pytest
import trimesh

from hunyuan_server import png
from scenewright.assets.normalise import parse_glb
from scenewright.backends import MeshRequest, create_backend
from scenewright.backends.meshy import Meshy
from scenewright.cache import RequestCache
from scenewright.errors import BackendError
from scenewright.scene import Vec3
from scenewright.settings import Settings

KEY = "msy-test-key"


class MeshyStandIn:
    """Submit → PENDING → IN_PROGRESS → SUCCEEDED after ``delay`` s; ``fail`` makes the first
    ``fail`` tasks end FAILED. Counts submissions (the paid calls)."""

    def __init__(self, glb: bytes, delay: float = 0.1, fail: int = 0):
        self.glb, self.delay, self.fail = glb, delay, fail
        self.tasks: dict[str, dict] = {}
        self.counts: Counter = Counter()
        self.images: list[bytes] = []
        stand_in = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args):
                return

            def reply(self, status, body, kind="application/json"):
                data = body if isinstance(body, bytes) else json.dumps(body).encode()
                self.send_response(status)
                self.send_header("Content-Type", kind)
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

            def authorised(self):
                if self.headers.get("Authorization") != f"Bearer {KEY}":
                    self.reply(401, {"message": "Invalid API key"})
                    return False
                return True

            def do_POST(self):
                body = json.loads(self.rfile.read(int(self.headers["Content-Length"])))
                if self.path != "/openapi/v1/image-to-3d" or not self.authorised():
                    return None if self.path == "/openapi/v1/image-to-3d" else self.reply(404, {"message": "no"})
                stand_in.counts["submit"] += 1
                head, _, data = body["image_url"].partition(",")
                assert head == "data:image/png;base64" and body["should_texture"] is True
                stand_in.images.append(base64.b64decode(data))
                task = uuid.uuid4().hex
                failed = stand_in.counts["submit"] <= stand_in.fail
                stand_in.tasks[task] = {"start": time.monotonic(), "failed": failed}
                self.reply(202, {"result": task})

            def do_GET(self):
                if self.path.startswith("/files/"):
                    stand_in.counts["download"] += 1
                    return self.reply(200, stand_in.glb, "model/gltf-binary")
                if not self.authorised():
                    return None
                stand_in.counts["poll"] += 1
                task_id = self.path.rsplit("/", 1)[-1]
                task = stand_in.tasks.get(task_id)
                if task is None:
                    return self.reply(404, {"message": "Task not found"})
                age = time.monotonic() - task["start"]
                if age < stand_in.delay / 2:
                    return self.reply(200, {"id": task_id, "status": "PENDING", "progress": 0})
                if age < stand_in.delay:
                    return self.reply(200, {"id": task_id, "status": "IN_PROGRESS", "progress": 50})
                if task["failed"]:
                    return self.reply(200, {"id": task_id, "status": "FAILED",
                                            "task_error": {"message": "Image could not be processed"}})
                url = f"http://127.0.0.1:{stand_in.port}/files/{task_id}.glb"
                self.reply(200, {"id": task_id, "status": "SUCCEEDED", "progress": 100, "model_urls": {"glb": url}})

        self.httpd = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.httpd.daemon_threads = True
        self.port = self.httpd.server_address[1]
        self.url = f"http://127.0.0.1:{self.port}"

    def __enter__(self):
        threading.Thread(target=self.httpd.serve_forever, args=(0.05,), daemon=True).start()
        return self

    def __exit__(self, *exc):
        self.httpd.shutdown()
        self.httpd.server_close()


def box_glb() -> bytes:
    return trimesh.Scene(trimesh.creation.box(extents=(0.8, 1.2, 0.6))).export(file_type="glb")


def requests(n: int) -> list[MeshRequest]:
    return [MeshRequest(id=f"lamp_{i}", name="lamp", category=None, description="", style="realistic",
                        size=Vec3(x=1, y=1, z=1), image=png((i * 40 % 256, 7, 7))) for i in range(1, n + 1)]


@pytest.fixture
def settings(tmp_path, monkeypatch):
    monkeypatch.setenv("MESHY_API_KEY", KEY)
    return Settings(cache_dir=tmp_path / "cache", mesh_concurrency=2,
                    extra={"meshy": {"poll_interval": 0.02}})


def test_submit_poll_download_one_paid_task_per_asset(settings):
    with MeshyStandIn(box_glb()) as api:
        backend = create_backend("meshes", f"meshy:{api.url}", settings)
        reqs = requests(3)
        seen: list[str] = []
        results = backend.generate(reqs, progress=seen.append)
        assert all(parse_glb(glb).extents == pytest.approx((0.8, 1.2, 0.6)) for glb in results.values())
        assert api.counts["submit"] == 3 and api.counts["download"] == 3
        assert sorted(api.images) == sorted(r.image for r in reqs)
        assert any("in_progress on Meshy" in line for line in seen)


def test_a_killed_run_resumes_its_paid_tasks_instead_of_submitting_again(settings):
    with MeshyStandIn(box_glb(), delay=2.0) as api:  # still building when the run is cancelled
        first = create_backend("meshes", f"meshy:{api.url}", settings)
        outcome: dict = {}
        thread = threading.Thread(target=lambda: outcome.setdefault("r", _try(first.generate, requests(1))))
        thread.start()
        while api.counts["submit"] < 1:
            time.sleep(0.01)
        first.cancel()  # the run is interrupted while Meshy builds the task
        thread.join(5)
        assert isinstance(outcome["r"], BackendError)
        resumed = create_backend("meshes", f"meshy:{api.url}", settings)
        assert len(resumed.generate(requests(1))) == 1
        assert api.counts["submit"] == 1  # the task paid for by the first run was polled, not bought again


def _try(function, *args):
    try:
        return function(*args)
    except BackendError as exc:
        return exc


def test_a_failed_task_is_submitted_once_more_and_recorded(settings):
    with MeshyStandIn(box_glb(), fail=1) as api:
        backend = Meshy(KEY, base_url=api.url, cache=RequestCache(settings.cache_dir), poll_interval=0.02)
        with pytest.raises(BackendError, match="Image could not be processed"):
            backend.generate(requests(1))
        # the failed task is forgotten: the next run pays for a new one, which succeeds
        assert len(backend.generate(requests(1))) == 1
        assert api.counts["submit"] == 2
        attempts = backend.provenance(["lamp_1"])
        assert attempts["built_by"] == {"lamp_1": api.url} and len(attempts["failed_attempts"]) == 1


def test_the_key_is_checked_before_any_call(tmp_path, monkeypatch):
    monkeypatch.delenv("MESHY_API_KEY", raising=False)
    with pytest.raises(BackendError, match="MESHY_API_KEY"):
        create_backend("meshes", "meshy", Settings(cache_dir=tmp_path))
    monkeypatch.setenv("MY_MESHY", "k")
    backend = create_backend("meshes", "meshy", Settings(cache_dir=tmp_path, extra={"meshy": {"api_key_env": "MY_MESHY"}}))
    assert backend.key == "k" and backend.servers[0].url == "https://api.meshy.ai"


def test_a_wrong_key_says_so(settings, monkeypatch):
    monkeypatch.setenv("MESHY_API_KEY", "wrong")
    with MeshyStandIn(box_glb()) as api:
        with pytest.raises(BackendError, match="refused the API key"):
            create_backend("meshes", f"meshy:{api.url}", settings).generate(requests(1))
        assert api.counts["submit"] == 0
