"""Living things the catalogue does not know one by one: four-legged animals, birds and
standing figures, each recognisable by its silhouette (a camel's hump, an elephant's trunk,
a giraffe's neck, a knight's shield, a musician's instrument).

The object's length runs along y with its head toward −Y, as for vehicles.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from scenewright.analysis.composition.posture import KNEEL_HEIGHT, OWN_SEAT, SIT_HEIGHT, STOOL_HEIGHT, posture_in
from scenewright.core.colours import COLOURS
from scenewright.procedural import parts as P
from scenewright.procedural.builder import Model


@dataclass(frozen=True)
class Build:
    """A four-legged body as shares of its box: leg length and body half-height of the
    height, body half-length of the length, where the head sits (y share of the half
    length ahead of centre, z share of the height), head size, snout length of the head,
    leg thickness of the width, ears, tail, neck thickness of the head, body half-width of
    the width (small when wings take the width)."""

    coat: str = "fur"
    legs: float = 0.4
    girth: float = 0.17
    length: float = 0.3
    head_y: float = 0.8
    head_z: float = 0.8
    head: float = 0.12
    snout: float = 0.6
    leg: float = 0.09
    ears: str = "pointy"
    tail: str = "up"
    neck: float = 0.8
    width: float = 0.32


#: Names → build, first match wins (so "sea lion" or "dragon" are read before "lion").
ANIMALS: tuple[tuple[tuple[str, ...], Build], ...] = (
    (("dragon", "wyvern"), Build("scales", 0.32, 0.17, 0.27, 0.85, 0.72, 0.09, 1.0, 0.05, "horns", "long", 0.8, 0.15)),
    (("t-rex", "tyrannosaurus", "raptor", "velociraptor", "allosaurus"),
     Build("scales", 0.45, 0.14, 0.25, 0.8, 0.86, 0.12, 0.9, 0.1, "none", "long")),
    (("dinosaur", "brontosaurus", "diplodocus", "brachiosaurus", "sauropod", "stegosaurus", "triceratops"),
     Build("scales", 0.3, 0.22, 0.26, 0.95, 0.95, 0.05, 0.8, 0.12, "none", "long", 0.9)),
    (("camel", "dromedary", "llama", "alpaca"), Build("fur_light", 0.5, 0.13, 0.26, 0.95, 0.9, 0.07, 1.3, 0.07, "small", "hang", 0.7)),
    (("giraffe",), Build("fur_light", 0.45, 0.12, 0.24, 0.85, 0.94, 0.05, 1.2, 0.07, "horns", "hang", 0.8)),
    (("elephant", "mammoth"), Build("hide", 0.38, 0.27, 0.3, 0.75, 0.68, 0.17, 0.2, 0.14, "big", "hang", 1.1)),
    (("rhino", "rhinoceros", "hippo", "hippopotamus"), Build("hide", 0.25, 0.28, 0.34, 0.82, 0.55, 0.14, 0.6, 0.12, "small", "hang")),
    (("pig", "piglet", "hog", "boar", "swine"), Build("skin_pink", 0.2, 0.28, 0.36, 0.8, 0.5, 0.14, 0.45, 0.1, "floppy", "curl", 1.2)),
    (("sheep", "lamb", "ram"), Build("wool", 0.3, 0.26, 0.32, 0.8, 0.68, 0.1, 0.6, 0.07, "floppy", "none")),
    (("goat", "ibex"), Build("fur_white", 0.42, 0.17, 0.3, 0.82, 0.82, 0.1, 0.6, 0.07, "horns", "up")),
    (("cow", "bull", "ox", "cattle", "calf", "bison", "buffalo", "yak"),
     Build("fur_white", 0.4, 0.22, 0.34, 0.85, 0.72, 0.12, 0.55, 0.1, "horns", "hang")),
    (("horse", "pony", "donkey", "mule", "zebra", "unicorn", "stallion", "mare", "foal"),
     Build("fur", 0.47, 0.14, 0.32, 0.92, 0.93, 0.07, 1.8, 0.07, "small", "hang", 0.9, 0.3)),
    (("deer", "reindeer", "elk", "moose", "stag", "antelope", "gazelle"),
     Build("fur", 0.5, 0.14, 0.3, 0.9, 0.7, 0.08, 1.0, 0.06, "antlers", "up", 0.8)),
    (("tiger",), Build("fur_orange", 0.4, 0.17, 0.32, 0.85, 0.74, 0.14, 0.45, 0.1, "small", "long")),  # orange under its stripes
    (("lion", "lioness", "leopard", "cheetah", "panther", "jaguar", "puma", "cougar"),
     Build("fur_light", 0.4, 0.17, 0.32, 0.85, 0.74, 0.14, 0.45, 0.1, "small", "long")),
    (("bear", "panda"), Build("fur", 0.3, 0.26, 0.32, 0.85, 0.62, 0.15, 0.45, 0.13, "round", "none", 1.1)),
    (("fox", "wolf", "coyote", "jackal"), Build("fur_orange", 0.4, 0.15, 0.3, 0.85, 0.8, 0.12, 0.8, 0.08, "pointy", "bushy")),
    (("rabbit", "bunny", "hare"), Build("fur_white", 0.2, 0.3, 0.3, 0.7, 0.58, 0.17, 0.3, 0.1, "long", "puff")),
    (("mouse", "rat", "hamster", "squirrel"), Build("fur", 0.15, 0.3, 0.34, 0.8, 0.5, 0.18, 0.6, 0.07, "round", "long")),
    (("cat", "kitten", "kitty"), Build("fur", 0.38, 0.17, 0.3, 0.8, 0.82, 0.14, 0.3, 0.08, "pointy", "up")),
    (("dog", "puppy", "hound", "poodle", "retriever", "labrador", "terrier", "shepherd"),
     Build("fur", 0.4, 0.18, 0.3, 0.82, 0.8, 0.13, 0.65, 0.09, "floppy", "up")),
)


def build_of(m: Model) -> tuple[str, Build]:
    for words, build in ANIMALS:
        for word in words:
            if m.named(word):
                return word, build
    return "", Build()


def animal(m: Model) -> None:
    """A four-legged animal facing −Y; its name picks the build and the parts that make it
    that animal (hump, trunk and tusks, long neck, wings and tail, horns, mane, spots)."""
    if m.named("fish", "koi", "goldfish", "carp", "shark", "dolphin", "whale"):
        fish(m)
        return
    if m.named("seal", "sea lion", "walrus", "manatee", "dugong"):
        _pinniped(m)
        return
    kind, b = build_of(m)
    m.main = b.coat
    coat = b.coat
    face = "fur_dark" if kind in ("sheep", "lamb", "ram") else coat
    biped = m.named("t-rex", "tyrannosaurus", "raptor", "velociraptor", "allosaurus")
    leg_h = b.legs * m.sz
    gz = b.girth * m.sz
    body_y = 0.05 * m.sy if b.tail != "long" else -0.02 * m.sy
    half = b.length * m.sy
    bw = b.width * m.sx
    body_z = leg_h + gz
    m.ball(coat, (0, body_y, body_z), (bw, half, gz), fraction=0.8)
    leg = max(b.leg * m.sx, 0.02 * m.sy)
    if biped:
        for s in (-1, 1):
            hip = np.array([s * 0.55 * bw, body_y + 0.3 * half, body_z])
            knee = np.array([s * 0.6 * bw, body_y + 0.1 * half, 0.5 * leg_h])
            m.ball(coat, hip, (1.6 * leg, 2.2 * leg, 2.4 * leg), fraction=0.5)
            m.cylinder(coat, hip, knee, 1.3 * leg, leg, fraction=0.5)
            m.cylinder(coat, knee, (s * 0.6 * bw, body_y + 0.2 * half, 0.0), leg, 0.8 * leg, fraction=0.5)
            m.ball("dark_plastic", (s * 0.6 * bw, body_y + 0.05 * half, 0.25 * leg), (leg, 2 * leg, 0.25 * leg), fraction=0.4)
            m.cylinder(coat, (s * 0.6 * bw, body_y - 0.7 * half, body_z), (s * 0.8 * bw, body_y - 0.95 * half, body_z - 0.4 * gz),
                       0.3 * leg, 0.2 * leg, fraction=0.4)
    else:
        rocking = m.named("rocking horse", "rocking")
        for x in (-0.6 * bw, 0.6 * bw):
            for y in (body_y - 0.65 * half, body_y + 0.7 * half):
                top = body_z - 0.2 * gz
                foot = _rocker_z(m, y - body_y, half, leg) if rocking else 0.0
                m.cylinder(face, (x, y, top), (x, y, foot), leg, 0.8 * leg if b.leg < 0.12 else leg, fraction=0.5)
                m.ball(coat, (x, y, top - 0.1 * leg_h), (1.5 * leg, 1.8 * leg, 0.3 * leg_h + gz * 0.3), fraction=0.5)
                hoof = "dark_plastic" if kind not in ("elephant", "mammoth") else "horn"
                m.ball(hoof, (x, y - 0.15 * leg, foot + 0.2 * leg), (leg, 1.15 * leg, 0.2 * leg), fraction=0.4)
        if rocking:
            _rockers(m, bw, body_y, half, leg)
    # Neck and head.
    head = np.array([0.0, -b.head_y * m.sy / 2, b.head_z * m.sz])
    hr = b.head * m.sz
    hw = min(0.5 * bw + 0.3 * hr, 0.3 * m.sx)
    shoulder = np.array([0.0, body_y - 0.75 * half, body_z + 0.4 * gz])
    neck_r = min(b.neck * hr, 0.9 * hw, 0.6 * bw)
    m.cylinder(coat, shoulder, head + (0, 0.3 * hr, -0.3 * hr), 1.4 * neck_r, neck_r, fraction=0.6)
    m.ball(face, head, (hw, 1.1 * hr, hr), fraction=0.7)
    snout_len = b.snout * hr
    snout = head + (0, -hr - 0.4 * snout_len, -(0.3 + 0.15 * (b.snout > 1.2)) * hr)
    m.ball(face, snout, (0.65 * hw, 0.5 * snout_len + 0.4 * hr, 0.6 * hr), fraction=0.6)
    nose_role = "skin_pink" if kind in ("pig", "piglet", "hog", "swine") else "dark_plastic"
    m.ball(nose_role, snout + (0, -0.5 * snout_len - 0.35 * hr, 0.1 * hr), (0.3 * hw, 0.1 * hr, 0.25 * hr), fraction=0.4)
    for s in (-1, 1):
        m.ball("lacquer", head + (s * 0.6 * hw, -0.75 * hr, 0.3 * hr), (0.15 * hr,) * 3, fraction=0.4)
    _ears(m, b, face, head, hw, hr)
    _tail(m, b, coat, body_y + half, body_z, gz, bw)
    _features(m, kind, coat, head, hw, hr, snout, snout_len, body_y, half, body_z, gz, bw, shoulder)


def _rocker_z(m: Model, along: float, half: float, leg: float) -> float:
    """The height of a rocking horse's runner top ``along`` its length from the body's middle."""
    return 0.12 * m.sz * (along / (1.35 * half)) ** 2 + leg


def _rockers(m: Model, bw: float, body_y: float, half: float, leg: float) -> None:
    """Two curved wooden runners the hooves stand on, joined at their ends: a rocking horse."""
    ys = np.linspace(body_y - 1.35 * half, body_y + 1.35 * half, 9)
    zs = [_rocker_z(m, y - body_y, half, leg) - 0.5 * leg for y in ys]
    for x in (-0.6 * bw, 0.6 * bw):
        for k in range(len(ys) - 1):
            m.cylinder("dark_wood", (x, ys[k], zs[k]), (x, ys[k + 1], zs[k + 1]), 0.5 * leg, 0.5 * leg, fraction=0.4)
    for k in (0, -1):
        m.cylinder("dark_wood", (-0.6 * bw, ys[k], zs[k]), (0.6 * bw, ys[k], zs[k]), 0.4 * leg, 0.4 * leg, fraction=0.4)


def _ears(m: Model, b: Build, coat: str, head, hw: float, hr: float) -> None:
    for s in (-1, 1):
        side = head + (s * 0.7 * hw, 0.2 * hr, 0.6 * hr)
        if b.ears == "pointy":
            m.cylinder(coat, side, side + (s * 0.2 * hw, 0.1 * hr, 0.9 * hr), 0.3 * hr, 0.02 * hr, fraction=0.4)
        elif b.ears == "small":
            m.ball(coat, side, (0.2 * hr, 0.1 * hr, 0.3 * hr), fraction=0.4)
        elif b.ears == "round":
            m.ball(coat, side + (0, 0, 0.2 * hr), (0.35 * hr, 0.12 * hr, 0.35 * hr), fraction=0.4)
        elif b.ears == "floppy":
            m.ball(coat, head + (s * 1.0 * hw, 0.1 * hr, 0.0), (0.18 * hw, 0.35 * hr, 0.7 * hr), fraction=0.4)
        elif b.ears == "long":
            m.ball(coat, side + (0, 0.2 * hr, 1.0 * hr), (0.2 * hr, 0.12 * hr, 1.1 * hr), fraction=0.4)
        elif b.ears == "big":
            m.ball(coat, head + (s * (hw + 0.1 * hr), 0.4 * hr, 0.0), (0.12 * hr, 0.9 * hr, 1.2 * hr), fraction=0.6)
        elif b.ears in ("horns", "antlers"):
            m.ball(coat, side + (s * 0.1 * hw, 0.2 * hr, 0.0), (0.15 * hr, 0.1 * hr, 0.25 * hr), fraction=0.4)


def _tail(m: Model, b: Build, coat: str, back_y: float, body_z: float, gz: float, bw: float) -> None:
    root = np.array([0.0, back_y - 0.05 * m.sy, body_z + 0.3 * gz])
    r = 0.12 * bw
    if b.tail == "up":
        m.cylinder(coat, root, (0, m.sy / 2, body_z + 1.6 * gz), r, 0.4 * r, fraction=0.4)
    elif b.tail == "hang":
        m.cylinder(coat, root, (0, m.sy / 2 - 0.02 * m.sy, 0.45 * body_z), 0.8 * r, 0.5 * r, fraction=0.4)
        m.ball("fur_dark", (0, m.sy / 2 - 0.02 * m.sy, 0.42 * body_z), (r, r, 0.12 * body_z), fraction=0.4)
    elif b.tail == "bushy":
        m.ball(coat, (0, back_y + 0.1 * m.sy, body_z + 0.2 * gz), (1.8 * r, 0.18 * m.sy, 2 * r), fraction=0.5)
        m.ball("fur_white", (0, m.sy / 2 - 0.05 * m.sy, body_z + 0.25 * gz), (1.3 * r, 0.06 * m.sy, 1.4 * r), fraction=0.4)
    elif b.tail == "curl":
        m.torus(coat, root + (0, 0.03 * m.sy, 0.1 * gz), 0.12 * gz, 0.2 * r, axis="x", fraction=0.4)
    elif b.tail == "puff":
        m.ball("fur_white", root + (0, 0.03 * m.sy, 0), (2 * r, 2 * r, 2 * r), fraction=0.4)
    elif b.tail == "long":
        # A tapering tail in a few segments, sweeping down to the back end of the box.
        points = [root + (0, 0, 0)]
        for k in range(1, 5):
            t = k / 4
            points.append(np.array([0.0, root[1] + t * (m.sy / 2 - root[1]), root[2] * (1 - 0.75 * t)]))
        for k, (a, c) in enumerate(zip(points, points[1:])):
            m.cylinder(coat, a, c, 2.2 * r * (1 - k / 4.5), 2.2 * r * (1 - (k + 1) / 4.5), fraction=0.4)


def _features(m: Model, kind: str, coat: str, head, hw, hr, snout, snout_len, body_y, half, body_z, gz, bw, shoulder) -> None:
    """The parts that make a build this animal and not its neighbour."""
    top = body_z + gz
    if kind in ("camel", "dromedary"):
        humps = 1 if kind == "dromedary" or m.has("dromedary", "one hump", "one-humped") else 2
        for k in range(humps):
            y = body_y + (0.0 if humps == 1 else (-0.3 + 0.6 * k) * half)
            m.ball(coat, (0, y, top - 0.3 * gz), (0.7 * bw, 0.35 * half, 1.6 * gz), fraction=0.6)
    if kind in ("elephant", "mammoth"):
        tip = np.array([0.0, snout[1] - 0.2 * hr, 0.08 * m.sz])
        bend = np.array([0.0, snout[1] - 0.25 * hr, snout[2] - 0.9 * hr])
        m.cylinder(coat, snout, bend, 0.35 * hr, 0.25 * hr, fraction=0.5)
        m.cylinder(coat, bend, tip, 0.25 * hr, 0.15 * hr, fraction=0.5)
        for s in (-1, 1):
            base = snout + (s * 0.45 * hw, 0.1 * hr, -0.2 * hr)
            m.cylinder("horn", base, base + (s * 0.1 * hw, -0.9 * hr, -0.6 * hr), 0.1 * hr, 0.03 * hr, fraction=0.4)
    if kind in ("rhino", "rhinoceros"):
        m.cylinder("horn", snout + (0, -0.2 * snout_len, 0.4 * hr), snout + (0, -0.5 * snout_len, 1.3 * hr), 0.25 * hr, 0.0,
                   fraction=0.4)
    if kind == "giraffe" or kind in ("cow", "bull", "cattle", "calf"):
        spots = "fur" if kind == "giraffe" else "fur_dark"
        for k in range(9):
            a = m.vary(0, 2 * np.pi)
            y = body_y + m.vary(-0.7, 0.7) * half
            m.ball(spots, (np.cos(a) * 0.9 * bw, y, body_z + np.sin(a) * 0.9 * gz), (0.2 * bw, 0.1 * half, 0.3 * gz),
                   fraction=0.3)
        if kind == "giraffe":
            for t in np.linspace(0.2, 0.8, 4):
                p = shoulder + t * (head - shoulder)
                m.ball(spots, p + (0.2 * hw, -0.2 * hr, 0), (0.2 * hw, 0.3 * hr, 0.4 * hr), fraction=0.3)
    if m.named("zebra", "tiger"):
        # Stripes are hoops over the back, each fitted to the body's cross-section where it
        # sits (an ellipse narrowing toward the ends), apart from one another along it. The
        # hoop turns about y as the builder's y-axis arcs do: from +X over +Z to −X.
        about_y = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], float)
        for k in range(7):
            t = -0.8 + 1.6 * k / 6
            fit = np.sqrt(1 - t * t)
            hoop = P.torus(1.0, 0.08, m.segments(0.5), m.segments(0.5, 4), np.pi)
            scale = np.diag([fit * bw, 0.05 * half / 0.08, fit * gz])
            m.add("fur_dark", P.transform(hoop, P.affine(scale @ about_y, (0, body_y + t * half, body_z))))
    if m.named("horse", "pony", "zebra", "unicorn", "stallion", "mare", "donkey", "mule"):
        m.beam("fur_dark", shoulder + (0, 0.3 * hr, 0.5 * gz), head + (0, 0.4 * hr, 0.8 * hr), 0.25 * hw, 0.3 * hr)
        if m.named("unicorn"):
            m.cylinder("gold", head + (0, -0.4 * hr, 0.8 * hr), head + (0, -0.9 * hr, 2.2 * hr), 0.18 * hr, 0.0, fraction=0.4)
    if m.named("lion") and not m.named("lioness"):
        m.ball("fur_orange", head + (0, 0.5 * hr, 0.1 * hr), (1.5 * hw, 0.8 * hr, 1.5 * hr), fraction=0.6)
    if m.named("panda"):
        for s in (-1, 1):
            m.ball("fur_dark", head + (s * 0.5 * hw, -0.8 * hr, 0.25 * hr), (0.3 * hr, 0.12 * hr, 0.25 * hr), fraction=0.3)
    if m.named("sheep", "lamb", "ram"):
        for k in range(8):
            a = 2 * np.pi * k / 8
            c = (np.cos(a) * 0.75 * bw, body_y + m.vary(-0.6, 0.6) * half, body_z + np.sin(a) * 0.75 * gz)
            m.ball(coat, c, (0.45 * bw, 0.35 * half, 0.45 * gz), fraction=0.4)
        m.ball("fur_dark", head, (1.01 * hw, 1.05 * hr, 0.95 * hr), fraction=0.5)
    horned = {"cow": 0.6, "bull": 0.9, "ox": 0.8, "bison": 0.5, "buffalo": 0.9, "yak": 0.8, "goat": 1.0, "ibex": 1.3,
              "giraffe": 0.6, "dragon": 1.4, "wyvern": 1.2, "ram": 0.9, "triceratops": 1.2}.get(kind)
    if horned:
        for s in (-1, 1):
            base = head + (s * 0.5 * hw, 0.2 * hr, 0.7 * hr)
            tip = base + (s * 0.5 * hw * (kind in ("cow", "bull", "buffalo", "yak", "ox")), 0.9 * hr, 0.8 * horned * hr)
            m.cylinder("horn", base, tip, 0.2 * hr, 0.02 * hr, fraction=0.4)
    if m.named("deer", "reindeer", "elk", "moose", "stag"):
        for s in (-1, 1):
            base = head + (s * 0.5 * hw, 0.3 * hr, 0.8 * hr)
            crown = base + (s * 0.9 * hw, 0.6 * hr, 2.2 * hr)
            m.beam("horn", base, crown, 0.1 * hr)
            for t in (0.4, 0.7):
                p = base + t * (crown - base)
                m.beam("horn", p, p + (s * 0.2 * hw, -0.5 * hr, 0.6 * hr), 0.08 * hr)
    if kind in ("dragon", "wyvern"):
        for s in (-1, 1):
            root = np.array([s * 0.6 * bw, body_y - 0.4 * half, top - 0.2 * gz])
            elbow = np.array([s * 0.6 * m.sx / 2, body_y - 0.3 * half, m.sz])
            tip = np.array([s * m.sx / 2, body_y + 0.6 * half, m.sz * 0.6])
            m.beam("dark_plastic", root, elbow, 0.06 * bw)
            m.beam("dark_plastic", elbow, tip, 0.04 * bw)
            _membrane(m, root, elbow, tip, (s * 0.5 * bw, body_y + 0.5 * half, top))
        for k in range(6):
            y = body_y + (-0.8 + 1.6 * k / 5) * half
            m.cylinder("horn", (0, y, top - 0.1 * gz), (0, y + 0.05 * half, top + 0.5 * gz), 0.12 * bw, 0.0, fraction=0.3)
    if kind in ("stegosaurus",):
        for k in range(5):
            y = body_y + (-0.6 + 1.2 * k / 4) * half
            m.extrude("horn", [(y - 0.12 * half, top - 0.2 * gz), (y + 0.12 * half, top - 0.2 * gz), (y, top + 0.8 * gz)],
                      "x", -0.04 * bw, 0.04 * bw)


def _membrane(m: Model, root, elbow, tip, back) -> None:
    """A wing's skin: two thin triangles from the shoulder to the wing's bones, faceted,
    with a second sheet just above facing the other way so both sides show."""
    points = np.array([root, elbow, tip, back], float)
    lift = np.array([0.0, 0.0, 0.01 * m.sz])
    vertices = np.concatenate([points, points + lift])
    faces = np.array([[0, 1, 2], [0, 2, 3], [4, 6, 5], [4, 7, 6]])
    m.add("wing", P.flatten(P.Part(vertices, faces, np.zeros_like(vertices))))


def bird(m: Model) -> None:
    """A bird facing −Y: body, head, beak, wings, tail and legs; the name picks the build
    (an upright penguin or owl, a long-legged flamingo, a swan's curved neck, a duck)."""
    m.main = "feather"
    if m.named("penguin"):
        m.main = "fur_dark"
        m.ball("fur_dark", (0, 0.05 * m.sy, 0.45 * m.sz), (0.4 * m.sx, 0.4 * m.sy, 0.45 * m.sz))
        m.ball("fur_white", (0, -0.12 * m.sy, 0.42 * m.sz), (0.3 * m.sx, 0.3 * m.sy, 0.36 * m.sz), fraction=0.7)
        m.ball("fur_dark", (0, 0.0, 0.85 * m.sz), (0.26 * m.sx, 0.28 * m.sy, 0.15 * m.sz), fraction=0.7)
        m.cylinder("flower_alt", (0, -0.22 * m.sy, 0.85 * m.sz), (0, -m.sy / 2, 0.82 * m.sz), 0.06 * m.sx, 0.0, fraction=0.4)
        for s in (-1, 1):
            m.ball("fur_dark", (s * 0.42 * m.sx, 0.05 * m.sy, 0.45 * m.sz), (0.08 * m.sx, 0.2 * m.sy, 0.3 * m.sz), fraction=0.5)
            m.ball("flower_alt", (s * 0.15 * m.sx, -0.15 * m.sy, 0.02 * m.sz), (0.12 * m.sx, 0.2 * m.sy, 0.02 * m.sz), fraction=0.4)
            m.ball("lacquer", (s * 0.1 * m.sx, -0.22 * m.sy, 0.9 * m.sz), (0.03 * m.sx,) * 3, fraction=0.4)
        return
    long_legs = m.named("flamingo", "heron", "stork", "crane bird", "ostrich", "emu")
    swan = m.named("swan", "goose")
    upright = m.named("owl", "parrot", "eagle", "hawk", "falcon", "vulture")
    if m.named("flamingo"):
        m.main = "skin_pink"
    elif swan or m.named("dove", "seagull", "gull"):
        m.main = "fur_white"
    elif m.named("parrot", "macaw"):
        m.main = "accent"
    elif m.named("crow", "raven", "blackbird"):
        m.main = "fur_dark"
    coat = m.main
    leg_top = (0.5 if long_legs else 0.12 if not upright else 0.08) * m.sz
    if upright:
        body_c, body_r = (0, 0.08 * m.sy, leg_top + 0.3 * m.sz), (0.36 * m.sx, 0.3 * m.sy, 0.32 * m.sz)
        head_c, head_r = (0, -0.15 * m.sy, 0.82 * m.sz), (0.3 * m.sx, 0.28 * m.sy, 0.18 * m.sz)
    else:
        body_z = leg_top + (0.13 if long_legs else 0.25) * m.sz
        body_c, body_r = (0, 0.1 * m.sy, body_z), (0.32 * m.sx, 0.38 * m.sy, (0.13 if long_legs else 0.24) * m.sz)
        head_c, head_r = (0, -0.3 * m.sy, 0.85 * m.sz), (0.16 * m.sx, 0.14 * m.sy, 0.13 * m.sz)
    m.ball(coat, body_c, body_r)
    if long_legs or swan:
        neck0 = np.array([0.0, body_c[1] - 0.6 * body_r[1], body_c[2] + 0.5 * body_r[2]])
        bend = np.array([0.0, (0.0 if swan else -0.15) * m.sy, 0.5 * (neck0[2] + head_c[2]) + 0.1 * m.sz])
        m.cylinder(coat, neck0, bend, 0.09 * m.sx, 0.07 * m.sx, fraction=0.4)
        m.cylinder(coat, bend, head_c, 0.07 * m.sx, 0.06 * m.sx, fraction=0.4)
    m.ball(coat, head_c, head_r, fraction=0.7)
    beak = "flower_alt" if not m.named("owl", "eagle", "hawk", "falcon", "crow", "raven") else "dark_plastic"
    tip = (0, -m.sy / 2, head_c[2] - (0.08 if upright else 0.03) * m.sz)
    m.cylinder(beak, (0, head_c[1] - 0.8 * head_r[1], head_c[2]), tip, 0.35 * head_r[0], 0.0, fraction=0.4)
    for s in (-1, 1):
        eye = 0.3 * head_r[0] if m.named("owl") else 0.15 * head_r[0]
        m.ball("lacquer", (s * 0.5 * head_r[0], head_c[1] - 0.8 * head_r[1], head_c[2] + 0.2 * head_r[2]), (eye,) * 3,
               fraction=0.4)
        m.ball(coat if not m.named("parrot", "macaw") else "book_b", (s * body_r[0], body_c[1] + 0.1 * m.sy, body_c[2] + 0.1 * body_r[2]),
               (0.3 * body_r[0], 0.9 * body_r[1], 0.6 * body_r[2]), fraction=0.6)
        m.cylinder("flower_alt", (s * 0.3 * body_r[0], body_c[1], body_c[2] - 0.8 * body_r[2]), (s * 0.3 * body_r[0], body_c[1], 0.0),
                   0.025 * m.sx + 0.01 * m.sz, fraction=0.3)
    m.ball(coat, (0, m.sy / 2 - 0.12 * m.sy, body_c[2] + (0.0 if upright else 0.2 * body_r[2])), (0.2 * m.sx, 0.12 * m.sy, 0.04 * m.sz),
           fraction=0.5)


#: How many people a word for a group of them is drawn as ("a couple" two, "a crowd" eight).
_GROUP_SIZES = {"couple": 2, "trio": 3, "quartet": 4, "family": 4, "band": 4, "crew": 4, "team": 5, "group": 4,
                "party": 4, "gang": 4, "troupe": 5, "ensemble": 5, "entourage": 4, "choir": 8, "crowd": 8,
                "mob": 8, "audience": 10, "class": 10, "orchestra": 10, "congregation": 10}  # fmt: skip
#: Colours of shirts, coats and robes, and of trousers, one each per person.
_SHIRTS = ("navy", "blue", "maroon", "green", "olive", "mustard", "teal", "grey", "white", "burgundy", "rust", "khaki")
_TROUSERS = ("charcoal", "navy", "brown", "black", "khaki", "grey")
#: The width one person of a group takes in its row (m).
_PERSON_WIDTH = 0.45
#: A child's height in a family, as a share of the adults'.
_CHILD_HEIGHT = 0.62


def figure(m: Model) -> None:
    """A person facing −Y, standing, or kneeling, sitting or lying when the description says so
    (the composition writes the pose the text gives, ``analysis/composition/posture.py``); a word
    for several people ("a family", "a crowd") is that many of them."""
    count = next((n for word, n in _GROUP_SIZES.items() if m.named(word)), 0)
    if count:
        _group(m, count)
        return
    posture = None if m.named("scarecrow", "mannequin", "dress form", "dummy") else posture_in(m.text)
    if posture is None:
        _standing(m)
        return
    # Draw the standing person at the size the pose was folded from, then fold it (onto the
    # stool of its own when the text named no seat).
    stool = STOOL_HEIGHT if posture == "sitting" and OWN_SEAT in m.text.lower() and m.sz > 2 * STOOL_HEIGHT else 0.0
    w, d, h = m.sx, m.sy, m.sz - stool
    standing = {
        "sitting": (w, _DEPTH * h / SIT_HEIGHT, h / SIT_HEIGHT), "kneeling": (w, _DEPTH * h / KNEEL_HEIGHT, h / KNEEL_HEIGHT),
    }.get(posture, (w, h, d))
    inner = Model(standing, m.style, m.rng, main=m.main, name=m.name)
    inner.text = m.text
    _standing(inner)
    m.tints.update(inner.tints)
    fold = {"sitting": partial(_sit, below=stool), "kneeling": _kneel}.get(posture, _lie)
    lift = P.affine(np.eye(3), (0.0, 0.0, stool))
    for role, parts in inner.parts.items():
        for part in parts:
            m.add(role, P.transform(fold(part, inner), lift) if stool else fold(part, inner))
    m.main = inner.main
    if stool:
        seat_y, r = 0.35 * inner.sy, min(0.2, 0.45 * w)
        m.cylinder("dark_wood", (0, seat_y, stool - 0.04), (0, seat_y, stool), r, r, fraction=0.5)
        for a in (np.pi / 2, np.pi / 2 + 2 * np.pi / 3, np.pi / 2 + 4 * np.pi / 3):
            foot = (0.9 * r * np.cos(a), seat_y + 0.9 * r * np.sin(a), 0.0)
            m.cylinder("dark_wood", foot, (0.6 * r * np.cos(a), seat_y + 0.6 * r * np.sin(a), stool - 0.04), 0.02, 0.02,
                       fraction=0.3)


def _group(m: Model, count: int) -> None:
    """Several people that are one object: side by side in as few rows as its footprint takes,
    in the pose its description gives, a family's children smaller than its parents."""
    per_row = max(1, min(count, int(m.sx // _PERSON_WIDTH)))
    rows = -(-count // per_row)
    w, d = m.sx / per_row, m.sy / rows
    for k in range(count):
        row, col = divmod(k, per_row)
        child = m.named("family") and k >= 2
        one = Model((min(0.9 * w, 0.55), min(0.9 * d, 0.35), m.sz * (_CHILD_HEIGHT if child else m.vary(0.92, 1.0))),
                    m.style, m.rng, main=m.main, name="person")
        one.text = m.text
        figure(one)
        for role, tint in one.tints.items():
            m.tints.setdefault(role, tint)
        # (the last row, if short, keeps to the middle)
        in_row = min(per_row, count - row * per_row)
        offset = ((col - (in_row - 1) / 2) * w, -m.sy / 2 + (row + 0.5) * d, 0.0)
        for role, parts in one.parts.items():
            for part in parts:
                m.add(role, P.transform(part, P.affine(np.eye(3), offset)))
        m.main = one.main


#: A standing person's knee height as a share of their height: where the poses bend the leg.
_KNEE = 0.25
#: A standing person's depth as a share of their height (the catalogue's figure: 0.3 of 1.75 m).
_DEPTH = 0.17


def _sit(part: P.Part, m: Model, below: float = 0.0) -> P.Part:
    """Fold a standing part into sitting: above the hips it moves down and back (the seat at
    the bottom of the box), below them the thigh turns forward to the knee and the shin down to
    the floor in front, each leg section turning with its bone. On the floor the knees come up;
    on a stool ``below`` the seat the thighs lie level and the shins reach down toward the floor."""
    H = m.sz
    hip, knee = 0.48 * H, _KNEE * H
    thigh, shin = hip - knee, knee
    rise = np.radians(0.0 if below else 30.0)
    knee_at = np.array([0.0, -thigh * np.cos(rise), thigh * np.sin(rise)])
    drop = np.arcsin(min(1.0, (knee_at[2] + below) / shin))
    v, n = part.vertices.copy(), part.normals.copy()
    legs = v[:, 2] < hip
    t = hip - v[legs, 2]  # how far down the leg from the hip
    upper = t <= thigh

    def turn(angle: float, points: np.ndarray) -> np.ndarray:
        c, s_ = np.cos(angle), np.sin(angle)
        return np.stack([points[:, 0], c * points[:, 1] - s_ * points[:, 2], s_ * points[:, 1] + c * points[:, 2]], axis=1)

    # Standing, the leg runs along −z; the thigh turns it to point forward and up (−y, +z),
    # the shin forward and down. A rotation about x by φ takes −z to (0, sin φ, −cos φ).
    thigh_turn = -(np.pi / 2 + rise)
    shin_turn = -(np.pi / 2 - drop)
    local = np.stack([v[legs, 0], v[legs, 1], -t], axis=1)
    out = np.empty_like(local)
    out[upper] = turn(thigh_turn, local[upper])
    below = local[~upper].copy()
    below[:, 2] += thigh
    out[~upper] = turn(shin_turn, below) + knee_at
    v[legs] = out
    n[legs] = np.where(upper[:, None], turn(thigh_turn, n[legs]), turn(shin_turn, n[legs]))
    v[~legs, 2] -= hip
    back = 0.35 * m.sy
    v[~legs, 1] += back
    v[legs, 1] += back
    return P.Part(v, part.faces, n)


def _kneel(part: P.Part, m: Model) -> P.Part:
    """Fold a standing part into kneeling upright: the shins turn back to lie along the floor
    behind the knees (the feet with them, soles up), and all above the knees comes down by
    the shins' length; the box's middle stays the body's."""
    H = m.sz
    knee, shin_r = _KNEE * H, 0.045 * H
    v, n = part.vertices.copy(), part.normals.copy()
    shins = v[:, 2] < knee
    # a quarter turn about x takes the leg's −z (down the shin) to +y (back); its round section,
    # folded up to lie on the floor: (x, y, z) → (x, knee − z, |y| + r)
    t = knee - v[shins, 2]
    v[shins] = np.stack([v[shins, 0], t, np.abs(v[shins, 1]) + shin_r], axis=1)
    n[shins] = np.stack([n[shins, 0], -n[shins, 2], n[shins, 1]], axis=1)
    v[~shins, 2] += 2 * shin_r - knee
    v[:, 1] -= 0.5 * knee
    return P.Part(v, part.faces, n)


def _lie(part: P.Part, m: Model) -> P.Part:
    """Lay a standing part on its back, head toward +Y (the back of the box), face up."""
    turn = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
    return P.transform(part, P.affine(turn, (0.0, 0.0, 0.0)))


def _standing(m: Model) -> None:
    """A standing person facing −Y, and the figures the name makes of one: a musician with
    an instrument, a knight in armour, a wizard, a chef, an astronaut, a scarecrow, a
    mannequin on its stand, an alien."""
    if m.named("scarecrow"):
        _scarecrow(m)
        return
    if m.named("mannequin", "dress form", "dummy"):
        _mannequin(m)
        return
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    alien = m.named("alien", "martian", "extraterrestrial")
    knight = m.named("knight", "armour", "armor", "warrior", "paladin")
    astronaut = m.named("astronaut", "cosmonaut", "spaceman")
    robe = m.named("wizard", "witch", "monk", "priest", "sorcerer", "mage")
    chef = m.named("chef", "cook", "baker")
    if not (knight or astronaut or chef or alien):
        # one of the colours people dress in, seeded by the object, so a crowd is not all in blue
        # (a colour the text names still wins: it is described)
        m.tints.setdefault("clothes", COLOURS[_SHIRTS[int(m.rng.integers(len(_SHIRTS)))]])
        m.tints.setdefault("trousers", COLOURS[_TROUSERS[int(m.rng.integers(len(_TROUSERS)))]])
    skin = "alien" if alien else "skin"
    clothes = "metal" if knight else "fur_white" if astronaut or chef else skin if alien else "clothes"
    trousers = "metal" if knight else "fur_white" if astronaut else skin if alien else "trousers"
    m.main = clothes
    head_r = min(0.05 * H, 0.45 * W, 0.9 * D) * (1.6 if alien else 1.0)
    head_z = H - (3.2 if robe or chef else 1.15) * head_r
    shoulder_z = head_z - 1.6 * head_r - 0.02 * H
    hip_z = 0.48 * H
    leg_r = min(0.2 * W, 0.045 * H, 0.5 * D) * (0.6 if alien else 1.0)
    arm_r = min(0.12 * W, 0.03 * H, 0.4 * D) * (0.7 if alien else 1.0)
    hands = _pose(m, W, D, H, shoulder_z)
    # Legs and feet (under a robe only the feet show).
    for s in (-1, 1):
        x = s * 0.3 * W
        if not robe:  # thigh and shin apart, so a pose bends the leg at the knee
            m.cylinder(trousers, (x, 0, hip_z), (x, 0, _KNEE * H), leg_r, 0.9 * leg_r, fraction=0.5)
            m.cylinder(trousers, (x, 0, _KNEE * H), (x, 0, 0.05 * H), 0.9 * leg_r, 0.8 * leg_r, fraction=0.5)
        m.box("dark_plastic" if not (astronaut or knight) else trousers, (x - 0.9 * leg_r, -0.95 * D, 0),
              (x + 0.9 * leg_r, 0.3 * D, 0.05 * H), rounded=0.3 * leg_r)
    if robe:
        m.lathe(clothes, [(0.75 * W, 0.02 * H), (0.45 * W, 0.5 * H), (0.5 * W, shoulder_z), (0.25 * W, shoulder_z + 0.03 * H)],
                scale=(1, min(1.0, 0.9 * D / (0.75 * W))))
    else:
        m.lathe(clothes, [(0.42 * W, hip_z - 0.04 * H), (0.5 * W, hip_z + 0.03 * H), (0.44 * W, 0.6 * H), (0.58 * W, shoulder_z - 0.03 * H),
                          (0.3 * W, shoulder_z + 0.02 * H)], scale=(1, min(1.0, 0.6 * D / (0.5 * W))))
    if knight:
        m.lathe("accent", [(0.51 * W, hip_z - 0.05 * H), (0.54 * W, hip_z + 0.02 * H)], scale=(1, min(1.0, 0.6 * D / (0.5 * W))),
                fraction=0.6)
    # Arms to the hands the pose asks for.
    for s, hand in zip((-1, 1), hands):
        shoulder = np.array([s * 0.62 * W, 0.0, shoulder_z - 0.02 * H])
        elbow = np.array([s * 0.8 * W, 0.1 * D, 0.5 * (shoulder_z + hand[2])]) if hand[1] > -0.3 * D else \
            np.array([s * 0.75 * W, -0.1 * D, 0.55 * (shoulder_z + hand[2])])
        m.ball(clothes, shoulder, (1.3 * arm_r,) * 3, fraction=0.4)
        m.cylinder(clothes, shoulder, elbow, 1.15 * arm_r, arm_r, fraction=0.4)
        m.cylinder(clothes if robe or knight or astronaut else skin, elbow, hand, arm_r, 0.85 * arm_r, fraction=0.4)
        m.ball("dark_plastic" if knight else skin, hand, (1.1 * arm_r,) * 3, fraction=0.4)
    # Neck and head.
    m.cylinder(skin, (0, 0, shoulder_z - 0.02 * H), (0, 0, head_z - 0.5 * head_r), 0.45 * head_r * (0.5 if alien else 1.0),
               fraction=0.4)
    head = np.array([0.0, 0.0, head_z])
    m.ball(skin, head, (0.85 * head_r, 0.95 * head_r, 1.15 * head_r))
    eye = 0.12 * head_r
    for s in (-1, 1):
        if alien:
            m.ball("lacquer", head + (s * 0.38 * head_r, -0.75 * head_r, 0.05 * head_r), (0.3 * head_r, 0.12 * head_r, 0.2 * head_r),
                   fraction=0.5)
            m.cylinder(skin, head + (s * 0.3 * head_r, 0, 0.9 * head_r), head + (s * 0.6 * head_r, 0.1 * head_r, 1.15 * head_r),
                       0.05 * head_r, fraction=0.3)
            m.ball("light", head + (s * 0.6 * head_r, 0.1 * head_r, 1.15 * head_r), (0.1 * head_r,) * 3, fraction=0.3)
        elif not (knight or astronaut):
            m.ball("lacquer", head + (s * 0.32 * head_r, -0.88 * head_r, 0.1 * head_r), (eye,) * 3, fraction=0.3)
    if knight:
        m.ball("metal", head + (0, 0, 0.1 * head_r), (0.95 * head_r, 1.05 * head_r, 1.2 * head_r))
        m.box("dark_plastic", (-0.6 * head_r, -1.07 * head_r, head_z + 0.05 * head_r), (0.6 * head_r, -0.8 * head_r, head_z + 0.2 * head_r),
              rounded=0.0)
        m.ball("accent", head + (0, 0.2 * head_r, 1.25 * head_r), (0.12 * head_r, 0.6 * head_r, 0.3 * head_r), fraction=0.4)
    elif astronaut:
        m.ball("fur_white", head, (1.05 * head_r, 1.1 * head_r, 1.2 * head_r))
        m.ball("glass", head + (0, -0.35 * head_r, 0), (0.75 * head_r, 0.8 * head_r, 0.75 * head_r), fraction=0.6)
        m.box("metal", (-0.45 * W, 0.4 * D, hip_z + 0.05 * H), (0.45 * W, 0.98 * D, shoulder_z), rounded=0.05 * W)
    elif robe:
        m.lathe("clothes", [(1.4 * head_r, head_z + 0.5 * head_r), (0.0, H)], fraction=0.5)
        m.lathe("clothes", [(1.7 * head_r, head_z + 0.45 * head_r), (1.7 * head_r, head_z + 0.55 * head_r)], fraction=0.5)
        m.ball("fur_white", head + (0, -0.7 * head_r, -0.9 * head_r), (0.55 * head_r, 0.3 * head_r, 0.8 * head_r), fraction=0.4)
    elif chef:
        m.lathe("fur_white", [(0.8 * head_r, head_z + 0.6 * head_r), (1.0 * head_r, H - 0.3 * head_r), (0.5 * head_r, H)],
                fraction=0.5)
    elif not alien:
        m.ball("hair", head + (0, 0.15 * head_r, 0.25 * head_r), (0.92 * head_r, 0.9 * head_r, 1.0 * head_r), fraction=0.6)
    _held(m, W, D, H, hands, arm_r, hip_z, shoulder_z, knight, robe)


#: Instruments by the words that name them or their player; the first found is held.
_INSTRUMENTS = (
    ("violin", ("violin", "violinist", "fiddle", "fiddler", "viola")),
    ("trumpet", ("trumpet", "trumpeter", "saxophone", "saxophonist", "sax", "trombone", "horn player", "clarinet")),
    ("drum", ("drum", "drummer", "percussionist", "bongo")),
    ("accordion", ("accordion", "accordionist")),
    ("microphone", ("singer", "vocalist", "rapper", "comedian", "speaker")),
    ("guitar", ("guitar", "guitarist", "musician", "busker", "bard", "minstrel", "banjo", "ukulele", "lute", "band")),
)


def _instrument(m: Model) -> str | None:
    return next((kind for kind, words in _INSTRUMENTS if m.named(*words)), None)


def _pose(m: Model, W: float, D: float, H: float, shoulder_z: float):
    """Where the two hands are (left, right): hanging, or at the instrument or weapon."""
    kind = _instrument(m)
    hang = (np.array([-0.9 * W, -0.05 * D, 0.47 * H]), np.array([0.9 * W, -0.05 * D, 0.47 * H]))
    if kind == "guitar":
        return np.array([-0.85 * W, -0.75 * D, 0.62 * H]), np.array([0.25 * W, -0.8 * D, 0.52 * H])
    if kind == "violin":
        return np.array([-0.7 * W, -0.85 * D, shoulder_z]), np.array([0.5 * W, -0.8 * D, 0.7 * H])
    if kind == "trumpet":
        return np.array([-0.2 * W, -0.85 * D, shoulder_z - 0.02 * H]), np.array([0.2 * W, -0.85 * D, shoulder_z - 0.02 * H])
    if kind in ("drum", "accordion"):
        return np.array([-0.55 * W, -0.8 * D, 0.58 * H]), np.array([0.55 * W, -0.8 * D, 0.58 * H])
    if kind == "microphone":
        return hang[0], np.array([0.3 * W, -0.8 * D, shoulder_z + 0.02 * H])
    if m.named("knight", "armour", "armor", "warrior", "paladin", "wizard", "sorcerer", "mage", "witch", "monk", "priest"):
        return np.array([-0.85 * W, -0.55 * D, 0.55 * H]), np.array([0.85 * W, -0.5 * D, 0.5 * H])
    return hang


def _held(m: Model, W, D, H, hands, arm_r, hip_z, shoulder_z, knight: bool, robe: bool) -> None:
    """What the figure holds: its instrument, a knight's sword and shield, a wizard's staff."""
    kind = _instrument(m)
    left, right = hands
    if kind == "guitar":
        lower, upper = min(0.1 * H, 0.9 * W), min(0.075 * H, 0.7 * W)
        body = np.array([0.15 * W, -0.85 * D, 0.5 * H])
        waist = body + (-0.8 * lower, 0, 0.6 * lower)
        m.cylinder("wood", body + (0, 0.12 * D, 0), body + (0, -0.12 * D, 0), lower, fraction=0.7)
        m.cylinder("wood", waist + (0, 0.1 * D, 0), waist + (0, -0.1 * D, 0), upper, fraction=0.7)
        m.cylinder("dark_plastic", waist + (0.2 * lower, -0.13 * D, -0.2 * lower), waist + (0.2 * lower, -0.14 * D, -0.2 * lower),
                   0.35 * upper, fraction=0.5)
        m.beam("dark_wood", waist + (-0.6 * upper, -0.05 * D, 0.4 * upper), left + (-0.2 * W, 0, 0.05 * H), 0.12 * upper, 0.05 * D)
    elif kind == "violin":
        m.ball("wood", left + (0.3 * W, 0.1 * D, -0.02 * H), (0.25 * W, 0.1 * D, 0.05 * H), fraction=0.5)
        m.beam("dark_wood", left + (0.3 * W, 0.1 * D, 0), left + (-0.15 * W, -0.1 * D, -0.03 * H), 0.04 * W, 0.04 * D)
        m.beam("wood", right, right + (-0.9 * W, -0.05 * D, 0.08 * H), 0.015 * W + 0.005 * H, 0.01 * D)
    elif kind == "trumpet":
        mouth = np.array([0.0, -0.6 * D, shoulder_z + 0.08 * H])
        m.cylinder("brass", mouth, mouth + (0, -0.4 * D, -0.03 * H), 0.03 * W, 0.03 * W, fraction=0.4)
        m.cylinder("brass", mouth + (0, -0.4 * D, -0.03 * H), (0, -D, shoulder_z + 0.02 * H), 0.04 * W, 0.2 * W, fraction=0.5)
    elif kind == "drum":
        m.cylinder("canvas", (0, -0.75 * D, 0.35 * H), (0, -0.75 * D, 0.5 * H), 0.5 * W, fraction=0.7)
        m.cylinder("canvas_alt", (0, -0.75 * D, 0.5 * H), (0, -0.75 * D, 0.505 * H), 0.48 * W, fraction=0.7)
        for s in (-1, 1):
            m.beam("wood", hands[(s + 1) // 2], hands[(s + 1) // 2] + (-s * 0.2 * W, -0.1 * D, 0.08 * H), 0.02 * W + 0.003 * H)
    elif kind == "accordion":
        m.box("accent", (-0.5 * W, -0.95 * D, 0.5 * H), (0.5 * W, -0.55 * D, 0.68 * H), rounded=0.02 * W)
        for k in range(5):
            x = -0.4 * W + 0.2 * W * k
            m.box("canvas_alt", (x - 0.03 * W, -0.97 * D, 0.52 * H), (x + 0.03 * W, -0.94 * D, 0.66 * H), rounded=0.0)
    elif kind == "microphone":
        m.cylinder("dark_metal", right + (0, 0, -0.02 * H), right + (0, 0, 0.06 * H), 0.06 * W, 0.04 * W, fraction=0.4)
        m.ball("dark_metal", right + (0, -0.02 * D, 0.08 * H), (0.1 * W,) * 3, fraction=0.4)
    if knight:
        m.cylinder("paint", left + (-0.05 * W, -0.25 * D, 0.0), left + (-0.05 * W, -0.4 * D, 0.0), 0.5 * min(W, 0.25 * H),
                   fraction=0.7)
        m.cylinder("gold", left + (-0.05 * W, -0.41 * D, 0.0), left + (-0.05 * W, -0.43 * D, 0.0), 0.15 * min(W, 0.25 * H),
                   fraction=0.5)
        m.beam("chrome", right, (right[0], right[1] - 0.2 * D, 0.1 * H), 0.08 * W, 0.02 * D + 0.004)
        m.beam("brass", right + (-0.2 * W, 0, -0.02 * H), right + (0.2 * W, 0, -0.02 * H), 0.05 * W)
    if robe:
        m.post("dark_wood", right[0], right[1], 0.0, 0.95 * H, 1.2 * arm_r, fraction=0.4)
        m.ball("crystal", (right[0], right[1], 0.95 * H), (2.5 * arm_r,) * 3, fraction=0.4)


def _scarecrow(m: Model) -> None:
    """A post with a crossbar for arms, an old shirt on it, a sack head and a straw hat."""
    m.main = "clothes"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    post = min(0.06 * W, 0.3 * D) + 0.01 * H
    m.post("wood", 0, 0, 0, 0.88 * H, post, fraction=0.4)
    arms_z = 0.66 * H
    m.beam("wood", (-0.95 * W, 0, arms_z), (0.95 * W, 0, arms_z), 1.4 * post)
    m.lathe("clothes", [(0.25 * W, 0.35 * H), (0.3 * W, 0.5 * H), (0.3 * W, arms_z + 0.03 * H), (0.15 * W, arms_z + 0.06 * H)],
            scale=(1, min(1.0, 0.7 * D / (0.3 * W))))
    for s in (-1, 1):
        m.cylinder("clothes", (s * 0.25 * W, 0, arms_z), (s * 0.8 * W, 0, arms_z), 0.07 * H, 0.05 * H, fraction=0.5)
        m.cylinder("straw", (s * 0.8 * W, 0, arms_z), (s * W, 0, arms_z - 0.03 * H), 0.04 * H, 0.01 * H, fraction=0.4)
        m.cylinder("trousers", (s * 0.12 * W, 0, 0.38 * H), (s * 0.15 * W, 0, 0.2 * H), 0.05 * H, 0.045 * H, fraction=0.4)
        m.cylinder("straw", (s * 0.15 * W, 0, 0.2 * H), (s * 0.17 * W, 0, 0.15 * H), 0.04 * H, 0.01 * H, fraction=0.4)
    m.box("accent", (-0.12 * W, -0.75 * D, 0.48 * H), (0.05 * W, -0.7 * D, 0.56 * H), rounded=0.0)
    head = np.array([0.0, 0.0, 0.8 * H])
    r = min(0.09 * H, 0.4 * W, 0.8 * D)
    m.ball("canvas_alt", head, (r, 0.9 * r, 1.1 * r))
    for s in (-1, 1):
        m.ball("dark_plastic", head + (s * 0.35 * r, -0.85 * r, 0.15 * r), (0.12 * r,) * 3, fraction=0.3)
    m.lathe("straw", [(2.1 * r, head[2] + 0.65 * r), (2.1 * r, head[2] + 0.75 * r), (0.8 * r, head[2] + 0.8 * r),
                      (0.6 * r, H)], fraction=0.6)


def _mannequin(m: Model) -> None:
    """A tailor's mannequin: a smooth torso on a pole over a round foot."""
    m.main = "plastic"
    W, D, H = m.sx / 2, m.sy / 2, m.sz
    m.lathe("dark_wood", [(0.9 * min(W, D), 0), (0.9 * min(W, D), 0.02 * H), (0.15 * min(W, D), 0.04 * H)], fraction=0.6)
    m.post("metal", 0, 0, 0.02 * H, 0.5 * H, 0.04 * min(W, D) + 0.005, fraction=0.4)
    m.lathe("plastic", [(0.6 * W, 0.45 * H), (0.75 * W, 0.55 * H), (0.55 * W, 0.68 * H), (0.8 * W, 0.82 * H), (0.85 * W, 0.88 * H),
                        (0.2 * W, 0.93 * H), (0.15 * W, 0.97 * H), (0.2 * W, H), (0, H)], scale=(1, min(1.0, 0.8 * D / (0.85 * W))))
    for s in (-1, 1):
        m.ball("plastic", (s * 0.85 * W, 0, 0.86 * H), (0.15 * W, 0.2 * min(W, D), 0.04 * H), fraction=0.5)


SHAPES = {"animal": animal, "bird": bird, "figure": figure}


def _pinniped(m: Model) -> None:
    """A seal (a sea lion, a walrus) lying with its head up, toward −Y: a long tapering body on
    the ground, flippers at the front and a pair spread flat behind; a walrus has its tusks."""
    m.main = "hide"
    body_z = 0.32 * m.sz
    m.ball("hide", (0, 0.08 * m.sy, body_z), (0.45 * m.sx, 0.4 * m.sy, body_z))
    m.ball("hide", (0, -0.3 * m.sy, 0.5 * m.sz), (0.32 * m.sx, 0.16 * m.sy, 0.3 * m.sz), fraction=0.7)
    head = np.array([0.0, -0.4 * m.sy, 0.78 * m.sz])
    m.ball("hide", head, (0.24 * m.sx, 0.1 * m.sy, 0.2 * m.sz), fraction=0.6)
    for s in (-1, 1):
        m.ball("lacquer", head + (s * 0.12 * m.sx, -0.08 * m.sy, 0.06 * m.sz), (0.04 * m.sx, 0.02 * m.sy, 0.04 * m.sz),
               fraction=0.3)
        m.leaf("hide", (s * 0.3 * m.sx, -0.22 * m.sy, 0.2 * m.sz), (s * 0.5 * m.sx, -0.3 * m.sy, 0.02 * m.sz),
               0.12 * m.sx, 0.03 * m.sz)
        m.leaf("hide", (s * 0.05 * m.sx, 0.4 * m.sy, 0.1 * m.sz), (s * 0.3 * m.sx, m.sy / 2, 0.02 * m.sz),
               0.15 * m.sx, 0.03 * m.sz)
        if m.named("walrus"):
            m.cylinder("horn", head + (s * 0.08 * m.sx, -0.09 * m.sy, -0.08 * m.sz),
                       head + (s * 0.08 * m.sx, -0.1 * m.sy, -0.6 * m.sz), 0.02 * m.sx, 0.01 * m.sx, fraction=0.3)


def fish(m: Model) -> None:
    """A fish (or shark, dolphin, whale) swimming toward −Y: body, tail fin, fins, eyes."""
    m.main = "hide" if m.named("shark", "dolphin", "whale") else "fur_orange"
    coat = m.main
    body_z = 0.5 * m.sz
    m.ball(coat, (0, -0.08 * m.sy, body_z), (0.45 * m.sx, 0.38 * m.sy, 0.38 * m.sz))
    m.ball("fur_white", (0, -0.1 * m.sy, body_z - 0.1 * m.sz), (0.4 * m.sx, 0.33 * m.sy, 0.3 * m.sz), fraction=0.7)
    m.extrude(coat, [(0.25 * m.sy, body_z), (m.sy / 2, m.sz), (0.42 * m.sy, body_z), (m.sy / 2, 0.0)], "x", -0.04 * m.sx, 0.04 * m.sx)
    m.extrude(coat, [(-0.2 * m.sy, 0.8 * m.sz), (0.1 * m.sy, 0.8 * m.sz), (0.05 * m.sy, m.sz if m.named("shark", "dolphin") else 0.92 * m.sz)],
              "x", -0.03 * m.sx, 0.03 * m.sx)
    for s in (-1, 1):
        m.ball("lacquer", (s * 0.3 * m.sx, -0.33 * m.sy, body_z + 0.08 * m.sz), (0.06 * m.sx, 0.04 * m.sy, 0.06 * m.sz), fraction=0.4)
        m.leaf(coat, (s * 0.35 * m.sx, -0.1 * m.sy, 0.4 * m.sz), (s * m.sx / 2, 0.05 * m.sy, 0.25 * m.sz), 0.05 * m.sy, 0.01 * m.sz)
