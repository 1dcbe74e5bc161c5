#!/usr/bin/env bash
# Installs what building and testing expmap needs, from Debian 12's archive.
# Run as root (or through sudo). Arguments name optional extra packages
# (scripts/build-docs.sh passes doxygen).
set -euo pipefail
if [ "$(id -u)" -ne 0 ]; then exec sudo "$0" "$@"; fi
export DEBIAN_FRONTEND=noninteractive
# libopenblas0-pthread: CHOLMOD's supernodal factorization runs on the
# machine's BLAS, which is Debian's reference BLAS unless an optimized one is
# installed; OpenBLAS factors large meshes faster (doc/paper_scale.md).
# liblapack-dev: the library calls LAPACK's SVD itself
# (include/expmap/internal/solver/Low_rank_rows_below.h).
packages=(g++ cmake make ccache
          libcgal-dev libeigen3-dev libsuitesparse-dev libmetis-dev liblapack-dev
          libboost-graph-dev libboost-test-dev libopenblas0-pthread
          libopenmesh-dev
          # The Python module, its tests and its Dask layer (python/, test/python/),
          # and the test that loads `expmap batch` .npz output with NumPy.
          python3-dev python3-numpy python3-scipy pybind11-dev python3-pytest python3-distributed
          # `pip install .` (pyproject.toml) and its test in a fresh venv.
          python3-pip python3-venv python3-setuptools python3-wheel
          # `expmap view`: its web server, and Chromium for the test that
          # drives its page (tools/viewer, test/viewer).
          libcpp-httplib-dev chromium
          "$@")
# The page's npm packages (three.js, playwright-core) need Node.js and npm;
# a Node.js installed otherwise (with its own npm) is kept.
command -v node >/dev/null && command -v npm >/dev/null || packages+=(nodejs npm)
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

# Debian's alternatives choose the BLAS that libblas.so.3 loads: in automatic
# mode (the default) the one of highest priority, OpenBLAS once installed.
# A choice made by hand is kept, with a note.
blas=$(update-alternatives --query "libblas.so.3-$(gcc -dumpmachine)" 2>/dev/null |
       awk '/^Value:/ {print $2}')
case "$blas" in
  *openblas*|"") ;;
  *) echo "note: libblas.so.3 is $blas, not OpenBLAS: CHOLMOD factors large meshes" \
          "slower (update-alternatives --auto libblas.so.3-$(gcc -dumpmachine))" >&2 ;;
esac
