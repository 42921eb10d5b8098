"""Run the Khronos glTF validator (``tools/validate-gltf.mjs``, installed by ``make tools``)."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

TOOLS = Path(__file__).resolve().parents[1] / "tools"


def validate(path: Path) -> dict:
    """The validator's JSON report on ``path``; skips the test when the validator is not installed."""
    node = shutil.which("node")
    if node is None or not (TOOLS / "node_modules" / "gltf-validator").is_dir():
        pytest.skip("the glTF validator is not installed; run `make tools`")
    proc = subprocess.run(
        [node, str(TOOLS / "validate-gltf.mjs"), str(path)], capture_output=True, text=True, timeout=120
    )
    assert proc.returncode in (0, 1), proc.stderr
    return json.loads(proc.stdout)


def assert_valid(path: Path) -> dict:
    """Zero errors per the validator; returns the report for further checks."""
    report = validate(path)
    errors = [m for m in report["issues"]["messages"] if m["severity"] == 0]
    assert report["issues"]["numErrors"] == 0, errors
    return report
