#!/usr/bin/env bash
# `pip install` of the checkout into a fresh virtual environment, as the
# README tells a Python user: builds a wheel (`pip wheel`, the step `pip
# install .` takes), installs it, then imports expmap from an unrelated folder
# and maps a mesh. The installed module must be the one in the environment
# and must give the same map, bit for bit, as the build tree's module.
#
# usage: install_in_venv.sh PYTHON SOURCE_DIR BUILD_TREE_PYTHONPATH MESH WORK_DIR
set -euo pipefail
python=$1 source_dir=$2 build_tree_package=$3 mesh=$4 work=$5

rm -rf "$work"
mkdir -p "$work/wheels" "$work/elsewhere"
# The system's site packages give NumPy (Debian: python3-numpy); the build
# requirements are taken from there too (no package index here).
"$python" -m venv --system-site-packages "$work/venv"
venv_python=$work/venv/bin/python
"$venv_python" -m pip wheel --no-build-isolation --no-deps --no-index \
    -w "$work/wheels" "$source_dir"
wheels=("$work"/wheels/expmap-*.whl)
[ ${#wheels[@]} -eq 1 ] && [ -f "${wheels[0]}" ] || { echo "expected one expmap wheel in $work/wheels"; exit 1; }
"$venv_python" -m pip install --no-index --no-deps "${wheels[0]}"

map_script='
import sys, numpy as np, expmap
V, F = expmap.read_mesh(sys.argv[1])
local = expmap.HeatExponentialMap(V, F).compute(0, fraction=0.05)
np.savez(sys.argv[2], vertices=local.vertices, uv=local.uv)
print(expmap.__file__, expmap.__version__, len(local.vertices))
'
cd "$work/elsewhere"
installed=$(env -u PYTHONPATH "$venv_python" -c "$map_script" "$mesh" installed.npz)
echo "installed: $installed"
case "$installed" in
  "$work/venv/"*) ;;
  *) echo "expmap was not imported from the virtual environment: $installed"; exit 1 ;;
esac
PYTHONPATH=$build_tree_package "$python" -c "$map_script" "$mesh" build_tree.npz >/dev/null
"$python" - <<'PY'
import numpy as np
a, b = np.load("installed.npz"), np.load("build_tree.npz")
assert len(a["vertices"]) > 10, "the installed module mapped an empty patch"
assert np.isfinite(a["uv"]).all(), "the installed module's map has non-finite (u, v)"
assert np.array_equal(a["vertices"], b["vertices"]) and np.array_equal(a["uv"], b["uv"]), \
    "the installed module's map differs from the build tree's"
print("the installed module maps as the build tree's does")
PY
