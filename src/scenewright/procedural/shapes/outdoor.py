"""Plants, rocks, water features, street furniture, play equipment and monuments."""

from __future__ import annotations

import numpy as np

from scenewright.procedural import parts as P
from scenewright.procedural.builder import Model
from scenewright.procedural.shapes.creatures import animal, bird, figure
from scenewright.procedural.shapes.families import family_of


def tree(m: Model) -> None:
    # a flowering tree is known by its blossom ("a cherry tree" in spring)
    m.main = "blossom" if m.named("cherry", "blossom", "sakura", "almond", "magnolia") else "leaf"
    trunk_top = m.vary(0.35, 0.45) * m.sz
    r = m.thick(0.06 * min(m.sx, m.sy), 0.12 * min(m.sx, m.sy))
    m.lathe("bark", [(1.6 * r, 0), (r, 0.1 * m.sz), (0.8 * r, trunk_top + 0.15 * m.sz)])
    if m.named("tree house", "treehouse"):
        # A hut on a deck where the trunk forks, half in the canopy, its door toward the viewer.
        floor, hut = trunk_top - 0.05 * m.sz, 0.22 * m.sz
        m.box("wood", (-0.3 * m.sx, -0.42 * m.sy, floor), (0.3 * m.sx, 0.2 * m.sy, floor + 0.03 * m.sz))
        m.box("wall", (-0.22 * m.sx, -0.35 * m.sy, floor + 0.03 * m.sz), (0.22 * m.sx, 0.12 * m.sy, floor + hut))
        m.box("dark_wood", (-0.05 * m.sx, -0.36 * m.sy, floor + 0.03 * m.sz), (0.05 * m.sx, -0.35 * m.sy, floor + 0.7 * hut))
        m.extrude("roof", [(-0.4 * m.sy, floor + hut), (0.17 * m.sy, floor + hut), (-0.115 * m.sy, floor + 1.5 * hut)],
                  "x", -0.26 * m.sx, 0.26 * m.sx)
        m.beam("wood", (0.15 * m.sx, -0.45 * m.sy, 0), (0.15 * m.sx, -0.42 * m.sy, floor), 0.04 * m.sx, 0.02 * m.sy)
    canopy_h = m.sz - trunk_top
    blobs = int(m.rng.integers(4, 7))
    m.ball(m.main, (0, 0, trunk_top + 0.55 * canopy_h), (0.33 * m.sx, 0.33 * m.sy, 0.4 * canopy_h))
    for k in range(blobs):
        a = 2 * np.pi * k / blobs + m.vary(-0.3, 0.3)
        d = m.vary(0.22, 0.3)
        s = m.vary(0.18, 0.24)
        z = trunk_top + m.vary(0.3, 0.65) * canopy_h
        centre = (np.cos(a) * d * m.sx, np.sin(a) * d * m.sy, z)
        m.ball(m.main, centre, (s * m.sx, s * m.sy, s * 1.2 * canopy_h), fraction=0.7)


def pine_tree(m: Model) -> None:
    m.main = "pine_leaf"
    r = min(m.sx, m.sy) / 2
    trunk = 0.18 * m.sz
    m.post("bark", 0, 0, 0, trunk + 0.1 * m.sz, m.thick(0.08 * r, 0.2 * r))
    tiers = 4 if m.sz > 3 else 3
    span = m.sz - trunk
    for i in range(tiers):
        h = span * (0.45 - 0.06 * i)
        z0 = trunk + span * i / (tiers + 0.6)
        rr = r * (1.0 - 0.2 * i)
        m.lathe("pine_leaf", [(rr, z0), (0, min(m.sz, z0 + h))], scale=(m.sx / (2 * r), m.sy / (2 * r)))
    m.lathe("pine_leaf", [(0.3 * r, m.sz - 0.2 * span), (0, m.sz)])


def palm_tree(m: Model) -> None:
    m.main = "leaf"
    top = 0.85 * m.sz
    lean = m.vary(0.05, 0.15) * min(m.sx, m.sy)
    r = m.thick(0.05 * min(m.sx, m.sy) + 0.05, 0.08 * min(m.sx, m.sy))
    steps = 8
    prev = np.array([0.0, 0.0, 0.0])
    if m.has("potted"):  # a house palm: its trunk rises from a pot
        pot_r, pot_h = 0.22 * min(m.sx, m.sy), 0.2 * m.sz
        m.lathe("ceramic", [(0.75 * pot_r, 0), (pot_r, 0.92 * pot_h), (1.05 * pot_r, pot_h)])
        m.lathe("soil", [(0.95 * pot_r, pot_h - 0.02), (0.95 * pot_r, pot_h + 0.005)])
        prev[2] = pot_h
    for i in range(1, steps + 1):
        t = i / steps
        cur = np.array([lean * t * t, 0.0, top * t])
        m.cylinder("bark", prev, cur, r * (1.25 - 0.4 * (i - 1) / steps), r * (1.25 - 0.4 * i / steps), fraction=0.5)
        prev = cur
    crown = prev
    fronds = int(m.rng.integers(7, 10))
    for k in range(fronds):
        a = 2 * np.pi * k / fronds + m.vary(-0.15, 0.15)
        reach = np.array([np.cos(a) * m.sx / 2, np.sin(a) * m.sy / 2])
        mid = crown + np.array([reach[0] * 0.5, reach[1] * 0.5, 0.12 * m.sz])
        tip = np.array([reach[0], reach[1], crown[2] - m.vary(0.1, 0.3) * m.sz])
        for a0, a1 in ((crown, mid), (mid, tip)):
            length = float(np.linalg.norm(a1 - a0))
            m.leaf("leaf", a0, a1, 0.12 * length + 0.1, 0.02 * length + 0.01)
    for k in range(3):
        a = 2 * np.pi * k / 3
        m.ball("bark", crown + np.array([np.cos(a) * r, np.sin(a) * r, -0.02 * m.sz]), (0.8 * r, 0.8 * r, 0.8 * r), fraction=0.5)


