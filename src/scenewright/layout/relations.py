"""The geometry of the ten spatial relations of the paper (Table 3, docs/architecture.md), each defined once.

Every relation has three parts, all here: ``holds`` (the check), ``violation`` (how far from
holding: metres, or degrees for ``face to``; 0 when it holds) and ``propose`` (candidate
source positions for the solver). They work on :class:`Boxes` — world bounding boxes with
numpy broadcasting — so the solver tests hundreds of candidates against one target in one
call, while :func:`check` and :func:`violation` give the same answer for two scene objects.

Decisions where the table leaves room:

- Relative relations (left of, right of, in front of, behind, side of) compare world boxes
  along one axis only, with the 0.1 m buffer: ``left of`` holds when the source's max x is
  at most the target's min x − 0.1 (a gap of exactly 0.1 m holds).
- ``near``/``far`` use the horizontal (xy) gap between the two objects' true footprints: the
  rectangles of their size boxes turned by their yaws (a tilted object's footprint is its
  tilted box's extent in its own yaw frame), not the world boxes, which grow by up to 41 % when
  an object turns. Overlapping footprints have gap 0. ``near`` holds at gap ≤ 2 m, ``far`` at
  gap > 8 m. Collision works on the same turned shapes (:mod:`.collision`).
- ``on``: the source's bottom is within 2 mm of the target's top (either side) and the
  source's centre stands over the target's true footprint. The paper's table asks only that the
  footprints overlap; a thing resting on a sliver of its host's corner meets that and would fall
  off it (an aquarium hanging off the end of a cabinet), so the centre of mass must be over the
  support, as a physics settle would ask. A seat's or a bed's "top" for ``on`` is where a
  thing put on it rests (:func:`rest_share`: the seat under the backrest, the mattress under the
  headboard), not the top of its box; a person on a sofa sits on the cushions.
- ``above``: the source is *positioned* at least 2 m above the target, as the table has it:
  its centre (an object's position, docs/architecture.md) at least 2 m higher than the
  target's; it does not touch the target (its bottom clears the target's top by more than the
  ``on`` gap: it hangs or floats); and the footprints overlap. Measured bottom to top instead,
  as this module once did, no lamp could hang over a table under a 2.7 m ceiling (0.75 m + 2 m
  is above the ceiling), though the paper's prompt gives exactly that use: a thing suspended
  over another without contact.
- ``face to``: the source's front (−Y at yaw 0, :func:`geometry.front_direction`) is within
  ±10° of the direction from the source's centre to the target's centre, in plan. A source
  whose centre coincides with the target's in plan faces nothing.

The four room relations (docs/rooms.md) have the room as their target, named by a reserved id
(:func:`scenewright.scene.room_target`): ``room`` (any wall; the ceiling for ``on ceiling``),
``wall_<i>`` (one wall) or ``ceiling``. Their target is a :class:`RoomTarget`, not a box:

- ``against wall``: the source's back (+Y at yaw 0) is within 2 cm of the wall's line (never
  through it), its front within ±10° of the wall's inward normal, and its footprint along
  the wall within the wall's ends.
- ``in corner``: against a wall, and a side within 2 cm of the wall that meets it at a convex
  corner (an L-shaped room's inner corner is no corner to stand in).
- ``on wall``: as ``against wall``, and mounted: its bottom at least 0.3 m above the floor and its
  top under the ceiling (a mirror, a painting, a TV, a clock, a wall shelf).
- ``on ceiling``: its top within 2 cm under the ceiling (hanging from it: fans, chandeliers).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Callable

import numpy as np

from scenewright.core.catalogue import load_catalogue
from scenewright.core.relations import ABOVE, BUFFER, FACE_DEGREES, FAR, NEAR, ON_GAP
from scenewright.core.vessels import boat_text, deck_area, deck_share
from scenewright.geometry import front_direction, rotation_matrix, world_box
from scenewright.scene import RELATION_TYPES, ROOM_RELATIONS, ROOM_TARGET, Room, SceneObject, Vec3, room_target

#: m, how far a back may stand off its wall (and a top below the ceiling) and still touch it.
WALL_GAP = 0.02
#: m, the lowest a wall-mounted object's bottom may hang.
MOUNT_MIN = 0.3
#: m, the gap the candidate generators leave between an object and its wall or ceiling.
FLUSH = 0.001
#: Centre heights (m) tried for a wall-mounted object, preferred first: eye level, then lower
#: (a TV, a mirror over a basin) and higher (a clock, a shelf over a desk).
MOUNT_HEIGHTS = (1.5, 1.25, 1.8)
#: m, the least gap the candidate heights of ``above`` leave under the source (it must not touch).
ABOVE_CLEARANCE = 0.05
#: Slack for floating-point round-off only, so that limits hold exactly at the limit.
EPS = 1e-9
#: m added to the distance of a spot on the front wall (its inward normal points more than this
#: along +Y, away from the viewer) when wall spots are ranked: the open front is the viewer's.
FRONT_NORMAL, FRONT_PENALTY = 0.7, 4.0


def rest_share(obj: SceneObject) -> float:
    """Share of ``obj``'s height where a thing put on it rests: 1 (its top) unless its catalogue
    category says lower (``rest_height``: a seat under its backrest, a mattress under its headboard;
    ``rest_inside``: a cage's floor) or it is a boat (its deck, by its words); the procedural mesh
    has its surface there."""
    category = load_catalogue().get(obj.category) if obj.category else None
    if category is not None and category.shape == "boat":
        return deck_share(boat_text(obj.name, obj.category, obj.visual_description), obj.size.tuple())
    share = category.rest_for(obj.name) if category is not None else None
    return share or 1.0


def rest_area(obj: SceneObject) -> np.ndarray | None:
    """The part of ``obj``'s footprint things put on it stand on, as shares (x0, y0, x1, y1) of
    its half extents in its own frame, when that is not all of it: a boat's open deck, clear of
    its cabin and off the point of its bow (:func:`scenewright.core.vessels.deck_area`)."""
    category = load_catalogue().get(obj.category) if obj.category else None
    if category is None or category.shape != "boat":
        return None
    text = boat_text(obj.name, obj.category, obj.visual_description)
    return np.array(deck_area(text, obj.size.tuple()), dtype=float)


@dataclass(frozen=True)
class Boxes:
    """World boxes (``lo``/``hi`` corners, shape (..., 3)), yaws (degrees, shape (...)) and
    footprints: half extents (..., 2) of the plan rectangle in the object's yaw frame. Without
    ``foot`` the footprint is the world box's own (an axis-aligned shape). ``rest`` (shape (...)
    or scalar, :func:`rest_share`) is the share of each box's height where things put on it rest;
    None is the top. ``area`` (shape (..., 4), :func:`rest_area`) is the part of the footprint
    they stand on; None is all of it."""

    lo: np.ndarray
    hi: np.ndarray
    yaw: np.ndarray
    foot: np.ndarray | None = None
    rest: np.ndarray | float | None = None
    area: np.ndarray | None = None

    @property
    def centre(self) -> np.ndarray:
        return (self.lo + self.hi) / 2.0

    @property
    def top(self) -> np.ndarray:
        """The height a thing put ``on`` each box rests at."""
        if self.rest is None:
            return self.hi[..., 2]
        return self.lo[..., 2] + np.asarray(self.rest) * (self.hi[..., 2] - self.lo[..., 2])

    @classmethod
    def at(
        cls, centre: np.ndarray, half: np.ndarray, yaw, foot: np.ndarray | None = None, rest=None, area=None
    ) -> Boxes:
        centre = np.asarray(centre, dtype=float)
        return cls(centre - half, centre + half, np.asarray(yaw, dtype=float), foot, rest, area)

    @classmethod
    def of(cls, obj: SceneObject) -> Boxes:
        lo, hi = world_box(obj)
        foot = footprint_half(obj.size, obj.rotation)
        return cls(lo, hi, np.asarray(obj.yaw, dtype=float), foot, rest_share(obj), rest_area(obj))

    def __getitem__(self, k) -> Boxes:
        """The boxes selected by an index or mask over the leading axis."""
        shape = self.lo.shape[:-1]
        return Boxes(self.lo[k], self.hi[k], np.broadcast_to(self.yaw, shape)[k],
                     None if self.foot is None else np.broadcast_to(self.foot, shape + (2,))[k],
                     None if self.rest is None else np.broadcast_to(self.rest, shape)[k],
                     None if self.area is None else np.broadcast_to(self.area, shape + (4,))[k])


def half_extents(size: Vec3, rotation: Vec3, yaws=None) -> np.ndarray:
    """Half extents of the world box of a ``size`` box at ``rotation`` (or at each yaw)."""
    half = np.array(size.tuple()) / 2.0
    if yaws is None:
        return np.abs(rotation_matrix(rotation)) @ half
    return rotated_half(half, tilt_matrix(rotation), yaws)


def footprint_half(size: Vec3, rotation: Vec3) -> np.ndarray:
    """Half extents (x, y) of an object's footprint in its own yaw frame (tilt included)."""
    return rotated_half(np.array(size.tuple()) / 2.0, tilt_matrix(rotation), 0.0)[:2]


