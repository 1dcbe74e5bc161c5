#!/usr/bin/env bash
# Runs browser_test.mjs, or skips it (exit 77) where Node.js or Chromium is
# not installed; scripts/install-dependencies.sh installs both.
set -euo pipefail
command -v node >/dev/null || { echo "skipped: node is not installed"; exit 77; }
[ -x "${EXPMAP_CHROMIUM:-/usr/bin/chromium}" ] || { echo "skipped: chromium is not installed"; exit 77; }
exec node "$(dirname "$0")/browser_test.mjs" "$@"
