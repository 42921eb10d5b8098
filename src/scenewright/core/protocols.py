"""The three kinds of backend the stages use, as protocols: what a stage may ask of each.

A vision-language model (objects, constraints, quality control, edits, judging), an image
generator (reference image, object images, ground texture) and a mesh generator (image or
description → GLB). Stages receive backend objects as arguments and never look them up; the
implementations and the registry that names them live in :mod:`scenewright.backends`, above
every stage (docs/architecture.md).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Generic, Protocol, TypeVar, runtime_checkable

from scenewright.core.plan import EditPlan
from scenewright.scene import Constraint, Event, Room, SceneObject, Vec3, Water

if TYPE_CHECKING:
    from scenewright.scene import LayoutReport, Scene


T = TypeVar("T")


@dataclass(frozen=True)
class AnchoredGroup:
    """Objects a model composed as one group (``ids``), and where the text puts one of them in
    the room (``member`` at ``anchor``: ``back``, ``wall`` or ``corner``): once the room is known
    the whole group goes there, keeping its arrangement ("a sofa at the back of the room" takes
    its coffee table and armchairs with it)."""

    member: str
    anchor: str
    ids: tuple[str, ...]


@dataclass(frozen=True)
class Answer(Generic[T]):
    """A model's answer after validation, with what had to be repaired or dropped in it to pass.

    The repairs travel with the answer (not as state left on the backend) so that one backend
    can serve several threads, and the stage that asked records them in the scene's provenance.
    """

    value: T
    repairs: tuple[Event, ...] = ()
    #: ``describe_objects`` of a model that proposes rooms (``proposes_room``): the room it
    #: proposed for the scene, None for an open scene. A backend that does not propose rooms
    #: leaves the room to the offline reading of the text (docs/rooms.md).
    room: Room | None = None
    proposes_room: bool = False
    #: ``describe_objects``: groups to move as one to where the text anchors them in the room.
    anchored: tuple[AnchoredGroup, ...] = ()
    #: ``describe_objects``: the water the objects were laid out by, None on dry land.
    water: Water | None = None


@runtime_checkable
class VisionLanguageModel(Protocol):
    """Reasons about the scene. Every answer is validated before a stage uses it."""

    name: str

    def describe_objects(self, text: str, style: str, reference: bytes | None) -> Answer[list[SceneObject]]:
        """Objects of the scene with initial position, rotation, size and visual description."""

    def write_constraints(
        self, text: str, objects: Sequence[SceneObject], reference: bytes | None, room: Room | None = None
    ) -> Answer[list[Constraint]]:
        """Spatial constraints between the objects (source is the object placed), and to the
        ``room``'s walls and ceiling when the scene has one."""

    def find_redundant(
        self, objects: Sequence[SceneObject], images: Mapping[str, bytes]
    ) -> Answer[dict[str, str]]:
        """Ids of objects whose image is already part of another object's image → reason."""

    def revise_constraints(
        self,
        text: str,
        objects: Sequence[SceneObject],
        constraints: Sequence[Constraint],
        report: LayoutReport,
        reference: bytes | None,
        room: Room | None = None,
    ) -> Answer[list[Constraint]]:
        """New constraints after the solver's ``report`` on the last ones (the paper's feedback loop)."""

    def plan_edit(self, scene: Scene, instruction: str) -> Answer[EditPlan]:
        """What an instruction asks: operation, focus object, new constraints, new object."""

    def judge(self, text: str, image: bytes, criterion: str) -> float:
        """A 1–100 score of a render against the text for one rubric criterion."""


@runtime_checkable
class ImageGenerator(Protocol):
    """Draws the reference image, the isolated object images and the ground texture."""

    name: str

    def reference_image(self, text: str, style: str) -> bytes | None:
        """PNG of the whole scene, or ``None`` when this backend draws none."""

    def object_images(
        self,
        objects: Sequence[SceneObject],
        style: str,
        reference: bytes | None,
        progress: Callable[[str], None] | None = None,
    ) -> dict[str, bytes]:
        """Transparent front-view PNG per object id (may be empty when the backend draws none)."""

    def ground_texture(self, text: str, style: str, kind: str, reference: bytes | None) -> bytes:
        """A seamless, tileable PNG of the ground."""


@dataclass(frozen=True)
class MeshRequest:
    """One asset to build: from an image where there is one, else from the description."""

    id: str
    name: str
    category: str | None
    description: str
    style: str
    size: Vec3
    image: bytes | None = None


@runtime_checkable
class MeshGenerator(Protocol):
    """Builds assets. Returns GLB bytes per request id in glTF convention (+Y up, front +Z),
    as image-to-3D models do; :mod:`scenewright.assets` normalises them to the scene frame."""

    name: str
    #: What besides the request decides the output (generation settings, a library's
    #: contents, the generators' code); part of the asset cache key, empty when nothing does.
    params: Mapping[str, Any]
    #: How many requests the assets stage hands over at once (one thread each): the jobs the
    #: backend runs at a time, or all of them when it keeps its own queue of jobs.
    concurrency: int

    def generate(
        self, requests: Sequence[MeshRequest], progress: Callable[[str], None] | None = None
    ) -> dict[str, bytes]:
        """GLB bytes per request id; raises BackendError naming every request that failed."""

    def cancel(self) -> None:
        """Abandon the requests under way (Ctrl-C); the assets stage keeps what finished."""


@dataclass
class Backends:
    """The three backends one run uses."""

    vlm: VisionLanguageModel
    images: ImageGenerator
    meshes: MeshGenerator

    def names(self) -> dict[str, str]:
        return {"vlm": self.vlm.name, "images": self.images.name, "meshes": self.meshes.name}
