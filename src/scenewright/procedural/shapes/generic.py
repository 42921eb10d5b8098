"""The fallback shape: soft things, instruments, pumpkins, cabbages, balls, ramps, goals, chimneys,
rails, orreries and party balloons (things with no family),
the family a name calls (animals, craft, figures...), and a lump under a dust sheet for a
name with no hint at all."""

from __future__ import annotations

import re

import numpy as np

from scenewright.procedural.builder import Model
from scenewright.procedural.shapes import outdoor, structures
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
    """Upright as it hangs on a rail; lying flat when it is low (a swim ring on the water)."""
    m.main = "paint"
    if m.sz < 0.5 * min(m.sx, m.sy):
        r = min(m.sx, m.sy) / 2
        m.torus("paint", (0, 0, m.sz / 2), r - m.sz / 2, m.sz / 2)
        return
    r = min(m.sx, m.sz) / 2
    m.torus("paint", (0, 0, r), 0.75 * r, 0.25 * r, axis="y")


def _pumpkin(m: Model) -> None:
    """A pumpkin (or gourd, melon): ribbed lobes round a core, a woody stalk and a leaf."""
    m.main = "flower_alt"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    lobes = 8
    for k in range(lobes):
        a = 2 * np.pi * k / lobes
        m.ball("flower_alt", (0.45 * W * np.cos(a), 0.45 * D * np.sin(a), 0.45 * H), (0.55 * W, 0.55 * D, 0.45 * H), fraction=0.6)
    m.ball("flower_alt", (0, 0, 0.45 * H), (0.7 * W, 0.7 * D, 0.47 * H), fraction=0.6)
    m.cylinder("bark", (0, 0, 0.85 * H), (0.05 * W, 0.02 * D, H), 0.08 * W, 0.06 * W, fraction=0.4)
    m.leaf("leaf", (0.05 * W, 0, 0.9 * H), (0.45 * W, 0.2 * D, 0.88 * H), 0.12 * W, 0.02 * H)


def _cabbage(m: Model) -> None:
    """A cabbage (or a lettuce, a head of kale): a round head cupped in its outer leaves."""
    m.main = "leaf"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.ball("leaf", (0, 0, 0.5 * H), (0.62 * W, 0.62 * D, 0.48 * H), fraction=0.6)
    for k in range(7):
        a = 2 * np.pi * k / 7
        c, s = np.cos(a), np.sin(a)
        m.leaf("leaf", (0.25 * W * c, 0.25 * D * s, 0.12 * H), (0.9 * W * c, 0.9 * D * s, 0.7 * H), 0.55 * W, 0.04 * H)


def _ball(m: Model) -> None:
    """A ball: a sphere with a contrasting band, or a bowling ball's three finger holes."""
    m.main = "paint"
    r = min(m.sx, m.sy, m.sz) / 2
    m.ball("paint", (0, 0, r), (r, r, r))
    if m.named("bowling ball"):
        for dx, dz in ((-0.2, 0.55), (0.2, 0.55), (0.0, 0.25)):
            m.ball("dark_plastic", (dx * r, -0.93 * r, r + dz * r), (0.12 * r, 0.1 * r, 0.12 * r), fraction=0.4)
        return
    m.torus("accent", (0, 0, r), 1.0 * r, 0.06 * r, axis="x", fraction=0.8)


def _egg(m: Model) -> None:
    """An egg standing on its broad end, filling its box: a hen's white shell; a dragon's or a
    dinosaur's scaly."""
    m.main = "scales" if m.named("dragon", "dinosaur", "wyvern", "serpent") else "fur_white"
    H = m.sz
    m.lathe(m.main, [(0.0, 0.0), (0.3, 0.03 * H), (0.45, 0.2 * H), (0.5, 0.4 * H), (0.46, 0.6 * H), (0.33, 0.82 * H),
                     (0.16, 0.96 * H), (0.0, H)], scale=(m.sx, m.sy))


