"""The meshes of a room: floor, ceiling, walls with real openings, door and window fittings.

Everything is built in the scene frame (+Z up, metres) from the :class:`~scenewright.scene.Room`
of the document; :func:`room_meshes` gives every mesh (export, renderer, simulation and
editor all draw the same room) and :func:`wall_boxes` the walls as boxes for simulators'
colliders. The conventions:

- The floor polygon is the *inside* of the room: each wall is a slab of
  :data:`WALL_THICKNESS` standing outside its edge, so the wall's inner face is the wall line
  the layout measures against. Neighbouring slabs meet on the bisector of their corner (a
  mitre), so corners are closed, inner (reflex) corners of an L-shaped room too.
- A wall is one closed surface: its elevation is cut on a grid at every opening edge, the
  solid cells get an inner and an outer face, and every cell edge that borders an opening or
  the wall's outline gets a face through the thickness. An opening is therefore a hole that
  goes through (a door, touching the floor, a notch in the bottom edge).
- The floor is a slab under the inside and the walls, its top at z = 0; the ceiling a slab
  on the walls' tops. Both follow the outer outline, so no seam shows under or over a wall.
- A door gets a casing around its hole and a leaf standing open, turned 90° outward about
  the hinge at the opening's start side: the doorway is free (a path runs through it), and
  the leaf never meets anything inside the room. A window gets a casing and a glass pane
  in the middle of the wall.

Materials come from the room's material words through the same words-to-surface code and
style shift as objects (:mod:`scenewright.procedural.material`, :mod:`.style`); the floor is
textured with the procedural ground texture its material word names.
"""

from __future__ import annotations

import hashlib
import logging
from dataclasses import dataclass, field
from functools import lru_cache
from typing import TYPE_CHECKING

import numpy as np
from PIL import Image

from scenewright.procedural.builder import gltf_material, pbr_material
from scenewright.procedural.material import described_surfaces
from scenewright.procedural.style import Style, Surface, resolve_style
from scenewright.procedural.textures import ground_texture, normalise_kind
from scenewright.scene import Opening, Room

if TYPE_CHECKING:
    import trimesh

log = logging.getLogger(__name__)

#: Metres: wall slabs, floor and ceiling slabs, door and window casings.
WALL_THICKNESS = 0.12
FLOOR_THICKNESS = 0.08
CEILING_THICKNESS = 0.08
CASING_WIDTH = {"door": 0.07, "window": 0.05}
#: How far a casing stands proud of each wall face.
CASING_PROUD = 0.015
DOOR_LEAF_THICKNESS = 0.04
GLASS_THICKNESS = 0.01
#: Metres of floor one copy of the floor texture covers (boards and tiles at a real size).
FLOOR_TILE_METRES = 2.0
FLOOR_TEXTURE_PIXELS = 512
#: A sharp corner's mitre would reach far out; it is cut at this many wall thicknesses.
MAX_MITRE = 4.0
#: An opening keeps this far from where its wall's slab ends (at an inner corner the
#: neighbouring wall stands behind that part, so a hole there could not go through).
CORNER_MARGIN = 0.01
#: Key of the exact glTF material (with its extensions) in a mesh's ``metadata``: trimesh's
#: own material copy rounds colours to 8 bits and forgets glass transmission.
GLTF_MATERIAL = "gltf_material"

UP = np.array([0.0, 0.0, 1.0])


@dataclass
class RoomMesh:
    """One mesh of the room as arrays (scene frame): the GLB writer needs no mesh library, and
    :meth:`to_trimesh` gives the renderer, editor and simulators theirs."""

    vertices: np.ndarray
    faces: np.ndarray
    #: The exact glTF material; the floor's names no texture (its ``image`` is the texture).
    material: dict = field(default_factory=dict)
    #: Texture coordinates (V up the image, as trimesh has them) and the texture, for the floor.
    uv: np.ndarray | None = None
    image: Image.Image | None = None

    def to_trimesh(self) -> trimesh.Trimesh:
        import trimesh

        mesh = trimesh.Trimesh(self.vertices, self.faces, process=False)
        if self.image is not None:
            pbr = self.material["pbrMetallicRoughness"]
            material = trimesh.visual.material.PBRMaterial(
                name=self.material["name"], baseColorTexture=self.image,
                metallicFactor=pbr["metallicFactor"], roughnessFactor=pbr["roughnessFactor"],
            )
            mesh.visual = trimesh.visual.TextureVisuals(uv=self.uv, material=material)
        else:
            mesh.visual = trimesh.visual.TextureVisuals(material=pbr_material(self.material))
            mesh.metadata[GLTF_MATERIAL] = self.material
        return mesh


