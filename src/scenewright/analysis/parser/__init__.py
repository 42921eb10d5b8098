"""Rule-based reading of a scene description: objects, counts, looks, sizes, relations, style.

The offline vision-language backend answers from this parse. It reads descriptions written
the way people write them (the paper's 50–300-word inputs): noun phrases are matched against
the catalogue (longest phrase first, plurals folded), counts come from the words before them,
and relation phrases connect the clause's subject (the thing placed) to the noun phrase after
the phrase.

Where things live: ``tokens`` (words, clauses), ``words`` (closed word classes), ``nouns``
(noun phrases, the open vocabulary, place words), ``sizes``, ``phrases`` (relation phrases;
the phrases themselves are ``data/relation_phrases.json``), ``reader`` (clause reading and
reference resolution), ``hands`` (what people and animals hold or act on), ``distribute`` ("each", around, between, rows: group relations to
object relations), ``support`` (default supports, ``on`` only onto hosts that can hold the
thing), ``vocabulary`` (``data/vocabulary.json``), ``language`` (English only), ``style``.
To add a phrase, add it to its kind's list in ``data/relation_phrases.json``; to add a thing,
add its head word to ``data/vocabulary.json``.

Decisions worth knowing:

- A noun the catalogue does not know still names an object: the vocabulary gives its shape
  family (animal, figure, machine, tank, structure, panel, container, tool, vehicle) and size;
  a noun nobody listed becomes a generic ``thing`` unless it names no thing (a place, a time,
  weather, a part, a material). Such objects are ``guessed``. A place word sets the scene
  ("inside a warehouse", "a hangar with a spaceship", "a farmhouse kitchen") and is no object.
- ``between A and B`` → right of one and left of the other (front/behind when the pair stands
  front to back) and near both; a seat ``at`` a desk or table → in front of it, facing it;
  ``at the foot of`` anything → in front of it, ``at the head of`` a bed → behind it (a table's head is
  an end); ``at the end of`` a table or a counter → on it for a tabletop thing, of a bed → in front
  of it, else near it; ``hanging from`` a beam → above it, from a tree → near it, from anything else (a post, a
  stall, a tower's railing) → on it; ``leaning on`` → side of, ``along`` → near (by it, parallel);
  ``in a row`` / ``stacked`` → each right of / on the one before; ``against the wall``, ``in
  the corner``, ``in the middle of the room``, ``at the back`` name no object and become the
  object's ``anchor`` for the arranger.
- ``on`` only onto a host that can hold the thing (flat hosts hold anything; floor furniture
  stands on no other piece; a thing at most about the host's size; a person or an animal on any
  host at least a stool's size; a hung container only what fits in it); otherwise ``side of``,
  and the repair is listed in ``ParsedScene.repairs``. A small thing hung from the ceiling hangs
  ("a birdcage hangs from the ceiling").

- ``beside`` / ``next to`` / ``alongside`` / ``leans against`` → ``side of``; ``near`` / ``close to`` / ``by`` / ``among`` →
  ``near``, and so is one who ``talks to`` / ``speaks to`` / ``chats with`` someone (the
  annotated sets: with them, not turned to them; a phrase after the addressee still places the
  talker); ``opposite`` / ``across from`` → ``in front of`` + ``face to``; ``flanked by`` and
  ``on either side of`` → one flanker ``left of`` and one ``right of`` (one thing named "on each
  side of" is two, one a side, even beside a door that is no object); ``around`` /
  ``surrounding`` / ``surrounded by`` → the surrounding objects shared among the target's
  sides (every side once, then the long sides of a long table), each facing it; fewer than four
  that are no seats cover the four sides between them, the first at corners ("two children run
  around the well"); one thing "around" another is ``near`` it, unless it moves (a person, an
  animal, a vehicle: "a dog runs around the tree"), which takes a corner, facing it; ``from A to
  B`` → between A and B; ``before`` ("kneels before her") → in front of + face to; ``followed by`` /
  ``chased by`` → the follower behind; ``from high above`` → above the last target ("films the balloons
  from high above": facing them too); a person, an animal or a vehicle going ``towards`` a thing faces it, unless
  the verb moves an object there ("pushes a cart toward the kiosk"); X ``towing`` / ``pulling`` Y →
  Y behind X, and the next phrase places X ("a pony pulls a cart between two shafts"); X ``hitched
  to`` Y → a living X in front of a load Y, a load X behind an animal Y; X ``drives`` / ``steers`` /
  ``pilots`` a vehicle → on it, the vehicle taking the next phrase ("drives a quad bike, towing a
  trailer"; "drives the sheep" is no phrase); what
  turns or spins ``above`` a thing is aloft ("a hologram turns above the table"); ``across`` a
  thing a living thing can stand on, or "leaning out of" / "peeks out of" one, → on it (across
  anything else, or fronted, nothing); "climbs out of" → near; ``at`` a part one stands on (its
  top, prow, stern, deck, roof) → on the thing; facing a thing "from across the room" (a place) or
  after an opening "Across the street," → across from it; ``at a distance of N m`` → ``near`` when
  N ≤ 2, ``far`` when N > 8.
- People and animals (``hands``): what one uses, works with or takes from is in hand, ``on`` the
  holder, when small enough to hold ("eats a sandwich", "practises with five clubs", "sipping
  coffee from a paper cup", "a glass in one hand", "baskets on their backs"): hand-sized (a box of
  at most 0.06 m³) for any verb, anything a person can carry for a verb of taking up in one's arms
  ("hoists a trunk"), so "examines a crate" is done by the crate (``near``); what one holds or grips
  that nobody could carry one stands by ("grips the railing"); the holder takes the
  next place phrase ("lifts a barbell next to the bales"), a seat or a perch carrying them and
  anything else worked at (``near``: "sharpen their spears on a grindstone"). A doer stands
  ``near`` what it acts on ("plays it", "scrubs its back", "forks straw into it", "pushes the front
  one"), is ``on`` the perch it acts from ("plays it from a bench", "feed ducks from a
  footbridge"); a small thing worked on where it lies takes the phrase ("stirs a pot on the stove":
  the pot on it, the doer near it). Companions keep ``near`` ("with its handler"), a led animal by
  its person ("walks a dachshund beside the van": the man beside it); "each holding" gives one to
  each of the people; "sharing a thermos" is one thermos; a giver holds the gift, ``near`` whom it
  goes to; a rider over a bridge is on it (the mount is). What one aims is in hand and the aimer
  faces the target ("aims a pitchfork at them"); "a bell on its collar" is on the animal; a
  person's thing in an absolute phrase is by its owner ("his lance planted in the grass": near
  him, "his helmet at his side": beside him), in hand when held ("his sword raised"); what one
  writes in or on, feeds or pours from is in hand ("recording every sack on a scroll"), and a
  parasol or a microphone a person is given is the hand-held kind (``carried_in_hand``).
- "on the left wall" places nothing: a side word before a noun is that noun's adjective, and
  walls are no objects. A part named by a possessive is its owner ("above its door" → above
  it), since doors, roofs and porches are not objects either.
- A phrase right after another's target places that target ("a globe on a side table to the
  right of the desk": the side table is right of the desk). ``with``/``holding`` parts hang
  from their head: "a sink with a mirror above it", "a cart loaded with barrels" (on it), "a
  desk with a lamp" (a surface thing with a support → on it); "a bed with a nightstand on
  either side" flanks the head, the with-thing's only target. "It"/"them" name the latest
  earlier mention of the right number. A phrase opening a sentence ("Behind the gate, a
  pond...", "Far from the house, ...") places every subject that follows ("Around it,
  toadstools and crystals glitter"); an adverb that starts a phrase ("far", "just") is part of it.
  A with-list runs on over commas to its verb ("a counter with combs, scissors and a jar runs
  beneath the mirror"); a with-thing placed on its own starts a new list, and a small thing
  next to "it" stands by its small peer ("with a till at one end and a computer beside it").
  Beside a small thing on a table means beside that thing, not the table.
- "the teacher's desk" is a new desk unless an earlier one has the same head noun; "the
  middle bench" is one of the benches; "a rack of dumbbells" is a dumbbell rack; "holographic
  koi" are holograms (a holographic sign stays a sign); "three rows of shelves" are three
  shelving units.
- A look written after the noun is part of its description, so the mesh gets its colours,
  materials and glow: "a vending machine glowing pink", "a sofa covered in green velvet" (a
  participle and its describing words, up to a verb, a relation phrase or another object); a
  catalogue noun after "made of" is a material ("a table made of glass" holds no glass).
- "the island" after "a kitchen island" refers back to it; "a vase of tulips", "a bowl full
  of apples" and "a statue of a horse" hold contents, not objects; "a stone path", "a pine
  forest", "a throne hall" name no object; "a potted palm" is a potted plant, "a round
  table" a round table.
- ``over`` means ``above`` after a hanging verb (hang, hover, float...) anywhere earlier in the
  clause part or for a small (tabletop or hanging) thing, else ``near`` (a tree leaning over a
  pond); a tabletop thing hung "from the ceiling" hangs. A tall standing thing ``above`` a thing
  is ``near`` it (a tree above a pond) unless it is a flat board or a storage unit with a wall form
  ("a sign above the counter", "a shelf above the desk"): those hang. ``X under Y`` puts Y ``on`` X when X is
  flat (a rug under a table), else X ``near`` Y.
- ``in`` a seat, a vehicle, a container or on a surface → ``on`` it ("a man in a rocking chair", "a
  duck floats in the tub", "a rabbit in a cage"), and a person or an animal is on every
  carrier it is in ("children in the bus", "fans in the stand"; ``carriers`` in
  ``data/vocabulary.json``); a phrase right after places the seat ("dozes in an armchair by the
  fire"); in anything else (a tent, a field) it places nothing. ``from`` a carrier after a verb one
  does from where one is (``lookout_verbs``: "a heron watches from a rock", "waves from the tower")
  → ``on`` it. A person's "in it" / "on it" after a posture verb (``postures``) is the nearest
  carrier of this sentence or the one before ("a bookcase stands beside an armchair, and a
  sailor dozes in it"), and "it" names no person; one who "sits on a stool at the counter" is
  ``near`` the counter too, one who "sits on a crate across from it" faces it herself, "rides" /
  "riding" a thing is ``on`` it; "the water" is the latest pond's (``part_owners``); living
  things a carrier is "packed with" or "full of" are on it and no subject of its verb; "each in a
  seat" and "riders on horseback" give one seat, one horse apiece; "a woman sits ..., her cat
  beside her chair" sits on her chair; a rider put on something else puts the mount there ("a kid
  on a bike at the top of the ramp").
- A part of a building or a vehicle that is no object ("on the roof", "beside its door", "the
  shop's roof", "the porch steps") places by its owner: one named in the same sentence, else the
  latest building, else the latest vehicle.
- People: "he"/"him"/"his" and "she"/"her" name a person of that sex (``people`` in
  ``data/vocabulary.json``), the clause's subject or a with-part's owner first ("a king and a queen
  sit in the hall, he on a throne, she on a sofa": each phrase about the one it names); a body part after
  a person's possessive places by the person ("a laptop on her knees" → on her, and the repair
  leaves it there; "a dog at his feet" → near him). "Their" of people names their own things, one
  each ("two teenagers on their motorbikes"); of things, a part ("lanterns on their roofs").
- A part named with "its" belongs to what has such a part (``part_owners``: "an owl on its
  back" is on the armchair, not on the fireplace named after it); "one of its branches" is its
  branch. "The tallest one" / "the nearest one" is one of the group named before.
- "Across from each other" / "opposite each other" → in front of + face to, one way (the other
  would close a cycle). A fronted ground phrase ("Behind the chair, a hologram floats above a
  round table") places what the subject floats above or stands on. "Side by side with" after
  several things is their row and opens their with-part.
- Attachment: a relative or a participle right after a target describes the target ("a lorry
  idling at the barrier", "a ring light that hangs from the ceiling"; before the subject's own
  verb a participle stays the subject's); a person on a seat is what *at*, *across from*,
  *facing* and, after a seat, *between* / *under* / *behind* place ("sits on a stool at the workbench"),
  while *beside* / *near* place the seat (the one on it is the clause's living subject the phrase
  before put there, also when the verb acts on a thing: "launch a rocket from a platform across
  from the barn" places the launchers), and what every place phrase places when the seat is a makeshift
  one (an upturned bucket, a hay bale, a sledge: "judges sitting on hay bales in front of it"); "it" right after a *between* names the thing between, not
  one of the pair; "with" right after the second end of *between* is that
  end's. X *under* a thing that hangs, is hung, is on a wall or is a thin board → that thing
  ``above`` X ("chairs under a ceiling fan"). "Between the first and second van", "between
  the second and the third" (of the row named before), "the two nearest benches" are members of
  the group named before; "to her left", "at its foot", "on the
  nurse's right" name a side of the possessor. A phrase opening a sentence, a clause after a
  semicolon, or a clause after "and" that names its own subject after the phrase ("and between
  them a crew heaves on the ropes"), names with "it"/"them" what the clause before was about (its subjects, then what
  placed them, latest first), and chains like any phrase ("On a mound behind the giraffes, ...");
  "it" never names a person, a thing never names what it sits on or in, and what a living thing
  watches is a living thing first. A where-clause's subjects placed nowhere else are ``near`` the
  place before "where". "Side by side" also puts each of a group beside the one before. A phrase
  word right after an article is the noun's own ("a border guard"). *From* a seat, a structure,
  a rock, a surface or a roof is ``on`` it ("a cat watches her from a stool"), from anything
  else nothing; "beside each of them" is one per member, and "a register on the counter in front
  of each of them" gives out registers, not counters.
- "A bench for parents", "six tatami mats in size" name no things; "a glowing crystal ball" is a
  crystal ball (a phrase opening with a describing word gives way to a longer thing inside it).
- Vague counts: a pair / a couple / both → 2; a few / several / some / a bare plural → 3;
  many / lots of → 5; ``each with a lamp``, ``every desk has a lamp`` and ``each surrounded by
  two chairs`` give that many per object of the group, placed by their own one. A bare plural of a
  crowd word ("spectators gather") is 5; "about twenty" is 20; a count in words is at most fifty
  (``CROWD``: "a hundred fans"), one in digits is taken as meant; "a herd of about twenty grazing"
  (no noun) is twenty more of the animal named before; ", a dozen in all" counts the sentence's
  first noun; "sheep" or "deer" with no determiner are several.
- Stated sizes (``2 meters wide``, ``a 3 m tall statue``) set that dimension; the others
  scale by the same factor so the object keeps its proportions.
- Things that rest on a surface but have no stated support get an inferred ``on`` to the
  most fitting support in the scene (a lamp → nightstand, desk, side table, table...); hanging
  things without a stated target get an inferred ``above`` the nearest-mentioned large
  object. Both are marked ``inferred`` (the parse benchmark scores stated relations only).
"""

