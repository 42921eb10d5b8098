"""The bundled example description (``generate --example``, and the scene the physics benchmark times)."""

from __future__ import annotations

from importlib import resources

EXAMPLE = "living_room.txt"


def example_text() -> str:
    return (resources.files("scenewright") / "data" / "examples" / EXAMPLE).read_text(encoding="utf-8")
