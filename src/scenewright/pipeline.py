"""Text → scene folder: analysis, assets, layout, export, render, resumable stage by stage.

Each stage adds its output to the document and the folder, then its name goes into
``scene.done``; a re-run skips every stage that is done and whose output is still on disk.
When a stage has to run again, every later stage runs again too, since it was built on the
old output.
"""

from __future__ import annotations

import logging
import shutil
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from pydantic import ValidationError

from scenewright.analysis.stage import analyze
from scenewright.assets import generate_assets, load_meshes
from scenewright.assets.stage import needs_asset
from scenewright.backends import Backends
from scenewright.cache import RequestCache
from scenewright.editing.history import recover
from scenewright.errors import InputError, MissingExtra
from scenewright.folder import SceneFolder
from scenewright.integrity import assemble_recorded, finish_first_save, glb_matches, rebuild_glb, remove_temporaries
from scenewright.layout.stage import arrange
from scenewright.lock import LOCK_NAME, locked
from scenewright.scene import Scene, describe_validation_error
from scenewright.settings import Settings

log = logging.getLogger(__name__)

STAGES = ("analyze", "assets", "layout", "export", "render")

#: Called with (stage, message) as the run goes; the CLI turns it into a progress display.
Progress = Callable[[str, str], None]


def _as_folder(folder: SceneFolder | str | Path) -> SceneFolder:
    return folder if isinstance(folder, SceneFolder) else SceneFolder(Path(folder))


def _output_present(stage: str, scene: Scene, folder: SceneFolder) -> bool:
    """Whether what ``stage`` produced is still there (a user may have deleted files)."""
    if stage == "analyze":
        return bool(scene.objects) and folder.ground_image.is_file()
    if stage == "assets":
        return not any(needs_asset(obj, folder) for obj in scene.objects)
    if stage == "layout":
        return scene.layout is not None
    if stage == "export":
        return glb_matches(scene, folder) if scene.glb_sha256 is not None else folder.glb.is_file()
    return folder.renders.is_dir() and any(folder.renders.glob("*.png"))


def _pending(scene: Scene, folder: SceneFolder) -> list[str]:
    """Stages to run: from the first one not done (or whose output is gone) to the end."""
    for index, stage in enumerate(STAGES):
        if stage not in scene.done or not _output_present(stage, scene, folder):
            return list(STAGES[index:])
    return []


def _render(scene: Scene, folder: SceneFolder, note: Callable[[str], None]) -> bool:
    """Preview renders when Blender is installed; without it the scene is complete all the same."""
    from scenewright.render import render

    try:
        paths = render(scene, folder, draft=False)
    except MissingExtra as exc:
        log.warning("no preview renders: %s", exc)
        note("skipped: Blender (the render extra) is not installed")
        return False
    scene.record("render", f"rendered {len(paths)} previews", files=[Path(p).name for p in paths])
    return True


@contextmanager
def writing(folder: SceneFolder, timeout: float) -> Iterator[SceneFolder]:
    """Hold the folder's lock and make it whole after any run that died in it (see
    :mod:`scenewright.integrity`); every command that writes a scene folder runs inside this."""
    if not folder.root.is_dir():
        folder.load()  # raises the error that names the folder and how to make a scene
    with locked(folder.root, timeout):
        finish_first_save(folder)
        remove_temporaries(folder)
        if folder.is_scene():
            recover(folder)
            rebuild_glb(folder)
        yield folder


def _stage_note(progress: Progress | None, stage: str) -> Callable[[str], None]:
    return (lambda message: progress(stage, message)) if progress else (lambda message: None)


def _room_option(scene: Scene) -> str:
    """The ``--room`` a scene was generated with (recorded when it was made), for a resumed run
    that analyses again; ``auto``, the default, when nothing recorded one (a first save cut short)."""
    for event in scene.provenance:
        if event.stage == "generate" and event.message == "new scene":
            return str(event.data.get("room", "auto"))
    return "auto"


def _decide_room(scene: Scene, vlm, option: str) -> None:
    """Give ``scene`` its room (or none) under ``--room`` ``option``, once its objects are known."""
    from scenewright.analysis.parser.room import parse_room_option, room_for

    proposed = bool(getattr(vlm, "proposes_rooms", False))
    scene.room = room_for(scene.text, scene.objects, parse_room_option(option),
                          getattr(vlm, "last_room", None) if proposed else None, proposed)
    if scene.room is not None:
        (x0, y0), (x1, y1) = scene.room.floor[0], scene.room.floor[2]
        scene.record("analyze", f"room {abs(x1 - x0):g} x {abs(y1 - y0):g} m, {scene.room.height:g} m high, "
                     f"{len(scene.room.openings)} openings", room=option, walls=len(scene.room.floor))


