"""The Typer application and its ``bench`` group; command modules attach to these."""

from __future__ import annotations

from collections.abc import Callable

import typer

app = typer.Typer(
    name="scenewright",
    help="Text in, an editable 3D scene out: styled objects, laid out by their relations, one GLB.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)
bench_app = typer.Typer(help="Benchmarks; each prints one JSON object.", no_args_is_help=True)
app.add_typer(bench_app, name="bench")


#: How to go on when Ctrl-C stops the running command, worked out when it happens (what to say
#: may depend on how far the command got); a command that writes sets it.
interrupt_hint: dict[str, Callable[[], str]] = {}


def on_interrupt(hint: Callable[[], str]) -> None:
    interrupt_hint["hint"] = hint
