"""``scenewright bench ...``: the benchmarks' command group; each prints one JSON object.

The measuring lives in :mod:`scenewright.bench` (one module per benchmark); these commands only
read their options, build the settings as every command does, and print the result. ``--json``
(the default) prints the object on one line, as ``make bench`` gathers it; ``--text`` prints
one ``key: value`` line per figure for reading at a terminal.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated, Any

import typer

from scenewright.cli.app import bench_app
from scenewright.cli.options import build_settings

JsonOption = Annotated[
    bool, typer.Option("--json/--text", help="One JSON object (default), or one 'key: value' line per figure.")
]


def flat(value: Any, prefix: str = "") -> list[str]:
    """``key: value`` lines of a nested result, keys joined by dots (lists of records by index)."""
    if isinstance(value, dict):
        return [line for k, v in value.items() for line in flat(v, f"{prefix}{k}.")]
    if isinstance(value, list) and any(isinstance(v, (dict, list)) for v in value):
        return [line for i, v in enumerate(value) for line in flat(v, f"{prefix}{i}.")]
    return [f"{prefix.rstrip('.')}: {json.dumps(value)}"]


def emit(result: dict, as_json: bool, indent: int | None = None) -> None:
    typer.echo(json.dumps(result, indent=indent) if as_json else "\n".join(flat(result)))


PromptsOption = Annotated[
    Path | None, typer.Option("--prompts", help="Folder of annotated prompt files (default: benchmarks/prompts).")
]


@bench_app.command("layout")
def bench_layout(
    sizes: Annotated[str | None, typer.Option(
        "--sizes", help="Object counts, comma-separated [default: 15,50,100; with --hard 10,30,60,100,200].")] = None,
    seeds: Annotated[int, typer.Option("--seeds", help="Problems per size.")] = 20,
    time_limit: Annotated[float, typer.Option("--time-limit", help="Per-problem search budget, seconds of counted work (see `solve --help`).")] = 10.0,
    hard: Annotated[bool, typer.Option(
        "--hard", help="Arbitrary yaws, 2+ relations per object, facing pairs, stacks, dense rooms.")] = False,
    room_seeds: Annotated[int, typer.Option("--room-seeds", help="With --hard: dense rooms per floor share.")] = 3,
    baseline: Annotated[Path | None, typer.Option(
        "--baseline", help="With --hard: also solve every problem with the scenewright checkout at this path.")] = None,
    as_json: JsonOption = True,
) -> None:
    """Solve planted-solution problems: timings, success and collisions per size."""
    from scenewright.bench.layout import run_layout_bench

    emit(run_layout_bench(sizes, seeds, time_limit, hard, room_seeds, baseline), as_json)


@bench_app.command("pipeline")
def bench_pipeline(
    prompts: PromptsOption = None,
    limit: Annotated[int | None, typer.Option("--limit", help="Use only the first N prompts.")] = None,
    details: Annotated[bool, typer.Option("--details", help="Add per-prompt figures, misses and times.")] = False,
    room: Annotated[str, typer.Option("--room", help="The room of every prompt: auto, none, or WxD[xH].")] = "auto",
    as_json: JsonOption = True,
) -> None:
    """`generate --no-render` (offline, no cache) per annotated prompt: the final layouts scored
    against the text (relations realised, supports right, spread), the parse's figures, and seconds."""
    from scenewright.bench.evaluation import run_pipeline_bench

    emit(run_pipeline_bench(prompts, limit, details, build_settings(), room), as_json, indent=1 if details else None)


@bench_app.command("parse")
def bench_parse(
    prompts: Annotated[
        Path | None,
        typer.Option(
            "--prompts",
            help="Folder (or one file) of annotated prompts, benchmarks/prompts* format (default: benchmarks/prompts).",
        ),
    ] = None,
    details: Annotated[bool, typer.Option("--details", help="Add per-prompt misses and extras.")] = False,
    as_json: JsonOption = True,
) -> None:
    """Object and relation recall/precision of the offline parser on annotated descriptions."""
    from scenewright.bench.analysis import run_parse_bench

    emit(run_parse_bench(prompts, details=details), as_json, indent=1 if details else None)


@bench_app.command("constructions")
def bench_constructions(
    per_shape: Annotated[int, typer.Option("--per-shape", min=1, help="Sentences written of each shape.")] = 40,
    seed: Annotated[int, typer.Option("--seed", help="Which fillings: the same seed writes the same sentences.")] = 0,
    failures: Annotated[int, typer.Option("--failures", min=0, help="Misread sentences kept per shape.")] = 3,
    as_json: JsonOption = True,
) -> None:
    """How the offline parser reads English sentence shapes (fronted and inverted place phrases,
    absolute clauses, possessives, "each of"...) filled from word lists and annotated from how they
    were built: per shape, the figures of `bench parse` and the share read right. A coverage figure
    over sentences the project writes, not evidence on fresh text."""
    from scenewright.bench.constructions import run_constructions_bench

    emit(run_constructions_bench(per_shape, seed, failures), as_json, indent=1)


