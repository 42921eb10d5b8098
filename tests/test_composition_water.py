"""The water prior: what floats starts on the water beyond the shore, the rest on land, a pier across it.

The sentences are written for these tests (not taken from the benchmark texts), so they test the rules."""

from __future__ import annotations

import pytest

from scenewright.analysis.arrange import compose
from scenewright.analysis.composition.water import floats
from scenewright.analysis.parser import detect_water, parse_scene


@pytest.mark.parametrize("text", [
    "A quiet lakeside at dusk: a canoe rests by a tent and a kettle sits on a camp stove.",
    "Two anglers sit on the river bank with their rods.",
    "On the far bank, a heron watches a mill.",
    "A busy ferry quay with a ticket booth and three benches.",
    "A cove with a rowing boat and a beach hut.",
])  # fmt: skip
def test_a_setting_by_open_water_reads_as_water(text):
    assert parse_scene(text).water
    assert detect_water(text, indoor=False)


@pytest.mark.parametrize("text", [
    "A frozen lake with two skaters and a bench; fir trees line the far shore.",
    "A garden with a duck pond, a bench and a birdbath.",
    "A bank robbery: two robbers run from the bank to a getaway car.",
    "A kitchen with a sea-blue fridge and a table; a window looks out on the sea.",
    "A meadow with three cows and an oak tree.",
])  # fmt: skip
def test_frozen_water_a_pond_a_money_bank_and_a_room_have_no_water(text):
    assert not parse_scene(text).water


def test_what_floats_is_read_from_its_kind_and_what_the_text_says_it_does():
    text = ("Two dinghies bob at their moorings. An otter swims past a moored punt, and a kayak lies upside "
            "down on the pebbles. A goose waddles after a lantern that floats above the path.")
    assert floats("dinghy", "boat", text)
    assert floats("punt", "thing", text)  # a vessel by its head word
    assert floats("otter", "animal", text)
    assert not floats("kayak", "boat", text)  # ashore
    assert not floats("goose", "bird", text)
    assert not floats("lantern", "lantern", text)  # up in the air
    text = "Two swans glide past a crate. Swimming ducks follow a wrecked canoe."
    assert floats("duck", "bird", text) and not floats("canoe", "boat", text)
    assert not floats("crate", "crate", text)  # what a swimmer passes does not swim


def _ground(composition):
    return [o for o in composition.objects if o.position.z - o.size.z / 2 < 0.05]


def test_boats_start_on_the_water_and_the_rest_on_land_behind_one_shore():
    text = ("A small marina on a sunny afternoon. A yacht and a motor launch float beyond a ticket kiosk, "
            "a vendor stands beside an ice cream cart, and two benches face a lamp post. A pelican paddles "
            "near the yacht.")
    parsed = parse_scene(text)
    composition = compose(parsed)
    assert composition.shore is not None
    for o in _ground(composition):
        afloat = floats(o.name, o.category, text)
        if afloat:
            assert o.position.y - o.size.y / 2 > composition.shore, o.id
        else:
            assert o.position.y < composition.shore, o.id
    assert sum(floats(o.name, o.category, text) for o in _ground(composition)) >= 2


def test_a_pier_runs_from_the_shore_out_over_the_water_with_its_boats_moored_alongside():
    text = "A harbour at dawn. Two sailing boats are tied up beside a wooden jetty, and a crate stands by a shed."
    composition = compose(parse_scene(text))
    by_id = {o.id: o for o in composition.objects}
    pier = next(o for o in composition.objects if o.category == "pier")
    assert pier.rotation.z in (90.0, -90.0)  # its length runs away from the viewer
    near_end = pier.position.y - pier.size.x / 2
    assert near_end < composition.shore < pier.position.y + pier.size.x / 2
    boats = [o for o in composition.objects if o.category == "boat"]
    assert len(boats) == 2
    for boat in boats:
        assert boat.position.y - boat.size.y / 2 > composition.shore
        assert abs(boat.position.x - pier.position.x) < pier.size.y / 2 + boat.size.x / 2 + 0.5  # alongside
    assert by_id["shed_1"].position.y < composition.shore


def test_a_scene_on_dry_land_has_no_shore():
    assert compose(parse_scene("A park with a bench, a lamp post and two oak trees.")).shore is None


