"""Vehicles: their length runs along y, the front toward −Y."""

from __future__ import annotations

import re

import numpy as np

from scenewright.core.colours import COLOURS
from scenewright.core.vessels import PLANKS, PLANT_HULL, floor_share, has_sail, hull_share, is_open
from scenewright.procedural import parts as P
from scenewright.procedural.builder import Model
from scenewright.procedural.shapes.frames import ring


def _wheel(m: Model, x: float, y: float, r: float, width: float, outward: int) -> None:
    """A tyre on the x axis with its hub on the outer face."""
    x0, x1 = sorted((x, x - outward * width))
    m.cylinder("rubber", (x0, y, r), (x1, y, r), r, fraction=0.8)
    face = max(x0, x1) if outward > 0 else min(x0, x1)
    m.cylinder("metal", (face, y, r), (face + outward * 0.01, y, r), 0.55 * r, fraction=0.6)


#: Vehicles whose trade fixes their colour, by their words; the first found paints them.
_LIVERIES = (
    (("fire engine", "fire truck", "fire tender", "mail van", "post van", "postal"), "red"),
    (("taxi", "school bus", "taxicab"), "yellow"),
    (("police", "ambulance", "ice cream"), "white"),
    (("army", "military"), "olive"),
)
#: Colours cars, vans and buses come in: one per vehicle (seeded by its id), so a car park is
#: not a row of one red.
_PAINTS = ("white", "silver", "black", "charcoal", "navy", "blue", "maroon", "red", "green", "beige")


def _livery(m: Model) -> None:
    """Paint is the main role; its colour by the vehicle's trade, else one of :data:`_PAINTS`
    (a colour the text names still wins: it is described)."""
    m.main = "paint"
    name = next((colour for words, colour in _LIVERIES if m.has(*words)), None)
    m.tints["paint"] = COLOURS[name or _PAINTS[int(m.rng.integers(len(_PAINTS)))]]


def car(m: Model) -> None:
    _livery(m)
    wr = min(0.2 * m.sz, 0.11 * m.sy)
    body_lo, body_hi = 0.35 * wr, 0.55 * m.sz
    L = m.sy / 2
    side = [(-L, body_lo + 0.1 * m.sz), (-L + 0.04 * m.sy, body_lo), (L - 0.04 * m.sy, body_lo), (L, body_lo + 0.1 * m.sz),
            (L, body_hi - 0.05 * m.sz), (L - 0.05 * m.sy, body_hi), (-L + 0.08 * m.sy, body_hi), (-L, body_hi - 0.1 * m.sz)]
    tw = 0.03 * m.sx
    m.extrude("paint", side, "x", -m.sx / 2 + tw, m.sx / 2 - tw)
    # The glass ends halfway up the roof, which is a little wider than it: their tops and
    # ends would otherwise lie in one plane (tests/test_procedural_coplanar.py).
    f = (0.98 * m.sz - body_hi) / (m.sz - body_hi)
    cabin = [(-L + 0.3 * m.sy, body_hi), (L - 0.12 * m.sy, body_hi), (L - (0.12 + 0.08 * f) * m.sy, 0.98 * m.sz),
             (-L + (0.3 + 0.15 * f) * m.sy, 0.98 * m.sz)]
    m.extrude("glass", cabin, "x", -m.sx / 2 + 0.08 * m.sx, m.sx / 2 - 0.08 * m.sx)
    roof = [(-L + 0.44 * m.sy, m.sz - 0.04 * m.sz), (L - 0.21 * m.sy, m.sz - 0.04 * m.sz), (L - 0.2 * m.sy, m.sz),
            (-L + 0.45 * m.sy, m.sz)]
    m.extrude("paint", roof, "x", -m.sx / 2 + 0.07 * m.sx, m.sx / 2 - 0.07 * m.sx)
    for y in (-L + 0.2 * m.sy, L - 0.2 * m.sy):
        for s in (-1, 1):
            _wheel(m, s * m.sx / 2, y, wr, 0.13 * m.sx, s)
    for s in (-1, 1):
        m.box("light", (s * 0.38 * m.sx - 0.08 * m.sx, -L - 0.005, body_hi - 0.15 * m.sz),
              (s * 0.38 * m.sx + 0.08 * m.sx, -L + 0.01, body_hi - 0.08 * m.sz), rounded=0.0)
        m.box("accent", (s * 0.38 * m.sx - 0.08 * m.sx, L - 0.01, body_hi - 0.14 * m.sz),
              (s * 0.38 * m.sx + 0.08 * m.sx, L + 0.005, body_hi - 0.08 * m.sz), rounded=0.0)
    m.box("dark_plastic", (-0.45 * m.sx, -L - 0.01, body_lo + 0.02), (0.45 * m.sx, -L + 0.02, body_lo + 0.08 * m.sz))


def truck(m: Model) -> None:
    if m.named("tractor", "bulldozer", "harvester", "forklift", "golf cart"):
        vehicle(m)
        return
    food = m.named("food truck", "ice cream truck", "ice cream van", "food van")
    roof = 0.72 * m.sz if m.named("ice cream") else m.sz
    _livery(m)
    wr = min(0.17 * m.sz, 0.07 * m.sy)
    chassis = 1.2 * wr
    L = m.sy / 2
    cab_len = 0.28 * m.sy
    m.box("dark_metal", (-0.4 * m.sx, -L + 0.05 * m.sy, 0.5 * wr), (0.4 * m.sx, L - 0.02 * m.sy, chassis))
    m.box("paint", (-m.sx / 2 + 0.1 * m.sx * 0.3, -L, chassis), (m.sx / 2 - 0.03 * m.sx, -L + cab_len, 0.75 * m.sz))
    # the windows stand a hair proud of the cab's box, so the windscreen and the side windows show
    m.extrude("glass", [(-L - 0.01, 0.5 * m.sz), (-L + cab_len * 0.9, 0.5 * m.sz), (-L + cab_len * 0.9, 0.72 * m.sz),
                        (-L - 0.01, 0.72 * m.sz)], "x", -m.sx / 2 + 0.025 * m.sx, m.sx / 2 - 0.025 * m.sx)
    y0 = -L + cab_len + 0.04 * m.sy
    if m.named("pickup", "pick-up", "ute"):  # an open bed with low sides: what rides in the back shows
        m.box("paint", (-m.sx / 2 + 0.02 * m.sx, y0, chassis), (m.sx / 2 - 0.02 * m.sx, L, chassis + 0.05 * m.sz))
        for x0 in (-0.48 * m.sx, 0.45 * m.sx):
            m.box("paint", (x0, y0, chassis), (x0 + 0.03 * m.sx, L, 0.45 * m.sz))
        m.box("paint", (-m.sx / 2 + 0.02 * m.sx, L - 0.03 * m.sy, chassis), (m.sx / 2 - 0.02 * m.sx, L, 0.45 * m.sz))
    elif m.named("fire engine", "fire engines", "fire truck", "fire trucks", "fire appliance"):
        # painted all over, roller shutters down the sides, a ladder on the roof
        m.box("paint", (-m.sx / 2 + 0.02 * m.sx, y0, chassis), (m.sx / 2 - 0.02 * m.sx, L, 0.85 * m.sz))
        for x in (-1, 1):
            for k in range(3):
                ya = y0 + (k + 0.1) * (L - y0) / 3
                m.box("metal", (x * (m.sx / 2 - 0.02 * m.sx), ya, 0.35 * m.sz),
                      (x * (m.sx / 2 - 0.01 * m.sx), ya + 0.8 * (L - y0) / 3, 0.78 * m.sz), rounded=0.0)  # fmt: skip
        for x in (-0.25 * m.sx, 0.25 * m.sx):
            m.box("metal", (x - 0.02 * m.sx, y0 - 0.15 * cab_len, 0.88 * m.sz), (x + 0.02 * m.sx, L, 0.91 * m.sz), rounded=0.0)
        for k in range(int((L - y0) / 0.4) + 1):
            y = y0 - 0.15 * cab_len + k * 0.4
            if y < L:
                m.box("metal", (-0.25 * m.sx, y, 0.885 * m.sz), (0.25 * m.sx, y + 0.04, 0.905 * m.sz), rounded=0.0)
        for x in (-0.25 * m.sx, 0.25 * m.sx):
            m.box("dark_metal", (x - 0.02 * m.sx, y0, 0.85 * m.sz), (x + 0.02 * m.sx, y0 + 0.04 * m.sy, 0.88 * m.sz), rounded=0.0)
            m.box("dark_metal", (x - 0.02 * m.sx, L - 0.06 * m.sy, 0.85 * m.sz), (x + 0.02 * m.sx, L - 0.02 * m.sy, 0.88 * m.sz), rounded=0.0)
    else:  # (an ice cream van's body stops short of the top: its cone stands on the roof)
        m.box("canvas_alt", (-m.sx / 2 + 0.02 * m.sx, y0, chassis), (m.sx / 2 - 0.02 * m.sx, L, roof))
    if food:
        y0, y1 = -L + cab_len + 0.12 * m.sy, L - 0.1 * m.sy
        m.box("dark_plastic", (-m.sx / 2 + 0.01 * m.sx, y0, 0.5 * roof), (-m.sx / 2 + 0.02 * m.sx, y1, 0.8 * roof), rounded=0.0)
        m.box("wood", (-m.sx / 2, y0, 0.48 * roof), (-m.sx / 2 + 0.02 * m.sx, y1, 0.5 * roof), rounded=0.0)
        m.extrude("canvas", [(-m.sx / 2 + 0.02 * m.sx, 0.83 * roof), (-m.sx / 2, 0.78 * roof), (-m.sx / 2, 0.8 * roof),
                             (-m.sx / 2 + 0.02 * m.sx, 0.85 * roof)], "y", y0, y1)
        m.box("light", (-m.sx / 2 + 0.005 * m.sx, y0, 0.87 * roof), (-m.sx / 2 + 0.02 * m.sx, y1, 0.95 * roof), rounded=0.0)
        if roof < m.sz:  # a giant cone on the roof says what it sells
            r = 0.3 * (m.sz - roof)
            m.lathe("wood", [(0.0, roof), (r, m.sz - 1.3 * r)], centre=(0, 0.5 * (y0 + y1), 0.0), fraction=0.5)
            m.ball("flower", (0, 0.5 * (y0 + y1), m.sz - r), (r, r, r), fraction=0.5)
    for y in (-L + 0.14 * m.sy, L - 0.32 * m.sy, L - 0.15 * m.sy):
        for s in (-1, 1):
            _wheel(m, s * m.sx / 2, y, wr, 0.12 * m.sx, s)
    for s in (-1, 1):
        m.box("light", (s * 0.38 * m.sx - 0.06 * m.sx, -L - 0.01, chassis + 0.05), (s * 0.38 * m.sx + 0.06 * m.sx, -L, chassis + 0.15),
              rounded=0.0)


