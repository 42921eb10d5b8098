"""Furniture: tables, seats, beds, storage, kitchen and bathroom pieces."""

from __future__ import annotations

import numpy as np

from scenewright.core.colours import COLOURS
from scenewright.procedural.builder import Model
from scenewright.procedural.shapes.machines import machine, tank
from scenewright.procedural.shapes.structures import structure


def _picnic_table(m: Model) -> None:
    """A picnic table: a plank top over the middle, a bench along each long side, both
    carried by A-frame legs at the ends and a crossbar under the benches."""
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    t = m.thick(0.04, 0.1 * H)
    seat = 0.6 * H
    leg = m.thick(0.05, 0.06 * min(m.sx, m.sy))
    m.box("wood", (-W, -0.55 * D, H - t), (W, 0.55 * D, H))
    for s in (-1, 1):
        y0, y1 = sorted((s * 0.68 * D, s * D))
        m.box("wood", (-0.95 * W, y0, seat - t), (0.95 * W, y1, seat))
    for x in (-0.7 * W, 0.7 * W):
        for s in (-1, 1):  # slanted legs with level feet; those of one A stop short of each other
            yb, yt = s * 0.9 * D, s * 0.12 * D
            m.extrude("wood", [(yb - leg / 2, 0), (yb + leg / 2, 0), (yt + leg / 2, H - t / 2), (yt - leg / 2, H - t / 2)],
                      "x", x - leg / 2, x + leg / 2)
        m.box("wood", (x - 0.35 * leg, -0.96 * D, seat - t - 0.06 * H), (x + 0.35 * leg, 0.96 * D, seat - t))


#: Words of the tables games are played on: a pool table's and a ping-pong table's.
_POOL = ("pool", "billiard", "billiards", "snooker")
_PING_PONG = ("ping pong", "ping-pong", "table tennis")


def _games_table(m: Model) -> None:
    """A pool table (green cloth in a wooden rail, a pocket at each corner and side) or a
    ping-pong table (a blue-green top with white lines and a net across, on metal legs)."""
    pool = m.named(*_POOL)
    m.main = "canvas"
    m.tints["canvas"] = COLOURS["green"] if pool else COLOURS["teal"]
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    t = m.thick(0.05, 0.2 * H)
    rail = 0.06 * min(m.sx, m.sy) if pool else 0.0
    m.box("canvas", (-W + rail, -D + rail, H - t), (W - rail, D - rail, H - 0.01), rounded=0.0)
    leg = m.thick(0.06 if pool else 0.04)
    m.legs("dark_wood" if pool else "metal", 0.08 * min(m.sx, m.sy), 0, H - t, leg, square=pool)
    if pool:
        for side in (-1, 1):  # the rails, long and short, the short ones a hair thinner
            m.box("dark_wood", (-W, side * D - (side > 0) * rail, H - t - 0.04), (W, side * D + (side < 0) * rail, H),
                  rounded=0.0)
            m.box("dark_wood", (side * W - (side > 0) * rail, -D + rail, H - t - 0.04),
                  (side * W + (side < 0) * rail, D - rail, H - 0.002), rounded=0.0)
        for x in (-W + rail, 0.0, W - rail):
            for y in (-D + rail, D - rail):
                m.cylinder("dark_plastic", (x, y, H - t + 0.003), (x, y, H - 0.005), 0.6 * rail, fraction=0.4)
        return
    # white lines a hair inside the top's edges; crossing, each a hair thicker than the last, so
    # no two share a face
    line, w, d = 0.02, W - 0.003, D - 0.003
    m.box("paper", (-line / 2, -d, H - 0.0100), (line / 2, d, H - 0.006), rounded=0.0)  # the centre line
    for side in (-1, 1):
        m.box("paper", (side * w - (side > 0) * line, -d, H - 0.0105), (side * w + (side < 0) * line, d, H - 0.007),
              rounded=0.0)
        m.box("paper", (-w + line, side * d - (side > 0) * line, H - 0.0110),
              (w - line, side * d + (side < 0) * line, H - 0.008), rounded=0.0)
    m.box("dark_plastic", (-0.005, -D - 0.05, H - 0.006), (0.005, D + 0.05, H + 0.15), rounded=0.0)  # the net


def table(m: Model) -> None:
    if m.named("picnic"):
        _picnic_table(m)
        return
    if m.named(*_POOL, *_PING_PONG):
        _games_table(m)
        return
    t = m.thick(0.04, 0.2 * m.sz)
    leg = m.thick(0.03)
    m.box("wood", (-m.sx / 2, -m.sy / 2, m.sz - t), (m.sx / 2, m.sy / 2, m.sz))
    apron = min(0.1, 0.15 * m.sz)
    inset = 0.04 * min(m.sx, m.sy)
    # The apron sits half a leg inside the legs' outer faces and the legs end inside the top,
    # so no face of one lies in a face of another (tests/test_procedural_coplanar.py).
    a = inset + 0.5 * leg
    m.box("wood", (-m.sx / 2 + a, -m.sy / 2 + a, m.sz - t - apron), (m.sx / 2 - a, m.sy / 2 - a, m.sz - t))
    m.legs("wood", inset, 0, m.sz - t / 2, leg, square=not m.has("round leg"))


def round_table(m: Model) -> None:
    if m.named("carousel", "merry-go-round", "merry go round"):
        structure(m)
        return
    t = m.thick(0.04, 0.2 * m.sz)
    m.lathe("wood", [(0.5, m.sz - t), (0.5, m.sz)], scale=(m.sx, m.sy))
    r = m.thick(0.05, 0.12 * min(m.sx, m.sy))
    m.post("wood", 0, 0, 0, m.sz - t, r)
    m.lathe("dark_wood", [(min(m.sx, m.sy) * 0.3, 0), (min(m.sx, m.sy) * 0.3, 0.03), (r, 0.06)])


def coffee_table(m: Model) -> None:
    t = m.thick(0.035, 0.25 * m.sz)
    m.box("wood", (-m.sx / 2, -m.sy / 2, m.sz - t), (m.sx / 2, m.sy / 2, m.sz))
    inset = 0.05 * min(m.sx, m.sy)
    shelf = 0.25 * m.sz
    m.box("dark_wood", (-m.sx / 2 + inset, -m.sy / 2 + inset, shelf), (m.sx / 2 - inset, m.sy / 2 - inset, shelf + t * 0.7))
    m.legs("wood", inset * 0.5, 0, m.sz - t, m.thick(0.025), square=True)


