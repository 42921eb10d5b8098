"""Sentence shapes the offline reader must read whatever words fill them.

Held-out batches say how the reader does on text nobody tuned for, but each of their misses is
one sentence: fixing it teaches little about the next one. This bench turns the question
around. It writes many short sentences from a few English shapes (a fronted place phrase, an
inverted subject, an adverb before the verb, a possessive subject, an absolute clause, ...),
fills their slots from word lists of things, animals, people, adjectives and adverbs, and
annotates each from how it was built. A shape that fails for a fair share of its fillings is a
gap in the grammar, not in a word table, and its failing sentences show which.

The figures are coverage figures of the reader's grammar over sentences its authors wrote:
they guide work and guard against regressions; they are not evidence of quality on fresh text.
"""

from __future__ import annotations

import random
from collections import defaultdict
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace

from scenewright.bench.analysis import parse_figures, score_prompt
from scenewright.core.catalogue import match_phrase
from scenewright.evaluation.annotations import Prompt


@dataclass(frozen=True)
class Noun:
    singular: str
    plural: str
    kind: str  # thing | animal | person | host | small

    @property
    def key(self) -> str:
        """The annotation key: the catalogue category the word names, else the word."""
        return match_phrase(tuple(self.singular.split())) or self.singular.replace(" ", "_")


def _nouns(kind: str, spec: str) -> tuple[Noun, ...]:
    """``"cart/carts, wolf/wolves"`` → nouns: each entry is a singular and its plural."""
    out = []
    for entry in spec.split(","):
        one, many = entry.strip().split("/")
        out.append(Noun(one, many, kind))
    return tuple(out)


#: Things that stand on the ground, some in the catalogue, some only in the open vocabulary,
#: some in neither (they must still become guessed things).
THINGS = _nouns(
    "thing",
    "barrel/barrels, crate/crates, statue/statues, armchair/armchairs, cart/carts, bicycle/bicycles, "
    "wardrobe/wardrobes, organ/organs, anvil/anvils, cauldron/cauldrons, loom/looms, harp/harps, "
    "cannon/cannons, wheelbarrow/wheelbarrows, beehive/beehives, sundial/sundials, totem/totems, "
    "gramophone/gramophones, easel/easels, boiler/boilers, generator/generators, scarecrow/scarecrows",
)
ANIMALS = _nouns(
    "animal",
    "dog/dogs, cat/cats, goat/goats, fox/foxes, pig/pigs, sheep/sheep, bear/bears, wolf/wolves, "
    "deer/deer, rabbit/rabbits, tortoise/tortoises, pony/ponies, donkey/donkeys, camel/camels, "
    "badger/badgers, pet/pets, hound/hounds, calf/calves, ox/oxen, mouse/mice",
)
PEOPLE = _nouns(
    "person",
    "woman/women, man/men, farmer/farmers, guard/guards, child/children, dwarf/dwarves, elf/elves, "
    "blacksmith/blacksmiths, monk/monks, sailor/sailors, nurse/nurses, knight/knights, "
    "fisherman/fishermen, grandmother/grandmothers, clerk/clerks, robot/robots",
)
#: Things with a top others stand on.
HOSTS = _nouns(
    "host",
    "table/tables, desk/desks, bench/benches, counter/counters, crate/crates, chest/chests, "
    "workbench/workbenches, barrel/barrels",
)
#: Things small enough to stand on a host.
SMALL = _nouns(
    "small",
    "lamp/lamps, vase/vases, book/books, candle/candles, bowl/bowls, kettle/kettles, clock/clocks, "
    "radio/radios, teapot/teapots, jar/jars, basket/baskets, skull/skulls, globe/globes, "
    "lantern/lanterns, typewriter/typewriters, hourglass/hourglasses, figurine/figurines",
)
ADJECTIVES = (
    "old dusty rusty small tall red wooden iron battered carved tentacled sleepy shaggy painted brass ancient "
    "glowing striped broken huge tiny green blue enormous chipped lonely faded bronze spotted grey"
).split()
ADVERBS = "still quietly slowly proudly lazily patiently silently calmly".split()
#: Present-tense verbs by subject kind, singular forms (the plural drops the final "s").
VERBS = {
    "thing": ("stands", "sits", "rests", "waits"),
    "animal": ("sleeps", "sits", "waits", "dozes", "naps", "stands"),
    "person": ("stands", "waits", "sits", "reads", "works"),
}
#: Place phrases for ground things and the relations annotations give them.
PLACES = {
    "beside": ("side of",),
    "next to": ("side of",),
    "behind": ("behind",),
    "in front of": ("in front of",),
    "near": ("near",),
    "to the left of": ("left of",),
    "to the right of": ("right of",),
    "at the foot of": ("in front of",),
    "across from": ("in front of", "face to"),
}
NUMBERS = {1: "a", 2: "two", 3: "three", 4: "four"}


