"""Seamless ground textures drawn from periodic noise and periodic cells.

Everything is periodic by construction — noise is filtered in the Fourier domain, cells
are measured on a torus, stripes and grids have whole periods per tile — so a texture
repeats across the ground without a seam, whatever the kind or style.
"""

from __future__ import annotations

import io
import logging
import re
from collections.abc import Callable

import numpy as np
from PIL import Image

from scenewright.procedural.style import INK_LIFT, STYLE_TABLE, nearest_ink, resolve_style

log = logging.getLogger(__name__)

SIZE = 512

#: Words of a ground kind or a scene text → the texture kind they mean.
KIND_WORDS: dict[str, tuple[str, ...]] = {
    "wood_floor": ("wood", "wooden", "parquet", "plank", "hardwood", "laminate", "floorboard", "deck"),
    "tiles": ("tile", "tiled", "tiles", "ceramic", "bathroom", "kitchen"),
    "grass": ("grass", "lawn", "meadow", "park", "field", "garden", "forest"),
    "gravel": ("gravel", "pebble", "pebbles", "shingle"),
    "cobblestone": ("cobble", "cobblestone", "cobbles", "paving", "pavement", "plaza", "square", "stone", "flagstone"),
    "sand": ("sand", "sandy", "beach", "desert", "dune"),
    "metal_deck": ("metal", "steel", "diamond plate", "spaceship", "space station", "industrial", "factory", "grating"),
    "carpet": ("carpet", "carpeted", "rug"),
    "concrete": ("concrete", "cement", "garage", "warehouse"),
    "dirt": ("dirt", "soil", "mud", "earth", "farm", "path", "trail"),
    "snow": ("snow", "snowy", "ice", "icy", "winter", "frozen"),
    "water": ("water", "sea", "ocean", "lake", "pond", "river", "pool"),
    "marble": ("marble", "palace", "lobby", "museum", "temple"),
    "asphalt": ("asphalt", "road", "street", "tarmac", "parking", "highway", "city"),
    "rubber": ("rubber", "playground", "gym", "running track"),
}
KINDS = tuple(KIND_WORDS)
_WORD_RE = {kind: re.compile(r"\b(%s)s?\b" % "|".join(map(re.escape, words))) for kind, words in KIND_WORDS.items()}


def normalise_kind(kind: str, text: str = "") -> str:
    """The texture kind a free-text ground kind means, else the first the scene text mentions."""
    key = kind.strip().lower().replace("-", " ").replace("_", " ")
    if key.replace(" ", "_") in KIND_WORDS:
        return key.replace(" ", "_")
    for source in (key, text.lower()):
        hits = [(m.start(), k) for k, rx in _WORD_RE.items() if (m := rx.search(source))]
        if hits:
            return min(hits)[1]
    log.info("ground kind %r not recognised: using concrete (kinds: %s)", kind, ", ".join(KINDS))
    return "concrete"


# Periodic building blocks ---------------------------------------------------------------
def noise(rng: np.random.Generator, n: int, beta: float = 2.0, stretch=(1.0, 1.0)) -> np.ndarray:
    """Tileable fractal noise in [0, 1]; ``stretch`` > 1 along an axis makes it streak that way."""
    white = rng.standard_normal((n, n))
    fy = np.fft.fftfreq(n)[:, None] * stretch[1]
    fx = np.fft.fftfreq(n)[None, :] * stretch[0]
    f = np.sqrt(fx**2 + fy**2)
    f[0, 0] = 1.0
    field = np.real(np.fft.ifft2(np.fft.fft2(white) / f ** (beta / 2)))
    field = (field - field.mean()) / max(field.std(), 1e-9)
    return np.clip(0.5 + field / 6, 0, 1)


