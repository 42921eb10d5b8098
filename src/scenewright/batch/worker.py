"""One scene of a batch, start to finish, in whatever process runs it (pool worker, Ray task).

:func:`run_scene` never raises for a scene's own failure: bad text, a backend error or an
unsatisfiable layout become an :class:`Outcome` with the reason, so one scene cannot stop the
others. A scene is *finished* when its ``scene_graph.json`` exists (written last, atomically)
and its document has every stage the batch asks for; a finished scene is not touched again,
a half-done one is resumed stage by stage by the pipeline.

Stopping: in a pool worker, SIGINT only sets a flag (:func:`init_worker`); the pipeline's
progress callback checks it at every step and the scene stops there, its document saved after
the last completed stage, so a re-run resumes it.
"""

from __future__ import annotations

import json
import logging
import signal
import threading
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from scenewright.batch.entries import Entry
from scenewright.errors import BackendError, InfeasibleLayout, InputError, ScenewrightError
from scenewright.settings import Settings

log = logging.getLogger(__name__)

GRAPH = "scene_graph.json"
_STOP = threading.Event()


class StopRequested(BaseException):
    """Raised from the progress callback once a stop was asked for (not an error of the scene)."""


def init_worker(log_level: int = logging.WARNING) -> None:
    """Pool worker start-up: Ctrl-C asks the current scene to stop at its next step."""
    logging.basicConfig(level=log_level, format="%(levelname)s %(name)s [%(processName)s]: %(message)s")
    signal.signal(signal.SIGINT, lambda *_: _STOP.set())


@dataclass(frozen=True)
class Job:
    """What a worker needs: the entry, the batch folder, settings, and the limits shared by all
    workers (a :class:`~scenewright.batch.limits.Limits`)."""

    entry: Entry
    out: Path
    settings: Settings
    render: bool = True
    limits: Any = None


@dataclass
class Outcome:
    id: str
    #: done (finished in this run), finished (already finished before it), failed, interrupted
    status: str
    line: int
    text: str
    #: the scene's style and seed (the style may come from the text)
    style: str | None = None
    seed: int = 0
    reason: str | None = None
    #: input (the text or entry), backend, layout, or crash (an unexpected exception)
    error: str | None = None
    objects: int = 0
    constraints_held: int = 0
    constraints: int = 0
    collision_free: bool | None = None
    unplaced: int = 0
    seconds: float = 0.0
    cpu_seconds: float = 0.0
    #: stages this run executed (empty for a finished scene)
    stages: list[str] = field(default_factory=list)

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def finished(folder: Path, render: bool) -> dict[str, Any] | None:
    """The scene graph of a finished scene in ``folder`` (None when it is not finished)."""
    graph = folder / GRAPH
    if not graph.is_file() or not (folder / "scene.json").is_file():
        return None
    try:
        done = json.loads((folder / "scene.json").read_text(encoding="utf-8")).get("done", [])
        data = json.loads(graph.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    from scenewright.pipeline import STAGES

    # A render that could not run (no Blender) leaves "render" out of done: still finished.
    if all(s in done for s in STAGES if s != "render") and ("render" in done or not render or data.get("unrendered")):
        return data
    return None


def _metrics(scene: Any, folder: Any) -> dict[str, Any]:
    from scenewright.assets import load_meshes
    from scenewright.evaluation.physical import physical
    from scenewright.evaluation.spatial import spatial

    held = spatial(scene)
    return {
        "objects": len(scene.objects),
        "constraints_held": held.satisfied,
        "constraints": held.total,
        "collision_free": physical(scene, load_meshes(scene, folder)).collision_free,
        "unplaced": len(scene.layout.unplaced) if scene.layout is not None else 0,
    }


def outcome(entry: Entry, status: str, metrics: dict[str, Any], **kw: Any) -> Outcome:
    keep = {k: metrics[k] for k in ("objects", "constraints_held", "constraints", "collision_free", "unplaced") if k in metrics}
    kw.setdefault("style", entry.style)
    return Outcome(id=entry.id, status=status, line=entry.line, text=entry.text, seed=entry.seed or 0, **keep, **kw)


def finished_outcome(entry: Entry, out: Path, render: bool) -> Outcome | None:
    """The record of an entry whose scene is already finished in ``out`` (None otherwise)."""
    graph = finished(Path(out) / entry.id, render)
    if graph is None:
        return None
    return outcome(entry, "finished", graph.get("metrics", {}), style=graph.get("style"))


def run_scene(job: Job) -> Outcome:
    """Make (or resume, or skip) the scene of ``job.entry`` in ``job.out/<id>``."""
    from scenewright.backends import backends_from_settings
    from scenewright.dataset import scene_graph
    from scenewright.folder import SceneFolder
    from scenewright.files import write_atomic
    from scenewright.pipeline import generate

    entry = job.entry
    start, cpu = time.perf_counter(), time.process_time()

    def timed(**kw: Any) -> dict[str, Any]:
        return {"seconds": round(time.perf_counter() - start, 3), "cpu_seconds": round(time.process_time() - cpu, 3), **kw}

    root = Path(job.out) / entry.id
    done = finished_outcome(entry, job.out, job.render)
    if done is not None:
        return done
    if _STOP.is_set():
        return outcome(entry, "interrupted", {}, reason="stopped before it started", **timed())
    stages: list[str] = []

    def progress(stage: str, message: str) -> None:
        if _STOP.is_set():
            raise StopRequested
        if message == "done":
            stages.append(stage)

    try:
        settings = entry.settings(job.settings)
        backends = backends_from_settings(settings)
        if job.limits is not None:
            from scenewright.batch.limits import share_limit

            share_limit(backends, job.limits)
        folder = SceneFolder(root)
        scene = generate(
            entry.text,
            folder,
            backends=backends,
            settings=settings,
            style=entry.style,
            seed=entry.seed or 0,
            render=job.render,
            progress=progress,
            room=entry.room,
        )
        metrics = _metrics(scene, folder)
        graph = scene_graph(scene, scene_id=entry.id, metrics=metrics)
        if job.render and "render" not in scene.done:
            graph["unrendered"] = "Blender (the render extra) is not installed"
        write_atomic(root / GRAPH, json.dumps(graph, indent=1) + "\n")
    except (StopRequested, KeyboardInterrupt):
        return outcome(entry, "interrupted", {}, reason="stopped; a re-run resumes it", stages=stages, **timed())
    except InputError as exc:
        return _failed(entry, "input", exc, stages, timed())
    except InfeasibleLayout as exc:
        return _failed(entry, "layout", exc, stages, timed())
    except (BackendError, ScenewrightError) as exc:
        return _failed(entry, "backend", exc, stages, timed())
    except Exception as exc:  # noqa: BLE001 - isolation: any crash of one scene is recorded, not raised
        log.exception("scene %s crashed", entry.id)
        return _failed(entry, "crash", exc, stages, timed(), prefix=f"{type(exc).__name__}: ")
    return outcome(entry, "done", metrics, stages=stages, style=scene.style, **timed())


def _failed(entry: Entry, kind: str, exc: BaseException, stages: list[str], times: dict, prefix: str = "") -> Outcome:
    log.info("scene %s failed (%s): %s", entry.id, kind, exc)
    return outcome(entry, "failed", {}, reason=f"{prefix}{exc}", error=kind, stages=stages, **times)
