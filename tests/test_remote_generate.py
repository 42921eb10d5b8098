"""`scenewright generate` through the real SDK against a local OpenAI-compatible server:
what the pipeline sends, what it builds, and how a killed run resumes without paying twice."""

from __future__ import annotations

import base64
import os
import signal
import subprocess
import sys
import time

import pytest

from scenewright.testing.fake_openai import CHAT, EDIT, GENERATE, Reply, chat_reply, image_reply, object_item, png
from scenewright.cli import main
from scenewright.folder import SceneFolder
from scenewright.layout import check

TEXT = (
    "A cartoon-style dining corner: a wooden table with a chair on its left and another on its right, "
    "a vase on the table."
)
REFERENCE = png((30, 90, 160, 255), (24, 16))


ANSWERS = {
    "scene_objects": {
        "objects": [
            object_item("table_1", "wooden table", (1.6, 0.9, 0.75)),
            object_item("chair_1", "left chair", (0.5, 0.5, 0.9), -1.5),
            object_item("chair_2", "right chair", (0.5, 0.5, 0.9), 1.5),
            object_item("vase_1", "vase", (0.2, 0.2, 0.35)),
            object_item("lamp_1", "table lamp", (0.3, 0.3, 0.5), 3.0),
            object_item("floor", "wooden floor", (5, 5, 0.1)),
        ]
    },
    "redundant_images": {"redundant": [{"id": "lamp_1", "reason": "already drawn in the table's picture"}]},
    "spatial_constraints": {
        "constraints": [
            {"relation": "on", "source": "vase_1", "target": "table_1"},
            {"relation": "left of", "source": "chair_1", "target": "table_1"},
            {"relation": "right of", "source": "chair_2", "target": "table_1"},
            {"relation": "right of", "source": "chair_2", "target": "table_1"},
            {"relation": "beneath", "source": "chair_1", "target": "table_1"},
            {"relation": "near", "source": "chair_2", "target": "sofa_9"},
        ]
    },
}


def _answer(request):
    return chat_reply(ANSWERS[request.schema_name])


@pytest.fixture
def server(openai_server):
    openai_server.responders[CHAT] = _answer
    openai_server.responders[GENERATE] = lambda request: image_reply(REFERENCE)
    return openai_server


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    """A working folder whose scenewright.toml keeps the cache inside the test."""
    (tmp_path / "scenewright.toml").write_text(
        f'cache_dir = "{(tmp_path / "cache").as_posix()}"\nmax_retries = 1\ntimeout = 20\nimage_concurrency = 2\n'
    )
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("OPENAI_API_KEY", raising=False)
    return tmp_path


def _flags(server):
    return ["--vlm", "openai:test-model", "--images", "openai:test-image", "--base-url", server.url, "--no-render"]


def test_generate_through_the_openai_backends(server, workdir):
    assert main(["generate", TEXT, "--out", "scene", *_flags(server)]) == 0

    # what was sent
    reference_url = "data:image/png;base64," + base64.b64encode(REFERENCE).decode()
    chats = {r.schema_name: r for r in server.seen(CHAT)}
    assert set(chats) == {"scene_objects", "redundant_images", "spatial_constraints"}
    for request in chats.values():
        fmt = request.json["response_format"]
        assert fmt["type"] == "json_schema" and fmt["json_schema"]["strict"] and fmt["json_schema"]["schema"]
        assert request.json["model"] == "test-model"
    assert chats["scene_objects"].image_urls == [reference_url]
    assert chats["spatial_constraints"].image_urls == [reference_url]
    assert len(chats["redundant_images"].image_urls) == 5
    (generated,) = server.seen(GENERATE)
    assert generated.json["model"] == "test-image" and "dining corner" in generated.json["prompt"]
    edits = server.seen(EDIT)
    assert len(edits) == 6  # five objects and the ground
    assert all(r.files["image"] == [REFERENCE] for r in edits)
    objects = [r for r in edits if r.fields.get("background") == "transparent"]
    assert len(objects) == 5 and any("seamless" in r.fields["prompt"] for r in edits)
    assert all("in cartoon style" in r.fields["prompt"] for r in objects)  # the style the text names

    # what was built
    folder = SceneFolder(workdir / "scene")
    scene = folder.load()
    assert [o.id for o in scene.objects] == ["table_1", "chair_1", "chair_2", "vase_1"]
    assert [(r.id, r.reason) for r in scene.removed] == [("lamp_1", "already drawn in the table's picture")]
    assert {str(c) for c in scene.constraints} == {
        "vase_1 on table_1",
        "chair_1 left of table_1",
        "chair_2 right of table_1",
    }
    assert scene.layout is not None and scene.layout.complete
    by_id = {o.id: o for o in scene.objects}
    for c in scene.constraints:
        assert check(c.relation, by_id[c.source], by_id[c.target]), str(c)
    assert all(folder.resolve(o.image).read_bytes().startswith(b"\x89PNG") for o in scene.objects)
    assert folder.reference_image.read_bytes() == REFERENCE
    assert folder.glb.is_file() and all(folder.asset(o.id).is_file() for o in scene.objects)
    assert scene.backends["vlm"] == "openai" and scene.backends["images"] == "openai"
    repairs = " | ".join(e.message for e in scene.provenance if e.stage.startswith("vlm."))
    assert "background element 'wooden floor'" in repairs
    assert "'beneath'" in repairs and "sofa_9" in repairs and "duplicate" in repairs


