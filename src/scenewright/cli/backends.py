"""``scenewright backends``: which backends this installation can use, and with ``--check``,
what an OpenAI-compatible server supports (before a run pays for anything on it)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.table import Table

from scenewright.cli.app import app
from scenewright.cli.display import safe
from scenewright.cli.options import ApiKeyEnvOption, BaseUrlOption, ConfigOption, TimeoutOption


@app.command("backends")
def list_backends(
    check: Annotated[
        bool,
        typer.Option("--check", help="Ask the server at --base-url what it supports (tiny requests, no generation)."),
    ] = False,
    base_url: BaseUrlOption = None,
    model: Annotated[
        str | None, typer.Option("--model", help="Model to check (default: the --vlm model of the settings).")
    ] = None,
    api_key_env: ApiKeyEnvOption = None,
    timeout: TimeoutOption = None,
    config: ConfigOption = None,
    json_output: Annotated[bool, typer.Option("--json", help="Print the check as JSON.")] = False,
) -> None:
    """List every backend by kind, with what is missing for the ones that cannot run here."""
    if check:
        _check(base_url, model, api_key_env, timeout, config, json_output)
        return
    from scenewright.backends import DEFAULTS, available_backends

    table = Table("kind", "backend", "status")
    for kind, names in available_backends().items():
        for name, status in names.items():
            label = f"{name} (default)" if DEFAULTS[kind] == name else name
            table.add_row(kind, label, "[green]ok[/green]" if status == "ok" else f"[red]{safe(status)}[/red]")
    Console().print(table)


def _check(
    base_url: str | None, model: str | None, api_key_env: str | None, timeout: float | None,
    config: Path | None, json_output: bool,
) -> None:
    """The server's capabilities for one model: json_schema, json_object, images, reasoning."""
    from scenewright.backends.openai_chat import DEFAULT_MODEL
    from scenewright.backends.probe import check_server
    from scenewright.backends.structured import model_name, openai_client
    from scenewright.cli.options import build_settings

    settings = build_settings(base_url=base_url, config=config, api_key_env=api_key_env, timeout=timeout)
    if model is None:
        name, _, argument = settings.vlm.partition(":")
        model = argument if name == "openai" and argument else DEFAULT_MODEL
    settings.max_retries = 0  # a probe is asked once: its failure is the answer
    report = check_server(openai_client(settings), settings.base_url or "api.openai.com", model_name(model, model))
    if json_output:
        typer.echo(json.dumps(report))
        return
    table = Table("capability", "status", title=safe(f"{report['server']} · {report['model']}"))
    served = report["model_served"]
    table.add_row("model listed", "no model list" if served is None else ("yes" if served else "[red]no[/red]"))
    for capability in ("json_schema", "json_object", "images", "reasoning"):
        status = str(report[capability])
        colour = "green" if status == "supported" else "yellow" if status.startswith("ignored") else "red"
        table.add_row(capability, f"[{colour}]{safe(status)}[/{colour}]")
    Console().print(table)
