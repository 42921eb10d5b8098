"""``scenewright export DIR --format usd|mjcf|glb-physics``; ``bench physics``: stability and export speed."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from scenewright.cli.app import app
from scenewright.cli.options import ConfigOption, build_settings

FormatOption = Annotated[
    list[str],
    typer.Option("--format", "-f", help="usd | mjcf | glb-physics; repeat for several."),
]
EngineOption = Annotated[
    str, typer.Option("--engine", help="Collider naming of glb-physics: godot (-convcolonly) | unreal (UCX_).")
]


def export_formats(directory: Path, formats: list[str], *, out: Path | None = None, engine: str = "godot",
                   config: Path | None = None) -> list[Path]:
    """Export the scene folder in each format; shared by ``export`` and ``generate --export``."""
    from scenewright.cache import RequestCache
    from scenewright.errors import InputError
    from scenewright.export.sim import check_format, export_scene
    from scenewright.folder import SceneFolder

    for fmt in formats:
        check_format(fmt)
    if out is not None and len(formats) > 1:
        raise InputError("--out names one file; give one --format with it, or drop --out for the defaults under sim/")
    from scenewright.pipeline import writing

    settings = build_settings(config=config)
    cache = RequestCache(settings.cache_dir)
    # Export writes physics into scene.json and files into the folder: under its lock, like every writer.
    with writing(SceneFolder(directory), settings.lock_timeout) as folder:
        scene = folder.load()
        return [export_scene(scene, folder, fmt, cache, out=out, engine=engine) for fmt in formats]


@app.command("export")
def export_command(
    directory: Annotated[Path, typer.Argument(help="The scene folder.")],
    formats: FormatOption = ["usd"],  # noqa: B006 (typer reads the default)
    out: Annotated[Path | None, typer.Option("--out", "-o", help="File to write (default: DIR/sim/...).")] = None,
    engine: EngineOption = "godot",
    config: ConfigOption = None,
) -> None:
    """Write the scene for simulators and engines: colliders, masses, friction, static or dynamic."""
    for path in export_formats(directory, formats, out=out, engine=engine, config=config):
        typer.echo(str(path))
