"""Rule-based reading of a scene description: objects, counts, looks, sizes, relations, style.

The offline vision-language backend answers from this parse. It reads descriptions written
the way people write them (the paper's 50–300-word inputs): noun phrases are matched against
the catalogue (longest phrase first, plurals folded), counts come from the words before them,
and relation phrases connect the clause's subject (the thing placed) to the noun phrase after
the phrase. Decisions worth knowing:

- ``beside`` / ``next to`` / ``alongside`` → ``side of``; ``near`` / ``close to`` / ``by`` →
  ``near``; ``opposite`` / ``across from`` → ``in front of`` + ``face to``; ``flanked by`` and
  ``on either side of`` → one flanker ``left of`` and one ``right of`` (one thing named "on each
  side of" is two, one a side, even beside a door that is no object); ``around`` /
  ``surrounding`` / ``surrounded by`` → the surrounding objects shared among the target's
  sides (every side once, then the long sides of a long table), each facing it; one thing
  "around" another is ``near`` it; ``between A and B`` → ``near`` both; ``at a distance of
  N m`` → ``near`` when N ≤ 2, ``far`` when N > 8.
- "on the left wall" places nothing: a side word before a noun is that noun's adjective, and
  walls are no objects. A part named by a possessive is its owner ("above its door" → above
  it), since doors, roofs and porches are not objects either.
- A phrase right after another's target places that target ("a globe on a side table to the
  right of the desk": the side table is right of the desk). ``with``/``holding`` parts hang
  from their head: "a sink with a mirror above it", "a cart loaded with barrels" (on it), "a
  desk with a lamp" (a surface thing with a support → on it); "a bed with a nightstand on
  either side" flanks the head, the with-thing's only target. "It"/"them" name the latest
  earlier mention of the right number. A phrase opening a sentence ("Behind the gate, a
  pond...", "Far from the house, ...") places every subject that follows ("Around it,
  toadstools and crystals glitter"); an adverb that starts a phrase ("far", "just") is part of it.
  A with-list runs on over commas to its verb ("a counter with combs, scissors and a jar runs
  beneath the mirror"); a with-thing placed on its own starts a new list, and a small thing
  next to "it" stands by its small peer ("with a till at one end and a computer beside it").
  Beside a small thing on a table means beside that thing, not the table.
- "the teacher's desk" is a new desk unless an earlier one has the same head noun; "the
  middle bench" is one of the benches; "a rack of dumbbells" is a dumbbell rack; "holographic
  koi" are holograms (a holographic sign stays a sign); "three rows of shelves" are three
  shelving units.
- A look written after the noun is part of its description, so the mesh gets its colours,
  materials and glow: "a vending machine glowing pink", "a sofa covered in green velvet" (a
  participle and its describing words, up to a verb, a relation phrase or another object); a
  catalogue noun after "made of" is a material ("a table made of glass" holds no glass).
- "the island" after "a kitchen island" refers back to it; "a vase of tulips", "a bowl full
  of apples" and "a statue of a horse" hold contents, not objects; "a stone path", "a pine
  forest", "a throne hall" name no object; "a potted palm" is a potted plant, "a round
  table" a round table.
- ``over`` means ``above`` after a hanging verb (hang, hover, float...), else ``near``; ``X under Y``
  puts Y ``on`` X when X is flat (a rug under a table), else X ``near`` Y.
- Vague counts: a pair / a couple / both → 2; a few / several / some / a bare plural → 3;
  many / lots of → 5; ``each with a lamp``, ``every desk has a lamp`` and ``each surrounded by
  two chairs`` give that many per object of the group, placed by their own one.
- Stated sizes (``2 meters wide``, ``a 3 m tall statue``) set that dimension; the others
  scale by the same factor so the object keeps its proportions.
- Things that rest on a surface but have no stated support get an inferred ``on`` to the
  most fitting support in the scene (a lamp → nightstand, desk, side table, table...); hanging
  things without a stated target get an inferred ``above`` the nearest-mentioned large
  object. Both are marked ``inferred`` (the parse benchmark scores stated relations only).
"""

from __future__ import annotations

import logging
import re
from collections import Counter
from dataclasses import dataclass, field, replace
from functools import lru_cache

from scenewright.analysis.catalogue import (
    Category,
    load_catalogue,
    match_phrase,
    phrase_index,
    singular,
)
from scenewright.scene import DEFAULT_STYLE, Constraint

log = logging.getLogger(__name__)

#: Ground kinds the procedural ground textures understand.
GROUND_KINDS = (
    "wood floor", "tiles", "carpet", "concrete", "marble", "grass", "gravel", "cobblestone",
    "sand", "dirt", "snow", "metal deck", "stone", "rubber", "asphalt",
)  # fmt: skip


@dataclass(frozen=True)
class ParsedObject:
    id: str
    category: str
    name: str
    description: str
    size: tuple[float, float, float]
    #: Index of the noun phrase it came from (objects of one phrase share it).
    group: int


@dataclass(frozen=True)
class ParsedRelation:
    source: str
    relation: str
    target: str
    #: Added by a default rule rather than read from the text.
    inferred: bool = False

    def constraint(self) -> Constraint:
        return Constraint(relation=self.relation, source=self.source, target=self.target)


@dataclass
class ParsedScene:
    text: str
    objects: list[ParsedObject]
    relations: list[ParsedRelation]
    style: str
    ground: str
    indoor: bool

    def constraints(self) -> list[Constraint]:
        return [r.constraint() for r in self.relations]


# --------------------------------------------------------------------------- tokens

_TOKEN = re.compile(r"\d+(?:\.\d+)?|[A-Za-z]+(?:['’][A-Za-z]+)?|[.,;:!?()\"]|[-–—]")


@dataclass
class _Tok:
    text: str  # lowercase
    orig: str
    joined: bool  # hyphen-joined to the previous word ("three-tiered")


def _tokenise(text: str) -> list[_Tok]:
    toks: list[_Tok] = []
    hyphen = False
    prev_end = -1
    for m in _TOKEN.finditer(text):
        s = m.group(0)
        if s in "-–" and m.start() == prev_end:
            hyphen = True
            prev_end = m.end()
            continue
        if s in "—–-":
            s = ","
        joined = hyphen and m.start() == prev_end
        hyphen = False
        prev_end = m.end()
        toks.append(_Tok(s.lower().replace("’", "'"), s, joined))
    return toks


_NUMBERS = {
    "one": 1, "single": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
    "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "dozen": 12, "twenty": 20,
}  # fmt: skip
_VAGUE = {"few": 3, "several": 3, "some": 3, "various": 3, "many": 5, "numerous": 5, "multiple": 3, "both": 2}
#: Nouns that count or arrange what follows "of" ("a row of lamps", "stacks of crates").
_QUANTITY = {
    "pair": 2, "couple": 2, "row": 3, "rows": 5, "line": 3, "set": 3, "group": 3, "cluster": 3,
    "stack": 3, "stacks": 4, "pile": 3, "piles": 4, "bunch": 3, "handful": 3, "collection": 3,
    "coils": 3, "coil": 1, "ring": 4, "circle": 4, "lot": 5, "lots": 5, "plenty": 5, "dozens": 12,
    "series": 3, "trio": 3, "clusters": 5, "grove": 4, "patch": 1,
}  # fmt: skip
_DETERMINERS = {"a", "an", "the", "this", "that", "these", "those", "its", "their", "his", "her", "our", "my",
                "your", "another", "each", "every", "any", "other", "one", "all"}  # fmt: skip
_DEFINITE = {"the", "this", "that", "these", "those", "its", "their", "his", "her", "our", "my", "your"}
_PRONOUNS = {"it", "them", "itself", "themselves", "one"}
#: Words that end a noun phrase when reading backwards for adjectives.
_STOP = (
    set(_NUMBERS) | set(_VAGUE) | _DETERMINERS | _PRONOUNS
    | {
        "and", "or", "but", "with", "of", "in", "on", "at", "to", "from", "by", "for", "into", "onto",
        "near", "beside", "behind", "above", "under", "below", "over", "between", "around", "is",
        "are", "was", "were", "be", "has", "have", "had", "there", "here", "while", "where", "which",
        "who", "that", "as", "than", "stands", "stand", "sits", "sit", "lies", "lie", "rests", "rest",
        "hangs", "hang", "grows", "grow", "placed", "next", "across", "opposite", "facing",
        "faces", "face", "toward", "towards", "against", "along", "inside", "outside", "up", "down",
        "out", "off", "through", "like", "full", "filled", "covered", "packed", "made", "also", "just",
        "very", "too", "so", "then", "it's", "each", "every", "lots", "plenty", "atop", "upon",
        "beneath", "underneath", "close", "far", "away", "front", "back",
        "side", "sides", "middle", "centre", "center", "corner", "edge", "end", "top", "bottom",
    }
)  # fmt: skip
_UNITS = {
    "m": 1.0, "meter": 1.0, "meters": 1.0, "metre": 1.0, "metres": 1.0, "cm": 0.01,
    "centimeter": 0.01, "centimeters": 0.01, "centimetre": 0.01, "centimetres": 0.01, "mm": 0.001,
    "ft": 0.3048, "foot": 0.3048, "feet": 0.3048, "inch": 0.0254, "inches": 0.0254,
}  # fmt: skip
_DIMENSIONS = {"wide": "x", "width": "x", "across": "x", "long": "long", "length": "long", "deep": "y",
               "depth": "y", "tall": "z", "high": "z", "height": "z", "diameter": "d"}  # fmt: skip
