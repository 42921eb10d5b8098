"""The ``bench`` command group: every benchmark's options, and ``--json``/``--text`` output."""

from __future__ import annotations

import json
from pathlib import Path

from scenewright.cli import main
from scenewright.cli.bench import flat

PROMPTS = Path(__file__).resolve().parents[1] / "benchmarks" / "prompts"


def test_flat_names_every_figure_by_its_path():
    result = {"a": 1, "b": {"c": 0.5, "d": [1, 2]}, "rows": [{"x": "y"}], "none": None}
    assert flat(result) == ["a: 1", "b.c: 0.5", "b.d: [1, 2]", "rows.0.x: \"y\"", "none: null"]


def test_json_is_one_object_and_text_one_line_per_figure(capsys):
    one = sorted(PROMPTS.iterdir())[0]
    assert main(["bench", "parse", "--prompts", str(one), "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["prompts"] == 1
    assert main(["bench", "parse", "--prompts", str(one), "--text"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines == flat(result)
    assert "prompts: 1" in lines
