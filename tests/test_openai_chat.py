"""The OpenAI-compatible vision-language backend against a local server: what it sends, how it
treats untrusted answers, and how it survives transport faults."""

from __future__ import annotations

import base64
import json

import pytest

from scenewright.backends import create_backend
from scenewright.testing.fake_openai import CHAT, chat_reply, error_reply, object_item, png
from scenewright.backends.openai_chat import EditAnswer, OpenAIChatVLM, parse_score, size_range
from scenewright.backends.structured import InvalidAnswer, strict_schema
from scenewright.errors import BackendError, InputError
from scenewright.scene import Constraint, LayoutReport, Scene, SceneObject, UnplacedObject, Vec3
from scenewright.settings import Settings

FAST = {"retry-after-ms": "5"}


def _objects():
    return [
        SceneObject(id="table_1", name="table", size=Vec3(x=1.6, y=0.9, z=0.75)),
        SceneObject(id="chair_1", name="chair", size=Vec3(x=0.5, y=0.5, z=0.9)),
        SceneObject(id="lamp_1", name="lamp", size=Vec3(x=0.3, y=0.3, z=0.5)),
    ]


def test_objects_request_carries_strict_schema_and_reference_image(openai_server, remote_settings):
    openai_server.script(CHAT, chat_reply({"objects": [object_item("table_1", "wooden table", (1.6, 0.9, 0.75))]}))
    reference = png()
    objects = OpenAIChatVLM("test-model", remote_settings).describe_objects("a wooden table", "cartoon", reference).value
    assert [o.id for o in objects] == ["table_1"]
    assert objects[0].category == "table"
    (request,) = openai_server.seen(CHAT)
    body = request.json
    assert body["model"] == "test-model"
    fmt = body["response_format"]
    assert fmt["type"] == "json_schema" and fmt["json_schema"]["strict"] is True
    schema = fmt["json_schema"]["schema"]
    assert schema["additionalProperties"] is False and schema["required"] == ["objects", "room"]
    item = schema["$defs"]["ProposedObject"]
    assert set(item["required"]) == {"id", "name", "position", "rotation", "size", "visual_description"}
    (url,) = request.image_urls
    assert url == "data:image/png;base64," + base64.b64encode(reference).decode()
    assert "cartoon" in request.text and "+Y" in request.text


def test_strict_schema_has_no_defaults_and_closes_every_object():
    text = json.dumps(strict_schema(EditAnswer))
    assert '"default"' not in text
    schema = strict_schema(EditAnswer)
    for definition in schema["$defs"].values():
        if definition.get("type") == "object":
            assert definition["additionalProperties"] is False
            assert set(definition["required"]) == set(definition["properties"])


def test_object_answers_are_repaired_and_recorded(openai_server, remote_settings):
    answer = {
        "objects": [
            object_item("Sofa 1", "grey sofa", (2.2, 0.9, 0.8)),
            object_item("sofa_1", "second sofa", (40, 0.9, 0.8)),
            object_item("floor", "wooden floor", (5, 5, 0.1)),
            object_item("lamp", "lamp", (0.01, 0.3, 0.5)),
        ]
    }
    answer["objects"][3]["rotation"] = {"x": 90, "y": 0, "z": -90}
    openai_server.script(CHAT, chat_reply(answer))
    vlm = OpenAIChatVLM("test-model", remote_settings)
    answer = vlm.describe_objects("a grey sofa, another sofa and a lamp", "realistic", None)
    objects = answer.value
    assert [o.id for o in objects] == ["sofa_1", "sofa_1_2", "lamp"]
    assert objects[1].size.x == 5.0
    assert objects[2].size.x == 0.1
    assert objects[2].rotation.tuple() == (0.0, 0.0, 270.0)
    messages = " | ".join(e.message for e in answer.repairs)
    assert "background element 'wooden floor'" in messages
    assert "renamed id 'Sofa 1' to 'sofa_1'" in messages
    assert "clamped" in messages and "upright" in messages
    assert all(e.stage == "vlm.scene_objects" for e in answer.repairs)
    assert openai_server.seen(CHAT)[0].image_urls == []


def test_stated_lengths_widen_the_size_range():
    assert size_range("a cosy room") == (0.1, 5.0)
    assert size_range("a 12 m tall clock tower beside a 5 cm coin") == (0.05, 12.0)
    assert size_range("a rack 2 meters wide, 30 centimetres deep") == (0.1, 5.0)


