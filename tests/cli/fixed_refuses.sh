#!/usr/bin/env bash
# fixed_refuses.sh SPANLIGHT SCENE.json FIELD
#
# A valid scene the fixed-point backend does not draw (fixed_backend_refuses.txt):
# `render --backend fixed` exits 2 with "SCENE: FIELD: expected ..." on stderr and
# leaves no output file; `--backend float` draws it.
export SPANLIGHT=$1
scene=$2
field=$3
# shellcheck source=tests/cli/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh"

mkdir "$scratch/fixed"
run_spanlight render "$scene" --backend fixed --out "$scratch/fixed/out.png"
expect_status 2
expect_stderr_has "$(basename "$scene"): $field: expected "
if [[ -n "$out_text" ]]; then fail "stdout should be empty, got: $out_text"; fi
expect_no_file "$scratch/fixed/out.png"
expect_only_files "$scratch/fixed"

run_spanlight render "$scene" --backend float --out "$scratch/float.png"
expect_status 0

finish