#: Containers and depictions: what follows their "of" is content or subject, not an object.
_CONTENT_HEADS = {"vase", "bowl", "basket", "plate", "bottle", "cup", "pot", "crate", "cart", "statue",
                  "picture_frame", "planter", "sign", "billboard", "shop_shelf", "bookshelf", "flask",
                  "barrel", "shipping_container", "flower_bed", "cauldron", "sandbox"}  # fmt: skip
_CONTENT_MARKERS = {("full", "of"), ("filled", "with"), ("packed", "with"), ("overflowing", "with"),
                    ("covered", "in"), ("covered", "with"), ("stacked", "with"), ("heaped", "with"),
                    ("stocked", "with"), ("lined", "with"), ("piled", "with"), ("overflow", "with")}  # fmt: skip
_HANG_VERBS = {"hang", "hangs", "hanging", "hung", "hover", "hovers", "hovering", "float", "floats",
               "floating", "suspended", "dangle", "dangles", "dangling", "fly", "flies", "flying",
               "soar", "soars", "soaring", "glow", "glows", "drift", "drifts", "mounted", "swing",
               "swings", "swim", "swims", "swimming"}  # fmt: skip

# --------------------------------------------------------------------------- relation phrases

_REL_PHRASES: dict[str, list[str]] = {
    "left of": ["to the left of", "on the left of", "left of", "to the left side of", "on the left side of",
                "at the left of", "on the left hand side of", "to the left hand side of",
                "against the left side of", "against the left of"],
    "right of": ["to the right of", "on the right of", "right of", "to the right side of", "on the right side of",
                 "at the right of", "on the right hand side of", "to the right hand side of",
                 "against the right side of", "against the right of"],
    "left": ["to the left", "on the left", "on the left hand side", "to the left hand side"],
    "right": ["to the right", "on the right", "on the right hand side", "to the right hand side"],
    "its left": ["to its left", "on its left", "at its left"],
    "its right": ["to its right", "on its right", "at its right"],
    "on top": ["on top", "on the top"],
    "in front of": ["in front of", "at the front of", "in the front of", "just in front of", "right in front of",
                    "to the front of", "pulled up to", "drawn up to", "pushed up to"],
    "behind": ["behind", "at the back of", "in back of", "to the back of", "at the rear of", "to the rear of",
               "in the back of", "just behind", "right behind", "directly behind"],
    "side of": ["beside", "next to", "alongside", "along side", "by the side of", "at the side of", "to the side of",
                "adjacent to", "right next to", "just beside", "side by side with"],
    "near": ["near", "near to", "close to", "close by", "nearby", "by", "not far from", "a short distance from",
             "a few steps from", "within reach of", "tied to", "against", "leaning against", "leans against",
             "lean against", "next door to", "a short walk from", "in the vicinity of", "shade", "shades",
             "shading", "border", "borders", "bordering"],
    "far": ["far from", "far away from", "a long way from", "far off from", "distant from", "away from",
            "well away from", "far away"],
    "on": ["on", "on top of", "atop", "upon", "onto", "on to", "resting on", "on the top of"],
    "above": ["above", "high above", "up above", "directly above", "right above", "just above", "overhead"],
    "over": ["over", "hanging over", "hangs over", "directly over"],
    "face to": ["facing", "face", "faces", "faced", "facing toward", "facing towards", "turned toward",
                "turned towards", "turned to face", "looking at", "looks at", "look at", "looking toward",
                "looking towards", "looks toward", "looks towards", "pointing at", "points at", "pointed at",
                "pointing toward", "pointing towards", "points toward", "points towards", "oriented toward",
                "oriented towards", "aimed at", "watching", "watches", "overlooking", "overlooks",
                "overlook", "gazing at", "gazes at", "looking out at"],
    "opposite": ["opposite", "opposite to", "opposite of", "across from", "across the room from",
                 "across the table from", "across the street from", "on the opposite side of",
                 "on the other side of", "directly opposite", "straight across from"],
    "no relation": ["from across", "in the middle of", "in the centre of", "in the center of", "across"],
    "flank": ["flank", "flanks", "flanking", "on either side of", "on each side of", "on both sides of",
              "either side of", "each side of", "to either side of", "on the left and right of",
              "to the left and right of", "left and right of", "on the left and right sides of",
              "on opposite sides of"],
    "flank elliptic": ["on either side", "on each side", "on both sides", "to either side"],
    "flanked by": ["flanked by", "framed by", "bracketed by"],
    "around": ["around", "surround", "surrounds", "surrounding", "encircle", "encircles", "encircling",
               "circling", "all around", "arranged around", "gathered around", "clustered around",
               "scattered around", "dotted around", "ringing", "round about", "enclose", "encloses",
               "enclosing"],
    "surrounded by": ["surrounded by", "ringed by", "encircled by", "circled by", "ringed with", "surrounded with",
                      "encircled with"],
    "near by": ["shaded by", "guarded by", "watched over by", "bordered by", "lit by", "accompanied by",
                "joined by", "overlooked by", "lined by", "lined with"],
    "on by": ["crossed by", "spanned by", "topped by", "crowned by"],
    "under": ["under", "beneath", "underneath", "below", "right under", "just below"],
    "between": ["between", "in between"],
}  # fmt: skip


@lru_cache(maxsize=1)
def _phrase_table() -> dict[tuple[str, ...], str]:
    table: dict[tuple[str, ...], str] = {}
    for kind, phrases in _REL_PHRASES.items():
        for phrase in phrases:
            table[tuple(phrase.split())] = kind
    return table


_MAX_REL = 6
_PLANT_SHAPES = ("tree", "pine_tree", "palm_tree", "bush", "flower_bed")
#: Phrase kinds that name relations of one object to one target, and the relations they mean.
_SINGLE_TARGET = {
    "left of": ("left of",), "right of": ("right of",), "in front of": ("in front of",), "behind": ("behind",),
    "side of": ("side of",), "near": ("near",), "far": ("far",), "on": ("on",), "above": ("above",),
    "over": ("above",), "face to": ("face to",), "opposite": ("in front of", "face to"), "between": ("near",),
}  # fmt: skip


def relation_phrases() -> dict[str, tuple[str, ...]]:
    """Phrase → the relations it means, for phrases that place one object relative to one
    target ("beside" → side of, "across from" → in front of + face to). Editing reads
    instructions with the same vocabulary."""
    return {
        phrase: _SINGLE_TARGET[kind]
        for kind, phrases in _REL_PHRASES.items()
        if kind in _SINGLE_TARGET
        for phrase in phrases
    }

# --------------------------------------------------------------------------- style & ground

_STYLE_WORDS = [
    ("low-poly", ("low poly", "lowpoly", "low-poly", "polygonal", "flat shaded")),
    ("cartoon", ("cartoon", "cartoonish", "cartoony", "toon", "pixar", "claymation")),
    ("anime", ("anime", "ghibli", "cel shaded", "cel-shaded")),
    ("cyberpunk", ("cyberpunk", "neon noir", "neon-noir", "blade runner")),
    ("steampunk", ("steampunk", "clockwork")),
    ("realistic", ("realistic", "photorealistic", "photo realistic", "photo-realistic", "lifelike")),
]


def detect_style(text: str, default: str = DEFAULT_STYLE) -> str:
    """The style the text names ("cartoon-style", "Cyberpunk.", "anime"), else ``default``.

    A word followed by "style" wins over a word used in passing; otherwise the first named."""
    low = " " + " ".join(re.findall(r"[a-z]+", text.lower())) + " "
    best: tuple[int, int, str] | None = None
    for style, words in _STYLE_WORDS:
        for w in words:
            w = " " + " ".join(re.findall(r"[a-z]+", w)) + " "
            pos = low.find(w)
            if pos < 0:
                continue
            styled = low[pos + len(w) : pos + len(w) + 6].startswith(("style", "styled", "look", "aesthetic"))
            rank = (0 if styled else 1, pos, style)
            if best is None or rank < best:
                best = rank
    return best[2] if best else default