@dataclass(frozen=True)
class Case:
    shape: str
    prompt: Prompt


def _article(word: str) -> str:
    return "an" if word[0] in "aeiou" else "a"


class _Draw:
    """Random fillings of one shape: noun phrases with their count and annotation key."""

    def __init__(self, rng: random.Random):
        self.rng = rng

    def pick(self, seq):
        return self.rng.choice(seq)

    def phrase(self, noun: Noun, count: int | None = None, adjective: bool | None = None) -> tuple[str, int]:
        """An indefinite noun phrase ("a dusty organ", "three wolves") and its count."""
        count = count if count is not None else self.rng.choice((1, 1, 2, 3))
        adjective = self.rng.random() < 0.6 if adjective is None else adjective
        words = [self.pick(ADJECTIVES)] if adjective else []
        words.append(noun.singular if count == 1 else noun.plural)
        head = " ".join(words)
        det = _article(head) if count == 1 else NUMBERS[count]
        return f"{det} {head}", count

    def subject(self, kinds=("thing", "animal", "person")) -> Noun:
        kind = self.pick(kinds)
        return self.pick({"thing": THINGS, "animal": ANIMALS, "person": PEOPLE}[kind])

    def target(self, avoid: Noun) -> Noun:
        return self.pick([n for n in THINGS + HOSTS if n.key != avoid.key])

    def verb(self, noun: Noun, count: int) -> str:
        verb = self.pick(VERBS[noun.kind])
        return verb if count == 1 else verb[:-1]


def _prompt(shape: str, index: int, text: str, objects: dict, relations=(), supports=None) -> Case:
    merged: dict[str, tuple[int, int]] = {}
    for key, count in objects:
        lo, hi = merged.get(key, (0, 0))
        merged[key] = (lo + count, hi + count)
    return Case(
        shape,
        Prompt(
            id=f"{shape}-{index}",
            domain="indoor",
            style="realistic",
            text=text,
            objects=merged,
            relations=frozenset(relations),
            supports=supports or {},
        ),
    )


def _capital(text: str) -> str:
    return text[0].upper() + text[1:]


def _ground_case(draw: _Draw, shape: str, index: int, write: Callable[..., str]) -> Case:
    """A subject placed by a place phrase, in the sentence ``write`` builds from its parts."""
    subject = draw.subject()
    np_, count = draw.phrase(subject)
    target = draw.target(subject)
    tp, _ = draw.phrase(target, 1)
    place = draw.pick(list(PLACES))
    verb = draw.verb(subject, count)
    text = write(np=np_, verb=verb, place=place, target=tp, adverb=draw.pick(ADVERBS))
    relations = {(subject.key, r, target.key) for r in PLACES[place]}
    return _prompt(shape, index, text, [(subject.key, count), (target.key, 1)], relations)


def _ground_shape(write: Callable[..., str]) -> Callable[[_Draw, str, int], Case]:
    return lambda draw, shape, index: _ground_case(draw, shape, index, write)


def _pronoun(draw: _Draw, shape: str, index: int) -> Case:
    target = draw.target(draw.pick(THINGS))
    subject = draw.subject()
    while subject.key == target.key:
        subject = draw.subject()
    tp, _ = draw.phrase(target, 1)
    np_, count = draw.phrase(subject)
    place = draw.pick(list(PLACES))
    text = f"{_capital(tp)} stands in the middle. {_capital(np_)} {draw.verb(subject, count)} {place} it."
    relations = {(subject.key, r, target.key) for r in PLACES[place]}
    return _prompt(shape, index, text, [(subject.key, count), (target.key, 1)], relations)


