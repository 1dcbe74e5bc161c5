# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Local exponential maps (geodesic polar coordinates) on triangle meshes.

NumPy in, NumPy out::

    import expmap
    V, F = expmap.read_mesh("data/meshes/elephant.off")
    heat = expmap.HeatExponentialMap(V, F)            # precomputes once
    local = heat.compute(0, fraction=0.05)             # one map
    local.vertices, local.r, local.theta, local.uv     # NumPy arrays
    batch = heat.compute_many(range(100), vertices=50, threads=0)  # many, no GIL
    batch.offsets, batch.vertex, batch.u, batch.v, batch.errors
    for source, m in zip(range(100), batch):          # per source: views, no copies
        m.vertices, m.r, m.theta, m.u, m.v, m.error
    dgpc = expmap.GeodesicPolarCoordinates(V, F)      # sources at points of faces:
    faces, barycentric = dgpc.locate(points)           # nearest surface points (k x 3 in)
    dgpc.compute_at_point(points[0], radius=0.1)       # or compute_at(face, barycentric, ...)

The four methods: HeatExponentialMap (Herholz & Alexa 2019, the smoothed
map by heat diffusion), DiscreteExponentialMap (Schmidt et al. 2006),
GeodesicPolarCoordinates (Melvaer & Reimers 2012) and ExactExponentialMap
(exact polyhedral geodesics, a slow reference). Invalid input raises
ValueError (expmap.InvalidInput) with the library's message; a failed
computation raises RuntimeError (expmap.ComputationError). expmap.dask
spreads many meshes over a Dask cluster. expmap.__version__ is the
library's version (include/expmap/version.h), compiled into the module.
"""

# METHODS: the method classes by the names the command-line program uses
# (--method), the library's.
from ._expmap import (
    AngleEstimator,
    BatchMap,
    BatchMaps,
    ComputationError,
    DiscreteExponentialMap,
    ExactExponentialMap,
    FactorPrecision,
    GeodesicPolarCoordinates,
    HeatExponentialMap,
    HeatFallback,
    InvalidInput,
    LaplacianMode,
    LocalMap,
    METHODS,
    MeshFileError,
    PoissonRegularization,
    VertexArea,
    read_mesh,
    __version__,
)

__all__ = [
    "AngleEstimator",
    "BatchMap",
    "BatchMaps",
    "ComputationError",
    "DiscreteExponentialMap",
    "ExactExponentialMap",
    "FactorPrecision",
    "GeodesicPolarCoordinates",
    "HeatExponentialMap",
    "HeatFallback",
    "InvalidInput",
    "LaplacianMode",
    "LocalMap",
    "METHODS",
    "MeshFileError",
    "PoissonRegularization",
    "VertexArea",
    "read_mesh",
]
