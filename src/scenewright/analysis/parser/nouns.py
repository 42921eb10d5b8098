"""Noun phrases: catalogue matches, their counts, adjectives and the look written after them.
"""

from __future__ import annotations

import itertools
import re

from dataclasses import dataclass, field
from functools import lru_cache

from scenewright.core.catalogue import load_catalogue, match_phrase, phrase_index, singular
from scenewright.analysis.parser import wordnet
from scenewright.analysis.parser.grammar import _BUILDING_PARTS, _LIVING, _THRESHOLDS
from scenewright.analysis.parser.phrases import _phrase_table
from scenewright.analysis.parser.tokens import _CLAUSE_WORDS, _Tok
from scenewright.analysis.parser.vocabulary import GENERIC, Entry, load_vocabulary
from scenewright.analysis.parser.words import (
    _APPROXIMATE,
    CROWD,
    _DEFINITE,
    _DETERMINERS,
    _NUMBERS,
    ORDINALS,
    _ORDINALS,
    _QUANTITY,
    _STOP,
    _UNITS,
    _VAGUE,
    _FINITE,
    _GAMES,
    _HAND_VERBS,
    _HANG_VERBS,
    _HOLD,
    _KEPT_IN_HAND,
    _PLACE_ADVERBS,
    _PLANT_SHAPES,
    _PREPOSITIONS,
    _TURN_VERBS,
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
    #: What the open vocabulary says of a thing the catalogue does not name (a guessed object).
    guess: Entry | None = None
    #: Nouns before the head that name its kind ("dragon" in "a dragon statue").
    modifier: list[str] = field(default_factory=list)
    #: The likeness this phrase names again by its kind ("the T-rex" after "a T-rex skeleton").
    likeness_of: _Mention | None = None
    #: The ones a counted plural names after a colon ("four adventurers sit by the fire: a knight,
    #: an elf, a dwarf and a wizard"): its members, each drawn as what it is.
    members: list[_Mention] = field(default_factory=list)
    #: The role an apposition gives it, the first word of its name ("the bride, a white fox": the bride fox).
    role: str | None = None
    #: The one this apposition names again ("their coach, a woman in a red parka": the coach).
    renames: _Mention | None = None

    @property
    def own(self) -> bool:
        """Said to be someone's own ("its own low table"): a thing of its own, no part of the owner."""
        return "own" in (a.lower() for a in self.adjectives)


@dataclass
class _Group:
    index: int
    category: str
    count: int
    name: str
    description: str
    size: tuple[float, float, float]
    ids: list[str] = field(default_factory=list)
    #: How it rests (``ground``, ``surface``, ``hanging``): its category's, or the vocabulary's.
    rests: str = "ground"
    #: Read through the open vocabulary, not the catalogue.
    guessed: bool = False
    #: The text states its size ("a 3 m tall statue"): no rule resizes it.
    sized: bool = False
    #: A toy or a model of its kind ("a toy penguin"): drawn as one, but no living thing (it is held,
    #: carried, set on shelves).
    likeness: bool = False


@lru_cache(maxsize=1)
def _max_phrase_len() -> int:
    return max(len(k) for k in phrase_index())


#: Places named after what they hold ("a throne hall", "a book shop").
_VENUES = {"room", "hall", "shop", "store", "garden", "yard", "market", "park", "studio", "gallery", "lab",
           "area", "aisle", "section", "station", "court", "museum", "cafe", "café", "bar", "square",
           "street", "farm", "factory", "workshop", "showroom", "district", "festival", "fair", "lot",
           "lounge", "parlour", "parlor", "emporium", "boutique", "depot", "dealership", "nursery", "expo",
           "convention", "meetup", "sale"}  # fmt: skip
#: Nouns that often qualify the next word ("a stone path", "a pine forest", "a canvas awning").
_MODIFIER_NOUNS = {"glass", "stone", "rock", "crystal", "box", "plant", "flower", "book", "rope", "candle",
                   "cat", "dog", "fruit", "bird", "horse", "tree", "sign", "toy", "table", "cactus", "mushroom",
                   "hay", "lamp", "pool", "tower", "pine", "oak", "maple", "birch", "cherry", "palm", "cedar",
                   "canvas", "chalkboard", "blackboard", "bench", "chair", "gem", "orb", "barrel", "wine",
                   "bottle", "cup", "coffee", "bus", "car", "boat", "robot", "fence", "kiosk", "computer"}  # fmt: skip

#: Adjectives that make any thing a projection.
_PROJECTED = {"holographic", "hologram", "projected", "virtual"}
#: Things that keep their kind when holographic: a sign with a holographic face is still a sign
#: (and so is a thing with a top, which projects: "a holographic table").
_SHOWS_PROJECTION = {"sign", "billboard", "menu_board"}


def _match_at(toks: list[_Tok], i: int) -> tuple[int, str, Entry | None] | None:
    """The longest thing named at ``i``: a catalogue phrase, else (same length) a vocabulary one."""
    n = len(toks)
    vocabulary = load_vocabulary()
    for length in range(min(max(_max_phrase_len(), vocabulary.longest), n - i), 0, -1):
        words = tuple(t.text for t in toks[i : i + length])
        if any(not w[0].isalpha() for w in words):
            continue
        # "a cork board" is the catalogue's corkboard: a compound written open or closed
        cat = match_phrase(words) or (match_phrase(("".join(words),)) if length == 2 else None)
        if _verb_ends_subject(toks, i, i + length):
            continue  # "a wizard in a pointed hat stands on ...", "the far wall looms": a verb, not a stand
        if cat and not vocabulary.over_catalogue(words):  # ("a figurine" is a statue of its own size)
            return i + length, cat, None
        entry = vocabulary.match(words)
        if entry is None and length > 1 and words[0].endswith("'s"):
            entry = vocabulary.match((words[0][:-2], *words[1:]))  # "a stag's head" is a stag head
        # a catalogue head keeps its kind ("a toy chest" is a chest) unless the vocabulary says
        # otherwise ("an arcade cabinet"); "a fig plant stands" has a verb, not a plant stand
        verb = length > 1 and words[-1] != singular(words[-1]) and singular(words[-1]) in _FINITE
        # "two music stands", "a cluster of hot dog stands" are stands
        verb = verb and not _counted_plural(toks, i) and not (i > 0 and toks[i - 1].text == "of")
        head_known = length > 1 and match_phrase(words[-1:]) and not vocabulary.over_catalogue(words)
        if entry is not None and not verb and not head_known:
            return i + length, entry.category, entry
    return None


#: Determiners of one thing: a plural after them is no noun of their phrase ("a hat stands").
_SINGULAR_DETERMINERS = {"a", "an", "another", "each", "every", "one"}


def _verb_ends_subject(toks: list[_Tok], i: int, end: int) -> bool:
    """The plural ending at ``end`` is the verb of a singular subject, not a noun: a phrase
    opened by "a" cannot end in a plural ("a wizard in a pointed hat stands", "a gondolier poles
    his boat"), and a plural placing verb right after a singular noun is its verb ("the far wall
    looms", "a tower looms")."""
    last = toks[end - 1].text
    transitive = end < len(toks) and toks[end].text in _OBJECT_OPENERS  # "... poles his boat"
    verb_next = transitive or end < len(toks) and toks[end].text in _PARTICLES
    placing = verb_next or end < len(toks) and toks[end].text in ("in", "inside", "near", "beneath")
    closes = toks[i - 1].text == "," and _closes_apposition(toks, i - 1)
    if end - i == 1 and last != singular(last) and placing and closes:
        return True  # "The captain, a parrot with one eye, perches on the wheel", "Their host, ..., rocks in a chair"
    if last == singular(last) or not (singular(last) in _FINITE or transitive) or _counted_plural(toks, i):
        return False
    j = i - 1
    # (past describing words, and the words hyphened into one: "a three-tier cake stands")
    while j >= 0 and i - j <= 4 and (toks[j].text[:1].isalpha() and toks[j].text not in _STOP or toks[j + 1].joined):
        j -= 1
    if j >= 0 and toks[j].text in _SINGULAR_DETERMINERS:
        return True  # ("a TV stands on the table")
    if end - i != 1 or i == 0:
        return False
    before = toks[i - 1].text
    return (
        before[:1].isalpha() and before not in _STOP and singular(before) == before
        and not load_vocabulary().is_adjective(before) and not toks[i].joined
    )  # fmt: skip


def _closes_apposition(toks: list[_Tok], k: int) -> bool:
    """The comma at ``k`` closes an apposition to a sentence's definite subject ("The captain,
    a parrot with one eye, ..."): what follows it is that subject's verb."""
    j = k - 1
    while j > 0 and toks[j].text not in (".", "!", "?", ";", ","):
        j -= 1
    if j < 2 or toks[j].text != "," or toks[j + 1].text not in ("a", "an"):
        return False
    start = j - 1
    while start > 0 and toks[start - 1].text[:1].isalpha() and toks[start - 1].text not in _STOP:
        start -= 1  # back over the subject's words to its determiner
    opening = start < 2 or toks[start - 2].text in (".", "!", "?", ";")
    return opening and start > 0 and (toks[start - 1].text == "the" or toks[start - 1].text in _POSSESSIVES)


def _counted_plural(toks: list[_Tok], i: int) -> bool:
    """A count above one stands right before ``i`` (adjectives aside): "two (wooden) music stands"."""
    j = i - 1
    while j >= 0 and i - j <= 3:
        w = toks[j].text
        if (w in _NUMBERS or w in _VAGUE or w.isdigit()) and not toks[j + 1].joined:
            return w not in ("one", "single", "1")  # ("a six-wheeled rover": no count)
        if w in _STOP and not toks[j + 1].joined or not w[:1].isalnum():
            return False
        j -= 1
    return False


def _read_in_setting(toks: list[_Tok]) -> None:
    """A word whose sense the setting fixes (``setting_senses``) reads as that sense from here on
    ("a kitchen with an island": the kitchen island), its own word kept as its name."""
    senses = load_vocabulary().setting_senses
    if not any(t.text in senses for t in toks):
        return
    setting = _opening_place_word(toks)
    for k, t in enumerate(toks):
        sense = senses.get(t.text)
        after = toks[k + 1].text if k + 1 < len(toks) else "."
        if sense is not None and setting in sense[1] and after != "of":
            t.text = sense[0]


def _stand_at(toks: list[_Tok], i: int) -> tuple[int, str, Entry | None] | None:
    """"A stand" as a noun, which no list can hold (it is a verb far more often): after a
    determiner and describing words only, the stand a TV is on is a TV stand ("a TV on a low
    stand"); an animal's is a perch of its own ("a parrot perches on a wooden stand"); any other
    is the thing's own ("a microphone on a tall stand")."""
    if toks[i].text != "stand":
        return None
    j = i - 1
    while j >= 0 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP and load_vocabulary().is_adjective(toks[j].text):
        j -= 1
    if j < 0 or toks[j].text not in ("a", "an", "the", "its", "his", "her", "their"):
        return None
    before = toks[max(0, j - 6) : j]
    if any(match_phrase((t.text,)) in ("tv", "monitor") for t in before):
        return i + 1, "tv_stand", None
    vocabulary = load_vocabulary()
    if any(vocabulary.is_creature(t.text) for t in before if t.text[:1].isalpha() and t.text not in _STOP):
        perch = vocabulary.match(("perch",))
        return i + 1, perch.category, perch
    return None


def _find_mentions(toks: list[_Tok]) -> tuple[list[_Mention], list[str]]:
    """Longest-first catalogue and vocabulary matches, with a noun followed by another noun read
    as a modifier ("glass table", "stone path"), then the nouns nobody listed (a generic thing
    each); also the place words that set the scene instead of standing in it ("a sci-fi hangar
    with a spaceship", "a farmhouse kitchen")."""
    _read_in_setting(toks)
    n = len(toks)
    vocabulary = load_vocabulary()
    raw: list[tuple[int, int, str, Entry | None]] = []
    i = 0
    while i < n:
        if toks[i].quoted:
            i += 1
            continue  # "a sign reading 'Fresh Fish'": the words on the sign
        found = _match_at(toks, i) or _stand_at(toks, i)
        quantity = found is not None and found[2] is not None and "of" in (t.text for t in toks[i : found[0]])
        if found and (vocabulary.is_adjective(toks[i].text) or quantity):
            # "a glowing crystal ball": a phrase that opens with a describing word ("glowing
            # crystal") gives way to a longer thing that starts inside it ("crystal ball"), and so
            # does a measure of stuff ("a pile of hay") to a thing ("a pile of hay bales")
            longer = next((j for j in range(i + 1, found[0]) if (_match_at(toks, j) or (0,))[0] > found[0]), None)
            if longer is not None:
                i = longer
                continue
        # (a people group may have a kind: "a pipe band of six pipers")
        group = found is not None and singular(toks[found[0] - 1].text) in _PEOPLE_GROUPS
        of = found is not None and (found[0] - i == 1 or group) and found[0] + 1 < n and toks[found[0]].text == "of"
        # ("a family of four" is the family; "a quartet of four fiddlers" are the fiddlers)
        after = toks[found[0] + 2].text if of and found[0] + 2 < n else ""  # ("of six pipers": people nobody listed)
        members = group and (
            toks[found[0] + 1].text not in _NUMBERS or _match_at(toks, found[0] + 2) is not None
            or singular(after) != after and wordnet.kind_of_sense(singular(after)) == "noun.person"
        ) if of else False
        counts = of and toks[found[0] + 1].text not in _DETERMINERS  # ("the tower of the castle" is a tower)
        if counts and (toks[i].text in _QUANTITY and singular(toks[i].text) not in _PEOPLE_GROUPS or members):
            i = found[0]  # "a crowd of fans", "a couple of crates", "a choir of monks": a count, not the crowd
            continue  # ("a family of four" is the family)
        if found:
            raw.append((i, *found))
            i = found[0]
        else:
            i += 1
    unknown = _unknown_nouns(toks, raw)
    guessed = {r[0] for r in unknown}  # (whatever family a guess gave them, nobody listed these)
    raw = sorted(raw + unknown, key=lambda r: r[0])
    mentions: list[_Mention] = []
    places: list[str] = []
    opening_place = _opening_place_word(toks)
    modifier: list[str] = []
    part_end: int | None = None  # where an opening "the bridge of" ends: its owner is the setting too
    picture_end: int | None = None  # where an opening "a painting" ends: what it shows is the setting
    for k, (s, e, cat, entry) in enumerate(raw):
        nxt = raw[k + 1] if k + 1 < len(raw) else None
        words = [t.text for t in toks[s:e]]
        if entry is not None and e - s == 1 and nxt and nxt[0] == e and words[0] in vocabulary.adjectives:
            raw[k] = (s, s, cat, entry)  # "a baby elephant": a describing word before a noun ("a sleeping
            continue  # baby" ends its phrase: a baby)
        if e - s == 1 and singular(words[0]) != words[0] and s > 1 and _worn(toks, s - 1, s):
            raw[k] = (s, s, cat, entry)  # "a baker in a white apron slides loaves": the verb of who wears it
            continue
        # the head of "suits of armour" is "suits": plural, so "two suits of armour guard the door" has a verb
        head = words[words.index("of") - 1] if "of" in words[1:] else words[-1] if words else ""
        # a singular noun before another names its kind ("glass table", "dragon statue"); a plural
        # one is the subject of a verb that looks like a noun ("pylons guard the altar")
        several = bool(words) and words[-1] in _SAME_PLURALS and _bare(toks, s)
        # ("cattle mill about": a word of any kind is their verb when a particle follows it)
        moves = nxt is not None and nxt[1] < n and toks[nxt[1]].text in _MOTION_PARTICLES | {"about"}
        if nxt and nxt[0] == e and several and (nxt[3] is None or nxt[3].category == GENERIC or moves):
            if nxt[1] - nxt[0] == 1 and not toks[nxt[0]].text.endswith("s"):
                raw[k + 1] = (nxt[0], nxt[0], nxt[2], nxt[3])  # "sheep graze by the wall": their verb
                nxt = None
        # "a family of monkeys swings from the branches": a plural right after a plural, before a
        # preposition, is the verb (of the family), no kind of thing
        after_next = toks[nxt[1]].text if nxt and nxt[1] < n else ""
        if nxt and nxt[0] == e and nxt[1] - nxt[0] == 1 and singular(head) != head and after_next in _VERB_PARTICLES | {
            "from", "on", "in", "above", "along", "by", "beside", "near"
        } and singular(toks[nxt[0]].text) != toks[nxt[0]].text:
            raw[k + 1] = (nxt[0], nxt[0], nxt[2], nxt[3])
            nxt = None
        if nxt and nxt[0] == e and singular(head) == head:
            last = toks[nxt[1] - 1].text
            if singular(last) != last and _plural_is_verb(toks, s, nxt):  # "a knight guards the gate": a verb
                raw[k + 1] = (nxt[0], nxt[0], nxt[2], nxt[3])
                nxt = None
        if nxt and nxt[0] == e and nxt[1] - nxt[0] == 1 and (_no_noun_after(toks, e, words[-1]) or (
            _perceived(toks, s) and _plural_form_verb(toks[e].text, toks[e + 1].text if e + 1 < n else ".")
        )):  # ("watching a cow eat from a bale": after a verb of seeing or letting, its bare verb)
            raw[k + 1] = (nxt[0], nxt[0], nxt[2], nxt[3])
            nxt = None
        if nxt and nxt[0] == e and singular(head) == head:
            kind_word = nxt[1] - nxt[0] == 1 and singular(toks[nxt[0]].text) in _KIND_WORDS
            if not (nxt[3] is not None and entry is None and kind_word):
                modifier += words
                continue
            raw[k + 1] = (nxt[0], nxt[0], nxt[2], nxt[3])  # "a chalkboard menu board": the board is the menu board
            e = nxt[1]
        if s == e:
            continue
        if not (nxt and nxt[0] == e) and _living_category(cat) and _names_contents_kind(toks, s, e):
            # "a bowl of dog treats", "a bag of cat food": treats of a kind (food is no thing), no dog
            if toks[e].text in vocabulary.not_things:
                continue
            entry = _guess(toks, e, toks[s:e])
            e, cat, words = e + 1, entry.category, [t.text for t in toks[s : e + 1]]
        if _role_after_as(toks, s, cat):
            continue  # "four logs around it as seats", "a crate used as a table": a use, not a thing
        if e < n and toks[e].text.endswith("'s") and toks[e].text[:-2].isalpha() and not toks[s].text.endswith("'s"):
            continue  # "a lighthouse keeper's cottage": the kind of keeper, no lighthouse
        if _owner_of_setting(toks, s, e, cat):
            continue  # "a kitchen in the cottage of the three bears": whose place it is, not who is there
        if _source_of_scene(toks, s):
            continue  # "a cel-shaded scene from an adventure game": where the picture comes from
        if e - s == 1 and toks[s].text in _GAMES and s > 0 and toks[s - 1].text in ("play", "plays", "playing"):
            continue  # "three guards play dice around a barrel": a game, not its pieces
        if _fire_in_hearth(toks, s, e):
            continue  # "a fire crackles in the fireplace": the fireplace's own fire
        if e - s == 1 and s > 0 and toks[s - 1].text in ("his", "her", "their") and words[0] in vocabulary.body_parts:
            continue  # "an orb hovering over his palm": a part of him, no palm tree
        # (a word nobody listed that the guess makes a person by the verb after it is worn too: "a grower
        # in a hairnet kneels")
        unlisted = entry is not None and (entry.category == GENERIC or vocabulary.match(tuple(words)) is None)
        if _worn(toks, s, e) or (unlisted and _worn_by(toks, s, e, mentions)):
            continue  # "a knight in battered armour": what he wears, not a thing standing there; "a diver
            # in a drysuit": a word nobody listed that a person is in
        if _in_look_list(toks, s):
            continue  # "a moon base, all chrome fins and pastel domes": how everything looks
        if _likeness_of(toks, s) or _material_of(toks, s):
            modifier = []  # (the kind of a noun that is no thing names no kind of the next one)
            continue  # "a neon sign shaped like a cactus", "in the style of a woodcut": a look, not a
            # thing; "a lantern made from a snail shell": what the lantern is made of
        if e + 1 < n and toks[e].text == "in" and toks[e + 1].text in _MEASURES:
            continue  # "a room six tatami mats in size", "two cars in length": a measure, not things
        if toks[s].joined and e - s == 1 and singular(words[0]) == words[0] and _names_kind(toks, e):
            modifier = []
            continue  # "a block-building game": half of a hyphened modifier, not a building (a plural
            # half heads its phrase: "three slug-creatures crawl")
        if _gerund_here(toks, s, e):
            continue  # "two children are building a snowman": a verb, not a building
        if _adverb_here(toks, s, e):
            continue  # "the shrine stands well behind the gate": an adverb, not a well
        if _idiom_here(toks, s, e) or _shape_of_group(toks, s, e) or _distance_here(toks, s, e) or (
            _verb_before_pronoun(toks, s, e)
        ):
            continue  # "a brig lies at anchor", "a guard stands on duty": no anchor there; "blocks
            # stacked into a tower": how they are set out, no tower; "a few meters in front": how far;
            # "researchers in parkas count them": a verb
        if _owned_part(toks, s, e, mentions) or _part_of_after(toks, s, e, raw[k + 1 :], mentions) or (
            _inside_of_vehicle(toks, s, e, mentions)
        ):
            continue  # "a console, reading its screens": the console's screens, no monitors of their own
        kind, modifier = modifier, []
        cat, entry = _kind_of_plant(kind, cat, entry)
        if kind and entry is not None and entry.category == "figure":
            machine = match_phrase(tuple(kind))
            if machine is not None and load_catalogue()[machine].shape == "robot":
                cat, entry = machine, None  # "a robot bartender" is a robot that tends the bar
        # "two robots stand guard": a bare word right after a verb is part of it (not "a news
        # helicopter"), unless it is a plural the verb of the noun before acts on ("a girl holds
        # balloons", "a clown juggles balls")
        plural = e - s == 1 and singular(words[-1]) != words[-1]
        # (a word the reader already read as a verb has an empty span: "a baker slides loaves")
        verb_of_noun = k > 0 and raw[k - 1][1] == s - 1 and (raw[k - 1][0] == s - 1 or _verb_of_one(toks, s - 1))
        verb_before = s > 0 and _is_verb(toks[s - 1].text) and not _opens_phrase(toks, s - 1) and not (plural and verb_of_noun)
        # "a robot with six arms ladles stew": a plural names no kind of the next word, so a plural
        # right after one is a verb
        before = toks[s - 1] if s > 0 else None
        verb_before = verb_before or (
            before is not None and before.text[:1].isalpha() and before.text not in _STOP and not toks[s].joined
            and singular(before.text) != before.text and plural and not verb_of_noun
            and before.text not in _PLURAL_KINDS
        )  # fmt: skip
        if entry is not None and (verb_before or (k > 0 and raw[k - 1][1] == s and not kind)):
            continue  # "two robots stand guard", "fox statues guard the path": a verb here
        if _bare_plural_verb(toks, s, e) and not kind:
            continue  # "the farrier, a broad woman, shoes a grey mare": a verb taking its object
        if e - s == 1 and words[0] in ("crowd", "crowds") and _noun_before_object(toks, s, e):
            continue  # "jars of jam crowd the shelf": their verb, no crowd
        if _verb_of_no_thing(toks, s, e):
            continue  # "the saloon doors swing behind him": what no-things do, not a swing
        if e - s == 1 and [t.text for t in toks[max(0, s - 3) : s]] == ["of", "them", ","]:
            continue  # "its passengers, a dozen of them, crowd along the parapet": the verb after the count
        if e - s == 1 and _one_doing(toks, s):
            continue  # "two dogs play; one chases a ball, the other sleeps": one of them, and its verb
        if entry is None and k > 0 and raw[k - 1][1] == s and _plural_subject_before(toks, raw[k - 1], e):
            continue  # "two kids fish from the pier", "the children swing on the gate": a verb here
        follow = toks[e].text if e < n else ""
        participle = toks[e].text.endswith(("ing", "ed")) or toks[e].text in _IRREGULAR_PARTICIPLES if e < n else False
        if e < n and toks[e].joined and (toks[e].text in _LIKENESS or participle):
            continue  # "a mushroom-shaped lamp", "a goldfish-scooping stall", "glass-domed huts", "a candle-lit
            # cellar": a look or a use
        if follow in ("style", "styled"):
            continue  # "a tower room in oil-painting style": a look, no painting
        # "three sheep graze": after a count, a compound would end in a plural ("three fish tanks")
        verb_after = _counted_plural(toks, s) and e < n and not toks[e].joined and singular(follow) == follow
        verb_after = verb_after or several
        # ("an airship hull hangs from chains": a part put somewhere on its own stands for its thing)
        whole = e + 1 < n and toks[e].text in _WHOLE_PARTS and _placed_verb(toks, e + 1)
        if entry is not None and singular(words[-1]) == words[-1] and _names_kind(toks, e) and not verb_after and not whole:
            continue  # "a bear face", "a train compartment", "camel-hair tents": a kind, not a thing
        if _use_compound(toks, s, e, cat):
            continue  # "a sheep shearing shed", "a horse riding school": what the next thing is for
        if _owner_of_named_part(toks, s, e):
            continue  # "a crawler with a crane arm", "a hat of peacock feathers": whose part, no crane
        # ("Children queue at a van": a plural names no kind of place, the word after it is its verb)
        if e < n and toks[e].text[:1].isalpha() and toks[e].text not in _STOP and not toks[e].joined and (
            singular(words[-1]) == words[-1] and not several
            and not _is_verb(toks[e].text) and not _participle(toks[e].text) and _match_at(toks, e) is None
            and toks[e].text not in vocabulary.adjectives and _unknown_opening_place(toks, e, e + 1)
        ):
            continue  # "An otter sanctuary by a river.": the kind of the place nobody listed the opening names
        follow_two = f"{follow} {toks[e + 1].text}" if e + 1 < n else ""
        # (a plural names no kind of place: "two kids dig a hole" has a verb, no dig site)
        placed_kind = singular(words[-1]) == words[-1] or words[-1] in _SAME_PLURALS
        # ("cattle mill about": a place word before a particle is the verb)
        placed_kind = placed_kind and not (e + 1 < n and toks[e + 1].text in _MOTION_PARTICLES | {"about"})
        # ("a cat lounges on the sofa": after "a", a plural place word is the verb of the thing)
        article = _phrase_opener(toks, s)
        plural_verb = singular(follow) != follow and article >= 0 and toks[article].text in _SINGULAR_DETERMINERS
        # ("two friends lounge in the tub": a counted plural names no kind of lounge either)
        # ("a film set on a soundstage": the two words name the place)
        named = follow in _VENUES or follow in vocabulary.places or follow_two in vocabulary.places
        named = named or f"{words[-1]} {follow}" in vocabulary.places and singular(words[-1]) not in vocabulary.places
        if placed_kind and named or (
            follow and singular(follow) in _VENUES and len(words) == 1
            and not plural_verb and not _counted_plural(toks, s)
        ) or _names_place_after(toks, e):
            continue  # "a throne hall", "a farmhouse kitchen", "a rocket launch site": the place, not the thing
        if _place_name(toks, s):
            continue  # "a dig on a hillside in southern Turkey": a country, not a bird
        if _during(toks, s):
            continue  # "a planetarium during a school visit", "during a live cooking show": when, no thing
        unlisted = s in guessed or entry is not None and entry.category in (GENERIC, *_ENCLOSING)
        if unlisted and _unknown_opening_place(toks, s, e):
            places.append(" ".join(words))
            continue  # "An art nouveau perfumery, all brass and glass.": a word nobody listed names the setting
        if (places or opening_place) and _whereabouts_of_setting(toks, s, mentions[-1].end if mentions else -1):
            places.append(" ".join(words))
            continue  # "a wizard's study at the top of a tower": where the setting is, not a thing in it
        if _is_place(toks, s, e, raw[k + 1 :]) or (
            follow in ("floor", "interior", "grounds") and singular(words[-1]) in vocabulary.places
        ):  # "an abandoned factory floor with a conveyor belt"
            places.append(" ".join(words))
            continue
        j = _described_from(toks, s)
        if cat in _LIVING and singular(words[-1]) in vocabulary.places and _placed_by(toks, j):
            # "three rigs are parked beside a wooden diner": the building, not one who dines
            building = vocabulary.building(tuple(words))
            cat, entry = (building.category, building) if building is not None else (cat, entry)
        if " ".join(words) in places and s > 0 and toks[s - 1].text in _DEFINITE:
            building = vocabulary.building(tuple(words)) if _placed_by(toks, s - 1) else None
            if building is None:
                continue  # "the middle of the cabin" after "The captain's cabin of a ship": the setting again
            cat, entry = building.category, building  # "a diner in the desert ... parked in front of the diner"
        shape = load_catalogue()[cat].shape
        alive = cat in _LIVING or shape in _LIVING
        shown = not alive and not vocabulary.carries(cat, " ".join(words), ("vehicles",))
        if picture_end is not None and shown and all(
            t.text[:1].isalpha() and t.text not in _STOP or t.text in ("a", "an") for t in toks[picture_end + 1 : s]
        ):  # ("a comic panel of a flying saucer": the saucer is there)
            places.append(" ".join(words))  # "... painting of a windy headland": the place it shows
            picture_end = None
            continue
        picture_end = None
        if _picture_of_scene(toks, s, e, cat):
            picture_end = e  # "A soft watercolour painting of a windy headland": the medium, not a thing in it
            continue
        opening = _opening_place(toks, s)
        enclosing = cat in _ENCLOSING or cat == GENERIC or load_catalogue()[cat].shape in _ENCLOSING
        building = load_catalogue()[cat].shape in ("house", "building")
        if _part_of_vessel(toks, s, e, building) or (part_end is not None and _owner_of_part(toks, part_end, s)) or (
            opening is not None and (enclosing or opening in ("inside", "interior"))
        ):  # (a word nobody listed too: "the kennel room of an animal shelter"; anything one is inside of:
            # "The inside of a genie's lamp")
            # "The bridge of a small cargo spaceship, ...": the bridge and the ship are the setting
            places.append(" ".join(words))
            part_end = e if part_end is None else None
            continue
        opener = next((t.text for t in reversed(toks[:s]) if not t.text[:1].isalpha() or t.text in _STOP), ".")
        qualifies = follow[:1].isalpha() and follow not in _STOP and follow not in vocabulary.adjectives and (
            not _opens_a_phrase_after(toks, e)
        ) and (
            not _is_verb(follow) or singular(follow) in vocabulary.not_things and opener not in _SINGULAR_DETERMINERS
            and not (e + 1 < n and toks[e + 1].text in _VERB_PARTICLES)
        )  # ("of tiny stone tiles": a plural part, no verb; "a brass lamp glows", "her dog barks at" have one)
        # (a participle after it is its state, "a candle left on it"; hyphened, a kind: "a horse-drawn cart")
        state = _participle(follow) and not (e < n and toks[e].joined and follow in _IRREGULAR_PARTICIPLES)
        if len(words) == 1 and words[0] in _MODIFIER_NOUNS and qualifies and not state and (
            not _joint_verb(toks, e, cat)
        ):  # ("a dog and a cat play": the verb of both)
            continue  # "a stone path", "a glass roof": an adjective here
        # "cargo loaders on caterpillar tracks wait": the parts' kind, no animal ("a cat curls up" has a verb)
        verb_after = e + 1 < n and toks[e + 1].text in _STOP
        parts_kind = follow in vocabulary.parts and singular(follow) != follow and not verb_after
        if shape in ("animal", "bird") and len(words) == 1 and parts_kind:
            continue
        after = singular(toks[e + 1].text) if e + 1 < n else "."
        if not alive and follow.endswith("ing") and (after in _ACTIVITIES or vocabulary.names_place(after)):
            continue  # "a cake decorating class", "a bread baking stall": what the activity is about
        projector = cat in _SHOWS_PROJECTION or load_catalogue()[cat].support
        if s > 0 and toks[s - 1].text in _PROJECTED and not projector:
            cat, entry = "hologram", None  # "holographic koi" are light, not fish: place and size them as one
        animal = vocabulary.animal_senses.get(singular(words[-1])) if len(words) == 1 else None
        animal_verb = (_verb_after(toks, e) or ("",))[0] in vocabulary.animal_only_verbs
        if animal is not None and (animal_verb or _haunt(toks, e)):
            cat, entry = animal.category, animal  # "two cranes wade in the reeds", "stands in the shallows": birds
        person = vocabulary.person_senses.get(singular(words[-1])) if len(words) == 1 else None
        if person is not None and (_as_person(toks, e) or _looks_like_person(toks, s)):
            cat, entry = person.category, person  # "fans in fancy dress line the barriers": people
        if singular(words[-1]) == "one" and mentions and (entry is None or entry.category == GENERIC):
            # "a tall pine tree ..., with a few smaller ones": more of the thing named before
            # (the sentence's subject, not the landmark it stands by)
            stop = max((k for k in range(s) if toks[k].text in (".", "!", "?")), default=-1)
            same = [m for m in mentions if m.start > stop]
            cat, entry = (same or mentions)[0 if same else -1].category, (same or mentions)[0 if same else -1].guess
        phrase = " ".join(t.orig for t in toks[s:e])
        phrase = phrase[:-2] if phrase.endswith(("'s", "’s")) else phrase  # "the diner's roof": the diner
        phrase = re.sub(r"['’]s ", " ", phrase)  # "a stag's head" is named as the stag head it is
        mention = _Mention(cat, phrase, s, e, 1, False, False)
        mention.guess, mention.modifier = entry, kind
        mentions.append(mention)
    if opening_place is not None and not any(opening_place.split()[-1] in p.split() for p in places):
        places.insert(0, opening_place)
    _short_for_compound(toks, mentions)
    _parts_of_each(toks, mentions)
    mentions = sorted(mentions + _elided_members(toks, mentions), key=lambda m: m.start)
    return _alias_mentions(toks, mentions), places


def _parts_of_each(toks: list[_Tok], mentions: list[_Mention]) -> None:
    """"Racks line the walls, every shelf packed with sacks": "every" or "each" before a part word
    (``part_owners``) of a thing this sentence named before is that thing's part, so the phrase
    names the things themselves (every rack), not a new one of the part's own catalogue word."""
    owners = load_vocabulary().part_owners
    catalogue = load_catalogue()
    for k, m in enumerate(mentions):
        word = singular(toks[m.end - 1].text)
        if m.end - m.start != 1 or m.start < 1 or toks[m.start - 1].text not in ("each", "every") or word not in owners:
            continue
        stop = max((j for j in range(m.start) if toks[j].text in (".", "!", "?")), default=-1)
        owner = next((o for o in reversed(mentions[:k]) if o.start > stop and o.category != m.category and (
            o.category in owners[word] or catalogue[o.category].shape in owners[word]
        )), None)  # fmt: skip
        if owner is not None:
            m.category, m.guess, m.alias = owner.category, owner.guess, True


def _one_doing(toks: list[_Tok], s: int) -> bool:
    """The word at ``s`` is the verb of a clause opened by "one" or "the other" standing for one of the
    several named before ("one chases a ball", "the other sleeps under a tree"): a "-s" form right
    after it, with what it acts on or where it goes next."""
    if s < 2 or s >= len(toks) or toks[s - 1].text not in ("one", "other") or not toks[s].text.endswith("s"):
        return False
    opener = toks[s - 2].text if toks[s - 1].text == "one" else (toks[s - 3].text if s > 2 else "")
    if toks[s - 1].text == "other" and toks[s - 2].text != "the":
        return False
    after = toks[s + 1].text if s + 1 < len(toks) else ""
    return opener in (".", ";", ",", "and", "while", "but") and (
        after in _STOP or after in _PREPOSITIONS or not after[:1].isalpha()
    )


def _elided_at(toks: list[_Tok], i: int) -> int | None:
    """Where a noun left out after "another", "a third" or "two others" would stand, when a verb
    follows right away ("..., while another draws water", "and a third waits by the door"): the
    index of the count word that stands for it; None when a noun follows or none is left out."""
    w = toks[i].text
    if w == "others" and i > 0 and toks[i - 1].text in _NUMBERS:
        return i  # ("two others sweep the steps": a plural noun could not follow)
    if w == "more" and i > 0 and _NUMBERS.get(toks[i - 1].text, 0) > 1 and i + 1 < len(toks):
        nxt, after = toks[i + 1].text, toks[i + 2].text if i + 2 < len(toks) else "."
        if not nxt[:1].isalpha() or nxt in _STOP or _plural_form_verb(nxt, after):
            return i  # "a goat drinks while three more graze": more of the kind before, no noun left out
    if _herd_count(toks, i):
        return i
    if w == "another":
        k = i
    elif w in ("a", "an") and i + 1 < len(toks) and toks[i + 1].text in ORDINALS:
        k = i + 1
    else:
        return None
    verb = toks[k + 1].text if k + 1 < len(toks) else ""
    return k if _is_verb(verb) else None  # (a singular noun after "another" ends in no -s)


#: Collective nouns of animals: "a herd of twenty" with no noun after it is twenty of the animal named before.
_HERDS = {"herd", "herds", "flock", "flocks", "pack", "school", "shoal", "swarm", "pod", "pride", "troop", "gaggle",
          "colony", "litter", "drove"}  # fmt: skip


def _herd_count(toks: list[_Tok], i: int) -> bool:
    """A count that stands for its animals: "a herd of (about) twenty" followed by no noun ("...
    from a herd of about twenty grazing past the tents", "a flock of thirty, wheeling")."""
    if toks[i].text not in _NUMBERS or _NUMBERS[toks[i].text] < 2 or i + 1 >= len(toks) or toks[i + 1].joined:
        return False
    k = i - 1 - (i > 0 and toks[i - 1].text in _APPROXIMATE)
    if k < 1 or toks[k].text != "of" or toks[k - 1].text not in _HERDS:
        return False
    after = toks[i + 1].text
    return not after[:1].isalpha() or after in _STOP or _match_at(toks, i + 1) is None and (
        _is_verb(after) or _participle(after)
    )


def _elided_members(toks: list[_Tok], mentions: list[_Mention]) -> list[_Mention]:
    """One more of the group named last ("two porters carry a crate, and a third waits by the
    door"; "a monk reads, while another sweeps"): a count with its noun left out names more of the
    latest plural noun (for "another", of the latest living thing too), in its sentence or the one
    before. Not after "one" as a subject ("one boy reads, another sleeps" splits a group)."""
    out = []
    for i in range(len(toks)):
        k = _elided_at(toks, i)
        if k is None:
            continue
        sentences = [j for j in range(i) if toks[j].text in (".", "!", "?")]
        since = sentences[-2] if len(sentences) > 1 else -1
        if any(t.text == "one" for t in toks[(sentences[-1] if sentences else -1) + 1 : i]):
            continue
        before = [m for m in mentions if since < m.start and m.end <= i and not m.alias]
        lives = [m for m in before if load_catalogue()[m.category].shape in _LIVING]
        if _herd_count(toks, k):  # (a herd is of animals: the latest that is no person)
            lives = [m for m in lives if not _person_mention(m)]
            if not lives:
                continue
        # (one that does something is more of the people or animals, when there are: "two smiths
        # work at a pair of anvils while a third pumps the bellows")
        plural = [m for m in before if _is_plural(toks, m)]
        # ("another" is one more of a single one too: "a monk reads, while another draws water")
        # (and so is "three more": "a goat drinks while three more graze")
        any_one = toks[i].text in ("another", "more") or _herd_count(toks, k)
        order = [lives, plural] if any_one else [[m for m in plural if m in lives], plural]
        if toks[i].text == "more":  # the latest subject or object, not a place: "lassos a grazer while four more drink"
            order.insert(0, [m for m in before if not _after_preposition(toks, m.start)])
        chosen = next((group[-1] for group in order if group), None)
        if chosen is None:
            continue
        *kind, head = chosen.phrase.split()
        name = " ".join([*kind, load_vocabulary().singular(head) if head.islower() else head])  # ("a third" of "mechanics")
        m = _Mention(chosen.category, name, k, k + 1, 1, False, False)
        m.guess, m.modifier = chosen.guess, chosen.modifier
        out.append(m)
    return out


_POSSESSIVES = {"his", "her", "their", "its", "my", "our", "your"}


def _short_for_compound(toks: list[_Tok], mentions: list[_Mention]) -> None:
    """"his bike" after "a motorbike rider" is the motorbike: a one-word noun after a possessive,
    the end of a closed compound the text used since it last named a thing of the noun's own
    kind (even as a modifier), which the catalogue files elsewhere. Not after "the": "the house"
    after "a greenhouse" is mostly another house."""
    for m in mentions:
        if m.end - m.start != 1 or m.start == 0 or toks[m.start - 1].text not in _POSSESSIVES or m.guess is not None:
            continue
        word = singular(toks[m.start].text)
        since = max((x.end for x in mentions if x.category == m.category and x.start < m.start), default=0)
        for t in reversed(toks[since : m.start]):
            whole = singular(t.text)
            category = match_phrase((whole,)) if whole != word and whole.endswith(word) else None
            if category is not None and category != m.category:
                m.category = category
                break


def _plural_subject_before(toks: list[_Tok], before: tuple, e: int) -> bool:
    """A catalogue noun right after a plural noun and before a preposition or an object is that
    plural's verb ("two kids fish from the pier"): a noun before another is singular ("a fish
    tank"), and a compound goes on with a noun."""
    last = toks[before[1] - 1].text
    follow = toks[e].text if e < len(toks) else "."
    plural = singular(last) != last and (last,) not in load_vocabulary().entries  # "herbs" is listed as written
    return plural and singular(toks[e - 1].text) == toks[e - 1].text and follow in _STOP and follow[:1].isalpha()


def _names_place_after(toks: list[_Tok], e: int) -> bool:
    """A noun, then a place word after it: the three name the place ("an orc war camp", "a
    zeppelin mooring field"), not a thing and what it does ("a dog guards camp")."""
    if e + 1 >= len(toks) or toks[e].joined or toks[e + 1].joined:
        return False
    middle, last = toks[e].text, toks[e + 1].text
    if not middle.isalpha() or middle in _STOP or _is_verb(middle) or middle in load_vocabulary().adjectives:
        return False
    after = toks[e + 2].text if e + 2 < len(toks) else "."
    places = load_vocabulary().places
    return (last in places or last in _VENUES) and (not after.isalpha() or after in _STOP)


def _during(toks: list[_Tok], s: int) -> bool:
    """The noun phrase at ``s`` follows "during" (past its article and describing words): an event
    that says when the scene is, whatever its words can name elsewhere ("a visit", "a show")."""
    j = s - 1
    while j >= 0 and (toks[j].text in _DETERMINERS or toks[j].text[:1].isalpha() and toks[j].text not in _STOP):
        j -= 1
    return j >= 0 and toks[j].text == "during"


def _place_name(toks: list[_Tok], s: int) -> bool:
    """A capitalised noun inside a sentence after "in" or "from" names a place ("in southern
    Turkey", "a carpet from Persia"), not the thing a lower-case word would."""
    if s == 0 or not toks[s].orig[:1].isupper() or toks[s - 1].text in (".", "!", "?", '"', ":"):
        return False
    j = s - 1
    while j >= 0 and s - j <= 3 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
        j -= 1
    return j >= 0 and toks[j].text in ("in", "from", "across", "throughout")


#: Categories that name any plant of their kind, so the kind before them says which ("a cypress tree").
_GENERIC_PLANTS = {"tree", "bush"}


def _kind_of_plant(kind: list[str], cat: str, entry: Entry | None) -> tuple[str, Entry | None]:
    """"a cypress tree" is the catalogue's cypress (a conifer), not any tree: a plant word
    before a generic plant noun names the plant."""
    if not kind or cat not in _GENERIC_PLANTS:
        return cat, entry
    named = match_phrase(tuple(kind))
    if named is None or named == cat or load_catalogue()[named].shape not in _PLANT_SHAPES:
        return cat, entry
    return named, None


#: Nouns that are also adverbs of degree or place, read as such when bare before a preposition.
_ADVERB_NOUNS = {"well", "way", "far", "right", "just", "back"}
_ADVERB_FOLLOWERS = {"behind", "away", "back", "above", "below", "beyond", "off", "over", "past", "ahead", "out",
                     "inside", "outside", "in", "into", "before", "under", "beneath", "apart", "clear", "up", "down"}  # fmt: skip


def _adverb_here(toks: list[_Tok], s: int, e: int) -> bool:
    """A one-word noun with no determiner, number or adjective of its own, right before a
    preposition: "stands well behind the gate", "set way back from the road"."""
    if e - s != 1 or toks[s].text not in _ADVERB_NOUNS or e >= len(toks) or toks[e].text not in _ADVERB_FOLLOWERS:
        return False
    before = toks[s - 1].text if s > 0 else "."
    if not before[:1].isalpha():
        return True
    return before not in _DETERMINERS and before not in _NUMBERS and not load_vocabulary().is_adjective(before)


#: Shapes of the buildings whose parts "the chimney", "the porch" name once one of them is named.
_HOUSES = ("house", "building")


def _owned_part(toks: list[_Tok], s: int, e: int, mentions: list[_Mention]) -> bool:
    """A part word after "its"/"their" (``part_owners``: "its screens", "its counter", "the
    truck's ... its cab") when a thing named before has such a part, or in the "with" part of
    such a thing ("a log cabin with a stone chimney", "a castle with two towers"): that thing's
    part, which the relation reading maps to its owner, not a thing of its own."""
    if e - s != 1 or s == 0:
        return False
    owners = load_vocabulary().part_owners.get(singular(toks[s].text))
    catalogue = load_catalogue()
    head = singular(toks[s].text)
    if not owners:
        return False
    if toks[s - 1].text in ("its", "their"):
        return any(m.category in owners or catalogue[m.category].shape in owners for m in mentions)
    article = s - 1 - (s > 1 and toks[s - 1].text in _PART_SIDES)  # ("the left tower")
    if toks[article].text == "the" and not any(singular(toks[m.end - 1].text) == head for m in mentions):
        # "a cabin ... smoke rises from the chimney": the part of a building named before that has one
        houses = [m for m in mentions if catalogue[m.category].shape in _HOUSES]
        return any(m.category in owners or catalogue[m.category].shape in owners for m in houses)
    j = _with_article(toks, s)
    if not j or not mentions:
        return False
    owner = mentions[-1]
    return owner.end == j - 1 and (owner.category in owners or catalogue[owner.category].shape in owners)


def _with_article(toks: list[_Tok], s: int) -> int:
    """Where the article or count of a with-part's noun at ``s`` stands ("with a smoking chimney",
    "with two towers", "with four wheels"), else 0."""
    j = s - 1
    while j > 0 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
        j -= 1  # back over its describing words ("a smoking chimney")
    return j if j > 0 and toks[j].text in ("a", "an", *_NUMBERS) and toks[j - 1].text == "with" else 0


#: Side words before a part that say which one it is ("the back seat of the car").
_PART_SIDES = {"back", "front", "rear", "left", "right", "near", "far", "top", "bottom", "upper", "lower"}


def _part_of_after(toks: list[_Tok], s: int, e: int, later: list, mentions: list[_Mention]) -> bool:
    """"The ladder of the nearer one", "the ramp of the van", "the back seat of an estate car": a
    part (``part_owners``) named by "the ... of" its owner, a thing that has such a part (the next
    noun, or for "one" the thing named lately that has one): the owner's part, placed by the
    owner, no thing of its own."""
    article = s - 1 - (s > 1 and toks[s - 1].text in _PART_SIDES)  # ("the back seat", "the front bench")
    if e - s != 1 or article < 0 or toks[article].text != "the" or e + 1 >= len(toks) or toks[e].text != "of":
        return False
    owners = load_vocabulary().part_owners.get(singular(toks[s].text))
    if not owners:
        return False
    k = e + 1
    while k < len(toks) and k - e <= 4 and toks[k].text[:1].isalpha() and toks[k].text not in ("one", "ones"):
        k += 1
    catalogue = load_catalogue()
    if k < len(toks) and toks[k].text in ("one", "ones"):
        candidates = [m.category for m in mentions[-3:]]
    else:
        candidates = [later[0][2]] if later and later[0][0] <= e + 4 else []
    return any(c in owners or catalogue[c].shape in owners for c in candidates)


def _idiom_here(toks: list[_Tok], s: int, e: int) -> bool:
    """A bare singular noun right after "at" ("at anchor", "at sea"), a phrase of manner or state,
    not a thing: no determiner, count or describing word, and the phrase ends there."""
    if e - s != 1 or s < 1 or toks[s - 1].text != "at" or singular(toks[s].text) != toks[s].text:
        return False
    after = toks[e].text if e < len(toks) else "."
    return not after[:1].isalpha() or after in _STOP


def _verb_before_pronoun(toks: list[_Tok], s: int, e: int) -> bool:
    """A singular word right after a plural and right before a pronoun it acts on ("two
    researchers in red parkas count them"): the plural's verb, no count."""
    if e - s != 1 or s < 1 or e >= len(toks) or toks[e].text not in ("them", "it", "him", "her", "their", "its"):
        return False
    before, word = toks[s - 1].text, toks[s].text
    return before[:1].isalpha() and before not in _STOP and singular(before) != before and singular(word) == word


def _distance_here(toks: list[_Tok], s: int, e: int) -> bool:
    """A unit of length right after a count ("a few meters in front of", "ten metres away"): a
    distance, no meter."""
    if e - s != 1 or s < 1 or toks[s].text not in _UNITS:
        return False
    count = toks[s - 1].text
    return count in _NUMBERS or count in _VAGUE or count.isdigit() or count in ("couple", "dozen")


#: Relation phrase kinds that set a group out in a shape ("in a circle", "stacked into a tower").
_GROUP_SHAPES = {"row", "rows", "stack", "circle"}


def _shape_of_group(toks: list[_Tok], s: int, e: int) -> bool:
    """The one-word noun at ``s`` ends a phrase that sets a group out in a shape: no thing."""
    table = _phrase_table()
    return e - s == 1 and any(
        table.get(tuple(t.text for t in toks[e - length : e])) in _GROUP_SHAPES for length in range(2, min(e, 4) + 1)
    )


#: Parts of a vessel or a building that are a setting when the text opens with "the X of a Y".
_PLACE_PARTS = {"bridge", "deck", "cockpit", "hold", "cabin", "interior", "inside", "galley", "hull", "flight deck",
                "top deck", "upper deck", "lower deck", "main deck", "gun deck", "passenger deck", "car deck"}


def _part_of_vessel(toks: list[_Tok], s: int, e: int, building: bool = False) -> bool:
    """The description opens with "The bridge of a ...", "The cockpit of an old plane", or with
    a ``building`` of another ("The weaving shed of a cotton mill")."""
    j = s - 1
    while j >= 0 and (
        toks[j].text in _DETERMINERS or toks[j].text[:1].isalpha() and toks[j].text not in _STOP
    ):  # "The captain's cabin of a sailing ship", "The kennel room of a shelter"
        j -= 1
    opening = j < 0 or toks[j].text in (".", "!", "?")
    part = " ".join(t.text for t in toks[s:e])
    # (what follows "of" is a thing named with its article: "a pool of water" is no part of the water)
    owner = e + 1 < len(toks) and (toks[e + 1].text in _DETERMINERS or toks[e + 1].orig[:1].isupper())
    place = building or part in _PLACE_PARTS or part in load_vocabulary().places
    return opening and place and e < len(toks) and toks[e].text == "of" and owner


def _inside_of_vehicle(toks: list[_Tok], s: int, e: int, mentions: list[_Mention]) -> bool:
    """"The open cabin door" after a seaplane, "the cockpit" after a glider: the inside of a
    vehicle named in this sentence or the one before (``_PLACE_PARTS``, with "the" or "its"), no
    cabin or hall of its own."""
    if " ".join(t.text for t in toks[s:e]) not in _PLACE_PARTS:
        return False
    j = _phrase_opener(toks, s)
    if j < 0 or toks[j].text not in ("the", "its"):
        return False
    stops = [k for k in range(s) if toks[k].text in (".", "!", "?")]
    since = stops[-2] if len(stops) > 1 else -1
    vocabulary = load_vocabulary()
    return any(m.start > since and vocabulary.carries(m.category, m.phrase, ("vehicles",)) for m in mentions)


#: Categories and shapes that can hold a scene inside them ("the engine room of a starship").
_ENCLOSING = {"house", "building", "tower", "spaceship", "boat", "vehicle", "bus", "truck", "tent", "structure"}


def _opening_place(toks: list[_Tok], s: int) -> str | None:
    """The place the description opens with when the noun at ``s`` owns it ("The engine room of
    a rusty cargo starship", "The kitchen of an old farmhouse"): a setting, not a thing in it."""
    j = s - 1
    # back over describing words and nouns of its kind ("a colony ship", "a small animal shelter",
    # "a long-haul freighter")
    while j >= 0 and (toks[j].text in _DETERMINERS or toks[j].text[:1].isalpha() and toks[j].text not in _STOP
                      or toks[j].joined or j + 1 < s and toks[j + 1].joined):
        j -= 1  # fmt: skip
    if j < 1 or toks[j].text != "of":
        return None
    places = load_vocabulary().places
    for width in (2, 1):
        part = " ".join(t.text for t in toks[max(0, j - width) : j])
        if part in places or part in _PLACE_PARTS:
            return part if _part_of_vessel(toks, j - width, j) else None
    return None


#: What a description may say it is a view of, before "from" and the work it comes from.
_SCENE_VIEWS = {"scene", "still", "shot", "screenshot", "level", "frame", "moment", "panel", "page"}


def _source_of_scene(toks: list[_Tok], s: int) -> bool:
    """The noun at ``s`` names the work a scene comes from ("a scene from an adventure game", "a
    still from a silent film"): no thing of the scene."""
    j = s - 1
    while j >= 0 and (toks[j].text in ("a", "an", "the") or toks[j].text[:1].isalpha() and toks[j].text not in _STOP):
        j -= 1
    return j >= 1 and toks[j].text == "from" and toks[j - 1].text in _SCENE_VIEWS


#: What burns a fire inside it, so that the fire is its own, no thing beside it.
_HEARTHS = {"fireplace", "hearth", "stove", "furnace", "oven", "grate", "brazier", "forge", "kiln", "fire pit",
            "firepit"}  # fmt: skip


def _fire_in_hearth(toks: list[_Tok], s: int, e: int) -> bool:
    """The fire at ``s`` burns in a hearth the next words name ("a fire crackles in the fireplace",
    "a log fire roaring in the hearth")."""
    if toks[e - 1].text not in ("fire", "fires", "flames", "blaze"):
        return False
    k = next((j for j in range(e, min(e + 3, len(toks))) if toks[j].text in ("in", "inside", "within")), None)
    if k is None:
        return False
    words = [t.text for t in toks[k + 1 : k + 5]]
    return any(w in _HEARTHS or f"{w} {v}" in _HEARTHS for w, v in zip(words, [*words[1:], ""]))


def _picture_of_scene(toks: list[_Tok], s: int, e: int, category: str) -> bool:
    """The description opens with the picture it is ("A watercolour painting of a headland", "An
    illustration of a market", "A pop art comic panel of a flying saucer", "Pencil storyboard
    frame: an orbital station"): a picture, or a panel, followed by "of" or a colon, with only
    describing words (a decade too: "a 1980s airbrush painting") before it."""
    if category not in ("picture_frame", "panel") or e >= len(toks) or toks[e].text not in ("of", ":"):
        return False
    if not all(t.text[:1].isalnum() and (t.text not in _STOP or t.joined) or t.text in ("a", "an") for t in toks[:s]):
        return False  # (a hyphened look is a describing word: "a blue-and-white tile panel of")
    k = e  # a sentence that only names the picture: "A painting of a ship hangs ..." is a thing
    while k < len(toks) and toks[k].text not in (".", "!", "?") and not _verb_word(toks[k].text):
        if toks[k].text == "all" and toks[k - 1].text == ",":
            return True  # ", all bold dots and outlines": how it looks, to the end
        k += 1
    return k >= len(toks) or toks[k].text in (".", "!", "?")


def _owner_of_part(toks: list[_Tok], part_end: int, s: int) -> bool:
    """The noun at ``s`` is the owner in "the bridge of a small cargo spaceship"."""
    return toks[part_end].text == "of" and s - part_end <= 5 and all(
        t.text[:1].isalpha() and t.text not in (",", "with") for t in toks[part_end + 1 : s]
    )


def _role_after_as(toks: list[_Tok], s: int, category: str) -> bool:
    """The noun at ``s`` names what another thing serves as ("as seats", "as a table"), not
    "as well as a lamp" or "such as a lamp"."""
    j = s - 1
    while j >= 0 and s - j <= 3 and toks[j].text not in ("as", "to", "by") and toks[j].text[:1].isalpha() and (
        toks[j].text in ("a", "an", "the", "her", "his", "their", "its") or toks[j].text not in _STOP
    ):
        j -= 1
    owner = category == GENERIC or load_catalogue()[category].shape in ("figure", "animal")
    if j >= 1 and (toks[j - 1].text, toks[j].text) in _ABSENT_OWNER and owner:
        return True  # "a bedroom belonging to a teenage girl": the owner is not in the scene ("boys run by a
        # tent": a thing owns nothing, the boys run past it)
    if j >= 1 and toks[j].text == "for" and not any(t.text in _DETERMINERS or t.text in _NUMBERS for t in toks[j + 1 : s]):
        return True  # "a bench for parents", "a fridge for vaccines": whom or what it serves, no thing here
    return j >= 1 and toks[j].text == "as" and toks[j - 1].text not in ("well", "such", "same")


def _owner_of_setting(toks: list[_Tok], s: int, e: int, category: str) -> bool:
    """People or animals after "<place> of" in the verbless opening own the setting ("the
    cottage of the three bears", "the den of an old fox") when the text names them again later
    ("Papa Bear stirs the pot"): those later ones are who is there ("the workshop of an old
    clockmaker" named once is the clockmaker in it)."""
    if load_catalogue()[category].shape not in ("figure", "animal"):
        return False
    head = singular(toks[e - 1].text)
    if not any(singular(t.text) == head for t in toks[e:]):
        return False
    j = s - 1
    while j >= 0 and s - j <= 4 and (toks[j].text in _DETERMINERS or toks[j].text in _NUMBERS or (
        toks[j].text[:1].isalpha() and toks[j].text not in _STOP
    )):
        j -= 1
    if j < 1 or toks[j].text != "of" or not _verbless_opening(toks, j):
        return False
    place = singular(toks[j - 1].text)
    known = match_phrase((place,))
    return place in load_vocabulary().places or (known is not None and load_catalogue()[known].shape in _ENCLOSING)


def _in_look_list(toks: list[_Tok], s: int) -> bool:
    """The noun at ``s`` is in a list opened by ", all" that says how the whole scene looks ("a
    moon base, all chrome fins and pastel domes", "a lounge, all black lacquer and fan shapes"):
    describing words, nouns, commas and "and" only, back to the comma."""
    j = s - 1
    while j >= 1 and s - j <= 10 and (toks[j].text in (",", "and") or (
        toks[j].text[:1].isalpha() and toks[j].text not in _STOP
    )):
        j -= 1
    return j >= 1 and toks[j].text == "all" and toks[j - 1].text == ","


#: Words right before what someone wears ("in battered armour", "wearing a cape").
_WEARING = {"in", "wearing", "wears", "wore", "donning", "clad"}


def _worn(toks: list[_Tok], s: int, e: int) -> bool:
    """Clothing the catalogue also names as a thing ("armour") is worn after "in" or
    "wearing": "a knight in battered armour"; "a suit of armour stands by the door" is a thing."""
    clothing = load_vocabulary().clothing
    last = toks[e - 1].text
    pair = f"{toks[s - 1].text} {last}" if s > 0 else ""  # ("a worker in ear defenders": no defenders)
    if singular(last) not in clothing and last not in clothing and pair not in clothing:
        return False
    j = s - 2 if pair in clothing else s - 1
    while j >= 0 and s - j <= 4 and toks[j].text[:1].isalpha() and toks[j].text not in _WEARING and (
        toks[j].text in _DETERMINERS or toks[j].text not in _STOP
    ):
        j -= 1
    return j >= 0 and toks[j].text in _WEARING


def worn_description(toks: list[_Tok], end: int) -> list[str]:
    """What a person is said to wear right after their noun ending at ``end`` ("a vet in a green
    coat", "with a red cap", "wearing a yellow hat and grey overalls"), as words for their
    description, so the figure is dressed in the colours the text gives; [] when none follows."""
    if end >= len(toks) or toks[end].text not in _WEARING | {"with"}:
        return []
    clothing = load_vocabulary().clothing
    k, last = end + 1, None
    while k < len(toks) and k - end <= 10 and toks[k].text[:1].isalpha() and (
        toks[k].text not in _STOP or toks[k].text in _DETERMINERS or toks[k].text == "and"
    ):
        if toks[k].text in clothing or singular(toks[k].text) in clothing:
            last = k
        elif toks[k].text == "and" and last != k - 1:
            break  # "in a green coat and a cap", not "in green and a dog"
        k += 1
    return [] if last is None else _written(toks[end : last + 1])


def _written(toks: list[_Tok]) -> list[str]:
    """The words of ``toks`` as written, a hyphened word whole ("neon-pink")."""
    words: list[str] = []
    for t in toks:
        if t.joined and words:
            words[-1] += "-" + t.text
        else:
            words.append(t.text)
    return words


def _worn_by(toks: list[_Tok], s: int, e: int, mentions: list[_Mention]) -> bool:
    """The noun at ``s`` follows "in" right after a person ("a diver in a drysuit"), or right after
    a noun and before what only people do ("a grower in a hairnet kneels"): what the person wears,
    since people are in clothes, not in things nobody listed."""
    j = s - 1
    while j >= 0 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
        j -= 1
    if j < 1 or toks[j].text not in ("a", "an") or toks[j - 1].text != "in":
        return False
    if any(_worn(toks, x, x + 1) for x in range(j + 1, s)):
        return False  # "a baker in a white apron slides loaves": the apron is worn, the loaves are slid
    if not mentions or mentions[-1].end != j - 1:
        return False
    return _person_mention(mentions[-1]) or _does_what_people_do(toks, e)


#: Participles before "like" that make what follows a look ("shaped like a fish", "painted like a comic").
_LIKENESS_VERBS = {"shaped", "painted", "styled", "drawn", "carved", "made", "built", "designed", "dressed",
                   "disguised", "decorated", "looks", "look", "looking", "rendered", "moulded", "molded",
                   "sculpted", "stitched", "sewn", "knitted", "woven", "together", "pieced", "assembled",
                   "cut", "folded", "glazed", "printed"}  # fmt: skip
#: Nouns before "of" that make what follows a look ("in the style of an etching", "in the shape of a heart").
_LIKENESS_NOUNS = {"style", "shape", "form", "manner", "likeness", "fashion", "spirit", "size"}
#: Words of size a comparison ends on before "as"/"than" ("as big as a horse", "no bigger than a cat").
_COMPARED = {"big", "large", "small", "tall", "long", "wide", "high", "heavy", "bigger", "larger", "smaller",
             "taller", "longer", "wider", "higher", "heavier", "tiny", "huge"}  # fmt: skip


def _likeness_of(toks: list[_Tok], s: int) -> bool:
    """The noun at ``s`` says what another thing looks like, not a thing of its own: "a sign
    shaped like a cactus", "a rock resembling a turtle", "in the style of an ink painting", "a
    crab the size of a dinner plate"."""
    j = s - 1
    while j >= 0 and s - j <= 5 and toks[j].text[:1].isalnum() and toks[j].text not in ("resembling", "resembles") and (
        toks[j].text in ("a", "an", "the") or toks[j].text not in _STOP
    ):  # ("in the style of a 1950s pulp magazine cover": a decade is a describing word)
        j -= 1
    if j < 1:
        return False
    w, before = toks[j].text, toks[j - 1].text
    if w == "like":
        return before in _LIKENESS_VERBS
    if w in ("as", "than") and before in _COMPARED:
        return True  # "a dragon as big as a barn", "a spider no bigger than a coin": a size, no barn
    return (w == "of" and before in _LIKENESS_NOUNS) or w in ("resembling", "resembles")


def _material_of(toks: list[_Tok], s: int) -> bool:
    """The noun at ``s`` follows "made from", "carved out of" and the like: the stuff another thing
    is made of ("a lantern made from a snail shell", "a boat carved from a single log")."""
    j = s - 1
    while j >= 0 and s - j <= 5 and toks[j].text[:1].isalpha() and (
        toks[j].text in _DETERMINERS or toks[j].text in _NUMBERS or toks[j].text not in _STOP
    ):
        j -= 1
    if j >= 1 and toks[j].text == "of" and toks[j - 1].text == "out":
        j -= 1  # "carved out of"
    return j >= 1 and (toks[j - 1].text, "of" if toks[j].text == "out" else toks[j].text) in _MADE_OF


#: After "in", what makes the noun before a unit of measure ("six tatami mats in size").
_MEASURES = {"size", "length", "width", "area", "diameter", "height", "depth", "breadth", "span"}
#: Word pairs after which a noun names an owner, not a thing of the scene.
_ABSENT_OWNER = {("belonging", "to"), ("belongs", "to"), ("owned", "by"), ("run", "by")}


def _gerund_here(toks: list[_Tok], s: int, e: int) -> bool:
    """A one-word "-ing" noun used as a verb: "two children are building a snowman" (no
    determiner, number or adjective before it, an object after it)."""
    w = toks[s].text
    if e - s != 1 or not w.endswith("ing") or s == 0 or e >= len(toks) or toks[e].text not in _OBJECT_OPENERS:
        return False
    before = toks[s - 1].text
    adjective = before[:1].isalpha() and load_vocabulary().is_adjective(before)  # ", painting a boat": no adjective
    return before not in _DETERMINERS and before not in _NUMBERS and not adjective


#: Words that open an object after a verb: "an astronaut plants a flag", "a knight guards the gate".
_OBJECT_OPENERS = {"a", "an", "the", "his", "her", "its", "their", "it", "them", "some", "two", "three", "four"}


def _plural_is_verb(toks: list[_Tok], s: int, nxt: tuple) -> bool:
    """Whether the plural noun-like word right after the singular noun at ``s`` is its verb
    ("an astronaut plants a flag") rather than the head of a compound ("two habitat domes
    stand", "three fuel tanks"): an object follows it, or (for the open vocabulary) nothing
    says it is a noun — a plural count before, or a verb after."""
    end = nxt[1]
    follow = toks[end].text if end < len(toks) else ""
    if follow in _OBJECT_OPENERS or follow in _NUMBERS:
        return True
    j = s - 1
    while j >= 0 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
        j -= 1  # (back over describing words to the article)
    if follow in _MOTION_PARTICLES and j >= 0 and toks[j].text in ("a", "an", "another"):
        return True  # "a trainee slides down it": no plural is the head of "a ..."
    if _counted_plural(toks, s):
        return False
    j = _phrase_opener(toks, s)
    if j >= 0 and toks[j].text in _SINGULAR_DETERMINERS and toks[nxt[1] - 1].text not in load_vocabulary().pair_nouns:
        return True  # "a yacht rocks at the jetty": after "a", a compound would end in a singular
    if j > 0 and toks[j].text == "of" and toks[j - 1].text in _QUANTITY:
        return False  # "a stack of drill pipes": what a quantity counts is a noun phrase
    person = load_vocabulary().match(tuple(t.text for t in toks[s : nxt[0]]))
    bare = j < 0 or not toks[j].text[:1].isalpha()  # ("Emperor penguins waddle": a lone singular needs an article)
    if person is not None and person.category == "figure":
        return not bare  # "the baker slides loaves into the oven": a person names no kind of slide
    if _is_verb(follow) or follow in _FINITE or follow.endswith("ing") and follow.isalpha():
        return False  # "glass domes holding birds": a participle after it makes it the noun
    return nxt[3] is not None


#: Words that make the noun hyphened before them a look ("mushroom-shaped", "star-patterned").
_LIKENESS = {"shaped", "like", "style", "styled", "themed", "sized", "patterned", "print", "printed", "inspired"}
#: Vocabulary words that only restate what the catalogue noun before them is ("a menu board").
_KIND_WORDS = {"board", "panel", "screen", "machine", "device", "unit", "box", "container", "tool", "vehicle",
               "structure", "apparatus", "console", "gadget", "station", "post", "pole", "platform"}  # fmt: skip


#: Participles without -ed that follow a noun to describe it ("strung with lights", "built of stone").
_IRREGULAR_PARTICIPLES = {"strung", "hung", "spun", "built", "made", "lit", "set", "worn", "torn", "sunk", "stuck",
                          "swung", "bound", "wound", "laid", "held", "spread", "cast", "shot", "dug", "hidden",
                          "frozen", "broken", "woven", "fallen", "overgrown", "half", "full", "covered", "slung",
                          "drawn", "bent", "kept", "cut", "split", "shut", "left", "forgotten", "lost"}  # fmt: skip


#: Parts of a body or a machine, and what covers a body: a noun right before one names whose part
#: it is ("a crane arm", "peacock feathers", "a bear hide"), not a thing of its own.
_PART_NOUNS = {"arm", "limb", "wing", "tail", "hook", "propeller", "boom", "jib", "feather", "fur", "hide", "scale",
               "plume", "horn", "antler", "tusk", "claw", "skin", "pelt", "fleece", "quill"}  # fmt: skip


def _owner_of_named_part(toks: list[_Tok], s: int, e: int) -> bool:
    """The singular noun ending at ``e`` qualifies a part noun that ends the phrase right after it."""
    if e >= len(toks) or toks[e].joined or singular(toks[e - 1].text) != toks[e - 1].text:
        return False
    if singular(toks[e].text) not in _PART_NOUNS or toks[e].quoted:
        return False
    j = s - 1
    while j >= 0 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
        j -= 1  # (past the phrase's describing words: "a hermit crab hides")
    if singular(toks[e].text) != toks[e].text and j >= 0 and toks[j].text in _SINGULAR_DETERMINERS:
        return False  # "a crab hides under a shell": a verb after one thing, no hides of a crab
    after = toks[e + 1].text if e + 1 < len(toks) else "."
    return not after[:1].isalpha() or after in _STOP or _is_verb(after) or _participle(after)


def _use_compound(toks: list[_Tok], s: int, e: int, category: str) -> bool:
    """A singular noun, not a person, then an -ing word and a bare singular thing ("a sheep
    shearing shed", "a cheese weighing house"): the first two name what the thing is for, so the
    first is no thing of the scene. (A person there does the deed: "a man watching television".)"""
    if e + 1 >= len(toks) or e - s != 1 or toks[e].joined or not toks[e].text.endswith("ing"):
        return False
    word, nxt = toks[s].text, toks[e + 1].text
    if singular(word) != word or category in _LIVING - {"animal", "bird"} or load_catalogue()[category].shape == "figure":
        return False
    found = _match_at(toks, e + 1)
    return found is not None and nxt not in _STOP and singular(toks[found[0] - 1].text) == toks[found[0] - 1].text


def _names_kind(toks: list[_Tok], e: int) -> bool:
    """The noun ending at ``e`` qualifies the word after it: a hyphen joins them, or a noun that
    is no verb, adverb or participle follows."""
    if e >= len(toks):
        return False
    t = toks[e]
    w = t.text
    if w in _PREPOSITIONS:
        return False  # "pushes a wheelchair past the chairs"
    if not t.joined and _plural_verb(toks, e):
        return False  # "two mechanics on a lift work on it", "a yew and a rowan shade the gate": a verb
    if _joint_verb_at(toks, e):
        return False  # "a farmer and his son wade into the pond"
    if e + 2 < len(toks) and (toks[e + 1].text, toks[e + 2].text) in (("each", "other"), ("one", "another")):
        return False  # "a nurse and a doctor face each other": only a subject of two does it, so a verb
    if w in _ADVERBS_OF_TIME and not t.joined:
        return False  # "a church organ still stands there": an adverb, no "organ still"
    if _opens_a_phrase_after(toks, e):
        return False  # "beside the table work two nurses": a verb before its subject or object
    participle = w in _IRREGULAR_PARTICIPLES and e + 1 < len(toks) and toks[e + 1].text in _PUT_PREPOSITIONS
    if not t.joined and participle:
        return False  # "an anvil set on a stump": its participle (a set is no thing, "a chess set" aside)
    if t.joined or (w in load_vocabulary().not_things and singular(w) == w and w not in _FINITE):
        return True  # "camel-hair tents", "a bear face"
    if w in _IRREGULAR_PARTICIPLES:
        return False  # "a ferris wheel strung with bulbs": a participle, not a kind
    return (
        w[:1].isalpha() and w not in _STOP and not _is_verb(w) and not w.endswith(("ed", "ing", "ly"))
        and not load_vocabulary().is_adjective(w) and w not in _DETERMINERS
    )  # fmt: skip


#: Prepositions that follow a verb of motion or sound ("barks at", "runs to"): a plural-looking word
#: before one is a verb, not the noun a word before it describes ("her dog barks at a seal").
_VERB_PARTICLES = {"at", "to", "into", "onto", "toward", "towards", "across", "around", "over", "through", "past"}
#: Adverbs without "-ly" that come between a subject and its verb ("the organ still stands").
_ADVERBS_OF_TIME = {"still", "now", "always", "often", "also", "already", "never", "soon", "sometimes", "ever",
                    "once", "together", "alone", "too", "again", "yet"}  # fmt: skip
#: Words that open the setting's contents after a place word ("a hangar with...", "a hangar where...").
_PLACE_OPENERS = {"with", "where", "full", "filled", "housing", "containing", "holding", "packed", "crammed"}
_INSIDE = {"in", "inside", "within", "into", "throughout"}
#: m, the least height of a building a scene can stand inside (a kennel is no setting).
_STOREY = 2.2
#: Words a place phrase may have before its noun ("a bright cartoon-style pet shop").
_PLACE_WORDS = 6


def _is_place(toks: list[_Tok], s: int, e: int, later: list) -> bool:
    """A place word used as the setting: "inside a hangar", "a hangar with a spaceship" (when the
    with-part names things), not "a barn stands behind the pond"."""
    vocabulary = load_vocabulary()
    head = singular(toks[e - 1].text)
    named = vocabulary.names_place(head) or (e >= 2 and f"{toks[e - 2].text} {head}" in vocabulary.places)
    if _aboard(toks, s, e):
        return True
    building = not named and _enterable(toks, s, e)
    if not (named or building):
        return False
    j = s - 1
    while j >= 0 and s - j <= _PLACE_WORDS and (
        toks[j].text in _DETERMINERS or (toks[j].text not in _STOP and toks[j].text[:1].isalpha())
    ):
        j -= 1
    platform = match_phrase((head,)) in _PLATFORMS
    if platform and toks[e - 1].text != head and not (s > 0 and toks[s - 1].text in _NUMBERS):
        return True  # "ships unload at the docks": the harbour (one dock is a pier of the scene; "two pools" are)
    if platform and _placed_by(toks, _described_from(toks, s), _OUTSIDE_KINDS | {"around"}):
        return False  # "palm trees surround a small pool": the pool is theirs to stand round
    if j >= 0 and toks[j].text in _INSIDE:
        # (in water one is in a thing of the scene: "two hippos wallow in a mud pool", not its setting)
        water = match_phrase((head,)) == "pond" and toks[j + 1].text in ("a", "an") and not _verbless_opening(toks, j)
        return not water
    if head in load_vocabulary().landforms and j >= 0 and (_landform_part(toks, j) or _by_landform(toks, j)):
        return False  # "a dragon sleeps on top of a hill", "flies over a volcano": the hill is a thing here
    placed = toks[j + 1].text in _DETERMINERS and _placed_by(toks, j + 1, _OUTSIDE_KINDS) and not _inner_part_of(toks, j)
    if (placed or _outside_part_of(toks, j + 1)) and not _verbless_opening(toks, j):
        return False  # "a mule waits beside the tavern", "pigeons sit on the roof of the tavern": seen
        # from outside, a building of the scene (_buildings)
    if _opening_setting(toks, s, e):
        return True
    if _inner_part_of(toks, j) and not platform and (not building or j >= 3 and toks[j - 3].text in _INSIDE):
        return True  # ("a rug lies in the middle of the hut": in it; "at the back of the barn" may be behind it)
    if building:
        return False
    listing = any(t.text in _PLACE_OPENERS for t in toks[:j])  # "a garden with a pond by the greenhouse"
    if j >= 0 and toks[j].text in _SETTING_PREPOSITIONS and _verbless_opening(toks, j) and not listing:
        return True  # "A mining outpost on a grey asteroid", "a tea terrace clinging to a mountainside"
    # a sentence that only names the place ("An anime-style ramen shop late at night.")
    if later and (j < 0 or toks[j].text in (".", "!", "?")):
        k = e
        while k < len(toks) and toks[k].text not in (".", "!", "?") and not _verb_word(toks[k].text):
            k += 1
        if k >= len(toks) or toks[k].text in (".", "!", "?"):
            return True
    # the description opens with the place ("A cyberpunk hangar on the edge of the city, late at night.")
    opening = j < 0 or (toks[j].text in (".", "!", "?") and j == s - 1)
    follow = toks[e].text if e < len(toks) else "."
    # ("A small courtroom during a trial.", "A schoolroom for young rabbits.": when and for whom)
    settled = follow in (",", ".", ":", ";") or follow in ("on", "at", "in", "during", "before", "after", "for")
    # ("A fish and chip shop run by otters, ...", "a bakery staffed by mice": who keeps it)
    kept = e + 1 < len(toks) and toks[e + 1].text == "by" and (follow.endswith("ed") or follow in ("run", "kept"))
    settled = settled or kept
    if opening and later and not later_before(later, toks, e) and settled:
        return True
    # (mid-sentence, a place with things is one of the scene's: "..., and a tea house with a lantern
    # hanging from its eaves stands behind the pond")
    if e < len(toks) and toks[e].text in _PLACE_OPENERS and (j < 0 or toks[j].text not in ("and", ",")):
        starts = {r[0] for r in later}
        spans = {i for r in later for i in range(r[0], r[1])}
        holds = False
        k = e + 1
        while k < len(toks) and toks[k].text not in (".", "!", "?", ";"):
            holds = holds or k in starts  # the with-part names a thing: the place holds the scene ...
            if _verb_word(toks[k].text) and k not in spans:
                # (... unless it stands somewhere itself: "A castle with two towers stands on a rug.")
                return holds and toks[k].text not in _PLACING_VERBS
            k += 1
        return holds
    return False


#: Places one walks out onto or stands round, things of the scene as well ("fishes from the end of a
#: wooden dock", "a camel drinks at the edge of the pool", "palm trees surround a small pool").
_PLATFORMS = {"pier", "pond"}
#: Parts of a place the scene can stand in ("on the top floor of a warehouse", "at the back of the shop").
_INNER_PARTS = {"floor", "top", "edge", "roof", "corner", "end", "back", "middle", "centre", "center", "rear",
                "interior", "inside"}  # fmt: skip


def _inner_part_of(toks: list[_Tok], j: int) -> bool:
    """The words up to ``j`` end in a part of the place after them ("on the top floor of [a
    converted warehouse]", "at the back of [the shop]"): the place holds the scene (but "on top
    of [a warehouse]" puts a thing on it)."""
    return j > 0 and toks[j].text == "of" and toks[j - 1].text in _INNER_PARTS and not (
        j > 1 and toks[j - 2].text in ("on", "onto")
    )


#: Prepositions that tie the opening's place to a wider one ("a base on a rocky shoulder").
_SETTING_PREPOSITIONS = {"on", "at", "of", "to", "near", "by", "below", "beneath", "under", "above", "beside",
                         "overlooking", "outside", "atop", "upon", "behind", "beyond", "along", "across"}  # fmt: skip
#: Prepositions after a participle that put its noun somewhere ("an anvil set on a stump").
_PUT_PREPOSITIONS = _SETTING_PREPOSITIONS - {"of", "to"} | {
    "in", "into", "onto", "against", "between", "around", "inside"
}


def _verbless_opening(toks: list[_Tok], k: int) -> bool:
    """No verb comes before ``k`` in the description (a verbless style line before it aside,
    "Low poly."): the words name where the scene is ("An archaeological dig on a hillside", "The
    waiting lanes of a ferry terminal"), so a place word there is the setting, not a thing in it."""
    return not any(_verb_word(t.text) for t in toks[:k])


def _opening_setting(toks: list[_Tok], s: int, e: int) -> bool:
    """The words from ``s`` open the description and run with no verb to a colon or to a with-list
    that never points back at them: "A cow shed at milking time: four cows ...", "A goat barn in
    the Alps, with three goats in a pen" name where the scene stands ("a barn stands behind the
    pond", "a barn with a tractor beside it" name a thing of it)."""
    if not _verbless_opening(toks, s) or any(t.text in (",", ":", ";", "with", "and") for t in toks[:s]):
        return False
    if any(t.text in (".", "!", "?") for t in toks[:s]) and _opening_place_word(toks) is not None:
        return False  # "A playroom. A wooden castle with two towers stands on a rug.": the setting was named
    if e < len(toks) and toks[e].text == "of":
        return False  # "the captain's cabin of a sailing ship": whose it is decides (_opening_place)
    k = e
    while k < len(toks) and toks[k].text not in (".", "!", "?", ";", ":", "with"):
        if toks[k].text == "where":
            return True  # "A tiny yarn shop where everything is crocheted": what goes on in it
        # ("at milking time", "in the Alps": no verbs)
        if _verb_word(toks[k].text) and not toks[k].text.endswith("ing") and not toks[k].orig[:1].isupper():
            return False
        k += 1
    if k < len(toks) and toks[k].text == "with":
        rest = itertools.takewhile(lambda t: t.text not in (".", "!", "?"), toks[k:])
        return not any(t.text in ("it", "its") for t in rest)
    if k < len(toks) and toks[k].text in (".", "!", "?"):
        # "A sheep shearing shed on a hill farm in late spring.": a sentence that only names the
        # building is where the scene stands, unless the text comes back to it from outside
        # ("... . Two cows graze beside the barn", "Its roof ...")
        head = singular(toks[e - 1].text)
        later = toks[k + 1 :]
        listed = any(t.text in ("and", ",") for t in toks[e:k])  # ("A garden shed and a mower.": things)
        # (from inside it is the setting still: "a horse stands in the middle of the barn")
        again = any(singular(t.text.removesuffix("'s")) == head and not _seen_inside(toks, i)
                    for i, t in enumerate(later, start=k + 1))
        return bool(later) and not listed and not again and later[0].text not in ("it", "its")
    return k < len(toks) and toks[k].text == ":"


def _seen_inside(toks: list[_Tok], i: int) -> bool:
    """The building named at ``i`` is seen from inside: "in the barn", "in the middle of the barn"."""
    j = i - 1
    while j >= 0 and toks[j].text in _DETERMINERS:
        j -= 1
    return j >= 0 and (toks[j].text in _INSIDE or _inner_part_of(toks, j))


def _opening_place_word(toks: list[_Tok]) -> str | None:
    """The place word the verbless opening names, though it names no thing ("A milking parlour on
    a farm", "A Victorian clockmaker's workshop, lit by a lamp"): where the scene stands, so it
    decides indoors before the animals or the lamps there. A style line before a colon is
    skipped ("Flat colours: a ...")."""
    places = load_vocabulary().places
    for k, t in enumerate(toks):
        if t.text in (".", "!", "?", ";"):
            return None
        if t.text == ":" or _verb_word(t.text) and not t.text.endswith("ing"):
            if not any(u.text == ":" for u in toks[k:] if u.text not in (".", "!", "?")):
                return None  # a verb before the place: the sentence tells, not where
            continue
        follow = toks[k + 1].text if k + 1 < len(toks) else "."
        if singular(t.text) in places and (follow in _SETTING_PREPOSITIONS or follow in (",", ".", ":", "in", "with")):
            before = " ".join(u.text for u in toks[:k])
            if re.search(r"\b(?:open air|drive in|outdoor|open)$|\b(?:front|outside|exterior|yard|forecourt) of\b", before):
                return None  # "a drive-in cinema", "the front of a fire station": outside the building
            two = f"{toks[k - 1].text} {t.text}" if k > 0 else ""
            return two if two in places else t.text
    return None


def _verb_with_object(toks: list[_Tok], k: int) -> bool:
    """A verb at ``k``, also one the vocabulary knows as a noun when an object follows it ("a seal
    balances a ball")."""
    w = toks[k].text
    return _verb_word(w) or (_is_verb(w) and k + 1 < len(toks) and toks[k + 1].text in _DEFINITE | {"a", "an"})


def _unknown_opening_place(toks: list[_Tok], s: int, e: int) -> bool:
    """A noun nobody listed heads a verbless opening sentence (or the part after its style line's
    colon) and is followed by where or when it is: "A busy perfumery, all brass and glass.",
    "Bold colours: a riverside regatta on a Sunday afternoon." name the setting, not a thing."""
    j = s - 1
    while j >= 0 and (toks[j].text in _DETERMINERS or toks[j].text[:1].isalpha() and toks[j].text not in _STOP
                      and not _verb_with_object(toks, j)):  # fmt: skip
        j -= 1
    if j >= 0 and toks[j].text != ":" or any(t.text in (".", "!", "?") for t in toks[:s]):
        return False
    follow = toks[e].text if e < len(toks) else "."
    # ("A Roman amphitheatre rendered as a floor mosaic": how it is drawn)
    if follow not in _SETTING_PREPOSITIONS and follow not in (",", ".", "in") and follow not in _LIKENESS_VERBS:
        return False
    k = e
    while k < len(toks) and toks[k].text not in (".", "!", "?"):
        if _verb_word(toks[k].text) and not toks[k].text.endswith("ing") and not toks[k].orig[:1].isupper() and (
            not _in_look_list(toks, k)
        ):  # ("..., all curving brass, lilies and green glass": how it looks, no verb)
            return False
        k += 1
    return True


#: Parts of a thing the opening's place sits in or by ("at the top of a tower", "beneath the roots
#: of an oak", "in the hold of a barge").
_SETTING_PARTS = {"top", "foot", "base", "bottom", "summit", "roots", "root", "heart", "depths", "shadow", "hold",
                  "belly", "hollow", "trunk", "branches", "crown"}  # fmt: skip


def _whereabouts_of_setting(toks: list[_Tok], s: int, thing_end: int = -1) -> bool:
    """The noun at ``s`` owns the part of a thing the opening sentence puts its place at, with no
    verb before it: "A wizard's study at the top of a tower", "a fox's den beneath the roots of a
    beech" name where the setting is (the tower, the beech), not a thing standing in the scene; not
    when a thing of the scene, ending at ``thing_end``, comes right before ("In the yard, an ox at the
    foot of a cart")."""
    j = s - 1
    while j >= 0 and s - j <= 4 and (toks[j].text in _DETERMINERS or (
        toks[j].text[:1].isalpha() and toks[j].text not in _STOP
    )):  # fmt: skip
        j -= 1
    if j < 3 or toks[j].text != "of" or toks[j - 1].text not in _SETTING_PARTS or toks[j - 2].text not in _DETERMINERS:
        return False
    if toks[j - 3].text not in _SETTING_PREPOSITIONS and toks[j - 3].text not in _INSIDE or thing_end == j - 3:
        return False
    start = max((k for k in range(j) if toks[k].text == ":"), default=-1) + 1
    return not any(t.text in (".", "!", "?", ";") or _verb_word(t.text) and not t.text.endswith("ing")
                   for t in toks[start:j])  # fmt: skip


def _enterable(toks: list[_Tok], s: int, e: int) -> bool:
    """A building people stand in, named in the opening sentence: "a forge in an old stone barn"
    sets the scene inside the barn, where "a barn stands behind the pond" is a thing of the scene."""
    if any(t.text in (".", "!", "?") for t in toks[:s]):
        return False
    head = singular(toks[e - 1].text)
    # "a cow shed", "a boathouse": a kind of shed or house
    name = match_phrase(tuple(t.text for t in toks[s:e])) or match_phrase((head,)) or (
        "house" if head.endswith("house") else None
    )
    category = load_catalogue()[name] if name else None
    if (head,) in load_vocabulary().buildings:
        return True  # "a showroom in a converted bus depot": a building the vocabulary lists
    if category is None or category.size[2] < _STOREY:
        return False
    # (towers, lighthouses and windmills have rooms too, when the opening only names where the scene
    # is: "A laboratory in a castle tower." is inside it, "a bell hangs in the clock tower" is not)
    return category.shape == "house" or category.shape in ("tower", "windmill") and _verbless_opening(toks, s)


#: The vessels a room of the scene may be aboard, and rooms only a vessel has.
_VESSELS = frozenset({"spaceship", "boat"})
_VESSEL_ROOMS = frozenset({"cabin", "galley", "hold", "deck", "cockpit", "berth", "wardroom", "cabins"})


def _aboard(toks: list[_Tok], s: int, e: int) -> bool:
    """A vessel an opening with no verb puts its place on or in: "A sci-fi cargo bay on a space
    freighter:" is aboard the freighter, no thing in its own hold ("A pirate ship at sea." is the ship)."""
    aboard = ("on", "aboard", "of", "in", "inside")
    j = s - 1
    while j >= 0 and toks[j].text not in aboard and (
        toks[j].text in _DETERMINERS or toks[j].text[:1].isalpha() and toks[j].text not in _STOP
    ):
        j -= 1
    if j < 1 or toks[j].text not in aboard or not _verbless_opening(toks, j):
        return False
    if toks[j].text == "of" and toks[j - 1].text in _QUANTITY:
        return False  # "Along the canal, a row of narrowboats is moored": the boats, counted out
    vocabulary = load_vocabulary()
    entry = vocabulary.match(tuple(t.text for t in toks[s:e])) or vocabulary.match((singular(toks[e - 1].text),))
    category = entry.category if entry is not None else match_phrase(tuple(t.text for t in toks[s:e]))
    room = any(vocabulary.names_place(singular(t.text)) or t.text in _VESSEL_ROOMS for t in toks[:j])
    return category in _VESSELS and room


def _verb_word(word: str) -> bool:
    """A verb, not a plural the vocabulary knows as a noun ("with chunky outlines and candy colours")."""
    if not _is_verb(word) or word in _FINITE or singular(word) in _FINITE:
        return _is_verb(word)
    return singular(word) not in load_vocabulary().not_things


def later_before(later: list, toks: list[_Tok], e: int) -> bool:
    """Whether a thing is named between ``e`` and the next verb (then the opening noun is a subject)."""
    starts = {r[0] for r in later}
    k = e
    while k < len(toks) and toks[k].text not in (".", "!", "?", ",", ":", ";"):
        if _is_verb(toks[k].text):
            return False
        if k in starts:
            return True
        k += 1
    return False


#: Measure words ("a coil of rope", "a stack of plates") that also name a thing of their own.
_MEASURE_THINGS = {"coil", "coils", "ring", "stack", "stacks", "column", "string", "set", "line"}


def _hyphened_head_after(toks: list[_Tok], j: int, covered: set[int]) -> bool:
    """Whether a hyphened noun of a doer nobody listed follows the word at ``j`` within three
    words, with only nouns between: the head of a compound the word at ``j`` qualifies ("bear
    taste-tester", "sword-swallower"; not "push-ups")."""
    for k in range(j + 1, min(j + 4, len(toks))):
        t = toks[k]
        if not t.text[:1].isalpha() or t.text in _STOP:
            return False
        if t.joined and k not in covered:
            return load_vocabulary().is_agent_noun(t.text)
    return False


#: Words after which a plural nobody counted is a thing of the scene ("drift under bright
#: parachutes", "a pool crowded with sunbathers", "reels and brushes"), as after a verb.
#: (Not "on": "a box on stilts", "saddles hang on pegs" name what holds it up.)
_BARE_OPENERS = {"with", "under", "and", "among", "amid", "beside", "between"}


def _bare_plural_after(toks: list[_Tok], i: int, covered: set[int]) -> bool:
    """After ``i`` (an opener or a verb), up to two describing words and a plural that
    :meth:`Vocabulary.bare_thing` takes for things, which nothing else read and no noun follows."""
    w = toks[i].text
    vocabulary = load_vocabulary()
    # (a word right after a noun that describes nothing is its verb: "two instructors fold parachutes")
    verb = _is_verb(w) or i - 1 in covered and w.isalpha() and not vocabulary.is_adjective(w)
    if not (w in _BARE_OPENERS or verb and w not in _STOP):
        return False
    if w == "and" and (i - 1 not in covered or any(t.text == "of" for t in toks[max(0, i - 3) : i])):
        return False  # ("film cans and reels"; not "a chandelier made of cogs and gears")
    k = i + 1
    while k < len(toks) and k - i <= 2 and k not in covered and vocabulary.is_adjective(toks[k].text):
        k += 1
    after = toks[k + 1].text if k + 1 < len(toks) else "."
    last = after in _STOP or not after[:1].isalpha() or after in _FINITE or after in _PLACE_ADVERBS
    if w == "with" and after == "on":
        return False  # "a radio operator with headphones on": worn
    return k < len(toks) and k not in covered and last and vocabulary.bare_thing(toks[k].text)


def _unknown_nouns(toks: list[_Tok], raw: list[tuple[int, int, str, Entry | None]]) -> list:
    """Noun phrases whose head neither the catalogue nor the vocabulary knows ("a zorbulator",
    "three glimmerwings"): counted phrases only, and only heads that can name a thing; after
    "the" or a possessive, only a person ("the old watchmaker sits") or a thing in hand ("with
    his putter")."""
    vocabulary = load_vocabulary()
    covered = {k for s, e, _, _ in raw for k in range(s, e)}
    # a listed word that also describes may stand before a noun nobody listed ("three baby stegosaurs")
    describers = {s for s, e, _, _ in raw if e - s == 1 and toks[s].text in vocabulary.adjectives}
    out = []
    n = len(toks)
    for i, t in enumerate(toks):
        w = t.text
        owner = w in _OWNERS  # only for a thing held ("his hat in his hands") or a person ("their sensei, ...")
        definite = owner or w == "the"  # only for a person ("the old watchmaker sits ...")
        counter = definite or w in ("a", "an", "another") or w in _NUMBERS or w in _VAGUE or w.isdigit() or (
            w == "of" and i > 0 and (toks[i - 1].text in _QUANTITY or singular(toks[i - 1].text) in _PEOPLE_GROUPS)
        ) or _shares_article(toks, i, covered) or _bare_plural_after(toks, i, covered)
        # ("a family of colonists": the colonists, nobody listed; "fold parachutes on a tarp")
        if not counter or w == "one" and i + 1 < n and toks[i + 1].text in ("of", "another", "other"):
            continue
        if owner and i + 2 < n and _is_verb(toks[i + 1].text) and toks[i + 2].text in ("a", "an"):
            continue  # "behind her rises a glass orangery": her own, then the verb of what comes after
        rough = i + 2 < n and toks[i + 1].text in _APPROXIMATE and _elided_at(toks, i + 2) is not None
        if _elided_at(toks, i) is not None or (i + 1 < n and _elided_at(toks, i + 1) is not None) or rough:
            continue  # "a third waits": more of a group named before (:func:`_elided_members`)
        if i + 1 < n and toks[i + 1].joined and w not in ("a", "an", "another", "the", *_OWNERS):
            continue  # "a six-wheeled rover": a number hyphened to a word describes, counts nothing
        people_of = i + 1 < n and singular(toks[i + 1].text) != toks[i + 1].text and (
            wordnet.kind_of_sense(singular(toks[i + 1].text)) == "noun.person"
        )  # ("a pipe band of six pipers": the people it is of)
        counted = w in _NUMBERS and i > 1 and toks[i - 1].text == "of" and singular(toks[i - 2].text) in _PEOPLE_GROUPS
        if counted and not people_of:
            continue  # "a family of four shelters under the awning": how many, then the verb
        if (w in _NUMBERS or w.isdigit()) and i + 1 < n and toks[i + 1].text in _UNITS:
            continue  # "ten paces apart", "five yards from the gate": a distance, no things
        stuff_end, listed = _heap_of_stuff(toks, i, covered) if w == "of" else (0, False)
        if listed:  # "a heap of gold coins lies": one mound of them
            out.append((i - 1, stuff_end, _MOUND.category, _MOUND))
            covered.update(range(i - 1, stuff_end))
            continue
        if stuff_end:
            entry = _guess(toks, stuff_end - 1, toks[i - 1 : i + 1])
            out.append((i + 1, stuff_end, entry.category, entry))
            covered.update(range(i + 1, stuff_end))
            continue  # "a pile of gold", "a heap of rubble": one heap, named by its stuff
        plural = w not in ("a", "an", "another", "one", "the", "and", *_OWNERS) and not (w.isdigit() and int(w) == 1)
        j = i + 1
        if w == "a" and j < n and toks[j].text in ("few", "couple", "pair", "dozen"):
            continue  # the count of a phrase read by its own rules
        head = None
        looks: set[int] = set()  # "a whale-shaped weathervane": a known noun in a hyphened look
        while j + 1 < n and toks[j].text in _NUMBERS and toks[j + 1].joined:
            j += 2  # "a pair of six-legged beasts": a hyphened count describes
        while j < n and j - i <= 5:
            x = toks[j].text
            if j in covered and j + 1 < n and toks[j + 1].joined and toks[j + 1].text in _LIKENESS:
                looks.add(j)
                j += 1
                continue
            if j in covered and j not in describers and _hyphened_head_after(toks, j, covered):
                looks.add(j)  # "a polar bear taste-tester", "a sword-swallower": a known word names its kind
                j += 1
                continue
            if j in covered and w == "of" and _kind_before_plural(toks, j, covered):
                looks.add(j)  # "a cluster of hot dog stands": no "dog" can follow "of" alone, it names the stands' kind
                j += 1
                continue
            kind_of = j - 1 in looks and w == "of"  # ("hot dog stands": a noun, though "stands" is a verb too)
            # (a stop word hyphened on describes: "a frost-covered colonist")
            if (j in covered and j not in describers) or not x[:1].isalpha() or (x in _STOP and not kind_of and not toks[j].joined):
                break
            # (a plural verb form cannot follow "a": "a washing line hangs" has no verb "line")
            plural_form = x in _FINITE and not x.endswith("s") and w in ("a", "an", "another")
            if j > i + 1 and not plural and (_is_verb(x) and not plural_form or _plural_verb(toks, j) or _joint_verb_at(toks, j)):
                break  # "a ladder stands", "two mechanics on a scissor lift work on its joint"
            adverb = x in _ADVERBS_OF_TIME and head is not None and not vocabulary.is_adjective(toks[head].text)
            if head is not None and (x in _PLACE_ADVERBS or adverb):
                break  # "a lantern hangs from a beam overhead", "an old windmill still turns": no kind of it
                # (after a describing word it is the noun: "a copper still bubbles")
            ends = j + 1 >= n or toks[j + 1].text in _STOP or not toks[j + 1].text[:1].isalpha()
            # "a sake brewery drawn as a print": a place word is no describing word before its participle
            describing = head is not None and vocabulary.is_adjective(toks[head].text) and (
                toks[head].text not in vocabulary.not_things
            )
            if head is not None and _participle(x) and ends and not describing:
                break  # "a low ledge watching, ...", "a tarp strung between two trees": its verb, not
                # a "home recording studio"
            head = j
            j += 1
            if plural and (singular(x) != x or x in _PEOPLE_GROUPS) and x not in _PLURAL_KINDS:
                break  # "three zorbs glow", "two ground crew hold": the plural noun ends the phrase
        known = head is not None and any(
            k in covered and k not in looks and not (k == head - 1 and k in describers) for k in range(i + 1, head + 1)
        )
        if head is None or known or toks[head].quoted:
            continue
        if w == "one" and toks[head].text in vocabulary.body_parts:
            continue  # "reclines on one elbow", "kneels on one knee": how one rests, no thing
        # a counted plural before a singular known word is its subject ("two stokers shovel coal")
        subject = plural and singular(toks[head].text) != toks[head].text and j < n
        subject = subject and singular(toks[j].text) == toks[j].text
        # ("a trainee slides down it": after "a", a plural is the verb, not the noun its word describes)
        verb_next = w in ("a", "an", "another") and j < n and j in covered and head == j - 1
        verb_next = verb_next and singular(toks[j].text) != toks[j].text and toks[j].text not in vocabulary.pair_nouns
        if j < n and j in covered and not subject and not verb_next:
            continue  # the words before a known noun are its adjectives ("a shiny [robot]")
        word = toks[head].text
        if word.endswith("ing") and j < n and toks[j].text in _OBJECT_OPENERS:
            continue  # "one aiming a gun at the ship": a verb taking its object, not a noun
        if _listed_adjective(toks, head):
            continue  # "on a clear, windy morning": the first of two describing words
        held = _held(toks, head) or (owner and _in_hand(toks, i) and vocabulary.is_thing_word(word))
        if held:
            definite = False
        # "eight lanes side by side": a setting is never counted, so a counted place is a row of things
        one = singular(word)
        counted_place = _NUMBERS.get(w, 0) > 1 and one != word and one in vocabulary.places and one not in _VENUES
        # "five pairs of shoes", "a rack of coats": clothing counted out is not worn; nor is
        # clothing that hangs or lies somewhere ("three coats lie on the bed")
        stock = w == "of" and word in vocabulary.clothing or _laid_out(toks, head, j)
        # "a tesla coil", "a drum set": a measure word after the noun of its kind is the thing itself
        kind = toks[head - 1].text  # ("a washing line": what it is for)
        compound = word in _MEASURE_THINGS and head > i + 1 and (not vocabulary.is_adjective(kind) or kind.endswith("ing"))
        # "two ground crew": a people group counted is so many of its people ("a film crew" is none)
        members = _NUMBERS.get(w, 0) > 1 and word in _PEOPLE_GROUPS and not (j < n and toks[j].text == "of")
        # "two planks lean against the wall", "a tall bouldering wall rises along one side": a part
        # (or a wall) its clause puts somewhere is a thing of its own (not "its planks", "the hull")
        part = word in vocabulary.parts or word == "wall"
        bounds = word == "wall" and j < n and toks[j].text in _BOUNDING_VERBS  # "a stone wall runs along the field"
        loose = w not in ("the", *_OWNERS) and part and j < n and (_placed_verb(toks, j) or bounds)
        loose = loose and (i == 0 or toks[i - 1].text in (".", "!", "?", ";", ",", "and"))  # (its clause's subject)
        # "a dozen moulds of fresh curd": counted things of a stuff are the things (not "two sides of the hut")
        filled = _NUMBERS.get(w, 0) > 1 and one != word and j + 1 < n and toks[j + 1].text not in _DETERMINERS
        filled = filled and word not in vocabulary.parts and word not in _QUANTITY
        # ("six teleport pads glow ... between the pads and the desk": the pads read before, again)
        again = w == "the" and any(singular(toks[h].text) == one for h, *_ in out) and not _named_before(toks, head)
        # "paper moons and stars hang from the ceiling", "a cardboard moon": a made likeness of a sky thing
        crafted = one in _SKY_THINGS and (toks[head - 1].text in _CRAFT_WORDS or w in _CRAFT_WORDS)
        named = vocabulary.is_thing_word(word) or held or counted_place or stock or compound or loose or again
        if not (named or crafted) or (
            word in _QUANTITY and not counted_place and not compound and not members
        ) or (j < n and toks[j].text == "of" and not filled):
            continue  # "a sunny afternoon", "a pair of", "a sense of calm", "a boy in a red cap"
        entry = vocabulary.family("figure") if members else _guess(toks, head, toks[max(i - 1, 0) : head])
        if entry.category == GENERIC and any(vocabulary.is_creature(toks[k].text) for k in looks if toks[head].joined):
            entry = vocabulary.family("figure")  # "a polar bear taste-tester": a creature in a role, as "a penguin chef"
        if bounds:
            entry = _FREE_WALL
        if entry.category == GENERIC and singular(word) in vocabulary.clothing:
            entry = Entry(GENERIC, vocabulary.clothing_size, "surface")  # "a felt hat" on a stand: its own size
        living = entry.category == "figure" or vocabulary.is_creature(word)
        if w in _NUMBERS and i > 0 and toks[i - 1].text == "its" and not living:
            continue  # "its four propellers gleaming": a thing's parts, counted ("its two cubs" are there)
        opening = i == 0 or not toks[i - 1].text[:1].isalpha()
        placed = w == "the" and j < n and (opening and toks[j].text in _PLACING_VERBS or toks[j].text in _STANDING)
        # "...; his leather glove lies on it": a thing of his that a clause opens with, put somewhere
        placing = j < n and _placing(toks[j].text)
        put = owner and opening and placing and j + 1 < n and toks[j + 1].text in _STOP
        # ("near", "by" and "past" the landmarks and the fittings of a place too: "near the airlock";
        # what hangs "above" one is no place either: "a hook above the loading pit")
        by = _placed_by(toks, i, (_BY_KINDS - {"near"}) | {"above"}) or _outside_part_of(toks, i)
        by = by and not _named_before(toks, head)
        by = by and (j >= n or toks[j].text not in ("one", "ones"))
        # "Above the sleigh flies the Firebird": the subject a fronted place phrase puts after its verb
        inverted = w == "the" and i > 0 and _inverted_subject(toks, i - 1) and (j >= n or not toks[j].text[:1].isalpha())
        # ("snapping at the salmon leaping below them": a creature the text has doing something is there)
        creature = vocabulary.is_creature(word) and not owner and j < n and toks[j].text.endswith("ing")
        kept = placed or put or by or inverted or creature or again
        if definite and entry.category != "figure" and not kept:
            continue  # "the far end", "her turn": after "the" or "her", only a person is read, a
            # subject that opens a clause standing somewhere ("The periscope rises in the middle"),
            # or what a thing is put by ("a horse waits beside the bunkhouse")
        out.append((head, head + 1, entry.category, entry))
        covered.add(head)
    out += _bare_subjects(toks, covered) + _bare_objects(toks, covered) + _landforms(toks, covered)
    out += _joined_plurals(toks, covered)
    out += _crowds(toks, raw, covered)
    out += _owners_of_parts(toks, covered)
    out += _loose_parts(toks, covered) + _buildings(toks, covered)
    return out + _unknown_heads(toks, raw, covered) + _possessed(toks, covered)


def _kind_before_plural(toks: list[_Tok], j: int, covered: set[int]) -> bool:
    """The singular count noun at ``j`` (after "<quantity> of") stands right before a plural
    nobody listed that ends the phrase: it names that plural's kind ("a row of oak saplings" aside,
    "a cluster of hot dog stands")."""
    word = toks[j].text
    if j + 1 >= len(toks) or j + 1 in covered or singular(word) != word or word in _SAME_PLURALS:
        return False  # ("a flock of sheep grazes": the flock's verb)
    if _stuff_word(toks, j, set()):
        return False
    nxt, after = toks[j + 1].text, toks[j + 2].text if j + 2 < len(toks) else "."
    return singular(nxt) != nxt and nxt[:1].isalpha() and (after in _STOP or not after[:1].isalpha())


def _shares_article(toks: list[_Tok], i: int, covered: set[int]) -> bool:
    """The "and" at ``i`` joins a bare singular word to a one-word thing opened by "a"/"an", which
    counts both ("armed with a net and trident"): one of each."""
    if toks[i].text != "and" or i < 2 or i - 1 not in covered or toks[i - 2].text not in ("a", "an"):
        return False
    if i + 2 >= len(toks) or not toks[i + 1].text[:1].isalpha() or toks[i + 1].text in _STOP:
        return False
    after = toks[i + 2].text
    word = toks[i + 1].text
    return singular(word) == word and (not after[:1].isalpha() or after in _STOP or _is_verb(after))


def _no_noun_after(toks: list[_Tok], k: int, noun: str) -> bool:
    """The one word at ``k``, right after the noun ``noun``, names no thing of its own: an adverb
    before the verb ("an old windmill still turns"; after a describing word it is the noun: "a
    copper still bubbles") or a verb before its subject or object ("beside the table work two nurses")."""
    after = toks[k + 1].text if k + 1 < len(toks) else "."
    adverb = toks[k].text in _ADVERBS_OF_TIME and noun not in load_vocabulary().adjectives and (
        _is_verb(after) or after in _FINITE
    )
    return adverb or _opens_a_phrase_after(toks, k)


def _opens_a_phrase_after(toks: list[_Tok], k: int) -> bool:
    """The word at ``k`` comes right before a count or an article, as a verb does before its
    subject or object ("beside the table work two nurses"), never a noun of the phrase before; not
    before a measure it is compared by ("a stone sphinx the size of a house")."""
    measure = [t.text for t in toks[k + 1 : k + 4]] in (["the", w, "of"] for w in ("size", "height", "length", "width"))
    return k + 1 < len(toks) and not toks[k].joined and not measure and (
        toks[k + 1].text in _NUMBERS or toks[k + 1].text in ("a", "an", "the")
    )


def _inverted_subject(toks: list[_Tok], k: int) -> bool:
    """The verb at ``k`` follows a place phrase that opens its clause ("Above the sleigh flies",
    "Beside the gate stands"), so the noun phrase after it is its subject."""
    if not (_is_verb(toks[k].text) or toks[k].text in _FINITE or toks[k].text in _HANG_VERBS):
        return False
    start = max((j for j in range(k) if toks[j].text in (".", "!", "?", ";", ",")), default=-1) + 1
    table = _phrase_table()  # (a verb of driving is no place: "Rows of seats stretch towards the galley")
    opening = (table.get(tuple(t.text for t in toks[start : start + n])) for n in range(1, min(4, k - start) + 1))
    return any(kind not in (None, "driving") for kind in opening)


def _verb_of_no_thing(toks: list[_Tok], s: int, e: int) -> bool:
    """A bare singular word right after a plural that names no thing ("doors", "flames") and before
    a place phrase or the clause's end is that plural's verb: "the saloon doors swing behind
    him", "its flames light the room" (not "the sports car", whose "sports" is no such plural)."""
    word = toks[s].text
    if e - s != 1 or s == 0 or singular(word) != word:
        return False
    vocabulary = load_vocabulary()
    verbs = vocabulary.person_verbs | vocabulary.animal_verbs | _HANG_VERBS | _TURN_VERBS
    if word not in verbs and word + "s" not in verbs:
        return False  # (a word no verb list knows is a noun: "a tall parts cabinet")
    before = toks[s - 1].text
    if singular(before) == before or singular(before) not in vocabulary.not_things:
        return False
    after = toks[e].text if e < len(toks) else "."
    return after in _STOP or after in _PREPOSITIONS or not after[:1].isalpha()


def _bare_plural_verb(toks: list[_Tok], s: int, e: int) -> bool:
    """A one-word plural with nothing of a noun phrase before it (no determiner, count or
    describing word) and an object right after it is a verb: "..., shoes a grey mare", "...,
    hammers the nails"; "two shoes lie there", "old shoes hang" are things."""
    if e - s != 1 or e >= len(toks):
        return False
    word = toks[s].text
    if singular(word) == word or s == 0 or toks[s - 1].text not in (",", ";", "and", "who", "that", "which"):
        return False
    after = toks[e].text
    if after in _OBJECT_OPENERS:
        return after not in _NUMBERS
    # "the quartermaster, an android, counts canisters by the gate": after an apposition's comma, a
    # bare noun that ends no list ("hats, shoes and bags"; "cacti and tumbleweeds dot the sand")
    two = toks[e + 1].text if e + 1 < len(toks) else "."
    if _plural_form_verb(after, two):
        return False  # "Beyond them, spectators crowd a grandstand", "..., musicians play for a princess"
    if _participle(after) and not after.endswith("ing") and not two[:1].isalpha():
        return False  # "..., cameras raised.": things held as a participle says
    return toks[s - 1].text == "," and after[:1].isalpha() and after not in _STOP and not toks[e].joined and (
        two not in (",", "and", "or")
    )


def _names_contents_kind(toks: list[_Tok], s: int, e: int) -> bool:
    """Right after "of", an animal's noun before a word that is neither listed nor a verb names
    the kind of the contents ("a bowl of dog treats"), no thing of its own ("a flock of sheep
    graze": a verb; "a bowl of dog biscuits": the biscuits are the thing)."""
    if s < 2 or toks[s - 1].text != "of" or e >= len(toks) or toks[e].joined:
        return False
    if singular(toks[s - 2].text) in COLLECTIVES:
        return False  # ("a flock of sheep grazes": the sheep)
    word, after = toks[e].text, toks[e + 1].text if e + 1 < len(toks) else "."
    last, vocabulary = toks[e - 1].text, load_vocabulary()
    verb = word in vocabulary.person_verbs | vocabulary.animal_verbs | _HANG_VERBS or vocabulary.is_posture_verb(word)
    noun = word[:1].isalpha() and word not in _STOP and singular(last) == last
    return noun and not verb and not _plural_form_verb(word, after)


#: Verbs whose object does a thing next, named by a bare verb ("watches a dog chase a ball").
_PERCEIVING = {"watch", "watches", "watching", "watched", "see", "sees", "seeing", "hear", "hears", "hearing",
               "let", "lets", "letting", "help", "helps", "helping"}  # fmt: skip


def _perceived(toks: list[_Tok], s: int) -> bool:
    """The noun phrase at ``s`` is the object of a verb of seeing or letting ("watching a cow")."""
    j = _phrase_opener(toks, s)
    return j > 0 and toks[j].text in _DETERMINERS and toks[j - 1].text in _PERCEIVING


def _plural_form_verb(word: str, after: str) -> bool:
    """``word`` reads as the plural verb of the noun before it: a person's, an animal's or a
    hanging verb without its -s ("play", "sing"), or any bare word with an object right after it
    ("crowd a grandstand", "unload the boxes"); a noun there would end in -s ("counts canisters")."""
    vocabulary = load_vocabulary()
    if not word[:1].isalpha() or word in _STOP or singular(word) != word:
        return False
    verbs = vocabulary.person_verbs | vocabulary.animal_verbs | _HANG_VERBS
    third = f"{word[:-1]}ies" if word.endswith("y") and word[-2:-1] not in "aeiou" else f"{word}s"  # ("fly": "flies")
    return word in _FINITE or third in verbs or f"{word}es" in verbs or after in _OBJECT_OPENERS


#: Nouns of a group of people, whose "of four" counts its members ("a family of four").
_PEOPLE_GROUPS = {"family", "couple", "crowd", "audience", "party", "group", "team", "crew", "band", "gang",
                  "troupe", "class", "congregation", "choir", "orchestra", "mob", "entourage", "retinue", "ensemble",
                  "quartet", "trio"}  # fmt: skip
#: One named thing that is several ("a family", "a herd"): "them" can name it.
COLLECTIVES = _PEOPLE_GROUPS | {"herd", "flock", "pack", "queue", "swarm"}


def _listed_adjective(toks: list[_Tok], k: int) -> bool:
    """The word at ``k`` is the first of describing words a comma parts ("a clear, windy
    morning", "a tall, narrow cupboard"): describing words, then a noun, follow the comma."""
    vocabulary = load_vocabulary()
    j = k + 2
    if j >= len(toks) or toks[k + 1].text != "," or not vocabulary.is_adjective(toks[j].text):
        return False
    while j < len(toks) and vocabulary.is_adjective(toks[j].text) and toks[j].text not in vocabulary.not_things:
        j += 1  # (not "morning", a noun that looks like a describing word)
    return j < len(toks) and toks[j].text[:1].isalpha() and toks[j].text not in _STOP


#: Particles of going somewhere: a bare word before one, after a plural subject, is its verb.
_MOTION_PARTICLES = {"up", "down", "out", "off", "across", "along", "around", "through", "towards", "toward",
                     "into", "onto", "past"}  # fmt: skip


def _plural_verb(toks: list[_Tok], j: int) -> bool:
    """The word at ``j`` is the plural verb of a subject before the phrase it follows, no noun
    of that phrase: a person's, an animal's or a hanging verb in its plural form ("work", "chat")
    with a preposition or an object after it, or any word before a particle of going, after a
    plural subject and its place phrase ("two mechanics on a scissor lift work on its joint", "two
    knights in armour creep up the slope"; "a work bench" stays a bench)."""
    vocabulary = load_vocabulary()
    after = toks[j + 1].text if j + 1 < len(toks) else "."
    takes = after in _PARTICLES or after in _OBJECT_OPENERS
    verbs = vocabulary.person_verbs | vocabulary.animal_verbs | _HANG_VERBS
    # a person verb, or any word that goes somewhere ("two knights in armour creep up the slope")
    verb = any(toks[j].text + ending in verbs for ending in ("s", "es")) or after in _MOTION_PARTICLES
    # ("four tourists on a sandbar laugh and hold up their phones": a person's verb ends its clause)
    acts = any(toks[j].text + ending in vocabulary.person_verbs for ending in ("s", "es"))
    takes = takes or after in ("and", ",", ".") and acts
    if not takes or singular(toks[j].text) != toks[j].text:
        return False
    k = j - 1  # back over the phrase to its preposition: the subject stands before it
    while k > 0 and toks[k].text[:1].isalpha() and (toks[k].text in _DETERMINERS or toks[k].text not in _STOP):
        k -= 1
    if toks[k].text == "and" and k > 0 and toks[k - 1].text[:1].isalpha() and toks[k - 1].text not in _STOP:
        return True  # "a yew and a rowan shade the gate": two subjects, one plural verb
    if not verb:
        return False
    subject = toks[k - 1].text if k > 0 and (toks[k].text in _PARTICLES or toks[k].text in ("in", "of", "near")) else ""
    return subject[:1].isalpha() and vocabulary.singular(subject) != subject


def _possessed(toks: list[_Tok], covered: set[int]) -> list:
    """A lone word right after a plural possessive is the noun it owns, though it looks like a
    verb ("the judges' stand", "the shepherds' shelter"): "judges'" can be no "judges is"."""
    vocabulary = load_vocabulary()
    out = []
    for k in range(2, len(toks)):
        owner, word = toks[k - 1], toks[k].text
        after = toks[k + 1].text if k + 1 < len(toks) else "."
        if k in covered or not owner.orig.endswith(("'", "’")) or toks[k - 2].text not in _DEFINITE:
            continue
        if toks[k].quoted or word in _STOP and not _is_verb(word) or not vocabulary.is_thing_word(word):
            continue
        if after[:1].isalpha() and after not in _STOP:
            continue  # a longer phrase: left to the other rules
        entry = _guess(toks, k, toks[k - 2 : k])
        out.append((k, k + 1, entry.category, entry))
        covered.add(k)
    return out


#: Parts only a building seen from outside shows: its owner, a place word, is a building of the scene.
_OUTSIDE_PARTS = {"roof", "rooftop", "chimney", "eave", "gable", "facade", "porch", "veranda", "doorstep", "balcony"}


#: Parts of an animal's or a person's body beyond those a thing is carried on ("the horse's mane").
_LIVING_PARTS = {"mane", "flank", "ear", "tail", "fur", "coat", "hoof", "horn", "trunk", "muzzle", "nose", "wing",
                 "feather", "hair", "face", "beard", "leg", "belly", "chin", "cheek", "snout", "ear"}  # fmt: skip


def _outside_part_of(toks: list[_Tok], i: int) -> bool:
    """The phrase opening at ``i`` owns a part only a building seen from outside shows ("on the
    roof of [the granary]", "on the steps of [the chapel]"): a building of the scene."""
    return i >= 2 and toks[i - 1].text == "of" and singular(toks[i - 2].text) in _OUTSIDE_PARTS | {"step"}


def _owners_of_parts(toks: list[_Tok], covered: set[int]) -> list:
    """"A sign stands on the diner's roof": the owner of a part is a thing of the scene, even
    when nothing else names it as one (a setting word like "diner" included)."""
    vocabulary = load_vocabulary()
    out: list = []
    for k in range(1, len(toks) - 1):
        w = toks[k].text
        indefinite = toks[k - 1].text in ("a", "an")  # ("a barber trims a man's beard": a man of his own)
        if k in covered or not w.endswith("'s") or toks[k - 1].text not in _DEFINITE and not indefinite:
            continue
        j = k + 1
        while j < len(toks) - 1 and vocabulary.is_adjective(toks[j].text):
            j += 1
        base = w[:-2]
        part = singular(toks[j].text)
        if part in vocabulary.body_parts or part in _LIVING_PARTS:
            known = match_phrase((base,))
            entry = None if known else vocabulary.match((base,))
            shape = load_catalogue()[known or entry.category].shape if known or entry is not None else None
            if shape in _LIVING:  # (one named before is that one again: "the calf's back")
                out.append((k, k + 1, known or entry.category, entry))  # "a groom brushes the horse's mane"
                covered.add(k)
            continue
        if indefinite or part not in _BUILDING_PARTS and part not in vocabulary.part_owners:
            continue
        if base not in vocabulary.places and any(singular(toks[i].text) == base for i in covered if i < k):
            continue  # "the hut's roof" after "a site hut": the part places by the hut named before (a
            # place named before set the scene and is no thing yet)
        known = match_phrase((base,))
        entry = None if known else vocabulary.match((base,))
        if singular(base) in vocabulary.places:
            if singular(toks[j].text) not in _OUTSIDE_PARTS:
                continue  # "by the shop's door": inside the setting, no building of it
            known, entry = "building", None  # "the diner's roof": a building seen from outside
        if known or entry is not None:
            out.append((k, k + 1, known or entry.category, entry))
            covered.add(k)
    return out


#: Words before "of" that put a thing on a landform or at its foot ("on top of", "at the foot of").
_LANDFORM_PARTS = {"top", "foot", "summit", "crest", "base"}


def _landform_part(toks: list[_Tok], k: int) -> bool:
    """"of" at ``k`` closes "on top of" or "(at) the foot of" outside the opening that names the
    setting ("A village at the foot of a mountain" is where the scene is); "at the top of the
    slope" is where on the place, not a thing on it."""
    if k < 2 or toks[k].text != "of" or toks[k - 1].text not in _LANDFORM_PARTS:
        return False
    if toks[k - 1].text == "top" and toks[k - 2].text != "on":
        return False
    return not _verbless_opening(toks, k)


#: Prepositions that put a thing by a landform seen in the scene: "a dragon circles over a volcano".
_BY_LANDFORM = {"over", "above", "beside", "behind", "past", "near", "towards", "toward"}


def _by_landform(toks: list[_Tok], k: int) -> bool:
    """``k`` is one of ``_BY_LANDFORM`` before "a"/"an" outside the opening that names the setting
    ("a pterodactyl flies over a smoking volcano"; not "A village beside a mountain.")."""
    return 0 < k < len(toks) - 1 and toks[k].text in _BY_LANDFORM and toks[k + 1].text in ("a", "an") and (
        not _verbless_opening(toks, k)
    )


#: Verbs of a landform that stands in the scene as its subject: "a large dune rises behind the camp".
_LANDFORM_VERBS = {"rises", "looms", "towers", "rears", "stands", "slopes", "climbs"}


def _risen_landform(toks: list[_Tok], k: int) -> int | None:
    """The landform at ``k`` opens a clause after the first words, the subject of
    ``_LANDFORM_VERBS``: a thing of the scene ("A desert camp. A large dune rises behind it"; not "A
    village where a mountain rises ..."). Where its phrase starts, after the article."""
    if k + 1 >= len(toks) or toks[k + 1].text not in _LANDFORM_VERBS:
        return None
    j = k - 1
    while j >= 0 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
        j -= 1
    risen = j > 0 and toks[j].text in ("a", "an") and toks[j - 1].text in (".", ",", ";", "and", "!")
    return j + 1 if risen else None


def _landforms(toks: list[_Tok], covered: set[int]) -> list:
    """A hill, a dune or a cliff sets the scene, but one the text puts a thing on top of or at
    the foot of is a thing of the scene ("a dragon sleeps on top of a flat-topped hill"), and so is
    one that rises somewhere (``_risen_landform``); not "at the top of the slope", a part of the
    place; nor one a thing is by or over (``_by_landform``)."""
    forms = load_vocabulary().landforms
    out: list = []
    for k in range(1, len(toks)):
        form = forms.get(singular(toks[k].text)) if k not in covered else None
        risen = _risen_landform(toks, k) if form is not None else None
        if risen is not None:
            out.append((risen, k + 1, form.category, form))
            covered.add(k)
            continue
        if not (k >= 2 and _landform_part(toks, k) or _by_landform(toks, k)):
            continue
        j = k + 1
        while j < len(toks) and j - k <= 5 and j not in covered and toks[j].text[:1].isalpha() and (
            toks[j].text in _DETERMINERS or toks[j].text not in _STOP
        ):
            j += 1
        head = j - 1
        entry = forms.get(singular(toks[head].text)) if head > k and head not in covered else None
        if entry is not None:
            out.append((head, head + 1, entry.category, entry))
            covered.add(head)
    return out


#: Kinds of relation phrase that put a thing outside another, by its walls ("beside the tavern",
#: "at the foot of the signal box"), not in or on it.
_BY_KINDS = {"in front of", "behind", "side of", "near", "opposite", "foot of", "face to", "flank", "between",
             "left of", "right of"}  # fmt: skip


def _placed_by(toks: list[_Tok], i: int, kinds: set[str] = _BY_KINDS) -> bool:
    """A relation phrase (of these kinds) that puts a thing outside what the noun phrase opening
    at ``i`` names ends right before it ("beside [the bunkhouse]", "at the foot of [the signal
    box]"), or it is the second of a pair after "between" ("between the cookhouse and [the shed]")."""
    table = _phrase_table()
    for length in range(1, min(i, 6) + 1):
        if table.get(tuple(t.text for t in toks[i - length : i])) in kinds:
            return True
    if i == 0 or toks[i - 1].text != "and":
        return False
    k = i - 2
    while k >= 0 and i - k <= 8 and toks[k].text not in (".", ",", ";", ":") and not _verb_word(toks[k].text):
        if toks[k].text == "between":
            return True
        k -= 1
    return False


def _named_before(toks: list[_Tok], k: int) -> bool:
    """The word at ``k`` is the end or the start of a closed compound named before ("the fire"
    after "a fireplace"): that thing again (``_alias_mentions``), no new one."""
    word = singular(toks[k].text)
    return any(
        w != word and (w.endswith(word) or w.startswith(word) and not _agent_compound(w[len(word) :]))
        for w in (singular(t.text) for t in toks[:k] if t.text[:1].isalpha())
    )


def _agent_compound(rest: str) -> bool:
    """``rest`` ends a closed compound that names whoever works at its first part ("wicketkeeper",
    "boatman", "lamplighter"): that thing is still to be named ("the boatman rows the boat")."""
    return len(rest) >= 3 and rest.endswith(("er", "or", "man", "woman", "ist"))


#: Verbs by which a building stands in a scene ("a saloon stands on the left", "a chapel rises behind it").
_BUILDING_STANDS = {"stands", "sits", "rises", "looms", "towers", "squats", "perches", "nestles"}


#: Phrase kinds that put a thing outside a building of the scene ("above the glass office").
_OUTSIDE_KINDS = _BY_KINDS | {"above", "on top"}


def _outside_of(toks: list[_Tok], i: int) -> bool:
    """The noun phrase opening at ``i`` names what a thing stands outside of ("beside [the tavern]",
    "above [the glass office]"), or a part of it seen from outside ("on the roof of [the inn]"),
    or a door of it a thing stands outside of ("in front of the doors of [the cinema]")."""
    if _placed_by(toks, i, _OUTSIDE_KINDS) or _outside_part_of(toks, i):
        return True
    door = i >= 3 and toks[i - 1].text == "of" and singular(toks[i - 2].text) in _THRESHOLDS
    return door and toks[i - 3].text in _DETERMINERS and _placed_by(toks, i - 3, _OUTSIDE_KINDS)


def _buildings(toks: list[_Tok], covered: set[int]) -> list:
    """A place word sets the scene ("a tavern at dusk"), but one a telling sentence puts a thing
    outside of is a building of the scene ("a mule waits beside the tavern", "milk churns stand at
    the foot of the little waiting room"), and so is one a clause has stand somewhere ("a saloon
    stands on the left"); inside it ("in the tavern") it stays the setting."""
    vocabulary = load_vocabulary()
    out: list = []
    for k, t in enumerate(toks):
        if not t.text[:1].isalpha() or t.text in _STOP or t.quoted:
            continue
        for width in (2, 1):
            if k + width > len(toks) or any(x in covered for x in range(k, k + width)):
                continue
            after = toks[k + width].text if k + width < len(toks) else "."
            if after[:1].isalpha() and after not in _STOP and not _is_verb(after):
                continue  # "the tavern keeper": a longer phrase, read by the other rules
            j = k - 1
            while j >= 0 and toks[j].text[:1].isalpha() and (
                toks[j].text not in _STOP or toks[j].joined or toks[j + 1].joined
            ):
                j -= 1  # back over describing words ("the little waiting room", "a false-front saloon")
            # "a saloon stands on the left": a building a clause opens with, standing somewhere
            # ("a street corner: a café with red awnings has four tables": after the setting, one with parts)
            standing = after in _BUILDING_STANDS or after == "with" and j > 0
            stands = j >= 0 and toks[j].text in ("a", "an") and standing and (
                j == 0 or toks[j - 1].text in (".", "!", "?", ";", ",", "and", ":")
            )
            seen = j >= 0 and toks[j].text in _DETERMINERS and _outside_of(toks, j) and not _verbless_opening(toks, j)
            # "Across from the stage is a long bar": the subject a fronted place phrase puts after its verb
            inverted = j > 0 and toks[j].text in _DETERMINERS and _inverted_subject(toks, j - 1)
            entry = vocabulary.building(tuple(u.text for u in toks[k : k + width])) if stands or seen or inverted else None
            if entry is None:
                continue
            end = k + width
            out.append((k, end, entry.category, entry))
            covered.update(range(k, end))
            break
    return out


#: Prepositions that hang a thing from another or put it under or against one: a part named after
#: one with "a" is a thing ("hangs from a hook"; "a sieve on a wooden frame" is the sieve's frame).
_PUT_ON = {"from", "under", "beneath", "underneath", "against"}
#: What a fitting is fixed to: "a ceiling hook", "a wall hook" are the room's.
_FITTED = {"ceiling", "wall", "roof"}


def _loose_parts(toks: list[_Tok], covered: set[int]) -> list:
    """A part of a body or a machine is no object ("its left arm", "a robot with six arms"), but
    one the text detaches is a thing of its own: a detaching word before it ("spare heads", "a
    severed claw") or right after it ("its left arm removed and lying on a workbench"), or a
    part that opens a clause as its own subject ("a crane hook hangs from a rail", "Chains hang
    from the beams"), or one named
    with "a" or a count where a thing is put ("hangs from a hook", "a stack of drill pipes", "under
    two awnings"; not "a stall with an awning", whose awning it is)."""
    vocabulary = load_vocabulary()
    out: list = []
    for k, t in enumerate(toks):
        entry = vocabulary.loose_parts.get(vocabulary.singular(t.text))
        if entry is None or k in covered or t.quoted or t.joined or (k + 1 < len(toks) and toks[k + 1].joined):
            continue
        j = k - 1
        while j >= 0 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
            j -= 1
        before = {u.text for u in toks[j + 1 : k]}
        after = toks[k + 1].text if k + 1 < len(toks) else "."
        opener = toks[j].text if j >= 0 else "."
        # its own subject, with a verb of its number: not "a mushroom with a tiny door stands" (whose
        # door it is), nor "a sieve on a wooden frame stand" (the verb of a plural subject before)
        whose = j > 0 and toks[j - 1].text in ("with", "of", "has", "have", "having")
        placing = _placing(after) or after in ("is", "are")  # ("chains lie")
        verb = placing and after.endswith("s") == (opener in ("a", "an"))
        counted = opener in ("a", "an") or opener in _NUMBERS
        # (a bare plural that opens a sentence too: "Chains hang from the ceiling")
        bare = (j < 0 or opener in (".", "!", "?", ";")) and vocabulary.singular(t.text) != t.text
        own = (counted or bare) and verb and not whose
        # (the thing something is put on, hung from or stacked as: "a helmet hangs from a hook")
        put = counted and j > 0 and toks[j - 1].text in _PUT_ON or opener == "of" and j > 0 and toks[
            j - 1
        ].text in _QUANTITY
        one = vocabulary.singular(t.text)
        # (not "a hook of the crane", "a ceiling hook": a fitting of the room, "under one arm": a body's)
        put = put and after != "of" and not before & _FITTED and one not in vocabulary.body_parts
        put = put and one not in _LIVING_PARTS
        # (one in hand: "each holding a long pipe", "clutching a spoke")
        held = counted and j > 0 and (toks[j - 1].text in _HOLD or toks[j - 1].text in _HAND_VERBS)
        held = held and one not in vocabulary.body_parts and one not in _LIVING_PARTS
        if before & vocabulary.detached or after in vocabulary.detached or own or put or held:
            out.append((k, k + 1, entry.category, entry))
            covered.add(k)
    return out


#: Words after "of" that say what sorts a plural comes in ("of every shape", "of all sizes").
_VARIETY = {"every", "all", "many", "different", "various", "each"}


def _bare_subjects(toks: list[_Tok], covered: set[int]) -> list:
    """Bare plurals nobody listed that open a sentence or a clause after ", and" as its subject
    ("Noodle cartons and soda cans litter the floor"): no count, but a verb (or "and" and another
    such plural) follows."""
    vocabulary = load_vocabulary()
    out: list = []
    n = len(toks)
    for k in range(n):
        after_and = k > 0 and toks[k - 1].text == "and" and bool(out) and out[-1][1] == k - 1
        clause = k > 1 and toks[k - 1].text == "and" and toks[k - 2].text == ","  # "..., and bridles hang"
        if not (k == 0 or toks[k - 1].text in (".", "!", "?", ";") or after_and or clause):
            continue
        j, head = k, None
        while j < n and j - k < 4 and j not in covered and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
            j += 1
            if singular(toks[j - 1].text) != toks[j - 1].text:
                head = j - 1  # the plural ends the phrase
                break
        if head is not None and j + 2 < n and toks[j].text == "of" and _stuff_word(toks, j + 1, covered):
            j += 2  # "Bales of wool are stacked": units of stuff, counted by the unit
        elif head is not None and j + 3 < n and toks[j].text == "of" and toks[j + 1].text in _VARIETY:
            j += 3  # "Kites of every shape fly above the grass": what sort they are, then the verb
        elif head is not None and j < n and toks[j].text == "in":
            # "Fans in fancy dress line the barriers": what they wear, then the verb
            j = next((x + 1 for x in range(j + 1, min(j + 5, n)) if toks[x].text in vocabulary.clothing), j)
        after = toks[j].text if j < n else "."
        verb = after[:1].isalpha() and (after not in _STOP or after in _FINITE)
        # a listed noun there is a verb when an object follows it ("cans litter the floor")
        verb = verb and (j not in covered or (j + 1 < n and toks[j + 1].text in _OBJECT_OPENERS))
        if head is None or toks[head].quoted or not (after == "and" or verb):
            continue
        word = toks[head].text
        if not (vocabulary.is_thing_word(word) or _laid_out(toks, head, j)) or _participle(word) or word in _QUANTITY:
            continue
        entry = _guess(toks, head, toks[k:head])
        out.append((head, head + 1, entry.category, entry))
        covered.add(head)
    return out


#: Markers after which what a seat or a perch holds is a crowd on it.
_PACKED = {("packed", "with"), ("crowded", "with"), ("thronged", "with"), ("teeming", "with")}


def _crowds(toks: list[_Tok], raw: list, covered: set[int]) -> list:
    """A bare plural nobody listed that a seat or a perch is packed or crowded with, as the whole
    phrase after the marker ("grandstands packed with fans", "a pier crowded with anglers"): the
    people on it, a crowd (a wheelbarrow full of dags, a cart packed with gourds: its load)."""
    vocabulary = load_vocabulary()
    ends = {e: (cat, " ".join(t.text for t in toks[s:e])) for s, e, cat, _ in raw}
    out: list = []
    for k in range(3, len(toks)):
        word, after = toks[k].text, toks[k + 1].text if k + 1 < len(toks) else "."
        if k in covered or (toks[k - 2].text, toks[k - 1].text) not in _PACKED or k - 2 not in ends:
            continue
        ends_phrase = after in _STOP or not after[:1].isalpha()
        if singular(word) == word or not vocabulary.is_thing_word(word) or not ends_phrase:
            continue
        category, name = ends[k - 2]
        if vocabulary.carries(category, name, ("seats", "perches")):
            out.append((k, k + 1, "figure", vocabulary.family("figure")))
            covered.add(k)
    return out


def _verb_of_one(toks: list[_Tok], k: int) -> bool:
    """The word at ``k`` is the -s verb of the singular noun right before it ("a girl *holds*"),
    not a plural noun there ("peacock *feathers*")."""
    w = toks[k].text
    return k > 0 and _is_verb(w) and singular(w) != w and singular(toks[k - 1].text) == toks[k - 1].text and (
        _match_at(toks, k) is None and singular(w) not in _PART_NOUNS
    )


def _verb_of_several(toks: list[_Tok], k: int) -> bool:
    """The word at ``k`` is the verb of the plural noun right before it ("kids *fly* kites"); not
    "play", whose bare plural is mostly a game ("deckhands play cards", "play doubles")."""
    w, before, after = toks[k].text, toks[k - 1].text, toks[k + 1].text if k + 1 < len(toks) else "."
    plural_subject = singular(before) != before and w != "play"
    return k > 0 and plural_subject and _plural_form_verb(w, after) and _match_at(toks, k) is None


def _bare_objects(toks: list[_Tok], covered: set[int]) -> list:
    """A bare plural nobody listed after the verb of a named one, ending the phrase: what the
    verb acts on ("a street performer juggles clubs beside the fountain", "kids fly kites"), also
    after a word that says its kind ("a robot carries ice blocks up the ramp")."""
    vocabulary = load_vocabulary()
    out: list = []
    for k in range(2, len(toks)):
        word = toks[k].text
        after = toks[k + 1].text if k + 1 < len(toks) else "."
        kind = k > 2 and k - 2 not in covered and k - 3 in covered and toks[k - 1].text[:1].isalpha()
        kind = kind and toks[k - 1].text not in _STOP and singular(toks[k - 1].text) == toks[k - 1].text
        verb = k - 2 if kind and not _participle(toks[k - 1].text) else k - 1
        if k in covered or k - 1 in covered or verb - 1 not in covered or toks[k].quoted:
            continue
        acted_on = _verb_of_one(toks, verb) or _verb_of_several(toks, verb)
        if singular(word) == word or not acted_on or word.endswith("wards"):
            continue  # ("drives towards": an adverb)
        if not (after in _STOP or not after[:1].isalpha()) or not vocabulary.is_thing_word(word) or _participle(word):
            continue
        entry = _guess(toks, k, toks[k - 1 : k])
        out.append((k, k + 1, entry.category, entry))
        covered.add(k)
    return out


def thing_plural(word: str) -> bool:
    """A plural WordNet knows as the name of things rather than as a verb ("cubes", "cupcakes";
    not "runs", "argues", "stands")."""
    one = singular(word)
    return one != word and bool(wordnet.names_a_thing(one)) and not wordnet.rather_verb(one)


def _listed_after(toks: list[_Tok], k: int, covered: set[int]) -> bool:
    """Whether the phrase ending at ``k`` lies in a list a "with" or a verb of holding opens, no
    verb of the clause's subject between ("a table with a cake in the middle and ...", "a tray
    holds a teapot and ..."; not "a teacher stands by the whiteboard and ...")."""
    vocabulary = load_vocabulary()
    j = k
    while j >= 0 and toks[j].text[:1].isalpha():
        w = toks[j].text
        if w == "with" or w in _HOLD:
            return True
        if j not in covered and (w in _FINITE or _placing(w) or w in vocabulary.person_verbs):
            return False
        j -= 1
    return False


def _joined_plurals(toks: list[_Tok], covered: set[int]) -> list:
    """A bare plural nobody listed joined by "and" to a named thing, ending the phrase: more of
    the things named together ("a big cake in the middle and cupcakes around it"), not what a
    thing is made of or holds ("made of cogs and gears")."""
    vocabulary = load_vocabulary()
    out: list = []
    for k in range(2, len(toks)):
        word, after = toks[k].text, toks[k + 1].text if k + 1 < len(toks) else "."
        # (after a thing, or after the place a thing is put in: "a cake in the middle and")
        named = k - 2 in covered or toks[k - 2].text in vocabulary.not_things and any(
            j in covered for j in range(max(0, k - 7), k - 2)
        )
        if k in covered or toks[k - 1].text != "and" or not named or toks[k].quoted:
            continue
        if any(t.text in ("of", "from") for t in toks[max(0, k - 4) : k - 1]):
            continue  # "a chandelier made of cogs and gears": what it is made of
        one = singular(word)
        # (the phrase ends, or the verb of both comes: "bottles and cans litter the floor")
        both = after[:1].isalpha() and after not in _STOP and _plural_verb(toks, k + 1)
        ends = after in _STOP or not after[:1].isalpha() or both
        if not ends or not vocabulary.is_thing_word(word):
            continue
        if not thing_plural(word):
            continue  # "holds a baby and argues with him", "slips its lead and runs off": a verb
        if not both and not _listed_after(toks, k - 2, covered):
            continue  # "stands by the whiteboard and points at a map": the subject's second verb
        if one in vocabulary.clothing or word in vocabulary.parts or _participle(word):
            continue
        entry = _guess(toks, k, toks[k - 1 : k])
        out.append((k, k + 1, entry.category, entry))
        covered.add(k)
    return out


def _stuff_word(toks: list[_Tok], k: int, covered: set[int]) -> bool:
    """The word at ``k`` names stuff, no thing ("wool", "gold", "sand"): what a unit or a heap
    of it is made of, so the unit, or the heap named by the stuff, is the thing."""
    w = toks[k].text
    return k not in covered and w[:1].isalpha() and w not in _STOP and singular(w) == w and (
        w in load_vocabulary().not_things and not load_vocabulary().is_adjective(w)
    )


#: A heap of a stuff the vocabulary lists as a material ("a pile of gold coins"): a low mound.
_MOUND = Entry("rock", (0.8, 0.8, 0.35), "ground")


def _heap_of_stuff(toks: list[_Tok], i: int, covered: set[int]) -> tuple[int, bool]:
    """Where the stuff ends that "of" at ``i`` joins a heap to ("a pile", "two bundles"), or 0,
    and whether that is one mound: a heap or a pile of a material the vocabulary lists, or of one
    it lists in two words ("a heap of gold coins lies", "a pile of treasure"). A material in the
    plural ("stacks of jewels") or one word of stuff that ends the phrase ("a heap of rubble.",
    "bundles of straw", a colour word too) names the things the heap is of."""
    if i < 1 or i + 1 >= len(toks) or toks[i - 1].text not in _HEAPS:
        return 0, False
    vocabulary = load_vocabulary()
    w = toks[i + 1].text
    two = i + 2 < len(toks) and f"{w} {toks[i + 2].text}" in vocabulary.materials
    end = i + 3 if two else i + 2
    after = toks[end].text if end < len(toks) else "."
    ends = not after[:1].isalpha() or (after in _STOP and after not in ("of", "and"))
    # (a verb may follow stuff, "a heap of rubble blocks the door", not a colour: "a pile of old bricks")
    # (a part word is a noun there, not a verb: "a stack of copper pipes")
    verb = (_is_verb(after) or _plural_verb(toks, end)) and singular(after) not in vocabulary.not_things
    mound = toks[i - 1].text in ("heap", "pile") and w in vocabulary.materials
    if i + 1 not in covered and (two or mound or w in vocabulary.materials and singular(w) != w):
        return (end, mound or two) if ends or verb else (0, False)
    stuff = ends and vocabulary.is_adjective(w) or (ends or verb) and w in vocabulary.not_things
    one = stuff and i + 1 not in covered and w[:1].isalpha() and w not in _STOP and singular(w) == w
    return (end, False) if one else (0, False)


#: Participles of clothing put down or hung up, not worn ("a coat draped over the chair").
_LAID = {"hung", "draped", "folded", "spread", "laid", "piled", "heaped", "strewn", "thrown", "slung", "pegged",
         "lined", "arranged", "stacked", "scattered", "left", "drying"}  # fmt: skip


#: Participles before "with" that put the with-thing on its holder ("a stand topped with a hat").
_TOPPED = {"topped", "crowned", "hung", "draped", "piled", "stacked", "loaded", "laden", "heaped", "strung"}


#: Where a person holds a piece of clothing they are not wearing.
_LAP_WORDS = {"lap", "knee", "knees", "hand", "hands", "arm", "arms"}


def _laid_out(toks: list[_Tok], head: int, j: int) -> bool:
    """The clothing word at ``head`` is the subject of a placing verb ("leather coats hang on a
    rail", "a cloak lies on the bench") or is put somewhere ("a shawl draped over the chair"): a
    thing of the scene, not worn."""
    clothing = load_vocabulary().clothing
    if (singular(toks[head].text) not in clothing and toks[head].text not in clothing) or j >= len(toks):
        return False  # (listed as worn: "gloves", "boots")
    k = head - 1
    while k >= 0 and toks[k].text[:1].isalpha() and (toks[k].text in _DETERMINERS or toks[k].text not in _STOP):
        if _is_verb(toks[k].text):
            break  # ("skirts a fleece spread out on it": the object of a deed)
        k -= 1
    if k > 0 and toks[k].text == "with" and toks[k - 1].text in _TOPPED:
        return True  # "three hat stands, each topped with a felt hat": put on the stand, not worn
    clause = k > 0 and toks[k].text == "and" and toks[k - 1].text == ","  # (", and clothes are piled on a chair")
    # ("each with a half-finished scarf on her lap": in her lap or hands, not on her)
    held = j + 2 < len(toks) and toks[j].text in ("on", "in", "across") and toks[j + 1].text in _OWNERS
    if held and toks[j + 2].text in _LAP_WORDS:
        return True
    if k >= 0 and toks[k].text in ("with", "in", "wearing", "without", "and", "or") and not clause:
        return False  # "a boy with a red cap stands by the swing": the boy's verb, his cap
    after = toks[j].text
    if after in ("is", "are", "was", "were") and j + 1 < len(toks):
        after = toks[j + 1].text
    return after in _LAID or _placing(after)


def _opens_phrase(toks: list[_Tok], k: int) -> bool:
    """The word at ``k`` is inside a noun phrase's opening: a determiner, a count or a describing
    word stands right before it ("a [golf] cart", "two small [ball] returns"), not a noun whose
    verb it is ("robots [sell] orbs")."""
    before = toks[k - 1].text if k > 0 else ""
    return (
        before in _DETERMINERS or before in _NUMBERS or before in _VAGUE or before == "of"
        or load_vocabulary().is_adjective(before)
    )  # fmt: skip


#: Verbs that place their subject: a definite noun nobody listed before one is a thing of the scene.
_PLACING_VERBS = _HANG_VERBS | {"stands", "sits", "lies", "rises", "rests", "leans", "waits", "towers", "looms"}


#: A wall that stands on open ground ("a stone wall runs along the field"): long and low, drawn as a fence.
_FREE_WALL = Entry("fence", (4.0, 0.5, 1.2), "ground")
#: Verbs of a wall that stands on its own, bounding ground ("a dry-stone wall runs along the lane").
_BOUNDING_VERBS = {"runs", "run", "stretches", "stretch", "encloses", "enclose", "surrounds", "surround", "borders",
                   "border", "separates", "separate", "divides", "divide", "circles", "winds", "snakes"}  # fmt: skip
#: Parts that, put somewhere on their own, stand for their whole thing ("an airship hull hangs from chains").
_WHOLE_PARTS = {"hull", "chassis", "fuselage", "frame", "carcass"}


def _placing(word: str) -> bool:
    """A verb that puts its subject somewhere, in either number ("lies", "lean")."""
    return word in _PLACING_VERBS or f"{word}s" in _PLACING_VERBS


def _placed_verb(toks: list[_Tok], k: int) -> bool:
    """A verb at ``k`` that puts its subject somewhere, in either number ("lies", "lean", "are piled")."""
    word = toks[k].text
    laid = k + 1 < len(toks) and (toks[k + 1].text in _LAID or toks[k + 1].text in _STANDING)
    return _placing(word) or (word in ("are", "is") and laid)


def _unknown_heads(toks: list[_Tok], raw: list, covered: set[int]) -> list:
    """A known noun right before a noun nobody listed names that noun's kind ("a ball return",
    "a wheel gun", "a horse trough"): the unknown noun is the thing, the known one its modifier."""
    vocabulary = load_vocabulary()
    out = []
    for s, e, category, _ in raw:
        k = e
        if e - s != 1 or k >= len(toks) or k in covered or toks[k].quoted or toks[k].joined or toks[s].joined:
            continue
        word, known = toks[k].text, toks[s].text
        # "two butterfly cases": after a count, a plural -s word is the head (a verb after it would have no -s)
        counted_head = _counted_plural(toks, s) and singular(word) != word and word not in _STOP
        looks_verb = word in _STOP or word in _FINITE or _is_verb(word)
        if singular(known) != known or looks_verb and not counted_head or _participle(word):
            continue
        if word in _ADVERB_NOUNS or word in _ORDINALS:
            continue  # "the counter right next to the till", "the stall left of the gate"
        if _joint_verb(toks, k, category):
            continue  # "a farmer and his son wade into the pond": the plural verb of both
        verb = word in _HANG_VERBS or word in vocabulary.person_verbs or _plural_verb(toks, k)  # "holographic koi swim"
        if verb or not _opens_phrase(toks, s) or (_counted_plural(toks, s) and singular(word) == word):
            continue  # "robots sell orbs", "three koi swim": a verb after its subject
        if not vocabulary.is_thing_word(word) or vocabulary.is_adjective(word) or word in _QUANTITY:
            continue
        after = toks[k + 1].text if k + 1 < len(toks) else "."
        two = toks[k + 2].text if k + 2 < len(toks) else "."
        # ("a donkey pinata dangling from the tree": a participle with its phrase ends it)
        acting = _participle(after) and (two in _STOP or not two[:1].isalpha())
        if k + 1 not in covered and after[:1].isalpha() and after not in _STOP and not _is_verb(after) and not acting:
            continue  # a longer phrase than two nouns: left to the other rules
        entry = _guess(toks, k, toks[max(s - 3, 0) : k])
        if toks[k].orig[:1].isupper() and load_catalogue()[category].shape == "figure":
            entry = vocabulary.guess_agent(word, False, human=True) or entry  # "Brother Anselm", "Captain Okafor"
        out.append((k, k + 1, entry.category, entry))
        covered.add(k)
    return out


#: Participles that say where a thing stands: "the heavy roller parked by the hut" names a thing.
_STANDING = {"parked", "moored", "propped", "standing", "lying", "resting", "leaning", "tethered", "stacked",
             "beached", "docked"}  # fmt: skip


def _joint_verb(toks: list[_Tok], k: int, category: str) -> bool:
    """The bare word at ``k`` follows a one-word living thing joined by "and" to one before it
    ("a goat and her kid", "the boy and his dog", "a father and daughter"): the two make a plural
    subject, so the word, with a preposition or an object after it, is their verb."""
    s = k - 1
    bare = s >= 1 and toks[s - 1].text == "and"
    joined = s >= 2 and toks[s - 2].text == "and" and toks[s - 1].text in _DETERMINERS or bare
    if not joined or k + 1 >= len(toks):
        return False
    word, after = toks[k].text, toks[k + 1].text
    if bare and not (after in _DETERMINERS or singular(after) != after and after not in _FINITE):
        return False  # (with no article, only an object says it: "a cat and mouse game is painted")
    # (its object: a preposition, a determiner or a bare plural, "fold towels"; not a verb of
    # one subject, "and a snake charmer plays", "stands")
    vocabulary = load_vocabulary()
    verbs = vocabulary.person_verbs | vocabulary.animal_verbs | _HANG_VERBS
    takes = after in _STOP or (singular(after) != after and singular(after) not in _FINITE and after not in verbs)
    # (or a verb of the living that ends the clause, "a goat and a horse graze."; not "a dog bed.")
    takes = takes or not after[:1].isalpha() and any(word + ending in verbs for ending in ("s", "es"))
    if not word[:1].isalpha() or word in _STOP or singular(word) != word or not takes:
        return False
    return _living_category(category)


def _living_category(category: str | None) -> bool:
    """A category of people or animals (``None``: no thing at all)."""
    return category is not None and (category in _LIVING or load_catalogue()[category].shape in _LIVING)


def _joint_verb_at(toks: list[_Tok], k: int) -> bool:
    """`_joint_verb` after whatever one-word thing stands before ``k``."""
    found = _match_at(toks, k - 1) if k > 0 else None
    return found is not None and found[0] == k and _joint_verb(toks, k, found[1])


def _guess(toks: list[_Tok], head: int, before: list[_Tok]) -> Entry:
    """What a noun nobody listed names, by its ending and by what the text has it do: "four
    pickers work", "a bored attendant", "a marshal waves", "their sensei, an old man, ..."; a
    person verb beats an ending that looks like a machine's ("a sonar operator hunches"). The
    verb after a "with" thing is its owner's ("a mechanic with a wheel gun kneels")."""
    vocabulary = load_vocabulary()
    word = toks[head].text
    if singular(word) in vocabulary.landforms:
        return vocabulary.landforms[singular(word)]  # "between two cliffs": a landform of its size
    entry = vocabulary.guess_by_form(word)
    # what WordNet says the word names, for when the text tells nothing else ("a musher", "a sampan");
    # no person for a thing read or held ("reads a comic")
    known = vocabulary.guess_in_wordnet(word) if entry.category == GENERIC else None
    handled = bool(before) and before[0].text in _HOLD | _HAND_VERBS | _KEPT_IN_HAND
    known = None if known is not None and handled and known.category == "figure" else known
    if any(t.text == "with" for t in before):
        after = toks[head + 1].text if head + 1 < len(toks) else ""
        if entry.category == GENERIC and after.endswith("ing") and (after in _HOLD or after in _HAND_VERBS):
            return vocabulary.guess_agent(word, True, True) or known or entry  # "with a tsarevich holding the reins"
        return known or entry
    fronted = _after_preposition(toks, head)  # "On the bank, an old woman grills ...": no apposition
    human = _does_what_people_do(toks, head + 1) or (_person_apposition(toks, head + 1) and not fronted)
    human = human or _dressed(toks, head + 1) or _role_subject(toks, head) or _addressed(toks, head)
    human = human or _goes_on_doing(toks, head)
    moody = any(t.text in vocabulary.moods for t in before)
    acts = moody or _acts_as_person(toks, head + 1) or _equipped(toks, head + 1) or _has_hands(toks, head)
    acts = acts or _owner_next(toks, head)
    # what the text has it do beats what the word alone says: "the binder, an old woman, sits" is
    # a person, "a maintenance crawler rolls" a vehicle (but "a cormorant watches" stays a bird)
    creature = known is not None and vocabulary.is_creature(word)
    if entry.category == GENERIC and not creature or (human and entry.category == "machine"):
        entry = vocabulary.guess_agent(word, acts, human) or entry
    found = _verb_after(toks, head + 1)
    if entry.category == GENERIC and found is not None and found[0] in _VEHICLE_VERBS:
        entry = vocabulary.family("vehicle")  # "a zil is parked"
    entry = known if entry.category == GENERIC and known is not None else entry
    if entry.category == GENERIC and any(t.text.endswith(_BODY_MARKS) for t in before):
        entry = vocabulary.family("animal")  # "a six-legged grazer", "a horned beast": a creature's body
    return entry


#: Endings of describing words that give a thing nobody listed a creature's body.
_BODY_MARKS = ("legged", "winged", "horned", "tusked", "tentacled", "furred", "feathered", "hoofed", "hooved", "clawed",
               "fanged", "tailed", "eyed", "headed", "scaled")


#: What only vehicles do: a word nobody listed that does it is a vehicle ("a snowcat idles").
_VEHICLE_VERBS = {"parked", "idles", "idling", "reverses", "reversing", "honks", "honking", "revs", "revving"}


#: Verbs that only carry the verb after them ("a picker is working").
_AUXILIARIES = {"is", "are", "was", "were", "has", "have", "been", "be", "busily", "quietly", "still"}


def _haunt(toks: list[_Tok], k: int) -> bool:
    """Whether the clause from ``k`` stands its subject where only an animal goes ("a crane stands
    in the shallows"; not what it does there: "a crane lifts a crate by the pond")."""
    clause = [t.text for t in itertools.takewhile(lambda t: t.text[:1].isalpha(), toks[k : k + 6])]
    haunts = load_vocabulary().animal_haunts
    return bool(clause) and _placing(clause[0]) and any(
        " ".join(clause[j : j + n]) in haunts for j in range(len(clause)) for n in (1, 2)
    )


def _verb_after(toks: list[_Tok], k: int) -> tuple[str, int] | None:
    """The verb after the subject ending at ``k`` (auxiliaries skipped) and where it stands."""
    start = k
    while k < len(toks) and toks[k].text in _AUXILIARIES:
        k += 1
    return (toks[k].text, k - start) if k < len(toks) else None


#: Particles and prepositions between a verb and what it takes ("leans over", "bends down to").
_PARTICLES = {"over", "on", "at", "into", "onto", "across", "up", "down", "to", "towards", "toward", "from",
              "with", "beside", "behind", "against", "under", "through", "out", "off", "by"}  # fmt: skip


def _as_person(toks: list[_Tok], k: int) -> bool:
    """Whether the noun ending at ``k`` is a person by what follows it: a person's verb, clothes
    ("fans in fancy dress") or a small thing in hand ("a coach with a stopwatch")."""
    if _acts_as_person(toks, k) or _dressed(toks, k):
        return True
    if k < len(toks) and toks[k].text == "with":
        thing = next((m for m in (_match_at(toks, j) for j in range(k + 1, min(k + 4, len(toks)))) if m), None)
        return thing is not None and load_catalogue()[thing[1]].rests == "surface"
    return False


def _noun_before_object(toks: list[_Tok], s: int, e: int) -> bool:
    """A noun (no describing word) right before ``s`` and a determiner or a count right after ``e``
    ("jam [crowd] the shelf"): the word between is the verb of the noun's phrase."""
    before, after = toks[s - 1].text if s else ".", toks[e].text if e < len(toks) else "."
    noun = before[:1].isalpha() and before not in _STOP and not load_vocabulary().is_adjective(before)
    return noun and (after in _DETERMINERS or after in _NUMBERS)


#: Describing words only people wear ("a grey-haired coach", "a bespectacled fan").
_PERSON_LOOKS = ("haired", "bearded", "moustached", "mustachioed", "bespectacled", "freckled")


def _looks_like_person(toks: list[_Tok], s: int) -> bool:
    """Whether the describing words before the noun at ``s`` are a person's ("a grey-haired coach"),
    or it is someone's own ("her coach stands beside it")."""
    opener = _phrase_opener(toks, s)
    own = opener >= 0 and toks[opener].text in ("her", "his")
    return own or any(t.text.endswith(_PERSON_LOOKS) for t in toks[opener + 1 : s])


def _acts_as_person(toks: list[_Tok], k: int) -> bool:
    """Whether the subject ending at ``k`` does what people do: a person verb ("a picker is
    working", "a welder kneels"), a deed done to a thing ("a farrier is shoeing a horse") or to
    something of his or hers ("a punter poles his raft")."""
    found = _verb_after(toks, k)
    if found is None:
        return False
    verb, skipped = found
    vocabulary = load_vocabulary()
    if vocabulary.is_person_verb(verb):
        return True  # ("three shearers work": the plural's verb, listed by its -s form)
    after = k + skipped + 1
    clause = next((p for p in range(after, min(after + 8, len(toks))) if not toks[p].text[:1].isalnum()), min(after + 8, len(toks)))
    if verb in vocabulary.postures.get("sitting", ()) and any(_seat_after(toks, p) for p in range(after, clause)):
        return True  # "members sit on benches", "a controller sits at each one on a swivel chair": people
    k += skipped
    owner = k + 1
    while owner < len(toks) and owner - k <= 2 and toks[owner].text in _PARTICLES:
        owner += 1  # "the old chandler leans over his ledger", "a tinker bends down to her pack"
    if _is_verb(verb) and owner < len(toks) and toks[owner].text in ("his", "her"):
        return True  # "a punter poles his raft": what is his is a person's
    return skipped > 0 and verb.endswith("ing") and k + 1 < len(toks) and toks[k + 1].text in _DETERMINERS


def _seat_after(toks: list[_Tok], k: int) -> bool:
    """A seat named right after ``k`` by "on"/"in"/"at" ("on benches", "in a deckchair")."""
    if k >= len(toks) or toks[k].text not in ("on", "in", "at", "upon"):
        return False
    seats = load_vocabulary().carriers.get("seats", ())
    for j in range(k + 1, min(k + 5, len(toks))):
        name = match_phrase((singular(toks[j].text),))
        if name is not None:
            return name in seats
    return False


def _dressed(toks: list[_Tok], k: int) -> bool:
    """Clothing follows the noun ending at ``k`` after "in" or "wearing" ("a perfumer in a velvet
    waistcoat", "a refueller in a hi-vis vest"), or a word nobody listed that what only people do
    follows ("a grower in a hairnet kneels"): an agent noun that wears clothes is a person."""
    if k >= len(toks) or toks[k].text not in _WEARING:
        return False
    vocabulary = load_vocabulary()
    clothing = vocabulary.clothing
    for i, t in enumerate(toks[k + 1 : k + 6], start=k + 1):
        if t.text in clothing or singular(t.text) in clothing:
            return True
        unlisted = vocabulary.match((t.text,)) is None and match_phrase((t.text,)) is None
        if unlisted and t.text[:1].isalpha() and t.text not in _STOP and _does_what_people_do(toks, i + 1):
            return True
        if not t.text[:1].isalpha() or t.text in _STOP and t.text not in _DETERMINERS:
            return False
    return False


def _described_from(toks: list[_Tok], s: int) -> int:
    """Where the words before ``s`` that only open or describe its noun begin ("[a wooden] diner",
    "[a small] pool"): what a relation phrase right before places."""
    while s > 0 and (toks[s - 1].text in _DETERMINERS or load_vocabulary().is_adjective(toks[s - 1].text)):
        s -= 1
    return s


def _phrase_opener(toks: list[_Tok], head: int) -> int:
    """Where the noun phrase of ``head`` opens: the determiner or count before its describing words."""
    j = head - 1
    while j >= 0 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
        j -= 1
    return j


def _role_subject(toks: list[_Tok], head: int) -> bool:
    """"The sexton watches from the porch": a word nobody listed, named with "the" though never
    brought in, opens a sentence or a clause and does what people (or animals) do — a role
    everyone knows, a person."""
    j = _phrase_opener(toks, head)
    if j < 0 or toks[j].text != "the" or j > 0 and toks[j - 1].text not in (".", "!", "?", ";", ":", ","):
        return False
    found = _verb_after(toks, head + 1)
    return found is not None and found[0] in load_vocabulary().person_verbs


#: Verbs of talking and greeting: whom they are done to or with is a person ("talks to a novice").
_SOCIAL_VERBS = {"talk", "talks", "talking", "chat", "chats", "chatting", "speak", "speaks", "speaking", "argue",
                 "argues", "arguing", "haggle", "haggles", "haggling", "bargain", "bargains", "bargaining",
                 "whisper", "whispers", "whispering", "wave", "waves", "waving", "smile", "smiles", "smiling",
                 "nod", "nods", "nodding", "listen", "listens", "listening", "gossip", "gossips", "gossiping",
                 "quarrel", "quarrels", "quarrelling", "bow", "bows", "bowing", "beckon", "beckons", "beckoning",
                 "flirt", "flirts", "flirting", "plead", "pleads", "pleading", "converse", "converses"}  # fmt: skip


def _addressed(toks: list[_Tok], head: int) -> bool:
    """The word at ``head`` is whom someone talks to, chats with, waves at ("the abbess talks to
    a novice by the well"): a person."""
    j = _phrase_opener(toks, head)
    return j >= 2 and toks[j - 1].text in ("to", "with", "at") and toks[j - 2].text in _SOCIAL_VERBS


def _equipped(toks: list[_Tok], k: int) -> bool:
    """A hand tool follows the noun ending at ``k`` after "with" ("a marshaller with a pair of
    glowing batons", "a fitter with a spanner"): an agent noun with a tool is one who uses it."""
    if k >= len(toks) or toks[k].text != "with":
        return False
    vocabulary = load_vocabulary()
    for j in range(k + 1, min(k + 7, len(toks))):
        w = toks[j].text
        entry = vocabulary.match((w,))
        if entry is not None or match_phrase((w,)) is not None:
            return entry is not None and entry.category == "tool"
        if not w[:1].isalpha() or w in _STOP and w not in _DETERMINERS and w != "of":
            return False
    return False


def _opens_clause(toks: list[_Tok], head: int) -> bool:
    """The noun phrase of ``head`` opens its sentence or clause: a subject, not what a verb or a
    phrase takes ("leans over the nearer one"); "a row of reapers" opens with the row."""
    opener = _phrase_opener(toks, head)
    while opener > 0 and toks[opener].text == "of":
        opener = _phrase_opener(toks, opener - 1)
    return opener <= 0 or toks[opener - 1].text in (".", "!", "?", ";", ",", *_CLAUSE_WORDS)


def _has_hands(toks: list[_Tok], head: int) -> bool:
    """A thing in "his" or "her" hand, arm or lap later in the clause of the subject at ``head``,
    or a hand tool its verb works with ("a cartographer leans over the table with a compass in
    his hand", "a courier waits with a parcel under her arm", "reapers cut the wheat with
    sickles"): an agent noun with hands is a person."""
    if not _opens_clause(toks, head):
        return False
    parts = load_vocabulary().body_parts
    for j in range(head + 1, min(len(toks) - 1, head + 17)):
        w = toks[j].text
        if w in (".", ";", "!", "?", "and") or w in _CLAUSE_WORDS:
            return False
        if w in ("his", "her") and parts.get(toks[j + 1].text) == "on" or _equipped(toks, j):
            return True
    return False


def _owner_next(toks: list[_Tok], head: int) -> bool:
    """The subject at ``head`` opens its sentence, and the clause after its own (past a semicolon
    or ", and") opens with "his" ("the falconer stands at a table; his glove lies on it"), or with
    "her" and clothing or a body part ("her apron hangs on a hook"; a ship is a "her" too: "the
    steamer waits; her funnel smokes"): who has a his is a person."""
    if not _opens_clause(toks, head):
        return False
    vocabulary = load_vocabulary()
    for j in range(head + 1, min(len(toks) - 2, head + 16)):
        w = toks[j].text
        if w in (".", "!", "?") or w in _CLAUSE_WORDS:
            return False
        if w == ";" or (w == "and" and toks[j - 1].text == ","):
            owner, owned = toks[j + 1].text, toks[j + 2].text
            worn = owned in vocabulary.clothing or singular(owned) in vocabulary.clothing or owned in vocabulary.body_parts
            return owner == "his" or (owner == "her" and worn)
    return False


def _goes_on_doing(toks: list[_Tok], head: int) -> bool:
    """The subject at ``head``, opening its sentence or clause, goes on, after the comma that
    closes its verb's phrase, with what only people do ("the chief sits at a desk in the corner,
    reading a logbook"; not "leans over the nearer one, stirring it": no subject)."""
    if not _opens_clause(toks, head):
        return False
    vocabulary = load_vocabulary()
    for j in range(head + 1, min(len(toks) - 1, head + 13)):
        if toks[j].text in (".", ";", "!", "?") or toks[j].text in _CLAUSE_WORDS or toks[j].text == "and":
            return False
        if toks[j].text == ",":
            w = toks[j + 1].text
            return w.endswith("ing") and w in vocabulary.person_verbs and w not in vocabulary.animal_verbs
    return False


def _does_what_people_do(toks: list[_Tok], k: int) -> bool:
    """A person verb animals do not share follows the subject ending at ``k`` ("a marshal waves"),
    or a verb of having a thing in hand ("a starter raises a pistol")."""
    found = _verb_after(toks, k)
    vocabulary = load_vocabulary()
    person = found is not None and found[0] in vocabulary.person_verbs | _HAND_VERBS
    return person and found[0] not in vocabulary.animal_verbs


def _after_preposition(toks: list[_Tok], head: int) -> bool:
    """The noun phrase ending at ``head`` follows a preposition ("on the bank", "behind the old
    mill"), or is joined by "and" / "or" to one that does ("between the desk and the table"): the
    object of a place phrase, which a comma after it closes."""
    j = head - 1
    # (a count is of the phrase too: "behind the two old mills", "lassos a six-legged grazer")
    while j >= 0 and head - j <= 4 and (toks[j].text in _DETERMINERS or toks[j].text in _NUMBERS or (
        toks[j].text[:1].isalpha() and toks[j].text not in _STOP
    )):
        j -= 1
    if j >= 1 and toks[j].text in ("and", "or") and toks[j - 1].text[:1].isalpha() and toks[j - 1].text not in _STOP:
        return _after_preposition(toks, j - 1)
    return j >= 0 and toks[j].text in _STOP and toks[j].text not in _DETERMINERS and toks[j].text[:1].isalpha() and (
        toks[j].text not in ("and", "or", "but", "while", "where", "which", "who", "that", "as", "than")
    ) and not _is_verb(toks[j].text)  # ("behind the counter stands the shopkeeper, a goblin": its subject)


#: Words an apposition may open with before the person it names ("their sensei, a tiny old man, ...").
_APPOSITION_OPENERS = {"a", "an", "the"}


def _person_apposition(toks: list[_Tok], k: int) -> bool:
    """A comma after the noun ending at ``k`` opens a phrase naming a person ("the keeper, an
    old woman in an oilskin, ..."): the noun names that person."""
    if k + 2 >= len(toks) or toks[k].text != "," or toks[k + 1].text not in _APPOSITION_OPENERS:
        return False
    vocabulary = load_vocabulary()
    for t in toks[k + 2 : k + 7]:
        if t.text in vocabulary.male or t.text in vocabulary.female or t.text in ("person", "figure"):
            return True
        if not t.text[:1].isalpha() or t.text in _STOP:
            return False
    return False


#: Possessives that open a held thing's phrase.
_OWNERS = ("his", "her", "their")
def _in_hand(toks: list[_Tok], owner: int) -> bool:
    """The possessive at ``owner`` opens a thing someone holds: "with his putter", "clutching
    her umbrella"."""
    before = toks[owner - 1].text if owner > 0 else ""
    return before == "with" or before in _HOLD or before in _HAND_VERBS


#: Body parts that hold what is named right before "in his/her/their ...".
_HOLDING_PARTS = {"hand", "hands", "arm", "arms", "grip", "fist", "lap", "paw", "paws", "claw", "claws"}


def _held(toks: list[_Tok], head: int) -> bool:
    """Clothing held, not worn: "his hat in his hands", "a scarf in her lap", or made there
    ("each knitting a striped scarf")."""
    if toks[head].text not in load_vocabulary().clothing:
        return False
    words = [t.text for t in toks[head + 1 : head + 4]]
    if len(words) == 3 and words[0] == "in" and words[1] in _DEFINITE and words[2] in _HOLDING_PARTS:
        return True
    j = _phrase_opener(toks, head)
    return j > 0 and toks[j].text in _DETERMINERS and toks[j - 1].text in _MAKING_VERBS


#: Verbs of making a piece of clothing by hand: what they make is in hand, not worn.
_MAKING_VERBS = {"knit", "knits", "knitting", "sew", "sews", "sewing", "mend", "mends", "mending", "darn",
                 "darns", "darning", "stitch", "stitches", "stitching", "embroider", "embroiders", "embroidering",
                 "crochet", "crochets", "crocheting", "weave", "weaves", "weaving"}  # fmt: skip


def _participle(word: str) -> bool:
    """A verb form that follows a noun to say what it does or how it is set ("watching", "strung")."""
    return word.endswith(("ing", "ed")) or word in _IRREGULAR_PARTICIPLES


def _alias_mentions(toks: list[_Tok], mentions: list[_Mention]) -> list[_Mention]:
    """"the island" after "a kitchen island", "the pumps" after "two fuel pumps": a definite
    head noun of an earlier phrase refers back to it."""
    heads: dict[str, str] = {}
    compounds: dict[str, str] = {}  # "campfire" answers to "the fire"
    taken = {k for m in mentions for k in range(m.start, m.end)}
    starts = {m.start: m for m in mentions}
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
            # "the fire" is the campfire, or the fireplace ("a stool next to the fire")
            compound = next(
                (c for w, c in compounds.items() if w.endswith(word) or (w.startswith(word) and w[len(word) :] == "place")),
                None,
            )
            if compound is not None:
                heads[word] = compound
        after = starts.get(i + 1)
        if i in taken or not t.text[0].isalpha() or word not in heads or (
            after is not None and (after.guess is None or _living_category(after.category))
        ):  # ("the alien captain" after "grey aliens", "the corral gate": the kind of the next
            continue  # thing; not "the fence rail", a rail nobody listed: the fence's)
        if i - 1 in taken and (singular(t.text) in _FINITE or load_vocabulary().is_posture_verb(t.text)):
            continue  # "the singer stands" after "a bandstand": her verb, no stand
        j = i - 1
        while j >= 0 and i - j <= 3 and toks[j].text not in _DEFINITE and toks[j].text not in _STOP:
            j -= 1
        if j >= 0 and toks[j].text in _DEFINITE | {"each", "every"}:
            m = _Mention(heads[word], t.orig, i, i + 1, 1, False, True, alias=True)
            extra.append(m)
    _likeness_aliases(toks, ordered)
    return sorted(mentions + extra, key=lambda m: m.start)


def _likeness_aliases(toks: list[_Tok], ordered: list[_Mention]) -> None:
    """"A T-rex skeleton ... children sit in front of the T-rex": the kind of a likeness named
    again with "the" is that likeness, not a living one of its own."""
    heads = load_vocabulary().likeness_heads
    kinds: dict[tuple[str, ...], _Mention] = {}
    for m in ordered:
        words = tuple(t.text for t in toks[m.start : m.end])
        definite = m.start > 0 and toks[m.start - 1].text in _DEFINITE
        if definite and not m.alias and words in kinds and words[-1] not in heads:
            m.alias, m.category, m.likeness_of = True, kinds[words].category, kinds[words]
            continue
        if words and singular(words[-1]) in heads:
            kind = tuple(w.lower() for w in m.modifier) or words[:-1]
            while kind and kind[0] in _DETERMINERS:
                kind = kind[1:]
            if kind:
                kinds.setdefault(kind, m)


def _mark_members(toks: list[_Tok], mentions: list[_Mention]) -> None:
    """A counted plural whose sentence ends in a colon and a list of as many single things, each
    opening an item ("Four adventurers sit around the fire: a knight, an elf archer, a dwarf with
    an axe and a wizard"): the listed ones are its members."""
    for k, m in enumerate(mentions):
        if not (m.counted and m.count >= 2 and _is_plural(toks, m)):
            continue
        j = m.end
        while j < len(toks) and toks[j].text not in (":", ".", "!", "?", ";"):
            j += 1
        if j >= len(toks) or toks[j].text != ":":
            continue
        end = next((i for i in range(j, len(toks)) if toks[i].text in (".", "!", "?", ";")), len(toks))
        items = [
            x for x in mentions[k + 1 :] if j < x.start < end and not x.content
            and toks[x.start - 1 - len(x.adjectives)].text in ("a", "an")
            and toks[x.start - 2 - len(x.adjectives)].text in (":", ",", "and")
        ]  # fmt: skip
        if len(items) == m.count and all(_person_mention(x) == _person_mention(m) for x in items):
            m.members = items


def _mark_appositions(toks: list[_Tok], mentions: list[_Mention]) -> None:
    """Noun phrases that only rename the one before are no objects of their own: a person after
    a person's comma ("the puppeteer, a round-faced woman, kneels"; the other way round after a
    word like "owner"), and the kinds of a counted
    plural, one each, closed by a comma ("two hand puppets, a crocodile and a policeman, lie ...")."""
    for k, m in enumerate(mentions):
        if m.end >= len(toks) or toks[m.end].text != ",":
            continue
        later = [x for x in mentions[k + 1 :] if not x.content]
        if _is_plural(toks, m):
            kinds = later[: m.count] if m.counted and len(later) >= m.count >= 2 else []
            renamed = kinds and all(
                _renames(toks, kinds[i - 1].end if i else m.end, x.start, i > 0) for i, x in enumerate(kinds)
            )
            if renamed and kinds[-1].end < len(toks) and toks[kinds[-1].end].text == ",":
                for x in kinds:
                    x.content = True
        elif later and _person_mention(later[0]) and not _person_mention(m) and not _is_plural(toks, m) and (
            m.end - m.start == 1 and m.start > 0 and toks[m.start - 1].text in ("the", *_POSSESSIVES)
            and not _fronted_subject(toks, m, later[0]) and _renames(toks, m.end, later[0].start)
            and (not _after_preposition(toks, m.start) or load_vocabulary().person_first(toks[m.start].text))
        ):  # fmt: skip  (not "Across from the press, a customer waits": a fronted place phrase)
            # "the coach, a red-faced man", "around their coach, a woman in a parka": a word the
            # catalogue files as a thing, renamed as a person, names that person's role (no thing
            # after a preposition that never names one: "films it from the bleachers, a toddler asleep")
            m.category, m.guess = "figure", load_vocabulary().guess_agent(toks[m.start].text, False, human=True)
            later[0].content, later[0].renames = True, m
        elif _person_mention(m) and later and _person_mention(later[0]) and _renames(toks, m.end, later[0].start) and (
            not _fronted_subject(toks, m, later[0]) and not _listed_on(toks, later[0].end)
        ):  # (not "At the foot of a scarecrow, a guard sits": a fronted place phrase)
            # the role is the name ("the keeper, an old woman", "the owner, a bearded man"); a word
            # that only says whose ("its owner, a girl in goggles") gives way to the person
            relational = singular(m.phrase.split()[-1].lower()) in load_vocabulary().relational
            j = m.start - 1
            while j > 0 and toks[j].text[:1].isalpha() and toks[j].text not in _STOP:
                j -= 1  # "its new owner"
            relational = relational and j >= 0 and toks[j].text in _POSSESSIVES
            if relational:
                m.content = True
            else:
                later[0].content, later[0].renames = True, m
        elif _person_mention(m) and later and load_catalogue()[later[0].category].shape in ("animal", "bird", "robot") and (
            _renames(toks, m.end, later[0].start) and not _after_preposition(toks, m.start)
        ):  # "their boss, a gorilla in a bowler hat": the role is played by a creature, drawn as one
            m.content, later[0].role = True, m.phrase
        elif later and not _person_mention(m) and not _person_mention(later[0]) and (
            _renames(toks, m.end, later[0].start) and _subject_renamed(toks, later[0].end)
        ):  # "The reactor, a huge glowing sphere, hangs from the ceiling": one thing, the reactor
            later[0].content, later[0].renames = True, m


def _subject_renamed(toks: list[_Tok], k: int) -> bool:
    """The phrase ending at ``k`` renames a sentence's definite subject between commas, its verb
    right after the second ("The reactor, a huge glowing sphere, hangs ...")."""
    while k < len(toks) and toks[k].text[:1].isalpha() and not _is_verb(toks[k].text):
        k += 1  # past what it is made of or has ("a dome of glass", "a cart with one wheel")
    return k + 1 < len(toks) and toks[k].text == "," and _closes_apposition(toks, k) and _is_verb(toks[k + 1].text)


def _fronted_subject(toks: list[_Tok], m: _Mention, later: _Mention) -> bool:
    """``later``, after the comma that closes ``m``, is the subject of a clause that a place
    phrase ending in ``m`` opens ("At the foot of a scarecrow, a guard sits"), not a second name
    for ``m`` ("they skate around their coach, a woman in a red parka holding a stopwatch."): it
    has a verb of its own before the next comma."""
    if not _after_preposition(toks, m.start):
        return False
    k = later.end
    while k < len(toks) and toks[k].text[:1].isalnum():
        if _is_verb(toks[k].text):
            return True
        k += 1
    return k >= len(toks) or toks[k].text not in (".", "!", "?", ";", ",")


def _listed_on(toks: list[_Tok], k: int) -> bool:
    """A list goes on after the phrase ending at ``k`` (past its own "with ..." or "in ..."):
    "a baker, a cook and a smith" names three people, where "the keeper, an old woman, feeds"
    names one."""
    while k < len(toks) and toks[k].text not in (",", ".", "!", "?", ";", ":", "and", "or") and not _verb_word(toks[k].text):
        k += 1
    if k < len(toks) and toks[k].text == ",":
        return k + 1 < len(toks) and toks[k + 1].text in ("a", "an", "and") | _NUMBERS.keys()
    return k < len(toks) and toks[k].text in ("and", "or")


def _person_mention(m: _Mention) -> bool:
    """A person: a figure of the catalogue or of the open vocabulary."""
    return load_catalogue()[m.category].shape == "figure"


def _renames(toks: list[_Tok], start: int, end: int, listed: bool = False) -> bool:
    """Only a comma (or, in a list, "and"), "a"/"an" and describing words lie between ``start``
    and ``end``: "…, a tiny old [man]", "… and a [policeman]"."""
    words = [t.text for t in toks[start:end]]
    joins = ([","], [",", "and"], ["and"]) if listed else ([","],)
    for join in joins:
        rest = words[len(join) :]
        if words[: len(join)] == join and rest and rest[0] in ("a", "an"):
            # (a number hyphened to a word is a describing word: "a one-legged goblin")
            first = start + len(join) + 1
            return all(
                (toks[k].text not in _STOP or toks[k].joined or k + 1 < end and toks[k + 1].joined)
                and (toks[k].text[:1].isalpha() or toks[k].text == "-")
                for k in range(first, end)
            )
    return False


def _is_plural(toks: list[_Tok], m: _Mention) -> bool:
    words = [t.text for t in toks[m.start : m.end]]
    if "of" in words[1:]:
        words = words[: words.index("of", 1)]  # "bottles of wine": the measure is the head
    last = words[-1]
    if last in _SAME_PLURALS:  # "sheep graze", "a rack hung with drying fish": no determiner, so several
        j = _phrase_opener(toks, m.start)
        # (after "of" the quantity word counts them, "a flock of sheep", or they are a holder's contents)
        return _bare(toks, m.start) and (j < 0 or toks[j].text != "of")
    if m.guess is not None and tuple(t.text for t in toks[m.start : m.end]) in load_vocabulary().entries:
        return False  # "a triceratops" is listed as it is written
    if last in load_vocabulary().pair_nouns or last.endswith("'s"):
        return False  # "shears" are one pair; "the diner's" roof is one diner's
    return load_vocabulary().singular(last) != last or last in ("people", "cacti", "shelves", "benches", "glasses")


def _bare(toks: list[_Tok], s: int) -> bool:
    """No determiner or count before the noun phrase at ``s`` (past its describing words)."""
    j = _phrase_opener(toks, s)
    return j < 0 or toks[j].text not in _DETERMINERS and toks[j].text not in _NUMBERS and toks[j].text not in _VAGUE


#: Words in the plural that name a kind of the noun after them ("two customs officers", "a sports car").
_PLURAL_KINDS = {"customs", "sports", "goods", "savings", "news"}
#: Nouns whose plural is written as the singular: several when no determiner or count comes before.
_SAME_PLURALS = {"sheep", "deer", "reindeer", "moose", "bison", "elk", "fish", "salmon", "trout", "swine", "cattle",
                 "koi", "carp", "cod", "tuna", "mackerel"}  # fmt: skip
#: Nouns of an activity a thing's noun and a verb's -ing form may name ("a cake decorating class").
_ACTIVITIES = {"class", "lesson", "session", "club", "course", "demonstration", "contest", "competition", "workshop"}
#: Things of the sky, and the words that make one a thing people made ("paper moons", "a tin star").
_SKY_THINGS = {"moon", "star", "sun", "cloud", "rainbow", "planet", "comet"}
_CRAFT_WORDS = {"paper", "cardboard", "wooden", "tin", "plastic", "felt", "foil", "papier-mâché", "origami",
                "inflatable", "neon", "giant", "painted", "cutout", "cut-out", "crocheted", "knitted"}  # fmt: skip
#: Place nouns that qualify the next noun after a determiner ("the middle bench", "the end stall").
_POSITION_WORDS = {"middle", "centre", "center", "corner", "end", "front", "back", "top", "bottom", "side"}


def _position_adjective(toks: list[_Tok], j: int) -> bool:
    """"the middle bench", "the two middle racks", "the middle one": a place noun between a
    determiner (or a count) and a noun works as an adjective; so does a bare verb after a
    describing word as well ("four long grow tables": no verb follows a count's adjective)."""
    w, before = toks[j].text, toks[j - 1].text if j > 0 else ""
    verb = w in _FINITE and w not in ("is", "are", "was", "were", "has", "have", "had")
    opened = before in _DETERMINERS or before in _NUMBERS or (verb and load_vocabulary().is_adjective(before))
    return (w in _POSITION_WORDS or verb) and opened and (
        j + 1 < len(toks) and toks[j + 1].text[:1].isalpha() and (toks[j + 1].text not in _STOP or toks[j + 1].text == "one")
    )


#: How many things an uncounted plural names ("barrels stand by the door").
UNCOUNTED = 3


def _read_count(toks: list[_Tok], m: _Mention, prev_end: int) -> None:
    """Fill count, definiteness and adjectives from the words before the noun."""
    plural = _is_plural(toks, m)
    j = m.start - 1
    adjectives: list[str] = []
    count: int | None = None
    counted = exact = False  # (exact: written in digits, "1000000 seats": kept, for the object limit to refuse)
    if _herd_count(toks, m.start):  # "a herd of about twenty": the count is the mention
        j, count, counted = -1, _NUMBERS[toks[m.start].text], True
    while j >= prev_end and j >= 0 and m.start - j <= 7:
        t = toks[j]
        w = t.text
        if w in _NUMBERS and not toks[j + 1].joined:
            count, counted = _NUMBERS[w], True
            if t.joined and j > 0 and toks[j - 1].text in _NUMBERS and _NUMBERS[toks[j - 1].text] >= 20:
                count += _NUMBERS[toks[j - 1].text]  # "twenty-five"
            if w == "dozen" and j > 0 and toks[j - 1].text in _NUMBERS:
                count *= _NUMBERS[toks[j - 1].text]  # "two dozen candles"
            units = [x.text for x in toks[max(0, j - 3) : j]]
            grouped = len(units) == 3 and units[2] == "of" and units[1] in _QUANTITY and units[0] in _NUMBERS
            if grouped and units[1] != units[0]:
                count *= _NUMBERS[units[0]]  # "two teams of five players", "three rows of four chairs": ten, twelve
            # "above one bench", "between every two benches", "the two nearest benches": of those
            # already there, if any
            m.definite = w == "one" or (j > 0 and toks[j - 1].text in ("every", "each", *_DEFINITE))
            # "on each of the four crates": each of them, as "on each crate"
            m.each = m.each or [t.text for t in toks[max(0, j - 3) : j]] in (["each", "of", "the"], ["every", "one", "of"])
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
            count, counted, exact = int(float(w)), True, True
            break
        if w in _VAGUE:
            count = _VAGUE[w]
            counted = w == "both"
            if w == "few" and j > 0 and toks[j - 1].text == "a":
                j -= 1
            break
        if w == "of" and j > 0 and toks[j - 1].text in _QUANTITY:
            q = toks[j - 1].text
            # (a stack of long things, "a stack of drill pipes", is several of them)
            size = m.guess.size if m.guess is not None else load_catalogue()[m.category].size
            rests = m.guess.rests if m.guess is not None else load_catalogue()[m.category].rests
            small = rests == "surface" and max(size) < 1.0
            # "a pair of shears", "a set of brass scales": one thing that is named in the plural
            pair = q in ("pair", "pairs", "set", "sets") and toks[m.end - 1].text in load_vocabulary().pair_nouns
            # "a stack of plates", "a pile of parchment", "a line of bunting": one heap of small
            # things, one lot of stuff (no count noun); "a flock of sheep" are sheep
            shape = load_catalogue()[m.category].shape
            alive = m.category in _LIVING or shape in _LIVING or m.category == "fish"
            last = toks[m.end - 1].text
            stuff = not plural and singular(last) == last and not alive  # not "herbs", listed as written
            # "bunches of garlic": several lots of it
            heaped = (q in _HEAPS and small) or (stuff and singular(q) == q and q != "pair")
            count = 1 if heaped or pair else _QUANTITY[q]
            counted = q in ("pair", "couple", "dozen")
            k = j - 2
            if k >= 0 and toks[k].text in _NUMBERS:  # "two pairs of", "three stacks of"
                # a row of tulips is a bed, a row of shelves or benches one long unit (not a row of consoles);
                # each of "five pairs" is a pair, of "three rows" a row
                long_unit = load_catalogue()[m.category].shape in ("bookshelf", "flower_bed", "bench")
                per = 1 if q in ("row", "rows", "line", "lines") and long_unit else _QUANTITY.get(singular(q), count)
                # each of "two bundles of salt" is one lot of it
                per = 1 if heaped or pair or stuff else per
                count, counted = per * _NUMBERS[toks[k].text], True  # "three rows of shelves": a unit a row
            elif k >= 0 and toks[k].text == "of" and k > 0 and toks[k - 1].text in _QUANTITY:
                count = _QUANTITY[toks[k - 1].text]  # "a lot of"
            elif q in ("row", "line", "stack", "pile", "set", "group", "cluster", "ring", "circle") and k >= 0 and toks[
                k
            ].text not in ("a", "an", "one"):
                count = max(count, 4)
            each = _per_unit(toks, m.end)
            if each is not None:  # "two long rows of arcade machines, five in each row"
                units = _units_before(toks, j - 2)
                count, counted = each * (units if units is not None else 1 if q in _QUANTITY_ONE else 2), True
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
        if j == prev_end and j > 0 and singular(w) == w and not t.joined and (
            _plural_subject_word(toks[j - 1]) or _joint_verb_at(toks, j)
        ):
            break  # "two volunteers unload crates", "a man and his son unload crates": the verb of
            # the subject before, no kind of crate
        if adjectives and (w in load_vocabulary().clothing or singular(w) in load_vocabulary().clothing):
            adjectives = []  # "fishermen in red caps cast nets": what they wear ends there, the word
            break  # after it is their verb, no kind of net
        one = j > 1 and toks[j - 1].text in ("one", "other", "another") and toks[j - 2].text in (",", "and", "the")
        if w.endswith("ing") and j > 0 and (toks[j - 1].text in (",", ";", ":") or one):
            break  # ", eating sandwiches from a basket", "..., one holding binoculars": the participle of
            # the one before, no kind of sandwich
        bare = singular(toks[m.end - 1].text) != toks[m.end - 1].text
        if j == prev_end and bare and _verb_of_one(toks, j):
            break  # "a girl holds (red) balloons": the verb of the one before, no kind of balloon
        adjectives.insert(0, t.orig)
        j -= 1
    if count is None and j >= 1 and (toks[j - 1].text, toks[j].text) in _CROWDED:
        # "a grandstand packed with cheering peasants": a crowd ("full of goldfish": a plural
        # that looks singular, since a bare singular thing is never what a place is full of)
        count = _QUANTITY["crowd"]
    total = _total_after(toks, m) if plural else None
    if total is not None:  # "Rows of bidders sit ..., a dozen in all"
        count, counted = total, True
    if count is None and plural and singular(toks[m.end - 1].text) in load_vocabulary().crowd_words:
        count = _QUANTITY["crowd"]  # "spectators gather behind the rope": a crowd, not a few
    lining = m.end + 1 < len(toks) and toks[m.end].text == "line" and toks[m.end + 1].text in ("the", "both", "either")
    if count is None and plural and lining:
        count = _QUANTITY["row"]  # "street lamps line the path": a row of them
    if count is None:
        count = UNCOUNTED if plural else 1
    count = count if exact else min(count, CROWD)
    if m.category in ("books", "string_lights") and not counted:
        count = 1  # ("books on the shelf", "fairy lights strung over the bar": one lot of them)
    if plural and count == 1 and counted and not m.each and toks[max(m.start - 1, 0)].text not in ("a", "an"):
        count = 2
    if not counted and not plural and any(a.lower() in _ORDINALS for a in adjectives):
        m.definite = True  # "between the first and second car": the second of those already there
    m.count, m.counted, m.adjectives = count, counted, adjectives


def _plural_subject_word(tok: _Tok) -> bool:
    """A plural noun, not a possessive ("the boys' bikes"): what follows it at once is its verb."""
    return tok.text[:1].isalpha() and singular(tok.text) != tok.text and not tok.orig.endswith(("'", "’"))


#: Quantity nouns of a heap: a heap of small things or of stuff is one thing ("a stack of plates").
_HEAPS = {"stack", "stacks", "pile", "piles", "heap", "heaps", "bundle", "bundles"}
#: Quantity nouns that name one unit ("a row of", "a stack of"); their plurals name several.
_QUANTITY_ONE = {"row", "line", "stack", "pile", "set", "group", "cluster", "ring", "circle", "pair", "couple"}
#: Unit nouns a "N in each ..." phrase counts by.
_UNIT_NOUNS = {"row", "line", "column", "stack", "pile", "group", "cluster", "ring", "circle", "set", "rank", "tier"}


#: Units a group of groups names its members by ("four teams of horses, each pair pulling a plough").
_MEMBER_UNITS = ("pair", "couple", "trio")


def _per_unit(toks: list[_Tok], end: int) -> int | None:
    """The count in ", five in each row" after a noun phrase, in its sentence ("two rows of
    machines face each other, five in each row"), or the unit ", each pair ..." names ("four
    teams of horses, each pair pulling a plough": two a team), else None."""
    k = end
    while k < len(toks) and toks[k].text not in (".", "!", "?", ";"):
        words = [t.text for t in toks[k : k + 4]]
        if toks[k - 1].text == "," and words[0] in ("each", "every") and words[1:2] and words[1] in _MEMBER_UNITS:
            return _QUANTITY[words[1]]
        if (k == end or toks[k - 1].text == ",") and len(words) == 4 and words[0] in _NUMBERS and words[1] in (
            "in", "per", "to"
        ) and words[2] in ("each", "every", "a") and singular(words[3]) in _UNIT_NOUNS:  # fmt: skip
            return _NUMBERS[words[0]]
        k += 1
    return None


_TOTALS = {("in", "all"), ("in", "total"), ("all", "told")}


def _total_after(toks: list[_Tok], m: _Mention) -> int | None:
    """The count in ", a dozen in all" / ", twenty in total" / ", thirty altogether" later in the
    sentence of its first noun ("Rows of pupils sit on benches, twenty in all"), or in ", a
    dozen of them," right after the noun ("its passengers, a dozen of them, crowd along"), else None."""
    a = m.end + 1 + (m.end + 1 < len(toks) and toks[m.end + 1].text in ("a", "an"))
    words = [t.text for t in toks[a : a + 3]]
    apposed = m.end < len(toks) and toks[m.end].text == ","
    if apposed and words[:1] and words[0] in _NUMBERS and words[1:] == ["of", "them"]:
        return _NUMBERS[words[0]]
    start = max((k for k in range(m.start) if toks[k].text in (".", "!", "?")), default=-1) + 1
    if any(_match_at(toks, k) for k in range(start, m.start)):
        return None  # (a total tells how many of the sentence's subject there are)
    k = m.end
    while k < len(toks) and toks[k].text not in (".", "!", "?", ";"):
        if toks[k - 1].text == ",":
            a = k + (toks[k].text in ("a", "an"))
            words = [t.text for t in toks[a : a + 3]]
            if words and words[0] in _NUMBERS and (tuple(words[1:3]) in _TOTALS or words[1:2] == ["altogether"]):
                return _NUMBERS[words[0]]
        k += 1
    return None


def _units_before(toks: list[_Tok], k: int) -> int | None:
    """The number before "rows of" across a few describing words ("two long rows of"), else None."""
    while k >= 0 and toks[k].text not in _NUMBERS and toks[k].text not in _STOP and toks[k].text[:1].isalpha():
        k -= 1
    return _NUMBERS[toks[k].text] if k >= 0 and toks[k].text in _NUMBERS else None


#: Markers after which a bare plural is a crowd ("packed with fans", "full of goldfish").
_CROWDED = {("packed", "with"), ("crowded", "with"), ("full", "of"), ("filled", "with"), ("teeming", "with"),
            ("swarming", "with"), ("thronged", "with"), ("crammed", "with")}  # fmt: skip
#: A light's colour is its look after a finite verb too ("four habitats glow orange"), written as
#: the participle ("glowing orange").
_FINITE_LOOKS = {"glows": "glowing", "glow": "glowing", "gleams": "gleaming", "gleam": "gleaming", "shines": "shining",
                 "shine": "shining"}  # fmt: skip
#: Participles that describe the look of the noun before them ("painted red", "made of steel").
_LOOK_PARTICIPLES = {"glowing", "gleaming", "shining", "painted", "covered", "made", "coated", "upholstered",
                     "carved", "lacquered", "varnished", "dyed", "tinted", "trimmed", "wrapped", "draped",
                     "clad", "plated", "cast", "forged", "woven", "built", "lit", "finished", *_FINITE_LOOKS}  # fmt: skip
_LOOK_PREPOSITIONS = {"in", "of", "from", "with"}
#: After these, every noun is what the thing is made of ("made of steel and glass").
_MADE_OF = {("made", "of"), ("made", "from"), ("built", "of"), ("built", "from"), ("carved", "from"),
            ("carved", "of"), ("cast", "in"), ("forged", "from"), ("woven", "from")}  # fmt: skip
_MAX_LOOK_WORDS = 4


def _post_description(toks: list[_Tok], end: int, nouns: set[int], relations: set[int]) -> tuple[list[str], int]:
    """The look a participle gives the noun ending at ``end`` ("glowing pink", "covered in green
    velvet") and where it ends: the descriptive words up to a verb, a relation phrase (starting
    at one of ``relations``) or another noun phrase (at one of ``nouns``), so the mesh generator
    reads colours and materials written after the noun too."""
    starts = nouns | relations
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

    joins = ("and", "or")
    while k - first < _MAX_LOOK_WORDS and (describes(k) or (k < len(toks) and toks[k].text in joins and describes(k + 1))):
        k += 1
    if k == first or (k in nouns and not made_of):
        return [], end  # "a table covered in books", "covered with glass flasks": things on it, no look
    words = _written(toks[end:k])
    words[0] = _FINITE_LOOKS.get(words[0], words[0])
    return words, k
