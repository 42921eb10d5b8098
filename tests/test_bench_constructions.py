"""The constructions bench: sentences of named shapes with annotations from how they were built."""

import json
from dataclasses import replace

from typer.testing import CliRunner

from scenewright.bench.analysis import score_prompt
from scenewright.bench.constructions import SHAPES, cases, run_constructions_bench
from scenewright.cli import app


def test_the_same_seed_writes_the_same_sentences_and_another_seed_others():
    first = [c.prompt.text for c in cases(5, seed=1)]
    assert first == [c.prompt.text for c in cases(5, seed=1)]
    assert first != [c.prompt.text for c in cases(5, seed=2)]
    assert len(first) == 5 * len(SHAPES)


def test_every_annotation_names_things_its_sentence_names():
    """An annotation key is a catalogue category or the word itself; either way the sentence
    says the thing, and every relation joins keys the annotation counts."""
    for case in cases(10, seed=3):
        prompt = case.prompt
        assert prompt.objects and all(lo >= 1 for lo, _ in prompt.objects.values())
        for source, _, target in prompt.relations:
            assert source in prompt.objects and target in prompt.objects, prompt.text
        for source, first, second in prompt.between:
            assert {source, first, second} <= set(prompt.objects)


def test_a_shape_the_reader_handles_scores_and_a_wrong_annotation_does_not():
    """The scoring is the parse bench's: a sentence read right scores full, and the same sentence
    with a relation it does not state is a miss, so the figures can fall."""
    case = next(c for c in cases(20, seed=0, shapes=["on_host"]) if score_prompt(c.prompt)["relations_recalled"])
    row = score_prompt(case.prompt)
    assert row["relations_recalled"] == row["relations_expected"] == 1
    (source, _, target), = case.prompt.relations
    wrong = replace(case.prompt, relations=frozenset({(source, "behind", target)}))
    assert score_prompt(wrong)["relations_recalled"] == 0


def test_the_cli_prints_figures_per_shape_with_misread_sentences():
    result = CliRunner().invoke(app, ["bench", "constructions", "--per-shape", "3", "--failures", "1", "--json"])
    assert result.exit_code == 0, result.output
    figures = json.loads(result.output)
    assert figures["sentences"] == 3 * len(SHAPES)
    assert set(figures["shapes"]) == set(SHAPES)
    for shape in figures["shapes"].values():
        assert 0.0 <= shape["read_right"] <= 1.0 and len(shape["misread"]) <= 1


def test_plain_place_phrases_are_read():
    """A guard for the reader: a subject, a verb and one place phrase is the commonest shape."""
    figures = run_constructions_bench(per_shape=20, seed=5, failures=0)["shapes"]
    assert figures["plain"]["relation_recall"] >= 0.85
    assert figures["on_host"]["read_right"] >= 0.9
