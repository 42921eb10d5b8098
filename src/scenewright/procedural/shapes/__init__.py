"""One generator per shape of the catalogue's vocabulary.

A generator is ``generator(model: Model) -> None``: it draws the object's parts into the
model inside the requested size box (see :mod:`scenewright.procedural.builder`).
"""

from __future__ import annotations

from collections.abc import Callable

from scenewright.procedural.builder import Model
from scenewright.procedural.shapes import buildings, creatures, furniture, generic, machines, outdoor, props, structures, vehicles


def _collect() -> dict[str, Callable[[Model], None]]:
    table: dict[str, Callable[[Model], None]] = {}
    for module in (furniture, props, outdoor, vehicles, buildings, creatures, machines, structures, generic):
        clash = table.keys() & module.SHAPES.keys()
        assert not clash, f"shape defined twice: {clash}"
        table.update(module.SHAPES)
    return table


SHAPES = _collect()
