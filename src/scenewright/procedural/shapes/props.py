"""Lamps, screens, small props and containers."""

from __future__ import annotations

import numpy as np

from scenewright.procedural.builder import Model
from scenewright.procedural.shapes.machines import _cauldron


def _lantern(m: Model) -> None:
    """A lantern, not a lamp with a shade: a paper globe between its lacquered caps, a stone garden
    lantern (a post under a lit box and a roof), or a glass and metal lantern with a ring to carry it by."""
    r, H = min(m.sx, m.sy) / 2, m.sz
    if m.has("paper", "chinese", "silk", "rice paper"):
        m.main = "paper"
        m.ball("paper", (0, 0, 0.5 * H), (r, r, 0.42 * H))
        m.ball("light", (0, 0, 0.5 * H), (0.45 * r, 0.45 * r, 0.25 * H), fraction=0.5)
        for z0, z1 in ((0.0, 0.12 * H), (0.88 * H, H)):
            m.lathe("lacquer", [(0.45 * r, z0), (0.45 * r, z1)], fraction=0.6)
        return
    if m.has("stone", "granite", "garden", "toro"):
        m.main = "stone"
        m.box("stone", (-r, -r, 0), (r, r, 0.08 * H))
        m.post("stone", 0, 0, 0.08 * H, 0.5 * H, 0.35 * r, fraction=0.6)
        m.box("stone", (-0.8 * r, -0.8 * r, 0.5 * H), (0.8 * r, 0.8 * r, 0.56 * H))
        m.box("light", (-0.5 * r, -0.5 * r, 0.56 * H), (0.5 * r, 0.5 * r, 0.76 * H))
        m.lathe("stone", [(r, 0.76 * H), (0.15 * r, 0.95 * H)], fraction=0.5)
        m.ball("stone", (0, 0, 0.96 * H), (0.15 * r, 0.15 * r, 0.05 * H), fraction=0.4)
        return
    m.main = "dark_metal"
    m.lathe("dark_metal", [(0.9 * r, 0), (0.9 * r, 0.1 * H), (0.7 * r, 0.12 * H)], fraction=0.6)
    m.lathe("glass", [(0.65 * r, 0.12 * H), (0.75 * r, 0.45 * H), (0.65 * r, 0.72 * H)], fraction=0.6)
    m.ball("flame", (0, 0, 0.38 * H), (0.18 * r, 0.18 * r, 0.12 * H), fraction=0.4)
    for k in range(4):  # the frame's posts
        a = np.pi / 4 + k * np.pi / 2
        x, y = 0.72 * r * np.cos(a), 0.72 * r * np.sin(a)
        m.post("dark_metal", x, y, 0.1 * H, 0.74 * H, m.thick(0.006, 0.06 * r), 0.3)
    m.lathe("dark_metal", [(0.85 * r, 0.72 * H), (0.2 * r, 0.86 * H)], fraction=0.6)
    m.torus("dark_metal", (0, 0, 0.92 * H), 0.3 * r, m.thick(0.005, 0.05 * r), axis="x", fraction=0.4)


def table_lamp(m: Model) -> None:
    if m.named("lantern", "lanterns", "hurricane lamp", "oil lamp"):
        _lantern(m)
        return
    m.main = "ceramic"
    r = min(m.sx, m.sy) / 2
    shade_h = 0.42 * m.sz
    m.lathe("ceramic", [(0.6 * r, 0), (0.62 * r, 0.04 * m.sz), (0.45 * r, 0.3 * m.sz), (0.12 * r, 0.45 * m.sz)])
    m.post("brass", 0, 0, 0.45 * m.sz, m.sz - shade_h * 0.6, m.thick(0.008, 0.05 * r), fraction=0.4)
    m.ball("light", (0, 0, m.sz - shade_h * 0.55), (0.18 * r, 0.18 * r, 0.25 * r), fraction=0.5)
    m.lathe("shade", [(r, m.sz - shade_h), (0.6 * r, m.sz)])


def _coat_rack(m: Model) -> None:
    """A coat stand: a turned pole on splayed feet, hooks angled out at the top under a knob."""
    m.main = "dark_wood"
    r = min(m.sx, m.sy) / 2
    H = m.sz
    pole = 0.08 * r + 0.01
    m.post("dark_wood", 0, 0, 0.06 * H, 0.95 * H, pole, fraction=0.5)
    m.ball("dark_wood", (0, 0, 0.96 * H), (1.6 * pole,) * 3, fraction=0.5)
    for k in range(3):
        a = 2 * np.pi * k / 3 + np.pi / 2
        m.beam("dark_wood", (0, 0, 0.12 * H), (0.95 * r * np.cos(a), 0.95 * r * np.sin(a), 0.0), 1.2 * pole)
    for k in range(4):
        a = 2 * np.pi * k / 4 + np.pi / 4
        tip = (0.7 * r * np.cos(a), 0.7 * r * np.sin(a), 0.92 * H)
        m.beam("brass", (0, 0, 0.84 * H), tip, 0.5 * pole)
        m.ball("brass", tip, (0.8 * pole,) * 3, fraction=0.4)


def floor_lamp(m: Model) -> None:
    if m.named("coat rack", "coat stand", "hat stand", "hat rack", "coat tree", "hall tree", "hat tree"):
        _coat_rack(m)
        return
    m.main = "metal"
    r = min(m.sx, m.sy) / 2
    shade_h = 0.22 * m.sz
    m.lathe("metal", [(0.7 * r, 0), (0.7 * r, 0.015 * m.sz), (0.1 * r, 0.03 * m.sz)])
    m.post("metal", 0, 0, 0.02 * m.sz, m.sz - shade_h * 0.5, m.thick(0.012, 0.1 * r), fraction=0.4)
    m.ball("light", (0, 0, m.sz - shade_h * 0.6), (0.15 * r, 0.15 * r, 0.2 * r), fraction=0.5)
    m.lathe("shade", [(r, m.sz - shade_h), (0.65 * r, m.sz)])




