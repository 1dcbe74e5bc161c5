# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Any positive finite radius is a patch: one beyond the mesh maps the
source's whole component, in Python and in the command-line program, for
every method; an infinite, NaN, zero or negative radius is InvalidInput.
No failure speaks a dependency's words."""

import csv
import os
import subprocess

import numpy as np
import pytest

import expmap

LARGE = [1e5, 1e9, 1e300]
BAD = [float("inf"), float("nan"), 0.0, -1.0, float("-inf")]


@pytest.fixture(scope="module")
def mappers(cactus):
    _, V, F = cactus
    return {name: cls(V, F) for name, cls in expmap.METHODS.items()}


@pytest.mark.parametrize("method", sorted(expmap.METHODS))
def test_a_radius_beyond_the_mesh_maps_the_whole_component(mappers, method):
    mapper = mappers[method]
    whole = mapper.compute(0, fraction=1.0)
    for radius in LARGE:
        local = mapper.compute(0, radius=radius)
        np.testing.assert_array_equal(np.sort(local.vertices), np.sort(whole.vertices))
        assert np.all(np.isfinite(local.r)) and np.all(np.isfinite(local.uv))
    batch = mapper.compute_many([0, 5], radius=1e9, threads=1)
    assert batch.errors == ["", ""]
    assert batch.offsets[1] == batch.offsets[2] - batch.offsets[1] == len(whole)


@pytest.mark.parametrize("method", sorted(expmap.METHODS))
def test_a_radius_that_is_not_a_positive_number_is_invalid_input(mappers, method):
    mapper = mappers[method]
    for radius in BAD:
        with pytest.raises(expmap.InvalidInput, match="radius must be positive and finite"):
            mapper.compute(0, radius=radius)
        with pytest.raises(expmap.InvalidInput, match="radius must be positive and finite"):
            mapper.compute_many([0], radius=radius)


@pytest.mark.parametrize("method", sorted(expmap.METHODS))
def test_the_program_maps_a_large_radius(cactus, mappers, tmp_path, method):
    cli = os.environ.get("EXPMAP_CLI")
    if not cli:
        pytest.skip("EXPMAP_CLI is not set (ctest sets it)")
    path = cactus[0]
    whole = len(mappers[method].compute(0, fraction=1.0))
    for radius in ("1e5", "1e9"):
        out = tmp_path / ("%s-%s.csv" % (method, radius))
        run = subprocess.run([cli, "compute", path, "--method", method, "--source", "0",
                              "--radius", radius, "-o", str(out)],
                             capture_output=True, text=True, timeout=600)
        assert run.returncode == 0, run.stderr
        with open(out) as f:
            assert len(list(csv.DictReader(f))) == whole
    for radius in ("inf", "nan", "-1", "0"):
        run = subprocess.run([cli, "compute", path, "--method", method, "--source", "0",
                              "--radius", radius, "-o", str(tmp_path / "bad.csv")],
                             capture_output=True, text=True, timeout=600)
        assert run.returncode in (1, 2), run.stderr
        lines = run.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("expmap: error: "), run.stderr
        assert "radius" in lines[0], run.stderr
