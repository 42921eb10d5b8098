"""Clause reading: one pass over the text that builds groups of objects and the relations
between them, resolving references ("it", "them", "the island") on the way.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from scenewright.analysis.parser.contents import _Contents
from scenewright.analysis.parser.grammar import (
    MAX_COUNT,
    _BUILDING_PARTS,
    _CEILING_WORDS,
    _CHAIN_KINDS,
    _COPULAS,
    _DEPICTIONS,
    _DRIVING_PARTS,
    _ENCLOSURES,
    _FLAT_DEPTH,
    _FLOOR_WORDS,
    _FORMATIONS,
    _FORMATION_NOUNS,
    _GROUND_KINDS,
    _HANDHELD_SIZE,
    _HOLDER_KINDS,
    _HUTCH_HEIGHT,
    _KIND_RELATION,
    _LOAD_HOSTS,
    _LOW_HOST,
    _MAKESHIFT_HEIGHT,
    _MAKESHIFT_LENGTH,
    _NARROW_TOP,
    _ONE_AT_A_TIME,
    _OWN_SIDES,
    _PERSONAL,
    _PERSON_POSSESSIVES,
    _PLACE_KINDS,
    _PLATFORM_HEIGHT,
    _POSSESSED,
    _RELATIVES,
    _REVERSED,
    _RIDDEN,
    _SEATS,
    _SIDE_WORDS,
    _STANDING_HEIGHT,
    _STANDING_PARTS,
    _THRESHOLDS,
    _VESSEL_KINDS,
    _TOOL_SIZE,
)
from scenewright.analysis.parser.hands import _Hands
from scenewright.analysis.parser.kinds import _Kinds
from scenewright.analysis.parser.nouns import (
    UNCOUNTED,
    _COMPARED,
    _MEMBER_UNITS,
    _Group,
    _Mention,
    _find_mentions,
    _is_plural,
    _mark_appositions,
    _mark_members,
    _one_doing,
    _opens_phrase,
    _participle,
    _post_description,
    _read_count,
    _verbless_opening,
    thing_plural,
    worn_description,
)
from scenewright.analysis.parser.phrases import _Rel, _find_relations, _phrase_table
from scenewright.analysis.parser.references import _References
from scenewright.analysis.parser.room import WALL_UNIT_HEIGHTS, standing_form
from scenewright.analysis.parser.sizes import _apply_sizes, _read_sizes
from scenewright.analysis.parser.support import FLAT_HOST
from scenewright.analysis.parser.tokens import _CLAUSE_WORDS, _split, _Tok, _tokenise
from scenewright.analysis.parser.vocabulary import GENERIC, load_vocabulary, replica, scaled, stretched
from scenewright.analysis.parser.words import (
    _ADVERBS,
    _CARRY_VERBS,
    _CONSUMING,
    _DETERMINERS,
    _FILL_VERBS,
    _FINITE,
    _GIVE_VERBS,
    _HAND_PAIRS,
    _HAND_VERBS,
    _HANG_VERBS,
    _HOLD,
    _HOLD_PAIRS,
    _KEPT_IN_HAND,
    _LEAD_VERBS,
    _NUMBERS,
    _ORDINALS,
    _OWNER_PRONOUNS,
    _OWN_PLACE,
    _PARTS_A_THING,
    _PLANT_SHAPES,
    _SHARE_VERBS,
    _STATE_PARTICIPLES,
    _STOP,
    _TAKING_VERBS,
    _TURN_VERBS,
    _USE_VERBS,
    _QUANTITY,
    _VAGUE,
    _WARES_VERBS,
    _WORKS_ITS_KIND,
    _is_verb,
    _verb_stem,
)
from scenewright.core.catalogue import Category, load_catalogue, match_phrase, singular


#: Describing words that give each of several its own ("at separate tables", "in individual pens").
_APIECE = {"separate", "individual"}

#: m, a seat narrower than this holds one sitter ("two rows of chairs": a chair each, not of benches).
_ONE_SEAT_WIDTH = 1.0
#: m, a seat this long seats as many side by side as fit (a bench, a sofa, a pew).
_BENCH_LENGTH = 1.2

#: How many sides "every side" / "all sides" names: a square's.
_ALL_SIDES = 4

#: How much larger than its animal a statue of one is.
_LIKENESS_SCALE = 1.3

#: Parts on top of a thing: what does something "from the roof of" it is fixed there.
_ROOF_PARTS = {"roof", "rooftop", "top"}
#: Verbs of being on the water, by their stem ("a swan glides", "a boat bobs").
_AFLOAT_VERBS = {"swim", "glide", "float", "paddle", "bob", "drift", "dabble"}


def _every_side(toks: list[_Tok], k: int, ce: int) -> int:
    """How many sides "every side", "all sides" or "all four sides" at ``k`` names, or how many of
    a part "at each corner", "at each end" (no object: one thing a part); 0 if none."""
    words = [t.text for t in toks[k : min(k + 3, ce)]]
    if words[:2] in (["every", "side"], ["all", "sides"]):
        return _ALL_SIDES
    if len(words) == 3 and words[0] == "all" and words[2] == "sides" and words[1] in _NUMBERS:
        return _NUMBERS[words[1]]
    at = k > 0 and toks[k - 1].text in ("at", "on", "by", "in")
    if at and len(words) > 1 and words[0] in ("each", "every") and words[1] in _PARTS_A_THING:
        return _PARTS_A_THING[words[1]]
    return 0


def _each_lead(toks: list[_Tok], k: int, ce: int) -> int:
    """Where "each of them", "every one" or "every one of them" at ``k`` ends, less one (the
    words then read as one "each"); ``k`` if none opens there."""
    words = [t.text for t in toks[k : min(k + 4, ce)]]
    j = k + 1
    unit = words[:1] in (["each"], ["every"]) and len(words) > 1 and words[1] in _MEMBER_UNITS
    if words[:2] in (["each", "one"], ["every", "one"]) or unit:
        j += 1  # ("each pair pulling a plough": each of the pairs of the group before)
    elif words[:1] != ["each"]:
        return k
    if [t.text for t in toks[j : j + 2]] in (["of", "them"], ["of", "these"], ["of", "those"]):
        j += 2
    return j - 1


#: Phrase kinds whose target is left unsaid: the thing just named ("on either side", "at one end").
_ELLIPTIC = ("flank elliptic", "above elliptic", "end of elliptic")
#: m, a palm grown in a pot ("a tall potted palm stands on either side of the desk").
_POTTED_PALM = (1.0, 1.0, 2.2)


@dataclass
class _Clause:
    """What one clause has built so far."""

    first: bool
    #: The clause opens as a sentence does, with a phrase before its own subject: the first of its
    #: sentence, or one after "and" that names its subject after the phrase ("..., and between
    #: them a crew heaves on the ropes").
    opens: bool = False
    main: list[int] = field(default_factory=list)
    head: list[int] | None = None  # what a "with" part hangs from
    wsub: list[int] = field(default_factory=list)
    hold: bool = False
    #: The with-things are in a person's hands ("with his putter", "waves a flag"): carried by
    #: the holder, who keeps the clause's next placing.
    hand: bool = False
    #: The holders share the one thing in hand ("sharing a thermos"): not one each.
    shared: bool = False
    #: ... and a verb of sharing (or of typing) says so: at a table, the thing is on it.
    sharing: bool = False
    #: The with-things are living ones a verb's doer is with ("a groom waits with the ponies"):
    #: the doer keeps the clause's next placing, they keep by the doer.
    company: bool = False
    #: With-things of "the other" of the holders ("one holding a lamp, the other a rope"): its second.
    others: set[int] = field(default_factory=set)
    wsub_related: set[int] = field(default_factory=set)
    last_target: list[int] = field(default_factory=list)
    last_target_end: int = -1
    expect_new: bool = False
    groups: list[int] = field(default_factory=list)
    main_groups: list[int] = field(default_factory=list)
    #: Phrases opening the clause before its subject: (kind, targets, one per member, the members
    #: of the target meant: "Between the second and the third, a miner kneels").
    fronted: list[tuple[str, list[int], bool, tuple[int | None, ...]]] = field(default_factory=list)
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
    #: "each" opened a deed ("each bent over an anvil", "each shaping a pot"): every thing the
    #: clause names after it comes once per member, not only its with-parts.
    each_deed: bool = False
    #: How many members "each" takes at a time: "each pair pulling a plough" is a plough a pair.
    each_unit: int = 1
    #: The several that a clause opening "one of them" picks its doer from ("colonists sit in the
    #: pews, one of them rocking a baby in her arms": "her" is one of them).
    one_of: list[int] = field(default_factory=list)
    #: Which of two holders a with-part belongs to: "one" or "other" ("two researchers, one with
    #: binoculars and the other with a clipboard"), so what it names comes once, not once each.
    single: str | None = None
    #: Single subjects named together that "each" goes over ("a dwarf and an elf, each with a
    #: tankard"): a with-thing of its own for every one.
    each_of: list[int] = field(default_factory=list)
    #: The group whose members each have their own target of the next placing ("each in a seat").
    each_own: int | None = None
    #: The subject's own verb has come ("a guard waves at ..."), so a participle after a target
    #: describes the target ("... at a lorry idling at the barrier").
    finite: bool = False
    #: ``finite`` as it stood when the last target was read.
    target_after_verb: bool = False
    #: What the last phrase placed ("a register on the counter ...": the register).
    last_srcs: list[int] = field(default_factory=list)
    #: Thing → what this clause put it on or in: no "it" of its own ("a parrot in a cage watches it").
    supports: dict[int, list[int]] = field(default_factory=dict)
    #: (doers, thing) for a living subject acting on a thing ("a porter pushes a cart").
    deeds: list[tuple[list[int], int]] = field(default_factory=list)
    #: Where the last thing acted on ends: a phrase right after it places it ("stirs a pot on the stove").
    deed_end: int = -1
    #: Thing acted on → which of its several members the text picks ("haggles at the middle stall").
    deed_members: dict[int, int] = field(default_factory=dict)


@dataclass
class _Phrase:
    """One relation phrase as :meth:`_Reader._relation` reads it, step by step."""

    rel: _Rel
    ce: int  # where its clause ends
    kind: str
    #: The target as read after the phrase: groups, a pronoun ("it", "him", "each one"), or nothing.
    target: list[int] | str | None
    end: int  # where the phrase and its target end
    #: "Between the first and second car": the two members of the target group.
    ordinals: tuple[int, int] | None = None
    #: The relation a body part names to its person ("on her knees": on), and the part word.
    body: str | None = None
    part: str | None = None
    #: "On each of its arms": how many parts, one thing on each.
    parts_each: int = 0
    srcs: list[int] = field(default_factory=list)
    targets: list[int] | str = field(default_factory=list)
    #: Who stands at the thing the phrase places, on the same perch ("stands at a lectern on a stage").
    riders: list[int] = field(default_factory=list)


#: What covers a sleeper ("under a blanket"): over them where they lie, no place of its own to be by.
_COVERS = frozenset({"picnic_blanket", "rug", "towel"})
#: Verbs after which "over" a thing is by it, bent or quarrelling over it, not up on it.
_OVER_VERBS = {"haggle", "argue", "quarrel", "bicker", "squabble", "fight", "bend", "lean", "hunch", "pore", "stoop",
               "toast", "roast", "warm", "cook", "huddle", "crouch"}  # fmt: skip
#: Machines that carry things as a person has them in hand ("a drone carrying a crate").
_MACHINE_BEARERS = frozenset({"robot", "drone"})
#: Machines that lift what they act on, and the verbs of it: the load hangs on them ("a crane swings a block").
_HOISTS = frozenset({"crane", "hoist", "derrick", "winch", "gantry", "arm"})
_HOIST_VERBS = frozenset({"lift", "lifts", "lifting", "hoist", "hoists", "hoisting", "swing", "swings", "swinging",
                          "lower", "lowers", "lowering", "raise", "raises", "raising", "dangle", "dangles",
                          "dangling"})  # fmt: skip
#: Words of how a thing is, after it, that the phrase after them goes on about ("a girl asleep on a bench").
_STATES = frozenset({"asleep", "awake", "alone", "aloft", "afloat", "ablaze", "adrift"})
#: Verbs of flying, and words after which a flyer comes down on something.
_FLIGHT = frozenset({"fly", "flies", "flying", "flew", "circle", "circles", "circling", "soar", "soars", "soaring",
                     "swoop", "swoops", "swooping", "glide", "glides", "gliding", "wheel", "wheels", "wheeling",
                     "flutter", "flutters", "fluttering", "flit", "flits", "flitting", "hover", "hovers", "hovering"})
_LANDING = frozenset({"to", "into", "onto", "down", "land", "lands", "landing", "perch", "perches", "perched"})
#: Beasts with wings the catalogue draws as four-legged animals.
_WINGED_BEASTS = frozenset({"dragon", "dragons", "wyvern", "wyverns", "griffin", "griffins", "gryphon", "pegasus"})
#: Participles of going after a thing: the doer is by it, however small it is (", chasing a rubber ball").
_CHASING = frozenset({"chasing", "stalking", "hunting", "herding"})


class _Reader(_Contents, _References, _Kinds, _Hands):
    """One pass over the text that builds groups of objects and relations between them. What is
    content (:mod:`.contents`), what a reference names (:mod:`.references`), what kind of thing
    a group is (:mod:`.kinds`) and what people hold or act on (:mod:`.hands`) are its parts in
    their own modules; the tables they share are in :mod:`.grammar`."""

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
        #: The body part the last target was read from names this relation to its person, if any.
        self._body_part: str | None = None
        #: The part word of the last target read through its owner ("its back" → "back").
        self._part: str | None = None
        #: That part is one a person or an animal stands or perches on ("from the barn's roof").
        self._perch_part = False
        #: "On each of its arms": how many parts the last target names, one thing on each.
        self._parts_each = 0
        #: Where the sentence before this one starts in ``history``: a posture verb's "in it"
        #: looks for a seat no further back.
        self._recent_from = 0
        #: Groups one of which each member of a group has ("his helmet" after "a knight on each
        #: bed"): "the bed" after them is each one's own.
        self.apiece: set[int] = set()
        #: Where this sentence starts in ``history``, and in ``groups``.
        self._sentence_from = 0
        self._sentence_groups = 0
        #: The living subjects of the clause before in this sentence: whom a clause that opens with a
        #: participle is about ("a knight kneels before the queen, offering her a sword": the knight).
        self.doers: list[int] = []
        #: (thing, person) groups where the text puts the thing on a part of the person.
        self.carried: set[tuple[int, int]] = set()
        #: Place words that set the scene rather than stand in it ("a hangar with a spaceship").
        self.places: list[str] = []
        #: Group → the part of the room the text puts it in (wall, corner, centre, back, front).
        self.anchors: dict[int, str] = {}
        #: Group → the formation its members stand in (row, stack, circle).
        self.formations: dict[int, str] = {}
        #: Groups the text names again as their rows ("walks between the rows").
        self.rows_named: set[int] = set()
        #: Group → how many rows its ``rows`` formation has ("in two rows").
        self.lines: dict[int, int] = {}
        #: What the clause before was about: its subjects, then what they were placed by, latest
        #: first; a phrase opening the next one with "it"/"them" names one of these first.
        self.topic: list[int] = []
        #: Puller → the load it pulls ("a horse pulls a plough"): what is behind the puller is behind its load.
        self.towed: dict[int, int] = {}
        #: Stand → the things on it, one a stand, as many as they come to by the end ("busts on
        #: pedestals at each corner": four pedestals).
        self.one_each: dict[int, int] = {}
        #: Where "of" follows "in two rows" after living subjects → those subjects ("twelve jurors sit in
        #: two rows of chairs"): the seats the rows are made of carry them, one each.
        self.rows_of: dict[int, list[int]] = {}
        #: Living thing → what the text has it "at" (a desk, a stall): "on it" after it names that first.
        self.worked_at: dict[int, int] = {}
        #: The latest subjects named together ("a singer and a fiddler stand ..."): "them" when no
        #: group of several is meant.
        self.together: list[int] = []
        #: What the clause before acted on ("a robot refills a coffee machine"): "it" after it names that first.
        self.acted_on: list[int] = []

    # ---- groups

    def _shown(self, m: _Mention) -> list[str]:
        """What a likeness shows, named after "of" ("a statue of a rearing horse", "a hologram of
        a planet"): the words that name it, which the likeness is named for (a rearing horse
        statue, whose mesh is a horse on a plinth)."""
        k = m.end + 1
        if m.category not in _DEPICTIONS or k >= len(self.toks) or self.toks[m.end].text != "of":
            return []
        while k < len(self.toks) and self.toks[k].text in _DETERMINERS:
            k += 1
        start, named = k, k in self.named_at  # a thing named there: its words ("a rearing horse")
        while k < len(self.toks) and k - start < 3 and self.toks[k].text[:1].isalpha() and (
            k in self.named_at if named else self.toks[k].text not in _STOP and not _is_verb(self.toks[k].text)
            and not _participle(self.toks[k].text)
        ):  # (else a word nobody listed, "a planet", up to its verb: "a hologram of the planet turning")
            k += 1
        return [t.text for t in self.toks[start:k]]

    def _under_word(self, start: int) -> bool:
        """Whether "under" (or "beneath") comes right before the noun phrase at ``start``."""
        j = start - 1
        while j >= 0 and (self.toks[j].text in _DETERMINERS or load_vocabulary().is_adjective(self.toks[j].text)):
            j -= 1
        return j >= 0 and self.toks[j].text in ("under", "beneath", "underneath")

    def _new_group(self, m: _Mention, sizes: list[tuple[str, float]]) -> int:
        adjectives = {a.lower() for a in m.adjectives}
        if m.category == "table" and adjectives & {"round", "circular"}:
            m.category = "round_table"
        potted = bool(adjectives & {"potted", "pot"}) and self.catalogue[m.category].shape in _PLANT_SHAPES
        if potted and m.category != "palm_tree":
            m.category, m.guess = "potted_plant", None  # "a potted olive tree" is a house plant, not a 6 m tree
        if (m.category == "table_lamp" and m.phrase.lower() in ("lamp", "lamps") and self._under_word(m.start)
                and not (m.end < len(self.toks) and (self.toks[m.end].text in ("on", "upon", "atop")
                                                      or self.toks[m.end].text.endswith("ed")))):
            # "grow tables stand under bright lamps": lamps overhead (not "the lamp on the desk", "a
            # lamp clamped to the bench")
            m.category = "pendant_lamp"
        cat: Category = self.catalogue[m.category]
        name = m.phrase.lower()
        vocabulary = load_vocabulary()
        words = name.split()
        # "the scales" are one thing, yet named as the listed word ("scale"), as "shears" are
        pair = words[-1] in vocabulary.pair_nouns and (words[-1],) not in vocabulary.entries
        if _is_plural(self.toks, m) or pair:
            one = vocabulary.singular  # ("mechanics" are mechanics)
            of = "of" in words[1:2]
            name = " ".join([one(words[0]), *words[1:]] if of else [*words[:-1], one(words[-1])])
        kind = [w.lower() for w in m.modifier]
        describing = [a.lower() for a in m.adjectives]
        if kind and describing[-len(kind) :] == kind:
            describing = describing[: -len(kind)]
        last = describing[-1] if describing else ""
        # a material makes a likeness of a living thing: its name keeps it ("a rubber chicken")
        likeness = last in vocabulary.materials and self._lives(m.category)
        kind_here = _opens_phrase(self.toks, m.start - 1) if m.guess is None else True
        # "a chopping block", "a diving hut": before a lifeless word nobody listed, an -ing word no
        # list calls a describing word names what it is for ("laughing children" do it)
        gerund = m.guess is not None and last.endswith("ing") and last not in vocabulary.adjectives
        # (inside the phrase, not a participle after the noun before: "statues holding axes")
        gerund = gerund and not self._lives(m.category) and _opens_phrase(self.toks, m.start - 1)
        # ("a raised bed planting lettuces": right after a noun, its participle)
        gerund = gerund and not any(o.end == m.start - 1 for o in self.by_start.values())
        if not kind and last and kind_here and (not vocabulary.is_adjective(last) or gerund) and (
            m.guess is not None or last not in vocabulary.not_things or likeness
        ):  # "a street musician", "a golf cart", "a taiko drum": the noun before names its kind
            # (a material, a place or a time before a catalogue thing does not: "an oak table")
            kind = describing[-1:]
            describing = describing[:-1]
        *before, head = [*kind, *name.split()]
        # ("the bride, a white fox in a red veil": the bride fox, "the fox" after)
        name = " ".join([*([m.role.lower()] if m.role else []), *before, *self._shown(m), head])
        description = " ".join([*describing, name, *m.post]).strip()
        bounds = "person" if cat.shape == "figure" else "creature" if self._lives(m.category) else "thing"
        base = m.guess.size if m.guess is not None else self._likeness_size(cat, kind) or cat.size
        base = self._kin_size(cat, kind, head) or base
        base = _POTTED_PALM if potted and m.category == "palm_tree" else base  # (a palm still, in its pot)
        base = stretched(scaled(base, describing, bounds), describing)
        likeness_of = {*kind, *describing} & vocabulary.replica_words
        copied = bool(likeness_of) and (cat.shape != "figure" or bool(likeness_of - {"model"}))
        if copied:
            base = replica(base)  # "a toy spaceship", "a model lighthouse", "toy soldiers" (not "a fashion model")
        size = _apply_sizes(base, sizes) if sizes else base
        rests = m.guess.rests if m.guess is not None else cat.rests
        if rests == "hanging" and standing_form(description):
            rests = "ground"  # "a full-length mirror", "a cheval mirror": stands on the floor, full height
            size = size if sizes else (size[0], size[1], max(size[2], _STANDING_HEIGHT))
        # "a candle burns on every table", no table named before: several tables, as many as an
        # uncounted plural names (not what a deed is done to: "counting every sack")
        words = range(m.start - 1, max(m.start - 5, -1), -1)
        det = next((j for j in words if self.toks[j].text in ("each", "every")), -1)
        place = any(r.end == det for r in self.rel_at.values())
        count = (m.count if m.count > 1 else UNCOUNTED) if m.each and place else min(max(1, m.count), MAX_COUNT)
        g = _Group(len(self.groups), m.category, count, name, description, size, rests=rests)
        g.guessed = m.guess is not None
        g.sized = bool(sizes)
        g.likeness = copied
        self.groups.append(g)
        default = UNCOUNTED if _is_plural(self.toks, m) else 1  # what an uncounted phrase gets
        j = m.start - 1
        while j > 0 and self.toks[j].text[:1].isalpha() and self.toks[j].text not in _STOP:
            j -= 1  # (past describing words: "their two fat ponies" is counted anyway)
        if default == UNCOUNTED and j >= 0 and self.toks[j].text == "their":
            self.theirs.add(g.index)
            # (whose they are: the sentence's first several things, "spacesuits hang on racks, their helmets ...")
            owner = next((o for o in self.groups[self._sentence_groups : g.index] if o.count > 1), None)
            if owner is not None:
                self.their_owner[g.index] = owner.index
        elif j >= 0 and self.toks[j].text in ("his", "her") and g.count == 1 and not m.counted:
            # "a knight snores on each bed, his helmet on the floor beside it": each knight's
            owner = next((o for o in reversed(self.groups[self._sentence_groups : g.index]) if self._person_at(o.index)), None)
            if owner is not None and owner.count > 1:
                g.count = owner.count
                self.apiece.add(g.index)
        elif j >= 0 and self.toks[j].text == "their" and not m.counted and self._pair_noun(m):
            g.count = UNCOUNTED  # "skiers with their skis on their shoulders": a pair each, as many as they
            self.theirs.add(g.index)
        if (m.counted and m.count > 1) or (not m.counted and m.count != default):  # "three", "many"
            self.numbered.add(g.index)
        self._formation_before(m, g)
        return g.index

    def _pair_noun(self, m: _Mention) -> bool:
        """A plural that names one thing ("skis", "shears"): ``pair_nouns`` in ``data/vocabulary.json``."""
        return self.toks[m.end - 1].text in load_vocabulary().pair_nouns

    def _formation_before(self, m: _Mention, g: _Group) -> None:
        """"Two rows of chairs", "a stack of crates", "a ring of stones": the formation the
        quantity noun before "of" names (a stack of small things is one thing, no formation)."""
        j = m.start - 1 - len(m.adjectives)
        if j < 1 or self.toks[j].text != "of" or g.count < 2:
            return
        formation = _FORMATION_NOUNS.get(self.toks[j - 1].text)
        if formation is None:
            return
        count = _NUMBERS.get(self.toks[j - 2].text) if j >= 2 else None
        if formation == "rows" and count == 1:
            formation = "row"
        self.formations.setdefault(g.index, formation)
        if formation == "rows" and count:
            self.lines.setdefault(g.index, count)
        several = self.toks[j - 1].text.endswith("s")  # ("three stacks of crates": three columns; "stacks of": two)
        if formation == "stack" and several:
            self.lines.setdefault(g.index, count or 2)

    def _resolve(self, m: _Mention, sizes: list[tuple[str, float]]) -> int:
        """A definite mention of something already present refers to it (by category, else by
        its head noun: "the island" → the kitchen island); anything else is new."""
        if m.group >= 0:
            return m.group
        if m.likeness_of is not None and m.likeness_of.group >= 0:
            m.group = m.likeness_of.group
            return m.group
        if (m.definite or m.each) and not sizes:
            vocabulary = load_vocabulary()
            last = self.toks[m.end - 1].text
            head = vocabulary.singular(last[:-2] if last.endswith("'s") else last)  # ("the calf's back": the calf)
            # a camel is not "the pig", nor "the cookhouse" the bunkhouse: in a family, or between
            # two guessed words, one thing only by the same head noun
            # (nor is "the ridge" the boulder named before, nor "the rocks" the cliffs: a landform
            # is one by its own name)
            family = self.catalogue[m.category].family or head in vocabulary.landforms
            # (nor are "the ducks" the one heron named before: several of a name the one does not
            # have are new; "the swings" are the swing set's)
            several = _is_plural(self.toks, m) and m.count != 1
            # (nor is "the waterfall" the rock named before: a word the vocabulary sizes as its own
            # thing is one by its own name)
            own_name = m.guess is not None and load_vocabulary().match((head,)) is m.guess
            same = [
                g for g in reversed(self.groups)
                if g.category == m.category and (not own_name or head in map(singular, g.name.split())) and (
                    not (family or m.guess is not None and g.guessed or self._landform(g))
                    or singular(g.name.split()[-1]) == head
                ) and not (several and g.count == 1 and head not in map(singular, g.name.split()))
            ]  # fmt: skip
            # ("two of the tables" after "three tables ... a fourth table": the three)
            found = next((g.index for g in same if g.count > 1 or not several), same[0].index if same else None)
            # "the teacher's desk" is not one of the school desks, nor "the teacher's bench" a lab table
            owned = any(t.text.endswith("'s") for t in self.toks[max(0, m.start - 1) : m.end - 1])
            owner = next((t.text for t in self.toks[max(0, m.start - 1) : m.end - 1] if t.text.endswith("'s")), "")
            # ("twelve desks face the teacher's desk": one of its own, not one of the twelve; "the home team's
            # bench" is one of two team benches)
            apart = not several and found is not None and self.groups[found].count > 1
            apart = apart and owner[:-2] not in self.groups[found].description.lower().split()
            if owned and found is not None and (singular(self.groups[found].name.split()[-1]) != head or apart):
                # "the captain's chair" again, after two crew seats: the captain's chair named before
                found = next(
                    (g.index for g in reversed(self.groups)
                     if g.category == m.category and singular(g.name.split()[-1]) == head
                     and owner in g.description.lower().split()),
                    None,
                )  # fmt: skip
            if found is None and not owned:
                found = next(
                    (g.index for g in reversed(self.groups) if g.name.split()[-1].endswith(head)), None
                )
            if found is None and not owned and several:  # "tends the roses" after "rose bushes": the bushes
                found = next(
                    (g.index for g in reversed(self.groups)
                     if head in g.name.split()[:-1] and self.catalogue[g.category].shape in _PLANT_SHAPES),
                    None,
                )  # fmt: skip
            kinds = vocabulary.hypernyms.get(head, ()) if m.definite and m.end - m.start == 1 else ()
            if found is None and kinds:  # "the ship" after "a flying saucer": that thing again
                found = next(
                    (g.index for g in reversed(self.groups)
                     if g.category in kinds or self.catalogue[g.category].shape in kinds),
                    None,
                )  # fmt: skip
            toks = self.toks
            partitive = several and m.start >= 3 and [t.text for t in toks[m.start - 2 : m.start]] == ["of", "the"]
            if found is None and partitive and toks[m.start - 3].text in _NUMBERS and self._lives(m.category):
                # "a foal lies between two of the mares" after "five white unicorns": some of the herd named before
                shape = self.catalogue[m.category].shape
                found = next((g.index for g in reversed(self.groups)
                              if g.count > 1 and self.catalogue[g.category].shape == shape), None)  # fmt: skip
            if found is not None:
                m.group = found
                if m.counted and _is_plural(self.toks, m) and self.groups[found].count < m.count:
                    self.groups[found].count = m.count  # "the two nearest benches" after "a bench": two at least
                # ("the bleachers" after "two sets of bleachers": all of them, a plural named as one)
                pair = self.toks[m.end - 1].text in load_vocabulary().pair_nouns and m.definite
                if not _is_plural(self.toks, m) and self.groups[found].count > 1 and not m.each and not pair:
                    self.instance[m.start] = self._member([a.lower() for a in m.adjectives], found)
                return found
        if m.alias:
            return -1
        several = self._one_of_several(m) if not sizes else None
        if several is not None:  # "the roof of a van" after "five vans": one of them, not a sixth
            m.group = several
            self.instance[m.start] = self._member([a.lower() for a in m.adjectives], several)
            return several
        m.group = self._new_group(m, sizes)
        return m.group

    def _one_of_several(self, m: _Mention) -> int | None:
        """The group of several things of ``m``'s kind named before, when ``m`` is one of them by a
        part of it: "a" after a part and "of" ("from the roof of a van", "on the back of a truck")."""
        j = m.start - len(m.adjectives) - 1
        if j < 2 or self.toks[j].text not in ("a", "an") or self.toks[j - 1].text != "of":
            return None
        parts = (*_BUILDING_PARTS, "back", *load_vocabulary().carriers.get("perches", ()))
        if singular(self.toks[j - 2].text) not in parts:
            return None
        # ("an estate car" is another car: a word of its kind before it, no describing word)
        if m.modifier or not all(load_vocabulary().is_adjective(a.lower()) for a in m.adjectives):
            return None
        name = " ".join(singular(t.text) for t in self.toks[m.start : m.end])
        return next((g.index for g in reversed(self.groups) if g.category == m.category and g.count > 1
                     and g.name.lower() == name), None)

    def _likeness_size(self, cat: Category, kind: list[str]) -> tuple[float, float, float] | None:
        """The size of a statue of an animal ("a cat statue", "a horse statue"): its animal's,
        a little larger; None for any other thing (a statue of a person stands taller than life)."""
        if cat.shape != "statue" or not kind:
            return None
        entry = load_vocabulary().match(tuple(kind))
        category = entry.category if entry is not None else match_phrase(tuple(kind))
        if category is None or self.catalogue[category].shape not in ("animal", "bird"):
            return None
        size = entry.size if entry is not None else self.catalogue[category].size
        return tuple(round(_LIKENESS_SCALE * v, 4) for v in size)

    def _member(self, words: list[str], g: int) -> int:
        """Which of a group's members the describing words name: "the middle table" of four the one
        halfway along, "the second", "the last", "the nearest"; else the first."""
        middle = self.groups[g].count // 2 if {"middle", "central", "centre", "center"} & {*words} else 0
        return next((_ORDINALS[w] for w in words if w in _ORDINALS), middle)

    # ---- the parse

    def read(self) -> None:
        toks = self.toks
        mentions, self.places = _find_mentions(toks)
        prev_end = 0
        for m in mentions:
            _read_count(toks, m, prev_end)
            prev_end = m.end
        _refer_forward(toks, mentions)
        #: (mention start, holder mention start): "a tray of bottles" puts the bottles on the tray.
        self.held_of: list[tuple[int, int]] = []
        #: (thing, person): a thing in its holder's hands ("a miner with a pickaxe").
        self.in_hand: list[tuple[int, int]] = []
        #: Groups whose count the text gives by a number or a vague word ("three", "a few").
        self.numbered: set[int] = set()
        #: Uncounted plurals after "their" ("walk their dogs"): one each of their owners.
        self.theirs: set[int] = set()
        #: A "their" group → the several things named before it in its sentence, its owners.
        self.their_owner: dict[int, int] = {}
        #: Starts of living things a holder is full of ("packed with laughing children") and of what a
        #: tray or a cart is "of" ("a cart of apples"): aboard it, no subject of the clause's verb.
        self.aboard: set[int] = set()
        self._mark_contents(mentions)
        _mark_appositions(toks, mentions)
        _mark_members(toks, mentions)
        self.size_of: dict[int, list[tuple[str, float]]] = {}
        for s, e, dim, value in _read_sizes(toks):
            owner = self._size_owner(mentions, s, e)
            if owner is not None:
                self.size_of.setdefault(owner, []).append((dim, value))
        for m in mentions:
            compared = self._compared_size(m.end)
            if compared is not None and m.start not in self.size_of:
                self.size_of[m.start] = [("long", compared)]
        taken = {k for m in mentions for k in range(m.start, m.end)}
        starts = {m.start for m in mentions}
        # "from" places only after a verb one does from where one is ("a heron watches from a rock"),
        # or one done to something too big to hold (below); "pulls a rope from the barrel" names
        # where the rope comes from
        found = [r for r in _find_relations(toks, taken)
                 if (r.kind != "at" or self._names_thing(r.end, starts)) and (r.kind != "covering" or self._covers(r))
                 and (r.kind != "driving" or self._drives(r, mentions))
                 and not self._rung(r, mentions)
                 and not any(s < r.start < e for s, e in self.pictures)]  # (where things stand in a picture)
        self.rel_at = {
            r.start: r for r in found
            if r.kind != "from" or self._verb_before(r.start, self._lookout) or self._from_to(r.end, starts)
            or self._seat_after(r, mentions)
        }  # fmt: skip
        # "carries a tray to the table": where one goes with it is a place one is near
        self.rel_at = {
            k: replace(r, kind="near") if r.kind == "to" else r
            for k, r in self.rel_at.items() if r.kind != "to" or self._destination(r.end, starts)
        }
        self._rows_then_with(mentions)
        #: Mentions the text puts on a wall ("a luggage rack on the wall"): hung, so "above" holds.
        self.on_wall = {m.start for m in mentions if self._on_wall_after(m.end)}
        self._read_looks(mentions)
        self.by_start = {m.start: m for m in mentions if not m.content}
        self.content_at = {k for m in mentions if m.content for k in range(m.start, m.end)}
        self.ends = {m.end for m in mentions if not m.content}
        #: Where an apposition ends, the end of the one it names again ("their coach, a woman").
        self.renamed_end = {m.end: m.renames.end for m in mentions if m.renames is not None}
        #: Words of a noun phrase, its describing words too ("a sleeping dog").
        self.named_at = {k for m in mentions for k in range(m.start - len(m.adjectives), m.end)}
        self.rel_at.update((r.start, r) for r in found if r.kind == "from" and self._acts_from(r.start))
        self.rel_at.update((r.start, r) for r in self._taken_from())
        self.rel_at.update((r.start, r) for r in self._aimed_at())
        sentence_from = 0
        for sentence in _split(toks):
            self._recent_from, sentence_from = sentence_from, len(self.history)
            self._sentence_from = sentence_from
            self._sentence_groups = len(self.groups)
            prev_subject: list[int] = []
            self.doers = []
            pending: list[tuple[str, list[int], tuple[int | None, ...]]] = []
            last_rels: list[tuple[str, list[int]]] = []
            clauses = self._merge_lists([part for cs, ce in sentence for part in self._split_at_and(cs, ce)])
            for ci, (cs, ce) in enumerate(clauses):
                # "and the guide, standing on its bonnet, ...": a subject its participle goes on with
                # ("while the tailor, a thin man ..., measures": a clause of its own, whose verb comes later)
                standalone = ci + 1 < len(clauses) and toks[clauses[ci + 1][0]].text.endswith("ing")
                standalone = standalone or (cs > 0 and toks[cs - 1].text in _CLAUSE_WORDS)
                # a clause after a semicolon opens like a sentence ("...; behind it, three cars wait")
                c = _Clause(first=ci == 0 or toks[cs - 1].text in (";", ":"))
                before = len(self.relations)
                self._clause(c, cs, ce, self._who_after(cs) or prev_subject)
                if c.fronted:
                    srcs = c.main_groups
                    targets_all = {t for _, ts, _, _ in c.fronted for t in ts}
                    srcs = [g for g in srcs if g not in targets_all]
                    if srcs:
                        worked = self._worked_there(c, srcs, before)
                        for kind, targets, each, members in c.fronted:
                            if kind == "flank":  # "On either side of the gate stands a stone lion": one a side
                                self._one_a_side(srcs)
                            if each:  # "beside every table stand two chairs" ("a cake on a stand": a stand each;
                                # "on the blanket in front of each bear is a plate": one blanket still)
                                carried = [*srcs[:1], *self._beneath(kind, srcs[:1], before, targets_all)]
                                self._per_each(list(dict.fromkeys(carried)), targets[0])
                            for t in targets:
                                for one in members:
                                    self._relate(kind, self._beneath(kind, srcs, before, targets_all), t, instance=one)
                                if kind in ("on", "on top"):
                                    self._relate(kind, [g for g in worked if g not in targets_all], t)
                        c.rels = [(kind, targets) for kind, targets, _, _ in c.fronted]
                    else:
                        pending = [(kind, targets, members) for kind, targets, _, members in c.fronted]
                elif pending and c.main_groups:
                    # "Around it, toadstools and crystals glitter": every coordinated subject
                    subjects = c.subjects or c.main_groups[:1]
                    worked = self._worked_there(c, subjects, before)
                    for kind, targets, members in pending:
                        for t in targets:
                            for one in members:
                                self._relate(kind, self._beneath(kind, subjects, before), t, instance=one)
                            if kind in ("on", "on top"):
                                self._relate(kind, [g for g in worked if g != t], t)
                    pending = []
                elif not c.produced and c.groups and last_rels and not standalone and self._is_list(cs, ce, strict=True):
                    # "On the desk there is a lamp, a laptop and a mug": the list shares the relation
                    # (not what a thing is full of: "..., each packed with children")
                    listed = [g for g in c.groups if all(self.by_start[s].group != g for s in self.aboard if s in self.by_start)]
                    for kind, targets in last_rels:
                        for t in targets:
                            self._relate(kind, listed, t)
                    c.rels = last_rels
                self._where(cs, c, before)
                self._take_wing(c, cs, ce, before)
                self._held_raised(c, cs, ce, prev_subject)
                last_rels = c.rels or last_rels
                # ("The coxswain, radio in hand, waits ...": what is in the subject's hand is no subject)
                held = {thing for thing, holder in [*self.in_hand, *self.carried] if holder in prev_subject}
                if c.main_groups and not set(c.main_groups) <= held:
                    prev_subject = c.main_groups[:1] if not c.main else c.main
                if len(c.subjects) > 1:
                    self.together = list(c.subjects)
                about = c.subjects or c.main_groups  # "In the centre stands a workbench; on it ..."
                if about:
                    placed_by = [r[2] for r in self.relations[before:] if r[1] in about]
                    self.topic = list(dict.fromkeys([*about, *reversed(placed_by)]))
                    self.doers = [g for g in about if self._living(g)]
                self.history.extend(c.groups)
                self.acted_on = [t for _, t in c.deeds if not self._living(t)]
        by_start = {m.start: m for m in mentions}
        held = [("on", by_start[s].group, by_start[h].group, None) for s, h in self.held_of
                if by_start[s].group >= 0 and by_start[h].group >= 0]  # fmt: skip
        self.relations[:0] = held  # before any other support the list gave them
        for stand, things in self.one_each.items():
            self.groups[stand].count = self.groups[things].count
        #: A plural group → the groups of the members a colon lists (:func:`_mark_members`).
        self.listed = {
            m.group: [x.group for x in m.members] for m in mentions
            if m.members and m.group >= 0 and all(x.group >= 0 for x in m.members)
        }  # fmt: skip
        self._aboard_their_vehicle(mentions)
        self._left_by_owner(mentions)
        self._one_per_holder()
        self._seated_rows(mentions)

    def _seated_rows(self, mentions: list[_Mention]) -> None:
        """"Twelve jurors sit in two rows of chairs": the rows are the seats', one seat a sitter
        when a seat holds one (however many the quantity word made: "in three rows of benches"
        keeps three benches), the sitters on them."""
        for of, sitters in self.rows_of.items():
            seat = next((m for m in mentions if of < m.start <= of + 3 and m.group >= 0), None)
            if seat is None or self.catalogue[seat.category].shape not in _SEATS:
                continue
            g = seat.group
            if self.groups[g].size[0] < _ONE_SEAT_WIDTH:
                self.groups[g].count = sum(self.groups[h].count for h in sitters)
            self.formations[g] = self.formations.get(sitters[0], "rows")
            if sitters[0] in self.lines:
                self.lines[g] = self.lines[sitters[0]]
            for h in sitters:
                self.relations.append(("on", h, g, None))

    def _worked_there(self, c: _Clause, subjects: list[int], since: int) -> list[int]:
        """What the living subjects of a clause after a fronted surface phrase act on, which
        nothing else places: up there with them ("On a raised platform, a robot works two
        turntables"; "On the stage, a drummer plays a drum kit")."""
        if not subjects or not all(self._living(g) for g in subjects):
            return []
        placed = {r[1] for r in self.relations[since:]}
        acted = {t for _, t in c.deeds}
        return [g for g in c.groups if g not in subjects and g not in placed and g in acted and not self._living(g)]

    def _who_after(self, cs: int) -> list[int]:
        """", who sits in the front row" right after a living thing: that one is the clause's
        subject ("a boy asleep on the lap of his father, who sits ..."), not the sentence's."""
        if cs < 1 or self.toks[cs].text != "who" or self.toks[cs - 1].text != ",":
            return []
        named = next((m for m in self.by_start.values() if m.end == cs - 1), None)
        return [named.group] if named is not None and named.group >= 0 and self._living(named.group) else []

    def _aboard_their_vehicle(self, mentions) -> None:
        """"A train waits at the platform, its driver leaning out": a person a vehicle's "its"
        names is its crew, on it (the latest vehicle named before in the sentence), unless the text
        puts them somewhere ("its passengers queue at a kiosk")."""
        placed = {r[1] for r in self.relations if r[0] != "face to"}
        # ("a tractor towing a trailer, its driver leaning out": the tractor's)
        puller = {load: head for head, load in self.towed.items()}
        for k, m in enumerate(mentions):
            g = m.group
            if m.content or g < 0 or g in placed or m.start == 0 or self.toks[m.start - 1].text != "its":
                continue
            if not self._person_at(g):
                continue
            for before in reversed(mentions[:k]):
                if any(t.text in (".", ";", "!", "?") for t in self.toks[before.end : m.start]):
                    break
                if before.group >= 0 and not before.content and self._carrier(before.group, ("vehicles",)):
                    self.relations.append(("on", g, puller.get(before.group, before.group), None))
                    break

    def _one_per_holder(self) -> None:
        """"Three miners with pickaxes", "a mechanic with a wheel gun kneels beside each car": a
        thing in hand comes once per holder, unless the text counts it ("two men with one ladder")
        or it is too big for one to hold ("two rescuers carry a stretcher" carry one); things the
        text gives in the plural, uncounted, come one each whatever their size ("two reapers with
        scythes"), and so do those of "their" by their owners ("two girls walk their ponies")."""
        theirs = [(g, h) for _, a, b, _ in self.relations for g, h in ((a, b), (b, a)) if g in self.theirs]
        theirs = [(g, h) for g, h in theirs if self._living(h) and h not in self.theirs]
        # ("a dozen spacesuits hang on racks, their helmets on a shelf": one each, placed elsewhere)
        theirs += [(g, h) for g, h in self.their_owner.items() if g not in {t for t, _ in theirs} and h not in self.theirs]
        for g, h in [*self.in_hand, *theirs]:
            uncounted = g not in self.numbered and self.groups[g].count == UNCOUNTED
            if g not in self.numbered and self.groups[h].count > 1 and (self._handheld(g) or uncounted):
                self.groups[g].count = self.groups[h].count

    def _held_raised(self, c: _Clause, cs: int, ce: int, holders: list[int]) -> None:
        """A clause of a bare thing and a participle alone after people ("six photographers crouch
        at the foot of the catwalk, cameras raised", "..., swords drawn"): what they hold, one each."""
        words = [t.text for t in self.toks[cs:ce]]
        m = self.by_start.get(cs)
        if len(c.groups) != 1 or m is None or m.end != ce - 1 or m.definite or not holders:
            return
        raised = _participle(words[-1]) and not words[-1].endswith("ing")
        if not raised or not all(self._person_at(h) for h in holders):
            return
        g = c.groups[0]
        if self._handheld(g) and not any(r[1] == g for r in self.relations):
            self._relate("on", [g], holders[0])
            self.in_hand.append((g, holders[0]))
            self.carried.add((g, holders[0]))

    def _take_wing(self, c: _Clause, cs: int, ce: int, since: int) -> None:
        """Birds and winged beasts the clause has flying ("gulls circle overhead", "a dragon soars
        over the valley") are in the air: hung, so the arranger keeps them up there, unless the
        clause puts them on something ("flies to its perch": it lands)."""
        words = [t.text for t in self.toks[cs:ce]]
        if not any(w in _FLIGHT for w in words) or any(w in _LANDING for w in words):
            return
        for g in c.main_groups:
            on = any(r[0] == "on" and r[1] == g for r in self.relations[since:])
            if self._winged(g) and not on:
                self.groups[g].rests = "hanging"

    def _winged(self, g: int) -> bool:
        """A bird, or a beast the catalogue draws four-legged that has wings (a dragon, a griffin)."""
        group = self.groups[g]
        return group.category == "bird" or any(w in _WINGED_BEASTS for w in group.name.lower().split())

    def _where(self, cs: int, c: _Clause, since: int) -> None:
        """"... next to the ticket booth, where an attendant waits": what a where-clause names and
        places nowhere else is near the place before "where" (the last thing named before it); on
        it when that is a platform the living can stand on (a jetty, a stage)."""
        if cs < 1 or self.toks[cs - 1].text != "where":
            return
        # the subjects up to their verb ("a mother pushing a pram": the pram is hers)
        verb = next(
            (k for k in range(cs, len(self.toks)) if k not in self.by_start and k not in self.content_at
             and (_is_verb(self.toks[k].text) or self.toks[k].text.endswith("ing"))),
            len(self.toks),
        )  # fmt: skip
        named = {m.group for m in self.by_start.values() if m.start < verb}
        subjects = [g for g in c.subjects or c.main_groups[:1] if g in named]
        if not subjects:
            return
        placed = [r[0] for r in self.relations[since:] if r[1] in subjects]
        # the noun right before, else, for people, the last thing named shortly before ("a barrier
        # guides the queue, where two men wait": the queue is no thing, the barrier is)
        before = [m for m in self.by_start.values() if cs - 10 <= m.start and m.end < cs and m.group >= 0]
        last = max(before, key=lambda m: m.end) if before else None
        gap = [t.text for t in self.toks[last.end : cs - 1]] if last is not None else []
        people = all(self._living(g) for g in subjects)
        place = last.group if last is not None and (people or all(w == "," for w in gap)) else None
        if place is None or place in subjects or not people and self._laid_on(subjects, place, since):
            return
        # ("the lily pond, where a white swan glides": on the water)
        afloat = self.groups[place].category == "pond" and any(
            _verb_stem(t.text, _AFLOAT_VERBS) for t in self.toks[cs : min(verb + 1, len(self.toks))]
        )
        if afloat and not placed:
            self._relate("on", subjects, place)
        elif people and self._platform(place, subjects[0]):
            # "a little wooden jetty, where a boy feeds the ducks": on the platform, whatever he does there
            if not any(kind in ("on", "above") for kind in placed):
                self._relate("on", subjects, place)
        elif not placed:
            self._relate("near", subjects, place)
        elif set(placed) == {"near"} and people and self.catalogue[self.groups[place].category].support:
            # "the reception desk, where a nurse types on a computer": she is at the desk, and what
            # she works at is on it
            worked = [r[2] for r in self.relations[since:] if r[1] in subjects and not self._living(r[2])]
            stands = {r[1] for r in self.relations if r[0] in ("on", "above")}
            loose = [g for g in worked if g not in stands and self.groups[g].rests == "surface"]
            if loose:
                self._relate("on", loose, place)
                self._relate("near", subjects, place)

    def _laid_on(self, subjects: list[int], place: int, since: int) -> bool:
        """"A long workbench, where a pair of shears lies beside a ball of twine": small things a
        where-clause names lie on the place when it has a top, and so do the small things they lie
        by; whether any did."""
        if not self.catalogue[self.groups[place].category].support:
            return False
        if any(r[0] in ("on", "above") and r[1] in subjects for r in self.relations[since:]):
            return False
        by = [r[2] for r in self.relations[since:] if r[1] in subjects and r[0] in _GROUND_KINDS]
        small = [g for g in (*subjects, *by) if self.groups[g].rests == "surface"]
        self._relate("on", small, place)
        return bool(small)

    def _on_wall_after(self, end: int) -> bool:
        """"... on the wall", "mounted on the back wall", "hangs on a wall" right after a noun."""
        words = [t.text for t in self.toks[end : end + 6]]
        k = 1 if words[:1] and words[0] in _HANG_VERBS else 0
        if words[k : k + 1] != ["on"]:
            return False
        for w in words[k + 1 : k + 5]:
            if w in ("wall", "walls"):
                return True
            if not w[:1].isalpha():
                return False
        return False

    def _beneath(
        self, kind: str, subjects: list[int], since: int, landmarks: set[int] | frozenset[int] = frozenset()
    ) -> list[int]:
        """What a fronted phrase of the ground ("Behind the chair, ...") places: each subject,
        or what the subject floats above or stands on in its own clause ("a hologram floats
        above a round table": the table is behind the chair). A person stays what it places: "Behind
        it, a sergeant on a swivel chair types" puts the sergeant behind, the chair comes along.
        A fronted host carries what its subject sits or stands on ("On the desk, a kettle steams on
        a camping stove": the stove is on the desk; "On the counter, a cat sleeps in a basket").
        A host among the fronted ``landmarks`` stays put ("On the blanket in front of each bear is a
        plate": the plate is in front of the bear, the blanket under them all)."""
        if kind in ("on", "on top"):
            host = {r[1]: r[2] for r in self.relations[since:] if r[0] == "on" and r[2] not in subjects}
            return list(dict.fromkeys(host.get(g, g) for g in subjects))
        if kind not in _GROUND_KINDS:
            return subjects
        under = {
            r[1]: r[2] for r in self.relations[since:]
            if r[0] in ("on", "above") and r[2] not in subjects and not self._living(r[1]) and r[2] not in landmarks
        }  # fmt: skip
        return list(dict.fromkeys(under.get(g, g) for g in subjects))

    def _rows_then_with(self, mentions: list[_Mention]) -> None:
        """"Two food trucks are parked side by side with three picnic tables in front of them":
        after several things, "side by side" is their row and the "with" opens their with-part;
        after one thing ("a bench side by side with a table") it is beside the next."""
        for start, rel in list(self.rel_at.items()):
            if [t.text for t in self.toks[start : rel.end]] != ["side", "by", "side", "with"]:
                continue
            before = [m for m in mentions if m.end <= start and start - m.end <= 5]
            if before and _is_plural(self.toks, before[-1]):
                self.rel_at[start] = _Rel("row", start, start + 3)

    def _read_looks(self, mentions: list[_Mention]) -> None:
        """Each noun's look written after it; a catalogue noun inside a "made of" look is its
        material, not an object ("a table made of glass" holds no drinking glass)."""
        nouns = {m.start for m in mentions}
        for m in mentions:
            m.post, end = _post_description(self.toks, m.end, nouns, set(self.rel_at))
            if not m.post and self.catalogue[m.category].shape == "figure":
                m.post = worn_description(self.toks, m.end)
            for other in mentions:
                other.content = other.content or m.end < other.start < end

    def _compared_size(self, end: int) -> float | None:
        """The longest side of what a thing is said to be the size of, right after it ("a dragon
        the size of a cat", "a snail as big as a football"): that of the compared thing's category
        or open-vocabulary guess; None when no such comparison follows."""
        words = [t.text for t in self.toks[end : end + 4]]
        if words[:3] == ["the", "size", "of"]:
            k = end + 3
        elif len(words) > 2 and words[0] == "as" and words[1] in _COMPARED and words[2] == "as":
            k = end + 3
        else:
            return None
        while k < len(self.toks) and self.toks[k].text in _DETERMINERS:
            k += 1
        if k >= len(self.toks) or not self.toks[k].text[:1].isalpha():
            return None
        category = None
        j = k
        while j < min(k + 3, len(self.toks)) and self.toks[j].text[:1].isalpha() and self.toks[j].text not in _STOP:
            phrase = tuple(singular(t.text) for t in self.toks[k : j + 1])
            # ("a dinner plate": the phrase's last word names it; "a pony sleeps": its verb names nothing)
            category = match_phrase(phrase) or match_phrase(phrase[-1:]) or category
            j += 1
        if category is None:
            guess = load_vocabulary().guess(singular(self.toks[k].text))
            return None if guess.category == GENERIC else max(guess.size[:2])
        return max(self.catalogue[category].size[:2])

    def _size_owner(self, mentions: list[_Mention], s: int, e: int) -> int | None:
        after = [m for m in mentions if m.start >= e and m.start - e <= 4]
        if after:
            return after[0].start
        before = [m for m in mentions if m.end <= s and s - m.end <= 8]
        return before[-1].start if before else None

    def _size(self, m: _Mention) -> tuple[float, float, float]:
        return m.guess.size if m.guess is not None else self.catalogue[m.category].size

    def _split_at_and(self, cs: int, ce: int) -> list[tuple[int, int]]:
        """A clause cut where "and" opens a new subject with its own verb after a subject that had
        one: "a barrel stands by the door and a cat sits on the table" is two clauses, as with a
        comma before "and" (not "a barrel and a cat sit on it", nor "between the door and a chest")."""
        toks = self.toks
        for k in range(cs + 1, ce - 2):
            if toks[k].text != "and":
                continue
            j = k + 1
            while j < ce and j not in self.by_start and (toks[j].text in _DETERMINERS or toks[j].text in _NUMBERS
                                                         or load_vocabulary().is_adjective(toks[j].text)):
                j += 1
            m = self.by_start.get(j)
            if m is None or m.end >= ce or not self._finite_at(m.end):
                continue
            if any(e in self.ends and self._finite_at(e) for e in range(cs + 1, k)):
                return [(cs, k), *self._split_at_and(k, ce)]
        return [(cs, ce)]

    def _merge_lists(self, clauses: list[tuple[int, int]]) -> list[tuple[int, int]]:
        """Join a clause that only lists objects to the next one when that one places them
        ("with a laptop, a mug and a lamp on it")."""
        out: list[tuple[int, int]] = []
        for cs, ce in clauses:
            places = any(k in self.rel_at for k in range(cs, ce))
            # "a counter with combs, scissors and a jar runs beneath the mirror": the list goes on
            goes_on = bool(out) and self._open_with(*out[-1]) and cs not in self.rel_at
            # ("with a clipboard, while her son carries a pail": "while" opens a clause of its own;
            # "with two chairs, where a man sits" goes on about the with-part)
            goes_on = goes_on and self.toks[cs].text not in ("and", "or", "but", "then", "so")
            goes_on = goes_on and self.toks[cs - 1].text not in _CLAUSE_WORDS - {"where"}
            # a bare list takes the next placing when "and" closes it ("a lamp, a laptop and a mug on
            # the desk"); a list of commas only is a list of separate things ("a desk, an armchair, a
            # globe on the desk": only the globe is on the desk)
            first_rel = min((k for k in range(cs, ce) if k in self.rel_at), default=ce)
            # (an "and" opening the placing clause starts a clause of its own: "..., and three
            # aliens wait in a line")
            joined = bool(out) and any(
                self.toks[k].text in ("and", "or") for k in (*range(out[-1][0] + 1, out[-1][1]), *range(cs + 1, first_rel))
            )
            # "an oil lamp and a teapot, and a clockwork automaton waits beside it": a list that
            # "and" already closed ends there; the next "and" opens a clause of its own
            closed = bool(out) and self.toks[cs].text in ("and", "or") and any(
                self.toks[k].text in ("and", "or") for k in range(out[-1][0] + 1, out[-1][1])
            )
            if goes_on or (places and out and joined and not closed and self._is_list(*out[-1], strict=True)):
                out[-1] = (out[-1][0], ce)
                # "a baker, a cook, a smith and a miller sit at a table": every item before the last
                # comma's belongs to the same list
                while not goes_on and len(out) > 1 and self._is_list(*out[-2], strict=True) and all(
                    t.text == "," for t in self.toks[out[-2][1] : out[-1][0]]
                ):
                    out[-2:] = [(out[-2][0], out[-1][1])]
                continue
            out.append((cs, ce))
        return out

    def _open_with(self, cs: int, ce: int) -> bool:
        """The clause ends inside the "with" part of a noun before it: nothing placed after."""
        toks = self.toks
        last = max((k for k in range(cs + 1, ce) if toks[k].text == "with" or toks[k].text in _HOLD), default=None)
        if last is not None and last <= cs + 1 and not any(k in self.rel_at for k in range(last, ce)):
            return True  # "..., cluttered with a microscope, an oil lamp and a teapot": the noun before's list
        if last is None or not any(cs <= k and m.end <= last for k, m in self.by_start.items()):
            return False  # "a market square with three stalls, ...": the place's list, not a thing's
        return not any(k in self.rel_at for k in range(last, ce))

    def _is_list(self, cs: int, ce: int, strict: bool = False) -> bool:
        """Only noun phrases joined by "and": no relation phrase, no verb."""
        if any(k in self.rel_at for k in range(cs, ce)):
            return False
        mentions = [m for k, m in self.by_start.items() if cs <= k < ce]
        end = max((m.end for m in mentions), default=ce + 1)
        contents = range(end, ce) if end < ce and self.toks[end].text == "of" and all(
            t.text[:1].isalpha() and t.text not in _STOP for t in self.toks[end + 1 : ce]
        ) else range(0)  # ("a hammer, a chisel and a box of nails": what the last one holds)
        if not mentions or end != ce and not contents:
            return False
        if not strict:
            return True
        allowed: set[int] = set(contents)
        for m in mentions:
            allowed.update(range(m.start - len(m.adjectives) - 2, m.end))
        for k in range(cs, ce):
            w = self.toks[k].text
            if w in _HOLD:  # "a counter holds a till, and clocks stand behind it": two clauses
                return False
            # ", feeding a goat", ", chasing a puppy": a participle with its object, a clause of its own
            # (not "a sleeping dog", whose participle is the noun's own word)
            nxt = k + 1 < ce and (self.toks[k + 1].text in _DETERMINERS or k + 1 in self.by_start)
            if w.endswith("ing") and k not in self.named_at and nxt:
                return False
            if k in allowed or w in ("and", "or", "with") or w in _DETERMINERS or w in _NUMBERS:
                continue
            return False
        return True

    def _clause(self, c: _Clause, cs: int, ce: int, prev_subject: list[int]) -> None:
        toks = self.toks
        k = cs
        while k < ce and toks[k].text in ("and", "or", "but", "then", "also", "so", "there", "is", "are"):
            k += 1
        one_a_side = k + 1 < ce and toks[k].text == "one" and k + 1 in self.rel_at
        # (not "..., one of them rocking a baby"; nor "one of them has turned its head": no place of its
        # own; but "one of them standing on a ladder" is up there)
        doing = k + 3 < ce and toks[k + 3].text.endswith("ing") and not self._posture(toks[k + 3].text)
        placed = k + 3 < ce and not doing and any(
            j in self.rel_at and self.rel_at[j].kind not in ("face to", "no relation") for j in range(k + 3, ce)
        )
        # (of the several the clause before named: "two engineers bolt a wind turbine together, one of them ...")
        several = [g for g in dict.fromkeys([*prev_subject, *self.doers]) if self.groups[g].count > 1]
        # ("two dogs play; one chases a ball, the other sleeps under a tree": one of them each)
        lone = k < ce and (
            toks[k].text == "one" and _one_doing(toks, k + 1)
            or [t.text for t in toks[k : k + 2]] == ["the", "other"] and _one_doing(toks, k + 2)
        )
        placed = placed or lone and any(
            j in self.rel_at and self.rel_at[j].kind not in ("face to", "no relation") for j in range(k + 2, ce)
        )
        if lone:  # (the several named last, of the sentence before too)
            several = next(([g] for g in reversed(self.history) if self.groups[g].count > 1 and self._living(g)), [])
        if ([t.text for t in toks[k + 1 : k + 3]] == ["of", "them"] or lone) and len(several) == 1 and placed:
            # "ten penguins huddle on the ice, and three of them dive from a floe": those three, a
            # group of their own split off the ten (the rest stay where the ten were put)
            g, n = several[0], 1 if toks[k].text == "one" or lone else _NUMBERS.get(toks[k].text, 0)
            if n and self.groups[g].count > n:
                prev_subject = [self._copy_group(g)]
                self.groups[g].count -= n
                self.groups[prev_subject[0]].count = n
                self.numbered.add(prev_subject[0])
                if lone:
                    c.main = list(prev_subject)  # (no noun names it: the one split off is the subject)
        if [t.text for t in toks[k : k + 3]] == ["one", "of", "them"]:
            c.one_of = list(prev_subject)
        if one_a_side and self.rel_at[k + 1].kind.startswith("flank"):
            # "two speakers on the desk, one on each side of the console": the speakers flank it
            plural = [g for g in [*self.history, *c.groups] if self.groups[g].count > 1]
            if plural:
                c.main = plural[-1:]
                k += 1
        j = k
        # an adverb that opens a relation phrase is part of it ("Far from the house, ...")
        while j < ce and j not in self.rel_at and (toks[j].text in _DETERMINERS or toks[j].text in _ADVERBS):
            j += 1
        starts_with_rel = j in self.rel_at
        # ", sipping coffee from a cup": a clause that opens with a participle is the subject's before
        participial = not c.first and k < ce and toks[k].text.endswith("ing") and k not in self.by_start
        participle = k if participial and k not in self.rel_at else None
        vehicle_tows = k in self.rel_at and self.rel_at[k].kind == "towing"  # ("drives a quad bike, towing a trailer")
        if participial and self.doers and not vehicle_tows:
            prev_subject = list(self.doers)  # "a keeper feeds the tiger, standing on a platform": the keeper
        # "the baker, in a white apron, pushes a tray into the oven": a clause that opens with a
        # verb goes on about the living subject before (what it acts on is its object)
        if not c.first and not participial and k == cs and k < ce and k not in self.by_start and k not in self.rel_at:
            if _is_verb(toks[k].text) and prev_subject and all(self._living(g) for g in prev_subject):
                c.main = list(prev_subject)
        # (after "they" a verb has no -s: "They gather around her feet")
        verb = k + 1 < ce and (_is_verb(toks[k + 1].text) or toks[k].text == "they" and toks[k + 1].text not in _STOP)
        if k + 1 < ce and toks[k].text in ("he", "she", "they", "it") and k + 1 not in self.by_start and (
            k + 1 in self.rel_at or (verb and toks[k + 1].text.isalpha() and toks[k + 1].text not in _COPULAS)
        ):  # "She sits on a bench", "They wait by the gate": whom the text went on about
            named = self._subject_pronoun(toks[k].text, [*prev_subject, *self.topic, *reversed(self.history)])
            if named:
                c.main, k = named, k + 1
        # (", is tied to a post" after an apposition goes on about the noun before it: no phrase of its own)
        copula = toks[cs].text in _COPULAS
        c.finite = copula  # (its verb: "... is tethered to a man sitting on a stool": the man sits)
        c.opens = c.first or (starts_with_rel and k > cs and not copula and self._subject_after(self.rel_at[j].end, ce))
        c.unknown_subject = j > k and toks[k].text in ("a", "an", "the") and j not in self.by_start and not starts_with_rel
        # ("..., and incense burns in a bronze bowl": a bare word no thing, then its verb)
        c.unknown_subject = c.unknown_subject or (
            not c.first and k + 1 < ce and k not in self.by_start and k not in self.content_at and toks[k].text[:1].isalpha()
            and toks[k].text not in _STOP and k + 1 not in self.by_start and _is_verb(toks[k + 1].text)
        )  # fmt: skip
        last_event_end = cs
        phrase_end = -1  # where the last relation phrase and its target end
        while k < ce:
            w = toks[k].text
            if not c.first and w in ("he", "she") and (k == cs or toks[k - 1].text == ",") and k + 1 < ce and (
                toks[k + 1].text.endswith("ing") or k + 1 in self.rel_at
            ):  # "a wizard and a witch face each other, he riding a tortoise, she on a carpet": an
                # absolute phrase about the one the pronoun names
                self._close_with(c)
                c.head, c.wsub = None, []
                people = [*c.main, *prev_subject, *self.topic, *self.history[self._sentence_from :]]
                c.main = self._named_by(w, people) or c.main
                k = last_event_end = k + 1
                continue
            lead = _each_lead(toks, k, ce) if k not in self.by_start else k
            unit = _QUANTITY.get(toks[k + 1].text, 1) if lead > k and toks[k + 1].text in _MEMBER_UNITS else 1
            if lead > k:  # "every one of them with a spade": as "each with a spade"
                w, k = "each", lead
            nxt = toks[k + 1].text if k + 1 < ce else ""
            each_part = nxt in ("with", "have", "has", "holding", "holds", "carrying", "bearing")
            # "each surrounded by two chairs", "each lit by a lantern": the passive ones come once per member too
            each_passive = k + 1 in self.rel_at and self.rel_at[k + 1].kind in ("flanked by", "surrounded by", "near by")
            each_hold = (nxt, toks[k + 2].text if k + 2 < ce else "") in _HOLD_PAIRS
            # "four pilots sit at the console, each in a leather seat": a seat apiece
            each_seat = k + 1 in self.rel_at and self.rel_at[k + 1].kind in ("in", "on", "at")
            # ("each pair pulling a plough": a plough a pair, pulled)
            towing = k + 1 in self.rel_at and self.rel_at[k + 1].kind == "towing"
            each_deed = _participle(nxt) and (k + 1 not in self.rel_at or towing) and k + 1 not in self.by_start
            doers = c.subjects or self.doers
            singles = [g for g in doers if self.groups[g].count == 1 and self._living(g)]
            if w == "each" and each_part and len(singles) > 1 and singles == doers:
                c.each_of = singles  # "a dwarf and an elf sit at a table, each with a tankard"
                k += 1
                continue
            if w == "each" and (each_part or each_passive or each_hold or each_seat or each_deed):
                plural = [g for g in [*self.history, *c.groups] if self.groups[g].count > 1]
                # "four astronauts sit on stools around a table, each holding a pouch": the holders
                holding = nxt in _HOLD or nxt in _HAND_VERBS or nxt in _USE_VERBS
                people = [
                    g for g in [*c.subjects, *prev_subject, *self.topic] if self.groups[g].count > 1 and self._living(g)
                ]
                # ("five customers sit on stools, each with a bowl in front of them": the sitters; "at
                # tables, each with a stack of files on it": the tables)
                said = {t.text for t in toks[k:ce]}
                own = bool(each_part and plural and people) and not self._living(plural[-1])
                own = own and people[0] in (c.subjects or c.main_groups[:1] or prev_subject[:1])
                # (or when the things are the seats they sit on: "six regulars sit on stools, each with a glass")
                seats = self._carrier(plural[-1], ("seats",)) if plural else False
                own = own and (bool(said & {"them", "their", "him", "her", "his"}) or seats) and not said & {"it", "its"}
                if (holding or each_deed or own) and people:
                    plural = people[:1]
                elif holding and (carriers := [g for g in [*c.subjects, *prev_subject] if self.groups[g].count > 1]):
                    plural = carriers[:1]  # "four cargo drones hover above the wrecks, each carrying a crate"
                if plural:
                    c.each, c.each_deed, c.each_unit = plural[-1], each_deed and bool(people), unit
                k += 1
                continue
            members = c.main or list(prev_subject)
            sides = _every_side(toks, k, ce)
            if sides:  # "benches stand on every side of the pond": one a side, a row along each
                # ("a table with a lamp at each end": the with-thing)
                placed = c.wsub if c.head is not None and c.wsub else members
                self._one_a_side(placed, sides, row=toks[k - 1].text == "along")
            if w == "each" and k + 1 in self.rel_at and members and self.groups[members[-1]].count > 1:
                c.each_own = members[-1]  # "two helmsmen sit ..., each in a steel seat": a seat each
                k += 1
                continue
            # ", holding a lamp": the subject before
            holder = c.main or (self.doers if participial else []) or list(prev_subject)
            # ("ducks gather around a boy holding a loaf": the person right before the participle)
            bearer = self._bearer_before(k)
            holder = [bearer] if bearer is not None else holder
            # (a hand verb that opens a relation phrase is no holding: "waves at a passing van")
            # (an animal has in hand what it plays with or eats: "a bear bangs a spoon")
            hand = k not in self.rel_at and bool(holder) and (
                (w in _HAND_VERBS and self._person_at(holder[-1]))
                or (w in _USE_VERBS and self._living(holder[-1]) and self._used_object(k, ce) is not None)
                # ("a vendor sells balloons": a person sells what they can hold from the hand)
                or (w in _WARES_VERBS and self._person_at(holder[-1]) and self._used_object(k, ce) is not None)
                or (self._person_at(holder[-1]) and self._used_at(k, ce))
            )
            # "sipping coffee from a paper cup", "practises with five clubs": in the doer's hand
            doer = (self.doers or list(prev_subject)) if participial else (c.subjects or holder)
            tool_end = self._tool_after(k, ce) if doer and self._person_at(doer[-1]) else None
            if tool_end is not None:
                holder, hand = doer, True
            # (the givers are the living subjects: "a postman has parked his bike and hands her a letter")
            givers = [g for g in holder if self._living(g)] if w in _GIVE_VERBS else []
            given = self._given_to(c, k, ce, givers, prev_subject) if givers else None
            if given is not None:
                c.deeds.append((givers, given[0]))  # "a robot hands one of them a toolbox": by them
                holder, hand, tool_end = givers, True, given[1]
            # ("has fallen asleep", "have gathered": a tense, nothing held)
            owns = w in ("has", "have") and not (_participle(nxt) or nxt in ("been", "gone", "come", "grown"))
            # ("three grey bears sit": a noun the reader found, not the verb "bears")
            # ("a gantry crane stands between them, lifting a rusty engine": on its hook; "swings a
            # trunk over them": where the phrase after it puts it)
            hoisted = w in _HOIST_VERBS and k not in self.by_start and bool(holder) and self._hoist(holder[-1])
            hoisted = hoisted and not any(j in self.rel_at for j in range(k + 1, ce))
            held_by_verb = (w in _HOLD and k not in self.by_start) or (w, nxt) in _HOLD_PAIRS or hoisted
            if w == "with" or held_by_verb or owns or hand:
                # ("with a workbench beside it covered in spanners": the workbench is covered, not what it is by)
                laden = (w, nxt) in _HOLD_PAIRS and toks[k - 1].text in ("it", "them")
                if (w in _HOLD and w.endswith("ing") or laden) and c.head is not None and c.wsub:
                    # "with a small table beside them holding a teapot": the with-thing holds it (what
                    # came with the head before it stays the head's: "a dwarf with an axe and a wizard holding a staff")
                    # (", each holding a camera" after "with six tourists aboard": they stay aboard)
                    holder = c.wsub[-1:]
                    c.wsub = c.wsub if c.each in holder else c.wsub[:-1]
                    self._close_with(c)
                    c.head, c.wsub, c.hold, c.expect_new = holder, [], True, False
                    k += 2 if laden else 1
                    last_event_end = k
                    continue
                self._close_with(c)  # "holds a horseshoe with tongs": the horseshoe is held before the tongs come
                own = holder if tool_end is not None or bearer is not None else (c.main or list(prev_subject))
                c.head = [c.each] if c.each is not None else list(c.each_of) or own
                mine = nxt in _PERSON_POSSESSIVES  # "by the flag with his mallet": his, not the flag's
                after_target = bool(c.last_target) and c.last_target_end == k
                between = c.last_kind == "between"
                # ("a sheep waits by the gate with its shepherd": a living thing's companion is its own)
                fellow = self._next_mention(k + 1, ce)
                fellow = fellow is not None and self._lives(fellow.category) and all(self._living(h) for h in c.head)
                c.company = fellow and w == "with" and self._after_verb(k, worn=True)
                # ("a guard stands at the gate with a spear": nothing stands on a gate, the spear is his)
                tool = self._hand_object(k + 1, ce, tool=True) if w == "with" else None
                # ("stirring a pot on it with a long spoon": the spoon is the stirrer's, not the pot's)
                workers = [g for g in (self.doers or prev_subject) if self._person_at(g)]
                if tool is not None and workers and c.head and not any(self._living(h) for h in c.head) and (
                    self._verb_before(k, self._work_verb) and not c.wsub
                ):
                    c.head = workers
                # ("with an inkwell and three quills on it": the phrase after the list places them all)
                listed = self._list_end(tool.end, ce) if tool is not None else k
                # (nor at a table, "sits at a table with a teapot", unless the clause's verb is work
                # done with it: "two pirates dig beside the chest with shovels")
                armed = tool is not None and not self._placed_by_pronoun(listed, ce) and all(
                    self._person_at(h) for h in c.head
                ) and (
                    not any(self.catalogue[self.groups[t].category].support for t in c.last_target)
                    or self._verb_before(k, self._work_verb)
                )
                # ("walks behind them with a broom": what a person works with is in hand, unless a
                # phrase of its own places it: "with a bible open on a lectern")
                if armed and (after_target or not self._placed_after(listed, ce)):
                    hand = True
                if after_target and not fellow and not armed and (
                    (w == "with" and not mine and (self._animate(*c.head) or between)) or (w, nxt) in _HOLD_PAIRS
                ):  # "a baker stands behind the counter with a tray on it", "between a drum and a shelf with
                    # cups on it", "sits at a desk covered in monitors": the target's
                    c.head = list(c.last_target[-1:] if between else c.last_target)
                if after_target and armed and self._by_agent(k) and all(self._person_at(t) for t in c.last_target):
                    c.head = list(c.last_target)  # "watched by a trainer with a rod": the trainer's rod
                # "two boys lead a donkey laden with sacks": the load is the noun's right before it
                laden = [m.group for m in self.by_start.values() if m.end == k and m.group is not None]
                if (w, nxt) in _HOLD_PAIRS and laden and laden[0] in c.groups:
                    c.head = laden[:1]
                c.wsub, c.expect_new = [], False
                before = [t.text for t in toks[max(0, k - 2) : k]]
                other_one = before in (["the", "other"], ["and", "another"])
                c.single = "one" if before[-1:] == ["one"] else "other" if other_one else None
                # "pickers fill baskets with apples": what the verb fills takes what it is filled with
                filled = w == "with" and c.deeds and c.deed_end == k and _verb_stem(self._acting_verb(k) or "", _FILL_VERBS)
                if filled:
                    c.head = [c.deeds[-1][1]]
                # "with his putter": a possessive after "with" says the person has it in hand
                hand = hand or (w == "with" and mine and all(self._person_at(h) for h in c.head))
                c.hold, c.hand = w in _HOLD or (w, nxt) in _HOLD_PAIRS or hand or bool(filled) or hoisted, hand
                # ("two men haul a trunk": one thing a verb of several has in hand is theirs together)
                # (what is given comes after whom it is given to: "one offering it a mackerel")
                thing_at = k if given is None else given[1] - 1
                c.shared = w in _SHARE_VERBS or (w != "with" and c.each is None and self._one_thing_after(thing_at, ce))
                # ("typing on a laptop" at a desk: on the desk, as what is shared at a table)
                typing = any(_verb_stem(t.text, {"type"}) for t in toks[max(0, k - 1) : k + 1])
                c.sharing = w in _SHARE_VERBS or typing
                k = tool_end if tool_end is not None else k + (2 if (w, nxt) in _HOLD_PAIRS else 1)
                last_event_end = k
                continue
            if k in self.by_start:
                m = self.by_start[k]
                g = self._resolve(m, self.size_of.get(m.start, []))
                k = m.end
                if g < 0:
                    continue
                if c.each is not None and (c.head is not None or c.each_deed) and not m.definite and g != c.each:
                    every = max(1, self.groups[c.each].count // c.each_unit)
                    self.groups[g].count = max(1, m.count) * every
                    self._stacks_apiece(g, every)
                    self.pair_each.add((g, c.each))
                # (not what a participle acts on: "noting every crate on a clipboard")
                words = range(m.start - 1, max(m.start - 6, -1), -1)
                opener = next((j for j in words if toks[j].text in ("each", "every")), 0)
                acted_on = opener > 0 and self._participle_at(opener - 1)
                if m.each and c.head is None and not c.verb_seen and not acted_on:
                    c.each = g  # "every desk has a lamp": a lamp per desk
                    # "each cow hooked up to a pump": a deed of each member, its things once per member
                    deed = m.end < ce and _participle(toks[m.end].text) and m.end not in self.rel_at
                    c.each_deed = deed and m.end not in self.by_start and self.groups[g].count > 1
                c.groups.append(g)
                if m.start in self.aboard:
                    pass  # "a bus full of children waits": the bus waits
                elif c.head is not None:
                    # (up to its describing words: "carries a spear and a polished shield")
                    gap = [t.text for t in toks[last_event_end : m.start - len(m.adjectives)]]
                    # (a list of things in hand goes on over "and a" or ", a": "holds a cup and a spoon",
                    # "with a sword, a shield and a helmet"; what a thing is made of or holds is no verb
                    # and ends no list: "holds a ball of red thread and a torch")
                    listed_gap = gap
                    if gap[:1] == ["of"]:
                        j = next((j for j in range(1, len(gap)) if gap[j] in _STOP or gap[j] in (",", *_DETERMINERS)), len(gap))
                        listed_gap = gap[j:]
                    listed = listed_gap[:1] in (["and"], ["or"], [","]) and all(
                        w in _DETERMINERS or w in _NUMBERS for w in listed_gap[1:]
                    )
                    closed = any(_is_verb(w) for w in (listed_gap if listed else gap))
                    if c.wsub and any(w in _OWN_PLACE for w in gap):  # "a till at one end and a computer"
                        self._close_with(c)
                        c.wsub_before, closed = list(c.wsub), True
                    # ("one holding a lamp, the other a rope": the second holder's thing, its verb left out)
                    other = [w for w in gap if w != ","][:2] in (["the", "other"], ["another", "a"], ["another", "an"])
                    stop = any(w in _STOP and w not in ("and", "or") for w in listed_gap)
                    # ("holds out a letter to the owl": whom it is held out to is no more in hand)
                    receiver = c.hold and not c.hand and any(w in ("to", "for") for w in gap) and "," not in gap
                    receiver = receiver and self._living(g)
                    if (c.hand and stop or receiver) and c.wsub and not other and not listed:
                        # "waves a flag from a gantry": what is in hand is the noun right after
                        if receiver:
                            self._relate("near", list(c.head), g)
                        self._close_with(c)
                        c.head, c.wsub, c.hand, c.hold = None, [], False, False
                        c.main_groups.append(g)
                        # ("a barber with a comb trims the hair of a pilot": the verb's, after the tool)
                        start = next((j for j in range(last_event_end, m.start) if toks[j].text not in _DETERMINERS), m.start)
                        start = max((mm.end for mm in self.by_start.values() if start <= mm.start < m.start), default=start)
                        if closed and self._object_of_verb(c, start, m.start) and self._living(c.main[-1]):
                            self._deed(c, list(c.main), g, m)
                        last_event_end = m.end
                        continue
                    c.wsub = [g] if (c.expect_new or closed) else [*c.wsub, g]
                    if other or c.single == "other":
                        c.others.add(g)
                    if c.single is not None:
                        self.numbered.add(g)  # ("one with binoculars": one pair, not one each)
                else:
                    c.main_groups.append(g)
                    # "an astronaut plants a flag next to it": the verb's object takes what follows,
                    # unless a person holds it ("a man reads a newspaper on the bench": he is on it)
                    verb_object = self._object_of_verb(c, last_event_end, m.start)
                    # "a man walks a dachshund beside the van": the dog by the man, the man by the van
                    led = verb_object and self._living(g) and self._person_at(c.main[-1]) and not c.expect_new and any(
                        t.text in _LEAD_VERBS for t in toks[last_event_end : m.start]
                    )
                    # "a man tips a crate of grapes into the trailer": by the trailer
                    into = bool(c.deeds) and c.deed_end == last_event_end and any(
                        t.text in ("into", "onto") for t in toks[last_event_end : m.start]
                    )
                    # "two boys fly a kite between the palms": what one flies is aloft, its flyer where the text says
                    flown = verb_object and self._living(c.main[-1]) and any(
                        t.text in _HANG_VERBS for t in toks[last_event_end : m.start]
                    )
                    acting = participle is not None and self._participle_deed(participle, m, prev_subject, c)
                    if acting:  # "a medic kneels between them, checking a stretcher": the medic by it
                        self._deed(c, list(self.doers or prev_subject), g, m)
                    elif into:
                        dropped = c.deeds[-1][1]
                        if not self._living(dropped) and self._small(dropped) and not self._living(g):
                            self._relate("on", [dropped], g)  # "lowers a sausage into a cart": in the cart
                        c.deeds[-1], c.deed_end = (c.deeds[-1][0], g), m.end
                    elif led:
                        follower, anchor = self._keeps_by(g, c.main[-1])
                        c.deeds.append(([follower], anchor))
                    elif verb_object and self._living(c.main[-1]) and not c.expect_new and not flown:
                        self._deed(c, list(c.main), g, m)
                        if m.each:  # "a weaver minds every loom": one at each
                            self._per_each(list(c.main), g)
                    small_object = verb_object and self._living(c.main[-1]) and self._small(g) and not c.expect_new
                    # "pulls a trailer of waving children past the pond": what the "of" after a
                    # phrase's target names is the target's load, not one the clause goes on about
                    load = phrase_end == m.start - len(m.adjectives) - 1 and toks[phrase_end].text == "of"
                    if not (led or into or small_object or load or flown):
                        c.main = [g] if c.expect_new or verb_object else [*c.main, g]
                    if not c.verb_seen:
                        c.subjects.append(g)
                c.expect_new = False
                last_event_end = m.end
                continue
            c.verb_seen = c.verb_seen or k in self.rel_at or _is_verb(w)
            c.finite = c.finite or _is_verb(w) or self._finite_at(k)  # ("children queue at a van")
            if k in self.rel_at:
                k = self._relation(c, self.rel_at[k], ce, prev_subject, starts_with_rel, last_event_end)
                last_event_end = phrase_end = k
                continue
            if c.head is None and k not in self.content_at:
                self._deed_on_pronoun(c, k, (self.doers or list(prev_subject)) if participial else [], prev_subject)
            k += 1
        self._close_with(c)
        self._do_deeds(c)

    def _subject_after(self, start: int, ce: int) -> bool:
        """Two things named after a phrase that opens a clause part, its target and the clause's
        own subject ("and between them a ground crew heaves ..."), or no verb at all: the
        subject comes in the next part ("and beside him, a dog sleeps")."""
        pronouns = ("it", "them", "him", "her")
        named = [
            k for k in range(start, ce)
            if (k in self.by_start and k not in self.content_at) or self.toks[k].text in pronouns
        ]  # fmt: skip
        # "and between the second and the third a farmer kneels": two of a row named before, no noun
        words = [t.text for t in self.toks[start : start + 5] if t.text != "the"]
        pair = len(words) >= 3 and words[0] in _ORDINALS and words[1] == "and" and words[2] in _ORDINALS
        if pair and not any(k in self.by_start for k in range(start, start + 5)):
            named.append(start)
        return len(named) >= 2 or not any(_is_verb(t.text) for t in self.toks[start:ce])

    def _deed(self, c: _Clause, doers: list[int], g: int, m: _Mention) -> None:
        """Record that ``doers`` act on the thing ``m`` names, and which of its members ("haggles
        at the middle stall")."""
        c.deeds.append((doers, g))
        c.deed_end = m.end
        if m.start in self.instance:
            c.deed_members[g] = self.instance[m.start]

    def _do_deeds(self, c: _Clause) -> None:
        """"A porter pushes a cart", "two engineers check the console": whoever acts on a thing
        too big to hold stands by it, unless the clause already relates the two; one who acts on
        a small thing stands by what it is on ("stirs a pot on the stove": by the stove), or by it
        when it lives ("a vet checks the smallest pup")."""
        for doers, thing in c.deeds:
            member = c.deed_members.get(thing)
            # ("pedals a sewing machine": a machine is worked where it stands, by it)
            worked = self.catalogue[self.groups[thing].category].shape == "machine"
            if self._small(thing) and not self._living(thing) and not worked:
                hosts = [r[2] for r in self.relations if r[0] == "on" and r[1] == thing and r[2] not in doers]
                if not hosts:
                    continue
                thing, member = hosts[-1], None
            free = [d for d in doers if not any({r[1], r[2]} == {d, thing} for r in self.relations)]
            self._relate("near", free, thing, instance=member)

    def _participle_deed(self, k: int, m: _Mention, prev_subject: list[int], c: _Clause) -> bool:
        """Whether ``m`` is what the participle at ``k`` that opens a clause acts on, for the
        living subject before (", checking a stretcher", ", feeding a falcon"): the clause's
        first thing, right after the participle, too big to have in hand or living, and a deed
        (holding, watching, sitting are not)."""
        doers = self.doers or prev_subject
        word = self.toks[k].text
        if c.main or c.deeds or not doers or not all(self._living(g) for g in doers):
            return False
        if not self._living(m.group) and max(self.groups[m.group].size) <= _HANDHELD_SIZE and word not in _CHASING:
            return False  # ", painting a toy sailboat", ", filling crates": worked on in hand or on the spot
        if word in _HAND_VERBS or self._lookout(word) or word in _HANG_VERBS or word in _TURN_VERBS:
            return False
        gap = self.toks[k + 1 : m.start - len(m.adjectives)]
        return all(t.text in _DETERMINERS or t.text in _NUMBERS for t in gap) and not c.main_groups[:-1]

    def _object_of_verb(self, c: _Clause, start: int, end: int) -> bool:
        """Whether the noun at ``end`` is the object of a verb that follows the clause's subject
        ("a porter pushes a cart", "an astronaut plants a flag"): a verb, and no list word, lies
        between them."""
        if not c.main:
            return False
        gap = [t.text for t in self.toks[start:end]]
        if any(w in ("and", "or", ",", "with", "while") for w in gap):
            return False
        # ("two children feed ducks": a verb after a plural subject has no -s; "two kids are loading
        # pumpkins", but "a mother pushing a pram" names the mother)
        toks = self.toks
        progressive = any(toks[j - 1].text in _COPULAS and toks[j].text.endswith("ing") for j in range(start + 1, end))
        finite = any((_is_verb(w) or self._finite_at(j)) and w not in _COPULAS for j, w in enumerate(gap, start))
        return progressive or finite

    def _verb_before(self, pos: int, test) -> bool:
        """A verb that passes ``test`` earlier in the same clause part ("dozes in it")."""
        k = pos - 1
        while k >= 0 and pos - k <= 8 and self.toks[k].text not in (",", ".", ";", "and", "while"):
            if test(self.toks[k].text):
                return True
            k -= 1
        return False

    @staticmethod
    def _posture(word: str) -> bool:
        """A verb of sitting, lying or standing ("slouches", "perched", "stands")."""
        return load_vocabulary().is_posture_verb(word)

    def _by_agent(self, k: int) -> bool:
        """The noun phrase ending at ``k`` is the doer of a passive ("watched by a trainer",
        "followed by two pages"): "by" after a past participle opens it."""
        j = k - 1
        while j > 0 and k - j <= 6 and self.toks[j].text != "by":
            if not self.toks[j].text[:1].isalpha():
                return False
            j -= 1
        verb = self.toks[j - 1].text if j > 0 else ""
        return self.toks[j].text == "by" and _participle(verb) and not verb.endswith("ing")

    @staticmethod
    def _work_verb(word: str) -> bool:
        """A verb of something people do with their hands, no posture ("digs", "two pirates dig")."""
        vocabulary = load_vocabulary()
        return vocabulary.is_person_verb(word) and not vocabulary.is_posture_verb(word)

    @staticmethod
    def _lookout(word: str) -> bool:
        """A verb one does from where one sits or stands ("watches", "waves"), or a posture."""
        vocabulary = load_vocabulary()
        return word in vocabulary.lookout_verbs or vocabulary.is_posture_verb(word)

    def _seat_owner(self, c: _Clause, srcs: list[int], m: _Mention) -> int | None:
        """Who sits on a seat named with a person's possessive ("an old woman sits knitting,
        her cat beside her chair": her chair is the one she sits on), when the sentence
        has someone sit and that person rests on nothing else yet."""
        toks = self.toks
        j = m.start - len(m.adjectives) - 1
        if j < 0 or toks[j].text not in _PERSON_POSSESSIVES or m.group < 0 or not self._carrier(m.group, ("seats",)):
            return None
        owner = self._person(c, srcs, _PERSON_POSSESSIVES[toks[j].text])
        if not owner or any(r[0] == "on" and r[1] == owner[0] for r in self.relations):
            return None
        sitting = load_vocabulary().postures.get("sitting", ())
        k = j
        while k >= 0 and toks[k].text not in (".", "!", "?"):
            if toks[k].text in sitting:
                return owner[0]
            k -= 1
        return None

    def _copy_group(self, g: int) -> int:
        """A new group like ``g``: the same thing once more, for another owner."""
        self.groups.append(replace(self.groups[g], index=len(self.groups), ids=[]))
        return len(self.groups) - 1

    def _close_with(self, c: _Clause) -> None:
        """"A desk with a lamp", "a cart loaded with barrels": small things with no place of
        their own stand on what they came with; people and animals keep by each other ("a dog
        with its handler")."""
        if c.head is None:
            return
        for g in c.wsub:
            if g in c.wsub_related:
                continue
            for i, h in enumerate(c.head):
                if i and c.head == c.each_of:
                    g = self._copy_group(g)  # one tankard each
                if h == g or any(r[1] == g and r[2] == h for r in self.relations):
                    continue  # "with a stone lantern beside it": placed by the head, not on it
                rests = self.groups[g].rests
                # "a miner with a pickaxe", "waves a flag" (a horse held by the reins is no load)
                held = (self._person_at(h) or c.hand and self._living(h)) and not self._living(g) and (
                    c.hand or self._handheld(g)
                ) or self._borne(g, h)
                if held and not c.hand and any(r[1] == g for r in self.relations):
                    continue  # "a clerk at the counter, with a radio beside it": placed on its own
                # ("a squire holds a horse by the reins": too big for arms, by him; "a girl with her dog": by her)
                big = c.hold and max(self.groups[g].size) > _HANDHELD_SIZE
                placed = any(r[1] == g for r in self.relations)
                if c.hold and not placed and self._person_at(g) and not self._person_at(h) and self._carrier(h, ("mounts",)):
                    # "elephants, each carrying a rider": the rider is up on it
                    self._relate("on", [g], h)
                    c.produced = True
                    continue
                if (big or c.hand or not c.hold) and self._living(g) and self._living(h) and not placed:
                    # ("a groom holds a pony by the reins": what one holds keeps by one, whatever its size)
                    follower, anchor = (g, h) if c.hold and not c.company else self._keeps_by(g, h)
                    # "a dog waits with its handler", "a farmer with two sheepdogs"
                    self._relate("near", [follower], anchor)
                    c.produced = True
                    continue
                alive = self._living(g) or self.groups[g].category == "fish"
                kept = alive and not self._living(h) and (
                    self._carrier(h, ("containers", "seats")) or self._person_at(g) and self._carrier(h, ("vehicles",))
                )
                # "a pond with koi", "a cage with two parrots", "a sleigh with a prince", "beds, each with a
                # sleeping patient": in it, on it
                if kept and not placed:
                    self._relate("on", [g], h)
                    c.produced = True
                    continue
                if not (c.hold or placed) and self._carrier(g, ("vehicles",)) and self._carrier(h, ("vehicles", "mounts")):
                    # "a snowmobile with a trailer", "a pony with a cart": the load behind what pulls it
                    self._relate("behind", [g], h)
                    self.towed[h] = g
                    c.produced = True
                    continue
                if not (c.hold or placed) and self._living(g) and self._carrier(g, ("mounts",)) and (
                    self._carrier(h, ("vehicles",))
                ):  # "a stagecoach with four horses": the team that draws it is by it
                    self._relate("near", [g], h)
                    c.produced = True
                    continue
                if c.sharing and self._small(g) and h in self.worked_at and not self._living(g):
                    # "a couple sits at the nearest table sharing a bottle": on the table they share it at
                    # ("a clerk sits at a desk, typing on a laptop": on the desk)
                    self._relate("on", [g], self.worked_at[h])
                    c.produced = True
                    continue
                if not (c.hold or placed) and self.catalogue[self.groups[g].category].shape in _SEATS and (
                    self.catalogue[self.groups[h].category].support and not self._living(h)
                ):  # "a round table with two chairs", "three tables, each with four stools": pulled up to it
                    # (to a desk's or a counter's front: one works or is served on that side)
                    self._relate("at seat" if self.groups[h].category in ("desk", "counter") else "around", [g], h)
                    c.produced = True
                    continue
                steadied = c.hold and self._steadied(g)
                if (c.hold or held) and self._person_at(h) and not self._living(g) and (not self._carriable(g, h) or steadied):
                    # ("a woman grips the railing", "a boy holds the wardrobe": too big to carry, by it;
                    # "his apprentice holds the ladder steady": he steadies it where it stands)
                    self._relate("near", [h], g)
                    c.produced = True
                    continue
                if c.hold or held or (rests == "surface" and self.catalogue[self.groups[h].category].support):
                    self._relate("on", [g], h, instance=1 if g in c.others and self.groups[h].count > 1 else None)
                    c.produced = True
                    # ("a mother holds a sleeping baby", "carries a lamb": in arms, a small living thing too)
                    small = not self._living(g) or max(self.groups[g].size) <= _HANDHELD_SIZE
                    # ("four cargo drones, each carrying a crate": carried by a machine, as in hand)
                    bearer = self._person_at(h) or self.groups[h].category in _MACHINE_BEARERS
                    if held or (c.hold and bearer and small):
                        if not c.shared:
                            self.in_hand.append((g, h))
                        self.carried.add((g, h))

    def _hoist(self, g: int) -> bool:
        """Whether ``g`` is a machine that lifts loads (:data:`_HOISTS`, by its name's last word)."""
        return not self._living(g) and singular(self.groups[g].name.split()[-1].lower()) in _HOISTS

    def _relation(self, c: _Clause, rel: _Rel, ce: int, prev_subject, starts_with_rel, last_event_end) -> int:
        """One relation phrase, in steps: read the phrase and its target, find what it places, set
        out a formation or an anchor, resolve the target, then relate (or hand the phrase to the
        clause's subject when it comes first). Returns where the reading goes on."""
        last = max((m.end for m in self.by_start.values() if m.end <= rel.start), default=0)
        if rel.kind == "end of elliptic" and any(t.text == "with" for t in self.toks[last : rel.start]):
            return rel.end  # "a table with folded fabric piled at one end": stuff, no thing of the scene
        p = self._read_phrase(c, rel, ce, prev_subject)
        if (stop := self._sources(c, p, prev_subject, last_event_end)) is not None:
            return stop
        if (stop := self._formation_or_anchor(c, p, prev_subject)) is not None:
            return stop
        self._targets(c, p, prev_subject, starts_with_rel)
        if (stop := self._reversed_phrase(c, p, prev_subject)) is not None:
            return stop
        if (stop := self._without_sources(c, p, prev_subject, starts_with_rel)) is not None:
            return stop
        return self._place(c, p)

    def _read_phrase(self, c: _Clause, rel: _Rel, ce: int, prev_subject) -> _Phrase:
        """The phrase's kind as its words and target make it, and its target: "stacked against",
        "on the artist's right", "between the first and second car", "on her knees", "at his
        back", "at its top"."""
        toks = self.toks
        kind = rel.kind
        stacked = any(r.end == rel.start and r.kind == "stack" for r in self.rel_at.values())
        if kind == "near" and toks[rel.start].text == "against" and stacked:
            kind = "side of"  # "drums are stacked against the hut": the stack rests on its side
        # "between the first and second car", "between the last two carts": two of one group (read
        # before the target, which would make "the last two carts" two new carts)
        pair = self._ordinal_pair(rel.end, ce) if kind == "between" else None
        # "To her left a globe sits": the possessive is the target, the noun after the subject
        if kind in _OWN_SIDES or pair is not None:  # (no target read: nothing of the last one's parts carries over)
            self._body_part = self._part = None
            self._parts_each = 0
        own = kind in _OWN_SIDES or pair is not None
        target, end = self._target_at(rel.end, ce) if not own else (None, rel.end)
        if kind in ("on", "at") and target is None and (side := self._owners_side(rel.end, ce)) is not None:
            kind, target, end = side  # "a cart is on the artist's right": right of the artist
        if toks[rel.start].text == "in" and target is None and (ride := self._vehicle_part(rel.start + 1, ce)):
            kind, (target, end) = "in", ride  # "a pickup truck with its lights on, a collie in the back"
        if rel.kind == "in front of" and toks[rel.start].text in ("line", "lines") and isinstance(target, list) and target and (
            self.catalogue[self.groups[target[0]].category].shape == "bookshelf"
        ):  # "jars line the shelves": on them, as "crowd the shelves" ("stools line the counter": in front)
            kind = "covering"
        inside = [t.text for t in toks[rel.start : rel.start + 3]] == ["in", "the", "back"]
        if inside and isinstance(target, list) and target and self._carrier(target[0], ("vehicles",)):
            kind = "in"  # "a boy in the back of the van": in it, not behind it
        ordinals: tuple[int, int] | None = None
        if pair is not None:
            group, ordinals, end = pair
            several = [group] if group is not None else self._one_of(c, c.main, prev_subject)
            if ordinals is None and several:  # "between the middle two" of four: the second and third
                half = (self.groups[several[0]].count - 2) // 2
                ordinals = (max(0, half), max(0, half) + 1)
            target, self._target_start = several or None, -1
        body, part = self._body_part, self._part  # "on her knees": by the person, as the part says
        self._perch_part = part in load_vocabulary().carriers.get("perches", ())
        parts_each = self._parts_each
        if kind == "on a carrier" and self._mutual(rel.start):
            kind = "no relation"  # "two men face each other across the bench": the bench is between them (_place)
        if kind == "face to" and self._across_from(rel.start, end):
            kind = "opposite"  # "a sofa faces the piano from across the room", "Across the street, a kiosk faces the shelter"
        verb = self._acting_verb(rel.start) if kind == "at" else None
        if verb is not None and _phrase_table().get((verb, toks[rel.start].text)) == "face to":
            kind = "face to"  # "aims a crossbow at them", "shouts a warning at them": as "aims at them"
        # ("hens around her feet" stay around her; "a surfboard under his arm", "an axe across his
        # knees", "a bag over her shoulder", "a snake around his neck" are carried)
        carried = ("on", "on top", "in", "under", "over", "around", "no relation", "on a carrier")
        # ("a parasol above her head" is above her)
        beside = body in ("near", "side of", "in front of") and kind not in ("around", "above")
        if beside or (body == "on" and kind in carried):
            kind = body
        elif body == "on" and kind == "at":  # "a shelf at his back": behind him, not carried
            kind, body = "behind" if any(t.text == "back" for t in toks[rel.end : end]) else "near", None
        if kind == "in" and part is not None and load_vocabulary().carries("thing", part, ("containers", "seats", "vehicles")):
            kind = "on"  # "stands in the nearest basket" (a balloon's): on what has it
        if kind == "at" and (part in _STANDING_PARTS or part in _DRIVING_PARTS or self._perch_part and part != "edge"):
            kind = "on"  # "a shuttle docked at its top", "the captain stands at its prow": as "on" it
        if kind == "along" and part is not None and self._hung_before(rel.start):
            kind = "on"  # "shields hang along the ship's side": the ship carries them
        return _Phrase(rel, ce, kind, target, end, ordinals, body, part, parts_each)

    def _vehicle_part(self, pos: int, ce: int) -> tuple[list[int], int] | None:
        """"In the back", "in the cab": a part (``part_owners``) of a vehicle this sentence names,
        no object, so the vehicle (the latest such); and where the part ends."""
        k = pos + (pos < ce and self.toks[pos].text in ("the", "its"))
        while k + 1 < ce and self.toks[k].text in _SIDE_WORDS and self.toks[k + 1].text[:1].isalpha():
            k += 1  # "under the front bumper", "by the rear wheel"
        if k >= ce or (k + 1 < ce and self.toks[k + 1].text[:1].isalpha()):
            return None
        owners = load_vocabulary().part_owners.get(singular(self.toks[k].text), ())
        stop = max((j for j in range(pos) if self.toks[j].text in (".", "!", "?")), default=-1)
        here = [m.group for j, m in sorted(self.by_start.items()) if stop < j < pos and m.group >= 0]
        vehicles = [g for g in here if self.groups[g].category in owners and self._carrier(g, ("vehicles",))]
        return (vehicles[-1:], k + 1) if vehicles else None

    def _across_from(self, start: int, end: int) -> bool:
        """Whether a facing phrase faces its target from across a place (no object: "from across the
        room" right after the target, not "from across the table"), or in the clause right after a
        sentence's opening "Across the street,": across from it."""
        toks = self.toks
        if [t.text for t in toks[end : end + 2]] == ["from", "across"]:
            return not any(k in self.by_start for k in range(end + 2, min(end + 6, len(toks))))
        opening = max((k for k in range(start) if toks[k].text in (".", "!", "?", ";")), default=-1) + 1
        breaks = sum(toks[k].text == "," for k in range(opening, start))
        return toks[opening].text == "across" and toks[opening + 1].text != "from" and breaks == 1

    def _set_down_as(self, start: int, thing: int) -> bool:
        """Whether the phrase at ``start`` opens with a participle saying how the lifeless ``thing``
        named right before it is set down ("a lamp clamped to the bench", "a paddle resting on it"):
        the phrase places that thing, whatever the clause is about."""
        word = self.toks[start].text
        return (word.endswith("ed") or word in _STATE_PARTICIPLES) and not self._living(thing)

    def _sources(self, c: _Clause, p: _Phrase, prev_subject, last_event_end) -> int | None:
        """What the phrase places: the target before it when the phrase chains on it or a
        description of it goes on, the with-part's things, else the clause's subject (or the small
        thing its verb acts on). Where the reading goes on when the phrase places nothing here."""
        toks, rel, kind, target, body, end = self.toks, p.rel, p.kind, p.target, p.body, p.end
        between = [t.text for t in toks[last_event_end : rel.start]]
        before = next((m.group for m in self.by_start.values() if m.end == rel.start), -1)  # the noun right before
        # sources: the noun the phrase follows when nothing but adverbs lies between
        srcs: list[int]
        # "a globe on a side table to the right of the desk", "chairs around a table left of the sofa"
        chained = (c.last_kind in _CHAIN_KINDS or kind in ("on", "on top")) and kind not in (
            "face to", "flank", "around", "no relation"
        )  # fmt: skip
        if chained and kind in ("above", "over") and self._hung_before(rel.start, "from") and c.main:
            # "bats hang from the bridge above the stalls": what hangs from a thing is above them, not the
            # thing it hangs from (which stands on its own feet); "a bell hangs in the tower above the
            # gate" still puts the tower there
            chained = False
        if chained and isinstance(target, list) and target and c.last_target:
            # "a lamp on the table next to a teapot": what stands by a small thing is its peer, not the table
            chained = not self._small(target[0]) or self._small(c.last_target[0])
            # "a horseman waits at its door on a black horse": he rides it, not the barn
            ridden = kind in ("on", "on top") and self._carrier(target[0], ("mounts",)) and self._living(target[0])
            chained = chained and not (ridden and not any(self._living(g) for g in c.last_target))
        tail = c.last_target_end
        if 0 <= tail < len(toks) - 1 and toks[tail].text == "of" and tail + 1 in self.by_start:
            tail = self.by_start[tail + 1].end  # "a tray of instruments on a trolley": what it holds, then the chain
        lined_up = kind in _FORMATIONS and c.target_after_verb and _participle(toks[rel.start].text)
        if lined_up and c.last_target and c.last_target_end == rel.start:
            # "shouts at twenty legionaries lined up in front of him": they stand in the row, and in front of him
            srcs = c.main = list(c.last_target)
        elif chained and c.last_target and tail == last_event_end and all(b in _ADVERBS for b in between):
            srcs = list(c.last_target)
            rider = c.main or ([] if c.first else list(prev_subject))
            if c.wsub and c.last_srcs and all(g in c.wsub for g in c.last_srcs):
                rider = list(c.last_srcs)  # "with a teapot on a tray in front of him": the with-part's, not his
            on = [r[1] for r in self.relations if r[0] == "on" and r[2] in c.last_target]
            # the living things the last phrase seated there ride it: "a unicorn rests its head in the
            # lap of a nun who sits on a bench beneath a tree" (the nun), "with three judges sitting on
            # hay bales in front of it" (the with-things)
            seated = [g for g in c.last_srcs if g in on and self._living(g)]
            if seated:
                rider = seated
            elif not all(self._living(g) for g in rider):
                # "scientists launch a balloon from a platform across from the huts": the clause's
                # subjects the last phrase put on the target ride it, not the thing they act on
                rider = [g for g in c.subjects if g in on and self._living(g)] or rider
            across = kind == "opposite" and self._across_from_doer(c, target, None, last_event_end)
            if self._rider_placed(c, rider, kind, rel.start) and not across:
                srcs = list(rider)  # "he sits on a stool at the workbench": he is at it, on his stool
            elif self._at_on_perch(c, rider, kind, target):
                p.riders = list(rider)  # "stands at a lectern on a low stage": both are on the stage
            elif self._sits_on_instead(c, rider, p):
                srcs = list(rider)  # "a troll sits beneath the bridge on a boulder": he is on it, not the bridge
            elif self._placed_by_person(c, p, rider):
                srcs = list(rider)  # "his apprentice rinses rice in a tub beside him": he is beside him, not the tub
            each = target == "each one" or (
                isinstance(target, list) and getattr(self.by_start.get(self._target_start), "each", False)
            )
            if each and all(t in self.history for t in c.last_target):
                # "a register on the counter in front of each of them": one each, not the counter (fronted,
                # "on the bench in front of every student is a cake": the subject to come)
                srcs = list(c.last_srcs)
            elif kind == "between" and c.last_kind in ("on", "on top") and c.last_srcs and (
                all(t in self.history for t in c.last_target)
            ):
                srcs = list(c.last_srcs)  # "a spool on the table between them": the host named before keeps its place
        elif self._seen_doing(c, rel, between, last_event_end):
            srcs = list(c.last_target)  # "watching a swarm of bats circle the chandelier": the bats circle it
        elif c.last_target and c.last_target_end == last_event_end and self._describes(between, c.target_after_verb):
            srcs = list(c.last_target)  # "a lorry idling at the barrier", "a lamp that hangs above the bar"
            if target is None:  # "a fork stuck in the soil beside it": the description goes on
                k = p.end
                while k < p.ce and k not in self.rel_at and k not in self.by_start and toks[k].text not in (",", "and"):
                    k += 1
                c.last_target_end = k
                return k
        elif c.head is not None:
            # contents are no verbs: "a cart with a bowl of apples on it" keeps the bowl as the source
            # ("ladies with parasols stroll along it": a plural verb has no -s, it comes right after a noun)
            closed = any(
                _is_verb(toks[k].text) or self._finite_at(k)
                for k in range(last_event_end, rel.start + 1)  # "with parrots inside hangs from": its own verb
                if k not in self.content_at and toks[k - 1].text not in ("of", "in")  # "a farmer in dungarees"
                and toks[k - 1].text not in _DETERMINERS
                and not (toks[k - 2].text == "of" and thing_plural(toks[k].text))  # "a bowl of sugar cubes on it"
                # (after a plural it is a verb: "a stall piled with crates of apples stands by the gate")
                and (
                    k - 1 not in self.content_at or toks[k].text in _FINITE or singular(toks[k - 1].text) != toks[k - 1].text
                )
            )
            # "a dad with his putter beside the windmill": what is in hand goes where its holder is
            # ("reads a book on the bench", "sharpen their spears on a grindstone": the readers and sharpeners)
            # (what a person holds or carries is in hand as well: "a waiter carries a tray between the tables")
            # (a setting holds nothing in hand: "a museum gallery displays a skeleton on a plinth")
            holding = c.hand or c.hold and bool(c.head) and all(self._living(h) for h in c.head)
            # (the holder faces what is aimed at: "aims a pitchfork at them"; "eats a pie at the foot of the
            # tower": the eater is there)
            # ("two servants wave fans on either side of him": "him" is not the two, so someone else;
            # but "three women, each with a basket at her feet": each one's own)
            other = target in ("him", "her") and bool(c.head) and all(self.groups[h].count > 1 for h in c.head)
            other = other and not self._said_before(rel.start, lambda k: toks[k].text in ("each", "every"))
            # ("carries a sack over the bridge": the carrier crosses it, the sack in hand)
            crossed = kind == "over" and isinstance(target, list) and bool(target)
            crossed = crossed and self._carrier(target[0], ("perches",))
            crossed = crossed and self.groups[target[0]].size[2] <= _PLATFORM_HEIGHT
            in_hand = holding and (target not in _PERSONAL or other) and (kind in (
                *_GROUND_KINDS, *_HOLDER_KINDS, "face to", "foot of", "flank"
            ) or crossed)
            # ("senators sit on benches, with an amphora beside each bench": by their own seat, not in hand)
            seats = {r[2] for r in self.relations if r[0] == "on" and r[1] in c.head}
            if in_hand and c.wsub and isinstance(target, list) and any(t in seats for t in target):
                in_hand = c.hand = False
            # ("with his terrier asleep under it": a living with-thing is no thing in hand, its phrase places it)
            in_hand = in_hand and not any(self._living(g) for g in c.wsub)
            # ("a groom waits with the ponies beside a shed": the groom is there, the ponies with him)
            company = c.company and target not in _PERSONAL and kind in (*_GROUND_KINDS, "at", "between", "under")
            in_hand = in_hand or company
            # "holding a lantern above her head": it stays in hand (above anything else it is above that)
            lifted = holding and kind in ("above", "over") and (body is not None or target in _PERSONAL)
            whose = toks[rel.end].text if rel.end < len(toks) else ""
            if lifted and whose in _PERSON_POSSESSIVES:
                # "two footmen ..., holding a parasol above her head": over the queen, not their own heads
                owner = self._person(c, list(c.wsub), _PERSON_POSSESSIVES[whose])
                lifted = not owner or bool(set(owner) & set(c.head or []))
            in_hand = in_hand or lifted
            # the with-part named stuff that is no object of its own ("with geraniums"; not "with a
            # great bible", one thing the catalogue does not know), and no verb of the head's ("a man
            # with a hat sits in a chair")
            gap = [toks[k].text for k in range(last_event_end, rel.start)]
            contents = (
                toks[last_event_end - 1].text == "with"
                and any(w not in _STOP and w[:1].isalpha() for w in gap)
                and not any(w in _FINITE or self._lookout(w) or w in ("a", "an", "one") for w in gap)
            )
            # "a trader argues with a buyer beside it", "a squire waits with the horses by a tower": the
            # company a verb names goes along with its subject, who is what the phrase places
            # ("a man sits on the bench, with his terrier asleep under it": the terrier; "argues with a
            # porter across from her": the porter, placed by her)
            with_at = next((k for k in range(rel.start - 1, max(rel.start - 8, 0), -1) if toks[k].text == "with"), 0)
            company = with_at > 0 and _is_verb(toks[with_at - 1].text) and target not in _PERSONAL and all(
                self._living(g) for g in [*c.wsub, *c.head]
            )
            # ("skirts a fleece spread out on it": a participle right after the thing in hand describes the thing)
            told = [toks[k].text for k in range(last_event_end, rel.start)]
            described = 0 < len(told) <= 2 and _participle(told[0]) and told[0] not in _HOLD and "," not in told
            described = described and not any(self._living(g) for g in c.wsub)
            # "with a campfire in front of them surrounded by four logs": a passive right after the with-thing's
            # place on the ground is the with-thing's ("with a vase on it, surrounded by chairs": the head's)
            passive = kind in _REVERSED and rel.start == last_event_end and toks[rel.start - 1].text != ","
            described = described or passive and c.last_kind in _GROUND_KINDS and c.last_srcs == c.wsub
            if c.wsub and (described or not closed and not c.expect_new and not in_hand and not company):
                srcs = list(c.wsub)
                covered = kind == "under" and self._covered(srcs, target)  # (in bed under a blanket: on the bed)
                if kind in ("on", "above", "over", "on top", "under") and target is not None and not covered:
                    c.wsub_related.update(srcs)  # (not "a dog on a lead": no thing to be on)
            elif not c.wsub and contents and kind == "in" and isinstance(target, list) and target:
                # "a chalet with geraniums in every window box": what holds the head's contents is
                # on the head
                for h in c.head:
                    self._relate("on", list(target), h)
                c.wsub, c.expect_new = list(target), False
                c.wsub_related.update(target)
                c.groups.extend(g for g in target if g not in c.groups)
                return p.end
            else:
                # one works on a grindstone or an anvil standing at it; what is worked there lies on it
                # (one who sits or stands on it is on it: "a musician with a flute sits on a carpet")
                worked_on = in_hand and kind == "on" and isinstance(target, list) and not self._carrier(target[0], _RIDDEN)
                # ("two musicians play lutes on a rug": a thing as low as a rug is stood or sat on)
                worked_on = worked_on and self.groups[target[0]].size[2] > FLAT_HOST
                worked_on = worked_on and not self._verb_before(rel.start, self._posture)
                if worked_on and not self._verb_before(rel.start, lambda w: w in _KEPT_IN_HAND):
                    self._set_down(c, target[0])
                self._close_with(c)
                srcs = list(c.head)
                c.head, c.wsub = None, []
                if body == "on" and not in_hand:
                    return end  # "a woman with clippers in her hand": no object named in hand, none placed
                if lifted:
                    return end  # held over one's own head: in hand, nothing more
                if in_hand and kind == "between" and target == "them" and all(self.groups[h].count > 1 for h in srcs):
                    return end  # "two porters hold up a portrait between them": in their hands, no place of theirs
                named = any(w not in _STOP and w[:1].isalpha() for w in gap)
                if named and not closed and p.part is not None and target in ("it", "them"):
                    return end  # "a stall ..., with a cash tin on its counter": what is on its own part is no object
                if worked_on:
                    kind = "near"
        else:
            srcs = list(c.main)
            # "a farmer guides a buffalo pulling a plough": a participle right after the verb's object is the object's
            if c.finite and toks[rel.start].text.endswith("ing") and before in c.main_groups and before not in c.main:
                srcs = [before]
            acted = c.deeds[-1][1] if c.deeds and c.deed_end == last_event_end else None
            if kind in _FORMATIONS and acted is not None and self._small(acted) and rel.start == last_event_end:
                # "pours squash into cups lined up on it": the cups are lined up, and the phrase after
                # goes on placing them (the pourer by them: :meth:`_do_deeds`)
                srcs, c.deed_end = [acted], p.end
            elif kind in ("on", "in", "on top", "over") and acted is not None and self._small(acted):
                # "a smith hammers a horseshoe on the anvil", "a cook stirs a pot over the fire": the
                # thing acted on is there (its doer by it: :meth:`_do_deeds`)
                srcs = [acted]
            elif kind == "on" and acted is not None and isinstance(target, list) and self._doer_seated(c, acted, target[0]):
                # "a woman milks a goat on a stool": the goat is too big for the stool; she sits on it
                srcs = [d for d in c.deeds[-1][0] if self._person_at(d)]
            elif kind == "opposite" and self._across_from_doer(c, target, acted, last_event_end):
                # "two dogs watch the flock across from them": the flock is across from the dogs;
                # "they queue at a kiosk across from it": the kiosk (no kiosk is across from itself)
                srcs = [acted] if acted is not None else list(c.last_target)
        if before >= 0 and before not in c.main and self._set_down_as(rel.start, before):
            srcs = [before]  # "sits under a lamp clamped to the bench", "with a gouge, a lamp clamped to its edge"
        elif before >= 0 and toks[rel.start].text.endswith("ing") and self._living(before) and before not in (
            *c.subjects, *(c.head or ()), *c.wsub
        ):  # "chats to a cyclist leaning on the ping-pong table": the cyclist leans on it
            srcs = [before]
        deed = c.deeds and c.deed_end in (last_event_end, rel.start)
        if kind == "on" and toks[rel.start].text == "from" and deed:
            srcs = list(c.deeds[-1][0])  # "two squirrels scold the workers from the top of a lamp post"
        lookout = any(t.text == "from" for t in toks[rel.start : rel.end]) and p.part is None
        lookout = lookout and p.body is None and isinstance(target, list) and bool(target)
        lookout = lookout and not self._living(target[0])
        lookout = lookout and self.groups[target[0]].size[2] > FLAT_HOST  # ("from a picnic blanket": on it)
        if kind == "on" and lookout and srcs and all(self._person_at(g) for g in srcs) and not self._carrier(target[0]):
            kind = "near"  # "the captain watches from a console": at it (from a tower, a rock: up on it)
        if kind in ("on", "in") and srcs and all(self._person_at(g) for g in srcs) and (
            kind == "on" and self._pair_before(rel.start) or self._works_on(rel.start, target, inside=kind == "in")
        ):  # "a girl writes on the blackboard", "a chef slices bread on a board", "rinses rice in a
            # tub": at it, not on or in it
            kind = "near"
        # ("guide a hose from it into a tank": what runs from one to the other is between them, the doers by it)
        span = kind == "from" and self._from_to(rel.end, set(self.by_start))
        if kind == "from" and not span and deed:
            srcs = list(c.deeds[-1][0])  # "two children feed ducks from a footbridge": the children are on it
        if kind == "from" and not span and not any(self._living(g) for g in srcs):
            # "a guard waves a flag from the tower": the one who waves is up there
            srcs = [g for g in c.subjects if self._living(g)] or srcs
        if kind == "face to" and rel.kind == "at":  # "a guard aims a crossbow at them": the guard faces them
            srcs = [g for g in c.subjects if self._living(g)] or srcs
        seats = isinstance(target, list) and all(
            self.catalogue[self.groups[t].category].shape in _SEATS
            or self._carrier(t, ("perches", "vehicles", "seats"))
            for t in target
        )
        if kind == "covering" and toks[rel.start].text.startswith("fill") and any(self._living(g) for g in srcs) and not seats:
            kind = "near"  # "a girl fills a jug at the pump": by what she fills, not in it (seats they fill, they sit
            # on, and a bandstand or a boat they fill they stand in: "a brass band fills the bandstand")
        p.kind, p.srcs = kind, srcs
        return None

    def _covered(self, srcs: list[int], targets) -> bool:
        """Whether living things are "under" a cover (``_COVERS``): lying under it where they are."""
        return isinstance(targets, list) and bool(targets) and bool(srcs) and all(
            isinstance(t, int) and self.groups[t].category in _COVERS for t in targets
        ) and all(self._living(g) for g in srcs)

    def _set_down(self, c: _Clause, host: int) -> None:
        """"A smith strikes a horseshoe on the anvil", "a clerk stamps a letter on the counter": the
        small lifeless things the clause's verb works lie on the host, so :meth:`_close_with` puts
        them in no hand (what is sharpened on a stone or played there stays in hand: :data:`_KEPT_IN_HAND`)."""
        for g in c.wsub:
            if not self._living(g) and max(self.groups[g].size) <= _HANDHELD_SIZE and g not in c.wsub_related:
                self._relate("on", [g], host)
                c.wsub_related.add(g)

    def _placed_by_person(self, c: _Clause, p: _Phrase, rider: list[int]) -> bool:
        """Whether a phrase chained on a lifeless thing the last phrase put a person by (``near``:
        one works at it) places that person instead: its target is a person named by a pronoun, no
        body part of theirs ("rinses rice in a tub beside him": the rinser is beside him; "a reel in
        his hands" is his; "soldiers stand on the shelf behind him": the shelf is)."""
        people = bool(c.last_srcs) and all(g in rider and self._person_at(g) for g in c.last_srcs)
        lifeless = not any(self._living(t) for t in c.last_target)
        return p.target in _PERSONAL and p.body is None and c.last_kind == "near" and people and lifeless

    def _doer_seated(self, c: _Clause, acted: int, seat: int) -> bool:
        """Whether "on" a seat after an animal acted on puts the person who acts on the seat: the
        animal's footprint is larger than the seat's ("milks a goat on a stool", not "strokes a
        cat on the sofa")."""
        doers = c.deeds[-1][0] if c.deeds else []
        if not self._living(acted) or not any(self._person_at(d) for d in doers) or not self._carrier(seat, ("seats",)):
            return False
        animal, host = self.groups[acted].size, self.groups[seat].size
        return animal[0] * animal[1] > host[0] * host[1]

    def _across_from_doer(self, c: _Clause, target, acted: int | None, last_event_end: int) -> bool:
        """Whether "across from" a pronoun, right after what the subject acts on, looks at or is at,
        places that thing across from what the pronoun names: after a thing acted on or looked at
        ("watching the pen across from them"), and after "at" a thing when the pronoun is "it" (a
        person at a table across from him is the one placed)."""
        if target not in ("it", "them", *_PERSONAL):
            return False
        if acted is not None:
            return True
        after = bool(c.last_target) and c.last_target_end == last_event_end
        return after and (c.last_kind == "face to" or (c.last_kind == "at" and target == "it"))

    def _formation_or_anchor(self, c: _Clause, p: _Phrase, prev_subject) -> int | None:
        """Phrases that place by no target: no relation ("toward the rack"), a formation ("in a
        row", "stacked"), a part of the room ("against the wall", "in the middle of the room")."""
        toks, rel, kind, srcs, end, ce = self.toks, p.rel, p.kind, p.srcs, p.end, p.ce
        if kind == "stack" and rel.end < ce and toks[rel.end].text == "of" and isinstance(p.target, list) and p.target:
            p.kind = "in" if toks[rel.start].text == "in" else "on"  # "two aliens wait in a stack of cages": in them
            return None
        toward = toks[rel.start].text.startswith(("toward", "heading"))
        # a load trails its puller, a led animal its leader and what one carries its carrier: none of
        # them is what goes there ("two rescuers carry a stretcher towards the helicopter": they face it)
        trailing = {t for k, ts in c.rels if k == "towing" for t in ts}
        trailing |= {d for doers, thing in c.deeds if thing in srcs for d in doers}
        trailing |= {thing for doers, thing in c.deeds if any(d in srcs for d in doers)}  # what they lead
        trailing |= {g for g, holder in self.carried if holder in srcs}
        objects = [g for g in c.main_groups if g not in c.subjects and g not in trailing]
        # what pulls a load moves under its own power, whatever the catalogue calls it ("a skidder hauls timber")
        hauls = self._verb_before(rel.start, lambda w: _phrase_table().get((w,)) == "towing")
        if kind == "no relation" and toward and c.head is None and srcs and not objects and all(
            self._living(g) or self._carrier(g, ("vehicles",)) or hauls for g in srcs
        ):  # "a knight rides over the bridge towards the dragon", "a waiter carries a tray towards them",
            # "a tug pulls four carts towards the hold": it faces it ("a porter pushes a cart toward the
            # kiosk": what goes there is the verb's object)
            p.kind = "face to"
            return None
        if kind == "no relation" and c.head is not None and toward:
            # "a forklift carries a pallet toward the rack": the with-part ends, the rack is no load
            self._close_with(c)
            c.head, c.wsub, c.expect_new = None, [], True
            return end
        pair = sum(self.groups[s].count for s in srcs) == 2
        across = pair and isinstance(p.target, list) and len(p.target) == 1
        if kind == "no relation" and across and self._mutual(rel.start):
            for s in srcs:  # "two armchairs face each other across a rug": the rug lies between them
                self._relate("between", p.target, s)
            c.last_target, c.last_target_end, c.last_kind = list(p.target), end, "near"  # (a place after it is its)
            return end
        # "pumpkins stacked in crates": put into several holders, so spread over them, not one stack
        into = end + 1 < ce and toks[end].text in ("in", "into") and end + 1 in self.by_start
        into = into and _is_plural(toks, self.by_start[end + 1])
        if kind == "no relation" or (kind == "stack" and end < ce and (toks[end].text == "with" or into)):
            if toward and isinstance(p.target, list):  # named all the same: "..., and a truck waits under it"
                c.groups.extend(g for g in p.target if g not in c.groups)
            return end  # "a shelf stacked with books": contents, no stack
        of_thing = rel.end < ce and toks[rel.end].text == "of" and any(
            k in self.by_start for k in range(rel.end + 1, min(rel.end + 3, ce))
        )
        if kind.startswith("anchor ") and of_thing:
            p.kind = "near"  # "at the far end of the counter": by the counter, at its end
            return None
        end_of_place = {"behind": "back", "in front of": "front"}.get(kind)
        said_end = any(t.text in ("back", "rear", "front") for t in toks[rel.start : rel.end])
        if end_of_place and p.target is None and said_end:
            kind = f"anchor {end_of_place}"  # "a counter at the back of the shop": the setting's back, no thing's
        # (what the with-part's owners sit around or at)
        tables = [r[2] for r in self.relations
                  if r[1] in (c.head or ()) and self.catalogue[self.groups[r[2]].category].support]
        # ("a long table with a big cake in the middle": the head's own middle)
        tables += [h for h in (c.head or ()) if not self._living(h) and self.catalogue[self.groups[h].category].support]
        if kind == "anchor centre" and toks[rel.end - 1].text != "of" and srcs and srcs == c.wsub and tables and (
            not any(self._living(g) for g in srcs)
        ):  # "four students sit around a table, with a plate of biscuits in the middle": the table's middle
            self._relate("on", srcs, tables[-1])
            c.wsub_related.update(srcs)
            c.wsub_before = list(srcs)  # ("... and cupcakes around it": around the cake)
            return end
        faced = c.last_kind == "face to" and c.last_target_end == rel.start and bool(c.last_target)
        if kind.startswith("anchor ") and faced:
            srcs = list(c.last_target)  # "desks face the teacher's desk at the front": the teacher's desk is there
        if p.target is None and kind in ("behind", "in front of") and self._setting_after(rel.end, ce):
            kind = "anchor back" if kind == "behind" else "anchor front"  # "a dune rises behind the camp": at the back
        if kind in _FORMATIONS or kind.startswith("anchor ") or (p.target is None and kind in _PLACE_KINDS):
            # "three stalls stand in a row", "a sofa against the wall", "a rug in the middle of the room"
            place = _PLACE_KINDS.get(kind) or self._anchor_after(rel.end, ce) if not kind.startswith("anchor ") else kind
            lines = next((_NUMBERS[t.text] for t in toks[rel.start : rel.end] if t.text in _NUMBERS), None)
            abreast = any(t.text in ("side", "next", "beside") for t in toks[rel.start : rel.end])
            for g in srcs or ([] if c.first else list(prev_subject)):
                if kind in _FORMATIONS:
                    self.formations.setdefault(g, "row" if kind == "rows" and lines == 1 else kind)
                    if abreast and self.groups[g].count > 1:  # "two helmsmen sit side by side": each beside the next
                        self.relations.append(("side of", g, g, None))
                    if kind == "rows" and lines:
                        self.lines.setdefault(g, lines)
                    uncounted = g not in self.numbered and self.groups[g].count == UNCOUNTED
                    if kind == "rows" and lines and lines > 1 and uncounted:
                        self.groups[g].count = lines * UNCOUNTED  # "cars are parked in two long rows": a few a row
                    heap = next((t.text for t in toks[rel.start : rel.end] if t.text in ("pyramid", "tower")), None)
                    if kind == "stack" and heap and uncounted:
                        self.groups[g].count = _QUANTITY[heap]  # "barrels are stacked in a pyramid": six of them
                elif place:
                    self.anchors.setdefault(g, place.removeprefix("anchor "))
            seated = bool(srcs) and all(self._living(g) for g in srcs)
            if kind == "rows" and rel.end < ce and toks[rel.end].text == "of" and seated:
                self.rows_of[rel.end] = list(srcs)
            if kind.startswith("anchor ") and toks[rel.end - 1].text != "of":
                return rel.end  # "In the centre a huge spellbook floats ...": the noun after is the subject
            return end
        return None

    def _targets(self, c: _Clause, p: _Phrase, prev_subject, starts_with_rel) -> None:
        """The groups the phrase's target names: a possessive's side ("to her left"), "on top",
        "inside", "each one", "that one", a part ("in the water"), a person ("beside him"), "it" /
        "them", the last target of an elliptic phrase ("on either side"), then the second end of
        *between* ("and ...", "from A to B")."""
        toks, rel, kind, target, srcs, part = self.toks, p.rel, p.kind, p.target, p.srcs, p.part
        if kind in _OWN_SIDES and target is None:
            # "to its left", "to her left", "at its foot": the side of what the possessive names
            owner = next(t.text for t in toks[rel.start : rel.end] if t.text in _POSSESSED)
            kind, target = _OWN_SIDES[kind], _POSSESSED[owner]
            # "at its feet": of what has feet (the giraffe, not the fence named after it)
            p.part = part = next((t.text for t in toks[rel.start : rel.end] if t.text in load_vocabulary().part_owners), part)
        if kind == "on top" and target is None:
            kind = "on"
            target = "it" if c.head is not None else None
            rel = replace(rel, elliptic=True)
        if kind == "in" and target is None and toks[rel.start].text == "inside" and c.head is not None:
            target = "it"  # "a cage with a rabbit inside": inside the with-part's head
        targets: list[int] | str
        if target == "each one":
            if all(g in self.history for g in srcs) and any(g not in self.history for g in c.main):
                # "a register on the counter in front of each of them": one register each, not a counter
                srcs = [g for g in c.main if g not in self.history]
            prefer = list(c.last_target)
            if c.head and srcs and all(s in c.wsub for s in srcs) and any(self.groups[h].count > 1 for h in c.head):
                # "tombstones stand behind the jail with a crow perched on each": on each tombstone
                prefer = list(c.head)
            if not prefer and toks[p.end - 1].text == "them" and c.main and srcs == c.main:
                # "four lambs lie on the mats, and a girl kneels beside each of them": the lambs, as
                # "beside them" ("beneath each one" stays the latest group: the pegs, not the coats)
                prefer = list(dict.fromkeys(prev_subject))
            targets = self._pronoun("them", c, srcs, prefer)
            if targets:  # one per member for what this clause brings in, not for "the counter" named before
                self._per_each([s for s in srcs if s in c.groups and s not in self.history], targets[0])
        elif target == "that one":
            targets = self._one_of(c, srcs, prev_subject)
        elif target == "the part":  # "in the water": the latest thing that has such a part
            candidates = [*c.last_target, *reversed(c.groups), *prev_subject, *reversed(self.history)]
            targets = self._part_owner(part, [], [*candidates, *reversed(range(len(self.groups)))], srcs)
        elif target in _PERSONAL or target in ("them living", "it living"):
            # "a pirate stands behind the chest with a shovel beside him": the person, not the chest
            targets = self._person(c, srcs, target)
            if not targets and target in ("them living", "it living"):  # "to their left" of things: them
                targets = self._pronoun(target.split()[0], c, srcs, list(c.last_target))
        elif isinstance(target, str) and target != "each other":
            targets = self._pronoun_target(c, p, target, kind, srcs, prev_subject, starts_with_rel)
        elif target is None and kind in ("left", "right") and toks[rel.start].text == "on" and (
            c.last_target and c.last_target_end == rel.start
        ):
            # "a bench sits beneath a willow on the right": a side of the scene, which the
            # willow is on, not a side of the willow ("to the right" after it stays the willow's)
            targets = []
        elif target is None and (kind in ("left", "right", *_ELLIPTIC) or rel.elliptic):
            # "a bed with a nightstand on either side": a with-thing's side is its head's ("films the
            # tents from high above": above them)
            owner = list(c.head) if c.head is not None and srcs == c.wsub else []
            targets = list(c.last_target) or owner or [g for g in self.history[-1:] if g not in srcs]
        elif target is None:
            targets = []
        else:
            targets = target
        end, ce = p.end, p.ce
        span = ("to", "into", "onto")  # "guide a hose from it into a tank": it runs from one to the other
        if kind == "from" and end < ce and toks[end].text == "onto" and isinstance(targets, list) and targets:
            onto, end2 = self._target_at(end + 1, ce)
            if isinstance(onto, list) and onto:  # "unloads crates from the boat onto a handcart": on the handcart
                kind, target, targets, end = "on", onto, onto, end2
        if kind == "from" and end < ce and toks[end].text in span and isinstance(targets, list) and targets and (
            not self._side_to(end)
        ):
            kind = "between"  # "a conveyor carries ore from it to a refinery": between the two
        if kind == "between" and isinstance(targets, list) and targets and target != "them":
            # (between "them" is between the pair already: "with a table between them and a rug under it")
            if end < ce and toks[end].text in (span if rel.kind == "from" else ("and",)):
                second, end2 = self._target_at(end + 1, ce)
                if isinstance(second, list):
                    targets, end = targets + second, end2
        if isinstance(targets, list) and targets:
            for t in targets:
                if t in c.groups:
                    continue
                c.groups.append(t)
        p.rel, p.kind, p.target, p.srcs, p.targets, p.end = rel, kind, target, srcs, targets, end

    def _subject_pronoun(self, pronoun: str, candidates: list[int]) -> list[int]:
        """What a subject pronoun that opens a clause names among ``candidates`` (most recent
        first): "he"/"she" a person of that sex, "they" several living things, "it" a thing or an
        animal that is no person."""
        if pronoun in ("he", "she"):
            return self._named_by(pronoun, candidates)
        if pronoun == "they":
            return next(([g] for g in candidates if self.groups[g].count > 1 and self._living(g)), [])
        return next(([g] for g in candidates if not self._person_at(g)), [])

    def _named_by(self, pronoun: str, candidates: list[int]) -> list[int]:
        """The person "he" or "she" names among ``candidates``: one whose name says that sex first
        (a witch for "she", not the gnome before her), else the first who may be of it."""
        vocabulary = load_vocabulary()
        other = "he" if pronoun == "she" else "she"
        people = [g for g in dict.fromkeys(candidates) if self._person_at(g)]
        fits = [g for g in people if vocabulary.agrees(pronoun, self.groups[g].name.split()[-1])]
        sexed = [g for g in fits if not vocabulary.agrees(other, self.groups[g].name.split()[-1])]
        return (sexed or fits)[:1]

    def _pronoun_target(
        self, c: _Clause, p: _Phrase, target: str, kind: str, srcs: list[int], prev_subject, starts_with_rel
    ) -> list[int]:
        """What "it" / "them" after a phrase names: the with-part's head, else the clause's own
        last target, the subject before, what the sentence before was about (for a fronted
        phrase), with the exceptions a person, a hung head, a plural head and a till make."""
        rel, part = p.rel, p.part
        # "a bench in front of the swing, facing it": the clause's own last target first.
        # then the subject before ("a wagon waits behind the fountain, and a donkey is tied to
        # a post next to it": the wagon)
        own_subject = list(prev_subject) if c.main and srcs == c.main else []
        # ("a robot refills a coffee machine, and a drone hovers beside it": the machine)
        own_subject = [*self.acted_on[-1:], *own_subject] if own_subject and kind in _GROUND_KINDS else own_subject
        prefer = [*c.last_target, *prev_subject] if c.last_target else own_subject
        if target == "it" and c.last_kind == "between":
            # "a woman at a table between the pen and the press spreads a fleece on it": the pair is
            # "them"; "it" is what stands between them
            prefer = [*c.last_srcs, *prefer]
        if not srcs and c.opens and starts_with_rel:
            prefer = list(self.topic)  # "Behind them, five soldiers sit": them of the sentence before
        if target == "it" and kind == "on" and srcs and self._small(*srcs):
            # "a clerk sits at a desk across from the fireplace, with an inkwell on it": the desk he works at
            at = [self.worked_at[g] for g in [*prefer, *self.doers, *prev_subject] if g in self.worked_at]
            prefer = [*at[:1], *prefer]
        who = srcs or ([] if c.opens else list(prev_subject))  # "..., watching them": the subject before
        own = [t for s in who for t in c.supports.get(s, [])]
        # what one goes along is not where one goes ("tourists walk along the pier towards it": the ferry)
        toward = any(t.text in ("toward", "towards") for t in self.toks[rel.start : rel.end])
        path = list(c.last_target) if toward and c.last_kind == "along" else []
        # nor is "it" what the phrase right before placed the same things by ("three hives stand along
        # the fence behind it": behind the cottage named before, not the fence)
        chain = srcs and srcs == c.last_srcs and c.last_target_end == rel.start and kind in _GROUND_KINDS
        path += list(c.last_target) if target == "it" and chain else []
        prefer = [g for g in prefer if g not in path]
        targets: list[int] = (
            list(c.head) if c.head is not None else self._pronoun(target, c, who + own, prefer, kind, others=path)
        )
        # (a scarecrow or a mannequin has a person's shape but is "it")
        # ("a hound with a bell on its collar": an animal's own part is its, not something else's)
        own_part = part is not None and c.head is not None and all(
            self._living(h) and not self._person_at(h) for h in c.head
        )
        owner = c.head is not None and (c.head == [c.each] or own_part)
        # ("an old pony dozes under an oak, with a bucket beside it": a thing set by an animal is by it)
        owner = owner or (c.head is not None and kind in _GROUND_KINDS and all(
            self._living(h) and not self._person_at(h) for h in c.head
        ) and not any(self._living(g) for g in srcs))
        if c.head is not None and not owner and target != "them" and all(
            self._living(h) and self.groups[h].category == "figure"
            or (self._living(h) and self.catalogue[self.groups[h].category].shape != "figure") for h in c.head
        ):  # fmt: skip
            # "a man on the bench, with his terrier asleep under it": "it" is no person ("two monks blow
            # horns, with a drummer on either side of them": "them" are)
            # ("each camel has a bucket in front of it": the camel, as "each" made it the owner)
            targets = self._pronoun(target, c, srcs, prefer, kind, others=c.head)
        if p.body is not None and targets and not all(self._living(t) for t in targets):
            # "perches on the shoulder of one of them": of the people named, not their benches
            named = [*c.last_target, *reversed(c.groups), *prev_subject, *reversed(self.history)]
            living = [g for g in named if g not in srcs and self._living(g)]
            targets = [g for g in living if (self.groups[g].count > 1) == (target == "them")][:1] or targets
        below = [r[2] for r in self.relations if c.head and r[1] in c.head and r[0] == "above"]
        if below and all(self.groups[h].rests == "hanging" for h in c.head) and not any(
            self.groups[g].rests == "hanging" for g in srcs
        ):  # "a chandelier hangs above the table, with a bench on either side of it": the table
            targets = below[-1:]
        if c.head is not None and srcs == c.head:
            targets = self._pronoun(target, c, srcs, prefer)
        elif c.head is not None and target == "it" and all(self.groups[h].count > 1 for h in c.head):
            # "two tents, with a campfire in front of them and four logs around it": "it" is
            # no plural head but the single thing named last, before the with-part too ("benches
            # stand in front of the hall, with a flag on either side of it")
            # (not each one's, "each with a lamp above it", nor one member's "on top")
            written = self.toks[p.end - 1].text == "it"
            before = list(reversed(self.history)) if c.each is None and written else []
            single = [
                g for g in [*reversed(c.groups), *before]
                if g not in srcs and g not in c.head and self.groups[g].count == 1
            ]  # fmt: skip
            targets = single[:1] or targets
        elif c.head is not None and c.wsub_before and srcs == c.wsub and self._small(*srcs, c.wsub_before[-1]):
            targets = c.wsub_before[-1:]  # "... and a computer beside it": beside the till
        elif kind == "between" and target == "them" and targets == c.head and len(targets) == 1:
            # "a sofa faces a TV, with a coffee table between them": the head and what it faces
            recent = [*c.last_target, *reversed(c.groups), *list(reversed(self.history))[:2]]
            other = [g for g in recent if g not in srcs and g not in targets]
            pair = [targets[0], *other[:1]]
            targets = pair if len(pair) == 2 and all(self.groups[g].count == 1 for g in pair) else targets
        candidates = [*c.last_target, *reversed(c.groups), *prev_subject, *reversed(self.history)]
        if target == "it":  # ("two goats graze at its feet": one thing's, not theirs)
            candidates = [g for g in candidates if self.groups[g].count == 1]
        targets = self._part_owner(part, targets, candidates, srcs)
        placing = kind in ("in", "on", "from") and part is None and p.body is None
        if c.head is None and target in ("it", "them") and placing:
            targets = self._seat(c, srcs, prefer, rel.start, target == "them", kind == "in") or targets
        return self._peer(kind, srcs, targets, c)

    def _reversed_phrase(self, c: _Clause, p: _Phrase, prev_subject) -> int | None:
        """"A desk flanked by two lamps", "a snowmobile towing a sled": the target is placed by
        the thing before the phrase."""
        if p.kind not in _REVERSED:
            return None
        kind, targets = p.kind, p.targets
        head = p.srcs or list(prev_subject)
        if kind == "towing" and isinstance(targets, list):
            targets = [t for t in targets if not self._small(t)]  # "pulls a pint": no load behind
        # "a tow truck hauls a hatchback onto its flatbed": a load pulled onto the puller itself rides it
        onto = kind == "towing" and [t.text for t in self.toks[p.end : p.end + 2]] in (
            ["onto", "its"], ["onto", "it"], ["into", "its"], ["into", "it"]
        )
        if onto and isinstance(targets, list) and targets and head and p.end in self.rel_at:
            for h in head:
                self._relate("on", targets, h)
            c.produced, c.expect_new = True, False
            c.last_target, c.last_target_end = [], -1
            return self._target_at(self.rel_at[p.end].end, p.ce)[1]  # (past "onto its flatbed")
        if isinstance(targets, list) and targets and head:
            active = _REVERSED[kind]
            if c.each is not None:  # "three tables, each surrounded by two chairs": two per table
                self._per_each([t for t in targets if t != c.each], c.each, c.each_unit)
            for t in targets:
                for h in head:
                    self._relate(active, [t], h)
                    if kind == "towing":
                        self.towed[h] = t
            c.produced = True
            c.rels.append((kind, targets))
            if c.head is None:
                # "guarded by a skeleton sitting on a barrel": what comes next is the skeleton's; but
                # a load trails its puller, so where "a pony pulls a cart" goes ("between two
                # shafts", "past the pond", "towards the gate") is the pony's
                c.main = list(head) if kind == "towing" else list(targets)
        c.last_target, c.last_target_end, c.expect_new = [], -1, False
        return p.end

    def _without_sources(self, c: _Clause, p: _Phrase, prev_subject, starts_with_rel) -> int | None:
        """A phrase with nothing before it to place: fronted, it waits for the clause's subject
        ("Behind the chair, a hologram floats"); later in a clause it places the subject before;
        "steam rises from a food cart" places the cart."""
        if p.srcs:
            return None
        kind, target, targets, end = p.kind, p.target, p.targets, p.end
        if starts_with_rel and c.opens and kind == "on a carrier":
            return end  # "Across the bridge, a troll waits": on its far side, no place of the layout
        if starts_with_rel and c.opens and not c.produced and isinstance(targets, list) and targets:
            tm = self.by_start.get(self._target_start) if isinstance(target, list) else None
            c.fronted.append((kind, targets, tm is not None and tm.each, p.ordinals or (None,)))
            if isinstance(target, list):  # "On a mound behind the giraffes, ...": the mound is behind them
                c.last_target, c.last_target_end, c.last_kind = targets, end, kind
            return end
        if starts_with_rel and c.opens and not c.produced and kind == "flank" and not targets:
            c.fronted.append((kind, [], False, (None,)))  # "On either side of the temple door stands a lion": two
            return end
        if not c.first and not c.unknown_subject:
            p.srcs = list(prev_subject)
        elif (kind == "from" or kind == "on" and not self._verb_before(p.rel.start, self._posture)) and (
            isinstance(target, list) and targets
        ):  # (one nobody listed who sits on a stool is someone: "the master of the mint sits on a stool")
            # "steam rises from a food cart next to the stall", "tagliatelle dries on racks on either side
            # of the table": steam and pasta are no things, the cart and the racks are placed
            c.main = c.main_groups = list(targets)
            c.last_target, c.last_target_end, c.last_kind = list(targets), end, kind
            return end
        return None

    def _mutual(self, start: int) -> bool:
        """Whether "each other" or "one another" comes right before ``start``."""
        return [t.text for t in self.toks[max(0, start - 2) : start]] in (["each", "other"], ["one", "another"])

    def _place(self, c: _Clause, p: _Phrase) -> int:
        """Relate the sources to the targets, one per member where "each" / "every" says so, and
        keep what the clause's next phrase chains on."""
        toks, rel, kind, target, targets, srcs, end = self.toks, p.rel, p.kind, p.target, p.targets, p.srcs, p.end
        # "a fiddler and a piper stand on either side of the stage": one a side, each once
        one_each = kind in ("flank", "flank elliptic") and len(srcs) == 2
        one_each = one_each and all(self.groups[g].count == 1 for g in srcs)
        if kind in ("flank", "flank elliptic") and not toks[rel.start].text.startswith("flank") and not one_each:
            # (counted on "each" side: that many a side, "two players stand on each side of the net")
            apiece = any(t.text == "each" for t in toks[rel.start : rel.end])
            # ("long tables ... with benches on both sides": a pair for every table)
            owners = self.groups[c.head[0]].count if c.head and isinstance(targets, list) and targets == c.head else 1
            self._one_a_side(srcs, apiece=apiece, owners=owners)  # also by no object: "on each side of the elevator"
        if kind == "end of elliptic":
            kind = "end of"  # "a long bench ...; a lady sits at one end": of the thing just named
        seats = kind == "end of" and bool(srcs and targets) and all(self._carrier(t, ("seats",)) for t in targets)
        if seats and all(self._living(g) for g in srcs) and self._verb_before(
            rel.start, lambda w: w in load_vocabulary().postures["sitting"] or w in load_vocabulary().postures["lying"]
        ):
            kind = "on"  # "an old man sits at one end of the bench": on it, at that end
        hang = kind == "hanging from" or self._hung_before(rel.start)
        hang = hang or any(t.text in _HANG_VERBS for t in toks[rel.start : rel.end])  # "hangs over the bar"
        if hang and kind in ("above", "over", "hanging from") and self._from_ceiling(rel.start):
            for g in srcs:  # "three paper lanterns hang from the ceiling over the counter": hung, not set down
                if self.groups[g].rests != "hanging" and not self._living(g):  # also "a birdcage hangs from the ceiling"
                    self.groups[g].rests = "hanging"
        if kind in ("above", "over") and target is None and self._on_floor(rel.end):
            for g in srcs:  # "an airship floats above the floor": up in the air, over what stands below
                if not self._living(g):
                    self.groups[g].rests = "hanging"
        if kind == "under" and self._covered(srcs, targets):
            return end  # "a patient asleep under a white blanket": covered where they lie, no place by it
        if kind == "on" and target is None and self._on_floor(rel.end):
            for g in srcs:  # "a helmet sits on the floor beneath each peg": on no table or desk
                if self.groups[g].rests == "surface" and not self._living(g):
                    self.groups[g].rests = "ground"
        if not srcs or not targets:
            if target is None and c.last_target and c.last_target_end == rel.start:
                # "fill two shelves on the wall behind her": the shelves are behind her ("a woman in a
                # red parka holding a stopwatch": up to the participle, which is hers)
                while end < p.ce and end not in self.rel_at and end not in self.by_start and toks[end].text not in (",", "and"):
                    if toks[end].text.endswith("ing") and end + 1 < p.ce and toks[end + 1].text in _DETERMINERS:
                        break
                    end += 1
                c.last_target_end = end
            return end
        if targets == "each other":
            # "face each other", "sit across from each other" (in front of and facing, each way)
            each_other = kind if kind in ("face to", "opposite") else "near"
            for s in srcs:
                self.relations.append((each_other, s, s, None))
            if len(srcs) == 2:  # "a goldfish stall and a takoyaki stall face each other": two groups
                self._relate(each_other, srcs[1:], srcs[0])
                if each_other in ("face to", "opposite"):
                    self._relate(each_other, srcs[:1], srcs[1])
            c.produced = True
            return end
        assert isinstance(targets, list)
        own = rel.end < len(toks) and toks[rel.end].text in _PERSON_POSSESSIVES
        devices = all(self._small(t) and not self.catalogue[self.groups[t].category].support for t in targets)
        seated = self._verb_before(rel.start, self._posture)  # ("sits on his toolbox": on it)
        if kind == "on" and own and devices and not seated and all(self._person_at(g) for g in srcs):
            # "two parents watch the race on their phones": one's own small thing one does something on
            # is in hand, as "chat on their phones" has it
            for s in srcs:
                self._relate("on", targets, s)
            self.carried.update((t, s) for t in targets for s in srcs)
            c.produced = True
            return end
        instance = self.instance.get(self._target_start) if isinstance(target, list) else None
        one_of = [t.text for t in toks[rel.end : rel.end + 2]] == ["one", "of"]
        if instance is None and one_of and len(targets) == 1 and self.groups[targets[0]].count > 1:
            # "a dog lies at the foot of one of them": of the first, not of them all
            instance = 0
        if target == "that one" and self.groups[targets[0]].count > 1:  # "in front of the middle one"
            named = [t.text for t in toks[rel.end : end] if t.text not in _DETERMINERS and t.text not in ("one", "on")]
            instance = self._member(named, targets[0])
        tm = self.by_start.get(self._target_start) if isinstance(target, list) else None
        # (a target named anew, or said to be its own: "each in a leather seat", "each at its own low table")
        fresh = tm is not None and (not tm.definite or tm.own and self.groups[targets[0]].count == 1)
        if c.each_own is not None and fresh and not tm.each:
            srcs = [c.each_own]
            for t in targets:
                self._per_each([t], c.each_own)
            c.each_own = None
        if tm is not None and tm.each:  # "a candle on every table": one per table
            self._per_each([s for s in srcs if s in c.groups], targets[0])
        elif fresh and c.each is not None and c.each in srcs and tm.count <= 1:
            self._per_each(targets, c.each)  # "each in a leather seat": one seat apiece
        elif tm is not None and kind == "on" and self._bare(tm) and len(srcs) == 1 and self._living(srcs[0]):
            self._per_each(targets, srcs[0])  # "two soldiers on horseback": a horse each
        elif tm is not None and len(srcs) == 1 and self._uncounted_new(tm) and self._apiece(tm):
            self.groups[targets[0]].count = self.groups[srcs[0]].count  # "two lawyers at separate tables": one each
        elif tm is not None and kind in ("on", "in") and len(srcs) == 1 and self._living(srcs[0]) and (
            self._seats_each(tm) or self._seat_apiece(srcs[0], tm)
        ):
            # "four astronauts sit on stools": one each (seats named before keep any more they had);
            # "eight children sit on benches": as many to a bench as its length seats
            seat, sitter = self.groups[targets[0]].size[0], self.groups[srcs[0]].size[0]
            bench = seat >= _BENCH_LENGTH and self._carrier(targets[0], ("seats",)) and sitter > 0
            per = max(1, int(seat / sitter)) if bench else 1
            seats = self.groups[targets[0]].count if tm.definite else 0
            self.groups[targets[0]].count = max(-(-self.groups[srcs[0]].count // per), seats)
        elif tm is not None and kind == "on" and len(srcs) == 1 and self._stands_each(srcs[0], tm):
            self.one_each[targets[0]] = srcs[0]  # "busts stand on pedestals (at each corner)": one each
        elif tm is not None and kind == "in" and len(srcs) == 1 and self._planted(srcs[0]) and self._uncounted_new(tm):
            self.groups[targets[0]].count = self.groups[srcs[0]].count  # "four fig trees in planters": one each
        elif tm is not None and kind == "under" and len(srcs) == 1 and self._uncounted_new(tm) and (
            self.groups[targets[0]].category == "pendant_lamp"
        ):
            # "four tables under bright lamps": one over each
            self.groups[targets[0]].count = self.groups[srcs[0]].count
        elif tm is not None and toks[rel.start].text == "over" and len(srcs) == 1 and self._person_at(srcs[0]) and (
            self._uncounted_new(tm) and self._handheld(targets[0])
        ):
            self.groups[targets[0]].count = self.groups[srcs[0]].count  # "two hackers hunch over laptops": one each
        elif tm is not None and kind == "at" and len(srcs) == 1 and self._person_at(srcs[0]) and (
            self._uncounted_new(tm) and self.groups[targets[0]].category in _ONE_AT_A_TIME
        ):
            self.groups[targets[0]].count = self.groups[srcs[0]].count  # "eight students stand at easels": one each
        elif tm is not None and kind == "hanging from" and len(srcs) == 1 and self._hooks_each(tm):
            self.groups[targets[0]].count = self.groups[srcs[0]].count  # "a dozen lanterns hang from posts": one each
        sitter = self._seat_owner(c, srcs, tm) if tm is not None else None
        if sitter is not None:
            self._relate("on", [sitter], targets[0], instance=instance)
        for g in srcs if p.parts_each and p.part is not None else []:
            if g in c.groups and g not in self.numbered and self.groups[g].count == 1:
                self.groups[g].count = p.parts_each
        if kind == "on" and p.body is None and all(self._person_at(g) for g in [*srcs, *targets]):
            kind = "near"  # "a nurse checks on a patient": by another person, never on one
        if kind in ("on", "on top") and p.body is None:
            srcs = self._carried_in(srcs)
        # "lanterns hang from the branches of an oak": on it, up in its crown, as what perches there;
        # by no side of it when the text says what they hang above ("... of the oak above the table")
        crown = kind == "hanging from" and any(
            "tree" in load_vocabulary().part_owners.get(singular(w.text), ()) for w in toks[rel.end : end]
        )
        over = crown and getattr(self.rel_at.get(end), "kind", None) in ("above", "over")
        for t in targets if not over else ():
            for one in p.ordinals or (instance,):
                if one_each:
                    self._relate("left of", srcs[:1], t, hang, one)
                    self._relate("right of", srcs[1:], t, hang, one)
                else:
                    self._relate("on" if crown else kind, srcs, t, hang, one)
            # a person holds nothing on top, but carries what is on a knee or an arm ("a crow on each of
            # its arms": a scarecrow's too)
            limb = p.part is not None and load_vocabulary().body_parts.get(p.part) == "on" and self._person_at(t)
            if p.body == "on" or (limb and kind == "on"):
                self.carried.update((s, t) for s in srcs)
            elif kind == "hanging from" and self._thin(t):
                self.carried.update((s, t) for s in srcs)  # "a lantern hangs from a post": it carries it
        for t in targets if p.riders else ():
            self._relate(kind, p.riders, t)
        if kind == "at" and targets:
            self.worked_at.update((s, targets[-1]) for s in srcs if self._living(s))
        c.produced = True
        c.rels = [(kind, targets)]
        if kind == "driving":
            c.main = list(targets)  # "drives a quad bike, towing a trailer": the bike tows it
        if kind in ("on", "in", "on top"):
            for s in srcs:
                c.supports.setdefault(s, []).extend(targets)
        c.last_srcs = list(srcs)
        c.last_kind = "between" if rel.kind == "between" else kind  # "between two trees to the left of"
        if isinstance(target, list):
            c.last_target, c.last_target_end = targets, end
            c.target_after_verb = c.finite
        else:
            c.last_target, c.last_target_end = [], -1
        c.expect_new = True
        return end

    def _carried_in(self, srcs: list[int]) -> list[int]:
        """What goes on a thing when living things already in a container are put there: the
        container ("a parrot in a cage perches on the desk": the cage is on the desk)."""
        holders = [next((t for k, s, t, _ in self.relations if s == g and k in ("in", "on")), None) for g in srcs]
        if all(h is not None and self._living(g) and self._carrier(h, ("containers",)) for g, h in zip(srcs, holders)):
            return list(dict.fromkeys(holders))
        return srcs

    def _seats_each(self, m: _Mention) -> bool:
        """Seats or ground covers named in the plural with no count of their own, new here ("on
        padded stools", "stretch on mats"): as many as sit or lie on them."""
        cover = m.group >= 0 and self.catalogue[self.groups[m.group].category].shape == "rug"
        # ("sit around the fire on logs": any low lifeless thing sat on is a seat)
        low = m.group >= 0 and not self._living(m.group) and self.groups[m.group].size[2] <= _MAKESHIFT_HEIGHT
        # ("bob on inflatable rings", "ride on horses", "race on bicycles": one carries one)
        one_rider = m.group >= 0 and max(self.groups[m.group].size[:2]) <= _MAKESHIFT_LENGTH and (
            low or self._carrier(m.group, ("mounts", "vehicles"))
        )
        sat = (low and self._verb_before(m.start, self._posture) or one_rider) and m.group not in self.formations
        # ("rows of seats ... Twenty children lie back in the seats": the seats named before, uncounted)
        # (a count "rows of" seats got is the rows' guess; not benches: "sit on the benches along the walls")
        guessed = m.group >= 0 and (m.group not in self.numbered or m.group in self.formations)
        again = _is_plural(self.toks, m) and m.definite and guessed and self.groups[m.group].size[0] < _ONE_SEAT_WIDTH
        return (self._uncounted_new(m) or again) and (self._carrier(m.group, ("seats",)) or cover or sat)

    def _said_before(self, pos: int, test) -> bool:
        """Whether a word before ``pos`` in its sentence passes ``test`` (given the word's index)."""
        k = pos - 1
        while k >= 0 and self.toks[k].text not in (".", "!", "?"):
            if test(k):
                return True
            k -= 1
        return False

    def _seat_apiece(self, g: int, m: _Mention) -> bool:
        """A seat named once, new here, for sitters the text gave one of to each of a group ("a
        controller sits at each one on a swivel chair"): a seat of their own each."""
        if m.group < 0 or self.groups[m.group].count != 1 or not self._carrier(m.group, ("seats",)):
            return False
        k = m.start - 1
        while k > 0 and m.start - k < 4 and self.toks[k].text not in _DETERMINERS and self.toks[k].text not in _STOP:
            k -= 1  # back over its describing words ("a comfy stool")
        apiece = any(src == g for src, _ in self.pair_each) and self.groups[g].count > 1
        return apiece and self.toks[k].text in ("a", "an")

    def _planted(self, g: int) -> bool:
        """Several plants: each grows in a pot, tub or planter of its own."""
        category = self.groups[g].category
        plant = self.catalogue[category].shape in _PLANT_SHAPES or category == "potted_plant"
        return self.groups[g].count > 1 and plant

    def _stands_each(self, g: int, m: _Mention) -> bool:
        """Several things on stands named in the plural with no count, new here, each stand no
        wider than one of them ("busts on pedestals", "vases on plinths"): a stand each."""
        thing, stand = self.groups[g].size, self.groups[m.group].size if m.group >= 0 else (0, 0)
        several = self.groups[g].count > 1 and not self._living(g)
        return several and self._uncounted_new(m) and stand[0] * stand[1] <= thing[0] * thing[1]

    @staticmethod
    def _apiece(m: _Mention) -> bool:
        """Whether its describing words give each of several its own ("separate tables")."""
        return bool(_APIECE & {a.lower() for a in m.adjectives})

    def _uncounted_new(self, m: _Mention) -> bool:
        """A plural with no count of its own, new here ("in clay pots", "on stools")."""
        return (
            _is_plural(self.toks, m) and not m.counted and not m.definite and m.group >= 0
            and m.group not in self.numbered
        )  # fmt: skip

    def _at_on_perch(self, c: _Clause, rider: list[int], kind: str, target) -> bool:
        """Whether the living subject "at" a thing the phrase puts on a low wide perch stands on
        that perch too ("a priest stands at an altar on a dais", "a vendor waits at a stall on the
        pier")."""
        if c.last_kind != "at" or kind not in ("on", "on top") or not isinstance(target, list) or not target:
            return False
        return bool(rider) and all(self._living(g) and self._platform(target[0], g) for g in rider)

    def _sits_on_instead(self, c: _Clause, rider: list[int], p: _Phrase) -> bool:
        """Whether an ``on`` / ``in`` phrase after a place of a sitting or lying living thing seats
        that thing, not the place: the place's footprint is larger than the seat's, so the seat
        cannot carry it ("sits beneath the bridge on a mossy boulder", "sleeps under the table on
        a cushion")."""
        if p.kind not in ("on", "in") or not isinstance(p.target, list) or not p.target or not rider:
            return False
        if not all(self._living(g) for g in rider) or not self._verb_before(p.rel.start, self._posture):
            return False
        if c.last_kind == "around":  # "sit around a campfire on logs": a ring is not sat on
            return True
        place, seat = self.groups[c.last_target[0]].size, self.groups[p.target[0]].size
        return place[0] * place[1] > seat[0] * seat[1]

    def _hooks_each(self, m: _Mention) -> bool:
        """Thin things named in the plural with no count of their own, new here, that things hang
        from ("lanterns hang from posts", "flags fly from poles"): one for each."""
        return (
            _is_plural(self.toks, m) and not m.counted and not m.definite and m.group >= 0
            and m.group not in self.numbered and self._thin(m.group)
        )  # fmt: skip

    def _thin(self, g: int) -> bool:
        """A post, a pole, a hook: too narrow on top to put anything on, only to hang it from."""
        return max(self.groups[g].size[:2]) < _NARROW_TOP

    def _rider_placed(self, c: _Clause, rider: list[int], kind: str, pos: int) -> bool:
        """Whether a phrase after "a person sits on X" places the person, not X: what the person
        faces after any target ("kneels at a low table across from the vats", "ponies tied to a
        fence across from the caravans"), where the person works ("sits on a stool at a
        workbench"), after a seat or a perch what the person is between ("in folding chairs between
        them", "stands on a platform between the first two"; "dozes on a cushion between the rack and
        the stove" places the cushion), and after a seat, what the person sits under, behind or at the
        foot of ("rest on a bench at the foot of a cross", "lounges in
        an armchair behind the desk": one works behind a desk as at it; but "a cat naps in a basket
        at the foot of the stove" places the basket); after "under", what one sits on ("sits
        beneath the bridge on a boulder"). A person on a makeshift seat (:meth:`_makeshift_seat`) is
        also what a place on the ground places: the bucket or the bale comes along under them ("a
        diver rests on a sledge beside it", "judges sitting on hay bales in front of it", "lies on a
        creeper beneath it"). Beside, near, in front of otherwise place the seat: furniture is set
        out by the designer ("a bard sits on a stool beside the fire"), and what an animal perches on
        was there before it ("a gull on a bollard beside the boat")."""
        if not rider or not all(self._living(g) for g in rider):
            return False
        if kind in ("opposite", "face to"):
            return True
        if c.last_kind == "under" and kind in ("on", "in"):
            return True  # "a troll sits beneath the bridge on a boulder": the troll is on it, not the bridge
        if c.last_kind not in ("on", "in", "on top"):
            return False
        seat = all(self.catalogue[self.groups[g].category].shape in _SEATS for g in c.last_target)
        perch = all(self._carrier(g, ("perches",)) for g in c.last_target)
        people = all(self._person_at(g) for g in rider)
        if people and c.last_kind in ("on", "in") and kind in (*_GROUND_KINDS, "under") and all(
            self._makeshift_seat(g, self._verb_before(pos, self._posture)) for g in c.last_target
        ):
            return True
        # (an animal's seat was there before it: "a cat watches from a stool at the foot of the counter")
        return kind == "at" or ((seat or perch) and kind == "between") or (
            seat and people and kind in ("under", "behind", "foot of")
        )

    def _makeshift_seat(self, g: int, seated: bool) -> bool:
        """A low perch, container or vehicle no bigger than a seat for one that is no piece of
        seating (an upturned bucket, a hay bale, a sledge, a crate), or, ``seated`` (a verb of sitting
        or lying before), any lifeless thing that low and small ("lies on a creeper"); not a stool, a
        motorbike, a pillar or a stage."""
        size = self.groups[g].size
        seat = self.catalogue[self.groups[g].category].shape in _SEATS or self._carrier(g, ("seats",))
        perch = self._carrier(g, ("perches", "containers", "vehicles")) or (seated and not self._living(g))
        return perch and not seat and size[2] <= _MAKESHIFT_HEIGHT and max(size[:2]) <= _MAKESHIFT_LENGTH

    def _seen_doing(self, c: _Clause, rel: _Rel, between: list[str], last_event_end: int) -> bool:
        """Whether the phrase tells what the things one watches or sees do: a verb right after them
        ("watching a swarm of bats circle the chandelier", "watches two jugglers perform beside the
        fountain"), the phrase's own word or one word before it; they, not the watcher, are placed."""
        if c.last_kind != "face to" or not c.last_target or c.last_target_end != last_event_end:
            return False
        if not self._verb_before(last_event_end, lambda w: w in load_vocabulary().lookout_verbs):
            return False
        words = [w for w in between if w not in _ADVERBS]
        if not words:
            return self.toks[rel.start].text not in _STOP
        return len(words) == 1 and words[0] not in _STOP and words[0][:1].isalpha()

    @staticmethod
    def _describes(words: list[str], after_verb: bool) -> bool:
        """Whether the words between a target and the next phrase open a description of the target:
        a relative pronoun ("a customer who lies back in the chair"), or a participle once the
        subject has its own verb ("a guard waves at a lorry idling at the barrier"; but "a dog on
        the rug sleeping by the fire" is the dog's)."""
        if not words or any(w in (",", "and", "or", "with", "while") for w in words):
            return False
        if words[0] in _RELATIVES:
            return True
        return after_verb and (_participle(words[0]) or words[0] in _STATES)

    @staticmethod
    def _landform(g: _Group) -> bool:
        """Whether ``g`` is a landform named by its own word ("two cliffs"): no rocks said later are it."""
        return singular(g.name.split()[-1].lower()) in load_vocabulary().landforms

    @staticmethod
    def _kin_size(cat: Category, kind: list[str], head: str) -> tuple[float, float, float] | None:
        """A person named with a kind of person of their own build is that build: "a dwarf smith"
        is a dwarf's height, "a troll guard" a troll's (not "a puppet master", who works them)."""
        if cat.shape != "figure" or len(kind) != 1 or head in _WORKS_ITS_KIND:
            return None
        kin = load_vocabulary().match((kind[0],))
        return kin.size if kin is not None and load_catalogue()[kin.category].shape == "figure" else None

    def _seat_after(self, rel: _Rel, mentions: list[_Mention]) -> bool:
        """A seat right after "from": whatever one does from a seat, one sits on it ("a servant
        plays the organ from a narrow bench"), unless a small thing taken from it comes right
        before ("takes a cushion from the sofa")."""
        seat = next((m for m in mentions if rel.end <= m.start < rel.end + 4), None)
        taken = any(m.end == rel.start and max(self._size(m)) <= _HANDHELD_SIZE for m in mentions)
        return seat is not None and not taken and load_vocabulary().carries(seat.category, seat.phrase, ("seats",))

    def _destination(self, end: int, starts: set[int]) -> bool:
        """"To" names where one goes with what one carries or leads ("carries a tray to the table",
        "leads the mare to the trough") when a thing follows it and a verb of going or carrying comes
        before it in the clause; not an infinitive ("stops to drink"), a receiver ("gives it to her")
        or the end of a span ("from the gate to the barn")."""
        k = end + 1 if end < len(self.toks) and self.toks[end].text in _DETERMINERS else end
        while k < len(self.toks) and k not in starts and self.toks[k].text in load_vocabulary().adjectives:
            k += 1  # "carries a bucket of tar to a long workbench"
        span = any(t.text == "from" for t in self.toks[max(0, end - 7) : end - 1])
        way = end >= 2 and self.toks[end - 2].text in ("up", "down")  # "a ladder that leads up to a hatch": a way
        return k in starts and not span and not way and self._verb_before(end - 1, lambda w: w in _CARRY_VERBS)

    def _from_to(self, start: int, starts: set[int]) -> bool:
        """"From it to a refinery", "from the gate to the barn", "from it into a tank": a thing, then
        "to" (or "into", "onto") and another thing; what runs or carries from one to the other is between them."""
        k = start
        span = ("to", "into", "onto")
        while k < len(self.toks) and k - start < 6 and self.toks[k].text not in span:
            if not self.toks[k].text[:1].isalnum():
                return False
            k += 1
        return k < len(self.toks) and self.toks[k].text in span and k > start and self._names_thing(start, starts) and (
            self._names_thing(k + 1, starts)
        ) and not self._side_to(k)

    def _side_to(self, k: int) -> bool:
        """The "to" at ``k`` opens a side ("from a platform to the left of the tower": the platform
        is left of it), no end of a span."""
        after = [t.text for t in self.toks[k + 1 : k + 3]]
        return self.toks[k].text == "to" and (after[:1] in (["left"], ["right"], ["one"]) or after in (
            ["the", "left"], ["the", "right"], ["the", "side"], ["either", "side"], ["each", "side"]
        ))

    def _drives(self, r: _Rel, mentions: list[_Mention]) -> bool:
        """A vehicle follows a driving verb ("drives a quad bike", "steers the barge"): the driver
        is aboard. What one drives otherwise is herded, not ridden ("a collie drives the sheep").
        After a describing word the verb's word is the vehicle's kind ("a striped paddle boat")."""
        before = self.toks[r.start - 1].text if r.start else "."
        after = self.toks[r.end].text if r.end < len(self.toks) else "."
        # (a verb has its subject before it and no "of" after: "Rows of seats stretch ...")
        described = before in _DETERMINERS or load_vocabulary().is_adjective(before)
        if not before[:1].isalpha() or described or after == "of":
            return False
        start = r.end
        m = next((m for m in mentions if m.start >= start), None)
        between = [t.text for t in self.toks[start : m.start]] if m else []
        near = m is not None and all(w in _DETERMINERS or (w[:1].isalpha() and w not in _STOP) for w in between)
        return near and load_vocabulary().carries(m.category, m.phrase.lower(), ("vehicles",))

    def _names_thing(self, start: int, starts: set[int]) -> bool:
        """A noun phrase of a thing follows ("at each desk"), not a time or a part ("at one end")."""
        k = start
        while k < len(self.toks) and k - start < 4:
            w = self.toks[k].text
            if k in starts or w in ("it", "them") or (k == start and self._body_part_at(k, len(self.toks), starts)):
                return True  # "at each desk", "at it", "at his feet"
            if k == start and w in _OWNER_PRONOUNS and k + 1 < len(self.toks) and self.toks[k + 1].text.isalpha():
                return True  # "queuing at its window": by its owner
            if w == "one" and (k > start + 1 or k > start and self.toks[start].text in ("each", "every")):
                return True  # "playing at the nearest one", "sits at each one": one of a group
            if w == "one" and k + 1 < len(self.toks) and self.toks[k + 1].text == "of":
                return True  # "argue at one of them": one of a group named before
            if w == "each" and (k + 1 == len(self.toks) or not self.toks[k + 1].text[:1].isalpha()):
                return True  # "two desks, with five players at each": at each of them
            # ("at three tables": a count before the noun)
            opener = w in _DETERMINERS or w in ("each", "every") or w in _NUMBERS
            if not (opener or (w[:1].isalpha() and w not in _STOP)):
                return False
            k += 1
        return False

    def _setting_after(self, start: int, ce: int) -> bool:
        """The words from ``start`` name the setting ("behind the camp" in "A desert camp"), no thing."""
        words = [t.text for t in self.toks[start : min(ce, start + 4)]]
        while words and (words[0] in _DETERMINERS or load_vocabulary().is_adjective(words[0])):
            words = words[1:]
        return bool(words) and any(singular(words[0]) == place.split()[-1] for place in self.places)

    def _anchor_after(self, start: int, ce: int) -> str | None:
        """The part of the room a phrase with no object names ("along the back wall" → wall)."""
        for t in self.toks[start : min(ce, start + 4)]:
            if t.text in ("wall", "walls"):
                return "wall"
            if t.text in ("corner", "corners"):
                return "corner"
        return None

    def _per_each(self, srcs: list[int], target: int, unit: int = 1) -> None:
        """As many of each source as it says, for every one (every ``unit``: a pair) of the target
        group; one for every one when it says no number of living things ("children bounce on
        every one of them"; "cartons fill every shelf" are a few a shelf)."""
        for src in srcs:
            if (src, target) not in self.pair_each:
                if src not in self.numbered and self.groups[src].count == UNCOUNTED and self._living(src):
                    self.groups[src].count = 1
                every = max(1, self.groups[target].count // unit)
                self.groups[src].count *= every
                self._stacks_apiece(src, every)
                self.pair_each.add((src, target))

    def _stacks_apiece(self, g: int, every: int) -> None:
        """A stack said once for each of ``every`` things is that many stacks ("two cannons, each
        with a stack of cannonballs beside it"), not one stack of all their balls."""
        if self.formations.get(g) == "stack":
            self.lines[g] = self.lines.get(g, 1) * every

    def _one_a_side(self, srcs: list[int], sides: int = 2, row: bool = False, apiece: bool = False,
                    owners: int = 1) -> None:
        """"A lamp post on each side of the door": one thing named for both sides means two; so do
        things the text does not count ("trunks sit on either side of the table"); on every side of
        a thing, four; things that run along every side make a row on each ("arches run along
        every side": as many a side as an uncounted plural names); several counted ``apiece`` ("two
        players on each side of the net") are that many on every side; things nobody counted by
        each of several ``owners`` are a pair for each ("tables with benches on both sides")."""
        for s in srcs:
            uncounted = s not in self.numbered and self.groups[s].count == UNCOUNTED
            if (self.groups[s].count == 1 or uncounted) and s not in self.history:
                self.groups[s].count = sides * (UNCOUNTED if row and uncounted else owners if uncounted else 1)
            elif apiece and s in self.numbered and self.groups[s].count > 1 and s not in self.history:
                self.groups[s].count *= sides

    def _rung(self, r: _Rel, mentions: list[_Mention]) -> bool:
        """"A monk sits on the steps ringing a bell": a tabletop thing that is "rung" is rung by hand,
        no ring around it ("standing stones ringing the pool", "caravans ring a campfire" are)."""
        if self.toks[r.start].text not in ("ring", "rings", "ringing"):
            return False
        m = next((m for m in mentions if r.end <= m.start <= r.end + 3), None)
        if m is None:
            return False
        record = m.guess if m.guess is not None else self.catalogue[m.category]
        return record.rests == "surface" and not self._lives(m.category)

    def _covers(self, r: _Rel) -> bool:
        """Whether a verb of covering ("crowd", "cover", "line") is one here: a noun phrase follows
        it ("vases crowd three shelves", "jars crowd every shelf"), not a verb or "of" ("a noisy
        crowd gathers", "crowds of tourists"), and it is no noun after an article."""
        after = self.toks[r.end].text if r.end < len(self.toks) else ""
        return after in _DETERMINERS or after in _NUMBERS or after in _VAGUE

    def _hung_before(self, pos: int, then: str | None = None) -> bool:
        """A hanging (or turning) verb earlier in the same clause part ("three lanterns hang from the
        ceiling over the counter": the over is hung, not a tree leaning over; "a hologram turns above
        the table"), with the word ``then`` right after it when given ("hang from")."""
        k = pos - 1
        while k >= 0 and pos - k <= 8 and self.toks[k].text not in (",", ".", ";", "and", "while"):
            if self.toks[k].text in _HANG_VERBS or self.toks[k].text in _TURN_VERBS:
                return then is None or (k + 1 < pos and self.toks[k + 1].text == then)
            k -= 1
        return False

    def _from_ceiling(self, pos: int) -> bool:
        """"From the ceiling" (or a beam, the rafters) earlier in the clause part, or right here."""
        k = pos - 1
        while k >= 0 and pos - k <= 8 and self.toks[k].text not in (",", ".", ";", "and", "while"):
            k -= 1
        return any(self.toks[i].text in _CEILING_WORDS for i in range(k + 1, min(pos + 4, len(self.toks))))

    def _on_floor(self, pos: int) -> bool:
        """"On the floor", "on the bare ground" at ``pos``: the ground itself (no object), where a
        small thing set down stands on no host."""
        for t in self.toks[pos : pos + 3]:
            if t.text in _FLOOR_WORDS:
                return True
            if not t.text[:1].isalpha():
                return False
        return False

    def _relate(self, kind: str, srcs: list[int], target: int, hang: bool = False, instance=None) -> None:
        for s in srcs:
            if s in self.apiece and self.groups[target].count == self.groups[s].count:
                instance = None  # ("his helmet on the floor beside the bed": each by his own)
            resolved = self._kind(kind, s, target, hang)
            # "a horse pulls a plough, and a farmer walks behind it": behind the plough, the train's
            # tail, and so behind the horse too
            seen, t = {s}, target
            while resolved == "behind" and t in self.towed and self.towed[t] not in seen:
                seen.add(t)
                if s != t:
                    self.relations.append((resolved, s, t, instance))
                t = self.towed[t]
            if resolved == "on":
                s = self._ridden(s, t)
            if s == t or resolved == "no relation":
                continue
            self.relations.append((resolved, s, t, instance))

    def _mountable(self, s: int) -> bool:
        """Whether a standing thing also comes fixed to a wall, so "above" a thing names it up there
        ("a sign above the counter", "a shelf above the desk"): a flat board (a sign, a panel) or a
        storage unit that has a wall form (:data:`WALL_UNIT_HEIGHTS`); a tree or a tower does not."""
        g = self.groups[s]
        return min(g.size[:2]) <= _FLAT_DEPTH or g.category in WALL_UNIT_HEIGHTS

    def _kind(self, kind: str, s: int, t: int, hang: bool = False) -> str:
        src = self.groups[s]
        target = self.catalogue[self.groups[t].category]
        if kind == "over":
            # a tree leaning over a pond stands by it; a lamp or a lantern over a table hangs above it;
            # a pot or a cauldron over a fire sits on it; a rider over a bridge (no more than a platform
            # high) is on it
            vessel = src.rests == "surface" or self._carrier(s, ("containers",))
            if not hang and vessel and not target.support and self.groups[t].size[2] <= _LOW_HOST:
                return "on"
            if vessel and target.shape == "fireplace":
                return "in front of"  # "a cauldron hanging over the fireplace": in its hearth, over the fire
            low = self.groups[t].size[2] <= _PLATFORM_HEIGHT
            # ("two aliens haggle over a crate", "a clerk bends over the ledger": by it, not on it)
            bent = self._verb_before(self._target_start, lambda w: _verb_stem(w, _OVER_VERBS))
            if not hang and self._living(s) and self._carrier(t, ("perches",)) and low and not bent:
                return "on"
            return "above" if hang or src.rests in ("hanging", "surface") else "near"
        if kind == "crossing":
            # "a bridge crosses the pond", "a fox crosses the bridge": on what is low enough to cross
            # (a pronoun that missed the stream and found the hill beside it crosses nothing)
            low = self.groups[t].size[2] < _LOW_HOST or self._carrier(t, ("perches",)) and not self._tall_perch(t)
            # ("two knights cross swords": what is held is crossed in hand, no ground to cross)
            return "on" if low and not self._living(t) and not self._handheld(t) else "no relation"
        walled = any(m.group == s for k, m in self.by_start.items() if k in self.on_wall)
        # ("a parasol above her head": held up over someone)
        held_up = self._person_at(t) and load_vocabulary().carried_by_hand(src.category, src.name)
        # ("a dragon circles above the tower": up in the air, as the clause's flying makes it afterwards)
        flying = self._winged(s) and self._verb_before(self._target_start, lambda w: w in _FLIGHT)
        if kind == "above" and src.rests == "ground" and src.size[2] > 1.5 and not (
            hang or walled or self._mountable(s) or held_up or flying
        ):
            return "near"  # a tree "above" a pond cannot float: read it as near (a rack on the wall can hang)
        if kind == "leaning on" and self._person_at(s) and target.shape == "tool" and max(self.groups[t].size) <= _TOOL_SIZE:
            self.carried.add((t, s))
            return "in hand"  # "the caretaker leans on his mop": he holds it (he leans on a fence by it)
        if kind == "under" and self._overhead(t):
            return "under hung"  # "chairs under a ceiling fan": the fan hangs above them
        if kind == "under":  # "a rug under the table" lies flat under it; "mice under the table" are by it
            flat = self.groups[s].size[2] < 0.1 and target.size[2] < 1.5 and not self._living(s)
            return "under flat" if flat else "near"
        if kind == "at":  # "an office chair at each desk": pulled up to it, facing it
            seat = self.catalogue[src.category].shape in _SEATS
            return "at seat" if seat and (target.support or target.shape in ("desk", "table", "counter")) else "near"
        if kind == "on top":  # "a cat on the top shelf": on the bookshelf the shelf is of
            return "on"
        if kind == "foot of":  # "a chest at the foot of the bed", "a box at the foot of its steps": its front
            return "in front of"
        if kind == "head of":  # the headboard is a bed's back
            if target.shape in ("bed", "sofa", "bench"):
                return "behind"
            if target.support:
                return "left of"  # the head of a table is one of its ends
            return "near"
        if kind == "in":  # "a man in a rocking chair", "a duck floats in the tub", "children in the bus": on it
            if self._part in _THRESHOLDS:
                return "near"  # "a tailor works in the doorway of his shop": at its edge, by it
            if self._living(s) and target.shape in _ENCLOSURES and self.groups[t].size[2] < _HUTCH_HEIGHT:
                return "on"  # "a dog in each kennel", "hens in the coop": a hutch holds them as a cage does
            if self._living(s) and target.shape in _ENCLOSURES and self._carrier(t, ("perches",)):
                return "on"  # "a band plays in the bandstand": an open shelter's floor carries them
            if hang and not self._living(s) and (target.shape == "tower" or self._carrier(t, ("perches",))):
                return "on"  # "a bell hangs in the small tower": the tower carries it, as a post would
            if target.shape in _ENCLOSURES or target.shape == "tower":
                return "no relation"  # in a tent, in the lighthouse: inside it, out of the layout
            if self._living(s) and (self._carrier(t, _VESSEL_KINDS) or self._carrier(t, by_family=False)):
                return "on"  # (in a guessed structure, a dome or an igloo, one is inside it)
            if self._living(s) and self._perch_part:
                return "on"  # "a pilot strapped into its seat", "in the cockpit of the glider": on what has it
            if self.catalogue[src.category].shape in _PLANT_SHAPES and self.groups[t].category == "planter":
                return "on"  # "orange trees grow in terracotta planters": each stands in its own
            # (in its branches, or small beside it: not "a healing house grown inside a living tree")
            up = self._part is not None or max(src.size) < self.groups[t].size[2] / 2
            if not self._living(s) and self._carrier(t, ("perches",)) and target.shape in _PLANT_SHAPES and up:
                return "on"  # "a platform sits high up in a tall pine", "a kite caught in the oak": up in its crown
            if self._living(s) and (target.shape == "bush" or target.shape == "flower_bed" and not self._person_at(s)):
                return "near"  # "a heron stands in the reeds", "a boy hides in the bushes": among them
                # (one stands in a bed of flowers: "a scarecrow stands in the last patch")
            holds = target.shape in _SEATS or target.support or self._carrier(t, _VESSEL_KINDS)
            # ("three salamanders bask in a brazier": a small creature is on what it is in)
            holds = holds or self._living(s) and not self._living(t) and max(src.size) < max(self.groups[t].size)
            return "on" if holds and target.size[2] <= 2.5 else "no relation"
        if kind == "hitched":  # "a cart hitched to a horse" trails it; "a mule stands hitched to a cart" pulls it
            return "in front of" if self._living(s) and not self._living(t) else "behind"
        if kind == "driving":
            return "on" if self._living(s) else "no relation"  # "a farmhand drives a quad bike": aboard it
        if kind in ("from", "on a carrier"):
            # "a heron watches from a rock", "a guard waves from the tower", "a peacock struts across
            # its roof", "a cat peeks out of the box": on it; one who watches or waves from what
            # carries nobody stands by it ("watches them from the gate"), as one who runs across it;
            # one drinks, eats or pours from a thing by it ("a cat drinks from a puddle", "stegosaurs
            # drink from a trough")
            perch = self._carrier(t, ("perches",)) or self._perch_part
            taken = kind == "from" and self._verb_before(
                self._target_start,
                lambda w: (w, "from") in _HAND_PAIRS and (not perch or w in _CONSUMING and not self._perch_part),
            )  # (not a perch: "two children feed ducks from a footbridge" are on it, as "drink from its rim")
            # ("a vendor sells fruit from a cart": by what one sells from, a cart or a stall)
            taken = taken or kind == "from" and self._verb_before(self._target_start, lambda w: w in _WARES_VERBS)
            # ("fishermen unload crates from a trawler": they stand by what they take things from)
            taken = taken or kind == "from" and self._verb_before(
                self._target_start, lambda w: _verb_stem(w, _TAKING_VERBS)
            )
            bird = self.catalogue[src.category].shape == "bird"  # ("a crow watches from the weathervane")
            # (a likeness watches as the living do: "a marble bust watches them from a plinth")
            watcher = self._living(s) or self.catalogue[src.category].shape == "statue"
            if watcher and (self._carrier(t) or self._perch_part or bird) and not taken:
                return "on"
            if kind == "from" and self._part in _ROOF_PARTS:
                return "on"  # "a dish points at the sky from the roof of the hut": fixed up there
            return "near" if self._living(s) else "no relation"
        if kind == "hanging from":
            # from a beam: above it; from a tree: beside it; from anything else (a post, a stall, a
            # barrier, a tower's railing) it is carried by that thing, on it
            if any(w in _CEILING_WORDS for w in self.groups[t].name.split()):
                return "above"
            return "near" if target.shape in _PLANT_SHAPES else "on"
        if kind == "end of":  # "a cushion at the end of the counter": on it; "a chest at the end of the bed": at its foot
            if src.rests == "surface" and target.support or self._platform(t, s):
                return "on"  # ("a lighthouse at the end of the pier": on the pier)
            return "in front of" if target.shape == "bed" else "near"  # "a barrow at the end of the patch"
        if kind == "along" and src.rests == "surface" and (target.support or target.shape in _LOAD_HOSTS):
            return "on"  # "bottles along the bar": on it, as at its end or centre
        if kind == "along" and self._living(s) and (self._platform(t, s) or self._part in _ROOF_PARTS):
            return "on"  # "six frogs sit along a wooden jetty", "a cat slinks along the roof of the boxcar": on it
        if kind == "covering":
            # "jars crowd every shelf", "crates cover a long table", "lasts lining a shelf": on what
            # has a top for them; "trees line the drive" stand beside it; people crowding a carrier
            # ("tourists crowd the pier") are on it, and in seats they fill ("spectators fill the
            # seats"), by anything else near it
            if self._living(s):
                return "on" if self._carrier(t) or target.shape in _SEATS else "near"
            flat = self.groups[t].size[2] <= FLAT_HOST
            # ("cabbages fill the raised beds": grown in a bed, they are on it)
            bedded = target.shape == "flower_bed" and self.groups[s].rests == "surface"
            return "on" if target.support or target.shape in _LOAD_HOSTS or flat or bedded else "side of"
        if kind == "centre of":  # "a vase in the middle of the table", "a throne in the centre of the stage": on it
            if src.rests == "surface" and target.support:
                return "on"
            # "a basket in the middle of the picnic blanket": a cover on the ground holds anything
            cover = self.groups[t].rests == "ground" and self.groups[t].size[2] < 0.1
            return "on" if cover or self._platform(t, s) else "near"
        return _KIND_RELATION.get(kind, kind)


def _refer_forward(toks: list[_Tok], mentions: list[_Mention]) -> None:
    """"Holding up a book for the children to see. Nine children sit on a rug": a definite plural
    nothing before names (or an uncounted one in the opening's words) is the counted group the
    text introduces later, which then refers back to it (its count is theirs), rather than three more."""
    for m in mentions:
        # (or a plural of the opening that names no count: "A fishing contest among frogs. Six frogs sit ...")
        opening = _verbless_opening(toks, m.start) and not any(t.text in (".", "!", "?", ":") for t in toks[: m.start])
        if not ((m.definite or opening) and not m.counted and _is_plural(toks, m)):
            continue
        head = singular(m.phrase.split()[-1].lower())
        same = [o for o in mentions if o.category == m.category and singular(o.phrase.split()[-1].lower()) == head]
        if same[0] is not m:
            continue  # named before: an ordinary reference back
        later = next((o for o in same[1:] if o.counted and not o.definite), None)
        if later is not None:
            later.definite = True
