"""The fallback shape: creatures, craft and soft things the catalogue files under ``generic``,
and a plain plinthed block for whatever is left."""

from __future__ import annotations

import numpy as np

from scenewright.procedural.builder import Model


def _quadruped(m: Model) -> None:
    """A four-legged animal facing −Y: body, legs, neck, head, ears, tail."""
    m.main = "fur"
    horse = m.named("horse", "pony", "donkey", "cow", "deer")
    leg_h = (0.5 if horse else 0.38) * m.sz
    body_r = (0.18 if horse else 0.22) * m.sz
    bx = 0.32 * m.sx
    m.ball("fur", (0, 0.05 * m.sy, leg_h + body_r * 0.8), (bx, 0.36 * m.sy, body_r), fraction=0.8)
    leg = m.thick(0.22 * bx, 0.3 * bx)
    for x in (-0.6 * bx, 0.6 * bx):
        for y in (-0.22 * m.sy, 0.3 * m.sy):
            m.cylinder("fur", (x, y, leg_h + body_r * 0.3), (x, y, 0.0), leg, leg * 0.75, fraction=0.5)
            m.ball("dark_plastic", (x, y - 0.2 * leg, 0.25 * leg), (leg * 0.85, leg * 1.2, 0.25 * leg), fraction=0.4)
    neck_base = np.array([0, -0.26 * m.sy, leg_h + body_r * 1.1])
    head = np.array([0, -0.4 * m.sy, m.sz - 0.12 * m.sz])
    m.cylinder("fur", neck_base, head, 0.6 * bx if not horse else 0.45 * bx, 0.4 * bx, fraction=0.6)
    m.ball("fur", head + (0, -0.04 * m.sy, 0), (0.55 * bx, 0.1 * m.sy if horse else 0.07 * m.sy, 0.1 * m.sz), fraction=0.7)
    m.ball("dark_plastic", head + (0, -0.1 * m.sy - 0.03 * m.sy * horse, -0.02 * m.sz), (0.25 * bx, 0.05 * m.sy, 0.05 * m.sz),
           fraction=0.5)
    for s in (-1, 1):
        m.cylinder("fur", head + (s * 0.3 * bx, 0, 0.05 * m.sz), head + (s * 0.45 * bx, 0.02 * m.sy, m.sz - head[2]),
                   0.12 * bx, 0.02 * bx, fraction=0.4)
        m.ball("dark_plastic", head + (s * 0.3 * bx, -0.08 * m.sy, 0.03 * m.sz), (0.07 * bx,) * 3, fraction=0.4)
    m.cylinder("fur", (0, 0.4 * m.sy, leg_h + body_r), (0, m.sy / 2, leg_h + body_r * (0.2 if horse else 1.6)), 0.1 * bx,
               0.05 * bx, fraction=0.4)


def _bird(m: Model) -> None:
    m.main = "fur"
    m.ball("fur", (0, 0.05 * m.sy, 0.45 * m.sz), (0.3 * m.sx, 0.4 * m.sy, 0.28 * m.sz))
    m.ball("fur", (0, -0.25 * m.sy, 0.78 * m.sz), (0.2 * m.sx, 0.2 * m.sy, 0.2 * m.sz))
    m.cylinder("accent", (0, -0.4 * m.sy, 0.78 * m.sz), (0, -m.sy / 2, 0.75 * m.sz), 0.05 * m.sx, 0.0, fraction=0.4)
    for s in (-1, 1):
        m.ball("fur", (s * 0.35 * m.sx, 0.1 * m.sy, 0.5 * m.sz), (0.15 * m.sx, 0.35 * m.sy, 0.12 * m.sz), fraction=0.6)
        m.ball("dark_plastic", (s * 0.12 * m.sx, -0.38 * m.sy, 0.83 * m.sz), (0.04 * m.sx,) * 3, fraction=0.4)
        m.cylinder("accent", (s * 0.1 * m.sx, 0, 0.2 * m.sz), (s * 0.1 * m.sx, 0, 0), 0.02 * m.sx, fraction=0.3)
    m.ball("fur", (0, 0.45 * m.sy, 0.4 * m.sz), (0.15 * m.sx, 0.1 * m.sy, 0.05 * m.sz), fraction=0.5)


