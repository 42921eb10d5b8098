"""What glTF asks of the colours and materials we write, and how they survive trimesh.

glTF colour factors (``baseColorFactor``, ``emissiveFactor``) are *linear*; palettes, colour
words and images are sRGB. Writing an sRGB value as a factor shows it lighter and greyer
than meant (a mid-grey sofa came out near-white), so every colour written as a factor goes
through :func:`srgb_to_linear`. Textures are images and stay sRGB.

trimesh keeps a material's base colour as 8-bit integers and drops material extensions
(``KHR_materials_transmission``) when it reads a GLB, so an asset that is read and written
again (normalised, then assembled into the scene) would lose its exact factors and its
glass. :func:`mesh_materials` reads the materials a GLB gives its meshes, and
:func:`keep_materials` writes them back into the glTF tree trimesh is about to export.

The GLB container itself is read here too (:class:`Glb`, :func:`check_glb`), with the
triangles a file draws (:func:`glb_triangles`): the solver and the editor need nothing more
of a stored asset, and reading them needs numpy only, not a mesh library's import.
:class:`GltfWriter` writes a GLB from arrays for the same reason: the procedural objects and the
room are built as arrays, and going through a mesh library to write them cost its import.
"""

from __future__ import annotations

import copy
import json
import struct
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass

import numpy as np

#: Material fields that hold plain values (no texture references), at the top level and
#: inside ``pbrMetallicRoughness``.
_FIELDS = ("name", "emissiveFactor", "alphaMode", "alphaCutoff", "doubleSided")
_PBR_FIELDS = ("baseColorFactor", "metallicFactor", "roughnessFactor")
#: GLB chunk types.
JSON_CHUNK = 0x4E4F534A
BIN_CHUNK = 0x004E4942


def srgb_to_linear(values: Iterable[float]) -> tuple[float, ...]:
    """The sRGB transfer function inverted, per channel (IEC 61966-2-1): display values
    in 0..1 to the linear values glTF factors hold."""
    out = []
    for value in values:
        c = min(1.0, max(0.0, float(value)))
        out.append(c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4)
    return tuple(out)


def check_glb(data: bytes) -> str | None:
    """Why ``data`` is not a complete binary glTF 2.0 file, or ``None`` when it is one.

    Servers answer 200 with an HTML error page or a truncated body often enough that the
    header is worth checking before anything is stored.
    """
    if len(data) < 12:
        return f"{len(data)} bytes, too short for a GLB"
    magic, version, length = struct.unpack("<4sII", data[:12])
    if magic != b"glTF":
        return f"data starts with {data[:4]!r}, not the glTF magic"
    if version != 2:
        return f"glTF container version {version}, expected 2"
    if length != len(data):
        return f"header declares {length} bytes but {len(data)} arrived (truncated?)"
    return None


@dataclass(frozen=True)
class Glb:
    """A binary glTF as its JSON tree and its binary chunk."""

    tree: dict
    binary: bytes

    @classmethod
    def parse(cls, data: bytes) -> Glb:
        """Split GLB bytes (``ValueError`` saying what is wrong when they are no usable GLB)."""
        if len(data) < 20 or data[:4] != b"glTF":
            raise ValueError("not a binary glTF (GLB) file")
        version, length = struct.unpack_from("<II", data, 4)
        if version != 2:
            raise ValueError(f"glTF version {version}; only 2 is read")
        if length > len(data):
            raise ValueError(f"cut short: the header says {length} bytes, the file has {len(data)}")
        chunks, offset = {}, 12
        while offset + 8 <= length:
            size, kind = struct.unpack_from("<II", data, offset)
            if offset + 8 + size > length:
                raise ValueError("a chunk runs past the end of the file")
            chunks.setdefault(kind, data[offset + 8 : offset + 8 + size])
            offset += 8 + size
        if JSON_CHUNK not in chunks:
            raise ValueError("no JSON chunk")
        try:
            tree = json.loads(chunks[JSON_CHUNK])
        except (UnicodeDecodeError, json.JSONDecodeError) as exc:
            raise ValueError(f"its JSON chunk does not parse ({exc})") from None
        if not isinstance(tree, dict):
            raise ValueError("its JSON chunk is not an object")
        return cls(tree, chunks.get(BIN_CHUNK, b""))

    def roots(self) -> list[int]:
        """The nodes of the default scene."""
        scenes = self.tree.get("scenes") or [{}]
        return list(scenes[self.tree.get("scene", 0)].get("nodes", []))

    def find(self, name: str) -> int | None:
        """The index of the first node called ``name``."""
        for i, node in enumerate(self.tree.get("nodes", [])):
            if node.get("name") == name:
                return i
        return None


