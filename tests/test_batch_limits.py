"""The batch's one limit on remote requests: at most K in flight across all workers, counted by
a local OpenAI-compatible server on 127.0.0.1; slots survive neither a killed holder nor a leak."""

from __future__ import annotations

import json
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from scenewright.testing.fake_openai import CHAT, EDIT, GENERATE, chat_reply, image_reply, object_item
from scenewright.batch.limits import FileSlots, SlotTable
from scenewright.cli import main

K = 2


class InFlight:
    """Counts requests the server is answering at once; each takes ``seconds``."""

    def __init__(self, seconds: float):
        self.seconds = seconds
        self.now = self.peak = self.total = 0
        self.lock = threading.Lock()

    def around(self, reply):
        def responder(request):
            with self.lock:
                self.now += 1
                self.total += 1
                self.peak = max(self.peak, self.now)
            try:
                time.sleep(self.seconds)
                return reply(request)
            finally:
                with self.lock:
                    self.now -= 1

        return responder


ANSWERS = {
    "scene_objects": {"objects": [object_item(f"crate_{i}", f"wooden crate {i}", (0.5, 0.5, 0.5), 1.5 * i) for i in range(3)]},
    "redundant_images": {"redundant": []},
    "spatial_constraints": {"constraints": []},
}


@pytest.mark.slow
def test_four_workers_share_one_limit_of_k_requests(openai_server, tmp_path):
    counter = InFlight(0.15)
    openai_server.responders[CHAT] = counter.around(lambda r: chat_reply(ANSWERS[r.schema_name]))
    openai_server.responders[GENERATE] = counter.around(lambda r: image_reply())
    openai_server.responders[EDIT] = counter.around(lambda r: image_reply())
    prompts = tmp_path / "prompts.jsonl"
    prompts.write_text("".join(json.dumps({"id": f"store_{i}", "text": f"a storeroom with crates, number {i}"}) + "\n" for i in range(4)))
    (tmp_path / "config.toml").write_text('cache_dir = ""\nimage_concurrency = 4\n')
    code = main(
        [
            "batch", str(prompts), "--out", str(tmp_path / "out"), "--workers", "4", "--no-render",
            "--config", str(tmp_path / "config.toml"), "--vlm", "openai:test-model", "--images", "openai:test-image",
            "--base-url", openai_server.url, "--remote-limit", str(K),
        ]
    )
    record = json.loads((tmp_path / "out" / "batch.json").read_text())
    assert code == 0, record
    assert record["totals"]["done"] == 4
    # Per scene: 3 chat calls, a reference image, 3 object images, a ground texture.
    assert counter.total == 4 * 8 == len(openai_server.requests)
    # Each scene alone would send up to 4 images at once; four workers up to 16. One limit: K.
    assert counter.peak == K


def test_file_slots_never_exceed_the_limit_among_threads(tmp_path):
    slots = FileSlots(tmp_path / "slots", K, poll=0.001)
    state = {"now": 0, "peak": 0}
    lock = threading.Lock()

    def request(_):
        with slots.slot("http://127.0.0.1:1/v1"):
            with lock:
                state["now"] += 1
                state["peak"] = max(state["peak"], state["now"])
            time.sleep(0.01)
            with lock:
                state["now"] -= 1

    with ThreadPoolExecutor(8) as pool:
        list(pool.map(request, range(40)))
    assert state["peak"] == K


HOLD = """
import sys, time
from pathlib import Path

import pytest
from scenewright.batch.limits import FileSlots
with FileSlots(Path(sys.argv[1]), 1).slot("server"):
    print("holding", flush=True)
    time.sleep(60)
"""


def test_a_killed_holder_frees_its_slot(tmp_path):
    holder = subprocess.Popen([sys.executable, "-c", HOLD, str(tmp_path)], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "holding"
        taken = threading.Event()

        def take():
            with FileSlots(tmp_path, 1, poll=0.005).slot("server"):
                taken.set()

        waiter = threading.Thread(target=take, daemon=True)
        waiter.start()
        assert not taken.wait(0.3)  # the only slot is held by the other process
        holder.kill()
        assert taken.wait(10)
    finally:
        holder.kill()
        holder.wait()


def test_slot_table_counts_per_server():
    table = SlotTable(2)
    assert table.acquire("a", "t1") and table.acquire("a", "t2")
    assert not table.acquire("a", "t3")
    assert table.acquire("b", "t3")  # another server has its own slots
    table.release("a", "t1")
    assert table.in_flight("a") == 1 and table.acquire("a", "t3")


def test_share_limit_wraps_only_remote_clients(remote_settings):
    from scenewright.backends import backends_from_settings
    from scenewright.batch.limits import share_limit
    from scenewright.settings import Settings

    offline = backends_from_settings(Settings(cache_dir=None))
    assert share_limit(offline, FileSlots(Path("/nonexistent"), 1)) == 0
    remote_settings.vlm, remote_settings.images = "openai:m", "openai:i"
    remote = backends_from_settings(remote_settings)
    assert share_limit(remote, FileSlots(Path("/nonexistent"), 1)) == 2
    assert share_limit(remote, FileSlots(Path("/nonexistent"), 1)) == 0  # never wrapped twice
