#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: installs the dependencies,
# builds the `expmap` program, fetches the armadillo mesh from Debian's
# libcgal-demo package and computes an exponential map on it. Writes
# out/armadillo.csv (r, theta, u, v per vertex), out/armadillo.obj (the
# patch with texture coordinates) and out/armadillo.svg (the flattened patch).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-dependencies.sh
scripts/fetch-cgal-meshes.sh data/meshes
scripts/build.sh -DEXPMAP_BUILD_TESTS=OFF -DEXPMAP_BUILD_BENCHMARKS=OFF -DEXPMAP_BUILD_EXAMPLES=OFF
mkdir -p out
build/tools/expmap compute data/meshes/armadillo.off --source 2000 --fraction 0.05 \
  -o out/armadillo.csv -o out/armadillo.obj -o out/armadillo.svg
