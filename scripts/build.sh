#!/usr/bin/env bash
# Configures and builds expmap (Release, 2 jobs) in build/, or in the folder
# EXPMAP_BUILD_DIR names. Extra arguments go to cmake, e.g.
# -DEXPMAP_BUILD_TESTS=OFF. With EXPMAP_CONFIGURE_ONLY=1 it only configures
# (test/test_command/after_main_job.sh uses that to check the scripts).
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache keys on paths relative to the checkout, so a fresh clone elsewhere
# (CI) reuses what an earlier build compiled.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
build_dir="${EXPMAP_BUILD_DIR:-build}"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@"
if [[ "${EXPMAP_CONFIGURE_ONLY:-0}" != 1 ]]; then
  cmake --build "$build_dir" -j2
fi
