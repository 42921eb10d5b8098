import json

import pytest

from scenewright.cli import main
from scenewright.layout import check
from scenewright.scene import SceneObject

ITEMS = [
    {"id": "table1", "name": "Dining Table", "position": {"x": 0, "y": 0, "z": 0.4},
     "rotation": {"x": 0, "y": 0, "z": 0}, "size": {"x": 1.6, "y": 0.9, "z": 0.75},
     "visual_description": "An oak dining table."},
    {"id": "chair1", "name": "Chair", "position": {"x": 0, "y": 0, "z": 0.45},
     "rotation": {"x": 0, "y": 0, "z": 0}, "size": {"x": 0.5, "y": 0.5, "z": 0.9},
     "visual_description": "A wooden chair."},
    {"id": "vase1", "name": "Vase", "position": {"x": 2, "y": 2, "z": 0},
     "rotation": {"x": 0, "y": 0, "z": 0}, "size": {"x": 0.2, "y": 0.2, "z": 0.4},
     "visual_description": "A blue vase."},
]
CONSTRAINTS = [
    {"type": "relative", "relation": "in front of", "source": "chair1", "target": "table1"},
    {"type": "rotation", "relation": "face to", "source": "chair1", "target": "table1"},
    {"type": "relative", "relation": "on", "source": "vase1", "target": "table1"},
]


def flat(text):
    """Rich wraps long lines to the terminal; compare words, not line breaks."""
    return " ".join(text.split())


def write(tmp_path, items=ITEMS, constraints=CONSTRAINTS):
    o, c = tmp_path / "objects.json", tmp_path / "constraints.json"
    o.write_text(json.dumps({"items": items}) if not isinstance(items, str) else items)
    c.write_text(json.dumps(constraints) if not isinstance(constraints, str) else constraints)
    return str(o), str(c), str(tmp_path / "layout.json")


def test_solves_the_paper_format(tmp_path, capsys):
    o, c, out = write(tmp_path)
    assert main(["solve", o, c, "-o", out, "--bounds", "6,6", "--seed", "2"]) == 0
    layout = json.loads(open(out).read())
    assert [i["id"] for i in layout["items"]] == ["table1", "chair1", "vase1"]
    assert layout["items"][2]["visual_description"] == "A blue vase."
    by = {i["id"]: SceneObject.model_validate(i) for i in layout["items"]}
    assert check("on", by["vase1"], by["table1"]) and check("face to", by["chair1"], by["table1"])
    assert sorted(layout["report"]["placed"]) == ["chair1", "table1", "vase1"]
    assert layout["report"]["unplaced"] == [] and layout["report"]["nodes"] >= 3
    assert "seconds" in layout["report"] and "Placed 3 of 3" in flat(capsys.readouterr().err)


def test_constraints_object_form_and_unknown_entries_are_dropped_not_fatal(tmp_path, capsys):
    extra = CONSTRAINTS + [{"relation": "under", "source": "vase1", "target": "table1"},
                           {"relation": "near", "source": "ghost", "target": "table1"}]
    o, c, out = write(tmp_path, constraints={"constraints": extra})
    assert main(["solve", o, c, "-o", out]) == 0
    dropped = json.loads(open(out).read())["report"]["dropped"]
    assert "unknown relation 'under'" in dropped[0]["reason"]
    assert "unknown object 'ghost'" in dropped[1]["reason"]
    assert "Dropped constraints" in flat(capsys.readouterr().err)


def test_some_unplaced_exits_3_and_still_writes(tmp_path, capsys):
    cons = CONSTRAINTS + [{"relation": "left of", "source": "vase1", "target": "table1"}]
    o, c, out = write(tmp_path, constraints=cons)
    assert main(["solve", o, c, "-o", out]) == 3
    report = json.loads(open(out).read())["report"]
    [u] = report["unplaced"]
    assert u["id"] == "vase1" and u["reason"] and u["failed"]
    err = flat(capsys.readouterr().err)
    assert "1 of 3 objects could not be placed (vase1)" in err and "vase1" in err


@pytest.mark.parametrize(
    "items, constraints, message",
    [
        ("{not json", CONSTRAINTS, "objects.json: not valid JSON"),
        (ITEMS, "[1, 2", "constraints.json: not valid JSON"),
        ([{k: v for k, v in ITEMS[0].items() if k != "size"}], [], "items[0].size: missing"),
        ([{**ITEMS[0], "size": {"x": -1, "y": 1, "z": 1}}], [], "items[0]: size: Value error, every size must be between 0.001 and 1000 metres"),
        ([{k: v for k, v in ITEMS[0].items() if k != "id"}], [], "items[0]: id: Field required"),
        ([ITEMS[0], ITEMS[0]], [], "id 'table1' used more than once"),
        ("[]", [], 'expected an object with an "items" list'),
        (ITEMS, [{"relation": "near", "source": "vase1"}], "constraints[0].target: missing"),
        (ITEMS, {"near": 1}, "expected a JSON list of constraints"),
    ],
)
def test_bad_input_exits_2_naming_file_and_field(tmp_path, capsys, items, constraints, message):
    o, c, out = write(tmp_path, items, constraints)
    assert main(["solve", o, c, "-o", out]) == 2
    assert message in flat(capsys.readouterr().err)


def test_bad_flags_and_missing_files_exit_2(tmp_path, capsys):
    o, c, out = write(tmp_path)
    assert main(["solve", o, c, "-o", out, "--bounds", "6"]) == 2
    assert "--bounds: expected W,D" in flat(capsys.readouterr().err)
    assert main(["solve", str(tmp_path / "nope.json"), c, "-o", out]) == 2
    assert "nope.json: no such file" in flat(capsys.readouterr().err)


def test_bench_layout_prints_one_json_object(capsys):
    assert main(["bench", "layout", "--sizes", "4,6", "--seeds", "2", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert set(result["sizes"]) == {"4", "6"}
    row = result["sizes"]["6"]
    assert row["success_rate"] == 1.0 and row["colliding_pairs"] == 0 and row["constraints_satisfied"] == 1.0
    assert row["median_seconds"] <= row["p90_seconds"] <= row["max_seconds"]


def test_usage_errors_exit_2_with_the_usage(tmp_path, capsys):
    o, c, out = write(tmp_path)
    assert main(["solve", o, c, "-o", out, "--no-such-flag"]) == 2
    err = flat(capsys.readouterr().err)
    assert "No such option: --no-such-flag" in err and "scenewright solve --help" in err
    assert main(["solve", o]) == 2
    assert "Missing argument" in flat(capsys.readouterr().err)


def test_bench_layout_hard_prints_this_version_per_row(capsys):
    assert main(["bench", "layout", "--hard", "--sizes", "5", "--seeds", "1", "--room-seeds", "0"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["benchmark"] == "layout-hard" and list(result["rows"]) == ["n=5"]
    row = result["rows"]["n=5"]["this"]
    assert row["problems"] == 1 and row["colliding_pairs"] == 0 and 0.0 <= row["solved_share"] <= 1.0
    assert "baseline" not in result["rows"]["n=5"]


def test_bench_layout_baseline_needs_hard_and_a_checkout(tmp_path, capsys):
    assert main(["bench", "layout", "--baseline", str(tmp_path)]) == 2
    assert "add --hard" in flat(capsys.readouterr().err)
    assert main(["bench", "layout", "--hard", "--sizes", "3", "--seeds", "1", "--room-seeds", "0",
                 "--baseline", str(tmp_path)]) == 2
    assert "no src/scenewright there" in flat(capsys.readouterr().err)
