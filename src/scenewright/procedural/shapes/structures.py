"""Large open structures, upright panels and containers the catalogue does not know one by
one: a windsock, a satellite or radar dish, a ferris wheel, crane, carousel, platform, stage, scaffold, grandstand, siege engine or skate
ramp; a screen, a folding screen, a banner or a notice board; a box, trunk, suitcase, backpack, sack,
basket, cool box, cage, pen or hatbox. Fronts face −Y."""

from __future__ import annotations

import math

import numpy as np

from scenewright.core.catalogue import load_catalogue
from scenewright.procedural.builder import Model
from scenewright.procedural.shapes.buildings import _crane, _dish, _dome, _windmill, house
from scenewright.procedural.shapes.props import _basket, _chest, _creel


def _windsock(m: Model) -> None:
    """A windsock: a mast with a ring at its top and a tapering striped sock streaming from it
    to one side, drooping a little."""
    m.main = "canvas"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    pole = 0.015 * H + 0.01
    m.post("metal", -W + 2 * pole, 0, 0, H, pole, fraction=0.4)
    m.box("concrete", (-W, -2.5 * pole, 0), (-W + 4 * pole, 2.5 * pole, 0.03 * H))
    mouth = min(D, 0.09 * H)
    length = 2 * W - 3 * pole
    bands = 5
    for k in range(bands):
        t0, t1 = k / bands, (k + 1) / bands
        x0, x1 = -W + 3 * pole + t0 * length, -W + 3 * pole + t1 * length
        z0, z1 = H - mouth - 0.12 * t0 * H, H - mouth - 0.12 * t1 * H
        r0, r1 = mouth * (1 - 0.55 * t0), mouth * (1 - 0.55 * t1)
        m.cylinder("canvas" if k % 2 == 0 else "canvas_alt", (x0, 0, z0), (x1, 0, z1), r0, r1, fraction=0.6)
    m.torus("metal", (-W + 3 * pole - 0.004, 0, H - mouth), mouth, 0.12 * pole, axis="x", fraction=0.6)


