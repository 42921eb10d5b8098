"""Apply one edit (paper §3.4): move, add, delete, replace — and nothing else changes.

The planner (a vision-language model, or the offline parser) names one focus object and its
new constraints. Layout edits re-solve only the focus with every other object fixed, as the
paper's solver does; objects resting ``on`` the focus ride along by the same rigid motion.
Asset edits regenerate the focus's mesh (through an object image where the image backend
draws one) and keep its place unless the new size no longer fits.

Everything is computed on a copy of the document; new asset files get content-addressed
names, so until the final commit (:func:`scenewright.editing.history.commit`) no file the
scene uses is touched. A failed edit leaves the folder exactly as it was.
"""

from __future__ import annotations

import hashlib
import logging
import math
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from pydantic import ValidationError

from scenewright.assets.load import AssetMesh, AssetMeshes, asset_mesh
from scenewright.core.protocols import Backends
from scenewright.cache import RequestCache
from scenewright.editing.history import commit
from scenewright.editing.parser import category_in, fresh_id
from scenewright.core.plan import EditPlan
from scenewright.errors import InfeasibleLayout, InputError
from scenewright.folder import SceneFolder
from scenewright.geometry import world_box, yaw_towards
from scenewright.layout import break_cycles, check, colliding_pairs, feedback_text, solve
from scenewright.layout.constraints import room_problem
from scenewright.layout.relations import check_room
from scenewright.layout.room import resized, wall_facing
from scenewright.scene import (
    ROOM_RELATIONS,
    Constraint,
    Opening,
    RemovedObject,
    Room,
    Scene,
    SceneObject,
    Vec3,
    describe_validation_error,
)
from scenewright.settings import Settings

log = logging.getLogger(__name__)

STAGE = "edit"


@dataclass
class _Edit:
    """What an edit produced, before anything is written."""

    scene: Scene
    plan: EditPlan
    changes: list[str] = field(default_factory=list)
    #: relative path → bytes of new files (assets, object images), named by their content.
    files: dict[str, bytes] = field(default_factory=dict)
    seconds_solving: float = 0.0
    #: The stored assets, parsed once (by the caller's store, which may serve many edits).
    assets: AssetMeshes = field(default_factory=AssetMeshes)


def apply_edit(
    scene: Scene,
    folder: SceneFolder,
    instruction: str,
    *,
    backends: Backends,
    settings: Settings,
    meshes: AssetMeshes | None = None,
) -> Scene:
    """Carry out ``instruction`` on the scene in ``folder``; save it, its history and ``scene.glb``.

    ``meshes`` holds the assets parsed by earlier edits of the same caller (a studio session);
    without it each asset is parsed once for this edit."""
    if not folder.is_scene():
        folder.load()  # raises the "not a scene folder" error, naming the folder
    if not instruction.strip():
        raise InputError(
            "the instruction is empty; say what to change, e.g. 'move the lamp next to the sofa'"
        )
    answer = backends.vlm.plan_edit(scene, instruction)
    plan = answer.value
    meshes = meshes if meshes is not None else AssetMeshes()
    try:
        edit = run_plan(scene, folder, plan, backends=backends, settings=settings, meshes=meshes)
    except ValidationError as exc:  # a pose or size out of bounds: the answer asked for the impossible
        raise InputError(
            f"the edit {plan.operation} {plan.focus} would give an invalid scene, so nothing was written: "
            f"{describe_validation_error(exc)}"
        ) from None
    edit.scene.provenance += answer.repairs  # what the model's answer needed repaired
    edit.scene.record(STAGE, f"{plan.operation} {plan.focus}: {instruction.strip()}",
                      backend=backends.vlm.name, changes=edit.changes)
    commit(folder, edit.scene, edit.files, instruction=instruction.strip(), operation=plan.operation,
           focus=plan.focus, changes=edit.changes, meshes=meshes)
    return edit.scene


