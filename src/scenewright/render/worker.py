"""The Blender side of rendering: the only module that imports ``bpy``.

Run as ``python -m scenewright.render.worker job.json``; it reads the job, renders, and
writes the result JSON the job names. Running it in its own process means a Blender crash
(or Blender's global state) never reaches the pipeline.

Per view it first renders a one-sample object-index pass at a quarter of the picture's width
and height — every object's material replaced by an emission of its ``pass_index`` (index =
R + 256·G, exact because the view transform is Raw and dithering is off) — counts the pixels
of each object against the pixels its box would cover unhidden, chooses the view (see
:func:`scenewright.render.views.best_view`), then renders the chosen views with Cycles,
denoised by OpenImageDenoise.
"""

from __future__ import annotations

import json
import logging
import math
import sys
import tempfile
import time
from pathlib import Path

import bpy
import numpy as np
from mathutils import Matrix
from PIL import Image

from scenewright.files import write_atomic
from scenewright.render.views import (
    LENS_MM,
    SENSOR_MM,
    best_view,
    camera_matrix,
    projected_area,
    visibility,
)

log = logging.getLogger(__name__)

#: style → (world colour, world strength, sun colour, sun strength, sun elevation, sun angle,
#: view transform). Styles not listed light like "realistic".
LIGHTING = {
    "realistic": ((0.50, 0.68, 0.95), 0.6, (1.0, 0.96, 0.9), 3.0, 50.0, 2.0, "AgX"),
    "cartoon": ((0.62, 0.80, 1.0), 1.3, (1.0, 1.0, 0.97), 2.2, 60.0, 15.0, "Standard"),
    "anime": ((0.72, 0.84, 1.0), 0.9, (1.0, 0.98, 0.95), 1.7, 60.0, 15.0, "Standard"),
    "low-poly": ((0.66, 0.82, 1.0), 1.1, (1.0, 0.97, 0.9), 2.6, 55.0, 8.0, "Standard"),
    "cyberpunk": ((0.05, 0.04, 0.12), 1.0, (0.5, 0.6, 1.0), 1.4, 35.0, 5.0, "AgX"),
    "steampunk": ((0.45, 0.32, 0.2), 0.6, (1.0, 0.74, 0.48), 3.2, 28.0, 4.0, "AgX"),
}
#: Plain ground colours by kind, for scenes without a ground texture.
GROUND_COLOURS = {"grass": (0.18, 0.32, 0.1), "sand": (0.76, 0.66, 0.46), "water": (0.1, 0.25, 0.4)}
#: Metres one repeat of the ground texture covers.
TILE_METRES = 2.0


def _clear() -> None:
    bpy.ops.wm.read_factory_settings(use_empty=True)


def _object_id(obj, ids: set[str]) -> str | None:
    """The scene id of the node an imported object belongs to (itself or an ancestor)."""
    while obj is not None:
        if obj.name in ids:
            return obj.name
        obj = obj.parent
    return None


def _is_ground(obj) -> bool:
    """Whether the node is the GLB's ground or water (or under it): the worker lays its own."""
    while obj is not None:
        if obj.name.lower().startswith(("ground", "water")):
            return True
        obj = obj.parent
    return False


def import_scene(glb: str, ids: list[str]) -> dict[str, list]:
    """Import the GLB, drop its ground and water nodes (the worker lays its own), index each object's meshes."""
    bpy.ops.import_scene.gltf(filepath=glb)
    known = set(ids)
    parts: dict[str, list] = {object_id: [] for object_id in ids}
    for obj in list(bpy.context.scene.objects):
        object_id = _object_id(obj, known)
        if object_id is None and _is_ground(obj):
            bpy.data.objects.remove(obj, do_unlink=True)
            continue
        obj.pass_index = ids.index(object_id) + 1 if object_id else 0
        if object_id and obj.type == "MESH":
            parts[object_id].append(obj)
    return parts


