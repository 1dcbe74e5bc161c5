#!/usr/bin/env bash
# Every public header compiles with clang and libc++ (LLVM's standard
# library, which lacks some of libstdc++'s extras, e.g. the special math
# functions): one translation unit including them all, syntax only.
# Exits 77 (skipped) when clang++ or libc++ is not installed.
#
# usage: public_headers_with_libcxx.sh CLANGXX INCLUDE_DIR SCRATCH_DIR SYSTEM_INCLUDE_DIR...
set -euo pipefail
clangxx=$1 include_dir=$2 scratch=$3
shift 3
mkdir -p "$scratch"

if ! echo '#include <vector>' | "$clangxx" -stdlib=libc++ -std=c++17 -fsyntax-only -x c++ - \
    2>/dev/null; then
  echo "clang++ with libc++ is not available (apt install clang libc++-dev libc++abi-dev): skipped"
  exit 77
fi

tu=$scratch/every_public_header.cpp
(cd "$include_dir" && find expmap -maxdepth 2 -name '*.h' -not -path '*/internal/*' | sort |
  sed 's/.*/#include <&>/') > "$tu"
echo "int main() {}" >> "$tu"
echo "$(grep -c '#include' "$tu") public headers"

system_includes=()
# The compiler's own search path must keep libc++ first: /usr/include as an
# -isystem would put the C headers ahead of libc++'s wrappers.
for dir in "$@"; do
  case $dir in /usr/include | /usr/local/include) ;; *) system_includes+=(-isystem "$dir") ;; esac
done
# The definitions the library's CMake target gives (CGAL with Eigen and GMP).
"$clangxx" -stdlib=libc++ -std=c++17 -fsyntax-only -DCGAL_EIGEN3_ENABLED -DCGAL_USE_GMPXX=1 \
  -I"$include_dir" "${system_includes[@]}" "$tu"
echo "compiled with $("$clangxx" --version | head -1) and libc++"