def tilt_matrix(rotation: Vec3) -> np.ndarray:
    """The rotation without its yaw: what stays fixed while the solver turns an object."""
    return rotation_matrix(Vec3(x=rotation.x, y=rotation.y, z=0.0))


def rotated_half(half: np.ndarray, tilt: np.ndarray, yaws) -> np.ndarray:
    """World half extents of a centred box (``half``) turned by ``tilt`` then each yaw."""
    a = np.radians(np.asarray(yaws, dtype=float))[..., None]
    c, s = np.cos(a), np.sin(a)
    # Rows of Rz(yaw) @ tilt, for every yaw at once.
    row_x = np.abs(c * tilt[0] - s * tilt[1]) @ half
    row_y = np.abs(s * tilt[0] + c * tilt[1]) @ half
    row_z = np.broadcast_to(np.abs(tilt[2]) @ half, row_x.shape)
    return np.stack([row_x, row_y, row_z], axis=-1)


# --- shared measures ---------------------------------------------------------------------

def _rectangle(b: Boxes) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A footprint as centre (..., 2), half extents (..., 2) and unit axes (..., 2, 2)."""
    centre = b.centre[..., :2]
    if b.foot is None:
        half = (b.hi[..., :2] - b.lo[..., :2]) / 2.0
        axes = np.broadcast_to(np.eye(2), centre.shape[:-1] + (2, 2))
    else:
        half = np.broadcast_to(b.foot, centre.shape)
        a = np.radians(np.broadcast_to(b.yaw, centre.shape[:-1]))
        c, s = np.cos(a), np.sin(a)
        axes = np.stack([np.stack([c, s], -1), np.stack([-s, c], -1)], -2)  # rows: local x, local y
    return centre, half, axes


_SIGNS = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])  # corners in order


def _corners(centre, half, axes) -> np.ndarray:
    """The rectangle's four corners (..., 4, 2), in order around it."""
    offsets = (_SIGNS * half[..., None, :]) @ axes
    return centre[..., None, :] + offsets