def pendant_lamp(m: Model) -> None:
    if m.named("ceiling fan", "fan"):
        m.main = "wood"
        m.post("metal", 0, 0, 0.3 * m.sz, m.sz, 0.02, fraction=0.4)
        m.lathe("metal", [(0.08 * m.sx, 0), (0.1 * m.sx, 0.3 * m.sz), (0.04 * m.sx, 0.45 * m.sz)])
        for k in range(4):
            a = np.pi / 4 + k * np.pi / 2
            m.beam("wood", (0, 0, 0.3 * m.sz), (np.cos(a) * m.sx / 2, np.sin(a) * m.sy / 2, 0.3 * m.sz), 0.12 * m.sx, 0.02)
        return
    m.main = "metal"
    r = min(m.sx, m.sy) / 2
    shade_h = min(0.45 * m.sz, 1.2 * r)
    m.lathe("metal", [(0.25 * r, m.sz - 0.02 * m.sz), (0.25 * r, m.sz)])
    m.post("dark_plastic", 0, 0, shade_h * 0.9, m.sz, 0.006, fraction=0.3)
    m.lathe("metal", [(r, 0), (0.9 * r, 0.3 * shade_h), (0.5 * r, 0.75 * shade_h), (0.12 * r, shade_h)])
    m.ball("light", (0, 0, 0.12 * shade_h), (0.3 * r, 0.3 * r, 0.3 * r), fraction=0.6)


def _water(m: Model) -> None:
    """Water in the ground: a pond or puddle is an oval of water in a stone rim, a pool a
    rectangle of water in a concrete coping, an ice rink white ice inside low boards."""
    rink = m.named("rink")
    m.main = "ceramic" if rink else "water"
    if not (rink or m.named("pool")):
        # The rim: up its outside, across its top, down its inside (a ring, open in the middle).
        m.lathe("stone", [(0.5, 0), (0.5, m.sz), (0.44, m.sz), (0.44, 0)], scale=(m.sx, m.sy))
        m.lathe("water", [(0.45, 0), (0.45, 0.6 * m.sz)], scale=(m.sx, m.sy))
        return
    rim, edge = ("plastic", 0.03 * min(m.sx, m.sy)) if rink else ("concrete", 0.06 * min(m.sx, m.sy))
    W, D = m.sx / 2, m.sy / 2
    # The long sides run full length, the ends fit between them: edge to edge, no shared face.
    for lo, hi in (((-W, -D), (-W + edge, D)), ((W - edge, -D), (W, D)),
                   ((-W + edge, -D), (W - edge, -D + edge)), ((-W + edge, D - edge), (W - edge, D))):
        m.box(rim, (*lo, 0), (*hi, m.sz), rounded=0.0)
    m.box("ceramic" if rink else "water", (-W + edge, -D + edge, 0), (W - edge, D - edge, 0.6 * m.sz), rounded=0.0)


def rug(m: Model) -> None:
    if m.named("pond", "pool", "puddle", "rink"):
        _water(m)
        return
    pelt = m.first_named(_PELTS)
    if pelt is not None:
        _pelt(m, pelt)
        return
    m.main = "fabric"
    border = 0.06 * min(m.sx, m.sy)
    if m.has("round", "circular", "oval"):
        m.lathe("cushion", [(0.5, 0), (0.5, 0.6 * m.sz)], scale=(m.sx, m.sy))
        m.lathe("fabric", [(0.5, 0), (0.5, m.sz)], scale=(m.sx - 2 * border, m.sy - 2 * border))
        return
    m.box("cushion", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, 0.6 * m.sz), rounded=0.0)
    # Each layer stands a little above the one around it: coplanar tops render as a black patch
    # in Cycles (the two faces shadow each other).
    m.box("fabric", (-m.sx / 2 + border, -m.sy / 2 + border, 0), (m.sx / 2 - border, m.sy / 2 - border, 0.85 * m.sz),
          rounded=0.0)
    m.box("accent", (-m.sx / 4, -m.sy / 4, 0), (m.sx / 4, m.sy / 4, m.sz), rounded=0.0)


#: Rugs that are an animal's skin, by the word that names them, and the fur's role.
_PELTS = ((("bearskin", "bear skin", "bear-skin"), "fur_dark"), (("sheepskin", "fleece"), "wool"),
          (("tiger skin", "tigerskin"), "fur_orange"), (("cowhide", "cow hide", "hide", "pelt"), "fur_light"))


def _pelt(m: Model, fur: str) -> None:
    """A skin laid flat, head to the front: an oval body, a round head, four legs spread and a tail
    (each part a little lower than the body, so no two tops share a plane)."""
    m.main = fur
    m.lathe(fur, [(0.5, 0), (0.5, m.sz)], centre=(0, 0.04 * m.sy, 0), scale=(0.5 * m.sx, 0.66 * m.sy))
    m.lathe(fur, [(0.5, 0), (0.5, 0.95 * m.sz)], centre=(0, -0.37 * m.sy, 0), scale=(0.24 * m.sx, 0.24 * m.sy))
    for side in (-1, 1):
        for y in (-0.2 * m.sy, 0.24 * m.sy):
            x0, x1 = sorted((side * 0.15 * m.sx, side * 0.42 * m.sx))
            m.box(fur, (x0, y - 0.1 * m.sy, 0), (x1, y + 0.1 * m.sy, 0.9 * m.sz), rounded=0.0)
    m.box(fur, (-0.03 * m.sx, 0.3 * m.sy, 0), (0.03 * m.sx, m.sy / 2, 0.9 * m.sz), rounded=0.0)