def _possessive(draw: _Draw, shape: str, index: int) -> Case:
    owner = draw.pick(PEOPLE)
    pet = draw.pick([n for n in ANIMALS if n.singular == n.plural[:-1] or n.plural.endswith("s")])
    target = draw.target(owner)
    op, _ = draw.phrase(owner, 1)
    tp, _ = draw.phrase(target, 1)
    place = draw.pick(list(PLACES))
    adjective = f"{draw.pick(ADJECTIVES)} " if draw.rng.random() < 0.5 else ""
    text = f"{_capital(op)} waits by the door. {draw.pick(('His', 'Her', 'Their'))} {adjective}{pet.singular} {draw.verb(pet, 1)} {place} {tp}."
    relations = {(pet.key, r, target.key) for r in PLACES[place]}
    return _prompt(shape, index, text, [(owner.key, 1), (pet.key, 1), (target.key, 1)], relations)


def _absolute(draw: _Draw, shape: str, index: int) -> Case:
    """"A loom stands in the corner, a cat asleep on it.": a subject and a state, no verb."""
    host = draw.pick(HOSTS)
    rider = draw.pick(ANIMALS + SMALL)
    hp, _ = draw.phrase(host, 1)
    rp, _ = draw.phrase(rider, 1)
    state = "asleep" if rider.kind == "animal" else draw.pick(("forgotten", "abandoned", "left"))
    text = f"{_capital(hp)} stands in the corner, {rp} {state} on it."
    return _prompt(shape, index, text, [(host.key, 1), (rider.key, 1)], {(rider.key, "on", host.key)},
                   {rider.key: host.key})


def _coordinated(draw: _Draw, shape: str, index: int) -> Case:
    first, second = draw.subject(), draw.subject()
    while second.key == first.key:
        second = draw.subject()
    target = draw.target(first)
    while target.key == second.key:
        target = draw.target(first)
    fp, fc = draw.phrase(first)
    sp, sc = draw.phrase(second)
    tp, _ = draw.phrase(target, 1)
    place = draw.pick(list(PLACES))
    # (a verb both kinds do: "a dog and a barrel wait")
    verb = draw.verb(first, 2) if first.kind == second.kind else draw.pick(("stand", "wait"))
    text = f"{_capital(fp)} and {sp} {verb} {place} {tp}."
    relations = {(n.key, r, target.key) for n in (first, second) for r in PLACES[place]}
    return _prompt(shape, index, text, [(first.key, fc), (second.key, sc), (target.key, 1)], relations)


def _on_host(draw: _Draw, shape: str, index: int) -> Case:
    host, small = draw.pick(HOSTS), draw.pick(SMALL)
    hp, _ = draw.phrase(host, 1)
    sp, count = draw.phrase(small)
    verb = "stands" if count == 1 else "stand"
    text = f"{_capital(sp)} {verb} on {hp}."
    return _prompt(shape, index, text, [(small.key, count), (host.key, 1)], {(small.key, "on", host.key)},
                   {small.key: host.key})


def _with_on_it(draw: _Draw, shape: str, index: int) -> Case:
    host, small = draw.pick(HOSTS), draw.pick(SMALL)
    subject = draw.subject(("animal", "person"))
    np_, count = draw.phrase(subject)
    hp, _ = draw.phrase(host, 1)
    sp, _ = draw.phrase(small, 1)
    place = draw.pick(list(PLACES))
    text = f"{_capital(np_)} {draw.verb(subject, count)} {place} {hp} with {sp} on it."
    relations = {(subject.key, r, host.key) for r in PLACES[place]} | {(small.key, "on", host.key)}
    return _prompt(shape, index, text, [(subject.key, count), (host.key, 1), (small.key, 1)], relations,
                   {small.key: host.key})


def _each(draw: _Draw, shape: str, index: int) -> Case:
    host, small = draw.pick(HOSTS), draw.pick(SMALL)
    n = draw.rng.choice((2, 3, 4))
    hp, _ = draw.phrase(host, n)
    sp, _ = draw.phrase(small, 1)
    text = f"{_capital(hp)} stand in a row, each with {sp} on it."
    return _prompt(shape, index, text, [(host.key, n), (small.key, n)], {(small.key, "on", host.key)},
                   {small.key: host.key})


