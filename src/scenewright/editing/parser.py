"""The offline edit planner: imperative instructions → :class:`EditPlan`, by rules.

It reads one instruction as *verb, focus, placement clauses* ("move the lamp next to the
sofa, facing the bed"); a request worded as a wish or a statement ("I'd like the lamp beside
the sofa", "the chair should face the desk") is first rewritten into that order. A move that
names no other object ("a bit to the left", "1 m back") shifts the focus from where it stands
(:attr:`EditPlan.offset`). It resolves every object reference against the scene (ids, names,
categories and their synonyms, colour or material words, ordinals and side words such as
"the second chair" or "the left chair") and refuses to guess: an ambiguous reference asks
which object is meant, naming the candidates, and an unknown one names what the scene has.
Placement phrases come from the text parser's vocabulary
(:func:`scenewright.analysis.parser.relation_phrases`), so generation and editing read
"beside" or "on top of" the same way.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from functools import lru_cache

from scenewright.core.catalogue import Category, load_catalogue, lookup, singular, words
from scenewright.analysis.parser import relation_phrases
from scenewright.analysis.parser.room import CEILING_THINGS, WALL_THINGS
from scenewright.analysis.parser.words import ORDINALS
from scenewright.core.plan import EditPlan, NewObject, RoomEdit
from scenewright.errors import InputError
from scenewright.layout.room import wall_facing
from scenewright.scene import CEILING_TARGET, ROOM_TARGET, Constraint, Scene, SceneObject, Vec3

_POLITE = ("please", "kindly", "can you", "could you", "would you", "will you", "can we", "could we",
           "i want you to", "i'd like you to", "i would like you to", "i need you to", "let's", "let", "lets",
           "let us", "now", "then", "also", "and", "maybe", "perhaps", "just", "go ahead and",
           "would it be possible to", "is it possible to", "i'd like to", "i would like to", "i want to",
           "it would be nice to", "it'd be nice to", "it would be great to", "it would be better to")  # fmt: skip
_DELETE = ("get rid of", "take away", "take out", "clear away", "remove", "delete", "erase",
           "eliminate", "discard", "drop")  # fmt: skip
_ADD = ("add", "insert", "create", "include", "introduce")
_PLACE = ("put", "place", "set", "position", "stand", "hang", "mount", "lay", "lean", "park", "stick")
_MOVE = ("move", "shift", "push", "pull", "slide", "bring", "relocate", "drag", "carry", "reposition",
         "nudge", "scoot", "budge")  # fmt: skip
_TURN = ("turn", "rotate", "spin", "swivel", "orient", "face")
_REPLACE = ("replace", "swap", "exchange", "substitute", "change", "make", "paint", "colour",
            "color", "recolour", "recolor", "restyle", "convert", "transform", "upgrade", "redo")  # fmt: skip
#: Words that introduce a new object rather than name an existing one.
_INDEFINITE = ("a", "an", "another", "one more", "a new", "an extra", "one", "some", "a second", "an additional")
_DETERMINERS = {"the", "this", "that", "my", "our", "its", "their", "your"}
#: Side words → (axis, pick the largest?): "left" is the smallest x in the scene frame.
_SIDES = {
    "left": (0, False), "leftmost": (0, False), "right": (0, True), "rightmost": (0, True),
    "front": (1, False), "frontmost": (1, False), "nearest": (1, False), "back": (1, True),
    "rear": (1, True), "backmost": (1, True), "farthest": (1, True), "far": (1, True),
    "lower": (2, False), "bottom": (2, False), "upper": (2, True), "top": (2, True),
}  # fmt: skip
_SIZES = {"biggest": True, "largest": True, "smallest": False, "tallest": True}
_SCALES = {
    "bigger": (1.5, 1.5, 1.5), "larger": (1.5, 1.5, 1.5), "smaller": (0.67, 0.67, 0.67),
    "taller": (1.0, 1.0, 1.5), "shorter": (1.0, 1.0, 0.67), "wider": (1.5, 1.0, 1.0),
    "narrower": (0.67, 1.0, 1.0), "longer": (1.5, 1.0, 1.0), "huge": (2.0, 2.0, 2.0),
    "tiny": (0.5, 0.5, 0.5),
}  # fmt: skip
#: Where a clause ends and the next begins: the target of one relation stops at these.
_CLAUSE = re.compile(r"\s*(?:,|;|\band then\b|\bthen\b|\band\b|\bso that\b|\bwhile\b|\bwith it\b)\s*")
_PRONOUNS = {"it", "itself", "them", "him", "her"}


@dataclass(frozen=True)
class _Phrase:
    """A relation phrase found in the text: where, and which relations it stands for."""

    start: int
    end: int
    relations: tuple[str, ...]


def _normalise(instruction: str) -> str:
    text = instruction.strip().lower().replace("’", "'")
    text = re.sub(r"[\"“”!?.]+", " ", text)
    text = re.sub(r"(?<=\w)'s\b", "", text)  # "the sofa's colour" → "the sofa colour"
    text = re.sub(r"\s*([,;])\s*", r" \1 ", text)
    return " ".join(text.split())


def _strip_lead(text: str) -> str:
    changed = True
    while changed:
        changed = False
        for word in _POLITE:
            if text == word or text.startswith(word + " "):
                text = text[len(word):].lstrip(" ,")
                changed = True
    return text


def _starts(text: str, words_: Sequence[str]) -> str | None:
    for word in sorted(words_, key=len, reverse=True):
        if text == word or text.startswith(word + " "):
            return word
    return None


#: Comparatives only an edit uses ("move it closer to the sofa"), on top of the text parser's phrases.
_EDIT_PHRASES = {
    "closer to": ("near",), "nearer to": ("near",), "nearer": ("near",), "up to": ("near",),
    "further from": ("far",), "farther from": ("far",), "further away from": ("far",),
    "farther away from": ("far",), "over to": ("near",), "over by": ("near",), "across to": ("near",),
}  # fmt: skip
_FILLERS = re.compile(r"\b(?:a bit|a little|a little bit|slightly|somewhat|just|over|instead)\b")


@lru_cache(maxsize=1)
def _vocabulary() -> list[tuple[re.Pattern[str], tuple[str, ...]]]:
    """The relation phrases as whole-word patterns, longest first."""
    ordered = sorted({**relation_phrases(), **_EDIT_PHRASES}.items(), key=lambda kv: -len(kv[0]))
    return [(re.compile(rf"(?<![\w]){re.escape(phrase)}(?![\w])"), tuple(rels)) for phrase, rels in ordered]


def _find_phrases(text: str) -> list[_Phrase]:
    """Every relation phrase in ``text``, longest match first, never overlapping."""
    found: list[_Phrase] = []
    taken: list[tuple[int, int]] = []
    for pattern, relations in _vocabulary():
        for m in pattern.finditer(text):
            if any(m.start() < e and s < m.end() for s, e in taken):
                continue
            taken.append((m.start(), m.end()))
            found.append(_Phrase(m.start(), m.end(), relations))
    return sorted(found, key=lambda p: p.start)


# --- object references -----------------------------------------------------------------------


def _tokens(obj: SceneObject) -> set[str]:
    """Every word the object answers to: id, name, category and the category's synonyms."""
    out = {singular(w) for w in words(obj.name)} | set(words(obj.id.replace("_", " ")))
    category = load_catalogue().get(obj.category or "")
    if category is not None:
        for phrase in category.phrases:
            out |= {singular(w) for w in words(phrase)}
    return out


