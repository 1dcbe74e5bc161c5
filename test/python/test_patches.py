# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""method.patch_operator(): the polar patch operator from Python, against
linear functions on a plane (reproduced exactly at every grid point) and at
a boundary (masked, never NaN)."""

import math
import os
import subprocess
import sys

import numpy as np
import pytest

import expmap


def plane(n=30, half=1.0):
    """A square [-half, half]^2 of the plane z = 0, n x n cells, two triangles each."""
    x = np.linspace(-half, half, n + 1)
    X, Y = np.meshgrid(x, x)
    V = np.column_stack([X.ravel(), Y.ravel(), np.zeros(X.size)])
    F = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            F += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    return V, np.array(F)


@pytest.mark.parametrize("cls", [expmap.GeodesicPolarCoordinates, expmap.ExactExponentialMap])
def test_linear_functions_on_a_plane_are_reproduced(cls):
    V, F = plane()
    f = 0.7 * V[:, 0] - 1.3 * V[:, 1] + 0.2
    sources = [i for i in range(len(V)) if max(abs(V[i, 0]), abs(V[i, 1])) < 0.5][::7]
    op = cls(V, F).patch_operator(sources, radius=0.3, rings=4, rays=8, reference=(1, 0, 0))
    assert op.sampled.shape == (len(sources), 4, 8) and op.sampled.all()
    patches = op.patches(f)
    assert patches.shape == (len(sources), 4, 8)
    rho = (np.arange(4) + 0.5) * 0.3 / 4
    theta = 2 * math.pi * np.arange(8) / 8
    for s, source in enumerate(sources):
        x = V[source, 0] + np.outer(rho, np.cos(theta))
        y = V[source, 1] + np.outer(rho, np.sin(theta))
        assert np.abs(patches[s] - (0.7 * x - 1.3 * y + 0.2)).max() < 1e-9


def test_weights_are_the_operator_and_channels_keep_their_shape(elephant):
    _, V, F = elephant
    op = expmap.HeatExponentialMap(V, F).patch_operator(range(0, len(V), 50), radius=0.05,
                                                        threads=2)
    assert op.weights.shape == (len(op.sources) * 5 * 16, len(V))
    signal = np.column_stack([V[:, 0], V[:, 1] ** 2])
    patches = op.patches(signal)
    assert patches.shape == (len(op.sources), 5, 16, 2)
    if isinstance(op.weights, tuple):
        pytest.skip("SciPy is not installed")
    expected = (op.weights @ signal).reshape(patches.shape)
    assert np.allclose(patches, expected, rtol=0, atol=1e-12)
    rows = np.asarray(op.weights.sum(axis=1)).ravel()
    assert np.allclose(rows[op.sampled.ravel()], 1)
    assert (rows[~op.sampled.ravel()] == 0).all()
    assert op.errors == [""] * len(op.sources)


def test_every_vertex_by_default_and_boundaries_masked():
    V, F = plane(12)
    op = expmap.GeodesicPolarCoordinates(V, F).patch_operator(radius=0.5, rings=3, rays=6)
    assert list(op.sources) == list(range(len(V)))
    assert op.sampled.shape == (len(V), 3, 6)
    assert 0 < op.sampled.sum() < op.sampled.size  # the corners see past the border
    assert np.isfinite(op.patches(V)).all()


def test_bad_grids_are_refused():
    V, F = plane(4)
    dgpc = expmap.GeodesicPolarCoordinates(V, F)
    with pytest.raises(ValueError, match="radius must be positive"):
        dgpc.patch_operator([0], radius=0.0)
    with pytest.raises(ValueError, match="at least one ring"):
        dgpc.patch_operator([0], radius=0.5, rings=0)
    with pytest.raises(ValueError, match="out of range"):
        dgpc.patch_operator([len(V)], radius=0.5)
    with pytest.raises(ValueError, match="signal must have shape"):
        dgpc.patch_operator([0], radius=0.5).patches(np.zeros(3))


def cli():
    path = os.environ.get("EXPMAP_CLI")
    if not path:
        pytest.skip("EXPMAP_CLI is not set (ctest sets it)")
    return path


def test_the_command_line_writes_the_same_operator_in_scipys_layout(elephant, tmp_path):
    scipy_sparse = pytest.importorskip("scipy.sparse")
    path, V, F = elephant
    out = tmp_path / "patches.npz"
    run = subprocess.run([cli(), "patches", path, "--radius", "0.05", "--rings", "4", "--rays",
                          "8", "--sources", "0,5,77", "-o", str(out)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    weights = scipy_sparse.load_npz(out)
    arrays = np.load(out)
    op = expmap.GeodesicPolarCoordinates(V, F).patch_operator([0, 5, 77], radius=0.05, rings=4,
                                                              rays=8)
    assert weights.shape == op.weights.shape
    assert abs(weights - op.weights).max() == 0
    assert (arrays["sampled"].astype(bool) == op.sampled).all()
    assert list(arrays["sources"]) == [0, 5, 77] and float(arrays["radius"]) == 0.05


@pytest.mark.parametrize("arguments,message", [
    (["--fraction", "0.1"], "give the grid's --radius"),
    (["--radius", "0.05", "--vertices", "9"], "--fraction and --vertices do not apply"),
    (["--radius", "0.05", "--rings", "0"], "--rings must be in [1, 4096]"),
    (["--radius", "0.05", "--trim-folds"], "drop --trim-folds"),
])
def test_the_command_line_refuses_what_a_grid_cannot_take(elephant, tmp_path, arguments, message):
    path = elephant[0]
    run = subprocess.run([cli(), "patches", path] + arguments + ["-o", str(tmp_path / "p.npz")],
                         capture_output=True, text=True)
    assert run.returncode == 2
    assert run.stderr.startswith("expmap: error: ") and message in run.stderr
    assert not (tmp_path / "p.npz").exists()


def test_the_example_draws_its_patches(tmp_path):
    pytest.importorskip("matplotlib")
    example = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "geodesic_patches.py")
    mesh = os.path.join(os.environ.get("EXPMAP_DATA_DIR", ""), "cactus.off")
    if not os.path.exists(mesh):
        pytest.skip("cactus.off not found")
    out = tmp_path / "patches.png"
    run = subprocess.run([sys.executable, example, mesh, "--show", "2", "-o", str(out)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert out.stat().st_size > 10000
    assert "sampled" in run.stdout


def test_a_reference_per_source_turns_each_patch_by_whole_rays():
    V, F = plane(24)
    sources = [i for i in range(len(V)) if max(abs(V[i, 0]), abs(V[i, 1])) < 0.4][::5]
    dgpc = expmap.GeodesicPolarCoordinates(V, F)
    straight = dgpc.patch_operator(sources, radius=0.3, rings=3, rays=8, reference=(1, 0, 0))
    # Source s turned by s rays (mod 8): its patch's rays shift by as many.
    turns = np.arange(len(sources)) % 8
    angle = 2 * math.pi * turns / 8
    references = np.column_stack([np.cos(angle), np.sin(angle), np.zeros(len(sources))])
    turned = dgpc.patch_operator(sources, radius=0.3, rings=3, rays=8, reference=references)
    f = V[:, 0] * 0.3 + V[:, 1] ** 2
    a, b = straight.patches(f), turned.patches(f)
    for s, k in enumerate(turns):
        assert np.abs(np.roll(a[s], -k, axis=1) - b[s]).max() < 1e-9
    with pytest.raises(ValueError, match="one reference direction per source|sources, 3"):
        dgpc.patch_operator(sources, radius=0.3, reference=references[:-1])
    with pytest.raises(ValueError, match="zero or not finite"):
        dgpc.patch_operator(sources, radius=0.3, reference=np.zeros((len(sources), 3)))
