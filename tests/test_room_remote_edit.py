"""Room edits through a remote model (docs/rooms.md): the edit answer's ``room`` operation,
its schema and prompt, checked like every other answer, against the local fake OpenAI server."""

from __future__ import annotations

import pytest

from scenewright.backends.openai_chat import OpenAIChatVLM
from scenewright.backends.structured import strict_schema
from scenewright.backends.openai_chat import EditAnswer
from scenewright.errors import BackendError
from scenewright.scene import Opening, Room, Scene, SceneObject, Vec3
from scenewright.testing.fake_openai import CHAT, chat_reply


def _scene(room: bool = True) -> Scene:
    objects = [SceneObject(id="bed_1", name="bed", size=Vec3(x=1.6, y=2.0, z=0.5)),
               SceneObject(id="lamp_1", name="lamp", size=Vec3(x=0.3, y=0.3, z=0.5))]
    walls = Room.rectangle(4.0, 4.5)
    walls = Room.model_validate({**walls.model_dump(), "openings": [Opening(kind="door", wall=3, offset=3.0, width=0.9, height=2.1)]})
    return Scene(text="a bedroom with a bed and a lamp", objects=objects, room=walls if room else None)


def _edit(**kw):
    plan = {"operation": "room", "focus": "room", "constraints": [], "new_object": None, "yaw": None, "offset": None,
            "room": None}
    plan.update(kw)
    return chat_reply(plan)


def _room(width=None, depth=None, height=None, opening=None, side=None):
    return {"width": width, "depth": depth, "height": height, "opening": opening, "side": side}


def test_the_edit_schema_and_prompt_offer_the_room(openai_server, remote_settings):
    openai_server.script(CHAT, _edit(room=_room(5.0, 6.0)))
    plan = OpenAIChatVLM("test-model", remote_settings).plan_edit(_scene(), "make the room 5 by 6 metres").value
    assert plan.operation == "room" and plan.focus == "room" and plan.room.size == (5.0, 6.0)
    request = openai_server.seen(CHAT)[0]
    schema = request.json["response_format"]["json_schema"]["schema"]
    assert "room" in schema["required"] and "room" in schema["properties"]["operation"]["enum"]
    assert "4 m wide (x) by 4.5 m deep (y), 2.7 m high" in request.text and "a door on the left wall" in request.text
    assert '"room" (change the room itself' in request.text


def test_a_half_given_size_is_asked_again_then_a_window_is_added(openai_server, remote_settings):
    openai_server.script(CHAT, _edit(room=_room(width=5.0)), _edit(room=_room(opening="window", side="back")))
    plan = OpenAIChatVLM("test-model", remote_settings).plan_edit(_scene(), "add a window on the back wall").value
    assert plan.room.opening == "window" and plan.room.side == "back" and plan.room.size is None
    assert "needs both width and depth" in openai_server.seen(CHAT)[1].json["messages"][-1]["content"]


def test_a_room_edit_that_changes_nothing_or_has_no_room_is_told_back(openai_server, remote_settings):
    openai_server.script(CHAT, _edit(room=_room()), _edit(room=_room(height=3.0)))
    plan = OpenAIChatVLM("test-model", remote_settings).plan_edit(_scene(), "make the ceiling 3 m high").value
    assert plan.room.height == 3.0
    assert "must say what changes" in openai_server.seen(CHAT)[1].json["messages"][-1]["content"]
    openai_server.script(CHAT, *[_edit(room=_room(5.0, 6.0))] * 3)
    with pytest.raises(BackendError):
        OpenAIChatVLM("test-model", remote_settings).plan_edit(_scene(room=False), "make the room bigger")
    assert "has no room" in openai_server.seen(CHAT)[-1].json["messages"][-1]["content"]
    assert "The scene has no room (open ground)." in openai_server.seen(CHAT)[2].text


def test_the_strict_schema_of_the_room_answer_requires_every_field():
    room = strict_schema(EditAnswer)["$defs"]["ProposedRoomEdit"]
    assert sorted(room["required"]) == ["depth", "height", "opening", "side", "width"]
