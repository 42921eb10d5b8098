"""The object under construction: parts by role, then one fitted, styled, PBR glTF scene.

Generators draw in the scene frame inside the requested box — footprint centred on the
origin, bottom at z = 0, front toward −Y — with sizes taken from the box, so proportions
follow whatever size the layout asked for. :meth:`Model.finish` then fits the result to
the box exactly (bevels and chunky cartoon legs may poke out a little), shades it per
style, converts it to glTF (+Y up, front +Z) and gives each role its PBR material.
"""

from __future__ import annotations

import re
from collections import defaultdict
from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from scenewright.core.catalogue import mentions
from scenewright.geometry import SCENE_TO_GLTF
from scenewright.gltf import GltfWriter, srgb_to_linear
from scenewright.procedural import parts as P
from scenewright.procedural.style import NEON_ROLES, NEONS, Style, Surface

if TYPE_CHECKING:
    import trimesh
    from trimesh.visual.material import PBRMaterial


#: Rotations taking a part drawn about local +Z to one about the named axis. Local x and y
#: go to the two other axes in cyclic order (about x: y, z; about y: x, z), local +Z to +x,
#: −y or +z; all are proper rotations, so windings stay outward.
_AXES = {
    "z": np.eye(3),
    "x": np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0]], float),
    "y": np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], float),
}


