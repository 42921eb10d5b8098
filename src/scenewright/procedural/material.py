"""Colour and material words of a description → the surface of an object's main part.

"a dark blue velvet sofa" should come out dark blue and soft whatever the style's palette
says; the style still tints it (pastel in anime, saturated in cartoon), as an artist of
that style would.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection
from dataclasses import replace

from scenewright.core.colours import COLOUR_RE, MATERIAL_COLOURS, colour_of
from scenewright.procedural.style import Surface

#: How each material's surface takes the light: metallic, roughness (its colour is ``MATERIAL_COLOURS``').
_FINISH: dict[str, tuple[float, float]] = {
    "wood": (0.0, 0.6), "oak": (0.0, 0.6), "walnut": (0.0, 0.55), "pine": (0.0, 0.65), "mahogany": (0.0, 0.45),
    "cherry": (0.0, 0.5), "teak": (0.0, 0.55), "birch": (0.0, 0.6), "maple": (0.0, 0.6), "bamboo": (0.0, 0.55),
    "ebony": (0.0, 0.4), "wicker": (0.0, 0.85), "rattan": (0.0, 0.85), "metal": (1.0, 0.35), "steel": (1.0, 0.3),
    "iron": (1.0, 0.6), "aluminium": (1.0, 0.3), "aluminum": (1.0, 0.3), "chrome": (1.0, 0.06), "brass": (1.0, 0.3),
    "copper": (1.0, 0.3), "bronze": (1.0, 0.4), "gold": (1.0, 0.2), "silver": (1.0, 0.15), "marble": (0.0, 0.2),
    "granite": (0.0, 0.4), "stone": (0.0, 0.9), "concrete": (0.0, 0.95), "brick": (0.0, 0.9), "leather": (0.0, 0.5),
    "velvet": (0.0, 1.0), "fabric": (0.0, 0.95), "linen": (0.0, 0.95), "cotton": (0.0, 0.95), "wool": (0.0, 1.0),
    "plastic": (0.0, 0.45), "ceramic": (0.0, 0.2), "porcelain": (0.0, 0.15), "rubber": (0.0, 0.9),
    "paper": (0.0, 0.9), "jade": (0.0, 0.25),
}  # fmt: skip
MATERIALS: dict[str, Surface] = {
    **{name: Surface(MATERIAL_COLOURS[name], metallic, roughness) for name, (metallic, roughness) in _FINISH.items()},
    "glass": Surface(MATERIAL_COLOURS["glass"], 0.0, 0.05, alpha=0.35, transmission=1.0),
    "crystal": Surface(MATERIAL_COLOURS["crystal"], 0.0, 0.05, alpha=0.5, transmission=0.9),
    "neon": Surface(MATERIAL_COLOURS["neon"], 0.0, 0.3, (0.0, 0.9, 1.0)),
}
_ADJECTIVES = {"wooden": "wood", "metallic": "metal", "metal": "metal", "golden": "gold", "stony": "stone",
               "glassy": "glass", "leathery": "leather", "marbled": "marble", "plush": "velvet",
               "upholstered": "fabric", "iron-wrought": "iron", "wrought-iron": "iron", "chromed": "chrome"}

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
    "awning": ("canvas",), "canopy": ("canvas", "leaf", "blossom"),
    "frame": ("wood", "dark_wood", "metal", "dark_metal"),
    "legs": ("wood", "dark_wood", "metal", "dark_metal", "chrome"), "base": ("dark_plastic", "metal", "dark_metal"),
    "handle": ("metal", "brass", "chrome"), "knobs": ("brass", "metal"), "pot": ("ceramic",),
    "screen": ("screen",), "flowers": ("flower",), "petals": ("flower", "blossom"), "blossoms": ("blossom",),
    "sheets": ("fabric",), "blanket": ("fabric",), "duvet": ("fabric",), "bedding": ("fabric",), "headboard": ("wood",),
    "wheels": ("rubber",), "tyres": ("rubber",), "tires": ("rubber",), "windows": ("glass",), "walls": ("wall",),
    "stripes": ("canvas",), "sail": ("canvas_alt",), "cabin": ("wall",), "top": ("marble",), "countertop": ("marble",),
    "door": ("dark_wood",), "front door": ("dark_wood",),
}
_PART_RE = re.compile(
    r"\s+(?:(%s)\s+)?(%s)s?\b" % (_MATERIAL_WORDS, "|".join(sorted(PART_NOUNS, key=len, reverse=True)))
)


def find_colour(text: str) -> tuple[float, float, float] | None:
    """The first colour phrase ("dark blue", "pastel pink", "red") of a description."""
    match = COLOUR_RE.search(text.lower())
    return colour_of(match) if match else None


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
_NATURAL = {"leaf", "pine_leaf", "blossom", "bark", "flower", "flower_alt", "fur", "water", "flame", "light", "soil",
            "sand"}  # fmt: skip


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
    for match in COLOUR_RE.finditer(text):
        part = _PART_RE.match(text, match.end())
        role = next((r for r in PART_NOUNS[part.group(2)] if r in roles), None) if part else None
        if role is not None and role != main:
            found.setdefault(role, _surface(base(role), part.group(1), colour_of(match)))
            taken.append((match.start(), part.end()))
        elif main_colour is None:
            main_colour = colour_of(match)
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
