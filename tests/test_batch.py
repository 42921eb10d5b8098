"""`scenewright batch` end to end, offline: twelve entries (one bad) on two spawned workers give
eleven scenes and a record of the bad one; Ctrl-C and a kill mid-batch lose nothing finished and
a re-run completes the same eleven scenes without redoing any; Ray in local mode gives the same
documents. Reading prompts files, the dataset files and the shared limiter are tested apart."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from scenewright.batch import RayOptions, read_entries, run_batch
from scenewright.batch.entries import text_id
from scenewright.cli import main
from scenewright.settings import Settings

#: Small scenes (two to five objects) so twelve of them cost little.
GOOD = [
    "A cosy reading corner with an armchair and a floor lamp to the right of the armchair.",
    "A kitchen with a fridge and a stove to the left of the fridge.",
    "A desk with a laptop on it and an office chair in front of the desk.",
    "A bedroom with a bed and a nightstand to the left of the bed.",
    "A garden with a bench and a tree behind the bench.",
    "A cartoon-style playground with a slide and a swing to the right of the slide.",
    "A dining table with two chairs near it.",
    "A bathroom with a bathtub and a sink to the right of the bathtub.",
    "A market stall with a barrel in front of it and a crate next to the barrel.",
    "A living room with a sofa and a coffee table in front of the sofa.",
    "A low-poly campsite with a tent and a campfire in front of the tent.",
]
BAD = "zzz qqq blorp"  # no object the offline parser knows: the scene fails, the batch goes on
SRC = str(Path(__file__).resolve().parents[1] / "src")


def _prompts(tmp_path: Path) -> Path:
    path = tmp_path / "prompts.txt"
    lines = ["# twelve entries, one of them bad", *GOOD[:6], BAD, *GOOD[6:]]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    # No request cache in any run: which assets came from a cache would differ between runs.
    (tmp_path / "no-cache.toml").write_text('cache_dir = ""\n', encoding="utf-8")
    return path


def _args(prompts: Path, out: Path) -> list[str]:
    config = prompts.parent / "no-cache.toml"
    return ["batch", str(prompts), "--out", str(out), "--workers", "2", "--no-render", "--config", str(config)]


def _comparable(path: Path) -> dict:
    """scene.json without what differs by nature between two runs: wall-clock stamps, the
    solver's measured seconds (in its report and in each layout round's provenance), and which
    assets the asset stage built in this run (a run interrupted in that stage keeps the assets
    it finished, so its resume records only the rest; the scene.glb hash still compares them)."""
    doc = json.loads(path.read_text(encoding="utf-8"))
    doc["provenance"] = [e for e in doc["provenance"] if e["stage"] != "assets"]
    for event in doc["provenance"]:
        event.pop("time")
        event["data"].pop("seconds", None)
    if doc.get("layout"):
        doc["layout"].pop("seconds")
    return doc


def _scenes(out: Path) -> dict[str, dict]:
    return {p.parent.name: _comparable(p) for p in sorted(out.glob("*/scene.json"))}


def _graphs(out: Path) -> list[Path]:
    return sorted(out.glob("*/scene_graph.json"))


@pytest.fixture(scope="module")
def fresh(tmp_path_factory):
    """One uninterrupted batch through the CLI: (prompts file, output folder, exit code).

    Made once per test session: under pytest-xdist the workers share it through a lock in
    the session's temporary folder, so the twelve scenes are not made once per worker.
    """
    import fcntl

    base = tmp_path_factory.getbasetemp()
    shared = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base
    tmp = shared / "batch-fresh"
    with open(shared / "batch-fresh.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not (tmp / "exit-code").is_file():
            tmp.mkdir(exist_ok=True)
            code = main(_args(_prompts(tmp), tmp / "out"))
            (tmp / "exit-code").write_text(str(code))
    return tmp / "prompts.txt", tmp / "out", int((tmp / "exit-code").read_text())


@pytest.mark.slow
def test_twelve_entries_one_bad_give_eleven_scenes_and_a_record(fresh):
    prompts, out, code = fresh
    assert code == 1  # some scene failed: the record says which
    record = json.loads((out / "batch.json").read_text())
    totals = record["totals"]
    assert (totals["entries"], totals["done"], totals["failed"], totals["pending"]) == (12, 11, 1, 0)
    failed = [s for s in record["scenes"] if s["status"] == "failed"]
    assert len(failed) == 1
    assert failed[0]["text"] == BAD and failed[0]["line"] == 8 and failed[0]["error"] == "input"
    assert "no object recognised" in failed[0]["reason"]
    assert not (out / failed[0]["id"]).exists()  # the pipeline leaves no half scene behind
    assert "no object recognised" in (out / "batch.md").read_text()
    assert len(_graphs(out)) == 11
    index = [json.loads(line) for line in (out / "index.jsonl").read_text().splitlines()]
    assert [row["id"] for row in index] == [s["id"] for s in record["scenes"] if s["status"] == "done"]
    for row in index:
        graph = json.loads((out / row["scene_graph"]).read_text())
        assert graph["id"] == row["id"] and graph["objects"] and (out / row["glb"]).is_file()
        assert row["objects"] == len(graph["objects"]) == graph["metrics"]["objects"]


def test_scene_graph_holds_poses_supports_and_relations(fresh):
    _, out, _ = fresh
    graph = json.loads(next(p for p in _graphs(out) if "desk" in p.parent.name).read_text())
    objects = {o["id"]: o for o in graph["objects"]}
    laptop = next(o for o in objects.values() if o["category"] == "laptop")
    desk = next(o for o in objects.values() if o["category"] == "desk")
    assert laptop["support"] == desk["id"] and desk["support"] is None
    geometric = {(r["source"], r["relation"], r["target"]) for r in graph["relations"]["geometric"]}
    assert (laptop["id"], "on", desk["id"]) in geometric
    assert all(r["holds"] for r in graph["relations"]["stated"])
    stated = {(r["source"], r["relation"], r["target"]) for r in graph["relations"]["stated"]}
    assert (laptop["id"], "on", desk["id"]) in stated
    for obj in objects.values():
        q = obj["pose"]["quaternion"]
        assert abs(sum(v * v for v in q) - 1.0) < 1e-6
        assert all(lo <= p <= hi for lo, p, hi in zip(obj["box"]["min"], obj["pose"]["position"], obj["box"]["max"]))


def _run_cli(prompts: Path, out: Path) -> subprocess.Popen:
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([SRC, os.environ.get("PYTHONPATH", "")])}
    return subprocess.Popen(
        [sys.executable, "-m", "scenewright", *_args(prompts, out)],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,  # its own process group: the kill below takes the workers too
        # A test runner started in the background inherits SIGINT ignored; Ctrl-C must reach the CLI.
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )


def _wait_for_scenes(out: Path, count: int, process: subprocess.Popen, timeout: float = 240.0) -> None:
    deadline = time.monotonic() + timeout
    while len(_graphs(out)) < count:
        assert process.poll() is None, process.communicate()
        assert time.monotonic() < deadline, "the batch made no progress"
        time.sleep(0.1)


@pytest.mark.slow
def test_ctrl_c_then_kill_then_rerun_gives_the_same_scenes(fresh, tmp_path):
    prompts, fresh_out, _ = fresh
    out = tmp_path / "out"
    # Ctrl-C (SIGINT to the parent only): a clean stop, exit 130, no traceback.
    first = _run_cli(prompts, out)
    _wait_for_scenes(out, 2, first)
    first.send_signal(signal.SIGINT)
    _, err = first.communicate(timeout=120)
    assert first.returncode == 130, err
    assert "Traceback" not in err
    record = json.loads((out / "batch.json").read_text())
    assert record["interrupted"] is True and record["totals"]["done"] >= 2
    # A hard kill of the whole process group mid-batch.
    second = _run_cli(prompts, out)
    _wait_for_scenes(out, len(_graphs(out)) + 1, second)
    os.killpg(second.pid, signal.SIGKILL)
    second.communicate(timeout=60)
    before = {p.parent.name: (p.stat().st_mtime_ns, (p.parent / "scene.json").stat().st_mtime_ns) for p in _graphs(out)}
    assert 3 <= len(before) < 11
    # The re-run finishes the rest and touches no finished scene.
    assert main(_args(prompts, out)) == 1
    record = json.loads((out / "batch.json").read_text())
    status = {s["id"]: s["status"] for s in record["scenes"]}
    assert all(status[name] == "finished" for name in before)
    assert sorted(status.values()).count("done") == 11 - len(before)
    after = {p.parent.name: (p.stat().st_mtime_ns, (p.parent / "scene.json").stat().st_mtime_ns) for p in _graphs(out)}
    assert {k: after[k] for k in before} == before
    assert _scenes(out) == _scenes(fresh_out)


@pytest.mark.slow
def test_ray_local_mode_gives_identical_scene_documents(fresh, tmp_path):
    ray = pytest.importorskip("ray", reason="the batch extra (ray) is not installed")
    prompts, fresh_out, _ = fresh
    entries, _ = read_entries(prompts)
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        record = run_batch(entries, tmp_path / "out", settings=Settings(cache_dir=None), workers=2, render=False, ray=RayOptions())
    finally:
        ray.shutdown()
    assert record.executor == "ray" and record.totals()["done"] == 11 and record.totals()["failed"] == 1
    assert _scenes(tmp_path / "out") == _scenes(fresh_out)
    fresh_graphs = {p.parent.name: json.loads(p.read_text())["relations"] for p in _graphs(fresh_out)}
    ray_graphs = {p.parent.name: json.loads(p.read_text())["relations"] for p in _graphs(tmp_path / "out")}
    assert ray_graphs == fresh_graphs


# --- reading prompts -------------------------------------------------------------------------


@pytest.mark.slow
def test_jsonl_bad_lines_are_named_by_number_and_skipped_or_refused(tmp_path, capsys):
    path = tmp_path / "prompts.jsonl"
    path.write_text(
        "\n".join(
            [
                '{"id": "corner", "text": "an armchair and a floor lamp", "style": "cartoon", "seed": 3}',
                '{"id": "broken", "text": "a sofa"',  # line 2: not JSON
                '["a list"]',  # line 3
                '{"id": "../escape", "text": "a bed"}',  # line 4: not a folder name
                '{"id": "kitchen", "text": "a fridge", "vlm": "openai:o3", "colour": "red"}',  # line 5: unknown key
                '{"id": "corner", "text": "a tree"}',  # line 6: duplicate id
                '{"id": "desk", "text": "a desk", "feedback_rounds": -1}',  # line 7: bad override
                '{"text": "a garden with a bench"}',
            ]
        )
        + "\n"
    )
    entries, problems = read_entries(path)
    assert [e.id for e in entries][0] == "corner" and len(entries) == 2
    assert entries[0].style == "cartoon" and entries[0].seed == 3
    assert [p.line for p in problems] == [2, 3, 4, 5, 6, 7]
    reasons = {p.line: p.reason for p in problems}
    assert "not valid JSON" in reasons[2] and "unknown keys colour" in reasons[5] and "line 1" in reasons[6]
    assert "feedback_rounds must be an integer >= 0" in reasons[7]
    assert main(["batch", str(path), "--out", str(tmp_path / "out"), "--strict"]) == 2
    err = " ".join(capsys.readouterr().err.split())
    assert "6 lines cannot be used: line 2: not valid JSON" in err and "Traceback" not in err
    assert not (tmp_path / "out").exists()
    # Without --strict the bad lines are named and skipped, the good ones made, the record lists them.
    assert main(["batch", str(path), "--out", str(tmp_path / "out"), "--workers", "1", "--no-render"]) == 0
    err = " ".join(capsys.readouterr().err.split())
    assert f"skipped {path}:2: not valid JSON" in err and f"skipped {path}:7:" in err and "Traceback" not in err
    record = json.loads((tmp_path / "out" / "batch.json").read_text())
    assert [p["line"] for p in record["skipped_lines"]] == [2, 3, 4, 5, 6, 7]
    assert record["totals"]["done"] == 2 and (tmp_path / "out" / "corner" / "scene_graph.json").is_file()


def test_text_ids_are_stable_and_seeds_multiply_entries(tmp_path):
    path = tmp_path / "prompts.txt"
    path.write_text("a sofa and a lamp\n\n# comment\na bed\n")
    entries, problems = read_entries(path, style="anime", seeds=[0, 1])
    assert not problems
    sofa, bed = text_id("a sofa and a lamp"), text_id("a bed")
    assert sofa.startswith("a-sofa-and-a-") and sofa != bed
    assert [e.id for e in entries] == [f"{sofa}-seed0", f"{sofa}-seed1", f"{bed}-seed0", f"{bed}-seed1"]
    assert {e.style for e in entries} == {"anime"} and [e.seed for e in entries] == [0, 1, 0, 1]
    path.write_text("a bed\na sofa and a lamp\n")  # reordered: same ids
    again, _ = read_entries(path, style="anime", seeds=[0, 1])
    assert {e.id for e in again} == {e.id for e in entries}


def test_ray_missing_names_the_extra(monkeypatch, tmp_path, capsys):
    monkeypatch.setitem(sys.modules, "ray", None)  # as if the batch extra were not installed
    prompts = tmp_path / "prompts.txt"
    prompts.write_text("a bed and a nightstand\n")
    assert main(["batch", str(prompts), "--out", str(tmp_path / "out"), "--ray", "local", "--no-render"]) == 1
    err = " ".join(capsys.readouterr().err.split())
    assert "pip install 'scenewright[batch]'" in err and "Traceback" not in err


#: The five-line loader the README shows, run as written against a batch folder.
LOADER = """
import json, pathlib
root = pathlib.Path(BATCH)
for row in map(json.loads, (root / "index.jsonl").read_text().splitlines()):
    graph = json.loads((root / row["scene_graph"]).read_text())
    print(row["id"], [(o["category"], o["pose"]["position"], o["support"]) for o in graph["objects"]])
