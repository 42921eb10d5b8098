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
  meet its constraints on the objects placed so far.
- Conflict-directed backjumping: when an object has no valid pose, the search jumps back to
  the latest object that blocked it or shaped its candidates (its targets and theirs),
  moves that one clear of where it was, and re-places what came after. Repeated failures
  escalate to earlier culprits, and move them farther.
- Bounded effort and restarts: each object may cause :data:`MAX_JUMPS` jumps; past that, or
  past the node or time limit, it is left unplaced with a report and the search goes on.
  An incomplete run is repeated (up to :data:`RESTARTS`) with the troublesome objects and
  everything they depend on placed first; the most complete layout wins. A last pass
  retries unplaced objects over a much wider candidate set.

Yaw: an object with a ``face to`` constraint is turned to face its target exactly
(:func:`geometry.yaw_towards`) at each candidate; every other object keeps the model's yaw.
Heights follow the paper's ground rule: an object that is not the source of ``on``/``above``
rests on the ground. ``above`` offers a few heights above its minimum.
"""

from __future__ import annotations

import logging
import time
from collections import Counter
from dataclasses import dataclass, field, replace
from typing import Iterable, Mapping, Sequence

import numpy as np
import trimesh

from scenewright.errors import InputError
from scenewright.geometry import world_box, yaw_towards
from scenewright.layout import relations as rel
from scenewright.layout.collision import CollisionWorld, colliding_pairs, resting_pairs
from scenewright.layout.constraints import clean_constraints, topological_order
from scenewright.layout.relations import Boxes, half_extents, rotated_half, tilt_matrix
from scenewright.scene import Constraint, LayoutReport, SceneObject, UnplacedObject, Vec3

log = logging.getLogger(__name__)

#: Backjumps one object may trigger before it is left unplaced.
MAX_JUMPS = 10
#: Searches per solve, until one is complete.
RESTARTS = 4
#: Candidates per broad-phase batch.
CHUNK = 64
#: Poses of one object forward checking may reject before its other targets must move.
FORWARD_REJECTS = 24


@dataclass
class LayoutResult:
    """Copies of the objects with solved poses, the cleaned constraints, and the report."""

    objects: list[SceneObject]
    constraints: list[Constraint]
    report: LayoutReport


@dataclass
class _Failure:
    reason: str
    failed: list[Constraint]
    nearest: str | None = None


@dataclass
class _Item:
    """One object to place, with its constraints resolved to indices."""

    index: int
    obj: SceneObject
    half: np.ndarray  # half size, local
    tilt: np.ndarray  # rotation without yaw
    half_z: float
    own: list[tuple[Constraint, int]]  # this object is the source; (constraint, target)
    reverse: list[tuple[Constraint, int]]  # a fixed object is the source; (constraint, source)


@dataclass
class _Node:
    item: _Item
    centres: np.ndarray
    yaws: np.ndarray
    lo: np.ndarray  # broad-phase boxes of the candidates
    hi: np.ndarray
    columns: np.ndarray  # placed objects the broad phase looks at
    hits: np.ndarray | None = None  # candidates × columns, filled a chunk at a time
    cursor: int = 0
    conflict: set[int] = field(default_factory=set)
    blockers: Counter = field(default_factory=Counter)
    avoid: list[tuple[np.ndarray, float]] = field(default_factory=list)
    forward_rejects: int = 0


class _Search:
    """One search's state: the poses placed so far, their collision world, the candidates."""

    def __init__(self, objects, constraints, meshes, bounds, fixed, seed, spread=0.0):
        self.objects = list(objects)
        self.index = {o.id: i for i, o in enumerate(self.objects)}
        self.bounds = None if bounds is None else np.asarray(bounds, dtype=float) / 2.0
        self.rng = np.random.default_rng(seed)
        self.world = CollisionWorld(self.objects, meshes, resting_pairs(constraints))
        n = len(self.objects)
        self.pos = np.array([o.position.tuple() for o in self.objects]).reshape(n, 3)
        #: Where each object's candidates start: its initial position, scattered on restarts.
        self.anchor = self.pos.copy()
        self.anchor[:, :2] += self.rng.normal(0.0, spread, (n, 2)) if spread else 0.0
        self.yaw = np.array([o.yaw for o in self.objects], dtype=float)
        self.lo = np.zeros((n, 3))
        self.hi = np.zeros((n, 3))
        self.placed = np.zeros(n, dtype=bool)
        self.fixed = {self.index[x] for x in fixed}
        own: dict[int, list] = {i: [] for i in range(n)}
        reverse: dict[int, list] = {i: [] for i in range(n)}
        for c in constraints:
            s, t = self.index[c.source], self.index[c.target]
            if s not in self.fixed:
                own[s].append((c, t))
            elif t not in self.fixed:
                reverse[t].append((c, s))
        self.items = {
            i: _Item(
                i, o, np.array(o.size.tuple()) / 2, tilt_matrix(o.rotation),
                float(half_extents(o.size, o.rotation)[2]), own[i], reverse[i],
            )
            for i, o in enumerate(self.objects)
        }
        #: Objects with a constraint on each object, for forward checking.
        self.dependents: dict[int, list[int]] = {i: [] for i in range(n)}
        for s in range(n):
            for t in sorted({t for _, t in own[s]}):
                self.dependents[t].append(s)
        for i in self.fixed:
            self.put(i, self.pos[i], self.yaw[i])

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

    def put(self, i: int, centre: np.ndarray, yaw: float) -> None:
        item = self.items[i]
        half = rotated_half(item.half, item.tilt, yaw)
        self.pos[i], self.yaw[i] = centre, yaw
        self.lo[i], self.hi[i] = centre - half, centre + half
        self.placed[i] = True
        self.world.place(i, centre, yaw)

    def take(self, i: int) -> None:
        self.placed[i] = False
        self.world.remove(i)

    def box(self, i: int) -> Boxes:
        return Boxes(self.lo[i], self.hi[i], self.yaw[i])

    # --- candidates ----------------------------------------------------------------------

    def candidates(self, item: _Item, wide: bool = False) -> _Node | _Failure:
        """The object's candidate poses that meet its constraints and the bounds, nearest first."""
        poses = self.poses(item, wide)
        if isinstance(poses, _Failure):
            return poses
        centres, yaws, boxes, sat, ok, inside = poses
        good = ok & inside
        if not good.any():
            return self.explain(item, boxes, sat, ok, inside)
        centres, yaws = centres[good], yaws[good]
        lo, hi = self.world.boxes(item.index, centres, yaws)
        return _Node(item, centres, yaws, lo, hi, self.world.neighbours(item.index))

    def feasible(self, item: _Item) -> bool:
        """Whether any candidate pose meets the object's constraints and the bounds."""
        poses = self.poses(item)
        return not isinstance(poses, _Failure) and bool(np.any(poses[4] & poses[5]))

    def poses(self, item: _Item, wide: bool = False):
        """Candidate poses and, per constraint, which of them satisfy it; or why there are none.

        Returns (centres, yaws, boxes, per-constraint masks, all-constraints mask, in-bounds
        mask), or a failure when a target is not placed.
        """
        obj = item.obj
        missing = [c for c, t in item.own if not self.placed[t]]
        if missing:
            names = sorted({c.target for c in missing})
            return _Failure(f"depends on {', '.join(names)}, which could not be placed", missing)
        anchor = self.anchor[item.index]
        half0 = rotated_half(item.half, item.tilt, obj.yaw)
        ranked = sorted(item.own, key=lambda ct: rel.PRIORITY[ct[0].relation])
        primary = ranked[0] if ranked else None
        relation, target = (primary[0].relation, self.box(primary[1])) if primary else ("face to", None)
        if wide:
            parts = [rel.propose(relation, half0, target, anchor, self.rng, n=900, spacing=0.3)]
            if self.bounds is not None:
                parts.append(self.rng.uniform(-self.bounds, self.bounds, size=(600, 2)))
        else:
            parts = [
                rel.propose(relation, half0, target, anchor, self.rng, n=160, spacing=0.12),
                rel.propose(relation, half0, target, anchor, self.rng, n=140, spacing=0.45),
            ]
        xy = np.concatenate(parts)
        if self.bounds is not None and np.all(self.bounds >= half0[:2]):
            # Pull outside points onto the bounds' edge: tight rooms need their walls and corners.
            xy = np.clip(xy, -self.bounds + half0[:2], self.bounds - half0[:2])
        xy = xy[np.argsort(np.linalg.norm(xy - anchor[:2], axis=1), kind="stable")]
        key = np.round(xy, 4) @ np.array([1.0, 1j])
        _, first = np.unique(key, return_index=True)
        xy = xy[np.sort(first)]

        heights = rel.source_heights(relation, item.half_z, target, anchor[2]) if primary else None
        if heights is None:
            heights = np.array([item.half_z])  # the ground rule
        elif len(heights) > 1:
            cost = np.linalg.norm(xy - anchor[:2], axis=1)[None] + np.abs(heights - heights[0])[:, None]
            flat = np.argsort(cost.ravel(), kind="stable")
            heights, xy = heights[flat // len(xy)], xy[flat % len(xy)]
        facing = next((t for c, t in ranked if c.relation == "face to"), None)
        if facing is None:
            yaws = np.full(len(xy), obj.yaw)
        else:
            goal = self.box(facing).centre[:2]
            yaws = np.array([yaw_towards(p, goal) for p in xy])
        centres = np.column_stack([xy, np.broadcast_to(heights, len(xy))])
        boxes = Boxes.at(centres, rotated_half(item.half, item.tilt, yaws), yaws)

        sat = [rel.holds(c.relation, boxes, self.box(t)) for c, t in item.own]
        sat += [rel.holds(c.relation, self.box(s), boxes) for c, s in item.reverse]
        ok = np.logical_and.reduce(sat) if sat else np.ones(len(xy), dtype=bool)
        return centres, yaws, boxes, sat, ok, self.inside(boxes)

    def inside(self, boxes: Boxes) -> np.ndarray:
        if self.bounds is None:
            return np.ones(boxes.lo.shape[0], dtype=bool)
        return np.all(boxes.lo[:, :2] >= -self.bounds - rel.EPS, axis=1) & np.all(
            boxes.hi[:, :2] <= self.bounds + rel.EPS, axis=1
        )

    def explain(self, item: _Item, boxes: Boxes, sat, ok, inside) -> _Failure:
        """Why no candidate satisfied the constraints and bounds, and the nearest miss."""
        pairs = [(c, self.box(t), None) for c, t in item.own] + [(c, None, self.box(s)) for c, s in item.reverse]
        never = [c for (c, _, _), s in zip(pairs, sat) if not s.any()]
        # A constraint that fails here may only fail among the primary's candidates: ask its own.
        never = [c for c in never if not self.alone(item, c)]
        if never:
            reason = "no candidate position satisfies " + "; ".join(f"'{c}'" for c in never)
            failed = never
        elif ok.any():
            w, d = self.bounds * 2
            reason = f"every position satisfying its constraints lies outside the {w:g} x {d:g} m bounds"
            failed = [c for c, _, _ in pairs]
        else:
            reason = "its constraints cannot all hold at once"
            failed = [c for c, _, _ in pairs]
        misses = [
            rel.violations(c.relation, boxes, tb) if tb is not None else rel.violations(c.relation, sb, boxes)
            for c, tb, sb in pairs
        ]
        total = np.sum(misses, axis=0) + (0.0 if self.bounds is None else self.outside_by(boxes))
        k = int(np.argmin(total))
        p = boxes.centre[k]
        detail = [
            f"'{c}' {rel.describe(c.relation, float(m[k]))}" for (c, _, _), m in zip(pairs, misses) if m[k] > 0
        ]
        if self.bounds is not None and self.outside_by(boxes)[k] > 0:
            detail.append(f"outside the bounds by {self.outside_by(boxes)[k]:.2f} m")
        nearest = f"at ({p[0]:.2f}, {p[1]:.2f}, {p[2]:.2f}): " + ("; ".join(detail) or "all constraints hold")
        return _Failure(reason, failed, nearest)

    def alone(self, item: _Item, constraint: Constraint) -> bool:
        """Whether ``constraint`` on its own has a candidate inside the bounds."""
        own = [(c, t) for c, t in item.own if c is constraint]
        if not own:
            return False  # a fixed object's constraint on this one: no generator of its own
        return self.feasible(replace(item, own=own, reverse=[]))

    def outside_by(self, boxes: Boxes) -> np.ndarray:
        over = np.maximum(boxes.hi[:, :2] - self.bounds, 0.0) + np.maximum(-self.bounds - boxes.lo[:, :2], 0.0)
        return over.max(axis=1)

    def next_free(self, node: _Node) -> int | None:
        """The next candidate of ``node`` that collides with nothing placed, if any."""
        i = node.item.index
        while node.cursor < len(node.centres):
            k = node.cursor
            node.cursor += 1
            if k % CHUNK == 0:  # broad phase for the next chunk of candidates
                node.hits = self.world.overlaps(node.columns, node.lo[k : k + CHUNK], node.hi[k : k + CHUNK])
            if any(np.linalg.norm(node.centres[k, :2] - p) < d for p, d in node.avoid):
                continue
            touching = node.columns[node.hits[k % CHUNK]]
            if len(touching) == 0:
                return k
            blockers = self.world.colliders(i, node.centres[k], float(node.yaws[k]), touching)
            if not blockers:
                return k
            node.conflict.update(blockers)
            node.blockers.update(blockers)
        return None

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
            known = [(c, t) for c, t in item.own if self.placed[t]]
            if self.placed[s] or (len(known) < 2 and self.bounds is None):
                continue
            if self.feasible(replace(item, own=known)):
                continue
            node.conflict.update(t for _, t in known if t != i)
            rest = replace(item, own=[(c, t) for c, t in known if t != i])
            if not self.feasible(rest):
                log.debug("%s cannot help %s: its other targets must move", self.objects[i].id, item.obj.id)
                return "hopeless"
            node.forward_rejects += 1
            log.debug("%s rejected: %s would have no position", self.objects[i].id, self.objects[s].id)
            return "reject"
        return "ok"

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
        return _Failure(reason, [c for c, _ in item.own] + [c for c, _ in item.reverse], nearest)


def solve(
    objects: Sequence[SceneObject],
    constraints: Iterable[Constraint | Mapping],
    *,
    meshes: Mapping[str, trimesh.Trimesh] | None = None,
    bounds: tuple[float, float] | None = None,
    fixed: Iterable[str] = (),
    time_limit: float = 10.0,
    node_limit: int | None = None,
    seed: int = 0,
    use_solver: bool = True,
) -> LayoutResult:
    """Place every object the constraints allow, collision-free, inside ``bounds`` (W, D).

    Unplaced objects keep their initial pose and are explained in the report. ``fixed`` ids
    keep their pose and count as placed. ``use_solver=False`` keeps every initial pose and
    only reports which objects violate their constraints, collide or leave the bounds.
    """
    start = time.perf_counter()
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
    cleaned, dropped = clean_constraints(objects, constraints)
    if not use_solver:
        search = _Search(objects, cleaned, meshes, bounds, fixed, seed)
        report = _audit(search, objects, cleaned, meshes)
    else:
        search, report = _restarts(objects, cleaned, meshes, bounds, fixed, seed, start, time_limit, node_limit)
    report.dropped = dropped
    report.seconds = round(time.perf_counter() - start, 4)
    placed = set(report.placed)
    solved = []
    for i, o in enumerate(objects):
        if o.id in placed and use_solver:
            p, y = search.pos[i], float(search.yaw[i])
            o = o.model_copy(
                update={"position": Vec3.of(p), "rotation": Vec3(x=o.rotation.x, y=o.rotation.y, z=y)}
            )
        else:
            o = o.model_copy(deep=True)
        solved.append(o)
    log.info(
        "layout: %d placed, %d unplaced, %d nodes, %.3fs",
        len(report.placed), len(report.unplaced), report.nodes, report.seconds,
    )
    return LayoutResult(solved, cleaned, report)


def _restarts(objects, constraints, meshes, bounds, fixed, seed, start, time_limit, node_limit):
    """Run the search up to :data:`RESTARTS` times until one places everything; keep the best.

    Every run but the last has a node budget proportional to the object count. A rerun puts
    the objects that gave trouble (left unplaced, or forced backjumps) and everything they
    depend on first — the "squeaky wheel": placed while the scene is still empty, they fit
    — and scatters the other starting anchors a little more each time.
    """
    best = None
    used = 0
    deadline = start + time_limit
    trouble: set[int] = set()
    for attempt in range(RESTARTS):
        search = _Search(objects, constraints, meshes, bounds, fixed, seed + attempt, spread=0.15 * attempt)
        budget = None if node_limit is None else node_limit - used
        stop = deadline
        if attempt < RESTARTS - 1:
            share = 10 * len(objects) + 100
            budget = share if budget is None else min(budget, share)
            now = time.perf_counter()
            stop = now + (deadline - now) / (RESTARTS - attempt)
        report, troubled = _dfs(search, stop, budget, first=search.ancestors(trouble))
        trouble |= troubled
        used += report.nodes
        if best is None or len(report.placed) > len(best[1].placed):
            best = (search, report)
        out_of_budget = node_limit is not None and used >= node_limit
        if report.complete or out_of_budget or time.perf_counter() > deadline:
            break
        log.info("layout attempt %d left %d unplaced; restarting", attempt + 1, len(report.unplaced))
    best[1].nodes = used
    return best


def _dfs(
    search: _Search, deadline: float, node_limit: int | None, first: set[int] = frozenset()
) -> tuple[LayoutReport, set[int]]:
    """One depth-first search; also returns the objects that gave trouble.

    Objects in ``first`` are placed before the rest (as far as the order allows); among the
    others, larger footprints go first.
    """
    free = [o.id for i, o in enumerate(search.objects) if i not in search.fixed]
    rank = {o.id: (i not in first, -o.size.x * o.size.y) for i, o in enumerate(search.objects)}
    own = [c for item in search.items.values() for c, _ in item.own]
    order = [search.index[x] for x in topological_order(free, own, key=rank.get)]
    nodes: list[_Node | None] = [None] * len(order)
    failures: dict[int, _Failure] = {}
    depth_of: dict[int, int] = {}
    jumps: Counter = Counter()
    count = 0
    limited = False
    depth = 0

    def place(i: int, centre, yaw) -> None:
        nonlocal depth
        search.put(i, centre, yaw)
        depth_of[i] = depth
        depth += 1

    while depth < len(order):
        if not limited and (
            time.perf_counter() > deadline or (node_limit is not None and count >= node_limit)
        ):
            limited = True
            log.info("layout search limit reached after %d nodes; finishing greedily", count)
        i = order[depth]
        node = nodes[depth]
        fallback = None  # a free pose that only failed forward checking
        if node is None:
            made = search.candidates(search.items[i])
            if isinstance(made, _Failure):
                # Its targets' poses decide its candidates: they are the conflict set.
                conflict, failure = {t for c, t in search.items[i].own if search.placed[t]}, made
            else:
                node = nodes[depth] = made
        if node is not None:
            k = search.next_free(node)
            verdict = "ok"
            while k is not None:
                search.put(i, node.centres[k], float(node.yaws[k]))
                count += 1
                verdict = "ok" if limited else search.forward_check(i, node)
                search.take(i)
                if verdict == "ok":
                    break
                fallback = k if fallback is None else fallback
                if verdict == "hopeless" or node.forward_rejects >= FORWARD_REJECTS:
                    k = None
                    break
                k = search.next_free(node)
            if k is not None:
                place(i, node.centres[k], float(node.yaws[k]))
                continue
            # Its targets, and theirs, shaped its candidates, so they share the blame.
            conflict, failure = node.conflict | search.ancestors({i}) - {i}, None
        culprits = {j for j in conflict if j in depth_of and search.placed[j]}
        if limited or not culprits or jumps[i] >= MAX_JUMPS:
            if fallback is not None:  # the dependents will report their own failure
                place(i, node.centres[fallback], float(node.yaws[fallback]))
            else:
                failures[i] = failure or search.blocked(node, limited)
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
            if search.placed[x]:
                search.take(x)
                depth_of.pop(x, None)
            failures.pop(x, None)
            if d > back:
                nodes[d] = None
        nodes[depth] = None
        half = half_extents(search.objects[i].size, search.objects[i].rotation)
        target = nodes[back]
        assert target is not None, "a placed object has its node"
        target.conflict |= culprits - {j}
        # Move the culprit clear of where it was, farther each time this object fails.
        reach = max(0.15, float(max(half[0], half[1]))) * jumps[i]
        target.avoid.append((search.pos[j][:2].copy(), reach))
        depth = back
    count += _repair(search, order, failures)
    placed = [o.id for i, o in enumerate(search.objects) if search.placed[i]]
    unplaced = [
        UnplacedObject(id=search.objects[i].id, failed=f.failed, reason=f.reason, nearest_miss=f.nearest)
        for i, f in sorted(failures.items(), key=lambda kv: order.index(kv[0]))
    ]
    troubled = set(failures) | {i for i, n in jumps.items() if n}
    return LayoutReport(placed=placed, unplaced=unplaced, nodes=count, solver=True), troubled


def _repair(search: _Search, order: list[int], failures: dict[int, _Failure]) -> int:
    """Retry each unplaced object, in order, over a wide candidate set; returns nodes used."""
    count = 0
    for i in [x for x in order if x in failures]:
        made = search.candidates(search.items[i], wide=True)
        if isinstance(made, _Failure):
            failures[i] = made
            continue
        k = search.next_free(made)
        if k is None:
            failures[i] = search.blocked(made, limited=False)
            continue
        search.put(i, made.centres[k], float(made.yaws[k]))
        del failures[i]
        count += 1
    return count


def _audit(search: _Search, objects, constraints, meshes) -> LayoutReport:
    """The ablation: keep every initial pose, report what it gets wrong."""
    collisions: dict[str, list[str]] = {}
    for a, b in colliding_pairs(objects, meshes, constraints):
        collisions.setdefault(a, []).append(b)
        collisions.setdefault(b, []).append(a)
    by_id = {o.id: o for o in objects}
    placed, unplaced = [], []
    for o in objects:
        failed = [c for c in constraints if c.source == o.id and not rel.check(c.relation, o, by_id[c.target])]
        problems = []
        if failed:
            problems.append("initial pose violates " + "; ".join(f"'{c}'" for c in failed))
        if o.id in collisions:
            problems.append(f"initial pose collides with {', '.join(collisions[o.id])}")
        lo, hi = world_box(o)
        if search.bounds is not None and not search.inside(Boxes(lo[None], hi[None], np.array([o.yaw])))[0]:
            problems.append("initial pose leaves the bounds")
        if problems:
            unplaced.append(UnplacedObject(id=o.id, failed=failed, reason="; ".join(problems)))
        else:
            placed.append(o.id)
    return LayoutReport(placed=placed, unplaced=unplaced, nodes=0, solver=False)
