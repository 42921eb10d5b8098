"""Art styles: how a style changes palette, surface, emission, bevels, proportions, facets.

A generator names the *role* of each part (wood, fabric, metal, leaf, light...) and its
proportions through :meth:`Style.thick`; the style decides what those become. That keeps
"cartoon" or "cyberpunk" a property of the whole scene rather than of sixty generators.
"""

from __future__ import annotations

import colorsys
import logging
from dataclasses import dataclass, field, replace
from functools import lru_cache

from scenewright.core.styles import Look, find_look, load_looks, named_colours
from scenewright.scene import DEFAULT_STYLE, STYLES

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class Surface:
    """A PBR surface: sRGB colour in 0..1 (as a palette or a colour word gives it; the
    builder converts it to linear glTF factors), metallic, roughness, emissive sRGB, opacity,
    and how much light passes through it (glass)."""

    color: tuple[float, float, float]
    metallic: float = 0.0
    roughness: float = 0.7
    emissive: tuple[float, float, float] = (0.0, 0.0, 0.0)
    alpha: float = 1.0
    transmission: float = 0.0


#: The realistic look of every role a generator may use.
ROLES: dict[str, Surface] = {
    "wood": Surface((0.55, 0.38, 0.22), 0.0, 0.6),
    "dark_wood": Surface((0.3, 0.19, 0.11), 0.0, 0.55),
    "fabric": Surface((0.55, 0.57, 0.6), 0.0, 0.95),
    "cushion": Surface((0.78, 0.74, 0.66), 0.0, 0.95),
    "leather": Surface((0.36, 0.2, 0.12), 0.0, 0.5),
    "fur": Surface((0.6, 0.42, 0.26), 0.0, 0.95),
    "metal": Surface((0.62, 0.63, 0.65), 1.0, 0.35),
    "dark_metal": Surface((0.18, 0.19, 0.2), 0.9, 0.45),
    "chrome": Surface((0.9, 0.9, 0.92), 1.0, 0.1),
    "brass": Surface((0.78, 0.6, 0.28), 1.0, 0.3),
    "copper": Surface((0.8, 0.45, 0.3), 1.0, 0.3),
    "glass": Surface((0.82, 0.9, 0.95), 0.0, 0.05, alpha=0.35, transmission=1.0),
    "plastic": Surface((0.9, 0.9, 0.88), 0.0, 0.45),
    "dark_plastic": Surface((0.08, 0.08, 0.09), 0.0, 0.4),
    "ceramic": Surface((0.94, 0.94, 0.92), 0.0, 0.2),
    "stone": Surface((0.56, 0.55, 0.52), 0.0, 0.9),
    "marble": Surface((0.9, 0.89, 0.86), 0.0, 0.2),
    "concrete": Surface((0.62, 0.61, 0.58), 0.0, 0.95),
    "brick": Surface((0.6, 0.28, 0.2), 0.0, 0.9),
    "wall": Surface((0.88, 0.84, 0.76), 0.0, 0.9),
    "roof": Surface((0.5, 0.2, 0.15), 0.0, 0.8),
    "paint": Surface((0.6, 0.08, 0.08), 0.3, 0.3),
    "yellow_paint": Surface((0.95, 0.72, 0.08), 0.3, 0.35),
    "olive_paint": Surface((0.33, 0.36, 0.2), 0.2, 0.6),
    "rubber": Surface((0.06, 0.06, 0.06), 0.0, 0.9),
    "bark": Surface((0.33, 0.23, 0.15), 0.0, 0.95),
    "leaf": Surface((0.22, 0.45, 0.18), 0.0, 0.8),
    "pine_leaf": Surface((0.12, 0.3, 0.16), 0.0, 0.85),
    "flower": Surface((0.85, 0.25, 0.35), 0.0, 0.7),
    "blossom": Surface((0.95, 0.62, 0.76), 0.0, 0.8),
    "soil": Surface((0.28, 0.2, 0.14), 0.0, 1.0),
    "sand": Surface((0.86, 0.72, 0.48), 0.0, 1.0),
    "water": Surface((0.25, 0.5, 0.65), 0.0, 0.05, alpha=0.75),
    "paper": Surface((0.92, 0.9, 0.84), 0.0, 0.9),
    "canvas": Surface((0.85, 0.2, 0.18), 0.0, 0.9),
    "canvas_alt": Surface((0.95, 0.93, 0.88), 0.0, 0.9),
    "gold": Surface((1.0, 0.77, 0.34), 1.0, 0.2),
    "crystal": Surface((0.55, 0.75, 0.95), 0.0, 0.1, (0.05, 0.1, 0.2), 0.8),
    "shade": Surface((0.95, 0.9, 0.78), 0.0, 0.9, (0.35, 0.3, 0.2)),
    "lacquer": Surface((0.03, 0.03, 0.03), 0.0, 0.12),
    "mirror": Surface((0.9, 0.92, 0.94), 1.0, 0.02),
    "flower_alt": Surface((0.95, 0.8, 0.2), 0.0, 0.7),
    "flame": Surface((1.0, 0.55, 0.15), 0.0, 0.6, (1.0, 0.45, 0.08)),
    "light": Surface((1.0, 0.93, 0.78), 0.0, 0.5, (1.0, 0.85, 0.6)),
    "screen": Surface((0.03, 0.04, 0.06), 0.0, 0.15, (0.05, 0.08, 0.12)),
    "accent": Surface((0.8, 0.15, 0.15), 0.0, 0.5),
    "book_a": Surface((0.55, 0.12, 0.12), 0.0, 0.8),
    "book_b": Surface((0.15, 0.25, 0.5), 0.0, 0.8),
    "book_c": Surface((0.2, 0.42, 0.25), 0.0, 0.8),
    # Creatures and figures.
    "fur_light": Surface((0.78, 0.62, 0.4), 0.0, 0.95),
    "fur_dark": Surface((0.16, 0.12, 0.1), 0.0, 0.9),
    "fur_orange": Surface((0.85, 0.45, 0.15), 0.0, 0.9),
    "fur_white": Surface((0.92, 0.9, 0.86), 0.0, 0.9),
    "skin_pink": Surface((0.93, 0.66, 0.64), 0.0, 0.6),
    "hide": Surface((0.52, 0.5, 0.48), 0.0, 0.85),
    "wool": Surface((0.94, 0.92, 0.86), 0.0, 1.0),
    "scales": Surface((0.2, 0.45, 0.25), 0.15, 0.45),
    "wing": Surface((0.45, 0.2, 0.15), 0.0, 0.7),
    "horn": Surface((0.86, 0.8, 0.66), 0.0, 0.4),
    "feather": Surface((0.55, 0.5, 0.45), 0.0, 0.85),
    "skin": Surface((0.87, 0.67, 0.53), 0.0, 0.6),
    "alien": Surface((0.45, 0.78, 0.35), 0.0, 0.4),
    "hair": Surface((0.2, 0.13, 0.08), 0.0, 0.8),
    "clothes": Surface((0.22, 0.36, 0.6), 0.0, 0.9),
    "trousers": Surface((0.2, 0.22, 0.28), 0.0, 0.9),
    "straw": Surface((0.86, 0.72, 0.38), 0.0, 0.95),
}

