"""``scenewright bench edits``: how well the offline planner reads instructions, and how fast a
move re-solves.

Cases are JSON files (``benchmarks/edits/*.json``): a scene (its text and objects, each with
id, name, category and position) and instructions annotated with the expected operation,
focus id and relations (``[relation, target]`` pairs), or ``"operation": "error"`` where the
planner must refuse (an ambiguous or unknown reference); a move relative to the object's own
place carries ``"offset": [dx, dy]``, the expected direction (signs) in the scene frame. The
annotations were written before the planner was tuned on them; ``benchmarks/edits/heldout/``
holds instructions written after, scored alone with ``--cases``.
"""

from __future__ import annotations

import json
import statistics
import tempfile
import time
from pathlib import Path

from scenewright.core.catalogue import load_catalogue, lookup
from scenewright.backends import Backends, backends_from_settings
from scenewright.editing.apply import run_plan
from scenewright.editing.parser import plan_edit_offline
from scenewright.errors import InputError
from scenewright.scene import Scene, SceneObject, Vec3


def case_scene(case: dict, source: Path) -> Scene:
    """The scene of a case file: objects sized from the catalogue unless the file gives a size."""
    objects = []
    for raw in case["objects"]:
        category = lookup(raw["category"])
        if category is None:
            raise InputError(f"{source}: object {raw['id']!r} has category {raw['category']!r}, not in the catalogue")
        size = raw.get("size", category.size)
        x, y = raw["position"]
        objects.append(SceneObject(
            id=raw["id"], name=raw.get("name", category.label), category=category.name,
            size=Vec3.of(size), position=Vec3(x=x, y=y, z=size[2] / 2),
            visual_description=raw.get("description", ""),
        ))
    return Scene(text=case["text"], objects=objects)


def _signs(values) -> tuple[int, ...]:
    return tuple((v > 1e-9) - (v < -1e-9) for v in values)


def score_cases(cases: Path) -> dict[str, float | int]:
    """Accuracy over a case file, or every case file directly in a folder."""
    cases = Path(cases)
    files = [cases] if cases.is_file() else sorted(cases.glob("*.json"))
    if not files:
        raise InputError(f"no edit cases (*.json) in {cases}; pass --cases FILE_OR_DIR")
    total = op_ok = focus_ok = offsets = offset_ok = 0
    planned_relations = correct_relations = expected_relations = 0
    for path in files:
        case = json.loads(path.read_text(encoding="utf-8"))
        scene = case_scene(case, path)
        for item in case["instructions"]:
            total += 1
            expected = {tuple(r) for r in item.get("relations", [])}
            expected_relations += len(expected)
            offsets += "offset" in item
            try:
                plan = plan_edit_offline(scene, item["instruction"])
            except InputError:
                if item["operation"] == "error":
                    op_ok += 1
                    focus_ok += 1
                continue
            if plan.operation != item["operation"]:
                continue
            op_ok += 1
            focus_ok += plan.focus == item["focus"]
            got = {(c.relation, c.target) for c in plan.constraints}
            planned_relations += len(got)
            correct_relations += len(got & expected)
            if "offset" in item and plan.offset is not None:
                offset_ok += _signs(item["offset"]) == _signs((plan.offset.x, plan.offset.y))
    return {
        "instructions": total,
        "operation_accuracy": round(op_ok / total, 4),
        "focus_accuracy": round(focus_ok / total, 4),
        "relation_precision": round(correct_relations / planned_relations, 4) if planned_relations else 1.0,
        "relation_recall": round(correct_relations / expected_relations, 4) if expected_relations else 1.0,
        "offset_accuracy": round(offset_ok / offsets, 4) if offsets else 1.0,
    }


def latency_scene(count: int, folder, backends: Backends, settings) -> Scene:
    """``count`` ground-standing catalogue objects on a grid, with their real assets built."""
    from scenewright.assets import generate_assets
    from scenewright.cache import RequestCache

    grounded = [c for c in load_catalogue().values() if c.rests == "ground" and max(c.size) <= 2.5]
    step = 3.0
    side = int(count ** 0.5 + 0.999)
    objects = []
    for index in range(count):
        category = grounded[index % len(grounded)]
        x, y = (index % side - side / 2) * step, (index // side - side / 2) * step
        objects.append(SceneObject(
            id=f"{category.name}_{index + 1}", name=category.label, category=category.name,
            size=Vec3.of(category.size), position=Vec3(x=x, y=y, z=category.size[2] / 2),
        ))
    scene = Scene(text="a benchmark scene", objects=objects)
    generate_assets(scene, folder, backends.meshes, RequestCache(settings.cache_dir))
    return scene


def latency(count: int, moves: int) -> tuple[list[float], list[float]]:
    """Seconds the solver spent per move edit, and seconds per whole planned edit (parse,
    meshes, solve; no file writes), on a ``count``-object scene."""
    from scenewright.folder import SceneFolder
    from scenewright.settings import Settings

    settings = Settings(cache_dir=None)
    backends = backends_from_settings(settings)
    solving, whole = [], []
    with tempfile.TemporaryDirectory(prefix="scenewright-bench-edits-") as tmp:
        folder = SceneFolder(Path(tmp))
        scene = latency_scene(count, folder, backends, settings)
        folder.save(scene)
        ids = [o.id for o in scene.objects]
        relations = ("to the left of", "to the right of", "in front of", "behind", "near")
        for n in range(moves):
            focus, target = ids[(n * 7) % len(ids)], ids[(n * 7 + 11) % len(ids)]
            start = time.perf_counter()
            plan = plan_edit_offline(scene, f"move {focus} {relations[n % len(relations)]} {target}")
            edit = run_plan(scene, folder, plan, backends=backends, settings=settings)
            whole.append(time.perf_counter() - start)
            solving.append(edit.seconds_solving)
            scene = edit.scene
    return solving, whole


def run_edits_bench(cases: Path, objects: int, moves: int) -> dict:
    """Offline planner accuracy on annotated instructions, and move-edit latency, as JSON.

    ``move_resolve_median_s`` is the solver's time per move; ``move_edit_median_s`` the whole
    edit short of writing files (parse, meshes, solve); ``move_edit_first_s`` the first edit of
    the session, which also parses every asset."""
    scores = score_cases(cases)
    solve_seconds, edit_seconds = latency(objects, moves)
    result = {
        **scores,
        "latency_objects": objects,
        "latency_moves": len(solve_seconds),
        "move_resolve_median_s": round(statistics.median(solve_seconds), 4),
        "move_edit_median_s": round(statistics.median(edit_seconds), 4),
        "move_edit_first_s": round(edit_seconds[0], 4),
    }
    return result
