"""``bench pipeline``: the offline pipeline on annotated prompts, scored from the final layout, and its speed.

The command generates each prompt from scratch (offline backends, no cache, no render, a
temporary folder) and hands the scenes here. The figures a user would see come from the finished scene checked against the
annotation of the text (:mod:`scenewright.evaluation.stated`), and from the spread of its
ground objects (:mod:`scenewright.evaluation.composition`); the parse figures beside them
score what the analysis stage read (:mod:`scenewright.bench.analysis`).
"""

from __future__ import annotations

import json
import statistics
import tempfile
import time
from pathlib import Path

from scenewright.bench.analysis import parse_figures, ratio, score_prompt
from scenewright.errors import ScenewrightError
from scenewright.evaluation.annotations import Prompt
from scenewright.evaluation.composition import LINE, in_a_line, spread
from scenewright.evaluation.room import room_metrics
from scenewright.evaluation.stated import stated
from scenewright.evaluation.water import by_water
from scenewright.scene import Scene
from scenewright.settings import Settings

#: Prompt domains → the paper's group names, so the table sits next to its figures.
PAPER_GROUPS = {"indoor": "indoor", "outdoor": "open-domain"}

#: Scenes with at least this many objects are reported apart (the speed target is for 15).
LARGE_SCENE = 12

#: What a room's layout must not have (docs/rooms.md), counted per scene and summed.
ROOM_PROBLEMS = ("outside", "above_ceiling", "blocked_openings", "stuck_doors", "unreachable", "not_on_wall", "not_on_ceiling")


def room_row(scene: Scene) -> dict:
    """Whether the scene got a room, and the objects (or openings) of each room problem."""
    metrics = room_metrics(scene)
    if metrics is None:
        return {"has_room": False}
    found = metrics.to_dict()
    return {"has_room": True, **{k: found[k] for k in ROOM_PROBLEMS if found[k]}}


def room_figures(rows: list[dict]) -> dict:
    """Indoor prompts with a room, outdoor prompts with one, and each problem summed over the rooms."""
    indoor = [r for r in rows if r["domain"] == "indoor"]
    return {
        "indoor_with_room": f"{sum(r['room']['has_room'] for r in indoor)}/{len(indoor)}",
        "outdoor_with_room": sum(r["room"]["has_room"] for r in rows if r["domain"] != "indoor"),
        **{k: sum(len(r["room"].get(k, ())) for r in rows) for k in ROOM_PROBLEMS},
    }


def layout_row(scene: Scene, prompt: Prompt) -> dict:
    """Relations realised, supports right and spread of one finished scene."""
    result = stated(scene, prompt)
    value, ground = spread(scene)
    water = by_water(scene)
    return {
        "by_water": None if water is None else vars(water),
        "relations_realised": result.realised,
        "relations_stated": result.relations,
        "supports_right": result.supports_right,
        "supports_checked": result.supports_checked,
        "supports_skipped": result.supports_skipped,
        "spread": value,
        "ground_objects": ground,
        "not_realised": result.not_realised,
        "wrong_supports": result.wrong_supports,
        "side_gaps": result.side_gaps,
    }


def layout_figures(rows: list[dict]) -> dict:
    skipped: dict[str, int] = {}
    for r in rows:
        for kind, n in r["supports_skipped"].items():
            skipped[kind] = skipped.get(kind, 0) + n
    spreads = [r["spread"] for r in rows if r["spread"] is not None]
    wet = [r["by_water"] for r in rows if r["by_water"] is not None]
    return {
        # scenes by water: floating things over the water, the other ground things on land
        "scenes_by_water": len(wet),
        "floating_afloat": ratio(sum(w["afloat"] for w in wet), sum(w["floating"] for w in wet)),
        "grounded_ashore": ratio(sum(w["ashore"] for w in wet), sum(w["grounded"] for w in wet)),
        "relations_realised": ratio(sum(r["relations_realised"] for r in rows), sum(r["relations_stated"] for r in rows)),
        "supports_right": ratio(sum(r["supports_right"] for r in rows), sum(r["supports_checked"] for r in rows)),
        "supports_skipped": skipped,
        "median_spread": round(statistics.median(spreads), 4) if spreads else None,
        f"scenes_spread_below_{LINE}": sum(in_a_line(r["spread"]) for r in rows),
        "scenes_with_spread": len(spreads),
        **side_gap_figures([g for r in rows for g in r["side_gaps"]]),
    }


#: m, the gap within which two things stated side by side count as standing together.
TOGETHER = 1.0


def side_gap_figures(gaps: list[float]) -> dict:
    """Median plan gap of the things stated beside, in front of or behind another, and the share
    standing within :data:`TOGETHER` of it."""
    return {
        "median_side_gap": round(statistics.median(gaps), 3) if gaps else None,
        f"side_gaps_within_{TOGETHER:g}m": ratio(sum(g <= TOGETHER for g in gaps), len(gaps)),
        "side_gaps": len(gaps),
    }


