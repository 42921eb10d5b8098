"""What a room asks of a layout besides its relations: containment, clear openings, walkability.

The solver, editing and evaluation all measure a layout against its room here (docs/rooms.md):

- **Containment**: an object's footprint lies inside the floor polygon. Measured as how far it
  pokes through the nearest wall (separating axes against each wall as a segment), or, when its
  centre is outside, the distance back in plus its size. Wall- and ceiling-mounted objects too.
- **Clear openings**: a strip in front of each door (as deep as the door swings, at least
  :data:`DOOR_CLEAR`) holds no object lower than the door's top; a strip in front of each window
  (:data:`WINDOW_CLEAR` deep) holds nothing that reaches into the window's height band, so a
  desk may stand under a window but a wardrobe may not stand in front of it.
- **Walkability**: on a 2D occupancy grid (:data:`CELL`), an agent of radius :data:`AGENT_RADIUS`
  walks from a door to every floor object. An object counts as reached when a position the
  agent can stand at lies within :data:`REACH` of its footprint, on any side: a chair pulled up
  to a desk is reached from behind it. Things that hang (bottom above :data:`HEAD_ROOM`) block
  no one; things on other things are reached with their host.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from scenewright.layout.relations import EPS, Boxes, _rectangle, _separation, _to_rectangle
from scenewright.scene import Opening, Room, SceneObject

#: m, the least depth kept clear in front of a door (a door swings as deep as it is wide).
DOOR_CLEAR = 0.9
#: m, the depth kept clear in front of a window.
WINDOW_CLEAR = 0.4
#: m, how far above a window's sill a thing in front of it may reach (a headboard, a desk lamp).
SILL_SLACK = 0.2
#: m, overlaps smaller than this are round-off, not a blocked strip or a wall poked through.
SLACK = 0.005
#: m, the radius of the agent that must walk to every object (SceneEval's navigability).
AGENT_RADIUS = 0.4
#: m, how far beyond its body the agent reaches to count an object as reached.
REACH = 0.25
#: m, the grid cell of the walkability check.
CELL = 0.1
#: m, an object whose bottom is higher than this stands in no one's way.
HEAD_ROOM = 1.9
#: Footprints whose grid cells a room shape keeps (:meth:`RoomShape._cells_near`): a few MB.
NEAR_CACHE = 20000
#: The largest share of the floor the floor objects may cover and leave room to walk: rooms
#: sized around their objects use it, and a room too small says how much floor is missing by it.
COVERAGE = 0.35
#: Up to this many floor objects, a floor :data:`COVERAGE` covered leaves each within reach:
#: the walls and a few aisles serve them all. Beyond it the share that must stand away from the
#: walls, each with an aisle of its own, grows like √n (see :func:`floor_needed`). Measured on
#: ``benchmarks/speed.py``'s showroom (docs/rooms.md): 60 floor objects were all reached at
#: about COVERAGE, 120 only after the room had grown twice, to about a third of it.
WALL_SERVED = 40
#: m, an object whose bottom is lower than this stands on the floor (a floor object); one no
#: taller than this (a rug) is walked over.
FLOOR = 0.05


@dataclass(frozen=True)
class _Rects:
    """Oriented rectangles in plan: centres (k, 2), half extents (k, 2), axes (k, 2, 2)."""

    centre: np.ndarray
    half: np.ndarray
    axes: np.ndarray


def _strip(room: Room, opening: Opening, corridor: bool = False) -> tuple[_Rects, float, float]:
    """The plan rectangle kept clear in front of ``opening``, and the height band it protects.
    A door's ``corridor`` runs on, as wide as the agent, to the floor's middle."""
    (x0, y0), (x1, y1) = room.walls[opening.wall]
    start, end = np.array([x0, y0]), np.array([x1, y1])
    d = (end - start) / np.linalg.norm(end - start)
    n = np.array([-d[1], d[0]])
    depth = max(DOOR_CLEAR, opening.width) if opening.kind == "door" else WINDOW_CLEAR
    width = opening.width
    mouth = start + opening.offset * d
    if corridor and opening.kind == "door":
        middle = np.asarray(room.floor, dtype=float).mean(axis=0)
        depth = max(depth, float(np.dot(middle - mouth, n)))
        width = max(width, 2 * AGENT_RADIUS + CELL)
    centre = mouth + n * depth / 2.0
    rect = _Rects(centre[None], np.array([[width / 2.0, depth / 2.0]]), np.stack([d, n])[None])
    bottom = opening.sill + (SILL_SLACK if opening.kind == "window" else 0.0)
    return rect, bottom, opening.sill + opening.height


def _extent(centre: np.ndarray, half: np.ndarray, axes: np.ndarray) -> np.ndarray:
    """Half extents (..., 2) along x and y of rectangles (centre, half, axes as :class:`_Rects`)."""
    return (np.abs(axes) * half[..., :, None]).sum(axis=-2)


def _plan_extent(boxes: Boxes) -> tuple[np.ndarray, np.ndarray]:
    """The axis-aligned plan extent (lo, hi) of each box's footprint."""
    centre, half, axes = _rectangle(boxes)
    e = _extent(centre, half, axes)
    return centre - e, centre + e


