"""A content-addressed cache for expensive backend answers (images, meshes, model replies).

Keys are a hash of the request, so a re-run, a resume or an edit never pays twice for the
same asset. Entries are written atomically; a half-written entry cannot exist.
"""

from __future__ import annotations

import hashlib
import json
import logging
from pathlib import Path
from typing import Any

from scenewright.files import write_atomic

log = logging.getLogger(__name__)


def request_key(*parts: Any) -> str:
    """A stable hash of a request: JSON-able parts hashed canonically, bytes hashed as they are."""
    h = hashlib.sha256()
    for part in parts:
        if isinstance(part, (bytes, bytearray, memoryview)):
            h.update(b"b")
            h.update(hashlib.sha256(bytes(part)).digest())
        else:
            h.update(b"j")
            h.update(json.dumps(part, sort_keys=True, separators=(",", ":"), default=str).encode())
    return h.hexdigest()


class RequestCache:
    """Files under ``root/<kind>/<key[:2]>/<key>``; ``None`` as root disables caching."""

    def __init__(self, root: str | Path | None):
        self.root = Path(root) if root is not None else None

    def _path(self, kind: str, key: str) -> Path:
        assert self.root is not None
        return self.root / kind / key[:2] / key

    def get(self, kind: str, key: str) -> bytes | None:
        if self.root is None:
            return None
        path = self._path(kind, key)
        if path.is_file():
            log.debug("cache hit %s/%s", kind, key[:12])
            return path.read_bytes()
        return None

    def put(self, kind: str, key: str, data: bytes) -> None:
        if self.root is not None:
            write_atomic(self._path(kind, key), data)