def _goal(m: Model) -> None:
    """A football goal: two posts and a crossbar at the front, the net sloping back to the
    ground, stanchions holding it out."""
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    post = 0.05 * H + 0.01
    for x in (-W + post, W - post):
        m.post("plastic", x, -D + post, 0, H - post, post, fraction=0.5)
        m.beam("metal", (x, -D + post, H - post), (x, D - post, 0.02 * H), 0.5 * post)
    m.cylinder("plastic", (-W, -D + post, H - post), (W, -D + post, H - post), post, fraction=0.5)
    m.extrude("canvas_alt", [(-D + 1.6 * post, H - 1.6 * post), (-D + 1.5 * post, 0.0), (D - post, 0.0)], "x", -W + 2 * post, W - 2 * post)
    m.cylinder("metal", (-W + post, D - post, 0.5 * post), (W - post, D - post, 0.5 * post), 0.5 * post, fraction=0.4)


def _chimney(m: Model) -> None:
    """A free-standing chimney stack: a brick column with a corbelled cap and a pot on top."""
    m.main = "brick"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("brick", (-0.8 * W, -0.8 * D, 0), (0.8 * W, 0.8 * D, 0.9 * H))
    m.box("stone", (-W, -D, 0.9 * H), (W, D, 0.94 * H))
    m.cylinder("ceramic", (0, 0, 0.94 * H), (0, 0, H), 0.35 * min(W, D), 0.3 * min(W, D), fraction=0.5)


def _rail(m: Model) -> None:
    """A grind rail: a long steel tube on legs with flat feet, along its longer side."""
    m.main = "metal"
    along_x = m.sx >= m.sy
    L = (m.sx if along_x else m.sy) / 2
    r = 0.06 * m.sz + 0.01

    def at(t: float, z: float):
        return (t, 0.0, z) if along_x else (0.0, t, z)

    m.cylinder("metal", at(-L, m.sz - r), at(L, m.sz - r), r, fraction=0.6)
    for t in (-0.8 * L, 0.0, 0.8 * L):
        m.cylinder("dark_metal", at(t, 0.06 * m.sz), at(t, m.sz - 1.5 * r), 0.7 * r, fraction=0.4)
        lo, hi = np.array(at(t - 0.15 * L, 0.0)), np.array(at(t + 0.15 * L, 0.06 * m.sz))
        side = np.array((0.0, 1.0, 0.0) if along_x else (1.0, 0.0, 0.0)) * 2.5 * r
        m.box("dark_metal", np.minimum(lo, hi) - side, np.maximum(lo, hi) + side, rounded=0.0)


def _orrery(m: Model) -> None:
    """An orrery: a brass sun on a column over a round base, planets on arms of different
    lengths and heights, a ring of the ecliptic."""
    m.main = "brass"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.lathe("dark_wood", [(0.5, 0.0), (0.5, 0.1 * H), (0.0, 0.1 * H)], scale=(m.sx, m.sy))
    m.post("brass", 0, 0, 0.1 * H, 0.7 * H, 0.03 * min(m.sx, m.sy) + 0.003, fraction=0.4)
    m.ball("gold", (0, 0, 0.7 * H), (0.14 * W, 0.14 * D, 0.14 * H))
    m.torus("brass", (0, 0, 0.55 * H), 0.8 * min(W, D), 0.01 * min(m.sx, m.sy) + 0.002, fraction=0.8)
    for k, (reach, z, size, role) in enumerate(((0.35, 0.6, 0.05, "copper"), (0.55, 0.5, 0.07, "book_b"), (0.8, 0.42, 0.08, "accent"),
                                                (0.95, 0.35, 0.06, "leaf"))):
        a = 2.1 * k + 0.4
        tip = (reach * W * np.cos(a), reach * D * np.sin(a), z * H)
        m.beam("brass", (0, 0, 0.25 * H + 0.03 * k * H), (tip[0], tip[1], 0.25 * H + 0.03 * k * H), 0.015 * min(m.sx, m.sy) + 0.002)
        m.post("brass", tip[0], tip[1], 0.25 * H + 0.03 * k * H, z * H, 0.008 * min(m.sx, m.sy) + 0.002, fraction=0.3)
        m.ball(role, tip, (size * W, size * D, size * H), fraction=0.5)