def _material(name: str):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    return mat, mat.node_tree.nodes, mat.node_tree.links


def add_ground(low, high, texture: str | None, kind: str, horizon, z: float = 0.0) -> None:
    """A ground reaching far past the scene that fades into the sky's colour as it recedes.

    A ground a few scene sizes wide ended at a hard edge with a band of the world's colour
    above it; this one is wide enough that its edge sits at the horizon, and camera rays see
    it blend into ``horizon`` (the sky as the camera sees it) with distance, like aerial
    haze, so there is no line where it stops and no tiled texture shimmering in the
    distance. Light and shadow rays still see the plain ground. (A gradient sky was tried
    too: any non-constant world cost about 40 % more render time, and the three views look
    down past the horizon at 16:9 anyway.)
    """
    cx, cy = (low[0] + high[0]) / 2.0, (low[1] + high[1]) / 2.0
    reach = max(high[0] - low[0], high[1] - low[1], 8.0) / 2.0
    half = reach * 60.0
    verts = [(cx - half, cy - half, z), (cx + half, cy - half, z), (cx + half, cy + half, z), (cx - half, cy + half, z)]
    mesh = bpy.data.meshes.new("ground")
    mesh.from_pydata(verts, [], [(0, 1, 2, 3)])
    uv = mesh.uv_layers.new(name="UVMap")
    for loop in mesh.loops:
        x, y, _ = verts[loop.vertex_index]
        uv.data[loop.index].uv = (x / TILE_METRES, y / TILE_METRES)
    ground = bpy.data.objects.new("ground", mesh)
    bpy.context.scene.collection.objects.link(ground)
    ground.pass_index = 0
    mat, nodes, links = _material("ground")
    bsdf = nodes["Principled BSDF"]
    bsdf.inputs["Roughness"].default_value = 0.85
    if texture and Path(texture).is_file():
        tex = nodes.new("ShaderNodeTexImage")
        tex.image = bpy.data.images.load(texture)
        tex.extension = "REPEAT"
        links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    else:
        colour = GROUND_COLOURS.get(kind, (0.45, 0.43, 0.4))
        bsdf.inputs["Base Color"].default_value = (*colour, 1.0)
    _haze(mat, bsdf, horizon, (cx, cy, z), reach)
    mesh.materials.append(mat)


def _haze(mat, bsdf, horizon, centre, reach: float) -> None:
    """Fade the plane's ``bsdf`` into ``horizon`` with distance from ``centre``, for camera rays only."""
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    haze = nodes.new("ShaderNodeEmission")
    haze.inputs["Color"].default_value = (*horizon, 1.0)
    distance = nodes.new("ShaderNodeVectorMath")
    distance.operation = "DISTANCE"
    links.new(nodes.new("ShaderNodeTexCoord").outputs["Object"], distance.inputs[0])
    distance.inputs[1].default_value = centre
    fade = nodes.new("ShaderNodeMapRange")
    fade.interpolation_type = "SMOOTHSTEP"
    fade.inputs["From Min"].default_value = reach * 3.0
    fade.inputs["From Max"].default_value = reach * 25.0
    links.new(distance.outputs["Value"], fade.inputs["Value"])
    camera_only = nodes.new("ShaderNodeMath")
    camera_only.operation = "MULTIPLY"
    links.new(fade.outputs["Result"], camera_only.inputs[0])
    links.new(nodes.new("ShaderNodeLightPath").outputs["Is Camera Ray"], camera_only.inputs[1])
    mix = nodes.new("ShaderNodeMixShader")
    links.new(camera_only.outputs["Value"], mix.inputs["Fac"])
    links.new(bsdf.outputs["BSDF"], mix.inputs[1])
    links.new(haze.outputs["Emission"], mix.inputs[2])
    links.new(mix.outputs["Shader"], nodes["Material Output"].inputs["Surface"])
    # The haze only colours what the camera sees (it is zero for every other ray), so Cycles
    # must not spend light samples on the huge plane as if it were a lamp.
    mat.cycles.emission_sampling = "NONE"


