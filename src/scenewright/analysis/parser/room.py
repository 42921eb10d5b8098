"""The room of an indoor scene, read from its text: size, height, doors and windows (docs/rooms.md).

``read_room`` reads what the text says ("a 4 by 5 m bedroom", "a 4x5 metre room", "a small
bathroom", "a large open-plan kitchen", "high ceilings", "a window on the left wall", "two
doors"); ``build_room`` makes the :class:`~scenewright.scene.Room` from it and the objects:
the stated size when there is one, else the floor the objects need with walking space (never
smaller than the place's usual size, scaled by "small"/"large"); at least one door; windows
where the text puts them, else one on the back wall. ``wall_phrases`` turns "against the back
wall", "in the corner", "a mirror on the left wall" into room relations.

Decisions where nothing is said:

- Rooms built here are rectangles centred at the origin, walls listed front (−y, the viewer's
  side), right, back, left: so "the back wall" is ``wall_2`` (:data:`RECTANGLE_WALLS`).
- The floor objects may cover at most :data:`COVERAGE` of the floor (less when there are many:
  :func:`~scenewright.layout.room.floor_needed`); each side is at least the
  longest object plus a walking lane on either side (:data:`LANE`).
- The default door is on the left wall near the front corner (the renders look from the front,
  so a door there stays visible); the default window is centred on the back wall.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace
from typing import Sequence

from scenewright.core.catalogue import load_catalogue, singular
from scenewright.analysis.parser.model import ParsedRelation, ParsedScene
from scenewright.analysis.parser.style import detect_ground
from scenewright.analysis.parser.vocabulary import load_vocabulary
from scenewright.analysis.parser.words import _DETERMINERS
from scenewright.errors import InputError
from scenewright.layout.room import COVERAGE, floor_needed
from scenewright.layout.room import FLOOR as FLAT
from scenewright.scene import CEILING_TARGET, MAX_ROOM_HEIGHT, MIN_ROOM_HEIGHT, MIN_WALL, Opening, Room, SceneObject

#: Walls of a room made by :meth:`Room.rectangle`, by the side of the room they stand on.
RECTANGLE_WALLS = {"front": 0, "right": 1, "back": 2, "left": 3}
_SIDE_WORDS = {"back": "back", "rear": "back", "far": "back", "left": "left", "right": "right", "front": "front",
               "near": "front", "side": None}
#: Usual floor (width, depth) in metres of the places people describe.
PLACE_SIZES: dict[str, tuple[float, float]] = {
    "bedroom": (3.6, 4.0), "bathroom": (2.4, 2.8), "kitchen": (3.6, 4.0), "office": (3.6, 4.0),
    "living room": (4.5, 5.0), "lounge": (4.5, 5.0), "dining room": (4.0, 4.5), "library": (6.0, 7.0),
    "classroom": (7.0, 8.0), "shop": (6.0, 7.0), "store": (6.0, 7.0), "bookstore": (6.0, 7.0),
    "boutique": (5.0, 6.0), "cafe": (6.0, 7.0), "café": (6.0, 7.0), "restaurant": (8.0, 9.0), "bar": (6.0, 7.0),
    "studio": (5.0, 6.0), "lab": (7.0, 8.0), "laboratory": (7.0, 8.0), "gym": (7.0, 8.0), "nursery": (3.5, 4.0),
    "study": (3.5, 4.0), "den": (4.0, 4.5), "attic": (4.5, 5.0), "basement": (5.0, 6.0), "garage": (5.5, 6.0),
    "workshop": (5.5, 6.5), "hallway": (2.0, 5.0), "corridor": (2.0, 6.0), "salon": (5.0, 6.0),
    "bakery": (5.0, 6.0), "clinic": (4.0, 5.0), "room": (4.0, 4.5), "apartment": (5.0, 6.0),
    "gallery": (7.0, 8.0), "chamber": (5.0, 6.0), "hall": (9.0, 10.0), "pantry": (2.0, 2.5),
    "laundry room": (2.5, 3.0), "playroom": (4.0, 4.5), "kids room": (3.5, 4.0), "games room": (5.0, 5.5),
    "conference room": (5.0, 7.0), "meeting room": (4.5, 6.0), "waiting room": (4.5, 5.5),
    "barn": (8.0, 10.0), "stable": (6.0, 8.0), "cabin": (5.0, 6.0), "cottage": (5.0, 6.0), "hut": (3.5, 4.0),
    "shed": (3.0, 3.5), "shack": (3.0, 3.5), "greenhouse": (5.0, 8.0),
}  # fmt: skip
_SMALL = ("small", "tiny", "cosy", "cozy", "compact", "little", "cramped", "narrow")
_LARGE = ("large", "big", "spacious", "huge", "grand", "vast", "open-plan", "open plan", "airy", "wide")
SMALL_SCALE, LARGE_SCALE = 0.8, 1.3
#: m, a walking lane beside the longest object.
LANE = 0.9
#: How much larger than the floor the objects need a room may grow to keep a lane round their groups.
GROWTH = 1.35
DEFAULT_HEIGHT = 2.7
DOOR = (0.9, 2.1)  # width, height
WINDOW = (1.2, 1.2, 0.9)  # width, height, sill
_NUMBERS = {"a": 1, "an": 1, "one": 1, "single": 1, "two": 2, "twin": 2, "pair": 2, "three": 3, "four": 4,
            "several": 3, "some": 2, "many": 4, "few": 2}
_LENGTH = r"(\d+(?:\.\d+)?)\s*(m\b|metres?|meters?|ft\b|feet|foot)?"
_SIZE = re.compile(_LENGTH + r"\s*(?:by|x|×|\*)\s*" + _LENGTH + r"(?:\s*(?:by|x|×|\*)\s*" + _LENGTH + r")?")
_PLACES = sorted(PLACE_SIZES, key=len, reverse=True)
_PLACE = re.compile(r"\b(" + "|".join(re.escape(p) for p in _PLACES) + r")s?\b")


@dataclass(frozen=True)
class RoomRequest:
    """What a text says about its room; ``None`` fields say nothing."""

    place: str | None = None
    size: tuple[float, float] | None = None
    height: float | None = None
    scale: float = 1.0
    #: Openings asked for: (kind, side or None, count).
    openings: tuple[tuple[str, str | None, int], ...] = field(default_factory=tuple)
    #: The floor's, the walls' and the ceiling's material words ("brick", "white tiled"), or None.
    floor_material: str | None = None
    wall_material: str | None = None
    ceiling_material: str | None = None
    #: "L" for an L-shaped room ("an L-shaped living room"), else None: a rectangle.
    shape: str | None = None


def _metres(value: str, unit: str | None) -> float:
    v = float(value)
    return v * 0.3048 if unit and unit.startswith(("ft", "f")) else v


def read_room(text: str) -> RoomRequest:
    """What ``text`` says about its room (any text: whether it is indoor is the parse's call)."""
    low = " ".join(text.lower().split())
    place_match = _PLACE.search(low)
    place = place_match.group(1) if place_match else None
    size = height = None
    for m in _SIZE.finditer(low):
        after, before = low[m.end() : m.end() + 30], low[max(0, m.start() - 30) : m.start()]
        # A size of the room: followed by a place word ("a 4 by 5 m bedroom") or after "room"
        # ("a room of 4 x 5 metres", "the kitchen measures 3 by 4 m"), never an object's size.
        if _PLACE.match(after.strip()) or re.search(r"\b(" + "|".join(map(re.escape, _PLACES)) + r")s?\b[^.,;]*$", before):
            w, d = _metres(m.group(1), m.group(2) or m.group(4)), _metres(m.group(3), m.group(4) or m.group(2))
            size = (w, d)
            if m.group(5):
                height = _metres(m.group(5), m.group(6) or m.group(4))
            break
    m = re.search(r"(\d+(?:\.\d+)?)\s*(m\b|metres?|meters?|ft\b|feet)[ -](?:high |tall )?ceilings?|ceilings?[^.,;]{0,20}?"
                  r"(\d+(?:\.\d+)?)\s*(m\b|metres?|meters?|ft\b|feet)", low)
    if height is None and m:
        height = _metres(m.group(1) or m.group(3), m.group(2) or m.group(4))
    elif height is None and re.search(r"\b(high|tall|lofty|vaulted|double-height)[\s-]+ceil(?:ings?|inged)\b", low):
        height = 3.4
    elif height is None and re.search(r"\blow[\s-]+ceil(?:ings?|inged)\b", low):
        height = 2.4
    scale = 1.0
    if place_match:
        lead = low[max(0, place_match.start() - 40) : place_match.start()]
        lead = re.split(r"[.,;]", lead)[-1]
        if any(re.search(rf"\b{re.escape(w)}\b", lead) for w in _LARGE):
            scale = LARGE_SCALE
        elif any(re.search(rf"\b{re.escape(w)}\b", lead) for w in _SMALL):
            scale = SMALL_SCALE
    materials = {noun: _surface_words(low, noun) for noun in ("floor", "wall", "ceiling")}
    # The floor's kind (a ground texture): from its own words, else from the place ("a kitchen":
    # tiles), never from what the walls or ceiling are made of ("white tiled walls").
    rest = low
    for noun in ("wall", "ceiling"):
        if materials[noun]:
            rest = re.sub(rf"\b{re.escape(materials[noun])}\s+(?:{_SURFACE_NOUNS[noun]})\b", " ", rest)
    materials["floor"] = detect_ground(f"{materials['floor']} floor" if materials["floor"] else rest, True)
    shape = "L" if re.search(r"\bl[- ]shaped\b|\bl[- ]shape\b", low) else None
    return RoomRequest(place=place, size=size, height=height, scale=scale, openings=tuple(_openings(low)),
                       floor_material=materials["floor"], wall_material=materials["wall"],
                       ceiling_material=materials["ceiling"], shape=shape)


#: Words that say what a floor, wall or ceiling is made of or how it looks: a phrase before the
#: noun becomes the room's material only with one of them ("brick walls", "a white tiled wall";
#: not "the back wall", "the kitchen wall"). The geometry reads the phrase (procedural/room.py).
_SURFACE_WORDS = frozenset("""
    wood wooden oak pine walnut maple cherry teak hardwood parquet plank planked timber log bamboo cork
    brick bricks stone marble granite slate concrete cement tile tiles tiled terracotta mosaic plaster
    plastered stucco painted wallpapered wallpaper panelled paneled whitewashed glass mirrored metal
    steel iron copper brass chrome aluminium aluminum carpet carpeted rubber linoleum vinyl velvet fabric
    white black grey gray red green blue yellow orange purple pink brown beige cream ivory teal turquoise
    navy olive golden gold silver dark light pale bright pastel rustic polished rough bare exposed
""".split())
_SURFACE_NOUNS = {"floor": r"floors?|flooring", "wall": r"walls?", "ceiling": r"ceilings?"}


def _surface_words(low: str, noun: str) -> str | None:
    """The material words right before the first ``noun`` that has some ("red brick walls" →
    "red brick"), or None."""
    for m in re.finditer(rf"((?:[a-z-]+\s+){{1,3}})(?:{_SURFACE_NOUNS[noun]})\b", low):
        words: list[str] = []
        for w in reversed(m.group(1).split()):
            if w not in _SURFACE_WORDS and not (w.endswith("-tiled") or w.endswith("-panelled")):
                break
            words.insert(0, w)
        if words:
            return " ".join(words)
    return None


def _openings(low: str) -> list[tuple[str, str | None, int]]:
    """Doors and windows the text names, with the wall it puts them on and how many."""
    out: list[tuple[str, str | None, int]] = []
    pattern = re.compile(r"(?:\b([\w-]+)\s+)?(?:\b([\w-]+)\s+)?\b(windows?|doors?|doorways?|french doors)\b"
                         r"((?:(?!\band\b|\bwith\b|,)[^.;]){0,40})")
    for m in pattern.finditer(low):
        words, noun, rest = (m.group(1), m.group(2)), m.group(3), m.group(4)
        kind = "window" if noun.startswith("window") else "door"
        if any(w in ("the", "its", "that", "this", "each", "every") for w in words) and any(k == kind for k, _, _ in out):
            continue  # a reference to one already named
        counted = [_NUMBERS[w] for w in words if w in _NUMBERS]
        count = counted[-1] if counted else (2 if noun.endswith("s") and noun != "french doors" else 1)
        side_m = re.search(r"\b(back|rear|far|left|right|front)(?:\s+|-)(?:hand\s+)?(?:side\s+)?wall\b|\bon the (left|right)\b", rest)
        side = _SIDE_WORDS.get((side_m.group(1) or side_m.group(2))) if side_m else None
        out.append((kind, side, min(count, 4)))
    return out


_ROOM_OPTION = re.compile(r"^\s*(\d+(?:\.\d+)?)\s*[x×]\s*(\d+(?:\.\d+)?)(?:\s*[x×]\s*(\d+(?:\.\d+)?))?\s*$")


def parse_room_option(value: str | None) -> str | tuple[float, float, float | None]:
    """``--room``'s value: ``"auto"``, ``"none"``, or (width, depth, height or None) in metres.

    Raises InputError naming the value for anything else, or a room that cannot be one."""
    if value is None:
        return "auto"
    v = value.strip().lower()
    if v in ("auto", "none"):
        return v
    m = _ROOM_OPTION.match(v)
    if not m:
        raise InputError(f"--room {value!r}: give auto, none, or the floor as WxD or WxDxH in metres (e.g. 4x5 or 4x5x2.7)")
    w, d = float(m.group(1)), float(m.group(2))
    h = float(m.group(3)) if m.group(3) else None
    if min(w, d) < MIN_WALL or max(w, d) > 200:
        raise InputError(f"--room {value!r}: each side of the floor must be from {MIN_WALL:g} to 200 m")
    if h is not None and not MIN_ROOM_HEIGHT <= h <= MAX_ROOM_HEIGHT:
        raise InputError(f"--room {value!r}: the height must be from {MIN_ROOM_HEIGHT:g} to {MAX_ROOM_HEIGHT:g} m")
    return (w, d, h)


def floor_objects(objects: Sequence[SceneObject]) -> list[SceneObject]:
    """The objects that stand on the floor: not hung, not on something, not walked over (a rug)."""
    catalogue = load_catalogue()
    out = []
    for o in objects:
        entry = catalogue.get(o.category) if o.category else None
        if (entry is not None and entry.rests != "ground") or o.size.z <= FLAT:
            continue
        out.append(o)
    return out


def floor_area(objects: Sequence[SceneObject]) -> tuple[float, float]:
    """The footprint area of the objects that stand on the floor, and the longest side of one."""
    floor = floor_objects(objects)
    return sum(o.size.x * o.size.y for o in floor), max((max(o.size.x, o.size.y) for o in floor), default=0.0)


def build_room(request: RoomRequest, objects: Sequence[SceneObject], size: tuple[float, float, float | None] | None = None) -> Room:
    """The room for ``objects``: ``size`` (from ``--room``) or the stated one, else sized around
    the objects' floor (see the module docstring), with the requested doors and windows."""
    height = (size[2] if size else None) or request.height or DEFAULT_HEIGHT
    height = min(max(height, MIN_ROOM_HEIGHT), MAX_ROOM_HEIGHT)
    if size is not None:
        width, depth = size[0], size[1]
    elif request.size is not None:
        width, depth = request.size
    else:
        area, longest = floor_area(objects)
        need = max(floor_needed(area, len(floor_objects(objects))), 6.0)
        width = max(math.sqrt(need * 1.2), longest + 2 * LANE)
        depth = max(need / width, longest + 2 * LANE, 2.4)
        if request.place in PLACE_SIZES:
            usual_w, usual_d = PLACE_SIZES[request.place]
            width, depth = max(width, usual_w * request.scale), max(depth, usual_d * request.scale)
        # Room to walk around the composed groups (a table with its chairs), up to a limit: the
        # first poses are spread for open ground, and a room that follows them all is a hall.
        (x0, y0), (x1, y1) = _extent(objects)
        width = min(max(width, x1 - x0 + 2 * LANE), GROWTH * width)
        depth = min(max(depth, y1 - y0 + 2 * LANE), GROWTH * depth)
        if request.shape == "L":  # the same floor with the notch cut out
            width, depth = width / math.sqrt(1 - NOTCH**2), depth / math.sqrt(1 - NOTCH**2)
        width, depth = math.ceil(width * 10) / 10, math.ceil(depth * 10) / 10
    materials = {**({"floor_material": request.floor_material} if request.floor_material else {}),
                 **({"wall_material": request.wall_material} if request.wall_material else {}),
                 **({"ceiling_material": request.ceiling_material} if request.ceiling_material else {})}
    room = l_shaped(width, depth, height, **materials) if request.shape == "L" else Room.rectangle(width, depth, height, **materials)
    return Room.model_validate({**room.model_dump(), "openings": place_openings(room, request.openings)})


#: The share of each side an L-shaped room's notch takes.
NOTCH = 0.4


def l_shaped(width: float, depth: float, height: float = DEFAULT_HEIGHT, **fields) -> Room:
    """An L: the ``width`` x ``depth`` rectangle centred at the origin, less a notch of
    :data:`NOTCH` of each side at its front-left corner. Walls 0..3 are then the front, right,
    back and left walls as in a rectangle (:data:`RECTANGLE_WALLS`, so "the back wall" means the
    same), walls 4 and 5 the notch's."""
    w, d = width / 2.0, depth / 2.0
    nx, ny = -w + NOTCH * width, -d + NOTCH * depth
    return Room(floor=[(nx, -d), (w, -d), (w, d), (-w, d), (-w, ny), (nx, ny)], height=height, **fields)


def _extent(objects: Sequence[SceneObject]) -> tuple[tuple[float, float], tuple[float, float]]:
    """The plan rectangle, centred at the origin, that holds the objects' first poses: a room
    around the composed groups (a table with its chairs) keeps a lane around them."""
    reach = [(abs(o.position.x) + max(o.size.x, o.size.y) / 2, abs(o.position.y) + max(o.size.x, o.size.y) / 2)
             for o in objects]
    if not reach:
        return (0.0, 0.0), (0.0, 0.0)
    hx, hy = max(r[0] for r in reach), max(r[1] for r in reach)
    return (-hx, -hy), (hx, hy)


def place_openings(room: Room, wanted: Sequence[tuple[str, str | None, int]]) -> list[Opening]:
    """Doors and windows on the walls ``wanted`` names (else the defaults), spread along each
    wall so none overlaps another; a wall too short for what it is given gets fewer."""
    doors = [(side, n) for kind, side, n in wanted if kind == "door"] or [("left", 1)]
    windows = [(side, n) for kind, side, n in wanted if kind == "window"] or [("back", 1)]
    per_wall: dict[int, list[str]] = {}
    for kind, asked in (("door", doors), ("window", windows)):
        for side, n in asked:
            wall = RECTANGLE_WALLS[side or ("left" if kind == "door" else "back")]
            per_wall.setdefault(wall, []).extend([kind] * n)
    out: list[Opening] = []
    for wall, kinds in sorted(per_wall.items()):
        length = room.wall_length(wall)
        kinds = sorted(kinds, key=lambda k: k != "door")  # doors first: nearest the wall's start
        widths = [DOOR[0] if k == "door" else min(WINDOW[0], length / 3) for k in kinds]
        while kinds and sum(widths) + 0.3 * (len(kinds) + 1) > length:
            kinds, widths = kinds[:-1], widths[:-1]
        if not kinds:
            continue
        gap = (length - sum(widths)) / (len(kinds) + 1)
        at = gap
        if kinds == ["door"] and wall == RECTANGLE_WALLS["left"]:
            at = length - 0.3 - widths[0]  # a lone door near the front corner (the left wall runs back to front)
        for kind, width in zip(kinds, widths):
            if kind == "door":
                out.append(Opening(kind="door", wall=wall, offset=at + width / 2, width=width,
                                   height=min(DOOR[1], room.height - 0.2)))
            else:
                sill = WINDOW[2]
                out.append(Opening(kind="window", wall=wall, offset=at + width / 2, width=width,
                                   height=max(0.3, min(WINDOW[1], room.height - sill - 0.3)), sill=sill))
            at += width + gap
    return out


#: Categories hung on a wall, and hung from the ceiling, when the scene has a room.
WALL_THINGS = frozenset({"picture_frame", "mirror", "wall_clock", "projector_screen", "lifebuoy"})
CEILING_THINGS = frozenset({"ceiling_fan", "pendant_lamp", "punching_bag"})


#: Words that make a thing that usually hangs (a mirror) one that stands on the floor.
STANDING_FORMS = ("full length", "standing", "free standing", "freestanding", "floor", "cheval")


def standing_form(name: str) -> bool:
    """Whether a name says a thing that usually hangs stands on the floor ("a full-length
    mirror", "a cheval mirror")."""
    return any(f" {form} " in f" {name.lower()} " for form in STANDING_FORMS)


def hangs_by_kind(o) -> bool:
    """Whether a parsed or a scene object hangs on a wall by its kind (:data:`WALL_THINGS`), not
    named or described in a standing form."""
    words = f"{o.name} {getattr(o, 'description', '')} {getattr(o, 'visual_description', '')}"
    return o.category in WALL_THINGS and not standing_form(words)

#: Words for a room's wall (a ship's bulkhead is its wall); "window" and "door" only for a thing hung there.
_WALL_WORDS = r"(wall|corner|bulkhead|window|door)"
#: (a verb that spreads things over a wall counts as its preposition: "clocks cover the walls")
_WALL_PHRASE = re.compile(r"\b(against|along|on|by|beside|to|in|at|onto|from|covers?|lines?|fills?|crowds?|adorns?|"
                          r"decorates?)\s+"
                          r"(?:the\s+|a\s+|one\s+)?(?:(back|rear|far|left|right|front)(?:[- ]hand)?\s+)?" + _WALL_WORDS + r"s?\b")
#: Verbs (and participles) that fix a thing to a wall or the ceiling.
_FIXING = r"(?:hang|hangs|hanging|hung|mounted|fixed|pinned|nailed|fastened|bolted|screwed|hooked|attached|affixed|clamped|tacked|taped|glued|stuck|suspended)"
#: "hangs from the ceiling", "suspended from the vaulted ceiling", "on the ceiling", "dangle from
#: strings hooked to the ceiling", "fixed to the ceiling".
_CEILING_PHRASE = re.compile(
    # (or from something in it: "hams hang from hooks in the ceiling beams")
    r"\b(?:(?:" + _FIXING + r"|dangles?|dangling|swings?)\s+(?:[\w-]+\s+){0,4}?(?:from|to)\s+(?:[\w-]+\s+(?:in|on)\s+)?|on\s+)"
    r"the\s+(?:[\w-]+\s+){0,2}?(?:ceiling|beams|rafters)\b"  # ("onions hang from the low beams")
    # what hangs from something "overhead" that is no thing of the scene hangs from the room's top
    # ("sandbags hang from the fly gallery overhead"; a named rack overhead carries its pans)
    r"|\b(?:" + _FIXING + r"|dangles?|dangling|swings?)\s+from\s+the\s+(?:[\w-]+\s+){1,3}?overhead\b"
)
#: A sentence that opens on a wall ("On the wall behind the otters, a menu board lists the day's
#: catch"): its subject is on (or against) that wall.
_FRONTED_WALL = re.compile(r"\s*(on|against|along)\s+(?:the\s+|a\s+|one\s+)?(?:(back|rear|far|left|right|front)"
                           r"(?:[- ]hand)?\s+)?walls?\b[^,]*,")
#: Words by which a thing leans or rests on a wall it stands against ("a bicycle leaning on the wall").
_LEANING = re.compile(r"\b(?:lean(?:s|ing|ed)?|propped|resting|rests)\b")
_MOUNTED = re.compile(r"\b" + _FIXING + r"\b")
#: Words before a thing's name that fix it to a wall: "a wall shelf", "a wall-mounted screen", "two
#: framed butterfly cases" (what is framed hangs).
_WALL_WORDS_BEFORE = re.compile(
    r"\b(?:wall\s+|(?:wall-mounted|framed)\s+(?:(?!(?:by|with|in|on|of|and|or|the|a|an)\b)[\w-]+\s+){0,2})$"
)
#: The leading list of a thing's fellow subjects ("saws and chisels hang on the wall"): names
#: there do not come between the thing and its wall phrase.
_FELLOWS = re.compile(r"(?:\s*(?:,|and|or)\s+(?:(?:a|an|the|some)\s+)?(?:[\w-]+\s+){0,2}?[\w-]+)+")


def _names_between(text: str, names: set[str], own: str) -> bool:
    """Whether ``text`` names a thing other than ``own``."""
    return any(_named(text, other) is not None for other in names if other != own)


def _named(text: str, name: str, nouns: frozenset[str] = frozenset()) -> tuple[int, int] | None:
    """Where ``text`` first names ``name``, singular or plural ("shelves" names a shelf); a name
    that is also a verb of standing names the thing only after a determiner or a describing word
    ("a wooden stand", not "three clocks stand against the wall"), and a plural right after one
    of the ``nouns`` is that one's verb ("a blacksmith hammers a sword", no hammers)."""
    vocabulary = load_vocabulary()
    before = ""
    for found in re.finditer(r"[\w-]+", text):
        word = found.group()
        if word == name or singular(word) == name and before not in nouns:
            described = before in _DETERMINERS or bool(before) and vocabulary.is_adjective(before)
            if not vocabulary.is_posture_verb(word) or described:
                return found.span()
        before = word
    return None


def _named_whole(text: str, name: str, whole: re.Pattern) -> tuple[int, int] | None:
    """Where ``text`` names a thing by its whole name (``whole``): the span of its head word ``name``."""
    found = whole.search(text)
    return (found.end() - len(name), found.end()) if found else None


def _head(o) -> str:
    """The word a thing is named by in the text (the last of its name)."""
    return o.name.lower().split()[-1] if o.name else o.category.replace("_", " ")


def _wall_of(side: str | None) -> str:
    """The wall a side word names ("back", "left"), else any wall of the room."""
    return f"wall_{RECTANGLE_WALLS[_SIDE_WORDS[side]]}" if side and _SIDE_WORDS.get(side) else "room"


def wall_phrases(parsed: ParsedScene) -> list[ParsedRelation]:
    """Room relations the text states: "against the (back) wall" → ``against wall``, "in the
    corner" → ``in corner``, a thing on, hung or mounted on "the left wall" (fixed, bolted, hung in
    the window, on a ship's bulkhead) → ``on wall``, a thing hanging from the ceiling → ``on
    ceiling``; "a wall shelf", "a wall-mounted screen" and "framed" things hang on a wall. The side
    picks the wall (:data:`RECTANGLE_WALLS`); no side means any wall (``room``). A thing is matched
    to the phrase in its own sentence, after its name (singular or plural); its fellow subjects
    ("saws and chisels hang on the wall") come with it. A thing on the floor the text puts at the
    back of the room, with nothing behind it, stands against the back wall."""
    low = " ".join(parsed.text.lower().split())
    sentences = [(m.start(), m.end()) for m in re.finditer(r"[^.;!?]+", low)]
    names = frozenset(_head(o) for o in parsed.objects)
    backed = {r.target for r in parsed.relations if r.relation == "behind"}
    out = []
    for o in parsed.objects:
        placed = len(out)
        name = _head(o)
        # a name of several words is found as a whole first ("a grandfather clock" after "clocks")
        # (and in the plural: "oil lamps hang on the walls")
        written = re.escape(" ".join(o.name.lower().split()))
        full = re.compile(rf"\b{written}(?:e?s)?\b") if " " in o.name.strip() else None
        whole = [(s, e) for s, e in sentences if full is not None and full.search(low[s:e])]
        for s, e in whole or sentences:
            sentence = low[s:e]
            found = _named_whole(sentence, name, full) if whole else _named(sentence, name, names)
            if found is None:
                continue
            if _WALL_WORDS_BEFORE.search(sentence[: found[0]]):
                out.append(ParsedRelation(source=o.id, relation="on wall", target="room"))
                break
            fronted = _FRONTED_WALL.match(sentence)
            subject = sentence[fronted.end() : found[0]] if fronted and fronted.end() <= found[0] else None
            if subject is not None and len(subject.split()) <= 4 and not _names_between(subject, names, name):
                against = fronted.group(1) != "on" and not hangs_by_kind(o)
                out.append(ParsedRelation(source=o.id, relation="against wall" if against else "on wall",
                                          target=_wall_of(fronted.group(2))))
                break
            at = found[1]
            ceiling = _CEILING_PHRASE.search(sentence, at)
            phrase = _WALL_PHRASE.search(sentence, at)
            if phrase is not None and ceiling is not None and phrase.start() < ceiling.start():
                ceiling = None  # "wheels hang on the back wall, and tubes dangle from the ceiling"
            fellows = _FELLOWS.match(sentence, at)
            if fellows is not None:
                at = fellows.end()  # "saws and chisels hang on the wall": the chisels are fellows
            # (names inside the phrase count: "a workbench, and two hanging lamps dangle from the ceiling")
            if ceiling is not None and not _names_between(sentence[at:ceiling.end()], names, name):
                out.append(ParsedRelation(source=o.id, relation="on ceiling", target=CEILING_TARGET))
                break
            if phrase is None:
                break
            # The phrase places this thing when the parse anchored it to a wall, when it is a wall
            # thing and the phrase names a wall, or when no other thing is named between the two
            # ("a wardrobe stands against the right wall"; not "a desk with a lamp by the wall",
            # nor "a mirror hangs above the rack, and a fan stands in the corner").
            between = sentence[at:phrase.start()]
            preposition, side, what = phrase.group(1), phrase.group(2), phrase.group(3)
            wall_thing = hangs_by_kind(o) and what == "wall"
            # (anchored at the back or in the middle of the room is no wall's: "a stage at the far
            # end with a microphone in his hand, and a screen hangs on the wall" hangs the screen)
            if o.anchor not in ("wall", "corner") and not wall_thing and _names_between(between, names, name):
                break
            if what in ("window", "door") and not _MOUNTED.search(between):
                break  # a thing hung in the window or by the door is on its wall; one standing there is not
            target = _wall_of(side)
            if what == "corner":
                relation = "in corner"
            elif _LEANING.search(between) and not hangs_by_kind(o):
                relation = "against wall"  # "a bicycle leaning on the wall" stands by it, not fixed up on it
            elif hangs_by_kind(o) or preposition in ("on", "onto") or _MOUNTED.search(between):
                relation = "on wall"  # a thing on a wall, or hung or mounted there, is fixed to it
            else:
                relation = "against wall"
            out.append(ParsedRelation(source=o.id, relation=relation, target=target))
            break
        if len(out) == placed and o.anchor == "back" and o.rests == "ground" and o.id not in backed:
            # "a long counter runs across the back": against the back wall, not any wall (unless
            # someone stands behind it: "a baker waits behind it")
            out.append(ParsedRelation(source=o.id, relation="against wall", target=_wall_of("back")))
    # a storage unit the text puts above a thing is a shelf or a cabinet fixed to the wall over it
    # ("a pelican watches from a shelf above the door", "a cabinet above the sink")
    category = {o.id: o.category for o in parsed.objects}
    for r in parsed.relations:
        if r.relation == "above" and not r.inferred and category.get(r.source) in WALL_UNIT_HEIGHTS:
            if not any(w.source == r.source for w in out):
                out.append(ParsedRelation(source=r.source, relation="on wall", target="room"))
    return out


#: Height (m) a floor-standing storage unit takes when the text fixes it to a wall: a wall shelf is
#: a board or two ("three shelves fixed to the back wall", "a wall shelf above the console"), not
#: a 1.9 m bookcase lifted off the floor, and what stands on it still fits under the ceiling.
WALL_UNIT_HEIGHTS = {"bookshelf": 0.45, "shop_shelf": 0.45, "cabinet": 0.7}
#: m, the depth of such a unit at most.
WALL_UNIT_DEPTH = 0.3


#: m, the depth of a thing nobody listed that the text fixes to a wall ("a calendar hangs on the wall").
WALL_SHEET_DEPTH = 0.05
#: Boards that stand on legs by themselves and hang flat, wider than tall, when fixed to a wall.
WALL_BOARDS = {"menu_board", "sign"}


def wall_units(parsed: ParsedScene) -> list:
    """``parsed``'s objects, each storage unit the text fixes to a wall (:func:`wall_phrases`) the
    size of a wall unit (:data:`WALL_UNIT_HEIGHTS`), each standing board a flat one (:data:`WALL_BOARDS`),
    and each thing nobody listed that is fixed
    there flat against it: a board if nothing says its shape ("a diploma hangs on the wall"),
    stood up if it was guessed lying flat ("a map pinned to the wall"; a tool hangs as it is); the
    rest as they are."""
    mounted = {r.source for r in wall_phrases(parsed) if r.relation == "on wall"}
    out = []
    for o in parsed.objects:
        height = WALL_UNIT_HEIGHTS.get(o.category)
        width, depth, tall = o.size
        if o.id in mounted and height is not None and tall > height:
            o = replace(o, size=(width, min(depth, WALL_UNIT_DEPTH), height))
        elif o.id in mounted and o.category in WALL_BOARDS:  # ("a chalkboard menu hangs on the wall": no A-frame)
            o = replace(o, size=(min(max(width, tall), 1.2), WALL_SHEET_DEPTH, min(width, tall)), rests="hanging")
        elif o.id in mounted and o.guessed and o.category == "thing":
            o = replace(o, category="panel", size=(width, WALL_SHEET_DEPTH, tall), rests="hanging")
        elif o.id in mounted and o.guessed and o.category != "tool" and tall < min(width, depth):
            o = replace(o, size=(width, tall, depth), rests="hanging")
        out.append(o)
    return out


def room_for(
    text: str,
    objects: Sequence[SceneObject],
    option: str | tuple[float, float, float | None] = "auto",
    proposal: Room | None = None,
    proposed: bool = False,
) -> Room | None:
    """The scene's room under ``--room`` ``option`` (:func:`parse_room_option`).

    ``none``: no room. A size: that floor, with the doors and windows the text names. ``auto``:
    the room a remote model proposed (``proposed``; its ``proposal`` may be None for an open
    scene), else, when the parse reads the text as indoor, one built from the text around the
    objects; an open-domain text stands on the ground plane.
    """
    from scenewright.analysis.parser import parse_scene  # the package imports this module

    if option == "none":
        return None
    request = read_room(text)
    if isinstance(option, tuple):
        return build_room(request, objects, option)
    if proposed:
        return proposal
    return build_room(request, objects) if parse_scene(text).indoor else None


def tall_freely(option: str, text: str) -> bool:
    """Whether a room's ceiling may be raised for what hangs in it: ``--room`` gave no height
    (``auto``, or a floor without one) and the ``text`` states none."""
    if option == "none":
        return False
    parsed = parse_room_option(option)
    return (parsed == "auto" or (isinstance(parsed, tuple) and parsed[2] is None)) and read_room(text).height is None


def sized_freely(option: str, text: str) -> bool:
    """Whether a room may be grown to fit its objects: ``--room auto`` and a ``text`` that
    states no size (the size was ours, or a model's guess), not one the user fixed."""
    return option == "auto" and read_room(text).size is None
