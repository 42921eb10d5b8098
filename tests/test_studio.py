"""``scenewright studio``: the editing session on its own, and the editor in a headless browser."""

from __future__ import annotations

import json
import socket
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from editing_scenes import RulePlanner, snapshot
from scenewright.backends import Backends, backends_from_settings
from scenewright.cli import main
from scenewright.editing import entries
from scenewright.errors import InputError, MissingExtra
from scenewright.layout import check
from scenewright.scene import Constraint, Vec3
from scenewright.settings import Settings
from scenewright.studio import Session, inside, object_panel
from scenewright.bench.studio import CHROMIUM, CHROMIUM_ARGS, drag_from_page, tiled_scene
from scenewright.studio.session import DragProbe



def session(folder) -> Session:
    settings = Settings()
    return Session(folder, backends=backends_from_settings(settings), settings=settings)


def test_panel_shows_constraints_held_and_violated_and_the_unplaced_reason(folder):
    scene = folder.load()
    lamp = scene.get("floor_lamp_1")
    lamp.position = Vec3(x=-3.0, y=1.5, z=lamp.position.z)  # now left of the sofa, not right
    scene.layout = {"unplaced": [{"id": "floor_lamp_1", "reason": "no free spot right of sofa_1"}]}
    panel = object_panel(scene, "floor_lamp_1")
    assert (panel.id, panel.name) == ("floor_lamp_1", "floor lamp")
    assert panel.size == pytest.approx((0.45, 0.45, 1.7), abs=1e-6)
    [state] = panel.constraints
    assert state.text == "floor_lamp_1 right of sofa_1" and not state.held and state.miss.startswith("misses by")
    assert panel.unplaced == "no free spot right of sofa_1"
    text = panel.markdown()
    assert "**violated**" in text and "unplaced" in text
    # Constraints where the object is the target are listed too, and held ones say so.
    sofa = object_panel(folder.load(), "sofa_1")
    assert {c.text for c in sofa.constraints} == {"coffee_table_1 in front of sofa_1", "floor_lamp_1 right of sofa_1",
                                                 "bookshelf_1 left of sofa_1"}
    assert all(c.held for c in sofa.constraints) and sofa.unplaced is None


def test_paths_outside_the_folder_are_refused(folder):
    assert inside(folder, "assets/sofa_1.glb") == (folder.root / "assets/sofa_1.glb").resolve()
    with pytest.raises(InputError, match="outside the scene folder"):
        inside(folder, "../../etc/passwd")
    scene = folder.load()
    scene.get("sofa_1").asset = "../secret.glb"
    with pytest.raises(InputError, match="outside the scene folder"):
        session(folder).asset_bytes(scene.get("sofa_1"))


def test_drag_commits_one_edit_and_keeps_the_constraints(folder):
    s = session(folder)
    message = s.drag("armchair_1", -1.2, -1.3, 30.0).message
    [entry] = entries(folder)
    assert entry.operation == "move" and entry.focus == "armchair_1" and message.startswith("edit 1")
    after = folder.load()
    chair = after.get("armchair_1")
    assert (round(chair.position.x, 3), round(chair.position.y, 3), round(chair.yaw, 3)) == (-1.2, -1.3, 30.0)
    assert all(check(c.relation, after.get(c.source), after.get(c.target)) for c in after.constraints)


def test_drag_into_a_collision_snaps_to_a_pose_that_fits(folder):
    s = session(folder)
    result = s.drag("armchair_1", 0.0, 1.5, 0.0)  # right onto the sofa
    assert result.committed and "snapped" in result.message
    after = folder.load()
    chair = after.get("armchair_1")
    assert (chair.position.x, chair.position.y) != (0.0, 1.5)
    assert all(check(c.relation, after.get(c.source), after.get(c.target)) for c in after.constraints)
    assert len(entries(folder)) == 1


