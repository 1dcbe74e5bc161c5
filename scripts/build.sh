#!/usr/bin/env bash
# Configures and builds expmap in build/ (Release, 2 jobs). Extra arguments
# go to cmake, e.g. -DEXPMAP_BUILD_TESTS=OFF.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j2
