"""What people and animals have in hand and what they act on: a thing used, worked with or
taken from is in the doer's hand ("eats a sandwich", "practises with five clubs", "sipping coffee
from a paper cup"), a thing acted on is one the doer stands by ("plays it from a bench",
"scrubs its back"), and "from" a perch is where the doer is. A mixin of
:class:`~scenewright.analysis.parser.reader._Reader`."""

from __future__ import annotations

from typing import TYPE_CHECKING

from scenewright.analysis.parser.grammar import _COPULAS, _PERSON_POSSESSIVES, _RIDDEN
from scenewright.analysis.parser.nouns import _Mention, _is_plural
from scenewright.analysis.parser.phrases import _Rel
from scenewright.analysis.parser.vocabulary import load_vocabulary, replica
from scenewright.analysis.parser.words import (
    _AIM_VERBS,
    _BEAR_VERBS,
    _DEFINITE,
    _DETERMINERS,
    _GIVE_VERBS,
    _HAND_PAIRS,
    _HAND_VERBS,
    _HANG_VERBS,
    _HOLD,
    _LEAD_VERBS,
    _LEAVING_VERBS,
    _TAKING_VERBS,
    _NOT_IN_HAND,
    _NUMBERS,
    _ORDINALS,
    _PUT_OR_WORKED,
    _RECORD_VERBS,
    _STOP,
    _USE_VERBS,
    _WARES_VERBS,
    _is_verb,
    _verb_stem,
)
from scenewright.core.catalogue import load_catalogue, singular

if TYPE_CHECKING:
    from scenewright.analysis.parser.reader import _Clause

#: How long (m) an animal is to be what its person stands by ("a girl leads a camel", "a herdsman
#: waits with two cows": by the animals), where a smaller one keeps by its person ("a man walks
#: a dachshund", "a girl with her dog").
_HERD_LENGTH = 1.0
#: m, the longest side at least of a carrier someone can be on while they work (not a plate or a bowl).
_RIDEABLE = 0.5

#: Participles of a thing left somewhere that do not end in -ed ("his rifle laid across the rock").
_LEFT_PARTICIPLES = {"laid", "set", "left", "put", "stuck", "leaning", "lying", "resting", "standing", "propped"}
#: Participles of a thing still in its owner's hand ("his sword raised", "her lantern held high").
_HELD_PARTICIPLES = {"raised", "held", "drawn", "clutched", "gripped", "lifted", "aloft", "brandished", "shouldered",
                     "levelled", "leveled", "outstretched", "out", "up", "high", "ready"}  # fmt: skip

#: The verbs of the hand tables: verbs, whatever their ending says ("play", "carry").
_DEED_VERBS = _USE_VERBS | _HAND_VERBS | _HOLD | _LEAD_VERBS | _GIVE_VERBS

#: The most a thing one works "on" in hand takes up, in m³ (a tablet, a flute; not a monitor, a till
#: or a microscope, which stay where they stand).
_DEVICE_VOLUME = 0.02


