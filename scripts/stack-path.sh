#!/usr/bin/env bash
# The deepest static call path below a function in a firmware app, from the call graphs GCC
# writes beside each object (-fcallgraph-info=su, set for every firmware build in
# hal/cortex_m/arm-none-eabi.cmake): each function's own frame (the .su figure) and the chain
# of callees whose frames add up to the most. On the baked apps it comes within a few words of
# what `render_frame stack N bytes` (hal::stack_mark, measured on QEMU) reports, and it names
# the frames to shrink first. Calls through a pointer and inline assembly's own stack are not
# in the graph.
#   scripts/stack-path.sh [--build DIR] CPU APP [FUNCTION]
#     CPU       cortex-m7, cortex-m4 or cortex-m0plus
#     APP       a firmware app target, e.g. render_textured_room
#     FUNCTION  a pattern of the root's mangled name (default 12render_frame: spanlight::render_frame)
set -euo pipefail
build=build
if [ "${1:-}" = "--build" ]; then
  build=$2
  shift 2
fi
if [ $# -lt 2 ]; then
  echo "usage: scripts/stack-path.sh [--build DIR] CPU APP [FUNCTION]" >&2
  exit 2
fi
cpu=$1 app=$2 root=${3:-12render_frame}
objects="$build/firmware-$cpu"
[ -d "$objects" ] || { echo "stack-path: $objects: no firmware build for $cpu" >&2; exit 2; }
mapfile -t graphs < <(find "$objects/" -path "*/CMakeFiles/$app.dir/*" -name '*.ci' | sort)
if [ ${#graphs[@]} -eq 0 ]; then
  echo "stack-path: no call graph (.ci) for $app under $objects: build it with this toolchain file" >&2
  exit 2
fi

awk -v root="$root" '
  # node: { title: "FILE:SYMBOL" label: "NAME\nFILE:LINE:COL\nN bytes (static)" [shape : ellipse] }
  /^node: / {
    t = $0; sub(/^node: \{ title: "/, "", t); sub(/" label: ".*/, "", t)
    label = $0; sub(/^node: \{ title: "[^"]*" label: "/, "", label); sub(/"( shape : ellipse)? \}[ \t]*$/, "", label)
    bytes = 0
    if (match(label, /\\n[0-9]+ bytes/)) bytes = substr(label, RSTART + 2, RLENGTH - 8) + 0
    frame[t] = bytes
    next
  }
  /^edge: / {
    s = $0; sub(/^edge: \{ sourcename: "/, "", s); sub(/" targetname: ".*/, "", s)
    d = $0; sub(/.*" targetname: "/, "", d); sub(/".*/, "", d)
    if (s != d && !((s, d) in seen)) { seen[s, d] = 1; callees[s] = callees[s] SUBSEP d }
    next
  }
  # The deepest total below t (memoised; the pipeline has no recursion, a cycle counts once).
  function deepest(t,    n, list, i, best, c) {
    if (t in memo) return memo[t]
    memo[t] = frame[t]
    best = 0; next_of[t] = ""
    n = split(substr(callees[t], 2), list, SUBSEP)
    for (i = 1; i <= n; ++i) {
      c = deepest(list[i])
      if (c > best) { best = c; next_of[t] = list[i] }
    }
    memo[t] = frame[t] + best
    return memo[t]
  }
  END {
    found = 0
    for (t in frame) {
      if (t !~ root) continue
      found = 1
      printf "%d bytes below and in %s\n", deepest(t), mangled(t)
      for (u = t; u != ""; u = next_of[u]) printf "%8d  %s\n", frame[u], mangled(u)
    }
    if (!found) { print "stack-path: no function matching " root " in the call graph" > "/dev/stderr"; exit 2 }
  }
  # A title is FILE:SYMBOL; GCC cuts some labels short, so the name comes from the symbol.
  function mangled(t) { sub(/^.*:/, "", t); return t }
' "${graphs[@]}" | c++filt | awk '
  # Template arguments, parameter lists and clone suffixes left out: the names read as a path.
  {
    line = $0
    sub(/ \[clone [^]]*\]/, "", line)
    while (gsub(/<[^<>]*>/, "", line) > 0) {}
    while (gsub(/\([^()]*\)/, "", line) > 0) {}
    print line
  }'
