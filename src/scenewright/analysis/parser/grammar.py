"""The tables the reader's parts share: phrase kinds, shapes and roles its rules ask about.

Closed classes of English words live in :mod:`words`; these say what the reader does with a
phrase kind or a kind of thing.
"""

from __future__ import annotations

from scenewright.analysis.parser.words import _OWNER_PRONOUNS

#: Phrases that place a group in a formation rather than by a target.
_FORMATIONS = ("row", "rows", "stack", "circle")
#: Quantity nouns that set their things out in a formation ("a row of stalls", "two rows of chairs").
_FORMATION_NOUNS = {"row": "row", "line": "row", "rows": "rows", "lines": "rows", "stack": "stack", "pile": "stack",
                    "heap": "stack", "stacks": "stack", "piles": "stack", "heaps": "stack", "ring": "circle",
                    "circle": "circle"}  # fmt: skip
#: Phrase kinds that, with no object after them, name a part of the room ("along the back wall").
_PLACE_KINDS = {"centre of": "anchor centre", "along": None, "leaning on": None, "foot of": None, "at": None,
                "end of": None, "covering": None}  # fmt: skip
#: Phrase kinds that place a thing on the ground beside another (not on it, not above it).
_GROUND_KINDS = ("left of", "right of", "in front of", "behind", "side of", "near", "far", "left", "right")
#: Sides facing each other across a thing: "it" after one of them names the thing the other placed by
#: ("a lamp right of the sofa, a plant left of it"; "a robot behind the counter, colonists in front of
#: it"). Not behind after in front of: "a cat sits in front of the fire, and a dog lies behind it" is
#: the cat's back.
_OPPOSITE_SIDES = {"in front of": "behind", "left of": "right of", "right of": "left of"}
#: Besides those of the ground, phrase kinds that place a person rather than what they have in hand
#: ("reads a book on the bench", "eats a sandwich at the table").
_HOLDER_KINDS = ("on", "at", "in", "between", "under")
#: Phrase kinds read as one of the scene's relations whatever they join ("benches along the fence"
#: stand by it, parallel to it on either face, not off one of its ends as "side of" would put them;
#: one who "talks to" someone stands with them, as the annotated sets read it, not turned to them).
_KIND_RELATION = {"left": "left of", "right": "right of", "flank elliptic": "flank", "above elliptic": "above",
                  "hanging from": "above", "leaning on": "side of", "along": "near", "talking to": "near"}  # fmt: skip
#: Phrase kinds that place their target by the thing before them ("a desk flanked by two lamps",
#: "a snowmobile towing a sled": the sled behind it; "passengers, followed by porters": the porters
#: behind them), and the relation the target gets.
_REVERSED = {"flanked by": "flank", "surrounded by": "around", "near by": "near", "on by": "on", "towing": "behind",
             "followed by": "behind"}  # fmt: skip
#: Seat shapes: what is "at" a desk or a table faces it from the front.
_SEATS = ("chair", "office_chair", "stool", "armchair", "bench", "sofa")
#: m, the height and the longest side at most of a makeshift seat (an upturned bucket, a hay bale, a
#: sledge): a person sits or lies on it where they are placed, it comes along.
_MAKESHIFT_HEIGHT, _MAKESHIFT_LENGTH = 1.0, 2.5

#: After these, a phrase right after the target places the target: "a lamp on a table left of the
#: sofa", "astronauts beside a lab bench to the right of the console", "sniffs at a cooler near the
#: truck", "dozes in an armchair by the fire" (the armchair is by the fire), "a chandelier hangs above
#: the table in front of the fireplace" (the table is), "lanterns hang from the branches of a tree
#: behind the chairs" (the tree is).
_CHAIN_KINDS = ("on", "on top", "near", "around", "side of", "at", "in", "from", "above", "over", "hanging from",
                "on a carrier", "driving", "covering")  # fmt: skip