def _separation(ca, ha, xa, cb, hb, xb) -> np.ndarray:
    """Largest gap along the four edge normals (> 0: apart; ≤ 0: minus the least overlap)."""
    d = cb - ca
    m = np.abs(np.einsum("...ij,...kj->...ik", xa, xb))  # |cos| between A's axis i and B's axis k
    da = np.abs(np.einsum("...j,...ij->...i", d, xa))
    db = np.abs(np.einsum("...j,...kj->...k", d, xb))
    on_a = da - ha - np.einsum("...ik,...k->...i", m, hb)
    on_b = db - hb - np.einsum("...ik,...i->...k", m, ha)
    return np.maximum(on_a.max(-1), on_b.max(-1))


def _to_rectangle(points, centre, half, axes) -> np.ndarray:
    """Distance from each of ``points`` (..., k, 2) to a rectangle (0 inside it)."""
    local = np.einsum("...kj,...ij->...ki", points - centre[..., None, :], axes)
    return np.linalg.norm(np.maximum(np.abs(local) - half[..., None, :], 0.0), axis=-1)


def _plan_gap(a: Boxes, b: Boxes) -> np.ndarray:
    """Horizontal distance between two footprints (0 when they overlap or touch).

    Two apart convex shapes are nearest at a corner of one of them, so the gap is the least
    distance from a corner of either to the other rectangle."""
    ra, rb = _rectangle(a), _rectangle(b)
    if a.foot is None and b.foot is None:  # two axis-aligned rectangles: the direct formula
        dx = np.maximum(0.0, np.abs(rb[0][..., 0] - ra[0][..., 0]) - ra[1][..., 0] - rb[1][..., 0])
        dy = np.maximum(0.0, np.abs(rb[0][..., 1] - ra[0][..., 1]) - ra[1][..., 1] - rb[1][..., 1])
        return np.hypot(dx, dy)
    apart = _separation(*ra, *rb) > 0.0
    gap = np.minimum(_to_rectangle(_corners(*ra), *rb).min(-1), _to_rectangle(_corners(*rb), *ra).min(-1))
    return np.where(apart, gap, 0.0)