#: Verbs of a person working on a thing; annotations read them as ``near``.
WORK_VERBS = ("repairs", "polishes", "paints", "inspects", "cleans", "guards", "mends", "oils", "sweeps", "examines")
#: Verbs of having a small thing in hand; annotations put the thing ``on`` its holder.
HOLD_VERBS = ("holding", "carrying", "clutching", "with")


def _works_on(draw: _Draw, shape: str, index: int) -> Case:
    person, target = draw.pick(PEOPLE), draw.pick(THINGS)
    pp, count = draw.phrase(person)
    tp, _ = draw.phrase(target, 1)
    verb = draw.pick(WORK_VERBS)
    text = f"{_capital(pp)} {verb if count == 1 else verb[:-1]} {tp}."
    return _prompt(shape, index, text, [(person.key, count), (target.key, 1)], {(person.key, "near", target.key)})


def _holding(draw: _Draw, shape: str, index: int) -> Case:
    person, small = draw.pick(PEOPLE), draw.pick(SMALL)
    target = draw.target(person)
    pp, _ = draw.phrase(person, 1)
    tp, _ = draw.phrase(target, 1)
    sp, _ = draw.phrase(small, 1)
    place = draw.pick(list(PLACES))
    text = f"{_capital(pp)} {draw.verb(person, 1)} {place} {tp}, {draw.pick(HOLD_VERBS)} {sp}."
    relations = {(person.key, r, target.key) for r in PLACES[place]} | {(small.key, "on", person.key)}
    return _prompt(shape, index, text, [(person.key, 1), (target.key, 1), (small.key, 1)], relations,
                   {small.key: person.key})


def _two_clauses(draw: _Draw, shape: str, index: int) -> Case:
    """Two placed subjects in one sentence, joined by "and" or "while"."""
    parts, objects, relations = [], [], set()
    used: set[str] = set()
    for _ in range(2):
        subject = draw.subject()
        while subject.key in used:
            subject = draw.subject()
        target = draw.target(subject)
        while target.key in used | {subject.key}:
            target = draw.target(subject)
        used |= {subject.key, target.key}
        np_, count = draw.phrase(subject)
        tp, _ = draw.phrase(target, 1)
        place = draw.pick(list(PLACES))
        parts.append(f"{np_} {draw.verb(subject, count)} {place} {tp}")
        objects += [(subject.key, count), (target.key, 1)]
        relations |= {(subject.key, r, target.key) for r in PLACES[place]}
    text = f"{_capital(parts[0])}{draw.pick((', and ', ' and ', ' while ', ', while '))}{parts[1]}."
    return _prompt(shape, index, text, objects, relations)


def _between(draw: _Draw, shape: str, index: int) -> Case:
    subject = draw.subject()
    first = draw.target(subject)
    second = draw.target(subject)
    while second.key == first.key:
        second = draw.target(subject)
    np_, _ = draw.phrase(subject, 1)
    fp, _ = draw.phrase(first, 1)
    sp, _ = draw.phrase(second, 1)
    text = f"{_capital(np_)} {draw.verb(subject, 1)} between {fp} and {sp}."
    case = _prompt(shape, index, text, [(subject.key, 1), (first.key, 1), (second.key, 1)])
    return Case(shape, replace(case.prompt, between=frozenset({(subject.key, first.key, second.key)})))


def _each_of(draw: _Draw, shape: str, index: int) -> Case:
    host = draw.pick(HOSTS)
    rider = draw.pick(ANIMALS + SMALL)
    n = draw.rng.choice((2, 3, 4))
    text = f"{_capital(_article(rider.singular))} {rider.singular} {draw.pick(('stands', 'sits', 'rests'))} on each of the {NUMBERS[n]} {host.plural}."
    return _prompt(shape, index, text, [(host.key, n), (rider.key, n)], {(rider.key, "on", host.key)},
                   {rider.key: host.key})


def _either_side(draw: _Draw, shape: str, index: int) -> Case:
    subject = draw.subject()
    target = draw.target(subject)
    np_, _ = draw.phrase(subject, 2)
    tp, _ = draw.phrase(target, 1)
    text = f"{_capital(np_)} {draw.verb(subject, 2)} on either side of {tp}."
    relations = {(subject.key, "left of", target.key), (subject.key, "right of", target.key)}
    return _prompt(shape, index, text, [(subject.key, 2), (target.key, 1)], relations)