from __future__ import annotations

from dataclasses import replace

from scenewright.analysis.parser.distribute import _acyclic, _expand, _ids
from scenewright.analysis.parser.model import ParsedObject, ParsedRelation, ParsedScene
from scenewright.analysis.parser.phrases import relation_phrases
from scenewright.analysis.parser.reader import _Reader
from scenewright.analysis.parser.room import wall_units
from scenewright.analysis.parser.style import GROUND_KINDS, _is_indoor, detect_ground, detect_style, detect_water
from scenewright.analysis.parser.support import _infer_support, fit_on_hosts, onto_stack_tops, repair_supports, standing_lamps

__all__ = [
    "GROUND_KINDS", "ParsedObject", "ParsedRelation", "ParsedScene",
    "detect_ground", "detect_style", "detect_water", "parse_scene", "relation_phrases",
]  # fmt: skip


def parse_scene(text: str) -> ParsedScene:
    """Read a description into objects (with ids, sizes, descriptions), relations, style and
    ground kind. Deterministic: the same text always gives the same parse. Each call returns a
    new parse the caller may change; a caller that reads one text often keeps its own (the
    offline backend does, per instance)."""
    text = " ".join(text.split())
    reader = _Reader(text)
    reader.read()
    _ids(reader.groups, reader.listed)
    catalogue = reader.catalogue
    objects = [
        ParsedObject(
            i, g.category, g.name, g.description, g.size, g.index, g.guessed, g.rests,
            reader.anchors.get(g.index), reader.formations.get(g.index), reader.lines.get(g.index),
        )
        for g in reader.groups if g.index not in reader.listed
        for i in g.ids
    ]
    expanded = _acyclic(_expand(reader), [o.id for o in objects])
    fixed = {i for g in reader.groups if g.sized for i in g.ids}
    objects = fit_on_hosts(standing_lamps(objects, expanded, catalogue, fixed), expanded, catalogue, fixed)
    by_group = {g.index: g.ids for g in reader.groups}
    carried = frozenset((a, b) for s, t in reader.carried for a in by_group[s] for b in by_group[t])
    stated, repairs = repair_supports(objects, onto_stack_tops(objects, expanded), catalogue, carried)
    inferred = _infer_support(objects, stated, catalogue)
    relations = _acyclic(stated + inferred, [o.id for o in objects])
    # a place the text also puts things outside of ("a bench in front of the bakery") is seen from outside
    outside = [p for p in reader.places if p in {o.name for o in objects}]
    indoor = _is_indoor([o.category for o in objects], text, catalogue, [p for p in reader.places if p not in outside])
    parsed = ParsedScene(
        text=text,
        objects=objects,
        relations=relations,
        style=detect_style(text),
        ground=detect_ground(text, indoor),
        indoor=indoor,
        places=reader.places,
        repairs=repairs,
        water=detect_water(text, indoor),
    )
    return replace(parsed, objects=wall_units(parsed))  # a shelf fixed to a wall is a wall shelf
