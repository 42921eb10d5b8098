"""A scene folder after a run that died: stale files removed, a mismatched GLB rebuilt, a
first save finished, and — killed at random points of ``generate`` and ``edit`` — always a
folder that resumes to what an uninterrupted run makes."""

from __future__ import annotations

import hashlib
import json
import os
import random
import shutil
import signal
import threading
import time
from pathlib import Path

import pytest

from editing_scenes import build_folder, snapshot
from scenewright.cli import main
from scenewright.editing import entries
from scenewright.folder import SceneFolder
from scenewright.integrity import temporaries
from scenewright.lock import LOCK_NAME
from scenewright.scene import Scene

TEXT = "a wooden table with a chair and a lamp"


@pytest.fixture(autouse=True)
def private_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.chdir(tmp_path)


def sha(path: Path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def canonical(folder: SceneFolder) -> dict:
    """The document without what differs between two runs of the same work (times, provenance)."""
    data = folder.load().model_dump(mode="json")
    data.pop("provenance")
    if data["layout"] is not None:
        data["layout"].pop("seconds")
    return data


def whole(folder: SceneFolder) -> None:
    """What every folder must be after a command finished in it."""
    assert temporaries(folder) == []
    assert not (folder.root / LOCK_NAME).exists()
    assert not (folder.history / "pending.json").exists()
    scene = folder.load()
    if scene.glb_sha256 is not None:
        assert sha(folder.glb) == scene.glb_sha256


# --- the pieces, one at a time ----------------------------------------------------------------


def test_a_writing_command_removes_temporary_files_left_by_a_killed_run(tmp_path):
    folder = build_folder(tmp_path / "scene")
    assert main(["edit", str(folder.root), "move the armchair half a metre to the left"]) == 0
    stale = [folder.root / ".scene.json.k2j4_x9a.tmp", folder.assets / ".sofa_1.glb.abcdefgh.tmp",
             folder.history / ".log.jsonl.0123abcd.tmp"]
    for path in stale:
        path.write_bytes(b"half")
    keep = folder.root / "notes.tmp"  # not a name an atomic write makes: the user's
    keep.write_text("mine")
    assert main(["undo", str(folder.root)]) == 0
    assert not any(p.exists() for p in stale) and keep.exists()
    whole(folder)


def test_a_glb_newer_than_the_document_is_rebuilt_by_the_next_command(tmp_path):
    folder = SceneFolder(tmp_path / "scene")
    assert main(["generate", TEXT, "--out", str(folder.root), "--no-render"]) == 0
    assert main(["edit", str(folder.root), "move the chair half a metre to the left"]) == 0
    edited_glb = folder.glb.read_bytes()
    assert main(["undo", str(folder.root)]) == 0
    original_glb = folder.glb.read_bytes()
    folder.glb.write_bytes(edited_glb)  # what a kill between the GLB and the document leaves
    assert main(["redo", str(folder.root)]) == 0
    assert folder.glb.read_bytes() == edited_glb
    folder.glb.write_bytes(original_glb)  # and the other way round, found by --resume
    assert main(["generate", "--resume", str(folder.root), "--no-render"]) == 0
    assert folder.glb.read_bytes() == edited_glb
    whole(folder)


def test_a_first_save_killed_before_its_rename_is_finished_by_resume(tmp_path):
    out = tmp_path / "scene"
    assert main(["generate", TEXT, "--out", str(out), "--no-render"]) == 0
    reference = canonical(SceneFolder(out))
    first = Scene.model_validate(
        {"text": TEXT, "style": reference["style"], "ground": {"kind": reference["ground"]["kind"]}}
    ).to_json()
    shutil.rmtree(out)
    out.mkdir()
    (out / ".scene.json.abcd1234.tmp").write_text(first)  # all a kill in the first save leaves
    assert main(["generate", "--resume", str(out), "--no-render"]) == 0
    assert canonical(SceneFolder(out)) == reference
    whole(SceneFolder(out))


def test_a_first_save_cut_short_mid_write_leaves_a_folder_generate_can_use(tmp_path):
    out = tmp_path / "scene"
    out.mkdir()
    (out / ".scene.json.abcd1234.tmp").write_text('{"schema_version": 1, "te')
    assert main(["generate", "--resume", str(out), "--no-render"]) == 2  # nothing to resume from
    assert main(["generate", TEXT, "--out", str(out), "--no-render"]) == 0
    assert not (out / ".scene.json.abcd1234.tmp").exists()
    whole(SceneFolder(out))


def test_an_edit_whose_document_was_never_saved_is_not_in_the_history(tmp_path, monkeypatch):
    folder = build_folder(tmp_path / "scene")
    before = snapshot(folder.root)
    from scenewright.editing import history

    def die(path, data):  # the document's write is the one that fails
        if Path(path) == folder.document:
            raise KeyboardInterrupt
        return real(path, data)

    real = history.write_atomic
    monkeypatch.setattr(history, "write_atomic", die)
    assert main(["edit", str(folder.root), "move the armchair half a metre to the left"]) == 130
    monkeypatch.undo()
    assert snapshot(folder.root) == before  # the rollback took back the GLB and the history
    assert entries(folder) == []
    assert main(["undo", str(folder.root)]) == 2


# --- kills at random points -------------------------------------------------------------------

#: Kill points per command: write events chosen at random, and moments chosen at random.
EVENT_KILLS = {"generate": 16, "edit": 14}
TIME_KILLS = {"generate": 4, "edit": 4}


def _run_killed(argv: list[str], *, at_event: int | None = None, after: float | None = None) -> tuple[int, int]:
    """Run the CLI in a forked child that SIGKILLs itself at its ``at_event``-th write event or
    ``after`` seconds; returns (exit status, write events seen). Status -9: it was killed.

    A write event is the moment a temporary file is complete (fsynced, not yet renamed) or the
    moment its rename is done: the points at which a document, a GLB or a history file changes.
    """
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: no pytest machinery from here on, only os._exit
        code = 99
        try:
            os.close(read)
            seen = [0]
            real_fsync, real_replace = os.fsync, os.replace

            def tick():
                seen[0] += 1
                os.write(write, b".")
                if seen[0] == at_event:
                    os.kill(os.getpid(), signal.SIGKILL)

            def fsync(fd):
                real_fsync(fd)
                tick()

            def replace(src, dst, **kwargs):
                real_replace(src, dst, **kwargs)
                tick()

            os.fsync, os.replace = fsync, replace
            if after is not None:
                threading.Timer(after, os.kill, (os.getpid(), signal.SIGKILL)).start()
            code = main(argv)
        finally:
            os._exit(code)
    os.close(write)
    events = b""
    while chunk := os.read(read, 4096):
        events += chunk
    os.close(read)
    _, status = os.waitpid(pid, 0)
    return os.waitstatus_to_exitcode(status), len(events)


def _plan(command: str, events: int, seconds: float, rng: random.Random) -> list[tuple[str, float]]:
    points = [("event", float(e)) for e in rng.sample(range(1, events + 1), min(EVENT_KILLS[command], events))]
    return points + [("time", rng.uniform(0.0, seconds)) for _ in range(TIME_KILLS[command])]


def _timed(argv: list[str]) -> tuple[int, float]:
    """Write events and seconds of an uninterrupted run (with what the first run cached)."""
    start = time.monotonic()
    status, events = _run_killed(argv)
    assert status == 0
    return events, time.monotonic() - start


def test_generate_killed_at_random_points_resumes_to_the_uninterrupted_result(tmp_path):
    reference = SceneFolder(tmp_path / "reference")
    assert _run_killed(["generate", TEXT, "--out", str(reference.root), "--no-render"])[0] == 0
    expected, expected_glb = canonical(reference), sha(reference.glb)
    again = SceneFolder(tmp_path / "again")
    events, seconds = _timed(["generate", TEXT, "--out", str(again.root), "--no-render"])
    assert events > 10 and canonical(again) == expected and sha(again.glb) == expected_glb
    outcomes: dict[str, int] = {}
    for k, (kind, point) in enumerate(_plan("generate", events, seconds, random.Random(11))):
        folder = SceneFolder(tmp_path / f"killed-{k}")
        command = ["generate", TEXT, "--out", str(folder.root), "--no-render"]
        status, _ = _run_killed(command, **({"at_event": int(point)} if kind == "event" else {"after": point}))
        assert status in (0, -signal.SIGKILL)
        if folder.document.exists() or list(folder.root.glob(".scene.json.*.tmp")):
            resumed = main(["generate", "--resume", str(folder.root), "--no-render"])
            if resumed == 2 and not folder.document.exists():  # a first save cut short mid-write
                resumed, how = main(command), "first save cut short: generate again"
            else:
                how = "generate --resume"
        else:
            resumed, how = main(command), "nothing saved: generate again"
        assert resumed == 0, (kind, point)
        assert canonical(folder) == expected, (kind, point)
        assert sha(folder.glb) == expected_glb, (kind, point)
        whole(folder)
        key = f"{'killed' if status else 'finished'}, {how}"
        outcomes[key] = outcomes.get(key, 0) + 1
    summary = {"command": "generate", "write_events": events, "seconds": round(seconds, 2), "outcomes": outcomes}
    print(json.dumps(summary))
    assert sum(outcomes.values()) == EVENT_KILLS["generate"] + TIME_KILLS["generate"]
    assert sum(n for key, n in outcomes.items() if key.startswith("killed")) >= EVENT_KILLS["generate"]


EDITS = ("move the armchair next to the bookshelf", "add a red armchair next to the coffee table")


def test_edit_killed_at_random_points_is_either_undone_or_done_and_resumes_to_the_same_result(tmp_path):
    template = build_folder(tmp_path / "template")
    original, original_glb = template.document.read_bytes(), sha(template.glb)
    rng = random.Random(7)
    outcomes: dict[str, int] = {}
    for e, instruction in enumerate(EDITS):
        reference = SceneFolder(shutil.copytree(template.root, tmp_path / f"reference-{e}"))
        assert _run_killed(["edit", str(reference.root), instruction])[0] == 0
        expected, expected_glb = canonical(reference), sha(reference.glb)
        again = SceneFolder(shutil.copytree(template.root, tmp_path / f"again-{e}"))
        events, seconds = _timed(["edit", str(again.root), instruction])
        assert events > 5 and canonical(again) == expected and sha(again.glb) == expected_glb
        points = _plan("edit", events, seconds, rng)
        for k, (kind, point) in enumerate(points[e::len(EDITS)]):  # the points shared between the edits
            folder = SceneFolder(shutil.copytree(template.root, tmp_path / f"killed-{e}-{k}"))
            argv = ["edit", str(folder.root), instruction]
            status, _ = _run_killed(argv, **({"at_event": int(point)} if kind == "event" else {"after": point}))
            assert status in (0, -signal.SIGKILL)
            done = [x for x in entries(folder) if x.active]
            if done:  # it took effect: exactly the uninterrupted result, and undo gives the original
                assert [x.instruction for x in done] == [instruction] and canonical(folder) == expected
                assert main(["undo", str(folder.root)]) == 0
                assert main(["redo", str(folder.root)]) == 0
                how = "took effect"
            else:  # it did not: the document untouched, nothing to undo, and the edit runs again
                assert folder.document.read_bytes() == original, (kind, point)
                assert main(["undo", str(folder.root)]) == 2
                assert sha(folder.glb) == original_glb, (kind, point)
                assert main(argv) == 0
                how = "no effect: edit again"
            assert canonical(folder) == expected and sha(folder.glb) == expected_glb, (kind, point)
            assert main(["undo", str(folder.root)]) == 0
            assert folder.document.read_bytes() == original and sha(folder.glb) == original_glb
            whole(folder)
            key = f"{'killed' if status else 'finished'}, {how}"
            outcomes[key] = outcomes.get(key, 0) + 1
    print(json.dumps({"command": "edit", "outcomes": outcomes}))
    assert sum(outcomes.values()) == EVENT_KILLS["edit"] + TIME_KILLS["edit"]
    assert sum(n for key, n in outcomes.items() if key.startswith("killed")) >= EVENT_KILLS["edit"]
