"""USD with UsdPhysics: what Isaac Sim, Omniverse and usdview open, one prim per object.

The stage is Z-up in metres and kilograms (the scene frame as it is). ``/World`` holds a
physics scene, the ground (a static box collider whose top is z = 0), the room when there is
one (``room/``: its meshes under ``visual/``, static box colliders for the walls under
``collision/``, openings left open) and one Xform per object,
named by its id (made a valid USD name when the id is not; the id itself is kept in the prim's
``scenewright:id`` attribute). Under each object: ``visual/`` meshes bound to
UsdPreviewSurface materials, and ``collision/`` convex pieces (CollisionAPI, convex-hull
approximation, guide purpose, bound to a physics material with the object's friction). A
dynamic object's prim has RigidBodyAPI and MassAPI (mass, centre of mass, principal inertia);
a static one has neither, which UsdPhysics reads as a static collider.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

from scenewright.errors import MissingExtra
from scenewright.export.colliders import Collider
from scenewright.export.ground import ground_extent
from scenewright.export.physics import inertia_matrix
from scenewright.export.visual import Look, object_parts, room_parts
from scenewright.folder import SceneFolder
from scenewright.geometry import object_matrix
from scenewright.scene import Scene

WORLD = "/World"
GROUND = "ground"
ROOM = "room"
GROUND_FRICTION = 0.8
GROUND_THICKNESS = 0.1
GROUND_COLOUR = (0.5, 0.5, 0.48)


def load_pxr():
    try:
        from pxr import Gf, Sdf, Tf, Usd, UsdGeom, UsdPhysics, UsdShade, Vt
    except ImportError:
        raise MissingExtra("USD export", "sim", "usd-core") from None
    return Gf, Sdf, Tf, Usd, UsdGeom, UsdPhysics, UsdShade, Vt


def prim_names(ids: list[str]) -> dict[str, str]:
    """Object id → a unique valid USD prim name (ids may hold '-' and '.', which USD names may not)."""
    _, _, Tf, *_ = load_pxr()
    names: dict[str, str] = {}
    taken = {GROUND, ROOM, "PhysicsScene", "Looks"}
    for oid in ids:
        name = Tf.MakeValidIdentifier(oid)
        base, n = name, 1
        while name in taken:
            n += 1
            name = f"{base}_{n}"
        taken.add(name)
        names[oid] = name
    return names


class _Writer:
    def __init__(self, stage):
        self.Gf, self.Sdf, _, self.Usd, self.UsdGeom, self.UsdPhysics, self.UsdShade, self.Vt = load_pxr()
        self.stage = stage
        self.looks: dict[Look, object] = {}

    def material(self, look: Look):
        """One UsdPreviewSurface material per distinct look, shared by every mesh that has it."""
        if look not in self.looks:
            path = f"{WORLD}/Looks/look_{len(self.looks)}"
            material = self.UsdShade.Material.Define(self.stage, path)
            shader = self.UsdShade.Shader.Define(self.stage, f"{path}/surface")
            shader.CreateIdAttr("UsdPreviewSurface")
            f = self.Sdf.ValueTypeNames
            shader.CreateInput("diffuseColor", f.Color3f).Set(self.Gf.Vec3f(*look.colour[:3]))
            shader.CreateInput("opacity", f.Float).Set(float(look.colour[3]))
            shader.CreateInput("metallic", f.Float).Set(look.metallic)
            shader.CreateInput("roughness", f.Float).Set(look.roughness)
            shader.CreateInput("emissiveColor", f.Color3f).Set(self.Gf.Vec3f(*look.emissive))
            material.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")
            self.looks[look] = material
        return self.looks[look]

    def mesh(self, path: str, mesh):
        prim = self.UsdGeom.Mesh.Define(self.stage, path)
        prim.CreatePointsAttr(self.Vt.Vec3fArray.FromNumpy(np.asarray(mesh.vertices, dtype=np.float32)))
        prim.CreateFaceVertexCountsAttr(self.Vt.IntArray.FromNumpy(np.full(len(mesh.faces), 3, dtype=np.int32)))
        prim.CreateFaceVertexIndicesAttr(self.Vt.IntArray.FromNumpy(np.asarray(mesh.faces, dtype=np.int32).ravel()))
        prim.CreateSubdivisionSchemeAttr("none")
        lo, hi = mesh.bounds
        prim.CreateExtentAttr([self.Gf.Vec3f(*map(float, lo)), self.Gf.Vec3f(*map(float, hi))])
        return prim

    def physics_material(self, path: str, friction: float):
        material = self.UsdShade.Material.Define(self.stage, path)
        api = self.UsdPhysics.MaterialAPI.Apply(material.GetPrim())
        api.CreateStaticFrictionAttr(friction)
        api.CreateDynamicFrictionAttr(friction)
        api.CreateRestitutionAttr(0.0)
        return material

    def bind(self, prim, material, purpose: str | None = None) -> None:
        api = self.UsdShade.MaterialBindingAPI.Apply(prim.GetPrim())
        if purpose is None:
            api.Bind(material)
        else:
            api.Bind(material, self.UsdShade.Tokens.weakerThanDescendants, purpose)


def _matrix(Gf, matrix: np.ndarray):
    # USD multiplies row vectors: its matrices are the transpose of ours.
    return Gf.Matrix4d(*[float(v) for v in matrix.T.ravel()])


def _object(w: _Writer, path: str, obj, folder: SceneFolder, piece: Collider) -> None:
    Gf, UsdGeom, UsdPhysics = w.Gf, w.UsdGeom, w.UsdPhysics
    xform = UsdGeom.Xform.Define(w.stage, path)
    xform.AddTransformOp().Set(_matrix(Gf, object_matrix(obj)))
    prim = xform.GetPrim()
    prim.CreateAttribute("scenewright:id", w.Sdf.ValueTypeNames.String).Set(obj.id)
    prim.CreateAttribute("scenewright:name", w.Sdf.ValueTypeNames.String).Set(obj.name)
    for k, part in enumerate(object_parts(obj, folder)):
        mesh = w.mesh(f"{path}/visual/part_{k}", part.mesh)
        w.bind(mesh, w.material(part.look))
    physics = obj.physics
    material = w.physics_material(f"{path}/physics_material", physics.friction)
    for k, hull in enumerate(piece.hulls):
        mesh = w.mesh(f"{path}/collision/hull_{k}", hull)
        mesh.CreatePurposeAttr(UsdGeom.Tokens.guide)
        UsdPhysics.CollisionAPI.Apply(mesh.GetPrim())
        UsdPhysics.MeshCollisionAPI.Apply(mesh.GetPrim()).CreateApproximationAttr(UsdPhysics.Tokens.convexHull)
        w.bind(mesh, material, "physics")
    if physics.static:
        return
    UsdPhysics.RigidBodyAPI.Apply(prim)
    mass = UsdPhysics.MassAPI.Apply(prim)
    mass.CreateMassAttr(float(physics.mass))
    mass.CreateCenterOfMassAttr(Gf.Vec3f(*physics.center_of_mass.tuple()))
    moments, axes = np.linalg.eigh(inertia_matrix(physics))
    if np.linalg.det(axes) < 0:
        axes[:, 2] = -axes[:, 2]
    x, y, z, qw = Rotation.from_matrix(axes).as_quat()
    mass.CreateDiagonalInertiaAttr(Gf.Vec3f(*map(float, np.maximum(moments, 1e-9))))
    mass.CreatePrincipalAxesAttr(Gf.Quatf(float(qw), float(x), float(y), float(z)))


def _room(w: _Writer, scene: Scene) -> None:
    from scenewright.procedural.room import wall_boxes

    Tf = load_pxr()[2]
    for part in room_parts(scene.room, scene.style):
        mesh = w.mesh(f"{WORLD}/{ROOM}/visual/{Tf.MakeValidIdentifier(part.name.removeprefix('room/'))}", part.mesh)
        w.bind(mesh, w.material(part.look))
    material = w.physics_material(f"{WORLD}/{ROOM}/physics_material", GROUND_FRICTION)
    for name, pose, extents in wall_boxes(scene.room):
        cube = w.UsdGeom.Cube.Define(w.stage, f"{WORLD}/{ROOM}/collision/{Tf.MakeValidIdentifier(name.removeprefix('room/'))}")
        cube.CreateSizeAttr(1.0)
        cube.AddTransformOp().Set(_matrix(w.Gf, pose))
        cube.AddScaleOp().Set(w.Gf.Vec3f(*map(float, extents)))
        cube.CreatePurposeAttr(w.UsdGeom.Tokens.guide)
        w.UsdPhysics.CollisionAPI.Apply(cube.GetPrim())
        w.bind(cube, material, "physics")


def _ground(w: _Writer, scene: Scene) -> None:
    lo, hi = ground_extent(scene.objects, scene.bounds, scene.room)
    cube = w.UsdGeom.Cube.Define(w.stage, f"{WORLD}/{GROUND}")
    cube.CreateSizeAttr(1.0)
    centre = ((lo + hi) / 2.0).tolist()
    cube.AddTranslateOp().Set(w.Gf.Vec3d(centre[0], centre[1], -GROUND_THICKNESS / 2.0))
    cube.AddScaleOp().Set(w.Gf.Vec3f(float(hi[0] - lo[0]), float(hi[1] - lo[1]), GROUND_THICKNESS))
    cube.CreateDisplayColorAttr([w.Gf.Vec3f(*GROUND_COLOUR)])
    w.UsdPhysics.CollisionAPI.Apply(cube.GetPrim())
    w.bind(cube, w.physics_material(f"{WORLD}/ground_material", GROUND_FRICTION), "physics")


def write_usd(scene: Scene, folder: SceneFolder, pieces: dict[str, Collider], path: Path) -> Path:
    """Write the stage to ``path`` (.usd binary, .usda text, .usdc), atomically; return it."""
    Gf, _, _, Usd, UsdGeom, UsdPhysics, _, _ = load_pxr()
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
    world = UsdGeom.Xform.Define(stage, WORLD)
    stage.SetDefaultPrim(world.GetPrim())
    stage.GetRootLayer().documentation = f"scenewright scene: {scene.text[:200]}"
    physics_scene = UsdPhysics.Scene.Define(stage, f"{WORLD}/PhysicsScene")
    physics_scene.CreateGravityDirectionAttr(Gf.Vec3f(0.0, 0.0, -1.0))
    physics_scene.CreateGravityMagnitudeAttr(9.81)
    writer = _Writer(stage)
    names = prim_names([o.id for o in scene.objects])
    for obj in scene.objects:
        _object(writer, f"{WORLD}/{names[obj.id]}", obj, folder, pieces[obj.id])
    _ground(writer, scene)
    if scene.room is not None:
        _room(writer, scene)
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    # USD picks the file format from the extension, so the temporary file keeps it.
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.stem}.", suffix=path.suffix)
    os.close(fd)
    try:
        if not stage.GetRootLayer().Export(tmp):
            raise OSError(f"USD could not write {tmp}")
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path
