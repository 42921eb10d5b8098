import pytest

from scenewright.backends import REGISTRY, available_backends, create_backend
from scenewright.errors import InputError
from scenewright.settings import Settings


def test_unknown_backend_names_the_choices():
    with pytest.raises(InputError, match="choose one of: offline, openai"):
        create_backend("vlm", "gemini:pro", Settings())
    with pytest.raises(InputError, match="kinds are"):
        create_backend("sound", "offline", Settings())


def test_every_registered_backend_is_reported():
    report = available_backends()
    assert {k: set(v) for k, v in report.items()} == {k: set(v) for k, v in REGISTRY.items()}


def test_offline_defaults_need_nothing_but_the_core():
    report = available_backends()
    assert report["vlm"]["offline"] == "ok"
    assert report["images"]["offline"] == "ok"
    assert report["meshes"]["procedural"] == "ok"
