"""What is content rather than a thing of the layout: what fills a holder ("a vase of
tulips"), what a building holds, what a stall sells. A mixin of
:class:`~scenewright.analysis.parser.reader._Reader`."""

from __future__ import annotations

from scenewright.analysis.parser.grammar import (
    _DEPICTIONS,
    _ENCLOSURES,
    _FLAT_HOLDERS,
    _HANGERS,
    _LOAD_HOSTS,
    _LOAD_SIZE,
    _LOADS,
    _MOUNTS,
    _POLE_BORNE,
    _SHELF_LOAD_SIZE,
    _VESSEL_KINDS,
)
from scenewright.analysis.parser.nouns import _LAID, _STANDING, _Mention, _after_preposition, _is_plural
from scenewright.analysis.parser.phrases import _phrase_table
from scenewright.analysis.parser.vocabulary import load_vocabulary
from scenewright.analysis.parser.words import (
    _CONTENT_HEADS,
    _CONTENT_MARKERS,
    _COOK_VERBS,
    _DETERMINERS,
    _HANG_VERBS,
    _HOLD,
    _NUMBERS,
    _PICTURE_MARKERS,
    _SHOW_VERBS,
    _SHOWING,
    _STOP,
    _WARES_VERBS,
    _is_verb,
)
from scenewright.core.catalogue import singular


