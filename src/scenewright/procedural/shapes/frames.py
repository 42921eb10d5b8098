"""Frames shared by several shapes: rings of beams around a lattice's legs."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

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
