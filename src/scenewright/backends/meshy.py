"""Image-to-3D on Meshy's hosted queue API: submit a task, poll it, download the GLB.

``POST {base}/openapi/v1/image-to-3d`` with the image as a data URI answers ``{"result":
task_id}``; ``GET {base}/openapi/v1/image-to-3d/{id}`` reports ``status`` (``PENDING``,
``IN_PROGRESS``, ``SUCCEEDED`` with ``model_urls.glb``, ``FAILED`` or ``CANCELED`` with
``task_error.message``) and ``progress``. The key is a bearer token from an environment
variable (``MESHY_API_KEY`` unless the settings name another).

Each submission is paid for, so the task id is written to the request cache the moment it is
known: a run killed while a task was being built finds the id again and polls that task
instead of paying for a second one. Tasks run ``mesh_concurrency`` at a time through the same
scheduler as the self-hosted backends, so failures and retries are recorded alike.
"""

from __future__ import annotations

import base64
import logging
import os
from collections.abc import Callable
from typing import Any

from scenewright.assets.normalise import check_glb
from scenewright.core.protocols import MeshRequest
from scenewright.backends.scheduler import JobFailed, Server, ServerPool
from scenewright.backends.structured import image_mime
from scenewright.cache import RequestCache, request_key
from scenewright.errors import BackendError, InputError, MissingExtra
from scenewright.settings import Settings

try:
    import httpx
except ImportError:  # the remote extra; Meshy.__init__ says how to install it
    httpx = None  # type: ignore[assignment]

log = logging.getLogger(__name__)

DEFAULT_BASE_URL = "https://api.meshy.ai"
DEFAULT_KEY_ENV = "MESHY_API_KEY"
ROUTE = "/openapi/v1/image-to-3d"
#: Task fields scenewright sends (Meshy's own defaults for the rest): a textured mesh.
DEFAULT_PARAMS: dict[str, Any] = {"should_texture": True, "enable_pbr": False}
RUNNING = ("PENDING", "IN_PROGRESS")
TASKS = "meshy-tasks"


