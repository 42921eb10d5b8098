"""Run configuration in one explicit object, filled from defaults, a TOML file and CLI flags.

Library code never reads the environment on its own: whatever a backend needs (an API key's
variable name, a base URL, a cache folder) comes through :class:`Settings`.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path


def default_cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "scenewright"


@dataclass
class Settings:
    #: Backend specs, ``name[:argument]``: ``offline``, ``openai:o3``, ``hunyuan3d:http://a:8081,...``.
    vlm: str = "offline"
    images: str = "offline"
    meshes: str = "procedural"
    #: OpenAI-compatible endpoint; ``None`` means the SDK's default (api.openai.com).
    base_url: str | None = None
    #: Name of the environment variable holding the API key (read only when a remote backend starts).
    api_key_env: str = "OPENAI_API_KEY"
    reasoning_effort: str | None = None
    timeout: float = 120.0
    max_retries: int = 3
    #: Concurrent image requests and jobs per mesh server.
    image_concurrency: int = 4
    mesh_concurrency: int = 1
    feedback_rounds: int = 3
    time_limit: float = 10.0
    cache_dir: Path | None = field(default_factory=default_cache_dir)
    extra: dict[str, object] = field(default_factory=dict)
