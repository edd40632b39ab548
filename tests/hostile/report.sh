#!/usr/bin/env bash
# report.sh [BUILD_DIR]: the hostile-input corpus's figures as a Markdown table
# (docs/limits.md), from BUILD_DIR/tests/hostile/measured/, written by
#   ctest --test-dir BUILD_DIR -R hostile -j1
# (-j1: the times are then each run's own, not shared with a neighbour).
set -euo pipefail
build=${1:-build}
measured="$build/tests/hostile/measured"
[[ -d "$measured" ]] || { echo "no $measured: run ctest -R hostile first" >&2; exit 1; }
echo "| case | exit | time | peak memory | deadline, cap | message (fragment checked) |"
echo "|---|---:|---:|---:|---|---|"
cat "$measured"/*.txt | LC_ALL=C sort | awk -F'|' '{
  fragment = $7; gsub(/\|/, "\\|", fragment)
  printf "| %s | %s | %.2f s | %.0f MiB | %s s, %s MiB | `%s` |\n", $1, $2, $3, $4 / 1024, $5, $6, fragment
}'
