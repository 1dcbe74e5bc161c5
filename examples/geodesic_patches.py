#!/usr/bin/env python3
# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Geodesic patches for learning: the polar patch operator of a mesh applied
to a per-vertex signal, and a picture of a few patches beside where they sit.

    PYTHONPATH=build/python python3 examples/geodesic_patches.py \
        [MESH] [--radius R] [--rings 5] [--rays 16] [-o patches.png]

The signal is the heat kernel signature (Sun et al., SGP 2009) at three
times, from the 40 lowest eigenpairs of the cotan Laplacian (SciPy), or the
vertices' heights where SciPy is missing. A network would take
`op.patches(signal)`: (vertices, rings, rays, channels).
"""

import argparse
import os
import sys

import numpy as np

import expmap


def cotan_laplacian(V, F):
    """The cotan Laplacian L (positive semi-definite) and the lumped mass M."""
    import scipy.sparse as sp
    L = sp.csr_matrix((len(V), len(V)))
    area = np.zeros(len(V))
    for k in range(3):
        i, j, o = F[:, k], F[:, (k + 1) % 3], F[:, (k + 2) % 3]
        a, b = V[i] - V[o], V[j] - V[o]
        cross = np.linalg.norm(np.cross(a, b), axis=1)
        cot = np.einsum("ij,ij->i", a, b) / np.maximum(cross, 1e-300)
        L = L + sp.csr_matrix((-0.5 * cot, (i, j)), shape=L.shape)
        np.add.at(area, i, cross / 6)
    L = L + L.T
    L = L - sp.diags(np.asarray(L.sum(axis=1)).ravel())
    return L, sp.diags(area)


def signal_of(V, F):
    try:
        import scipy.sparse.linalg
    except ImportError:
        print("SciPy is not installed: the signal is the height", file=sys.stderr)
        return V[:, 2:3], ["height"]
    L, M = cotan_laplacian(V, F)
    values, vectors = scipy.sparse.linalg.eigsh(L, k=40, M=M, sigma=-1e-8)
    times = 4 / values[-1] * np.array([1, 4, 16])
    hks = (vectors ** 2) @ np.exp(-np.outer(values, times))
    return hks / hks.max(axis=0), ["HKS t=%.2g" % t for t in times]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?",
                        default=os.path.join(here, "..", "data", "meshes", "elephant.off"))
    parser.add_argument("--radius", type=float, help="default: 5 mean edge lengths")
    parser.add_argument("--rings", type=int, default=5)
    parser.add_argument("--rays", type=int, default=16)
    parser.add_argument("--show", type=int, default=4, help="patches in the picture")
    parser.add_argument("-o", "--output", default="patches.png")
    args = parser.parse_args()

    V, F = expmap.read_mesh(args.mesh)
    edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    radius = args.radius or 5 * np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1).mean()
    # DGPC places grid points closest to the exact map among the fast methods.
    method = expmap.GeodesicPolarCoordinates(V, F)
    op = method.patch_operator(radius=radius, rings=args.rings, rays=args.rays, threads=0)
    signal, names = signal_of(V, F)
    patches = op.patches(signal)  # (vertices, rings, rays, channels)
    print("%s: %d vertices, %d x %d grid of radius %.4g: operator %s, %.1f%% of the grid "
          "sampled, patches %s" % (args.mesh, len(V), args.rings, args.rays, radius,
                                   op.weights.shape, 100 * op.sampled.mean(), patches.shape))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rng = np.random.default_rng(1)
    shown = rng.choice(len(V), size=args.show, replace=False)
    figure = plt.figure(figsize=(3 * (args.show + 1), 6))
    surface = figure.add_subplot(1, args.show + 1, 1, projection="3d")
    surface.plot_trisurf(V[:, 0], V[:, 1], V[:, 2], triangles=F, color="0.85", linewidth=0)
    surface.scatter(*V[shown].T, color="red", s=30)
    for k, s in enumerate(shown):
        surface.text(*V[s], str(k + 1), color="red")
    surface.set_axis_off()
    rho = np.arange(args.rings + 1) * radius / args.rings        # ring edges
    theta = (np.arange(args.rays + 1) - 0.5) * 2 * np.pi / args.rays  # ray edges
    for k, s in enumerate(shown):
        for c in range(2):
            axes = figure.add_subplot(2, args.show + 1, c * (args.show + 1) + k + 2,
                                      projection="polar")
            axes.grid(False)
            values = np.ma.masked_where(~op.sampled[s], patches[s, :, :, min(c, patches.shape[3] - 1)])
            axes.pcolormesh(theta, rho, values, cmap="viridis", shading="flat")
            axes.set_xticklabels([])
            axes.set_yticklabels([])
            axes.set_title("%d: %s" % (k + 1, names[min(c, len(names) - 1)]), fontsize=8)
    figure.tight_layout()
    figure.savefig(args.output, dpi=100)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
