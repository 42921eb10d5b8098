"""The offline reader refuses text it cannot read, and says how to read it instead."""

import pytest

from scenewright.analysis.parser.language import check_english
from scenewright.analysis.parser.tokens import _tokenise
from scenewright.cli import main
from scenewright.errors import InputError


@pytest.mark.parametrize(
    "text",
    [
        "Une petite table en bois avec deux chaises et une lampe.",
        "Ein Tisch mit zwei Stühlen und einer Lampe neben dem Fenster.",
        "Una mesa con dos sillas junto a la ventana.",
        "Стол и два стула у окна",
        "一张桌子和两把椅子",
    ],
)
def test_other_languages_are_refused_with_the_way_out(text):
    with pytest.raises(InputError) as err:
        check_english(text)
    message = str(err.value)
    assert "reads English" in message and "--vlm openai:MODEL" in message


@pytest.mark.parametrize(
    "text",
    [
        "A café with three tables and a crêpe stand.",
        "Zen garden",
        "a sofa facing a TV",
        "Two camels, a dragon and a zorbulator near the oasis.",
        "Cyberpunk ramen bar",
        "Neo-Tokyo noodle stall at midnight",
    ],
)
def test_english_passes(text):
    check_english(text)


def test_accented_words_are_one_token():
    assert [t.text for t in _tokenise("A café and a crêpe")] == ["a", "café", "and", "a", "crêpe"]


def test_generate_refuses_another_language_with_exit_2(tmp_path, capsys):
    code = main(["generate", "Une petite table en bois avec deux chaises.", "--out", str(tmp_path / "s"), "--no-render"])
    assert code == 2
    assert "--vlm openai:MODEL" in capsys.readouterr().err
    assert not (tmp_path / "s" / "scene.glb").exists()
