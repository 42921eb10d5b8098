"""One limit on remote requests in flight for a whole batch, however many workers run it.

Each scene's backends keep their own limits (``image_concurrency`` threads per scene), which
multiply with the number of workers; a provider's limit does not. So every request to a
remote model server first takes a slot from one table shared by all workers, keyed by the
server (its base URL), at most ``limit`` slots per server:

- :class:`FileSlots` for workers on one machine (the process pool, Ray in local mode): slot
  *i* is an exclusive ``flock`` on the file ``<folder>/<server>/<i>.lock``. The kernel drops a
  lock when its process dies, so a killed worker can never leak a slot.
- :class:`ActorSlots` for a Ray cluster: the table lives in one Ray actor every task asks.

Both are small picklable values, handed to each worker with its scene. Requests are limited
where the backends make them, the SDK call (:func:`share_limit`), so retries inside the SDK
keep their slot and the count is of requests, not of HTTP connections.
"""

from __future__ import annotations

import hashlib
import os
import random
import re
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

#: Seconds between attempts to take a slot (with jitter, so waiters do not move in step).
POLL = 0.02


class Slots(Protocol):
    limit: int

    def slot(self, key: str) -> Any:
        """A context manager holding one of the ``limit`` slots of ``key`` while it is open."""


def _key_folder(key: str) -> str:
    readable = re.sub(r"[^A-Za-z0-9]+", "_", key).strip("_")[:40]
    return f"{readable}-{hashlib.sha1(key.encode()).hexdigest()[:8]}"


@dataclass(frozen=True)
class FileSlots:
    """Slots as ``flock``-ed files in ``folder``: shared by every process of one machine."""

    folder: Path
    limit: int
    poll: float = POLL

    def __post_init__(self) -> None:
        if self.limit < 1:
            raise ValueError(f"a limit of {self.limit} slots admits no request; it must be at least 1")

    @contextmanager
    def slot(self, key: str) -> Iterator[int]:
        import fcntl

        folder = Path(self.folder) / _key_folder(key)
        folder.mkdir(parents=True, exist_ok=True)
        while True:
            start = random.randrange(self.limit)
            for k in range(self.limit):
                index = (start + k) % self.limit
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


class SlotTable:
    """The bookkeeping of :class:`ActorSlots`, run inside one Ray actor (plain Python here)."""

    def __init__(self, limit: int):
        self.limit = limit
        self.held: dict[str, set[str]] = {}

    def acquire(self, key: str, token: str) -> bool:
        held = self.held.setdefault(key, set())
        if len(held) >= self.limit:
            return False
        held.add(token)
        return True

    def release(self, key: str, token: str) -> None:
        self.held.get(key, set()).discard(token)

    def in_flight(self, key: str) -> int:
        return len(self.held.get(key, ()))


@dataclass(frozen=True)
class ActorSlots:
    """Slots kept by a Ray actor (a handle to a :class:`SlotTable` actor): one table per cluster."""

    actor: Any
    limit: int
    poll: float = POLL

    @contextmanager
    def slot(self, key: str) -> Iterator[None]:
        import uuid

        import ray

        token = uuid.uuid4().hex
        while not ray.get(self.actor.acquire.remote(key, token)):
            time.sleep(self.poll * (0.5 + random.random()))
        try:
            yield None
        finally:
            self.actor.release.remote(key, token)


class _Limited:
    """A view of an SDK client whose every call holds a slot of ``key`` while it runs."""

    def __init__(self, target: Any, slots: Slots, key: str):
        self._target, self._slots, self._key = target, slots, key

    def __getattr__(self, name: str) -> Any:
        value = getattr(self._target, name)
        if callable(value):
            return self._call(value)
        return _Limited(value, self._slots, self._key)

    def _call(self, function: Callable[..., Any]) -> Callable[..., Any]:
        def limited(*args: Any, **kwargs: Any) -> Any:
            with self._slots.slot(self._key):
                return function(*args, **kwargs)

        return limited


def share_limit(backends: Any, slots: Slots) -> int:
    """Route every remote SDK call of ``backends`` through ``slots``; returns how many clients.

    The OpenAI-compatible backends (chat and images) hold their SDK client as ``client``
    (the chat model on its ``chat`` helper); each is wrapped, keyed by its server.
    """
    from scenewright.backends.structured import RemoteModel

    wrapped = 0
    for backend in (backends.vlm, backends.images, backends.meshes):
        for holder in (backend, getattr(backend, "chat", None)):
            if isinstance(holder, RemoteModel) and not isinstance(holder.client, _Limited):
                key = holder.settings.base_url or "https://api.openai.com/v1"
                holder.client = _Limited(holder.client, slots, key)
                wrapped += 1
    return wrapped
