"""Command line: ``scenewright generate|batch|solve|edit|undo|redo|history|render|evaluate|studio|bench``.

Each command lives in the module named for what it drives; importing them registers them on
:data:`scenewright.cli.app.app`. Library errors become one readable line and an exit code:
2 for bad input, 1 for a backend failure, 3 for an infeasible layout.
"""

from __future__ import annotations

import logging
import sys

import typer
from rich.console import Console
from rich.markup import escape

from scenewright.cli import assets, backends, batch, edit, evaluate, generate, parse, remote, render, solve, studio  # noqa: F401
from scenewright.cli.app import app
from scenewright.errors import BackendError, InfeasibleLayout, InputError, ScenewrightError

EXIT_BAD_INPUT = 2
EXIT_BACKEND = 1
EXIT_INFEASIBLE = 3


def main(argv: list[str] | None = None) -> int:
    logging.basicConfig(level=logging.WARNING, format="%(levelname)s %(name)s: %(message)s")
    err = Console(stderr=True, soft_wrap=True)
    try:
        # A command that ends with typer.Exit(code) (batch: some scenes failed) returns its code.
        code = app(args=argv, prog_name="scenewright", standalone_mode=False)
    except InputError as exc:
        err.print(f"[red]error:[/red] {escape(str(exc))}", highlight=False)
        return EXIT_BAD_INPUT
    except InfeasibleLayout as exc:
        err.print(f"[yellow]layout incomplete:[/yellow] {escape(str(exc))}", highlight=False)
        return EXIT_INFEASIBLE
    except BackendError as exc:
        err.print(f"[red]backend error:[/red] {escape(str(exc))}", highlight=False)
        return EXIT_BACKEND
    except ScenewrightError as exc:
        err.print(f"[red]error:[/red] {escape(str(exc))}", highlight=False)
        return EXIT_BACKEND
    except typer.Abort:  # Ctrl-C at a prompt
        return 130
    except typer.TyperException as exc:  # usage errors (unknown option, missing argument) with standalone_mode=False
        exc.show()
        return EXIT_BAD_INPUT
    return code if isinstance(code, int) else 0


def run() -> None:
    sys.exit(main())
