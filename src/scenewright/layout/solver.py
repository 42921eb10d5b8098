"""The layout solver: the paper's depth-first search (Algorithm 1), made fast and honest.

Objects are placed in topological order (every target before its sources; among ready
objects, larger footprints first). For each object the candidates come from its
highest-priority constraint — ``on``/``above`` first (they fix the height and footprint),
then the relative ones (a half-plane), then ``near``, ``far`` and ``face to`` — or, without
constraints, from a spiral around its initial position; nearest to the initial position
first, so the model's guess is preferred. All candidates are checked against all the
object's constraints and the bounds at once (numpy), then for collision in order (a numpy
box broad phase in batches, fcl for the rest).

Three things keep the search from blowing up where plain backtracking would:

- Forward checking: a pose is taken only if every object that depends on this one can still
  meet its constraints on the objects placed so far. How many poses it may reject adapts:
  each time a later object's failure jumps back into this one, its allowance doubles. In a
  rerun, an allowance used up on one dependent first puts the poses that leave it room first.
- Conflict-directed backjumping: when an object has no valid pose, the search jumps back to
  the latest object that blocked it or shaped its candidates (its targets and theirs),
  moves that one clear of where it was, and re-places what came after. Repeated failures
  escalate to earlier culprits, and move them farther.
- Bounded effort and restarts: each object may cause :data:`MAX_JUMPS` jumps; past that, or
  past the work limit, it is given up. An incomplete run is repeated (up to
  :data:`RESTARTS`, each with a bounded budget) with the troublesome objects and everything
  they depend on placed first; the most complete layout wins.

An object given up on is still placed: at its nearest miss, the collision-free pose (inside
the bounds where there is one) that violates its constraints least. It is reported with the
constraints in conflict, and everything placed against it is placed as usual, so one
contradiction costs one object, not all that depend on it.

Yaw: an object with a ``face to`` is turned to face its target exactly
(:func:`geometry.yaw_towards`) at each candidate; when that target is placed after it (two
objects facing each other), it holds the room to turn in and is turned when the target is
placed. Every other object not named in ``keep_yaw`` is tried at the model's yaw and at the
four axis yaws (a turn costs :data:`TURN_COST` of distance), so a dense room can be packed.
Heights follow the paper's ground rule: an object that is not the source of ``on``/``above``
rests on the ground. ``above`` offers a few heights above its minimum.

The search is limited by counted work, never by a clock, so the same problem and seed give the
same layout on any machine and under any load: search nodes (``node_limit``), and a work count
(:class:`_Clock`) that ``time_limit`` sets in seconds of a reference machine. CPU time stops a
search only at :data:`CPU_BACKSTOP` times that, on a machine far slower than the reference.
"""

from __future__ import annotations

import logging
import time
from collections import Counter
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Iterable, Mapping, Sequence

import numpy as np

from scenewright.errors import InputError
from scenewright.geometry import world_box
from scenewright.core.relations import BINDING, BUFFER, OPPOSITE_SIDES, PRIORITY
from scenewright.layout import relations as rel
from scenewright.layout.collision import CollisionWorld, colliding_pairs, resting_pairs
from scenewright.layout.constraints import clean_constraints, topological_order
from scenewright.layout.relations import (
    Boxes,
    RoomTarget,
    footprint_half,
    half_extents,
    rest_area,
    rest_share,
    rotated_half,
    tilt_matrix,
)
from scenewright.layout.room import SLACK as ROOM_SLACK
from scenewright.layout.room import RoomShape, shortfall
from scenewright.layout.room import problems as room_problems
from scenewright.scene import ROOM_RELATIONS, Constraint, LayoutReport, Room, SceneObject, UnplacedObject, Vec3

if TYPE_CHECKING:  # meshes are only handed on to the collision world, which needs no mesh library
    import trimesh

log = logging.getLogger(__name__)

#: Backjumps one object may trigger before it is given up.
MAX_JUMPS = 10
#: Searches per solve, until one is complete.
RESTARTS = 4
#: Candidates per broad-phase batch.
CHUNK = 64
#: Poses of one object forward checking may first reject; doubled each time the object is
#: jumped back into.
FORWARD_REJECTS = 32
#: Radius (m) around a pose forward checking rejected in which no other pose is tried.
REJECT_SPREAD = 0.2
#: The most poses forward checking may reject in one go, however often it was jumped back into.
MAX_REJECTS = 128
#: Poses of a refusing dependent :meth:`_Search.aim` pairs with the next untried candidates (at
#: most :data:`AIM_UNTRIED` of them), and the seed of the generator it draws them with (its own,
#: so the search's draws stay as they were).
AIM_POSES = 120
AIM_UNTRIED = 400
AIM_SEED = 0
#: Poses forward checking may reject once aimed: the pairing is judged on a sample, without the
#: facing's turn, so when the first few it put first fail, it has misjudged that dependent.
AIM_REJECTS = 8
#: Search nodes per object each of the first searches may use; the last one gets
#: :data:`LAST_NODES` times as many, at most what is left of the whole budget
#: (:data:`NODES_PER_OBJECT` per object).
ATTEMPT_NODES = 6
LAST_NODES = 2
NODES_PER_OBJECT = 80
#: The work count: one unit per narrow-phase pair test, :data:`GENERATE_WORK` per generation of
#: an object's candidates; :data:`WORK_PER_SECOND` units make one second of ``time_limit``. Both
#: are CPU costs on the reference machine (the project's 2-core one), fitted over 85 solves of three
#: fresh batches: they predict a search's CPU time within 20 % (median) for the searches over 2 s.
GENERATE_WORK = 40
WORK_PER_SECOND = 20_000
CPU_BACKSTOP = 3.0
#: Distance (m) a turned pose must gain over the model's yaw to be tried first.
TURN_COST = 0.3
#: Floor share covered from which candidates include positions flush against others.
CROWDED = 0.25
#: Clearance (m) of a position flush against another object.
FLUSH_GAP = 1e-3
#: Mesh-level collision checks one search node may make before its remaining candidates are
#: given up: in a crowded room the nearest thousands may all collide (a blanket among the
#: furniture of a bathroom), and each check costs a narrow phase; the wider set comes next.
NARROW_CHECKS = 600
#: Poses of one floor object that may be rejected for cutting a walking path in a room before
#: the next free one is taken all the same (the repair pass and the report take it from there).
WALK_REJECTS = 40
#: Relations of one side that a turn can break: checked on the box an object sweeps turning
#: while it waits to face an object placed after it.
SWEPT = ("left of", "right of", "in front of", "behind", "side of")
#: m, room left in a gap for a thing still to be placed between two others beyond its own width
#: and the buffers, so it is not held to one exact spot.
GAP_SLACK = 0.5
#: Shares of the way from one target to the other tried for a thing between them.
GAP_STEPS = np.linspace(0.05, 0.95, 37)
#: How much more a constraint an object's failure does not name weighs at its nearest miss.
KEPT = 10.0
#: Yaws tried for an object whose orientation nothing fixes, besides the model's.
AXIS_YAWS = (0.0, 90.0, 180.0, 270.0)
#: m, the plan gap within which an object's first pose stands beside its target (:meth:`_Search.follow_target`).
BESIDE_GAP = 1.0


def _cpu() -> float:
    return time.thread_time()


@dataclass
class _Clock:
    """The work budget of one solve, shared by its searches: each adds its ``work`` when done."""

    limit: int
    deadline: float  # CPU seconds of the solving thread: the backstop
    spent: int = 0

    @classmethod
    def starting(cls, time_limit: float) -> _Clock:
        return cls(int(time_limit * WORK_PER_SECOND), _cpu() + CPU_BACKSTOP * time_limit)

    def out(self, running: int = 0) -> bool:
        """Whether the budget is spent, with ``running`` work of a search under way."""
        return self.spent + running >= self.limit or _cpu() > self.deadline


def _area(bounds, room: RoomShape | None) -> tuple[np.ndarray, np.ndarray] | None:
    """The rectangle (lo, hi) in plan that holds the bounds (centred at the origin) and the room."""
    boxes = [] if bounds is None else [(-np.asarray(bounds, dtype=float) / 2.0, np.asarray(bounds, dtype=float) / 2.0)]
    boxes += [] if room is None else [(room.lo, room.hi)]
    if not boxes:
        return None
    return np.max([b[0] for b in boxes], axis=0), np.min([b[1] for b in boxes], axis=0)


def _opposite_pair(own: Sequence[tuple[Constraint, int]]) -> tuple[int, int, int] | None:
    """The two targets an object must stand on opposite sides of (right of one and left of the
    other; behind one and in front of the other), if any: it stands between them. Returned as
    (the one at the low end, the one at the high end, the world axis between them)."""
    sides: dict[str, int] = {}
    for c, t in own:
        sides.setdefault(c.relation, t)
    for axis, (low, high) in enumerate(OPPOSITE_SIDES):
        if low in sides and high in sides and sides[low] != sides[high]:
            return sides[low], sides[high], axis
    return None


def _off_segment(points: np.ndarray, ends: np.ndarray) -> np.ndarray:
    """Distance from each of ``points`` (k, 2) to the segment between ``ends`` (2, 2)."""
    d = ends[1] - ends[0]
    t = np.clip((points - ends[0]) @ d / max(float(d @ d), 1e-12), 0.0, 1.0)
    return np.linalg.norm(points - (ends[0] + t[:, None] * d), axis=1)


def _yaws_towards(src: np.ndarray, dst: np.ndarray) -> np.ndarray:
    """:func:`geometry.yaw_towards` for many points at once."""
    d = np.asarray(dst, dtype=float) - np.asarray(src, dtype=float)
    return np.degrees(np.arctan2(d[..., 0], -d[..., 1]))