def _cactus(m: Model) -> None:
    m.main = "leaf"
    r = 0.16 * min(m.sx, m.sy) + 0.02
    m.cylinder("leaf", (0, 0, 0), (0, 0, m.sz - r), r, fraction=0.6)
    m.ball("leaf", (0, 0, m.sz - r), (r, r, r), fraction=0.6)
    for s, z0, top in ((-1, 0.35, 0.75), (1, 0.5, 0.85)):
        x = s * (m.sx / 2 - 0.7 * r)
        m.cylinder("leaf", (0, 0, z0 * m.sz), (x, 0, z0 * m.sz), 0.7 * r, fraction=0.5)
        m.cylinder("leaf", (x, 0, z0 * m.sz), (x, 0, top * m.sz), 0.7 * r, fraction=0.5)
        m.ball("leaf", (x, 0, top * m.sz), (0.7 * r,) * 3, fraction=0.5)

def bush(m: Model) -> None:
    if m.named("cactus", "saguaro"):
        _cactus(m)
        return
    m.main = "leaf"
    flowers = m.has("flower", "rose", "hydrangea", "blossom")
    m.ball("leaf", (0, 0, 0.45 * m.sz), (0.33 * m.sx, 0.33 * m.sy, 0.45 * m.sz))
    blobs = int(m.rng.integers(5, 8))
    for k in range(blobs):
        a = 2 * np.pi * k / blobs + m.vary(-0.3, 0.3)
        s = m.vary(0.17, 0.23)
        c = (np.cos(a) * 0.3 * m.sx, np.sin(a) * 0.3 * m.sy, m.vary(0.3, 0.5) * m.sz)
        m.ball("leaf", c, (s * m.sx, s * m.sy, min(c[2], 1.4 * s * m.sz)), fraction=0.7)
        if flowers:
            m.ball("flower", (c[0] * 1.5, c[1] * 1.5, c[2] + 0.1 * m.sz), (0.05 * m.sx,) * 2 + (0.05 * m.sz,), fraction=0.4)


def flower_bed(m: Model) -> None:
    m.main = "flower"
    edge = m.thick(0.08, 0.15 * min(m.sx, m.sy))
    wall_h = 0.35 * m.sz
    for lo, hi in (((-m.sx / 2, -m.sy / 2), (m.sx / 2, -m.sy / 2 + edge)), ((-m.sx / 2, m.sy / 2 - edge), (m.sx / 2, m.sy / 2)),
                   ((-m.sx / 2, -m.sy / 2 + edge), (-m.sx / 2 + edge, m.sy / 2 - edge)),
                   ((m.sx / 2 - edge, -m.sy / 2 + edge), (m.sx / 2, m.sy / 2 - edge))):
        m.box("stone", (*lo, 0), (*hi, wall_h))
    m.box("soil", (-m.sx / 2 + edge, -m.sy / 2 + edge, 0), (m.sx / 2 - edge, m.sy / 2 - edge, wall_h * 0.8), rounded=0.0)
    nx = min(10, max(2, int((m.sx - 2 * edge) / 0.25)))
    ny = min(6, max(1, int((m.sy - 2 * edge) / 0.25)))
    fx = (m.sx - 2 * edge) / nx
    fy = (m.sy - 2 * edge) / ny
    for i in range(nx):
        for j in range(ny):
            x = -m.sx / 2 + edge + (i + 0.5) * fx + m.vary(-0.2, 0.2) * fx
            y = -m.sy / 2 + edge + (j + 0.5) * fy + m.vary(-0.2, 0.2) * fy
            top = m.sz * m.vary(0.75, 1.0)
            s = 0.3 * min(fx, fy)
            m.post("leaf", x, y, wall_h * 0.7, top - s, 0.01, fraction=0.2)
            m.ball("flower" if (i + j) % 2 else "flower_alt", (x, y, top - s), (s, s, s), fraction=0.3)
            if (i + j) % 2 == 0:
                m.ball("leaf", (x, y, wall_h * 0.9), (0.7 * fx, 0.7 * fy, 0.15 * m.sz), fraction=0.3)


def _campfire(m: Model) -> None:
    m.main = "stone"
    stones = 9
    for k in range(stones):
        a = 2 * np.pi * k / stones
        s = 0.1 * min(m.sx, m.sy)
        m.ball("stone", (np.cos(a) * (0.5 * m.sx - s), np.sin(a) * (0.5 * m.sy - s), s * 0.6), (s, s, s * 0.8), fraction=0.4)
    for k in range(4):
        a = np.pi * k / 4 + 0.3
        d = np.array([np.cos(a), np.sin(a)]) * 0.32 * min(m.sx, m.sy)
        m.cylinder("bark", (d[0], d[1], 0.05 * m.sz), (-d[0], -d[1], 0.2 * m.sz), 0.05 * min(m.sx, m.sy), fraction=0.5)
    m.lathe("flame", [(0.2 * min(m.sx, m.sy), 0.1 * m.sz), (0.1 * min(m.sx, m.sy), 0.5 * m.sz), (0.0, m.sz)], fraction=0.5)

def _lump(m: Model, role: str, centre=(0.0, 0.0, 0.0), radii=(1.0, 1.0, 1.0), floor: float = -0.35) -> None:
    """A lumpy faceted boulder: a sphere with random waves on it, its bottom cut flat at
    ``floor`` (in units of its radius)."""
    part = P.sphere((0, 0, 0), (1, 1, 1), max(6, m.segments(0.45)))
    d = part.vertices
    waves = m.rng.normal(size=(5, 3))
    phase = m.rng.uniform(0, 2 * np.pi, 5)
    bump = 1 + 0.18 * np.sin(d @ waves.T * 2 + phase).sum(axis=1) / 2.2
    verts = d * bump[:, None]
    verts[:, 2] = np.maximum(verts[:, 2], floor)
    m.add(role, P.flatten(P.Part(verts * np.asarray(radii) + np.asarray(centre), part.faces, part.normals)))