def desk(m: Model) -> None:
    t = m.thick(0.035, 0.15 * m.sz)
    top = m.sz - t
    m.box("wood", (-m.sx / 2, -m.sy / 2, top), (m.sx / 2, m.sy / 2, m.sz))
    ped = 0.32 * m.sx
    x0 = m.sx / 2 - ped
    m.box("wood", (x0, -m.sy / 2 + 0.02, 0), (m.sx / 2 - 0.01, m.sy / 2 - 0.02, top))
    drawers = 3
    h = top / drawers
    for i in range(drawers):
        z0 = i * h + 0.01
        m.box("dark_wood", (x0 + 0.015, -m.sy / 2, z0 + 0.01), (m.sx / 2 - 0.025, -m.sy / 2 + 0.02, z0 + h - 0.02))
        m.box("metal", (x0 + ped * 0.35, -m.sy / 2 - 0.015, z0 + h * 0.5), (x0 + ped * 0.6, -m.sy / 2, z0 + h * 0.5 + 0.015))
    leg = m.thick(0.025)
    for y in (-m.sy / 2 + 0.04, m.sy / 2 - 0.04):
        m.box("wood", (-m.sx / 2 + 0.02, y - leg, 0), (-m.sx / 2 + 0.02 + 2 * leg, y + leg, top))
    # The modesty panel runs from the back leg's side, not through it (their tops would coincide).
    m.box("wood", (-m.sx / 2 + 0.02 + 2 * leg, m.sy / 2 - 0.05, top * 0.35), (x0, m.sy / 2 - 0.03, top))


def _chair_frame(m: Model, seat_z: float, seat_t: float) -> None:
    """Legs end halfway up the seat board of thickness ``seat_t`` (not flush with its top)."""
    leg = m.thick(0.022, 0.12 * min(m.sx, m.sy))
    m.legs("wood", 0.02 * m.sx, 0, seat_z - seat_t / 2, leg, square=True)
    hx = m.sx / 2 - 0.02 * m.sx - leg
    yb = m.sy / 2 - leg
    for x in (-hx, hx):
        m.box("wood", (x - leg, yb - leg, seat_z), (x + leg, yb + leg, m.sz))
    m.box("wood", (-hx, yb - leg * 0.8, seat_z + 0.45 * (m.sz - seat_z)), (hx, yb + leg * 0.8, m.sz - 0.02 * m.sz))
    m.box("wood", (-hx, yb - leg * 0.6, seat_z + 0.15 * (m.sz - seat_z)), (hx, yb + leg * 0.6, seat_z + 0.25 * (m.sz - seat_z)))


def chair(m: Model) -> None:
    seat_z = min(0.46, 0.5 * m.sz)
    t = m.thick(0.04, 0.1 * m.sz)
    m.box("wood", (-m.sx / 2, -m.sy / 2, seat_z - t), (m.sx / 2, m.sy / 2, seat_z))
    m.box("cushion", (-m.sx / 2 + 0.03, -m.sy / 2 + 0.02, seat_z), (m.sx / 2 - 0.03, m.sy / 2 - 0.08, seat_z + t * 0.8))
    _chair_frame(m, seat_z, t)


def _throne(m: Model) -> None:
    """A throne: its seat where the catalogue seats a sitter (0.45 of its height, as an
    armchair's), a seat's height above a stone dais that makes up the rest, a back rising far
    above it to a pointed crest, carved arms, gilt trim and a red cushion."""
    m.main = "dark_wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    seat = 0.45 * H
    step = max(0.04 * H, seat - 0.45)
    back_t = 0.2 * m.sy
    arm = 0.14 * m.sx
    m.box("stone", (-W, -D, 0), (W, D, step / 2))
    m.box("stone", (-0.92 * W, -0.92 * D, step / 2), (0.92 * W, 0.92 * D, step))
    m.box("dark_wood", (-W + arm, -D + 0.03, step), (W - arm, D - back_t, seat - 0.06))
    m.box("paint", (-W + arm, -D + 0.04, seat - 0.06), (W - arm, D - back_t, seat))
    crest = 0.85 * H
    m.box("dark_wood", (-W + 0.5 * arm, D - back_t, step), (W - 0.5 * arm, D, crest))
    m.extrude("gold", [(-W + 0.5 * arm, crest), (W - 0.5 * arm, crest), (0.0, H)], "y", D - back_t, D)
    m.box("paint", (-W + 1.3 * arm, D - back_t - 0.02, seat + 0.05), (W - 1.3 * arm, D - back_t, crest - 0.08))
    for sgn in (-1, 1):
        x0, x1 = sorted((sgn * W, sgn * (W - arm)))
        m.box("dark_wood", (x0, -D + 0.03, step), (x1, D - back_t, seat + 0.25))
        m.ball("gold", ((x0 + x1) / 2, -D + 0.06, seat + 0.27), (0.6 * arm, 0.6 * arm, 0.6 * arm), fraction=0.5)
        m.ball("gold", (sgn * (W - 0.6 * arm), D - back_t / 2, crest + 0.02), (0.5 * arm, 0.5 * arm, 0.5 * arm), fraction=0.5)


def armchair(m: Model) -> None:
    if m.named("throne"):
        _throne(m)
        return
    m.main = "fabric"
    leg_h = 0.1 * m.sz
    arm = m.thick(0.15, 0.22 * m.sx)
    seat_z = 0.45 * m.sz
    back_t = 0.22 * m.sy
    # Base, back and arms meet face to face, never overlapping: coplanar faces of two parts
    # z-fight into a black band in Cycles (tests/test_procedural_coplanar.py).
    m.box("fabric", (-m.sx / 2 + arm, -m.sy / 2, leg_h), (m.sx / 2 - arm, m.sy / 2 - back_t, seat_z - 0.1 * m.sz))
    m.box("cushion", (-m.sx / 2 + arm, -m.sy / 2 + 0.01 * m.sy, seat_z - 0.1 * m.sz), (m.sx / 2 - arm, m.sy / 2 - back_t, seat_z))
    m.box("fabric", (-m.sx / 2, m.sy / 2 - back_t, leg_h), (m.sx / 2, m.sy / 2, m.sz))
    for s in (-1, 1):
        x0, x1 = sorted((s * m.sx / 2, s * (m.sx / 2 - arm)))
        m.box("fabric", (x0, -m.sy / 2, leg_h), (x1, m.sy / 2 - back_t, 0.68 * m.sz))
    m.legs("dark_wood", 0.04, 0, leg_h + 0.01, m.thick(0.025))


def office_chair(m: Model) -> None:
    m.main = "fabric"
    r = min(m.sx, m.sy) / 2
    caster = 0.05 * m.sz
    for k in range(5):
        a = 2 * np.pi * k / 5 - np.pi / 2
        end = np.array([np.cos(a) * (r - caster), np.sin(a) * (r - caster), caster * 1.6])
        m.beam("dark_plastic", (0, 0, caster * 1.9), end, m.thick(0.04, 0.2 * r), m.thick(0.03, 0.2 * r))
        m.ball("rubber", (end[0], end[1], caster), (caster, caster, caster), fraction=0.5)
    seat_z = 0.47 * m.sz
    m.post("chrome", 0, 0, caster * 1.5, seat_z - 0.05, m.thick(0.025, 0.1 * r))
    m.box("dark_plastic", (-0.4 * m.sx, -0.4 * m.sy, seat_z - 0.05), (0.4 * m.sx, 0.35 * m.sy, seat_z - 0.02))
    m.box("fabric", (-0.45 * m.sx, -0.45 * m.sy, seat_z - 0.02), (0.45 * m.sx, 0.38 * m.sy, seat_z + 0.06))
    back_y = 0.42 * m.sy
    m.beam("dark_plastic", (0, 0.3 * m.sy, seat_z), (0, back_y, seat_z + 0.15 * m.sz), 0.06, 0.03)
    m.box("fabric", (-0.4 * m.sx, back_y - 0.04, seat_z + 0.12 * m.sz), (0.4 * m.sx, m.sy / 2, m.sz))
    for s in (-1, 1):
        x = s * 0.44 * m.sx
        m.box("dark_plastic", (x - 0.02, -0.1 * m.sy, seat_z + 0.05), (x + 0.02, 0.0, seat_z + 0.2))
        m.box("dark_plastic", (x - 0.03, -0.3 * m.sy, seat_z + 0.2), (x + 0.03, 0.15 * m.sy, seat_z + 0.23))