def cells(
    rng: np.random.Generator, n: int, count: int, jitter: float | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Voronoi cells on a torus: distance to the nearest and second site (in cell units) and
    the nearest site's index, per pixel. With ``jitter`` the sites are a jittered grid, so
    cells come out of even size (cobbles) rather than random (gravel)."""
    if jitter is None:
        sites = rng.random((count, 2))
    else:
        k = int(round(np.sqrt(count)))
        count = k * k
        g = (np.stack(np.meshgrid(np.arange(k), np.arange(k)), axis=-1).reshape(-1, 2) + 0.5) / k
        sites = (g + rng.uniform(-jitter, jitter, (count, 2)) / k) % 1.0
    from scipy.spatial import cKDTree  # only the cell textures (stones, cobbles) need it

    tree = cKDTree(sites, boxsize=1.0)
    g = (np.arange(n) + 0.5) / n
    gy, gx = np.meshgrid(g, g, indexing="ij")
    d, i = tree.query(np.column_stack([gx.ravel(), gy.ravel()]) % 1.0, k=2)
    scale = np.sqrt(count)
    return (d[:, 0] * scale).reshape(n, n), (d[:, 1] * scale).reshape(n, n), i[:, 0].reshape(n, n)


def _mix(t: np.ndarray, a, b) -> np.ndarray:
    t = np.clip(t, 0, 1)[..., None]
    return np.asarray(a, float) * (1 - t) + np.asarray(b, float) * t


def _grid(n: int) -> tuple[np.ndarray, np.ndarray]:
    g = np.arange(n) / n
    return np.meshgrid(g, g, indexing="ij")  # (y, x) in [0, 1)


# Kinds -----------------------------------------------------------------------------------
def _wood_floor(rng, n):
    rows = 8
    row_px = n // rows
    iy, ix = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    row = iy // row_px
    offsets = rng.integers(0, n, rows)
    along = (ix + offsets[row]) % n
    plank = along // (n // 2)
    tone = rng.uniform(-0.12, 0.12, (rows, 2))[row, plank]
    grain = noise(rng, n, 2.2, stretch=(0.08, 1.0))
    fine = noise(rng, n, 1.0)
    img = _mix(grain * 0.8 + fine * 0.2 + tone, (0.42, 0.27, 0.15), (0.72, 0.52, 0.32))
    gap = max(1, n // 256)
    img[(iy % row_px < gap) | (along % (n // 2) < gap)] *= 0.45
    return img


def _tiles(rng, n):
    k = 8
    y, x = _grid(n)
    tile = (np.floor(y * k) * k + np.floor(x * k)).astype(int)
    tone = rng.uniform(-0.04, 0.04, k * k)[tile]
    base = _mix(0.85 + tone + 0.05 * noise(rng, n, 2.0), (0.2, 0.2, 0.2), (0.95, 0.94, 0.9))
    grout = (((x * k) % 1.0) < 0.04) | (((y * k) % 1.0) < 0.04)
    base[grout] = (0.55, 0.53, 0.5)
    return base


def _grass(rng, n):
    blades = noise(rng, n, 0.6, stretch=(1.0, 0.3))
    patches = noise(rng, n, 3.0)
    img = _mix(patches, (0.16, 0.34, 0.08), (0.4, 0.6, 0.18))
    img *= (0.55 + 0.8 * blades[..., None])
    dry = noise(rng, n, 2.5) > 0.75
    img[dry] = img[dry] * 0.6 + np.array([0.45, 0.42, 0.2]) * 0.4
    return img


def _stones(rng, n, count, mortar, light, dark, gap_width, jitter=None):
    f1, f2, idx = cells(rng, n, count, jitter)
    tone = rng.random(idx.max() + 1)[idx]
    img = _mix(tone, dark, light)
    img *= (1.1 - 0.5 * np.clip(f1, 0, 1))[..., None]
    img *= (0.9 + 0.2 * noise(rng, n, 1.5))[..., None]
    edge = (f2 - f1) < gap_width
    img[edge] = mortar
    return img


def _gravel(rng, n):
    return _stones(rng, n, 700, (0.25, 0.23, 0.21), (0.78, 0.76, 0.72), (0.42, 0.4, 0.38), 0.08)


def _cobblestone(rng, n):
    return _stones(rng, n, 100, (0.3, 0.28, 0.26), (0.66, 0.63, 0.58), (0.4, 0.38, 0.36), 0.07, jitter=0.35)


def _sand(rng, n):
    y, x = _grid(n)
    warp = noise(rng, n, 3.0)
    ripples = 0.5 + 0.5 * np.sin(2 * np.pi * (12 * y + 3 * x + 2.0 * warp))
    grains = noise(rng, n, 0.3)
    return _mix(0.55 * ripples + 0.3 * grains + 0.15 * warp, (0.76, 0.64, 0.44), (0.93, 0.84, 0.64))


def _metal_deck(rng, n):
    y, x = _grid(n)
    p = 16
    u, v = (x * p) % 1.0, (y * p) % 1.0
    bump1 = np.exp(-(((u - v) * 4) ** 2 + ((u + v - 1) * 1.2) ** 2) * 6)
    bump2 = np.exp(-((((u + v) % 1.0 - 0.5) * 4) ** 2 + ((u - v) * 1.2) ** 2) * 6)
    brushed = noise(rng, n, 1.5, stretch=(0.05, 1.0))
    base = 0.55 + 0.1 * brushed + 0.3 * np.maximum(bump1, bump2)
    return _mix(base, (0.1, 0.1, 0.11), (0.8, 0.81, 0.84))


def _carpet(rng, n):
    fibres = noise(rng, n, 0.2)
    tone = noise(rng, n, 3.0)
    return _mix(0.7 * tone + 0.3 * fibres, (0.35, 0.1, 0.12), (0.6, 0.22, 0.22))


def _concrete(rng, n):
    base = 0.6 * noise(rng, n, 2.5) + 0.4 * noise(rng, n, 1.0)
    img = _mix(base, (0.5, 0.5, 0.48), (0.72, 0.71, 0.68))
    pits = noise(rng, n, 0.0) > 0.93
    img[pits] *= 0.7
    return img


def _dirt(rng, n):
    base = 0.6 * noise(rng, n, 2.8) + 0.4 * noise(rng, n, 1.2)
    img = _mix(base, (0.3, 0.21, 0.13), (0.55, 0.42, 0.28))
    f1, _, _ = cells(rng, n, 150)
    img[f1 < 0.12] *= 1.3
    return img


def _snow(rng, n):
    base = noise(rng, n, 3.0)
    img = _mix(base, (0.8, 0.85, 0.95), (0.98, 0.98, 1.0))
    sparkle = noise(rng, n, 0.0) > 0.985
    img[sparkle] = (1.0, 1.0, 1.0)
    return img


def _water(rng, n):
    a, b = noise(rng, n, 2.5), noise(rng, n, 2.0)
    caustic = 1 - np.abs(2 * a - 1)
    caustic2 = 1 - np.abs(2 * b - 1)
    lines = np.clip((caustic * caustic2 - 0.6) * 3, 0, 1)
    return _mix(0.4 * b + 0.6 * lines, (0.05, 0.25, 0.4), (0.45, 0.75, 0.85))


def _marble(rng, n):
    y, x = _grid(n)
    turbulence = noise(rng, n, 3.5)
    veins = np.abs(np.sin(2 * np.pi * (2 * x + y + 1.5 * turbulence)))
    vein = np.clip(1 - veins * 3, 0, 1) ** 2
    img = _mix(0.85 + 0.15 * noise(rng, n, 2.5), (0.7, 0.7, 0.7), (0.95, 0.94, 0.92))
    return img * (1 - 0.45 * vein[..., None])


def _asphalt(rng, n):
    speckle = noise(rng, n, 0.1)
    wear = noise(rng, n, 3.0)
    return _mix(0.5 * speckle + 0.5 * wear, (0.13, 0.13, 0.14), (0.33, 0.33, 0.34))


def _rubber(rng, n):
    """Poured rubber of playgrounds and gyms: a base colour flecked with coloured granules."""
    f1, _, idx = cells(rng, n, 4000)
    palette = np.array([(0.55, 0.12, 0.1), (0.15, 0.4, 0.18), (0.15, 0.2, 0.45), (0.1, 0.1, 0.1)])
    weights = (0.8, 0.08, 0.05, 0.07)
    img = palette[rng.choice(len(palette), 4000, p=weights)][idx]
    return img * (0.85 + 0.3 * (1 - np.clip(f1, 0, 1)))[..., None]


_KINDS: dict[str, Callable[[np.random.Generator, int], np.ndarray]] = {
    "wood_floor": _wood_floor, "tiles": _tiles, "grass": _grass, "gravel": _gravel, "cobblestone": _cobblestone,
    "sand": _sand, "metal_deck": _metal_deck, "carpet": _carpet, "concrete": _concrete, "dirt": _dirt,
    "snow": _snow, "water": _water, "marble": _marble, "asphalt": _asphalt, "rubber": _rubber,
}
assert set(_KINDS) == set(KINDS)


# Styles ----------------------------------------------------------------------------------
def _saturate(img, amount):
    grey = img.mean(axis=2, keepdims=True)
    return grey + (img - grey) * amount


def _posterise(img, levels):
    return np.round(img * (levels - 1)) / (levels - 1)


def _cartoon(img, rng):
    return _posterise(np.clip(_saturate(img, 1.6) * 1.1, 0, 1), 6)


def _low_poly(img, rng):
    count = 220
    _, _, idx = cells(rng, img.shape[0], count)
    flat = np.stack([np.bincount(idx.ravel(), img[..., c].ravel(), count) for c in range(3)], axis=1)
    flat /= np.maximum(np.bincount(idx.ravel(), minlength=count), 1)[:, None]
    return flat[idx] * 1.05


def _cyberpunk(img, rng):
    n = img.shape[0]
    y, x = _grid(n)
    dark = _saturate(img, 0.5) * 0.4 + np.array([0.02, 0.0, 0.06])
    period = 4
    d = np.minimum(np.abs(((x * period) % 1.0) - 0.5), np.abs(((y * period) % 1.0) - 0.5))
    glow = np.exp(-((0.5 - d) * 25) ** 2)
    neon = _mix((np.sin(2 * np.pi * (x + y)) + 1) / 2, (0.0, 0.9, 1.0), (1.0, 0.1, 0.8))
    return dark + glow[..., None] * neon


def _steampunk(img, rng):
    lum = img.mean(axis=2, keepdims=True)
    sepia = lum * np.array([1.15, 0.88, 0.6])
    return 0.35 * img + 0.65 * sepia * 0.9


def _anime(img, rng):
    soft = 0.75 * img + 0.25 * img.mean(axis=(0, 1))
    return _saturate(soft, 1.25) * 0.72 + 0.28


_STYLES = {"cartoon": _cartoon, "low-poly": _low_poly, "cyberpunk": _cyberpunk, "steampunk": _steampunk, "anime": _anime}


def _look(img, look, base):
    """A named look's palette over its base style's filter: a film-noir ground is grey too."""
    img = _saturate(img, look.saturation / max(base.saturation, 1e-6)) * (look.value / base.value)
    whiten = max(0.0, look.pastel - base.pastel)
    img = img + (1 - img) * whiten
    if look.duotone:
        dark, light = (np.array(c, float) for c in look.duotone)
        lum = np.clip(img @ np.array([0.299, 0.587, 0.114]), 0, 1) ** INK_LIFT
        img = dark + (light - dark) * lum[..., None]
    if look.inks:  # one flat ink, the nearest to the ground's own colour, its grain barely showing
        ink = np.array(nearest_ink(tuple(img.reshape(-1, 3).mean(axis=0)), look.inks), float)
        lum = img @ np.array([0.299, 0.587, 0.114])
        img = ink * (0.88 + 0.12 * lum / max(float(lum.mean()), 1e-6))[..., None]
    return img


def ground_texture(kind: str, style: str, seed: int, size: int = SIZE) -> np.ndarray:
    """An RGB uint8 tile of a ground kind (see :data:`KINDS`) in a style or look name from
    :mod:`scenewright.procedural.style`."""
    if kind not in _KINDS:
        raise ValueError(f"unknown ground kind {kind!r}; kinds are: {', '.join(KINDS)}")
    rng = np.random.default_rng(seed)
    img = _KINDS[kind](rng, size)
    look = resolve_style(style)
    if look.family in _STYLES:
        img = _STYLES[look.family](img, rng)
    if look.name != look.family:
        img = _look(img, look, STYLE_TABLE[look.family])
    # Move structured lines (grout, plank gaps) off the tile border; still periodic.
    img = np.roll(img, (size // 8 + 5, size // 8 + 11), axis=(0, 1))
    return (np.clip(img, 0, 1) * 255).astype(np.uint8)


def png_bytes(image: np.ndarray) -> bytes:
    buffer = io.BytesIO()
    Image.fromarray(image, "RGB").save(buffer, format="PNG", compress_level=3)
    return buffer.getvalue()
