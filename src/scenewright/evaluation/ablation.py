"""The paper's ablation: the same objects and assets, laid out without the solver.

"Without the layout solver" keeps the vision-language model's initial layout. The layout
stage records those poses in the document (``Scene.initial``) before its first solve, and an
``add`` edit records the pose its new object starts from, so the ablation reads exactly the
layout the solver started from; asking a remote model again would give a fresh sample.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping

import trimesh

from scenewright.layout import audit
from scenewright.scene import Scene, SceneObject

log = logging.getLogger(__name__)


def initial_objects(scene: Scene) -> list[SceneObject]:
    """The scene's objects (sizes, assets as built) at their recorded initial poses.

    An object with none recorded (a scene laid out before the poses were kept) stays where
    it is, which makes it count as solved; a warning names those objects.
    """
    missing = [obj.id for obj in scene.objects if obj.id not in scene.initial]
    if missing:
        log.warning(
            "no initial pose recorded for %s (laid out before scenewright kept them); the ablation keeps "
            "their solved poses",
            ", ".join(missing),
        )
    out = []
    for obj in scene.objects:
        pose = scene.initial.get(obj.id)
        if pose is not None:
            obj = obj.model_copy(update={"position": pose.position.model_copy(), "rotation": pose.rotation.model_copy()})
        out.append(obj)
    return out


def without_solver(
    scene: Scene, initial: list[SceneObject], meshes: Mapping[str, trimesh.Trimesh] | None = None
) -> Scene:
    """A copy of ``scene`` whose layout is the initial one, judged by :func:`~scenewright.layout.audit`."""
    result = audit(initial, scene.constraints, meshes=meshes, bounds=scene.bounds, room=scene.room)
    return scene.model_copy(update={"objects": result.objects, "layout": result.report})