def room_meshes(room: Room, style: str) -> list[tuple[str, trimesh.Trimesh]]:
    """The room as named meshes in the scene frame, each with its material.

    Names: ``room/floor``, ``room/ceiling``, ``room/wall_<i>`` (wall ``i`` of
    :attr:`Room.walls`), and per opening, numbered per kind in the order of
    :attr:`Room.openings`: ``room/door_<k>/frame``, ``room/door_<k>/leaf``,
    ``room/door_<k>/handle``, ``room/window_<k>/frame``, ``room/window_<k>/glass``. Every mesh
    except the floor (which is textured) carries its exact glTF material in
    ``mesh.metadata["gltf_material"]``.
    """
    return [(name, mesh.to_trimesh()) for name, mesh in room_geometry(room, style)]


def room_geometry(room: Room, style: str) -> list[tuple[str, RoomMesh]]:
    """The meshes of :func:`room_meshes` as arrays, in the same order and under the same names."""
    resolved = resolve_style(style)
    outline = _outer_outline(room.floor)
    holes = _holes(room, outline)
    meshes = [
        ("room/floor", _floor(room, outline, resolved)),
        ("room/ceiling", _coloured(_prism(outline, room.height, room.height + CEILING_THICKNESS),
                                   "ceiling", _worded(room.ceiling_material, "wall", resolved))),
    ]
    wall_look = _worded(room.wall_material, "wall", resolved)
    for i in range(len(room.floor)):
        meshes.append((f"room/wall_{i}", _coloured(_wall(room, outline, i, holes[i]), "wall", wall_look)))
    for k, (name, opening) in enumerate(zip(opening_nodes(room), room.openings, strict=True)):
        meshes += [(f"{name}/{part}", mesh) for part, mesh in _fittings(room, opening, holes[opening.wall][k], resolved)]
    return meshes


def opening_nodes(room: Room) -> list[str]:
    """The node of each opening, in the order of :attr:`Room.openings`: ``room/door_0``,
    ``room/window_0``, ... (numbered per kind); its meshes are named under it."""
    counts = {"door": 0, "window": 0}
    names = []
    for opening in room.openings:
        names.append(f"room/{opening.kind}_{counts[opening.kind]}")
        counts[opening.kind] += 1
    return names


# Outline --------------------------------------------------------------------------------
def _frame(room: Room, i: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """Wall ``i``'s start corner, direction along it, inward normal (its left) and length."""
    (x0, y0), (x1, y1) = room.walls[i]
    a = np.array([x0, y0, 0.0])
    along = np.array([x1 - x0, y1 - y0, 0.0])
    length = float(np.linalg.norm(along))
    along /= length
    inward = np.cross(UP, along)
    return a, along, inward, length


def _outer_outline(floor: list[tuple[float, float]]) -> np.ndarray:
    """The walls' outer corners (n×2): where neighbouring outer faces meet, each on its
    corner's bisector, so the slabs close the corner between them."""
    pts = np.asarray(floor, float)
    n = len(pts)
    out = np.empty_like(pts)
    for i in range(n):
        before, after = pts[i] - pts[i - 1], pts[(i + 1) % n] - pts[i]
        n1 = np.array([before[1], -before[0]]) / np.linalg.norm(before)  # outward normals
        n2 = np.array([after[1], -after[0]]) / np.linalg.norm(after)
        # The corner where both walls' outer lines (offset by the thickness) cross.
        offset = WALL_THICKNESS * (n1 + n2) / max(1.0 + float(n1 @ n2), 1e-9)
        reach = float(np.linalg.norm(offset))
        if reach > MAX_MITRE * WALL_THICKNESS:
            offset *= MAX_MITRE * WALL_THICKNESS / reach
        out[i] = pts[i] + offset
    return out


def _holes(room: Room, outline: np.ndarray) -> list[dict[int, tuple[float, float, float, float]]]:
    """Per wall, opening index → its hole (u0, u1, z0, z1) in wall coordinates (u along the
    wall from its start corner, z up), kept within the part of the slab the wall owns."""
    holes: list[dict[int, tuple[float, float, float, float]]] = [{} for _ in room.floor]
    for k, o in enumerate(room.openings):
        a, along, _, length = _frame(room, o.wall)
        n = len(room.floor)
        start = max(0.0, float((outline[o.wall] - a[:2]) @ along[:2])) + CORNER_MARGIN
        end = min(length, float((outline[(o.wall + 1) % n] - a[:2]) @ along[:2])) - CORNER_MARGIN
        u0, u1 = o.offset - o.width / 2.0, o.offset + o.width / 2.0
        if u0 < start or u1 > end:
            log.warning(
                "%s %d on wall %d reaches into the corner (%.2f..%.2f m of %.2f..%.2f m): its hole is narrowed",
                o.kind, k, o.wall, u0, u1, start, end,
            )
            u0, u1 = max(u0, start), min(u1, end)
        if u1 - u0 > 1e-3:
            holes[o.wall][k] = (u0, u1, o.sill, o.sill + o.height)
    return holes


# Slabs ----------------------------------------------------------------------------------
def _ear_clip(poly: np.ndarray) -> np.ndarray:
    """Triangles (k×3 indices, counter-clockwise) of a simple counter-clockwise polygon."""
    left = list(range(len(poly)))
    triangles = []

    def cross(o, p, q) -> float:
        return float((p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]))

    while len(left) > 3:
        for j in range(len(left)):
            i0, i1, i2 = left[j - 1], left[j], left[(j + 1) % len(left)]
            a, b, c = poly[i0], poly[i1], poly[i2]
            if cross(a, b, c) <= 1e-12:
                continue  # a reflex or flat corner is no ear
            inside = any(
                cross(a, b, poly[m]) >= 0 and cross(b, c, poly[m]) >= 0 and cross(c, a, poly[m]) >= 0
                for m in left
                if m not in (i0, i1, i2)
            )
            if not inside:
                triangles.append((i0, i1, i2))
                left.pop(j)
                break
        else:  # only flat corners left (collinear points): drop one
            left.pop(0)
    triangles.append(tuple(left))
    return np.array(triangles, dtype=np.int64)


