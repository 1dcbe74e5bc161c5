# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Batches equal single queries; options and enums; every kind of bad input
is a ValueError (never a crash)."""

import math
import os
import re

import numpy as np
import pytest

import expmap

METHOD_CLASSES = [expmap.HeatExponentialMap, expmap.DiscreteExponentialMap,
                  expmap.GeodesicPolarCoordinates]


@pytest.fixture(scope="module")
def heat(elephant):
    _, V, F = elephant
    return expmap.HeatExponentialMap(V, F)


@pytest.mark.parametrize("method", METHOD_CLASSES)
@pytest.mark.parametrize("threads", [1, 2, 0])
def test_batch_equals_single_queries(elephant, method, threads):
    _, V, F = elephant
    mapper = method(V, F)
    sources = np.array([5, 0, 2000, 5, 77], dtype=np.int32)
    batch = mapper.compute_many(sources, vertices=60, threads=threads)
    assert batch.failures == 0 and batch.errors == [""] * 5
    np.testing.assert_array_equal(batch.sources, sources)
    assert batch.offsets[0] == 0 and len(batch.offsets) == 6
    for i, s in enumerate(sources):
        rows = slice(batch.offsets[i], batch.offsets[i + 1])
        local = mapper.compute(int(s), vertices=60)
        np.testing.assert_array_equal(batch.vertex[rows], local.vertices)
        np.testing.assert_array_equal(batch.r[rows], local.r)
        np.testing.assert_array_equal(batch.theta[rows], local.theta)
        np.testing.assert_array_equal(batch.u[rows], local.uv[:, 0])
        np.testing.assert_array_equal(batch.v[rows], local.uv[:, 1])
    assert set(batch.as_dict()) == {"sources", "offsets", "vertex", "r", "theta", "u", "v",
                                    "fold_free_radius"}


def test_batch_maps_index_and_iterate_as_views(heat):
    sources = [5, 0, 2000, 77]
    batch = heat.compute_many(sources, vertices=60, threads=2)
    assert len(batch) == 4
    for i, (source, m) in enumerate(zip(sources, batch)):
        assert isinstance(m, expmap.BatchMap)
        assert m.source == source and m.error is None
        local = heat.compute(source, vertices=60)
        np.testing.assert_array_equal(m.vertices, local.vertices)
        np.testing.assert_array_equal(m.r, local.r)
        np.testing.assert_array_equal(m.theta, local.theta)
        np.testing.assert_array_equal(m.u, local.uv[:, 0])
        np.testing.assert_array_equal(m.v, local.uv[:, 1])
        # Views of the flat arrays' rows, not copies.
        for name, flat in (("vertices", batch.vertex), ("r", batch.r), ("theta", batch.theta),
                           ("u", batch.u), ("v", batch.v)):
            view = getattr(m, name)
            assert np.shares_memory(view, flat), name
            assert view.base is not None and len(view) == batch.offsets[i + 1] - batch.offsets[i]
        np.testing.assert_array_equal(batch[i].r, m.r)
    assert [m.source for m in batch] == sources
    assert batch[-1].source == 77 and batch[-4].source == 5
    assert batch[np.int64(1)].source == 0
    for index in (4, -5, 10**30):
        with pytest.raises(IndexError, match="out of range"):
            batch[index]
    with pytest.raises(TypeError, match="integers"):
        batch["0"]
    # The views keep the arrays alive without the batch.
    first = batch[0]
    del batch
    assert first.r[0] == 0 and first.vertices[0] == 5


def test_batch_maps_name_a_failed_source(cactus):
    # A vertex without faces cannot be a source: that query alone fails.
    _, V, F = cactus
    isolated = len(V)
    dem = expmap.DiscreteExponentialMap(np.vstack([V, [[0.0, 0.0, 0.0]]]), F)
    batch = dem.compute_many([0, isolated], vertices=20)
    ok, failed = batch
    assert batch.failures == 1
    assert ok.error is None and len(ok.vertices) == 20
    assert failed.source == isolated and "isolated" in failed.error
    assert failed.error == batch.errors[1]
    assert len(failed.vertices) == len(failed.r) == len(failed.u) == 0


def test_version_is_the_headers():
    header = os.path.join(os.path.dirname(__file__), "..", "..", "include", "expmap", "version.h")
    with open(header) as f:
        match = re.search(r'#define EXPMAP_VERSION_STRING "([^"]+)"', f.read())
    assert match and expmap.__version__ == match.group(1)
    assert re.fullmatch(r"\d+\.\d+\.\d+", expmap.__version__)


def test_local_map_arrays(heat):
    local = heat.compute(np.int64(10), vertices=50)
    assert local.source == 10 and len(local) == 50 and local.vertices[0] == 10
    assert local.uv.shape == (50, 2) and local.r[0] == 0
    assert np.all(np.diff(local.r) >= -1e-12)  # nearest first
    np.testing.assert_allclose(local.uv[:, 0], local.r * np.cos(local.theta))
    assert abs(np.linalg.norm(local.normal) - 1) < 1e-12
    assert np.all(np.isfinite(local.theta)) and np.all(np.abs(local.theta) <= math.pi)


def test_statistics_count_the_region_retries(elephant):
    # Source 21's 1% patch comes too close to its first region's edge; the
    # retry continues the first attempt, so its map is a first attempt on the
    # doubled region (region_growth 4).
    _, V, F = elephant
    heat = expmap.HeatExponentialMap(V, F)
    retried = heat.compute(21, fraction=0.01)
    direct = heat.compute(21, fraction=0.01, region_growth=4)
    assert retried.statistics["region_retries"] == 1
    assert direct.statistics["region_retries"] == 0
    assert retried.statistics["factor_entries"] > 0
    np.testing.assert_array_equal(retried.vertices, direct.vertices)
    np.testing.assert_allclose(retried.r, direct.r, rtol=0, atol=1e-12)
    np.testing.assert_allclose(retried.theta, direct.theta, rtol=0, atol=1e-12)
    dem = expmap.DiscreteExponentialMap(V, F).compute(21, fraction=0.01)
    assert all(value == 0 for value in dem.statistics.values())


def test_patch_kinds(heat):
    assert len(heat.compute(3, vertex_set=[3, 4, 5, 6])) >= 1
    local = heat.compute(3, radius=0.02)
    assert np.all(local.r <= 0.02 + 1e-12)
    assert len(heat.compute(3, fraction=0.01)) == math.ceil(0.01 * heat.number_of_vertices)


def test_every_enum_member_is_accepted_by_name_and_value(cactus):
    _, V, F = cactus
    heat = expmap.HeatExponentialMap(V, F)
    for name, value in expmap.AngleEstimator.__members__.items():
        by_name = heat.compute(0, vertices=30, angle_estimator=name)
        by_value = heat.compute(0, vertices=30, angle_estimator=value)
        np.testing.assert_array_equal(by_name.uv, by_value.uv)
    for enum, option in ((expmap.LaplacianMode, "laplacian"),
                         (expmap.VertexArea, "vertex_area"),
                         (expmap.FactorPrecision, "factor_precision"),
                         (expmap.PoissonRegularization, "regularization")):
        assert len(enum.__members__) >= 2
        for name, value in enum.__members__.items():
            by_name = expmap.HeatExponentialMap(V, F, **{option: name}).compute(0, vertices=30)
            by_value = expmap.HeatExponentialMap(V, F, **{option: value}).compute(0, vertices=30)
            np.testing.assert_array_equal(by_name.uv, by_value.uv)


def flipped_triangles(local, F):
    """Triangles of F with all corners in the map whose (u, v) turns over."""
    position = {v: i for i, v in enumerate(local.vertices)}
    count = 0
    for face in F:
        if all(v in position for v in face):
            a, b, c = (local.uv[position[v]] for v in face)
            count += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0
    return count


def test_the_geodesic_front_replaces_a_folding_heat_map(elephant):
    # Vertex 841, at the tip of a tusk: the heat's reading at the source
    # folds a region over; the default returns the front's map, which folds
    # fewer triangles, and fallback="none" the heat's own.
    _, V, F = elephant
    heat = expmap.HeatExponentialMap(V, F)
    default = heat.compute(841, fraction=0.05)
    paper = heat.compute(841, fraction=0.05, fallback="none")
    assert default.statistics["front_maps"] == 1 and paper.statistics["front_maps"] == 0
    assert flipped_triangles(default, F) < flipped_triangles(paper, F)
    assert heat.compute(841, fraction=0.05, fallback=expmap.HeatFallback.none).statistics[
        "front_checks"] == 0
    # Where the heat's map is sound it is returned untouched.
    sound = heat.compute(527, fraction=0.05)
    assert sound.statistics["front_maps"] == 0
    np.testing.assert_array_equal(sound.uv, heat.compute(527, fraction=0.05, fallback="none").uv)


def test_single_precision_factors_move_distances_by_float_round_off(elephant):
    _, V, F = elephant
    double = expmap.HeatExponentialMap(V, F).compute(0, fraction=0.05)
    single = expmap.HeatExponentialMap(
        V, F, factor_precision="single_precision").compute(0, fraction=0.05)
    np.testing.assert_array_equal(single.vertices, double.vertices)
    radius = double.r.max()
    assert np.max(np.abs(single.r - double.r)) <= 1e-5 * radius
    assert np.max(np.abs(single.r - double.r)) > 0  # the factor was rounded


def test_a_second_query_thread_gives_the_same_map(elephant):
    # A 50% patch: a region of every vertex, solved for the star beside the
    # distance.
    _, V, F = elephant
    heat = expmap.HeatExponentialMap(V, F)
    one = heat.compute(0, fraction=0.5)
    two = heat.compute(0, fraction=0.5, query_threads=2)
    np.testing.assert_array_equal(two.vertices, one.vertices)
    radius = one.r.max()
    assert np.max(np.abs(two.r - one.r)) <= 1e-12 * radius
    assert np.max(np.abs(np.angle(np.exp(1j * (two.theta - one.theta))))) <= 1e-12


def test_failed_query_in_a_batch_keeps_the_others(elephant):
    _, V, F = elephant
    isolated = len(V)
    V2 = np.vstack([V, [[0.0, 0.0, 0.0]]])
    heat = expmap.HeatExponentialMap(V2, F)
    batch = heat.compute_many([0, isolated, 1], vertices=20)
    assert batch.failures == 1 and "isolated" in batch.errors[1]
    assert batch.errors[0] == batch.errors[2] == ""
    assert batch.offsets[2] - batch.offsets[1] == 0
    assert batch.offsets[3] - batch.offsets[2] == 20
    with pytest.raises(ValueError, match="isolated"):
        heat.compute(isolated, vertices=20)


def bad_meshes(V, F):
    """(description, vertices, faces) a caller might pass by mistake."""
    nan = V.copy()
    nan[3, 1] = np.nan
    inf = V.copy()
    inf[0, 0] = np.inf
    out_of_range = F.copy()
    out_of_range[5, 2] = len(V)
    negative = F.copy()
    negative[0, 0] = -1
    repeated = F.copy()
    repeated[1, 1] = repeated[1, 0]
    return [
        ("vertices n x 2", V[:, :2], F),
        ("vertices 1-D", V.ravel(), F),
        ("vertices 3-D", V[None], F),
        ("faces m x 4", V, np.hstack([F, F[:, :1]])),
        ("faces 1-D", V, F.ravel()),
        ("integer vertices", V.astype(np.int64), F),
        ("complex vertices", V.astype(complex), F),
        ("string vertices", V.astype(str), F),
        ("float faces", V, F.astype(float)),
        ("bool faces", V, F.astype(bool)),
        ("object faces", V, F.astype(object)),
        ("NaN coordinate", nan, F),
        ("infinite coordinate", inf, F),
        ("face index out of range", V, out_of_range),
        ("negative face index", V, negative),
        ("huge unsigned face index", V, np.full_like(F, np.iinfo(np.uint64).max, dtype=np.uint64)),
        ("repeated vertex in a face", V, repeated),
        ("empty vertices", np.zeros((0, 3)), F),
        ("empty faces", V, np.zeros((0, 3), dtype=np.int64)),
        ("None", None, F),
        ("a scalar", V, 3),
        ("a nested list", [[1, 2], [3]], F),
        ("all faces on one point", np.zeros_like(V), F),
    ]


@pytest.mark.parametrize("method", METHOD_CLASSES + [expmap.ExactExponentialMap])
def test_bad_meshes_raise_value_error(cactus, method):
    _, V, F = cactus
    for description, vertices, faces in bad_meshes(V, F):
        with pytest.raises(ValueError):
            method(vertices, faces)
            pytest.fail("accepted " + description)


def test_bad_options_raise_value_error(cactus):
    _, V, F = cactus
    for options in ({"time_factor": 0.0}, {"time_factor": float("nan")}, {"time_factor": -1.0},
                    {"time_factor": float("inf")}, {"poisson_compression_tolerance": 1e-6},
                    {"laplacian": "delaunay"}, {"regularization": None}):
        with pytest.raises(ValueError):
            expmap.HeatExponentialMap(V, F, **options)
    heat = expmap.HeatExponentialMap(V, F)
    for settings in ({"region_growth": 0.5}, {"region_growth": "2"}, {"pruning_tolerance": -1.0},
                     {"angle_estimator": 3}, {"near_source_blend": (3, 1)},
                     {"near_source_blend": 2.0}, {"query_threads": 0}, {"query_threads": 3},
                     {"fallback": "dgpc"}):
        with pytest.raises(ValueError):
            heat.compute(0, vertices=30, **settings)
        with pytest.raises(ValueError):
            heat.compute_many([0, 1], vertices=30, **settings)
    # Query settings belong to the query; the other methods have none.
    with pytest.raises(TypeError, match="'region_growth': it is a query setting"):
        expmap.HeatExponentialMap(V, F, region_growth=2.0)
    with pytest.raises(TypeError, match="unexpected keyword argument 'angle_estimator'"):
        expmap.DiscreteExponentialMap(V, F).compute(0, vertices=30, angle_estimator="heat_gradient")
    with pytest.raises(TypeError, match="unexpected keyword argument 'region_grwoth'"):
        heat.compute(0, vertices=30, region_grwoth=2.0)


def test_near_source_blend_is_scaled_per_source(cactus):
    _, V, F = cactus
    mapper = expmap.HeatExponentialMap(V, F)
    scales = set()
    for s in range(0, len(V), 37):
        begin, end = mapper.near_source_blend_at(s)
        assert 0 < end <= 1.5 * 6.0 + 1e-12
        assert begin == pytest.approx(end / 3, rel=1e-12)
        scales.add(round(end, 9))
    assert len(scales) > 1  # the cactus bends more at some sources than at others
    assert mapper.near_source_blend_at(0, near_source_blend=(0, 0)) == (0, 0)
    for bad in (len(V), -1, 1.5):
        with pytest.raises(ValueError):
            mapper.near_source_blend_at(bad)


@pytest.mark.parametrize("method", METHOD_CLASSES)
def test_bad_queries_raise_value_error(cactus, method):
    _, V, F = cactus
    mapper = method(V, F)
    n = len(V)
    bad_queries = [
        ((n,), {"vertices": 5}), ((-1,), {"vertices": 5}), ((2**70,), {"vertices": 5}),
        ((1.5,), {"vertices": 5}), (("0",), {"vertices": 5}),
        ((0,), {}), ((0,), {"radius": 0.1, "fraction": 0.1}),
        ((0,), {"radius": 0.0}), ((0,), {"radius": float("nan")}), ((0,), {"radius": -1.0}),
        ((0,), {"fraction": 0.0}), ((0,), {"fraction": 1.5}),
        ((0,), {"vertices": 0}), ((0,), {"vertices": -3}),
        ((0,), {"vertex_set": []}), ((0,), {"vertex_set": [n]}), ((0,), {"vertex_set": [-1]}),
        ((0,), {"vertex_set": [[1, 2]]}), ((0,), {"vertex_set": [0.5]}),
        ((0,), {"vertices": 5, "reference": [0, 0, 0]}),
        ((0,), {"vertices": 5, "reference": [np.nan, 1, 0]}),
        ((0,), {"vertices": 5, "reference": [1, 0]}), ((0,), {"vertices": 5, "reference": "x"}),
    ]
    for args, kwargs in bad_queries:
        with pytest.raises(ValueError):
            mapper.compute(*args, **kwargs)
            pytest.fail("accepted compute%r %r" % (args, kwargs))
    for sources, kwargs in [([], {"vertices": 5}), ([0, n], {"vertices": 5}),
                            ([-1], {"vertices": 5}), ([[0, 1]], {"vertices": 5}),
                            ([0.0], {"vertices": 5}), ([0], {"vertices": 5, "threads": -1}),
                            ([0], {}), (None, {"vertices": 5})]:
        with pytest.raises(ValueError):
            mapper.compute_many(sources, **kwargs)
            pytest.fail("accepted compute_many(%r, %r)" % (sources, kwargs))


def test_read_mesh_errors_and_repairs(tmp_path):
    with pytest.raises(OSError, match="cannot open"):
        expmap.read_mesh(str(tmp_path / "missing.off"))
    garbage = tmp_path / "garbage.off"
    garbage.write_text("OFF\n3 1 0\n0 0 0\n1 0\n")
    with pytest.raises(ValueError):
        expmap.read_mesh(str(garbage))
    quad = tmp_path / "quad.off"
    quad.write_text("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    with pytest.raises(ValueError, match="not a triangle"):
        expmap.read_mesh(str(quad), triangulate=False)
    with pytest.warns(UserWarning, match="triangulated 1 faces"):
        V, F, file_index = expmap.read_mesh(quad, return_file_index=True)  # any os.PathLike
    assert V.shape == (4, 3) and F.shape == (2, 3)
    np.testing.assert_array_equal(file_index, np.arange(4))


def test_everything_is_documented():
    for name in expmap.__all__:
        obj = getattr(expmap, name)
        if callable(obj):
            assert obj.__doc__, name
    for cls in (expmap.HeatExponentialMap, expmap.DiscreteExponentialMap,
                expmap.GeodesicPolarCoordinates, expmap.ExactExponentialMap):
        for member in ("__init__", "compute", "compute_many"):
            assert getattr(cls, member).__doc__, (cls, member)


@pytest.mark.filterwarnings("ignore:.*triangulated")  # hole.off has polygons
@pytest.mark.filterwarnings("ignore:split non-manifold")  # faces removed leave bow ties
@pytest.mark.filterwarnings("ignore:its faces are not")
def test_damaged_real_meshes_raise_or_give_finite_maps():
    """Real meshes with faces removed, points merged, flattened or scaled to
    extremes: every method either raises ValueError / RuntimeError or
    returns finite maps (a crash would end the test run)."""
    from conftest import mesh_path

    rng = np.random.default_rng(12)
    bases = [expmap.read_mesh(mesh_path(name))
             for name in ("icosahedron.off", "octahedron.off", "fold.off", "star.off", "hole.off")]
    classes = (expmap.HeatExponentialMap, expmap.DiscreteExponentialMap,
               expmap.GeodesicPolarCoordinates, expmap.ExactExponentialMap)
    for trial in range(40):
        V, F = (a.copy() for a in bases[trial % len(bases)])
        F = F[rng.random(len(F)) < 0.8] if trial % 3 == 0 else F
        if len(F) == 0:
            continue
        if trial % 4 == 1:
            V[rng.integers(len(V))] = V[rng.integers(len(V))]
        if trial % 5 == 2:
            V[:, 2] = 0
        if trial % 7 == 3:
            V *= 1e-200
        for cls in classes:
            try:
                mapper = cls(V, F)
            except (ValueError, RuntimeError):
                continue
            for source in range(len(V)):
                for patch in ({"fraction": 1.0}, {"vertices": 3}, {"radius": 0.5}):
                    try:
                        local = mapper.compute(source, **patch)
                    except (ValueError, RuntimeError):
                        continue
                    assert np.all(np.isfinite(local.r)) and np.all(np.isfinite(local.uv))
