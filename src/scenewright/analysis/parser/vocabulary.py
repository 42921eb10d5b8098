"""The open vocabulary: things the catalogue does not name still become objects.

A camel, a fuel tank or a street musician has no catalogue record, but each names a thing a
user expects to see. ``data/vocabulary.json`` maps such head words to a shape family (a
catalogue record marked ``family``: animal, figure, machine, tank...) or to an existing
category, with a typical size; words that name no thing (places, times, weather, parts,
materials) are listed so that a noun nobody listed can still become a generic ``thing``
without turning "a sunny afternoon" into an object. Objects read this way are *guessed*.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import lru_cache
from importlib import resources

from scenewright.analysis.parser import wordnet
from scenewright.core.catalogue import load_catalogue, match_phrase, singular, words

#: The family a thing nobody listed falls back to.
GENERIC = "thing"
#: Endings of nouns that name a person doing a trade or a study ("florist", "optician", "musketeer",
#: "watchmaker", "locksmith", "shipwright", "a soigneur", "a masseuse"): one word, so "coffee maker"
#: stays a machine.
_PERSON_ENDINGS = ("ist", "ian", "eer", "eur", "euse", "maker", "smith", "wright")
#: Endings of agent nouns: a person when the text has them do what people do ("a picker is working"),
#: a tool or a machine otherwise ("a heater", "a tractor").
_AGENT_ENDINGS = ("er", "or", "ant", "ent")
#: WordNet kinds too broad (or too many things' names) to tell a shape: the walk up stops there.
_VAGUE_KINDS = frozenset({"device", "instrumentality", "artifact", "whole", "object", "canvas", "support",
                          "covering", "equipment", "implement", "structure", "creation", "commodity"})  # fmt: skip
#: WordNet kinds of a place word that make it a room of a larger place ("an office", "a kitchen",
#: "a wheelhouse"), drawn as a box of :data:`_ROOM_BOX` metres, or a building of the scene.
_ROOM_KINDS = frozenset({"room", "compartment"})
_ROOM_BOX = (4.0, 3.0, 3.0)
_BUILDING_KINDS = frozenset({"building", "place of business", "establishment", "facility", "outbuilding",
                             "farm building", "place of worship", "mercantile establishment"})  # fmt: skip
#: Letters a word keeps before an ending for the ending to tell its family ("gator" is no machine).
_MIN_STEM = 3
#: WordNet's kinds of sense a bare plural must name to be things of the scene, and the kinds of
#: made thing one wears (a bare plural of those is clothing: "students in jumpsuits") or that are
#: a part or a cover of another ("tables with white tablecloths", "a box on stilts").
_BARE_SENSES = ("noun.artifact", "noun.animal", "noun.person")
_NOT_BARE_KINDS = frozenset({"clothing", "garment", "footwear", "headdress", "attire", "protective garment",
                             "linen", "piece of cloth", "fabric", "fastener", "structural member"})
#: Letters the listed noun that ends a closed compound must have to name it ("racehorse" is a horse;
#: a "carpet" is no pet, a "pheasant" no ant).
_MIN_HEAD = 4
#: Letters an "-ish" describing word keeps before its ending ("reddish", "greenish"); fewer make a
#: noun ("finish", "radish", "parish").
_ISH_STEM = 4
#: Endings of English adjectives ("rusty", "glowing", "magical", "robotic", "woollen").
_ADJECTIVE_ENDINGS = ("ly", "ous", "ful", "ish", "less", "able", "ible", "ive", "ed", "est", "y", "ing", "al", "ic",
                      "en", "ern", "ar", "ant", "ent", "ese", "ian")  # fmt: skip


@dataclass(frozen=True)
class Entry:
    """What the vocabulary says of one head word or phrase."""

    category: str
    size: tuple[float, float, float]
    rests: str


@dataclass(frozen=True)
class Vocabulary:
    entries: dict[tuple[str, ...], Entry]
    not_things: frozenset[str]
    places: frozenset[str]
    #: Parts of a thing ("hull", "planks", "pipes"): no thing where they belong to one.
    parts: frozenset[str]
    adjectives: frozenset[str]
    size_words: dict[str, float]
    #: How far size words may take a thing ("thing") or a person ("person") from the size its
    #: name gives: a name already says a typical one.
    size_word_bounds: dict[str, tuple[float, float]]
    #: Words that make a thing a small likeness ("a toy truck", "a model ship"), and how large one is.
    replica_words: frozenset[str]
    replica_side: float
    likeness_heads: frozenset[str]
    #: Words that stretch one side of any thing ("a long desk" is wider): x, y, z factors.
    shape_words: dict[str, tuple[float, float, float]]
    suffixes: tuple[tuple[str, str], ...]
    longest: int
    #: Endings of a compound that names a place ("hayfield", "farmland") → the shortest stem before them.
    place_endings: dict[str, int] = field(default_factory=dict)
    #: Phrases that beat the catalogue noun they end with ("arcade cabinet").
    overrides: frozenset[tuple[str, ...]] = frozenset()
    #: Person words "she"/"her" and "he"/"him" can name ("grandmother", "wizard").
    female: frozenset[str] = frozenset()
    male: frozenset[str] = frozenset()
    #: Body parts after "his"/"her"/"their": the relation they give to that person
    #: (``on``: "a laptop on her knees"; ``near``: "a dog at his feet"; ``side of``: "at his side").
    body_parts: dict[str, str] = field(default_factory=dict)
    #: Part word → the categories or shapes that have such a part ("its back": a seat's).
    part_owners: dict[str, frozenset[str]] = field(default_factory=dict)
    #: Catalogue things that stand on the ground at the catalogue's size but that a person the text
    #: gives one carries in hand ("ladies with parasols").
    carried_in_hand: frozenset[str] = frozenset()
    #: A word's sense in a setting: word → (the word it means there, the settings where it does):
    #: "an island" in a kitchen is a kitchen island, "a range" there a cooker.
    setting_senses: dict[str, tuple[str, frozenset[str]]] = field(default_factory=dict)
    #: A word the catalogue files as a thing that also names an animal, read as the animal when
    #: its verb is one only animals do ("two cranes wade in the reeds": birds, not machines).
    animal_senses: dict[str, Entry] = field(default_factory=dict)
    animal_only_verbs: frozenset[str] = frozenset()
    animal_haunts: frozenset[str] = frozenset()
    #: A word the catalogue files as a thing that also names a person, read as the person when the
    #: text has it act, dress or carry as people do ("fans in fancy dress"; "a fan whirrs" is the machine).
    person_senses: dict[str, Entry] = field(default_factory=dict)
    #: What people do: an agent noun nobody listed that does one of these is a person.
    person_verbs: frozenset[str] = frozenset()
    #: Moods and looks only people have ("a bored attendant"): an agent noun with one is a person.
    moods: frozenset[str] = frozenset()
    #: What things are made of ("rubber", "brass"): before a living thing, a likeness's name ("a rubber chicken").
    materials: frozenset[str] = frozenset()
    #: Person words that say whose someone is ("its owner", "her friend"), not who: an apposition
    #: after one names the person ("its owner, a girl in goggles" is the girl).
    relational: frozenset[str] = frozenset()
    #: Person verbs animals do too: alone they make no person of an unknown noun.
    animal_verbs: frozenset[str] = frozenset()
    #: Plural nouns that name one thing ("a pair of shears" is one pair).
    pair_nouns: frozenset[str] = frozenset()
    #: What people wear: no object while worn, a thing when held ("his hat in his hands").
    clothing: frozenset[str] = frozenset()
    #: The size (m) of a piece of clothing that is a thing (held, hung up, laid out, put on a stand).
    clothing_size: tuple[float, float, float] = (0.4, 0.3, 0.2)
    #: People who come as a crowd: a bare plural of one is many ("spectators gather").
    crowd_words: frozenset[str] = frozenset()
    #: Kind (seats, vehicles, mounts, perches, containers) → the categories, shapes, families
    #: and head words of things a person or an animal is on when it is in or on them.
    carriers: dict[str, frozenset[str]] = field(default_factory=dict)
    #: Posture (sitting, lying, standing) → the words that give it ("dozes", "lies").
    postures: dict[str, tuple[str, ...]] = field(default_factory=dict)
    #: What one does from where one is: "a heron watches from a rock" puts the heron on the rock
    #: ("pulls a rope from the barrel" does not).
    lookout_verbs: frozenset[str] = frozenset()
    #: Place words that are a thing when the text puts something on top of them or at their foot.
    landforms: dict[str, Entry] = field(default_factory=dict)
    #: Words that name a kind of thing named before ("the ship" after "a flying saucer").
    hypernyms: dict[str, frozenset[str]] = field(default_factory=dict)
    #: Place words that are a building of the scene when the text puts something outside them.
    buildings: dict[tuple[str, ...], Entry] = field(default_factory=dict)
    #: Parts that are a thing of their own once detached ("spare heads", "its arm removed").
    loose_parts: dict[str, Entry] = field(default_factory=dict)
    #: Words that detach a part ("spare", "severed", "removed").
    detached: frozenset[str] = frozenset()

    def carries(self, category: str, name: str, kinds: tuple[str, ...] | None = None, by_family: bool = True) -> bool:
        """Whether a thing of ``category`` named ``name`` is one of the ``kinds`` of carriers
        (all kinds when None): by its category, its catalogue shape or its head noun; with
        ``by_family`` False a guessed thing counts by its head noun only (a dome is a structure
        one stands on, but one is *in* it, not on it)."""
        record = load_catalogue()[category]
        head = singular(name.lower().split()[-1]) if name.strip() else ""
        names = (head,) if record.family and not by_family else (category, record.shape, head)
        return any(n in self.carriers[k] for k in (kinds or tuple(self.carriers)) for n in names)

    def carried_by_hand(self, category: str, name: str) -> bool:
        """Whether a thing of ``category`` named ``name`` is one people carry in hand though the
        catalogue sizes it as it stands on the ground (``carried_in_hand``: a parasol)."""
        head = singular(name.lower().split()[-1]) if name.strip() else ""
        return category in self.carried_in_hand or head in self.carried_in_hand

    def is_person_verb(self, word: str) -> bool:
        """Whether ``word`` is a verb only people do, as listed or as the plural subject's form of a
        listed "-s" form ("a picker works", "two pirates dig")."""
        forms = (word, f"{word}s", f"{word}es") if word.isalpha() else (word,)
        return any(f in self.person_verbs for f in forms)

    def is_posture_verb(self, word: str) -> bool:
        """A verb of sitting, lying or standing ("dozes", "perched", "stands")."""
        return any(word in verbs for verbs in self.postures.values())

    def agrees(self, pronoun: str, head: str) -> bool:
        """Whether "she"/"her" or "he"/"him"/"his" can name a thing whose name ends in ``head``:
        a person word of the other sex cannot; any other word can."""
        w = head.lower()
        if pronoun in ("her", "hers", "herself", "she"):
            return w not in self.male
        if pronoun in ("him", "his", "himself", "he"):
            return w not in self.female
        return True

    def over_catalogue(self, tokens: tuple[str, ...]) -> bool:
        return tokens in self.overrides or (*tokens[:-1], singular(tokens[-1])) in self.overrides

    def match(self, tokens: tuple[str, ...]) -> Entry | None:
        """The entry a word tuple names, the last word also in its singular form."""
        if tokens in self.entries:
            return self.entries[tokens]
        if not tokens:
            return None
        return self.entries.get((*tokens[:-1], self.singular(tokens[-1])))

    def singular(self, word: str) -> str:
        """``singular``, also for the plural of a listed "-ic" noun ("mechanics", "medics"),
        which ``singular`` keeps as a subject of study ("physics")."""
        return word[:-1] if word.endswith("ics") and (word[:-1],) in self.entries else singular(word)

    def is_thing_word(self, word: str) -> bool:
        """Could ``word`` head a noun phrase naming a thing? Not a place, time, part, material
        or adjective, and shaped like a noun."""
        w = word.lower()
        one = singular(w)
        if w in self.not_things or one in self.not_things or w in self.adjectives or self.is_place_compound(one):
            return False
        if self.comparative(w):
            return False  # "a smaller skeleton": no "smaller" of its own
        if not w.isalpha() or len(w) < 3:
            return False
        # what WordNet knows of a word nobody listed ("a bout" is an event, "a jellyfish" a thing; its
        # "one" is the number, though "smaller ones" stand for a noun said before)
        known = None if one == "one" or self._entry_of((one,)) is not None else wordnet.names_a_thing(one)
        if known is not None:
            return known
        # an ending makes an adjective only after a stem of its own ("tallest", not "nest" or "chest")
        endings = ("ly", "ous", "ful", "ish", "less", "able", "ible", "ive", "ed", "est")
        return not any(w.endswith(e) and len(w) - len(e) >= _MIN_STEM for e in endings)

    def bare_thing(self, word: str) -> bool:
        """Whether a plural nobody counted or listed names things of the scene ("drift under bright
        parachutes", "a pool crowded with sunbathers"): WordNet's sense of it is plainly a made
        thing, an animal or a person, and nothing one wears ("in jumpsuits") or a part of a thing."""
        w = word.lower()
        one = singular(w)
        if one == w or one in self.clothing or w in self.clothing or w in self.parts or not self.is_thing_word(w):
            return False
        if wordnet.kind_of_sense(one) not in _BARE_SENSES:
            return False
        return not any(kind in _NOT_BARE_KINDS for kind in wordnet.kinds(one))

    def names_place(self, word: str) -> bool:
        """Whether ``word`` (singular) is a place word: listed as one, or a word nobody listed that
        WordNet knows as a room, a building, a facility or an area ("a courtroom", "a racecourse"),
        which the text may set the scene in."""
        return word in self.places or (self._entry_of((word,)) is None and wordnet.is_place(word))

    def building(self, tokens: tuple[str, ...]) -> Entry | None:
        """What a place word is when the text puts a thing outside it ("a clock hangs above the glass
        office", "ambulances wait by the harbour office"): the building the vocabulary lists, else, for
        a place word nobody listed as one, a room-sized box when WordNet files it under rooms, a house
        when under buildings or businesses; None for open ground ("the street", "the square")."""
        key = (*tokens[:-1], singular(tokens[-1])) if tokens else ()
        if key in self.buildings or not key:
            return self.buildings.get(key)
        head = key[-1]
        if len(key) > 1 and " ".join(key) not in self.places:
            return None  # ("the long bar", "the harbour office": the head word's)
        if not (head in self.places or self.names_place(head)):
            return None
        built = set(wordnet.kinds(head))
        if built & _ROOM_KINDS:
            return Entry("house", _ROOM_BOX, load_catalogue()["house"].rests)
        if built & _BUILDING_KINDS:
            return self._family("house")
        return None

    def is_place_compound(self, word: str) -> bool:
        """A compound nobody listed that ends in a place word ("a mown hayfield", "the farmland"):
        ground the scene stands on, no thing in it."""
        if (word,) in self.entries:
            return False
        return any(word.endswith(e) and len(word) - len(e) >= stem for e, stem in self.place_endings.items())

    def comparative(self, word: str) -> bool:
        """A listed describing word's comparative ("smaller", "bigger", "larger", "busier"): "-er"
        makes agent nouns too ("a trucker", "a planter"), so only after a stem the list knows."""
        if not word.endswith("er") or len(word) < 5:
            return False
        stem = word[:-2]
        known = self.adjectives | self.size_words.keys()
        doubled = len(stem) > 2 and stem[-1] == stem[-2] and stem[:-1] in known  # "bigger", "fatter"
        return stem in known or stem + "e" in known or doubled or (stem.endswith("i") and stem[:-1] + "y" in known)

    def is_adjective(self, word: str) -> bool:
        """A describing word rather than a noun that names the kind ("rusty" vs "street")."""
        w = word.lower()
        if w in self.adjectives or w in self.size_words or self.comparative(w):
            return True
        if self.match((w,)) is not None or w in self.places:
            return False
        if w.endswith("ish") and len(w) - len("ish") < _ISH_STEM:
            return not w.isalpha()  # "a finish tape", "a polish jar": nouns; "reddish", "childish" keep a word before
        return w.endswith(_ADJECTIVE_ENDINGS) or not w.isalpha()

    def guess(self, head: str) -> Entry:
        """A family for a noun nobody listed: by its form (:meth:`guess_by_form`), else by what
        WordNet says it is, else a thing."""
        entry = self.guess_by_form(head)
        return (self.guess_in_wordnet(head) or entry) if entry.category == GENERIC else entry

    def guess_by_form(self, head: str) -> Entry:
        """A family for a noun nobody listed, from its ending ("…saurus" → animal) or as a word that
        says whose someone is ("her colleague"), else a thing."""
        one = singular(head.lower())
        if one in self.relational:
            return self._family("figure")  # "her colleague", "a companion": a word for whose someone is names a person
        for suffix, family in self.suffixes:
            if one.endswith(suffix) and len(one) - len(suffix) >= _MIN_STEM:
                return self._family(family)
        tail = self._compound_head(one)
        if tail is not None:
            return tail  # "a postmistress", "six racehorses", "the schoolchildren": a closed compound is its last noun
        ending = next((e for e in _PERSON_ENDINGS if one.endswith(e)), None)
        if ending is not None and len(one) - len(ending) >= _MIN_STEM:
            return self._family("figure")  # "a florist", "two technicians", "a puppeteer", "a watchmaker"
        return self._family(GENERIC)

    def _compound_head(self, word: str) -> Entry | None:
        """The entry of the longest listed noun that ends ``word`` after a stem of its own, else None."""
        tails = (self._entry_of((word[i:],)) for i in range(_MIN_STEM, len(word) - _MIN_HEAD + 1))
        return next((entry for entry in tails if entry is not None), None)

    def _entry_of(self, tokens: tuple[str, ...]) -> Entry | None:
        """The entry the vocabulary or else the catalogue has for a word tuple, else None."""
        entry = self.match(tokens)
        if entry is not None:
            return entry
        category = match_phrase(tokens)
        return self._family(category) if category is not None else None

    def guess_in_wordnet(self, word: str) -> Entry | None:
        """What WordNet says ``word`` is ("a musher" is a traveller, a person; "a sampan" a skiff, a
        small boat, a boat): a person is a figure; anything else the nearest of its kinds that the
        vocabulary or the catalogue names, else an animal's family when it is one, else None (a
        body part, a thing of no kind drawn, a word WordNet does not know)."""
        one = singular(word.lower())
        sense = wordnet.kind_of_sense(one)
        # (an agent noun that may also be a made thing is a person when the text has it act as one:
        # :meth:`guess_agent`)
        agent = one.endswith(_AGENT_ENDINGS) and not wordnet.only_people(one)
        if sense in ("noun.person", "noun.body", None):
            return self._family("figure") if sense == "noun.person" and not agent else None
        for kind in wordnet.kinds(one):
            if kind in _VAGUE_KINDS:
                break  # above these a kind says nothing of a shape ("device": a harpsichord, a winch)
            entry = self._entry_of(tuple(words(kind)))
            if entry is not None:
                return entry
        return self._family("animal") if sense == "noun.animal" else None

    @staticmethod
    def person_first(word: str) -> bool:
        """Whether ``word`` names a person before anything else it can see ("a coach", "a pilot";
        not "the bleachers", "a chair"), as written if WordNet knows that form."""
        word = word.lower()
        return wordnet.kind_of_sense(word if wordnet.senses(word) else singular(word)) == "noun.person"

    @staticmethod
    def is_creature(word: str) -> bool:
        """Whether WordNet knows ``word`` as an animal first ("a heron", "two cormorants")."""
        return wordnet.kind_of_sense(singular(word.lower())) == "noun.animal"

    def guess_agent(self, head: str, acts: bool, human: bool = False) -> Entry | None:
        """A person for a noun nobody listed when the text has it do what people do: an agent
        noun that acts (``acts``: "four pickers are working", "a picker sleeps"), or any noun
        that does what only people do (``human``: "a marshal waves", "their sensei, an old
        man, ..."); None otherwise ("a heater hums", "a tanuki sleeps")."""
        return self._family("figure") if (self.is_agent_noun(head) and acts) or human else None

    @staticmethod
    def is_agent_noun(word: str) -> bool:
        """Whether a word ends as a noun of one who does something ("tester", "swallower")."""
        one = singular(word.lower())
        return one.endswith(_AGENT_ENDINGS) and len(one) - 2 >= _MIN_STEM

    def family(self, family: str) -> Entry:
        """The entry of a shape family ("vehicle"), its size and rest the catalogue's."""
        return self._family(family)

    @staticmethod
    def _family(family: str) -> Entry:
        category = load_catalogue()[family]
        return Entry(family, category.size, category.rests)


def _senses(table: dict) -> dict[str, Entry]:
    """A table of other senses (word -> [category, width, depth, height]) as entries on the ground."""
    return {
        k: Entry(v[0], (float(v[1]), float(v[2]), float(v[3])), "ground")
        for k, v in table.items() if k not in ("about", "verbs", "haunts")
    }  # fmt: skip


def _validate(raw: dict) -> Vocabulary:
    catalogue = load_catalogue()
    entries: dict[tuple[str, ...], Entry] = {}
    for phrase, spec in raw["things"].items():
        name, *size = spec[:4]
        if name not in catalogue:
            raise ValueError(f"vocabulary: {phrase!r} names category {name!r}, which the catalogue does not have")
        if len(size) != 3 or min(size) <= 0:
            raise ValueError(f"vocabulary: {phrase!r} needs three positive sizes, got {size}")
        rests = spec[4] if len(spec) > 4 else catalogue[name].rests
        entries[tuple(words(phrase))] = Entry(name, (float(size[0]), float(size[1]), float(size[2])), rests)
    lists = raw["not_things"]
    people = raw.get("people", {})
    not_things = frozenset(w for kind in lists.values() for w in kind)
    for family in raw["suffixes"].values():
        if family not in catalogue:
            raise ValueError(f"vocabulary: suffix family {family!r} is not a catalogue category")
    return Vocabulary(
        entries=entries,
        not_things=not_things,
        places=frozenset(lists["places"]),
        parts=frozenset(lists["parts"]),
        adjectives=frozenset(raw["adjectives"]),
        size_words={k: float(v) for k, v in raw["size_words"].items()},
        size_word_bounds={k: (float(v[0]), float(v[1])) for k, v in raw["size_word_bounds"].items()},
        replica_words=frozenset(raw["replicas"]["words"]),
        replica_side=float(raw["replicas"]["largest_side"]),
        likeness_heads=frozenset(raw["replicas"]["heads"]),
        shape_words={k: (float(v[0]), float(v[1]), float(v[2])) for k, v in raw.get("shape_words", {}).items()},
        suffixes=tuple(sorted(raw["suffixes"].items(), key=lambda kv: -len(kv[0]))),
        longest=max(len(k) for k in entries),
        place_endings={k: int(v) for k, v in raw.get("place_endings", {}).items()},
        overrides=frozenset(tuple(words(p)) for p in raw.get("over_catalogue", ())),
        female=frozenset(people.get("female", ())),
        male=frozenset(people.get("male", ())),
        body_parts={
            **{w: "on" for w in people.get("body_parts_on", ())},
            **{w: "near" for w in people.get("body_parts_near", ())},
            **{w: "in front of" for w in people.get("body_parts_front", ())},  # "a dog at his feet", as "at the foot of"
            **{w: "side of" for w in people.get("body_parts_beside", ())},  # "his helmet at his side"
        },
        part_owners={k: frozenset(v) for k, v in raw.get("part_owners", {}).items() if k != "about"},
        animal_senses=_senses(raw.get("animal_senses", {})),
        animal_only_verbs=frozenset(raw.get("animal_senses", {}).get("verbs", ())),
        animal_haunts=frozenset(raw.get("animal_senses", {}).get("haunts", ())),
        person_senses=_senses(raw.get("person_senses", {})),
        setting_senses={
            k: (v["as"], frozenset(v["in"])) for k, v in raw.get("setting_senses", {}).items() if k != "about"
        },
        person_verbs=frozenset(raw.get("person_verbs", ())),
        animal_verbs=frozenset(raw.get("animal_verbs", ())),
        moods=frozenset(people.get("moods", ())),
        carried_in_hand=frozenset(people.get("carried_in_hand", ())),
        relational=frozenset(people.get("relational", ())),
        pair_nouns=frozenset(raw.get("pair_nouns", ())),
        clothing=frozenset(lists.get("clothing", ())),
        crowd_words=frozenset(raw.get("crowd_words", ())),
        clothing_size=tuple(float(v) for v in raw.get("clothing_size", (0.4, 0.3, 0.2))),  # type: ignore[arg-type]
        materials=frozenset(lists.get("materials", ())),
        carriers={k: frozenset(v) for k, v in raw.get("carriers", {}).items() if k != "about"},
        postures={k: tuple(v) for k, v in raw.get("postures", {}).items() if k != "about"},
        lookout_verbs=frozenset(raw.get("lookout_verbs", ())),
        landforms={
            k: Entry(v[0], (float(v[1]), float(v[2]), float(v[3])), catalogue[v[0]].rests)
            for k, v in raw.get("landforms", {}).items()
            if k != "about"
        },
        hypernyms={k: frozenset(v) for k, v in raw.get("hypernyms", {}).items() if k != "about"},
        buildings={
            tuple(words(k)): Entry(v[0], (float(v[1]), float(v[2]), float(v[3])), catalogue[v[0]].rests)
            for k, v in raw.get("buildings", {}).items()
            if k != "about"
        },
        loose_parts={
            k: Entry(v[0], (float(v[1]), float(v[2]), float(v[3])), catalogue[v[0]].rests)
            for k, v in raw.get("loose_parts", {}).items()
            if k not in ("about", "detached")
        },
        detached=frozenset(raw.get("loose_parts", {}).get("detached", ())),
    )


@lru_cache(maxsize=1)
def load_vocabulary() -> Vocabulary:
    """The vocabulary, read once from the package data."""
    text = resources.files("scenewright.data").joinpath("vocabulary.json").read_text(encoding="utf-8")
    return _validate(json.loads(text))


#: m per unit of a size word's factor, the least a creature called giant or huge is long.
MONSTER_SIDE = 0.8


def scaled(size: tuple[float, float, float], adjectives: list[str], bounds: str | None = None) -> tuple[float, float, float]:
    """``size`` scaled by the size words among ``adjectives`` ("a giant tortoise", "a tiny dragon"),
    kept within the ``size_word_bounds`` of that name when given ("a small fridge" is an
    under-counter one, "a tall man" no giant); a creature called giant or huge (``creature``) is
    a monster's size however small its kind ("a giant spider")."""
    factor = 1.0
    vocabulary = load_vocabulary()
    for adjective in adjectives:
        factor *= vocabulary.size_words.get(adjective.lower(), 1.0)
    said = factor
    if bounds is not None:
        lo, hi = vocabulary.size_word_bounds[bounds]
        factor = min(max(factor, lo), hi)
    if bounds == "creature" and said >= 2.0:
        # "a giant spider", "a huge seahorse": a creature of a story, its longest side at least
        # MONSTER_SIDE metres per unit of the word's factor (a bear is big already)
        factor = max(factor, said * MONSTER_SIDE / max(size))
    return (round(size[0] * factor, 4), round(size[1] * factor, 4), round(size[2] * factor, 4))


def replica(size: tuple[float, float, float]) -> tuple[float, float, float]:
    """The size of a likeness of a thing of ``size`` ("a toy spaceship", "a model windmill"): its
    proportions, no side longer than a replica's."""
    factor = min(1.0, load_vocabulary().replica_side / max(size))
    return (round(size[0] * factor, 4), round(size[1] * factor, 4), round(size[2] * factor, 4))


def stretched(size: tuple[float, float, float], adjectives: list[str]) -> tuple[float, float, float]:
    """``size`` with the sides the shape words among ``adjectives`` stretch ("a long table" is
    wider than a table; "wide" too, "narrow" the other way)."""
    x, y, z = size
    table = load_vocabulary().shape_words
    for adjective in adjectives:
        fx, fy, fz = table.get(adjective.lower(), (1.0, 1.0, 1.0))
        x, y, z = x * fx, y * fy, z * fz
    return (round(x, 4), round(y, 4), round(z, 4))
