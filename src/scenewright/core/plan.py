"""What an edit instruction asks for, as both edit planners (model and rule-based) answer it.

The plan is validated like any model answer before :func:`scenewright.editing.apply_edit`
acts on it: the focus must exist, and it must be the only source of the new constraints.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from scenewright.scene import Constraint, Vec3

Operation = Literal["move", "add", "delete", "replace"]


class NewObject(BaseModel):
    """The object an ``add`` creates or a ``replace`` turns the focus into."""

    model_config = ConfigDict(extra="forbid")

    name: str
    category: str | None = None
    visual_description: str = ""
    size: Vec3 | None = None


class EditPlan(BaseModel):
    model_config = ConfigDict(extra="forbid")

    operation: Operation
    #: Id of the one object the edit changes; for ``add``, the id the new object will take.
    focus: str
    #: New constraints with ``focus`` as their only source (move, add; replace when re-placed).
    constraints: list[Constraint] = Field(default_factory=list)
    new_object: NewObject | None = None
    #: Turn the focus in place (degrees about +Z), when the instruction asks for a rotation only.
    yaw: float | None = None
    #: Shift the focus from where it stands, in metres in the scene frame (+X right, +Y back),
    #: when a move names no other object ("move the sofa to the left", "1 m forward").
    offset: Vec3 | None = None
