# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""HeatExponentialMap on subdomains (geodesic balls factored per query, the
default on meshes of 200,000 vertices or more), forced here on a smaller
mesh: its maps agree with the whole mesh's, and batches are the same on
any number of threads up to round-off."""

import numpy as np

import expmap
from conftest import mesh_path


def test_subdomain_maps_agree_with_the_whole_mesh_and_batches_with_themselves():
    V, F = expmap.read_mesh(mesh_path("refined_elephant.off"))
    whole = expmap.HeatExponentialMap(V, F)
    sub = expmap.HeatExponentialMap(V, F, subdomain_min_vertices=0,
                                    subdomain_cache_bytes=200 << 20)
    assert not whole.uses_subdomains and whole.subdomain_bytes == 0
    assert sub.uses_subdomains
    sources = np.random.default_rng(46).choice(len(V), 12, replace=False)
    errors = []
    for s in sources:
        a = whole.compute(int(s), vertices=150)
        b = sub.compute(int(s), vertices=150)
        assert np.array_equal(np.sort(a.vertices), np.sort(b.vertices))
        order = np.argsort(b.vertices)[np.argsort(np.argsort(a.vertices))]
        errors.append(np.mean(np.abs(a.r - b.r[order])) / a.r.max())
    assert np.mean(errors) < 2e-3
    assert 0 < sub.subdomain_bytes <= (200 << 20) + (100 << 20)
    one = sub.compute_many(sources, vertices=150, threads=1)
    two = expmap.HeatExponentialMap(V, F, subdomain_min_vertices=0).compute_many(
        sources, vertices=150, threads=2)
    assert one.failures == two.failures == 0
    # The same balls: equal up to the round-off of their factorizations,
    # whose BLAS blocks may split otherwise on a batch's worker threads.
    for name, a in one.as_dict().items():
        np.testing.assert_allclose(two.as_dict()[name], a, rtol=1e-12, atol=1e-12, err_msg=name)
