"""Bring any backend's GLB to the stored asset convention.

Image-to-3D models, asset libraries and the procedural generator all hand back meshes at
arbitrary scale and offset. The rest of scenewright relies on one convention (docs/architecture.md, "Frames and units"):
glTF axes (+Y up, front +Z), footprint centred at the origin, bottom at y = 0, height equal
to the object's requested height. Like the paper, the rescale is uniform and uses the
height only, so a generated sofa keeps its proportions and the document learns its real
width and depth from the mesh.

A GLB that is in the convention already (the procedural generator builds each object to its
box) is stored as it came, read with numpy alone: re-baking it would move no vertex by more
than float32 rounding, and would cost the mesh library's import (most of a small scene's run).
"""

from __future__ import annotations

import io
import logging
from typing import TYPE_CHECKING

import numpy as np

from scenewright.errors import BackendError, MissingExtra
from scenewright.gltf import Glb, check_glb, glb_triangles, keep_materials, mesh_materials  # check_glb: also the backends'
from scenewright.scene import Vec3

if TYPE_CHECKING:
    import trimesh

log = logging.getLogger(__name__)

#: A footprint side never written smaller than this (a flat picture still needs a positive size).
MIN_SIDE = 0.001
#: Relative to the height: how far a GLB may be off the convention (float32 rounding of a
#: mesh built to its box) and still be stored as it came.
IN_CONVENTION = 1e-6


def stored_glb(
    glb: bytes, size: Vec3, *, name: str, backend: str, max_faces: int | None = None
) -> tuple[bytes, Vec3]:
    """The asset's GLB in the convention and its new size (as :func:`normalise` and
    :func:`to_glb` make them); a GLB in the convention already is kept byte for byte."""
    kept = _in_convention(glb, size, max_faces)
    if kept is not None:
        return glb, kept
    scene, new_size = normalise(glb, size, name=name, backend=backend, max_faces=max_faces)
    return to_glb(scene, source=glb), new_size


def _in_convention(glb: bytes, size: Vec3, max_faces: int | None) -> Vec3 | None:
    """The size of a GLB that needs no normalising: one self-contained buffer, triangles only,
    centred on the footprint, standing on y = 0 and ``size.z`` tall (within
    :data:`IN_CONVENTION`), no more faces than ``max_faces``; else ``None``."""
    if check_glb(glb) is not None:
        return None
    try:
        parsed = Glb.parse(glb)
        tree = parsed.tree
        if any("uri" in item for key in ("buffers", "images") for item in tree.get(key, [])):
            return None
        if any(p.get("mode", 4) != 4 for mesh in tree.get("meshes", []) for p in mesh.get("primitives", [])):
            return None  # points and lines are dropped by normalising
        vertices, faces = glb_triangles(parsed)
    except (ValueError, KeyError, TypeError, AttributeError):
        return None
    if not len(faces) or not np.isfinite(vertices).all() or (max_faces is not None and len(faces) > max_faces):
        return None
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    slack = IN_CONVENTION * max(size.z, 1e-9)
    off = max(abs(hi[1] - lo[1] - size.z), abs(lo[1]), abs(lo[0] + hi[0]) / 2.0, abs(lo[2] + hi[2]) / 2.0)
    if not off <= slack:
        return None
    return Vec3(x=max(float(hi[0] - lo[0]), MIN_SIDE), y=max(float(hi[2] - lo[2]), MIN_SIDE), z=size.z)


def mesh_library():
    """trimesh, imported with Ctrl-C held back until the import is done: trimesh wraps its
    optional imports in ``except BaseException``, so a Ctrl-C landing during its import was
    swallowed and the run went on waiting for its jobs."""
    import sys
    import threading

    if "trimesh" in sys.modules or threading.current_thread() is not threading.main_thread():
        import trimesh

        return trimesh
    import signal

    caught: list[int] = []
    previous = signal.signal(signal.SIGINT, lambda number, frame: caught.append(number))
    try:
        import trimesh
    finally:
        signal.signal(signal.SIGINT, previous)
    if caught:
        raise KeyboardInterrupt
    return trimesh


def parse_glb(data: bytes) -> trimesh.Scene:
    """The triangle meshes of a GLB as a scene; ``ValueError`` saying why when there are none."""
    trimesh = mesh_library()
    problem = check_glb(data)
    if problem:
        raise ValueError(problem)
    try:
        scene = trimesh.load(io.BytesIO(data), file_type="glb", force="scene", process=False)
    except Exception as exc:  # trimesh raises many kinds on malformed files
        raise ValueError(f"unreadable GLB ({type(exc).__name__}: {exc})") from None
    others = [name for name, geom in scene.geometry.items() if not isinstance(geom, trimesh.Trimesh)]
    if others:
        # Point clouds and paths carry no surface; keeping them would skew the bounds.
        scene.delete_geometry(others)
    meshes = [geom for geom in scene.geometry.values() if len(geom.faces)]
    if not meshes:
        raise ValueError("the GLB holds no triangles")
    if not all(np.isfinite(geom.vertices).all() for geom in meshes):
        raise ValueError("the GLB has non-finite vertex coordinates")
    return scene


