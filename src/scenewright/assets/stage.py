"""The Object Generation stage (paper §3.2): one normalised GLB per object.

Asset generation dominates a run (80 % of an hour in the paper), so the stage never pays
twice: an object whose asset file is on disk is skipped, the backend's raw answer is cached
by a hash of the request, and the document is saved as each asset lands, so a killed run
resumes with only the unfinished objects. Requests go to the backend one per call, as many
at a time as the backend asks for (its ``concurrency``: the jobs it runs at once, or all of
them when it queues jobs itself), which lets each finished asset be stored at once instead of
waiting for the whole batch. A backend with a ``provenance(ids)`` method says which server
built which asset and which attempts failed; that goes into the scene's record with the
stage's own summary. The stage does not save the document: the caller does when it ends
(also on an error or Ctrl-C) and at the checkpoints offered as each asset lands. The bytes
written go into the run's :class:`~scenewright.assets.load.AssetMeshes`, so the later stages
do not read and parse them again.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor, as_completed, wait

from scenewright.assets.load import AssetMeshes
from scenewright.assets.normalise import mesh_library, stored_glb
from scenewright.core.protocols import MeshGenerator, MeshRequest
from scenewright.cache import RequestCache, request_key
from scenewright.errors import BackendError, InputError
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.scene import Scene, SceneObject

log = logging.getLogger(__name__)

CACHE_KIND = "meshes"
#: Seconds a Ctrl-C waits for the request threads: a job its server has just finished is
#: handed over by its thread a moment later (a queueing backend may already have sent the next
#: one), and once cancelled the others end within a poll interval.
HANDOVER_SECONDS = 2.0


def needs_asset(obj: SceneObject, folder: SceneFolder, store: AssetMeshes) -> bool:
    """Whether ``obj`` has no usable asset: none, missing, empty, corrupt or without triangles."""
    problem = store.problem(obj, folder)
    if problem is not None and obj.asset is not None:
        log.warning("object %r: %s; it is built again", obj.id, problem)
    return problem is not None


def mesh_request(obj: SceneObject, folder: SceneFolder, style: str) -> MeshRequest:
    image = None
    path = folder.image_of(obj)
    if path is not None:
        try:
            image = folder.read_image(path, f"objects[{obj.id}].image")
        except FileNotFoundError:
            raise InputError(
                f"object {obj.id!r}: its image {obj.image} is missing from {folder.root}; "
                "restore it or clear the object's 'image' field to build from the description"
            ) from None
    return MeshRequest(
        id=obj.id,
        name=obj.name,
        category=obj.category,
        description=obj.visual_description,
        style=style,
        size=obj.size,
        image=image,
    )


def cache_key(meshes: MeshGenerator, request: MeshRequest) -> str:
    """What the backend builds from: the image when there is one, else the words and size.

    The id is part of a description's key because generators vary look-alike objects by id
    (two chairs of one scene are not the same mesh). ``params`` is the backend's own say in
    what changes its output (Hunyuan3D's generation settings, a library's contents).
    """
    params = dict(meshes.params)
    if request.image is not None:
        return request_key(meshes.name, params, request.image, request.style)
    return request_key(
        meshes.name, params, request.id, request.name, request.category, request.description,
        request.style, request.size.tuple(),
    )


def generate_assets(
    scene: Scene,
    folder: SceneFolder,
    meshes: MeshGenerator,
    cache: RequestCache,
    progress: Callable[[str], None] | None = None,
    *,
    max_faces: int | None = None,
    store: AssetMeshes | None = None,
    checkpoint: Callable[[], None] = lambda: None,
) -> Scene:
    """Build every missing asset of ``scene`` (in place), writing ``assets/<id>.glb``.

    Each object gets ``asset`` and the x/y size of its rescaled mesh. When some objects
    fail, the others are still stored and a BackendError names each failure. ``store`` (the
    run's parsed assets) learns each file written; ``checkpoint`` is offered after each one
    (the caller saves the document, see :class:`~scenewright.folder.DocumentSaver`).
    """
    parsed = store if store is not None else AssetMeshes()
    todo = [obj for obj in scene.objects if needs_asset(obj, folder, parsed)]
    if not todo:
        return scene
    requests = {obj.id: mesh_request(obj, folder, scene.style) for obj in todo}
    keys = {oid: cache_key(meshes, req) for oid, req in requests.items()}
    raw: dict[str, bytes] = {}
    for oid, key in keys.items():
        hit = cache.get(CACHE_KIND, key)
        if hit is not None:
            raw[oid] = hit
    missing = [requests[oid] for oid in requests if oid not in raw]
    log.info("assets: %d to build, %d from the cache, %d with %s",
             len(todo), len(raw), len(missing), meshes.name)

    failures: dict[str, str] = {}
    if not getattr(meshes, "in_convention", False):
        # Its meshes will need normalising with the mesh library: import it before any job
        # runs, so a Ctrl-C while jobs run is never held up by that import.
        mesh_library()

    def store(oid: str, glb: bytes) -> None:
        obj = scene.get(oid)
        try:
            data, size = stored_glb(glb, obj.size, name=oid, backend=meshes.name, max_faces=max_faces)
        except BackendError as exc:
            failures[oid] = str(exc)
            return
        path = write_atomic(folder.asset(oid), data)
        parsed.add(path, data)
        obj.asset = folder.relative(path)
        obj.size = size
        checkpoint()
        if progress:
            progress(oid)

    for oid in list(raw):
        store(oid, raw[oid])
    width = max(1, min(len(missing), meshes.concurrency))
    pool = ThreadPoolExecutor(max_workers=width, thread_name_prefix="assets")
    futures = {}
    stored: set[str] = set()

    def land(oid: str, glb: bytes) -> None:
        store(oid, glb)
        stored.add(oid)
        if oid not in failures:  # a broken mesh is asked for again next time
            cache.put(CACHE_KIND, keys[oid], glb)

    try:
        futures = {pool.submit(meshes.generate, [req], progress): req.id for req in missing}
        for future in as_completed(futures):
            oid = futures[future]
            try:
                glb = future.result()[oid]
            except BackendError as exc:
                failures[oid] = str(exc)
                continue
            except KeyError:
                failures[oid] = f"{meshes.name} returned no mesh for {oid!r}"
                continue
            land(oid, glb)
    except KeyboardInterrupt:
        # Ctrl-C: requests not yet started are never sent, running ones are abandoned (when the
        # backend can), and meshes that finished meanwhile are kept: they are paid for.
        pool.shutdown(wait=False, cancel_futures=True)
        meshes.cancel()
        wait(futures, timeout=HANDOVER_SECONDS)
        for future, oid in futures.items():
            if oid not in stored and future.done() and not future.cancelled() and future.exception() is None:
                glb = future.result().get(oid)
                if glb is not None:
                    land(oid, glb)
        raise
    finally:
        pool.shutdown(wait=False, cancel_futures=True)

    built = [obj.id for obj in todo if obj.id not in failures]
    servers = getattr(meshes, "provenance", None)
    scene.record("assets", f"built {len(built)} assets with {meshes.name}", objects=built,
                 from_cache=sorted(set(raw) & set(built)),
                 **(servers([r.id for r in missing]) if callable(servers) else {}))
    if failures:
        details = "; ".join(f"{oid}: {why}" for oid, why in failures.items())
        raise BackendError(
            f"{len(failures)} of {len(todo)} assets failed with {meshes.name} "
            f"({len(built)} stored; re-run to retry only the failed ones): {details}"
        )
    return scene