def _footprint_overlap(a: Boxes, b: Boxes) -> np.ndarray:
    """Whether the footprints overlap with positive area."""
    return _separation(*_rectangle(a), *_rectangle(b)) < -EPS


def _area_span(area: np.ndarray, half: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The middle and half extents, in the footprint's own frame, of the ``area`` (shares of the
    half extents ``half``) that things put on it stand on."""
    lo, hi = area[..., :2] * half, area[..., 2:] * half
    return (lo + hi) / 2.0, (hi - lo) / 2.0


def _rest_rectangle(b: Boxes) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The part of a footprint things put on it stand on (its ``area``), as :func:`_rectangle`."""
    centre, half, axes = _rectangle(b)
    if b.area is None:
        return centre, half, axes
    middle, span = _area_span(np.broadcast_to(b.area, centre.shape[:-1] + (4,)), half)
    return centre + np.einsum("...i,...ij->...j", middle, axes), span, axes


def _centre_off(a: Boxes, b: Boxes) -> np.ndarray:
    """How far ``a``'s centre lies outside the part of ``b``'s footprint things stand on (0 over it)."""
    return _to_rectangle(a.centre[..., None, :2], *_rest_rectangle(b))[..., 0]


def _footprint_miss(a: Boxes, b: Boxes) -> np.ndarray:
    """How far the footprints are from overlapping (the plan gap; 0 when they overlap)."""
    return np.where(_footprint_overlap(a, b), 0.0, np.maximum(_plan_gap(a, b), EPS))


def _angle_off(src: Boxes, tgt: Boxes) -> np.ndarray:
    """Degrees between the source's front and the direction to the target's centre."""
    d = tgt.centre[..., :2] - src.centre[..., :2]
    front = np.moveaxis(front_direction(src.yaw), 0, -1)
    norm = np.linalg.norm(d, axis=-1)
    cos = np.sum(front * d, axis=-1) / np.where(norm > EPS, norm, 1.0)
    return np.where(norm > EPS, np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))), 180.0)


# --- checks and violations -----------------------------------------------------------------

def _left_miss(s, t):
    return np.maximum(0.0, s.hi[..., 0] - (t.lo[..., 0] - BUFFER))


def _right_miss(s, t):
    return np.maximum(0.0, (t.hi[..., 0] + BUFFER) - s.lo[..., 0])


def _front_miss(s, t):
    return np.maximum(0.0, s.hi[..., 1] - (t.lo[..., 1] - BUFFER))


def _behind_miss(s, t):
    return np.maximum(0.0, (t.hi[..., 1] + BUFFER) - s.lo[..., 1])


def _on_miss(s, t):
    dz = np.maximum(0.0, np.abs(s.lo[..., 2] - t.top) - ON_GAP)
    return dz + _centre_off(s, t)


def _rise(s, t):
    """How far the source's centre stands above the target's."""
    return (s.lo[..., 2] + s.hi[..., 2] - t.lo[..., 2] - t.hi[..., 2]) / 2.0


def _above_miss(s, t):
    clear = np.maximum(0.0, ON_GAP - (s.lo[..., 2] - t.hi[..., 2]))
    return np.maximum(0.0, ABOVE - _rise(s, t)) + clear + _footprint_miss(s, t)


_VIOLATION: dict[str, Callable[[Boxes, Boxes], np.ndarray]] = {
    "left of": _left_miss,
    "right of": _right_miss,
    "in front of": _front_miss,
    "behind": _behind_miss,
    "side of": lambda s, t: np.minimum(_left_miss(s, t), _right_miss(s, t)),
    "near": lambda s, t: np.maximum(0.0, _plan_gap(s, t) - NEAR),
    "far": lambda s, t: np.maximum(0.0, FAR - _plan_gap(s, t)),
    "on": _on_miss,
    "above": _above_miss,
    "face to": lambda s, t: np.maximum(0.0, _angle_off(s, t) - FACE_DEGREES),
}


def holds(relation: str, src: Boxes, tgt: Boxes | RoomTarget) -> np.ndarray:
    """Whether ``relation`` holds for every (broadcast) source/target box pair."""
    if relation in ROOM_RELATIONS:
        return _room_miss(relation, src, tgt) <= EPS
    if relation == "far":  # strict: the gap must exceed 8 m
        return _plan_gap(src, tgt) > FAR
    if relation == "on":
        return (np.abs(src.lo[..., 2] - tgt.top) <= ON_GAP + EPS) & (_centre_off(src, tgt) <= EPS)
    if relation == "above":
        clear = src.lo[..., 2] - tgt.hi[..., 2] > ON_GAP + EPS
        return (_rise(src, tgt) >= ABOVE - EPS) & clear & _footprint_overlap(src, tgt)
    return _VIOLATION[relation](src, tgt) <= EPS


