"""Physical properties per object: collision pieces, mass, centre of mass, inertia, friction, static or not.

Derived from the object's asset and words, stored in the document (``SceneObject.physics``) and
the convex pieces in ``colliders/<id>.npz``; the pieces are also cached by a hash of the asset,
so re-exporting, editing another object or generating the same asset again never recomputes
them. A record is derived again when its asset or words change (its ``key``).

Mass is an effective density per kind of thing times the mesh's solid volume: procedural and
image-to-3D meshes are solid where the real thing is hollow or stuffed (a sofa is foam and air,
a cabinet is boards around nothing), so densities are per category, chosen to give typical
masses, not the density of the raw material. Mass is spread over the collision pieces, which
gives the centre of mass and the inertia the simulator sees.
"""

from __future__ import annotations

import logging
import re

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from scenewright.core.catalogue import load_catalogue
from scenewright.assets import asset_mesh
from scenewright.cache import RequestCache, request_key
from scenewright.errors import InputError
from scenewright.export.colliders import VERSION as COLLIDER_VERSION
from scenewright.export.colliders import Collider, coacd_available, collider
from scenewright.export.visual import size_box
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.scene import ObjectPhysics, Scene, SceneObject, Vec3

log = logging.getLogger(__name__)

CACHE_KIND = "colliders"
#: Version of the derivation below: records of another version are derived again.
VERSION = 2

#: Effective density (kg/m³ of the mesh's solid volume) per procedural shape; see the module doc.
DENSITY = {
    "table": 500, "round_table": 500, "coffee_table": 500, "desk": 400, "chair": 400, "armchair": 75,
    "office_chair": 150, "stool": 450, "sofa": 70, "bench": 450, "bed": 120, "bookshelf": 450, "cabinet": 110, "fireplace": 1500,
    "wardrobe": 110, "nightstand": 200, "counter": 250, "table_lamp": 500, "floor_lamp": 900,
    "pendant_lamp": 150, "rug": 150, "tv": 400, "monitor": 400, "laptop": 600, "potted_plant": 300, "vase": 1000,
    "bathtub": 300, "toilet": 400, "sink": 400, "stove": 250, "fridge": 150, "piano": 300, "clock": 300,
    "mirror": 800, "picture_frame": 500, "trash_can": 150, "crate": 300, "barrel": 300, "books": 700,
    "bottle": 400, "cup": 500, "bowl": 600, "tree": 600, "pine_tree": 600, "palm_tree": 600, "bush": 100,
    "flower_bed": 1200, "rock": 2600, "fountain": 2300, "statue": 2400, "lamp_post": 1500, "sign": 600,
    "fence": 600, "arch": 2000, "bollard": 2000, "hydrant": 3000, "car": 250, "truck": 250, "bus": 200,
    "bicycle": 800, "boat": 200, "building": 300, "house": 300, "kiosk": 200, "market_stall": 200, "tent": 30,
    "umbrella": 100, "swing": 300, "slide": 400, "treadmill": 400, "whiteboard": 500, "robot": 800,
    "crystal": 2600, "tower": 300, "well": 2200, "cart": 300, "pillar": 2400, "generic": 400,
}  # fmt: skip
DEFAULT_DENSITY = 400.0

#: Things fixed where they stand: built in, anchored in the ground, or too big to move. They
#: collide but never move in a simulator.
FIXED_SHAPES = frozenset({
    "building", "house", "tower", "kiosk", "market_stall", "tent", "tree", "pine_tree", "palm_tree",
    "lamp_post", "fence", "arch", "pillar", "fountain", "well", "swing", "slide", "bollard", "hydrant",
    "flower_bed", "bathtub", "toilet", "sink", "counter", "pendant_lamp",
    # rooted, grown from the ground, afloat or on a cradle, wall-mounted, on a plinth or frozen to
    # the ground (a snowman is a statue): none is a loose body standing on the ground
    "bush", "crystal", "boat", "whiteboard", "statue",
})  # fmt: skip
#: Living things hold their own pose (a bird on one leg, a cat on a chair's back); a rigid body
#: standing in for one would topple where the animal would not, so they do not move either.
ANIMALS = frozenset({"bird", "cat", "dog", "horse", "fish"})
#: Heavier than this (kg), an object is treated as immovable furniture or structure.
STATIC_MASS = 400.0

