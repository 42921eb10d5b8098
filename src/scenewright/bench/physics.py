"""``scenewright bench physics``: how many generated objects stand still in a simulator, and what
the simulation export costs."""

from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

from scenewright.settings import Settings


def run_physics_bench(prompts: Path | None, limit: int | None, repeats: int, settings: Settings) -> dict:
    """Stability after a 2 s settle on the shipped prompts, and export + settle seconds of the bundled
    example (15 objects, all of them dynamic)."""
    from scenewright.bench.analysis import load_prompts
    from scenewright.backends import backends_from_settings
    from scenewright.cache import RequestCache
    from scenewright.examples import example_text
    from scenewright.evaluation.stability import load_mujoco, stability
    from scenewright.export.sim import export_scene
    from scenewright.folder import SceneFolder
    from scenewright.pipeline import generate

    load_mujoco()
    chosen = load_prompts(prompts)[:limit]
    backends = backends_from_settings(settings)
    scenes = []
    with tempfile.TemporaryDirectory(prefix="scenewright-physics-") as tmp:
        cache = RequestCache(Path(tmp) / "cache")
        settings.cache_dir = cache.root
        for prompt in chosen:
            folder = SceneFolder(Path(tmp) / prompt.id)
            scene = generate(prompt.text, folder, backends=backends, settings=settings, style=prompt.style, render=False)
            result = stability(scene, folder, cache)
            scenes.append({"id": prompt.id, "objects": len(scene.objects)} | result.to_dict())
        folder = SceneFolder(Path(tmp) / "example")
        scene = generate(example_text(), folder, backends=backends, settings=settings, render=False)
        seconds = []
        for _ in range(repeats):
            # Fresh derivation each time: the cache would hide the cost of the colliders.
            for obj in scene.objects:
                obj.physics = None
            run_cache = RequestCache(Path(tmp) / f"cache-{len(seconds)}")
            start = time.perf_counter()
            export_scene(scene, folder, "mjcf", run_cache)
            export_scene(scene, folder, "usd", run_cache)
            timed = stability(scene, folder, run_cache)
            seconds.append(time.perf_counter() - start)
    dynamic = sum(s["dynamic"] for s in scenes)
    stable = sum(s["stable_objects"] for s in scenes)
    worst = sorted((u | {"scene": s["id"]} for s in scenes for u in s["unstable"]), key=lambda u: -u["shift_m"])
    result = {
        "prompts": len(scenes),
        "dynamic_objects": dynamic,
        "static_objects": sum(len(s["static"]) for s in scenes),
        "stable_objects_pct": round(100.0 * stable / dynamic, 2) if dynamic else None,
        "stable_scenes_pct": round(100.0 * sum(s["stable"] for s in scenes) / len(scenes), 2) if scenes else None,
        "worst": worst[:10],
        "timed_scene": {"id": "example", "objects": len(scene.objects), "dynamic": len(timed.objects)} if seconds else None,
        "export_settle_median_seconds": round(statistics.median(seconds), 3) if seconds else None,
        "export_settle_runs": [round(s, 3) for s in seconds],
    }
    return result