def _screen_panel(m: Model, z0: float, z1: float, depth: float) -> None:
    y = -m.sy / 2
    m.box("dark_plastic", (-m.sx / 2, y, z0), (m.sx / 2, y + depth, z1))
    bezel = 0.03 * min(m.sx, z1 - z0)
    m.box("screen", (-m.sx / 2 + bezel, y - 0.003, z0 + bezel), (m.sx / 2 - bezel, y, z1 - bezel), rounded=0.0)


def tv(m: Model) -> None:
    m.main = "dark_plastic"
    stand = 0.14 * m.sz
    _screen_panel(m, stand, m.sz, min(0.06, 0.5 * m.sy))
    m.box("dark_plastic", (-0.04 * m.sx, -m.sy / 2 + 0.01, 0.02), (0.04 * m.sx, -m.sy / 2 + 0.05, stand + 0.05))
    m.box("dark_plastic", (-0.25 * m.sx, -m.sy / 2, 0), (0.25 * m.sx, m.sy / 2, 0.02))


def monitor(m: Model) -> None:
    m.main = "dark_plastic"
    neck = 0.28 * m.sz
    _screen_panel(m, neck, m.sz, min(0.03, 0.3 * m.sy))
    m.box("dark_plastic", (-0.03 * m.sx, -m.sy / 2 + 0.02, 0.01), (0.03 * m.sx, -m.sy / 2 + 0.05, neck + 0.05))
    m.box("metal", (-0.2 * m.sx, -m.sy / 2, 0), (0.2 * m.sx, m.sy / 2, 0.015))


def laptop(m: Model) -> None:
    m.main = "metal"
    base = 0.1 * m.sz
    m.box("metal", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2 - 0.05 * m.sy, base))
    m.box("dark_plastic", (-0.42 * m.sx, -m.sy / 2 + 0.4 * m.sy, base), (0.42 * m.sx, m.sy / 2 - 0.1 * m.sy, base + 0.003), rounded=0.0)
    m.box("dark_plastic", (-0.15 * m.sx, -m.sy / 2 + 0.07 * m.sy, base), (0.15 * m.sx, -m.sy / 2 + 0.32 * m.sy, base + 0.002), rounded=0.0)
    t = 0.06 * m.sz
    hinge = m.sy / 2 - 0.05 * m.sy
    outline = [(hinge, base), (hinge + t, base), (m.sy / 2, m.sz), (m.sy / 2 - t, m.sz)]
    m.extrude("metal", outline, "x", -m.sx / 2, m.sx / 2)
    inner = [(hinge - 0.002, base + 0.05 * m.sz), (m.sy / 2 - t - 0.002, m.sz - 0.05 * m.sz),
             (m.sy / 2 - t + 0.002, m.sz - 0.05 * m.sz), (hinge + 0.002, base + 0.05 * m.sz)]
    m.extrude("screen", inner, "x", -0.44 * m.sx, 0.44 * m.sx)




def vase(m: Model) -> None:
    if m.named("globe"):
        r = min(m.sx, m.sy, 0.8 * m.sz) / 2
        m.main = "water"
        m.lathe("dark_wood", [(0.7 * r, 0), (0.7 * r, 0.05 * m.sz), (0.1 * r, 0.12 * m.sz), (0.08 * r, m.sz - 2 * r)])
        m.ball("water", (0, 0, m.sz - r), (r, r, r))
        m.torus("brass", (0, 0, m.sz - r), 1.05 * r, 0.03 * r, axis="x")
        return
    m.main = "ceramic"
    r = min(m.sx, m.sy) / 2
    flowers = m.has("flower", "rose", "tulip", "bouquet")
    h = m.sz * (0.65 if flowers else 1.0)
    belly = m.vary(0.35, 0.55)
    m.lathe("ceramic", [(0.55 * r, 0), (0.95 * r, belly * h), (0.4 * r, 0.85 * h), (0.5 * r, h), (0.4 * r, h * 0.98)],
            scale=(1, 1))
    if flowers:
        for k in range(5):
            a = 2 * np.pi * k / 5
            tip = (np.cos(a) * 0.6 * r, np.sin(a) * 0.6 * r, m.sz - 0.15 * r)
            m.cylinder("leaf", (0, 0, h * 0.9), tip, 0.01, fraction=0.3)
            m.ball("flower" if k % 2 else "flower_alt", tip, (0.22 * r, 0.22 * r, 0.15 * r), fraction=0.5)


def potted_plant(m: Model) -> None:
    m.main = "ceramic"
    r = min(m.sx, m.sy) / 2
    pot_h = min(0.35 * m.sz, 1.6 * r)
    m.lathe("ceramic", [(0.6 * r, 0), (0.75 * r, pot_h * 0.92), (0.8 * r, pot_h * 0.92), (0.8 * r, pot_h)])
    m.lathe("soil", [(0.7 * r, pot_h - 0.02), (0.7 * r, pot_h + 0.005)])
    top = m.sz - pot_h
    if m.sz > 3 * min(m.sx, m.sy):
        m.post("bark", 0, 0, pot_h, pot_h + 0.5 * top, m.thick(0.015, 0.1 * r), fraction=0.4)
        blobs = 5
        for k in range(blobs):
            z = pot_h + top * (0.45 + 0.45 * k / (blobs - 1))
            a = m.vary(0, 2 * np.pi)
            off = m.vary(0.1, 0.3) * r
            rr = r * (0.75 - 0.35 * k / blobs)
            m.ball("leaf", (np.cos(a) * off, np.sin(a) * off, z), (rr, rr, top * 0.16), fraction=0.6)
        return
    leaves = int(m.rng.integers(6, 10))
    for k in range(leaves):
        a = 2 * np.pi * k / leaves + m.vary(-0.2, 0.2)
        lean = m.vary(0.6, 1.0)
        tip = np.array([np.cos(a) * r * lean, np.sin(a) * r * lean, pot_h + top * m.vary(0.75, 1.0)])
        m.leaf("leaf", (0, 0, pot_h), tip, 0.28 * r, 0.05 * r)
    m.ball("leaf", (0, 0, pot_h + 0.2 * top), (0.5 * r, 0.5 * r, 0.25 * top), fraction=0.6)


