import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from scenewright.geometry import (
    GLTF_TO_SCENE,
    SCENE_TO_GLTF,
    front_direction,
    object_matrix,
    world_box,
    yaw_towards,
)
from scenewright.scene import SceneObject, Vec3

angles = st.floats(-360, 360, allow_nan=False)
coords = st.floats(-50, 50, allow_nan=False)


def test_front_is_minus_y_at_yaw_zero_and_turns_counter_clockwise():
    assert np.allclose(front_direction(0), [0, -1])
    assert np.allclose(front_direction(90), [1, 0])
    assert np.allclose(front_direction(180), [0, 1])
    assert np.allclose(front_direction(-90), [-1, 0])


@given(coords, coords, coords, coords)
def test_yaw_towards_makes_the_front_point_at_the_target(x0, y0, x1, y1):
    d = np.array([x1 - x0, y1 - y0])
    if np.linalg.norm(d) < 1e-6:
        return
    f = front_direction(yaw_towards((x0, y0), (x1, y1)))
    assert np.allclose(f, d / np.linalg.norm(d), atol=1e-6)


def test_gltf_conversion_maps_up_and_front():
    up_scene = np.array([0, 0, 1, 0])
    front_scene = np.array([0, -1, 0, 0])
    assert np.allclose(SCENE_TO_GLTF @ up_scene, [0, 1, 0, 0])
    assert np.allclose(SCENE_TO_GLTF @ front_scene, [0, 0, 1, 0])
    assert np.allclose(GLTF_TO_SCENE @ SCENE_TO_GLTF, np.eye(4))


@given(coords, coords, st.floats(0.1, 5), angles)
def test_object_matrix_puts_the_box_centre_at_position(x, y, h, yaw):
    obj = SceneObject(id="a", name="a", position=Vec3(x=x, y=y, z=h / 2), rotation=Vec3(z=yaw), size=Vec3(x=1, y=2, z=h))
    m = object_matrix(obj)
    centre = m @ np.array([0, 0, h / 2, 1])
    assert np.allclose(centre[:3], [x, y, h / 2], atol=1e-9)
    bottom = m @ np.array([0, 0, 0, 1])
    assert bottom[2] == pytest.approx(0, abs=1e-9)


def test_world_box_of_a_quarter_turn_swaps_extents():
    obj = SceneObject(id="a", name="a", position=Vec3(x=1, y=2, z=0.5), rotation=Vec3(z=90), size=Vec3(x=2, y=1, z=1))
    lo, hi = world_box(obj)
    assert np.allclose(hi - lo, [1, 2, 1])
    assert np.allclose((hi + lo) / 2, [1, 2, 0.5])