def violations(relation: str, src: Boxes, tgt: Boxes | RoomTarget) -> np.ndarray:
    if relation in ROOM_RELATIONS:
        miss = _room_miss(relation, src, tgt)
        return np.where(miss <= EPS, 0.0, np.maximum(miss, EPS))
    if relation == "far":
        return np.where(holds("far", src, tgt), 0.0, np.maximum(FAR - _plan_gap(src, tgt), EPS))
    return np.where(holds(relation, src, tgt), 0.0, np.maximum(_VIOLATION[relation](src, tgt), EPS))


def _known(relation: str) -> str:
    if relation not in RELATION_TYPES:
        raise ValueError(f"unknown relation {relation!r}; valid relations: {', '.join(RELATION_TYPES)}")
    return relation


def check(relation: str, source: SceneObject, target: SceneObject) -> bool:
    """Whether ``source`` stands in ``relation`` to ``target`` (the one definition, Table 3)."""
    return bool(holds(_known(relation), Boxes.of(source), Boxes.of(target)))


def violation(relation: str, source: SceneObject, target: SceneObject) -> float:
    """How far the pair is from the relation: metres (degrees for ``face to``); 0 if it holds."""
    return float(violations(_known(relation), Boxes.of(source), Boxes.of(target)))


def plan_gap(source: SceneObject, target: SceneObject) -> float:
    """Metres between the two footprints in plan (0 when they touch or overlap): the measure
    ``near`` and ``far`` judge, also how far apart things stated side by side stand."""
    return float(_plan_gap(Boxes.of(source), Boxes.of(target)))


# --- candidate generation ------------------------------------------------------------------

@lru_cache(maxsize=32)
def sunflower(n: int, spacing: float) -> np.ndarray:
    """``n`` offsets spreading evenly outward from (0, 0), nearest first (Vogel's spiral)."""
    k = np.arange(n, dtype=float)
    r = spacing * np.sqrt(k)
    theta = k * np.pi * (3.0 - np.sqrt(5.0))
    out = np.stack([r * np.cos(theta), r * np.sin(theta)], axis=-1)
    out.flags.writeable = False
    return out


def _region(relation: str, half: np.ndarray, t: Boxes | None) -> list[tuple[np.ndarray, np.ndarray]]:
    """Axis-aligned rectangles (lo, hi) of source centres (x, y) where the relation can hold.

    Unbounded sides are ±inf. ``near`` and ``far`` get the rectangle that contains (near)
    or is contained by (far) their rounded region; the exact checks filter afterwards.
    """
    inf = np.inf
    if isinstance(t, RoomTarget):  # "on ceiling": anywhere under it
        return [(t.lo + half[:2], t.hi - half[:2])]
    if relation == "face to" or t is None:  # any position can face the target
        return [(np.array([-inf, -inf]), np.array([inf, inf]))]
    tlo, thi = t.lo[:2], t.hi[:2]
    hx, hy = half[0], half[1]
    if relation == "left of":
        return [(np.array([-inf, -inf]), np.array([tlo[0] - BUFFER - hx, inf]))]
    if relation == "right of":
        return [(np.array([thi[0] + BUFFER + hx, -inf]), np.array([inf, inf]))]
    if relation == "in front of":
        return [(np.array([-inf, -inf]), np.array([inf, tlo[1] - BUFFER - hy]))]
    if relation == "behind":
        return [(np.array([-inf, thi[1] + BUFFER + hy]), np.array([inf, inf]))]
    if relation == "side of":
        return _region("left of", half, t) + _region("right of", half, t)
    if relation in ("on", "above"):
        # Fully supported when it fits; else centred over the target's top.
        inner_lo, inner_hi = tlo + half[:2], thi - half[:2]
        mid = (tlo + thi) / 2.0
        lo = np.where(inner_lo <= inner_hi, inner_lo, mid)
        hi = np.where(inner_lo <= inner_hi, inner_hi, mid)
        return [(lo, hi)]
    if relation == "near":
        return [(tlo - half[:2] - NEAR, thi + half[:2] + NEAR)]
    if relation == "far":
        m = FAR + 1e-3
        return [
            (np.array([-inf, -inf]), np.array([tlo[0] - hx - m, inf])),
            (np.array([thi[0] + hx + m, -inf]), np.array([inf, inf])),
            (np.array([-inf, -inf]), np.array([inf, tlo[1] - hy - m])),
            (np.array([-inf, thi[1] + hy + m]), np.array([inf, inf])),
        ]
    raise ValueError(f"unknown relation {relation!r}")


