import json

import pytest
from PIL import Image

from scenewright.errors import BackendError, MissingExtra
from scenewright.evaluation import ABLATED, FULL, evaluate_scene
from scenewright.evaluation.ablation import initial_objects, without_solver
from scenewright.evaluation.judge import judge
from scenewright.evaluation.physical import physical
from scenewright.evaluation.report import (
    aggregate,
    markdown_table,
    summarise,
    write_report,
)
from scenewright.evaluation.spatial import spatial
from scenewright.folder import SceneFolder
from scenewright.scene import Constraint, Pose, Scene, SceneObject, Vec3


def box(object_id, x, y, z, sx, sy, sz, yaw=0.0):
    return SceneObject(
        id=object_id, name=object_id.split("_")[0], position=Vec3(x=x, y=y, z=z), rotation=Vec3(z=yaw), size=Vec3(x=sx, y=sy, z=sz)
    )


def cluttered() -> Scene:
    """One collision (lamp in the table), a cup resting on the table, a floating crate out of bounds."""
    return Scene(
        text="a table, a chair in front of it, a cup on it, a lamp left of it",
        bounds=(6.0, 4.0),
        objects=[
            box("table_1", 0, 0, 0.4, 1.4, 0.8, 0.8),
            box("chair_1", 0, -1.0, 0.45, 0.5, 0.5, 0.9),
            box("cup_1", 0, 0, 0.85, 0.1, 0.1, 0.1),
            box("lamp_1", 0.6, 0, 0.8, 0.4, 0.4, 1.6),
            box("crate_1", 3.0, 0, 1.5, 0.5, 0.5, 0.5),
        ],
        constraints=[
            Constraint(relation="in front of", source="chair_1", target="table_1"),
            Constraint(relation="on", source="cup_1", target="table_1"),
            Constraint(relation="left of", source="lamp_1", target="table_1"),
            Constraint(relation="near", source="chair_1", target="table_1"),
            Constraint(relation="near", source="ghost_1", target="table_1"),  # names no object: not counted
        ],
    )


def tidy() -> Scene:
    return Scene(text="two crates", objects=[box("crate_1", -1, 0, 0.25, 0.5, 0.5, 0.5), box("crate_2", 1, 0, 0.25, 0.5, 0.5, 0.5)])


def test_physical_counts_the_planted_problems_and_excuses_resting_contact():
    result = physical(cluttered())
    assert result.collisions == [("lamp_1", "table_1")]
    assert result.out_of_bounds == ["crate_1"]
    assert result.floating == ["crate_1"]
    assert result.sunken == []
    assert not result.collision_free
    assert physical(tidy()).collision_free


def test_hanging_sources_of_above_are_not_floating_but_sunken_objects_are_reported():
    scene = Scene(
        text="a lamp above a table",
        objects=[box("table_1", 0, 0, 0.4, 1, 1, 0.8), box("lamp_1", 0, 0, 3.0, 0.3, 0.3, 0.3), box("rock_1", 3, 0, 0.1, 0.5, 0.5, 0.5)],
        constraints=[Constraint(relation="above", source="lamp_1", target="table_1")],
    )
    result = physical(scene)
    assert result.floating == [] and result.sunken == ["rock_1"]


def test_spatial_shares_by_relation_and_type():
    result = spatial(cluttered())
    assert result.by_relation == {"in front of": [1, 1], "on": [1, 1], "left of": [0, 1], "near": [1, 1]}
    assert (result.satisfied, result.total) == (3, 4)
    assert result.by_type() == {"relative": [1, 2], "vertical": [1, 1], "distance": [1, 1]}
    assert result.violated == ["lamp_1 left of table_1"]


class FixedJudge:
    """Stands in for a remote vision-language model that scores every render."""

    name = "fixed"

    def judge(self, text, image, criterion):
        return {"positional": 70.0, "rotational": 60.0, "semantic": 80.0}[criterion]


class OfflineJudge:
    name = "offline"

    def judge(self, text, image, criterion):
        raise BackendError("judging needs a remote vision-language model (--vlm openai:MODEL)")


