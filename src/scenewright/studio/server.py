"""The editor in the browser, drawn with viser (scene frame +Z up, as viser's world).

The page is viser's prebuilt client: no JavaScript is built here. Every button calls the
:class:`~scenewright.studio.session.Session`, and the 3D view is redrawn from the document
after each change and whenever scene.json changes on disk.

While an object is dragged, each gizmo update only moves its node; checking the pose (the
collision and relation checks of :class:`~scenewright.studio.session.DragProbe`) runs on a
thread of its own on the latest pose, at most every ``CHECK_SECONDS``, so a slow check never
holds the drag back. Renders run on a thread too, reporting their progress in the panel.
"""

from __future__ import annotations

import logging
import threading
import time

import numpy as np
import trimesh

from scenewright.errors import MissingExtra, ScenewrightError
from scenewright.export.ground import ground_mesh
from scenewright.geometry import GLTF_TO_SCENE, object_matrix
from scenewright.scene import Scene, SceneObject
from scenewright.studio.session import DragCheck, DragProbe, Session, inside
from scenewright.studio.view import view_glb, view_mesh

log = logging.getLogger(__name__)

#: How often scene.json's modification time is looked at, seconds.
POLL_SECONDS = 0.5
#: Least time between two checks of the dragged pose, seconds (at most ten a second).
CHECK_SECONDS = 0.1
HIGHLIGHT = (255, 170, 0)
#: The dragged object's outline where it fits, and where it does not.
FITS = (60, 200, 90)
MISFITS = (230, 40, 40)
#: The hemisphere light standing in for viser's environment map in the plain view: light
#: from above, a warm bounce from below, so faces turned away from the sun are not black.
SKY, BOUNCE = (235, 240, 255), (120, 105, 90)
#: Outlines of the objects it collides with, and of the other objects of constraints it breaks.
COLLIDING = (230, 40, 40)
VIOLATED = (190, 70, 230)


#: How opaque the walls between the opening view and the room are drawn.
NEAR_WALL_OPACITY = 0.18
#: The view the editor opens on: from the front, as :meth:`Studio._aim_camera` places it.
OPENING_VIEW = "front"


def near_walls(scene: Scene) -> set[str]:
    """The room's walls (and the doors and windows in them) between the opening view and the
    room, by node name: the ones the render's front view leaves out. Drawn solid they hide
    everything standing against them (a TV stand at the front wall) from a camera that looks
    over them; drawn see-through the room reads from outside and still shows where they are."""
    if scene.room is None:
        return set()
    from scenewright.render.views import cut_away

    return set(cut_away(scene.room, OPENING_VIEW)) - {"room/ceiling"}


