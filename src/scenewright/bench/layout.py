"""The layout benchmark: planted problems solved, timed and re-checked independently.

:func:`run` is the everyday benchmark; :func:`run_hard` the hard one (arbitrary yaws, two or
more relations per object, facing pairs, stacks, dense rooms), which can also solve every
problem with another checkout of scenewright (``baseline``) in a subprocess, so that the
figures of two versions come from one run on the same problems and the same checker.
"""

from __future__ import annotations

import logging
import os
import pickle
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Mapping, Sequence

import numpy as np
import trimesh

from scenewright.errors import InputError
from scenewright.geometry import object_matrix, world_box
from scenewright.testing.problems import Problem, dense_room, hard_problem, planted_problem
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
    """Per size: solve CPU seconds (median, p90), success rate, collisions, constraints satisfied."""
    out: dict = {
        "benchmark": "layout", "seeds": seeds, "time_limit": time_limit, "clock": "cpu", "cpus": os.cpu_count(),
        "sizes": {},
    }
    for n in sizes:
        seconds, complete, collisions, satisfied, total, counts, nodes = [], 0, 0, 0, 0, [], []
        for seed in range(seeds):
            problem = planted_problem(n, seed)
            t0 = time.process_time()
            result = solve(problem.objects, problem.constraints, meshes=problem.meshes,
                           bounds=problem.bounds, seed=seed, time_limit=time_limit)
            seconds.append(time.process_time() - t0)
            nodes.append(result.report.nodes)
            counts.append((len(problem.objects), len(problem.constraints)))
            complete += result.report.complete
            placed = set(result.report.placed)
            kept = [o for o in result.objects if o.id in result.posed]
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


#: Floor shares of the dense rooms in the hard benchmark, and their object count.
COVERAGES = (0.4, 0.55, 0.7)
ROOM_OBJECTS = 20

#: Solves pickled problems with whatever scenewright is on the path; prints nothing.
_DRIVER = """
import pickle, sys, time
from scenewright.layout import solve
from scenewright.scene import SceneObject
out = []
for objects, constraints, meshes, bounds, seed, limit in pickle.load(open(sys.argv[1], "rb")):
    objects = [SceneObject.model_validate(o) for o in objects]
    start = time.process_time()
    r = solve(objects, constraints, meshes=meshes, bounds=bounds, seed=seed, time_limit=limit)
    cpu = time.process_time() - start
    out.append(([o.model_dump() for o in r.objects], [c.model_dump() for c in r.constraints],
                list(r.report.placed), [u.id for u in r.report.unplaced], cpu))
pickle.dump(out, open(sys.argv[2], "wb"))
"""


def hard_suite(sizes: Sequence[int], seeds: int, room_seeds: int = 3) -> list[tuple[str, int, Problem]]:
    """(row label, seed, problem) for every hard problem: ``seeds`` per size, ``room_seeds``
    dense rooms per floor share."""
    suite = [(f"n={n}", seed, hard_problem(n, seed)) for n in sizes for seed in range(seeds)]
    suite += [
        (f"room {round(100 * c)}%", seed, dense_room(ROOM_OBJECTS, c, seed))
        for c in COVERAGES for seed in range(room_seeds)
    ]
    return suite


def score(problem: Problem, objects: Sequence[SceneObject], placed: set[str], posed: set[str]) -> dict:
    """One solved problem, checked independently against the problem's own constraints (one a
    solver dropped counts as missed): constraints by the relations' one definition, collisions
    by trimesh's manager among the objects the solver gave a pose, bounds by box."""
    constraints = problem.constraints
    by_id = {o.id: o for o in objects}
    held = sum(check(c.relation, by_id[c.source], by_id[c.target]) for c in constraints)
    kept = [o for o in objects if o.id in posed]
    collisions = len(independent_collisions(kept, problem.meshes, constraints))
    half = np.array(problem.bounds) / 2 + 1e-9
    outside = sum(
        bool(np.any(lo[:2] < -half) or np.any(hi[:2] > half)) for lo, hi in (world_box(o) for o in kept)
    )
    complete = len(placed) == len(objects)
    return {
        "solved": complete and held == len(constraints) and collisions == 0 and outside == 0,
        "placed": len(placed) / len(objects),
        "held": held, "constraints": len(constraints), "collisions": collisions, "outside": outside,
    }


def _solve_here(problem: Problem, seed: int, time_limit: float) -> tuple[dict, float]:
    start = time.process_time()
    r = solve(problem.objects, problem.constraints, meshes=problem.meshes, bounds=problem.bounds,
              seed=seed, time_limit=time_limit)
    cpu = time.process_time() - start
    return score(problem, r.objects, set(r.report.placed), r.posed), cpu


def _checkout(tree: Path) -> Path:
    src = Path(tree) / "src"
    if not (src / "scenewright").is_dir():
        raise InputError(f"--baseline {tree}: no src/scenewright there; give the root of a scenewright checkout")
    return src