_GROUND_WORDS = [
    ("metal deck", ("metal deck", "metal floor", "steel deck", "landing pad", "spaceport", "space station",
                    "spaceship deck", "metal grating", "starship", "platform deck", "metal plating")),
    ("cobblestone", ("cobblestone", "cobblestones", "cobbled", "cobble")),
    ("gravel", ("gravel",)),
    ("snow", ("snow", "snowy", "snow covered", "frozen", "icy", "winter")),
    ("sand", ("sand", "sandy", "beach", "desert", "dunes", "dune", "oasis")),
    ("rubber", ("rubber ground", "rubber floor", "rubber mat", "rubber flooring", "gym floor", "gym")),
    ("marble", ("marble floor", "marble floors", "marble tiles", "marble flooring")),
    ("tiles", ("tile", "tiles", "tiled", "bathroom", "kitchen", "laboratory", "lab", "spa")),
    ("carpet", ("carpeted", "wall to wall carpet", "carpet floor", "bedroom", "nursery", "office", "conference")),
    ("asphalt", ("asphalt", "tarmac", "road", "street", "parking", "highway", "city", "gas station")),
    ("concrete", ("concrete", "pavement", "sidewalk", "station", "platform", "warehouse", "garage", "industrial",
                  "dock", "harbour", "harbor", "pier")),
    ("wood floor", ("wooden floor", "wood floor", "hardwood", "parquet", "floorboards", "wooden deck",
                    "plank", "room", "house", "cabin", "studio", "apartment", "cafe", "café", "bistro",
                    "restaurant", "shop", "store", "boutique", "hall")),
    ("stone", ("stone floor", "flagstone", "flagstones", "paved", "plaza", "courtyard", "castle", "temple")),
    ("dirt", ("dirt", "mud", "muddy", "soil", "farm", "dusty", "village", "campsite", "orchard", "trail",
              "planet", "rocky", "crater", "martian", "wasteland")),
    ("grass", ("grass", "grassy", "lawn", "meadow", "park", "garden", "field", "backyard", "yard", "forest")),
]


def detect_ground(text: str, indoor: bool) -> str:
    """A ground kind from :data:`GROUND_KINDS`: an explicit floor word, else the place's word,
    else wood floor indoors and grass outdoors."""
    low = " " + " ".join(re.findall(r"[a-zé]+", text.lower())) + " "
    best: tuple[int, int, str] | None = None
    for rank, (kind, words) in enumerate(_GROUND_WORDS):
        for w in words:
            pos = low.find(" " + w + " ")
            if pos >= 0:
                # Material words ("cobblestones", "tiles") outrank place words ("kitchen", "park").
                explicit = 0 if rank < 7 or " " in w or w in ("tile", "tiles", "tiled", "concrete", "asphalt", "grass") else 1
                key = (explicit, rank, kind)
                if best is None or key < best:
                    best = key
    if best is not None:
        return best[2]
    return "wood floor" if indoor else "grass"


# --------------------------------------------------------------------------- noun phrases


@dataclass
class _Mention:
    category: str
    phrase: str
    start: int
    end: int  # exclusive
    count: int
    counted: bool  # the count was stated (a number, "a", "a pair of")
    definite: bool
    each: bool = False  # "each X" / "every X"
    adjectives: list[str] = field(default_factory=list)
    group: int = -1
    content: bool = False  # inside a container or a depiction: not an object
    #: Describing words after the noun ("a vending machine glowing pink", "a crate made of steel").
    post: list[str] = field(default_factory=list)
    alias: bool = False  # "the island" after "a kitchen island": only a reference


@dataclass
class _Group:
    index: int
    category: str
    count: int
    name: str
    description: str
    size: tuple[float, float, float]
    ids: list[str] = field(default_factory=list)


@lru_cache(maxsize=1)
def _max_phrase_len() -> int:
    return max(len(k) for k in phrase_index())


#: Places named after what they hold ("a throne hall", "a book shop").
_VENUES = {"room", "hall", "shop", "store", "garden", "yard", "market", "park", "studio", "gallery", "lab",
           "area", "aisle", "section", "station", "court", "museum", "cafe", "café", "bar", "square",
           "street", "farm", "factory", "workshop", "showroom", "district", "festival", "fair", "lot",
           "lounge", "parlour", "parlor", "emporium", "boutique", "depot", "dealership", "nursery"}  # fmt: skip
#: Nouns that often qualify the next word ("a stone path", "a pine forest", "a canvas awning").
_MODIFIER_NOUNS = {"glass", "stone", "rock", "crystal", "box", "plant", "flower", "book", "rope", "candle",
                   "cat", "dog", "fruit", "bird", "horse", "tree", "sign", "toy", "table", "cactus", "mushroom",
                   "hay", "lamp", "pool", "tower", "pine", "oak", "maple", "birch", "cherry", "palm", "cedar",
                   "canvas", "chalkboard", "blackboard", "bench", "chair", "gem", "orb", "barrel", "wine",
                   "bottle", "cup", "coffee", "bus", "car", "boat", "robot", "fence", "kiosk", "computer"}  # fmt: skip

#: Adjectives that make any thing a projection.
_PROJECTED = {"holographic", "hologram", "projected", "virtual"}
#: Things that keep their kind when holographic: a sign with a holographic face is still a sign.
_SHOWS_PROJECTION = {"sign", "billboard", "menu_board"}


def _find_mentions(toks: list[_Tok]) -> list[_Mention]:
    """Longest-first catalogue matches, with a noun followed by another noun read as a modifier
    ("glass table", "stone path")."""
    n = len(toks)
    longest = _max_phrase_len()
    raw: list[tuple[int, int, str]] = []
    i = 0
    while i < n:
        found = None
        for length in range(min(longest, n - i), 0, -1):
            words = tuple(t.text for t in toks[i : i + length])
            if any(not w[0].isalpha() for w in words):
                continue
            cat = match_phrase(words)
            if cat:
                found = (i, i + length, cat)
                break
        if found:
            raw.append(found)
            i = found[1]
        else:
            i += 1
    mentions: list[_Mention] = []
    for k, (s, e, cat) in enumerate(raw):
        nxt = raw[k + 1] if k + 1 < len(raw) else None
        if nxt and nxt[0] == e:
            continue  # modifier of the next noun ("glass table", "tree house")
        words = [t.text for t in toks[s:e]]
        follow = toks[e].text if e < n else ""
        if follow in _VENUES or (follow and singular(follow) in _VENUES and len(words) == 1):
            continue  # "a throne hall", "a flower shop": the place, not the thing
        qualifies = follow[:1].isalpha() and follow not in _STOP and not _is_verb(follow)
        if len(words) == 1 and words[0] in _MODIFIER_NOUNS and qualifies and not follow.endswith(("ed", "ing")):
            continue  # "a stone path", "a glass roof": an adjective here
        if s > 0 and toks[s - 1].text in _PROJECTED and cat not in _SHOWS_PROJECTION:
            cat = "hologram"  # "holographic koi" are light, not fish: place and size them as one
        mentions.append(_Mention(cat, " ".join(t.orig for t in toks[s:e]), s, e, 1, False, False))
    return _alias_mentions(toks, mentions)


def _alias_mentions(toks: list[_Tok], mentions: list[_Mention]) -> list[_Mention]:
    """"the island" after "a kitchen island", "the pumps" after "two fuel pumps": a definite
    head noun of an earlier phrase refers back to it."""
    heads: dict[str, str] = {}
    compounds: dict[str, str] = {}  # "campfire" answers to "the fire"
    taken = {k for m in mentions for k in range(m.start, m.end)}
    extra: list[_Mention] = []
    ordered = sorted(mentions, key=lambda m: m.start)
    nxt = 0
    for i, t in enumerate(toks):
        while nxt < len(ordered) and ordered[nxt].end <= i:
            m = ordered[nxt]
            words = m.phrase.lower().split()
            if len(words) > 1:
                heads.setdefault(singular(words[-1]), m.category)
            else:
                compounds.setdefault(singular(words[0]), m.category)
            nxt += 1
        word = singular(t.text)
        if word not in heads and len(word) >= 4:
            compound = next((c for w, c in compounds.items() if w.endswith(word)), None)
            if compound is not None:
                heads[word] = compound
        if i in taken or not t.text[0].isalpha() or word not in heads:
            continue
        j = i - 1
        while j >= 0 and i - j <= 3 and toks[j].text not in _DEFINITE and toks[j].text not in _STOP:
            j -= 1
        if j >= 0 and toks[j].text in _DEFINITE | {"each", "every"}:
            m = _Mention(heads[word], t.orig, i, i + 1, 1, False, True, alias=True)
            extra.append(m)
    return sorted(mentions + extra, key=lambda m: m.start)


def _is_plural(toks: list[_Tok], m: _Mention) -> bool:
    last = toks[m.end - 1].text
    return singular(last) != last or last in ("people", "cacti", "shelves", "benches", "glasses")


#: Place nouns that qualify the next noun after a determiner ("the middle bench", "the end stall").
_POSITION_WORDS = {"middle", "centre", "center", "corner", "end", "front", "back", "top", "bottom", "side"}


def _position_adjective(toks: list[_Tok], j: int) -> bool:
    """"the middle bench": a place noun between a determiner and a noun works as an adjective."""
    return toks[j].text in _POSITION_WORDS and j > 0 and toks[j - 1].text in _DETERMINERS and (
        j + 1 < len(toks) and toks[j + 1].text[:1].isalpha() and toks[j + 1].text not in _STOP
    )