def _outcrop(m: Model) -> None:
    """A rocky outcrop (a kopje, a tor): great rounded boulders heaped on a low rock base,
    tufts of grass between them."""
    m.main = "stone"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    _lump(m, "stone", (0, 0, 0), (W, D, 0.35 * H), floor=0.0)
    for k in range(7):
        a = 2 * np.pi * k / 7 + m.vary(-0.3, 0.3)
        reach = 0.25 + 0.3 * (k % 2)
        r = m.vary(0.22, 0.32)
        _lump(m, "stone", (reach * W * np.cos(a), reach * D * np.sin(a), 0.25 * H + r * H * 0.3), (r * W, r * D, r * H * 0.9))
    _lump(m, "stone", (0.05 * W, -0.05 * D, 0.65 * H), (0.3 * W, 0.28 * D, 0.35 * H))
    for k in range(5):
        a = 2 * np.pi * k / 5 + 0.4
        m.ball("leaf", (0.7 * W * np.cos(a), 0.7 * D * np.sin(a), 0.12 * H), (0.1 * W, 0.1 * D, 0.08 * H), fraction=0.4)


def _mound(m: Model) -> None:
    """A termite mound or anthill: a lumpy cone of earth, spires rising from its shoulders."""
    m.main = "soil"
    H = m.sz
    _lump(m, "soil", (0, 0, 0.2 * H), (0.5 * m.sx, 0.5 * m.sy, 0.25 * H), floor=-0.8)
    m.lathe("soil", [(0.42, 0.0), (0.32, 0.3 * H), (0.18, 0.7 * H), (0.06, 0.95 * H), (0.0, H)], scale=(m.sx, m.sy))
    if m.sz > max(m.sx, m.sy):
        for k, (a, top) in enumerate(((0.3, 0.7), (2.4, 0.55), (4.2, 0.62))):
            x, y = 0.16 * m.sx * np.cos(a), 0.16 * m.sy * np.sin(a)
            m.lathe("soil", [(0.1, 0.2 * H), (0.05, top * H), (0.0, (top + 0.05) * H)], centre=(x, y, 0), scale=(m.sx, m.sy))


def _mound_of_land(m: Model) -> None:
    """A dune, a hill or a knoll: a smooth low mound, sand for a dune, turf for the rest (a boulder
    the size of a hill reads as a grey rock)."""
    role = "sand" if m.named("dune", "dunes", "sandbank", "sand dune") else "leaf"
    m.main = role
    m.lathe(role, [(0.5, 0.0), (0.44, 0.18 * m.sz), (0.3, 0.62 * m.sz), (0.14, 0.92 * m.sz), (0.0, m.sz)],
            scale=(m.sx, m.sy))


def rock(m: Model) -> None:
    """A boulder; by its name a campfire, a rocky outcrop, a termite mound or anthill, a dune or a hill."""
    variants = (
        (("dune", "dunes", "sand dune", "hill", "hillock", "knoll"), _mound_of_land),
        (("campfire", "bonfire", "fire pit"), _campfire),
        (("kopje", "koppie", "outcrop", "tor", "rock formation"), _outcrop),
        (("termite mound", "termite hill", "anthill", "ant hill", "mound"), _mound),
    )
    build = m.first_named(variants)
    if build is not None:
        build(m)
        return
    m.main = "stone"
    _lump(m, "stone")


def fountain(m: Model) -> None:
    m.main = "stone"
    r = 0.5
    wall = 0.25 * m.sz
    m.lathe("stone", [(r, 0), (r, wall), (r * 0.9, wall), (r * 0.9, 0.06 * m.sz), (0, 0.06 * m.sz)], scale=(m.sx, m.sy))
    m.lathe("water", [(r * 0.9, 0.05 * m.sz), (r * 0.9, wall * 0.8)], scale=(m.sx, m.sy))
    pr = 0.06 * min(m.sx, m.sy)
    # The pedestal rises from inside the basin floor and the bowl's water stops below its rim.
    m.lathe("stone", [(pr * 1.6, 0.04 * m.sz), (pr, 0.15 * m.sz), (pr, 0.55 * m.sz), (pr * 1.2, 0.6 * m.sz)])
    m.lathe("stone", [(0.1, 0.58 * m.sz), (0.3, 0.68 * m.sz), (0.28, 0.7 * m.sz)], scale=(m.sx, m.sy))
    m.lathe("water", [(0.27, 0.69 * m.sz), (0.27, 0.695 * m.sz)], scale=(m.sx, m.sy))
    m.lathe("stone", [(pr * 0.8, 0.68 * m.sz), (pr * 0.6, 0.85 * m.sz), (pr, 0.88 * m.sz), (pr * 0.3, 0.93 * m.sz)])
    m.lathe("water", [(pr * 0.5, 0.9 * m.sz), (pr * 0.35, m.sz)], fraction=0.5)


def _snowman(m: Model) -> None:
    m.main = "ceramic"
    r = min(m.sx, m.sy) / 2
    z = 0.0
    for frac in (0.42, 0.33, 0.25):
        h = frac * m.sz
        m.ball("ceramic", (0, 0, z + h / 2), (r * frac / 0.42, r * frac / 0.42, h / 2 * 1.05))
        z += h * 0.92
    head = z - 0.25 * m.sz * 0.92 / 2
    m.cylinder("accent", (0, -0.2 * r, head), (0, -r, head - 0.02 * m.sz), 0.06 * r, 0.0, fraction=0.4)
    for s in (-1, 1):
        m.ball("dark_plastic", (s * 0.15 * r, -0.5 * r, head + 0.04 * m.sz), (0.05 * r,) * 3, fraction=0.4)
        m.cylinder("bark", (s * 0.45 * r, 0, 0.58 * m.sz), (s * r, 0, 0.75 * m.sz), 0.03 * r, fraction=0.3)