#: The water's colour (linear) and how much of the ground beneath shows through it.
WATER_COLOUR = (0.03, 0.11, 0.19)
WATER_ALPHA = 0.85


def add_water(low, high, shore: float, level: float, horizon) -> None:
    """The water beyond the shore: a smooth blue plane from the shore line to the horizon, as
    wide as the ground, hazed like it with distance."""
    cx, cy = (low[0] + high[0]) / 2.0, (low[1] + high[1]) / 2.0
    reach = max(high[0] - low[0], high[1] - low[1], 8.0) / 2.0
    half = reach * 60.0
    verts = [(cx - half, shore, level), (cx + half, shore, level), (cx + half, cy + half, level),
             (cx - half, cy + half, level)]
    mesh = bpy.data.meshes.new("water")
    mesh.from_pydata(verts, [], [(0, 1, 2, 3)])
    water = bpy.data.objects.new("water", mesh)
    bpy.context.scene.collection.objects.link(water)
    water.pass_index = 0
    mat, nodes, _ = _material("water")
    bsdf = nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*WATER_COLOUR, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.08
    bsdf.inputs["Alpha"].default_value = WATER_ALPHA
    _haze(mat, bsdf, horizon, (cx, cy, level), reach)
    mesh.materials.append(mat)


def cut_away(names: set[str]) -> None:
    """Leave the named room nodes (and what hangs under them) out of the next render, bring back the rest."""
    for obj in bpy.context.scene.objects:
        node, hide = obj, False
        while node is not None and not hide:
            hide, node = node.name in names, node.parent
        obj.hide_render = hide


def add_lighting(style: str, low, high) -> str:
    """World and lamps for the style; returns the view transform the style looks right in."""
    world_colour, world_strength, sun_colour, sun_strength, elevation, angle, transform = LIGHTING.get(
        style, LIGHTING["realistic"]
    )
    scene = bpy.context.scene
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (*world_colour, 1.0)
    background.inputs["Strength"].default_value = world_strength
    scene.world = world

    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", type="SUN"))
    sun.data.energy = sun_strength
    sun.data.color = sun_colour
    sun.data.angle = math.radians(angle)
    # From the front-left, so the fronts the cameras look at are lit.
    sun.rotation_euler = (math.radians(90.0 - elevation), 0.0, math.radians(-35.0))
    scene.collection.objects.link(sun)

    if style == "cyberpunk":
        # Neon accents: magenta and cyan lamps at opposite corners, bright enough at the centre.
        reach = max(float(np.linalg.norm(np.subtract(high, low))) / 2.0, 2.0)
        for name, colour, corner in (
            ("neon_magenta", (1.0, 0.1, 0.7), (low[0], low[1])),
            ("neon_cyan", (0.1, 0.8, 1.0), (high[0], low[1])),
        ):
            lamp = bpy.data.objects.new(name, bpy.data.lights.new(name, type="POINT"))
            lamp.data.color = colour
            lamp.data.energy = 4.0 * math.pi * reach**2 * 1.2
            lamp.data.shadow_soft_size = 0.5
            lamp.location = (corner[0], corner[1], max(high[2], 1.0) + 1.0)
            scene.collection.objects.link(lamp)
    return transform


def add_camera(aspect: float):
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    camera.data.lens = LENS_MM
    camera.data.sensor_width = SENSOR_MM
    camera.data.sensor_fit = "AUTO"
    camera.data.clip_start = 0.05
    camera.data.clip_end = 10000.0
    bpy.context.scene.collection.objects.link(camera)
    bpy.context.scene.camera = camera
    return camera