class RoomShape:
    """A room's floor, walls and opening strips as arrays, for measuring many boxes at once.

    With ``corridors``, each door's strip runs on to the middle of the floor: the solver's
    second try when its first layout walled a door off (a bed and a desk leaving a pocket)."""

    def __init__(self, room: Room, corridors: bool = False):
        self.room = room
        pts = np.asarray(room.floor, dtype=float)
        self.floor = pts
        end = np.roll(pts, -1, axis=0)
        vec = end - pts
        length = np.linalg.norm(vec, axis=1)
        d = vec / length[:, None]
        self.walls = _Rects((pts + end) / 2.0, np.stack([length / 2.0, np.zeros(len(pts))], axis=1),
                            np.stack([d, np.stack([-d[:, 1], d[:, 0]], axis=1)], axis=1))
        self.lo, self.hi = pts.min(axis=0), pts.max(axis=0)
        #: A floor that is its own bounding rectangle: a footprint inside that is inside the floor.
        self.rectangular = (len(pts) == 4 and bool(np.all((pts == self.lo) | (pts == self.hi)))
                            and math.isclose(self.area, float(np.prod(self.hi - self.lo))))
        self.strips = [(o, *_strip(room, o, corridors)) for o in room.openings]
        #: Each strip's plan extent (lo, hi): a footprint clear of it is clear of the strip.
        self._strip_extents = [(r.centre[0] - e, r.centre[0] + e) for _, r, _, _ in self.strips
                               for e in [_extent(r.centre, r.half, r.axes)[0]]]
        self._cells: tuple[np.ndarray, np.ndarray] | None = None
        self._door_cells: list[np.ndarray] | None = None
        self._near: dict[tuple[bytes, float, bool], tuple[tuple[slice, slice], np.ndarray]] = {}

    @property
    def area(self) -> float:
        x, y = self.floor[:, 0], self.floor[:, 1]
        return float(0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y)))

    def contains(self, points: np.ndarray) -> np.ndarray:
        """Whether each point (..., 2) lies inside the floor polygon (even-odd rule)."""
        p = np.asarray(points, dtype=float)[..., None, :]
        a, b = self.floor, np.roll(self.floor, -1, axis=0)
        crosses = (a[:, 1] > p[..., 1]) != (b[:, 1] > p[..., 1])
        with np.errstate(divide="ignore", invalid="ignore"):
            x = a[:, 0] + (p[..., 1] - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
        return (np.sum(crosses & (p[..., 0] < x), axis=-1) % 2) == 1

    def _to_boundary(self, points: np.ndarray) -> np.ndarray:
        """Distance from each point (..., 2) to the nearest wall."""
        p = np.asarray(points, dtype=float)[..., None, :]
        a, b = self.floor, np.roll(self.floor, -1, axis=0)
        ab = b - a
        t = np.clip(np.sum((p - a) * ab, axis=-1) / np.sum(ab * ab, axis=-1), 0.0, 1.0)
        return np.linalg.norm(p - (a + t[..., None] * ab), axis=-1).min(axis=-1)

    def _penetration(self, boxes: Boxes, rects: _Rects) -> np.ndarray:
        """How deep each box's footprint overlaps each rectangle (boxes × rects; 0 when apart)."""
        c, h, x = _rectangle(boxes)
        sep = _separation(c[..., None, :], h[..., None, :], x[..., None, :, :], rects.centre, rects.half, rects.axes)
        return np.maximum(0.0, -sep)

    def outside_by(self, boxes: Boxes) -> np.ndarray:
        """How far (m) each box's footprint reaches outside the floor polygon (0 inside it). On a
        rectangular floor a footprint whose plan extent lies within it is 0 without measuring."""
        out = np.zeros(boxes.lo.shape[:-1])
        todo = np.ones(out.shape, dtype=bool)
        if self.rectangular:
            lo, hi = _plan_extent(boxes)
            todo = ~(np.all(lo > self.lo, axis=-1) & np.all(hi < self.hi, axis=-1))
        if todo.any():
            out[todo] = self._outside_by(boxes[todo])
        return out

    def _outside_by(self, boxes: Boxes) -> np.ndarray:
        centre = boxes.centre[..., :2]
        poke = self._penetration(boxes, self.walls).max(axis=-1)
        _, half, _ = _rectangle(boxes)
        out = self._to_boundary(centre) + np.linalg.norm(half, axis=-1)
        return np.where(self.contains(centre), np.where(poke > SLACK, poke, 0.0), out)

    def blocking(self, boxes: Boxes) -> np.ndarray:
        """How deep (m) each box stands in the clear strip of a door or window (0 when in none)."""
        worst = np.zeros(boxes.lo.shape[:-1])
        lo, hi = _plan_extent(boxes)
        for (_, rect, bottom, top), (s_lo, s_hi) in zip(self.strips, self._strip_extents):
            band = (boxes.lo[..., 2] < top - EPS) & (boxes.hi[..., 2] > bottom + EPS)
            # Only a footprint whose plan extent meets the strip's can stand in it.
            band &= np.all(lo < s_hi, axis=-1) & np.all(hi > s_lo, axis=-1)
            if band.any():
                worst[band] = np.maximum(worst[band], self._penetration(boxes[band], rect)[..., 0])
        return np.where(worst > SLACK, worst, 0.0)

    def above_ceiling(self, boxes: Boxes) -> np.ndarray:
        """How far (m) each box reaches past the ceiling (0 under it)."""
        over = boxes.hi[..., 2] - self.room.height
        return np.where(over > SLACK, over, 0.0)

    def misfit(self, boxes: Boxes) -> np.ndarray:
        """Containment (under the ceiling too) and clear openings together (m): 0 where a box may stand."""
        return np.maximum(np.maximum(self.outside_by(boxes), self.above_ceiling(boxes)), self.blocking(boxes))

    def fits(self, boxes: Boxes) -> np.ndarray:
        """Whether each box may stand where it is (its :meth:`misfit` is 0): the cheap measures
        first, the walls only for the boxes those leave, as the solver asks it of thousands."""
        ok = (self.above_ceiling(boxes) <= EPS) & (self.blocking(boxes) <= EPS)
        if ok.any():
            ok[ok] = self.outside_by(boxes[ok]) <= EPS
        return ok

    def blocked_openings(self, objects: Sequence[SceneObject]) -> list[tuple[int, Opening, list[str]]]:
        """Each opening whose clear strip an object stands in: (index, opening, those ids)."""
        if not objects:
            return []
        boxes = boxes_of(objects)
        out = []
        for k, (opening, rect, bottom, top) in enumerate(self.strips):
            band = (boxes.lo[:, 2] < top - EPS) & (boxes.hi[:, 2] > bottom + EPS)
            inside = band & (self._penetration(boxes, rect)[:, 0] > SLACK)
            if inside.any():
                out.append((k, opening, [o.id for o, hit in zip(objects, inside) if hit]))
        return out

    def unreachable(self, objects: Sequence[SceneObject], floor_ids: set[str] | None = None) -> tuple[list[str], list[int]]:
        """Floor objects an agent cannot walk to from any door, and the doors it cannot step
        through (their indices in ``room.openings``). ``floor_ids`` limits which objects must be
        reached (default: those standing on the floor)."""
        if not objects:
            return [], self.stuck_doors(None)
        boxes = boxes_of(objects)
        if floor_ids is None:
            reach = boxes.lo[:, 2] < FLOOR
        else:
            reach = np.array([o.id in floor_ids for o in objects])
        missed, stuck = self.walk(boxes, reach)
        return [objects[i].id for i in missed], stuck

    def stuck_doors(self, boxes: Boxes | None) -> list[int]:
        return self.walk(boxes, None)[1]

    def walk(self, boxes: Boxes | None, reach: np.ndarray | None) -> tuple[list[int], list[int]]:
        """The walkability check on world boxes: indices of the boxes marked in ``reach`` that no
        agent position reachable from a door lies near, and the doors it cannot step through."""
        doors = [(k, o) for k, o in enumerate(self.room.openings) if o.kind == "door"]
        if not doors:
            return [], []  # a room with no door: nothing to walk in from (problems() says so)
        grid, free = self._grid()
        if boxes is not None and len(boxes.lo):
            standing = (boxes.lo[:, 2] < HEAD_ROOM) & (boxes.hi[:, 2] > FLOOR)
            blocked = np.zeros(free.shape, dtype=bool)
            for window, cells in self._cells_near(boxes[standing], AGENT_RADIUS, strict=True):
                blocked[window] |= cells
            free = free & ~blocked
        from scipy import ndimage  # a third of a second to import; only a room's walking check needs it

        labels, _ = ndimage.label(free)
        reached: set[int] = set()
        stuck: list[int] = []
        for k, mouth in enumerate(self._mouths(doors)):
            found = set(np.unique(labels[free & mouth])) - {0}
            if not found:
                stuck.append(doors[k][0])
            reached |= found
        if boxes is None or reach is None or not reach.any():
            return [], stuck
        walked = np.isin(labels, sorted(reached)) if reached else np.zeros(free.shape, dtype=bool)
        wanted = np.flatnonzero(reach)
        return [int(i) for i, (window, cells) in zip(wanted, self._cells_near(boxes[wanted], AGENT_RADIUS + REACH + CELL))
                if not np.any(walked[window] & cells)], stuck

    def _mouths(self, doors: list[tuple[int, Opening]]) -> list[np.ndarray]:
        """For each door, the grid cells of its strip: the agent steps in through the door, so
        its first free cells lie there (cached with the grid: the room does not change)."""
        if self._door_cells is None:
            grid, _ = self._grid()
            self._door_cells = []
            for _, opening in doors:
                rect, _, _ = _strip(self.room, opening)
                local = np.einsum("...j,ij->...i", grid - rect.centre[0], rect.axes[0])
                self._door_cells.append(np.all(np.abs(local) <= rect.half[0] + EPS, axis=-1))
        return self._door_cells

    def _cells_near(self, boxes: Boxes, margin: float, strict: bool = False):
        """For each box's footprint, a window of grid cells and which of them lie within
        ``margin`` of it (nearer than it, when ``strict``).

        A window covers the footprint's circumscribed circle grown by ``margin``: the cost follows
        the objects' size, not the room's (a whole-grid distance per object made a 60-object room
        take half a minute). Each footprint's cells are kept, keyed by its exact pose: the solver
        asks about the same placed objects again with every pose it tries for the next one, so
        only the new pose costs a distance computation (issue #18: 120 objects in a room)."""
        grid, _ = self._grid()
        centre, half, axes = _rectangle(boxes)
        keys = np.concatenate([centre, half, axes.reshape(len(centre), 4)], axis=1)
        size = np.array(grid.shape[:2])
        for c, h, x, key in zip(centre, half, axes, keys):
            known = self._near.get((key.tobytes(), margin, strict))
            if known is None:
                r = float(np.linalg.norm(h)) + margin + CELL
                first = np.clip(np.floor((c - r - self.lo) / CELL).astype(int), 0, size)
                last = np.clip(np.ceil((c + r - self.lo) / CELL).astype(int) + 1, 0, size)
                window = (slice(first[0], last[0]), slice(first[1], last[1]))
                d = _to_rectangle(grid[window], c, h, x)
                known = (window, d < margin if strict else d <= margin)
                if len(self._near) >= NEAR_CACHE:
                    self._near.clear()
                self._near[(key.tobytes(), margin, strict)] = known
            yield known

    def _grid(self) -> tuple[np.ndarray, np.ndarray]:
        """Cell centres (nx, ny, 2) over the floor's extent, and which of them an agent may
        stand on with no wall nearer than its radius (cached: the room does not change)."""
        if self._cells is None:
            xs = np.arange(self.lo[0] + CELL / 2, self.hi[0], CELL)
            ys = np.arange(self.lo[1] + CELL / 2, self.hi[1], CELL)
            grid = np.stack(np.meshgrid(xs, ys, indexing="ij"), axis=-1)
            self._cells = (grid, self.contains(grid) & (self._to_boundary(grid) >= AGENT_RADIUS))
        return self._cells


def floor_needed(footprint: float, count: int) -> float:
    """The floor (m²) that ``count`` floor objects covering ``footprint`` m² need to be placed
    with every one within reach: ``footprint / COVERAGE`` for up to :data:`WALL_SERVED` of
    them, more beyond. A room's wall length grows with its side, √area, while the objects grow
    with its area, so the share of them a wall can serve falls like 1/√n and the rest need
    aisles: without this a dense room was solved, found unreachable and solved again, grown."""
    return footprint / COVERAGE * max(1.0, math.sqrt(count / WALL_SERVED))


def boxes_of(objects: Sequence[SceneObject]) -> Boxes:
    """The objects' world boxes with their footprints, stacked for the measures above."""
    if not objects:
        return Boxes(np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0), np.zeros((0, 2)))
    parts = [Boxes.of(o) for o in objects]
    return Boxes(np.stack([b.lo for b in parts]), np.stack([b.hi for b in parts]),
                 np.array([float(b.yaw) for b in parts]), np.stack([b.foot for b in parts]))