def statue(m: Model) -> None:
    """A statue shows its subject on a plinth: the animal its name says ("dragon statue",
    "lion statue", a dinosaur skeleton in bone), else a standing figure; a scarecrow,
    mannequin or suit of armour is the figure itself, a snowman is a snowman."""
    if m.named("snowman"):
        _snowman(m)
        return
    if m.named("scarecrow", "mannequin", "dress form", "dummy", "suit of armor", "suit of armour", "armor", "armour"):
        figure(m)
        return
    family = family_of(m.name)
    subject = {"animal": animal, "bird": bird}.get(family, figure)
    if m.named("skeleton model", "human skeleton", "anatomical skeleton"):
        subject = figure  # a classroom's skeleton is a person's, whatever its category files it under
    if m.named("skeleton", "fossil"):
        role = "horn"
    elif m.has("gold", "golden", "gilded"):
        role = "gold"
    elif m.has("bronze", "brass", "copper"):
        role = "brass"
    else:
        role = "marble"
    m.main = role
    plinth = (0.18 if subject is not figure else 0.22) * m.sz
    m.box("stone", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, plinth * 0.8))
    m.box("stone", (-0.46 * m.sx, -0.46 * m.sy, plinth * 0.8), (0.46 * m.sx, 0.46 * m.sy, plinth))
    m.box("brass", (-0.2 * m.sx, -0.465 * m.sy, 0.3 * plinth), (0.2 * m.sx, -0.46 * m.sy, 0.6 * plinth), rounded=0.0)
    m.inset(subject, (0.0, 0.0, plinth), (0.88 * m.sx, 0.88 * m.sy, m.sz - plinth), role)


def _traffic_light(m: Model) -> None:
    m.main = "dark_metal"
    r = min(m.sx, m.sy) / 2
    m.post("dark_metal", 0, 0, 0, 0.7 * m.sz, 0.12 * r)
    m.box("dark_metal", (-0.5 * r, -0.5 * r, 0.7 * m.sz), (0.5 * r, 0.4 * r, m.sz))
    for k, role in enumerate(("accent", "flower_alt", "leaf")):
        z = m.sz - (k + 0.5) * 0.3 * m.sz / 3
        # Lamps set into the housing and never touching one another (their faces would coincide).
        m.cylinder(role, (0, -0.45 * r, z), (0, -0.52 * r, z), min(0.3 * r, 0.045 * m.sz), fraction=0.5)
        m.box("dark_metal", (-0.35 * r, -r, z + 0.3 * r), (0.35 * r, -0.5 * r, z + 0.35 * r))


def _flagpole(m: Model) -> None:
    m.main = "canvas"
    m.lathe("concrete", [(0.15 * m.sx, 0), (0.15 * m.sx, 0.02 * m.sz)])
    m.post("metal", -m.sx / 2 + 0.03 * m.sx, 0, 0, m.sz, 0.02 * m.sx + 0.01)
    m.ball("gold", (-m.sx / 2 + 0.03 * m.sx, 0, m.sz - 0.01 * m.sz), (0.03 * m.sx,) * 3, fraction=0.4)
    m.box("canvas", (-m.sx / 2 + 0.05 * m.sx, -0.01, 0.72 * m.sz), (m.sx / 2, 0.01, 0.97 * m.sz))

def lamp_post(m: Model) -> None:
    if m.named("traffic light", "traffic signal"):
        _traffic_light(m)
        return
    if m.named("flagpole", "flag"):
        _flagpole(m)
        return
    m.main = "dark_metal"
    r = min(m.sx, m.sy) / 2
    m.lathe("dark_metal", [(0.6 * r, 0), (0.6 * r, 0.05 * m.sz), (0.25 * r, 0.12 * m.sz)])
    m.post("dark_metal", 0, 0, 0.1 * m.sz, 0.86 * m.sz - 0.005, m.thick(0.1 * r, 0.2 * r))
    lz = 0.86 * m.sz
    lh = 0.1 * m.sz
    m.lathe("dark_metal", [(0.25 * r, lz - 0.01), (0.4 * r, lz)], fraction=0.5)
    m.lathe("light", [(0.35 * r, lz), (0.5 * r, lz + lh)], fraction=0.5)
    m.lathe("dark_metal", [(0.75 * r, lz + lh), (0.1 * r, m.sz - 0.02 * m.sz), (0.05 * r, m.sz)], fraction=0.5)
    for s in (-1, 1):
        m.beam("dark_metal", (0, 0, 0.72 * m.sz), (s * r * 0.9, 0, 0.8 * m.sz), 0.05 * r)
        m.ball("light", (s * r * 0.9, 0, 0.79 * m.sz), (0.1 * r, 0.1 * r, 0.1 * r), fraction=0.4)


def _tombstone(m: Model) -> None:
    m.main = "stone"
    r = m.sx / 2
    m.box("stone", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, m.sz - r))
    # A half-round top on the slab (a whole cylinder's lower half would share the slab's faces).
    arch = [(r * np.cos(a), m.sz - r + r * np.sin(a)) for a in np.linspace(0, np.pi, m.segments(0.5) + 1)]
    m.extrude("stone", arch, "y", -m.sy / 2, m.sy / 2)
    m.box("dark_plastic", (-0.25 * m.sx, -m.sy / 2 - 0.003, 0.5 * m.sz), (0.25 * m.sx, -m.sy / 2, 0.55 * m.sz), rounded=0.0)

def sign(m: Model) -> None:
    if m.named("tombstone", "gravestone", "headstone"):
        _tombstone(m)
        return
    m.main = "paint"
    glowing = m.has("neon", "holographic", "hologram", "led", "illuminated", "lit")
    if m.sz <= m.sx:
        _board_sign(m, glowing)
        return
    board_z = 0.55 * m.sz
    post = m.thick(0.05, 0.12 * m.sx)
    m.box("crystal" if glowing else "canvas_alt", (-m.sx / 2, -0.3 * m.sy, board_z), (m.sx / 2, 0.2 * m.sy, m.sz))
    m.box("paint", (-m.sx / 2 + 0.04 * m.sx, -0.3 * m.sy - 0.005, board_z + 0.6 * (m.sz - board_z)),
          (m.sx / 2 - 0.04 * m.sx, -0.3 * m.sy, board_z + 0.8 * (m.sz - board_z)), rounded=0.0)
    m.box("accent", (-m.sx / 2 + 0.1 * m.sx, -0.3 * m.sy - 0.005, board_z + 0.2 * (m.sz - board_z)),
          (m.sx / 2 - 0.3 * m.sx, -0.3 * m.sy, board_z + 0.4 * (m.sz - board_z)), rounded=0.0)
    for x in (-0.35 * m.sx, 0.35 * m.sx):
        m.box("dark_metal", (x - post / 2, 0.2 * m.sy, 0), (x + post / 2, 0.2 * m.sy + post, m.sz - 0.02))
    m.box("concrete", (-m.sx / 2, -m.sy / 2, 0), (-0.2 * m.sx, m.sy / 2, 0.03), rounded=0.0)
    m.box("concrete", (0.2 * m.sx, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, 0.03), rounded=0.0)


