"""The small word tables of the reader: counts, determiners, stop words, units, verbs.

They are the closed classes of English the rules lean on; the open classes (things, relation
phrases) live in data files (``catalogue.json``, ``relation_phrases.json``, ``vocabulary.json``).
"""

from __future__ import annotations


_NUMBERS = {
    "one": 1, "single": 1, "two": 2, "twin": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
    "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "dozen": 12, "thirteen": 13, "fourteen": 14,
    "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18, "nineteen": 19, "twenty": 20,
    "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90, "hundred": 100,
}  # fmt: skip
#: The most of one kind a count in words gives: "thirty guests" and "forty players" are as many, "a
#: hundred fans" or "two hundred" stand as fifty, so a crowd reads as a crowd and the scene stays light
#: enough to lay out and render (a count in digits is taken as meant, and the object limit refuses one
#: too large).
CROWD = 50
#: Words that make the count after them a rough one ("about twenty", "some thirty"): no things.
_APPROXIMATE = {"about", "around", "roughly", "nearly", "almost", "approximately", "perhaps", "maybe"}
_VAGUE = {"few": 3, "several": 3, "some": 3, "various": 3, "many": 5, "numerous": 5, "multiple": 3, "both": 2}
#: Nouns that count or arrange what follows "of" ("a row of lamps", "stacks of crates").
_QUANTITY = {
    "pair": 2, "pairs": 4, "couple": 2, "row": 4, "rows": 6, "line": 4, "set": 3, "sets": 6, "group": 3,
    "groups": 6, "cluster": 3,
    "stack": 3, "stacks": 4, "pile": 3, "piles": 4, "heap": 3, "heaps": 4, "bunch": 3, "bunches": 4,
    "bundle": 3, "bundles": 4, "lane": 3, "lanes": 6, "queue": 4, "handful": 3, "collection": 3, "teams": 10,
    "coils": 3, "coil": 1, "ring": 4, "circle": 4, "lot": 5, "lots": 5, "plenty": 5, "dozens": 24, "hundreds": 30,
    "series": 3, "trio": 3, "clusters": 5, "grove": 4, "patch": 1, "flock": 6, "herd": 6, "flocks": 12,
    "herds": 12, "string": 1, "school": 8, "shoal": 8, "swarm": 10, "pod": 4, "pack": 5, "pride": 5, "troop": 6,
    "litter": 4, "gaggle": 6, "colony": 10, "fleet": 5, "convoy": 4, "crew": 4, "team": 5, "squad": 5, "gang": 4,
    "band": 4, "crowd": 10, "crowds": 10, "throng": 10, "procession": 6, "column": 4, "file": 4, "parade": 6, "train": 4,
    "caravan": 4, "tower": 4, "pyramid": 6,
}  # fmt: skip
_DETERMINERS = {"a", "an", "the", "this", "that", "these", "those", "its", "their", "his", "her", "our", "my",
                "your", "another", "each", "every", "any", "other", "one", "all"}  # fmt: skip
_DEFINITE = {"the", "this", "that", "these", "those", "its", "their", "his", "her", "our", "my", "your"}
_PRONOUNS = {"it", "them", "itself", "themselves", "one"}
#: Less common prepositions: they end a noun phrase and name no kind of the noun before ("a wheelchair past the door").
_PREPOSITIONS = {"past", "beyond", "among", "amongst", "amid", "amidst", "via", "within", "without", "alongside",
                 "during", "until", "despite", "except", "aboard", "astride", "before"}  # fmt: skip
#: Adverbs of place that may follow a noun ("a beam overhead", "a fish on the ice nearby"): no kind of it.
_PLACE_ADVERBS = {"overhead", "nearby", "aloft", "upstairs", "downstairs", "ashore", "underfoot", "offshore",
                  "uphill", "downhill", "downstream", "upstream", "yonder"}  # fmt: skip