def _solve_baseline(tree: Path, suite, time_limit: float) -> list[tuple[dict, float]]:
    """Every problem solved by the scenewright in ``tree`` (a checkout with ``src/``), in one
    subprocess; its layouts scored here. Objects it leaves unplaced keep their initial poses
    and are left out of its collision count, as it reports them."""
    src = _checkout(tree)
    jobs = [([o.model_dump() for o in p.objects], [c.model_dump() for c in p.constraints], p.meshes, p.bounds,
             seed, time_limit) for _, seed, p in suite]
    with tempfile.TemporaryDirectory(prefix="scenewright-bench-baseline-") as tmp:
        given, taken = Path(tmp) / "in.pickle", Path(tmp) / "out.pickle"
        given.write_bytes(pickle.dumps(jobs))
        env = {**os.environ, "PYTHONPATH": str(src)}
        done = subprocess.run([sys.executable, "-c", _DRIVER, str(given), str(taken)], env=env,
                              capture_output=True, text=True)
        if done.returncode != 0:
            raise InputError(f"--baseline {tree}: its solver failed:\n{done.stderr[-2000:]}")
        answers = pickle.loads(taken.read_bytes())
    out = []
    for (_, _, problem), (objects, _, placed, _, cpu) in zip(suite, answers):
        objects = [SceneObject.model_validate(o) for o in objects]
        out.append((score(problem, objects, set(placed), set(placed)), cpu))
    return out


def _summary(rows: list[tuple[dict, float]]) -> dict:
    cpu = [c for _, c in rows]
    held = sum(r["held"] for r, _ in rows)
    total = sum(r["constraints"] for r, _ in rows)
    return {
        "solved": sum(r["solved"] for r, _ in rows), "problems": len(rows),
        "solved_share": round(sum(r["solved"] for r, _ in rows) / len(rows), 3),
        "placed_share": round(statistics.fmean(r["placed"] for r, _ in rows), 4),
        "constraints_held": round(held / total, 4) if total else 1.0,
        "median_cpu_seconds": round(statistics.median(cpu), 3),
        "max_cpu_seconds": round(max(cpu), 3),
        "colliding_pairs": sum(r["collisions"] for r, _ in rows),
        "outside_bounds": sum(r["outside"] for r, _ in rows),
    }


def run_hard(sizes: Sequence[int], seeds: int, time_limit: float = 10.0, room_seeds: int = 3,
             baseline: Path | None = None) -> dict:
    """The hard benchmark: per row (a size, or a dense room's floor share) the share fully solved
    (every object placed, every constraint held, no collision, inside the bounds), median CPU
    seconds, colliding pairs; with ``baseline``, the same for that checkout beside it."""
    if baseline is not None:
        _checkout(baseline)  # before the long part
    suite = hard_suite(sizes, seeds, room_seeds)
    here = [_solve_here(p, seed, time_limit) for _, seed, p in suite]
    there = _solve_baseline(Path(baseline), suite, time_limit) if baseline is not None else None
    out: dict = {"benchmark": "layout-hard", "seeds": seeds, "room_seeds": room_seeds, "time_limit": time_limit,
                 "cpus": os.cpu_count(), "rows": {}}
    for label in dict.fromkeys(label for label, _, _ in suite):
        idx = [k for k, (lab, _, _) in enumerate(suite) if lab == label]
        ps = [suite[k][2] for k in idx]
        row = {"objects_mean": round(statistics.fmean(len(p.objects) for p in ps), 1),
               "constraints_mean": round(statistics.fmean(len(p.constraints) for p in ps), 1),
               "this": _summary([here[k] for k in idx])}
        if there is not None:
            row["baseline"] = _summary([there[k] for k in idx])
        out["rows"][label] = row
    if baseline is not None:
        out["baseline"] = str(baseline)
    return out


def run_layout_bench(
    sizes: str | None, seeds: int, time_limit: float, hard: bool, room_seeds: int, baseline: Path | None
) -> dict:
    """Solve planted-solution problems: timings, success and collisions per size."""
    text = sizes or ("10,30,60,100,200" if hard else "15,50,100")
    try:
        counts = [int(s) for s in text.split(",")]
    except ValueError:
        raise InputError(f"--sizes: expected comma-separated integers, got {text!r}") from None
    if not counts or min(counts) < 1 or seeds < 1 or room_seeds < 0:
        raise InputError("--sizes must be positive integers, --seeds at least 1 and --room-seeds at least 0")
    if baseline is not None and not hard:
        raise InputError("--baseline compares on the hard problems: add --hard")
    logging.getLogger("scenewright.layout").setLevel(logging.ERROR)  # the solver's per-object notes
    if hard:
        return run_hard(counts, seeds, time_limit, room_seeds, baseline)
    return run(counts, seeds, time_limit)
