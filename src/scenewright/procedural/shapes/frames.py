"""Frames shared by several shapes: rings of beams around a lattice's legs."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from scenewright.core.catalogue import POST
from scenewright.procedural.builder import Model


def ring(m: Model, role: str, corners: Sequence, width: float) -> None:
    """Beams of ``width`` joining each corner to the next, round the closed ring.

    Each stops half its width short of both corners: two beams meeting at a corner would
    otherwise overlap there and share their top and bottom faces, a flickering patch in
    every renderer (tests/test_procedural_coplanar.py). The leg standing at the corner,
    wider than the beam, fills the gap.
    """
    points = [np.asarray(c, float) for c in corners]
    for a, b in zip(points, points[1:] + points[:1]):
        inward = 0.5 * width * (b - a) / np.linalg.norm(b - a)
        m.beam(role, a + inward, b - inward, width)


def on_post(m: Model, build) -> None:
    """``build``'s thing at the top of the box, :data:`POST` m up, on a round post with a foot
    plate behind its middle: a station clock, a lifebuoy stand, a sign board on a pole."""
    face = max(m.sz - POST, 0.25 * m.sz)
    r = min(0.05, 0.25 * m.sy, 0.15 * m.sx)
    m.inset(build, (0.0, 0.0, m.sz - face), (m.sx, m.sy, face))
    y = m.sy / 2 - r
    m.post("dark_metal", 0.0, y, 0.03, m.sz - 0.5 * face, r)
    m.box("dark_metal", (-2.5 * r, y - 2.5 * r, 0.0), (2.5 * r, min(y + 2.5 * r, m.sy / 2), 0.03), rounded=0.0)
