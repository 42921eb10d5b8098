"""scenewright: text in, an editable, styled, collision-free 3D scene out.

The stage functions a library user calls are re-exported here and imported on first use
(PEP 562 module ``__getattr__``), so ``import scenewright`` loads the errors only; the document
model (pydantic), trimesh, scipy, fcl, Blender and the network are paid for by what runs
(docs/architecture.md, "Layers")::

    from pathlib import Path

    import scenewright as sw

    settings = sw.Settings(cache_dir=Path.home() / ".cache" / "scenewright")
    backends = sw.backends_from_settings(settings)  # offline by default: no key, no GPU
    scene = sw.generate("a sofa facing a TV, a lamp beside the sofa", "living-room",
                        backends=backends, settings=settings, render=False)
    scene = sw.apply_edit(scene, sw.SceneFolder("living-room"), "move the lamp left of the TV",
                          backends=backends, settings=settings)
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from scenewright.errors import BackendError, InfeasibleLayout, InputError, ScenewrightError
from scenewright.version import __version__

#: name → module that defines it, imported when the name is first read.
_LAZY = {
    "Constraint": "scenewright.scene",
    "Scene": "scenewright.scene",
    "SceneObject": "scenewright.scene",
    "Vec3": "scenewright.scene",
    "generate": "scenewright.pipeline",
    "resume": "scenewright.pipeline",
    "analyze": "scenewright.analysis.stage",
    "generate_assets": "scenewright.assets.stage",
    "arrange": "scenewright.layout.stage",
    "solve": "scenewright.layout.solver",
    "audit": "scenewright.layout.solver",
    "assemble": "scenewright.export.glb",
    "export_scene": "scenewright.export.sim",
    "apply_edit": "scenewright.editing.apply",
    "undo": "scenewright.editing.history",
    "redo": "scenewright.editing.history",
    "evaluate": "scenewright.evaluation",
    "backends_from_settings": "scenewright.backends",
    "create_backend": "scenewright.backends",
    "Settings": "scenewright.settings",
    "SceneFolder": "scenewright.folder",
    "EditPlan": "scenewright.core.plan",
}

if TYPE_CHECKING:
    from scenewright.analysis.stage import analyze
    from scenewright.assets.stage import generate_assets
    from scenewright.backends import backends_from_settings, create_backend
    from scenewright.core.plan import EditPlan
    from scenewright.editing.apply import apply_edit
    from scenewright.editing.history import redo, undo
    from scenewright.evaluation import evaluate
    from scenewright.export.glb import assemble
    from scenewright.export.sim import export_scene
    from scenewright.folder import SceneFolder
    from scenewright.layout.solver import audit, solve
    from scenewright.layout.stage import arrange
    from scenewright.pipeline import generate, resume
    from scenewright.scene import Constraint, Scene, SceneObject, Vec3
    from scenewright.settings import Settings

__all__ = [
    "BackendError",
    "InfeasibleLayout",
    "InputError",
    "ScenewrightError",
    "__version__",
    *_LAZY,
]


def __getattr__(name: str) -> Any:
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'scenewright' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value  # read once; later lookups do not come here
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
