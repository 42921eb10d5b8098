"""``scenewright export`` and ``generate --export`` end to end: USD, MJCF and GLB with colliders."""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

import numpy as np
import pytest
import trimesh

from scenewright.bench.analysis import default_prompt_dir, load_prompts
from scenewright.cli import main
from scenewright.folder import SceneFolder
from gltf_validator import assert_valid
from sim_scenes import box, glb

#: Shipped prompts exported in the tests: indoor with a rug and stacked things, outdoor with
#: fixtures and animals, and a small scene.
PROMPTS = ("living_room_cosy", "town_square", "home_office")


def _prompt(prompt_id: str):
    return next(p for p in load_prompts() if p.id == prompt_id)


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """Each prompt generated through the CLI with --export mjcf (and usd when usd-core is there)."""
    root = tmp_path_factory.mktemp("sim")
    formats = ["--export", "mjcf"] + (["--export", "usd"] if importlib.util.find_spec("pxr") else [])
    folders = {}
    for prompt_id in PROMPTS:
        prompt = _prompt(prompt_id)
        out = root / prompt_id
        code = main(["generate", prompt.text, "--out", str(out), "--style", prompt.style, "--no-render", *formats])
        assert code == 0, f"generate {prompt_id} exited {code}"
        folders[prompt_id] = SceneFolder(out)
    return folders


@pytest.mark.parametrize("prompt_id", PROMPTS)
def test_every_object_is_one_usd_prim_with_physics(exported, prompt_id):
    pxr = pytest.importorskip("pxr", reason="USD export needs the 'sim' extra (usd-core)")
    from pxr import Usd, UsdGeom, UsdPhysics

    del pxr
    folder = exported[prompt_id]
    scene = folder.load()
    stage = Usd.Stage.Open(str(folder.simulation / "scene.usd"))
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z and UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    problems = _validation_errors(stage)
    assert problems == [], problems
    world = stage.GetDefaultPrim()
    bodies = {p.GetAttribute("scenewright:id").Get(): p for p in world.GetChildren() if p.HasAttribute("scenewright:id")}
    ground = world.GetChild("ground")
    assert set(bodies) == {o.id for o in scene.objects}
    colliding = [p for p in world.GetChildren() if any(d.HasAPI(UsdPhysics.CollisionAPI) for d in Usd.PrimRange(p))]
    # The objects, the ground and, in a room, the room (its walls collide as static boxes).
    expected = len(scene.objects) + 1 + (scene.room is not None)
    assert len(colliding) == expected and ground.HasAPI(UsdPhysics.CollisionAPI)
    for obj in scene.objects:
        prim = bodies[obj.id]
        hulls = [d for d in Usd.PrimRange(prim) if d.HasAPI(UsdPhysics.CollisionAPI)]
        assert len(hulls) == obj.physics.hulls
        assert all(UsdPhysics.MeshCollisionAPI(h).GetApproximationAttr().Get() == "convexHull" for h in hulls)
        assert prim.HasAPI(UsdPhysics.RigidBodyAPI) == (not obj.physics.static)
        if not obj.physics.static:
            assert UsdPhysics.MassAPI(prim).GetMassAttr().Get() == pytest.approx(obj.physics.mass, rel=1e-5)
        visual = [d for d in Usd.PrimRange(prim) if d.IsA(UsdGeom.Mesh) and "/visual/" in str(d.GetPath())]
        assert visual and all(d.HasAPI(pxr_binding()) for d in visual)


def _validation_errors(stage) -> list[str]:
    """What USD's own validators (UsdPhysics rigid body and collider checkers among them) find."""
    from pxr import UsdValidation

    validators = UsdValidation.ValidationRegistry().GetOrLoadAllValidators()
    return [e.GetMessage() for e in UsdValidation.ValidationContext(validators).Validate(stage)]


def pxr_binding():
    from pxr import UsdShade

    return UsdShade.MaterialBindingAPI


@pytest.mark.parametrize("prompt_id", PROMPTS)
def test_every_scene_loads_in_mujoco_with_free_joints_for_dynamic_objects(exported, prompt_id):
    mujoco = pytest.importorskip("mujoco", reason="loading MJCF needs the 'sim' extra (mujoco)")
    folder = exported[prompt_id]
    scene = folder.load()
    model = mujoco.MjModel.from_xml_path(str(folder.simulation / "mjcf" / "scene.xml"))
    assert model.nbody == len(scene.objects) + 1  # and the world
    free = [model.jnt_bodyid[j] for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    names = {mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, b) for b in free}
    assert names == {o.id for o in scene.objects if not o.physics.static}
    for obj in scene.objects:
        assert model.body(obj.id).mass[0] == pytest.approx(obj.physics.mass, rel=1e-4)
    assert mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "floor") >= 0


