#!/usr/bin/env bash
# Installs whatever scripts/packages.txt lists and the machine lacks, then configures build/
# (everything on: host tools, tests, firmware). The callers build what they need from it:
# run-main.sh the CLI, run-tests.sh everything.
set -euo pipefail
cd "$(dirname "$0")/.."

wanted=$(grep -v '^#' scripts/packages.txt | grep -v '^$')
missing=()
for p in $wanted; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release ${SPANLIGHT_CMAKE_ARGS:-}