def test_malformed_json_is_sent_back_with_the_error(openai_server, remote_settings):
    openai_server.script(
        CHAT,
        chat_reply('{"objects": [ {"id": "table_1",'),
        chat_reply("```json\n" + json.dumps({"objects": [object_item("table_1", "table")]}) + "\n```"),
    )
    objects = OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value
    assert [o.id for o in objects] == ["table_1"]
    first, second = openai_server.seen(CHAT)
    assert len(second.json["messages"]) == len(first.json["messages"]) + 2
    assert second.json["messages"][-2] == {"role": "assistant", "content": '{"objects": [ {"id": "table_1",'}
    assert "not valid JSON" in second.json["messages"][-1]["content"]


def test_schema_invalid_answers_exhaust_the_budget_with_a_clear_error(openai_server, remote_settings):
    bad = chat_reply({"objects": [{"id": "t", "name": "table"}]})
    openai_server.script(CHAT, bad, bad, bad)
    with pytest.raises(BackendError) as err:
        OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value
    message = str(err.value)
    assert "scene_objects (test-model at http://127.0.0.1" in message and "3 attempts" in message
    assert "objects.0.position" in message and "Field required" in message
    assert len(openai_server.seen(CHAT)) == 3


def test_a_refusal_is_retried(openai_server, remote_settings):
    openai_server.script(
        CHAT,
        chat_reply(None, refusal="I cannot help with that."),
        chat_reply({"objects": [object_item("table_1", "table")]}),
    )
    vlm = OpenAIChatVLM("test-model", remote_settings)
    assert [o.id for o in vlm.describe_objects("a table", "realistic", None).value] == ["table_1"]
    assert "refused" in openai_server.seen(CHAT)[1].json["messages"][-1]["content"]


def test_refusing_every_time_names_the_refusal(openai_server, remote_settings):
    openai_server.script(CHAT, *[chat_reply(None, refusal="No.")] * 3)
    with pytest.raises(BackendError, match="the model refused: No."):
        OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value


def test_rate_limit_then_success(openai_server, remote_settings):
    openai_server.script(
        CHAT,
        error_reply(429, "slow down", headers=FAST),
        error_reply(429, "slow down", headers=FAST),
        chat_reply({"objects": [object_item("table_1", "table")]}),
    )
    assert len(OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value) == 1
    assert len(openai_server.seen(CHAT)) == 3


def test_server_errors_past_the_retry_budget(openai_server, remote_settings):
    openai_server.script(CHAT, *[error_reply(500, "the GPU caught fire", headers=FAST)] * 3)
    expected = r"scene_objects \(test-model at http://127.0.0.1:\d+/v1\): server answered HTTP 500: the GPU caught fire"
    with pytest.raises(BackendError, match=expected):
        OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value
    assert len(openai_server.seen(CHAT)) == 3


def test_a_hung_request_times_out_and_is_retried(openai_server, remote_settings):
    remote_settings.timeout = 0.3
    hung = chat_reply({"objects": []}, delay=30)
    openai_server.script(CHAT, hung, chat_reply({"objects": [object_item("table_1", "table")]}))
    assert len(OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value) == 1
    assert len(openai_server.seen(CHAT)) == 2


def test_a_server_that_always_hangs_fails_naming_the_timeout(openai_server, remote_settings):
    remote_settings.timeout, remote_settings.max_retries = 0.2, 1
    openai_server.script(CHAT, *[chat_reply({"objects": []}, delay=30)] * 2)
    with pytest.raises(BackendError, match="timed out"):
        OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value


def test_accepted_replies_are_cached(openai_server, remote_settings):
    openai_server.script(CHAT, chat_reply({"objects": [object_item("table_1", "table")]}))
    first = OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value
    again = OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value
    assert first == again
    assert len(openai_server.seen(CHAT)) == 1


def test_an_empty_object_list_is_asked_again(openai_server, remote_settings):
    openai_server.script(
        CHAT,
        chat_reply({"objects": [object_item("grass", "grass")]}),
        chat_reply({"objects": [object_item("bench_1", "bench")]}),
    )
    objects = OpenAIChatVLM("test-model", remote_settings).describe_objects("a bench", "realistic", None).value
    assert [o.id for o in objects] == ["bench_1"]
    assert "no usable object" in openai_server.seen(CHAT)[1].json["messages"][-1]["content"]


