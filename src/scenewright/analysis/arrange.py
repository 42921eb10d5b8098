"""Initial poses from a parse: a designed first guess the layout solver starts from.

The text's relations place what they name (``composition.relational``), one related group at
a time. Everything else follows placement priors, each a small named rule of
``composition``: functional groups first (each desk its chair, each bed its nightstands, a
lounge around its coffee table, a rug under its group), then outdoor arrangements (stalls
around a square or along a street), then the groups are set out compactly with the viewer's
side open, tall storage goes along the edges with its back outward, vehicles park along a
road, natural things are scattered with Poisson-disc spacing, and no set of ground objects is
left in a line. The solver searches candidates nearest these poses first, so the
composition is also its candidate order.

Groups with a member the text anchors to a wall ("a sofa at the back of the room") are recorded
(``Composition.anchored``): once the room is known the analysis stage moves each one there as a
whole (``composition.anchors``). Everything finally stands centred on the origin, where the room
is built around it.

The arrangement is deterministic for a given seed (only the scatter draws random numbers).
Rules may add relations (a sofa standing on the rug put under it); :func:`compose` returns
them with the poses, so the constraints written from the parse keep them.
"""

from __future__ import annotations

import random
from collections import defaultdict
from dataclasses import dataclass, replace

from scenewright.analysis.composition import (
    anchors, edges, formations, groups, hosts, mounts, outdoor, packing, posture, relational, roles, water,
)
from scenewright.analysis.composition.footprint import bbox
from scenewright.analysis.composition.lines import unline
from scenewright.analysis.composition.units import Layout, Unit
from scenewright.analysis.parser import ParsedRelation, ParsedScene
from scenewright.core.protocols import AnchoredGroup
from scenewright.scene import SceneObject


@dataclass
class Composition:
    """First poses for every object of a parse, and the relations they were made to satisfy:
    the parse's own, with inferred supports shared among instances and the priors' additions."""

    objects: list[SceneObject]
    relations: list[ParsedRelation]
    #: Groups to move as one to where the text anchors one of their members in the room
    #: (:func:`~scenewright.analysis.composition.anchors.into_room`, once the room is known).
    anchored: tuple[AnchoredGroup, ...] = ()
    #: The shore line's y when the scene lies by water (``composition.water``), the water beyond it.
    shore: float | None = None


#: Rules that join units into groups, in order: a host's own partners before shared ones.
GROUP_RULES = (outdoor.square, outdoor.street, outdoor.stock, *groups.RULES)


def compose(parsed: ParsedScene, seed: int = 0) -> Composition:
    """The designed first layout of ``parsed``."""
    if not parsed.objects:
        return Composition([], list(parsed.relations))
    parsed = mounts.on_posts(parsed)  # outdoors a clock made for a wall stands on a post
    parsed = mounts.over_holders(parsed)  # onions hang over the bear, not over the spoon it holds
    parsed = replace(parsed, objects=posture.pose(parsed))  # people sit and lie as the text says
    parsed = replace(parsed, objects=hosts.laid_flat(parsed))  # shearers stand on a board laid flat
    parsed = replace(parsed, objects=hosts.fit_unsized(parsed))  # a baton nobody sized fits a hand
    parsed = replace(parsed, objects=hosts.lengthen(parsed))  # a cabinet long enough for two aquariums
    relations = share_supports(parsed)
    relations += formations.stack_relations(parsed.objects, relations)
    relations += formations.row_relations(parsed.objects, relations)
    layout = Layout(parsed.objects, relations + groups.facing_focal(parsed.objects, relations))
    aisles = formations.aisles(parsed.objects, relations)
    ties = water.pier_ties(parsed.objects, relations, parsed.text) if parsed.water else set()
    _place_related(layout, {(s, t) for s, pair in aisles.items() for t in pair} | ties)
    for rule in GROUP_RULES:
        rule(layout)
    formations.arrange(layout, aisles)
    storage, vehicles, natural, core, front = [], [], [], [], []
    walled = {id(u): g for u in layout.top_units() if (g := anchors.anchored(layout, u)) is not None}
    # a group the text puts against a wall goes there, whatever of it is also "in the middle"
    centred = {id(u): m for u in layout.top_units() if id(u) not in walled and (m := _member_at(layout, u, "centre"))}
    for unit in layout.top_units():
        kind = layout.kind(unit.root)
        anchor = layout.by_id[unit.root].anchor
        centre = centred.get(id(unit))
        if anchor == "front":
            front.append(unit)
        elif centre is not None:
            p = layout.placed[centre]  # the member the text puts in the middle stands there
            layout.move(unit, -p.x, -p.y)
            core.insert(0, unit)
        elif unit.turnable and not unit.partners and (
            kind in roles.EDGE_STORAGE or anchor in edges.ANCHORED or edges.backdrop(layout, unit)
        ):
            storage.append(unit)
        elif unit.turnable and not unit.partners and kind in roles.VEHICLES:
            vehicles.append(unit)
        elif unit.turnable and not unit.partners and kind in roles.NATURAL:
            natural.append(unit)
        else:
            core.append(unit)
    packing.pack(layout, core, centred=sum(id(u) in centred for u in core),
                 backed={id(u) for u in core if id(u) in walled}, open_air=not parsed.indoor)
    edges.along_edges(layout, storage, back_taken=any(id(u) in walled for u in core))
    edges.in_front(layout, front)
    outdoor.park(layout, vehicles)
    outdoor.scatter(layout, natural, random.Random(seed))
    unline(layout, layout.relations_hold)
    shore = water.by_water(layout, parsed.text, ties) if parsed.water else None
    if not centred:
        dy = _centre(layout)
        shore = shore + dy if shore is not None else None
    return Composition([layout.scene_object(o.id) for o in parsed.objects], layout.relations,
                       tuple(walled[id(u)] for u in layout.top_units() if id(u) in walled),
                       None if shore is None else round(shore, 4))


