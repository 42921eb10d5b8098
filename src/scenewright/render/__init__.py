"""Preview renders of a scene with Blender (Cycles on the CPU), run in a subprocess.

:func:`render` writes a job file, runs :mod:`scenewright.render.worker` (the only module that
imports ``bpy``) with the same interpreter, and reads its result file, so a missing or crashing
Blender never takes the caller down. Renders land in ``renders/<view>.png``; ``renders/renders.json``
records which view was chosen and how many pixels of each object every candidate view shows.

The worker works in a temporary folder only (its images, its own temporary files); this
process copies the images into the scene folder once the worker has succeeded, so a worker
that outlives a stopped run could never write there. It does not outlive it: it runs in its
own session (Ctrl-C reaches this process, which kills it and removes the temporary folder),
and on Linux the kernel kills it when this process dies, however it dies.
"""

from __future__ import annotations

import ctypes
import importlib.util
import json
import logging
import os
import signal
import subprocess
import sys
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from scenewright.core.styles import find_look
from scenewright.errors import BackendError, InputError, MissingExtra
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder, as_folder
from scenewright.geometry import object_matrix, world_box
from scenewright.render.views import VIEWS, cut_away, object_weights
from scenewright.scene import WATER_LEVEL, Scene
from scenewright.settings import Settings

if TYPE_CHECKING:
    from scenewright.assets.load import AssetMeshes

log = logging.getLogger(__name__)

DEFAULT_VIEWS = tuple(VIEWS)


@dataclass(frozen=True)
class Preview:
    """A render quality: picture size, Cycles samples per pixel (before the denoiser), the
    light-path bounces each ray may take (total, diffuse, glossy), OpenImageDenoise's quality
    (FAST, BALANCED or HIGH), and how its albedo and normal guides are cleaned first (FAST takes
    them as they are, ACCURATE denoises each of them too: two more denoiser runs)."""

    resolution: tuple[int, int]
    samples: int
    bounces: tuple[int, int, int]
    denoise: str
    prefilter: str


#: The render qualities ``--preview`` names; docs/rendering.md tells how they were chosen.
PREVIEWS = {
    "draft": Preview((480, 270), 2, (2, 1, 1), "FAST", "FAST"),
    "default": Preview((1280, 720), 2, (3, 1, 1), "BALANCED", "FAST"),
    "final": Preview((1920, 1080), 64, (8, 4, 4), "HIGH", "ACCURATE"),
}
DEFAULT_TIMEOUT = 900.0
METADATA = "renders.json"


def scene_bounds(scene: Scene) -> tuple[list[float], list[float]]:
    """The box holding every object and the scene's footprint, which the ground and lamps cover."""
    if not scene.objects:
        raise InputError("the scene has no objects to render; add some with `scenewright edit`")
    boxes = [world_box(obj) for obj in scene.objects]
    low = np.min([b[0] for b in boxes], axis=0)
    high = np.max([b[1] for b in boxes], axis=0)
    if scene.bounds is not None:
        width, depth = scene.bounds
        low = np.minimum(low, [-width / 2.0, -depth / 2.0, 0.0])
        high = np.maximum(high, [width / 2.0, depth / 2.0, 0.0])
    if scene.room is not None:
        floor = np.asarray(scene.room.floor, float)
        low[:2] = np.minimum(low[:2], floor.min(axis=0))
        high[:2] = np.maximum(high[:2], floor.max(axis=0))
    low[2] = min(low[2], 0.0)
    return low.tolist(), high.tolist()


#: Corners of the normalised asset box (footprint centred, bottom at z = 0) in units of its size.
_UNIT_BOX = np.array([[x, y, z, 1.0] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (0.0, 1.0)])


def object_corners(scene: Scene) -> list[list[float]]:
    """The eight corners of every object's posed size box: the points each camera frames.

    The posed boxes rather than their axis-aligned hulls, so a turned object does not widen
    the shot by its hull's empty corners.
    """
    if not scene.objects:
        raise InputError("the scene has no objects to render; add some with `scenewright edit`")
    return np.concatenate(list(box_corners(scene).values())).tolist()


