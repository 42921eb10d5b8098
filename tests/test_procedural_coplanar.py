"""No two parts of a procedural object share a face: overlapping coplanar faces facing the same
way z-fight in every renderer (the armchair's black band, the bed's and the rug's before it).

Every shape generator is drawn in every style, under the name of every catalogue category that
uses it (names pick variants: a lighthouse among towers, a snowman among statues), and the
faces of each part are compared with the faces of every other part.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np
import pytest
from test_procedural import FAMILIES, VARIANTS

from scenewright.core.catalogue import load_catalogue
from scenewright.procedural import parts as P
from scenewright.procedural.builder import Model
from scenewright.procedural.shapes import SHAPES
from scenewright.procedural.shapes.families import FAMILY_WORDS
from scenewright.procedural.style import STYLE_TABLE

#: m², the smallest shared area that shows as a band in a render.
MIN_AREA = 1e-4
#: m, how close two planes are to count as one (float round-off of a shared coordinate).
PLANE_TOL = 1e-6


def _plane_keys(part: P.Part):
    v = part.vertices[part.faces]
    n = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    length = np.linalg.norm(n, axis=1)
    keep = length > 1e-12
    n = n[keep] / length[keep, None]
    d = np.einsum("ij,ij->i", n, v[keep, 0])
    return v[keep], n, d


def _clip(poly: list[np.ndarray], a: np.ndarray, b: np.ndarray) -> list[np.ndarray]:
    """Sutherland–Hodgman: the part of a convex polygon left of the directed edge a→b (2D)."""
    def side(p):
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])

    out = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        sp, sq = side(p), side(q)
        if sp >= 0:
            out.append(p)
        if (sp >= 0) != (sq >= 0):
            out.append(p + (q - p) * (sp / (sp - sq)))
    return out


def _area(poly: list[np.ndarray]) -> float:
    if len(poly) < 3:
        return 0.0
    pts = np.array(poly)
    return 0.5 * abs(float(np.dot(pts[:, 0], np.roll(pts[:, 1], -1)) - np.dot(pts[:, 1], np.roll(pts[:, 0], -1))))


def _ccw(tri: np.ndarray) -> np.ndarray:
    cross = (tri[1, 0] - tri[0, 0]) * (tri[2, 1] - tri[0, 1]) - (tri[1, 1] - tri[0, 1]) * (tri[2, 0] - tri[0, 0])
    return tri if cross > 0 else tri[::-1]


def _overlap(t1: np.ndarray, t2: np.ndarray) -> float:
    poly = list(_ccw(t1))
    clip = _ccw(t2)
    for i in range(3):
        poly = _clip(poly, clip[i], clip[(i + 1) % 3])
        if not poly:
            return 0.0
    return _area(poly)


def shared_faces(parts: list[P.Part]) -> list[tuple[int, int, tuple, float]]:
    """(part i, part j, plane, shared area) for every plane where faces of two parts facing the
    same way overlap by more than :data:`MIN_AREA`. One material does not help: rounded parts'
    normals differ along the shared face, so even a fight within one role shows as a band."""
    planes: dict[tuple, dict[int, list[np.ndarray]]] = defaultdict(lambda: defaultdict(list))
    for index, part in enumerate(parts):
        tris, normals, offsets = _plane_keys(part)
        for tri, n, d in zip(tris, normals, offsets):
            key = (*np.round(n, 4), round(float(d) / PLANE_TOL / 100) * PLANE_TOL * 100)
            planes[key][index].append(tri)
    found = []
    for key, by_part in planes.items():
        if len(by_part) < 2:
            continue
        n = np.array(key[:3])
        u = np.cross(n, (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0))
        u /= np.linalg.norm(u)
        w = np.cross(n, u)
        flat = {i: [np.stack([t @ u, t @ w], axis=1) for t in tris] for i, tris in by_part.items()}
        indices = sorted(flat)
        for a_pos, a in enumerate(indices):
            for b in indices[a_pos + 1:]:
                area = sum(_overlap(t1, t2) for t1 in flat[a] for t2 in flat[b]
                           if (t1.max(0) > t2.min(0)).all() and (t2.max(0) > t1.min(0)).all())
                if area > MIN_AREA:
                    found.append((a, b, key, area))
    return found


#: Styles that change how parts meet: plain boxes, rounded edges, flat shading with chunky parts.
STYLES = ("realistic", "cartoon", "low-poly")


def _cases() -> dict[str, list[str]]:
    """Shape → the names it is drawn under: its own, every catalogue name that uses it, every
    family word, every name the shape tests pick a variant by."""
    cases: dict[str, set[str]] = {shape: {shape.replace("_", " ")} for shape in SHAPES}
    for category in load_catalogue().values():
        cases[category.shape].add(category.label)
    for family, words in FAMILY_WORDS.items():
        cases[family].update(words)
    for family, names in FAMILIES.items():
        cases[family].update(names)
    for shape, name, _ in VARIANTS:
        cases[shape].add(name)
    return {shape: sorted(names) for shape, names in sorted(cases.items())}


def _drawn(shape: str, name: str, style: str) -> list[P.Part]:
    model = Model((1.0, 0.8, 1.2), STYLE_TABLE[style], np.random.default_rng(0), name=name)
    SHAPES[shape](model)
    return [part for parts in model.parts.values() for part in parts]


def _on_the_floor(key: tuple) -> bool:
    """A downward face at z = 0 rests on the floor: nobody sees it fight."""
    return key[2] < -0.999 and abs(key[3]) < 1e-6


def test_finds_a_shared_face():
    """The check itself: two boxes standing on one floor with their fronts flush share that front."""
    a = P.box((0, 0, 0), (1, 1, 1), 0.0)
    b = P.box((0.5, 0, 0), (1.5, 1, 0.5), 0.0)
    found = shared_faces([a, b])
    areas = sorted(round(area, 6) for *_, area in found)
    assert areas == [0.25, 0.25, 0.5]  # the bottom (0.5 m²) and the front and back (0.25 m² each)
    assert shared_faces([a, P.box((1, 0, 0), (2, 1, 1), 0.0)]) == []  # touching back to back is fine


CASES = _cases()


@pytest.mark.parametrize("shape", list(CASES))
def test_no_part_shares_a_face_with_another(shape):
    problems = []
    for style in STYLES:
        for name in CASES[shape]:
            for a, b, key, area in shared_faces(_drawn(shape, name, style)):
                if not _on_the_floor(key):
                    problems.append(f"{style} {name}: parts {a} and {b} share {area:.4f} m² on plane {key}")
    assert not problems, "\n".join(problems[:20]) + f"\n... {len(problems)} in all"