def test_drag_with_no_pose_that_fits_changes_nothing(folder):
    scene = folder.load()  # left of the sofa and right of it: no pose keeps both
    scene.constraints += [Constraint(relation="left of", source="armchair_1", target="sofa_1"),
                          Constraint(relation="right of", source="armchair_1", target="sofa_1")]
    folder.save(scene)
    before = snapshot(folder.root)
    result = session(folder).drag("armchair_1", -1.0, -1.5, 0.0)
    assert not result.committed and "stays where it was" in result.message
    assert "armchair_1 left of sofa_1" in result.message
    assert snapshot(folder.root) == before


def test_language_edit_undo_redo_and_disk_changes(folder, monkeypatch):
    s = session(folder)
    s.backends = Backends(vlm=RulePlanner(), images=s.backends.images, meshes=s.backends.meshes)
    original = folder.document.read_bytes()
    entry = s.edit("move the lamp to the left of the sofa")
    assert entry.number == 1 and check("left of", s.scene.get("floor_lamp_1"), s.scene.get("sofa_1"))
    assert s.undo().number == 1 and folder.document.read_bytes() == original
    assert s.redo().number == 1
    assert not s.changed_on_disk()
    time.sleep(0.01)
    assert main(["undo", str(folder.root)]) == 0  # the CLI edits while the editor is open
    assert s.changed_on_disk()
    s.reload()
    assert not s.changed_on_disk() and folder.document.read_bytes() == original


def test_studio_command_reports_a_folder_that_is_not_a_scene(tmp_path):
    assert main(["studio", str(tmp_path)]) == 2


def test_without_viser_the_error_names_the_extra(folder, monkeypatch):
    from scenewright.studio import server

    monkeypatch.setitem(sys.modules, "viser", None)
    with pytest.raises(MissingExtra, match=r"scenewright\[studio\]"):
        server.Studio(session(folder))


# --- in the browser ----------------------------------------------------------------------------


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


@pytest.fixture
def browser():
    playwright = pytest.importorskip("playwright.sync_api", reason="playwright is not installed (the test extra)")
    pytest.importorskip("viser", reason="viser is not installed (the studio extra: make install-studio)")
    if not CHROMIUM.is_file():
        pytest.skip(f"no chromium at {CHROMIUM}: `make tools` installs it with apt (apt-get install chromium)")
    with playwright.sync_playwright() as p:
        launched = p.chromium.launch(
            executable_path=str(CHROMIUM),
            args=list(CHROMIUM_ARGS),
        )
        yield launched
        launched.close()


@pytest.mark.slow
@pytest.mark.timeout(600)
def test_editor_in_the_browser(folder, browser, tmp_path):
    """Select (through the editor's server-side API: clicks in software WebGL are not reliable),
    read the panel, type an edit, undo, reload, redo with the CLI: the page and scene.json agree throughout."""
    from scenewright.studio.server import Studio

    s = session(folder)
    s.backends = Backends(vlm=RulePlanner(), images=s.backends.images, meshes=s.backends.meshes)
    studio = Studio(s, port=_free_port())
    try:
        assert studio.url.startswith("http://127.0.0.1:")
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        page.goto(studio.url)
        page.get_by_text("Connected").wait_for(timeout=30_000)
        studio.select("floor_lamp_1")
        page.get_by_text("floor_lamp_1 right of sofa_1: held").wait_for(timeout=15_000)
        assert "size 0.45 × 0.45 × 1.70 m" in page.inner_text("body")

        original = folder.document.read_bytes()
        typed = "move the lamp to the left of the sofa"
        page.locator("input.mantine-TextInput-input:visible").fill(typed)  # the Instruction box
        for _ in range(100):  # the typed value reaches the server before the button is pressed
            if studio.instruction.value == typed:
                break
            time.sleep(0.1)
        # Playwright clicks once the button is stable over two drawn frames; software WebGL on a
        # loaded machine draws a frame every few seconds, so the wait is long.
        page.get_by_role("button", name="Apply edit").click(timeout=180_000)
        page.get_by_text("floor_lamp_1 left of sofa_1: held").wait_for(timeout=30_000)
        [entry] = entries(folder)
        assert entry.active and entry.instruction == "move the lamp to the left of the sofa"
        assert json.loads(folder.document.read_bytes())["objects"] != json.loads(original)["objects"]
        page.screenshot(path=str(tmp_path / "studio.png"))

        page.get_by_role("button", name="Undo").click(timeout=180_000)
        page.get_by_text("undid 1").wait_for(timeout=30_000)
        assert folder.document.read_bytes() == original and not entries(folder)[0].active

        page.reload()
        page.get_by_text("Connected").wait_for(timeout=30_000)
        page.get_by_text("floor_lamp_1 right of sofa_1: held").wait_for(timeout=15_000)
        assert "(undone)" in page.inner_text("body")

        assert main(["redo", str(folder.root)]) == 0  # the CLI changes scene.json: the page follows
        page.get_by_text("scene.json changed on disk; reloaded").wait_for(timeout=30_000)
        page.get_by_text("floor_lamp_1 left of sofa_1: held").wait_for(timeout=15_000)
        assert "(undone)" not in page.inner_text("body")

        # Drag the armchair's gizmo from the page (the messages viser's client sends while a gizmo
        # is dragged): released, it is one more edit, and every constraint holds.
        studio.select("armchair_1")
        before = folder.load().get("armchair_1").position
        drag_from_page(page, studio, count=30, rate=30.0, step=-0.02)
        page.get_by_text("edit 2: drag armchair_1").wait_for(timeout=60_000)
        history = entries(folder)
        assert len(history) == 2 and history[-1].operation == "move" and history[-1].focus == "armchair_1"
        after = folder.load()
        assert after.get("armchair_1").position != before
        assert all(check(c.relation, after.get(c.source), after.get(c.target)) for c in after.constraints)
    finally:
        studio.stop()


