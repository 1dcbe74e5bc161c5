#!/usr/bin/env bash
# The test command still registers every test in a build folder that the
# main job configured first (without tests): configures a scratch folder with
# the build line of scripts/main-job.sh, then with that of scripts/test.sh,
# and checks that ctest then lists every test this build lists, and that
# scripts/test.sh makes ctest fail when no test is found.
#
# usage: after_main_job.sh SOURCE_DIR THIS_BUILD_DIR SCRATCH_DIR
set -euo pipefail
source_dir=$1 this_build=$2 scratch=$3

build_line() {
  local lines
  lines=$(grep -E '^scripts/build\.sh' "$source_dir/scripts/$1")
  if [[ $(wc -l <<<"$lines") != 1 ]]; then
    echo "scripts/$1 must call scripts/build.sh exactly once" >&2
    exit 1
  fi
  echo "$lines"
}
configure_like() {
  (cd "$source_dir" && EXPMAP_BUILD_DIR="$scratch" EXPMAP_CONFIGURE_ONLY=1 bash -c "$1") >/dev/null
}
listing() {
  (cd "$1" && ctest -N) | sed -n 's/^ *Test *#[0-9]*: //p' | sort
}
count() { grep -c . <<<"$1" || true; }

rm -rf "$scratch"
configure_like "$(build_line main-job.sh)"
echo "after the main job's configure: $(count "$(listing "$scratch")") tests"
configure_like "$(build_line test.sh)"
expected=$(listing "$this_build")
found=$(listing "$scratch")
echo "after the test command's configure: $(count "$found") tests"
missing=$(comm -23 <(echo "$expected") <(echo "$found"))
rm -rf "$scratch"
if [[ -z "$found" || -n "$missing" ]]; then
  echo "the test command would not run: ${missing:-any test}" >&2
  exit 1
fi
if ! grep -Eq '^cd build && ctest .*--no-tests=error' "$source_dir/scripts/test.sh"; then
  echo "scripts/test.sh must run ctest with --no-tests=error" >&2
  exit 1
fi
echo "the test command registers all $(count "$expected") tests of this build"