def _prism(poly: np.ndarray, z0: float, z1: float) -> RoomMesh:
    """A closed slab over a counter-clockwise polygon, from ``z0`` up to ``z1``."""
    n = len(poly)
    vertices = np.vstack([np.column_stack([poly, np.full(n, z0)]), np.column_stack([poly, np.full(n, z1)])])
    cap = _ear_clip(poly)
    sides = [f for i in range(n) for f in ((i, (i + 1) % n, n + (i + 1) % n), (i, n + (i + 1) % n, n + i))]
    faces = np.vstack([cap[:, ::-1], cap + n, np.array(sides)])
    return RoomMesh(vertices, faces)


@lru_cache(maxsize=16)
def _floor_image(kind: str, style: str) -> Image.Image:
    """The floor's texture tile, drawn once per kind and style (it costs most of a room's
    build time, and editing a scene rebuilds its room often)."""
    seed = int.from_bytes(hashlib.sha256(f"{kind} {style}".encode()).digest()[:4], "little")
    return Image.fromarray(ground_texture(kind, style, seed, FLOOR_TEXTURE_PIXELS), "RGB")


def _floor(room: Room, outline: np.ndarray, style: Style) -> RoomMesh:
    mesh = _prism(outline, -FLOOR_THICKNESS, 0.0)
    mesh.image = _floor_image(normalise_kind(room.floor_material), style.name)
    mesh.material = {"name": "floor", "pbrMetallicRoughness": {"metallicFactor": 0.0, "roughnessFactor": 0.8}}
    mesh.uv = mesh.vertices[:, :2] / FLOOR_TILE_METRES
    return mesh


def _grid(room: Room, i: int, holes: dict) -> tuple[list[float], list[float], np.ndarray]:
    """Wall ``i``'s elevation cut at every opening edge: the cut positions along it and up it,
    and which cells are solid (the rest are openings)."""
    length = room.wall_length(i)
    us = sorted({0.0, length, *(h[j] for h in holes.values() for j in (0, 1))})
    zs = sorted({0.0, room.height, *(min(h[j], room.height) for h in holes.values() for j in (2, 3))})
    solid = np.ones((len(us) - 1, len(zs) - 1), dtype=bool)
    for iu in range(len(us) - 1):
        for iz in range(len(zs) - 1):
            u, z = (us[iu] + us[iu + 1]) / 2.0, (zs[iz] + zs[iz + 1]) / 2.0
            solid[iu, iz] = not any(h[0] < u < h[1] and h[2] < z < h[3] for h in holes.values())
    return us, zs, solid