#: Words that end a noun phrase when reading backwards for adjectives.
_STOP = (
    set(_NUMBERS) | set(_VAGUE) | _DETERMINERS | _PRONOUNS | _APPROXIMATE
    | {
        "and", "or", "but", "with", "of", "in", "on", "at", "to", "from", "by", "for", "into", "onto",
        "near", "beside", "behind", "above", "under", "below", "over", "between", "around", "is",
        "are", "was", "were", "be", "has", "have", "had", "there", "here", "while", "where", "which",
        "who", "that", "as", "than", "stands", "stand", "sits", "sit", "lies", "lie", "rests", "rest",
        "hangs", "hang", "grows", "grow", "placed", "next", "across", "opposite", "facing",
        "faces", "face", "toward", "towards", "against", "along", "inside", "outside", "up", "down",
        "out", "off", "through", "like", "full", "filled", "covered", "packed", "made", "also", "just",
        "very", "too", "so", "then", "it's", "each", "every", "lots", "plenty", "atop", "upon",
        "beneath", "underneath", "close", "far", "away", "front", "back",
        "side", "sides", "middle", "centre", "center", "corner", "edge", "end", "top", "bottom",
    }
    | _PREPOSITIONS
)  # fmt: skip
_UNITS = {
    "m": 1.0, "meter": 1.0, "meters": 1.0, "metre": 1.0, "metres": 1.0, "cm": 0.01,
    "centimeter": 0.01, "centimeters": 0.01, "centimetre": 0.01, "centimetres": 0.01, "mm": 0.001,
    "ft": 0.3048, "foot": 0.3048, "feet": 0.3048, "inch": 0.0254, "inches": 0.0254,
    "yard": 0.9144, "yards": 0.9144, "pace": 0.75, "paces": 0.75, "stride": 0.9, "strides": 0.9,
    "step": 0.75, "steps": 0.75,
}  # fmt: skip
_DIMENSIONS = {"wide": "x", "width": "x", "across": "x", "long": "long", "length": "long", "deep": "y",
               "depth": "y", "tall": "z", "high": "z", "height": "z", "diameter": "d"}  # fmt: skip
#: Containers and depictions: what follows their "of" is content or subject, not an object.
_CONTENT_HEADS = {"vase", "bowl", "basket", "bucket", "plate", "bottle", "cup", "pot", "crate", "cart", "statue",
                  "cabinet", "wardrobe", "display_case", "treasure_chest", "trash_can", "laundry_basket",
                  "picture_frame", "planter", "sign", "billboard", "shop_shelf", "bookshelf", "flask",
                  "barrel", "shipping_container", "flower_bed", "cauldron", "sandbox", "hologram", "panel"}  # fmt: skip
_CONTENT_MARKERS = {("full", "of"), ("filled", "with"), ("packed", "with"), ("overflowing", "with"),
                    ("covered", "in"), ("covered", "with"), ("stacked", "with"), ("heaped", "with"),
                    ("stocked", "with"), ("lined", "with"), ("piled", "with"), ("overflow", "with"),
                    ("overflows", "with"), ("brims", "with"), ("brimming", "with"), ("bulges", "with"),
                    ("bulging", "with"), ("crowded", "with")}  # fmt: skip
#: What a surface shows, not a thing that stands there ("a folding screen painted with cranes", "a
#: cushion embroidered with roses").
_PICTURE_MARKERS = {(verb, "with") for verb in ("painted", "embroidered", "printed", "stencilled", "stenciled",
                                                "patterned", "etched", "engraved", "tattooed", "inlaid")}  # fmt: skip
#: What screens, pictures and windows do with what is on them: it is their picture, no thing of the
#: layout ("a giant screen showing the rocket on its pad", "a window shows the Earth turning").
_SHOW_VERBS = {"showing", "shows", "show", "displaying", "displays", "depicting", "depicts", "playing"}
#: Things whose picture a show verb names (beside the depictions of the grammar): screens and windows.
_SHOWING = {"tv", "monitor", "projector_screen", "laptop", "window", "windows", "screen", "screens", "mural", "tapestry"}
#: Verbs of trade: the bare plural after them is what is sold or served, not things of the layout
#: ("a stall selling pies", "a cart serving hot drinks"; but "a vendor sells two balloons").
_WARES_VERBS = {"sell", "sells", "selling", "sold", "serve", "serves", "serving", "served", "offer", "offers",
                "offering", "stocks", "stocking", "peddles", "peddling", "hawks", "hawking"}  # fmt: skip
#: Verbs of cooking: a bare noun right after one is the food cooked, no thing of the layout ("a woman
#: grills fish over the fire", "roasting chestnuts"; but "grills two fish" are there).
_COOK_VERBS = {"grill", "grills", "grilling", "fry", "fries", "frying", "roast", "roasts", "roasting", "bake",
               "bakes", "baking", "boil", "boils", "boiling", "toast", "toasts", "toasting", "smoke", "smokes",
               "smoking", "barbecue", "barbecues", "barbecuing", "cook", "cooks", "cooking", "stew", "stews",
               "stewing", "sear", "sears", "searing", "steam", "steams", "steaming", "gut", "guts", "gutting",
               "fillet", "fillets", "filleting", "chop", "chops", "chopping", "knead", "kneads", "kneading"}  # fmt: skip
