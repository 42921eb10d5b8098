"""People sit and lie as the text says, in a box that fits the pose, and the mesh agrees."""

from __future__ import annotations

import numpy as np
import pytest

from scenewright.analysis.arrange import compose
from scenewright.analysis.composition.posture import pose, posed_size, posture_in, posture_of
from scenewright.analysis.parser import parse_scene
from scenewright.procedural.builder import Model
from scenewright.procedural.shapes import SHAPES
from scenewright.procedural.style import resolve_style


def _figure(text: str, name: str):
    parsed = parse_scene(text)
    return parsed, next(o for o in parsed.objects if o.name.endswith(name))


@pytest.mark.parametrize(
    ("text", "name", "posture"),
    [
        ("A young woman sits on the sofa with a laptop on her knees.", "woman", "sitting"),
        ("An old wizard dozes in a patched armchair by the fireplace.", "wizard", "sitting"),
        ("A boy and a girl sit across from each other at the kotatsu.", "boy", "sitting"),
        ("A man lies on a picnic blanket under a tree.", "man", "lying"),
        # on a rug or a blanket the verb decides; with no verb of posture one lies
        ("Three musicians with flutes sit on a carpet.", "musician", "sitting"),
        ("A boy stands on the rug by the fire.", "boy", None),
        ("A woman reads on a blanket.", "woman", "lying"),
        ("A knight stands guard beside the gate.", "knight", None),
        ("A chef stirs a pot on the stove.", "chef", None),
        # riders sit on a vehicle or an animal unless the text has them stand on it
        ("A soldier on horseback waits by the tent.", "soldier", "sitting"),
        ("A van stops by the gate, and a boy stands on its bonnet.", "boy", None),
        # the verbs of another clause or another subject pose nobody else
        ("A customer waits at the counter, holding a hat, while a brass till sits on the counter.", "customer", None),
        ("Three scouts march past the well, and a grey cat lies on the wall.", "scout", None),
        ("A hound sleeps at the feet of an old shepherd.", "shepherd", None),
        ("A lorry full of waving farmhands rolls past, and a boy stands on the gate.", "farmhand", "sitting"),
        ("Under the oak tree sits an old shepherd.", "shepherd", "sitting"),
        # on a boat with a deck one stands, in an open boat one sits
        ("Three fishermen stand on a trawler.", "fisherman", None),
        ("A fisherman on a trawler mends a net.", "fisherman", None),
        ("A fisherman on a rowing boat mends a net.", "fisherman", "sitting"),
        ("A ferryman on a punt poles it along.", "ferryman", "sitting"),
    ],
)
def test_posture_read_from_host_and_verbs(text, name, posture):
    parsed, person = _figure(text, name)
    assert posture_of(parsed, person) == posture


def test_only_people_are_posed():
    parsed = parse_scene("A cat sits on the sofa.")
    assert all(posture_of(parsed, o) is None for o in parsed.objects)


def test_composition_gives_the_pose_its_box_and_word():
    composed = compose(parse_scene("A young woman sits on a park bench."))
    woman = next(o for o in composed.objects if o.name.endswith("woman"))
    standing = next(o for o in parse_scene("A young woman stands.").objects if o.name.endswith("woman"))
    assert posture_in(woman.visual_description) == "sitting"
    assert woman.size.z == pytest.approx(posed_size(standing.size, "sitting")[2])
    assert woman.size.z < 0.7 * standing.size[2]


