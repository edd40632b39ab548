#!/usr/bin/env bash
# Configures and builds examples/firmware against an installed spanlight (its toolchain file,
# find_package, the installed CLI for the bake), as the example's CMakeLists.txt says to.
#   example.sh SOURCE_DIR PREFIX WORKDIR
set -euo pipefail
source_dir=$1 prefix=$2 work=$3
rm -rf "$work"
cmake -S "$source_dir/examples/firmware" -B "$work" -G Ninja \
  -DCMAKE_TOOLCHAIN_FILE="$prefix/share/cmake/spanlight/arm-none-eabi.cmake" -DSPANLIGHT_CPU=cortex-m4 \
  -DCMAKE_PREFIX_PATH="$prefix"
cmake --build "$work"