_HANG_VERBS = {"hang", "hangs", "hanging", "hung", "strung", "hover", "hovers", "hovering", "float", "floats",
               "floating", "suspended", "dangle", "dangles", "dangling", "fly", "flies", "flying",
               "soar", "soars", "soaring", "glow", "glows", "drift", "drifts", "mounted", "swing",
               "swings", "swim", "swims", "swimming"}  # fmt: skip
#: Verbs of turning or flickering in place: what turns, spins or flickers over a thing is up in
#: the air there (a hologram, a mobile, a fan), not a tall thing standing by it as a tree "above"
#: a pond does.
_TURN_VERBS = {"turn", "turns", "turning", "spin", "spins", "spinning", "rotate", "rotates", "rotating",
               "revolve", "revolves", "revolving", "twirl", "twirls", "twirling", "whirl", "whirls", "whirling",
               "flicker", "flickers", "flickering", "shimmer", "shimmers", "shimmering"}  # fmt: skip

_PLANT_SHAPES = ("tree", "pine_tree", "palm_tree", "bush", "flower_bed")
_FINITE = {"is", "are", "was", "were", "has", "have", "had", "stand", "sit", "lie", "rest", "hang", "grow",
           "lean", "wait", "glow", "run", "line", "rise", "stay", "remain", "tower", "loom", "float", "hover"}  # fmt: skip
_ADVERBS = {"just", "right", "directly", "all", "both", "neatly", "slightly", "also", "then", "only", "far", "well"}
_HOLD = {"holds", "hold", "holding", "carries", "carry", "carrying", "supports", "support", "supporting",
         "bears", "bearing", "displays", "displaying", "seats", "seating"}  # fmt: skip
#: Games named by their pieces: what one plays ("three guards play dice"), no thing of the scene.
_GAMES = {"dice", "cards", "dominoes", "marbles", "darts", "chess", "checkers", "draughts", "mahjong", "backgammon",
          "skittles", "jacks"}  # fmt: skip
#: People named with the kind they hunt, tame or work, not the kind they are ("a puppet master", "a troll hunter").
_WORKS_ITS_KIND = {"master", "hunter", "slayer", "tamer", "keeper", "catcher", "handler", "trainer", "killer",
                   "charmer", "whisperer", "rider", "wrangler", "herder"}  # fmt: skip
#: Verbs whose object stays in hand wherever they are done: held against a stone or a wheel
#: ("sharpen their spears on a grindstone"), or played, read, eaten there ("plays a lute on the
#: steps of the town hall": the bard is there, the lute in hand).
_KEPT_IN_HAND = {"sharpen", "sharpens", "sharpening", "hone", "hones", "honing", "whet", "whets", "whetting",
                 "grind", "grinds", "grinding", "strop", "strops", "stropping",
                 "play", "plays", "playing", "strum", "strums", "strumming", "read", "reads", "reading",
                 "eat", "eats", "eating", "drink", "drinks", "drinking", "sip", "sips", "sipping",
                 "blow", "blows", "blowing", "tune", "tunes", "tuning", "knit", "knits", "knitting",
                 "hug", "hugs", "hugging", "cradle", "cradles", "cradling", "cuddle", "cuddles", "cuddling"}  # fmt: skip
_HOLD_PAIRS = {("loaded", "with"), ("laden", "with"), ("topped", "with"), ("set", "with"), ("laid", "with"), ("decorated", "with"),
               ("piled", "with"), ("stacked", "with"), ("heaped", "with"), ("covered", "in"),
               ("covered", "with"), ("packed", "with"), ("lined", "with"), ("stocked", "with"),
               ("crammed", "with"), ("hung", "with")}  # fmt: skip
#: Verbs whose object a person has in hand ("waves a flag"): the thing is carried by its holder, as
#: with "holds".
_HAND_VERBS = {"waves", "waving", "wields", "wielding", "brandishes", "brandishing", "clutches", "clutching",
               "grips", "gripping", "clasps", "clasping", "swings", "swinging", "twirls", "twirling", "raises",
               "raising", "juggle", "juggles", "juggling", "wave", "wield", "brandish", "clutch", "clasp", "twirl",
               "raise", "spins", "spinning", "spin", "throws", "throwing", "throw", "tosses", "tossing", "toss",
               "hurls", "hurling", "hurl", "flings", "flinging", "fling", "lobs", "lobbing", "lob"}  # fmt: skip
