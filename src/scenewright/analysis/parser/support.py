"""Default supports: surface things nobody put anywhere go on the best support present, hanging
things above the nearest large object. Marked ``inferred``.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import replace

from scenewright.analysis.parser.grammar import _PLATFORM_AREA
from scenewright.analysis.parser.model import ParsedObject, ParsedRelation
from scenewright.analysis.parser.vocabulary import load_vocabulary
from scenewright.analysis.parser.words import _PLANT_SHAPES


_SUPPORT_PREFERENCE = {
    "table_lamp": ("nightstand", "desk", "side_table", "dresser", "vanity", "table", "coffee_table", "cabinet"),
    "alarm_clock": ("nightstand", "dresser", "desk", "side_table"),
    "tv": ("tv_stand", "cabinet", "dresser", "counter", "desk", "table"),
    "monitor": ("desk", "school_desk", "table", "counter", "control_panel", "lab_bench"),
    "laptop": ("desk", "school_desk", "table", "coffee_table", "counter", "round_table"),
    "keyboard": ("desk", "school_desk", "table"),
    "printer": ("desk", "cabinet", "filing_cabinet", "table"),
    "microwave": ("counter", "cabinet", "table"),
    "coffee_machine": ("counter", "side_table", "table", "cabinet"),
    "toaster": ("counter", "table"),
    "cash_register": ("counter", "display_case", "table"),
    "flask": ("lab_bench", "table", "desk", "counter"),
    "microscope": ("lab_bench", "desk", "table"),
    "projector": ("table", "desk", "side_table"),
    "radio": ("cabinet", "side_table", "dresser", "desk", "table"),
    "aquarium": ("cabinet", "dresser", "side_table", "counter", "table"),
    "magic_orb": ("pedestal", "altar", "table", "round_table", "desk"),
    "candle": ("altar", "table", "round_table", "dining_table", "side_table", "nightstand", "fireplace"),
    "vase": ("table", "side_table", "coffee_table", "round_table", "pedestal", "dresser", "nightstand"),
    "pot": ("stove", "grill", "fireplace", "counter", "table"),
    "books": ("desk", "side_table", "coffee_table", "nightstand", "table"),
}
#: Hosts anything small may be put on when the text says nothing; other hosts (an altar, a
#: pedestal, a fireplace, a stove, a pier) only take what names them in its preferences.
_GENERAL_HOSTS = frozenset({
    "table", "round_table", "side_table", "coffee_table", "desk", "school_desk", "counter", "nightstand",
    "dresser", "cabinet", "tv_stand", "lab_bench", "display_case", "picnic_table", "vanity", "filing_cabinet",
    "control_panel", "dining_table",
})  # fmt: skip


#: What fish swim in when the text puts them nowhere.
_FISH_WATERS = ("pond", "aquarium", "fountain")


def usual_host(host: str, thing: str) -> bool:
    """Whether a thing of category ``thing`` is usually set on a ``host``: a general host, or one
    its preferences name (a candle on a fireplace; an inkwell on a desk, not on a fireplace)."""
    return host in _GENERAL_HOSTS or host in _SUPPORT_PREFERENCE.get(thing, ())


def _infer_support(objects: list[ParsedObject], relations: list[ParsedRelation], catalogue) -> list[ParsedRelation]:
    """Surface things with no stated support go on the best support present; hanging things
    with no stated target or wall hang above the nearest-mentioned large object."""
    placed_vertically = {r.source for r in relations if r.relation in ("on", "above")}
    load: Counter[str] = Counter(r.target for r in relations if r.relation == "on")
    extra: list[ParsedRelation] = []
    supports = [o for o in objects if catalogue[o.category].support]
    by_id = {o.id: o for o in objects}
    beside = _beside(objects, relations, catalogue)
    partners: dict[str, set[str]] = {}  # beside a thing, never inferred onto it: both cannot hold
    for r in relations:
        if r.relation in _SIDES:
            partners.setdefault(r.source, set()).add(r.target)
    # a thing a person or an animal sits or lies on stays on the floor (a cushion, a basket)
    ridden = {r.target for r in relations
              if r.relation == "on" and catalogue[by_id[r.source].category].shape in LIVING_SHAPES}
    # the members of a stack above its first rest on the one below (the composition says so)
    first_of: dict[int, str] = {}
    for o in objects:
        first_of.setdefault(o.group, o.id)
    stacked = {o.id for o in objects if o.formation == "stack" and first_of[o.group] != o.id}
    waters = [o for o in objects if o.category in _FISH_WATERS]
    for obj in objects:
        rests = obj.rests or catalogue[obj.category].rests
        if obj.id in placed_vertically or obj.id in stacked:
            continue
        if obj.category == "fish" and waters:
            # "an old man feeds the koi": in the pond (the nearest mention), never on the grass
            water = min(waters, key=lambda o: (abs(o.group - obj.group), o.group > obj.group))
            extra.append(ParsedRelation(obj.id, "on", water.id, inferred=True))
            continue
        if rests == "surface" and obj.id not in ridden:
            # "a rocking horse and a gramophone stand in the middle of the floor": where the text
            # puts it, not on a cabinet by the wall
            anchored = [o for o in supports if o.anchor == obj.anchor] if obj.anchor else supports
            prefs = _SUPPORT_PREFERENCE.get(obj.category, ())
            fitting = [
                s for s in anchored
                if s.id != obj.id and s.id not in partners.get(obj.id, ())
                and s.size[0] >= obj.size[0] * 0.9 and s.size[1] >= obj.size[1] * 0.9
                and usual_host(s.category, obj.category)
            ]  # fmt: skip
            if obj.id in beside:
                host = beside[obj.id]  # the partner's host, or the ground by it
                if host is not None and can_hold(by_id[host], obj, catalogue):
                    load[host] += 1
                    extra.append(ParsedRelation(obj.id, "on", host, inferred=True))
                continue
            if not fitting:
                continue

            def score(s: ParsedObject, prefs=prefs, obj=obj) -> tuple:
                rank = prefs.index(s.category) if s.category in prefs else len(prefs)
                return (rank, load[s.id], abs(s.group - obj.group))

            best = min(fitting, key=score)
            load[best.id] += 1
            extra.append(ParsedRelation(obj.id, "on", best.id, inferred=True))
        elif rests == "hanging" and obj.anchor is None:  # ("clocks cover the walls": on the walls, above nothing)
            hosts = [
                o for o in objects
                if o.id != obj.id and (o.rests or catalogue[o.category].rests) == "ground" and 0.3 < o.size[2] < 2.5
                and o.anchor != "centre"  # a picture hangs on a wall, over nothing in the middle of the room
                and catalogue[o.category].shape not in LIVING_SHAPES  # (over furniture, not over someone's head)
            ]  # fmt: skip
            if hosts:
                # the nearest mention, the one before on a tie ("a dresser with a mirror")
                best = min(hosts, key=lambda o: (abs(o.group - obj.group), o.group > obj.group, -o.size[0] * o.size[1]))
                extra.append(ParsedRelation(obj.id, "above", best.id, inferred=True))
    return extra + _on_shared_floor(objects, relations, catalogue)


#: m², the most ground a thing may cover to share a floor with what it stands by (a person, a
#: lamb, a microphone stand; not a cart or a tree).
_SHARED_FOOTPRINT = 1.0


def _on_shared_floor(objects: list[ParsedObject], relations: list[ParsedRelation], catalogue) -> list[ParsedRelation]:
    """What the text sets by, before or behind a thing standing on a stage, a pier or a raft
    stands on that floor too ("On the stage, a manger ...; three lambs kneel around the manger,
    and a donkey stands behind it": on the stage): people, animals and things a person's size,
    no vehicle, nothing put anywhere else, nothing also set by a thing on another floor or on
    the ground. A chain of them shares it ("a singer at a microphone in front of the band")."""
    by_id = {o.id: o for o in objects}
    vocabulary = load_vocabulary()
    placed = {r.source for r in relations if r.relation in ("on", "above")}
    floor_of = {r.source: r.target for r in relations if r.relation == "on"}
    partners: dict[str, set[str]] = {}  # what the text sets each thing by (it, not they, is placed)
    for r in relations:
        if r.relation in _HORIZONTAL and not r.inferred:
            partners.setdefault(r.source, set()).add(r.target)

    def shares(thing: ParsedObject, floor: ParsedObject) -> bool:
        if (thing.rests or catalogue[thing.category].rests) != "ground" or thing.anchor is not None:
            return False
        small = catalogue[thing.category].shape in LIVING_SHAPES or thing.size[0] * thing.size[1] <= _SHARED_FOOTPRINT
        wide = floor.size[0] * floor.size[1] >= _PLATFORM_AREA * thing.size[0] * thing.size[1]
        wide = wide and min(floor.size[:2]) >= _FLOOR_SIDE  # (a log or a barrel is no floor to stand by things on)
        deck = vocabulary.carries(floor.category, floor.name, ("perches",)) and floor.size[2] <= _PLATFORM_TOP
        vehicle = vocabulary.carries(thing.category, thing.name, ("vehicles",))
        return small and wide and deck and not vehicle and can_hold(floor, thing, catalogue)

    out: dict[str, str] = {}
    changed = True
    while changed:  # ("a singer at a microphone in front of the band": the microphone first, then the singer)
        changed = False
        for thing, by in partners.items():
            # one floor under all it stands by ("between the piano on the stage and the stall": on neither)
            floors = {floor_of.get(p) or out.get(p) for p in by}
            floor = floors.pop() if len(floors) == 1 else None
            if thing in placed or thing in out or floor is None or floor == thing:
                continue
            if shares(by_id[thing], by_id[floor]):
                out[thing] = floor
                changed = True
    return [ParsedRelation(thing, "on", floor, inferred=True) for thing, floor in out.items()]


#: Relations that put one thing on a side of another: it cannot be on it as well.
_SIDES = ("side of", "left of", "right of", "in front of", "behind")
_HORIZONTAL = ("near", *_SIDES)


def _beside(objects: list[ParsedObject], relations: list[ParsedRelation], catalogue) -> dict[str, str | None]:
    """Surface things the text sets beside (or in front of, behind) another, with where they
    stand by it: on the piece of furniture that other thing rests on ("a cat on the counter next
    to a microscope": the microscope is on the counter too; a cup by a man on a chair is not on
    the chair), or on the ground (``None``) by one that stands there ("a cart waits next to a
    lantern", "a basket at the foot of the stove"). A thing
    the catalogue gives hosts of its own (a lamp, a TV) beside a piece of furniture or a seat is
    left to those ("a lamp beside the bed" is on the nightstand). Never on the thing it is beside:
    beside it and on it cannot both hold."""
    by_id = {o.id: o for o in objects}
    host = {r.source: r.target for r in relations if r.relation == "on"}
    raised = {r.source for r in relations if r.relation == "above"}

    def rests(o: ParsedObject) -> str:
        return o.rests or catalogue[o.category].rests

    def furniture(o: ParsedObject) -> bool:
        category = catalogue[o.category]
        return category.support or category.shape in _SEAT_SHAPES

    pairs = [(by_id[r.source], by_id[r.target]) for r in relations if r.relation in _HORIZONTAL and not r.inferred]
    pairs += [(b, a) for a, b in pairs]
    out: dict[str, str | None] = {}
    grounded = {o.id for o in objects if rests(o) == "ground" and o.id not in host and o.id not in raised}
    # ("two hackers hunch over laptops at the counter": by the counter, so on it, whoever stands by them)
    furnished = {thing.id for thing, partner in pairs if thing.category in _SUPPORT_PREFERENCE and furniture(partner)}
    changed = True
    while changed:  # a thing set on the ground by one may ground the next ("a basket at its foot")
        changed = False
        for thing, partner in pairs:
            if thing.id in out or thing.id in host or thing.id in raised or rests(thing) != "surface":
                continue
            if partner.id in host:
                shared = by_id[host[partner.id]]  # furniture things are put on, not a seat or a dais
                if shared.id == thing.id or not (catalogue[shared.category].support
                                                 or shared.category in _SUPPORT_PREFERENCE.get(thing.category, ())):
                    continue
                out[thing.id] = shared.id
            elif partner.id in grounded and thing.id not in furnished:
                out[thing.id] = None
                grounded.add(thing.id)
            else:
                continue
            changed = True
    return out


_SEAT_SHAPES = ("chair", "armchair", "sofa", "bench", "stool", "office_chair", "bed")

#: Hosts with no top to put things on: people and birds (a horse or a camel can carry a load).
_NO_TOP = {"figure", "bird", "mannequin", "scarecrow"}
#: Floor coverings: a building or a vehicle stated on one is a toy (``fit_on_hosts``), this share of its width.
_COVERINGS = {"rug", "yoga_mat", "picnic_blanket"}
_BUILT_SHAPES = {"house", "building", "tower", "arch", "car", "truck", "bus", "boat", "tank", "vehicle"}
_TOY_SHARE = 0.6
#: The category of a thing nobody listed: its size is a guess, not knowledge.
_UNKNOWN = "thing"
#: A host this low is ground-like (a rug, a pond, a pallet, a blanket): anything may stand on it.
FLAT_HOST = 0.3
#: m, the least width of a floor a thing shares with what it stands by (a stage, a raft; no log).
_FLOOR_SIDE = 1.0
#: m, the highest top of a thing one stands on that is a floor to furniture (a stage, a pier).
_PLATFORM_TOP = 1.5
#: How much larger than its host a thing may be and still rest on it (footprint, longest side):
#: a statue overhangs its plinth, a bird its bollard.
_AREA_SLACK, _SIDE_SLACK = 2.0, 1.6
#: People and animals sit, stand and perch on things smaller than themselves (a man on a stool,
#: a lynx on a mound, a dog on a low stool, a tourist on a suitcase): any host a stool's size or wider.
_PERCH_SIDE = 0.3
LIVING_SHAPES = ("figure", "animal", "bird")
#: Furniture that stands on the floor, never on another piece ("a sofa on the desk" is beside it).
_FLOOR_FURNITURE = {"sofa", "armchair", "bed", "wardrobe", "bookshelf", "office_chair", "piano", "fridge",
                    "stove", "counter", "desk", "table", "round_table", "coffee_table", "bathtub", "treadmill",
                    "dresser", "tv_stand", "school_desk", "dining_table", "pool_table", "ping_pong_table"}  # fmt: skip


#: A floor-standing thing the text puts on a table-like host is its tabletop kind: at most this
#: share of the host's height ("two speakers on the desk" are desk speakers, not floor ones).
_ON_TOP_HEIGHT = 0.6
#: The longest side (m) of a thing nobody listed that the text puts on a table, a desk or a counter,
#: or in someone's hand.
_TABLETOP_SIDE = 0.35
#: Hosts no taller than this are furniture one puts things on (a desk, a counter, a sideboard).
_FURNITURE_HEIGHT = 1.3


def standing_lamps(
    objects: list[ParsedObject], relations: list[ParsedRelation], catalogue, fixed: set[str]
) -> list[ParsedObject]:
    """A lamp the text sets beside a seat, on nothing, where no table of its own stands ("a
    reading lamp beside a leather armchair in the corner"): a floor lamp, not a table lamp
    taken to the nearest counter."""
    by_id = {o.id: o for o in objects}
    hosts = set(_SUPPORT_PREFERENCE["table_lamp"][:4])  # a nightstand, a desk, a side table, a dresser
    if any(o.category in hosts for o in objects):
        return objects
    placed = {r.source for r in relations if r.relation in ("on", "above")}
    by_seat = {
        r.source for r in relations
        if r.relation in _SIDES + ("near",) and catalogue[by_id[r.target].category].shape in _SEAT_SHAPES
    }  # fmt: skip
    floor = catalogue["floor_lamp"]
    return [
        replace(o, category="floor_lamp", size=floor.size, rests=floor.rests)
        if o.category == "table_lamp" and o.id in by_seat and o.id not in placed and o.id not in fixed else o
        for o in objects
    ]


def fit_on_hosts(
    objects: list[ParsedObject], relations: list[ParsedRelation], catalogue, fixed: set[str]
) -> list[ParsedObject]:
    """Objects with every floor-standing thing stated ``on`` a general host scaled down to a
    tabletop size (its proportions kept), a lifeless thing as small as the host it is stated on
    needs ("two hoglets sit on pebble stools", "a statue on the bookshelf": the text knows better
    than the catalogue's size), and a host nobody listed as wide as a listed thing on it needs;
    sizes the text states (``fixed``) stay."""
    by_id = {o.id: o for o in objects}
    scale: dict[str, float] = {}
    widen: dict[int, float] = {}
    for r in relations:
        if r.relation != "on" or r.source in fixed:
            continue
        thing, host = by_id[r.source], by_id[r.target]
        if host.category == _UNKNOWN != thing.category and r.target not in fixed and not can_hold(host, thing, catalogue):
            # "a huge copper cauldron on an open fire": a host nobody listed is as wide as what is on it
            need = max(max(thing.size[:2]) / max(host.size[:2]), (thing.size[0] * thing.size[1] / (host.size[0] * host.size[1])) ** 0.5)
            widen[host.group] = max(widen.get(host.group, 1.0), need)
            continue
        if host.category in _COVERINGS and catalogue[thing.category].shape in _BUILT_SHAPES and (
            max(thing.size[:2]) > min(host.size[:2])
        ):  # "a wooden castle stands on a rug", "a fire engine on the rug": no castle fits on a rug, a toy one does
            scale[thing.id] = min(scale.get(thing.id, 1.0), _TOY_SHARE * min(host.size[:2]) / max(thing.size[:2]))
            continue
        # a thing nobody listed is as small as its host needs; so is a listed lifeless one the text
        # puts on a standing host ("a marble statue on the bookshelf", "a spaceship on the desk": a
        # statuette, a model), not a piece of floor furniture ("a sofa on the desk" is beside it)
        listed = catalogue[thing.category].shape not in LIVING_SHAPES and (
            (host.rests or catalogue[host.category].rests) != "hanging" and thing.category not in _FLOOR_FURNITURE
        )
        if (thing.category == _UNKNOWN or listed) and host.category not in _NO_TOP and not can_hold(host, thing, catalogue):
            side = max(host.size[:2]) / max(thing.size[:2])
            area = (host.size[0] * host.size[1] / (thing.size[0] * thing.size[1])) ** 0.5
            scale[thing.id] = min(scale.get(thing.id, 1.0), side, area)
            continue
        held = host.category == "figure"
        if thing.category == _UNKNOWN and (held or host.category in _GENERAL_HOSTS) and max(thing.size) > _TABLETOP_SIDE:
            # "a stack of files on each table", "pointing with a laser pointer": what nobody listed
            # that lies on a table or is held is a tabletop thing
            scale[thing.id] = min(scale.get(thing.id, 1.0), _TABLETOP_SIDE / max(thing.size))
            continue
        if (thing.rests or catalogue[thing.category].rests) != "ground" or host.category not in _GENERAL_HOSTS:
            continue
        if host.size[2] > _FURNITURE_HEIGHT or thing.category in _FLOOR_FURNITURE:
            continue
        if catalogue[thing.category].shape in LIVING_SHAPES:
            continue  # "a reporter sits on the edge of the desk": a person on a desk is no figurine
        limit = _ON_TOP_HEIGHT * host.size[2]
        if thing.size[2] > limit:
            scale[thing.id] = min(scale.get(thing.id, 1.0), limit / thing.size[2])
    # the members of one phrase share its size ("a stack of files": the ones stacked on the first too)
    group_scale: dict[int, float] = {}
    for oid, factor in scale.items():
        group_scale[by_id[oid].group] = min(group_scale.get(by_id[oid].group, 1.0), factor)
    out = [
        replace(o, size=tuple(round(v * group_scale[o.group], 4) for v in o.size))  # type: ignore[misc]
        if o.group in group_scale and o.id not in fixed else o
        for o in objects
    ]
    return [
        replace(o, size=(round(o.size[0] * widen[o.group], 4), round(o.size[1] * widen[o.group], 4), o.size[2]))
        if o.group in widen and o.id not in fixed else o
        for o in out
    ]


def can_hold(host: ParsedObject, thing: ParsedObject, catalogue) -> bool:
    """Whether ``thing`` can rest on ``host``: hosts that hang hold nothing but what fits in a
    hung container; a flat host holds anything; a person or an animal sits or stands on any
    host at least a stool's size; otherwise the thing must be about the host's size or smaller."""
    if catalogue[thing.category].shape == "bird" and thing.size[0] <= host.size[0]:
        return True  # "a robin perches on top of the clock on the wall", "a raven perches on the scarecrow"
    if host.category in _NO_TOP:
        return False  # what a knight holds is beside him, not on him
    if (host.rests or catalogue[host.category].rests) == "hanging":
        # a hung container holds what fits in it (a parrot in a birdcage); other hung things nothing
        inside = load_vocabulary().carries(host.category, host.name, ("containers",))
        return inside and thing.size[0] <= host.size[0] and thing.size[1] <= host.size[1]
    if host.size[2] <= FLAT_HOST:
        return True
    if catalogue[thing.category].shape in LIVING_SHAPES and max(host.size[:2]) >= _PERCH_SIDE:
        return True
    if host.category == "planter" and catalogue[thing.category].shape in _PLANT_SHAPES:
        return True  # a tree grows out of its planter, its crown far wider than the pot
    if thing.category in _FLOOR_FURNITURE and thing.rests != "surface":  # (a camping stove is the tabletop kind)
        # a stage or a pier is a floor to what stands on it ("a low round stage holds a grand piano")
        floor = load_vocabulary().carries(host.category, host.name, ("perches",)) and host.size[2] <= _PLATFORM_TOP
        return floor and thing.size[0] * thing.size[1] <= host.size[0] * host.size[1]
    area = thing.size[0] * thing.size[1] <= _AREA_SLACK * host.size[0] * host.size[1]
    side = max(thing.size[:2]) <= _SIDE_SLACK * max(host.size[:2])
    return area and side


def onto_stack_tops(objects: list[ParsedObject], relations: list[ParsedRelation]) -> list[ParsedRelation]:
    """``relations`` with each ``on`` a member of a stack ("a goat stands on a stack of hay bales",
    read onto the first bale) onto its top member: the others carry the ones above them (the
    composition puts each member on the one below), so only the top has room."""
    members: dict[int, list[str]] = {}
    for o in objects:
        if o.formation == "stack":
            members.setdefault(o.group, []).append(o.id)
    top = {i: ids[-1] for ids in members.values() if len(ids) > 1 for i in ids}
    return [replace(r, target=top[r.target]) if r.relation == "on" and r.target in top and r.source not in top else r
            for r in relations]


def repair_supports(
    objects: list[ParsedObject], relations: list[ParsedRelation], catalogue,
    carried: frozenset[tuple[str, str]] = frozenset(),
) -> tuple[list[ParsedRelation], list[str]]:
    """Each ``on`` whose host cannot hold the thing becomes ``side of`` (what the text most
    likely meant: "a dinosaur skeleton on a barrel" stands beside it), with a note of the repair.
    What the text puts on a part of a person (``carried``: "a laptop on her knees") or hangs from a
    post stays on it."""
    by_id = {o.id: o for o in objects}
    out: list[ParsedRelation] = []
    notes: list[str] = []
    for r in relations:
        held = (r.source, r.target) in carried
        if r.relation == "on" and not held and not can_hold(by_id[r.target], by_id[r.source], catalogue):
            notes.append(f"{r.source} on {r.target}: {r.target} cannot hold it; placed beside it instead")
            r = ParsedRelation(r.source, "side of", r.target, r.inferred)
        out.append(r)
    return out, notes
