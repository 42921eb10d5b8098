"""Whom and what a reference names: "it", "them", "him", "her", "one of them", a
possessive's part ("its back", "at his feet"), an ordinal pair ("the first and second car"). A mixin of
:class:`~scenewright.analysis.parser.reader._Reader`."""

from __future__ import annotations

from math import prod
from typing import TYPE_CHECKING

from scenewright.analysis.parser.grammar import (
    _BUILDING_PARTS,
    _ENCLOSURES,
    _FLAT_HOLDERS,
    _GROUND_KINDS,
    _OPPOSITE_SIDES,
    _OWNER_PARTS,
    _PERSON_POSSESSIVES,
    _PLATFORM_HEIGHT,
    _ROOFED,
    _ROOFED_VEHICLES,
    _SIDE_WORDS,
)
from scenewright.analysis.parser.nouns import (
    COLLECTIVES,
    _HOLDING_PARTS,
    _PLACING_VERBS,
    _STANDING,
    _is_plural,
    _position_adjective,
)
from scenewright.analysis.parser.support import usual_host
from scenewright.analysis.parser.vocabulary import load_vocabulary
from scenewright.analysis.parser.words import (
    ORDINALS,
    _DEFINITE,
    _DETERMINERS,
    _NUMBERS,
    _ORDINALS,
    _OWNER_PRONOUNS,
    _STOP,
    _is_verb,
)
from scenewright.core.catalogue import match_phrase, singular

if TYPE_CHECKING:
    from scenewright.analysis.parser.reader import _Clause


#: Nouns for a formation named again ("the stack", "the row"), and the formation they name.
_FORMATION_NOUNS = {"stack": "stack", "pile": "stack", "heap": "stack", "row": "row", "line": "row",
                    "circle": "circle", "ring": "circle"}  # fmt: skip

