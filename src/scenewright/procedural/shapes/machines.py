"""Machines, vessels and hand tools the catalogue does not know one by one: a boxy machine
with the panels, vents, pipes, screens and buttons its name calls for (or a furnace, a
periscope), a tank (fuel tank on saddles, silo, water tower, boiler, cauldron, aquarium), a
tool (anvil, hammer, long-handled tools, sword, lens, papers, telescope, cone, trophy, radio,
weathervane..., else a toolbox). Fronts face −Y."""

from __future__ import annotations

import numpy as np

from scenewright.procedural.builder import Model
from scenewright.procedural.shapes import creatures
from scenewright.procedural.shapes.frames import ring
from scenewright.procedural.shapes.vehicles import _battle_tank


def _buttons(m: Model, x0: float, x1: float, z: float, y: float, count: int, r: float) -> None:
    """A row of round buttons on a front at ``y``, in alternating colours."""
    for k in range(count):
        x = x0 + (k + 0.5) * (x1 - x0) / count
        role = ("accent", "flower_alt", "leaf", "book_b")[k % 4]
        m.cylinder(role, (x, y + 0.002, z), (x, y - r, z), r, fraction=0.3)


def _vents(m: Model, x0: float, x1: float, z0: float, z1: float, y: float, count: int) -> None:
    """Horizontal louvres on a front at ``y``."""
    step = (z1 - z0) / count
    for k in range(count):
        z = z0 + (k + 0.3) * step
        m.box("dark_metal", (x0, y - 0.01 * m.sy, z), (x1, y + 0.001, z + 0.4 * step), rounded=0.0)


def _jukebox(m: Model) -> None:
    """A jukebox: a cabinet under a round arched top, a lit arch of tubes round a glass dome
    over the record deck, a speaker grille below."""
    m.main = "dark_wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    body = H - W  # the arch's springing line: a half circle as wide as the cabinet tops it
    m.box("dark_wood", (-W, -D, 0), (W, D, body))
    m.cylinder("dark_wood", (0, -0.97 * D, body), (0, 0.97 * D, body), W, fraction=1.0)  # inside the body's faces
    m.torus("light", (0, -D - 0.01, body), 0.85 * W, 0.06 * W, axis="y", arc=np.pi, fraction=0.8)
    m.ball("glass", (0, -D + 0.1 * D, body), (0.6 * W, 0.3 * D, 0.55 * W), fraction=0.6)
    m.box("chrome", (-0.7 * W, -D - 0.01, 0.45 * body), (0.7 * W, -D, 0.5 * body), rounded=0.0)
    m.box("fabric", (-0.6 * W, -D - 0.01, 0.08 * body), (0.6 * W, -D, 0.4 * body), rounded=0.0)
    for x in (-0.85 * W, 0.85 * W):
        m.box("accent", (x - 0.05 * W, -D - 0.02, 0.05 * body), (x + 0.05 * W, -D + 0.02, 0.98 * body), rounded=0.0)


def _hood_dryer(m: Model) -> None:
    """A salon hair dryer on its stand: a five-footed base, a pole, and the hood on an arm,
    tilted forward."""
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = 0.03 * min(m.sx, m.sy) + 0.008
    for k in range(5):
        a = 2 * np.pi * k / 5 + np.pi / 2
        m.beam("dark_metal", (0, 0, 0.03 * H), (0.8 * W * np.cos(a), 0.8 * D * np.sin(a), 0.02 * H), 1.5 * r)
    m.post("chrome", 0, 0.3 * D, 0.04 * H, 0.72 * H, r, fraction=0.4)
    m.beam("chrome", (0, 0.3 * D, 0.7 * H), (0, -0.1 * D, 0.76 * H), r)
    hood = min(W, D, 0.15 * H)
    m.ball("plastic", (0, -0.25 * D, 0.78 * H), (hood, 1.1 * hood, 0.9 * hood), fraction=0.8)
    m.ball("dark_plastic", (0, -0.25 * D - 0.4 * hood, 0.74 * H), (0.8 * hood, 0.75 * hood, 0.6 * hood), fraction=0.6)


def _arcade(m: Model) -> None:
    """An arcade cabinet: side panels, a tilted screen, a control deck, a lit marquee."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    side = 0.08 * W
    # Each side panel in three convex pieces (body, marquee hood, control deck): an extrusion's
    # caps are fans from the outline's mean, which fold over on a notched outline.
    pieces = ([(-0.2 * D, 0), (D, 0), (D, H), (-0.1 * D, H), (-0.1 * D, 0.6 * H), (-0.2 * D, 0.42 * H)],
              [(-0.1 * D, H), (-0.5 * D, H), (-0.5 * D, 0.85 * H), (-0.1 * D, 0.8 * H)],
              [(-D, 0.45 * H), (-0.2 * D, 0.42 * H), (-0.1 * D, 0.6 * H), (-D, 0.52 * H)])
    for s in (-1, 1):
        x0, x1 = sorted((s * W, s * (W - side)))
        for outline in pieces:
            m.extrude("paint", outline, "x", x0, x1)
    m.box("dark_plastic", (-W + side, -0.2 * D, 0), (W - side, D, 0.42 * H))
    m.box("dark_plastic", (-W + side, -0.1 * D, 0.6 * H), (W - side, D, 0.85 * H))
    m.extrude("screen", [(-0.1 * D, 0.6 * H), (-0.45 * D, 0.84 * H), (-0.42 * D, 0.845 * H), (-0.07 * D, 0.605 * H)], "x",
              -W + side + 0.002, W - side - 0.002)  # its ends clear the panels (the box behind it meets them)
    m.extrude("dark_plastic", [(-D, 0.45 * H), (-0.2 * D, 0.42 * H), (-0.1 * D, 0.6 * H), (-D, 0.52 * H)], "x", -W + side, W - side)
    m.box("light", (-W + side, -0.5 * D, 0.87 * H), (W - side, -0.45 * D, 0.97 * H), rounded=0.0)
    m.post("dark_metal", -0.4 * W, -0.7 * D, 0.5 * H, 0.56 * H, 0.03 * W, fraction=0.3)
    m.ball("accent", (-0.4 * W, -0.7 * D, 0.565 * H), (0.07 * W,) * 3, fraction=0.4)
    for k in range(4):
        m.cylinder(("accent", "flower_alt", "leaf", "book_b")[k], (0.05 * W + 0.2 * W * k, -0.75 * D, 0.5 * H),
                   (0.05 * W + 0.2 * W * k, -0.75 * D, 0.515 * H), 0.06 * W, fraction=0.3)
    m.box("brass", (-0.2 * W, -0.21 * D, 0.2 * H), (0.2 * W, -0.19 * D, 0.3 * H), rounded=0.0)


def _console(m: Model) -> None:
    """A control console or terminal: a desk-high base with a sloped top of screens and keys."""
    m.main = "metal"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    desk = 0.55 * H
    m.box("metal", (-W, -0.4 * D, 0), (W, D, desk))
    m.box("dark_metal", (-W, -D, 0.02 * H), (W, -0.4 * D, 0.06 * H), rounded=0.0)
    # The sloped top and its front lip as two convex outlines (a fan over the notched whole folds).
    m.extrude("metal", [(-0.4 * D, desk), (D, desk), (D, 0.72 * H), (-0.4 * D, desk + 0.02 * H)], "x", -W, W)
    m.extrude("metal", [(-D, desk), (-0.4 * D, desk), (-0.4 * D, desk + 0.02 * H)], "x", -W, W)
    def slope(y: float) -> float:
        return desk + 0.02 * H + (y + 0.4 * D) * (0.72 * H - desk - 0.02 * H) / (1.4 * D)

    # The dark control surface lies on the slope (its underside on the slope's face, facing away).
    m.extrude("dark_plastic", [(-0.25 * D, slope(-0.25 * D)), (0.9 * D, slope(0.9 * D)), (0.9 * D, slope(0.9 * D) + 0.01 * H),
                               (-0.25 * D, slope(-0.25 * D) + 0.01 * H)], "x", -0.95 * W, 0.95 * W)
    _buttons(m, -0.9 * W, -0.1 * W, desk + 0.03 * H, -0.4 * D, 5, 0.02 * H)
    m.box("dark_plastic", (-0.8 * W, 0.6 * D, 0.72 * H), (0.8 * W, D, H))
    screens = max(1, min(3, int(round(m.sx / max(0.5, 0.6 * m.sz)))))
    for k in range(screens):
        x0 = -0.75 * W + k * 1.5 * W / screens
        m.box("screen", (x0 + 0.03 * W, 0.58 * D, 0.75 * H), (x0 + 1.5 * W / screens - 0.03 * W, 0.6 * D, 0.97 * H), rounded=0.0)
    m.box("light", (-0.3 * W, -0.3 * D, desk + 0.035 * H), (0.9 * W, 0.3 * D, desk + 0.045 * H), rounded=0.0)


def _engine(m: Model) -> None:
    """A generator or engine on a skid: a block with cylinder heads, a radiator, an exhaust,
    a fuel tank and a control box with gauges."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    skid = 0.08 * H
    for s in (-1, 1):
        m.box("dark_metal", (-W, s * 0.8 * D - 0.1 * D, 0), (W, s * 0.8 * D + 0.1 * D, skid))
    m.box("dark_metal", (-0.9 * W, -0.75 * D, skid), (0.9 * W, 0.75 * D, skid + 0.04 * H))
    m.box("paint", (-0.55 * W, -0.6 * D, skid + 0.04 * H), (0.35 * W, 0.6 * D, 0.62 * H))  # on the plate, not through it
    for k in range(3):
        x = -0.4 * W + 0.3 * W * k
        m.box("metal", (x - 0.1 * W, -0.45 * D, 0.62 * H), (x + 0.1 * W, 0.45 * D, 0.72 * H))
    m.box("dark_metal", (0.4 * W, -0.7 * D, skid + 0.04 * H), (W, 0.7 * D, 0.7 * H))
    _vents(m, 0.45 * W, 0.95 * W, 0.15 * H, 0.65 * H, -0.7 * D, 8)
    m.cylinder("metal", (-0.75 * W, -0.4 * D, skid), (-0.75 * W, 0.4 * D, skid), 0.01 * H)
    m.cylinder("paint", (-0.55 * W, 0.0, 0.82 * H), (0.35 * W, 0.0, 0.82 * H), min(0.1 * H, 0.4 * D), fraction=0.7)
    m.cylinder("dark_metal", (-0.8 * W, 0.3 * D, 0.5 * H), (-0.8 * W, 0.3 * D, H), 0.05 * min(W, D) + 0.01 * H, fraction=0.5)
    m.cylinder("dark_metal", (-0.55 * W, 0.3 * D, 0.5 * H), (-0.8 * W, 0.3 * D, 0.5 * H), 0.04 * min(W, D) + 0.01 * H, fraction=0.5)
    m.box("dark_plastic", (-W, -0.8 * D, 0.3 * H), (-0.6 * W, -0.3 * D, 0.6 * H))
    for z in (0.48 * H, 0.38 * H):
        m.cylinder("ceramic", (-0.8 * W, -0.8 * D, z), (-0.8 * W, -0.82 * D, z), 0.04 * H, fraction=0.4)
    m.box("accent", (-0.7 * W, -0.82 * D, 0.33 * H), (-0.65 * W, -0.8 * D, 0.36 * H), rounded=0.0)