#: Parts of a thing one stands on: "at" one is on the thing ("at its top", "at its prow", "at the stern").
_STANDING_PARTS = ("top", "roof", "rooftop", "deck", "prow", "bow", "stern")
#: Parts of a vehicle one steers it by: "at" one is on the vehicle ("a woman at the wheel").
_DRIVING_PARTS = ("wheel", "helm", "tiller")
#: Sides of a thing named by a possessive ("against its side"): the owner places.
_OWNER_PARTS = ("side", "sides", "front", "back", "top", "end", "edge", "base", "foot")
#: "Piled with" or "covered in" on a cart, a stall, a shelf or anything with a top is a load of things
#: standing on it when they are this big or bigger ("a cart piled with suitcases", "a desk covered in
#: monitors", "a table covered with glass flasks", "a workbench covered in clay tools"); smaller ones
#: ("piled with apples", "covered in crumbs") stay its contents, and so does what a thing is "filled
#: with" ("shelves filled with boxes and bottles": its stock). Shelves draw their own stock, so only
#: things of the larger size stand on them as objects ("shelves packed with sacks", not "a bookshelf
#: packed with paperbacks").
_LOADS = {("piled", "with"), ("stacked", "with"), ("heaped", "with"), ("covered", "in"), ("covered", "with"),
          ("packed", "with"), ("laden", "with"), ("loaded", "with"), ("lined", "with"), ("stocked", "with"),
          ("crammed", "with")}  # fmt: skip
_LOAD_HOSTS = ("cart", "truck", "table", "round_table", "desk", "counter", "bookshelf", "shop_shelf", "market_stall",
               "boat")  # fmt: skip
_LOAD_SIZE = 0.15
_SHELF_LOAD_SIZE = 0.3
#: Things that show what follows their "of", even a definite one ("a statue of the king").
_DEPICTIONS = ("statue", "hologram", "picture_frame", "sign", "billboard", "panel")
#: Flat holders whose "of" things stand on them as objects ("a tray of bottles", "a pallet of tires").
_FLAT_HOLDERS = ("plate", "pallet")
#: Shapes that hold what they hold inside, out of the layout ("a greenhouse holds tomato plants").
_ENCLOSURES = ("house", "building", "tent", "kiosk")
#: What has the parts of a building (a roof, a door, a porch): enclosures, and stalls under their roof
#: (a stall's only when the sentence names it: "the roof" of a hall is no stall's).
_ROOFED = (*_ENCLOSURES, "market_stall")
#: m, an enclosure lower than this is an animal's hutch or kennel, no building one goes into.
_HUTCH_HEIGHT = 1.5
#: m, a thing whose top is narrower than this (a post, a pole) holds only what hangs from it.
_NARROW_TOP = 0.3
#: Where a hung thing hangs from indoors.
_CEILING_WORDS = ("ceiling", "ceilings", "beam", "beams", "rafter", "rafters")
#: m, the least height of such a thing standing on the floor: a person sees all of themselves in it.
_STANDING_HEIGHT = 1.6
#: What a thing set down "on the floor" stands on: the ground itself, no host.
_FLOOR_WORDS = ("floor", "floorboards", "ground", "deck")
#: Vehicles with a roof and doors of their own.
_ROOFED_VEHICLES = ("car", "truck", "bus", "vehicle")
#: Parts of a building that place a thing by the building itself when nothing else is named.
_BUILDING_PARTS = ("roof", "rooftop", "porch", "step", "doorstep", "chimney", "eave", "gable", "veranda", "facade",
                   "door", "doorway", "balcony", "entrance", "gateway")
