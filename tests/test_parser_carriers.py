"""People and animals on or in what carries them: seats, vehicles, ridden animals, perches and
containers ("in" read as "on", as the annotations read it), "from" a perch, a posture verb's
"in it", living things a holder is full of, a seat apiece."""

import pytest

from scenewright.analysis.parser import parse_scene


def rels(text: str) -> set[tuple[str, str, str]]:
    return {(r.source, r.relation, r.target) for r in parse_scene(text).relations if not r.inferred}


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a living thing in a vehicle, a seat, a container, a bed: on it
        ("A bus with four children in it waits by the school gate.", ("child_4", "on", "bus_1")),
        ("A rabbit sleeps in a wicker basket by the fire.", ("rabbit_1", "on", "basket_1")),
        ("A small cage with a white rabbit inside stands on the counter.", ("rabbit_1", "on", "cage_1")),
        ("A nurse talks to an old patient who lies in the bed by the window.", ("patient_1", "on", "bed_1")),
        # the relative clause's subject is the noun it follows, not the sentence's subject
        ("A barber stands on a mat, bent over a sleepy client who sits in the chair.", ("client_1", "on", "chair_1")),
        # "the water" is the water of the pond named before
        ("Two swans glide across a wide pond. A duck swims in the water.", ("bird_1", "on", "pond_1")),
        # a part of a vehicle places by the vehicle, not by the nearer barn
        ("A tractor stands by the barn, and a boy sits on its bonnet.", ("boy_1", "on", "tractor_1")),
        # "from" a perch after a verb one does from where one is
        ("A heron watches the pond from a flat rock.", ("heron_1", "on", "rock_1")),
        # a platform's middle holds what stands in it
        ("A grandstand faces the pitch, and the mayor sits on a throne in the centre of it.", ("throne_1", "on", "grandstand_1")),
        # "rides" puts the rider on what is ridden
        ("A farmer rides a tractor across the field, and his dog runs beside it.", ("farmer_1", "on", "tractor_1")),
        # one who drives, steers or pilots a vehicle is aboard it; two ride a mount
        ("A farmhand drives a quad bike along the fence.", ("farmhand_1", "on", "bicycle_1")),
        ("A bargee steers the narrowboat under the bridge.", ("bargee_1", "on", "narrowboat_1")),
        ("Two children ride a giant tortoise past the gift shop.", ("child_2", "on", "tortoise_1")),
        # what one does from a perch with nothing acted on is done up there, from a part of it too
        ("A village green. A fiddler plays from the back of a hay cart.", ("fiddler_1", "on", "cart_1")),
        # "its" names no person: the boat's bow, not the fisherman's
        ("An old fisherman sits in his boat by the jetty, and a gull perches on its bow.", ("gull_1", "on", "boat_1")),
        # a sitting person's own seat is the one they sit on
        ("An old woman sits knitting by the fire, her cat curled beside her chair.", ("woman_1", "on", "chair_1")),
    ],
)
def test_on_what_carries_them(text, expected):
    assert expected in rels(text)


def test_a_posture_verbs_it_names_the_seat_not_the_nearer_subject():
    found = rels("A bookcase stands beside an armchair, and an old sailor dozes in it.")
    assert ("sailor_1", "on", "armchair_1") in found
    assert not any(r[0] == "sailor_1" and r[2] == "bookshelf_1" for r in found)


def test_a_posture_verbs_them_names_several_seats_one_each():
    found = rels("Two armchairs stand by the shelves, and two boys doze in them.")
    assert {("boy_1", "on", "armchair_1"), ("boy_2", "on", "armchair_2")} <= found


def test_in_a_tower_or_a_dome_is_inside_it_not_on_top():
    assert not any(r[0] == "keeper_1" for r in rels("A keeper sits in the lighthouse."))
    assert not any(r[0] == "man_1" for r in rels("A young man stands in the dome."))
    assert ("man_1", "on", "stage_1") in rels("A young man stands in the stage.")


def test_an_animals_it_is_what_stands_on_the_ground_not_a_hung_lamp():
    found = rels("A chandelier hangs from the ceiling above the table, and a cat naps on it.")
    assert ("cat_1", "on", "table_1") in found


