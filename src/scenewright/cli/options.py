"""Backend options shared by every command that runs models (generate, edit, evaluate).

Settings come from three layers, the later winning: the defaults, a TOML config file
(``--config FILE``, else ``scenewright.toml`` in the working folder when there is one) with
the keys of :class:`~scenewright.settings.Settings`, then the flags given.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Annotated

import typer

from scenewright.errors import InputError

from scenewright.settings import DEFAULT_CONFIG, MAX_SEED, Settings, apply, default_cache_dir, load_config

VlmOption = Annotated[str | None, typer.Option("--vlm", help="Vision-language backend: offline | openai:MODEL.")]
ImagesOption = Annotated[str | None, typer.Option("--images", help="Image backend: offline | openai:MODEL.")]
MeshesOption = Annotated[
    str | None,
    typer.Option(
        "--meshes",
        help="Mesh backend: procedural | hunyuan3d:URL[,URL...] | gradio:URL[,URL...]#APP | meshy | library:FOLDER.",
    ),
]
BaseUrlOption = Annotated[str | None, typer.Option("--base-url", help="OpenAI-compatible server URL.")]
ConfigOption = Annotated[
    Path | None,
    typer.Option("--config", help=f"TOML file with the same keys (default: ./{DEFAULT_CONFIG} when present)."),
]
PreviewOption = Annotated[
    str,
    typer.Option("--preview", help="Render quality: draft (480x270, seconds), default (1280x720) or final (1920x1080)."),
]
ApiKeyEnvOption = Annotated[
    str | None,
    typer.Option("--api-key-env", help="Environment variable holding the API key (default OPENAI_API_KEY)."),
]
ReasoningEffortOption = Annotated[
    str | None,
    typer.Option("--reasoning-effort", help="Reasoning effort for models that take one: low | medium | high."),
]
TimeoutOption = Annotated[float | None, typer.Option("--timeout", help="Seconds before a model request is retried.")]
ImageConcurrencyOption = Annotated[
    int | None, typer.Option("--image-concurrency", help="Image requests in flight at once (default 4).")
]
FeedbackRoundsOption = Annotated[
    int | None,
    typer.Option("--feedback-rounds", help="Constraint revisions after an incomplete layout (default 3)."),
]

MaxFacesOption = Annotated[
    int | None,
    typer.Option("--max-faces", help="Simplify each new mesh to about N triangles (needs the 'simplify' extra)."),
]

MaxObjectsOption = Annotated[
    int | None,
    typer.Option("--max-objects", help="Refuse texts that ask for more objects than this (default 150)."),
]


def check_seed(seed: int) -> int:
    if not 0 <= seed <= MAX_SEED:
        raise InputError(f"--seed must be an integer from 0 to {MAX_SEED}, got {seed}")
    return seed


def build_settings(
    vlm: str | None = None,
    images: str | None = None,
    meshes: str | None = None,
    base_url: str | None = None,
    config: Path | None = None,
    **flags: object,
) -> Settings:
    """Defaults, then the config file, then flags: the later wins. ``flags`` are further
    Settings keys (``api_key_env=...``); a flag left at ``None`` was not given."""
    settings = Settings(cache_dir=default_cache_dir(os.environ))  # the one place the environment is read
    if config is None and Path(DEFAULT_CONFIG).is_file():
        config = Path(DEFAULT_CONFIG)
    if config is not None:
        apply(settings, load_config(config), str(config))
    given = {"vlm": vlm, "images": images, "meshes": meshes, "base_url": base_url, **flags}
    return apply(settings, {k: v for k, v in given.items() if v is not None}, "command line")