# --- while dragging, two tabs, renders ----------------------------------------------------------


def test_drag_probe_names_collisions_and_broken_constraints(folder):
    s = session(folder)
    scene = s.scene
    sofa = scene.get("sofa_1")
    probe = DragProbe(scene, "armchair_1", s.meshes(scene))
    chair = scene.get("armchair_1")
    assert probe.check(chair.position.x, chair.position.y, chair.yaw).fits  # where it stands
    onto_sofa = probe.check(sofa.position.x, sofa.position.y, 0.0)
    assert onto_sofa.colliding == ["sofa_1"] and not onto_sofa.fits
    assert "collides with" in onto_sofa.markdown()
    lamp = DragProbe(scene, "floor_lamp_1", s.meshes(scene))
    left = lamp.check(sofa.position.x - 3.0, sofa.position.y, 0.0)  # left of the sofa, not right
    assert [v.text for v in left.violated] == ["floor_lamp_1 right of sofa_1"] and left.partners == ["sofa_1"]
    assert left.violated[0].miss.startswith("misses by") and "**violated**" in left.markdown()


def test_a_drop_that_collides_says_with_what_it_snapped_away_from(folder):
    result = session(folder).drag("armchair_1", 0.0, 1.5, 0.0)
    assert result.committed and "it collided with sofa_1" in result.message


def test_edits_from_two_tabs_at_once_both_land(folder):
    """Two tabs share the server's session; a second editor process has a session of its own.
    Either way the edits are serialised: each starts from the document the other wrote."""
    tab = session(folder)
    other_editor = session(folder)
    for s in (tab, other_editor):
        s.backends = Backends(vlm=RulePlanner(), images=s.backends.images, meshes=s.backends.meshes)
    jobs = [lambda: tab.edit("move the lamp to the left of the sofa"),
            lambda: tab.drag("armchair_1", -1.2, -1.3, 30.0),
            lambda: other_editor.drag("coffee_table_1", 0.0, 0.6, 0.0)]
    with ThreadPoolExecutor(3) as pool:
        list(pool.map(lambda job: job(), jobs))
    history = entries(folder)
    assert len(history) == 3 and all(e.active for e in history)
    after = folder.load()
    assert check("left of", after.get("floor_lamp_1"), after.get("sofa_1"))  # nothing lost
    assert (round(after.get("armchair_1").position.x, 3), round(after.get("armchair_1").yaw, 3)) == (-1.2, 30.0)
    assert all(check(c.relation, after.get(c.source), after.get(c.target)) for c in after.constraints)