def clock(m: Model) -> None:
    if m.sz > 1.2:
        m.main = "dark_wood"
        m.box("dark_wood", (-m.sx / 2 + 0.04, -m.sy / 2 + 0.03, 0.05 * m.sz), (m.sx / 2 - 0.04, m.sy / 2, 0.75 * m.sz))
        m.box("dark_wood", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, 0.06 * m.sz))
        m.box("dark_wood", (-m.sx / 2, -m.sy / 2, 0.75 * m.sz), (m.sx / 2, m.sy / 2, m.sz))
        m.box("glass", (-0.25 * m.sx, -m.sy / 2 + 0.02, 0.3 * m.sz), (0.25 * m.sx, -m.sy / 2 + 0.03, 0.65 * m.sz), rounded=0.0)
        m.post("brass", 0, -m.sy / 2 + 0.06, 0.35 * m.sz, 0.6 * m.sz, 0.006)
        m.cylinder("brass", (0, -m.sy / 2 + 0.05, 0.36 * m.sz), (0, -m.sy / 2 + 0.04, 0.36 * m.sz), 0.12 * m.sx)
        cz, r = 0.875 * m.sz, min(0.4 * m.sx, 0.11 * m.sz)
        face_y = -m.sy / 2
    else:
        m.main = "wood"
        r = min(m.sx, m.sz) / 2
        cz = m.sz / 2
        face_y = -m.sy / 2 + 0.3 * m.sy
        m.torus("wood", (0, face_y + 0.3 * m.sy, cz), r * 0.92, r * 0.08, axis="y")
        m.cylinder("wood", (0, m.sy / 2, cz), (0, face_y + 0.3 * m.sy, cz), r * 0.9)
    m.cylinder("ceramic", (0, face_y + 0.02, cz), (0, face_y - 0.002, cz), r * 0.85)
    for k in range(12):
        a = 2 * np.pi * k / 12
        p = (np.sin(a) * r * 0.72, face_y - 0.004, cz + np.cos(a) * r * 0.72)
        m.cbox("dark_metal", p, (0.04 * r, 0.004, 0.04 * r), rounded=0.0)
    m.beam("dark_metal", (0, face_y - 0.006, cz), (0.35 * r, face_y - 0.006, cz + 0.3 * r), 0.04 * r, 0.004)
    m.beam("dark_metal", (0, face_y - 0.008, cz), (-0.1 * r, face_y - 0.008, cz + 0.65 * r), 0.03 * r, 0.004)


def _round_mirror(m: Model, f: float) -> None:
    """A round glass in a ring frame that stays round whatever box the layout asked for: in
    a box taller than wide a thin (wall) mirror hangs from a strap, a deep one stands on a
    slim stand like a vanity mirror."""
    r = min(m.sx, m.sz) / 2
    ring = min(f / 2, 0.2 * r)
    tall = m.sz - 2 * r > 0.1 * m.sz
    hanging = tall and m.sy < 0.15 * m.sx
    cz = r if hanging else m.sz - r
    m.torus("wood", (0, 0, cz), r - ring, ring, axis="y")
    m.cylinder("mirror", (0, 0.4 * m.sy, cz), (0, -0.2 * m.sy, cz), r - ring)
    if hanging:
        for s in (-1, 1):
            m.beam("leather", (s * 0.35 * r, 0.3 * m.sy, cz + 0.9 * r), (0, 0.3 * m.sy, m.sz - 0.02 * m.sz), 0.1 * r, 0.2 * m.sy)
        m.ball("brass", (0, 0.2 * m.sy, m.sz - 0.03 * m.sz), (0.06 * r, 0.3 * m.sy, 0.03 * m.sz), fraction=0.4)
    elif tall:
        m.post("wood", 0, 0, 0.04 * m.sz, cz - r + ring, min(0.3 * ring, 0.05 * m.sx) + 0.004, fraction=0.5)
        m.lathe("wood", [(0.35 * m.sx, 0), (0.35 * m.sx, 0.03 * m.sz), (0.1 * m.sx, 0.05 * m.sz)], scale=(1, m.sy / (0.7 * m.sx)))


def mirror(m: Model) -> None:
    m.main = "wood"
    f = m.thick(0.04, 0.12 * min(m.sx, m.sz))
    y0, y1 = -m.sy / 2, m.sy / 2
    if m.has("round", "circular") or abs(m.sx - m.sz) < 0.1 * max(m.sx, m.sz):
        _round_mirror(m, f)
        return
    stand = m.sz > 1.4 and m.sy > 0.15
    if stand:
        y0 = -0.15 * m.sy
        m.beam("wood", (-m.sx / 2 + f / 2, m.sy / 2, 0), (-m.sx / 2 + f / 2, 0, m.sz * 0.6), f / 2)
        m.beam("wood", (m.sx / 2 - f / 2, m.sy / 2, 0), (m.sx / 2 - f / 2, 0, m.sz * 0.6), f / 2)
        y1 = -0.15 * m.sy + 0.04
    m.box("wood", (-m.sx / 2, y0, 0), (-m.sx / 2 + f, y1, m.sz))
    m.box("wood", (m.sx / 2 - f, y0, 0), (m.sx / 2, y1, m.sz))
    m.box("wood", (-m.sx / 2 + f, y0, 0), (m.sx / 2 - f, y1, f))
    m.box("wood", (-m.sx / 2 + f, y0, m.sz - f), (m.sx / 2 - f, y1, m.sz))
    m.box("mirror", (-m.sx / 2 + f, y0 + 0.005, f), (m.sx / 2 - f, y1, m.sz - f), rounded=0.0)


