#!/usr/bin/env bash
# Installs what building and testing expmap needs, from Debian 12's archive.
# Run as root (or through sudo).
set -euo pipefail
if [ "$(id -u)" -ne 0 ]; then exec sudo "$0" "$@"; fi
export DEBIAN_FRONTEND=noninteractive
packages=(g++ cmake make ccache
          libcgal-dev libeigen3-dev libsuitesparse-dev libmetis-dev
          libboost-graph-dev libboost-test-dev
          # The Python module, its tests and its Dask layer (python/, test/python/).
          python3-dev python3-numpy pybind11-dev python3-pytest python3-distributed)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  # apt-get download (for the meshes) needs package lists too.
  [ -n "$(ls -A /var/lib/apt/lists 2>/dev/null | grep -v lock)" ] || apt-get update -q
fi
