"""Text from outside (model answers, file names, server messages) made safe to print.

A model names objects, a server writes error messages, a user names folders: printed raw,
``[red]`` in a name would restyle the terminal output (or raise a markup error) and an escape
sequence could rewrite the screen. Every CLI message passes what it did not write itself
through :func:`safe` (for Rich) or :func:`printable` (for plain output).
"""

from __future__ import annotations

import re

from rich.markup import escape

#: C0 and C1 control characters and DEL, except the newline and tab that lay out messages.
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")


def printable(text: object) -> str:
    """``text`` without control characters (each becomes ``?``)."""
    return _CONTROL.sub("?", str(text))


def safe(text: object) -> str:
    """``text`` as Rich prints it literally: no control characters, markup escaped."""
    return escape(printable(text))
