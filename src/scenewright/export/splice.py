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
from collections.abc import Iterable

from scenewright.gltf import ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, Glb, GltfWriter

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


class GlbWriter(GltfWriter):
    """One GLB under construction: nodes made here (:class:`~scenewright.gltf.GltfWriter`),
    node trees copied in from other GLBs."""

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