def run_plan(
    scene: Scene,
    folder: SceneFolder,
    plan: EditPlan,
    *,
    backends: Backends,
    settings: Settings,
    meshes: AssetMeshes | None = None,
) -> _Edit:
    """The edited document (a copy) and its new files; writes nothing. ``meshes`` holds the
    assets the caller has parsed already."""
    plan = validate_plan(scene, plan)
    edit = _Edit(scene=scene.model_copy(deep=True), plan=plan, assets=meshes if meshes is not None else AssetMeshes())
    if plan.operation == "delete":
        _delete(edit)
    elif plan.operation == "move":
        _move(edit, folder, settings)
    elif plan.operation == "replace":
        _replace(edit, folder, backends, settings)
    elif plan.operation == "room":
        _room(edit, folder, settings)
    else:
        _add(edit, folder, backends, settings)
    return edit


def validate_plan(scene: Scene, plan: EditPlan) -> EditPlan:
    """Check a planner's answer like any model answer: one focus, the only source, never a target."""
    ids = {o.id for o in scene.objects}
    known = ", ".join(f"{o.id} ({o.name})" for o in scene.objects) or "none"
    if plan.operation == "room":
        if scene.room is None:
            raise InputError("this scene has no room to change (it stands on open ground)")
        if plan.room is None or (plan.room.size is None and plan.room.height is None and plan.room.opening is None):
            raise InputError("a 'room' edit must say what changes: its size, its height, or a door or window to add")
        return plan
    if plan.operation == "add":
        if plan.new_object is None:
            raise InputError(f"an 'add' edit needs the new object's name; got none for {plan.focus!r}")
        if plan.focus in ids:  # a model reusing an id: give the new object a fresh one
            fresh = fresh_id(scene, plan.new_object.category or plan.focus.rsplit("_", 1)[0])
            plan = plan.model_copy(update={
                "focus": fresh,
                "constraints": [c.model_copy(update={"source": fresh}) if c.source == plan.focus else c
                                for c in plan.constraints],
            })
    elif plan.focus not in ids:
        raise InputError(f"the edit names object {plan.focus!r}, which the scene does not have; objects: {known}")
    if plan.operation == "replace" and plan.new_object is None:
        raise InputError(f"a 'replace' edit of {plan.focus} needs the new object's description")
    for c in plan.constraints:
        if c.source != plan.focus:
            raise InputError(f"constraint '{c}' has source {c.source!r}; an edit may only place its focus {plan.focus!r}")
        if c.target == plan.focus:
            raise InputError(f"constraint '{c}' uses the focus {plan.focus!r} as its target; it must be the source only")
        wrong = room_problem(c, scene.room, ids)
        if wrong is not None:
            raise InputError(wrong)
        if c.target not in ids and c.relation not in ROOM_RELATIONS:
            raise InputError(f"constraint '{c}' names {c.target!r}, which the scene does not have; objects: {known}")
    if plan.yaw is not None and not math.isfinite(plan.yaw):
        raise InputError(f"the edit turns {plan.focus} to yaw {plan.yaw}; a yaw must be a finite number of degrees")
    if plan.operation == "move" and not plan.constraints and plan.yaw is None and plan.offset is None:
        raise InputError(f"the edit moves {plan.focus} but says neither where to nor which way to turn it")
    if plan.offset is not None:
        if plan.operation != "move":
            raise InputError(f"an offset shifts an object from where it stands; a {plan.operation!r} edit takes none")
        placing = [str(c) for c in plan.constraints if c.relation != "face to"]
        if placing:
            raise InputError(
                f"the edit both shifts {plan.focus} by an offset and places it by {', '.join(placing)}; "
                "say one place: relative to another object, or a shift from where it stands"
            )
    if plan.operation == "delete" and plan.constraints:
        raise InputError(f"a 'delete' edit takes no constraints; got {', '.join(map(str, plan.constraints))}")
    return plan


# --- shared pieces ---------------------------------------------------------------------------


def riders(scene: Scene, object_id: str) -> list[str]:
    """Ids resting ``on`` the object, and on those, and so on (the things that move with it)."""
    out: list[str] = []
    frontier = [object_id]
    while frontier:
        current = frontier.pop()
        for c in scene.constraints:
            if c.relation == "on" and c.target == current and c.source not in out and c.source != object_id:
                out.append(c.source)
                frontier.append(c.source)
    return out