def _dressed(draw: _Draw, shape: str, index: int) -> Case:
    """A person in what they wear: the clothes are no object."""
    person = draw.pick(PEOPLE)
    target = draw.target(person)
    pp, _ = draw.phrase(person, 1)
    tp, _ = draw.phrase(target, 1)
    place = draw.pick(list(PLACES))
    wear = draw.pick(("in a red coat", "in a tweed cap", "with a long beard", "in blue overalls", "wearing a leather apron"))
    text = f"{_capital(pp)} {wear} {draw.verb(person, 1)} {place} {tp}."
    relations = {(person.key, r, target.key) for r in PLACES[place]}
    return _prompt(shape, index, text, [(person.key, 1), (target.key, 1)], relations)


def _in_it(draw: _Draw, shape: str, index: int) -> Case:
    """A holder with a living thing in it: the annotations put what is in a holder on it."""
    holder = draw.pick(_nouns("thing", "cart/carts, wheelbarrow/wheelbarrows, basket/baskets, crate/crates, tub/tubs"))
    rider = draw.pick(ANIMALS[:6])
    target = draw.target(holder)
    hp, _ = draw.phrase(holder, 1)
    tp, _ = draw.phrase(target, 1)
    rp, _ = draw.phrase(rider, 1, adjective=False)
    text = f"{_capital(hp)} stands beside {tp} with {rp} in it."
    relations = {(holder.key, "side of", target.key), (rider.key, "on", holder.key)}
    return _prompt(shape, index, text, [(holder.key, 1), (target.key, 1), (rider.key, 1)], relations,
                   {rider.key: holder.key})


def _row_of(draw: _Draw, shape: str, index: int) -> Case:
    subject = draw.pick(THINGS)
    target = draw.target(subject)
    n = draw.rng.choice((3, 4))
    tp, _ = draw.phrase(target, 1)
    place = draw.pick(list(PLACES))
    text = f"A row of {NUMBERS[n]} {subject.plural} stands {place} {tp}."
    relations = {(subject.key, r, target.key) for r in PLACES[place]}
    return _prompt(shape, index, text, [(subject.key, n), (target.key, 1)], relations)


def _nested(draw: _Draw, shape: str, index: int) -> Case:
    """"A cat sleeps on a cushion on the sofa": the second place phrase places the first's thing."""
    rider = draw.pick(ANIMALS[:6] + SMALL)
    middle = draw.pick(_nouns("small", "cushion/cushions, tray/trays, mat/mats, blanket/blankets, box/boxes"))
    host = draw.pick(HOSTS)
    mp, _ = draw.phrase(middle, 1)
    hp, _ = draw.phrase(host, 1)
    rp, _ = draw.phrase(rider, 1)
    text = f"{_capital(rp)} {'sleeps' if rider.kind == 'animal' else 'stands'} on {mp} on {hp}."
    relations = {(rider.key, "on", middle.key), (middle.key, "on", host.key)}
    return _prompt(shape, index, text, [(rider.key, 1), (middle.key, 1), (host.key, 1)], relations,
                   {rider.key: middle.key, middle.key: host.key})


def _one_of_them(draw: _Draw, shape: str, index: int) -> Case:
    person, small = draw.pick(PEOPLE), draw.pick(SMALL)
    seat = draw.pick(_nouns("host", "bench/benches, sofa/sofas"))
    n = draw.rng.choice((2, 3, 4))
    sp, _ = draw.phrase(seat, 1)
    kp, _ = draw.phrase(small, 1)
    text = f"{_capital(NUMBERS[n])} {person.plural} sit on {sp}, one of them {draw.pick(HOLD_VERBS[:3])} {kp}."
    relations = {(person.key, "on", seat.key), (small.key, "on", person.key)}
    return _prompt(shape, index, text, [(person.key, n), (seat.key, 1), (small.key, 1)], relations,
                   {person.key: seat.key, small.key: person.key})


def _group_of(draw: _Draw, shape: str, index: int) -> Case:
    """"A group of three monks waits by the cart": the members are the things."""
    person = draw.pick(PEOPLE)
    target = draw.target(person)
    n = draw.rng.choice((2, 3, 4))
    tp, _ = draw.phrase(target, 1)
    place = draw.pick(list(PLACES))
    group = draw.pick(("group", "crowd", "band", "family", "team"))
    text = f"A {group} of {NUMBERS[n]} {person.plural} waits {place} {tp}."
    relations = {(person.key, r, target.key) for r in PLACES[place]}
    return _prompt(shape, index, text, [(person.key, n), (target.key, 1)], relations)


