"""The offline vision-language backend: the catalogue parser answering the model's questions.

No network, no weights: objects, sizes and first poses come from :func:`parse_scene` and
:func:`compose`, constraints from the relations the parse read (with those the composition
added, such as a sofa standing on the rug put under it), and the feedback loop
relaxes what the solver could not satisfy. Edits are planned by the rule-based edit parser;
judging renders needs a real vision model and says so.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from scenewright.analysis.arrange import Composition, compose
from scenewright.analysis.parser import ParsedScene, parse_scene
from scenewright.analysis.parser.language import check_english
from scenewright.core.protocols import Answer
from scenewright.core.relations import BINDING
from scenewright.analysis.parser.room import WALL_THINGS, wall_phrases
from scenewright.errors import BackendError, InputError
from scenewright.scene import ROOM_RELATIONS, ROOM_TARGET, Constraint, Event, LayoutReport, Room, SceneObject, Water

if TYPE_CHECKING:
    from scenewright.core.plan import EditPlan
    from scenewright.scene import Scene
    from scenewright.settings import Settings

#: One relaxation step per failed relation: a side becomes "near", the rest are dropped.
_RELAX: dict[str, str | None] = {
    "left of": "near", "right of": "near", "in front of": "near", "behind": "near", "side of": "near",
    "near": None, "far": None, "face to": None, "above": None, "on": None,
    # A wall-mounted or hanging thing keeps its wall or ceiling: without it, it would stand on the floor.
    "in corner": "against wall", "against wall": None, "on wall": "on wall", "on ceiling": "on ceiling",
}  # fmt: skip
#: Which relation gives way first when the report names no failed relation.

NO_OBJECT = "no object recognised in the text; name things like 'a sofa', 'two trees', 'a lamp on the desk'"
#: The default of ``Settings.max_objects``.
DEFAULT_MAX_OBJECTS = 150
TOO_MANY = (
    "the text asks for {count} objects, more than the limit of {limit}; describe fewer, or raise the "
    "limit with --max-objects N (config key max_objects)"
)


class OfflineVLM:
    """Rule-based scene analysis over the object catalogue."""

    name = "offline"

    def __init__(self, max_objects: int = DEFAULT_MAX_OBJECTS) -> None:
        self._parses: dict[str, ParsedScene] = {}
        self.max_objects = max_objects
        self._compositions: dict[str, Composition] = {}

    @classmethod
    def from_spec(cls, argument: str, settings: Settings) -> OfflineVLM:
        if argument:
            raise InputError(f"the offline vision-language backend takes no argument, got {argument!r}; use --vlm offline")
        return cls(max_objects=settings.max_objects)

    def parse(self, text: str) -> ParsedScene:
        """The parse of ``text``, read once per text; English only (the rules are English rules)."""
        key = " ".join(text.split())
        if not key:
            raise InputError("the scene text is empty; describe the scene, e.g. 'a sofa facing a TV on a stand'")
        if key not in self._parses:
            check_english(key)
            self._parses[key] = parse_scene(key)
        return self._parses[key]

    def composition(self, text: str) -> Composition:
        """The designed first layout of ``text``, made once per text."""
        parsed = self.parse(text)
        key = parsed.text
        if key not in self._compositions:
            self._compositions[key] = compose(parsed)
        return self._compositions[key]

    def describe_objects(self, text: str, style: str, reference: bytes | None) -> Answer[list[SceneObject]]:
        parsed = self.parse(text)
        repairs: list[Event] = []
        if not parsed.objects:
            raise InputError(NO_OBJECT)
        if len(parsed.objects) > self.max_objects:
            raise InputError(TOO_MANY.format(count=len(parsed.objects), limit=self.max_objects))
        guessed = {o.id: o.category for o in parsed.objects if o.guessed}
        if guessed:
            names = ", ".join(f"{i} ({c})" for i, c in guessed.items())
            repairs.append(
                Event(
                    stage="vlm.objects",
                    message=f"guessed {len(guessed)} objects the catalogue does not name: {names}",
                    data={"backend": self.name, "step": "guessed", "guessed": guessed},
                )
            )
        composition = self.composition(text)
        water = None if composition.shore is None else Water(shore=composition.shore)
        return Answer([o.model_copy(deep=True) for o in composition.objects], tuple(repairs),
                      anchored=composition.anchored, water=water)

    def write_constraints(
        self, text: str, objects: Sequence[SceneObject], reference: bytes | None, room: Room | None = None
    ) -> Answer[list[Constraint]]:
        parsed = self.parse(text)
        repairs = tuple(
            Event(stage="vlm.constraints", message=f"repaired: {note}", data={"backend": self.name, "step": "repair"})
            for note in parsed.repairs
        )
        ids = _match_ids(parsed, objects)
        out: list[Constraint] = []
        relations = self.composition(text).relations
        # A support the reader only inferred gives way to a side the text states to the same
        # thing ("a coffee machine stands beside a small table": not on it).
        beside = {(r.source, r.target) for r in relations if r.relation in _SIDES and not r.inferred}
        # ... and to a wall or a ceiling the text hangs it on ("hammers hang on the wall").
        walls = wall_phrases(parsed) if room is not None else []
        hung = {r.source for r in walls if r.relation in ("on wall", "on ceiling")}
        wall_of = {r.source: r.target for r in walls if r.target != "room"}
        category = {o.id: o.category for o in parsed.objects}
        kinds_above = {(category.get(r.source), category.get(r.target)) for r in relations
                       if r.relation == "above" and not r.inferred}
        for r in relations:
            if r.relation == "on" and r.inferred and ((r.source, r.target) in beside or r.source in hung):
                continue
            elsewhere = r.source in wall_of and wall_of[r.source] != wall_of.get(r.target)
            if r.relation == "above" and r.inferred and elsewhere:
                continue  # "paintings hang on the right wall": over nothing the back wall holds
            relation = r.relation
            if (relation == "above" and r.inferred and category.get(r.source) in WALL_THINGS
                    and (category.get(r.source), category.get(r.target)) not in kinds_above):
                # The reader's guess of where a picture or a clock hangs gives it a place, not a
                # height: the wall gives that ("a mirror" over the nearest wardrobe is near it).
                # One the text states for another of its kind stands as stated ("a clock above
                # each of the cabinets").
                relation = "near"
            if r.source in ids and r.target in ids:
                out.append(Constraint(relation=relation, source=ids[r.source], target=ids[r.target]))
        for r in walls:  # "against the back wall"
            if r.source in ids:
                out.append(Constraint(relation=r.relation, source=ids[r.source], target=r.target))
        return Answer(out, repairs)

    def find_redundant(
        self, objects: Sequence[SceneObject], images: Mapping[str, bytes]
    ) -> Answer[dict[str, str]]:
        # The parse lists each thing once, and there are no pictures to compare offline.
        return Answer({})

    def revise_constraints(
        self,
        text: str,
        objects: Sequence[SceneObject],
        constraints: Sequence[Constraint],
        report: LayoutReport,
        reference: bytes | None,
        room: Room | None = None,
    ) -> Answer[list[Constraint]]:
        return Answer(relax_constraints(constraints, report))

    def plan_edit(self, scene: Scene, instruction: str) -> Answer[EditPlan]:
        from scenewright.editing.parser import plan_edit_offline

        return Answer(plan_edit_offline(scene, instruction))

    def judge(self, text: str, image: bytes, criterion: str) -> float:
        raise BackendError("judging renders needs a remote vision-language model: --vlm openai:MODEL")


#: Relations that set a thing beside another.
_SIDES = frozenset({"left of", "right of", "in front of", "behind", "side of"})
#: Relations that say what a thing stands on or hangs from: when they fail together with others
#: ("a radio on the counter" and "beside the counter"), the others give way first, and these
#: only in a later round if they still fail alone.
_SUPPORTING = frozenset({"on", "above", "on wall", "on ceiling"})


def relax_constraints(constraints: Sequence[Constraint], report: LayoutReport) -> list[Constraint]:
    """The constraints with every failed relation of each unplaced object relaxed one step
    (a side → near, anything else dropped), its supports (:data:`_SUPPORTING`) only when nothing
    else failed with them, and its wall or ceiling only when no other support did; where the report names no failed relation (the object collided
    everywhere), its lowest-priority relation is dropped instead."""
    out = list(constraints)
    for unplaced in report.unplaced:
        failed = {c.key() for c in unplaced.failed}
        # supports last, and of those the wall or the ceiling last of all: twelve ladles "from the
        # ceiling above the stove" that cannot all hang over it still hang from the ceiling
        failed = ({k for k in failed if k[0] not in _SUPPORTING}
                  or {k for k in failed if k[0] not in ROOM_RELATIONS} or failed)
        if not failed:
            own = [c for c in out if c.source == unplaced.id]
            if own:
                failed = {max(own, key=lambda c: BINDING.index(c.relation)).key()}
        revised: list[Constraint] = []
        for c in out:
            if c.key() not in failed:
                revised.append(c)
                continue
            relaxed = _RELAX[c.relation]
            if c.relation in ROOM_RELATIONS and c.target != ROOM_TARGET and c.relation != "on ceiling":
                relaxed, target = c.relation, ROOM_TARGET  # one wall -> any wall
            else:
                target = c.target
            if relaxed is not None and (relaxed, c.source, target) in failed:
                relaxed = None  # what it would become failed as well ("near" the airship too)
            if relaxed is not None:
                revised.append(Constraint(relation=relaxed, source=c.source, target=target))
        out = revised
    unique: dict[tuple[str, str, str], Constraint] = {}
    for c in out:
        unique.setdefault(c.key(), c)
    return list(unique.values())


def _match_ids(parsed: ParsedScene, objects: Sequence[SceneObject]) -> dict[str, str]:
    """Parse id → scene id: the same id where the scene kept it, else the next unused object of
    the same category (objects another backend described, or renamed)."""
    scene_ids = {o.id for o in objects}
    mapping = {o.id: o.id for o in parsed.objects if o.id in scene_ids}
    used = set(mapping.values())
    for p in parsed.objects:
        if p.id in mapping:
            continue
        match = next((o.id for o in objects if o.category == p.category and o.id not in used), None)
        if match is not None:
            mapping[p.id] = match
            used.add(match)
    return mapping