def access_trouble(room: Room, objects: Sequence[SceneObject]) -> int:
    """How much of what :func:`problems` finds a larger floor can cure (all but a missing
    door), counted by the things it is about: seven seats out of reach are worse than one,
    though one sentence says each."""
    return sum(count for sentence, count in _findings(room, objects) if sentence != NO_DOOR)


#: The sentence :func:`problems` says of a room without a door.
NO_DOOR = "the room has no door"


def problems(room: Room, objects: Sequence[SceneObject], floor_ids: set[str] | None = None) -> list[str]:
    """What is wrong with ``objects`` in ``room``, one sentence each: objects outside it,
    openings blocked, doors nobody can step through, floor objects nobody can walk to."""
    return [sentence for sentence, _ in _findings(room, objects, floor_ids)]


def _findings(room: Room, objects: Sequence[SceneObject], floor_ids: set[str] | None = None) -> list[tuple[str, int]]:
    """:func:`problems`' sentences, each with how many objects or doors it is about."""
    shape = RoomShape(room)
    out = []
    if objects:
        outside = shape.outside_by(boxes_of(objects))
        for o, by in zip(objects, outside):
            if by > SLACK:
                out.append((f"{o.id} is outside the room by {by:.2f} m", 1))
        for o, by in zip(objects, shape.above_ceiling(boxes_of(objects))):
            if by > 0:
                out.append((f"{o.id} reaches {by:.2f} m above the ceiling", 1))
    for k, opening, ids in shape.blocked_openings(objects):
        out.append((f"{opening.kind} {k} on wall_{opening.wall} is blocked by {', '.join(ids)}", len(ids)))
    if not any(o.kind == "door" for o in room.openings):
        out.append((NO_DOOR, 1))
    unreachable, stuck = shape.unreachable(objects, floor_ids)
    for k in stuck:
        out.append((f"door {k} on wall_{room.openings[k].wall} opens onto no free floor", 1))
    if unreachable:
        out.append((f"no walking path from a door reaches {', '.join(unreachable)}", len(unreachable)))
    return out


