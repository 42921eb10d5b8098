"""The offline mesh generator: a styled parametric model per object, as GLB bytes.

The shape comes from the object's catalogue category (or the shape family an open-vocabulary
object was given as its category); where the catalogue does not know it, from the nouns of
the object's name; failing both, the generic shape. The result is
deterministic: the random variation (how many books, where the canopy blobs sit) is
seeded from the object id.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import replace
from functools import cache
from pathlib import Path

from typing import TYPE_CHECKING

import numpy as np

from scenewright.core.catalogue import POST, POSTED, load_catalogue, lookup
from scenewright.errors import InputError
from scenewright.procedural.builder import Model
from scenewright.procedural.material import described_surfaces
from scenewright.procedural.shapes import SHAPES
from scenewright.procedural.shapes.families import FAMILY_WORDS
from scenewright.procedural.shapes.frames import on_post
from scenewright.procedural.style import resolve_style

if TYPE_CHECKING:
    import trimesh


#: Words of an object's name → shape, for names the catalogue does not know as a whole ("oak
#: couch cushion"): the shapes' own names, the words of each shape family ("camel" → animal),
#: every catalogue name and synonym (the catalogue owns synonyms; data/catalogue.json), and
#: the few words the catalogue does not name ("bar" reads as a counter).
KEYWORDS: dict[str, str] = {
    **{name.replace("_", " "): name for name in SHAPES},
    **{word: family for family, words in FAMILY_WORDS.items() for word in words},
    **{
        word: category.shape
        for category in load_catalogue().values()
        if category.shape in SHAPES and not category.family
        for word in (category.label, *category.synonyms)
    },
    "bedside": "nightstand", "bar": "counter", "frame": "picture_frame", "trash": "trash_can",
    "castle tower": "tower",
}
_KEYWORD_RE = re.compile(r"\b(%s)(?:e?s)?\b" % "|".join(sorted(map(re.escape, KEYWORDS), key=len, reverse=True)))


def _catalogue_shape(word: str) -> str | None:
    category = lookup(word)
    shape = getattr(category, "shape", None) if category is not None else None
    return shape if shape in SHAPES else None


def keyword_shape(name: str) -> str | None:
    """The shape a name's head noun means: the last keyword wins ("oak table lamp" → lamp)."""
    best = None
    for match in _KEYWORD_RE.finditer(name.lower().replace("_", " ")):
        key = (match.end(), len(match.group(1)))
        if best is None or key > best[0]:
            best = (key, KEYWORDS[match.group(1)])
    return best[1] if best else None


def choose_shape(name: str, category: str | None) -> str:
    """Catalogue category → its shape; else the category or the name read as keywords; else generic."""
    for word in (category, name):
        if word:
            shape = word if word in SHAPES else _catalogue_shape(word)
            if shape:
                return shape
    for word in (category, name):
        if word and (shape := keyword_shape(word)):
            return shape
    return "generic"


@cache
def code_fingerprint() -> str:
    """A hash of this package's sources: assets cached by an older generator must not be
    served once the generators change."""
    root = Path(__file__).parent
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*.py")):
        digest.update(path.relative_to(root).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def seed_of(text: str) -> int:
    return int.from_bytes(hashlib.sha256(text.encode()).digest()[:8], "little")


def build_model(
    shape: str, size, style: str, seed: int, description: str = "", name: str = ""
) -> trimesh.Scene:
    """The styled object as a glTF-convention scene: one node and PBR material per part role.
    ``name`` (the object's name and category) picks variants within a shape: a lighthouse
    among towers, a dog for the generic shape."""
    model, described = _drawn(shape, size, style, seed, description, name)
    return model.finish(described)


def _drawn(shape: str, size, style: str, seed: int, description: str, name: str) -> tuple[Model, dict]:
    """The model with its parts drawn, and the surfaces its description asks for by role."""
    if shape not in SHAPES:
        raise InputError(f"unknown shape {shape!r}; shapes are: {', '.join(sorted(SHAPES))}")
    resolved = resolve_style(style)
    model = Model(size, resolved, np.random.default_rng(seed), name=name, description=description)
    if POSTED in description.lower() and float(size[2]) > POST:  # a wall thing standing outdoors
        on_post(model, SHAPES[shape])
    else:
        SHAPES[shape](model)
    # A style that repaints a role (steampunk's bronze-green paint) keeps its own colour there.
    tinted = {role: replace(resolved.base(role), color=colour) for role, colour in model.tints.items()
              if role not in resolved.overrides}
    return model, {**tinted, **described_surfaces(model.described_text(), model.main, model.parts.keys(), resolved.base)}


def build_glb(shape: str, size, style: str, seed: int, description: str = "", name: str = "") -> bytes:
    """The object as GLB bytes, its materials exact."""
    model, described = _drawn(shape, size, style, seed, description, name)
    return model.glb(described)
