"""One shared job queue over several mesh servers, for every remote mesh backend.

Image-to-3D servers take minutes per asset and fail now and then (out of memory, a restart, a
dropped connection). Two rules keep every healthy server busy: jobs wait in one queue in the
order they came, and a free slot goes to the first waiting job that has not failed on that
server yet; a job that fails goes back to the head of the queue, where the next free server
takes it, instead of waiting for one particular server. A server leaves the rotation after
``max_failures`` failures in a row (a success resets the count) and is asked for its health
again every ``reprobe_interval`` seconds while out; when it answers well it is back.

Every attempt is recorded (server, outcome, seconds), so the asset stage can write which
server built which asset and which attempts failed, and why, into the scene's provenance.

A backend subclasses :class:`ServerPool` and supplies ``_run`` (one attempt of one job on
one server, raising :class:`JobFailed`) and ``_health``.
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Callable, Sequence
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass, field
from typing import Any

from scenewright.core.protocols import MeshRequest
from scenewright.errors import BackendError, InputError

log = logging.getLogger(__name__)

Progress = Callable[[str], None] | None


class JobFailed(Exception):
    """One attempt of one job on one server failed; the job may go to another server."""


@dataclass
class Server:
    url: str
    slots: int
    busy: int = 0
    #: Failures in a row; a success resets it.
    failures: int = 0
    #: Why the server left the rotation, or None while it is in it.
    retired: str | None = None
    #: When it left (monotonic seconds), for the re-probe.
    retired_at: float = 0.0
    #: A re-probe of its health is under way.
    probing: bool = False
    healthy: bool = False
    #: Whether it has /send and /status (None until the first job tells; Hunyuan3D only).
    jobs_api: bool | None = None
    #: The ``worker_id`` /health gave; a different one later means the server restarted.
    worker_id: str | None = None


@dataclass
class Attempt:
    """One try of one job: where, how long, and the error (None when it built the asset)."""

    server: str
    seconds: float
    error: str | None = None

    def as_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"server": self.server, "seconds": round(self.seconds, 3)}
        if self.error is not None:
            out["error"] = self.error
        return out


@dataclass
class _Job:
    request: MeshRequest
    #: server url → why it failed there.
    tried: dict[str, str] = field(default_factory=dict)


class ServerPool:
    """MeshGenerator scheduling over servers; subclasses say how to run a job and check health."""

    name = "pool"
    #: What the errors call the servers ("Hunyuan3D", "Gradio app", ...).
    label = "mesh"

    def __init__(
        self,
        urls: Sequence[str],
        *,
        concurrency: int = 1,
        max_failures: int = 3,
        reprobe_interval: float = 60.0,
        timeout: float = 120.0,
        max_download_bytes: int | None = None,
    ):
        if not urls:
            raise InputError(f"the {self.name} mesh backend needs at least one server URL")
        if concurrency < 1:
            raise InputError(f"mesh concurrency must be at least 1 job per server, got {concurrency}")
        if max_failures < 1:
            raise InputError(f"max_failures must be at least 1, got {max_failures}")
        self.servers = [Server(url=u.rstrip("/"), slots=concurrency) for u in urls]
        self.max_failures = max_failures
        self.reprobe_interval = reprobe_interval
        # One HTTP client for every server, bounded in time and size, with a connection for
        # each job slot (a job polls while the next one submits).
        self.timeout, self.max_download_bytes = timeout, max_download_bytes
        self._http = None
        self._cond = threading.Condition()
        self._health_lock = threading.Lock()
        self._cancelled = threading.Event()
        self._waiting: list[_Job] = []
        #: request id → every attempt, in order (kept across calls, read by the asset stage).
        self.attempts: dict[str, list[Attempt]] = {}
        #: Held around each job attempt, given the server's URL and its slots: a batch puts its
        #: limit shared by all workers here (scenewright.batch.limits); alone, nothing.
        self.job_gate: Callable[[str, int], AbstractContextManager[Any]] = lambda url, slots: nullcontext()

    # -- what subclasses supply ---------------------------------------------------------

    def _run(self, server: Server, request: MeshRequest, progress: Progress) -> bytes:
        """GLB bytes of one attempt; raises JobFailed."""
        raise NotImplementedError

    def _health(self, server: Server) -> tuple[str | None, str | None]:
        """(what is wrong with the server or None, an id of the running worker or None)."""
        raise NotImplementedError

    def _check_requests(self, requests: Sequence[MeshRequest]) -> None:
        """Refuse requests this backend cannot build at all: image-to-3D services need the
        object's image, so a run with no image backend fails before any job is sent."""
        imageless = [r.id for r in requests if r.image is None]
        if imageless:
            raise BackendError(
                f"{self.label} builds meshes from object images, and these objects have none: "
                f"{', '.join(imageless)}. Configure an image backend (e.g. --images openai:gpt-image-1) "
                "or use --meshes procedural"
            )

    # -- the MeshGenerator protocol -------------------------------------------------------

    @property
    def slots(self) -> int:
        """Jobs the servers in rotation can run at once."""
        return sum(s.slots for s in self.servers if s.retired is None) or 1

    #: The asset stage hands every request over at once (each waits in the shared queue), so
    #: a server that frees a slot always finds the next job waiting; the slots bound the work.
    concurrency = 1 << 16

    @property
    def _client(self):
        """The servers' HTTP client, made on first use (so a pool that never calls out, as in
        the scheduler's own tests, needs no HTTP library)."""
        if self._http is None:
            import httpx

            from scenewright.backends.http import limited_client
            from scenewright.settings import Settings

            self._http = limited_client(
                self.timeout, self.max_download_bytes or Settings.max_download_bytes,
                limits=httpx.Limits(max_connections=sum(s.slots for s in self.servers) * 2 + 4),
            )
        return self._http

    def close(self) -> None:
        if self._http is not None:
            self._http.close()

    def cancel(self) -> None:
        """Stop for good (the run was interrupted): waiting jobs are never sent, and running
        ones stop being polled, so their threads end within a poll interval."""
        self._cancelled.set()
        with self._cond:
            self._cond.notify_all()

    def generate(self, requests: Sequence[MeshRequest], progress: Progress = None) -> dict[str, bytes]:
        self._check_requests(requests)
        self._check_health()
        if len(requests) == 1:
            outcomes = [self._build(requests[0], progress)]
        else:
            from concurrent.futures import ThreadPoolExecutor

            with ThreadPoolExecutor(max_workers=len(requests), thread_name_prefix=self.name) as pool:
                outcomes = list(pool.map(lambda r: self._build(r, progress), requests))
        results: dict[str, bytes] = {}
        errors: dict[str, str] = {}
        for request, outcome in zip(requests, outcomes):
            if isinstance(outcome, bytes):
                results[request.id] = outcome
            else:
                errors[request.id] = outcome
        if errors:
            details = "; ".join(f"{oid}: {why}" for oid, why in errors.items())
            raise BackendError(f"{self.label} could not build {', '.join(errors)} ({details}){self._retired_note()}")
        return results

    def provenance(self, ids: Sequence[str]) -> dict[str, Any]:
        """For the scene's record: which server built each asset, every failed attempt and why,
        and the servers out of rotation."""
        with self._cond:
            built_by: dict[str, str] = {}
            failed: list[dict[str, Any]] = []
            for oid in ids:
                for attempt in self.attempts.get(oid, []):
                    if attempt.error is None:
                        built_by[oid] = attempt.server
                    else:
                        failed.append({"object": oid, **attempt.as_dict()})
            out: dict[str, Any] = {"built_by": built_by}
            if failed:
                out["failed_attempts"] = failed
            retired = {s.url: s.retired for s in self.servers if s.retired is not None}
            if retired:
                out["out_of_rotation"] = retired
            return out

    # -- scheduling -----------------------------------------------------------------------

    def _build(self, request: MeshRequest, progress: Progress) -> bytes | str:
        """The GLB, or why no server could build it (every server in rotation tried once)."""
        job = _Job(request)
        with self._cond:
            self._waiting.append(job)
        while (server := self._acquire(job)) is not None:
            started = time.monotonic()
            failure: str | None = "interrupted by an unexpected error"
            try:
                with self.job_gate(server.url, server.slots):
                    glb = self._run(server, request, progress)
                failure = None
                return glb
            except JobFailed as exc:
                failure = job.tried[server.url] = str(exc)
                log.warning("%s %s failed %s: %s", self.name, server.url, request.id, exc)
            finally:
                self._release(server, job, failure, time.monotonic() - started)
        if not job.tried:
            return f"no {self.label} server is in rotation"
        return "; ".join(f"{url}: {why}" for url, why in job.tried.items())

    def _acquire(self, job: _Job) -> Server | None:
        """A free slot for ``job``: the job waits in line, and a free server goes to the first
        waiting job that has not failed on it. None when the job has no server left to try."""
        with self._cond:
            while True:
                if self._cancelled.is_set():
                    self._drop(job)
                    return None
                self._reprobe_due()
                untried = [s for s in self.servers if s.retired is None and s.url not in job.tried]
                if not untried:
                    self._drop(job)
                    return None
                for server in sorted(untried, key=lambda s: (s.busy / s.slots, s.failures)):
                    if server.busy < server.slots and self._first_for(server) is job:
                        server.busy += 1
                        self._drop(job)
                        return server
                self._cond.wait(timeout=self._next_reprobe())

    def _first_for(self, server: Server) -> _Job | None:
        return next((j for j in self._waiting if server.url not in j.tried), None)

    def _drop(self, job: _Job) -> None:
        if job in self._waiting:
            self._waiting.remove(job)
            self._cond.notify_all()

    def _release(self, server: Server, job: _Job, failure: str | None, seconds: float) -> None:
        with self._cond:
            server.busy -= 1
            self.attempts.setdefault(job.request.id, []).append(Attempt(server.url, seconds, failure))
            if failure is None:
                server.failures = 0
            else:
                server.failures += 1
                if server.failures >= self.max_failures and server.retired is None:
                    self._retire(server, f"{server.failures} failures in a row, last: {failure}")
                # Back to the head of the line: the next free server it has not failed on takes it.
                self._waiting.insert(0, job)
            self._cond.notify_all()

    def _retire(self, server: Server, reason: str) -> None:
        server.retired = reason
        server.retired_at = time.monotonic()
        log.warning("%s server %s taken out of rotation: %s", self.name, server.url, reason)

    def _retired_note(self) -> str:
        out = [f"{s.url} ({s.retired})" for s in self.servers if s.retired is not None]
        return f"; servers out of rotation: {'; '.join(out)}" if out else ""

    def _next_reprobe(self) -> float | None:
        """Seconds until the next retired server is due for a health check (None: never)."""
        due = [s.retired_at + self.reprobe_interval for s in self.servers if s.retired is not None and not s.probing]
        due = [t for t in due if t != float("inf")]
        return max(0.01, min(due) - time.monotonic()) if due else None

    def _reprobe_due(self) -> None:
        """Start a health check of each retired server whose re-probe time has come (called with
        the lock held; the check itself runs on its own thread, so no job waits for it)."""
        now = time.monotonic()
        for server in self.servers:
            if server.retired is not None and not server.probing and now >= server.retired_at + self.reprobe_interval:
                server.probing = True
                threading.Thread(target=self._reprobe, args=(server,), daemon=True,
                                 name=f"{self.name}-reprobe").start()

    def _reprobe(self, server: Server) -> None:
        problem, worker_id = self._health(server)
        with self._cond:
            server.probing = False
            if problem is None:
                log.info("%s server %s is healthy again; back in rotation", self.name, server.url)
                server.retired, server.failures, server.healthy, server.worker_id = None, 0, True, worker_id
            else:
                server.retired_at = time.monotonic()
            self._cond.notify_all()

    def _check_health(self) -> None:
        """Ask each server not yet seen for its health once; one that fails leaves the rotation.
        A retired server due for its re-probe is asked again here, so a new batch starts with it."""
        with self._health_lock:
            now = time.monotonic()
            for server in self.servers:
                if server.retired is not None and not server.probing and now >= server.retired_at + self.reprobe_interval:
                    with self._cond:
                        server.probing = True
                    self._reprobe(server)
                if server.healthy or server.retired is not None:
                    continue
                problem, worker_id = self._health(server)
                with self._cond:
                    if problem is None:
                        server.healthy = True
                        server.worker_id = worker_id
                    else:
                        self._retire(server, f"health check failed: {problem}")
                    self._cond.notify_all()
            if all(s.retired is not None for s in self.servers):
                raise BackendError(f"no {self.label} server is usable{self._retired_note()}")


def server_urls(argument: str, backend: str, example: str) -> list[str]:
    """The comma-separated http(s) URLs of a ``--meshes BACKEND:URL,URL`` spec, checked."""
    urls = [u.strip() for u in argument.split(",") if u.strip()]
    if not urls:
        raise InputError(f"{backend} needs at least one server URL; write {example}")
    for url in urls:
        if not url.startswith(("http://", "https://")):
            raise InputError(f"{backend} server {url!r} is not an http(s) URL; write {example}")
    return urls
