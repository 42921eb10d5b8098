"""Convex collision pieces: the right method per kind of mesh, and pieces that cover the mesh."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st

from scenewright.export.colliders import MAX_HULLS, Collider, coacd_available, collider


def _box(extents, centre) -> trimesh.Trimesh:
    box = trimesh.creation.box(extents=extents)
    box.apply_translation(centre)
    return box


def _table() -> trimesh.Trimesh:
    """A top on four legs: five separate closed parts, far from filling their hull."""
    parts = [_box((1.2, 0.8, 0.04), (0, 0, 0.73))]
    parts += [_box((0.05, 0.05, 0.71), (sx * 0.55, sy * 0.35, 0.355)) for sx in (-1, 1) for sy in (-1, 1)]
    return trimesh.util.concatenate(parts)


def _ring() -> trimesh.Trimesh:
    """One welded, closed body filling about a third of its hull."""
    return trimesh.creation.annulus(r_min=0.4, r_max=0.5, height=0.3)


def _inside(hull: trimesh.Trimesh, points: np.ndarray, tolerance: float) -> np.ndarray:
    """Which points lie in a convex hull: behind every face's plane."""
    anchors = hull.vertices[hull.faces[:, 0]]
    heights = points @ hull.face_normals.T - np.einsum("ij,ij->i", anchors, hull.face_normals)
    return (heights <= tolerance).all(axis=1)


def _covered(mesh: trimesh.Trimesh, piece: Collider, tolerance: float = 1e-6) -> bool:
    """Every vertex of the mesh lies in some piece."""
    inside = np.zeros(len(mesh.vertices), dtype=bool)
    for hull in piece.hulls:
        inside |= _inside(hull, np.asarray(mesh.vertices), tolerance)
    return bool(inside.all())


def test_a_convex_mesh_is_its_hull():
    piece = collider(_box((1, 2, 3), (0, 0, 1.5)))
    assert piece.method == "hull" and len(piece.hulls) == 1
    assert piece.volume == pytest.approx(6.0)
    assert piece.notes == []


def test_a_table_keeps_the_space_under_its_top_free():
    piece = collider(_table())
    assert piece.method == "parts" and len(piece.hulls) == 5
    under_top = np.array([[0.0, 0.0, 0.3]])
    assert not any(_inside(h, under_top, 0.0)[0] for h in piece.hulls)
    assert piece.volume == pytest.approx(_table().split()[0].volume + 4 * 0.05 * 0.05 * 0.71, rel=0.05)


def test_many_parts_are_grouped_into_at_most_max_hulls():
    books = trimesh.util.concatenate(
        [_box((0.03, 0.2, 0.25), (-1 + 0.045 * k, 0, 0.125 + 0.3 * (k % 3))) for k in range(60)]
    )
    piece = collider(books)
    assert piece.method == "parts" and 1 < len(piece.hulls) <= MAX_HULLS
    assert _covered(books, piece)
    assert sum(piece.weights) == pytest.approx(piece.volume, rel=1e-6)


def test_a_non_watertight_mesh_still_gets_a_hull_and_a_note():
    open_box = _box((1, 1, 1), (0, 0, 0.5))
    open_box.update_faces(np.arange(len(open_box.faces)) >= 2)  # drop one side's two triangles
    assert not open_box.is_watertight
    piece = collider(open_box, use_coacd=False)
    assert len(piece.hulls) >= 1 and all(h.is_watertight for h in piece.hulls)
    assert any("not watertight" in note for note in piece.notes)


def test_a_concave_body_without_coacd_falls_back_to_its_hull_and_says_so():
    shape = _ring()
    piece = collider(shape, use_coacd=False)
    assert piece.method == "hull" and len(piece.hulls) == 1
    assert any("CoACD is not installed" in note for note in piece.notes)


@pytest.mark.skipif(not coacd_available(), reason="CoACD (the 'sim' extra) is not installed")
def test_coacd_splits_a_concave_body():
    shape = _ring()
    piece = collider(shape, use_coacd=True)
    assert piece.method == "coacd" and len(piece.hulls) >= 2
    assert sum(h.volume for h in piece.hulls) < 0.8 * shape.convex_hull.volume


def test_pieces_round_trip_through_bytes():
    piece = collider(_table())
    back = Collider.from_bytes(piece.to_bytes())
    assert back.method == piece.method and back.notes == piece.notes and back.weights == piece.weights
    assert [len(h.vertices) for h in back.hulls] == [len(h.vertices) for h in piece.hulls]
    assert np.allclose(back.hulls[0].vertices, piece.hulls[0].vertices)


def test_a_mesh_without_volume_is_refused_with_a_reason():
    with pytest.raises(ValueError, match="fewer than three"):
        collider(trimesh.Trimesh(vertices=[[0, 0, 0], [0, 0, 0], [0, 0, 0]], faces=[[0, 1, 2]], process=False))


boxes = st.lists(
    st.tuples(
        st.tuples(*[st.floats(0.02, 0.6)] * 3),
        st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.3, 1)),
    ),
    min_size=1,
    max_size=40,
)


@settings(max_examples=25, deadline=None)
@given(boxes)
def test_every_vertex_of_any_set_of_boxes_is_inside_some_piece(specs):
    mesh = trimesh.util.concatenate([_box(e, c) for e, c in specs])
    piece = collider(mesh, use_coacd=False)
    assert 1 <= len(piece.hulls) <= MAX_HULLS
    assert all(h.volume > 0 for h in piece.hulls)
    assert _covered(mesh, piece, tolerance=1e-5)
