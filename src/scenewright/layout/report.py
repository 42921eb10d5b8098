"""The solver's report as text: what a language model reads to revise its constraints."""

from __future__ import annotations

from typing import Sequence

from scenewright.scene import LayoutReport, SceneObject


def feedback_text(report: LayoutReport, objects: Sequence[SceneObject]) -> str:
    """A readable account of what was placed, what was not and why, and what was dropped."""
    names = {o.id: o.name for o in objects}
    total = len(report.placed) + len(report.unplaced)
    verb = "Placed" if report.solver else "Initial poses are fine for"
    lines = [f"{verb} {len(report.placed)} of {total} objects ({report.nodes} nodes, {report.seconds:.2f} CPU s)."]
    if report.unplaced:
        lines.append(
            "Could not satisfy (each stands at its nearest miss where a collision-free pose exists):"
            if report.solver else "Problems with the initial poses:"
        )
        for u in report.unplaced:
            label = f"{u.id} ({names[u.id]})" if names.get(u.id) and names[u.id] != u.id else u.id
            lines.append(f"- {label}: {u.reason}.")
            if u.failed:
                lines.append("  failed constraints: " + "; ".join(str(c) for c in u.failed))
            if u.nearest_miss:
                lines.append(f"  nearest miss: {u.nearest_miss}")
    if report.dropped:
        lines.append("Dropped constraints:")
        lines.extend(f"- {d.reason}" for d in report.dropped)
    return "\n".join(lines)
