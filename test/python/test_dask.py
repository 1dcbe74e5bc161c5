# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""expmap.dask on a LocalCluster of two worker processes (loopback only):
the same maps as one process, also when a worker is killed mid-run."""

import logging
import os
import signal

import numpy as np
import pytest

import expmap

distributed = pytest.importorskip("distributed")
import dask  # noqa: E402
import expmap.dask  # noqa: E402  (after the skip: it needs distributed at run time)

from conftest import mesh_path  # noqa: E402

PATCH = {"vertices": 40}


def local_cluster():
    # Work stealing off, as the manual recommends: chunks then stay with the
    # worker that precomputed their mesh. Generous timeouts: the test
    # machine may be a loaded 2-core box.
    with dask.config.set({"distributed.scheduler.work-stealing": False}):
        return distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                        host="127.0.0.1", dashboard_address=None,
                                        silence_logs=logging.CRITICAL, death_timeout=120)


@pytest.fixture(scope="module")
def meshes_and_sources():
    # Three meshes on two workers: one waits for a worker to finish a mesh.
    elephant = mesh_path("elephant.off")
    cactus = mesh_path("cactus.off")
    cow = mesh_path("cow.off")
    return {elephant: np.arange(0, 2775, 3), cactus: np.arange(0, 620, 3), cow: np.arange(5, 2904, 29)}


def single_process(mesh, sources):
    V, F = expmap.read_mesh(mesh)
    return expmap.HeatExponentialMap(V, F).compute_many(sources, **PATCH).as_dict()


def assert_same_as_single_process(results, meshes_and_sources):
    assert set(results) == set(meshes_and_sources)
    for mesh, sources in meshes_and_sources.items():
        expected = single_process(mesh, sources)
        got = results[mesh]
        for name in ("sources", "offsets", "vertex"):
            np.testing.assert_array_equal(got[name], expected[name], err_msg="%s %s" % (mesh, name))
        # Dask starts its workers with one BLAS thread (OPENBLAS_NUM_THREADS=1),
        # this process may use more: the factorizations then differ in rounding.
        for name in ("r", "theta", "u", "v"):
            np.testing.assert_allclose(got[name], expected[name], rtol=0, atol=1e-12,
                                       err_msg="%s %s" % (mesh, name))
        assert list(got["errors"]) == [""] * len(sources)


def test_cluster_maps_equal_single_process(meshes_and_sources, tmp_path, monkeypatch):
    with local_cluster() as cluster, distributed.Client(cluster, timeout=120) as client:
        results = expmap.dask.map_meshes(client, list(meshes_and_sources), sources=meshes_and_sources,
                                         chunk_size=64, **PATCH)
        assert_same_as_single_process(results, meshes_and_sources)
        # One precomputation per mesh: every chunk ran where its mesh was.
        made = client.run(expmap.dask.precomputed_meshes)
        assert sorted(sum(made.values(), [])) == sorted(meshes_and_sources)

        files = expmap.dask.map_meshes(client, list(meshes_and_sources), sources=meshes_and_sources,
                                       out_dir=str(tmp_path), chunk_size=100, **PATCH)
        loaded = {}
        for mesh, path in files.items():
            assert os.path.dirname(path) == str(tmp_path)
            with np.load(path) as npz:  # no pickles: plain arrays only
                loaded[mesh] = {name: npz[name] for name in npz.files}
        assert_same_as_single_process(loaded, meshes_and_sources)

        # A folder that does not exist yet is made, as in the README's example
        # (a relative out_dir="maps/"), parents included.
        monkeypatch.chdir(tmp_path)
        cactus = list(meshes_and_sources)[1]
        for out_dir in ("maps/", os.path.join("new", "nested")):
            assert not os.path.exists(out_dir)
            written = expmap.dask.map_meshes(client, [cactus], sources={cactus: [0, 7]},
                                             out_dir=out_dir, **PATCH)
            assert os.path.normpath(written[cactus]) == os.path.join(os.path.normpath(out_dir), "cactus.npz")
            with np.load(written[cactus]) as npz:
                assert list(npz["sources"]) == [0, 7] and list(npz["errors"]) == ["", ""]

        # No sources: empty arrays, one offset.
        elephant = list(meshes_and_sources)[0]
        empty = expmap.dask.map_meshes(client, [elephant], sources={elephant: []}, vertices=5)[elephant]
        assert len(empty["sources"]) == len(empty["vertex"]) == 0 and list(empty["offsets"]) == [0]

        # Errors on a worker come back as the library's exceptions.
        with pytest.raises(OSError, match="cannot open"):
            expmap.dask.map_meshes(client, [str(tmp_path / "missing.off")], vertices=5)
        with pytest.raises(ValueError, match="out of range"):
            expmap.dask.map_meshes(client, [elephant], sources={elephant: [0, 10**6]}, vertices=5)

        # Polar patch operators, chunked over the workers: the same operator as
        # one process's, and a file SciPy reads.
        scipy_sparse = pytest.importorskip("scipy.sparse")
        grid = {"radius": 0.05, "rings": 3, "rays": 8}
        operators = expmap.dask.patch_operators(client, list(meshes_and_sources),
                                                sources=meshes_and_sources, chunk_size=40, **grid)
        for mesh, chosen in meshes_and_sources.items():
            V, F = expmap.read_mesh(mesh)
            expected = expmap.GeodesicPolarCoordinates(V, F).patch_operator(chosen, **grid)
            got = operators[mesh]
            weights = scipy_sparse.csr_matrix((got["data"], got["indices"], got["indptr"]),
                                              shape=tuple(got["shape"]))
            assert abs(weights - expected.weights).max() == 0
            assert (got["sampled"].astype(bool) == expected.sampled).all()
            assert list(got["sources"]) == list(chosen)
        written = expmap.dask.patch_operators(client, [cactus], sources={cactus: [0, 7, 9]},
                                              out_dir=str(tmp_path / "patches"), **grid)
        assert scipy_sparse.load_npz(written[cactus]).shape == (3 * 3 * 8, 620)


def test_worker_killed_mid_run_loses_and_duplicates_nothing(meshes_and_sources):
    with local_cluster() as cluster, distributed.Client(cluster, timeout=120) as client:
        client.wait_for_workers(2, timeout=120)
        pids = client.run(os.getpid)
        elephant = list(meshes_and_sources)[0]
        lost = []  # the meshes the killed worker held

        # The elephant has the most chunks: killed as soon as it is held (its
        # chunks are submitted only then), its worker dies with most of them
        # still to run. A smaller mesh could be finished before the kill lands.
        def kill_the_worker_holding_the_elephant(done, total):
            if lost:
                return
            held = client.run(expmap.dask.cached_meshes, on_error="ignore")
            holders = [a for a in sorted(held) if a in pids and elephant in (held[a] or [])]
            if holders:  # else try again after the next chunk
                os.kill(pids[holders[0]], signal.SIGKILL)
                lost.extend(held[holders[0]])

        # Small chunks, so most of them are still queued when the worker dies.
        results = expmap.dask.map_meshes(client, list(meshes_and_sources), sources=meshes_and_sources,
                                         chunk_size=8, progress=kill_the_worker_holding_the_elephant,
                                         **PATCH)
        assert elephant in lost
        # The elephant was precomputed again in a live process (the one that
        # took over its chunks).
        client.wait_for_workers(1, timeout=120)
        made = client.run(expmap.dask.precomputed_meshes, on_error="ignore")
        assert elephant in set().union(*(m for m in made.values() if isinstance(m, list)))
        assert_same_as_single_process(results, meshes_and_sources)


def test_bad_arguments_raise_value_error(meshes_and_sources):
    # Checked before anything is scheduled: no cluster needed.
    meshes = list(meshes_and_sources)
    for kwargs in ({}, {"fraction": 0.1, "radius": 1.0}, {"vertices": 5, "method": "nope"},
                   {"vertices": 5, "chunk_size": 0}, {"vertices": 5, "sources": [1, 2]},
                   {"vertices": 5, "sources": {meshes[0]: [1]}},
                   {"vertices": 5, "out_dir": meshes[0]}):  # a file, not a folder
        with pytest.raises(ValueError):
            expmap.dask.map_meshes(None, meshes, **kwargs)
    with pytest.raises(ValueError, match="list"):
        expmap.dask.map_meshes(None, meshes[0], vertices=5)
    with pytest.raises(ValueError, match="twice"):
        expmap.dask.map_meshes(None, [meshes[0], meshes[0]], vertices=5)
