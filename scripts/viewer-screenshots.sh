#!/usr/bin/env bash
# Renders the viewer's pictures in doc/figures (viewer.png, viewer_compare.png)
# in headless Chromium from the build in build/ (or EXPMAP_BUILD_DIR):
#   scripts/viewer-screenshots.sh [MESH] [--point X,Y,Z] [--method M] [--compare M] [--fraction F]
#                                 [--name NAME]   (writes NAME.png, NAME_compare.png)
# The default: armadillo, the source on its snout, heat beside DGPC.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EXPMAP_BUILD_DIR:-build}"
if [ $# -ge 1 ]; then mesh="$1"; shift; else
  mesh=data/meshes/armadillo.off
  set -- --point -3.18,75.14,-30.36 --fraction 0.05 --method heat --compare dgpc
fi
exec node test/viewer/screenshots.mjs --expmap "$build/tools/expmap" --mesh "$mesh" \
  --npm-dir "$build/tools/viewer-npm" --out doc/figures "$@"
