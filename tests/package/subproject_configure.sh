#!/usr/bin/env bash
# Configures tests/package/consumer with spanlight as its subproject (HOW: add_subdirectory or
# FetchContent) in a host build with spanlight's default options, which add the CLI and its
# host libraries (they build in the top-level build; the other package.subproject tests build
# the consumer). Checks that every include folder of every compile command exists, so no path
# was taken from the consumer's tree instead of spanlight's, and that spanlight wrote nothing
# into the consumer's build folder outside its own subfolder.
#   subproject_configure.sh SOURCE_DIR HOW WORKDIR SCENE
set -euo pipefail
source_dir=$1 how=$2 work=$3 scene=$4
rm -rf "$work"
build=$work/build
cmake -S "$source_dir/tests/package/consumer" -B "$build" -G Ninja -DSPANLIGHT_SOURCE="$source_dir" -DHOW="$how" \
  -DSCENE="$scene" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON

failed=0
for dir in $(grep -o -- '-\(I\|isystem \)[^ "]*' "$build/compile_commands.json" | sed 's/^-I//; s/^-isystem //' | sort -u); do
  [ -d "$dir" ] || { echo "an include folder that does not exist: $dir"; failed=1; }
done
grep -q '"file": "[^"]*host_tools/cli/main.cpp"' "$build/compile_commands.json" || {
  echo "the CLI is not part of the subproject's default host build"
  failed=1
}
unexpected=$(cd "$build" && ls -A | grep -vxE 'CMakeCache.txt|CMakeFiles|build.ninja|cmake_install.cmake|compile_commands.json|spanlight|_deps|spanlight_baked' || true)
[ -z "$unexpected" ] || { echo "spanlight wrote into the consumer's build folder: $unexpected"; failed=1; }
exit "$failed"
