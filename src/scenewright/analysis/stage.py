"""Scene analysis (paper §3.1): text → reference image, objects, object images, ground texture.

Each step writes its output into the scene folder and the document before the next starts,
and is skipped when that output is already there, so an interrupted run resumes where it
stopped. The stage does not save the document itself: the pipeline does, when the stage ends,
and at the checkpoints this stage offers after each step (``checkpoint``). Paid answers are cached by the remote backends themselves (keyed by the whole
request), so a fresh run of the same text pays for nothing twice; the offline backends are
cheap enough to ask again.
"""

from __future__ import annotations

import logging
from collections.abc import Callable

from scenewright.analysis.parser.support import LIVING_SHAPES
from scenewright.core.catalogue import load_catalogue
from scenewright.core.protocols import ImageGenerator, VisionLanguageModel
from scenewright.errors import InputError
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.scene import RemovedObject, Scene, Vec3

log = logging.getLogger(__name__)

STAGE = "analyze"
#: m, the least gap left between the tallest object and the ceiling.
CEILING_CLEARANCE = 0.1
#: m, the least height a thing stacked under the ceiling keeps (a host filling the room leaves none).
MIN_STACKED = 0.1
#: Provenance step that marks the redundancy check as done (its output may be "nothing removed").
REDUNDANCY_STEP = "redundant"


def _note(progress: Callable[[str], None] | None, message: str) -> None:
    log.info(message)
    if progress is not None:
        progress(message)


def _reference(scene: Scene, folder: SceneFolder, images: ImageGenerator) -> bytes | None:
    if folder.reference_image.is_file():
        return folder.reference()
    data = images.reference_image(scene.text, scene.style)
    if data is None:
        return None
    write_atomic(folder.reference_image, data)
    scene.record(STAGE, "drew the reference image", step="reference", backend=images.name)
    return data


def _objects(scene: Scene, vlm: VisionLanguageModel, reference: bytes | None, room: str) -> None:
    """The objects, and the room they stand in (decided with them, so that a resumed run that
    finds the objects finds their room too)."""
    from scenewright.analysis.composition.anchors import into_room
    from scenewright.analysis.parser.room import parse_room_option, room_for

    answer = vlm.describe_objects(scene.text, scene.style, reference)
    scene.provenance += answer.repairs  # what the model's answer needed repaired
    objects = answer.value
    if not objects:
        raise InputError(
            f"found no object to build in the text {scene.text[:80]!r}; name the things the scene "
            "holds, e.g. 'a wooden table with four chairs around it'"
        )
    scene.objects = objects
    scene.initial = {}  # poses proposed for an earlier object list no longer apply
    scene.record(
        STAGE, f"found {len(objects)} objects", step="objects", backend=vlm.name, ids=[o.id for o in objects]
    )
    scene.room = room_for(scene.text, objects, parse_room_option(room), answer.room, answer.proposes_room)
    scene.ground.water = answer.water if scene.room is None else None  # a room's floor has no water
    if scene.room is not None and answer.anchored:  # "a sofa at the back of the room", with its group
        scene.objects = into_room(scene.objects, scene.room, answer.anchored)
    if scene.room is not None:
        _fit_under_ceiling(scene)
        xs, ys = [p[0] for p in scene.room.floor], [p[1] for p in scene.room.floor]
        scene.record(STAGE, f"room {max(xs) - min(xs):g} x {max(ys) - min(ys):g} m, {scene.room.height:g} m high, "
                     f"{len(scene.room.openings)} openings", step="room", room=room, walls=len(scene.room.floor))


def _fit_under_ceiling(scene: Scene) -> None:
    """Scale down, proportions kept, every object taller than the room, and every thing stacked
    on another that would reach past the ceiling on it: a thing the text puts in a room stands
    in it (a "cat tree" read as a 6 m tree; a plant on top of a wardrobe under a low ceiling).
    A thing is stacked when its first pose stands on another's top (within 2 cm, over it). What
    stands on a hung thing (a pelican on a wall shelf) keeps its size: the ceiling a room nobody
    gave a height gets is raised for it later (``lift``), or the solver says it does not fit. A
    host keeps room for the people and animals on it, so a stage or a ladder shrinks rather than
    the quizmaster or the apprentice on it."""
    assert scene.room is not None
    ceiling = scene.room.height - CEILING_CLEARANCE
    first = {o.id: (o.position.z - o.size.z / 2, o.position.z + o.size.z / 2) for o in scene.objects}
    tops_first = [top for _, top in first.values()]
    hung = {i for i, (bottom, _) in first.items() if bottom > 0.02 and all(abs(t - bottom) >= 0.02 for t in tops_first)}
    order = sorted(scene.objects, key=lambda o: first[o.id][0])
    host_of = {o.id: _first_host(o, order[:k], first) for k, o in enumerate(order)}
    catalogue = load_catalogue()
    riders: dict[str, float] = {}  # host id -> the tallest person or animal standing on it
    for o in order:
        host = host_of[o.id]
        if host is not None and o.category in catalogue and catalogue[o.category].shape in LIVING_SHAPES:
            riders[host.id] = max(riders.get(host.id, 0.0), o.size.z)
    tops: dict[str, float] = {}  # each object's top once fitted, lowest first
    shrunk = {}
    for obj in order:
        bottom, host = first[obj.id][0], host_of[obj.id]
        base = tops[host.id] if host is not None else 0.0
        rider = riders.get(obj.id, 0.0)
        limit = max(ceiling - base - (rider if rider < ceiling - base - MIN_STACKED else 0.0), MIN_STACKED)
        if obj.size.z > limit and (host is None or host.id not in hung):
            k = limit / obj.size.z
            obj.size = Vec3(x=obj.size.x * k, y=obj.size.y * k, z=limit)
            shrunk[obj.id] = round(k, 3)
        if host is not None:
            obj.position = obj.position.model_copy(update={"z": base + obj.size.z / 2})
        tops[obj.id] = (base if host is not None else max(bottom, 0.0)) + obj.size.z
    if shrunk:
        scene.record(STAGE, f"scaled {len(shrunk)} objects down to fit under the {scene.room.height:g} m ceiling",
                     step="room", scaled=shrunk)


