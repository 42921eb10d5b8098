"""Image-to-3D on Hunyuan3D-2.1 API servers, many at once.

The server (``api_server.py`` of Tencent-Hunyuan/Hunyuan3D-2.1) offers ``GET /health``,
``POST /send`` (a job, answered with ``{"uid"}``), ``GET /status/{uid}`` (``processing`` →
``texturing`` → ``completed`` with ``model_base64``, or ``error`` with ``message``) and
``POST /generate`` (the GLB itself; the only endpoint of older servers). It answers errors
with 404 and 200 alike, so every answer is judged by its body: a job only succeeds with
bytes that decode and form a complete GLB.

Two habits of that server shape the client. ``/status`` reports ``completed`` only once a
textured file exists, so untextured jobs (``texture = false``) go through ``/generate``. And
it keeps jobs as files it wipes when it starts, answering ``processing`` for a uid it has
never heard of; so while a job runs the client re-reads ``/health`` now and then, and a new
``worker_id`` means the server restarted and the job is gone.

Several servers share one job queue (:mod:`scenewright.backends.scheduler`): each has
``concurrency`` slots, a free slot takes the first waiting job that has not failed there, and
a failed job goes back to the queue for the next free server. A server that fails
``max_failures`` times in a row leaves the rotation until a later ``/health`` says it is back.
"""

from __future__ import annotations

import base64
import binascii
import logging
import time
from collections.abc import Callable, Sequence
from typing import Any

from scenewright.assets.normalise import check_glb
from scenewright.backends.scheduler import JobFailed, Server, ServerPool, server_urls
from scenewright.core.protocols import MeshRequest
from scenewright.errors import InputError, MissingExtra
from scenewright.settings import Settings

try:
    import httpx
except ImportError:  # the remote extra; Hunyuan3D.__init__ says how to install it
    httpx = None  # type: ignore[assignment]

log = logging.getLogger(__name__)

#: The server's request fields (api_models.GenerationRequest) with the values scenewright uses:
#: textured assets, as the paper renders them.
DEFAULT_PARAMS: dict[str, Any] = {
    "seed": 1234,
    "octree_resolution": 256,
    "num_inference_steps": 5,
    "guidance_scale": 5.0,
    "texture": True,
    "face_count": 40000,
    "remove_background": True,
}
RUNNING = ("processing", "texturing")