def stool(m: Model) -> None:
    t = m.thick(0.04, 0.15 * m.sz)
    m.lathe("wood", [(0.5, m.sz - t), (0.5, m.sz - 0.3 * t), (0.45, m.sz)], scale=(m.sx, m.sy))
    leg = m.thick(0.02, 0.08 * min(m.sx, m.sy))
    for k in range(4):
        a = np.pi / 4 + k * np.pi / 2
        top = np.array([np.cos(a) * 0.3 * m.sx, np.sin(a) * 0.3 * m.sy, m.sz - t])
        foot = np.array([np.cos(a) * (0.5 * m.sx - leg), np.sin(a) * (0.5 * m.sy - leg), 0])
        m.cylinder("wood", foot, top, leg, leg, fraction=0.5)
    ring = 0.33 * m.sz
    m.torus("metal", (0, 0, ring), 0.39 * min(m.sx, m.sy), leg * 0.6, fraction=1.0)


def sofa(m: Model) -> None:
    m.main = "fabric"
    leg_h = 0.08 * m.sz
    arm = m.thick(0.18, 0.15 * m.sx)
    back_t = 0.22 * m.sy
    base_top = 0.4 * m.sz
    # Base, back and arms meet face to face (see armchair).
    m.box("fabric", (-m.sx / 2, -m.sy / 2, leg_h), (m.sx / 2, m.sy / 2 - back_t, base_top))
    m.box("fabric", (-m.sx / 2, m.sy / 2 - back_t, leg_h), (m.sx / 2, m.sy / 2, m.sz))
    for s in (-1, 1):
        x0, x1 = sorted((s * m.sx / 2, s * (m.sx / 2 - arm)))
        m.box("fabric", (x0, -m.sy / 2, base_top), (x1, m.sy / 2 - back_t, 0.65 * m.sz))
    inner = m.sx - 2 * arm
    count = max(1, min(4, int(round(inner / 0.7))))
    w = inner / count
    for i in range(count):
        x0 = -m.sx / 2 + arm + i * w
        m.box("cushion", (x0 + 0.01, -m.sy / 2 + 0.02, base_top), (x0 + w - 0.01, m.sy / 2 - back_t, base_top + 0.13 * m.sz))
        m.box("cushion", (x0 + 0.02, m.sy / 2 - back_t - 0.14 * m.sy, base_top + 0.13 * m.sz),
              (x0 + w - 0.02, m.sy / 2 - back_t, 0.92 * m.sz))
    m.legs("dark_wood", 0.05, 0, leg_h + 0.01, m.thick(0.025))


def bench(m: Model) -> None:
    outdoor = m.sy > 0.5 or m.has("park", "garden", "outdoor")
    seat_z = min(0.45, 0.5 * m.sz) if outdoor and m.sz > 0.6 else m.sz
    depth = m.sy * (0.7 if outdoor and m.sz > 0.6 else 1.0)
    slats = 4
    gap = 0.015
    w = (depth - gap * (slats - 1)) / slats
    t = m.thick(0.035, 0.2 * seat_z)
    for i in range(slats):
        y0 = -m.sy / 2 + i * (w + gap)
        m.box("wood", (-m.sx / 2, y0, seat_z - t), (m.sx / 2, y0 + w, seat_z))
    frame = m.thick(0.05, 0.15 * m.sx)
    for x in (-m.sx / 2 + 0.1 * m.sx, m.sx / 2 - 0.1 * m.sx - frame):
        # The legs end inside the rail, which is a little wider than they are.
        leg_top = seat_z - t - frame / 2
        m.box("dark_metal", (x, -m.sy / 2 + 0.02, 0), (x + frame, -m.sy / 2 + 0.02 + frame, leg_top))
        m.box("dark_metal", (x, depth - m.sy / 2 - frame - 0.02, 0), (x + frame, depth - m.sy / 2 - 0.02, leg_top))
        m.box("dark_metal", (x - 0.1 * frame, -m.sy / 2 + 0.01, seat_z - t - frame),
              (x + 1.1 * frame, depth - m.sy / 2 - 0.01, seat_z - t))
        if seat_z < m.sz:
            m.beam("dark_metal", (x + frame / 2, depth - m.sy / 2 - 0.05, seat_z - t), (x + frame / 2, m.sy / 2 - frame / 2, m.sz),
                   frame, frame)
    if seat_z < m.sz:
        for k in range(3):
            z0 = seat_z + 0.1 + k * (m.sz - seat_z - 0.1) / 3
            frac = (z0 - seat_z) / (m.sz - seat_z)
            y = depth - m.sy / 2 + frac * (m.sy - depth) - 0.01
            m.box("wood", (-m.sx / 2, y - 0.02, z0), (m.sx / 2, y + 0.02, z0 + (m.sz - seat_z) / 3 - 0.03))


def bed(m: Model) -> None:
    if m.named("bunk"):
        _bunk_bed(m)
        return
    m.main = "fabric"
    frame_top = 0.3 * m.sz
    head_t = 0.06 * m.sy
    # The frame runs from the footboard to the headboard, touching both: overlapping coplanar
    # faces render black in Cycles.
    m.box("wood", (-m.sx / 2, -m.sy / 2 + head_t * 0.7, 0.05 * m.sz), (m.sx / 2, m.sy / 2 - head_t, frame_top))
    m.legs("wood", 0.0, 0, 0.06 * m.sz, m.thick(0.04))
    m.box("wood", (-m.sx / 2, m.sy / 2 - head_t, 0), (m.sx / 2, m.sy / 2, m.sz))
    m.box("wood", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, -m.sy / 2 + head_t * 0.7, 0.42 * m.sz))
    mattress_top = 0.52 * m.sz
    m.box("canvas_alt", (-m.sx / 2 + 0.03, -m.sy / 2 + head_t, frame_top), (m.sx / 2 - 0.03, m.sy / 2 - head_t, mattress_top))
    m.box("fabric", (-m.sx / 2 + 0.01, -m.sy / 2 + head_t * 0.8, mattress_top - 0.12 * m.sz),
          (m.sx / 2 - 0.01, m.sy / 2 - head_t - 0.3 * m.sy, mattress_top + 0.03 * m.sz))
    pillows = 2 if m.sx > 1.2 else 1
    pw = (m.sx - 0.2) / pillows
    for i in range(pillows):
        x0 = -m.sx / 2 + 0.1 + i * pw
        m.box("cushion", (x0 + 0.03, m.sy / 2 - head_t - 0.28 * m.sy, mattress_top),
              (x0 + pw - 0.03, m.sy / 2 - head_t - 0.03, mattress_top + 0.1 * m.sz))


