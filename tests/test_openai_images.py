"""The OpenAI Images backend against a local server: generate vs edit, transparency, the
reference image sent along, concurrency, progress, and the per-request cache."""

from __future__ import annotations

import io
import threading

import pytest
from scenewright.testing.fake_openai import EDIT, GENERATE, Reply, error_reply, image_reply, png
from PIL import Image

from scenewright.backends.openai_images import OpenAIImages
from scenewright.errors import BackendError
from scenewright.scene import SceneObject, Vec3

FAST = {"retry-after-ms": "5"}


def _objects(n):
    return [SceneObject(id=f"crate_{i}", name="crate", size=Vec3(x=0.5, y=0.5, z=0.5), visual_description=f"crate {i}")
            for i in range(1, n + 1)]


def test_reference_is_generated_from_text_style_and_frame(openai_server, remote_settings):
    drawn = OpenAIImages("test-image", remote_settings).reference_image("a market with three stalls", "anime")
    assert drawn == png()
    (request,) = openai_server.seen(GENERATE)
    assert request.json["model"] == "test-image"
    assert "a market with three stalls" in request.json["prompt"] and "anime" in request.json["prompt"]
    assert "+Y" in request.json["prompt"]
    assert "background" not in request.json


def test_object_images_are_edits_of_the_reference_asking_for_transparency(openai_server, remote_settings):
    reference = png((10, 20, 30, 255), (16, 16))
    openai_server.responders[EDIT] = lambda r: image_reply(png((len(r.fields["prompt"]) % 255, 0, 0, 0)))
    seen = []
    images = OpenAIImages("test-image", remote_settings).object_images(_objects(5), "cartoon", reference, seen.append)
    assert list(images) == [f"crate_{i}" for i in range(1, 6)]
    assert sorted(note.split(":")[0] for note in seen) == sorted(images)
    assert "image 5 of 5" in seen[-1]
    requests = openai_server.seen(EDIT)
    assert len(requests) == 5 and openai_server.seen(GENERATE) == []
    for request in requests:
        assert request.fields["background"] == "transparent"
        assert request.fields["model"] == "test-image"
        assert request.files["image"] == [reference]
        assert "front" in request.fields["prompt"] and "cartoon" in request.fields["prompt"]
    assert {r.fields["prompt"].count("crate 3") for r in requests} == {0, 1}


def test_without_reference_objects_are_generated_transparent(openai_server, remote_settings):
    OpenAIImages("test-image", remote_settings).object_images(_objects(2), "realistic", None)
    assert openai_server.seen(EDIT) == []
    assert [r.json["background"] for r in openai_server.seen(GENERATE)] == ["transparent", "transparent"]


def test_no_more_requests_in_flight_than_the_limit(openai_server, remote_settings):
    lock, state = threading.Lock(), {"now": 0, "max": 0}
    release = threading.Event()

    def respond(request):
        with lock:
            state["now"] += 1
            state["max"] = max(state["max"], state["now"])
            if state["max"] == remote_settings.image_concurrency:
                release.set()
        release.wait(2)
        with lock:
            state["now"] -= 1
        return image_reply()

    openai_server.responders[EDIT] = respond
    OpenAIImages("test-image", remote_settings).object_images(_objects(7), "realistic", png())
    assert state["max"] == remote_settings.image_concurrency


def test_every_image_is_cached_by_its_request(openai_server, remote_settings):
    backend = OpenAIImages("test-image", remote_settings)
    reference = backend.reference_image("a dock", "realistic")
    backend.object_images(_objects(3), "realistic", reference)
    backend.ground_texture("a dock", "realistic", "wood planks", reference)
    assert len(openai_server.requests) == 5
    again = OpenAIImages("test-image", remote_settings)
    again.reference_image("a dock", "realistic")
    again.object_images(_objects(3), "realistic", reference)
    again.ground_texture("a dock", "realistic", "wood planks", reference)
    assert len(openai_server.requests) == 5
    again.object_images(_objects(4), "realistic", reference)
    assert len(openai_server.requests) == 6


def test_a_failed_object_fails_the_call_after_caching_the_others(openai_server, remote_settings):
    def respond(request):
        if "crate 2" in request.fields["prompt"]:
            return error_reply(500, "moderation hiccup", headers=FAST)
        return image_reply()

    openai_server.responders[EDIT] = respond
    backend = OpenAIImages("test-image", remote_settings)
    with pytest.raises(BackendError, match=r"1 of 3 object images failed .*image of crate_2 .*HTTP 500"):
        backend.object_images(_objects(3), "realistic", png())
    assert len(openai_server.seen(EDIT)) == 5  # crate_2 tried three times (max_retries=2)
    openai_server.responders[EDIT] = lambda r: image_reply()
    assert len(backend.object_images(_objects(3), "realistic", png())) == 3
    assert len(openai_server.seen(EDIT)) == 6  # only crate_2 asked again


def test_ground_texture_is_an_edit_of_the_reference(openai_server, remote_settings):
    reference = png((1, 1, 1, 255))
    OpenAIImages("test-image", remote_settings).ground_texture("a beach bar", "realistic", "sand", reference)
    (request,) = openai_server.seen(EDIT)
    assert request.files["image"] == [reference]
    assert "seamless" in request.fields["prompt"] and "sand" in request.fields["prompt"]
    assert "background" not in request.fields


def test_jpeg_answers_become_png_and_garbage_is_refused(openai_server, remote_settings):
    out = io.BytesIO()
    Image.new("RGB", (4, 4), (9, 9, 9)).save(out, format="JPEG")
    openai_server.script(GENERATE, image_reply(out.getvalue()), Reply({"data": [{"b64_json": "bm90IGFuIGltYWdl"}]}))
    backend = OpenAIImages("test-image", remote_settings)
    assert backend.reference_image("a", "realistic").startswith(b"\x89PNG")
    with pytest.raises(BackendError, match="not an image"):
        backend.reference_image("b", "realistic")


def test_rate_limits_are_waited_out(openai_server, remote_settings):
    openai_server.script(GENERATE, error_reply(429, headers=FAST), image_reply())
    assert OpenAIImages("test-image", remote_settings).reference_image("a park", "realistic") == png()
    assert len(openai_server.seen(GENERATE)) == 2


def test_objects_described_alike_share_one_drawing(openai_server, remote_settings):
    pair = [SceneObject(id=f"chair_{i}", name="chair", size=Vec3(x=0.5, y=0.5, z=0.9), visual_description="a red chair")
            for i in (1, 2)]
    seen = []
    backend = OpenAIImages("test-image", remote_settings)
    images = backend.object_images([*pair, *_objects(1)], "realistic", png(), seen.append)
    assert set(images) == {"chair_1", "chair_2", "crate_1"} and images["chair_1"] == images["chair_2"]
    assert sorted(note.split(":")[0] for note in seen) == ["chair_1", "chair_2", "crate_1"]
    assert len(openai_server.seen(EDIT)) == 2


def test_an_opaque_object_image_is_kept_with_a_warning(openai_server, remote_settings, caplog):
    opaque = io.BytesIO()
    Image.new("RGB", (4, 4), (9, 9, 9)).save(opaque, format="PNG")
    openai_server.script(EDIT, image_reply(opaque.getvalue()))
    images = OpenAIImages("test-image", remote_settings).object_images(_objects(1), "realistic", png())
    assert images["crate_1"] == opaque.getvalue()
    assert "image of crate_1 has no transparency" in caplog.text