def index_material():
    """Emission of (pass_index mod 256, pass_index // 256, 0) / 255: the object-index pass."""
    mat, nodes, links = _material("object_index")
    for node in list(nodes):
        nodes.remove(node)

    def math(operation: str, value, constant: float | None = None):
        node = nodes.new("ShaderNodeMath")
        node.operation = operation
        links.new(value, node.inputs[0])
        if constant is not None:
            node.inputs[1].default_value = constant
        return node.outputs[0]

    index = nodes.new("ShaderNodeObjectInfo").outputs["Object Index"]
    combine = nodes.new("ShaderNodeCombineColor")
    links.new(math("DIVIDE", math("FLOORED_MODULO", index, 256.0), 255.0), combine.inputs["Red"])
    links.new(math("DIVIDE", math("FLOOR", math("DIVIDE", index, 256.0)), 255.0), combine.inputs["Green"])
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Strength"].default_value = 1.0
    links.new(combine.outputs["Color"], emission.inputs["Color"])
    links.new(emission.outputs["Emission"], nodes.new("ShaderNodeOutputMaterial").inputs["Surface"])
    return mat


def configure(job: dict) -> None:
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.render.resolution_x, scene.render.resolution_y = job["resolution"]
    scene.render.resolution_percentage = 100
    scene.render.use_persistent_data = True  # one BVH build for every view
    # A sun, the sky and at most two lamps: the light tree's build and traversal cost more CPU
    # than its better choice among so few lights saves (docs/rendering.md).
    scene.cycles.use_light_tree = False
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGBA"
    scene.render.image_settings.color_depth = "8"


#: The object-index pass is rendered this many times smaller on each side than the preview: it
#: only counts pixels per object to choose the view, and costs a sixteenth of a full-size pass.
INDEX_SCALE = 4


def render_index(path: Path, override) -> None:
    scene = bpy.context.scene
    scene.render.resolution_percentage = 100 // INDEX_SCALE
    layer = scene.view_layers[0]
    saved = (scene.view_settings.view_transform, scene.view_settings.look, scene.render.film_transparent)
    layer.material_override = override
    scene.cycles.samples = 1
    scene.cycles.use_denoising = False
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.max_bounces = 0
    scene.render.dither_intensity = 0.0
    scene.render.film_transparent = True
    scene.view_settings.view_transform = "Raw"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)
    layer.material_override = None
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform, scene.view_settings.look, scene.render.film_transparent = saved


def render_beauty(path: Path, job: dict, transform: str) -> None:
    scene = bpy.context.scene
    scene.cycles.samples = job["samples"]
    scene.cycles.use_adaptive_sampling = True
    scene.cycles.adaptive_threshold = 0.05
    # Previews of opaque furniture gain little past a few bounces; each costs time on a CPU.
    total, diffuse, glossy = job.get("bounces", (4, 2, 2))
    scene.cycles.max_bounces = total
    scene.cycles.diffuse_bounces = diffuse
    scene.cycles.glossy_bounces = glossy
    scene.cycles.transmission_bounces = min(total, 4)
    scene.cycles.transparent_max_bounces = 4
    # Caustics are noise in a preview of opaque things, and filter glossy blurs what is left.
    scene.cycles.caustics_reflective = scene.cycles.caustics_refractive = False
    scene.cycles.blur_glossy = 1.0
    scene.cycles.use_denoising = job["denoise"]
    if job["denoise"]:
        scene.cycles.denoiser = "OPENIMAGEDENOISE"
        # Albedo and normal guide the denoiser, so edges and textures stay crisp at few samples.
        scene.cycles.denoising_input_passes = "RGB_ALBEDO_NORMAL"
        # The guides of opaque, sharp-focused previews are clean after a couple of samples:
        # denoising them as well (ACCURATE) was half of a default preview's CPU time and changed
        # no visible pixel (docs/rendering.md).
        scene.cycles.denoising_prefilter = job.get("denoise_prefilter", "ACCURATE")
        scene.cycles.denoising_quality = job.get("denoise_quality", "HIGH")
    scene.render.dither_intensity = 1.0
    scene.render.film_transparent = job["transparent"]
    scene.view_settings.view_transform = transform
    # AgX alone flattens saturated asset colours; its punchy look keeps them.
    scene.view_settings.look = "AgX - Punchy" if transform == "AgX" else "None"
    scene.view_settings.exposure = 0.4 if transform == "AgX" else 0.0  # AgX maps mid-grey darker
    scene.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)


