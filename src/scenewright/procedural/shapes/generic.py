"""The fallback shape: soft things and instruments the catalogue files under ``generic``,
the family a name calls (animals, craft, figures...), and a plain plinthed block for a name
with no hint at all."""

from __future__ import annotations

from scenewright.procedural.builder import Model
from scenewright.procedural.shapes.families import FAMILIES, family_of


def _guitar(m: Model) -> None:
    m.main = "wood"
    t = 0.8 * m.sy
    lo = 0.3 * m.sz
    m.cylinder("wood", (0, -t / 2, 0.2 * m.sz), (0, t / 2, 0.2 * m.sz), 0.22 * m.sz * min(1.0, m.sx / (0.44 * m.sz)), fraction=1)
    # The upper bout a little thinner than the lower: their overlapping faces would share a plane.
    m.cylinder("wood", (0, -0.45 * t, 0.42 * m.sz), (0, 0.45 * t, 0.42 * m.sz), 0.16 * m.sz * min(1.0, m.sx / (0.44 * m.sz)), fraction=1)
    m.cylinder("dark_plastic", (0, -t / 2 - 0.005, 0.3 * m.sz), (0, -t / 2, 0.3 * m.sz), 0.06 * m.sz, fraction=0.6)
    m.box("dark_wood", (-0.03 * m.sx, -0.1 * m.sy, lo), (0.03 * m.sx, 0.1 * m.sy, 0.88 * m.sz))
    m.box("dark_wood", (-0.06 * m.sx, -0.1 * m.sy, 0.88 * m.sz), (0.06 * m.sx, 0.15 * m.sy, m.sz))


def _cushion(m: Model) -> None:
    m.main = "fabric"
    m.box("fabric", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, m.sz), rounded=0.45 * min(m.sx, m.sy, m.sz))


def _curtain(m: Model) -> None:
    m.main = "fabric"
    folds = max(3, int(m.sx / 0.15))
    w = m.sx / folds
    for i in range(folds):
        x = -m.sx / 2 + (i + 0.5) * w
        y = (0.25 if i % 2 else -0.25) * m.sy
        m.cylinder("fabric", (x, y, 0.02 * m.sz), (x, y, 0.96 * m.sz), 0.55 * w, fraction=0.5)
    m.cylinder("metal", (-m.sx / 2, 0, 0.98 * m.sz), (m.sx / 2, 0, 0.98 * m.sz), 0.02 * m.sz, fraction=0.4)


def _lifebuoy(m: Model) -> None:
    m.main = "paint"
    r = min(m.sx, m.sz) / 2
    m.torus("paint", (0, 0, r), 0.75 * r, 0.25 * r, axis="y")


def generic(m: Model) -> None:
    """Soft things and instruments by name; else the family the name calls (a horse the
    catalogue files here is an animal); only a name with no hint at all gets the block."""
    variants = (
        (("guitar", "violin", "cello"), _guitar),
        (("cushion", "pillow", "pouf"), _cushion),
        (("curtain", "drape"), _curtain),
        (("lifebuoy", "life ring", "tyre", "tire"), _lifebuoy),
    )
    for words, build in variants:
        if m.named(*words):
            build(m)
            return
    family = family_of(m.name)
    if family is not None:
        FAMILIES[family](m)
        return
    m.main = "plastic"
    base = 0.08 * m.sz
    m.box("dark_plastic", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, base))
    m.box("plastic", (-0.46 * m.sx, -0.46 * m.sy, base), (0.46 * m.sx, 0.46 * m.sy, m.sz),
          rounded=max(0.06 * min(m.sx, m.sy, m.sz), 0.01))
    m.box("accent", (-0.3 * m.sx, -0.47 * m.sy, 0.6 * m.sz), (0.3 * m.sx, -0.46 * m.sy, 0.7 * m.sz), rounded=0.0)


SHAPES = {"generic": generic}
