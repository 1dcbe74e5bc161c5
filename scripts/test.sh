#!/usr/bin/env bash
# All tests, from a fresh Debian 12 machine: installs the dependencies,
# fetches the test meshes, builds everything and runs ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-dependencies.sh
scripts/fetch-cgal-meshes.sh data/meshes
scripts/build.sh
cd build && ctest --output-on-failure -j2
