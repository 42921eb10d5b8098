"""Convex collision pieces for an asset: what simulators collide, since they only do convex shapes well.

Three ways, the cheapest that is faithful wins:

- ``hull``: one convex hull, when the mesh fills most of its hull (a crate, a cabinet, a vase).
- ``parts``: one hull per separate part, when the mesh is made of parts (procedural assets are:
  a table's top and legs, a chair's seat, back and legs), so the space under a table top stays
  free for the chair pushed under it. Many small parts (books on a shelf, leaves of a plant) are
  grouped by position into at most :data:`MAX_HULLS` pieces.
- ``coacd``: an approximate convex decomposition by CoACD (the ``sim`` extra) of a single
  closed concave body (an image-to-3D mesh is one welded surface); without CoACD, or when the
  surface is open, its convex hull stands in and a note says so.

A mesh that is not watertight still gets hulls (a hull needs only points) and a note, since its
volume, and so its mass, is then an estimate.
"""

from __future__ import annotations

import io
import json
import logging
import multiprocessing
import warnings
from dataclasses import dataclass, field

import numpy as np
import trimesh
from scipy.cluster.vq import kmeans2
from scipy.spatial import ConvexHull, QhullError

log = logging.getLogger(__name__)

#: Version of the method: cached pieces from another version are computed again.
VERSION = 5
#: A mesh whose solid fills at least this share of its hull collides as the hull.
CONVEX_SHARE = 0.85
#: Upper bound of pieces per object: simulators slow down with every convex piece.
MAX_HULLS = 24
#: Flat parts (a screen's quad, a rug's top) are thickened inward by this many metres to make a hull.
MIN_THICKNESS = 0.004
#: An open surface (a lamp shade, a leaf) is a shell this many metres thick, not the solid its
#: hull encloses, so a shade does not outweigh the lamp's base.
SHELL_THICKNESS = 0.01
#: CoACD's concavity threshold (its default is 0.05; coarser is faster and enough for contact).
COACD_THRESHOLD = 0.08
#: A lighter search than CoACD's defaults: about half the time for the same number of pieces on
#: a ring (a few seconds instead of ten), which matters when a scene has dozens of assets.
#: Seconds CoACD may take for one mesh before the convex hull stands in.
COACD_SECONDS = 30.0
COACD_SEARCH = {"mcts_iterations": 60, "mcts_nodes": 10, "resolution": 1000, "preprocess_resolution": 30}


@dataclass
class Collider:
    hulls: list[trimesh.Trimesh]
    method: str
    notes: list[str] = field(default_factory=list)
    #: Solid volume (m³) of the asset: its watertight parts' volume, open surfaces as shells.
    volume: float = 0.0
    #: Solid volume each hull stands for, in the order of ``hulls``: where the mass sits.
    weights: list[float] = field(default_factory=list)

    def __post_init__(self) -> None:
        if not self.weights:
            self.weights = [float(h.volume) for h in self.hulls]

    def to_bytes(self) -> bytes:
        arrays = {"meta": np.array(json.dumps({"method": self.method, "notes": self.notes, "volume": self.volume, "weights": self.weights}))}
        for k, hull in enumerate(self.hulls):
            arrays[f"v{k}"] = np.asarray(hull.vertices, dtype=np.float64)
            arrays[f"f{k}"] = np.asarray(hull.faces, dtype=np.int32)
        buffer = io.BytesIO()
        np.savez(buffer, **arrays)
        return buffer.getvalue()

    @classmethod
    def from_bytes(cls, data: bytes) -> Collider:
        with np.load(io.BytesIO(data), allow_pickle=False) as npz:
            arrays = {name: npz[name] for name in npz.files}
        meta = json.loads(str(arrays["meta"]))
        count = sum(1 for name in arrays if name.startswith("v"))
        hulls = [trimesh.Trimesh(arrays[f"v{k}"], arrays[f"f{k}"], process=False) for k in range(count)]
        return cls(hulls, meta["method"], meta["notes"], meta["volume"], meta["weights"])


def coacd_available() -> bool:
    try:
        import coacd  # noqa: F401
    except ImportError:
        return False
    return True