def _read_count(toks: list[_Tok], m: _Mention, prev_end: int) -> None:
    """Fill count, definiteness and adjectives from the words before the noun."""
    plural = _is_plural(toks, m)
    j = m.start - 1
    adjectives: list[str] = []
    count: int | None = None
    counted = False
    while j >= prev_end and j >= 0 and m.start - j <= 7:
        t = toks[j]
        w = t.text
        if w in _NUMBERS and not toks[j + 1].joined:
            count, counted = _NUMBERS[w], True
            # "above one bench", "between every two benches": of those already there, if any
            m.definite = w == "one" or (j > 0 and toks[j - 1].text in ("every", "each"))
            break
        if toks[j + 1].joined and adjectives:  # "three-tiered", "red-and-white": one adjective
            adjectives[0] = f"{t.orig}-{adjectives[0]}"
            j -= 1
            continue
        if w.replace(".", "").isdigit():
            if j + 1 < len(toks) and (toks[j + 1].joined or toks[j + 1].text in _UNITS):
                adjectives.insert(0, t.orig)  # "27-inch", "4 m tall": a size, not a count
                j -= 1
                continue
            count, counted = int(float(w)), True
            break
        if w in _VAGUE:
            count = _VAGUE[w]
            counted = w == "both"
            if w == "few" and j > 0 and toks[j - 1].text == "a":
                j -= 1
            break
        if w == "of" and j > 0 and toks[j - 1].text in _QUANTITY:
            q = toks[j - 1].text
            small = load_catalogue()[m.category].rests == "surface"
            count = 1 if q in ("stack", "pile") and small else _QUANTITY[q]
            counted = q in ("pair", "couple", "dozen")
            k = j - 2
            if k >= 0 and toks[k].text in _NUMBERS:  # "two pairs of", "three stacks of"
                width, depth, _ = load_catalogue()[m.category].size
                per = 1 if q in ("row", "rows", "line", "lines") and width >= 1.0 and depth <= 0.6 else count
                count, counted = per * _NUMBERS[toks[k].text], True  # "three rows of shelves": a unit a row
            elif k >= 0 and toks[k].text == "of" and k > 0 and toks[k - 1].text in _QUANTITY:
                count = _QUANTITY[toks[k - 1].text]  # "a lot of"
            elif q in ("row", "line", "stack", "pile", "set", "group", "cluster", "ring", "circle") and k >= 0 and toks[
                k
            ].text not in ("a", "an", "one"):
                count = max(count, 4)
            break
        if w in ("a", "an", "another"):
            count, counted = 1, True
            break
        if w in ("each", "every"):
            m.each = True
            count, counted = 1, True
            break
        if w in _DEFINITE:
            m.definite = True
            break
        if (w in _STOP and not _position_adjective(toks, j)) or not w[0].isalnum():
            break
        adjectives.insert(0, t.orig)
        j -= 1
    if count is None:
        count = 3 if plural else 1
    if m.category == "books" and not counted:
        count = 1
    if plural and count == 1 and counted and not m.each and toks[max(m.start - 1, 0)].text not in ("a", "an"):
        count = 2
    m.count, m.counted, m.adjectives = count, counted, adjectives


#: Participles that describe the look of the noun before them ("painted red", "made of steel").
_LOOK_PARTICIPLES = {"glowing", "gleaming", "shining", "painted", "covered", "made", "coated", "upholstered",
                     "carved", "lacquered", "varnished", "dyed", "tinted", "trimmed", "wrapped", "draped",
                     "clad", "plated", "cast", "forged", "woven", "built", "lit", "finished"}  # fmt: skip
_LOOK_PREPOSITIONS = {"in", "of", "from", "with"}
#: After these, every noun is what the thing is made of ("made of steel and glass").
_MADE_OF = {("made", "of"), ("made", "from"), ("built", "of"), ("built", "from"), ("carved", "from"),
            ("carved", "of"), ("cast", "in"), ("forged", "from"), ("woven", "from")}  # fmt: skip
_MAX_LOOK_WORDS = 4


def _post_description(toks: list[_Tok], end: int, starts: set[int]) -> tuple[list[str], int]:
    """The look a participle gives the noun ending at ``end`` ("glowing pink", "covered in green
    velvet") and where it ends: the descriptive words up to a verb, a relation phrase or another
    noun phrase, so the mesh generator reads colours and materials written after the noun too."""
    if end >= len(toks) or toks[end].text not in _LOOK_PARTICIPLES or end in starts:
        return [], end
    k = end + 1
    made_of = k < len(toks) and (toks[end].text, toks[k].text) in _MADE_OF
    if k < len(toks) and toks[k].text in _LOOK_PREPOSITIONS:
        k += 1
    first = k

    def describes(i: int) -> bool:
        w = toks[i].text if i < len(toks) else ""
        noun_ok = made_of or i not in starts
        return w[:1].isalpha() and w not in _STOP and noun_ok and not _is_verb(w)

    while k - first < _MAX_LOOK_WORDS and (describes(k) or (toks[k].text in ("and", "or") and describes(k + 1))):
        k += 1
    if k == first:
        return [], end  # "a table covered in books": contents, no look
    words: list[str] = []
    for t in toks[end:k]:
        if t.joined and words:  # "neon-pink"
            words[-1] += "-" + t.text
        else:
            words.append(t.text)
    return words, k


# --------------------------------------------------------------------------- sizes

_NUM_WORD = {**{k: float(v) for k, v in _NUMBERS.items() if k not in ("single", "dozen")}, "half": 0.5}


def _read_sizes(toks: list[_Tok]) -> list[tuple[int, int, str, float]]:
    """(start, end, dimension, metres) for each "N unit dimension" phrase."""
    out = []
    for i, t in enumerate(toks):
        value = None
        if t.text.replace(".", "", 1).isdigit():
            value = float(t.text)
        elif t.text in _NUM_WORD:
            value = _NUM_WORD[t.text]
        if value is None or i + 2 >= len(toks) + 1:
            continue
        j = i + 1
        if j < len(toks) and toks[j].text in _UNITS:
            unit = _UNITS[toks[j].text]
            j += 1
            if j < len(toks) and toks[j].text in ("in", "of") and j + 1 < len(toks) and toks[j + 1].text in _DIMENSIONS:
                j += 1
            if j < len(toks) and toks[j].text in _DIMENSIONS:
                out.append((i, j + 1, _DIMENSIONS[toks[j].text], value * unit))
    return out


def _apply_sizes(base: tuple[float, float, float], dims: list[tuple[str, float]]) -> tuple[float, float, float]:
    x, y, z = base
    stated: dict[str, float] = {}
    named = {d for d, _ in dims}
    for dim, value in dims:
        if dim == "long":  # the longer side, unless the width or depth is named too
            dim = "y" if "x" in named else "x" if "y" in named else "y" if y > x else "x"
        if dim == "d":
            stated["x"] = stated["y"] = value
        else:
            stated[dim] = value
    first_dim = next(iter(stated))
    scale = stated[first_dim] / {"x": x, "y": y, "z": z}[first_dim]
    result = {"x": x * scale, "y": y * scale, "z": z * scale}
    result.update(stated)
    return (round(result["x"], 4), round(result["y"], 4), round(result["z"], 4))


# --------------------------------------------------------------------------- the parse


@dataclass
class _Rel:
    kind: str
    start: int
    end: int
    #: The target is the last one named ("..., at a distance of 12 m").
    elliptic: bool = False


#: At most this far apart is "near", beyond the other "far" (the relations' own thresholds).
NEAR_LIMIT = 2.0
FAR_LIMIT = 8.0


def _distance_at(toks: list[_Tok], i: int) -> _Rel | None:
    """"at a distance of N m (from X)", "N metres (away) from X" → near / far / nothing."""
    j = i
    if [t.text for t in toks[i : i + 4]] == ["at", "a", "distance", "of"]:
        j = i + 4
    elif i > 0 and toks[i - 1].text in ("about", "some", "roughly", "around", "only", "just", "of"):
        return None
    value = toks[j].text if j < len(toks) else ""
    number = float(value) if value.replace(".", "", 1).isdigit() else _NUM_WORD.get(value)
    if number is None or j + 1 >= len(toks) or toks[j + 1].text not in _UNITS:
        return None
    metres = number * _UNITS[toks[j + 1].text]
    k = j + 2
    if k < len(toks) and toks[k].text == "away":
        k += 1
    has_from = k < len(toks) and toks[k].text == "from"
    if not has_from and j == i:
        return None  # "2 m" alone is a size or a count, not a distance
    kind = "near" if metres <= NEAR_LIMIT else "far" if metres > FAR_LIMIT else "no relation"
    return _Rel(kind, i, k + 1 if has_from else k, elliptic=not has_from)


def _qualifies_noun(toks: list[_Tok], end: int, kind: str) -> bool:
    """"on the left wall", "on the left bench": the side word is the next noun's adjective, so
    the phrase is only its preposition (a wall is no object: nothing is left of anything)."""
    if kind not in ("left", "right") or end >= len(toks):
        return False
    w = toks[end].text
    return w[0].isalpha() and w not in _STOP and not _is_verb(w)


def _find_relations(toks: list[_Tok], taken: set[int]) -> list[_Rel]:
    table = _phrase_table()
    rels: list[_Rel] = []
    i = 0
    while i < len(toks):
        if i in taken:
            i += 1
            continue
        hit = _distance_at(toks, i)
        for length in range(min(_MAX_REL, len(toks) - i), 0, -1):
            if hit or any(k in taken for k in range(i, i + length)):
                continue
            key = tuple(t.text for t in toks[i : i + length])
            if key in table and not _qualifies_noun(toks, i + length, table[key]):
                hit = _Rel(table[key], i, i + length)
                break
        if hit:
            rels.append(hit)
            i = hit.end
        else:
            i += 1
    return rels


