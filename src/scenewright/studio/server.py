"""The editor in the browser, drawn with viser (scene frame +Z up, as viser's world).

The page is viser's prebuilt client: no JavaScript is built here. Every button calls the
:class:`~scenewright.studio.session.Session`, and the 3D view is redrawn from the document
after each change and whenever scene.json changes on disk.
"""

from __future__ import annotations

import threading

import numpy as np
import trimesh

from scenewright.errors import MissingExtra, ScenewrightError
from scenewright.export.ground import ground_mesh
from scenewright.geometry import GLTF_TO_SCENE, object_matrix
from scenewright.scene import Scene, SceneObject
from scenewright.studio.panel import object_panel
from scenewright.studio.session import Session, inside


#: How often scene.json's modification time is looked at, seconds.
POLL_SECONDS = 0.5
HIGHLIGHT = (255, 170, 0)


def _viser():
    try:
        import viser
    except ImportError:
        raise MissingExtra("scenewright studio", "studio", "viser") from None
    return viser


def _pose(matrix: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(wxyz, position) of a rigid 4×4 transform."""
    return trimesh.transformations.quaternion_from_matrix(matrix), matrix[:3, 3].copy()


def _yaw_quaternion(yaw_degrees: float) -> np.ndarray:
    half = np.radians(yaw_degrees) / 2
    return np.array([np.cos(half), 0.0, 0.0, np.sin(half)])


def _yaw_of(wxyz) -> float:
    w, x, y, z = wxyz
    return float(np.degrees(np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))))


class Studio:
    """A viser server showing one :class:`Session`; ``select``/``submit``/… are what the GUI calls."""

    def __init__(self, session: Session, *, host: str = "127.0.0.1", port: int = 8080) -> None:
        viser = _viser()
        self.session = session
        self.server = viser.ViserServer(host=host, port=port, verbose=False)
        self.server.scene.set_up_direction("+z")
        self.selected: str | None = None
        self._nodes: dict[str, object] = {}
        self._gizmo = None
        self._outline = None
        self._stop = threading.Event()
        #: GUI callbacks and the disk watcher redraw from their own threads.
        self._drawing = threading.RLock()
        gui = self.server.gui
        gui.configure_theme(control_width="large", show_logo=False)
        gui.main_panel.dock_right()
        self._aim_camera()
        self.status = gui.add_markdown("Click an object to select it.")
        with gui.add_folder("Object"):
            self.panel = gui.add_markdown("_nothing selected_")
        with gui.add_folder("Edit"):
            self.instruction = gui.add_text("Instruction", initial_value="", hint="move the lamp next to the sofa")
            apply = gui.add_button("Apply edit")
            undo = gui.add_button("Undo")
            redo = gui.add_button("Redo")
            download = gui.add_button("Download GLB")
        with gui.add_folder("History"):
            self.history = gui.add_markdown("")
        apply.on_click(lambda _: self.submit(self.instruction.value))
        undo.on_click(lambda _: self._run(self.session.undo, "undid"))
        redo.on_click(lambda _: self._run(self.session.redo, "redid"))
        download.on_click(self._download)
        self.draw()
        self._watcher = threading.Thread(target=self._watch, name="studio-watch", daemon=True)
        self._watcher.start()

    @property
    def url(self) -> str:
        return f"http://{self.server.get_host()}:{self.server.get_port()}"

    def stop(self) -> None:
        self._stop.set()
        self.server.stop()

    def _aim_camera(self) -> None:
        """Start the view above the front of the scene, looking at its middle."""
        scene = self.session.scene
        points = np.array([o.position.tuple() for o in scene.objects] or [(0.0, 0.0, 0.0)])
        centre = (points.min(axis=0) + points.max(axis=0)) / 2
        reach = max(float(np.ptp(points[:, :2], axis=0).max()), 2.0)
        camera = self.server.initial_camera
        camera.look_at = (float(centre[0]), float(centre[1]), 0.0)
        camera.position = (float(centre[0]), float(centre[1]) - 1.2 * reach, 0.9 * reach)

    # --- drawing ---------------------------------------------------------------------------

    def draw(self) -> None:
        """Redraw the scene from the session's document, keeping the selection if it still exists."""
        with self._drawing:
            self._draw()

    def _draw(self) -> None:
        scene = self.session.scene
        for handle in self._nodes.values():
            handle.remove()
        self._nodes.clear()
        self._draw_ground(scene)
        for obj in scene.objects:
            self._nodes[obj.id] = self._add_object(obj)
        self.history.content = self._history_markdown()
        if self.selected is not None and self.selected not in {o.id for o in scene.objects}:
            self.selected = None
        self._select(self.selected)

    def _draw_ground(self, scene: Scene) -> None:
        """The ground, or the room when the scene has one: its floor, walls, doors and
        windows, without the ceiling, so the view from above sees in."""
        if scene.room is not None:
            from scenewright.procedural.room import room_meshes

            for name, mesh in room_meshes(scene.room, scene.style):
                if name != "room/ceiling":
                    self._nodes[f"__{name}"] = self.server.scene.add_mesh_trimesh(f"/{name}", mesh)
            return
        texture = None
        if scene.ground.texture:
            path = inside(self.session.folder, scene.ground.texture)
            texture = path if path.is_file() else None
        ground = ground_mesh(scene.objects, scene.bounds, texture)
        ground.apply_transform(GLTF_TO_SCENE)
        self._nodes["__ground"] = self.server.scene.add_mesh_trimesh("/ground", ground)

    def _add_object(self, obj: SceneObject):
        data = self.session.asset_bytes(obj)
        if data is None:  # no asset yet: its box stands in, as for the solver
            handle = self.server.scene.add_box(f"/objects/{obj.id}", color=(160, 160, 170), dimensions=obj.size.tuple(),
                                               wxyz=_yaw_quaternion(obj.yaw), position=obj.position.tuple())
        else:
            wxyz, position = _pose(object_matrix(obj) @ GLTF_TO_SCENE)
            handle = self.server.scene.add_glb(f"/objects/{obj.id}", data, wxyz=wxyz, position=position)
        handle.on_click(lambda _event, oid=obj.id: self.select(oid))
        return handle

    def _history_markdown(self) -> str:
        found = self.session.history()
        if not found:
            return "_no edits yet_"
        return "\n".join(f"{e.number}. {'' if e.active else '~~'}{e.instruction}{'' if e.active else '~~ (undone)'}"
                         for e in found)

    # --- what the GUI calls ----------------------------------------------------------------

    def select(self, object_id: str | None) -> None:
        """Highlight ``object_id``, show its panel and put the gizmo on it (None: clear)."""
        with self._drawing:
            self._select(object_id)

    def _select(self, object_id: str | None) -> None:
        for handle in (self._outline, self._gizmo):
            if handle is not None:
                handle.remove()
        self._outline = self._gizmo = None
        self.selected = object_id
        if object_id is None:
            self.panel.content = "_nothing selected_"
            return
        obj = self.session.scene.get(object_id)
        self.panel.content = self.session.panel(object_id).markdown()
        rotation = _yaw_quaternion(obj.yaw)
        self._gizmo = self.server.scene.add_transform_controls(
            "/gizmo", scale=max(obj.size.x, obj.size.y, 0.5) + 0.3, active_axes=(True, True, False),
            wxyz=rotation, position=obj.position.tuple(),
        )
        self._outline = self.server.scene.add_box(
            "/gizmo/outline", color=HIGHLIGHT, dimensions=obj.size.tuple(), wireframe=True,
        )
        self._gizmo.on_update(self._dragged)

    def _dragged(self, event) -> None:
        """Move the object with the gizmo; on release commit it as one edit."""
        if self.selected is None:
            return
        obj = self.session.scene.get(self.selected)
        x, y, _ = event.target.position
        yaw = _yaw_of(event.target.wxyz)
        moved = obj.model_copy(update={"position": obj.position.model_copy(update={"x": float(x), "y": float(y)}),
                                       "rotation": obj.rotation.model_copy(update={"z": yaw})})
        node = self._nodes.get(obj.id)
        if node is not None:
            node.wxyz, node.position = (_pose(object_matrix(moved) @ GLTF_TO_SCENE) if obj.asset is not None
                                        else (_yaw_quaternion(yaw), moved.position.tuple()))
        if event.phase == "end":
            self.drag(obj.id, float(x), float(y), yaw)
        else:  # which of its constraints the pose under the pointer breaks (boxes only: cheap enough per update)
            trial = self.session.scene.model_copy(update={
                "objects": [moved if o.id == obj.id else o for o in self.session.scene.objects]})
            self.panel.content = object_panel(trial, obj.id).markdown()

    def drag(self, object_id: str, x: float, y: float, yaw: float) -> str:
        result = self.session.drag(object_id, x, y, yaw)
        self.status.content = result.message
        self.draw()
        return result.message

    def submit(self, instruction: str) -> str:
        return self._run(lambda: self.session.edit(instruction), "edit")

    def _run(self, action, verb: str) -> str:
        try:
            entry = action()
        except ScenewrightError as exc:  # the CLI's messages: bad input, an infeasible place, a backend
            message = f"**not done:** {exc}"
        else:
            message = f"{verb} {entry.number}: {entry.instruction}"
            if verb == "edit" and entry.changes:
                message += " — " + "; ".join(entry.changes)
        self.status.content = message
        self.draw()
        return message

    def _download(self, event) -> None:
        try:
            data = self.session.glb()
        except ScenewrightError as exc:
            self.status.content = f"**not done:** {exc}"
            return
        if event.client is not None:
            event.client.send_file_download("scene.glb", data)

    def _watch(self) -> None:
        """Follow edits made outside the editor (the CLI) by polling scene.json's stamp."""
        while not self._stop.wait(POLL_SECONDS):
            if self.session.changed_on_disk():
                with self.session.lock:
                    try:
                        self.session.reload()
                    except ScenewrightError as exc:  # half-written by hand: say so, keep the last good one
                        self.status.content = f"**scene.json is not readable:** {exc}"
                        continue
                self.status.content = "scene.json changed on disk; reloaded"
                self.draw()
