"""Fixtures shared by test modules."""

from __future__ import annotations

import pytest

from scenewright.testing.fake_openai import FakeOpenAI
from scenewright.settings import Settings

#: The edited-scene fixtures (``template``, ``folder``) live with the scenes they build.
pytest_plugins = ["editing_scenes"]


@pytest.fixture(autouse=True)
def private_cache(tmp_path_factory, monkeypatch):
    """Commands that build their own Settings cache under XDG_CACHE_HOME: never the user's."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path_factory.mktemp("xdg-cache")))


@pytest.fixture
def openai_server():
    """A scripted OpenAI-compatible server on 127.0.0.1 (see scenewright.testing.fake_openai)."""
    with FakeOpenAI() as server:
        yield server


@pytest.fixture
def remote_settings(openai_server, tmp_path):
    """Settings for the OpenAI backends against ``openai_server``, with a private cache."""
    return Settings(
        base_url=openai_server.url, cache_dir=tmp_path / "cache", max_retries=2, timeout=5.0, image_concurrency=3
    )
