"""``scenewright bench assets``: how well the asset stage spreads jobs over several mesh servers."""

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


def run_assets_bench(assets: int, servers: int, delay: float, poll: float) -> dict:
    """Wall time of the asset stage over local servers (one job each at a time) against the ideal."""
    from scenewright.assets import generate_assets
    from scenewright.backends.hunyuan3d import Hunyuan3D
    from scenewright.testing.hunyuan3d_standin import StandInServer
    from scenewright.cache import RequestCache
    from scenewright.folder import SceneFolder
    from scenewright.scene import Scene, SceneObject, Vec3

    glb = _box_glb()
    started = [StandInServer(model=lambda image: glb, delay=delay).start() for _ in range(servers)]
    try:
        backend = Hunyuan3D([s.url for s in started], concurrency=1, poll_interval=poll)
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
        backend.close()
    finally:
        for server in started:
            server.stop()
    ideal = -(-assets // servers) * delay
    result = {
        "assets": assets,
        "servers": servers,
        "seconds_per_asset": delay,
        "poll_seconds": poll,
        "ideal_seconds": round(ideal, 3),
        "wall_seconds": round(wall, 3),
        "ratio_to_ideal": round(wall / ideal, 3),
        "target_ratio": 1.25,
        "jobs_per_server": [s.counts["send"] for s in started],
    }
    return result
