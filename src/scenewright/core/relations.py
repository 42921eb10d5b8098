"""The relation vocabulary: the relations' names and types, their limits, their priority and
their inverses, each written once (docs/architecture.md, "Relations").

The geometry that checks a relation and proposes places for it is :mod:`scenewright.layout.relations`;
the parser's reading of distances (:mod:`scenewright.analysis.parser.phrases`) and the backends'
repairs use the same figures from here.
"""

from __future__ import annotations

from scenewright.scene import RELATION_TYPES, Relation

__all__ = [
    "ABOVE", "BINDING", "BUFFER", "FACE_DEGREES", "FAR", "INVERSE", "NEAR", "ON_GAP", "OPPOSITE_SIDES",
    "PRIORITY", "RELATION_TYPES", "Relation",
]

BUFFER = 0.1  # m, relative relations
NEAR = 2.0  # m, horizontal gap
FAR = 8.0  # m, horizontal gap
ON_GAP = 0.002  # m, clearance for "on"
ABOVE = 2.0  # m, centre of source over centre of target (not touching it)
FACE_DEGREES = 10.0
#: The side relations that put a thing between two others when it has both of a pair, per world
#: axis (x, y) from the low end to the high end: right of one and left of the other, behind one
#: and in front of the other.
OPPOSITE_SIDES = (("right of", "left of"), ("behind", "in front of"))

#: Solver priority by relation type: the first relation of an object in this order generates
#: its candidates (vertical ones fix height and footprint, relative ones a side, the rest last).
#: The room relations rank with "on"/"above": a wall, corner or ceiling fixes a place as firmly
#: (a lamp on a desk against the wall is placed on the desk, which is placed at the wall).
PRIORITY: dict[str, int] = {
    relation: {"vertical": 0, "room": 0, "relative": 1, "distance": 2, "rotation": 2}[kind]
    for relation, kind in RELATION_TYPES.items()
}

#: The relations from the most binding to the least, within the priority groups above: what a
#: relaxation gives up last comes first.
BINDING: tuple[str, ...] = (
    "on ceiling", "on wall", "on", "above", "against wall", "in corner", "behind", "in front of", "right of", "left of", "side of", "near", "face to", "far",
)

#: relation → the relation that says the same with source and target swapped.
INVERSE: dict[str, str] = {
    "left of": "right of",
    "right of": "left of",
    "in front of": "behind",
    "behind": "in front of",
    "side of": "side of",
    "near": "near",
    "far": "far",
}