def box_corners(scene: Scene) -> dict[str, np.ndarray]:
    """Each object's eight posed box corners (8×3) by id."""
    return {obj.id: ((_UNIT_BOX * [*obj.size.tuple(), 1.0]) @ object_matrix(obj).T)[:, :3] for obj in scene.objects}


def view_weights(scene: Scene) -> dict[str, float]:
    """How much showing each object matters to the view choice (see
    :func:`scenewright.render.views.object_weights`): its size and the relations it is in."""
    relations = {obj.id: 0 for obj in scene.objects}
    for c in scene.constraints:
        for end in (c.source, c.target):
            if end in relations:
                relations[end] += 1
    return object_weights({obj.id: obj.size.tuple() for obj in scene.objects}, relations)


def _ground_texture(scene: Scene, folder: SceneFolder) -> str | None:
    named = folder.ground_texture(scene)
    candidates = [named, folder.ground_image] if named is not None else [folder.ground_image]
    return next((str(p.resolve()) for p in candidates if p.is_file()), None)


#: With a room, the worker's ground lies this far under the floor slab's underside.
ROOM_GROUND_GAP = 0.01


def _ground_and_room(scene: Scene, folder: SceneFolder, views: Sequence[str]) -> dict:
    """The worker's ground, and per view the room nodes it leaves out. A room's floor is the
    ground inside; outside it the worker's ground is plain and sits under the floor slab, so
    the two never fight for the same pixels."""
    if scene.room is None:
        water = scene.ground.water
        return {"ground_texture": _ground_texture(scene, folder), "ground_kind": scene.ground.kind,
                **({"water": {"shore": water.shore, "level": WATER_LEVEL}} if water is not None else {})}
    from scenewright.procedural.room import FLOOR_THICKNESS

    return {
        "ground_texture": None,
        "ground_kind": "",
        "ground_z": -FLOOR_THICKNESS - ROOM_GROUND_GAP,
        "hidden": {view: cut_away(scene.room, view) for view in views},
    }


def check_renderable(scene: Scene, folder: SceneFolder, meshes: AssetMeshes | None = None) -> None:
    """Refuse a folder whose assets or ``scene.glb`` are missing, empty or corrupt: a render of
    it would show something other than the scene, or nothing at all. ``meshes`` holds the
    assets the caller has parsed already."""
    from scenewright.assets.load import AssetMeshes
    from scenewright.assets.normalise import check_glb

    store = meshes if meshes is not None else AssetMeshes()
    broken = [
        f"{obj.id} ({problem})"
        for obj in scene.objects
        if obj.asset is not None and (problem := store.problem(obj, folder))
    ]
    if not folder.glb.is_file():
        broken.append(f"{folder.glb.name} (missing)")
    elif (problem := check_glb(folder.glb.read_bytes())) is not None:
        broken.append(f"{folder.glb.name} ({problem})")
    if broken:
        raise InputError(
            f"cannot render {folder.root}: {'; '.join(broken)}; rebuild them with "
            f"`scenewright generate --resume {folder.root}`"
        )


def check_render_size(resolution: tuple[int, int], samples: int, max_pixels: int, max_samples: int) -> None:
    """Resolution and samples within what a preview needs, so one flag cannot run Blender for days."""
    width, height = resolution
    if min(resolution) < 16 or samples < 1:
        raise InputError(f"resolution {width}x{height} and samples {samples}: need at least 16x16 pixels and 1 sample")
    if width * height > max_pixels:
        raise InputError(
            f"resolution {width}x{height} has {width * height:,} pixels, more than max_render_pixels "
            f"({max_pixels:,}); lower --resolution or raise max_render_pixels in the config"
        )
    if samples > max_samples:
        raise InputError(
            f"{samples} samples is more than max_render_samples ({max_samples}); "
            "lower --samples or raise max_render_samples in the config"
        )