def test_from_after_a_verb_of_taking_places_nobody():
    found = rels("A sailor pulls a rope from the barrel.")
    assert not any(r[0] == "sailor_1" and r[1] == "on" for r in found)


def test_living_things_a_holder_is_full_of_are_on_it_and_no_subject():
    found = rels("A rowing boat packed with laughing children drifts past the pier.")
    assert {(f"child_{i}", "on", "boat_1") for i in (1, 2, 3)} <= found
    assert not any(r[0].startswith("child") and r[2] == "pier_1" for r in found)
    found = rels("Three baskets sit by the stove, each of them full of kittens.")
    assert {("cat_1", "on", "basket_1"), ("cat_2", "on", "basket_2"), ("cat_3", "on", "basket_3")} <= found


def test_a_seat_apiece():
    parsed = parse_scene("Four pilots sit at the console, each in a leather seat.")
    assert [o.category for o in parsed.objects].count("chair") == 4
    assert {(f"pilot_{i}", "on", f"chair_{i}") for i in (1, 2, 3, 4)} <= rels(parsed.text)
    parsed = parse_scene("Two riders on horseback wait by the gate.")
    assert [o.category for o in parsed.objects].count("horse") == 2
    assert {("rider_1", "on", "horse_1"), ("rider_2", "on", "horse_2")} <= rels(parsed.text)


def test_seated_at_a_counter_the_sitter_is_at_it_too():
    found = rels("A clerk sits on a high stool at the counter.")
    assert {("clerk_1", "on", "stool_1"), ("clerk_1", "near", "counter_1")} <= found


def test_seated_across_from_a_thing_the_sitter_faces_it():
    found = rels("A robot stands in the middle, and a boy sits on an old crate across from it.")
    assert {("boy_1", "on", "crate_1"), ("boy_1", "in front of", "robot_1"), ("boy_1", "face to", "robot_1")} <= found
    assert not any(r[0] == "crate_1" and r[2] == "robot_1" for r in found)


def test_people_and_animals_perch_on_hosts_smaller_than_they_are():
    parsed = parse_scene("A big dog stands on a low stool. A lynx crouches on a boulder.")
    found = {(r.source, r.relation, r.target) for r in parsed.relations}
    assert {("dog_1", "on", "stool_1"), ("lynx_1", "on", "rock_1")} <= found
    assert not parsed.repairs


def test_a_cage_hung_from_the_ceiling_hangs_and_holds_its_bird():
    parsed = parse_scene("A small cage with a canary inside hangs from the ceiling above the desk.")
    cage = next(o for o in parsed.objects if o.id == "cage_1")
    assert cage.rests == "hanging"
    assert ("canary_1", "on", "cage_1") in {(r.source, r.relation, r.target) for r in parsed.relations}
    assert not parsed.repairs


def test_it_is_never_what_the_subject_rests_on():
    found = rels("A tabby cat dozes under the desk, and a canary in a cage watches it.")
    assert {("canary_1", "on", "cage_1"), ("canary_1", "face to", "cat_1")} <= found


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a vehicle's "its" person is its crew, aboard
        ("A red bus idles at the stop, its driver waving to a boy.", {("driver_1", "on", "bus_1")}),
        # at a vehicle's perch part (its prow, stern, deck) is on the vehicle
        ("A rowing boat lies on the sand, and a fisherman stands at its stern.", {("fisherman_1", "on", "boat_1")}),
        # things hung along a part of something are carried by it
        ("A market stall stands by the gate. Lanterns hang along the stall's front.",
         {("lantern_1", "on", "market_stall_1")}),
        # "a <carrier> of <living things>": they ride in it, no contents
        ("A tractor pulls a cart of bleating sheep towards the barn.", {("sheep_1", "on", "cart_1")}),
        ("A basket of puppies sits by the stove.", {("dog_1", "on", "basket_1")}),
        # "a N in each" after a group: one per member, in it
        ("Five hutches stand along the fence, a rabbit in each.", {("rabbit_5", "on", "cabinet_5")}),
        # a small enclosure (a kennel, a coop) holds an animal as a cage does; a building does not
        ("Two hens doze in the little coop, and a farmer waits in the barn.", {("hen_2", "on", "coop_1")}),
        # climbing a thing is on it
        ("Two cat trees stand by the sofa, with four kittens climbing them.", {("cat_1", "on", "cat_tree_1")}),
        ("A boy climbs the ladder beside the shed.", {("boy_1", "on", "ladder_1")}),
    ],
)
def test_aboard_in_and_climbing(text, expected):
    assert expected <= rels(text)


