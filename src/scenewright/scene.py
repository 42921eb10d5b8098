"""The scene document: one versioned pydantic model, saved atomically as ``scene.json``.

Every stage reads a :class:`Scene`, adds what it produces and writes it back, so a run that
stops half way resumes from what is on disk. The document holds plain data only (no
backend objects, no meshes): paths to images and assets are relative to the scene folder.

Frames (DESIGN.md §3): +X right, +Y backward, +Z up, metres, degrees. ``position`` is the
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

SCHEMA_VERSION = 1

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
}
Relation = Literal[
    "left of", "right of", "in front of", "behind", "side of", "near", "far", "on", "above", "face to"
]
RelationType = Literal["relative", "distance", "vertical", "rotation"]

#: Styles every backend understands; free text is accepted and mapped by each backend.
STYLES = ("realistic", "cartoon", "low-poly", "cyberpunk", "steampunk", "anime")
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
#: Seeds feed numpy's generator, which takes 0 .. 2**32 - 1.
MAX_SEED = 2**32 - 1
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


class Ground(_Model):
    kind: str = "grass"
    texture: str | None = None
    description: str = ""

    # limits (docs/security.md)
    _kind_length = field_validator("kind")(_at_most(MAX_NAME_CHARS))
    _description_length = field_validator("description")(_at_most(MAX_DESCRIPTION_CHARS))


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
            return cls.model_validate(data)
        except ValidationError as exc:
            raise InputError(f"{path}: {describe_validation_error(exc)}") from None


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
