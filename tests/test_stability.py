"""The MuJoCo settle check: stacked things that rest stay, things that overhang fall."""

from __future__ import annotations

import pytest

from scenewright.cache import RequestCache
from scenewright.evaluation import stability as stability_module
from scenewright.evaluation.stability import MAX_SHIFT, stability
from sim_scenes import box, scene_of

pytest.importorskip("mujoco", reason="the physics check needs the 'sim' extra (mujoco)")


def test_a_crate_resting_on_a_table_top_is_stable(tmp_path):
    scene, folder = scene_of(
        tmp_path,
        {"table_1": ("crate", box((1.0, 1.0, 0.7), (0, 0, 0.35))), "crate_1": ("crate", box((0.3, 0.3, 0.3), (0, 0, 0.15)))},
        positions={"table_1": (0, 0, 0.35), "crate_1": (0.1, 0, 0.85)},
    )
    result = stability(scene, folder, RequestCache(None))
    assert result.stable and len(result.objects) == 2
    assert all(o.shift < MAX_SHIFT / 4 for o in result.objects)


def test_a_plank_hanging_over_a_post_falls_and_is_reported(tmp_path):
    scene, folder = scene_of(
        tmp_path,
        {"post_1": ("crate", box((0.2, 0.2, 0.6), (0, 0, 0.3))), "plank_1": ("crate", box((1.2, 0.2, 0.05), (0, 0, 0.025)))},
        positions={"post_1": (0, 0, 0.3), "plank_1": (0.5, 0, 0.625)},
    )
    result = stability(scene, folder, RequestCache(None))
    assert not result.stable
    assert [o.id for o in result.unstable] == ["plank_1"]
    report = result.to_dict()
    assert report["dynamic"] == 2 and report["stable_objects"] == 1 and report["unstable"][0]["id"] == "plank_1"


def test_static_objects_are_listed_and_not_counted(tmp_path):
    scene, folder = scene_of(tmp_path, {"tree_1": ("tree", box((0.5, 0.5, 2), (0, 0, 1))), "crate_1": ("crate", None)})
    result = stability(scene, folder, RequestCache(None))
    assert result.static == ["tree_1"] and [o.id for o in result.objects] == ["crate_1"]


def test_without_mujoco_the_evaluation_says_which_extra_is_missing(tmp_path, monkeypatch):
    import sys

    from scenewright.evaluation import SceneMetrics

    monkeypatch.setitem(sys.modules, "mujoco", None)
    scene, folder = scene_of(tmp_path, {"crate_1": ("crate", None)})
    metrics = SceneMetrics("s", "g", "full", 1, [], [], [], [], {}, [])
    stability_module.settle_check(metrics, scene, folder)
    assert metrics.stability is None and "scenewright[sim]" in metrics.unavailable["stability"]
