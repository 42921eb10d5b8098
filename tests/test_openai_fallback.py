"""Servers without structured output, as old vLLM, llama.cpp and Ollama versions are: each
fallback level ends in a valid scene with the paid calls counted; cheap checks come first."""

from __future__ import annotations

import json

import pytest

from scenewright.testing.fake_openai import CHAT, EDIT, GENERATE, chat_reply, error_reply, image_reply
from scenewright.backends.formats import FormatMemory, compact_schema, extract_json, schema_instruction
from scenewright.backends.openai_chat import ConstraintsAnswer, EditAnswer, ObjectsAnswer, OpenAIChatVLM
from scenewright.cache import RequestCache
from scenewright.cli import main
from scenewright.errors import BackendError, InputError
from scenewright.folder import SceneFolder
from scenewright.layout import check
from test_remote_generate import ANSWERS, REFERENCE, TEXT

#: The first key of each answer's shape, as the prompt spells it below json_schema.
SHAPES = {'{"objects"': "scene_objects", '{"redundant"': "redundant_images", '{"constraints"': "spatial_constraints"}


def task_of(request) -> str | None:
    """The task a request asks: its schema name, else the shape its prompt describes."""
    if request.schema_name:
        return request.schema_name
    system = request.json["messages"][0]["content"]
    return next((task for shape, task in SHAPES.items() if shape in system), None)


def response_format(request) -> str:
    return ((request.json or {}).get("response_format") or {}).get("type", "text")


def refuses_json_schema(request):
    """vLLM before guided decoding, llama.cpp servers before json_schema: HTTP 400."""
    if response_format(request) == "json_schema":
        return error_reply(400, "response_format json_schema not supported")
    return chat_reply(ANSWERS[task_of(request)])


def ignores_formats(request):
    """Ollama before 0.5 and servers that drop unknown fields: the format is ignored, the model
    writes prose, and JSON only when the prompt spells the shape out (wrapped in chatter)."""
    task = task_of(request)
    if request.schema_name or task is None:
        return chat_reply("Sure! The scene has a table, two chairs and a vase on the table.")
    return chat_reply(f"Here is the answer you asked for:\n{json.dumps(ANSWERS[task])}\nLet me know!")


def fences_everything(request):
    """Servers that accept json_schema and answer fenced JSON all the same."""
    return chat_reply(f"```json\n{json.dumps(ANSWERS[task_of(request)], indent=1)}\n```")


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    (tmp_path / "scenewright.toml").write_text(
        f'cache_dir = "{(tmp_path / "cache").as_posix()}"\nmax_retries = 2\ntimeout = 20\nimage_concurrency = 2\n'
    )
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("OPENAI_API_KEY", raising=False)
    return tmp_path


def generate(server, *extra: str) -> int:
    server.responders[GENERATE] = lambda request: image_reply(REFERENCE)
    return main(["generate", TEXT, "--out", "scene", "--vlm", "openai:test-model", "--images", "openai:test-image",
                 "--base-url", server.url, "--no-render", *extra])


def assert_valid_scene(workdir) -> None:
    scene = SceneFolder(workdir / "scene").load()
    assert {o.id for o in scene.objects} == {"table_1", "chair_1", "chair_2", "vase_1"}
    assert {str(c) for c in scene.constraints} == {"vase_1 on table_1", "chair_1 left of table_1",
                                                   "chair_2 right of table_1"}
    by_id = {o.id: o for o in scene.objects}
    assert all(check(c.relation, by_id[c.source], by_id[c.target]) for c in scene.constraints)


def paid(server) -> dict[str, int]:
    """Chat calls the server answered (a 400 is not served) by response format, and image calls."""
    counts: dict[str, int] = {}
    for request in server.seen(CHAT):
        counts[response_format(request)] = counts.get(response_format(request), 0) + 1
    counts["images"] = len(server.seen(GENERATE)) + len(server.seen(EDIT))
    return counts