def test_without_blender_the_render_names_the_extra(folder, monkeypatch):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "bpy" else real(name, *a))
    s = session(folder)
    with pytest.raises(MissingExtra, match=r"scenewright\[render\]"):
        s.render(draft=True)
    assert not s.rendering.is_set()


@pytest.fixture
def studio(folder):
    pytest.importorskip("viser", reason="viser is not installed (the studio extra: make install-studio)")
    from scenewright.studio.server import Studio

    s = session(folder)
    started = Studio(s, port=_free_port())
    yield started
    started.stop()


def _until(condition, seconds: float = 60.0) -> None:
    deadline = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < deadline, "the editor did not get there"
        time.sleep(0.02)


def test_dragging_outlines_what_the_pose_runs_into_and_checks_only_the_latest_pose(studio):
    from scenewright.studio.server import COLLIDING, MISFITS, VIOLATED

    studio.select("floor_lamp_1")
    sofa = studio.session.scene.get("sofa_1")
    # A burst of pointer moves: the checker takes the latest pose, not one check per move.
    for k in range(200):
        studio.want_check("floor_lamp_1", sofa.position.x - 3.0 + k * 0.001, sofa.position.y - 3.0, 0.0)
    studio.want_check("floor_lamp_1", sofa.position.x, sofa.position.y, 0.0)  # onto the sofa
    _until(lambda: "collides with" in studio.checks.content)
    assert studio.checks_run < 20
    assert "`sofa_1`" in studio.checks.content and "**violated** floor_lamp_1 right of sofa_1" in studio.checks.content
    assert studio._marks["sofa_1"].color == COLLIDING and studio._outline.color == MISFITS
    studio.want_check("floor_lamp_1", sofa.position.x - 3.0, sofa.position.y, 0.0)  # left of it, clear
    _until(lambda: "collides with" not in studio.checks.content and "violated" in studio.checks.content)
    assert studio._marks["sofa_1"].color == VIOLATED
    studio.select(None)  # the drag's outlines go with it
    assert not studio._marks and studio.checks.content == ""


@pytest.mark.slow
@pytest.mark.timeout(600)
def test_the_render_button_renders_under_the_lock_and_shows_the_images(studio):
    pytest.importorskip("bpy", reason="Blender (the render extra) is not installed")
    folder = studio.session.folder
    thread = studio.start_render(draft=True)
    assert thread is not None and studio.render_button.disabled
    _until(lambda: studio.session.rendering.is_set() or not thread.is_alive())
    if thread.is_alive():  # while it renders, edits are refused at once, naming the render
        assert "being rendered" in studio.drag("armchair_1", -1.2, -1.3, 30.0)
        assert studio.start_render(draft=True) is None and "already running" in studio.render_status.content
    thread.join(600)
    assert studio.render_status.content.startswith("rendered"), studio.render_status.content
    assert not studio.render_button.disabled
    assert len(studio._preview_images) == len(studio.session.previews()) >= 1
    assert (folder.renders / "renders.json").is_file()
    assert not entries(folder)


def test_the_benchmark_scene_tiles_a_scene_with_its_meshes_and_relations(folder, tmp_path):
    scene = folder.load()
    large = tiled_scene(folder, tmp_path / "large", 2 * len(scene.objects) + 3)
    tiled = large.load()
    assert len(tiled.objects) == len({o.id for o in tiled.objects}) == 2 * len(scene.objects) + 3
    assert len(tiled.constraints) >= 2 * len(scene.constraints)
    assert all(check(c.relation, tiled.get(c.source), tiled.get(c.target)) for c in tiled.constraints)
    assert large.glb.is_file() and all(inside(large, o.asset).is_file() for o in tiled.objects if o.asset)


