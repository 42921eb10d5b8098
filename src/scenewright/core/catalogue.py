"""The object catalogue: what the offline backends know about each kind of thing.

One record per category (``data/catalogue.json``): the words that name it, its typical size
(x width, y depth, z height in metres, at yaw 0 with the front toward −Y), how it rests
(``ground``, on a ``surface``, or ``hanging`` above something), the procedural generator
that builds it (``shape``, one name of :data:`SHAPE_NAMES`), indoor/outdoor tags, and
whether other things are usually put on it (``support``: tables, desks, counters). The last
records are shape families (``family``): what a thing nobody catalogued becomes (a camel is an
``animal`` named "camel"), sized by ``data/vocabulary.json``.

Sizes stay within 0.1–5 m except where the thing itself is larger: buildings, houses,
towers, trees, vehicles, cranes and the like keep their real size, because a 5 m bus or
lighthouse would look wrong next to a 0.9 m chair. Flat things (rugs, mats) are thinner
than 0.1 m on purpose.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

#: The procedural generators' names (the shape vocabulary of :mod:`scenewright.procedural.shapes`); ``generic`` is the fallback.
SHAPE_NAMES = (
    "table", "round_table", "coffee_table", "desk", "chair", "armchair", "office_chair", "stool",
    "sofa", "bench", "bed", "bookshelf", "cabinet", "fireplace", "wardrobe", "nightstand", "counter",
    "table_lamp", "floor_lamp", "pendant_lamp", "rug", "tv", "monitor", "laptop", "potted_plant",
    "vase", "bathtub", "toilet", "sink", "stove", "fridge", "piano", "clock", "mirror",
    "picture_frame", "trash_can", "crate", "barrel", "books", "bottle", "cup", "bowl", "garland", "tree",
    "pine_tree", "palm_tree", "bush", "flower_bed", "rock", "fountain", "statue", "lamp_post",
    "sign", "fence", "arch", "bollard", "hydrant", "car", "truck", "bus", "bicycle", "boat",
    "building", "house", "kiosk", "market_stall", "tent", "umbrella", "swing", "slide",
    "treadmill", "whiteboard", "robot", "crystal", "tower", "well", "cart", "pillar", "generic",
    # shape families of the open vocabulary: things the catalogue does not name
    "animal", "bird", "figure", "machine", "tank", "structure", "panel", "container", "tool", "vehicle",
)  # fmt: skip
RESTS = ("ground", "surface", "hanging")
#: m from the ground to the foot of a thing made for a wall that stands outdoors on a post
#: (:mod:`scenewright.analysis.composition.mounts` makes its box this much taller)...
POST = 2.2
#: ... and what its description then says: the procedural mesh draws the post under it.
POSTED = "on a post"

_WORD = re.compile(r"[^\W_]+(?:['’][^\W\d_]+)?")  # letters of any script: "café" is one word
#: Plurals that the suffix rules below would get wrong.
_IRREGULAR = {"cacti": "cactus", "mice": "mouse", "geese": "goose", "people": "person", "children": "child",
              "pegasi": "pegasus", "fungi": "fungus", "octopi": "octopus", "larvae": "larva", "pupae": "pupa",
              "taxis": "taxi", "buses": "bus", "octopuses": "octopus", "walruses": "walrus", "cactuses": "cactus",
              "thermoses": "thermos", "canvases": "canvas", "lenses": "lens", "atlases": "atlas",
              "canvas": "canvas", "atlas": "atlas", "oxen": "ox", "axes": "axe", "pickaxes": "pickaxe",
              # nouns whose -s is no plural ("a triceratops skeleton" names one kind of skeleton)
              "triceratops": "triceratops", "cyclops": "cyclops", "lens": "lens", "rhinoceros": "rhinoceros",
              "species": "species", "series": "series", "dais": "dais", "chaos": "chaos"}
#: Irregular plurals that also end closed compounds, whose plural is made by their last part.
_COMPOUND_HEADS = ("children", "mice", "geese", "people")
#: Plurals in -ves of nouns in -f or -fe other than those in -lf ("knives"); the rest drop the s ("hives").
_F_PLURALS = {"knives": "knife", "wives": "wife", "lives": "life", "leaves": "leaf", "loaves": "loaf",
              "thieves": "thief", "sheaves": "sheaf", "scarves": "scarf", "hooves": "hoof", "wharves": "wharf",
              "dwarves": "dwarf", "turves": "turf",
              "valves": "valve"}  # fmt: skip
#: Nouns in -ie, whose plural the -ies → -y rule would get wrong ("pixies" are no "pixy").
_IE_NOUNS = {"pixie", "zombie", "cookie", "movie", "hippie", "brownie", "magpie", "smoothie", "selfie", "genie",
             "rookie", "hoodie", "birdie", "beanie", "auntie", "collie", "goalie", "budgie", "pie", "tie", "lie",
             "bootie", "walkie", "talkie", "techie", "yuppie", "sweetie", "boogie", "calorie", "prairie", "lassie",
             "rotisserie", "kelpie", "yorkie", "onesie", "sortie", "eyrie", "newbie", "freebie", "menagerie",
             "lingerie", "coterie", "reverie", "camaraderie", "gendarmerie", "patisserie", "brasserie"}  # fmt: skip
#: Singular nouns in -men; other words in -men are plurals of -man ("women", "fishermen").
_SINGULAR_MEN = {"specimen", "omen", "abdomen", "stamen", "regimen", "hymen", "semen", "lumen", "amen", "acumen",
                 "albumen", "bitumen", "germen", "yemen"}  # fmt: skip
_KEEP_S = ("ss", "us", "is", "ous", "ics")


@dataclass(frozen=True)
class Category:
    name: str
    synonyms: tuple[str, ...]
    size: tuple[float, float, float]
    rests: str
    shape: str
    tags: tuple[str, ...]
    support: bool = False
    #: A shape family of the open vocabulary (``animal``, ``machine``...): reached through
    #: ``data/vocabulary.json`` from the words it covers, never by its own name as a phrase.
    family: bool = False
    #: Share of its height where a thing put on it rests, when that is below its top: a seat
    #: under a backrest, a mattress under a headboard. The procedural mesh has its surface there.
    rest_height: float | None = None
    #: Head nouns of things of this family that hold what is put on them inside, with the share
    #: of their height where that rests: their floor ("a parrot in a birdcage" sits on the cage's
    #: base, not on its dome, which may hang against the ceiling).
    rest_inside: tuple[tuple[str, float], ...] = ()

    def rest_for(self, name: str) -> float | None:
        """The share of its height where a thing put on one named ``name`` rests, when that is
        below its top: the category's :attr:`rest_height`, else the floor of a holder its head
        noun names (:attr:`rest_inside`)."""
        if self.rest_height is not None or not self.rest_inside:
            return self.rest_height
        tokens = words(name)
        return dict(self.rest_inside).get(singular(tokens[-1])) if tokens else None

    @property
    def indoor(self) -> bool:
        return "indoor" in self.tags

    @property
    def outdoor(self) -> bool:
        return "outdoor" in self.tags

    @property
    def label(self) -> str:
        """The category as words, for names and descriptions."""
        return self.name.replace("_", " ")

    @property
    def phrases(self) -> tuple[str, ...]:
        return (self.label, *self.synonyms)


def words(text: str) -> list[str]:
    """Lowercase word tokens; hyphens and punctuation split words (``four-poster`` → two)."""
    return _WORD.findall(text.lower().replace("’", "'"))


def mentions(text: str, words) -> bool:
    """Whether ``text`` uses one of ``words`` whole, or its plural ("canoes")."""
    return any(re.search(rf"\b{re.escape(w)}(?:e?s)?\b", text) for w in words)


#: Nouns whose singular itself ends in "oe" (their plural only adds "s"; "horseshoes" ends in a shoe).
_OE_NOUNS = frozenset(f"{n}s" for n in ("shoe", "canoe", "toe", "tiptoe", "hoe", "oboe", "floe", "sloe", "foe", "roe",
                                         "doe", "aloe", "throe", "felloe"))


def singular(word: str) -> str:
    """The singular of an English plural noun, by the common suffix rules."""
    if word in _IRREGULAR:
        return _IRREGULAR[word]
    head = next((h for h in _COMPOUND_HEADS if word.endswith(h) and len(word) - len(h) >= 3), None)
    if head is not None:
        return word[: -len(head)] + _IRREGULAR[head]  # "grandchildren", "dormice", "snowgeese"
    if word.endswith("men") and word not in _SINGULAR_MEN:
        return word[:-3] + "man"
    if len(word) <= 3 or not word.endswith("s") or word.endswith(_KEEP_S):
        return word
    if word.endswith("ies"):
        return word[:-1] if word[:-1] in _IE_NOUNS else word[:-3] + "y"
    if word.endswith("ves") and word not in ("eaves",):
        if word in _F_PLURALS:
            return _F_PLURALS[word]
        return word[:-3] + "f" if word.endswith("lves") else word[:-1]  # shelves, wolves; but hives, olives
    if word.endswith(("ches", "shes", "xes", "sses", "zes")):
        return word[:-2]
    if word.endswith("oes") and word not in _OE_NOUNS and not word.endswith("shoes"):
        return word[:-2]  # volcanoes, potatoes, heroes (but shoes, canoes, oboes)
    return word[:-1]


def _key(phrase: str) -> tuple[str, ...]:
    return tuple(words(phrase))


def _validate(entry: dict, seen: set[str]) -> Category:
    name = entry["name"]
    if name in seen:
        raise ValueError(f"catalogue: category {name!r} appears twice")
    if entry["shape"] not in SHAPE_NAMES:
        raise ValueError(f"catalogue: {name!r} has unknown shape {entry['shape']!r}; shapes: {', '.join(SHAPE_NAMES)}")
    if entry["rests"] not in RESTS:
        raise ValueError(f"catalogue: {name!r} rests {entry['rests']!r}; choose one of {', '.join(RESTS)}")
    size = tuple(float(v) for v in entry["size"])
    if len(size) != 3 or min(size) <= 0:
        raise ValueError(f"catalogue: {name!r} needs three positive sizes, got {entry['size']}")
    rest_height = entry.get("rest_height")
    inside = {k: float(v) for k, v in entry.get("rest_inside", {}).items()}
    for share in [rest_height, *inside.values()]:
        if share is not None and not 0 < float(share) <= 1:
            raise ValueError(f"catalogue: {name!r} rest height {share!r} is a share of its height, in (0, 1]")
    return Category(
        name=name,
        synonyms=tuple(entry.get("synonyms", ())),
        size=size,  # type: ignore[arg-type]
        rests=entry["rests"],
        shape=entry["shape"],
        tags=tuple(entry.get("tags", ())),
        support=bool(entry.get("support", False)),
        family=bool(entry.get("family", False)),
        rest_height=None if rest_height is None else float(rest_height),
        rest_inside=tuple(sorted(inside.items())),
    )


@lru_cache(maxsize=1)
def load_catalogue() -> dict[str, Category]:
    """Category name → :class:`Category`, read once from the package data."""
    raw = json.loads(resources.files("scenewright.data").joinpath("catalogue.json").read_text(encoding="utf-8"))
    seen: set[str] = set()
    result: dict[str, Category] = {}
    for entry in raw["categories"]:
        category = _validate(entry, seen)
        seen.add(category.name)
        result[category.name] = category
    return result


@lru_cache(maxsize=1)
def phrase_index() -> dict[tuple[str, ...], str]:
    """Word tuple → category name, for every name and synonym; the first category to claim a
    phrase keeps it."""
    index: dict[tuple[str, ...], str] = {}
    for category in load_catalogue().values():
        if category.family:
            continue
        for phrase in category.phrases:
            index.setdefault(_key(phrase), category.name)
    return index


def match_phrase(tokens: tuple[str, ...]) -> str | None:
    """The category a word tuple names, trying the last word in its singular form too."""
    index = phrase_index()
    if tokens in index:
        return index[tokens]
    if not tokens:
        return None
    single = (*tokens[:-1], singular(tokens[-1]))
    if single in index:
        return index[single]
    if len(tokens) >= 3 and tokens[1] == "of":  # "suits of armour", "chests of drawers"
        found = index.get((singular(tokens[0]), *tokens[1:]))
        if found is None and len(tokens) <= 4:  # "a rack of dumbbells" is a dumbbell rack ("of test tubes" too)
            found = index.get((*tokens[2:-1], singular(tokens[-1]), singular(tokens[0])))
        return found
    return None


def lookup(word_or_phrase: str) -> Category | None:
    """The category a word or phrase names (``"couches"`` → sofa), or ``None``."""
    catalogue = load_catalogue()
    text = word_or_phrase.strip().lower().replace(" ", "_")
    if text in catalogue:
        return catalogue[text]
    name = match_phrase(_key(word_or_phrase))
    return catalogue[name] if name else None
