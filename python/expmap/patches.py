# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The polar patch operator that geodesic convolutional networks apply
(Masci et al., ICCV workshops 2015): what ``method.patch_operator()`` returns."""

import numpy as np


class PolarPatchOperator:
    """Patches of per-vertex signals on the polar grids of many sources.

    weights: a ``scipy.sparse.csr_matrix`` of shape (sources * rings * rays,
        vertices) where SciPy is installed, else the tuple (data, indices,
        indptr) of its compressed rows; row (s * rings + i) * rays + j is
        grid point (ring i, ray j) of source s.
    sampled: bool array (sources, rings, rays), False where a grid point has
        no weights (beyond the map's fold-free disk, past a boundary, or its
        source's query failed).
    sources: the source rows, in the operator's order.
    radius, rings, rays: the grid: rho_i = (i + 1/2) radius / rings,
        theta_j = 2 pi j / rays.
    errors: per source, "" or why its query failed.
    """

    def __init__(self, data, indices, indptr, vertices, sources, radius, rings, rays, sampled,
                 errors):
        self.shape = (len(indptr) - 1, int(vertices))
        self.sources = sources
        self.radius = float(radius)
        self.rings = int(rings)
        self.rays = int(rays)
        self.sampled = sampled
        self.errors = list(errors)
        self._csr = (data, indices, indptr)
        try:
            import scipy.sparse
        except ImportError:
            self.weights = self._csr
        else:
            self.weights = scipy.sparse.csr_matrix(self._csr, shape=self.shape)

    def patches(self, signal):
        """The patches of ``signal`` (vertices,) or (vertices, channels):
        an array (sources, rings, rays) or (sources, rings, rays, channels),
        0 where ``sampled`` is False."""
        x = np.asarray(signal, dtype=np.float64)
        if x.shape[:1] != (self.shape[1],) or x.ndim > 2:
            raise ValueError("signal must have shape (%d,) or (%d, channels) (got %s)"
                             % (self.shape[1], self.shape[1], x.shape))
        columns = x.reshape(self.shape[1], -1)
        data, indices, indptr = self._csr
        # y[r] = sum over row r's entries of weight * x[column]
        products = data[:, None] * columns[indices]
        rows = np.repeat(np.arange(self.shape[0]), np.diff(indptr))
        y = np.zeros((self.shape[0], columns.shape[1]))
        np.add.at(y, rows, products)
        shape = (len(self.sources), self.rings, self.rays) + x.shape[1:]
        return y.reshape(shape)

    def __repr__(self):
        return "PolarPatchOperator(%d sources, %d x %d grid of radius %g, %d of %d points sampled)" % (
            len(self.sources), self.rings, self.rays, self.radius, int(self.sampled.sum()),
            self.sampled.size)