def test_a_server_that_refuses_json_schema_is_asked_in_json_mode(openai_server, workdir):
    openai_server.responders[CHAT] = refuses_json_schema
    openai_server.models = ["test-model", "test-image"]
    assert generate(openai_server) == 0
    assert_valid_scene(workdir)
    # One refused request (not served), then one json_object call per task: 3 chat calls paid.
    assert paid(openai_server) == {"json_schema": 1, "json_object": 3, "images": 7}
    assert openai_server.gets.count("/v1/models") == 2  # the chat and the image model, checked first


def test_a_server_that_ignores_the_schema_gets_it_in_the_prompt(openai_server, workdir):
    openai_server.responders[CHAT] = ignores_formats
    assert generate(openai_server) == 0
    assert_valid_scene(workdir)
    # The first answer (prose) is the one wasted call; every later task starts in json_object
    # mode with the shape in its prompt and is answered at once.
    assert paid(openai_server) == {"json_schema": 1, "json_object": 3, "images": 7}


def test_fenced_json_is_accepted_without_a_retry(openai_server, workdir):
    openai_server.responders[CHAT] = fences_everything
    assert generate(openai_server) == 0
    assert_valid_scene(workdir)
    assert paid(openai_server) == {"json_schema": 3, "images": 7}


def test_the_level_learnt_is_kept_for_the_next_run(openai_server, remote_settings):
    openai_server.responders[CHAT] = refuses_json_schema
    OpenAIChatVLM("test-model", remote_settings).describe_objects(TEXT, "cartoon", None)
    assert [response_format(r) for r in openai_server.seen(CHAT)] == ["json_schema", "json_object"]
    # A new client (a resumed run) finds its answer in the cache, under the request at the learnt level.
    objects = OpenAIChatVLM("test-model", remote_settings).describe_objects(TEXT, "cartoon", None).value
    assert len(objects) == 5 and len(openai_server.seen(CHAT)) == 2
    assert FormatMemory(RequestCache(remote_settings.cache_dir), remote_settings.base_url, "test-model").level() \
        == "json_object"


def test_plain_text_is_the_last_level_and_its_answer_is_dug_out_of_prose(openai_server, remote_settings):
    def no_formats_at_all(request):
        if response_format(request) != "text":
            return error_reply(400, f"unknown response_format type {response_format(request)}")
        return ignores_formats(request)

    openai_server.responders[CHAT] = no_formats_at_all
    objects = OpenAIChatVLM("test-model", remote_settings).describe_objects(TEXT, "cartoon", None).value
    assert len(objects) == 5
    assert [response_format(r) for r in openai_server.seen(CHAT)] == ["json_schema", "json_object", "text"]
    assert "Write only the JSON object" in openai_server.seen(CHAT)[-1].json["messages"][0]["content"]


def test_when_every_level_fails_the_error_names_the_server_and_what_to_try(openai_server, remote_settings):
    openai_server.responders[CHAT] = lambda request: (
        error_reply(400, "response_format is not supported") if response_format(request) != "text"
        else chat_reply("I would rather describe it in words: a table and chairs.")
    )
    with pytest.raises(BackendError) as info:
        OpenAIChatVLM("test-model", remote_settings).describe_objects(TEXT, "cartoon", None)
    message = str(info.value)
    assert openai_server.url in message and "response format text" in message
    assert "json_schema: refused" in message and "json_object: refused" in message
    assert "backends --check" in message
    served = [r for r in openai_server.seen(CHAT) if response_format(r) == "text"]
    assert len(served) == remote_settings.max_retries + 1


def test_an_invalid_reasoning_effort_stops_before_any_request(openai_server, workdir, capsys):
    assert generate(openai_server, "--reasoning-effort", "extreme") == 2
    assert "low | medium | high" in capsys.readouterr().err
    assert openai_server.requests == [] and openai_server.gets == []


def test_a_model_the_server_does_not_serve_stops_before_any_paid_call(openai_server, workdir, capsys):
    openai_server.models = ["llama3.2:latest", "test-image"]
    assert generate(openai_server) == 2
    err = capsys.readouterr().err
    assert "does not serve the model 'test-model'" in err and "llama3.2:latest" in err
    assert openai_server.requests == []