class _Hands:
    def _tool_after(self, k: int, ce: int) -> int | None:
        """Where the thing starts that a person has in hand as the word at ``k`` says: "with" right
        after a verb or its object ("practises with five clubs", "stirring it with a long paddle"),
        or the preposition of a hand pair ("sipping coffee from a paper cup", "counting coins out
        of a pouch", "sketching on a clipboard"); None when it says no such thing, or what follows
        is too big to work with."""
        w = self.toks[k].text
        rel = self.rel_at.get(k)
        device = False
        if rel is not None and (w, self.toks[rel.end - 1].text) in _HAND_PAIRS:
            end = rel.end  # "peering through a loupe": a phrase of its own (near), but the loupe is in hand
        elif w == "with":
            # (past where the verb takes its thing from: "draws water from the pump with a bucket")
            end = k + 1 if self._after_verb(k, over=("from", "off", "out", "of"), worn=True) else None
        elif any(p == w for _, p in _HAND_PAIRS) and self._pair_before(k):
            end = k + 2 if w == "out" and k + 1 < ce and self.toks[k + 1].text == "of" else k + 1
            device = w == "on"  # ("writes on a clipboard" in hand, "types on a computer" at it)
        elif w == "on" and self._device_verb_before(k):
            end, device = k + 1, True  # "films it on a tablet", "plays a tune on a flute"
        else:
            return None
        thing = self._hand_object(end, ce, tool=True) if end is not None else None
        if thing is None or self._placed_by_pronoun(thing.end, ce):
            return None  # "fanning a stove with a kettle on it": the stove's, not in hand
        if device and not self._device(thing):
            return None  # "reads a book on the bench", "sharpens a knife on a whetstone": where, not with what
        return end

    def _acting_verb(self, k: int, held: bool = False) -> str | None:
        """The verb before the phrase word at ``k`` in the same clause part, with at most what it
        acts on between (with ``held``, nothing small enough to hold); None when there is none, or
        another phrase or such a thing comes first."""
        j = k - 1
        while j >= 0 and k - j <= 5 and self.toks[j].text not in (",", ".", ";", "and", "while"):
            w = self.toks[j].text
            # (a verb of looking opens a phrase of its own and still acts: "films it on a tablet")
            looking = j in self.rel_at and self.rel_at[j].kind == "face to" and _is_verb(w)
            if j in self.rel_at and not looking or (held and j in self.by_start and self._hand_object(j, k) is not None):
                return None
            verb = self._participle_at(j) or self._finite_at(j) or (_is_verb(w) and w not in _STOP)
            if verb and j not in self.named_at:
                return w
            j -= 1
        return None

    def _device_verb_before(self, k: int) -> bool:
        """A verb a person does with a small thing "on" which at ``k`` comes before it in the same
        clause part, with nothing in hand between ("films it on a tablet", "plays a tune on a
        flute"; "sharpens a knife on a whetstone" works the knife there), or a verb of writing down
        ("noting every crate on a clipboard"): no posture, placing or work in place ("sits on a
        cushion", "sets a cup on a tray", "chops onions on a board")."""
        w = self._acting_verb(k, held=True)
        if w is None:  # ("noting every crate on a clipboard": the crates are what is written down)
            w = self._acting_verb(k)
            return w is not None and _verb_stem(w, _RECORD_VERBS)
        return not (_verb_stem(w, _PUT_OR_WORKED) or self._still(w))

    def _works_on(self, k: int, target, inside: bool = False) -> bool:
        """Whether a person's verb "on" a thing that carries nobody, at ``k``, is work done at it,
        not standing on it ("a chef slices bread on a board", "two mechanics work on the engine";
        but "reads a book on the bench": a seat, "stands on a crate": a posture, "stretch on mats": a
        cover on the ground); with ``inside``, "in" it, when the verb acts on something there and
        it is no seat, vehicle or perch ("rinses rice in a tub", "washes shirts in the sink"; not
        "splashes in a tub", "reads a book in the armchair")."""
        w = self._acting_verb(k)
        if inside and (w is None or self.toks[k - 1].text == w):
            return False
        # (what one is "in" while working: a seat, a vehicle, a perch; not a tub or a pen)
        kinds = ("seats", "vehicles", "mounts", "perches") if inside else None
        # (a cover on the ground carries whoever is on it: "two girls stretch on mats")
        carrier = isinstance(target, list) and target and (
            self._carrier(target[0], kinds) or self.catalogue[self.groups[target[0]].category].shape == "rug"
        )
        # (a plate or a bowl carries no one who works at it: "a cook ladles soup onto a plate"; a stool does;
        # nor does a part of a thing one stands on no part of: "work on the engine of the plane")
        if carrier and max(self.groups[target[0]].size[:2]) < _RIDEABLE and not self._carrier(target[0], ("seats",)):
            carrier = False
        of = next((j for j in range(k + 1, self._target_start) if self.toks[j].text == "of"), None)
        if carrier and of is not None and singular(self.toks[of - 1].text) not in load_vocabulary().carriers.get("perches", ()):
            carrier = False
        return w is not None and isinstance(target, list) and bool(target) and not carrier and not self._still(w)

    @staticmethod
    def _still(w: str) -> bool:
        """A verb of posture, being or hanging: one done where one is ("sits", "is", "dangles")."""
        return load_vocabulary().is_posture_verb(w) or w in _COPULAS or w in _HANG_VERBS

    def _device(self, m: _Mention) -> bool:
        """A tabletop thing that holds nothing and carries nobody (a tablet, a flute, a notepad), light
        enough to lift: what one does something "on" with it in hand ("types on a computer" is done
        at the desk)."""
        record = m.guess if m.guess is not None else self.catalogue[m.category]
        rests = self.groups[m.group].rests if m.group >= 0 else record.rests
        x, y, z = self.groups[m.group].size if m.group >= 0 else record.size
        return rests == "surface" and not getattr(record, "support", False) and x * y * z <= _DEVICE_VOLUME

    def _used_at(self, k: int, ce: int) -> bool:
        """Whether the word at ``k`` is a verb a person does with the thing right after it in hand:
        any verb but those of :data:`_NOT_IN_HAND` or looking out, when the thing is small
        enough to hold ("checks a wristwatch next to the kiosk": in hand, and he is by the kiosk;
        "turning a small jug"; "two men haul a trunk up the stairs")."""
        w = self.toks[k].text
        if k in self.named_at or k in self.content_at or w in _STOP or w in _COPULAS or not w.isalpha():
            return False
        vocabulary = load_vocabulary()
        aimed = _verb_stem(w, _AIM_VERBS)  # ("points from the tower" is looking out, "points a camera" aims it)
        # (a posture verb that takes a thing small enough to hold has it in hand: "balances a tray")
        if _verb_stem(w, _NOT_IN_HAND) or w in vocabulary.lookout_verbs and not aimed:
            return False
        verb = w.endswith("ing") or _is_verb(w) or self._finite_at(k)
        # (what one aims is a tool or a weapon, as long as a pitchfork)
        held = self._hand_object(k + 1, ce, tool=True) if aimed else self._used_object(k, ce)
        return verb and w not in _HANG_VERBS and held is not None

    def _one_thing_after(self, k: int, ce: int) -> bool:
        """The noun phrase right after ``k`` names one thing ("a trunk", not "trunks", "two trunks"
        or "a pair of oars")."""
        m = self._next_mention(k + 1, ce)
        return m is not None and m.count <= 1 and not _is_plural(self.toks, m)

    def _bearer_before(self, k: int) -> int | None:
        """The person named right before a participle of holding or use at ``k``, or before "who"
        and such a verb, with no comma between: the one who holds ("ducks gather around a boy
        holding a loaf": the boy's, not the ducks'; "talking to a biker who holds her helmet";
        "..., holding a lamp" after a comma is the subject's); the thing a relative pronoun
        right before a verb of holding follows ("a post that holds a lantern")."""
        w = self.toks[k].text
        if w in _HOLD and k > 0 and self.toks[k - 1].text in ("that", "which") and k - 1 in self.ends:
            # "skaters glide around a pillar that holds up a disco ball": the pillar bears it
            return next((m.group for m in self.by_start.values() if m.end == k - 1 and m.group >= 0), None)
        who = k > 0 and self.toks[k - 1].text == "who" and w in _DEED_VERBS
        end = k - 1 if who else k
        end = self._dressed_end(end)
        end = self.renamed_end.get(end, end)  # ("their coach, a woman holding a stopwatch": the coach's)
        if not (who or w.endswith("ing") and w in _DEED_VERBS) or end not in self.ends:
            return None
        named = next((m.group for m in self.by_start.values() if m.end == end and m.group >= 0), None)
        return named if named is not None and self._person_at(named) else None

    def _dressed_end(self, end: int) -> int:
        """Where the person ends whom the clothes before ``end`` dress ("a woman in a red parka
        holding a stopwatch": the woman), else ``end``."""
        j = end - 1
        while j > 0 and end - j <= 5 and self.toks[j].text not in ("in", "wearing") and j not in self.named_at:
            if not self.toks[j].text[:1].isalpha():
                return end
            j -= 1
        dressed = self.toks[j].text in ("in", "wearing") and j < end - 1
        return j if dressed and (j in self.ends or j in self.renamed_end) else end

    def _keeps_by(self, g: int, h: int) -> tuple[int, int]:
        """(who stands near whom) for two living things that go together, ``g`` named with or led
        by ``h``: a person stands by livestock and mounts, which hold their place; a pet, or one
        person with another, keeps by the one the text pairs it with."""
        animal = self.groups[g]
        herd = not self._person_at(g) and max(animal.size[:2]) >= _HERD_LENGTH and self._person_at(h)
        return (h, g) if herd else (g, h)

    def _borne(self, g: int, h: int) -> bool:
        """A small thing an animal or a robot has with it is on it, as a person's is in hand: what
        it wears, carries or has in its mouth ("three mules, each with a bell", "a dog with a
        ball", "a robot with a tray of drinks"); nothing as big as the animal ("a horse with a
        cart"). (A robot's arms are parts, no things: "a robot with six arms".)"""
        animal, thing = self.groups[h], self.groups[g]
        return (
            self._living(h) and not self._person_at(h) and self._handheld(g)
            and max(thing.size) < 0.5 * max(animal.size)
        )  # fmt: skip

    def _hand_object(self, start: int, ce: int, tool: bool = False, used: bool = False) -> _Mention | None:
        """The thing named right after ``start`` when a person can have it in hand (with ``tool``,
        one they work with; with ``used``, one they have in hand while doing something with it:
        "eats a sandwich")."""
        m = self._next_mention(start, ce)
        if m is None:
            return None
        if m.group >= 0:
            size, rests = self.groups[m.group].size, self.groups[m.group].rests
        else:
            record = m.guess if m.guess is not None else self.catalogue[m.category]
            size, rests = record.size, record.rests
        words = {t.text for t in self.toks[m.start - len(m.adjectives) : m.end]}
        toy = self._lives(m.category) and bool(words & load_vocabulary().replica_words)  # ("hugs a toy penguin")
        size = replica(size) if toy else size
        return m if self._holdable(m.category, m.phrase, size, rests, tool, used, toy) else None

    def _used_object(self, k: int, ce: int) -> _Mention | None:
        """What the verb at ``k`` has in hand, named right after it: a thing a person can carry
        after a verb of taking it up in one's arms ("lifts a crate"), a hand-sized one after any
        other ("eats a sandwich", "plays a guitar"; "cleans a barrel" is done by the barrel)."""
        return self._hand_object(k + 1, ce, used=not _verb_stem(self.toks[k].text, _BEAR_VERBS))

    def _next_mention(self, start: int, ce: int) -> _Mention | None:
        """The noun phrase right after ``start``, past its determiners and describing words."""
        k = start
        while k < ce and k - start < 5:
            if k in self.by_start:
                return self.by_start[k]
            w = self.toks[k].text
            if w == "of" and self.toks[k - 1].text in ("pair", "couple"):
                k += 1  # "lifts a pair of binoculars": the pair is the thing
                continue
            if w in _STOP and w not in _DETERMINERS and w not in _NUMBERS or not w[:1].isalpha():
                return None
            k += 1
        return None

    def _pair_before(self, k: int) -> bool:
        """A verb of a hand pair with the preposition at ``k`` before it in the same clause part,
        no other phrase between ("types at a computer on the counter" is no typing on it)."""
        j = k - 1
        while j >= 0 and k - j <= 6 and self.toks[j].text not in (",", ".", ";", "and", "while"):
            if (self.toks[j].text, self.toks[k].text) in _HAND_PAIRS:
                return True  # (the verb may open a phrase itself: "watching the ships through a spyglass")
            if j in self.rel_at:
                return False
            j -= 1
        return False

    def _placed_by_pronoun(self, end: int, ce: int) -> bool:
        """A phrase right after a thing, or after the list it opens, places it by "it" or "them" ("a
        kettle on it", "with an inkwell and three quills on it")."""
        while end < ce and self.toks[end].text in (",", "and") and (m := self._next_mention(end + 1, ce)) is not None:
            end = m.end
        rel = self.rel_at.get(end)
        return rel is not None and rel.end < ce and self.toks[rel.end].text in ("it", "them", "its", "their")

    def _list_end(self, end: int, ce: int) -> int:
        """Where a list of things that goes on from a thing ending at ``end`` ends ("an inkwell
        and three quills", "a cup, a spoon and a fork")."""
        while end < ce and self.toks[end].text in ("and", ","):
            m = self._next_mention(end + 1, ce)
            if m is None:
                break
            end = m.end
        return end

    def _placed_after(self, end: int, ce: int) -> bool:
        """A relation phrase right after a thing, or after one word that describes it ("a bible
        open on a lectern", "an urn beside each bench")."""
        # ("an official with a flag sits on a snowmobile", "two peasants with pitchforks shout at the
        # foot of the tree": the subject's verb, the official sits there)
        word = self.toks[end].text if end < ce else ""
        verb = _is_verb(word) or (end < ce and self._finite_at(end))  # ("with lamp": nothing after it)
        return end in self.rel_at or (end + 1 < ce and word.isalpha() and not verb and end + 1 in self.rel_at)

    def _after_verb(self, k: int, over: tuple[str, ...] = (), worn: bool = False) -> bool:
        """Whether the word at ``k`` comes right after a verb, or after a verb and what it acts on
        ("practises with", "scrubs its back with", "tapping a heel with"), not after a noun phrase
        of its own ("a woman in a coat with ..."); the words ``over`` may lie between too
        ("forks straw into it", "pushes the front one"); with ``worn``, a verb in -s after what
        the doer wears ("a trader in a turban argues with"), which names no object."""
        j = k - 1
        while j >= 0 and k - j <= 6:
            w = self.toks[j].text
            finite = worn and _is_verb(w) and w not in _STOP and j not in self.named_at and j not in self.content_at
            if self._participle_at(j) or self._finite_at(j) or finite:
                return w not in _COPULAS
            owned = j > 0 and (self.toks[j - 1].text.endswith("'s") or self.toks[j - 1].text in _DETERMINERS)
            if owned and w[:1].isalpha():
                j -= 1  # "scrubs the calf's back with", "polishes its hull with": the part acted on
                continue
            if w in _STOP and w not in _DETERMINERS and w not in ("it", "them") and w not in over or not w[:1].isalpha():
                return False
            j -= 1
        return False

    def _participle_at(self, j: int) -> bool:
        """A verb in -ing that is no describing word of a noun ("stirring it", not "a rocking chair")."""
        return self.toks[j].text.endswith("ing") and j + 1 not in self.by_start and j not in self.named_at

    def _finite_at(self, j: int) -> bool:
        """A verb right after its subject ("a juggler practises", "two scouts sharpen"): a word
        after a noun phrase that is no phrase word, no noun and no describing word."""
        w = self.toks[j].text
        # ("feed", "weed" end as past participles do, "play", "carry" as "rusty" does, but are no
        # describing words; "two elves clean a crate", "they empty the nets": a describing word
        # in its plain form right before an article or a possessive is a verb, where a participle
        # still describes: "lasts lining a shelf")
        nxt = self.toks[j + 1].text if j + 1 < len(self.toks) else ""
        acts = (nxt in _DEFINITE or nxt in ("a", "an")) and not w.endswith(("ing", "ed"))
        describing = load_vocabulary().is_adjective(w) and not w.endswith("eed") and w not in _DEED_VERBS and not acts
        verb = w not in _STOP or _is_verb(w)  # ("sits", "stands" are stop words of noun phrases)
        return j in self.ends and j not in self.by_start and w.isalpha() and verb and not describing

    def _acts_from(self, k: int) -> bool:
        """Whether the "from" at ``k`` says where a doer is: after a verb of selling, a vehicle or a
        thing with a top right after ("sells fruit from a cart"); or after a verb and what it acts
        on, when that is named by a pronoun, lives or is too big to hold ("plays it from a narrow
        bench", "two children feed ducks from a footbridge"; not "pulls a rope from the barrel")."""
        perch = self._next_mention(k + 1, len(self.toks))
        sold_from = perch is not None and perch.start <= k + 3 and self._verb_before(k, lambda w: w in _WARES_VERBS)
        if sold_from and (
            load_catalogue()[perch.category].support
            or load_vocabulary().carries(perch.category, perch.phrase, ("vehicles",))
        ):
            return True  # by the cart, the stall or the table one sells from (not "from baskets")
        part_of = k + 3 < len(self.toks) and self.toks[k + 1].text in _DETERMINERS and self.toks[k + 3].text == "of"
        if perch is None and part_of:
            perch = self._next_mention(k + 4, len(self.toks))  # "from the back of a hay cart": the cart's
        ridden = perch is None or load_vocabulary().carries(perch.category, perch.phrase, _RIDDEN)
        if self._perch_part_after(k):
            return self._after_verb(k, worn=True)
        if not self._after_verb(k, worn=True) or not ridden:
            return False  # ("feeds the goats from a bucket": what the feed comes out of)
        j = k - 1
        while j >= 0 and k - j <= 6:
            w = self.toks[j].text
            if w in ("it", "them", "him", "her"):
                return True
            m = self.by_start.get(j)
            if m is not None:
                # ("blows a whistle from a lifeguard chair": where one sits; not "takes a cup from the chair")
                seat = perch is not None and load_vocabulary().carries(perch.category, perch.phrase, ("seats",))
                seat = seat and not self._verb_before(k, lambda w: _verb_stem(w, _TAKING_VERBS))
                return self._lives(m.category) or self._hand_object(j, k) is None or seat
            if self._finite_at(j) or self._participle_at(j):
                # the verb, acting on nothing named: what one does up there ("a fiddler plays from the
                # back of a hay cart"), not where one leaves ("climbs from the cab")
                return perch is not None and j == k - 1 and not _verb_stem(w, _LEAVING_VERBS)
            j -= 1
        return False

    def _perch_part_after(self, k: int) -> bool:
        """A part one perches on, of a thing, right after ``k``: "from the fountain's rim", "from
        the rim of the trough" (not the thing itself: "pulls a rope from the barrel")."""
        toks, parts = self.toks, load_vocabulary().carriers.get("perches", ())
        reach = min(len(toks), k + 6)
        end = next((j for j in range(k + 1, reach) if not toks[j].text[:1].isalnum()), reach)
        return any(
            singular(toks[j].text) in parts
            and (toks[j - 1].text.endswith("'s") or (j + 1 < end and toks[j + 1].text == "of"))
            for j in range(k + 2, end)
        )

    def _aimed_at(self) -> list[_Rel]:
        """"Aims a pitchfork at them", "points a torch at the door": the thing aimed is in hand
        (:meth:`_used_at`), so the "at" phrase after it turns its holder to the target rather than
        standing the thing by it."""
        out = []
        for k, rel in self.rel_at.items():
            thing = next((m for m in self.by_start.values() if m.end == k), None)
            if rel.kind != "at" or thing is None:
                continue
            j = thing.start - len(thing.adjectives) - 1
            while j >= 0 and (self.toks[j].text in _DETERMINERS or self.toks[j].text in _NUMBERS):
                j -= 1
            if j >= 0 and _verb_stem(self.toks[j].text, _AIM_VERBS) and self._hand_object(j + 1, k, tool=True):
                out.append(_Rel("face to", k, rel.end))
        return out

    def _left_by_owner(self, mentions: list[_Mention]) -> None:
        """", his lance planted in the grass", "and her bicycle parked nearby": a person's thing in
        an absolute phrase (after a comma or "and", its participle next) that nothing places is
        left by its owner, the latest person of the sentence the possessive agrees with; in hand
        when the participle says it is held ("his sword raised"), whatever the rest of the phrase
        says ("their rods out over the water": where the holders reach, not where the rods stand)."""
        placed = {r[1] for r in self.relations if r[0] != "face to"} | {g for g, _ in self.carried}
        vocabulary = load_vocabulary()
        for k, m in enumerate(mentions):
            j = m.start - len(m.adjectives) - 1
            if m.content or m.group < 0 or j < 1 or m.end >= len(self.toks):
                continue
            owned, after = self.toks[j].text, self.toks[m.end].text
            absolute = self.toks[j - 1].text in (",", "and") and owned in _PERSON_POSSESSIVES
            participle = after.endswith(("ed", "en")) or after in _LEFT_PARTICIPLES
            group = self.groups[m.group]
            raised = after in _HELD_PARTICIPLES and self._holdable(group.category, group.name, group.size, group.rests, True)
            if not absolute or self._living(m.group) or not (participle and m.group not in placed or raised):
                continue
            for before in reversed(mentions[:k]):
                if any(t.text in (".", ";", "!", "?") for t in self.toks[before.end : m.start]):
                    break
                g = before.group
                if g >= 0 and self._person_at(g) and vocabulary.agrees(owned, self.groups[g].name.split()[-1]):
                    if raised:
                        self.relations[:] = [r for r in self.relations if r[1] != m.group or r[0] == "face to"]
                        self.carried.add((m.group, g))
                    self.relations.append(("on" if raised else "near", m.group, g, None))
                    break

    def _taken_from(self) -> list[_Rel]:
        """"Lifts a tray from the counter", "two porters lift cases off it", "takes a jar out of
        the cabinet": a small thing taken from something too big to hold puts the one who takes
        it by that thing (a "near" phrase of their own; the thing is in hand), or on it when it
        carries people ("launches a kite from the pier")."""
        toks, out = self.toks, []
        for k, tok in enumerate(toks):
            if tok.text not in ("from", "off", "out") or (k in self.rel_at and self.rel_at[k].kind != "from"):
                continue
            end = k + 2 if tok.text == "out" and k + 1 < len(toks) and toks[k + 1].text == "of" else k + 1
            if tok.text == "out" and end == k + 1:
                continue
            if tok.text == "from" and self._from_to(end, set(self.by_start)):
                continue  # "guide a hose from it into a tank": it runs between them, no thing taken
            thing = next((m for m in self.by_start.values() if m.end == k), None)
            if thing is None or self._hand_object(thing.start, k) is None or not self._after_verb(thing.start, worn=True):
                continue  # ("a man from the village": no thing taken)
            source = self._next_mention(end, len(toks))
            pronoun = end < len(toks) and toks[end].text in ("it", "them")
            if pronoun or (source is not None and self._hand_object(source.start, source.end) is None):
                # ("launches a kite from the pier": what carries people is where the doer stands)
                perch = not pronoun and load_vocabulary().carries(source.category, source.phrase, ("perches",))
                out.append(_Rel("on" if perch else "near", k, end))
        return out

    def _deed_on_pronoun(self, c: _Clause, k: int, doers: list[int], prev_subject: list[int]) -> None:
        """"Plays it from a bench", "scrubs its back", "forks straw into it", "pushes the front
        one": what a verb acts on named by a pronoun is a deed too (whoever acts stands by it)."""
        toks, w = self.toks, self.toks[k].text
        doers = doers or list(c.main)
        if not doers or not all(self._living(g) for g in doers):
            return
        after = toks[k + 1].text if k + 1 < len(toks) else ""
        one = w == "one" and k > 0 and toks[k - 1].text not in _NUMBERS and after != "of"
        # "scrubs its back", "trims its ears", "measures his arm": the owner of the part
        part = k + 1 not in self.by_start and after.isalpha() and (after not in _STOP or self._part_word(after))
        owner = part and (w == "its" or w in _PERSON_POSSESSIVES and toks[k + 1].text in load_vocabulary().body_parts)
        if not (w in ("it", "them") or one or owner):
            return
        if not self._after_verb(k, over=("into", "onto", *_ORDINALS, "front", "back"), worn=True):
            return  # (also after what the doer wears: "a worker in ear defenders tends each one")
        if one:
            thing = self._one_of(c, doers, prev_subject)
        elif owner and w != "its":
            thing = self._person(c, doers, _PERSON_POSSESSIVES[w])
        else:  # "leans over the vat, stirring it": the clause's own target, else what the one before was about
            prefer = [*c.last_target, *prev_subject, *self.topic]
            thing = self._pronoun("them" if w == "them" else "it", c, doers, prefer)
            # (only what this sentence or the clause before named: "the nearer one" of two vats is no "it" of long ago)
            thing = [g for g in thing if g in {*prefer, *c.groups, *self.history[self._sentence_from :]}]
        if thing:
            c.deeds.append((doers, thing[0]))
            c.deed_end = k + 1
            if one and toks[k - 1].text in ("each", "every") and self.groups[thing[0]].count > 1:
                self._per_each(doers, thing[0])  # "a worker in ear defenders tends each one": one at each
            if w == "it" and k + 1 in self.rel_at and self.rel_at[k + 1].kind in ("on", "in"):
                c.main = [thing[0]]  # "weighing it on a scale": what the phrase places is the verb's thing, as
                # after a noun ("weighs the chick on a scale")

    def _given_to(
        self, c: _Clause, k: int, ce: int, giver: list[int], prev_subject: list[int]
    ) -> tuple[int, int] | None:
        """Whom the giving verb at ``k`` gives to, and where that phrase ends, when a thing to
        hold follows ("hands one of them a toolbox", "passes her a cup", "gives the boy a kite")."""
        toks, j = self.toks, k + 1
        words = [t.text for t in toks[j : j + 3]]
        m = self._next_mention(j, ce)
        if words == ["one", "of", "them"]:  # one of the people (or animals) named just before
            order = [*prev_subject, *self.topic, *reversed(self.history)]
            whom, end = [g for g in order if g not in giver and self.groups[g].count > 1 and self._living(g)], j + 3
        elif words[:1] and words[0] in ("him", "her", "them", "it"):  # ("offers it a mackerel": an animal)
            whom, end = self._person(c, giver, f"{words[0]} living" if words[0] in ("them", "it") else words[0]), j + 1
        elif m is not None and self._lives(m.category):
            group = self._resolve(m, self.size_of.get(m.start, []))
            whom, end = ([group] if group >= 0 else []), m.end
            c.groups.extend(whom)
        else:
            return None
        if not whom or self._hand_object(end, ce) is None:
            return None
        return whom[0], end

