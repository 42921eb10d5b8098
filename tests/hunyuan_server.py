"""Local Hunyuan3D servers for the protocol tests: real GLBs built here, scripted faults.

The server itself is :mod:`scenewright.testing.hunyuan3d_standin` (the assets benchmark runs
it too); this module builds the meshes it returns and starts groups of servers.
"""

from __future__ import annotations

import contextlib
import io
from collections.abc import Iterator

import numpy as np
import trimesh
from PIL import Image

from scenewright.testing.hunyuan3d_standin import StandInServer

#: What every test server returns, in glTF axes: 0.8 wide, 1.2 tall, 0.6 deep, off-centre.
MODEL_EXTENTS = (0.8, 1.2, 0.6)


def box_glb(extents=MODEL_EXTENTS, offset=(0.3, -0.2, 0.1)) -> bytes:
    box = trimesh.creation.box(extents=extents)
    box.apply_translation(offset)
    box.visual.face_colors = np.tile([180, 120, 60, 255], (len(box.faces), 1))
    return trimesh.Scene(box).export(file_type="glb")


def model(image: bytes) -> bytes:
    return box_glb()


def png(colour=(200, 30, 30)) -> bytes:
    buffer = io.BytesIO()
    Image.new("RGBA", (8, 8), (*colour, 255)).save(buffer, format="PNG")
    return buffer.getvalue()


@contextlib.contextmanager
def servers(*configs: dict) -> Iterator[list[StandInServer]]:
    """One started server per config (keyword arguments of StandInServer besides ``model``)."""
    started = [StandInServer(model=model, **config).start() for config in configs]
    try:
        yield started
    finally:
        for server in started:
            server.stop()