#: Coulomb friction per material word, the first word found in the object's description, else
#: in the name of its asset's largest material. Values are typical dry sliding coefficients.
FRICTION = (
    ("rubber", 1.0), ("tyre", 1.0), ("leather", 0.6), ("velvet", 0.7), ("fabric", 0.7), ("cushion", 0.7),
    ("wool", 0.7), ("linen", 0.7), ("cotton", 0.7), ("carpet", 0.7), ("rug", 0.7), ("wicker", 0.6),
    ("rattan", 0.6), ("concrete", 0.7), ("brick", 0.65), ("stone", 0.6), ("granite", 0.55), ("marble", 0.45),
    ("chrome", 0.3), ("glass", 0.35), ("crystal", 0.35), ("ceramic", 0.45), ("porcelain", 0.45),
    ("plastic", 0.4), ("lacquer", 0.4), ("steel", 0.4), ("iron", 0.4), ("alumin", 0.4), ("brass", 0.4),
    ("copper", 0.4), ("bronze", 0.4), ("gold", 0.4), ("silver", 0.4), ("metal", 0.4), ("wood", 0.5),
    ("oak", 0.5), ("walnut", 0.5), ("pine", 0.5), ("bamboo", 0.5), ("paper", 0.5), ("book", 0.5),
    ("leaf", 0.6), ("bark", 0.6), ("soil", 0.6),
)  # fmt: skip
DEFAULT_FRICTION = ("default", 0.5)


def _shape(obj: SceneObject) -> str:
    category = load_catalogue().get(obj.category or "")
    return category.shape if category is not None else "generic"


def _hangs(obj: SceneObject, hanging: set[str]) -> bool:
    category = load_catalogue().get(obj.category or "")
    return obj.id in hanging or (category is not None and category.rests == "hanging")


def friction(description: str, materials: list[str]) -> tuple[str, float]:
    """(material word, coefficient): the description's material first, then the asset's."""
    for text in (description.lower(), *(m.lower() for m in materials)):
        found = [(text.find(word), word, mu) for word, mu in FRICTION if re.search(rf"\b{word}", text)]
        if found:
            _, word, mu = min(found)
            return word, mu
    return DEFAULT_FRICTION


def mass_properties(piece: Collider, mass: float) -> tuple[np.ndarray, np.ndarray]:
    """Centre of mass and inertia tensor about it (3×3): ``mass`` shared among the hulls by the
    solid volume each stands for, spread evenly within each."""
    weights = np.array(piece.weights, dtype=float)
    centres = np.array([h.center_mass for h in piece.hulls])
    total = float(weights.sum())
    com = (weights[:, None] * centres).sum(axis=0) / total
    inertia = np.zeros((3, 3))
    for hull, weight, centre in zip(piece.hulls, weights, centres):
        d = centre - com
        # trimesh's moment of inertia is for density 1; this hull's density is weight / volume.
        inertia += np.asarray(hull.moment_inertia) * (weight / hull.volume) + weight * (d @ d * np.eye(3) - np.outer(d, d))
    return com, inertia * (mass / total)


#: Points of the collision pieces this close (m) to their lowest point are what the object stands on.
SUPPORT_BAND = 0.01
#: The centre of mass is kept within this share of its support polygon (scaled about its centre).
SUPPORT_SHARE = 0.9


def over_support(com: np.ndarray, piece: Collider) -> tuple[np.ndarray, float]:
    """The centre of mass moved horizontally over the object's support, and how far (m) it moved.

    Something that stands by itself has its centre of mass over what it stands on, or it would
    not stand. The mesh's volume is only a proxy for where the mass is (a cart's solid wheels
    against its thin bed), so when the proxy puts the centre outside the support polygon it is
    brought back toward the polygon's centre until it lies inside :data:`SUPPORT_SHARE` of it.
    A point or a line of support (a ball, a keel) has no inside, and the centre stays.
    """
    points = np.vstack([h.vertices for h in piece.hulls])
    low = points[points[:, 2] <= points[:, 2].min() + SUPPORT_BAND][:, :2]
    try:
        polygon = ConvexHull(low)
    except (QhullError, ValueError):
        return com, 0.0
    centre = low[polygon.vertices].mean(axis=0)
    normals, offsets = polygon.equations[:, :2], polygon.equations[:, 2]
    direction = com[:2] - centre
    reach = normals @ direction
    # Inside the scaled polygon: n·(c + t·d / share) + b <= 0 for every edge.
    limits = [-(n @ centre + b) * SUPPORT_SHARE / r for n, b, r in zip(normals, offsets, reach) if r > 1e-12]
    t = min([1.0, *limits])
    if t >= 1.0:
        return com, 0.0
    moved = com.copy()
    moved[:2] = centre + max(t, 0.0) * direction
    return moved, float(np.linalg.norm(moved[:2] - com[:2]))