def test_constraints_drop_unknown_relations_ids_duplicates_and_cycles(openai_server, remote_settings):
    answer = {
        "constraints": [
            {"relation": "right of", "source": "Chair_1", "target": "table_1"},
            {"relation": "right of", "source": "chair_1", "target": "table_1"},
            {"relation": "under", "source": "lamp_1", "target": "table_1"},
            {"relation": "on", "source": "lamp_1", "target": "sofa_9"},
            {"relation": "on", "source": "lamp_1", "target": "lamp_1"},
            {"relation": "near", "source": "table_1", "target": "chair_1"},
        ]
    }
    openai_server.script(CHAT, chat_reply(answer))
    vlm = OpenAIChatVLM("test-model", remote_settings)
    answer = vlm.write_constraints("a chair right of a table, a lamp", _objects(), png())
    assert [str(c) for c in answer.value] == ["chair_1 right of table_1"]
    dropped = [e.message for e in answer.repairs]
    assert len(dropped) == 5
    assert any("'under'" in m and "unknown relation" in m for m in dropped), dropped
    assert any("sofa_9" in m for m in dropped)
    assert all(e.stage == "vlm.spatial_constraints" for e in answer.repairs)
    (request,) = openai_server.seen(CHAT)
    assert request.schema_name == "spatial_constraints"
    schema = request.json["response_format"]["json_schema"]["schema"]
    assert "face to" in schema["$defs"]["ProposedConstraint"]["properties"]["relation"]["enum"]
    assert "table_1: table, 1.60x0.90x0.75 m" in request.text
    assert len(request.image_urls) == 1


def test_revision_sends_the_last_constraints_and_the_solver_report(openai_server, remote_settings):
    near = {"relation": "near", "source": "chair_1", "target": "table_1"}
    openai_server.script(CHAT, chat_reply({"constraints": [near]}))
    last = [Constraint(relation="left of", source="chair_1", target="table_1")]
    report = LayoutReport(
        placed=["table_1", "lamp_1"],
        unplaced=[UnplacedObject(id="chair_1", failed=last, reason="no collision-free place left of table_1")],
    )
    vlm = OpenAIChatVLM("test-model", remote_settings)
    revised = vlm.revise_constraints("a chair by a table", _objects(), last, report, None).value
    assert [str(c) for c in revised] == ["chair_1 near table_1"]
    (request,) = openai_server.seen(CHAT)
    assert request.schema_name == "revised_constraints"
    assert '"relation": "left of"' in request.text
    assert "chair_1" in request.text.split("report:")[1]


def test_redundant_images_are_labelled_and_unknown_ids_ignored(openai_server, remote_settings):
    openai_server.script(
        CHAT,
        chat_reply({"redundant": [{"id": "lamp_1", "reason": "drawn on the table"}, {"id": "ghost", "reason": "?"}]}),
    )
    vlm = OpenAIChatVLM("test-model", remote_settings)
    images = {"table_1": png((1, 2, 3, 255)), "lamp_1": png((4, 5, 6, 255))}
    answer = vlm.find_redundant(_objects(), images)
    assert answer.value == {"lamp_1": "drawn on the table"}
    assert "ghost" in answer.repairs[0].message
    (request,) = openai_server.seen(CHAT)
    assert len(request.image_urls) == 2
    assert "Picture of table_1:" in request.text and "chair_1" not in request.text


def test_redundancy_needs_no_call_for_a_single_image(openai_server, remote_settings):
    assert OpenAIChatVLM("test-model", remote_settings).find_redundant(_objects(), {"table_1": png()}).value == {}
    assert openai_server.requests == []


def _scene() -> Scene:
    return Scene(text="a table with a chair and a lamp", objects=_objects())


def _edit(**kw):
    plan = {"operation": "move", "focus": "chair_1", "constraints": [], "new_object": None, "yaw": None}
    plan.update(kw)
    return chat_reply(plan)