def run(job: dict) -> dict:
    started, started_cpu = time.perf_counter(), time.process_time()
    _clear()
    configure(job)
    ids: list[str] = job["ids"]
    low, high = job["bounds"]
    parts = import_scene(job["glb"], ids)
    missing = [object_id for object_id, meshes in parts.items() if not meshes]
    world_colour, world_strength = LIGHTING.get(job["style"], LIGHTING["realistic"])[:2]
    horizon = tuple(c * world_strength for c in world_colour)
    add_ground(low, high, job.get("ground_texture"), job.get("ground_kind", ""), horizon, job.get("ground_z", 0.0))
    if job.get("water"):
        add_water(low, high, job["water"]["shore"], job["water"]["level"], horizon)
    hidden = {view: set(names) for view, names in job.get("hidden", {}).items()}
    transform = add_lighting(job["style"], low, high)
    width, height = job["resolution"]
    camera = add_camera(width / height)
    override = index_material()
    out = Path(job["out_dir"])
    out.mkdir(parents=True, exist_ok=True)
    visible: dict[str, dict[str, int]] = {}
    expected: dict[str, dict[str, float]] = {}
    frame_pixels = 0
    index_started = time.process_time()
    with tempfile.TemporaryDirectory(prefix="scenewright-index-") as tmp:
        for view in job["views"]:
            camera.matrix_world = Matrix(camera_matrix(view, job["frame"], width / height).tolist())
            cut_away(hidden.get(view, set()))
            index_png = Path(tmp) / f"{view}.png"
            render_index(index_png, override)
            image = np.asarray(Image.open(index_png).convert("RGBA"))
            visible[view] = visibility(image, ids)
            matrix = camera_matrix(view, job["frame"], width / height)
            size = (image.shape[1], image.shape[0])
            expected[view] = {oid: projected_area(box, matrix, size) for oid, box in job.get("boxes", {}).items()}
            frame_pixels = image.shape[0] * image.shape[1]
    index_cpu = round(time.process_time() - index_started, 3)
    best = best_view(visible, expected or None, job.get("weights"), frame_pixels)
    chosen = list(job["views"]) if job["keep_all"] else [best]
    chosen.sort(key=lambda v: v != best)
    images, seconds, cpu = {}, {}, {}
    for view in chosen:
        camera.matrix_world = Matrix(camera_matrix(view, job["frame"], width / height).tolist())
        cut_away(hidden.get(view, set()))
        t0, c0 = time.perf_counter(), time.process_time()
        path = out / f"{view}.png"
        render_beauty(path, job, transform)
        images[view], seconds[view] = str(path), round(time.perf_counter() - t0, 3)
        cpu[view] = round(time.process_time() - c0, 3)
    return {
        "best": best,
        "images": images,
        "visible": visible,
        "missing": missing,
        "render_seconds": seconds,
        # CPU seconds (all threads) per view and for the whole worker: what a loaded machine
        # does not inflate, so previews can be compared across runs.
        "render_cpu_seconds": cpu,
        "index_cpu_seconds": index_cpu,
        "total_seconds": round(time.perf_counter() - started, 3),
        "total_cpu_seconds": round(time.process_time() - started_cpu, 3),
        "blender": bpy.app.version_string,
        "denoiser": "OPENIMAGEDENOISE" if job["denoise"] else None,
    }


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        sys.stderr.write("usage: python -m scenewright.render.worker JOB.json\n")
        return 2
    job = json.loads(Path(argv[0]).read_text(encoding="utf-8"))
    result = run(job)
    write_atomic(job["result"], json.dumps(result, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