def _centre(layout: Layout) -> float:
    """Everything moved so that what stands on the ground is centred on the origin: a room is
    built centred there around the first poses, so a composition set out to one side (groups
    packed behind the first one) would start half outside its room and be squeezed along a wall.
    Returns how far everything moved along y (the shore moves with it)."""
    prints = layout.ground_prints(list(layout.placed))
    if not prints:
        return 0.0
    x0, y0, x1, y1 = bbox(prints)
    dx, dy = -(x0 + x1) / 2, -(y0 + y1) / 2
    for p in layout.placed.values():
        p.x += dx
        p.y += dy
    return dy


def _member_at(layout: Layout, unit: Unit, anchor: str) -> str | None:
    """The unit's member (its root first) standing on the ground that the text anchors at
    ``anchor``, if any: a ceiling fan "in the middle of the room" hangs there whatever stands
    under it."""
    return next((i for i in [unit.root, *unit.ids] if layout.by_id[i].anchor == anchor and layout.on_ground(i)), None)


def initial_objects(parsed: ParsedScene, seed: int = 0) -> list[SceneObject]:
    """Scene objects with a first pose for every object of the parse."""
    return compose(parsed, seed).objects


def share_supports(parsed: ParsedScene) -> list[ParsedRelation]:
    """The parse's relations, with inferred supports shared among instances: monitors the
    parser put on "the" desk go one to each desk (each category of thing in turn), among the
    desks named together (a globe on the teacher's desk stays there)."""
    category = {o.id: o.category for o in parsed.objects}
    group = {o.id: o.group for o in parsed.objects}
    instances: dict[int, list[str]] = defaultdict(list)
    for o in parsed.objects:
        instances[o.group].append(o.id)
    count: dict[tuple[str, int], int] = defaultdict(int)
    out = []
    for r in parsed.relations:
        hosts = instances[group[r.target]]
        if r.inferred and r.relation == "on" and len(hosts) > 1:
            key = (category[r.source], group[r.target])
            target = hosts[count[key] % len(hosts)]
            count[key] += 1
            if target != r.source:
                r = ParsedRelation(source=r.source, relation="on", target=target, inferred=True)
        out.append(r)
    return out


def _components(layout: Layout, apart: set[tuple[str, str]]) -> list[list[str]]:
    """Groups of objects connected by relations (but those between ``apart`` pairs), in text order."""
    parent = {o.id: o.id for o in layout.objects}

    def find(x: str) -> str:
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for r in layout.relations:
        if r.source in parent and r.target in parent and (r.source, r.target) not in apart:
            parent[find(r.source)] = find(r.target)
    members: dict[str, list[str]] = defaultdict(list)
    for o in layout.objects:
        members[find(o.id)].append(o.id)
    return list(members.values())


def _place_related(layout: Layout, apart: set[tuple[str, str]]) -> None:
    """Each related group placed by its relations in its own frame: one unit each; the relations
    between ``apart`` pairs join nothing (what stands between two rows, or by a pier's land end,
    goes there later)."""
    for ids in _components(layout, apart):
        chosen = set(ids)
        objects = [layout.by_id[i] for i in ids]
        relations = [r for r in layout.relations if r.source in chosen and r.target in chosen]
        placed = relational.place_related(objects, relations, packing.free_spot)
        layout.placed.update(placed)
        root = relational.main_object(objects, relations).id
        unit = Unit(root=root, ids=list(ids), turnable=_rests_on(root, ids, relations))
        layout.units.append(unit)
        for i in ids:
            layout.unit_of[i] = unit


def _rests_on(root: str, ids: list[str], relations: list[ParsedRelation]) -> bool:
    """Whether every object of the group but ``root`` rests, however high the stack, on ``root``."""
    support = {r.source: r.target for r in relations if r.relation in ("on", "above")}
    for i in ids:
        seen = set()
        while i != root:
            if i not in support or i in seen:
                return False
            seen.add(i)
            i = support[i]
    return all(r.relation in ("on", "above") for r in relations)
