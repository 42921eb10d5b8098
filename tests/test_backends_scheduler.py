"""The shared job queue over mesh servers: fair hand-out, failed jobs re-queued, re-probing."""

from __future__ import annotations

import threading
import time

import pytest

from hunyuan_server import png, servers
from scenewright.core.protocols import MeshRequest
from scenewright.backends.scheduler import JobFailed, Server, ServerPool, server_urls
from scenewright.errors import BackendError, InputError
from scenewright.scene import Vec3


def request(i: int) -> MeshRequest:
    return MeshRequest(id=f"job_{i}", name="crate", category=None, description="", style="realistic",
                       size=Vec3(x=1, y=1, z=1), image=png((i, 1, 1)))


class Scripted(ServerPool):
    """Servers "a", "b", ... whose behaviour per (server, job) a test scripts."""

    name = "scripted"

    def __init__(self, urls, behave, health=None, **kw):
        super().__init__(urls, **kw)
        self.behave, self.health = behave, health or (lambda url: None)
        self.log: list[tuple[str, str]] = []
        self._log_lock = threading.Lock()

    def _run(self, server: Server, req: MeshRequest, progress) -> bytes:
        with self._log_lock:
            self.log.append((server.url, req.id))
        return self.behave(server.url, req.id)

    def _health(self, server: Server):
        return self.health(server.url), None


def wait_for(condition, seconds: float = 10.0) -> None:
    deadline = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < deadline, "timed out"
        time.sleep(0.005)


def test_a_server_whose_job_failed_takes_the_next_job_while_the_failed_one_waits_for_another():
    release_b, b_started = threading.Event(), threading.Event()
    ran_on_a: list[str] = []
    pool: Scripted

    def behave(url, job):
        if url == "a":
            ran_on_a.append(job)
            if job == "job_1":
                # fail only once another job runs on "b" and a third one waits in line
                wait_for(lambda: b_started.is_set() and len(pool._waiting) == 1)
                raise JobFailed("out of memory")
            return b"glb-" + job.encode()
        b_started.set()
        assert release_b.wait(10)
        return b"glb-" + job.encode()

    pool = Scripted(["a", "b"], behave)
    results: dict[str, bytes] = {}
    threads = [threading.Thread(target=lambda i=i: results.update(pool.generate([request(i)]))) for i in (1, 2, 3)]
    threads[0].start()
    wait_for(lambda: ran_on_a == ["job_1"])  # job_1 runs on "a"
    for t in threads[1:]:
        t.start()
    wait_for(lambda: len(ran_on_a) == 2)
    # "b" is still busy, yet "a" already works on the job that was waiting: it did not sit idle,
    # and the failed job_1 did not take that place on "a" again.
    assert ran_on_a[1] != "job_1" and not release_b.is_set()
    release_b.set()
    for t in threads:
        t.join(10)
    assert set(results) == {"job_1", "job_2", "job_3"}
    record = pool.provenance(["job_1", "job_2", "job_3"])
    assert record["built_by"]["job_1"] == "b" and record["built_by"][ran_on_a[1]] == "a"
    assert record["failed_attempts"] == [
        {"object": "job_1", "server": "a", "seconds": pytest.approx(0, abs=10), "error": "out of memory"}
    ]
    assert "out_of_rotation" not in record


def test_a_retired_server_is_probed_again_and_back_in_rotation():
    state = {"a_broken": True}

    def behave(url, job):
        if url == "a" and state["a_broken"]:
            raise JobFailed("CUDA error")
        return b"glb"

    probes: list[str] = []
    pool = Scripted(["a", "b"], behave, health=lambda url: probes.append(url), max_failures=1, reprobe_interval=0.05)
    pool.generate([request(1)])
    assert pool.servers[0].retired is not None and "CUDA error" in pool.servers[0].retired
    state["a_broken"] = False
    time.sleep(0.1)
    pool.generate([request(i) for i in range(2, 8)])
    assert pool.servers[0].retired is None and probes.count("a") == 2  # the first check, then the re-probe
    assert any(url == "a" for url, job in pool.log if job != "job_1")


def test_a_job_fails_only_after_every_server_in_rotation_failed_it_and_names_each():
    pool = Scripted(["a", "b"], lambda url, job: (_ for _ in ()).throw(JobFailed(f"broken {url}")), max_failures=5)
    with pytest.raises(BackendError) as info:
        pool.generate([request(1)])
    assert "a: broken a" in str(info.value) and "b: broken b" in str(info.value)
    assert [url for url, _ in pool.log] in (["a", "b"], ["b", "a"])


def test_cancel_ends_waiting_jobs_without_sending_them():
    started = threading.Event()

    def behave(url, job):
        started.set()
        time.sleep(1.0)  # long enough for the cancel to come while it runs, even on a loaded machine
        return b"glb"

    pool = Scripted(["a"], behave)
    outcome: dict[str, object] = {}

    def run(i):
        try:
            outcome[i] = pool.generate([request(i)])
        except BackendError as exc:
            outcome[i] = exc

    threads = [threading.Thread(target=run, args=(i,)) for i in (1, 2, 3)]
    for t in threads:
        t.start()
    assert started.wait(5)
    pool.cancel()
    for t in threads:
        t.join(5)
    assert len(pool.log) == 1  # only the job already running was ever sent
    assert sum(isinstance(v, BackendError) for v in outcome.values()) == 2


def test_stage_records_which_server_built_each_asset_and_what_failed(tmp_path):
    from scenewright.assets import generate_assets
    from scenewright.backends.hunyuan3d import Hunyuan3D
    from scenewright.cache import RequestCache
    from scenewright.folder import SceneFolder
    from scenewright.scene import Scene, SceneObject

    with servers({"fault": "error", "fault_jobs": 1}, {}) as (flaky, good):
        folder = SceneFolder(tmp_path)
        folder.object_images.mkdir(parents=True)
        objects = []
        for i in range(4):
            image = folder.object_image(f"crate_{i}")
            image.write_bytes(png((i * 40, 5, 5)))
            objects.append(SceneObject(id=image.stem, name="crate", size=Vec3(x=1, y=1, z=1),
                                       image=folder.relative(image)))
        scene = Scene(text="crates", objects=objects)
        generate_assets(scene, folder, Hunyuan3D([flaky.url, good.url], poll_interval=0.01), RequestCache(None))
    event = [e for e in scene.provenance if e.stage == "assets"][-1]
    assert set(event.data["built_by"]) == {o.id for o in objects}
    assert set(event.data["built_by"].values()) <= {flaky.url, good.url}
    (failed,) = event.data["failed_attempts"]
    assert failed["server"] == flaky.url and "CUDA out of memory" in failed["error"]
    assert event.data["built_by"][failed["object"]] == good.url
    # the record survives the document's round trip (the stage's caller saves it)
    folder.save(scene)
    again = SceneFolder(tmp_path).load()
    assert [e for e in again.provenance if e.stage == "assets"][-1].data["failed_attempts"] == [failed]


def test_server_urls_are_checked():
    assert server_urls("http://a:1, https://b:2", "x", "--meshes x:URL") == ["http://a:1", "https://b:2"]
    with pytest.raises(InputError, match="not an http"):
        server_urls("gpu1:8081", "x", "--meshes x:URL")
    with pytest.raises(InputError, match="at least one"):
        server_urls(" , ", "x", "--meshes x:URL")
