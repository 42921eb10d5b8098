"""Speed of the offline assets: every shape in every style, a 15-object scene, ground textures.

Prints one JSON object. Run: ``.venv/bin/python benchmarks/procedural.py``.
"""

from __future__ import annotations

import json
import statistics
import time

from scenewright.core.protocols import MeshRequest
from scenewright.procedural import SHAPES
from scenewright.backends.procedural_images import ProceduralImages
from scenewright.backends.procedural_meshes import ProceduralMeshes
from scenewright.procedural.textures import KINDS
from scenewright.scene import STYLES, Vec3

LIVING_ROOM = [
    ("sofa", (2.1, 0.9, 0.85)), ("coffee_table", (1.1, 0.6, 0.45)), ("armchair", (0.9, 0.85, 0.9)),
    ("armchair", (0.9, 0.85, 0.9)), ("tv", (1.2, 0.25, 0.75)), ("bookshelf", (1.0, 0.35, 1.9)),
    ("rug", (2.4, 1.7, 0.02)), ("floor_lamp", (0.45, 0.45, 1.6)), ("potted_plant", (0.5, 0.5, 1.1)),
    ("table", (1.6, 0.9, 0.75)), ("chair", (0.48, 0.52, 0.92)), ("chair", (0.48, 0.52, 0.92)),
    ("picture_frame", (0.8, 0.04, 0.6)), ("vase", (0.25, 0.25, 0.45)), ("table_lamp", (0.35, 0.35, 0.6)),
]


def main() -> None:
    meshes = ProceduralMeshes()
    per_asset, faces_bytes = [], []
    for style in STYLES:
        for shape in SHAPES:
            request = MeshRequest(id=f"{shape}_1", name=shape, category=shape, description="", style=style,
                                  size=Vec3(x=1.0, y=0.8, z=1.2))
            start = time.perf_counter()
            glb = meshes.generate([request])[request.id]
            per_asset.append(time.perf_counter() - start)
            faces_bytes.append(len(glb))
    scene_times = []
    for style in STYLES:
        requests = [
            MeshRequest(id=f"{name}_{i}", name=name, category=name, description="a red one", style=style, size=Vec3.of(size))
            for i, (name, size) in enumerate(LIVING_ROOM)
        ]
        start = time.perf_counter()
        meshes.generate(requests)
        scene_times.append(time.perf_counter() - start)
    images = ProceduralImages()
    texture_times = []
    for kind in KINDS:
        start = time.perf_counter()
        images.ground_texture("", "realistic", kind, None)
        texture_times.append(time.perf_counter() - start)
    ordered = sorted(per_asset)
    print(json.dumps({
        "generators": len(SHAPES), "styles": len(STYLES), "assets_built": len(per_asset),
        "asset_median_ms": round(1000 * statistics.median(per_asset), 1),
        "asset_p95_ms": round(1000 * ordered[int(0.95 * (len(ordered) - 1))], 1),
        "asset_max_ms": round(1000 * ordered[-1], 1),
        "glb_median_kb": round(statistics.median(faces_bytes) / 1024, 1),
        "scene_15_objects_median_s": round(statistics.median(scene_times), 3),
        "texture_median_ms": round(1000 * statistics.median(texture_times), 1),
        "texture_max_ms": round(1000 * max(texture_times), 1),
    }))


if __name__ == "__main__":
    main()