_CLAUSE_BREAK = {",", ";", ":", "(", ")", '"'}
_CLAUSE_WORDS = {"while", "whereas", "where", "whilst", "although", "though"}
_SENTENCE_END = {".", "!", "?"}


def _split(toks: list[_Tok]) -> list[list[tuple[int, int]]]:
    """Sentences as lists of clauses, each a (start, end) token span."""
    sentences: list[list[tuple[int, int]]] = []
    clauses: list[tuple[int, int]] = []
    start = 0
    for i, t in enumerate(toks + [_Tok(".", ".", False)]):
        if t.text in _SENTENCE_END or t.text in _CLAUSE_BREAK or t.text in _CLAUSE_WORDS:
            if i > start:
                clauses.append((start, i))
            start = i + 1
            if t.text in _SENTENCE_END and clauses:
                sentences.append(clauses)
                clauses = []
    return sentences


_FINITE = {"is", "are", "was", "were", "has", "have", "had", "stand", "sit", "lie", "rest", "hang", "grow",
           "lean", "wait", "glow", "run", "line", "rise", "stay", "remain", "tower", "loom", "float", "hover"}  # fmt: skip
_ADVERBS = {"just", "right", "directly", "all", "both", "neatly", "slightly", "also", "then", "only", "far", "well"}
_HOLD = {"holds", "hold", "holding", "carries", "carry", "carrying", "supports", "support", "supporting",
         "bears", "bearing", "displays", "displaying"}  # fmt: skip
_HOLD_PAIRS = {("loaded", "with"), ("topped", "with"), ("set", "with"), ("laid", "with"), ("decorated", "with")}
#: Words that start a with-thing's own placing ("with a till at one end and a computer ...").
_OWN_PLACE = {"at", "in", "along", "against", "under", "inside"}
#: Possessives whose noun, when no object, is a part of what the pronoun names ("its door").
_OWNER_PRONOUNS = {"its": "it", "their": "them"}
_ORDINALS = {"first": 0, "second": 1, "third": 2, "last": -1, "left": 0, "right": -1, "other": -1, "nearest": 0}


def _is_verb(word: str) -> bool:
    """A finite verb, roughly: what closes a noun phrase's "with" part ("with a mirror is placed")."""
    return word in _FINITE or (len(word) > 3 and word.endswith("s") and not word.endswith(("ss", "us", "is")))


@dataclass
class _Clause:
    """What one clause has built so far."""

    first: bool
    main: list[int] = field(default_factory=list)
    head: list[int] | None = None  # what a "with" part hangs from
    wsub: list[int] = field(default_factory=list)
    hold: bool = False
    wsub_related: set[int] = field(default_factory=set)
    last_target: list[int] = field(default_factory=list)
    last_target_end: int = -1
    expect_new: bool = False
    groups: list[int] = field(default_factory=list)
    main_groups: list[int] = field(default_factory=list)
    fronted: list[tuple[str, list[int], bool]] = field(default_factory=list)
    last_kind: str = ""
    #: The clause opens with a noun phrase the catalogue does not know ("a small ice rink lies...").
    unknown_subject: bool = False
    rels: list[tuple[str, list[int]]] = field(default_factory=list)
    produced: bool = False
    #: The nouns before the clause's first verb or relation: its subjects.
    subjects: list[int] = field(default_factory=list)
    verb_seen: bool = False
    #: The "with" things before one that was placed on its own ("with a till at one end and ...").
    wsub_before: list[int] = field(default_factory=list)
    #: The group "each"/"every" distributes over: its with-parts and flankers come once per member.
    each: int | None = None


