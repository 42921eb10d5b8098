"""Scene generation (paper §3.3): constraints from the model, the solver, and the feedback loop.

When the solver cannot place every object, its report (which object, which constraints,
the nearest miss) goes back to the vision-language model, which revises the constraints;
the layout is solved again, for a bounded number of rounds. The most complete layout of all
rounds wins, so a revision that makes things worse costs nothing.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from scenewright.core.protocols import VisionLanguageModel
from scenewright.folder import SceneFolder
from scenewright.layout import LayoutResult, solve
from scenewright.layout.room import access_trouble, resized
from scenewright.scene import ROOM_RELATIONS, Constraint, Scene, SceneObject

if TYPE_CHECKING:  # the meshes are an asset's AssetMesh: the collision world needs no mesh library
    import trimesh

#: Adds the placement priors of a room to the constraints (objects, constraints, ceiling height) -> constraints.
Furnish = Callable[[Sequence[SceneObject], Sequence[Constraint], float], list[Constraint]]
#: The ceiling height a room needs for its constraints (objects, constraints, ceiling height) -> height.
Lift = Callable[[Sequence[SceneObject], Sequence[Constraint], float], float]

log = logging.getLogger(__name__)

STAGE = "layout"
#: How much each side of a room nobody sized grows when its layout leaves something out of reach.
GROW_STEP = 1.15
#: How many times it may grow (1.15³ ≈ 1.5 times as long and wide).
GROW_STEPS = 3


def _score(result: LayoutResult) -> tuple[int, int]:
    """More objects placed is better; among equals, more of the model's constraints kept."""
    return (len(result.report.placed), len(result.constraints))


def _grown(scene: Scene, best: LayoutResult, meshes: Mapping[str, trimesh.Trimesh], time_limit: float) -> LayoutResult:
    """``best``, or the layout of its constraints in the room grown by :data:`GROW_STEP` per side
    (up to :data:`GROW_STEPS` times) until every object is placed, inside, reachable, and no
    door or window is blocked; the room grows with it. The fewest problems win, the smaller
    room on a tie (docs/rooms.md). The growing shares one layout's ``time_limit`` among its solves."""
    assert scene.room is not None

    def trouble(result: LayoutResult, room) -> tuple[int, int]:
        placed = [o for o in result.objects if o.id in result.report.placed]
        return len(result.report.unplaced), access_trouble(room, placed)

    room, score = scene.room, trouble(best, scene.room)
    bigger = room
    for _ in range(GROW_STEPS):
        if score == (0, 0):
            break
        (x0, y0), (x1, y1) = np.min(bigger.floor, axis=0), np.max(bigger.floor, axis=0)
        bigger = resized(bigger, round((x1 - x0) * GROW_STEP, 1), round((y1 - y0) * GROW_STEP, 1))
        result = solve(scene.objects, best.constraints, meshes=meshes, bounds=scene.bounds,
                       time_limit=time_limit / GROW_STEPS, seed=scene.seed, room=bigger)
        now = trouble(result, bigger)
        if now < score:
            best, room, score = result, bigger, now
    if room is not scene.room:
        (x0, y0), (x1, y1) = np.min(room.floor, axis=0), np.max(room.floor, axis=0)
        left = "every object placed and within reach" if score == (0, 0) else f"{sum(score)} problems left"
        scene.record(STAGE, f"grew the room to {x1 - x0:g} x {y1 - y0:g} m: {left}",
                     step="grow room", floor=[list(p) for p in room.floor])
        scene.room = room
    return best


def _record_round(scene: Scene, number: int, result: LayoutResult) -> None:
    report = result.report
    unplaced = {u.id: u.reason for u in report.unplaced}
    scene.record(
        STAGE,
        f"round {number}: placed {len(report.placed)} of {len(report.placed) + len(unplaced)} objects",
        round=number,
        constraints=[str(c) for c in result.constraints],
        dropped=len(report.dropped),
        unplaced=unplaced,
        nodes=report.nodes,
        seconds=round(report.seconds, 3),
        **({"room": list(report.room)} if report.room else {}),
    )


def arrange(
    scene: Scene,
    folder: SceneFolder,
    vlm: VisionLanguageModel,
    meshes: Mapping[str, trimesh.Trimesh],
    *,
    rounds: int = 3,
    time_limit: float = 10.0,
    furnish: Furnish | None = None,
    grow: bool = False,
    lift: Lift | None = None,
) -> Scene:
    """Solve the layout of ``scene``'s objects, revising constraints up to ``rounds`` times
    (the caller saves the document).

    In a room, ``furnish`` adds its placement priors to freshly written constraints; without
    one, relations to a room are dropped (and recorded), since there are no walls to meet.
    With ``grow`` (a room nobody gave a size), a layout that leaves objects unplaced or out
    of reach, or a door blocked, is solved again in a larger room (docs/rooms.md). ``lift`` (for a
    room nobody gave a height) raises the ceiling to what the fresh constraints need first."""
    reference = folder.reference()
    constraints = list(scene.constraints)
    if not constraints:
        answer = vlm.write_constraints(scene.text, scene.objects, reference, scene.room)
        scene.provenance += answer.repairs  # what the model's answer needed repaired
        constraints = answer.value
        scene.record(STAGE, f"wrote {len(constraints)} constraints", backend=vlm.name)
        if scene.room is not None and lift is not None:
            height = lift(scene.objects, constraints, scene.room.height)
            if height > scene.room.height:
                (x0, y0), (x1, y1) = np.min(scene.room.floor, axis=0), np.max(scene.room.floor, axis=0)
                scene.room = resized(scene.room, float(x1 - x0), float(y1 - y0), height)
                scene.record(STAGE, f"raised the ceiling to {height:g} m for what hangs above another",
                             step="raise ceiling", height=height)
        if scene.room is not None and furnish is not None:
            constraints = furnish(scene.objects, constraints, scene.room.height)
    if scene.room is None and any(c.relation in ROOM_RELATIONS for c in constraints):
        dropped = [str(c) for c in constraints if c.relation in ROOM_RELATIONS]
        constraints = [c for c in constraints if c.relation not in ROOM_RELATIONS]
        scene.record(STAGE, f"dropped {len(dropped)} relations to a room: the scene has none", dropped=dropped)
    scene.remember_initial_poses()  # the model's proposal, before any solve moves it (the ablation's layout)
    best: LayoutResult | None = None
    for number in range(rounds + 1):
        result = solve(
            scene.objects,
            constraints,
            meshes=meshes,
            bounds=scene.bounds,
            time_limit=time_limit,
            seed=scene.seed,
            room=scene.room,
        )
        _record_round(scene, number, result)
        if best is None or _score(result) > _score(best):
            best = result
        if result.report.complete or number == rounds:
            break
        log.info("round %d left %d unplaced; asking for new constraints", number, len(result.report.unplaced))
        answer = vlm.revise_constraints(
            scene.text, scene.objects, result.constraints, result.report, reference, scene.room
        )
        scene.provenance += answer.repairs
        constraints = answer.value
    assert best is not None
    if grow and scene.room is not None:
        best = _grown(scene, best, meshes, time_limit)
    solved = {obj.id: obj for obj in best.objects}
    scene.objects = [solved[obj.id] for obj in scene.objects]
    scene.constraints = list(best.constraints)
    scene.layout = best.report
    return scene