def _inverted_the(draw: _Draw, shape: str, index: int) -> Case:
    """"Beside the gate stands the old sentinel": one subject, named with "the" after its verb."""
    subject = draw.subject()
    target = draw.target(subject)
    words = f"{draw.pick(ADJECTIVES)} {subject.singular}" if draw.rng.random() < 0.5 else subject.singular
    tp, _ = draw.phrase(target, 1)
    place = draw.pick(list(PLACES))
    text = f"{_capital(place)} {tp} {draw.verb(subject, 1)} the {words}."
    relations = {(subject.key, r, target.key) for r in PLACES[place]}
    return _prompt(shape, index, text, [(subject.key, 1), (target.key, 1)], relations)


#: Shape name → how one sentence of it is built.
SHAPES: dict[str, Callable[[_Draw, str, int], Case]] = {
    "plain": _ground_shape(lambda np, verb, place, target, **_: f"{_capital(np)} {verb} {place} {target}."),
    "adverb": _ground_shape(
        lambda np, verb, place, target, adverb, **_: f"{_capital(np)} {adverb} {verb} {place} {target}."
    ),
    "fronted": _ground_shape(lambda np, verb, place, target, **_: f"{_capital(place)} {target} {np} {verb}."),
    "fronted_comma": _ground_shape(lambda np, verb, place, target, **_: f"{_capital(place)} {target}, {np} {verb}."),
    "inverted": _ground_shape(lambda np, verb, place, target, **_: f"{_capital(place)} {target} {verb} {np}."),
    "inverted_the": _inverted_the,
    "there_is": _ground_shape(
        lambda np, verb, place, target, **_: f"There {'is' if np.split()[0] in ('a', 'an') else 'are'} {np} {place} {target}."
    ),
    "verbless": _ground_shape(lambda np, verb, place, target, **_: f"In the yard, {np} {place} {target}."),
    "pronoun": _pronoun,
    "possessive": _possessive,
    "absolute": _absolute,
    "coordinated": _coordinated,
    "on_host": _on_host,
    "with_on_it": _with_on_it,
    "each": _each,
    "works_on": _works_on,
    "holding": _holding,
    "two_clauses": _two_clauses,
    "between": _between,
    "each_of": _each_of,
    "either_side": _either_side,
    "dressed": _dressed,
    "in_it": _in_it,
    "row_of": _row_of,
    "nested": _nested,
    "one_of_them": _one_of_them,
    "group_of": _group_of,
}


def cases(per_shape: int = 40, seed: int = 0, shapes: list[str] | None = None) -> Iterator[Case]:
    """``per_shape`` sentences of every shape, the same ones for the same seed."""
    for name in shapes or SHAPES:
        draw = _Draw(random.Random(f"{seed}-{name}"))
        for index in range(per_shape):
            yield SHAPES[name](draw, name, index)


def run_constructions_bench(per_shape: int = 40, seed: int = 0, failures: int = 3) -> dict:
    """Per shape: object and relation recall/precision and the share of sentences read right,
    with up to ``failures`` sentences it misread."""
    rows: dict[str, list[dict]] = defaultdict(list)
    for case in cases(per_shape, seed):
        row = score_prompt(case.prompt) | {"text": case.prompt.text}
        rows[case.shape].append(row)
    shapes = {}
    for name, shape_rows in rows.items():
        wrong = [r for r in shape_rows if r["missing_objects"] or r["extra_objects"] or r["missing_relations"]
                 or r["wrong_relations"]]
        shapes[name] = parse_figures(shape_rows) | {
            "read_right": round(1 - len(wrong) / len(shape_rows), 4),
            "misread": [
                {k: r[k] for k in ("text", "missing_objects", "extra_objects", "missing_relations", "wrong_relations")}
                for r in wrong[:failures]
            ],
        }
    everything = [r for shape_rows in rows.values() for r in shape_rows]
    right = sum(not (r["missing_objects"] or r["extra_objects"] or r["missing_relations"] or r["wrong_relations"])
                for r in everything)
    return {"sentences": len(everything), "read_right": round(right / len(everything), 4),
            **parse_figures(everything), "shapes": shapes}
