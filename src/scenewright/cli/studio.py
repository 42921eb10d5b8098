"""``scenewright studio``: open a scene folder in the browser editor."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console

from scenewright.cli.app import app
from scenewright.cli.options import (
    ApiKeyEnvOption,
    BaseUrlOption,
    ConfigOption,
    ImagesOption,
    MeshesOption,
    ReasoningEffortOption,
    TimeoutOption,
    VlmOption,
    build_settings,
)
from scenewright.folder import SceneFolder

LOCAL = "127.0.0.1"


@app.command("studio")
def studio_command(
    folder: Annotated[Path, typer.Argument(help="The scene folder (holds scene.json).")],
    host: Annotated[
        str, typer.Option("--host", help="Address to listen on; anything but 127.0.0.1 exposes the editor.")
    ] = LOCAL,
    port: Annotated[int, typer.Option("--port", help="Port to listen on.")] = 8080,
    vlm: VlmOption = None,
    images: ImagesOption = None,
    meshes: MeshesOption = None,
    base_url: BaseUrlOption = None,
    config: ConfigOption = None,
    api_key_env: ApiKeyEnvOption = None,
    reasoning_effort: ReasoningEffortOption = None,
    timeout: TimeoutOption = None,
) -> None:
    """Edit the scene in the browser: select, drag, type edits, undo; the same engine as `edit`."""
    from scenewright.backends import backends_from_settings
    from scenewright.studio import Session
    from scenewright.studio.server import Studio

    settings = build_settings(vlm=vlm, images=images, meshes=meshes, base_url=base_url, config=config,
                              api_key_env=api_key_env, reasoning_effort=reasoning_effort, timeout=timeout)
    session = Session(SceneFolder(folder), backends=backends_from_settings(settings), settings=settings)
    console = Console()
    if host != LOCAL:
        console.print(f"[yellow]warning:[/yellow] listening on {host}: anyone who can reach this machine "
                      "can edit the scene (the editor has no login)")
    studio = Studio(session, host=host, port=port)
    console.print(f"scenewright studio on {folder}: open {studio.url} (Ctrl-C to stop)")
    try:
        while True:
            time.sleep(3600)
    except KeyboardInterrupt:
        pass
    finally:
        studio.stop()
