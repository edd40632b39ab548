#!/usr/bin/env bash
# Where a frame's instructions go on the host, stage by stage: builds the render_baked app
# of a baked scene with -O2 -g (the Release host apps carry no line info), runs it under
# callgrind, and sums the executed instructions (Ir) per pipeline source file, with inlined
# code counted in the file it comes from. The pipeline's files are its stages (1_vertex/ ..
# 5_frame/, one job a file: transform.hpp, setup.hpp, walk.hpp, texture.hpp, ...), so the table reads
# as "share of the frame per stage". Proportions only: x86-64 is not Cortex-M; QEMU counts
# (spanlight sweep, per pass) are the figures of record.
#   profile_stages.sh BUILD_DIR SCENE [WORK_DIR]     (the host build's bake of render_SCENE_host)
set -euo pipefail

build=$1
scene=$2
work=${3:-$(mktemp -d)}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
baked=$build/firmware/apps/render_baked/spanlight_baked/render_${scene}_host
[ -f "$baked/baked_scene.cpp" ] || { echo "profile_stages: $baked/baked_scene.cpp is missing (build target render_${scene}_host)" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "profile_stages: valgrind is not installed" >&2; exit 2; }

mkdir -p "$work"
app=$work/render_${scene}_profile
g++ -std=c++20 -O2 -g -DNDEBUG \
  -I"$source_dir/pipeline/include" -I"$source_dir/fixedpoint/include" -I"$source_dir/hal/include" \
  -I"$source_dir/hal/common" -I"$baked" \
  "$source_dir/firmware/apps/render_baked/render_baked_main.cpp" "$baked/baked_scene.cpp" "$source_dir"/hal/host/*.cpp \
  -o "$app"
valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" "$app" "$work/frame.ppm" >/dev/null 2>"$work/valgrind.log"

# Callgrind's format: "fl=" names the function's file, "fi="/"fe=" the file of inlined lines
# that follow, and plain "line Ir" lines carry the cost ("calls=" lines are followed by an
# inclusive cost, which is skipped). Names are compressed: "(n) name" the first time, in any of
# fl=, fi=, fe=, cfi= or cfl=, and "(n)" after.
awk '
  function file_of(spec,   id, name) {
    if (match(spec, /^\([0-9]+\)/)) {
      id = substr(spec, 2, RLENGTH - 2); name = substr(spec, RLENGTH + 2)
      if (name != "") names[id] = name
      return names[id]
    }
    return spec
  }
  /^cf[il]=/ { file_of(substr($0, 5)); next }  # a called function'"'"'s file: only defines the name
  /^fl=/ { fl = file_of(substr($0, 4)); current = fl; next }
  /^f[ie]=/ { current = file_of(substr($0, 4)); next }
  /^fn=/ { current = fl; next }
  /^calls=/ { skip = 1; next }
  /^[0-9+-]/ { if (skip) { skip = 0; next } cost[current] += $2; total += $2; next }
  END {
    for (f in cost) {
      stage = f; sub(/.*\//, "", stage)
      if (f !~ /spanlight|fixedpoint/) stage = "(other: libc, HAL, app)"
      by_stage[stage] += cost[f]
    }
    printf "%-28s %14s %7s\n", "source file (stage)", "Ir", "share"
    for (s in by_stage) printf "%-28s %14d %6.1f%%\n", s, by_stage[s], 100 * by_stage[s] / total | "sort -k2 -n -r"
    close("sort -k2 -n -r")
    printf "%-28s %14d\n", "total", total
  }' "$work/callgrind.out"
echo
echo "Heaviest functions (self cost; inlined code counted where it was inlined):"
callgrind_annotate --inclusive=no --threshold=95 "$work/callgrind.out" 2>/dev/null | sed -n '/file:function/,$p' | sed -n '3,22p' | cut -c1-170
