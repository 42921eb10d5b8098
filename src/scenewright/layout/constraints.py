"""The paper's authoring rules applied to a constraint list before solving.

Models write constraints that repeat themselves, point at themselves, name objects that do
not exist, use relations outside Table 3, or contradict the acyclic rule. None of that is a
crash: each bad entry is dropped and reported (:class:`~scenewright.scene.DroppedConstraint`)
so the report can go back to the model. Cycles are broken deterministically: constraints are
admitted by relation priority (vertical first, then relative, then the rest) and then input
order, and one that would close a cycle is dropped.

Only positional relations make cycles. ``face to`` turns its source and places nothing, so
two chairs facing each other, or a couple at a table, is satisfiable: a ``face to`` orders
placement (target first) where it can, and where it would close a cycle it is kept without
ordering anything; the solver then turns its source when the target is placed.
"""

from __future__ import annotations

import heapq
import logging
from typing import Any, Callable, Collection, Iterable, Mapping, Sequence

from pydantic import ValidationError

from scenewright.core.relations import PRIORITY
from scenewright.scene import (
    ROOM_RELATIONS,
    Constraint,
    DroppedConstraint,
    Room,
    SceneObject,
    describe_validation_error,
    room_target,
)

log = logging.getLogger(__name__)


def _as_dict(c: Constraint | Mapping[str, Any]) -> dict[str, Any]:
    return c.model_dump() if isinstance(c, Constraint) else dict(c)


def room_problem(c: Constraint, room: Room | None, ids: Collection[str]) -> str | None:
    """Why a constraint's room side is wrong (None when it is right): a room relation must name
    the room (``room``, ``ceiling``, ``wall_<i>``) of a scene that has one, and only room
    relations may."""
    named = room_target(c.target) if c.target not in ids else None
    if c.relation not in ROOM_RELATIONS:
        return None if named is None else f"'{c}': only {', '.join(ROOM_RELATIONS)} relate to the room"
    if room is None:
        return f"'{c}' needs a room, and this scene has none (an open scene; try --room auto or WxD)"
    walls = len(room.floor)
    ceiling = c.relation == "on ceiling"
    if isinstance(named, int):
        fits = not ceiling and named < walls
    else:
        fits = named == "room" or (named == "ceiling" and ceiling)
    if not fits:
        return (f"'{c}': the target of '{c.relation}' must be "
                + ("'ceiling' or 'room'" if c.relation == "on ceiling" else f"'room' or one of wall_0 .. wall_{walls - 1}"))
    return None


def clean_constraints(
    objects: Sequence[SceneObject], constraints: Iterable[Constraint | Mapping[str, Any]], room: Room | None = None
) -> tuple[list[Constraint], list[DroppedConstraint]]:
    """Valid, unique, acyclic constraints in input order, and every dropped one with why.
    Room relations are kept when ``room`` is given and they name a part of it."""
    ids = {o.id for o in objects}
    kept: list[Constraint] = []
    dropped: list[DroppedConstraint] = []
    seen: set[tuple[str, str, str]] = set()

    def drop(raw, reason: str) -> None:
        entry = _as_dict(raw) if isinstance(raw, (Constraint, Mapping)) else {"value": repr(raw)}
        dropped.append(DroppedConstraint(constraint=entry, reason=reason))
        log.warning("constraint dropped: %s", reason)

    for raw in constraints:
        if isinstance(raw, Constraint):
            c = raw
        elif isinstance(raw, Mapping):
            try:
                c = Constraint.model_validate(dict(raw))
            except ValidationError as exc:
                drop(raw, f"invalid constraint: {describe_validation_error(exc)}")
                continue
        else:
            drop(raw, f"a constraint must be an object with relation, source and target, got {raw!r}")
            continue
        wrong = room_problem(c, room, ids)
        unknown = [x for x in (c.source, c.target) if x not in ids and not (x == c.target and c.relation in ROOM_RELATIONS)]
        if wrong is not None:
            drop(c, wrong)
        elif unknown:
            names = ", ".join(map(repr, unknown))
            drop(c, f"'{c}' names unknown object {names}; objects are: {', '.join(sorted(ids))}")
        elif c.source == c.target:
            drop(c, f"'{c}' relates an object to itself")
        elif c.key() in seen:
            drop(c, f"'{c}' is a duplicate")
        else:
            seen.add(c.key())
            kept.append(c)
    acyclic, cyclic = break_cycles(kept)
    for c, path in cyclic:
        drop(c, f"'{c}' would make a cycle ({' -> '.join(path)}, each placed relative to the next); "
             "constraints must be acyclic")
    return acyclic, dropped


