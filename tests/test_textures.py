"""Ground textures: seamless, distinct per kind and per style, reachable from free text."""

from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image

from scenewright.backends import create_backend
from scenewright.errors import InputError
from scenewright.backends.procedural_images import ProceduralImages
from scenewright.procedural.textures import KINDS, ground_texture, normalise_kind
from scenewright.scene import STYLES
from scenewright.settings import Settings


def seamless(image: np.ndarray) -> bool:
    """The step across each wrapped border is no larger than the largest step inside the tile."""
    a = image.astype(float)
    for axis in (0, 1):
        steps = np.abs(np.diff(a, axis=axis)).mean(axis=(1 - axis, 2) if axis == 0 else (0, 2))
        wrap = np.abs(a.take(0, axis=axis) - a.take(-1, axis=axis)).mean()
        if wrap > steps.max():
            return False
    return True


def test_the_seam_check_catches_a_seam():
    gradient = np.repeat(np.linspace(0, 255, 64)[None, :, None], 64, axis=0).repeat(3, axis=2).astype(np.uint8)
    assert not seamless(gradient)


@pytest.mark.parametrize("style", STYLES)
@pytest.mark.parametrize("kind", KINDS)
def test_every_kind_and_style_tiles(kind, style):
    image = ground_texture(kind, style, seed=3, size=128)
    assert image.shape == (128, 128, 3) and image.dtype == np.uint8
    assert seamless(image)
    assert image.std() > 1.0, "a texture, not a flat colour"


def difference(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.abs(a.astype(float).mean(axis=(0, 1)) - b.astype(float).mean(axis=(0, 1))).sum()
                 + abs(a.astype(float).std() - b.astype(float).std()))


def test_kinds_differ():
    images = {k: ground_texture(k, "realistic", seed=1, size=128) for k in KINDS}
    for i, a in enumerate(KINDS):
        for b in KINDS[i + 1 :]:
            assert difference(images[a], images[b]) > 5, (a, b)


def test_styles_differ():
    images = {s: ground_texture("cobblestone", s, seed=1, size=128) for s in STYLES}
    for i, a in enumerate(STYLES):
        for b in STYLES[i + 1 :]:
            assert np.abs(images[a].astype(float) - images[b].astype(float)).mean() > 8, (a, b)


@pytest.mark.parametrize(
    ("kind", "text", "expected"),
    [
        ("wooden floor", "", "wood_floor"), ("cobblestone street", "", "cobblestone"), ("Grass", "", "grass"),
        ("metal_deck", "", "metal_deck"), ("floor", "a cozy bedroom with a thick carpet", "carpet"),
        ("ground", "a sandy beach at sunset", "sand"), ("", "", "concrete"), ("lawn", "", "grass"),
    ],
)
def test_kind_names(kind, text, expected):
    assert normalise_kind(kind, text) == expected


def test_offline_images_backend():
    images = create_backend("images", "offline", Settings())
    assert isinstance(images, ProceduralImages) and images.name == "offline"
    assert images.reference_image("a park", "cartoon") is None
    assert images.object_images([], "cartoon", None) == {}
    png = images.ground_texture("a park with a fountain", "cartoon", "grass", None)
    picture = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))
    assert picture.shape == (512, 512, 3) and seamless(picture)
    assert png == images.ground_texture("a park with a fountain", "cartoon", "grass", None)
    with pytest.raises(InputError, match="no argument"):
        ProceduralImages.from_spec("x", Settings())


def test_every_ground_kind_the_parser_writes_has_its_own_texture():
    from scenewright.analysis.parser import GROUND_KINDS

    for kind in GROUND_KINDS:
        assert kind == "concrete" or normalise_kind(kind) != "concrete", kind
