"""Aggregates per scene group and method, written as JSON, a Table-1-style markdown table and a PNG chart.

The report says where each number comes from: "constraints held" checks the layout against the
constraints the analysis stage wrote, so it cannot see a relation the parser missed or misread;
only "text relations held" (with an annotation of the text) measures fidelity to the text.
The chart is drawn with Pillow (already a core dependency) rather than pulling in matplotlib
for a few bars.
"""

from __future__ import annotations

import json
import statistics
from collections.abc import Sequence
from pathlib import Path

from PIL import Image, ImageDraw, ImageFont

from scenewright.evaluation import SceneMetrics
from scenewright.evaluation.composition import LINE, in_a_line
from scenewright.evaluation.stability import stability_figures
from scenewright.files import write_atomic

#: The paper's Tables 1 and 2 (Holodeck 2.0, full and without the layout solver), for comparison.
PAPER = {
    ("indoor", "full"): {"clip": 0.297, "cf": 97.14, "cn": 0.11, "pos": 81.03, "rot": 82.86, "psa": 82.67},
    ("indoor", "w/o solver"): {"clip": 0.289, "cf": 54.29, "cn": 1.23, "pos": 77.83, "rot": 76.11, "psa": 45.30},
    ("open-domain", "full"): {"clip": 0.307, "cf": 97.14, "cn": 0.86, "pos": 84.43, "rot": 83.63, "psa": 86.00},
    ("open-domain", "w/o solver"): {"clip": 0.306, "cf": 42.86, "cn": 1.89, "pos": 79.09, "rot": 77.83, "psa": 36.53},
}
#: column key → (header, format)
COLUMNS = {
    "scenes": ("Scenes", "{:d}"),
    "clip": ("CLIP↑", "{:.3f}"),
    "cf": ("CF (%)↑", "{:.2f}"),
    "cn": ("CN↓", "{:.2f}"),
    "stable_objects": ("Stable objects (%)↑", "{:.2f}"),
    "stable_scenes": ("Stable scenes (%)↑", "{:.2f}"),
    "pos": ("Pos.↑", "{:.2f}"),
    "rot": ("Rot.↑", "{:.2f}"),
    "psa": ("PSA↑", "{:.2f}"),
    "constraints": ("Parser constraints held (%)*", "{:.2f}"),
    "stated": ("Text relations held (%)↑", "{:.2f}"),
    "supports": ("Supports right (%)↑", "{:.2f}"),
    "spread": ("Spread (median)↑", "{:.3f}"),
    "in_a_line": (f"In a line (spread < {LINE})↓", "{:d}"),
    "floating": ("Floating↓", "{:.2f}"),
    "out_of_bounds": ("Out of bounds↓", "{:.2f}"),
}
#: Where each figure comes from, written into report.json and under table.md.
SOURCES = {
    "constraints": (
        "constraints held: as written by the analysis stage, not checked against the text; a relation the "
        "parser missed or misread is not counted, so this is not text fidelity"
    ),
    "stated": (
        "text relations held: the relations an annotation of the text states, checked in the final layout "
        "with the layout engine's relation checks (needs --annotations)"
    ),
    "supports": "supports right: objects resting where the annotation says (ground or another object; wall, ceiling and air not checked)",
    "spread": (
        "spread: minor/major standard deviation of the ground objects' centres (near 0: a line); "
        f"in a line: scenes with at least 3 ground objects and spread < {LINE}"
    ),
}


def _mean(values: Sequence[float]) -> float | None:
    return round(statistics.fmean(values), 4) if values else None


def _share(stated: Sequence[dict], key: str) -> float | None:
    """Percentage over [held, total] pairs, or None when nothing was annotated."""
    held, total = sum(d[key][0] for d in stated), sum(d[key][1] for d in stated)
    return round(100.0 * held / total, 2) if total else None