def picture_frame(m: Model) -> None:
    m.main = "wood"
    f = m.thick(0.035, 0.12 * min(m.sx, m.sz))
    y0, y1 = -m.sy / 2, m.sy / 2
    m.box("wood", (-m.sx / 2, y0, 0), (-m.sx / 2 + f, y1, m.sz))
    m.box("wood", (m.sx / 2 - f, y0, 0), (m.sx / 2, y1, m.sz))
    m.box("wood", (-m.sx / 2 + f, y0, 0), (m.sx / 2 - f, y1, f))
    m.box("wood", (-m.sx / 2 + f, y0, m.sz - f), (m.sx / 2 - f, y1, m.sz))
    yc = y0 + 0.4 * (y1 - y0)
    m.box("canvas_alt", (-m.sx / 2 + f, yc, f), (m.sx / 2 - f, y1, m.sz - f), rounded=0.0)
    for k, role in enumerate(("book_b", "book_c", "flower_alt")):
        cx, cz = m.vary(-0.25, 0.25) * m.sx, m.vary(0.3, 0.7) * m.sz
        w, h = m.vary(0.1, 0.3) * m.sx, m.vary(0.1, 0.3) * m.sz
        # Each patch of paint a little proud of the one before: overlapping patches in one
        # plane would fight.
        front = yc - 0.002 * (k + 1)
        m.box(role, (cx - w / 2, front, cz - h / 2), (cx + w / 2, front + 0.002, cz + h / 2), rounded=0.0)


def _post_box(m: Model) -> None:
    """A pillar post box: a red column with a domed cap, a letter slot and a plate."""
    m.main = "accent"
    r = min(m.sx, m.sy) / 2
    H = m.sz
    m.lathe("dark_metal", [(r, 0.0), (r, 0.06 * H), (0.0, 0.06 * H)])
    m.lathe("accent", [(0.9 * r, 0.06 * H), (0.9 * r, 0.82 * H), (r, 0.84 * H), (r, 0.88 * H), (0.6 * r, 0.97 * H), (0.0, H)])
    m.box("dark_metal", (-0.4 * r, -0.95 * r, 0.68 * H), (0.4 * r, -0.85 * r, 0.72 * H), rounded=0.0)
    m.box("paper", (-0.3 * r, -0.93 * r, 0.45 * H), (0.3 * r, -0.87 * r, 0.58 * H), rounded=0.0)


def trash_can(m: Model) -> None:
    if m.named("basket", "hamper"):
        _basket(m)
        return
    if m.named("mailbox", "mail box", "post box", "postbox", "letterbox", "letter box", "pillar box"):
        _post_box(m)
        return
    m.main = "metal"
    r = min(m.sx, m.sy) / 2
    m.lathe("metal", [(0.82 * r, 0), (0.95 * r, 0.88 * m.sz)], scale=(m.sx / (2 * r), m.sy / (2 * r)))
    m.torus("dark_metal", (0, 0, 0.88 * m.sz), 0.95 * r, 0.04 * r)
    m.lathe("dark_metal", [(r, 0.88 * m.sz), (r, 0.9 * m.sz), (0.6 * r, 0.97 * m.sz), (0.15 * r, m.sz)])


def _chest(m: Model) -> None:
    lid = 0.35 * m.sz
    m.box("wood", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, m.sz - lid))
    # The lid overhangs the body a little (its ends would lie in the body's sides) and the
    # bands run up into it (their tops would lie in the body's top).
    m.cylinder("wood", (-0.51 * m.sx, 0, m.sz - lid), (0.51 * m.sx, 0, m.sz - lid), m.sy / 2)
    for x in (-0.4 * m.sx, 0.4 * m.sx):
        m.box("brass", (x - 0.03 * m.sx, -m.sy / 2 - 0.005, 0), (x + 0.03 * m.sx, m.sy / 2 + 0.005, m.sz - lid + 0.02 * m.sz))
        m.torus("brass", (x, 0, m.sz - lid), m.sy / 2, 0.015 * m.sz, axis="x", arc=np.pi)
    m.box("gold", (-0.06 * m.sx, -m.sy / 2 - 0.02, m.sz - lid - 0.12 * m.sz), (0.06 * m.sx, -m.sy / 2, m.sz - lid + 0.02 * m.sz))

def _bale(m: Model) -> None:
    """A bale of hay or straw: a straw block, its edges rounded, bound by two cords."""
    m.main = "straw"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("straw", (-W, -D, 0), (W, D, H), rounded=0.08 * min(m.sx, m.sy, m.sz))
    for x in (-0.5 * W, 0.5 * W):
        m.box("bark", (x - 0.015 * m.sx, -1.01 * D, 0.0), (x + 0.015 * m.sx, 1.01 * D, 1.01 * H), rounded=0.0)