def test_a_killed_run_resumes_without_repeating_finished_calls(server, workdir):
    finished = {"count": 0}

    def slow_after_three(request):
        finished["count"] += 1
        return image_reply() if finished["count"] <= 3 else Reply(delay=60)

    server.responders[EDIT] = slow_after_three
    command = [sys.executable, "-m", "scenewright", "generate", TEXT, "--out", "scene", *_flags(server)]
    env = {k: v for k, v in os.environ.items() if k != "OPENAI_API_KEY"}
    process = subprocess.Popen(command, cwd=workdir, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 60
        # two workers: the fifth edit is only sent once the first three answers are cached
        while len(server.seen(EDIT)) < 5 and process.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert len(server.seen(EDIT)) == 5, "the run did not reach the object images"
    finally:
        process.send_signal(signal.SIGKILL)
        process.wait()

    before = {route: len(server.seen(route)) for route in (CHAT, GENERATE, EDIT)}
    assert before[CHAT] == 1 and before[GENERATE] == 1
    server.responders[EDIT] = lambda request: image_reply()
    assert main(["generate", "--resume", "scene", *_flags(server)]) == 0

    new = server.requests[sum(before.values()) :]
    assert sum(r.path == GENERATE for r in new) == 0  # the reference is not drawn again
    assert sorted(r.schema_name for r in new if r.path == CHAT) == ["redundant_images", "spatial_constraints"]
    assert sum(r.path == EDIT for r in new) == 2 + 1  # the two unfinished objects, then the ground
    scene = SceneFolder(workdir / "scene").load()
    assert scene.layout is not None and scene.layout.complete and "export" in scene.done


def test_a_refusing_model_fails_generate_with_a_clear_message(server, workdir, capsys):
    server.responders[CHAT] = lambda request: chat_reply(None, refusal="I can't help with that.")
    assert main(["generate", TEXT, "--out", "scene", *_flags(server)]) == 1
    err = " ".join(capsys.readouterr().err.split())  # rich wraps long lines
    assert "scene_objects (test-model at http://127.0.0.1" in err and "the model refused" in err
    assert len(server.seen(CHAT)) == 2  # one retry (max_retries = 1 in scenewright.toml)


def test_a_missing_key_stops_the_run_before_it_starts(workdir, capsys):
    assert main(["generate", TEXT, "--out", "scene", "--vlm", "openai:o3", "--api-key-env", "NO_SUCH_KEY"]) == 1
    assert "set the environment variable NO_SUCH_KEY" in " ".join(capsys.readouterr().err.split())
    assert not (workdir / "scene").exists()


def test_unplaced_objects_go_back_to_the_model_for_revised_constraints(server, workdir):
    contradictory = {
        "constraints": [
            {"relation": "on", "source": "vase_1", "target": "table_1"},
            {"relation": "left of", "source": "chair_1", "target": "table_1"},
            {"relation": "right of", "source": "chair_1", "target": "table_1"},
        ]
    }
    revised = {"constraints": contradictory["constraints"][:2]}
    replies = {**ANSWERS, "spatial_constraints": contradictory, "revised_constraints": revised}
    server.responders[CHAT] = lambda request: chat_reply(replies[request.schema_name])
    assert main(["generate", TEXT, "--out", "scene", *_flags(server), "--feedback-rounds", "2"]) == 0

    (revision,) = [r for r in server.seen(CHAT) if r.schema_name == "revised_constraints"]
    last, report = revision.text.split("report:")
    assert '"right of"' in last.split("given these constraints:")[1]
    assert "chair_1" in report
    scene = SceneFolder(workdir / "scene").load()
    assert scene.layout is not None and scene.layout.complete
    assert {str(c) for c in scene.constraints} == {"vase_1 on table_1", "chair_1 left of table_1"}
    rounds = [e for e in scene.provenance if e.stage == "layout" and "round" in e.data]
    assert [e.data["round"] for e in rounds] == [0, 1]


def test_an_edit_through_the_openai_backend(server, workdir):
    assert main(["generate", TEXT, "--out", "scene", *_flags(server)]) == 0
    backwards = {"relation": "behind", "source": "table_1", "target": "chair_1"}  # the model wrote it the other way
    plan = {"operation": "move", "focus": "chair_1", "constraints": [backwards], "new_object": None, "yaw": None}
    server.responders[CHAT] = lambda request: chat_reply(plan)
    flags = ["--vlm", "openai:test-model", "--images", "openai:test-image", "--base-url", server.url]
    assert main(["edit", "scene", "put the first chair in front of the table", *flags]) == 0

    (request,) = [r for r in server.seen(CHAT) if r.schema_name == "edit_plan"]
    assert "put the first chair in front of the table" in request.text and "chair_1: left chair" in request.text
    scene = SceneFolder(workdir / "scene").load()
    by_id = {o.id: o for o in scene.objects}
    assert check("in front of", by_id["chair_1"], by_id["table_1"])
    assert any(e.stage == "vlm.edit_plan" and e.message.startswith("turned") for e in scene.provenance)
