"""The look of the scene as a whole: the named style, the ground kind and indoor-ness.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from scenewright.analysis.parser.vocabulary import load_vocabulary
from scenewright.core.colours import COLOUR_RE, palette_re
from scenewright.core.styles import load_looks, made_looks, media_heads, media_parts, named_colours, normalise
from scenewright.scene import DEFAULT_STYLE, MAX_STYLE_CHARS

#: Ground kinds the procedural ground textures understand.
GROUND_KINDS = (
    "wood floor", "tiles", "carpet", "concrete", "marble", "grass", "gravel", "cobblestone",
    "sand", "dirt", "snow", "metal deck", "stone", "rubber", "asphalt",
)  # fmt: skip


#: A verb of making (an adverb may come between) before "as", "like", "in", "into" or "from" ("knitted from
#: wool", "drawn entirely as"), "in the style of", or a clause opening "as" or "like": the words after it,
#: up to "of" or the clause's end, say what the picture is ("drawn as a Soviet constructivist poster",
#: "painted like an impressionist canvas", "rendered in cross-stitch", "in the style of a pulp magazine
#: cover", "A fishing village, as a woodblock print."). Verbs that also build or
#: film things say it only before "as" or "like" ("built as a tiny diorama", "shot as a tilt-shift photo"), or
#: "built" the material it is built from ("built from plastic toy bricks").
_MADE_AS = re.compile(
    r"\b(?:(?P<verb>drawn|rendered|painted|printed|done|made|sketched|woven|stitched|embroidered|etched|engraved|"
    r"carved|cut|shown|depicted|illustrated|imagined|pictured|styled|crafted|modelled|modeled|sculpted|knitted|"
    r"felted|dyed|glazed|inlaid|folded)\s+(?:\w+ly\s+)?(?:as|like|in|into|from|of)|"
    r"(?P<builds>built|shot|photographed|filmed|captured|cast|moulded|molded)\s+(?:as|like)|"
    r"(?P<built_from>built)\s+(?:\w+ly\s+)?(?:from|of|out\s+of)|"
    r"(?P<style_of>in\s+the\s+(?:style|manner)\s+of)|[,:;(]\s*(?:as|like))\s+"
    r"(?:(?:an?|the)\s+)?(?P<manner>(?:style|manner)\s+of\s+(?:(?:an?|the)\s+)?)?(?P<phrase>[^.,:;!?()]*)"
)
#: "as a ..." with no verb before it: the picture only when its phrase names a look ("A lavender farm as a
#: 1950s travel poster"; not "a porter dressed as a clown").
_AS = re.compile(r"\bas\s+(?:(?:an?|the)\s+)?(?P<phrase>[^.,:;!?()]*)")
#: A verb that puts the opening picture somewhere: "A painting of a ship hangs above the fireplace" is
#: a thing in the room, "A painting of a harbour at dawn." the scene's look.
_PLACED = re.compile(r"\b(?:is|are|hangs?|hung|sits?|stands?|leans?|rests?|lies|covers?|fills?|decorates?|"
                     r"dominates?|propped|pinned|taped|mounted)\b")
#: "Walls painted in pastel colours" name colours, not a medium; said of the whole picture ("A parade,
#: painted in loud Fauvist colours") they are its palette.
_COLOUR_NOUNS = {"colour", "colours", "color", "colors", "shade", "shades", "tone", "tones", "hue", "hues", "tints"}
#: Words that end a medium phrase: "a poster" in "a study with a poster" is a thing in it.
_PHRASE_ENDS = {"of", "with", "and", "or", "in", "on", "at", "by", "from", "near", "under", "above", "over", "behind",
                "beside", "for", "to", "where", "that", "which", "while", "as", "showing", "depicting", "featuring",
                "so", "like"}
_ARTICLES = {"a", "an", "the"}
#: The longest medium phrase read: "a two-colour risograph print", not a whole clause.
_MEDIUM_WORDS = 6
#: Words a clause of colours after the medium may hold besides them ("all gold leaf and lapis blue", "in flat
#: red, yellow and black shapes").
_PALETTE_FILLERS = {"and", "or", "with", "of", "a", "an", "the", "leaf", "touches", "flecks", "accents", "plus", "on",
                    "over", "against", "flat", "bold", "shapes", "blocks", "areas", "lines", "strokes", "washes",
                    "patches", *_COLOUR_NOUNS}
#: The palette after the medium, as its own clause: ", all gold leaf and lapis blue", ", in red and black", or
#: the list of colours going on (", yellow and black").
_PALETTE_AFTER = re.compile(r"\s*[,:;]\s*(?:(?:all|in|mostly|entirely)\s+)?([^.,:;!?()]*)")


@dataclass(frozen=True)
class _Medium:
    """A phrase that says what the picture is: its normalised words, the span of the text it is said in,
    its verb of making, whether it is said of the whole picture (opening the text, after a comma, "as
    a ..."), which a phrase said of one thing ("walls painted in pastel colours") is not, and whether it
    follows "in the style of", which says a picture whatever its words."""

    words: list[str]
    span: tuple[int, int]
    verb: str | None = None
    whole: bool = True
    style_of: bool = False


def _medium_phrases(media: list[_Medium]) -> list[tuple[str, str]]:
    """The phrases, each as written and with its plurals made singular ("in the style of old engravings",
    "drawn in crayons")."""
    phrases = []
    for medium in media:
        single = [w[:-1] if len(w) > 3 and w.endswith("s") and not w.endswith("ss") else w for w in medium.words]
        phrases.append((" ".join(medium.words), " ".join(single)))
    return phrases


def _media(text: str) -> list[_Medium]:
    """Each phrase that says what the picture is (:class:`_Medium`): after a verb of making (:data:`_MADE_AS`,
    the words up to the clause's end); after "as" when it names a look (:data:`_AS`); opening the text when
    it ends in a picture noun or a look's word ("A child's crayon drawing of a ...", "A needle-felted
    miniature: ..."; ``media`` in ``data/styles.json``) and its clause places nothing ("A painting of a ship
    hangs above the fireplace" is a thing of the scene), or its opening noun's "in ..." names a look ("A
    harbour in walnut and maple marquetry")."""
    low = text.lower()
    found = []
    for m in _MADE_AS.finditer(low):
        words, end = _noun_phrase(m["phrase"])
        opens = re.search(r"(?:^|[,.:;!?(])\s*$", low[: m.start()]) is not None  # a clause of its own
        style_of = bool(m["style_of"] or m["manner"])
        verb = normalise(m["verb"] or m["builds"] or m["built_from"] or "") or None
        span = (m.start("phrase"), m.start("phrase") + max(end, _medium_end(m["phrase"])))
        found.append(_Medium(words, span, verb, not verb or style_of or opens, style_of))
    for m in _AS.finditer(low):
        words, end = _noun_phrase(m["phrase"])
        head = _without_colours(words)  # a look's noun, or a picture noun with a look's word ("a stained-glass window")
        if (_names_a_look(head) or head[-1:] and head[-1] in media_heads() and _holds_a_look(head)) and all(
            m.start("phrase") != f.span[0] for f in found
        ):
            found.append(_Medium(words, (m.start("phrase"), m.start("phrase") + end)))
    clause = re.split(r"[.,:;!?()]|\s[-–—]\s", low, maxsplit=1)[0]
    start = re.match(r"^\W*(?:(?:an?|the)\s+)?", clause).end()
    opening, end = _noun_phrase(clause[start:], joins=("of", "from", "and"))  # its "in ..." comes next
    # ("A boy reads a comic book": an article inside, after no "of", opens the object of a verb)
    told = any(w in _ARTICLES and before not in ("of", "from", "and") for before, w in zip(opening, opening[1:]))
    if opening and not told and (opening[-1] in media_heads() or _names_a_look(opening)) and not _PLACED.search(clause):
        found.append(_Medium(opening, (0, len(clause.split(" of ")[0]))))
    look = _opening_look(opening)
    if look and not _PLACED.search(clause):
        found.append(_Medium(look, (start, start + len(" ".join(look)))))
    after = re.match(r"\s*in\s+(?:(?:an?|the)\s+)?", clause[start + end :])
    if opening and after:
        at = start + end + after.end()
        words, length = _noun_phrase(clause[at:])
        if _names_a_look(words):
            found.append(_Medium(words, (at, at + length)))
    # (a phrase of colours alone is no medium, "walls painted in pastel colours"; one that names a look
    # with its colours is: "printed as a two-colour silkscreen poster in hot pink and teal")
    return [f for f in found if f.words and _length(f.words) <= _MEDIUM_WORDS
            and (f.whole or not _says_colours(f.words) or _names_a_look(_without_colours(f.words)))]


#: Nouns an opening names a whole scene or picture by, besides place words ("An origami calligraphy class",
#: "Pointillist dots of yellow and violet").
_SCENE_NOUNS = {"scene", "class", "lesson", "seascape", "landscape", "cityscape", "world", "diorama", "tableau",
                "centre", "center", "show", "match", "game", "dots", "strokes", "brushstrokes"}  # fmt: skip


#: Looks' words besides made ("-ed") and painted ("-ist") ones that an opening names its whole setting in.
_OPENING_LOOKS = {"isometric", "origami", "dollhouse"}


def _opening_look(opening: list[str]) -> list[str]:
    """The look's word a text opens with when it describes the setting it names ("A knitted garden tea
    party", "An isometric war room", "A needle-felted lantern shop"; not "A knitted scarf lies on the
    bench" nor "A stained-glass window glows": things of the scene), else nothing."""
    places = load_vocabulary().places
    for look in load_looks().values():
        for w in look.styled:
            n = len(w.split())
            # (a made or painted look, not a kind of building or trade: "a gothic chapel", "a textile mill")
            made = w.endswith(("ed", "ist")) or w in _OPENING_LOOKS
            if made and opening[:n] == w.split() and any(x in places or x in _SCENE_NOUNS for x in opening[n : n + 3]):
                return opening[:n]
    return []


def _length(words: list[str]) -> int:
    """A medium phrase's length, its colours and the words joining them aside ("a batik cloth in indigo and
    ochre" is two words long)."""
    return sum(w not in {"and", "in", "on", "of", "from", *_ARTICLES} and not palette_re().fullmatch(w) for w in words)


def _says_a_medium(words: list[str]) -> bool:
    """Whether a phrase after a verb of making names colours, materials or a picture ("drawn in red", "knitted
    in wool", "sketched as a postcard"), not where a thing goes ("a cart, drawn into the yard")."""
    return _says_colours(words) or bool(named_colours(" ".join(words))) or words[-1] in media_heads()


def _says_colours(words: list[str]) -> bool:
    """Whether a phrase names colours as such ("in loud Fauvist colours", "in shades of blue")."""
    return any(w in _COLOUR_NOUNS for w in words)


def _medium_end(words: str) -> int:
    """Where the medium's own words end: its "of ..." is what it is made of ("a floor mosaic of tiny stone
    tiles"), any other phrase end goes back to the scene ("done in cross-stitch, with a tiled floor")."""
    ends = re.search(r"(?<![\w-])(?:" + "|".join(sorted(_PHRASE_ENDS - {"of"})) + r")(?![\w-])", words)
    return ends.start() if ends else len(words)


def without_media(text: str) -> str:
    """The text, lowercased, with what its picture is made of blanked out: "rendered as a floor mosaic
    of tiny stone tiles" says nothing of the ground the scene stands on."""
    low = text.lower()
    for medium in _media(text):
        start, end = medium.span
        low = low[:start] + " " * (end - start) + low[end:]
    return low


def _names_a_look(phrase: list[str]) -> bool:
    """Whether a phrase ends in a look's word ("a mezzotint", "a floor mosaic"): the picture's own noun, the
    colours it is in aside ("a propaganda poster in red and black")."""
    tail = f" {' '.join(_without_colours(phrase))}"
    return any(tail.endswith(f" {w}") for look in load_looks().values() for w in (*look.words, *look.styled))


def _without_colours(phrase: list[str]) -> list[str]:
    """A phrase without the "in ..." or "on ..." that ends it and says only its colours."""
    for at in range(len(phrase) - 1, 0, -1):
        if phrase[at] in ("in", "on"):
            tail = " ".join(phrase[at + 1 :])
            if palette_re().search(tail) and _only_colours(tail):
                return phrase[:at]
            break
    return phrase


def _only_colours(words: str) -> bool:
    """Whether words say colours and nothing else: filler words, and a word or two shading them ("all gold leaf
    and lapis blue", "faded reds and holly green")."""
    rest = palette_re().sub(" | ", normalise(words)).split()
    shading = [w for i, w in enumerate(rest) if w not in _PALETTE_FILLERS | {"|"}]
    return len(shading) <= 2 and all(rest.index(w) + 1 < len(rest) and rest[rest.index(w) + 1] == "|" for w in shading)


def _holds_a_look(phrase: list[str]) -> bool:
    """Whether a look's word is in a phrase ("a silk scarf in teal and saffron")."""
    padded = f" {' '.join(phrase)} "
    return any(f" {w} " in padded for look in load_looks().values() for w in (*look.words, *look.styled))


def _goes_on(out: list[str], word: str, rest: str, joins: tuple[str, ...]) -> bool:
    """Whether a word that ends a noun phrase goes on with the medium: a part's "of" or "from" ("a page of
    an illuminated manuscript", "shades of blue"), an "and", "in" or "on" before a colour, a material or a
    look's word ("walnut and maple marquetry", "a batik cloth in indigo and ochre", "cobalt blue on white
    porcelain"); ``joins`` the words of these that may go on."""
    if word not in joins:
        return False
    if not out:
        return False
    padded = f"{rest} "
    look_next = any(padded.startswith(f"{w} ") for look in load_looks().values() for w in (*look.words, *look.styled))
    if word in ("of", "from"):  # "a panel from a graphic novel", not "a quilted panel of an orchard"
        return out[-1] in media_parts() or out[-1] in _COLOUR_NOUNS or (out[-1] in media_heads() and look_next)
    # a word or two may shade the colours: "in faded reds and blues", "in deep sea greens"
    starts = [0, *(m.end() for m in re.finditer(" ", rest))][:3]
    return look_next or any(palette_re().match(rest, at) for at in starts)


def _noun_phrase(words: str, joins: tuple[str, ...] = ("of", "from", "and", "in", "on")) -> tuple[list[str], int]:
    """The normalised words before the first that ends a noun phrase ("of", "with", "and", "on" ...;
    not inside a hyphened word: "a blue-and-white tile panel"; :func:`_goes_on` where the medium goes
    on over one of ``joins``), and where they end in ``words``."""
    out: list[str] = []
    tokens = [(m.end(), normalise(m[0])) for m in re.finditer(r"\S+", words)]
    end = 0
    for i, (stop, token) in enumerate(tokens):
        if token in _PHRASE_ENDS:
            rest = " ".join(t for _, t in tokens[i + 1 :]).split()
            rest = " ".join(rest[1:] if rest and rest[0] in _ARTICLES else rest)
            if not _goes_on(out, token, rest, joins):
                break
        out += token.split()
        end = stop
    return out, end


def _palette(text: str, media: list[_Medium]) -> list[str]:
    """The colours the picture is named in: those of its medium phrases that name a look or are said of the
    whole picture, and of an "all ..." or "in ..." after one that holds only colours ("…, all gold leaf and
    lapis blue"); each as its words ("cobalt blue", "walnut")."""
    named: list[str] = []
    for medium in media:
        phrases, end = [_common_words(text, *medium.span)], medium.span[1]
        while (after := _PALETTE_AFTER.match(text, end)) and palette_re().search(after[1].lower()) and _only_colours(
            after[1]
        ):
            phrases.append(_common_words(text, *after.span(1)))
            end = after.end()
        named += [words for phrase in phrases for words, _ in named_colours(phrase) if words not in named]
    # one material alone says what the picture is made of ("a mosaic of tiny stone tiles"), not its colours
    return named if len(named) > 1 or any(COLOUR_RE.search(words) for words in named) else []


def _common_words(text: str, start: int, end: int) -> str:
    """The text from ``start`` to ``end`` with its names blanked: a capital inside a sentence makes "Golden"
    in "a Dutch Golden Age oil painting" part of a name, no colour."""
    return re.sub(r"(?<=[\w,;:] )[A-Z][\w-]*", lambda m: "|".ljust(len(m[0])), text)[start:end].lower()


def detect_style(text: str, default: str = DEFAULT_STYLE) -> str:
    """The look the text names ("cartoon-style", "Cyberpunk.", "a voxel-art quarry", "A linocut print
    of ...", "drawn as a blueprint"; the words are ``data/styles.json``'s), else the look a verb of making
    said of the whole picture makes ("…, drawn in red"), else ``default``; with the colours its
    medium is named in ("textile in indigo and ochre", :func:`_palette`) as far as a style's name holds them.

    A word followed by "style" wins over a word used in passing; otherwise the first named. Words
    that also describe things ("gothic", "poster", "mosaic") name the look only before "style" or in
    the phrase that says what the picture is (:func:`_media`)."""
    low = f" {normalise(text)} "
    found = _media(text)
    media = [(low.find(f" {p} "), f" {form} ") for p, single in _medium_phrases(found) for form in {p, single}]
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
    made = next((made_looks()[m.verb] for m in found if m.whole and m.verb in made_looks() and _says_a_medium(m.words)),
                None)  # fmt: skip
    name = best[3] if best else made or default
    # a phrase that names no look gives colours after "in the style of" or when only a picture is made so
    # ("…, drawn in red"), not paint or weaving, which make things too ("A cottage, painted in white, ..."),
    # nor a bare ", as" ("A beach hut, as blue as the sea")
    said = [m for m in found if _holds_a_look(m.words) or m.style_of or (m.whole and m.verb in made_looks())]
    colours = _palette(text, said)
    while colours and len(f"{name} in {' and '.join(colours)}") > MAX_STYLE_CHARS:
        colours.pop()
    return f"{name} in {' and '.join(colours)}" if colours else name


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
    ("wood floor", ("wooden floor", "wood floor", "hardwood", "parquet", "floorboards", "wooden deck", "plank",
                    "ship deck", "ship s deck", "quarterdeck", "poop deck")),
    ("stone", ("stone floor", "flagstone", "flagstones", "paved")),
    ("dirt", ("dirt", "mud", "muddy", "soil")),
    ("grass", ("grass", "grassy", "lawn", "turf", "outfield", "cricket", "croquet", "bowling green", "playing field",
               "football pitch", "rugby pitch", "village green", "on a green", "on the green")),
    # (games played on grass, and a village's green: the ground of the village too)
]
#: Words for places, and the ground each has: the setting's own word decides (the first one the
#: description names, its opening sentence first), so "a savannah enclosure at a city zoo" is
#: dirt, not the city's asphalt, and a landing pad further on does not floor a construction site.
#: Ground kinds only a room's floor has: a place word of an outdoor scene does not give them.
_FLOORS = ("wood floor", "tiles", "carpet", "rubber")
#: Ground kinds of the open air: indoors only a word that names the floor gives them ("a dirt
#: floor", "a sand-covered floor"), never the place ("a village hall", "an esports arena", "an
#: origami wedding in a banquet hall") nor the weather ("a winter evening in the workshop").
_OPEN_GROUNDS = ("grass", "dirt", "sand", "snow")
_FLOOR_NOUNS = (" floor ", " floors ", " ground ", " covered floor ")
_GROUND_PLACES = [
    ("metal deck", ("landing pad", "spaceport", "space station", "starship", "spaceship", "space ship", "submarine",
                    "engine room", "airlock")),
    ("sand", ("beach", "desert", "oasis")),
    ("snow", ("comet", "glacier", "ice field", "ice sheet", "ice floe", "arctic", "antarctic", "polar", "tundra")),
    ("rubber", ("gym",)),
    ("tiles", ("bathroom", "kitchen", "laboratory", "lab", "spa", "laundromat", "hospital", "clinic", "pharmacy",
               "post office")),
    ("carpet", ("bedroom", "nursery", "office", "conference")),
    ("asphalt", ("road", "street", "alley", "alleyway", "parking", "highway", "city", "gas station")),
    ("concrete", ("pavement", "sidewalk", "station", "platform", "warehouse", "garage", "industrial", "dock", "harbour",
                  "harbor", "pier", "hangar", "factory floor", "factory", "rooftop", "roof")),
    ("wood floor", ("room", "house", "cabin", "studio", "apartment", "cafe", "café", "bistro", "restaurant", "shop",
                    "store", "boutique", "hall", "bakery", "tavern", "attic")),
    ("stone", ("plaza", "courtyard", "castle", "temple", "cave", "cavern", "dungeon", "crypt", "smithy", "forge")),
    ("dirt", ("farm", "farmyard", "barnyard", "stable yard", "paddock", "dusty", "village", "campsite", "orchard",
              "trail", "planet", "asteroid", "regolith", "rocky", "crater", "martian", "mars", "wasteland", "savannah", "savanna",
              "construction site", "building site", "quarry", "enclosure", "ranch", "arena")),
    ("grass", ("meadow", "park", "garden", "field", "backyard", "yard", "forest", "zoo", "airfield", "clearing",
               "glade", "wedding", "picnic", "golf", "fete")),
]


#: Place words for a room of something named after them: "the control room of a submarine" is floored as the submarine.
_PART_ROOMS = frozenset({"room", "rooms", "hall", "cabin"})


def _owner_floors(low: str, end: int) -> bool:
    """Whether the words from ``end`` are "of" and, within six words, a place the ground table
    knows ("room of an old diesel submarine")."""
    if not low.startswith(" of ", end):
        return False
    owner = " " + " ".join(low[end + 4 :].split()[:6]) + " "
    return any(f" {w} " in owner for _, words in _GROUND_PLACES for w in words)


def detect_ground(text: str, indoor: bool) -> str:
    """A ground kind from :data:`GROUND_KINDS`: a word for the ground itself, else the setting's
    place word (the first one named, the opening sentence first; a room "of" something gives way
    to what it is a room of), else wood floor indoors and grass outdoors. Indoors the open air's
    grounds (:data:`_OPEN_GROUNDS`) come only from words for the floor."""
    text = without_media(text)
    sentences = re.split(r"[.!?]", text.lower())
    low = " " + " ".join(re.findall(r"[a-zé]+", text.lower())) + " "
    opening = len(" " + " ".join(re.findall(r"[a-zé]+", sentences[0])) + " ") if sentences else 0
    best: tuple[int, int, int, str] | None = None
    for explicit, table in ((0, _GROUND_MATERIALS), (1, _GROUND_PLACES)):
        for rank, (kind, words) in enumerate(table):
            if explicit and not indoor and kind in _FLOORS:
                continue  # outside "a small bakery on a village street": the street's ground, not its floor
            if explicit and indoor and kind in _OPEN_GROUNDS:
                continue  # in "a village hall" the village gives no floor
            for w in words:
                pos = low.find(" " + w + " ")
                if pos < 0 or (explicit and w in _PART_ROOMS and _owner_floors(low, pos + len(w) + 1)):
                    continue  # ("the control room of a submarine": the submarine's floor)
                if indoor and kind in _OPEN_GROUNDS and not low.startswith(_FLOOR_NOUNS, pos + len(w) + 1):
                    continue  # "snow falls outside the workshop" floors nothing; "a dirt floor" does
                # materials by their order of precedence; places by where the text names them
                key = (explicit, rank, pos, kind) if explicit == 0 else (explicit, int(pos >= opening), pos, kind)
                if best is None or key < best:
                    best = key
    if best is not None:
        return best[3]
    return "wood floor" if indoor else "grass"


#: Words that set a scene by open water: the water lies beyond the land the scene stands on (a pier
#: or a jetty reaches out into it, a boat is moored on it). A pond
#: or a pool is a thing of the scene (it has a size and a place), not its setting; so is a stream a
#: bridge crosses, too narrow to be the water the scene lies by.
_WATER_PLACES = ("river", "riverside", "riverbank", "lake", "lakeside", "lakeshore", "sea", "seaside", "seafront",
                 "ocean", "harbour", "harbor", "harbourside", "bay", "canal", "towpath", "lagoon", "cove", "shore",
                 "shoreline", "beach", "coast", "quay", "quayside", "wharf", "waterfront", "marina", "fjord",
                 "estuary", "tideline", "pier", "jetty", "moored")
#: The water itself among those words (the rest are land by it, which may be icy or dry itself).
_WATERS = frozenset({"river", "lake", "sea", "ocean", "harbour", "harbor", "bay", "canal", "lagoon", "cove", "fjord",
                     "estuary"})
#: Words that set the scene under the water: its floor is the ground, and nothing lies by a shore.
_UNDERWATER = re.compile(r"\b(?:sea ?floor|seabed|ocean floor|underwater|under the (?:sea|water|waves))\b")
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
    the sea, a harbour, a shore or a bank (:data:`_WATER_PLACES`), and not the sea floor. A water
    named frozen or dry anywhere makes the whole text's water so ("a frozen lake ... pine trees
    line the far shore"). A room has no water, whatever its windows look out on ("a captain's
    cabin ... sea charts")."""
    if indoor:
        return False
    low = " ".join(re.findall(r"[a-zé']+", without_media(text).lower()))
    if _UNDERWATER.search(low):
        return False  # "the ruins of a sunken city on the sea floor": under the water, no shore to lie by
    named = list(re.finditer(r"\b(?:" + "|".join(_WATER_PLACES) + r")\b", low))
    # (what is frozen is the water: "an icy shore at the edge of the sea" lies by open water)
    if any(_NOT_OPEN_BEFORE.search(low[max(0, m.start() - 20) : m.start()]) or _NOT_OPEN_AFTER.search(low[m.end() :])
           for m in named if m.group(0) in _WATERS):
        return False
    return bool(named) or bool(_BANK.search(low))


#: A bay that is a room of a ship, a station or a garage, not water: "a repair bay", "the troop bay".
_ROOM_BAY = (r"(?:repair|loading|troop|medical|med|maintenance|launch|shuttle|service|storage|bomb|drone|mech|"
             r"vehicle|assembly|cargo|docking|hangar|sick|engine|weapons|equipment|landing|hydroponics?) bay")
#: Places whose setting is a building: a scene "in a hangar" is an interior.
_INDOOR_PLACES = {"soundstage", "carriage", "hangar", "warehouse", "factory", "garage", "workshop", "library", "museum", "tavern", "inn", "pub",
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


#: Open land a building can stand in: an opening that sets its building there looks at it from outside
#: as often as from inside.
_OPEN_LAND = ("desert", "field", "fields", "forest", "woods", "hills", "mountains", "meadow", "prairie", "steppe",
              "savannah", "tundra", "jungle", "countryside", "dunes", "wilderness", "moor", "moors", "valley")


#: What each of several buildings standing among the objects weighs against an indoor setting.
_STANDING_BUILDING_VOTES = 5
#: A room, also one a closed compound names ("a playroom", "the boardroom"; no mushroom, no broom).
_ROOM_WORD = re.compile(r"\b(?!(?:mush|b)rooms?\b)\w*rooms?\b")


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
    # buildings that stand in the scene are seen from outside ("three red huts stand on the snow"); one
    # may be the setting itself ("the winter quarters, a big barn with sawdust on the floor")
    buildings = sum(catalogue[name].shape in ("house", "building") and catalogue[name].size[2] >= 2.5 for name in categories)
    votes -= _STANDING_BUILDING_VOTES * buildings * (buildings > 1)
    # a building the opening sentence stands in outweighs what stands there ("A cow shed at milking
    # time: four cows ..."); one named further on counts as one voice among the objects
    stood_in = re.split(r"\bwith\b", opening, maxsplit=1)[0]  # (not "a graveyard, with a chapel at the end")
    # (a building set in open land is seen from outside as often: "a roadside diner in the desert")
    landscape = re.search(rf"\b(?:in|on|at)\s+(?:the|a|an)\s+(?:\w+\s+)?(?:{'|'.join(_OPEN_LAND)})\b", stood_in)
    votes += sum(3 + 7 * (p in stood_in and not landscape) for p in places if _building(p))
    votes += 3 * len(_INSIDE.findall(low))
    votes += 2 * (bool(_ROOM_WORD.search(setting)) + bool(_ROOM_WORD.search(opening)))  # "a playroom", "a tearoom"
    for word in ("kitchen", "bedroom", "bathroom", "office", "classroom", "lab", "apartment", "studio", "café",
                 "cafe", "shop", "store", "boutique", "gallery", "hall", "interior", "indoors", "smithy", "forge",
                 "workshop", "cave", "cavern", _ROOM_BAY, "terminal", "departure lounge", "airport gate",
                 "boarding gate"):
        votes += 2 * (bool(re.search(rf"\b{word}\b", setting)) + bool(re.search(rf"\b{word}\b", opening)))
    for word in ("street", "park", "garden", "square", "market", "beach", "forest", "yard", "outdoor", "harbour",
                 "harbor", "village", "desert", "planet", "courtyard", "playground", "campsite", "field", "alley",
                 "alleyway", "roadside", "meadow", "orchard", "hillside", "riverbank", "shore", "seashore", "lakeshore",
                 "dunes"):
        votes -= 2 * (bool(re.search(rf"\b{word}\b", setting)) + bool(re.search(rf"\b{word}\b", opening)))
    return votes > 0
