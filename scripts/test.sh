#!/usr/bin/env bash
# All tests, from a fresh Debian 12 machine: installs the dependencies,
# fetches the test meshes, builds everything and runs ctest.
#
# Every option the tests need is set here rather than taken from the cache:
# the main job configures build/ without tests, examples and benchmarks, and
# CMake would keep those settings. ctest fails if it finds no test.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-dependencies.sh
scripts/fetch-cgal-meshes.sh data/meshes
scripts/build.sh -DEXPMAP_BUILD_TESTS=ON -DEXPMAP_BUILD_TOOLS=ON -DEXPMAP_BUILD_EXAMPLES=ON -DEXPMAP_BUILD_BENCHMARKS=ON
cd build && ctest --output-on-failure --no-tests=error -j2
