"""Where a boat's deck lies, by the words that name it: its procedural mesh builds the hull up
to that height, and the layout stands what is put on the boat there, not on the roof of its
cabin or at the top of its mast (a fisherman on a trawler, a cat on a rowing boat's floor)."""

from __future__ import annotations

from scenewright.core.catalogue import mentions

#: Words of boats that carry a sail.
SAILS = ("sail", "sailing", "yacht", "longship", "viking", "galleon", "schooner", "clipper", "dhow", "junk", "frigate",
         "pirate", "sloop", "ketch", "caravel")  # fmt: skip
#: Words of boats open to the sky, rowed, paddled or poled, or carrying people on an open deck
#: (a tour boat, a water taxi): a gunwale and thwarts, no cabin.
OPEN = ("rowing", "rowboat", "row boat", "canoe", "kayak", "dinghy", "punt", "gondola", "longship", "viking", "raft",
        "skiff", "coracle", "lifeboat", "fishing boat", "whaler", "tour boat", "passenger boat",
        "excursion boat", "sightseeing boat", "pleasure boat", "water taxi")  # fmt: skip
#: Words of what boats are made of by hand from plants (a reed boat, a dugout, a bark canoe): such a
#: boat is open, and its hull shows that stuff instead of paint.
PLANT_HULL = ("reed", "papyrus", "rush", "bamboo", "bark", "dugout", "log", "wicker", "birch")
#: Shares of the boat's height as its mesh draws it: its hull's (low under a sail or open to the
#: sky, else up to a cabin's floor), an open boat's floor's share of its hull's, and the deck
#: planks' thickness laid over the floor.
_LOW_HULL, _HIGH_HULL, OPEN_FLOOR, PLANKS = 0.3, 0.55, 0.7, 0.02
#: Where one stands on a boat, as shares (x0, y0, x1, y1) of its half width and half length from
#: its centre (the bow toward −y): inside the hull, off the point of the bow, and on a motor boat
#: clear of its cabin (which starts a tenth of the half length before the middle).
_CABIN_DECK = (-0.5, -0.55, 0.5, -0.2)
_OPEN_DECK = (-0.4, -0.45, 0.4, 0.85)


def boat_text(name: str, category: str | None, description: str) -> str:
    """A boat's words as its procedural mesh reads them (name, category, description, lower case):
    what the functions below take as ``text``."""
    return f"{name} {category or ''} {description}".lower().replace("_", " ")


def has_sail(text: str, size) -> bool:
    """A boat with a mast: by its words, or by its size (taller than half again its width)."""
    return mentions(text, SAILS) or float(size[2]) > 1.5 * float(size[0])


def hull_share(text: str, size) -> float:
    """The height of the hull as a share of the boat's, from its name and description (lower case)."""
    return _LOW_HULL if has_sail(text, size) or is_open(text) else _HIGH_HULL


def is_open(text: str) -> bool:
    """An open boat: rowed, paddled or poled, or made by hand from plants."""
    return mentions(text, PLANT_HULL) or mentions(text, OPEN)


def floor_share(text: str, size) -> float:
    """The height of the boat's floor (an open boat's, under its gunwale) or deck as drawn, a
    share of its height, before the planks."""
    hull = hull_share(text, size)
    return OPEN_FLOOR * hull if is_open(text) else hull


def deck_share(text: str, size) -> float:
    """Where things put on the boat rest, as a share of its height: on the planks over its floor.
    An open boat with no mast is drawn up to its gunwale, and its mesh is then stretched to the
    boat's height, floor and all."""
    drawn = hull_share(text, size) if is_open(text) and not has_sail(text, size) else 1.0
    return (floor_share(text, size) + PLANKS) / drawn


def deck_area(text: str, size) -> tuple[float, float, float, float]:
    """Where things put on the boat stand, as shares of its half extents (:data:`_OPEN_DECK`)."""
    return _CABIN_DECK if hull_share(text, size) == _HIGH_HULL else _OPEN_DECK