def _bunk_bed(m: Model) -> None:
    """Two beds one above the other on four corner posts, a guard rail along the top bunk and a
    ladder up its side at the foot."""
    m.main = "wood"
    post = m.thick(0.03, 0.05)
    for x in (-m.sx / 2 + post, m.sx / 2 - post):
        for y in (-m.sy / 2 + post, m.sy / 2 - post):
            m.box("wood", (x - post, y - post, 0), (x + post, y + post, m.sz), rounded=0.0)
    inner = (-m.sx / 2 + 2 * post, -m.sy / 2 + 2 * post)
    for deck in (0.18 * m.sz, 0.6 * m.sz):
        m.box("wood", (inner[0], inner[1], deck), (-inner[0], -inner[1], deck + 0.05 * m.sz), rounded=0.0)
        m.box("canvas_alt", (inner[0] + 0.02, inner[1] + 0.02, deck + 0.05 * m.sz),
              (-inner[0] - 0.02, -inner[1] - 0.02, deck + 0.11 * m.sz))
        m.box("cushion", (inner[0] + 0.08, m.sy / 2 - 0.35 * m.sy, deck + 0.11 * m.sz),
              (-inner[0] - 0.08, -inner[1] - 0.05, deck + 0.15 * m.sz))
    rail = 0.85 * m.sz
    m.box("wood", (-m.sx / 2 + 0.2 * post, -m.sy / 2 + 2 * post, rail), (-m.sx / 2 + 1.6 * post, m.sy / 2 - 2 * post,
                                                                          rail + 0.04 * m.sz), rounded=0.0)
    ladder_x = m.sx / 2 + 0.2 * post
    for y in (-0.42 * m.sy, -0.25 * m.sy):
        m.box("wood", (ladder_x - post, y - 0.6 * post, 0), (ladder_x, y + 0.6 * post, 0.75 * m.sz), rounded=0.0)
    for k in range(1, 5):
        z = 0.15 * k * m.sz
        m.box("wood", (ladder_x - 0.8 * post, -0.42 * m.sy, z), (ladder_x - 0.2 * post, -0.25 * m.sy, z + 0.025 * m.sz),
              rounded=0.0)


def _books_row(m: Model, x0: float, x1: float, y0: float, y1: float, z: float, height: float) -> None:
    """Books side by side; on a very long shelf they thicken so a row stays under ~40 books."""
    x = x0
    roles = ("book_a", "book_b", "book_c", "paper")
    scale = max(1.0, (x1 - x0) / 1.4)
    while x < x1 - 0.02:
        w = min(m.vary(0.02, 0.05) * scale, x1 - x)
        h = height * m.vary(0.65, 0.95)
        m.box(roles[int(m.rng.integers(4))], (x, y0 + m.vary(0, 0.03) * (y1 - y0), z), (x + w - 0.003, y1, z + h), rounded=0.0)
        x += w + (m.vary(0.05, 0.15) if m.rng.random() < 0.08 else 0.0)


def _goods_row(m: Model, x0: float, x1: float, y0: float, y1: float, z: float, height: float) -> None:
    """Odds and ends side by side with gaps between: boxes, jars and tins of different
    heights, what a shelf that is no bookshelf holds."""
    x = x0 + m.vary(0.0, 0.1)
    depth = y1 - y0
    while x < x1 - 0.06:
        w = min(m.vary(0.06, 0.18), x1 - x)
        h = height * m.vary(0.35, 0.8)
        kind = int(m.rng.integers(3))
        if kind == 0:
            m.box("paper", (x, y0 + 0.1 * depth, z), (x + w, y1 - 0.05 * depth, z + h), rounded=0.0)
        else:
            r = min(0.5 * w, 0.4 * depth)
            m.cylinder("ceramic" if kind == 1 else "metal", (x + r, (y0 + y1) / 2, z), (x + r, (y0 + y1) / 2, z + h), r, fraction=0.5)
            w = 2 * r
        x += w + m.vary(0.02, 0.12)


def _rack_frame(m: Model, role: str) -> tuple[float, float]:
    """Two end frames (a post at each corner, rails joining them at the foot and the top):
    an open rack's ends. Returns the half width inside the posts and the posts' radius."""
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = min(0.025, 0.08 * min(m.sx, m.sy)) + 0.004
    for x in (-W + r, W - r):
        for y in (-D + r, D - r):
            m.post(role, x, y, 0, H, r, fraction=0.4)
        for z in (0.06 * H, H - r):
            m.cylinder(role, (x, -D + 2 * r, z), (x, D - 2 * r, z), 0.7 * r, fraction=0.4)
    return W - 2 * r, r


def _hanging_rack(m: Model) -> None:
    """A rack things hang from (tongs, tools, weapons, coats): an open frame with a top bar of
    pegs, the things hanging from them side by side, a foot rail where long ones rest."""
    m.main = "dark_wood"
    H = m.sz
    inner, r = _rack_frame(m, "dark_wood")
    m.cylinder("dark_wood", (-inner, 0, 0.9 * H), (inner, 0, 0.9 * H), r, fraction=0.4)
    m.cylinder("dark_wood", (-inner, 0, 0.15 * H), (inner, 0, 0.15 * H), 0.8 * r, fraction=0.4)
    count = max(3, int(2 * inner / 0.12))
    long_things = m.named("weapon", "spear", "sword", "lance", "pike", "staff", "polearm", "halberd", "rifle", "musket", "bow")
    for k in range(count):
        x = -inner + (k + 0.5) * 2 * inner / count
        m.cylinder("metal", (x, -1.2 * r, 0.9 * H), (x, -2.6 * r, 0.9 * H), 0.3 * r, fraction=0.3)  # a peg
        if long_things:  # a shaft resting on the foot rail against the top bar, its blade above
            y = -2.2 * r
            m.cylinder("wood", (x, y, 0.15 * H + r), (x, y, 0.84 * H), 0.35 * r, fraction=0.3)
            m.cylinder("metal", (x, y, 0.84 * H), (x, y, 0.97 * H), 0.6 * r, 0.05 * r, fraction=0.3)
        else:  # tongs, tools: two thin arms hanging from the peg, spread toward their ends
            drop = m.vary(0.35, 0.55) * H
            for side in (-1, 1):
                m.beam("dark_metal", (x, -2.6 * r, 0.9 * H - r), (x + side * 0.025, -2.6 * r, 0.9 * H - drop), 0.5 * r)


