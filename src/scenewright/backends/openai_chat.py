"""The vision-language model behind any OpenAI-compatible chat API (OpenAI, vLLM, Ollama...).

Each task sends its prompt (:mod:`scenewright.backends.prompts`), the images it needs and the
JSON schema of its answer, then treats the answer as untrusted input. What the schema cannot
guarantee is repaired here and kept on record: ids are made valid and unique, sizes clamped,
background "objects" dropped; constraints with unknown relations or ids, duplicates, self
references and cycles dropped. Each answer comes back as an :class:`~scenewright.core.protocols.Answer`
with one provenance :class:`~scenewright.scene.Event` per repair, for the stage to add to the scene.

Sizes are clamped to [0.1, 5] m, the paper's range, widened to any length the text itself
states ("a 12 m tall tower", "a 5 cm coin"), so a model's slip cannot make a 40 m chair while
a stated size is kept.
"""

from __future__ import annotations

import logging
import math
import re
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, WithJsonSchema

from scenewright.backends import prompts
from scenewright.core.plan import EditPlan, NewObject, RoomEdit
from scenewright.core.protocols import Answer
from scenewright.core.relations import INVERSE
from scenewright.backends.structured import ChatClient, InvalidAnswer, json_text, model_name, user_message
from scenewright.errors import InputError
from scenewright.scene import (
    ROOM_TARGET,
    MAX_ID_CHARS,
    MAX_ROOM_HEIGHT,
    MIN_ROOM_HEIGHT,
    MIN_WALL,
    RELATION_TYPES,
    Constraint,
    Event,
    Room,
    SceneObject,
    Vec3,
)

if TYPE_CHECKING:
    from scenewright.scene import LayoutReport, Scene
    from scenewright.settings import Settings

log = logging.getLogger(__name__)

DEFAULT_MODEL = "o3"
SIZE_RANGE = (0.1, 5.0)

#: Names whose head word is scenery, not an object (the paper keeps these out of the list).
BACKGROUND_WORDS = frozenset(
    "wall walls floor floors ceiling ceilings ground grass lawn sky skies road roads street "
    "terrain landscape curtain curtains window windows background horizon water sea ocean river".split()
)

class _Answer(BaseModel):
    model_config = ConfigDict(extra="forbid")


# The schema lists the ten relations, so servers with strict decoding can only emit those;
# validation accepts any string so that one bad relation drops one constraint, not the answer.
RelationName = Annotated[str, WithJsonSchema({"type": "string", "enum": list(RELATION_TYPES)})]


class ProposedConstraint(_Answer):
    relation: RelationName
    source: str
    target: str


class ConstraintsAnswer(_Answer):
    constraints: list[ProposedConstraint]


class ProposedObject(_Answer):
    id: str
    name: str
    position: Vec3
    rotation: Vec3
    size: Vec3
    visual_description: str


class ProposedOpening(_Answer):
    kind: Literal["door", "window"]
    wall: Literal["front", "back", "left", "right"]


class ProposedRoom(_Answer):
    width: float
    depth: float
    height: float
    openings: list[ProposedOpening]


class ObjectsAnswer(_Answer):
    objects: list[ProposedObject]
    #: The room around an indoor scene; null for an open one (docs/rooms.md).
    room: ProposedRoom | None = None


class RedundantImage(_Answer):
    id: str
    reason: str


class RedundantAnswer(_Answer):
    redundant: list[RedundantImage]


class ProposedNewObject(_Answer):
    name: str
    category: str | None
    visual_description: str
    size: Vec3 | None


class ProposedRoomEdit(_Answer):
    """A ``room`` edit: a new floor size and height (null: unchanged), or a door or window to add."""

    width: float | None
    depth: float | None
    height: float | None
    opening: Literal["door", "window"] | None
    side: Literal["back", "front", "left", "right"] | None


class EditAnswer(_Answer):
    operation: Literal["move", "add", "delete", "replace", "room"]
    focus: str
    constraints: list[ProposedConstraint]
    new_object: ProposedNewObject | None
    yaw: float | None
    offset: Vec3 | None = None  # strict schemas list it as required; older answers may omit it
    room: ProposedRoomEdit | None = None  # likewise; docs/rooms.md


_LENGTH = re.compile(
    r"(\d+(?:\.\d+)?)\s*-?\s*(cm|centimet(?:er|re)s?|m|met(?:er|re)s?)\b(?!\s*/)", re.IGNORECASE
)


