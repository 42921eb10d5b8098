"""What kind of thing a group is, as the rules ask it: living, a person, small enough to
hold, a carrier, a platform, hung overhead. A mixin of
:class:`~scenewright.analysis.parser.reader._Reader`."""

from __future__ import annotations

from scenewright.analysis.parser.grammar import (
    _CARRY_VOLUME,
    _HAND_VOLUME,
    _HANDHELD_SIZE,
    _PLATFORM_AREA,
    _PLATFORM_HEIGHT,
    _RIDDEN,
    _THIN,
    _TOOL_SIZE,
)
from scenewright.analysis.parser.nouns import _Mention, _is_plural, _living_category
from scenewright.analysis.parser.vocabulary import GENERIC, load_vocabulary
from scenewright.analysis.parser.words import _HANG_VERBS


def _volume(size) -> float:
    """m³ of a thing's box."""
    return size[0] * size[1] * size[2]

#: Words after a held thing that keep it where it stands: its holder steadies it ("holds the ladder steady").
_STEADYING = {"steady", "still", "upright", "firm", "straight"}


class _Kinds:
    def _living(self, g: int) -> bool:
        """A person or an animal (catalogue dogs and horses too, guessed figures and animals), no
        toy or model of one."""
        return self._lives(self.groups[g].category) and not self.groups[g].likeness

    def _human(self, g: int) -> bool:
        """A person, whom "it" never names (an animal, a scarecrow or a mannequin it can)."""
        return self.groups[g].category == "figure"

    def _lives(self, category: str) -> bool:
        return _living_category(category)

    def _carrier(self, g: int, kinds: tuple[str, ...] | None = None, by_family: bool = True) -> bool:
        """Something a person or an animal sits, stands or rides on, or is carried in (``carriers``
        in ``data/vocabulary.json``), of these kinds (all when None)."""
        return load_vocabulary().carries(self.groups[g].category, self.groups[g].name, kinds, by_family)

    def _platform(self, g: int, thing: int) -> bool:
        """A perch one stands things in the middle of (a stand, a stage, a pier): low enough
        to climb and many times the thing's footprint."""
        host, size = self.groups[g], self.groups[thing].size
        low = host.size[2] <= _PLATFORM_HEIGHT
        return self._carrier(g, ("perches",)) and low and host.size[0] * host.size[1] >= _PLATFORM_AREA * size[0] * size[1]

    def _grounded(self, g: int) -> bool:
        """Stands on the ground (no tabletop thing, nothing hung)."""
        return self.groups[g].rests == "ground"

    def _animate(self, *groups: int) -> bool:
        """People and animals: what comes "with" right after their target belongs to the target."""
        return bool(groups) and all(self.groups[g].category in ("figure", "animal", "bird") for g in groups)

    def _person_at(self, g: int) -> bool:
        """A person (a figure of the catalogue or a guessed one), not an animal: who can have things
        in hand, and whom a seat, not a desk, carries."""
        return self.catalogue[self.groups[g].category].shape == "figure"

    def _handheld(self, g: int) -> bool:
        """A thing a person carries with them: no living thing, and one that stands on tables or
        is small enough to hold ("a pickaxe", "a clipboard"), not "a man with a ladder"."""
        group = self.groups[g]
        return self._holdable(group.category, group.name, group.size, group.rests, toy=group.likeness)

    def _steadied(self, g: int) -> bool:
        """A word right after the thing says it is held where it stands ("holds the ladder steady"),
        not carried ("holds a pet carrier open" has it in hand)."""
        ends = [m.end for m in self.by_start.values() if m.group == g and m.end < len(self.toks)]
        return any(self.toks[e].text in _STEADYING for e in ends)

    def _carriable(self, g: int, h: int) -> bool:
        """Whether the person or people ``h`` can carry the thing ``g`` in their hands or arms:
        what they could have in hand or work with ("peers through a telescope"), or a long thing
        of little bulk ("carries a ladder"); several people carry together what one cannot ("two
        men carry a sofa"), not what one holds or grips ("grips the railing", "holds the sofa": by it)."""
        group = self.groups[g]
        tool = self._holdable(group.category, group.name, group.size, group.rests, tool=True)
        return self._handheld(g) or tool or _volume(group.size) <= _CARRY_VOLUME or self.groups[h].count > 1

    def _holdable(
        self, category: str, name: str, size, rests: str, tool: bool = False, used: bool = False, toy: bool = False
    ) -> bool:
        """What :meth:`_handheld` says of a thing of this category, name, size and rest; with
        ``tool``, what a person works with in hand ("stirs it with a long paddle", "peers through
        a telescope"): up to ``_TOOL_SIZE`` long, and nothing one sits or rides on ("rows with a
        canoe" is no paddle); with ``used``, what a person has in hand while doing something with
        it: a hand-sized thing, no bigger than ``_HAND_VOLUME`` ("inspects a lantern"; "inspects a
        crate" is done by the crate), or one of unknown size ("reads a comic"). A ``toy`` or model of a
        living thing of this ``size`` is held when it is as small as a thing in hand ("hugs a toy penguin")."""
        if toy:
            return max(size) <= _HANDHELD_SIZE
        if self._lives(category):
            return False
        if load_vocabulary().carried_by_hand(category, name):
            return True  # "ladies with parasols", "a singer with a microphone": one's own is the hand-held kind
        if tool:
            return max(size) <= _TOOL_SIZE and not load_vocabulary().carries(category, name, _RIDDEN)
        # (a noun nobody listed has no size of its own to tell: "reads a comic")
        if used and category != GENERIC and _volume(size) > _HAND_VOLUME:
            return False
        if used and self.catalogue[category].shape == "machine":
            return False  # "pedals a sewing machine", "works a blender": where it stands
        return rests == "surface" or max(size) <= _HANDHELD_SIZE

    def _small(self, *groups: int) -> bool:
        """All of these stand on surfaces (tabletop things)."""
        return all(self.groups[g].rests == "surface" for g in groups)

    def _bare(self, m: _Mention) -> bool:
        """A singular noun with no determiner, count or describing word ("on horseback")."""
        return not (m.definite or m.counted or m.adjectives or _is_plural(self.toks, m))

    def _ridden(self, g: int, host: int) -> int:
        """What a rider put on something else is on: "a kid on a bike waits at the top of the
        ramp" puts the bike on the ramp, the kid stays on the bike."""
        rides = (r[2] for r in self.relations if r[0] == "on" and r[1] == g and r[2] != host)
        return next((v for v in rides if self._living(g) and self._carrier(v, ("vehicles", "mounts"))), g)

    def _overhead(self, g: int) -> bool:
        """Whether a thing hangs or is fixed to a wall, so what stands under it is below it: it
        hangs, the text hangs it ("a ring light that hangs from the ceiling") or puts it on a
        wall, or it is a board or a frame, too thin to stand on its own."""
        group = self.groups[g]
        if group.rests == "hanging" or (group.size[1] <= _THIN and group.size[2] >= 2 * _THIN):
            return True
        for k, m in self.by_start.items():
            if m.group != g:
                continue
            after = [t.text for t in self.toks[m.end : m.end + 3]]
            if k in self.on_wall or any(w in _HANG_VERBS for w in after[after[:1] in (["that"], ["which"]) :][:1]):
                return True
        return False