def _bottle_rack(m: Model) -> None:
    """A wine rack: a lattice of cubbies, a bottle lying in each, its neck out."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    t = m.thick(0.02, 0.06 * m.sx)
    cols, rows = max(2, int(m.sx / 0.12)), max(2, int(m.sz / 0.12))
    for k in range(cols + 1):
        x = -W + t / 2 + k * (m.sx - t) / cols
        m.box("wood", (x - t / 2, -D, 0), (x + t / 2, D, H))
    for k in range(rows + 1):  # shelves a little inside the uprights' faces: no shared planes
        z = k * (H - t - 0.004) / rows
        m.box("dark_wood", (-W + t, -0.97 * D, z), (W - t, 0.97 * D, z + t))
    cw, ch = (m.sx - t) / cols - t, (H - t) / rows - t
    for i in range(cols):
        for j in range(rows):
            if m.rng.random() < 0.25:
                continue
            x = -W + t + i * (m.sx - t) / cols + cw / 2
            z = t + j * (H - t) / rows + ch / 2
            rb = 0.4 * min(cw, ch)
            m.cylinder("lacquer", (x, -0.9 * D, z), (x, 0.9 * D, z), rb, fraction=0.4)
            m.cylinder("dark_plastic", (x, -D - 0.05, z), (x, -0.9 * D, z), 0.35 * rb, fraction=0.3)


def _weights_rack(m: Model) -> None:
    """A dumbbell rack: a frame with two sloping rails, dumbbells lying across them."""
    m.main = "dark_metal"
    D, H = m.sy / 2, m.sz
    inner, r = _rack_frame(m, "dark_metal")
    for y0, y1, z0, z1 in ((-0.9 * D, 0.0, 0.55 * H, 0.62 * H), (0.0, 0.9 * D, 0.85 * H, 0.92 * H)):
        m.box("metal", (-inner, y0, z0), (inner, y1, z0 + 0.3 * r), rounded=0.0)
        count = max(2, int(2 * inner / 0.22))
        for k in range(count):
            x = -inner + (k + 0.5) * 2 * inner / count
            z = z0 + 0.3 * r + 0.035
            yc = (y0 + y1) / 2
            m.cylinder("chrome", (x, yc - 0.12, z), (x, yc + 0.12, z), 0.012, fraction=0.3)
            for e in (-1, 1):
                m.cylinder("rubber", (x, yc + e * 0.12, z), (x, yc + e * 0.17, z), 0.035, fraction=0.4)


def _slatted_rack(m: Model) -> None:
    """A plain rack (shoes, boots, crates, goods): an open frame with slatted levels, the top
    one flush with the frame's top so what stands on the rack stands on slats."""
    m.main = "wood"
    D, H = m.sy / 2, m.sz
    inner, r = _rack_frame(m, "dark_wood")
    levels = max(2, min(5, int(round(H / 0.4))))
    slats = max(3, int(m.sy / 0.07))
    for k in range(1, levels + 1):
        top = 0.06 * H + k * (H - 0.06 * H) / levels - (r if k == levels else 0.0)
        for j in range(slats):
            y = -D + 2 * r + (j + 0.5) * (m.sy - 4 * r) / slats
            m.box("wood", (-inner, y - 0.4 * (m.sy - 4 * r) / slats, top - 0.02), (inner, y + 0.4 * (m.sy - 4 * r) / slats, top))


#: Words of a rack things hang from, in its name or description ("a weapon rack", "a rack of tongs").
_HUNG = ("weapon", "spear", "sword", "lance", "pike", "halberd", "rifle", "musket", "tong", "tongs", "tool", "utensil",
         "ladle", "pan", "key", "hook", "coat")


def bookshelf(m: Model) -> None:
    """Shelves of books (a shelf that is no bookshelf, of odds and ends); a rack is an open frame instead: a wine rack's cubbies of bottles, a
    dumbbell rack's rails, a rack of tongs or weapons hanging from pegs, else slatted levels."""
    rack = m.first_named(((("wine rack", "bottle rack", "wine shelf"), _bottle_rack),
                          (("dumbbell", "weight", "kettlebell"), _weights_rack),
                          (("rack", "racks"), _hanging_rack if m.has(*_HUNG) else _slatted_rack)))
    if rack is not None:
        rack(m)
        return
    # Books when it is a bookshelf or the text says so; a shelf of anything else holds odds and ends.
    row = m.first_named(((("shelf", "shelves", "shelving", "shelf unit"), _goods_row),
                         (("bookshelf", "bookshelves", "bookcase", "book shelf", "book case"), _books_row)))
    row = _books_row if row is None or m.has("book", "books", "library") else row
    side = m.thick(0.025, 0.1 * m.sx)
    m.box("wood", (-m.sx / 2, -m.sy / 2, 0), (-m.sx / 2 + side, m.sy / 2, m.sz))
    m.box("wood", (m.sx / 2 - side, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, m.sz))
    m.box("dark_wood", (-m.sx / 2 + side, m.sy / 2 - 0.015, 0), (m.sx / 2 - side, m.sy / 2, m.sz))
    shelves = min(8, max(2, int(round(m.sz / 0.38))))
    pitch = (m.sz - side) / shelves
    for i in range(shelves + 1):
        z = i * pitch
        m.box("wood", (-m.sx / 2 + side, -m.sy / 2, z), (m.sx / 2 - side, m.sy / 2 - 0.015, z + side))
        if i < shelves:
            row(m, -m.sx / 2 + side, m.sx / 2 - side, -m.sy / 2 + 0.03, m.sy / 2 - 0.02, z + side, pitch - side - 0.02)


def _doors(m: Model, x0, x1, z0, z1, count: int, y: float) -> None:
    w = (x1 - x0) / count
    for i in range(count):
        a, b = x0 + i * w + 0.004, x0 + (i + 1) * w - 0.004
        m.box("wood", (a, y - 0.018, z0), (b, y, z1))
        hx = b - 0.05 if i % 2 == 0 else a + 0.05
        m.box("metal", (hx - 0.01, y - 0.04, z0 + 0.45 * (z1 - z0)), (hx + 0.01, y - 0.018, z0 + 0.45 * (z1 - z0) + min(0.15, 0.3 * (z1 - z0))))


def cabinet(m: Model) -> None:
    if m.named("washing machine", "washer", "dryer", "dishwasher", "printer", "copier", "photocopier", "server", "server rack"):
        machine(m)
        return
    if m.named("aquarium", "fish tank"):
        tank(m)
        return
    plinth = 0.06 * m.sz
    m.box("dark_wood", (-m.sx / 2 + 0.03, -m.sy / 2 + 0.03, 0), (m.sx / 2 - 0.03, m.sy / 2, plinth))
    m.box("wood", (-m.sx / 2, -m.sy / 2 + 0.02, plinth), (m.sx / 2, m.sy / 2, m.sz - 0.03))
    m.box("wood", (-m.sx / 2, -m.sy / 2, m.sz - 0.03), (m.sx / 2, m.sy / 2, m.sz))
    _doors(m, -m.sx / 2 + 0.02, m.sx / 2 - 0.02, plinth + 0.02, m.sz - 0.05, 2 if m.sx > 0.6 else 1, -m.sy / 2 + 0.02)


