"""Distribution: the reader's group-level relations as relations between single objects
("each", "around", "on either side", opposite), then made acyclic and ordered for the solver.
"""

from __future__ import annotations

import logging
import re
import unicodedata
from collections import Counter
from dataclasses import replace

from scenewright.analysis.parser.grammar import _SEATS
from scenewright.analysis.parser.model import ParsedRelation
from scenewright.analysis.parser.nouns import _Group
from scenewright.analysis.parser.reader import _Reader
from scenewright.layout.constraints import PlacementGraph

log = logging.getLogger(__name__)


def _ids(groups: list[_Group], listed: dict[int, list[int]]) -> None:
    """``chair_1``, ``chair_2``...; a guessed thing by its own name (``fuel_tank_1``, not ``tank_1``).
    A plural whose members are listed is theirs: what the text says of it, it says of them."""
    counters: Counter[str] = Counter()
    for g in groups:
        if g.index in listed:
            continue
        # (accents folded: "café" is cafe_1, not caf_1)
        plain = unicodedata.normalize("NFKD", g.name.lower()).encode("ascii", "ignore").decode()
        base = (re.sub(r"[^a-z0-9]+", "_", plain).strip("_") or g.category) if g.guessed else g.category
        for _ in range(g.count):
            counters[base] += 1
            g.ids.append(f"{base}_{counters[base]}")
    for g, members in listed.items():
        groups[g].ids = [i for m in members for i in groups[m].ids]


def _around_sides(n: int, src: _Group, tgt: _Group, corners: bool) -> list[tuple[str, ...]]:
    """Which sides of the target each of ``n`` surrounding objects takes: long sides first. Fewer
    than four ("two children run around the well", "three dogs sit around her", "three chairs
    around the campfire") stand so that between them they are on every side, the first ones at
    corners (on two sides at once); seats at a table keep one side each, pulled up to it."""
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
    if n < 4 and corners:
        return [(first[0], short[0]), (first[1], short[1]) if n == 2 else (first[1],), (short[1],)][:n]
    if n < 4:
        order = first + short
    return [(order[i % len(order)],) for i in range(n)]


def _singles(reader: _Reader, kind: str) -> dict[int, list[int]]:
    """Target group → the groups of one thing each the text relates to all of it by ``kind``, in
    the order named (a plural keeps its own share: "toadstools and crystals around it")."""
    out: dict[int, list[int]] = {}
    for k, s, t, instance in reader.relations:
        if k == kind and instance is None and len(reader.groups[s].ids) == 1 and s not in out.get(t, []):
            out.setdefault(t, []).append(s)
    return out


def _rings(reader: _Reader) -> dict[tuple[int, int], tuple[int, list[tuple[str, ...]]]]:
    """Several single things around one thing ("a knight, an elf and a dwarf sit around the fire")
    share its sides as one group would: (source, target) → where the source stands in the ring,
    and the sides of the whole ring."""
    out: dict[tuple[int, int], tuple[int, list[tuple[str, ...]]]] = {}
    for t, sources in _singles(reader, "around").items():
        tgt, first = reader.groups[t], reader.groups[sources[0]]
        if len(sources) < 2 or len(tgt.ids) != 1:
            continue
        seat_at = reader.catalogue[first.category].shape in _SEATS and reader.catalogue[tgt.category].support
        sides = _around_sides(len(sources), first, tgt, corners=not seat_at)
        out.update(((s, t), (k, sides)) for k, s in enumerate(sources))
    return out


def _one_each(reader: _Reader) -> dict[tuple[int, int], int]:
    """Single things put on a group of as many ("the king and the queen sit on their thrones"):
    (source, target) → which member of the target each is on."""
    return {
        (s, t): k for t, sources in _singles(reader, "on").items()
        if 1 < len(sources) <= len(reader.groups[t].ids) for k, s in enumerate(sources)
    }  # fmt: skip


def _instance_pairs(src: _Group, tgt: _Group, paired: bool) -> list[tuple[str, str]]:
    n, m = len(src.ids), len(tgt.ids)
    if paired and m > n and m % n == 0:  # "each pair pulling a plough": a plough to each pair
        unit = m // n
        return [(src.ids[i], tgt.ids[i * unit + j]) for i in range(n) for j in range(unit)]
    if paired or (n == m and n > 1):
        return [(src.ids[i], tgt.ids[i % m]) for i in range(n)]
    return [(s, tgt.ids[i % m]) for i, s in enumerate(src.ids)]


#: The sides that put a thing between two others, by how the two stand to each other.
_BETWEEN_SIDES = {
    "left of": ("left of", "right of"), "right of": ("right of", "left of"),
    "in front of": ("in front of", "behind"), "behind": ("behind", "in front of"),
}  # fmt: skip


#: Relations that put a pair front to back, read as "in front of" when choosing between's axis.
_FACING = {"opposite": "in front of", "face to": "in front of", "at seat": "in front of"}