def test_edit_plans_keep_the_focus_as_the_only_source(openai_server, remote_settings):
    openai_server.script(
        CHAT,
        _edit(
            constraints=[
                {"relation": "left of", "source": "table_1", "target": "chair_1"},
                {"relation": "on", "source": "lamp_1", "target": "chair_1"},
                {"relation": "near", "source": "chair_1", "target": "sofa_7"},
                {"relation": "face to", "source": "chair_1", "target": "lamp_1"},
            ]
        ),
    )
    vlm = OpenAIChatVLM("test-model", remote_settings)
    answer = vlm.plan_edit(_scene(), "put the chair to the right of the table, facing the lamp")
    plan = answer.value
    assert plan.operation == "move" and plan.focus == "chair_1"
    assert [str(c) for c in plan.constraints] == ["chair_1 right of table_1", "chair_1 face to lamp_1"]
    messages = " | ".join(e.message for e in answer.repairs)
    assert "turned {'relation': 'left of', 'source': 'table_1'" in messages
    assert "'source': 'lamp_1', 'target': 'chair_1'}: its source is not the focus" in messages
    assert "unknown object 'sofa_7'" in messages
    assert openai_server.seen(CHAT)[0].schema_name == "edit_plan"


def test_an_unknown_focus_is_asked_again_with_the_choices(openai_server, remote_settings):
    openai_server.script(CHAT, _edit(focus="armchair_3"), _edit(operation="delete", focus="Lamp_1"))
    plan = OpenAIChatVLM("test-model", remote_settings).plan_edit(_scene(), "remove the lamp").value
    assert plan.operation == "delete" and plan.focus == "lamp_1" and plan.constraints == []
    retry = openai_server.seen(CHAT)[1].json["messages"][-1]["content"]
    assert "'armchair_3', which the scene does not have" in retry
    assert "table_1 (table), chair_1 (chair), lamp_1 (lamp)" in retry


def test_an_added_object_is_planned_with_a_clamped_size(openai_server, remote_settings):
    from scenewright.editing.apply import validate_plan

    size = {"x": 9, "y": 0.4, "z": 1}
    new = {"name": "plant", "category": "potted_plant", "visual_description": "a fern", "size": size}
    openai_server.script(
        CHAT,
        _edit(operation="add", focus="plant"),
        _edit(
            operation="add",
            focus="Chair 1",
            new_object=new,
            constraints=[{"relation": "left of", "source": "chair_1", "target": "table_1"}],
        ),
    )
    plan = OpenAIChatVLM("test-model", remote_settings).plan_edit(_scene(), "add a plant left of the table").value
    assert "an 'add' edit needs the new object's name" in openai_server.seen(CHAT)[1].json["messages"][-1]["content"]
    assert plan.operation == "add" and plan.new_object.size.tuple() == (5.0, 0.4, 1.0)
    # the model reused an existing id for the new object: the plan's checks give it a fresh one
    assert plan.focus == "potted_plant_1"
    assert [str(c) for c in plan.constraints] == ["potted_plant_1 left of table_1"]
    assert validate_plan(_scene(), plan) == plan  # checked once, it passes again unchanged


def test_a_move_going_nowhere_is_asked_again(openai_server, remote_settings):
    nowhere = [{"relation": "near", "source": "chair_1", "target": "ghost"}]
    openai_server.script(CHAT, _edit(constraints=nowhere), _edit(yaw=-90.0))
    plan = OpenAIChatVLM("test-model", remote_settings).plan_edit(_scene(), "turn the chair to the right").value
    assert plan.operation == "move" and plan.yaw == 270.0 and plan.constraints == []
    assert "says neither where to nor which way to turn it" in openai_server.seen(CHAT)[1].json["messages"][-1]["content"]


@pytest.mark.parametrize(
    "reply, score",
    [
        ("The chairs face the table.\nScore: 87", 87.0),
        ("Mostly right, 2 relations broken. **Score:** 64.5", 64.5),
        ("I would give it 72/100.", 72.0),
        ("Placement of 3 objects is good; overall 55", 55.0),
        ("Score: 40 ... on reflection, final score = 45", 45.0),
    ],
)
def test_scores_are_read_from_free_text(reply, score):
    assert parse_score(reply) == score


@pytest.mark.parametrize("reply", ["no idea", "Score: 0", "Score: 250"])
def test_unusable_verdicts_are_refused(reply):
    with pytest.raises(InvalidAnswer):
        parse_score(reply)


def test_judge_attaches_the_render_and_retries_a_verdict_without_score(openai_server, remote_settings):
    openai_server.script(CHAT, chat_reply("Looks fine."), chat_reply("Positions hold.\nScore: 91"))
    vlm = OpenAIChatVLM("test-model", remote_settings)
    assert vlm.judge("a chair left of a table", png(), "positional") == 91.0
    first = openai_server.seen(CHAT)[0]
    assert "response_format" not in first.json
    assert len(first.image_urls) == 1 and "positional" in first.text
    with pytest.raises(InputError, match="choose one of: positional, rotational, semantic"):
        vlm.judge("x", png(), "aesthetic")


