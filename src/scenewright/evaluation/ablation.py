"""The paper's ablation: the same objects and assets, laid out without the solver.

"Without the layout solver" keeps the vision-language model's initial layout. A finished
scene holds only the solved poses, so the initial ones are asked again from the same
backend; the offline backend is deterministic and gives back exactly the poses the
analysis stage started from (a remote one gives a fresh sample of the same kind).
"""

from __future__ import annotations

from collections.abc import Mapping

import trimesh

from scenewright.backends import VisionLanguageModel
from scenewright.folder import SceneFolder
from scenewright.layout import solve
from scenewright.scene import Scene, SceneObject


def initial_objects(scene: Scene, folder: SceneFolder, vlm: VisionLanguageModel) -> list[SceneObject]:
    """The scene's objects (sizes, assets as built) at the poses the backend first proposed."""
    reference = folder.reference_image.read_bytes() if folder.reference_image.is_file() else None
    proposed = {obj.id: obj for obj in vlm.describe_objects(scene.text, scene.style, reference)}
    return [
        obj.model_copy(update={"position": proposed[obj.id].position, "rotation": proposed[obj.id].rotation})
        if obj.id in proposed
        else obj
        for obj in scene.objects
    ]


def without_solver(
    scene: Scene, initial: list[SceneObject], meshes: Mapping[str, trimesh.Trimesh] | None = None
) -> Scene:
    """A copy of ``scene`` whose layout is the initial one, as ``solve(use_solver=False)`` keeps it."""
    result = solve(initial, scene.constraints, meshes=meshes, bounds=scene.bounds, use_solver=False)
    return scene.model_copy(update={"objects": result.objects, "layout": result.report})
