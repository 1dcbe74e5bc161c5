# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The module gives the C++ library's results, vertex for vertex: compared
with the CSV the command-line program writes for the same mesh file."""

import csv
import os
import subprocess

import numpy as np
import pytest

import expmap

CLI_NAMES = {"heat": expmap.HeatExponentialMap, "dem": expmap.DiscreteExponentialMap,
             "dgpc": expmap.GeodesicPolarCoordinates, "exact": expmap.ExactExponentialMap}


def cli_map(tmp_path, mesh, method, source, *patch):
    return cli_map_from(tmp_path, mesh, method, "--source", str(source), *patch)


def cli_map_from(tmp_path, mesh, method, *arguments):
    """The map `expmap compute` writes for the source and patch in `arguments`."""
    cli = os.environ.get("EXPMAP_CLI")
    if not cli:
        pytest.skip("EXPMAP_CLI is not set (ctest sets it)")
    out = tmp_path / "map.csv"
    subprocess.run([cli, "compute", mesh, "--method", method, *arguments, "-o", str(out)],
                   check=True, stdout=subprocess.DEVNULL, timeout=600)
    with open(out) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in ("vertex", "r", "theta", "u", "v")}


def assert_same_map(local, reference):
    # The CSV holds the doubles exactly (max_digits10 digits), both sides
    # build the same Surface_mesh, and ctest runs both with the same
    # environment, so OpenBLAS on as many threads: equal to the last bit
    # (different BLAS thread counts: test_determinism.py).
    np.testing.assert_array_equal(local.vertices, reference["vertex"].astype(np.int64))
    np.testing.assert_array_equal(local.r, reference["r"])
    np.testing.assert_array_equal(local.theta, reference["theta"])
    np.testing.assert_array_equal(local.uv[:, 0], reference["u"])
    np.testing.assert_array_equal(local.uv[:, 1], reference["v"])


@pytest.mark.parametrize("method", ["heat", "dem", "dgpc"])
def test_same_maps_as_the_command_line_program(tmp_path, elephant, method):
    path, V, F = elephant
    mapper = CLI_NAMES[method](V, F)
    for source in (0, 1000, 2774):
        local = mapper.compute(source, fraction=0.05)
        assert_same_map(local, cli_map(tmp_path, path, method, source, "--fraction", "0.05"))


def test_point_sources_as_the_command_line_program(tmp_path, elephant):
    # The faces of read_mesh() are the file's, corners in its order, as
    # --source-face takes them.
    path, V, F = elephant
    dgpc = expmap.GeodesicPolarCoordinates(V, F)
    for face, w in ((0, [0.2, 0.3, 0.5]), (4000, [0.0, 0.25, 0.75])):
        assert_same_map(dgpc.compute_at(face, w, vertices=60),
                        cli_map_from(tmp_path, path, "dgpc", "--source-face", str(face),
                                     "--barycentric", ",".join(map(str, w)), "--vertices", "60"))
    xyz = V[F[77]].mean(axis=0) + 0.001
    point = ",".join(repr(float(x)) for x in xyz)
    assert_same_map(dgpc.compute_at_point(xyz, vertices=60),
                    cli_map_from(tmp_path, path, "dgpc", "--source-point", point, "--vertices", "60"))


def test_exact_method_as_the_command_line_program(tmp_path, cactus):
    path, V, F = cactus
    local = expmap.ExactExponentialMap(V, F).compute(7, vertices=40)
    assert_same_map(local, cli_map(tmp_path, path, "exact", 7, "--vertices", "40"))


def test_heat_options_reach_the_library(tmp_path, elephant):
    path, V, F = elephant
    heat = expmap.HeatExponentialMap(V, F, time_factor=3.0, laplacian="direct",
                                     vertex_area="barycentric")
    local = heat.compute(500, radius=0.05, angle_estimator="heat_gradient",
                         near_source_blend=(1.0, 3.0))
    reference = cli_map(tmp_path, path, "heat", 500, "--radius", "0.05", "--time-factor", "3",
                        "--laplacian", "direct", "--vertex-area", "barycentric",
                        "--angles", "heat-gradient",
                        "--near-source-blend", "1,3")
    assert_same_map(local, reference)


def test_read_mesh_keeps_file_order(elephant):
    path, V, F = elephant
    with open(path) as f:
        lines = [line.split() for line in f if line.strip() and not line.startswith("#")]
    assert lines[0] == ["OFF"]
    n, m, _ = (int(x) for x in lines[1])
    first = [float(x) for x in lines[2]]
    assert V.shape == (n, 3) and V.dtype == np.float64
    assert F.shape == (m, 3) and F.dtype == np.int64
    np.testing.assert_array_equal(V[0], first)
