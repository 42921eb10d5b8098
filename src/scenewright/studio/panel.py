"""What the editor's panel says about one object: who it is, where, and which of its
constraints hold, judged by the same checks as the solver and the evaluation."""

from __future__ import annotations

from dataclasses import dataclass

from scenewright.layout.relations import check, describe, violation
from scenewright.scene import Constraint, Scene, SceneObject


@dataclass(frozen=True)
class ConstraintState:
    text: str
    held: bool
    #: How far it is from holding ("misses by 0.30 m"), empty when it holds.
    miss: str


@dataclass(frozen=True)
class ObjectPanel:
    id: str
    name: str
    description: str
    size: tuple[float, float, float]
    position: tuple[float, float, float]
    yaw: float
    constraints: list[ConstraintState]
    #: The layout report's reason when the solver could not place the object.
    unplaced: str | None

    def markdown(self) -> str:
        sx, sy, sz = self.size
        px, py, pz = self.position
        lines = [
            f"**{self.name}** `{self.id}`",
            "",
            self.description or "_no description_",
            "",
            f"size {sx:.2f} × {sy:.2f} × {sz:.2f} m",
            "",
            f"position ({px:.2f}, {py:.2f}, {pz:.2f}), yaw {self.yaw:.0f}°",
            "",
        ]
        if self.unplaced:
            lines += [f"**unplaced:** {self.unplaced}", ""]
        if not self.constraints:
            lines.append("no constraints")
        for c in self.constraints:
            lines.append(f"- {c.text}: " + ("held" if c.held else f"**violated** ({c.miss})"))
        return "\n".join(lines)


def constraint_state(constraint: Constraint, source: SceneObject, target: SceneObject) -> ConstraintState:
    """Whether ``constraint`` holds between these poses of its two objects, and by how much it misses."""
    held = check(constraint.relation, source, target)
    miss = "" if held else describe(constraint.relation, violation(constraint.relation, source, target))
    return ConstraintState(str(constraint), held, miss)


def object_panel(scene: Scene, object_id: str) -> ObjectPanel:
    """The panel of ``object_id`` (an :class:`InputError` naming the known ids when absent)."""
    obj = scene.get(object_id)
    states = [constraint_state(c, scene.get(c.source), scene.get(c.target))
              for c in scene.constraints if object_id in (c.source, c.target)]
    unplaced = None
    if scene.layout is not None:
        unplaced = next((u.reason + (f" ({u.nearest_miss})" if u.nearest_miss else "")
                         for u in scene.layout.unplaced if u.id == object_id), None)
    return ObjectPanel(
        id=obj.id, name=obj.name, description=obj.visual_description, size=obj.size.tuple(),
        position=obj.position.tuple(), yaw=obj.yaw, constraints=states, unplaced=unplaced,
    )