def bus(m: Model) -> None:
    if m.named("tram", "streetcar"):  # the catalogue files trams with buses; they run on rails
        _railcars(m)
        return
    _livery(m)
    wr = min(0.16 * m.sz, 0.05 * m.sy)
    L = m.sy / 2
    m.box("paint", (-m.sx / 2 + 0.02, -L, 0.6 * wr), (m.sx / 2 - 0.02, L, m.sz))
    win_lo, win_hi = 0.5 * m.sz, 0.85 * m.sz
    m.box("glass", (-m.sx / 2 + 0.01, -L + 0.15 * m.sy, win_lo), (m.sx / 2 - 0.01, L - 0.05 * m.sy, win_hi), rounded=0.0)
    m.box("glass", (-m.sx / 2 + 0.1, -L - 0.01, 0.35 * m.sz), (m.sx / 2 - 0.1, -L + 0.02, 0.9 * m.sz), rounded=0.0)
    m.box("dark_plastic", (-m.sx / 2 + 0.005, -L + 0.04 * m.sy, 0.1 * m.sz), (-m.sx / 2 + 0.03, -L + 0.1 * m.sy, 0.8 * m.sz),
          rounded=0.0)
    for y in (-L + 0.15 * m.sy, L - 0.2 * m.sy):
        for s in (-1, 1):
            _wheel(m, s * m.sx / 2, y, wr, 0.1 * m.sx, s)
    for s in (-1, 1):
        m.box("light", (s * 0.4 * m.sx - 0.05 * m.sx, -L - 0.01, 0.15 * m.sz), (s * 0.4 * m.sx + 0.05 * m.sx, -L, 0.22 * m.sz),
              rounded=0.0)
    m.box("screen", (-0.3 * m.sx, -L - 0.015, 0.9 * m.sz), (0.3 * m.sx, -L, 0.97 * m.sz), rounded=0.0)


def _motorcycle(m: Model) -> None:
    _livery(m)
    r = min(0.3 * m.sy, 0.33 * m.sz)
    tyre = 0.35 * r
    yf, yr = -m.sy / 2 + r, m.sy / 2 - r
    for y in (yf, yr):
        m.torus("rubber", (0, y, r), r - tyre / 2, tyre / 2, axis="x")
        m.cylinder("metal", (-0.12 * m.sx, y, r), (0.12 * m.sx, y, r), 0.5 * r, fraction=0.6)
    m.box("dark_metal", (-0.2 * m.sx, -0.15 * m.sy, 0.25 * m.sz), (0.2 * m.sx, 0.15 * m.sy, 0.5 * m.sz))
    m.ball("paint", (0, -0.12 * m.sy, 0.62 * m.sz), (0.22 * m.sx, 0.16 * m.sy, 0.1 * m.sz))
    m.box("leather", (-0.16 * m.sx, 0.02 * m.sy, 0.55 * m.sz), (0.16 * m.sx, 0.3 * m.sy, 0.64 * m.sz))
    m.beam("paint", (0, 0.1 * m.sy, 0.5 * m.sz), (0, yr, r), 0.08 * m.sx)
    m.beam("chrome", (0, yf, r), (0, yf + 0.12 * m.sy, 0.8 * m.sz), 0.05 * m.sx)
    m.cylinder("chrome", (-m.sx / 2, yf + 0.12 * m.sy, 0.8 * m.sz), (m.sx / 2, yf + 0.12 * m.sy, 0.8 * m.sz), 0.03 * m.sx,
               fraction=0.4)
    m.ball("light", (0, yf + 0.08 * m.sy, 0.7 * m.sz), (0.1 * m.sx, 0.04 * m.sy, 0.06 * m.sz), fraction=0.5)
    m.cylinder("chrome", (0.15 * m.sx, -0.05 * m.sy, 0.3 * m.sz), (0.18 * m.sx, 0.45 * m.sy, 0.35 * m.sz), 0.05 * m.sx,
               fraction=0.5)

def bicycle(m: Model) -> None:
    if m.named("motorcycle", "motorbike", "scooter", "moped"):
        _motorcycle(m)
        return
    _livery(m)
    r = min(0.25 * m.sy, 0.36 * m.sz)  # two wheels, never overlapping
    tube = m.thick(0.018, 0.2 * m.sx)
    yf, yr = -m.sy / 2 + r, m.sy / 2 - r
    for y in (yf, yr):
        m.torus("rubber", (0, y, r), r - 0.02, 0.02, axis="x")
        for k in range(6):
            a = np.pi * k / 6
            # Spokes (and frame tubes) all lie in one plane and cross: each a hair thicker than
            # the last, so their sides never lie in one plane.
            m.beam("chrome", (0, y - np.cos(a) * (r - 0.03), r - np.sin(a) * (r - 0.03)),
                   (0, y + np.cos(a) * (r - 0.03), r + np.sin(a) * (r - 0.03)), 0.004 * (1 + 0.1 * k))
    crank = np.array([0, 0.05 * m.sy, r])
    seat = np.array([0, yr - 0.1 * m.sy, 0.85 * m.sz])
    head = np.array([0, yf + 0.12 * m.sy, 0.82 * m.sz])
    for k, (a, b) in enumerate(((crank, seat), (crank, head), (seat, head), (crank, (0, yr, r)), (seat, (0, yr, r)),
                                (head, (0, yf, r)))):
        m.beam("paint", a, b, tube * (1 + 0.05 * k))
    m.box("leather", seat + (-0.06, -0.1, 0), seat + (0.06, 0.08, 0.05))
    m.beam("chrome", head, head + (0, -0.03, 0.13 * m.sz), 0.8 * tube)
    m.cylinder("dark_plastic", head + (-m.sx / 2, -0.03, 0.14 * m.sz), head + (m.sx / 2, -0.03, 0.14 * m.sz), 0.015,
               fraction=0.4)
    m.cylinder("dark_metal", crank + (-0.04, 0, 0), crank + (0.04, 0, 0), 0.08, fraction=0.6)


#: Words of boats whose sail is square-rigged.
_SQUARE_RIG = ("longship", "viking", "galleon", "junk", "square", "caravel")


def boat(m: Model) -> None:
    """A hull tapering to a bow at the front; by its words an open boat (gunwale and thwarts:
    rowing boat, canoe, longship), a sailing boat (mast and sail, square-rigged for a longship
    or a galleon) or, else, a motor boat with a cabin."""
    size = (m.sx, m.sy, m.sz)
    m.main = "straw" if m.has(*PLANT_HULL) else "paint"
    open_, sail = is_open(m.text), has_sail(m.text, size)
    hull_h = hull_share(m.text, size) * m.sz
    top = floor_share(m.text, size) * m.sz  # an open boat's floor lies below its gunwale
    L = m.sy / 2
    deck = [(0, -L), (0.3 * m.sx, -0.55 * L), (0.5 * m.sx, -0.05 * L), (0.47 * m.sx, L), (-0.47 * m.sx, L),
            (-0.5 * m.sx, -0.05 * L), (-0.3 * m.sx, -0.55 * L)]
    hull = P.prism(deck, top)
    bottom = hull.vertices[:, 2] < 1e-9
    hull.vertices[bottom, 0] *= 0.3
    hull.vertices[bottom, 1] = hull.vertices[bottom, 1] * 0.85 + 0.05 * L
    m.add(m.main, P.flatten(hull))
    planks = P.prism([(x * 0.94, y * 0.96) for x, y in deck], PLANKS * m.sz + 0.01)
    m.add("wood", P.flatten(P.transform(planks, P.affine(np.eye(3), (0, 0, top - 0.01)))))
    if open_:
        rail = hull_h - top
        ring(m, "dark_wood", [(x, y, top + rail / 2) for x, y in deck], rail)
        for k in range(3):  # thwarts across, a little under the gunwale
            y = -0.3 * L + k * 0.45 * L
            half = 0.47 * m.sx * min(1.0, 0.6 + 0.4 * (y + 0.55 * L) / (0.5 * L))
            m.box("wood", (-half + rail / 2, y - 0.05 * L, top + 0.02 * m.sz), (half - rail / 2, y + 0.05 * L, top + 0.5 * rail),
                  rounded=0.0)
    else:
        m.box("canvas_alt", (-0.5 * m.sx - 0.005, -0.05 * L, 0.92 * hull_h), (0.5 * m.sx + 0.005, L, 0.98 * hull_h), rounded=0.0)
    if sail:
        m.post("wood", 0, -0.1 * L, top, m.sz, 0.02 * m.sx + 0.01, fraction=0.4)
        if m.has(*_SQUARE_RIG):
            m.cylinder("wood", (-0.6 * m.sx, -0.1 * L, 0.93 * m.sz), (0.6 * m.sx, -0.1 * L, 0.93 * m.sz), 0.015 * m.sx + 0.005,
                       fraction=0.4)
            m.box("canvas", (-0.55 * m.sx, -0.1 * L - 0.02 * m.sx - 0.012, hull_h + 0.15 * m.sz),
                  (0.55 * m.sx, -0.1 * L - 0.02 * m.sx - 0.007, 0.92 * m.sz), rounded=0.0)
        else:
            m.extrude("canvas_alt", [(-0.08 * L, hull_h + 0.1 * m.sz), (0.8 * L, hull_h + 0.1 * m.sz), (-0.08 * L, 0.97 * m.sz)],
                      "x", -0.005, 0.005)
    elif not open_:
        m.box("wall", (-0.32 * m.sx, -0.1 * L, hull_h), (0.32 * m.sx, 0.6 * L, 0.85 * m.sz))
        m.box("glass", (-0.33 * m.sx, -0.11 * L, 0.65 * m.sz), (0.33 * m.sx, 0.55 * L, 0.78 * m.sz), rounded=0.0)
        m.box("paint", (-0.35 * m.sx, -0.15 * L, 0.85 * m.sz), (0.35 * m.sx, 0.65 * L, m.sz))


