"""What a batch did, on disk: ``batch.json`` (for programs), ``batch.md`` (for people) and
``index.jsonl`` (the dataset index: one line per finished scene, in entry order).

All three are rewritten atomically after every scene, so they are always whole and current.
"""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Sequence
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

from scenewright.batch.entries import Entry, Problem
from scenewright.batch.worker import GRAPH, Outcome
from scenewright.files import write_atomic

FORMAT = "scenewright.batch/1"
#: Statuses of a scene whose folder is complete.
COMPLETE = ("done", "finished")


def _now() -> str:
    return datetime.now(timezone.utc).isoformat(timespec="seconds")


class Record:
    def __init__(
        self,
        out: Path,
        entries: Sequence[Entry],
        problems: Sequence[Problem],
        *,
        source: str,
        executor: str,
        workers: int,
    ):
        self.out = Path(out)
        self.entries = list(entries)
        self.problems = list(problems)
        self.source = source
        self.executor = executor
        self.workers = workers
        self.started = _now()
        self.outcomes: dict[str, Outcome] = {}
        self.interrupted = False
        self.seconds = 0.0

    def add(self, outcome: Outcome) -> None:
        self.outcomes[outcome.id] = outcome

    def status(self, entry_id: str) -> str:
        outcome = self.outcomes.get(entry_id)
        return outcome.status if outcome else "pending"

    def totals(self) -> dict[str, Any]:
        counts = Counter(self.status(e.id) for e in self.entries)
        ran = [o for o in self.outcomes.values() if o.status == "done"]
        complete = [o for o in self.outcomes.values() if o.status in COMPLETE]
        minutes = self.seconds / 60.0
        return {
            "entries": len(self.entries),
            "done": counts["done"],
            "finished_before": counts["finished"],
            "failed": counts["failed"],
            "interrupted": counts["interrupted"],
            "pending": counts["pending"],
            "skipped_lines": len(self.problems),
            "objects": sum(o.objects for o in complete),
            "constraints_held": sum(o.constraints_held for o in complete),
            "constraints": sum(o.constraints for o in complete),
            "collision_free": sum(1 for o in complete if o.collision_free),
            "seconds": round(self.seconds, 3),
            "scene_cpu_seconds": round(sum(o.cpu_seconds for o in ran), 3),
            "scenes_per_minute": round(len(ran) / minutes, 3) if minutes > 0 and ran else None,
        }

    def to_dict(self) -> dict[str, Any]:
        scenes = []
        for entry in self.entries:
            outcome = self.outcomes.get(entry.id)
            row = outcome.to_dict() if outcome else {
                "id": entry.id, "status": "pending", "line": entry.line, "text": entry.text,
                "style": entry.style, "seed": entry.seed or 0,
            }
            scenes.append(row)
        return {
            "format": FORMAT,
            "prompts": self.source,
            "executor": self.executor,
            "workers": self.workers,
            "started": self.started,
            "updated": _now(),
            "interrupted": self.interrupted,
            "totals": self.totals(),
            "scenes": scenes,
            "skipped_lines": [{"line": p.line, "reason": p.reason} for p in self.problems],
        }

    def index_rows(self) -> list[dict[str, Any]]:
        rows = []
        for entry in self.entries:
            outcome = self.outcomes.get(entry.id)
            if outcome is None or outcome.status not in COMPLETE:
                continue
            rows.append(
                {
                    "id": entry.id,
                    "text": entry.text,
                    "style": outcome.style,
                    "seed": outcome.seed,
                    "folder": entry.id,
                    "scene_graph": f"{entry.id}/{GRAPH}",
                    "scene": f"{entry.id}/scene.json",
                    "glb": f"{entry.id}/scene.glb",
                    "objects": outcome.objects,
                    "collision_free": outcome.collision_free,
                }
            )
        return rows

    def markdown(self) -> str:
        t = self.totals()
        state = "interrupted" if self.interrupted else ("running" if t["pending"] else "complete")
        lines = [
            f"# Batch {self.out.name}",
            "",
            f"{t['entries']} scenes from `{self.source}` on {self.executor} ({self.workers} workers), {state}: "
            f"{t['done']} made now, {t['finished_before']} finished before, {t['failed']} failed, "
            f"{t['interrupted']} interrupted, {t['pending']} pending; input lines skipped: {t['skipped_lines']}. "
            f"{t['objects']} objects, constraints held {t['constraints_held']}/{t['constraints']}, "
            f"collision-free {t['collision_free']}/{t['done'] + t['finished_before']}; {t['seconds']:.1f} s.",
            "",
            "| scene | status | objects | constraints held | CF | seconds | reason |",
            "|---|---|---:|---:|:-:|---:|---|",
        ]
        for entry in self.entries:
            o = self.outcomes.get(entry.id)
            if o is None:
                lines.append(f"| {entry.id} | pending | | | | | |")
                continue
            complete = o.status in COMPLETE
            cf = ("yes" if o.collision_free else "no") if complete and o.collision_free is not None else ""
            held = f"{o.constraints_held}/{o.constraints}" if complete else ""
            reason = (o.reason or "").replace("|", "\\|").replace("\n", " ")
            reason = f"{o.error}: {reason}" if o.error else reason
            lines.append(
                f"| {o.id} | {o.status} | {o.objects if complete else ''} | {held} | {cf} | {o.seconds:.2f} | {reason} |"
            )
        if self.problems:
            lines += ["", "## Input lines skipped", ""] + [f"- line {p.line}: {p.reason}" for p in self.problems]
        return "\n".join(lines) + "\n"

    def write(self) -> None:
        write_atomic(self.out / "batch.json", json.dumps(self.to_dict(), indent=1) + "\n")
        write_atomic(self.out / "batch.md", self.markdown())
        write_atomic(self.out / "index.jsonl", "".join(json.dumps(r) + "\n" for r in self.index_rows()))