def _wall(room: Room, outline: np.ndarray, i: int, holes: dict) -> RoomMesh:
    """Wall ``i`` as one closed surface with its openings cut through (see the module doc)."""
    a, along, inward, _ = _frame(room, i)
    n = len(room.floor)
    start, end = np.append(outline[i], 0.0), np.append(outline[(i + 1) % n], 0.0)
    us, zs, solid = _grid(room, i, holes)

    def outer(iu: int) -> np.ndarray:
        """Where the line through inner point ``us[iu]``, across the wall, meets the outer face."""
        if iu == 0:
            return start
        if iu == len(us) - 1:
            return end
        p = a + us[iu] * along
        # Solve p - s·inward = start + r·(end - start) for s (the outer face need not be parallel).
        m = np.column_stack([-inward[:2], -(end - start)[:2]])
        s, _ = np.linalg.solve(m, (start - p)[:2])
        return p - s * inward

    inner_pts = [a + u * along for u in us]
    outer_pts = [outer(iu) for iu in range(len(us))]
    vertices, faces = [], []

    def quad(corners, normal) -> None:
        base = len(vertices)
        vertices.extend(corners)
        p0, p1, p2 = (np.asarray(c) for c in corners[:3])
        if np.cross(p1 - p0, p2 - p0) @ normal >= 0:
            faces.extend([(base, base + 1, base + 2), (base, base + 2, base + 3)])
        else:
            faces.extend([(base, base + 2, base + 1), (base, base + 3, base + 2)])

    def inner_v(iu, iz):
        return inner_pts[iu] + zs[iz] * UP

    def outer_v(iu, iz):
        return outer_pts[iu] + zs[iz] * UP

    cols, rows = solid.shape
    for iu in range(cols):
        for iz in range(rows):
            if not solid[iu, iz]:
                continue
            quad([inner_v(iu, iz), inner_v(iu + 1, iz), inner_v(iu + 1, iz + 1), inner_v(iu, iz + 1)], inward)
            quad([outer_v(iu, iz), outer_v(iu + 1, iz), outer_v(iu + 1, iz + 1), outer_v(iu, iz + 1)], -inward)
            # Faces through the thickness where the cell borders an opening or the outline.
            if iu == 0 or not solid[iu - 1, iz]:
                quad([inner_v(iu, iz), inner_v(iu, iz + 1), outer_v(iu, iz + 1), outer_v(iu, iz)], -along)
            if iu == cols - 1 or not solid[iu + 1, iz]:
                quad([inner_v(iu + 1, iz), inner_v(iu + 1, iz + 1), outer_v(iu + 1, iz + 1), outer_v(iu + 1, iz)], along)
            if iz == 0 or not solid[iu, iz - 1]:
                quad([inner_v(iu, iz), inner_v(iu + 1, iz), outer_v(iu + 1, iz), outer_v(iu, iz)], -UP)
            if iz == rows - 1 or not solid[iu, iz + 1]:
                quad([inner_v(iu, iz + 1), inner_v(iu + 1, iz + 1), outer_v(iu + 1, iz + 1), outer_v(iu, iz + 1)], UP)
    return _merged(np.array(vertices), np.array(faces))  # the cells share their corners: one closed surface


def _merged(vertices: np.ndarray, faces: np.ndarray) -> RoomMesh:
    """The mesh with the vertices that sit at one point (to 1e-8 m) made one, in the order
    they first appear."""
    key = np.round(vertices, 8) + 0.0  # + 0.0: -0.0 and 0.0 are one point
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    order = np.argsort(first)
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    return RoomMesh(vertices[first[order]], rank[inverse.reshape(-1)][faces])


def wall_boxes(room: Room) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """The walls as boxes for simulators, which collide boxes best: per wall, one box per
    solid run of its elevation grid, so the openings stay open. Each is (name, pose, extents):
    ``room/wall_<i>/box_<k>``, a 4×4 scene-frame pose of its centre (x along the wall, y
    inward, z up) and its full extents. At a corner the boxes run on to the outer corner, so
    nothing slips through; neighbouring walls' boxes overlap there, which static colliders may.
    """
    outline = _outer_outline(room.floor)
    holes = _holes(room, outline)
    n = len(room.floor)
    boxes = []
    for i in range(n):
        a, along, inward, length = _frame(room, i)
        us, zs, solid = _grid(room, i, holes[i])
        first = len(boxes)
        ends = list(us)
        ends[0] = min(0.0, float((outline[i] - a[:2]) @ along[:2]))
        ends[-1] = max(length, float((outline[(i + 1) % n] - a[:2]) @ along[:2]))
        for iu in range(solid.shape[0]):
            iz = 0
            while iz < solid.shape[1]:
                if not solid[iu, iz]:
                    iz += 1
                    continue
                top = iz
                while top < solid.shape[1] and solid[iu, top]:
                    top += 1
                u0, u1, z0, z1 = ends[iu], ends[iu + 1], zs[iz], zs[top]
                pose = np.eye(4)
                pose[:3, 0], pose[:3, 1], pose[:3, 2] = along, inward, UP
                pose[:3, 3] = a + (u0 + u1) / 2.0 * along - WALL_THICKNESS / 2.0 * inward + (z0 + z1) / 2.0 * UP
                boxes.append((f"room/wall_{i}/box_{len(boxes) - first}", pose, np.array([u1 - u0, WALL_THICKNESS, z1 - z0])))
                iz = top
    return boxes