def test_a_building_holds_no_one_and_food_is_a_crates_contents():
    assert not any(s.startswith("farmer") and r == "on" for s, r, _ in rels("A farmer waits in the barn."))
    parsed = parse_scene("Crates of fish are stacked by the stall.")
    assert [o.category for o in parsed.objects if o.category == "fish"] == []


def test_things_hung_from_posts_are_carried_by_them_one_post_each():
    """A post or a pole has no top to set a thing on, but what hangs from it is on it (no repair
    to "beside"); posts the text does not count come one per hung thing."""
    parsed = parse_scene("Eight paper lanterns hang from poles around the pond. A bell hangs from a post by the gate.")
    got = {(r.source, r.relation, r.target) for r in parsed.relations}
    assert ("lantern_8", "on", "pole_8") in got and ("bell_1", "on", "post_1") in got
    assert not parsed.repairs


def test_a_sitter_s_seat_after_a_larger_place_seats_the_sitter():
    """"An ogre sits beside the barn on an upturned crate": the crate cannot carry the barn, so
    the phrase seats the ogre; a thing that does not sit leaves the chain as it is."""
    got = rels("An old ogre sits beside the barn on an upturned crate.")
    assert ("ogre_1", "on", "crate_1") in got and not any(s == "barn_1" and r == "on" for s, r, _ in got)


def test_counted_things_of_a_container_are_there_in_it():
    """"A nest of four speckled eggs": counted, so objects, in (on) the nest; "a vase of tulips"
    stays the vase's contents."""
    got = rels("A heron stands beside a nest of four speckled eggs.")
    assert ("egg_4", "on", "nest_1") in got
    parsed = parse_scene("A vase of tulips stands on the table.")
    assert [o.category for o in parsed.objects] == ["vase", "table"]


def test_people_in_an_open_shelter_stand_on_its_floor_and_a_band_is_people():
    parsed = parse_scene("A brass band plays in the pavilion while two girls sit in a gazebo by the lake.")
    found = {(r.source, r.relation, r.target) for r in parsed.relations}
    assert ("band_1", "on", "gazebo_1") in found and ("girl_1", "on", "gazebo_2") in found
    # a closed tent keeps whoever is inside out of the layout
    assert not parse_scene("A scout sleeps in the tent.").relations



def test_from_a_rim_or_an_edge_one_perches_on_its_owner():
    found = {(r.source, r.relation, r.target) for r in parse_scene("Two finches drink from the birdbath's rim.").relations}
    assert ("finch_1", "on", "bird_bath_1") in found


def test_a_plant_in_a_planter_stands_on_it_one_planter_each():
    """"Lemon trees grow in wooden planters": each tree on a planter of its own (planters with
    no count of their own), kept there by the support check although its crown is wider."""
    parsed = parse_scene("Three lemon trees grow in wooden planters along the terrace.")
    got = {(r.source, r.relation, r.target) for r in parsed.relations}
    assert {("tree_3", "on", "planter_3"), ("tree_1", "on", "planter_1")} <= got
    assert [o.category for o in parsed.objects].count("planter") == 3
    parsed = parse_scene("A bay tree stands in a big stone planter by the door.")
    assert ("tree_1", "on", "planter_1") in {(r.source, r.relation, r.target) for r in parsed.relations}
    assert not parsed.repairs


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a body part "of" someone carries as "her lap" does
        ("A toddler dozes on the lap of her grandmother by the stove.", ("toddler_1", "on", "grandmother_1")),
        ("A parrot rides on the shoulder of a pirate by the mast.", ("bird_1", "on", "pirate_1")),
        # "back" alone ends a phrase ("at the back"), but "the back of a horse" names the horse
        ("A girl sits on the back of a horse.", ("girl_1", "on", "horse_1")),
        # "has" with a participle and no object of its own is no "has" of owning
        ("A boy has fallen asleep on the lap of his uncle.", ("boy_1", "on", "uncle_1")),
        # ", who sits ..." after a living thing: that one sits there
        ("A toddler dozes on the lap of her grandmother, who sits in a rocking chair.", ("grandmother_1", "on", "chair_1")),
        ("A girl waves to her uncle, who stands on the pier.", ("uncle_1", "on", "pier_1")),
        # a verb that puts one "into" a seat or a vehicle
        ("Three karts wait at the line, each with a driver strapped into its seat.", ("driver_3", "on", "kart_3")),
        ("A farmer climbs into his tractor by the barn.", ("farmer_1", "on", "tractor_1")),
    ],
)
def test_on_a_person_or_a_vehicle_by_other_words(text, expected):
    assert expected in rels(text)


