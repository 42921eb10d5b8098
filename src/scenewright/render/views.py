"""The paper's three candidate viewpoints, framed on the scene's objects, and the choice among them.

Pure numpy, so the worker (which has Blender) and the tests (which may not) share it. The
Blender world frame equals the scene frame (+Z up): the glTF importer undoes the export's
Y-up conversion, so camera poses computed here go to Blender unchanged.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from scenewright.scene import Room

#: view name → (azimuth of the camera around the scene in degrees, 0 = in front (−Y) and
#: counter-clockwise seen from above, so −90 = from the left; elevation in degrees).
VIEWS: dict[str, tuple[float, float]] = {
    "iso_left": (-45.0, 35.264),  # overhead isometric from the front-left
    "front": (0.0, 20.0),
    "right": (90.0, 20.0),
}
#: Horizontal field of view of the camera (a 35 mm lens on a 36 mm sensor).
LENS_MM = 35.0
SENSOR_MM = 36.0
#: The framed points span at most this share of the frame's width or height: a thin border.
FILL = 0.94


def view_direction(name: str) -> np.ndarray:
    """Unit vector from the scene's centre toward the camera."""
    if name not in VIEWS:
        raise ValueError(f"unknown view {name!r}; views are {', '.join(VIEWS)}")
    azimuth, elevation = (math.radians(a) for a in VIEWS[name])
    return np.array(
        [
            math.sin(azimuth) * math.cos(elevation),
            -math.cos(azimuth) * math.cos(elevation),
            math.sin(elevation),
        ]
    )


def half_fov_tangents(aspect: float) -> tuple[float, float]:
    """Tangents of the half field of view across and up the frame (Blender's AUTO sensor fit)."""
    tan_wide = SENSOR_MM / 2.0 / LENS_MM
    return (tan_wide, tan_wide / aspect) if aspect >= 1.0 else (tan_wide * aspect, tan_wide)


def camera_matrix(name: str, points: Sequence[Sequence[float]], aspect: float) -> np.ndarray:
    """4×4 world matrix of a camera (looking down its −Z, +Y up) framing ``points`` tightly.

    The caller passes the corners of the object boxes, not the scene's bounds: the box around a
    whole scene projects to a hexagon much larger than the objects inside it, which left wide
    empty floor in the isometric view. The view's direction is fixed; the camera moves back
    along it to the nearest distance at which every point fits in the frame at :data:`FILL`,
    and across it so the points' projections are centred on both axes, so the binding axis
    is filled to :data:`FILL` whatever the scene's size.
    """
    pts = np.asarray(points, float).reshape(-1, 3)
    if len(pts) == 0:
        raise ValueError("nothing to frame: no points given")
    back = view_direction(name)
    right = np.cross(np.array([0.0, 0.0, 1.0]), back)
    right /= np.linalg.norm(right)
    up = np.cross(back, right)
    depth = pts @ back  # larger is nearer the camera
    axes, tangents = (right, up), [tan * FILL for tan in half_fov_tangents(aspect)]
    distances = []
    for axis, tan in zip(axes, tangents, strict=True):
        # A point p fits when |p·axis − o| ≤ (D − p·back)·tan, o the camera's offset along the
        # axis and D its distance along the view: two linear bounds whose tightest pair gives
        # the least D that fits this axis.
        high = np.max(pts @ axis + depth * tan)
        low = np.max(-(pts @ axis) + depth * tan)
        distances.append(float(high + low) / (2.0 * tan))
    # Keep the nearest point at least a few centimetres in front of the lens.
    distance = max(*distances, float(np.max(depth)) + 0.05)
    position = distance * back
    for axis in axes:
        position += _centred_offset(pts @ axis, distance - depth) * axis
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2] = right, up, back
    m[:3, 3] = position
    return m


def _centred_offset(along: np.ndarray, depth: np.ndarray) -> float:
    """The camera offset along an axis at which the points' projections reach equally far both ways.

    At the binding axis this is the linear bounds' midpoint; at the other axis the points'
    different depths make it nonlinear, and the projected reach each way is monotone in the
    offset, so bisection finds it.
    """
    lo, hi = float(along.min()), float(along.max())
    for _ in range(60):
        mid = (lo + hi) / 2.0
        if np.max((along - mid) / depth) > np.max((mid - along) / depth):
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2.0


def visibility(index_image: np.ndarray, ids: Sequence[str]) -> dict[str, int]:
    """Pixels per object id in an index image (H×W×4 uint8: index = R + 256·G, alpha > 0)."""
    rgba = np.asarray(index_image)
    index = rgba[..., 0].astype(np.int64) + 256 * rgba[..., 1].astype(np.int64)
    index = index[rgba[..., 3] > 0]
    counts = np.bincount(index, minlength=len(ids) + 1)
    return {object_id: int(counts[i + 1]) for i, object_id in enumerate(ids)}


#: An object counts as well shown in a view when it has at least this share of the pixels it
#: has in the view that shows it most (less means it is mostly hidden behind others).
WELL_SHOWN = 0.25
#: An object counts as seen at all only with at least this share of the pixels its box would
#: cover unhidden in that view: a few dozen pixels of a console behind a spaceship are not it.
SEEN_SHARE = 0.08
#: ... and at least this share of the whole frame (a speck is not a view of anything).
SEEN_FRAME = 0.0001


