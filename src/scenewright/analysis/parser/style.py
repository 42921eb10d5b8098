"""The look of the scene as a whole: the named style, the ground kind and indoor-ness.
"""

from __future__ import annotations

import re

from scenewright.core.styles import load_looks, media_heads, normalise
from scenewright.scene import DEFAULT_STYLE

#: Ground kinds the procedural ground textures understand.
GROUND_KINDS = (
    "wood floor", "tiles", "carpet", "concrete", "marble", "grass", "gravel", "cobblestone",
    "sand", "dirt", "snow", "metal deck", "stone", "rubber", "asphalt",
)  # fmt: skip


#: A verb of making before "as", "like", "in" or "into", "in the style of", or a clause opening "as" or
#: "like": the words after it, up to "of" or the clause's end, say what the picture is ("drawn as a Soviet
#: constructivist poster", "painted like an impressionist canvas", "rendered in cross-stitch", "in the
#: style of a pulp magazine cover", "A fishing village, as a woodblock print.").
_MADE_AS = re.compile(
    r"\b(?:(?:drawn|rendered|painted|printed|done|made|sketched|woven|stitched|embroidered|etched|engraved|carved|"
    r"cut|shown|depicted|illustrated|imagined|pictured|styled|crafted|modelled|modeled|sculpted|knitted|felted)\s+"
    r"(?:as|like|in|into)|in\s+the\s+(?:style|manner)\s+of|[,:;(]\s*(?:as|like))\s+(?:(?:an?|the)\s+)?([^.,:;!?()]*)"
)
#: A verb that puts the opening picture somewhere: "A painting of a ship hangs above the fireplace" is
#: a thing in the room, "A painting of a harbour at dawn." the scene's look.
_PLACED = re.compile(r"\b(?:is|are|hangs?|hung|sits?|stands?|leans?|rests?|lies|covers?|fills?|decorates?|"
                     r"dominates?|propped|pinned|taped|mounted)\b")
#: "Walls painted in pastel colours" name colours, not a medium.
_COLOUR_NOUNS = {"colour", "colours", "color", "colors", "shade", "shades", "tone", "tones", "hue", "hues", "tints"}
#: Words that end a medium phrase: "a poster" in "a study with a poster" is a thing in it.
_PHRASE_ENDS = {"of", "with", "and", "or", "in", "on", "at", "by", "from", "near", "under", "above", "over", "behind",
                "beside", "for", "to", "where", "that", "which", "while", "as", "showing", "depicting", "featuring"}
#: The longest medium phrase read: "a two-colour risograph print", not a whole clause.
_MEDIUM_WORDS = 6


def _medium_phrases(text: str) -> list[tuple[str, str]]:
    """Phrases that name what the scene is a picture of, normalised (:func:`_media`): each as written
    and with its plurals made singular ("in the style of old engravings", "drawn in crayons")."""
    phrases = []
    for words, _ in _media(text):
        single = [w[:-1] if len(w) > 3 and w.endswith("s") and not w.endswith("ss") else w for w in words]
        phrases.append((" ".join(words), " ".join(single)))
    return phrases


def _media(text: str) -> list[tuple[list[str], tuple[int, int]]]:
    """Each phrase that says what the picture is, as words, and the span of the text it is said in:
    after a verb of making (:data:`_MADE_AS`, the words up to the clause's end), or opening the text
    when it ends in a picture noun or a look's word ("A child's crayon drawing of a ...", "A
    needle-felted miniature: ..."; ``media`` in ``data/styles.json``) and its clause places nothing
    ("A painting of a ship hangs above the fireplace" is a thing of the scene)."""
    low = text.lower()
    found = [(_noun_phrase(m[1]), (m.start(1), m.start(1) + _medium_end(m[1]))) for m in _MADE_AS.finditer(low)]
    clause = re.split(r"[.,:;!?()]|\s[-–—]\s", low, maxsplit=1)[0]
    opening = _noun_phrase(re.sub(r"^\W*(?:(?:an?|the)\s+)?", "", clause))
    if opening and (opening[-1] in media_heads() or _names_a_look(opening)) and not _PLACED.search(clause):
        found.append((opening, (0, len(clause.split(" of ")[0]))))
    return [(w, span) for w, span in found if w and len(w) <= _MEDIUM_WORDS and w[-1] not in _COLOUR_NOUNS]


