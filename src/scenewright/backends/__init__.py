"""Backend protocols and the registry that names their implementations.

Three kinds of model serve the stages: a vision-language model (objects, constraints,
quality control, edits, judging), an image generator (reference image, object images,
ground texture) and a mesh generator (image or description → GLB). Each kind has an
offline default and remote implementations; stages receive backend objects as arguments
and never look them up themselves.

Implementations are named by dotted path and imported only when chosen, so an unused
remote backend costs nothing and a missing extra surfaces only when it is asked for.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

from scenewright.errors import InputError, ScenewrightError
from scenewright.scene import Constraint, SceneObject, Vec3

if TYPE_CHECKING:
    from scenewright.editing.plan import EditPlan
    from scenewright.scene import LayoutReport, Scene
    from scenewright.settings import Settings


@runtime_checkable
class VisionLanguageModel(Protocol):
    """Reasons about the scene. Every answer is validated before a stage uses it."""

    name: str

    def describe_objects(self, text: str, style: str, reference: bytes | None) -> list[SceneObject]:
        """Objects of the scene with initial position, rotation, size and visual description."""

    def write_constraints(
        self, text: str, objects: Sequence[SceneObject], reference: bytes | None
    ) -> list[Constraint]:
        """Spatial constraints between the objects (source is the object placed)."""

    def find_redundant(self, objects: Sequence[SceneObject], images: Mapping[str, bytes]) -> dict[str, str]:
        """Ids of objects whose image is already part of another object's image → reason."""

    def revise_constraints(
        self,
        text: str,
        objects: Sequence[SceneObject],
        constraints: Sequence[Constraint],
        report: LayoutReport,
        reference: bytes | None,
    ) -> list[Constraint]:
        """New constraints after the solver's ``report`` on the last ones (the paper's feedback loop)."""

    def plan_edit(self, scene: Scene, instruction: str) -> EditPlan:
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

    def generate(
        self, requests: Sequence[MeshRequest], progress: Callable[[str], None] | None = None
    ) -> dict[str, bytes]:
        """GLB bytes per request id; raises BackendError naming every request that failed."""


KINDS = ("vlm", "images", "meshes")

#: kind → backend name → "module:Class". The class has ``from_spec(argument, settings)``.
REGISTRY: dict[str, dict[str, str]] = {
    "vlm": {
        "offline": "scenewright.analysis.offline:OfflineVLM",
        "openai": "scenewright.backends.openai_chat:OpenAIChatVLM",
    },
    "images": {
        "offline": "scenewright.procedural.images:ProceduralImages",
        "openai": "scenewright.backends.openai_images:OpenAIImages",
    },
    "meshes": {
        "procedural": "scenewright.procedural.meshes:ProceduralMeshes",
        "hunyuan3d": "scenewright.backends.hunyuan3d:Hunyuan3D",
        "gradio": "scenewright.backends.gradio:Gradio",
        "meshy": "scenewright.backends.meshy:Meshy",
        "library": "scenewright.assets.library:AssetLibrary",
    },
}
#: Offline default per kind.
DEFAULTS = {"vlm": "offline", "images": "offline", "meshes": "procedural"}


def _resolve(kind: str, name: str) -> type:
    if kind not in REGISTRY:
        raise InputError(f"unknown backend kind {kind!r}; kinds are {', '.join(KINDS)}")
    table = REGISTRY[kind]
    if name not in table:
        raise InputError(f"unknown {kind} backend {name!r}; choose one of: {', '.join(table)}")
    module, _, cls = table[name].partition(":")
    return getattr(importlib.import_module(module), cls)


def create_backend(kind: str, spec: str, settings: Settings) -> Any:
    """Build the backend a spec such as ``openai:o3`` or ``hunyuan3d:http://h:8081`` names."""
    name, _, argument = spec.partition(":")
    return _resolve(kind, name.strip().lower()).from_spec(argument.strip(), settings)


@dataclass
class Backends:
    """The three backends one run uses."""

    vlm: VisionLanguageModel
    images: ImageGenerator
    meshes: MeshGenerator

    @classmethod
    def from_settings(cls, settings: Settings) -> Backends:
        return cls(
            vlm=create_backend("vlm", settings.vlm, settings),
            images=create_backend("images", settings.images, settings),
            meshes=create_backend("meshes", settings.meshes, settings),
        )

    def names(self) -> dict[str, str]:
        return {"vlm": self.vlm.name, "images": self.images.name, "meshes": self.meshes.name}


def available_backends() -> dict[str, dict[str, str]]:
    """kind → name → "ok" or why it cannot be used here (a missing extra), for the CLI."""
    result: dict[str, dict[str, str]] = {}
    for kind, table in REGISTRY.items():
        result[kind] = {}
        for name in table:
            try:
                _resolve(kind, name)
                result[kind][name] = "ok"
            except (ImportError, ScenewrightError) as exc:
                result[kind][name] = str(exc)
    return result
