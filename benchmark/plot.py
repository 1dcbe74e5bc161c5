#!/usr/bin/env python3
# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Draws the CSV rows of expmap-bench as the paper's Figs. 7 and 8.

    python3 benchmark/plot.py doc/benchmark/queries.csv [more.csv ...] --out-dir doc

writes
  doc/performance_fraction.png   median query time against patch fraction,
                                 log y, one panel per mesh, one line per
                                 method (bars: up to the 90th percentile)
  doc/performance_mesh_size.png  median query time against mesh vertices at a
                                 fixed fraction (--fraction, default 0.05),
                                 and time per patch vertex, one line per method

Several CSVs (e.g. a separate run of the slow `exact` method) are merged;
a later row for the same mesh, method and fraction replaces an earlier one.

Needs matplotlib. On Debian 12: `apt-get install python3-matplotlib` (what
scripts/benchmark.sh does); nothing is installed from pip.
"""

import argparse
import csv
import math
import os
import sys

# The order and look of the methods in every plot.
METHODS = [
    ("heat", "heat (localized)", "C0", "o"),
    ("heat-full", "heat (whole mesh)", "C0", "x"),
    ("dem", "DEM", "C1", "s"),
    ("dgpc", "DGPC", "C2", "^"),
    ("exact", "exact", "C3", "D"),
]


def read_rows(paths):
    rows = {}
    for path in paths:
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                if not r.get("median_ms"):
                    continue
                key = (r["mesh"], r["method"], float(r["fraction"]))
                rows[key] = {
                    "mesh": r["mesh"],
                    "vertices": int(r["vertices"]),
                    "method": r["method"],
                    "fraction": float(r["fraction"]),
                    "patch": float(r["patch_vertices"] or "nan"),
                    "median": float(r["median_ms"]),
                    "p90": float(r["p90_ms"] or r["median_ms"]),
                }
    return list(rows.values())


def method_style(name):
    for key, label, color, marker in METHODS:
        if key == name:
            return label, color, marker, ("--" if key == "heat-full" else "-")
    return name, None, ".", ":"


def ordered_methods(rows):
    present = {r["method"] for r in rows}
    known = [m[0] for m in METHODS if m[0] in present]
    return known + sorted(present - set(known))


def plot_fraction(plt, rows, path):
    meshes = sorted({(r["vertices"], r["mesh"]) for r in rows})
    n = len(meshes)
    cols = min(n, 2) if n > 1 else 1
    nrows = math.ceil(n / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(5.6 * cols, 4.2 * nrows), squeeze=False)
    for ax, (vertices, mesh) in zip(axes.flat, meshes):
        for method in ordered_methods(rows):
            pts = sorted((r["fraction"], r["median"], r["p90"]) for r in rows
                         if r["mesh"] == mesh and r["method"] == method)
            if not pts:
                continue
            label, color, marker, style = method_style(method)
            x = [p[0] for p in pts]
            y = [p[1] for p in pts]
            up = [max(0.0, p[2] - p[1]) for p in pts]
            ax.errorbar(x, y, yerr=[[0] * len(up), up], label=label, color=color,
                        marker=marker, linestyle=style, capsize=2, linewidth=1.4, markersize=5)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(f"{mesh} ({vertices:,} vertices)")
        ax.set_xlabel("patch fraction of the mesh")
        ax.set_ylabel("query time [ms] (median, bar to p90)")
        fractions = sorted({r["fraction"] for r in rows if r["mesh"] == mesh})
        ax.set_xticks(fractions)
        ax.set_xticklabels([f"{f:g}" for f in fractions])
        ax.minorticks_off()
        ax.xaxis.set_minor_locator(plt.NullLocator())
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize=8)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    fig.suptitle("Query time against patch size (cf. Herholz & Alexa 2019, Fig. 7)")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def plot_mesh_size(plt, rows, fraction, path):
    available = sorted({r["fraction"] for r in rows})
    chosen = min(available, key=lambda f: abs(math.log(f) - math.log(fraction)))
    if abs(chosen - fraction) > 1e-12:
        print(f"plot.py: no rows at fraction {fraction}; using {chosen}", file=sys.stderr)
    sel = [r for r in rows if r["fraction"] == chosen]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11.5, 4.4))
    for method in ordered_methods(sel):
        pts = sorted((r["vertices"], r["median"], r["patch"], r["mesh"]) for r in sel
                     if r["method"] == method)
        if not pts:
            continue
        label, color, marker, style = method_style(method)
        x = [p[0] for p in pts]
        left.plot(x, [p[1] for p in pts], label=label, color=color, marker=marker,
                  linestyle=style)
        per_vertex = [(p[0], 1e3 * p[1] / p[2]) for p in pts if p[2] and p[2] > 0]
        right.plot([p[0] for p in per_vertex], [p[1] for p in per_vertex], label=label,
                   color=color, marker=marker, linestyle=style)
    meshes = sorted({(r["vertices"], r["mesh"]) for r in sel})
    for ax in (left, right):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("mesh vertices")
        ax.set_xticks([v for v, _ in meshes])
        ax.set_xticklabels([f"{m}\n{v:,}" for v, m in meshes], fontsize=7)
        ax.xaxis.set_minor_locator(plt.NullLocator())
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize=8)
    left.set_ylabel("query time [ms] (median)")
    left.set_title(f"patch = {chosen:g} of the mesh")
    right.set_ylabel("time per patch vertex [µs]")
    right.set_title(f"patch = {chosen:g} of the mesh, per patch vertex")
    fig.suptitle("Query time against mesh size (cf. Herholz & Alexa 2019, Fig. 8)")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def plot_heat_over_dgpc(plt, rows, path):
    """Heat query time over DGPC's, per mesh and fraction (the paper's claim: below 1)."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    meshes = sorted({(r["vertices"], r["mesh"]) for r in rows})
    for vertices, mesh in meshes:
        median = {(r["method"], r["fraction"]): r["median"] for r in rows if r["mesh"] == mesh}
        pts = sorted((f, median[("heat", f)] / median[("dgpc", f)])
                     for (m, f) in median if m == "heat" and ("dgpc", f) in median
                     and median[("dgpc", f)] > 0)
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o",
                    label=f"{mesh} ({vertices:,})")
    ax.axhline(1.0, color="black", linewidth=0.8)
    ax.set_xscale("log")
    fractions = sorted({r["fraction"] for r in rows})
    ax.set_xticks(fractions)
    ax.set_xticklabels([f"{f:g}" for f in fractions])
    ax.xaxis.set_minor_locator(plt.NullLocator())
    ax.set_xlabel("patch fraction of the mesh")
    ax.set_ylabel("heat median / DGPC median")
    ax.set_title("Heat query time relative to DGPC (below 1: heat is faster)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv", nargs="+", help="expmap-bench --csv output(s)")
    parser.add_argument("--out-dir", default="doc", help="where the PNGs go (default: doc)")
    parser.add_argument("--fraction", type=float, default=0.05,
                        help="patch fraction of the mesh-size plot (default: 0.05)")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("plot.py needs matplotlib: apt-get install python3-matplotlib")
    rows = read_rows(args.csv)
    if not rows:
        sys.exit("plot.py: no rows with timings in " + ", ".join(args.csv))
    os.makedirs(args.out_dir, exist_ok=True)
    fraction_png = os.path.join(args.out_dir, "performance_fraction.png")
    size_png = os.path.join(args.out_dir, "performance_mesh_size.png")
    plot_fraction(plt, rows, fraction_png)
    plot_mesh_size(plt, rows, args.fraction, size_png)
    ratio_png = os.path.join(args.out_dir, "performance_heat_over_dgpc.png")
    plot_heat_over_dgpc(plt, rows, ratio_png)
    print(f"wrote {fraction_png}, {size_png} and {ratio_png}")


if __name__ == "__main__":
    main()
