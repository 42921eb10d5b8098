"""The package root: the stage functions a library user calls, imported only when first read."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import scenewright

SRC = Path(__file__).resolve().parents[1] / "src"


def _modules_after(code: str) -> set[str]:
    out = subprocess.run(
        [sys.executable, "-c", f"import sys; {code}; print(' '.join(sys.modules))"],
        capture_output=True, text=True, check=True, env={"PYTHONPATH": str(SRC), "PATH": ""},
    )
    return set(out.stdout.split())


def test_every_public_name_resolves_to_what_its_module_defines():
    import importlib

    for name in scenewright.__all__:
        value = getattr(scenewright, name)
        assert value is not None
        if name in scenewright._LAZY:
            assert value is getattr(importlib.import_module(scenewright._LAZY[name]), name)
    assert set(scenewright._LAZY) <= set(dir(scenewright))


def test_a_stage_is_imported_on_first_use_only():
    assert "scenewright.pipeline" not in _modules_after("import scenewright")
    assert "scenewright.pipeline" in _modules_after("import scenewright; scenewright.generate")


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'generat'"):
        scenewright.generat  # noqa: B018


def test_the_package_says_it_is_typed():
    assert (SRC / "scenewright" / "py.typed").is_file()
    assert '"py.typed"' in (SRC.parent / "pyproject.toml").read_text(encoding="utf-8")
