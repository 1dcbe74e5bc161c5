# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every map's fold-free radius, recomputed here from the faces, and
trim_folds=True cutting maps to it, on a 5% patch of the camel that every
method folds."""

import numpy as np
import pytest

import expmap

from conftest import mesh_path

METHOD_CLASSES = [expmap.HeatExponentialMap, expmap.DiscreteExponentialMap,
                  expmap.GeodesicPolarCoordinates, expmap.ExactExponentialMap]
SOURCE = 79


@pytest.fixture(scope="module")
def camel():
    return expmap.read_mesh(mesh_path("camel.off"))


def flipped_triangles(local, F):
    """The faces with three patch vertices whose signed uv area is not
    positive (evaluated from the corner nearest the source, as the library
    does), as rows of map positions."""
    position = np.full(F.max() + 1, -1, dtype=np.int64)
    position[local.vertices] = np.arange(len(local.vertices))
    corners = position[F]
    corners = corners[(corners >= 0).all(axis=1)]
    first = corners.argmin(axis=1)
    corners = np.stack([corners[np.arange(len(corners)), (first + k) % 3] for k in range(3)], axis=1)
    a, b, c = (local.uv[corners[:, k]] for k in range(3))
    area2 = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    return corners[~(area2 > 0)]


@pytest.mark.parametrize("method", METHOD_CLASSES, ids=lambda m: m.__name__)
def test_fold_free_radius_and_trimmed_maps(camel, method):
    V, F = camel
    mapper = method(V, F)
    local = mapper.compute(SOURCE, fraction=0.05)
    flipped = flipped_triangles(local, F)
    assert len(flipped) > 0
    radius = local.r[flipped].max(axis=1).min()
    assert local.fold_free_radius == radius
    assert 0 < local.fold_free_radius < local.r.max()

    trimmed = mapper.compute(SOURCE, fraction=0.05, trim_folds=True)
    inside = local.r < radius
    np.testing.assert_array_equal(trimmed.vertices, local.vertices[inside])
    np.testing.assert_array_equal(trimmed.r, local.r[inside])
    np.testing.assert_array_equal(trimmed.uv, local.uv[inside])
    assert len(flipped_triangles(trimmed, F)) == 0
    assert trimmed.fold_free_radius == trimmed.r.max()

    batch = mapper.compute_many([SOURCE, 0], fraction=0.05, trim_folds=True, threads=1)
    np.testing.assert_array_equal(batch[0].vertices, trimmed.vertices)
    assert batch.fold_free_radius[0] == trimmed.fold_free_radius
    assert batch.fold_free_radius[1] == mapper.compute(0, fraction=0.05, trim_folds=True).fold_free_radius


def test_a_failed_source_has_no_fold_free_radius(camel):
    V, F = camel
    dem = expmap.DiscreteExponentialMap(np.vstack([V, [[0.0, 0.0, 0.0]]]), F)
    batch = dem.compute_many([SOURCE, len(V)], vertices=20)
    assert batch.failures == 1
    assert batch.fold_free_radius[0] > 0 and np.isnan(batch.fold_free_radius[1])
