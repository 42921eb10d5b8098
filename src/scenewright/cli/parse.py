"""``scenewright bench parse``: how well the offline parser reads annotated descriptions.

``bench pipeline`` (in :mod:`scenewright.cli.generate`) scores the final layouts of the same
prompts; the two together are how a fresh batch is scored.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated

import typer

from scenewright.cli.app import bench_app


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
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON (the only output format).")] = True,
) -> None:
    """Object and relation recall/precision of the offline parser on annotated descriptions."""
    from scenewright.analysis.bench import run_parse_bench

    typer.echo(json.dumps(run_parse_bench(prompts, details=details), indent=None if not details else 1))
