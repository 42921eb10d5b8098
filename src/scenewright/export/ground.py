"""The ground of an assembled scene: one textured plane under everything, in glTF frame.

The plane covers the objects' footprint (and the scene's bounds, when it has some) plus a
margin, so a camera framing the scene never sees its edge. Its UVs follow world metres, so
the seamless texture tiles at a fixed real size instead of stretching with the scene.
"""

from __future__ import annotations

import io
import logging
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from scenewright.geometry import SCENE_TO_GLTF, world_box
from scenewright.gltf import srgb_to_linear
from scenewright.scene import WATER_LEVEL, Room, SceneObject, Water

log = logging.getLogger(__name__)

#: Metres of ground one copy of the texture covers.
TILE_METRES = 2.0
#: Margin around the scene's extent: a fixed part plus a share of the extent's larger side.
MARGIN_METRES = 2.0
MARGIN_SHARE = 0.25
#: Extent used when there is nothing to measure.
EMPTY_HALF_EXTENT = 5.0
#: Colour of an untextured ground (the texture file is missing): a neutral mid grey, as a
#: linear glTF factor.
PLAIN_COLOUR = (*srgb_to_linear((0.5, 0.5, 0.5)), 1.0)


def ground_extent(
    objects: Sequence[SceneObject], bounds: tuple[float, float] | None, room: Room | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """(min xy, max xy) in the scene frame that the ground must cover (the room too, when
    there is one), margin included."""
    corners = [np.asarray(room.floor, dtype=float)] if room is not None else []
    for obj in objects:
        lo, hi = world_box(obj)
        corners += [lo[:2], hi[:2]]
    if bounds is not None:
        half = np.array(bounds, dtype=float) / 2.0
        corners += [-half, half]
    if not corners:
        half = np.full(2, EMPTY_HALF_EXTENT)
        return -half, half
    pts = np.vstack(corners)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    margin = MARGIN_METRES + MARGIN_SHARE * float((hi - lo).max())
    return lo - margin, hi + margin


def ground_plane(
    objects: Sequence[SceneObject], bounds: tuple[float, float] | None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The ground's vertices in glTF frame (+Y up), its two triangles and its UVs in texture
    copies (V up, as a mesh library holds them; glTF's V runs down)."""
    (x0, y0), (x1, y1) = ground_extent(objects, bounds)
    scene_xy = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    scene_pts = np.column_stack([scene_xy, np.zeros(4), np.ones(4)])
    vertices = (scene_pts @ SCENE_TO_GLTF.T)[:, :3]
    # Counter-clockwise seen from above (scene +Z), so the face normal points up (glTF +Y).
    faces = np.array([[0, 1, 2], [0, 2, 3]])
    return vertices, faces, scene_xy / TILE_METRES


#: The water's look, as a linear glTF factor: a deep blue-green, three quarters opaque.
WATER_COLOUR = (*srgb_to_linear((0.16, 0.36, 0.48)), 0.8)


def water_plane(objects: Sequence[SceneObject], bounds: tuple[float, float] | None, water: Water) -> np.ndarray:
    """The water's four corners in glTF frame (+Y up), counter-clockwise seen from above: the
    ground's width, from the shore to the ground's far edge (at least a margin past the shore)."""
    (x0, _), (x1, y1) = ground_extent(objects, bounds)
    y1 = max(y1, water.shore + MARGIN_METRES)
    scene_xy = np.array([[x0, water.shore], [x1, water.shore], [x1, y1], [x0, y1]])
    scene_pts = np.column_stack([scene_xy, np.full(4, WATER_LEVEL), np.ones(4)])
    return (scene_pts @ SCENE_TO_GLTF.T)[:, :3]


def ground_mesh(objects: Sequence[SceneObject], bounds: tuple[float, float] | None, texture: Path | None):
    """The plane of :func:`ground_plane` as a trimesh mesh with a PBR material (the editor's)."""
    import trimesh
    from PIL import Image

    vertices, faces, uv = ground_plane(objects, bounds)
    if texture is not None and texture.is_file():
        image = Image.open(io.BytesIO(texture.read_bytes()))
        image.load()
        material = trimesh.visual.material.PBRMaterial(
            name="ground", baseColorTexture=image, metallicFactor=0.0, roughnessFactor=0.9
        )
    else:
        if texture is not None:
            log.warning("ground texture %s is missing; the ground gets a plain colour", texture)
        material = trimesh.visual.material.PBRMaterial(
            name="ground", baseColorFactor=PLAIN_COLOUR, metallicFactor=0.0, roughnessFactor=0.9
        )
    visual = trimesh.visual.TextureVisuals(uv=uv, material=material)
    return trimesh.Trimesh(vertices=vertices, faces=faces, visual=visual, process=False)
