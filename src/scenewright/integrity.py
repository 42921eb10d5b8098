"""A scene folder made whole again after a run that died part way, before anything writes to it.

``scene.json`` is the commit point of every change: files it names are written first, the
document last. A run killed in between leaves files the document does not account for:

- ``scene.glb`` newer than the document: the document records the hash of the GLB it was
  assembled into, so a GLB that does not match is rebuilt from the document;
- temporary files of atomic writes that never got their rename: stale, removed — except a
  complete first ``scene.json``, whose rename is finished, so the folder resumes;
- an edit's history not yet written after its document: see
  :func:`scenewright.editing.history.recover`.

Only a command that holds the folder's lock (:mod:`scenewright.lock`) may call these: a
temporary file of a writer that is still running is not stale.
"""

from __future__ import annotations

import hashlib
import logging
import os
import re
from pathlib import Path

from scenewright.assets.load import AssetMeshes
from scenewright.errors import InputError
from scenewright.export import assemble
from scenewright.folder import SceneFolder
from scenewright.scene import Scene

log = logging.getLogger(__name__)

#: The temporary files :func:`scenewright.files.write_atomic` makes: ``.<name>.<8 random>.tmp``.
_TEMPORARY = re.compile(r"^\..+\.[a-z0-9_]{8}\.tmp$")


def file_sha256(path: Path) -> str | None:
    """The file's SHA-256, or ``None`` when there is no such file."""
    try:
        return hashlib.sha256(Path(path).read_bytes()).hexdigest()
    except FileNotFoundError:
        return None


def assemble_recorded(scene: Scene, folder: SceneFolder, meshes: AssetMeshes | None = None) -> Path:
    """Write ``scene.glb`` from ``scene`` and record its hash in ``scene`` (the caller saves it);
    ``meshes`` holds the assets the caller has parsed already."""
    path = assemble(scene, folder, meshes)
    scene.glb_sha256 = file_sha256(path)
    return path


def glb_matches(scene: Scene, folder: SceneFolder) -> bool:
    """Whether ``scene.glb`` is the one ``scene`` was assembled into."""
    return scene.glb_sha256 is not None and file_sha256(folder.glb) == scene.glb_sha256


def temporaries(folder: SceneFolder) -> list[Path]:
    """Temporary files of atomic writes in the folder and its sub-folders of known kinds."""
    places = (folder.root, folder.history, folder.assets, folder.images, folder.object_images, folder.renders)
    found = []
    for place in places:
        if place.is_dir() and not place.is_symlink():
            found += [p for p in place.iterdir() if _TEMPORARY.match(p.name) and p.is_file()]
    return found


def finish_first_save(folder: SceneFolder) -> bool:
    """Complete the rename of a first ``scene.json`` written in full by a run killed before it.

    Returns whether the folder now holds a document it did not before.
    """
    if folder.document.exists():
        return False
    pending = sorted(folder.root.glob(f".{folder.document.name}.*.tmp"), key=lambda p: p.stat().st_mtime, reverse=True)
    for candidate in pending:
        try:
            Scene.load(candidate)
        except InputError:
            continue  # cut short mid-write: nothing to finish
        os.replace(candidate, folder.document)
        log.warning("finished saving %s, which an interrupted run had written but not renamed", folder.document)
        return True
    return False


def remove_temporaries(folder: SceneFolder) -> None:
    for path in temporaries(folder):
        log.info("removing %s, left by an interrupted run", path)
        path.unlink(missing_ok=True)


def rebuild_glb(folder: SceneFolder) -> bool:
    """Assemble ``scene.glb`` again when it is not the one the document records; save the
    document only when the rebuilt file's hash differs from the recorded one (a different
    trimesh writes other bytes). Returns whether it rebuilt."""
    if not folder.is_scene():
        return False
    scene = folder.load()
    if scene.glb_sha256 is None or glb_matches(scene, folder):
        return False
    recorded = scene.glb_sha256
    try:
        assemble_recorded(scene, folder)
    except InputError as exc:  # assets missing: resuming the scene builds them, then the GLB
        log.warning("scene.glb does not match scene.json and cannot be rebuilt yet: %s", exc)
        return False
    log.warning("rebuilt %s: it did not match %s (a run was interrupted)", folder.glb, folder.document)
    if scene.glb_sha256 != recorded:
        folder.save(scene)
    return True
