"""One set of limits on remote requests for a whole batch, however many workers run it.

Each scene's backends keep their own limits (``image_concurrency`` threads, ``mesh_concurrency``
jobs per Hunyuan3D server), which multiply with the number of workers; a provider's limit does
not. So every request to a remote server first passes one set of counters shared by all
workers, keyed by the server (its URL):

- **in flight**: at most ``concurrency`` requests to an OpenAI-compatible server, and at most
  ``mesh_concurrency`` jobs on each Hunyuan3D server (a job holds its place from ``/send``
  until its mesh arrives);
- **per minute** (when ``per_minute`` is set): request starts to one server are spaced at
  least ``60 / per_minute`` seconds apart. Even spacing rather than bursts of ``per_minute``:
  providers often enforce a per-minute limit over shorter periods too (1,000 a second for
  60,000 a minute), so a burst within the minute can be refused.

Where the counters live:

- :class:`FileSlots` for workers on one machine (the process pool, Ray in local mode): slot
  *i* is an exclusive ``flock`` on the file ``<folder>/<server>/<i>.lock``, and the next free
  start time is a small file read and written under a ``flock``. The kernel drops a lock when
  its process dies, so a killed worker can never leak a slot.
- :class:`ActorSlots` for a Ray cluster: the same counters in one Ray actor every task asks.

Both are small picklable values, handed to each worker with its scene in a :class:`Limits`.
Requests are limited where the backends make them: the SDK call of the OpenAI-compatible
backends (so the SDK's own retries keep their slot; the count is of requests, not HTTP
connections) and each Hunyuan3D job attempt.
"""

from __future__ import annotations

import hashlib
import os
import random
import re
import time
from collections.abc import Callable, Iterator
from contextlib import AbstractContextManager, contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

#: Seconds between attempts to take a slot (with jitter, so waiters do not move in step).
POLL = 0.02
MINUTE = 60.0


class Slots(Protocol):
    def slot(self, key: str, limit: int) -> AbstractContextManager[Any]:
        """A context manager holding one of the ``limit`` slots of ``key`` while it is open."""

    def reserve(self, key: str, interval: float, horizon: float) -> float:
        """Book the next start of a request to ``key``; returns the seconds to wait for it."""


def _key_folder(key: str) -> str:
    readable = re.sub(r"[^A-Za-z0-9]+", "_", key).strip("_")[:40]
    return f"{readable}-{hashlib.sha1(key.encode()).hexdigest()[:8]}"


def book(next_free: float, now: float, interval: float, horizon: float) -> tuple[float, float]:
    """(seconds to wait, the next free start) for a request booked at ``now``.

    Starts are ``interval`` apart. A booked time more than ``horizon`` ahead cannot come from
    the waiters there can be (each holds a slot), so it is a stale value (a clock set back) and
    is ignored rather than waited for.
    """
    if next_free > now + horizon:
        next_free = now
    start = max(now, next_free)
    return start - now, start + interval


def _check_limit(limit: int) -> None:
    if limit < 1:
        raise ValueError(f"a limit of {limit} slots admits no request; it must be at least 1")


@dataclass(frozen=True)
class FileSlots:
    """Slots as ``flock``-ed files in ``folder``: shared by every process of one machine."""

    folder: Path
    poll: float = POLL

    @contextmanager
    def slot(self, key: str, limit: int) -> Iterator[int]:
        import fcntl

        _check_limit(limit)
        folder = Path(self.folder) / _key_folder(key)
        folder.mkdir(parents=True, exist_ok=True)
        while True:
            start = random.randrange(limit)
            for k in range(limit):
                index = (start + k) % limit
                fd = os.open(folder / f"{index}.lock", os.O_RDWR | os.O_CREAT, 0o644)
                try:
                    fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
                except BlockingIOError:
                    os.close(fd)
                    continue
                try:
                    yield index
                    return
                finally:
                    fcntl.flock(fd, fcntl.LOCK_UN)
                    os.close(fd)
            time.sleep(self.poll * (0.5 + random.random()))

    def reserve(self, key: str, interval: float, horizon: float) -> float:
        import fcntl

        folder = Path(self.folder) / _key_folder(key)
        folder.mkdir(parents=True, exist_ok=True)
        fd = os.open(folder / "next-start", os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX)
            raw = os.read(fd, 64).decode("ascii", "replace").strip()
            try:
                next_free = float(raw) if raw else 0.0
            except ValueError:  # a torn or foreign file: start afresh
                next_free = 0.0
            wait, following = book(next_free, time.time(), interval, horizon)
            os.lseek(fd, 0, os.SEEK_SET)
            os.ftruncate(fd, 0)
            os.write(fd, repr(following).encode("ascii"))
            return wait
        finally:
            os.close(fd)  # closing drops the flock


