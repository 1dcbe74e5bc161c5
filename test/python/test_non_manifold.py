# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Arrays whose faces are not an oriented 2-manifold are made a mesh as a
file's faces are: a bow-tie vertex or a non-manifold edge is split into one
copy per sheet (a UserWarning names it), so that no map crosses from one
sheet to another, and results name every copy by the caller's row."""

import numpy as np
import pytest

import expmap

CLASSES = [expmap.HeatExponentialMap, expmap.DiscreteExponentialMap,
           expmap.GeodesicPolarCoordinates, expmap.ExactExponentialMap]

# Two triangles touching at vertex 0 only.
BOW_TIE_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]], dtype=float)
BOW_TIE_F = np.array([[0, 1, 2], [0, 3, 4]])


@pytest.mark.parametrize("cls", CLASSES)
def test_a_bow_tie_vertex_is_split_and_each_sheet_mapped_alone(cls):
    with pytest.warns(UserWarning, match=r"split non-manifold vertex 0 into 1 extra copy"):
        mapper = cls(BOW_TIE_V, BOW_TIE_F)
    assert mapper.number_of_vertices == 5  # the caller's rows, not the copies
    sheets = ({0, 1, 2}, {0, 3, 4})
    for source in range(5):
        local = mapper.compute(source, fraction=1.0)
        rows = local.vertices.tolist()
        # One sheet, each of its vertices once, the split vertex by its row.
        assert len(rows) == 3 and len(set(rows)) == 3, (source, rows)
        assert set(rows) in sheets, (source, rows)
        assert local.source == source and rows[0] == source and local.r[0] == 0
        # The legs of the right triangle are 1 from the corner 0.
        if source == 0:
            assert np.all(np.abs(local.r[1:] - 1) < 0.2), local.r
    # The rows (1, 2) and (3, 4) are on different sheets whichever kept row 0.
    assert set(mapper.compute(1, fraction=1.0).vertices.tolist()) == {0, 1, 2}
    assert set(mapper.compute(3, fraction=1.0).vertices.tolist()) == {0, 3, 4}

    batch = mapper.compute_many([1, 3], vertices=3, threads=1)
    assert batch.failures == 0
    assert set(batch.vertex[batch.offsets[0]:batch.offsets[1]].tolist()) == {0, 1, 2}
    assert set(batch.vertex[batch.offsets[1]:batch.offsets[2]].tolist()) == {0, 3, 4}
    # A patch of rows takes the split vertex's copy on the source's sheet.
    assert set(mapper.compute(3, vertex_set=[0, 3]).vertices.tolist()) == {0, 3}
    batch = mapper.compute_many([1, 3], vertex_set=[0], threads=1)
    assert batch.failures == 0
    assert batch.vertex.tolist() == [1, 0, 3, 0]
    with pytest.raises(expmap.InvalidInput, match="not connected"):
        mapper.compute(1, vertex_set=[3])
    # A copy is no row of the caller's: out of range as a source.
    for bad in (5, 6):
        with pytest.raises(expmap.InvalidInput, match="out of range"):
            mapper.compute(bad, vertices=2)
        with pytest.raises(expmap.InvalidInput, match="out of range"):
            mapper.compute_many([bad], vertices=2)


@pytest.mark.parametrize("cls", CLASSES)
def test_a_non_manifold_edge_is_split(cls):
    # Three triangles on the edge (0, 1), fins at 90 degrees.
    V = np.array([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -1, 0], [0.5, 0, 1]], dtype=float)
    F = np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    with pytest.warns(UserWarning, match=r"split non-manifold vertices 0, 1 into \d+ extra copies"):
        mapper = cls(V, F)
    tips = {2, 3, 4}
    for source in sorted(tips):
        rows = mapper.compute(source, fraction=1.0).vertices.tolist()
        # Two fins joined at most: never all three tips through one edge.
        assert len(rows) == len(set(rows)) and set(rows) >= {0, 1, source}, (source, rows)
        assert not tips <= set(rows), (source, rows)


@pytest.mark.parametrize("cls", CLASSES)
def test_a_flipped_face_is_oriented_as_in_a_file(cactus, cls):
    _, V, F = cactus
    flipped = F.copy()
    flipped[100] = flipped[100, ::-1]
    with pytest.warns(UserWarning, match="reversed 1 faces"):
        repaired = cls(V, flipped)
    reference = cls(V, F).compute(7, vertices=40)
    local = repaired.compute(7, vertices=40)
    np.testing.assert_array_equal(local.vertices, reference.vertices)
    np.testing.assert_allclose(local.r, reference.r, rtol=0, atol=1e-12)
    np.testing.assert_allclose(local.uv, reference.uv, rtol=0, atol=1e-12)


def test_read_mesh_and_arrays_split_alike(tmp_path):
    path = tmp_path / "bow_tie.off"
    path.write_text("OFF\n5 2 0\n" + "".join("%g %g %g\n" % tuple(p) for p in BOW_TIE_V) +
                    "3 0 1 2\n3 0 3 4\n")
    with pytest.warns(UserWarning, match="split non-manifold vertex 0"):
        V, F, file_index = expmap.read_mesh(path, return_file_index=True)
    assert len(V) == 6 and file_index.tolist() == [0, 1, 2, 3, 4, 0]
    # The split mesh is a 2-manifold: no warning when it is given back.
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        split = expmap.GeodesicPolarCoordinates(V, F)
    with pytest.warns(UserWarning):
        arrays = expmap.GeodesicPolarCoordinates(BOW_TIE_V, BOW_TIE_F)
    for source in range(5):
        a = arrays.compute(source, fraction=1.0)
        s = split.compute(source, fraction=1.0)
        np.testing.assert_array_equal(a.vertices, file_index[s.vertices])
        np.testing.assert_array_equal(a.uv, s.uv)