class Model:
    """Parts of one object grouped by role; ``main`` is the role the description recolours."""

    def __init__(
        self, size, style: Style, rng: np.random.Generator, main: str = "wood", name: str = "", description: str = ""
    ):
        self.sx, self.sy, self.sz = (float(v) for v in size)
        #: What the object is (name and category) and how it is described, lower case:
        #: generators pick variants from them (a lighthouse among towers, a round rug).
        self.name = name.lower().replace("_", " ")
        self.text = f"{self.name} {description.lower()}"
        self.style = style
        self.rng = rng
        self.main = main
        self.parts: dict[str, list[P.Part]] = defaultdict(list)
        self.neon = NEONS[int(rng.integers(len(NEONS)))]
        #: Role → colour a generator chose where the text names none (a car's paint, one of the
        #: colours cars come in): applied as if described, so a colour the text names wins.
        self.tints: dict[str, tuple[float, float, float]] = {}
        #: Role → its glTF material, exact, as :meth:`finish` made it (trimesh keeps 8 bits).
        self.materials: dict[str, dict] = {}
        #: Words of the name that say what kind of thing it is, not what it is made of ("a wood
        #: stove" burns wood): a generator lists them, and no material is read from them.
        self.kind_words: tuple[str, ...] = ()

    def described_text(self) -> str:
        """Name and description, with the words that only name its kind left out."""
        return re.sub(rf"\b(?:{'|'.join(map(re.escape, self.kind_words))})\b", " ", self.text) if self.kind_words else self.text

    # Proportions -------------------------------------------------------------------------
    def thick(self, metres: float, limit: float | None = None) -> float:
        """A frame or leg thickness in this style, capped at ``limit`` (default: a quarter
        of the smaller footprint side) so chunky styles never swallow the object."""
        cap = limit if limit is not None else 0.25 * min(self.sx, self.sy)
        return min(self.style.thick(metres), cap)

    def segments(self, fraction: float = 1.0, minimum: int = 5) -> int:
        return max(minimum, int(round(self.style.segments * fraction)))

    def vary(self, low: float, high: float) -> float:
        return float(self.rng.uniform(low, high))

    # Drawing -----------------------------------------------------------------------------
    def add(self, role: str, part: P.Part) -> None:
        self.parts[role].append(part)

    def box(self, role: str, lo, hi, rounded: float | None = None) -> None:
        """Axis-aligned box by corners; edges rounded per style unless ``rounded`` is given."""
        radius = self.style.rounding(lo, hi) if rounded is None else rounded * (self.style.bevel > 0)
        self.add(role, P.box(lo, hi, radius))

    def cbox(self, role: str, centre, size, rounded: float | None = None) -> None:
        c, h = np.asarray(centre, float), np.asarray(size, float) / 2
        self.box(role, c - h, c + h, rounded)

    def cylinder(self, role: str, p0, p1, r0: float, r1: float | None = None, fraction: float = 1.0) -> None:
        self.add(role, P.frustum(p0, p1, r0, r0 if r1 is None else r1, self.segments(fraction)))

    def post(self, role: str, x: float, y: float, z0: float, z1: float, r: float, fraction: float = 0.6) -> None:
        """A vertical round post (legs, poles, trunks)."""
        self.cylinder(role, (x, y, z0), (x, y, z1), r, r, fraction)

    def legs(self, role: str, inset: float, z0: float, z1: float, r: float, square: bool = False,
             half_x: float | None = None, half_y: float | None = None) -> None:
        """Four legs at the corners of the footprint (or of a ``half_x`` × ``half_y`` rectangle)."""
        hx = (self.sx / 2 if half_x is None else half_x) - inset - r
        hy = (self.sy / 2 if half_y is None else half_y) - inset - r
        for x in (-hx, hx):
            for y in (-hy, hy):
                if square:
                    self.box(role, (x - r, y - r, z0), (x + r, y + r, z1))
                else:
                    self.post(role, x, y, z0, z1, r)

    def has(self, *words: str) -> bool:
        """Whether the name or description uses one of the words (an attribute: round, claw-foot)."""
        return mentions(self.text, words)

    def named(self, *words: str) -> bool:
        """Whether the object *is* one of these (its name or category), not merely described with it."""
        return mentions(self.name, words)

    def first_named(self, variants):
        """The build of the variant whose word comes first in the name, or ``None``: a name is
        the object's own words, then its category's ("forklift tractor" is a forklift, "ice
        chest cooler" a cooler). A word hyphened to the one before it describes ("a
        two-carriage train" is a train, not a carriage)."""
        found = [(match.start(), k) for k, (words, _) in enumerate(variants) for w in words
                 if (match := re.search(rf"(?<!-)\b{re.escape(w)}(?:e?s)?\b", self.name))]
        return variants[min(found)[1]][1] if found else None

    def lathe(self, role: str, profile, centre=(0.0, 0.0, 0.0), scale=(1.0, 1.0), fraction: float = 1.0) -> None:
        part = P.lathe(profile, self.segments(fraction))
        self.add(role, P.transform(part, P.affine(np.diag([scale[0], scale[1], 1.0]), centre)))

    def ball(self, role: str, centre, radii, fraction: float = 1.0) -> None:
        self.add(role, P.sphere(centre, radii, self.segments(fraction)))

    def leaf(self, role: str, p0, p1, width: float, thickness: float, fraction: float = 0.5) -> None:
        """A flat ellipsoid from ``p0`` to ``p1``, its broad side level (fronds, leaves, petals)."""
        p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
        d = p1 - p0
        length = float(np.linalg.norm(d))
        d = d / length
        side = np.cross(d, (0.0, 0.0, 1.0))
        side = side / np.linalg.norm(side) if np.linalg.norm(side) > 1e-6 else np.array([1.0, 0.0, 0.0])
        frame = np.column_stack([side, np.cross(side, d), d])
        unit = P.sphere((0, 0, 0), (width, thickness, length / 2), self.segments(fraction))
        self.add(role, P.transform(unit, P.affine(frame, (p0 + p1) / 2)))

    def torus(self, role: str, centre, major: float, minor: float, axis: str = "z", arc: float = 2 * np.pi,
              fraction: float = 1.0) -> None:
        """A ring or arc about ``axis``; an x-axis arc starts at +Y and turns over +Z,
        a y-axis arc starts at +X and turns over +Z (arches, handles, wheels)."""
        part = P.torus(major, minor, self.segments(fraction), self.segments(0.5, 4), arc)
        self.add(role, P.transform(part, P.affine(_AXES[axis], centre)))

    def extrude(self, role: str, outline, axis: str, start: float, end: float) -> None:
        """Extrude a counter-clockwise outline: along x the outline is (y, z), along y it is
        (x, z), along z it is (x, y)."""
        part = P.prism(outline, end - start)
        offset = np.zeros(3)
        offset["xyz".index(axis)] = end if axis == "y" else start
        self.add(role, P.transform(part, P.affine(_AXES[axis], offset)))

    def beam(self, role: str, p0, p1, width: float, height: float | None = None) -> None:
        self.add(role, P.beam(p0, p1, width, height))

    def inset(self, generator, lo, size, role: str | None = None) -> None:
        """Draw another generator's object into a box of ``size`` standing at ``lo`` (its
        footprint centred on ``lo``'s x/y, its bottom at ``lo``'s z), every part in ``role``
        when one is given: the lion on a statue's plinth, all in marble."""
        inner = Model(size, self.style, self.rng, main=self.main, name=self.name)
        inner.text = self.text
        generator(inner)
        offset = P.affine(np.eye(3), lo)
        for own, parts in inner.parts.items():
            for part in parts:
                self.add(role or own, P.transform(part, offset))

    # Output ------------------------------------------------------------------------------
    def fitted(self, described: Mapping[str, Surface] | None = None) -> list[tuple[str, P.Part]]:
        """Fit to the box, shade, convert to glTF: one part per role, in glTF axes, each
        role's exact PBR material in :attr:`materials`; ``described`` holds the surfaces the
        description asked for, by role."""
        described = described or {}
        if not self.parts:
            raise ValueError("a generator drew nothing")
        roles = list(self.parts)
        merged = {role: P.merge(self.parts[role]) for role in roles}
        points = np.concatenate([m.vertices for m in merged.values()])
        lo, hi = points.min(axis=0), points.max(axis=0)
        target = np.array([self.sx, self.sy, self.sz])
        scale = target / np.maximum(hi - lo, 1e-9)
        offset = np.array([-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]]) * scale
        place = P.affine(np.diag(scale), offset)
        fit = SCENE_TO_GLTF @ place
        if self.style.neon and not NEON_ROLES.intersection(roles):
            merged["trim"] = P.transform(self._trim(), np.linalg.inv(place))
            roles.append("trim")
        out = []
        for role in roles:
            part = P.drop_degenerate(P.transform(merged[role], fit))
            if self.style.flat:
                part = P.flatten(part)
            if role in described:
                surface = self.style.restyle(described[role], "described", self.neon)
            else:
                surface = self.style.surface(role, self.neon)
            self.materials[role] = gltf_material(role, surface)
            out.append((role, part))
        return out

    def glb(self, described: Mapping[str, Surface] | None = None) -> bytes:
        """The fitted object as GLB bytes: a node, mesh and exact material per role, written
        from the arrays (no mesh library: building an asset must not cost its import)."""
        out = GltfWriter("scenewright procedural")
        for role, part in self.fitted(described):
            out.mesh(role, part.vertices, part.faces, out.material(self.materials[role]), normals=part.normals)
        return out.to_bytes()

    def finish(self, described: Mapping[str, Surface] | None = None) -> trimesh.Scene:
        """:meth:`fitted` as a trimesh scene, one node and PBR material per role (trimesh's
        copy rounds the base colour to 8 bits; :attr:`materials` keeps it exact)."""
        import trimesh

        scene = trimesh.Scene()
        for role, part in self.fitted(described):
            mesh = trimesh.Trimesh(part.vertices, part.faces, vertex_normals=part.normals, process=False)
            mesh.visual = trimesh.visual.TextureVisuals(material=pbr_material(self.materials[role]))
            scene.add_geometry(mesh, geom_name=role, node_name=role)
        return scene

    def _trim(self) -> P.Part:
        """A neon strip around the base, for cyberpunk objects with no glowing part of their own
        (drawn in the fitted frame, where the box is exact)."""
        t = 0.03 * min(self.sx, self.sy, self.sz)
        x, y, h = self.sx / 2, self.sy / 2, min(0.04 * self.sz, 0.05)
        sides = (((-x, -y, 0), (x, -y + t, h)), ((-x, y - t, 0), (x, y, h)),
                 ((-x, -y, 0), (-x + t, y, h)), ((x - t, -y, 0), (x, y, h)))
        return P.merge([P.box(lo, hi) for lo, hi in sides])