def _shipping_container(m: Model) -> None:
    """A steel shipping container along y: ribbed sides, corner posts, double doors at the
    front (its end toward −Y, the side a viewer is shown)."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("paint", (-W, -D, 0), (W, D, H), rounded=0.0)
    ribs = max(4, int(m.sy / 0.3))
    for k in range(ribs):
        y = -D + (k + 0.5) * m.sy / ribs
        for s in (-1, 1):  # corrugation: ribs standing proud of each long side
            x0, x1 = sorted((s * W, s * (W + 0.01 * m.sx)))
            m.box("paint", (x0, y - 0.2 * m.sy / ribs, 0.05 * H), (x1, y + 0.2 * m.sy / ribs, 0.95 * H), rounded=0.0)
    post = 0.04 * min(m.sx, m.sz)
    for x in (-W - 0.005, W - post + 0.005):
        for y in (-D - 0.005, D - post + 0.005):
            m.box("dark_metal", (x, y, -0.0), (x + post, y + post, H + 0.005), rounded=0.0)
    for x in (-0.5 * W, -0.2 * W, 0.2 * W, 0.5 * W):  # the doors' locking bars
        m.beam("dark_metal", (x, -D - 0.01, 0.05 * H), (x, -D - 0.01, 0.95 * H), 0.02 * m.sx)
    m.box("dark_metal", (-0.003 * m.sx, -D - 0.005, 0.03 * H), (0.003 * m.sx, -D, 0.97 * H), rounded=0.0)


def _pallet(m: Model) -> None:
    """A wooden pallet: deck boards across three runners, bottom boards under them."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    runner = 0.1 * m.sx
    for k in range(3):
        x = -W + k * (m.sx - runner) / 2
        m.box("wood", (x, -D, 0.2 * H), (x + runner, D, 0.78 * H))
    boards = 7
    w = m.sy / (boards + (boards - 1) * 0.5)
    for k in range(boards):
        y = -D + k * 1.5 * w
        m.box("wood", (-W, y, 0.78 * H), (W, y + w, H))
    for y in (-D, -w / 2, D - w):
        m.box("wood", (-W, y, 0), (W, y + w, 0.2 * H))


def crate(m: Model) -> None:
    """A wooden crate, or what the catalogue files with crates and draws its own way: a
    treasure chest, a bale of hay, a shipping container, a pallet."""
    for words, build in ((("chest", "treasure"), _chest), (("hay", "straw", "haystack"), _bale),
                         (("shipping container", "cargo container"), _shipping_container), (("pallet",), _pallet)):
        if m.named(*words):
            build(m)
            return
    b = m.thick(0.06, 0.15 * min(m.sx, m.sy, m.sz))
    m.box("wood", (-m.sx / 2 + b * 0.3, -m.sy / 2 + b * 0.3, b * 0.3), (m.sx / 2 - b * 0.3, m.sy / 2 - b * 0.3, m.sz - b * 0.3))
    hx, hy, hz = m.sx / 2, m.sy / 2, m.sz
    for x in (-hx, hx - b):
        for y in (-hy, hy - b):
            m.box("dark_wood", (x, y, 0), (x + b, y + b, hz))
    for z in (0, hz - b):
        for y in (-hy, hy - b):
            m.box("dark_wood", (-hx + b, y, z), (hx - b, y + b, z + b))
        for x in (-hx, hx - b):
            m.box("dark_wood", (x, -hy + b, z), (x + b, hy - b, z + b))
    m.beam("dark_wood", (-hx + b, -hy - 0.001, b), (hx - b, -hy - 0.001, hz - b), b * 0.8, 0.02)




