"""Poses and boxes in the scene frame, shared by the solver, export, rendering and evaluation.

An asset is stored normalised: footprint centred at the origin, bottom at z = 0, front to
−Y, already scaled to the object's size. :func:`object_matrix` places it: rotate about the
asset's own axes, then move the box centre to ``position``.
"""

from __future__ import annotations

import numpy as np

from scenewright.scene import SceneObject, Vec3

#: glTF is +Y up with fronts toward +Z; the scene is +Z up with fronts toward −Y.
#: A scene point (x, y, z) is the glTF point (x, z, −y).
SCENE_TO_GLTF = np.array(
    [[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, -1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
)
GLTF_TO_SCENE = SCENE_TO_GLTF.T.copy()


def rotation_matrix(rotation: Vec3) -> np.ndarray:
    """3×3 rotation for Euler angles in degrees, applied x, then y, then z (extrinsic)."""
    rx, ry, rz = np.radians([rotation.x, rotation.y, rotation.z])
    cx, sx, cy, sy, cz, sz = np.cos(rx), np.sin(rx), np.cos(ry), np.sin(ry), np.cos(rz), np.sin(rz)
    mx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    my = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    mz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return mz @ my @ mx


def object_matrix(obj: SceneObject) -> np.ndarray:
    """4×4 transform from the normalised asset frame to the scene frame."""
    m = np.eye(4)
    r = rotation_matrix(obj.rotation)
    m[:3, :3] = r
    # The asset's origin is the bottom centre; its box centre sits half a height above.
    centre_offset = r @ np.array([0.0, 0.0, obj.size.z / 2.0])
    m[:3, 3] = np.array(obj.position.tuple()) - centre_offset
    return m


def front_direction(yaw_degrees: float) -> np.ndarray:
    """Unit vector (x, y) an object faces at this yaw: −Y at yaw 0, turning counter-clockwise."""
    a = np.radians(yaw_degrees)
    return np.array([np.sin(a), -np.cos(a)])


def yaw_towards(src_xy, dst_xy) -> float:
    """The yaw (degrees) at which an object at ``src_xy`` faces ``dst_xy``."""
    dx, dy = float(dst_xy[0] - src_xy[0]), float(dst_xy[1] - src_xy[1])
    return float(np.degrees(np.arctan2(dx, -dy)))


def world_box(obj: SceneObject) -> tuple[np.ndarray, np.ndarray]:
    """Axis-aligned (min, max) corners of the object's size box at its pose."""
    half = np.array(obj.size.tuple()) / 2.0
    corners = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) * half
    world = corners @ rotation_matrix(obj.rotation).T + np.array(obj.position.tuple())
    return world.min(axis=0), world.max(axis=0)
