#!/usr/bin/env bash
# Builds tests/package/consumer with spanlight as its subproject (HOW: add_subdirectory or
# FetchContent) in a host or a cross (Cortex-M4) build, baking with the given host CLI; runs the
# program (on QEMU's mps2-an386 for cross) and checks its frame equals `spanlight render` of the
# scene. spanlight must write nothing into the consumer's build folder outside its own subfolder.
#   subproject.sh SOURCE_DIR SPANLIGHT HOW host|cross WORKDIR SCENE [KNOB]...
set -euo pipefail
source_dir=$1 spanlight=$2 how=$3 kind=$4 work=$5 scene=$6
shift 6
rm -rf "$work"
mkdir -p "$work/run"
build=$work/build
args=(-DSPANLIGHT_SOURCE="$source_dir" -DHOW="$how" -DSCENE="$scene" -DKNOBS="$*"
      -DSPANLIGHT_HOST_TOOLS=OFF -DSPANLIGHT_HOST_TOOLS_DIR="$(dirname "$spanlight")")
if [ "$kind" = cross ]; then
  args+=(-DCMAKE_TOOLCHAIN_FILE="$source_dir/hal/cortex_m/arm-none-eabi.cmake" -DSPANLIGHT_CPU=cortex-m4)
fi
cmake -S "$source_dir/tests/package/consumer" -B "$build" -G Ninja "${args[@]}"
cmake --build "$build"

# The consumer's own files, CMake's, and spanlight's one folder: spanlight/ or _deps/.
unexpected=$(cd "$build" && ls -A | grep -vxE 'CMakeCache.txt|CMakeFiles|build.ninja|cmake_install.cmake|\.ninja_(deps|log)|spanlight|_deps|render_scene|spanlight_baked' || true)
if [ -n "$unexpected" ]; then
  echo "spanlight wrote into the consumer's build folder: $unexpected"
  exit 1
fi

cd "$work/run"
if [ "$kind" = cross ]; then
  bash "$source_dir/tools/qemu_icount/run_on_qemu.sh" --cpu cortex-m4 "$build/render_scene" frame.ppm
else
  "$build/render_scene" frame.ppm
fi
bash "$source_dir/tests/package/frame_matches_render.sh" "$work/run/frame.ppm" "$spanlight" "$scene" "$@"
