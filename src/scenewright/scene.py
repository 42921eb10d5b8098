"""The scene document: one versioned pydantic model, saved atomically as ``scene.json``.

Every stage reads a :class:`Scene`, adds what it produces and writes it back, so a run that
stops half way resumes from what is on disk. The document holds plain data only (no
backend objects, no meshes): paths to images and assets are relative to the scene folder.

Frames (docs/architecture.md, "Frames and units"): +X right, +Y backward, +Z up, metres, degrees. ``position`` is the
centre of the object's bounding box (the paper's convention, which is what a model writes);
``size`` is the axis-aligned extent at yaw 0; at yaw 0 an object's front faces −Y.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from scenewright.errors import InputError
from scenewright.files import write_atomic
from scenewright.settings import MAX_SEED, STYLES  # noqa: F401  (defined there so the CLI need not load pydantic)

#: Version 2 added ``room``; :func:`migrate` brings older documents up to date.
SCHEMA_VERSION = 2

#: The ten relations of the paper (Table 3) and the type each belongs to. Their geometry is
#: defined once, in :mod:`scenewright.layout.relations`.
RELATION_TYPES: dict[str, str] = {
    "left of": "relative",
    "right of": "relative",
    "in front of": "relative",
    "behind": "relative",
    "side of": "relative",
    "near": "distance",
    "far": "distance",
    "on": "vertical",
    "above": "vertical",
    "face to": "rotation",
    # Relations to the room (an indoor scene's walls and ceiling), not to another object: their
    # targets are the reserved ids below. Geometry in :mod:`scenewright.layout.relations` too.
    "against wall": "room",
    "in corner": "room",
    "on wall": "room",
    "on ceiling": "room",
}
Relation = Literal[
    "left of", "right of", "in front of", "behind", "side of", "near", "far", "on", "above", "face to",
    "against wall", "in corner", "on wall", "on ceiling",
]
RelationType = Literal["relative", "distance", "vertical", "rotation", "room"]
#: The relations whose target is the room rather than an object.
ROOM_RELATIONS = ("against wall", "in corner", "on wall", "on ceiling")
#: Reserved target ids of the room relations: ``room`` means any wall (the ceiling for ``on
#: ceiling``), ``wall_<i>`` wall ``i`` of :attr:`Room.walls`, ``ceiling`` the ceiling.
ROOM_TARGET, CEILING_TARGET, WALL_PREFIX = "room", "ceiling", "wall_"
_WALL_TARGET = re.compile(r"^wall_(\d{1,3})$")


def room_target(target: str) -> int | str | None:
    """What a reserved target id names: a wall index, ``"room"``, ``"ceiling"``; None when it is
    no reserved id (an object's id)."""
    if target in (ROOM_TARGET, CEILING_TARGET):
        return target
    m = _WALL_TARGET.match(target)
    return int(m.group(1)) if m else None

DEFAULT_STYLE = "realistic"

_ID = re.compile(r"^[A-Za-z0-9_\-.]+$")

#: Sane bounds for every length a document or a model answer gives, in metres: a position
#: further out, or a size outside them, is a typo or a broken answer, never a scene.
MAX_COORDINATE = 10_000.0
MIN_SIZE = 0.001
MAX_SIZE = 1_000.0
# --- limits on what a document (and so a model's answer) may hold (docs/security.md) ---------
# Fixed rather than configured: a scene must load the same on every machine. Ids name files.
MAX_ID_CHARS = 64
MAX_NAME_CHARS = 200
MAX_DESCRIPTION_CHARS = 2_000
MAX_TEXT_CHARS = 20_000
MAX_STYLE_CHARS = 40
_STYLE = re.compile(r"^[A-Za-z0-9][A-Za-z0-9 _\-]*$")


def _at_most(limit: int):
    """A field validator: the string has at most ``limit`` characters."""

    def check(cls, v: Any) -> Any:
        if isinstance(v, str) and len(v) > limit:
            raise ValueError(f"{len(v)} characters, more than the {limit} allowed")
        return v

    return classmethod(check)


class _Model(BaseModel):
    # NaN and infinity are refused in every float field: one of them in a pose poisons the
    # solver, the GLB and every later save (JSON has no spelling for them).
    model_config = ConfigDict(extra="forbid", validate_assignment=True, allow_inf_nan=False)


class Vec3(_Model):
    x: float = 0.0
    y: float = 0.0
    z: float = 0.0

    def tuple(self) -> tuple[float, float, float]:
        return (self.x, self.y, self.z)

    @classmethod
    def of(cls, values) -> Vec3:
        x, y, z = (float(v) for v in values)
        return cls(x=x, y=y, z=z)


def check_position(v: Vec3) -> Vec3:
    """``v`` when every coordinate is within ±MAX_COORDINATE metres; else ValueError saying so."""
    if max(abs(c) for c in v.tuple()) > MAX_COORDINATE:
        raise ValueError(f"a position must lie within ±{MAX_COORDINATE:g} m of the origin, got {v.tuple()}")
    return v


def check_size(v: Vec3) -> Vec3:
    """``v`` when every extent is between MIN_SIZE and MAX_SIZE metres; else ValueError saying so."""
    if min(v.tuple()) < MIN_SIZE or max(v.tuple()) > MAX_SIZE:
        raise ValueError(f"every size must be between {MIN_SIZE:g} and {MAX_SIZE:g} metres, got {v.tuple()}")
    return v
class ObjectPhysics(_Model):
    """What a simulator needs of an object, derived from its asset (:mod:`scenewright.export.physics`).

    Mass, centre of mass and inertia are in the asset frame (bottom centre at the origin,
    front −Y, before the object's pose); ``inertia`` is (ixx, iyy, izz, ixy, ixz, iyz) about
    the centre of mass in kg m². ``collider`` is the file of convex pieces in the scene folder.
    ``key`` hashes what the record was derived from: when the asset or the object's words
    change, the record is derived again.
    """

    static: bool
    mass: float = Field(gt=0)
    center_of_mass: Vec3
    inertia: tuple[float, float, float, float, float, float]
    friction: float = Field(gt=0)
    material: str
    density: float = Field(gt=0)
    volume: float = Field(ge=0)
    collider: str
    method: Literal["hull", "parts", "coacd"]
    hulls: int = Field(ge=1)
    notes: list[str] = Field(default_factory=list)
    key: str


class SceneObject(_Model):
    """One object of the scene; the fields of the paper's object JSON plus provenance."""

    id: str
    name: str
    category: str | None = None
    position: Vec3 = Field(default_factory=Vec3)
    rotation: Vec3 = Field(default_factory=Vec3)
    size: Vec3
    visual_description: str = ""
    asset: str | None = None
    image: str | None = None
    physics: ObjectPhysics | None = None

    @field_validator("id")
    @classmethod
    def _id_is_a_name(cls, v: str) -> str:
        if not _ID.match(v):
            raise ValueError(f"id {v!r} must use only letters, digits, '_', '-' and '.'")
        return v

    @field_validator("size")
    @classmethod
    def _size_is_sane(cls, v: Vec3) -> Vec3:
        return check_size(v)

    @field_validator("position")
    @classmethod
    def _position_is_sane(cls, v: Vec3) -> Vec3:
        return check_position(v)

    @property
    def yaw(self) -> float:
        return self.rotation.z

    # limits (docs/security.md)
    _id_length = field_validator("id")(_at_most(MAX_ID_CHARS))
    _name_length = field_validator("name", "category")(_at_most(MAX_NAME_CHARS))
    _description_length = field_validator("visual_description")(_at_most(MAX_DESCRIPTION_CHARS))


class Pose(_Model):
    """Where an object stands and how it is turned, apart from what it is."""

    position: Vec3
    rotation: Vec3

    @field_validator("position")
    @classmethod
    def _position_is_sane(cls, v: Vec3) -> Vec3:
        return check_position(v)


class Constraint(_Model):
    """⟨type, relation, source, target⟩: ``source`` is the object being placed."""

    type: RelationType | None = None
    relation: Relation
    source: str
    target: str

    @field_validator("relation", mode="before")
    @classmethod
    def _normalise_relation(cls, v: Any) -> Any:
        if isinstance(v, str):
            v = " ".join(v.strip().lower().replace("_", " ").split())
            if v not in RELATION_TYPES:
                raise ValueError(f"unknown relation {v!r}; valid relations: {', '.join(RELATION_TYPES)}")
        return v

    @model_validator(mode="after")
    def _type_follows_relation(self) -> Constraint:
        # Models often mislabel the type (the paper's own example types "on" as relative);
        # the relation decides.
        expected = RELATION_TYPES[self.relation]
        if self.type != expected:
            object.__setattr__(self, "type", expected)
        return self

    def key(self) -> tuple[str, str, str]:
        return (self.relation, self.source, self.target)

    # limits (docs/security.md)
    _id_length = field_validator("source", "target")(_at_most(MAX_ID_CHARS))

    def __str__(self) -> str:
        return f"{self.source} {self.relation} {self.target}"


class RemovedObject(_Model):
    """An object dropped from the scene (quality control, an edit), kept on record."""

    id: str
    name: str
    reason: str

    # limits (docs/security.md)
    _id_length = field_validator("id")(_at_most(MAX_ID_CHARS))
    _name_length = field_validator("name")(_at_most(MAX_NAME_CHARS))
    _reason_length = field_validator("reason")(_at_most(MAX_DESCRIPTION_CHARS))


#: m, the water's surface above the ground: a hull or a swimmer's body sits a little in it.
WATER_LEVEL = 0.05


class Water(_Model):
    """Open water the scene lies by: it covers the ground beyond the shore line ``shore``
    (y, metres), the back of the scene seen from the viewer, to the ground's far edge.

    The back, because a viewer stands on the land looking out, so the land's things stand in
    front of the boats and both are seen; and one straight shore is what a designer sketches
    for a quay, a beach or a river bank."""

    shore: float = Field(ge=-MAX_COORDINATE, le=MAX_COORDINATE)


class Ground(_Model):
    kind: str = "grass"
    texture: str | None = None
    description: str = ""
    #: The water beyond the shore, for a scene by a river, a lake, the sea; none on dry land.
    water: Water | None = None

    # limits (docs/security.md)
    _kind_length = field_validator("kind")(_at_most(MAX_NAME_CHARS))
    _description_length = field_validator("description")(_at_most(MAX_DESCRIPTION_CHARS))


#: Room limits: a wall shorter than this is a typo, a room taller than this is a hall, not a room.
MIN_WALL = 0.5
MIN_ROOM_HEIGHT, MAX_ROOM_HEIGHT = 2.0, 12.0


class Opening(_Model):
    """A door or window cut into one wall of the room.

    ``wall`` indexes :attr:`Room.walls`; ``offset`` is the distance in metres along that wall,
    from its start corner, to the opening's centre; ``sill`` is the height of its bottom edge
    above the floor (0 for a door).
    """

    kind: Literal["door", "window"]
    wall: int = Field(ge=0)
    offset: float = Field(ge=0)
    width: float = Field(gt=0)
    height: float = Field(gt=0)
    sill: float = Field(default=0.0, ge=0)

    @model_validator(mode="after")
    def _door_on_the_floor(self) -> Opening:
        if self.kind == "door" and self.sill != 0:
            raise ValueError(f"a door starts at the floor (sill 0), got sill {self.sill:g} m")
        return self


class Room(_Model):
    """The room of an indoor scene: a floor polygon, walls along its edges, openings in them.

    ``floor`` lists the corners (x, y) counter-clockwise seen from above, so each wall's inside
    is to its left; wall ``i`` runs from corner ``i`` to corner ``i + 1`` (the last one closes
    the polygon). The floor is at z = 0 and the ceiling at ``height``.
    """

    floor: list[tuple[float, float]]
    height: float = 2.7
    openings: list[Opening] = Field(default_factory=list)
    floor_material: str = "wood floor"
    wall_material: str = "painted plaster"
    ceiling_material: str = "white plaster"

    @classmethod
    def rectangle(cls, width: float, depth: float, height: float = 2.7, **fields: Any) -> Room:
        """A ``width`` (x) by ``depth`` (y) room centred at the origin; walls front, right, back, left."""
        w, d = width / 2.0, depth / 2.0
        return cls(floor=[(-w, -d), (w, -d), (w, d), (-w, d)], height=height, **fields)

    @property
    def walls(self) -> list[tuple[tuple[float, float], tuple[float, float]]]:
        """The wall segments (start, end), in the order openings index them."""
        n = len(self.floor)
        return [(self.floor[i], self.floor[(i + 1) % n]) for i in range(n)]

    def wall_length(self, index: int) -> float:
        (x0, y0), (x1, y1) = self.walls[index]
        return ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5

    @field_validator("height")
    @classmethod
    def _height_is_a_room(cls, v: float) -> float:
        if not MIN_ROOM_HEIGHT <= v <= MAX_ROOM_HEIGHT:
            raise ValueError(f"a room's height must be from {MIN_ROOM_HEIGHT:g} to {MAX_ROOM_HEIGHT:g} m, got {v:g}")
        return v

    @field_validator("floor")
    @classmethod
    def _floor_is_a_simple_polygon(cls, v: list[tuple[float, float]]) -> list[tuple[float, float]]:
        if len(v) < 3:
            raise ValueError(f"a floor needs at least 3 corners, got {len(v)}")
        if max(abs(c) for p in v for c in p) > MAX_COORDINATE:
            raise ValueError(f"every floor corner must lie within ±{MAX_COORDINATE:g} m of the origin")
        n = len(v)
        for i in range(n):
            a, b = v[i], v[(i + 1) % n]
            if ((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2) ** 0.5 < MIN_WALL:
                raise ValueError(f"wall {i} from {a} to {b} is shorter than {MIN_WALL:g} m")
            for j in range(i + 2, n):
                if i == 0 and j == n - 1:
                    continue  # the first and last walls share a corner
                if _segments_cross(a, b, v[j], v[(j + 1) % n]):
                    raise ValueError(f"the floor polygon intersects itself: wall {i} crosses wall {j}")
        area = _signed_area(v)
        if abs(area) < MIN_WALL**2:
            raise ValueError(f"the floor polygon encloses {abs(area):.3g} m², too little for a room")
        # Clockwise as given: the same room with its walls listed the other way round.
        return v if area > 0 else list(reversed(v))

    @model_validator(mode="after")
    def _openings_fit_their_walls(self) -> Room:
        for k, o in enumerate(self.openings):
            if o.wall >= len(self.floor):
                raise ValueError(f"opening {k} is on wall {o.wall}, but the room has walls 0..{len(self.floor) - 1}")
            length = self.wall_length(o.wall)
            if o.offset - o.width / 2 < 0 or o.offset + o.width / 2 > length:
                raise ValueError(
                    f"opening {k} ({o.kind}, {o.width:g} m wide at {o.offset:g} m) does not fit on wall "
                    f"{o.wall}, which is {length:.2f} m long"
                )
            if o.sill + o.height > self.height:
                raise ValueError(
                    f"opening {k} ({o.kind}) reaches {o.sill + o.height:g} m, above the {self.height:g} m ceiling"
                )
        return self

    _material_length = field_validator("floor_material", "wall_material", "ceiling_material")(
        _at_most(MAX_NAME_CHARS)
    )


def _signed_area(points: list[tuple[float, float]]) -> float:
    """Shoelace area: positive when the corners run counter-clockwise."""
    n = len(points)
    return 0.5 * sum(points[i][0] * points[(i + 1) % n][1] - points[(i + 1) % n][0] * points[i][1] for i in range(n))


def _segments_cross(a, b, c, d) -> bool:
    """True when segment ab and segment cd share a point (touching counts)."""

    def orient(p, q, r) -> float:
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])

    def within(p, q, r) -> bool:
        return min(p[0], q[0]) - 1e-9 <= r[0] <= max(p[0], q[0]) + 1e-9 and min(p[1], q[1]) - 1e-9 <= r[1] <= max(p[1], q[1]) + 1e-9

    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    if (o1 > 0) != (o2 > 0) and (o3 > 0) != (o4 > 0) and 0 not in (o1, o2, o3, o4):
        return True
    return any(
        abs(o) < 1e-12 and within(p, q, r) for o, p, q, r in ((o1, a, b, c), (o2, a, b, d), (o3, c, d, a), (o4, c, d, b))
    )


