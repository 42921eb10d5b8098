"""Every backend implementation, and the registry that names them.

The protocols they implement live in :mod:`scenewright.core.protocols` (re-exported here for
callers above the stages). Each kind has an offline default (the rule-based VLM, procedural
images and meshes) and remote implementations; stages receive backend objects as arguments
and never look them up themselves.

Implementations are named by dotted path and imported only when chosen, so an unused
remote backend costs nothing and a missing extra surfaces only when it is asked for.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from scenewright.core.protocols import Backends, ImageGenerator, MeshGenerator, MeshRequest, VisionLanguageModel
from scenewright.errors import InputError, ScenewrightError

if TYPE_CHECKING:
    from scenewright.settings import Settings

__all__ = [
    "DEFAULTS", "KINDS", "REGISTRY", "Backends", "ImageGenerator", "MeshGenerator", "MeshRequest",
    "VisionLanguageModel", "available_backends", "backends_from_settings", "create_backend",
]


KINDS = ("vlm", "images", "meshes")

#: kind → backend name → "module:Class". The class has ``from_spec(argument, settings)``.
REGISTRY: dict[str, dict[str, str]] = {
    "vlm": {
        "offline": "scenewright.backends.offline_vlm:OfflineVLM",
        "openai": "scenewright.backends.openai_chat:OpenAIChatVLM",
    },
    "images": {
        "offline": "scenewright.backends.procedural_images:ProceduralImages",
        "openai": "scenewright.backends.openai_images:OpenAIImages",
    },
    "meshes": {
        "procedural": "scenewright.backends.procedural_meshes:ProceduralMeshes",
        "hunyuan3d": "scenewright.backends.hunyuan3d:Hunyuan3D",
        "gradio": "scenewright.backends.gradio:Gradio",
        "meshy": "scenewright.backends.meshy:Meshy",
        "library": "scenewright.backends.library:AssetLibrary",
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


def backends_from_settings(settings: Settings) -> Backends:
    """The three backends the settings name (``--vlm``, ``--images``, ``--meshes``)."""
    return Backends(
        vlm=create_backend("vlm", settings.vlm, settings),
        images=create_backend("images", settings.images, settings),
        meshes=create_backend("meshes", settings.meshes, settings),
    )


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