#: Verbs of taking a thing up in one's arms, by their stem (:func:`_verb_stem`): what they take is
#: in arms whenever a person can carry it ("lifts a crate", "two men haul a trunk", "hugs a
#: pillow"), where other verbs have in hand only a hand-sized thing ("examines a crate": by it).
_BEAR_VERBS = {"lift", "hoist", "heave", "haul", "lug", "tote", "shoulder", "hug", "cradle", "cuddle", "embrace"}
#: Verbs of taking an animal along ("a man walks a dachshund beside the van"): the animal keeps by
#: its person, whom what follows places.
#: Verbs of going or of taking something somewhere: what follows "to" after them is where one goes
#: ("carries a tray to the table", "wheels the barrow to the shed").
_CARRY_VERBS = {f"{stem}{end}" for stem in ("carr", "hurr") for end in ("y", "ies", "ying")} | {
    f"{stem}{end}" for stem in ("bring", "lead", "wheel", "push", "pull", "drag", "haul", "roll", "walk", "head",
                                "return", "trundle", "steer", "tow") for end in ("", "s", "es", "ing", "ed")
} | {"takes", "take", "taking", "drives", "drive", "driving", "runs", "run", "running", "goes", "go", "going",
     "dragging", "brought", "led", "took", "drove", "went", "ran"}  # fmt: skip
#: Participles that say how a lifeless thing is set down, besides the regular "-ed" ones.
_STATE_PARTICIPLES = {"laid", "slung", "hung", "set", "resting", "lying", "standing", "hanging", "leaning", "balanced"}
#: Verbs of leaving a place: "from" after one names where one was ("climbs from the cab", "steps
#: from the bus"), not where one is.
_LEAVING_VERBS = {"climb", "step", "fall", "emerge", "run", "walk", "come", "return", "escape", "flee", "hop",
                  "slide", "tumble", "stumble", "descend", "dismount", "alight", "rise", "drift", "fly", "swing",
                  "stream", "pour", "spill", "hang", "dangle", "leak", "drip", "float"}  # fmt: skip
#: Verbs whose "from" names where a thing is taken from ("takes a cup from the chair", "unloads crates
#: from a trawler"), not where the doer is.
_TAKING_VERBS = {"take", "pull", "lift", "grab", "pick", "fetch", "remove", "snatch", "steal", "draw", "collect",
                 "unload", "offload"}  # fmt: skip
#: Verbs of going with a living thing one leads or chases: where the doer goes ("walks a dachshund
#: beside the van", "children chase a dog around the well") is the doer's place, the other keeps by them.
_LEAD_VERBS = {"walk", "walks", "walking", "lead", "leads", "leading", "guide", "guides", "guiding",
               "chase", "chases", "chasing"}  # fmt: skip
#: Verbs of giving ("a robot hands one of them a toolbox"): the giver has the thing in hand and
#: stands by whom it is given to.
_GIVE_VERBS = {"hands", "handing", "hand", "gives", "giving", "give", "passes", "passing", "pass", "offers",
               "offering", "offer", "feeds", "feeding", "feed"}  # fmt: skip
#: Use verbs whose one thing several people have between them ("two girls share a bento box"): no
#: thing for each.
_SHARE_VERBS = {"share", "shares", "sharing"}
#: Eating and drinking: what one does it "from" is by one or in hand, never under one ("a cow eats
#: from a hay bale").
_CONSUMING = {"sips", "sipping", "sip", "drinks", "drinking", "drink", "tastes", "tasting", "taste", "eats",
              "eating", "eat"}  # fmt: skip