class _Contents:
    def _mark_contents(self, mentions: list[_Mention]) -> None:
        """Nouns after "full of", or after "of" following a container or a depiction ("a vase of
        tulips", "a statue of a horse"), are contents, not objects of the scene."""
        toks, phrases = self.toks, _phrase_table()
        chain = False
        self.pictures = self._pictures(mentions)
        for k, m in enumerate(mentions):
            prev = mentions[k - 1] if k else None
            if any(v < m.start < e for v, e in self.pictures):
                m.content = chain = True  # "a screen showing a football match with two players"
                continue
            j = m.start - 1
            while j >= 0 and (toks[j].text in _DETERMINERS or toks[j].text in _NUMBERS or (
                toks[j].text not in _STOP and toks[j].text[0].isalnum() and (toks[j].text,) not in phrases
            )) and m.start - j < 5:  # fmt: skip
                j -= 1  # (a relation phrase ends the noun phrase: "jars of fluid crowd every shelf")
            if (prev is not None and self._held_inside(m, prev)) or self._wares(m, prev):
                m.content = chain = True
                continue
            if j < 1 or prev is None:
                chain = False
                continue
            gap = [t.text for t in toks[prev.end : j + 1]]
            self._each_full(m, mentions[:k], j)
            content = self._is_content(m, prev, j) or (
                chain and prev.content and not (m.counted or m.definite) and all(g in ("and", ",", "or") for g in gap)
            )
            m.content = content
            chain = content

    def _wares(self, m: _Mention, seller: _Mention | None) -> bool:
        """"A stall selling pies", "a cart serving hot drinks": a bare plural after a verb of
        trade is what is sold, not things of the layout ("a vendor sells two balloons" are there,
        and so is the stock a person sells from the hand: "a vendor sells balloons", "a boy
        hawking flags"); a bare noun right after a verb of cooking is the food ("a woman grills fish")."""
        head = m.phrase.split()[-1].lower()
        if m.counted or m.definite:
            return False
        before = self.toks[m.start - 1].text if m.start > 0 else ""
        if before in _COOK_VERBS and before not in load_vocabulary().adjectives:
            return True  # "a woman grills fish": the food cooked (not "push steaming trolleys")
        if singular(head) == head:
            return False
        k = m.start - 1  # back over describing words and a list of wares before ("pies, cakes and jams")
        while k >= 0 and m.start - k <= 8 and self.toks[k].text not in _WARES_VERBS and (
            self.toks[k].text in (",", "and", "or") or self.toks[k].text not in _STOP and self.toks[k].text[:1].isalpha()
        ):
            k -= 1
        if k < 0 or self.toks[k].text not in _WARES_VERBS:
            return False
        if m.end < len(self.toks) and self.toks[m.end].text in _LAID | _STANDING:
            return False  # "sells pumpkins stacked in crates": stock the text puts somewhere is laid out
        hawker = seller is not None and seller.end in (k, k - 1) and self.catalogue[seller.category].shape == "figure"
        return not (hawker and load_vocabulary().carried_by_hand(m.category, m.phrase))

    def _pictures(self, mentions: list[_Mention]) -> list[tuple[int, int]]:
        """(verb, clause end) of each picture a screen, a picture or a window shows: what is in it
        is no thing of the layout ("a giant screen on the front wall, showing the rocket on its
        pad", "a stained-glass window depicts a ship")."""
        toks, out = self.toks, []
        for v, verb in enumerate(toks):
            if verb.text not in _SHOW_VERBS:
                continue
            before = [m for m in mentions if m.end <= v]
            gap = [t.text for t in toks[before[-1].end if before else 0 : v]]
            if not before or len(gap) > 6 or any(w in (".", "!", "?", ";") for w in gap):
                shower = any(t.text in _SHOWING for t in toks[max(0, v - 2) : v])
            else:
                shower = before[-1].category in _DEPICTIONS or before[-1].category in _SHOWING or any(
                    w in _SHOWING for w in gap[-2:]
                )
            if shower:
                end = next((e for e in range(v + 1, len(toks)) if self._picture_ends(e)), len(toks))
                out.append((v, end))
        return out

    def _picture_ends(self, e: int) -> bool:
        """Whether a picture's words end at ``e``: its clause ends, or the verb of the thing that
        shows it comes ("a window showing a mermaid market on a harbour glows above the altar")."""
        w, before = self.toks[e].text, self.toks[e - 1].text
        if w in (",", ";", ".", "!", "?"):
            return True
        noun_before = before[:1].isalpha() and before not in _STOP and before not in _DETERMINERS and (
            before not in _NUMBERS and not load_vocabulary().is_adjective(before)
        )
        return noun_before and _is_verb(w) and w not in _SHOW_VERBS

    def _held_inside(self, m: _Mention, prev: _Mention) -> bool:
        """"A greenhouse holds tomato plants": what a building or a tent holds is inside it, its
        contents rather than things of the layout; not what the clause's subject holds after a
        place phrase ("a merchant stands in front of the tent holding a brass lantern")."""
        gap = [t.text for t in self.toks[prev.end : m.start]]
        if not gap or gap[0] not in _HOLD or len(gap) > 4 or self.catalogue[prev.category].shape not in _ENCLOSURES:
            return False
        return not (gap[0].endswith("ing") and _after_preposition(self.toks, prev.end - 1))

    def _is_content(self, m: _Mention, prev: _Mention, j: int) -> bool:
        w = self.toks[j].text
        marker = (self.toks[j - 1].text, w)
        host = self.catalogue[prev.category]
        vehicle = load_vocabulary().carries(prev.category, prev.phrase, ("vehicles",))  # ("a trailer stacked with hay bales")
        least = _SHELF_LOAD_SIZE if host.shape in ("bookshelf", "shop_shelf") else _LOAD_SIZE
        if marker in _LOADS and (host.shape in _LOAD_HOSTS or host.support or vehicle) and max(self._size(m)) >= least:
            return False  # "a luggage cart piled with suitcases": they stand on the cart
        if marker in _PICTURE_MARKERS and j - prev.end <= 2:
            return True
        alive = self._lives(m.category) or m.category == "fish"
        if marker in _CONTENT_MARKERS and j - prev.end <= 2:
            # "a bowl full of apples"; but "a tank full of guppies", "a stand packed with fans" are
            # there, on what holds them; "a grandstand full of spectators" is a crowd that fills
            # it, its look, where people the text counts or describes are there
            crowd = marker == ("full", "of") and not m.counted and self.catalogue[m.category].shape == "figure"
            if crowd and m.start == j + 1 and not load_vocabulary().carries(prev.category, prev.phrase, _VESSEL_KINDS):
                return True  # (a boat full of children carries them: they are in it)
            if alive and self._holds_living(prev):
                self.held_of.append((m.start, prev.start))
                self.aboard.add(m.start)
            return not alive
        if self._listed_content(m.start):
            return not alive  # "crates overflow with apples, pumpkins and carrots"
        # ("racks of skis", "shelves of dusty jars": what the shelves hold stands on them)
        shelved = host.shape in ("bookshelf", "shop_shelf") and max(self._size(m)) >= _SHELF_LOAD_SIZE
        shelved = shelved and not self._lives(m.category)  # ("a rack of resistance bands": no band of people)
        flat = prev.category in _FLAT_HOLDERS or vehicle or shelved
        if w == "of" and prev.end == j and flat and not m.definite:
            self.held_of.append((m.start, prev.start))  # "a tray of medicine bottles", "a trolley of books": on it
            self.aboard.add(m.start)
            return False
        vessel = load_vocabulary().carries(prev.category, prev.phrase, _VESSEL_KINDS)
        if w == "of" and prev.end == j and self._lives(m.category) and vessel and not m.definite and (
            prev.category not in _DEPICTIONS
        ):  # "a trailer of waving children", "a basket of kittens": they ride in it ("crates of fish" hold food)
            self.held_of.append((m.start, prev.start))
            self.aboard.add(m.start)
            return False
        holder = prev.category in _CONTENT_HEADS or prev.category in ("container", "tool")
        if w == "of" and prev.end == j and holder and m.counted and prev.category not in _DEPICTIONS:
            self.held_of.append((m.start, prev.start))  # "a nest of five golden eggs": counted, so there, in it
            return False
        if w == "of" and prev.end == j and holder and (not m.definite or prev.category in _DEPICTIONS):
            return True  # "a vase of tulips", "a statue of a horse", "a hologram of the star map"
        borne = prev.category in _POLE_BORNE or self.catalogue[prev.category].shape in _POLE_BORNE
        if w == "on" and j - prev.end <= 2 and singular(m.phrase.split()[-1].lower()) in _MOUNTS and borne:
            return True  # "a windsock on a tall pole", "a flag flutters on a pole": the pole is its part
            # (not "a dish stands on a tall pole")
        hung = j >= 1 and self.toks[j - 1].text in _HANG_VERBS and not m.definite
        if w == "from" and hung and j - prev.end <= 2 and singular(m.phrase.split()[-1].lower()) in _HANGERS:
            return True  # "a lantern hangs from a chain above the anvil": the chain is the lantern's
        plant = self.catalogue[prev.category].shape in ("potted_plant", "bush", "flower_bed")
        if w == "with" and prev.end == j and prev.category == "vase" and not m.counted:
            # "a vase with roses in it": its flowers, as "a vase of roses" (not three flower beds)
            return self.catalogue[m.category].shape in ("potted_plant", "bush", "flower_bed")
        return w == "in" and j - prev.end <= 2 and m.category in ("pot", "planter", "vase") and plant

    def _each_full(self, m: _Mention, before: list[_Mention], j: int) -> None:
        """"Three baskets by the stove, each of them full of kittens": living things each of
        several holders is full of stand on those holders (the latest several named)."""
        toks = self.toks
        if j < 1 or (toks[j - 1].text, toks[j].text) not in _CONTENT_MARKERS:
            return
        k = j - 2
        while k >= 0 and toks[k].text in ("of", "them", "these", "those"):
            k -= 1
        if k < 0 or toks[k].text != "each" or not (self._lives(m.category) or m.category == "fish"):
            return
        several = [h for h in before if h.end <= k and _is_plural(toks, h) and self._holds_living(h)]
        if several:
            self.held_of.append((m.start, several[-1].start))
            self.aboard.add(m.start)

    def _holds_living(self, holder: _Mention) -> bool:
        """What people or animals it is full of stand on: a carrier ("a stand packed with
        fans", "a boat full of children", "a jetty crowded with anglers") or a thing with a top."""
        vocabulary, category, name = load_vocabulary(), holder.category, holder.phrase
        vessel = vocabulary.carries(category, name, _VESSEL_KINDS) or vocabulary.carries(category, name, by_family=False)
        return self.catalogue[category].support or vessel  # ("a dome full of visitors": inside it)

    def _listed_content(self, start: int) -> bool:
        """Whether the noun at ``start`` is in a list of bare nouns that a content marker opens
        ("overflow with apples, pumpkins and carrots": the pumpkins are contents too)."""
        toks = self.toks
        k = start - 1
        while k > 0 and start - k <= 10:
            w = toks[k].text
            if (toks[k - 1].text, w) in _CONTENT_MARKERS:
                return True
            if not (w in (",", "and", "or") or (w[:1].isalpha() and w not in _STOP)):
                return False
            k -= 1
        return False
