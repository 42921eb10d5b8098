"""Colour and material words of a description → the surface of an object's main part.

"a dark blue velvet sofa" should come out dark blue and soft whatever the style's palette
says; the style still tints it (pastel in anime, saturated in cartoon), as an artist of
that style would.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection
from dataclasses import replace

from scenewright.procedural.style import Surface

COLOURS: dict[str, tuple[float, float, float]] = {
    "red": (0.75, 0.1, 0.1), "crimson": (0.7, 0.06, 0.15), "scarlet": (0.85, 0.12, 0.08),
    "maroon": (0.42, 0.06, 0.08), "burgundy": (0.45, 0.07, 0.15), "orange": (0.95, 0.5, 0.1),
    "amber": (0.95, 0.65, 0.1), "yellow": (0.95, 0.85, 0.2), "mustard": (0.8, 0.65, 0.15),
    "olive": (0.45, 0.45, 0.15), "lime": (0.6, 0.85, 0.2), "green": (0.15, 0.55, 0.2),
    "emerald": (0.05, 0.55, 0.35), "mint": (0.6, 0.9, 0.75), "teal": (0.05, 0.5, 0.5),
    "turquoise": (0.2, 0.8, 0.75), "cyan": (0.1, 0.85, 0.9), "aqua": (0.3, 0.85, 0.85),
    "sky blue": (0.5, 0.75, 0.95), "blue": (0.12, 0.3, 0.75), "navy": (0.06, 0.1, 0.32),
    "cobalt": (0.05, 0.25, 0.65), "indigo": (0.25, 0.1, 0.5), "purple": (0.45, 0.15, 0.6),
    "violet": (0.55, 0.3, 0.8), "lavender": (0.75, 0.65, 0.9), "lilac": (0.8, 0.65, 0.85),
    "magenta": (0.85, 0.1, 0.65), "pink": (0.95, 0.55, 0.7), "rose": (0.9, 0.4, 0.5),
    "peach": (0.98, 0.72, 0.58), "coral": (0.95, 0.45, 0.38), "salmon": (0.95, 0.55, 0.48),
    "brown": (0.4, 0.25, 0.13), "chocolate": (0.3, 0.17, 0.08), "tan": (0.78, 0.64, 0.45),
    "beige": (0.87, 0.8, 0.66), "khaki": (0.74, 0.7, 0.5), "cream": (0.96, 0.93, 0.82),
    "ivory": (0.97, 0.95, 0.88), "white": (0.93, 0.93, 0.93), "black": (0.04, 0.04, 0.04),
    "grey": (0.5, 0.5, 0.5), "gray": (0.5, 0.5, 0.5), "charcoal": (0.2, 0.2, 0.22),
    "silver": (0.78, 0.79, 0.8), "golden": (1.0, 0.77, 0.34), "whitewashed": (0.92, 0.91, 0.88),
    "limewashed": (0.92, 0.91, 0.88),
}

_MODIFIERS = {
    "dark": lambda c: tuple(0.45 * x for x in c),
    "deep": lambda c: tuple(0.6 * x for x in c),
    "light": lambda c: tuple(x + (1 - x) * 0.45 for x in c),
    "pale": lambda c: tuple(x + (1 - x) * 0.5 for x in c),
    "pastel": lambda c: tuple(x + (1 - x) * 0.55 for x in c),
    "bright": lambda c: tuple(min(1.0, 1.2 * x) for x in c),
    "vivid": lambda c: tuple(min(1.0, 1.2 * x) for x in c),
    "muted": lambda c: tuple(0.7 * x + 0.3 * sum(c) / 3 for x in c),
}

MATERIALS: dict[str, Surface] = {
    "wood": Surface((0.55, 0.38, 0.22), 0.0, 0.6), "oak": Surface((0.66, 0.49, 0.3), 0.0, 0.6),
    "walnut": Surface((0.34, 0.21, 0.12), 0.0, 0.55), "pine": Surface((0.82, 0.66, 0.44), 0.0, 0.65),
    "mahogany": Surface((0.42, 0.16, 0.09), 0.0, 0.45), "cherry": Surface((0.55, 0.24, 0.14), 0.0, 0.5),
    "teak": Surface((0.6, 0.42, 0.22), 0.0, 0.55), "birch": Surface((0.86, 0.76, 0.6), 0.0, 0.6),
    "bamboo": Surface((0.8, 0.7, 0.42), 0.0, 0.55), "ebony": Surface((0.08, 0.06, 0.05), 0.0, 0.4),
    "wicker": Surface((0.76, 0.6, 0.38), 0.0, 0.85), "rattan": Surface((0.76, 0.6, 0.38), 0.0, 0.85),
    "metal": Surface((0.62, 0.63, 0.65), 1.0, 0.35), "steel": Surface((0.66, 0.67, 0.7), 1.0, 0.3),
    "iron": Surface((0.3, 0.3, 0.31), 1.0, 0.6), "aluminium": Surface((0.85, 0.86, 0.88), 1.0, 0.3),
    "aluminum": Surface((0.85, 0.86, 0.88), 1.0, 0.3), "chrome": Surface((0.92, 0.92, 0.94), 1.0, 0.06),
    "brass": Surface((0.78, 0.6, 0.28), 1.0, 0.3), "copper": Surface((0.8, 0.45, 0.3), 1.0, 0.3),
    "bronze": Surface((0.6, 0.42, 0.22), 1.0, 0.4), "gold": Surface((1.0, 0.77, 0.34), 1.0, 0.2),
    "silver": Surface((0.9, 0.9, 0.92), 1.0, 0.15),
    "glass": Surface((0.82, 0.9, 0.95), 0.0, 0.05, alpha=0.35, transmission=1.0),
    "crystal": Surface((0.85, 0.92, 1.0), 0.0, 0.05, alpha=0.5, transmission=0.9), "marble": Surface((0.92, 0.91, 0.88), 0.0, 0.2),
    "granite": Surface((0.45, 0.44, 0.43), 0.0, 0.4), "stone": Surface((0.56, 0.55, 0.52), 0.0, 0.9),
    "concrete": Surface((0.62, 0.61, 0.58), 0.0, 0.95), "brick": Surface((0.6, 0.28, 0.2), 0.0, 0.9),
    "leather": Surface((0.36, 0.2, 0.12), 0.0, 0.5), "velvet": Surface((0.45, 0.08, 0.15), 0.0, 1.0),
    "fabric": Surface((0.6, 0.6, 0.6), 0.0, 0.95), "linen": Surface((0.85, 0.82, 0.74), 0.0, 0.95),
    "cotton": Surface((0.9, 0.9, 0.88), 0.0, 0.95), "wool": Surface((0.8, 0.76, 0.68), 0.0, 1.0),
    "plastic": Surface((0.9, 0.9, 0.88), 0.0, 0.45), "ceramic": Surface((0.94, 0.94, 0.92), 0.0, 0.2),
    "porcelain": Surface((0.96, 0.96, 0.95), 0.0, 0.15), "rubber": Surface((0.06, 0.06, 0.06), 0.0, 0.9),
    "paper": Surface((0.92, 0.9, 0.84), 0.0, 0.9), "jade": Surface((0.3, 0.65, 0.45), 0.0, 0.25),
    "neon": Surface((0.2, 0.2, 0.2), 0.0, 0.3, (0.0, 0.9, 1.0)),
}
_ADJECTIVES = {"wooden": "wood", "metallic": "metal", "metal": "metal", "golden": "gold", "stony": "stone",
               "glassy": "glass", "leathery": "leather", "marbled": "marble", "plush": "velvet",
               "upholstered": "fabric", "iron-wrought": "iron", "wrought-iron": "iron", "chromed": "chrome"}

_COLOUR_RE = re.compile(
    r"\b(?:(%s)[\s-]+)?(%s)\b" % ("|".join(_MODIFIERS), "|".join(sorted(COLOURS, key=len, reverse=True)))
)
_MATERIAL_WORDS = "|".join(sorted(list(MATERIALS) + list(_ADJECTIVES), key=len, reverse=True))
_MATERIAL_RE = re.compile(r"\b(%s)\b" % _MATERIAL_WORDS)
#: Words that make the described colour a light's: "a glowing pink vending machine", "a neon blue sign".
_GLOW_RE = re.compile(r"\b(?:glow(?:s|ing|y)?|luminous|illuminated|neon(?:-lit)?|light-up|backlit|fluorescent)\b")


#: Nouns for parts other than the main one: "a wooden chair with a red cushion" colours the
#: cushion, not the chair. Each noun lists the roles it may mean, first present wins.
PART_NOUNS: dict[str, tuple[str, ...]] = {
    "cushion": ("cushion",), "seat": ("cushion",), "pillow": ("cushion",), "upholstery": ("fabric", "cushion"),
    "shade": ("shade",), "lampshade": ("shade",), "leaves": ("leaf", "pine_leaf"), "leaf": ("leaf", "pine_leaf"),
    "foliage": ("leaf", "pine_leaf"), "needles": ("pine_leaf",), "trunk": ("bark",), "roof": ("roof",),
    "awning": ("canvas",), "canopy": ("canvas", "leaf"), "frame": ("wood", "dark_wood", "metal", "dark_metal"),
    "legs": ("wood", "dark_wood", "metal", "dark_metal", "chrome"), "base": ("dark_plastic", "metal", "dark_metal"),
    "handle": ("metal", "brass", "chrome"), "knobs": ("brass", "metal"), "pot": ("ceramic",),
    "screen": ("screen",), "flowers": ("flower",), "petals": ("flower",), "sheets": ("fabric",),
    "blanket": ("fabric",), "duvet": ("fabric",), "bedding": ("fabric",), "headboard": ("wood",),
    "wheels": ("rubber",), "tyres": ("rubber",), "tires": ("rubber",), "windows": ("glass",), "walls": ("wall",),
    "stripes": ("canvas",), "sail": ("canvas_alt",), "cabin": ("wall",), "top": ("marble",), "countertop": ("marble",),
    "door": ("dark_wood",), "front door": ("dark_wood",),
}
_PART_RE = re.compile(
    r"\s+(?:(%s)\s+)?(%s)s?\b" % (_MATERIAL_WORDS, "|".join(sorted(PART_NOUNS, key=len, reverse=True)))
)


def _colour(match: re.Match) -> tuple[float, float, float]:
    modifier, name = match.groups()
    colour = COLOURS[name]
    return _MODIFIERS[modifier](colour) if modifier else colour


def find_colour(text: str) -> tuple[float, float, float] | None:
    """The first colour phrase ("dark blue", "pastel pink", "red") of a description."""
    match = _COLOUR_RE.search(text.lower())
    return _colour(match) if match else None


def _material(word: str) -> Surface:
    return MATERIALS[_ADJECTIVES.get(word, word)]


def find_material(text: str) -> Surface | None:
    match = _MATERIAL_RE.search(text.lower())
    return _material(match.group(1)) if match else None


def _surface(base: Surface, material: str | None, colour, glow: bool = False) -> Surface:
    surface = _material(material) if material else base
    if colour is None:
        return surface
    colour = tuple(float(c) for c in colour)
    return replace(surface, color=colour, emissive=colour if glow else surface.emissive)


#: Main roles whose cushions are upholstered in the same cover.
_UPHOLSTERED = {"fabric", "leather"}

#: Roles of living or elemental things: "an oak tree" names a species, not a wood finish,
#: so material words never apply to them (colour words still do: "a red maple").
_NATURAL = {"leaf", "pine_leaf", "bark", "flower", "flower_alt", "fur", "water", "flame", "light", "soil"}


def described_surfaces(
    description: str, main: str, roles: Collection[str], base: Callable[[str], Surface]
) -> dict[str, Surface]:
    """Role → surface the description asks for. A colour (and material) right before a part
    noun goes to that part when the object has it ("with a green shade"); the first other
    colour and material go to the ``main`` role, as light when the description says it glows.
    ``base`` gives a role's unstyled surface."""
    text = description.lower()
    found: dict[str, Surface] = {}
    taken: list[tuple[int, int]] = []
    main_colour = None
    for match in _COLOUR_RE.finditer(text):
        part = _PART_RE.match(text, match.end())
        role = next((r for r in PART_NOUNS[part.group(2)] if r in roles), None) if part else None
        if role is not None and role != main:
            found.setdefault(role, _surface(base(role), part.group(1), _colour(match)))
            taken.append((match.start(), part.end()))
        elif main_colour is None:
            main_colour = _colour(match)
    material = next(
        (m.group(1) for m in _MATERIAL_RE.finditer(text) if not any(a <= m.start() < b for a, b in taken)), None
    )
    if main in _NATURAL:
        material = None
    if material is not None or main_colour is not None:
        found[main] = _surface(base(main), material, main_colour, glow=_GLOW_RE.search(text) is not None)
        # A grey sofa's cushions are grey too (a shade lighter), unless the text colours them.
        if main in _UPHOLSTERED and "cushion" in roles and "cushion" not in found:
            found["cushion"] = replace(found[main], color=tuple(c + (1 - c) * 0.12 for c in found[main].color))
    return found
