"""``scenewright backends``: which backends this installation can use."""

from __future__ import annotations

from rich.console import Console
from rich.table import Table

from scenewright.cli.app import app
from scenewright.cli.display import safe


@app.command("backends")
def list_backends() -> None:
    """List every backend by kind, with what is missing for the ones that cannot run here."""
    from scenewright.backends import DEFAULTS, available_backends

    table = Table("kind", "backend", "status")
    for kind, names in available_backends().items():
        for name, status in names.items():
            label = f"{name} (default)" if DEFAULTS[kind] == name else name
            table.add_row(kind, label, "[green]ok[/green]" if status == "ok" else f"[red]{safe(status)}[/red]")
    Console().print(table)