_COMPONENTS = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}
_WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
#: Primitive modes: triangles, triangle strip, triangle fan (points and lines hold no surface).
_TRIANGLES, _STRIP, _FAN = 4, 5, 6


def _node_matrix(node: dict) -> np.ndarray:
    """A node's local transform (its ``matrix``, else translation @ rotation @ scale)."""
    if "matrix" in node:
        return np.asarray(node["matrix"], dtype=float).reshape(4, 4).T
    x, y, z, w = node.get("rotation", (0.0, 0.0, 0.0, 1.0))
    rotation = np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])
    out = np.eye(4)
    out[:3, :3] = rotation * np.asarray(node.get("scale", (1.0, 1.0, 1.0)), dtype=float)
    out[:3, 3] = node.get("translation", (0.0, 0.0, 0.0))
    return out


def _read(glb: Glb, view_index: int, offset: int, component: int, kind: str, count: int) -> np.ndarray:
    """``count`` elements of ``kind`` from a buffer view, as a (count, width) array."""
    dtype = np.dtype(_COMPONENTS[component]).newbyteorder("<")
    width = _WIDTHS[kind]
    view = glb.tree["bufferViews"][view_index]
    stride = view.get("byteStride") or dtype.itemsize * width
    start = view.get("byteOffset", 0) + offset
    end = start + (count - 1) * stride + dtype.itemsize * width if count else start
    if end > view.get("byteOffset", 0) + view["byteLength"] or end > len(glb.binary):
        raise ValueError(f"an accessor runs past buffer view {view_index}")
    return np.ndarray((count, width), dtype=dtype, buffer=glb.binary, offset=start,
                      strides=(stride, dtype.itemsize)).copy()


def _accessor(glb: Glb, k: int) -> np.ndarray:
    """Accessor ``k`` as a (count, width) array (normalised integers scaled to 0..1 or -1..1)."""
    spec = glb.tree["accessors"][k]
    component, kind, count = spec["componentType"], spec["type"], spec["count"]
    if "bufferView" in spec:
        out = _read(glb, spec["bufferView"], spec.get("byteOffset", 0), component, kind, count)
    else:
        out = np.zeros((count, _WIDTHS[kind]), dtype=_COMPONENTS[component])
    sparse = spec.get("sparse")
    if sparse:
        indices, values, n = sparse["indices"], sparse["values"], sparse["count"]
        where = _read(glb, indices["bufferView"], indices.get("byteOffset", 0), indices["componentType"], "SCALAR", n)
        out[where[:, 0].astype(np.int64)] = _read(glb, values["bufferView"], values.get("byteOffset", 0),
                                                  component, kind, n)
    if spec.get("normalized") and out.dtype.kind in "iu":
        return np.maximum(out / np.iinfo(out.dtype).max, -1.0)
    return out


