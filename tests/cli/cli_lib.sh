# shellcheck shell=bash
# Shared helpers for the CLI tests (sourced, not run). Plain bash and
# coreutils only: a fresh machine has no python.
#
#   run_spanlight ARGS...   runs $SPANLIGHT, sets $status, $out_text, $err_text
#   expect_status N         the last run exited with N
#   expect_stderr_has TEXT  stderr of the last run contains TEXT (fixed string)
#   expect_stdout_has TEXT
#   expect_no_file PATH     PATH does not exist
#   expect_only_files DIR NAME...   DIR holds exactly these entries (hidden ones too):
#                           catches temporaries left behind by a failed write
#   finish                  exit 1 if any expectation failed, else 0
#
# Every failed expectation prints one line starting with FAIL and the command;
# the script goes on, so one run reports every problem.

set -u

failures=0
last_command=""
status=0
out_text=""
err_text=""

: "${SPANLIGHT:?set SPANLIGHT to the spanlight binary}"

scratch=$(mktemp -d "${TMPDIR:-/tmp}/spanlight-cli-test.XXXXXX")
trap 'rm -rf "$scratch"' EXIT

fail() {
  echo "FAIL: $*"
  echo "      command: $last_command"
  failures=$((failures + 1))
}

run_spanlight() {
  last_command="spanlight $*"
  "$SPANLIGHT" "$@" >"$scratch/.stdout" 2>"$scratch/.stderr"
  status=$?
  out_text=$(cat "$scratch/.stdout")
  err_text=$(cat "$scratch/.stderr")
  rm -f "$scratch/.stdout" "$scratch/.stderr"
}

expect_status() {
  if [[ "$status" != "$1" ]]; then
    fail "exit status $status, expected $1; stderr: ${err_text:-<empty>}"
  fi
}

expect_stderr_has() {
  if [[ "$err_text" != *"$1"* ]]; then
    fail "stderr does not contain '$1'; stderr: ${err_text:-<empty>}"
  fi
}

expect_stdout_has() {
  if [[ "$out_text" != *"$1"* ]]; then
    fail "stdout does not contain '$1'; stdout: ${out_text:-<empty>}"
  fi
}

expect_no_file() {
  if [[ -e "$1" || -L "$1" ]]; then
    fail "$1 exists but should not"
  fi
}

expect_only_files() {
  local dir=$1
  shift
  local expected actual
  expected=$(printf '%s\n' "$@" | LC_ALL=C sort)
  actual=$(cd "$dir" && LC_ALL=C ls -A | LC_ALL=C sort)  # names here are plain
  if [[ "$expected" != "$actual" ]]; then
    fail "$dir holds [${actual//$'\n'/ }], expected [${expected//$'\n'/ }]"
  fi
}

# A file with known bytes standing in for an earlier render the user wants to keep.
make_previous_output() {
  printf 'an earlier render, not to be replaced by a half-written file\n' >"$1"
}

expect_unchanged_previous_output() {
  local expected
  expected='an earlier render, not to be replaced by a half-written file'
  if [[ ! -f "$1" ]]; then
    fail "$1 (present before the run) is gone"
  elif [[ "$(cat "$1")" != "$expected" ]]; then
    fail "$1 (present before the run) was changed"
  fi
}

# WIDTH HEIGHT of a PNG, read back through `spanlight compare` (size line).
png_size() {
  "$SPANLIGHT" compare "$1" "$1" 2>/dev/null | sed -n 's/^size *\([0-9]*\) x \([0-9]*\)$/\1 \2/p'
}

finish() {
  if ((failures > 0)); then
    echo "$failures expectation(s) failed"
    exit 1
  fi
  exit 0
}
