"""Colour words: one table for the reader's palettes and the procedural surfaces."""

from __future__ import annotations

import pytest

from scenewright.core.colours import COLOURS, MATERIAL_COLOURS, palette
from scenewright.core.styles import named_colours
from scenewright.procedural.material import MATERIALS


@pytest.mark.parametrize(
    "text, names",
    [
        ("sage green and brick red", ["green", "red"]),  # a word before a colour word qualifies it
        ("navy blue on white linen", ["navy blue", "white"]),  # a colour before a material is the colour
        ("in dark walnut and pale gold leaf", ["dark walnut", "pale gold"]),  # a material's own colour
        ("a crimson-and-cream check", ["crimson", "cream"]),
        ("red, red and more red", ["red"]),
        ("faded reds and ochres", ["red", "ochre"]),  # plurals name the colour
        ("a quiet evening", []),
    ],
)
def test_a_palette_is_each_colour_once_in_order(text, names):
    assert [words for words, _ in palette(text)] == names


def test_a_look_word_names_no_colour_of_its_own():
    assert named_colours("stained glass") == [] and named_colours("copper plate engraving") == []
    assert [w for w, _ in named_colours("blue and white porcelain")] == ["blue", "white"]


def test_materials_draw_in_the_colour_the_palette_reads():
    assert all(surface.color == MATERIAL_COLOURS[name] for name, surface in MATERIALS.items())
    assert palette("ochre")[0][1] == COLOURS["ochre"]


def test_mud_is_a_colour_water_takes():
    assert named_colours("three pigs in a mud pool") and named_colours("a muddy stream")
