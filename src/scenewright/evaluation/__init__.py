"""Scoring scenes the way the paper does (§4, Table 1) so every change can be compared.

Per scene: physical plausibility (collisions at mesh level, out of bounds, unsupported
objects), composition (the spread of the ground objects: near 0 is a line), the constraints
the analysis stage wrote that hold (the paper's spatial consistency: it checks the layout
against the parser's own reading, never against the text), and, when an annotation of the
text is given, the relations the *text* states that hold and the supports that are right
(:mod:`scenewright.evaluation.stated`); then perceptual quality (CLIP on the render, with
user-supplied weights) and the vision-language judge (Pos., Rot., SA, PSA).
:mod:`scenewright.evaluation.report` aggregates them into the paper's table.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path

import trimesh

from scenewright.core.protocols import VisionLanguageModel
from scenewright.evaluation.annotations import Prompt, find_annotation
from scenewright.evaluation.composition import spread
from scenewright.evaluation.judge import judge, psa
from scenewright.evaluation.perceptual import ClipScorer
from scenewright.evaluation.physical import physical
from scenewright.evaluation.room import room_metrics
from scenewright.evaluation.spatial import spatial
from scenewright.evaluation.stated import stated
from scenewright.files import check_image
from scenewright.folder import SceneFolder, as_folder
from scenewright.scene import Scene

log = logging.getLogger(__name__)

FULL = "full"
ABLATED = "w/o solver"


@dataclass
class SceneMetrics:
    scene: str
    group: str
    method: str
    objects: int
    collisions: list[tuple[str, str]]
    out_of_bounds: list[str]
    floating: list[str]
    sunken: list[str]
    #: relation → [satisfied, total], over the constraints the analysis stage wrote (not the text)
    constraints: dict[str, list[int]]
    violated: list[str]
    #: minor/major standard deviation of the ground objects' centres (None: fewer than three)
    spread: float | None = None
    ground_objects: int = 0
    #: the annotation this scene was checked against, and what its text states that holds
    #: (:meth:`scenewright.evaluation.stated.Stated.to_dict`); None without an annotation
    annotation: str | None = None
    stated: dict | None = None
    clip: float | None = None
    #: pos, rot, sa (1–100) when the judge could score the render
    judge: dict[str, float] = field(default_factory=dict)
    psa: float | None = None
    #: metric → why it could not be computed
    unavailable: dict[str, str] = field(default_factory=dict)
    #: the MuJoCo settle check (:mod:`scenewright.evaluation.stability`), when it could run
    stability: dict | None = None
    #: how the layout sits in its room (:mod:`scenewright.evaluation.room`); None without a room
    room: dict | None = None

    @property
    def collision_free(self) -> bool:
        return not self.collisions

    def to_dict(self) -> dict:
        return asdict(self) | {"collision_free": self.collision_free}


def evaluate_scene(
    scene: Scene,
    *,
    name: str,
    group: str = "scenes",
    method: str = FULL,
    meshes: Mapping[str, trimesh.Trimesh] | None = None,
    image: Path | None = None,
    clip: ClipScorer | None = None,
    vlm: VisionLanguageModel | None = None,
    annotation: Prompt | None = None,
) -> SceneMetrics:
    """Every metric for one scene; render-based ones only when ``image`` (its render) is given,
    the text's relations only when its ``annotation`` is."""
    phys, spat = physical(scene, meshes), spatial(scene)
    ratio, ground = spread(scene)
    metrics = SceneMetrics(
        scene=name,
        group=group,
        method=method,
        objects=len(scene.objects),
        collisions=[tuple(p) for p in phys.collisions],
        out_of_bounds=phys.out_of_bounds,
        floating=phys.floating,
        sunken=phys.sunken,
        constraints=spat.by_relation,
        violated=spat.violated,
        spread=ratio,
        ground_objects=ground,
    )
    in_room = room_metrics(scene)
    metrics.room = None if in_room is None else in_room.to_dict()
    if annotation is not None:
        metrics.annotation = annotation.id
        metrics.stated = stated(scene, annotation).to_dict()
    wanted = [m for m, asked in (("clip", clip), ("judge", vlm)) if asked is not None]
    if image is None:
        for metric in wanted:
            metrics.unavailable[metric] = "no render of this layout (run `scenewright render DIR`)"
        return metrics
    if clip is not None:
        metrics.clip = clip.score(scene.text, image)
    if vlm is not None:
        verdict = judge(scene.text, check_image(image.read_bytes(), f"the render {image}"), vlm)
        if verdict.unavailable:
            metrics.unavailable["judge"] = verdict.unavailable
        else:
            metrics.judge = verdict.scores
            metrics.psa = psa(metrics.collision_free, verdict.scores["sa"])
    return metrics


def evaluate(
    folders: Sequence[SceneFolder | str | Path],
    *,
    group: str = "scenes",
    ablation: bool = False,
    clip: ClipScorer | None = None,
    judge_vlm: VisionLanguageModel | None = None,
    annotations: Sequence[Prompt] | None = None,
) -> list[SceneMetrics]:
    """Metrics of each scene folder; with ``ablation`` also its layout without the solver.

    The ablated layout is the initial one recorded in the document; it is not rendered, so its
    CLIP and judge scores are reported unavailable. With ``annotations``, each scene is checked
    against the one with its text (or, failing that, whose id is the folder's name).
    """
    from scenewright.assets import load_meshes
    from scenewright.evaluation.ablation import initial_objects, without_solver
    from scenewright.evaluation.stability import settle_check
    from scenewright.render import best_render

    results = []
    for item in folders:
        folder = as_folder(item)
        scene = folder.load()
        meshes = load_meshes(scene, folder)
        name = str(folder.root)
        annotation = find_annotation(annotations, text=scene.text, name=folder.root.name) if annotations else None
        results.append(
            evaluate_scene(
                scene,
                name=name,
                group=group,
                meshes=meshes,
                image=best_render(folder),
                clip=clip,
                vlm=judge_vlm,
                annotation=annotation,
            )
        )
        settle_check(results[-1], scene, folder)
        if ablation:
            ablated = without_solver(scene, initial_objects(scene), meshes)
            results.append(
                evaluate_scene(
                    ablated,
                    name=name,
                    group=group,
                    method=ABLATED,
                    meshes=meshes,
                    clip=clip,
                    vlm=judge_vlm,
                    annotation=annotation,
                )
            )
        if annotations and annotation is None:
            for r in results[-(2 if ablation else 1):]:
                r.unavailable["stated"] = (
                    f"no annotation has this scene's text or the id {folder.root.name!r}"
                )
    return results