def projected_area(corners: Sequence[Sequence[float]], camera: np.ndarray, resolution: Sequence[int]) -> float:
    """Pixels the silhouette of a box (its eight ``corners``) covers in a camera's picture, hidden
    or not: the area of the convex hull of the projected corners. 0 when it is behind the camera."""
    width, height = resolution
    tan_w, tan_h = half_fov_tangents(width / height)
    rel = np.asarray(corners, float) - camera[:3, 3]
    depth = -(rel @ camera[:3, 2])
    if np.any(depth <= 1e-6):
        return 0.0
    u = (rel @ camera[:3, 0]) / depth / tan_w * (width / 2.0)
    v = (rel @ camera[:3, 1]) / depth / tan_h * (height / 2.0)
    return _hull_area(np.column_stack((u, v)))


def _hull_area(points: np.ndarray) -> float:
    """Area of the convex hull of 2-D points (monotone chain, then the shoelace formula)."""
    pts = sorted(map(tuple, np.round(points, 9)))
    if len(pts) < 3:
        return 0.0

    def half(seq):
        out: list[tuple[float, float]] = []
        for p in seq:
            while len(out) >= 2 and (out[-1][0] - out[-2][0]) * (p[1] - out[-2][1]) - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0]) <= 0:
                out.pop()
            out.append(p)
        return out

    hull = np.array(half(pts)[:-1] + half(pts[::-1])[:-1])
    x, y = hull[:, 0], hull[:, 1]
    return float(abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) / 2.0)


def object_weights(sizes: Mapping[str, Sequence[float]], relations: Mapping[str, int]) -> dict[str, float]:
    """How much showing each object matters: larger objects and those more related to others
    (the table the chairs face, the barn the animals stand by) weigh more, a vase less.

    Size is the cube root of the box volume over the scene's median, held to [0.5, 3] so one
    hangar-sized ship does not outweigh everything; each relation adds half of that again.
    """
    typical = {i: float(np.prod(np.maximum(s, 1e-3))) ** (1.0 / 3.0) for i, s in sizes.items()}
    middle = float(np.median(list(typical.values()))) if typical else 1.0
    return {
        i: float(np.clip(t / middle, 0.5, 3.0)) * (1.0 + 0.5 * relations.get(i, 0)) for i, t in typical.items()
    }


def best_view(
    visible: Mapping[str, Mapping[str, int]],
    expected: Mapping[str, Mapping[str, float]] | None = None,
    weights: Mapping[str, float] | None = None,
    frame_pixels: int = 0,
) -> str:
    """The view showing the most of what matters, then the most of it well, then the most evenly.

    An object is seen in a view when it has at least :data:`SEEN_SHARE` of the pixels its box
    would cover there unhidden (``expected``, from :func:`projected_area`) and
    :data:`SEEN_FRAME` of the ``frame_pixels``; without them any pixel counts. The first key
    sums the ``weights`` (:func:`object_weights`; 1 each without them) of the objects seen,
    the second those well shown (:data:`WELL_SHOWN` of their best view's pixels).

    "Evenly" is the geometric mean of each shown object's share of the view's object pixels.
    Raw pixel counts, the former last key, reward whichever view happens to sit closest to
    the objects: every view is framed to fill the picture, so the count mostly says how
    compact the scene's projection is, and it peaks when one large near object (a truck in
    front of the rest) covers the frame. Shares are unchanged when a view zooms (every count
    scales alike) and highest when small objects are neither dwarfed nor half hidden, which
    is what a preview should show. Ties keep the paper's order.
    """
    order = list(visible)
    ids = {object_id for counts in visible.values() for object_id in counts}
    most = {i: max(visible[v].get(i, 0) for v in order) for i in ids}
    weight = {i: (weights or {}).get(i, 1.0) for i in ids}

    def seen(view: str, object_id: str, pixels: int) -> bool:
        if pixels <= 0 or pixels < SEEN_FRAME * frame_pixels:
            return False
        if expected is None or expected.get(view, {}).get(object_id) is None:
            return True
        return pixels >= SEEN_SHARE * expected[view][object_id]

    def key(view: str):
        counts = {i: n for i, n in visible[view].items() if seen(view, i, n)}
        shown = np.array(list(counts.values()), float)
        well = sum(weight[i] for i, n in counts.items() if n >= WELL_SHOWN * most[i])
        # Rounded so that equal shares tie exactly and fall to the paper's order.
        evenness = round(float(np.mean(np.log(shown / shown.sum()))), 9) if len(shown) else -math.inf
        return (round(sum(weight[i] for i in counts), 9), round(well, 9), evenness, -order.index(view))

    return max(order, key=key)


def cut_away(room: Room, name: str) -> list[str]:
    """The room's nodes a view leaves out so the room shows from outside: the ceiling, and
    every wall whose inside faces away from the camera (the walls between the camera and the
    room), with the doors and windows in them. A wall seen edge-on stays. Names as in
    :func:`scenewright.procedural.room.room_meshes`; a door or window is hidden by its group node.
    """
    from scenewright.procedural.room import opening_nodes

    toward = view_direction(name)[:2]
    hidden = ["room/ceiling"]
    near = set()
    for i, ((x0, y0), (x1, y1)) in enumerate(room.walls):
        inward = np.array([y0 - y1, x1 - x0]) / math.hypot(x1 - x0, y1 - y0)
        if inward @ toward < -1e-6:
            near.add(i)
            hidden.append(f"room/wall_{i}")
    hidden += [node for node, opening in zip(opening_nodes(room), room.openings, strict=True) if opening.wall in near]
    return hidden