def _drum(m: Model) -> None:
    """A big drum (taiko, bass drum) on its side in a wooden stand: a barrel body, a skin at
    each end fixed by a ring of tacks."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = min(D, 0.42 * H)
    cz = H - r
    m.cylinder("wood", (-0.85 * W, 0, cz), (0.0, 0, cz), 0.88 * r, r, fraction=0.8)
    m.cylinder("wood", (0.0, 0, cz), (0.85 * W, 0, cz), r, 0.88 * r, fraction=0.8)
    for s in (-1, 1):
        m.cylinder("hide", (s * 0.85 * W, 0, cz), (s * 0.86 * W, 0, cz), 0.86 * r, fraction=0.8)
        m.torus("brass", (s * 0.8 * W, 0, cz), 0.88 * r, 0.03 * r, axis="x", fraction=0.6)
    for y in (-0.6 * D, 0.6 * D):
        m.beam("dark_wood", (-0.7 * W, y, 0), (-0.3 * W, y, cz - 0.7 * r), 0.12 * r)
        m.beam("dark_wood", (0.7 * W, y, 0), (0.3 * W, y, cz - 0.7 * r), 0.12 * r)
    m.box("dark_wood", (-0.6 * W, -0.7 * D, cz - 0.98 * r), (0.6 * W, 0.7 * D, cz - 0.85 * r))


#: Words that make a drum an instrument: a plain "drum" among barrels is an oil drum.
_INSTRUMENT_DRUMS = ("taiko", "bass", "war", "snare", "kettle", "tom", "ceremonial", "festival", "temple", "marching")


def barrel(m: Model) -> None:
    if m.named("drum") and m.has(*_INSTRUMENT_DRUMS):
        _drum(m)
        return
    if m.named("log", "trunk"):
        r = min(m.sy, m.sz) / 2
        m.cylinder("bark", (-m.sx / 2, 0, r), (m.sx / 2, 0, r), r, fraction=0.6)
        for s in (-1, 1):
            m.cylinder("wood", (s * m.sx / 2, 0, r), (s * (m.sx / 2 + 0.005), 0, r), 0.85 * r, fraction=0.6)
        return
    r = min(m.sx, m.sy) / 2
    prof = [(0.85 * r, 0), (0.97 * r, 0.25 * m.sz), (r, 0.5 * m.sz), (0.97 * r, 0.75 * m.sz), (0.85 * r, m.sz)]
    m.lathe("wood", prof, scale=(m.sx / (2 * r), m.sy / (2 * r)))
    for z, rr in ((0.1, 0.9), (0.3, 0.985), (0.7, 0.985), (0.9, 0.9)):
        m.torus("dark_metal", (0, 0, z * m.sz), rr * r, 0.025 * r)
    m.lathe("dark_wood", [(0.8 * r, m.sz - 0.02), (0.8 * r, m.sz - 0.005)])


def books(m: Model) -> None:
    m.main = "book_a"
    roles = ("book_a", "book_b", "book_c")
    if m.sz < max(m.sx, m.sy) * 0.6:
        z = 0.0
        while z < m.sz - 0.005:
            h = min(m.vary(0.025, 0.05) * max(1.0, m.sz / 0.6), m.sz - z)
            dx, dy = m.vary(-0.05, 0.05) * m.sx, m.vary(-0.05, 0.05) * m.sy
            lo = (-0.45 * m.sx + dx, -0.45 * m.sy + dy, z)
            hi = (0.45 * m.sx + dx, 0.45 * m.sy + dy, z + h)
            m.box(roles[int(m.rng.integers(3))], lo, hi, rounded=0.0)
            m.box("paper", (lo[0] + 0.005, lo[1] - 0.001, z + 0.003), (hi[0] - 0.005, hi[1] - 0.01, z + h - 0.003), rounded=0.0)
            z += h
        return
    x = -m.sx / 2
    while x < m.sx / 2 - 0.01:
        w = min(m.vary(0.025, 0.06) * max(1.0, m.sx / 1.2), m.sx / 2 - x)
        m.box(roles[int(m.rng.integers(3))], (x, -m.sy / 2, 0), (x + w - 0.002, m.sy / 2, m.sz * m.vary(0.75, 1.0)), rounded=0.0)
        x += w




def bottle(m: Model) -> None:
    if m.named("candle"):
        m.main = "paper"
        r = min(m.sx, m.sy) / 2
        m.lathe("brass", [(r, 0), (r, 0.04 * m.sz), (0.5 * r, 0.08 * m.sz)])
        m.lathe("paper", [(0.45 * r, 0.06 * m.sz), (0.45 * r, 0.85 * m.sz)])
        m.ball("flame", (0, 0, 0.93 * m.sz), (0.15 * r, 0.15 * r, 0.07 * m.sz), fraction=0.4)
        return
    m.main = "glass"
    r = min(m.sx, m.sy) / 2
    m.lathe("glass", [(0.95 * r, 0), (r, 0.55 * m.sz), (0.35 * r, 0.75 * m.sz), (0.3 * r, 0.92 * m.sz)])
    m.lathe("paper", [(1.01 * r, 0.2 * m.sz), (1.02 * r, 0.45 * m.sz)])
    m.lathe("accent", [(0.33 * r, 0.9 * m.sz), (0.33 * r, m.sz)])


def cup(m: Model) -> None:
    m.main = "ceramic"
    r = min(m.sy, m.sx * 0.7) / 2
    m.lathe("ceramic", [(0.85 * r, 0), (r, m.sz), (0.9 * r, m.sz), (0.8 * r, 0.1 * m.sz)], centre=(-(m.sx / 2 - r), 0, 0))
    hr = (m.sx - 2 * r) / 2 + 0.15 * r
    m.torus("ceramic", (m.sx / 2 - hr - 0.12 * r, 0, 0.5 * m.sz), hr, 0.12 * r, axis="y")
    m.lathe("soil", [(0.85 * r, 0.8 * m.sz), (0.85 * r, 0.82 * m.sz)], centre=(-(m.sx / 2 - r), 0, 0))


def _basket(m: Model) -> None:
    m.main = "wood"
    m.lathe("wood", [(0.0, 0.0), (0.38, 0.0), (0.5, 0.6 * m.sz), (0.46, 0.6 * m.sz), (0.34, 0.04 * m.sz), (0.0, 0.04 * m.sz)],
            scale=(m.sx, m.sy))
    for z in (0.15, 0.3, 0.45):
        m.lathe("dark_wood", [(0.38 + 0.2 * z, z * m.sz), (0.38 + 0.2 * z, z * m.sz + 0.03 * m.sz)], scale=(m.sx * 1.02, m.sy * 1.02),
                fraction=0.7)
    m.torus("dark_wood", (0, 0, 0.6 * m.sz), 0.45 * m.sx, 0.02 * min(m.sx, m.sz), axis="y", arc=np.pi, fraction=0.5)
    m.lathe("canvas", [(0.47, 0.56 * m.sz), (0.5, 0.64 * m.sz), (0.3, 0.6 * m.sz)], scale=(m.sx, m.sy), fraction=0.7)


def _creel(m: Model) -> None:
    """A lobster or crab pot: wooden hoops arched along a slatted base, rope lines running
    over them, a funnel mouth at the front and a brick for weight inside."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    base = 0.08 * H
    for x in (-0.8 * W, 0.0, 0.8 * W):
        m.box("wood", (x - 0.12 * W, -D, 0), (x + 0.12 * W, D, base))
    hoop = 0.025 * min(m.sx, m.sy, m.sz) + 0.004
    rise = H - base - hoop
    for y in (-0.85 * D, -0.3 * D, 0.3 * D, 0.85 * D):
        m.torus("dark_wood", (0, y, base), 0.95 * W, hoop, axis="y", arc=np.pi, fraction=0.6)
    for k in range(1, 8):
        a = np.pi * k / 8
        x, z = 0.95 * W * np.cos(a), base + 0.95 * W * np.sin(a) * rise / (0.95 * W)
        m.cylinder("canvas_alt", (x, -0.9 * D, z), (x, 0.9 * D, z), 0.5 * hoop, fraction=0.3)
    m.torus("canvas_alt", (0, -0.86 * D, base + 0.45 * rise), 0.3 * min(W, rise), 0.6 * hoop, axis="y", fraction=0.5)
    m.box("brick", (-0.25 * W, -0.3 * D, base), (0.25 * W, 0.3 * D, base + 0.15 * H))