def test_ollama_names_match_without_their_latest_tag(openai_server, remote_settings):
    from scenewright.backends.structured import ChatClient

    openai_server.models = ["llama3.2:latest"]
    remote_settings.base_url = openai_server.url
    ChatClient("llama3.2", remote_settings).preflight()  # no error
    with pytest.raises(InputError, match="does not serve the model 'qwen'"):
        ChatClient("qwen", remote_settings).preflight()


def test_backends_check_reports_capabilities_without_generating(openai_server, workdir, capsys):
    def old_vllm(request):
        if response_format(request) == "json_schema":
            return error_reply(400, "response_format json_schema not supported")
        if request.json.get("reasoning_effort"):
            return error_reply(400, "extra fields not permitted: reasoning_effort")
        return chat_reply('{"colour": "red"}' if response_format(request) == "json_object" else "Red.")

    openai_server.responders[CHAT] = old_vllm
    openai_server.models = ["test-model"]
    assert main(["backends", "--check", "--base-url", openai_server.url, "--model", "test-model", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["model_served"] is True and report["models"] == ["test-model"]
    assert report["json_schema"].startswith("refused") and "not supported" in report["json_schema"]
    assert report["json_object"] == "supported"
    assert report["images"] == "supported" and report["reasoning"].startswith("refused")
    assert len(openai_server.seen(CHAT)) == 4 and not openai_server.seen(GENERATE)  # four one-word probes


def test_backends_check_tells_an_ignored_schema(openai_server, workdir, capsys):
    openai_server.responders[CHAT] = lambda request: chat_reply("Blue, I think.")
    assert main(["backends", "--check", "--base-url", openai_server.url, "--model", "m", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["model_served"] is None  # the server has no model list
    assert report["json_schema"].startswith("ignored") and report["json_object"].startswith("ignored")


# -- the pieces --------------------------------------------------------------------------


def test_compact_schema_spells_every_field_enum_and_null():
    text = compact_schema(EditAnswer)
    assert text.startswith('{"operation": "move" | "add" | "delete" | "replace" | "room", "focus": string')
    assert '"new_object": {"name": string, "category": string | null' in text
    assert '"yaw": number | null' in text
    assert '"relation": "left of" | "right of"' in compact_schema(ConstraintsAnswer)
    assert '"position": {"x": number, "y": number, "z": number}' in compact_schema(ObjectsAnswer)
    assert schema_instruction(ObjectsAnswer, "json_schema") == ""
    assert "no explanation" in schema_instruction(ObjectsAnswer, "text")


@pytest.mark.parametrize(
    "reply",
    [
        '{"a": 1}',
        '```json\n{"a": 1}\n```',
        'Sure, here it is:\n```\n{"a": 1}\n```\nAnything else?',
        'The answer is {"a": 1} as requested.',
        'Thinking {not json} ... final: {"a": 1}',
    ],
)
def test_extract_json_finds_the_object(reply):
    assert json.loads(extract_json(reply)) == {"a": 1}


def test_extract_json_leaves_a_reply_without_json_as_it_is():
    assert extract_json("  no json here ") == "no json here"


def test_backends_check_prints_a_table(openai_server, workdir, capsys):
    openai_server.responders[CHAT] = lambda request: chat_reply('{"colour": "red"}')
    openai_server.models = ["test-model"]
    assert main(["backends", "--check", "--base-url", openai_server.url, "--model", "test-model"]) == 0
    out = capsys.readouterr().out
    assert "json_schema" in out and "supported" in out and "model listed" in out


def test_backends_lists_the_new_mesh_backends(capsys):
    assert main(["backends"]) == 0
    out = capsys.readouterr().out
    assert "gradio" in out and "meshy" in out


def test_json_cut_short_is_retried_without_giving_up_the_schema(openai_server, remote_settings):
    from scenewright.testing.fake_openai import object_item

    openai_server.script(CHAT, chat_reply('{"objects": [{"id": "table_1", "na'),
                         chat_reply({"objects": [object_item("table_1", "table")]}))
    OpenAIChatVLM("test-model", remote_settings).describe_objects("a table", "realistic", None)
    assert [response_format(r) for r in openai_server.seen(CHAT)] == ["json_schema", "json_schema"]
