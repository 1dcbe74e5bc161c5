#!/usr/bin/env bash
# The boundary study: the four methods at sources on and near the boundary
# of every libcgal-demo mesh that has one, and at interior sources whose
# patches stay clear of it, against the exact map, with the heat method's
# targets relative to DGPC (benchmark/evaluation/boundary_study.cpp
# documents the measures and options).
#
#   scripts/boundary-study.sh [OUT_PREFIX] [expmap-boundary-study options]
#
# Builds only expmap-boundary-study in build/ (configuring it if needed) and
# writes OUT_PREFIX.txt (the summary), OUT_PREFIX.csv (one row per map),
# OUT_PREFIX_summary.csv; OUT_PREFIX defaults to boundary_study. Run it
# before and after a change to the heat method and compare the summaries.
# About a minute on 2 cores for all meshes, plus the build (~2-4 minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=${1:-boundary_study}
[ $# -gt 0 ] && shift
if [ ! -f build/CMakeCache.txt ] || ! grep -q "EXPMAP_BUILD_BENCHMARKS:BOOL=ON" build/CMakeCache.txt; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEXPMAP_BUILD_BENCHMARKS=ON
fi
cmake --build build -j"$(nproc)" --target expmap_boundary_study
build/benchmark/expmap-boundary-study --csv "$prefix.csv" --summary-csv "${prefix}_summary.csv" \
  "$@" | tee "$prefix.txt"
