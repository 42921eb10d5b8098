"""How a person rests: standing, kneeling, sitting or lying, from what the text says of them
(and a long flat thing leant against something: on its end).

The reader records no posture, so it is read here from two things the parse does hold: the
host a person is put ``on`` (a seat or a cushion → sitting; a bed, a rug, a blanket → lying)
and the verbs of the clause that names them ("sits", "dozes", "is asleep", "lies"). A
posed person keeps the standing size the catalogue gave their kind, folded to the pose's box
(:func:`posed_size`), and the pose word joins their description, where the figure generator
reads it (``procedural/shapes/creatures.py``), so the mesh and its box agree.
"""

from __future__ import annotations

import re
from dataclasses import replace

from scenewright.analysis.composition import roles
from scenewright.analysis.parser import ParsedObject, ParsedScene
from scenewright.analysis.parser.vocabulary import load_vocabulary
from scenewright.core.catalogue import load_catalogue
from scenewright.core.vessels import boat_text, is_open

#: Kneeling first: one who kneels on a cushion or a mat kneels there (the reader counts the
#: verbs of kneeling among those of sitting, for what carries them).
POSTURES = ("kneeling", "sitting", "lying")
#: Words of a description that pose its figure (``postures`` in ``data/vocabulary.json``, which
#: the reader shares); the first of each list is the one written.
POSTURE_WORDS: dict[str, tuple[str, ...]] = {p: load_vocabulary().postures[p] for p in POSTURES}
#: Hosts a person lies on, and hosts a person sits on besides the seats of :mod:`.roles`.
LYING_HOSTS = frozenset({"bed", "crib", "rug", "picnic_blanket", "hammock", "pet_bed", "bath_mat", "mat", "sun_lounger"})
#: Lying hosts that are a floor to sit or stand on as well: on them the verb decides ("three
#: musicians sit on a carpet", "a picnic on a blanket"), and with no verb of posture one lies.
FLOOR_COVERS = frozenset({"rug", "picnic_blanket", "bath_mat", "mat"})
SITTING_HOSTS = roles.SEATS | frozenset({"cushion", "swing", "log", "rock", "stairs", "bean_bag", "pouf", "kotatsu"})
#: Shares of the standing height a sitting person's box takes in depth and height (knees up,
#: seat at the box's bottom), as the figure generator folds a standing person.
SIT_DEPTH = 0.52
SIT_HEIGHT = 0.56
#: The same for kneeling upright, the shins back along the floor.
KNEEL_DEPTH = 0.31
KNEEL_HEIGHT = 0.78
_FIGURES = frozenset({"figure"})
#: What a person who sits with no seat named sits on, written into their description, and its
#: height (m): "two sailors sit at the sonar console" sit at it, not on the floor before it.
OWN_SEAT = "sitting on a stool"
STOOL_HEIGHT = 0.45
#: Verbs of sitting on a seat, and words that put the one who sits on the ground or on their knees.
_SEATED = ("sit", "sits", "sitting", "seated", "sat")
_GROUNDED = ("floor", "ground", "grass", "lawn", "sand", "beach", "rug", "mat", "carpet", "step", "steps", "lap", "knees",
             "cross-legged", "kneel", "kneels", "kneeling", "squat", "squats", "squatting", "crouches", "heels", "snow")


def _mentions(text: str, words) -> bool:
    return any(re.search(rf"\b{re.escape(w)}\b", text) for w in words)


def posture_in(text: str) -> str | None:
    """The posture a description's words give, or ``None`` (standing)."""
    text = text.lower()
    for posture in POSTURES:
        if _mentions(text, POSTURE_WORDS[posture]):
            return posture
    return None


#: Where one clause of a sentence gives way to another with a subject of its own ("a customer
#: waits at the counter, while a till sits on it": the till sits, not the customer).
_CLAUSE_BREAK = re.compile(r"[.!?;]\s+|,?\s+\b(?:while|whilst|whereas|but)\b|,\s+(?:and|as)\b")
#: A clause opening with a place puts its verb before its subject ("on the bench sits an old man").
_PLACE_FIRST = re.compile(r"^\s*(?:on|in|at|by|beside|behind|under|near|inside|outside|against|next|across|between)\b")


def _clause_of(parsed: ParsedScene, obj: ParsedObject) -> str:
    """What the first clause naming the object (its name's last word) says of it: the words from
    its name on, or the whole clause when that opens with a place and so puts the verb first.
    A verb before the name is another's ("a dog sleeps at the feet of an old man")."""
    head = obj.name.lower().split()[-1] if obj.name.strip() else obj.category
    for clause in _CLAUSE_BREAK.split(parsed.text.lower()):
        found = re.search(rf"\b{re.escape(head)}s?\b", clause)
        if found:
            return clause if _PLACE_FIRST.match(clause) else clause[found.start() :]
    return ""


def _hosts(parsed: ParsedScene, obj: ParsedObject) -> list[ParsedObject]:
    """What the parse puts ``obj`` on."""
    by_id = {o.id: o for o in parsed.objects}
    return [by_id[r.target] for r in parsed.relations
            if r.source == obj.id and r.relation == "on" and r.target in by_id]  # fmt: skip


