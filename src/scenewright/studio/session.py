"""The editor's state on one scene folder: the document as on disk, and the edits made on it.

Every change goes through the editing engine the CLI uses (:func:`scenewright.editing.apply_edit`,
:func:`~scenewright.editing.undo`, :func:`~scenewright.editing.redo`, and for a drag
:func:`~scenewright.editing.run_plan` + the history's ``commit``), so an edit made in the browser
is one history entry like any other, undoable from either side.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh

from scenewright.assets import asset_mesh
from scenewright.assets.load import AssetMeshes
from scenewright.backends import Backends
from scenewright.editing import EditPlan, apply_edit, entries, redo, run_plan, undo
from scenewright.editing.apply import STAGE, riders
from scenewright.editing.history import Entry, commit
from scenewright.errors import FolderBusy, InfeasibleLayout, InputError
from scenewright.folder import SceneFolder
from scenewright.layout import solve
from scenewright.layout.collision import CollisionWorld, resting_pairs
from scenewright.pipeline import writing
from scenewright.scene import Scene, SceneObject, Vec3
from scenewright.settings import Settings
from scenewright.studio.panel import ConstraintState, ObjectPanel, constraint_state, object_panel


def inside(folder: SceneFolder, relative: str) -> Path:
    """The file ``relative`` names in the folder; refuses a path that leads outside it.

    A scene document is a file anyone may hand over, and the editor reads what it names.
    """
    root = folder.root.resolve()
    path = (root / relative).resolve()
    if not path.is_relative_to(root):
        raise InputError(f"{relative!r} points outside the scene folder {folder.root}; refusing to read it")
    return path


@dataclass(frozen=True)
class DragResult:
    committed: bool
    message: str


@dataclass(frozen=True)
class DragCheck:
    """What a pose of the dragged object runs into: whom it collides with, which of its
    constraints it breaks (and the other objects of those)."""

    colliding: list[str]
    violated: list[ConstraintState]
    #: The other object of each violated constraint.
    partners: list[str]

    @property
    def fits(self) -> bool:
        return not self.colliding and not self.violated

    def markdown(self) -> str:
        if self.fits:
            return "fits here: no collision, its constraints hold"
        parts = []
        if self.colliding:
            parts.append("**collides with** " + ", ".join(f"`{c}`" for c in self.colliding))
        if self.violated:
            parts.append("\n".join(f"- **violated** {v.text} ({v.miss})" for v in self.violated))
        return "\n\n".join(parts)


class DragProbe:
    """Poses of one object checked against the rest of the scene, which stays put.

    The collision shapes (the mesh BVHs) are built once per drag, so each pose costs a broad
    phase and a few narrow-phase tests: cheap enough to run while the pointer moves. What
    rides on the object moves with it and is left out, as when the move is committed.
    """

    def __init__(self, scene: Scene, object_id: str, meshes: dict[str, trimesh.Trimesh]) -> None:
        self.scene = scene
        self.object_id = object_id
        self.object = scene.get(object_id)
        carried = riders(scene, object_id)
        world = [o for o in scene.objects if o.id not in carried]
        self.others = {o.id: o for o in world if o.id != object_id}
        self.constraints = [c for c in scene.constraints if object_id in (c.source, c.target)
                            and c.source not in carried and c.target not in carried]
        self.world = CollisionWorld(world, meshes, resting_pairs(scene.constraints))
        for i, o in enumerate(world):
            self.world.place(i, np.array(o.position.tuple()), o.yaw)
        self.index = self.world.ids.index(object_id)

    def moved(self, x: float, y: float, yaw: float) -> SceneObject:
        obj = self.object
        return obj.model_copy(update={"position": Vec3(x=x, y=y, z=obj.position.z),
                                      "rotation": Vec3(x=obj.rotation.x, y=obj.rotation.y, z=yaw)})

    def check(self, x: float, y: float, yaw: float) -> DragCheck:
        moved = self.moved(x, y, yaw)
        i, centre = self.index, np.array(moved.position.tuple())
        self.world.place(i, centre, yaw)
        idx = self.world.neighbours(i)
        near = idx[self.world.overlaps(idx, self.world.lo[i : i + 1], self.world.hi[i : i + 1])[0]]
        colliding = sorted(self.world.ids[j] for j in self.world.colliders(i, centre, yaw, near))
        violated, partners = [], []
        pose = {**self.others, self.object_id: moved}
        for c in self.constraints:
            state = constraint_state(c, pose[c.source], pose[c.target])
            if not state.held:
                violated.append(state)
                partners.append(c.target if c.source == self.object_id else c.source)
        return DragCheck(colliding, violated, sorted(set(partners)))


class Session:
    """One scene folder open in the editor.

    Edits are serialised by ``lock`` (two browser tabs cannot interleave one edit's read and
    write) and by the folder's lock (:func:`scenewright.pipeline.writing`), so the CLI and the
    editor exclude each other too.
    """

    def __init__(self, folder: SceneFolder, *, backends: Backends, settings: Settings) -> None:
        self.folder = folder
        self.backends = backends
        self.settings = settings
        self.lock = threading.RLock()
        #: Set while the previews render (see :meth:`render`).
        self.rendering = threading.Event()
        self._one_render = threading.Lock()
        self._meshes: dict[Path, trimesh.Trimesh] = {}
        #: Assets parsed once for every edit of the session (the editing module keeps none).
        self.assets = AssetMeshes()
        self._stamp: tuple[int, int] | None = None
        self.scene = self.reload()

    # --- reading ---------------------------------------------------------------------------

    def _disk_stamp(self) -> tuple[int, int]:
        stat = self.folder.document.stat()
        return stat.st_mtime_ns, stat.st_size

    def reload(self) -> Scene:
        with self.lock:
            self.folder.load()  # a folder without scene.json: the error says how to make one
            stamp = self._disk_stamp()
            self.scene = self.folder.load()
            self._stamp = stamp
            return self.scene

    def changed_on_disk(self) -> bool:
        """Whether scene.json changed since the editor last read it (the CLI edited it)."""
        try:
            return self._disk_stamp() != self._stamp
        except FileNotFoundError:
            return False

    def asset_bytes(self, obj: SceneObject) -> bytes | None:
        if obj.asset is None:
            return None
        path = inside(self.folder, obj.asset)
        return path.read_bytes() if path.is_file() else None

    def glb(self) -> bytes:
        if not self.folder.glb.is_file():
            raise InputError(f"{self.folder.glb} does not exist; "
                             f"export it with `scenewright generate --resume {self.folder.root}`")
        return self.folder.glb.read_bytes()

    def panel(self, object_id: str) -> ObjectPanel:
        return object_panel(self.scene, object_id)

    def history(self) -> list[Entry]:
        return entries(self.folder)

    # --- changing --------------------------------------------------------------------------

    @contextmanager
    def _writing(self) -> Iterator[None]:
        if self.rendering.is_set():
            raise FolderBusy("the previews are being rendered (the render holds the folder); "
                             "try again when it has finished")
        with self.lock, writing(self.folder, self.settings.lock_timeout):
            yield

    def render(self, *, draft: bool = False) -> list[Path]:
        """Render the previews as ``scenewright render`` does (under the folder's lock); the
        editor's own edits are refused meanwhile rather than left waiting for the lock."""
        from scenewright.render import render

        if not self._one_render.acquire(blocking=False):
            raise FolderBusy("a render is already running")
        self.rendering.set()
        try:
            with writing(self.folder, self.settings.lock_timeout):
                return render(self.folder.load(), self.folder, draft=draft, max_pixels=self.settings.max_render_pixels,
                              max_samples=self.settings.max_render_samples)
        finally:
            self.rendering.clear()
            self._one_render.release()

    def previews(self) -> list[Path]:
        """The preview images in the folder, the chosen view first (none before a render)."""
        from scenewright.render import render_info

        info = render_info(self.folder)
        if not info:
            return []
        paths = {view: inside(self.folder, image) for view, image in info["images"].items()}
        views = sorted(paths, key=lambda view: view != info["best"])  # stable: the best first
        return [paths[v] for v in views if paths[v].is_file()]

    def edit(self, instruction: str) -> Entry:
        """A language edit, exactly as ``scenewright edit`` makes it."""
        with self._writing():
            self.reload()
            apply_edit(self.scene, self.folder, instruction, backends=self.backends, settings=self.settings,
                       meshes=self.assets)
            self.reload()
            return [e for e in entries(self.folder) if e.active][-1]

    def undo(self) -> Entry:
        with self._writing():
            _, entry = undo(self.folder)
            self.reload()
            return entry

    def redo(self) -> Entry:
        with self._writing():
            _, entry = redo(self.folder)
            self.reload()
            return entry

    def _mesh_of(self, obj: SceneObject) -> trimesh.Trimesh | None:
        if obj.asset is None:
            return None
        path = inside(self.folder, obj.asset)
        if path not in self._meshes:  # assets are never rewritten in place: the path is the key
            if not path.is_file():
                return None
            self._meshes[path] = asset_mesh(path.read_bytes())
        return self._meshes[path]

    def meshes(self, scene: Scene) -> dict[str, trimesh.Trimesh]:
        found = {o.id: self._mesh_of(o) for o in scene.objects}
        return {oid: m for oid, m in found.items() if m is not None}

    def drag(self, object_id: str, x: float, y: float, yaw: float) -> DragResult:
        """Commit a gizmo move of ``object_id`` to (x, y) turned to ``yaw`` as one edit.

        Where the object was dropped is kept when it collides with nothing and its constraints
        hold there; otherwise the solver looks for the nearest pose that does (it tries the
        candidates nearest the start first). When none exists nothing is written.
        """
        with self._writing():
            scene = self.reload()
            obj = scene.get(object_id)
            meshes = self.meshes(scene)
            probe = DragProbe(scene, object_id, meshes)
            dropped = probe.moved(x, y, yaw)
            found = probe.check(x, y, yaw)
            snapped = ""
            if not found.fits:
                world = [*probe.others.values(), dropped]
                result = solve(world, probe.constraints, meshes=meshes, bounds=scene.bounds,
                               fixed=list(probe.others), time_limit=self.settings.time_limit, seed=scene.seed)
                if any(u.id == object_id for u in result.report.unplaced):
                    return DragResult(False, f"no collision-free pose near there keeps {object_id}'s constraints "
                                             f"({', '.join(map(str, probe.constraints)) or 'none'}); "
                                             "it stays where it was")
                dropped = next(o for o in result.objects if o.id == object_id)
                why = [f"collided with {', '.join(found.colliding)}"] if found.colliding else []
                why += [f"broke {v.text}" for v in found.violated]
                snapped = f" (snapped to the nearest pose that fits: where it was dropped it {'; '.join(why)})"
            p = dropped.position
            plan = EditPlan(operation="move", focus=object_id,
                            offset=Vec3(x=p.x - obj.position.x, y=p.y - obj.position.y, z=p.z - obj.position.z),
                            yaw=dropped.yaw if abs(dropped.yaw - obj.yaw) > 1e-6 else None)
            instruction = f"drag {object_id} to ({p.x:.2f}, {p.y:.2f}), yaw {dropped.yaw:.0f}°"
            try:
                edit = run_plan(scene, self.folder, plan, backends=self.backends, settings=self.settings,
                                meshes=self.assets)
            except InfeasibleLayout as exc:  # what rides on it does not fit there
                return DragResult(False, f"{exc}; {object_id} stays where it was")
            edit.scene.record(STAGE, f"move {object_id}: {instruction}", backend="studio", changes=edit.changes)
            number = commit(self.folder, edit.scene, edit.files, instruction=instruction, operation="move",
                            focus=object_id, changes=edit.changes, meshes=self.assets)
            self.reload()
            return DragResult(True, f"edit {number}: {instruction}{snapped}")
