"""``scenewright generate``: text → scene folder, with progress; ``bench pipeline``: its speed."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.console import Console
from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

from scenewright.cli.app import app, on_interrupt
from scenewright.cli.display import safe
from scenewright.cli.options import (
    ApiKeyEnvOption,
    BaseUrlOption,
    ConfigOption,
    FeedbackRoundsOption,
    ImageConcurrencyOption,
    ImagesOption,
    MaxFacesOption,
    MaxObjectsOption,
    MeshesOption,
    PreviewOption,
    ReasoningEffortOption,
    TimeoutOption,
    VlmOption,
    build_settings,
    check_seed,
)
from scenewright.errors import InfeasibleLayout, InputError
from scenewright.examples import example_text
from scenewright.folder import SceneFolder
from scenewright.settings import STYLES

if TYPE_CHECKING:
    from scenewright.scene import Scene

#: The bundled text ``--example`` generates (``make demo``).


class _StageProgress:
    """One spinner line per pipeline stage, its latest message beside it."""

    def __init__(self, progress: Progress):
        self.progress = progress
        self.tasks: dict[str, int] = {}

    def __call__(self, stage: str, message: str) -> None:
        if stage not in self.tasks:
            self.tasks[stage] = self.progress.add_task(stage, total=1, note="")
        task = self.tasks[stage]
        if message == "done":
            self.progress.update(task, completed=1, note="[green]done[/green]")
        elif message.startswith("skipped"):
            self.progress.update(task, completed=1, note=f"[yellow]{safe(message)}[/yellow]")
        else:
            self.progress.update(task, note=safe(message))


def _summary(console: Console, folder: SceneFolder, scene: Scene) -> None:
    console.print(f"[bold green]Scene written to {safe(folder.root)}[/bold green]")
    console.print(f"  scene.glb    {safe(folder.glb)}  (open it in Blender, Godot or Unreal)")
    counts = f"{len(scene.objects)} objects, {len(scene.constraints)} constraints"
    console.print(f"  scene.json   {safe(folder.document)}  ({counts})")
    console.print(f"  assets/      {safe(folder.assets)}  (one GLB per object)")
    console.print(f"  images/      {safe(folder.images)}")
    renders = sorted(folder.renders.glob("*.png")) if folder.renders.is_dir() else []
    if renders:
        plural = "s" if len(renders) != 1 else ""
        console.print(f"  renders/     {safe(folder.renders)}  ({len(renders)} preview{plural})")
    for removed in scene.removed:
        console.print(f"  [dim]removed {safe(removed.id)}: {safe(removed.reason)}[/dim]")
    guessed = {k: v for e in scene.provenance for k, v in e.data.get("guessed", {}).items()}
    if guessed:
        names = ", ".join(f"{i} ({family})" for i, family in guessed.items())
        console.print(f"  [yellow]guessed {len(guessed)} objects the catalogue does not name: {safe(names)}[/yellow]")


@app.command("generate")
def generate_command(
    text: Annotated[
        str | None, typer.Argument(help="The scene description (25-300 words work best).")
    ] = None,
    out: Annotated[Path | None, typer.Option("--out", "-o", help="Folder to write the scene into.")] = None,
    style: Annotated[
        str | None,
        typer.Option(
            "--style", help=f"Visual style ({', '.join(STYLES)}, or a look such as voxel, watercolour, film noir, engraving or poster, or a name that says one, as copperplate engraving); default: named in the text, else realistic."
        ),
    ] = None,
    seed: Annotated[int, typer.Option("--seed", help="Seed of the layout search and procedural looks.")] = 0,
    no_render: Annotated[bool, typer.Option("--no-render", help="Skip the Blender preview renders.")] = False,
    preview: PreviewOption = "default",
    resume_dir: Annotated[
        Path | None, typer.Option("--resume", help="Finish an interrupted scene folder instead of a new one.")
    ] = None,
    example: Annotated[bool, typer.Option("--example", help="Generate the bundled example text.")] = False,
    vlm: VlmOption = None,
    images: ImagesOption = None,
    meshes: MeshesOption = None,
    base_url: BaseUrlOption = None,
    config: ConfigOption = None,
    api_key_env: ApiKeyEnvOption = None,
    reasoning_effort: ReasoningEffortOption = None,
    timeout: TimeoutOption = None,
    image_concurrency: ImageConcurrencyOption = None,
    feedback_rounds: FeedbackRoundsOption = None,
    max_faces: MaxFacesOption = None,
    export: Annotated[
        list[str] | None,
        typer.Option("--export", help="Also export for simulators: usd | mjcf | glb-physics (repeatable)."),
    ] = None,
    max_objects: MaxObjectsOption = None,
    room: Annotated[
        str,
        typer.Option("--room", help="The room: auto (indoor text gets one), none, or the floor as WxD or WxDxH metres."),
    ] = "auto",
) -> None:
    """Turn TEXT into a scene folder: scene.json, one asset per object, scene.glb, previews."""
    from scenewright.backends import backends_from_settings
    from scenewright.cli.export import export_formats

    if export:  # the simulator exporters pull in trimesh and scipy: only for a run that asks for them
        from scenewright.export.sim import check_format

        for fmt in export:
            check_format(fmt)  # before the run, not after it
    from scenewright.pipeline import generate, resume

    sources = (("TEXT", text is not None), ("--example", example), ("--resume", resume_dir is not None))
    given = [name for name, present in sources if present]
    if len(given) != 1:
        raise InputError(
            f"give exactly one of TEXT, --example or --resume DIR (got {', '.join(given) or 'none'})"
        )
    if resume_dir is not None and (out is not None or style is not None or room != "auto"):
        raise InputError("--resume takes the scene folder itself and keeps its style and room; drop --out, --style and --room")
    from scenewright.analysis.parser.room import parse_room_option

    parse_room_option(room)  # exit 2 naming the value, before any work
    if resume_dir is None and out is None:
        raise InputError("--out DIR is required: the folder to write the scene into")
    check_seed(seed)
    from scenewright.render import PREVIEWS

    if preview not in PREVIEWS:  # before the run, not at its end
        raise InputError(f"--preview {preview!r}: choose {', '.join(PREVIEWS)}")
    settings = build_settings(
        vlm=vlm,
        images=images,
        meshes=meshes,
        base_url=base_url,
        config=config,
        api_key_env=api_key_env,
        reasoning_effort=reasoning_effort,
        timeout=timeout,
        image_concurrency=image_concurrency,
        feedback_rounds=feedback_rounds,
        max_faces=max_faces,
        max_objects=max_objects,
    )
    backends = backends_from_settings(settings)
    folder = SceneFolder((resume_dir if resume_dir is not None else out).absolute())
    on_interrupt(lambda: f"resume with `scenewright generate --resume {folder.root}`" if folder.is_scene()
                 else "nothing was saved; run the same command again")
    console = Console(stderr=True)
    with Progress(
        SpinnerColumn(),
        TextColumn("[bold]{task.description:<8}"),
        TextColumn("{task.fields[note]}"),
        TimeElapsedColumn(),
        console=console,
        transient=False,
    ) as bar:
        report = _StageProgress(bar)
        if resume_dir is not None:
            scene = resume(
                folder, backends=backends, settings=settings, render=not no_render, preview=preview,
                progress=report,
            )
        else:
            scene = generate(
                example_text() if example else text,
                folder,
                backends=backends,
                settings=settings,
                style=style,
                seed=seed,
                render=not no_render,
                preview=preview,
                progress=report,
                room=room,
            )
    _summary(Console(soft_wrap=True), folder, scene)
    for path in export_formats(folder.root, export, config=config) if export else ():
        typer.echo(f"  exported     {path}")
    if scene.layout is not None and scene.layout.room:
        Console(stderr=True, soft_wrap=True).print(f"[yellow]room: {safe('; '.join(scene.layout.room))}[/yellow]")
    if scene.layout is not None and scene.layout.unplaced:
        lines = "; ".join(f"{u.id} ({u.reason}{': ' + u.nearest_miss if u.nearest_miss else ''})"
                          for u in scene.layout.unplaced)
        room = "".join(f" {line}." for line in scene.layout.room if " do not fit: " in line)
        raise InfeasibleLayout(
            f"{len(scene.layout.unplaced)} objects could not be placed and stay at their initial "
            f"positions: {lines}.{room} The scene is written; move them with `scenewright edit`."
        )
