"""Text → scene folder: analysis, assets, layout, export, render, resumable stage by stage.

Each stage adds its output to the document and the folder, then its name goes into
``scene.done``; a re-run skips every stage that is done and whose output is still on disk.
When a stage has to run again, every later stage runs again too, since it was built on the
old output. The stages are one table, :data:`PIPELINE` (name, what runs it, whether its output
is still there), and :func:`run_stages` is the only place a run saves the document.
"""

from __future__ import annotations

import logging
import shutil
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from pydantic import ValidationError

from scenewright.assets.load import AssetMeshes
from scenewright.backends import Backends
from scenewright.cache import RequestCache
from scenewright.editing.history import recover
from scenewright.errors import InputError, MissingExtra
from scenewright.folder import DocumentSaver, SceneFolder, as_folder
from scenewright.integrity import assemble_recorded, finish_first_save, glb_matches, rebuild_glb, remove_temporaries
from scenewright.lock import LOCK_NAME, locked
from scenewright.scene import Scene, describe_validation_error
from scenewright.settings import Settings

log = logging.getLogger(__name__)

#: Called with (stage, message) as the run goes; the CLI turns it into a progress display.
Progress = Callable[[str, str], None]


@dataclass
class Run:
    """What the stages of one run share: the document, its folder, the backends and settings,
    and the assets parsed so far (each asset file is parsed once per run, see
    :class:`~scenewright.assets.load.AssetMeshes`)."""

    scene: Scene
    folder: SceneFolder
    backends: Backends
    settings: Settings
    saver: DocumentSaver
    #: Preview quality of the render stage (see :data:`scenewright.render.PREVIEWS`).
    preview: str = "default"
    #: The ``--room`` choice the analysis applies when it reads the objects.
    room: str = "auto"
    note: Callable[[str], None] = lambda message: None
    meshes: AssetMeshes = field(default_factory=AssetMeshes)


@dataclass(frozen=True)
class Stage:
    """One step of the pipeline: ``run`` adds its output to the document and the folder (and
    says False when it could not, so the run stops there without marking it done), ``present``
    says whether that output is still there (a user may have deleted files)."""

    name: str
    run: Callable[[Run], bool]
    present: Callable[[Run], bool]


# Each stage imports its module when it runs: a command that only holds the folder (``writing``)
# or resumes past a stage does not pay for the reader, the mesh library or the solver.
def _analyze(run: Run) -> bool:
    from scenewright.analysis.stage import analyze

    analyze(run.scene, run.folder, run.backends.vlm, run.backends.images, run.note, checkpoint=run.saver.checkpoint,
            room=run.room)
    return True


def _assets(run: Run) -> bool:
    from scenewright.assets.stage import generate_assets

    generate_assets(
        run.scene, run.folder, run.backends.meshes, RequestCache(run.settings.cache_dir), run.note,
        max_faces=run.settings.max_faces, store=run.meshes, checkpoint=run.saver.checkpoint,
    )
    return True


def _assets_present(run: Run) -> bool:
    from scenewright.assets.stage import needs_asset

    return not any(needs_asset(o, run.folder, run.meshes) for o in run.scene.objects)


def _layout(run: Run) -> bool:
    from scenewright.analysis.composition.walls import ceiling_for, room_constraints
    from scenewright.analysis.parser.room import sized_freely, tall_freely
    from scenewright.layout.stage import arrange

    option = next((e.data.get("room") for e in reversed(run.scene.provenance) if e.data.get("step") == "room"), None)
    arrange(
        run.scene,
        run.folder,
        run.backends.vlm,
        run.meshes.of(run.scene, run.folder),
        rounds=run.settings.feedback_rounds,
        time_limit=run.settings.time_limit,
        furnish=room_constraints,
        grow=isinstance(option, str) and sized_freely(option, run.scene.text),
        lift=ceiling_for if isinstance(option, str) and tall_freely(option, run.scene.text) else None,
    )
    return True


def _export(run: Run) -> bool:
    path = assemble_recorded(run.scene, run.folder, run.meshes)
    run.scene.record("export", f"wrote {run.folder.relative(path)}")
    return True


def _render(run: Run) -> bool:
    """Preview renders when Blender is installed; without it the scene is complete all the same."""
    from scenewright.render import render

    try:
        paths = render(run.scene, run.folder, preview=run.preview, meshes=run.meshes)
    except MissingExtra as exc:
        log.warning("no preview renders: %s", exc)
        run.note("skipped: Blender (the render extra) is not installed")
        return False
    run.scene.record("render", f"rendered {len(paths)} previews", files=[Path(p).name for p in paths])
    return True