def resized(room: Room, width: float, depth: float, height: float | None = None) -> Room:
    """``room`` with its floor stretched to ``width`` x ``depth`` m (its plan extent; about its
    middle, so an L stays an L) and ``height`` high. Each opening keeps its wall and its place
    along it as a share of the wall's length, nudged in from the ends; one that no longer fits
    its wall is dropped. Raises pydantic's ValidationError for a room that cannot be."""
    pts = np.asarray(room.floor, dtype=float)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    middle, scale = (lo + hi) / 2.0, np.array([width, depth]) / (hi - lo)
    floor = [(float(x), float(y)) for x, y in np.round(middle + (pts - middle) * scale, 6)]
    height = room.height if height is None else height
    bare = Room.model_validate({**room.model_dump(), "floor": floor, "height": height, "openings": []})
    kept = []
    for o in room.openings:
        length = bare.wall_length(o.wall)
        offset = min(max(o.offset / room.wall_length(o.wall) * length, o.width / 2 + 0.05), length - o.width / 2 - 0.05)
        tall = min(o.height, height - o.sill - 0.1)
        if offset - o.width / 2 >= 0 and tall > 0.3:
            kept.append(o.model_copy(update={"offset": offset, "height": tall}))
    return Room.model_validate({**bare.model_dump(), "openings": kept})


