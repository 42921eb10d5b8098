"""Every prompt scenewright sends to a remote model, in one place.

The information each task receives follows the paper's pipeline (text and reference image
for the objects; text, objects and image for the constraints; the solver's report for the
revision; the scene and an instruction for an edit); the wording is scenewright's own. The
JSON shape is not spelled out here: it travels as the request's JSON schema.
"""

from __future__ import annotations

from scenewright.scene import RELATION_TYPES

FRAME = (
    "Coordinates: metres, right-handed, origin at the centre of the ground; +X points right, "
    "+Y points away from the viewer (backward), +Z points up. Rotations are degrees; an object's "
    "yaw (rotation z) turns it about +Z, and at yaw 0 its front faces the viewer (-Y)."
)

RELATIONS = """Relations (the source is the object being placed, the target is the one it is placed against):
- "left of" / "right of": source lies beyond the target's box along -X / +X.
- "in front of" / "behind": source lies beyond the target's box along -Y (toward the viewer) / +Y.
- "side of": either "left of" or "right of".
- "near": at most 2 m between the two boxes, horizontally. "far": more than 8 m apart.
- "on": source rests on the target's top surface. "above": source hangs at least 2 m over the target without touching it.
- "face to": source turns so its front points at the target.
In a scene with a room, four relations have a part of the room as their target instead of an object: "room" (any wall), "wall_0", "wall_1", "wall_2", "wall_3" (the front, right, back and left walls) or "ceiling":
- "against wall": source stands with its back to the wall (beds, wardrobes, bookshelves, sofas, counters).
- "in corner": source stands against a wall, in a corner of the room.
- "on wall": source hangs on the wall, off the floor (mirrors, paintings, wall TVs, clocks, wall shelves).
- "on ceiling": source hangs from the ceiling (ceiling fans, chandeliers, pendant lamps).
Every object stands on the ground unless it is the source of "on", "above", "on wall" or "on ceiling"; do not write a constraint for standing on the ground."""


# --- images -------------------------------------------------------------------------------


def reference_image(text: str, style: str) -> str:
    return (
        f"{text.strip()}\n\nDraw this whole scene as one {style} picture, seen from the front and a "
        "little above, with +X to the right, +Y going away from the viewer and +Z up. Every object "
        "the text names is fully visible, evenly lit, and nothing is added that the text does not ask for."
    )


def object_image(name: str, description: str, style: str) -> str:
    detail = f" ({description.strip()})" if description.strip() else ""
    return (
        f"Draw exactly one {name}{detail}, alone, seen straight from the front, whole and centred, "
        f"on a fully transparent background, in {style} style. Match its shape, colours and materials "
        "to the same object in the reference scene. No other objects, no ground, no shadow, no text."
    )


def ground_texture(text: str, style: str, kind: str) -> str:
    return (
        f"Make one square, seamless, tileable {style} texture of the {kind} ground of this scene: "
        f"{text.strip()}\nUse the floor or ground material and pattern visible in the reference picture, "
        "seen from straight above, evenly lit, uniform across the whole image and at a scale that covers "
        "a large area when repeated. Leave out walls, furniture, objects, shadows and edges. Fully opaque."
    )


# --- scene analysis ------------------------------------------------------------------------

OBJECTS_SYSTEM = (
    "You turn scene descriptions into a list of 3D objects for a layout engine. "
    "You answer with JSON in the requested schema only."
)


def describe_objects(text: str, style: str, low: float, high: float) -> str:
    return f"""Scene ({style} style):
{text.strip()}

List the objects this scene is made of, using the description and the attached reference picture (when there is one).

{FRAME}

For each object give:
- id: short lowercase snake_case, unique (e.g. "sofa_1", "lamp_left");
- name: what it is, in a few words;
- position: the centre of its bounding box; an object on the ground has z = half its height;
- rotation: 0 for x and y; z is its yaw;
- size: its extent along x, y, z at yaw 0, in metres, each between {low:g} and {high:g};
- visual_description: one sentence on its look: shape, colours, materials, style.

Rules:
- Every object the text names, each one separately when the text gives a count ("three chairs" is three objects).
- Whole objects only: never list a part (a handle, a leg, a window, a cushion) as its own object.
- No background: walls, floors, ceilings, ground, grass, sky, roads, water surfaces, terrain and curtains are not objects.
- Keep to the main objects; skip clutter the text does not mention.

Also give the room: when the scene is indoors (a bedroom, a kitchen, a shop, any room inside a building), its rectangular floor centred at the origin, width along x and depth along y in metres, big enough for every object with space to walk, its ceiling height, and its doors and windows, each on one wall (front is the viewer's side, -Y); at least one door. Every object then lies inside the room. For an outdoor or open scene, the room is null."""


REDUNDANT_SYSTEM = (
    "You check generated object pictures for a 3D scene and find the ones that are redundant. "
    "You answer with JSON in the requested schema only."
)


