#!/usr/bin/env python3
# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Maps a patch of a mesh with the heat method and shows it flattened in the
(u, v) plane, coloured by geodesic distance (Matplotlib, when installed).

    PYTHONPATH=build/python python3 examples/python_patch.py \
        [MESH] [--source V] [--fraction F] [-o patch.png]

Without a display the picture goes to a PNG file (default: patch.png); with
-o it is always saved. Without Matplotlib it prints the map's numbers only.
"""

import argparse
import os
import sys

import numpy as np

import expmap


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", default=os.path.join(here, "..", "data", "meshes", "elephant.off"))
    parser.add_argument("--source", type=int, default=0)
    parser.add_argument("--fraction", type=float, default=0.05)
    parser.add_argument("-o", "--output", help="save the picture here (.png, .pdf, .svg)")
    args = parser.parse_args()

    V, F = expmap.read_mesh(args.mesh)
    heat = expmap.HeatExponentialMap(V, F)          # precomputation, once per mesh
    local = heat.compute(args.source, fraction=args.fraction)
    print("%s: %d vertices; patch of %d vertices around %d, max r %.4g"
          % (args.mesh, len(V), len(local), args.source, local.r.max()))

    try:
        import matplotlib
    except ImportError:
        print("matplotlib is not installed: no picture", file=sys.stderr)
        return 0
    output = args.output
    if output is None and not os.environ.get("DISPLAY"):
        output = "patch.png"
    if output is not None:
        matplotlib.use("Agg")  # headless: no window needed
    import matplotlib.pyplot as plt
    import matplotlib.tri as mtri

    # The mesh's triangles with all three corners in the patch, in (u, v).
    row = np.full(len(V), -1)
    row[local.vertices] = np.arange(len(local))
    inside = np.all(row[F] >= 0, axis=1)
    triangles = row[F[inside]]
    figure, axes = plt.subplots(figsize=(6, 6))
    shading = axes.tripcolor(mtri.Triangulation(local.uv[:, 0], local.uv[:, 1], triangles),
                             local.r, shading="gouraud", cmap="viridis")
    axes.triplot(local.uv[:, 0], local.uv[:, 1], triangles, color="k", linewidth=0.2)
    axes.set_aspect("equal")
    axes.set_title("heat method, source %d, %d vertices" % (args.source, len(local)))
    figure.colorbar(shading, ax=axes, label="geodesic distance r")
    if output is not None:
        figure.savefig(output, dpi=120)
        print("wrote", output)
    else:
        plt.show()
    return 0


if __name__ == "__main__":
    sys.exit(main())