def test_a_group_with_its_floating_thing_behind_the_rest_straddles_the_shore():
    text = "A quiet river bank at dawn. A heron wades behind an old angler who sits on a folding stool."
    composition = compose(parse_scene(text))
    by_id = {o.id: o for o in composition.objects}
    assert by_id["heron_1"].position.y > composition.shore > by_id["stool_1"].position.y


def test_a_boat_the_text_sets_nowhere_moors_at_the_pier_before_the_swimmers_take_the_spots():
    text = ("A small harbour on a grey day. Two swans glide past a crate. A ferry is tied up beside a stone "
            "jetty. A dinghy bobs in the water, and a net hangs on a shed.")
    composition = compose(parse_scene(text))
    pier = next(o for o in composition.objects if o.category == "pier")
    dinghy = next(o for o in composition.objects if o.name == "dinghy")
    gap = abs(dinghy.position.x - pier.position.x) - pier.size.y / 2 - dinghy.size.x / 2
    assert gap < 1.0 and dinghy.position.y > composition.shore


def test_diving_birds_are_in_the_water():
    text = "Four boats drift on the river, and the cormorants dive around the boats. A heron stands on the bank."
    assert floats("cormorant", "bird", text) and not floats("heron", "bird", text)


def test_a_pier_with_a_dry_thing_beside_it_still_reaches_out_and_the_thing_waits_on_the_shore():
    """"A parrot perches on a barrel beside the jetty": the barrel held the jetty (and its boat)
    on the sand, far from the water."""
    text = ("A pirate cove: a small wooden jetty runs out into the water, and a rowing boat is tied to the end of it. "
            "A parrot perches on a barrel beside the jetty.")
    composition = compose(parse_scene(text))
    by_id = {o.id: o for o in composition.objects}
    pier, barrel, boat = by_id["pier_1"], by_id["barrel_1"], by_id["boat_1"]
    assert pier.rotation.z in (90.0, -90.0)  # its length runs out over the water
    assert pier.position.y - pier.size.x / 2 < composition.shore < pier.position.y + pier.size.x / 2
    assert boat.position.y - boat.size.y / 2 > composition.shore
    assert barrel.position.y + barrel.size.y / 2 < composition.shore


def test_a_pier_or_a_mooring_sets_the_scene_by_water():
    assert parse_scene("Three fishermen stand on a trawler moored at the pier.").water
    assert parse_scene("A cat dozes at the end of a jetty.").water
    assert not parse_scene("A shuttle is docked in the hangar.").water


def test_who_works_a_moored_boat_from_land_waits_by_the_pier_while_the_boat_floats():
    """People who unload crates from a trawler moored at a pier stand on the shore by the pier's
    land end, with their crates; the trawler floats alongside the pier (before, the near ties made
    one unit of them all, and the trawler was left on land among the market stalls)."""
    text = ("A harbour fish market: fishermen unload crates of fish from a small trawler moored at the pier, "
            "and three stalls stand in a row along the quay.")
    composition = compose(parse_scene(text))
    by_id = {o.id: o for o in composition.objects}
    trawler = by_id["trawler_1"]
    assert trawler.position.y - trawler.size.y / 2 > composition.shore
    for o in composition.objects:
        if o.name in ("fisherman", "crate", "stall"):
            assert o.position.y < composition.shore, o.id


def test_an_icy_shore_still_lies_by_open_water_and_floes_and_lurkers_are_in_it():
    assert detect_water("A penguin colony on an icy shore at the edge of the sea.", False)
    assert not detect_water("Skaters on a frozen lake by the shore.", False)
    text = "A leopard seal lurks in the water near the floe. A heron stands on a rock by the water."
    assert floats("ice floe", "rock", text) and floats("leopard seal", "animal", text)
    assert not floats("heron", "bird", text)


def test_a_scene_on_the_sea_floor_lies_under_the_water_not_by_it():
    assert not detect_water("The ruins of a sunken city on the sea floor. Two divers swim past its columns.", False)
    assert not detect_water("An underwater kelp farm on the floor of a cold northern bay.", False)
    assert detect_water("A harbour at dawn, with fishing boats at the quay.", False)