def _balloon(m: Model) -> None:
    """A party balloon on its string: a small weight on the ground, the string, the knot and
    the balloon at the top (a hot-air balloon is a vehicle)."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = min(W, D)
    m.box("dark_plastic", (-0.2 * r, -0.2 * r, 0), (0.2 * r, 0.2 * r, 0.15 * r))
    knot = H - 2.3 * r
    m.cylinder("paper", (0, 0, 0.15 * r), (0, 0, knot), 0.012 * r + 0.001, fraction=0.3)
    m.cylinder("paint", (0, 0, knot - 0.02 * r), (0, 0, knot + 0.12 * r), 0.04 * r, 0.09 * r, fraction=0.4)
    m.ball("paint", (0, 0, H - 1.15 * r), (0.95 * r, 0.95 * r, 1.15 * r))


def generic(m: Model) -> None:
    """Soft things, instruments, pumpkins, cabbages, balls, eggs, ramps, goals, chimneys, rails, orreries and
    party balloons by name; a fire (a driftwood fire, a cooking fire: "fire" heads the name) as a
    campfire; else the family the name calls (a horse the catalogue files here is an animal);
    only a name with no hint at all gets the draped lump."""
    if _FIRE.search(m.name):
        outdoor._campfire(m)
        return
    variants = (
        (("guitar", "violin", "cello"), _guitar),
        (("cushion", "pillow", "pouf"), _cushion),
        (("curtain", "drape"), _curtain),
        (("lifebuoy", "life ring", "swim ring", "swimming ring", "rubber ring", "inflatable ring", "tyre", "tire"),
         _lifebuoy),
        (("pumpkin", "gourd", "squash", "melon", "watermelon"), _pumpkin),
        (("cabbage", "lettuce", "kale"), _cabbage),
        (("ball", "bowling ball", "football", "beach ball", "basketball", "soccer ball", "cannonball", "cannon ball",
          "snowball", "medicine ball"), _ball),
        (("ramp", "skate ramp"), structures._ramp),
        (("goal", "goalpost", "goal post"), _goal),
        (("chimney", "smokestack", "chimney stack"), _chimney),
        (("grind rail", "rail"), _rail),
        (("orrery",), _orrery),
        (("balloon", "party balloon"), _balloon),
        (("egg", "eggs"), _egg),
    )
    for words, build in variants:
        if m.named(*words):
            build(m)
            return
    family = family_of(m.name)
    if family is not None:
        FAMILIES[family](m)
        return
    _draped(m)


#: A name whose head is "fire" (the category's word may follow: "driftwood fire thing"); not a fire
#: engine, a fire extinguisher or a fire bucket, where "fire" says what the thing is for.
_FIRE = re.compile(r"\bfires?(?: thing)?$")


def _draped(m: Model) -> None:
    """A thing nobody can draw, under a dust sheet: a flat top, rounded shoulders, sides
    falling straight and flaring into a hem on the ground. It says "something of this size
    stands here" without claiming to be a crate or a cooler, which a plain block with a
    stripe was taken for."""
    m.main = "fabric"
    H = m.sz
    profile = [(0.0, H), (0.36, 0.985 * H), (0.43, 0.93 * H), (0.445, 0.8 * H), (0.44, 0.25 * H), (0.47, 0.06 * H), (0.5, 0.0)]
    m.lathe("fabric", profile, scale=(m.sx, m.sy))


SHAPES = {"generic": generic}