#: Words of carts pushed by hand over smooth floors (stations, airports, shops): a flat trolley.
_TROLLEY = ("luggage", "baggage", "platform trolley", "trolley", "shopping", "hand truck", "dolly", "flatbed cart",
            "tea trolley", "serving cart", "service cart", "laundry")


def _trolley(m: Model) -> None:
    """A trolley: a flat deck at the cart's rest height with a low rail round it, on four
    castors on legs, a push handle rising at the back."""
    m.main = "metal"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    wr = min(0.1 * H, 0.12 * L, 0.3 * W)
    deck = 0.51 * H - 0.01  # its top at the cart's rest height (data/catalogue.json), like a cart's bed
    m.box("wood", (-W + 0.02 * m.sx, -L, deck), (W - 0.02 * m.sx, 0.92 * L, 0.55 * H))
    for x in (-0.8 * W, 0.8 * W):
        for y in (-0.8 * L, 0.75 * L):
            m.cylinder("rubber", (x - 0.3 * wr, y, wr), (x + 0.3 * wr, y, wr), wr, fraction=0.5)
            m.post("dark_metal", x, y, wr, deck, 0.25 * wr, fraction=0.4)
    rail = deck + 0.12 * H
    corners = [(-0.98 * W, -0.98 * L, rail), (0.98 * W, -0.98 * L, rail), (0.98 * W, 0.9 * L, rail), (-0.98 * W, 0.9 * L, rail)]
    ring(m, "metal", corners, 0.02 * H + 0.005)
    for x in (-0.9 * W, 0.9 * W):
        m.beam("metal", (x, 0.93 * L, deck), (x, L - 0.01 * L, H - 0.02 * H), 0.025 * H + 0.005)
    m.cylinder("dark_plastic", (-0.95 * W, L - 0.01 * L, H - 0.02 * H), (0.95 * W, L - 0.01 * L, H - 0.02 * H), 0.02 * H + 0.005,
               fraction=0.4)


def _sledge(m: Model) -> None:
    """A sledge on two runners that curl up at the front, a slatted bed on struts; a sleigh
    (by its word) also gets high curved sides and a seat."""
    m.main = "wood"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    sleigh = m.named("sleigh")
    runner = "metal" if sleigh else "dark_wood"
    r = m.thick(0.02, 0.08 * W) + 0.004
    bed = (0.35 if sleigh else 0.7) * H
    curl = min(0.25 * m.sy, 0.8 * bed)
    arc = [(-L + curl - curl * np.sin(a), r + curl * (1 - np.cos(a))) for a in np.linspace(0, np.pi / 2, 4)]
    for x in (-0.8 * W, 0.8 * W):
        m.cylinder(runner, (x, arc[0][0], r), (x, L, r), r, fraction=0.4)
        for k, ((y0, z0), (y1, z1)) in enumerate(zip(arc, arc[1:])):  # the curl, each piece a hair thinner
            m.beam(runner, (x, y0, z0), (x, y1, z1), 2 * r * (1 - 0.03 * k))
        for y in (-0.45 * L, 0.1 * L, 0.65 * L):
            m.post("dark_wood", x, y, 2 * r, bed + 0.02 * H, 0.8 * r, fraction=0.3)
    for k in range(5):  # slats a hair apart: boards that touch would share a face
        y0 = -0.6 * L + k * 1.5 * L / 5
        m.box("wood", (-0.94 * W, y0, bed), (0.94 * W, y0 + 0.26 * L, bed + 0.1 * H))
    if sleigh:
        low = bed - 0.03 * H  # below the slats' underside, which would otherwise share its plane
        side = [(-0.7 * L, low), (L, low), (L, H), (0.5 * L, 0.75 * H), (-0.55 * L, 0.75 * H), (-0.7 * L, 0.95 * H)]
        for x in (-W, W - 0.06 * m.sx):
            m.extrude("paint", side, "x", x, x + 0.06 * m.sx)
        m.box("fabric", (-0.92 * W, 0.35 * L, bed + 0.08 * H), (0.92 * W, 0.8 * L, 0.6 * H))


def _wheelbarrow(m: Model) -> None:
    """A wheelbarrow: a sloped tub over one wheel at the front, two legs and two handles
    running back from under the tub."""
    m.main = "paint"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    wr = min(0.3 * H, 0.17 * m.sy)
    floor = 0.55 * H  # the cart's rest height (data/catalogue.json): what it carries sits here
    m.lathe("paint", [(0.0, floor - 0.03 * H), (0.5 * W, floor - 0.03 * H), (0.62 * W, floor), (0.95 * W, H - 0.04 * H), (0.99 * W, H)],
            centre=(0, -0.05 * L, 0), scale=(1.0, 0.55 * L / W))
    m.box("dark_metal", (-0.45 * W, -0.35 * L, floor - 0.05 * H), (0.45 * W, 0.25 * L, floor - 0.02 * H))
    m.cylinder("rubber", (-0.12 * W, -L + wr, wr), (0.12 * W, -L + wr, wr), wr, fraction=0.6)
    m.cylinder("metal", (-0.14 * W, -L + wr, wr), (0.14 * W, -L + wr, wr), 0.3 * wr, fraction=0.4)
    for s in (-1, 1):
        m.beam("wood", (s * 0.14 * W, -L + wr, wr), (s * 0.55 * W, L, floor + 0.05 * H), 0.05 * W + 0.01)
        m.post("dark_metal", s * 0.45 * W, 0.45 * L, 0, floor - 0.02 * H, 0.03 * W + 0.005, fraction=0.3)
        m.cylinder("dark_plastic", (s * 0.55 * W, 0.85 * L, floor + 0.04 * H), (s * 0.57 * W, L, floor + 0.05 * H), 0.04 * W + 0.008,
                   fraction=0.4)


def _spokes(m: Model, x: float, y: float, r: float) -> None:
    """A wooden wheel at (``x``, ``y``) of radius ``r``, its axle along x: a rim and four spokes across."""
    m.torus("dark_wood", (x, y, r), r - 0.03, 0.03, axis="x")
    for k in range(4):
        a = np.pi * k / 4
        # (each spoke a little thicker than the one before: crossing spokes would share their faces)
        m.beam("dark_wood", (x, y - np.cos(a) * r, r - np.sin(a) * r), (x, y + np.cos(a) * r, r + np.sin(a) * r), 0.025 * (1 + 0.1 * k))


def _coach(m: Model) -> None:
    """A horse-drawn coach facing -y: a closed cabin with windows between small front and big
    back wheels, a roof rail and the driver's box in front."""
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.main = "paint"
    front_r, back_r = 0.22 * H, 0.3 * H
    floor = 0.38 * H
    m.box("paint", (-0.8 * W, -0.45 * D, floor), (0.8 * W, 0.6 * D, 0.88 * H))
    m.box("dark_wood", (-0.85 * W, -0.5 * D, 0.88 * H), (0.85 * W, 0.65 * D, 0.92 * H))
    for x in (-0.8 * W - 0.004, 0.8 * W):
        m.box("glass", (x, -0.25 * D, 0.6 * H), (x + 0.004, 0.35 * D, 0.8 * H), rounded=0.0)
    for x in (-0.9 * W, 0.9 * W):  # the roof rail
        m.beam("dark_metal", (x, -0.45 * D, 0.98 * H), (x, 0.6 * D, 0.98 * H), 0.015)
    m.box("dark_wood", (-0.7 * W, -0.95 * D, 0.55 * H), (0.7 * W, -0.5 * D, 0.62 * H))  # the driver's box
    m.box("dark_wood", (-0.7 * W, -0.6 * D, 0.62 * H), (0.7 * W, -0.5 * D, 0.78 * H))
    for x in (-0.92 * W, 0.92 * W):
        _spokes(m, x, -0.55 * D, front_r)
        _spokes(m, x, 0.7 * D, back_r)
    for y, r in ((-0.55 * D, front_r), (0.7 * D, back_r)):
        m.cylinder("dark_metal", (-W, y, r), (W, y, r), 0.025, fraction=0.4)
    m.beam("wood", (0, -0.5 * D, floor), (0, -D, 0.3 * H), 0.03)  # the pole the horses pull by


