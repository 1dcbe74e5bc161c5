# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""What the documentation promises about equal maps (manual, section 7):
one object gives the same maps bit for bit on any number of batch threads;
processes whose BLAS runs on different numbers of threads factor the heat
method's matrices in a different order of operations, and their maps agree
to round-off (the stated bound: 1e-12 of the radius in r, 1e-12 rad in
theta)."""

import os
import subprocess
import sys

import numpy as np
import pytest

import expmap

# The bound the manual states for maps of different processes.
ROUND_OFF = 1e-12


@pytest.mark.parametrize("method", sorted(expmap.METHODS))
def test_batch_threads_do_not_change_a_bit(cactus, method):
    _, V, F = cactus
    mapper = expmap.METHODS[method](V, F)
    sources = np.arange(0, len(V), 7)
    one = mapper.compute_many(sources, fraction=0.05, threads=1)
    two = mapper.compute_many(sources, fraction=0.05, threads=2)
    assert one.failures == two.failures == 0
    for name, a in one.as_dict().items():
        np.testing.assert_array_equal(two.as_dict()[name], a, err_msg=name)


MAP_SCRIPT = """
import sys, numpy as np, expmap
V, F = expmap.read_mesh(sys.argv[1])
heat = expmap.HeatExponentialMap(V, F)
batch = heat.compute_many(np.arange(0, len(V), len(V) // 25), fraction=0.02, threads=1)
assert batch.failures == 0, batch.errors
np.savez(sys.argv[2], **batch.as_dict())
"""


def test_blas_threads_change_heat_maps_by_round_off_only(tmp_path):
    from conftest import mesh_path

    mesh = mesh_path("man.off")  # large enough for supernodes that BLAS splits
    maps = []
    for threads in ("1", "2"):
        env = dict(os.environ, OPENBLAS_NUM_THREADS=threads, OMP_NUM_THREADS=threads)
        out = tmp_path / ("blas-%s.npz" % threads)
        subprocess.run([sys.executable, "-c", MAP_SCRIPT, mesh, str(out)], env=env, check=True,
                       timeout=600)
        maps.append(np.load(out))
    a, b = maps
    np.testing.assert_array_equal(a["sources"], b["sources"])
    np.testing.assert_array_equal(a["offsets"], b["offsets"])
    worst_r = worst_theta = 0.0
    for i in range(len(a["sources"])):
        rows = slice(a["offsets"][i], a["offsets"][i + 1])
        # Nearest first: vertices at equal distances up to round-off may swap.
        order_a, order_b = np.argsort(a["vertex"][rows]), np.argsort(b["vertex"][rows])
        np.testing.assert_array_equal(a["vertex"][rows][order_a], b["vertex"][rows][order_b])
        radius = a["r"][rows].max()
        worst_r = max(worst_r, np.max(np.abs(a["r"][rows][order_a] - b["r"][rows][order_b])) / radius)
        turn = a["theta"][rows][order_a] - b["theta"][rows][order_b]
        worst_theta = max(worst_theta, np.max(np.abs(np.angle(np.exp(1j * turn)))))
    print("largest difference: r %.3g of the radius, theta %.3g rad" % (worst_r, worst_theta))
    assert worst_r <= ROUND_OFF and worst_theta <= ROUND_OFF
