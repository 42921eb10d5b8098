"""``scenewright export DIR --format usd|mjcf|glb-physics``; ``bench physics``: stability and export speed."""

from __future__ import annotations

import json
import statistics
import tempfile
import time
from pathlib import Path
from typing import Annotated

import typer

from scenewright.cli.app import app, bench_app
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


@bench_app.command("physics")
def bench_physics(
    prompts: Annotated[
        Path | None, typer.Option("--prompts", help="Folder of prompt files (default: benchmarks/prompts).")
    ] = None,
    limit: Annotated[int | None, typer.Option("--limit", help="Use only the first N prompts.")] = None,
    repeats: Annotated[int, typer.Option("--repeats", help="Timed export + settle runs.")] = 5,
    json_output: Annotated[bool, typer.Option("--json", help="Print JSON (the only output format).")] = True,
) -> None:
    """Stability after a 2 s settle on the shipped prompts, and export + settle seconds of the bundled
    example (15 objects, all of them dynamic)."""
    from scenewright.analysis.bench import load_prompts
    from scenewright.backends import backends_from_settings
    from scenewright.cache import RequestCache
    from scenewright.cli.generate import _example_text
    from scenewright.evaluation.stability import load_mujoco, stability
    from scenewright.export.sim import export_scene
    from scenewright.folder import SceneFolder
    from scenewright.pipeline import generate

    load_mujoco()
    chosen = load_prompts(prompts)[:limit]
    settings = build_settings()
    backends = backends_from_settings(settings)
    scenes = []
    with tempfile.TemporaryDirectory(prefix="scenewright-physics-") as tmp:
        cache = RequestCache(Path(tmp) / "cache")
        settings.cache_dir = cache.root
        for prompt in chosen:
            folder = SceneFolder(Path(tmp) / prompt.id)
            scene = generate(prompt.text, folder, backends=backends, settings=settings, style=prompt.style, render=False)
            result = stability(scene, folder, cache)
            scenes.append({"id": prompt.id, "objects": len(scene.objects)} | result.to_dict())
        folder = SceneFolder(Path(tmp) / "example")
        scene = generate(_example_text(), folder, backends=backends, settings=settings, render=False)
        seconds = []
        for _ in range(repeats):
            # Fresh derivation each time: the cache would hide the cost of the colliders.
            for obj in scene.objects:
                obj.physics = None
            run_cache = RequestCache(Path(tmp) / f"cache-{len(seconds)}")
            start = time.perf_counter()
            export_scene(scene, folder, "mjcf", run_cache)
            export_scene(scene, folder, "usd", run_cache)
            timed = stability(scene, folder, run_cache)
            seconds.append(time.perf_counter() - start)
    dynamic = sum(s["dynamic"] for s in scenes)
    stable = sum(s["stable_objects"] for s in scenes)
    worst = sorted((u | {"scene": s["id"]} for s in scenes for u in s["unstable"]), key=lambda u: -u["shift_m"])
    result = {
        "prompts": len(scenes),
        "dynamic_objects": dynamic,
        "static_objects": sum(len(s["static"]) for s in scenes),
        "stable_objects_pct": round(100.0 * stable / dynamic, 2) if dynamic else None,
        "stable_scenes_pct": round(100.0 * sum(s["stable"] for s in scenes) / len(scenes), 2) if scenes else None,
        "worst": worst[:10],
        "timed_scene": {"id": "example", "objects": len(scene.objects), "dynamic": len(timed.objects)} if seconds else None,
        "export_settle_median_seconds": round(statistics.median(seconds), 3) if seconds else None,
        "export_settle_runs": [round(s, 3) for s in seconds],
    }
    typer.echo(json.dumps(result))