@dataclass
class LayoutResult:
    """Copies of the objects with solved poses, the cleaned constraints, and the report.

    ``posed`` holds the ids the solver gave a collision-free pose: every placed object and each
    unplaced one put at its nearest miss (the rest keep their initial pose)."""

    objects: list[SceneObject]
    constraints: list[Constraint]
    report: LayoutReport
    posed: set[str] = field(default_factory=set)


@dataclass(frozen=True)
class _Poses:
    """One object's candidate poses (nearest the anchor first) and what each of them meets."""

    centres: np.ndarray
    yaws: np.ndarray
    boxes: Boxes
    #: Per active constraint, which candidates satisfy it.
    satisfied: list[np.ndarray]
    #: Which candidates satisfy all of them (and keep the followers' relations when turned).
    ok: np.ndarray
    #: Which of the candidates in ``ok`` lie inside the bounds (the others are not measured).
    inside: np.ndarray
    #: Follower index → its yaw per candidate (an object facing this one turns with it).
    turns: dict[int, np.ndarray]


@dataclass
class _Failure:
    reason: str
    failed: list[Constraint]
    nearest: str | None = None
    #: No move of another object can help: the constraints contradict each other, or it is
    #: placed against an object that stands at its nearest miss.
    inherent: bool = False


@dataclass
class _Item:
    """One object to place, with its constraints resolved to indices."""

    index: int
    obj: SceneObject
    half: np.ndarray  # half size, local
    tilt: np.ndarray  # rotation without yaw
    half_z: float
    foot: np.ndarray  # footprint half extents in its own yaw frame
    rest: float  # share of its height where things put on it rest (relations.rest_share)
    area: np.ndarray | None  # the part of its footprint they stand on (relations.rest_area)
    own: list[tuple[Constraint, int]]  # this object is the source; (constraint, target)
    reverse: list[tuple[Constraint, int]]  # a fixed object is the source; (constraint, source)
    yaws: tuple[float, ...]  # yaws it may take when no facing decides
    walls: list[tuple[Constraint, RoomTarget]] = field(default_factory=list)  # its room relations


@dataclass
class _Node:
    item: _Item
    centres: np.ndarray
    yaws: np.ndarray
    lo: np.ndarray  # broad-phase boxes of the candidates
    hi: np.ndarray
    columns: np.ndarray  # placed objects the broad phase looks at
    turns: dict[int, np.ndarray] = field(default_factory=dict)  # follower -> its yaw per candidate
    hits: np.ndarray | None = None  # candidates × columns, filled a chunk at a time
    cursor: int = 0
    conflict: set[int] = field(default_factory=set)
    blockers: Counter = field(default_factory=Counter)
    avoid: list[tuple[np.ndarray, float]] = field(default_factory=list)
    shunned: np.ndarray | None = None  # which candidates of the chunk under way lie in an avoided place
    shunned_by: int = 0  # how many of ``avoid`` ``shunned`` has taken in
    forward_rejects: int = 0
    reject_allowance: int = FORWARD_REJECTS
    wide: bool = False  # drawn from the wide set, after the usual one ran out
    narrow: int = 0  # mesh-level checks made for it so far
    narrow_cap: int = 0  # the most it may make (0: no limit)
    walk_rejects: int = 0  # poses rejected for cutting the walking paths
    walk_base: int | None = None  # objects out of reach (and doors stuck) without it
    refuser: int | None = None  # the dependent that forward checking last found without a pose
    aimed: bool = False  # its untried candidates were ordered for that dependent (:meth:`_Search.aim`)


