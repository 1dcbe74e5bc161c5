# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Where the tests find the meshes and the command-line program: ctest sets
EXPMAP_DATA_DIR and EXPMAP_CLI (and PYTHONPATH to the built package)."""

import os

import pytest

import expmap


def pytest_configure(config):
    # Debian 12's distributed 2022.12 on tornado 6.2: noise, not ours.
    config.addinivalue_line("filterwarnings", "ignore:make_current is deprecated:DeprecationWarning")


def data_dir():
    return os.environ.get("EXPMAP_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data", "meshes"))


def mesh_path(name):
    path = os.path.join(data_dir(), name)
    if not os.path.exists(path):
        pytest.skip("mesh %s not found (scripts/fetch-cgal-meshes.sh fetches it)" % path)
    return path


@pytest.fixture(scope="session")
def elephant():
    """A real mesh of 2,775 vertices: (path, V, F)."""
    path = mesh_path("elephant.off")
    return (path,) + tuple(expmap.read_mesh(path))


@pytest.fixture(scope="session")
def cactus():
    """A smaller real mesh (620 vertices): (path, V, F)."""
    path = mesh_path("cactus.off")
    return (path,) + tuple(expmap.read_mesh(path))