def test_psa_is_sa_only_for_collision_free_scenes_and_aggregates_like_the_paper(tmp_path):
    image = tmp_path / "render.png"
    Image.new("RGB", (8, 8)).save(image)
    results = [
        evaluate_scene(cluttered(), name="a", group="indoor", image=image, vlm=FixedJudge()),
        evaluate_scene(tidy(), name="b", group="indoor", image=image, vlm=FixedJudge()),
    ]
    assert [r.psa for r in results] == [0.0, 80.0]
    row = aggregate(results)
    assert row["cf"] == 50.0 and row["cn"] == 0.5
    assert row["constraints"] == 75.0 and row["constraints_by_relation"]["left of"] == 0.0
    assert (row["pos"], row["rot"], row["sa"], row["psa"]) == (70.0, 60.0, 80.0, 40.0)
    assert row["floating"] == 0.5 and row["out_of_bounds"] == 0.5


def test_offline_judge_is_reported_unavailable_not_faked(tmp_path):
    image = tmp_path / "render.png"
    Image.new("RGB", (8, 8)).save(image)
    verdict = judge("text", image.read_bytes(), OfflineJudge())
    assert verdict.scores == {} and "remote" in verdict.unavailable
    metrics = evaluate_scene(tidy(), name="b", image=image, vlm=OfflineJudge())
    assert metrics.psa is None and "remote" in metrics.unavailable["judge"]
    row = aggregate([metrics])
    assert row["pos"] is None and row["psa"] is None and row["unavailable"]
    no_render = evaluate_scene(tidy(), name="b", vlm=FixedJudge())
    assert "no render" in no_render.unavailable["judge"]


def stacked() -> Scene:
    """Two crates apart, as solved, whose recorded initial poses overlap (the model stacked them)."""
    scene = tidy()
    scene.initial = {
        "crate_1": Pose(position=Vec3(x=0.0, y=0.0, z=0.25), rotation=Vec3(z=0.0)),
        "crate_2": Pose(position=Vec3(x=0.1, y=0.05, z=0.25), rotation=Vec3(z=30.0)),
    }
    return scene


def test_ablation_keeps_the_recorded_initial_poses_and_the_assets():
    scene = stacked()
    scene.objects[1] = scene.objects[1].model_copy(update={"asset": "assets/crate_2.glb"})
    ablated = without_solver(scene, initial_objects(scene))
    assert {o.id: Pose(position=o.position, rotation=o.rotation) for o in ablated.objects} == scene.initial
    assert ablated.objects[1].asset == "assets/crate_2.glb"
    assert ablated.layout is not None and ablated.layout.solver is False
    assert [o.position.x for o in scene.objects] == [-1.0, 1.0]  # the scene itself is untouched
    full = evaluate_scene(scene, name="s", method=FULL)
    ablation = evaluate_scene(ablated, name="s", method=ABLATED)
    assert full.collision_free and ablation.collisions == [("crate_1", "crate_2")]


def test_ablation_keeps_the_current_pose_of_an_object_with_none_recorded(caplog):
    scene = stacked()
    del scene.initial["crate_2"]
    initial = initial_objects(scene)
    assert initial[0].position == scene.initial["crate_1"].position
    assert initial[1].position == scene.objects[1].position
    assert "crate_2" in caplog.text


def test_report_writes_json_table_and_chart(tmp_path):
    results = [
        evaluate_scene(cluttered(), name="a", group="indoor"),
        evaluate_scene(tidy(), name="b", group="indoor", method=ABLATED),
        evaluate_scene(tidy(), name="c", group="open-domain"),
    ]
    paths = write_report(results, tmp_path / "report")
    report = json.loads(paths["json"].read_text())
    assert report["summary"]["indoor"]["full"]["cf"] == 0.0
    assert report["summary"]["open-domain"]["full"]["cf"] == 100.0
    assert len(report["scenes"]) == 3 and report["scenes"][0]["collisions"] == [["lamp_1", "table_1"]]
    table = paths["table"].read_text()
    assert "| indoor | full | 1 | – | 0.00 | 1.00 |" in table
    assert "| indoor | full (paper) | – | 0.297 | 97.14 | 0.11 |" in table
    assert Image.open(paths["chart"]).size == (1600, 420)
    rows = [line for line in markdown_table(summarise(results), paper=False).splitlines() if line.startswith("|")]
    assert len(rows) == 5