def normalise(
    glb: bytes, size: Vec3, *, name: str, backend: str, max_faces: int | None = None
) -> tuple[trimesh.Scene, Vec3]:
    """The asset in glTF convention, sitting on y = 0, centred, ``size.z`` tall; and its new size.

    The returned size keeps the requested height and carries the mesh's own width (x) and
    depth (y, scene frame) after the uniform rescale. ``max_faces`` reduces heavy meshes.
    """
    try:
        scene = parse_glb(glb)
    except ValueError as exc:
        raise BackendError(f"the {backend} mesh for {name!r} is invalid: {exc}") from None
    if max_faces is not None:
        reduce_faces(scene, max_faces)  # first: decimation moves the extremes a little
    lo, hi = scene.bounds
    height = float(hi[1] - lo[1])
    if not height > 1e-9 * max(1.0, float(np.max(hi - lo))):
        raise BackendError(
            f"the {backend} mesh for {name!r} is flat (no height along glTF +Y), "
            "so it cannot be scaled to the object's height"
        )
    scale = size.z / height
    centre = np.array([(lo[0] + hi[0]) / 2.0, lo[1], (lo[2] + hi[2]) / 2.0])
    transform = np.diag([scale, scale, scale, 1.0])
    transform[:3, 3] = -centre * scale
    scene = baked(scene, transform)
    ext = scene.extents
    new_size = Vec3(x=max(float(ext[0]), MIN_SIDE), y=max(float(ext[2]), MIN_SIDE), z=size.z)
    log.debug("normalised %s from %s: scale %.4g, size %s", name, backend, scale, new_size.tuple())
    return scene, new_size


def baked(scene: trimesh.Scene, transform: np.ndarray) -> trimesh.Scene:
    """One node per mesh with ``transform`` applied to the vertices themselves.

    Scene-graph transforms are not used because trimesh snaps a node matrix that is close
    to the identity to exactly the identity, which loses a rescale by 0.99999.
    """
    import trimesh

    out = trimesh.Scene()
    for node in scene.graph.nodes_geometry:
        matrix, name = scene.graph[node]
        # The cache holds the file's own normals; without it smooth ones would be guessed.
        mesh = scene.geometry[name].copy(include_cache=True)
        mesh.apply_transform(transform @ matrix)
        out.add_geometry(mesh, geom_name=name)
    return out


def reduce_faces(scene: trimesh.Scene, max_faces: int) -> None:
    """Simplify the scene's meshes in place to about ``max_faces`` triangles in total.

    Quadric decimation drops UV maps: a mesh with a plain PBR material keeps that material,
    a textured or vertex-coloured one keeps its look as colours sampled from the nearest
    original vertex.
    """
    import trimesh

    total = sum(len(g.faces) for g in scene.geometry.values())
    if total <= max_faces:
        return
    try:
        import fast_simplification  # noqa: F401  (trimesh's decimation engine)
    except ImportError:
        raise MissingExtra("face-count reduction (max_faces)", "simplify", "fast-simplification") from None
    from scipy.spatial import cKDTree

    for key, geom in list(scene.geometry.items()):
        target = max(4, int(len(geom.faces) * max_faces / total))
        if len(geom.faces) <= target:
            continue
        reduced = geom.simplify_quadric_decimation(face_count=target)
        if geom.visual.kind == "texture" and geom.visual.uv is None:
            reduced.visual = trimesh.visual.TextureVisuals(material=geom.visual.material)
        else:
            visual = geom.visual.to_color() if geom.visual.kind == "texture" else geom.visual
            _, nearest = cKDTree(geom.vertices).query(reduced.vertices)
            colours = np.asarray(visual.vertex_colors)[nearest]
            reduced.visual = trimesh.visual.ColorVisuals(reduced, vertex_colors=colours)
        scene.geometry[key] = reduced
    log.debug("reduced %d faces to %d", total, sum(len(g.faces) for g in scene.geometry.values()))


def to_glb(scene: trimesh.Scene, source: bytes | None = None) -> bytes:
    """The scene as GLB; with the ``source`` GLB it was read from, each mesh keeps that
    file's material exactly (extensions and full-precision factors, which trimesh drops)."""
    keep = None
    if source is not None:
        try:
            keep = keep_materials(mesh_materials(source))
        except ValueError as exc:  # trimesh read it, but its JSON chunk is not plain glTF JSON
            log.warning("materials kept as trimesh read them: the source GLB's JSON is unreadable (%s)", exc)
    return scene.export(file_type="glb", tree_postprocessor=keep)