def _pair_axis(reader: _Reader, a: str, b: str) -> tuple[str, str]:
    """The sides of ``a`` and ``b`` that put a thing between them, along the axis the text stands
    the pair on: front to back when one is in front of (or facing) the other, else left to right."""
    for kind, s, t, _ in reader.relations:
        ids_s, ids_t = reader.groups[s].ids, reader.groups[t].ids
        if kind == "face to" and s == t and a in ids_s and b in ids_s:  # two sofas facing each other
            return "behind", "in front of"
        kind = _FACING.get(kind, kind)  # a TV opposite the sofa: the pair stands front to back
        if kind in _BETWEEN_SIDES and a in ids_s and b in ids_t:  # a left of b: x right of a, left of b
            first, second = _BETWEEN_SIDES[kind]
            return second, first
        if kind in _BETWEEN_SIDES and b in ids_s and a in ids_t:
            return _BETWEEN_SIDES[kind]
    return "right of", "left of"


def _between(
    reader: _Reader, src: _Group, a: str, b: str, sides: tuple[str, str] | None = None
) -> list[ParsedRelation]:
    """"A bin between the machine and the stall": the centre in the gap, as a side of each (right
    of one, left of the other) along ``sides`` or the axis the pair already stands on
    (:func:`_pair_axis`), and near both."""
    sides = sides or _pair_axis(reader, a, b)
    out = []
    host = _common_host(reader, src, a, b)
    for x in src.ids:
        out += [ParsedRelation(x, sides[0], a), ParsedRelation(x, sides[1], b)]
        out += [ParsedRelation(x, "near", a), ParsedRelation(x, "near", b)]
        if host is not None:  # "on its veranda a hermit and a monk sit, a kettle between them": on it too
            out.append(ParsedRelation(x, "on", host, inferred=True))
    return out


def _common_host(reader: _Reader, src: _Group, a: str, b: str) -> str | None:
    """The one thing both ends of a *between* rest on, when the thing between them rests on nothing
    of its own: where it stands too."""
    group_of = {i: g.index for g in reader.groups for i in g.ids}
    on = [(s, t) for kind, s, t, _ in reader.relations if kind == "on"]
    if any(s == src.index for s, _ in on):
        return None
    hosts = [{t for s, t in on if s == group_of.get(end)} for end in (a, b)]
    common = hosts[0] & hosts[1]
    if len(common) != 1:
        return None
    host = reader.groups[common.pop()]
    return host.ids[0] if len(host.ids) == 1 else None


def _expand(reader: _Reader) -> list[ParsedRelation]:
    """Group relations as object relations. A stack stands where its bottom stands: the others
    only rest on the one below, which the composition writes from the ``stack`` formation (one
    thing said once, not relations the text states between its members)."""
    out = _expand_relations(reader)
    # ("three stacks of crates": the first three are the feet of three stacks)
    feet = {g: reader.lines.get(g, 1) for g, f in reader.formations.items() if f == "stack"}
    upper = {i for g, n in feet.items() for i in reader.groups[g].ids[n:]}
    return [r for r in out if r.source not in upper]