def render(
    scene: Scene,
    folder: SceneFolder | str | Path,
    *,
    views: Sequence[str] = DEFAULT_VIEWS,
    keep_all: bool = False,
    preview: str = "default",
    resolution: tuple[int, int] | None = None,
    samples: int | None = None,
    draft: bool = False,
    transparent: bool = False,
    timeout: float = DEFAULT_TIMEOUT,
    max_pixels: int = Settings.max_render_pixels,
    max_samples: int = Settings.max_render_samples,
    meshes: AssetMeshes | None = None,
) -> list[Path]:
    """Render the scene from the candidate views; return the chosen view first (all when ``keep_all``).

    ``preview`` names a quality of :data:`PREVIEWS` (``draft=True`` is ``preview="draft"``);
    ``resolution`` and ``samples`` override its size and samples.
    """
    folder = as_folder(folder)
    unknown = [v for v in views if v not in VIEWS]
    if unknown or not views:
        raise InputError(f"unknown view(s) {unknown or views!r}; views are {', '.join(VIEWS)}")
    if draft:
        preview = "draft"
    if preview not in PREVIEWS:
        raise InputError(f"unknown preview quality {preview!r}; choose {', '.join(PREVIEWS)}")
    quality = PREVIEWS[preview]
    resolution = tuple(resolution) if resolution is not None else quality.resolution
    samples = samples if samples is not None else quality.samples
    check_render_size(resolution, samples, max_pixels, max_samples)
    if not folder.glb.is_file():
        raise InputError(f"{folder.glb} does not exist; build the scene with `scenewright generate` first")
    check_renderable(scene, folder, meshes)
    if importlib.util.find_spec("bpy") is None:
        raise MissingExtra("Rendering", "render", "bpy")
    low, high = scene_bounds(scene)
    frame = object_corners(scene)
    with tempfile.TemporaryDirectory(prefix="scenewright-render-") as tmp:
        job = {
            "glb": str(folder.glb.resolve()),
            "ids": [obj.id for obj in scene.objects],
            "bounds": [low, high],
            "frame": frame,
            "boxes": {oid: box.tolist() for oid, box in box_corners(scene).items()},
            "weights": view_weights(scene),
            "style": look.lit if (look := find_look(scene.style)) else "realistic",  # a named look lights as its base
            **_ground_and_room(scene, folder, views),
            "views": list(views),
            "keep_all": keep_all,
            "resolution": [int(resolution[0]), int(resolution[1])],
            "samples": int(samples),
            "bounces": list(quality.bounces),
            "denoise_quality": quality.denoise,
            "denoise_prefilter": quality.prefilter,
            "denoise": True,
            "transparent": transparent,
            "out_dir": str(Path(tmp) / "renders"),
            "result": str(Path(tmp) / "result.json"),
        }
        job_path = write_atomic(Path(tmp) / "job.json", json.dumps(job))
        result = _run_worker(job_path, Path(job["result"]), timeout)
        result["images"] = {
            view: str(write_atomic(folder.renders / f"{view}.png", Path(made).read_bytes()))
            for view, made in result["images"].items()
        }
    images = [Path(result["images"][v]) for v in result["images"]]
    for view in VIEWS:  # a previous keep-all run's other views would now be stale
        stale = folder.renders / f"{view}.png"
        if view not in result["images"] and stale.exists():
            stale.unlink()
    result["images"] = {v: folder.relative(Path(p)) for v, p in result["images"].items()}
    result.update(resolution=job["resolution"], samples=job["samples"], preview=preview, draft=preview == "draft",
                  transparent=transparent)
    write_atomic(folder.renders / METADATA, json.dumps(result, indent=2) + "\n")
    log.info("rendered %s in %.1f s (best view %s)", [p.name for p in images], result["total_seconds"], result["best"])
    return images


def render_again(scene: Scene, folder: SceneFolder | str | Path) -> list[Path]:
    """Refresh the previews as the last render made them (size, samples, one view or all), so
    they show the scene as it is now, e.g. after an edit."""
    info = render_info(folder) or {}
    preview = info.get("preview") if info.get("preview") in PREVIEWS else ("draft" if info.get("draft") else "default")
    return render(
        scene,
        folder,
        keep_all=len(info.get("images", {})) > 1,
        preview=preview,
        resolution=tuple(info.get("resolution", PREVIEWS[preview].resolution)),
        samples=int(info.get("samples", PREVIEWS[preview].samples)),
        transparent=bool(info.get("transparent", False)),
    )


