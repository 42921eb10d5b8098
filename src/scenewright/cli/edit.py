"""``scenewright edit|undo|redo|history`` and ``bench edits``: language edits of a scene folder."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.table import Table

from scenewright.cli.app import app, on_interrupt
from scenewright.cli.display import safe
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

FolderArgument = Annotated[Path, typer.Argument(help="The scene folder (holds scene.json).")]


@app.command("edit")
def edit_command(
    folder: FolderArgument,
    instruction: Annotated[str, typer.Argument(help="What to change, e.g. 'move the lamp next to the sofa'.")],
    vlm: VlmOption = None,
    images: ImagesOption = None,
    meshes: MeshesOption = None,
    base_url: BaseUrlOption = None,
    config: ConfigOption = None,
    api_key_env: ApiKeyEnvOption = None,
    reasoning_effort: ReasoningEffortOption = None,
    timeout: TimeoutOption = None,
    render: Annotated[
        bool, typer.Option("--render", help="Refresh the previews in renders/ after the edit, as they were made.")
    ] = False,
) -> None:
    """Apply one edit (move, add, delete, replace/restyle); the previous version goes to history/."""
    from scenewright.backends import backends_from_settings
    from scenewright.editing import apply_edit, entries
    from scenewright.pipeline import writing
    from scenewright.render import render_info

    scene_folder = SceneFolder(folder)
    settings = build_settings(vlm=vlm, images=images, meshes=meshes, base_url=base_url, config=config,
                              api_key_env=api_key_env, reasoning_effort=reasoning_effort, timeout=timeout)
    backends = backends_from_settings(settings)
    on_interrupt(lambda: f"the edit took effect if `scenewright history {folder}` lists it; if not, run it again")
    with writing(scene_folder, settings.lock_timeout):
        scene = scene_folder.load()  # read under the lock: a concurrent edit's result is not lost
        # Read first: a broken history or renders.json stops the edit before it asks a model or saves.
        entries(scene_folder)
        rendered = render_info(scene_folder) is not None
        apply_edit(scene, scene_folder, instruction, backends=backends, settings=settings)
        last = [e for e in entries(scene_folder) if e.active][-1]
        console = Console()
        console.print(f"[bold green]edit {last.number}[/bold green]: {safe(last.operation)} {safe(last.focus)}")
        for change in last.changes:
            console.print(f"  {safe(change)}")
        console.print(
            f"  wrote {safe(scene_folder.document)} and {safe(scene_folder.glb)}; "
            f"undo with `scenewright undo {safe(folder)}`"
        )
        if render:
            from scenewright.render import render_again

            paths = render_again(scene_folder.load(), scene_folder)
            console.print(f"  rendered {safe(', '.join(str(p) for p in paths))}")
        elif rendered:
            console.print(f"  renders/ show the scene before this edit: refresh them with `scenewright render {safe(folder)}`"
                          " (or edit with --render)")


@app.command("undo")
def undo_command(folder: FolderArgument) -> None:
    """Restore the scene as it was before the last edit (scene.json byte for byte, and scene.glb)."""
    from scenewright.editing import undo
    from scenewright.pipeline import writing

    on_interrupt(lambda: f"`scenewright history {folder}` shows which edits are in effect")
    with writing(SceneFolder(folder), build_settings().lock_timeout) as scene_folder:
        _, entry = undo(scene_folder)
    Console().print(f"undid edit {entry.number}: {safe(repr(entry.instruction))}; redo with `scenewright redo {safe(folder)}`")


@app.command("redo")
def redo_command(folder: FolderArgument) -> None:
    """Re-apply the edit undone last, exactly as it came out."""
    from scenewright.editing import redo
    from scenewright.pipeline import writing

    on_interrupt(lambda: f"`scenewright history {folder}` shows which edits are in effect")
    with writing(SceneFolder(folder), build_settings().lock_timeout) as scene_folder:
        _, entry = redo(scene_folder)
    Console().print(f"redid edit {entry.number}: {safe(repr(entry.instruction))}")


@app.command("history")
def history_command(folder: FolderArgument) -> None:
    """List the edits of a scene folder, oldest first; undone ones are marked."""
    from scenewright.editing import entries

    found = entries(SceneFolder(folder))
    console = Console()
    if not found:
        console.print(f"no edits yet in {safe(folder)}")
        return
    table = Table("#", "time", "operation", "focus", "instruction", "state")
    for e in found:
        table.add_row(str(e.number), safe(e.time), safe(e.operation), safe(e.focus), safe(e.instruction),
                      "in effect" if e.active else "[dim]undone[/dim]")
    console.print(table)
