"""Stored assets as meshes in the scene-frame asset frame, for the solver, export and evaluation.

Parsing a GLB costs more than anything else a stage does with it, and a run reads every
asset in three stages (checking it, laying it out, assembling ``scene.glb``, which copies
the file's bytes and parses nothing: :mod:`scenewright.export.glb`). An
:class:`AssetMeshes` made by the run and handed to each stage parses every file once: the
asset stage hands over the bytes it has just written, the later stages find them parsed.
It lives as long as its owner keeps it (a run, an edit, a studio session), never in the
module, so nothing outlives the caller or leaks between folders.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from scenewright.errors import InputError
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE
from scenewright.gltf import Glb, check_glb, glb_triangles
from scenewright.scene import Scene, SceneObject

if TYPE_CHECKING:
    import trimesh


class AssetMesh:
    """An asset's triangles in the scene-frame asset frame (bottom at z = 0, front −Y): all the
    solver, the collision checks and the editor ask of a mesh, without a mesh library's import
    (scipy and networkx come with it) on the path of every edit. :meth:`to_trimesh` gives the
    full mesh to what needs more (collision hulls)."""

    __slots__ = ("vertices", "faces", "_bounds", "__weakref__")

    def __init__(self, vertices: np.ndarray, faces: np.ndarray) -> None:
        self.vertices = np.asarray(vertices, dtype=float)
        self.faces = np.asarray(faces, dtype=np.int64)
        self._bounds: np.ndarray | None = None

    @property
    def bounds(self) -> np.ndarray:
        """(min corner, max corner) of the vertices."""
        if self._bounds is None:
            self._bounds = np.array([self.vertices.min(axis=0), self.vertices.max(axis=0)])
        return self._bounds

    @property
    def extents(self) -> np.ndarray:
        return self.bounds[1] - self.bounds[0]

    @property
    def triangles(self) -> np.ndarray:
        """(faces, 3 corners, xyz)."""
        return self.vertices[self.faces]

    def to_trimesh(self) -> trimesh.Trimesh:
        import trimesh

        return trimesh.Trimesh(self.vertices, self.faces, process=False)


def asset_mesh(glb: bytes) -> AssetMesh:
    """One mesh, bottom at z = 0, front −Y, from a normalised GLB (``ValueError`` saying why it
    is unreadable or holds no triangles).

    The triangles are read straight from the file's accessors (:func:`~scenewright.gltf.glb_triangles`):
    the solver, export and evaluation need geometry only, and a mesh library's loader builds
    materials, textures and a scene graph first, which cost several times the read.
    """
    problem = check_glb(glb)
    if problem:
        raise ValueError(problem)
    vertices, faces = glb_triangles(Glb.parse(glb))
    if not len(faces):
        raise ValueError("the GLB holds no triangles")
    if not np.isfinite(vertices).all():
        raise ValueError("the GLB has non-finite vertex coordinates")
    return AssetMesh(vertices @ GLTF_TO_SCENE[:3, :3].T + GLTF_TO_SCENE[:3, 3], faces)


@dataclass
class ParsedAsset:
    """One asset file: its bytes and its scene-frame mesh (:func:`asset_mesh`)."""

    data: bytes
    mesh: AssetMesh


def _parse(data: bytes) -> ParsedAsset:
    return ParsedAsset(data=data, mesh=asset_mesh(data))


class AssetMeshes:
    """Asset files parsed once, by (resolved path, mtime, size).

    Asset files are only ever replaced whole (atomic writes, or new content-addressed names),
    never rewritten in place, so a key stays true while the file is there; a replaced file
    has a new key and is parsed again. A file that does not parse is remembered as its error.
    """

    def __init__(self) -> None:
        self._parsed: dict[tuple[str, int, int], ParsedAsset | str] = {}
        self._data: dict[tuple[str, int, int], bytes] = {}

    @staticmethod
    def _key(path: Path) -> tuple[str, int, int]:
        stat = path.stat()
        return (str(path.resolve()), stat.st_mtime_ns, stat.st_size)

    def add(self, path: Path, data: bytes) -> ParsedAsset:
        """Take the bytes just written to ``path`` as that file's content, parsed now."""
        parsed = _parse(data)
        self._parsed[self._key(path)] = parsed
        return parsed

    def data(self, path: Path) -> bytes:
        """The asset file's bytes, read once (``FileNotFoundError`` when gone); not parsed, for
        what copies them (``scene.glb`` is spliced from them)."""
        key = self._key(path)
        found = self._parsed.get(key)
        if isinstance(found, ParsedAsset):
            return found.data
        if key not in self._data:
            self._data[key] = path.read_bytes()
        return self._data[key]

    def parsed(self, path: Path) -> ParsedAsset:
        """The asset file at ``path`` (``FileNotFoundError`` when gone, ``ValueError`` saying why
        it is not a usable GLB)."""
        key = self._key(path)
        if key not in self._parsed:
            try:
                self._parsed[key] = _parse(self._data.pop(key, None) or path.read_bytes())
            except ValueError as exc:
                self._parsed[key] = str(exc)
        found = self._parsed[key]
        if isinstance(found, str):
            raise ValueError(found)
        return found

    def problem(self, obj: SceneObject, folder: SceneFolder) -> str | None:
        """Why ``obj``'s stored asset cannot be used (none, missing, empty, corrupt, no triangles),
        or ``None`` when it can; a path the document should not name is an InputError."""
        path = folder.asset_of(obj)
        if path is None:
            return "it has no asset"
        try:
            self.parsed(path)
        except FileNotFoundError:
            return f"its asset {obj.asset} is missing"
        except ValueError as exc:
            return f"its asset {obj.asset} is not a usable GLB ({exc})"
        return None

    def of(self, scene: Scene, folder: SceneFolder, skip: frozenset[str] | set[str] = frozenset()) -> dict[str, AssetMesh]:
        """Each object's asset mesh by id; objects without an asset (boxes stand in) and those in
        ``skip`` are left out. A missing or broken file is an InputError saying how to mend it."""
        meshes: dict[str, AssetMesh] = {}
        for obj in scene.objects:
            path = folder.asset_of(obj)
            if path is None or obj.id in skip:
                continue
            try:
                meshes[obj.id] = self.parsed(path).mesh
            except FileNotFoundError:
                raise InputError(
                    f"object {obj.id!r}: its asset {obj.asset} is missing from {folder.root}; "
                    f"re-run `scenewright generate --resume {folder.root}` to rebuild it"
                ) from None
            except ValueError as exc:
                raise InputError(f"object {obj.id!r}: its asset {path} is not a usable GLB: {exc}") from None
        return meshes


def load_meshes(scene: Scene, folder: SceneFolder, store: AssetMeshes | None = None) -> dict[str, AssetMesh]:
    """Each object's asset by id (see :meth:`AssetMeshes.of`), parsed by ``store`` when given."""
    return (store or AssetMeshes()).of(scene, folder)