def _craft(m: Model) -> None:
    """A spaceship or drone: a hull, wings or rotor arms, glowing engines."""
    m.main = "metal"
    if m.named("drone", "quadcopter"):
        m.box("dark_plastic", (-0.2 * m.sx, -0.2 * m.sy, 0.3 * m.sz), (0.2 * m.sx, 0.2 * m.sy, 0.7 * m.sz))
        for sx in (-1, 1):
            for sy in (-1, 1):
                c = np.array([sx * 0.35 * m.sx, sy * 0.35 * m.sy, 0.75 * m.sz])
                m.beam("dark_plastic", (0, 0, 0.55 * m.sz), c, 0.05 * m.sx)
                m.lathe("glass", [(0.15 * m.sx, 0.9 * m.sz), (0.15 * m.sx, m.sz)], centre=(c[0], c[1], 0))
                m.cylinder("metal", c, c + (0, 0, 0.1 * m.sz), 0.03 * m.sx, fraction=0.5)
        m.ball("light", (0, -0.2 * m.sy, 0.5 * m.sz), (0.05 * m.sx,) * 3, fraction=0.4)
        m.post("dark_plastic", -0.1 * m.sx, 0, 0, 0.3 * m.sz, 0.02 * m.sx)
        m.post("dark_plastic", 0.1 * m.sx, 0, 0, 0.3 * m.sz, 0.02 * m.sx)
        return
    m.ball("metal", (0, 0, 0.5 * m.sz), (0.2 * m.sx, 0.5 * m.sy, 0.25 * m.sz))
    m.ball("glass", (0, -0.2 * m.sy, 0.65 * m.sz), (0.1 * m.sx, 0.18 * m.sy, 0.12 * m.sz), fraction=0.6)
    m.extrude("paint", [(-m.sx / 2, 0.35 * m.sy), (-0.1 * m.sx, -0.2 * m.sy), (0.1 * m.sx, -0.2 * m.sy), (m.sx / 2, 0.35 * m.sy),
                        (m.sx / 2, 0.45 * m.sy), (-m.sx / 2, 0.45 * m.sy)], "z", 0.4 * m.sz, 0.47 * m.sz)
    m.extrude("paint", [(0.2 * m.sy, 0.5 * m.sz), (0.45 * m.sy, 0.5 * m.sz), (0.48 * m.sy, m.sz), (0.38 * m.sy, m.sz)],
              "x", -0.02 * m.sx, 0.02 * m.sx)
    for s in (-1, 1):
        m.cylinder("light", (s * 0.1 * m.sx, 0.45 * m.sy, 0.45 * m.sz), (s * 0.1 * m.sx, m.sy / 2, 0.45 * m.sz), 0.06 * m.sx)
    for x in (-0.15 * m.sx, 0.15 * m.sx):
        m.post("dark_metal", x, 0, 0, 0.3 * m.sz, 0.02 * m.sx, fraction=0.4)


def _guitar(m: Model) -> None:
    m.main = "wood"
    t = 0.8 * m.sy
    lo = 0.3 * m.sz
    m.cylinder("wood", (0, -t / 2, 0.2 * m.sz), (0, t / 2, 0.2 * m.sz), 0.22 * m.sz * min(1.0, m.sx / (0.44 * m.sz)), fraction=1)
    m.cylinder("wood", (0, -t / 2, 0.42 * m.sz), (0, t / 2, 0.42 * m.sz), 0.16 * m.sz * min(1.0, m.sx / (0.44 * m.sz)), fraction=1)
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
    variants = (
        (("dog", "cat", "horse", "pony", "donkey", "cow", "deer", "fox", "wolf", "sheep", "goat", "pig", "lion", "tiger"),
         _quadruped),
        (("bird", "parrot", "duck", "chicken", "owl", "pigeon", "penguin"), _bird),
        (("spaceship", "spacecraft", "starship", "drone", "jet", "airplane", "plane"), _craft),
        (("guitar", "violin", "cello"), _guitar),
        (("cushion", "pillow", "pouf"), _cushion),
        (("curtain", "drape"), _curtain),
        (("lifebuoy", "life ring", "tyre", "tire"), _lifebuoy),
    )
    for words, build in variants:
        if m.named(*words):
            build(m)
            return
    m.main = "plastic"
    base = 0.08 * m.sz
    m.box("dark_plastic", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, base))
    m.box("plastic", (-0.46 * m.sx, -0.46 * m.sy, base), (0.46 * m.sx, 0.46 * m.sy, m.sz),
          rounded=max(0.06 * min(m.sx, m.sy, m.sz), 0.01))
    m.box("accent", (-0.3 * m.sx, -0.47 * m.sy, 0.6 * m.sz), (0.3 * m.sx, -0.46 * m.sy, 0.7 * m.sz), rounded=0.0)


SHAPES = {"generic": generic}
