"""What the editor sends the browser: meshes with what costs most to draw taken out.

The editor is for placing things, so it drops what only changes how light passes through a
surface: ``KHR_materials_transmission`` (and ``KHR_materials_volume``, which needs it). three.js
draws a transmissive material by rendering the whole scene a second time into a texture every
frame and compiles every other material again for that pass; in software WebGL that doubled
the first frame of the demo scene (docs/studio.md). The material keeps its colour and its alpha
blend, so glass still looks like glass; the asset on disk, the render and the download are
unchanged.

Each material variant is a shader program the page compiles, 0.2–0.5 s each in software WebGL,
so the room and the ground are sent with their faces' normals (:func:`view_mesh`): without
normals three.js shades them flat, a variant of its own, while with them they share the
objects' program and still look flat.
"""

from __future__ import annotations

import json
import struct

import trimesh

#: Extensions whose effect only a second render pass can draw.
DROPPED = ("KHR_materials_transmission", "KHR_materials_volume")

_MAGIC, _JSON = 0x46546C67, 0x4E4F534A


def view_glb(data: bytes) -> bytes:
    """``data`` without :data:`DROPPED` material extensions (the same bytes when it has none,
    or when it is not a GLB this reads: the browser's loader then says what is wrong)."""
    if len(data) < 20:
        return data
    magic, version, _ = struct.unpack_from("<III", data, 0)
    length, kind = struct.unpack_from("<II", data, 12)
    if magic != _MAGIC or version != 2 or kind != _JSON or 20 + length > len(data):
        return data
    try:
        document = json.loads(data[20 : 20 + length])
    except ValueError:
        return data
    used = document.get("extensionsUsed") or []
    if not any(name in used for name in DROPPED):
        return data
    for material in document.get("materials") or []:
        extensions = material.get("extensions") or {}
        for name in DROPPED:
            extensions.pop(name, None)
        if "extensions" in material and not extensions:
            del material["extensions"]
    for key in ("extensionsUsed", "extensionsRequired"):
        if key in document:
            document[key] = [name for name in document[key] if name not in DROPPED]
            if not document[key]:
                del document[key]
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)  # chunks stay 4-byte aligned, padded with spaces (glTF 2.0 §4.4.3)
    rest = data[20 + length :]
    return struct.pack("<III", _MAGIC, 2, 12 + 8 + len(text) + len(rest)) + struct.pack("<II", len(text), _JSON) + text + rest


def view_mesh(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """A copy of ``mesh`` whose vertices each belong to one face and carry its normal, which
    the GLB export then includes (texture coordinates stay with their vertices)."""
    view = mesh.copy()
    view.unmerge_vertices()
    view.vertex_normals = view.face_normals[:, None, :].repeat(3, axis=1).reshape(-1, 3)
    return view