def test_a_body_part_of_someone_near_stays_near_and_the_sitter_is_not_the_sentence_subject():
    assert ("dog_1", "near", "shepherd_1") in rels("A puppy curls up at the feet of the old shepherd.")
    got = rels("A toddler dozes on the lap of her grandmother, who sits in a rocking chair.")
    assert ("toddler_1", "on", "chair_1") not in got and ("toddler_1", "on", "grandmother_1") in got


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a part one sits in or perches on names the thing that has it
        ("A glider waits on the field, and a pilot sits in the cockpit of the glider.", ("pilot_1", "on", "glider_1")),
        ("Sparrows drink from the birdbath's rim.", ("sparrow_3", "on", "bird_bath_1")),
        (
            "A birdbath stands on the lawn. Two sparrows bathe from the rim of the birdbath.",
            ("sparrow_2", "on", "bird_bath_1"),
        ),
    ],
)
def test_on_a_thing_by_its_seat_or_rim(text, expected):
    assert expected in rels(text)


def test_a_thing_taken_from_a_perch_noun_places_nobody_on_it():
    assert not any(r == "on" and t == "barrel_1" for _, r, t in rels("A cooper lifts a lid from the barrel."))


def test_pulling_on_a_rope_stands_nobody_on_it():
    """"Haul on ropes", "tugs on a rope": a deed on the thing, not a place to stand; the place
    phrase after it places the doers."""
    got = rels("Three deckhands heave on ropes beside the capstan.")
    assert ("deckhand_1", "side of", "capstan_1") in got and not any(r == "on" for _, r, _ in got)


def test_the_top_with_nothing_after_it_is_the_top_of_the_latest_tower():
    got = rels("A stone lighthouse guards the harbour, and a keeper peers out from the top.")
    assert ("keeper_1", "on", "lighthouse_1") in got
    assert not rels("A market stall sells pies, and a boy waves from the top.")


def test_sitting_in_a_row_is_sitting_on_one_of_the_seats_in_rows():
    """"Sits in the front row": one of the seats named in rows before (not the room's front);
    with no seats named there is nothing to sit on."""
    got = rels("Rows of pews face the pulpit. A widow sits in the front row, and her nephew waits by the door.")
    assert ("widow_1", "on", "bench_1") in got
    assert not any(s == "widow_1" and r == "on" for s, r, _ in rels("A widow sits in the front row."))


def test_where_clause_after_a_platform_puts_the_living_on_it():
    """", where a boy feeds the ducks" after a jetty: on the jetty, though his deed relates him
    to the ducks; after a thing one cannot stand on, near it as before."""
    got = rels("Three punts are moored by a long wooden jetty, where a girl throws crumbs to the gulls.")
    assert ("girl_1", "on", "pier_1") in got
    assert ("cat_1", "near", "stove_1") in rels("A stove stands in the corner, where a cat sleeps.")


