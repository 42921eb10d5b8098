"""Scene generation (paper §3.3): constraints from the model, the solver, and the feedback loop.

When the solver cannot place every object, its report (which object, which constraints,
the nearest miss) goes back to the vision-language model, which revises the constraints;
the layout is solved again, for a bounded number of rounds. The most complete layout of all
rounds wins, so a revision that makes things worse costs nothing.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping, Sequence

import trimesh

from scenewright.core.protocols import VisionLanguageModel
from scenewright.folder import SceneFolder
from scenewright.layout import LayoutResult, solve
from scenewright.scene import ROOM_RELATIONS, Constraint, Scene, SceneObject

#: Adds the placement priors of a room to the constraints (objects, constraints) -> constraints.
Furnish = Callable[[Sequence[SceneObject], Sequence[Constraint]], list[Constraint]]

log = logging.getLogger(__name__)

STAGE = "layout"


def _score(result: LayoutResult) -> tuple[int, int]:
    """More objects placed is better; among equals, more of the model's constraints kept."""
    return (len(result.report.placed), len(result.constraints))


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
) -> Scene:
    """Solve the layout of ``scene``'s objects, revising constraints up to ``rounds`` times
    (the caller saves the document).

    In a room, ``furnish`` adds its placement priors to freshly written constraints; without
    one, relations to a room are dropped (and recorded), since there are no walls to meet."""
    reference = folder.reference()
    constraints = list(scene.constraints)
    if not constraints:
        answer = vlm.write_constraints(scene.text, scene.objects, reference, scene.room)
        scene.provenance += answer.repairs  # what the model's answer needed repaired
        constraints = answer.value
        scene.record(STAGE, f"wrote {len(constraints)} constraints", backend=vlm.name)
        if scene.room is not None and furnish is not None:
            constraints = furnish(scene.objects, constraints)
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
    solved = {obj.id: obj for obj in best.objects}
    scene.objects = [solved[obj.id] for obj in scene.objects]
    scene.constraints = list(best.constraints)
    scene.layout = best.report
    return scene
