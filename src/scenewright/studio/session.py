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

import trimesh

from scenewright.assets import asset_mesh
from scenewright.assets.load import AssetMeshes
from scenewright.backends import Backends
from scenewright.editing import EditPlan, apply_edit, entries, redo, run_plan, undo
from scenewright.editing.apply import STAGE, riders
from scenewright.editing.history import Entry, commit
from scenewright.errors import InfeasibleLayout, InputError
from scenewright.folder import SceneFolder
from scenewright.layout import check, colliding_pairs, solve
from scenewright.pipeline import writing
from scenewright.scene import Scene, SceneObject, Vec3
from scenewright.settings import Settings
from scenewright.studio.panel import ObjectPanel, object_panel


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
        with self.lock, writing(self.folder, self.settings.lock_timeout):
            yield

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
            carried = riders(scene, object_id)
            mine = [c for c in scene.constraints if object_id in (c.source, c.target)
                    and c.source not in carried and c.target not in carried]
            trial = scene.model_copy(deep=True)
            dropped = trial.get(object_id)
            dropped.position = Vec3(x=x, y=y, z=obj.position.z)
            dropped.rotation = Vec3(x=obj.rotation.x, y=obj.rotation.y, z=yaw)
            world = [o for o in trial.objects if o.id not in carried]
            fits = all(check(c.relation, trial.get(c.source), trial.get(c.target)) for c in mine) and not [
                p for p in colliding_pairs(world, meshes, trial.constraints) if object_id in p]
            snapped = ""
            if not fits:
                result = solve(world, mine, meshes=meshes, bounds=scene.bounds,
                               fixed=[o.id for o in world if o.id != object_id],
                               time_limit=self.settings.time_limit, seed=scene.seed)
                if any(u.id == object_id for u in result.report.unplaced):
                    return DragResult(False, f"no collision-free pose near there keeps {object_id}'s constraints "
                                             f"({', '.join(map(str, mine)) or 'none'}); it stays where it was")
                dropped = next(o for o in result.objects if o.id == object_id)
                snapped = " (snapped to the nearest pose that fits)"
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