def _materials_by_area(glb: bytes) -> list[str]:
    from scenewright.assets.normalise import parse_glb

    scene = parse_glb(glb)
    return sorted(scene.geometry, key=lambda name: -scene.geometry[name].area)


def properties(obj: SceneObject, piece: Collider, glb: bytes, *, hanging: bool, key: str, path: str) -> ObjectPhysics:
    """The physics record of ``obj`` from its collision pieces and asset."""
    shape = _shape(obj)
    density = float(DENSITY.get(shape, DEFAULT_DENSITY))
    volume = piece.volume if piece.volume > 0 else float(sum(h.volume for h in piece.hulls))
    mass = max(density * volume, 0.05)
    com, inertia = mass_properties(piece, mass)
    material, mu = friction(obj.visual_description or obj.name, _materials_by_area(glb) if obj.asset else [])
    static = hanging or shape in FIXED_SHAPES or obj.category in ANIMALS or mass > STATIC_MASS
    notes = list(piece.notes)
    if not static:
        com, moved = over_support(com, piece)
        if moved > 0:
            notes.append(f"centre of mass moved {100 * moved:.1f} cm to lie over the object's support")
    return ObjectPhysics(
        static=static,
        mass=round(mass, 4),
        center_of_mass=Vec3.of(com),
        inertia=(inertia[0, 0], inertia[1, 1], inertia[2, 2], inertia[0, 1], inertia[0, 2], inertia[1, 2]),
        friction=mu,
        material=material,
        density=density,
        volume=round(volume, 6),
        collider=path,
        method=piece.method,
        hulls=len(piece.hulls),
        notes=notes,
        key=key,
    )


def inertia_matrix(physics: ObjectPhysics) -> np.ndarray:
    ixx, iyy, izz, ixy, ixz, iyz = physics.inertia
    return np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])


def _source(obj: SceneObject, folder: SceneFolder) -> tuple[bytes, trimesh.Trimesh | None]:
    """What the record derives from: the asset's bytes (its mesh parsed later, only when needed);
    an object without an asset collides as its size box."""
    if obj.asset is None:
        return f"box {obj.size.tuple()}".encode(), size_box(obj.size)
    source = folder.resolve(obj.asset)
    try:
        return source.read_bytes(), None
    except FileNotFoundError:
        raise InputError(
            f"object {obj.id!r}: its asset {obj.asset} is missing from {folder.root}, so it has no "
            f"collision shape; re-run `scenewright generate --resume {folder.root}` to rebuild it"
        ) from None


def ensure_physics(
    scene: Scene, folder: SceneFolder, cache: RequestCache, *, use_coacd: bool | None = None
) -> dict[str, Collider]:
    """Derive every missing or stale physics record (saving the document when one changed); return
    each object's collision pieces by id."""
    if use_coacd is None:
        use_coacd = coacd_available()
    hanging = {c.source for c in scene.constraints if c.relation == "above"}
    pieces: dict[str, Collider] = {}
    derived = []
    for obj in scene.objects:
        glb, mesh = _source(obj, folder)
        hangs = _hangs(obj, hanging)
        key = request_key(
            "physics", VERSION, COLLIDER_VERSION, use_coacd, glb, obj.category, obj.name, obj.visual_description, hangs
        )
        path = folder.collider(obj.id)
        if obj.physics is not None and obj.physics.key == key and path.is_file():
            pieces[obj.id] = Collider.from_bytes(path.read_bytes())
            continue
        hull_key = request_key("colliders", COLLIDER_VERSION, use_coacd, glb)
        raw = cache.get(CACHE_KIND, hull_key)
        if raw is None:
            try:
                raw = collider(mesh if mesh is not None else asset_mesh(glb).to_trimesh(), use_coacd=use_coacd).to_bytes()
            except ValueError as exc:
                raise InputError(f"object {obj.id!r}: no collision shape from its asset {obj.asset}: {exc}") from None
            cache.put(CACHE_KIND, hull_key, raw)
        pieces[obj.id] = Collider.from_bytes(raw)
        write_atomic(path, raw)
        obj.physics = properties(obj, pieces[obj.id], glb, hanging=hangs, key=key, path=folder.relative(path))
        derived.append(obj.id)
    if derived:
        notes = {oid: scene.get(oid).physics.notes for oid in derived if scene.get(oid).physics.notes}
        scene.record("physics", f"derived physical properties of {len(derived)} objects", objects=derived, notes=notes)
        folder.save(scene)
        log.info("physics: derived %d records", len(derived))
    return pieces
