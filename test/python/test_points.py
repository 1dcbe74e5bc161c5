# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Point sources: locate(), compute_at(), compute_at_point() and
compute_many_at_points(), judged against the vertex source's map and, on a
plane, the Euclidean distances; bad input is a ValueError."""

import numpy as np
import pytest

import expmap

ALL_METHODS = [expmap.HeatExponentialMap, expmap.DiscreteExponentialMap,
               expmap.GeodesicPolarCoordinates, expmap.ExactExponentialMap]


def planar_grid(n):
    """An n x n grid of unit squares in z = 0, two triangles each."""
    i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1))
    V = np.column_stack([i.ravel(), j.ravel(), np.zeros(i.size)]).astype(float)
    F = []
    for y in range(n):
        for x in range(n):
            a = y * (n + 1) + x
            F += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    return V, np.array(F)


@pytest.fixture(scope="module")
def dgpc(elephant):
    _, V, F = elephant
    return expmap.GeodesicPolarCoordinates(V, F)


def assert_same_map(a, b):
    np.testing.assert_array_equal(a.vertices, b.vertices)
    np.testing.assert_array_equal(a.r, b.r)
    np.testing.assert_array_equal(a.theta, b.theta)
    np.testing.assert_array_equal(a.uv, b.uv)


def test_a_point_at_a_vertex_gives_the_vertex_map(elephant, dgpc):
    _, V, F = elephant
    for v in (0, 100, 2000):
        vertex_map = dgpc.compute(v, vertices=80)
        assert_same_map(dgpc.compute_at_point(V[v], vertices=80), vertex_map)
        f = int(np.nonzero((F == v).any(axis=1))[0][0])
        w = (F[f] == v).astype(float)
        assert_same_map(dgpc.compute_at(f, w, vertices=80), vertex_map)
        face, barycentric = dgpc.locate(V[v])
        assert v in F[face] and barycentric[list(F[face]).index(v)] == 1.0


def test_locate_finds_the_face_and_its_coordinates(elephant, dgpc):
    _, V, F = elephant
    rng = np.random.default_rng(7)
    faces = rng.choice(len(F), 50, replace=False)
    w = rng.uniform(0.1, 1.0, (50, 3))
    w /= w.sum(axis=1, keepdims=True)
    points = np.einsum("ij,ijk->ik", w, V[F[faces]])
    found, barycentric = dgpc.locate(points)
    assert found.dtype == np.int64 and found.shape == (50,) and barycentric.shape == (50, 3)
    np.testing.assert_array_equal(found, faces)
    np.testing.assert_allclose(barycentric, w, atol=1e-9)
    one_face, one_w = dgpc.locate(points[3])
    assert one_face == faces[3] and one_w.shape == (3,)


def test_a_point_in_a_face_of_a_plane_has_euclidean_distances():
    V, F = planar_grid(8)
    # The corners in another order, and one face reversed: the coordinates
    # follow each row's own order whatever the mesh made of it.
    F[53] = F[53][[2, 0, 1]]
    F[54] = F[54][::-1]
    with pytest.warns(UserWarning):  # the reversed face is oriented
        dgpc = expmap.GeodesicPolarCoordinates(V, F)
    for face in (53, 54, 10):
        w = np.array([0.2, 0.3, 0.5])
        point = w @ V[F[face]]
        local = dgpc.compute_at(face, w, radius=3)
        assert len(local) >= 15 and local.r.min() > 0  # no vertex at the point
        np.testing.assert_allclose(local.r, np.linalg.norm(V[local.vertices] - point, axis=1),
                                   rtol=0, atol=1e-12)
        located = dgpc.compute_at_point(point + [0, 0, 0.25], radius=3)  # above: the nearest point
        order, located_order = np.argsort(local.vertices), np.argsort(located.vertices)  # ties
        np.testing.assert_array_equal(located.vertices[located_order], local.vertices[order])
        np.testing.assert_allclose(located.r[located_order], local.r[order], rtol=0, atol=1e-12)


@pytest.mark.parametrize("threads", [1, 2])
def test_many_points_equal_single_queries(elephant, dgpc, threads):
    _, V, F = elephant
    points = np.vstack([V[5], V[F[10]].mean(axis=0), V[F[3000]].mean(axis=0) + 0.01, V[5]])
    batch = dgpc.compute_many_at_points(points, vertices=40, threads=threads)
    assert batch.failures == 0
    np.testing.assert_array_equal(batch.sources, np.arange(4))
    for i, m in enumerate(batch):
        local = dgpc.compute_at_point(points[i], vertices=40)
        np.testing.assert_array_equal(m.vertices, local.vertices)
        np.testing.assert_array_equal(m.r, local.r)
        np.testing.assert_array_equal(m.theta, local.theta)


@pytest.mark.parametrize("method", ALL_METHODS)
def test_every_method_maps_from_points(cactus, method):
    _, V, F = cactus
    mapper = method(V, F)
    centre = V[F[7]].mean(axis=0)
    face, w = mapper.locate(centre)
    assert face == 7
    np.testing.assert_allclose(w, [1 / 3] * 3, atol=1e-12)
    at = mapper.compute_at(7, [1, 1, 1], vertices=10)
    at_point = mapper.compute_at_point(centre, vertices=10)
    batch = mapper.compute_many_at_points(V[F[:3]].mean(axis=1), vertices=10)
    assert batch.failures == 0 and len(batch) == 3
    for m in (at, at_point, *batch):
        assert len(m.vertices) == 10
        assert m.r.min() > 0  # no vertex at the point
        assert np.isfinite(m.r).all() and np.isfinite(m.theta).all()
    assert np.isfinite(at.uv).all() and np.isfinite(at_point.uv).all()
    # The face's centre, given by its coordinates or by its position.
    np.testing.assert_array_equal(at_point.vertices, at.vertices)
    np.testing.assert_allclose(at_point.r, at.r, rtol=0, atol=1e-9)
    # The corners are reached straight across the face: r is their distance
    # (heat's is smoothed: up to 4% off on other faces of cactus).
    corners = np.isin(at.vertices, F[7])
    assert corners.sum() == 3
    np.testing.assert_allclose(at.r[corners], np.linalg.norm(V[at.vertices[corners]] - centre, axis=1),
                               rtol=0.1 if method is expmap.HeatExponentialMap else 1e-12)
    # Each map of the batch is that point's single query.
    single = mapper.compute_at_point(V[F[2]].mean(axis=0), vertices=10)
    np.testing.assert_array_equal(batch[2].vertices, single.vertices)
    np.testing.assert_array_equal(batch[2].r, single.r)


def test_bad_points_raise_value_error(elephant, dgpc):
    _, V, F = elephant
    bad_calls = [
        lambda: dgpc.compute_at(len(F), [1, 0, 0], vertices=5),  # face out of range
        lambda: dgpc.compute_at(-1, [1, 0, 0], vertices=5),
        lambda: dgpc.compute_at(0, [1, -1, 1], vertices=5),
        lambda: dgpc.compute_at(0, [0, 0, 0], vertices=5),
        lambda: dgpc.compute_at(0, [1, 0], vertices=5),
        lambda: dgpc.compute_at(0, [np.nan, 0, 1], vertices=5),
        lambda: dgpc.compute_at(0, "abc", vertices=5),
        lambda: dgpc.compute_at(0, [1, 0, 0]),  # no patch
        lambda: dgpc.compute_at_point([0, 0], vertices=5),
        lambda: dgpc.compute_at_point([0, 0, np.inf], vertices=5),
        lambda: dgpc.compute_at_point(np.zeros((2, 3)), vertices=5),
        lambda: dgpc.compute_many_at_points(np.zeros((2, 4)), vertices=5),
        lambda: dgpc.compute_many_at_points(np.zeros((0, 3)), vertices=5),
        lambda: dgpc.compute_many_at_points(np.zeros((2, 3)), vertices=5, threads=-1),
        lambda: dgpc.locate(np.zeros((2, 2))),
        lambda: dgpc.locate([[0, 0, np.nan]]),
    ]
    # Too far from the mesh to locate (more than 1e8 times its size): the
    # nearest-point search would overflow.
    far_calls = [
        lambda: dgpc.locate([-1e308, 0, 1e308]),
        lambda: dgpc.locate([[0, 0, 0], [1e9, 0, 0]]),
        lambda: dgpc.compute_at_point([-1e308, 0, 1e308], vertices=5),
        lambda: dgpc.compute_many_at_points([[0, 0, 0], [0, -1e200, 0]], vertices=5),
    ]
    for call in far_calls:
        with pytest.raises(ValueError, match="too far from the mesh"):
            call()
    for call in bad_calls:
        with pytest.raises(ValueError):
            call()
    # Each coordinate finite, their sum not: refused by name, not divided.
    with pytest.raises(ValueError, match="barycentric must have a finite sum"):
        dgpc.compute_at(0, [1e308, 1e308, 1e308], vertices=5)
    with pytest.raises(TypeError):
        dgpc.compute_at(0, [1, 0, 0], vertices=5, angle_estimator="heat_gradient")


def test_point_queries_are_documented():
    for cls in ALL_METHODS:
        for member in ("locate", "compute_at", "compute_at_point", "compute_many_at_points"):
            assert getattr(cls, member).__doc__, (cls, member)