def _pan(m: Model) -> None:
    """A frying pan or wok: a shallow dish with a long handle out to one side."""
    m.main = "dark_metal"
    r = min(0.35 * m.sx, 0.5 * m.sy)
    cx = -m.sx / 2 + r
    m.lathe("dark_metal", [(0.0, 0.0), (0.8 * r, 0.0), (r, m.sz), (0.95 * r, m.sz), (0.76 * r, 0.1 * m.sz), (0.0, 0.1 * m.sz)],
            centre=(cx, 0, 0))
    m.beam("dark_wood", (cx + 0.98 * r, 0, 0.8 * m.sz), (m.sx / 2, 0, 0.95 * m.sz), 0.15 * r, 0.12 * r)


def _teapot(m: Model) -> None:
    """A teapot or kettle: a round body with a lid and knob, a spout and a handle."""
    m.main = "ceramic"
    W, H = m.sx / 2, m.sz
    r = min(0.6 * W, 0.5 * m.sy)
    m.lathe("ceramic", [(0.0, 0.0), (0.8 * r, 0.0), (r, 0.35 * H), (0.8 * r, 0.7 * H), (0.5 * r, 0.75 * H), (0.0, 0.75 * H)])
    m.lathe("ceramic", [(0.52 * r, 0.74 * H), (0.45 * r, 0.82 * H), (0.0, 0.84 * H)])
    m.ball("accent", (0, 0, 0.88 * H), (0.12 * r, 0.12 * r, 0.06 * H), fraction=0.4)
    m.cylinder("ceramic", (-0.8 * r, 0, 0.3 * H), (-W, 0, 0.7 * H), 0.18 * r, 0.08 * r, fraction=0.5)
    m.torus("ceramic", (0.9 * r + 0.12 * H, 0, 0.4 * H), 0.15 * H, 0.06 * r, axis="y", fraction=0.5)


def bowl(m: Model) -> None:
    if m.named("lobster pot", "crab pot", "creel", "fish trap", "eel trap"):
        _creel(m)
        return
    if m.named("frying pan", "pan", "wok", "skillet", "saucepan"):
        _pan(m)
        return
    if m.named("teapot", "tea pot", "kettle"):
        _teapot(m)
        return
    if m.named("cauldron"):
        _cauldron(m)
        return
    if m.named("basket", "hamper"):
        _basket(m)
        return
    m.main = "ceramic"
    r = 0.5
    h = m.sz * (0.6 if m.has("fruit") else 1.0)
    m.lathe("ceramic", [(0, 0), (0.3 * r, 0), (0.85 * r, 0.6 * h), (r, h), (0.93 * r, h), (0.3 * r, 0.12 * h), (0, 0.12 * h)],
            scale=(m.sx, m.sy))
    if m.has("fruit"):
        for k in range(5):
            a = 2 * np.pi * k / 5
            s = 0.18 * min(m.sx, m.sy)
            m.ball("flower" if k % 2 else "flower_alt", (np.cos(a) * 0.2 * m.sx, np.sin(a) * 0.2 * m.sy, h * 0.6), (s, s, s))


def garland(m: Model) -> None:
    """A string of lights, or of bunting flags, strung across the box's width: a cord sagging from
    its two ends at the top to its middle, with lit bulbs or little triangular flags hanging from it."""
    W, H = m.sx / 2, m.sz
    flags = m.named("bunting", "flag", "flags", "pennant", "pennants")
    m.main = "canvas" if flags else "light"
    n = int(np.clip(round(m.sx / 0.3), 6, 40))
    xs = np.linspace(-W, W, n + 1)
    drop = 0.55 * H if flags else 0.75 * H  # the flags hang below the cord's lowest point

    def cord(x: float) -> float:
        return H - 0.01 - drop * (1.0 - (x / W) ** 2)

    for k, (a, b) in enumerate(zip(xs[:-1], xs[1:])):  # (each a hair thicker, so no two share a cap)
        m.cylinder("dark_plastic", (a, 0.0, cord(a)), (b, 0.0, cord(b)), 0.006 * (1 + 0.01 * k), fraction=0.2)
    for k, x in enumerate((xs[:-1] + xs[1:]) / 2):
        z = cord(x)
        if flags:
            half = 0.4 * (xs[1] - xs[0])
            flag = [(x - half, z), (x + half, z), (x, z - 0.4 * H)]
            m.extrude("canvas" if k % 2 else "accent", flag, "y", -0.003, 0.003)
        else:
            m.ball("light", (x, 0.0, z - 0.04), (0.025, 0.025, 0.035), fraction=0.3)


SHAPES = {
    "garland": garland, "table_lamp": table_lamp, "floor_lamp": floor_lamp, "pendant_lamp": pendant_lamp, "rug": rug,
    "tv": tv, "monitor": monitor, "laptop": laptop, "vase": vase, "potted_plant": potted_plant, "clock": clock,
    "mirror": mirror, "picture_frame": picture_frame, "trash_can": trash_can, "crate": crate, "barrel": barrel,
    "books": books, "bottle": bottle, "cup": cup, "bowl": bowl,
}
