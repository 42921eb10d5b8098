"""Where things made to hang go when the text does not hold them up.

Outdoors, a thing made to hang on a wall, or a light that only hangs, stands on a post.

A clock, a mirror, a picture or a lifebuoy hangs on a wall. In a scene with no room, where the
text puts it on nothing ("a clock on the kiosk" keeps its kiosk), nothing holds it up: it would
float over what the text hangs it above. A designer stands it on a post, as a station clock or
a lifebuoy stand: its box grows by the post's height (:data:`~scenewright.core.catalogue.POST`),
it rests on the ground, its description says so (the mesh then draws the post), and what the
text hangs it ``above`` it stands ``behind``, over it to the viewer's eye. An ``above`` the
reader only guessed gives a place, not a height: that becomes ``near``. So with a light the text
only hangs ("lanterns hang from the rafters" of a shed read as open ground): the reader hangs it
over the nearest thing, a guess, and with no roof overhead it would float there; on a post it is
a lamp post's lantern. Only lights: the reader reads hovering and flying as hanging too, and a
drone "hovering over the track" must keep flying.

Nothing hangs over what someone holds: the reader hangs a thing it was told only hangs ("bunches
of onions hang from the beams") over the nearest thing, and when that is in a hand ("a wooden
spoon" a bear bangs) the guess moves to the one holding it (:func:`over_holders`).
"""

from __future__ import annotations

from dataclasses import replace

from scenewright.analysis.parser import ParsedRelation, ParsedScene
from scenewright.analysis.parser.room import hangs_by_kind
from scenewright.core.catalogue import POST, POSTED, load_catalogue

#: m, the least depth of a posted thing's box: the post stands behind its face.
DEPTH = 0.12
#: Shapes of the living: what is on one of them is in hand (or carried, or perched).
LIVING = frozenset({"figure", "animal", "bird"})
#: Shapes of lights that hang (lanterns, lamps, chandeliers): outdoors, hung on nothing, a lamp post's.
LIGHTS = frozenset({"table_lamp", "pendant_lamp"})


def on_posts(parsed: ParsedScene) -> ParsedScene:
    """``parsed`` with every wall thing of an outdoor scene that stands on nothing, and every light
    hung only by the reader's guess, put on a post."""
    if parsed.indoor:
        return parsed
    held = {r.source for r in parsed.relations if r.relation == "on"}
    catalogue = load_catalogue()
    hung = {r.source for r in parsed.relations if r.relation == "above" and r.inferred}
    lights = {o.id for o in parsed.objects if o.id in hung and o.category in catalogue and catalogue[o.category].shape in LIGHTS}
    posted = {o.id for o in parsed.objects if (hangs_by_kind(o) or o.id in lights) and o.id not in held}
    if not posted:
        return parsed
    objects = [
        replace(o, size=(o.size[0], max(o.size[1], DEPTH), o.size[2] + POST), rests="ground",
                description=f"{o.description} {POSTED}".strip())
        if o.id in posted else o
        for o in parsed.objects
    ]  # fmt: skip
    relations = [_grounded(r) if r.source in posted else r for r in parsed.relations]
    return replace(parsed, objects=objects, relations=relations)


def _grounded(r: ParsedRelation) -> ParsedRelation:
    if r.relation != "above":
        return r
    return replace(r, relation="near" if r.inferred else "behind")


def over_holders(parsed: ParsedScene) -> ParsedScene:
    """``parsed`` with each ``above`` the reader guessed whose target is held by the living
    turned to the holder."""
    catalogue = load_catalogue()
    category = {o.id: o.category for o in parsed.objects}
    holder = {r.source: r.target for r in parsed.relations
              if r.relation == "on" and r.target in category and catalogue[category[r.target]].shape in LIVING}
    if not holder:
        return parsed
    relations = [replace(r, target=holder[r.target]) if r.relation == "above" and r.inferred and r.target in holder else r
                 for r in parsed.relations]
    return replace(parsed, relations=relations)