class _Reader:
    """One pass over the text that builds groups of objects and relations between them."""

    def __init__(self, text: str):
        self.text = text
        self.toks = _tokenise(text)
        self.catalogue = load_catalogue()
        self.groups: list[_Group] = []
        #: (kind, source group, target group, target instance when one of the group is meant)
        self.relations: list[tuple[str, int, int, int | None]] = []
        self.pair_each: set[tuple[int, int]] = set()
        self.history: list[int] = []  # groups in the order earlier clauses mentioned them
        self.instance: dict[int, int | None] = {}  # mention start → instance it names
        self._target_start = -1

    # ---- groups

    def _new_group(self, m: _Mention, sizes: list[tuple[str, float]]) -> int:
        adjectives = {a.lower() for a in m.adjectives}
        if m.category == "table" and adjectives & {"round", "circular"}:
            m.category = "round_table"
        if adjectives & {"potted", "pot"} and self.catalogue[m.category].shape in _PLANT_SHAPES:
            m.category = "potted_plant"  # "a potted palm" is a house plant, not a 6 m tree
        cat: Category = self.catalogue[m.category]
        name = m.phrase.lower()
        if _is_plural(self.toks, m):
            words = name.split()
            name = " ".join([singular(words[0]), *words[1:]]) if "of" in words[1:2] else singular(name)
        description = " ".join([*(a.lower() for a in m.adjectives), name, *m.post]).strip()
        size = _apply_sizes(cat.size, sizes) if sizes else cat.size
        g = _Group(len(self.groups), m.category, max(1, m.count), name, description, size)
        self.groups.append(g)
        return g.index

    def _resolve(self, m: _Mention, sizes: list[tuple[str, float]]) -> int:
        """A definite mention of something already present refers to it (by category, else by
        its head noun: "the island" → the kitchen island); anything else is new."""
        if m.group >= 0:
            return m.group
        if (m.definite or m.each) and not sizes:
            head = singular(self.toks[m.end - 1].text)
            found = next((g.index for g in reversed(self.groups) if g.category == m.category), None)
            # "the teacher's desk" is not one of the school desks, nor "the teacher's bench" a lab table
            owned = any(t.text.endswith("'s") for t in self.toks[max(0, m.start - 1) : m.end - 1])
            if owned and found is not None and singular(self.groups[found].name.split()[-1]) != head:
                found = None
            if found is None and not owned:
                found = next(
                    (g.index for g in reversed(self.groups) if g.name.split()[-1].endswith(head)), None
                )
            if found is not None:
                m.group = found
                if not _is_plural(self.toks, m) and self.groups[found].count > 1:
                    adj = [a.lower() for a in m.adjectives]
                    self.instance[m.start] = next((_ORDINALS[a] for a in adj if a in _ORDINALS), 0)
                return found
        if m.alias:
            return -1
        m.group = self._new_group(m, sizes)
        return m.group

    # ---- the parse

    def read(self) -> None:
        toks = self.toks
        mentions = _find_mentions(toks)
        prev_end = 0
        for m in mentions:
            _read_count(toks, m, prev_end)
            prev_end = m.end
        self._mark_contents(mentions)
        self.size_of: dict[int, list[tuple[str, float]]] = {}
        for s, e, dim, value in _read_sizes(toks):
            owner = self._size_owner(mentions, s, e)
            if owner is not None:
                self.size_of.setdefault(owner, []).append((dim, value))
        taken = {k for m in mentions for k in range(m.start, m.end)}
        self.rel_at = {r.start: r for r in _find_relations(toks, taken)}
        self._read_looks(mentions)
        self.by_start = {m.start: m for m in mentions if not m.content}
        for sentence in _split(toks):
            prev_subject: list[int] = []
            pending: list[tuple[str, list[int]]] = []
            last_rels: list[tuple[str, list[int]]] = []
            for ci, (cs, ce) in enumerate(self._merge_lists(sentence)):
                c = _Clause(first=ci == 0)
                self._clause(c, cs, ce, prev_subject)
                if c.fronted:
                    srcs = c.main_groups
                    targets_all = {t for _, ts, _ in c.fronted for t in ts}
                    srcs = [g for g in srcs if g not in targets_all]
                    if srcs:
                        for kind, targets, each in c.fronted:
                            if each:  # "beside every table stand two chairs"
                                self._per_each(srcs[:1], targets[0])
                            for t in targets:
                                self._relate(kind, srcs, t)
                        c.rels = [(kind, targets) for kind, targets, _ in c.fronted]
                    else:
                        pending = [(kind, targets) for kind, targets, _ in c.fronted]
                elif pending and c.main_groups:
                    # "Around it, toadstools and crystals glitter": every coordinated subject
                    subjects = c.subjects or c.main_groups[:1]
                    for kind, targets in pending:
                        for t in targets:
                            self._relate(kind, subjects, t)
                    pending = []
                elif not c.produced and c.groups and last_rels and self._is_list(cs, ce, strict=True):
                    # "On the desk there is a lamp, a laptop and a mug": the list shares the relation
                    for kind, targets in last_rels:
                        for t in targets:
                            self._relate(kind, c.groups, t)
                    c.rels = last_rels
                last_rels = c.rels or last_rels
                if c.main_groups:
                    prev_subject = c.main_groups[:1] if not c.main else c.main
                self.history.extend(c.groups)

    def _read_looks(self, mentions: list[_Mention]) -> None:
        """Each noun's look written after it; a catalogue noun inside a "made of" look is its
        material, not an object ("a table made of glass" holds no drinking glass)."""
        starts = {m.start for m in mentions} | set(self.rel_at)
        for m in mentions:
            m.post, end = _post_description(self.toks, m.end, starts)
            for other in mentions:
                other.content = other.content or m.end < other.start < end

    def _size_owner(self, mentions: list[_Mention], s: int, e: int) -> int | None:
        after = [m for m in mentions if m.start >= e and m.start - e <= 4]
        if after:
            return after[0].start
        before = [m for m in mentions if m.end <= s and s - m.end <= 8]
        return before[-1].start if before else None

    def _mark_contents(self, mentions: list[_Mention]) -> None:
        """Nouns after "full of", or after "of" following a container or a depiction ("a vase of
        tulips", "a statue of a horse"), are contents, not objects of the scene."""
        toks = self.toks
        chain = False
        for k, m in enumerate(mentions):
            prev = mentions[k - 1] if k else None
            j = m.start - 1
            while j >= 0 and (toks[j].text in _DETERMINERS or toks[j].text in _NUMBERS or (
                toks[j].text not in _STOP and toks[j].text[0].isalnum())) and m.start - j < 5:  # fmt: skip
                j -= 1
            if j < 1 or prev is None:
                chain = False
                continue
            gap = [t.text for t in toks[prev.end : j + 1]]
            content = self._is_content(m, prev, j) or (
                chain and prev.content and not (m.counted or m.definite) and all(g in ("and", ",", "or") for g in gap)
            )
            m.content = content
            chain = content

    def _is_content(self, m: _Mention, prev: _Mention, j: int) -> bool:
        w = self.toks[j].text
        if (self.toks[j - 1].text, w) in _CONTENT_MARKERS and j - prev.end <= 2:
            return True  # "a bowl full of apples"
        if w == "of" and prev.end == j and prev.category in _CONTENT_HEADS and not m.definite:
            return True  # "a vase of tulips", "a statue of a horse"
        plant = self.catalogue[prev.category].shape in ("potted_plant", "bush", "flower_bed")
        return w == "in" and j - prev.end <= 2 and m.category in ("pot", "planter", "vase") and plant

    def _merge_lists(self, clauses: list[tuple[int, int]]) -> list[tuple[int, int]]:
        """Join a clause that only lists objects to the next one when that one places them
        ("with a laptop, a mug and a lamp on it")."""
        out: list[tuple[int, int]] = []
        for cs, ce in clauses:
            places = any(k in self.rel_at for k in range(cs, ce))
            # "a counter with combs, scissors and a jar runs beneath the mirror": the list goes on
            goes_on = bool(out) and self._open_with(*out[-1]) and cs not in self.rel_at
            goes_on = goes_on and self.toks[cs].text not in ("and", "or", "but", "then", "so")
            if goes_on or (places and out and self._is_list(*out[-1], strict=True)):  # a bare list takes the next placing
                out[-1] = (out[-1][0], ce)
                continue
            out.append((cs, ce))
        return out

    def _open_with(self, cs: int, ce: int) -> bool:
        """The clause ends inside the "with" part of a noun before it: nothing placed after."""
        toks = self.toks
        last = max((k for k in range(cs + 1, ce) if toks[k].text == "with" or toks[k].text in _HOLD), default=None)
        if last is None or not any(cs <= k and m.end <= last for k, m in self.by_start.items()):
            return False  # "a market square with three stalls, ...": the place's list, not a thing's
        return not any(k in self.rel_at for k in range(last, ce))

    def _is_list(self, cs: int, ce: int, strict: bool = False) -> bool:
        """Only noun phrases joined by "and": no relation phrase, no verb."""
        if any(k in self.rel_at for k in range(cs, ce)):
            return False
        mentions = [m for k, m in self.by_start.items() if cs <= k < ce]
        if not mentions or max(m.end for m in mentions) != ce:
            return False
        if not strict:
            return True
        allowed: set[int] = set()
        for m in mentions:
            allowed.update(range(m.start - len(m.adjectives) - 2, m.end))
        for k in range(cs, ce):
            w = self.toks[k].text
            if w in _HOLD:  # "a counter holds a till, and clocks stand behind it": two clauses
                return False
            if k in allowed or w in ("and", "or", "with") or w in _DETERMINERS or w in _NUMBERS:
                continue
            return False
        return True

    def _target_at(self, pos: int, ce: int) -> tuple[list[int] | str | None, int]:
        """The noun phrase (or pronoun) right after a relation phrase, and where it ends."""
        toks = self.toks
        j = pos
        while j < ce and j - pos < 6:
            if j in self.by_start:
                m = self.by_start[j]
                self._target_start = m.start
                g = self._resolve(m, self.size_of.get(m.start, []))
                return ([g] if g >= 0 else None), m.end
            w = toks[j].text
            if w in ("it", "them", "itself", "themselves", "him", "her"):
                return w, j + 1
            if w in ("each", "one") and j + 1 < ce and toks[j + 1].text in ("other", "another"):
                return "each other", j + 2
            after_determiner = j > pos and toks[j - 1].text in _DETERMINERS  # a noun, not a verb ("its walls")
            if w in _DETERMINERS or w in _NUMBERS or w in _ORDINALS or w == "of" or _position_adjective(toks, j) or (
                w not in _STOP and w[0].isalnum() and (after_determiner or not _is_verb(w))
            ):
                j += 1
                continue
            break
        owner = _OWNER_PRONOUNS.get(toks[pos].text) if pos < ce else None
        if owner and j > pos + 1:
            return owner, j  # "above its door": a part of its owner places by the owner itself
        return None, pos

    def _pronoun(self, word: str, c: _Clause, srcs: list[int], prefer: list[int]) -> list[int]:
        """The group "it" / "them" names: the subject before (when this clause has its own) or
        the latest earlier mention, of the right number."""
        plural = word in ("them", "themselves")
        recent = [g for g in [*prefer, *reversed(self.history), *reversed(c.groups)] if g not in srcs]
        for g in recent:
            if (self.groups[g].count > 1) == plural:
                return [g]
        # "them" after two single things ("an armchair ... a bookcase ..., between them")
        return list(dict.fromkeys(recent))[:2] if plural else []

    def _clause(self, c: _Clause, cs: int, ce: int, prev_subject: list[int]) -> None:
        toks = self.toks
        k = cs
        while k < ce and toks[k].text in ("and", "or", "but", "then", "also", "so", "there", "is", "are"):
            k += 1
        j = k
        # an adverb that opens a relation phrase is part of it ("Far from the house, ...")
        while j < ce and j not in self.rel_at and (toks[j].text in _DETERMINERS or toks[j].text in _ADVERBS):
            j += 1
        starts_with_rel = j in self.rel_at
        c.unknown_subject = j > k and toks[k].text in ("a", "an", "the") and j not in self.by_start and not starts_with_rel
        last_event_end = cs
        while k < ce:
            w = toks[k].text
            nxt = toks[k + 1].text if k + 1 < ce else ""
            each_part = nxt in ("with", "have", "has", "holding", "holds", "carrying", "bearing")
            # "each surrounded by two chairs": the passive flankers come once per member too
            each_passive = k + 1 in self.rel_at and self.rel_at[k + 1].kind in ("flanked by", "surrounded by")
            each_hold = (nxt, toks[k + 2].text if k + 2 < ce else "") in _HOLD_PAIRS
            if w == "each" and (each_part or each_passive or each_hold):
                plural = [g for g in [*self.history, *c.groups] if self.groups[g].count > 1]
                if plural:
                    c.each = plural[-1]
                k += 1
                continue
            if w == "with" or w in _HOLD or (w, nxt) in _HOLD_PAIRS or w in ("has", "have"):
                c.head = [c.each] if c.each is not None else (c.main or list(prev_subject))
                c.wsub, c.expect_new = [], False
                c.hold = w in _HOLD or (w, nxt) in _HOLD_PAIRS
                k += 2 if (w, nxt) in _HOLD_PAIRS else 1
                last_event_end = k
                continue
            if k in self.by_start:
                m = self.by_start[k]
                g = self._resolve(m, self.size_of.get(m.start, []))
                k = m.end
                if g < 0:
                    continue
                if c.each is not None and c.head is not None and not m.definite and g != c.each:
                    self.groups[g].count = max(1, m.count) * self.groups[c.each].count
                    self.pair_each.add((g, c.each))
                if m.each and c.head is None and not c.verb_seen:
                    c.each = g  # "every desk has a lamp": a lamp per desk
                c.groups.append(g)
                if c.head is not None:
                    gap = [t.text for t in toks[last_event_end : m.start]]
                    closed = any(_is_verb(w) for w in gap)
                    if c.wsub and any(w in _OWN_PLACE for w in gap):  # "a till at one end and a computer"
                        self._close_with(c)
                        c.wsub_before, closed = list(c.wsub), True
                    c.wsub = [g] if (c.expect_new or closed) else [*c.wsub, g]
                else:
                    c.main_groups.append(g)
                    c.main = [g] if c.expect_new else [*c.main, g]
                    if not c.verb_seen:
                        c.subjects.append(g)
                c.expect_new = False
                last_event_end = m.end
                continue
            c.verb_seen = c.verb_seen or k in self.rel_at or _is_verb(w)
            if k in self.rel_at:
                k = self._relation(c, self.rel_at[k], ce, prev_subject, starts_with_rel, last_event_end)
                last_event_end = k
                continue
            k += 1
        self._close_with(c)

    def _small(self, *groups: int) -> bool:
        """All of these stand on surfaces (tabletop things)."""
        return all(self.catalogue[self.groups[g].category].rests == "surface" for g in groups)

    def _close_with(self, c: _Clause) -> None:
        """"A desk with a lamp", "a cart loaded with barrels": small things with no place of
        their own stand on what they came with."""
        if c.head is None:
            return
        for g in c.wsub:
            if g in c.wsub_related:
                continue
            for h in c.head:
                if h == g:
                    continue
                rests = self.catalogue[self.groups[g].category].rests
                if c.hold or (rests == "surface" and self.catalogue[self.groups[h].category].support):
                    self._relate("on", [g], h)
                    c.produced = True

    def _relation(self, c: _Clause, rel: _Rel, ce: int, prev_subject, starts_with_rel, last_event_end) -> int:
        toks = self.toks
        kind = rel.kind
        target, end = self._target_at(rel.end, ce)
        between = [t.text for t in toks[last_event_end : rel.start]]
        # sources: the noun the phrase follows when nothing but adverbs lies between
        srcs: list[int]
        # "a globe on a side table to the right of the desk", "chairs around a table left of the sofa"
        chained = (c.last_kind in ("on", "on top", "near", "around") or kind in ("on", "on top")) and kind not in (
            "face to", "flank", "around", "no relation"
        )  # fmt: skip
        if chained and isinstance(target, list) and target and c.last_target:
            # "a lamp on the table next to a teapot": what stands by a small thing is its peer, not the table
            chained = not self._small(target[0]) or self._small(c.last_target[0])
        if chained and c.last_target and c.last_target_end == last_event_end and all(b in _ADVERBS for b in between):
            srcs = list(c.last_target)
        elif c.head is not None:
            closed = any(_is_verb(b) for b in between)
            if c.wsub and not closed and not c.expect_new:
                srcs = list(c.wsub)
                if kind in ("on", "above", "over", "on top", "under"):
                    c.wsub_related.update(srcs)
            else:
                self._close_with(c)
                srcs = list(c.head)
                c.head, c.wsub = None, []
        else:
            srcs = list(c.main)
        if kind == "no relation":
            return end
        if kind in ("its left", "its right") and target is None:
            kind, target = ("left of" if kind == "its left" else "right of"), "it"
        if kind == "on top" and target is None:
            kind = "on"
            target = "it" if c.head is not None else None
            rel = replace(rel, elliptic=True)
        if isinstance(target, str) and target != "each other":
            # "a bench in front of the swing, facing it": the clause's own last target first.
            prefer = list(c.last_target) or (list(prev_subject) if c.main and srcs == c.main else [])
            targets: list[int] | str = self._pronoun(target, c, srcs, prefer) if c.head is None else list(c.head)
            if c.head is not None and srcs == c.head:
                targets = self._pronoun(target, c, srcs, prefer)
            elif c.head is not None and c.wsub_before and srcs == c.wsub and self._small(*srcs, c.wsub_before[-1]):
                targets = c.wsub_before[-1:]  # "... and a computer beside it": beside the till
        elif target is None and (kind in ("left", "right", "flank elliptic") or rel.elliptic):
            # "a bed with a nightstand on either side": a with-thing's side is its head's
            owner = list(c.head) if c.head is not None and srcs == c.wsub else []
            targets = list(c.last_target) or owner or [g for g in self.history[-1:] if g not in srcs]
        elif target is None:
            targets = []
        else:
            targets = target
        if kind == "between" and isinstance(targets, list) and targets:
            if end < ce and toks[end].text == "and":
                second, end2 = self._target_at(end + 1, ce)
                if isinstance(second, list):
                    targets, end = targets + second, end2
            kind = "near"
        if isinstance(targets, list) and targets:
            for t in targets:
                if t in c.groups:
                    continue
                c.groups.append(t)
        if kind in ("flanked by", "surrounded by", "near by", "on by"):
            head = srcs or list(prev_subject)
            if isinstance(targets, list) and head:
                active = {"flanked by": "flank", "surrounded by": "around", "near by": "near", "on by": "on"}[kind]
                if c.each is not None:  # "three tables, each surrounded by two chairs": two per table
                    self._per_each([t for t in targets if t != c.each], c.each)
                for t in targets:
                    for h in head:
                        self._relate(active, [t], h)
                c.produced = True
                c.rels.append((kind, targets))
                if c.head is None:
                    c.main = list(targets)  # "guarded by a skeleton sitting on a barrel"
            c.last_target, c.last_target_end, c.expect_new = [], -1, False
            return end
        if not srcs:
            if starts_with_rel and c.first and not c.produced and isinstance(targets, list) and targets:
                tm = self.by_start.get(self._target_start) if isinstance(target, list) else None
                c.fronted.append((kind, targets, tm is not None and tm.each))
                return end
            if not c.first and not c.unknown_subject:
                srcs = list(prev_subject)
        if kind in ("flank", "flank elliptic") and not toks[rel.start].text.startswith("flank"):
            self._one_a_side(srcs)  # also beside what is no object: "on each side of the elevator"
        if not srcs or not targets:
            return end
        hang = any(t.text in _HANG_VERBS for t in toks[max(0, rel.start - 3) : rel.start])
        if targets == "each other":
            for s in srcs:
                self.relations.append(("face to" if kind == "face to" else "near", s, s, None))
            c.produced = True
            return end
        assert isinstance(targets, list)
        instance = self.instance.get(self._target_start) if isinstance(target, list) else None
        tm = self.by_start.get(self._target_start) if isinstance(target, list) else None
        if tm is not None and tm.each:  # "a candle on every table": one per table
            self._per_each([s for s in srcs if s in c.groups], targets[0])
        for t in targets:
            self._relate(kind, srcs, t, hang, instance)
        c.produced = True
        c.rels = [(kind, targets)]
        c.last_kind = "between" if rel.kind == "between" else kind  # "between two trees to the left of"
        if isinstance(target, list):
            c.last_target, c.last_target_end = targets, end
        else:
            c.last_target, c.last_target_end = [], -1
        c.expect_new = True
        return end

    def _per_each(self, srcs: list[int], target: int) -> None:
        """As many of each source as it says, for every one of the target group."""
        for src in srcs:
            if (src, target) not in self.pair_each:
                self.groups[src].count *= self.groups[target].count
                self.pair_each.add((src, target))

    def _one_a_side(self, srcs: list[int]) -> None:
        """"A lamp post on each side of the door": one thing named for both sides means two."""
        for s in srcs:
            if self.groups[s].count == 1 and s not in self.history:
                self.groups[s].count = 2

    def _relate(self, kind: str, srcs: list[int], target: int, hang: bool = False, instance=None) -> None:
        for s in srcs:
            resolved = self._kind(kind, s, target, hang)
            if s == target or resolved == "no relation":
                continue
            self.relations.append((resolved, s, target, instance))

    def _kind(self, kind: str, s: int, t: int, hang: bool = False) -> str:
        src = self.catalogue[self.groups[s].category]
        if kind == "over":
            return "above" if hang or src.rests == "hanging" else "near"  # a tree leaning over a pond
        if kind == "above" and src.rests == "ground" and src.size[2] > 1.5 and not hang:
            return "near"  # a tree "above" a pond cannot float: read it as near
        if kind == "under":
            tgt = self.catalogue[self.groups[t].category]
            return "under flat" if self.groups[s].size[2] < 0.1 and tgt.size[2] < 1.5 else "near"
        return {"left": "left of", "right": "right of", "flank elliptic": "flank"}.get(kind, kind)


