"""Outdoors, a thing made for a wall stands on a post; indoors and on a host it stays as it was."""

from scenewright.analysis.composition.mounts import on_posts, over_holders
from scenewright.analysis.parser import ParsedObject, ParsedRelation, ParsedScene
from scenewright.core.catalogue import POST, POSTED


def _scene(indoor: bool, relations) -> ParsedScene:
    mirror = ParsedObject("mirror_1", "mirror", "mirror", "oval mirror", (0.6, 0.04, 0.9), 0)
    kiosk = ParsedObject("kiosk_1", "kiosk", "kiosk", "kiosk", (2.0, 2.0, 2.6), 1)
    bench = ParsedObject("bench_1", "bench", "bench", "bench", (1.6, 0.6, 0.85), 2)
    return ParsedScene("", [mirror, kiosk, bench], relations, "realistic", "grass", indoor)


def test_outdoors_a_wall_thing_on_nothing_stands_on_a_post_behind_what_it_hangs_over():
    out = on_posts(_scene(False, [ParsedRelation("mirror_1", "above", "bench_1")]))
    mirror = out.objects[0]
    assert mirror.size[2] == 0.9 + POST and mirror.rests == "ground" and POSTED in mirror.description
    assert [(r.relation, r.target) for r in out.relations] == [("behind", "bench_1")]
    guessed = on_posts(_scene(False, [ParsedRelation("mirror_1", "above", "bench_1", inferred=True)]))
    assert guessed.relations[0].relation == "near"  # a guessed "above" gives a place, not a height


def test_outdoors_a_light_the_reader_only_guessed_hanging_stands_on_a_post():
    """"Paper lanterns hang from the eaves" with no eaves read: hung over the nearest thing, a
    guess, it would float; on a post it stands near that thing. A stated ``above`` stays, and
    what is no light (a drone "hovering over the field", read as hanging) keeps flying."""
    lamp = ParsedObject("lantern_1", "lantern", "lantern", "paper lantern", (0.25, 0.25, 0.4), 3)
    scene = _scene(False, [ParsedRelation("lantern_1", "above", "bench_1", inferred=True)])
    out = on_posts(ParsedScene("", [*scene.objects, lamp], scene.relations, "realistic", "grass", False))
    assert out.objects[-1].size[2] == 0.4 + POST and POSTED in out.objects[-1].description
    assert [(r.relation, r.target) for r in out.relations] == [("near", "bench_1")]
    said = ParsedScene("", [*scene.objects[1:], lamp], [ParsedRelation("lantern_1", "above", "bench_1")], "realistic", "grass", False)
    assert on_posts(said) == said
    indoor = ParsedScene("", [*scene.objects, lamp], scene.relations, "realistic", "wood", True)
    assert on_posts(indoor) == indoor
    drone = ParsedObject("drone_1", "drone", "drone", "drone", (0.6, 0.6, 0.2), 3)
    flying = ParsedScene("", [*scene.objects[1:], drone], [ParsedRelation("drone_1", "above", "bench_1", inferred=True)],
                         "realistic", "grass", False)
    assert on_posts(flying) == flying


def test_indoors_or_on_a_host_a_wall_thing_stays_as_it_was():
    indoor = _scene(True, [ParsedRelation("mirror_1", "above", "bench_1")])
    assert on_posts(indoor) == indoor
    hung = _scene(False, [ParsedRelation("mirror_1", "on", "kiosk_1")])
    assert on_posts(hung) == hung


def test_a_guessed_above_over_a_held_thing_moves_to_its_holder():
    """"Garlic hangs from the rafters" guessed over the whisk a cook holds hangs over the cook."""
    cook = ParsedObject("figure_1", "figure", "cook", "cook", (0.5, 0.3, 1.75), 0)
    whisk = ParsedObject("whisk_1", "thing", "whisk", "whisk", (0.3, 0.1, 0.1), 1, guessed=True)
    garlic = ParsedObject("garlic_1", "thing", "garlic", "garlic", (0.3, 0.3, 0.3), 2, guessed=True)
    held = ParsedRelation("whisk_1", "on", "figure_1")
    out = over_holders(ParsedScene("", [cook, whisk, garlic], [held, ParsedRelation("garlic_1", "above", "whisk_1", inferred=True)],
                                   "realistic", "wood", True))
    assert out.relations[1].target == "figure_1"
    said = ParsedScene("", [cook, whisk, garlic], [held, ParsedRelation("garlic_1", "above", "whisk_1")], "realistic", "wood", True)
    assert over_holders(said) == said  # what the text says stands
