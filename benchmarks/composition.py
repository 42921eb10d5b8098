"""Composition of the shipped prompts: lines of ground objects, relations held, time.

For every annotated prompt (``benchmarks/prompts*``) the offline pipeline runs without
renders; per scene it records the spread of the ground objects (minor/major standard
deviation of their centres, near 0 = a line) for the initial poses and the final layout,
how many of the relations the parser read from the text (not the ones it inferred) hold in
the initial poses and in the final layout, whether the layout is complete, and the seconds. Prints one JSON object.

The spread is computed by this checkout's ``analysis/composition/spread.py``, loaded by path,
so the same figure scores scenes made by any other checkout put first on ``PYTHONPATH``
(the before/after comparison). Run from the repository root:

    PYTHONPATH=src python benchmarks/composition.py [--per-scene]
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import statistics
import tempfile
import time
from pathlib import Path

from scenewright.bench.analysis import load_prompts
from scenewright.analysis.parser import parse_scene
from scenewright.backends import backends_from_settings
from scenewright.cli.options import build_settings
from scenewright.layout import relations as rel
from scenewright.pipeline import generate

ROOT = Path(__file__).resolve().parents[1]
FOLDERS = ("prompts", "prompts-heldout", "prompts-heldout-2", "prompts-heldout-3")


def _spread_module():
    path = ROOT / "src" / "scenewright" / "analysis" / "composition" / "spread.py"
    spec = importlib.util.spec_from_file_location("composition_spread", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--per-scene", action="store_true", help="also list every scene's figures")
    parser.add_argument("--limit", type=int, default=None, help="only the first N prompts")
    args = parser.parse_args()
    measure = _spread_module()
    prompts = [(folder, p) for folder in FOLDERS for p in load_prompts(ROOT / "benchmarks" / folder)][: args.limit]
    settings = build_settings()
    settings.cache_dir = None
    backends = backends_from_settings(settings)
    rows = []
    with tempfile.TemporaryDirectory(prefix="scenewright-composition-") as tmp:
        for folder, prompt in prompts:
            start = time.perf_counter()
            out = Path(tmp) / folder / prompt.id
            scene = generate(prompt.text, out, backends=backends, settings=settings, render=False)
            seconds = time.perf_counter() - start
            initial = [
                o.model_copy(update={"position": p.position, "rotation": p.rotation}) if p else o
                for o, p in ((o, scene.initial.get(o.id)) for o in scene.objects)
            ]
            by_id = {o.id: o for o in scene.objects}
            stated = [r for r in parse_scene(prompt.text).relations if not r.inferred]
            held = _held(stated, by_id)
            held_initial = _held(stated, {o.id: o for o in initial})
            ground = measure.ground_objects(scene.objects)
            rows.append({
                "id": f"{folder}/{prompt.id}",
                "objects": len(scene.objects),
                "ground": len(ground),
                "spread_initial": round(measure.scene_spread(initial), 3),
                "spread_final": round(measure.scene_spread(scene.objects), 3),
                "stated": len(stated),
                "stated_held": len(held),
                "stated_held_initial": len(held_initial),
                "complete": scene.layout.complete,
                "seconds": round(seconds, 3),
            })
    lined = [r for r in rows if r["ground"] >= 3 and r["spread_final"] < measure.MIN_SPREAD]
    lined_initial = [r for r in rows if r["ground"] >= 3 and r["spread_initial"] < measure.MIN_SPREAD]
    result = {
        "scenes": len(rows),
        "lines_final": len(lined),
        "lines_final_share": round(len(lined) / len(rows), 3),
        "lines_initial": len(lined_initial),
        "median_spread_final": round(statistics.median(r["spread_final"] for r in rows), 3),
        "stated_relations": sum(r["stated"] for r in rows),
        "stated_held_share": round(sum(r["stated_held"] for r in rows) / max(1, sum(r["stated"] for r in rows)), 3),
        "stated_held_initial": sum(r["stated_held_initial"] for r in rows),
        "complete_layouts": sum(r["complete"] for r in rows),
        "median_seconds": round(statistics.median(r["seconds"] for r in rows), 3),
        "lined_scenes": [r["id"] for r in lined],
    }
    if args.per_scene:
        result["per_scene"] = rows
    print(json.dumps(result))


def _held(relations, by_id):
    """The relations whose source and target both stand where the relation holds."""
    return [r for r in relations if r.source in by_id and r.target in by_id
            and rel.check(r.relation, by_id[r.source], by_id[r.target])]  # fmt: skip


if __name__ == "__main__":
    main()