def _compressor(m: Model) -> None:
    """An air compressor: a horizontal receiver tank on feet with the motor and pump on top."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = min(0.3 * H, 0.9 * D)
    for x in (-0.6 * W, 0.6 * W):
        m.box("dark_metal", (x - 0.05 * W, -0.8 * D, 0), (x + 0.05 * W, 0.8 * D, 0.2 * r))
    m.cylinder("paint", (-0.92 * W, 0, 0.2 * r + r), (0.92 * W, 0, 0.2 * r + r), r, fraction=0.8)
    for s in (-1, 1):
        m.ball("paint", (s * 0.92 * W, 0, 1.2 * r), (0.1 * W, r, r), fraction=0.6)
    top = 2.2 * r
    m.cylinder("dark_metal", (-0.5 * W, 0, top + 0.2 * (H - top)), (0.05 * W, 0, top + 0.2 * (H - top)), 0.5 * (H - top) * 0.6,
               fraction=0.6)
    m.box("metal", (0.15 * W, -0.5 * D, top), (0.6 * W, 0.5 * D, H))
    _vents(m, 0.2 * W, 0.55 * W, top + 0.1 * (H - top), H - 0.1 * (H - top), -0.5 * D, 5)
    m.cylinder("ceramic", (-0.7 * W, -r, top - 0.1 * r), (-0.7 * W, -1.05 * r, top - 0.1 * r), 0.2 * r, fraction=0.4)


def _printer(m: Model) -> None:
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    if m.named("3d printer"):
        m.box("dark_plastic", (-W, -D, 0), (W, D, 0.12 * H))
        for x in (-0.99 * W, 0.91 * W):  # posts between base and top, standing in from their sides
            for y in (-0.99 * D, 0.91 * D):
                m.box("dark_metal", (x, y, 0.12 * H), (x + 0.08 * W, y + 0.08 * D, 0.92 * H))
        m.box("dark_metal", (-W, -D, 0.92 * H), (W, D, H))
        m.box("metal", (-0.6 * W, -0.6 * D, 0.25 * H), (0.6 * W, 0.6 * D, 0.28 * H), rounded=0.0)
        m.box("accent", (-0.2 * W, -0.2 * D, 0.28 * H), (0.2 * W, 0.2 * D, 0.45 * H))
        m.box("dark_metal", (-0.9 * W, -0.1 * D, 0.7 * H), (0.9 * W, 0.1 * D, 0.75 * H))
        m.box("screen", (-0.4 * W, -1.01 * D, 0.03 * H), (0.1 * W, -D, 0.1 * H), rounded=0.0)
        return
    m.box("plastic", (-W, -0.8 * D, 0), (W, D, 0.75 * H))
    m.box("dark_plastic", (-0.8 * W, -D, 0.15 * H), (0.8 * W, -0.8 * D, 0.3 * H))
    m.box("paper", (-0.6 * W, -D - 0.01 * D, 0.3 * H), (0.6 * W, -0.6 * D, 0.32 * H), rounded=0.0)
    m.box("plastic", (-W, -0.8 * D, 0.75 * H), (W, D, 0.82 * H))
    m.extrude("paper", [(-0.3 * D, 0.82 * H), (0.9 * D, 0.82 * H), (0.9 * D, H), (0.7 * D, H)], "x", -0.5 * W, 0.5 * W)
    m.box("screen", (0.3 * W, -0.82 * D, 0.6 * H), (0.8 * W, -0.8 * D, 0.7 * H), rounded=0.0)
    _buttons(m, 0.3 * W, 0.8 * W, 0.5 * H, -0.8 * D, 3, 0.02 * H)


def _washer(m: Model) -> None:
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("plastic", (-W, -0.95 * D, 0), (W, D, H))
    r = min(0.7 * W, 0.32 * H)
    m.torus("metal", (0, -0.95 * D, 0.42 * H), r, 0.1 * r, axis="y")
    m.cylinder("glass", (0, -0.9 * D, 0.42 * H), (0, -D, 0.42 * H), 0.9 * r)
    m.box("metal", (-W, -D, 0.85 * H), (W, -0.95 * D, H), rounded=0.0)
    m.cylinder("dark_plastic", (0.6 * W, -D, 0.92 * H), (0.6 * W, -1.02 * D, 0.92 * H), 0.04 * H, fraction=0.4)
    m.box("screen", (-0.3 * W, -1.005 * D, 0.89 * H), (0.3 * W, -D, 0.95 * H), rounded=0.0)


def _server(m: Model) -> None:
    m.main = "dark_metal"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("dark_metal", (-W, -D, 0), (W, D, H))
    units = max(4, min(16, int(m.sz / 0.12)))
    for k in range(units):
        z0 = 0.05 * H + k * 0.9 * H / units
        m.box("dark_plastic", (-0.9 * W, -1.01 * D, z0), (0.9 * W, -D, z0 + 0.8 * 0.9 * H / units), rounded=0.0)
        m.box("leaf" if k % 3 else "accent", (0.7 * W, -1.02 * D, z0 + 0.3 * 0.9 * H / units),
              (0.78 * W, -1.01 * D, z0 + 0.5 * 0.9 * H / units), rounded=0.0)


def _furnace(m: Model) -> None:
    """A furnace, kiln or forge: a brick body with a glowing mouth behind an iron door
    frame, an ash door below and a flue rising from the top."""
    m.main = "brick"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    body = 0.75 * H
    m.box("brick", (-W, -D, 0), (W, D, body))
    m.box("dark_metal", (-0.45 * W, -1.03 * D, 0.3 * body), (0.45 * W, -D, 0.75 * body), rounded=0.0)
    m.box("flame", (-0.35 * W, -1.04 * D, 0.36 * body), (0.35 * W, -1.03 * D, 0.68 * body), rounded=0.0)
    m.box("dark_metal", (-0.3 * W, -1.03 * D, 0.05 * body), (0.3 * W, -D, 0.2 * body), rounded=0.0)
    m.box("stone", (-1.03 * W, -1.03 * D, body), (1.03 * W, 1.03 * D, body + 0.05 * H))
    r = 0.2 * min(m.sx, m.sy)
    m.cylinder("dark_metal", (0, 0.2 * D, body + 0.05 * H), (0, 0.2 * D, H), r, 0.8 * r, fraction=0.6)


def _periscope(m: Model) -> None:
    """A periscope: a column rising through a collar, a head box at eye height with its
    eyepiece and two folding handles."""
    m.main = "dark_metal"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = 0.18 * min(m.sx, m.sy)
    m.lathe("dark_metal", [(0.45, 0.0), (0.3, 0.06 * H), (0.0, 0.07 * H)], scale=(m.sx, m.sy), fraction=0.6)
    m.post("metal", 0, 0.1 * D, 0.06 * H, H, r, fraction=0.6)
    m.box("dark_metal", (-0.3 * W, -0.45 * D, 0.6 * H), (0.3 * W, 0.4 * D, 0.78 * H))
    m.cylinder("dark_plastic", (0, -0.45 * D, 0.69 * H), (0, -0.6 * D, 0.69 * H), 0.6 * r, fraction=0.5)
    for s in (-1, 1):
        m.cylinder("dark_metal", (s * 0.3 * W, -0.1 * D, 0.66 * H), (s * 0.75 * W, -0.1 * D, 0.66 * H), 0.35 * r, fraction=0.4)
        m.cylinder("rubber", (s * 0.7 * W, -0.1 * D, 0.66 * H), (s * W, -0.1 * D, 0.66 * H), 0.45 * r, fraction=0.4)
    m.box("glass", (-0.5 * r, 0.1 * D - r * 1.05, 0.95 * H), (0.5 * r, 0.1 * D - r * 0.95, 0.99 * H), rounded=0.0)


def _claw_machine(m: Model) -> None:
    """A claw crane game: a cabinet with a control deck and prize chute, a glass case of
    prizes on top with the claw hanging from its gantry, a lit header."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    base, case = 0.4 * H, 0.88 * H
    m.box("paint", (-W, -D, 0), (W, D, base))
    m.box("dark_plastic", (-0.5 * W, -1.02 * D, 0.1 * H), (-0.1 * W, -D, 0.25 * H), rounded=0.0)
    m.box("dark_plastic", (-W, -1.2 * D, base - 0.06 * H), (W, -D, base), rounded=0.0)
    m.post("dark_metal", 0.4 * W, -1.1 * D, base, base + 0.08 * H, 0.03 * W, fraction=0.3)
    m.ball("accent", (0.4 * W, -1.1 * D, base + 0.09 * H), (0.06 * W,) * 3, fraction=0.4)
    for k, x in enumerate(np.linspace(-0.7 * W, 0.7 * W, 5)):
        for j, y in enumerate((-0.5 * D, 0.3 * D)):
            m.ball(("flower", "flower_alt", "leaf", "book_b")[(k + j) % 4], (x, y, base + 0.07 * H), (0.15 * W, 0.2 * D, 0.07 * H),
                   fraction=0.4)
    m.box("glass", (-0.97 * W, -0.97 * D, base), (0.97 * W, 0.97 * D, case), rounded=0.0)
    m.box("light", (-W, -D, case), (W, D, H))
    m.post("metal", 0.1 * W, 0, 0.62 * H, 0.99 * case, 0.01 * W + 0.003, fraction=0.3)
    for k in range(3):
        a = 2 * np.pi * k / 3
        m.beam("metal", (0.1 * W, 0, 0.62 * H), (0.1 * W + 0.12 * W * np.cos(a), 0.12 * D * np.sin(a), 0.55 * H), 0.02 * W)