def cart(m: Model) -> None:
    """A wooden cart on two spoked wheels with shafts; a mine cart, a sledge, a wheelbarrow or
    a hand trolley (luggage, baggage, shopping...) by its words."""
    if m.named("minecart", "mine cart", "mine car", "ore cart", "ore car"):
        _minecart(m)
        return
    if m.named("sled", "sledge", "sleigh", "toboggan", "sledges"):
        _sledge(m)
        return
    if m.named("wheelbarrow", "barrow"):
        _wheelbarrow(m)
        return
    if m.has(*_TROLLEY):
        _trolley(m)
        return
    if m.named("stagecoach", "coach", "carriage") and not m.named("baby carriage"):
        _coach(m)
        return
    wr = 0.35 * m.sz
    bed_z = 0.5 * m.sz
    # The side boards run full length; the bed and the end boards fit between them, edge to
    # edge, so no two boards share a face.
    x0, x1 = -0.35 * m.sx + 0.04, 0.35 * m.sx - 0.04
    m.box("wood", (x0, -0.1 * m.sy + 0.04, bed_z), (x1, m.sy / 2 - 0.04, bed_z + 0.06))
    for x in (-0.35 * m.sx, 0.35 * m.sx - 0.04):
        m.box("wood", (x, -0.1 * m.sy, bed_z), (x + 0.04, m.sy / 2, m.sz))
    m.box("wood", (x0, m.sy / 2 - 0.04, bed_z), (x1, m.sy / 2, m.sz))
    m.box("wood", (x0, -0.1 * m.sy, bed_z), (x1, -0.1 * m.sy + 0.04, m.sz * 0.9))
    if m.has("apple", "fruit", "vegetable", "flower", "melon", "pumpkin"):
        role = "flower_alt" if m.has("pumpkin", "orange", "lemon") else "flower"
        s = 0.08 * min(m.sx, m.sy)
        for i in range(4):
            for j in range(5):
                c = (-0.28 * m.sx + i * 0.56 * m.sx / 3, -0.05 * m.sy + j * 0.5 * m.sy / 4, 0.8 * m.sz + (i + j) % 2 * s)
                m.ball(role, c, (s, s, s), fraction=0.4)
    for s in (-1, 1):
        _spokes(m, s * (m.sx / 2 - 0.03), 0.2 * m.sy, wr)
        m.beam("wood", (s * 0.3 * m.sx, -0.1 * m.sy, bed_z + 0.03), (s * 0.25 * m.sx, -m.sy / 2, bed_z - 0.05), 0.05)
    m.cylinder("dark_metal", (-m.sx / 2, 0.2 * m.sy, wr), (m.sx / 2, 0.2 * m.sy, wr), 0.025, fraction=0.4)
    m.post("wood", 0, -0.05 * m.sy, 0, bed_z, 0.03)


def robot(m: Model) -> None:
    m.main = "metal"
    leg_h = 0.35 * m.sz
    body_top = 0.75 * m.sz
    for s in (-1, 1):
        m.box("dark_metal", (s * 0.18 * m.sx - 0.08 * m.sx, -0.1 * m.sy, 0.05 * m.sz), (s * 0.18 * m.sx + 0.08 * m.sx, 0.1 * m.sy, leg_h))
        m.box("dark_metal", (s * 0.18 * m.sx - 0.1 * m.sx, -m.sy / 2, 0), (s * 0.18 * m.sx + 0.1 * m.sx, 0.25 * m.sy, 0.06 * m.sz))
        m.cylinder("metal", (s * 0.33 * m.sx, 0, body_top - 0.05 * m.sz), (s * 0.44 * m.sx, -0.1 * m.sy, 0.4 * m.sz), 0.05 * m.sx,
                   fraction=0.5)
        m.ball("dark_metal", (s * 0.44 * m.sx, -0.1 * m.sy, 0.38 * m.sz), (0.06 * m.sx, 0.06 * m.sx, 0.06 * m.sx), fraction=0.5)
    m.box("metal", (-0.32 * m.sx, -0.3 * m.sy, leg_h), (0.32 * m.sx, 0.3 * m.sy, body_top))
    m.box("screen", (-0.18 * m.sx, -0.3 * m.sy - 0.01, 0.5 * m.sz), (0.18 * m.sx, -0.3 * m.sy, 0.65 * m.sz), rounded=0.0)
    m.box("metal", (-0.2 * m.sx, -0.25 * m.sy, body_top + 0.02 * m.sz), (0.2 * m.sx, 0.25 * m.sy, 0.92 * m.sz))
    for s in (-1, 1):
        m.ball("light", (s * 0.08 * m.sx, -0.25 * m.sy, 0.85 * m.sz), (0.04 * m.sx, 0.02 * m.sy, 0.04 * m.sx), fraction=0.5)
    m.post("dark_metal", 0, 0, 0.92 * m.sz, m.sz - 0.02 * m.sz, 0.01)
    m.ball("accent", (0, 0, m.sz - 0.02 * m.sz), (0.02 * m.sz,) * 3, fraction=0.4)


def treadmill(m: Model) -> None:
    m.main = "dark_plastic"
    deck = 0.15 * m.sz
    m.box("dark_plastic", (-m.sx / 2, -0.2 * m.sy, 0), (m.sx / 2, m.sy / 2, deck))
    m.box("rubber", (-0.4 * m.sx, -0.18 * m.sy, deck), (0.4 * m.sx, m.sy / 2 - 0.02, deck + 0.01), rounded=0.0)
    for s in (-1, 1):
        m.beam("metal", (s * 0.45 * m.sx, -0.15 * m.sy, deck), (s * 0.45 * m.sx, -0.4 * m.sy, 0.8 * m.sz), 0.05)
        m.beam("metal", (s * 0.45 * m.sx, -0.35 * m.sy, 0.75 * m.sz), (s * 0.45 * m.sx, 0.05 * m.sy, 0.75 * m.sz), 0.04)
    m.box("dark_plastic", (-0.4 * m.sx, -m.sy / 2, 0.78 * m.sz), (0.4 * m.sx, -0.35 * m.sy, m.sz))
    m.box("screen", (-0.25 * m.sx, -0.35 * m.sy, 0.82 * m.sz), (0.25 * m.sx, -0.34 * m.sy, 0.95 * m.sz), rounded=0.0)


#: Words of aircraft driven by propellers rather than jets.
_PROPELLER = ("propeller", "prop", "turboprop", "biplane", "seaplane", "floatplane", "crop duster", "twin-propeller")


def _plane(m: Model) -> None:
    """A fixed-wing aeroplane, nose toward −Y: a round fuselage with a cockpit and a window
    line, low tapered wings across the box's width, a tailplane and a fin, engines under the
    wings (propellers when the words say so, else jets) and a tricycle landing gear."""
    m.main = "plastic"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    r = min(0.2 * H, 0.1 * m.sy, 0.25 * W)
    gear = 0.35 * H - r
    zc = gear + r
    m.cylinder("plastic", (0, -0.8 * L, zc), (0, 0.6 * L, zc), r, fraction=0.8)
    m.ball("plastic", (0, -0.8 * L, zc), (r, 0.18 * L, r), fraction=0.8)
    m.cylinder("plastic", (0, 0.6 * L, zc), (0, 0.98 * L, zc + 0.6 * r), r, 0.25 * r, fraction=0.8)
    m.box("screen", (-0.55 * r, -0.92 * L, zc + 0.25 * r), (0.55 * r, -0.86 * L, zc + 0.6 * r), rounded=0.0)
    for s in (-1, 1):  # the window line, a hair proud of the fuselage's side
        x0, x1 = sorted((s * 0.96 * r, s * 1.01 * r))
        m.box("screen", (x0, -0.7 * L, zc + 0.05 * r), (x1, 0.55 * L, zc + 0.25 * r), rounded=0.0)
    zw = zc - 0.5 * r
    m.extrude("paint", [(-W, -0.02 * L), (0.0, -0.25 * L), (W, -0.02 * L), (W, 0.06 * L), (0.0, 0.08 * L), (-W, 0.06 * L)],
              "z", zw - 0.04 * r - 0.005, zw + 0.04 * r + 0.005)
    zt = zc + 0.55 * r
    span = 0.32 * m.sx
    m.extrude("paint", [(-span, 0.9 * L), (0.0, 0.78 * L), (span, 0.9 * L), (span, 0.97 * L), (-span, 0.97 * L)],
              "z", zt - 0.03 * r - 0.003, zt + 0.03 * r + 0.003)
    m.extrude("paint", [(0.72 * L, zc + 0.5 * r), (L, zc + 0.7 * r), (L, H), (0.9 * L, H)], "x", -0.04 * r - 0.004, 0.04 * r + 0.004)
    propeller = m.has(*_PROPELLER)
    for s in (-1, 1):
        x = s * 0.35 * m.sx
        n = 0.45 * r
        m.cylinder("metal", (x, -0.3 * L, zw - 0.4 * n), (x, 0.02 * L, zw - 0.4 * n), n, 0.7 * n, fraction=0.6)
        if propeller:
            m.cylinder("dark_metal", (x, -0.31 * L, zw - 0.4 * n), (x, -0.315 * L, zw - 0.4 * n), min(2.2 * n, zw + 0.4 * n - 0.02),
                       fraction=0.8)
        else:
            m.cylinder("dark_metal", (x, -0.301 * L, zw - 0.4 * n), (x, -0.302 * L, zw - 0.4 * n), 0.85 * n, fraction=0.6)
    wheel = 0.35 * gear + 0.01
    for x, y in ((0.0, -0.7 * L), (-0.2 * m.sx, 0.0), (0.2 * m.sx, 0.0)):
        m.post("dark_metal", x, y, wheel, zc - 0.5 * r if x == 0 else zw, 0.02 * H + 0.01, fraction=0.4)
        m.cylinder("rubber", (x - 0.3 * wheel, y, wheel), (x + 0.3 * wheel, y, wheel), wheel, fraction=0.6)