def fireplace(m: Model) -> None:
    """A brick fireplace: a stone hearth slab in front, a surround with a dark firebox, logs
    burning in it and a wooden mantel shelf; by its name a cast-iron wood stove."""
    if m.named("wood stove", "woodstove", "stove"):
        _wood_stove(m)
        return
    m.main = "brick"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    shelf, hearth = 0.08 * H, 0.05 * H
    front, back = -0.55 * D, 0.5 * D  # the surround's face, the firebox's back wall
    box_w, box_top = 0.55 * W, hearth + 0.55 * (H - shelf - hearth)
    m.box("stone", (-W, -D, 0), (W, D, hearth))
    m.box("brick", (-0.92 * W, back, hearth), (0.92 * W, D, H - shelf))  # the chimney breast behind
    for x0, x1 in ((-0.92 * W, -box_w), (box_w, 0.92 * W)):
        m.box("brick", (x0, front, hearth), (x1, back, H - shelf))
    m.box("brick", (-box_w, front, box_top), (box_w, back, H - shelf))
    m.box("dark_metal", (-box_w, back - 0.02, hearth), (box_w, back, box_top), rounded=0.0)  # sooted back
    m.box("dark_wood", (-W, -0.75 * D, H - shelf), (W, D, H))
    for k in (-1, 1):
        m.cylinder("bark", (-0.6 * box_w, 0.1 * k * D, hearth + 0.05), (0.6 * box_w, -0.1 * k * D, hearth + 0.05),
                   0.04, fraction=0.5)  # fmt: skip
    m.lathe("flame", [(0.3 * box_w, 0.0), (0.18 * box_w, 0.4 * (box_top - hearth)), (0.0, 0.75 * (box_top - hearth))],
            centre=(0.0, 0.0, hearth + 0.06), scale=(1.0, 0.45), fraction=0.5)  # fmt: skip


def _wood_stove(m: Model) -> None:
    m.main, m.kind_words = "dark_metal", ("wood", "woodstove")
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    body = 0.55 * H
    m.legs("dark_metal", 0.03, 0, 0.12 * H, 0.025, square=True)
    m.box("dark_metal", (-W, -D, 0.12 * H), (W, D, body))
    m.box("glass", (-0.6 * W, -D - 0.01, 0.2 * H), (0.6 * W, -D, body - 0.08 * H), rounded=0.0)
    m.box("flame", (-0.45 * W, -D + 0.01, 0.22 * H), (0.45 * W, -D + 0.02, 0.38 * H), rounded=0.0)
    m.cylinder("dark_metal", (0, 0.3 * D, body), (0, 0.3 * D, H), min(0.08, 0.3 * W))


def wardrobe(m: Model) -> None:
    m.box("wood", (-m.sx / 2 + 0.01, -m.sy / 2 + 0.03, 0.05), (m.sx / 2 - 0.01, m.sy / 2, m.sz - 0.06))
    m.box("dark_wood", (-m.sx / 2 + 0.03, -m.sy / 2 + 0.05, 0), (m.sx / 2 - 0.03, m.sy / 2 - 0.02, 0.05))
    m.box("dark_wood", (-m.sx / 2, -m.sy / 2, m.sz - 0.06), (m.sx / 2, m.sy / 2, m.sz))
    _doors(m, -m.sx / 2 + 0.02, m.sx / 2 - 0.02, 0.08, m.sz - 0.09, 3 if m.sx > 1.5 else 2, -m.sy / 2 + 0.03)


def nightstand(m: Model) -> None:
    leg_h = 0.12 * m.sz
    m.legs("wood", 0.01, 0, leg_h, m.thick(0.018), square=True)
    m.box("wood", (-m.sx / 2, -m.sy / 2 + 0.02, leg_h), (m.sx / 2, m.sy / 2, m.sz))
    h = (m.sz - leg_h - 0.04) / 2
    for i in range(2):
        z0 = leg_h + 0.02 + i * h
        m.box("dark_wood", (-m.sx / 2 + 0.02, -m.sy / 2, z0 + 0.01), (m.sx / 2 - 0.02, -m.sy / 2 + 0.02, z0 + h - 0.01))
        m.ball("brass", (0, -m.sy / 2 - 0.005, z0 + h / 2), (0.015, 0.015, 0.015), fraction=0.4)


def _display_case(m: Model) -> None:
    """A display case: a wooden cabinet with a glass case on top, things on show inside, a
    flat wooden rim round the glass top (what stands on it stands on the glass)."""
    m.main = "glass"  # "a glass display case" describes the case, not its cabinet
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    base = 0.55 * H
    m.box("wood", (-W, -D, 0), (W, D, base))
    _doors(m, -W + 0.03, W - 0.03, 0.05 * H, base - 0.05 * H, min(8, max(1, int(round(m.sx / 0.6)))), -D)
    m.box("glass", (-0.97 * W, -0.95 * D, base), (0.97 * W, 0.95 * D, 0.99 * H), rounded=0.0)
    m.box("dark_wood", (-W, -D, 0.99 * H), (W, D, H), rounded=0.0)
    for k, x in enumerate(np.linspace(-0.6 * W, 0.6 * W, 4)):
        m.ball(("gold", "crystal")[k % 2], (x, 0, base + 0.06 * H), (0.1 * W, 0.25 * D, 0.06 * H), fraction=0.4)


def counter(m: Model) -> None:
    if m.named("control panel", "console", "terminal", "control desk", "control console"):
        machine(m)
        return
    if m.named("display case", "display cabinet", "glass case", "vitrine", "showcase", "glass cabinet", "jewelry case"):
        _display_case(m)
        return
    top_t = m.thick(0.04, 0.08 * m.sz)
    m.box("dark_wood", (-m.sx / 2 + 0.02, -m.sy / 2 + 0.08, 0), (m.sx / 2 - 0.02, m.sy / 2, 0.1))
    m.box("wood", (-m.sx / 2 + 0.02, -m.sy / 2 + 0.04, 0.1), (m.sx / 2 - 0.02, m.sy / 2, m.sz - top_t))
    m.box("marble", (-m.sx / 2, -m.sy / 2, m.sz - top_t), (m.sx / 2, m.sy / 2, m.sz))
    _doors(m, -m.sx / 2 + 0.03, m.sx / 2 - 0.03, 0.12, m.sz - top_t - 0.02, min(12, max(1, int(round(m.sx / 0.5)))),
           -m.sy / 2 + 0.04)


