"""A boat's deck is where its mesh has it: the layout and the procedural mesh read one function."""

import numpy as np
import pytest

from scenewright.assets.load import asset_mesh
from scenewright.core.vessels import deck_area, deck_share, is_open
from scenewright.layout import colliding_pairs
from scenewright.procedural.meshes import build_glb
from scenewright.scene import SceneObject, Vec3


def _box(oid, x, y, z, size):
    return SceneObject(id=oid, name=oid, size=Vec3.of(size), position=Vec3(x=x, y=y, z=z))


@pytest.mark.parametrize(
    "name, size",
    [("trawler boat", (4.0, 13.0, 5.0)), ("rowing boat boat", (1.5, 4.5, 1.2)), ("yacht boat", (3.0, 10.0, 9.0)),
     ("reed boat boat", (1.2, 4.0, 0.8))],
)
def test_one_stands_on_the_deck_of_the_mesh_not_in_it(name, size):
    """A person at the corners of the deck area, at the deck's height, touches nothing of the
    boat's mesh (its cabin, its gunwale, its thwarts); sunk into it by a few centimetres, they
    collide with the planks."""
    boat = _box("boat", 0.0, 0.0, size[2] / 2, size)
    meshes = {"boat": asset_mesh(build_glb("boat", size, "realistic", 0, "", name))}
    x0, y0, x1, y1 = deck_area(name, size)
    deck = deck_share(name, size) * size[2]
    person = (0.1, 0.1, 0.5)
    for fx, fy in ((x0 * 0.8, y0), (x1 * 0.8, y1 * 0.85), (x0 * 0.8, y1 * 0.85)):
        x, y = fx * size[0] / 2, fy * size[1] / 2
        standing = _box("p", x, y, deck + 0.25 + 0.005, person)
        assert colliding_pairs([boat, standing], meshes) == [], (name, fx, fy)
        sunk = _box("p", x, y, deck - 0.05 + 0.25, person)
        assert colliding_pairs([boat, sunk], meshes) == [("boat", "p")], (name, fx, fy)


def test_open_boats_by_their_words():
    assert is_open("rowing boat") and is_open("bark canoe") and is_open("dugout")
    assert not is_open("trawler boat") and not is_open("yacht")
    # (a rowing boat is drawn to its gunwale and stretched to its height: its floor is high in its box)
    assert deck_share("yacht", (3, 10, 9)) < deck_share("trawler", (4, 13, 5)) < deck_share("rowing boat", (1.5, 4.5, 1.2))


def test_a_tour_boat_carries_its_people_on_an_open_deck():
    from scenewright.analysis.parser import parse_scene

    boats = [o for o in parse_scene("Two small tour boats wait by the pier.").objects if o.name == "tour boat"]
    assert len(boats) == 2 and boats[0].size[1] > 5.0  # room for a crowd, small as they are
    assert is_open("tour boat boat") and deck_area("tour boat", boats[0].size)[3] > 0.5
