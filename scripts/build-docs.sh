#!/usr/bin/env bash
# Builds the reference manual with Doxygen (an optional dependency, installed
# here) into build/doc/reference/html/index.html. Doxygen's warnings, e.g.
# public API without documentation, go to build/doc/reference/warnings.log.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-dependencies.sh doxygen
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --target doc
