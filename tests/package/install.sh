#!/usr/bin/env bash
# Installs this build into PREFIX (emptied first) and checks what a firmware project needs is
# there: the headers, the host CLI (it runs), the CMake package with its version file, and the
# toolchain file.
#   install.sh BUILD_DIR PREFIX
set -euo pipefail
build=$1 prefix=$2
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix"
missing=0
for file in include/fixedpoint/reciprocal.hpp include/spanlight/render.hpp include/hal/hal.hpp bin/spanlight \
            share/cmake/spanlight/spanlightConfig.cmake share/cmake/spanlight/spanlightConfigVersion.cmake \
            share/cmake/spanlight/spanlightTargets.cmake share/cmake/spanlight/SpanlightBake.cmake \
            share/cmake/spanlight/arm-none-eabi.cmake; do
  [ -f "$prefix/$file" ] || { echo "install: $prefix/$file is missing"; missing=1; }
done
[ "$missing" -eq 0 ]
"$prefix/bin/spanlight" --help >/dev/null
echo "install: headers, CLI, CMake package and toolchain file in $prefix"
