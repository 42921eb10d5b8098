"""Scores the offline parser against annotated descriptions (``benchmarks/prompts*``).

Each parsed object counts as the annotation key it matches (its category, or for a thing
outside the catalogue the key's words in its name, :func:`assign_keys`). Relations are compared
at key level, as sets, and only the relations the parser read from the text count: the ones it
inferred (a lamp put on a nightstand nobody mentioned it standing on) are reported separately.
A relation and its inverse are one spatial fact ("the farmer near the goat" is "the goat near
the farmer", "a cart left of the shed" is "the shed right of the cart": the same boxes, the same
buffer), so each side is compared in one orientation. A *between* entry is recalled when the
parser related the source to both targets, in whatever relations it chose; those relations are
then correct, not wrong.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from pathlib import Path

from scenewright.analysis.parser import parse_scene
from scenewright.core.relations import INVERSE
from scenewright.core.styles import find_look
from scenewright.evaluation.annotations import Prompt, assign_keys, default_prompt_dir, load_prompts

__all__ = ["Prompt", "default_prompt_dir", "load_prompts", "run_parse_bench", "score_objects", "score_prompt", "summarise"]


def oriented(triple: tuple[str, str, str]) -> tuple[str, str, str]:
    """One orientation of a relation and its inverse: the one whose source key sorts first."""
    source, relation, target = triple
    if relation in INVERSE and target < source:
        return target, INVERSE[relation], source
    return triple


def score_objects(
    prompt: Prompt,
    objects: Iterable[tuple[str, str | None, str]],
    relations: Iterable[tuple[str, str, str]],
) -> dict:
    """Object and relation counts of one reading: ``(id, category, name)`` objects, ``(source id, relation, target id)``."""
    objects = list(objects)
    keys = assign_keys(objects, prompt.objects)
    label = {oid: keys.get(oid, category or name.replace(" ", "_")) for oid, category, name in objects}
    predicted = Counter(label.values())
    need = sum(lo for lo, _ in prompt.objects.values())
    found = sum(min(predicted.get(key, 0), lo) for key, (lo, _) in prompt.objects.items())
    right = sum(min(n, prompt.objects.get(key, (0, 0))[1]) for key, n in predicted.items())
    triples = {(label[s], r, label[t]) for s, r, t in relations if s in label and t in label}
    stated = {oriented(t) for t in prompt.relations}
    hits = {t for t in triples if oriented(t) in stated}
    recalled = {t for t in prompt.relations if oriented(t) in {oriented(p) for p in triples}}
    explained: set[tuple[str, str, str]] = set()
    between_hits = []
    for source, first, second in sorted(prompt.between):
        to_first = {t for t in triples if {t[0], t[2]} == {source, first} and (t[0] == source or t[1] in INVERSE)}
        to_second = {t for t in triples if {t[0], t[2]} == {source, second} and (t[0] == source or t[1] in INVERSE)}
        if to_first and to_second:
            between_hits.append((source, first, second))
            explained |= to_first | to_second
    correct = hits | explained
    return {
        "objects_expected": need,
        "objects_found": found,
        "objects_predicted": sum(predicted.values()),
        "objects_correct": right,
        "relations_expected": prompt.stated,
        "relations_predicted": len(triples),
        "relations_recalled": len(recalled) + len(between_hits),
        "relations_correct": len(correct),
        "missing_objects": sorted(
            f"{key}×{lo - predicted.get(key, 0)}" for key, (lo, _) in prompt.objects.items() if predicted.get(key, 0) < lo
        ),
        "extra_objects": sorted(
            f"{key}×{n - prompt.objects.get(key, (0, 0))[1]}"
            for key, n in predicted.items()
            if n > prompt.objects.get(key, (0, 0))[1]
        ),
        "missing_relations": sorted(
            [" | ".join(t) for t in prompt.relations - recalled]
            + [f"{s} | between | {a} | {b}" for s, a, b in prompt.between if (s, a, b) not in between_hits]
        ),
        "wrong_relations": sorted(" | ".join(t) for t in triples - correct),
    }


def score_prompt(prompt: Prompt) -> dict:
    parsed = parse_scene(prompt.text)
    row = score_objects(
        prompt,
        ((o.id, o.category, o.name) for o in parsed.objects),
        ((r.source, r.relation, r.target) for r in parsed.relations if not r.inferred),
    )
    return {
        "id": prompt.id,
        "domain": prompt.domain,
        **row,
        "relations_inferred": sum(r.inferred for r in parsed.relations),
        "style_correct": same_look(parsed.style, prompt.style),
    }


def same_look(read: str, annotated: str) -> bool:
    """Whether the reader named the look an annotation names: annotations name a style as a writer
    would ("copperplate engraving", "Art Deco travel poster"), the reader by the look that draws it
    (``data/styles.json``) and the colours it is named in ("textile in indigo and ochre"), so a name
    the table knows counts as its look."""
    look, drawn = find_look(annotated), find_look(read)
    return read == annotated or (look is not None and drawn is not None and look.name == drawn.name)


def ratio(a: int, b: int) -> float:
    return round(a / b, 4) if b else 1.0


def parse_figures(rows: list[dict]) -> dict:
    """Object recall / precision and relation recall / precision over ``rows`` of :func:`score_objects`."""

    def total(key: str) -> int:
        return sum(r[key] for r in rows)

    return {
        "object_recall": ratio(total("objects_found"), total("objects_expected")),
        "object_precision": ratio(total("objects_correct"), total("objects_predicted")),
        "relation_recall": ratio(total("relations_recalled"), total("relations_expected")),
        "relation_precision": ratio(total("relations_correct"), total("relations_predicted")),
    }


def summarise(rows: list[dict]) -> dict:
    result: dict = {"prompts": len(rows)}
    domains = ((d, [r for r in rows if r["domain"] == d]) for d in ("indoor", "outdoor"))
    for name, subset in (("all", rows), *((d, subset) for d, subset in domains if subset)):
        result[name] = parse_figures(subset) | {
            "style_accuracy": ratio(sum(r["style_correct"] for r in subset), len(subset)),
        }
    result.update(result.pop("all"))
    result["inferred_relations"] = sum(r["relations_inferred"] for r in rows)
    return result


def run_parse_bench(folder: Path | None = None, details: bool = False) -> dict:
    rows = [score_prompt(p) for p in load_prompts(folder)]
    result = summarise(rows)
    if details:
        result["details"] = rows
    return result
