"""Relation phrases: where they are in the text and what kind each is.

The phrases themselves are data (``data/relation_phrases.json``): a newcomer adds a phrase to the
list of its kind there. This module finds them (longest first), reads distances ("at a distance of
12 m") and says which kinds place one object relative to one target.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

from scenewright.analysis.parser import wordnet
from scenewright.analysis.parser.sizes import _NUM_WORD
from scenewright.analysis.parser.tokens import _Tok
from scenewright.analysis.parser.vocabulary import load_vocabulary
from scenewright.analysis.parser.words import _DEFINITE, _STOP, _UNITS, _is_verb
from scenewright.core.catalogue import load_catalogue, match_phrase, singular
from scenewright.core.relations import FAR, NEAR


@lru_cache(maxsize=1)
def _rel_phrases() -> dict[str, list[str]]:
    """Kind → phrases, read once from ``data/relation_phrases.json``."""
    raw = resources.files("scenewright.data").joinpath("relation_phrases.json").read_text(encoding="utf-8")
    return json.loads(raw)["phrases"]


@lru_cache(maxsize=1)
def _phrase_table() -> dict[tuple[str, ...], str]:
    table: dict[tuple[str, ...], str] = {}
    for kind, phrases in _rel_phrases().items():
        for phrase in phrases:
            table[tuple(phrase.split())] = kind
    return table


_MAX_REL = 6
#: Phrase kinds that name relations of one object to one target, and the relations they mean.
_SINGLE_TARGET = {
    "left of": ("left of",), "right of": ("right of",), "in front of": ("in front of",), "behind": ("behind",),
    "side of": ("side of",), "near": ("near",), "far": ("far",), "on": ("on",), "above": ("above",),
    "over": ("above",), "face to": ("face to",), "opposite": ("in front of", "face to"), "between": ("near",),
    "foot of": ("in front of",), "head of": ("behind",), "hanging from": ("above",), "leaning on": ("side of",),
    "along": ("near",), "talking to": ("near",), "hitched": ("behind",), "crossing": ("on",),
}  # fmt: skip


def relation_phrases() -> dict[str, tuple[str, ...]]:
    """Phrase → the relations it means, for phrases that place one object relative to one
    target ("beside" → side of, "across from" → in front of + face to). Editing reads
    instructions with the same vocabulary."""
    return {
        phrase: _SINGLE_TARGET[kind]
        for kind, phrases in _rel_phrases().items()
        if kind in _SINGLE_TARGET
        for phrase in phrases
    }

@dataclass
class _Rel:
    kind: str
    start: int
    end: int
    #: The target is the last one named ("..., at a distance of 12 m").
    elliptic: bool = False



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
    # At most NEAR apart is "near", beyond FAR "far": the relations' own thresholds.
    kind = "near" if metres <= NEAR else "far" if metres > FAR else "no relation"
    return _Rel(kind, i, k + 1 if has_from else k, elliptic=not has_from)


#: Words for the lines things stand in ("in two long rows").
_LINE_WORDS = ("rows", "lines", "columns", "ranks")
#: Describing words between the count and the line word that leave the phrase a formation.
_MAX_LINE_WORDS = 2


def _rows_at(toks: list[_Tok], i: int) -> _Rel | None:
    """"In two long rows", "in three straight lines": the rows formation with describing words
    the listed phrases ("in two rows", "in two neat rows") do not spell out."""
    if toks[i].text != "in" or i + 2 >= len(toks) or _NUM_WORD.get(toks[i + 1].text, 0) < 2:
        return None
    for j in range(i + 2, min(i + 3 + _MAX_LINE_WORDS, len(toks))):
        w = toks[j].text
        if w in _LINE_WORDS:
            return _Rel("rows", i, j + 1)
        if w in _STOP or not w.isalpha() or not load_vocabulary().is_adjective(w):
            return None
    return None


def _qualifies_noun(toks: list[_Tok], end: int, kind: str) -> bool:
    """"on the left wall", "on the left bench", "on the left one", "in a corner seat": the side word is
    the next noun's adjective, so the phrase is only its preposition (a wall is no object: nothing
    is left of anything).
    "A ring of stones", "two circles of chairs": a verb of going around that is also a noun is
    the noun before its "of". "In the front row": the row's adjective."""
    if kind == "around" and end < len(toks) and toks[end].text == "of":
        return True
    if kind.startswith("anchor") and end < len(toks) and toks[end].text in ("row", "rows"):
        return True  # "sits in the front row": a row of seats, not the front of the room
    if kind == "anchor corner" and end < len(toks) and toks[end - 1].text == "corner" and not toks[end].joined:
        seat = match_phrase((toks[end].text,))
        return seat is not None and load_catalogue()[seat].shape in ("chair", "sofa", "bench", "stool", "armchair")
    if kind not in ("left", "right") or end >= len(toks):
        return False
    w = toks[end].text
    # ("on the left tower": a singular chiefly a noun; "on the left stands a lamp", "on the left sit two boys": verbs)
    noun = not _is_verb(w) or singular(w) == w and not wordnet.rather_verb(w)
    return w in ("one", "ones") or (w[0].isalpha() and w not in _STOP and noun)  # ("on the left one")


#: Words that open a noun phrase: a phrase word right after one is a noun's own word ("a border
#: guard", "the past"), no relation ("her" and "that" also stand before verbs and prepositions).
_ARTICLES = (_DEFINITE - {"her", "that"}) | {"a", "an", "another"}


#: Kinds of phrase that name a side of their target ("to the right of", "at her left", "to
#: either side of"): one that opens on the last word of another phrase is the place, and the
#: other no phrase ("reads to the right of the cannon": nobody reads to a side).
_SIDE_KINDS = {"left of", "right of", "left", "right", "its left", "its right", "side of", "flank", "flank elliptic"}


def _listed_at(toks: list[_Tok], i: int, taken: set[int]) -> _Rel | None:
    """The longest listed phrase that starts at ``i`` and overlaps no phrase already found."""
    table = _phrase_table()
    for length in range(min(_MAX_REL, len(toks) - i), 0, -1):
        if any(k in taken for k in range(i, i + length)):
            continue
        key = tuple(t.text for t in toks[i : i + length])
        if key in table and not _qualifies_noun(toks, i + length, table[key]):
            return _Rel(table[key], i, i + length)
    return None


def _find_relations(toks: list[_Tok], taken: set[int]) -> list[_Rel]:
    rels: list[_Rel] = []
    i = 0
    while i < len(toks):
        if i in taken or (i > 0 and toks[i - 1].text in _ARTICLES):
            i += 1
            continue
        hit = _distance_at(toks, i) or _rows_at(toks, i)
        if hit is None and (hit := _listed_at(toks, i, taken)) is not None and hit.end - hit.start > 1:
            side = _listed_at(toks, hit.end - 1, taken)
            if side is not None and (side.kind in _SIDE_KINDS or side.kind.startswith("anchor")):
                hit = side  # "reads to the right of", "waves at her left", "runs along the back": the side phrase
        if hit:
            rels.append(hit)
            i = hit.end
        else:
            i += 1
    return rels