def _faces(indices: np.ndarray, mode: int) -> np.ndarray:
    if mode == _TRIANGLES:
        return indices[: len(indices) // 3 * 3].reshape(-1, 3)
    k = np.arange(max(len(indices) - 2, 0))
    if mode == _STRIP:  # every other triangle turns the other way round
        order = np.where(k[:, None] % 2 == 0, [0, 1, 2], [1, 0, 2]) + k[:, None]
        return indices[order]
    return np.column_stack([np.full(len(k), indices[0]), indices[k + 1], indices[k + 2]])  # a fan


def glb_triangles(glb: Glb) -> tuple[np.ndarray, np.ndarray]:
    """Every triangle the default scene draws, as (vertices in the file's frame, faces): each
    mesh under each node that uses it, moved by the node's world transform; a mirroring node's
    triangles turned over, so they still face out. ``ValueError`` when the JSON refers to
    something the file does not hold."""
    vertices, faces, count = [], [], 0
    tree = glb.tree
    try:
        stack = [(k, np.eye(4)) for k in reversed(glb.roots())]
        seen = 0
        while stack:
            k, parent = stack.pop()
            seen += 1
            if seen > len(tree.get("nodes", [])) * 4 + 16:
                raise ValueError("its node tree has a cycle")
            node = tree["nodes"][k]
            world = parent @ _node_matrix(node)
            stack += [(child, world) for child in reversed(node.get("children", []))]
            if "mesh" not in node:
                continue
            flip = np.linalg.det(world[:3, :3]) < 0
            for primitive in tree["meshes"][node["mesh"]]["primitives"]:
                mode = primitive.get("mode", _TRIANGLES)
                if mode not in (_TRIANGLES, _STRIP, _FAN) or "POSITION" not in primitive["attributes"]:
                    continue
                points = _accessor(glb, primitive["attributes"]["POSITION"])[:, :3].astype(float)
                if "indices" in primitive:
                    index = _accessor(glb, primitive["indices"])[:, 0].astype(np.int64)
                else:
                    index = np.arange(len(points), dtype=np.int64)
                if len(index) and (index.min() < 0 or index.max() >= len(points)):
                    raise ValueError("a triangle names a vertex its mesh does not have")
                tri = _faces(index, mode)
                if flip:
                    tri = tri[:, ::-1]
                vertices.append(points @ world[:3, :3].T + world[:3, 3])
                faces.append(tri + count)
                count += len(points)
    except (KeyError, IndexError, TypeError) as exc:
        raise ValueError(f"its glTF JSON refers to something it does not hold ({type(exc).__name__}: {exc})") from None
    if not vertices:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    return np.concatenate(vertices), np.concatenate(faces)


def json_chunk(glb: bytes) -> dict:
    """The JSON chunk of a GLB (``ValueError`` when the bytes are no GLB)."""
    if len(glb) < 20 or glb[:4] != b"glTF" or glb[16:20] != b"JSON":
        raise ValueError("not a binary glTF (GLB) file")
    length = struct.unpack_from("<I", glb, 12)[0]
    return json.loads(glb[20 : 20 + length])


def _portable(material: dict) -> dict:
    """The parts of a material that hold values, not textures: they can be copied onto
    another file's material without dangling references."""
    out = {key: copy.deepcopy(material[key]) for key in _FIELDS if key in material}
    pbr = material.get("pbrMetallicRoughness", {})
    kept = {key: copy.deepcopy(pbr[key]) for key in _PBR_FIELDS if key in pbr}
    if kept:
        out["pbrMetallicRoughness"] = kept
    extensions = {
        name: copy.deepcopy(body)
        for name, body in material.get("extensions", {}).items()
        if isinstance(body, dict) and not any(key.endswith("Texture") for key in body)
    }
    if extensions:
        out["extensions"] = extensions
    return out


def mesh_materials(glb: bytes) -> dict[str, dict]:
    """Mesh name → the material of its one primitive, for the meshes that have a unique
    name, one primitive and a material (trimesh names a loaded mesh's geometry after it)."""
    tree = json_chunk(glb)
    materials = tree.get("materials", [])
    names = [mesh.get("name") for mesh in tree.get("meshes", [])]
    found: dict[str, dict] = {}
    for mesh in tree.get("meshes", []):
        name, primitives = mesh.get("name"), mesh.get("primitives", [])
        if not name or names.count(name) > 1 or len(primitives) != 1:
            continue
        index = primitives[0].get("material")
        if index is not None and 0 <= index < len(materials):
            found[name] = _portable(materials[index])
    return found


def keep_materials(by_mesh: Mapping[str, dict]) -> Callable[[dict], None]:
    """A tree hook for trimesh's glTF export giving each named mesh's primitives the
    material ``by_mesh`` holds for it: exact factors and extensions over trimesh's 8-bit
    copy. A material trimesh shared between meshes that should differ is split."""

    def postprocess(tree: dict) -> None:
        materials = tree.get("materials", [])
        pristine = copy.deepcopy(materials)
        claimed: dict[int, str] = {}
        copies: dict[tuple[int, str], int] = {}
        used = set(tree.get("extensionsUsed", []))
        for mesh in tree.get("meshes", []):
            spec = by_mesh.get(mesh.get("name"))
            key = json.dumps(spec, sort_keys=True)
            for primitive in mesh.get("primitives", []):
                index = primitive.get("material")
                if index is None:
                    continue
                if claimed.setdefault(index, key) != key:
                    if (index, key) not in copies:
                        materials.append(copy.deepcopy(pristine[index]))
                        copies[index, key] = len(materials) - 1
                        claimed[len(materials) - 1] = key
                    index = primitive["material"] = copies[index, key]
                if spec is None:
                    continue
                target = materials[index]
                target.update({k: copy.deepcopy(v) for k, v in spec.items() if k != "pbrMetallicRoughness"})
                target.setdefault("pbrMetallicRoughness", {}).update(copy.deepcopy(spec.get("pbrMetallicRoughness", {})))
                used.update(spec.get("extensions", {}))
        if used:
            tree["extensionsUsed"] = sorted(used)

    return postprocess


#: The order a node's fields are written in, whichever way the node was made (copied from an
#: asset, or from an earlier ``scene.glb``), so the same scene always gives the same bytes.
_NODE_FIELDS = ("name", "children", "mesh", "matrix", "translation", "rotation", "scale", "extras", "extensions")
#: glTF bufferView targets: vertex attributes and triangle indices.
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963


class GltfWriter:
    """One GLB under construction from arrays: nodes, meshes, materials, images."""

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

    def mesh(self, name: str, vertices: np.ndarray, faces: np.ndarray, material: int,
             normals: np.ndarray | None = None, uv: np.ndarray | None = None, parent: int | None = None) -> int:
        """A node called ``name`` drawing one triangle mesh (glTF frame; ``uv`` with V running
        down the image, as glTF has it) in ``material``; the node's index."""
        attributes = {"POSITION": self.accessor(vertices, "VEC3", ARRAY_BUFFER)}
        if normals is not None:
            attributes["NORMAL"] = self.accessor(normals, "VEC3", ARRAY_BUFFER)
        if uv is not None:
            attributes["TEXCOORD_0"] = self.accessor(uv, "VEC2", ARRAY_BUFFER)
        indices = self.accessor(faces, "SCALAR", ELEMENT_ARRAY_BUFFER)
        mesh = self.add("meshes", {"name": name, "primitives": [
            {"attributes": attributes, "indices": indices, "mode": 4, "material": material}]})
        node = self.node(name, parent)
        self.tree["nodes"][node]["mesh"] = mesh
        return node

    def material(self, material: dict) -> int:
        """``material`` (glTF JSON, exact) as a new material, its extensions declared used."""
        self._extensions["extensionsUsed"].update(material.get("extensions", {}))
        return self.add("materials", copy.deepcopy(material))

    def image(self, payload: bytes, mime: str) -> int:
        return self._append("images", {"bufferView": self.data(payload), "mimeType": mime})

    def add(self, item: str, value: dict) -> int:
        """A new top-level entry (a material, texture, mesh) written as given; its index."""
        return self._append(item, value)

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



def _mark_buffer_targets(tree: dict) -> None:
    """Say which buffer views hold vertices and which indices, as engines prefer to be told."""
    for mesh in tree.get("meshes", []):
        for primitive in mesh["primitives"]:
            for accessor in primitive["attributes"].values():
                tree["bufferViews"][tree["accessors"][accessor]["bufferView"]]["target"] = ARRAY_BUFFER
            if "indices" in primitive:
                view = tree["accessors"][primitive["indices"]]["bufferView"]
                tree["bufferViews"][view]["target"] = ELEMENT_ARRAY_BUFFER