def aggregate(results: Sequence[SceneMetrics]) -> dict:
    """One row: CF is the share of collision-free scenes, CN the mean colliding pairs per scene."""
    satisfied = sum(s for r in results for s, _ in r.constraints.values())
    total = sum(t for r in results for _, t in r.constraints.values())
    by_relation: dict[str, list[int]] = {}
    for r in results:
        for relation, (s, t) in r.constraints.items():
            counts = by_relation.setdefault(relation, [0, 0])
            counts[0], counts[1] = counts[0] + s, counts[1] + t
    judged = [r for r in results if r.judge]
    annotated = [r.stated for r in results if r.stated is not None]
    spreads = [r.spread for r in results if r.spread is not None]
    return {
        "scenes": len(results),
        "clip": _mean([r.clip for r in results if r.clip is not None]),
        "cf": _mean([100.0 * r.collision_free for r in results]),
        "cn": _mean([len(r.collisions) for r in results]),
        "pos": _mean([r.judge["pos"] for r in judged]),
        "rot": _mean([r.judge["rot"] for r in judged]),
        "sa": _mean([r.judge["sa"] for r in judged]),
        "psa": _mean([r.psa for r in judged]),
        "constraints": round(100.0 * satisfied / total, 2) if total else None,
        "constraints_by_relation": {k: round(100.0 * s / t, 2) for k, (s, t) in sorted(by_relation.items())},
        "stated": _share(annotated, "relations_realised"),
        "supports": _share(annotated, "supports_right"),
        "annotated_scenes": len(annotated),
        "spread": round(statistics.median(spreads), 4) if spreads else None,
        "in_a_line": sum(in_a_line(r.spread) for r in results),
        "floating": _mean([len(r.floating) for r in results]),
        "out_of_bounds": _mean([len(r.out_of_bounds) for r in results]),
        "unavailable": sorted({f"{k}: {v}" for r in results for k, v in r.unavailable.items()}),
        **stability_figures(results),
    }


def summarise(results: Sequence[SceneMetrics]) -> dict[str, dict[str, dict]]:
    """group → method → aggregate, groups and methods in the order first seen."""
    groups: dict[str, dict[str, list[SceneMetrics]]] = {}
    for r in results:
        groups.setdefault(r.group, {}).setdefault(r.method, []).append(r)
    return {g: {m: aggregate(rs) for m, rs in methods.items()} for g, methods in groups.items()}


def _cell(value, fmt: str) -> str:
    return "–" if value is None else fmt.format(value)


def markdown_table(summary: dict[str, dict[str, dict]], *, paper: bool = True) -> str:
    """Rows per group and method (and the paper's figures for the same group, where it has them)."""
    header = ["Group", "Method", *(h for h, _ in COLUMNS.values())]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for group, methods in summary.items():
        for method, row in methods.items():
            cells = [_cell(row.get(k), fmt) for k, (_, fmt) in COLUMNS.items()]
            lines.append("| " + " | ".join([group, method, *cells]) + " |")
        if paper:
            for method in methods:
                figures = PAPER.get((group, method))
                if figures:
                    cells = [_cell(figures.get(k), fmt) for k, (_, fmt) in COLUMNS.items()]
                    lines.append("| " + " | ".join([group, f"{method} (paper)", *cells]) + " |")
    lines += ["", *(f"{'*' if key == 'constraints' else '-'} {text}" for key, text in SOURCES.items())]
    return "\n".join(lines) + "\n"


def _percent(pair: list[int] | None) -> str:
    return "–" if not pair or not pair[1] else f"{100.0 * pair[0] / pair[1]:.1f} ({pair[0]}/{pair[1]})"