def _carry(scene: Scene, ids: list[str], before: SceneObject, after: SceneObject) -> None:
    """Move ``ids`` by the rigid motion that took ``before`` to ``after`` (turn about +Z, then shift)."""
    turn = after.yaw - before.yaw
    a = np.radians(turn)
    rot = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
    old_xy = np.array([before.position.x, before.position.y])
    new_xy = np.array([after.position.x, after.position.y])
    dz = (after.position.z + after.size.z / 2) - (before.position.z + before.size.z / 2)  # its top's rise
    for oid in ids:
        obj = scene.get(oid)
        xy = rot @ (np.array([obj.position.x, obj.position.y]) - old_xy) + new_xy
        obj.position = Vec3(x=float(xy[0]), y=float(xy[1]), z=obj.position.z + dz)
        obj.rotation = Vec3(x=obj.rotation.x, y=obj.rotation.y, z=(obj.yaw + turn + 180.0) % 360.0 - 180.0)


def _meshes(edit: _Edit, folder: SceneFolder, staged: dict[str, AssetMesh]) -> dict[str, AssetMesh]:
    """The stored meshes of every object, with the ones built by this edit in their place."""
    return {**edit.assets.of(edit.scene, folder, skip=set(staged)), **staged}


def _place(
    edit: _Edit,
    ids: list[str],
    constraints: list[Constraint],
    meshes: dict[str, AssetMesh],
    settings: Settings,
    *,
    leave_out: list[str] = (),
) -> None:
    """Solve ``ids`` under ``constraints`` with every other object fixed; raise when they do not fit.

    Objects in ``leave_out`` (those riding on the focus) are out of the world while it is solved.
    """
    objects = [o for o in edit.scene.objects if o.id not in leave_out]
    placing = set(ids)
    result = solve(
        objects,
        constraints,
        meshes=meshes,
        bounds=edit.scene.bounds,
        fixed=[o.id for o in objects if o.id not in placing],
        time_limit=settings.time_limit,
        seed=edit.scene.seed,
        room=edit.scene.room,
    )
    edit.seconds_solving += result.report.seconds
    unplaced = [u for u in result.report.unplaced if u.id in placing]
    if unplaced:
        raise InfeasibleLayout(
            f"cannot place {', '.join(u.id for u in unplaced)} as asked; the scene is unchanged.\n"
            + feedback_text(result.report, objects)
        )
    solved = {o.id: o for o in result.objects}
    for oid in ids:
        obj = edit.scene.get(oid)
        obj.position, obj.rotation = solved[oid].position, solved[oid].rotation


def holds(scene: Scene, c: Constraint) -> bool:
    """Whether constraint ``c`` holds in ``scene``: between two objects, or to the room."""
    if c.relation in ROOM_RELATIONS:
        return scene.room is not None and check_room(c.relation, scene.get(c.source), scene.room, c.target)
    return check(c.relation, scene.get(c.source), scene.get(c.target))


def _anchor(scene: Scene, obj: SceneObject, constraints: list[Constraint]) -> None:
    """Start ``obj``'s search at its first target, since the solver tries candidates nearest the
    start first: "next to the sofa" then ends up beside the sofa, not just anywhere to its side.
    ``far`` keeps the current start, to stay as close to where the object was as it allows."""
    target = next((c.target for c in constraints if c.relation not in ("far", "face to", *ROOM_RELATIONS)), None)
    if target is not None:
        p = scene.get(target).position
        obj.position = Vec3(x=p.x, y=p.y, z=obj.position.z)


def _collisions(scene: Scene, ids: list[str], meshes: dict[str, AssetMesh]) -> list[tuple[str, str]]:
    moved = set(ids)
    return [p for p in colliding_pairs(scene.objects, meshes, scene.constraints) if moved & set(p)]


def _prune(edit: _Edit, moved: list[str]) -> None:
    """Drop constraints on moved objects that no longer hold (the objects they relate to stayed put)."""
    scene, kept = edit.scene, []
    moved_set = set(moved)
    for c in scene.constraints:
        if (c.source in moved_set or c.target in moved_set) and not holds(scene, c):
            edit.changes.append(f"dropped '{c}': it no longer holds after the edit")
            continue
        kept.append(c)
    scene.constraints = kept


