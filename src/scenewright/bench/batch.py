"""``scenewright bench batch``: scenes per minute of the batch runner per worker count, and Ray's
overhead per scene against the process pool."""

from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

from scenewright.settings import Settings


def run_batch_bench(scenes: int, workers: str, ray: bool, settings: Settings) -> dict:
    """Scenes per minute offline with --no-render for each worker count, and Ray's overhead
    per scene against the process pool; with CPU times and the load, since cores are shared."""
    import resource

    from scenewright.bench.analysis import load_prompts
    from scenewright.batch import Entry, RayOptions, run_batch
    from scenewright.batch.entries import text_id

    counts = [int(w) for w in workers.split(",") if w.strip()]
    texts = [p.text for p in load_prompts()][:scenes]
    entries = [Entry(id=text_id(t), text=t, line=i + 1) for i, t in enumerate(texts)]
    settings.cache_dir = None
    runs: dict[str, dict] = {}

    def timed(label: str, n: int, ray_options=None, extra: dict | None = None) -> None:
        with tempfile.TemporaryDirectory(prefix="scenewright-bench-batch-") as tmp:
            load = os.getloadavg()[0]
            children = resource.getrusage(resource.RUSAGE_CHILDREN)
            own = resource.getrusage(resource.RUSAGE_SELF)
            start = time.perf_counter()
            record = run_batch(entries, Path(tmp), settings=settings, workers=n, render=False, ray=ray_options)
            wall = time.perf_counter() - start
            after_children = resource.getrusage(resource.RUSAGE_CHILDREN)
            after_own = resource.getrusage(resource.RUSAGE_SELF)
        made = [o for o in record.outcomes.values() if o.status == "done"]
        in_scene = sum(o.seconds for o in made)
        runs[label] = {
            "workers": n,
            "scenes": len(made),
            "failed": sum(1 for o in record.outcomes.values() if o.status == "failed"),
            "wall_s": round(wall, 2),
            "scenes_per_minute": round(60 * len(made) / wall, 2) if wall else None,
            "scene_wall_s_median": round(sorted(o.seconds for o in made)[len(made) // 2], 3) if made else None,
            # CPU the scenes themselves used (inside the workers), and per scene.
            "scene_cpu_s": round(sum(o.cpu_seconds for o in made), 2),
            "cpu_s_per_scene": round(sum(o.cpu_seconds for o in made) / len(made), 3) if made else None,
            # Everything the pool's workers used, start-up and imports included (not visible for Ray's workers).
            "worker_processes_cpu_s": None if ray_options else round(
                (after_children.ru_utime + after_children.ru_stime) - (children.ru_utime + children.ru_stime), 2),
            "parent_cpu_s": round((after_own.ru_utime + after_own.ru_stime) - (own.ru_utime + own.ru_stime), 3),
            # Wall time per scene the workers spent outside scenes (start-up, dispatch, idle), per scene.
            "overhead_s_per_scene": round((n * wall - in_scene) / len(made), 3) if made else None,
            "load_average_1min_before": round(load, 2),
            "load_average_1min_after": round(os.getloadavg()[0], 2),
            **(extra or {}),
        }

    for n in counts:
        timed(f"local_{n}", n)
        run = runs[f"local_{n}"]
        # What the wall time would be with a free core per worker: the workers' CPU (start-up
        # included) spread over them. On a shared machine this is the figure that compares.
        run["cpu_bound_wall_s"] = round(run["worker_processes_cpu_s"] / n, 2)
        run["cpu_bound_scenes_per_minute"] = round(60 * run["scenes"] / run["cpu_bound_wall_s"], 2)
    result: dict = {"scenes": len(entries), "cpus_available": len(os.sched_getaffinity(0)), "runs": runs}
    first, last = runs[f"local_{counts[0]}"], runs[f"local_{counts[-1]}"]
    if len(counts) > 1:
        result["speedup"] = {
            "wall": round(first["wall_s"] / last["wall_s"], 3),
            "cpu_bound": round(first["cpu_bound_wall_s"] / last["cpu_bound_wall_s"], 3),
        }
    if ray:
        try:
            import ray as ray_module
        except ImportError:
            result["ray"] = "not measured: the batch extra (ray) is not installed"
        else:
            n = counts[-1]
            start = time.perf_counter()
            ray_module.init(num_cpus=n, include_dashboard=False, log_to_driver=False)
            init_s = time.perf_counter() - start
            try:
                timed(f"ray_{n}", n, RayOptions(num_cpus=n), {"ray_init_s": round(init_s, 2)})
            finally:
                ray_module.shutdown()
            pool, on_ray = runs[f"local_{n}"], runs[f"ray_{n}"]
            if pool["scenes"] and on_ray["scenes"]:
                result["ray_vs_pool"] = {
                    "workers": n,
                    "extra_wall_s_per_scene": round((on_ray["wall_s"] - pool["wall_s"]) / len(entries), 3),
                    "extra_cpu_s_per_scene_in_task": round(on_ray["cpu_s_per_scene"] - pool["cpu_s_per_scene"], 3),
                    "extra_driver_cpu_s_per_scene": round((on_ray["parent_cpu_s"] - pool["parent_cpu_s"]) / len(entries), 4),
                    "ray_init_s": round(init_s, 2),
                }
    return result
