"""``scenewright bench assets``: how well the asset stage spreads jobs over several mesh servers.

One of the servers can fail on purpose: ``transient`` fails its first job after the job's
full time (an error status at the end), ``reject`` turns its first job away at once (HTTP
500 from ``/send``), ``permanent`` fails every job until it leaves the rotation. The ideal
wall time is that of the remaining capacity: the fewest rounds of ``delay`` seconds in which
the healthy servers, plus the flaky one after the rounds its failed jobs took, have room for
every asset. A rejected job takes no round, so there the ideal is that of no fault at all:
any time the flaky server sits idle after turning a job away shows in the ratio.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path


def _box_glb() -> bytes:
    import trimesh

    return trimesh.Scene(trimesh.creation.box(extents=(0.8, 1.0, 0.6))).export(file_type="glb")


def _png(index: int) -> bytes:
    import io

    from PIL import Image

    buffer = io.BytesIO()
    Image.new("RGBA", (16, 16), (index * 13 % 256, 80, 160, 255)).save(buffer, format="PNG")
    return buffer.getvalue()


#: --fault → how the first stand-in server misbehaves.
FAULTS: dict[str, dict] = {
    "none": {},
    "transient": {"fault": "error", "fault_jobs": 1},
    "reject": {"fault": "reject", "fault_jobs": 1},
    "permanent": {"fault": "error"},
}
MAX_FAILURES = 3


def ideal_rounds(assets: int, servers: int, lost: int, *, permanent: bool) -> int:
    """The fewest rounds in which the servers' remaining capacity holds every asset: each
    healthy server builds one asset a round, the flaky one loses ``lost`` rounds to its failed
    jobs, and a permanently failing one builds nothing."""
    rounds = 1
    while (servers - 1) * rounds + (0 if permanent else max(0, rounds - lost)) < assets:
        rounds += 1
    return rounds


def run_assets_bench(assets: int, servers: int, delay: float, poll: float, fault: str) -> dict:
    """Wall time of the asset stage over local servers (one job each at a time) against the ideal."""
    from scenewright.assets import generate_assets
    from scenewright.backends.hunyuan3d import Hunyuan3D
    from scenewright.testing.hunyuan3d_standin import StandInServer
    from scenewright.cache import RequestCache
    from scenewright.errors import InputError
    from scenewright.folder import SceneFolder
    from scenewright.scene import Scene, SceneObject, Vec3

    if fault not in FAULTS:
        raise InputError(f"--fault {fault!r} is not one of: {', '.join(FAULTS)}")
    if servers < 2 and fault == "permanent":
        raise InputError("--fault permanent needs --servers 2 or more (one must stay healthy)")
    glb = _box_glb()
    faults = [FAULTS[fault]] + [{}] * (servers - 1)
    started = [StandInServer(model=lambda image: glb, delay=delay, **f).start() for f in faults]
    try:
        backend = Hunyuan3D([s.url for s in started], concurrency=1, poll_interval=poll, max_failures=MAX_FAILURES)
        with tempfile.TemporaryDirectory(prefix="scenewright-bench-assets-") as tmp:
            folder = SceneFolder(Path(tmp))
            folder.object_images.mkdir(parents=True)
            objects = []
            for index in range(assets):
                image = folder.object_image(f"crate_{index + 1}")
                image.write_bytes(_png(index))
                objects.append(SceneObject(id=image.stem, name="crate", size=Vec3(x=1, y=1, z=1),
                                           image=folder.relative(image)))
            scene = Scene(text="a yard full of crates", objects=objects)
            start = time.perf_counter()
            generate_assets(scene, folder, backend, RequestCache(None))
            wall = time.perf_counter() - start
            record = [e for e in scene.provenance if e.stage == "assets"][-1].data
        backend.close()
    finally:
        for server in started:
            server.stop()
    failed = len(record.get("failed_attempts", []))
    lost = 0 if fault == "reject" else failed  # rounds the failed jobs kept the flaky server busy
    ideal = ideal_rounds(assets, servers, lost, permanent=fault == "permanent") * delay
    result = {
        "assets": assets,
        "servers": servers,
        "fault": fault,
        "seconds_per_asset": delay,
        "poll_seconds": poll,
        "failed_attempts": failed,
        "out_of_rotation": sorted(record.get("out_of_rotation", {})),
        "ideal_seconds": round(ideal, 3),
        "wall_seconds": round(wall, 3),
        "ratio_to_ideal": round(wall / ideal, 3),
        "target_ratio": 1.15,
        "jobs_per_server": [s.counts["send"] for s in started],
    }
    return result