def _medium_end(words: str) -> int:
    """Where the medium's own words end: its "of ..." is what it is made of ("a floor mosaic of tiny stone
    tiles"), any other phrase end goes back to the scene ("done in cross-stitch, with a tiled floor")."""
    ends = re.search(r"(?<![\w-])(?:" + "|".join(sorted(_PHRASE_ENDS - {"of"})) + r")(?![\w-])", words)
    return ends.start() if ends else len(words)


def without_media(text: str) -> str:
    """The text, lowercased, with what its picture is made of blanked out: "rendered as a floor mosaic
    of tiny stone tiles" says nothing of the ground the scene stands on."""
    low = text.lower()
    for _, (start, end) in _media(text):
        low = low[:start] + " " * (end - start) + low[end:]
    return low


def _names_a_look(phrase: list[str]) -> bool:
    """Whether a phrase ends in a look's word ("a mezzotint", "a floor mosaic"): the picture's own noun."""
    tail = f" {' '.join(phrase)}"
    return any(tail.endswith(f" {w}") for look in load_looks().values() for w in (*look.words, *look.styled))


def _noun_phrase(words: str) -> list[str]:
    """The normalised words before the first that ends a noun phrase ("of", "with", "and", "on" ...;
    not inside a hyphened word: "a blue-and-white tile panel")."""
    out: list[str] = []
    for token in words.split():
        if normalise(token) in _PHRASE_ENDS:
            break
        out += normalise(token).split()
    return out


def detect_style(text: str, default: str = DEFAULT_STYLE) -> str:
    """The look the text names ("cartoon-style", "Cyberpunk.", "a voxel-art quarry", "A linocut print
    of ...", "drawn as a blueprint"; the words are ``data/styles.json``'s), else ``default``.

    A word followed by "style" wins over a word used in passing; otherwise the first named. Words
    that also describe things ("gothic", "poster", "mosaic") name the look only before "style" or in
    the phrase that says what the picture is (:func:`_medium_phrases`)."""
    low = f" {normalise(text)} "
    media = [(low.find(f" {p} "), f" {form} ") for p, single in _medium_phrases(text) for form in {p, single}]
    best: tuple[int, int, int, str] | None = None
    for look in load_looks().values():
        for w in (*look.words, *look.styled):
            ranks = [(1, at + phrase.find(f" {w} "), -len(w), look.name) for at, phrase in media if f" {w} " in phrase]
            pos = low.find(f" {w} ")
            if pos >= 0:
                styled = low[pos + len(w) + 2 :].startswith(("style", "styled", "look", "aesthetic"))
                if styled or w not in look.styled:
                    ranks.append((0 if styled else 1, pos, -len(w), look.name))
            for rank in ranks:
                if best is None or rank < best:
                    best = rank
    return best[3] if best else default


#: Words for the ground itself, anywhere in the text: they name the floor ("a tiled floor", "on the sand").
_GROUND_MATERIALS = [
    ("metal deck", ("metal deck", "metal floor", "steel deck", "metal grating", "metal plating", "platform deck",
                    "spaceship deck")),
    ("cobblestone", ("cobblestone", "cobblestones", "cobbled", "cobble")),
    ("gravel", ("gravel",)),
    ("snow", ("snow", "snowy", "snow covered", "frozen", "icy", "winter")),
    ("sand", ("sand", "sandy", "dunes", "dune")),
    ("rubber", ("rubber ground", "rubber floor", "rubber mat", "rubber flooring", "gym floor")),
    ("marble", ("marble floor", "marble floors", "marble tiles", "marble flooring")),
    ("tiles", ("tile", "tiles", "tiled")),
    ("carpet", ("carpeted", "wall to wall carpet", "carpet floor")),
    ("asphalt", ("asphalt", "tarmac")),
    ("concrete", ("concrete",)),
    ("wood floor", ("wooden floor", "wood floor", "hardwood", "parquet", "floorboards", "wooden deck", "plank")),
    ("stone", ("stone floor", "flagstone", "flagstones", "paved")),
    ("dirt", ("dirt", "mud", "muddy", "soil")),
    ("grass", ("grass", "grassy", "lawn", "turf", "outfield", "cricket", "croquet", "bowling green", "playing field",
               "football pitch", "rugby pitch")),  # (games played on grass: the ground of the village too)
]
#: Words for places, and the ground each has: the setting's own word decides (the first one the
#: description names, its opening sentence first), so "a savannah enclosure at a city zoo" is
#: dirt, not the city's asphalt, and a landing pad further on does not floor a construction site.
_GROUND_PLACES = [
    ("metal deck", ("landing pad", "spaceport", "space station", "starship", "spaceship", "space ship")),
    ("sand", ("beach", "desert", "oasis")),
    ("rubber", ("gym",)),
    ("tiles", ("bathroom", "kitchen", "laboratory", "lab", "spa", "laundromat", "hospital", "clinic", "pharmacy")),
    ("carpet", ("bedroom", "nursery", "office", "conference")),
    ("asphalt", ("road", "street", "alley", "alleyway", "parking", "highway", "city", "gas station")),
    ("concrete", ("pavement", "sidewalk", "station", "platform", "warehouse", "garage", "industrial", "dock", "harbour",
                  "harbor", "pier", "hangar", "factory floor", "factory", "rooftop", "roof")),
    ("wood floor", ("room", "house", "cabin", "studio", "apartment", "cafe", "café", "bistro", "restaurant", "shop",
                    "store", "boutique", "hall", "bakery", "tavern", "attic")),
    ("stone", ("plaza", "courtyard", "castle", "temple", "cave", "cavern", "dungeon", "crypt", "smithy", "forge")),
    ("dirt", ("farm", "farmyard", "barnyard", "stable yard", "paddock", "dusty", "village", "campsite", "orchard",
              "trail", "planet", "rocky", "crater", "martian", "mars", "wasteland", "savannah", "savanna",
              "construction site", "building site", "quarry", "enclosure", "ranch", "arena")),
    ("grass", ("meadow", "park", "garden", "field", "backyard", "yard", "forest", "zoo", "airfield", "clearing",
               "glade", "wedding", "picnic", "golf")),
]