def _stage_asset(edit: _Edit, obj: SceneObject, folder: SceneFolder, backends: Backends, settings: Settings) -> AssetMesh:
    """Build ``obj``'s asset in a scratch folder and stage it under a content-addressed name.

    Sets ``obj.asset``, ``obj.image`` and the size the mesh came out at; returns the mesh.
    """
    from scenewright.assets.stage import generate_assets  # a move or delete needs no new mesh

    scene = edit.scene
    reference = folder.reference()
    with tempfile.TemporaryDirectory(prefix="scenewright-edit-") as tmp:
        scratch = SceneFolder(Path(tmp))
        single = Scene(text=scene.text, style=scene.style, seed=scene.seed,
                       objects=[obj.model_copy(update={"asset": None, "image": None})])
        image = backends.images.object_images(single.objects, scene.style, reference).get(obj.id)
        if image is not None:
            path = scratch.object_image(obj.id)
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(image)
            single.objects[0].image = scratch.relative(path)
        generate_assets(
            single, scratch, backends.meshes, RequestCache(settings.cache_dir), max_faces=settings.max_faces
        )
        built = single.objects[0]
        glb = scratch.resolve(built.asset).read_bytes()
    digest = hashlib.sha256(glb).hexdigest()[:12]
    asset = folder.relative(folder.assets / f"{obj.id}-{digest}.glb")
    edit.files[asset] = glb
    obj.asset = asset
    obj.image = None
    if image is not None:
        picture = folder.relative(folder.object_images / f"{obj.id}-{hashlib.sha256(image).hexdigest()[:12]}.png")
        edit.files[picture] = image
        obj.image = picture
    bottom = obj.position.z - obj.size.z / 2
    obj.size = built.size
    obj.position = Vec3(x=obj.position.x, y=obj.position.y, z=bottom + built.size.z / 2)
    return asset_mesh(glb)


# --- the four operations ---------------------------------------------------------------------


def _delete(edit: _Edit) -> None:
    scene, focus = edit.scene, edit.scene.get(edit.plan.focus)
    gone = [focus.id]
    for oid in riders(scene, focus.id):
        supports = {c.target for c in scene.constraints if c.source == oid and c.relation == "on"}
        if supports <= set(gone):  # it rested only on removed things
            gone.append(oid)
    for oid in gone:
        obj = scene.get(oid)
        reason = "deleted by an edit" if oid == focus.id else f"rested on {focus.id}, which was deleted"
        scene.removed.append(RemovedObject(id=oid, name=obj.name, reason=reason))
        edit.changes.append(f"removed {oid} ({obj.name})" + ("" if oid == focus.id else f": it rested on {focus.id}"))
    dropped = [c for c in scene.constraints if c.source in gone or c.target in gone]
    edit.changes += [f"dropped '{c}'" for c in dropped]
    scene.objects = [o for o in scene.objects if o.id not in gone]
    scene.constraints = [c for c in scene.constraints if c not in dropped]
    scene.initial = {oid: pose for oid, pose in scene.initial.items() if oid not in gone}


def _renew_constraints(edit: _Edit, focus: str) -> tuple[list[Constraint], list[Constraint], list[Constraint]]:
    """Put the plan's constraints in place of the focus's old ones of the same kind.

    A new place replaces where it was asked to be, a new facing (or a turn) what it faced;
    the rest of what it was asked still holds. Returns the plan's facing and placing
    constraints and all the focus's constraints now.
    """
    scene, plan = edit.scene, edit.plan
    turning = [c for c in plan.constraints if c.relation == "face to"]
    placing = [c for c in plan.constraints if c.relation != "face to"]
    kept = []
    for c in scene.constraints:
        if c.source == focus:
            facing = c.relation == "face to"
            if (facing and (turning or plan.yaw is not None)) or (not facing and placing):
                edit.changes.append(f"replaced '{c}'")
                continue
        kept.append(c)
    scene.constraints, cyclic = break_cycles(kept + list(plan.constraints), first={c.key() for c in plan.constraints})
    edit.changes += [f"added '{c}'" for c in plan.constraints]
    edit.changes += [f"dropped '{c}': with the edit it would make a cycle ({' -> '.join(path)})" for c, path in cyclic]
    return turning, placing, [c for c in scene.constraints if c.source == focus]