class _Search:
    """One search's state: the poses placed so far, their collision world, the candidates."""

    def __init__(self, objects, constraints, meshes, bounds, fixed, seed, spread=0.0, keep_yaw=(), room=None,
                 corridors=False, aiming=False):
        self.objects = list(objects)
        #: Whether forward checking that runs out of allowance aims (:meth:`aim`): in reruns.
        self.aiming = aiming
        self.index = {o.id: i for i, o in enumerate(self.objects)}
        self.room = None if room is None else RoomShape(room, corridors)
        #: The rectangle (lo, hi) every footprint must stay in: the bounds, the room's extent.
        self.area = _area(bounds, self.room)
        self.rng = np.random.default_rng(seed)
        self.work = 0  # counted as :data:`WORK_PER_SECOND` explains
        self.meshes = meshes or {}
        self.world = CollisionWorld(self.objects, meshes, resting_pairs(constraints))
        n = len(self.objects)
        self.pos = np.array([o.position.tuple() for o in self.objects]).reshape(n, 3)
        #: Where each object's candidates start: its initial position, scattered on restarts.
        self.anchor = self.pos.copy()
        #: The initial poses, which :meth:`follow_target` measures a target's move from.
        self.start = self.pos.copy()
        self.anchor[:, :2] += self.rng.normal(0.0, spread, (n, 2)) if spread else 0.0
        self.yaw = np.array([o.yaw for o in self.objects], dtype=float)
        self.lo = np.zeros((n, 3))
        self.hi = np.zeros((n, 3))
        #: In the collision world.
        self.placed = np.zeros(n, dtype=bool)
        #: Has a pose others may be placed against (placed, or given up at its initial pose).
        self.posed = np.zeros(n, dtype=bool)
        self.fixed = {self.index[x] for x in fixed}
        own: dict[int, list] = {i: [] for i in range(n)}
        reverse: dict[int, list] = {i: [] for i in range(n)}
        walls: dict[int, list] = {i: [] for i in range(n)}
        for c in constraints:
            if c.relation in ROOM_RELATIONS:
                if self.index[c.source] not in self.fixed:
                    walls[self.index[c.source]].append((c, RoomTarget.of(room, c.target)))
                continue
            s, t = self.index[c.source], self.index[c.target]
            if s not in self.fixed:
                own[s].append((c, t))
            elif t not in self.fixed:
                reverse[t].append((c, s))
        keep = set(keep_yaw)
        self.items = {}
        for i, o in enumerate(self.objects):
            facing = any(c.relation == "face to" for c, _ in own[i])
            yaws = (o.yaw,) if facing or o.id in keep or i in self.fixed else self._yaw_options(o)
            self.items[i] = _Item(
                i, o, np.array(o.size.tuple()) / 2, tilt_matrix(o.rotation),
                float(half_extents(o.size, o.rotation)[2]), footprint_half(o.size, o.rotation), rest_share(o),
                rest_area(o), own[i], reverse[i], yaws, walls[i],
            )
        #: Objects with a constraint on each object, for forward checking and re-checks.
        self.dependents: dict[int, list[int]] = {i: [] for i in range(n)}
        for s in range(n):
            for t in sorted({t for _, t in own[s]}):
                self.dependents[t].append(s)
        self.twins = self._twins()
        #: Objects placed at their nearest miss, violating their constraints.
        self.missed: set[int] = set()
        #: (object, target, target's yaw) -> the object's constraints to that target if they
        #: contradict each other, else None.
        self.contradictions: dict[tuple[int, int, float], list[Constraint] | None] = {}
        #: Per object, the placed objects that face it and turn when it is placed.
        self.followers: dict[int, list[int]] = {i: [] for i in range(n)}
        for i in self.fixed:
            self.put(i, self.pos[i], self.yaw[i])

    def _twins(self) -> dict[int, set[int]]:
        """Per free object nothing depends on, the others of its kind: the same shape, the same
        yaws and the same constraints to the same targets ("a dozen ladles above the stove").
        Twins swap places without changing anything, so one that collides only with its twins has
        met the room its constraints leave, not a bad pose of theirs (:func:`_dfs`)."""
        kinds: dict[tuple, set[int]] = {}
        for i, item in self.items.items():
            if i in self.fixed or self.dependents[i] or item.reverse:
                continue
            key = (tuple(self.world.local_half[i]), item.obj.rotation.tuple(), item.yaws,
                   tuple(sorted((c.relation, t) for c, t in item.own)),
                   tuple(sorted((c.relation, c.target) for c, _ in item.walls)))
            kinds.setdefault(key, set()).add(i)
        return {i: kind - {i} for kind in kinds.values() for i in kind}

    def _yaw_options(self, obj: SceneObject) -> tuple[float, ...]:
        """The model's yaw, then the axis yaws that give a different shape: a half turn of a plain
        box changes nothing the solver sees, a quarter turn does."""
        symmetric = obj.id not in self.meshes
        seen, out = [], []
        for yaw in (obj.yaw, *AXIS_YAWS):
            key = yaw % (180.0 if symmetric else 360.0)
            if not any(min(abs(key - k), abs(abs(key - k) - (180.0 if symmetric else 360.0))) < 1e-6 for k in seen):
                seen.append(key)
                out.append(float(yaw))
        return tuple(out)

    def follow(self, order: list[int]) -> None:
        """Set up the facings whose target comes later in ``order``: the source turns then."""
        at = {i: k for k, i in enumerate(order)}
        for i, item in self.items.items():
            if i not in at:
                continue
            for c, t in item.own:
                if c.relation == "face to" and at.get(t, -1) > at[i]:
                    self.followers[t].append(i)
                    self.world.turning_room(i)

    def ancestors(self, ids: set[int]) -> set[int]:
        """``ids`` and every object they depend on, through their constraints' targets."""
        out, stack = set(), list(ids)
        while stack:
            i = stack.pop()
            if i not in out:
                out.add(i)
                stack.extend(t for _, t in self.items[i].own)
        return out

    # --- state ---------------------------------------------------------------------------

    def set_pose(self, i: int, centre: np.ndarray, yaw: float) -> None:
        """Record ``i``'s pose for the relations (not the collision world)."""
        item = self.items[i]
        half = rotated_half(item.half, item.tilt, yaw)
        self.pos[i], self.yaw[i] = centre, yaw
        self.lo[i], self.hi[i] = centre - half, centre + half
        self.posed[i] = True

    def put(self, i: int, centre: np.ndarray, yaw: float) -> None:
        self.set_pose(i, centre, yaw)
        self.placed[i] = True
        self.world.place(i, centre, yaw)

    def take(self, i: int) -> None:
        self.placed[i] = self.posed[i] = False
        self.missed.discard(i)
        self.world.remove(i)

    def downstream(self, item: _Item) -> bool:
        """Whether the object is placed against one at its nearest miss: its own trouble follows
        from that conflict, and moving other objects is no cure."""
        return any(t in self.missed for _, t in item.own)

    def box(self, i: int) -> Boxes:
        item = self.items[i]
        return Boxes(self.lo[i], self.hi[i], self.yaw[i], item.foot, item.rest, item.area)

    def boxes_of(self, item: _Item, centres: np.ndarray, yaws: np.ndarray) -> Boxes:
        return Boxes.at(centres, rotated_half(item.half, item.tilt, yaws), yaws, item.foot, item.rest, item.area)

    # --- candidates ----------------------------------------------------------------------

    def candidates(self, item: _Item, wide: bool = False) -> _Node | _Failure:
        """The object's candidate poses that meet its constraints and the bounds, nearest first."""
        poses = self.poses(item, "wide" if wide else "normal")
        good = poses.ok & poses.inside
        if not good.any():
            return self.explain(item, poses.boxes, poses.satisfied, poses.ok, poses.inside)
        centres, yaws = poses.centres[good], poses.yaws[good]
        lo, hi = self.world.boxes(item.index, centres, yaws)
        return _Node(item, centres, yaws, lo, hi, self.world.neighbours(item.index),
                     {f: y[good] for f, y in poses.turns.items()}, wide=wide, narrow_cap=NARROW_CHECKS)

    def feasible(self, item: _Item) -> bool:
        """Whether any candidate pose meets the object's constraints and the bounds: a sparse
        set at the model's yaw first (it usually answers), then the full one."""
        return any(self.any_pose(item, density) for density in ("probe", "check"))

    def active(self, item: _Item) -> list[tuple[Constraint, int]]:
        """The object's constraints whose targets have a pose (a facing waits for its target)."""
        return [(c, t) for c, t in item.own if self.posed[t]]

    def poses(
        self, item: _Item, density: str = "normal", anchor: np.ndarray | None = None, bounded: bool = True
    ) -> _Poses:
        """Candidate poses and, per constraint, which of them satisfy it. ``density`` is
        ``"normal"``, ``"wide"`` (farther and denser, when the normal set ran out), ``"probe"``
        (a sparse set at the model's yaw) or ``"check"`` (sparser than normal): the last two for
        forward checking. ``anchor`` replaces the object's own; ``bounded=False`` ignores the bounds.
        """
        centres, yaws, boxes, turns, swept = self._generate(item, density, anchor, bounded)
        sat = [
            rel.holds(c.relation, swept if swept is not None and c.relation in SWEPT else boxes, tb)
            if tb is not None else rel.holds(c.relation, sb, boxes)
            for c, tb, sb in self.pairs(item, turns, centres)
        ]
        ok = np.logical_and.reduce(sat) if sat else np.ones(len(centres), dtype=bool)
        for f, y in turns.items():  # and its own relations must survive the turn
            ok &= self.still_holds(f, y, exclude=item.index)
        return _Poses(centres, yaws, boxes, sat, ok, self.inside(boxes if swept is None else swept, among=ok), turns)

    def any_pose(
        self, item: _Item, density: str, anchor: np.ndarray | None = None, bounded: bool = True, inside: bool = True
    ) -> bool:
        """Whether any of the candidates :meth:`poses` makes meets every constraint (and, with
        ``inside``, the bounds): the same answer, found by judging each constraint only on the
        candidates that met the ones before, as forward checking asks it thousands of times."""
        centres, yaws, boxes, turns, swept = self._generate(item, density, anchor, bounded)
        alive = np.arange(len(centres))
        for c, tb, sb in self.pairs(item, turns, centres):
            if tb is None:
                keep = rel.holds(c.relation, sb, boxes[alive])
            else:
                mine = swept if swept is not None and c.relation in SWEPT else boxes
                turned = isinstance(tb, Boxes) and tb.lo.ndim == 2  # a target facing each candidate
                keep = rel.holds(c.relation, mine[alive], tb[alive] if turned else tb)
            alive = alive[keep]
            if not len(alive):
                return False
        for f, y in turns.items():
            alive = alive[self.still_holds(f, y[alive], exclude=item.index)]
        if inside and len(alive):
            alive = alive[self.inside((boxes if swept is None else swept)[alive])]
        return bool(len(alive))

    def _generate(
        self, item: _Item, density: str, anchor: np.ndarray | None, bounded: bool
    ) -> tuple[np.ndarray, np.ndarray, Boxes, dict[int, np.ndarray], Boxes | None]:
        """The candidate poses of :meth:`poses`, nearest the anchor first: centres, yaws, their
        boxes, the yaw per candidate of each object facing this one, and the box each candidate
        sweeps turning when it waits to face an object placed later (else None)."""
        self.work += GENERATE_WORK
        obj = item.obj
        own = self.active(item)
        area = self.area if bounded else None
        ranked = sorted(own, key=lambda ct: PRIORITY[ct[0].relation])
        primary = ranked[0] if ranked else (self.rider_lead(item) if not item.walls else None)
        relation, target = (primary[0].relation, self.box(primary[1])) if primary else ("face to", None)
        # A room relation leads unless the object rests on another: a wall one fixes position
        # and yaw, "on ceiling" fixes the height (and "above" then only the plan position).
        wall = next(((c, t) for c, t in item.walls if c.relation != "on ceiling"), None)
        ceiling = next(((c, t) for c, t in item.walls if c.relation == "on ceiling"), None)
        resting = primary is not None and relation == "on"
        if ceiling is not None and not resting and primary is None:
            relation, target = "on ceiling", ceiling[1]
        ends = self.gap_between(own)
        if ends is None and not own:
            ends = self.riders_gap(item)
        if anchor is None:
            anchor = self.follow_target(item, primary)
            if ceiling is not None and relation == "near":
                # A thing hung near another hangs over it first (a lamp over its table), as a
                # designer would hang it: its candidates spread from the target's centre.
                anchor = np.append(target.centre[:2], anchor[2])
            elif ends is not None:
                anchor = np.append(ends.mean(axis=0), anchor[2])
            anchor = self.leave_gap(item, anchor)
        facing = next((t for c, t in ranked if c.relation == "face to"), None)
        waiting = next((t for c, t in item.own if c.relation == "face to" and not self.posed[t]), None)
        if facing is not None or waiting is not None:
            yaw_choices = (obj.yaw,)
        else:
            yaw_choices = item.yaws[:1] if density == "probe" else item.yaws
            if resting and self.posed[primary[1]]:
                # what rests on a thing turns with it first: a sitter faces where the chair faces
                host = float(self.yaw[primary[1]])
                yaw_choices = (host, *(y for y in yaw_choices if abs((y - host + 180.0) % 360.0 - 180.0) > 1e-6))
        xy_parts, yaw_parts, cost_parts = [], [], []
        if wall is not None and not resting:
            relation, target = wall[0].relation, wall[1]
            spacing = {"probe": 0.4, "check": 0.2, "normal": 0.1, "wide": 0.05}[density]
            xy, yaws, cost = rel.propose_wall(relation, item.foot, target, anchor, spacing)
            xy_parts, yaw_parts, cost_parts = [xy], [yaws], [cost]
            yaw_choices, facing = (), None  # the wall turns it
        for k, yaw in enumerate(yaw_choices):
            half = rotated_half(item.half, item.tilt, yaw)
            few = k > 0  # turned yaws get a sparser set
            if density == "probe":
                parts = [rel.propose(relation, half, target, anchor, self.rng, n=40, spacing=0.3),
                         rel.propose(relation, half, target, anchor, self.rng, n=40, spacing=0.8)]
            elif density == "wide":
                parts = [rel.propose(relation, half, target, anchor, self.rng, n=450 if few else 900, spacing=0.3)]
                if area is not None:
                    parts.append(self.rng.uniform(*area, size=(300 if few else 600, 2)))
            else:
                scale = 0.5 if density == "check" else 1.0
                parts = [
                    rel.propose(relation, half, target, anchor, self.rng, n=int(scale * (80 if few else 160)),
                                spacing=0.12 / np.sqrt(scale)),
                    rel.propose(relation, half, target, anchor, self.rng, n=int(scale * (70 if few else 140)),
                                spacing=0.45 / np.sqrt(scale)),
                ]
            if density != "probe" and bounded and relation not in ("on", "above") and self.crowded():
                parts.append(self.flush(item, half, anchor))
            if ends is not None and density != "probe":
                parts.append(ends[0] + GAP_STEPS[:, None] * (ends[1] - ends[0]))  # on the line between the two
            xy = np.concatenate(parts)
            if area is not None and np.all(area[1] - area[0] >= 2 * half[:2]):
                # Pull outside points onto the bounds' edge: tight rooms need their walls and corners.
                xy = np.clip(xy, area[0] + half[:2], area[1] - half[:2])
            key = np.round(xy, 4) @ np.array([1.0, 1j])
            _, first = np.unique(key, return_index=True)
            xy = xy[np.sort(first)]
            xy_parts.append(xy)
            yaw_parts.append(np.full(len(xy), yaw))
            cost = np.linalg.norm(xy - anchor[:2], axis=1) + (TURN_COST if k else 0.0)
            if ends is not None:  # in the gap, not beside it: off the line between the two costs double
                cost = cost + 2.0 * _off_segment(xy, ends)
            cost_parts.append(cost)
        xy, yaws, cost = np.concatenate(xy_parts), np.concatenate(yaw_parts), np.concatenate(cost_parts)

        heights = rel.source_heights(relation, item.half_z, target, anchor[2]) if target is not None else None
        if ceiling is not None and not resting:
            heights = rel.room_heights("on ceiling", item.half_z, ceiling[1])
        over = next((t for c, t in own if c.relation == "above"), None)
        if wall is not None and not resting and wall[0].relation == "on wall" and over is not None:
            # On a wall above a thing standing at it (a clock over a cabinet): the height "above" asks.
            mounted = rel.mounted_above_heights(item.half_z, wall[1], self.box(over))
            heights = heights if mounted is None else mounted
        if heights is None:
            heights = np.array([item.half_z])  # the ground rule
        cost = cost[None] + np.abs(heights - heights[0])[:, None]
        flat = np.argsort(cost.ravel(), kind="stable")
        h, xy, yaws = heights[flat // len(xy)], xy[flat % len(xy)], yaws[flat % len(xy)]
        if facing is not None:
            yaws = _yaws_towards(xy, self.box(facing).centre[:2])
        centres = np.column_stack([xy, h])
        boxes = self.boxes_of(item, centres, yaws)

        # An object facing this one turns to face each candidate: relations to it are to it turned.
        turns = {f: _yaws_towards(self.pos[f][:2], centres[:, :2]) for f in self.followers[item.index] if self.posed[f]}
        # One that will turn to face an object placed later may take any yaw then: its one-sided
        # relations and the bounds must hold for the box it sweeps turning, or a pose flush
        # against its target leaves it no room to turn (two chairs facing each other on one
        # side of a table).
        swept = None
        if waiting is not None:
            reach = float(np.hypot(*item.foot))
            swept = Boxes.at(centres, np.array([reach, reach, item.half_z]), yaws)
        return centres, yaws, boxes, turns, swept

    def follow_target(self, item: _Item, primary: tuple[Constraint, int] | None) -> np.ndarray:
        """The object's anchor, moved as far as the target of its leading relation has moved from
        its initial pose. The first poses put the two side by side ("a ladder leaning against the
        tree", "a judge behind the bench"); when the search stands the target somewhere else, the
        source's candidates start beside it again, not at the point of the relation's half-plane
        nearest the old spot, which can lie metres off along the other axis and still hold. Only an
        object that started within :data:`BESIDE_GAP` of its target follows it: an offset the first
        poses did not design is not worth keeping."""
        anchor = self.anchor[item.index].copy()
        if primary is None or primary[0].relation not in (*SWEPT, "near") or not self.posed[primary[1]]:
            return anchor
        t = primary[1]
        if rel.plan_gap(self.objects[item.index], self.objects[t]) <= BESIDE_GAP:  # they started together
            anchor[:2] += self.pos[t, :2] - self.start[t, :2]
        return anchor

    def gap_between(self, own: list[tuple[Constraint, int]]) -> np.ndarray | None:
        """The centres (2, 2) of two targets the object must stand on opposite sides of (right
        of one, left of the other; in front of one, behind the other), if any: a thing between
        two others, whose candidates then spread from the middle of the gap and keep to the line
        joining the two (where a viewer sees it between them) rather than anywhere the two
        half-planes meet."""
        pair = _opposite_pair(own)
        return None if pair is None else np.stack([self.box(pair[0]).centre[:2], self.box(pair[1]).centre[:2]])

    def riders(self, item: _Item) -> list[_Item]:
        """The objects still to be placed that rest ``on`` this one (a sitter on a stool)."""
        return [self.items[s] for s in self.dependents[item.index] if not self.posed[s]
                and any(c.relation == "on" and t == item.index for c, t in self.items[s].own)]

    def rider_lead(self, item: _Item) -> tuple[Constraint, int] | None:
        """For a thing with no relation of its own that something still to be placed rests ``on``,
        the most binding relation of that rider to a placed object beside it ("a toymaker on a
        stool, at his bench": near the bench): the thing's candidates come from it, so the rider
        can meet it from its back (forward checking still decides)."""
        for rider in self.riders(item):
            beside = [(c, t) for c, t in rider.own
                      if t != item.index and self.posed[t] and c.relation in (*SWEPT, "near")]
            if beside:
                return min(beside, key=lambda ct: BINDING.index(ct[0].relation))
        return None

    def riders_gap(self, item: _Item) -> np.ndarray | None:
        """The gap (as :meth:`gap_between`) a thing still to be put ``on`` this one must stand in,
        when this one is free to go there: a chair whose sitter stands between two benches goes
        in their gap, where the sitter then can."""
        for rider in self.riders(item):
            pair = _opposite_pair(rider.own)
            if pair is not None and item.index not in pair[:2] and self.posed[pair[0]] and self.posed[pair[1]]:
                return np.stack([self.box(pair[0]).centre[:2], self.box(pair[1]).centre[:2]])
        return None

    def leave_gap(self, item: _Item, anchor: np.ndarray) -> np.ndarray:
        """``anchor`` moved, where it must be, to the side of the gap that the objects still to be
        placed between this one and a placed one need ("a boulder right of the truck and left
        of the hut": the truck stands left of the hut, a boulder's width and both buffers apart),
        so the search starts where that gap can open rather than on the wrong side of the other."""
        anchor = np.array(anchor, dtype=float)
        half = float(np.max(item.foot))
        for s in self.dependents[item.index]:
            pair = None if self.posed[s] else _opposite_pair(self.items[s].own)
            if pair is None:
                continue
            low, high, axis = pair
            # all that stand in this gap side by side ("a row of parents between the benches"),
            # each as the model turned it
            width = sum(2 * rotated_half(o.half, o.tilt, o.obj.yaw)[axis]
                        for x, o in self.items.items()
                        if x in self.dependents[item.index] and not self.posed[x] and _opposite_pair(o.own) == pair)
            need = 2 * BUFFER + GAP_SLACK + width
            if item.index == low and self.posed[high]:
                anchor[axis] = min(anchor[axis], self.lo[high, axis] - need - half)
            elif item.index == high and self.posed[low]:
                anchor[axis] = max(anchor[axis], self.hi[low, axis] + need + half)
        return anchor

    def crowded(self) -> bool:
        """Whether the floor inside the bounds is so full that free positions are best found
        flush against what stands there (:data:`CROWDED` of it covered)."""
        if self.area is None:
            return False
        ground = self.placed & (self.lo[:, 2] < 0.05)
        covered = np.prod(self.hi[ground, :2] - self.lo[ground, :2], axis=1).sum()
        floor = self.room.area if self.room is not None else np.prod(self.area[1] - self.area[0])
        return covered > CROWDED * floor

    def flush(self, item: _Item, half: np.ndarray, anchor: np.ndarray, near: int = 8) -> np.ndarray:
        """Positions flush against the walls and the nearest placed objects standing at its
        height: every pairing of their edges' x and y (and the anchor's), the corner points a
        packer tries, which leave the floor in the fewest, largest free pieces."""
        i = item.index
        others = np.flatnonzero(self.placed & (self.world.lo[:, 2] < 2 * item.half_z))
        others = others[others != i]
        if len(others) > near:
            dist = np.linalg.norm((self.world.lo[others, :2] + self.world.hi[others, :2]) / 2 - anchor[:2], axis=1)
            others = others[np.argsort(dist, kind="stable")[:near]]
        lo, hi = self.world.lo[others, :2], self.world.hi[others, :2]
        gap = half[:2] + FLUSH_GAP  # a hair apart: touching counts as a collision to some checkers
        edges = np.concatenate([[self.area[0] + half[:2], self.area[1] - half[:2]], hi + gap, lo - gap])
        xs = np.append(edges[:, 0], anchor[0])
        ys = np.append(edges[:, 1], anchor[1])
        return np.stack(np.meshgrid(xs, ys), axis=-1).reshape(-1, 2)

    def still_holds(self, f: int, yaws: np.ndarray, exclude: int) -> np.ndarray:
        """Whether follower ``f``, turned to each of ``yaws``, keeps its constraints, those of the
        objects placed against it, and the bounds."""
        item = self.items[f]
        boxes = self.boxes_of(item, np.broadcast_to(self.pos[f], (len(yaws), 3)), yaws)
        ok = self.inside(boxes)
        for c, t in item.own:
            if t != exclude and self.posed[t] and c.relation != "face to":
                ok &= rel.holds(c.relation, boxes, self.box(t))
        for c, t in item.walls:
            ok &= rel.holds(c.relation, boxes, t)
        for s in self.dependents[f]:
            if s != exclude and self.posed[s]:
                for c, t in self.items[s].own:
                    if t == f:
                        ok &= rel.holds(c.relation, self.box(s), boxes)
        return ok

    def inside(self, boxes: Boxes, among: np.ndarray | None = None) -> np.ndarray:
        """Whether each box stands inside the bounds and the room, clear of its openings; with
        ``among`` (a mask), only those boxes are measured and the rest count as outside. The
        room's measure is the costly one: it is taken only of boxes inside the bounds."""
        if self.area is None:
            return np.ones(boxes.lo.shape[0], dtype=bool) if among is None else among.copy()
        ok = np.all(boxes.lo[:, :2] >= self.area[0] - rel.EPS, axis=1) & np.all(
            boxes.hi[:, :2] <= self.area[1] + rel.EPS, axis=1
        )
        if among is not None:
            ok &= among
        if self.room is not None and ok.any():
            ok[ok] = self.room.fits(boxes[ok])
        return ok

    def pairs(self, item: _Item, turns=None, centres=None) -> list[tuple[Constraint, Boxes | None, Boxes | None]]:
        """The object's constraints with the other side's box: (constraint, target box, source box);
        a target that ``turns`` to face each of ``centres`` with its boxes so turned."""
        turns = turns or {}

        def target(t):
            if t not in turns:
                return self.box(t)
            return self.boxes_of(self.items[t], np.broadcast_to(self.pos[t], centres.shape), turns[t])

        return [(c, target(t), None) for c, t in self.active(item)] + [(c, t, None) for c, t in item.walls] + [
            (c, None, self.box(s)) for c, s in item.reverse
        ]

    def explain(self, item: _Item, boxes: Boxes, sat, ok, inside) -> _Failure:
        """Why no candidate satisfied the constraints and bounds."""
        pairs = self.pairs(item)
        never = [c for (c, _, _), s in zip(pairs, sat) if not s.any()]
        # A constraint that fails here may only fail among the primary's candidates: ask its own.
        never = [c for c in never if not self.alone(item, c)]
        # Its height follows from its support's, which no move in plan changes: no jump back can help.
        over = self.over_ceiling(item)
        if never:
            return _Failure("no candidate position satisfies " + "; ".join(f"'{c}'" for c in never), never,
                            inherent=over is not None)
        if ok.any() and over is not None:
            how = "resting on" if any(c.relation == "on" and t == over for c, t in item.own) else "above"
            return _Failure(f"{how} {self.objects[over].id} it reaches past the {self.room.room.height:g} m "
                            "ceiling", [c for c, _, _ in pairs], inherent=True)
        if ok.any():
            w, d = self.area[1] - self.area[0]
            where = "room, or in a door's or window's clear strip" if self.room is not None else "bounds"
            reason = f"every position satisfying its constraints lies outside the {w:g} x {d:g} m {where}"
        elif any(self.posed[f] for f in self.followers[item.index]):
            reason = "its constraints cannot all hold at once, with the objects facing it turned"
        else:
            reason = "its constraints cannot all hold at once"
        conflict = self.contradiction(item) if not ok.any() else None
        if conflict is not None:
            return _Failure(reason, conflict, inherent=True)
        given_up = self.given_up(item) if not ok.any() else []
        return _Failure(reason, given_up or [c for c, _, _ in pairs])

    def over_ceiling(self, item: _Item) -> int | None:
        """What the object rests ``on`` or hangs ``above``, when there it reaches past the room's
        ceiling: its lowest height follows from that one's top, the same wherever in plan the two
        stand, so no pose of any object helps it (a stack too tall for the room, a lamp over a
        cupboard that reaches the ceiling). None otherwise."""
        ranked = sorted(self.active(item), key=lambda ct: PRIORITY[ct[0].relation])
        if self.room is None or not ranked or ranked[0][0].relation not in ("on", "above"):
            return None
        relation, support = ranked[0][0].relation, ranked[0][1]
        box = self.box(support)
        if relation == "on":
            top = float(box.top) + 2 * item.half_z
        else:
            top = rel.lowest_above(item.half_z, float(box.lo[2]), float(box.hi[2])) + item.half_z
        return support if top - self.room.room.height > ROOM_SLACK else None

    def given_up(self, item: _Item) -> list[Constraint]:
        """The object's constraints to go without so that the rest can hold together, as few and
        as weak as a greedy pass finds: each is kept, the most binding first (:data:`BINDING`,
        then the text's order), when the ones kept so far still have a pose with it. The report
        names these, so the feedback gives up what conflicts ("a car right of the mast and left
        of the airship, in front of the mast": right of the mast or left of the airship, not all
        three), not everything the object was asked."""
        ranked = sorted(self.active(item), key=lambda ct: BINDING.index(ct[0].relation))
        kept: list[tuple[Constraint, int]] = []
        out: list[Constraint] = []
        for c, t in ranked:
            if self.feasible(replace(item, own=kept + [(c, t)], reverse=[])):
                kept.append((c, t))
            else:
                out.append(c)
        return out

    def contradiction(self, item: _Item) -> list[Constraint] | None:
        """Constraints to one object that no pose meets together, or None. Relations between two
        objects do not change when both move together, so moving that object cannot help: it is
        a conflict in the constraints, and the report names only these."""
        groups: dict[int, list[tuple[Constraint, int]]] = {}
        for c, t in self.active(item):
            groups.setdefault(t, []).append((c, t))
        for t, group in groups.items():
            if len(group) < 2:
                continue
            key = (item.index, t, round(float(self.yaw[t]) % 360.0, 3))
            if key not in self.contradictions:
                saved = self.followers[item.index]
                self.followers[item.index] = []  # as the objects facing it stand
                try:
                    probe = replace(item, own=group, reverse=[], walls=[])
                    found = self.any_pose(probe, "wide", anchor=self.box(t).centre, bounded=False, inside=False)
                finally:
                    self.followers[item.index] = saved
                self.contradictions[key] = None if found else [c for c, _ in group]
            if self.contradictions[key] is not None:
                return self.contradictions[key]
        return None

    def alone(self, item: _Item, constraint: Constraint) -> bool:
        """Whether ``constraint`` on its own has a candidate inside the bounds."""
        own = [(c, t) for c, t in item.own if c is constraint]
        walls = [(c, t) for c, t in item.walls if c is constraint]
        if not own and not walls:
            return False  # another object's constraint on this one: no generator of its own
        probe = replace(item, own=own, reverse=[], walls=walls)
        saved, self.followers[item.index] = self.followers[item.index], []
        try:
            return self.feasible(probe)
        finally:
            self.followers[item.index] = saved

    def outside_by(self, boxes: Boxes) -> np.ndarray:
        """How far (m) each box is from standing where :meth:`inside` allows."""
        lo, hi = self.area
        over = (np.maximum(boxes.hi[:, :2] - hi, 0.0) + np.maximum(lo - boxes.lo[:, :2], 0.0)).max(axis=1)
        return over if self.room is None else np.maximum(over, self.room.misfit(boxes))

    def on_floor(self, i: int) -> bool:
        """Whether object ``i`` stands on the floor: no ``on``/``above`` or mounting places it."""
        up = ("on", "above")
        return not any(c.relation in up for c, _ in self.items[i].own) and not any(
            c.relation in ("on wall", "on ceiling") for c, _ in self.items[i].walls)

    def cuts_path(self, i: int, node: _Node) -> bool:
        """Whether ``i`` where it was just put leaves more floor objects out of an agent's reach
        from the doors (or more doors walled in) than without it; always False once the node
        has rejected :data:`WALK_REJECTS` poses, or for what does not stand on the floor."""
        if self.room is None or node.walk_rejects >= WALK_REJECTS or not self.on_floor(i):
            return False
        placed = np.flatnonzero(self.placed)
        boxes = Boxes(self.lo[placed], self.hi[placed], self.yaw[placed],
                      np.stack([self.items[j].foot for j in placed]))
        floor = np.array([self.on_floor(j) and self.lo[j, 2] < 0.05 for j in placed])

        def lost(mask: np.ndarray) -> int:
            missed, stuck = self.room.walk(boxes[mask], floor[mask])
            return len(missed) + len(stuck)

        if node.walk_base is None:
            node.walk_base = lost(placed != i)
        if lost(np.ones(len(placed), dtype=bool)) <= node.walk_base:
            return False
        node.walk_rejects += 1
        return True

    def misfit_detail(self, box: Boxes) -> str:
        """Where one box stands that :meth:`inside` does not allow, and by how much."""
        lo, hi = self.area
        over = float((np.maximum(box.hi[:, :2] - hi, 0.0) + np.maximum(lo - box.lo[:, :2], 0.0)).max())
        if self.room is None:
            return f"outside the bounds by {over:.2f} m"
        out, strip = float(max(over, self.room.outside_by(box)[0])), float(self.room.blocking(box)[0])
        parts = [f"outside the room by {out:.2f} m"] if out > 0 else []
        parts += [f"in a door's or window's clear strip by {strip:.2f} m"] if strip > 0 else []
        up = float(self.room.above_ceiling(box)[0])
        parts += [f"above the ceiling by {up:.2f} m"] if up > 0 else []
        return "; ".join(parts)

    def next_free(self, node: _Node) -> int | None:
        """The next candidate of ``node`` that collides with nothing placed, if any."""
        i = node.item.index
        while node.cursor < len(node.centres):
            k = node.cursor
            node.cursor += 1
            start = k - k % CHUNK
            if k == start:  # broad phase for the next chunk of candidates
                node.hits = self.world.overlaps(node.columns, node.lo[k : k + CHUNK], node.hi[k : k + CHUNK])
            if k == start or node.shunned is None:
                node.shunned, node.shunned_by = np.zeros(len(node.centres[start : start + CHUNK]), dtype=bool), 0
            if node.shunned_by < len(node.avoid):
                # The chunk's candidates near the places avoided since it was last looked at, at once.
                where = np.array([p for p, _ in node.avoid[node.shunned_by :]])
                reach = np.array([d for _, d in node.avoid[node.shunned_by :]])
                gaps = np.linalg.norm(node.centres[start : start + CHUNK, None, :2] - where[None], axis=2)
                node.shunned |= (gaps < reach).any(axis=1)
                node.shunned_by = len(node.avoid)
            if node.shunned[k - start]:
                continue
            touching = node.columns[node.hits[k % CHUNK]]
            if len(touching) == 0:
                return k
            self.work += len(touching)
            blockers = self.world.colliders(i, node.centres[k], float(node.yaws[k]), touching)
            if not blockers:
                return k
            node.narrow += 1
            if node.narrow_cap and node.narrow >= node.narrow_cap:
                log.debug("%s: %d candidates collided; the rest are not tried", node.item.obj.id, node.narrow)
                node.cursor = len(node.centres)
            node.conflict.update(blockers)
            node.blockers.update(blockers)
        return None

    def place_at(self, node: _Node, k: int) -> None:
        """Put ``node``'s object at candidate ``k`` and turn the objects that face it."""
        self.put(node.item.index, node.centres[k], float(node.yaws[k]))
        for f, yaws in node.turns.items():
            self.set_pose(f, self.pos[f], float(yaws[k]))
            if self.placed[f]:
                self.world.place(f, self.pos[f], float(yaws[k]))

    def forward_check(self, i: int, node: _Node) -> str:
        """Whether every object that depends on ``i`` can still meet its constraints.

        Run with ``i`` placed; each unplaced dependent is probed with its constraints on
        the objects placed so far. Returns ``"ok"``; ``"reject"`` when a dependent would have
        no candidate at this pose of ``i`` (its other targets join ``i``'s conflict set); or
        ``"hopeless"`` when it has none even ignoring ``i``, so no pose of ``i`` can help and
        only moving its other targets can.
        """
        for s in self.dependents[i]:
            item = self.items[s]
            known = self.active(item)
            if self.posed[s] or (len(known) < 2 and self.area is None) or self.downstream(item):
                continue
            if self.feasible(replace(item, own=known)):
                continue
            if self.contradiction(replace(item, own=known)) is not None or self.over_ceiling(item) is not None:
                continue  # no pose of anything helps it; it will be placed at its nearest miss
            node.conflict.update(t for _, t in known if t != i)
            rest = replace(item, own=[(c, t) for c, t in known if t != i])
            if not self.feasible(rest):
                log.debug("%s cannot help %s: its other targets must move", self.objects[i].id, item.obj.id)
                return "hopeless"
            node.forward_rejects += 1
            node.refuser = s
            log.debug("%s rejected: %s would have no position", self.objects[i].id, self.objects[s].id)
            return "reject"
        return "ok"

    def aim(self, node: _Node) -> bool:
        """When forward checking has used up a node's allowance on one dependent, put first the
        untried candidates at which that dependent could still stand, once; returns whether any.

        Candidates come nearest the anchor first, so when a dependent's other targets leave it room
        only on one side of this object (children on a bench across from the grandmother, who
        stands near a table beyond the bench), the allowance runs out on the wrong side and the
        search jumps back again and again. Here the dependent's poses that meet its other
        constraints (a sample, drawn with its own generator so the search's draws stay as they
        were) are paired with the next untried candidates, its relations to this object judged on
        each pair, and the candidates some pose pairs with go first, in their order, with a small
        fresh allowance (:data:`AIM_REJECTS`). Only a dependent whose relations to this object are
        relative, distance or facing ones is aimed for (a facing is left to the real check, which
        still decides).
        Only reruns aim (:func:`_restarts`): a first search that places everything stays the
        layout it was.
        """
        s, i = node.refuser, node.item.index
        if not self.aiming or s is None or node.aimed or node.cursor >= len(node.centres):
            return False
        node.aimed = True
        item = self.items[s]  # this object is taken again by now: its relations are the ones to it
        mine = [c for c, t in item.own if t == i and c.relation != "face to"]
        rest = [(c, t) for c, t in self.active(item) if t != i]
        if not mine or not rest or any(c.relation not in (*SWEPT, "near", "far") for c in mine):
            return False
        saved, self.rng = self.rng, np.random.default_rng(AIM_SEED)
        try:
            found = self.poses(replace(item, own=rest), "check")
        finally:
            self.rng = saved
        theirs = found.boxes[np.flatnonzero(found.ok & found.inside)[:AIM_POSES]]
        if not len(theirs.lo):
            return False
        k = node.cursor
        end = min(len(node.centres), k + AIM_UNTRIED)
        untried = self.boxes_of(node.item, node.centres[k:end], node.yaws[k:end])[:, None]
        pairs = np.ones((end - k, len(theirs.lo)), dtype=bool)
        for c in mine:
            pairs &= rel.holds(c.relation, theirs[None], untried)
        good = pairs.any(axis=1)
        if not good.any():
            return False
        order = np.concatenate([np.arange(k), k + np.flatnonzero(good), k + np.flatnonzero(~good),
                                np.arange(end, len(node.centres))])
        node.centres, node.yaws = node.centres[order], node.yaws[order]
        node.lo, node.hi = node.lo[order], node.hi[order]
        node.turns = {f: y[order] for f, y in node.turns.items()}
        start = k - k % CHUNK  # the broad phase of the chunk under way, for its new candidates
        node.hits = self.world.overlaps(node.columns, node.lo[start : start + CHUNK], node.hi[start : start + CHUNK])
        node.shunned = None
        node.reject_allowance = node.forward_rejects + AIM_REJECTS
        log.debug("%s: %d untried candidates leave %s a position; they go first",
                  node.item.obj.id, int(good.sum()), item.obj.id)
        return True

    def blocked(self, node: _Node, limited: bool) -> _Failure:
        item = node.item
        names = ", ".join(self.objects[j].id for j, _ in node.blockers.most_common(3)) or "nothing"
        if node.forward_rejects and not node.blockers:
            reason = "every free position leaves an object that depends on it without a valid position"
        elif not node.blockers:
            reason = "every candidate position was tried and rejected"
        else:
            reason = f"every position satisfying its constraints collides (most often with {names})"
        if limited:
            reason = "search limit reached; " + reason
        nearest = None
        if len(node.centres):
            p = node.centres[0]
            nearest = f"at ({p[0]:.2f}, {p[1]:.2f}, {p[2]:.2f}) it would collide with {names}"
        return _Failure(reason, [c for c, _, _ in self.pairs(item)], nearest)

    def settle(self, i: int, failure: _Failure) -> tuple[_Failure, int]:
        """Put an object given up on at its nearest miss; returns its failure and the nodes used.

        The nearest miss is the collision-free pose, inside the bounds if any is, whose summed
        violation of its constraints is least (a degree of facing counts as a centimetre; one the
        failure does not name counts :data:`KEPT` times). With
        no collision-free pose at all it keeps its initial pose, outside the collision world,
        so the objects placed against it still have a pose to be placed against.
        """
        item = self.items[i]
        poses = self.poses(item, "wide")
        centres, yaws, boxes, turns = poses.centres, poses.yaws, poses.boxes, poses.turns
        pairs = self.pairs(item, turns, centres)
        misses = [
            rel.violations(c.relation, boxes, tb) if tb is not None else rel.violations(c.relation, sb, boxes)
            for c, tb, sb in pairs
        ]
        # What the failure names gives way first: the rest weighs KEPT times more, so the nearest
        # miss keeps what :meth:`given_up` found can hold together.
        given = {c.key() for c in failure.failed}
        scale = [(0.01 if c.relation == "face to" else 1.0) * (1.0 if c.key() in given else KEPT)
                 for c, _, _ in pairs]
        total = sum(m * w for m, w in zip(misses, scale)) if misses else np.zeros(len(centres))
        if self.area is not None:
            total = total + 1e3 * self.outside_by(boxes)
        for f, yaw in turns.items():  # a follower that cannot turn there misses its facing
            total = total + 1e3 * ~self.still_holds(f, yaw, exclude=i)
        order = np.argsort(total, kind="stable")
        obj = item.obj
        lo, hi = self.world.boxes(i, centres[order], yaws[order])
        node = _Node(item, centres[order], yaws[order], lo, hi, self.world.neighbours(i),
                     {f: y[order] for f, y in turns.items()})
        k = self.next_free(node)
        if k is None:
            self.set_pose(i, np.array(obj.position.tuple()), obj.yaw)
            log.debug("%s: no collision-free pose at all; it keeps its initial pose", obj.id)
            return failure, node.cursor
        p, j = node.centres[k], order[k]
        detail = [
            f"'{c}' {rel.describe(c.relation, float(m[j]))}" for (c, _, _), m in zip(pairs, misses) if m[j] > 0
        ]
        # The report names every constraint this pose leaves unmet, besides those that explained
        # the failure: the ones it misses, and the facings of objects that cannot turn to it.
        missed = [c for (c, _, _), m in zip(pairs, misses) if m[j] > 0]
        if self.area is not None and self.outside_by(boxes)[j] > 0:
            detail.append(self.misfit_detail(boxes[j : j + 1]))
        if self.downstream(item):
            failure = replace(failure, inherent=True)
        for f in list(node.turns):
            if not self.still_holds(f, node.turns[f][k : k + 1], exclude=i)[0]:
                del node.turns[f]  # it stays as it is, not facing this object
                detail.append(f"'{self.objects[f].id} face to {obj.id}' not met: it cannot turn there")
                missed += [c for c, t in self.items[f].own if t == i and c.relation == "face to"]
        self.place_at(node, k)
        if not detail:
            return None, node.cursor  # the wider set found a pose that meets everything
        self.missed.add(i)
        nearest = f"placed at ({p[0]:.2f}, {p[1]:.2f}, {p[2]:.2f}): " + "; ".join(detail)
        named = {c.key() for c in failure.failed}
        failed = failure.failed + [c for c in missed if c.key() not in named]
        return replace(failure, failed=failed, nearest=nearest), node.cursor


def solve(
    objects: Sequence[SceneObject],
    constraints: Iterable[Constraint | Mapping],
    *,
    meshes: Mapping[str, trimesh.Trimesh] | None = None,
    bounds: tuple[float, float] | None = None,
    fixed: Iterable[str] = (),
    keep_yaw: Iterable[str] = (),
    time_limit: float = 10.0,
    node_limit: int | None = None,
    seed: int = 0,
    room: Room | None = None,
) -> LayoutResult:
    """Place every object the constraints allow, collision-free, inside ``bounds`` (W, D).

    An object that cannot meet its constraints is put at its nearest miss and explained in
    the report; only with no collision-free pose anywhere does it keep its initial pose.
    ``fixed`` ids keep their pose and count as placed; ``keep_yaw`` ids keep their yaw unless a
    ``face to`` turns them. ``node_limit`` caps the search work (default
    :data:`NODES_PER_OBJECT` per object), ``time_limit`` its counted work in seconds of the
    reference machine (:class:`_Clock`).

    With a ``room``, every object stays inside its floor polygon and out of the clear strips of
    its doors and windows (:mod:`.room`), room relations hold like the others, and a repair
    pass moves floor objects nobody can walk to; what stays wrong is in ``report.room``.
    """
    start = _cpu()
    clock = _Clock.starting(time_limit)
    objects, fixed = _checked(objects, fixed, bounds)
    cleaned, dropped = clean_constraints(objects, constraints, room)
    if node_limit is None:
        node_limit = NODES_PER_OBJECT * len(objects) + 1000
    search, report = _restarts(objects, cleaned, meshes, bounds, fixed, keep_yaw, seed, clock, node_limit, room)
    if room is not None:
        search, report = _walkable(search, report, objects, cleaned, meshes, bounds, fixed, keep_yaw, seed,
                                   clock, node_limit, room)
        report.room = _room_report(search, report, objects, solved=True)
    # An unplaced object the search left at its nearest miss has a pose too.
    posed = {u.id for u in report.unplaced if search.placed[search.index[u.id]]}
    return _result(objects, cleaned, dropped, search, report, posed, start)


def audit(
    objects: Sequence[SceneObject],
    constraints: Iterable[Constraint | Mapping],
    *,
    meshes: Mapping[str, trimesh.Trimesh] | None = None,
    bounds: tuple[float, float] | None = None,
    fixed: Iterable[str] = (),
    room: Room | None = None,
) -> LayoutResult:
    """The layout as it stands, judged without moving anything: which objects violate their
    constraints, collide, leave the bounds or the ``room`` (the ablation's layout "without
    the solver")."""
    start = _cpu()
    objects, fixed = _checked(objects, fixed, bounds)
    cleaned, dropped = clean_constraints(objects, constraints, room)
    search = _Search(objects, cleaned, meshes, bounds, fixed, 0, room=room)
    report = _audit(search, objects, cleaned, meshes)
    if room is not None:
        report.room = _room_report(search, report, objects, solved=False)
    return _result(objects, cleaned, dropped, search, report, set(), start)


def _checked(
    objects: Sequence[SceneObject], fixed: Iterable[str], bounds: tuple[float, float] | None
) -> tuple[list[SceneObject], list[str]]:
    objects = list(objects)
    ids = [o.id for o in objects]
    if len(set(ids)) != len(ids):
        dup = sorted({x for x in ids if ids.count(x) > 1})
        raise InputError(f"object ids must be unique; repeated: {', '.join(dup)}")
    fixed = list(dict.fromkeys(fixed))
    unknown = [x for x in fixed if x not in ids]
    if unknown:
        raise InputError(f"fixed ids {unknown} are not objects; objects are: {', '.join(ids)}")
    if bounds is not None and (len(bounds) != 2 or min(bounds) <= 0):
        raise InputError(f"bounds must be two positive numbers (width, depth), got {bounds!r}")
    return objects, fixed


def _result(
    objects: list[SceneObject],
    cleaned: list[Constraint],
    dropped: list,
    search: _Search,
    report: LayoutReport,
    posed_unplaced: set[str],
    start: float,
) -> LayoutResult:
    """The objects at the poses the search gave the placed ones (and ``posed_unplaced``)."""
    report.dropped = dropped
    report.seconds = round(_cpu() - start, 4)
    posed = set(report.placed) | posed_unplaced
    solved = []
    for i, o in enumerate(objects):
        if o.id in posed:
            p, y = search.pos[i], float(search.yaw[i])
            o = o.model_copy(
                update={"position": Vec3.of(p), "rotation": Vec3(x=o.rotation.x, y=o.rotation.y, z=y)}
            )
        else:
            o = o.model_copy(deep=True)
        solved.append(o)
    log.info(
        "layout: %d placed, %d unplaced, %d nodes, %.3f CPU s",
        len(report.placed), len(report.unplaced), report.nodes, report.seconds,
    )
    return LayoutResult(solved, cleaned, report, posed)


def _restarts(objects, constraints, meshes, bounds, fixed, keep_yaw, seed, clock, node_limit, room=None,
              corridors=False):
    """Run the search up to :data:`RESTARTS` times until one places everything; keep the best.

    Every run but the last has a node budget of :data:`ATTEMPT_NODES` per object; the last
    :data:`LAST_NODES` times that (within what is left): a last run that completes has needed at
    most 1.6 times a first run's budget, while one that cannot ran on rejecting and jumping back
    through all that was left (five times a first run's budget, to the end of the clock). A rerun
    puts the objects that gave trouble (left unplaced, or forced backjumps) and everything they
    depend on first — the "squeaky wheel": placed while the scene is still empty, they fit — and
    scatters the other starting anchors a little more each time. A run whose every failure is a
    contradiction among one object's constraints (or one no pose mends: it reaches past the
    ceiling) ends the search: no rerun can mend that.
    """
    best = None
    used = 0
    trouble: set[int] = set()
    for attempt in range(RESTARTS):
        search = _Search(objects, constraints, meshes, bounds, fixed, seed + attempt, spread=0.15 * attempt,
                         keep_yaw=keep_yaw, room=room, corridors=corridors, aiming=attempt > 0)
        budget = (ATTEMPT_NODES * len(objects) + 100) * (LAST_NODES if attempt == RESTARTS - 1 else 1)
        budget = min(budget, node_limit - used)
        report, troubled, inherent = _dfs(search, clock, budget, first=search.ancestors(trouble))
        trouble |= troubled
        used += report.nodes
        clock.spent += search.work
        if best is None or _score(report) > _score(best[1]):
            best = (search, report)
        if report.complete or used >= node_limit or clock.out() or inherent:
            break
        log.info("layout attempt %d left %d unplaced; restarting", attempt + 1, len(report.unplaced))
    best[1].nodes = used
    return best


def _score(report: LayoutReport) -> tuple[int, int]:
    return (len(report.placed), -len(report.unplaced))


def _dfs(
    search: _Search, clock: _Clock, node_limit: int, first: set[int] = frozenset()
) -> tuple[LayoutReport, set[int], bool]:
    """One depth-first search; also returns the objects that gave trouble, and whether every
    failure was a contradiction among one object's constraints.

    Objects in ``first`` are placed before the rest (as far as the order allows); among the
    others, larger footprints go first.
    """
    free = [o.id for i, o in enumerate(search.objects) if i not in search.fixed]
    rank = {o.id: (i not in first, -o.size.x * o.size.y) for i, o in enumerate(search.objects)}
    own = [c for item in search.items.values() for c, _ in item.own]
    order = [search.index[x] for x in topological_order(free, own, key=rank.get)]
    search.follow(order)
    nodes: list[_Node | None] = [None] * len(order)
    failures: dict[int, _Failure] = {}
    depth_of: dict[int, int] = {}
    jumps: Counter = Counter()
    #: Objects left over among their twins: their failure, and the twins placed then.
    left_over: dict[int, tuple[_Failure, list[int]]] = {}
    count = 0
    limited = False
    depth = 0

    def settle(i: int, failure) -> int:
        """Leave ``i`` at its nearest miss, its failure recorded; the nodes that cost."""
        settled, used = search.settle(i, failure)
        if settled is not None:
            failures[i] = settled
        return 1 + used // CHUNK

    def place(i: int, node: _Node, k: int) -> None:
        nonlocal depth
        search.place_at(node, k)
        depth_of[i] = depth
        depth += 1

    while depth < len(order):
        if not limited and (clock.out(search.work) or count >= node_limit):
            limited = True
            log.info("layout search limit reached after %d nodes; finishing greedily", count)
        i = order[depth]
        node = nodes[depth]
        fallback = None  # a free pose that only failed forward checking
        over = next((f for t, (f, held) in left_over.items()
                     if t in failures and t in search.twins.get(i, ()) and search.placed[held].all()), None)
        if node is None and over is not None:
            # A twin was left over and every twin that filled the room is still there: so is this one.
            failure = replace(over, failed=[c for c, _, _ in search.pairs(search.items[i])], nearest=None)
            count += settle(i, failure)
            depth += 1
            continue
        if node is None:
            made = search.candidates(search.items[i])
            if isinstance(made, _Failure):
                # Its targets' poses decide its candidates: they are the conflict set.
                conflict, failure = {t for c, t in search.items[i].own if search.placed[t]}, made
                conflict = set() if made.inherent else conflict | set(search.followers[i])
            else:
                node = nodes[depth] = made
        if node is not None:
            k = search.next_free(node)
            verdict = "ok"
            while k is not None:
                search.place_at(node, k)
                count += 1
                verdict = "ok" if limited else search.forward_check(i, node)
                if verdict == "ok" and not limited and search.cuts_path(i, node):
                    verdict = "walk"
                search.take(i)
                if verdict == "ok":
                    break
                fallback = k if fallback is None else fallback
                # Its neighbours would most likely fail the same way: look a little farther.
                node.avoid.append((node.centres[k, :2].copy(), REJECT_SPREAD))
                if verdict == "hopeless" or (node.forward_rejects >= node.reject_allowance and not search.aim(node)):
                    k = None
                    break
                k = search.next_free(node)
            if k is not None:
                place(i, node, k)
                continue
            if not node.wide and not limited and verdict != "hopeless":
                # Before blaming others, look farther afield (the same avoidances hold).
                wider = search.candidates(search.items[i], wide=True)
                if not isinstance(wider, _Failure):
                    wider.conflict, wider.blockers, wider.avoid = node.conflict, node.blockers, node.avoid
                    wider.forward_rejects, wider.reject_allowance = node.forward_rejects, node.reject_allowance
                    nodes[depth] = wider
                    continue
            # Its targets, and theirs, shaped its candidates, so they share the blame.
            conflict, failure = node.conflict | search.ancestors({i}) - {i}, None
            conflict |= set(search.followers[i])
        culprits = {j for j in conflict if j in depth_of and search.placed[j]}
        crowded = node is not None and node.blockers and node.blockers.keys() <= search.twins.get(i, set())
        if crowded:
            # Only its twins are in the way: moving them (or what they stand against) only swaps
            # which of them is left over, so the search goes on without jumping back.
            culprits = set()
        if limited or not culprits or jumps[i] >= MAX_JUMPS or search.downstream(search.items[i]):
            if fallback is not None:  # the dependents will report their own failure
                place(i, node, fallback)
                continue
            failure = failure or search.blocked(node, limited)
            if crowded:
                left_over[i] = (failure, [t for t in search.twins[i] if search.placed[t]])
            count += settle(i, failure)
            depth += 1
            continue
        # Backjump to the latest culprit; everything after it is undone and re-placed.
        jumps[i] += 1
        # The latest culprit first; each time this object fails again, the next earlier one.
        depths = sorted((depth_of[j] for j in culprits), reverse=True)
        back = depths[(jumps[i] - 1) % len(depths)]
        j = order[back]
        log.debug("%s has no position; back to %s", search.objects[i].id, search.objects[j].id)
        for d in range(depth - 1, back - 1, -1):
            x = order[d]
            if search.posed[x]:
                search.take(x)
                depth_of.pop(x, None)
            failures.pop(x, None)
            if d > back:
                nodes[d] = None
        nodes[depth] = None
        # In a rerun, one whose every pose a dependent refused moves the culprit by that one's size
        # too: a nest whose egg leaves a dragon curled round it no room moves a dragon's length, not
        # an egg's. (Not when the allowance ran out first: candidates were left to try there.)
        refused = (search.aiming and node is not None and node.refuser is not None
                   and node.cursor >= len(node.centres) and not node.blockers)
        movers = [i] + ([node.refuser] if refused else [])
        half = np.max([half_extents(search.objects[x].size, search.objects[x].rotation) for x in movers], axis=0)
        target = nodes[back]
        assert target is not None, "a placed object has its node"
        target.conflict |= culprits - {j}
        target.reject_allowance = min(target.forward_rejects + 2 * target.reject_allowance,
                                      target.forward_rejects + MAX_REJECTS)
        # Move the culprit clear of where it was, farther each time this object fails.
        reach = max(0.15, float(max(half[0], half[1]))) * jumps[i]
        target.avoid.append((search.pos[j][:2].copy(), reach))
        depth = back
    placed = [o.id for i, o in enumerate(search.objects) if search.placed[i] and i not in failures]
    unplaced = [
        UnplacedObject(id=search.objects[i].id, failed=f.failed, reason=f.reason, nearest_miss=f.nearest)
        for i, f in sorted(failures.items(), key=lambda kv: order.index(kv[0]))
    ]
    troubled = set(failures) | {i for i, n in jumps.items() if n}
    inherent = all(f.inherent or search.downstream(search.items[i]) for i, f in failures.items())
    return LayoutReport(placed=placed, unplaced=unplaced, nodes=count, solver=True), troubled, inherent


def _audit(search: _Search, objects, constraints, meshes) -> LayoutReport:
    """The ablation: keep every initial pose, report what it gets wrong."""
    collisions: dict[str, list[str]] = {}
    for a, b in colliding_pairs(objects, meshes, constraints):
        collisions.setdefault(a, []).append(b)
        collisions.setdefault(b, []).append(a)
    by_id = {o.id: o for o in objects}
    placed, unplaced = [], []
    for o in objects:
        failed = [c for c in constraints if c.source == o.id and c.relation not in ROOM_RELATIONS
                  and not rel.check(c.relation, o, by_id[c.target])]
        failed += [c for c, target in search.items[search.index[o.id]].walls
                   if not rel.holds(c.relation, Boxes.of(o), target)]
        problems = []
        if failed:
            problems.append("initial pose violates " + "; ".join(f"'{c}'" for c in failed))
        if o.id in collisions:
            problems.append(f"initial pose collides with {', '.join(collisions[o.id])}")
        lo, hi = world_box(o)
        if search.area is not None and not search.inside(Boxes.of(o)[None])[0]:
            problems.append("initial pose leaves the " + ("room" if search.room is not None else "bounds"))
        if problems:
            unplaced.append(UnplacedObject(id=o.id, failed=failed, reason="; ".join(problems)))
        else:
            placed.append(o.id)
    return LayoutReport(placed=placed, unplaced=unplaced, nodes=0, solver=False)


#: Candidate poses tried per object the repair pass moves, and objects it may move.
REPAIR_TRIES = 24
REPAIR_OBJECTS = 4


def _posed_objects(search: _Search) -> list[SceneObject]:
    """The objects at their current poses in the search (those with one)."""
    out = []
    for i, o in enumerate(search.objects):
        if search.posed[i]:
            out.append(o.model_copy(update={"position": Vec3.of(search.pos[i]),
                                            "rotation": Vec3(x=o.rotation.x, y=o.rotation.y, z=float(search.yaw[i]))}))
    return out


def _floor_ids(search: _Search) -> set[str]:
    """Objects that stand on the floor: not the source of ``on``/``above``, not hung or mounted."""
    up = {"on", "above", "on wall", "on ceiling"}
    return {o.id for i, o in enumerate(search.objects)
            if search.posed[i] and not any(c.relation in up for c, _ in search.items[i].own + search.items[i].walls)
            and search.lo[i, 2] < 0.05}


def _walkable(search, report, objects, constraints, meshes, bounds, fixed, keep_yaw, seed, clock, node_limit,
              room):
    """The layout with floor objects reachable from a door, as far as the search can make it.

    First the repair pass over the layout found; when something is still out of reach, the
    search runs again with each door's strip run on to the middle of the floor (a corridor no
    floor object may block) and the repair pass again, if the first search left half its work;
    the better layout wins: fewer objects unplaced or out of reach, the first on a tie."""
    left = _make_walkable(search, report)
    if not left or clock.spent > clock.limit / 2 or _cpu() > clock.deadline:
        return search, report  # all reached, or no budget for a second search
    log.info("layout: %d objects out of reach; solving again with corridors from the doors", left)
    again, second = _restarts(objects, constraints, meshes, bounds, fixed, keep_yaw, seed, clock, node_limit,
                              room, corridors=True)
    second.nodes += report.nodes
    if len(second.unplaced) + _make_walkable(again, second) < len(report.unplaced) + left:
        return again, second
    report.nodes = second.nodes
    return search, report


def _make_walkable(search: _Search, report: LayoutReport) -> int:
    """The repair pass: move each floor object no one can walk to (latest placed first), to the
    nearest pose that meets its constraints and lets the agent reach everything reached before.
    Objects others stand on or against stay: moving them would drag their dependents along.
    Returns how many floor objects stay out of reach."""
    floor = _floor_ids(search)
    stuck, _ = search.room.unreachable(_posed_objects(search), floor)
    moved = 0
    for oid in reversed(stuck):
        i = search.index[oid]
        if moved >= REPAIR_OBJECTS or i in search.fixed or not search.placed[i]:
            continue
        if any(search.posed[s] for s in search.dependents[i]) or search.followers[i]:
            continue
        old = search.pos[i].copy(), float(search.yaw[i])
        search.take(i)
        node = search.candidates(search.items[i], wide=True)
        fixed = False
        for _ in range(REPAIR_TRIES if not isinstance(node, _Failure) else 0):
            k = search.next_free(node)
            if k is None:
                break
            search.place_at(node, k)
            now, _ = search.room.unreachable(_posed_objects(search), floor)
            if len(now) < len(stuck) and oid not in now:
                stuck, fixed = now, True
                break
            search.take(i)
        if not fixed:
            search.put(i, *old)
        moved += 1
    log.debug("walkability repair: %d still unreachable", len(stuck))
    return len(stuck)


def _room_report(search: _Search, report: LayoutReport, objects: Sequence[SceneObject], solved: bool) -> list[str]:
    """What is wrong with the layout in its room (:func:`scenewright.layout.room.problems`), and
    each room relation that does not hold."""
    posed = _posed_objects(search) if solved else list(objects)
    floor = _floor_ids(search) if solved else None
    out = room_problems(search.room.room, posed, floor)
    footprint = sum(4.0 * float(np.prod(search.items[i].foot)) for i in search.items if search.on_floor(i))
    lacking = shortfall(search.room.room, footprint, [u.id for u in report.unplaced])
    if lacking:
        out.insert(0, lacking)
    by_id = {o.id: o for o in posed}
    for i, item in search.items.items():
        o = by_id.get(item.obj.id)
        for c, target in item.walls:
            if o is not None and not rel.holds(c.relation, Boxes.of(o), target):
                miss = float(rel.violations(c.relation, Boxes.of(o), target))
                out.append(f"'{c}' does not hold: {rel.describe(c.relation, miss)}")
    return out
