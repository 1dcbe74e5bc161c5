#!/usr/bin/env bash
# Makes the folder `expmap view` serves: installs the page's npm packages
# (three.js, and playwright-core for the browser test) from
# tools/viewer/package-lock.json into NPM_DIR, then copies the page and
# three.js's module build into OUT_DIR. The build runs it (tools/CMakeLists.txt);
# NPM_DIR and OUT_DIR are in the build tree, so the source tree stays clean.
#
# usage: scripts/viewer-assets.sh NPM_DIR OUT_DIR
set -euo pipefail
src="$(cd "$(dirname "$0")/../tools/viewer" && pwd)"
npm_dir="$1"
out="$2"
mkdir -p "$npm_dir"
# npm ci again only when the lock file changed or an earlier one failed.
if ! cmp -s "$src/package-lock.json" "$npm_dir/package-lock.json" ||
   [ ! -f "$npm_dir/node_modules/three/build/three.module.js" ]; then
  cp "$src/package.json" "$src/package-lock.json" "$npm_dir/"
  (cd "$npm_dir" && npm ci --no-audit --no-fund --loglevel=error)
fi
three="$npm_dir/node_modules/three"
rm -rf "$out"
mkdir -p "$out/three/addons/controls"
cp "$src"/www/* "$out/"
cp "$three/build/three.module.js" "$three/build/three.core.js" "$three/LICENSE" "$out/three/"
cp "$three/examples/jsm/controls/OrbitControls.js" "$out/three/addons/controls/"