def test_clip_scores_a_render_with_a_randomly_initialised_model(tmp_path):
    """Real weights cannot be downloaded here: this checks the plumbing (model, preprocessing,
    tokenizer, cosine) with random weights, so only the range of the score is asserted."""
    from scenewright.evaluation.perceptual import ClipScorer

    try:
        scorer = ClipScorer(None)
    except (MissingExtra, BackendError) as exc:
        pytest.skip(f"CLIP extra not usable here: {exc}")
    image = tmp_path / "render.png"
    Image.new("RGB", (64, 48), (200, 40, 40)).save(image)
    score = scorer.score("a red square " * 40, image)  # longer than CLIP's 77 tokens
    assert -1.0 <= score <= 1.0


def test_evaluate_command_scores_scene_folders(tmp_path):
    from scenewright.cli import main

    folders = []
    for name, scene in (("a", cluttered()), ("b", stacked())):
        folder = SceneFolder(tmp_path / name)
        folder.create()
        folder.save(scene)
        folders.append(str(folder.root))
    out = tmp_path / "report"
    assert main(["evaluate", *folders, "--out", str(out), "--group", "indoor"]) == 0
    summary = json.loads((out / "report.json").read_text())["summary"]
    assert summary["indoor"]["full"]["cf"] == 50.0 and summary["indoor"]["full"]["cn"] == 0.5
    assert ABLATED not in summary["indoor"]
    assert main(["evaluate", *folders, "--out", str(out), "--group", "indoor", "--ablation"]) == 0
    summary = json.loads((out / "report.json").read_text())["summary"]
    assert summary["indoor"][FULL]["cn"] == 0.5 and summary["indoor"][ABLATED]["cn"] == 1.0
    assert "(paper)" not in (out / "table.md").read_text()
    assert main(["evaluate", str(tmp_path / "missing"), "--out", str(out)]) == 2


def test_bench_eval_generates_prompts_full_and_without_solver(tmp_path, capsys):
    from scenewright.cli import main

    out = tmp_path / "eval"
    assert main(["bench", "eval", "--limit", "1", "--out", str(out)]) == 0
    printed = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    assert printed["prompts"] == 2
    assert set(printed["summary"]) == {"indoor", "open-domain"}
    for methods in printed["summary"].values():
        assert set(methods) == {FULL, ABLATED}
        assert methods[FULL]["scenes"] == 1 and methods[FULL]["cf"] is not None
    assert {p.name for p in out.iterdir()} == {"report.json", "table.md", "chart.png"}


def test_evaluate_judges_renders_through_a_remote_model(tmp_path, openai_server, monkeypatch):
    """Pos., Rot., SA and PSA from a scripted OpenAI-compatible server, driven through the CLI."""
    from scenewright.backends.fake_openai import CHAT, chat_reply
    from scenewright.cli import main

    monkeypatch.setenv("OPENAI_API_KEY", "test-key")
    folder = SceneFolder(tmp_path / "tidy")
    folder.create()
    folder.save(tidy())
    folder.renders.mkdir()
    Image.new("RGB", (16, 9), (90, 120, 200)).save(folder.renders / "front.png")
    (folder.renders / "renders.json").write_text(json.dumps({"best": "front", "images": {"front": "renders/front.png"}}))
    openai_server.script(
        CHAT, chat_reply("Placement is sound.\nScore: 70"), chat_reply("Mostly well turned. 60"),
        chat_reply("Matches the text.\nFinal score: 80/100"),
    )
    out = tmp_path / "report"
    argv = ["evaluate", str(folder.root), "--out", str(out), "--group", "indoor", "--judge",
            "--vlm", "openai:test-model", "--base-url", openai_server.url]
    assert main(argv) == 0
    row = json.loads((out / "report.json").read_text())["summary"]["indoor"][FULL]
    assert (row["pos"], row["rot"], row["sa"], row["psa"]) == (70.0, 60.0, 80.0, 80.0)
    asked = openai_server.seen(CHAT)
    assert len(asked) == 3 and all(len(r.image_urls) == 1 for r in asked)