#: A verb, then (after what it takes, if anything) a preposition whose thing a person has in hand:
#: "sips from a glass", "sipping coffee from a paper cup", "counting coins out of a pouch",
#: "sketching on a clipboard", "peering through a loupe", "watching the ships through a spyglass",
#: "stitching beads onto a purse".
_HAND_PAIRS = {
    *((verb, "from") for verb in _CONSUMING), ("counts", "out"), ("counting", "out"), ("count", "out"),
    ("peers", "through"), ("peering", "through"), ("looks", "through"), ("looking", "through"),
    ("squints", "through"), ("squinting", "through"), ("watches", "through"), ("watching", "through"),
    ("watch", "through"), ("sketches", "on"), ("sketching", "on"), ("sketch", "on"), ("writes", "on"),
    ("writing", "on"), ("write", "on"), ("scribbles", "on"), ("scribbling", "on"), ("draws", "on"),
    ("drawing", "on"), ("draw", "on"), ("types", "on"), ("typing", "on"), ("type", "on"),
    # what the feed or the drink comes out of ("feeds the ducks from a paper bag", "pours tea from a pot")
    *((verb, "from") for verb in ("feeds", "feeding", "feed", "pours", "pouring", "pour", "scatters",
                                  "scattering", "scatter")),
    # the pan one tosses in ("tosses pancakes in a frying pan")
    *((verb, "in") for verb in ("tosses", "tossing", "toss", "flips", "flipping", "flip")),
    # the book one writes in ("writes in a ledger", "sketching in a notebook")
    *((verb, "in") for verb in ("writes", "writing", "write", "scribbles", "scribbling", "sketches", "sketching",
                                "jots", "jotting", "notes", "noting")),
    # the piece one works small things onto ("stitching beads onto a purse", "glues shells onto a box")
    *((verb, "onto") for verb in ("stitches", "stitching", "stitch", "sews", "sewing", "sew", "glues", "gluing",
                                  "glue", "pins", "pinning", "pin", "threads", "threading", "thread")),
    # what one sifts or strains through ("sifts grit through a sieve")
    *((verb, "through") for verb in ("sifts", "sifting", "sift", "strains", "straining", "strain")),
    # what one speaks into or through ("shouts through a megaphone", "shouting into radios")
    *((verb, p) for verb in ("shouts", "shouting", "shout", "speaks", "speaking", "speak", "talks", "talking",
                             "talk", "calls", "calling", "call", "yells", "yelling", "yell", "barks", "barking",
                             "sings", "singing", "sing", "announces", "announcing", "announce")
      for p in ("into", "through")),
}  # fmt: skip
#: Verbs whose object a person has in hand while doing them, when it is small enough to hold
#: ("eats a sandwich", "plays a flute", "lifts a barbell", "two scouts sharpen their spears"); a
#: bigger object is acted on where it stands ("paints a fence"). Stirring or hammering a thing
#: works on it where it lies ("stirs a pot on the stove"), so those verbs are not here.
_USE_VERBS = {
    "eat", "eats", "eating", "munch", "munches", "munching", "nibble", "nibbles", "nibbling",
    "chew", "chews", "chewing", "gnaw", "gnaws", "gnawing", "lick", "licks", "licking", "slurp", "slurps", "slurping",
    "read", "reads", "reading", "play", "plays", "playing", "strum", "strums", "strumming",
    "bang", "bangs", "banging", "shake", "shakes", "shaking", "ring", "rings", "ringing",
    "lift", "lifts", "lifting", "toss", "tosses", "tossing",
    "share", "shares", "sharing", "sharpen", "sharpens", "sharpening", "polish", "polishes", "polishing",
    "paint", "paints", "painting", "carve", "carves", "carving", "whittle", "whittles", "whittling",
    "knit", "knits", "knitting", "sew", "sews", "sewing", "mend", "mends", "mending",
    "taste", "tastes", "tasting", "sip", "sips", "sipping", "drink", "drinks", "drinking",
    "hug", "hugs", "hugging", "cradle", "cradles", "cradling", "cuddle", "cuddles", "cuddling",
    "inspect", "inspects", "inspecting", "examine", "examines", "examining", "study", "studies", "studying",
    "count", "counts", "counting", "blow", "blows", "blowing", "tune", "tunes", "tuning",
}  # fmt: skip
#: Verbs of filling, by their stem (:func:`_verb_stem`): what comes "with" after their object is
#: what goes in or on it, not a tool in hand ("pickers fill baskets with apples").
_FILL_VERBS = {"fill", "load", "stuff", "pack", "stock", "heap", "pile", "stack", "cover", "line", "decorate"}
#: Verbs of placing or of work done where the thing lies, by their stem (:func:`_verb_stem`): their
#: small object is not in the doer's hand ("sets a cup on the tray", "stirs a pot on the stove",
#: "chops onions", "pushes a pram"), nor is a small thing they are done "on".
_PUT_OR_WORKED = {
    # placing
    "put", "place", "set", "lay", "stack", "arrange", "hang", "mount", "plant", "drop", "leave", "lean",
    "prop", "pile", "load", "unload", "fill", "empty", "spread", "scatter", "tip", "dump", "lower", "store",
    "stock", "display", "pack", "unpack", "stuff", "slide", "shove", "slip", "tuck", "insert", "slot",
    # work in place
    "stir", "chop", "cut", "slice", "dice", "knead", "hammer", "weld", "forge", "fry", "grill", "roast",
    "shape", "sculpt", "mould", "mold", "glaze", "bake", "cook", "boil", "wash", "scrub", "sweep", "mop", "water", "repair", "fix", "assemble", "build",
    "open", "close", "lock", "unlock", "shoe", "dig", "rake", "shovel", "split", "saw", "plough", "plow",
    "light", "stoke", "tend", "fan", "push", "wheel", "trundle",
}  # fmt: skip
#: Verbs of sense, pursuit, trade and going, by their stem: what they take reaches the doer from afar
#: or stays where it is ("watches a kite", "kicks a ball", "sells lanterns", "leads a pony").
_FROM_AFAR = {
    "watch", "see", "eye", "admire", "observe", "chase", "follow", "kick", "throw", "face", "guard",
    "approach", "pursue", "film", "photograph", "sell", "serve", "hunt", "stalk", "sniff",
    "ignore", "feed", "greet", "wait", "guide", "lead", "walk", "ride", "drive", "steer", "board", "climb", "cross",
    "enter", "circle", "block",
}  # fmt: skip
#: Verbs of aiming, by their stem: what they take is a tool or a weapon in the doer's hand, however
#: long ("aims a pitchfork at them", "points a torch at the door"), and the doer faces what it is
#: aimed at.
_AIM_VERBS = {"aim", "point", "level", "train", "throw", "toss", "hurl", "fling", "lob"}
#: Verbs of writing things down, by their stem: what they take is what is written about, not in
#: hand, and the sheet or device they are done "on" is ("recording every sack on a scroll", "noting
#: each crate on a clipboard").
_RECORD_VERBS = {"record", "note", "log", "list", "tally", "jot", "register", "catalogue", "catalog", "copy"}
#: Verbs whose small object is not in hand: any other verb a person does to a thing small enough to
#: hold has it in hand ("checks a wristwatch", "turning a small jug", "haul a trunk up the stairs").
_NOT_IN_HAND = _PUT_OR_WORKED | _FROM_AFAR | _RECORD_VERBS
#: Words that start a with-thing's own placing ("with a till at one end and a computer ...").
_OWN_PLACE = {"at", "in", "along", "against", "under", "inside"}
#: How many of these parts a thing has: "a lamp at each corner" is four lamps, "a cone at each
#: wingtip" two.
_PARTS_A_THING = {"corner": 4, "end": 2, "wingtip": 2}
#: Possessives whose noun, when no object, is a part of what the pronoun names ("its door").
_OWNER_PRONOUNS = {"its": "it", "their": "them"}
#: Ordinal words → position, counted from 0 as Python indexes ("first" is 0); the scene parser
#: and the edit parser both read ordinals through this one table.
ORDINALS = {
    "first": 0, "second": 1, "third": 2, "fourth": 3, "fifth": 4, "sixth": 5, "seventh": 6,
    "eighth": 7, "ninth": 8, "tenth": 9, "1st": 0, "2nd": 1, "3rd": 2, "4th": 3, "5th": 4,
    "6th": 5, "7th": 6, "8th": 7, "9th": 8, "10th": 9,
}  # fmt: skip
#: Words that pick one of a group the text named before ("the other chair", "the last lamp").
_ORDINALS = {**ORDINALS, "last": -1, "left": 0, "right": -1, "other": -1, "nearest": 0}


def _verb_stem(word: str, stems: set[str]) -> bool:
    """Whether ``word`` is a form of one of ``stems`` ("stirs", "stirring", "chopped", "bakes")."""
    w = word.lower()
    forms = {w}
    for end in ("ing", "ed", "es", "s"):
        if w.endswith(end) and len(w) - len(end) >= 2:
            base = w[: -len(end)]
            forms |= {base, base + "e"}
            if len(base) > 2 and base[-1] == base[-2]:
                forms.add(base[:-1])  # "stirring", "chopped"
    return bool(forms & stems)


def _is_verb(word: str) -> bool:
    """A finite verb, roughly: what closes a noun phrase's "with" part ("with a mirror is placed")."""
    if word.endswith("'s"):  # "there's" is a verb, "the team's bench" a possessive
        return word in ("there's", "here's", "it's", "that's", "what's", "who's", "where's")
    return word in _FINITE or (len(word) > 3 and word.endswith("s") and not word.endswith(("ss", "us", "is")))
