"""Settings layers: defaults, a TOML config file (explicit or ./scenewright.toml), then flags."""

from __future__ import annotations

from pathlib import Path

import pytest

from scenewright.cli import main
from scenewright.cli.options import build_settings
from scenewright.errors import InputError
from scenewright.settings import KEYS, Settings, default_cache_dir


def test_every_settings_field_is_a_config_key():
    assert set(KEYS) == set(Settings.__dataclass_fields__)


def test_file_then_flags(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    config = tmp_path / "remote.toml"
    config.write_text(
        'vlm = "openai:o3"\nimages = "openai:gpt-image-1"\nbase_url = "http://gpu:8000/v1"\n'
        'reasoning_effort = "high"\nimage_concurrency = 8\ntimeout = 30\ncache_dir = ""\n'
        '[extra]\nquality = "low"\n'
    )
    settings = build_settings(vlm="openai:qwen2.5-vl", config=config, image_concurrency=2, api_key_env=None)
    assert settings.vlm == "openai:qwen2.5-vl"  # the flag wins
    assert settings.images == "openai:gpt-image-1" and settings.base_url == "http://gpu:8000/v1"
    assert settings.reasoning_effort == "high" and settings.timeout == 30.0
    assert settings.image_concurrency == 2 and settings.api_key_env == "OPENAI_API_KEY"
    assert settings.cache_dir is None and settings.extra == {"quality": "low"}


def test_the_working_folder_config_is_read_when_no_file_is_named(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert build_settings().vlm == "offline"
    (tmp_path / "scenewright.toml").write_text('vlm = "openai:o3"\ncache_dir = "~/sw-cache"\n')
    settings = build_settings()
    assert settings.vlm == "openai:o3" and settings.cache_dir == Path("~/sw-cache").expanduser()


@pytest.mark.parametrize(
    "text, message",
    [
        ('vlm = "offline"\nmodel = "o3"\nconcurency = 2\n', "unknown keys concurency, model; valid keys: vlm, images"),
        ("image_concurrency = 0\n", "image_concurrency must be an integer >= 1, got 0"),
        ('timeout = "fast"\n', "timeout must be a finite number > 0, got 'fast'"),
        ("timeout = inf\n", "timeout must be a finite number > 0, got inf"),
        ("max_objects = 0\n", "max_objects must be an integer >= 1, got 0"),
        ("max_download_bytes = 10\n", "max_download_bytes must be an integer >= 1024, got 10"),
        ("max_answer_chars = -1\n", "max_answer_chars must be an integer >= 1000, got -1"),
        ("max_render_pixels = 1.5\n", "max_render_pixels must be an integer >= 256, got 1.5"),
        ('max_render_samples = "many"\n', "max_render_samples must be an integer >= 1, got 'many'"),
        ("max_retries = 1.5\n", "max_retries must be an integer >= 0"),
        ("vlm = [1]\n", "vlm must be a non-empty string"),
        ("max_faces = 50\n", "max_faces must be an integer >= 100 (or 0 for no limit), got 50"),
        ("vlm = \n", "is not valid TOML"),
    ],
)
def test_bad_config_files_name_the_key(tmp_path, text, message):
    config = tmp_path / "bad.toml"
    config.write_text(text)
    with pytest.raises(InputError) as err:
        build_settings(config=config)
    assert message in str(err.value) and str(config) in str(err.value)


def test_a_missing_config_file_is_bad_input(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        build_settings(config=tmp_path / "nope.toml")


def test_bad_flags_are_named_as_command_line(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(InputError, match="command line: feedback_rounds must be an integer >= 0"):
        build_settings(feedback_rounds=-1)


def test_the_cli_reports_a_bad_config_with_exit_code_2(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "scenewright.toml").write_text("colour = 'red'\n")
    assert main(["generate", "a table", "--out", str(tmp_path / "scene")]) == 2
    assert "unknown keys colour" in capsys.readouterr().err


def test_max_faces_zero_means_no_limit(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "scenewright.toml").write_text("max_faces = 20000\n")
    assert build_settings().max_faces == 20000
    assert build_settings(max_faces=0).max_faces is None


def test_library_settings_read_no_environment_and_the_cli_does(monkeypatch, tmp_path):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert Settings().cache_dir is None  # a library caller caches nothing until told where
    assert default_cache_dir({"XDG_CACHE_HOME": "/c"}) == Path("/c/scenewright")
    assert default_cache_dir({}) == Path.home() / ".cache" / "scenewright"
    monkeypatch.chdir(tmp_path)  # no scenewright.toml here
    assert build_settings().cache_dir == tmp_path / "xdg" / "scenewright"
