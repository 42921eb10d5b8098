"""Mesh primitives with their own normals, built straight in numpy.

Generators assemble many small parts per object and a scene holds dozens of objects, so
the primitives avoid trimesh's processing (vertex merging, cache rebuilds) and carry
analytic normals: a rounded box or a lathed vase shades smoothly where it is round and
stays crisp at its edges without a crease-angle pass. Every part is in the scene frame
(+Z up, front toward −Y) until the builder converts the finished object to glTF.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache

import numpy as np


@dataclass
class Part:
    """A triangle mesh with one normal per vertex; faces wind counter-clockwise outward."""

    vertices: np.ndarray
    faces: np.ndarray
    normals: np.ndarray


def _unit(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n == 0, 1.0, n)


def inverse3(linear: np.ndarray) -> tuple[np.ndarray, float]:
    """The inverse of a 3×3 matrix and its determinant, in closed form (rows a, b, c: the
    inverse's columns are b×c, c×a, a×b over the determinant).

    Thousands of parts per scene each need one; ``np.linalg.inv`` goes through LAPACK and
    wakes an OpenBLAS thread per call, which cost a quarter of the asset stage.
    """
    a, b, c = linear
    bc, ca, ab = np.cross(b, c), np.cross(c, a), np.cross(a, b)
    det = float(a @ bc)
    if det == 0.0:
        raise ValueError("the part transform is singular (a zero scale): it would flatten the part")
    return np.column_stack((bc, ca, ab)) / det, det


def transform(part: Part, matrix: np.ndarray) -> Part:
    """Apply a 4×4 affine transform; normals follow the inverse transpose."""
    linear = matrix[:3, :3]
    vertices = part.vertices @ linear.T + matrix[:3, 3]
    inverse, det = inverse3(linear)
    normals = _unit(part.normals @ inverse)
    faces = part.faces if det > 0 else part.faces[:, ::-1]
    return Part(vertices, faces, normals)


def flatten(part: Part) -> Part:
    """One vertex per face corner with the face normal: the faceted look of low-poly art."""
    corners = part.vertices[part.faces]
    normals = _unit(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]))
    count = len(part.faces)
    return Part(
        corners.reshape(-1, 3),
        np.arange(count * 3).reshape(-1, 3),
        np.repeat(normals, 3, axis=0),
    )


def drop_degenerate(part: Part) -> Part:
    """Without zero-area faces (poles of spheres, tips of cones): they carry no normal, and
    a glTF normal must be a unit vector."""
    corners = part.vertices[part.faces]
    area2 = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    keep = area2 > 1e-12 * max(1.0, float(np.ptp(part.vertices, axis=0).max()) ** 2)
    if keep.all():
        return part
    used, faces = np.unique(part.faces[keep], return_inverse=True)
    return Part(part.vertices[used], faces.reshape(-1, 3), part.normals[used])


def merge(parts: Sequence[Part]) -> Part:
    offsets = np.cumsum([0] + [len(p.vertices) for p in parts[:-1]])
    return Part(
        np.concatenate([p.vertices for p in parts]),
        np.concatenate([p.faces + o for p, o in zip(parts, offsets)]),
        np.concatenate([p.normals for p in parts]),
    )


def align_z(direction: np.ndarray) -> np.ndarray:
    """3×3 rotation taking +Z to ``direction`` (shortest arc)."""
    d = _unit(np.asarray(direction, dtype=float))
    z = np.array([0.0, 0.0, 1.0])
    c = float(d @ z)
    if c > 1 - 1e-9:
        return np.eye(3)
    if c < -1 + 1e-9:
        return np.diag([1.0, -1.0, -1.0])
    axis = np.cross(z, d)
    s = np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]]) / s
    return np.eye(3) + s * k + (1 - c) * (k @ k)


def affine(linear: np.ndarray, offset) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3] = linear
    m[:3, 3] = offset
    return m


_BOX_FACES = [  # normal, the two in-plane axes (u, v) with u × v = normal
    ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
    ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
    ((0, 1, 0), (0, 0, 1), (1, 0, 0)),
    ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
    ((0, 0, -1), (0, 1, 0), (1, 0, 0)),
]


def _plain_box(lo: np.ndarray, hi: np.ndarray) -> Part:
    centre, half = (lo + hi) / 2, (hi - lo) / 2
    vertices, normals, faces = [], [], []
    for i, (n, u, v) in enumerate(_BOX_FACES):
        n, u, v = np.array(n, float), np.array(u, float), np.array(v, float)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            vertices.append(centre + half * (n + su * u + sv * v))
            normals.append(n)
        b = 4 * i
        faces += [(b, b + 1, b + 2), (b, b + 2, b + 3)]
    return Part(np.array(vertices), np.array(faces), np.array(normals))


def _octant_directions(detail: int) -> np.ndarray:
    """Unit vectors covering the positive octant, boundary included."""
    dirs = []
    for i in range(detail + 1):
        for j in range(detail + 1 - i):
            k = detail - i - j
            dirs.append((i, j, k))
    return _unit(np.array(dirs, dtype=float))


def _hull(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Convex hull faces (into ``points``) wound outward, and the vertices they use."""
    from scipy.spatial import ConvexHull  # built once per detail level (cached), not on import

    hull = ConvexHull(points)
    faces = hull.simplices.copy()
    tri = points[faces]
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    outward = (tri.mean(axis=1) - points.mean(axis=0)) * normal
    flip = outward.sum(axis=1) < 0
    faces[flip] = faces[flip][:, ::-1]
    used, faces = np.unique(faces, return_inverse=True)
    return used, faces.reshape(-1, 3)


@lru_cache(maxsize=4)
def _rounded_template(detail: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Corner signs, unit normals and faces of a rounded box. A rounded box is a box swept by
    a sphere, and every such sweep has the same faces whatever its sides, so the hull is
    computed once."""
    octant = _octant_directions(detail)
    signs, normals = [], []
    for sx in (-1, 1):
        for sy in (-1, 1):
            for sz in (-1, 1):
                sign = np.array([sx, sy, sz], float)
                signs.append(np.tile(sign, (len(octant), 1)))
                normals.append(octant * sign)
    signs, normals = np.concatenate(signs), np.concatenate(normals)
    used, faces = _hull(signs + 0.5 * normals)
    return signs[used], normals[used], faces


def box(lo, hi, radius: float = 0.0, detail: int = 2) -> Part:
    """An axis-aligned box from its corners; ``radius`` rounds edges and corners."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    radius = min(radius, 0.45 * float(np.min(hi - lo)))
    if radius <= 1e-4:
        return _plain_box(lo, hi)
    signs, normals, faces = _rounded_template(detail)
    inner_half = (hi - lo) / 2 - radius
    vertices = (lo + hi) / 2 + signs * inner_half + radius * normals
    return Part(vertices, faces, normals)


def lathe(profile: Sequence[tuple[float, float]], sections: int, crease_degrees: float = 40.0) -> Part:
    """Revolve a (radius, height) profile about +Z.

    Segments meet smoothly unless they turn more than ``crease_degrees``; an end with a
    non-zero radius is closed by a flat cap, so solids stay closed.
    """
    prof = np.asarray(profile, float)
    seg_dir = _unit(np.diff(prof, axis=0))
    seg_normal = np.stack([seg_dir[:, 1], -seg_dir[:, 0]], axis=1)
    theta = np.linspace(0.0, 2 * np.pi, sections, endpoint=False)
    cos, sin = np.cos(theta), np.sin(theta)
    limit = np.cos(np.radians(crease_degrees))

    def ring(point, normal2d):
        r, z = point
        v = np.stack([r * cos, r * sin, np.full(sections, z)], axis=1)
        n = np.stack([normal2d[0] * cos, normal2d[0] * sin, np.full(sections, normal2d[1])], axis=1)
        return v, n

    vertices, normals, faces = [], [], []
    count = 0
    k = np.arange(sections)
    k1 = (k + 1) % sections
    for s in range(len(seg_dir)):
        ends = []
        for end, neighbour in ((s, s - 1), (s + 1, s + 1)):
            n = seg_normal[s]
            if 0 <= neighbour < len(seg_dir) and seg_normal[neighbour] @ n >= limit:
                n = _unit(seg_normal[s] + seg_normal[neighbour])
            ends.append(ring(prof[end], n))
        (va, na), (vb, nb) = ends
        vertices += [va, vb]
        normals += [na, nb]
        a, b = count + k, count + sections + k
        a1, b1 = count + k1, count + sections + k1
        faces.append(np.stack([a, a1, b1], axis=1))
        faces.append(np.stack([a, b1, b], axis=1))
        count += 2 * sections
    for index, up in ((0, -1.0), (len(prof) - 1, 1.0)):
        r, z = prof[index]
        if r <= 1e-9:
            continue
        v, _ = ring(prof[index], (0.0, up))
        vertices.append(np.vstack([v, [[0.0, 0.0, z]]]))
        normals.append(np.tile([0.0, 0.0, up], (sections + 1, 1)))
        centre = count + sections
        tri = np.stack([count + k, count + k1, np.full(sections, centre)], axis=1)
        faces.append(tri if up > 0 else tri[:, ::-1])
        count += sections + 1
    return Part(np.concatenate(vertices), np.concatenate(faces), np.concatenate(normals))


def sphere(centre, radii, sections: int) -> Part:
    """An ellipsoid with semi-axes ``radii``."""
    rings = max(3, sections // 2)
    a = np.linspace(-np.pi / 2, np.pi / 2, rings + 1)
    unit = lathe(np.stack([np.abs(np.cos(a)), np.sin(a)], axis=1), sections, crease_degrees=89.0)
    return transform(unit, affine(np.diag(np.broadcast_to(np.asarray(radii, float), 3)), centre))


def frustum(p0, p1, r0: float, r1: float, sections: int) -> Part:
    """A capped cylinder or cone from point ``p0`` (radius r0) to ``p1`` (radius r1)."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    length = float(np.linalg.norm(p1 - p0))
    unit = lathe([(r0, 0.0), (r1, length)], sections)
    return transform(unit, affine(align_z(p1 - p0), p0))


def torus(major: float, minor: float, sections: int, tube_sections: int, arc: float = 2 * np.pi) -> Part:
    """A torus about +Z (an open arc when ``arc`` < 2π, e.g. an arch or a handle)."""
    closed = arc >= 2 * np.pi - 1e-9
    n_u = sections if closed else sections + 1
    u = np.linspace(0, arc, n_u, endpoint=not closed)
    v = np.linspace(0, 2 * np.pi, tube_sections, endpoint=False)
    uu, vv = np.meshgrid(u, v, indexing="ij")
    normals = np.stack([np.cos(vv) * np.cos(uu), np.cos(vv) * np.sin(uu), np.sin(vv)], axis=-1)
    centres = np.stack([major * np.cos(uu), major * np.sin(uu), np.zeros_like(uu)], axis=-1)
    vertices = centres + minor * normals
    i = np.arange(n_u if closed else n_u - 1)
    j = np.arange(tube_sections)
    ii, jj = np.meshgrid(i, j, indexing="ij")
    i1 = (ii + 1) % n_u
    j1 = (jj + 1) % tube_sections
    idx = lambda a, b: (a * tube_sections + b).ravel()  # noqa: E731
    faces = np.concatenate(
        [np.stack([idx(ii, jj), idx(i1, jj), idx(i1, j1)], 1), np.stack([idx(ii, jj), idx(i1, j1), idx(ii, j1)], 1)]
    )
    return Part(vertices.reshape(-1, 3), faces, normals.reshape(-1, 3))


def prism(polygon: Sequence[tuple[float, float]], depth: float) -> Part:
    """Extrude a star-shaped polygon (in x/y, either winding) along +Z from 0 to ``depth``.

    Caps are fans from the polygon's centroid, which covers every outline the generators
    draw (roofs, hulls, car bodies, signs) without a general triangulator.
    """
    poly = np.asarray(polygon, float)
    x, y = poly[:, 0], poly[:, 1]
    if np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y) < 0:
        poly = poly[::-1]
    n = len(poly)
    centre = poly.mean(axis=0)
    parts = []
    for z, up in ((0.0, -1.0), (depth, 1.0)):
        v = np.vstack([np.column_stack([poly, np.full(n, z)]), [[centre[0], centre[1], z]]])
        k = np.arange(n)
        tri = np.stack([k, (k + 1) % n, np.full(n, n)], axis=1)
        parts.append(Part(v, tri if up > 0 else tri[:, ::-1], np.tile([0.0, 0.0, up], (n + 1, 1))))
    nxt = np.roll(poly, -1, axis=0)
    edge = nxt - poly
    side_normal = _unit(np.column_stack([edge[:, 1], -edge[:, 0], np.zeros(n)]))
    quads = np.stack(
        [
            np.column_stack([poly, np.zeros(n)]),
            np.column_stack([nxt, np.zeros(n)]),
            np.column_stack([nxt, np.full(n, depth)]),
            np.column_stack([poly, np.full(n, depth)]),
        ],
        axis=1,
    ).reshape(-1, 3)
    base = 4 * np.arange(n)[:, None]
    faces = np.concatenate([base + [0, 1, 2], base + [0, 2, 3]])
    parts.append(Part(quads, faces, np.repeat(side_normal, 4, axis=0)))
    return merge(parts)


def beam(p0, p1, width: float, height: float | None = None) -> Part:
    """A square-section bar between two points (rails, frames, slats)."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    height = width if height is None else height
    length = float(np.linalg.norm(p1 - p0))
    unit = _plain_box(np.array([-width / 2, -height / 2, 0.0]), np.array([width / 2, height / 2, length]))
    return transform(unit, affine(align_z(p1 - p0), p0))