#: Parts of a building one stands *in* at its edge, outside it: by the building ("in the doorway of his shop").
_THRESHOLDS = ("door", "doorway", "entrance", "gateway")
#: Carriers anything smaller is on when it is *in* them ("in the tub", "in the canoe", "a broom in the
#: bucket"); a person or an animal is on every kind of carrier it is in ("fans in the stand"), a
#: guessed structure only when its name is listed (one in a dome is inside it).
_VESSEL_KINDS = ("seats", "vehicles", "containers")
#: Carrier kinds a person sits, rides or stands on, and never has in hand ("rows with a canoe").
_RIDDEN = ("seats", "vehicles", "mounts", "perches")
#: What a thing is mounted on as a part of it ("lanterns on tall poles"), when it is one of the
#: ``_POLE_BORNE`` (a flag, a lantern, a sign, a flat board such as a windsock or a banner); a mast is
#: a structure of its own, and so is the pole a dish or a camera stands on.
_MOUNTS = ("pole", "stick", "stake", "spike")
#: What a thing hangs by, part of it when it "hangs from" one ("a lantern hangs from a chain above the anvil").
_HANGERS = ("chain", "rope", "cord", "string", "wire", "cable", "thread", "ribbon", "strap")
_POLE_BORNE = ("flagpole", "lantern", "sign", "billboard", "menu_board", "torch", "panel")
#: Verbs that join a subject to what it is, not to a thing it acts on.
_COPULAS = ("is", "are", "was", "were", "be", "has", "have", "had", "seems", "looks")
#: A perch no taller than this, and this many times a thing's footprint, is a platform whose middle
#: the thing stands on ("a throne in the centre of the stage").
_PLATFORM_HEIGHT, _PLATFORM_AREA = 3.5, 4.0
#: Height (m) at most of a host that a small thing "over" it sits on ("a pot over the fire"); over
#: a taller one (a table) it hangs above.
_LOW_HOST = 1.0
#: m, the depth at most of a flat standing board (a sign, a panel, a curtain) that may as well hang on a wall.
_FLAT_DEPTH = 0.15
#: Pronouns that name a person or an animal ("someone": the owner of a body part no possessive
#: names, "a glass in one hand").
_PERSONAL = ("him", "her", "himself", "herself", "someone")
#: Possessives of people and the pronoun that names their owner ("at his feet" → him).
_PERSON_POSSESSIVES = {"his": "him", "her": "her", "their": "them living", "my": "him", "your": "him"}
#: The longest side (m) of a thing a person has in hand when the text says "with" ("a wheel gun").
_HANDHELD_SIZE = 1.1
#: Room (m³, of its box) a thing takes at most to be hand-sized: what a person has in hand while
#: doing something with it ("plays a guitar", "inspects a lantern"); a bigger thing they could
#: carry (a crate, a barrel, a cauldron) is worked on where it stands ("cleans a barrel": by it)
#: unless a verb of carrying takes it up ("carries a crate", "two men haul a trunk").
_HAND_VOLUME = 0.06
#: Room (m³, of its box) at most of a thing longer than ``_HANDHELD_SIZE`` that a person can still
#: carry (a ladder, a sign, a sled); what a person holds or grips that is bigger (a sofa, a
#: railing) they stand by.
_CARRY_VOLUME = 0.25
#: The longest side (m) of a tool a person works with in hand ("a long paddle", "a telescope").
_TOOL_SIZE = 1.6
#: What one person works at alone: people "at easels" have one each ("at tables" may share them).
_ONE_AT_A_TIME = frozenset({"easel", "lectern", "school_desk", "desk", "monitor"})
#: Depth (m) at most of a board or a frame that hangs or leans rather than stands.
_THIN = 0.12
#: Words that open a relative clause about the noun before them.
_RELATIVES = ("that", "which", "who")
#: Phrase kinds that name a side of what their possessive names ("to her left") and its relation.
_OWN_SIDES = {"its left": "left of", "its right": "right of", "its foot": "foot of"}
#: The pronoun a possessive in such a phrase stands for.
_POSSESSED = {**_OWNER_PRONOUNS, **_PERSON_POSSESSIVES}
#: Categories and shapes of living things ("him", "her" name one of them).
_LIVING = frozenset({"figure", "animal", "bird", "robot"})

#: No phrase makes more objects than this ("a million chairs"): the object limit then refuses the text.
MAX_COUNT = 10_000
#: Words that say which of a thing's parts a phrase names ("the front bumper", "the rear wheel").
_SIDE_WORDS = frozenset({"front", "rear", "back", "left", "right", "near", "far", "upper", "lower", "top", "bottom"})