def _board_sign(m: Model, glowing: bool) -> None:
    """A sign wider than it is tall hangs on a wall or sits on a roof: the board with its lettering,
    no posts (a neon sign over a bar counter)."""
    m.box("crystal" if glowing else "canvas_alt", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, m.sz))
    m.box("paint", (-0.4 * m.sx, -m.sy / 2 - 0.005, 0.55 * m.sz), (0.4 * m.sx, -m.sy / 2, 0.8 * m.sz), rounded=0.0)
    m.box("accent", (-0.4 * m.sx, -m.sy / 2 - 0.005, 0.2 * m.sz), (0.2 * m.sx, -m.sy / 2, 0.4 * m.sz), rounded=0.0)


def _ladder(m: Model) -> None:
    """A ladder standing upright: two rails and evenly spaced rungs between them."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    rail = min(0.12 * W, 0.8 * D)
    for x in (-W + rail, W - rail):
        m.box("wood", (x - rail, -rail, 0), (x + rail, rail, H))
    rungs = max(3, int(H / 0.3))
    for k in range(1, rungs + 1):
        m.cylinder("dark_wood", (-W + 2 * rail, 0, H * k / (rungs + 1)), (W - 2 * rail, 0, H * k / (rungs + 1)), 0.6 * rail,
                   fraction=0.4)


def fence(m: Model) -> None:
    if m.named("ladder", "stepladder", "step ladder"):
        _ladder(m)
        return
    post = m.thick(0.08, 0.4 * m.sy)
    count = min(40, max(2, int(round(m.sx / 1.5)) + 1))
    xs = np.linspace(-m.sx / 2 + post / 2, m.sx / 2 - post / 2, count)
    for x in xs:
        m.box("wood", (x - post / 2, -post / 2, 0), (x + post / 2, post / 2, m.sz))
    for z in (0.3 * m.sz, 0.75 * m.sz):
        m.box("wood", (-m.sx / 2, -m.sy / 2, z), (m.sx / 2, -m.sy / 2 + 0.35 * m.sy, z + 0.06 * m.sz))
    picket = max(0.08, m.sx / 180)
    n = int(m.sx / (picket * 1.8))
    for i in range(n):
        x = -m.sx / 2 + (i + 0.5) * m.sx / n
        m.extrude("wood", [(x - picket / 2, 0.05 * m.sz), (x + picket / 2, 0.05 * m.sz), (x + picket / 2, 0.9 * m.sz),
                           (x, 0.95 * m.sz), (x - picket / 2, 0.9 * m.sz)], "y", m.sy / 2 - 0.35 * m.sy, m.sy / 2)


def arch(m: Model) -> None:
    if m.named("bridge", "footbridge"):
        _bridge(m)
        return
    if m.has("torii", "shrine", "japanese"):
        _torii(m)
        return
    m.main = "stone"
    pillar = m.thick(0.15 * m.sx, 0.3 * m.sx)
    span = m.sx - 2 * pillar
    r = span / 2 + pillar / 2
    spring = max(0.1 * m.sz, m.sz - r - pillar / 2)
    for s in (-1, 1):
        x0, x1 = sorted((s * m.sx / 2, s * (m.sx / 2 - pillar)))
        m.box("stone", (x0, -m.sy / 2, 0), (x1, m.sy / 2, spring))
    ring = P.torus(r, pillar / 2, m.segments(1.0), 8, np.pi)
    ring = P.transform(ring, P.affine(np.diag([1.0, 1.0, m.sy / pillar]), (0, 0, 0)))
    m.add("stone", P.transform(ring, P.affine(np.array([[1, 0, 0], [0, 0, 1], [0, 1, 0]], float), (0, 0, spring))))
    m.box("stone", (-0.06 * m.sx, -m.sy / 2 - 0.01, m.sz - pillar * 0.6), (0.06 * m.sx, m.sy / 2 + 0.01, m.sz))


def _bridge(m: Model) -> None:
    """A footbridge one walks along its depth: a deck that rises from ground at both ends to its
    crown (higher when it is "arched" or "humped"), a railing of posts and a handrail each side
    (a parapet on a stone one),
    so what stands on it stands on the deck and what passes under it passes under the crown."""
    m.main = "stone" if m.has("stone", "brick") else "wood"
    rail = min(0.9, 0.45 * m.sz)
    thick = max(0.06, 0.08 * m.sz)
    crown = m.sz - rail if m.has("arched", "humped", "humpback", "curved", "moon") else 0.5 * (m.sz - rail)
    half, width = m.sy / 2, m.sx
    ys = np.linspace(-half, half, 9)
    tops = thick + (crown - thick) * (1 - (ys / half) ** 2)
    for y0, y1, z0, z1 in zip(ys, ys[1:], tops, tops[1:]):
        m.extrude(m.main, [(y0, z0 - thick), (y1, z1 - thick), (y1, z1), (y0, z0)], "x", -width / 2, width / 2)
    r = m.thick(0.02 * width, 0.035 * width)
    if m.main == "stone":  # a parapet wall each side
        wall = 0.6 * rail
        for y0, y1, z0, z1 in zip(ys, ys[1:], tops, tops[1:]):
            for x0 in (-width / 2, width / 2 - 2 * r):
                m.extrude(m.main, [(y0, z0), (y1, z1), (y1, z1 + wall), (y0, z0 + wall)], "x", x0, x0 + 2 * r)
        return
    for side in (-1, 1):
        x = side * (width / 2 - r)
        for y, z in zip(ys, tops):
            m.post(m.main, x, y, z, z + rail, r)
        for y0, y1, z0, z1 in zip(ys, ys[1:], tops, tops[1:]):
            m.cylinder(m.main, (x, y0, z0 + rail), (x, y1, z1 + rail), 1.2 * r, fraction=0.4)


def _torii(m: Model) -> None:
    m.main = "paint"
    r = m.thick(0.05 * m.sx, 0.1 * m.sx)
    for s in (-1, 1):
        m.post("paint", s * 0.36 * m.sx, 0, 0.06 * m.sz, 0.88 * m.sz, r)
        m.lathe("dark_metal", [(1.3 * r, 0), (1.3 * r, 0.06 * m.sz)], centre=(s * 0.36 * m.sx, 0, 0))
    m.box("paint", (-0.45 * m.sx, -0.5 * r, 0.7 * m.sz), (0.45 * m.sx, 0.5 * r, 0.76 * m.sz))
    m.extrude("lacquer", [(-m.sx / 2, 0.93 * m.sz), (-0.4 * m.sx, 0.88 * m.sz), (0.4 * m.sx, 0.88 * m.sz),
                          (m.sx / 2, 0.93 * m.sz), (m.sx / 2, m.sz), (-m.sx / 2, m.sz)], "y", -m.sy / 2, m.sy / 2)
    m.box("paint", (-0.47 * m.sx, -0.4 * m.sy, 0.84 * m.sz), (0.47 * m.sx, 0.4 * m.sy, 0.89 * m.sz))


def bollard(m: Model) -> None:
    m.main = "dark_metal"
    r = min(m.sx, m.sy) / 2
    m.lathe("dark_metal", [(r, 0), (r, 0.05 * m.sz), (0.8 * r, 0.08 * m.sz), (0.8 * r, 0.88 * m.sz), (0.6 * r, 0.96 * m.sz),
                           (0, m.sz)])
    m.lathe("accent", [(0.82 * r, 0.75 * m.sz), (0.82 * r, 0.82 * m.sz)])


def hydrant(m: Model) -> None:
    m.main = "paint"
    r = min(m.sx, m.sy) / 2
    m.lathe("paint", [(0.7 * r, 0), (0.7 * r, 0.06 * m.sz), (0.5 * r, 0.08 * m.sz), (0.5 * r, 0.75 * m.sz),
                      (0.6 * r, 0.78 * m.sz), (0.45 * r, 0.92 * m.sz), (0.1 * r, m.sz)])
    z = 0.55 * m.sz
    m.cylinder("paint", (-m.sx / 2 + 0.02, 0, z), (m.sx / 2 - 0.02, 0, z), 0.2 * r, fraction=0.5)  # ends inside the caps
    m.cylinder("metal", (0, 0, z), (0, -m.sy / 2, z), 0.28 * r, fraction=0.5)
    m.cylinder("metal", (-m.sx / 2, 0, z), (-m.sx / 2 + 0.04, 0, z), 0.24 * r, fraction=0.5)
    m.cylinder("metal", (m.sx / 2 - 0.04, 0, z), (m.sx / 2, 0, z), 0.24 * r, fraction=0.5)


def well(m: Model) -> None:
    m.main = "stone"
    r = 0.5
    wall = 0.35 * m.sz
    m.lathe("stone", [(r * 0.82, 0), (r, 0), (r, wall), (r * 0.8, wall), (r * 0.8, 0.02)], scale=(0.8 * m.sx, 0.8 * m.sy))
    m.lathe("water", [(r * 0.8, 0.01), (r * 0.8, wall * 0.5)], scale=(0.8 * m.sx, 0.8 * m.sy))
    post = m.thick(0.07, 0.08 * m.sx)
    roof_z = 0.75 * m.sz
    for s in (-1, 1):
        m.box("wood", (s * 0.42 * m.sx - post / 2, -post / 2, 0), (s * 0.42 * m.sx + post / 2, post / 2, roof_z))
    m.cylinder("wood", (-0.42 * m.sx, 0, 0.6 * m.sz), (0.45 * m.sx, 0, 0.6 * m.sz), 0.04 * m.sz, fraction=0.5)
    m.post("dark_metal", 0, 0, 0.35 * m.sz, 0.6 * m.sz, 0.006, fraction=0.3)
    m.lathe("wood", [(0.06 * m.sx, 0.3 * m.sz), (0.07 * m.sx, 0.4 * m.sz)])
    m.extrude("roof", [(-m.sy / 2, roof_z), (m.sy / 2, roof_z), (0, m.sz)], "x", -m.sx / 2, m.sx / 2)


def _cat_tree(m: Model) -> None:
    """A cat tree: carpeted platforms on sisal posts over a base board, the widest platform on
    top at the full height, so a cat put ``on`` it lies on the carpet (a scratching post is one
    post with a small top)."""
    m.main = "fabric"
    base = 0.05 * m.sz
    m.box("fabric", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, base))
    post_r = m.thick(0.06, 0.18 * min(m.sx, m.sy))
    deck = max(0.03, 0.04 * m.sz)
    if m.named("scratching post", "scratch post", "scratcher"):
        m.post("paper", 0, 0, base, m.sz - deck, post_r)
        m.box("fabric", (-0.3 * m.sx, -0.3 * m.sy, m.sz - deck), (0.3 * m.sx, 0.3 * m.sy, m.sz))
        return
    # Two posts up to a middle deck to one side, one post from there up to the top platform.
    mid = 0.5 * m.sz
    for x, y in ((-0.25 * m.sx, -0.2 * m.sy), (0.25 * m.sx, 0.2 * m.sy)):
        m.post("paper", x, y, base, mid - deck, post_r)
    m.box("fabric", (-m.sx / 2, -m.sy / 2 + 0.1 * m.sy, mid - deck), (0.1 * m.sx, m.sy / 2, mid))
    m.post("paper", -0.2 * m.sx, 0.1 * m.sy, mid, m.sz - deck, post_r)
    m.box("fabric", (-m.sx / 2, -m.sy / 2, m.sz - deck), (m.sx / 2, m.sy / 2, m.sz))
    m.ball("cushion", (0.3 * m.sx, -0.3 * m.sy, 0.3 * m.sz), (0.07 * m.sx,) * 3, fraction=0.4)


def pillar(m: Model) -> None:
    if m.named("cat tree", "cat tower", "cat condo", "cat climber", "scratching post", "scratch post", "scratcher"):
        _cat_tree(m)
        return
    m.main = "marble"
    base = 0.08 * m.sz
    m.box("marble", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, base))
    m.box("marble", (-m.sx / 2, -m.sy / 2, m.sz - base), (m.sx / 2, m.sy / 2, m.sz))
    r = 0.4 * min(m.sx, m.sy)
    m.lathe("marble", [(1.1 * r, base), (r, base + 0.03 * m.sz), (0.88 * r, m.sz - base - 0.05 * m.sz),
                       (1.1 * r, m.sz - base)])


def _hologram(m: Model) -> None:
    """A hologram: light alone, so it floats wherever the text puts it; a ring of light at its
    foot, and above it, in glowing translucent light, what it shows: the creature or person its
    name says, a planet (a globe with a ring), else an orb inside orbit rings."""
    m.main = "crystal"
    r, H = min(m.sx, m.sy) / 2, m.sz
    base = min(0.08 * H, 0.12)
    m.torus("light", (0, 0, base), 0.7 * r, 0.03 * r + 0.005)
    family = family_of(" ".join(w for w in m.name.split() if not w.startswith("holo")))
    if family in ("animal", "bird", "figure"):
        # (a person in a standing person's footprint: a deeper box would draw one sitting)
        box = (m.sx, m.sy) if family != "figure" else (min(m.sx, 0.3 * (H - base)), min(m.sy, 0.17 * (H - base)))
        m.inset({"animal": animal, "bird": bird}.get(family, figure), (0, 0, 1.3 * base), (*box, H - 1.3 * base), "crystal")
        return
    ringed = m.has("planet", "saturn", "world")
    globe = min(r / (1.55 if ringed else 1.35), (H - base) / 2.4)
    centre = (0, 0, H - 1.15 * globe)
    m.ball("crystal", centre, (globe, globe, globe))
    if ringed:
        m.torus("crystal", centre, 1.5 * globe, 0.04 * globe)
    elif not m.has("globe", "earth", "moon", "sun", "star"):
        for axis in ("x", "y"):
            m.torus("crystal", centre, 1.3 * globe, 0.025 * globe, axis=axis)


def crystal(m: Model) -> None:
    if m.named("hologram", "holographic", "holo"):
        _hologram(m)
        return
    m.main = "crystal"
    r = min(m.sx, m.sy) / 2
    m.ball("stone", (0, 0, 0.05 * m.sz), (0.8 * r, 0.8 * r, 0.12 * m.sz), fraction=0.4)
    count = int(m.rng.integers(3, 6))
    for k in range(count):
        h = m.sz * (1.0 if k == 0 else m.vary(0.35, 0.7))
        cr = r * (0.35 if k == 0 else m.vary(0.15, 0.25))
        a = 2 * np.pi * k / count
        tilt = 0.0 if k == 0 else m.vary(0.3, 0.6)
        base = np.array([np.cos(a) * 0.35 * r, np.sin(a) * 0.35 * r, 0.0]) * (k > 0)
        d = np.array([np.cos(a) * np.sin(tilt), np.sin(a) * np.sin(tilt), np.cos(tilt)])
        part = P.lathe([(cr, 0), (cr, 0.78 * h), (0, h)], 6)
        m.add("crystal", P.flatten(P.transform(part, P.affine(P.align_z(d), base))))


def _mushroom(m: Model) -> None:
    m.main = "paint"
    m.lathe("canvas_alt", [(0.16 * m.sx, 0), (0.12 * m.sx, 0.4 * m.sz), (0.14 * m.sx, 0.65 * m.sz)])
    m.lathe("paint", [(0.5, 0.55 * m.sz), (0.48, 0.7 * m.sz), (0.35, 0.88 * m.sz), (0.0, m.sz)], scale=(m.sx, m.sy))
    for k in range(7):
        a = 2 * np.pi * k / 7
        m.ball("canvas_alt", (np.cos(a) * 0.3 * m.sx, np.sin(a) * 0.3 * m.sy, 0.84 * m.sz), (0.05 * m.sx, 0.05 * m.sy, 0.04 * m.sz),
               fraction=0.4)

def umbrella(m: Model) -> None:
    if m.named("mushroom", "toadstool"):
        _mushroom(m)
        return
    m.main = "canvas"
    r = 0.5
    m.lathe("dark_metal", [(0.15 * min(m.sx, m.sy), 0), (0.15 * min(m.sx, m.sy), 0.03 * m.sz), (0.02, 0.05 * m.sz)])
    m.post("dark_metal", 0, 0, 0.03 * m.sz, 0.97 * m.sz, m.thick(0.02, 0.04 * min(m.sx, m.sy)), fraction=0.4)
    canopy = P.lathe([(r, 0.78 * m.sz), (0.3 * r, 0.9 * m.sz), (0.0, 0.95 * m.sz)], max(6, m.segments(0.67)))
    m.add("canvas", P.transform(canopy, P.affine(np.diag([m.sx, m.sy, 1.0]), (0, 0, 0))))
    m.lathe("canvas_alt", [(r * 1.0, 0.76 * m.sz), (r * 1.0, 0.78 * m.sz)], scale=(m.sx, m.sy), fraction=0.67)
    m.ball("dark_metal", (0, 0, 0.97 * m.sz), (0.02, 0.02, 0.03 * m.sz), fraction=0.4)


def swing(m: Model) -> None:
    m.main = "paint"
    leg = m.thick(0.06, 0.1 * m.sy)
    top = m.sz - leg
    for s in (-1, 1):
        x = s * (m.sx / 2 - leg)
        for ys in (-1, 1):  # the legs of an A meet at the top: one a little thinner, or their sides coincide
            m.cylinder("paint", (x, ys * (m.sy / 2 - leg), 0), (x, 0, top), leg * (1 if ys < 0 else 0.92), fraction=0.5)
    m.cylinder("paint", (-m.sx / 2, 0, top), (m.sx / 2, 0, top), leg, fraction=0.5)
    seats = 2 if m.sx > 1.8 else 1
    for i in range(seats):
        cx = -m.sx / 2 + m.sx * (i + 1) / (seats + 1)
        seat_z = 0.4 if m.sz > 1.2 else 0.2 * m.sz
        for dx in (-0.2, 0.2):
            m.post("chrome", cx + dx, 0, seat_z, top, 0.008, fraction=0.25)
        m.box("rubber", (cx - 0.24, -0.1, seat_z - 0.03), (cx + 0.24, 0.1, seat_z))


def slide(m: Model) -> None:
    m.main = "paint"
    deck = 0.6 * m.sz
    back = m.sy / 2 - 0.25 * m.sy
    w = 0.4 * m.sx
    for x in (-w, w):
        m.beam("metal", (x, m.sy / 2 - 0.02, 0), (x, back, deck + 0.35 * (m.sz - deck)), 0.04)
    for k in range(1, 6):
        z = deck * k / 6
        y = m.sy / 2 - 0.02 - (m.sy / 2 - 0.02 - back) * z / (deck + 0.35 * (m.sz - deck))
        m.cylinder("metal", (-w, y, z), (w, y, z), 0.015, fraction=0.3)
    m.box("accent", (-m.sx / 2, back - 0.25 * m.sy, deck - 0.05), (m.sx / 2, back, deck))
    for x in (-m.sx / 2, m.sx / 2 - 0.05):
        m.box("metal", (x, back - 0.25 * m.sy, 0), (x + 0.05, back - 0.2 * m.sy, deck - 0.05))  # up to the platform
        m.box("metal", (x, back - 0.25 * m.sy, deck), (x + 0.05, back, m.sz))
    start = back - 0.25 * m.sy
    chute = [(start, deck), (start, deck + 0.12), (-m.sy / 2, 0.12), (-m.sy / 2, 0.0), (-m.sy / 2 + 0.2, 0.0)]
    m.extrude("paint", chute, "x", -0.3 * m.sx, 0.3 * m.sx)
    for x in (-0.3 * m.sx - 0.04, 0.3 * m.sx):  # side walls outside the chute, not overlapping it
        m.extrude("paint", [(start, deck), (start, deck + 0.25), (-m.sy / 2, 0.3), (-m.sy / 2, 0.05)], "x", x, x + 0.04)


def _gazebo(m: Model) -> None:
    m.main = "wood"
    eave = 0.62 * m.sz
    post = m.thick(0.1, 0.06 * m.sx)
    for k in range(6):
        a = 2 * np.pi * k / 6
        m.post("wood", np.cos(a) * 0.44 * m.sx, np.sin(a) * 0.44 * m.sy, 0.1, eave, post, fraction=0.5)
    m.lathe("wood", [(0.48, 0), (0.48, 0.1)], scale=(m.sx, m.sy), fraction=0.25)
    m.lathe("roof", [(0.5, eave), (0.5, eave + 0.04 * m.sz), (0.0, m.sz)], scale=(m.sx, m.sy), fraction=0.25)
    m.lathe("wood", [(0.46, 0.42 * eave), (0.46, 0.45 * eave)], scale=(m.sx, m.sy), fraction=0.25)

def _canopy(m: Model) -> None:
    """A canopy (a forecourt's, a market's, a shelter's): a flat roof with a deep fascia on
    square posts, open on every side, so what stands under it shows."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    fascia = min(0.15 * H, 0.6)
    post = m.thick(0.12, 0.06 * min(m.sx, m.sy))
    nx = 2 if m.sx < 8 else 3
    for i in range(nx):
        x = -0.8 * W + i * 1.6 * W / (nx - 1)
        for y in (-0.75 * D, 0.75 * D):
            m.box("metal", (x - post, y - post, 0), (x + post, y + post, H - fascia + 0.01))
    m.box("paint", (-W, -D, H - fascia), (W, D, H))
    m.box("light", (-0.9 * W, -0.9 * D, H - fascia - 0.02), (0.9 * W, 0.9 * D, H - fascia + 0.005), rounded=0.0)


def tent(m: Model) -> None:
    if m.named("gazebo", "pavilion", "pergola"):
        _gazebo(m)
        return
    if m.named("canopy", "awning", "shelter", "carport", "lean-to"):
        _canopy(m)
        return
    m.main = "canvas"
    m.extrude("canvas", [(-m.sx / 2, 0), (m.sx / 2, 0), (0, m.sz)], "y", -m.sy / 2 + 0.02, m.sy / 2)
    m.extrude("dark_plastic", [(-0.2 * m.sx, 0), (0.2 * m.sx, 0), (0, 0.7 * m.sz)], "y", -m.sy / 2, -m.sy / 2 + 0.03)
    m.post("dark_metal", 0, -m.sy / 2 + 0.01, 0, m.sz * 1.0, 0.015, fraction=0.3)
    for s in (-1, 1):
        m.cylinder("canvas_alt", (0, s * (m.sy / 2 - 0.02), m.sz), (s * 0.05 * m.sx, s * m.sy / 2, 0), 0.006, fraction=0.25)


SHAPES = {
    "tree": tree, "pine_tree": pine_tree, "palm_tree": palm_tree, "bush": bush, "flower_bed": flower_bed, "rock": rock,
    "fountain": fountain, "statue": statue, "lamp_post": lamp_post, "sign": sign, "fence": fence, "arch": arch,
    "bollard": bollard, "hydrant": hydrant, "well": well, "pillar": pillar, "crystal": crystal, "umbrella": umbrella,
    "swing": swing, "slide": slide, "tent": tent,
}