def run_row(prompt: Prompt, scene: Scene, seconds: float) -> dict:
    """One generated prompt: its time, size, layout figures and the parse's own score."""
    return {
        "id": prompt.id,
        "domain": prompt.domain,
        "seconds": round(seconds, 3),
        "objects": len(scene.objects),
        "complete": scene.layout.complete if scene.layout is not None else False,
        **layout_row(scene, prompt),
        "room": room_row(scene),
        "parse": score_prompt(prompt),
    }


def summarise_runs(rows: list[dict], *, details: bool = False) -> dict:
    """Parse figures, layout figures and speed over the rows of :func:`run_row`."""
    seconds = [r["seconds"] for r in rows]
    large = [r["seconds"] for r in rows if r["objects"] >= LARGE_SCENE]
    result = {
        "prompts": len(rows),
        **parse_figures([r["parse"] for r in rows]),
        **layout_figures(rows),
        "median_seconds": round(statistics.median(seconds), 3),
        "max_seconds": max(seconds),
        "median_objects": statistics.median(r["objects"] for r in rows),
        f"median_seconds_{LARGE_SCENE}plus_objects": round(statistics.median(large), 3) if large else None,
        f"scenes_{LARGE_SCENE}plus_objects": len(large),
        "complete_layouts": sum(r["complete"] for r in rows),
        "refused": [{"id": r["id"], "error": r["error"]} for r in rows if "error" in r],
        "rooms": room_figures(rows),
        "slowest": [
            {k: r[k] for k in ("id", "seconds", "objects", "complete")}
            for r in sorted(rows, key=lambda r: -r["seconds"])[:3]
        ],
    }
    if details:
        result["details"] = rows
    return result


def run_pipeline_bench(
    prompts: Path | None, limit: int | None, details: bool, settings: Settings, room: str = "auto"
) -> dict:
    """`generate --no-render` (offline, no cache) per annotated prompt: the final layouts scored
    against the text (relations realised, supports right, spread), the rooms' problems, the parse's
    figures, and seconds. ``room`` is every prompt's ``--room`` (``none`` measures what the rooms cost)."""
    from scenewright.analysis.parser.room import parse_room_option
    from scenewright.bench.analysis import load_prompts
    from scenewright.backends import backends_from_settings
    from scenewright.pipeline import generate

    parse_room_option(room)
    chosen = load_prompts(prompts)[:limit]
    settings.cache_dir = None
    backends = backends_from_settings(settings)
    rows = []
    with tempfile.TemporaryDirectory(prefix="scenewright-bench-") as tmp:
        for prompt in chosen:
            start = time.perf_counter()
            try:
                scene = generate(prompt.text, Path(tmp) / prompt.id, backends=backends, settings=settings,
                                 render=False, room=room)
            except ScenewrightError as error:
                # A text the pipeline refuses is a scene the user did not get: it scores as an empty
                # scene (nothing realised, no support right) and the batch goes on.
                rows.append({**run_row(prompt, Scene(text=prompt.text), time.perf_counter() - start),
                             "error": str(error)})
                continue
            rows.append(run_row(prompt, scene, time.perf_counter() - start))
    return summarise_runs(rows, details=details)


def run_eval_bench(out: Path, prompts: Path | None, limit: int | None, settings: Settings) -> dict:
    """Generate the shipped prompts offline and score them, full pipeline vs without the solver."""
    from scenewright.bench.analysis import load_prompts
    from scenewright.backends import backends_from_settings
    from scenewright.evaluation import evaluate
    from scenewright.evaluation.report import write_report
    from scenewright.pipeline import generate

    entries = load_prompts(prompts)
    if limit is not None:
        by_domain: dict[str, list] = {}
        for entry in entries:
            by_domain.setdefault(entry.domain, []).append(entry)
        entries = [e for group in by_domain.values() for e in group[:limit]]
    settings.cache_dir = None
    backends = backends_from_settings(settings)
    results = []
    with tempfile.TemporaryDirectory(prefix="scenewright-eval-") as tmp:
        for entry in entries:
            folder = Path(tmp) / entry.id
            generate(entry.text, folder, backends=backends, settings=settings, style=entry.style, render=False)
            group = PAPER_GROUPS.get(entry.domain, entry.domain)
            results += evaluate([folder], group=group, ablation=True, annotations=[entry])
    for r in results:  # the temporary folders are gone; name scenes by their prompt
        r.scene = Path(r.scene).name
    paths = write_report(results, out)
    summary = json.loads(paths["json"].read_text(encoding="utf-8"))["summary"]
    return {"prompts": len(entries), "out": str(out), "summary": summary}