def _surface_colour(mesh: trimesh.Trimesh) -> tuple[int, int, int]:
    """The sRGB colour (0-255) of a room mesh's glTF material's base colour, which is linear."""
    from scenewright.procedural.room import GLTF_MATERIAL

    linear = mesh.metadata.get(GLTF_MATERIAL, {}).get("pbrMetallicRoughness", {}).get("baseColorFactor", (0.8,) * 3)
    return tuple(int(round(255 * min(max(c, 0.0), 1.0) ** (1 / 2.2))) for c in linear[:3])


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

    def __init__(self, session: Session, *, host: str = "127.0.0.1", port: int = 8080,
                 detailed_light: bool = False) -> None:
        viser = _viser()
        self.session = session
        self.server = viser.ViserServer(host=host, port=port, verbose=False)
        self.server.scene.set_up_direction("+z")
        self.selected: str | None = None
        self._nodes: dict[str, object] = {}
        self._gizmo = None
        self._outline = None
        self._marks: dict[str, object] = {}
        #: The latest pose under the pointer (object id, x, y, yaw) waiting to be checked.
        self._pose: tuple[str, float, float, float] | None = None
        self._probe: DragProbe | None = None
        #: Counts drags; a check of an earlier drag is dropped instead of drawn.
        self._drag_number = 0
        self._check_wanted = threading.Event()
        #: Checks run (for the benchmark: how many the throttle let through).
        self.checks_run = 0
        self._preview_images: list[object] = []
        self._stop = threading.Event()
        #: GUI callbacks and the disk watcher redraw from their own threads.
        self._drawing = threading.RLock()
        self._sky = self.server.scene.add_light_hemisphere("/lights/sky", sky_color=SKY, ground_color=BOUNCE,
                                                           intensity=1.2)
        self.light_view(detailed=detailed_light)
        gui = self.server.gui
        gui.configure_theme(control_width="large", show_logo=False)
        gui.main_panel.dock_right()
        self._aim_camera()
        self.status = gui.add_markdown("Click an object to select it.")
        with gui.add_folder("Object"):
            self.panel = gui.add_markdown("_nothing selected_")
            self.checks = gui.add_markdown("")
        with gui.add_folder("Edit"):
            self.instruction = gui.add_text("Instruction", initial_value="", hint="move the lamp next to the sofa")
            apply = gui.add_button("Apply edit")
            undo = gui.add_button("Undo")
            redo = gui.add_button("Redo")
            download = gui.add_button("Download GLB")
        with gui.add_folder("View", expand_by_default=False):
            detailed = gui.add_checkbox("Environment light and shadows", initial_value=detailed_light,
                                        hint="slow to draw without a graphics card")
        detailed.on_update(lambda _: self.light_view(detailed=detailed.value))
        with gui.add_folder("History"):
            self.history = gui.add_markdown("")
        self._previews = gui.add_folder("Previews")
        with self._previews:
            self.draft = gui.add_checkbox("Draft (fast, noisy)", initial_value=False)
            self.render_button = gui.add_button("Re-render previews")
            self.render_status = gui.add_markdown("")
        apply.on_click(lambda _: self.submit(self.instruction.value))
        undo.on_click(lambda _: self._run(self.session.undo, "undid"))
        redo.on_click(lambda _: self._run(self.session.redo, "redid"))
        download.on_click(self._download)
        self.render_button.on_click(lambda _: self.start_render(self.draft.value))
        self.draw()
        self._show_previews()
        self.status.content = f"{len(self.session.scene.objects)} objects loaded. Click an object to select it."
        self._threads = [threading.Thread(target=self._watch, name="studio-watch", daemon=True),
                         threading.Thread(target=self._check_drags, name="studio-drag-check", daemon=True)]
        for thread in self._threads:
            thread.start()

    @property
    def url(self) -> str:
        return f"http://{self.server.get_host()}:{self.server.get_port()}"

    def stop(self) -> None:
        self._stop.set()
        self._check_wanted.set()
        self.server.stop()

    def light_view(self, *, detailed: bool) -> None:
        """Plain light (the default) or viser's environment map and shadows.

        Sent before the scene so the page compiles its shaders once. viser's own default, an
        HDR environment map and a shadow-casting sun, keeps the canvas nearly transparent until
        the map is prefiltered and then fades it in over five frames, and every shadow draws
        the scene three more times; in software WebGL (no graphics card) that is seconds before
        anything shows, so it is offered as a choice, not the start (figures in docs/studio.md).
        """
        self.server.scene.configure_environment_map("city" if detailed else None)
        self.server.scene.configure_default_lights(True, cast_shadow=detailed)
        self._sky.visible = not detailed

    def _aim_camera(self) -> None:
        """Start the view above the front of the scene, looking at its middle; in a room, high
        enough that the line of sight to the middle clears the front wall."""
        scene = self.session.scene
        points = np.array([o.position.tuple() for o in scene.objects] or [(0.0, 0.0, 0.0)])
        if scene.room is not None:
            points = np.vstack([points, [(x, y, 0.0) for x, y in scene.room.floor]])
        centre = (points.min(axis=0) + points.max(axis=0)) / 2
        reach = max(float(np.ptp(points[:, :2], axis=0).max()), 2.0)
        back, height = 1.2 * reach, 0.9 * reach
        if scene.room is not None:  # closer in, as a room's walls frame what matters
            back = 0.6 * reach
            inside_depth = max(float(centre[1] - points[:, 1].min()), 0.5)  # middle to the front wall
            height = max(height, 1.15 * scene.room.height * (back + inside_depth) / inside_depth)
        camera = self.server.initial_camera
        camera.look_at = (float(centre[0]), float(centre[1]), 0.0)
        camera.position = (float(centre[0]), float(centre[1]) - back, height)

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
        windows, without the ceiling, so the view from above sees in. The walls between the
        opening view and the room are see-through (:func:`near_walls`)."""
        if scene.room is not None:
            from scenewright.procedural.room import room_meshes

            near = near_walls(scene)
            for name, mesh in room_meshes(scene.room, scene.style):
                if name == "room/ceiling":
                    continue
                if name in near or name.rsplit("/", 1)[0] in near:
                    self._nodes[f"__{name}"] = self.server.scene.add_mesh_simple(
                        f"/{name}", mesh.vertices, mesh.faces, color=_surface_colour(mesh), opacity=NEAR_WALL_OPACITY,
                        cast_shadow=False)
                else:
                    self._nodes[f"__{name}"] = self.server.scene.add_mesh_trimesh(f"/{name}", view_mesh(mesh))
            return
        texture = None
        if scene.ground.texture:
            path = inside(self.session.folder, scene.ground.texture)
            texture = path if path.is_file() else None
        ground = ground_mesh(scene.objects, scene.bounds, texture)
        ground.apply_transform(GLTF_TO_SCENE)
        self._nodes["__ground"] = self.server.scene.add_mesh_trimesh("/ground", view_mesh(ground))

    def _add_object(self, obj: SceneObject):
        data = self.session.asset_bytes(obj)
        if data is None:  # no asset yet: its box stands in, as for the solver
            handle = self.server.scene.add_box(f"/objects/{obj.id}", color=(160, 160, 170), dimensions=obj.size.tuple(),
                                               wxyz=_yaw_quaternion(obj.yaw), position=obj.position.tuple())
        else:
            wxyz, position = _pose(object_matrix(obj) @ GLTF_TO_SCENE)
            handle = self.server.scene.add_glb(f"/objects/{obj.id}", view_glb(data), wxyz=wxyz, position=position)
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
        self._end_checks()
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
        """Move the object with the gizmo and have the pose checked; on release commit it as one edit."""
        if self.selected is None:
            return
        obj = self.session.scene.get(self.selected)
        x, y, _ = (float(v) for v in event.target.position)
        yaw = _yaw_of(event.target.wxyz)
        self.move_node(obj, x, y, yaw)
        if event.phase == "end":
            self.drag(obj.id, x, y, yaw)
        else:
            self.want_check(obj.id, x, y, yaw)

    def move_node(self, obj: SceneObject, x: float, y: float, yaw: float) -> None:
        """Show ``obj`` at (x, y) turned to ``yaw`` (the document is not changed)."""
        node = self._nodes.get(obj.id)
        if node is None:
            return
        moved = obj.model_copy(update={"position": obj.position.model_copy(update={"x": x, "y": y}),
                                       "rotation": obj.rotation.model_copy(update={"z": yaw})})
        node.wxyz, node.position = (_pose(object_matrix(moved) @ GLTF_TO_SCENE) if obj.asset is not None
                                    else (_yaw_quaternion(yaw), moved.position.tuple()))

    def want_check(self, object_id: str, x: float, y: float, yaw: float) -> None:
        """Ask for the pose under the pointer to be checked (the latest one wins)."""
        self._pose = (object_id, x, y, yaw)
        self._check_wanted.set()

    def _check_drags(self) -> None:
        while not self._stop.is_set():
            self._check_wanted.wait()
            self._check_wanted.clear()
            pose, number = self._pose, self._drag_number
            if pose is None or self._stop.is_set():
                continue
            started = time.monotonic()
            try:
                found = self._check(pose)
            except ScenewrightError as exc:  # e.g. an asset that no longer reads
                log.warning("could not check the dragged pose: %s", exc)
                continue
            except Exception:  # noqa: BLE001 - the checker outlives one bad pose; the drag itself goes on
                log.exception("checking the dragged pose failed")
                continue
            with self._drawing:
                if number == self._drag_number and self.selected == pose[0]:
                    self._show_check(found)
            self.checks_run += 1
            self._stop.wait(max(0.0, CHECK_SECONDS - (time.monotonic() - started)))

    def _check(self, pose: tuple[str, float, float, float]) -> DragCheck:
        object_id, x, y, yaw = pose
        with self.session.lock:
            scene = self.session.scene
            probe = self._probe
            if probe is None or probe.object_id != object_id or probe.scene is not scene:
                probe = self._probe = DragProbe(scene, object_id, self.session.meshes(scene))
        return probe.check(x, y, yaw)

    def _show_check(self, found: DragCheck) -> None:
        """Outline what the dragged pose runs into, and list it in the panel."""
        if self._outline is not None:
            self._outline.color = FITS if found.fits else MISFITS
        wanted = {oid: VIOLATED for oid in found.partners}
        wanted.update({oid: COLLIDING for oid in found.colliding})  # a collision outweighs a relation
        for oid in [k for k in self._marks if k not in wanted]:
            self._marks.pop(oid).remove()
        scene = self.session.scene
        for oid, colour in wanted.items():
            if oid in self._marks and self._marks[oid].color == colour:
                continue
            if oid in self._marks:
                self._marks.pop(oid).remove()
            other = scene.get(oid)
            self._marks[oid] = self.server.scene.add_box(
                f"/checks/{oid}", color=colour, dimensions=other.size.tuple(), wireframe=True,
                wxyz=_yaw_quaternion(other.yaw), position=other.position.tuple())
        self.checks.content = "**while dragging:** " + found.markdown()

    def _end_checks(self) -> None:
        """Forget the drag's check: its outlines go, a check still running is not drawn."""
        self._drag_number += 1
        self._pose = None
        for handle in self._marks.values():
            handle.remove()
        self._marks.clear()
        self.checks.content = ""

    def drag(self, object_id: str, x: float, y: float, yaw: float) -> str:
        with self._drawing:
            self._end_checks()
        try:
            message = self.session.drag(object_id, x, y, yaw).message
        except ScenewrightError as exc:  # the folder is busy (a render, another command)
            message = f"**not done:** {exc}"
        self.status.content = message
        self.draw()
        return message

    # --- previews --------------------------------------------------------------------------

    def start_render(self, draft: bool) -> threading.Thread | None:
        """Render the previews on a thread of its own; the panel shows its progress and the images."""
        with self._drawing:  # two quick clicks start one render
            if self.session.rendering.is_set() or self.render_button.disabled:
                self.render_status.content = "a render is already running"
                return None
            self.render_button.disabled = True
        thread = threading.Thread(target=self._render, args=(draft,), name="studio-render", daemon=True)
        thread.start()
        return thread

    def _render(self, draft: bool) -> None:
        started = time.monotonic()
        done = threading.Event()

        def tick() -> None:
            while not done.wait(1.0):
                self.render_status.content = f"rendering{' a draft' if draft else ''} with Blender… " \
                                             f"{time.monotonic() - started:.0f} s"

        self.render_status.content = f"rendering{' a draft' if draft else ''} with Blender…"
        ticker = threading.Thread(target=tick, name="studio-render-tick", daemon=True)
        ticker.start()
        try:
            paths = self.session.render(draft=draft)
        except ScenewrightError as exc:  # no Blender (the render extra), a busy folder, a failed render
            message = f"**render not done:** {exc}"
        else:
            message = f"rendered {len(paths)} preview(s) in {time.monotonic() - started:.0f} s"
        finally:
            done.set()
            ticker.join()
            self.render_button.disabled = False
        self.render_status.content = message
        self._show_previews()

    def _show_previews(self) -> None:
        """The folder's preview images in the panel, the chosen view first."""
        try:
            paths = self.session.previews()
        except ScenewrightError as exc:
            self.render_status.content = f"**previews not shown:** {exc}"
            return
        from PIL import Image

        with self._drawing:
            for handle in self._preview_images:
                handle.remove()
            self._preview_images = []
            for path in paths:
                with Image.open(path) as image:
                    pixels = np.asarray(image.convert("RGB"))
                with self._previews:
                    self._preview_images.append(self.server.gui.add_image(pixels, label=path.stem, format="jpeg"))

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
            with self.session.lock:  # not in the middle of the editor's own edit, which rereads it after
                if not self.session.changed_on_disk():
                    continue
                try:
                    self.session.reload()
                except ScenewrightError as exc:  # half-written by hand: say so, keep the last good one
                    self.status.content = f"**scene.json is not readable:** {exc}"
                    continue
            self.status.content = "scene.json changed on disk; reloaded"
            self.draw()
