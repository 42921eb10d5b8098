"""Backend options shared by every command that runs models (generate, edit, evaluate)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from scenewright.settings import Settings

VlmOption = Annotated[str | None, typer.Option("--vlm", help="Vision-language backend: offline | openai:MODEL.")]
ImagesOption = Annotated[str | None, typer.Option("--images", help="Image backend: offline | openai:MODEL.")]
MeshesOption = Annotated[
    str | None,
    typer.Option("--meshes", help="Mesh backend: procedural | hunyuan3d:URL[,URL...] | library:FOLDER."),
]
BaseUrlOption = Annotated[str | None, typer.Option("--base-url", help="OpenAI-compatible server URL.")]
ConfigOption = Annotated[Path | None, typer.Option("--config", help="TOML file with the same keys.")]


def build_settings(
    vlm: str | None = None,
    images: str | None = None,
    meshes: str | None = None,
    base_url: str | None = None,
    config: Path | None = None,
) -> Settings:
    """Defaults, then the config file, then flags: the later wins."""
    settings = Settings()
    for key, value in (("vlm", vlm), ("images", images), ("meshes", meshes), ("base_url", base_url)):
        if value is not None:
            setattr(settings, key, value)
    return settings
