"""Shape families for things the catalogue does not know: the words that call each one.

An unknown noun ("camel", "fuel tank", "street musician") gets the family its words name.
The same table serves the name → shape keywords of the mesh backend (so a remote-model
object named "camel" also gets the animal) and the ``generic`` fallback (so a catalogue
entry filed under ``generic``, such as a horse, still gets its family).
"""

from __future__ import annotations

import re
from collections.abc import Callable

from scenewright.procedural.builder import Model
from scenewright.procedural.shapes import creatures, machines, structures, vehicles

#: Family → words of names that belong to it (singular; plurals match too).
FAMILY_WORDS: dict[str, tuple[str, ...]] = {
    "animal": (
        "animal", "camel", "dromedary", "llama", "alpaca", "giraffe", "elephant", "mammoth", "rhino", "rhinoceros", "hippo",
        "hippopotamus", "pig", "piglet", "hog", "boar", "sheep", "lamb", "ram", "goat", "cow", "bull", "ox", "oxen", "cattle",
        "calf", "bison", "buffalo", "yak", "horse", "pony", "donkey", "mule", "zebra", "unicorn", "deer", "reindeer", "elk",
        "moose", "stag", "antelope", "gazelle", "lion", "lioness", "tiger", "leopard", "cheetah", "panther", "jaguar", "puma",
        "bear", "panda", "fox", "wolf", "coyote", "rabbit", "bunny", "hare", "mouse", "rat", "hamster", "squirrel", "cat",
        "kitten", "dog", "puppy", "hound", "poodle", "dragon", "wyvern", "dinosaur", "t-rex", "tyrannosaurus", "raptor",
        "stegosaurus", "triceratops", "brontosaurus", "diplodocus", "livestock", "beast", "creature", "monster", "fish", "koi",
        "goldfish", "carp", "shark", "dolphin", "whale",
    ),
    "bird": (
        "bird", "parrot", "macaw", "duck", "chicken", "hen", "rooster", "owl", "pigeon", "dove", "penguin", "flamingo", "swan",
        "goose", "eagle", "hawk", "falcon", "vulture", "crow", "raven", "seagull", "gull", "heron", "stork", "ostrich", "emu",
        "peacock", "turkey", "sparrow", "robin",
    ),
    "figure": (
        "person", "people", "man", "woman", "boy", "girl", "child", "kid", "musician", "busker", "guitarist", "violinist",
        "drummer", "singer", "pianist", "trumpeter", "saxophonist", "accordionist", "fiddler", "bard", "knight", "warrior",
        "wizard", "witch", "sorcerer", "mage", "monk", "priest", "chef", "cook", "baker", "astronaut", "cosmonaut", "alien",
        "martian", "scarecrow", "mannequin", "dress form", "guard", "soldier", "police officer", "policeman", "vendor",
        "shopkeeper", "merchant", "farmer", "worker", "customer", "tourist", "pedestrian", "dancer", "juggler", "clown",
        "pirate", "sailor", "fisherman", "doctor", "nurse", "scientist", "teacher", "student", "player", "figure", "villager",
        "rider", "traveller", "traveler", "king", "queen", "princess", "prince",
    ),
    "machine": (
        "machine", "arcade", "arcade cabinet", "pinball", "jukebox", "slot machine", "console", "terminal", "control panel",
        "control desk", "switchboard", "generator", "engine", "motor", "pump", "turbine", "compressor", "printer", "3d printer",
        "copier", "photocopier", "washing machine", "washer", "dryer", "dishwasher", "server", "server rack", "mainframe",
        "supercomputer", "dynamo", "contraption", "apparatus", "mechanism",
    ),
    "tank": (
        "tank", "fuel tank", "oil tank", "gas tank", "water tank", "propane tank", "tanker", "silo", "grain silo", "water tower",
        "boiler", "water heater", "cauldron", "cistern", "vat", "aquarium", "fish tank", "terrarium", "gas cylinder",
        # a barrel lying on its mount: a cannon's shape, not a car's
        "cannon", "howitzer", "mortar",
    ),
    "structure": (
        "ferris wheel", "big wheel", "observation wheel", "crane", "tower crane", "carousel", "merry-go-round", "stage",
        "bandstand", "scaffold", "scaffolding", "gantry", "truss", "rig", "roller coaster", "structure",
    ),
    "panel": (
        "panel", "solar panel", "notice board", "noticeboard", "bulletin board", "corkboard", "banner", "tapestry",
        "projection screen", "video wall", "display", "hologram", "board", "placard", "easel",
    ),
    "container": (
        "container", "cardboard box", "box", "trunk", "footlocker", "suitcase", "luggage", "sack", "sandbag", "bag", "basket",
        "hamper", "coffer", "bin", "parcel", "package",
    ),
    "tool": (
        "tool", "anvil", "hammer", "axe", "hatchet", "mallet", "sledgehammer", "pickaxe", "wrench", "spanner", "toolbox",
        "tool box", "toolkit", "gadget", "device", "remote", "walkie-talkie", "detector", "calculator",
    ),
    "vehicle": (
        "vehicle", "tractor", "bulldozer", "harvester", "forklift", "golf cart", "buggy", "go-kart", "kart", "rickshaw",
        "army tank", "battle tank", "military tank", "panzer", "locomotive", "train", "steam engine", "carriage", "chariot",
        "spaceship", "spacecraft", "starship", "drone", "quadcopter", "jet", "airplane", "plane", "aircraft", "ufo",
        "helicopter", "jeep", "suv", "pickup", "minivan", "ambulance", "fire engine", "police car", "limousine",
        "hot air balloon",
    ),
}

FAMILIES: dict[str, Callable[[Model], None]] = {
    **{name: getattr(creatures, name) for name in ("animal", "bird", "figure")},
    **machines.SHAPES, **structures.SHAPES, "vehicle": vehicles.vehicle,
}
assert set(FAMILIES) == set(FAMILY_WORDS)

_WORD_FAMILY = {word: family for family, words in FAMILY_WORDS.items() for word in words}
_FAMILY_RE = re.compile(r"\b(%s)(?:e?s)?$" % "|".join(sorted(map(re.escape, _WORD_FAMILY), key=len, reverse=True)))
#: Words after which the rest of a name describes, not names: "man with a guitar".
_CLAUSE_RE = re.compile(r"\s+\b(?:with|holding|carrying|wearing|riding|in|on|at|near|beside|by|from)\b.*$")
#: Nouns for a depiction of the thing before them: "dragon statue" shows a dragon.
_DEPICTIONS = {"statue", "sculpture", "figurine", "skeleton", "fossil", "toy", "replica", "plush", "plushie", "carving",
               "bust", "effigy", "monument"}


def family_of(name: str) -> str | None:
    """The family the name's head noun calls, or ``None``: the head is the last word before
    any "with ..." clause, past words for a depiction ("dragon statue" → animal); a family
    word elsewhere in the name is a modifier ("horse cart", "queen bed", "hot dog stand")."""
    text = _CLAUSE_RE.sub("", " ".join(name.lower().replace("_", " ").split()))
    words = text.split()
    while len(words) > 1 and words[-1].rstrip("s") in _DEPICTIONS | {d.rstrip("s") for d in _DEPICTIONS}:
        words.pop()
    match = _FAMILY_RE.search(" ".join(words))
    return _WORD_FAMILY[match.group(1)] if match else None