def posture_of(parsed: ParsedScene, obj: ParsedObject) -> str | None:
    """Kneeling, sitting, lying or ``None`` for a person of the parse; ``None`` for anything else.

    Kneeling is said in so many words and holds on any host. Else the host decides first (a
    person on a bed lies, on a chair sits, whatever the verb), but on a rug or a blanket the
    verb does ("sit on a carpet", "stands on the rug"); with no host, or a host of neither
    kind, the sentence's verbs do ("a boy sits at the kotatsu"); "asleep"/"sleeps"
    alone is lying unless the host is a seat ("dozes in the armchair" sits). On a vehicle or a
    ridden animal a person sits unless the sentence has them stand ("standing on its bonnet").
    """
    if obj.category not in _FIGURES or set(obj.name.lower().split()) & load_vocabulary().replica_words:
        return None  # (a toy knight stands as it was made, on the rug or anywhere)
    clause = _clause_of(parsed, obj)
    if "kneeling" in (posture_in(clause), posture_in(obj.description)):
        return "kneeling"  # on whatever carries them ("kneels on a tatami mat")
    hosts = [o.category for o in _hosts(parsed, obj)]
    if hosts and all(h in FLOOR_COVERS for h in hosts):
        if _mentions(clause, load_vocabulary().postures["standing"]):
            return None
        said = posture_in(clause)
        if said is not None:
            return said
    if any(h in LYING_HOSTS for h in hosts):
        return "lying"
    if any(h in SITTING_HOSTS for h in hosts):
        return "sitting"
    vocabulary = load_vocabulary()
    decked = [
        o for o in _hosts(parsed, obj)
        if load_catalogue()[o.category].shape == "boat" and not is_open(boat_text(o.name, o.category, o.description))
    ]  # fmt: skip
    if any(vocabulary.carries(h, h, ("vehicles", "mounts")) for h in hosts) and not decked:
        # riders sit ("a soldier on horseback", "children in the bus") unless they stand on it;
        # on a boat with a deck they stand ("fishermen unload crates from a trawler")
        return None if _mentions(clause, vocabulary.postures["standing"]) else posture_in(clause) or "sitting"
    # one who rides past on nothing the text names stands ("a cyclist rides past the newsstand")
    found = posture_in(clause if hosts else re.sub(r"\brid(?:es|ing)\b", "", clause))
    if found:
        return found
    if _mentions(clause, ("asleep", "sleeps", "sleeping", "naps", "napping")):
        return "lying"
    return None


def seat_implied(parsed: ParsedScene, obj: ParsedObject) -> bool:
    """Whether a sitting person sits on a seat the text does not name: nothing carries them and
    their clause has them sit, not on the ground or on their knees ("sits at the desk")."""
    if any(r.source == obj.id and r.relation == "on" for r in parsed.relations):
        return False
    clause = _clause_of(parsed, obj)
    return _mentions(clause, _SEATED) and not _mentions(clause, _GROUNDED)


def posed_size(size: tuple[float, float, float], posture: str | None, stool: bool = False) -> tuple[float, float, float]:
    """The box of a person of standing ``size`` in ``posture`` (on a stool of their own)."""
    w, d, h = size
    if posture == "sitting":
        return (w, round(SIT_DEPTH * h, 3), round(SIT_HEIGHT * h + (STOOL_HEIGHT if stool else 0.0), 3))
    if posture == "kneeling":
        return (w, round(KNEEL_DEPTH * h, 3), round(KNEEL_HEIGHT * h, 3))
    if posture == "lying":  # on the back along the depth, head to the back
        return (w, h, d)
    return size


#: Words that stand a long flat thing on its end against something ("skis lean against the wall").
_LEANING = ("lean", "leans", "leaning", "propped")
#: m, the most a thing lying flat rises; and its least length to stand on end when it leans.
_FLAT_RISE, _LEANING_LENGTH = 0.25, 1.0


def stood_on_end(parsed: ParsedScene, obj: ParsedObject) -> tuple[float, float, float] | None:
    """The upright box of a long thing the catalogue sizes lying flat (skis, a mattress) when its
    clause leans or props it against something, its long side up; ``None`` for anything else.
    Only a plainly drawn thing: a generator that draws a sword or an oar draws it lying."""
    w, d, h = obj.size
    long = max(w, d)
    if load_catalogue()[obj.category].shape != "generic" or h > _FLAT_RISE or long < max(_LEANING_LENGTH, 4 * h):
        return None
    if not _mentions(_clause_of(parsed, obj), _LEANING):
        return None
    return (w, h, d) if d >= w else (d, h, w)


def pose(parsed: ParsedScene) -> list[ParsedObject]:
    """The parse's objects with every person put in the posture the text gives them: the
    pose's box, and the pose word added to the description when it does not say it (with the
    stool they sit on when the text names no seat); a long flat thing leant against something
    stands on its end."""
    posed = []
    for obj in parsed.objects:
        upright = stood_on_end(parsed, obj)
        if upright is not None:
            posed.append(replace(obj, size=upright))
            continue
        posture = posture_of(parsed, obj)
        if posture is None:
            posed.append(obj)
            continue
        stool = posture == "sitting" and seat_implied(parsed, obj)
        said = f"{obj.description}, {OWN_SEAT}" if stool else f"{obj.description}, {posture}"
        description = obj.description if posture_in(obj.description) == posture and not stool else said
        posed.append(replace(obj, size=posed_size(obj.size, posture, stool), description=description))
    return posed