#: The pipeline, in order. A re-run skips every stage that is done and whose output is still
#: there; when a stage has to run again, every later stage runs again too.
PIPELINE: tuple[Stage, ...] = (
    Stage("analyze", _analyze, lambda r: bool(r.scene.objects) and r.folder.ground_image.is_file()),
    Stage("assets", _assets, _assets_present),
    Stage("layout", _layout, lambda r: r.scene.layout is not None),
    Stage("export", _export, lambda r: glb_matches(r.scene, r.folder) if r.scene.glb_sha256 is not None
          else r.folder.glb.is_file()),
    Stage("render", _render, lambda r: r.folder.renders.is_dir() and any(r.folder.renders.glob("*.png"))),
)
STAGES = tuple(stage.name for stage in PIPELINE)


def _pending(run: Run) -> list[Stage]:
    """Stages to run: from the first one not done (or whose output is gone) to the end."""
    for index, stage in enumerate(PIPELINE):
        if stage.name not in run.scene.done or not stage.present(run):
            return list(PIPELINE[index:])
    return []


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


def _room_option(scene: Scene) -> str:
    """The ``--room`` a scene was generated with (recorded when it was made), for a resumed run
    that analyses again; ``auto``, the default, when nothing recorded one (a first save cut short)."""
    for event in scene.provenance:
        if event.stage == "generate" and event.message == "new scene":
            return str(event.data.get("room", "auto"))
    return "auto"


def run_stages(
    scene: Scene,
    folder: SceneFolder,
    *,
    backends: Backends,
    settings: Settings,
    render: bool = True,
    preview: str = "default",
    progress: Progress | None = None,
    room: str | None = None,
) -> Scene:
    """Run every stage of ``scene`` that is not done yet; save the document after each.

    This is the one place a run saves its document: once per stage, also when a stage stops
    with an error or Ctrl-C (what it finished is kept), and at the checkpoints a long stage
    asks for (see :class:`~scenewright.folder.DocumentSaver`). ``room`` is the ``--room``
    choice, applied when the objects are read (default: the one the scene was made with).
    """
    scene.backends = backends.names()
    run = Run(scene, folder, backends, settings, DocumentSaver(folder, scene), preview, room or _room_option(scene))
    pending = _pending(run)
    scene.done = [s for s in scene.done if s not in {stage.name for stage in pending}]
    for stage in pending:
        if stage.name == "render" and not render:
            break
        run.note = (lambda message, name=stage.name: progress(name, message)) if progress else (lambda message: None)
        run.note("started")
        try:
            finished = stage.run(run)
            if finished:
                scene.done.append(stage.name)
        finally:
            run.saver.save()
        if not finished:
            break
        run.note("done")
    return scene


def _new_scene(text: str, style: str | None, seed: int, offline: bool) -> Scene:
    """A scene with the style (the flag, else the one the text names, else the default) and the
    ground kind the text names.

    With the offline model the ground kind comes from its parse of the text (the same parse
    the analysis stage uses, cached), which knows whether the objects stand indoors. With a
    remote model the offline parser does not run at all (it would cost time and could refuse
    a text the model reads well): the kind is read from the text's words alone.
    Made before the folder is touched, so bad input leaves nothing behind.
    """
    from scenewright.analysis.parser import _is_indoor, detect_ground, detect_style, parse_scene

    try:
        scene = Scene(text=text, seed=seed, **({"style": style.strip().lower()} if style and style.strip() else {}))
    except ValidationError as exc:
        raise InputError(describe_validation_error(exc)) from None
    if not (style and style.strip()):
        scene.style = detect_style(text)
    if offline:
        scene.ground.kind = parse_scene(text).ground
    else:
        scene.ground.kind = detect_ground(text, _is_indoor([], text, None))
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
    preview: str = "default",
    progress: Progress | None = None,
    room: str | None = "auto",
) -> Scene:
    """Make the scene ``text`` describes in ``folder``; resume it when the folder holds it already.

    ``room``: ``auto`` (a room when the text is indoor, docs/rooms.md), ``none``, or the floor
    as ``WxD`` or ``WxDxH`` metres."""
    from scenewright.analysis.parser.room import parse_room_option

    folder = as_folder(folder)
    room = room or "auto"
    parse_room_option(room)  # bad input fails before the folder is touched
    text = text.strip()
    if not text:
        raise InputError(
            "the text is empty; describe the scene, e.g. 'a cosy reading corner with an armchair'"
        )
    candidate = _new_scene(text, style, seed, offline=backends.vlm.name == "offline")
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
                scene, folder, backends=backends, settings=settings, render=render, preview=preview,
                progress=progress, room=room if fresh else None,
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
    preview: str = "default",
    progress: Progress | None = None,
) -> Scene:
    """Finish an interrupted scene: run only the stages it has not completed."""
    folder = as_folder(folder)
    with writing(folder, settings.lock_timeout):
        scene = folder.load()
        return run_stages(
            scene, folder, backends=backends, settings=settings, render=render, preview=preview, progress=progress
        )