def _saucer(m: Model) -> None:
    """A flying saucer: a metal disc thickest at the middle with a glass dome on top, a ring
    of lights round the rim and three landing legs."""
    m.main = "metal"
    H = m.sz
    leg = 0.15 * H
    m.lathe("metal", [(0.0, leg), (0.25, leg + 0.05 * H), (0.5, 0.42 * H), (0.3, 0.6 * H), (0.0, 0.62 * H)], scale=(m.sx, m.sy))
    m.lathe("glass", [(0.17, 0.58 * H), (0.14, 0.85 * H), (0.0, H)], scale=(m.sx, m.sy), fraction=0.8)
    for k in range(10):
        a = 2 * np.pi * k / 10
        m.ball("light", (0.47 * m.sx * np.cos(a), 0.47 * m.sy * np.sin(a), 0.42 * H), (0.025 * m.sx,) * 3, fraction=0.4)
    for k in range(3):
        a = 2 * np.pi * k / 3 + np.pi / 2
        foot = np.array([0.3 * m.sx * np.cos(a), 0.3 * m.sy * np.sin(a), 0.0])
        m.beam("dark_metal", foot + (0, 0, 0.01 * H), (0.2 * m.sx * np.cos(a), 0.2 * m.sy * np.sin(a), leg + 0.05 * H), 0.02 * m.sx)
        m.cylinder("dark_metal", foot, foot + (0, 0, 0.02 * H), 0.04 * m.sx, fraction=0.5)


def craft(m: Model) -> None:
    """A spaceship or drone: a hull, wings or rotor arms, glowing engines; a saucer by name."""
    if m.named("flying saucer", "saucer", "ufo", "flying disc"):
        _saucer(m)
        return
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


def _tractor(m: Model) -> None:
    """A farm tractor: big rear wheels under the cab, small front wheels, a long hood, an
    exhaust stack."""
    m.main = "paint"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    rear = min(0.42 * H, 0.3 * m.sy)
    front = 0.55 * rear
    yr, yf = L - rear, -L + front
    for s in (-1, 1):
        _wheel(m, s * W, yr, rear, 0.25 * m.sx, s)
        _wheel(m, s * 0.8 * W, yf, front, 0.16 * m.sx, s)
        m.torus("paint", (s * 0.85 * W, yr, rear), 1.05 * rear, 0.06 * rear, axis="x", arc=np.pi, fraction=0.6)
    m.box("paint", (-0.35 * W, yf - 0.6 * front, 0.7 * front), (0.35 * W, yr - 0.3 * rear, 1.05 * rear))
    m.box("dark_metal", (-0.3 * W, yf - 0.65 * front, 0.9 * front), (0.3 * W, yf - 0.6 * front, 1.0 * rear), rounded=0.0)
    # Pillars stand centred on the cab's glass edges and reach into the body and the roof.
    m.box("dark_metal", (-0.5 * W, yr - 0.5 * rear, 0.6 * rear), (0.5 * W, L - 0.05 * m.sy, 1.15 * rear))
    cab_lo, cab_hi = 1.15 * rear, H - 0.04 * H
    m.box("glass", (-0.5 * W, yr - 0.6 * rear, cab_lo), (0.5 * W, L - 0.08 * m.sy, cab_hi), rounded=0.0)
    for x in (-0.5 * W, 0.5 * W):
        for y in (yr - 0.6 * rear, L - 0.08 * m.sy):
            m.box("dark_metal", (x - 0.01 * W, y - 0.01 * m.sy, cab_lo - 0.02 * H), (x + 0.01 * W, y + 0.01 * m.sy, cab_hi + 0.02 * H),
                  rounded=0.0)
    m.box("paint", (-0.55 * W, yr - 0.65 * rear, cab_hi), (0.55 * W, L - 0.05 * m.sy, H))
    m.post("dark_metal", 0.2 * W, yf + 0.3 * front, 1.0 * rear, 0.95 * H, 0.03 * m.sx + 0.01, fraction=0.4)
    for s in (-1, 1):
        m.box("light", (s * 0.25 * W - 0.06 * W, yf - 0.67 * front, 0.85 * rear), (s * 0.25 * W + 0.06 * W, yf - 0.62 * front, 0.95 * rear),
              rounded=0.0)


def _forklift(m: Model) -> None:
    """A forklift: a low body with its counterweight, a mast and forks at the front, an
    overhead guard over the seat."""
    m.main = "yellow_paint"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    wr = 0.14 * H
    mast_y = -L + 0.22 * m.sy
    for s in (-1, 1):
        _wheel(m, s * W, mast_y + 0.12 * m.sy, wr, 0.18 * m.sx, s)
        _wheel(m, s * 0.9 * W, L - 0.2 * m.sy, 0.85 * wr, 0.16 * m.sx, s)
    m.box("yellow_paint", (-0.8 * W, mast_y + 0.02 * m.sy, 0.5 * wr), (0.8 * W, L, 0.42 * H))
    m.box("dark_metal", (-0.8 * W, L - 0.2 * m.sy, 0.42 * H), (0.8 * W, L, 0.55 * H))
    m.box("dark_plastic", (-0.3 * W, 0.05 * m.sy, 0.42 * H), (0.3 * W, 0.25 * m.sy, 0.5 * H))
    m.box("dark_plastic", (-0.3 * W, 0.2 * m.sy, 0.5 * H), (0.3 * W, 0.25 * m.sy, 0.65 * H))
    for x in (-0.45 * W, 0.45 * W):
        m.box("dark_metal", (x - 0.06 * W, mast_y - 0.03 * m.sy, 0.02 * H), (x + 0.06 * W, mast_y, H))
    m.box("dark_metal", (-0.55 * W, mast_y - 0.06 * m.sy, 0.05 * H), (0.55 * W, mast_y - 0.03 * m.sy, 0.3 * H))
    for x in (-0.3 * W, 0.3 * W):
        m.box("metal", (x - 0.05 * W, -L, 0.02 * H), (x + 0.05 * W, mast_y - 0.06 * m.sy, 0.04 * H), rounded=0.0)
    guard = 0.9 * H
    for x in (-0.72 * W, 0.72 * W):
        for y in (mast_y + 0.08 * m.sy, L - 0.22 * m.sy):
            m.beam("dark_metal", (x, y, 0.4 * H), (x, y, guard), 0.04 * m.sx + 0.01)
    for k in range(4):
        x = -0.75 * W + k * 0.5 * W
        m.beam("dark_metal", (x, mast_y + 0.08 * m.sy, guard), (x, L - 0.22 * m.sy, guard), 0.03 * m.sx + 0.01)
    m.box("light", (0.5 * W, mast_y + 0.03 * m.sy, guard - 0.06 * H), (0.7 * W, mast_y + 0.06 * m.sy, guard - 0.01 * H), rounded=0.0)


def _golf_cart(m: Model) -> None:
    """A golf cart: a small open body, a bench seat, a roof on four posts, a windscreen."""
    m.main = "fur_white"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    wr = 0.14 * H
    for y in (-L + 0.2 * m.sy, L - 0.2 * m.sy):
        for s in (-1, 1):
            _wheel(m, s * W, y, wr, 0.12 * m.sx, s)
    m.box("fur_white", (-0.85 * W, -L, 0.6 * wr), (0.85 * W, L, 0.3 * H))
    m.box("fur_white", (-0.85 * W, -L, 0.3 * H), (0.85 * W, -L + 0.25 * m.sy, 0.42 * H))
    m.box("leather", (-0.75 * W, 0.05 * m.sy, 0.3 * H), (0.75 * W, 0.3 * m.sy, 0.4 * H))
    m.box("leather", (-0.75 * W, 0.25 * m.sy, 0.4 * H), (0.75 * W, 0.32 * m.sy, 0.62 * H))
    roof = 0.95 * H
    for x in (-0.8 * W, 0.8 * W):
        for y in (-L + 0.27 * m.sy, 0.35 * m.sy):
            m.post("metal", x, y, 0.25 * H, (roof + H) / 2, 0.02 * m.sx + 0.005, fraction=0.3)
    m.box("fur_white", (-0.9 * W, -L + 0.2 * m.sy, roof), (0.9 * W, 0.45 * m.sy, H))
    m.box("glass", (-0.8 * W, -L + 0.26 * m.sy, 0.45 * H), (0.8 * W, -L + 0.27 * m.sy, roof), rounded=0.0)
    m.cylinder("dark_plastic", (0.3 * W, -L + 0.3 * m.sy, 0.5 * H), (0.3 * W, -L + 0.25 * m.sy, 0.55 * H), 0.15 * W, fraction=0.4)
    m.box("canvas_alt", (-0.5 * W, L - 0.05 * m.sy, 0.3 * H), (0.5 * W, L, 0.7 * H))


def _tracks(m: Model, track_h: float) -> None:
    """Two crawler tracks ``track_h`` high along the sides, road wheels on their outer faces."""
    W, L = m.sx / 2, m.sy / 2
    for s in (-1, 1):
        x0, x1 = sorted((s * W, s * 0.65 * W))
        m.extrude("rubber", [(-L, 0.5 * track_h), (-L + 0.1 * m.sy, 0), (L - 0.08 * m.sy, 0), (L, 0.5 * track_h), (L - 0.04 * m.sy, track_h),
                             (-L + 0.04 * m.sy, track_h)], "x", x0, x1)
        # Road wheels never overlap (their faces would share a plane): on a short hull they shrink.
        step = 0.7 * m.sy / 5
        for k in range(6):
            y = -L + 0.15 * m.sy + k * step
            m.cylinder("dark_metal", (s * W * 1.001, y, 0.35 * track_h), (s * W * 1.02, y, 0.35 * track_h),
                       min(0.3 * track_h, 0.48 * step), fraction=0.4)


