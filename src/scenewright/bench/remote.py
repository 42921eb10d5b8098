"""``scenewright bench analysis``: how close remote scene analysis comes to ideal concurrency.

A local OpenAI-compatible server adds a fixed latency to every image call; the scene analysis
stage then runs with the OpenAI backends against it. Chat answers are instant, so the ideal
wall time is the image calls' critical path: the reference image, ceil(objects / concurrency)
rounds of object images, and the ground texture.
"""

from __future__ import annotations

import math
import tempfile
import time
from pathlib import Path


def run_analysis_bench(objects: int, latency: float, concurrency: int) -> dict:
    """Wall time of scene analysis over the OpenAI backends against a local server with latency."""
    from scenewright.analysis.stage import analyze
    from scenewright.testing.fake_openai import CHAT, FakeOpenAI, chat_reply, object_item
    from scenewright.backends.openai_chat import OpenAIChatVLM
    from scenewright.backends.openai_images import OpenAIImages
    from scenewright.folder import SceneFolder
    from scenewright.scene import Scene
    from scenewright.settings import Settings

    answers = {
        "scene_objects": {
            "objects": [
                object_item(f"crate_{i}", f"wooden crate number {i}", (0.5, 0.5, 0.5), 2.0 * i)
                for i in range(1, objects + 1)
            ]
        },
        "redundant_images": {"redundant": []},
    }
    with FakeOpenAI() as server, tempfile.TemporaryDirectory(prefix="scenewright-bench-") as tmp:
        server.responders[CHAT] = lambda request: chat_reply(answers[request.schema_name])
        server.image_latency = latency
        settings = Settings(
            base_url=server.url, cache_dir=Path(tmp) / "cache", image_concurrency=concurrency, timeout=60 + latency
        )
        folder = SceneFolder(Path(tmp) / "scene")
        folder.create()
        scene = Scene(text=f"a warehouse with {objects} wooden crates", style="realistic")
        # Backends are built before the clock starts, as the CLI builds them before the pipeline runs.
        vlm, images = OpenAIChatVLM("bench-model", settings), OpenAIImages("bench-image", settings)
        start = time.perf_counter()
        analyze(scene, folder, vlm, images)
        seconds = time.perf_counter() - start
        image_calls = len(server.requests) - len([r for r in server.requests if r.path == CHAT])
    ideal = latency * (1 + math.ceil(objects / concurrency) + 1)
    return {
        "objects": objects,
        "latency_s": latency,
        "concurrency": concurrency,
        "image_calls": image_calls,
        "chat_calls": len(server.requests) - image_calls,
        "seconds": round(seconds, 3),
        "ideal_seconds": round(ideal, 3),
        "ratio": round(seconds / ideal, 3) if ideal else None,
    }