def test_glb_physics_names_colliders_for_godot_or_unreal(exported, tmp_path):
    folder = exported["home_office"]
    scene = folder.load()
    assert main(["export", str(folder.root), "--format", "glb-physics"]) == 0
    godot = trimesh.load(folder.simulation / "scene-physics.glb", force="scene")
    for obj in scene.objects:
        hulls = [n for n in godot.graph.nodes if n.startswith(f"{obj.id}-hull") and n.endswith("-convcolonly")]
        assert len(hulls) == obj.physics.hulls
        assert all(godot.graph.transforms.parents[n] == obj.id for n in hulls)
    out = tmp_path / "unreal.glb"
    assert main(["export", str(folder.root), "-f", "glb-physics", "--engine", "unreal", "--out", str(out)]) == 0
    unreal = trimesh.load(out, force="scene")
    # A collider per hull, one for the ground and, in a room, one per solid piece of its walls.
    walls = 0
    if scene.room is not None:
        from scenewright.procedural.room import wall_boxes

        walls = len(wall_boxes(scene.room))
    assert sum(n.startswith("UCX_") for n in unreal.graph.nodes) == sum(o.physics.hulls for o in scene.objects) + 1 + walls
    assert not any("convcolonly" in n for n in unreal.graph.nodes)


@pytest.mark.node
def test_glb_physics_passes_the_gltf_validator(exported, tmp_path):
    folder = exported["living_room_cosy"]
    for engine in ("godot", "unreal"):
        out = tmp_path / f"{engine}.glb"
        assert main(["export", str(folder.root), "-f", "glb-physics", "--engine", engine, "--out", str(out)]) == 0
        assert_valid(out)


def test_unknown_format_lists_the_valid_ones(exported, capsys):
    assert main(["export", str(exported["home_office"].root), "--format", "obj"]) == 2
    err = capsys.readouterr().err
    assert "'obj'" in err and "usd, mjcf, glb-physics" in err


def test_generate_refuses_an_unknown_export_format_before_any_work(tmp_path, capsys):
    out = tmp_path / "never"
    assert main(["generate", "a chair", "--out", str(out), "--no-render", "--export", "fbx"]) == 2
    assert "usd, mjcf, glb-physics" in capsys.readouterr().err and not out.exists()


def test_unknown_engine_is_refused(exported, capsys):
    assert main(["export", str(exported["home_office"].root), "-f", "glb-physics", "--engine", "unity"]) == 2
    assert "godot, unreal" in capsys.readouterr().err


def test_a_non_watertight_asset_still_gets_a_hull_and_a_note(exported, tmp_path):
    import shutil

    source = exported["home_office"]
    folder = SceneFolder(tmp_path / "copy")
    shutil.copytree(source.root, folder.root)
    scene = folder.load()
    victim = scene.objects[0]
    open_box = box(victim.size.tuple(), (0, 0, victim.size.z / 2))
    open_box.update_faces(np.arange(len(open_box.faces)) >= 2)  # one side open
    folder.resolve(victim.asset).write_bytes(glb(open_box))
    assert main(["export", str(folder.root), "-f", "mjcf"]) == 0
    record = folder.load().get(victim.id).physics
    assert record.hulls >= 1 and any("not watertight" in n for n in record.notes)
    mujoco = pytest.importorskip("mujoco", reason="loading MJCF needs the 'sim' extra (mujoco)")
    mujoco.MjModel.from_xml_path(str(folder.simulation / "mjcf" / "scene.xml"))


def test_usd_without_usd_core_names_the_extra(exported, monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "pxr", None)
    assert main(["export", str(exported["home_office"].root), "-f", "usd", "--out", "/nonexistent/x.usd"]) == 1
    assert "scenewright[sim]" in capsys.readouterr().err


def test_evaluate_reports_stable_objects_next_to_cf(exported, tmp_path, capsys):
    pytest.importorskip("mujoco", reason="the physics check needs the 'sim' extra (mujoco)")
    folders = [str(exported[p].root) for p in PROMPTS]
    assert main(["evaluate", *folders, "--out", str(tmp_path / "eval")]) == 0
    report = json.loads(Path(tmp_path / "eval" / "report.json").read_text())
    row = report["summary"]["scenes"]["full"]
    assert row["stable_objects"] is not None and 0 <= row["stable_objects"] <= 100
    assert all(s["stability"]["dynamic"] >= 1 for s in report["scenes"])
    assert "Stable objects (%)" in capsys.readouterr().out


def test_importing_the_cli_pulls_no_simulator(tmp_path):
    import subprocess

    code = "import sys, scenewright.cli, scenewright.export.sim; print(sorted({'pxr', 'mujoco', 'coacd'} & set(sys.modules)))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_bench_physics_prints_stability_and_timing(tmp_path, capsys):
    pytest.importorskip("mujoco", reason="the physics bench needs the 'sim' extra (mujoco)")
    pytest.importorskip("pxr", reason="the physics bench exports USD (the 'sim' extra)")
    import shutil

    prompts = tmp_path / "prompts"
    prompts.mkdir()
    shutil.copy(next(default_prompt_dir().glob("*home_office.json")), prompts)
    assert main(["bench", "physics", "--prompts", str(prompts), "--repeats", "1", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["prompts"] == 1 and result["dynamic_objects"] >= 1
    assert 0 <= result["stable_objects_pct"] <= 100 and result["stable_scenes_pct"] in (0.0, 100.0)
    assert result["timed_scene"]["objects"] == 15 and len(result["export_settle_runs"]) == 1
