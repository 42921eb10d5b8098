"""Hosts long enough for what the text puts on them.

A catalogue size is one piece of furniture of its kind: a cabinet 0.9 m wide. "Two big
aquariums sit on a long low cabinet" needs 2 m of it; left at 0.9 m, one aquarium finds no
place (the ``on`` relation wants its centre over the cabinet) and the solver's feedback drops
it. Furniture that comes in any length (tables, counters, cabinets, desks, benches) is
lengthened along its width to hold side by side what stands on it, as a designer would pick a
longer sideboard. A thing the catalogue does not know ("a concrete ledge") has a guessed size,
not one piece of furniture's: it is lengthened the same way, as wide as what the text puts on
it. A rock comes in any size too: "three goats have climbed onto a boulder" wants one whose top
holds three goats, so it grows in all three directions until its top does. Other hosts keep
their size, and what does not fit is the solver's to report.

The other way round, a thing nobody sized (a guessed ``thing``: "a baton", "a gouge", "a pocket
watch") has the size of a middling crate, which is right on the ground and wrong in a hand: one
a person or an animal holds is hand-sized (:data:`HAND`), one put on furniture made to hold
things (a table, a shelf: the catalogue's ``support``) keeps to a share of its top
(:data:`TOP_SHARE`), proportions kept (:func:`fit_unsized`). What stands on a seat, a rock, a lift
or another unknown thing is left alone: a thing nobody knows there is as likely someone.

A board or a panel is drawn upright, a sign; one that people or animals stand ``on`` ("shearers on
a raised wooden board", "a goat on a plank") is a floor: it lies flat as a low platform
(:data:`RAISED` high) long enough for them side by side (:func:`laid_flat`), and says so in its
description, so the mesh draws a deck and what stands on it stands on the deck, not on the top
edge of a sign 1.6 m up.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import replace

from scenewright.analysis.parser import ParsedObject, ParsedScene
from scenewright.analysis.composition import formations
from scenewright.analysis.composition.mounts import LIVING
from scenewright.analysis.composition.roles import SEATS
from scenewright.analysis.parser.vocabulary import GENERIC, load_vocabulary
from scenewright.core.catalogue import load_catalogue

#: Procedural shapes that are drawn well at any width.
STRETCHABLE = frozenset({"table", "counter", "cabinet", "desk", "bench"})
#: Space left between two things standing side by side on a host, and at its ends (m).
GAP = 0.05
#: Space left between two seats side by side along a host's front (m): room to sit down.
SEAT_GAP = 0.2
#: No host is lengthened past this many metres (a banquet table, a shop counter).
LONGEST = 7.0
#: No fence is lengthened past this many metres (a car park's side).
LONGEST_LINE = 30.0
#: Procedural shapes that come in any size and grow as a whole (a boulder for three goats).
GROWN = frozenset({"rock"})
#: Top area a grown host gives its load, as a multiple of the load's own footprints.
ROOM_ON_TOP = 1.5
#: m, the longest side of a thing nobody sized that a person or an animal has in hand.
HAND = 0.3
#: m, the longest side of a thing drawn at the size it stands on the ground that a person carries
#: (``carried_in_hand``: a parasol over one's head, not a patio umbrella).
CARRIED = 1.0
#: Share of its host's smaller top side the longest side of a thing nobody sized keeps to.
TOP_SHARE = 0.5
#: m, the height of a board or panel laid flat as a platform for who stands on it (a step up).
RAISED = 0.3
#: m, the least depth of such a platform: a person stands on it with room to work.
PLATFORM_DEPTH = 1.5
#: Word the description of a board laid flat gets: the panel mesh draws a platform for it.
PLATFORM = "platform"


def laid_flat(parsed: ParsedScene) -> list[ParsedObject]:
    """The parse's objects, each panel someone or an animal stands ``on`` (the living, or an agent
    noun nobody listed that the reader would take for a person were it seen acting) laid flat:
    :data:`RAISED` high, at least :data:`PLATFORM_DEPTH` deep, as long as its load side by side."""
    catalogue = load_catalogue()
    vocabulary = load_vocabulary()
    by_id = {o.id: o for o in parsed.objects}

    def stands(o: ParsedObject) -> bool:
        entry = catalogue.get(o.category)
        if entry is not None and entry.shape in ("figure", "animal"):
            return True
        return o.category == GENERIC and vocabulary.guess_agent(o.name.split()[-1], True) is not None

    loads: dict[str, list[ParsedObject]] = defaultdict(list)
    for r in parsed.relations:
        if r.relation == "on" and r.source in by_id and r.target in by_id and stands(by_id[r.source]):
            loads[r.target].append(by_id[r.source])
    out = []
    for o in parsed.objects:
        entry = catalogue.get(o.category)
        on = loads.get(o.id, [])
        if on and entry is not None and entry.shape == "panel" and PLATFORM not in o.description:
            width = max(o.size[0], min(sum(s.size[0] + GAP for s in on) + GAP, LONGEST))
            depth = max(PLATFORM_DEPTH, max(s.size[1] for s in on) + 2 * GAP)
            o = replace(o, size=(width, depth, RAISED), description=f"{o.description} {PLATFORM}".strip())
        out.append(o)
    return out


def lengthen(parsed: ParsedScene) -> list[ParsedObject]:
    """The parse's objects, each stretchable host as wide as the widths of what is ``on`` it
    side by side, in as many rows as its depth takes, and as the seats in front of it side by
    side ("six stools line the counter": one row along its front); never narrower than it was,
    never past :data:`LONGEST`."""
    catalogue = load_catalogue()
    by_id = {o.id: o for o in parsed.objects}
    loads: dict[str, list[ParsedObject]] = defaultdict(list)
    seated: dict[str, list[ParsedObject]] = defaultdict(list)
    lined: dict[str, list[ParsedObject]] = defaultdict(list)
    for r in parsed.relations:
        if r.source not in by_id or r.target not in by_id:
            continue
        if r.relation == "on":
            loads[r.target].append(by_id[r.source])
        elif r.relation == "in front of" and by_id[r.source].category in SEATS:
            seated[r.target].append(by_id[r.source])
        elif r.relation in ("near", "in front of") and by_id[r.source].formation == "row":
            lined[r.target].append(by_id[r.source])
    out = []
    for o in parsed.objects:
        entry = catalogue.get(o.category)
        on, seats = loads.get(o.id, []), seated.get(o.id, [])
        if entry is not None and entry.shape in formations.LINES and len(lined.get(o.id, [])) > 1:
            # "four vans parked in a row along the fence": the fence runs the row's length
            row = lined[o.id]
            need = sum(s.size[0] for s in row) + formations.GAP * (len(row) + 1)
            o = replace(o, size=(max(o.size[0], min(need, LONGEST_LINE)), *o.size[1:]))
        stretchable = o.guessed or (entry is not None and entry.shape in STRETCHABLE)
        if stretchable and (len(on) > 1 or len(seats) > 1):
            need = sum(s.size[0] + SEAT_GAP for s in seats)
            if on:
                rows = max(1, int(o.size[1] // max(s.size[1] + GAP for s in on)))  # a deep table holds rows
                need = max(need, (sum(s.size[0] + GAP for s in on) + GAP) / rows)
            width = max(o.size[0], min(need, LONGEST))
            o = replace(o, size=(width, *o.size[1:]))
        elif entry is not None and entry.shape in GROWN and on:
            need = ROOM_ON_TOP * sum(s.size[0] * s.size[1] for s in on)
            factor = min((need / (o.size[0] * o.size[1])) ** 0.5, LONGEST / max(o.size[:2]))
            if factor > 1.0:
                o = replace(o, size=tuple(round(v * factor, 4) for v in o.size))
        out.append(o)
    return out


def fit_unsized(parsed: ParsedScene) -> list[ParsedObject]:
    """The parse's objects, each guessed ``thing`` held by the living or put ``on`` a support
    scaled down, proportions kept, to a hand's size (:data:`HAND`) or to :data:`TOP_SHARE` of
    its host's top, and each thing people carry that the catalogue sizes as it stands on the
    ground (a parasol) held by the living to :data:`CARRIED`; never up."""
    catalogue = load_catalogue()
    vocabulary = load_vocabulary()
    by_id = {o.id: o for o in parsed.objects}
    hosts = {r.source: by_id[r.target] for r in parsed.relations if r.relation == "on" and r.target in by_id}
    out = []
    for o in parsed.objects:
        host = hosts.get(o.id)
        entry = catalogue.get(host.category) if host is not None else None
        unsized = o.guessed and o.category == GENERIC and entry is not None and (entry.shape in LIVING or entry.support)
        held = entry is not None and entry.shape in LIVING and vocabulary.carried_by_hand(o.category, o.name)
        if unsized or held:
            longest = CARRIED if held else HAND if entry.shape in LIVING else TOP_SHARE * min(host.size[:2])
            factor = longest / max(o.size)
            if factor < 1.0:
                o = replace(o, size=tuple(round(v * factor, 4) for v in o.size))
        out.append(o)
    return out
