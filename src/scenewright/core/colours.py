"""Colour and material words → sRGB colours, one table for the reader and the procedural surfaces.

The reader names a look's palette from them ("a batik cloth in indigo and ochre", "in walnut and maple
marquetry"); the procedural backend colours a described part with them ("a dark blue sofa") and draws
the palette. Colours are sRGB in 0..1.
"""

from __future__ import annotations

import re
from functools import lru_cache

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
    "brown": (0.4, 0.25, 0.13), "chocolate": (0.3, 0.17, 0.08), "tan": (0.78, 0.64, 0.45), "muddy": (0.36, 0.27, 0.17),
    "mud": (0.36, 0.27, 0.17),
    "beige": (0.87, 0.8, 0.66), "khaki": (0.74, 0.7, 0.5), "cream": (0.96, 0.93, 0.82),
    "ivory": (0.97, 0.95, 0.88), "white": (0.93, 0.93, 0.93), "black": (0.04, 0.04, 0.04),
    "grey": (0.5, 0.5, 0.5), "gray": (0.5, 0.5, 0.5), "charcoal": (0.2, 0.2, 0.22),
    "silver": (0.78, 0.79, 0.8), "golden": (1.0, 0.77, 0.34), "whitewashed": (0.92, 0.91, 0.88),
    "limewashed": (0.92, 0.91, 0.88),
    # painters' pigments, the colours an artist's medium is named in
    "ochre": (0.8, 0.55, 0.18), "sienna": (0.63, 0.32, 0.18), "umber": (0.39, 0.28, 0.18),
    "vermilion": (0.89, 0.26, 0.2), "ultramarine": (0.15, 0.2, 0.65), "lapis": (0.15, 0.25, 0.6),
    "saffron": (0.96, 0.77, 0.19), "sepia": (0.44, 0.26, 0.08), "verdigris": (0.26, 0.6, 0.5),
    "ruby": (0.7, 0.07, 0.2), "sapphire": (0.06, 0.2, 0.6), "rust": (0.6, 0.25, 0.1),
}  # fmt: skip

#: Words that shade a colour word after them ("dark blue", "pale gold").
MODIFIERS = {
    "dark": lambda c: tuple(0.45 * x for x in c),
    "deep": lambda c: tuple(0.6 * x for x in c),
    "light": lambda c: tuple(x + (1 - x) * 0.45 for x in c),
    "pale": lambda c: tuple(x + (1 - x) * 0.5 for x in c),
    "pastel": lambda c: tuple(x + (1 - x) * 0.55 for x in c),
    "bright": lambda c: tuple(min(1.0, 1.2 * x) for x in c),
    "vivid": lambda c: tuple(min(1.0, 1.2 * x) for x in c),
    "muted": lambda c: tuple(0.7 * x + 0.3 * sum(c) / 3 for x in c),
}

#: The colour of each material a text may name ("a walnut chest"; a marquetry "in walnut and maple").
MATERIAL_COLOURS: dict[str, tuple[float, float, float]] = {
    "wood": (0.55, 0.38, 0.22), "oak": (0.66, 0.49, 0.3), "walnut": (0.34, 0.21, 0.12), "pine": (0.82, 0.66, 0.44),
    "mahogany": (0.42, 0.16, 0.09), "cherry": (0.55, 0.24, 0.14), "teak": (0.6, 0.42, 0.22),
    "birch": (0.86, 0.76, 0.6), "maple": (0.88, 0.76, 0.56), "bamboo": (0.8, 0.7, 0.42), "ebony": (0.08, 0.06, 0.05),
    "wicker": (0.76, 0.6, 0.38), "rattan": (0.76, 0.6, 0.38), "metal": (0.62, 0.63, 0.65), "steel": (0.66, 0.67, 0.7),
    "iron": (0.3, 0.3, 0.31), "aluminium": (0.85, 0.86, 0.88), "aluminum": (0.85, 0.86, 0.88),
    "chrome": (0.92, 0.92, 0.94), "brass": (0.78, 0.6, 0.28), "copper": (0.8, 0.45, 0.3), "bronze": (0.6, 0.42, 0.22),
    "gold": (1.0, 0.77, 0.34), "silver": (0.9, 0.9, 0.92), "glass": (0.82, 0.9, 0.95), "crystal": (0.85, 0.92, 1.0),
    "marble": (0.92, 0.91, 0.88), "granite": (0.45, 0.44, 0.43), "stone": (0.56, 0.55, 0.52),
    "concrete": (0.62, 0.61, 0.58), "brick": (0.6, 0.28, 0.2), "leather": (0.36, 0.2, 0.12),
    "velvet": (0.45, 0.08, 0.15), "fabric": (0.6, 0.6, 0.6), "linen": (0.85, 0.82, 0.74), "cotton": (0.9, 0.9, 0.88),
    "wool": (0.8, 0.76, 0.68), "plastic": (0.9, 0.9, 0.88), "ceramic": (0.94, 0.94, 0.92),
    "porcelain": (0.96, 0.96, 0.95), "rubber": (0.06, 0.06, 0.06), "paper": (0.92, 0.9, 0.84),
    "jade": (0.3, 0.65, 0.45), "neon": (0.2, 0.2, 0.2),
}  # fmt: skip

#: A colour word with its modifier ("dark blue", "sky blue", "red").
COLOUR_RE = re.compile(
    r"\b(?:(%s)[\s-]+)?(%s)\b" % ("|".join(MODIFIERS), "|".join(sorted(COLOURS, key=len, reverse=True)))
)


def colour_of(match: re.Match) -> tuple[float, float, float]:
    """The colour a :data:`COLOUR_RE` match names, its modifier applied."""
    modifier, name = match.groups()
    return MODIFIERS[modifier](COLOURS[name]) if modifier else COLOURS[name]


_WORDS = {*COLOURS, *MATERIAL_COLOURS, *MODIFIERS}


@lru_cache(maxsize=1)
def palette_re() -> re.Pattern:
    """A run of colour and material words side by side ("cobalt blue", "white porcelain", "gold leaf" → gold;
    "reds and blues" are colours too)."""
    word = r"(?:(?:%s)[\s-]+)?(?:%s)s?" % (
        "|".join(MODIFIERS), "|".join(sorted({*COLOURS, *MATERIAL_COLOURS}, key=len, reverse=True)))
    return re.compile(rf"\b{word}(?:[\s-]+{word})*\b")


def palette(text: str) -> list[tuple[str, tuple[float, float, float]]]:
    """The colours a phrase names, in order, each once, with the words that name it: a run of words side by
    side is one colour, its first colour word's ("cobalt blue", "lapis blue"), else its material's ("walnut",
    "gold leaf"); a colour word before a material names the colour ("white porcelain" is white)."""
    found: dict[tuple[float, float, float], str] = {}
    for run in palette_re().finditer(text.lower()):
        words = [w[:-1] if w not in _WORDS and w[:-1] in _WORDS else w for w in run[0].replace("-", " ").split()]
        colour = COLOUR_RE.search(" ".join(words))
        if colour is not None:  # the colour words of the run, its materials only what they are made of
            rgb, words = colour_of(colour), [w for w in words if w in COLOURS or w not in MATERIAL_COLOURS]
        else:
            rgb = MATERIAL_COLOURS[words[-1]]
            rgb = MODIFIERS[words[0]](rgb) if words[0] in MODIFIERS else rgb
        found.setdefault(tuple(float(c) for c in rgb), " ".join(words))
    return [(words, rgb) for rgb, words in found.items()]