def _sewing_machine(m: Model) -> None:
    """A sewing machine: a bed plate, a pillar and an arm reaching over to the needle head,
    a hand wheel at the back end."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("paint", (-W, -D, 0), (W, D, 0.2 * H))
    m.box("paint", (0.45 * W, -0.5 * D, 0.2 * H), (0.85 * W, 0.5 * D, 0.75 * H))
    m.box("paint", (-0.8 * W, -0.45 * D, 0.75 * H), (0.9 * W, 0.45 * D, H))
    m.box("paint", (-0.8 * W, -0.4 * D, 0.45 * H), (-0.55 * W, 0.4 * D, 0.75 * H))
    m.post("chrome", -0.68 * W, -0.2 * D, 0.22 * H, 0.45 * H, 0.015 * W + 0.002, fraction=0.3)
    m.box("chrome", (-0.5 * W, -0.6 * D, 0.2 * H), (0.1 * W, 0.2 * D, 0.21 * H), rounded=0.0)
    m.cylinder("dark_metal", (0.9 * W, 0, 0.75 * H), (W, 0, 0.75 * H), 0.2 * H, fraction=0.6)
    m.box("gold", (-0.3 * W, -0.46 * D, 0.82 * H), (0.4 * W, -0.45 * D, 0.92 * H), rounded=0.0)


def _ball_return(m: Model) -> None:
    """A bowling ball return: a rounded hood over the lift, a rail track of balls in front."""
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("dark_plastic", (-W, -D, 0), (W, D, 0.25 * H))
    m.ball("plastic", (0, 0.35 * D, 0.25 * H), (0.6 * W, 0.6 * D, 0.75 * H))
    m.box("accent", (-0.62 * W, 0.35 * D - 0.6 * D, 0.2 * H), (0.62 * W, 0.35 * D + 0.6 * D, 0.26 * H), rounded=0.0)
    r = min(0.18 * m.sx, 0.25 * H, 0.3 * D)
    for s in (-1, 1):
        m.beam("metal", (s * 0.95 * W, -D, 0.25 * H + 0.5 * r), (s * 0.95 * W, 0.0, 0.25 * H + 0.5 * r), 0.03 * m.sx)
    for k, x in enumerate(np.linspace(-0.7 * W, 0.7 * W, 4)):
        m.ball(("accent", "paint", "flower_alt", "book_b")[k % 4], (x, -0.6 * D, 0.25 * H + r), (r, r, r), fraction=0.6)


def machine(m: Model) -> None:
    """A boxy machine; its name picks the build: arcade cabinet, console or terminal,
    generator or engine, compressor, printer, washing machine, server rack, furnace,
    periscope, bowling ball return, claw crane game, sewing machine."""
    variants = (
        (("jukebox", "juke box"), _jukebox),
        (("arcade", "pinball", "slot machine", "game cabinet"), _arcade),
        (("console", "terminal", "control panel", "control desk", "dashboard", "workstation", "switchboard", "cockpit"),
         _console),
        (("compressor",), _compressor),
        (("generator", "engine", "motor", "pump", "turbine", "dynamo"), _engine),
        (("printer", "copier", "photocopier", "fax", "scanner"), _printer),
        (("hair dryer", "hood dryer", "salon dryer", "blow dryer"), _hood_dryer),
        (("washing machine", "washer", "dryer", "dishwasher", "laundry"), _washer),
        (("server", "mainframe", "rack", "supercomputer"), _server),
        (("furnace", "kiln", "forge", "smelter", "foundry"), _furnace),
        (("periscope",), _periscope),
        (("claw machine", "claw crane", "crane game", "prize machine"), _claw_machine),
        (("sewing machine",), _sewing_machine),
        (("ball return",), _ball_return),
        (("scales", "scale", "balance", "weighbridge", "weighing machine"), _scales),
    )
    for words, build in variants:
        if m.named(*words):
            build(m)
            return
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    feet = 0.05 * H
    for x in (-0.85 * W, 0.85 * W):
        for y in (-0.8 * D, 0.8 * D):
            m.box("rubber", (x - 0.08 * W, y - 0.1 * D, 0), (x + 0.08 * W, y + 0.1 * D, feet))
    m.box("paint", (-0.95 * W, -0.85 * D, feet), (0.95 * W, D, 0.9 * H))
    m.box("dark_metal", (-W, -0.9 * D, 0.9 * H), (W, D, H))
    m.box("dark_plastic", (-0.8 * W, -0.9 * D, 0.45 * H), (0.1 * W, -0.85 * D, 0.8 * H))
    m.box("screen", (-0.75 * W, -0.91 * D, 0.5 * H), (0.05 * W, -0.9 * D, 0.75 * H), rounded=0.0)
    _buttons(m, 0.25 * W, 0.85 * W, 0.7 * H, -0.85 * D, 3, 0.03 * min(H, m.sx))
    m.box("light", (0.3 * W, -0.87 * D, 0.55 * H), (0.8 * W, -0.85 * D, 0.6 * H), rounded=0.0)
    _vents(m, -0.8 * W, 0.8 * W, 0.12 * H, 0.38 * H, -0.85 * D, 6)
    for s in (-1, 1):
        m.cylinder("metal", (s * 0.95 * W, 0.3 * D, 0.3 * H), (s * W, 0.3 * D, 0.3 * H), 0.08 * min(H, m.sy), fraction=0.5)
    m.cylinder("metal", (0.95 * W, 0.3 * D, 0.3 * H), (0.95 * W, 0.3 * D, 0.95 * H), 0.05 * min(H, m.sy), fraction=0.5)


def _scales(m: Model) -> None:
    """Scales by the shape of their box: a tall one a beam balance (a pillar on a plinth, a
    beam across its top, a pan hung from each end); a low one a platform scale (a plate to
    stand things on, a dial on a column at the back)."""
    m.main = "brass"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    if H >= 0.8 * max(m.sx, m.sy):
        m.box("dark_wood", (-0.3 * W, -0.3 * D, 0), (0.3 * W, 0.3 * D, 0.06 * H))
        post = 0.04 * min(W, D) + 0.01
        m.post("brass", 0, 0, 0.06 * H, 0.95 * H, post, fraction=0.4)
        m.ball("brass", (0, 0, 0.95 * H), (1.6 * post,) * 3, fraction=0.4)
        m.cylinder("brass", (-0.8 * W, 0, 0.9 * H), (0.8 * W, 0, 0.9 * H), 0.6 * post, fraction=0.4)
        for s in (-1, 1):
            x = s * 0.75 * W
            for a in range(3):  # three cords from the beam's end to the pan's rim
                ang = 2 * np.pi * a / 3
                m.beam("dark_metal", (x, 0, 0.9 * H), (x + 0.2 * W * np.cos(ang), 0.2 * D * np.sin(ang), 0.42 * H), 0.004 + 0.001 * a)
            m.lathe("brass", [(0.0, 0.38 * H), (0.2 * W, 0.39 * H), (0.25 * W, 0.43 * H)], centre=(x, 0, 0), scale=(1.0, D / W))
        return
    m.box("dark_metal", (-W, -D, 0), (W, 0.6 * D, 0.35 * H))
    m.box("metal", (-0.9 * W, -0.9 * D, 0.33 * H), (0.9 * W, 0.5 * D, 0.42 * H))  # set into the base
    m.box("dark_metal", (-0.12 * W, 0.65 * D, 0), (0.12 * W, 0.85 * D, 0.7 * H))
    m.cylinder("brass", (0, 0.7 * D, 0.8 * H), (0, D, 0.8 * H), 0.2 * min(H, m.sx), fraction=0.6)
    m.cylinder("canvas_alt", (0, 0.68 * D, 0.8 * H), (0, 0.705 * D, 0.8 * H), 0.16 * min(H, m.sx), fraction=0.6)


def _horizontal_tank(m: Model) -> None:
    """A fuel or gas tank lying on saddles, with a manway, a ladder and a warning band."""
    m.main = "paint"
    along_x = m.sx >= m.sy
    L, R = (m.sx / 2, m.sy / 2) if along_x else (m.sy / 2, m.sx / 2)
    r = min(R, 0.42 * m.sz)
    cz = m.sz - 0.08 * m.sz - r
    axis = np.array([1.0, 0, 0]) if along_x else np.array([0, 1.0, 0])
    across = np.array([0, 1.0, 0]) if along_x else np.array([1.0, 0, 0])
    centre = np.array([0, 0, cz])
    m.cylinder("paint", centre - 0.85 * L * axis, centre + 0.85 * L * axis, r, fraction=1)
    for s in (-1, 1):
        radii = np.where(axis > 0, 0.15 * L, r)
        radii[2] = r
        m.ball("paint", centre + s * 0.85 * L * axis, radii, fraction=0.8)
        foot = centre + s * 0.55 * L * axis
        lo = foot - 0.06 * L * axis - 0.9 * r * across
        hi = foot + 0.06 * L * axis + 0.9 * r * across
        inset = 0.05 * (hi - lo)  # the saddle overhangs its plinth (flush sides would coincide)
        m.box("concrete", (lo[0] + inset[0], lo[1] + inset[1], 0), (hi[0] - inset[0], hi[1] - inset[1], cz - 0.6 * r))
        m.box("dark_metal", (lo[0], lo[1], cz - 0.62 * r), (hi[0], hi[1], cz - 0.4 * r))
    for t in (-0.3, 0.3):
        m.torus("accent", centre + t * L * axis, 1.01 * r, 0.03 * r, axis="x" if along_x else "y", fraction=0.6)
    m.cylinder("dark_metal", centre + (0, 0, 0.9 * r), centre + (0, 0, r + 0.08 * m.sz), 0.2 * r, fraction=0.5)
    m.cylinder("metal", centre + (0, 0, r + 0.07 * m.sz), centre + (0, 0, r + 0.09 * m.sz), 0.25 * r, fraction=0.5)
    ladder = centre - 0.3 * L * axis - 1.02 * r * across
    for k in range(2):
        off = (k - 0.5) * 0.1 * L * axis
        m.beam("metal", (ladder + off)[:2].tolist() + [0.0], (ladder + off)[:2].tolist() + [cz], 0.02 * r + 0.005)
    for k in range(1, 6):
        z = cz * k / 6
        a, b = ladder - 0.05 * L * axis, ladder + 0.05 * L * axis
        m.beam("metal", (a[0], a[1], z), (b[0], b[1], z), 0.015 * r + 0.004)


def _silo(m: Model) -> None:
    m.main = "metal"
    r = 0.45
    body = 0.8 * m.sz
    m.lathe("concrete", [(r * 1.1, 0), (r * 1.1, 0.02 * m.sz)], scale=(m.sx, m.sy), fraction=0.7)
    m.lathe("metal", [(r, 0), (r, body)], scale=(m.sx, m.sy))
    m.lathe("metal", [(r * 1.02, body), (r * 0.2, 0.97 * m.sz), (0.0, m.sz)], scale=(m.sx, m.sy))
    for k in range(1, 6):
        m.lathe("dark_metal", [(r * 1.01, body * k / 6 - 0.005 * m.sz), (r * 1.01, body * k / 6 + 0.005 * m.sz)], scale=(m.sx, m.sy),
                fraction=0.7)
    y = -0.5 * m.sy
    for x in (-0.05 * m.sx, 0.05 * m.sx):
        m.beam("dark_metal", (x, y, 0), (x, y, body), 0.01 * m.sx + 0.01)
    for k in range(1, 12):
        m.beam("dark_metal", (-0.05 * m.sx, y, body * k / 12), (0.05 * m.sx, y, body * k / 12), 0.008 * m.sx + 0.005)


def _water_tower(m: Model) -> None:
    m.main = "wood"
    r = 0.45
    legs_top = 0.55 * m.sz
    for x in (-0.4 * m.sx, 0.4 * m.sx):
        for y in (-0.4 * m.sy, 0.4 * m.sy):
            m.beam("dark_metal", (x, y, 0), (0.8 * x, 0.8 * y, legs_top), 0.02 * min(m.sx, m.sy) + 0.02)
    for z in (0.2 * legs_top, 0.6 * legs_top):
        k = 0.4 - 0.08 * z / legs_top
        corners = [(-k, -k), (k, -k), (k, k), (-k, k)]
        ring(m, "dark_metal", [(x * m.sx, y * m.sy, z) for x, y in corners], 0.015 * min(m.sx, m.sy) + 0.01)
    m.lathe("wood", [(r, legs_top), (r, 0.85 * m.sz)], scale=(m.sx, m.sy))
    for z in (0.62, 0.72, 0.82):
        m.lathe("dark_metal", [(r * 1.01, z * m.sz), (r * 1.01, z * m.sz + 0.01 * m.sz)], scale=(m.sx, m.sy), fraction=0.7)
    m.lathe("roof", [(r * 1.08, 0.85 * m.sz), (0.0, m.sz)], scale=(m.sx, m.sy))


def _boiler(m: Model) -> None:
    m.main = "metal"
    r = 0.4
    m.lathe("metal", [(r, 0), (r, 0.85 * m.sz), (0.6 * r, 0.95 * m.sz), (0.0, 0.97 * m.sz)], scale=(m.sx, m.sy))
    m.lathe("dark_metal", [(r * 1.02, 0), (r * 1.02, 0.06 * m.sz)], scale=(m.sx, m.sy))
    for s in (-1, 1):
        m.cylinder("copper", (s * 0.35 * m.sx, 0, 0.7 * m.sz), (s * 0.5 * m.sx, 0, 0.7 * m.sz), 0.04 * min(m.sx, m.sz), fraction=0.4)
        m.cylinder("copper", (s * 0.5 * m.sx, 0, 0.7 * m.sz), (s * 0.5 * m.sx, 0, 0.1 * m.sz), 0.036 * min(m.sx, m.sz), fraction=0.4)
    m.cylinder("copper", (0, 0, 0.95 * m.sz), (0, 0, m.sz), 0.06 * min(m.sx, m.sy), fraction=0.4)
    m.cylinder("ceramic", (0, -0.4 * m.sy, 0.55 * m.sz), (0, -0.5 * m.sy, 0.55 * m.sz), 0.1 * m.sx, fraction=0.5)
    m.box("flame", (-0.12 * m.sx, -0.42 * m.sy, 0.1 * m.sz), (0.12 * m.sx, -0.38 * m.sy, 0.2 * m.sz), rounded=0.0)


def _cauldron(m: Model) -> None:
    m.main = "dark_metal"
    rim = 0.85 * m.sz
    scale = (m.sx * 0.95, m.sy * 0.95)
    m.lathe("dark_metal", [(0.0, 0.12 * m.sz), (0.3, 0.12 * m.sz), (0.48, 0.3 * m.sz), (0.5, 0.55 * m.sz), (0.42, rim),
                           (0.46, rim + 0.03 * m.sz)], scale=scale)
    brew = "crystal" if m.has("potion", "magic", "witch", "bubbling", "glowing") else "water"
    m.lathe(brew, [(0.41, rim - 0.04 * m.sz), (0.41, rim - 0.02 * m.sz)], scale=scale)
    for k in range(3):
        a = 2 * np.pi * k / 3 + np.pi / 2
        m.cylinder("dark_metal", (np.cos(a) * 0.3 * m.sx, np.sin(a) * 0.3 * m.sy, 0.25 * m.sz),
                   (np.cos(a) * 0.4 * m.sx, np.sin(a) * 0.4 * m.sy, 0.0), 0.04 * min(m.sx, m.sy), fraction=0.4)
    m.torus("dark_metal", (0, 0, rim + 0.02 * m.sz), 0.44 * m.sx, 0.015 * min(m.sx, m.sz), axis="x", arc=np.pi, fraction=0.5)
    for k in range(3):
        a = np.pi * k / 3
        d = np.array([np.cos(a), np.sin(a)]) * 0.3 * min(m.sx, m.sy)
        m.cylinder("bark", (d[0], d[1], 0.04 * m.sz), (-d[0], -d[1], 0.04 * m.sz), 0.04 * min(m.sx, m.sy, m.sz), fraction=0.4)
    for k in range(3):
        a = 2 * np.pi * k / 3
        m.ball(brew, (np.cos(a) * 0.15 * m.sx, np.sin(a) * 0.15 * m.sy, rim - 0.02 * m.sz), (0.05 * m.sx,) * 2 + (0.04 * m.sz,),
               fraction=0.3)


def _aquarium(m: Model) -> None:
    m.main = "glass"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("dark_metal", (-W, -D, 0), (W, D, 0.05 * H), rounded=0.0)
    # Gravel sunk a little into the base, water on the gravel: three bottoms in the glass's
    # plane would fight.
    m.box("water", (-0.97 * W, -0.95 * D, 0.12 * H), (0.97 * W, 0.95 * D, 0.88 * H), rounded=0.0)
    m.box("stone", (-0.96 * W, -0.94 * D, 0.045 * H), (0.96 * W, 0.94 * D, 0.12 * H), rounded=0.0)
    m.box("glass", (-W, -D, 0.05 * H), (W, D, 0.95 * H), rounded=0.0)
    m.box("dark_metal", (-W, -D, 0.95 * H), (W, D, H), rounded=0.0)
    for k in range(3):
        x = -0.6 * W + 0.5 * W * k
        m.leaf("leaf", (x, 0.5 * D, 0.1 * H), (x + 0.05 * W, 0.4 * D, 0.7 * H), 0.06 * W, 0.02 * D)
        m.ball("flower_alt", (x + 0.2 * W, -0.2 * D, 0.45 * H + 0.1 * k * H), (0.08 * W, 0.04 * D, 0.05 * H), fraction=0.4)


def tank(m: Model) -> None:
    """A vessel; its name picks the build: a fuel or gas tank on saddles, a silo, a water
    tower on legs, a boiler, a cauldron, an aquarium (and an army tank is the vehicle);
    else standing or lying by its box."""
    variants = (
        (("army tank", "battle tank", "military tank", "panzer", "armored tank", "armoured tank"), _battle_tank),
        (("fish tank", "aquarium", "terrarium", "vivarium"), _aquarium),
        (("cauldron", "pot", "kettle"), _cauldron),
        (("silo", "grain silo", "grain bin"), _silo),
        (("water tower",), _water_tower),  # (a water tank is a standing tank: indoors it has no legs and roof)
        (("furnace", "kiln", "smelter"), _furnace),
        (("boiler", "water heater", "still", "reactor"), _boiler),
        (("fuel tank", "oil tank", "gas tank", "propane", "tanker", "cistern", "gas cylinder", "pressure vessel"),
         _horizontal_tank),
    )
    for words, build in variants:
        if m.named(*words):
            build(m)
            return
    if m.sz > 1.2 * max(m.sx, m.sy):
        _silo(m)
    else:
        _horizontal_tank(m)


def _last(m: Model) -> None:
    """A shoemaker's last: a wooden foot, sole down, toe to the front, the instep rising to a
    flat-topped ankle at the heel."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.ball("wood", (0, -0.15 * D, 0.3 * H), (0.9 * W, 0.85 * D, 0.3 * H), fraction=0.8)  # the sole's bulk
    m.ball("wood", (0, 0.45 * D, 0.45 * H), (0.8 * W, 0.5 * D, 0.45 * H), fraction=0.8)  # the heel and instep
    m.cylinder("dark_wood", (0, 0.5 * D, 0.6 * H), (0, 0.5 * D, H), 0.55 * W, 0.5 * W, fraction=0.6)  # the ankle