def bathtub(m: Model) -> None:
    m.main = "ceramic"
    wall = m.thick(0.07, 0.2 * min(m.sx, m.sy))
    feet = m.has("claw", "vintage", "victorian") or m.style.name == "steampunk"
    z0 = 0.12 * m.sz if feet else 0.0
    # Floor and walls butt edge to edge (the end walls run between the side walls), never
    # overlapping: overlapping boxes share their top and outer faces.
    m.box("ceramic", (-m.sx / 2 + wall, -m.sy / 2 + wall, z0), (m.sx / 2 - wall, m.sy / 2 - wall, z0 + 0.12 * m.sz))
    for lo, hi in (((-m.sx / 2, -m.sy / 2), (-m.sx / 2 + wall, m.sy / 2)), ((m.sx / 2 - wall, -m.sy / 2), (m.sx / 2, m.sy / 2)),
                   ((-m.sx / 2 + wall, -m.sy / 2), (m.sx / 2 - wall, -m.sy / 2 + wall)),
                   ((-m.sx / 2 + wall, m.sy / 2 - wall), (m.sx / 2 - wall, m.sy / 2))):
        m.box("ceramic", (*lo, z0), (*hi, m.sz))
    m.box("water", (-m.sx / 2 + wall, -m.sy / 2 + wall, z0 + 0.12 * m.sz), (m.sx / 2 - wall, m.sy / 2 - wall, 0.7 * m.sz), rounded=0.0)
    if feet:
        m.legs("brass", 0.08, 0, z0 + 0.02, m.thick(0.04))
    m.post("chrome", 0, m.sy / 2 - wall / 2, m.sz, m.sz + 0.01, 0.02)
    m.beam("chrome", (0, m.sy / 2 - wall / 2, m.sz - 0.01), (0, m.sy / 2 - wall - 0.08, m.sz - 0.01), 0.03, 0.03)


def toilet(m: Model) -> None:
    m.main = "ceramic"
    tank_d = 0.25 * m.sy
    seat_z = 0.55 * m.sz
    bowl_y = -m.sy / 2 + 0.38 * (m.sy - tank_d)
    r = min(m.sx / 2, 0.38 * (m.sy - tank_d))
    h = seat_z - 0.03
    m.lathe("ceramic", [(0.55, 0), (0.5, 0.3 * h), (0.75, 0.85 * h), (1.0, h)], centre=(0, bowl_y, 0), scale=(r * 0.95, r * 1.1))
    m.torus("plastic", (0, bowl_y, seat_z - 0.02), r * 0.8, 0.025)
    m.box("ceramic", (-0.45 * m.sx, -m.sy / 2 + (m.sy - tank_d) * 0.75, 0), (0.45 * m.sx, m.sy / 2 - tank_d * 0.6, seat_z))
    m.box("ceramic", (-m.sx / 2, m.sy / 2 - tank_d, seat_z), (m.sx / 2, m.sy / 2, m.sz - 0.03))
    m.box("ceramic", (-m.sx / 2 - 0.005, m.sy / 2 - tank_d - 0.01, m.sz - 0.03), (m.sx / 2 + 0.005, m.sy / 2, m.sz))
    m.box("chrome", (0.25 * m.sx, m.sy / 2 - tank_d - 0.02, m.sz - 0.1), (0.38 * m.sx, m.sy / 2 - tank_d, m.sz - 0.08))


def sink(m: Model) -> None:
    m.main = "ceramic"
    basin_h = min(0.2, 0.3 * m.sz)
    top = m.sz - 0.12 * m.sz if m.sz > 0.5 else m.sz - 0.25 * m.sz
    if m.sz > 0.5:
        m.box("wood", (-m.sx / 2 + 0.02, -m.sy / 2 + 0.03, 0), (m.sx / 2 - 0.02, m.sy / 2, top - basin_h))
        _doors(m, -m.sx / 2 + 0.03, m.sx / 2 - 0.03, 0.05, top - basin_h - 0.03, 2, -m.sy / 2 + 0.03)
    m.box("ceramic", (-m.sx / 2, -m.sy / 2, top - basin_h), (m.sx / 2, m.sy / 2, top))
    m.lathe("water", [(0.5, top), (0.45, top + 0.002)], centre=(0, -0.05 * m.sy, 0), scale=(0.7 * m.sx, 0.6 * m.sy))
    fy = m.sy / 2 - 0.08 * m.sy
    m.post("chrome", 0, fy, top, m.sz, 0.02)
    m.beam("chrome", (0, fy, m.sz - 0.02), (0, fy - 0.25 * m.sy, m.sz - 0.02), 0.025)
    for x in (-0.12, 0.12):
        m.post("chrome", x * m.sx, fy, top, top + 0.05, 0.02)


def stove(m: Model) -> None:
    if m.named("wood burner", "woodburner") or m.has("pot-bellied", "potbelly", "cast-iron", "iron", "wood-burning"):
        _wood_stove(m)  # a stove that heats a room, not a kitchen range
        return
    m.main = "metal"
    back = min(0.15, 0.15 * m.sz)
    top = m.sz - back
    m.box("metal", (-m.sx / 2, -m.sy / 2, 0), (m.sx / 2, m.sy / 2, top))
    m.box("metal", (-m.sx / 2, m.sy / 2 - 0.06, top), (m.sx / 2, m.sy / 2, m.sz))
    m.box("dark_plastic", (-m.sx / 2 + 0.02, -m.sy / 2 + 0.02, top), (m.sx / 2 - 0.02, m.sy / 2 - 0.07, top + 0.01), rounded=0.0)
    for ix in (-1, 1):
        for iy in (-1, 1):
            c = (ix * m.sx / 4, iy * (m.sy - 0.1) / 4 - 0.03, top + 0.012)
            m.torus("dark_metal", c, 0.07 * min(m.sx, m.sy) + 0.02, 0.01)
    m.box("glass", (-m.sx / 2 + 0.08, -m.sy / 2 - 0.01, 0.15 * top), (m.sx / 2 - 0.08, -m.sy / 2, 0.65 * top), rounded=0.0)
    m.beam("chrome", (-m.sx / 2 + 0.1, -m.sy / 2 - 0.04, 0.72 * top), (m.sx / 2 - 0.1, -m.sy / 2 - 0.04, 0.72 * top), 0.02)
    for i in range(4):
        x = -m.sx / 2 + (i + 0.5) * m.sx / 4
        m.cylinder("dark_plastic", (x, -m.sy / 2, 0.87 * top), (x, -m.sy / 2 - 0.03, 0.87 * top), 0.022, fraction=0.5)
    m.box("screen", (-0.15 * m.sx, m.sy / 2 - 0.065, top + 0.04), (0.15 * m.sx, m.sy / 2 - 0.06, m.sz - 0.03), rounded=0.0)


def _vending_machine(m: Model) -> None:
    m.main = "paint"
    m.box("paint", (-m.sx / 2, -m.sy / 2 + 0.02, 0), (m.sx / 2, m.sy / 2, m.sz))
    m.box("glass", (-0.45 * m.sx, -m.sy / 2, 0.3 * m.sz), (0.18 * m.sx, -m.sy / 2 + 0.02, 0.92 * m.sz), rounded=0.0)
    rows, cols = 5, 4
    for r in range(rows):
        for c in range(cols):
            x = -0.42 * m.sx + (c + 0.5) * 0.57 * m.sx / cols
            z = 0.33 * m.sz + (r + 0.3) * 0.58 * m.sz / rows
            role = ("book_a", "book_b", "book_c", "flower_alt")[(r + c) % 4]
            m.box(role, (x - 0.04 * m.sx, -m.sy / 2 + 0.04, z), (x + 0.04 * m.sx, -m.sy / 2 + 0.2 * m.sy, z + 0.06 * m.sz), rounded=0.0)
    m.box("screen", (0.24 * m.sx, -m.sy / 2 + 0.01, 0.6 * m.sz), (0.44 * m.sx, -m.sy / 2 + 0.02, 0.75 * m.sz), rounded=0.0)
    m.box("dark_plastic", (-0.4 * m.sx, -m.sy / 2 + 0.005, 0.08 * m.sz), (0.1 * m.sx, -m.sy / 2 + 0.02, 0.2 * m.sz), rounded=0.0)
    m.box("light", (-m.sx / 2 + 0.02, -m.sy / 2 + 0.005, 0.94 * m.sz), (m.sx / 2 - 0.02, -m.sy / 2 + 0.02, 0.98 * m.sz), rounded=0.0)