def _expand_relations(reader: _Reader) -> list[ParsedRelation]:
    out: list[ParsedRelation] = []
    groups = reader.groups
    betweens: dict[int, list[tuple[int, int | None]]] = {}
    for kind, s, t, instance in reader.relations:
        if kind == "between":
            betweens.setdefault(s, []).append((t, instance))
    for s, targets in betweens.items():
        ends = [
            groups[t].ids[i] if i is not None else groups[t].ids[0] for t, i in targets
        ]  # "between the machine and the stall"
        sides = None
        if len(targets) == 1 and len(groups[targets[0][0]].ids) >= 2 and targets[0][1] is None:
            ids = groups[targets[0][0]].ids
            lines = reader.lines.get(targets[0][0], 1) if targets[0][0] in reader.rows_named else 1
            per = -(-len(ids) // lines)
            # "between the two trees", "between them"; "walks between the rows": behind the first
            # member of the front row, in front of the first of the next
            ends, sides = (ids[:2], None) if lines < 2 else ([ids[0], ids[per]], ("behind", "in front of"))
        if len(ends) >= 2:
            out += _between(reader, groups[s], ends[0], ends[1], sides)
        else:
            out += [ParsedRelation(x, "near", ends[0]) for x in groups[s].ids]
    ring, seat = _rings(reader), _one_each(reader)
    for kind, s, t, instance in reader.relations:
        src, tgt = groups[s], groups[t]
        paired = (s, t) in reader.pair_each or (t, s) in reader.pair_each
        if s == t:  # "facing each other", "across from each other": the later ones face the first
            if kind == "face to" and len(src.ids) > 1:
                out += [ParsedRelation(i, "face to", src.ids[0]) for i in src.ids[1:]]
            if kind == "opposite" and len(src.ids) > 1:
                out += [ParsedRelation(i, r, src.ids[0]) for i in src.ids[1:] for r in ("in front of", "face to")]
            if kind == "side of":  # "side by side": each beside the one before
                out += [ParsedRelation(b, "side of", a) for a, b in zip(src.ids, src.ids[1:])]
            continue
        if instance is not None:
            tgt = replace(tgt, ids=[tgt.ids[instance]])
        elif reader.formations.get(t) == "stack":
            # a pile is one thing to what is put by it: gulls above a pile of boxes, a cat on top of it
            tgt = replace(tgt, ids=[tgt.ids[-1] if kind == "on" else tgt.ids[0]])
        elif kind in ("left of", "right of") and reader.formations.get(t) == "row" and len(src.ids) < len(tgt.ids):
            # "a change machine to the right of them" (a row): beside the row's end, not its first
            tgt = replace(tgt, ids=[tgt.ids[-1] if kind == "right of" else tgt.ids[0]])
        elif kind in _BETWEEN_SIDES and len(src.ids) == 1 and len(tgt.ids) > 1 and not paired:
            # "a cottage behind the boats": behind all of them, not the first while the rest stand anywhere
            out += [ParsedRelation(src.ids[0], kind, b) for b in tgt.ids]
            continue
        pairs = _instance_pairs(src, tgt, paired)
        if kind == "opposite":
            for a, b in pairs:
                out += [ParsedRelation(a, "in front of", b), ParsedRelation(a, "face to", b)]
        elif kind == "at seat":  # a chair at a desk: pulled up to its front, facing it
            for a, b in pairs:
                out += [ParsedRelation(a, "in front of", b), ParsedRelation(a, "face to", b), ParsedRelation(a, "near", b)]
        elif kind == "flank":
            for i, (a, _) in enumerate(pairs):
                out.append(ParsedRelation(a, ("left of", "right of")[i % 2], tgt.ids[(i // 2) % len(tgt.ids)]))
        elif kind == "on" and (s, t) in seat:  # "the king and queen watch from their thrones": a throne each
            out.append(ParsedRelation(src.ids[0], "on", tgt.ids[seat[s, t]]))
        elif kind == "around" and (s, t) in ring:  # "a knight, an elf and a dwarf sit around a fire": one ring
            place, sides = ring[s, t]
            out += [ParsedRelation(src.ids[0], side, tgt.ids[0]) for side in sides[place]]
            out.append(ParsedRelation(src.ids[0], "face to", tgt.ids[0]))
        elif kind == "around" and len(src.ids) == 1 and not (reader._living(s) or reader._carrier(s, ("vehicles",))):
            # one round ottoman "surrounds" a palm: it is near (a dog that runs around the tree, a
            # toy train that circles a chair, is at one side of it on its way, facing it, as one of
            # a group would be)
            out += [ParsedRelation(src.ids[0], "near", b) for b in tgt.ids[:1]]
        elif kind == "around":
            # paired ("each surrounded by two chairs"): each target's sides go to its own share
            per = len(tgt.ids) if paired else 1
            # (seats at a table or a desk are pulled up to a side each; around a fire or a well any way round)
            seat_at = reader.catalogue[src.category].shape in _SEATS and reader.catalogue[tgt.category].support
            sides = _around_sides(-(-len(src.ids) // per), src, tgt, corners=not seat_at)
            for i, a in enumerate(src.ids):
                b = tgt.ids[i % len(tgt.ids)]
                out += [ParsedRelation(a, side, b) for side in sides[i // per]] + [ParsedRelation(a, "face to", b)]
        elif kind in ("under flat", "in hand"):  # the target on the source: a table on its rug, a mop in hand
            for a, b in pairs:
                out.append(ParsedRelation(b, "on", a))
        elif kind == "under hung":  # "chairs under a ceiling fan": the fan above them
            for a, b in pairs:
                out.append(ParsedRelation(b, "above", a))
        elif kind in ("left of", "right of", "in front of", "behind", "side of", "near", "far", "on", "above", "face to"):
            out += [ParsedRelation(a, kind, b) for a, b in pairs]
    return out


def _acyclic(relations: list[ParsedRelation], ids: list[str]) -> list[ParsedRelation]:
    """Drop duplicates and any relation that would close a cycle (later and inferred ones go
    first), then order them so that an object is placed before it serves as a target."""
    seen: set[tuple[str, str, str]] = set()
    kept: list[ParsedRelation] = []
    edges: dict[str, set[str]] = {i: set() for i in ids}  # source → targets
    graph = PlacementGraph()

    for r in sorted(relations, key=lambda r: r.inferred):
        key = (r.source, r.relation, r.target)
        if key in seen or r.source == r.target or r.source not in edges or r.target not in edges:
            continue
        if graph.cycle(r.source, r.target) is not None:
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
        graph.add(r.source, r.target)
    depth: dict[str, int] = {}

    def level(x: str) -> int:
        if x not in depth:
            depth[x] = 0
            depth[x] = 1 + max((level(t) for t in edges[x]), default=-1)
        return depth[x]

    order = {i: n for n, i in enumerate(ids)}
    return sorted(kept, key=lambda r: (level(r.source), order[r.source]))
