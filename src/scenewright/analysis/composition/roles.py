"""What part each kind of thing plays in a composition, by catalogue category.

The rules of the arranger ask these questions (is it a seat? a desk? tall storage that
belongs against the edge?) instead of naming categories themselves, so a new category joins
a rule by being added here. Categories the catalogue does not know (guessed objects) fall
back on their shape, and else play no part.
"""

from __future__ import annotations

from scenewright.core.catalogue import load_catalogue

#: A person sits on it, facing its front.
SEATS = frozenset({
    "chair", "armchair", "office_chair", "stool", "sofa", "bench", "bean_bag", "booth", "throne",
    "deck_chair", "ottoman",
})  # fmt: skip
#: Seats one pulls up to a desk or a table.
CHAIRS = frozenset({"chair", "office_chair", "stool"})
#: High seats that line a bar or a counter.
BAR_SEATS = frozenset({"stool"})
#: What bar stools line, facing it.
BARS = frozenset({"counter"})
#: Seats of a lounge, gathered around a coffee table.
LOUNGE_SEATS = frozenset({"sofa", "armchair", "bean_bag", "booth", "deck_chair"})
#: Work surfaces with one chair in front.
DESKS = frozenset({"desk", "vanity", "school_desk", "lab_bench"})
#: Tables chairs go around.
TABLES = frozenset({"table", "round_table", "picnic_table"})
ROUND_TABLES = frozenset({"round_table"})
COFFEE_TABLES = frozenset({"coffee_table"})
#: What a lounge's seats face.
FOCAL = frozenset({"tv_stand", "fireplace", "tv", "piano"})
#: What a person the text puts by it works at, facing it ("two sailors sit at the sonar console").
WORKPLACES = DESKS | TABLES | BARS | frozenset({
    "control_panel", "piano", "easel", "stove", "grill", "lectern", "sink", "microscope", "market_stall", "kiosk",
    "vending_machine",
})  # fmt: skip
BEDS = frozenset({"bed", "crib"})
#: What spans the gap between two things, its long side from one to the other ("a rope bridge between two cliffs").
SPANS = frozenset({"bridge"})
NIGHTSTANDS = frozenset({"nightstand"})
#: What stands at the foot of a bed.
BED_FOOT = frozenset({"treasure_chest", "ottoman", "bench"})
#: Tall or wall-bound storage, and what is built into a wall (a fireplace, a TV stand): along the
#: edges of the scene, backs outward.
EDGE_STORAGE = frozenset({
    "bookshelf", "wardrobe", "cabinet", "fridge", "filing_cabinet", "shop_shelf", "wine_rack",
    "locker", "server_rack", "dresser", "dumbbell_rack", "grandfather_clock", "fume_hood",
    "whiteboard", "water_cooler", "display_case", "vending_machine", "counter", "shower",
    "washing_machine", "dishwasher", "stove", "sink", "curtain", "easel", "fireplace", "tv_stand",
})  # fmt: skip
#: Buildings and landforms that, big and tied to nothing, stand behind the scene's groups, not among them.
BACKDROPS = frozenset({
    "house", "building", "warehouse", "barn", "greenhouse", "lighthouse", "windmill", "tower", "rock",
})  # fmt: skip
RUGS = frozenset({"rug"})
FLOOR_LAMPS = frozenset({"floor_lamp", "torch", "coat_rack"})
#: Grown or found things, scattered with Poisson-disc spacing.
NATURAL = frozenset({
    "tree", "pine_tree", "palm_tree", "bush", "flower_bed", "rock", "cactus", "mushroom", "log",
    "tumbleweed", "hay_bale", "crystal",
})  # fmt: skip
#: Selling places, set out in rows or around a square.
STALLS = frozenset({"market_stall", "kiosk", "food_truck"})
#: Goods and stock a stall keeps beside it.
STALL_PROPS = frozenset({"barrel", "crate", "hay_bale", "basket", "cooler", "pallet"})
#: Parked along an edge of the scene, like a road.
VEHICLES = frozenset({"car", "truck", "bus", "motorcycle", "tractor", "bicycle", "cart", "spaceship"})
#: The middle of an outdoor square.
CENTREPIECES = frozenset({"fountain", "well", "statue", "obelisk", "campfire", "gazebo", "totem"})

_SHAPE_FALLBACK = {
    "chair": "chair", "armchair": "armchair", "sofa": "sofa", "bench": "bench", "stool": "stool",
    "desk": "desk", "table": "table", "round_table": "round_table", "bed": "bed",
    "bookshelf": "bookshelf", "wardrobe": "wardrobe", "tree": "tree", "pine_tree": "pine_tree",
    "palm_tree": "palm_tree", "bush": "bush", "rock": "rock", "car": "car", "truck": "truck",
    "market_stall": "market_stall", "fountain": "fountain",
}  # fmt: skip


def kind(category: str) -> str:
    """The category the rules treat this one as: itself when the catalogue knows it, else the
    category its procedural shape stands for (a guessed 'camel' on a generic shape is nothing)."""
    catalogue = load_catalogue()
    if category in catalogue:
        return category
    return _SHAPE_FALLBACK.get(category, category)