def detect_ground(text: str, indoor: bool) -> str:
    """A ground kind from :data:`GROUND_KINDS`: a word for the ground itself, else the setting's
    place word (the first one named, the opening sentence first), else wood floor indoors and
    grass outdoors."""
    text = without_media(text)
    sentences = re.split(r"[.!?]", text.lower())
    low = " " + " ".join(re.findall(r"[a-zé]+", text.lower())) + " "
    opening = len(" " + " ".join(re.findall(r"[a-zé]+", sentences[0])) + " ") if sentences else 0
    best: tuple[int, int, int, str] | None = None
    for explicit, table in ((0, _GROUND_MATERIALS), (1, _GROUND_PLACES)):
        for rank, (kind, words) in enumerate(table):
            for w in words:
                pos = low.find(" " + w + " ")
                if pos < 0:
                    continue
                # materials by their order of precedence; places by where the text names them
                key = (explicit, rank, pos, kind) if explicit == 0 else (explicit, int(pos >= opening), pos, kind)
                if best is None or key < best:
                    best = key
    if best is not None:
        return best[3]
    return "wood floor" if indoor else "grass"


#: Words that set a scene by open water: the water lies beyond the land the scene stands on. A pond
#: or a pool is a thing of the scene (it has a size and a place), not its setting; so is a stream a
#: bridge crosses, too narrow to be the water the scene lies by.
_WATER_PLACES = ("river", "riverside", "riverbank", "lake", "lakeside", "lakeshore", "sea", "seaside", "seafront",
                 "ocean", "harbour", "harbor", "harbourside", "bay", "canal", "towpath", "lagoon", "cove", "shore",
                 "shoreline", "beach", "coast", "quay", "quayside", "wharf", "waterfront", "marina", "fjord",
                 "estuary", "tideline")
#: A bank of a river, not a bank of money: "on the far bank", "along the banks", "the river bank" (a
#: robber runs from the bank, a guard stands on the bank's steps).
_BANK = re.compile(r"\b(?:on|along) the (?:\w+ )?banks?\b(?!\s+(?:steps|vault|counter|building|doors?|roof)\b)|"
                   r"\b(?:river|canal) ?banks?\b")
#: Water that is not open, by the words before and after its name: frozen or dry ("a frozen lake",
#: "the sea ice", "a dry river bed").
_NOT_OPEN_BEFORE = re.compile(r"\b(?:frozen|icy|iced|dry|dried)\s+(?:\w+\s+)?$")
_NOT_OPEN_AFTER = re.compile(r"^\s*(?:ice|bed)\b")


def detect_water(text: str, indoor: bool) -> bool:
    """Whether the scene lies by open water: an outdoor text whose words name a river, a lake,
    the sea, a harbour, a shore or a bank (:data:`_WATER_PLACES`). A water named frozen or dry
    anywhere makes the whole text's water so ("a frozen lake ... pine trees line the far
    shore"). A room has no water, whatever its windows look out on ("a captain's cabin ... sea
    charts")."""
    if indoor:
        return False
    low = " ".join(re.findall(r"[a-zé']+", without_media(text).lower()))
    named = list(re.finditer(r"\b(?:" + "|".join(_WATER_PLACES) + r")\b", low))
    if any(_NOT_OPEN_BEFORE.search(low[max(0, m.start() - 20) : m.start()]) or _NOT_OPEN_AFTER.search(low[m.end() :])
           for m in named):
        return False
    return bool(named) or bool(_BANK.search(low))