def test_living_things_with_a_container_are_in_it():
    """"A pond with three ducks", "a cage with two parrots": the animals are in what they came
    with (a person's dog keeps by the person)."""
    found = {(r.source, r.relation, r.target) for r in parse_scene("A duck pond with three geese lies by the mill.").relations}
    assert {(f"goose_{i}", "on", "pond_1") for i in (1, 2, 3)} <= found
    found = {(r.source, r.relation, r.target) for r in parse_scene("A cage with two canaries hangs by the window.").relations}
    assert {("canary_1", "on", "cage_1"), ("canary_2", "on", "cage_1")} <= found
    assert ("dog_1", "near", "shepherd_1") in {(r.source, r.relation, r.target) for r in parse_scene("A shepherd with a dog.").relations}


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # climbing or sliding along a thing puts one on it ("climbs down from" leaves it)
        ("A tall mast rises from the quay, and a young deckhand shins up it.", ("deckhand_1", "on", "mast_1")),
        ("Two monkeys climb down a rope ladder beside the hut.", ("monkey_2", "on", "ladder_1")),
        # a part named "of" a thing named before is that thing's ("the cab of the crane")
        ("Two cranes stand by the dock, and a worker sits on the ladder of the taller one.", ("worker_1", "on", "crane_1")),
        # a carrier part nobody named picks one of the group before ("the first basket" of the
        # gondolas, which the catalogue reads as boats)
        ("Four gondolas hang from the cable. A skier waits in the first basket.", ("skier_1", "on", "boat_1")),
        # "in the back" of a vehicle this sentence names
        ("A rusty van is parked by the fence, a sleepy terrier in the back.", ("dog_1", "on", "truck_1")),
        ("A boy in the back of the jeep waves at the zebras.", ("boy_1", "on", "car_1")),
        # birds that perch or roost along a thing are on it
        ("A row of crows perch along the old wall of the barn.", ("crow_1", "on", "barn_1")),
        # one at a thing on a low wide perch stands on the perch too
        ("A priest stands at an altar on a low dais.", ("priest_1", "on", "dais_1")),
    ],
)
def test_on_what_carries_them_by_a_part_or_a_verb_of_going(text, expected):
    assert expected in rels(text)


def test_a_carrier_part_of_a_group_names_no_object_of_its_own():
    objects = [o.category for o in parse_scene("Four gondolas hang from the cable. A skier waits in the first basket.").objects]
    assert "basket" not in objects


def test_things_on_uncounted_stands_get_a_stand_each_as_many_as_they_come_to():
    parsed = parse_scene("Stone sculptures rest on plinths at each corner of the cloister.")
    stands = [o.id for o in parsed.objects if o.category == "pedestal"]
    assert len(stands) == 4
    assert {r.target for r in parsed.relations if r.relation == "on"} == set(stands)


def test_a_thing_set_down_on_the_floor_goes_on_no_table():
    parsed = parse_scene("A tailor works at a wide table. A teapot sits on the floor beside the door.")
    assert not any(r.source == "teapot_1" for r in parsed.relations if r.relation == "on")


def test_things_that_fill_shelves_are_on_them_and_the_shelves_take_the_next_phrase():
    found = rels("A potter sits at her wheel. Clay jugs fill three shelves on the wall behind her.")
    assert any(r[1] == "on" and r[2].startswith("bookshelf") for r in found)
    assert ("bookshelf_1", "behind", "potter_1") in found


def test_a_person_who_fills_a_thing_stands_by_it():
    assert not any(r[0] == "girl_1" and r[1] == "on" for r in rels("A girl fills a bucket at the pump."))


def test_a_with_list_placed_by_it_is_no_thing_in_hand():
    found = rels("A scribe sits at a desk, with a candle and two scrolls on it.")
    assert ("candle_1", "on", "desk_1") in found
    assert not any(r[0] == "scribe_1" and r[1] == "on" for r in found)


def test_on_it_after_one_who_works_at_a_thing_is_on_that_thing():
    found = rels("A jeweller sits at a bench across from the window, polishing a ring, with a loupe and two files on it.")
    assert {("loupe_1", "on", "bench_1"), ("file_2", "on", "bench_1")} <= found


def test_one_at_the_wheel_of_a_vehicle_this_sentence_names_is_on_it():
    assert ("man_1", "on", "tractor_1") in rels("A tractor rumbles up the lane, an old man at the wheel.")


def test_a_thing_hung_in_a_tower_is_carried_by_it():
    assert ("bell_1", "on", "tower_1") in rels("A bronze bell hangs in the old clock tower.")


def test_a_thing_a_relative_says_holds_another_bears_it_once():
    parsed = parse_scene("Five children dance around a maypole that holds up a paper lantern.")
    lanterns = [o.id for o in parsed.objects if o.category == "lantern"]
    assert len(lanterns) == 1
    assert not any(r.source == lanterns[0] and r.target.startswith("child") for r in parsed.relations)