#: Roles that carry neon in a cyberpunk scene.
NEON_ROLES = {"light", "flame", "shade", "screen", "accent", "crystal", "glass", "water", "flower", "flower_alt", "trim"}
NEONS = ((0.0, 0.95, 1.0), (1.0, 0.1, 0.75), (0.6, 0.2, 1.0), (0.2, 1.0, 0.5))
_STEAMPUNK = {
    "wood": Surface((0.32, 0.18, 0.09), 0.0, 0.5),
    "metal": Surface((0.78, 0.58, 0.3), 1.0, 0.35),
    "chrome": Surface((0.72, 0.45, 0.3), 1.0, 0.3),
    "dark_metal": Surface((0.25, 0.2, 0.16), 0.9, 0.5),
    "plastic": Surface((0.5, 0.35, 0.2), 0.6, 0.4),
    "fabric": Surface((0.42, 0.14, 0.1), 0.0, 0.9),
    "cushion": Surface((0.45, 0.15, 0.1), 0.0, 0.9),
    "paint": Surface((0.18, 0.28, 0.2), 0.5, 0.4),
    "accent": Surface((0.72, 0.45, 0.3), 1.0, 0.3),
    "trim": Surface((0.78, 0.6, 0.28), 1.0, 0.3),
}

#: Cartoon and anime artists repaint neutral materials: toy-like primaries for cartoon,
#: soft pastel hues for anime (which the pastel shift then lightens further).
_CARTOON = {
    "fabric": Surface((0.2, 0.5, 0.95), 0.0, 0.6), "cushion": Surface((1.0, 0.82, 0.35), 0.0, 0.6),
    "wood": Surface((0.85, 0.5, 0.2), 0.0, 0.55), "dark_wood": Surface((0.6, 0.32, 0.15), 0.0, 0.55),
    "metal": Surface((0.72, 0.76, 0.85), 0.3, 0.4), "wall": Surface((1.0, 0.9, 0.65), 0.0, 0.6),
    "roof": Surface((0.95, 0.22, 0.18), 0.0, 0.6), "leaf": Surface((0.3, 0.8, 0.2), 0.0, 0.6),
    "pine_leaf": Surface((0.1, 0.62, 0.3), 0.0, 0.6), "stone": Surface((0.62, 0.65, 0.75), 0.0, 0.7),
    "plastic": Surface((0.98, 0.96, 0.9), 0.0, 0.5), "paint": Surface((0.98, 0.15, 0.15), 0.0, 0.4),
    "bark": Surface((0.6, 0.36, 0.18), 0.0, 0.7), "ceramic": Surface((0.98, 0.98, 1.0), 0.0, 0.3),
}
_ANIME = {
    "fabric": Surface((0.62, 0.58, 0.9), 0.0, 0.8), "cushion": Surface((1.0, 0.75, 0.8), 0.0, 0.8),
    "wood": Surface((0.85, 0.65, 0.45), 0.0, 0.8), "wall": Surface((0.98, 0.95, 0.9), 0.0, 0.8),
    "roof": Surface((0.3, 0.45, 0.85), 0.0, 0.7), "leaf": Surface((0.35, 0.78, 0.4), 0.0, 0.8),
    "pine_leaf": Surface((0.2, 0.6, 0.45), 0.0, 0.8), "paint": Surface((0.95, 0.45, 0.55), 0.0, 0.6),
    "stone": Surface((0.75, 0.75, 0.82), 0.0, 0.8), "canvas": Surface((0.5, 0.7, 0.95), 0.0, 0.8),
}