def _move(edit: _Edit, folder: SceneFolder, settings: Settings) -> None:
    scene, plan = edit.scene, edit.plan
    focus = scene.get(plan.focus)
    before = focus.model_copy(deep=True)
    carried = riders(scene, focus.id)
    poses = {oid: (scene.get(oid).position, scene.get(oid).rotation) for oid in carried}
    if set(carried) & {c.target for c in plan.constraints}:
        raise InputError(
            f"{', '.join(sorted(set(carried) & {c.target for c in plan.constraints}))} rests on {focus.id}, "
            f"so {focus.id} cannot be placed against it; move that first"
        )
    turning, placing, mine = _renew_constraints(edit, focus.id)
    meshes = _meshes(edit, folder, {})
    if plan.yaw is not None:
        focus.rotation = Vec3(x=focus.rotation.x, y=focus.rotation.y, z=plan.yaw)
    if not placing and turning:  # turn in place towards the target when nothing is in the way
        target = scene.get(turning[-1].target)
        focus.rotation = Vec3(x=focus.rotation.x, y=focus.rotation.y,
                              z=yaw_towards(focus.position.tuple(), target.position.tuple()))
    if plan.offset is not None:
        _shift(edit, focus, before, carried, meshes)
        return
    in_place = not placing and all(holds(scene, c) for c in mine)
    if in_place:
        _carry(scene, carried, before, focus)
        hits = _collisions(scene, [focus.id, *carried], meshes)
        if hits:
            if plan.yaw is not None and not turning:
                pairs = ", ".join(" and ".join(p) for p in hits)
                raise InfeasibleLayout(f"turning {focus.id} in place makes {pairs} collide; move it first")
            in_place = False
            for oid in carried:  # back to where they were, to follow the solved focus instead
                scene.get(oid).position, scene.get(oid).rotation = poses[oid]
    if not in_place:
        _anchor(scene, focus, placing)
        _place(edit, [focus.id], mine, meshes, settings, leave_out=carried)
        _carry(scene, carried, before, focus)
        hits = _collisions(scene, carried, meshes)
        if hits:
            raise InfeasibleLayout(
                f"{focus.id} fits at its new place but what rests on it does not: "
                + ", ".join(" and ".join(p) for p in hits) + " would collide; the scene is unchanged"
            )
    _moved(edit, focus, carried)


def _moved(edit: _Edit, focus: SceneObject, carried: list[str]) -> None:
    p = focus.position
    edit.changes.append(f"{focus.id} now at ({p.x:.2f}, {p.y:.2f}, {p.z:.2f}), yaw {focus.yaw:.0f}°"
                        + (f", carrying {', '.join(carried)}" if carried else ""))
    _prune(edit, [focus.id, *carried])


def _shift(edit: _Edit, focus: SceneObject, before: SceneObject, carried: list[str], meshes: dict[str, AssetMesh]) -> None:
    """Shift the focus by the plan's offset, exactly: the instruction gave the step, so a step
    that collides or leaves the scene's bounds is refused, not bent into another place. Its
    constraints that no longer hold are dropped."""
    scene, d = edit.scene, edit.plan.offset
    p = focus.position
    focus.position = Vec3(x=p.x + d.x, y=p.y + d.y, z=p.z + d.z)
    _carry(scene, carried, before, focus)
    step = f"shifting {focus.id} by ({d.x:+.2f}, {d.y:+.2f}, {d.z:+.2f}) m"
    if scene.bounds is not None:
        low, high = world_box(focus)
        half = np.array(scene.bounds) / 2.0
        if np.any(low[:2] < -half - 1e-6) or np.any(high[:2] > half + 1e-6):
            raise InfeasibleLayout(
                f"{step} takes it outside the scene's {scene.bounds[0]:g} × {scene.bounds[1]:g} m bounds; "
                "try a smaller step or another direction; the scene is unchanged"
            )
    hits = _collisions(scene, [focus.id, *carried], meshes)
    if hits:
        raise InfeasibleLayout(
            f"{step} makes {', '.join(' and '.join(pair) for pair in hits)} collide; "
            "try a smaller step or another direction; the scene is unchanged"
        )
    _moved(edit, focus, carried)