def _ferris_wheel(m: Model) -> None:
    """Two rims joined by spokes and cabins, on an A-frame, over a boarding platform; the
    wheel turns in the x–z plane, facing the viewer."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    R = min(W, 0.5 * H) * 0.9
    hub = np.array([0.0, 0.0, H - R - 0.06 * H])
    bar = 0.012 * R + 0.01
    rims = (-0.45 * D, 0.45 * D)
    spokes = 16
    for y in rims:
        m.torus("paint", hub + (0, y, 0), R, 1.5 * bar, axis="y", fraction=1.0)
        m.torus("metal", hub + (0, y, 0), 0.55 * R, bar, axis="y", fraction=0.8)
        for k in range(spokes):
            a = 2 * np.pi * k / spokes
            # Spokes cross at the hub: each a hair thicker than the last, so no two share a side.
            m.beam("metal", hub + (0, y, 0), hub + (np.cos(a) * R, y, np.sin(a) * R), bar * (1 + 0.02 * k))
    m.cylinder("dark_metal", hub + (0, -0.7 * D, 0), hub + (0, 0.7 * D, 0), 0.05 * R, fraction=0.5)
    for s in (-1, 1):
        for y in (-0.75 * D, 0.75 * D):
            m.beam("dark_metal", (s * 0.6 * R, y, 0.05 * H), hub + (0, 0.93 * y, 0), 2.5 * bar)
    cabins = 8
    cabin = 0.14 * R
    roles = ("accent", "book_b", "flower_alt", "leaf")
    for k in range(cabins):
        a = 2 * np.pi * k / cabins + np.pi / cabins
        c = hub + (np.cos(a) * R, 0, np.sin(a) * R - 1.2 * cabin)
        role = roles[k % len(roles)]
        m.cbox(role, c, (1.4 * cabin, 0.7 * D, 1.2 * cabin))
        m.cbox("canvas_alt", c + (0, 0, 0.75 * cabin), (1.5 * cabin, 0.75 * D, 0.25 * cabin))
    m.box("concrete", (-0.7 * R, -D, 0), (0.7 * R, D, 0.05 * H))
    m.box("wall", (-0.25 * R, -D, 0.05 * H), (0.25 * R, -0.5 * D, 0.12 * H))


def _carousel(m: Model) -> None:
    """A carousel: round platform, centre column, striped conical canopy, horses on poles."""
    m.main = "canvas"
    H = m.sz
    deck = 0.08 * H
    eave = 0.7 * H
    m.lathe("wood", [(0.48, 0), (0.48, deck)], scale=(m.sx, m.sy))
    m.lathe("brass", [(0.08, deck), (0.08, eave)], scale=(m.sx, m.sy), fraction=0.6)
    m.lathe("canvas_alt", [(0.5, eave), (0.5, eave + 0.06 * H)], scale=(m.sx, m.sy))
    stripes = 12
    for k in range(stripes):
        a0, a1 = 2 * np.pi * k / stripes, 2 * np.pi * (k + 1) / stripes
        role = "canvas" if k % 2 else "canvas_alt"
        m.extrude(role, [(0, 0), (0.5 * np.cos(a0) * m.sx, 0.5 * np.sin(a0) * m.sy), (0.5 * np.cos(a1) * m.sx, 0.5 * np.sin(a1) * m.sy)],
                  "z", eave + 0.06 * H, eave + 0.07 * H)
        m.add(role, _cone_slice(m, a0, a1, eave + 0.06 * H, H - 0.04 * H))
    m.ball("gold", (0, 0, H - 0.03 * H), (0.03 * m.sx, 0.03 * m.sy, 0.03 * H), fraction=0.4)
    horses = 8
    for k in range(horses):
        a = 2 * np.pi * k / horses
        x, y = 0.36 * np.cos(a) * m.sx, 0.36 * np.sin(a) * m.sy
        m.post("brass", x, y, deck, eave, 0.006 * min(m.sx, m.sy) + 0.01, fraction=0.3)
        z = deck + (0.22 + 0.08 * (k % 2)) * H
        t = np.array([-np.sin(a), np.cos(a), 0.0])
        size = 0.07 * min(m.sx, m.sy)
        body = np.array([x, y, z])
        radii = np.abs(t) * 1.1 * size + (1 - np.abs(t)) * 0.4 * size
        radii[2] = 0.45 * size
        m.ball("fur_white", body, radii, fraction=0.5)
        m.ball("fur_white", body + t * 1.1 * size + (0, 0, 0.5 * size), (0.3 * size,) * 3, fraction=0.4)
        for s in (-0.7, 0.7):
            m.beam("fur_white", body + s * t * size, body + s * t * size - (0, 0, 0.9 * size), 0.12 * size)


def _cone_slice(m: Model, a0: float, a1: float, z0: float, z1: float):
    """One gore of a conical roof from angle ``a0`` to ``a1``: a triangle to the apex."""
    from scenewright.procedural import parts as P

    points = np.array([[0.5 * np.cos(a0) * m.sx, 0.5 * np.sin(a0) * m.sy, z0],
                       [0.5 * np.cos(a1) * m.sx, 0.5 * np.sin(a1) * m.sy, z0], [0.0, 0.0, z1]])
    return P.flatten(P.Part(points, np.array([[0, 1, 2], [0, 2, 1]]), np.zeros_like(points)))


#: m, the height a stage's box must pass to hold a lighting truss above its deck.
_TRUSS_FROM = 2.2


def _stage(m: Model) -> None:
    """A stage: a raised platform with steps, and when it is tall enough to have them (its box
    reaches past :data:`_TRUSS_FROM`) a backdrop and a lighting truss on posts; a low one is
    the deck alone, whose top is where what stands on it stands."""
    m.main = "dark_wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    deck = min(0.2 * H, 0.4 * D) + 0.05 if H > _TRUSS_FROM else H
    m.box("dark_wood", (-W, -D, 0), (W, D, deck))
    m.box("dark_plastic", (-W - 0.001, -D - 0.001, 0), (W + 0.001, -D + 0.01 * D, 0.97 * deck), rounded=0.0)
    steps = 3
    for k in range(steps):  # one tread each, side by side (nested blocks would share their sides)
        h = deck * (k + 1) / (steps + 1)
        y0, y1 = -D - (steps - k) * 0.06 * D, -D - (steps - k - 1) * 0.06 * D
        m.box("dark_wood", (0.55 * W, y0, 0), (0.8 * W, y1 - 0.003, h))  # (a hair apart: no shared face)
    if H <= _TRUSS_FROM:  # a valance along the front edge of the deck
        m.box("canvas", (-W - 0.002, -D - 0.004, 0.75 * deck), (W + 0.002, -D + 0.005 * D, 0.98 * deck), rounded=0.0)
        return
    m.box("canvas", (-0.95 * W, 0.85 * D, deck), (0.95 * W, D, 0.85 * H))
    post = 0.015 * m.sx + 0.03
    # Posts run from inside the deck to the middle of the truss; the side rails hang a little
    # lower than the front and back ones, so rails crossing at a corner share no face.
    for x in (-W + post, W - post):
        for y in (-0.8 * D, 0.9 * D):
            m.post("dark_metal", x, y, 0.9 * deck, H - post, post, fraction=0.4)
    for y in (-0.8 * D, 0.9 * D):
        m.beam("dark_metal", (-W, y, H - post), (W, y, H - post), 2 * post)
    for x in (-W, W):
        m.beam("dark_metal", (x, -0.8 * D, H - 1.1 * post), (x, 0.9 * D, H - 1.1 * post), 2 * post)
    for k in range(6):
        x = -0.8 * W + k * 0.32 * W
        m.cylinder("dark_plastic", (x, -0.8 * D, H - 2 * post), (x, -0.85 * D, H - 5 * post), 1.2 * post, fraction=0.4)
        m.cylinder("light", (x, -0.85 * D, H - 5 * post), (x, -0.86 * D, H - 5.3 * post), 1.1 * post, fraction=0.4)
    m.post("dark_metal", 0, -0.3 * D, deck, deck + 0.3 * (H - deck), 0.01 * m.sx + 0.005, fraction=0.3)
    m.ball("dark_metal", (0, -0.3 * D, deck + 0.3 * (H - deck)), (0.02 * m.sx + 0.01,) * 3, fraction=0.3)


def _scaffold(m: Model) -> None:
    """Scaffolding: a grid of tubes with planks on each lift and diagonal braces."""
    m.main = "metal"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    tube = 0.006 * max(m.sx, m.sz) + 0.02
    bays = max(1, min(8, int(round(m.sx / 2.0))))
    lifts = max(1, min(8, int(round(m.sz / 2.0))))
    xs = np.linspace(-W + tube, W - tube, bays + 1)
    ys = (-D + tube, D - tube)
    for x in xs:
        for y in ys:
            m.post("metal", x, y, 0.01 * H, H, tube, fraction=0.3)
            m.box("dark_wood", (x - 3 * tube, y - 2 * tube, 0), (x + 3 * tube, y + 2 * tube, 0.01 * H))
    for j in range(1, lifts + 1):
        z = H * j / lifts - tube
        # Ledgers a little thinner than the standards they cross (equal tubes share facets).
        for y in ys:
            m.cylinder("metal", (-W, y, z), (W, y, z), 0.8 * tube, fraction=0.3)
        for x in xs:
            m.cylinder("metal", (x, -D, z), (x, D, z), 0.8 * tube, fraction=0.3)
        m.box("wood", (-W + tube, -D + 2 * tube, z + tube), (W - tube, D - 2 * tube, z + tube + 0.04))
    for i in range(bays):
        m.beam("metal", (xs[i], -D + tube, 0.05 * H), (xs[i + 1], -D + tube, H - tube), 0.8 * tube)


def _climbing_frame(m: Model) -> None:
    """A playground climbing frame: a lattice of painted bars, two bays by one, rungs up its
    sides and a plank deck at half height (the catalogue's ``rest_height``: children put on it
    stand there), monkey bars along its top."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    bar = 0.02 + 0.005 * max(m.sx, m.sy)
    xs, ys = np.linspace(-W + bar, W - bar, 3), (-D + bar, D - bar)
    for x in xs:
        for y in ys:
            m.post("paint", x, y, 0.0, H, bar, fraction=0.3)
    deck = load_catalogue()["climbing_frame"].rest_height * H  # (between the rungs' ends)
    m.box("wood", (xs[0], ys[0] + bar, deck - 0.04), (xs[1], ys[1] - bar, deck), rounded=0.0)
    for k, y in enumerate(ys):  # the top rails (a hair apart in thickness, so they never share faces)
        m.cylinder("accent", (xs[0], y, H - bar), (xs[-1], y, H - bar), 0.8 * bar * (1 + 0.05 * k), fraction=0.3)
    for x in np.linspace(xs[0], xs[-1], 7)[1:-1]:  # monkey bars across
        m.cylinder("metal", (x, ys[0], H - bar), (x, ys[1], H - bar), 0.6 * bar, fraction=0.3)
    for z in np.arange(0.25, 1.0, 0.25) * H:  # rungs up both ends
        for x in (xs[0], xs[-1]):
            m.cylinder("accent", (x, ys[0], z), (x, ys[1], z), 0.7 * bar, fraction=0.3)