def _hsv(color, saturation: float = 1.0, value: float = 1.0, toward_white: float = 0.0):
    h, s, v = colorsys.rgb_to_hsv(*color)
    r, g, b = colorsys.hsv_to_rgb(h, min(1.0, s * saturation), min(1.0, v * value))
    w = toward_white
    return (r + (1 - r) * w, g + (1 - g) * w, b + (1 - b) * w)


#: The power a duotone lifts lightness by before it is drawn between ink and paper.
INK_LIFT = 0.75


def _ink(color, duotone):
    """A colour as one ink on paper draws it: its lightness between the dark and the light, lifted
    (an engraving or a sketch is mostly paper, its darks the lines)."""
    (dark, light), lum = duotone, (0.299 * color[0] + 0.587 * color[1] + 0.114 * color[2]) ** INK_LIFT
    return tuple(d + (l_ - d) * lum for d, l_ in zip(dark, light))


def _opponent(color):
    """Lightness and two colour-difference axes (red–green, yellow–blue), the colour ones weighted
    twice: a pale wall is nearer white than a pale skin tone, which is nearer by RGB alone."""
    r, g, b = color[0], color[1], color[2]
    return (0.299 * r + 0.587 * g + 0.114 * b, 2 * (r - g), 2 * ((r + g) / 2 - b))