def test_the_view_glb_drops_transmission_and_keeps_everything_else():
    import struct

    from scenewright.studio.view import view_glb

    def glb(document: dict, binary: bytes = b"\x01\x02\x03\x04") -> bytes:
        text = json.dumps(document).encode()
        text += b" " * (-len(text) % 4)
        body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
        return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body

    def document_of(data: bytes) -> dict:
        magic, version, total = struct.unpack_from("<III", data, 0)
        assert (magic, version, total) == (0x46546C67, 2, len(data))
        length = struct.unpack_from("<I", data, 12)[0]
        assert length % 4 == 0
        return json.loads(data[20 : 20 + length])

    glass = {"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_volume"],
             "materials": [{"name": "glass", "alphaMode": "BLEND", "doubleSided": True,
                            "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.9, 0.9, 0.35]},
                            "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                                           "KHR_materials_volume": {}}},
                           {"name": "wood"}]}
    viewed = view_glb(glb(glass))
    found = document_of(viewed)
    assert "extensionsUsed" not in found and "extensions" not in found["materials"][0]
    assert found["materials"][0]["alphaMode"] == "BLEND"
    assert found["materials"][0]["pbrMetallicRoughness"] == glass["materials"][0]["pbrMetallicRoughness"]
    assert viewed.endswith(b"\x01\x02\x03\x04")  # the binary chunk is untouched
    plain = glb({"asset": {"version": "2.0"}, "materials": [{"name": "wood"}]})
    assert view_glb(plain) is plain
    assert view_glb(b"not a glb at all") == b"not a glb at all"



def test_the_view_mesh_carries_face_normals_and_keeps_its_texture_coordinates():
    import io
    import struct

    import numpy as np
    import trimesh

    from scenewright.studio.view import view_mesh

    box = trimesh.creation.box((2.0, 1.0, 0.5))
    box.visual = trimesh.visual.TextureVisuals(uv=np.random.default_rng(0).random((len(box.vertices), 2)))
    view = view_mesh(box)
    assert len(view.vertices) == 3 * len(box.faces)
    assert np.allclose(view.vertex_normals, np.repeat(box.face_normals, 3, axis=0))
    assert np.allclose(view.visual.uv, box.visual.uv[box.faces.reshape(-1)])
    assert len(box.vertices) == 8  # the original is left alone
    data = io.BytesIO()
    view.export(data, file_type="glb")
    length = struct.unpack_from("<I", data.getvalue(), 12)[0]
    attributes = json.loads(data.getvalue()[20 : 20 + length])["meshes"][0]["primitives"][0]["attributes"]
    assert {"POSITION", "NORMAL", "TEXCOORD_0"} <= set(attributes)


def test_a_room_opens_from_outside_its_front_wall_which_is_drawn_see_through(folder):
    """The opening camera stands outside the room in front of its front wall and above it,
    looking in; that wall (between camera and room) is see-through so what stands against it
    shows, and every other wall is solid."""
    pytest.importorskip("viser", reason="viser is not installed (the studio extra: make install-studio)")
    from scenewright.scene import Room
    from scenewright.studio.server import NEAR_WALL_OPACITY, Studio, near_walls

    scene = folder.load()
    xy = np.array([o.position.tuple()[:2] for o in scene.objects])
    (x0, y0), (x1, y1) = xy.min(axis=0) - 1.0, xy.max(axis=0) + 1.0
    scene.room = Room(floor=[(x0, y0), (x1, y0), (x1, y1), (x0, y1)], height=2.7)
    folder.save(scene)
    assert near_walls(scene) == {"room/wall_0"}  # the wall along y = y0, the front
    studio = Studio(session(folder), port=_free_port())
    try:
        front = studio._nodes["__room/wall_0"]
        assert front.opacity == pytest.approx(NEAR_WALL_OPACITY)
        walls = [name for name in studio._nodes if name.startswith("__room/wall_")]
        assert len(walls) == 4
        assert all(getattr(studio._nodes[name], "opacity", None) is None for name in walls if name != "__room/wall_0")
        camera = studio.server.initial_camera
        x, y, z = camera.position
        assert x0 < x < x1 and y < y0 - 0.1 and z > scene.room.height  # outside, before and above the front wall
        assert y0 < camera.look_at[1] < y1  # looking into the room
    finally:
        studio.stop()
