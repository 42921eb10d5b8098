"""What a parse gives back: objects, relations and the scene's look, as plain data.

The arranger and the offline backend consume these; their fields are the parser's public contract.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from scenewright.scene import Constraint


@dataclass(frozen=True)
class ParsedObject:
    id: str
    category: str
    name: str
    description: str
    size: tuple[float, float, float]
    #: Index of the noun phrase it came from (objects of one phrase share it).
    group: int
    #: Read through the open vocabulary (a shape family sized from its head word), not the catalogue.
    guessed: bool = False
    #: How it rests when that differs from its category's (an anvil is a ``tool`` on the ground).
    rests: str | None = None
    #: The part of the room the text puts it in with no object to relate to: ``wall``,
    #: ``corner``, ``centre``, ``back`` or ``front`` ("a sofa against the wall").
    anchor: str | None = None
    #: The formation its group stands in: ``row``, ``rows``, ``stack`` or ``circle`` ("three stalls
    #: in a row", "ten chairs in two rows"); the composition sets it out.
    formation: str | None = None
    #: How many rows a ``rows`` formation has, when the text says ("in two rows", "three rows of desks").
    formation_lines: int | None = None


@dataclass(frozen=True)
class ParsedRelation:
    source: str
    relation: str
    target: str
    #: Added by a default rule rather than read from the text.
    inferred: bool = False

    def constraint(self) -> Constraint:
        return Constraint(relation=self.relation, source=self.source, target=self.target)


@dataclass
class ParsedScene:
    text: str
    objects: list[ParsedObject]
    relations: list[ParsedRelation]
    style: str
    ground: str
    indoor: bool
    #: Place words that set the scene and stand nowhere in it ("hangar", "kitchen").
    places: list[str] = field(default_factory=list)
    #: What the parse changed from the text's literal reading, and why ("x on y: y cannot hold it").
    repairs: list[str] = field(default_factory=list)
    #: The setting lies by open water (:func:`~scenewright.analysis.parser.style.detect_water`).
    water: bool = False

    def constraints(self) -> list[Constraint]:
        return [r.constraint() for r in self.relations]