# --------------------------------------------------------------------------- to objects


def _ids(groups: list[_Group]) -> None:
    counters: Counter[str] = Counter()
    for g in groups:
        for _ in range(g.count):
            counters[g.category] += 1
            g.ids.append(f"{g.category}_{counters[g.category]}")




def _around_sides(n: int, src: _Group, tgt: _Group) -> list[str]:
    """Which side of the target each of ``n`` surrounding objects takes: long sides first."""
    tx, ty, _ = tgt.size
    width = max(src.size[0], 0.3) + 0.15
    if tx >= 1.4 * ty:
        first, short = ["in front of", "behind"], ["left of", "right of"]
        long_cap, short_cap = max(1, int(tx // width)), max(1, int(ty // width))
    elif ty >= 1.4 * tx:
        first, short = ["left of", "right of"], ["in front of", "behind"]
        long_cap, short_cap = max(1, int(ty // width)), max(1, int(tx // width))
    else:
        first, short = ["left of", "right of"], ["in front of", "behind"]
        long_cap = short_cap = max(1, int(max(tx, ty) // width))
    # every side once (four chairs take four sides), then the long sides fill up first
    order = first + short + first * (long_cap - 1) + short * (short_cap - 1)
    if n < 4:
        order = first + short
    return [order[i % len(order)] for i in range(n)]


def _instance_pairs(src: _Group, tgt: _Group, paired: bool) -> list[tuple[str, str]]:
    n, m = len(src.ids), len(tgt.ids)
    if paired or (n == m and n > 1):
        return [(src.ids[i], tgt.ids[i % m]) for i in range(n)]
    return [(s, tgt.ids[i % m]) for i, s in enumerate(src.ids)]


def _expand(reader: _Reader) -> list[ParsedRelation]:
    out: list[ParsedRelation] = []
    groups = reader.groups
    for kind, s, t, instance in reader.relations:
        src, tgt = groups[s], groups[t]
        paired = (s, t) in reader.pair_each or (t, s) in reader.pair_each
        if s == t:  # "facing each other": the later ones face the first
            if kind == "face to" and len(src.ids) > 1:
                out += [ParsedRelation(i, "face to", src.ids[0]) for i in src.ids[1:]]
            continue
        if instance is not None:
            tgt = replace(tgt, ids=[tgt.ids[instance]])
        pairs = _instance_pairs(src, tgt, paired)
        if kind == "opposite":
            for a, b in pairs:
                out += [ParsedRelation(a, "in front of", b), ParsedRelation(a, "face to", b)]
        elif kind == "flank":
            for i, (a, _) in enumerate(pairs):
                out.append(ParsedRelation(a, ("left of", "right of")[i % 2], tgt.ids[(i // 2) % len(tgt.ids)]))
        elif kind == "around" and len(src.ids) == 1:  # one round ottoman "surrounds" a palm: it is near
            out += [ParsedRelation(src.ids[0], "near", b) for b in tgt.ids[:1]]
        elif kind == "around":
            # paired ("each surrounded by two chairs"): each target's sides go to its own share
            per = len(tgt.ids) if paired else 1
            sides = _around_sides(-(-len(src.ids) // per), src, tgt)
            for i, a in enumerate(src.ids):
                b = tgt.ids[i % len(tgt.ids)]
                out += [ParsedRelation(a, sides[i // per], b), ParsedRelation(a, "face to", b)]
        elif kind == "under flat":
            for a, b in pairs:
                out.append(ParsedRelation(b, "on", a))
        elif kind in ("left of", "right of", "in front of", "behind", "side of", "near", "far", "on", "above", "face to"):
            out += [ParsedRelation(a, kind, b) for a, b in pairs]
    return out


def _acyclic(relations: list[ParsedRelation], ids: list[str]) -> list[ParsedRelation]:
    """Drop duplicates and any relation that would close a cycle (later and inferred ones go
    first), then order them so that an object is placed before it serves as a target."""
    seen: set[tuple[str, str, str]] = set()
    kept: list[ParsedRelation] = []
    edges: dict[str, set[str]] = {i: set() for i in ids}  # source → targets

    def reaches(a: str, b: str) -> bool:
        stack, visited = [a], set()
        while stack:
            x = stack.pop()
            if x == b:
                return True
            if x in visited:
                continue
            visited.add(x)
            stack.extend(edges.get(x, ()))
        return False

    for r in sorted(relations, key=lambda r: r.inferred):
        key = (r.source, r.relation, r.target)
        if key in seen or r.source == r.target or r.source not in edges or r.target not in edges:
            continue
        if reaches(r.target, r.source):
            log.debug("dropping %s %s %s: it would close a cycle", r.source, r.relation, r.target)
            continue
        # one vertical support per object
        if r.relation in ("on", "above") and any(
            k.source == r.source and k.relation in ("on", "above") for k in kept
        ):
            continue
        seen.add(key)
        kept.append(r)
        edges[r.source].add(r.target)
    depth: dict[str, int] = {}

    def level(x: str) -> int:
        if x not in depth:
            depth[x] = 0
            depth[x] = 1 + max((level(t) for t in edges[x]), default=-1)
        return depth[x]

    order = {i: n for n, i in enumerate(ids)}
    return sorted(kept, key=lambda r: (level(r.source), order[r.source]))


_SUPPORT_PREFERENCE = {
    "table_lamp": ("nightstand", "desk", "side_table", "dresser", "vanity", "table", "coffee_table", "cabinet"),
    "alarm_clock": ("nightstand", "dresser", "desk", "side_table"),
    "tv": ("tv_stand", "cabinet", "dresser", "counter", "desk", "table"),
    "monitor": ("desk", "school_desk", "table", "counter", "control_panel", "lab_bench"),
    "laptop": ("desk", "school_desk", "table", "coffee_table", "counter", "round_table"),
    "keyboard": ("desk", "school_desk", "table"),
    "printer": ("desk", "cabinet", "filing_cabinet", "table"),
    "microwave": ("counter", "cabinet", "table"),
    "coffee_machine": ("counter", "side_table", "table", "cabinet"),
    "toaster": ("counter", "table"),
    "cash_register": ("counter", "display_case", "table"),
    "flask": ("lab_bench", "table", "desk", "counter"),
    "microscope": ("lab_bench", "desk", "table"),
    "projector": ("table", "desk", "side_table"),
    "radio": ("cabinet", "side_table", "dresser", "desk", "table"),
    "aquarium": ("cabinet", "dresser", "side_table", "counter", "table"),
    "magic_orb": ("pedestal", "altar", "table", "round_table", "desk"),
}


def _infer_support(objects: list[ParsedObject], relations: list[ParsedRelation], catalogue) -> list[ParsedRelation]:
    """Surface things with no stated support go on the best support present; hanging things
    with no stated target hang above the nearest-mentioned large object."""
    placed_vertically = {r.source for r in relations if r.relation in ("on", "above")}
    load: Counter[str] = Counter(r.target for r in relations if r.relation == "on")
    extra: list[ParsedRelation] = []
    supports = [o for o in objects if catalogue[o.category].support]
    for obj in objects:
        cat = catalogue[obj.category]
        if obj.id in placed_vertically:
            continue
        if cat.rests == "surface":
            prefs = _SUPPORT_PREFERENCE.get(obj.category, ())
            fitting = [
                s for s in supports
                if s.id != obj.id and s.size[0] >= obj.size[0] * 0.9 and s.size[1] >= obj.size[1] * 0.9
            ]  # fmt: skip
            if not fitting:
                continue

            def score(s: ParsedObject, prefs=prefs, obj=obj) -> tuple:
                rank = prefs.index(s.category) if s.category in prefs else len(prefs)
                return (rank, load[s.id], abs(s.group - obj.group))

            best = min(fitting, key=score)
            load[best.id] += 1
            extra.append(ParsedRelation(obj.id, "on", best.id, inferred=True))
        elif cat.rests == "hanging":
            hosts = [
                o for o in objects
                if o.id != obj.id and catalogue[o.category].rests == "ground" and 0.3 < o.size[2] < 2.5
            ]  # fmt: skip
            if hosts:
                # the nearest mention, the one before on a tie ("a dresser with a mirror")
                best = min(hosts, key=lambda o: (abs(o.group - obj.group), o.group > obj.group, -o.size[0] * o.size[1]))
                extra.append(ParsedRelation(obj.id, "above", best.id, inferred=True))
    return extra


def _is_indoor(categories: list[str], text: str, catalogue) -> bool:
    low = text.lower()
    votes = 0
    for name in categories:
        tags = catalogue[name].tags
        votes += ("indoor" in tags) - ("outdoor" in tags)
    for word in ("room", "kitchen", "bedroom", "bathroom", "office", "classroom", "lab", "apartment", "studio",
                 "café", "cafe", "shop", "store", "boutique", "gallery", "hall", "interior", "indoors"):
        if re.search(rf"\b{word}\b", low):
            votes += 2
    for word in ("street", "park", "garden", "square", "market", "beach", "forest", "yard", "outdoor", "harbour",
                 "harbor", "village", "desert", "planet", "courtyard", "playground", "campsite", "field"):
        if re.search(rf"\b{word}\b", low):
            votes -= 2
    return votes > 0


def parse_scene(text: str) -> ParsedScene:
    """Read a description into objects (with ids, sizes, descriptions), relations, style and
    ground kind. Deterministic: the same text always gives the same parse."""
    return _parse_cached(" ".join(text.split()))


@lru_cache(maxsize=64)
def _parse_cached(text: str) -> ParsedScene:
    reader = _Reader(text)
    reader.read()
    _ids(reader.groups)
    catalogue = reader.catalogue
    objects = [
        ParsedObject(i, g.category, g.name, g.description, g.size, g.index) for g in reader.groups for i in g.ids
    ]
    stated = _acyclic(_expand(reader), [o.id for o in objects])
    inferred = _infer_support(objects, stated, catalogue)
    relations = _acyclic(stated + inferred, [o.id for o in objects])
    indoor = _is_indoor([o.category for o in objects], text, catalogue)
    return ParsedScene(
        text=text,
        objects=objects,
        relations=relations,
        style=detect_style(text),
        ground=detect_ground(text, indoor),
        indoor=indoor,
    )