#: Places whose setting is a building: a scene "in a hangar" is an interior.
_INDOOR_PLACES = {"hangar", "warehouse", "factory", "garage", "workshop", "library", "museum", "tavern", "inn", "pub",
                  "attic", "basement", "cellar", "loft", "lobby", "hallway", "corridor", "chamber", "church",
                  "cathedral", "chapel", "temple", "dungeon", "cell", "crypt", "bunker", "vault", "gym", "spa", "bakery",
                  "salon", "theatre", "theater", "cinema", "ballroom", "lounge", "pantry", "diner", "restaurant",
                  "bar", "arcade", "mall", "station", "hospital", "clinic", "nursery", "school", "kitchen", "bedroom",
                  "barn", "house", "cottage", "cabin", "hut", "shed", "shack", "stable", "greenhouse", "farmhouse",
                  "teahouse", "coffeehouse", "bathhouse", "guesthouse", "alehouse", "playhouse", "parlour", "parlor"}  # fmt: skip


def _building(place: str) -> bool:
    """A place word whose setting is a building ("a hangar", "a cow shed", "a boathouse")."""
    head = place.split()[-1]
    return head in _INDOOR_PLACES or head.endswith("house")


#: A clause that looks out of the setting: the places it names are seen, not stood in ("a window
#: looking out on a ringed planet", "a view of the sea").
_VIEW = re.compile(r"\b(?:looking out|looks out|look out|overlooking|overlooks|views? (?:of|over|across|onto)|"
                   r"out of the windows?|through the windows?)\b[^.;,]*")
#: Words that put the scene inside something: a ceiling, the text opening "inside a ...", the
#: bridge or cockpit of a vessel, a cave (fresh batches: a smithy, a spaceship's bridge, a cave).
_INSIDE = re.compile(r"\bceilings?\b|^\W*(?:inside|in the interior of|within)\b|\binterior of\b|"
                     r"\b(?:bridge|cockpit|hold|cabin|galley|engine room) of (?:a|an|the|our|his|her|their)\b[^.;,]*"
                     r"\b(?:ship|spaceship|starship|spacecraft|vessel|submarine|airship|boat|yacht|station)\b")


def _is_indoor(categories: list[str], text: str, catalogue, places: list[str] = ()) -> bool:
    """Whether the scene stands inside (and so gets a room, docs/rooms.md): the objects' tags,
    the places the reader found, and place words vote, those of the opening sentence (where a
    text sets its scene: "A low-poly goblin cave.") twice; a ceiling, an opening "inside a ..."
    or the bridge of a ship weigh like a place; places only seen through a window do not count."""
    low = text.lower()
    if places and re.match(r"\W*inside\b", low):
        return True  # "Inside a horse stable at dawn, ...": the text says so, whatever stands there
    setting = _VIEW.sub(" ", low)
    opening = re.split(r"[.!?]", setting, maxsplit=1)[0]
    votes = 0
    for name in categories:
        tags = catalogue[name].tags
        votes += ("indoor" in tags) - ("outdoor" in tags)
    # a building the opening sentence stands in outweighs what stands there ("A cow shed at milking
    # time: four cows ..."); one named further on counts as one voice among the objects
    stood_in = re.split(r"\bwith\b", opening, maxsplit=1)[0]  # (not "a graveyard, with a chapel at the end")
    votes += sum(3 + 7 * (p in stood_in) for p in places if _building(p))
    votes += 3 * len(_INSIDE.findall(low))
    for word in ("room", "kitchen", "bedroom", "bathroom", "office", "classroom", "lab", "apartment", "studio",
                 "café", "cafe", "shop", "store", "boutique", "gallery", "hall", "interior", "indoors", "smithy",
                 "cave", "cavern"):
        votes += 2 * (bool(re.search(rf"\b{word}\b", setting)) + bool(re.search(rf"\b{word}\b", opening)))
    for word in ("street", "park", "garden", "square", "market", "beach", "forest", "yard", "outdoor", "harbour",
                 "harbor", "village", "desert", "planet", "courtyard", "playground", "campsite", "field"):
        votes -= 2 * (bool(re.search(rf"\b{word}\b", setting)) + bool(re.search(rf"\b{word}\b", opening)))
    return votes > 0
