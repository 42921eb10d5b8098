"""Text from outside is printed literally: Rich markup escaped, control characters gone."""

import json

from scenewright.cli import main
from scenewright.cli.display import printable, safe


def test_safe_escapes_markup_and_strips_control_characters():
    assert safe("[red]chair[/red]") == "\\[red]chair\\[/red]"
    assert safe("a\x1b[2Jb\x9bc\x07") == "a?[2Jb?c?"
    assert printable("line one\nline\ttwo\x00") == "line one\nline\ttwo?"


def test_a_model_supplied_name_in_an_error_is_printed_raw_no_more(tmp_path, capsys):
    # The id is checked by the schema, so it reaches the message as the user wrote it.
    scene = {"text": "t", "objects": [{"id": "[bold red]x\x1b[2J", "name": "n", "size": {"x": 1, "y": 1, "z": 1}}]}
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    assert main(["render", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "[bold red]x" in err and "\x1b" not in err