def test_what_the_subject_works_after_a_fronted_surface_is_up_there_too():
    # (a bandstand is read as a gazebo)
    assert ("drum_kit_1", "on", "gazebo_1") in rels("On the bandstand, a bearded drummer plays a drum kit.")


def test_a_mirror_in_a_standing_form_stands_on_the_floor():
    mirror = next(o for o in parse_scene("A tailor pins a hem in front of a full-length mirror.").objects if o.category == "mirror")
    assert mirror.rests == "ground" and mirror.size[2] >= 1.6


def test_people_on_uncounted_ground_covers_are_on_them_one_each():
    parsed = parse_scene("Two boys do push-ups on blankets beside the tent.")
    blankets = [o.id for o in parsed.objects if o.category == "picnic_blanket"]
    assert len(blankets) == 2
    assert {(r.source, r.target) for r in parsed.relations if r.relation == "on"} >= {("boy_1", blankets[0])}


def test_a_load_pulled_onto_the_puller_rides_it_not_behind():
    found = rels("A recovery lorry winches a wrecked van onto its flatbed.")  # (both read as trucks)
    assert ("truck_2", "on", "truck_1") in found
    assert not any(r[1] == "behind" for r in found)


def test_what_one_wheels_on_a_barrow_is_on_the_barrow_not_in_hand():
    found = rels("Behind the stall, a gardener wheels a sack of soil on a barrow.")
    assert ("sack_1", "on", "barrow_1") in found
    assert not any(r[0] == "gardener_1" and r[1] == "on" for r in found)


def test_a_bird_that_sits_on_a_branch_is_on_the_tree_named_before():
    found = rels("A fox sleeps under an old beech tree, and a crow perches on a branch.")
    assert ("crow_1", "on", "tree_1") in found
    # (not without a verb of sitting: "a squirrel drops a nut on a branch" names no perch)
    assert not any(r[0] == "squirrel_1" and r[1] == "on" for r in rels("An oak stands by the wall. A squirrel drops a nut on a branch."))


def test_one_who_watches_from_what_carries_nobody_stands_by_it():
    found = rels("Two goats graze on the slope while a shepherd watches them from the fence.")
    assert ("shepherd_1", "near", "fence_1") in found
    assert ("heron_1", "on", "rock_1") in rels("A heron watches from a flat rock.")
    # (a plural's verb as well: "two teenagers dive from a rock")
    assert ("teenager_1", "on", "rock_1") in rels("A pool. Two teenagers dive from a high flat rock.")


def test_a_living_thing_in_a_container_put_somewhere_brings_the_container():
    found = rels("A clinic. A parrot in a cage perches on the reception desk.")
    assert {("cage_1", "on", "counter_1"), ("bird_1", "on", "cage_1")} <= found


def test_what_is_behind_a_towing_vehicle_is_behind_it_and_its_load_and_its_driver_drives_it():
    found = rels("A lane. A tractor towing a trailer waits at the barrier. Behind it queue a van and two cyclists.")
    assert {("truck_1", "behind", "tractor_1"), ("truck_1", "behind", "trailer_1"),
            ("cyclist_2", "behind", "tractor_1"), ("cyclist_2", "behind", "trailer_1")} <= found
    found = rels("A lane. A tractor towing a trailer waits at the barrier, its driver leaning out to watch.")
    assert ("driver_1", "on", "tractor_1") in found


@pytest.mark.parametrize(
    ("text", "expected", "absent"),
    [
        # one drinks from a thing by it, not on it; from a perch one is on it
        ("A street. A stray cat drinks from a puddle next to a rubbish bin.", ("cat_1", "near", "pond_1"), ("cat_1", "on", "pond_1")),
        ("A valley. Three stegosaurs drink from a water trough.", ("stegosaur_3", "near", "water_trough_1"), None),
        ("A canal. Two children feed ducks from a wooden footbridge.", ("child_2", "on", "bridge_1"), None),
    ],
)
def test_drinking_from_a_thing_is_by_it(text, expected, absent):
    found = rels(text)
    assert expected in found and absent not in found