def nearest_ink(color, inks):
    """The ink a print with few inks draws a colour in: the nearest one (a skin tone the cream, a
    wood the tan, a red the red)."""
    seen = _opponent(color)
    return min(inks, key=lambda ink: sum((a - b) ** 2 for a, b in zip(seen, _opponent(ink))))


@dataclass(frozen=True)
class Style:
    #: A base style's name or a named look's (``data/styles.json``); the ground texture follows
    #: the base, :attr:`family`.
    name: str
    #: Segments around round parts; low-poly keeps them few.
    segments: int
    #: Edge rounding as a fraction of a part's smallest side, and its cap in metres.
    bevel: float
    bevel_max: float
    #: Thickness multiplier for legs, frames, rails: cartoon is chunky.
    chunk: float
    #: Flat shading: one normal per face.
    flat: bool
    saturation: float = 1.0
    value: float = 1.0
    pastel: float = 0.0
    roughness: float | None = None
    metallic_scale: float = 1.0
    neon: bool = False
    #: A print or drawing in one ink: (dark, light) sRGB, every colour's lightness drawn between them.
    duotone: tuple | None = None
    #: A print in a few flat inks (sRGB): every colour becomes the nearest.
    inks: tuple | None = None
    overrides: dict[str, Surface] = field(default_factory=dict)

    @property
    def family(self) -> str:
        """The base style this one is drawn like."""
        return find_look(self.name).like

    def thick(self, metres: float) -> float:
        return metres * self.chunk

    def rounding(self, lo, hi) -> float:
        smallest = min(abs(h - lo_) for lo_, h in zip(lo, hi))
        return min(self.bevel * smallest, self.bevel_max)

    def base(self, role: str) -> Surface:
        """A role's surface before the style's palette shift."""
        return self.overrides.get(role) or ROLES.get(role) or ROLES["accent" if role == "trim" else "plastic"]

    def surface(self, role: str, neon_color=NEONS[0]) -> Surface:
        """The look of a role in this style."""
        return self.restyle(self.base(role), role, neon_color)

    def restyle(self, base: Surface, role: str, neon_color=NEONS[0]) -> Surface:
        """Apply this style's palette shift to a surface (also to colours the text asked for)."""
        if self.inks:  # the inks are the print's own colours, not shifted
            color = nearest_ink(base.color, self.inks)
        else:
            color = _hsv(base.color, self.saturation, self.value, self.pastel)
        if self.duotone:
            color = _ink(color, self.duotone)
        metallic = base.metallic * self.metallic_scale
        roughness = base.roughness if self.roughness is None else self.roughness
        emissive = base.emissive
        if self.neon and role in NEON_ROLES:
            color = tuple(0.2 * c for c in neon_color)
            emissive = neon_color
            roughness = 0.3
        elif self.neon:
            metallic = max(metallic, 0.5)
            roughness = min(roughness, 0.45)
        elif self.pastel and any(emissive):
            emissive = _hsv(emissive, toward_white=self.pastel)
        return replace(base, color=tuple(float(c) for c in color), metallic=float(metallic), roughness=float(roughness),
                       emissive=tuple(float(c) for c in emissive))