def _replace(edit: _Edit, folder: SceneFolder, backends: Backends, settings: Settings) -> None:
    scene, plan = edit.scene, edit.plan
    focus = scene.get(plan.focus)
    new = plan.new_object
    assert new is not None
    before = focus.model_copy(deep=True)
    category = category_in(new.category, new.name)
    changed_kind = category is not None and category.name != focus.category
    focus.name = new.name
    focus.category = category.name if category else (new.category or focus.category)
    focus.visual_description = new.visual_description or new.name
    if new.size is not None:
        focus.size = new.size
    elif changed_kind and category is not None:
        focus.size = Vec3.of(category.size)
    mesh = _stage_asset(edit, focus, folder, backends, settings)
    rise = (focus.size.z - before.size.z) / 2  # a new height keeps the bottom where it stood
    focus.position = Vec3(x=focus.position.x, y=focus.position.y, z=focus.position.z + rise)
    if focus.id in scene.initial:  # and so does the pose the ablation starts it from
        start = scene.initial[focus.id].position
        scene.initial[focus.id].position = Vec3(x=start.x, y=start.y, z=start.z + rise)
    z = focus.size
    edit.changes.append(f"{focus.id} is now {focus.name!r} ({focus.visual_description}), "
                        f"{z.x:.2f} × {z.y:.2f} × {z.z:.2f} m")
    meshes = _meshes(edit, folder, {focus.id: mesh})
    carried = riders(scene, focus.id)
    _, placing, mine = _renew_constraints(edit, focus.id)
    if plan.yaw is not None:
        focus.rotation = Vec3(x=focus.rotation.x, y=focus.rotation.y, z=plan.yaw)
    _carry(scene, carried, before, focus)
    fits = not _collisions(scene, [focus.id], meshes) and all(holds(scene, c) for c in mine)
    if not fits:
        edit.changes.append(f"re-placed {focus.id}: " + ("as asked" if placing else "it no longer fitted where it was"))
        placed_from = focus.model_copy(deep=True)
        _anchor(scene, focus, placing)
        _place(edit, [focus.id], mine, meshes, settings, leave_out=carried)
        _carry(scene, carried, placed_from, focus)
    unsettled = [oid for oid in carried if not all(
        holds(scene, c) for c in scene.constraints if c.source == oid
    ) or _collisions(scene, [oid], meshes)]
    if unsettled:
        _place(edit, unsettled, [c for c in scene.constraints if c.source in unsettled], meshes, settings)
        edit.changes.append(f"re-placed {', '.join(unsettled)} on the new {focus.name}")
    _prune(edit, [focus.id, *carried])


def _add(edit: _Edit, folder: SceneFolder, backends: Backends, settings: Settings) -> None:
    scene, plan = edit.scene, edit.plan
    new = plan.new_object
    assert new is not None
    category = category_in(new.category, new.name)
    if new.size is not None:
        size = new.size
    elif category is not None:
        size = Vec3.of(category.size)
    else:
        raise InputError(
            f"how big is the new {new.name!r}? it is not in the catalogue; give its size in the instruction "
            "(e.g. '1 metre wide') or a catalogue object"
        )
    obj = SceneObject(
        id=plan.focus,
        name=new.name,
        category=category.name if category else new.category,
        size=size,
        visual_description=new.visual_description or new.name,
        position=Vec3(z=size.z / 2),
        rotation=Vec3(z=plan.yaw or 0.0),
    )
    if scene.room is not None:  # a mirror hangs on a wall, a wardrobe stands against one
        from scenewright.analysis.composition.walls import room_constraints

        plan = plan.model_copy(update={"constraints": room_constraints([obj], plan.constraints)})
    _anchor(scene, obj, list(plan.constraints))
    scene.objects.append(obj)
    mesh = _stage_asset(edit, obj, folder, backends, settings)
    scene.constraints = scene.constraints + list(plan.constraints)
    meshes = _meshes(edit, folder, {obj.id: mesh})
    scene.remember_initial_poses([obj.id])  # where it starts, at its built size: its layout without the solver
    _place(edit, [obj.id], list(plan.constraints), meshes, settings)
    p = obj.position
    edit.changes.append(f"added {obj.id} ({obj.name}) at ({p.x:.2f}, {p.y:.2f}, {p.z:.2f})")
    edit.changes += [f"added '{c}'" for c in plan.constraints]


