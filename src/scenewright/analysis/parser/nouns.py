"""Noun phrases: catalogue matches, their counts, adjectives and the look written after them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

from scenewright.analysis.catalogue import load_catalogue, match_phrase, phrase_index, singular
from scenewright.analysis.parser.tokens import _Tok
from scenewright.analysis.parser.words import (
    _DEFINITE,
    _DETERMINERS,
    _NUMBERS,
    _QUANTITY,
    _STOP,
    _UNITS,
    _VAGUE,
    _is_verb,
)


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
