"""A placed object's footprint while the arranger works: centre, yaw, and the axis-aligned box
around its turned footprint (conservative for any yaw, exact at quarter turns)."""

from __future__ import annotations

import math
from collections.abc import Iterable

#: Walking room between things the arranger sets out side by side.
GAP = 0.3
#: m, between things set side by side on one top (crates on a pallet, plates on a table).
TOP_GAP = 0.05


def fits_across(room: float, length: float) -> int:
    """How many things ``length`` long stand side by side on a top ``room`` long: each centre
    over the top, none hanging over it by more than a quarter of itself."""
    return max(1, int((room + length / 4) / (length + TOP_GAP)))


class Footprint:
    __slots__ = ("d", "h", "size", "w", "x", "y", "yaw", "z")

    def __init__(self, x: float, y: float, z: float, yaw: float, size: tuple[float, float, float]):
        self.x, self.y, self.z, self.size = x, y, z, size
        self.turn(yaw)

    def turn(self, yaw: float) -> None:
        self.yaw = normal_yaw(yaw)
        c, s = abs(math.cos(math.radians(self.yaw))), abs(math.sin(math.radians(self.yaw)))
        c, s = (0.0 if c < 1e-9 else c), (0.0 if s < 1e-9 else s)  # quarter turns stay exact
        self.w = c * self.size[0] + s * self.size[1]
        self.d = s * self.size[0] + c * self.size[1]
        self.h = self.size[2]

    @property
    def bottom(self) -> float:
        return self.z - self.h / 2

    def overlaps(self, other: Footprint, margin: float = 0.05) -> bool:
        """Whether the two boxes come closer than ``margin`` in plan and share some height."""
        return (
            abs(self.x - other.x) < (self.w + other.w) / 2 + margin
            and abs(self.y - other.y) < (self.d + other.d) / 2 + margin
            and self.z - self.h / 2 < other.z + other.h / 2
            and other.z - other.h / 2 < self.z + self.h / 2
        )

    def plan_overlaps(self, other: Footprint, margin: float = 0.05) -> bool:
        """Whether the two footprints come closer than ``margin``, whatever their heights."""
        return abs(self.x - other.x) < (self.w + other.w) / 2 + margin and abs(self.y - other.y) < (
            self.d + other.d
        ) / 2 + margin

    def local_to_world(self, lx: float, ly: float) -> tuple[float, float]:
        """A point given in this object's frame (x right, y back at yaw 0) in the scene frame."""
        c, s = math.cos(math.radians(self.yaw)), math.sin(math.radians(self.yaw))
        return self.x + c * lx - s * ly, self.y + s * lx + c * ly


def normal_yaw(yaw: float) -> float:
    """The yaw in (−180, 180], with −0 and round-off made 0."""
    yaw = (yaw + 180.0) % 360.0 - 180.0
    if abs(yaw + 180.0) < 1e-9:
        yaw = 180.0
    return 0.0 if abs(yaw) < 1e-9 else yaw


def clear(p: Footprint, others: Iterable[Footprint], margin: float = 0.05) -> bool:
    return not any(p.overlaps(q, margin) for q in others)


def bbox(prints: Iterable[Footprint]) -> tuple[float, float, float, float]:
    """(min x, min y, max x, max y) of the footprints; zeros when there are none."""
    prints = list(prints)
    if not prints:
        return 0.0, 0.0, 0.0, 0.0
    return (
        min(p.x - p.w / 2 for p in prints),
        min(p.y - p.d / 2 for p in prints),
        max(p.x + p.w / 2 for p in prints),
        max(p.y + p.d / 2 for p in prints),
    )


def push(p: Footprint, direction: tuple[float, float], others: list[Footprint], step: float = 0.25) -> Footprint:
    """Move ``p`` along ``direction`` until it is clear of ``others``."""
    dx, dy = direction
    norm = math.hypot(dx, dy)
    dx, dy = (1.0, 0.0) if norm < 1e-9 else (dx / norm, dy / norm)
    for _ in range(400):
        if clear(p, others):
            return p
        p.x += dx * step
        p.y += dy * step
    return p
