"""Run configuration in one explicit object, filled from defaults, a TOML file and CLI flags.

Library code never reads the environment on its own: whatever a backend needs (an API key's
variable name, a base URL, a cache folder) comes through :class:`Settings`. The command line is
the edge that reads it (:func:`scenewright.cli.options.build_settings` passes ``os.environ`` to
:func:`default_cache_dir`); a library caller's ``Settings()`` caches nothing until told where.
"""

from __future__ import annotations

import math
import os
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from scenewright.errors import InputError


def default_cache_dir(environ: Mapping[str, str]) -> Path:
    """The command line's cache: ``$XDG_CACHE_HOME/scenewright``, else ``~/.cache/scenewright``."""
    base = environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "scenewright"


#: Styles every backend understands; free text is accepted and mapped by each backend. The
#: document model (:mod:`scenewright.scene`) checks against them; they live here, with the other
#: plain values, so a command's help can list them without loading the document model.
STYLES = ("realistic", "cartoon", "low-poly", "cyberpunk", "steampunk", "anime")
#: Seeds feed numpy's generator, which takes 0 .. 2**32 - 1.
MAX_SEED = 2**32 - 1


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
    #: Simplify each generated mesh to about this many triangles (image-to-3D meshes run to
    #: hundreds of thousands, and layout slows with every one); ``None`` keeps them as they come.
    max_faces: int | None = 200_000
    #: The layout search's budget per solve, in seconds of counted work (:mod:`.layout.solver`).
    time_limit: float = 10.0
    #: Seconds a command that writes a scene folder waits while another one is writing it.
    lock_timeout: float = 60.0
    # Limits on what untrusted servers may hand back (docs/security.md).
    #: Characters of one model answer; a longer one is refused and asked for again.
    max_answer_chars: int = 200_000
    #: Objects of one scene, from the text, a model's answer or an edit; more is refused before
    #: any work (a runaway count).
    max_objects: int = 150
    #: Bytes of one HTTP response body (a GLB, an image, a status); the download stops there.
    max_download_bytes: int = 256 * 1024 * 1024
    #: Pixels (width × height) and Cycles samples of one render.
    max_render_pixels: int = 3840 * 2160
    max_render_samples: int = 4096
    #: Where model answers and meshes are cached; ``None`` caches nothing (the CLI's default is
    #: :func:`default_cache_dir`).
    cache_dir: Path | None = None
    extra: dict[str, object] = field(default_factory=dict)


# How each key of a config file or a flag is read; a converter's ValueError says what fits.
def _text(value: object) -> str:
    if not isinstance(value, str) or not value.strip():
        raise ValueError("a non-empty string")
    return value.strip()


def _optional_text(value: object) -> str | None:
    if value is None or value == "":
        return None
    return _text(value)


def _count(minimum: int):
    def convert(value: object) -> int:
        if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
            raise ValueError(f"an integer >= {minimum}")
        return value

    return convert


def _optional_count(minimum: int):
    """An integer >= ``minimum``, or 0 for none."""
    check = _count(minimum)

    def convert(value: object) -> int | None:
        if value is None or (value == 0 and not isinstance(value, bool)):
            return None
        try:
            return check(value)
        except ValueError:
            raise ValueError(f"an integer >= {minimum} (or 0 for no limit)") from None

    return convert


def _positive(value: object) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 < value < math.inf:
        raise ValueError("a finite number > 0")
    return float(value)


def _non_negative(value: object) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 <= value < float("inf"):
        raise ValueError("a number >= 0")
    return float(value)


def _cache_dir(value: object) -> Path | None:
    """A folder, or an empty string for no cache."""
    if value is None or value == "":
        return None
    if not isinstance(value, (str, Path)):
        raise ValueError('a folder path (or "" for no cache)')
    return Path(value).expanduser()


def _table(value: object) -> dict[str, object]:
    if not isinstance(value, dict):
        raise ValueError("a table")
    return dict(value)


KEYS = {
    "vlm": _text,
    "images": _text,
    "meshes": _text,
    "base_url": _optional_text,
    "api_key_env": _text,
    "reasoning_effort": _optional_text,
    "timeout": _positive,
    "max_retries": _count(0),
    "image_concurrency": _count(1),
    "mesh_concurrency": _count(1),
    "feedback_rounds": _count(0),
    "max_faces": _optional_count(100),
    "max_answer_chars": _count(1000),
    "max_objects": _count(1),
    "max_download_bytes": _count(1024),
    "max_render_pixels": _count(256),
    "max_render_samples": _count(1),
    "time_limit": _positive,
    "lock_timeout": _non_negative,
    "cache_dir": _cache_dir,
    "extra": _table,
}


def apply(settings: Settings, values: Mapping[str, object], source: str) -> Settings:
    """Set ``values`` on ``settings``, each checked; errors name ``source``, the key and what fits."""
    unknown = sorted(set(values) - set(KEYS))
    if unknown:
        raise InputError(f"{source}: unknown keys {', '.join(unknown)}; valid keys: {', '.join(KEYS)}")
    for key, value in values.items():
        try:
            setattr(settings, key, KEYS[key](value))
        except ValueError as exc:
            raise InputError(f"{source}: {key} must be {exc}, got {value!r}") from None
    return settings


#: Read from the working folder when no ``--config`` is given.
DEFAULT_CONFIG = "scenewright.toml"


def load_config(path: str | os.PathLike) -> dict[str, object]:
    """The keys of a TOML config file (unchecked; :func:`apply` checks them)."""
    path = Path(path)
    try:
        with path.open("rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise InputError(f"config file {path} does not exist") from None
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"config file {path} is not valid TOML: {exc}") from None