def scene_table(results: Sequence[SceneMetrics]) -> str:
    """One row per scene and method: its spread, the text's relations and supports, the parser's constraints."""
    lines = [
        "| Scene | Method | Objects | Ground | Spread | Text relations held (%) | Supports right (%) | Parser constraints held (%)* |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in results:
        held = [sum(s for s, _ in r.constraints.values()), sum(t for _, t in r.constraints.values())]
        stated = r.stated or {}
        spread = "–" if r.spread is None else f"{r.spread:.3f}" + (" (line)" if in_a_line(r.spread) else "")
        cells = [
            Path(r.scene).name or r.scene,
            r.method,
            str(r.objects),
            str(r.ground_objects),
            spread,
            _percent(stated.get("relations_realised")),
            _percent(stated.get("supports_right")),
            _percent(held),
        ]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


#: The chart's panels: metric, title, axis maximum (None: from the data).
PANELS = (
    ("cf", "Collision-free scenes (%)", 100.0),
    ("cn", "Colliding pairs per scene", None),
    ("constraints", "Parser's own constraints held (%)", 100.0),
    ("stated", "Relations the text states held (%)", 100.0),
)
COLOURS = ((46, 117, 182), (237, 125, 49), (112, 173, 71), (165, 165, 165))


def chart(summary: dict[str, dict[str, dict]], *, paper: bool = True, size=(1600, 420)) -> Image.Image:
    """One panel per metric; per group a cluster of bars, one colour per method (paper hatched grey)."""
    series: list[tuple[str, dict[str, dict]]] = []
    methods = list(dict.fromkeys(m for ms in summary.values() for m in ms))
    for method in methods:
        series.append((method, {g: ms.get(method, {}) for g, ms in summary.items()}))
    if paper:
        for method in methods:
            rows = {g: PAPER.get((g, method), {}) for g in summary}
            if any(rows.values()):
                series.append((f"{method} (paper)", rows))
    image = Image.new("RGB", size, "white")
    draw = ImageDraw.Draw(image)
    font = ImageFont.load_default()
    width, height = size
    panel_w = width // len(PANELS)
    top, bottom = 50, height - 70
    for p, (key, title, top_value) in enumerate(PANELS):
        x0 = p * panel_w + 40
        x1 = (p + 1) * panel_w - 15
        draw.text((x0, 12), title, fill="black", font=font)
        values = [rows.get(g, {}).get(key) for _, rows in series for g in summary]
        scale = top_value or max([v for v in values if v is not None] + [1.0]) * 1.15
        draw.line([(x0, bottom), (x1, bottom)], fill="black")
        draw.line([(x0, top), (x0, bottom)], fill="black")
        draw.text((x0 - 36, top - 6), f"{scale:.3g}", fill="black", font=font)
        draw.text((x0 - 12, bottom - 6), "0", fill="black", font=font)
        cluster = (x1 - x0) / max(len(summary), 1)
        bar = cluster * 0.8 / max(len(series), 1)
        for g, group in enumerate(summary):
            gx = x0 + g * cluster + cluster * 0.1
            draw.text((gx, bottom + 6), group, fill="black", font=font)
            for s, (_, rows) in enumerate(series):
                value = rows.get(group, {}).get(key)
                if value is None:
                    continue
                bx = gx + s * bar
                by = bottom - (bottom - top) * min(value / scale, 1.0)
                draw.rectangle([bx, by, bx + bar - 3, bottom], fill=COLOURS[s % len(COLOURS)])
                draw.text((bx, by - 12), f"{value:.3g}", fill="black", font=font)
    for s, (name, _) in enumerate(series):
        lx = 40 + s * 220
        draw.rectangle([lx, height - 30, lx + 14, height - 16], fill=COLOURS[s % len(COLOURS)])
        draw.text((lx + 20, height - 30), name, fill="black", font=font)
    return image


def write_report(results: Sequence[SceneMetrics], out: str | Path, *, paper: bool = True) -> dict[str, Path]:
    """``report.json`` (aggregates and every scene), ``table.md`` and ``chart.png`` in ``out``."""
    out = Path(out)
    summary = summarise(results)
    payload = {"sources": SOURCES, "summary": summary, "scenes": [r.to_dict() for r in results]}
    table = markdown_table(summary, paper=paper) + "\n## Per scene\n\n" + scene_table(results)
    paths = {
        "json": write_atomic(out / "report.json", json.dumps(payload, indent=2) + "\n"),
        "table": write_atomic(out / "table.md", table),
    }
    target = out / "chart.png"
    out.mkdir(parents=True, exist_ok=True)
    from io import BytesIO

    buffer = BytesIO()
    chart(summary, paper=paper).save(buffer, format="PNG")
    paths["chart"] = write_atomic(target, buffer.getvalue())
    return paths