def _first_host(obj, below, first: dict[str, tuple[float, float]]):
    """What ``obj``'s first pose stands on among the objects ``below`` it: one whose top it
    touches (within 2 cm) and whose footprint its centre is over; None on the floor."""
    bottom = first[obj.id][0]
    return next((h for h in below if bottom > 0.02 and abs(first[h.id][1] - bottom) < 0.02
                 and abs(obj.position.x - h.position.x) <= h.size.x / 2 + 0.01
                 and abs(obj.position.y - h.position.y) <= h.size.y / 2 + 0.01), None)


def _object_images(
    scene: Scene,
    folder: SceneFolder,
    images: ImageGenerator,
    reference: bytes | None,
    progress: Callable[[str], None] | None,
) -> None:
    wanted = [o for o in scene.objects if not (o.image and folder.image_of(o).is_file())]
    drawn = images.object_images(wanted, scene.style, reference, progress) if wanted else {}
    for obj in wanted:
        if obj.id in drawn:
            path = write_atomic(folder.object_image(obj.id), drawn[obj.id])
            obj.image = folder.relative(path)
    if drawn:
        scene.record(STAGE, f"drew {len(drawn)} object images", step="object_images", backend=images.name)


def _remove_redundant(scene: Scene, folder: SceneFolder, vlm: VisionLanguageModel) -> None:
    if any(e.stage == STAGE and e.data.get("step") == REDUNDANCY_STEP for e in scene.provenance):
        return
    pictures = {o.id: folder.read_image(folder.image_of(o), f"objects[{o.id}].image") for o in scene.objects if o.image}
    answer = vlm.find_redundant(scene.objects, pictures)
    scene.provenance += answer.repairs
    redundant = answer.value
    unknown = sorted(set(redundant) - {o.id for o in scene.objects})
    if unknown:
        log.warning("quality control named unknown objects %s; ignoring them", ", ".join(unknown))
    keep = [o for o in scene.objects if o.id not in redundant]
    if not keep:
        log.warning("quality control would remove every object; keeping them all")
        redundant, keep = {}, scene.objects
    removed = {o.id: redundant[o.id] for o in scene.objects if o.id in redundant}
    scene.removed += [
        RemovedObject(id=o.id, name=o.name, reason=removed[o.id]) for o in scene.objects if o.id in removed
    ]
    scene.objects = keep
    scene.record(
        STAGE,
        f"quality control removed {len(removed)} redundant objects",
        step=REDUNDANCY_STEP,
        backend=vlm.name,
        removed=removed,
    )


def _ground(scene: Scene, folder: SceneFolder, images: ImageGenerator, reference: bytes | None) -> None:
    if not folder.ground_image.is_file():
        data = images.ground_texture(scene.text, scene.style, scene.ground.kind, reference)
        write_atomic(folder.ground_image, data)
        message = f"made the {scene.ground.kind} ground texture"
        scene.record(STAGE, message, step="ground", backend=images.name)
    scene.ground.texture = folder.relative(folder.ground_image)


def analyze(
    scene: Scene,
    folder: SceneFolder,
    vlm: VisionLanguageModel,
    images: ImageGenerator,
    progress: Callable[[str], None] | None = None,
    *,
    checkpoint: Callable[[], None] = lambda: None,
    room: str = "auto",
) -> Scene:
    """Fill ``scene`` with its objects, their room (``room`` is the ``--room`` choice, see
    docs/rooms.md), their images and the ground texture, offering a ``checkpoint`` after each
    step (the caller saves; see :class:`~scenewright.folder.DocumentSaver`)."""
    _note(progress, "reference image")
    reference = _reference(scene, folder, images)
    if not scene.objects:
        _note(progress, "reading the objects from the text")
        _objects(scene, vlm, reference, room)
        checkpoint()
    _note(progress, f"object images for {len(scene.objects)} objects")
    _object_images(scene, folder, images, reference, progress)
    checkpoint()
    _note(progress, "quality control")
    _remove_redundant(scene, folder, vlm)
    checkpoint()
    _note(progress, "ground texture")
    _ground(scene, folder, images, reference)
    return scene
