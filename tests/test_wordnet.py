"""WordNet's nouns as the reader reaches them: binary search over the shipped files, senses in
frequency order, kinds within the sense's own kind, and a plain "unknown" without the data."""

from __future__ import annotations

import pytest

from scenewright.analysis.parser import wordnet
from scenewright.analysis.parser.vocabulary import load_vocabulary


def test_the_first_and_the_last_entries_of_the_sorted_files_are_found():
    index = wordnet._folder() / "index.noun"
    assert wordnet._search(index, wordnet._lemma, b"'hood") and wordnet._search(index, wordnet._lemma, b"zyrian")
    assert wordnet._synset(15300051) is not None  # the last synset of data.noun
    assert wordnet.senses("zorbulator") == () and wordnet.names_a_thing("zorbulator") is None


def test_names_of_people_are_no_sense_of_a_common_noun():
    assert wordnet.senses("heron")[0].lexname == "noun.animal"  # not Heron the mathematician


def test_only_words_that_can_name_something_seen_are_things():
    assert wordnet.names_a_thing("cormorant") and wordnet.names_a_thing("logbook") and wordnet.names_a_thing("crew")
    assert wordnet.names_a_thing("bout") is False and wordnet.names_a_thing("trial") is False


def test_kinds_run_nearest_first_and_stay_within_their_own_kind_of_sense():
    assert list(wordnet.kinds("sampan"))[:3] == ["skiff", "small boat", "boat"]
    assert "agent" not in list(wordnet.kinds("beer"))  # beer is a drink, not a chemical agent


@pytest.mark.parametrize(
    "word, family",
    [("musher", "figure"), ("cormorant", "bird"), ("spaniel", "dog"), ("mare", "horse"), ("sampan", "boat"),
     ("aardvark", "animal"), ("gator", "animal")],
)  # fmt: skip
def test_a_word_nobody_listed_takes_the_nearest_kind_the_catalogue_draws(word, family):
    assert load_vocabulary().guess(word).category == family


def test_without_the_data_every_word_is_unknown_and_the_reader_keeps_its_own_rules(monkeypatch):
    monkeypatch.setattr(wordnet, "_folder", lambda: None)
    wordnet._entry.cache_clear()
    try:
        assert wordnet.names_a_thing("cormorant") is None
        assert load_vocabulary().guess("cormorant").category == "thing"
    finally:
        wordnet._entry.cache_clear()


def test_the_top_of_the_tree_still_names_things():
    assert wordnet.names_a_thing("animal") and wordnet.names_a_thing("person")  # noun.Tops, as "event" is
