# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""How far from the source each method's 5% patches stay one-to-one: the
median fold-free radius as a fraction of the patch radius (the largest r),
and the median share of the patch's vertices inside it (what trim_folds=True
keeps), over all patches and over those that fold, on the folds study's
meshes and sources (doc/evaluation/folds_detail.csv).

usage: PYTHONPATH=build/python python3 benchmark/fold_free_radius.py [MESH_DIR]

Prints a Markdown table per measure. Every method with its defaults (heat:
m = 10, intrinsic Delaunay Laplacian).
"""

import csv
import os
import sys

import numpy as np

import expmap

HERE = os.path.dirname(os.path.abspath(__file__))
MESHES = ["armadillo", "bunny00", "refined_elephant", "camel", "bull", "dino"]
METHODS = ["heat", "dem", "dgpc", "exact"]
LABELS = {"heat": "heat", "dem": "DEM", "dgpc": "DGPC", "exact": "exact"}


def study_sources():
    """The folds study's sources per mesh, in its order (repeats included)."""
    sources = {}
    with open(os.path.join(HERE, "..", "doc", "evaluation", "folds_detail.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if row["method"] == "dem":  # one row per source and method
                sources.setdefault(row["mesh"], []).append(int(row["source"]))
    return sources


def measure(mesh_dir):
    """(mesh, method) -> per patch: fold-free radius / patch radius, share of
    vertices inside, whether it folds."""
    sources = study_sources()
    results = {}
    for name in MESHES:
        V, F = expmap.read_mesh(os.path.join(mesh_dir, name + ".off"))
        for method in METHODS:
            batch = expmap.METHODS[method](V, F).compute_many(sources[name], fraction=0.05)
            radius, kept, folding = [], [], []
            for i, m in enumerate(batch):
                if m.error is not None:
                    continue
                ffr = batch.fold_free_radius[i]
                folds = flips(m, F)
                folding.append(folds)
                radius.append(ffr / m.r.max())
                kept.append(np.count_nonzero(m.r < ffr) / len(m.r) if folds else 1.0)
            results[name, method] = (np.array(radius), np.array(kept), np.array(folding, dtype=bool))
            print("%s %s: %d of %d patches fold" % (name, method, sum(folding), len(folding)),
                  file=sys.stderr)
    return results


def flips(m, F):
    """Whether the map of a BatchMap turns a triangle over (or collapses it)."""
    position = np.full(F.max() + 1, -1, dtype=np.int64)
    position[m.vertices] = np.arange(len(m.vertices))
    corners = position[F]
    corners = corners[(corners >= 0).all(axis=1)]
    a, b, c = (np.stack([m.u, m.v], axis=1)[corners[:, k]] for k in range(3))
    area2 = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    return bool(np.any(~(area2 > 0)))


def table(results, column, title):
    print("\n%s\n" % title)
    print("| mesh | " + " | ".join(LABELS[m] for m in METHODS) + " |")
    print("|---|" + "---|" * len(METHODS))
    for name in MESHES:
        cells = []
        for m in METHODS:
            values, folds = results[name, m][column], results[name, m][2]
            cells.append("%.2f / %s" % (np.median(values),
                                        "%.2f" % np.median(values[folds]) if folds.any() else "-"))
        print("| %s | %s |" % (name, " | ".join(cells)))


def main():
    mesh_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "data", "meshes")
    results = measure(mesh_dir)
    table(results, 0, "Median fold-free radius / patch radius (all patches / patches that fold)")
    table(results, 1, "Median share of patch vertices inside the fold-free disk (all / folding)")
    print("\nPatches that fold\n")
    print("| mesh | " + " | ".join(LABELS[m] for m in METHODS) + " |")
    print("|---|" + "---|" * len(METHODS))
    for name in MESHES:
        print("| %s | %s |" % (name, " | ".join("%d/%d" % (results[name, m][2].sum(), len(results[name, m][2]))
                                              for m in METHODS)))


if __name__ == "__main__":
    main()