@pytest.mark.parametrize("posture", ["sitting", "lying", "kneeling"])
def test_figure_mesh_fills_the_posed_box(posture):
    """Folded from a standing person, the mesh's own extents are the posed box's shape, so
    fitting it to the box does not stretch the person."""
    size = posed_size((0.5, 0.3, 1.75), posture)
    model = Model(size, resolve_style("realistic"), np.random.default_rng(0), name="woman", description=posture)
    SHAPES["figure"](model)
    verts = np.concatenate([p.vertices for parts in model.parts.values() for p in parts])
    extent = verts.max(axis=0) - verts.min(axis=0)
    assert extent / np.array(size) == pytest.approx(np.ones(3), rel=0.2)  # a standing one fills 0.82 of its depth
    if posture == "sitting":  # the seat is the lowest part, under the body, not the feet in front
        low = verts[verts[:, 2] < verts[:, 2].min() + 0.02]
        assert low[:, 1].max() > verts[:, 1].min() + 0.3 * extent[1]
    if posture == "kneeling":  # the shins lie along the floor behind the knees
        shins = np.concatenate([p.vertices for p in model.parts["trousers"]])
        low = shins[shins[:, 2] < 0.15 * size[2]]
        assert len(low) and low[:, 1].max() - low[:, 1].min() > 0.15 * size[2]


@pytest.mark.parametrize(
    ("text", "name", "stool"),
    [
        ("Two clerks sit at the long counter of the bank.", "clerk", True),
        ("A radio operator sits at a folding table, a lamp beside him.", "operator", True),
        ("A girl sits on the rug by the fire.", "girl", False),
        ("A monk kneels at the altar.", "monk", False),
        ("A farmer sits on a hay bale.", "farmer", False),
    ],
)
def test_one_who_sits_with_no_seat_named_sits_on_a_stool_of_their_own(text, name, stool):
    """Sitting at a counter with no seat named is not sitting on the floor before it: the figure
    brings a stool, in its box and in its mesh; on a rug, on one's knees or on a seat, none."""
    composed = compose(parse_scene(text))
    person = next(o for o in composed.objects if o.name.endswith(name))
    assert ("stool" in person.visual_description) == stool
    if stool:
        standing = next(o for o in parse_scene(f"A {name} stands.").objects if o.name.endswith(name))
        assert person.size.z == pytest.approx(posed_size(standing.size, "sitting", stool=True)[2])
        size = (person.size.x, person.size.y, person.size.z)
        model = Model(size, resolve_style("realistic"), np.random.default_rng(0), name=name,
                      description=person.visual_description)
        SHAPES["figure"](model)
        body = np.concatenate([p.vertices for role, parts in model.parts.items() if role != "dark_wood" for p in parts])
        torso = np.concatenate([p.vertices for p in model.parts["clothes"]])
        assert torso[:, 2].min() > 0.3  # the body sits on the stool (0.45 m)
        assert body[:, 2].min() < 0.1  # and its feet reach down to the floor


def test_one_who_kneels_kneels_on_whatever_carries_them():
    parsed = parse_scene("A tea room. A woman in a kimono kneels on a tatami mat before a low table.")
    woman = next(o for o in parsed.objects if o.name == "woman")
    assert posture_of(parsed, woman) == "kneeling"
    w, d, h = posed_size((0.5, 0.3, 1.75), "kneeling")
    assert h < 1.75 and d > 0.3  # lower than standing, the shins back along the floor


def test_a_long_flat_thing_leant_against_a_wall_stands_on_its_end():
    parsed = parse_scene("A ski lodge: a pair of skis leans against the wall, and a mattress lies on the floor.")
    sizes = {o.name: o.size for o in pose(parsed)}
    assert sizes["pair of skis"] == (0.2, 0.1, 1.8)  # its length now its height
    assert sizes["mattress"][2] < 0.3  # lying where it lies


def test_one_who_rides_on_nothing_named_stands():
    sizes = {o.name: o.size for o in pose(parse_scene("A cyclist rides past the newsstand. A knight rides a horse."))}
    assert sizes["cyclist"][2] > 1.5 and sizes["knight"][2] < 1.2


def test_a_toy_figure_stands_as_it_was_made():
    """Six toy knights guarding a toy castle on a rug lay flat on it, as people on a rug may."""
    parsed = parse_scene("A playroom. Six toy knights wait on the rug in front of a wooden castle.")
    knights = [o for o in parsed.objects if o.name == "toy knight"]
    assert knights and all(posture_of(parsed, o) is None for o in knights)
