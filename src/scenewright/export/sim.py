"""``scenewright export``: the scene in a simulator's or engine's format, with physics.

One table names the formats, each with its default file under the folder's ``sim/`` and the
function writing it; every format first derives the objects' physical properties
(:func:`scenewright.export.physics.ensure_physics`), cached, so exporting twice is cheap.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from scenewright.cache import RequestCache
from scenewright.errors import InputError
from scenewright.export.colliders import Collider
from scenewright.export.physics import ensure_physics
from scenewright.folder import SceneFolder
from scenewright.scene import Scene

log = logging.getLogger(__name__)


def _usd(scene, folder, pieces, path, engine):
    from scenewright.export.usd import write_usd

    return write_usd(scene, folder, pieces, path)


def _pxr() -> None:
    from scenewright.export.usd import load_pxr

    load_pxr()


def _mjcf(scene, folder, pieces, path, engine):
    from scenewright.export.mjcf import build_mjcf

    return build_mjcf(scene, folder, pieces).write(path)


def _glb(scene, folder, pieces, path, engine):
    from scenewright.export.glb_physics import write_glb_physics

    return write_glb_physics(scene, folder, pieces, path, engine)


@dataclass(frozen=True)
class Format:
    default: str
    write: Callable[[Scene, SceneFolder, dict[str, Collider], Path, str], Path]
    describe: str
    #: Raises MissingExtra when the format's optional package is not installed.
    requires: Callable[[], None] = lambda: None


FORMATS: dict[str, Format] = {
    "usd": Format("scene.usd", _usd, "USD with UsdPhysics rigid bodies and colliders (Isaac Sim, usdview)", _pxr),
    "mjcf": Format("mjcf/scene.xml", _mjcf, "MJCF for MuJoCo, meshes beside it"),
    "glb-physics": Format("scene-physics.glb", _glb, "GLB with Godot or Unreal collider nodes"),
}


def check_format(name: str) -> Format:
    if name not in FORMATS:
        raise InputError(f"unknown export format {name!r}; valid formats: {', '.join(FORMATS)}")
    return FORMATS[name]


def export_scene(
    scene: Scene,
    folder: SceneFolder,
    fmt: str,
    cache: RequestCache,
    *,
    out: Path | None = None,
    engine: str = "godot",
) -> Path:
    """Write ``scene`` in format ``fmt`` (to ``out``, else its default under ``sim/``); return the path."""
    from scenewright.export.glb_physics import ENGINES

    chosen = check_format(fmt)
    if engine not in ENGINES:
        raise InputError(f"unknown engine {engine!r} for glb-physics; valid engines: {', '.join(ENGINES)}")
    chosen.requires()
    pieces = ensure_physics(scene, folder, cache)
    path = chosen.write(scene, folder, pieces, Path(out) if out else folder.simulation / chosen.default, engine)
    log.info("exported %s to %s", fmt, path)
    return path
