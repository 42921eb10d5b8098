"""Stored assets as meshes in the scene-frame asset frame, for the solver, export and evaluation.

Parsing a GLB costs more than anything else a stage does with it, and a run reads every
asset in three stages (checking it, laying it out, assembling ``scene.glb``). An
:class:`AssetMeshes` made by the run and handed to each stage parses every file once: the
asset stage hands over the bytes it has just written, the later stages find them parsed.
It lives as long as its owner keeps it (a run, an edit, a studio session), never in the
module, so nothing outlives the caller or leaks between folders.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh

from scenewright.assets.normalise import parse_glb
from scenewright.errors import InputError
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE
from scenewright.gltf import mesh_materials
from scenewright.scene import Scene, SceneObject


def scene_mesh(asset: trimesh.Scene) -> trimesh.Trimesh:
    """The triangles of a parsed asset as one mesh in the scene frame, geometry only.

    The same vertices and faces, in the same order, as trimesh's ``to_mesh`` followed by the
    frame change, without merging the materials and textures, which no geometric user needs
    and which cost five times the parse.
    """
    vertices, faces, count = [], [], 0
    for node in asset.graph.nodes_geometry:
        matrix, name = asset.graph[node]
        geom = asset.geometry[name]
        transform = GLTF_TO_SCENE @ matrix
        vertices.append(trimesh.transform_points(np.asarray(geom.vertices, dtype=float), transform))
        tri = np.asarray(geom.faces, dtype=np.int64)
        if np.linalg.det(transform[:3, :3]) < 0:  # a mirroring node turns the winding over
            tri = tri[:, ::-1]
        faces.append(tri + count)
        count += len(geom.vertices)
    return trimesh.Trimesh(np.concatenate(vertices), np.concatenate(faces), process=False)


def asset_mesh(glb: bytes) -> trimesh.Trimesh:
    """One mesh, bottom at z = 0, front −Y, from a normalised GLB (``ValueError`` when unreadable)."""
    return scene_mesh(parse_glb(glb))


@dataclass
class ParsedAsset:
    """One asset file, parsed: its glTF-frame scene as stored and its bytes; its scene-frame mesh
    and its exact glTF materials (for :mod:`scenewright.export.glb`) are made on first use."""

    asset: trimesh.Scene
    data: bytes
    _mesh: trimesh.Trimesh | None = None

    @property
    def mesh(self) -> trimesh.Trimesh:
        if self._mesh is None:
            self._mesh = scene_mesh(self.asset)
        return self._mesh

    def materials(self) -> dict[str, dict]:
        """The file's own material of each mesh by name (``ValueError`` when its JSON is not plain
        glTF JSON); trimesh's copy is rounded and loses extensions."""
        return mesh_materials(self.data)


def _parse(data: bytes) -> ParsedAsset:
    return ParsedAsset(asset=parse_glb(data), data=data)


class AssetMeshes:
    """Asset files parsed once, by (resolved path, mtime, size).

    Asset files are only ever replaced whole (atomic writes, or new content-addressed names),
    never rewritten in place, so a key stays true while the file is there; a replaced file
    has a new key and is parsed again. A file that does not parse is remembered as its error.
    """

    def __init__(self) -> None:
        self._parsed: dict[tuple[str, int, int], ParsedAsset | str] = {}

    @staticmethod
    def _key(path: Path) -> tuple[str, int, int]:
        stat = path.stat()
        return (str(path.resolve()), stat.st_mtime_ns, stat.st_size)

    def add(self, path: Path, data: bytes) -> ParsedAsset:
        """Take the bytes just written to ``path`` as that file's content, parsed now."""
        parsed = _parse(data)
        self._parsed[self._key(path)] = parsed
        return parsed

    def parsed(self, path: Path) -> ParsedAsset:
        """The asset file at ``path`` (``FileNotFoundError`` when gone, ``ValueError`` saying why
        it is not a usable GLB)."""
        key = self._key(path)
        if key not in self._parsed:
            try:
                self._parsed[key] = _parse(path.read_bytes())
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

    def of(self, scene: Scene, folder: SceneFolder, skip: frozenset[str] | set[str] = frozenset()) -> dict[str, trimesh.Trimesh]:
        """Each object's asset mesh by id; objects without an asset (boxes stand in) and those in
        ``skip`` are left out. A missing or broken file is an InputError saying how to mend it."""
        meshes: dict[str, trimesh.Trimesh] = {}
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


def load_meshes(scene: Scene, folder: SceneFolder, store: AssetMeshes | None = None) -> dict[str, trimesh.Trimesh]:
    """Each object's asset by id (see :meth:`AssetMeshes.of`), parsed by ``store`` when given."""
    return (store or AssetMeshes()).of(scene, folder)