@bench_app.command("analysis")
def bench_analysis(
    objects: Annotated[int, typer.Option("--objects", min=1, help="Objects in the scene.")] = 15,
    latency: Annotated[
        float, typer.Option("--latency", min=0.0, help="Seconds the server takes per image call.")
    ] = 1.0,
    concurrency: Annotated[int, typer.Option("--concurrency", min=1, help="Image calls in flight at once.")] = 4,
    as_json: JsonOption = True,
) -> None:
    """Wall time of scene analysis over the OpenAI backends against a local server with latency."""
    from scenewright.bench.remote import run_analysis_bench

    emit(run_analysis_bench(objects, latency, concurrency), as_json)


@bench_app.command("assets")
def bench_assets(
    assets: Annotated[int, typer.Option("--assets", help="Objects to build.")] = 16,
    servers: Annotated[int, typer.Option("--servers", help="Local stand-in Hunyuan3D servers.")] = 4,
    delay: Annotated[float, typer.Option("--delay", help="Seconds each server takes per asset.")] = 2.0,
    poll: Annotated[float, typer.Option("--poll", help="Seconds between status polls.")] = 0.1,
    fault: Annotated[
        str, typer.Option("--fault", help="What the first server does: none | transient | reject | permanent.")
    ] = "transient",
    as_json: JsonOption = True,
) -> None:
    """Wall time of the asset stage over local servers (one job each at a time) against the ideal."""
    from scenewright.bench.assets import run_assets_bench

    emit(run_assets_bench(assets, servers, delay, poll, fault), as_json)


@bench_app.command("edits")
def bench_edits(
    cases: Annotated[
        Path, typer.Option("--cases", help="A case file, or a folder of them (*.json, not its subfolders).")
    ] = Path("benchmarks/edits"),
    objects: Annotated[int, typer.Option("--objects", help="Objects in the latency scene.")] = 30,
    moves: Annotated[int, typer.Option("--moves", help="Move edits timed on the latency scene.")] = 20,
    as_json: JsonOption = True,
) -> None:
    """Offline planner accuracy on annotated instructions, and move-edit latency.

    ``move_resolve_median_s`` is the solver's time per move; ``move_edit_median_s`` the whole
    edit short of writing files (parse, meshes, solve); ``move_edit_first_s`` the first edit of
    the session, which also parses every asset."""
    from scenewright.bench.editing import run_edits_bench

    emit(run_edits_bench(cases, objects, moves), as_json)


@bench_app.command("eval")
def bench_eval(
    out: Annotated[Path, typer.Option("--out", help="Folder for table.md, report.json and chart.png.")] = Path(
        "bench-results/eval"
    ),
    prompts: Annotated[
        Path | None, typer.Option("--prompts", help="Folder of benchmark prompts (default: benchmarks/prompts).")
    ] = None,
    limit: Annotated[int | None, typer.Option("--limit", help="Use only the first N prompts of each domain.")] = None,
    as_json: JsonOption = True,
) -> None:
    """Generate the shipped prompts offline and score them, full pipeline vs without the solver."""
    from scenewright.bench.evaluation import run_eval_bench

    emit(run_eval_bench(out, prompts, limit, build_settings()), as_json)


@bench_app.command("physics")
def bench_physics(
    prompts: Annotated[
        Path | None, typer.Option("--prompts", help="Folder of prompt files (default: benchmarks/prompts).")
    ] = None,
    limit: Annotated[int | None, typer.Option("--limit", help="Use only the first N prompts.")] = None,
    repeats: Annotated[int, typer.Option("--repeats", help="Timed export + settle runs.")] = 5,
    as_json: JsonOption = True,
) -> None:
    """Stability after a 2 s settle on the shipped prompts, and export + settle seconds of the bundled
    example (15 objects, all of them dynamic)."""
    from scenewright.bench.physics import run_physics_bench

    emit(run_physics_bench(prompts, limit, repeats, build_settings()), as_json)


@bench_app.command("batch")
def bench_batch(
    scenes: Annotated[int, typer.Option("--scenes", min=1, help="Scenes per run (the first shipped prompts).")] = 8,
    workers: Annotated[str, typer.Option("--workers", help="Worker counts to time, comma separated.")] = "1,2",
    ray: Annotated[bool, typer.Option("--ray/--no-ray", help="Also time Ray (needs the batch extra).")] = True,
    as_json: JsonOption = True,
) -> None:
    """Scenes per minute offline with --no-render for each worker count, and Ray's overhead
    per scene against the process pool; with CPU times and the load, since cores are shared."""
    from scenewright.bench.batch import run_batch_bench

    emit(run_batch_bench(scenes, workers, ray, build_settings()), as_json)


@bench_app.command("studio")
def bench_studio(
    objects: Annotated[int, typer.Option("--objects", min=1, help="Objects of the large scene the drag is timed on.")] = 100,
    seconds: Annotated[float, typer.Option("--seconds", min=0.5, help="How long the drag lasts.")] = 5.0,
    rate: Annotated[float, typer.Option("--rate", min=1.0, help="Gizmo updates the page sends per second.")] = 60.0,
    runs: Annotated[int, typer.Option("--runs", min=1, help="Reloads timed after each first visit.")] = 3,
    as_json: JsonOption = True,
) -> None:
    """Initial load of the demo scene and drag updates per second on a large scene, in headless
    chromium (software WebGL); with a bare viser page's load and the load average for scale."""
    import contextlib
    import sys

    from scenewright.bench.studio import run

    with contextlib.redirect_stdout(sys.stderr):  # viser's banners: stdout carries the figures only
        result = run(objects=objects, seconds=seconds, rate=rate, runs=runs)
    emit(result, as_json)
