"""The layout benchmark: planted problems solved, timed and re-checked independently."""

from __future__ import annotations

import os
import statistics
import time
from typing import Mapping, Sequence

import numpy as np
import trimesh

from scenewright.geometry import object_matrix
from scenewright.layout.problems import planted_problem
from scenewright.layout.relations import check
from scenewright.layout.solver import solve
from scenewright.scene import Constraint, SceneObject


def collision_manager(
    objects: Sequence[SceneObject], meshes: Mapping[str, trimesh.Trimesh]
) -> trimesh.collision.CollisionManager:
    """trimesh's manager holding every object at its pose (a box mesh where there is no asset)."""
    manager = trimesh.collision.CollisionManager()
    for o in objects:
        mesh = meshes.get(o.id)
        if mesh is None:
            mesh = trimesh.creation.box(o.size.tuple())
            mesh.apply_translation((0.0, 0.0, o.size.z / 2))
        manager.add_object(o.id, mesh, transform=object_matrix(o))
    return manager


def independent_collisions(
    objects: Sequence[SceneObject], meshes: Mapping[str, trimesh.Trimesh], constraints: Sequence[Constraint]
) -> list[tuple[str, str]]:
    """Colliding pairs by trimesh's collision manager, placed with :func:`geometry.object_matrix`.

    Shares nothing with the solver's collision code but the pose convention: objects without
    a mesh become box meshes in the asset frame (bottom at z = 0), ``on`` pairs are allowed
    to touch.
    """
    _, names = collision_manager(objects, meshes).in_collision_internal(return_names=True)
    resting = {frozenset((c.source, c.target)) for c in constraints if c.relation == "on"}
    return sorted(tuple(sorted(pair)) for pair in names if frozenset(pair) not in resting)


def run(sizes: Sequence[int], seeds: int, time_limit: float = 10.0) -> dict:
    """Per size: solve seconds (median, p90), success rate, collisions, constraints satisfied."""
    out: dict = {
        "benchmark": "layout", "seeds": seeds, "time_limit": time_limit, "cpus": os.cpu_count(), "sizes": {},
    }
    for n in sizes:
        seconds, complete, collisions, satisfied, total, counts, nodes = [], 0, 0, 0, 0, [], []
        for seed in range(seeds):
            problem = planted_problem(n, seed)
            t0 = time.perf_counter()
            result = solve(problem.objects, problem.constraints, meshes=problem.meshes,
                           bounds=problem.bounds, seed=seed, time_limit=time_limit)
            seconds.append(time.perf_counter() - t0)
            nodes.append(result.report.nodes)
            counts.append((len(problem.objects), len(problem.constraints)))
            complete += result.report.complete
            placed = set(result.report.placed)
            kept = [o for o in result.objects if o.id in placed]
            collisions += len(independent_collisions(kept, problem.meshes, result.constraints))
            by_id = {o.id: o for o in result.objects}
            for c in result.constraints:
                total += 1
                both = c.source in placed and c.target in placed
                satisfied += both and check(c.relation, by_id[c.source], by_id[c.target])
        out["sizes"][str(n)] = {
            "objects_mean": round(statistics.fmean(c[0] for c in counts), 1),
            "constraints_mean": round(statistics.fmean(c[1] for c in counts), 1),
            "median_seconds": round(statistics.median(seconds), 4),
            "p90_seconds": round(float(np.percentile(seconds, 90)), 4),
            "max_seconds": round(max(seconds), 4),
            "median_nodes": statistics.median(nodes),
            "success_rate": complete / seeds,
            "colliding_pairs": collisions,
            "constraints_satisfied": round(satisfied / total, 4) if total else 1.0,
        }
    return out
