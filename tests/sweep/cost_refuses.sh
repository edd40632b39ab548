#!/usr/bin/env bash
# `spanlight cost` loads and prepares the scene before building anything: bad input exits 2
# naming the file and the field, and nothing is written (no scratch folder is left either).
#   cost_refuses.sh SPANLIGHT SOURCE_DIR
set -u
spanlight=$1
source_dir=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/spanlight-cost-refuses.XXXXXX")
trap 'rm -rf "$work"' EXIT
export TMPDIR=$work/tmp  # where a scratch build would go
mkdir "$TMPDIR"
failed=0
expect_refused() {  # WHAT EXPECTED_STDERR ARGS...
  local what=$1 expected=$2
  shift 2
  (cd "$work" && "$spanlight" cost "$@" >"$work/out" 2>"$work/err")
  local status=$?
  [ "$status" -eq 2 ] || { echo "FAIL: $what: exit status $status, expected 2"; cat "$work/err"; failed=1; }
  grep -qF -- "$expected" "$work/err" || { echo "FAIL: $what: stderr lacks '$expected':"; cat "$work/err"; failed=1; }
  [ -z "$(ls -A "$TMPDIR")" ] || { echo "FAIL: $what: something was written to $TMPDIR"; failed=1; }
  [ ! -s "$work/out" ] || { echo "FAIL: $what: a table was printed"; failed=1; }
}
expect_refused "missing scene" "$work/missing.json" "$work/missing.json"
printf '{"version": 2, "output": {"width": 0}}' >"$work/bad.json"
expect_refused "bad field" "$work/bad.json: " "$work/bad.json"
expect_refused "too far" "beyond the supported" "$source_dir/tests/sweep/scenes/far_positions.json"
expect_refused "bad knob" "--span" "$source_dir/scenes/textured_room.json" --span 3
expect_refused "bad core" "--cpu" "$source_dir/scenes/textured_room.json" --cpu cortex-m3
[ "$failed" -eq 0 ] && echo "ok: every bad input refused with exit 2, nothing written"
exit "$failed"