def propose(
    relation: str,
    half: np.ndarray,
    target: Boxes | None,
    anchor: np.ndarray,
    rng: np.random.Generator,
    n: int = 160,
    spacing: float = 0.12,
) -> np.ndarray:
    """Candidate source centres (x, y) for ``relation``, nearest to ``anchor`` first.

    ``half`` is the source's world half extents at its intended yaw; without a ``target``
    every position is feasible (an unconstrained object). Candidates are a spiral
    around the anchor's projection onto each feasible rectangle, plus uniform samples of the
    rectangle where it is bounded; every point lies inside the rectangle.
    """
    anchor = np.asarray(anchor, dtype=float)[:2]
    origin, axes = np.zeros(2), np.eye(2)
    if relation in ("on", "above") and target is not None and target.foot is not None:
        # Over a turned target, work in its own frame, where its footprint is a rectangle.
        origin, _, axes = _rectangle(target)
        turned = np.abs(axes @ np.array([[half[0], 0.0], [0.0, half[1]]])).sum(-1)  # source box in that frame
        if relation == "on" and target.area is not None:  # (only the part things stand on)
            middle, span = _area_span(target.area, target.foot)
            local = Boxes.at(np.append(middle, 0.0), np.append(span, 0.0), 0.0)
        else:
            local = Boxes.at(np.zeros(3), np.append(target.foot, 0.0), 0.0)
        regions = _region(relation, turned, local)
    else:
        regions = _region(relation, half, target)
    start = (anchor - origin) @ axes.T
    out = []
    for lo, hi in regions:
        base = np.clip(start, lo, hi)
        jitter = rng.uniform(0.0, 2 * np.pi)
        c, s = np.cos(jitter), np.sin(jitter)
        spiral = sunflower(n, spacing) @ np.array([[c, -s], [s, c]])
        pts = np.clip(base + spiral, lo, hi)
        if np.all(np.isfinite(hi - lo)):
            pts = np.concatenate([pts, rng.uniform(lo, hi, size=(n // 2, 2))])
        out.append(pts)
    pts = np.concatenate(out) @ axes + origin
    order = np.argsort(np.linalg.norm(pts - anchor, axis=1), kind="stable")
    return pts[order]


def lowest_above(half_z: float, target_lo: float, target_hi: float) -> float:
    """The lowest centre height at which a source ``half_z`` half high is ``above`` a target
    standing from ``target_lo`` to ``target_hi``: its centre :data:`ABOVE` over the target's,
    and its bottom :data:`ABOVE_CLEARANCE` clear of the target's top. A ceiling lower than this
    plus ``half_z`` leaves no room for the relation."""
    return max((target_lo + target_hi) / 2.0 + ABOVE, target_hi + half_z + ABOVE_CLEARANCE)


def source_heights(relation: str, half_z: float, target: Boxes, initial_z: float) -> np.ndarray | None:
    """Centre heights a vertical relation allows its source, preferred first (None: not vertical).

    ``on`` has one; ``above`` starts at the initial height or the lowest allowed one, and
    offers a few higher levels so two hanging objects can share a footprint, then the lowest
    one (an initial height a ceiling is below leaves that).
    """
    if isinstance(target, RoomTarget):
        return room_heights(relation, half_z, target)
    top = float(target.hi[2])
    if relation == "on":
        return np.array([float(target.top) + half_z])
    if relation == "above":
        lowest = lowest_above(half_z, float(target.lo[2]), top)
        levels = max(initial_z, lowest) + np.array([0.0, 0.3, 0.7, 1.2])
        # the lowest allowed level last, for when the initial one is above the ceiling
        return levels if initial_z <= lowest else np.append(levels, lowest)
    return None


# --- the room relations ----------------------------------------------------------------------

@dataclass(frozen=True)
class RoomTarget:
    """The walls a room relation may use and the ceiling, as arrays over those walls.

    ``start``/``direction``/``normal`` (k, 2): each wall's first corner, unit direction and
    inward unit normal; ``length`` (k,); for ``in corner``, the walls meeting it at its start
    and end corners (``before``/``after``: start (k, 2) and inward normal (k, 2)) and whether
    each of those corners is convex. ``lo``/``hi`` bound the floor; ``height`` is the ceiling.
    """

    index: np.ndarray
    start: np.ndarray
    direction: np.ndarray
    normal: np.ndarray
    length: np.ndarray
    before: tuple[np.ndarray, np.ndarray]
    after: tuple[np.ndarray, np.ndarray]
    convex: tuple[np.ndarray, np.ndarray]
    lo: np.ndarray
    hi: np.ndarray
    height: float

    @classmethod
    def of(cls, room: Room, target: str = ROOM_TARGET) -> RoomTarget:
        """The walls ``target`` names in ``room`` (every wall for ``room`` and ``ceiling``)."""
        named = room_target(target)
        if named is None:
            raise ValueError(f"{target!r} names no part of the room; use 'room', 'ceiling' or 'wall_<i>'")
        n = len(room.floor)
        if isinstance(named, int) and named >= n:
            raise ValueError(f"{target!r}: the room has walls wall_0 .. wall_{n - 1}")
        pts = np.asarray(room.floor, dtype=float)
        start, end = pts, np.roll(pts, -1, axis=0)
        vec = end - start
        length = np.linalg.norm(vec, axis=1)
        direction = vec / length[:, None]
        normal = np.stack([-direction[:, 1], direction[:, 0]], axis=1)  # left of a CCW edge: inside
        prev, nxt = np.roll(np.arange(n), 1), np.roll(np.arange(n), -1)
        turn = direction[prev, 0] * direction[:, 1] - direction[prev, 1] * direction[:, 0]
        convex_start = turn > EPS  # the corner at each wall's start
        keep = np.arange(n) if not isinstance(named, int) else np.array([named])
        return cls(
            index=keep, start=start[keep], direction=direction[keep], normal=normal[keep], length=length[keep],
            before=(start[prev][keep], normal[prev][keep]), after=(start[nxt][keep], normal[nxt][keep]),
            convex=(convex_start[keep], convex_start[nxt][keep]),
            lo=pts.min(axis=0), hi=pts.max(axis=0), height=float(room.height),
        )


def wall_yaw(normal: np.ndarray) -> np.ndarray:
    """The yaw (degrees) at which an object's front points along ``normal`` (..., 2)."""
    return np.degrees(np.arctan2(normal[..., 0], -normal[..., 1]))


def _reach(b: Boxes, direction: np.ndarray) -> np.ndarray:
    """How far each footprint reaches from its centre along ``direction`` (broadcast (..., 2))."""
    _, half, axes = _rectangle(b)
    return np.sum(np.abs(np.einsum("...ij,...j->...i", axes, direction)) * half, axis=-1)


def _off_line(b: Boxes, start: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """How far a line (through ``start``, inward ``normal``) is from touching each footprint:
    0 within :data:`WALL_GAP` of it; the overshoot when the footprint crosses it."""
    gap = np.sum((b.centre[..., :2] - start) * normal, axis=-1) - _reach(b, normal)
    return np.maximum(0.0, gap - WALL_GAP) + np.maximum(0.0, -gap)


def _wall_miss(src: Boxes, room: RoomTarget, corner: bool) -> np.ndarray:
    """Per source box, the least miss over the target's walls of standing back to one of them
    (in a corner of it, with ``corner``). Shape: the source boxes' leading shape."""
    b = Boxes(src.lo[..., None, :], src.hi[..., None, :], np.asarray(src.yaw)[..., None],
              None if src.foot is None else np.asarray(src.foot)[..., None, :])
    miss = _off_line(b, room.start, room.normal)
    front = np.moveaxis(front_direction(np.asarray(b.yaw, dtype=float)), 0, -1)
    cos = np.clip(np.sum(front * room.normal, axis=-1), -1.0, 1.0)
    miss = miss + 0.01 * np.maximum(0.0, np.degrees(np.arccos(cos)) - FACE_DEGREES)
    along = np.sum((b.centre[..., :2] - room.start) * room.direction, axis=-1)
    reach = _reach(b, room.direction)
    miss = miss + np.maximum(0.0, reach - along) + np.maximum(0.0, along + reach - room.length)
    if corner:
        at_start = np.where(room.convex[0], _off_line(b, *room.before), np.inf)
        at_end = np.where(room.convex[1], _off_line(b, *room.after), np.inf)
        miss = miss + np.minimum(at_start, at_end)
    return miss.min(axis=-1)


def _room_miss(relation: str, src: Boxes, room: RoomTarget) -> np.ndarray:
    if not isinstance(room, RoomTarget):
        raise TypeError(f"'{relation}' relates an object to the room, not to another object")
    if relation == "on ceiling":
        top = src.hi[..., 2]
        return np.maximum(0.0, room.height - top - WALL_GAP) + np.maximum(0.0, top - room.height)
    miss = _wall_miss(src, room, corner=relation == "in corner")
    if relation == "on wall":
        miss = miss + np.maximum(0.0, MOUNT_MIN - src.lo[..., 2]) + np.maximum(0.0, src.hi[..., 2] - room.height)
    return miss


def check_room(relation: str, source: SceneObject, room: Room, target: str = ROOM_TARGET) -> bool:
    """Whether ``source`` stands in a room relation to the part of ``room`` that ``target`` names."""
    return bool(holds(_known(relation), Boxes.of(source), RoomTarget.of(room, target)))


def room_violation(relation: str, source: SceneObject, room: Room, target: str = ROOM_TARGET) -> float:
    """How far (m) ``source`` is from a room relation; 0 when it holds."""
    return float(violations(_known(relation), Boxes.of(source), RoomTarget.of(room, target)))


def propose_wall(
    relation: str, foot: np.ndarray, room: RoomTarget, anchor: np.ndarray, spacing: float = 0.1
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Candidate centres (x, y), yaws and costs of a source standing back to a wall (``against
    wall``, ``on wall``) or in a corner, cheapest first: nearest to ``anchor``, the front wall last. ``foot`` is the source's footprint
    half extents in its own yaw frame: its back sits :data:`FLUSH` off the wall, facing in."""
    anchor = np.asarray(anchor, dtype=float)[:2]
    fx, fy = float(foot[0]), float(foot[1])
    xy, yaws, spans = [], [], {}
    for k in range(len(room.length)):
        length = float(room.length[k])
        if length < 2 * fx:
            continue  # the wall is too short for it
        if relation == "in corner":
            ends = [(fx + FLUSH, room.convex[0][k]), (length - fx - FLUSH, room.convex[1][k])]
            t = np.array([x for x, convex in ends if convex])
        else:
            to_anchor = float(np.dot(anchor - room.start[k], room.direction[k]))
            t = np.append(np.arange(fx, length - fx + EPS, spacing), np.clip(to_anchor, fx, length - fx))
        if not len(t):
            continue
        spans[k] = t
        xy.append(room.start[k] + t[:, None] * room.direction[k] + (fy + FLUSH) * room.normal[k])
        yaws.append(np.full(len(t), float(wall_yaw(room.normal[k]))))
    if not xy:
        return np.zeros((0, 2)), np.zeros(0), np.zeros(0)
    xy, yaws = np.concatenate(xy), np.concatenate(yaws)
    # the front wall is the viewer's: a thing stands against it only when no other wall will do
    front = np.concatenate([np.full(len(t), room.normal[k][1] > FRONT_NORMAL) for k, t in spans.items()])
    cost = np.linalg.norm(xy - anchor, axis=1) + FRONT_PENALTY * front
    order = np.argsort(cost, kind="stable")
    return xy[order], yaws[order], cost[order]


def room_heights(relation: str, half_z: float, room: RoomTarget) -> np.ndarray | None:
    """Centre heights a room relation allows its source, preferred first (None: the ground rule)."""
    if relation == "on ceiling":
        return np.array([room.height - half_z - FLUSH])
    if relation == "on wall":
        low, high = MOUNT_MIN + half_z, room.height - FLUSH - half_z
        return np.array(list(dict.fromkeys(round(float(np.clip(h, low, max(low, high))), 4) for h in MOUNT_HEIGHTS)))
    return None


def mounted_above_heights(half_z: float, room: RoomTarget, target: Boxes) -> np.ndarray | None:
    """Centre heights, lowest first, for a thing on a wall ``above`` a target (a clock over a
    cabinet against that wall): from the lowest that holds up to its top under the ceiling; None
    when the ceiling is too low for it."""
    lowest = lowest_above(half_z, float(target.lo[2]), float(target.hi[2]))
    highest = room.height - FLUSH - half_z
    if lowest > highest + EPS:
        return None
    return np.unique(np.minimum(lowest + np.array([0.0, 0.15, 0.3, 0.6]), highest))


def describe(relation: str, miss: float) -> str:
    unit = "°" if relation == "face to" else " m"
    return f"misses by {miss:.2f}{unit}"