def _tracked(m: Model) -> None:
    """A tracked working vehicle (a snowcat, a crawler, a half-track): a glazed cab at the front
    and a load box behind it on two crawler tracks."""
    m.main = "paint"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    track_h = 0.3 * H
    _tracks(m, track_h)
    deck = 1.05 * track_h
    m.box("dark_metal", (-0.66 * W, -0.95 * L, 0.5 * track_h), (0.66 * W, 0.95 * L, deck), rounded=0.0)
    m.box("paint", (-0.9 * W, -L, deck), (0.9 * W, -0.1 * L, 0.6 * H))
    m.box("screen", (-0.85 * W, -1.004 * L, 0.62 * H), (0.85 * W, -0.15 * L, 0.9 * H), rounded=0.0)
    m.box("paint", (-0.9 * W, -L, 0.9 * H), (0.9 * W, -0.1 * L, H))
    m.box("paint", (-0.9 * W, 0.0, deck), (0.9 * W, 0.98 * L, 0.75 * H))
    m.box("light", (-0.6 * W, -1.01 * L, 0.45 * H), (-0.35 * W, -L + 0.01, 0.52 * H), rounded=0.0)
    m.box("light", (0.35 * W, -1.01 * L, 0.45 * H), (0.6 * W, -L + 0.01, 0.52 * H), rounded=0.0)


def _snowmobile(m: Model) -> None:
    """A snowmobile: two skis at the front on struts, a track under the rear, a tapered hood
    with a windscreen, a long seat and handlebars."""
    m.main = "paint"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    for s in (-1, 1):
        m.extrude("dark_metal", [(-L, 0.12 * H), (-0.95 * L, 0.02 * H), (-0.2 * L, 0.0), (-0.2 * L, 0.05 * H), (-0.9 * L, 0.07 * H)],
                  "x", s * 0.8 * W - 0.06 * W, s * 0.8 * W + 0.06 * W)
        m.beam("dark_metal", (s * 0.8 * W, -0.55 * L, 0.05 * H), (s * 0.4 * W, -0.45 * L, 0.35 * H), 0.04 * H)
    m.extrude("rubber", [(0.0, 0.15 * H), (0.1 * L, 0.0), (0.95 * L, 0.0), (L, 0.15 * H), (0.95 * L, 0.3 * H), (0.05 * L, 0.3 * H)],
              "x", -0.45 * W, 0.45 * W)
    m.extrude("paint", [(-0.75 * L, 0.3 * H), (0.2 * L, 0.28 * H), (0.2 * L, 0.62 * H), (-0.3 * L, 0.62 * H), (-0.7 * L, 0.45 * H)],
              "x", -0.55 * W, 0.55 * W)
    m.box("leather", (-0.4 * W, 0.15 * L, 0.3 * H), (0.4 * W, 0.9 * L, 0.66 * H))  # above the hood's top
    m.extrude("glass", [(-0.32 * L, 0.6 * H), (-0.26 * L, 0.6 * H), (-0.18 * L, 0.85 * H), (-0.24 * L, 0.85 * H)], "x", -0.4 * W, 0.4 * W)
    m.cylinder("dark_metal", (-W, -0.12 * L, 0.8 * H), (W, -0.12 * L, 0.8 * H), 0.03 * H, fraction=0.4)
    m.post("dark_metal", 0, -0.15 * L, 0.6 * H, 0.8 * H, 0.03 * H)
    m.box("light", (-0.2 * W, -0.755 * L, 0.36 * H), (0.2 * W, -0.7 * L, 0.42 * H), rounded=0.0)


def _battle_tank(m: Model) -> None:
    """A battle tank: tracks with road wheels, a hull with a sloped glacis, a turret and gun."""
    m.main = "olive_paint"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    track_h = 0.4 * H
    _tracks(m, track_h)
    m.extrude("olive_paint", [(-L + 0.05 * m.sy, 0.35 * track_h), (L, 0.35 * track_h), (L, 0.6 * H), (-0.2 * L, 0.6 * H), (-L, 1.1 * track_h)],
              "x", -0.65 * W, 0.65 * W)
    m.box("olive_paint", (-W, -L + 0.1 * m.sy, track_h), (W, 0.98 * L, 1.1 * track_h), rounded=0.0)
    m.lathe("olive_paint", [(0.5, 0.6 * H), (0.42, 0.85 * H), (0.0, 0.87 * H)], centre=(0, 0.1 * m.sy, 0), scale=(0.9 * W, 0.55 * L))
    m.cylinder("olive_paint", (0, -0.2 * L, 0.74 * H), (0, -L, 0.76 * H), 0.05 * H, fraction=0.5)
    m.cylinder("dark_metal", (0, -L, 0.76 * H), (0, -L - 0.001, 0.76 * H), 0.04 * H, fraction=0.4)
    m.lathe("dark_metal", [(0.12 * W, 0.86 * H), (0.1 * W, H)], centre=(0.25 * W, 0.25 * L, 0), fraction=0.5)


#: Words that make a train a steam train: its power, or an age or a likeness that calls the
#: classic shape ("a toy train", "an old locomotive").
_STEAM = ("steam", "puffing", "coal", "toy", "model", "miniature", "old", "vintage", "antique", "heritage", "victorian")
#: Words of modern rail traction: the train is a unit of carriages with cabs.
_MODERN = ("diesel", "electric", "commuter", "passenger", "express", "high-speed", "bullet", "metro", "subway",
           "underground", "tram", "streetcar", "railcar", "railbus", "multiple unit", "light rail", "monorail")
#: Words of electric traction: a pantograph on the roof.
_ELECTRIC = ("electric", "tram", "streetcar", "metro", "high-speed", "bullet", "light rail")
_CARRIAGES = re.compile(r"\b(one|two|three|four|five|six|\d)[- ](?:carriages?|cars?|coach(?:es)?)\b")
_COUNT = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6}


def _ccw(points) -> list:
    """A (y, z) outline turned counter-clockwise, as :meth:`Model.extrude` wants it."""
    pts = [tuple(map(float, p)) for p in points]
    area = sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(pts, pts[1:] + pts[:1]))
    return pts if area > 0 else pts[::-1]


def _train(m: Model) -> None:
    """A train by its traction: steam words (or a locomotive with no modern word) give the
    steam locomotive; diesel, electric, commuter, tram... a unit of carriages with cabs."""
    steam = m.has(*_STEAM) and not m.has(*_MODERN)
    if steam or (not m.has(*_MODERN) and m.named("locomotive", "steam engine", "engine")):
        _locomotive(m)
    else:
        _railcars(m)