#: prctl(2) option: the signal the kernel sends a process when the thread that started it dies.
PR_SET_PDEATHSIG = 1


def _dies_with_parent() -> Callable[[], None] | None:
    """A function for the worker to run between fork and exec, on Linux: have the kernel SIGKILL
    it when this process dies (even by SIGKILL, which runs no cleanup). None elsewhere."""
    if not sys.platform.startswith("linux"):
        return None
    try:
        prctl = ctypes.CDLL(None, use_errno=True).prctl  # looked up before the fork, not in it
    except (OSError, AttributeError):
        return None
    parent = os.getpid()

    def arrange() -> None:
        prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        if os.getppid() != parent:  # the parent died before the request took effect
            os._exit(1)

    return arrange


def start_worker(command: Sequence[str], workdir: Path) -> subprocess.Popen:
    """Start ``command`` as a worker tied to this process, its temporary files in ``workdir``."""
    return subprocess.Popen(
        list(command),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "TMPDIR": str(workdir)},
        start_new_session=True,  # the terminal's Ctrl-C goes to this process, which ends it
        preexec_fn=_dies_with_parent(),
    )


def _run_worker(job_path: Path, result_path: Path, timeout: float) -> dict:
    command = [sys.executable, "-m", "scenewright.render.worker", str(job_path)]
    process = start_worker(command, job_path.parent)
    try:
        stdout, stderr = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        process.kill()
        process.communicate()
        raise BackendError(f"Blender did not finish rendering within {timeout:.0f} s; lower --samples or --resolution") from None
    except BaseException:  # Ctrl-C: no worker left behind, and its folder goes with the caller's
        process.kill()
        process.wait()
        raise
    if process.returncode != 0 or not result_path.is_file():
        tail = "\n".join((stderr or stdout).strip().splitlines()[-15:])
        raise BackendError(f"Blender render failed (exit code {process.returncode}):\n{tail}")
    log.debug("blender output:\n%s", stdout[-4000:])
    return json.loads(result_path.read_text(encoding="utf-8"))


def render_info(folder: SceneFolder | str | Path) -> dict | None:
    """What the last render of the folder recorded (chosen view, visibility, timings), if any.

    The file is checked as the document is: a broken one is an InputError saying how to make
    it again, and the paths it names must be renders inside the folder.
    """
    folder = as_folder(folder)
    path = folder.renders / METADATA
    if not path.is_file():
        return None
    folder.check()
    try:
        info = json.loads(path.read_text(encoding="utf-8"))
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise _broken(path, f"not valid JSON ({exc})") from None
    if not isinstance(info, dict) or not isinstance(info.get("images"), dict) or not isinstance(info.get("best"), str):
        raise _broken(path, "it needs an 'images' table and a 'best' view")
    for view, image in info["images"].items():
        folder.resolve(image, f"renders/{METADATA} images.{view}", "image")
    for key, kind in (("resolution", list), ("samples", int)):
        if key in info and not isinstance(info[key], kind):
            raise _broken(path, f"{key} is {info[key]!r}")
    if "resolution" in info and (len(info["resolution"]) != 2 or not all(isinstance(v, int) for v in info["resolution"])):
        raise _broken(path, f"resolution is {info['resolution']!r}")
    return info


def _broken(path: Path, why: str) -> InputError:
    return InputError(f"{path} is broken: {why}; delete it and render again with `scenewright render {path.parent.parent}`")


def best_render(folder: SceneFolder | str | Path) -> Path | None:
    """The preview the last render chose, for judging and CLIP scoring."""
    folder = as_folder(folder)
    info = render_info(folder)
    if info is None or info["best"] not in info["images"]:
        return None
    path = folder.resolve(info["images"][info["best"]], f"renders/{METADATA} images.{info['best']}", "image")
    return path if path.is_file() else None
