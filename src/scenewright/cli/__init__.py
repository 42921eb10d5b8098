"""Command line: ``scenewright generate|batch|solve|edit|undo|redo|history|render|evaluate|export|studio|bench``.

Each command lives in the module named for what it drives; importing them registers them on
:data:`scenewright.cli.app.app`. Library errors become one readable line and an exit code:
2 for bad input, 1 for a backend failure, 3 for an infeasible layout.
"""

from __future__ import annotations

import logging
import sys

import typer
from rich.console import Console

from scenewright.cli import (  # noqa: F401  (importing a command module registers it)
    backends, batch, bench, edit, evaluate, export, generate, render, solve, studio,
)
from scenewright.cli.app import app, interrupt_hint
from scenewright.cli.display import safe
from scenewright.errors import BackendError, InfeasibleLayout, InputError, ScenewrightError

EXIT_BAD_INPUT = 2
EXIT_BACKEND = 1
EXIT_INFEASIBLE = 3
#: A shell's code for a command stopped by Ctrl-C (128 + SIGINT).
EXIT_INTERRUPTED = 130


def main(argv: list[str] | None = None) -> int:
    logging.basicConfig(level=logging.WARNING, format="%(levelname)s %(name)s: %(message)s")
    err = Console(stderr=True, soft_wrap=True)
    interrupt_hint.clear()
    try:
        # Typer turns Ctrl-C into this return value, and a typer.Exit (batch: some scenes failed)
        # into its code.
        code = app(args=argv, prog_name="scenewright", standalone_mode=False)
    except InputError as exc:
        err.print(f"[red]error:[/red] {safe(exc)}", highlight=False)
        return EXIT_BAD_INPUT
    except InfeasibleLayout as exc:
        err.print(f"[yellow]layout incomplete:[/yellow] {safe(exc)}", highlight=False)
        return EXIT_INFEASIBLE
    except BackendError as exc:
        err.print(f"[red]backend error:[/red] {safe(exc)}", highlight=False)
        return EXIT_BACKEND
    except ScenewrightError as exc:
        err.print(f"[red]error:[/red] {safe(exc)}", highlight=False)
        return EXIT_BACKEND
    except OSError as exc:  # a read-only or full disk, a folder where a file should be: the user's to fix
        where = f"{exc.filename}: " if exc.filename else ""
        err.print(f"[red]error:[/red] {safe(where)}{safe(exc.strerror or exc)}", highlight=False)
        return EXIT_BAD_INPUT
    except typer.Abort:  # Ctrl-C at a prompt
        code = EXIT_INTERRUPTED
    except typer.TyperException as exc:  # usage errors (unknown option, missing argument) with standalone_mode=False
        exc.show()
        return EXIT_BAD_INPUT
    if code == EXIT_INTERRUPTED:
        hint = interrupt_hint["hint"]() if "hint" in interrupt_hint else None
        err.print(f"[yellow]interrupted[/yellow]{'; ' + safe(hint) if hint else ''}", highlight=False)
    return code if isinstance(code, int) else 0


def run() -> None:
    sys.exit(main())
