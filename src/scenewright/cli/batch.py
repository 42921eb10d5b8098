"""``scenewright batch``: many scenes from a prompts file, with a progress bar; ``bench batch``."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

from scenewright.cli.app import app
from scenewright.cli.display import safe
from scenewright.cli.options import (
    ApiKeyEnvOption,
    BaseUrlOption,
    ConfigOption,
    FeedbackRoundsOption,
    ImageConcurrencyOption,
    ImagesOption,
    MaxFacesOption,
    MeshesOption,
    ReasoningEffortOption,
    TimeoutOption,
    VlmOption,
    build_settings,
)
from scenewright.errors import InputError
from scenewright.settings import STYLES

EXIT_SOME_FAILED = 1
EXIT_INTERRUPTED = 130


def _ray_options(address: str | None, workers: int | None, gpus: float):
    from scenewright.batch import RayOptions

    if address is None:
        if gpus:
            raise InputError("--gpus-per-scene needs --ray (local, auto or an address)")
        return None
    address = address.strip()
    return RayOptions(address=None if address == "local" else address, num_cpus=workers, gpus_per_scene=gpus)


@app.command("batch")
def batch_command(
    prompts: Annotated[
        Path, typer.Argument(help="Text file (one description a line) or JSONL (id, text, style, seed, backends).")
    ],
    out: Annotated[Path, typer.Option("--out", "-o", help="Folder for the scenes, one subfolder per id.")],
    workers: Annotated[
        int | None, typer.Option("--workers", "-j", min=1, help="Scenes at once (default: the cores available).")
    ] = None,
    ray_address: Annotated[
        str | None,
        typer.Option("--ray", help="Run on Ray: 'local' starts one here, 'auto' joins a running cluster, or an address."),
    ] = None,
    style: Annotated[
        str | None, typer.Option("--style", help=f"Style of entries that name none ({', '.join(STYLES)}).")
    ] = None,
    seeds: Annotated[
        str | None, typer.Option("--seeds", help="Seeds for entries without one: '0,1,2' or '0-4' (one scene each).")
    ] = None,
    strict: Annotated[bool, typer.Option("--strict", help="Refuse the file if any line cannot be used.")] = False,
    no_render: Annotated[bool, typer.Option("--no-render", help="Skip the Blender preview renders.")] = False,
    remote_limit: Annotated[
        int | None,
        typer.Option("--remote-limit", min=1, help="Requests in flight per remote model server, across all workers "
                     "(default: image_concurrency; Hunyuan3D servers take mesh_concurrency jobs each)."),
    ] = None,
    requests_per_minute: Annotated[
        int | None,
        typer.Option("--requests-per-minute", min=1, help="Requests started per minute per remote server, across "
                     "all workers, spaced evenly (default: no limit)."),
    ] = None,
    gpus_per_scene: Annotated[
        float, typer.Option("--gpus-per-scene", min=0.0, help="GPUs each Ray task declares (renders, local models).")
    ] = 0.0,
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
) -> None:
    """Make one scene per entry of PROMPTS under --out; a re-run skips finished scenes and
    resumes half-done ones. Writes batch.json, batch.md and index.jsonl (the dataset index)."""
    from scenewright.batch import default_workers, parse_seeds, read_entries, run_batch

    entries, problems = read_entries(prompts, style=style, seeds=parse_seeds(seeds) if seeds else None)
    err = Console(stderr=True, soft_wrap=True, highlight=False)
    if problems and strict:
        listed = "; ".join(str(p) for p in problems[:20])
        more = f" (and {len(problems) - 20} more)" if len(problems) > 20 else ""
        raise InputError(f"{prompts}: {len(problems)} lines cannot be used: {listed}{more}. Fix them or drop --strict")
    for problem in problems:
        err.print(f"[yellow]skipped[/yellow] {safe(str(prompts))}:{problem.line}: {safe(problem.reason)}")
    if not entries:
        raise InputError(f"{prompts}: no usable entry; every line was skipped")
    ray = _ray_options(ray_address, workers, gpus_per_scene)
    settings = build_settings(
        vlm=vlm, images=images, meshes=meshes, base_url=base_url, config=config, api_key_env=api_key_env,
        reasoning_effort=reasoning_effort, timeout=timeout, image_concurrency=image_concurrency,
        feedback_rounds=feedback_rounds, max_faces=max_faces,
    )
    counts = {"done": 0, "failed": 0, "interrupted": 0}
    with Progress(
        TextColumn("[bold]batch"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("done {task.fields[done]} · failed {task.fields[failed]} · running {task.fields[running]}"),
        TimeElapsedColumn(),
        TextColumn("ETA"),
        TimeRemainingColumn(),
        console=err,
    ) as bar:
        n_workers = workers or default_workers()
        task = bar.add_task("batch", total=len(entries), done=0, failed=0, running=0)

        def arrived(outcome) -> None:
            key = "done" if outcome.status in ("done", "finished") else outcome.status
            counts[key] = counts.get(key, 0) + 1
            running = min(n_workers, len(entries) - sum(counts.values()))
            bar.update(task, advance=1, done=counts["done"], failed=counts["failed"], running=running)
            if outcome.status == "failed":
                bar.console.print(f"[red]failed[/red] {outcome.id}: {safe(outcome.reason or '')}")

        record = run_batch(
            entries, out, settings=settings, workers=workers, render=not no_render, ray=ray,
            remote_limit=remote_limit, requests_per_minute=requests_per_minute, problems=problems, source=str(prompts), on_outcome=arrived,
        )
    t = record.totals()
    console = Console(soft_wrap=True, highlight=False)
    console.print(
        f"[bold]{t['done'] + t['finished_before']} of {t['entries']} scenes finished[/bold] in {safe(out)} "
        f"({t['done']} now, {t['finished_before']} before), {t['failed']} failed, {t['interrupted']} interrupted; "
        f"{t['seconds']:.1f} s"
    )
    console.print(f"  batch.md / batch.json  {safe(out / 'batch.md')}  (per scene status, objects, constraints, CF, time)")
    console.print(f"  index.jsonl            {safe(out / 'index.jsonl')}  (one line per finished scene)")
    if record.interrupted:
        console.print("[yellow]interrupted[/yellow]: run the same command again to finish the rest")
        raise typer.Exit(EXIT_INTERRUPTED)
    if t["failed"]:
        raise typer.Exit(EXIT_SOME_FAILED)