def _water_cooler(m: Model) -> None:
    """A water cooler: a cabinet with two taps over a drip tray, a blue bottle upside down on top."""
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    body = 0.68 * H
    m.box("plastic", (-W, -D, 0), (W, D, body))
    m.box("dark_plastic", (-0.6 * W, -1.02 * D, 0.35 * body), (0.6 * W, -D, 0.4 * body), rounded=0.0)
    for x, role in ((-0.3 * W, "accent"), (0.3 * W, "book_b")):
        m.box(role, (x - 0.08 * W, -1.1 * D, 0.62 * body), (x + 0.08 * W, -D, 0.7 * body), rounded=0.0)
    m.lathe("glass", [(0.08, body), (0.08, body + 0.04 * H), (0.42, body + 0.1 * H), (0.42, 0.96 * H), (0.3, H), (0.0, H)],
            scale=(m.sx, m.sy))


def _fuel_pump(m: Model) -> None:
    """A fuel pump: a painted column on an island kerb, a lit price panel at the front, a lamp box
    on top and a nozzle holstered on each side with its hose hanging in a loop."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    # (parts overlap a little instead of meeting face to face: tests/test_procedural_coplanar.py)
    m.box("concrete", (-W, -D, 0), (W, D, 0.06 * H))
    m.box("paint", (-0.8 * W, -0.7 * D, 0.05 * H), (0.8 * W, 0.7 * D, 0.83 * H))
    m.box("screen", (-0.55 * W, -0.73 * D, 0.5 * H), (0.55 * W, -0.69 * D, 0.7 * H), rounded=0.0)
    m.box("plastic", (-W, -0.8 * D, 0.84 * H), (W, 0.8 * D, H))
    m.box("paint", (-0.98 * W, -0.82 * D, 0.82 * H), (0.98 * W, 0.82 * D, 0.85 * H), rounded=0.0)
    for x in (-1, 1):
        m.box("dark_plastic", (x * 0.78 * W, -0.25 * D, 0.38 * H), (x * 0.95 * W, 0.1 * D, 0.5 * H), rounded=0.0)
        m.torus("dark_plastic", (x * 0.9 * W, -0.1 * D, 0.3 * H), 0.1 * H, 0.012, axis="x", arc=np.pi)


def fridge(m: Model) -> None:
    if m.named("fuel pump", "gas pump", "petrol pump", "fuel pumps", "gas pumps", "petrol pumps", "fuel dispenser"):
        _fuel_pump(m)
        return
    if m.named("vending machine", "arcade", "atm"):
        _vending_machine(m)
        return
    if m.named("water cooler", "water dispenser"):
        _water_cooler(m)
        return
    m.main = "metal"
    m.box("metal", (-m.sx / 2, -m.sy / 2 + 0.04, 0), (m.sx / 2, m.sy / 2, m.sz))
    split = 0.68 * m.sz
    m.box("metal", (-m.sx / 2 + 0.005, -m.sy / 2 + 0.01, 0.05), (m.sx / 2 - 0.005, -m.sy / 2 + 0.045, split - 0.01))
    m.box("metal", (-m.sx / 2 + 0.005, -m.sy / 2 + 0.01, split + 0.01), (m.sx / 2 - 0.005, -m.sy / 2 + 0.045, m.sz - 0.02))
    x = m.sx / 2 - 0.08
    m.beam("chrome", (x, -m.sy / 2 + 0.02, split - 0.45 * split), (x, -m.sy / 2 + 0.02, split - 0.1), 0.025, 0.04)
    m.beam("chrome", (x, -m.sy / 2 + 0.02, split + 0.05), (x, -m.sy / 2 + 0.02, split + 0.22 * (m.sz - split) + 0.1), 0.025, 0.04)
    m.box("dark_plastic", (-m.sx / 2 + 0.03, -m.sy / 2 + 0.05, 0), (m.sx / 2 - 0.03, m.sy / 2 - 0.01, 0.05))


def piano(m: Model) -> None:
    m.main = "lacquer"
    key_y = -m.sy / 2 + 0.3 * m.sy
    key_z = 0.55 * m.sz
    m.box("lacquer", (-m.sx / 2, key_y, 0.05 * m.sz), (m.sx / 2, m.sy / 2, m.sz))
    m.box("lacquer", (-m.sx / 2, -m.sy / 2, key_z - 0.04), (-m.sx / 2 + 0.05, key_y, key_z + 0.08))
    m.box("lacquer", (m.sx / 2 - 0.05, -m.sy / 2, key_z - 0.04), (m.sx / 2, key_y, key_z + 0.08))
    m.box("lacquer", (-m.sx / 2 + 0.05, -m.sy / 2 + 0.02, key_z - 0.05), (m.sx / 2 - 0.05, key_y, key_z - 0.01))
    m.box("ceramic", (-m.sx / 2 + 0.05, -m.sy / 2 + 0.02, key_z - 0.01), (m.sx / 2 - 0.05, key_y, key_z + 0.015), rounded=0.0)
    octave = (m.sx - 0.1) / 7
    for o in range(7):
        for k in (0.1, 0.25, 0.52, 0.66, 0.8):
            x = -m.sx / 2 + 0.05 + (o + k) * octave
            m.box("lacquer", (x, -m.sy / 2 + 0.1 * m.sy, key_z + 0.015), (x + 0.08 * octave, key_y, key_z + 0.03), rounded=0.0)
    for x in (-m.sx / 2 + 0.06, m.sx / 2 - 0.1):
        m.box("lacquer", (x, -m.sy / 2 + 0.02, 0), (x + 0.04, -m.sy / 2 + 0.08, key_z - 0.05))
    m.box("brass", (-0.1 * m.sx, key_y - 0.1, 0.04 * m.sz), (0.1 * m.sx, key_y - 0.02, 0.07 * m.sz))
    m.box("lacquer", (-m.sx / 2, key_y - 0.02, 0), (m.sx / 2, m.sy / 2, 0.05 * m.sz))


SHAPES = {
    "table": table, "round_table": round_table, "coffee_table": coffee_table, "desk": desk, "chair": chair,
    "armchair": armchair, "office_chair": office_chair, "stool": stool, "sofa": sofa, "bench": bench, "bed": bed,
    "bookshelf": bookshelf, "cabinet": cabinet, "fireplace": fireplace, "wardrobe": wardrobe, "nightstand": nightstand, "counter": counter,
    "bathtub": bathtub, "toilet": toilet, "sink": sink, "stove": stove, "fridge": fridge, "piano": piano,
}