def _describe(objects: Sequence[SceneObject]) -> str:
    return ", ".join(f"{o.id} ({o.name})" for o in objects)


def _category_of(tokens: list[str]) -> tuple[Category | None, int]:
    """The catalogue category the phrase's noun names, and where that noun starts.

    The longest run of trailing words wins ("coffee table" over "table"); failing that, the
    longest run anywhere, so "lamp with a shade" still finds the lamp.
    """
    for start in range(len(tokens)):
        category = lookup(" ".join(tokens[start:]))
        if category is not None:
            return category, start
    for length in range(len(tokens), 0, -1):
        for start in range(len(tokens) - length + 1):
            category = lookup(" ".join(tokens[start:start + length]))
            if category is not None:
                return category, start
    return None, len(tokens)


def category_in(*texts: str | None) -> Category | None:
    """The catalogue category the first of ``texts`` that names one names ("brass lantern",
    "torii_gate" → none, "stone gate arch" → arch); for plans a model wrote in its own words."""
    for text in texts:
        if text:
            category, _ = _category_of(words(text.replace("_", " ")))
            if category is not None:
                return category
    return None


def resolve(scene: Scene, phrase: str, *, role: str = "object") -> SceneObject:
    """The one scene object ``phrase`` names, or an InputError that says what to write instead."""
    phrase = text = phrase.strip()
    raw = text.replace(" ", "_")
    for obj in scene.objects:  # an exact id, "chair_2" or "chair 2"
        if obj.id.lower() in (text, raw):
            return obj
    tokens = [t for t in words(text) if t not in _DETERMINERS and t not in ("one", "object", "thing")]
    if not tokens:
        raise InputError(f"which {role}? name one of: {_describe(scene.objects)}")
    ordinal = next((ORDINALS[t] for t in tokens if t in ORDINALS), None)
    last = "last" in tokens
    side = next((_SIDES[t] for t in tokens if t in _SIDES), None)
    middle = any(t in ("middle", "centre", "center", "central") for t in tokens)
    extreme = next((_SIZES[t] for t in tokens if t in _SIZES), None)
    number = next((int(t) for t in tokens if t.isdigit()), None)
    skip = set(ORDINALS) | set(_SIDES) | set(_SIZES) | {"last", "middle", "centre", "center", "central", "side", "number", "no"}
    nouns = [t for t in tokens if t not in skip and not t.isdigit()]
    if not nouns:
        raise InputError(f"which {role} is {phrase!r}? the scene has: {_describe(scene.objects)}")
    category, head = _category_of(nouns)
    if category is not None:
        candidates = [o for o in scene.objects if o.category == category.name]
        modifiers = nouns[:head]
    else:
        candidates = []
        modifiers = nouns[:-1]
    if not candidates:  # a name the catalogue does not know ("the torii gate", "the robot")
        every, last = {singular(t) for t in nouns}, {singular(nouns[-1])}
        candidates = [o for o in scene.objects if every <= _tokens(o)] or [
            o for o in scene.objects if last <= _tokens(o)
        ]
    if not candidates:
        raise InputError(
            f"there is no {' '.join(nouns)} in the scene; it has: {_describe(scene.objects)}"
        )
    if modifiers:  # colour, material and name words narrow the choice when some object has them
        def has_all(o: SceneObject) -> bool:
            text_words = {singular(w) for w in words(f"{o.name} {o.visual_description}")} | _tokens(o)
            return all(singular(m) in text_words for m in modifiers)

        narrowed = [o for o in candidates if has_all(o)]
        candidates = narrowed or candidates
    if number is not None:
        numbered = [o for o in candidates if o.id.rsplit("_", 1)[-1] == str(number)]
        if not numbered:
            raise InputError(f"there is no {nouns[-1]} number {number}; there are: {_describe(candidates)}")
        candidates = numbered
    if len(candidates) > 1 and (ordinal is not None or last):
        ordered = sorted(candidates, key=_id_index)
        index = len(ordered) - 1 if last else ordinal
        if index >= len(ordered):
            raise InputError(
                f"there are only {len(ordered)} {nouns[-1]}s, so no number {index + 1}: {_describe(ordered)}"
            )
        candidates = [ordered[index]]
    if len(candidates) > 1 and side is not None:
        axis, largest = side
        key = lambda o: o.position.tuple()[axis]  # noqa: E731
        candidates = [max(candidates, key=key) if largest else min(candidates, key=key)]
    if len(candidates) > 1 and middle:
        ordered = sorted(candidates, key=lambda o: o.position.x)
        candidates = [ordered[(len(ordered) - 1) // 2]] if len(ordered) % 2 else candidates
    if len(candidates) > 1 and extreme is not None:
        volume = lambda o: o.size.x * o.size.y * o.size.z  # noqa: E731
        candidates = [max(candidates, key=volume) if extreme else min(candidates, key=volume)]
    if len(candidates) > 1:
        raise InputError(
            f"{phrase!r} is ambiguous: which one? the scene has {len(candidates)}: {_describe(candidates)}; "
            f"say it by id (e.g. {candidates[0].id!r}) or as 'the left/right/second ...'"
        )
    return candidates[0]


def _id_index(obj: SceneObject) -> tuple[int, str]:
    tail = obj.id.rsplit("_", 1)[-1]
    return (int(tail) if tail.isdigit() else 0, obj.id)


def fresh_id(scene: Scene, category: str) -> str:
    """The first unused ``<category>_<n>``; ids of removed objects stay taken, so undo never clashes."""
    used = {o.id for o in scene.objects} | {r.id for r in scene.removed}
    index = 1
    while f"{category}_{index}" in used:
        index += 1
    return f"{category}_{index}"


# --- placement clauses -----------------------------------------------------------------------


def _constraints(scene: Scene, focus: SceneObject | None, focus_id: str, text: str) -> list[Constraint]:
    """The constraints a placement text asks for, with the focus as the only source."""
    phrases = _find_phrases(text)
    out: list[Constraint] = []
    for index, found in enumerate(phrases):
        stop = phrases[index + 1].start if index + 1 < len(phrases) else len(text)
        target_text = _CLAUSE.split(text[found.end:stop], maxsplit=1)[0].strip()
        # "between the sofa and the lamp": both are targets
        targets = [target_text]
        if "between" in text[found.start:found.end]:
            targets = [t for t in re.split(r"\band\b|,", text[found.end:stop]) if t.strip()]
        for phrase in targets:
            phrase = phrase.strip()
            if not phrase or phrase in _PRONOUNS or not words(phrase):
                raise InputError(
                    f"{text[found.start:found.end]!r} of what? name the object, e.g. "
                    f"'{text[found.start:found.end]} the {scene.objects[0].name if scene.objects else 'table'}'"
                )
            target = resolve(scene, phrase, role="target")
            if focus is not None and target.id == focus.id:
                raise InputError(f"{focus.id} cannot be placed relative to itself; name another object")
            for relation in found.relations:
                c = Constraint(relation=relation, source=focus_id, target=target.id)
                if c.key() not in {k.key() for k in out}:
                    out.append(c)
    return out


#: A place in the room rather than by an object: "against the left wall", "in the corner",
#: "on the back wall", "from the ceiling".
_ROOM_PHRASE = re.compile(
    r"\b(?:(?:up |flush |right |back )?(against|along|onto|on|to|by|next to|in|into|from|under|below|at)\s+)"
    r"(?:the |a |one |that )?(?:(back|rear|far|front|left|right)(?:[- ]hand)?\s+)?(?:(side)\s+)?(walls?|corner|ceiling)\b"
)
_ROOM_SIDES = {"back": "back", "rear": "back", "far": "back", "front": "front", "left": "left", "right": "right"}


def _room_constraint(scene: Scene, focus_id: str, category: str | None, match: re.Match[str]) -> Constraint:
    """The room relation a room phrase asks for: a wall thing (or "on"/"onto" a wall) hangs on
    it, anything else stands against it; "in the corner" and "from the ceiling" likewise."""
    if scene.room is None:
        raise InputError(
            f"{match.group(0)!r}: this scene has no room (it stands on open ground); give it one with "
            "'make the room 4 by 5 metres', or place it relative to an object"
        )
    word, side, what = match.group(1), match.group(2), match.group(4)
    if what == "ceiling":
        return Constraint(relation="on ceiling", source=focus_id, target=CEILING_TARGET)
    target = f"wall_{wall_facing(scene.room, _ROOM_SIDES[side])}" if side else ROOM_TARGET
    if what == "corner":
        return Constraint(relation="in corner", source=focus_id, target=ROOM_TARGET)
    mounted = category in WALL_THINGS or category in CEILING_THINGS or word in ("on", "onto")
    return Constraint(relation="on wall" if mounted else "against wall", source=focus_id, target=target)


def _without_room_phrase(scene: Scene, focus_id: str, category: str | None, text: str) -> tuple[str, list[Constraint]]:
    """``text`` with its room phrase cut out, and the room relation it asked for (if any)."""
    m = _ROOM_PHRASE.search(text)
    if m is None:
        return text, []
    return text[: m.start()] + " " + text[m.end():], [_room_constraint(scene, focus_id, category, m)]


_ROOM_SIZE = re.compile(
    r"^(?:make|resize|change|set|enlarge|shrink|grow)\s+(?:the\s+)?room\s+(?:size\s+)?(?:to\s+|into\s+)?(?:be\s+)?"
    r"(\d+(?:\.\d+)?)\s*(?:m|metres?|meters?)?\s*(?:by|x|×)\s*(\d+(?:\.\d+)?)\s*(?:m|metres?|meters?)?"
    r"(?:\s*(?:by|x|×)\s*(\d+(?:\.\d+)?)\s*(?:m|metres?|meters?)?(?:\s+(?:high|tall))?)?\s*$"
)
_ROOM_OPENING = re.compile(
    r"^(?:add|put|cut|insert|make|open|create)\s+(?:a|an|one|another|a new|an extra)\s+(window|door|doorway)"
    r"(?:\s+(?:on|in|into|to)\s+(?:the\s+)?(back|rear|far|front|left|right)(?:[- ]hand)?(?:\s+side)?(?:\s+wall)?)?\s*$"
)


def _plan_room(scene: Scene, text: str) -> EditPlan | None:
    """A change to the room itself: its size, or a door or window added; None for anything else."""
    size, opening = _ROOM_SIZE.match(text), _ROOM_OPENING.match(text)
    if size is None and opening is None:
        return None
    if scene.room is None:
        raise InputError("this scene has no room (it stands on open ground); generate it with --room WxD or --room auto")
    if size is not None:
        height = float(size.group(3)) if size.group(3) else None
        return EditPlan(operation="room", focus="room",
                        room=RoomEdit(size=(float(size.group(1)), float(size.group(2))), height=height))
    kind = "door" if opening.group(1).startswith("door") else "window"
    side = _ROOM_SIDES[opening.group(2)] if opening.group(2) else None
    return EditPlan(operation="room", focus="room", room=RoomEdit(opening=kind, side=side))


def _split_target(rest: str, separators: Sequence[str]) -> tuple[str, str] | None:
    for sep in separators:
        m = re.search(rf"(?<![\w]){re.escape(sep)}(?![\w])", rest)
        if m:
            return rest[: m.start()].strip(), rest[m.end():].strip()
    return None


def _new_object(scene: Scene, phrase: str, *, base: SceneObject | None = None) -> NewObject:
    """What a noun phrase describes: a new category when it names one, else a restyle of ``base``."""
    tokens = [t for t in words(phrase) if t not in _DETERMINERS]
    while tokens and " ".join(tokens[:2]) in _INDEFINITE or (tokens and tokens[0] in _INDEFINITE):
        tokens = tokens[2:] if " ".join(tokens[:2]) in _INDEFINITE else tokens[1:]
    if not tokens:
        raise InputError(f"what should {phrase!r} be? describe the object, e.g. 'a red armchair'")
    category, head = _category_of(tokens)
    description = " ".join(tokens)
    if base is not None and (category is None or category.name == base.category):
        # A restyle: the same kind of object with a new look (and maybe a new size).
        scale = next((_SCALES[t] for t in tokens if t in _SCALES), None)
        size = Vec3.of(a * b for a, b in zip(base.size.tuple(), scale)) if scale else None
        look = [t for t in tokens if t not in _SCALES]
        if category is not None:  # "a red persian rug": the phrase names the object itself
            return NewObject(name=" ".join(look[head:]) or base.name, category=base.category,
                             visual_description=" ".join(look), size=size)
        known = load_catalogue().get(base.category or "")
        label = known.label if known else ""
        noun = label if label and label in " ".join(words(base.name)) else base.name
        description = f"{' '.join(look)} {noun}".strip()
        return NewObject(name=base.name, category=base.category, visual_description=description, size=size)
    if category is None:
        raise InputError(
            f"I do not know what {description!r} is; the offline planner knows catalogue objects "
            f"(e.g. {', '.join(list(load_catalogue())[:8])}, ...); use a model backend (--vlm openai:MODEL) for others"
        )
    noun_end = head + 1
    while noun_end < len(tokens) and lookup(" ".join(tokens[head:noun_end + 1])) == category:
        noun_end += 1
    name = " ".join(tokens[head:noun_end]) if noun_end > head else category.label
    return NewObject(name=singular(name) if " " not in name else name, category=category.name,
                     visual_description=description, size=Vec3.of(category.size))


_COUNTS = re.compile(
    r"^(?:[2-9]|\d\d+|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|several|some|many|few|"
    r"a few|a couple of|a couple|a pair of|a number of|a lot of|lots of|a dozen|a set of)\b"
)


def _count_check(phrase: str) -> None:
    """Refuse several new objects at once: an edit changes one object, and each gets its own place."""
    text = " ".join(words(phrase))
    counted = _COUNTS.match(text)
    if counted:
        rest = text[counted.end():]
        tokens = [singular(t) for t in words(rest)]
        category = next(  # the counted noun comes first: the longest run of words from the start
            (found for end in range(len(tokens), 0, -1) if (found := lookup(" ".join(tokens[:end]))) is not None), None
        )
        noun = category.label if category is not None else (singular(tokens[0]) if tokens else "object")
        raise InputError(f"one object per edit: add them one at a time (e.g. 'add a {noun} ...', then another)")


def plan_edit_offline(scene: Scene, instruction: str) -> EditPlan:
    """The edit an instruction asks for, resolved against ``scene``."""
    text = _strip_lead(_normalise(instruction))
    if not text:
        raise InputError(
            "the instruction is empty; say what to change, e.g. 'move the lamp next to the sofa' "
            "or 'remove the rug'"
        )
    if not scene.objects and not text.startswith(_ADD):
        raise InputError("the scene has no objects; the only edit possible is to add one, e.g. 'add a sofa'")
    _single_edit_check(text)
    plan = _plan_room(scene, text) or _plan_imperative(scene, text)
    if plan is None:  # a wish or a statement: read as the command it amounts to
        imperative = _imperative(text)
        plan = _plan_imperative(scene, _strip_lead(imperative)) if imperative is not None else None
    if plan is None:
        known = ", ".join(("move/put/place", "turn/rotate", "remove/delete", "add", "replace/swap/change/make/paint"))
        raise InputError(
            f"I cannot tell what {instruction.strip()!r} asks; start with one of: {known} "
            "(e.g. 'move the lamp next to the sofa')"
        )
    return plan


_EDIT_VERBS = (*_DELETE, *_ADD, *_PLACE, *_MOVE, *_TURN, *_REPLACE)
#: After an edit verb, words that start a reference to another object ("... and add a lamp").
_ANOTHER_OBJECT = re.compile(r"(?:the|a|an|another|this|that|these|those|my|our|some|one)\b")


def _verb_clauses(text: str) -> Iterator[tuple[re.Match[str], str, str]]:
    """Each later clause of ``text`` that starts with an edit verb: (the cut, the verb, the clause).
    "a black and white rug" has none: only a verb starts a clause."""
    for cut in _CLAUSE.finditer(text):
        clause = _strip_lead(text[cut.end():])
        verb = _starts(clause, _EDIT_VERBS)
        if verb:
            yield cut, verb, clause


def _first_clause(text: str) -> str:
    """``text`` up to its first clause with a verb of its own ("a lamp and put it on the desk")."""
    cut = next(_verb_clauses(text), None)
    return text if cut is None else text[: cut[0].start()]


def _single_edit_check(text: str) -> None:
    """Refuse two edits in one instruction ("remove the vase and add a lamp"): each is its own
    step of the history, so undo stays one step per change. A clause that goes on with the
    same object ("... and turn it to face the bed", "..., facing the sofa") is the same edit."""
    for cut, verb, clause in _verb_clauses(text):
        if verb != "face" and _ANOTHER_OBJECT.match(clause[len(verb):].strip()):
            first = text[: cut.start()].strip()
            raise InputError(f"one edit at a time: run {first!r}, then {clause!r} as a second edit")


def _plan_imperative(scene: Scene, text: str) -> EditPlan | None:
    """The edit a command (normalised text starting with its verb) asks for; None when it
    starts with no verb the planner knows."""
    verb = _starts(text, _DELETE)
    if verb:
        focus = resolve(scene, _CLAUSE.split(text[len(verb):], maxsplit=1)[0], role="object to remove")
        return EditPlan(operation="delete", focus=focus.id)

    verb = _starts(text, _ADD) or _starts(text, _PLACE)
    if verb:
        rest = text[len(verb):].strip()
        _count_check(rest)
        if verb in _ADD or _starts(rest, _INDEFINITE) or rest.split(" ", 1)[0].isdigit():
            return _plan_add(scene, rest)
        return _plan_move(scene, rest)

    verb = _starts(text, _MOVE)
    if verb:
        return _plan_move(scene, text[len(verb):].strip(), small=verb in _SOFT_VERBS)

    verb = _starts(text, _TURN)
    if verb:
        rest = text[len(verb):].strip()
        if verb != "face" and _split_target(rest, ("into",)) is not None:  # "turn the rug into ..."
            return _plan_replace(scene, verb, rest)
        if verb == "face" or (not _find_phrases(rest) and re.search(r"\btowards?\b", rest)):
            focus_text, target_text = _split_face(rest)  # "turn the chair towards the window"
            rest = f"{focus_text} to face {target_text}"
        return _plan_move(scene, rest, turning=True)

    verb = _starts(text, _REPLACE)
    if verb:
        rest = text[len(verb):].strip()
        if verb == "make" and re.search(r"\bface\b|\bfacing\b", rest):
            return _plan_move(scene, rest, turning=True)
        return _plan_replace(scene, verb, rest)
    return None


#: "I'd like ...", "we need ...", "have ...": a wish for how the scene should be.
_WISH = re.compile(r"^(?:(?:i|we)(?:'d| would) (?:like|love|prefer)|(?:i|we) (?:want|need)|have|see|give me)\s+")
#: "<object> should|could|needs to ... <predicate>": a statement of how the object should be.
_MODAL = re.compile(r"(?<=\s)(?:should|must|shall|could|would|can|will|might|needs? to|has to|have to|ought to)\s+")
#: Words between the object and what is asked of it: "to be placed", "go", "look better".
_LINKING = re.compile(r"^(?:(?:to\s+)?be(?:ing)?\s+|to\s+|go\s+|stand\s+|sit\s+|end up\s+|look\s+\w+\s+|looks\s+\w+\s+)+")
_PARTICIPLES = {"put": "put", "set": "set", "made": "make", "laid": "lay", "hung": "hang", "brought": "bring",
                "stuck": "stick", "spun": "spin", "got rid of": "get rid of", "taken away": "take away"}  # fmt: skip


def _verb(word: str, *, base: bool) -> str | None:
    """The verb of the planner's vocabulary that ``word`` is a form of ("placed", "facing",
    "swapped"); its bare form counts only where ``base`` says a verb must come ("to face")."""
    verbs = {*_MOVE, *_PLACE, *_TURN, *_REPLACE, *(v for v in _DELETE if " " not in v)}
    if word in _PARTICIPLES:
        return _PARTICIPLES[word]
    if base and word in verbs:
        return word
    for suffix in ("ed", "ing", "d"):
        if word.endswith(suffix):
            stem = word[: -len(suffix)]
            for candidate in (stem, stem + "e", stem[:-1]):
                if candidate in verbs:
                    return candidate
    return None


def _predicate(subject: str, predicate: str) -> str | None:
    """``subject`` and what is asked of it, as an imperative the planner reads; None when the
    predicate asks for nothing it knows (a verb form, a placement, a direction or a look)."""
    linked = _LINKING.match(predicate)
    rest = predicate[linked.end():] if linked else predicate
    first, _, after = rest.partition(" ")
    verb = _verb(first, base=linked is not None and linked.group(0).strip().endswith(("to", "be")))
    if verb is None and rest.startswith(tuple(p + " " for p in _PARTICIPLES if " " in p)):
        first = next(p for p in _PARTICIPLES if " " in p and rest.startswith(p + " "))
        verb, after = _PARTICIPLES[first], rest[len(first):].strip()
    if verb == "face":
        return f"turn {subject} to face {after}"
    if verb is not None:
        return f"{verb} {subject} {after}".strip()
    phrases = _find_phrases(rest)
    if phrases:
        return f"put {subject} {rest[phrases[0].start:]}"
    if _DIRECTION.search(rest):
        return f"move {subject} {rest}"
    if linked is not None and re.match(r"(?:to\s+)?be\s", linked.group(0)):  # "the sofa should be blue"
        return f"make {subject} {rest}"
    return None


def _imperative(text: str) -> str | None:
    """A wish ("I'd like the lamp placed beside the sofa") or a statement ("the chair should
    face the desk") as the imperative it amounts to ("put the lamp beside the sofa",
    "turn the chair to face the desk"); None when the text is neither."""
    wish = _WISH.match(text)
    if wish:
        rest = text[wish.end():]
        tokens = rest.split(" ")
        phrase_starts = {p.start for p in _find_phrases(rest)}
        offset = len(tokens[0]) + 1
        for token in tokens[1:]:  # the object ends where what is asked of it begins
            if token in ("to", "be", "being") or _verb(token, base=False) or offset in phrase_starts:
                return _predicate(rest[:offset].strip(), rest[offset:])
            offset += len(token) + 1
        return f"put {rest}"  # "I'd like two lamps": nothing asked of it but to be there
    for modal in _MODAL.finditer(text):  # "the trash can should ...": the modal is the last of a run
        if not _MODAL.match(text, modal.end()):
            return _predicate(text[:modal.start()].strip(), text[modal.end():])
    return None


def _split_face(rest: str) -> tuple[str, str]:
    found = _split_target(rest, ("towards", "toward", "to"))
    if found is None:
        raise InputError(f"face towards what? e.g. 'face the chair towards the table' (got {rest!r})")
    return found


def _plan_add(scene: Scene, rest: str) -> EditPlan:
    _count_check(rest)
    phrases = _find_phrases(rest)
    noun = _first_clause(rest[: phrases[0].start] if phrases else rest).strip()
    room = _ROOM_PHRASE.search(rest)
    if room is not None and (not phrases or room.start() <= phrases[0].start):
        noun = _first_clause(rest[: room.start()]).strip()
    new = _new_object(scene, noun)
    focus_id = fresh_id(scene, new.category or "object")
    placement = rest[min([p.start for p in phrases] + ([room.start()] if room else [])):] if phrases or room else ""
    placement, walls = _without_room_phrase(scene, focus_id, new.category, placement)
    constraints = walls + (_constraints(scene, None, focus_id, placement) if _find_phrases(placement) else [])
    return EditPlan(operation="add", focus=focus_id, new_object=new, constraints=constraints)


#: "to the left", "back", "forwards": a move relative to where the object stands (scene frame).
_DIRECTION = re.compile(
    r"\b(?:(?:more |further |farther )?(?:to|towards?) the )?(left|right|front|back|rear)(?:(?: hand)? side)?\b(?! of\b)"
    r"|\b(forwards?|backwards?|ahead|leftwards?|rightwards?)\b"
)
_HEADINGS = {
    **dict.fromkeys(("left", "leftward", "leftwards"), (-1.0, 0.0)),
    **dict.fromkeys(("right", "rightward", "rightwards"), (1.0, 0.0)),
    **dict.fromkeys(("front", "forward", "forwards", "ahead"), (0.0, -1.0)),
    **dict.fromkeys(("back", "backward", "backwards", "rear"), (0.0, 1.0)),
}
_DISTANCE = re.compile(
    r"(?:\bby )?(?:about |around |roughly |another )?\b(\d+(?:\.\d+)?|an?|one|two|three|half an?) ?"
    r"(cm|centimet(?:re|er)s?|mm|millimet(?:re|er)s?|m|met(?:re|er)s?|ft|foot|feet)\b"
)
_NUMBERS = {"a": 1.0, "an": 1.0, "one": 1.0, "two": 2.0, "three": 3.0, "half a": 0.5, "half an": 0.5}
_UNITS = {"c": 0.01, "m": 1.0, "f": 0.3048}
#: How far a move with no stated distance goes, in metres: a plain step, and "a bit".
STEP, SMALL_STEP = 0.5, 0.2
_SOFT = re.compile(r"\b(?:a bit|a little|a little bit|slightly|a touch|a tad)\b")
#: Verbs that themselves mean a small step.
_SOFT_VERBS = ("nudge", "scoot", "budge")


def _metres(match: re.Match[str]) -> float:
    number, unit = match.group(1), match.group(2)
    value = _NUMBERS[number] if number in _NUMBERS else float(number)
    if unit.startswith(("mm", "millim")):
        return value / 1000.0
    return value * _UNITS[unit[0]]


def _relative_move(rest: str, *, small: bool) -> tuple[str, Vec3] | None:
    """The object phrase and the shift of "the sofa 1 m to the left", "the table back a bit";
    None when ``rest`` names no direction. The heading is the direction word that only a step
    follows, since side words also pick objects ("the left chair to the right", "the left chair")."""
    distance = _DISTANCE.search(rest)
    def blank(m: re.Match[str]) -> str:  # same length, so positions in ``rest`` still hold
        return " " * len(m.group(0))

    unsaid = _SOFT.sub(blank, _DISTANCE.sub(blank, rest))  # what is not the step
    headings = [d for d in _DIRECTION.finditer(rest) if not unsaid[d.end():].strip()]
    if not headings:
        return None
    heading = headings[-1]
    dx, dy = _HEADINGS[heading.group(1) or heading.group(2)]
    if distance is not None:
        length = _metres(distance)
    else:
        length = SMALL_STEP if small or _SOFT.search(rest) else STEP
    cut = min(heading.start(), distance.start() if distance else len(rest))
    return rest[:cut], Vec3(x=dx * length, y=dy * length, z=0.0)


_TURN_AROUND = re.compile(r"\b(?:around|round|about)\b|\b(?:by\s+)?(-?\d+(?:\.\d+)?)\s*(?:degrees?|deg|°)")


def _plan_move(scene: Scene, rest: str, *, turning: bool = False, small: bool = False) -> EditPlan:
    room = None if turning else _ROOM_PHRASE.search(rest)
    if room is not None:  # "move the bed against the left wall", "hang the clock on the back wall"
        reference = _FILLERS.sub(" ", rest[: room.start()])
        reference = re.sub(r"\b(?:so it|so that it|to|over|back|away|up|down)\s*$", "", reference.strip())
        focus = resolve(scene, reference, role="object to move")
        remainder, walls = _without_room_phrase(scene, focus.id, focus.category, rest[room.start():])
        return EditPlan(operation="move", focus=focus.id,
                        constraints=walls + (_constraints(scene, focus, focus.id, remainder) if _find_phrases(remainder) else []))
    turn = _TURN_AROUND.search(rest) if turning else None
    if turn is not None:  # "by 90 degrees" is a turn, not a place ("by" also means "near")
        rest = f"{rest[:turn.start()]} {rest[turn.end():]}".strip()
    distance = None if turning else _DISTANCE.search(rest)
    phrases = _find_phrases(rest if distance is None else rest[:distance.start()] + rest[distance.end():])
    shift = None if turning or phrases else _relative_move(rest, small=small)
    if shift is not None:
        reference = _FILLERS.sub(" ", _CLAUSE.split(shift[0], maxsplit=1)[0])
        focus = resolve(scene, reference, role="object to move")
        return EditPlan(operation="move", focus=focus.id, offset=shift[1])
    if distance is not None:  # "1 m to the right of the sofa": the relation places it
        rest = rest[:distance.start()] + rest[distance.end():]
    reference = rest[: phrases[0].start] if phrases else rest
    reference = _FILLERS.sub(" ", _CLAUSE.split(reference, maxsplit=1)[0])
    reference = re.sub(r"\b(?:so it|so that it|to|over|back|away|up|down|clockwise|counterclockwise|"
                       r"anticlockwise|left|right)\s*$", "", reference.strip())
    focus = resolve(scene, reference, role="object to move")
    constraints = _constraints(scene, focus, focus.id, rest[phrases[0].start:]) if phrases else []
    yaw = None
    if turn is not None and not any(c.relation == "face to" for c in constraints):
        degrees = float(turn.group(1)) if turn.group(1) else 180.0
        if "counterclockwise" in rest or "anticlockwise" in rest or "left" in rest.split():
            degrees = abs(degrees)
        elif "clockwise" in rest or "right" in rest.split():
            degrees = -abs(degrees)
        yaw = (focus.yaw + degrees + 180.0) % 360.0 - 180.0
    if not constraints and yaw is None:
        hint = "turn it to face what" if turning else "where to"
        raise InputError(
            f"{hint}? say where {focus.id} goes relative to another object, e.g. "
            f"'move {focus.name} next to the {next((o.name for o in scene.objects if o.id != focus.id), 'table')}'"
            + ("" if turning else ", or which way to shift it, e.g. 'a bit to the left', '1 m back'")
        )
    return EditPlan(operation="move", focus=focus.id, constraints=constraints, yaw=yaw)


def _plan_replace(scene: Scene, verb: str, rest: str) -> EditPlan:
    """replace X with Y, swap X for Y, substitute Y for X, change/turn X into Y, make/paint X Y."""
    if verb == "substitute":
        parts = _split_target(rest, ("for",))
        if parts is None:
            raise InputError("substitute what for what? e.g. 'substitute a lantern for the lamp'")
        new_text, old_text = parts
    else:
        parts = _split_target(rest, ("with", "for", "by", "into", "to be", "to look like", "to", "as"))
        if parts is not None:
            old_text, new_text = parts
            old_text = re.sub(r"^(?:the )?(?:colou?r|style|look|material|finish) of ", "", old_text)
            old_text = re.sub(r"\s(?:colou?r|style|look|material|finish)$", "", old_text)
        else:  # "make the sofa red", "paint the fence white": the object then its new look
            old_text, new_text = _split_look(scene, rest)
    focus = resolve(scene, _CLAUSE.split(old_text, maxsplit=1)[0], role="object to change")
    return EditPlan(operation="replace", focus=focus.id, new_object=_new_object(scene, new_text, base=focus))


def _split_look(scene: Scene, rest: str) -> tuple[str, str]:
    """Split "the big sofa bright red" into the reference and the new look: the shortest
    prefix that names exactly one object, grown by the words that still name it."""
    tokens = rest.split()
    first_error: InputError | None = None
    for end in range(1, len(tokens)):
        prefix = " ".join(tokens[:end])
        try:
            obj = resolve(scene, prefix)
        except InputError as exc:
            if first_error is None and _category_of(words(prefix))[0] is not None:
                first_error = exc
            continue
        own = _tokens(obj)
        while end < len(tokens) - 1 and singular(tokens[end]) in own:
            end += 1
        return " ".join(tokens[:end]), " ".join(tokens[end:])
    raise first_error or InputError(
        f"change {rest!r} how? e.g. 'make the sofa red', 'replace the lamp with a lantern'; "
        f"the scene has: {_describe(scene.objects)}"
    )