class Hunyuan3D(ServerPool):
    """MeshGenerator over one or more Hunyuan3D-2.1 API servers."""

    name = "hunyuan3d"
    label = "Hunyuan3D"

    def __init__(
        self,
        urls: Sequence[str],
        *,
        concurrency: int = 1,
        params: dict[str, Any] | None = None,
        timeout: float = 120.0,
        job_timeout: float = 1800.0,
        poll_interval: float = 2.0,
        health_interval: float = 60.0,
        reprobe_interval: float = 60.0,
        max_failures: int = 3,
        max_download_bytes: int = Settings.max_download_bytes,
    ):
        if httpx is None:
            raise MissingExtra("the Hunyuan3D mesh backend", "remote", "httpx")
        if not urls:
            raise InputError("hunyuan3d needs at least one server URL, e.g. hunyuan3d:http://gpu1:8081")
        unknown = set(params or {}) - set(DEFAULT_PARAMS)
        if unknown:
            raise InputError(
                f"unknown hunyuan3d parameters {sorted(unknown)}; valid ones: {', '.join(DEFAULT_PARAMS)}"
            )
        super().__init__(urls, concurrency=concurrency, max_failures=max_failures, reprobe_interval=reprobe_interval,
                         timeout=timeout, max_download_bytes=max_download_bytes)
        self.params = {**DEFAULT_PARAMS, **(params or {})}
        self.job_timeout = job_timeout
        self.poll_interval = poll_interval
        self.health_interval = health_interval

    @classmethod
    def from_spec(cls, argument: str, settings: Settings) -> Hunyuan3D:
        """``http://a:8081,http://b:8081``; tuning from ``settings.extra["hunyuan3d"]``."""
        urls = server_urls(argument, "hunyuan3d", "--meshes hunyuan3d:http://gpu1:8081,http://gpu2:8081")
        extra = dict(settings.extra.get("hunyuan3d", {}) or {})
        knobs = ("job_timeout", "poll_interval", "health_interval", "reprobe_interval", "max_failures")
        tuning = {k: extra.pop(k) for k in knobs if k in extra}
        return cls(
            urls, concurrency=settings.mesh_concurrency, params=extra, timeout=settings.timeout,
            max_download_bytes=settings.max_download_bytes, **tuning,
        )


    def _health(self, server: Server) -> tuple[str | None, str | None]:
        """(what is wrong with the server or None, its worker id)."""
        try:
            response = self._client.get(f"{server.url}/health")
            body = response.json()
        except httpx.HTTPError as exc:
            return f"unreachable ({_http_problem(exc)})", None
        except ValueError:
            return f"HTTP {response.status_code} with a body that is not JSON", None
        if not isinstance(body, dict) or body.get("status") not in ("healthy", "ok"):
            return f"HTTP {response.status_code}, answered {str(body)[:200]!r}", None
        worker_id = body.get("worker_id")
        return None, worker_id if isinstance(worker_id, str) else None

    # -- one attempt on one server --------------------------------------------------------

    def _run(self, server: Server, request: MeshRequest, progress: Callable[[str], None] | None) -> bytes:
        assert request.image is not None
        payload = {"image": base64.b64encode(request.image).decode("ascii"), **self.params}
        try:
            if server.jobs_api is not False and self.params["texture"]:
                uid = self._send(server, payload)
                if uid is not None:
                    return self._poll(server, uid, request, progress)
            return self._generate_direct(server, payload)
        except httpx.HTTPError as exc:
            raise JobFailed(f"connection failed ({_http_problem(exc)})") from None

    def _send(self, server: Server, payload: dict[str, Any]) -> str | None:
        """The job's uid, or None when the server has no job endpoints (so /generate is used)."""
        response = self._client.post(f"{server.url}/send", json=payload)
        body = _json_or_none(response)
        if response.status_code in (404, 405) and not (isinstance(body, dict) and "uid" in body):
            log.info("hunyuan3d %s has no /send; using /generate", server.url)
            server.jobs_api = False
            return None
        if not isinstance(body, dict) or not isinstance(body.get("uid"), str) or not body["uid"]:
            raise JobFailed(f"/send answered HTTP {response.status_code} without a job uid: {_excerpt(response)}")
        server.jobs_api = True
        return body["uid"]

    def _poll(
        self, server: Server, uid: str, request: MeshRequest, progress: Callable[[str], None] | None
    ) -> bytes:
        deadline = time.monotonic() + self.job_timeout
        next_health = time.monotonic() + self.health_interval
        worker = server.worker_id
        last = None
        while True:
            response = self._client.get(f"{server.url}/status/{uid}")
            body = _json_or_none(response)
            status = body.get("status") if isinstance(body, dict) else None
            if status != last and status is not None:
                last = status
                if progress:
                    progress(f"{request.id}: {status} on {server.url}")
            if status == "completed":
                return _decode_model(body.get("model_base64"))
            if status == "error":
                raise JobFailed(f"job {uid} ended in error: {body.get('message') or 'no message'}")
            if status not in RUNNING:
                raise JobFailed(f"/status answered HTTP {response.status_code}: {_excerpt(response)}")
            if time.monotonic() > deadline:
                raise JobFailed(f"job {uid} still {status} after {self.job_timeout:g} s")
            if time.monotonic() > next_health:
                next_health = time.monotonic() + self.health_interval
                self._check_same_worker(server, uid, worker)
            if self._cancelled.wait(self.poll_interval):
                raise JobFailed(f"job {uid} abandoned: the run was interrupted")

    def _check_same_worker(self, server: Server, uid: str, worker: str | None) -> None:
        """JobFailed when the server that took job ``uid`` (as ``worker``) is not the one running now."""
        problem, worker_id = self._health(server)
        if problem is not None:
            raise JobFailed(f"server stopped answering /health during job {uid}: {problem}")
        if worker is not None and worker_id != worker:
            with self._cond:
                server.worker_id = worker_id
            raise JobFailed(f"server restarted during job {uid} (worker {worker_id}), so the job is lost")

    def _generate_direct(self, server: Server, payload: dict[str, Any]) -> bytes:
        response = self._client.post(
            f"{server.url}/generate", json=payload, timeout=httpx.Timeout(self.job_timeout, connect=10.0)
        )
        problem = check_glb(response.content)
        if problem is None:
            return response.content
        raise JobFailed(f"/generate answered HTTP {response.status_code} without a GLB ({problem}): {_excerpt(response)}")


def _decode_model(encoded: Any) -> bytes:
    if not isinstance(encoded, str) or not encoded:
        raise JobFailed("job completed without model_base64")
    try:
        data = base64.b64decode(encoded, validate=True)
    except (binascii.Error, ValueError) as exc:
        raise JobFailed(f"model_base64 does not decode ({exc})") from None
    problem = check_glb(data)
    if problem:
        raise JobFailed(f"model_base64 is not a GLB: {problem}")
    return data


def _http_problem(exc: httpx.HTTPError) -> str:
    """What went wrong, in words: a deadline or size limit says so itself."""
    from scenewright.backends.http import DeadlineExceeded, ResponseTooLarge

    return str(exc) if isinstance(exc, (DeadlineExceeded, ResponseTooLarge)) else f"{type(exc).__name__}: {exc}"


def _json_or_none(response: httpx.Response) -> Any:
    try:
        return response.json()
    except ValueError:
        return None


def _excerpt(response: httpx.Response) -> str:
    text = response.text.strip().replace("\n", " ")
    return repr(text[:200]) if text else "(empty body)"