def break_cycles(
    constraints: list[Constraint], first: Collection[tuple[str, str, str]] = ()
) -> tuple[list[Constraint], list[tuple[Constraint, list[str]]]]:
    """Admit constraints by (priority, input order); drop a positional one whose target depends on
    its source, with the path that makes the cycle. Keys in ``first`` are admitted before all
    others: an edit's new constraints win over the old ones they contradict. ``face to`` is never
    dropped (see the module docstring)."""
    ordering, cyclic = _admit(constraints, first)
    keep = ordering | {i for i, c in enumerate(constraints) if c.relation == "face to"}
    dropped = [(c, path) for i, c, path in cyclic if c.relation != "face to"]
    return [c for i, c in enumerate(constraints) if i in keep], dropped


def _admit(
    constraints: Sequence[Constraint], first: Collection[tuple[str, str, str]] = ()
) -> tuple[set[int], list[tuple[int, Constraint, list[str]]]]:
    """Indices of the constraints that order placement, and the ones that would close a cycle
    (with its path). Positional relations are admitted first, ``face to`` last, so a facing
    never costs a positional constraint its place."""
    graph = PlacementGraph()
    admitted: set[int] = set()
    cyclic: list[tuple[int, Constraint, list[str]]] = []
    ranked = sorted(
        range(len(constraints)),
        key=lambda i: (
            constraints[i].key() not in first,
            constraints[i].relation == "face to",
            PRIORITY[constraints[i].relation],
            i,
        ),
    )
    for i in ranked:
        c = constraints[i]
        cycle = graph.cycle(c.source, c.target)
        if cycle is not None:
            cyclic.append((i, c, cycle))
            continue
        graph.add(c.source, c.target)
        admitted.add(i)
    return admitted, cyclic


class PlacementGraph:
    """Who is placed relative to whom, grown one relation at a time; the one place that says
    whether a relation would close a cycle (the layout's cleaning and the parser both ask it)."""

    def __init__(self) -> None:
        self._after: dict[str, set[str]] = {}  # target -> sources: the target is placed first

    def cycle(self, source: str, target: str) -> list[str] | None:
        """The cycle ``source -> target -> ... -> source`` (each placed relative to the next)
        that placing ``source`` relative to ``target`` would close, or ``None``."""
        path = _path(self._after, source, target)
        return None if path is None else [source] + path[::-1]

    def add(self, source: str, target: str) -> None:
        self._after.setdefault(target, set()).add(source)


def _path(after: dict[str, set[str]], start: str, goal: str) -> list[str] | None:
    """A path start -> ... -> goal along the placement edges, if one exists."""
    stack = [(start, [start])]
    seen = {start}
    while stack:
        node, path = stack.pop()
        if node == goal:
            return path
        for nxt in sorted(after.get(node, ())):
            if nxt not in seen:
                seen.add(nxt)
                stack.append((nxt, path + [nxt]))
    return None


def topological_order(
    ids: Sequence[str], constraints: Sequence[Constraint], key: Callable[[str], Any] | None = None
) -> list[str]:
    """Every target before its sources; among ready objects, smallest ``key`` first.

    ``constraints`` must have acyclic positional relations (as :func:`clean_constraints` returns
    them); a ``face to`` that would close a cycle orders nothing. Constraints naming ids outside
    ``ids`` are ignored.
    """
    index = {x: i for i, x in enumerate(ids)}
    inside = [c for c in constraints if c.source in index and c.target in index]
    ordering, cyclic = _admit(inside)
    assert all(c.relation == "face to" for _, c, _ in cyclic), "topological_order needs acyclic constraints"
    constraints = [c for i, c in enumerate(inside) if i in ordering]
    rank = key or index.__getitem__
    indegree = {x: 0 for x in ids}
    after: dict[str, list[str]] = {x: [] for x in ids}
    for c in constraints:
        after[c.target].append(c.source)
        indegree[c.source] += 1
    ready = [(rank(x), index[x], x) for x in ids if indegree[x] == 0]
    heapq.heapify(ready)
    order = []
    while ready:
        _, _, x = heapq.heappop(ready)
        order.append(x)
        for s in after[x]:
            indegree[s] -= 1
            if indegree[s] == 0:
                heapq.heappush(ready, (rank(s), index[s], s))
    assert len(order) == len(ids), "topological_order needs acyclic constraints"
    return order