class _References:
    def _target_at(self, pos: int, ce: int) -> tuple[list[int] | str | None, int]:
        """The noun phrase (or pronoun) right after a relation phrase, and where it ends."""
        toks = self.toks
        self._body_part = self._part = None
        self._parts_each = 0
        self._target_start = -1  # (no noun phrase of an earlier target: "on every desk" is not "between the rows")
        body = self._body_part_at(pos, ce, self.by_start)
        if body is not None:
            return body
        # "on one of its branches": the part of one owner, as "on its branch"
        opening = [t.text for t in toks[pos : pos + 2]]
        lead = pos + 2 if opening in (["one", "of"], ["each", "of"]) else pos
        if opening == ["each", "of"] and lead + 1 < ce and toks[lead].text in _OWNER_PRONOUNS:
            # "a crow on each of its outstretched arms": one per part, two unless the text counts them
            self._parts_each = _NUMBERS.get(toks[lead + 1].text, 2)
        part_of_each = next((k for k in range(pos + 1, min(ce - 1, pos + 5)) if toks[k].text == "of"), None)
        if part_of_each is not None and toks[part_of_each + 1].text in ("each", "every") and (
            part_of_each + 2 >= ce or not toks[part_of_each + 2].text[:1].isalpha()
        ):  # "looks out over the door of each": a part of every member, one by each
            self._part = singular(toks[part_of_each - 1].text)
            return "each one", part_of_each + 2
        j = pos
        # a part "of" a thing reaches a few words further ("on the balance beam of the upper gate")
        while j < ce and j - pos < (9 if "of" in [t.text for t in toks[pos + 1 : j]] else 6):
            if j in self.by_start:
                m = self.by_start[j]
                owned = self._owner_of_part(m, ce)
                if owned is not None:
                    return owned
                self._target_start = m.start
                owner = _OWNER_PRONOUNS.get(toks[lead].text) if lead < ce else None
                people = self._people_own(toks[m.end - 1].text) if owner == "them" else None
                # ("the king and queen sit on their thrones": the single ones named together)
                owners = self.groups[people].count if people is not None else self._named_together() if owner == "them" else 0
                if owners:  # "two teenagers sit on their motorbikes": people's things are things,
                    owner = None  # one each when the text gives no count
                    if m.group < 0 and not m.counted and _is_plural(toks, m):
                        m.count = owners
                # "a rocket stands on its launch pad": what a thing is placed on is no part of it
                # ("bells hang from its railing": the railing is)
                own_support = pos >= 2 and toks[pos - 1].text in ("on", "upon") and toks[pos - 2].text in _PLACING_VERBS
                # ("a horse looks out of its stable": one's own shelter, a thing of its own)
                own_support = own_support or [t.text for t in toks[max(0, pos - 2) : pos]] == ["out", "of"]
                # ("a husky sleeps in its kennel", "a cat naps on its blanket": what one rests in or on, a thing)
                own_support = own_support or load_vocabulary().carries(m.category, m.phrase.lower(), ("seats",)) or (
                    m.category in ("doghouse", "basket") or self.catalogue[m.category].shape in ("rug", "bed")
                )
                # ("each at its own low table": a thing of its own, no part of it)
                own_support = own_support or m.own
                if owner and m.group < 0 and not own_support and not any(g.category == m.category for g in self.groups):
                    self._part = singular(toks[m.end - 1].text)
                    return owner, m.end  # "pumpkins on its counter": the stall's own counter is the stall
                possessor = self._possessor(pos, j)
                # (a living thing is no part of its owner: "in front of the lead wagon's two horses")
                if possessor is not None and m.group < 0 and not self._lives(m.category) and not any(
                    g.category == m.category for g in self.groups
                ):
                    self._part = singular(toks[m.end - 1].text)
                    return [possessor], m.end  # "either side of the warehouse's gate": the warehouse
                g = self._resolve(m, self.size_of.get(m.start, []))
                # "struts across the roof of the barn", "waves from the deck of the ship": a part one stands on
                perch = load_vocabulary().carriers.get("perches", ())
                self._part = next((
                    singular(toks[k].text) for k in range(pos, m.start - 1)
                    if toks[k + 1].text == "of" and singular(toks[k].text) in (*_BUILDING_PARTS, *perch)
                ), None)  # fmt: skip
                if g >= 0 and self._living(g):  # "on the lap of her father": on him, as "on her lap"
                    self._body_part = self._part_of_one(pos, m.start)
                part = toks[m.end].text if m.end < ce and toks[m.end - 1].text.endswith("'s") else ""
                if g >= 0 and self._living(g) and part in load_vocabulary().body_parts:
                    self._body_part = load_vocabulary().body_parts[part]
                    return [g], m.end + 1  # "on her father's shoulders": on him, as "on his shoulders"
                if singular(part) in (*_BUILDING_PARTS, *perch):  # (a perch's: "drink from the fountain's rim")
                    self._part = singular(part)
                    return ([g] if g >= 0 else None), m.end + 1  # "on the diner's roof": by the diner, on its roof
                return ([g] if g >= 0 else None), m.end
            w = toks[j].text
            if w in ("it", "them", "itself", "themselves", "him", "her", "himself", "herself") and not (
                w == "her" and j + 1 in self.by_start
            ):  # "beside her dog": a possessive, the dog is the target
                # ("on the shoulder of one of them": a body part's, as "on their shoulders")
                parts = load_vocabulary().body_parts
                if [t.text for t in toks[max(pos, j - 2) : j]] == ["one", "of"]:
                    self._body_part = next((parts[t.text] for t in toks[pos:j] if t.text in parts), None)
                return w, j + 1
            if w in ("each", "one") and j + 1 < ce and toks[j + 1].text in ("other", "another"):
                return "each other", j + 2
            if w in ("each", "every") and j + 1 < ce and toks[j + 1].text == "one":
                return "each one", j + 2  # "a chair in front of each one": one per member
            if w == "each" and j == pos and (j + 1 >= ce or not toks[j + 1].text[:1].isalpha()):
                return "each one", j + 1  # "eight kennels along the wall, a dog in each": one per member
            of_them = [t.text for t in toks[j + 1 : j + 3]] in (["of", "them"], ["of", "these"], ["of", "those"])
            if w == "each" and of_them:
                return "each one", j + 3  # "a clock hangs above each of them": as "each one"
            if w == "one" and j > pos and toks[j - 1].text not in _NUMBERS and (j + 1 >= ce or toks[j + 1].text != "of"):
                side = [t.text for t in toks[j + 1 : j + 4]] in (["on", "the", "left"], ["on", "the", "right"])
                # "at the foot of the tallest one": one of a group named before; "the one on the left"
                return "that one", j + (4 if side else 1)
            # a word hyphen-joined to its neighbour, or right before the noun, describes the noun
            # ("a fold-down table", "a tall parts cabinet"), whatever verb it could also be
            hyphened = (j > pos and toks[j].joined) or (j + 1 < ce and toks[j + 1].joined)
            # a noun, not a verb, after a determiner or a count ("its walls", "two rows of")
            after_determiner = j > pos and (toks[j - 1].text in _DETERMINERS or toks[j - 1].text in _NUMBERS)
            # "leans against the wall reading a book": a participle with its own object ends the phrase
            if w.endswith("ing") and j + 1 < ce and toks[j + 1].text in _DETERMINERS and j > pos:
                break
            # "in the middle of the arena a cowboy clings": an article after a word opens a noun
            # phrase of its own (not in "a hook-a-duck stall")
            if w in ("a", "an", "the") and j > pos and not (after_determiner or hyphened) and toks[j - 1].text != "of":
                break
            modifier = w not in _STOP and w[0].isalnum() and j + 1 in self.by_start
            # ("a man in a straw hat pushes barrels": after a noun, a verb's form is its verb)
            noun_before = j > pos and not after_determiner and not load_vocabulary().is_adjective(toks[j - 1].text)
            modifier = modifier and not (noun_before and _is_verb(w) and not hyphened)
            # "on the back of a horse": a part "of" something, though "back" alone ends a phrase
            # ("on every side of": a phrase of its own, one a side)
            # ("sits on the edge of the bed": an edge or an end any thing has, the thing's; "the top of
            # a mast" is no place on it)
            part_of = (self._part_word(w) or w in ("edge", "end")) and w not in ("side", "sides") and (
                j + 1 < ce and toks[j + 1].text == "of"
            )
            if w in _DETERMINERS or w in _NUMBERS or w in _ORDINALS or w == "of" or _position_adjective(toks, j) or (
                hyphened or modifier or part_of
            ) or (
                w not in _STOP and w[0].isalnum() and (after_determiner or not _is_verb(w) or self._part_word(w))
            ):
                j += 1
                continue
            break
        building = self._building_of_part(pos, j)
        if building is not None:
            self._part = next(singular(t.text) for t in toks[pos:j] if singular(t.text) in _BUILDING_PARTS)
            return [building], j  # "mounted on the roof", "beside its door", "on the shop's roof"
        possessor = self._possessor(pos, j)
        if possessor is not None:
            self._part = singular(toks[j - 1].text)
            return [possessor], j  # "on either side of the refinery's airlock": the refinery
        owner = _OWNER_PRONOUNS.get(toks[lead].text) if lead < ce else None
        if owner and j > lead + 1:
            self._part = singular(toks[j - 1].text)
            # "a helicopter waits on its pad", "a cable car hangs from its wire": what a thing is placed
            # on or hung from with "its" and nobody names as a part of anything is its own, no object
            # ("an owl perches on its back": the armchair's)
            placed_on = pos >= 2 and toks[pos - 1].text in ("on", "upon", "from") and toks[pos - 2].text in _PLACING_VERBS
            if placed_on and self._part not in load_vocabulary().part_owners:
                self._part = None
                return None, pos
            return owner, j  # "above its door": a part of its owner places by the owner itself
        side = lead + 1 + (lead + 2 < ce and toks[lead + 1].text in ("near", "far", "left", "right", "upper", "lower"))
        if owner and side < ce and toks[side].text in _OWNER_PARTS:
            self._part = toks[side].text
            return owner, side + 1  # "piled against its side", "drink at its near edge": by the owner
        row = next((k for k in range(pos + 1, min(ce, pos + 3)) if toks[k].text == "row"), None)
        if row is not None and toks[pos].text == "the" and self._sitting_before(pos):
            rows = (g.index for g in reversed(self.groups) if g.count > 1 and self._carrier(g.index, ("seats",)))
            seats = next(rows, None)
            if seats is not None:
                return [seats], row + 1  # "his father, who sits in the front row": on one of the rows of seats
        if [t.text for t in toks[pos : pos + 2]] == ["the", "top"] and (pos + 2 >= ce or toks[pos + 2].text != "of"):
            tower = next((g.index for g in reversed(self.groups) if self._tall_perch(g.index)), None)
            if tower is not None:
                self._part = "top"
                return [tower], pos + 2  # "with a ranger looking out from the top": the watchtower's
        formed = _FORMATION_NOUNS.get(singular(toks[lead + 1].text)) if lead + 1 < ce and toks[lead].text == "the" else None
        if formed is not None and j == lead + 2:
            # ("between the rows": the group set out in rows)
            group = next((g for g in reversed(self.history) if self.formations.get(g) in (formed, f"{formed}s")), None)
            if group is not None and toks[lead + 1].text != singular(toks[lead + 1].text):
                self.rows_named.add(group)
            if group is not None:
                return [group], j  # "a dog lies on top of the stack": the stack of hay bales named before
        sided = lead + 1 < ce and toks[lead + 1].text in _SIDE_WORDS  # ("under the front bumper")
        if lead < ce and toks[lead].text == "the" and j == lead + 2 + sided and (
            singular(toks[j - 1].text) in load_vocabulary().part_owners
        ):
            self._part = singular(toks[j - 1].text)
            return "the part", j  # "lies in the water": the water of the pond named before
        if lead < ce and toks[lead].text in ("a", "an") and j == lead + 2 and self._verb_before(pos, self._posture):
            word = singular(toks[lead + 1].text)  # "an owl sits on a branch": a branch of the tree named before
            if word in load_vocabulary().part_owners and word in load_vocabulary().carriers.get("perches", ()):
                self._part = word
                return "the part", j
        return None, pos

    def _possessor(self, pos: int, end: int) -> int | None:
        """The thing a possessive before a part names ("the refinery's airlock" → the refinery), a
        part being no object of its own; a person's or an animal's things are things ("the
        farmer's cart")."""
        owned = [t.text[:-2] for t in self.toks[pos:end] if t.text.endswith("'s")]
        if not owned:
            return None
        head = singular(owned[-1])
        found = next((g.index for g in reversed(self.groups) if singular(g.name.split()[-1]) == head), None)
        return found if found is not None and not self._living(found) else None

    @staticmethod
    def _part_word(word: str) -> bool:
        """A part of a body or a thing ("its outstretched arms", "its rusty wheels"): a noun, no verb."""
        vocabulary = load_vocabulary()
        return word in vocabulary.body_parts or singular(word) in vocabulary.part_owners

    def _people_own(self, word: str) -> int | None:
        """The group "their" most likely names when it is people or animals: the latest group
        of several, when living (what such owners have is a thing of its own, not a part like a
        roof); when ``word``, what "their" is before, is no part of a thing, the sentence's latest
        living group of several ("fishermen mend nets beside their boats": the fishermen's)."""
        several = [g.index for g in self.groups if g.count > 1]
        if several and self._living(several[-1]):
            return several[-1]
        if singular(word) in load_vocabulary().parts:
            return None
        return next((g for g in reversed(several) if g >= self._sentence_groups and self._living(g)), None)

    def _named_together(self) -> int:
        """How many living things, one each, the sentence has named last in a row ("the king and
        the queen"): the owners "their" names when no group of several is meant; 0 if under two."""
        n = 0
        for g in reversed(self.groups[self._sentence_groups :]):
            if g.count != 1 or not self._living(g.index):
                break
            n += 1
        return n if n > 1 else 0

    def _body_part_at(self, pos: int, ce: int, starts) -> tuple[str, int] | None:
        """"on her knees", "at his feet", "in their arms": a part of a person places by the
        person ("her" → the woman); the part's relation (carried on, or near) is kept for
        :meth:`_relation`."""
        toks = self.toks
        k = pos
        while k < ce and toks[k].text in ("one", "of", "both", "each", "either"):
            k += 1  # "on one of her knees"
        vocabulary = load_vocabulary()
        if k < ce and (pos < k or toks[k].text in ("hand", "hands")) and toks[k].text in _HOLDING_PARTS and k not in starts:
            # "a glass in one hand", "a sword in each hand", ", baton in hand": whoever the clause is about
            self._body_part = vocabulary.body_parts[toks[k].text]
            return "someone", k + 1
        if k == pos and [t.text for t in toks[k : k + 2]] == ["the", "other"] and self._said_before(
            k, lambda j: j > 0 and toks[j].text in _HOLDING_PARTS and toks[j - 1].text == "one"
        ):
            # "a palette in one hand and a brush in the other": the other hand
            self._body_part = "on"
            return "someone", k + 3 if k + 2 < ce and toks[k + 2].text in _HOLDING_PARTS else k + 2
        if k + 1 < ce and toks[k].text == "its" and vocabulary.body_parts.get(toks[k + 1].text) == "on":
            if singular(toks[k + 1].text) not in vocabulary.part_owners and k + 1 not in starts:
                # "a dog with a bell on its neck": carried by an animal's body, a part no thing has
                self._body_part = "on"
                return "it living", k + 2
        if k + 1 >= ce or toks[k].text not in _PERSON_POSSESSIVES:
            return None
        j = k + 1
        while j < ce - 1 and j - k <= 2 and load_vocabulary().is_adjective(toks[j].text) and not toks[j].text.endswith("'s"):
            j += 1  # "at her tiny feet" (not "on her father's shoulders": the father's)
        part = toks[j].text if j < ce else ""
        relation = load_vocabulary().body_parts.get(part)
        if relation is None or j in starts:  # "on her back porch": a thing named, not a part
            return None
        self._body_part = relation
        return _PERSON_POSSESSIVES[toks[k].text], j + 1

    def _sitting_before(self, pos: int) -> bool:
        """A verb of sitting right before the phrase at ``pos`` ("sits in the front row")."""
        return pos >= 2 and self.toks[pos - 2].text in load_vocabulary().postures.get("sitting", ())

    def _owner_of_part(self, m, ce: int) -> tuple[list[int] | str | None, int] | None:
        """A thing named new with "the" that is a part of one named before (no object of its own):
        the owner is the target, and where the phrase ends. "On the ladder of the nearer one" (of
        a thing named before); "in the nearest basket" (a carrier part of a group, one member);
        "a woman at the wheel" (a part, by ``part_owners``, of a thing this sentence names). Not a
        living thing (a body part reads its own way), nor one named before ("the ladder" after "a
        ladder"); None when none of these."""
        toks = self.toks
        head = singular(toks[m.end - 1].text)
        named = any(g.category == m.category and singular(g.name.split()[-1]) == head for g in self.groups)
        if not m.definite or m.group >= 0 or self._lives(m.category) or named:
            return None
        picked = [a.lower() for a in m.adjectives if a.lower() in _ORDINALS or a.lower().endswith("est")]
        if picked and load_vocabulary().carries(m.category, m.phrase.lower(), ("containers", "seats", "vehicles")):
            # "three balloons inflate, each tethered to a truck. A pilot stands in the nearest
            # basket": none was named, so one of a group named before has it (the sentence
            # before first, in its order: its subject before what it is tied to)
            size = m.guess.size if m.guess is not None else self.catalogue[m.category].size
            owners = [
                g for g in [*self.history[self._recent_from : self._sentence_from], *reversed(self.history)]
                if self.groups[g].count > 1 and not self._living(g)
                and prod(self.groups[g].size) > prod(size)  # (bigger than its part)
            ]  # fmt: skip
            if owners:
                self._target_start = m.start
                self.instance[m.start] = _ORDINALS.get(picked[0], 0)
                self._part = head
                return owners[:1], m.end
        owners = load_vocabulary().part_owners.get(head, ())
        # ("climb the ladders propped against its hull": ladders of their own, set against it; "the
        # control tower": a kind of its own)
        before, words = toks[m.start - 1].text, tuple(t.text for t in toks[m.start : m.end])
        kind = before[:1].isalpha() and before not in (*_DEFINITE, *_SIDE_WORDS) and not load_vocabulary().is_adjective(before)
        kind = kind or len(words) > 1 and bool(match_phrase(words) or load_vocabulary().match(words))  # "the clock tower"
        if owners and not (m.modifier or kind) and (m.end >= ce or toks[m.end].text != "of" and toks[m.end].text not in _STANDING):
            # "a tractor drives past, a woman at the wheel": the part of a thing this sentence names
            stop = max((k for k in range(m.start) if toks[k].text in (".", "!", "?")), default=-1)
            here = [n.group for k, n in sorted(self.by_start.items()) if stop < k < m.start and n.group >= 0]
            cats = [(g, self.groups[g].category) for g in here]
            have = [g for g, cat in cats if cat in owners or self.catalogue[cat].shape in owners]
            if have:
                self._part = head
                return have[-1:], m.end
        if m.end + 1 >= ce or toks[m.end].text != "of":
            return None
        if toks[m.end + 1].text not in ("the", "its"):
            return None
        owner = self.by_start.get(m.end + 1) or self._next_mention(m.end + 1, ce)
        if owner is not None:
            known = any(g.category == owner.category for g in self.groups) and not self._lives(owner.category)
            if not known:
                return None
        elif not any(toks[k].text in ("one", "it") for k in range(m.end + 1, min(m.end + 4, ce))):
            return None  # ("the nearer one", "the front one": one of a group named before)
        target, end = self._target_at(m.end + 1, ce)
        if not target:
            return None
        self._part = head
        return target, end

    def _tall_perch(self, g: int) -> bool:
        """A perch too tall to climb onto like a platform (a tower, a mast): what "the top" names
        when nothing follows."""
        return self._carrier(g, ("perches",)) and self.groups[g].size[2] > _PLATFORM_HEIGHT

    def _part_of_one(self, pos: int, end: int) -> str | None:
        """The relation of a body part named "of" someone between ``pos`` and ``end`` ("the lap
        of", "the broad shoulders of", "the feet of"), the other way round of "her lap"."""
        parts = load_vocabulary().body_parts
        return next((
            parts[self.toks[k].text] for k in range(pos, end - 1)
            if self.toks[k + 1].text == "of" and self.toks[k].text in parts
        ), None)  # fmt: skip

    def _building_of_part(self, pos: int, end: int) -> int | None:
        """The building (or vehicle) a part of one names when no thing is named ("on the roof",
        "beside its door", "at the foot of the porch steps"): the one whose name the possessive
        gives, else the latest one mentioned."""
        words = [t.text for t in self.toks[pos:end]]
        if not any(singular(w) in _BUILDING_PARTS for w in words):
            return None
        # one named in this sentence first ("a truck is parked behind the tents with two kayaks
        # on its roof"), then earlier buildings, then earlier vehicles
        stop = max((k for k in range(pos) if self.toks[k].text in (".", "!", "?")), default=-1)
        here = {m.group for k, m in self.by_start.items() if stop < k < pos and m.group >= 0}
        shapes = [self.catalogue[g.category].shape for g in self.groups]
        latest = range(len(self.groups) - 1, -1, -1)
        buildings = [
            *(g for g in latest if g in here and shapes[g] in (*_ROOFED, *_ROOFED_VEHICLES)),
            *(g for g in latest if shapes[g] in _ENCLOSURES),
            *(g for g in latest if shapes[g] in _ROOFED_VEHICLES),
        ]
        named = [w[:-2] for w in words if w.endswith("'s")]
        for g in buildings:
            if not named or singular(named[0]) == singular(self.groups[g].name.split()[-1]):
                return g
        return None

    def _pronoun(
        self, word: str, c: _Clause, srcs: list[int], prefer: list[int], kind: str = "", others: list[int] | None = None
    ) -> list[int]:
        """The group "it" / "them" names: the subject before (when this clause has its own) or
        the latest earlier mention, of the right number; never a source, one of ``others`` or
        what a source rests on."""
        plural = word in ("them", "themselves")
        # "a unicorn rests its head in the lap of a nun who sits on a bench beneath a tree. Across from
        # them, ...": "them" after a subject that is one living thing names it and the other living one
        # just named with it, not the things they are on or under
        just = [*prefer, *self.history[self._recent_from :]]
        living = [g for g in dict.fromkeys(just) if g not in srcs and self._living(g) and self.groups[g].count == 1]
        lone = bool(prefer) and self.groups[prefer[0]].count == 1 and self._living(prefer[0])
        # (several living ones just named are "them": "children chase a dog ..., and a lighthouse watches over them")
        lone = lone and not any(self.groups[g].count > 1 and self._living(g) for g in just if g not in srcs)
        # "a fish stall and a noodle stall face each other, and a girl stands between them": two
        # single things of this clause, or of the subject before, are "them"
        for pair in ([g for g in c.groups if g not in srcs], living[:2] if lone else [], [g for g in prefer if g not in srcs]):
            if plural and len(pair) >= 2 and all(self.groups[g].count == 1 for g in pair):
                return pair[-2:]
        # "a singer and a fiddler stand on either side of the harp, and the harpist sits at it. A drummer
        # plays behind them": the ones named together, every one of them, when none of the things
        # just named is several
        together = [g for g in self.together if g not in srcs and self.groups[g].count == 1]
        several = any(self.groups[g].count > 1 for g in [*prefer, *self.history[self._recent_from :]] if g not in srcs)
        if plural and len(together) > 1 and not several:
            return together
        # never what a source rests on ("a parrot in a cage watches it": not the cage)
        hosts = {r[2] for r in self.relations if r[0] == "on" and r[1] in srcs}
        skip = {*srcs, *(others or ()), *hosts}
        # the other side of the landmark the subject before was placed by ("a robot works behind the
        # counter, and colonists wait in front of it": the counter's front, not the robot's)
        flip = _OPPOSITE_SIDES.get(kind)
        landmark = [r[2] for r in reversed(self.relations) if flip and r[0] == flip and r[1] in prefer[:1]]
        prefer = [*landmark[:1], *prefer]
        recent = [g for g in [*prefer, *reversed(self.history), *reversed(c.groups)] if g not in skip]
        if not plural:  # "it" is never a person ("a guard waves at a lorry; behind it, ...")
            recent = [g for g in recent if not self._human(g)] or recent
        # a thing on the floor is not placed by a small thing on a table ("a nightstand with a lamp
        # on it. A rug lies in front of it": the nightstand)
        # (above a small thing is fine: "a register on the counter, and a hologram floats above it")
        # (one standing on its own is: "a pirate skull grins over the hole, and a windmill stands in front of it")
        big = bool(srcs) and not self._small(*srcs) and kind not in ("above", "over")
        # the people on seats, not the seats ("two helmsmen, each in a seat. Across from them, ...")
        sat_on = {r[2] for r in self.relations if r[0] == "on" and self._person_at(r[1]) and r[1] in recent}
        tabletop = {r[1] for r in self.relations if r[0] in ("on", "above")}

        # what someone has in hand goes where they go: nothing stands by "it" ("a man holds a rope, and a
        # dog barks at the swans gliding alongside it": the boat)
        in_hand = {g for g, _ in self.carried} if kind in (*_GROUND_KINDS, "flank", "around") else set()
        # nor is anything set "on it" but on a tray ("the chief reads a logbook at his desk; a radio
        # crackles on it": the desk)
        if kind in ("on", "on top"):
            in_hand = {g for g, _ in self.carried if self.groups[g].category not in _FLAT_HOLDERS}

        def aside(g: int) -> bool:
            return (big and self._small(g) and g in tabletop) or g in in_hand

        # what a living thing watches is first a living thing ("a fox sits on the drum, watching them")
        watcher = kind == "face to" and bool(srcs) and all(self._living(g) for g in srcs)
        # what is "at the foot of it" is at the foot of a thing this sentence names (a tree, a tower),
        # not of an animal ("a goat grazes by an apple tree, and chickens scratch at the foot of it")
        local = {*self.history[self._sentence_from :], *c.groups}
        # what hangs or stands above "it" is above a thing of this sentence first ("a bear stirs a pot on
        # the stove, and ladles hang from the ceiling above it": the stove; "pigeons perch along the
        # fence, and a flag flaps above them": the pigeons, not boats of a sentence before)
        overhead = kind in ("above", "over") and any(
            g in local and not self._living(g) and (self.groups[g].count > 1) == plural for g in recent
        )
        # what stands "under it" is under something taller ("a tractor drives towards a crane, and
        # a truck waits under it": the crane, not the tractor)
        tallest = max((self.groups[g].size[2] for g in srcs), default=0.0) if kind == "under" else 0.0
        footed = kind == "foot of" and any(
            g in local and not self._living(g) and (self.groups[g].count > 1) == plural for g in recent
        )

        # who sit on seats "around it" sit around a thing, as at a table ("two hoglets sit on stools around it")
        seated = kind == "around" and any(c.supports.get(s) for s in srcs)

        # a small thing "on it" among hosts of this sentence is on one it is usually set on ("a clerk sits at
        # a desk across from the fireplace, with an inkwell on it": the desk)
        this_sentence = {*self.history[self._sentence_from :], *c.groups}
        usual = [g for g in this_sentence if kind == "on" and srcs and self._small(*srcs) and self._usual_host(g, srcs)]

        def likeness(g: int) -> bool:  # a scarecrow, a mannequin: "it", and what circles above it is above it
            return self._person_at(g) and not self._human(g)

        # what is "on it" is on an animal only when the animal can bear it ("checking the suitcases on it",
        # after "a sniffer dog trots along the belt": the belt)
        laden = kind in ("on", "on top") and bool(srcs) and not any(self._living(s) for s in srcs)

        def kind_fits(g: int) -> bool:
            unborne = laden and self._living(g) and not all(self._borne(s, g) for s in srcs)
            return (
                not unborne and (not watcher or self._living(g)) and not ((overhead or seated) and self._living(g) and not likeness(g))
                and self.groups[g].size[2] > tallest and not (footed and (self._living(g) or g not in local))
                and not (usual and g in this_sentence and g not in usual)
            )  # fmt: skip

        # the members, not what each of them has ("six cows, each hooked up to a pump. The farmer
        # walks behind them": the cows)
        apiece = {g for g, each in self.pair_each if each in recent}
        for fits in (
            (lambda g: not aside(g) and g not in sat_on and g not in apiece and kind_fits(g)),
            (lambda g: not aside(g) and g not in sat_on),
            (lambda g: not aside(g)),
            (lambda g: True),
        ):  # fmt: skip
            for g in recent:
                if self._several(g) == plural and fits(g):
                    return [g]
        # "them" after two single things ("an armchair ... a bookcase ..., between them")
        return list(dict.fromkeys(recent))[:2] if plural else []

    def _several(self, g: int) -> bool:
        """Whether "them" can name group ``g``: several of a thing, or one that is several ("a family")."""
        group = self.groups[g]
        return group.count > 1 or singular(group.name.split()[-1]) in COLLECTIVES

    def _usual_host(self, g: int, things: list[int]) -> bool:
        """Whether ``g`` is a host these things are usually set on (:func:`.support.usual_host`)."""
        return self.catalogue[self.groups[g].category].support and all(
            usual_host(self.groups[g].category, self.groups[t].category) for t in things
        )

    def _part_owner(self, part: str | None, targets: list[int], candidates: list[int], srcs: list[int]) -> list[int]:
        """The owner of a part named with "its" ("an owl perched on its back"): what the pronoun
        resolved to when that can have the part, else the latest candidate that can (the
        armchair, not the fireplace named after it)."""
        owners = load_vocabulary().part_owners.get(part or "")
        if not owners:
            return targets

        def has(g: int) -> bool:
            category = self.groups[g].category
            return category in owners or self.catalogue[category].shape in owners

        if targets and any(has(t) for t in targets):
            return [t for t in targets if has(t)]  # "a bookcase and a piano ..., on its lid": the piano
        return next(([g] for g in candidates if g not in srcs and has(g)), targets)

    def _seat(
        self, c: _Clause, srcs: list[int], prefer: list[int], pos: int, plural: bool = False, inside: bool = False
    ) -> list[int]:
        """What a person or an animal who sits, lies or stands "in it" / "on it" is on: the
        nearest thing named in this sentence or the one before that can hold them, when the
        clause has a posture verb. A person's is a carrier ("a bookcase stands beside an
        armchair, and a sailor dozes in it": the armchair); an animal's anything standing on the
        ground ("a lamp hangs above the table, and a cat naps on it": the table), but "in it" a
        container first, hung or not ("a cage hangs above the desk, and a finch sleeps in it")."""
        if not srcs or not all(self._living(g) for g in srcs) or not self._verb_before(pos, self._posture):
            return []
        person = all(self._person_at(g) for g in srcs)
        holds = self._carrier if person else self._grounded
        recent = [*prefer, *reversed(self.history[self._recent_from :]), *reversed(c.groups)]
        fits = [g for g in recent if (self.groups[g].count > 1) == plural and g not in srcs and not self._living(g)]
        vessel = [g for g in fits if inside and not person and self._carrier(g, ("containers",), False)]
        return vessel[:1] or next(([g] for g in fits if holds(g)), [])

    def _one_of(self, c: _Clause, srcs: list[int], prev_subject: list[int]) -> list[int]:
        """The group "the tallest one", "the nearest one" picks from: the subject of this clause
        or the one before when it is several ("three stalls ..., and a drone hovers above the
        nearest one"), else the latest group of several mentioned; not what each of a group has
        ("five racers wait, each with a pilot in its seat. A marshal stands between the first two":
        the racers)."""
        order = [*c.subjects, *prev_subject, *reversed(c.groups), *reversed(self.history)]
        apiece = {g for g, _ in self.pair_each}
        several = [g for g in order if g not in srcs and self.groups[g].count > 1]
        return next(([g] for g in several if g not in apiece), several[:1])

    def _person(self, c: _Clause, srcs: list[int], word: str) -> list[int]:
        """Whom "him" / "her" (or "their" before a body part, "it living" for "its") names: the
        clause's own living subject, else the latest living thing mentioned before, of a sex the pronoun agrees
        with ("her" is not the dad) and, for "their", several."""
        # "..., with his cat at his feet": the with-part's owner before the things it lists; then
        # the doers of the clause before ("... while her cousin waits beside her, a map under his
        # arm": the cousin, not whom he waits beside)
        order = [
            *c.subjects, *(c.head or []), *c.main_groups, *reversed(c.groups), *self.doers, *reversed(self.history)
        ]  # fmt: skip
        vocabulary = load_vocabulary()
        # "him" / "her" is one, unless the clause is about several, each on their own ("each nurse
        # holds a tray in her hand", "one of them rocks a baby in her arms"): "... facing the
        # marines. Crates stand beside her": the sergeant
        own = {*c.subjects, *(c.head or []), *c.main, *c.one_of}

        def fits(g: int) -> bool:
            group = self.groups[g]
            return (
                g not in srcs and self._living(g) and vocabulary.agrees(word, group.name.split()[-1])
                and (word != "them living" or group.count > 1)
                and (word not in ("him", "her") or group.count == 1 or g in own)
            )  # fmt: skip

        if word == "it living":  # "its neck": an animal's, never a person's
            return next(([g] for g in order if fits(g) and not self._person_at(g)), [])
        # "the king and queen watch ..., with a jester at their feet": the ones the clause names together
        joint = [g for g in (c.subjects or c.head or []) if g not in srcs and self._living(g) and self.groups[g].count == 1]
        if word == "them living" and len(joint) > 1:
            return joint
        # "her dachshund naps in a hatbox beside her": a person before an animal the text calls "her";
        # a robot the text calls "him" is one ("a robot DJ works the decks, a speaker either side of him")
        def personal(g: int) -> bool:
            return self._person_at(g) or self.catalogue[self.groups[g].category].shape == "robot"

        return next(([g] for g in order if fits(g) and personal(g)), []) or next(([g] for g in order if fits(g)), [])

    def _peer(self, kind: str, srcs: list[int], targets: list[int], c: _Clause) -> list[int]:
        """A small thing beside "it", where "it" came out as a host with a small thing just
        named on it, stands by that thing ("a computer on the counter, with a radio beside it")."""
        beside = kind in ("side of", "near", "left of", "right of")
        if not beside or not srcs or len(targets) != 1 or not self._small(*srcs):
            return targets
        if c.head is None and self.topic[:1] == targets:
            return targets  # "a stove stands there with a kettle on it, and ladles hang beside it": the stove
        recent = [*self.history[-3:], *c.groups]  # this clause, or the one just before the "with"
        on_it = [r[1] for r in self.relations if r[0] == "on" and r[2] == targets[0] and r[1] in recent]
        peers = [g for g in on_it if g not in srcs and self._small(g)]
        return peers[-1:] or targets

    def _owners_side(self, pos: int, ce: int) -> tuple[str, list[int], int] | None:
        """"(on) the artist's right": right of the latest thing of that name, and where it ends."""
        toks = self.toks
        k = pos + (pos < ce and toks[pos].text == "the")
        if k + 1 >= ce or not toks[k].text.endswith("'s") or toks[k + 1].text not in ("left", "right"):
            return None
        head = singular(toks[k].text[:-2])
        owner = next((g.index for g in reversed(self.groups) if singular(g.name.split()[-1]) == head), None)
        return None if owner is None else (f"{toks[k + 1].text} of", [owner], k + 2)

    def _ordinal_pair(self, pos: int, ce: int) -> tuple[int | None, tuple[int, int] | None, int] | None:
        """"(between) the first and second ramp", "the first and the last car", "the last two
        carts", "the middle two": the group the noun names back, the two ordinals (``None`` for the
        middle two, which the group's count gives), and where the noun ends; no group when no noun
        follows ("between the second and the third", "between the first two": of the row named before)."""
        toks = self.toks
        k = pos + (pos < ce and toks[pos].text == "the")
        if k + 1 < ce and toks[k].text == "middle" and toks[k + 1].text == "two":
            j, ordinals = k + 1, None
        elif k + 1 < ce and (toks[k].text in ORDINALS or toks[k].text == "last") and toks[k + 1].text == "two":
            first = _ORDINALS[toks[k].text]
            j, ordinals = k + 1, ((first, first + 1) if first >= 0 else (first - 1, first))
        else:
            if k + 2 >= ce or toks[k].text not in _ORDINALS or toks[k + 1].text != "and":
                return None
            j = k + 2 + (toks[k + 2].text == "the")
            if j >= ce or toks[j].text not in _ORDINALS:
                return None
            ordinals = (_ORDINALS[toks[k].text], _ORDINALS[toks[j].text])
        after = toks[j + 1].text if j + 1 < ce else "."
        verb = j + 1 not in self.by_start and (after.endswith("ing") or _is_verb(after))
        # ("between the second and the third holding a lamp"; "... and between the second and the
        # third a farmer kneels": an article opens the subject, no noun of the pair)
        if not after[:1].isalpha() or verb or after in ("a", "an"):
            return None, ordinals, j + 1
        m = next((self.by_start[i] for i in range(j + 1, min(ce, j + 4)) if i in self.by_start), None)
        if m is None:
            return None
        m.definite = True  # "the first and second car": the cars named before
        group = self._resolve(m, [])
        if group < 0:
            return None
        return group, ordinals, m.end
