"""``scenewright render DIR``: Blender previews of a scene folder."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from scenewright.cli.app import app, on_interrupt
from scenewright.cli.display import printable
from scenewright.cli.options import ConfigOption, PreviewOption, build_settings
from scenewright.errors import InputError
from scenewright.folder import SceneFolder


def parse_resolution(text: str) -> tuple[int, int]:
    try:
        width, height = (int(part) for part in text.lower().split("x"))
    except ValueError:
        raise InputError(f"--resolution {text!r}: write it as WIDTHxHEIGHT, e.g. 1280x720") from None
    return width, height


@app.command("render")
def render_command(
    directory: Annotated[Path, typer.Argument(help="Scene folder (holds scene.json and scene.glb).")],
    views: Annotated[
        str, typer.Option("--views", help="best: render the view showing most objects; all: the three views.")
    ] = "best",
    preview: PreviewOption = "default",
    draft: Annotated[bool, typer.Option("--draft", help="Same as --preview draft.")] = False,
    resolution: Annotated[str | None, typer.Option("--resolution", help="WIDTHxHEIGHT in pixels [default: the preview's].")] = None,
    samples: Annotated[int | None, typer.Option("--samples", help="Cycles samples per pixel, denoised [default: the preview's].")] = None,
    transparent: Annotated[bool, typer.Option("--transparent", help="Transparent background instead of the sky.")] = False,
    config: ConfigOption = None,
) -> None:
    """Render previews with Blender (Cycles on the CPU) into DIR/renders/."""
    from scenewright.pipeline import writing
    from scenewright.render import render, render_info

    if views not in ("best", "all"):
        raise InputError(f"--views {views!r}: choose best or all")
    settings = build_settings(config=config)
    size = parse_resolution(resolution) if resolution is not None else None
    on_interrupt(lambda: f"the previews were left as they were; render again with `scenewright render {directory}`")
    with writing(SceneFolder(directory), settings.lock_timeout) as folder:
        paths = render(
            folder.load(),
            folder,
            keep_all=views == "all",
            preview="draft" if draft else preview,
            resolution=size,
            samples=samples,
            transparent=transparent,
            max_pixels=settings.max_render_pixels,
            max_samples=settings.max_render_samples,
        )
        info = render_info(folder) or {}
    for path in paths:
        typer.echo(printable(path))
    typer.echo(printable(f"best view: {info.get('best')}; {info.get('total_seconds')} s in Blender"), err=True)