class SlotTable:
    """The bookkeeping of :class:`ActorSlots`, run inside one Ray actor (plain Python here)."""

    def __init__(self) -> None:
        self.held: dict[str, set[str]] = {}
        self.next_free: dict[str, float] = {}

    def acquire(self, key: str, token: str, limit: int) -> bool:
        held = self.held.setdefault(key, set())
        if len(held) >= limit:
            return False
        held.add(token)
        return True

    def release(self, key: str, token: str) -> None:
        self.held.get(key, set()).discard(token)

    def in_flight(self, key: str) -> int:
        return len(self.held.get(key, ()))

    def reserve(self, key: str, interval: float, horizon: float) -> float:
        wait, self.next_free[key] = book(self.next_free.get(key, 0.0), time.monotonic(), interval, horizon)
        return wait


@dataclass(frozen=True)
class ActorSlots:
    """Slots kept by a Ray actor (a handle to a :class:`SlotTable` actor): one table per cluster."""

    actor: Any
    poll: float = POLL

    @contextmanager
    def slot(self, key: str, limit: int) -> Iterator[None]:
        import uuid

        import ray

        _check_limit(limit)
        token = uuid.uuid4().hex
        while not ray.get(self.actor.acquire.remote(key, token, limit)):
            time.sleep(self.poll * (0.5 + random.random()))
        try:
            yield None
        finally:
            self.actor.release.remote(key, token)

    def reserve(self, key: str, interval: float, horizon: float) -> float:
        import ray

        return ray.get(self.actor.reserve.remote(key, interval, horizon))


@dataclass(frozen=True)
class Limits:
    """What every worker of one batch obeys: where the counters are, and the limits themselves.

    ``concurrency``: requests in flight per OpenAI-compatible server; Hunyuan3D servers have
    their own (``mesh_concurrency`` jobs each). ``per_minute``: request starts per minute per
    server, of any kind (None: no such limit).
    """

    slots: Slots
    concurrency: int
    per_minute: int | None = None

    def __post_init__(self) -> None:
        _check_limit(self.concurrency)
        if self.per_minute is not None and self.per_minute < 1:
            raise ValueError(f"a limit of {self.per_minute} requests per minute admits none; it must be at least 1")

    @contextmanager
    def request(self, key: str, concurrency: int | None = None) -> Iterator[None]:
        """Held around one request to the server ``key``: a slot, then its turn to start."""
        limit = concurrency or self.concurrency
        with self.slots.slot(key, limit):
            if self.per_minute:
                interval = MINUTE / self.per_minute
                wait = self.slots.reserve(key, interval, horizon=(limit + 1) * interval)
                if wait > 0:
                    time.sleep(wait)
            yield


class _Limited:
    """A view of an SDK client whose every call is one request under ``limits`` to ``key``."""

    def __init__(self, target: Any, limits: Limits, key: str):
        self._target, self._limits, self._key = target, limits, key

    def __getattr__(self, name: str) -> Any:
        value = getattr(self._target, name)
        if callable(value):
            return self._call(value)
        return _Limited(value, self._limits, self._key)

    def _call(self, function: Callable[..., Any]) -> Callable[..., Any]:
        def limited(*args: Any, **kwargs: Any) -> Any:
            with self._limits.request(self._key):
                return function(*args, **kwargs)

        return limited


def share_limit(backends: Any, limits: Limits) -> int:
    """Put every remote request of ``backends`` under ``limits``; returns how many backends.

    The OpenAI-compatible backends (chat and images) hold their SDK client as ``client`` (the
    chat model on its ``chat`` helper); each is wrapped, keyed by its server. A mesh-server
    backend (Hunyuan3D, Gradio, Meshy) runs each job attempt through its ``job_gate``, keyed by the server the job went
    to, with that server's ``mesh_concurrency`` slots.
    """
    from scenewright.backends.scheduler import ServerPool
    from scenewright.backends.structured import RemoteModel

    wrapped = 0
    for backend in (backends.vlm, backends.images, backends.meshes):
        for holder in (backend, getattr(backend, "chat", None)):
            if isinstance(holder, RemoteModel) and not isinstance(holder.client, _Limited):
                key = holder.settings.base_url or "https://api.openai.com/v1"
                holder.client = _Limited(holder.client, limits, key)
                wrapped += 1
    if isinstance(backends.meshes, ServerPool) and backends.meshes.job_gate != limits.request:
        backends.meshes.job_gate = limits.request
        wrapped += 1
    return wrapped