def _room(edit: _Edit, folder: SceneFolder, settings: Settings) -> None:
    """Resize the room or add a door or window to it; objects no longer where the room allows
    (outside it, in an opening's clear strip, a room relation broken) are solved again inside,
    with everything else fixed. A resize re-solves every object, since the walls moved."""
    scene, change = edit.scene, edit.plan.room
    assert scene.room is not None and change is not None
    old = scene.room
    if change.size is not None or change.height is not None:
        (x0, y0), (x1, y1) = np.min(old.floor, axis=0), np.max(old.floor, axis=0)
        width, depth = change.size if change.size is not None else (x1 - x0, y1 - y0)
        height = change.height or old.height
        try:
            room = resized(old, width, depth, height)
        except ValidationError as exc:
            raise InputError(f"a {width:g} x {depth:g} m room, {height:g} m high: {describe_validation_error(exc)}") from None
        scene.room = room
        moving = [o.id for o in scene.objects]
        edit.changes.append(f"the room is now {width:g} x {depth:g} m, {height:g} m high")
    else:
        scene.room = _with_opening(old, change.opening, change.side)
        added = scene.room.openings[-1]
        edit.changes.append(f"added a {added.kind} on wall_{added.wall}, {added.width:g} m wide, "
                            f"centred {added.offset:.2f} m along it")
        moving = _misplaced(scene)
    if moving:
        meshes = _meshes(edit, folder, {})
        _place(edit, moving, [c for c in scene.constraints if c.source in moving], meshes, settings)
        edit.changes.append(f"re-placed {', '.join(moving)} in the room")
    _prune(edit, moving)


def _misplaced(scene: Scene) -> list[str]:
    """Objects the room does not allow where they stand: outside it, in a door's or window's
    clear strip, or with a room relation that no longer holds."""
    from scenewright.layout.relations import Boxes
    from scenewright.layout.room import RoomShape

    assert scene.room is not None
    shape = RoomShape(scene.room)
    out = []
    for o in scene.objects:
        box = Boxes.of(o)[None]
        broken = any(not holds(scene, c) for c in scene.constraints if c.source == o.id and c.relation in ROOM_RELATIONS)
        if shape.misfit(box)[0] > 0 or broken:
            out.append(o.id)
    return out


def _with_opening(room: Room, kind: str, side: str | None) -> Room:
    """``room`` with a door or window added on the wall on ``side`` (else the wall with the most
    free length), at the middle of the widest free stretch of it; InputError when none fits."""
    width = 0.9 if kind == "door" else 1.2
    walls = [wall_facing(room, side)] if side else sorted(range(len(room.walls)), key=room.wall_length, reverse=True)
    best = None
    for wall in walls:
        length = room.wall_length(wall)
        taken = sorted((o.offset - o.width / 2 - 0.15, o.offset + o.width / 2 + 0.15) for o in room.openings if o.wall == wall)
        start = 0.15
        for lo, hi in [*taken, (length - 0.15, length)]:
            if lo - start >= width and (best is None or lo - start > best[2]):
                best = (wall, (start + lo) / 2, lo - start)
            start = max(start, hi)
        if best is not None and side:
            break
    if best is None:
        where = f"the {side} wall" if side else "any wall"
        raise InputError(f"no room for a {width:g} m wide {kind} on {where}: its openings leave no free stretch that wide")
    wall, offset, _ = best
    opening = (Opening(kind="door", wall=wall, offset=offset, width=width, height=min(2.1, room.height - 0.2))
               if kind == "door" else
               Opening(kind="window", wall=wall, offset=offset, width=width, height=min(1.2, room.height - 1.2), sill=0.9))
    return Room.model_validate({**room.model_dump(), "openings": [*room.openings, opening]})
