"""Scores the offline parser against the annotated descriptions in ``benchmarks/prompts/``.

Each prompt file holds the text, its domain, the style it names, the expected objects
(category → count, or [least, most] where the text is vague) and the expected relations as
(source category, relation, target category). Relations are compared at category level, as
sets, and only the relations the parser read from the text count: the ones it inferred (a
lamp put on a nightstand nobody mentioned it standing on) are reported separately.
"""

from __future__ import annotations

import json
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from scenewright.analysis.parser import ParsedScene, parse_scene
from scenewright.errors import InputError


@dataclass(frozen=True)
class Prompt:
    id: str
    domain: str
    style: str
    text: str
    objects: dict[str, tuple[int, int]]
    relations: frozenset[tuple[str, str, str]]


def default_prompt_dir() -> Path:
    """``benchmarks/prompts`` of the source tree this package runs from, else of the cwd."""
    here = Path(__file__).resolve().parents[3] / "benchmarks" / "prompts"
    return here if here.is_dir() else Path("benchmarks/prompts")


def load_prompts(folder: Path | None = None) -> list[Prompt]:
    folder = Path(folder) if folder else default_prompt_dir()
    files = sorted(folder.glob("*.json"))
    if not files:
        raise InputError(f"{folder}: no prompt files (*.json); pass --prompts DIR")
    prompts = []
    for path in files:
        try:
            raw = json.loads(path.read_text(encoding="utf-8"))
            objects = {
                cat: (int(v[0]), int(v[1])) if isinstance(v, list) else (int(v), int(v))
                for cat, v in raw["objects"].items()
            }
            relations = frozenset(tuple(r) for r in raw["relations"])
            prompts.append(Prompt(raw["id"], raw["domain"], raw["style"], raw["text"], objects, relations))  # type: ignore[arg-type]
        except (json.JSONDecodeError, KeyError, TypeError, ValueError) as exc:
            raise InputError(f"{path}: not a prompt file ({exc})") from None
    return prompts


def _relation_triples(parsed: ParsedScene) -> set[tuple[str, str, str]]:
    category = {o.id: o.category for o in parsed.objects}
    return {(category[r.source], r.relation, category[r.target]) for r in parsed.relations if not r.inferred}


def score_prompt(prompt: Prompt) -> dict:
    parsed = parse_scene(prompt.text)
    predicted = Counter(o.category for o in parsed.objects)
    need = sum(lo for lo, _ in prompt.objects.values())
    found = sum(min(predicted.get(cat, 0), lo) for cat, (lo, _) in prompt.objects.items())
    right = sum(min(n, prompt.objects.get(cat, (0, 0))[1]) for cat, n in predicted.items())
    triples = _relation_triples(parsed)
    hits = triples & prompt.relations
    return {
        "id": prompt.id,
        "domain": prompt.domain,
        "objects_expected": need,
        "objects_found": found,
        "objects_predicted": sum(predicted.values()),
        "objects_correct": right,
        "relations_expected": len(prompt.relations),
        "relations_predicted": len(triples),
        "relations_correct": len(hits),
        "relations_inferred": sum(r.inferred for r in parsed.relations),
        "style_correct": parsed.style == prompt.style,
        "missing_objects": sorted(
            f"{cat}×{lo - predicted.get(cat, 0)}" for cat, (lo, _) in prompt.objects.items() if predicted.get(cat, 0) < lo
        ),
        "extra_objects": sorted(
            f"{cat}×{n - prompt.objects.get(cat, (0, 0))[1]}"
            for cat, n in predicted.items()
            if n > prompt.objects.get(cat, (0, 0))[1]
        ),
        "missing_relations": sorted(" | ".join(t) for t in prompt.relations - triples),
        "wrong_relations": sorted(" | ".join(t) for t in triples - prompt.relations),
    }


def _ratio(a: int, b: int) -> float:
    return round(a / b, 4) if b else 1.0


def summarise(rows: list[dict]) -> dict:
    def total(key: str, subset=rows) -> int:
        return sum(r[key] for r in subset)

    result: dict = {"prompts": len(rows)}
    for name, subset in (("all", rows), *((d, [r for r in rows if r["domain"] == d]) for d in ("indoor", "outdoor"))):
        result[name] = {
            "object_recall": _ratio(total("objects_found", subset), total("objects_expected", subset)),
            "object_precision": _ratio(total("objects_correct", subset), total("objects_predicted", subset)),
            "relation_recall": _ratio(total("relations_correct", subset), total("relations_expected", subset)),
            "relation_precision": _ratio(total("relations_correct", subset), total("relations_predicted", subset)),
            "style_accuracy": _ratio(sum(r["style_correct"] for r in subset), len(subset)),
        }
    result.update(result.pop("all"))
    result["inferred_relations"] = total("relations_inferred")
    return result


def run_parse_bench(folder: Path | None = None, details: bool = False) -> dict:
    rows = [score_prompt(p) for p in load_prompts(folder)]
    result = summarise(rows)
    if details:
        result["details"] = rows
    return result
