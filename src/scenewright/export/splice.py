"""Binary glTF put together from other GLBs' already-encoded parts (docs/architecture.md, "Data flow").

``scene.glb`` is the assets' GLBs under one node per object, plus the ground or the room.
Reading each asset into meshes and writing them out again re-encodes every texture and
rounds every material, and it was most of what a move edit cost; here a node tree of one GLB
is copied into another as it is: its nodes, meshes, materials, textures and images keep their
JSON, their accessors and buffer views are re-numbered, and their bytes are copied unread.
Only what the copied nodes reach is copied, so a part of an earlier ``scene.glb`` (its room)
can be taken over as well as a whole asset.

The subset of glTF 2.0 copied is the one scenewright's GLBs use (one binary buffer, embedded
images, textures, samplers, materials with texture references in their extensions too);
cameras, skins and animations are not copied, and a GLB whose buffers or images live in
other files is refused (``ValueError``), since ``scene.glb`` must stand alone.
"""

from __future__ import annotations

import copy
import json
import struct
from collections.abc import Iterable

import numpy as np

from scenewright.gltf import BIN_CHUNK, JSON_CHUNK, Glb

#: The order a node's fields are written in, whichever way the node was made (copied from an
#: asset, or from an earlier ``scene.glb``), so the same scene always gives the same bytes.
_NODE_FIELDS = ("name", "children", "mesh", "matrix", "translation", "rotation", "scale", "extras", "extensions")
#: glTF bufferView targets: vertex attributes and triangle indices.
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963

__all__ = ["ARRAY_BUFFER", "ELEMENT_ARRAY_BUFFER", "Glb", "GlbWriter"]


def _remap_textures(value, textures: dict[int, int], under_texture: bool = False):
    """A material's JSON with every texture reference (``{"index": k}`` under a key ending in
    ``Texture``, in extensions too) pointing at the new texture numbers."""
    if isinstance(value, dict):
        out = {}
        for key, item in value.items():
            if key == "index" and under_texture and isinstance(item, int):
                out[key] = textures[item]
            else:
                out[key] = _remap_textures(item, textures, key.endswith("Texture"))
        return out
    if isinstance(value, list):
        return [_remap_textures(v, textures) for v in value]
    return value


