#!/usr/bin/env bash
# Measures how many maps a second the viewer draws while the source is
# dragged across the surface, in headless Chromium (WebGL in software):
#   scripts/viewer-drag-rate.sh [MESH] [METHOD] [FRACTION] [extra --name value ...]
# e.g. scripts/viewer-drag-rate.sh data/meshes/refined_elephant.off heat 0.02 --m 10
# Needs the build (scripts/build.sh) in build/ or EXPMAP_BUILD_DIR.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EXPMAP_BUILD_DIR:-build}"
mesh="${1:-data/meshes/refined_elephant.off}"
method="${2:-dgpc}"
fraction="${3:-0.02}"
shift $(( $# < 3 ? $# : 3 ))
exec node test/viewer/drag_rate.mjs --expmap "$build/tools/expmap" --mesh "$mesh" \
  --npm-dir "$build/tools/viewer-npm" --method "$method" --fraction "$fraction" "$@"
