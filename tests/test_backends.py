import pytest

from scenewright.backends import REGISTRY, _resolve, available_backends, create_backend
from scenewright.core.protocols import ImageGenerator, MeshGenerator, VisionLanguageModel
from scenewright.errors import InputError
from scenewright.settings import Settings


def test_unknown_backend_names_the_choices():
    with pytest.raises(InputError, match="choose one of: offline, openai"):
        create_backend("vlm", "gemini:pro", Settings())
    with pytest.raises(InputError, match="kinds are"):
        create_backend("sound", "offline", Settings())


def test_a_backend_that_cannot_load_is_reported_with_the_reason(monkeypatch):
    monkeypatch.setitem(REGISTRY["meshes"], "ghost", "scenewright.no_such_backend:Ghost")
    report = available_backends()
    assert report["meshes"]["procedural"] == "ok"
    assert report["meshes"]["ghost"] != "ok" and "no_such_backend" in report["meshes"]["ghost"]


@pytest.mark.parametrize("kind, protocol", [("vlm", VisionLanguageModel), ("images", ImageGenerator),
                                            ("meshes", MeshGenerator)])
def test_every_registered_backend_offers_its_protocol(kind, protocol):
    methods = [m for m in dir(protocol) if not m.startswith("_") and callable(getattr(protocol, m))]
    assert methods
    for name in REGISTRY[kind]:
        cls = _resolve(kind, name)
        assert callable(getattr(cls, "from_spec", None)), f"{kind} backend {name} has no from_spec"
        missing = [m for m in methods if not callable(getattr(cls, m, None))]
        assert missing == [], f"{kind} backend {name} lacks {missing}"


def test_offline_defaults_need_nothing_but_the_core():
    report = available_backends()
    assert report["vlm"]["offline"] == "ok"
    assert report["images"]["offline"] == "ok"
    assert report["meshes"]["procedural"] == "ok"