class GlbWriter:
    """One GLB under construction: nodes made here, node trees copied in from other GLBs."""

    def __init__(self, generator: str) -> None:
        self.tree: dict = {"asset": {"version": "2.0", "generator": generator}, "scene": 0,
                           "scenes": [{"nodes": []}]}
        self._binary = bytearray()
        self._extensions: dict[str, set[str]] = {"extensionsUsed": set(), "extensionsRequired": set()}

    def _list(self, key: str) -> list:
        return self.tree.setdefault(key, [])

    def _append(self, key: str, item: dict) -> int:
        items = self._list(key)
        items.append(item)
        return len(items) - 1

    def node(self, name: str, parent: int | None = None, matrix: np.ndarray | None = None,
             extras: dict | None = None) -> int:
        """A new node (a child of ``parent``, else a root of the scene); its index."""
        node: dict = {"name": name}
        if matrix is not None and not np.allclose(matrix, np.eye(4), rtol=0.0, atol=0.0):
            node["matrix"] = [float(x) for x in np.asarray(matrix, dtype=float).T.reshape(-1)]
        if extras is not None:
            node["extras"] = extras
        index = self._append("nodes", node)
        self._attach(index, parent)
        return index

    def _attach(self, index: int, parent: int | None) -> None:
        if parent is None:
            self.tree["scenes"][0]["nodes"].append(index)
        else:
            self.tree["nodes"][parent].setdefault("children", []).append(index)

    def data(self, payload: bytes, phase: int = 0) -> int:
        """``payload`` appended to the binary chunk as a new buffer view, starting at an offset
        that is ``phase`` past a multiple of 4 (the alignment its accessors were written for)."""
        while len(self._binary) % 4 != phase % 4:
            self._binary.append(0)
        view = {"buffer": 0, "byteOffset": len(self._binary), "byteLength": len(payload)}
        self._binary += payload
        return self._append("bufferViews", view)

    def accessor(self, array: np.ndarray, kind: str, target: int | None = None) -> int:
        """A new accessor holding ``array`` (float32 vectors or uint32 indices), with min/max."""
        if kind == "SCALAR":
            values = np.ascontiguousarray(array, dtype=np.uint32).reshape(-1)
            component, low, high = 5125, [int(values.min())], [int(values.max())]
        else:
            values = np.ascontiguousarray(array, dtype=np.float32)
            component = 5126
            low, high = values.min(axis=0).tolist(), values.max(axis=0).tolist()
        view = self.data(values.tobytes())
        if target is not None:
            self.tree["bufferViews"][view]["target"] = target
        return self._append("accessors", {"bufferView": view, "componentType": component, "count": len(values),
                                          "type": kind, "min": low, "max": high})

    def image(self, payload: bytes, mime: str) -> int:
        return self._append("images", {"bufferView": self.data(payload), "mimeType": mime})

    def add(self, item: str, value: dict) -> int:
        """A new top-level entry (a material, texture, mesh) written as given; its index."""
        return self._append(item, value)

    def splice(self, source: Glb, roots: Iterable[int], parent: int | None = None,
               prefix: str | None = None) -> list[int]:
        """Copy the node trees under ``roots`` of ``source`` (under ``parent``, else as scene
        roots), with everything they reach; names get ``prefix/`` in front. The new roots' indices."""
        tree, binary = source.tree, source.binary
        for key in ("buffers", "images"):
            for item in tree.get(key, []):
                if "uri" in item:
                    raise ValueError(f"its {key[:-1]} refers to an outside file or data URI; only embedded data is read")
        nodes, meshes = tree.get("nodes", []), tree.get("meshes", [])
        maps: dict[str, dict[int, int]] = {k: {} for k in
                                           ("nodes", "meshes", "materials", "textures", "images", "samplers",
                                            "accessors", "bufferViews")}

        def view(k: int) -> int:
            if k not in maps["bufferViews"]:
                old = tree["bufferViews"][k]
                if old.get("buffer", 0) != 0:
                    raise ValueError("it has more than one buffer")
                start = old.get("byteOffset", 0)
                payload = binary[start : start + old["byteLength"]]
                if len(payload) != old["byteLength"]:
                    raise ValueError("a buffer view runs past the binary chunk")
                new = self.data(payload, start % 4)
                self.tree["bufferViews"][new].update(
                    {key: copy.deepcopy(v) for key, v in old.items() if key not in ("buffer", "byteOffset", "byteLength")}
                )
                maps["bufferViews"][k] = new
            return maps["bufferViews"][k]

        def accessor(k: int) -> int:
            if k not in maps["accessors"]:
                item = copy.deepcopy(tree["accessors"][k])
                if "bufferView" in item:
                    item["bufferView"] = view(item["bufferView"])
                sparse = item.get("sparse")
                if sparse:
                    sparse["indices"]["bufferView"] = view(sparse["indices"]["bufferView"])
                    sparse["values"]["bufferView"] = view(sparse["values"]["bufferView"])
                maps["accessors"][k] = self._append("accessors", item)
            return maps["accessors"][k]

        def image(k: int) -> int:
            if k not in maps["images"]:
                item = copy.deepcopy(tree["images"][k])
                item["bufferView"] = view(item["bufferView"])
                maps["images"][k] = self._append("images", item)
            return maps["images"][k]

        def sampler(k: int) -> int:
            if k not in maps["samplers"]:
                maps["samplers"][k] = self._append("samplers", copy.deepcopy(tree["samplers"][k]))
            return maps["samplers"][k]

        def texture(k: int) -> int:
            if k not in maps["textures"]:
                item = copy.deepcopy(tree["textures"][k])
                if "source" in item:
                    item["source"] = image(item["source"])
                if "sampler" in item:
                    item["sampler"] = sampler(item["sampler"])
                for ext in item.get("extensions", {}).values():
                    if isinstance(ext, dict) and isinstance(ext.get("source"), int):
                        ext["source"] = image(ext["source"])
                maps["textures"][k] = self._append("textures", item)
            return maps["textures"][k]

        def material(k: int) -> int:
            if k not in maps["materials"]:
                item = tree["materials"][k]
                used = {}
                for i in _texture_indices(item):
                    used[i] = texture(i)
                maps["materials"][k] = self._append("materials", _remap_textures(item, used))
            return maps["materials"][k]

        def mesh(k: int, name: str | None) -> int:
            if k not in maps["meshes"]:
                item = copy.deepcopy(meshes[k])
                if name is not None:
                    item["name"] = name
                for primitive in item.get("primitives", []):
                    primitive["attributes"] = {a: accessor(i) for a, i in primitive.get("attributes", {}).items()}
                    if "indices" in primitive:
                        primitive["indices"] = accessor(primitive["indices"])
                    if "material" in primitive:
                        primitive["material"] = material(primitive["material"])
                    if "targets" in primitive:
                        primitive["targets"] = [{a: accessor(i) for a, i in t.items()} for t in primitive["targets"]]
                maps["meshes"][k] = self._append("meshes", item)
            return maps["meshes"][k]

        def copy_node(k: int, parent_index: int | None, seen: set[int]) -> int:
            if k in seen:
                raise ValueError("its node tree has a cycle")
            seen = seen | {k}
            old = nodes[k]
            name = old.get("name") or (meshes[old["mesh"]].get("name") if "mesh" in old else None) or f"node{k}"
            if prefix:
                name = f"{prefix}/{name}"
            item = {key: copy.deepcopy(v) for key, v in old.items()
                    if key not in ("children", "mesh", "camera", "skin", "weights", "name")}
            item = {"name": name, **item}
            index = self._append("nodes", item)
            self._attach(index, parent_index)
            if "mesh" in old:
                item["mesh"] = mesh(old["mesh"], name if prefix else None)
            for child in old.get("children", []):
                copy_node(child, index, seen)
            maps["nodes"][k] = index
            return index

        try:
            made = [copy_node(k, parent, set()) for k in roots]
        except (KeyError, IndexError, TypeError) as exc:
            raise ValueError(f"its glTF JSON refers to something it does not hold ({type(exc).__name__}: {exc})") from None
        for key in self._extensions:
            self._extensions[key].update(tree.get(key, []))
        return made

    def to_bytes(self) -> bytes:
        """The GLB: buffer views marked as vertices or indices, extensions listed, chunks padded."""
        tree = self.tree
        for key, names in self._extensions.items():
            if names:
                tree[key] = sorted(names)
        _mark_buffer_targets(tree)
        rank = {key: i for i, key in enumerate(_NODE_FIELDS)}
        tree["nodes"] = [dict(sorted(n.items(), key=lambda kv: rank.get(kv[0], len(rank)))) for n in tree.get("nodes", [])]
        binary = bytes(self._binary) + b"\0" * (-len(self._binary) % 4)
        if binary:
            tree["buffers"] = [{"byteLength": len(binary)}]
        text = json.dumps(tree, separators=(",", ":")).encode("utf-8")
        text += b" " * (-len(text) % 4)
        chunks = struct.pack("<II", len(text), JSON_CHUNK) + text
        if binary:
            chunks += struct.pack("<II", len(binary), BIN_CHUNK) + binary
        return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def _texture_indices(value, under_texture: bool = False) -> list[int]:
    """Every texture a material refers to, in the order its JSON names them."""
    found: list[int] = []
    if isinstance(value, dict):
        for key, item in value.items():
            if key == "index" and under_texture and isinstance(item, int):
                found.append(item)
            else:
                found += _texture_indices(item, key.endswith("Texture"))
    elif isinstance(value, list):
        for item in value:
            found += _texture_indices(item)
    return found


def _mark_buffer_targets(tree: dict) -> None:
    """Say which buffer views hold vertices and which indices, as engines prefer to be told."""
    for mesh in tree.get("meshes", []):
        for primitive in mesh["primitives"]:
            for accessor in primitive["attributes"].values():
                tree["bufferViews"][tree["accessors"][accessor]["bufferView"]]["target"] = ARRAY_BUFFER
            if "indices" in primitive:
                view = tree["accessors"][primitive["indices"]]["bufferView"]
                tree["bufferViews"][view]["target"] = ELEMENT_ARRAY_BUFFER
