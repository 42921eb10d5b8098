"""scenewright: text in, an editable, styled, collision-free 3D scene out.

The core imports only numpy, trimesh and pydantic; Blender, torch and the network are
reached lazily by the stages that need them.
"""

from scenewright.errors import BackendError, InfeasibleLayout, InputError, ScenewrightError
from scenewright.scene import Constraint, Scene, SceneObject, Vec3

from scenewright.version import __version__

__all__ = [
    "BackendError",
    "Constraint",
    "InfeasibleLayout",
    "InputError",
    "Scene",
    "SceneObject",
    "ScenewrightError",
    "Vec3",
    "__version__",
]