def _railcars(m: Model) -> None:
    """A diesel or electric unit: as many carriages as the text says ("a two-carriage train"; a
    train two, a railcar or tram one), each a long body on two bogies with a band of windows,
    doors and a stripe, a sloped cab at each end of the unit, gangways between carriages, and a
    pantograph (electric) or exhaust stacks (diesel) on the roof."""
    m.main = "paint"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    said = _CARRIAGES.search(m.text)
    n = (_COUNT.get(said.group(1)) or int(said.group(1))) if said else 2 if m.named("train") else 1
    n = max(1, min(n, int(m.sy // (1.5 * m.sx)), 8))  # no carriage shorter than 1.5 times its width
    gap = 0.015 * m.sy
    car = (m.sy - (n - 1) * gap) / n
    wr, floor, roof = min(0.09 * H, 0.06 * car), 0.27 * H, 0.9 * H
    for i in range(n):
        y0, y1 = -L + i * (car + gap), -L + i * (car + gap) + car
        nose = min(0.1 * car, 0.25 * H)
        lo = y0 + nose if i == 0 else y0
        hi = y1 - nose if i == n - 1 else y1
        outline = [(y0, floor), (y1, floor)]
        outline += [(y1, 0.6 * H), (hi, roof)] if i == n - 1 else [(y1, roof)]
        outline += [(lo, roof), (y0, 0.6 * H)] if i == 0 else [(y0, roof)]
        m.extrude("paint", outline, "x", -W, W)
        for end, top, sign in ((y0, lo, -1), (y1, hi, 1)):
            if top != end:  # a cab: its windscreen a hair proud of the slope, headlights below
                d = np.array([top - end, roof - 0.6 * H])
                out = sign * np.array([d[1], -d[0]]) / np.hypot(*d)
                foot = np.array([end, 0.6 * H])
                pane = [foot + t * d + u * out for t, u in ((0.15, 0.004), (0.85, 0.004), (0.85, 0.012), (0.15, 0.012))]
                m.extrude("screen", _ccw(pane), "x", -0.75 * W, 0.75 * W)
                for s in (-1, 1):
                    m.box("light", (s * 0.6 * W - 0.1 * W, end - 0.01, 0.38 * H), (s * 0.6 * W + 0.1 * W, end + 0.01, 0.44 * H),
                          rounded=0.0)
        windows = max(2, int((hi - lo) / (0.35 * H)))
        pitch = (hi - lo - 0.2 * car) / windows
        for k in range(windows):
            w0 = lo + 0.1 * car + k * pitch
            for s in (-1, 1):  # dark panes a hair proud of the side (clear glass would show the paint)
                x0, x1 = sorted((s * (W + 0.008), s * (W - 0.01)))  # inner faces apart from the door's
                m.box("screen", (x0, w0 + 0.08 * pitch, 0.55 * H), (x1, w0 + 0.92 * pitch, 0.8 * H), rounded=0.0)
        for s in (-1, 1):
            x0, x1 = sorted((s * (W + 0.004), s * (W - 0.015)))
            m.box("canvas_alt", (x0, y0 + 0.01 * car, 0.42 * H), (x1, y1 - 0.01 * car, 0.47 * H), rounded=0.0)
            x0, x1 = sorted((s * (W + 0.012), s * (W - 0.02)))
            for t in (0.3, 0.7):
                m.box("dark_plastic", (x0, y0 + t * car - 0.04 * car, floor + 0.02 * H), (x1, y0 + t * car + 0.04 * car, 0.82 * H),
                      rounded=0.0)
        for yb in (y0 + 0.2 * car, y1 - 0.2 * car):
            m.box("dark_metal", (-0.75 * W, yb - 2.4 * wr, 0.6 * wr), (0.75 * W, yb + 2.4 * wr, 1.9 * wr), rounded=0.0)
            for dy in (-1.2 * wr, 1.2 * wr):
                for s in (-1, 1):
                    _wheel(m, s * 0.85 * W, yb + dy, wr, 0.08 * m.sx, s)
        m.box("dark_metal", (-0.8 * W, y0 + 0.04 * car, 1.8 * wr), (0.8 * W, y1 - 0.04 * car, floor + 0.01 * H), rounded=0.0)
        m.box("metal", (-0.8 * W, lo + 0.02 * car, roof - 0.01 * H), (0.8 * W, hi - 0.02 * car, roof + 0.03 * H), rounded=0.0)
        if i < n - 1:
            m.box("rubber", (-0.55 * W, y1 - 0.01, floor + 0.05 * H), (0.55 * W, y1 + gap + 0.01, 0.85 * H), rounded=0.0)
    top = roof + 0.03 * H
    if m.has(*_ELECTRIC):
        y = -L + 0.5 * car
        for dy in (-0.12 * H, 0.12 * H):
            m.beam("dark_metal", (0, y + dy, top), (0, y, 0.96 * H), 0.015 * H)
        m.beam("dark_metal", (-0.5 * W, y, 0.97 * H), (0.5 * W, y, 0.97 * H), 0.02 * H, 0.06 * H)
    else:
        for i in range(n):
            y = -L + i * (car + gap) + 0.5 * car
            m.box("dark_metal", (-0.25 * W, y - 0.08 * car, top - 0.005), (0.25 * W, y + 0.08 * car, 0.97 * H), rounded=0.0)


def _locomotive(m: Model) -> None:
    """A steam locomotive: a boiler on a frame, a chimney, a cab, large driving wheels."""
    m.main = "dark_metal"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    wr = min(0.2 * H, 0.48 * 0.35 * L)  # driving wheels never overlap
    for k in range(3):
        y = -0.25 * L + k * 0.35 * L
        for s in (-1, 1):
            _wheel(m, s * 0.9 * W, y, wr, 0.1 * m.sx, s)
    for s in (-1, 1):
        _wheel(m, s * 0.85 * W, -0.8 * L, 0.6 * wr, 0.1 * m.sx, s)
    m.box("dark_metal", (-0.7 * W, -L, 0.8 * wr), (0.7 * W, L, 1.3 * wr))
    br = min(0.6 * W, 0.22 * H)
    m.cylinder("dark_metal", (0, -0.95 * L, 1.3 * wr + br), (0, 0.35 * L, 1.3 * wr + br), br)
    m.cylinder("accent", (0, -0.95 * L, 1.3 * wr + br), (0, -0.97 * L, 1.3 * wr + br), 0.9 * br)
    m.cylinder("dark_metal", (0, -0.75 * L, 1.3 * wr + 1.8 * br), (0, -0.75 * L, H), 0.3 * br, 0.4 * br, fraction=0.5)
    m.ball("brass", (0, -0.2 * L, 1.3 * wr + 2 * br), (0.3 * br, 0.4 * br, 0.3 * br), fraction=0.5)
    m.box("accent", (-W, 0.35 * L, 1.3 * wr), (W, L, 0.9 * H))
    m.box("glass", (-1.001 * W, 0.45 * L, 0.6 * H), (1.001 * W, 0.8 * L, 0.8 * H), rounded=0.0)
    m.box("dark_metal", (-1.05 * W, 0.3 * L, 0.9 * H), (1.05 * W, L, 0.95 * H))
    m.extrude("dark_metal", [(-L, 0.0), (-0.85 * L, 0.0), (-0.85 * L, 0.8 * wr), (-L, 0.8 * wr)], "x", -0.7 * W, 0.7 * W)
    m.box("light", (-0.2 * W, -0.99 * L, 1.3 * wr + 1.6 * br), (0.2 * W, -0.96 * L, 1.3 * wr + 1.9 * br))


def _balloon(m: Model) -> None:
    """A hot air balloon at rest: a striped envelope over a wicker basket on four ropes."""
    m.main = "paint"
    H = m.sz
    heights = np.array([0.36, 0.5, 0.72, 0.88, 0.97, 1.0]) * H
    radii = np.array([0.1, 0.3, 0.5, 0.45, 0.3, 0.0])
    m.lathe("paint", list(zip(radii, heights)), scale=(m.sx, m.sy))
    for z0, z1 in ((0.55, 0.62), (0.75, 0.82)):  # bands a hair outside the envelope
        zs = np.linspace(z0, z1, 3) * H
        m.lathe("flower_alt", [(1.01 * float(np.interp(z, heights, radii)), z) for z in zs], scale=(m.sx, m.sy))
    m.box("wood", (-0.1 * m.sx, -0.1 * m.sy, 0), (0.1 * m.sx, 0.1 * m.sy, 0.12 * H))
    m.cylinder("dark_metal", (0, 0, 0.2 * H), (0, 0, 0.26 * H), 0.04 * m.sx, fraction=0.5)
    for sx in (-1, 1):
        for sy in (-1, 1):
            m.beam("dark_wood", (sx * 0.09 * m.sx, sy * 0.09 * m.sy, 0.11 * H), (sx * 0.07 * m.sx, sy * 0.07 * m.sy, 0.37 * H),
                   0.01 * m.sx)


def _helicopter(m: Model) -> None:
    """A helicopter: a rounded cabin with a glazed nose, a tail boom with a fin and tail
    rotor, a main rotor on a mast, landing skids."""
    m.main = "paint"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    skid = 0.12 * H
    cz = skid + 0.32 * H
    m.ball("paint", (0, -0.35 * L, cz), (0.75 * W, 0.35 * L, 0.3 * H))
    m.ball("glass", (0, -0.55 * L, cz + 0.05 * H), (0.6 * W, 0.17 * L, 0.2 * H), fraction=0.6)
    m.cylinder("paint", (0, -0.1 * L, cz + 0.05 * H), (0, 0.9 * L, cz + 0.12 * H), 0.12 * H, 0.05 * H, fraction=0.6)
    m.extrude("accent", [(0.78 * L, cz + 0.1 * H), (0.95 * L, cz + 0.12 * H), (L, cz + 0.4 * H), (0.9 * L, cz + 0.38 * H)],
              "x", -0.02 * W, 0.02 * W)
    m.cylinder("dark_metal", (0.03 * W, 0.92 * L, cz + 0.2 * H), (0.15 * W, 0.92 * L, cz + 0.2 * H), 0.12 * H, fraction=0.5)
    top = cz + 0.3 * H
    m.post("dark_metal", 0, -0.3 * L, top - 0.05 * H, 0.95 * H, 0.05 * W, fraction=0.4)
    m.box("dark_metal", (-0.05 * W, -L, 0.95 * H), (0.05 * W, 0.45 * L, H), rounded=0.0)
    m.box("dark_metal", (-W, -0.33 * L, 0.955 * H), (W, -0.27 * L, 0.995 * H), rounded=0.0)
    for s in (-1, 1):
        m.cylinder("metal", (s * 0.8 * W, -0.8 * L, 0.5 * skid), (s * 0.8 * W, 0.1 * L, 0.5 * skid), 0.4 * skid, fraction=0.4)
        for y in (-0.55 * L, -0.1 * L):
            m.beam("metal", (s * 0.8 * W, y, 0.5 * skid), (s * 0.4 * W, y, cz - 0.2 * H), 0.3 * skid)


def _airship(m: Model) -> None:
    """An airship: a long envelope with tail fins, a gondola slung under it, propellers."""
    m.main = "canvas"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    cz = 0.62 * H
    m.ball("canvas", (0, 0, cz), (W, L, 0.38 * H))
    m.extrude("accent", [(0.55 * L, cz), (L, cz), (L, cz + 0.42 * H), (0.8 * L, cz + 0.3 * H)], "x", -0.03 * W, 0.03 * W)
    m.extrude("accent", [(0.55 * L, cz), (0.8 * L, cz - 0.3 * H), (L, cz - 0.42 * H), (L, cz)], "x", -0.03 * W, 0.03 * W)
    m.box("accent", (-W, 0.75 * L, cz - 0.02 * H), (W, 0.98 * L, cz + 0.02 * H), rounded=0.0)
    m.box("wood", (-0.25 * W, -0.35 * L, 0.05 * H), (0.25 * W, 0.15 * L, 0.24 * H))
    m.box("glass", (-0.26 * W, -0.3 * L, 0.14 * H), (0.26 * W, 0.1 * L, 0.2 * H), rounded=0.0)
    for y in (-0.3 * L, 0.1 * L):
        for s in (-1, 1):
            m.beam("dark_metal", (s * 0.2 * W, y, 0.24 * H), (s * 0.35 * W, y, 0.3 * H), 0.01 * m.sy + 0.01)
    for s in (-1, 1):
        m.cylinder("dark_metal", (s * 0.3 * W, 0.1 * L, 0.17 * H), (s * 0.45 * W, 0.2 * L, 0.17 * H), 0.04 * H, fraction=0.4)
        m.box("wood", (s * 0.45 * W - 0.01 * W, 0.2 * L, 0.05 * H), (s * 0.45 * W + 0.01 * W, 0.21 * L, 0.29 * H), rounded=0.0)


def _submarine(m: Model) -> None:
    """A submarine: a long round hull with rounded ends, a conning tower with a periscope,
    hydroplanes, a rudder and a propeller."""
    m.main = "dark_metal"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    r = min(W, 0.32 * H)
    cz = r
    m.cylinder("dark_metal", (0, -0.75 * L, cz), (0, 0.7 * L, cz), r, fraction=0.8)
    m.ball("dark_metal", (0, -0.75 * L, cz), (r, 0.25 * L, r), fraction=0.8)
    m.cylinder("dark_metal", (0, 0.7 * L, cz), (0, 0.95 * L, cz), r, 0.2 * r, fraction=0.8)
    m.extrude("paint", [(-0.3 * L, cz + 0.9 * r), (-0.05 * L, cz + 0.9 * r), (-0.08 * L, 0.8 * H), (-0.28 * L, 0.8 * H)],
              "x", -0.3 * W, 0.3 * W)
    m.post("metal", 0, -0.2 * L, 0.78 * H, H, 0.04 * W, fraction=0.4)
    m.box("metal", (-0.05 * W, -0.25 * L, 0.95 * H), (0.05 * W, -0.18 * L, H - 0.01 * H), rounded=0.0)
    m.box("dark_metal", (-0.95 * W, -0.25 * L, 0.62 * H - 0.02 * H), (0.95 * W, -0.12 * L, 0.62 * H), rounded=0.0)
    m.box("dark_metal", (-W, 0.8 * L, cz - 0.03 * r), (W, 0.9 * L, cz + 0.03 * r), rounded=0.0)
    m.extrude("dark_metal", [(0.82 * L, cz - 0.9 * r), (0.92 * L, cz - 0.9 * r), (0.92 * L, cz + 0.9 * r), (0.82 * L, cz + 0.9 * r)],
              "x", -0.02 * W, 0.02 * W)
    m.cylinder("brass", (0, 0.95 * L, cz), (0, L, cz), 0.5 * r, fraction=0.5)


def _minecart(m: Model) -> None:
    """A mine cart: a steel tub wider at the top, on four small wheels on two rails, heaped
    with ore when the text fills it."""
    m.main = "dark_metal"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    rail = 0.05 * H
    wr = min(0.17 * H, 0.4 * L)  # the two wheels of a side never overlap
    for s in (-1, 1):
        m.box("metal", (s * 0.6 * W - 0.04 * W, -L, 0), (s * 0.6 * W + 0.04 * W, L, rail), rounded=0.0)
        for y in (-0.45 * L, 0.45 * L):
            m.cylinder("dark_metal", (s * 0.6 * W, y, rail + wr), (s * 0.75 * W, y, rail + wr), wr, fraction=0.6)
    for y in (-0.85 * L, -0.3 * L, 0.3 * L, 0.85 * L):
        m.box("dark_wood", (-W, y - 0.06 * L, -0.001 * H), (W, y + 0.06 * L, 0.6 * rail), rounded=0.0)
    floor = rail + 1.3 * wr
    m.extrude("dark_metal", [(-0.7 * L, floor), (0.7 * L, floor), (0.9 * L, 0.8 * H), (-0.9 * L, 0.8 * H)], "x", -0.8 * W, 0.8 * W)
    m.box("metal", (-0.84 * W, -0.92 * L, 0.8 * H), (0.84 * W, 0.92 * L, 0.85 * H), rounded=0.0)
    for y in (-0.4 * L, 0.4 * L):
        m.box("metal", (-0.81 * W, y - 0.04 * L, floor + 0.1 * H), (0.81 * W, y + 0.04 * L, 0.79 * H), rounded=0.0)
    if m.has("ore", "coal", "gold", "gem", "rock", "stone", "full", "loaded"):
        role = "crystal" if m.has("glowing", "gem", "crystal", "gold") else "stone"
        for i in range(3):
            for j in range(4):
                c = (-0.5 * W + 0.5 * W * i, -0.6 * L + 0.4 * L * j, 0.85 * H + 0.05 * H * ((i + j) % 2))
                m.ball(role, c, (0.22 * W, 0.2 * L, 0.12 * H), fraction=0.4)


def _pram(m: Model) -> None:
    """A pram: a deep body with a folding hood, on a chassis of four wheels, a push handle."""
    m.main = "fabric"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    wr = 0.16 * H
    for s in (-1, 1):
        for y in (-0.6 * L, 0.6 * L):
            m.cylinder("rubber", (s * 0.85 * W, y, wr), (s * W, y, wr), wr, fraction=0.6)
        m.beam("metal", (s * 0.8 * W, -0.6 * L, wr), (s * 0.8 * W, 0.6 * L, wr), 0.02 * H)
        m.beam("metal", (s * 0.75 * W, 0.6 * L, wr), (s * 0.7 * W, L, 0.95 * H), 0.02 * H)
    m.cylinder("dark_plastic", (-0.75 * W, L, 0.95 * H), (0.75 * W, L, 0.95 * H), 0.025 * H, fraction=0.4)
    m.box("fabric", (-0.7 * W, -0.7 * L, 0.35 * H), (0.7 * W, 0.6 * L, 0.62 * H), rounded=0.3 * min(W, 0.3 * H))
    m.ball("canvas_alt", (0, 0.3 * L, 0.62 * H), (0.72 * W, 0.35 * L, 0.3 * H), fraction=0.6)


#: Names of craft that float: a word ending in -boat or -ship (craft that fly are matched
#: before it), or one of the few other words for a hull.
_WATERCRAFT = re.compile(r"\b(?:\w*boat|\w+ship|ship|barge|canoe|kayak|raft|ferry|yacht|galleon|dinghy|gondola|punt|dhow|"
                         r"sampan|trawler|schooner|frigate|steamer|clipper)s?\b")


def _caravan(m: Model) -> None:
    """A touring caravan: a tall white box on one axle in its middle, a coloured band, windows
    and a door along its sides, an A-frame drawbar with a jockey wheel at the front (not a car
    six metres long)."""
    m.main = "canvas_alt"
    W, L, H = m.sx / 2, m.sy / 2, m.sz
    wr = min(0.12 * H, 0.06 * m.sy)
    lo = 1.5 * wr
    y0 = -L + 0.15 * m.sy  # the body's front; the drawbar reaches forward from it
    m.box("canvas_alt", (-W, y0, lo), (W, L, H))
    m.box("paint", (-W - 0.005, y0 + 0.02, 0.42 * H), (W + 0.005, L - 0.02, 0.48 * H), rounded=0.0)
    span = L - y0
    for a, b in ((0.08, 0.4), (0.72, 0.93)):
        m.box("glass", (-W - 0.008, y0 + a * span, 0.58 * H), (W + 0.008, y0 + b * span, 0.8 * H), rounded=0.0)
    m.box("dark_plastic", (W - 0.01, y0 + 0.5 * span, lo + 0.04 * H), (W + 0.01, y0 + 0.64 * span, 0.85 * H), rounded=0.0)
    m.box("glass", (-0.6 * W, y0 - 0.008, 0.55 * H), (0.6 * W, y0 + 0.02, 0.75 * H), rounded=0.0)
    axle = y0 + 0.55 * span
    for s in (-1, 1):
        _wheel(m, s * (W + 0.01), axle, wr, 0.1 * m.sx, s)  # its face clear of the body side
        m.beam("dark_metal", (s * 0.5 * W, y0 + 0.01, lo + 0.01), (s * 0.02, -L + 0.03, 0.8 * lo), 0.04 * W + 0.02 + 0.002 * (s + 1))
    m.ball("dark_metal", (0, -L + 0.03, 0.8 * lo), (0.035,) * 3, fraction=0.4)
    m.post("metal", 0, -L + 0.06 * m.sy, 0.35 * wr, lo, 0.02 + 0.01 * W, fraction=0.4)
    m.cylinder("rubber", (-0.04, -L + 0.06 * m.sy, 0.35 * wr), (0.04, -L + 0.06 * m.sy, 0.35 * wr), 0.35 * wr, fraction=0.5)


def vehicle(m: Model) -> None:
    """A vehicle the catalogue does not know: tractor, forklift, golf cart, caravan, cart, battle
    tank, snowmobile, tracked crawler, train (steam or a diesel/electric unit, by its words), an aeroplane
    (propellers or jets, by its words), a flying craft (drone, spaceship, saucer), a boat (a name ending in -boat or -ship); else a car."""
    variants = (
        (("tractor", "bulldozer", "harvester", "combine"), _tractor),
        (("forklift", "fork lift", "pallet truck"), _forklift),
        (("golf cart", "buggy", "gokart", "go-kart", "kart", "rickshaw"), _golf_cart),
        (("army tank", "battle tank", "military tank", "panzer", "armored", "armoured", "tank"), _battle_tank),
        (("snowmobile", "skidoo", "ski-doo", "snow scooter", "motor sledge"), _snowmobile),
        (("snowcat", "tracked", "crawler", "half-track", "halftrack", "snow groomer", "piste basher", "caterpillar"), _tracked),
        (("locomotive", "train", "engine car", "steam engine", "railcar", "railbus", "multiple unit"), _train),
        (("hot air balloon", "balloon"), _balloon),
        (("minecart", "mine cart", "mine car", "ore cart", "ore car"), _minecart),
        (("caravan", "camper trailer", "travel trailer", "trailer home", "mobile home"), _caravan),
        (("cart", "wagon", "carriage", "stagecoach", "wheelbarrow", "trolley", "chariot",
          "trailer"), cart),
        (("pram", "stroller", "pushchair", "baby carriage", "perambulator"), _pram),
        (("helicopter", "chopper", "gyrocopter"), _helicopter),
        (("airship", "blimp", "zeppelin", "dirigible"), _airship),
        (("submarine", "u-boat", "sub"), _submarine),
        (("airplane", "aeroplane", "plane", "aircraft", "airliner", "jet", "jetliner", "biplane", "seaplane", "glider",
          "turboprop", "propeller plane", "cargo plane", "fighter jet"), _plane),
        (("spaceship", "spacecraft", "starship", "drone", "quadcopter", "ufo", "flying saucer", "saucer", "shuttle",
          "rocket ship"), craft),
    )
    build = m.first_named(variants)
    if build is None and _WATERCRAFT.search(m.name):
        build = boat  # "a longship", "a narrowboat", "a ferry": hulls, not wheels
    (build or car)(m)


SHAPES = {
    "vehicle": vehicle,
    "car": car, "truck": truck, "bus": bus, "bicycle": bicycle, "boat": boat, "cart": cart, "robot": robot,
    "treadmill": treadmill,
}
