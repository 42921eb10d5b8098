"""``scenewright batch``: many scenes from a prompts file, with a progress bar; ``bench batch``."""

from __future__ import annotations

import json
import os
import tempfile
import time
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

from scenewright.cli.app import app, bench_app
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
from scenewright.scene import STYLES

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


@bench_app.command("batch")
def bench_batch(
    scenes: Annotated[int, typer.Option("--scenes", min=1, help="Scenes per run (the first shipped prompts).")] = 8,
    workers: Annotated[str, typer.Option("--workers", help="Worker counts to time, comma separated.")] = "1,2",
    ray: Annotated[bool, typer.Option("--ray/--no-ray", help="Also time Ray (needs the batch extra).")] = True,
    json_output: Annotated[bool, typer.Option("--json", help="Print JSON (the only output format).")] = True,
) -> None:
    """Scenes per minute offline with --no-render for each worker count, and Ray's overhead
    per scene against the process pool; with CPU times and the load, since cores are shared."""
    import resource

    from scenewright.analysis.bench import load_prompts
    from scenewright.batch import Entry, RayOptions, run_batch
    from scenewright.batch.entries import text_id

    counts = [int(w) for w in workers.split(",") if w.strip()]
    texts = [p.text for p in load_prompts()][:scenes]
    entries = [Entry(id=text_id(t), text=t, line=i + 1) for i, t in enumerate(texts)]
    settings = build_settings()
    settings.cache_dir = None
    runs: dict[str, dict] = {}

    def timed(label: str, n: int, ray_options=None, extra: dict | None = None) -> None:
        with tempfile.TemporaryDirectory(prefix="scenewright-bench-batch-") as tmp:
            load = os.getloadavg()[0]
            children = resource.getrusage(resource.RUSAGE_CHILDREN)
            own = resource.getrusage(resource.RUSAGE_SELF)
            start = time.perf_counter()
            record = run_batch(entries, Path(tmp), settings=settings, workers=n, render=False, ray=ray_options)
            wall = time.perf_counter() - start
            after_children = resource.getrusage(resource.RUSAGE_CHILDREN)
            after_own = resource.getrusage(resource.RUSAGE_SELF)
        made = [o for o in record.outcomes.values() if o.status == "done"]
        in_scene = sum(o.seconds for o in made)
        runs[label] = {
            "workers": n,
            "scenes": len(made),
            "failed": sum(1 for o in record.outcomes.values() if o.status == "failed"),
            "wall_s": round(wall, 2),
            "scenes_per_minute": round(60 * len(made) / wall, 2) if wall else None,
            "scene_wall_s_median": round(sorted(o.seconds for o in made)[len(made) // 2], 3) if made else None,
            # CPU the scenes themselves used (inside the workers), and per scene.
            "scene_cpu_s": round(sum(o.cpu_seconds for o in made), 2),
            "cpu_s_per_scene": round(sum(o.cpu_seconds for o in made) / len(made), 3) if made else None,
            # Everything the pool's workers used, start-up and imports included (not visible for Ray's workers).
            "worker_processes_cpu_s": None if ray_options else round(
                (after_children.ru_utime + after_children.ru_stime) - (children.ru_utime + children.ru_stime), 2),
            "parent_cpu_s": round((after_own.ru_utime + after_own.ru_stime) - (own.ru_utime + own.ru_stime), 3),
            # Wall time per scene the workers spent outside scenes (start-up, dispatch, idle), per scene.
            "overhead_s_per_scene": round((n * wall - in_scene) / len(made), 3) if made else None,
            "load_average_1min_before": round(load, 2),
            "load_average_1min_after": round(os.getloadavg()[0], 2),
            **(extra or {}),
        }

    for n in counts:
        timed(f"local_{n}", n)
        run = runs[f"local_{n}"]
        # What the wall time would be with a free core per worker: the workers' CPU (start-up
        # included) spread over them. On a shared machine this is the figure that compares.
        run["cpu_bound_wall_s"] = round(run["worker_processes_cpu_s"] / n, 2)
        run["cpu_bound_scenes_per_minute"] = round(60 * run["scenes"] / run["cpu_bound_wall_s"], 2)
    result: dict = {"scenes": len(entries), "cpus_available": len(os.sched_getaffinity(0)), "runs": runs}
    first, last = runs[f"local_{counts[0]}"], runs[f"local_{counts[-1]}"]
    if len(counts) > 1:
        result["speedup"] = {
            "wall": round(first["wall_s"] / last["wall_s"], 3),
            "cpu_bound": round(first["cpu_bound_wall_s"] / last["cpu_bound_wall_s"], 3),
        }
    if ray:
        try:
            import ray as ray_module
        except ImportError:
            result["ray"] = "not measured: the batch extra (ray) is not installed"
        else:
            n = counts[-1]
            start = time.perf_counter()
            ray_module.init(num_cpus=n, include_dashboard=False, log_to_driver=False)
            init_s = time.perf_counter() - start
            try:
                timed(f"ray_{n}", n, RayOptions(num_cpus=n), {"ray_init_s": round(init_s, 2)})
            finally:
                ray_module.shutdown()
            pool, on_ray = runs[f"local_{n}"], runs[f"ray_{n}"]
            if pool["scenes"] and on_ray["scenes"]:
                result["ray_vs_pool"] = {
                    "workers": n,
                    "extra_wall_s_per_scene": round((on_ray["wall_s"] - pool["wall_s"]) / len(entries), 3),
                    "extra_cpu_s_per_scene_in_task": round(on_ray["cpu_s_per_scene"] - pool["cpu_s_per_scene"], 3),
                    "extra_driver_cpu_s_per_scene": round((on_ray["parent_cpu_s"] - pool["parent_cpu_s"]) / len(entries), 4),
                    "ray_init_s": round(init_s, 2),
                }
    typer.echo(json.dumps(result))