def _potters_wheel(m: Model) -> None:
    """A potter's wheel: a low cabinet, a splash pan round a turning disc on its shaft."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = 0.8 * min(W, D)
    m.box("wood", (-W, -D, 0), (W, D, 0.7 * H))
    m.cylinder("dark_metal", (0, 0, 0.7 * H), (0, 0, 0.9 * H), 0.08 * r, fraction=0.4)
    m.torus("plastic", (0, 0, 0.82 * H), 0.95 * r, 0.06 * r, fraction=0.8)
    m.cylinder("metal", (0, 0, 0.9 * H), (0, 0, H), 0.7 * r, fraction=1.0)


def _grindstone(m: Model) -> None:
    """A grindstone: a stone wheel on an axle between the sides of a wooden frame on four
    legs, a crank at one end and a trough under the wheel."""
    m.main = "stone"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    leg = m.thick(0.04, 0.12 * min(m.sx, m.sy))
    frame = 0.45 * H
    m.legs("wood", 0.02, 0, frame, leg, square=True)
    for x in (-W + 0.02, W - 0.02 - 2 * leg):
        m.box("wood", (x, -D + 0.02, frame), (x + 2 * leg, D - 0.02, frame + 2 * leg))
    radius = min(0.48 * (H - frame), 0.9 * D)
    axle = H - radius
    width = min(0.35 * m.sx, 0.18)
    m.cylinder("stone", (-width / 2, 0, axle), (width / 2, 0, axle), radius, fraction=1.0)
    m.cylinder("dark_metal", (-W + 0.02, 0, axle), (W + 0.02, 0, axle), 0.15 * radius, fraction=0.4)
    for x in (-W + 0.02 + leg, W - 0.02 - leg):
        m.box("wood", (x - leg, -leg, frame + 2 * leg), (x + leg, leg, axle - 0.15 * radius))
    m.beam("dark_metal", (W + 0.02, 0, axle), (W + 0.02, 0, axle - 0.5 * radius), 0.1 * radius)
    m.cylinder("wood", (W + 0.02, 0, axle - 0.5 * radius), (W + 0.02, -0.5 * D, axle - 0.5 * radius), 0.08 * radius, fraction=0.3)
    m.box("dark_wood", (-0.8 * width, -0.6 * radius, frame + 2 * leg), (0.8 * width, 0.6 * radius, frame + 2 * leg + 0.12 * radius))


def _anvil(m: Model) -> None:
    m.main = "dark_metal"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.lathe("bark", [(0.6 * min(W, D) * 1.6, 0), (0.55 * min(W, D) * 1.6, 0.4 * H)], scale=(1, min(1.0, D / (0.96 * min(W, D)))))
    m.box("dark_metal", (-0.45 * W, -0.6 * D, 0.4 * H), (0.45 * W, 0.6 * D, 0.5 * H))
    m.box("dark_metal", (-0.25 * W, -0.4 * D, 0.5 * H), (0.25 * W, 0.4 * D, 0.75 * H))
    m.box("dark_metal", (-0.6 * W, -0.55 * D, 0.75 * H), (0.6 * W, 0.55 * D, H))
    m.cylinder("dark_metal", (0.55 * W, 0, 0.9 * H), (W, 0, 0.97 * H), min(0.12 * H, 0.5 * D), 0.0, fraction=0.6)
    m.box("dark_metal", (-W, -0.3 * D, 0.85 * H), (-0.6 * W, 0.3 * D, H))
    m.box("metal", (-0.58 * W, -0.53 * D, H), (0.58 * W, 0.53 * D, 1.003 * H), rounded=0.0)  # the steel face on top


class _Along:
    """Coordinates along a hand tool's longest side, so a hammer filed as 0.1 × 0.35 m is
    drawn along its 0.35 m: ``t`` runs from the head end (the bottom of a standing tool) to
    the grip, ``a`` across its broad side, ``b`` through its thickness; boxes stay
    axis-aligned (the axes are a permutation of the scene's)."""

    def __init__(self, m: Model):
        self.m = m
        long = int(np.argmax((m.sx, m.sy, m.sz)))
        if long == 2:  # standing
            self.u, self.v, self.w, self.o = np.eye(3)[2], np.eye(3)[0], np.eye(3)[1], np.zeros(3)
            self.L, self.A, self.B, self.ring = m.sz, m.sx / 2, m.sy / 2, "y"
        elif long == 1:  # lying along y, head to the front
            self.u, self.v, self.w, self.o = np.eye(3)[1], np.eye(3)[0], np.eye(3)[2], np.array([0, -m.sy / 2, m.sz / 2])
            self.L, self.A, self.B, self.ring = m.sy, m.sx / 2, m.sz / 2, "z"
        else:  # lying along x
            self.u, self.v, self.w, self.o = np.eye(3)[0], np.eye(3)[1], np.eye(3)[2], np.array([-m.sx / 2, 0, m.sz / 2])
            self.L, self.A, self.B, self.ring = m.sx, m.sy / 2, m.sz / 2, "z"

    def p(self, t: float, a: float = 0.0, b: float = 0.0) -> np.ndarray:
        return self.o + t * self.u + a * self.v + b * self.w

    def box(self, role: str, lo, hi, rounded: float | None = None) -> None:
        c0, c1 = self.p(*lo), self.p(*hi)
        self.m.box(role, np.minimum(c0, c1), np.maximum(c0, c1), rounded)

    def rod(self, role: str, t0: float, t1: float, r0: float, r1: float | None = None, a: float = 0.0, b: float = 0.0,
            fraction: float = 0.5) -> None:
        self.m.cylinder(role, self.p(t0, a, b), self.p(t1, a, b), r0, r1, fraction=fraction)


def _hammer(m: Model) -> None:
    """A hammer, axe, pickaxe or mallet: a handle with a grip, the head across its end."""
    m.main = "wood"
    f = _Along(m)
    L, A, B = f.L, f.A, f.B
    r = 0.3 * min(A, B)
    f.rod("wood", 0.06 * L, 0.8 * L, 0.9 * r, 0.8 * r)  # its end inside the grip
    f.rod("rubber", 0.78 * L, L, r)
    if m.named("pickaxe", "pick", "mattock"):
        n = 6  # the head bows, its two points curving toward the grip
        pts = [f.p(0.03 * L + 0.14 * L * (k / n * 2 - 1) ** 2, A * (k / n * 2 - 1), 0) for k in range(n + 1)]
        for k in range(n):
            taper = 1 - abs(k + 0.5 - n / 2) / (n / 2)
            m.cylinder("metal", pts[k], pts[k + 1], 0.5 * B * max(taper, 0.2), 0.5 * B * max(taper, 0.2), fraction=0.5)
    elif m.named("axe", "hatchet"):
        f.box("metal", (0.0, -0.3 * A, -0.25 * B), (0.12 * L, A, 0.25 * B))
    elif m.named("mallet", "gavel"):
        m.cylinder("wood", f.p(0.06 * L, -A, 0), f.p(0.06 * L, A, 0), 0.06 * L, fraction=0.6)
    else:
        f.box("metal", (0.0, -A, -0.8 * B), (0.12 * L, A, 0.8 * B))


def _wrench(m: Model) -> None:
    m.main = "chrome"
    f = _Along(m)
    L, A, B = f.L, f.A, f.B
    f.box("chrome", (0.15 * L, -0.25 * A, -0.3 * B), (0.85 * L, 0.25 * A, 0.3 * B))
    for t in (0.12 * L, 0.88 * L):
        m.torus("chrome", f.p(t), 0.7 * A, 0.25 * A, axis=f.ring, fraction=0.6)


def _long_tool(m: Model) -> None:
    """A long-handled tool, its head at the bottom when it stands: a shovel or spade, a garden
    fork, a rake, a broom, a golf club or putter, a hockey stick, an oar."""
    m.main = "wood"
    f = _Along(m)
    L, A, B = f.L, f.A, f.B
    club = m.named("putter", "golf club", "club", "hockey stick")
    r = (0.15 if club else 0.3) * min(A, B)
    f.rod("metal" if club else "wood", 0.05 * L, 0.85 * L, r)
    f.rod("rubber" if club else "dark_wood", 0.83 * L, L, 1.3 * r)
    if club:
        f.box("chrome", (0.0, -0.2 * A, -0.6 * B), (0.06 * L, A, 0.6 * B))
    elif m.named("fork", "pitchfork"):
        f.box("metal", (0.26 * L, -0.8 * A, -1.2 * r), (0.3 * L, 0.8 * A, 1.2 * r))
        for a in np.linspace(-0.7 * A, 0.7 * A, 4):
            f.rod("metal", 0.0, 0.27 * L, 0.6 * r, 0.9 * r, a=a, fraction=0.3)
    elif m.named("rake"):
        f.box("metal", (0.04 * L, -A, -r), (0.08 * L, A, r))
        for a in np.linspace(-0.9 * A, 0.9 * A, 9):
            m.cylinder("metal", f.p(0.06 * L, a, -0.9 * r), f.p(0.0, a, -B), 0.4 * r, fraction=0.3)
    elif m.named("broom", "brush", "mop"):
        f.box("dark_wood", (0.2 * L, -0.8 * A, -0.5 * B), (0.25 * L, 0.8 * A, 0.5 * B))
        f.box("straw", (0.0, -A, -0.6 * B), (0.2 * L, A, 0.6 * B))
    else:  # a shovel, spade, oar or paddle: a flat blade
        f.rod("metal", 0.25 * L, 0.3 * L, 1.4 * r, 1.1 * r)
        f.box("metal", (0.0, -A, -0.15 * B), (0.27 * L, A, 0.15 * B), rounded=0.2 * A)


def _blade(m: Model) -> None:
    """A sword, cutlass or dagger lying flat: a blade, a cross guard, a grip and a pommel."""
    m.main = "chrome"
    f = _Along(m)
    L, A, B = f.L, f.A, f.B
    f.box("chrome", (0.0, -0.35 * A, -0.12 * B), (0.72 * L, 0.35 * A, 0.12 * B), rounded=0.1 * A)
    f.box("brass", (0.72 * L, -A, -0.5 * B), (0.76 * L, A, 0.5 * B))
    f.rod("leather", 0.755 * L, 0.95 * L, 0.4 * min(A, B))
    m.ball("brass", f.p(0.965 * L), (0.5 * min(A, B),) * 3, fraction=0.4)


def _lens(m: Model) -> None:
    """A magnifying glass (a lens in a rim on a handle) or a jeweller's loupe (a short
    black eyepiece with a lens at each end)."""
    m.main = "dark_plastic"
    if m.named("loupe", "eyepiece", "eyeglass"):
        r = 0.5 * min(m.sx, m.sy)
        m.lathe("dark_plastic", [(0.7 * r, 0.0), (r, 0.7 * m.sz), (0.95 * r, m.sz), (0.6 * r, m.sz), (0.6 * r, 0.05 * m.sz), (0.0, 0.05 * m.sz)])
        m.lathe("glass", [(0.58 * r, 0.02 * m.sz), (0.58 * r, 0.08 * m.sz), (0.0, 0.08 * m.sz)])
        m.lathe("chrome", [(1.01 * r, 0.55 * m.sz), (1.01 * r, 0.65 * m.sz)], fraction=0.7)
        return
    f = _Along(m)
    L, A, B = f.L, f.A, f.B
    rim = min(A, 0.3 * L)
    centre = f.p(rim)
    m.torus("dark_plastic", centre, 0.9 * rim, 0.1 * rim, axis=f.ring, fraction=0.7)
    m.cylinder("glass", centre - 0.3 * B * f.w, centre + 0.3 * B * f.w, 0.88 * rim)
    f.rod("dark_plastic", 1.95 * rim, L, 0.15 * rim, 0.2 * rim)
    f.rod("chrome", 1.88 * rim, 2.1 * rim, 0.22 * rim)


def _papers(m: Model) -> None:
    """A script, letter or document: a stack of sheets, a little askew, typed lines on top,
    held by a clip."""
    m.main = "paper"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    sheets = 4
    for k in range(sheets):
        dx, dy = (0.03 * (k % 2) - 0.015) * W, (0.02 * k - 0.03) * D
        m.box("paper", (-0.95 * W + dx, -0.95 * D + dy, H * k / sheets), (0.95 * W + dx, 0.95 * D + dy, H * (k + 1) / sheets), rounded=0.0)
    for k in range(6):
        y = 0.6 * D - k * 0.22 * D
        m.box("dark_plastic", (-0.7 * W, y, H), (0.7 * W - 0.15 * W * (k % 3), y + 0.06 * D, 1.04 * H), rounded=0.0)
    m.box("metal", (-0.2 * W, 0.84 * D, -0.1 * H), (0.2 * W, 0.995 * D, 1.1 * H), rounded=0.0)


def _scroll(m: Model) -> None:
    """A scroll: rolled parchment on two wooden rods, part unrolled between them."""
    m.main = "paper"
    f = _Along(m)
    L, A, B = f.L, f.A, f.B
    r = 0.9 * min(A, B)
    for a in (-0.6 * A, 0.6 * A):
        m.cylinder("paper", f.p(0.08 * L, a), f.p(0.92 * L, a), 0.4 * r, fraction=0.6)
    f.box("paper", (0.1 * L, -0.6 * A, -0.05 * B), (0.9 * L, 0.6 * A, 0.02 * B), rounded=0.0)
    for a in (-0.6 * A, 0.6 * A):
        f.rod("dark_wood", 0.0, L, 0.12 * r, a=a, fraction=0.3)
    f.box("accent", (0.45 * L, -0.62 * A, -0.42 * r), (0.55 * L, -0.58 * A, 0.42 * r), rounded=0.0)


def _helmet(m: Model) -> None:
    """A helmet: a rounded shell, a rim round its edge and a dark visor across the front."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    shell = [(1.0, 0.0), (0.99, 0.25 * H), (0.9, 0.55 * H), (0.65, 0.82 * H), (0.3, 0.97 * H), (0.02, H)]
    m.lathe("paint", shell, scale=(W, D))
    m.lathe("dark_plastic", [(1.02, 0.0), (1.02, 0.08 * H)], scale=(W, D), fraction=0.7)
    m.box("dark_plastic", (-0.6 * W, -D * 1.0, 0.2 * H), (0.6 * W, -0.55 * D, 0.55 * H), rounded=0.1 * W)


def _toolbox(m: Model) -> None:
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("paint", (-W, -D, 0), (W, D, 0.75 * H))
    m.box("paint", (-W, -D, 0.77 * H), (W, D, 0.85 * H))
    m.box("dark_metal", (-1.005 * W, -1.01 * D, 0.74 * H), (1.005 * W, 1.01 * D, 0.78 * H), rounded=0.0)
    for s in (-1, 1):
        m.box("metal", (s * 0.2 * W - 0.08 * W, -1.03 * D, 0.6 * H), (s * 0.2 * W + 0.08 * W, -D, 0.8 * H), rounded=0.0)
        m.post("dark_metal", s * 0.45 * W, 0, 0.85 * H, H, 0.04 * min(W, D) + 0.004, fraction=0.3)
    m.cylinder("dark_plastic", (-0.5 * W, 0, H - 0.04 * H), (0.5 * W, 0, H - 0.04 * H), 0.05 * H, fraction=0.4)


def _gadget(m: Model) -> None:
    m.main = "dark_plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    top = 0.75 * H
    m.box("dark_plastic", (-W, -D, 0), (W, D, top))
    m.box("screen", (-0.8 * W, -1.01 * D, 0.45 * top), (0.8 * W, -D, 0.9 * top), rounded=0.0)
    _buttons(m, -0.7 * W, 0.7 * W, 0.2 * top, -D, 4, 0.08 * min(top, m.sx))
    m.post("metal", 0.7 * W, 0.5 * D, top, H, 0.04 * min(W, D) + 0.002, fraction=0.3)
    m.ball("light", (0.7 * W, 0.5 * D, H - 0.02 * H), (0.06 * min(W, D) + 0.002,) * 3, fraction=0.3)


def _telescope(m: Model) -> None:
    """A telescope: a tube tilted up on a tripod when it stands, a brass spyglass when it lies."""
    m.main = "brass"
    if m.sz < max(m.sx, m.sy):
        f = _Along(m)
        L, A, B = f.L, f.A, f.B
        r = 0.9 * min(A, B)
        for k, (t0, t1) in enumerate(((0.0, 0.45 * L), (0.43 * L, 0.75 * L), (0.73 * L, L))):
            f.rod("brass" if k % 2 == 0 else "dark_metal", t0, t1, r * (1 - 0.15 * k), fraction=0.6)
        f.rod("glass", -0.002 * L, 0.0, 0.9 * r)
        return
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    head = np.array([0.0, 0.0, 0.7 * H])
    for k in range(3):
        a = 2 * np.pi * k / 3 + np.pi / 2
        m.beam("dark_wood", (0.9 * W * np.cos(a), 0.9 * D * np.sin(a), 0), head, 0.03 * min(m.sx, m.sy) + 0.01)
    m.box("dark_metal", head - (0.05 * W, 0.05 * D, 0.0), head + (0.05 * W, 0.05 * D, 0.06 * H))
    front, back = np.array([0.0, -0.9 * D, H - 0.1 * min(m.sx, m.sy)]), np.array([0.0, 0.7 * D, 0.62 * H])
    r = 0.1 * min(m.sx, m.sy) + 0.01
    m.cylinder("brass", back, front, 0.7 * r, r, fraction=0.6)
    m.cylinder("glass", front, front + 0.01 * (front - back), 0.9 * r, fraction=0.6)
    m.cylinder("dark_metal", back, back + 0.12 * (back - front), 0.4 * r, fraction=0.4)


def _pencil(m: Model) -> None:
    """A pencil, a crayon or a pen lying along its longest side: a painted shaft and a sharpened tip."""
    m.main = "accent"
    along = "y" if m.sy >= m.sx else "x"
    half = (m.sy if along == "y" else m.sx) / 2
    r = min(m.sx if along == "y" else m.sy, m.sz) / 2
    tip = 0.8 * half

    def at(t: float) -> tuple[float, float, float]:
        return (0.0, t, r) if along == "y" else (t, 0.0, r)

    m.cylinder("accent", at(-half), at(tip - half * 0.1), r, r, fraction=0.4)
    m.cylinder("wood", at(tip - half * 0.1), at(half), r, 0.15 * r, fraction=0.4)


def _cone(m: Model) -> None:
    """A traffic cone: an orange cone with white bands on a square rubber base."""
    m.main = "accent"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    base = 0.06 * H
    m.box("rubber", (-W, -D, 0), (W, D, base), rounded=0.0)
    m.lathe("accent", [(0.42, base), (0.08, 0.98 * H), (0.0, H)], scale=(m.sx, m.sy))
    for z0, z1 in ((0.45, 0.55), (0.7, 0.78)):
        r0, r1 = (0.42 - 0.34 * (z - 0.06) / 0.92 for z in (z0, z1))
        m.lathe("paint", [(1.02 * r0, z0 * H), (1.02 * r1, z1 * H)], scale=(m.sx, m.sy), fraction=0.7)


def _trophy(m: Model) -> None:
    """A trophy: a gold cup with two handles on a stem, standing on a dark plinth."""
    m.main = "gold"
    r = 0.5
    m.lathe("dark_wood", [(0.45, 0.0), (0.45, 0.2 * m.sz)], scale=(m.sx * 0.9, m.sy * 0.9), fraction=0.5)
    m.lathe("gold", [(0.2, 0.2 * m.sz), (0.06, 0.25 * m.sz), (0.05, 0.45 * m.sz), (0.12, 0.5 * m.sz), (0.3, 0.75 * m.sz),
                     (r * 0.8, m.sz), (0.33, m.sz), (0.1, 0.55 * m.sz), (0.0, 0.55 * m.sz)], scale=(0.9 * m.sx, 0.9 * m.sy))
    for s in (-1, 1):
        m.torus("gold", (s * 0.36 * m.sx, 0, 0.78 * m.sz), 0.12 * m.sz, 0.015 * m.sz, axis="y", fraction=0.4)
    m.box("brass", (-0.15 * m.sx, -0.41 * m.sy, 0.05 * m.sz), (0.15 * m.sx, -0.4 * m.sy, 0.15 * m.sz), rounded=0.0)


def _radio(m: Model) -> None:
    """A radio: a cabinet with a round speaker grille, a tuning dial and window, a carry
    handle and an aerial."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    top = 0.8 * H
    m.box("wood", (-W, -D, 0), (W, D, top))
    r = min(0.3 * m.sx, 0.35 * top)
    m.cylinder("fabric", (-0.4 * W, -D, 0.5 * top), (-0.4 * W, -1.02 * D, 0.5 * top), r, fraction=0.7)
    m.box("light", (0.2 * W, -1.01 * D, 0.6 * top), (0.85 * W, -D, 0.78 * top), rounded=0.0)
    m.cylinder("dark_plastic", (0.5 * W, -D, 0.3 * top), (0.5 * W, -1.08 * D, 0.3 * top), 0.12 * top, fraction=0.4)
    m.torus("dark_plastic", (0, 0, top), 0.5 * W, 0.03 * H + 0.003, axis="y", arc=np.pi, fraction=0.4)
    m.cylinder("chrome", (0.8 * W, 0.6 * D, top), (0.3 * W, 0.6 * D, H + 0.6 * H), 0.01 * H + 0.002, fraction=0.3)


def _weathervane(m: Model) -> None:
    """A weathervane: a mast with the four compass arms and an arrow turning on top."""
    m.main = "dark_metal"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    rod = 0.015 * max(m.sx, m.sz) + 0.004
    m.lathe("dark_metal", [(0.15, 0.0), (0.12, 0.05 * H), (0.0, 0.06 * H)], scale=(m.sx, m.sy), fraction=0.5)
    m.post("dark_metal", 0, 0, 0.05 * H, 0.95 * H, rod, fraction=0.3)
    arms = 0.55 * H
    m.beam("dark_metal", (-0.6 * W, 0, arms), (0.6 * W, 0, arms), 1.2 * rod)
    m.beam("dark_metal", (0, -0.6 * D, arms + 1.3 * rod), (0, 0.6 * D, arms + 1.3 * rod), 1.2 * rod)
    for x, y in ((0.6 * W, 0), (-0.6 * W, 0), (0, 0.6 * D), (0, -0.6 * D)):
        m.ball("brass", (x, y, arms + 0.6 * rod), (2 * rod,) * 3, fraction=0.3)
    vane = 0.85 * H
    m.beam("dark_metal", (-0.9 * W, 0, vane), (0.6 * W, 0, vane), 1.5 * rod)
    tip = [(0.55 * W, vane - 0.1 * H), (W, vane), (0.55 * W, vane + 0.1 * H)]
    m.extrude("gold", tip, "y", -0.6 * rod, 0.6 * rod)
    m.extrude("dark_metal", [(-W, vane - 0.12 * H), (-0.7 * W, vane - 0.05 * H), (-0.7 * W, vane + 0.05 * H), (-W, vane + 0.15 * H)],
              "y", -0.5 * rod, 0.5 * rod)
    m.ball("brass", (0, 0, vane), (2.2 * rod,) * 3, fraction=0.3)


def _skateboard(m: Model) -> None:
    """A skateboard: a deck with kicked-up ends on two trucks of two wheels."""
    m.main = "paint"
    W, L, H = (m.sx / 2, m.sy / 2, m.sz) if m.sy >= m.sx else (m.sy / 2, m.sx / 2, m.sz)
    along = np.array([0, 1.0, 0]) if m.sy >= m.sx else np.array([1.0, 0, 0])
    across = np.array([1.0, 0, 0]) if m.sy >= m.sx else np.array([0, 1.0, 0])
    wr = 0.22 * H
    deck = 0.7 * H
    lo, hi = -0.8 * L * along - W * across + np.array([0, 0, deck]), 0.8 * L * along + W * across + np.array([0, 0, deck + 0.12 * H])
    m.box("paint", np.minimum(lo, hi), np.maximum(lo, hi), rounded=0.5 * min(W, 0.06 * H))
    for s in (-1, 1):
        m.beam("paint", s * 0.79 * L * along + (0, 0, deck + 0.06 * H), s * L * along + (0, 0, H - 0.06 * H), 1.9 * W, 0.12 * H)
        c = s * 0.55 * L * along
        m.box("metal", c - 0.5 * W * across - 0.05 * L * along + (0, 0, wr), c + 0.5 * W * across + 0.05 * L * along + (0, 0, deck))
        for t in (-1, 1):
            p = c + t * 0.7 * W * across + (0, 0, wr)
            m.cylinder("plastic", p - 0.15 * W * across, p + 0.15 * W * across, wr, fraction=0.5)


def _tyre(m: Model) -> None:
    """A tyre: a rubber ring on its tread, or lying flat when its box is low."""
    m.main = "rubber"
    if m.sz < 0.6 * max(m.sx, m.sy):
        r = min(m.sx, m.sy) / 2
        m.torus("rubber", (0, 0, 0.5 * m.sz), 0.7 * r, 0.3 * r)
        m.cylinder("metal", (0, 0, 0.3 * m.sz), (0, 0, 0.6 * m.sz), 0.45 * r, fraction=0.6)
        m.cylinder("dark_metal", (0, 1.3 * r, 0.5 * m.sz), (0, 1.3 * r, 0.62 * m.sz), 0.04 * r, fraction=0.3)
        return
    r = min(m.sx, m.sz) / 2
    m.torus("rubber", (0, 0, r), 0.7 * r, 0.3 * r, axis="y")
    m.cylinder("metal", (0, -0.3 * m.sy, r), (0, 0.3 * m.sy, r), 0.45 * r, fraction=0.6)
    m.cylinder("dark_metal", (0.3 * r, -0.3 * m.sy, 1.3 * r), (0.3 * r, -0.36 * m.sy, 1.3 * r), 0.04 * r, fraction=0.3)  # the valve


def _wheel(m: Model) -> None:
    """A spoked wheel (a bicycle's, a cart's): a thin tyre round a rim, spokes to a hub,
    standing on its tread across its box's longer side, or lying flat when its box is low."""
    m.main = "rubber"
    flat = m.sz < 0.6 * max(m.sx, m.sy)
    r = (min(m.sx, m.sy) if flat else min(max(m.sx, m.sy), m.sz)) / 2
    axis = "z" if flat else ("y" if m.sx >= m.sy else "x")
    centre = np.array((0.0, 0.0, 0.5 * m.sz if flat else r))
    m.torus("rubber", tuple(centre), 0.92 * r, 0.08 * r, axis=axis)
    m.torus("metal", tuple(centre), 0.8 * r, 0.035 * r, axis=axis, fraction=0.8)
    normal = {"z": np.array((0.0, 0.0, 1.0)), "y": np.array((0.0, 1.0, 0.0)), "x": np.array((1.0, 0.0, 0.0))}[axis]
    m.cylinder("dark_metal", tuple(centre - 0.08 * r * normal), tuple(centre + 0.08 * r * normal), 0.08 * r, fraction=0.4)
    u = np.cross(normal, (0.0, 0.0, 1.0) if axis != "z" else (1.0, 0.0, 0.0))
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    for k in range(12):
        a = 2 * np.pi * (k + 0.5) / 12
        tip = centre + 0.78 * r * (np.cos(a) * u + np.sin(a) * v)
        m.beam("metal", tuple(centre + 0.07 * r * (np.cos(a) * u + np.sin(a) * v)), tuple(tip), 0.012 * r + 0.001)


def _microscope(m: Model) -> None:
    """A microscope: a heavy foot, a curved arm holding an eyepiece tube over a stage."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("paint", (-0.8 * W, -D, 0), (0.8 * W, D, 0.1 * H))
    m.box("dark_metal", (-0.7 * W, -0.5 * D, 0.35 * H), (0.7 * W, 0.3 * D, 0.4 * H))
    m.beam("paint", (0, 0.7 * D, 0.1 * H), (0, 0.7 * D, 0.55 * H), 0.35 * W)
    m.beam("paint", (0, 0.7 * D, 0.55 * H), (0, 0.2 * D, 0.85 * H), 0.3 * W)
    m.cylinder("metal", (0, -0.1 * D, 0.45 * H), (0, 0.25 * D, 0.92 * H), 0.18 * W, fraction=0.6)
    m.cylinder("dark_metal", (0, 0.25 * D, 0.92 * H), (0, 0.35 * D, H), 0.13 * W, fraction=0.5)
    m.cylinder("chrome", (0, -0.12 * D, 0.45 * H), (0, -0.15 * D, 0.41 * H), 0.1 * W, fraction=0.4)
    for s in (-1, 1):
        m.cylinder("dark_plastic", (s * 0.15 * W, 0.7 * D, 0.3 * H), (s * 0.55 * W, 0.7 * D, 0.3 * H), 0.12 * W, fraction=0.4)


def _skull(m: Model) -> None:
    """A skull: a rounded cranium, a narrower jaw, dark eye sockets and nose."""
    m.main = "ceramic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.ball("ceramic", (0, 0.05 * D, 0.6 * H), (W, 0.95 * D, 0.4 * H))
    m.box("ceramic", (-0.6 * W, -0.9 * D, 0.0), (0.6 * W, 0.3 * D, 0.4 * H), rounded=0.2 * min(W, D, H))
    for s in (-1, 1):
        m.ball("dark_plastic", (s * 0.38 * W, -0.78 * D, 0.52 * H), (0.25 * W, 0.12 * D, 0.14 * H), fraction=0.4)
    m.ball("dark_plastic", (0, -0.88 * D, 0.36 * H), (0.1 * W, 0.06 * D, 0.08 * H), fraction=0.3)
    for k in range(5):
        x = -0.4 * W + 0.2 * W * k
        m.box("paper", (x - 0.07 * W, -0.92 * D, 0.12 * H), (x + 0.07 * W, -0.88 * D, 0.25 * H), rounded=0.0)


def _till(m: Model) -> None:
    """A cash register: a cash drawer, a sloped keypad, a receipt slot and a display."""
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    drawer = 0.35 * H
    m.box("plastic", (-W, -D, 0), (W, D, drawer))
    m.box("dark_plastic", (-0.85 * W, -1.01 * D, 0.08 * H), (0.85 * W, -D, drawer - 0.08 * H), rounded=0.0)
    m.extrude("plastic", [(-D, drawer), (0.5 * D, drawer), (0.5 * D, 0.65 * H), (-D, 0.45 * H)], "x", -0.9 * W, 0.9 * W)
    for i in range(4):
        for j in range(3):
            y = -0.85 * D + 0.35 * D * j
            z = 0.45 * H + (y + D) * 0.2 * H / (1.5 * D) + 0.005
            m.box(("paint", "accent", "paper")[(i + j) % 3], (-0.7 * W + 0.35 * W * i, y, z), (-0.5 * W + 0.35 * W * i, y + 0.2 * D, z + 0.03 * H))
    m.box("plastic", (-0.6 * W, 0.5 * D, drawer), (0.6 * W, D, 0.7 * H))
    m.post("dark_plastic", 0.5 * W, 0.75 * D, 0.7 * H, 0.85 * H, 0.04 * W, fraction=0.4)
    m.box("screen", (0.2 * W, 0.65 * D, 0.85 * H), (0.8 * W, 0.85 * D, H), rounded=0.0)


def _compass(m: Model) -> None:
    """A ship's compass: a round brass case with a glass face over the card and its needle."""
    m.main = "brass"
    r = 0.5 * min(m.sx, m.sy)
    H = m.sz
    m.lathe("brass", [(0.0, 0.0), (r, 0.0), (r, 0.7 * H), (0.85 * r, 0.8 * H), (0.0, 0.8 * H)])
    m.lathe("paper", [(0.84 * r, 0.8 * H), (0.84 * r, 0.82 * H), (0.0, 0.82 * H)])
    m.beam("accent", (0, -0.7 * r, 0.84 * H), (0, 0.0, 0.84 * H), 0.1 * r, 0.02 * H)
    m.beam("dark_metal", (0, 0.0, 0.845 * H), (0, 0.7 * r, 0.845 * H), 0.1 * r, 0.02 * H)
    m.lathe("glass", [(0.86 * r, 0.82 * H), (0.86 * r, H), (0.0, H)])


def _shears(m: Model) -> None:
    """Shears or scissors lying open: two blades crossing at a pivot, a ring handle on each."""
    m.main = "chrome"
    f = _Along(m)
    L, A, B = f.L, f.A, f.B
    pivot = 0.55 * L
    for s, b in ((-1, -0.3 * B), (1, 0.3 * B)):
        m.beam("chrome", f.p(0.0, s * 0.5 * A, b), f.p(pivot, -s * 0.05 * A, b), 0.3 * A, 0.35 * B)
        m.beam("chrome", f.p(pivot, -s * 0.05 * A, b), f.p(0.78 * L, -s * 0.45 * A, b), 0.15 * A, 0.3 * B)
        m.torus("dark_plastic", f.p(0.88 * L, -s * 0.5 * A, b), 0.1 * L, 0.12 * min(A, B) + 0.002, axis=f.ring, fraction=0.5)
    m.cylinder("brass", f.p(pivot, 0, -0.8 * B), f.p(pivot, 0, 0.8 * B), 0.1 * A, fraction=0.4)


def _tape_measure(m: Model) -> None:
    """A tape measure: a round case with a belt clip, the tape's end and hook drawn out."""
    m.main = "yellow_paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = min(W, 0.5 * H)
    m.cylinder("yellow_paint", (0, -0.8 * D, r), (0, 0.8 * D, r), r, fraction=0.7)
    m.cylinder("dark_plastic", (0, -0.81 * D, r), (0, -0.8 * D, r), 0.5 * r, fraction=0.6)
    m.box("metal", (-0.6 * r, -0.5 * D, 0.0), (0.95 * W, 0.5 * D, 0.05 * H), rounded=0.0)
    m.box("dark_metal", (0.95 * W, -0.55 * D, 0.0), (W, 0.55 * D, 0.15 * H), rounded=0.0)


def _power_tool(m: Model) -> None:
    """A power tool held like a pistol (drill, impact wrench, wheel gun): a body with a nose
    and socket, a grip, a battery foot."""
    m.main = "paint"
    f = _Along(m)
    L, A, B = f.L, f.A, f.B
    f.box("paint", (0.25 * L, -A, 0.1 * B), (L, A, B), rounded=0.3 * A)
    f.rod("dark_metal", 0.08 * L, 0.26 * L, 0.5 * A)
    f.rod("chrome", 0.0, 0.09 * L, 0.35 * A)
    f.box("dark_plastic", (0.55 * L, -0.8 * A, -0.6 * B), (0.8 * L, 0.8 * A, 0.1 * B), rounded=0.2 * A)
    f.box("accent", (0.5 * L, -A, -B), (0.9 * L, A, -0.6 * B), rounded=0.1 * A)


def tool(m: Model) -> None:
    """A small object by its name: an anvil on its stump, a hammer, axe, pickaxe or mallet, a
    wrench, a long-handled tool (shovel, fork, rake, broom, golf club), a sword, a lens, papers
    or a scroll, a telescope, a traffic cone, a trophy, a radio, a weathervane, a skateboard,
    a tyre, a spoked wheel, a microscope, a skull, a till, a power tool, a compass, shears, a tape measure, a
    grindstone on its frame, a shoemaker's last, a potter's wheel, a helmet, a gadget, a teddy bear
    or a doll; else a toolbox. The variant named first
    wins ("radio scanner" is a radio)."""
    variants = (
        (("anvil",), _anvil),
        (("grindstone", "grinding wheel", "whetstone wheel", "sharpening wheel"), _grindstone),
        (("last", "shoe last"), _last),
        (("potter's wheel", "potters wheel", "pottery wheel"), _potters_wheel),
        (("hammer", "axe", "hatchet", "mallet", "gavel", "sledgehammer", "pickaxe", "pick", "mattock"), _hammer),
        (("wrench", "spanner"), _wrench),
        (("shovel", "spade", "fork", "pitchfork", "rake", "hoe", "broom", "mop", "oar", "paddle", "putter", "golf club",
          "club", "hockey stick"), _long_tool),
        (("sword", "cutlass", "sabre", "saber", "katana", "dagger", "rapier", "scimitar", "machete"), _blade),
        (("loupe", "eyeglass", "magnifying glass", "magnifier", "lens"), _lens),
        (("script", "letter", "document", "papers", "paper", "manuscript", "contract", "newspaper", "envelope"), _papers),
        (("scroll", "parchment"), _scroll),
        (("telescope", "spyglass"), _telescope),
        (("traffic cone", "cone", "pylon cone"), _cone),
        (("pencil", "crayon", "pen", "marker", "felt tip", "chalk"), _pencil),
        (("trophy", "award", "cup trophy"), _trophy),
        (("radio", "gramophone", "record player", "turntable", "stereo", "wireless"), _radio),
        (("weathervane", "weather vane", "wind vane"), _weathervane),
        (("skateboard", "longboard"), _skateboard),
        (("tyre", "tire", "spare tyre", "spare tire"), _tyre),
        (("microscope",), _microscope),
        (("wheel gun", "impact wrench", "drill", "nail gun", "power tool"), _power_tool),
        (("compass",), _compass),
        (("shears", "scissors", "secateurs", "clippers"), _shears),
        (("tape measure", "measuring tape"), _tape_measure),
        (("skull",), _skull),
        (("cash register", "till", "register"), _till),
        # after the names that hold "wheel" as a modifier ("wheel gun"): a tie goes to the earlier
        (("wheel", "bicycle wheel", "bike wheel", "cartwheel", "cart wheel", "wagon wheel"), _wheel),
        (("toolbox", "tool box", "tool chest", "toolkit", "kit"), _toolbox),
        (("helmet", "hard hat", "hardhat", "crash helmet"), _helmet),
        (("gadget", "device", "remote", "walkie-talkie", "scanner", "detector", "controller", "calculator",
          "phone", "tablet"), _gadget),
        # toys in hand: a small animal or person, which the parse keeps a thing that is held
        (("teddy", "teddy bear", "plush toy", "stuffed animal", "soft toy", "cuddly toy"), creatures.animal),
        (("doll", "rag doll", "action figure"), creatures.figure),
    )
    (m.first_named(variants) or _toolbox)(m)


SHAPES = {"machine": machine, "tank": tank, "tool": tool}
