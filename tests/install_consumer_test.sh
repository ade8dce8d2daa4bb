#!/usr/bin/env bash
# ctest InstallAndConsume: installs this build into a fresh prefix, then configures, builds and
# runs examples/consumer against it with nothing but find_package(opgraph). Fails when the
# package is broken: a header, library, target or dependency missing, or an installed CMake file
# pointing back into the source or build tree (which would hide the rest on this machine).
#
#   install_consumer_test.sh CMAKE SOURCE_DIR BUILD_DIR WORK_DIR [consumer configure args...]
set -euo pipefail
cmake=$1 source_dir=$2 build_dir=$3 work_dir=$4
shift 4

fail() {
  echo "InstallAndConsume: $*"
  exit 1
}
# Runs a command quietly, showing its log when it fails.
quiet() {
  local log=$1
  shift
  "$@" >"$log" 2>&1 || { cat "$log"; fail "failed: $*"; }
}

rm -rf "$work_dir"
mkdir -p "$work_dir"
prefix=$work_dir/prefix
quiet "$work_dir/install.log" "$cmake" --install "$build_dir" --prefix "$prefix"
config=$(find "$prefix" -path '*/cmake/opgraph/opgraphConfig.cmake')
[ -n "$config" ] || fail "no opgraphConfig.cmake under $prefix"
if grep -lF -e "$source_dir" -e "$build_dir" "$(dirname "$config")"/*.cmake; then
  fail "the installed package names the source or build tree (files above)"
fi

consumer=$work_dir/consumer
quiet "$work_dir/configure.log" "$cmake" -S "$source_dir/examples/consumer" -B "$consumer" "$@" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON
grep -qxF "opgraph_DIR:PATH=$(dirname "$config")" "$consumer/CMakeCache.txt" ||
  fail "the consumer found another opgraph: $(grep opgraph_DIR "$consumer/CMakeCache.txt")"
quiet "$work_dir/build.log" "$cmake" --build "$consumer"

output=$("$consumer/opgraph_consumer" "$source_dir/examples/barrel.obj" "$work_dir/out")
echo "$output"
grep -qx 'sequence: 5 operations' <<<"$output" || fail "expected 5 operations"
grep -qE '^result: [1-9][0-9]* vertices, [1-9][0-9]* faces$' <<<"$output" || fail "expected a result mesh"
grep -qE '^recovered: [1-9][0-9]* operations' <<<"$output" || fail "expected a recovered sequence"
for file in result.obj result.glb sequence.json rebuild_blender.py steps/04_Subdivision.obj; do
  [ -s "$work_dir/out/$file" ] || fail "missing output $file"
done
echo "InstallAndConsume: ok"
