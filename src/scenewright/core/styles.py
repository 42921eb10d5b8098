"""Named looks (``data/styles.json``): the words a text uses for each, and how a look beyond the
six base styles differs from the base it is drawn like.

One table serves the reader, which names a scene's look from its words, and the procedural
backends, which draw it; so a look added there is read and drawn with no code.
"""

from __future__ import annotations

import json
import re
import unicodedata
from dataclasses import dataclass, field
from functools import lru_cache
from importlib import resources

from scenewright.core.colours import palette
from scenewright.settings import STYLES

#: What a look may change of its base: palette and shading only, so every look draws the same
#: geometry as a base style (the shared-face test covers the bases).
PALETTE = ("saturation", "value", "pastel", "roughness", "metallic_scale", "flat", "duotone", "inks")


@dataclass(frozen=True)
class Look:
    name: str
    #: Words a text names it by, normalised to lowercase words split by single spaces.
    words: tuple[str, ...]
    #: Words that name it only when "style" follows: "a gothic style" is the look, "a gothic
    #: chapel" is a building.
    styled: tuple[str, ...]
    #: The base style it is drawn like (itself for a base style).
    like: str
    palette: dict = field(default_factory=dict)
    #: Role → (r, g, b, metallic, roughness).
    overrides: dict = field(default_factory=dict)
    #: The base style whose lights a render uses (its ``like`` unless the look says: an engraving is
    #: drawn like a realistic scene but lit flat, like paper).
    lit: str = ""


def normalise(words: str) -> str:
    """Lowercase words joined by single spaces, accents folded: "Ukiyo-e" and "ukiyo e" are one
    name, and so are "papier-mâché" and "papier mache"."""
    plain = "".join(c for c in unicodedata.normalize("NFKD", words.lower()) if not unicodedata.combining(c))
    return " ".join("".join(c if c.isalnum() else " " for c in plain).split())


@lru_cache(maxsize=1)
def load_looks() -> dict[str, Look]:
    """Look name → :class:`Look`, checked once: every base style is there, every ``like`` is a base."""
    looks = {}
    for name, entry in _table()["looks"].items():
        like = entry.get("like", name)
        lit = entry.get("lit", like)
        unknown = set(entry) - {"words", "styled", "like", "lit", "overrides", *PALETTE}
        if like not in STYLES or lit not in STYLES or unknown:
            raise ValueError(f"styles.json: look {name!r} must be drawn and lit like one of {', '.join(STYLES)} "
                             f"and change only {', '.join(PALETTE)} and overrides (got {sorted(unknown) or like!r})")
        styled = tuple(normalise(w) for w in entry.get("styled", ()))
        words = tuple(normalise(w) for w in (name, *entry["words"]) if normalise(w) not in styled)
        looks[name] = Look(name, words, styled, like,
                           {k: entry[k] for k in PALETTE if k in entry}, entry.get("overrides", {}), lit)
    missing = set(STYLES) - set(looks)
    if missing:
        raise ValueError(f"styles.json: the base styles {sorted(missing)} have no entry")
    return looks


@lru_cache(maxsize=1)
def _table() -> dict:
    return json.loads(resources.files("scenewright.data").joinpath("styles.json").read_text(encoding="utf-8"))


@lru_cache(maxsize=1)
def media_heads() -> frozenset[str]:
    """Nouns that name a picture or a made image ("a copperplate *engraving* of a port", "woven as a
    *tapestry*"): a phrase ending in one, where a text says what it is, names the scene's look."""
    return frozenset(normalise(w) for w in _table()["media"])


@lru_cache(maxsize=1)
def media_parts() -> frozenset[str]:
    """Nouns for a piece of a picture, whose "of" or "from" names the medium ("a page of an illuminated
    manuscript", "a detail from a fresco")."""
    return frozenset(normalise(w) for w in _table()["parts"])


@lru_cache(maxsize=1)
def made_looks() -> dict[str, str]:
    """Verb of making → the look it makes when its phrase names none ("…, painted in blue and gold" is a
    painting, "…, woven in red and black" a textile); every look one of :func:`load_looks`."""
    made = {normalise(verb): look for verb, look in _table()["made"].items()}
    unknown = set(made.values()) - set(load_looks())
    if unknown:
        raise ValueError(f"styles.json: 'made' names looks that are not there: {sorted(unknown)}")
    return made


def find_look(name: str) -> Look | None:
    """The look a free-text style name means: a look's name or any word for it ("Ukiyo-e",
    "cartoon-style", "low poly"), else the first look a word of it names ("an Art Deco travel
    poster" is art deco, "children's crayon drawing" crayon: a style's name is all style), else None."""
    key = normalise(name).removesuffix(" style")
    looks = load_looks().values()
    exact = next((look for look in looks if key in look.words or key in look.styled), None)
    if exact is not None:
        return exact
    padded = f" {key} "
    named = [(padded.find(f" {w} "), -len(w), look.name) for look in looks for w in (*look.words, *look.styled)
             if f" {w} " in padded]
    return load_looks()[min(named)[2]] if named else None


@lru_cache(maxsize=1)
def _look_words() -> re.Pattern:
    words = {w for look in load_looks().values() for w in (*look.words, *look.styled)}
    return re.compile(r"(?<![\w])(?:%s)(?![\w])" % "|".join(re.escape(w) for w in sorted(words, key=len, reverse=True)))


def named_colours(text: str) -> list[tuple[str, tuple[float, float, float]]]:
    """The colours a style's name or phrase gives (:func:`~scenewright.core.colours.palette`), the looks' own
    words aside: "blue and white porcelain" is blue and white, "ceramic" or "stained glass" names no colour."""
    return palette(_look_words().sub(" | ", normalise(text)))