def _mast(m: Model) -> None:
    """A ship's mast: a tall wooden pole with two yards across it, a sail bent to each, and a
    crow's nest near the top."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    r = min(0.12, 0.06 * min(m.sx, m.sy) + 0.05)
    m.post("wood", 0, 0, 0, H, r, fraction=0.6)
    for z0, z1, span in ((0.3 * H, 0.58 * H, 0.95), (0.62 * H, 0.82 * H, 0.75)):
        m.cylinder("dark_wood", (-span * W, 0, z1), (span * W, 0, z1), 0.6 * r, fraction=0.4)  # the yard
        m.box("canvas_alt", (-0.9 * span * W, -0.6 * D, z0), (0.9 * span * W, -0.55 * D, z1 - r), rounded=0.0)
    m.cylinder("dark_wood", (0, 0, 0.88 * H), (0, 0, 0.92 * H), 3 * r, fraction=0.6)  # the crow's nest


def _truss(m: Model) -> None:
    """A generic open structure: a gantry of two lattice towers joined by a truss."""
    m.main = "metal"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    bar = 0.01 * max(m.sx, m.sz) + 0.02
    legs = min(0.25 * W, D)
    for x0 in (-W + legs, W - legs):
        corners = [(x0 - legs, -legs), (x0 + legs, -legs), (x0 + legs, legs), (x0 - legs, legs)]
        for x, y in corners:  # legs a little thinner than the chords they meet
            m.beam("metal", (x, y, 0), (x, y, H), 0.9 * bar)
        for k in range(4):
            z0, z1 = H * k / 4, H * (k + 1) / 4
            for (ax, ay), (bx, by) in zip(corners, corners[1:] + corners[:1]):
                m.beam("metal", (ax, ay, z0), (bx, by, z1), 0.6 * bar)
    for y in (-legs, legs):
        for z in (H - bar, 0.85 * H):
            m.beam("metal", (-W, y, z), (W, y, z), bar)
        for k in range(8):
            x0, x1 = -W + 2 * W * k / 8, -W + 2 * W * (k + 1) / 8
            m.beam("metal", (x0, y, 0.85 * H), (x1, y, H - bar), 0.5 * bar)
    m.box("accent", (-0.3 * W, -legs - bar, 0.86 * H), (0.3 * W, -legs, H - 2 * bar), rounded=0.0)


def _pad(m: Model) -> None:
    """A launch or landing pad: a concrete slab with a painted ring and cross, flat on top so
    what stands on it stands on the slab."""
    m.main = "concrete"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    paint = min(0.02, 0.1 * H)
    m.box("concrete", (-W, -D, 0), (W, D, H - paint), rounded=0.0)
    r, band = 0.38 * min(m.sx, m.sy), 0.03 * min(m.sx, m.sy)
    for k in range(24):  # the ring, as short straight strips
        a0, a1 = 2 * np.pi * k / 24, 2 * np.pi * (k + 1) / 24
        m.beam("yellow_paint", (r * np.cos(a0), r * np.sin(a0), H - paint / 2), (r * np.cos(a1), r * np.sin(a1), H - paint / 2),
               band, paint)
    m.box("yellow_paint", (-0.6 * r, -band / 2, H - paint), (0.6 * r, band / 2, H), rounded=0.0)
    m.box("yellow_paint", (-band / 2, -0.6 * r, H - paint), (-band / 2 + band, -band / 2, H), rounded=0.0)
    m.box("yellow_paint", (-band / 2, band / 2, H - paint), (-band / 2 + band, 0.6 * r, H), rounded=0.0)


def _platform(m: Model) -> None:
    """A raised platform, flat on top at its full height so what stands on it stands on the
    deck: of timber (said so, or taller than a step or two and not said to be masonry) a plank deck on posts and joists
    with steps up at one end; else a solid masonry platform under an overhanging coping, a
    painted line along each long edge and a ramp down at one end."""
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    run = min(0.3 * m.sx, max(1.5 * H, 0.3))
    deck_end = W - run
    masonry = m.has("stone", "brick", "concrete", "masonry", "marble")
    if m.has("wood", "wooden", "timber", "plank", "board", "boardwalk") or (H > 1.2 and not masonry):
        m.main = "wood"
        t = min(0.1, 0.3 * H)
        boards = max(3, int(m.sy / 0.25))
        width = m.sy / boards
        for k in range(boards):  # boards with a hair between them: no shared sides
            y0 = -D + k * width
            m.box("wood", (-W, y0 + 0.004, H - t), (deck_end, y0 + width - 0.004, H), rounded=0.0)
        post = min(0.08, 0.1 * min(m.sx, m.sy))
        for x in np.linspace(-W + post, deck_end - post, max(2, int((deck_end + W) / 1.5) + 1)):
            for y in (-D + post, D - post):
                m.box("dark_wood", (x - post, y - post, 0), (x + post, y + post, H - t - 0.5 * post), rounded=0.0)  # into the joist
        for y in (-D + post, D - post):  # joists under the boards, between the posts' faces
            m.box("dark_wood", (-W + 0.5 * post, y - 0.7 * post, H - t - 2 * post), (deck_end - 0.5 * post, y + 0.7 * post, H - t),
                  rounded=0.0)
        steps = max(2, int(H / 0.2))
        for k in range(steps):  # treads side by side, each as high as its step
            x0 = deck_end + k * run / steps
            m.box("wood", (x0, -0.4 * D, 0), (x0 + run / steps - 0.004, 0.4 * D, H * (steps - k) / (steps + 1)), rounded=0.0)
        return
    m.main = "concrete"
    body = "brick" if m.has("brick") else "stone" if m.has("stone", "masonry") else "concrete"
    cap = min(0.1, 0.25 * H)
    m.box(body, (-W, -D + 0.04, 0), (deck_end, D - 0.04, H - cap), rounded=0.0)
    m.box("stone", (-W, -D, H - cap), (deck_end, D, H - 0.002), rounded=0.0)
    line = min(0.1, 0.05 * m.sy)
    for y in (-D + 0.08, D - 0.08 - line):  # either edge may face the track
        m.box("yellow_paint", (-W + 0.01, y, H - 0.5 * cap), (deck_end - 0.01, y + line, H), rounded=0.0)
    m.extrude(body, [(deck_end, 0.0), (W, 0.0), (deck_end, H - cap)], "y", -D + 0.04, D - 0.04)


def _grandstand(m: Model) -> None:
    """A grandstand: rows of seats on tiers rising to the back, under a roof on posts.
    Each tier is its own slab, front to back (nested blocks would share their sides)."""
    m.main = "concrete"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    rows = max(3, min(10, int(m.sy / 0.8)))
    top = 0.55 * H
    depth = 1.8 * D / rows
    for k in range(rows):
        y0, z = -D + k * depth, top * (k + 1) / rows
        m.box("concrete", (-W, y0, 0), (W, y0 + depth, z), rounded=0.0)
        m.box("paint" if k % 2 else "accent", (-0.96 * W, y0 + 0.35 * depth, z), (0.96 * W, y0 + 0.75 * depth, z + 0.12 * top / rows * 3))
    m.box("concrete", (-W, -D + rows * depth, 0), (W, D, top + 0.05 * H), rounded=0.0)  # the back wall
    post = 0.012 * m.sx + 0.04
    for x in np.linspace(-0.97 * W, 0.97 * W, max(2, min(6, int(m.sx / 6) + 2))):
        m.post("dark_metal", x, 0.93 * D, top + 0.05 * H, 0.97 * H, post, fraction=0.4)
    m.extrude("roof", [(-0.4 * D, 0.9 * H), (0.98 * D, 0.95 * H), (0.98 * D, H), (-0.4 * D, 0.92 * H)], "x", -1.02 * W, 1.02 * W)
    for x in np.linspace(-0.8 * W, 0.8 * W, 3):
        m.beam("dark_metal", (x, 0.93 * D, 0.75 * H), (x, -0.2 * D, 0.89 * H), 0.8 * post)


def _trebuchet(m: Model) -> None:
    """A siege engine: a timber base, an A-frame on each side carrying an axle, a long
    throwing arm with a counterweight box on its short end (a catapult's arm, a cup)."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    t = 0.03 * max(m.sy, m.sz) + 0.02
    axle_z = 0.55 * H
    for x in (-0.8 * W, 0.8 * W):
        m.beam("dark_wood", (x, -D, t / 2), (x, D, t / 2), t)
        for y, w in ((-0.45 * D, 0.8 * t), (0.45 * D, 0.7 * t)):  # legs of two widths: their sides meet at the top
            m.beam("wood", (x, y, t), (x, 0.0, axle_z), w)
    for y in (-0.8 * D, 0.8 * D):
        m.beam("dark_wood", (-0.8 * W + 0.55 * t, y, 0.45 * t), (0.8 * W - 0.55 * t, y, 0.45 * t), 0.85 * t)
    m.cylinder("dark_metal", (-0.85 * W, 0, axle_z), (0.85 * W, 0, axle_z), 0.35 * t, fraction=0.5)
    if m.named("catapult", "ballista", "mangonel", "onager"):
        tip = np.array([0.0, -0.6 * D, 0.95 * H])
        m.beam("wood", (0, 0.5 * D, 0.3 * H), tip, 0.7 * t)
        m.lathe("wood", [(0.0, 0.0), (0.18 * W, 0.0), (0.22 * W, 0.08 * H), (0.18 * W, 0.08 * H), (0.0, 0.02 * H)], centre=tip)
        return
    tip, heel = np.array([0.0, -0.95 * D, H]), np.array([0.0, 0.35 * D, 0.35 * H])
    m.beam("wood", heel, tip, 0.6 * t)
    m.box("dark_wood", (-0.3 * W, heel[1] - 0.12 * D, heel[2] - 0.25 * H), (0.3 * W, heel[1] + 0.12 * D, heel[2] - 0.02 * H))
    m.box("stone", (-0.25 * W, heel[1] - 0.1 * D, heel[2] - 0.04 * H), (0.25 * W, heel[1] + 0.1 * D, heel[2] + 0.005 * H))
    m.beam("canvas_alt", tip, tip + (0, 0.05 * D, -0.3 * H), 0.15 * t)
    m.ball("canvas_alt", tip + (0, 0.05 * D, -0.3 * H), (0.4 * t,) * 3, fraction=0.4)


def _ramp(m: Model) -> None:
    """A skate ramp across the width: a curved transition up to a deck with a metal coping,
    at both ends for a half pipe. The curve is a row of thin slabs (one concave outline
    would fold)."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    both = m.named("half pipe", "halfpipe", "half-pipe")
    deck = 0.12 * W
    run = (0.4 if both else 0.8) * W
    steps = max(6, m.segments(0.5))
    for s in ((-1, 1) if both else (1,)):
        wall = s * (W - deck)
        for k in range(steps):
            a0, a1 = np.pi / 2 * k / steps, np.pi / 2 * (k + 1) / steps
            x0, x1 = wall - s * run * (1 - np.sin(a0)), wall - s * run * (1 - np.sin(a1))
            z0, z1 = H * (1 - np.cos(a0)), H * (1 - np.cos(a1))
            lo, hi = sorted((x0, x1))
            low, high = (z0, z1) if s > 0 else (z1, z0)
            m.extrude("wood", [(lo, 0.0), (hi, 0.0), (hi, high), (lo, low)], "y", -D, D)
        x0, x1 = sorted((wall, s * W))
        m.box("dark_wood", (x0, -D, 0), (x1, D, H), rounded=0.0)
        m.cylinder("metal", (wall - s * 0.01 * W, -1.01 * D, H), (wall - s * 0.01 * W, 1.01 * D, H), 0.02 * H + 0.01, fraction=0.4)
    if both:
        m.box("wood", (-W + deck + run, -D, 0), (W - deck - run, D, 0.01 * H), rounded=0.0)


def _stairs(m: Model) -> None:
    """A flight of stone steps rising to the back between two side walls; a spiral staircase's
    steps fan round a central post instead, a rail on posts at their outer ends."""
    m.main = "stone"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    if m.named("spiral staircase", "spiral stairs", "spiral stair"):
        r = min(W, D)
        steps = max(8, min(24, int(H / 0.2)))
        m.post("dark_metal", 0, 0, 0, H, 0.08 * r + 0.03, fraction=0.5)
        width = 0.6 * 1.6 * np.pi * r / steps  # most of the arc a step turns through, at its outer end
        for k in range(steps):
            a, z = 1.6 * np.pi * k / steps, H * (k + 1) / steps
            end = (r * np.cos(a), r * np.sin(a))
            m.beam("stone", (0, 0, z - 0.04 * H), (*end, z - 0.04 * H), width, 0.04 * H)
            if z + 0.3 < H:  # the rail's posts, within the box
                m.post("dark_metal", *end, z, min(z + 0.9, H), 0.015, fraction=0.4)
        return
    steps = max(4, min(20, int(H / 0.18)))
    side = min(0.12 * W, 0.25)
    for k in range(steps):  # one slab a step, front to back
        y0, z = -D + 2 * D * k / steps, H * (k + 1) / steps
        m.box("stone", (-W + side, y0, 0), (W - side, y0 + 2 * D / steps, z), rounded=0.0)
    for x0, x1 in ((-W, -W + side), (W - side, W)):  # the side walls, a slope along the steps' edge
        m.extrude("concrete", [(-D, 0), (D, 0), (D, H), (-D, 0.15 * H)], "x", x0, x1)


def structure(m: Model) -> None:
    """A large open structure; its name picks it: dome, climbing frame, ferris wheel, windmill, crane,
    carousel, platform, stage, scaffold, launch pad, grandstand, siege engine, skate ramp, staircase;
    else a truss gantry."""
    variants = (
        (("dome", "igloo", "geodesic dome", "habitat dome", "dome habitat"), _dome),
        (("climbing frame", "jungle gym", "monkey bars", "play structure"), _climbing_frame),
        (("windsock", "wind sock", "wind cone"), _windsock),
        (("satellite dish", "radar dish", "radar", "dish", "radio telescope"), _dish),
        (("ferris wheel", "big wheel", "observation wheel", "wheel"), _ferris_wheel),
        (("windmill", "wind turbine"), _windmill),
        (("crane", "tower crane", "gantry crane"), _crane),
        (("carousel", "merry-go-round", "merry go round", "roundabout"), _carousel),
        (("mast", "masts"), _mast),
        (("platform", "dais"), _platform),
        (("stage", "bandstand", "podium"), _stage),
        (("scaffold", "scaffolding"), _scaffold),
        (("launch pad", "landing pad", "helipad", "pad"), _pad),
        (("grandstand", "bleachers", "stands", "tribune", "spectator stand", "viewing stand", "royal box"), _grandstand),
        (("trebuchet", "catapult", "ballista", "mangonel", "onager", "siege engine"), _trebuchet),
        (("half pipe", "halfpipe", "half-pipe", "quarter pipe", "skate ramp", "ramp"), _ramp),
        (("staircase", "stairway", "stairs", "spiral staircase", "flight of steps"), _stairs),
    )
    for words, build in variants:
        if m.named(*words):
            build(m)
            return
    _truss(m)


#: m, the thickness at most of a panel that is a sheet: a calendar or a chart on a wall, a map on a table.
_SHEET = 0.05


def _sheet(m: Model) -> None:
    """A printed sheet on a backing board, as thin as its size says, standing (hung on a wall) or
    lying (spread on a table): no feet, which would hold it off the wall or the table."""
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.main = "paper"
    if m.sy <= m.sz:  # upright, its face toward -y
        m.box("paint", (-W, -D, 0), (W, D, H), rounded=0.0)
        m.box("paper", (-0.92 * W, -D - 0.002, 0.06 * H), (0.92 * W, -D, 0.94 * H), rounded=0.0)
        m.box("accent", (-0.8 * W, -D - 0.003, 0.7 * H), (0.8 * W, -D - 0.002, 0.85 * H), rounded=0.0)
        return
    m.box("paint", (-W, -D, 0), (W, D, H), rounded=0.0)  # lying, its face up
    m.box("paper", (-0.92 * W, -0.92 * D, H), (0.92 * W, 0.92 * D, H + 0.002), rounded=0.0)
    m.box("accent", (-0.8 * W, 0.5 * D, H + 0.002), (0.8 * W, 0.8 * D, H + 0.003), rounded=0.0)


def panel(m: Model) -> None:
    """A flat upright board: a screen on feet, a banner between poles, a notice board on
    legs, a tilted solar panel, a windsock (filed with panels as a thing that flies); else a
    painted board on two feet; a board laid flat for people to stand on (said to be a platform,
    analysis/composition/hosts.py) a platform."""
    if m.has("platform", "dais"):
        _platform(m)
        return
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    t = min(0.3 * D, 0.03 * max(m.sx, m.sz)) + 0.005
    if m.named("solar panel", "solar"):
        m.main = "screen"
        for x in (-0.8 * W, 0.8 * W):
            for y, top in ((0.6 * D, 0.9 * H), (-0.6 * D, 0.3 * H)):
                m.post("metal", x, y, 0.04 * H, top, 0.02 * W + 0.01, fraction=0.3)
                m.box("concrete", (x - 0.08 * W, y - 0.1 * D, 0), (x + 0.08 * W, y + 0.1 * D, 0.04 * H))
        m.extrude("metal", [(-D, 0.25 * H), (D, 0.92 * H), (D, H), (-D, 0.33 * H)], "x", -W, W)
        for k in range(6):
            x = -W + (k + 0.5) * 2 * W / 6
            m.extrude("screen", [(-0.95 * D, 0.34 * H), (0.95 * D, 1.0 * H), (0.95 * D, 1.005 * H), (-0.95 * D, 0.345 * H)], "x",
                      x - 0.15 * W, x + 0.15 * W)
        return
    if m.named("windsock", "wind sock", "wind cone"):
        _windsock(m)
        return
    if m.named("banner", "flag", "tapestry", "pennant"):
        m.main = "canvas"
        pole = 0.03 * W + 0.01
        for x in (-W + pole, W - pole):
            m.post("dark_wood", x, 0, 0, H, pole, fraction=0.4)
            m.ball("gold", (x, 0, H - pole), (1.5 * pole,) * 3, fraction=0.4)
        m.cylinder("dark_wood", (-W, 0, 0.95 * H), (W, 0, 0.95 * H), 0.7 * pole, fraction=0.4)
        m.extrude("canvas", [(-W + 2 * pole, 0.94 * H), (W - 2 * pole, 0.94 * H), (W - 2 * pole, 0.3 * H), (0, 0.22 * H),
                             (-W + 2 * pole, 0.3 * H)], "y", -0.5 * t, 0.5 * t)
        m.box("canvas_alt", (-0.6 * W, -0.5 * t - 0.003, 0.6 * H), (0.6 * W, -0.5 * t, 0.75 * H), rounded=0.0)
        return
    if m.named("scoreboard", "score board", "departure board", "arrivals board", "timetable", "leaderboard", "tote board"):
        _scoreboard(m)
        return
    if m.named("backdrop", "back drop", "scenery", "flat", "set piece", "cyclorama", "painted cloth"):
        _backdrop(m)
        return
    if m.sy <= _SHEET or m.sz < min(m.sx, m.sy):  # (lying: "a map on the table", "a striped awning")
        _sheet(m)
        return
    if m.named("folding screen", "room divider", "divider", "privacy screen", "shoji screen", "shoji"):
        _folding_screen(m)
        return
    board_lo = (0.35 if m.named("notice board", "bulletin board", "noticeboard", "corkboard", "cork board") else 0.25) * H
    if m.named("screen", "display", "monitor", "video wall", "projection screen", "jumbotron", "hologram", "holo"):
        m.main = "dark_plastic"
        m.box("dark_plastic", (-W, -0.2 * D, board_lo), (W, 0.4 * D, H))
        m.box("screen", (-0.95 * W, -0.2 * D - 0.005, board_lo + 0.04 * (H - board_lo)), (0.95 * W, -0.2 * D, H - 0.04 * (H - board_lo)),
              rounded=0.0)
        for x in (-0.5 * W, 0.5 * W):
            m.box("dark_metal", (x - 0.05 * W, 0.0, 0), (x + 0.05 * W, 0.3 * D, board_lo))
            m.box("dark_metal", (x - 0.08 * W, -D, 0), (x + 0.08 * W, D, 0.03 * H))
        return
    notice = board_lo > 0.3 * H
    m.main = "wood" if notice else "paint"
    frame = 0.04 * min(m.sx, H - board_lo)
    m.box("wood" if notice else "paint", (-W, -0.5 * t, board_lo), (W, 0.5 * t, H))
    m.box("fur_light" if notice else "canvas_alt", (-W + frame, -0.5 * t - 0.004, board_lo + frame), (W - frame, -0.5 * t, H - frame),
          rounded=0.0)
    if notice:
        for k in range(6):
            cx = m.vary(-0.7, 0.7) * W
            cz = board_lo + m.vary(0.2, 0.8) * (H - board_lo)
            w, h = m.vary(0.1, 0.2) * m.sx, m.vary(0.1, 0.25) * (H - board_lo)
            # Each note a millimetre proud of the one before: notes that overlap would share a face.
            front = -0.5 * t - 0.006 - 0.001 * k
            m.box(("paper", "canvas_alt", "flower_alt")[k % 3], (cx - w / 2, front, cz - h / 2), (cx + w / 2, front + 0.002, cz + h / 2),
                  rounded=0.0)
            m.ball("accent", (cx, front - 0.002, cz + 0.4 * h), (0.01 * m.sx,) * 3, fraction=0.3)
    else:
        m.box("accent", (-0.7 * W, -0.5 * t - 0.006, board_lo + 0.6 * (H - board_lo)), (0.7 * W, -0.5 * t - 0.004, board_lo + 0.8 * (H - board_lo)),
              rounded=0.0)
    leg = min(0.06 * W, 0.4 * D) + 0.01
    for x in (-0.8 * W, 0.8 * W):
        m.box("dark_wood" if notice else "dark_metal", (x - leg, -0.3 * t, 0), (x + leg, 0.5 * t + leg, board_lo + 0.1 * (H - board_lo)))
        m.box("dark_wood" if notice else "dark_metal", (x - 1.5 * leg, -D, 0), (x + 1.5 * leg, D, 0.03 * H))


def _folding_screen(m: Model) -> None:
    """A folding screen: four leaves of paper in dark wooden rails, hinged on posts and standing
    in a zigzag across the footprint (a painted one shows its colours on the paper)."""
    m.main = "paper"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    leaves, t, rail = 4, 0.012, 0.05 * H
    joints = [(-W + k * m.sx / leaves, 0.8 * D * (1 if k % 2 else -1)) for k in range(leaves + 1)]
    for a, b in zip(joints, joints[1:]):
        # (the paper's edges inside the rails and the posts, so no face of one lies on another's)
        m.extrude("paper", _strip(a, b, t / 2, 0.03), "z", 0.8 * rail, H - 0.8 * rail)
        for lo, hi in ((0.0, rail), (H - rail, H)):
            m.extrude("dark_wood", _strip(a, b, t, 0.024), "z", lo, hi)
    for x, y in joints:
        m.post("dark_wood", x, y, 0.0, H, 0.026, fraction=0.3)


def _strip(a: tuple[float, float], b: tuple[float, float], half: float, inset: float) -> list[tuple[float, float]]:
    """The counter-clockwise outline, seen from above, of a strip ``half`` either side of the line
    from ``a`` to ``b``, its ends ``inset`` short of both."""
    length = math.hypot(b[0] - a[0], b[1] - a[1])
    ux, uy = (b[0] - a[0]) / length, (b[1] - a[1]) / length
    p, q = (a[0] + ux * inset, a[1] + uy * inset), (b[0] - ux * inset, b[1] - uy * inset)
    nx, ny = -uy * half, ux * half  # the strip's left
    return [(p[0] - nx, p[1] - ny), (q[0] - nx, q[1] - ny), (q[0] + nx, q[1] + ny), (p[0] + nx, p[1] + ny)]


def _scoreboard(m: Model) -> None:
    """A scoreboard: a dark board on two posts under a little roof, rows of white number plates
    and a name band (not a billboard, whose white face and stripe read as an advert)."""
    m.main = "dark_wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    t = min(0.5 * D, 0.04 * max(m.sx, m.sz)) + 0.01
    lo, top = 0.3 * H, 0.9 * H
    front = -0.5 * t
    post = min(0.05 * W, 0.8 * D) + 0.01
    for x in (-0.85 * W, 0.85 * W):  # each post set into the board's back, below its top
        m.box("dark_wood", (x - post, 0.5 * t - 0.003, 0), (x + post, 0.5 * t + 2 * post, top - 0.01 * H))
    m.box("dark_wood", (-W, front, lo), (W, 0.5 * t, top - 0.003))
    m.extrude("roof", [(-D, top), (D, top), (D, top + 0.02 * H), (0, H), (-D, top + 0.02 * H)], "x", -1.02 * W, 1.02 * W)
    m.box("canvas_alt", (-0.8 * W, front - 0.004, top - 0.14 * (top - lo)), (0.8 * W, front + 0.002, top - 0.04 * (top - lo)),
          rounded=0.0)
    cols = 4
    ph, pw = 0.17 * (top - lo), 0.13 * m.sx
    for r in range(3):
        z = lo + (0.08 + 0.27 * r) * (top - lo)
        for c in range(cols):
            x = -0.75 * W + c * 1.5 * W / (cols - 1)
            m.box("canvas_alt", (x - pw / 2, front - 0.006, z), (x + pw / 2, front + 0.002, z + ph), rounded=0.0)
            m.box("lacquer", (x - 0.15 * pw, front - 0.008, z + 0.2 * ph), (x + 0.15 * pw, front - 0.004, z + 0.8 * ph),
                  rounded=0.0)


def _backdrop(m: Model) -> None:
    """A painted backdrop (a stage flat, scenery): a canvas in a timber frame painted with sky,
    hills and a castle's outline, braced from behind so it stands on its own."""
    m.main = "canvas_alt"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    t = min(0.3 * D, 0.02 * max(m.sx, m.sz)) + 0.01
    y0 = -D + 0.02 * m.sy  # the frame's face, toward the viewer; the braces reach back to +D
    m.box("wood", (-W, y0, 0.01 * H), (W, y0 + t, H))
    # Layers a few millimetres apart, each set into the one behind, so no two share a face.
    m.box("fabric", (-0.97 * W, y0 - 0.003, 0.45 * H), (0.97 * W, y0 + 0.002, 0.98 * H), rounded=0.0)
    hills = [(-0.96 * W, 0.03 * H), (0.96 * W, 0.03 * H), (0.96 * W, 0.5 * H), (0.5 * W, 0.62 * H), (0.0, 0.48 * H),
             (-0.45 * W, 0.6 * H), (-0.96 * W, 0.47 * H)]
    m.extrude("leaf", hills, "y", y0 - 0.005, y0 + 0.001)
    m.box("stone", (0.05 * W, y0 - 0.007, 0.5 * H), (0.55 * W, y0 - 0.004, 0.75 * H), rounded=0.0)
    for x in (0.08 * W, 0.52 * W):
        m.box("stone", (x - 0.06 * W, y0 - 0.008, 0.49 * H), (x + 0.06 * W, y0 - 0.0035, 0.86 * H), rounded=0.0)
    for x in (-0.7 * W, 0.0, 0.7 * W):
        m.beam("dark_wood", (x, y0 + t, 0.7 * H), (x, D, 0.02 * H), 0.02 * W + 0.01)
        m.box("dark_wood", (x - 0.04 * W, y0 + 0.5 * t, 0), (x + 0.04 * W, D, 0.02 * H))


def _box(m: Model) -> None:
    """A cardboard box with its flaps taped shut."""
    m.main = "fur_light"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("fur_light", (-W, -D, 0), (W, D, H), rounded=0.01 * min(m.sx, m.sy, m.sz))
    m.box("paper", (-0.12 * W, -1.005 * D, 0.7 * H), (0.12 * W, 1.005 * D, 1.003 * H), rounded=0.0)
    m.box("canvas_alt", (0.3 * W, -1.004 * D, 0.2 * H), (0.8 * W, -D, 0.45 * H), rounded=0.0)
    m.box("fur_dark", (-W, -0.01 * D, 0.997 * H), (W, 0.01 * D, 1.001 * H), rounded=0.0)


def _pet_carrier(m: Model) -> None:
    """A pet carrier: a rounded plastic shell with a wire grille door at the front and a handle on top."""
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("plastic", (-W, -D, 0), (W, D, 0.88 * H), rounded=0.15 * min(m.sx, m.sz))
    bar = 0.015 * min(m.sx, m.sz) + 0.003
    for k in range(1, 6):
        x = -0.7 * W + k * 1.4 * W / 6
        m.beam("metal", (x, -1.01 * D, 0.15 * H), (x, -1.01 * D, 0.75 * H), bar)
    for z in (0.15 * H, 0.75 * H):  # (a little further out than the bars, so no face is shared)
        m.beam("metal", (-0.7 * W, -1.01 * D - bar, z), (0.7 * W, -1.01 * D - bar, z), bar)
    m.torus("dark_plastic", (0, 0, 0.88 * H), 0.35 * W, 0.06 * W, axis="y", arc=np.pi, fraction=0.5)


def _trough(m: Model) -> None:
    """A long open trough of planks on splayed legs, water (or feed) inside."""
    m.main = "wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    wall, floor = 0.08 * min(m.sx, m.sy), 0.35 * H
    for y in (-D, D - wall):  # the long sides, then the ends and the bottom between them
        m.box("wood", (-W, y, floor), (W, y + wall, H), rounded=0.0)
    for x in (-W, W - wall):
        m.box("wood", (x, -D + wall, floor), (x + wall, D - wall, H), rounded=0.0)
    m.box("wood", (-W + wall, -D + wall, floor), (W - wall, D - wall, floor + wall), rounded=0.0)
    inside = "straw" if m.named("feeding trough", "feed trough", "hay trough") else "water"
    m.box(inside, (-W + wall, -D + wall, floor + wall), (W - wall, D - wall, 0.8 * H), rounded=0.0)
    for x in (-0.8 * W, 0.8 * W):
        for y in (-0.7 * D, 0.7 * D):
            m.post("dark_wood", x, y, 0.0, floor, 0.06 * min(m.sx, m.sy) + 0.01)


def _trunk(m: Model) -> None:
    """A travel trunk: a box with leather straps, brass corners, a lock and side handles."""
    m.main = "dark_wood"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("dark_wood", (-W, -D, 0), (W, D, H))
    m.box("dark_metal", (-1.005 * W, -1.005 * D, 0.62 * H), (1.005 * W, 1.005 * D, 0.66 * H), rounded=0.0)
    for x in (-0.5 * W, 0.5 * W):
        m.box("leather", (x - 0.07 * W, -1.01 * D, 0), (x + 0.07 * W, 1.01 * D, 1.01 * H), rounded=0.0)
    c = 0.12 * min(W, D, H)
    for x in (-W, W - c):
        for y in (-D, D - c):
            for z in (0, H - c):
                m.box("brass", (x - 0.01 * c, y - 0.01 * c, z - 0.01 * c), (x + 1.01 * c, y + 1.01 * c, z + 1.01 * c), rounded=0.0)
    m.box("brass", (-0.08 * W, -1.02 * D, 0.5 * H), (0.08 * W, -D, 0.68 * H), rounded=0.0)
    for s in (-1, 1):
        m.torus("leather", (s * W, 0, 0.6 * H), 0.15 * D, 0.03 * H, axis="x", arc=np.pi, fraction=0.4)


def _sack(m: Model) -> None:
    """A sack: a lumpy bag tied at the neck, its top flopping over."""
    m.main = "canvas_alt"
    r = 0.5
    m.lathe("canvas_alt", [(0.0, 0.0), (0.38 * r * 2, 0.02 * m.sz), (0.48 * r * 2, 0.3 * m.sz), (0.42 * r * 2, 0.65 * m.sz),
                           (0.15 * r * 2, 0.8 * m.sz), (0.1 * r * 2, 0.84 * m.sz)], scale=(m.sx, m.sy))
    m.lathe("bark", [(0.11, 0.78 * m.sz), (0.11, 0.85 * m.sz)], scale=(m.sx, m.sy), fraction=0.5)
    m.ball("canvas_alt", (0.05 * m.sx, 0, 0.9 * m.sz), (0.18 * m.sx, 0.16 * m.sy, 0.1 * m.sz), fraction=0.5)
    m.box("accent", (-0.15 * m.sx, -0.47 * m.sy, 0.3 * m.sz), (0.15 * m.sx, -0.45 * m.sy, 0.5 * m.sz), rounded=0.0)


def _backpack(m: Model) -> None:
    """A backpack standing on its base: a padded body rounded on top, a front pocket, a
    top handle and two shoulder straps down its back."""
    m.main = "fabric"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("fabric", (-W, -0.7 * D, 0), (W, 0.8 * D, 0.8 * H), rounded=0.3 * min(W, D))
    m.ball("fabric", (0, 0.05 * D, 0.78 * H), (0.98 * W, 0.74 * D, 0.2 * H), fraction=0.6)
    m.box("canvas_alt", (-0.75 * W, -D, 0.08 * H), (0.75 * W, -0.65 * D, 0.45 * H), rounded=0.25 * min(W, D))
    m.box("dark_plastic", (-0.5 * W, -0.92 * D, 0.44 * H), (0.5 * W, -0.86 * D, 0.47 * H), rounded=0.0)
    for s in (-1, 1):
        m.beam("canvas_alt", (s * 0.45 * W, 0.85 * D, 0.85 * H), (s * 0.55 * W, 0.9 * D, 0.15 * H), 0.14 * W, 0.08 * D)
    m.torus("canvas_alt", (0, 0.1 * D, 0.96 * H), 0.2 * W, 0.03 * H, axis="y", arc=np.pi, fraction=0.4)


def _suitcase(m: Model) -> None:
    """A suitcase standing upright: a hard shell with ribs, a zip seam, corner wheels and a
    pull handle."""
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    wheel = 0.05 * H
    body = 0.85 * H
    m.box("plastic", (-W, -D, wheel), (W, D, body), rounded=0.15 * min(W, D))
    m.box("dark_plastic", (-1.01 * W, -0.03 * D, wheel + 0.02 * H), (1.01 * W, 0.03 * D, body - 0.02 * H), rounded=0.0)
    for x in (-0.5 * W, 0.0, 0.5 * W):
        m.box("plastic", (x - 0.05 * W, -1.02 * D, wheel + 0.05 * H), (x + 0.05 * W, -0.9 * D, body - 0.05 * H), rounded=0.0)
    for x in (-0.75 * W, 0.75 * W):
        for y in (-0.7 * D, 0.7 * D):
            m.cylinder("rubber", (x - 0.08 * W, y, 0.5 * wheel), (x + 0.08 * W, y, 0.5 * wheel), 0.5 * wheel, fraction=0.4)
    for x in (-0.4 * W, 0.4 * W):
        m.box("metal", (x - 0.04 * W, 0.7 * D, body), (x + 0.04 * W, 0.85 * D, 0.98 * H), rounded=0.0)
    m.box("dark_plastic", (-0.5 * W, 0.65 * D, 0.97 * H), (0.5 * W, 0.9 * D, H))


def _cooler(m: Model) -> None:
    """A cool box: a plastic tub with a white lid, a drain plug and a carry handle that
    folds over the lid."""
    m.main = "paint"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.box("paint", (-W, -D, 0), (W, D, 0.78 * H), rounded=0.08 * min(W, D, H))
    m.box("plastic", (-1.02 * W, -1.02 * D, 0.78 * H), (1.02 * W, 1.02 * D, 0.9 * H), rounded=0.05 * min(W, D, H))
    m.cylinder("dark_plastic", (0.7 * W, -D, 0.1 * H), (0.7 * W, -1.04 * D, 0.1 * H), 0.05 * H, fraction=0.4)
    for s in (-1, 1):
        m.box("dark_plastic", (s * 1.0 * W - 0.04 * W, -0.3 * D, 0.6 * H), (s * 1.0 * W + 0.04 * W, 0.3 * D, 0.7 * H), rounded=0.0)
    m.torus("dark_plastic", (0, 0, 0.9 * H), 0.96 * W, 0.02 * min(W, H) + 0.005, axis="y", arc=np.pi, fraction=0.5)


def _birdcage(m: Model) -> None:
    """A bird cage: a round base, wire bars, a domed top with a hanging ring, a perch."""
    m.main = "brass"
    r = 0.5
    scale = (m.sx, m.sy)
    base = 0.08 * m.sz
    wall = 0.72 * m.sz
    m.lathe("dark_wood", [(r, 0.0), (r, base)], scale=scale, fraction=0.7)
    bar = 0.008 * min(m.sx, m.sy) + 0.002
    bars = 16
    for k in range(bars):
        a = 2 * np.pi * k / bars
        x, y = 0.47 * m.sx * np.cos(a), 0.47 * m.sy * np.sin(a)
        m.post("brass", x, y, base, wall, bar, fraction=0.3)
    for z in (0.3 * m.sz, wall):
        m.torus("brass", (0, 0, z), 0.47 * min(m.sx, m.sy), 1.5 * bar, fraction=0.7)
    dome = 0.47 * min(m.sx, m.sy)
    for axis in ("x", "y"):
        m.torus("brass", (0, 0, wall), dome, bar, axis=axis, arc=np.pi, fraction=0.5)
    m.torus("brass", (0, 0, wall + dome + 0.05 * m.sx), 0.05 * m.sx, bar, axis="x", fraction=0.4)
    m.cylinder("wood", (-0.4 * m.sx, 0, 0.4 * m.sz), (0.4 * m.sx, 0, 0.4 * m.sz), 1.5 * bar, fraction=0.3)


def _pen(m: Model) -> None:
    """An open pen: wire mesh panels on posts round a square, no top."""
    m.main = "metal"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    post = 0.01 * max(m.sx, m.sy) + 0.01
    wire = 0.4 * post
    corners = [(-W + post, -D + post), (W - post, -D + post), (W - post, D - post), (-W + post, D - post)]
    for x, y in corners:
        m.post("dark_metal", x, y, 0, H, post, fraction=0.4)
    for (ax, ay), (bx, by) in zip(corners, corners[1:] + corners[:1]):
        length = float(np.hypot(bx - ax, by - ay))
        for z in (0.05 * H, 0.5 * H, 0.97 * H):
            m.beam("metal", (ax, ay, z), (bx, by, z), wire)
        for k in range(1, max(3, int(length / 0.1))):
            t = k / max(3, int(length / 0.1))
            x, y = ax + t * (bx - ax), ay + t * (by - ay)
            m.post("metal", x, y, 0.0, 0.97 * H, 0.5 * wire, fraction=0.3)
    m.box("brass", (W - 2.5 * post, -D + 2 * post, 0.45 * H), (W - 1.5 * post, -D + 3 * post, 0.55 * H), rounded=0.0)  # the latch


def _spool(m: Model) -> None:
    """A spool or reel: thread wound on a core between two flanges, standing on one."""
    m.main = "fabric"
    flange = 0.08 * m.sz
    m.lathe("wood", [(0.5, 0.0), (0.5, flange), (0.0, flange)], scale=(m.sx, m.sy), fraction=0.8)
    m.lathe("fabric", [(0.38, flange), (0.4, 0.5 * m.sz), (0.38, m.sz - flange)], scale=(m.sx, m.sy), fraction=0.8)
    m.lathe("wood", [(0.5, m.sz - flange), (0.5, m.sz), (0.0, m.sz)], scale=(m.sx, m.sy), fraction=0.8)
    m.lathe("paper", [(0.2, m.sz), (0.2, 1.005 * m.sz), (0.0, 1.005 * m.sz)], scale=(m.sx, m.sy), fraction=0.6)


def _hatbox(m: Model) -> None:
    """A hatbox: a round box with a lid a little wider, a ribbon round it."""
    m.main = "paper"
    m.lathe("paper", [(0.0, 0.0), (0.47, 0.0), (0.47, 0.85 * m.sz), (0.0, 0.85 * m.sz)], scale=(m.sx, m.sy))
    m.lathe("canvas_alt", [(0.0, 0.8 * m.sz), (0.5, 0.8 * m.sz), (0.5, m.sz), (0.0, m.sz)], scale=(m.sx, m.sy))
    m.lathe("accent", [(0.475, 0.35 * m.sz), (0.475, 0.45 * m.sz)], scale=(m.sx, m.sy), fraction=0.7)


def _nest(m: Model) -> None:
    """A nest: a low round bowl of woven twigs, stray sticks poking out of its rim (not a box,
    which the eggs put in it made a crate of)."""
    m.main = "straw"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.lathe("straw", [(0.0, 0.25 * H), (0.3, 0.3 * H), (0.42, 0.6 * H), (0.5, 0.85 * H), (0.47, H), (0.36, 0.7 * H),
                      (0.2, 0.45 * H), (0.0, 0.42 * H)], scale=(m.sx, m.sy))
    m.lathe("dark_wood", [(0.35, 0.0), (0.45, 0.1 * H), (0.5, 0.3 * H)], scale=(m.sx, m.sy), fraction=0.6)
    for k in range(7):
        a = 2 * np.pi * k / 7 + 0.3
        r0, r1 = 0.4, 0.55
        m.beam("dark_wood", (r0 * np.cos(a) * m.sx, r0 * np.sin(a) * m.sy, 0.7 * H),
               (r1 * np.cos(a + 0.4) * m.sx, r1 * np.sin(a + 0.4) * m.sy, 0.9 * H), 0.006 + 0.02 * min(W, D) * (1 + 0.05 * k))


def container(m: Model) -> None:
    """Something that holds things: a cardboard box, a treasure chest, a travel trunk, a
    suitcase, a backpack, a sack, a basket, a cool box, a cage, a pen, a lobster pot, a
    spool, a hatbox, a nest, a dollhouse; else a box. The variant named first wins ("ice chest cooler" is a cool box)."""
    variants = (
        (("chest", "treasure", "coffer"), _chest),
        (("trunk", "footlocker"), _trunk),
        (("suitcase", "luggage", "travel case", "wheelie case"), _suitcase),
        (("backpack", "rucksack", "knapsack", "schoolbag", "school bag", "daypack"), _backpack),
        (("sack", "bag", "sandbag", "pouch"), _sack),
        (("basket", "hamper"), _basket),
        (("cooler", "cool box", "coolbox", "ice chest", "ice box"), _cooler),
        (("cage", "birdcage", "bird cage"), _birdcage),
        (("pen", "playpen", "play pen", "corral"), _pen),
        (("lobster pot", "crab pot", "creel", "fish trap"), _creel),
        (("spool", "reel", "bobbin", "cable drum"), _spool),
        (("hatbox", "hat box"), _hatbox),
        (("nest", "nests"), _nest),
        (("trough", "manger"), _trough),
        (("pet carrier", "cat carrier", "dog carrier", "carrier"), _pet_carrier),
        (("dollhouse", "dolls house", "doll house", "doll's house"), house),  # a little house with its roof
    )
    build = m.first_named(variants)
    if build is _chest:
        m.main = "wood"
    (build or _box)(m)


SHAPES = {"structure": structure, "panel": panel, "container": container}
