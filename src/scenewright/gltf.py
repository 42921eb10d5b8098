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
"""

from __future__ import annotations

import copy
import json
import struct
from collections.abc import Callable, Iterable, Mapping

#: Material fields that hold plain values (no texture references), at the top level and
#: inside ``pbrMetallicRoughness``.
_FIELDS = ("name", "emissiveFactor", "alphaMode", "alphaCutoff", "doubleSided")
_PBR_FIELDS = ("baseColorFactor", "metallicFactor", "roughnessFactor")


def srgb_to_linear(values: Iterable[float]) -> tuple[float, ...]:
    """The sRGB transfer function inverted, per channel (IEC 61966-2-1): display values
    in 0..1 to the linear values glTF factors hold."""
    out = []
    for value in values:
        c = min(1.0, max(0.0, float(value)))
        out.append(c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4)
    return tuple(out)


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
