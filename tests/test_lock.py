"""The scene folder's lock: one writer at a time, a clear message when it waits too long, and
concurrent edits through the CLI that both land with an unbroken history."""

from __future__ import annotations

import json
import multiprocessing
import os
import threading
import time

import pytest

from editing_scenes import build_folder
from scenewright.cli import main
from scenewright.errors import FolderBusy
from scenewright.lock import LOCK_NAME, locked

#: Forked children run the CLI exactly as a second terminal would, without a new interpreter.
FORK = multiprocessing.get_context("fork")


def test_a_second_holder_waits_and_then_gives_up_naming_the_holder(tmp_path):
    with locked(tmp_path, timeout=1):
        assert (tmp_path / LOCK_NAME).read_text().strip() == str(os.getpid())
        with pytest.raises(FolderBusy, match=f"being changed by process {os.getpid()}.*waiting 0.2 s.*lock_timeout"):
            with locked(tmp_path, timeout=0.2):
                pass
    assert not (tmp_path / LOCK_NAME).exists()  # released and gone: the folder is as it was


def test_a_waiter_gets_the_folder_when_the_holder_lets_go(tmp_path):
    order = []
    held = threading.Event()

    def holder():
        with locked(tmp_path, timeout=1):
            held.set()
            time.sleep(0.3)
            order.append("holder done")

    thread = threading.Thread(target=holder)
    thread.start()
    held.wait()
    with locked(tmp_path, timeout=30):
        order.append("waiter in")
    thread.join()
    assert order == ["holder done", "waiter in"]


def _hold_then_signal(root, ready, release):
    with locked(root, timeout=5):
        ready.set()
        release.wait(30)
    os._exit(0)


def test_a_command_on_a_folder_another_process_holds_says_who_and_changes_nothing(tmp_path, monkeypatch, capsys):
    folder = build_folder(tmp_path / "scene")
    monkeypatch.chdir(tmp_path)
    (tmp_path / "scenewright.toml").write_text("lock_timeout = 0.2\n")
    before = folder.document.read_bytes()
    ready, release = FORK.Event(), FORK.Event()
    child = FORK.Process(target=_hold_then_signal, args=(folder.root, ready, release))
    child.start()
    try:
        assert ready.wait(30)
        assert main(["edit", str(folder.root), "move the armchair half a metre to the left"]) == 1
        assert main(["undo", str(folder.root)]) == 1
        assert main(["export", str(folder.root), "--format", "mjcf"]) == 1  # writes physics and sim/
        assert not (folder.root / "sim").exists()
    finally:
        release.set()
        child.join(30)
    err = capsys.readouterr().err
    assert f"being changed by process {child.pid}" in err and "gave up after waiting 0.2 s" in err
    assert folder.document.read_bytes() == before
    assert main(["edit", str(folder.root), "move the armchair half a metre to the left"]) == 0


def _edit(root, instruction, start):
    start.wait(30)
    os._exit(main(["edit", str(root), instruction]))


def _chain(folder):
    """The history's records, checked to be one unbroken line ending at the document."""
    history = folder.root / "history"
    records = [json.loads(line) for line in (history / "log.jsonl").read_text().splitlines()]
    numbers = [r["number"] for r in records]
    assert numbers == list(range(1, len(records) + 1))
    assert json.loads((history / "state.json").read_text())["current"] == len(records)
    for n in numbers[1:]:
        assert (history / f"{n:04d}.json").read_bytes() == (history / f"{n - 1:04d}.after.json").read_bytes()
    assert (history / f"{numbers[-1]:04d}.after.json").read_bytes() == folder.document.read_bytes()
    assert not (history / "pending.json").exists()
    return records


def test_ten_pairs_of_concurrent_edits_through_the_cli_both_land_in_an_unbroken_history(tmp_path, monkeypatch):
    folder = build_folder(tmp_path / "scene")
    monkeypatch.chdir(tmp_path)
    for pair in range(10):
        way = 1 if pair % 2 == 0 else -1
        moves = {
            "armchair_1": ("x", -0.5 * way, f"move the armchair half a metre to the {'left' if way > 0 else 'right'}"),
            "floor_lamp_1": ("y", -0.5 * way, f"move the floor lamp half a metre {'forward' if way > 0 else 'back'}"),
        }
        before = folder.load()
        start = FORK.Event()
        children = [FORK.Process(target=_edit, args=(folder.root, instruction, start))
                    for _, _, instruction in moves.values()]
        for child in children:
            child.start()
        start.set()
        for child in children:
            child.join(60)
        assert [child.exitcode for child in children] == [0, 0], pair
        after = folder.load()
        for oid, (axis, step, _) in moves.items():  # both changes are in the document
            moved = getattr(after.get(oid).position, axis) - getattr(before.get(oid).position, axis)
            assert moved == pytest.approx(step), (pair, oid)
        records = _chain(folder)
        assert len(records) == 2 * (pair + 1)
        assert {r["instruction"] for r in records[-2:]} == {m[2] for m in moves.values()}
    assert main(["undo", str(folder.root)]) == 0 and main(["undo", str(folder.root)]) == 0
    assert folder.document.read_bytes() == (folder.root / "history" / "0019.json").read_bytes()