def run_stages(
    scene: Scene,
    folder: SceneFolder,
    *,
    backends: Backends,
    settings: Settings,
    render: bool = True,
    progress: Progress | None = None,
    room: str | None = None,
) -> Scene:
    """Run every stage of ``scene`` that is not done yet; save the document after each.

    ``room`` is the ``--room`` choice, applied when the analysis runs (default: the one the
    scene was made with)."""
    from scenewright.analysis.composition.walls import room_constraints
    cache = RequestCache(settings.cache_dir)
    scene.backends = backends.names()
    pending = _pending(scene, folder)
    scene.done = [s for s in scene.done if s not in pending]
    for stage in pending:
        if stage == "render" and not render:
            break
        note = _stage_note(progress, stage)
        note("started")
        if stage == "analyze":
            analyze(scene, folder, backends.vlm, backends.images, note)
            _decide_room(scene, backends.vlm, room or _room_option(scene))
        elif stage == "assets":
            generate_assets(scene, folder, backends.meshes, cache, note, max_faces=settings.max_faces)
        elif stage == "layout":
            arrange(
                scene,
                folder,
                backends.vlm,
                load_meshes(scene, folder),
                rounds=settings.feedback_rounds,
                time_limit=settings.time_limit,
                furnish=room_constraints,
            )
        elif stage == "export":
            path = assemble_recorded(scene, folder)
            scene.record(stage, f"wrote {folder.relative(path)}")
        elif not _render(scene, folder, note):
            break
        scene.done.append(stage)
        folder.save(scene)
        note("done")
    return scene


def _new_scene(text: str, style: str | None, seed: int) -> Scene:
    """A scene with the style (the flag, else the one the text names, else the default) and the
    ground kind read from the text by the offline parser, whichever backends run the stages.

    Made before the folder is touched, so bad input leaves nothing behind.
    """
    from scenewright.analysis.parser import parse_scene

    try:
        scene = Scene(text=text, seed=seed, **({"style": style.strip().lower()} if style and style.strip() else {}))
    except ValidationError as exc:
        raise InputError(describe_validation_error(exc)) from None
    parsed = parse_scene(text)
    if not (style and style.strip()):
        scene.style = parsed.style
    scene.ground.kind = parsed.ground
    return scene


def generate(
    text: str,
    folder: SceneFolder | str | Path,
    *,
    backends: Backends,
    settings: Settings,
    style: str | None = None,
    seed: int = 0,
    render: bool = True,
    progress: Progress | None = None,
    room: str | None = "auto",
) -> Scene:
    """Make the scene ``text`` describes in ``folder``; resume it when the folder holds it already.

    ``room``: ``auto`` (a room when the text is indoor, docs/rooms.md), ``none``, or the floor
    as ``WxD`` or ``WxDxH`` metres."""
    from scenewright.analysis.parser.room import parse_room_option

    folder = _as_folder(folder)
    room = room or "auto"
    parse_room_option(room)  # bad input fails before the folder is touched
    text = text.strip()
    if not text:
        raise InputError(
            "the text is empty; describe the scene, e.g. 'a cosy reading corner with an armchair'"
        )
    candidate = _new_scene(text, style, seed)
    existed = folder.root.exists()
    folder.create()
    with writing(folder, settings.lock_timeout):
        fresh = not folder.is_scene()
        if not fresh:
            scene = folder.load()
            if scene.text != text or scene.seed != seed or (style and scene.style != style.strip().lower()):
                raise InputError(
                    f"{folder.root} already holds another scene ({scene.text[:60]!r}, style {scene.style}, "
                    f"seed {scene.seed}); resume it with `scenewright generate --resume {folder.root}` "
                    "or choose a new --out"
                )
            log.info("resuming %s (done: %s)", folder.root, ", ".join(scene.done) or "nothing")
        else:
            scene = candidate
            scene.record("generate", "new scene", style=scene.style, seed=seed, backends=backends.names(), room=room)
            folder.save(scene)
        try:
            return run_stages(
                scene, folder, backends=backends, settings=settings, render=render, progress=progress,
                room=room if fresh else None,
            )
        except InputError:
            if fresh and not scene.objects:
                _discard(folder, existed)
            raise


def _discard(folder: SceneFolder, existed: bool) -> None:
    """Remove a scene that never got an object, so the folder is as the user left it (empty)."""
    if not existed:
        shutil.rmtree(folder.root, ignore_errors=True)
        return
    for child in folder.root.iterdir():
        if child.name == LOCK_NAME:  # held by this run until it returns
            continue
        if child.is_dir():
            shutil.rmtree(child, ignore_errors=True)
        else:
            child.unlink(missing_ok=True)


def resume(
    folder: SceneFolder | str | Path,
    *,
    backends: Backends,
    settings: Settings,
    render: bool = True,
    progress: Progress | None = None,
) -> Scene:
    """Finish an interrupted scene: run only the stages it has not completed."""
    folder = _as_folder(folder)
    with writing(folder, settings.lock_timeout):
        scene = folder.load()
        return run_stages(scene, folder, backends=backends, settings=settings, render=render, progress=progress)