def find_redundant(objects_text: str) -> str:
    return f"""Each object below was drawn as its own picture (attached after this text, each labelled with its id).

Objects:
{objects_text}

Some pictures of large objects may already contain a smaller object of the list (a bathtub drawn with its faucet, a desk drawn with its chair, a table drawn with its vase). Building both would put the small object in the scene twice.

List the ids of the smaller objects that are already visible inside another object's picture, each with a short reason naming that other object. List nothing when no picture contains another object. Never list an object whose picture is the only one showing it."""


# --- layout --------------------------------------------------------------------------------

CONSTRAINTS_SYSTEM = (
    "You decide the spatial constraints that place the objects of a 3D scene. "
    "Order matters: once an object has been a target it is never a source again later in the list, "
    "and all constraints of one source come one after another. You answer with JSON in the requested schema only."
)


def _constraint_rules() -> str:
    names = ", ".join(f'"{r}"' for r in RELATION_TYPES)
    return f"""{RELATIONS}

Rules:
- Use only these relations: {names}; and only the ids listed above.
- Write a constraint only when the description or the picture supports it; the most important ones, none redundant.
- Direction: "a lamp on the desk" has the lamp as source and the desk as target; "a chair to the right of the table" has the chair as source.
- Never let an object depend on itself, directly or through a chain.
- An object is either on the ground (no vertical constraint) or the source of exactly one "on" or "above"."""


def write_constraints(text: str, objects_text: str) -> str:
    return f"""Scene description:
{text.strip()}

Objects (id: name, size x/y/z in metres, look):
{objects_text}

Write the spatial constraints between these objects, using the description and the attached reference picture (when there is one).

{_constraint_rules()}"""


def revise_constraints(text: str, objects_text: str, constraints_text: str, report_text: str) -> str:
    return f"""Scene description:
{text.strip()}

Objects (id: name, size x/y/z in metres, look):
{objects_text}

The layout solver was given these constraints:
{constraints_text}

It could not satisfy all of them without collisions. Its report:
{report_text}

Write a revised, complete list of constraints that keeps the meaning of the description but can be satisfied: drop or loosen the constraints that failed (for example "near" instead of an exact side when space is short, or another target with room for the object), and keep the ones that worked.

{_constraint_rules()}"""


# --- editing -------------------------------------------------------------------------------

EDIT_SYSTEM = (
    "You turn an edit instruction for a 3D scene into one structured edit of exactly one object. "
    "You answer with JSON in the requested schema only."
)


def plan_edit(objects_text: str, instruction: str, room_text: str | None = None) -> str:
    room = (f"\nThe room: {room_text}\n" if room_text else "\nThe scene has no room (open ground).\n")
    room_op = (' or "room" (change the room itself: its size or height, or add a door or window)' if room_text else "")
    return f"""Objects in the scene (id: name, position, yaw, size):
{objects_text}
{room}
Instruction:
{instruction.strip()}

Decide the one edit it asks for:
- operation: "move" (place an existing object elsewhere or turn it), "add" (a new object), "delete" (remove one), or "replace" (change an object into something else or restyle it){room_op}.
- focus: the id of the one object the edit changes, exactly as listed; for "add", a new unused snake_case id for the new object; for "room", "room".
- constraints: where the focus goes, only for "move", "add" and "replace" when it asks for a new place. The focus is the source of every constraint and never a target; targets are listed ids.
- new_object: for "add" and "replace", the new object's name, category word, one-sentence look and, when the instruction says so, its size in metres (else null); null for "move" and "delete".
- yaw: a new yaw in degrees when the instruction asks only to turn the object; else null.
- offset: for a "move" that names no other object ("a bit to the left", "1 m back"), the shift from where the focus stands in metres (x right, y back, z up; 0.5 m when no distance is said) with no placing constraints; else null.
- room: for "room" only (else null): the new floor width and depth in metres (both, or both null), the new ceiling height (or null), and a door or window to add with the wall's side (back, front, left, right; null: any) (or nulls).

{RELATIONS}"""


# --- judging -------------------------------------------------------------------------------

_CRITERIA = {
    "positional": (
        "positional coherence: are the objects where the description puts them relative to each "
        "other (left and right, in front and behind, on top, near and far)? Judge every stated "
        "relation and how much each violation breaks the intended layout."
    ),
    "rotational": (
        "rotational coherence: do the objects face the way the description implies (facing each "
        "other, towards a focal object, aligned in rows)? Judge how much wrong orientations hurt "
        "what the objects are for."
    ),
    "semantic": (
        "semantic alignment: as a whole, does the arrangement of the scene match what the "
        "description means, with the right objects, in a sensible, usable organisation?"
    ),
}
CRITERIA = tuple(_CRITERIA)

JUDGE_SYSTEM = "You are a strict, consistent evaluator of rendered 3D scenes."


def judge(text: str, criterion: str) -> str:
    return f"""Scene description:
{text.strip()}

The attached picture is a render of a 3D scene generated from this description. Rate its {_CRITERIA[criterion]}

Explain briefly, then end with a final line of the form "Score: N", where N is a whole number from 1 (no agreement) to 100 (perfect agreement)."""