#: Directions (x, y) of the room's sides as a viewer at the front sees them (DESIGN frames: +Y back).
SIDES = {"back": (0.0, 1.0), "front": (0.0, -1.0), "left": (-1.0, 0.0), "right": (1.0, 0.0)}


def wall_facing(room: Room, side: str) -> int:
    """The wall on ``side`` (back, front, left, right) of ``room``: the one whose outward normal
    points most that way (the longest among equals), so "the back wall" of an L-shaped room is
    its wall furthest along +Y."""
    if side not in SIDES:
        raise ValueError(f"unknown side {side!r}; sides are {', '.join(SIDES)}")
    direction = np.array(SIDES[side])
    best, key = 0, None
    for i, ((x0, y0), (x1, y1)) in enumerate(room.walls):
        d = np.array([x1 - x0, y1 - y0])
        length = float(np.linalg.norm(d))
        outward = np.array([d[1], -d[0]]) / length  # right of a CCW edge: outside
        # Most outward that way first; then the one furthest that way; then the longest.
        mid = np.array([(x0 + x1) / 2.0, (y0 + y1) / 2.0])
        rank = (round(float(outward @ direction), 6), round(float(mid @ direction), 6), length)
        if key is None or rank > key:
            best, key = i, rank
    return best


def shortfall(room: Room, footprint: float, unplaced: Sequence[str]) -> str | None:
    """Why ``unplaced`` objects do not fit, when the floor is the reason: the floor objects'
    ``footprint`` (m²) against the room's floor, and how much more floor would hold them with
    walking space (:data:`COVERAGE`); None when nothing is unplaced or the floor is not short."""
    have = RoomShape(room).area
    if not unplaced or footprint <= COVERAGE * have:
        return None  # nothing left out, or not for want of floor
    more = footprint / COVERAGE - have
    sentence = (f"{', '.join(unplaced)} do not fit: the floor objects cover {footprint:.1f} m² of the "
                f"{have:.1f} m² floor ({footprint / have:.0%})")
    if more > 0:
        sentence += f"; about {more:.1f} m² more floor ({footprint / COVERAGE:.0f} m² in all) would hold them with room to walk"
    return sentence
