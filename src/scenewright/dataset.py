"""The dataset view of a scene: ``scene_graph.json``, what embodied-AI code loads.

Per object: id, category, name, pose (position of the box centre and a unit quaternion
``[w, x, y, z]``, scene frame: +X right, +Y backward, +Z up, metres), the world box, and the
object it rests on (``null``: the ground or hanging). Relations come in two lists: the
*stated* ones (the scene's constraints, each with whether it holds in the final layout) and
the *geometric* ones that hold between every pair, by the layout engine's own checks
(:mod:`scenewright.layout.relations`): left of, right of, in front of, behind and on for
each ordered pair, near once per unordered pair.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from scenewright.evaluation.stated import supports
from scenewright.geometry import rotation_matrix, world_box
from scenewright.layout import check
from scenewright.layout.relations import Boxes, holds
from scenewright.scene import Scene, SceneObject

FORMAT = "scenewright.scene_graph/1"
#: Relations listed for every ordered pair that satisfies them.
DIRECTED = ("left of", "right of", "in front of", "behind", "on")
#: Symmetric relations, listed once per pair (source id < target id).
SYMMETRIC = ("near",)


def quaternion(obj: SceneObject) -> list[float]:
    """``[w, x, y, z]`` of the object's rotation (w >= 0), from its rotation matrix."""
    from scipy.spatial.transform import Rotation

    x, y, z, w = Rotation.from_matrix(rotation_matrix(obj.rotation)).as_quat()
    q = np.array([w, x, y, z])
    if q[0] < 0:
        q = -q
    return [round(float(v), 9) for v in q]


def _boxes(objects: list[SceneObject]) -> tuple[Boxes, Boxes]:
    corners = [world_box(o) for o in objects]
    lo = np.array([c[0] for c in corners])
    hi = np.array([c[1] for c in corners])
    yaw = np.array([o.yaw for o in objects], dtype=float)
    return Boxes(lo[:, None], hi[:, None], yaw[:, None]), Boxes(lo[None], hi[None], yaw[None])


def geometric_relations(objects: list[SceneObject]) -> list[dict[str, str]]:
    """Every relation of :data:`DIRECTED` and :data:`SYMMETRIC` that holds, all pairs at once."""
    if len(objects) < 2:
        return []
    sources, targets = _boxes(objects)
    ids = [o.id for o in objects]
    found: list[dict[str, str]] = []
    for relation in (*DIRECTED, *SYMMETRIC):
        mask = holds(relation, sources, targets)
        np.fill_diagonal(mask, False)
        for i, j in zip(*np.nonzero(mask)):
            if relation in SYMMETRIC and ids[i] > ids[j]:
                continue
            found.append({"source": ids[i], "relation": relation, "target": ids[j]})
    found.sort(key=lambda r: (r["source"], r["relation"], r["target"]))
    return found


def scene_graph(scene: Scene, *, scene_id: str, metrics: dict[str, Any] | None = None) -> dict[str, Any]:
    """The scene as a graph of posed objects and relations (see the module docstring)."""
    rests = supports(scene.objects)
    by_id = {o.id: o for o in scene.objects}
    objects = []
    for obj in scene.objects:
        lo, hi = world_box(obj)
        hosts = rests[obj.id][1]
        objects.append(
            {
                "id": obj.id,
                "category": obj.category,
                "name": obj.name,
                "description": obj.visual_description,
                "pose": {"position": list(obj.position.tuple()), "quaternion": quaternion(obj)},
                "size": list(obj.size.tuple()),
                "box": {"min": [float(v) for v in lo], "max": [float(v) for v in hi]},
                # The highest host when an object spans several (a rug under a table's legs).
                "support": max(hosts, key=lambda h: world_box(by_id[h])[1][2]) if hosts else None,
                "asset": obj.asset,
            }
        )
    stated = [
        {
            "source": c.source,
            "relation": c.relation,
            "target": c.target,
            "holds": check(c.relation, by_id[c.source], by_id[c.target]),
        }
        for c in scene.constraints
        if c.source in by_id and c.target in by_id
    ]
    return {
        "format": FORMAT,
        "id": scene_id,
        "text": scene.text,
        "style": scene.style,
        "seed": scene.seed,
        "frame": {"up": "+z", "forward": "-y is the front at yaw 0", "units": "metres", "quaternion": "wxyz"},
        "ground": scene.ground.kind,
        "files": {"scene": "scene.json", "glb": "scene.glb", "assets": "assets/"},
        "objects": objects,
        "relations": {"stated": stated, "geometric": geometric_relations(scene.objects)},
        "metrics": metrics or {},
    }