class Meshy(ServerPool):
    """MeshGenerator over Meshy's image-to-3D task API."""

    name = "meshy"
    label = "Meshy"

    def __init__(
        self,
        key: str,
        *,
        base_url: str = DEFAULT_BASE_URL,
        params: dict[str, Any] | None = None,
        concurrency: int = 1,
        cache: RequestCache | None = None,
        timeout: float = 120.0,
        job_timeout: float = 1800.0,
        poll_interval: float = 5.0,
        max_download_bytes: int = Settings.max_download_bytes,
    ):
        if httpx is None:
            raise MissingExtra("the Meshy mesh backend", "remote", "httpx")
        # One "server"; a failure there fails the job (no other server to move to), and after
        # three in a row (a spent quota, an outage) the API rests for a minute before the
        # next task is sent, instead of being asked for every asset.
        super().__init__([base_url], concurrency=concurrency, max_failures=3, reprobe_interval=60.0, timeout=timeout,
                         max_download_bytes=max_download_bytes)
        self.key = key
        self.params = {**DEFAULT_PARAMS, **(params or {})}
        self.tasks = cache or RequestCache(None)
        self.job_timeout = job_timeout
        self.poll_interval = poll_interval

    @classmethod
    def from_spec(cls, argument: str, settings: Settings) -> Meshy:
        """``meshy`` or ``meshy:BASE_URL``; ``settings.extra["meshy"]`` holds ``api_key_env``,
        task fields and tuning."""
        base_url = argument or DEFAULT_BASE_URL
        if not base_url.startswith(("http://", "https://")):
            raise InputError(f"meshy base URL {base_url!r} is not an http(s) URL; write --meshes meshy "
                             "or --meshes meshy:https://api.meshy.ai")
        extra = dict(settings.extra.get("meshy", {}) or {})
        key_env = str(extra.pop("api_key_env", DEFAULT_KEY_ENV))
        tuning = {k: extra.pop(k) for k in ("job_timeout", "poll_interval") if k in extra}
        key = os.environ.get(key_env)
        if not key:
            raise BackendError(
                f"the meshy backend needs an API key: set the environment variable {key_env} "
                "(or name another under [extra.meshy] api_key_env)"
            )
        return cls(key, base_url=base_url.rstrip("/"), params=extra, concurrency=settings.mesh_concurrency,
                   cache=RequestCache(settings.cache_dir), timeout=settings.timeout,
                   max_download_bytes=settings.max_download_bytes, **tuning)


    def _health(self, server: Server) -> tuple[str | None, str | None]:
        return None, None  # a hosted API: the first task says whether the key and the service work

    def _headers(self) -> dict[str, str]:
        return {"Authorization": f"Bearer {self.key}"}

    def _run(self, server: Server, request: MeshRequest, progress: Callable[[str], None] | None) -> bytes:
        assert request.image is not None
        task_key = request_key("meshy-task", server.url, self.params, request.image)
        try:
            known = self.tasks.get(TASKS, task_key)
            task_id = known.decode() if known else self._submit(server, request.image)
            if known:
                log.info("meshy: %s resumes task %s (already paid for)", request.id, task_id)
            else:
                self.tasks.put(TASKS, task_key, task_id.encode())
            glb = self._poll(server, task_id, request, progress, task_key)
        except httpx.HTTPError as exc:
            raise JobFailed(f"connection failed ({type(exc).__name__}: {exc})") from None
        return glb

    def _submit(self, server: Server, image: bytes) -> str:
        uri = f"data:{image_mime(image)};base64,{base64.b64encode(image).decode('ascii')}"
        response = self._client.post(f"{server.url}{ROUTE}", json={"image_url": uri, **self.params},
                                     headers=self._headers())
        body = _json(response)
        if response.status_code in (401, 403):
            raise JobFailed(f"Meshy refused the API key (HTTP {response.status_code}); check {DEFAULT_KEY_ENV} "
                            "or the variable [extra.meshy] api_key_env names")
        if response.status_code not in (200, 202) or not isinstance(body, dict) or not body.get("result"):
            raise JobFailed(f"submit answered HTTP {response.status_code}: {_message(body, response)}")
        return str(body["result"])

    def _poll(self, server: Server, task_id: str, request: MeshRequest,
              progress: Callable[[str], None] | None, task_key: str) -> bytes:
        import time

        deadline = time.monotonic() + self.job_timeout
        last = None
        while True:
            response = self._client.get(f"{server.url}{ROUTE}/{task_id}", headers=self._headers())
            body = _json(response)
            if response.status_code == 404:
                self.tasks.put(TASKS, task_key, b"")  # forget it: the next attempt submits afresh
                raise JobFailed(f"task {task_id} is unknown to Meshy (expired?)")
            status = body.get("status") if isinstance(body, dict) else None
            if status != last and status is not None:
                last = status
                if progress:
                    progress(f"{request.id}: {status.lower()} on Meshy (task {task_id})")
            if status == "SUCCEEDED":
                return self._download(body, task_id)
            if status in ("FAILED", "CANCELED", "EXPIRED"):
                self.tasks.put(TASKS, task_key, b"")
                error = (body.get("task_error") or {}).get("message") if isinstance(body.get("task_error"), dict) else None
                raise JobFailed(f"task {task_id} {status.lower()}: {error or 'no message'}")
            if status not in RUNNING:
                raise JobFailed(f"task {task_id} answered HTTP {response.status_code}: {_message(body, response)}")
            if time.monotonic() > deadline:
                raise JobFailed(f"task {task_id} still {status} after {self.job_timeout:g} s")
            if self._cancelled.wait(self.poll_interval):
                raise JobFailed(f"task {task_id} abandoned: the run was interrupted (a re-run picks it up)")

    def _download(self, body: dict[str, Any], task_id: str) -> bytes:
        urls = body.get("model_urls")
        url = urls.get("glb") if isinstance(urls, dict) else None
        if not isinstance(url, str) or not url.startswith(("http://", "https://")):
            raise JobFailed(f"task {task_id} succeeded without a GLB URL in model_urls")
        response = self._client.get(url)
        problem = check_glb(response.content) if response.status_code == 200 else f"HTTP {response.status_code}"
        if problem:
            raise JobFailed(f"the GLB of task {task_id} cannot be used: {problem}")
        return response.content


def _json(response: httpx.Response) -> Any:
    try:
        return response.json()
    except ValueError:
        return None


def _message(body: Any, response: httpx.Response) -> str:
    if isinstance(body, dict) and body.get("message"):
        return str(body["message"])[:300]
    text = response.text.strip().replace("\n", " ")
    return repr(text[:200]) if text else "(empty body)"
