#!/usr/bin/env bash
# The performance study (Herholz & Alexa 2019, Figs. 7 and 8) on this
# machine, from a fresh Debian 12 machine: installs the dependencies (and
# python3-matplotlib for the plots), fetches the libcgal-demo meshes, builds
# expmap-bench and times queries from 20 random sources on armadillo,
# bunny00, refined_elephant and elephant_loop2 (refined_elephant
# Loop-subdivided twice, 711,420 vertices; made by the benchmark and cached
# as build/meshes/elephant_loop2.off) for the methods heat, heat-full, dem
# and dgpc at patch fractions 0.01, 0.02, 0.05, 0.1 and 0.25.
#
# Writes
#   doc/benchmark/queries.csv   one row per mesh, method and fraction
#   doc/benchmark/meshes.csv    precompute time, peak memory, factor sizes per mesh
#   doc/benchmark/detail.csv    one row per query (with the stream floor)
#   doc/benchmark/output.txt    the tables expmap-bench printed
#   doc/performance_fraction.png, doc/performance_mesh_size.png
# (expmap_bench.cpp's header describes every column.)
#
# Environment:
#   EXPMAP_BENCH_SOURCES=N       sources per mesh (default 20)
#   EXPMAP_BENCH_REPEATS=K       runs per query, the fastest kept (default 3;
#                                the methods take turns per source)
#   EXPMAP_BENCH_FULL_SOURCES=N  sources for heat-full, the whole-mesh query
#                                (default 20; about 1 s each on elephant_loop2)
#   EXPMAP_BENCH_EXACT=1         also time the exact method, in a second run
#                                on the three libcgal-demo meshes only with
#                                EXPMAP_BENCH_EXACT_SOURCES (default 5) sources
#                                (about 0.5 s per 6,500-vertex patch; on
#                                elephant_loop2 a 25% patch would take hours):
#                                doc/benchmark/exact.csv, merged into the plots
#
# Time on 2 cores: about 4 minutes of benchmark with 3 runs per query
# (elephant_loop2 dominates: 12-25 s precompute, then per source and run
# ~0.4 s of heat, dem and dgpc queries and ~0.9 s of heat-full),
# plus the build (~2 minutes) and, on a fresh machine, the installs.
# Run it on a quiet machine: the timings are wall-clock.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS

scripts/install-dependencies.sh
# The plots need Debian's matplotlib (for /usr/bin/python3; pip is not used).
python=/usr/bin/python3
if ! "$python" -c "import matplotlib" 2>/dev/null; then
  if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -q --no-install-recommends python3 python3-matplotlib
fi
scripts/fetch-cgal-meshes.sh data/meshes

# Only the benchmark target: scripts/build.sh would also build every test
# suite, which alone takes longer than the whole study.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEXPMAP_BUILD_BENCHMARKS=ON
cmake --build build --target expmap_bench -j2
bench=build/benchmark/expmap-bench

fractions=0.01,0.02,0.05,0.1,0.25
sources=${EXPMAP_BENCH_SOURCES:-20}
repeats=${EXPMAP_BENCH_REPEATS:-3}
full_sources=${EXPMAP_BENCH_FULL_SOURCES:-20}
out=doc/benchmark
mkdir -p "$out"

# Smallest mesh first, the subdivided one last (it is also the largest).
"$bench" --mesh data/meshes/armadillo.off --mesh data/meshes/bunny00.off \
  --mesh data/meshes/refined_elephant.off \
  --subdivide-elephant 2 --cache-dir build/meshes \
  --methods heat,heat-full,dem,dgpc --fractions "$fractions" \
  --sources "$sources" --full-sources "$full_sources" --seed 1 --repeats "$repeats" \
  --csv "$out/queries.csv" --stats "$out/meshes.csv" --detail "$out/detail.csv" \
  | tee "$out/output.txt"

csvs=("$out/queries.csv")
if [ "${EXPMAP_BENCH_EXACT:-0}" = 1 ]; then
  "$bench" --mesh data/meshes/armadillo.off --mesh data/meshes/bunny00.off \
    --mesh data/meshes/refined_elephant.off \
    --methods exact --fractions "$fractions" \
    --sources "${EXPMAP_BENCH_EXACT_SOURCES:-5}" --seed 1 --repeats 1 \
    --csv "$out/exact.csv" --detail "$out/exact_detail.csv" \
    | tee "$out/exact_output.txt"
  csvs+=("$out/exact.csv")
fi

"$python" benchmark/plot.py "${csvs[@]}" --out-dir doc
echo "benchmark done in $((SECONDS - start)) s: $out/, doc/performance_*.png"