def test_reasoning_effort_is_sent_when_configured(openai_server, remote_settings):
    remote_settings.reasoning_effort = "high"
    openai_server.script(CHAT, chat_reply("Score: 50"))
    OpenAIChatVLM("test-model", remote_settings).judge("a room", png(), "semantic")
    assert openai_server.seen(CHAT)[0].json["reasoning_effort"] == "high"


def test_without_key_or_base_url_the_error_names_the_variable(monkeypatch, tmp_path):
    monkeypatch.delenv("MY_KEY", raising=False)
    settings = Settings(api_key_env="MY_KEY", cache_dir=tmp_path)
    with pytest.raises(BackendError, match="set the environment variable MY_KEY"):
        create_backend("vlm", "openai:o3", settings)


def test_the_key_comes_from_the_named_variable(openai_server, remote_settings, monkeypatch):
    monkeypatch.setenv("MY_KEY", "sk-test-123")
    remote_settings.api_key_env = "MY_KEY"
    openai_server.script(CHAT, chat_reply("Score: 50"))
    OpenAIChatVLM("test-model", remote_settings).judge("a room", png(), "semantic")
    assert openai_server.seen(CHAT)[0].headers["authorization"] == "Bearer sk-test-123"


# --- limits on what a server may send (issue 11) ----------------------------------------------

from scenewright.testing.fake_openai import Reply  # noqa: E402


def test_a_reply_trickled_a_byte_at_a_time_stops_at_the_total_deadline(openai_server, remote_settings):
    # Every byte comes within the read timeout; without a total deadline this takes minutes.
    remote_settings.timeout, remote_settings.max_retries = 1.0, 0
    body = chat_reply({"objects": [object_item("table_1", "table")]}).body
    openai_server.script(CHAT, Reply(body, drip=0.1))
    with pytest.raises(BackendError, match=r"scene_objects \(test-model at [^)]*\): timed out after 1 s"):
        OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value


def test_a_body_larger_than_max_download_bytes_is_not_read(openai_server, remote_settings):
    remote_settings.max_retries, remote_settings.max_download_bytes = 0, 100_000
    openai_server.script(CHAT, chat_reply({"objects": [object_item("t", "x" * 200_000)]}))
    with pytest.raises(BackendError, match=r"larger than max_download_bytes \(100,000 bytes\)"):
        OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value


def test_a_200_whose_body_is_not_json_is_a_backend_error(openai_server, remote_settings):
    openai_server.script(CHAT, Reply("<html>maintenance</html>"))
    with pytest.raises(BackendError, match="body that is not JSON"):
        OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value


def test_an_oversized_answer_is_refused_and_not_sent_back_whole(openai_server, remote_settings):
    remote_settings.max_answer_chars = 5_000
    huge = {"objects": [object_item("table_1", "table " * 2_000)]}
    good = {"objects": [object_item("table_1", "table")]}
    openai_server.script(CHAT, chat_reply(huge), chat_reply(good))
    objects = OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None).value
    assert [o.id for o in objects] == ["table_1"]
    retry = openai_server.seen(CHAT)[1].json
    assert len(json.dumps(retry)) < 10_000
    assert "more than max_answer_chars (5,000)" in retry["messages"][-1]["content"]


def test_too_many_objects_or_too_long_names_are_asked_again(openai_server, remote_settings):
    remote_settings.max_objects, remote_settings.max_retries = 3, 1
    many = {"objects": [object_item(f"box_{i}", "box", x=i) for i in range(4)]}
    long_name = {"objects": [object_item("lamp_1", "lamp " * 50)]}
    openai_server.script(CHAT, chat_reply(many), chat_reply(long_name))
    with pytest.raises(BackendError, match=r"name: Value error, 249 characters, more than the 200 allowed"):
        OpenAIChatVLM("test-model", remote_settings).describe_objects("boxes", "realistic", None).value
    first = openai_server.seen(CHAT)[1].json["messages"][-1]["content"]
    assert "4 objects, more than max_objects (3)" in first


def test_a_model_name_that_is_not_one_is_an_input_error(remote_settings):
    with pytest.raises(InputError, match="is not a model name"):
        create_backend("vlm", "openai:" + "m" * 300, remote_settings)
    with pytest.raises(InputError, match="is not a model name"):
        create_backend("images", "openai:a model; rm -rf", remote_settings)