def _convex(points: np.ndarray) -> trimesh.Trimesh | None:
    """The hull as a mesh straight from Qhull, faces turned outward (trimesh's own hull repairs and
    checks each one, which costs more than the hull when an asset has hundreds of parts)."""
    try:
        hull = ConvexHull(points)
    except QhullError:
        return None
    if not hull.volume > 0:
        return None
    used = np.unique(hull.simplices)
    index = np.full(len(points), -1)
    index[used] = np.arange(len(used))
    vertices, faces = points[used], index[hull.simplices]
    triangles = vertices[faces]
    normals = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    inward = np.einsum("ij,ij->i", normals, hull.equations[:, :3]) < 0
    faces[inward] = faces[inward][:, ::-1]
    return trimesh.Trimesh(vertices, faces, process=False)


def _hull(points: np.ndarray, inward: np.ndarray) -> trimesh.Trimesh | None:
    """The convex hull of points. A flat set (a screen's quad, a rug's face) is thickened toward
    ``inward`` (the middle of the whole mesh), so the piece never pokes out of the object and
    into what it rests on or what rests on it."""
    points = np.unique(np.asarray(points, dtype=float).round(9), axis=0)
    if len(points) < 3:
        return None
    middle = points.mean(axis=0)
    _, singular, axes = np.linalg.svd(points - middle, full_matrices=False)
    if len(singular) < 3 or singular[2] < 1e-6 * max(singular[0], 1e-12):
        normal = axes[-1] if np.dot(axes[-1], inward - middle) >= 0 else -axes[-1]
        points = np.vstack([points, points + normal * MIN_THICKNESS])
    return _convex(points)


def _hull_volume(points: np.ndarray) -> float:
    """Volume of the points' hull without building a mesh (0 for a flat set): many parts are cheap."""
    if len(points) < 4:
        return 0.0
    try:
        return float(ConvexHull(points).volume)
    except QhullError:
        return 0.0


@dataclass
class _Part:
    points: np.ndarray
    closed: bool
    #: the enclosed volume when closed (else meaningless) and the surface area
    volume: float
    area: float

    def solid(self, hull_volume: float) -> float:
        """A closed part's own volume; an open surface's as a shell, never more than its hull (a
        flat one, whose hull is empty, as a shell all the same)."""
        if self.closed:
            return abs(self.volume)
        shell = self.area * SHELL_THICKNESS
        return min(hull_volume, shell) if hull_volume > 0 else shell


def _parts(mesh: trimesh.Trimesh) -> list[_Part]:
    """The mesh's connected pieces (faces sharing a vertex index), each closed when every one of its
    edges has exactly two faces. Coincident vertices are not merged: a generator's separate parts
    often touch (a leg under a top) and should stay separate pieces."""
    if not len(mesh.faces):
        return []
    labels = trimesh.graph.connected_component_labels(mesh.face_adjacency, node_count=len(mesh.faces))
    _, inverse, counts = np.unique(mesh.edges_sorted, axis=0, return_inverse=True, return_counts=True)
    open_faces = np.zeros(len(mesh.faces), dtype=bool)
    open_faces[mesh.edges_face[counts[inverse.ravel()] != 2]] = True
    v0, v1, v2 = (mesh.triangles[:, k] for k in range(3))
    signed = np.einsum("ij,ij->i", v0, np.cross(v1, v2)) / 6.0
    count = int(labels.max()) + 1
    volumes = np.bincount(labels, weights=signed, minlength=count)
    areas = np.bincount(labels, weights=mesh.area_faces, minlength=count)
    opened = np.bincount(labels, weights=open_faces, minlength=count)
    order = np.argsort(labels, kind="stable")
    bounds = np.searchsorted(labels[order], np.arange(count + 1))
    parts = []
    for k in range(count):
        faces = mesh.faces[order[bounds[k]:bounds[k + 1]]]
        points = np.asarray(mesh.vertices[np.unique(faces)], dtype=float)
        parts.append(_Part(points, opened[k] == 0, float(volumes[k]), float(areas[k])))
    return parts