def size_range(text: str) -> tuple[float, float]:
    """[0.1, 5] m, widened to include every length the text states."""
    low, high = SIZE_RANGE
    for number, unit in _LENGTH.findall(text):
        metres = float(number) / (100.0 if unit.lower().startswith("c") else 1.0)
        if metres > 0:
            low, high = min(low, metres), max(high, metres)
    return low, high


def snake_id(raw: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", raw.lower()).strip("_")


_SCORE = re.compile(r"score\W{0,4}(\d+(?:\.\d+)?)", re.IGNORECASE)
_OUT_OF = re.compile(r"(\d+(?:\.\d+)?)\s*(?:/|out of)\s*100\b", re.IGNORECASE)
_NUMBER = re.compile(r"(?<![\d.])(\d+(?:\.\d+)?)(?![\d.])")


def parse_score(reply: str) -> float:
    """The final 1–100 score in a free-text verdict: the last "Score: N", else the last
    "N/100", else the last number in range."""
    for pattern in (_SCORE, _OUT_OF):
        found = pattern.findall(reply)
        if found:
            value = float(found[-1])
            break
    else:
        numbers = [float(n) for n in _NUMBER.findall(reply) if 1 <= float(n) <= 100]
        if not numbers:
            raise InvalidAnswer('the verdict has no score; end with a line "Score: N" with N from 1 to 100')
        value = numbers[-1]
    if not 1 <= value <= 100:
        raise InvalidAnswer(f"the score {value:g} is outside 1..100")
    return value


class OpenAIChatVLM:
    """The VisionLanguageModel protocol over chat completions with JSON-schema answers."""

    name = "openai"

    def __init__(self, model: str, settings: Settings, client: Any = None):
        self.model = model
        self.chat = ChatClient(model, settings, client)

    @classmethod
    def from_spec(cls, argument: str, settings: Settings) -> OpenAIChatVLM:
        vlm = cls(model_name(argument, DEFAULT_MODEL), settings)
        vlm.chat.preflight()  # before the run pays for anything
        return vlm

    # --- repairs -------------------------------------------------------------------------

    def _repaired(self, repairs: list[Event], task: str, message: str, **data: Any) -> None:
        log.info("%s: %s", task, message)
        repairs.append(Event(stage=f"vlm.{task}", message=message, data={"model": self.model, **data}))

    # --- scene analysis ------------------------------------------------------------------

    def describe_objects(self, text: str, style: str, reference: bytes | None) -> Answer[list[SceneObject]]:
        low, high = size_range(text)
        messages = [
            {"role": "system", "content": prompts.OBJECTS_SYSTEM},
            user_message(prompts.describe_objects(text, style, low, high), [reference] if reference else []),
        ]

        def check(answer: ObjectsAnswer) -> Answer[list[SceneObject]]:
            # Each check keeps its own record: only the accepted answer's repairs count.
            repairs: list[Event] = []
            limit = self.chat.settings.max_objects
            if len(answer.objects) > limit:
                raise InvalidAnswer(
                    f"the list has {len(answer.objects)} objects, more than max_objects ({limit}); "
                    "list only the objects the description names"
                )
            objects = self._objects_from(answer.objects, low, high, repairs)
            if not objects:
                raise InvalidAnswer("the list has no usable object; list the objects the description names")
            return Answer(objects, tuple(repairs), room=_room_from(answer.room), proposes_room=True)

        return self.chat.ask("scene_objects", messages, ObjectsAnswer, check)

    def _objects_from(
        self, proposed: Sequence[ProposedObject], low: float, high: float, repairs: list[Event]
    ) -> list[SceneObject]:
        from scenewright.core.catalogue import lookup

        objects: list[SceneObject] = []
        taken: set[str] = set()
        for item in proposed:
            name = " ".join(item.name.split())
            words = snake_id(name).split("_")
            if not name or not words[0]:
                self._repaired(repairs, "scene_objects", f"dropped an object without a name (id {item.id!r})")
                continue
            if words[-1] in BACKGROUND_WORDS:
                self._repaired(repairs, "scene_objects", f"dropped background element {name!r}", id=item.id)
                continue
            object_id = (snake_id(item.id) or snake_id(name))[:MAX_ID_CHARS - 4].strip("_")
            base, n = object_id, 1
            while object_id in taken:
                n += 1
                object_id = f"{base}_{n}"
            if object_id != item.id:
                self._repaired(repairs, "scene_objects", f"renamed id {item.id!r} to {object_id!r}", id=object_id)
            taken.add(object_id)
            size = self._clamped(repairs, "scene_objects", object_id, item.size, low, high)
            position = Vec3.of(v if math.isfinite(v) else 0.0 for v in item.position.tuple())
            yaw = item.rotation.z if math.isfinite(item.rotation.z) else 0.0
            if item.rotation.x or item.rotation.y:
                self._repaired(repairs, "scene_objects", f"{object_id}: kept the yaw only; objects stand upright", id=object_id)
            category = lookup(name)
            objects.append(
                SceneObject(
                    id=object_id,
                    name=name,
                    category=category.name if category else None,
                    position=position,
                    rotation=Vec3(z=yaw % 360.0),
                    size=size,
                    visual_description=item.visual_description.strip(),
                )
            )
        return objects

    def _clamped(self, repairs: list[Event], task: str, object_id: str, size: Vec3, low: float, high: float) -> Vec3:
        values = [v if math.isfinite(v) else low for v in size.tuple()]
        clamped = Vec3.of(min(max(v, low), high) for v in values)
        if clamped.tuple() != size.tuple():
            self._repaired(repairs, 
                task,
                f"{object_id}: size {size.tuple()} clamped to [{low:g}, {high:g}] m",
                id=object_id,
                size=list(clamped.tuple()),
            )
        return clamped

    def find_redundant(
        self, objects: Sequence[SceneObject], images: Mapping[str, bytes]
    ) -> Answer[dict[str, str]]:
        shown = [obj for obj in objects if obj.id in images]
        if len(shown) < 2:
            return Answer({})
        labelled = [(f"Picture of {obj.id}:", images[obj.id]) for obj in shown]
        messages = [
            {"role": "system", "content": prompts.REDUNDANT_SYSTEM},
            user_message(prompts.find_redundant(_objects_text(shown)), labelled),
        ]

        def check(answer: RedundantAnswer) -> Answer[dict[str, str]]:
            repairs: list[Event] = []
            known = {obj.id for obj in shown}
            result: dict[str, str] = {}
            for item in answer.redundant:
                if item.id not in known:
                    self._repaired(repairs, "redundant_images", f"ignored unknown id {item.id!r}", id=item.id)
                    continue
                result[item.id] = item.reason.strip() or "already part of another object's image"
            return Answer(result, tuple(repairs))

        return self.chat.ask("redundant_images", messages, RedundantAnswer, check)

    # --- layout ---------------------------------------------------------------------------

    def write_constraints(
        self, text: str, objects: Sequence[SceneObject], reference: bytes | None, room: Room | None = None
    ) -> Answer[list[Constraint]]:
        messages = [
            {"role": "system", "content": prompts.CONSTRAINTS_SYSTEM},
            user_message(prompts.write_constraints(text, _objects_text(objects)), [reference] if reference else []),
        ]
        return self._ask_constraints("spatial_constraints", messages, objects, room)

    def revise_constraints(
        self,
        text: str,
        objects: Sequence[SceneObject],
        constraints: Sequence[Constraint],
        report: LayoutReport,
        reference: bytes | None,
        room: Room | None = None,
    ) -> Answer[list[Constraint]]:
        from scenewright.layout import feedback_text

        last = json_text([c.model_dump(exclude={"type"}) for c in constraints])
        prompt = prompts.revise_constraints(text, _objects_text(objects), last, feedback_text(report, objects))
        messages = [
            {"role": "system", "content": prompts.CONSTRAINTS_SYSTEM},
            user_message(prompt, [reference] if reference else []),
        ]
        return self._ask_constraints("revised_constraints", messages, objects, room)

    def _ask_constraints(
        self, task: str, messages: list, objects: Sequence[SceneObject], room: Room | None
    ) -> Answer[list[Constraint]]:
        def check(answer: ConstraintsAnswer) -> Answer[list[Constraint]]:
            repairs: list[Event] = []
            kept = self._cleaned(repairs, task, self._matched(answer.constraints, objects), objects, room)
            return Answer(kept, tuple(repairs))

        return self.chat.ask(task, messages, ConstraintsAnswer, check)

    @staticmethod
    def _matched(proposed: Sequence[ProposedConstraint], objects: Sequence[SceneObject]) -> list[dict[str, str]]:
        """Constraints as plain dicts with ids matched leniently ("Chair 1" is chair_1)."""
        by_snake = {snake_id(o.id): o.id for o in objects}
        return [
            {
                "relation": item.relation,
                "source": by_snake.get(snake_id(item.source), item.source),
                "target": by_snake.get(snake_id(item.target), item.target),
            }
            for item in proposed
        ]

    def _cleaned(
        self,
        repairs: list[Event],
        task: str,
        raw: Sequence[dict[str, str]],
        objects: Sequence[SceneObject],
        room: Room | None = None,
    ) -> list[Constraint]:
        """The layout engine's cleaning drops unknown relations and ids, self references,
        duplicates and cycles, and relations to a part of the room the scene lacks; each drop
        is recorded."""
        from scenewright.layout import clean_constraints

        kept, dropped = clean_constraints(objects, raw, room)
        for item in dropped:
            self._repaired(repairs, task, f"dropped a constraint: {item.reason}", constraint=item.constraint)
        return kept

    # --- editing --------------------------------------------------------------------------

    def plan_edit(self, scene: Scene, instruction: str) -> Answer[EditPlan]:
        from scenewright.editing.apply import validate_plan

        objects_text = "\n".join(
            f"- {o.id}: {o.name}, at ({o.position.x:.2f}, {o.position.y:.2f}, {o.position.z:.2f}), "
            f"yaw {o.yaw:g}, size {_size_text(o)}" + (f", {o.visual_description}" if o.visual_description else "")
            for o in scene.objects
        )
        messages = [
            {"role": "system", "content": prompts.EDIT_SYSTEM},
            user_message(prompts.plan_edit(objects_text, instruction, _room_text(scene.room))),
        ]
        known = {o.id for o in scene.objects}
        by_snake = {snake_id(i): i for i in known}

        def check(answer: EditAnswer) -> Answer[EditPlan]:
            repairs: list[Event] = []
            if answer.operation == "room":
                return Answer(self._room_plan(scene, answer.room), ())
            focus = answer.focus if answer.focus in known else by_snake.get(snake_id(answer.focus), answer.focus)
            if answer.operation == "add":
                # An id the scene already uses is replaced by editing.validate_plan, constraints and all.
                focus = snake_id(answer.focus)[:MAX_ID_CHARS - 4].strip("_") or "object"
            placing = answer.operation != "delete" and (answer.operation == "add" or focus in known)
            constraints = self._focus_constraints(answer.constraints, focus, scene.objects, repairs) if placing else []
            new = answer.new_object
            yaw = answer.yaw if answer.yaw is not None and math.isfinite(answer.yaw) else None
            plan = EditPlan(
                operation=answer.operation,
                focus=focus,
                constraints=constraints,
                new_object=NewObject(
                    name=new.name.strip(),
                    category=new.category,
                    visual_description=new.visual_description.strip(),
                    size=self._clamped(repairs, "edit_plan", focus, new.size, *size_range(instruction)) if new.size else None,
                )
                if new is not None and answer.operation != "move"
                else None,
                yaw=yaw % 360.0 if yaw is not None else None,
                offset=answer.offset if answer.operation == "move" else None,
            )
            try:  # the checks every plan passes (editing.validate_plan), the model's errors told back to it
                plan = validate_plan(scene, plan)
            except InputError as exc:
                raise InvalidAnswer(str(exc)) from None
            return Answer(plan, tuple(repairs))

        return self.chat.ask("edit_plan", messages, EditAnswer, check)

    @staticmethod
    def _room_plan(scene: Scene, change: ProposedRoomEdit | None) -> EditPlan:
        """The plan of a ``room`` answer, checked as the rule-based planner's is (editing.validate_plan):
        a size needs both sides, and the room must exist and something must change."""
        from scenewright.editing.apply import validate_plan

        if change is not None and (change.width is None) != (change.depth is None):
            raise InvalidAnswer("a room resize needs both width and depth in metres (or both null)")
        room = None
        if change is not None:
            size = (change.width, change.depth) if change.width is not None and change.depth is not None else None
            if size is not None and not all(math.isfinite(v) and v > 0 for v in size):
                raise InvalidAnswer(f"room width and depth must be positive metres, got {size}")
            room = RoomEdit(size=size, height=change.height, opening=change.opening, side=change.side)
        try:
            return validate_plan(scene, EditPlan(operation="room", focus=ROOM_TARGET, room=room))
        except InputError as exc:
            raise InvalidAnswer(str(exc)) from None

    def _focus_constraints(
        self,
        proposed: Sequence[ProposedConstraint],
        focus: str,
        objects: Sequence[SceneObject],
        repairs: list[Event],
    ) -> list[Constraint]:
        """The focus as the only source: constraints written the other way round are turned
        when their relation has an inverse, dropped otherwise; then cleaned as any others."""
        if all(o.id != focus for o in objects):  # an added object: let the cleaning know its id
            objects = [*objects, SceneObject(id=focus, name=focus, size=Vec3(x=1, y=1, z=1))]
        focused = []
        for item in self._matched(proposed, objects):
            if item["source"] != focus and item["target"] == focus:
                try:
                    relation = Constraint.model_validate(item).relation
                except ValueError:
                    relation = None
                if relation in INVERSE:
                    turned = {"relation": INVERSE[relation], "source": focus, "target": item["source"]}
                    self._repaired(repairs, "edit_plan", f"turned {item} into {turned}", constraint=turned)
                    item = turned
            if item["source"] == focus:
                focused.append(item)
            else:
                self._repaired(repairs, "edit_plan", f"dropped {item}: its source is not the focus {focus!r}", constraint=item)
        return self._cleaned(repairs, "edit_plan", focused, objects)

    # --- judging --------------------------------------------------------------------------

    def judge(self, text: str, image: bytes, criterion: str) -> float:
        if criterion not in prompts.CRITERIA:
            raise InputError(f"unknown judging criterion {criterion!r}; choose one of: {', '.join(prompts.CRITERIA)}")
        messages = [
            {"role": "system", "content": prompts.JUDGE_SYSTEM},
            user_message(prompts.judge(text, criterion), [image]),
        ]
        return self.chat.ask_text(f"judge_{criterion}", messages, parse_score)


def _room_text(room: Room | None) -> str | None:
    """The room as the edit prompt shows it: its floor, height and openings by side; None outdoors."""
    if room is None:
        return None
    from scenewright.layout.room import SIDES

    xs, ys = [p[0] for p in room.floor], [p[1] for p in room.floor]
    sides = {}
    for i, ((x0, y0), (x1, y1)) in enumerate(room.walls):
        out = (y1 - y0, -(x1 - x0))  # a wall's outward normal: right of its counter-clockwise run
        sides[i] = max(SIDES, key=lambda s: SIDES[s][0] * out[0] + SIDES[s][1] * out[1])
    openings = ", ".join(f"a {o.kind} on the {sides[o.wall]} wall" for o in room.openings) or "no openings"
    return (f"{max(xs) - min(xs):g} m wide (x) by {max(ys) - min(ys):g} m deep (y), {room.height:g} m high, "
            f"{len(room.floor)} walls; {openings}")


def _size_text(obj: SceneObject) -> str:
    return "x".join(f"{v:.2f}" for v in obj.size.tuple()) + " m"


def _objects_text(objects: Sequence[SceneObject]) -> str:
    return "\n".join(
        f"- {o.id}: {o.name}, {_size_text(o)}" + (f", {o.visual_description}" if o.visual_description else "")
        for o in objects
    )


def _room_from(proposed: ProposedRoom | None) -> Room | None:
    """The proposed room as a document room, validated like the rest of the answer: a floor or
    height out of range is an invalid answer the model is asked to correct. Doors and windows
    go on the walls it names, spread along them (at least one door)."""
    if proposed is None:
        return None
    from scenewright.analysis.parser.room import place_openings

    w, d, h = proposed.width, proposed.depth, proposed.height
    if not all(math.isfinite(v) for v in (w, d, h)) or not (MIN_WALL <= min(w, d) and max(w, d) <= 200):
        raise InvalidAnswer(f"room: width and depth must be from {MIN_WALL:g} to 200 m, got {w:g} x {d:g}")
    if not MIN_ROOM_HEIGHT <= h <= MAX_ROOM_HEIGHT:
        raise InvalidAnswer(f"room: height must be from {MIN_ROOM_HEIGHT:g} to {MAX_ROOM_HEIGHT:g} m, got {h:g}")
    room = Room.rectangle(w, d, h)
    wanted = [(o.kind, o.wall, 1) for o in proposed.openings]
    if not any(kind == "door" for kind, _, _ in wanted):
        wanted.append(("door", None, 1))
    return Room.model_validate({**room.model_dump(), "openings": place_openings(room, wanted)})