STYLE_TABLE: dict[str, Style] = {
    "realistic": Style("realistic", segments=24, bevel=0.08, bevel_max=0.012, chunk=1.0, flat=False),
    "cartoon": Style(
        "cartoon", segments=18, bevel=0.3, bevel_max=0.25, chunk=1.45, flat=False,
        saturation=1.4, value=1.1, roughness=0.55, metallic_scale=0.3, overrides=_CARTOON,
    ),
    "low-poly": Style(
        "low-poly", segments=6, bevel=0.0, bevel_max=0.0, chunk=1.15, flat=True,
        saturation=1.2, value=1.05, roughness=0.9, metallic_scale=0.0,
    ),
    "cyberpunk": Style(
        "cyberpunk", segments=16, bevel=0.04, bevel_max=0.01, chunk=1.0, flat=False,
        saturation=0.55, value=0.5, neon=True,
    ),
    "steampunk": Style(
        "steampunk", segments=20, bevel=0.1, bevel_max=0.02, chunk=1.15, flat=False,
        saturation=0.9, value=0.9, overrides=_STEAMPUNK,
    ),
    "anime": Style(
        "anime", segments=20, bevel=0.2, bevel_max=0.08, chunk=1.1, flat=False,
        saturation=0.85, value=1.1, pastel=0.35, roughness=0.8, metallic_scale=0.2, overrides=_ANIME,
    ),
}
assert set(STYLE_TABLE) == set(STYLES)


def _drawn_like(look: Look) -> Style:
    """A named look as a style: its base's geometry and palette, with the look's changes on top."""
    base = STYLE_TABLE[look.like]
    if look.name == look.like:
        return base
    overrides = {**base.overrides, **{role: Surface(tuple(v[:3]), v[3], v[4]) for role, v in look.overrides.items()}}
    palette = dict(look.palette)
    for key in ("duotone", "inks"):
        if key in palette:
            palette[key] = tuple(tuple(c) for c in palette[key])
    return replace(base, name=look.name, overrides=overrides, **palette)


#: How far a one-colour palette's dark and light lie from its colour: toward black, toward white.
SHADE, TINT = 0.45, 0.85
#: The saturation below which a named colour has no hue of its own (white, cream, grey, black).
NO_HUE = 0.16


def _in_colours(style: Style, colours: list) -> Style:
    """A look drawn in the colours its name gives ("textile in indigo and ochre", "blue and white
    porcelain"). One colour is a duotone of its own shade and tint (a red chalk drawing); a look drawn in
    one ink takes two as its dark and light (cobalt on white porcelain), and so does any look when one of
    the two has no hue (a film noir "all black and white", a woodcut in red on cream); a look printed in
    flat inks takes them as its inks (two woods of a marquetry); any other look paints in them as flat inks,
    with the darkest one's shade and the lightest one's tint for shadow and ground (a batik in indigo and
    ochre: a blend of two hues would be a third, muddy one)."""
    def lightness(c):
        return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]

    dark, light = min(colours, key=lightness), max(colours, key=lightness)
    shade, tint = tuple(SHADE * x for x in dark), tuple(x + (1 - x) * TINT for x in light)
    if len(colours) == 1:
        return replace(style, inks=None, duotone=(shade, tint))
    if len(colours) == 2 and (style.duotone or min(colorsys.rgb_to_hsv(*c)[1] for c in colours) < NO_HUE):
        return replace(style, inks=None, duotone=(dark, light))
    return replace(style, duotone=None, inks=tuple(colours) if style.inks else (shade, *colours, tint))


@lru_cache(maxsize=64)
def resolve_style(text: str | None) -> Style:
    """The style a free-text name means (a look's name or any word for it, ``data/styles.json``), in the
    colours the name gives (:func:`_in_colours`); unknown names fall back to realistic with a note."""
    look = find_look(text or DEFAULT_STYLE)
    if look is not None:
        colours = [rgb for _, rgb in named_colours(text or "")]
        return _in_colours(_drawn_like(look), colours) if colours else _drawn_like(look)
    log.warning("unknown style %r: using realistic (known: %s)", text, ", ".join(load_looks()))
    return STYLE_TABLE[DEFAULT_STYLE]
