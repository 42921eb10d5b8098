"""What an edit instruction asks for, as both edit planners (model and rule-based) answer it.

The plan is validated like any model answer before :func:`scenewright.editing.apply_edit`
acts on it: the focus must exist, and it must be the only source of the new constraints.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from scenewright.scene import Constraint, Vec3

Operation = Literal["move", "add", "delete", "replace", "room"]


class NewObject(BaseModel):
    """The object an ``add`` creates or a ``replace`` turns the focus into."""

    model_config = ConfigDict(extra="forbid")

    name: str
    category: str | None = None
    visual_description: str = ""
    size: Vec3 | None = None


class RoomEdit(BaseModel):
    """What a ``room`` edit changes: the floor's size, or a door or window added on a side."""

    model_config = ConfigDict(extra="forbid")

    #: New floor (width, depth) in metres; the room stays a rectangle centred where it was.
    size: tuple[float, float] | None = None
    height: float | None = None
    #: A door or window to add, on the wall facing ``side`` (back, front, left, right; None: any).
    opening: Literal["door", "window"] | None = None
    side: Literal["back", "front", "left", "right"] | None = None


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
    #: For a ``room`` edit (its focus is ``room``): what changes in the room.
    room: RoomEdit | None = None
