"""The paper's three candidate viewpoints, framed on the scene's bounds, and the choice among them.

Pure numpy, so the worker (which has Blender) and the tests (which may not) share it. The
Blender world frame equals the scene frame (+Z up): the glTF importer undoes the export's
Y-up conversion, so camera poses computed here go to Blender unchanged.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

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
#: Room left around the framed bounds, as a share of the view.
MARGIN = 1.03


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


def camera_matrix(name: str, low: Sequence[float], high: Sequence[float], aspect: float) -> np.ndarray:
    """4×4 world matrix of a camera (looking down its −Z, +Y up) that frames the box [low, high].

    The distance is the smallest at which every corner of the box falls inside the view
    (with :data:`MARGIN`), so scenes of any size fill the picture the same way.
    """
    low, high = np.asarray(low, float), np.asarray(high, float)
    centre = (low + high) / 2.0
    back = view_direction(name)
    right = np.cross(np.array([0.0, 0.0, 1.0]), back)
    right /= np.linalg.norm(right)
    up = np.cross(back, right)
    tan_x = SENSOR_MM / 2.0 / LENS_MM / MARGIN
    tan_y = tan_x / aspect if aspect >= 1.0 else tan_x
    tan_x = tan_x if aspect >= 1.0 else tan_x * aspect
    corners = np.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])])
    rel = corners - centre
    # A corner at depth D - r·back needs |r·right| ≤ (D - r·back)·tan_x, likewise for up.
    distance = max(
        float(np.max(np.abs(rel @ right) / tan_x + rel @ back)),
        float(np.max(np.abs(rel @ up) / tan_y + rel @ back)),
        1e-3,
    )
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2] = right, up, back
    m[:3, 3] = centre + back * distance
    return m


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


def best_view(visible: Mapping[str, Mapping[str, int]]) -> str:
    """The view showing the most objects, then the most of them well, then the most object pixels.

    Pixels come last because they only reward the view closest to the objects; ties keep the
    paper's order.
    """
    order = list(visible)
    ids = {object_id for counts in visible.values() for object_id in counts}
    most = {i: max(visible[v].get(i, 0) for v in order) for i in ids}

    def key(view: str):
        counts = visible[view]
        shown = sum(1 for n in counts.values() if n > 0)
        well = sum(1 for i, n in counts.items() if n > 0 and n >= WELL_SHOWN * most[i])
        return (shown, well, sum(counts.values()), -order.index(view))

    return max(order, key=key)