def gltf_material(name: str, s: Surface) -> dict:
    """A surface as a glTF material: sRGB colours as linear factors; see-through surfaces
    blend (alpha) and, where a viewer supports it, transmit light (``KHR_materials_transmission``)."""
    material = {
        "name": name,
        "pbrMetallicRoughness": {
            "baseColorFactor": [*srgb_to_linear(s.color), float(s.alpha)],
            "metallicFactor": float(s.metallic),
            "roughnessFactor": float(s.roughness),
        },
        "emissiveFactor": list(srgb_to_linear(s.emissive)),
        "alphaMode": "BLEND" if s.alpha < 1 else "OPAQUE",
        "doubleSided": s.alpha < 1 or s.transmission > 0,
    }
    if s.transmission > 0:
        material["extensions"] = {"KHR_materials_transmission": {"transmissionFactor": float(s.transmission)}}
    return material


def pbr_material(material: dict) -> PBRMaterial:
    """trimesh's copy of a glTF material (its base colour rounded to 8 bits)."""
    from trimesh.visual.material import PBRMaterial

    pbr = material["pbrMetallicRoughness"]
    return PBRMaterial(
        name=material["name"],
        baseColorFactor=pbr["baseColorFactor"],
        metallicFactor=pbr["metallicFactor"],
        roughnessFactor=pbr["roughnessFactor"],
        emissiveFactor=material["emissiveFactor"],
        alphaMode=material["alphaMode"],
        doubleSided=material["doubleSided"],
    )