# Fittings -------------------------------------------------------------------------------
#: A unit box's corners and its triangles, wound outward.
_BOX_CORNERS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
_BOX_FACES = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
                       [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])


def _boxes(room: Room, wall: int, spans) -> RoomMesh:
    """Boxes given in wall coordinates (u along the wall, s inward from its line, z up)."""
    a, along, inward, _ = _frame(room, wall)
    frame = np.column_stack([along, inward, UP])  # a proper rotation: windings stay outward
    vertices, faces = [], []
    for k, (lo, hi) in enumerate(spans):
        lo, hi = np.asarray(lo, float), np.asarray(hi, float)
        vertices.append((lo + _BOX_CORNERS * (hi - lo)) @ frame.T + a)
        faces.append(_BOX_FACES + 8 * k)
    return RoomMesh(np.concatenate(vertices), np.concatenate(faces))


def _casing(room: Room, o: Opening, hole, width: float) -> RoomMesh:
    u0, u1, z0, z1 = hole
    s0, s1 = -WALL_THICKNESS - CASING_PROUD, CASING_PROUD
    top = min(z1 + width, room.height)
    spans = [((u0 - width, s0, z0), (u0, s1, top)), ((u1, s0, z0), (u1 + width, s1, top))]
    if top > z1:
        spans.append(((u0, s0, z1), (u1, s1, top)))
    if z0 > 0:
        spans.append(((u0, s0, max(z0 - width, 0.0)), (u1, s1, z0)))
    return _boxes(room, o.wall, spans)


def _fittings(room: Room, o: Opening, hole, style: Style) -> list[tuple[str, RoomMesh]]:
    u0, u1, z0, z1 = hole
    casing = _coloured(_casing(room, o, hole, CASING_WIDTH[o.kind]), f"{o.kind} frame", style.surface("plastic"))
    if o.kind == "window":
        s = -WALL_THICKNESS / 2.0
        glass = _boxes(room, o.wall, [((u0, s - GLASS_THICKNESS / 2, z0), (u1, s + GLASS_THICKNESS / 2, z1))])
        return [("frame", casing), ("glass", _coloured(glass, "window glass", style.surface("glass")))]
    # The leaf, open 90° outward about its hinge on the outer face at the start jamb.
    outside, width = -WALL_THICKNESS, u1 - u0
    leaf = _boxes(room, o.wall, [((u0, outside - width, z0 + 0.01), (u0 + DOOR_LEAF_THICKNESS, outside, z1 - 0.01))])
    knob_s = outside - width + 0.08
    handle_z = min(0.95, (z0 + z1) / 2.0)
    handle = _boxes(room, o.wall, [((u0 - 0.05, knob_s - 0.07, handle_z - 0.012),
                                    (u0 + DOOR_LEAF_THICKNESS + 0.05, knob_s + 0.03, handle_z + 0.012))])
    return [
        ("frame", casing),
        ("leaf", _coloured(leaf, "door leaf", style.surface("wood"))),
        ("handle", _coloured(handle, "door handle", style.surface("metal"))),
    ]


# Materials ------------------------------------------------------------------------------
def _worded(words: str, role: str, style: Style) -> Surface:
    """The surface a material phrase asks for ("white plaster", "oak"), else the role's, in the style."""
    described = described_surfaces(words, role, {role}, style.base).get(role)
    return style.restyle(described, role) if described is not None else style.surface(role)


def _coloured(mesh: RoomMesh, name: str, surface: Surface) -> RoomMesh:
    mesh.material = gltf_material(name, surface)
    return mesh


def opening_centre(room: Room, index: int) -> np.ndarray:
    """The centre of opening ``index`` on its wall's inner face, in the scene frame."""
    o = room.openings[index]
    a, along, _, _ = _frame(room, o.wall)
    return a + o.offset * along + (o.sill + o.height / 2.0) * UP


def wall_normal(room: Room, wall: int) -> np.ndarray:
    """Wall ``wall``'s inward normal (horizontal, toward the room)."""
    return _frame(room, wall)[2]
