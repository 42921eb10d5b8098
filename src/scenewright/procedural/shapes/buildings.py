"""Buildings, booths and boards."""

from __future__ import annotations

import numpy as np

from scenewright.procedural import parts as P
from scenewright.procedural.builder import Model
from scenewright.procedural.shapes.frames import ring


def _windows(m: Model, x0, x1, z0, z1, y: float, facing: int, floors: int, along: str = "x") -> None:
    """A grid of glass panes with sills on one wall (``along`` the wall's axis)."""
    width = x1 - x0
    if width <= 0:  # a wall narrower than a pane with its margins keeps none (panes would turn inside out)
        return
    floors = min(floors, 15)
    # Wide panes on big facades keep a tower inside the face budget (about 48 panes per wall).
    cols = min(10, max(1, int(width / 2.2)), max(1, 48 // floors))
    fh = (z1 - z0) / floors
    cw = width / cols
    for f in range(floors):
        for c in range(cols):
            a, b = x0 + (c + 0.25) * cw, x0 + (c + 0.75) * cw
            lo, hi = z0 + f * fh + 0.3 * fh, z0 + f * fh + 0.85 * fh
            d0, d1 = sorted((y, y + facing * 0.04))
            s0, s1 = sorted((y, y + facing * 0.08))
            if along == "x":
                m.box("glass", (a, d0, lo), (b, d1, hi), rounded=0.0)
                m.box("concrete", (a - 0.05, s0, lo - 0.06), (b + 0.05, s1, lo), rounded=0.0)
            else:
                m.box("glass", (d0, a, lo), (d1, b, hi), rounded=0.0)
                m.box("concrete", (s0, a - 0.05, lo - 0.06), (s1, b + 0.05, lo), rounded=0.0)


def _dome(m: Model) -> None:
    """A dome on a low ring wall (a habitat dome, an igloo, a geodesic dome): ribs over the
    shell, a ring of round windows and an entrance tunnel toward the viewer."""
    m.main = "wall"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    tunnel = 0.22 * D
    R, Ry, cy = W, D - 0.5 * tunnel, 0.5 * tunnel  # the shell leaves the tunnel room in front
    ring = 0.12 * H
    quarter = np.linspace(0.0, np.pi / 2, 10)
    shell = [(np.cos(t), ring + (H - ring) * np.sin(t)) for t in quarter[:-1]] + [(0.02, H)]
    m.lathe("wall", [(1.0, 0.0), *shell], centre=(0, cy, 0), scale=(R, Ry))
    m.lathe("dark_metal", [(1.02, 0.0), (1.02, ring)], centre=(0, cy, 0), scale=(R, Ry), fraction=0.8)
    rib = 0.012 * max(R, H) + 0.01
    for k in range(6):  # meridian ribs from the ring up to the crown
        a = np.pi * k / 6
        for t0, t1 in zip(quarter[:-1], quarter[1:]):
            p0 = (np.cos(t0) * R * np.cos(a), cy + np.cos(t0) * Ry * np.sin(a), ring + (H - ring) * np.sin(t0))
            p1 = (np.cos(t1) * R * np.cos(a), cy + np.cos(t1) * Ry * np.sin(a), ring + (H - ring) * np.sin(t1))
            for sign in (1, -1):
                q0 = (sign * p0[0], cy + sign * (p0[1] - cy), p0[2])
                q1 = (sign * p1[0], cy + sign * (p1[1] - cy), p1[2])
                m.cylinder("dark_metal", q0, q1, rib, fraction=0.3)
    t = np.pi / 5  # windows a fifth of the way up the shell, between the ribs
    for k in range(6):
        a = np.pi * (k + 0.5) / 6 + np.pi
        if abs(np.sin(a) + 1) < 0.3:
            continue  # none over the entrance
        x, y = 0.99 * np.cos(t) * R * np.cos(a), cy + 0.99 * np.cos(t) * Ry * np.sin(a)
        m.ball("glass", (x, y, ring + (H - ring) * np.sin(t)), (0.12 * R, 0.12 * Ry, 0.1 * H), fraction=0.4)
    door_w, door_h = min(0.35 * R, 1.2), min(0.45 * H, 2.4)
    m.box("wall", (-door_w, -D, 0), (door_w, cy - 0.8 * Ry, door_h), rounded=0.2 * door_w)
    m.box("dark_metal", (-0.7 * door_w, -D - 0.01, 0), (0.7 * door_w, -D + 0.02, 0.85 * door_h))


def _pagoda(m: Model) -> None:
    """Tiers of walls each under a wide roof with a lifted rim, narrowing upward, the ground tier
    tallest, a spire on top and a door toward the viewer: a pagoda, not an office block."""
    m.main = "wall"
    tiers = 3 if m.sz < 8.0 else 5
    spire = 0.12 * m.sz
    heights = np.array([1.6] + [1.0] * (tiers - 1))
    heights *= (m.sz - spire) / heights.sum()
    c = np.sqrt(0.5)
    turn = P.affine(np.array([[c, -c, 0.0], [c, c, 0.0], [0.0, 0.0, 1.0]]), (0.0, 0.0, 0.0))  # a lathe's square, edge on
    z0 = 0.0
    for k, h in enumerate(heights):
        shrink = 1.0 - 0.45 * k / max(1, tiers - 1)
        hx, hy = 0.36 * m.sx * shrink, 0.36 * m.sy * shrink
        eave = z0 + h - 0.4 * heights[-1]
        m.box("wall", (-hx, -hy, z0), (hx, hy, eave), rounded=0.0)
        # the roof: a square frustum broad at the eaves, its rim lifted
        eave_x, eave_y = min(0.5 * m.sx, 1.45 * hx), min(0.5 * m.sy, 1.45 * hy)
        rise = 0.4 * heights[-1]
        roof = P.lathe([(np.sqrt(2), eave), (np.sqrt(2), eave + 0.2 * rise), (0.6 * np.sqrt(2), eave + 0.6 * rise),
                        (0.5 * np.sqrt(2), eave + rise)], 4)
        m.add("roof", P.transform(P.transform(roof, turn), P.affine(np.diag([eave_x, eave_y, 1.0]), (0, 0, 0))))
        z0 += h
    m.cylinder("brass", (0, 0, z0), (0, 0, m.sz), 0.05 * min(m.sx, m.sy), 0.01)
    door = min(1.2, 0.25 * m.sx)
    m.box("dark_wood", (-door / 2, -0.36 * m.sy - 0.03, 0), (door / 2, -0.36 * m.sy + 0.01, min(2.2, 0.6 * heights[0])), rounded=0.0)


def building(m: Model) -> None:
    """A building its name picks: a castle, a church, a dome, a pagoda; else a block of floors
    with windows on every side and a glass door under an awning at the front."""
    variants = (
        (("castle", "fort", "fortress", "citadel", "keep", "stronghold"), _castle),
        (("church", "chapel", "cathedral", "kirk", "basilica"), _church),
        (("dome", "domed", "igloo", "habitat"), _dome),
        (("pagoda",), _pagoda),
    )
    for words, build in variants:
        if m.named(*words):
            build(m)
            return
    m.main = "wall"
    parapet = min(1.0, 0.05 * m.sz)
    top = m.sz - parapet
    m.box("wall", (-m.sx / 2 + 0.08, -m.sy / 2 + 0.08, 0), (m.sx / 2 - 0.08, m.sy / 2 - 0.08, top))
    m.box("concrete", (-m.sx / 2, -m.sy / 2, top), (m.sx / 2, m.sy / 2, m.sz))
    floors = max(1, int(round(top / 3.2)))
    fh = top / floors
    for f in range(1, floors):
        m.box("concrete", (-m.sx / 2 + 0.04, -m.sy / 2 + 0.04, f * fh - 0.12), (m.sx / 2 - 0.04, m.sy / 2 - 0.04, f * fh))
    inset = 0.08
    _windows(m, -m.sx / 2 + 0.5, m.sx / 2 - 0.5, fh, top, -m.sy / 2 + inset, -1, max(1, floors - 1))
    _windows(m, -m.sx / 2 + 0.5, m.sx / 2 - 0.5, 0, top, m.sy / 2 - inset, 1, floors)
    _windows(m, -m.sy / 2 + 0.5, m.sy / 2 - 0.5, 0, top, -m.sx / 2 + inset, -1, floors, along="y")
    _windows(m, -m.sy / 2 + 0.5, m.sy / 2 - 0.5, 0, top, m.sx / 2 - inset, 1, floors, along="y")
    door = min(1.8, 0.3 * m.sx)
    m.box("glass", (-door / 2, -m.sy / 2 + 0.02, 0), (door / 2, -m.sy / 2 + inset, min(2.5, 0.8 * fh)), rounded=0.0)
    # The awning reaches into the wall, so its back face is not in the plane of the sills'.
    m.box("accent", (-m.sx / 2 + 0.3, -m.sy / 2, min(2.7, 0.85 * fh)), (m.sx / 2 - 0.3, -m.sy / 2 + 1.5 * inset, min(3.0, 0.95 * fh)))


def _castle(m: Model) -> None:
    """Curtain walls with battlements round a courtyard, a round tower with a pointed roof at each
    corner, a tall keep behind and a gate in the front wall: a castle seen from anywhere."""
    m.main = "stone"
    r = min(0.13 * min(m.sx, m.sy), 0.22 * m.sz)
    side = min(m.sx, m.sy)  # (walls and battlements no thicker than a tenth of it: a toy castle keeps its shape)
    wall_h, t = 0.45 * m.sz, min(max(0.4, 0.03 * side), 0.1 * side)
    x0, x1, y0, y1 = -m.sx / 2 + r, m.sx / 2 - r, -m.sy / 2 + r, m.sy / 2 - r
    for lo, hi in (((x0, y0 - t / 2), (x1, y0 + t / 2)), ((x0, y1 - t / 2), (x1, y1 + t / 2)),
                   ((x0 - t / 2, y0), (x0 + t / 2, y1)), ((x1 - t / 2, y0), (x1 + t / 2, y1))):
        m.box("stone", (*lo, 0), (*hi, wall_h), rounded=0.0)
    merlon = min(max(0.5, t), 0.1 * side)  # battlements along the front and back walls
    for y in (y0, y1):
        n = max(2, int((x1 - x0) / (2 * merlon)))
        for k in range(n):
            x = x0 + (k + 0.5) * (x1 - x0) / n
            m.box("stone", (x - merlon / 2, y - t / 2, wall_h), (x + merlon / 2, y + t / 2, wall_h + merlon), rounded=0.0)
    tower_h = 0.7 * m.sz
    for x, y in ((x0, y0), (x1, y0), (x0, y1), (x1, y1)):
        m.post("stone", x, y, 0, tower_h, r, fraction=1.0)
        m.cylinder("roof", (x, y, tower_h), (x, y, tower_h + 0.3 * m.sz - 0.02), 1.15 * r, 0.02)
    kw, kd = 0.3 * m.sx, 0.25 * m.sy
    m.box("stone", (-kw / 2, y1 - t - kd, 0), (kw / 2, y1 - t, 0.8 * m.sz), rounded=0.0)
    m.extrude("roof", [(y1 - t - kd, 0.8 * m.sz), (y1 - t, 0.8 * m.sz), (y1 - t - kd / 2, m.sz)], "x", -kw / 2, kw / 2)
    gate_w = min(3.0, 0.2 * m.sx)
    m.box("dark_wood", (-gate_w / 2, y0 - t / 2 - 0.05, 0), (gate_w / 2, y0 - t / 2, 0.7 * wall_h), rounded=0.0)


def _church(m: Model) -> None:
    """A gabled nave with a bell tower and spire at its front, a door under the tower."""
    m.main = "stone"
    tw = min(0.3 * m.sx, 0.25 * m.sy)
    eave = 0.4 * m.sz
    y_nave = -m.sy / 2 + tw
    m.box("stone", (-m.sx / 2, y_nave, 0), (m.sx / 2, m.sy / 2, eave), rounded=0.0)
    m.extrude("roof", [(y_nave, eave), (m.sy / 2, eave), (m.sy / 2, eave + 0.02), ((y_nave + m.sy / 2) / 2, 0.65 * m.sz),
                       (y_nave, eave + 0.02)], "x", -m.sx / 2 - 0.1, m.sx / 2 + 0.1)  # fmt: skip
    tower_h = 0.7 * m.sz
    m.box("stone", (-tw / 2, -m.sy / 2, 0), (tw / 2, y_nave + 0.05, tower_h), rounded=0.0)
    m.cylinder("roof", (0, -m.sy / 2 + tw / 2, tower_h), (0, -m.sy / 2 + tw / 2, m.sz), 0.72 * tw, 0.02)
    door = min(1.6, 0.6 * tw)
    m.box("dark_wood", (-door / 2, -m.sy / 2 - 0.05, 0), (door / 2, -m.sy / 2, min(3.0, 0.3 * tower_h)), rounded=0.0)
    for k in range(3):  # tall windows down each side of the nave
        y = y_nave + (k + 0.5) * (m.sy / 2 - y_nave) / 3
        for x in (-m.sx / 2 - 0.03, m.sx / 2):
            m.box("glass", (x, y - 0.4, 0.3 * eave), (x + 0.03, y + 0.4, 0.85 * eave), rounded=0.0)


#: Words of houses built of timber (a log cabin, a hut, a wooden shed): their walls are wood, not render.
_TIMBER = ("log", "cabin", "hut", "shack", "shed", "wooden", "timber")


def _barn(m: Model) -> None:
    """A barn: red plank walls under a big gambrel roof whose ridge runs front to back, wide
    double doors braced with white crosses in its front gable, a hay-loft door above them."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    eave, knee, over, t = 0.45 * H, 0.8 * H, 0.05 * min(m.sx, m.sy), 0.03 * H
    m.box("paint", (-W + over, -D + over, 0), (W - over, D - over, eave))
    # the gable ends, a gambrel's five sides, and the roof's four slopes laid over them
    gable = [(-W + over, eave), (W - over, eave), (0.62 * (W - over), knee), (0.0, H - t), (-0.62 * (W - over), knee)]
    m.extrude("paint", gable, "y", -D + over, D - over)
    slope = [(-W, eave - t), (-0.64 * W, knee), (0.0, H), (0.64 * W, knee), (W, eave - t)]
    for (x0, z0), (x1, z1) in zip(slope, slope[1:]):
        nx, nz = -(z1 - z0), (x1 - x0)  # the slope's outward normal, to give the slab its thickness
        k = t / max(1e-9, (nx * nx + nz * nz) ** 0.5)
        quad = [(x0, z0), (x1, z1), (x1 + nx * k, z1 + nz * k), (x0 + nx * k, z0 + nz * k)]
        m.extrude("roof", quad if _ccw(quad) else quad[::-1], "y", -D, D)
    door_w, door_h = min(3.0, 0.5 * m.sx), min(3.2, 0.8 * eave)
    front = -D + over
    m.box("dark_wood", (-door_w / 2, front - 0.04, 0), (door_w / 2, front, door_h), rounded=0.0)
    for x0, x1 in ((-door_w / 2, 0.0), (0.0, door_w / 2)):
        # (the two braces of a cross a hair apart in depth: no shared face where they cross)
        for k, ((xa, za), (xb, zb)) in enumerate((((x0, 0.0), (x1, door_h)), ((x0, door_h), (x1, 0.0)))):
            m.beam("canvas_alt", (xa, front - 0.06 - 0.004 * k, za), (xb, front - 0.06 - 0.004 * k, zb), 0.1)
        m.box("canvas_alt", (x0, front - 0.07, door_h - 0.1), (x1, front - 0.04, door_h), rounded=0.0)
    loft = 0.35 * door_w
    m.box("dark_wood", (-loft / 2, front - 0.04, eave + 0.05 * H), (loft / 2, front, eave + 0.05 * H + loft), rounded=0.0)


def _ccw(outline) -> bool:
    """Whether a 2D outline runs counter-clockwise (positive signed area)."""
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(outline, outline[1:] + outline[:1])) > 0


def house(m: Model) -> None:
    """A gabled house: walls (of wood for a cabin, a hut or a shed), a roof, a door, windows, a
    chimney; by its name a barn."""
    if m.named("barn", "stable", "stables", "cowshed", "byre"):
        _barn(m)
        return
    m.main = "wood" if m.has(*_TIMBER) else "wall"
    eave = 0.55 * m.sz
    over = 0.06 * min(m.sx, m.sy)
    m.box(m.main, (-m.sx / 2 + over, -m.sy / 2 + over, 0), (m.sx / 2 - over, m.sy / 2 - over, eave))
    m.extrude(m.main, [(-m.sy / 2 + over, eave), (m.sy / 2 - over, eave), (0, m.sz - 0.05 * m.sz)], "x",
              -m.sx / 2 + over, m.sx / 2 - over)
    t = 0.04 * m.sz
    for s in (-1, 1):
        outline = [(s * m.sy / 2, eave - 0.08 * m.sz), (s * m.sy / 2, eave - 0.08 * m.sz + t), (0, m.sz), (0, m.sz - t)]
        m.extrude("roof", outline, "x", -m.sx / 2, m.sx / 2)
    door_w = min(1.0, 0.2 * m.sx)
    m.box("dark_wood", (-door_w / 2, -m.sy / 2 + over - 0.04, 0), (door_w / 2, -m.sy / 2 + over, min(2.1, 0.8 * eave)), rounded=0.0)
    m.ball("brass", (door_w * 0.35, -m.sy / 2 + over - 0.05, min(1.0, 0.4 * eave)), (0.04, 0.03, 0.04), fraction=0.4)
    for x in (-0.3 * m.sx, 0.3 * m.sx):
        w = min(1.2, 0.18 * m.sx)
        m.box("glass", (x - w / 2, -m.sy / 2 + over - 0.03, 0.4 * eave), (x + w / 2, -m.sy / 2 + over, 0.8 * eave), rounded=0.0)
        m.box("dark_wood", (x - w / 2 - 0.05, -m.sy / 2 + over - 0.06, 0.38 * eave), (x + w / 2 + 0.05, -m.sy / 2 + over, 0.4 * eave))
    for y in (-0.2 * m.sy, 0.2 * m.sy):
        w = min(1.2, 0.18 * m.sy)
        for s in (-1, 1):
            x0, x1 = sorted((s * (m.sx / 2 - over), s * (m.sx / 2 - over + 0.03)))
            m.box("glass", (x0, y - w / 2, 0.4 * eave), (x1, y + w / 2, 0.8 * eave), rounded=0.0)
    cx = 0.25 * m.sx
    m.box("brick", (cx - 0.06 * m.sx, 0.1 * m.sy, 0.6 * m.sz), (cx + 0.06 * m.sx, 0.2 * m.sy, 0.97 * m.sz))


def _puppet_booth(m: Model) -> None:
    """A puppet booth: a tall striped canvas box, a stage opening at the top framed by
    curtains, a gable with a painted sign."""
    m.main = "canvas"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    stage = 0.55 * H
    stripes = 6
    for k in range(stripes):
        x0 = -W + 2 * W * k / stripes
        m.box("canvas" if k % 2 == 0 else "canvas_alt", (x0, -D, 0), (x0 + 2 * W / stripes, D, stage), rounded=0.0)
    m.box("wood", (-1.02 * W, -1.05 * D, stage), (1.02 * W, 1.02 * D, stage + 0.04 * H))
    for x in (-W, 0.8 * W):
        m.box("wood", (x, -D, stage + 0.04 * H), (x + 0.2 * W, D, 0.85 * H), rounded=0.0)
    m.box("dark_plastic", (-0.8 * W, 0.7 * D, stage + 0.04 * H), (0.8 * W, D, 0.85 * H), rounded=0.0)
    for s in (-1, 1):
        for k in range(3):
            x = s * (0.72 - 0.08 * k) * W
            m.cylinder("fabric", (x, -0.85 * D, stage + (0.05 + 0.005 * k) * H), (x, -0.85 * D, (0.84 - 0.005 * k) * H), 0.06 * W,
                       fraction=0.5)  # folds of different lengths: equal ones would share their ends
    m.box("wood", (-1.02 * W, -D, 0.85 * H), (1.02 * W, D, 0.88 * H))
    m.extrude("accent", [(-1.02 * W, 0.88 * H), (1.02 * W, 0.88 * H), (0.0, H)], "y", -D, -0.8 * D)
    m.box("paper", (-0.3 * W, -1.01 * D, 0.9 * H), (0.3 * W, -D, 0.95 * H), rounded=0.0)


def kiosk(m: Model) -> None:
    if m.named("puppet booth", "puppet theatre", "puppet theater", "punch and judy"):
        _puppet_booth(m)
        return
    m.main = "paint"
    roof = 0.85 * m.sz
    m.box("paint", (-m.sx / 2 + 0.1, -m.sy / 2 + 0.15, 0), (m.sx / 2 - 0.1, m.sy / 2 - 0.1, roof))
    m.box("dark_plastic", (-0.35 * m.sx, -m.sy / 2 + 0.13, 0.45 * m.sz), (0.35 * m.sx, -m.sy / 2 + 0.15, 0.8 * m.sz), rounded=0.0)
    m.box("wood", (-0.38 * m.sx, -m.sy / 2 + 0.02, 0.43 * m.sz), (0.38 * m.sx, -m.sy / 2 + 0.16, 0.46 * m.sz))
    m.box("roof", (-m.sx / 2, -m.sy / 2, roof), (m.sx / 2, m.sy / 2, roof + 0.05 * m.sz))
    m.box("accent", (-m.sx / 2 + 0.05, -m.sy / 2, roof + 0.05 * m.sz), (m.sx / 2 - 0.05, -m.sy / 2 + 0.1, m.sz))
    m.box("light", (-0.3 * m.sx, -m.sy / 2 - 0.005, roof + 0.07 * m.sz), (0.3 * m.sx, -m.sy / 2, m.sz - 0.02 * m.sz), rounded=0.0)


def market_stall(m: Model) -> None:
    """A counter of goods at the front under a striped awning on four posts, and a trestle at
    the back at the counter's height, where what the text puts on the stall stands (the
    catalogue's ``rest_height``)."""
    m.main = "canvas"
    post = m.thick(0.05, 0.05 * m.sx)
    counter = 0.4 * m.sz
    front_top, back_top = 0.82 * m.sz, m.sz
    m.box("wood", (-m.sx / 2 + post, -m.sy / 2 + 0.12 * m.sy, 0), (m.sx / 2 - post, -m.sy / 2 + 0.45 * m.sy, counter))
    y0, y1 = 0.02 * m.sy, m.sy / 2 - post - 0.03 * m.sy
    m.box("wood", (-m.sx / 2 + post, y0, counter - 0.04 * m.sz), (m.sx / 2 - post, y1, counter))
    for x in (-m.sx / 2 + 2 * post, m.sx / 2 - 2 * post):
        for y in (y0 + post, y1 - post):
            m.post("wood", x, y, 0.0, counter - 0.04 * m.sz, post / 3)
    for x in (-m.sx / 2 + post / 2, m.sx / 2 - post / 2):
        m.box("wood", (x - post / 2, -m.sy / 2 + 0.1 * m.sy, 0), (x + post / 2, -m.sy / 2 + 0.1 * m.sy + post, front_top))
        m.box("wood", (x - post / 2, m.sy / 2 - post - 0.01 * m.sy, 0), (x + post / 2, m.sy / 2 - 0.01 * m.sy, back_top))
    # The awning overhangs the posts a little at the sides (and at the back, where the back
    # posts stand in from the edge): posts flush with its edges would share its end faces.
    stripes = min(16, max(4, int(m.sx / 0.35)))
    w = 1.02 * m.sx / stripes
    for i in range(stripes):
        role = "canvas" if i % 2 == 0 else "canvas_alt"
        x0 = -0.51 * m.sx + i * w
        m.extrude(role, [(-m.sy / 2, front_top - 0.06 * m.sz), (-m.sy / 2, front_top), (m.sy / 2, back_top), (m.sy / 2, back_top - 0.03)],
                  "x", x0, x0 + w)
    goods = min(12, max(3, int(m.sx / 0.3)))
    for i in range(goods):
        x = -m.sx / 2 + post + (i + 0.5) * (m.sx - 2 * post) / goods
        s = 0.08 * min(m.sx, 1.5)
        role = ("flower", "flower_alt", "leaf")[i % 3]
        for j in range(3):
            m.ball(role, (x + (j - 1) * s * 0.9, -m.sy / 2 + 0.28 * m.sy + (j % 2) * s * 0.5, counter + s * 0.8), (s * 0.5,) * 3,
                   fraction=0.4)


def _lighthouse(m: Model) -> None:
    m.main = "wall"
    top = 0.72 * m.sz
    bands = 4
    for k in range(bands):
        z0, z1 = top * k / bands, top * (k + 1) / bands
        r0, r1 = 0.45 - 0.12 * k / bands, 0.45 - 0.12 * (k + 1) / bands
        m.lathe("wall" if k % 2 == 0 else "paint", [(r0, z0), (r1, z1)], scale=(m.sx, m.sy))
    m.lathe("dark_metal", [(0.42, top), (0.42, top + 0.03 * m.sz)], scale=(m.sx, m.sy))
    m.lathe("light", [(0.25, top + 0.03 * m.sz), (0.25, 0.88 * m.sz)], scale=(m.sx, m.sy))
    m.lathe("paint", [(0.3, 0.88 * m.sz), (0.0, m.sz)], scale=(m.sx, m.sy))


def _windmill(m: Model) -> None:
    m.main = "wall"
    body = 0.7 * m.sz
    r = 0.3 * min(m.sx, m.sy * 2)
    m.lathe("wall", [(r, 0), (0.7 * r, body)], centre=(0, 0.1 * m.sy, 0))
    m.lathe("roof", [(0.8 * r, body), (0.0, body + 0.15 * m.sz)], centre=(0, 0.1 * m.sy, 0))
    hub = np.array([0, -m.sy / 2 + 0.05 * m.sy, body])
    m.cylinder("dark_wood", hub, hub + (0, 0.5 * m.sy, 0), 0.05 * r, fraction=0.4)
    arm = min(m.sx / 2, m.sz - body, body - 0.05 * m.sz)
    for k in range(4):
        a = np.pi / 4 + k * np.pi / 2
        tip = hub + (np.cos(a) * arm, 0, np.sin(a) * arm)
        m.beam("wood", hub, tip, 0.04 * arm, 0.02 * arm)
        mid = hub + (np.cos(a) * arm * 0.6, 0, np.sin(a) * arm * 0.6)
        m.beam("canvas_alt", mid, tip, 0.25 * arm, 0.01 * arm)


def _rocket(m: Model) -> None:
    m.main = "paint"
    r = 0.3 * min(m.sx, m.sy)
    m.lathe("canvas_alt", [(0.8 * r, 0.06 * m.sz), (r, 0.15 * m.sz), (r, 0.7 * m.sz), (0.6 * r, 0.88 * m.sz), (0.0, m.sz)])
    m.lathe("paint", [(1.01 * r, 0.6 * m.sz), (1.01 * r, 0.7 * m.sz)])
    m.lathe("dark_metal", [(0.5 * r, 0), (0.8 * r, 0.06 * m.sz)])
    m.cylinder("glass", (0, -0.95 * r, 0.5 * m.sz), (0, -1.02 * r, 0.5 * m.sz), 0.3 * r, fraction=0.5)
    for k in range(4):
        a = 2 * np.pi * k / 4 + np.pi / 4
        d = np.array([np.cos(a), np.sin(a)])
        outline = [(0.8 * r, 0.05 * m.sz), (m.sx / 2 * 0.98 / max(abs(d[0]), abs(d[1]), 0.7), 0.0), (r, 0.3 * m.sz)]
        fin = P.prism(outline, 0.04 * r)
        linear = np.array([[d[0], -d[1], 0], [d[1], d[0], 0], [0, 0, 1]]) @ np.array([[1, 0, 0], [0, 0, 1], [0, 1, 0]], float)
        m.add("paint", P.transform(fin, P.affine(linear, (0, 0, 0))))

def _dish(m: Model) -> None:
    """A satellite dish (or radar dish): a pedestal, a yoke, and a shallow dish tilted up
    toward the sky at the front, a feed on struts at its focus."""
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    R = min(W, D, 0.42 * H)
    hub = H - R * 1.05
    m.box("concrete", (-0.5 * W, -0.5 * D, 0), (0.5 * W, 0.5 * D, 0.05 * H))
    m.post("dark_metal", 0, 0, 0.05 * H, hub, 0.08 * R + 0.01, fraction=0.5)
    tilt = np.radians(50.0)  # from facing straight up toward the front (−Y)
    rot = np.array([[1, 0, 0], [0, np.cos(tilt), -np.sin(tilt)], [0, np.sin(tilt), np.cos(tilt)]])
    dish = P.lathe([(0.0, 0.0), (0.35 * R, 0.03 * R), (0.7 * R, 0.12 * R), (R, 0.28 * R), (0.97 * R, 0.3 * R),
                    (0.67 * R, 0.15 * R), (0.0, 0.05 * R)], m.segments(1.0))
    m.add("plastic", P.transform(dish, P.affine(rot, (0.0, 0.0, hub))))
    focus = rot @ np.array([0.0, 0.0, 0.75 * R]) + (0.0, 0.0, hub)
    for a in (0.0, 2.1, 4.2):
        rim = rot @ np.array([0.85 * R * np.cos(a), 0.85 * R * np.sin(a), 0.22 * R]) + (0.0, 0.0, hub)
        m.beam("metal", rim, focus, 0.02 * R + 0.004)
    m.ball("dark_plastic", focus, (0.07 * R,) * 3, fraction=0.4)


def _lattice_tower(m: Model) -> None:
    """A steel lattice tower: four tapering legs, cross bracing, arms near the top."""
    m.main = "metal"
    top = 0.82 * m.sz
    bar = m.thick(0.006 * m.sz + 0.02, 0.03 * min(m.sx, m.sy) + 0.01)
    foot, head = 0.4, 0.08
    levels = 6
    def corner(sx, sy, z):
        k = foot + (head - foot) * z / top
        return np.array([sx * k * m.sx, sy * k * m.sy, z])
    corners = ((-1, -1), (1, -1), (1, 1), (-1, 1))
    for sx, sy in corners:
        m.beam("metal", corner(sx, sy, 0), corner(sx, sy, top), bar)
    for i in range(levels):
        z0, z1 = top * i / levels, top * (i + 1) / levels
        for (ax, ay), (bx, by) in zip(corners, corners[1:] + corners[:1]):
            m.beam("metal", corner(ax, ay, z0), corner(bx, by, z1), bar * 0.6)
        ring(m, "metal", [corner(x, y, z1) for x, y in corners], bar * 0.6)
    m.beam("metal", corner(0, 0, top), (0, 0, m.sz), bar)
    for z in (0.78 * m.sz, 0.9 * m.sz):
        m.beam("metal", (-m.sx / 2, 0, z), (m.sx / 2, 0, z), 0.8 * bar)
        for s in (-1, 1):
            m.post("ceramic", s * 0.45 * m.sx, 0, z - 0.04 * m.sz, z, bar * 0.8, fraction=0.4)

def _crane(m: Model) -> None:
    """A tower crane: a lattice mast, a long jib and a short counter-jib with its weights,
    the operator's cab and a hook on its cable."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    mast = min(0.08 * m.sx, 0.8 * D, 0.06 * H)
    x0 = -W + 0.3 * m.sx
    top = 0.85 * H
    bar = 0.08 * mast + 0.01
    levels = max(4, int(top / (2 * mast + 1e-9)) // 2 * 2)
    levels = min(levels, 24)
    corners = [(x0 - mast / 2, -mast / 2), (x0 + mast / 2, -mast / 2), (x0 + mast / 2, mast / 2), (x0 - mast / 2, mast / 2)]
    for x, y in corners:
        m.beam("paint", (x, y, 0), (x, y, top), bar)
    for i in range(levels):
        z0, z1 = top * i / levels, top * (i + 1) / levels
        for (ax, ay), (bx, by) in zip(corners, corners[1:] + corners[:1]):
            m.beam("paint", (ax, ay, z0), (bx, by, z1), 0.6 * bar)
    m.box("concrete", (x0 - 1.5 * mast, -min(D, 1.5 * mast), 0), (x0 + 1.5 * mast, min(D, 1.5 * mast), 0.03 * H))
    jib_z = top + 0.02 * H
    m.beam("paint", (x0, 0, jib_z), (W, 0, jib_z), 0.6 * mast, 0.5 * mast)
    m.beam("paint", (-W + 0.05 * m.sx, 0, jib_z), (x0, 0, jib_z), 0.6 * mast, 0.5 * mast)
    m.box("concrete", (-W, -0.4 * mast, jib_z - 0.8 * mast), (-W + 0.12 * m.sx, 0.4 * mast, jib_z + 0.25 * mast))
    peak = np.array([x0, 0.0, H])
    m.beam("paint", (x0, 0, jib_z), peak, 0.45 * mast)
    m.beam("dark_metal", peak, (W - 0.02 * m.sx, 0, jib_z + 0.2 * mast), 0.1 * bar + 0.005)
    m.beam("dark_metal", peak, (-W + 0.05 * m.sx, 0, jib_z + 0.2 * mast), 0.1 * bar + 0.005)
    m.box("glass", (x0 + 0.5 * mast, -0.6 * mast, top - 1.2 * mast), (x0 + 1.5 * mast, 0.6 * mast, top - 0.1 * mast))
    hook_x = x0 + 0.6 * (W - x0)
    m.box("dark_metal", (hook_x - 0.3 * mast, -0.3 * mast, jib_z - 0.5 * mast), (hook_x + 0.3 * mast, 0.3 * mast, jib_z - 0.25 * mast))
    m.beam("dark_metal", (hook_x, 0, jib_z - 0.3 * mast), (hook_x, 0, 0.45 * H), 0.08 * bar + 0.004)
    m.torus("flower_alt", (hook_x, 0, 0.45 * H - 0.2 * mast), 0.2 * mast, 0.06 * mast, axis="y", arc=1.5 * np.pi, fraction=0.5)


def tower(m: Model) -> None:
    if m.named("crane"):
        _crane(m)
        return
    if m.named("satellite dish", "radar dish", "dish", "radio telescope"):
        _dish(m)
        return
    if m.named("pylon", "transmission tower", "radio tower", "antenna") or m.has("steel", "lattice", "service tower", "launch tower"):
        _lattice_tower(m)
        return
    if m.named("lighthouse"):
        _lighthouse(m)
        return
    if m.named("windmill"):
        _windmill(m)
        return
    if m.named("rocket"):
        _rocket(m)
        return
    m.main = "stone"
    r = 0.5
    body_top = 0.78 * m.sz
    m.lathe("stone", [(r, 0), (0.88 * r, body_top)], scale=(m.sx, m.sy))
    m.lathe("stone", [(0.92 * r, body_top), (0.98 * r, body_top + 0.03 * m.sz), (0.98 * r, body_top + 0.06 * m.sz)],
            scale=(m.sx, m.sy))
    merlons = 8
    for k in range(merlons):
        a = 2 * np.pi * (k + 0.5) / merlons
        c = (np.cos(a) * 0.43 * m.sx, np.sin(a) * 0.43 * m.sy, body_top + 0.08 * m.sz)
        m.cbox("stone", c, (0.1 * m.sx, 0.1 * m.sy, 0.04 * m.sz))
    m.lathe("roof", [(0.38, body_top + 0.04 * m.sz), (0.0, m.sz)], scale=(m.sx, m.sy))
    for z in (0.3, 0.5, 0.7):
        m.box("dark_plastic", (-0.04 * m.sx, -0.47 * m.sy, z * m.sz), (0.04 * m.sx, -0.4 * m.sy, z * m.sz + 0.07 * m.sz), rounded=0.0)
    m.box("dark_wood", (-0.12 * m.sx, -0.5 * m.sy, 0), (0.12 * m.sx, -0.4 * m.sy, 0.12 * m.sz), rounded=0.0)


def whiteboard(m: Model) -> None:
    m.main = "ceramic"
    standing = m.sz > 1.3 and m.sy > 0.2
    z0 = 0.45 * m.sz if standing else 0.0
    y = -0.02 if standing else -m.sy / 2
    d = 0.03
    m.box("metal", (-m.sx / 2, y, z0), (m.sx / 2, y + d, m.sz))
    m.box("ceramic", (-m.sx / 2 + 0.03, y - 0.003, z0 + 0.03), (m.sx / 2 - 0.03, y, m.sz - 0.03), rounded=0.0)
    m.box("metal", (-0.4 * m.sx, y - 0.06, z0 + 0.01), (0.4 * m.sx, y, z0 + 0.03))
    for i, role in enumerate(("book_a", "book_b", "dark_plastic")):  # markers side by side on the tray, not through each other
        m.cylinder(role, (-0.3 * m.sx + i * 0.05, y - 0.015 - 0.02 * i, z0 + 0.04),
                   (-0.3 * m.sx + i * 0.05 + 0.11, y - 0.015 - 0.02 * i, z0 + 0.04), 0.008, fraction=0.3)
    if standing:
        for s in (-1, 1):
            x = s * (m.sx / 2 - 0.03)
            m.box("metal", (x - 0.02, y + d, 0.05), (x + 0.02, y + d + 0.03, m.sz))
            m.box("metal", (x - 0.03, -m.sy / 2, 0.03), (x + 0.03, m.sy / 2, 0.07))
            for yy in (-m.sy / 2 + 0.03, m.sy / 2 - 0.03):
                m.ball("rubber", (x, yy, 0.03), (0.03, 0.03, 0.03), fraction=0.4)


SHAPES = {
    "building": building, "house": house, "kiosk": kiosk, "market_stall": market_stall, "tower": tower,
    "whiteboard": whiteboard,
}
