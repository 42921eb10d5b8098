"""Distribution: the reader's group-level relations as relations between single objects
("each", "around", "on either side", opposite), then made acyclic and ordered for the solver.
"""

from __future__ import annotations

import logging
import re
from collections import Counter
from dataclasses import replace

from scenewright.analysis.parser.model import ParsedRelation
from scenewright.analysis.parser.nouns import _Group
from scenewright.analysis.parser.reader import _Reader

log = logging.getLogger(__name__)


def _ids(groups: list[_Group]) -> None:
    """``chair_1``, ``chair_2``...; a guessed thing by its own name (``fuel_tank_1``, not ``tank_1``)."""
    counters: Counter[str] = Counter()
    for g in groups:
        base = (re.sub(r"[^a-z0-9]+", "_", g.name.lower()).strip("_") or g.category) if g.guessed else g.category
        for _ in range(g.count):
            counters[base] += 1
            g.ids.append(f"{base}_{counters[base]}")


def _around_sides(n: int, src: _Group, tgt: _Group) -> list[str]:
    """Which side of the target each of ``n`` surrounding objects takes: long sides first."""
    tx, ty, _ = tgt.size
    width = max(src.size[0], 0.3) + 0.15
    if tx >= 1.4 * ty:
        first, short = ["in front of", "behind"], ["left of", "right of"]
        long_cap, short_cap = max(1, int(tx // width)), max(1, int(ty // width))
    elif ty >= 1.4 * tx:
        first, short = ["left of", "right of"], ["in front of", "behind"]
        long_cap, short_cap = max(1, int(ty // width)), max(1, int(tx // width))
    else:
        first, short = ["left of", "right of"], ["in front of", "behind"]
        long_cap = short_cap = max(1, int(max(tx, ty) // width))
    # every side once (four chairs take four sides), then the long sides fill up first
    order = first + short + first * (long_cap - 1) + short * (short_cap - 1)
    if n < 4:
        order = first + short
    return [order[i % len(order)] for i in range(n)]


def _instance_pairs(src: _Group, tgt: _Group, paired: bool) -> list[tuple[str, str]]:
    n, m = len(src.ids), len(tgt.ids)
    if paired or (n == m and n > 1):
        return [(src.ids[i], tgt.ids[i % m]) for i in range(n)]
    return [(s, tgt.ids[i % m]) for i, s in enumerate(src.ids)]


def _expand(reader: _Reader) -> list[ParsedRelation]:
    out: list[ParsedRelation] = []
    groups = reader.groups
    for kind, s, t, instance in reader.relations:
        src, tgt = groups[s], groups[t]
        paired = (s, t) in reader.pair_each or (t, s) in reader.pair_each
        if s == t:  # "facing each other": the later ones face the first
            if kind == "face to" and len(src.ids) > 1:
                out += [ParsedRelation(i, "face to", src.ids[0]) for i in src.ids[1:]]
            continue
        if instance is not None:
            tgt = replace(tgt, ids=[tgt.ids[instance]])
        pairs = _instance_pairs(src, tgt, paired)
        if kind == "opposite":
            for a, b in pairs:
                out += [ParsedRelation(a, "in front of", b), ParsedRelation(a, "face to", b)]
        elif kind == "flank":
            for i, (a, _) in enumerate(pairs):
                out.append(ParsedRelation(a, ("left of", "right of")[i % 2], tgt.ids[(i // 2) % len(tgt.ids)]))
        elif kind == "around" and len(src.ids) == 1:  # one round ottoman "surrounds" a palm: it is near
            out += [ParsedRelation(src.ids[0], "near", b) for b in tgt.ids[:1]]
        elif kind == "around":
            # paired ("each surrounded by two chairs"): each target's sides go to its own share
            per = len(tgt.ids) if paired else 1
            sides = _around_sides(-(-len(src.ids) // per), src, tgt)
            for i, a in enumerate(src.ids):
                b = tgt.ids[i % len(tgt.ids)]
                out += [ParsedRelation(a, sides[i // per], b), ParsedRelation(a, "face to", b)]
        elif kind == "under flat":
            for a, b in pairs:
                out.append(ParsedRelation(b, "on", a))
        elif kind in ("left of", "right of", "in front of", "behind", "side of", "near", "far", "on", "above", "face to"):
            out += [ParsedRelation(a, kind, b) for a, b in pairs]
    return out


def _acyclic(relations: list[ParsedRelation], ids: list[str]) -> list[ParsedRelation]:
    """Drop duplicates and any relation that would close a cycle (later and inferred ones go
    first), then order them so that an object is placed before it serves as a target."""
    seen: set[tuple[str, str, str]] = set()
    kept: list[ParsedRelation] = []
    edges: dict[str, set[str]] = {i: set() for i in ids}  # source → targets

    def reaches(a: str, b: str) -> bool:
        stack, visited = [a], set()
        while stack:
            x = stack.pop()
            if x == b:
                return True
            if x in visited:
                continue
            visited.add(x)
            stack.extend(edges.get(x, ()))
        return False

    for r in sorted(relations, key=lambda r: r.inferred):
        key = (r.source, r.relation, r.target)
        if key in seen or r.source == r.target or r.source not in edges or r.target not in edges:
            continue
        if reaches(r.target, r.source):
            log.debug("dropping %s %s %s: it would close a cycle", r.source, r.relation, r.target)
            continue
        # one vertical support per object
        if r.relation in ("on", "above") and any(
            k.source == r.source and k.relation in ("on", "above") for k in kept
        ):
            continue
        seen.add(key)
        kept.append(r)
        edges[r.source].add(r.target)
    depth: dict[str, int] = {}

    def level(x: str) -> int:
        if x not in depth:
            depth[x] = 0
            depth[x] = 1 + max((level(t) for t in edges[x]), default=-1)
        return depth[x]

    order = {i: n for n, i in enumerate(ids)}
    return sorted(kept, key=lambda r: (level(r.source), order[r.source]))
