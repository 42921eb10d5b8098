"""``scenewright evaluate DIR...``: the paper's metrics on scene folders; ``bench eval``: full vs w/o solver."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from scenewright.cli.app import app
from scenewright.cli.display import printable
from scenewright.errors import InputError
from scenewright.cli.options import (
    ApiKeyEnvOption,
    BaseUrlOption,
    ConfigOption,
    VlmOption,
    build_settings,
)


def _clip(weights: Path | None):
    from scenewright.evaluation.perceptual import ClipScorer

    return ClipScorer(weights) if weights is not None else None


@app.command("evaluate")
def evaluate_command(
    directories: Annotated[list[Path], typer.Argument(help="Scene folders to score.")],
    out: Annotated[Path, typer.Option("--out", help="Folder for report.json, table.md and chart.png.")],
    ablation: Annotated[
        bool,
        typer.Option("--ablation", help="Also score each scene at the model's initial poses, as before the solver."),
    ] = False,
    clip_weights: Annotated[
        Path | None, typer.Option("--clip-weights", help="Local open_clip ViT-B/32 checkpoint for the CLIP score.")
    ] = None,
    judge: Annotated[
        bool, typer.Option("--judge", help="Ask the vision-language backend for Pos., Rot. and SA on the renders.")
    ] = False,
    group: Annotated[str, typer.Option("--group", help="Name of this set of scenes in the table.")] = "scenes",
    annotations: Annotated[
        Path | None,
        typer.Option(
            "--annotations",
            help="An annotated prompt file or a folder of them (benchmarks/prompts* format): also check the "
            "relations the text states and the supports in each scene whose text or folder name matches one.",
        ),
    ] = None,
    vlm: VlmOption = None,
    base_url: BaseUrlOption = None,
    api_key_env: ApiKeyEnvOption = None,
    config: ConfigOption = None,
) -> None:
    """Collisions (CF, CN), unsupported and out-of-bounds objects, spread of the ground objects, the
    parser's constraints held, and with --annotations the relations the text states that hold; CLIP, judge."""
    from scenewright.backends import create_backend
    from scenewright.evaluation import evaluate
    from scenewright.evaluation.annotations import load_prompts
    from scenewright.evaluation.report import write_report

    if out.exists() and not out.is_dir():
        raise InputError(f"--out {out} is a file; give a folder for report.json, table.md and chart.png")
    settings = build_settings(vlm=vlm, base_url=base_url, config=config, api_key_env=api_key_env)
    results = evaluate(
        directories,
        group=group,
        ablation=ablation,
        clip=_clip(clip_weights),
        judge_vlm=create_backend("vlm", settings.vlm, settings) if judge else None,
        annotations=load_prompts(annotations) if annotations is not None else None,
    )
    paths = write_report(results, out, paper=False)
    typer.echo(printable(paths["table"].read_text(encoding="utf-8")))
    typer.echo(printable(f"wrote {', '.join(str(p) for p in paths.values())}"), err=True)