def test_single_people_on_their_things_are_on_one_each():
    found = rels("A hall. The king and queen sit on their thrones.")
    assert {("king_1", "on", "throne_1"), ("queen_1", "on", "throne_2")} <= found


def test_one_in_the_doorway_of_a_building_stands_by_it_not_inside():
    assert ("keeper_1", "near", "house_1") in rels("The keeper stands in the doorway of his brick hut.")
    assert ("woman_1", "near", "barn_1") in rels("A woman waits in the entrance of the barn.")


def test_what_one_drives_that_is_no_vehicle_is_herded_and_a_vehicle_tows_for_its_driver():
    found = rels("A hillside. A collie drives five sheep towards a small pen.")
    assert not any(r[0] == "collie_1" and r[1] == "on" for r in found), found
    found = rels("A farm. A farmhand drives a quad bike along the fence, towing a small trailer.")
    assert ("trailer_1", "behind", "bicycle_1") in found, found


def test_one_who_leaves_a_perch_is_not_on_it():
    assert not any(r[1] == "on" for r in rels("A lay-by. A driver climbs from the cab of a lorry."))


def test_what_is_hitched_to_a_load_pulls_it_and_a_hitched_load_trails():
    assert ("mule_1", "in front of", "cart_1") in rels("A farm. A mule stands hitched to a cart.")
    assert ("cart_1", "behind", "horse_1") in rels("A farm. A cart hitched to a pony waits by the gate.")


def test_several_who_peek_out_of_a_thing_are_in_it():
    found = rels("Three baby wyverns peek out of a wicker basket at the foot of the table.")
    assert {("wyvern_1", "on", "basket_1"), ("basket_1", "in front of", "table_1")} <= found


@pytest.mark.parametrize(
    ("text", "rider", "carrier"),
    [
        ("Four knights ride on horses across the field.", "knight", "horse"),
        ("Four swimmers bob on rubber rings.", "swimmer", "rubber_ring"),
    ],
)
def test_riders_on_an_uncounted_plural_get_one_carrier_each(text, rider, carrier):
    """A horse, a swim ring, a bicycle carries one: "four knights ride on horses" was two knights
    on one of three horses."""
    found = rels(text)
    assert {(f"{rider}_{k}", "on", f"{carrier}_{k}") for k in range(1, 5)} <= found
    assert not any(t == f"{carrier}_5" for _, _, t in found)


def test_a_person_watching_from_a_thing_nobody_stands_on_is_at_it():
    assert rels("The captain watches from a console.") == {("captain_1", "near", "control_panel_1")}
    assert ("guard_1", "on", "tower_1") in rels("A guard watches from the tower.")
    assert ("sniper_1", "on", "barn_1") in rels("A sniper watches from the roof of the barn.")
    assert ("boy_1", "on", "father_1") in rels("A small boy watches from his father's shoulders.")


def test_a_thing_up_in_a_tree_is_on_it_and_a_house_grown_inside_one_is_not():
    found = rels("Two wooden platforms sit high up in tall pines on either side of a clearing.")
    assert {("platform_1", "on", "pine_tree_1"), ("platform_2", "on", "pine_tree_2")} <= found
    assert not any(r == "on" for _, r, _ in rels("A healing house is grown inside a living tree."))


def test_eating_from_a_hay_bale_is_beside_it_and_drinking_from_its_rim_on_it():
    assert rels("A cow eats from a hay bale.") == {("horse_1", "near", "hay_bale_1")}
    assert ("child_1", "on", "bridge_1") in rels("Two children feed ducks from a footbridge.")


def test_a_rider_named_after_a_buildings_door_rides_the_horse_not_the_building():
    found = rels("Three ghosts drift out of an old barn, and a headless horseman waits at its door on a black horse.")
    assert ("horseman_1", "on", "horse_1") in found and not any(s == "barn_1" for s, _, _ in found)


def test_a_bird_perches_on_what_it_watches_from_even_a_clock_on_the_wall():
    assert ("crow_1", "on", "weathervane_1") in rels("A crow watches them from the weathervane on the barn roof.")
    assert ("robin_1", "on", "wall_clock_1") in rels("A robin perches on top of the clock on the wall.")