def _grouped(centres: np.ndarray, sizes: list[float], limit: int) -> list[np.ndarray]:
    """Indices of parts in at most ``limit`` groups by where they are (k-means on the part
    centres, seeded deterministically with the biggest parts)."""
    if len(centres) <= limit:
        return [np.array([k]) for k in range(len(centres))]
    order = np.argsort([-s for s in sizes], kind="stable")
    with warnings.catch_warnings():  # a group left empty is merely dropped
        warnings.simplefilter("ignore")
        _, labels = kmeans2(centres, centres[order[:limit]], minit="matrix", iter=20)
    return [np.flatnonzero(labels == label) for label in np.unique(labels)]


def _run_coacd(vertices: np.ndarray, faces: np.ndarray) -> list[np.ndarray]:
    import coacd

    coacd.set_log_level("error")
    pieces = coacd.run_coacd(
        coacd.Mesh(vertices, faces), threshold=COACD_THRESHOLD, max_convex_hull=MAX_HULLS, seed=0, **COACD_SEARCH
    )
    return [np.asarray(v) for v, _ in pieces]


def _coacd(mesh: trimesh.Trimesh) -> list[trimesh.Trimesh] | None:
    """CoACD's pieces, or None when it took longer than :data:`COACD_SECONDS` (it runs in a child
    process, so it can be stopped: its search time varies by orders of magnitude with the shape)."""
    context = multiprocessing.get_context("spawn")
    with context.Pool(1) as pool:
        job = pool.apply_async(_run_coacd, (np.asarray(mesh.vertices), np.asarray(mesh.faces)))
        try:
            pieces = job.get(timeout=COACD_SECONDS)
        except multiprocessing.TimeoutError:
            log.warning("CoACD took longer than %s s; the convex hull stands in", COACD_SECONDS)
            return None
    middle = np.asarray(mesh.bounds).mean(axis=0)
    return [h for h in (_hull(v, middle) for v in pieces) if h is not None]


def collider(mesh: trimesh.Trimesh, *, use_coacd: bool | None = None) -> Collider:
    """Convex pieces of ``mesh`` (scene-frame asset frame) and its solid volume.

    ``use_coacd`` None means: when the package is installed.
    """
    if use_coacd is None:
        use_coacd = coacd_available()
    notes = []
    parts = _parts(mesh)
    closed = bool(parts) and all(p.closed for p in parts)
    if not closed:
        notes.append("the mesh is not watertight: its collision hulls are built from its points and its volume is estimated")
    lo, hi = mesh.bounds
    middle = (lo + hi) / 2.0
    whole = _hull(mesh.vertices, middle)
    if whole is None:
        raise ValueError("the mesh has fewer than three distinct points; no collision shape can be made")
    points = [p.points for p in parts]
    hull_volumes = [_hull_volume(v) for v in points]
    solid = [p.solid(h) for p, h in zip(parts, hull_volumes)]
    volume = min(sum(solid), float(whole.volume))
    # How much of the whole hull the parts fill: a single open surface says nothing about it.
    filled = volume if len(parts) == 1 else min(sum(hull_volumes), float(whole.volume))
    if (len(parts) > 1 or closed) and filled >= CONVEX_SHARE * whole.volume:
        return Collider([whole], "hull", notes, volume)
    if len(parts) > 1:
        hulls, weights = [], []
        for group in _grouped(np.array([v.mean(axis=0) for v in points]), hull_volumes, MAX_HULLS):
            hull = _hull(np.vstack([points[k] for k in group]), middle)
            if hull is not None:
                hulls.append(hull)
                weights.append(max(sum(solid[k] for k in group), 1e-9))
        return Collider(hulls, "parts", notes, volume, weights)
    if not closed:
        # CoACD would first remesh the open surface into a thin solid and then cut it for minutes;
        # with no inside to measure, the hull is the honest shape.
        notes.append("an open single surface collides as its convex hull")
        return Collider([whole], "hull", notes, volume)
    if use_coacd:
        pieces = _coacd(mesh)
        if pieces:
            return Collider(pieces, "coacd", notes, volume)
        notes.append(
            f"CoACD took longer than {COACD_SECONDS:g} s, so the convex hull stands in"
            if pieces is None
            else "CoACD returned no pieces; the convex hull stands in"
        )
    else:
        notes.append(
            "the mesh is concave but CoACD is not installed, so its convex hull stands in "
            "(install the 'sim' extra for a convex decomposition)"
        )
    return Collider([whole], "hull", notes, volume)
