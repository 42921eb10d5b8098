"""Machines, vessels and hand tools the catalogue does not know one by one: a boxy machine
with the panels, vents, pipes, screens and buttons its name calls for, a tank (fuel tank on
saddles, silo, water tower, boiler, cauldron, aquarium), a tool (anvil, hammer, toolbox,
gadget). Fronts face −Y."""

from __future__ import annotations

import numpy as np

from scenewright.procedural.builder import Model
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


def machine(m: Model) -> None:
    """A boxy machine; its name picks the build: arcade cabinet, console or terminal,
    generator or engine, compressor, printer, washing machine, server rack."""
    variants = (
        (("arcade", "pinball", "slot machine", "jukebox", "game cabinet"), _arcade),
        (("console", "terminal", "control panel", "control desk", "dashboard", "workstation", "switchboard", "cockpit"),
         _console),
        (("compressor",), _compressor),
        (("generator", "engine", "motor", "pump", "turbine", "dynamo"), _engine),
        (("printer", "copier", "photocopier", "fax", "scanner"), _printer),
        (("washing machine", "washer", "dryer", "dishwasher", "laundry"), _washer),
        (("server", "mainframe", "rack", "supercomputer"), _server),
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
        (("water tower", "water tank"), _water_tower),
        (("boiler", "water heater", "furnace", "still", "reactor"), _boiler),
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


def _hammer(m: Model) -> None:
    """A hammer (or axe, mallet) lying on its side, the handle along x."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = 0.3 * H
    m.cylinder("wood", (-0.95 * W, 0.2 * D, r), (0.6 * W, 0.2 * D, r), r, 0.8 * r, fraction=0.5)  # its end inside the grip
    if m.named("axe", "hatchet"):
        m.extrude("metal", [(-D, 0.0), (0.5 * D, 0.2 * H), (0.5 * D, 0.8 * H), (-D, H)], "x", 0.55 * W, 0.85 * W)
    elif m.named("mallet", "gavel"):
        m.cylinder("wood", (0.75 * W, -D, 0.5 * H), (0.75 * W, D, 0.5 * H), 0.25 * W, fraction=0.6)
    else:
        m.box("metal", (0.55 * W, -D, 0.05 * H), (0.85 * W, D, 0.95 * H))
        m.extrude("metal", [(0.6 * W, 0.2 * H), (W, 0.4 * H), (W, 0.6 * H), (0.6 * W, 0.8 * H)], "y", 0.0, 0.9 * D)
    m.cylinder("rubber", (-W, 0.2 * D, r), (-0.6 * W, 0.2 * D, r), 1.15 * r, fraction=0.5)


def _wrench(m: Model) -> None:
    m.main = "chrome"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("chrome", (-0.7 * W, -0.15 * D, 0), (0.7 * W, 0.15 * D, H))
    for s in (-1, 1):
        m.torus("chrome", (s * 0.8 * W, 0, 0.5 * H), 0.7 * D, 0.25 * D, fraction=0.6)


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


def tool(m: Model) -> None:
    """A small object: an anvil on its stump, a hammer, axe or mallet, a wrench, a toolbox,
    a gadget with a screen and buttons."""
    variants = (
        (("anvil",), _anvil),
        (("hammer", "axe", "hatchet", "mallet", "gavel", "sledgehammer", "pickaxe"), _hammer),
        (("wrench", "spanner"), _wrench),
        (("toolbox", "tool box", "tool chest", "toolkit", "kit"), _toolbox),
        (("gadget", "device", "remote", "radio", "walkie-talkie", "scanner", "detector", "controller", "calculator",
          "phone", "tablet"), _gadget),
    )
    for words, build in variants:
        if m.named(*words):
            build(m)
            return
    _toolbox(m)


SHAPES = {"machine": machine, "tank": tank, "tool": tool}
