#!/usr/bin/env bash
# The whole test suite: set up, build everything (tests, sanitizer twins, fuzzers, firmware),
# then every test through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j2