class DroppedConstraint(_Model):
    constraint: dict[str, Any]
    reason: str


class UnplacedObject(_Model):
    id: str
    failed: list[Constraint] = Field(default_factory=list)
    reason: str
    nearest_miss: str | None = None


class LayoutReport(_Model):
    """What the solver did: the feedback the vision-language model revises constraints from."""

    placed: list[str] = Field(default_factory=list)
    unplaced: list[UnplacedObject] = Field(default_factory=list)
    dropped: list[DroppedConstraint] = Field(default_factory=list)
    nodes: int = 0
    seconds: float = 0.0
    solver: bool = True
    #: What the room check found wrong with the final layout (a blocked door, an object no one
    #: can walk to from a door), one sentence each; empty without a room or when all is well.
    room: list[str] = Field(default_factory=list)

    @property
    def complete(self) -> bool:
        return not self.unplaced


class Event(_Model):
    """One provenance record: which stage did what, when, with which backend."""

    stage: str
    message: str
    data: dict[str, Any] = Field(default_factory=dict)
    time: str = Field(default_factory=lambda: datetime.now(timezone.utc).isoformat(timespec="seconds"))


class Scene(_Model):
    schema_version: int = SCHEMA_VERSION
    text: str
    style: str = DEFAULT_STYLE
    seed: int = 0
    objects: list[SceneObject] = Field(default_factory=list)
    constraints: list[Constraint] = Field(default_factory=list)
    removed: list[RemovedObject] = Field(default_factory=list)
    ground: Ground = Field(default_factory=Ground)
    #: Optional footprint (width along x, depth along y), centred at the origin.
    bounds: tuple[float, float] | None = None
    #: The room of an indoor scene; None for an open scene on the ground plane.
    room: Room | None = None
    backends: dict[str, str] = Field(default_factory=dict)
    layout: LayoutReport | None = None
    #: The poses the vision-language model proposed, before the solver moved anything; kept for
    #: the paper's without-solver ablation, since a remote model asked again answers afresh.
    initial: dict[str, Pose] = Field(default_factory=dict)
    #: Names of the stages whose output is complete, in order; drives resume.
    done: list[str] = Field(default_factory=list)
    #: SHA-256 of the ``scene.glb`` assembled from this document. The GLB is written before the
    #: document, so a run killed in between leaves a GLB that does not match; it is rebuilt.
    glb_sha256: str | None = None
    provenance: list[Event] = Field(default_factory=list)

    @field_validator("schema_version")
    @classmethod
    def _known_version(cls, v: int) -> int:
        if v > SCHEMA_VERSION:
            raise ValueError(
                f"scene.json has schema_version {v}, newer than this scenewright understands "
                f"({SCHEMA_VERSION}); upgrade scenewright"
            )
        return v

    @field_validator("bounds")
    @classmethod
    def _bounds_are_sane(cls, v: tuple[float, float] | None) -> tuple[float, float] | None:
        if v is not None and not all(0 < side <= 2 * MAX_COORDINATE for side in v):
            raise ValueError(f"bounds (width, depth) must each be > 0 and at most {2 * MAX_COORDINATE:g} m, got {v}")
        return v

    # limits (docs/security.md)
    _text_length = field_validator("text")(_at_most(MAX_TEXT_CHARS))

    @field_validator("schema_version")
    @classmethod
    def _version_positive(cls, v: int) -> int:
        if v < 1:
            raise ValueError(f"schema_version {v} is not a version scenewright ever wrote (1..{SCHEMA_VERSION})")
        return v

    @field_validator("seed")
    @classmethod
    def _seed_in_range(cls, v: int) -> int:
        if not 0 <= v <= MAX_SEED:
            raise ValueError(f"the seed must be from 0 to {MAX_SEED}, got {v}")
        return v

    @field_validator("style")
    @classmethod
    def _style_is_a_word(cls, v: str) -> str:
        if len(v) > MAX_STYLE_CHARS or not _STYLE.match(v):
            raise ValueError(
                f"style {v[:60]!r} must be a name of at most {MAX_STYLE_CHARS} letters, digits, spaces, "
                f"'-' and '_' (e.g. {', '.join(STYLES)})"
            )
        return v

    @model_validator(mode="after")
    def _ids_unique(self) -> Scene:
        seen: set[str] = set()
        for obj in self.objects:
            if obj.id in seen:
                raise ValueError(f"object id {obj.id!r} is used twice")
            seen.add(obj.id)
        return self

    def get(self, object_id: str) -> SceneObject:
        for obj in self.objects:
            if obj.id == object_id:
                return obj
        known = ", ".join(o.id for o in self.objects) or "none"
        raise InputError(f"no object with id {object_id!r}; objects are: {known}")

    def remember_initial_poses(self, ids: Iterable[str] | None = None) -> None:
        """Record the current pose of each object (of ``ids``, else every one) as its initial one.

        An object that already has one keeps it: the first proposal is what the ablation
        measures, and a resumed or repeated layout starts from poses the solver already moved.
        """
        wanted = None if ids is None else set(ids)
        for obj in self.objects:
            if obj.id not in self.initial and (wanted is None or obj.id in wanted):
                self.initial[obj.id] = Pose(position=obj.position.model_copy(), rotation=obj.rotation.model_copy())

    def record(self, stage: str, message: str, **data: Any) -> None:
        self.provenance.append(Event(stage=stage, message=message, data=data))

    def to_json(self) -> str:
        return self.model_dump_json(indent=2) + "\n"

    @classmethod
    def from_json(cls, document: str | bytes) -> Scene:
        """The scene in ``document``, migrated from an older schema version when need be.

        Raises pydantic's ValidationError for anything that is not a valid scene, bad JSON too.
        """
        try:
            data = json.loads(document)
        except ValueError:
            return cls.model_validate_json(document)  # raises the ValidationError that says where
        return cls.model_validate(migrate(data))

    def save(self, path: str | Path) -> Path:
        return write_atomic(path, self.to_json())

    @classmethod
    def load(cls, path: str | Path) -> Scene:
        path = Path(path)
        try:
            raw = path.read_text(encoding="utf-8")
        except FileNotFoundError:
            raise InputError(f"{path}: no such file") from None
        except UnicodeDecodeError as exc:
            raise InputError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start})") from None
        try:
            data = json.loads(raw)
        except json.JSONDecodeError as exc:
            raise InputError(f"{path}: not valid JSON ({exc.msg} at line {exc.lineno})") from None
        try:
            return cls.model_validate(migrate(data))
        except ValidationError as exc:
            raise InputError(f"{path}: {describe_validation_error(exc)}") from None


def migrate(data: Any) -> Any:
    """A document of an older schema version brought up to this one (the input is not changed).

    Each step takes version ``n`` to ``n + 1``; a version newer than this scenewright, or not a
    number, is left for validation to refuse with its message.
    """
    if not isinstance(data, dict) or not isinstance(data.get("schema_version", 1), int):
        return data
    data = dict(data)
    version = data.get("schema_version", 1)
    if version == 1:  # 1 -> 2: rooms arrived; a version-1 scene stands on the open ground
        data["room"] = None
        version = 2
    if 1 <= version <= SCHEMA_VERSION:
        data["schema_version"] = version
    return data


def describe_validation_error(exc: ValidationError, limit: int = 5) -> str:
    """A one-line summary naming each bad field by its path, for users and for model retries."""
    parts = []
    for err in exc.errors()[:limit]:
        where = ".".join(str(p) for p in err["loc"]) or "(top level)"
        parts.append(f"{where}: {err['msg']}")
    more = len(exc.errors()) - limit
    if more > 0:
        parts.append(f"... and {more} more")
    return "; ".join(parts)