"""


def test_the_readme_loader_reads_every_scene(fresh, capsys):
    _, out, _ = fresh
    capsys.readouterr()
    exec(LOADER, {"BATCH": str(out)})
    printed = capsys.readouterr().out.splitlines()
    assert len(printed) == 11 and all("(" in line for line in printed)


def test_a_jsonl_entry_chooses_its_room(tmp_path):
    path = tmp_path / "prompts.jsonl"
    path.write_text(
        '{"id": "open", "text": "a bedroom with a bed and a wardrobe", "room": "none"}\n'
        '{"id": "sized", "text": "a bedroom with a bed and a wardrobe", "room": "4x5"}\n'
        '{"id": "bad", "text": "a bedroom with a bed", "room": "0x5"}\n'
        '{"id": "odd", "text": "a bedroom with a bed", "room": 4}\n'
    )
    entries, problems = read_entries(path)
    assert [(e.id, e.room) for e in entries] == [("open", "none"), ("sized", "4x5")]
    reasons = {p.line: p.reason for p in problems}
    assert "room '0x5'" in reasons[3] and "'room' must be a string" in reasons[4]
    record = run_batch(entries, tmp_path / "out", settings=Settings(cache_dir=None), workers=1, render=False)
    assert record.totals()["done"] == 2
    open_scene = json.loads((tmp_path / "out" / "open" / "scene.json").read_text())
    sized = json.loads((tmp_path / "out" / "sized" / "scene.json").read_text())
    assert open_scene["room"] is None
    xs, ys = zip(*sized["room"]["floor"])
    assert (max(xs) - min(xs), max(ys) - min(ys)) == (4.0, 5.0)
